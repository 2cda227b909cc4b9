//! The scale view's frames: a tick advances a playing view, `[`/`]` scrub, Space plays or
//! pauses.

use crate::tui::model::app::App;

impl App {
    /// Advances the spinner and, while the scale view plays, its frame (called on ticks; the
    /// play stops at the last frame).
    pub fn tick(&mut self) {
        self.ui.spinner = self.ui.spinner.wrapping_add(1);
        if self.ui.playing {
            match self.scale_frame() {
                Some((i, n, _)) if i + 1 < n => self.ui.frame = Some(i + 1),
                Some(_) => {
                    self.ui.playing = false;
                    self.ui.frame = None;
                }
                None => {}
            }
        }
    }

    /// Moves the scale view `dir` frames (stops at the ends; pauses a play).
    pub fn scrub(&mut self, dir: i32) {
        self.ui.playing = false;
        if let Some((i, n, _)) = self.scale_frame() {
            let j = (i as i64 + i64::from(dir)).clamp(0, n as i64 - 1) as usize;
            self.ui.frame = if j + 1 == n { None } else { Some(j) };
        } else {
            self.info("no scale view: v picks the scales chart");
        }
    }

    /// Plays the scale view from its first frame (or from where it stands), or pauses it.
    pub fn toggle_play(&mut self) {
        if self.ui.playing {
            self.ui.playing = false;
            return;
        }
        match self.scale_frame() {
            Some((i, n, _)) => {
                self.ui.playing = true;
                if i + 1 >= n {
                    self.ui.frame = Some(0);
                }
            }
            None if self.shows_scales() => {
                // play as soon as the frames arrive
                self.ui.playing = true;
                self.ui.frame = Some(0);
            }
            None => self.info("no scale view: v picks the scales chart"),
        }
    }
}
