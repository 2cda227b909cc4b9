//! The explorer's charts as plain data: [`build`] turns the [`App`]'s results into a
//! [`Chart`] (title, axis titles, scales, series in data units, vertical markers). The
//! terminal view ([`crate::tui::view`]) draws a model with ratatui; `s` ([`crate::tui::effects::export`]) hands
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
//! | `scales`     | Pr(σ*, q) at one resolution q of the march, the wall −σ_a*(q), Pr at q_s | [S-5, S-7, S-8] |
//! | `scales-area`| a_r(q) along the resolution, the scale view's q marked        | [S-6]      |
//! | `stress`     | σ̄_c*(p*)                                                      | Fig. 5     |
//! | `gap`        | ū/h_rms(p*)                                                   | Fig. 6     |
//! | `psd`        | C(q) of the scene's spectrum (a preset's or a measured one), cut-offs, self-affine fit | §1 |
//!
//! Stresses and pressures are reduced by E*ḡ (σ* = σ/E*ḡ, p* = p/E*ḡ), the gap by h_rms;
//! Pr(σ*) is a density in σ* (∫Pr dσ* = a_r). With `M` every model (1–4, model 5 on an
//! adhesive scene, and the custom one when it is selected) is drawn with its own colour and marker. The preset's `[[reference]]`
//! points are drawn as points named by their source (and the conditions, where they differ
//! from the scene's).

pub mod load;
pub mod plot;
pub mod psd;
pub mod scales;
pub mod shared;
pub mod snapshot;

use crate::tui::base::data::{self, PointData};
pub use crate::tui::base::kinds::{overlay_models, slot, slot_name, ChartKind, Needs};
use crate::tui::charts::load::{area, loads, thickness};
use crate::tui::charts::shared::{base, current_point, data_bounds, others, set_empty, theory_name, theory_role};
pub use crate::tui::charts::shared::{Chart, Draw, Role, Series, VLine};
use crate::tui::model::app::App;
use crate::tui::model::pins::{self, Pin};
use asperity::input::scene::Scene;
use plot::Scale;
/// Builds the chart `kind` from the app's results.
pub fn build(app: &App, kind: ChartKind) -> Chart {
    let mut m = build_own(app, kind);
    m.model = slot(&app.params.scene.model());
    draw_pins(&mut m, kind, &app.results.pins, &app.params.scene);
    m
}

/// The theory curve of every visible chart that has one (what `P` pins).
pub fn pin_curves(app: &App) -> Vec<(ChartKind, Vec<(f64, f64)>)> {
    let theory = theory_role(app);
    let mut curves: Vec<(ChartKind, Vec<(f64, f64)>)> = Vec::new();
    for k in app.ui.charts {
        if curves.iter().any(|(c, _)| *c == k) {
            continue;
        }
        let m = build_own(app, k);
        if m.empty.is_some() || m.stale {
            continue;
        }
        if let Some(s) = m.series.iter().rev().find(|s| s.role == theory && s.points.len() > 1) {
            curves.push((k, s.points.clone()));
        }
    }
    curves
}

/// The chart without the pins.
pub fn build_own(app: &App, kind: ChartKind) -> Chart {
    match kind {
        ChartKind::Pr => pr_linear(app),
        ChartKind::PrLog => pr_loglog(app),
        ChartKind::Area | ChartKind::AreaRatio => area(app, kind == ChartKind::AreaRatio),
        ChartKind::Thickness => thickness(app),
        ChartKind::Stress => loads(app, ChartKind::Stress),
        ChartKind::Gap => loads(app, ChartKind::Gap),
        ChartKind::Scales => crate::tui::charts::scales::scales(app),
        ChartKind::ScalesArea => crate::tui::charts::scales::scales_area(app),
        ChartKind::Psd => crate::tui::charts::psd::psd(app),
    }
}

fn pr_linear(app: &App) -> Chart {
    let mut title = format!("Pr(σ*) at p* = {}", crate::numfmt::sig(app.params.scene.pressure(), 3));
    if crate::tui::charts::shared::on_unloading(app) {
        // the distribution of the branch the path is on (the loading branch's until the
        // unloading branch's has come)
        let whole = current_point(app).is_some_and(|p| p.unloading.is_some());
        title.push_str(if whole {
            ", unloading branch"
        } else {
            ", loading branch"
        });
    }
    // `y`: a log density axis, for the small distributions beside a large one (thick slabs
    // beside thin ones, the tails)
    let ys = if app.ui.log_pr { Scale::Log10 } else { Scale::Linear };
    let mut m = base(title, "σ* = σ/E*ḡ", "Pr", Scale::Linear, ys);
    m.clip_y = app.ui.log_pr;
    let Some(p) = current_point(app) else {
        set_empty(&mut m, app, app.results.point());
        return m;
    };
    m.stale = app.point_is_stale();
    if let Some(c) = p.adhesionless.as_ref().filter(|_| app.ui.compare) {
        m.series
            .push(Series::new("γ_s=0", c.clone(), Role::Compare, Draw::Line));
    }
    if let Some(g) = app.gfmd_for_scene() {
        m.series.push(Series::new(
            "GFMD",
            g.pr.iter().copied().filter(|(_, d)| *d > 0.0).collect(),
            Role::Gfmd,
            Draw::Points,
        ));
    }
    for (i, o) in others(app, App::model_point) {
        m.series
            .push(Series::new(slot_name(i), o.pr.clone(), Role::Model(i), Draw::Line));
    }
    // the theory's distribution and wall on the branch the path is on
    let on = crate::tui::charts::shared::shown_point(app).unwrap_or(p);
    m.series.push(Series::new(
        theory_name(app),
        on.pr.clone(),
        theory_role(app),
        Draw::Line,
    ));
    if let Some(w) = on.wall {
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
    let peak = yb.map_or(0.0, |b| if app.ui.log_pr { 10f64.powf(b[1]) } else { b[1] });
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
    m.yb = if app.ui.log_pr {
        let top = yb.map_or(0.0, |b| b[1]);
        [top - 4.0, top + 0.1]
    } else {
        plot::guard(0.0, yb.map_or(1.0, |b| b[1]).max(0.0) * 1.05)
    };
    m
}

/// The positive-σ* part of a Pr curve (a log axis cannot show σ* ≤ 0).
fn positive(pr: &[(f64, f64)]) -> Vec<(f64, f64)> {
    pr.iter().copied().filter(|(s, d)| *s > 0.0 && *d > 0.0).collect()
}

fn pr_loglog(app: &App) -> Chart {
    let title = format!(
        "Pr(σ*) log–log at p* = {}",
        crate::numfmt::sig(app.params.scene.pressure(), 3)
    );
    let mut m = base(title, "σ* = σ/E*ḡ", "Pr", Scale::Log10, Scale::Log10);
    m.clip_y = true;
    let Some(p) = current_point(app) else {
        set_empty(&mut m, app, app.results.point());
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
    // the branch the path is on
    let theory = curve(crate::tui::charts::shared::shown_point(app).unwrap_or(p));
    if let Some(c) = p.adhesionless.as_ref().filter(|_| app.ui.compare) {
        m.series
            .push(Series::new("γ_s=0", positive(c), Role::Compare, Draw::Line));
    }
    if app.params.scene.surface_energy_j_m2() == 0.0 && p.width > 0.0 {
        // [S] Fig. 3: Pr ∝ σ* for σ* → 0 and the Gaussian tail
        let (pp, d) = (app.params.scene.pressure(), p.width);
        let xs: Vec<f64> = theory.iter().map(|q| q.0).collect();
        // each where it applies: σ* below Δ, and above Δ/2 (they coincide for σ* ≪ Δ)
        m.series.push(Series::new(
            "σ→0 asymptote",
            xs.iter()
                .filter(|&&s| s <= d)
                .map(|&s| (s, data::pr_small_stress(s, pp, d)))
                .collect(),
            Role::Closed,
            Draw::Dashed,
        ));
        m.series.push(Series::new(
            "large-σ asymptote",
            xs.iter()
                .filter(|&&s| s >= 0.5 * d)
                .map(|&s| (s, data::pr_large_stress(s, pp, d)))
                .collect(),
            Role::Closed2,
            Draw::Dashed,
        ));
    }
    if let Some(g) = app.gfmd_for_scene() {
        m.series
            .push(Series::new("GFMD", positive(&g.pr), Role::Gfmd, Draw::Points));
    }
    for (i, o) in others(app, App::model_point) {
        m.series
            .push(Series::new(slot_name(i), curve(o), Role::Model(i), Draw::Line));
    }
    m.series.push(Series::new(
        theory_name(app),
        theory.clone(),
        theory_role(app),
        Draw::Line,
    ));
    // x: the theory's σ* range; y: from 10⁻⁶ of the peak to twice the peak
    let runs = plot::segments(&theory, m.xs, m.ys);
    let refs: Vec<&[(f64, f64)]> = runs.iter().map(|r| r.as_slice()).collect();
    m.xb = plot::bounds(&refs, true, 0.0).unwrap_or([-3.0, 0.0]);
    let top = plot::bounds(&refs, false, 0.0).map_or(0.0, |b| b[1]);
    m.yb = [top - 6.0, top + 0.3];
    m
}

/// Draws the pins that have a curve of this chart's kind under its series (before them), and
/// widens the chart's plane bounds to show them.
fn draw_pins(m: &mut Chart, kind: ChartKind, pins: &[Pin], now: &Scene) {
    if m.empty.is_some() {
        return;
    }
    let mut added = Vec::new();
    for (i, p) in pins.iter().enumerate() {
        if let Some((_, pts)) = p.curves.iter().find(|(k, _)| *k == kind) {
            added.push(Series::new(
                pins::label(&p.scene, now),
                pts.clone(),
                Role::Pin(i),
                Draw::Dotted,
            ));
        }
    }
    if added.is_empty() {
        return;
    }
    for s in &added {
        for &(x, y) in &s.points {
            let (Some(px), Some(py)) = (m.xs.forward(x), m.ys.forward(y)) else {
                continue;
            };
            if !(px.is_finite() && py.is_finite()) || (m.clip_y && py < m.yb[0]) {
                continue;
            }
            // Pr charts: the flat tails do not widen the σ* axis
            let tail = matches!(kind, ChartKind::Pr) && y <= 1e-3 * m.ys.inverse(m.yb[1]);
            if !tail {
                m.xb = [m.xb[0].min(px), m.xb[1].max(px)];
            }
            m.yb = [m.yb[0].min(py), m.yb[1].max(py)];
        }
    }
    // the current curve is named the same way, by what differs from the first pin (its own
    // name while the scene is the pinned one)
    if let Some(first) = pins.first().filter(|p| p.scene != *now) {
        let now_name = pins::label(now, &first.scene);
        for s in m.series.iter_mut().filter(|s| s.role == Role::Theory) {
            s.name = now_name.clone();
        }
    }
    m.series.splice(0..0, added);
}

#[cfg(test)]
mod tests {
    use super::*;
    use asperity::input::preset::Preset;

    fn app() -> App {
        let mut a = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        a.set_typed(crate::tui::model::app::Param::Gamma, "0").unwrap();
        crate::tui::drive::compute_now(&mut a, &mut Default::default());
        a
    }

    #[test]
    fn load_charts_share_the_requested_x_axis_when_low_loads_fail() {
        let mut a = app();
        if let Some(Ok(sw)) = a.results.sweep_mut() {
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
            assert_eq!(m.vlines[0].x, a.params.scene.pressure(), "{k:?}");
            assert!(m.series.iter().any(|s| s.role == Role::Current), "{k:?}");
        }
    }

    #[test]
    fn asymptotes_follow_the_closed_forms_and_eq18_is_drawn() {
        let a = app();
        let m = build(&a, ChartKind::PrLog);
        let p = a.results.point().unwrap().as_ref().unwrap();
        let small = m.series.iter().find(|s| s.name == "σ→0 asymptote").unwrap();
        let theory = m.series.iter().find(|s| s.role == Role::Theory).unwrap();
        // at the smallest σ* the theory (mirror Gaussian) and the asymptote agree to 1e-3
        let (s0, d0) = theory.points[0];
        assert!(s0 <= 2.0 * crate::tui::base::data::PR_LOG_FROM);
        assert!(
            (small.points[0].1 / d0 - 1.0).abs() < 1e-3,
            "{} vs {d0}",
            small.points[0].1
        );
        assert!(small.points.iter().all(|q| q.0 <= p.width));
        let m = build(&a, ChartKind::Area);
        let eq = m.series.iter().find(|s| s.name == "eq. (18)").unwrap();
        for &(x, y) in &eq.points {
            assert_eq!(y, crate::tui::base::data::eq18_area(x));
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
        assert_eq!(ChartKind::Gap.cycle(1), ChartKind::Psd);
        assert_eq!(ChartKind::Psd.cycle(1), ChartKind::Pr);
        assert_eq!(ChartKind::parse("nope"), None);
    }
}
