//! Self-consistency as one scalar equation (the causal form of [S-9, S-14]).
//!
//! With C := γ(q_L) (a_r(q_L) = 1) the energy balance reads
//! a_r(q)γ(q) = C + ∫_{q_L}^{q} a_r W (q'E*f/4) dm, so for a given C the march runs forward
//! with σ_a(q) = k_G√(qE*f γ₊(q)) [S-8]. The balance at q_s then requires
//!
//! ```text
//! H(C) = C + I(C) − γ_s a_r(q_s; C) = 0,   I(C) = ∫_{q_L}^{q_s} a_r W (qE*f/4) dm,
//! ```
//!
//! with H(−u_ela^(f)) < 0 ≤ H(γ_s). Every root lies in [−I₀, γ_s], I₀ the integral of the
//! adhesionless march: below −I₀ the wall never turns on and H = C + I₀ − γ_s a₀ < 0. H is
//! scanned on points geometric in C + I₀ (it changes fastest just above the onset) and every
//! sign change is refined by regula falsi (Illinois, with bisection, geometric about −I₀,
//! whenever the bracket has not halved in two steps). Each root is a branch, ordered by C
//! (a_r grows with C): the first is the loading branch, the last the unloading one. A pair of
//! roots closer than the scan's spacing is missed: the tests compare only scenes with one.

use super::march::{march, Outcome, Path, Resolution};
use super::physics::Physics;

/// Marches run so far (all threads), for cost reports.
pub static MARCHES: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// One self-consistent solution.
#[derive(Debug, Clone)]
pub struct Root {
    /// C = γ(q_L) (J/m²).
    pub c: f64,
    pub outcome: Outcome,
}

/// H(C) and the march behind it.
pub fn residual(ph: &Physics, path: &Path, res: &Resolution, c: f64) -> (f64, Outcome) {
    MARCHES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let wall = |q: f64, _v: f64, a: f64, j: f64| -> f64 {
        if a <= 0.0 {
            0.0
        } else {
            ph.sigma_a(q, (c + j) / a)
        }
    };
    let out = march(ph, path, res, &wall, Some(-c));
    (c + out.energy - ph.gamma * out.a_r, out)
}

/// All roots of H found by a scan (C + I₀ = (γ_s + I₀)·4^−k, k = `scan`…0, and C = −I₀) and
/// refinement of each sign change, in increasing C.
pub fn roots(ph: &Physics, res: &Resolution, scan: usize) -> Vec<Root> {
    roots_dense(ph, res, scan, 1)
}

/// [`roots`] with each factor 4 of the scan divided into `sub` geometric steps (a pair of
/// roots closer than a factor 4^(1/sub) in C + I₀ is missed).
pub fn roots_dense(ph: &Physics, res: &Resolution, scan: usize, sub: usize) -> Vec<Root> {
    let path = Path::new(ph, res);
    // below C = −I₀ (I₀: the integral of the adhesionless march) the wall never turns on and
    // H = C + I₀ − γ_s a₀ < 0: every root lies in [−I₀, γ_s]
    let i0 = residual(ph, &path, res, -path.e_full).1.energy;
    let lo = -i0;
    let hi = ph.gamma;
    // H changes fastest just above the onset −I₀ (a_r can grow by orders of magnitude within
    // 1e-4 of the bracket): the scan is geometric in C + I₀, from (γ_s + I₀)·4^−scan up
    let mut cs = vec![lo];
    let n = scan * sub.max(1);
    cs.extend(
        (0..=n)
            .rev()
            .map(|k| lo + (hi - lo) * 0.25f64.powf(k as f64 / sub.max(1) as f64)),
    );
    let hs: Vec<(f64, Outcome)> = cs.iter().map(|&c| residual(ph, &path, res, c)).collect();
    let mut out = Vec::new();
    let scan = cs.len() - 1;
    for k in 0..scan {
        let (h0, h1) = (hs[k].0, hs[k + 1].0);
        if h1 == 0.0 && k + 1 == scan {
            out.push(Root {
                c: cs[k + 1],
                outcome: hs[k + 1].1.clone(),
            });
        }
        if h0 == 0.0 {
            out.push(Root {
                c: cs[k],
                outcome: hs[k].1.clone(),
            });
            continue;
        }
        if h0.signum() == h1.signum() {
            continue;
        }
        out.push(bisect(ph, &path, res, (cs[k], h0), (cs[k + 1], h1), lo));
    }
    out
}

/// Illinois regula falsi on a bracket, to |ΔC| ≤ `C_TOL`·(γ_s + u_ela^(f)).
fn bisect(ph: &Physics, path: &Path, res: &Resolution, mut a: (f64, f64), mut b: (f64, f64), origin: f64) -> Root {
    let tol = C_TOL * (ph.gamma + path.e_full);
    let mut side = 0i8;
    let mut best: Option<Root> = None;
    // widths of the bracket over the last iterations: a step that has not halved it within
    // two iterations is replaced by a bisection (H is linear, with slope 1, where the wall never
    // turns on, and steep past the onset: plain regula falsi crawls there)
    let mut widths = [f64::INFINITY; 2];
    for _ in 0..200 {
        let width = (b.0 - a.0).abs();
        let falsi = (a.0 * b.1 - b.0 * a.1) / (b.1 - a.1);
        let inside = falsi.is_finite() && falsi > a.0.min(b.0) && falsi < a.0.max(b.0);
        let c = if inside && width <= 0.5 * widths[0] {
            falsi
        } else {
            // bisection, geometric about the onset where the bracket spans a factor > 4 there
            let (da, db) = (a.0.min(b.0) - origin, a.0.max(b.0) - origin);
            if da > 0.0 && db > 4.0 * da {
                origin + (da * db).sqrt()
            } else {
                0.5 * (a.0 + b.0)
            }
        };
        widths = [widths[1], width];
        let (h, o) = residual(ph, path, res, c);
        best = Some(Root { c, outcome: o });
        if h.abs() <= tol || (b.0 - a.0).abs() < tol {
            break;
        }
        if h.signum() == a.1.signum() {
            a = (c, h);
            if side == -1 {
                b.1 *= 0.5;
            }
            side = -1;
        } else {
            b = (c, h);
            if side == 1 {
                a.1 *= 0.5;
            }
            side = 1;
        }
        if (b.0 - a.0).abs() < tol {
            break;
        }
    }
    best.unwrap()
}

/// The root of H nearest to `c` (a root of a nearby resolution): secant steps from c and
/// c + `width`, kept if they converge within 8 steps without leaving [c ± 64·width]; else a
/// bracket grown from c ± `width` (doubling) and bisected.
pub fn root_near(ph: &Physics, res: &Resolution, c: f64, width: f64) -> Root {
    let path = Path::new(ph, res);
    let tol = C_TOL * (ph.gamma + path.e_full);
    let (lo_end, hi_end) = (-path.e_full, ph.gamma);
    let mut x0 = (c, residual(ph, &path, res, c));
    let c1 = if c + width < hi_end { c + width } else { c - width };
    let mut x1 = (c1, residual(ph, &path, res, c1));
    for _ in 0..8 {
        let (h0, h1) = (x0.1 .0, x1.1 .0);
        if h1.abs() <= tol || (x1.0 - x0.0).abs() < tol {
            return Root {
                c: x1.0,
                outcome: x1.1 .1,
            };
        }
        let next = x1.0 - h1 * (x1.0 - x0.0) / (h1 - h0);
        if !next.is_finite() || (next - c).abs() > 64.0 * width || next <= lo_end || next >= hi_end {
            break;
        }
        x0 = x1;
        x1 = (next, residual(ph, &path, res, next));
    }
    let mut d = width;
    loop {
        let a = (c - d).max(lo_end);
        let b = (c + d).min(hi_end);
        let ha = residual(ph, &path, res, a).0;
        let hb = residual(ph, &path, res, b).0;
        if ha.signum() != hb.signum() || ha == 0.0 || hb == 0.0 {
            return bisect(ph, &path, res, (a, ha), (b, hb), lo_end);
        }
        assert!(a > lo_end || b < hi_end, "no sign change of H in its whole bracket");
        d *= 4.0;
    }
}

/// Tolerance on C (and on H) relative to γ_s + u_ela^(f): a_r then moves by ≲ 1e-7·a_r where
/// it is steepest in C (just above the onset on a thin slab), far below the oracle's error bar.
pub const C_TOL: f64 = 1e-9;

/// The oracle's answer for a_r on the loading branch (the lowest root of H): the roots are
/// found by a scan of `scan` points at `res`, the lowest is polished again at `res` refined
/// twofold (steps split in two, h/√2), and the two levels are Richardson-extrapolated as first
/// order, a = 2a₂ − a₁ (the moving wall makes the march first order; see `march`).
///
/// `error` = |a₂ − a₁| + 1e-4·a: measured in `oracle_refinement_study` on a ladder of five
/// levels for seven scenes (systems I and II, models 1, 3, 4, t·q_r = ∞ to 0.25, p* = 1e-4 to
/// 0.05), the two-level extrapolation lies within 0.37 of this bar from the finest one (the
/// levels wander by a few 1e-5·a at low resolution: the wall crossing nodes and the
/// coarsenings of the grid make the error not quite smooth in the resolution).
#[derive(Debug, Clone)]
pub struct Answer {
    pub a_r: f64,
    pub error: f64,
    /// a_r at the two levels.
    pub levels: [f64; 2],
    /// a_r of every root of the scan at `res` (more than one: a hysteresis window).
    pub all: Vec<f64>,
    /// σ_a*(q_s) and C at the finer level.
    pub sigma_a: f64,
    pub c: f64,
}

/// Error bar of [`Answer`]: `ERROR_FRACTION`·|a₂ − a₁| + `ERROR_FLOOR`·a.
pub const ERROR_FRACTION: f64 = 1.0;
/// See [`ERROR_FRACTION`].
pub const ERROR_FLOOR: f64 = 1e-4;

pub fn loading(ph: &Physics, res: &Resolution, scan: usize) -> Answer {
    let r1 = roots(ph, res, scan);
    let first = r1.first().expect("H changes sign in its bracket");
    let width = 1e-6 * (ph.gamma + Path::new(ph, res).e_full);
    let r2 = root_near(ph, &res.refined(2.0), first.c, width);
    let (a1, a2) = (first.outcome.a_r, r2.outcome.a_r);
    let a = 2.0 * a2 - a1;
    Answer {
        a_r: a,
        error: ERROR_FRACTION * (a2 - a1).abs() + ERROR_FLOOR * a.abs(),
        levels: [a1, a2],
        all: r1.iter().map(|r| r.outcome.a_r).collect(),
        sigma_a: r2.outcome.sigma_a,
        c: r2.c,
    }
}

/// Every root of H at `res` (a scan of `scan` levels of `sub` steps each), each polished again at `res` refined
/// twofold and extrapolated like [`loading`]: (a_r, error bar, C) per branch, in increasing C.
pub fn branches(ph: &Physics, res: &Resolution, scan: usize, sub: usize) -> Vec<(f64, f64, f64)> {
    let width = 1e-6 * (ph.gamma + Path::new(ph, res).e_full);
    roots_dense(ph, res, scan, sub)
        .iter()
        .map(|r1| {
            let r2 = root_near(ph, &res.refined(2.0), r1.c, width);
            let (a1, a2) = (r1.outcome.a_r, r2.outcome.a_r);
            let a = 2.0 * a2 - a1;
            (a, ERROR_FRACTION * (a2 - a1).abs() + ERROR_FLOOR * a.abs(), r2.c)
        })
        .collect()
}

/// The default resolution of the oracle: steps of at most 5 % in B and 1/8 in ln q, at least
/// 16 nodes per width (measured cost: 20–30 marches of 10–40 ms per scene at the test
/// profile's opt-level 2 on the shared machine; 0.4–2 s per scene).
pub fn default_resolution() -> Resolution {
    Resolution {
        eps: 0.05,
        steps_per_ln_q: 8.0,
        points_per_width: 16.0,
        split: 1,
    }
}
