//! `P` pins the theory curves shown.

use crate::tui::model::app::*;

impl App {
    /// `P`: pins the theory curve of every visible chart that has one (the oldest pin goes
    /// beyond [`crate::tui::model::pins::MAX_PINS`]).
    pub fn pin(&mut self) {
        let curves = crate::tui::charts::pin_curves(self);
        if curves.is_empty() {
            return self.info("nothing to pin yet (no current curve)");
        }
        if self.results.pins.iter().any(|p| p.scene == self.params.scene) {
            return self.info("this scene is pinned already: change a knob, then P pins the next");
        }
        if self.results.pins.len() >= crate::tui::model::pins::MAX_PINS {
            self.results.pins.remove(0);
        }
        let scene = self.params.scene.clone();
        self.results.pins.push(crate::tui::model::pins::Pin { scene, curves });
        let n = self.results.pins.len();
        self.info(format!(
            "pinned ({n} of {}): u unpins the newest, U all",
            crate::tui::model::pins::MAX_PINS
        ));
    }
}
