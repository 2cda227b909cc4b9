//! The helpers every chart builder shares: the theory's role and name, the other models'
//! data, the preset's reference points, the current-point marker. The chart they build is
//! the one chart model, [`crate::chart::Chart`].

use crate::tui::base::data::{PointData, SweepData};
use crate::tui::base::kinds::{overlay_models, slot, slot_name};
use crate::tui::base::stored_gfmd::stored_gfmd;
use crate::tui::charts::plot::{self, Scale};
use crate::tui::model::app::App;
use asperity::input::model::Model;

/// How a series is drawn: the one chart model's style, so the screen and the `s` export
/// agree by construction.
pub use crate::chart::SeriesStyle as Draw;

/// What a series is (every renderer takes its colour and marker from [`crate::looks`]).
pub use crate::looks::Role;

pub use crate::chart::{Chart, Series, VLine};

pub fn theory_role(app: &App) -> Role {
    if app.ui.all_models {
        Role::Model(slot(&app.params.scene.model()))
    } else {
        Role::Theory
    }
}

pub fn theory_name(app: &App) -> String {
    if app.ui.all_models {
        slot_name(slot(&app.params.scene.model()))
    } else {
        "theory".into()
    }
}

/// The other models' data for `M` (slot, data), current model excluded.
pub fn others<'a, T>(app: &'a App, get: impl Fn(&'a App, &Model) -> Option<&'a T>) -> Vec<(usize, &'a T)> {
    if !app.ui.all_models {
        return Vec::new();
    }
    overlay_models(&app.params.scene)
        .into_iter()
        .filter(|m| slot(m) != slot(&app.params.scene.model()))
        .filter_map(|m| get(app, &m).map(|d| (slot(&m), d)))
        .collect()
}

/// Marks a chart with nothing to draw: where the result it draws failed, its title says why in
/// brief and its body in full (another quantity's failure does not concern it); else
/// "computing…" while the worker runs, or "no data".
pub fn set_empty<T>(m: &mut Chart, app: &App, own: Option<&asperity::error::Result<T>>) {
    match own {
        Some(Err(e)) => mark_failed(m, &crate::tui::base::words::describe(e)),
        _ => m.empty = Some(if app.jobs.busy() { "computing…" } else { "no data" }.into()),
    }
}

/// A chart whose quantity failed: `" · failed: <gist>"` in the title and the whole reason in
/// the body.
pub fn mark_failed(m: &mut Chart, why: &str) {
    m.title
        .push_str(&format!(" · failed: {}", crate::tui::base::words::brief(why)));
    m.empty = Some(format!("no data: {why}"));
}

pub fn base(title: String, x: &str, y: &str, xs: Scale, ys: Scale) -> Chart {
    Chart::new(title, x, y, xs, ys)
}

/// Plane bounds of every series (and vertical line, for x).
pub fn data_bounds(m: &Chart) -> (Option<[f64; 2]>, Option<[f64; 2]>) {
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

pub fn current_point(app: &App) -> Option<&PointData> {
    app.results.point().and_then(|r| r.as_ref().ok())
}

/// The point on the branch the user's path is on: the current point, or where the path is on
/// the unloading branch of a hysteresis window, that branch evaluated whole
/// ([`PointData::unloading`]; the current point until it has come).
pub fn shown_point(app: &App) -> Option<&PointData> {
    let p = current_point(app)?;
    Some(match p.unloading.as_deref() {
        Some(u) if on_unloading(app) => u,
        _ => p,
    })
}

/// Whether the path is on the unloading branch at a load inside its window, and so the view
/// shows that branch ([`shown_point`]).
pub fn on_unloading(app: &App) -> bool {
    path_row(app).is_some()
}

/// a_r on the branch the user's path is on: the point's, or its unloading branch's where the
/// path has jumped in and the load lies in the window.
pub fn path_a_r(app: &App) -> Option<f64> {
    let p = current_point(app)?;
    Some(match (p.unloading.as_deref(), path_row(app)) {
        (Some(u), Some(_)) => u.a_r,
        (None, Some(b)) => b.a_r,
        _ => p.a_r,
    })
}

/// σ̄_c* on the branch the path is on: ∫σ*Pr dσ*/a_r of that branch's distribution (the
/// same definition on both branches); None while the unloading branch's point is on its way.
pub fn path_stress(app: &App) -> Option<f64> {
    let p = current_point(app)?;
    match (path_row(app), p.unloading.as_deref()) {
        (None, _) => Some(p.mean_contact_stress),
        (Some(_), Some(u)) => Some(u.mean_contact_stress),
        (Some(_), None) => None,
    }
}

/// ū/h_rms and its bracket on the branch the path is on: the unloading branch's own gap
/// ([`PointData::gap`]) where the path is on it, else the loading branch's.
pub fn path_gap_bracket(app: &App) -> Option<(f64, f64)> {
    if path_row(app).is_some() {
        let g = current_point(app)?.unloading.as_deref()?.gap?;
        return Some((g.lower, g.upper));
    }
    let sw = app.results.sweep()?.as_ref().ok()?;
    sw.gap_bracket_at(app.params.scene.pressure())
}

/// ū/h_rms on the branch the path is on: the point's, or where the path is on the
/// unloading branch that branch's own gap at p* ([`PointData::gap`]), else (while it is on
/// its way) the load sweep's unloading gap interpolated in ln p* between its loads (None
/// where the sweep has none there).
pub fn path_gap(app: &App) -> Option<f64> {
    if path_row(app).is_none() {
        return app.gap_value();
    }
    if let Some(g) = current_point(app)?.unloading.as_deref().and_then(|u| u.gap) {
        return Some(g.relative).filter(|g| g.is_finite());
    }
    let sw = app.results.sweep()?.as_ref().ok()?;
    let p = app.params.scene.pressure();
    let k = sw.p.windows(2).position(|w| w[0] <= p && p <= w[1])?;
    let (u0, u1) = (*sw.gap_unloading.get(k)?, *sw.gap_unloading.get(k + 1)?);
    let t = (p / sw.p[k]).ln() / (sw.p[k + 1] / sw.p[k]).ln();
    Some(u0 + t * (u1 - u0)).filter(|g| g.is_finite())
}

/// The point's unloading branch, where the path is on it.
pub fn path_row(app: &App) -> Option<&crate::tui::base::data::BranchRow> {
    let p = current_point(app)?;
    (app.params.history.on == crate::tui::model::history::Path::Unloading)
        .then(|| p.branches.iter().find(|b| b.name == "unloading"))
        .flatten()
}

/// The reference points of `quantity`: the preset's `[[reference]]` values, then the GFMD
/// points the library stores for the scene's case ([`stored_gfmd`]).
pub fn references(app: &App, quantity: &str) -> Vec<asperity::input::preset::ReferencePoint> {
    // a measured surface is another system: the preset's reference values are not its own
    if crate::tui::base::words::surface_name(&app.params.scene).is_some() {
        return Vec::new();
    }
    let preset = &app.params.preset;
    preset
        .reference
        .iter()
        .cloned()
        .chain(stored_gfmd(preset, &app.params.scene))
        .filter(|r| r.quantity == quantity)
        .collect()
}

/// Legend name of a reference point: its source, and its conditions where they differ from
/// the scene's.
pub fn reference_name(app: &App, r: &asperity::input::preset::ReferencePoint, with_thickness: bool) -> String {
    let mut cond = Vec::new();
    let gamma = r.gamma.unwrap_or(app.params.preset.adhesion.surface_energy_j_m2);
    if gamma != app.params.scene.surface_energy_j_m2() {
        cond.push(format!("γ_s={}", crate::numfmt::short(gamma)));
    }
    let t = r.thickness_qr.unwrap_or(f64::INFINITY);
    if with_thickness && t.to_bits() != app.params.scene.thickness_qr().to_bits() {
        cond.push(format!("t·q_r={}", crate::numfmt::short(t)));
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
pub fn reference_series(app: &App, quantity: &str, y: impl Fn(f64, f64) -> f64) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    for r in references(app, quantity) {
        let name = reference_name(app, &r, true);
        let pt = (r.pressure, y(r.pressure, r.value));
        match out.iter_mut().find(|s| s.name == name) {
            Some(s) => s.points.push(pt),
            None => out.push(Series {
                name,
                points: vec![pt],
                role: Role::Reference,
                style: Draw::Points,
                look: None,
            }),
        }
    }
    out
}

/// A preview sweep's chart says that the full one is on its way.
pub fn mark_preview(m: &mut Chart, sw: &SweepData) {
    if sw.preview {
        m.title.push_str(" · refining…");
    }
}

pub fn sweep_of(app: &App) -> Option<&SweepData> {
    app.results.sweep().and_then(|r| r.as_ref().ok())
}

/// The load charts share one x axis: the requested p* range, whatever converged.
pub fn load_x(app: &App) -> [f64; 2] {
    let (a, b) = app.range();
    [a.log10(), b.log10()]
}

/// Marks the current load: a guide at `x` and the current point (drawn under the reference
/// points, which a caption may point at).
pub fn add_current(m: &mut Chart, x: f64, y: Option<f64>) {
    m.vlines.insert(
        0,
        VLine {
            x,
            role: Role::Guide,
            name: String::new(),
        },
    );
    if let Some(y) = y.filter(|y| y.is_finite()) {
        // under the reference points: a caption points at them, and the guide marks p*
        let at = m
            .series
            .iter()
            .position(|s| s.role == Role::Reference)
            .unwrap_or(m.series.len());
        m.series
            .insert(at, Series::new("p*", vec![(x, y)], Role::Current, Draw::Points));
    }
}
