//! The explorer's state as plain data, and the messages and commands that cross it: nothing
//! here imports the update, the view or the effects.

pub mod app;
pub mod caption;
pub mod command;
pub mod data;
pub mod history;
pub mod jobs;
pub mod keys;
pub mod kinds;
pub mod knobs;
pub mod msg;
pub mod params;
pub mod pins;
pub mod progress;
pub mod protocol;
pub mod results;
pub mod stored_gfmd;
pub mod tour;
pub mod tour_check;
pub mod ui;
pub mod words;
pub mod wrap;
