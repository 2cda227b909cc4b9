//! The worker's replies → the next state: a result is kept under its key; it is shown where
//! the key is the current scene's (compared with the keys computed once per scene change,
//! [`crate::tui::model::results::Results::keys`]), and kept for `M` where it is another
//! model's of the current scene.

use crate::tui::base::protocol::{CacheKey, Reply};
use crate::tui::model::app::*;
use crate::tui::model::results::{Slot, Stored};

impl App {
    /// Takes a worker reply: kept only if it belongs to the current scene.
    pub fn on_reply(&mut self, reply: Reply) {
        match reply {
            Reply::Point { gen, key, result } => {
                if &key == Slot::Point.key_in(self.results.keys()) {
                    self.results.point_gen = self.results.point_gen.max(gen);
                }
                self.keep(key, Stored::Point(result));
            }
            Reply::Sweep { key, result, .. } => {
                let current = &key == Slot::Sweep.key_in(self.results.keys());
                self.keep(key, Stored::Sweep(result));
                if current {
                    self.follow_window();
                }
            }
            Reply::Gap { key, result, .. } => self.keep(key, Stored::Gap(result)),
            Reply::Thickness { key, result, .. } => self.keep(key, Stored::Thickness(result)),
            Reply::Scales { key, result, .. } => self.keep(key, Stored::Scales(result)),
            Reply::GfmdProgress { id, progress } => self.on_gfmd_progress(id, progress),
            Reply::GfmdDone { id, result, elapsed_s } => self.on_gfmd_done(id, result, elapsed_s),
            Reply::Fault { gen, message } => {
                // the fault stands for every result of the current scene still missing, so
                // the panel and the charts say what failed instead of "computing…"
                let fault = asperity::error::Error::io("compute this scene", &message);
                if !self.results.is_current(Slot::Point) {
                    self.results.set_point(Err(fault.clone()));
                }
                if !self.results.is_current(Slot::Sweep) {
                    self.results.set_sweep(Err(fault.clone()));
                }
                if !self.results.is_current(Slot::Gap) {
                    self.results.set_gap(Err(fault));
                }
                self.jobs.served(gen);
            }
            Reply::Done { gen } => self.jobs.served(gen),
        }
    }

    /// Stores `value` under `key`: shown where `key` is the current scene's; kept for `M`
    /// where it is another model's key of the same kind (points, load and thickness sweeps:
    /// the kinds [`crate::tui::base::protocol::SceneKeys::overlays`] holds); dropped otherwise.
    fn keep(&mut self, key: CacheKey, value: Stored) {
        let keys = self.results.keys();
        let overlay = match value.slot() {
            Slot::Point => Some(0),
            Slot::Sweep => Some(1),
            Slot::Thickness => Some(2),
            Slot::Gap | Slot::Scales => None,
        };
        if &key == value.slot().key_in(keys) {
            self.results.put(key, value, true);
        } else if self.ui.all_models && overlay.is_some_and(|o| keys.overlays.iter().any(|(_, k)| k[o] == key)) {
            self.results.put(key, value, false);
        }
    }
}
