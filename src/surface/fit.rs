//! The self-affine fit of a PSD table (physics.md §1.1): ln C against ln q by weighted least
//! squares with the model C₀ for q < q_r, C₀(q/q_r)^{−β} above (β = 2(1+H) for a 2-D PSD);
//! q_r scanned over the points and refined by golden section; q_s the last point before C falls
//! (for two points) below a tenth of the power law through the two points before it.
//! Uncertainties: H from the covariance of (ln C₀, β) scaled by the residual variance; q_r from
//! where the residual sum rises by one residual variance (Δχ² = 1); q_s to the next point.

use serde::Serialize;

/// The fitted self-affine summary.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SelfAffineFit {
    /// Hurst exponent H.
    pub hurst: f64,
    /// Standard error of H.
    pub hurst_error: f64,
    /// Roll-off wave number q_r (1/m); the first bin when there is no plateau.
    pub q_r: f64,
    /// q_r's interval (Δχ² = 1), low end.
    pub q_r_low: f64,
    /// q_r's interval, high end.
    pub q_r_high: f64,
    /// Short-wavelength cut-off q_s (1/m): the last bin on the power law.
    pub q_s: f64,
    /// The next bin's q (q_s lies below it), or q_s when the data end there.
    pub q_s_high: f64,
    /// Exponent β of the fitted power law C ∝ q^{−β}.
    pub exponent: f64,
    /// Root-mean-square residual of ln C.
    pub residual: f64,
}

/// Weighted least squares of y = a − β·max(0, x − x_r) for a given x_r: (a, β, SSR, cov).
/// (a, β, SSR, the upper triangle of (XᵀWX)⁻¹).
type LineFit = (f64, f64, f64, [f64; 3]);
/// (x_r, a, β, SSR, covariance).
type KinkFit = (f64, f64, f64, f64, [f64; 3]);

fn fit_at(x: &[f64], y: &[f64], w: &[f64], xr: f64) -> Option<LineFit> {
    let (mut s00, mut s01, mut s11, mut t0, mut t1) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for ((&xi, &yi), &wi) in x.iter().zip(y).zip(w) {
        let z = -(xi - xr).max(0.0);
        s00 += wi;
        s01 += wi * z;
        s11 += wi * z * z;
        t0 += wi * yi;
        t1 += wi * z * yi;
    }
    let det = s00 * s11 - s01 * s01;
    if det.is_nan() || det <= 1e-300 * s00 * s11.max(1e-300) || s11 <= 0.0 {
        return None;
    }
    let a = (s11 * t0 - s01 * t1) / det;
    let beta = (s00 * t1 - s01 * t0) / det;
    let ssr: f64 = x
        .iter()
        .zip(y)
        .zip(w)
        .map(|((&xi, &yi), &wi)| wi * (yi - a + beta * (xi - xr).max(0.0)).powi(2))
        .sum();
    Some((a, beta, ssr, [s11 / det, -s01 / det, s00 / det]))
}

/// Fits the self-affine PSD with roll-off to a table (q ascending, C > 0, weights ≥ 0); see the
/// module docs. `hurst` assumes a 2-D PSD (β = 2(1+H)); `exponent` is β. None with fewer than
/// four points or a degenerate table.
pub fn fit_self_affine(q: &[f64], c: &[f64], weights: &[f64]) -> Option<SelfAffineFit> {
    let pts: Vec<(f64, f64, f64, f64)> = (0..q.len())
        .filter(|&i| c[i] > 0.0 && q[i] > 0.0 && weights[i] > 0.0)
        .map(|i| (q[i].ln(), c[i].ln(), weights[i], q[i]))
        .collect();
    if pts.len() < 4 {
        return None;
    }
    let solve = |m: usize| -> Option<KinkFit> {
        let x: Vec<f64> = pts[..m].iter().map(|p| p.0).collect();
        let y: Vec<f64> = pts[..m].iter().map(|p| p.1).collect();
        let w: Vec<f64> = pts[..m].iter().map(|p| p.2).collect();
        // candidates: every point that leaves two or more on the power law
        let mut best: Option<KinkFit> = None;
        for &xr in x.iter().take(m.saturating_sub(2)) {
            if let Some((a, b, ssr, cov)) = fit_at(&x, &y, &w, xr) {
                if best.is_none_or(|bb| ssr < bb.3) {
                    best = Some((xr, a, b, ssr, cov));
                }
            }
        }
        let (mut xr, _, _, mut ssr, _) = best?;
        // golden-section refinement between the neighbours of the best point
        let k = x.iter().position(|&v| v == xr).unwrap_or(0);
        let (mut lo, mut hi) = (x[k.saturating_sub(1)], x[(k + 1).min(m - 3)]);
        let f = |v: f64| fit_at(&x, &y, &w, v).map_or(f64::INFINITY, |r| r.2);
        let g = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..60 {
            let (u, v) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if f(u) < f(v) {
                hi = v;
            } else {
                lo = u;
            }
        }
        let mid = 0.5 * (lo + hi);
        // a table that is exactly a piecewise power law keeps its node (SSR at round-off)
        let floor = 1e-20 * w.iter().sum::<f64>();
        if f(mid) < ssr * (1.0 - 1e-6) - floor {
            xr = mid;
            ssr = f(mid);
        }
        let (a, b, _, cov) = fit_at(&x, &y, &w, xr)?;
        Some((xr, a, b, ssr, cov))
    };
    // q_s: the first point (from the fifth on) that falls below a tenth of the power law
    // through the two before it, and the next one with it (a drop, not one noisy bin)
    let ten = 10f64.ln();
    let line = |k: usize, x: f64| {
        let (p, q) = (&pts[k - 2], &pts[k - 1]);
        q.1 + (q.1 - p.1) / (q.0 - p.0) * (x - q.0)
    };
    let m = (4..pts.len())
        .find(|&k| {
            pts[k].1 < line(k, pts[k].0) - ten && (k + 1 == pts.len() || pts[k + 1].1 < line(k, pts[k + 1].0) - ten)
        })
        .unwrap_or(pts.len());
    let (xr, _, beta, ssr, cov) = solve(m)?;
    let wsum: f64 = pts[..m].iter().map(|p| p.2).sum();
    let dof = (m as f64 - 3.0).max(1.0);
    // residual variance per unit weight, and of one mean-weight point
    let s2 = ssr / dof;
    let beta_err = (s2 * cov[2]).max(0.0).sqrt();
    // q_r interval: where SSR ≤ min + s2 (scan in ln q)
    let (x0, x1) = (pts[0].0, pts[m.saturating_sub(3)].0);
    let (mut rlo, mut rhi) = (xr, xr);
    let x: Vec<f64> = pts[..m].iter().map(|p| p.0).collect();
    let y: Vec<f64> = pts[..m].iter().map(|p| p.1).collect();
    let w: Vec<f64> = pts[..m].iter().map(|p| p.2).collect();
    for i in 0..=400 {
        let v = x0 + (x1 - x0) * i as f64 / 400.0;
        if let Some((_, _, s, _)) = fit_at(&x, &y, &w, v) {
            if s <= ssr + s2 {
                rlo = rlo.min(v);
                rhi = rhi.max(v);
            }
        }
    }
    Some(SelfAffineFit {
        hurst: beta / 2.0 - 1.0,
        hurst_error: beta_err / 2.0,
        // a node's own q (exp∘ln may differ from it in the last bit)
        q_r: pts.iter().find(|p| p.0 == xr).map_or(xr.exp(), |p| p.3),
        q_r_low: rlo.exp(),
        q_r_high: rhi.exp(),
        q_s: pts[m - 1].3,
        q_s_high: pts.get(m).map_or(pts[m - 1].3, |p| p.3),
        exponent: beta,
        residual: (ssr / wsum).sqrt(),
    })
}
