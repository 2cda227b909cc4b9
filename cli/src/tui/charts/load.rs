//! The load and thickness charts: a_r(p*), a_r/p*, σ̄_c*(p*), ū/h_rms(p*) with the hysteresis
//! window's branches and edges, and a_r(t·q_r).

use crate::tui::base::data::{self, SweepData, ThicknessData};
use crate::tui::base::kinds::{slot_name, ChartKind};
use crate::tui::charts::plot::{self, Scale};
use crate::tui::charts::shared::*;
use crate::tui::model::app::App;

pub fn area(app: &App, ratio: bool) -> Chart {
    let (kind, title, ylab, ys) = if ratio {
        (ChartKind::AreaRatio, "a_r/p*", "a_r/p*", Scale::Linear)
    } else {
        (ChartKind::Area, "a_r(p*)", "a_r", Scale::Log10)
    };
    let mut m = base(title.into(), "p* = p/E*ḡ", ylab, Scale::Log10, ys);
    let y_of = |p: f64, a: f64| if ratio { a / p } else { a };
    let curve =
        |sw: &SweepData| -> Vec<(f64, f64)> { sw.p.iter().zip(&sw.a_r).map(|(&p, &a)| (p, y_of(p, a))).collect() };
    let Some(sw) = sweep_of(app) else {
        set_empty(&mut m, app, app.results.sweep());
        return m;
    };
    m.stale = app.sweep_is_stale();
    mark_preview(&mut m, sw);
    if let Some(line) = app
        .results
        .point()
        .and_then(|p| p.as_ref().ok())
        .and_then(|p| p.pull_off.as_ref())
        .filter(|_| !ratio)
    {
        m.title = format!("a_r(p*) · {line}");
    }
    if app.eq18_applies() {
        m.series.push(Series::new(
            "eq. (18)",
            sw.p.iter().map(|&p| (p, y_of(p, data::eq18_area(p)))).collect(),
            Role::Closed,
            Draw::Dashed,
        ));
    }
    for (i, o) in others(app, App::model_sweep) {
        m.series
            .push(Series::new(slot_name(i), curve(o), Role::Model(i), Draw::Line));
    }
    if !app.ui.all_models {
        hysteresis(&mut m, sw, &y_of);
    }
    m.series
        .push(Series::new(theory_name(app), curve(sw), theory_role(app), Draw::Line));
    m.series
        .extend(reference_series(app, kind.reference_quantity().unwrap_or("a_r"), y_of));
    if let Some(g) = app.gfmd_for_scene() {
        // the theory on GFMD's own (reduced) map: a second system, apart from the scene's curve
        if g.theory_sweep.len() > 1 {
            m.series.push(Series::new(
                "theory on the GFMD map",
                g.theory_sweep.iter().map(|&(p, a, _)| (p, y_of(p, a))).collect(),
                Role::GfmdTheory,
                Draw::Dashed,
            ));
        }
        m.series.push(Series::new(
            "GFMD",
            std::iter::once((g.pressure, g.a_r))
                .chain(g.sweep.iter().map(|&(p, a, _)| (p, a)))
                .map(|(p, a)| (p, y_of(p, a)))
                .collect(),
            Role::Gfmd,
            Draw::Points,
        ));
    }
    let p = app.params.scene.pressure();
    add_current(&mut m, p, path_a_r(app).map(|a| y_of(p, a)));
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
fn hysteresis(m: &mut Chart, sw: &SweepData, y_of: &dyn Fn(f64, f64) -> f64) {
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
    // the edges named with their p* (the x axis says p*)
    let edges = |x: Option<f64>| x.into_iter().collect::<Vec<f64>>();
    push_window(m, points, [edges(sw.jump_in), edges(sw.pull_off)], "");
}

/// A hysteresis window on a chart: the unloading branch (dashed, where it has a point) and
/// the jump-in and pull-off edges as vertical markers named `jump-in {unit}x`.
fn push_window(m: &mut Chart, points: Vec<(f64, f64)>, [jump_in, pull_off]: [Vec<f64>; 2], unit: &str) {
    if points.iter().any(|q| q.0.is_finite() && q.1.is_finite()) {
        m.series
            .push(Series::new("unloading", points, Role::Unloading, Draw::Dashed));
    }
    for (xs, role, what) in [
        (jump_in, Role::JumpIn, "jump-in"),
        (pull_off, Role::PullOff, "pull-off"),
    ] {
        for x in xs.into_iter().filter(|x| x.is_finite() && *x > 0.0) {
            m.vlines.push(VLine {
                x,
                role,
                name: format!("{what} {unit}{}", crate::numfmt::sig(x, 2)),
            });
        }
    }
}

/// The hysteresis windows of the thickness chart, as on the a_r(p*) chart: the unloading
/// branch's a_r (dashed) where p* lies inside a window, joined at the window's end to the
/// neighbour where it goes on as the only branch (the one nearer in ln a_r), and the edges as
/// vertical markers named with their t·q_r: jump-in where the loading branch (small contact)
/// ends, pull-off where the unloading branch ends.
fn thickness_window(m: &mut Chart, td: &ThicknessData) {
    let n = td.t.len().min(td.a_r_unloading.len()).min(td.a_r.len());
    let u = &td.a_r_unloading;
    let near = |a: f64, b: f64| (a.ln() - b.ln()).abs();
    let mut points: Vec<(f64, f64)> = Vec::new();
    for k in 0..n {
        if !u[k].is_finite() {
            continue;
        }
        let first = k == 0 || !u[k - 1].is_finite();
        let last = k + 1 == n || !u[k + 1].is_finite();
        if first && k > 0 && near(td.a_r[k - 1], u[k]) < near(td.a_r[k - 1], td.a_r[k]) {
            points.push((td.t[k - 1], td.a_r[k - 1]));
        }
        points.push((td.t[k], u[k]));
        if last && k + 1 < n && near(td.a_r[k + 1], u[k]) < near(td.a_r[k + 1], td.a_r[k]) {
            points.push((td.t[k + 1], td.a_r[k + 1]));
        }
        if last {
            points.push((f64::NAN, f64::NAN));
        }
    }
    push_window(m, points, [td.jump_in.clone(), td.pull_off.clone()], "t·q_r ");
}

/// Rows of points per load filling the gap's bracket (enough to shade a braille column).
const BAND_ROWS: usize = 12;

/// The bracket [lower, upper] of the loading branch's ū/h_rms as a shaded band: at each load,
/// BAND_ROWS + 1 points from the lower to the upper end; None without a bracket.
pub fn gap_band(sw: &SweepData) -> Option<Series> {
    if sw.gap_lower.len() != sw.p.len() || sw.gap_upper.len() != sw.p.len() {
        return None;
    }
    let mut points = Vec::new();
    for ((&p, &lo), &hi) in sw.p.iter().zip(&sw.gap_lower).zip(&sw.gap_upper) {
        if lo.is_finite() && hi.is_finite() && hi >= lo {
            points.extend((0..=BAND_ROWS).map(|k| (p, lo + (hi - lo) * k as f64 / BAND_ROWS as f64)));
        }
    }
    (!points.is_empty()).then(|| Series::new("bracket (same a_r … same load)", points, Role::Band, Draw::Points))
}

pub fn loads(app: &App, kind: ChartKind) -> Chart {
    let gap = kind == ChartKind::Gap;
    let (title, ylab) = if gap {
        ("ū/h_rms(p*)", "ū/h_rms")
    } else {
        ("σ̄_c*(p*)", "σ̄_c*")
    };
    let quantity = kind.reference_quantity().unwrap_or("mean_contact_stress");
    let mut m = base(title.into(), "p* = p/E*ḡ", ylab, Scale::Log10, Scale::Linear);
    let pick = |sw: &SweepData| -> Vec<(f64, f64)> {
        let ys = if gap { &sw.gap_rel } else { &sw.mean_contact_stress };
        sw.p.iter().copied().zip(ys.iter().copied()).collect()
    };
    let Some(sw) = sweep_of(app) else {
        set_empty(&mut m, app, app.results.sweep());
        return m;
    };
    m.stale = app.sweep_is_stale();
    mark_preview(&mut m, sw);
    // the mean gap can fail where a_r and σ̄_c* did not: this chart alone says so
    let gap_failed = gap.then(|| gap_failure(app, sw)).flatten();
    if let Some(why) = &gap_failed {
        m.title
            .push_str(&format!(" · failed: {}", crate::tui::base::words::brief(why)));
    }
    if gap {
        // the bracket of the loading branch's gap, shaded under the curves (§5.1)
        if let Some(band) = gap_band(sw) {
            m.series.push(band);
        }
    }
    for (i, o) in others(app, App::model_sweep) {
        m.series
            .push(Series::new(slot_name(i), pick(o), Role::Model(i), Draw::Line));
    }
    m.series
        .push(Series::new(theory_name(app), pick(sw), theory_role(app), Draw::Line));
    if gap && sw.gap_unloading.len() == sw.p.len() {
        m.series.push(Series::new(
            "unloading",
            sw.p.iter().copied().zip(sw.gap_unloading.iter().copied()).collect(),
            Role::Unloading,
            Draw::Dashed,
        ));
    }
    m.series.extend(reference_series(app, quantity, |_, v| v));
    if let Some(g) = app.gfmd_for_scene() {
        let y = if gap { g.gap_rel } else { g.mean_contact_stress };
        let mut points = vec![(g.pressure, y)];
        if gap {
            if g.theory_sweep.len() > 1 {
                m.series.push(Series::new(
                    "theory on the GFMD map",
                    g.theory_sweep.iter().map(|&(p, _, u)| (p, u)).collect(),
                    Role::GfmdTheory,
                    Draw::Dashed,
                ));
            }
            points.extend(g.sweep.iter().map(|&(p, _, u)| (p, u)));
        }
        m.series.push(Series::new("GFMD", points, Role::Gfmd, Draw::Points));
    }
    let y = if gap {
        path_gap(app)
    } else {
        // σ̄_c* of the branch the path is on
        crate::tui::charts::shared::path_stress(app)
    };
    add_current(&mut m, app.params.scene.pressure(), y);
    let (_, yb) = data_bounds(&m);
    m.xb = load_x(app);
    if let (Some(why), None) = (&gap_failed, yb) {
        // nothing else (GFMD, reference points) to draw: the body gives the whole reason
        m.empty = Some(format!("no data: {why}"));
    }
    let yb = yb.unwrap_or([0.0, 1.0]);
    m.yb = if gap {
        // the gap may be negative with adhesion: show what comes, and 0 for scale
        plot::guard(yb[0].min(0.0), yb[1])
    } else {
        m.fit_y = true;
        plot::guard(yb[0], yb[1])
    };
    m
}

/// Why the theory's ū/h_rms is missing from every load of the sweep `sw` (the sweep's own
/// reason, else the current point's gap error), None where some load has it.
fn gap_failure(app: &App, sw: &SweepData) -> Option<String> {
    if sw.gap_rel.iter().any(|g| g.is_finite()) {
        return None;
    }
    let point = match app.results.gap() {
        Some(Err(e)) => Some(crate::tui::base::words::describe(e)),
        _ => None,
    };
    Some(
        sw.gap_note
            .clone()
            .or(point)
            .unwrap_or_else(|| "no load of the sweep has a mean gap".into()),
    )
}

pub fn thickness(app: &App) -> Chart {
    let title = format!(
        "a_r(t·q_r) at p* = {}",
        crate::numfmt::sig(app.params.scene.pressure(), 3)
    );
    let mut m = base(title, "t·q_r", "a_r", Scale::Log10, Scale::Linear);
    let Some(td) = app.results.thickness().and_then(|r| r.as_ref().ok()) else {
        set_empty(&mut m, app, app.results.thickness());
        return m;
    };
    m.stale = app.thickness_is_stale();
    let curve = |t: &ThicknessData| -> Vec<(f64, f64)> { t.t.iter().copied().zip(t.a_r.iter().copied()).collect() };
    let (t0, t1) = (
        td.t.first().copied().unwrap_or(1e-2),
        td.t.last().copied().unwrap_or(1e2),
    );
    if let Some(a0) = &td.adhesionless {
        m.series.push(Series::new(
            "γ_s=0",
            td.t.iter().copied().zip(a0.iter().copied()).collect(),
            Role::Compare,
            Draw::Line,
        ));
    }
    if td.a_r_inf.is_finite() {
        m.series.push(Series::new(
            "t=∞",
            vec![(t0, td.a_r_inf), (t1, td.a_r_inf)],
            Role::Closed,
            Draw::Dashed,
        ));
    }
    for (i, o) in others(app, App::model_thickness) {
        m.series
            .push(Series::new(slot_name(i), curve(o), Role::Model(i), Draw::Line));
    }
    if !app.ui.all_models {
        thickness_window(&mut m, td);
    }
    m.series
        .push(Series::new(theory_name(app), curve(td), theory_role(app), Draw::Line));
    // reference a_r points at this p* with a finite thickness
    let mut refs: Vec<Series> = Vec::new();
    for r in references(app, ChartKind::Thickness.reference_quantity().unwrap_or("a_r")) {
        let Some(t) = r.thickness_qr.filter(|t| t.is_finite()) else {
            continue;
        };
        if (r.pressure / app.params.scene.pressure() - 1.0).abs() > 1e-9 {
            continue;
        }
        let name = reference_name(app, &r, false);
        match refs.iter_mut().find(|s| s.name == name) {
            Some(s) => s.points.push((t, r.value)),
            None => refs.push(Series {
                name,
                points: vec![(t, r.value)],
                role: Role::Reference,
                style: Draw::Points,
                look: None,
            }),
        }
    }
    m.series.extend(refs);
    let t = app.params.scene.thickness_qr();
    if t.is_finite() && t >= t0 && t <= t1 {
        add_current(&mut m, t, path_a_r(app));
    }
    let (_, yb) = data_bounds(&m);
    m.xb = [t0.log10(), t1.log10()];
    let yb = yb.unwrap_or([0.0, 1.0]);
    m.yb = plot::guard(0.0, yb[1].min(1.0));
    m
}
