//! Mean gap ū(p₀) [S-11, S-12]: the energy route without adhesion, each branch's state mapped
//! onto it with adhesion, and the Yang–Persson closed form.
//!
//! # Without adhesion (physics.md §5)
//!
//! ```text
//! ū(p₀) = + ∫_{p₀}^{∞} U'(p)/p dp          (reduced: ū/h_rms = ∫ dU*/p*)
//! ```
//!
//! [S-12] with the sign of erratum 5 ([`route`]). U is sampled on a uniform grid in x = ln p*
//! that reaches full contact (p*_full, where erf(p*/√(2v_full)) = erf(6), so 1 − a_r < 1e-16
//! and U' ≈ 0 above it). The default step [`GAP_STEP_LN`] keeps the Richardson error estimate
//! below 1e-6 relative on the tested scenes. A mean gap is defined for p₀ > 0 only (the
//! integrand is singular at p = 0): p₀ ≤ 0 is an error.
//!
//! # With adhesion (physics.md §5.1)
//!
//! With adhesion the energy balance does not give ū (the snap-ins dissipate an amount the
//! theory does not know, and a route over the loads above p₀ crosses the loading branch's jump
//! into contact). Each branch b at p₀ is an equilibrium state whose contact carries the net
//! force p_c,b = ∫σPr_b dσ = p₀ + X_b (the mirror kernel's wall removes tension with the
//! area that detaches; the edges' cohesive zones pull with X_b); its gap is the adhesionless
//! gap of the same scene at that load ([`state`]):
//!
//! ```text
//! ū_b(p₀) = ū₀(p_c,b),   ū₀(p_area,b) ≤ ū_b ≤ ū₀(p₀)
//! ```
//!
//! with p_area,b the adhesionless load with the branch's a_r. A sweep of N loads shares one
//! adhesionless table.

pub mod closed_form;
pub mod route;
pub mod state;

pub use closed_form::{asymptotic_slope, closed_form, closed_form_gamma_p, expint_e1};
pub use route::{stored_energy, stored_from, GapTable, KnownJump, DECREASE_NOISE_REL};
pub use state::{BranchGap, DryGap};

use crate::error::{Error, Field, Result};
use crate::input::scene::Scene;
use crate::theory::engine::Evaluation;
use crate::theory::slab::slab_factor_at;

/// Largest grid step in ln p* of the energy route (Richardson error below 1e-6 relative on the
/// tested scenes; see `tests/gap.rs`).
pub const GAP_STEP_LN: f64 = 0.1;

pub use crate::theory::persson::ENERGY_RTOL;

/// erf argument p*/√(2v_full) above which the contact is taken as full (erf(6) = 1 − 2e-17).
pub const FULL_CONTACT_ERF_ARG: f64 = 6.0;

/// Minimum number of grid nodes of the energy route.
const MIN_NODES: usize = 9;

/// The reduced pressure above which a_r = 1 to within 1e-16 for every model: with W(1) = 1 the
/// full-contact variance is v_full = ∫f²q²dm/(4ḡ²), and p*_full = 6√(2v_full). Adhesion only
/// adds contact, so this also bounds the adhesive case. Clamped to the allowed pressure range.
pub fn full_contact_pressure(scene: &Scene) -> f64 {
    let t = scene.thickness_m();
    let g2 = scene.spectrum.moment(2);
    let v_full = scene.spectrum.integrate(|q| {
        let f = slab_factor_at(q, t);
        f * f * q * q
    }) / (4.0 * g2);
    let p = FULL_CONTACT_ERF_ARG * (2.0 * v_full).sqrt();
    p.clamp(
        crate::input::scene::PRESSURE_RANGE.0 * 10.0,
        crate::input::scene::PRESSURE_RANGE.1,
    )
}

/// A uniform ln p* grid from `p_lo` reaching full contact, with step ≤ [`GAP_STEP_LN`] and at
/// least `MIN_NODES` (9) nodes: (ln p0, step, nodes).
pub fn grid_from(scene: &Scene, p_lo: f64, max_step: f64) -> (f64, f64, usize) {
    let x0 = p_lo.ln();
    let top = full_contact_pressure(scene).ln().max(x0 + 1.0);
    let intervals = ((top - x0) / max_step).ceil().max((MIN_NODES - 1) as f64) as usize;
    (x0, (top - x0) / intervals as f64, intervals + 1)
}

/// The mean gap at one load: the loading branch's (the only one without adhesion or outside a
/// hysteresis window) and, inside a window, the unloading branch's (physics.md §5.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeanGap {
    /// ū/h_rms of the loading branch: the adhesionless gap at the load its contact carries
    /// ([`state`]).
    pub relative: f64,
    /// ū in metres.
    pub metres: f64,
    /// Estimated absolute error of ū/h_rms (quadrature and interpolation of the adhesionless
    /// gap; the model's bracket is [`MeanGap::lower`]..[`MeanGap::upper`]).
    pub error: f64,
    /// U* at p₀ (U/(E*ḡh_rms)), the total energy [S-11] of the loading branch.
    pub energy_reduced: f64,
    /// The stored elastic energy U_el* at p₀ (= U* without adhesion).
    pub stored_energy_reduced: f64,
    /// The bracket's lower end: the adhesionless gap at the load with the branch's a_r (no
    /// higher than `relative`); equal to `relative` without adhesion.
    pub lower: f64,
    /// The bracket's upper end: the adhesionless gap at the same load.
    pub upper: f64,
    /// The same as `upper` (the dissipation-free route [S-12] of the scene without adhesion,
    /// where it is exact).
    pub reversible: f64,
    /// p_c*, the net force the loading branch's contact carries per nominal area (p* without
    /// adhesion).
    pub contact_load: f64,
    /// The gap of the unloading branch (the highest stable one) where it differs from the
    /// loading one at p₀ (inside a hysteresis window); None elsewhere.
    pub unloading: Option<BranchGap>,
}

/// The mean gap at the scene's pressure, p* > 0 (an error otherwise: the energy route is
/// singular at p = 0). Evaluates the scene once and the adhesionless scene from p* up to full
/// contact ([`mean_gap_of`]).
///
/// # Errors
/// [`crate::Error::NotConverged`] when the evaluation or the adhesionless table of ū₀ cannot
/// be resolved.
///
/// # Examples
/// ```
/// use asperity::input::preset::Preset;
/// use asperity::theory::{engine::Options, gap::mean_gap};
///
/// // adhesion pulls the surfaces together: at the same load the gap is smaller (§5.1)
/// let wet = Preset::resolve("system-2").unwrap().scene().unwrap().with_pressure(1e-3).unwrap();
/// let dry = wet.without_adhesion();
/// let (g, g0) = (mean_gap(&wet, &Options::default()).unwrap(), mean_gap(&dry, &Options::default()).unwrap());
/// assert!(g.relative <= g0.relative && g.lower <= g.relative && g.relative <= g.upper);
/// ```
pub fn mean_gap(scene: &Scene, opts: &crate::theory::engine::Options) -> Result<MeanGap> {
    check_load(scene.pressure)?;
    let ev = crate::theory::engine::evaluate(scene, opts)?;
    mean_gap_of(scene, &ev, opts)
}

fn check_load(p: f64) -> Result<()> {
    if p > 0.0 && p.is_finite() {
        Ok(())
    } else {
        Err(Error::invalid(
            Field::Pressure,
            p,
            "p* > 0 (the mean gap is defined for positive loads: the energy route is singular at p = 0)",
        ))
    }
}

/// The mean gap of an evaluation `ev` of `scene` at its pressure (every branch of `ev` is
/// used; nothing adhesive is solved again): the adhesionless table of the scene from p* up to
/// full contact and the load each stable branch's contact carries ([`state`]).
pub fn mean_gap_of(scene: &Scene, ev: &Evaluation, opts: &crate::theory::engine::Options) -> Result<MeanGap> {
    mean_gap_of_cancellable(scene, ev, opts, None)
}

/// [`mean_gap_of`], abandoned with [`crate::Error::Cancelled`] between the loads of its
/// adhesionless table when `cancel` is set.
pub fn mean_gap_of_cancellable(
    scene: &Scene,
    ev: &Evaluation,
    opts: &crate::theory::engine::Options,
    cancel: Option<&std::sync::atomic::AtomicBool>,
) -> Result<MeanGap> {
    let p = scene.pressure;
    check_load(p)?;
    let unit = crate::theory::energy::energy_unit(scene);
    let h_rms = scene.spectrum.rms_height();
    let energy_reduced = ev.elastic_energy / unit;
    let stored_energy_reduced = stored_energy(scene, ev) / unit;
    if p >= full_contact_pressure(scene) {
        // full contact: U' = 0 from here on, so ū = 0 on every branch
        let zero = BranchGap {
            relative: 0.0,
            error: 0.0,
            lower: 0.0,
            upper: 0.0,
            contact_load: p,
        };
        return Ok(assemble(zero, None, h_rms, energy_reduced, stored_energy_reduced));
    }
    let dry = DryGap::new_cancellable(scene, p, opts, cancel)?;
    let (loading, unloading) = branch_gaps(&dry, p, ev)?;
    Ok(assemble(
        loading,
        unloading,
        h_rms,
        energy_reduced,
        stored_energy_reduced,
    ))
}

/// The gaps of an evaluation's loading branch and, where distinct, its unloading branch, on
/// the adhesionless table `dry` (which must start at or below p).
pub fn branch_gaps(dry: &DryGap, p: f64, ev: &Evaluation) -> Result<(BranchGap, Option<BranchGap>)> {
    use crate::theory::adhesion::Branch;
    if ev.branches.is_empty() {
        return Ok((dry.branch(p, ev.stats.a_r, p)?, None));
    }
    let of = |kind: Branch| -> Result<Option<BranchGap>> {
        match ev.branches.iter().position(|b| b.branch == kind && b.stable) {
            Some(i) => {
                let rep = ev.contact_loads.get(i).copied().unwrap_or(f64::NAN);
                Ok(Some(dry.branch(p, ev.branches[i].a_r, rep)?))
            }
            None => Ok(None),
        }
    };
    let loading = of(Branch::Loading)?.ok_or_else(|| Error::NotConverged {
        solver: crate::error::Solver::MeanGap,
        reason: "the evaluation has no stable loading branch".into(),
    })?;
    Ok((loading, of(Branch::Unloading)?))
}

fn assemble(l: BranchGap, u: Option<BranchGap>, h_rms: f64, energy: f64, stored: f64) -> MeanGap {
    MeanGap {
        relative: l.relative,
        metres: l.relative * h_rms,
        error: l.error,
        energy_reduced: energy,
        stored_energy_reduced: stored,
        lower: l.lower,
        upper: l.upper,
        reversible: l.upper,
        contact_load: l.contact_load,
        unloading: u,
    }
}
