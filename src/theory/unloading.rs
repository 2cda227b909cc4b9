//! An unloading branch with hysteresis from the theory's own quantities: the pinned contact as
//! an ensemble of JKR patches anchored at the turning load (physics.md §6.6).
//!
//! \[S\]'s formulation gives no hysteresis window at the loads where GFMD unloads with 1.1–6.7×
//! its loading contact (§6.2). This route keeps the contact reached at the turning load p*_max
//! and lets it recede as a fixed population of adhesive patches:
//!
//! ```text
//! p*(a) = p_rep(a) − κ a^β,     κ = (p_rep(a_t) − p*_max) / a_t^β,
//! ```
//!
//! - a_t: the theory's loading a_r at p*_max (the scene's model, [S-5..S-9]);
//! - p_rep(a): the adhesionless load that holds area a, the theory's γ_s = 0 branch inverted
//!   (`theory::gap::DryGap`, log-linear between its nodes, a ∝ p below its first node);
//! - κ a^β: the tension the held area carries. Derived for n patches per area that shrink but
//!   do not vanish, each a flat punch of radius r detaching at the Griffith load
//!   √(8π r³ E* w): p_adh = n √(8π E* w) r^{3/2} with a = nπr², so β = 3/4 (the default). The
//!   patch density n and the work w enter only through κ, which the anchor fixes: the curve
//!   passes through the theory's own state (a_t, p*_max). Assumed, not derived: that the
//!   turning state is such an ensemble in equilibrium, and that n stays fixed on unloading.
//!
//! The branch runs from a_t down to the first minimum of p*(a): stable where p* rises with a
//! (load control), its minimum the pull-off (0 where the minimum lies above 0: the contact
//! then vanishes at p* → 0⁺). Without adhesion a_t = a₀(p*_max), κ = 0 and the branch is the
//! adhesionless one: unloading retraces loading.
//!
//! **Measured** (`scripts/unloading-routes.py` on `data/reference/unloading-theory-256.csv`;
//! GFMD's unloading rows of system II below the turning load 10⁻², 3 maps, with model 5's
//! a_t; no coefficient is fitted, so every number is out of sample): mean |ln(a_r/GFMD)| 0.31
//! on the slabs t·q_r ≤ 0.3 (141 rows, none detached; the theory's loading branch there:
//! 0.51), 0.56 at t·q_r 0.5 and 1, **1.18 on the half-space**, where GFMD retraces and the
//! route claims hysteresis at 15 of 16 loads; its pull-off is 4–8× GFMD's (mean |ln| 1.4–2.1).
//! `tests/unloading.rs` checks the slab number against the stored rows.

use crate::error::{Error, Result};
use crate::input::scene::Scene;
use crate::theory::engine::{evaluate, Options};
use crate::theory::gap::DryGap;

/// The detachment exponent β of a fixed population of flat-punch patches (see the module docs).
pub const PINNED_EXPONENT: f64 = 0.75;
/// Decades of a below a_t that the branch is followed before it is taken to have no minimum.
const DECADES: f64 = 10.0;
/// Nodes of the branch per decade of a.
const NODES_PER_DECADE: usize = 400;
/// The adhesionless table's first load (its a₀ ∝ p* continues below).
const DRY_P_LO: f64 = 1e-7;

/// The unloading branch of a pinned contact: p*(a) from the turning state down to its fold.
#[derive(Debug, Clone, PartialEq)]
pub struct PinnedUnloading {
    /// The turning load p*_max.
    pub turning_load: f64,
    /// a_t: the loading branch's a_r there.
    pub turning_a_r: f64,
    /// β.
    pub exponent: f64,
    /// κ (reduced stress).
    pub kappa: f64,
    /// The pull-off p*: the branch's fold, or 0 where it lies above 0.
    pub pull_off: f64,
    /// a_r at the fold.
    pub pull_off_a_r: f64,
    /// (a, p*) along the branch, a falling from a_t, p* falling to the fold.
    pub nodes: Vec<(f64, f64)>,
}

impl PinnedUnloading {
    /// a_r on the branch at p*, linear in p* between its nodes (a_t where p* ≥ p*_max: the
    /// branch starts there); `None` below the fold, where the contact is lost.
    pub fn a_r_at(&self, p: f64) -> Option<f64> {
        let first = self.nodes[0];
        if p >= first.1 {
            return Some(first.0);
        }
        self.nodes.windows(2).find(|w| w[1].1 <= p && p <= w[0].1).map(|w| {
            let ((a0, p0), (a1, p1)) = (w[0], w[1]);
            let f = if p0 > p1 { (p0 - p) / (p0 - p1) } else { 0.0 };
            a0 + f * (a1 - a0)
        })
    }
}

/// The adhesionless load that holds area `a`: `dry` inverted (a ∝ p* below its first node).
pub fn repulsive_load(dry: &DryGap, a: f64) -> f64 {
    if a <= dry.a_r[0] {
        return dry.ln_p0.exp() * a / dry.a_r[0];
    }
    dry.load_with_area(a)
}

/// The branch from its parts: the adhesionless table, the turning state (a_t, p*_max) and β.
///
/// # Errors
/// [`Error::InvalidField`] for a_t outside (0, 1], p*_max not positive and finite, β outside
/// (0, 1], or a turning load below the table's first load.
pub fn from_parts(dry: &DryGap, turning_a_r: f64, turning_load: f64, exponent: f64) -> Result<PinnedUnloading> {
    if !(turning_a_r > 0.0 && turning_a_r <= 1.0) {
        return Err(Error::field("turning contact fraction a_t", turning_a_r, "(0, 1]"));
    }
    if !(turning_load.is_finite() && turning_load >= dry.ln_p0.exp()) {
        return Err(Error::field(
            "turning load p*_max",
            turning_load,
            format!(
                "finite and >= {:e} (the adhesionless table's first load)",
                dry.ln_p0.exp()
            ),
        ));
    }
    if !(exponent > 0.0 && exponent <= 1.0) {
        return Err(Error::field("detachment exponent beta", exponent, "(0, 1]"));
    }
    let kappa = (repulsive_load(dry, turning_a_r) - turning_load).max(0.0) / turning_a_r.powf(exponent);
    let n = (DECADES * NODES_PER_DECADE as f64) as usize;
    let mut nodes: Vec<(f64, f64)> = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let a = turning_a_r * 10f64.powf(-(i as f64) / NODES_PER_DECADE as f64);
        let p = repulsive_load(dry, a) - kappa * a.powf(exponent);
        if nodes.last().is_some_and(|&(_, last)| p > last) {
            break;
        }
        nodes.push((a, p));
    }
    let (fold_a, fold_p) = nodes[nodes.len() - 1];
    Ok(PinnedUnloading {
        turning_load,
        turning_a_r,
        exponent,
        kappa,
        pull_off: fold_p.min(0.0),
        pull_off_a_r: fold_a,
        nodes,
    })
}

/// The thickest slab (t·q_r) the route was measured to hold on (system II's slabs 0.1–0.3,
/// physics.md §6.6); on thicker bodies and the half-space it claims a hysteresis GFMD does not
/// show, so the cycle reports it only up to here.
pub const PINNED_THICKEST_QR: f64 = 0.3;

/// The route's a_r on a cycle's path: for each load of `unloading` (p*, the path's unloading
/// and tensile loads below the turning load) the pinned branch's a_r from the turning state
/// (`turning_load`, `turning_a_r`: the path's top), NaN below the branch's fold. All NaN where
/// the scene is thicker than [`PINNED_THICKEST_QR`], the turning state is not a number, or the
/// adhesionless table cannot be built: the value is an addition to the path, never a reason
/// for it to fail.
pub fn pinned_on_path(
    scene: &Scene,
    turning_load: f64,
    turning_a_r: f64,
    unloading: &[f64],
    opts: &Options,
) -> Vec<f64> {
    let none = vec![f64::NAN; unloading.len()];
    if scene.thickness_qr() > PINNED_THICKEST_QR || !(turning_a_r > 0.0 && turning_load > 0.0) {
        return none;
    }
    let p_lo = DRY_P_LO.min(turning_load);
    let Ok(dry) = scene
        .clone()
        .with_pressure(turning_load)
        .and_then(|s| DryGap::new(&s, p_lo, opts))
    else {
        return none;
    };
    let Ok(branch) = from_parts(&dry, turning_a_r, turning_load, PINNED_EXPONENT) else {
        return none;
    };
    unloading
        .iter()
        .map(|&p| branch.a_r_at(p).unwrap_or(f64::NAN))
        .collect()
}

/// The pinned unloading branch of `scene` from the turning load p*_max: its loading a_r there
/// by the scene's model and its adhesionless table (γ_s = 0, the same model), then
/// [`from_parts`] with β.
///
/// # Errors
/// Those of [`from_parts`], of the scene's validation at p*_max and of the evaluations.
pub fn pinned_unloading(scene: &Scene, turning_load: f64, exponent: f64, opts: &Options) -> Result<PinnedUnloading> {
    let at_turn = scene.clone().with_pressure(turning_load)?;
    let a_t = evaluate(&at_turn, opts)?.stats.a_r;
    let dry = DryGap::new(&at_turn, DRY_P_LO.min(turning_load), opts)?;
    from_parts(&dry, a_t, turning_load, exponent)
}
