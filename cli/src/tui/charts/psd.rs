//! The `psd` chart: the power spectrum C(q) the theory integrates (docs/physics.md §1), on
//! log–log axes, with its cut-offs and its self-affine summary.
//!
//! C(q) is in m⁴ in the convention h_rms² = 2π∫q C(q) dq; q in 1/m.
//!
//! - A preset's ideal spectrum: C = C₀ for q_L ≤ q < q_r, C₀(q/q_r)^{−2(1+H)} up to q_s
//!   (a piecewise power law: straight on log–log axes, so its three corners draw it exactly).
//! - A measured spectrum (`--surface FILE` or `--psd FILE`): the table's points, the log–log
//!   interpolant between the cut-offs [q_min, q_max] that the theory integrates, and the
//!   self-affine fit of [`asperity::surface::fit::fit_self_affine`] on the points inside the
//!   cut-offs with equal weights (the fit that gives the table its q_r): a plateau to q_r, a
//!   power law of exponent β = 2(1+H) to the fit's q_s. The plateau's level is the fit's
//!   least-squares intercept, ⟨ln C + β·max(0, ln q/q_r)⟩ over the fitted points. A fit
//!   whose H falls outside the spectrum's range (0, 1] is not drawn: the title says the table
//!   is not self-affine.
//!
//! The chart depends on the scene's spectrum only (no knob changes it), so it needs no job.

use crate::numfmt::sig;
use crate::tui::charts::plot::{self, Scale};
use crate::tui::charts::shared::{base, Chart, Draw, Role, Series, VLine};
use crate::tui::model::app::App;
use asperity::surface::fit::fit_self_affine;
use asperity::surface::spectrum::{Spectrum, HURST_RANGE};
use asperity::surface::tabulated::Tabulated;

/// The `psd` chart of the app's scene.
pub fn psd(app: &App) -> Chart {
    let mut m = base(String::new(), "q (1/m)", "C(q) (m⁴)", Scale::Log10, Scale::Log10);
    let spectrum = app.params.scene.spectrum();
    match spectrum {
        Spectrum::SelfAffine(s) => {
            m.title = format!("C(q) self-affine H={}", sig(s.hurst, 3));
            let corners: Vec<(f64, f64)> = [s.q_l(), s.q_r(), s.q_s()].into_iter().map(|q| (q, s.psd(q))).collect();
            m.series.push(Series::new("C(q)", corners, Role::Theory, Draw::Line));
        }
        Spectrum::Tabulated(t) => tabulated(&mut m, t),
        Spectrum::Discrete(_) => {
            m.empty = Some("a discrete map spectrum: see `asperity psd`".into());
            return m;
        }
    }
    let (q_l, q_r, q_s) = (spectrum.q_l(), spectrum.q_r(), spectrum.q_s());
    m.vlines.push(VLine {
        x: q_r,
        role: Role::Guide,
        name: "q_r".into(),
    });
    m.vlines.push(VLine {
        x: q_l,
        role: Role::Wall,
        name: "cut-offs".into(),
    });
    m.vlines.push(VLine {
        x: q_s,
        role: Role::Wall,
        name: String::new(),
    });
    m.xb = plot::guard(q_l.log10(), q_s.log10());
    let ys: Vec<f64> = m
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .filter(|y| y.is_finite() && *y > 0.0)
        .map(f64::log10)
        .collect();
    let (lo, hi) = ys
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
    m.yb = if lo.is_finite() {
        plot::guard(lo, hi)
    } else {
        [0.0, 1.0]
    };
    m
}

/// The table, the interpolant the theory integrates, and the self-affine fit.
fn tabulated(m: &mut Chart, t: &Tabulated) {
    let name = crate::tui::base::words::surface_name_of(t);
    m.title = format!("C(q) of {name}");
    m.series.push(Series::new(
        "table",
        t.q.iter().copied().zip(t.psd.iter().copied()).collect(),
        Role::Reference,
        Draw::Points,
    ));
    let mut used: Vec<(f64, f64)> = vec![(t.q_min, t.psd_at(t.q_min))];
    used.extend(
        t.q.iter()
            .zip(&t.psd)
            .filter(|(q, _)| **q > t.q_min && **q < t.q_max)
            .map(|(&q, &c)| (q, c)),
    );
    used.push((t.q_max, t.psd_at(t.q_max)));
    m.series
        .push(Series::new("C(q) used", used.clone(), Role::Theory, Draw::Line));
    let (q, c): (Vec<f64>, Vec<f64>) = used.iter().copied().unzip();
    let fit = fit_self_affine(&q, &c, &vec![1.0; q.len()]);
    // a fit whose H is outside the self-affine range says the table is not self-affine
    // (several bands of roughness, a single peak): no line, a word in the title
    let Some(fit) = fit.filter(|f| (HURST_RANGE.0..=HURST_RANGE.1).contains(&f.hurst)) else {
        m.title.push_str(" (not self-affine)");
        return;
    };
    let beta = fit.exponent;
    let kink = |x: f64| beta * (x / fit.q_r).ln().max(0.0);
    let fitted: Vec<&(f64, f64)> = used.iter().filter(|p| p.0 <= fit.q_s).collect();
    let ln_c0 = fitted.iter().map(|p| p.1.ln() + kink(p.0)).sum::<f64>() / fitted.len().max(1) as f64;
    let law = |x: f64| (ln_c0 - kink(x)).exp();
    let q0 = used[0].0;
    let mut pts = vec![(q0, law(q0))];
    if fit.q_r > q0 {
        pts.push((fit.q_r, law(fit.q_r)));
    }
    pts.push((fit.q_s, law(fit.q_s)));
    m.series.push(Series::new(
        format!("fit H={}±{}", sig(fit.hurst, 3), sig(fit.hurst_error, 1)),
        pts,
        Role::Closed,
        Draw::Dashed,
    ));
}
