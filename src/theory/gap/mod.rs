//! Mean gap ū(p₀) from the elastic energy [S-11, S-12] (with and without adhesion), and the
//! Yang–Persson closed form.
//!
//! # The route (physics.md §5)
//!
//! Along a quasi-static path of one branch, the external load's work goes into the energy of
//! the interface or is dissipated: −p dū = dU_el − γ_s da_r(q_s) + dD, dD ≥ 0 in the direction
//! of the process, with U_el = Σ_q a_r W u_ela^(f) [S-14] the stored elastic energy and
//! −a_r γ_s the interfacial energy [S-11]. The reported gap is the one of the loading path in
//! which the interfacial energy of the contact gained is spent in the cohesive zone (the
//! adhesive stresses that pull a region into contact do the work γ_s per area and it is not
//! stored), so the load's work goes into the stored elastic energy:
//!
//! ```text
//! ū(p₀) = + ∫_{p₀}^{∞} U_el'(p)/p dp          (reduced: ū/h_rms = ∫ dU_el*/p*)
//! ```
//!
//! Without adhesion U_el = U and this is [S-12] (sign: erratum 5), the route asperity has
//! always used; as γ_s → 0 it tends to that value continuously. It is ≥ 0 and non-increasing
//! in p* on any branch whose stored energy grows with the load (a_r(q) grows at every q on a
//! stable branch, and a·W(a) grows with a); [`route`] checks that and limits each interval so
//! that a jump of the branch between two loads cannot make it ring. The reversible route on
//! U = U_el − a_r γ_s (dD = 0, [S-12] as printed) is a lower bound on loading and can be
//! negative; [`MeanGap::lower`] reports max(0, max_{p' ≥ p₀} ū_rev(p')) beside the gap.
//!
//! U is sampled on a uniform grid in x = ln p* that reaches full contact (p*_full, where
//! erf(p*/√(2v_full)) = erf(6), so 1 − a_r < 1e-16 and U' ≈ 0 above it). A sweep of N loads
//! shares one table ([`GapTable`]); the gap of another branch comes from the table of that
//! branch ([`GapTable::from_evaluations`]). The default step [`GAP_STEP_LN`] keeps the
//! Richardson error estimate below 1e-6 relative on the tested scenes. A mean gap is defined for
//! p₀ > 0 only (the integrand is singular at p = 0).

pub mod closed_form;
pub mod route;

pub use closed_form::{asymptotic_slope, closed_form, closed_form_gamma_p, expint_e1};
pub use route::{stored_energy, stored_from, GapTable, KnownJump, DECREASE_NOISE_REL};

use crate::error::Result;
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

/// The mean gap at one load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeanGap {
    /// ū/h_rms.
    pub relative: f64,
    /// ū in metres.
    pub metres: f64,
    /// Estimated absolute error of ū/h_rms.
    pub error: f64,
    /// U* at p₀ (U/(E*ḡh_rms)), the total energy [S-11].
    pub energy_reduced: f64,
    /// The stored elastic energy U_el* at p₀ (= U* without adhesion).
    pub stored_energy_reduced: f64,
    /// Lower bound of ū/h_rms on loading (the reversible route made admissible; equal to
    /// `relative` without adhesion up to quadrature error).
    pub lower: f64,
    /// The reversible route ∫dU*/p* on the total energy at p₀ (ū/h_rms, may be negative with
    /// adhesion; `lower` is its admissible form).
    pub reversible: f64,
    /// The gap of the unloading branch (the highest stable root) where it differs from the
    /// loading one at p₀ (inside a hysteresis window); None elsewhere, or where the table of
    /// that branch is not one stable branch (see [`route`]).
    pub unloading: Option<BranchGap>,
}

/// The mean gap of one branch at p₀ by the two routes on that branch's own table (the branch
/// followed from p₀ up to full contact; physics.md §5.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BranchGap {
    /// ū/h_rms = ∫dU_el*/p* on the stored elastic energy (the reported route).
    pub relative: f64,
    /// Its estimated absolute error.
    pub error: f64,
    /// ∫dU*/p* on the total energy: dissipation-free; a lower bound of the gap on loading
    /// and an upper bound on unloading (may be negative, which no admissible gap is).
    pub reversible: f64,
}

/// Mean gap at the scene's pressure (U from [`crate::theory::engine::evaluate`] on a grid from
/// p₀ to full contact). Adhesionless grids are evaluated in parallel; adhesive ones in order of
/// increasing load (the loading branch). Returns `Ok(None)` for p₀ ≤ 0.
pub fn mean_gap(scene: &Scene, opts: &crate::theory::engine::Options) -> Result<Option<MeanGap>> {
    mean_gap_knowing(scene, opts, None)
}

/// [`mean_gap`] given the loading branch's jump-in load where the caller already has it
/// (`window::window_around` at a load inside the window): no bisection of its own then.
pub fn mean_gap_knowing(
    scene: &Scene,
    opts: &crate::theory::engine::Options,
    jump_in: Option<f64>,
) -> Result<Option<MeanGap>> {
    if scene.pressure <= 0.0 || !scene.pressure.is_finite() {
        return Ok(None);
    }
    scene.validate()?;
    let unit = crate::theory::energy::energy_unit(scene);
    if scene.pressure >= full_contact_pressure(scene) {
        // full contact: U' = 0 from here on, so ū = 0 (no grid above p*_full is needed, and
        // none may leave the allowed pressure range)
        let ev = crate::theory::loads::evaluations(scene, &[scene.pressure], opts, None)?;
        return Ok(Some(MeanGap {
            relative: 0.0,
            metres: 0.0,
            error: 0.0,
            energy_reduced: ev[0].elastic_energy / unit,
            stored_energy_reduced: stored_energy(scene, &ev[0]) / unit,
            lower: 0.0,
            reversible: 0.0,
            unloading: None,
        }));
    }
    let (x0, h, n) = grid_from(scene, scene.pressure, GAP_STEP_LN);
    let ps: Vec<f64> = (0..n).map(|i| (x0 + i as f64 * h).exp()).collect();
    let evs = crate::theory::loads::evaluations(scene, &ps, opts, None)?;
    // the loading branch jumps into contact at the top of a hysteresis window: its load,
    // refined, places the jump of U_el inside its grid step (a few more solves, only then)
    let branches: Vec<Option<&[_]>> = evs.iter().map(|e| Some(e.branches.as_slice())).collect();
    let jump = if let Some(p) = jump_in {
        Some(KnownJump {
            ln_p: p.ln(),
            uncertainty_ln: 0.5 * opts.edge_rel,
        })
    } else if evs.iter().any(|e| e.branches.iter().filter(|b| b.stable).count() >= 2) {
        crate::theory::window::window_on_branches(scene, &ps, &branches, &opts.adhesion, opts.edge_rel, None)?
            .jump_in_pressure
            .map(|p| KnownJump {
                ln_p: p.ln(),
                uncertainty_ln: 0.5 * opts.edge_rel,
            })
    } else {
        None
    };
    let table = GapTable::from_evaluations_with_jump(scene, x0, h, &evs, jump)?;
    let h_rms = scene.spectrum.rms_height();
    Ok(Some(MeanGap {
        relative: table.gap[0],
        metres: table.gap[0] * h_rms,
        error: table.error[0],
        energy_reduced: table.total_energy[0],
        stored_energy_reduced: table.energy[0],
        lower: table.lower[0],
        reversible: table.reversible[0],
        // a table that is not one stable branch leaves the unloading gap unknown, not the run
        unloading: unloading_gap(scene, x0, h, &evs).unwrap_or(None),
    }))
}

/// The gap of the unloading branch at the first load of `evs` (a uniform ln p* grid up to full
/// contact, every branch solved at each load), where two stable branches exist there: the
/// route on the table of the highest stable root at every load (the unloading branch, which
/// above the window's jump-in is the loading one). No extra solves: the loads' evaluations
/// already hold every branch.
fn unloading_gap(scene: &Scene, x0: f64, h: f64, evs: &[Evaluation]) -> Result<Option<BranchGap>> {
    let stable = |e: &Evaluation| e.branches.iter().filter(|b| b.stable).count();
    if evs.first().is_none_or(|e| stable(e) < 2) {
        return Ok(None);
    }
    let unit = crate::theory::energy::energy_unit(scene);
    let (stored, total): (Vec<f64>, Vec<f64>) = evs
        .iter()
        .map(|e| {
            let (u, a) = e
                .branches
                .iter()
                .rev()
                .find(|b| b.stable)
                .map_or((e.elastic_energy, e.stats.a_r), |b| (b.elastic_energy, b.a_r));
            (stored_from(scene, u, a) / unit, u / unit)
        })
        .unzip();
    let t = GapTable::from_energies(x0, h, stored, total)?;
    Ok(Some(BranchGap {
        relative: t.gap[0],
        error: t.error[0],
        reversible: t.reversible[0],
    }))
}
