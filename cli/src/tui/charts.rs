//! The explorer's charts as plain data: [`build`] turns the [`App`]'s results into a
//! [`ChartModel`] (title, axis titles, scales, series in data units, vertical markers). The
//! terminal view ([`super::view`]) draws a model with ratatui; `s` ([`super::export`]) hands
//! the same models to the SVG/PNG renderer, so an exported chart is what was on screen.
//!
//! Charts (the selector cycles them in this order; names are used by tours):
//!
//! | name         | shows                                                         | \[S\]      |
//! |--------------|---------------------------------------------------------------|------------|
//! | `pr`         | Pr(σ*) at the current p*, linear axes, −σ_a* wall             | Figs. 2, 4 |
//! | `pr-loglog`  | Pr(σ*) on log–log axes with the small- and large-stress asymptotes | Fig. 3 |
//! | `area`       | a_r(p*) on log–log axes with eq. (18); with hysteresis the unloading branch and the jump-in / pull-off loads | [S-18] |
//! | `area-ratio` | a_r/p* against p* with eq. (18) (and the unloading branch)     | Fig. 1     |
//! | `thickness`  | a_r(t·q_r) at the current p*, with the adhesionless reference | Fig. 7     |
//! | `stress`     | σ̄_c*(p*)                                                      | Fig. 5     |
//! | `gap`        | ū/h_rms(p*)                                                   | Fig. 6     |
//!
//! Stresses and pressures are reduced by E*ḡ (σ* = σ/E*ḡ, p* = p/E*ḡ), the gap by h_rms;
//! Pr(σ*) is a density in σ* (∫Pr dσ* = a_r). With `M` every model (1–4, and the custom one
//! when it is selected) is drawn with its own colour and marker. The preset's `[[reference]]`
//! points are drawn as points named by their source (and the conditions, where they differ
//! from the scene's).

use super::app::App;
use super::data::{PointData, SweepData, ThicknessData};
use super::plot::{self, Scale};
use asperity::input::model::{Model, ModelKind};
use asperity::theory::closed_form;

/// One chart of the selector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChartKind {
    /// Pr(σ*), linear axes.
    Pr,
    /// Pr(σ*), log–log with asymptotes.
    PrLog,
    /// a_r(p*), log–log, with eq. (18).
    Area,
    /// a_r/p* against log p*, with eq. (18).
    AreaRatio,
    /// a_r(t·q_r) at the current p*.
    Thickness,
    /// σ̄_c*(p*).
    Stress,
    /// ū/h_rms(p*).
    Gap,
}

/// What a chart needs computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Needs {
    /// Pr(σ*) at the current p* (of every drawn model).
    pub point: bool,
    /// The load sweep.
    pub loads: bool,
    /// The thickness sweep.
    pub thickness: bool,
}

impl Needs {
    /// Union.
    pub fn or(self, o: Needs) -> Needs {
        Needs {
            point: self.point || o.point,
            loads: self.loads || o.loads,
            thickness: self.thickness || o.thickness,
        }
    }
}

impl ChartKind {
    /// Every chart, in selector order.
    pub const ALL: [ChartKind; 7] = [
        ChartKind::Pr,
        ChartKind::PrLog,
        ChartKind::Area,
        ChartKind::AreaRatio,
        ChartKind::Thickness,
        ChartKind::Stress,
        ChartKind::Gap,
    ];

    /// The name used in tours and file names.
    pub fn name(self) -> &'static str {
        match self {
            ChartKind::Pr => "pr",
            ChartKind::PrLog => "pr-loglog",
            ChartKind::Area => "area",
            ChartKind::AreaRatio => "area-ratio",
            ChartKind::Thickness => "thickness",
            ChartKind::Stress => "stress",
            ChartKind::Gap => "gap",
        }
    }

    /// The chart named `s`.
    pub fn parse(s: &str) -> Option<ChartKind> {
        ChartKind::ALL.into_iter().find(|k| k.name() == s)
    }

    /// The next (`dir` = 1) or previous (−1) chart of the selector.
    pub fn cycle(self, dir: i32) -> ChartKind {
        let n = ChartKind::ALL.len() as i32;
        let i = ChartKind::ALL.iter().position(|k| *k == self).unwrap_or(0) as i32;
        ChartKind::ALL[(i + dir).rem_euclid(n) as usize]
    }

    /// The quantity of the preset's `[[reference]]` points this chart draws (GFMD data such
    /// as \[S\] Table 1), if any.
    pub fn reference_quantity(self) -> Option<&'static str> {
        match self {
            ChartKind::Area | ChartKind::AreaRatio | ChartKind::Thickness => Some("a_r"),
            ChartKind::Stress => Some("mean_contact_stress"),
            ChartKind::Gap => Some("mean_gap_rel"),
            ChartKind::Pr | ChartKind::PrLog => None,
        }
    }

    /// What it needs computed.
    pub fn needs(self) -> Needs {
        match self {
            ChartKind::Pr | ChartKind::PrLog => Needs {
                point: true,
                ..Needs::default()
            },
            ChartKind::Thickness => Needs {
                thickness: true,
                ..Needs::default()
            },
            _ => Needs {
                loads: true,
                ..Needs::default()
            },
        }
    }
}

/// What a series is (the view picks colour and marker from it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// The theory of the current scene.
    Theory,
    /// Model slot 0–3 (models 1–4) or 4 (custom), with `M`.
    Model(usize),
    /// The adhesionless comparison.
    Compare,
    /// A closed form (eq. (18), the small-stress asymptote, t = ∞).
    Closed,
    /// A second closed form (the large-stress asymptote).
    Closed2,
    /// The preset's reference points.
    Reference,
    /// GFMD.
    Gfmd,
    /// The current point.
    Current,
    /// A guide line (σ* = 0, current p*).
    Guide,
    /// The −σ_a* wall.
    Wall,
    /// The unloading branch of a hysteresis (a_r charts).
    Unloading,
    /// The jump-in load: above it the loading branch no longer exists.
    JumpIn,
    /// The pull-off load: below it the unloading branch no longer exists.
    PullOff,
}

/// How a series is drawn: the file renderer's style, so the screen and the `s` export agree
/// by construction.
pub use crate::chart::SeriesStyle as Draw;

/// One series, in data units (NaN marks a gap).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend name.
    pub name: String,
    /// Points (data units).
    pub points: Vec<(f64, f64)>,
    /// What it is.
    pub role: Role,
    /// How it is drawn.
    pub draw: Draw,
}

/// A vertical marker across the whole y range.
#[derive(Debug, Clone, PartialEq)]
pub struct VLine {
    /// x (data units).
    pub x: f64,
    /// What it is ([`Role::Guide`], [`Role::Wall`], [`Role::JumpIn`], [`Role::PullOff`]).
    pub role: Role,
    /// Legend name (empty: no legend entry).
    pub name: String,
}

/// A chart ready to draw.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartModel {
    /// Which chart.
    pub kind: ChartKind,
    /// Title (the quantity and the load it is drawn at).
    pub title: String,
    /// x axis title, with units.
    pub x_label: String,
    /// y axis title, with units.
    pub y_label: String,
    /// x scale.
    pub xs: Scale,
    /// y scale.
    pub ys: Scale,
    /// Plane bounds of x before rounding (the view rounds them to [`plot::ticks`]).
    pub xb: [f64; 2],
    /// Plane bounds of y before rounding.
    pub yb: [f64; 2],
    /// Series, drawn in this order (the key curve last).
    pub series: Vec<Series>,
    /// Vertical markers.
    pub vlines: Vec<VLine>,
    /// Why there is nothing to draw.
    pub empty: Option<String>,
    /// The data belong to an earlier scene (a newer one is being computed).
    pub stale: bool,
    /// Points of the y data outside [`ChartModel::yb`] are dropped (log axes spanning many
    /// decades).
    pub clip_y: bool,
}

/// Model slot of a model: 0–3 for models 1–4, 4 for custom.
pub fn slot(m: &Model) -> usize {
    match m.kind {
        ModelKind::Custom => 4,
        _ => m.number().map_or(4, |n| usize::from(n) - 1),
    }
}

/// Legend name of a model slot.
pub fn slot_name(i: usize) -> String {
    if i < 4 {
        format!("model {}", i + 1)
    } else {
        "custom".into()
    }
}

/// The models drawn with `M`: 1–4, and the current one when it is custom.
pub fn overlay_models(current: &Model) -> Vec<Model> {
    let mut v: Vec<Model> = (1..=4).filter_map(|n| Model::named(n).ok()).collect();
    if current.kind == ModelKind::Custom {
        v.push(*current);
    }
    v
}

fn theory_role(app: &App) -> Role {
    if app.all_models {
        Role::Model(slot(&app.scene.model))
    } else {
        Role::Theory
    }
}

fn theory_name(app: &App) -> String {
    if app.all_models {
        slot_name(slot(&app.scene.model))
    } else {
        "theory".into()
    }
}

/// The other models' data for `M` (slot, data), current model excluded.
fn others<'a, T>(app: &'a App, get: impl Fn(&'a App, &Model) -> Option<&'a T>) -> Vec<(usize, &'a T)> {
    if !app.all_models {
        return Vec::new();
    }
    overlay_models(&app.scene.model)
        .into_iter()
        .filter(|m| slot(m) != slot(&app.scene.model))
        .filter_map(|m| get(app, &m).map(|d| (slot(&m), d)))
        .collect()
}

fn empty_message(app: &App) -> String {
    if app.busy {
        "computing…".into()
    } else if app.compute_error().is_some() {
        "no data: see the status line".into()
    } else {
        "no data".into()
    }
}

fn base(kind: ChartKind, title: String, x: &str, y: &str, xs: Scale, ys: Scale) -> ChartModel {
    ChartModel {
        kind,
        title,
        x_label: x.into(),
        y_label: y.into(),
        xs,
        ys,
        xb: [0.0, 1.0],
        yb: [0.0, 1.0],
        series: Vec::new(),
        vlines: Vec::new(),
        empty: None,
        stale: false,
        clip_y: false,
    }
}

/// Plane bounds of every series (and vertical line, for x).
fn data_bounds(m: &ChartModel) -> (Option<[f64; 2]>, Option<[f64; 2]>) {
    let runs: Vec<Vec<(f64, f64)>> = m
        .series
        .iter()
        .flat_map(|s| plot::segments(&s.points, m.xs, m.ys))
        .collect();
    let refs: Vec<&[(f64, f64)]> = runs.iter().map(|r| r.as_slice()).collect();
    let mut xb = plot::bounds(&refs, true, 0.0);
    for v in &m.vlines {
        if let Some(x) = m.xs.forward(v.x) {
            xb = Some(match xb {
                Some(b) => [b[0].min(x), b[1].max(x)],
                None => plot::guard(x, x),
            });
        }
    }
    (xb, plot::bounds(&refs, false, 0.0))
}

/// Builds the chart `kind` from the app's results.
pub fn build(app: &App, kind: ChartKind) -> ChartModel {
    match kind {
        ChartKind::Pr => pr_linear(app),
        ChartKind::PrLog => pr_loglog(app),
        ChartKind::Area | ChartKind::AreaRatio => area(app, kind == ChartKind::AreaRatio),
        ChartKind::Thickness => thickness(app),
        ChartKind::Stress => loads(app, ChartKind::Stress),
        ChartKind::Gap => loads(app, ChartKind::Gap),
    }
}

fn current_point(app: &App) -> Option<&PointData> {
    app.point.as_ref().and_then(|r| r.as_ref().ok())
}

fn pr_linear(app: &App) -> ChartModel {
    let title = format!("Pr(σ*) at p* = {}", super::view::sig(app.scene.pressure, 3));
    let mut m = base(ChartKind::Pr, title, "σ* = σ/E*ḡ", "Pr", Scale::Linear, Scale::Linear);
    let Some(p) = current_point(app) else {
        m.empty = Some(empty_message(app));
        return m;
    };
    m.stale = app.point_is_stale();
    if let Some(c) = p.adhesionless.as_ref().filter(|_| app.compare) {
        m.series.push(Series {
            name: "γ_s=0".into(),
            points: c.clone(),
            role: Role::Compare,
            draw: Draw::Line,
        });
    }
    if let Some(g) = app.gfmd_for_scene() {
        m.series.push(Series {
            name: "GFMD".into(),
            points: g.pr.iter().copied().filter(|(_, d)| *d > 0.0).collect(),
            role: Role::Gfmd,
            draw: Draw::Points,
        });
    }
    for (i, o) in others(app, App::model_point) {
        m.series.push(Series {
            name: slot_name(i),
            points: o.pr.clone(),
            role: Role::Model(i),
            draw: Draw::Line,
        });
    }
    m.series.push(Series {
        name: theory_name(app),
        points: p.pr.clone(),
        role: theory_role(app),
        draw: Draw::Line,
    });
    if let Some(w) = p.wall {
        m.vlines.push(VLine {
            x: w,
            role: Role::Wall,
            name: "−σ_a*".into(),
        });
    }
    let (xb, yb) = data_bounds(&m);
    m.xb = xb.unwrap_or([0.0, 1.0]);
    // the sampled tails are flat zeros: end the axis where every curve is below 10⁻³ of the
    // peak
    let peak = yb.map_or(0.0, |b| b[1]);
    let last = m
        .series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|(s, d)| s.is_finite() && *d > 1e-3 * peak)
        .map(|(s, _)| *s)
        .fold(f64::NEG_INFINITY, f64::max);
    if last.is_finite() && last > m.xb[0] {
        m.xb[1] = m.xb[1].min(last);
    }
    if m.xb[0] < 0.0 && m.xb[1] > 0.0 {
        // σ* = 0 separates tension from compression
        m.vlines.insert(
            0,
            VLine {
                x: 0.0,
                role: Role::Guide,
                name: String::new(),
            },
        );
    }
    m.yb = plot::guard(0.0, yb.map_or(1.0, |b| b[1]).max(0.0) * 1.05);
    m
}

/// The positive-σ* part of a Pr curve (a log axis cannot show σ* ≤ 0).
fn positive(pr: &[(f64, f64)]) -> Vec<(f64, f64)> {
    pr.iter().copied().filter(|(s, d)| *s > 0.0 && *d > 0.0).collect()
}

fn pr_loglog(app: &App) -> ChartModel {
    let title = format!("Pr(σ*) log–log at p* = {}", super::view::sig(app.scene.pressure, 3));
    let mut m = base(ChartKind::PrLog, title, "σ* = σ/E*ḡ", "Pr", Scale::Log10, Scale::Log10);
    m.clip_y = true;
    let Some(p) = current_point(app) else {
        m.empty = Some(empty_message(app));
        return m;
    };
    m.stale = app.point_is_stale();
    let curve = |pd: &PointData| {
        if pd.pr_log.is_empty() {
            positive(&pd.pr)
        } else {
            pd.pr_log.clone()
        }
    };
    let theory = curve(p);
    if let Some(c) = p.adhesionless.as_ref().filter(|_| app.compare) {
        m.series.push(Series {
            name: "γ_s=0".into(),
            points: positive(c),
            role: Role::Compare,
            draw: Draw::Line,
        });
    }
    if app.scene.gamma == 0.0 && p.width > 0.0 {
        // [S] Fig. 3: Pr ∝ σ* for σ* → 0 and the Gaussian tail
        let (pp, d) = (app.scene.pressure, p.width);
        let xs: Vec<f64> = theory.iter().map(|q| q.0).collect();
        // each where it applies: σ* below Δ, and above Δ/2 (they coincide for σ* ≪ Δ)
        m.series.push(Series {
            name: "σ→0 asymptote".into(),
            points: xs
                .iter()
                .filter(|&&s| s <= d)
                .map(|&s| (s, closed_form::pr_small_stress(s, pp, d)))
                .collect(),
            role: Role::Closed,
            draw: Draw::Dashed,
        });
        m.series.push(Series {
            name: "large-σ asymptote".into(),
            points: xs
                .iter()
                .filter(|&&s| s >= 0.5 * d)
                .map(|&s| (s, closed_form::pr_large_stress(s, pp, d)))
                .collect(),
            role: Role::Closed2,
            draw: Draw::Dashed,
        });
    }
    if let Some(g) = app.gfmd_for_scene() {
        m.series.push(Series {
            name: "GFMD".into(),
            points: positive(&g.pr),
            role: Role::Gfmd,
            draw: Draw::Points,
        });
    }
    for (i, o) in others(app, App::model_point) {
        m.series.push(Series {
            name: slot_name(i),
            points: curve(o),
            role: Role::Model(i),
            draw: Draw::Line,
        });
    }
    m.series.push(Series {
        name: theory_name(app),
        points: theory.clone(),
        role: theory_role(app),
        draw: Draw::Line,
    });
    // x: the theory's σ* range; y: from 10⁻⁶ of the peak to twice the peak
    let runs = plot::segments(&theory, m.xs, m.ys);
    let refs: Vec<&[(f64, f64)]> = runs.iter().map(|r| r.as_slice()).collect();
    m.xb = plot::bounds(&refs, true, 0.0).unwrap_or([-3.0, 0.0]);
    let top = plot::bounds(&refs, false, 0.0).map_or(0.0, |b| b[1]);
    m.yb = [top - 6.0, top + 0.3];
    m
}

fn references<'a>(
    app: &'a App,
    quantity: &'a str,
) -> impl Iterator<Item = &'a asperity::input::preset::ReferencePoint> {
    app.preset.reference.iter().filter(move |r| r.quantity == quantity)
}

/// Legend name of a reference point: its source, and its conditions where they differ from
/// the scene's.
fn reference_name(app: &App, r: &asperity::input::preset::ReferencePoint, with_thickness: bool) -> String {
    let mut cond = Vec::new();
    let gamma = r.gamma.unwrap_or(app.preset.adhesion.surface_energy_j_m2);
    if gamma != app.scene.gamma {
        cond.push(format!("γ_s={}", plot::format_number(gamma)));
    }
    let t = r.thickness_qr.unwrap_or(f64::INFINITY);
    if with_thickness && t.to_bits() != app.scene.thickness_qr.to_bits() {
        cond.push(format!("t·q_r={}", plot::format_number(t)));
    }
    if let Some(n) = r.model {
        cond.push(format!("model {n}"));
    }
    if cond.is_empty() {
        r.source.clone()
    } else {
        format!("{} ({})", r.source, cond.join(", "))
    }
}

/// Reference points of `quantity` as series (one per source and conditions), y = f(p, value).
fn reference_series(app: &App, quantity: &str, y: impl Fn(f64, f64) -> f64) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    for r in references(app, quantity) {
        let name = reference_name(app, r, true);
        let pt = (r.pressure, y(r.pressure, r.value));
        match out.iter_mut().find(|s| s.name == name) {
            Some(s) => s.points.push(pt),
            None => out.push(Series {
                name,
                points: vec![pt],
                role: Role::Reference,
                draw: Draw::Points,
            }),
        }
    }
    out
}

/// A preview sweep's chart says that the full one is on its way.
fn mark_preview(m: &mut ChartModel, sw: &SweepData) {
    if sw.preview {
        m.title.push_str(" · refining…");
    }
}

fn sweep_of(app: &App) -> Option<&SweepData> {
    app.sweep.as_ref().and_then(|r| r.as_ref().ok())
}

/// The load charts share one x axis: the requested p* range, whatever converged.
fn load_x(app: &App) -> [f64; 2] {
    let (a, b) = app.range();
    [a.log10(), b.log10()]
}

fn add_current(m: &mut ChartModel, x: f64, y: Option<f64>) {
    m.vlines.insert(
        0,
        VLine {
            x,
            role: Role::Guide,
            name: String::new(),
        },
    );
    if let Some(y) = y.filter(|y| y.is_finite()) {
        m.series.push(Series {
            name: "p*".into(),
            points: vec![(x, y)],
            role: Role::Current,
            draw: Draw::Points,
        });
    }
}

fn area(app: &App, ratio: bool) -> ChartModel {
    let (kind, title, ylab, ys) = if ratio {
        (ChartKind::AreaRatio, "a_r/p*", "a_r/p*", Scale::Linear)
    } else {
        (ChartKind::Area, "a_r(p*)", "a_r", Scale::Log10)
    };
    let mut m = base(kind, title.into(), "p* = p/E*ḡ", ylab, Scale::Log10, ys);
    let y_of = |p: f64, a: f64| if ratio { a / p } else { a };
    let curve =
        |sw: &SweepData| -> Vec<(f64, f64)> { sw.p.iter().zip(&sw.a_r).map(|(&p, &a)| (p, y_of(p, a))).collect() };
    let Some(sw) = sweep_of(app) else {
        m.empty = Some(empty_message(app));
        return m;
    };
    m.stale = app.sweep_is_stale();
    mark_preview(&mut m, sw);
    if app.eq18_applies() {
        m.series.push(Series {
            name: "eq. (18)".into(),
            points: sw.p.iter().map(|&p| (p, y_of(p, closed_form::eq18_area(p)))).collect(),
            role: Role::Closed,
            draw: Draw::Dashed,
        });
    }
    for (i, o) in others(app, App::model_sweep) {
        m.series.push(Series {
            name: slot_name(i),
            points: curve(o),
            role: Role::Model(i),
            draw: Draw::Line,
        });
    }
    if !app.all_models {
        hysteresis(&mut m, sw, &y_of);
    }
    m.series.push(Series {
        name: theory_name(app),
        points: curve(sw),
        role: theory_role(app),
        draw: Draw::Line,
    });
    m.series
        .extend(reference_series(app, kind.reference_quantity().unwrap_or("a_r"), y_of));
    if let Some(g) = app.gfmd_for_scene() {
        // the theory on GFMD's own (reduced) map: a second system, apart from the scene's curve
        if g.theory_sweep.len() > 1 {
            m.series.push(Series {
                name: "theory on the GFMD map".into(),
                points: g.theory_sweep.iter().map(|&(p, a, _)| (p, y_of(p, a))).collect(),
                role: Role::Gfmd,
                draw: Draw::Dashed,
            });
        }
        m.series.push(Series {
            name: "GFMD".into(),
            points: std::iter::once((g.pressure, g.a_r))
                .chain(g.sweep.iter().map(|&(p, a, _)| (p, a)))
                .map(|(p, a)| (p, y_of(p, a)))
                .collect(),
            role: Role::Gfmd,
            draw: Draw::Points,
        });
    }
    let p = app.scene.pressure;
    add_current(&mut m, p, current_point(app).map(|pt| y_of(p, pt.a_r)));
    let (_, yb) = data_bounds(&m);
    m.xb = load_x(app);
    let yb = yb.unwrap_or([0.0, 1.0]);
    m.yb = if ratio {
        plot::guard(0.0, yb[1] * 1.05)
    } else {
        // a_r <= 1
        plot::guard(yb[0], yb[1].min(0.0))
    };
    m
}

/// The unloading branch of a hysteresis (a dashed curve over the loads where it is distinct
/// from the loading one, joined to the curve it merges into at the window's top) and the
/// jump-in and pull-off loads as vertical markers named with their p*.
fn hysteresis(m: &mut ChartModel, sw: &SweepData, y_of: &dyn Fn(f64, f64) -> f64) {
    let n = sw.p.len().min(sw.a_r_unloading.len());
    let mut points: Vec<(f64, f64)> = Vec::new();
    for k in 0..n {
        let u = sw.a_r_unloading[k];
        if u.is_finite() {
            points.push((sw.p[k], y_of(sw.p[k], u)));
        } else if k > 0 && sw.a_r_unloading[k - 1].is_finite() {
            // the window's top: the unloading branch goes on as the only one
            points.push((sw.p[k], y_of(sw.p[k], sw.a_r[k])));
            points.push((f64::NAN, f64::NAN));
        } else if points.last().is_some_and(|q| q.0.is_finite()) {
            points.push((f64::NAN, f64::NAN));
        }
    }
    if points.iter().any(|q| q.0.is_finite() && q.1.is_finite()) {
        m.series.push(Series {
            name: "unloading".into(),
            points,
            role: Role::Unloading,
            draw: Draw::Dashed,
        });
    }
    // named with their p* (the x axis says p*)
    for (x, role, what) in [
        (sw.jump_in, Role::JumpIn, "jump-in"),
        (sw.pull_off, Role::PullOff, "pull-off"),
    ] {
        if let Some(x) = x.filter(|x| x.is_finite() && *x > 0.0) {
            m.vlines.push(VLine {
                x,
                role,
                name: format!("{what} {}", super::view::sig(x, 2)),
            });
        }
    }
}

fn loads(app: &App, kind: ChartKind) -> ChartModel {
    let gap = kind == ChartKind::Gap;
    let (title, ylab) = if gap {
        ("ū/h_rms(p*)", "ū/h_rms")
    } else {
        ("σ̄_c*(p*)", "σ̄_c*")
    };
    let quantity = kind.reference_quantity().unwrap_or("mean_contact_stress");
    let mut m = base(kind, title.into(), "p* = p/E*ḡ", ylab, Scale::Log10, Scale::Linear);
    let pick = |sw: &SweepData| -> Vec<(f64, f64)> {
        let ys = if gap { &sw.gap_rel } else { &sw.mean_contact_stress };
        sw.p.iter().copied().zip(ys.iter().copied()).collect()
    };
    let Some(sw) = sweep_of(app) else {
        m.empty = Some(empty_message(app));
        return m;
    };
    m.stale = app.sweep_is_stale();
    mark_preview(&mut m, sw);
    for (i, o) in others(app, App::model_sweep) {
        m.series.push(Series {
            name: slot_name(i),
            points: pick(o),
            role: Role::Model(i),
            draw: Draw::Line,
        });
    }
    m.series.push(Series {
        name: theory_name(app),
        points: pick(sw),
        role: theory_role(app),
        draw: Draw::Line,
    });
    m.series.extend(reference_series(app, quantity, |_, v| v));
    if let Some(g) = app.gfmd_for_scene() {
        let y = if gap { g.gap_rel } else { g.mean_contact_stress };
        let mut points = vec![(g.pressure, y)];
        if gap {
            if g.theory_sweep.len() > 1 {
                m.series.push(Series {
                    name: "theory on the GFMD map".into(),
                    points: g.theory_sweep.iter().map(|&(p, _, u)| (p, u)).collect(),
                    role: Role::Gfmd,
                    draw: Draw::Dashed,
                });
            }
            points.extend(g.sweep.iter().map(|&(p, _, u)| (p, u)));
        }
        m.series.push(Series {
            name: "GFMD".into(),
            points,
            role: Role::Gfmd,
            draw: Draw::Points,
        });
    }
    let y = if gap {
        app.gap_value()
    } else {
        current_point(app).map(|p| p.mean_contact_stress)
    };
    add_current(&mut m, app.scene.pressure, y);
    let (_, yb) = data_bounds(&m);
    m.xb = load_x(app);
    let yb = yb.unwrap_or([0.0, 1.0]);
    m.yb = if gap {
        // the gap may be negative with adhesion: show what comes, and 0 for scale
        plot::guard(yb[0].min(0.0), yb[1])
    } else {
        plot::guard(yb[0], yb[1])
    };
    m
}

fn thickness(app: &App) -> ChartModel {
    let title = format!("a_r(t·q_r) at p* = {}", super::view::sig(app.scene.pressure, 3));
    let mut m = base(ChartKind::Thickness, title, "t·q_r", "a_r", Scale::Log10, Scale::Linear);
    let Some(td) = app.thickness.as_ref().and_then(|r| r.as_ref().ok()) else {
        m.empty = Some(match app.thickness.as_ref() {
            Some(Err(e)) => format!("no data: {e}"),
            _ => empty_message(app),
        });
        return m;
    };
    m.stale = app.thickness_is_stale();
    let curve = |t: &ThicknessData| -> Vec<(f64, f64)> { t.t.iter().copied().zip(t.a_r.iter().copied()).collect() };
    let (t0, t1) = (
        td.t.first().copied().unwrap_or(1e-2),
        td.t.last().copied().unwrap_or(1e2),
    );
    if let Some(a0) = &td.adhesionless {
        m.series.push(Series {
            name: "γ_s=0".into(),
            points: td.t.iter().copied().zip(a0.iter().copied()).collect(),
            role: Role::Compare,
            draw: Draw::Line,
        });
    }
    if td.a_r_inf.is_finite() {
        m.series.push(Series {
            name: "t=∞".into(),
            points: vec![(t0, td.a_r_inf), (t1, td.a_r_inf)],
            role: Role::Closed,
            draw: Draw::Dashed,
        });
    }
    for (i, o) in others(app, App::model_thickness) {
        m.series.push(Series {
            name: slot_name(i),
            points: curve(o),
            role: Role::Model(i),
            draw: Draw::Line,
        });
    }
    m.series.push(Series {
        name: theory_name(app),
        points: curve(td),
        role: theory_role(app),
        draw: Draw::Line,
    });
    // reference a_r points at this p* with a finite thickness
    let mut refs: Vec<Series> = Vec::new();
    for r in references(app, ChartKind::Thickness.reference_quantity().unwrap_or("a_r")) {
        let Some(t) = r.thickness_qr.filter(|t| t.is_finite()) else {
            continue;
        };
        if (r.pressure / app.scene.pressure - 1.0).abs() > 1e-9 {
            continue;
        }
        let name = reference_name(app, r, false);
        match refs.iter_mut().find(|s| s.name == name) {
            Some(s) => s.points.push((t, r.value)),
            None => refs.push(Series {
                name,
                points: vec![(t, r.value)],
                role: Role::Reference,
                draw: Draw::Points,
            }),
        }
    }
    m.series.extend(refs);
    let t = app.scene.thickness_qr;
    if t.is_finite() && t >= t0 && t <= t1 {
        add_current(&mut m, t, current_point(app).map(|p| p.a_r));
    }
    let (_, yb) = data_bounds(&m);
    m.xb = [t0.log10(), t1.log10()];
    let yb = yb.unwrap_or([0.0, 1.0]);
    m.yb = plot::guard(0.0, yb[1].min(1.0));
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use asperity::input::preset::Preset;

    fn app() -> App {
        let mut a = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        a.set_typed(super::super::app::Param::Gamma, "0").unwrap();
        super::super::worker::compute_now(&mut a, &mut Default::default());
        a
    }

    #[test]
    fn load_charts_share_the_requested_x_axis_when_low_loads_fail() {
        let mut a = app();
        if let Some(Ok(sw)) = a.sweep.as_mut() {
            // the lowest third of the loads failed
            let n = sw.p.len() / 3;
            for i in 0..n {
                sw.a_r[i] = f64::NAN;
                sw.gap_rel[i] = f64::NAN;
                sw.mean_contact_stress[i] = f64::NAN;
            }
        }
        let want = [a.range().0.log10(), a.range().1.log10()];
        for k in [ChartKind::Area, ChartKind::AreaRatio, ChartKind::Stress, ChartKind::Gap] {
            let m = build(&a, k);
            assert_eq!(m.xb, want, "{k:?}");
            // the p* marker stays
            assert_eq!(m.vlines[0].x, a.scene.pressure, "{k:?}");
            assert!(m.series.iter().any(|s| s.role == Role::Current), "{k:?}");
        }
    }

    #[test]
    fn asymptotes_follow_the_closed_forms_and_eq18_is_drawn() {
        let a = app();
        let m = build(&a, ChartKind::PrLog);
        let p = a.point.as_ref().unwrap().as_ref().unwrap();
        let small = m.series.iter().find(|s| s.name == "σ→0 asymptote").unwrap();
        let theory = m.series.iter().find(|s| s.role == Role::Theory).unwrap();
        // at the smallest σ* the theory (mirror Gaussian) and the asymptote agree to 1e-3
        let (s0, d0) = theory.points[0];
        assert!(s0 <= 2.0 * super::super::data::PR_LOG_FROM);
        assert!(
            (small.points[0].1 / d0 - 1.0).abs() < 1e-3,
            "{} vs {d0}",
            small.points[0].1
        );
        assert!(small.points.iter().all(|q| q.0 <= p.width));
        let m = build(&a, ChartKind::Area);
        let eq = m.series.iter().find(|s| s.name == "eq. (18)").unwrap();
        for &(x, y) in &eq.points {
            assert_eq!(y, closed_form::eq18_area(x));
        }
        // reference points of Table 1 (γ_s = 0, as the scene): named by source only
        let r = m.series.iter().find(|s| s.role == Role::Reference).unwrap();
        assert_eq!(r.name, "[S] Table 1, GFMD (65536^2)");
        assert_eq!(r.points, vec![(0.01, 0.0202)]);
        let r = build(&a, ChartKind::AreaRatio);
        let r = r.series.iter().find(|s| s.role == Role::Reference).unwrap();
        assert!((r.points[0].1 - 2.02).abs() < 1e-12);
    }

    #[test]
    fn chart_names_round_trip_and_cycle() {
        for k in ChartKind::ALL {
            assert_eq!(ChartKind::parse(k.name()), Some(k));
            assert_eq!(k.cycle(1).cycle(-1), k);
        }
        assert_eq!(ChartKind::Gap.cycle(1), ChartKind::Pr);
        assert_eq!(ChartKind::parse("nope"), None);
    }
}
