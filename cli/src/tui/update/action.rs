//! An action of the key table → the next state, and the commands it asks for (files, GFMD,
//! a tour to load).

use crate::tui::base::keys::Action;
use crate::tui::base::kinds::ChartKind;
use crate::tui::model::app::*;

impl App {
    /// Performs an action of the key table; the command it asks for, if any.
    pub fn act(&mut self, action: Action) -> Option<Command> {
        let n = self.knob_rows().len();
        match action {
            Action::Up => self.ui.selected = (self.ui.selected + n - 1) % n,
            Action::Down => self.ui.selected = (self.ui.selected + 1) % n,
            Action::Dec => return self.step(-1, false),
            Action::Inc => return self.step(1, false),
            Action::DecCoarse => return self.step(-1, true),
            Action::IncCoarse => return self.step(1, true),
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
                self.params.history.reset_to(self.params.preset.follows_unloading());
                self.set_scene(self.params.base.clone());
                self.info(format!("reset to preset {}", self.params.preset.name));
            }
            Action::Export => return Some(self.export(false)),
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
                    let name = crate::tui::base::tour::DEFAULT_TOUR.to_string();
                    return Some(Command::LoadTour(name));
                }
            }
            Action::Save => return Some(self.export(true)),
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
            Action::Gfmd => return self.toggle_gfmd(),
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
                    crate::tui::base::wrap::caption_rows_at_most(&t.tour.steps[t.step].caption)
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
                if matches!(self.jobs.gfmd(), GfmdState::Running { .. }) {
                    return self.toggle_gfmd();
                } else if self.ui.zoom {
                    self.ui.zoom = false;
                } else {
                    self.info("nothing to cancel: q quits");
                }
            }
            Action::Quit => self.ui.quit = true,
        }
        None
    }

    /// `e` (`charts` false) or `s`: the files, with the data the screen shows now.
    fn export(&self, charts: bool) -> Command {
        Command::Export(Box::new(crate::tui::charts::snapshot::export_job(self, charts)))
    }
}
