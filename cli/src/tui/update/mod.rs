//! Key presses and worker replies → the next state ([`App`]) plus [`Command`]s, the work it
//! asks for: the worker's computation (`pending`, built when taken), a GFMD run to start,
//! files to write, quitting; all leave by [`App::take_commands`]. No terminal, no threads,
//! no files written here, so every key is unit-tested.

pub mod gfmd;
pub mod models;
pub mod turn;

use crate::tui::model::app::*;
use crate::tui::model::keys::{self, Action};
use crate::tui::model::kinds::ChartKind;
use crate::tui::model::protocol::{point_key, scales_key, sweep_key, thickness_key, Reply};
use crate::tui::model::tour::Tour;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

impl App {
    /// The GFMD run to start, if `g` asked for one: its id, scene and cancel flag (the event
    /// loop builds the setup, `jobs::gfmd_setup`, and starts the thread).
    pub fn take_gfmd_request(&mut self) -> Option<(u64, Scene, Arc<AtomicBool>)> {
        let i = self
            .jobs
            .commands
            .iter()
            .position(|c| matches!(c, Command::StartGfmd { .. }))?;
        match self.jobs.commands.remove(i) {
            Command::StartGfmd { id, scene, cancel } => Some((id, scene, cancel)),
            _ => None,
        }
    }

    /// Every command the updates since the last call asked for, in order: the computation of
    /// the current scene first (when it changed), then the queued ones, then `Quit` if asked.
    pub fn take_commands(&mut self) -> Vec<Command> {
        let mut out: Vec<Command> = self.take_request().map(Command::Compute).into_iter().collect();
        out.append(&mut self.jobs.commands);
        if self.ui.quit {
            out.push(Command::Quit);
        }
        out
    }

    /// Takes a worker reply: kept only if it belongs to the current scene.
    pub fn on_reply(&mut self, reply: Reply) {
        match reply {
            Reply::Point { gen, key, result } => {
                if key == point_key(&self.params.source, &self.params.scene) {
                    self.results.point_gen = self.results.point_gen.max(gen);
                    self.results.point = Some(result);
                    self.results.point_shown = Some(key);
                } else if self.overlay_keys().0.contains(&key) {
                    bounded_insert(&mut self.results.overlay_points, key, result);
                }
            }
            Reply::Sweep { key, result, .. } => {
                if key == sweep_key(&self.params.source, &self.params.scene, self.range()) {
                    self.results.sweep = Some(result);
                    self.results.sweep_shown = Some(key);
                    self.follow_window();
                } else if self.overlay_keys().1.contains(&key) {
                    bounded_insert(&mut self.results.overlay_sweeps, key, result);
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
                    bounded_insert(&mut self.results.overlay_thickness, key, result);
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
            Reply::Done { gen } => {
                if gen == self.jobs.gen {
                    self.jobs.busy = false;
                    self.jobs.busy_since = None;
                }
            }
        }
    }

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

    /// Handles one key press.
    pub fn on_key(&mut self, ev: KeyEvent) {
        if ev.code == KeyCode::Char('c') && ev.modifiers.contains(KeyModifiers::CONTROL) {
            self.ui.quit = true;
            return;
        }
        self.ui.message = None;
        if self.ui.edit.is_some() {
            self.on_edit_key(ev);
            return;
        }
        match self.ui.overlay {
            Overlay::Help => {
                // ↓↑ (j k, PgDn PgUp) scroll, any other key closes the help; q still quits
                let n = crate::tui::model::keys::help_rows();
                match ev.code {
                    KeyCode::Down | KeyCode::Char('j') => self.ui.help_scroll = (self.ui.help_scroll + 1).min(n),
                    KeyCode::PageDown => self.ui.help_scroll = (self.ui.help_scroll + 8).min(n),
                    KeyCode::Up | KeyCode::Char('k') => self.ui.help_scroll = self.ui.help_scroll.saturating_sub(1),
                    KeyCode::PageUp => self.ui.help_scroll = self.ui.help_scroll.saturating_sub(8),
                    code => {
                        self.ui.overlay = Overlay::None;
                        self.ui.help_scroll = 0;
                        self.ui.quit = code == KeyCode::Char('q');
                    }
                }
                return;
            }
            Overlay::Presets(cursor) => {
                self.on_picker_key(ev, cursor);
                return;
            }
            Overlay::None => {}
        }
        if self.ui.tour.is_some()
            && ev
                .modifiers
                .intersection(KeyModifiers::SHIFT | KeyModifiers::CONTROL)
                .is_empty()
        {
            match ev.code {
                KeyCode::Left => return self.tour_go(-1),
                KeyCode::Right => return self.tour_go(1),
                KeyCode::Esc => return self.leave_tour(),
                _ => {}
            }
        }
        if let KeyCode::Char(c) = ev.code {
            if (c.is_ascii_digit() || c == '.' || c == '-') && !ev.modifiers.contains(KeyModifiers::CONTROL) {
                self.ui.edit = Some(c.to_string());
                return;
            }
        }
        let Some(action) = keys::action_for(&ev) else {
            return;
        };
        self.act(action);
    }

    /// Performs an action of the key table.
    pub fn act(&mut self, action: Action) {
        let n = self.knob_rows().len();
        match action {
            Action::Up => self.ui.selected = (self.ui.selected + n - 1) % n,
            Action::Down => self.ui.selected = (self.ui.selected + 1) % n,
            Action::Dec => self.step(-1, false),
            Action::Inc => self.step(1, false),
            Action::DecCoarse => self.step(-1, true),
            Action::IncCoarse => self.step(1, true),
            Action::Edit => self.ui.edit = Some(String::new()),
            Action::CycleModel => self.cycle_model(1),
            Action::Presets => {
                let cur = self
                    .params
                    .presets
                    .iter()
                    .position(|e| e.source == self.params.source)
                    .unwrap_or(0);
                self.ui.overlay = Overlay::Presets(cur);
            }
            Action::Reset => {
                self.params.anchors = Anchors::default();
                self.params.history.reset();
                self.set_scene(self.params.base.clone());
                self.info(format!("reset to preset {}", self.params.preset.name));
            }
            Action::Export => self.jobs.commands.push(Command::Export),
            Action::AreaMode => {
                let mut any = false;
                for c in &mut self.ui.charts {
                    *c = match *c {
                        ChartKind::Area => ChartKind::AreaRatio,
                        ChartKind::AreaRatio => ChartKind::Area,
                        other => other,
                    };
                    any |= matches!(*c, ChartKind::Area | ChartKind::AreaRatio);
                }
                if !any {
                    self.info("no area chart shown: v picks the charts");
                }
            }
            Action::Chart => {
                let f = self.ui.focus.min(2);
                self.ui.charts[f] = self.ui.charts[f].cycle(1);
                self.refresh();
            }
            Action::Focus => self.ui.focus = (self.ui.focus + 1) % 3,
            Action::Models => {
                self.ui.all_models = !self.ui.all_models;
                self.refresh();
            }
            Action::Tour => {
                if self.ui.tour.is_some() {
                    self.leave_tour();
                } else {
                    match Tour::resolve(crate::tui::model::tour::DEFAULT_TOUR) {
                        Ok(t) => self.start_tour(t, 0),
                        Err(e) => self.fail(e),
                    }
                }
            }
            Action::Save => self.jobs.commands.push(Command::SaveCharts),
            Action::Compare => {
                if self.params.scene.is_adhesive() {
                    self.ui.compare = !self.ui.compare;
                    let on = if self.ui.compare { "shown" } else { "hidden" };
                    self.info(format!("the adhesionless comparison (γ_s = 0) is {on}"));
                } else {
                    self.info(
                        "c compares with the scene without adhesion: this one has none (γ_s = 0); turn γ_s up first",
                    );
                }
            }
            Action::Gfmd => self.toggle_gfmd(),
            Action::Pin => self.pin(),
            Action::Unpin | Action::UnpinAll => {
                let text = crate::tui::model::pins::unpin(
                    &mut self.results.pins,
                    action == Action::UnpinAll,
                    &self.params.scene,
                );
                self.info(text);
            }
            Action::FramePrev => self.scrub(-1),
            Action::FrameNext => self.scrub(1),
            Action::Play => self.toggle_play(),
            Action::CaptionDown => {
                let most = self.ui.tour.as_ref().map_or(0, |t| {
                    crate::tui::model::wrap::caption_rows_at_most(&t.tour.steps[t.step].caption)
                });
                self.ui.caption_scroll = (self.ui.caption_scroll + 1).min(most.saturating_sub(1));
            }
            Action::CaptionUp => self.ui.caption_scroll = self.ui.caption_scroll.saturating_sub(1),
            Action::Help => self.ui.overlay = Overlay::Help,
            Action::Zoom => self.ui.zoom = !self.ui.zoom,
            Action::LogY => {
                self.ui.log_pr = !self.ui.log_pr;
                if !self.ui.charts.contains(&ChartKind::Pr) {
                    self.info("y sets the Pr chart's density axis: no Pr chart shown (v picks the charts)");
                }
            }
            Action::Cancel => {
                if matches!(self.jobs.gfmd, GfmdState::Running { .. }) {
                    self.toggle_gfmd();
                } else if self.ui.zoom {
                    self.ui.zoom = false;
                } else {
                    self.info("nothing to cancel: q quits");
                }
            }
            Action::Quit => self.ui.quit = true,
        }
    }

    pub(crate) fn on_edit_key(&mut self, ev: KeyEvent) {
        let Some(buf) = self.ui.edit.as_mut() else {
            return;
        };
        match ev.code {
            // q cancels the field (a second q quits): no value contains a q
            KeyCode::Esc | KeyCode::Char('q') => self.ui.edit = None,
            KeyCode::Backspace => {
                buf.pop();
            }
            KeyCode::Enter => {
                let text = std::mem::take(buf);
                self.ui.edit = None;
                if !text.trim().is_empty() {
                    if let Err(e) = self.set_typed(self.selected_param(), &text) {
                        // in the panel's words (t·q_r, p*), not the preset's keys
                        self.fail(crate::tui::model::words::describe(&e));
                    }
                }
            }
            KeyCode::Char(c) if buf.chars().count() < 64 => buf.push(c),
            _ => {}
        }
    }

    pub(crate) fn on_picker_key(&mut self, ev: KeyEvent, cursor: usize) {
        let n = self.params.presets.len().max(1);
        match ev.code {
            KeyCode::Up | KeyCode::Char('k') => self.ui.overlay = Overlay::Presets((cursor + n - 1) % n),
            KeyCode::Down | KeyCode::Char('j') | KeyCode::Tab => self.ui.overlay = Overlay::Presets((cursor + 1) % n),
            KeyCode::Enter => {
                self.ui.overlay = Overlay::None;
                if let Some(e) = self.params.presets.get(cursor).cloned() {
                    self.load_preset(&e.source);
                }
            }
            KeyCode::Char('q') => self.ui.quit = true,
            _ => self.ui.overlay = Overlay::None,
        }
    }

    /// Starts walking `tour` at step `step`.
    pub fn start_tour(&mut self, tour: Tour, step: usize) {
        let step = step.min(tour.steps.len().saturating_sub(1));
        self.ui.tour = Some(TourState { tour, step });
        self.apply_step();
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
        self.params.history.reset();
        self.ui.charts = st.charts;
        self.ui.all_models = st.models;
        // a step that shows the scale view plays it from q_L
        self.ui.playing = self.shows_scales();
        self.ui.frame = self.ui.playing.then_some(0);
        self.ui.focus = 0;
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

    /// Loads a preset by name or path; on error the current one stays and the error shows.
    pub fn load_preset(&mut self, source: &str) {
        match Preset::resolve(source).and_then(|p| initial_scene(&p).map(|s| (p, s))) {
            Ok((p, s)) => {
                self.params.source = source.to_string();
                self.params.preset = p;
                self.params.base = s.clone();
                self.params.anchors = Anchors::default();
                self.set_scene(s);
                self.params.history.reset();
                self.info(format!("preset {}", self.params.preset.name));
            }
            Err(e) => self.fail(e),
        }
    }

    pub(crate) fn set_scene(&mut self, scene: Scene) {
        if scene != self.params.scene {
            self.jobs.pending = true;
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
        let Some(Ok(sw)) = &self.results.sweep else { return };
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

#[cfg(test)]
#[path = "update_tests.rs"]
mod tests;

#[cfg(test)]
#[path = "keys_tests.rs"]
mod keys_tests;
