//! The mean gap of one branch state with adhesion: the adhesionless gap at the load the
//! branch's contact carries (physics.md §5.1).
//!
//! ```text
//! ū_b(p₀) = ū₀(p_c,b),   p_c,b = ∫_{−σ_a}^∞ σ Pr_b(σ, q_s) dσ = p₀ + X_b,
//! X_b = ∫ σ_a(q) |da_r,b(q)|  (the tension carried off by the area that detached at the wall)
//! ```
//!
//! ū₀ is the adhesionless gap of the same scene (γ_s = 0) by the energy route [S-12]
//! ([`super::route`]). p_c,b is the net force the branch's contact carries per nominal area:
//! the mirror kernel [S-7] with its wall at −σ_a raises ∫σPr by σ_a per unit of area that
//! detaches (physics.md §4), so the contact carries p₀ + X and, for the load to balance, the
//! non-contact area around it must pull with X: the cohesive zones of the contact edges, which
//! the theory's Pr does not hold. That attraction presses the contact as a load would (the DMT
//! picture of Persson & Scaraggi 2014); the tension inside the contact (Pr between −σ_a and 0)
//! is balanced within it. Each branch is a state, so each branch has its own gap; without
//! adhesion p_c = p₀ and the gap is the energy route itself.
//!
//! Bracket: ū₀(p_area) ≤ ū_b ≤ ū₀(p₀), p_area the adhesionless load with the branch's a_r
//! (all contact taken as pressed at the finest scale, where adhesion adds most of it) and p₀
//! the load itself (no attraction at all). The lower end is min(ū₀(p_area), ū_b), so both ends
//! bound the reported value by construction.
//!
//! The adhesionless table covers [p_lo, p*_full] on a uniform ln p* grid ([`super::grid_from`]);
//! ū₀ between its nodes is the cubic Lagrange interpolant in ln p* (limited to the two nodes'
//! values: ū₀ falls with p), its error the table's plus |cubic − quadratic|; above p*_full it
//! is 0. p_area interpolates ln a_r linearly in ln p* between nodes (a_r ∝ p at small loads).

use super::route::GapTable;
use crate::error::{Error, Result};
use crate::input::scene::Scene;
use crate::theory::engine::{Evaluation, Options};

/// The adhesionless gap ū₀(p*)/h_rms and contact area a₀(p*) of a scene on a uniform ln p* grid
/// from a load up to full contact.
#[derive(Debug, Clone, PartialEq)]
pub struct DryGap {
    /// ln p* of the first node.
    pub ln_p0: f64,
    /// Grid step in ln p*.
    pub step: f64,
    /// ū₀/h_rms at the nodes (0 at the last, full contact).
    pub gap: Vec<f64>,
    /// Its estimated absolute error at the nodes.
    pub error: Vec<f64>,
    /// a₀ at the nodes.
    pub a_r: Vec<f64>,
}

/// The mean gap of one branch at p₀ (see the module docs); all ū/h_rms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BranchGap {
    /// The estimate ū₀(p_c).
    pub relative: f64,
    /// Its estimated absolute error (quadrature and interpolation of ū₀).
    pub error: f64,
    /// The bracket's lower end, min(ū₀(p_area), estimate).
    pub lower: f64,
    /// The bracket's upper end, ū₀(p₀): the adhesionless gap at the same load.
    pub upper: f64,
    /// p_c*: the load at which ū₀ is taken (the contact's net force per nominal area).
    pub contact_load: f64,
}

impl DryGap {
    /// The adhesionless table of `scene` (its γ_s set to 0) from `p_lo` to full contact.
    pub fn new(scene: &Scene, p_lo: f64, opts: &Options) -> Result<DryGap> {
        DryGap::new_cancellable(scene, p_lo, opts, None)
    }

    /// [`DryGap::new`], abandoned with [`crate::Error::Cancelled`] between its loads when
    /// `cancel` is set.
    pub fn new_cancellable(
        scene: &Scene,
        p_lo: f64,
        opts: &Options,
        cancel: Option<&std::sync::atomic::AtomicBool>,
    ) -> Result<DryGap> {
        let mut dry = scene.clone();
        dry.gamma = 0.0;
        dry.pressure = p_lo;
        dry.validate()?;
        let (x0, h, n) = super::grid_from(&dry, p_lo, super::GAP_STEP_LN);
        let ps: Vec<f64> = (0..n).map(|i| (x0 + i as f64 * h).exp()).collect();
        let evs = crate::theory::loads::evaluations(&dry, &ps, opts, cancel)?;
        DryGap::from_evaluations(&dry, x0, h, &evs)
    }

    /// The table from adhesionless evaluations at the nodes of a uniform ln p* grid reaching
    /// full contact.
    pub fn from_evaluations(scene: &Scene, ln_p0: f64, step: f64, evs: &[Evaluation]) -> Result<DryGap> {
        if evs.iter().any(|e| !e.branches.is_empty()) {
            return Err(Error::Unsupported(
                "the adhesionless gap table needs adhesionless evaluations".into(),
            ));
        }
        let t = GapTable::from_evaluations(scene, ln_p0, step, evs)?;
        Ok(DryGap {
            ln_p0,
            step,
            gap: t.gap,
            error: t.error,
            a_r: evs.iter().map(|e| e.stats.a_r).collect(),
        })
    }

    fn top(&self) -> f64 {
        self.ln_p0 + (self.gap.len() - 1) as f64 * self.step
    }

    /// ū₀/h_rms at p* and its error; 0 at and above the table's top (full contact). Loads
    /// below the table's first node are outside it: an error.
    pub fn gap_at(&self, p: f64) -> Result<(f64, f64)> {
        let x = p.ln();
        let n = self.gap.len();
        let first = self.ln_p0 - 1e-12 * self.ln_p0.abs().max(1.0);
        if x.is_nan() || x < first {
            return Err(Error::field(
                "mean gap load",
                format!("{p:e}"),
                format!(
                    "p* >= {:e} (the first load of the adhesionless table)",
                    self.ln_p0.exp()
                ),
            ));
        }
        if x >= self.top() {
            return Ok((0.0, 0.0));
        }
        let s = ((x - self.ln_p0) / self.step).max(0.0);
        let j = (s.floor() as usize).min(n - 2);
        let k = j.saturating_sub(1).min(n - 4);
        let tau = s - k as f64;
        let (mut cubic, mut quad) = (0.0, 0.0);
        for i in 0..4 {
            cubic += lagrange(i, 4, tau) * self.gap[k + i];
        }
        // the quadratic on the three nodes nearest to x
        let kq = if s - (j as f64) < 0.5 { j.saturating_sub(1) } else { j }.min(n - 3);
        for i in 0..3 {
            quad += lagrange(i, 3, s - kq as f64) * self.gap[kq + i];
        }
        let (lo, hi) = (self.gap[j + 1], self.gap[j]);
        let g = cubic.clamp(lo, hi);
        let err = self.error[j].max(self.error[j + 1]) + (cubic - quad).abs();
        Ok((g, err))
    }

    /// The adhesionless load p* whose contact area is `a` (the table's first load where `a` is
    /// below its a_r, its top where above).
    pub fn load_with_area(&self, a: f64) -> f64 {
        let n = self.a_r.len();
        if a.is_nan() || a <= self.a_r[0] {
            return self.ln_p0.exp();
        }
        match (0..n - 1).find(|&i| a <= self.a_r[i + 1]) {
            Some(i) => {
                let (a0, a1) = (self.a_r[i].max(f64::MIN_POSITIVE).ln(), self.a_r[i + 1].ln());
                let f = if a1 > a0 { (a.ln() - a0) / (a1 - a0) } else { 1.0 };
                (self.ln_p0 + (i as f64 + f.clamp(0.0, 1.0)) * self.step).exp()
            }
            None => self.top().exp(),
        }
    }

    /// The gap of a branch at p₀ with contact area `a_r` whose contact carries `load`
    /// (reduced; p₀ without adhesion).
    pub fn branch(&self, p0: f64, a_r: f64, load: f64) -> Result<BranchGap> {
        if !(load.is_finite() && a_r.is_finite()) {
            return Err(Error::NotConverged {
                solver: crate::error::Solver::MeanGap,
                reason: format!("the branch's contact load ({load:e}) or a_r ({a_r:e}) is not finite"),
            });
        }
        // the wall only removes tension: p_c ≥ p₀ (the sampled ∫σPr may fall a hair short)
        let p_c = load.max(p0);
        let (upper, e_up) = self.gap_at(p0)?;
        let (est, err) = self.gap_at(p_c)?;
        let (area, _) = self.gap_at(self.load_with_area(a_r).max(p0))?;
        Ok(BranchGap {
            relative: est,
            error: err.max(if p_c == p0 { e_up } else { 0.0 }),
            lower: area.min(est),
            upper,
            contact_load: p_c,
        })
    }
}

/// The Lagrange basis polynomial ℓ_i on the nodes 0, 1, …, m−1 at τ.
fn lagrange(i: usize, m: usize, tau: f64) -> f64 {
    let mut v = 1.0;
    for j in 0..m {
        if j != i {
            v *= (tau - j as f64) / (i as f64 - j as f64);
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(f: impl Fn(f64) -> f64) -> DryGap {
        let (x0, h, n) = (-6.0, 0.1, 61);
        DryGap {
            ln_p0: x0,
            step: h,
            gap: (0..n).map(|i| f(x0 + i as f64 * h)).collect(),
            error: vec![0.0; n],
            a_r: (0..n).map(|i| (x0 + i as f64 * h).exp().min(1.0)).collect(),
        }
    }

    #[test]
    fn interpolation_is_exact_for_cubics_and_its_error_covers_a_smooth_curve() {
        let cubic = table(|x| 1.0 - 0.3 * x - 0.001 * x * x * x - 0.02 * x * x);
        for x in [-5.97, -4.33, -1.05, -0.11] {
            let exact = 1.0 - 0.3 * x - 0.001 * x * x * x - 0.02 * x * x;
            let (g, _) = cubic.gap_at(f64::exp(x)).unwrap();
            assert!((g - exact).abs() < 1e-12, "{x}: {g} vs {exact}");
        }
        let smooth = table(|x| (-x).exp().ln_1p());
        for x in [-5.97, -3.04, -0.55] {
            let exact = f64::exp(-x).ln_1p();
            let (g, e) = smooth.gap_at(f64::exp(x)).unwrap();
            assert!((g - exact).abs() <= e + 1e-15, "{x}: {g} vs {exact} ± {e}");
        }
        assert_eq!(smooth.gap_at(2.0).unwrap(), (0.0, 0.0));
        assert!(smooth.gap_at(1e-4).is_err());
    }

    #[test]
    fn the_area_load_inverts_a_r_and_the_bracket_holds_the_estimate() {
        let t = table(|x| (-x).exp().ln_1p());
        // a_r = p* on this table
        for p in [3e-3, 0.02, 0.5] {
            assert!((t.load_with_area(p) / p - 1.0).abs() < 1e-9, "{p}");
        }
        assert_eq!(t.load_with_area(1e-9), t.ln_p0.exp());
        let b = t.branch(0.01, 0.03, 0.012).unwrap();
        assert!(b.lower <= b.relative && b.relative <= b.upper, "{b:?}");
        assert!(b.lower < b.relative, "the area load 0.03 > 0.012: {b:?}");
        // without tension the estimate is the adhesionless gap
        let d = t.branch(0.01, 0.01, 0.01).unwrap();
        assert_eq!(d.relative, d.upper);
    }
}
