//! The effects of the explorer's updates: the theory request goes to the worker and a GFMD
//! run to its own thread (both by the event loop, [`super::run_app`]); here the files of `e`
//! and `s`. (`worker::compute_now` serves the requests on the calling thread, for tests.)

use super::export;
use super::state::{App, Effect};

/// Does the work the last keys asked for ([`App::effects`]), reporting in the status line.
pub fn apply(app: &mut App) {
    for e in std::mem::take(&mut app.effects) {
        let (verb, r) = match e {
            Effect::Export => ("exported", export::export(app)),
            Effect::SaveCharts => ("saved", export::export_charts(app)),
        };
        match r {
            Ok(paths) => app.info(format!("{verb} {}", paths.join(", "))),
            Err(e) => app.fail(e),
        }
    }
}
