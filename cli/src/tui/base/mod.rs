//! What the explorer's state is made of, below it: the worker protocol (requests, replies and
//! the cache keys that tie a reply to its scene), the plain data of the engine's results, the
//! chart kinds, the GFMD job as data, the tours with their captions and claims (and reading a
//! tour file), the key table, the words for fields and errors, word wrap, and the brute-force
//! points stored for a scene's case. It imports nothing else of the explorer.

pub mod caption;
pub mod data;
pub mod gfmd_view;
pub mod keys;
pub mod kinds;
pub mod progress;
pub mod protocol;
pub mod stored_gfmd;
pub mod tour;
pub mod tour_check;
pub mod words;
pub mod wrap;
