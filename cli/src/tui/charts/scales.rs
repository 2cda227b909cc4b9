//! The scale view: the theory built scale by scale (physics.md §4; [S-5, S-7, S-8]).
//!
//! `scales` draws Pr(σ*, q) at the resolution q of the current frame, the wall at −σ_a*(q)
//! and, for comparison, the final Pr at q_s; `scales-area` draws a_r(q) along the whole
//! march with the current frame marked (and σ_a*(q) in its title). `[`/`]` scrub the frames,
//! Space plays them from q_L to q_s. The frames are the engine's own march
//! ([`crate::tui::base::data::ScalesData`]); nothing here computes.

use crate::numfmt::sig;
use crate::tui::charts::plot::{self, Scale};
use crate::tui::charts::shared::{base, set_empty, Chart, Draw, Role, Series, VLine};
use crate::tui::model::app::App;

/// Why a scale chart is empty.
fn empty(app: &App, m: &mut Chart) {
    set_empty(m, app, app.results.scales());
}

/// Pr(σ*, q) at the current frame.
pub fn scales(app: &App) -> Chart {
    let mut m = base(
        "Pr(σ*, q) scale by scale".into(),
        "σ* = σ/E*ḡ",
        "Pr",
        Scale::Linear,
        Scale::Log10,
    );
    m.clip_y = true;
    let (Some(d), Some((i, n, f))) = (app.scales_data(), app.scale_frame()) else {
        empty(app, &mut m);
        return m;
    };
    m.stale = app.scales_is_stale();
    m.title = format!(
        "Pr(σ*, q) q/q_L={} {}/{n}{} a_r(q)={}",
        sig(f.q_rel, 3),
        i + 1,
        if app.ui.playing { " ▶" } else { "" },
        sig(f.a_r, 3)
    );
    if let Some(last) = d.frames.last().filter(|_| i + 1 < n) {
        m.series
            .push(Series::new("q = q_s", last.pr.clone(), Role::Compare, Draw::Line));
    }
    m.series.push(Series::new(
        format!("q/q_L = {}", sig(f.q_rel, 3)),
        f.pr.clone(),
        Role::Theory,
        Draw::Line,
    ));
    let lo = f.pr.first().map_or(0.0, |p| p.0);
    let hi = f.pr.last().map_or(1.0, |p| p.0);
    if lo < 0.0 {
        m.vlines.push(VLine {
            x: 0.0,
            role: Role::Guide,
            name: String::new(),
        });
    }
    if f.sigma_a > 0.0 {
        m.vlines.push(VLine {
            x: -f.sigma_a,
            role: Role::Wall,
            name: "−σ_a*(q)".into(),
        });
    }
    // both axes stay put while the frames run (the frames share their σ* range): a log
    // density axis from the highest peak of any frame (the coarsest, a spike) down to 10⁻³
    // of the final frame's, so the first frames and the last are read on the same axes
    m.xb = plot::guard(lo, hi);
    let peak = |pr: &[(f64, f64)]| pr.iter().map(|p| p.1).filter(|y| y.is_finite()).fold(0.0f64, f64::max);
    let top = d.frames.iter().map(|fr| peak(&fr.pr)).fold(0.0f64, f64::max);
    let last = d.frames.last().map_or(top, |fr| peak(&fr.pr));
    m.yb = if top > 0.0 && last > 0.0 {
        plot::guard(last.log10() - 3.0, top.log10() + 0.1)
    } else {
        [-3.0, 0.0]
    };
    m
}

/// a_r(q) along the march, the current frame marked.
pub fn scales_area(app: &App) -> Chart {
    let mut m = base(
        "a_r(q) along the resolution".into(),
        "q/q_L",
        "a_r(q)",
        Scale::Log10,
        Scale::Log10,
    );
    let (Some(d), Some((_, _, f))) = (app.scales_data(), app.scale_frame()) else {
        empty(app, &mut m);
        return m;
    };
    m.stale = app.scales_is_stale();
    m.title = if f.sigma_a > 0.0 {
        format!("a_r(q)={} σ_a*(q)={}", sig(f.a_r, 3), sig(f.sigma_a, 3))
    } else {
        format!("a_r(q)={} no wall", sig(f.a_r, 3))
    };
    m.series
        .push(Series::new("a_r(q)", d.area.clone(), Role::Theory, Draw::Line));
    let x = f.q_rel.log10();
    m.vlines.push(VLine {
        x: f.q_rel,
        role: Role::Guide,
        name: String::new(),
    });
    m.series
        .push(Series::new("q", vec![(f.q_rel, f.a_r)], Role::Current, Draw::Points));
    // a_r(q) falls from 1 at q_L over decades: log axes, the top at a_r = 1
    let q_hi = d.area.last().map_or(10.0, |p| p.0).max(1.0 + 1e-9);
    m.xb = [0.0, q_hi.log10().max(x)];
    let a_min = d.area.iter().map(|p| p.1).filter(|a| *a > 0.0).fold(1.0f64, f64::min);
    m.yb = plot::guard(a_min.log10(), 0.0);
    m.clip_y = true;
    m
}
