//! The brute-force points the library stores for the scene's case, drawn beside the preset's
//! `[[reference]]` points on the charts of a_r, ū/h_rms and σ̄_c*: asperity's own GFMD
//! bandwidth set ([`asperity::fit::reference_set::bandwidth_set`], docs/reference-set.md),
//! system II's adhesive cases loaded over p* = 10⁻³…10⁻² on 512² and 1024² maps.
//!
//! A scene has stored points when it is one of those cases: the built-in system II (its
//! spectrum, E* and adhesion range unchanged), a stored t·q_r and γ_s a stored multiple of the
//! preset's. Of the grids stored for the case the widest is shown (λ_r/λ_s = 64 at 1024², the
//! nearest to the full system's 128; on these slabs GFMD's a_r moves by at most 25 % between
//! λ_r/λ_s = 16 and 128, docs/physics.md §3.6), its loading points as stored (mean over its seeds), named
//! by the grid so a reader knows the bandwidth the brute force ran at. The main set's 256²
//! maps (λ_r/λ_s = 16) are not drawn over the full system's curves: how far its GFMD values
//! would move at the full bandwidth was not measured for every case.

use asperity::fit::reference_set::{bandwidth_set, ReferencePoint as SetPoint};
use asperity::input::preset::{Preset, ReferencePoint, BUILTIN};
use asperity::input::scene::Scene;
use std::sync::OnceLock;

/// Relative tolerance of matching a scene's t·q_r and γ_s factor to a stored case's.
const MATCH: f64 = 1e-9;

/// The built-in presets' scenes, parsed once: (name, system number, scene).
fn builtins() -> &'static [(&'static str, u8, Scene)] {
    static SCENES: OnceLock<Vec<(&'static str, u8, Scene)>> = OnceLock::new();
    SCENES.get_or_init(|| {
        BUILTIN
            .iter()
            .filter_map(|(name, text)| {
                let system = name.strip_prefix("system-")?.parse().ok()?;
                let scene = Preset::parse(text, name).ok()?.scene().ok()?;
                Some((*name, system, scene))
            })
            .collect()
    })
}

/// Equal within [`MATCH`] (∞ only equals ∞).
fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_finite() && b.is_finite() && (a - b).abs() <= MATCH * a.abs().max(b.abs()))
}

/// The stored system and γ_s factor of `scene` when it is a built-in system of \[S\].
fn case_of(preset: &Preset, scene: &Scene) -> Option<(u8, f64)> {
    let (_, system, own) = builtins().iter().find(|(n, _, _)| *n == preset.name)?;
    let kept = scene.spectrum() == own.spectrum()
        && scene.contact_modulus_pa() == own.contact_modulus_pa()
        && scene.range_m() == own.range_m();
    let gamma = own.surface_energy_j_m2();
    (kept && gamma > 0.0).then(|| (*system, scene.surface_energy_j_m2() / gamma))
}

/// The stored loading points of the scene's case on the widest stored grid, as reference
/// points of a_r, ū/h_rms and σ̄_c* (empty where the scene is not a stored case).
pub fn stored_gfmd(preset: &Preset, scene: &Scene) -> Vec<ReferencePoint> {
    let Some((system, factor)) = case_of(preset, scene) else {
        return Vec::new();
    };
    let t = scene.thickness_qr();
    let of_case = |r: &&SetPoint| {
        r.system == system
            && same(r.thickness_qr, t)
            && same(r.gamma_factor, factor)
            && r.branch.name() == "loading"
            && r.p > 0.0
            && r.a_r.0.is_finite()
    };
    let points: Vec<&SetPoint> = bandwidth_set().iter().filter(of_case).collect();
    let Some(grid) = points.iter().map(|r| r.grid).max() else {
        return Vec::new();
    };
    let source = format!("GFMD ({grid}^2)");
    let mut out = Vec::new();
    for r in points.into_iter().filter(|r| r.grid == grid) {
        for (quantity, (value, _)) in [
            ("a_r", r.a_r),
            ("mean_gap_rel", r.mean_gap_rel),
            ("mean_contact_stress", r.mean_contact_stress),
        ] {
            if value.is_finite() {
                out.push(ReferencePoint {
                    source: source.clone(),
                    quantity: quantity.into(),
                    pressure: r.p,
                    thickness_qr: t.is_finite().then_some(t),
                    gamma: Some(scene.surface_energy_j_m2()),
                    model: None,
                    value,
                });
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(preset: &Preset, t: f64, factor: f64) -> Scene {
        let mut s = preset.scene().unwrap();
        s.set_thickness_qr(t).unwrap();
        s.set_surface_energy_j_m2(factor * preset.adhesion.surface_energy_j_m2)
            .unwrap();
        s
    }

    #[test]
    fn a_stored_case_shows_its_widest_grid_as_stored() {
        let p = Preset::resolve("system-2").unwrap();
        let pts = stored_gfmd(&p, &scene(&p, 0.15, 1.0));
        // the bandwidth set holds this case at 512² and 1024²: the 1024² loads are shown
        let a_r: Vec<&ReferencePoint> = pts.iter().filter(|r| r.quantity == "a_r").collect();
        assert!(!a_r.is_empty());
        assert!(pts.iter().all(|r| r.source == "GFMD (1024^2)"), "{pts:?}");
        for r in &a_r {
            let stored = bandwidth_set()
                .iter()
                .find(|s| {
                    s.grid == 1024
                        && s.thickness_qr == 0.15
                        && s.gamma_factor == 1.0
                        && s.branch.name() == "loading"
                        && s.p == r.pressure
                })
                .unwrap();
            assert_eq!(r.value, stored.a_r.0);
            assert_eq!(r.thickness_qr, Some(0.15));
        }
        // where 2048² is stored too (the half-space at the preset's γ_s), 2048² is shown
        let half_space = stored_gfmd(&p, &scene(&p, f64::INFINITY, 1.0));
        assert!(!half_space.is_empty());
        assert!(half_space.iter().all(|r| r.source == "GFMD (2048^2)"), "{half_space:?}");
    }

    #[test]
    fn other_scenes_have_no_stored_points() {
        let p = Preset::resolve("system-2").unwrap();
        // a thickness, a γ_s or a modulus the set does not hold; no adhesion (only the 256²
        // set holds it); system I (likewise)
        assert!(stored_gfmd(&p, &scene(&p, 0.12, 1.0)).is_empty());
        assert!(stored_gfmd(&p, &scene(&p, 0.15, 0.0)).is_empty());
        let one = Preset::resolve("system-1").unwrap();
        assert!(stored_gfmd(&one, &one.scene().unwrap()).is_empty());
        assert!(stored_gfmd(&p, &scene(&p, 0.15, 0.7)).is_empty());
        let mut s = scene(&p, 0.15, 1.0);
        s.set_contact_modulus_pa(2.0 * s.contact_modulus_pa()).unwrap();
        assert!(stored_gfmd(&p, &s).is_empty());
        // a preset that is not a built-in system of [S]
        let mut other = p.clone();
        other.name = "my-slab".into();
        assert!(stored_gfmd(&other, &scene(&p, 0.15, 1.0)).is_empty());
    }
}
