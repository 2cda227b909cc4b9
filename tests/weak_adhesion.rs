//! The limit γ_s → 0 of the adhesive theory (`theory::adhesion`, "Weak adhesion"): from
//! the smallest subnormal surface energy up to 1e-3 J/m², on systems I and II at two loads
//! and two thicknesses, every evaluation answers (no panic, no NaN, converged), and a_r and
//! the mean gap tend to the adhesionless answer.
//!
//! Reference: the adhesionless theory of the same scene (γ_s = 0). Tolerance: the adhesive
//! march with its walls at zero differs from the adhesionless ODE by its discretisation error
//! (`tolerances::WEAK_ADHESION_REL`), and the walls of γ_s ≤ 1e-9 J/m² move a_r by less
//! than a_r·σ_a*/p* ~ 1e-5 a_r; above that the curve is checked for continuity (neighbouring
//! surface energies of the sweep differ by less than the adhesive effect allows).

use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::report::{self, PointReport};
use asperity::theory::engine::Options;
use asperity::tolerances::WEAK_ADHESION_REL;

/// The surface energies of the sweep (J/m²), smallest first.
const GAMMAS: [f64; 13] = [
    5e-324, 1e-320, 1e-300, 1e-250, 1e-100, 1e-14, 1e-12, 1e-9, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3,
];

fn scene(preset: &str, p: f64, t: f64, gamma: f64) -> Scene {
    Preset::resolve(preset)
        .unwrap()
        .scene()
        .unwrap()
        .with_pressure(p)
        .unwrap()
        .with_thickness_qr(t)
        .unwrap()
        .with_surface_energy_j_m2(gamma)
        .unwrap()
}

fn point(s: &Scene) -> PointReport {
    let opts = Options {
        adhesion_error_estimate: false,
        ..Options::default()
    };
    let r = report::point(s, &opts).unwrap_or_else(|e| panic!("gamma {:e}: {e}", s.surface_energy_j_m2()));
    assert!(
        r.converged,
        "gamma {:e}: {:?}",
        s.surface_energy_j_m2(),
        r.converged_note
    );
    assert!(r.stats.a_r.is_finite() && r.stats.a_r > 0.0 && r.stats.a_r < 1.0);
    r
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn weak_adhesion_tends_to_the_adhesionless_answer() {
    for preset in ["system-1", "system-2"] {
        for (p, t) in [(1e-3, f64::INFINITY), (1e-2, 0.3)] {
            let dry = point(&scene(preset, p, t, 0.0));
            let dry_gap = dry.mean_gap_rel.expect("adhesionless mean gap");
            let mut prev: Option<(f64, f64)> = None;
            for g in GAMMAS {
                let r = point(&scene(preset, p, t, g));
                let gap = r
                    .mean_gap_rel
                    .unwrap_or_else(|| panic!("{preset} gamma {g:e}: {:?}", r.mean_gap_note));
                assert!(gap.is_finite() && gap > 0.0);
                let (da, dg) = (rel(r.stats.a_r, dry.stats.a_r), rel(gap, dry_gap));
                if g <= 1e-9 {
                    assert!(
                        da < WEAK_ADHESION_REL && dg < WEAK_ADHESION_REL,
                        "{preset} p* {p} t {t} gamma {g:e}: a_r {} against {} ({da:.1e}), gap {gap} against \
                         {dry_gap} ({dg:.1e})",
                        r.stats.a_r,
                        dry.stats.a_r
                    );
                }
                // continuity: adhesion only adds contact and pulls the surfaces together, by
                // at most a_r·σ_a*/p* (σ_a* ∝ √γ_s) beyond the march's own error
                if let Some((a0, g0)) = prev {
                    let allowed = WEAK_ADHESION_REL + 2.0 * r.sigma_a / p;
                    assert!(
                        rel(r.stats.a_r, a0) < allowed && rel(gap, g0) < allowed,
                        "{preset} p* {p} t {t} gamma {g:e}: a_r {} after {a0}, gap {gap} after {g0} (allowed \
                         {allowed:.1e})",
                        r.stats.a_r
                    );
                }
                prev = Some((r.stats.a_r, gap));
            }
        }
    }
}
