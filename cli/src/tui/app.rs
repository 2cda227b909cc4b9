//! The explorer's state and key handling: pure (no terminal, no threads), so every key can be
//! unit-tested. The event loop ([`super::run`]) feeds it key events and worker replies and
//! forwards the [`Request`] it asks for ([`App::take_request`]) to the worker.

use super::charts::{self, ChartKind, Needs};
use super::data::{GfmdView, PointData, SweepData, ThicknessData, ADHESION_BY_DEFAULT};
use super::keys::{self, Action};
use super::tour::Tour;
use super::worker::{point_key, sweep_key, thickness_key, CacheKey, Reply, Request};
use asperity::error::{Error, Result};
use asperity::input::model::{Model, ModelKind};
use asperity::input::preset::{self, Preset};
use asperity::input::scene::Scene;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// An adjustable parameter (a row of the parameter panel).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// The preset.
    Preset,
    /// Model 1–4 or custom.
    Model,
    /// p*.
    Pressure,
    /// t·q_r (∞ = semi-infinite).
    Thickness,
    /// γ_s (0 = off).
    Gamma,
    /// Custom c₁.
    C1,
    /// Custom c₂.
    C2,
    /// Custom α.
    Alpha,
    /// Custom k_G.
    KGriffith,
    /// Custom σ_a cap.
    Cap,
}

impl Param {
    /// Label in the panel.
    pub fn label(self) -> &'static str {
        match self {
            Param::Preset => "preset",
            Param::Model => "model",
            Param::Pressure => "p*",
            Param::Thickness => "t·q_r",
            Param::Gamma => "γ_s J/m²",
            Param::C1 => "c1",
            Param::C2 => "c2",
            Param::Alpha => "alpha",
            Param::KGriffith => "k_G",
            Param::Cap => "cap σ_a",
        }
    }
}

const BASIC: [Param; 5] = [
    Param::Preset,
    Param::Model,
    Param::Pressure,
    Param::Thickness,
    Param::Gamma,
];
const CUSTOM: [Param; 5] = [Param::C1, Param::C2, Param::Alpha, Param::KGriffith, Param::Cap];

/// Steps per decade of the log-stepped parameters (fine, coarse).
pub const PRESSURE_STEPS: (f64, f64) = (20.0, 4.0);
/// p* range reachable with the arrow keys (typing reaches the engine's whole range).
pub const PRESSURE_KEYS: (f64, f64) = (1e-6, 1e2);
/// Steps per decade of t·q_r.
pub const THICKNESS_STEPS: (f64, f64) = (10.0, 2.0);
/// t·q_r range of the arrow keys; one step above the top is ∞.
pub const THICKNESS_KEYS: (f64, f64) = (1e-2, 1e4);
/// Steps per decade of γ_s.
pub const GAMMA_STEPS: (f64, f64) = (10.0, 2.0);
/// γ_s range of the arrow keys (J/m²); one step below the bottom is 0 (off).
pub const GAMMA_KEYS: (f64, f64) = (1e-4, 1.0);

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
    /// Overlay.
    pub overlay: Overlay,
    /// The charts of the big panel, the lower-left and the lower-right panel.
    pub charts: [ChartKind; 3],
    /// The panel the chart selector (`v`) changes.
    pub focus: usize,
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
    /// The tour, when one is being walked.
    pub tour: Option<TourState>,
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
    /// The background GFMD run (started with `g`).
    pub gfmd: GfmdState,
    /// A GFMD run to start (taken by the event loop).
    gfmd_request: Option<(u64, asperity::gfmd::GfmdSetup, Arc<AtomicBool>)>,
    gfmd_cancel: Option<Arc<AtomicBool>>,
    gfmd_next: u64,
    pending: bool,
}

/// The state of the background GFMD run.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum GfmdState {
    /// None started (or the last was cancelled).
    #[default]
    Idle,
    /// Running: id, the scene it runs, FIRE steps and residual so far.
    Running {
        /// Run id.
        id: u64,
        /// The scene it runs.
        scene: Scene,
        /// FIRE steps so far.
        iteration: usize,
        /// Residual so far.
        residual: f64,
    },
    /// Finished: the scene it ran and its outcome.
    Done {
        /// The scene it ran.
        scene: Scene,
        /// The result, or the error.
        result: std::result::Result<GfmdView, String>,
    },
}

/// Whether two scenes describe the same physical system (GFMD does not depend on the model).
fn same_system(a: &Scene, b: &Scene) -> bool {
    a.spectrum == b.spectrum
        && a.modulus == b.modulus
        && a.pressure == b.pressure
        && a.thickness_qr.to_bits() == b.thickness_qr.to_bits()
        && a.gamma == b.gamma
        && a.range == b.range
}

/// The p* range of the load charts for a current p*: at least 1e-3..1, widened to whole
/// decades that include p*.
pub fn chart_range(p: f64) -> (f64, f64) {
    let (lo, hi) = asperity::input::scene::PRESSURE_RANGE;
    let p = if p.is_finite() && p > 0.0 { p } else { 1e-2 };
    let a = 10f64.powf(p.log10().floor()).min(1e-3).max(lo);
    let b = 10f64.powf(p.log10().ceil()).max(1.0).min(hi);
    (a, b)
}

/// The p* range of the load charts after p* moved to `p`: the previous range while it still
/// holds p (stepping p* then reuses the cached load sweep: on system II's thin slab each
/// decade boundary crossed cost a new sweep, ~0.85 s, where a step inside the range redraws
/// every chart in 0.09–0.14 s), else [`chart_range`] of p (not the union: a wider range costs
/// more loads).
pub fn sticky_range(prev: Option<(f64, f64)>, p: f64) -> (f64, f64) {
    match prev {
        Some((a, b)) if p >= a && p <= b => (a, b),
        _ => chart_range(p),
    }
}

/// Next grid value of a log-stepped parameter: `steps` grid points up (or down) from `x` on
/// the grid of `per_decade` points per decade. Off-grid values go to the neighbouring point.
pub fn log_step(x: f64, per_decade: f64, steps: i32) -> f64 {
    log_step_from(x, 1.0, per_decade, steps)
}

/// [`log_step`] on the grid anchor·10^(k/per_decade), which contains `anchor` (the preset's
/// value), so stepping away and back returns to it exactly.
pub fn log_step_from(x: f64, anchor: f64, per_decade: f64, steps: i32) -> f64 {
    let anchor = if anchor.is_finite() && anchor > 0.0 {
        anchor
    } else {
        1.0
    };
    let u = (x / anchor).log10() * per_decade;
    let k = if steps > 0 {
        (u + 1e-9).floor() + steps as f64
    } else {
        (u - 1e-9).ceil() + steps as f64
    };
    if k == 0.0 {
        anchor
    } else {
        anchor * 10f64.powf(k / per_decade)
    }
}

/// An additive step on a grid of `step` (values snap to the grid, so toggling back is exact).
pub fn lin_step(x: f64, step: f64, steps: i32) -> f64 {
    let u = x / step;
    let k = if steps > 0 {
        (u + 1e-9).floor() + steps as f64
    } else {
        (u - 1e-9).ceil() + steps as f64
    };
    let v = k * step;
    // −0 → 0
    if v == 0.0 {
        0.0
    } else {
        v
    }
}

fn parse_number(field: &str, s: &str) -> Result<f64> {
    s.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| Error::field(field, s, "a number"))
}

fn parse_bool(field: &str, s: &str) -> Result<bool> {
    match s.trim().to_ascii_lowercase().as_str() {
        "1" | "y" | "yes" | "true" | "on" => Ok(true),
        "0" | "n" | "no" | "false" | "off" => Ok(false),
        _ => Err(Error::field(field, s, "yes or no")),
    }
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
            all_models: false,
            overlay_points: HashMap::new(),
            overlay_sweeps: HashMap::new(),
            overlay_thickness: HashMap::new(),
            thickness: None,
            point_shown: None,
            sweep_shown: None,
            gap_shown: None,
            thickness_shown: None,
            tour: None,
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
            gfmd: GfmdState::Idle,
            gfmd_request: None,
            gfmd_cancel: None,
            gfmd_next: 0,
            pending: true,
        })
    }

    /// The rows of the parameter panel (the custom coefficients only for the custom model).
    pub fn params(&self) -> Vec<Param> {
        let mut v = BASIC.to_vec();
        if self.scene.model.kind == ModelKind::Custom {
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
            charts::overlay_models(&self.scene.model)
                .into_iter()
                .filter(|m| charts::slot(m) != charts::slot(&self.scene.model))
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

    /// What the visible charts need computed.
    pub fn needs(&self) -> Needs {
        self.charts.iter().fold(Needs::default(), |n, c| n.or(c.needs()))
    }

    /// The scene with another model.
    fn with_model(&self, m: &Model) -> Scene {
        let mut s = self.scene.clone();
        s.model = *m;
        s
    }

    /// The point of model `m` at the current scene (the current point for the current model).
    pub fn model_point(&self, m: &Model) -> Option<&PointData> {
        if charts::slot(m) == charts::slot(&self.scene.model) {
            return self.point.as_ref().and_then(|r| r.as_ref().ok());
        }
        let key = point_key(&self.source, &self.with_model(m));
        self.overlay_points.get(&key).and_then(|r| r.as_ref().ok())
    }

    /// The load sweep of model `m`.
    pub fn model_sweep(&self, m: &Model) -> Option<&SweepData> {
        if charts::slot(m) == charts::slot(&self.scene.model) {
            return self.sweep.as_ref().and_then(|r| r.as_ref().ok());
        }
        let key = sweep_key(&self.source, &self.with_model(m), self.range());
        self.overlay_sweeps.get(&key).and_then(|r| r.as_ref().ok())
    }

    /// The thickness sweep of model `m`.
    pub fn model_thickness(&self, m: &Model) -> Option<&ThicknessData> {
        if charts::slot(m) == charts::slot(&self.scene.model) {
            return self.thickness.as_ref().and_then(|r| r.as_ref().ok());
        }
        let key = thickness_key(&self.source, &self.with_model(m));
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

    /// ū/h_rms at the current point, if computed.
    pub fn gap_value(&self) -> Option<f64> {
        match &self.gap {
            Some(Ok(g)) => Some(*g),
            _ => None,
        }
    }

    /// Whether eq. (18) describes the scene (adhesionless, semi-infinite).
    pub fn eq18_applies(&self) -> bool {
        self.scene.gamma == 0.0 && self.scene.thickness_qr.is_infinite()
    }

    /// Shows `charts` in the big, lower-left and lower-right panels.
    pub fn set_charts(&mut self, charts: [ChartKind; 3]) {
        self.charts = charts;
        self.refresh();
    }

    /// Asks for the charts' data again (after the charts or `M` changed; cached parts are
    /// instant).
    fn refresh(&mut self) {
        self.pending = true;
    }

    /// Keys of the other models' results for the current scene (for keeping replies).
    fn overlay_keys(&self) -> (Vec<CacheKey>, Vec<CacheKey>, Vec<CacheKey>) {
        let mut p = Vec::new();
        let mut sw = Vec::new();
        let mut t = Vec::new();
        if self.all_models {
            for m in charts::overlay_models(&self.scene.model) {
                let s = self.with_model(&m);
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
        sticky_range(self.load_range, self.scene.pressure)
    }

    /// Takes a worker reply: kept only if it belongs to the current scene.
    pub fn on_reply(&mut self, reply: Reply) {
        match reply {
            Reply::Point { gen, key, result } => {
                if key == point_key(&self.source, &self.scene) {
                    self.point_gen = self.point_gen.max(gen);
                    self.point = Some(result);
                    self.point_shown = Some(key);
                } else if self.overlay_keys().0.contains(&key) {
                    bounded_insert(&mut self.overlay_points, key, result);
                }
            }
            Reply::Sweep { key, result, .. } => {
                if key == sweep_key(&self.source, &self.scene, self.range()) {
                    self.sweep = Some(result);
                    self.sweep_shown = Some(key);
                } else if self.overlay_keys().1.contains(&key) {
                    bounded_insert(&mut self.overlay_sweeps, key, result);
                }
            }
            Reply::Gap { key, result, .. } => {
                if key == point_key(&self.source, &self.scene) {
                    self.gap = Some(result);
                    self.gap_shown = Some(key);
                }
            }
            Reply::Thickness { key, result, .. } => {
                if key == thickness_key(&self.source, &self.scene) {
                    self.thickness = Some(result);
                    self.thickness_shown = Some(key);
                } else if self.overlay_keys().2.contains(&key) {
                    bounded_insert(&mut self.overlay_thickness, key, result);
                }
            }
            Reply::GfmdProgress {
                id,
                iteration,
                residual,
            } => {
                if let GfmdState::Running {
                    id: cur,
                    iteration: it,
                    residual: res,
                    ..
                } = &mut self.gfmd
                {
                    if *cur == id {
                        *it = iteration;
                        *res = residual;
                        self.spinner = self.spinner.wrapping_add(1);
                    }
                }
            }
            Reply::GfmdDone { id, result } => {
                if let GfmdState::Running { id: cur, scene, .. } = &self.gfmd {
                    if *cur == id {
                        let scene = scene.clone();
                        self.gfmd_cancel = None;
                        if self
                            .message
                            .as_ref()
                            .is_some_and(|m| m.text.starts_with("GFMD started"))
                        {
                            self.message = None;
                        }
                        match result {
                            Err(Error::Cancelled) => self.gfmd = GfmdState::Idle,
                            r => {
                                self.gfmd = GfmdState::Done {
                                    scene,
                                    result: r.map_err(|e| e.to_string()),
                                }
                            }
                        }
                    }
                }
            }
            Reply::Done { gen } => {
                if gen == self.gen {
                    self.busy = false;
                    self.busy_since = None;
                }
            }
        }
    }

    /// `g`: starts a GFMD run of the current scene on the preset's reduced grid, or cancels
    /// the running one.
    pub fn toggle_gfmd(&mut self) {
        if let GfmdState::Running { .. } = self.gfmd {
            if let Some(c) = self.gfmd_cancel.take() {
                c.store(true, Ordering::Relaxed);
            }
            self.gfmd = GfmdState::Idle;
            self.gfmd_request = None;
            self.info("GFMD cancelled");
            return;
        }
        let grid = self
            .preset
            .gfmd
            .as_ref()
            .map(asperity::gfmd::GridSpec::from_preset)
            .unwrap_or(asperity::gfmd::GridSpec {
                system_size_ratio: 2.0,
                bandwidth: 32.0,
                points_per_short_wavelength: 8.0,
            });
        let setup = asperity::gfmd::GfmdSetup {
            scene: self.scene.clone(),
            grid,
            seed: 1,
            surface: None,
            rescale: true,
        };
        self.gfmd_next += 1;
        let id = self.gfmd_next;
        let cancel = Arc::new(AtomicBool::new(false));
        self.gfmd_cancel = Some(cancel.clone());
        self.gfmd_request = Some((id, setup, cancel));
        self.gfmd = GfmdState::Running {
            id,
            scene: self.scene.clone(),
            iteration: 0,
            residual: f64::NAN,
        };
        self.info(format!("GFMD started on a {0}x{0} grid (g cancels)", grid.n()));
    }

    /// The GFMD run to start, if `g` asked for one.
    pub fn take_gfmd_request(&mut self) -> Option<(u64, asperity::gfmd::GfmdSetup, Arc<AtomicBool>)> {
        self.gfmd_request.take()
    }

    /// The finished GFMD result, when it was run on the scene shown now (the model only
    /// matters for the theory, so it is not compared).
    pub fn gfmd_for_scene(&self) -> Option<&GfmdView> {
        match &self.gfmd {
            GfmdState::Done { scene, result: Ok(v) } if same_system(scene, &self.scene) => Some(v),
            _ => None,
        }
    }

    /// Advances the spinner (called on ticks while busy).
    pub fn tick(&mut self) {
        self.spinner = self.spinner.wrapping_add(1);
    }

    /// The first error of the current results, for the status bar.
    pub fn compute_error(&self) -> Option<String> {
        use super::words::describe;
        if let Some(Err(e)) = &self.point {
            return Some(describe(e));
        }
        if let Some(Err(e)) = &self.sweep {
            return Some(format!("load sweep: {}", describe(e)));
        }
        if let Some(Err(e)) = &self.gap {
            return Some(format!("mean gap: {}", describe(e)));
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

    fn info(&mut self, text: impl Into<String>) {
        self.message = Some(Message {
            text: text.into(),
            error: false,
        });
    }

    fn fail(&mut self, e: impl std::fmt::Display) {
        self.message = Some(Message {
            text: e.to_string(),
            error: true,
        });
    }

    /// Handles one key press.
    pub fn on_key(&mut self, ev: KeyEvent) {
        if ev.code == KeyCode::Char('c') && ev.modifiers.contains(KeyModifiers::CONTROL) {
            self.quit = true;
            return;
        }
        self.message = None;
        if self.edit.is_some() {
            self.on_edit_key(ev);
            return;
        }
        match self.overlay {
            Overlay::Help => {
                // any key closes the help; q still quits
                self.overlay = Overlay::None;
                if ev.code == KeyCode::Char('q') {
                    self.quit = true;
                }
                return;
            }
            Overlay::Presets(cursor) => {
                self.on_picker_key(ev, cursor);
                return;
            }
            Overlay::None => {}
        }
        if self.tour.is_some()
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
                self.edit = Some(c.to_string());
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
        let n = self.params().len();
        match action {
            Action::Up => self.selected = (self.selected + n - 1) % n,
            Action::Down => self.selected = (self.selected + 1) % n,
            Action::Dec => self.step(-1, false),
            Action::Inc => self.step(1, false),
            Action::DecCoarse => self.step(-1, true),
            Action::IncCoarse => self.step(1, true),
            Action::Edit => self.edit = Some(String::new()),
            Action::CycleModel => self.cycle_model(1),
            Action::Presets => {
                let cur = self.presets.iter().position(|e| e.source == self.source).unwrap_or(0);
                self.overlay = Overlay::Presets(cur);
            }
            Action::Reset => {
                self.set_scene(self.base.clone());
                self.info(format!("reset to preset {}", self.preset.name));
            }
            Action::Export => match super::export::export(self) {
                Ok(paths) => self.info(format!("exported {}", paths.join(", "))),
                Err(e) => self.fail(e),
            },
            Action::AreaMode => {
                let mut any = false;
                for c in &mut self.charts {
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
                let f = self.focus.min(2);
                self.charts[f] = self.charts[f].cycle(1);
                self.refresh();
            }
            Action::Focus => self.focus = (self.focus + 1) % 3,
            Action::Models => {
                self.all_models = !self.all_models;
                self.refresh();
            }
            Action::Tour => {
                if self.tour.is_some() {
                    self.leave_tour();
                } else {
                    match Tour::resolve(super::tour::DEFAULT_TOUR) {
                        Ok(t) => self.start_tour(t, 0),
                        Err(e) => self.fail(e),
                    }
                }
            }
            Action::Save => match super::export::export_charts(self) {
                Ok(paths) => self.info(format!("saved {}", paths.join(", "))),
                Err(e) => self.fail(e),
            },
            Action::Compare => self.compare = !self.compare,
            Action::Gfmd => self.toggle_gfmd(),
            Action::Help => self.overlay = Overlay::Help,
            Action::Quit => self.quit = true,
        }
    }

    fn on_edit_key(&mut self, ev: KeyEvent) {
        let Some(buf) = self.edit.as_mut() else {
            return;
        };
        match ev.code {
            // q cancels the field (a second q quits): no value contains a q
            KeyCode::Esc | KeyCode::Char('q') => self.edit = None,
            KeyCode::Backspace => {
                buf.pop();
            }
            KeyCode::Enter => {
                let text = std::mem::take(buf);
                self.edit = None;
                if !text.trim().is_empty() {
                    if let Err(e) = self.set_typed(self.selected_param(), &text) {
                        self.fail(e);
                    }
                }
            }
            KeyCode::Char(c) if buf.chars().count() < 64 => buf.push(c),
            _ => {}
        }
    }

    fn on_picker_key(&mut self, ev: KeyEvent, cursor: usize) {
        let n = self.presets.len().max(1);
        match ev.code {
            KeyCode::Up | KeyCode::Char('k') => self.overlay = Overlay::Presets((cursor + n - 1) % n),
            KeyCode::Down | KeyCode::Char('j') | KeyCode::Tab => self.overlay = Overlay::Presets((cursor + 1) % n),
            KeyCode::Enter => {
                self.overlay = Overlay::None;
                if let Some(e) = self.presets.get(cursor).cloned() {
                    self.load_preset(&e.source);
                }
            }
            KeyCode::Char('q') => self.quit = true,
            _ => self.overlay = Overlay::None,
        }
    }

    /// Starts walking `tour` at step `step`.
    pub fn start_tour(&mut self, tour: Tour, step: usize) {
        let step = step.min(tour.steps.len().saturating_sub(1));
        self.tour = Some(TourState { tour, step });
        self.apply_step();
    }

    /// Moves `dir` steps along the tour (stops at the ends).
    pub fn tour_go(&mut self, dir: i32) {
        let Some(t) = self.tour.as_mut() else { return };
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
        if self.tour.take().is_some() {
            if let Ok(s) = initial_scene(&self.preset) {
                self.base = s;
            }
            self.info("left the tour (t starts it again)");
        }
    }

    fn apply_step(&mut self) {
        let Some(t) = &self.tour else { return };
        let st = t.tour.steps[t.step].clone();
        if st.source != self.source || st.preset != self.preset {
            self.source = st.source.clone();
            self.preset = st.preset.clone();
            if !self.presets.iter().any(|e| e.source == st.source) {
                self.presets.push(PresetEntry {
                    source: st.source.clone(),
                    place: "tour".into(),
                });
            }
        }
        // `r` goes back to the step's scene
        self.base = st.scene.clone();
        self.set_scene(st.scene);
        self.charts = st.charts;
        self.all_models = st.models;
        self.focus = 0;
        self.edit = None;
        if let Some(k) = st.select {
            let want = knob_param(k);
            if let Some(i) = self.params().iter().position(|p| *p == want) {
                self.selected = i;
            }
        }
        self.refresh();
    }

    /// Loads a preset by name or path; on error the current one stays and the error shows.
    pub fn load_preset(&mut self, source: &str) {
        match Preset::resolve(source).and_then(|p| initial_scene(&p).map(|s| (p, s))) {
            Ok((p, s)) => {
                self.source = source.to_string();
                self.preset = p;
                self.base = s.clone();
                self.set_scene(s);
                self.info(format!("preset {}", self.preset.name));
            }
            Err(e) => self.fail(e),
        }
    }

    fn set_scene(&mut self, scene: Scene) {
        if scene != self.scene {
            self.pending = true;
        }
        self.scene = scene;
        self.selected = self.selected.min(self.params().len() - 1);
    }

    /// Applies a candidate scene if it validates; otherwise shows why not.
    fn try_scene(&mut self, scene: Scene) {
        match scene.validate() {
            Ok(()) => self.set_scene(scene),
            Err(e) => self.fail(e),
        }
    }

    fn try_model(&mut self, m: Result<Model>) {
        match m {
            Ok(m) => {
                let mut s = self.scene.clone();
                s.model = m;
                self.try_scene(s);
            }
            Err(e) => self.fail(e),
        }
    }

    fn cycle_model(&mut self, dir: i32) {
        let cur = self.scene.model.number().map_or(5, i32::from);
        let next = (cur - 1 + dir).rem_euclid(5) + 1;
        if next == 5 {
            let m = self.scene.model;
            self.try_model(Model::custom(m.c1, m.c2, m.alpha, m.k_griffith, m.cap));
        } else {
            self.try_model(Model::named(next as u8));
        }
    }

    fn step(&mut self, dir: i32, coarse: bool) {
        let pick = |s: (f64, f64)| if coarse { s.1 } else { s.0 };
        let mut s = self.scene.clone();
        let m = s.model;
        match self.selected_param() {
            Param::Preset => {
                let n = self.presets.len() as i32;
                if n > 0 {
                    let cur = self.presets.iter().position(|e| e.source == self.source).unwrap_or(0) as i32;
                    let next = self.presets[(cur + dir).rem_euclid(n) as usize].source.clone();
                    self.load_preset(&next);
                }
                return;
            }
            Param::Model => {
                self.cycle_model(dir);
                return;
            }
            Param::Pressure => {
                let p = log_step_from(s.pressure, self.base.pressure, pick(PRESSURE_STEPS), dir);
                s.pressure = p.clamp(PRESSURE_KEYS.0, PRESSURE_KEYS.1);
            }
            Param::Thickness => {
                let t = s.thickness_qr;
                s.thickness_qr = if t.is_infinite() {
                    if dir > 0 {
                        t
                    } else {
                        THICKNESS_KEYS.1
                    }
                } else {
                    let v = log_step_from(t, self.base.thickness_qr, pick(THICKNESS_STEPS), dir);
                    if v > THICKNESS_KEYS.1 * (1.0 + 1e-9) {
                        f64::INFINITY
                    } else {
                        v.max(THICKNESS_KEYS.0)
                    }
                };
            }
            Param::Gamma => {
                let g = s.gamma;
                s.gamma = if g == 0.0 {
                    if dir > 0 {
                        let pg = self.preset.adhesion.surface_energy_j_m2;
                        if pg > 0.0 {
                            pg
                        } else {
                            1e-2
                        }
                    } else {
                        0.0
                    }
                } else {
                    let v = log_step_from(g, self.preset.adhesion.surface_energy_j_m2, pick(GAMMA_STEPS), dir);
                    if v < GAMMA_KEYS.0 * (1.0 - 1e-9) {
                        0.0
                    } else {
                        v.min(GAMMA_KEYS.1)
                    }
                };
            }
            Param::C1 => {
                return self.try_model(Model::custom(
                    lin_step(m.c1, pick((0.01, 0.1)), dir),
                    m.c2,
                    m.alpha,
                    m.k_griffith,
                    m.cap,
                ))
            }
            Param::C2 => {
                return self.try_model(Model::custom(
                    m.c1,
                    lin_step(m.c2, pick((0.01, 0.1)), dir),
                    m.alpha,
                    m.k_griffith,
                    m.cap,
                ))
            }
            Param::Alpha => {
                let a = lin_step(m.alpha, pick((0.05, 0.25)), dir).clamp(0.0, 4.0);
                return self.try_model(Model::custom(m.c1, m.c2, a, m.k_griffith, m.cap));
            }
            Param::KGriffith => {
                let k = lin_step(m.k_griffith, pick((0.1, 1.0)), dir);
                let k = if k <= 0.0 { m.k_griffith.min(0.1) } else { k };
                return self.try_model(Model::custom(m.c1, m.c2, m.alpha, k, m.cap));
            }
            Param::Cap => return self.try_model(Model::custom(m.c1, m.c2, m.alpha, m.k_griffith, !m.cap)),
        }
        self.try_scene(s);
    }

    /// Sets a parameter from typed text.
    pub fn set_typed(&mut self, param: Param, text: &str) -> Result<()> {
        let mut s = self.scene.clone();
        let m = s.model;
        let t = text.trim();
        match param {
            Param::Preset => {
                self.load_preset(t);
                return match &self.message {
                    Some(Message { error: true, text }) => Err(Error::Unsupported(text.clone())),
                    _ => Ok(()),
                };
            }
            Param::Model => {
                s.model = Model::of_kind(t.parse::<asperity::input::model::ModelKind>()?, &m)?;
            }
            Param::Pressure => {
                let p = parse_number("p*", t)?;
                if p <= 0.0 {
                    return Err(Error::field("p*", t, "p* > 0"));
                }
                s.pressure = p;
            }
            Param::Thickness => s.thickness_qr = t.parse::<asperity::input::scene::ThicknessQr>()?.0,
            Param::Gamma => {
                s.gamma = if t.eq_ignore_ascii_case("off") {
                    0.0
                } else {
                    parse_number("gamma", t)?
                }
            }
            Param::C1 => s.model = Model::custom(parse_number("c1", t)?, m.c2, m.alpha, m.k_griffith, m.cap)?,
            Param::C2 => s.model = Model::custom(m.c1, parse_number("c2", t)?, m.alpha, m.k_griffith, m.cap)?,
            Param::Alpha => s.model = Model::custom(m.c1, m.c2, parse_number("alpha", t)?, m.k_griffith, m.cap)?,
            Param::KGriffith => s.model = Model::custom(m.c1, m.c2, m.alpha, parse_number("k_G", t)?, m.cap)?,
            Param::Cap => s.model = Model::custom(m.c1, m.c2, m.alpha, m.k_griffith, parse_bool("cap", t)?)?,
        }
        s.validate()?;
        self.set_scene(s);
        Ok(())
    }
}

/// The panel row of a tour step's knob.
pub fn knob_param(k: super::tour::Knob) -> Param {
    use super::tour::Knob;
    match k {
        Knob::Preset => Param::Preset,
        Knob::Model => Param::Model,
        Knob::Pressure => Param::Pressure,
        Knob::Thickness => Param::Thickness,
        Knob::Gamma => Param::Gamma,
    }
}

/// Inserts into a reply map, forgetting everything when it grows past a few hundred entries.
fn bounded_insert<V>(map: &mut HashMap<CacheKey, V>, key: CacheKey, v: V) {
    if map.len() >= 256 {
        map.clear();
    }
    map.insert(key, v);
}

/// The scene the explorer opens a preset with (γ_s per [`ADHESION_BY_DEFAULT`]).
pub fn initial_scene(p: &Preset) -> Result<Scene> {
    let mut s = p.scene()?;
    if !ADHESION_BY_DEFAULT {
        s.gamma = 0.0;
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g_starts_and_cancels_a_gfmd_run() {
        let mut a = app();
        key(&mut a, KeyCode::Char('g'));
        assert!(matches!(a.gfmd, GfmdState::Running { .. }));
        let (id, setup, cancel) = a.take_gfmd_request().expect("a run to start");
        assert_eq!(setup.scene, a.scene);
        assert_eq!(setup.grid.n(), 512);
        // progress of this run is shown; a stale run's is not
        a.on_reply(Reply::GfmdProgress {
            id,
            iteration: 120,
            residual: 1e-3,
        });
        assert!(matches!(a.gfmd, GfmdState::Running { iteration: 120, .. }));
        a.on_reply(Reply::GfmdProgress {
            id: id + 7,
            iteration: 999,
            residual: 1.0,
        });
        assert!(matches!(a.gfmd, GfmdState::Running { iteration: 120, .. }));
        // g again cancels
        key(&mut a, KeyCode::Char('g'));
        assert!(cancel.load(Ordering::Relaxed));
        assert_eq!(a.gfmd, GfmdState::Idle);
        assert!(a.take_gfmd_request().is_none());
        // a finished run is shown for its own scene only
        key(&mut a, KeyCode::Char('g'));
        let (id, _, _) = a.take_gfmd_request().unwrap();
        let view = GfmdView {
            pressure: a.scene.pressure,
            a_r: 0.02,
            mean_contact_stress: 0.5,
            gap_rel: 1.5,
            pr: vec![(0.1, 0.01), (0.2, 0.02)],
            grid: 512,
            iterations: 400,
            elapsed_s: 0.5,
            theory_a_r: Some(0.021),
            ..GfmdView::default()
        };
        a.on_reply(Reply::GfmdDone {
            id,
            result: Ok(view.clone()),
        });
        assert_eq!(a.gfmd_for_scene(), Some(&view));
        key(&mut a, KeyCode::Right); // p* changes: the result belongs to another scene
        assert_eq!(a.gfmd_for_scene(), None);
    }
    use ratatui::crossterm::event::KeyModifiers as M;

    fn app() -> App {
        let p = Preset::resolve("system-1").unwrap();
        let mut a = App::new("system-1", p).unwrap();
        a.export_dir = std::env::temp_dir();
        a
    }

    fn key(a: &mut App, code: KeyCode) {
        a.on_key(KeyEvent::new(code, M::NONE));
    }

    fn typed(a: &mut App, s: &str) {
        for c in s.chars() {
            key(a, KeyCode::Char(c));
        }
        key(a, KeyCode::Enter);
    }

    #[test]
    fn log_and_linear_steps_are_on_a_grid() {
        assert!((log_step(0.01, 20.0, 1) - 10f64.powf(-1.95)).abs() < 1e-15);
        assert_eq!(log_step(log_step(0.01, 20.0, 1), 20.0, -1), 10f64.powf(-2.0));
        // off-grid goes to the neighbours
        let x = 0.0123;
        assert!(log_step(x, 20.0, 1) > x && log_step(x, 20.0, 1) < 0.0142);
        assert!(log_step(x, 20.0, -1) < x && log_step(x, 20.0, -1) > 0.0112);
        // coarse grid is a subset of the fine grid
        assert_eq!(log_step(1.0, 4.0, -1), log_step(1.0, 20.0, -5));
        assert!((lin_step(0.5, 0.1, 1) - 0.6).abs() < 1e-12);
        assert_eq!(lin_step(0.05, 0.1, -1), 0.0);
        assert!((lin_step(lin_step(0.3, 0.01, 1), 0.01, -1) - 0.3).abs() < 1e-12);
    }

    #[test]
    fn pressure_steps_round_trip_exactly() {
        let mut a = app();
        assert_eq!(a.selected_param(), Param::Pressure);
        let p0 = a.scene.pressure;
        key(&mut a, KeyCode::Right);
        let p1 = a.scene.pressure;
        assert!(p1 > p0 && p1 < p0 * 1.2);
        key(&mut a, KeyCode::Left);
        assert_eq!(a.scene.pressure, p0);
        a.on_key(KeyEvent::new(KeyCode::Right, M::SHIFT));
        assert!((a.scene.pressure / p0 - 10f64.powf(0.25)).abs() < 1e-12);
        key(&mut a, KeyCode::PageDown);
        assert_eq!(a.scene.pressure, p0);
    }

    #[test]
    fn pressure_steps_return_to_the_presets_value() {
        // system-2's p* = 0.005 is not on the 10^(k/20) grid: → → ← gave 0.004467
        let p = Preset::resolve("system-2").unwrap();
        let mut a = App::new("system-2", p).unwrap();
        assert_eq!(a.scene.pressure, 0.005);
        key(&mut a, KeyCode::Right);
        key(&mut a, KeyCode::Right);
        key(&mut a, KeyCode::Left);
        key(&mut a, KeyCode::Left);
        assert_eq!(a.scene.pressure, 0.005);
        key(&mut a, KeyCode::Right);
        assert!((a.scene.pressure / 0.005 - 10f64.powf(0.05)).abs() < 1e-12);
        // the coarse grid contains the preset's value too
        a.on_key(KeyEvent::new(KeyCode::Left, M::SHIFT));
        assert_eq!(a.scene.pressure, 0.005);
        a.on_key(KeyEvent::new(KeyCode::Right, M::SHIFT));
        a.on_key(KeyEvent::new(KeyCode::Left, M::SHIFT));
        assert_eq!(a.scene.pressure, 0.005);
    }

    #[test]
    fn a_failed_point_keeps_the_load_charts_and_the_panel_agrees() {
        let mut a = app();
        super::super::worker::compute_now(&mut a, &mut Default::default());
        assert!(a.sweep.as_ref().is_some_and(|s| s.is_ok()));
        let key_now = point_key(&a.source, &a.scene);
        a.on_reply(Reply::Point {
            gen: a.gen,
            key: key_now,
            result: Err(Error::NotConverged {
                solver: "adhesive self-consistency".into(),
                reason: "test".into(),
            }),
        });
        assert!(a.sweep.as_ref().is_some_and(|s| s.is_ok()), "the load charts stay");
        assert!(a.gap.is_some());
        assert!(a.compute_error().unwrap().contains("did not converge"));
    }

    #[test]
    fn the_gfmd_start_message_goes_when_the_run_ends() {
        let mut a = app();
        key(&mut a, KeyCode::Char('g'));
        assert!(a.message.as_ref().unwrap().text.starts_with("GFMD started"));
        let (id, _, _) = a.take_gfmd_request().unwrap();
        a.on_reply(Reply::GfmdDone {
            id,
            result: Err(Error::Io("test".into())),
        });
        assert!(a.message.is_none());
    }

    #[test]
    fn chart_selector_focus_and_models_ask_for_data() {
        let mut a = app();
        let _ = a.take_request();
        key(&mut a, KeyCode::Char('v'));
        assert_eq!(a.charts[0], ChartKind::PrLog);
        key(&mut a, KeyCode::Char('f'));
        key(&mut a, KeyCode::Char('v'));
        assert_eq!(a.charts[1], ChartKind::AreaRatio);
        for _ in 0..2 {
            key(&mut a, KeyCode::Char('v'));
        }
        assert_eq!(a.charts[1], ChartKind::Stress);
        key(&mut a, KeyCode::Char('f'));
        key(&mut a, KeyCode::Char('v'));
        key(&mut a, KeyCode::Char('v'));
        key(&mut a, KeyCode::Char('v'));
        key(&mut a, KeyCode::Char('v'));
        key(&mut a, KeyCode::Char('v'));
        assert_eq!(a.charts[2], ChartKind::Thickness);
        let r = a.take_request().expect("a new chart asks for its data");
        assert!(r.needs.thickness && r.needs.loads && r.needs.point);
        assert!(r.models.is_empty());
        key(&mut a, KeyCode::Char('M'));
        let r = a.take_request().unwrap();
        // models 1, 2, 4 besides the current model 3
        let n: Vec<u8> = r.models.iter().filter_map(|m| m.number()).collect();
        assert_eq!(n, [1, 2, 4]);
        // only what is visible is asked for
        a.set_charts([ChartKind::Pr, ChartKind::PrLog, ChartKind::Pr]);
        let r = a.take_request().unwrap();
        assert!(r.needs.point && !r.needs.loads && !r.needs.thickness);
    }

    #[test]
    fn requests_carry_increasing_generations_and_only_on_change() {
        let mut a = app();
        let r1 = a.take_request().unwrap();
        assert!(a.take_request().is_none());
        key(&mut a, KeyCode::Right);
        key(&mut a, KeyCode::Right);
        let r2 = a.take_request().unwrap();
        assert!(r2.gen > r1.gen);
        assert!(a.busy);
        // a stale point (from r1's scene) is dropped, the current one kept
        a.on_reply(Reply::Point {
            gen: r1.gen,
            key: point_key(&r1.source, &r1.scene),
            result: Err(Error::Cancelled),
        });
        assert!(a.point.is_none());
        a.on_reply(Reply::Done { gen: r1.gen });
        assert!(a.busy);
        a.on_reply(Reply::Done { gen: r2.gen });
        assert!(!a.busy);
    }

    #[test]
    fn thickness_reaches_infinity_and_back() {
        let mut a = app();
        key(&mut a, KeyCode::Down); // t·q_r
        assert_eq!(a.selected_param(), Param::Thickness);
        assert!(a.scene.thickness_qr.is_infinite());
        key(&mut a, KeyCode::Left);
        assert_eq!(a.scene.thickness_qr, THICKNESS_KEYS.1);
        key(&mut a, KeyCode::Right);
        assert!(a.scene.thickness_qr.is_infinite());
        typed(&mut a, "0.5");
        assert_eq!(a.scene.thickness_qr, 0.5);
        key(&mut a, KeyCode::Enter);
        typed(&mut a, "inf");
        assert!(a.scene.thickness_qr.is_infinite());
    }

    #[test]
    fn gamma_zero_is_off() {
        let mut a = app();
        key(&mut a, KeyCode::Down);
        key(&mut a, KeyCode::Down);
        assert_eq!(a.selected_param(), Param::Gamma);
        // the preset's own surface energy is the default
        assert_eq!(a.scene.gamma, 0.05);
        for _ in 0..40 {
            key(&mut a, KeyCode::Left);
        }
        assert_eq!(a.scene.gamma, 0.0);
        key(&mut a, KeyCode::Left);
        assert_eq!(a.scene.gamma, 0.0);
        key(&mut a, KeyCode::Right);
        assert!(a.scene.gamma > 0.0);
    }

    #[test]
    fn models_cycle_and_custom_rows_appear() {
        let mut a = app();
        assert_eq!(a.scene.model.number(), Some(3));
        key(&mut a, KeyCode::Char('m'));
        assert_eq!(a.scene.model.number(), Some(4));
        assert_eq!(a.params().len(), 5);
        key(&mut a, KeyCode::Char('m'));
        assert_eq!(a.scene.model.kind, ModelKind::Custom);
        assert_eq!(a.scene.model.c1, 0.65);
        assert_eq!(a.params().len(), 10);
        // edit c1 until W < 0 is refused with a message
        a.selected = a.params().iter().position(|p| *p == Param::C1).unwrap();
        for _ in 0..10 {
            a.on_key(KeyEvent::new(KeyCode::Right, M::SHIFT));
        }
        assert!(a.scene.model.c1 <= 1.0);
        assert!(a.message.as_ref().is_some_and(|m| m.error), "{:?}", a.message);
        key(&mut a, KeyCode::Char('m'));
        assert_eq!(a.scene.model.number(), Some(1));
        assert!(a.selected < a.params().len());
    }

    #[test]
    fn typing_bad_values_keeps_the_scene_and_explains() {
        let mut a = app();
        let before = a.scene.clone();
        typed(&mut a, "-3");
        assert_eq!(a.scene, before);
        assert!(a.message.as_ref().unwrap().text.contains("p*"));
        key(&mut a, KeyCode::Enter);
        typed(&mut a, "abc");
        assert_eq!(a.scene, before);
        typed(&mut a, "1e-3");
        assert_eq!(a.scene.pressure, 1e-3);
        // Esc cancels typing without quitting
        key(&mut a, KeyCode::Char('5'));
        key(&mut a, KeyCode::Esc);
        assert!(!a.quit && a.edit.is_none());
        assert_eq!(a.scene.pressure, 1e-3);
    }

    #[test]
    fn reset_help_picker_and_quit() {
        let mut a = app();
        key(&mut a, KeyCode::Right);
        key(&mut a, KeyCode::Char('r'));
        assert_eq!(a.scene, a.base);
        key(&mut a, KeyCode::Char('?'));
        assert_eq!(a.overlay, Overlay::Help);
        key(&mut a, KeyCode::Char('x'));
        assert_eq!(a.overlay, Overlay::None);
        key(&mut a, KeyCode::Char('p'));
        assert!(matches!(a.overlay, Overlay::Presets(0)));
        key(&mut a, KeyCode::Down);
        key(&mut a, KeyCode::Enter);
        assert_eq!(a.preset.name, "system-2");
        assert_eq!(a.overlay, Overlay::None);
        key(&mut a, KeyCode::Char('a'));
        assert_eq!(a.charts[1], ChartKind::AreaRatio);
        assert!(!a.quit);
        key(&mut a, KeyCode::Esc);
        assert!(a.quit);
        let mut b = app();
        b.on_key(KeyEvent::new(KeyCode::Char('c'), M::CONTROL));
        assert!(b.quit);
        // q while typing cancels the field and keeps the scene; a second q quits
        let mut c = app();
        let before = c.scene.clone();
        key(&mut c, KeyCode::Char('5'));
        key(&mut c, KeyCode::Char('q'));
        assert_eq!((c.edit.as_deref(), c.quit), (None, false));
        assert_eq!(c.scene, before);
        key(&mut c, KeyCode::Char('q'));
        assert!(c.quit);
    }

    #[test]
    fn a_tour_step_selects_the_knob_its_caption_names() {
        let mut a = app();
        a.start_tour(Tour::resolve("wang-muser").unwrap(), 0);
        assert_eq!(a.selected_param(), Param::Pressure);
        let n = a.tour.as_ref().unwrap().tour.steps.len();
        a.act(Action::Up);
        a.tour_go(n as i32);
        let step = &a.tour.as_ref().unwrap().tour.steps[n - 1];
        assert_eq!(step.select, Some(crate::tui::tour::Knob::Pressure));
        assert_eq!(a.selected_param(), Param::Pressure);
        a.tour_go(-2);
        assert_eq!(a.selected_param(), Param::Thickness);
    }

    #[test]
    fn the_load_range_stays_while_p_stays_inside_it() {
        // stepping p* up from 1e-6 keeps 1e-6..1 (the cached sweep), leaving it resets
        let r = sticky_range(None, 1e-6);
        assert_eq!(r, chart_range(1e-6));
        assert_eq!(sticky_range(Some(r), 3e-4), r);
        assert_eq!(sticky_range(Some(r), 1.0), r);
        assert_eq!(sticky_range(Some(r), 3.0), chart_range(3.0));
        assert_eq!(sticky_range(Some(r), 1e-7), chart_range(1e-7));
        assert_ne!(chart_range(3e-4), r);
    }

    #[test]
    fn chart_range_covers_p() {
        assert_eq!(chart_range(0.01), (1e-3, 1.0));
        let (a, b) = chart_range(3e-5);
        assert!(a <= 3e-5 && b == 1.0);
        let (a, b) = chart_range(20.0);
        assert!(a == 1e-3 && b >= 20.0);
        assert_eq!(chart_range(f64::NAN), (1e-3, 1.0));
    }
}
