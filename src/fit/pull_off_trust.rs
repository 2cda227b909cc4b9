//! How far to trust a pull-off: the theory's and the DMT routes' pull-offs measured against
//! GFMD's at the stored cases nearest a scene.
//!
//! The table (`data/reference/pull-off-theory-256.csv`, written by
//! `examples/theory_pull_off.rs`) holds system II's 21 adhesive cases of the 256² reference set
//! (t·q_r ∞…0.1, γ_s × ½, 1, 2): GFMD's pull-off p\*_c (mean over its maps ± standard error),
//! the theory's along GFMD's tensile path for models 3, 4 and 5 (physics.md §6.2) and the two
//! DMT routes' (BAM and the gap distribution's, §6.3), each computed on the maps GFMD ran and
//! averaged. None of them was fitted to these pull-offs.
//!
//! A pull-off does not depend on the load, so a case is placed by (t·q_r, γ̃_glo) alone, in
//! the coordinates of [`super::trust_band`], and read within its
//! [`CASE_REACH`], the [`NEAREST`] nearest first. At each
//! case the read-out gives r = p\*_c(x)/p\*_c(GFMD) for the theory x (the scene's model; model 4's
//! column for models 1 and 2, labelled) and each route (0 where x holds no tension), and
//! whether GFMD's pull-off lies between the theory's and the larger route's. With fewer than
//! [`MIN_CASES`] cases within reach, or without adhesion, nothing is claimed: the read-out says
//! so. It states the measured ratios; it does not turn them into an estimate.

use super::table::{number, rows};
use super::trust_band::{case_distance, Place, CASE_REACH, MIN_CASES};
use serde::Serialize;
use std::sync::OnceLock;

/// Cases the read-out takes at most.
pub const NEAREST: usize = 4;

const TABLE_CSV: &str = include_str!("../../data/reference/pull-off-theory-256.csv");

/// One stored case of the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PullOffCase {
    /// t·q_r (∞: half-space).
    pub thickness_qr: f64,
    /// γ_s over the preset's.
    pub gamma_factor: f64,
    /// γ̃_glo of the reduced system GFMD ran.
    pub gamma_glo: f64,
    /// Maps GFMD averaged.
    pub seeds: usize,
    /// GFMD's pull-off p\* (≤ 0) and its standard error.
    pub gfmd: (f64, f64),
    /// The theory's pull-off for models 3, 4 and 5.
    pub theory: [f64; 3],
    /// The bound no contact branch of the theory passes (§6.2).
    pub tension_bound: f64,
    /// Ciavarella's bearing-area model's pull-off.
    pub bam: f64,
    /// The gap distribution's DMT pull-off (Persson & Scaraggi).
    pub gap_dmt: f64,
}

/// The stored table, parsed once.
pub fn table() -> &'static [PullOffCase] {
    static TABLE: OnceLock<Vec<PullOffCase>> = OnceLock::new();
    TABLE.get_or_init(|| parse(TABLE_CSV))
}

fn parse(text: &str) -> Vec<PullOffCase> {
    rows(text)
        .iter()
        .map(|row| {
            let num = |k: &str| number(row, k);
            PullOffCase {
                thickness_qr: num("thickness_qr"),
                gamma_factor: num("gamma_factor"),
                gamma_glo: num("gamma_glo"),
                seeds: num("seeds") as usize,
                gfmd: (num("gfmd"), num("gfmd_err")),
                theory: [num("model3"), num("model4"), num("model5")],
                tension_bound: num("tension_bound"),
                bam: num("bam"),
                gap_dmt: num("gap_dmt"),
            }
        })
        .collect()
}

/// One measured case near the scene, with each pull-off over GFMD's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CaseRatio {
    /// t·q_r of the case (null: a half-space).
    pub thickness_qr: Option<f64>,
    /// γ_s of the case over the preset's.
    pub gamma_factor: f64,
    /// γ̃_glo of the case.
    pub gamma_glo: f64,
    /// GFMD's pull-off p\* there (≤ 0).
    pub gfmd: f64,
    /// Its standard error over the maps.
    pub gfmd_err: f64,
    /// The theory's pull-off over GFMD's (the measured model's).
    pub theory_ratio: f64,
    /// BAM's over GFMD's.
    pub bam_ratio: f64,
    /// The gap distribution's over GFMD's.
    pub gap_dmt_ratio: f64,
    /// Distance from the scene (units of [`super::trust_band`]).
    pub distance: f64,
}

/// The pull-off read-out of a scene (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PullOffTrust {
    /// Whether enough measured cases lie near the scene.
    pub known: bool,
    /// The model whose theory column is read (3, 4 or 5).
    pub measured_model: u8,
    /// The cases, nearest first.
    pub cases: Vec<CaseRatio>,
    /// Smallest and largest theory/GFMD over the cases (null where unknown).
    pub theory_ratio: Option<[f64; 2]>,
    /// Smallest and largest BAM/GFMD (null where unknown).
    pub bam_ratio: Option<[f64; 2]>,
    /// Smallest and largest gap-DMT/GFMD (null where unknown).
    pub gap_dmt_ratio: Option<[f64; 2]>,
    /// Whether GFMD's pull-off lay between the theory's and the larger route's at every case
    /// (null where unknown).
    pub bracketed: Option<bool>,
    /// One line for a table.
    pub summary: String,
}

/// The column of the table read for `model` (models 1 and 2 read model 4's, the set's own).
fn column(model: Option<u8>) -> (usize, u8) {
    match model {
        Some(3) => (0, 3),
        Some(5) => (2, 5),
        _ => (1, 4),
    }
}

fn range(v: impl Iterator<Item = f64>) -> Option<[f64; 2]> {
    v.fold(None, |acc: Option<[f64; 2]>, x| {
        Some(acc.map_or([x, x], |[lo, hi]| [lo.min(x), hi.max(x)]))
    })
}

/// The pull-off read-out at (t·q_r, γ̃_glo) for `model` (`adhesive` false: nothing to read).
pub fn assess(thickness_qr: f64, gamma_glo: f64, model: Option<u8>, adhesive: bool) -> PullOffTrust {
    assess_on(table(), thickness_qr, gamma_glo, model, adhesive)
}

/// [`assess`] on the cases `cases` (a test leaves one out to measure the read-out's coverage).
pub fn assess_on(
    cases: &[PullOffCase],
    thickness_qr: f64,
    gamma_glo: f64,
    model: Option<u8>,
    adhesive: bool,
) -> PullOffTrust {
    let (col, measured_model) = column(model);
    let place = Place {
        p: 1.0,
        gamma_glo,
        thickness_qr,
    };
    let mut near: Vec<CaseRatio> = if adhesive {
        cases
            .iter()
            .filter(|c| c.gfmd.0 < 0.0)
            .map(|c| {
                // both ≤ 0: the ratio is ≥ 0 (and 0, not −0, where x holds no tension)
                let r = |x: f64| (x / c.gfmd.0).abs();
                CaseRatio {
                    thickness_qr: c.thickness_qr.is_finite().then_some(c.thickness_qr),
                    gamma_factor: c.gamma_factor,
                    gamma_glo: c.gamma_glo,
                    gfmd: c.gfmd.0,
                    gfmd_err: c.gfmd.1,
                    theory_ratio: r(c.theory[col]),
                    bam_ratio: r(c.bam),
                    gap_dmt_ratio: r(c.gap_dmt),
                    distance: case_distance(place, c.thickness_qr, c.gamma_glo),
                }
            })
            .filter(|c| c.distance <= CASE_REACH)
            .collect()
    } else {
        Vec::new()
    };
    near.sort_by(|a, b| a.distance.total_cmp(&b.distance));
    near.truncate(NEAREST);
    let known = near.len() >= MIN_CASES;
    let known_range = |f: fn(&CaseRatio) -> f64| if known { range(near.iter().map(f)) } else { None };
    let theory_ratio = known_range(|c| c.theory_ratio);
    let bam_ratio = known_range(|c| c.bam_ratio);
    let gap_dmt_ratio = known_range(|c| c.gap_dmt_ratio);
    let bracketed = known.then(|| {
        near.iter()
            .all(|c| c.theory_ratio <= 1.0 && c.bam_ratio.max(c.gap_dmt_ratio) >= 1.0)
    });
    let summary = summary(
        adhesive,
        measured_model,
        &near,
        [theory_ratio, bam_ratio, gap_dmt_ratio],
        bracketed,
    );
    PullOffTrust {
        known,
        measured_model,
        cases: near,
        theory_ratio,
        bam_ratio,
        gap_dmt_ratio,
        bracketed,
        summary,
    }
}

fn summary(
    adhesive: bool,
    model: u8,
    near: &[CaseRatio],
    ratios: [Option<[f64; 2]>; 3],
    bracketed: Option<bool>,
) -> String {
    let [theory, bam, gap] = ratios;
    if !adhesive {
        return "without adhesion no tension is held: pull-off 0, as GFMD's at every adhesionless case".into();
    }
    let (Some(t), Some(b), Some(g)) = (theory, bam, gap) else {
        return format!(
            "no error known: {} measured pull-off case(s) within reach of this thickness and γ̃_glo (at least {MIN_CASES} needed)",
            near.len()
        );
    };
    let pct = |r: [f64; 2]| format!("{}–{} %", sig(100.0 * r[0]), sig(100.0 * r[1]));
    let times = |r: [f64; 2]| format!("{}–{}×", sig(r[0]), sig(r[1]));
    let between = if bracketed == Some(true) {
        "GFMD's lay between the theory's and the larger route's at each"
    } else {
        "GFMD's did not always lie between them"
    };
    format!(
        "model {model}'s pull-off was {} of GFMD's at the {} nearest measured cases (a lower bound, not an estimate); BAM's {} and gap-DMT's {} of it; {between}",
        pct(t),
        near.len(),
        times(b),
        times(g),
    )
}

/// `x` with two significant digits (no exponent for the ratios read here).
fn sig(x: f64) -> String {
    if x >= 10.0 || x == 0.0 {
        format!("{x:.0}")
    } else if x >= 1.0 {
        format!("{x:.1}")
    } else {
        format!("{x:.2}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_holds_the_sets_adhesive_cases_with_gfmds_pull_offs() {
        let t = table();
        assert_eq!(t.len(), 21);
        for c in t {
            let g =
                super::super::reference_set::pull_off_of(2, c.thickness_qr, c.gamma_factor).expect("a case of the set");
            assert_eq!(g.pressure.0, c.gfmd.0, "{c:?}");
            assert!(
                c.theory.iter().all(|&x| x <= 0.0) && c.bam <= 0.0 && c.gap_dmt <= 0.0,
                "{c:?}"
            );
        }
    }

    #[test]
    fn far_or_adhesionless_scenes_claim_nothing() {
        let dry = assess(0.3, 0.0, Some(5), false);
        assert!(!dry.known && dry.cases.is_empty() && dry.summary.contains("no tension"));
        // γ̃_glo 100 lies beyond every case
        let far = assess(0.3, 100.0, Some(5), true);
        assert!(!far.known && far.theory_ratio.is_none() && far.summary.starts_with("no error known"));
    }

    #[test]
    fn a_case_of_the_set_reads_its_own_ratios_first() {
        let c = table()
            .iter()
            .find(|c| c.thickness_qr == 0.3 && c.gamma_factor == 1.0)
            .unwrap();
        let t = assess(0.3, c.gamma_glo, Some(4), true);
        assert!(t.known);
        assert_eq!(t.cases[0].distance, 0.0);
        assert_eq!(t.cases[0].theory_ratio, c.theory[1] / c.gfmd.0);
        let [lo, hi] = t.theory_ratio.unwrap();
        assert!(lo <= t.cases[0].theory_ratio && t.cases[0].theory_ratio <= hi);
    }
}
