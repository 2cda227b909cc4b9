//! The explorer's state as plain data ([`app::App`] and its four parts, the load history, the
//! knobs, the pins) and the messages and commands that cross it: nothing here imports the
//! update, the view or the effects, and nothing here reads a file or the clock or starts a
//! thread (`cli/tests/architecture.rs`). What the state is made of lies below it, in
//! [`crate::tui::base`].

pub mod app;
pub mod command;
pub mod history;
pub mod jobs;
pub mod knobs;
pub mod msg;
pub mod params;
pub mod pins;
pub mod results;
pub mod ui;
