//! Walking a tour: its steps set the preset, the scene, the charts and the knob selected;
//! ←/→ move between steps, Esc leaves.

use crate::tui::base::tour::Tour;
use crate::tui::model::app::*;
use asperity::error::Result;

impl App {
    /// Starts walking `tour` at step `step`.
    pub fn start_tour(&mut self, tour: Tour, step: usize) {
        let step = step.min(tour.steps.len().saturating_sub(1));
        self.ui.tour = Some(TourState { tour, step });
        self.apply_step();
    }

    /// A tour read (`t`): walked from its first step; on error the explorer stays as it is.
    pub fn tour_loaded(&mut self, result: Result<Tour>) {
        match result {
            Ok(t) => self.start_tour(t, 0),
            Err(e) => self.fail(e),
        }
    }

    /// Moves `dir` steps along the tour (stops at the ends).
    pub fn tour_go(&mut self, dir: i32) {
        let Some(t) = self.ui.tour.as_mut() else { return };
        let n = t.tour.steps.len() as i32;
        let next = (t.step as i32 + dir).clamp(0, n - 1) as usize;
        if next == t.step {
            self.info(if dir > 0 {
                "last step of the tour: Esc leaves"
            } else {
                "first step of the tour"
            });
            return;
        }
        t.step = next;
        self.apply_step();
    }

    /// Leaves the tour; the scene and the charts stay as they are.
    pub fn leave_tour(&mut self) {
        if self.ui.tour.take().is_some() {
            if let Ok(s) = initial_scene(&self.params.preset) {
                self.params.base = s;
            }
            self.info("left the tour (t starts it again)");
        }
    }

    pub(crate) fn apply_step(&mut self) {
        let Some(t) = &self.ui.tour else { return };
        let st = t.tour.steps[t.step].clone();
        if st.source != self.params.source || st.preset != self.params.preset {
            self.params.source = st.source.clone();
            self.params.preset = st.preset.clone();
            if !self.params.presets.iter().any(|e| e.source == st.source) {
                self.params.presets.push(PresetEntry {
                    source: st.source.clone(),
                    place: "tour".into(),
                });
            }
        }
        // `r` goes back to the step's scene; the arrows step on its grids
        self.params.base = st.scene.clone();
        self.params.anchors = Anchors::default();
        self.set_scene(st.scene);
        self.params.history.reset_to(self.params.preset.follows_unloading());
        self.ui.charts = st.charts;
        self.ui.all_models = st.models;
        // a step that shows the scale view plays it from q_L
        self.ui.playing = self.shows_scales();
        self.ui.frame = self.ui.playing.then_some(0);
        // the chart the caption refers to first: the one a one-panel screen shows
        self.ui.focus = st.refers.first().copied().unwrap_or(0);
        self.ui.caption_scroll = 0;
        self.ui.edit = None;
        if let Some(k) = st.select {
            let want = knob_param(k);
            if let Some(i) = self.knob_rows().iter().position(|p| *p == want) {
                self.ui.selected = i;
            }
        }
        self.refresh();
    }
}
