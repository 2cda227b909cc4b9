//! The energy route on a table of energies: ū at the nodes of a uniform ln p* grid.
//!
//! ```text
//! ū(p₀) = ∫_{p₀}^{∞} U'(p)/p dp = ∫_{ln p₀}^{∞} (dU/d ln p) e^{−ln p} d ln p
//! ```
//!
//! (physics.md §5: the route of [S-12] with the sign of erratum 5, on the adhesionless U [S-11];
//! the mean gap with adhesion maps each branch onto this table, §5.1 and [`super::state`]. The
//! table also takes a stored energy U_el and a total energy apart, for energy tables with
//! adhesion such as GFMD's.) In reduced units U* = U/(E*ḡh_rms), p* = p/(E*ḡ), so
//! ū/h_rms = ∫ dU*/p*.
//!
//! Quadrature: on each grid interval dU/dx (x = ln p*) is the derivative of the cubic Lagrange
//! interpolant through the four nearest nodes, integrated against e^{−x} with 4-point
//! Gauss–Legendre; only differences U_k − U_j enter, so nothing cancels near full contact where
//! U is flat. The result of each interval is then limited to the bracket
//! [ΔU e^{−x_{j+1}}, ΔU e^{−x_j}] that holds for any U monotone on the interval: on smooth data
//! the 4th-order value lies inside it (the limiter is inactive), and across a jump of the branch
//! (a jump into contact between two nodes) it stops the cubic from ringing, so ū stays
//! monotone and ≥ 0. An interval whose change exceeds 3 times each neighbour's (`JUMP_RATIO`)
//! holds a jump whose place inside it the nodes do not show; it, every interval whose cubic
//! reaches across it, and every interval where the limiter acts take the bracket's midpoint,
//! with half the bracket's width in the error (a jump into contact in an interval 0.1 wide in
//! ln p* carries ±5 % of its term; the Richardson difference alone had missed it 12×); where the
//! caller knows the jump's load ([`KnownJump`], the refined jump-in of the loading branch)
//! the interval's change is put there instead, with the error of that placement and of the
//! smooth change moved with it (~0.5 % of the jump's term). The same sum on the
//! every-other-node grid (step 2h) gives the Richardson estimate |ū_h − ū_2h|/15 per node;
//! the reported error is that plus the unresolved jumps' and the dropped noise's parts.
//!
//! The stored energy of a stable branch does not decrease with the load (a_r(q) grows at every
//! q, and a·W(a) grows with a): a decrease larger than [`DECREASE_NOISE_REL`] of the table's
//! range is an error naming the loads (the table is then not one stable branch), smaller ones
//! are solver noise, counted as no change and added to the error.
//!
//! The reversible route (the same sum on the total U = U_el − a_r γ_s) is the gap of a path
//! without dissipation; on loading the dissipation is ≥ 0, so it bounds the gap from below, and
//! with ū ≥ 0 and non-increasing in p* the bound is [`GapTable::lower`] =
//! max(0, max_{p' ≥ p} ū_rev(p')).

use crate::error::{Error, Result};
use crate::input::scene::Scene;
use crate::surface::spectrum::GL4;
use crate::theory::engine::Evaluation;

/// A decrease of the stored elastic energy between neighbouring loads up to this fraction of
/// the table's range (max − min) is taken as solver noise; a larger one means the table is not
/// one stable branch. None at all was measured on 120-load adhesive sweeps (systems I and II,
/// models 3 and 4, t·q_r = 0.05…∞): the margin is for the adhesive solver's tolerance and
/// grid error, which move U_el smoothly with the load.
pub const DECREASE_NOISE_REL: f64 = 1e-4;

/// A jump of the branch's energy at a known load between two nodes of a table: the jump into
/// contact of a loading branch, refined by bisection ([`crate::theory::window::edge`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KnownJump {
    /// ln p* of the jump.
    pub ln_p: f64,
    /// Its uncertainty in ln p* (half the last bisection bracket).
    pub uncertainty_ln: f64,
}

/// Mean gap at the nodes of a uniform ln p* grid along one branch (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct GapTable {
    /// ln p* of the first node.
    pub ln_p0: f64,
    /// Grid step in ln p*.
    pub step: f64,
    /// Stored elastic energy U_el* = U_el/(E*ḡh_rms) at the nodes (= U* without adhesion).
    pub energy: Vec<f64>,
    /// Total energy U* = U_el* − a_r γ_s* [S-11] at the nodes.
    pub total_energy: Vec<f64>,
    /// ū/h_rms at the nodes (0 at the last one, which must be at full contact).
    pub gap: Vec<f64>,
    /// Estimated absolute error of `gap` at each node (Richardson, plus the noise set to 0).
    pub error: Vec<f64>,
    /// The reversible route ∫dU*/p* on the total energy (may be negative with adhesion).
    pub reversible: Vec<f64>,
    /// The lower bound max(0, max over the nodes at and above of `reversible`).
    pub lower: Vec<f64>,
}

impl GapTable {
    /// The table of an adhesionless branch (stored = total energy) from U* at `energy.len()`
    /// nodes ln p*_i = ln_p0 + i·step (at least 4; at least 7 for an error estimate, else the
    /// error is reported as the full gap).
    pub fn from_energy(ln_p0: f64, step: f64, energy: Vec<f64>) -> Result<GapTable> {
        let total = energy.clone();
        GapTable::from_energies(ln_p0, step, energy, total)
    }

    /// The table of one branch from U_el* (`stored`) and U* (`total`) at the nodes.
    pub fn from_energies(ln_p0: f64, step: f64, stored: Vec<f64>, total: Vec<f64>) -> Result<GapTable> {
        GapTable::from_energies_with_jump(ln_p0, step, stored, total, None)
    }

    /// [`GapTable::from_energies`] with the branch's jump at a known load, where it has one
    /// between two nodes (see the module docs).
    pub fn from_energies_with_jump(
        ln_p0: f64,
        step: f64,
        stored: Vec<f64>,
        total: Vec<f64>,
        jump: Option<KnownJump>,
    ) -> Result<GapTable> {
        let n = stored.len();
        if n < 4 || total.len() != n || !(step > 0.0 && step.is_finite()) {
            return Err(Error::field(
                "gap grid",
                format!("{n} nodes, step {step}"),
                "at least 4 nodes (stored and total energy alike) with a finite step > 0",
            ));
        }
        let p_at = |i: usize| (ln_p0 + i as f64 * step).exp();
        if let Some(i) = stored
            .iter()
            .zip(&total)
            .position(|(u, v)| !u.is_finite() || !v.is_finite())
        {
            return Err(Error::NotConverged {
                solver: crate::error::Solver::MeanGapEnergyRoute,
                reason: format!("U is not finite at p* = {:e}", p_at(i)),
            });
        }
        let noise = noise_level(&stored);
        if let Some(j) = last_decrease(&stored) {
            return Err(Error::NotConverged {
                solver: crate::error::Solver::MeanGapEnergyRoute,
                reason: format!(
                    "the stored elastic energy falls from p* = {:.4e} to {:.4e} (by {:.2e} of its range): \
                     the loads are not one stable branch, whose contact only grows with the load",
                    p_at(j),
                    p_at(j + 1),
                    (stored[j] - stored[j + 1]) / (noise / DECREASE_NOISE_REL).max(f64::MIN_POSITIVE)
                ),
            });
        }
        let sum = cumulative(ln_p0, step, &stored, true, jump);
        let gap = sum.gap;
        let mut error = richardson(ln_p0, step, &stored, &gap, jump);
        for ((e, d), u) in error.iter_mut().zip(&sum.dropped).zip(&sum.unresolved) {
            *e += d + u;
        }
        let reversible = cumulative(ln_p0, step, &total, false, jump).gap;
        let mut lower = vec![0.0; n];
        let mut best = 0.0f64;
        for i in (0..n).rev() {
            best = best.max(reversible[i]);
            lower[i] = best;
        }
        Ok(GapTable {
            ln_p0,
            step,
            energy: stored,
            total_energy: total,
            gap,
            error,
            reversible,
            lower,
        })
    }

    /// The table of one branch from its evaluations at the nodes (in increasing p*).
    pub fn from_evaluations(scene: &Scene, ln_p0: f64, step: f64, evs: &[Evaluation]) -> Result<GapTable> {
        GapTable::from_evaluations_with_jump(scene, ln_p0, step, evs, None)
    }

    /// [`GapTable::from_evaluations`] with the branch's jump at a known load.
    pub fn from_evaluations_with_jump(
        scene: &Scene,
        ln_p0: f64,
        step: f64,
        evs: &[Evaluation],
        jump: Option<KnownJump>,
    ) -> Result<GapTable> {
        let unit = crate::theory::energy::energy_unit(scene);
        let stored = evs.iter().map(|e| stored_energy(scene, e) / unit).collect();
        let total = evs.iter().map(|e| e.elastic_energy / unit).collect();
        GapTable::from_energies_with_jump(ln_p0, step, stored, total, jump)
    }

    /// p* at node i.
    pub fn pressure(&self, i: usize) -> f64 {
        (self.ln_p0 + i as f64 * self.step).exp()
    }
}

/// The stored elastic energy U_el = U + a_r(q_s)γ_s = Σ a_r W u_ela^(f) (J/m²) of an
/// evaluation [S-11, S-14]; U without adhesion.
pub fn stored_energy(scene: &Scene, ev: &Evaluation) -> f64 {
    stored_from(scene, ev.elastic_energy, ev.stats.a_r)
}

/// U_el = U + a_r(q_s)γ_s (J/m²) from a branch's total energy U and contact area a_r(q_s),
/// for tables built from branch states rather than evaluations.
pub fn stored_from(scene: &Scene, elastic_energy: f64, a_r: f64) -> f64 {
    elastic_energy + a_r * scene.gamma
}

/// The largest decrease of `stored` between neighbouring nodes that is still noise.
fn noise_level(stored: &[f64]) -> f64 {
    let (lo, hi) = stored
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &u| (a.min(u), b.max(u)));
    DECREASE_NOISE_REL * (hi - lo) + 1e-14 * hi.abs().max(lo.abs())
}

/// The highest node j after which the stored energy falls by more than noise (see the module
/// docs): the gap is unknown at and below p*_j.
pub fn last_decrease(stored: &[f64]) -> Option<usize> {
    let noise = noise_level(stored);
    (0..stored.len().saturating_sub(1))
        .rev()
        .find(|&j| stored[j] - stored[j + 1] > noise)
}

/// An interval whose change of U exceeds this many times each neighbour's holds a jump (see
/// [`cumulative`]).
const JUMP_RATIO: f64 = 3.0;

/// The cumulative sums of [`cumulative`].
struct Sums {
    /// ∫_{x_i}^{x_top} U'(x) e^{−x} dx at every node.
    gap: Vec<f64>,
    /// Per node, what counting decreases as no change dropped from the sum above it.
    dropped: Vec<f64>,
    /// Per node, the error of the unresolved jumps above it (see the module docs).
    unresolved: Vec<f64>,
}

/// ∫_{x_i}^{x_top} U'(x) e^{−x} dx at every node (cubic Lagrange derivative, GL4 per interval,
/// limited per interval, jumps placed at their midpoint or at `jump`; see the module docs).
/// With `monotone`, decreases are counted as no change.
fn cumulative(x0: f64, h: f64, u: &[f64], monotone: bool, jump: Option<KnownJump>) -> Sums {
    let n = u.len();
    // coefficient c[o][i] = Σ_g w_g ℓ_i'(o + τ_g) e^{−h(o + τ_g)} for an interval starting at
    // stencil offset o ∈ {0, 1, 2}, stencil nodes τ = 0, 1, 2, 3 (in units of h).
    let mut c = [[0.0f64; 4]; 3];
    for (o, row) in c.iter_mut().enumerate() {
        for &(xg, wg) in &GL4 {
            let tau = o as f64 + 0.5 * (1.0 + xg);
            let e = (-h * tau).exp();
            for (i, ci) in row.iter_mut().enumerate() {
                *ci += 0.5 * wg * lagrange_deriv(i, tau) * e;
            }
        }
    }
    let mut sums = Sums {
        gap: vec![0.0; n],
        dropped: vec![0.0; n],
        unresolved: vec![0.0; n],
    };
    let change = |j: usize| -> f64 {
        let du = u[j + 1] - u[j];
        if monotone {
            du.max(0.0)
        } else {
            du
        }
    };
    // a jump: an interval whose change exceeds JUMP_RATIO times each neighbour's (a smooth U
    // changes by similar amounts over neighbouring intervals, or monotonically more or less)
    let jumps: Vec<bool> = (0..n - 1)
        .map(|j| {
            let d = change(j).abs();
            let over = |i: Option<usize>| i.is_none_or(|i| d > JUMP_RATIO * change(i).abs());
            d > 0.0 && over(j.checked_sub(1)) && over((j + 2 < n).then_some(j + 1))
        })
        .collect();
    for j in (0..n - 1).rev() {
        let k = j.saturating_sub(1).min(n - 4);
        let o = j - k;
        let base = u[j];
        let mut s = 0.0;
        for i in 0..4 {
            s += c[o][i] * (u[k + i] - base);
        }
        let cubic = s * (-(x0 + k as f64 * h)).exp();
        let du = change(j);
        let lost = if monotone && u[j + 1] < u[j] {
            (u[j] - u[j + 1]) * (-(x0 + j as f64 * h)).exp()
        } else {
            0.0
        };
        let (xa, xb) = (x0 + j as f64 * h, x0 + (j + 1) as f64 * h);
        let (ea, eb) = ((-xa).exp(), (-xb).exp());
        let (b_lo, b_hi) = ((du * eb).min(du * ea), (du * eb).max(du * ea));
        // the cubic's stencil (intervals k..k+2) reaches across a jump: it rings
        let polluted = (k..k + 3).any(|i| jumps[i]);
        let (inc, unresolved) = match jump.filter(|jp| jp.ln_p >= xa && jp.ln_p < xb) {
            Some(jp) => {
                // the whole change at the jump: off by the placement's uncertainty, and by the
                // smooth change (as large as a neighbouring interval's) moved to it
                let ej = (-jp.ln_p).exp();
                let smooth = [j.checked_sub(1), (j + 2 < n).then_some(j + 1)]
                    .into_iter()
                    .flatten()
                    .map(|i| change(i).abs())
                    .fold(0.0, f64::max);
                (du * ej, du.abs() * ej * jp.uncertainty_ln.abs() + smooth * (ea - eb))
            }
            None if !polluted && cubic >= b_lo && cubic <= b_hi => (cubic, 0.0),
            None => (0.5 * (b_lo + b_hi), 0.5 * (b_hi - b_lo)),
        };
        sums.gap[j] = sums.gap[j + 1] + inc;
        sums.dropped[j] = sums.dropped[j + 1] + lost;
        sums.unresolved[j] = sums.unresolved[j + 1] + unresolved;
    }
    sums
}

/// Richardson estimate of the error of `gap` (computed on step h) from the every-other-node
/// grid; the full gap where that grid has fewer than 4 nodes.
fn richardson(x0: f64, h: f64, u: &[f64], gap: &[f64], jump: Option<KnownJump>) -> Vec<f64> {
    let n = u.len();
    let mut error = vec![0.0; n];
    // coarse grid: every other node, keeping the top one
    let first = (n - 1) % 2;
    let coarse: Vec<f64> = u.iter().skip(first).step_by(2).copied().collect();
    if coarse.len() < 4 {
        return gap.to_vec();
    }
    let cg = cumulative(x0 + first as f64 * h, 2.0 * h, &coarse, true, jump).gap;
    for (k, g) in cg.iter().enumerate() {
        error[first + 2 * k] = (gap[first + 2 * k] - g).abs() / 15.0;
    }
    for i in 0..n {
        if (i + first) % 2 == 1 {
            let lo = if i > 0 { error[i - 1] } else { 0.0 };
            let hi = if i + 1 < n { error[i + 1] } else { 0.0 };
            error[i] = lo.max(hi);
        }
    }
    error
}

/// d/dτ of the Lagrange basis polynomial ℓ_i on the nodes 0, 1, 2, 3.
fn lagrange_deriv(i: usize, tau: f64) -> f64 {
    let nodes = [0.0, 1.0, 2.0, 3.0];
    let mut denom = 1.0;
    for (m, &xm) in nodes.iter().enumerate() {
        if m != i {
            denom *= nodes[i] - xm;
        }
    }
    let mut sum = 0.0;
    for l in 0..4 {
        if l == i {
            continue;
        }
        let mut prod = 1.0;
        for (m, &xm) in nodes.iter().enumerate() {
            if m != i && m != l {
                prod *= tau - xm;
            }
        }
        sum += prod;
    }
    sum / denom
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_rule_exact_for_cubics_in_ln_p() {
        // U(x) = x³ (a cubic in x, increasing): ∫_{x_i}^{x_top} 3x² e^{−x} dx in closed form;
        // the limiter must leave the exact values alone
        let (x0, h, n) = (-3.0, 0.3, 21);
        let u: Vec<f64> = (0..n).map(|i| (x0 + i as f64 * h).powi(3)).collect();
        let Sums { gap: g, dropped, .. } = cumulative(x0, h, &u, true, None);
        let anti = |x: f64| -(-x).exp() * (3.0 * x * x + 6.0 * x + 6.0);
        let top = x0 + (n - 1) as f64 * h;
        for (i, gi) in g.iter().enumerate() {
            let x = x0 + i as f64 * h;
            let exact = anti(top) - anti(x);
            assert!((gi - exact).abs() < 1e-5 * exact.abs().max(1.0), "{i}: {gi} vs {exact}");
            assert_eq!(dropped[i], 0.0);
        }
    }

    #[test]
    fn a_step_in_the_energy_gives_its_exact_jump_and_no_ringing() {
        // U = Θ(x − x_s): ∫U'e^{−x} = e^{−x_s} at and below the step, 0 above; between two nodes
        // the step's position is unknown, so the limited rule lands in the bracket of that
        // interval and stays monotone and ≥ 0 elsewhere (a cubic alone rings to both sides)
        let (x0, h, n) = (-4.0, 0.25, 17);
        let js = 8; // the step lies between nodes 8 and 9
        let u: Vec<f64> = (0..n).map(|i| if i > js { 1.0 } else { 0.0 }).collect();
        let g = cumulative(x0, h, &u, true, None).gap;
        for w in g.windows(2) {
            assert!(w[0] >= w[1] && w[1] >= 0.0, "{g:?}");
        }
        let (lo, hi) = ((-(x0 + (js + 1) as f64 * h)).exp(), (-(x0 + js as f64 * h)).exp());
        assert!(g[0] >= lo && g[0] <= hi, "{} not in [{lo}, {hi}]", g[0]);
        assert_eq!(g[js + 1], 0.0);
    }

    #[test]
    fn a_jump_between_nodes_is_inside_the_error_and_placed_where_known() {
        // U = 0.1x + Θ(x − x_s): ∫_{x_i}^{x_top} U'e^{−x} dx = 0.1(e^{−x_i} − e^{−x_top}) +
        // e^{−x_s} below the step. Without its place the error must cover the step's term
        // anywhere in its interval; with the place known (to ±1e-3 in x) it is put there
        let (x0, h, n) = (-4.0, 0.25, 17);
        let xs = x0 + 8.3 * h;
        let u: Vec<f64> = (0..n)
            .map(|i| {
                let x = x0 + i as f64 * h;
                0.1 * x + if x > xs { 1.0 } else { 0.0 }
            })
            .collect();
        let top = x0 + (n - 1) as f64 * h;
        let exact = |x: f64| 0.1 * ((-x).exp() - (-top).exp()) + if x < xs { (-xs).exp() } else { 0.0 };
        let blind = GapTable::from_energy(x0, h, u.clone()).unwrap();
        let jump = KnownJump {
            ln_p: xs + 4e-4,
            uncertainty_ln: 1e-3,
        };
        let placed = GapTable::from_energies_with_jump(x0, h, u.clone(), u, Some(jump)).unwrap();
        for i in 0..n {
            let x = x0 + i as f64 * h;
            for t in [&blind, &placed] {
                let miss = (t.gap[i] - exact(x)).abs();
                assert!(
                    miss <= t.error[i],
                    "{i}: {} vs {} (error {})",
                    t.gap[i],
                    exact(x),
                    t.error[i]
                );
            }
            if i <= 8 {
                // the step's term dominates below it: the known place cuts its error 5×
                assert!(
                    placed.error[i] < 0.2 * blind.error[i],
                    "{i}: {} vs {}",
                    placed.error[i],
                    blind.error[i]
                );
                assert!((placed.gap[i] - exact(x)).abs() < 2e-3 * exact(x), "{i}");
            }
        }
    }

    #[test]
    fn decreases_beyond_noise_are_an_error_noise_is_dropped_into_the_error() {
        let up: Vec<f64> = (0..12).map(|i| i as f64).collect();
        let mut bump = up.clone();
        bump[6] = 5.0 - 1e-9; // below node 5 by noise: no change, counted in the error
        let t = GapTable::from_energy(-3.0, 0.3, bump).unwrap();
        assert!(t.gap.windows(2).all(|w| w[0] >= w[1]));
        assert!(t.error[0] >= 1e-9 * (3.0f64 - 5.0 * 0.3).exp() * 0.99);
        let mut fall = up;
        fall[6] = 3.0;
        let e = GapTable::from_energy(-3.0, 0.3, fall).unwrap_err().to_string();
        assert!(e.contains("not one stable branch"), "{e}");
    }

    #[test]
    fn the_lower_bound_is_the_monotone_envelope_of_the_reversible_route() {
        // total energy falling with the load (adhesion winning): the reversible route is
        // negative; the bound is 0 there and never above the stored route
        let stored: Vec<f64> = (0..12).map(|i| 0.1 * i as f64).collect();
        let total: Vec<f64> = (0..12).map(|i| 0.1 * i as f64 - 0.15 * (i as f64).min(6.0)).collect();
        let t = GapTable::from_energies(-3.0, 0.3, stored, total).unwrap();
        for i in 0..12 {
            assert!(t.lower[i] >= 0.0 && t.lower[i] >= t.reversible[i].max(0.0));
            assert!(t.lower[i] <= t.gap[i] + 1e-15, "{i}: {t:?}");
            if i > 0 {
                assert!(t.lower[i - 1] >= t.lower[i]);
            }
        }
        assert!(t.reversible[0] < 0.0);
    }
}
