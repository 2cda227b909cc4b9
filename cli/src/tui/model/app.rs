//! The explorer's state, [`App`]: four plain-data parts ([`Params`], [`Ui`], [`Results`],
//! [`Jobs`]) and the queries the view and the update ask (which results are current, what the
//! charts need, the request for the worker). Messages change it in [`crate::tui::update`];
//! work that leaves the process (the worker, GFMD, files) is run by [`crate::tui::effects`].

use crate::tui::base::data::{PointData, ScaleFrame, ScalesData, SweepData, ThicknessData, ADHESION_BY_DEFAULT};
use crate::tui::base::gfmd_view::GfmdView;
use crate::tui::base::kinds::{self as charts, ChartKind, Needs};
use crate::tui::base::progress::same_system;
pub use crate::tui::base::progress::GfmdState;
use crate::tui::base::protocol::{Request, SceneKeys};
pub use crate::tui::model::command::Command;
pub use crate::tui::model::jobs::Jobs;
pub use crate::tui::model::knobs::*;
pub use crate::tui::model::params::{Params, PresetEntry};
pub use crate::tui::model::results::{Results, Slot};
pub use crate::tui::model::ui::{Message, Overlay, TourState, Ui};
use asperity::error::Result;
use asperity::input::model::{Model, ModelKind};
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::heightmap::Surface;
use asperity::surface::spectrum::Spectrum;
use std::path::PathBuf;

/// The charts the explorer opens with: Pr(σ*) big, a_r(p*) and ū(p*) small.
pub const DEFAULT_CHARTS: [ChartKind; 3] = [ChartKind::Pr, ChartKind::Area, ChartKind::Gap];

/// The explorer's state, in four plain-data parts.
#[derive(Debug)]
pub struct App {
    /// The scene's parameters: the presets, the preset, the scene being explored and the path of loads it took.
    pub params: Params,
    /// What the screen shows and how: the knob selected, the charts, overlays, the tour, the status line.
    pub ui: Ui,
    /// The engine's results for the scene and the curves pinned (each with the key of the scene it was computed for).
    pub results: Results,
    /// The work under way: the worker's requests, the GFMD run, the files written.
    pub jobs: Jobs,
}

impl App {
    /// A fresh explorer on `preset` (resolved from `source`), whose picker lists `listed`
    /// (name, where) as `asperity::input::preset::list_available` gives them (read by the
    /// effects: `App::new` there lists them and calls this).
    pub fn open(source: &str, preset: Preset, listed: Vec<(String, String)>) -> Result<App> {
        let base = initial_scene(&preset)?;
        let keys = SceneKeys::of(source, &base, sticky_range(None, base.pressure()));
        let mut presets: Vec<PresetEntry> = listed
            .into_iter()
            .map(|(name, place)| PresetEntry { source: name, place })
            .collect();
        if !presets.iter().any(|e| e.source == source) {
            presets.push(PresetEntry {
                source: source.to_string(),
                place: "--preset".into(),
            });
        }
        let mut history = crate::tui::model::history::LoadHistory::new();
        history.reset_to(preset.follows_unloading());
        Ok(App {
            params: Params {
                presets,
                source: source.to_string(),
                preset,
                scene: base.clone(),
                base,
                anchors: Anchors::default(),
                history,
                map: None,
                measured: None,
            },
            ui: Ui {
                selected: 2,
                edit: None,
                overlay: Overlay::None,
                charts: DEFAULT_CHARTS,
                help_scroll: 0,
                caption_scroll: 0,
                focus: 0,
                zoom: false,
                log_pr: false,
                all_models: false,
                compare: true,
                message: None,
                frame: None,
                playing: false,
                tour: None,
                quit: false,
                show_timing: true,
                color: true,
                mouse: false,
                spinner: 0,
                now: None,
                size: None,
            },
            results: Results::new(keys),
            jobs: Jobs::new(PathBuf::from(".")),
        })
    }

    /// The rows of the parameter panel (the custom coefficients only for the custom model).
    pub fn knob_rows(&self) -> Vec<Param> {
        let mut v = BASIC.to_vec();
        if self.params.scene.model().kind == ModelKind::Custom {
            v.extend(CUSTOM);
        }
        v
    }

    /// The selected parameter.
    pub fn selected_param(&self) -> Param {
        let p = self.knob_rows();
        p[self.ui.selected.min(p.len() - 1)]
    }

    /// The request the worker should serve next, if the scene changed since the last one.
    pub fn take_request(&mut self) -> Option<Request> {
        if !self.jobs.pending {
            return None;
        }
        self.jobs.pending = false;
        self.jobs.gen += 1;
        self.jobs.busy = true;
        self.jobs.busy_since = self.ui.now;
        let models = if self.ui.all_models {
            charts::overlay_models(&self.params.scene)
                .into_iter()
                .filter(|m| charts::slot(m) != charts::slot(&self.params.scene.model()))
                .collect()
        } else {
            Vec::new()
        };
        let range = self.range();
        self.jobs.load_range = Some(range);
        let needs = self.needs();
        self.jobs.asked = needs;
        Some(Request {
            gen: self.jobs.gen,
            source: self.params.source.clone(),
            scene: self.params.scene.clone(),
            range,
            needs,
            models,
        })
    }

    /// The measured map GFMD runs on for `scene`: [`Params::map`] while the scene's spectrum is
    /// the one tabulated from it (None on a preset's spectrum or a PSD table).
    pub fn map_of(&self, scene: &Scene) -> Option<&Surface> {
        self.map_entry(scene).map(|m| &**m)
    }

    /// [`App::map_of`], shared (a GFMD run carries it to its thread).
    pub fn shared_map_of(&self, scene: &Scene) -> Option<std::sync::Arc<Surface>> {
        self.map_entry(scene).cloned()
    }

    fn map_entry(&self, scene: &Scene) -> Option<&std::sync::Arc<Surface>> {
        match (scene.spectrum(), &self.params.map) {
            (Spectrum::Tabulated(t), Some((name, map))) if t.source == *name => Some(map),
            _ => None,
        }
    }

    /// The charts the screen shows (indices into [`Ui::charts`]): those the terminal's size
    /// holds ([`crate::tui::base::wrap::shown_charts`]: all three at 160×48, the focused one
    /// at 80×24, the focused one under `z`); all three while the size is unknown.
    pub fn shown_charts(&self) -> Vec<usize> {
        let Some((cols, rows)) = self.ui.size else {
            return vec![0, 1, 2];
        };
        let caption = self
            .ui
            .tour
            .as_ref()
            .map(|t| t.tour.steps[t.step].caption.as_slice())
            .unwrap_or_default();
        crate::tui::base::wrap::shown_charts(cols, rows, caption, self.ui.focus, self.ui.zoom)
    }

    /// What the charts shown need computed: a chart not on screen is computed when it is
    /// shown (`App::follow_shown`).
    pub fn needs(&self) -> Needs {
        self.shown_charts()
            .into_iter()
            .fold(Needs::default(), |n, i| n.or(self.ui.charts[i].needs()))
    }

    /// Asks for the computation again where a chart now shown (after `z`, `f`, `v`, a
    /// resize, a tour step) needs what the last request left out.
    pub(crate) fn follow_shown(&mut self) {
        let n = self.needs();
        let asked = self.jobs.asked;
        let covered = (!n.point || asked.point)
            && (!n.loads || asked.loads)
            && (!n.thickness || asked.thickness)
            && (!n.scales || asked.scales);
        if !covered {
            self.refresh();
        }
    }

    /// The point of model `m` at the current scene (the current point for the current model).
    pub fn model_point(&self, m: &Model) -> Option<&PointData> {
        if charts::slot(m) == charts::slot(&self.params.scene.model()) {
            return self.results.point().and_then(|r| r.as_ref().ok());
        }
        let key = &self.results.keys().of_model(m)?[0];
        self.results.overlay_point(key)
    }

    /// The load sweep of model `m`.
    pub fn model_sweep(&self, m: &Model) -> Option<&SweepData> {
        if charts::slot(m) == charts::slot(&self.params.scene.model()) {
            return self.results.sweep().and_then(|r| r.as_ref().ok());
        }
        let key = &self.results.keys().of_model(m)?[1];
        self.results.overlay_sweep(key)
    }

    /// The thickness sweep of model `m`.
    pub fn model_thickness(&self, m: &Model) -> Option<&ThicknessData> {
        if charts::slot(m) == charts::slot(&self.params.scene.model()) {
            return self.results.thickness().and_then(|r| r.as_ref().ok());
        }
        let key = &self.results.keys().of_model(m)?[2];
        self.results.overlay_thickness(key)
    }

    /// Whether the shown point belongs to an earlier scene.
    pub fn point_is_stale(&self) -> bool {
        self.results.is_stale(Slot::Point)
    }

    /// Whether the shown load sweep belongs to an earlier scene.
    pub fn sweep_is_stale(&self) -> bool {
        self.results.is_stale(Slot::Sweep)
    }

    /// Whether the shown gap belongs to an earlier scene.
    pub fn gap_is_stale(&self) -> bool {
        self.results.is_stale(Slot::Gap)
    }

    /// Whether the shown thickness sweep belongs to an earlier scene.
    pub fn thickness_is_stale(&self) -> bool {
        self.results.is_stale(Slot::Thickness)
    }

    /// Whether the shown scale view belongs to an earlier scene.
    pub fn scales_is_stale(&self) -> bool {
        self.results.is_stale(Slot::Scales)
    }

    /// The scale view, if computed.
    pub fn scales_data(&self) -> Option<&ScalesData> {
        self.results.scales().and_then(|r| r.as_ref().ok())
    }

    /// The scale view's current frame: its index, the number of frames and the frame.
    pub fn scale_frame(&self) -> Option<(usize, usize, &ScaleFrame)> {
        let d = self.scales_data()?;
        let n = d.frames.len();
        let i = self.ui.frame.unwrap_or(usize::MAX).min(n.checked_sub(1)?);
        Some((i, n, &d.frames[i]))
    }

    /// Whether a scale chart is shown.
    pub fn shows_scales(&self) -> bool {
        self.ui
            .charts
            .iter()
            .any(|c| matches!(c, ChartKind::Scales | ChartKind::ScalesArea))
    }

    /// Whether the event loop must tick without input (a computation runs, GFMD runs: its
    /// clock, or the scale view plays).
    pub fn animating(&self) -> bool {
        self.jobs.busy
            || matches!(self.jobs.gfmd(), GfmdState::Running { .. })
            || (self.ui.playing && self.shows_scales())
    }

    /// ū/h_rms at the current point, if computed.
    pub fn gap_value(&self) -> Option<f64> {
        match self.results.gap() {
            Some(Ok(g)) => Some(*g),
            _ => None,
        }
    }

    /// Whether eq. (18) describes the scene (adhesionless, semi-infinite).
    pub fn eq18_applies(&self) -> bool {
        self.params.scene.surface_energy_j_m2() == 0.0 && self.params.scene.thickness_qr().is_infinite()
    }

    /// Shows `charts` in the big, lower-left and lower-right panels.
    pub fn set_charts(&mut self, charts: [ChartKind; 3]) {
        self.ui.charts = charts;
        self.refresh();
    }

    /// Computes the scene's keys ([`Results::keys`]) where the preset, the scene or the load
    /// range changed since they were computed (a comparison, no hashing, when nothing did).
    pub fn rekey(&mut self) {
        let range = self.range();
        if !self.results.keys.is_for(&self.params.source, &self.params.scene, range) {
            self.results.keys = SceneKeys::of(&self.params.source, &self.params.scene, range);
        }
    }

    /// Asks for the charts' data again (after the charts or `M` changed; cached parts are
    /// instant).
    pub(crate) fn refresh(&mut self) {
        self.jobs.pending = true;
    }

    /// Whether the scene changed since the last request.
    pub fn has_pending(&self) -> bool {
        self.jobs.pending
    }

    /// The p* range the load charts show ([`sticky_range`] of the last request's).
    pub fn range(&self) -> (f64, f64) {
        sticky_range(self.jobs.load_range, self.params.scene.pressure())
    }

    /// The finished GFMD result, when it was run on the scene shown now (the model only
    /// matters for the theory, so it is not compared).
    pub fn gfmd_for_scene(&self) -> Option<&GfmdView> {
        match self.jobs.gfmd() {
            GfmdState::Done {
                scene, result: Ok(v), ..
            } if same_system(scene, &self.params.scene) => Some(v),
            _ => None,
        }
    }

    /// The first error of the current results, for the status bar.
    pub fn compute_error(&self) -> Option<String> {
        use crate::tui::base::words::describe;
        if let Some(Err(e)) = self.results.point() {
            return Some(describe(e));
        }
        if let Some(Err(e)) = self.results.sweep() {
            return Some(format!("load sweep: {}", describe(e)));
        }
        if let Some(Err(e)) = self.results.gap() {
            return Some(format!("mean gap: {}", describe(e)));
        }
        if self.shows_scales() {
            if let Some(Err(e)) = self.results.scales() {
                return Some(format!("scale view: {}", describe(e)));
            }
        }
        if self.ui.charts.contains(&ChartKind::Thickness) {
            if let Some(Err(e)) = self.results.thickness() {
                return Some(format!("thickness chart: {}", describe(e)));
            }
        }
        None
    }

    /// Why the current point has no error bar, if so (shown in the status line).
    pub fn compute_warning(&self) -> Option<String> {
        match self.results.point() {
            Some(Ok(p)) => p.warning.as_ref().map(|w| format!("a_r without error bar: {w}")),
            _ => None,
        }
    }

    pub(crate) fn info(&mut self, text: impl Into<String>) {
        self.ui.message = Some(Message {
            text: text.into(),
            error: false,
        });
    }

    pub(crate) fn fail(&mut self, e: impl std::fmt::Display) {
        self.ui.message = Some(Message {
            text: e.to_string(),
            error: true,
        });
    }
}

/// The scene the explorer opens a preset with (γ_s per [`ADHESION_BY_DEFAULT`]).
pub fn initial_scene(p: &Preset) -> Result<Scene> {
    let mut s = p.scene()?;
    if !ADHESION_BY_DEFAULT {
        s = s.without_adhesion();
    }
    Ok(s)
}
