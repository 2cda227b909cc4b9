//! Persson theory without adhesion: the W-coupled variance ODE and its mirror-Gaussian
//! solution (physics.md §3).
//!
//! Resolution q acts as time. Without adhesion the absorbing wall sits at σ = 0 and mirror
//! kernels compose exactly [S-5, S-7], so at every resolution
//!
//! ```text
//! Pr(σ, q) = K(σ, p₀, √V(q)),     a_r(q) = erf(p₀ / √(2V(q)))                   [S-22]
//! dV = W(a_r(q))^{2α} · f(qt)² · (qE*/2)² · dm(q),   dm = 2πqC(q)dq             [S-2, S-15]
//! ```
//!
//! (f² in the variance: physics.md §7 erratum 3). In reduced units v = V/(E*ḡ)² and with
//! s = ln q this is the scalar ODE
//!
//! ```text
//! dv/ds = W(a(v))^{2α} · f(e^s t)² · q² · (dm/d ln q) / (4ḡ²),   v(ln q_L) = 0,
//! ```
//!
//! so that v(q_s) = 1/4 for W = f = 1 and a_r = erf(√2 p*) (original Persson theory). It is
//! integrated with adaptive Dormand–Prince 5(4) ([`crate::numerics::ode`]) segment by segment between
//! the PSD's breakpoints (q_L, q_r, q_s). For a discrete spectrum (the modes of a height map)
//! the integral is the paper's sum over modes: one midpoint step per |q| shell.
//!
//! Error estimate: the sum of the local error estimates in v, mapped to a_r with |da/dv|.
//!
//! Xu24 (Xu et al. 2024, docs/physics.md §3.4) does not weight the increments: with v₁(q) the
//! W ≡ 1 variance, the effective variance is v(q) = S(a_r(q))·v₁(q), S(a) = γ_f + (1 − γ_f)a,
//! and a_r(q) solves a = erf(p/√(2S(a)v₁(q))) at every resolution ([`xu24_area`]); the
//! mirror Gaussian of width √v(q_s) then gives Pr, σ̄_c and ⟨δσ_c²⟩ as for the other models.

use crate::error::Result;
use crate::input::scene::Scene;
use crate::numerics::ode::{Control, Trajectory};
use crate::surface::spectrum::{Discrete, Spectrum};
use crate::theory::mirror;
use serde::Serialize;
use statrs::function::erf::erf;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// ODE tolerance of the energies that enter the energy route. The route differentiates U in
/// p, and at small loads ū ≈ ΔU/p*: U must be smooth in p* to ~p*·tol, not just accurate to
/// the default rtol. Adaptive step sequences that change with p* make U noisy at the rtol
/// level; on a thin slab (t·q_r = 0.01, U ≈ const at small p*) rtol = 1e-7 made ū(p*)
/// non-monotone below p* = 1e-7, rtol = 1e-11 does not. A 64-point sweep still costs ~10 ms.
pub const ENERGY_RTOL: f64 = 1e-11;

/// Accuracy of the adhesionless solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accuracy {
    /// Relative tolerance of each ODE step in v.
    pub rtol: f64,
    /// Number of points at which a_r(q) is reported along the resolution.
    pub resolution_points: usize,
}

impl Default for Accuracy {
    /// rtol = 1e-7: measured relative error of a_r ~1e-9 (system 1 and 2, half-space and
    /// slabs; `cargo bench --bench engine`), two orders below the 1e-6 target, checked on a
    /// grid of scenes in `tests/persson.rs`.
    fn default() -> Self {
        Accuracy {
            rtol: 1e-7,
            resolution_points: 64,
        }
    }
}

/// a_r and v at one resolution q.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ResolutionPoint {
    /// Resolution q (1/m).
    pub q: f64,
    /// Contact fraction a_r(q).
    pub a_r: f64,
    /// Reduced stress variance v(q) = V/(E*ḡ)².
    pub variance: f64,
}

/// The adhesionless solution of one scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Solution {
    /// p*.
    pub pressure: f64,
    /// Relative contact area a_r(q_s).
    pub a_r: f64,
    /// Mean contact stress σ̄_c* = p*/a_r.
    pub mean_contact_stress: f64,
    /// Variance of the stress inside the contact ⟨δσ_c²⟩* (reduced by (E*ḡ)²).
    pub contact_stress_variance: f64,
    /// Width Δ* = √v(q_s) of the mirror Gaussian.
    pub width: f64,
    /// a_r(q) along the resolution (log-spaced in q from q_L to q_s).
    pub resolution: Vec<ResolutionPoint>,
    /// Estimated absolute error of a_r.
    pub error_estimate: f64,
    /// Right-hand-side evaluations (work measure).
    pub evaluations: usize,
    /// Dense record of v(q): (ln q, v, dv/d ln q) at the solver's points, for interpolation.
    #[serde(skip)]
    pub trajectory: Trajectory,
}

impl Solution {
    /// Pr(σ*) at the given reduced stresses (∫Pr dσ* = a_r).
    pub fn density(&self, sigma: f64) -> f64 {
        mirror::density(sigma, self.pressure, self.width)
    }

    /// A σ* grid from 0 to `sigma_max` with `n` points and Pr on it.
    pub fn sample(&self, sigma_max: f64, n: usize) -> (Vec<f64>, Vec<f64>) {
        let n = n.max(2);
        let sigma: Vec<f64> = (0..n).map(|i| sigma_max * i as f64 / (n - 1) as f64).collect();
        let density = sigma.iter().map(|&s| self.density(s)).collect();
        (sigma, density)
    }

    /// Reduced variance v(q) at resolution q (monotone cubic Hermite on the solver's points,
    /// [`Trajectory::eval_monotone`]: v never decreases with q, so a_r(q) never rises; for a
    /// discrete spectrum, the value after the last shell with |q'| ≤ q).
    pub fn variance_at(&self, q: f64) -> f64 {
        if q <= 0.0 {
            return 0.0;
        }
        self.trajectory.eval_monotone(q.ln())
    }

    /// a_r(q) at resolution q.
    pub fn area_at(&self, q: f64) -> f64 {
        area_of_variance(self.pressure, self.variance_at(q))
    }

    /// A σ* range that shows the whole distribution: up to p* + 5Δ*.
    pub fn default_sigma_max(&self) -> f64 {
        self.pressure + 5.0 * self.width
    }
}

/// The resolutions at which a_r(q) is reported: `points` (at least 2) log-spaced from q_L to
/// q_s.
pub fn resolution_grid(scene: &Scene, points: usize) -> Vec<f64> {
    let (q_l, q_s) = (scene.spectrum.q_l(), scene.spectrum.q_s());
    let n = points.max(2);
    (0..n)
        .map(|i| (q_l.ln() + (q_s / q_l).ln() * i as f64 / (n - 1) as f64).exp())
        .collect()
}

/// a_r for a reduced variance v at reduced pressure p.
#[inline]
pub fn area_of_variance(p: f64, v: f64) -> f64 {
    if v <= 0.0 {
        1.0
    } else {
        erf(p / v.sqrt() * FRAC_1_SQRT_2)
    }
}

/// a_r of Xu24 at reduced pressure p and W ≡ 1 variance v₁: the root of
/// a = erf(p/√(2(γ_f + (1 − γ_f)a)v₁)) in (0, 1]. The right side falls as a grows (S grows),
/// so the root is unique; bisection to the last bit.
pub fn xu24_area(p: f64, v1: f64, gamma_f: f64) -> f64 {
    if v1 <= 0.0 {
        return 1.0;
    }
    let s = |a: f64| gamma_f + (1.0 - gamma_f) * a;
    let g = |a: f64| a - area_of_variance(p, s(a) * v1);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    if g(hi) <= 0.0 {
        return 1.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if g(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The effective variance of Xu24 and its derivative in v₁: v = S(a)v₁ with a = xu24_area;
/// dv/dv₁ = S/(1 − v₁S'·da/dv), da/dv = −(2/√π)e^{−x²}x/(2v), x = p/√(2v).
fn xu24_variance(p: f64, v1: f64, gamma_f: f64) -> (f64, f64) {
    let a = xu24_area(p, v1, gamma_f);
    let s = gamma_f + (1.0 - gamma_f) * a;
    let v = s * v1;
    if v <= 0.0 {
        return (0.0, s);
    }
    let x = p / (2.0 * v).sqrt();
    let da_dv = -2.0 / PI.sqrt() * (-x * x).exp() * x / (2.0 * v);
    (v, s / (1.0 - v1 * (1.0 - gamma_f) * da_dv))
}

/// Xu24: the W ≡ 1 solution mapped to the effective variance S(a)·v₁ at every resolution.
fn solve_xu24(scene: &Scene, acc: &Accuracy) -> Result<Solution> {
    let gamma_f = scene
        .model
        .fudge_gamma()
        .unwrap_or(crate::input::model::FUDGE_GAMMA_DEFAULT);
    let mut plain = scene.clone();
    plain.model = crate::input::model::Model::named(1)?;
    let base = solve(&plain, acc)?;
    let p = scene.pressure;
    let mut trajectory = base.trajectory.clone();
    for i in 0..trajectory.s.len() {
        let (v, dv_dv1) = xu24_variance(p, trajectory.y[i], gamma_f);
        trajectory.y[i] = v;
        trajectory.dy[i] *= dv_dv1;
    }
    let resolution = base
        .resolution
        .iter()
        .map(|r| {
            let (v, _) = xu24_variance(p, r.variance, gamma_f);
            ResolutionPoint {
                q: r.q,
                a_r: area_of_variance(p, v),
                variance: v,
            }
        })
        .collect();
    let v1 = base.width * base.width;
    let (v_end, dv_dv1) = xu24_variance(p, v1, gamma_f);
    let width = v_end.max(0.0).sqrt();
    let (mean, var) = mirror::contact_moments(p, width);
    // the W ≡ 1 error in v₁ carried through dv/dv₁ and |da/dv|
    let err_v = if base.width > 0.0 {
        let x1 = p / (2.0 * v1).sqrt();
        let da_dv1 = 2.0 / PI.sqrt() * (-x1 * x1).exp() * x1 / (2.0 * v1);
        base.error_estimate / da_dv1.max(f64::MIN_POSITIVE) * dv_dv1
    } else {
        0.0
    };
    let error_estimate = if v_end > 0.0 {
        let x = p / (2.0 * v_end).sqrt();
        (2.0 / PI.sqrt() * (-x * x).exp() * x / (2.0 * v_end) * err_v).min(1.0)
    } else {
        0.0
    };
    Ok(Solution {
        pressure: p,
        a_r: mirror::area(p, width),
        mean_contact_stress: mean,
        contact_stress_variance: var,
        width,
        resolution,
        error_estimate,
        evaluations: base.evaluations,
        trajectory,
    })
}

/// Solves the adhesionless theory for a scene (γ is ignored: callers route adhesive scenes
/// to the adhesion solver).
pub fn solve(scene: &Scene, acc: &Accuracy) -> Result<Solution> {
    if scene.model.kind == crate::input::model::ModelKind::Xu24 {
        return solve_xu24(scene, acc);
    }
    let p = scene.pressure;
    let out_q = resolution_grid(scene, acc.resolution_points);
    let Integrated {
        v_end,
        err_v,
        evaluations,
        resolution,
        trajectory,
    } = match &scene.spectrum {
        Spectrum::SelfAffine(_) | Spectrum::Tabulated(_) => integrate_continuous(scene, acc, &out_q)?,
        Spectrum::Discrete(d) => sum_shells(scene, d, &out_q),
    };

    let width = v_end.max(0.0).sqrt();
    let a_r = mirror::area(p, width);
    let (mean, var) = mirror::contact_moments(p, width);
    // |da/dv| = (2/√π) e^{−x²} x / (2v), x = p/√(2v)
    let error_estimate = if v_end > 0.0 {
        let x = p / (2.0 * v_end).sqrt();
        2.0 / PI.sqrt() * (-x * x).exp() * x / (2.0 * v_end) * err_v
    } else {
        0.0
    };
    Ok(Solution {
        pressure: p,
        a_r,
        mean_contact_stress: mean,
        contact_stress_variance: var,
        width,
        resolution,
        error_estimate,
        evaluations,
        trajectory,
    })
}

/// The variance ODE integrated over the resolution by one of [`integrate_continuous`] and
/// [`sum_shells`]: what [`solve`] turns into the mirror Gaussian at q_s.
struct Integrated {
    /// v(q_s).
    v_end: f64,
    /// Estimated absolute error of v(q_s).
    err_v: f64,
    /// Right-hand-side evaluations (work measure).
    evaluations: usize,
    /// a_r and v at the reported resolutions.
    resolution: Vec<ResolutionPoint>,
    /// Dense record of v(q) for [`Solution::variance_at`].
    trajectory: Trajectory,
}

/// The variance ODE of the module docs for a continuous spectrum (self-affine or tabulated):
/// Dormand–Prince segment by segment between the PSD's breakpoints, so that the dense output
/// does not smear the kinks of the PSD; with a constant broadening (W^{2α} ≡ 1) v(q_s) is
/// replaced by its quadrature ([`plain_variance`]), the ODE then only giving a_r(q) along the
/// resolution.
fn integrate_continuous(scene: &Scene, acc: &Accuracy, out_q: &[f64]) -> Result<Integrated> {
    let p = scene.pressure;
    let g2 = scene.spectrum.moment(2);
    let t = scene.thickness_m();
    let model = scene.model;
    let q_s = scene.spectrum.q_s();
    let spec = &scene.spectrum;
    let mut rhs = |s: f64, v: f64| -> f64 {
        let q = s.exp();
        let a = area_of_variance(p, v);
        let f = crate::elastic::slab::slab_factor_at(q, t);
        model.broadening(a) * f * f * q * q * spec.dm_dlnq(q) / (4.0 * g2)
    };
    let ctl = Control {
        rtol: acc.rtol,
        atol: acc.rtol * 1e-3 * variance_scale(scene, t, g2),
        max_steps: 200_000,
    };
    let bp = scene.spectrum.breakpoints();
    let mut traj = Trajectory::start(bp[0].ln(), 0.0, &mut rhs);
    for w in bp.windows(2) {
        // the plateau's right end and the tail's left end differ: restart the
        // derivative record at the kink so the dense output does not smear it
        let (s0, s1) = (w[0].ln(), w[1].ln());
        let h0 = traj.last_step((s1 - s0) / 16.0).min((s1 - s0) / 4.0);
        if traj.s.len() > 1 {
            let (s, v) = traj.last();
            let d = rhs(s, v);
            *traj.dy.last_mut().unwrap() = d;
        }
        traj.advance(s1, h0, &ctl, &mut rhs)?;
    }
    let (_, mut v_end) = traj.last();
    let mut err_sum = traj.err_sum;
    if model.constant_broadening() {
        v_end = plain_variance(scene, t, g2);
        err_sum = v_end * 1e-14;
    }
    let resolution = out_q
        .iter()
        .map(|&q| {
            let v = traj.eval_monotone(q.ln().clamp(bp[0].ln(), q_s.ln()));
            ResolutionPoint {
                q,
                a_r: area_of_variance(p, v),
                variance: v,
            }
        })
        .collect();
    Ok(Integrated {
        v_end,
        err_v: err_sum,
        evaluations: traj.evaluations,
        resolution,
        trajectory: traj,
    })
}

/// The scale of the ODE's absolute tolerance: the W = 1 variance v₁ = ∫f²q²dm/(4ḡ²) (1/4 on
/// a half-space). v(q_s) lies between W_min^{2α}·v₁ and v₁, so errors below rtol·1e-3·v₁
/// cannot move a_r by more than ~rtol. (Scaling by p*² instead would ask to resolve the a_r
/// drop at v ≈ p*², which for p* = 1e-8 lies within 1e-13 of ln q_L: below the spacing of
/// doubles, and irrelevant for v(q_s).) Only its order of magnitude matters, so on a slab
/// coarse panels (1 in ln q) suffice.
fn variance_scale(scene: &Scene, t: f64, g2: f64) -> f64 {
    if t.is_infinite() {
        0.25
    } else {
        scene
            .spectrum
            .nodes(1.0)
            .iter()
            .map(|m| {
                let f = crate::elastic::slab::slab_factor_at(m.q, t);
                f * f * m.q * m.q * m.dm
            })
            .sum::<f64>()
            / (4.0 * g2)
    }
}

/// v(q_s) for W^{2α} ≡ 1: ∫f²q²dm/(4ḡ²) exactly (Gauss–Legendre, ~1e-14), 1/4 on a
/// half-space.
fn plain_variance(scene: &Scene, t: f64, g2: f64) -> f64 {
    if t.is_infinite() {
        0.25
    } else {
        scene.spectrum.integrate(|q| {
            let f = crate::elastic::slab::slab_factor_at(q, t);
            f * f * q * q
        }) / (4.0 * g2)
    }
}

/// The variance ODE for a discrete spectrum (the modes of a height map): the paper's sum over
/// modes, one midpoint step per |q| shell (predicted with W at the shell's start, corrected at
/// its middle), and v recorded as a step function of ln q.
fn sum_shells(scene: &Scene, d: &Discrete, out_q: &[f64]) -> Integrated {
    let p = scene.pressure;
    let g2 = scene.spectrum.moment(2);
    let t = scene.thickness_m();
    let model = scene.model;
    let q_l = scene.spectrum.q_l();
    let mut v = 0.0;
    let mut shells = Vec::with_capacity(d.modes.len());
    for m in &d.modes {
        let f = crate::elastic::slab::slab_factor_at(m.q, t);
        let base = f * f * m.q * m.q * m.dm / (4.0 * g2);
        // midpoint in the shell: predict with W at the start, correct at the middle
        let pred = v + 0.5 * model.broadening(area_of_variance(p, v)) * base;
        v += model.broadening(area_of_variance(p, pred)) * base;
        shells.push((m.q, v));
    }
    let resolution = out_q
        .iter()
        .map(|&q| {
            let i = shells.partition_point(|&(qq, _)| qq <= q * (1.0 + 1e-12));
            let v = if i == 0 { 0.0 } else { shells[i - 1].1 };
            ResolutionPoint {
                q,
                a_r: area_of_variance(p, v),
                variance: v,
            }
        })
        .collect();
    // step-function record: v is constant between shells (zero slope)
    let mut traj = Trajectory::default();
    let mut prev = 0.0;
    for &(q, vv) in &shells {
        let s = q.ln();
        traj.s.push(s - 1e-12);
        traj.y.push(prev);
        traj.dy.push(0.0);
        traj.s.push(s);
        traj.y.push(vv);
        traj.dy.push(0.0);
        prev = vv;
    }
    if traj.s.is_empty() {
        traj.s.push(q_l.ln());
        traj.y.push(0.0);
        traj.dy.push(0.0);
    }
    Integrated {
        v_end: v,
        err_v: 0.0,
        evaluations: 2 * d.modes.len(),
        resolution,
        trajectory: traj,
    }
}
