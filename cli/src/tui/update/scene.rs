//! A new scene or preset: the load history follows the hysteresis window it moves under the
//! load; a preset arrives resolved (the effect [`crate::tui::effects::load`] reads the file).

use crate::tui::base::protocol::sweep_key;
use crate::tui::model::app::*;
use asperity::error::Result;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;

/// Asks for a preset by name or path (the effect reads it; [`App::preset_loaded`] takes it).
pub fn load_preset(source: &str) -> Command {
    Command::LoadPreset(source.to_string())
}

impl App {
    /// A preset read: it becomes the current one, with its scene; on error the current one
    /// stays and the error shows.
    pub fn preset_loaded(&mut self, source: &str, result: Result<Preset>) {
        match result.and_then(|p| initial_scene(&p).map(|s| (p, s))) {
            Ok((p, s)) => {
                self.params.source = source.to_string();
                self.params.preset = p;
                self.params.base = s.clone();
                self.params.anchors = Anchors::default();
                self.set_scene(s);
                self.params.history.reset_to(self.params.preset.follows_unloading());
                self.info(format!("preset {}", self.params.preset.name));
            }
            Err(e) => self.fail(e),
        }
    }

    pub(crate) fn set_scene(&mut self, scene: Scene) {
        if scene != self.params.scene {
            self.refresh();
            let range = self.range();
            if sweep_key(&self.params.source, &scene, range)
                != sweep_key(&self.params.source, &self.params.scene, range)
            {
                // t·q_r, γ_s or the model moves the window: the loads visited so far are
                // walked through the old one, the load is walked again through the new one
                self.follow_window();
                self.params.history.forget_pending();
            }
            self.params.history.visit(scene.pressure());
        }
        self.params.scene = scene;
        self.ui.selected = self.ui.selected.min(self.knob_rows().len() - 1);
    }

    /// Walks the loads the path visited through the hysteresis window of the current scene's
    /// load sweep, when it is computed; says so when the branch changes.
    pub(crate) fn follow_window(&mut self) {
        if self.sweep_is_stale() {
            return;
        }
        let Some(Ok(sw)) = self.results.sweep() else { return };
        let w = crate::tui::model::history::Window {
            jump_in: sw.jump_in,
            pull_off: sw.pull_off,
            hysteresis: sw.has_hysteresis(),
        };
        if self.params.history.resolve(&w) {
            self.info(self.params.history.describe());
        }
    }

    /// Applies a changed scene (each change was validated where it was made).
    pub(crate) fn try_scene(&mut self, scene: Scene) {
        self.set_scene(scene)
    }
}
