//! asperity's own GFMD reference set (docs/reference-set.md), built into the library: load
//! cycles of system II over t·q_r ∈ {∞, 1, 0.5, 0.3, 0.2, 0.15, 0.1} and γ_s ∈ {0, ½, 1, 2} ×
//! 0.157 J/m², and of system I at its adhesion, on 256² reduced maps (γ̃_glo and the Tabor
//! parameter of the full systems kept), mean ± standard error over seeds, with the theory
//! (the preset's model: 4 for system II, 3 for system I) on the same maps' spectra beside
//! each point.
//!
//! The data are `data/reference/reference-set-256.csv` (one row per case, branch and load) and
//! `data/reference/pull-off-256.csv` (per case: γ̃_glo, the pull-off), read once.
//!
//! Model 5's theory columns (`data/reference/theory-model5-256.csv`, the same points, model 5 on
//! the same maps) are attached to system II's points, so that the trust read-out can give
//! model 5's own measured error.
//!
//! Beside it, the *bandwidth set* ([`bandwidth_set`], `data/reference/bandwidth-set.csv`): the
//! adhesive system II cases' loading sweeps at p* = 10⁻³…10⁻² on wider grids (512², 1024²:
//! λ_r/λ_s = 32, 64), the data that tell how the theory's error moves with the bandwidth. Its
//! model 5 columns (`data/reference/theory-model5-full.csv`) are model 5 on the *full* system II
//! (λ_r/λ_s = 128) at the same loads, a_r only: what the trust read-out gives a model 5 scene of
//! the full bandwidth.

use super::table::{number as num, rows, Row};
use crate::theory::cycle::PathBranch;
use std::sync::OnceLock;

const SET_CSV: &str = include_str!("../../data/reference/reference-set-256.csv");
const CASES_CSV: &str = include_str!("../../data/reference/pull-off-256.csv");
const BANDWIDTH_CSV: &str = include_str!("../../data/reference/bandwidth-set.csv");
const MODEL5_CSV: &str = include_str!("../../data/reference/theory-model5-256.csv");
const MODEL5_FULL_CSV: &str = include_str!("../../data/reference/theory-model5-full.csv");
const SMALL_CSV: &str = include_str!("../../data/reference/small-load-256.csv");
const SMALL_CASES_CSV: &str = include_str!("../../data/reference/pull-off-small-256.csv");
const SMALL_MODELS_CSV: &str = include_str!("../../data/reference/theory-models-small-256.csv");
/// Models whose theory columns the small-load set holds (1–5).
pub const MODELS: usize = 5;
/// Grid side of the stored set.
pub const SET_GRID: usize = 256;

/// One stored load of one case (mean over the seeds; `…_err` the standard error, NaN where the
/// set has one seed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferencePoint {
    /// 1 (the contact-mechanics challenge) or 2 (the adhesive slab system).
    pub system: u8,
    /// Grid side N of the GFMD maps (λ_r/λ_s = N/16 for the set's reduction).
    pub grid: usize,
    /// t·q_r (∞ for a half-space).
    pub thickness_qr: f64,
    /// γ_s as a multiple of the preset's.
    pub gamma_factor: f64,
    /// γ̃_glo of the case [S-24].
    pub gamma_glo: f64,
    /// The path's direction at this load.
    pub branch: PathBranch,
    /// p* (negative: tension).
    pub p: f64,
    /// Maps averaged.
    pub seeds: usize,
    /// GFMD's a_r and its standard error.
    pub a_r: (f64, f64),
    /// GFMD's ū/h_rms and its standard error.
    pub mean_gap_rel: (f64, f64),
    /// GFMD's σ̄_c* and its standard error.
    pub mean_contact_stress: (f64, f64),
    /// The model of the theory columns: the preset's (4 for system II, 3 for system I).
    pub theory_model: u8,
    /// The theory's a_r on the same maps (the branch the path is on); NaN under tension.
    pub theory_a_r: f64,
    /// The theory's ū/h_rms on the same maps; NaN where it has none.
    pub theory_mean_gap_rel: f64,
    /// Model 5's a_r on the same maps and branch (mean over seeds; NaN where not computed).
    pub theory5_a_r: f64,
    /// Model 5's ū/h_rms there (NaN where not computed).
    pub theory5_mean_gap_rel: f64,
    /// The theory's (a_r, ū/h_rms) on the same maps for models 1–5 (index model − 1), on the
    /// branch the path is on; NaN where not computed (the small-load set holds all five).
    pub theory_models: [(f64, f64); MODELS],
}

fn system_of(row: &Row) -> u8 {
    row.get("system")
        .and_then(|s| s.strip_prefix("system-"))
        .and_then(|s| s.parse().ok())
        .unwrap_or(0)
}

/// One set's rows; γ̃_glo from the row's own `gamma_glo` column, else from `cases`; model 5's
/// columns from `model5` where it has the point.
fn parse(set_csv: &str, cases_csv: &str, model5: &str, models_csv: &str) -> Vec<ReferencePoint> {
    let cases = rows(cases_csv);
    let five = rows(model5);
    let models = rows(models_csv);
    let models_at = |sys: u8, t: f64, f: f64, branch: &str, p: f64| {
        let mut out = [(f64::NAN, f64::NAN); MODELS];
        for c in models.iter().filter(|c| {
            system_of(c) == sys
                && num(c, "thickness_qr") == t
                && num(c, "gamma_factor") == f
                && c.get("branch").map(String::as_str) == Some(branch)
                && (num(c, "p") / p - 1.0).abs() < 1e-6
        }) {
            let m = num(c, "model");
            if (1.0..=MODELS as f64).contains(&m) {
                out[m as usize - 1] = (num(c, "theory_a_r"), num(c, "theory_mean_gap_rel"));
            }
        }
        out
    };
    let five_at = |sys: u8, t: f64, f: f64, branch: &str, p: f64| {
        five.iter()
            .find(|c| {
                system_of(c) == sys
                    && num(c, "thickness_qr") == t
                    && num(c, "gamma_factor") == f
                    && c.get("branch").map(String::as_str) == Some(branch)
                    && (num(c, "p") / p - 1.0).abs() < 1e-6
            })
            .map_or((f64::NAN, f64::NAN), |c| {
                (num(c, "theory_a_r"), num(c, "theory_mean_gap_rel"))
            })
    };
    let glo = |sys: u8, t: f64, f: f64| {
        cases
            .iter()
            .find(|c| system_of(c) == sys && num(c, "thickness_qr") == t && num(c, "gamma_factor") == f)
            .map_or(f64::NAN, |c| num(c, "gamma_glo"))
    };
    rows(set_csv)
        .iter()
        .map(|r| {
            let (system, t, f) = (system_of(r), num(r, "thickness_qr"), num(r, "gamma_factor"));
            let pair = |k: &str| (num(r, k), num(r, &format!("{k}_err")));
            let grid = num(r, "grid");
            let own_glo = num(r, "gamma_glo");
            let branch = r.get("branch").map_or("", String::as_str);
            let five = five_at(system, t, f, branch, num(r, "p"));
            let theory_models = models_at(system, t, f, branch, num(r, "p"));
            ReferencePoint {
                system,
                grid: if grid.is_finite() { grid as usize } else { SET_GRID },
                thickness_qr: t,
                gamma_factor: f,
                gamma_glo: if own_glo.is_finite() {
                    own_glo
                } else {
                    glo(system, t, f)
                },
                branch: if branch == "unloading" {
                    PathBranch::Unloading
                } else {
                    PathBranch::Loading
                },
                p: num(r, "p"),
                seeds: num(r, "seeds") as usize,
                a_r: pair("a_r"),
                mean_gap_rel: pair("mean_gap_rel"),
                mean_contact_stress: pair("mean_contact_stress"),
                theory_model: if system == 1 { 3 } else { 4 },
                theory_a_r: num(r, "theory_a_r"),
                theory_mean_gap_rel: num(r, "theory_mean_gap_rel"),
                theory5_a_r: five.0,
                theory5_mean_gap_rel: five.1,
                theory_models,
            }
        })
        .collect()
}

/// The stored set (256²), parsed once.
pub fn reference_set() -> &'static [ReferencePoint] {
    static SET: OnceLock<Vec<ReferencePoint>> = OnceLock::new();
    SET.get_or_init(|| parse(SET_CSV, CASES_CSV, MODEL5_CSV, ""))
}

/// The small-load set (256², L/λ_r = 2, loads 10⁻⁵…10⁻², docs/reference-set.md "Small loads
/// and finite size"), with the theory columns of models 1–5 on the same maps, parsed once.
/// Its cases' pull-offs are [`small_load_pull_offs`].
pub fn small_load_set() -> &'static [ReferencePoint] {
    static SET: OnceLock<Vec<ReferencePoint>> = OnceLock::new();
    SET.get_or_init(|| parse(SMALL_CSV, SMALL_CASES_CSV, "", SMALL_MODELS_CSV))
}

/// The points the trust read-out and the held-out checks use: the small-load set, and the
/// 256² set's cases that the small-load set does not hold.
pub fn combined_set() -> &'static [ReferencePoint] {
    static SET: OnceLock<Vec<ReferencePoint>> = OnceLock::new();
    SET.get_or_init(|| {
        small_load_set()
            .iter()
            .copied()
            .chain(
                reference_set()
                    .iter()
                    .copied()
                    .filter(|r| !small_load_holds(r.system, r.thickness_qr, r.gamma_factor)),
            )
            .collect()
    })
}

/// One case's pull-off in the stored set (`pull-off-256.csv`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferencePullOff {
    /// 1 or 2.
    pub system: u8,
    /// t·q_r (∞: half-space).
    pub thickness_qr: f64,
    /// γ_s as a multiple of the preset's.
    pub gamma_factor: f64,
    /// γ̃_glo of the reduced system.
    pub gamma_glo: f64,
    /// The pull-off p* (mean over seeds, ≤ 0) and its standard error.
    pub pressure: (f64, f64),
    /// Maps averaged.
    pub seeds: usize,
}

/// The stored set's pull-offs, one per case, parsed once.
pub fn pull_offs() -> &'static [ReferencePullOff] {
    static SET: OnceLock<Vec<ReferencePullOff>> = OnceLock::new();
    SET.get_or_init(|| parse_pull_offs(CASES_CSV))
}

/// The stored set's pull-off of the case (system, t·q_r, γ_s factor), if it holds the case.
pub fn pull_off_of(system: u8, thickness_qr: f64, gamma_factor: f64) -> Option<&'static ReferencePullOff> {
    pull_offs()
        .iter()
        .find(|r| r.system == system && r.thickness_qr == thickness_qr && r.gamma_factor == gamma_factor)
}

/// Whether the small-load set holds the case (system, t·q_r, γ_s factor): where it does, it
/// stands for the 256² set's case.
pub fn small_load_holds(system: u8, thickness_qr: f64, gamma_factor: f64) -> bool {
    small_load_set()
        .iter()
        .any(|s| s.system == system && s.thickness_qr == thickness_qr && s.gamma_factor == gamma_factor)
}

/// The small-load set's cases' pull-offs (`pull-off-small-256.csv`: the cycles from p* = 10⁻⁵).
pub fn small_load_pull_offs() -> &'static [ReferencePullOff] {
    static SET: OnceLock<Vec<ReferencePullOff>> = OnceLock::new();
    SET.get_or_init(|| parse_pull_offs(SMALL_CASES_CSV))
}

fn parse_pull_offs(text: &str) -> Vec<ReferencePullOff> {
    rows(text)
        .iter()
        .map(|r| ReferencePullOff {
            system: system_of(r),
            thickness_qr: num(r, "thickness_qr"),
            gamma_factor: num(r, "gamma_factor"),
            gamma_glo: num(r, "gamma_glo"),
            pressure: (num(r, "pull_off_pressure"), num(r, "pull_off_pressure_err")),
            seeds: num(r, "seeds") as usize,
        })
        .collect()
}

/// The bandwidth set (system II, adhesive, loading, p* ≥ 10⁻³ on grids wider than 256²), parsed
/// once.
pub fn bandwidth_set() -> &'static [ReferencePoint] {
    static SET: OnceLock<Vec<ReferencePoint>> = OnceLock::new();
    SET.get_or_init(|| parse(BANDWIDTH_CSV, "", MODEL5_FULL_CSV, ""))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_sets_parse_with_their_grids() {
        assert!(reference_set()
            .iter()
            .all(|p| p.grid == SET_GRID && p.a_r.0.is_finite()));
        let bw = bandwidth_set();
        assert!(!bw.is_empty());
        for p in bw {
            assert!(p.grid > SET_GRID, "{p:?}");
            assert!(p.gamma_glo > 0.0 && p.a_r.0 > 0.0 && p.a_r.0 <= 1.0, "{p:?}");
            assert_eq!(p.branch, PathBranch::Loading);
            // model 5 on the full system at every load, a_r only
            assert!(p.theory5_a_r > 0.0 && p.theory5_a_r <= 1.0, "{p:?}");
            assert!(p.theory5_mean_gap_rel.is_nan(), "{p:?}");
        }
        // model 5's columns: on every system II point with a theory, none elsewhere
        for p in reference_set() {
            let want = p.system == 2 && p.p > 0.0 && p.theory_a_r.is_finite();
            assert_eq!(p.theory5_a_r.is_finite(), want, "{p:?}");
        }
        let po = pull_offs();
        assert_eq!(po.len(), 29);
        for c in po {
            assert!(c.pressure.0 <= 0.0 && c.pressure.1 >= 0.0 && c.seeds == 3, "{c:?}");
            assert_eq!(c.pressure.0 == 0.0, c.gamma_factor == 0.0, "{c:?}");
        }
    }
}
