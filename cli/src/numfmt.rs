//! Numbers as the front ends write them: the library's [`asperity::report::numfmt`] (one
//! routine behind every tick label, legend, caption and panel value), under the name the
//! binary's modules use.

pub use asperity::report::numfmt::*;
