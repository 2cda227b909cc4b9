//! Pull-off and the unloading branch from the PSD alone: two DMT-type routes of the literature
//! on top of the theory's adhesionless contact (physics.md §6.3).
//!
//! In the DMT picture the attraction does not change the contact's shape: the contact carries
//! a repulsive load p_rep and is, in every respect, the adhesionless contact at that load
//! (a_r = a₀(p_rep), ū = ū₀(p_rep) by the energy route of §5), while the attraction p_att of
//! the gap around it pulls; the external load is
//!
//! ```text
//! p*(p_rep) = p_rep* − p_att*(p_rep)
//! ```
//!
//! p_att is [`Route::BearingArea`] (Ciavarella's BAM) or [`Route::GapDistribution`] (the
//! interaction law averaged over Persson's distribution of interfacial separations, Persson &
//! Scaraggi 2014), both in [`attraction`]. The curve is tabulated on the adhesionless gap
//! table's loads ([`crate::theory::gap::DryGap`]). Under load control a state is stable where
//! p rises with p_rep (falls with ū): the **unloading branch** runs from full contact down to
//! the first minimum of p, the **pull-off** p*_c = min(that minimum, 0); the **loading branch**
//! comes from ū = ∞ (p → 0⁺) up to the first maximum of p, the **jump-in**. Where both exist
//! the two branches overlap on [pull-off, jump-in]: hysteresis.

pub mod attraction;
mod curve;

pub use curve::{Hysteresis, NetPoint};

use crate::error::{Error, Result};
use crate::input::scene::Scene;
use crate::theory::engine::Options;
use crate::theory::gap::DryGap;
use crate::theory::persson;
use attraction::SpectralNodes;

/// A route to the attraction p_att.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Route {
    /// Ciavarella's bearing-area model: σ0 on the undeformed area within Δr of the flat.
    BearingArea,
    /// The exponential law averaged over Persson's P(u) of the adhesionless contact.
    GapDistribution,
}

impl Route {
    /// Both routes.
    pub const ALL: [Route; 2] = [Route::BearingArea, Route::GapDistribution];

    /// A short name ("bam", "gap-dmt").
    pub fn name(self) -> &'static str {
        match self {
            Route::BearingArea => "bam",
            Route::GapDistribution => "gap-dmt",
        }
    }
}

/// Resolution of a route.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RouteOptions {
    /// The smallest contact load p_rep* of the table (the far end of the curve).
    pub p_lo: f64,
    /// Resolutions ζ at which the gap distribution bins the detached area.
    pub zeta_points: usize,
    /// Options of the adhesionless theory (its ODE accuracy).
    pub theory: Options,
}

impl Default for RouteOptions {
    /// p_lo = 1e-10 (the pull-offs of the reference set lie at p_rep* ≥ 3e-3); 48 resolutions:
    /// on system II's 256² maps the gap route's pull-off moves by ≤ 2 % against 96–384 where
    /// it exceeds 10⁻² in p*, but by up to 2× near the threshold of stickiness (|p*_c| ≲ 10⁻³,
    /// the half-space at γ_s × 1, t·q_r = 1 at × ½), where the minimum is shallow.
    fn default() -> Self {
        RouteOptions {
            p_lo: 1e-10,
            zeta_points: 48,
            theory: Options::default(),
        }
    }
}

/// Allowed [`RouteOptions::p_lo`].
pub const P_LO_RANGE: (f64, f64) = (1e-12, 1e-4);
/// Allowed [`RouteOptions::zeta_points`].
pub const ZETA_POINTS_RANGE: (usize, usize) = (4, 2000);

/// One state on a branch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BranchState {
    /// The repulsive load the contact carries, p_rep*.
    pub contact_load: f64,
    /// a_r = a₀(p_rep).
    pub a_r: f64,
    /// ū/h_rms = ū₀(p_rep).
    pub gap: f64,
}

/// The branches at one external load p*.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BranchPoint {
    /// p*.
    pub pressure: f64,
    /// The unloading branch (the contact branch), None below the pull-off.
    pub unloading: Option<BranchState>,
    /// The loading branch: the far branch on (0, jump-in], else the contact branch at loads
    /// above the jump-in; None at p* ≤ 0 (and below the jump-in where none exists).
    pub loading: Option<BranchState>,
}

/// A route's pull-off and branches.
#[derive(Debug, Clone, PartialEq)]
pub struct RouteResult {
    /// Which route.
    pub route: Route,
    /// The pull-off p*_c ≤ 0: the most tensile load the unloading branch holds (0: none).
    pub pull_off: f64,
    /// The state at the pull-off (None when it is 0: the branch detaches at ū → ∞).
    pub at_pull_off: Option<BranchState>,
    /// The hysteresis window where the far and the contact branch overlap.
    pub hysteresis: Option<Hysteresis>,
    /// The branches at the requested loads.
    pub branch: Vec<BranchPoint>,
    /// The net-pressure curve, from the far end (smallest p_rep) to full contact.
    pub curve: Vec<NetPoint>,
}

/// The route's pull-off and its branches at `loads` (p*, tensile loads negative).
///
/// # Errors
/// [`Error::InvalidField`] for a load that is not finite or outside (−10³, 10³], for
/// [`RouteOptions`] outside [`P_LO_RANGE`] / [`ZETA_POINTS_RANGE`]; [`Error::NotConverged`]
/// where the adhesionless theory fails or the curve's minimum lies at the table's far end
/// (lower `p_lo`).
///
/// # Examples
/// ```
/// use asperity::input::preset::Preset;
/// use asperity::theory::dmt::{pull_off_route, Route, RouteOptions};
///
/// let scene = Preset::resolve("system-2").unwrap().scene().unwrap();
/// let r = pull_off_route(&scene, Route::BearingArea, &[1e-4, 0.0], &RouteOptions::default()).unwrap();
/// assert!(r.pull_off < 0.0);
/// ```
pub fn pull_off_route(scene: &Scene, route: Route, loads: &[f64], opts: &RouteOptions) -> Result<RouteResult> {
    validate(loads, opts)?;
    let dry = DryGap::new(scene, opts.p_lo, &opts.theory)?;
    let p_rep: Vec<f64> = (0..dry.gap.len())
        .map(|i| (dry.ln_p0 + i as f64 * dry.step).exp())
        .collect();
    let att = attraction_table(scene, route, &dry, &p_rep, opts)?;
    let curve: Vec<NetPoint> = (0..p_rep.len())
        .map(|i| NetPoint {
            contact_load: p_rep[i],
            attraction: att[i],
            pressure: p_rep[i] - att[i],
            gap: dry.gap[i],
            a_r: dry.a_r[i],
        })
        .collect();
    curve::assemble(route, curve, loads)
}

fn validate(loads: &[f64], opts: &RouteOptions) -> Result<()> {
    for &p in loads {
        if !(p.is_finite() && p > -1e3 && p <= 1e3) {
            return Err(Error::field("route load p*", p, "a finite p* in (-1e3, 1e3]"));
        }
    }
    if !(opts.p_lo >= P_LO_RANGE.0 && opts.p_lo <= P_LO_RANGE.1) {
        return Err(Error::field(
            "route p_lo",
            opts.p_lo,
            format!("[{:e}, {:e}]", P_LO_RANGE.0, P_LO_RANGE.1),
        ));
    }
    if !(ZETA_POINTS_RANGE.0..=ZETA_POINTS_RANGE.1).contains(&opts.zeta_points) {
        return Err(Error::field(
            "route zeta_points",
            opts.zeta_points,
            format!("{}..={}", ZETA_POINTS_RANGE.0, ZETA_POINTS_RANGE.1),
        ));
    }
    opts.theory.validate()
}

/// The attraction σ0*-scaled at each contact load of the table (0 without adhesion).
fn attraction_table(scene: &Scene, route: Route, dry: &DryGap, p_rep: &[f64], opts: &RouteOptions) -> Result<Vec<f64>> {
    if !scene.is_adhesive() {
        return Ok(vec![0.0; p_rep.len()]);
    }
    let h = scene.spectrum().moment(0).sqrt();
    let range = scene.range_m() / h;
    let strength = scene.surface_energy_j_m2() / scene.range_m() / scene.stress_unit();
    match route {
        Route::BearingArea => Ok(dry
            .gap
            .iter()
            .map(|&g| attraction::bearing_area(g, range, strength))
            .collect()),
        Route::GapDistribution => {
            let nodes = SpectralNodes::new(scene, opts.zeta_points);
            let dry_scene = scene.without_adhesion();
            p_rep
                .iter()
                .map(|&p| {
                    let s = dry_scene.clone().with_pressure(p)?;
                    let sol = persson::solve(&s, &opts.theory.accuracy)?;
                    Ok(nodes.gap_distribution(&sol, range, strength))
                })
                .collect()
        }
    }
}
