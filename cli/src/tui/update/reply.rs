//! The worker's replies → the next state: a result is kept only if it belongs to the current
//! scene (or to another model of it, while `M` overlays every model).

use crate::tui::base::protocol::{point_key, scales_key, sweep_key, thickness_key, Reply};
use crate::tui::model::app::*;
use crate::tui::model::results::Stored;

impl App {
    /// Takes a worker reply: kept only if it belongs to the current scene.
    pub fn on_reply(&mut self, reply: Reply) {
        match reply {
            Reply::Point { gen, key, result } => {
                if key == point_key(&self.params.source, &self.params.scene) {
                    self.results.point_gen = self.results.point_gen.max(gen);
                    self.results.point = Some(result);
                    self.results.point_shown = Some(key);
                } else if self.overlay_keys().0.contains(&key) {
                    self.results.store(key, Stored::Point(result));
                }
            }
            Reply::Sweep { key, result, .. } => {
                if key == sweep_key(&self.params.source, &self.params.scene, self.range()) {
                    self.results.sweep = Some(result);
                    self.results.sweep_shown = Some(key);
                    self.follow_window();
                } else if self.overlay_keys().1.contains(&key) {
                    self.results.store(key, Stored::Sweep(result));
                }
            }
            Reply::Gap { key, result, .. } => {
                if key == point_key(&self.params.source, &self.params.scene) {
                    self.results.gap = Some(result);
                    self.results.gap_shown = Some(key);
                }
            }
            Reply::Thickness { key, result, .. } => {
                if key == thickness_key(&self.params.source, &self.params.scene) {
                    self.results.thickness = Some(result);
                    self.results.thickness_shown = Some(key);
                } else if self.overlay_keys().2.contains(&key) {
                    self.results.store(key, Stored::Thickness(result));
                }
            }
            Reply::Scales { key, result, .. } => {
                if key == scales_key(&self.params.source, &self.params.scene) {
                    self.results.scales = Some(result);
                    self.results.scales_shown = Some(key);
                }
            }
            Reply::GfmdProgress { id, progress } => self.on_gfmd_progress(id, progress),
            Reply::GfmdDone { id, result, elapsed_s } => self.on_gfmd_done(id, result, elapsed_s),
            Reply::Fault { gen, message } => {
                // the fault stands for every result of the current scene still missing, so
                // the panel and the charts say what failed instead of "computing…"
                let p = &self.params;
                let fault = asperity::error::Error::io("compute this scene", &message);
                if self.results.point_shown.as_ref() != Some(&point_key(&p.source, &p.scene)) {
                    self.results.point = Some(Err(fault.clone()));
                    self.results.point_shown = Some(point_key(&p.source, &p.scene));
                }
                let sk = sweep_key(&p.source, &p.scene, self.range());
                if self.results.sweep_shown.as_ref() != Some(&sk) {
                    self.results.sweep = Some(Err(fault.clone()));
                    self.results.sweep_shown = Some(sk);
                }
                if self.results.gap_shown.as_ref() != Some(&point_key(&p.source, &p.scene)) {
                    self.results.gap = Some(Err(fault));
                    self.results.gap_shown = Some(point_key(&p.source, &p.scene));
                }
                self.jobs.served(gen);
            }
            Reply::Done { gen } => self.jobs.served(gen),
        }
    }
}
