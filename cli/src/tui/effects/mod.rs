//! The work that leaves the explorer's state, each [`Command`] run here for the event loop
//! ([`crate::tui::run_app`]): the compute worker ([`worker`], [`engine`]), GFMD threads, the
//! files of `e` and `s` ([`files`], [`export`]), presets and tours read ([`load`]). What an
//! effect finds goes back to the update as a [`Msg`]; effects never change the state.

pub mod clock;
pub mod engine;
pub mod export;
pub mod files;
pub mod load;
pub mod worker;

use crate::tui::base::protocol::Reply;
use crate::tui::model::command::Command;
use crate::tui::model::msg::Msg;
use asperity::error::{Error, Result};
use std::sync::atomic::Ordering;

/// Runs a command that finishes at once (a file read or written, a GFMD run told to stop)
/// and returns its message; None for the others (and for the loop's own: the worker, GFMD
/// threads, quitting).
pub fn run_now(cmd: &Command) -> Option<Msg> {
    cancel_gfmd(cmd);
    files::run(cmd).or_else(|| load::run(cmd))
}

/// Tells a GFMD run to stop for [`Command::CancelGfmd`] (its thread ends at its next check;
/// its replies, if any, are dropped by the update). True when `cmd` was one.
pub fn cancel_gfmd(cmd: &Command) -> bool {
    match cmd {
        Command::CancelGfmd(flag) => {
            flag.store(true, Ordering::Relaxed);
            true
        }
        _ => false,
    }
}

/// Starts a GFMD run for [`Command::StartGfmd`] in its own thread (its replies go to
/// `reply`), set up from what the command carries; the message says on which grid.
pub fn start_gfmd(cmd: Command, reply: impl Fn(Reply) + Send + 'static) -> Result<Option<Msg>> {
    let Command::StartGfmd {
        id,
        scene,
        preset,
        map,
        cancel,
    } = cmd
    else {
        return Ok(None);
    };
    let setup = engine::gfmd_setup(&preset, &scene, map.as_deref());
    let grid = engine::grid_side(&setup);
    engine::spawn_gfmd(id, setup, cancel, reply).map_err(|e| Error::io("start the GFMD thread", e))?;
    let at = std::time::Instant::now();
    Ok(Some(Msg::GfmdStarted { id, grid, at }))
}
