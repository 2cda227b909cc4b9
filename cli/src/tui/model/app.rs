//! The explorer's state: the scene, the knobs, the charts, the results shown, plain data with
//! pure stepping helpers (grids of p*, t·q_r and γ_s) and the queries the view asks (which
//! results are current, what the charts need). Keys change it in [`crate::tui::update`]; work that
//! leaves the process (engine jobs, files) is done by [`crate::tui::effects::files`] and the worker.

pub use crate::tui::model::command::Command;
use crate::tui::model::data::{
    GfmdView, PointData, ScaleFrame, ScalesData, SweepData, ThicknessData, ADHESION_BY_DEFAULT,
};
use crate::tui::model::kinds::{self as charts, ChartKind, Needs};
pub use crate::tui::model::knobs::*;
use crate::tui::model::progress::same_system;
pub use crate::tui::model::progress::GfmdState;
use crate::tui::model::protocol::{point_key, scales_key, sweep_key, thickness_key, CacheKey, Request};
use crate::tui::model::tour::Tour;
use asperity::error::Result;
use asperity::input::model::{Model, ModelKind};
use asperity::input::preset::{self, Preset};
use asperity::input::scene::Scene;
use asperity::surface::heightmap::Surface;
use asperity::surface::spectrum::Spectrum;
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
/// What covers the main view.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Overlay {
    /// Nothing.
    None,
    /// The key help.
    Help,
    /// The preset picker, with its cursor.
    Presets(usize),
}

/// The tour being walked (`t`, `asperity tour`).
#[derive(Debug, Clone, PartialEq)]
pub struct TourState {
    /// The tour.
    pub tour: Tour,
    /// The current step.
    pub step: usize,
}

/// The charts the explorer opens with: Pr(σ*) big, a_r(p*) and ū(p*) small.
pub const DEFAULT_CHARTS: [ChartKind; 3] = [ChartKind::Pr, ChartKind::Area, ChartKind::Gap];

/// One entry of the preset picker.
#[derive(Debug, Clone, PartialEq)]
pub struct PresetEntry {
    /// Name or path passed to [`Preset::resolve`].
    pub source: String,
    /// Where it comes from ("built-in", a path).
    pub place: String,
}

/// A line for the status bar.
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    /// Text.
    pub text: String,
    /// Whether it reports a problem.
    pub error: bool,
}

/// The explorer's state.
#[derive(Debug)]
pub struct App {
    /// Presets the picker offers.
    pub presets: Vec<PresetEntry>,
    /// The current preset's source (name or path).
    pub source: String,
    /// The current preset.
    pub preset: Preset,
    /// The preset's scene (what `r` goes back to).
    pub base: Scene,
    /// The scene being explored.
    pub scene: Scene,
    /// Selected row of [`App::params`].
    pub selected: usize,
    /// The value being typed, if any.
    pub edit: Option<String>,
    /// Typed values that anchor their knob's grid (see [`Anchors`]).
    pub anchors: Anchors,
    /// Overlay.
    pub overlay: Overlay,
    /// The charts of the big panel, the lower-left and the lower-right panel.
    pub charts: [ChartKind; 3],
    /// First row of the help shown (the help scrolls where the terminal is short).
    pub help_scroll: usize,
    /// First line of the tour's caption shown (it scrolls where the terminal is short).
    pub caption_scroll: usize,
    /// The panel the chart selector (`v`) changes.
    pub focus: usize,
    /// The focused chart fills the screen (`z`).
    pub zoom: bool,
    /// The linear Pr chart has a log density axis (`y`).
    pub log_pr: bool,
    /// The last `e`/`s`: its scene, file name, number and the keys done under that number.
    /// The last `e`/`s`: its scene, file name, number, and whether `e` and `s` were done
    /// under that number.
    pub last_export: Option<(Scene, String, u32, [bool; 2])>,
    /// Overlay every model on the charts (`M`).
    pub all_models: bool,
    /// Results of the other models (`M`), by cache key.
    pub overlay_points: HashMap<CacheKey, Result<PointData>>,
    /// Load sweeps of the other models, by cache key.
    pub overlay_sweeps: HashMap<CacheKey, Result<SweepData>>,
    /// Thickness sweeps of the other models, by cache key.
    pub overlay_thickness: HashMap<CacheKey, Result<ThicknessData>>,
    /// a_r(t·q_r) at the current p*.
    pub thickness: Option<Result<ThicknessData>>,
    /// The key of the shown point (None: set directly, e.g. in tests).
    pub point_shown: Option<CacheKey>,
    /// The key of the shown load sweep.
    pub sweep_shown: Option<CacheKey>,
    /// The key of the shown gap.
    pub gap_shown: Option<CacheKey>,
    /// The key of the shown thickness sweep.
    pub thickness_shown: Option<CacheKey>,
    /// The scale view: Pr(σ*, q) frames from q_L to q_s.
    pub scales: Option<Result<ScalesData>>,
    /// The key of the shown scale view.
    pub scales_shown: Option<CacheKey>,
    /// Pinned curves (`P`), oldest first.
    pub pins: Vec<crate::tui::model::pins::Pin>,
    /// The scale view's frame (None: the last, at q_s).
    pub frame: Option<usize>,
    /// The scale view plays (one frame per tick).
    pub playing: bool,
    /// The tour, when one is being walked.
    pub tour: Option<TourState>,
    /// The branch of a hysteresis the user's path has reached (`r` resets it).
    pub history: crate::tui::model::history::LoadHistory,
    /// Show the adhesionless comparison in the Pr chart.
    pub compare: bool,
    /// Status-bar message (cleared by the next key).
    pub message: Option<Message>,
    /// Generation of the newest request.
    pub gen: u64,
    /// The load charts' p* range of the last request (see [`sticky_range`]).
    pub load_range: Option<(f64, f64)>,
    /// The current point (for the current scene, or the last one while computing).
    pub point: Option<Result<PointData>>,
    /// Generation of the request whose reply set [`App::point`].
    pub point_gen: u64,
    /// The load curves.
    pub sweep: Option<Result<SweepData>>,
    /// ū/h_rms at the current point.
    pub gap: Option<Result<f64>>,
    /// A request is being served.
    pub busy: bool,
    /// When the current request was made (while busy).
    pub busy_since: Option<std::time::Instant>,
    /// Spinner phase (advanced by ticks while busy).
    pub spinner: usize,
    /// Set when the user quits.
    pub quit: bool,
    /// Show compute times (off in snapshot tests: they vary from run to run).
    pub show_timing: bool,
    /// Use colour (off under `NO_COLOR`).
    pub color: bool,
    /// Where `e` writes.
    pub export_dir: PathBuf,
    /// The measured height map of `tui --surface` (its file name, as the tabulated spectrum
    /// names it, and the map): `g` runs GFMD on it while the scene is on its spectrum.
    pub map: Option<(String, Arc<Surface>)>,
    /// The background GFMD run (started with `g`).
    pub gfmd: GfmdState,
    pub(crate) gfmd_cancel: Option<Arc<AtomicBool>>,
    pub(crate) gfmd_next: u64,
    /// The scene or the charts changed since the last request.
    pub(crate) pending: bool,
    /// Work the update asked for (files, GFMD, quitting), taken with the computation by
    /// [`App::take_commands`].
    pub commands: Vec<Command>,
}

impl App {
    /// A fresh explorer on `preset` (resolved from `source`).
    pub fn new(source: &str, preset: Preset) -> Result<App> {
        let base = initial_scene(&preset)?;
        let mut presets: Vec<PresetEntry> = preset::list_available()
            .into_iter()
            .map(|(name, place)| PresetEntry { source: name, place })
            .collect();
        if !presets.iter().any(|e| e.source == source) {
            presets.push(PresetEntry {
                source: source.to_string(),
                place: "--preset".into(),
            });
        }
        Ok(App {
            presets,
            source: source.to_string(),
            preset,
            scene: base.clone(),
            base,
            selected: 2,
            edit: None,
            overlay: Overlay::None,
            charts: DEFAULT_CHARTS,
            focus: 0,
            zoom: false,
            log_pr: false,
            last_export: None,
            help_scroll: 0,
            caption_scroll: 0,
            anchors: Anchors::default(),
            all_models: false,
            overlay_points: HashMap::new(),
            overlay_sweeps: HashMap::new(),
            overlay_thickness: HashMap::new(),
            thickness: None,
            point_shown: None,
            sweep_shown: None,
            gap_shown: None,
            thickness_shown: None,
            scales: None,
            scales_shown: None,
            frame: None,
            playing: false,
            pins: Vec::new(),
            tour: None,
            history: Default::default(),
            compare: true,
            message: None,
            gen: 0,
            load_range: None,
            point: None,
            point_gen: 0,
            sweep: None,
            gap: None,
            busy: false,
            busy_since: None,
            spinner: 0,
            quit: false,
            show_timing: true,
            color: true,
            export_dir: PathBuf::from("."),
            map: None,
            gfmd: GfmdState::Idle,
            gfmd_cancel: None,
            gfmd_next: 0,
            pending: true,
            commands: Vec::new(),
        })
    }

    /// The rows of the parameter panel (the custom coefficients only for the custom model).
    pub fn params(&self) -> Vec<Param> {
        let mut v = BASIC.to_vec();
        if self.scene.model().kind == ModelKind::Custom {
            v.extend(CUSTOM);
        }
        v
    }

    /// The selected parameter.
    pub fn selected_param(&self) -> Param {
        let p = self.params();
        p[self.selected.min(p.len() - 1)]
    }

    /// The request the worker should serve next, if the scene changed since the last one.
    pub fn take_request(&mut self) -> Option<Request> {
        if !self.pending {
            return None;
        }
        self.pending = false;
        self.gen += 1;
        self.busy = true;
        self.busy_since = Some(std::time::Instant::now());
        let models = if self.all_models {
            charts::overlay_models(&self.scene.model())
                .into_iter()
                .filter(|m| charts::slot(m) != charts::slot(&self.scene.model()))
                .collect()
        } else {
            Vec::new()
        };
        let range = self.range();
        self.load_range = Some(range);
        Some(Request {
            gen: self.gen,
            source: self.source.clone(),
            scene: self.scene.clone(),
            range,
            needs: self.needs(),
            models,
        })
    }

    /// The measured map GFMD runs on for `scene`: [`App::map`] while the scene's spectrum is
    /// the one tabulated from it (None on a preset's spectrum or a PSD table).
    pub fn map_of(&self, scene: &Scene) -> Option<&Surface> {
        match (scene.spectrum(), &self.map) {
            (Spectrum::Tabulated(t), Some((name, map))) if t.source == *name => Some(map),
            _ => None,
        }
    }

    /// What the visible charts need computed.
    pub fn needs(&self) -> Needs {
        self.charts.iter().fold(Needs::default(), |n, c| n.or(c.needs()))
    }

    /// The scene with another model; None where the scene does not take it (a variant
    /// defined on the adhesionless half-space only, on an adhesive or slab scene).
    pub(crate) fn with_model(&self, m: &Model) -> Option<Scene> {
        self.scene.clone().with_model(*m).ok()
    }

    /// The point of model `m` at the current scene (the current point for the current model).
    pub fn model_point(&self, m: &Model) -> Option<&PointData> {
        if charts::slot(m) == charts::slot(&self.scene.model()) {
            return self.point.as_ref().and_then(|r| r.as_ref().ok());
        }
        let key = point_key(&self.source, &self.with_model(m)?);
        self.overlay_points.get(&key).and_then(|r| r.as_ref().ok())
    }

    /// The load sweep of model `m`.
    pub fn model_sweep(&self, m: &Model) -> Option<&SweepData> {
        if charts::slot(m) == charts::slot(&self.scene.model()) {
            return self.sweep.as_ref().and_then(|r| r.as_ref().ok());
        }
        let key = sweep_key(&self.source, &self.with_model(m)?, self.range());
        self.overlay_sweeps.get(&key).and_then(|r| r.as_ref().ok())
    }

    /// The thickness sweep of model `m`.
    pub fn model_thickness(&self, m: &Model) -> Option<&ThicknessData> {
        if charts::slot(m) == charts::slot(&self.scene.model()) {
            return self.thickness.as_ref().and_then(|r| r.as_ref().ok());
        }
        let key = thickness_key(&self.source, &self.with_model(m)?);
        self.overlay_thickness.get(&key).and_then(|r| r.as_ref().ok())
    }

    /// Whether the shown point belongs to an earlier scene.
    pub fn point_is_stale(&self) -> bool {
        self.point_shown
            .as_ref()
            .is_some_and(|k| *k != point_key(&self.source, &self.scene))
    }

    /// Whether the shown load sweep belongs to an earlier scene.
    pub fn sweep_is_stale(&self) -> bool {
        self.sweep_shown
            .as_ref()
            .is_some_and(|k| *k != sweep_key(&self.source, &self.scene, self.range()))
    }

    /// Whether the shown gap belongs to an earlier scene.
    pub fn gap_is_stale(&self) -> bool {
        self.gap_shown
            .as_ref()
            .is_some_and(|k| *k != point_key(&self.source, &self.scene))
    }

    /// Whether the shown thickness sweep belongs to an earlier scene.
    pub fn thickness_is_stale(&self) -> bool {
        self.thickness_shown
            .as_ref()
            .is_some_and(|k| *k != thickness_key(&self.source, &self.scene))
    }

    /// Whether the shown scale view belongs to an earlier scene.
    pub fn scales_is_stale(&self) -> bool {
        self.scales_shown
            .as_ref()
            .is_some_and(|k| *k != scales_key(&self.source, &self.scene))
    }

    /// The scale view, if computed.
    pub fn scales_data(&self) -> Option<&ScalesData> {
        self.scales.as_ref().and_then(|r| r.as_ref().ok())
    }

    /// The scale view's current frame: its index, the number of frames and the frame.
    pub fn scale_frame(&self) -> Option<(usize, usize, &ScaleFrame)> {
        let d = self.scales_data()?;
        let n = d.frames.len();
        let i = self.frame.unwrap_or(usize::MAX).min(n.checked_sub(1)?);
        Some((i, n, &d.frames[i]))
    }

    /// Whether a scale chart is shown.
    pub fn shows_scales(&self) -> bool {
        self.charts
            .iter()
            .any(|c| matches!(c, ChartKind::Scales | ChartKind::ScalesArea))
    }

    /// Whether the event loop must tick without input (a computation runs, GFMD runs: its
    /// clock, or the scale view plays).
    pub fn animating(&self) -> bool {
        self.busy || matches!(self.gfmd, GfmdState::Running { .. }) || (self.playing && self.shows_scales())
    }

    /// ū/h_rms at the current point, if computed.
    pub fn gap_value(&self) -> Option<f64> {
        match &self.gap {
            Some(Ok(g)) => Some(*g),
            _ => None,
        }
    }

    /// Whether eq. (18) describes the scene (adhesionless, semi-infinite).
    pub fn eq18_applies(&self) -> bool {
        self.scene.surface_energy_j_m2() == 0.0 && self.scene.thickness_qr().is_infinite()
    }

    /// Shows `charts` in the big, lower-left and lower-right panels.
    pub fn set_charts(&mut self, charts: [ChartKind; 3]) {
        self.charts = charts;
        self.refresh();
    }

    /// Asks for the charts' data again (after the charts or `M` changed; cached parts are
    /// instant).
    pub(crate) fn refresh(&mut self) {
        self.pending = true;
    }

    /// Keys of the other models' results for the current scene (for keeping replies).
    pub(crate) fn overlay_keys(&self) -> (Vec<CacheKey>, Vec<CacheKey>, Vec<CacheKey>) {
        let mut p = Vec::new();
        let mut sw = Vec::new();
        let mut t = Vec::new();
        if self.all_models {
            for s in charts::overlay_models(&self.scene.model())
                .iter()
                .filter_map(|m| self.with_model(m))
            {
                p.push(point_key(&self.source, &s));
                sw.push(sweep_key(&self.source, &s, self.range()));
                t.push(thickness_key(&self.source, &s));
            }
        }
        (p, sw, t)
    }

    /// Whether the scene changed since the last request.
    pub fn has_pending(&self) -> bool {
        self.pending
    }

    /// The p* range the load charts show ([`sticky_range`] of the last request's).
    pub fn range(&self) -> (f64, f64) {
        sticky_range(self.load_range, self.scene.pressure())
    }

    /// The finished GFMD result, when it was run on the scene shown now (the model only
    /// matters for the theory, so it is not compared).
    pub fn gfmd_for_scene(&self) -> Option<&GfmdView> {
        match &self.gfmd {
            GfmdState::Done {
                scene, result: Ok(v), ..
            } if same_system(scene, &self.scene) => Some(v),
            _ => None,
        }
    }

    /// Advances the spinner and, while the scale view plays, its frame (called on ticks; the
    /// play stops at the last frame).
    pub fn tick(&mut self) {
        self.spinner = self.spinner.wrapping_add(1);
        if self.playing {
            match self.scale_frame() {
                Some((i, n, _)) if i + 1 < n => self.frame = Some(i + 1),
                Some(_) => {
                    self.playing = false;
                    self.frame = None;
                }
                None => {}
            }
        }
    }

    /// Moves the scale view `dir` frames (stops at the ends; pauses a play).
    pub fn scrub(&mut self, dir: i32) {
        self.playing = false;
        if let Some((i, n, _)) = self.scale_frame() {
            let j = (i as i64 + i64::from(dir)).clamp(0, n as i64 - 1) as usize;
            self.frame = if j + 1 == n { None } else { Some(j) };
        } else {
            self.info("no scale view: v picks the scales chart");
        }
    }

    /// Plays the scale view from its first frame (or from where it stands), or pauses it.
    pub fn toggle_play(&mut self) {
        if self.playing {
            self.playing = false;
            return;
        }
        match self.scale_frame() {
            Some((i, n, _)) => {
                self.playing = true;
                if i + 1 >= n {
                    self.frame = Some(0);
                }
            }
            None if self.shows_scales() => {
                // play as soon as the frames arrive
                self.playing = true;
                self.frame = Some(0);
            }
            None => self.info("no scale view: v picks the scales chart"),
        }
    }

    /// The first error of the current results, for the status bar.
    pub fn compute_error(&self) -> Option<String> {
        use crate::tui::model::words::describe;
        if let Some(Err(e)) = &self.point {
            return Some(describe(e));
        }
        if let Some(Err(e)) = &self.sweep {
            return Some(format!("load sweep: {}", describe(e)));
        }
        if let Some(Err(e)) = &self.gap {
            return Some(format!("mean gap: {}", describe(e)));
        }
        if self.shows_scales() {
            if let Some(Err(e)) = &self.scales {
                return Some(format!("scale view: {}", describe(e)));
            }
        }
        if self.charts.contains(&ChartKind::Thickness) {
            if let Some(Err(e)) = &self.thickness {
                return Some(format!("thickness chart: {}", describe(e)));
            }
        }
        None
    }

    /// Why the current point has no error bar, if so (shown in the status line).
    pub fn compute_warning(&self) -> Option<String> {
        match &self.point {
            Some(Ok(p)) => p.warning.as_ref().map(|w| format!("a_r without error bar: {w}")),
            _ => None,
        }
    }

    pub(crate) fn info(&mut self, text: impl Into<String>) {
        self.message = Some(Message {
            text: text.into(),
            error: false,
        });
    }

    pub(crate) fn fail(&mut self, e: impl std::fmt::Display) {
        self.message = Some(Message {
            text: e.to_string(),
            error: true,
        });
    }
}

/// Inserts into a reply map, forgetting everything when it grows past a few hundred entries.
pub(crate) fn bounded_insert<V>(map: &mut HashMap<CacheKey, V>, key: CacheKey, v: V) {
    if map.len() >= 256 {
        map.clear();
    }
    map.insert(key, v);
}

/// The scene the explorer opens a preset with (γ_s per [`ADHESION_BY_DEFAULT`]).
pub fn initial_scene(p: &Preset) -> Result<Scene> {
    let mut s = p.scene()?;
    if !ADHESION_BY_DEFAULT {
        s = s.without_adhesion();
    }
    Ok(s)
}
