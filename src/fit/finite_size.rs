//! GFMD's own finite-size error at small loads, as measured by the finite-size study
//! (docs/reference-set.md, "Small loads and finite size"): the reference set's maps have
//! L/λ_r = 2; the study repeats loading sweeps of some cases on maps with L/λ_r = 4 and 8 at
//! the same λ_r/λ_s = 16 and λ_s/Δa = 8 (γ̃_glo and the Tabor parameter kept), so that the
//! difference is the system size alone.
//!
//! `data/reference/finite-size.csv` holds, per case and load, GFMD's a_r (mean ± standard
//! error over seeds) at each L/λ_r and `log_error` = |ln(a_r(L/λ_r = 2) / a_r(largest L))|:
//! how far the set's value is from the largest system measured. The trust read-out adds it to
//! its band where a measured case lies within reach of the scene ([`log_error`]).

use super::table::{number, rows};
use super::trust_band::{case_distance, Place, CASE_REACH, LOAD_REACH};
use std::sync::OnceLock;

const CSV: &str = include_str!("../../data/reference/finite-size.csv");

/// One load of one case of the study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FiniteSizePoint {
    /// t·q_r (∞: a half-space).
    pub thickness_qr: f64,
    /// γ_s over the preset's.
    pub gamma_factor: f64,
    /// γ̃_glo of the case.
    pub gamma_glo: f64,
    /// p*.
    pub p: f64,
    /// GFMD's a_r (mean, standard error) at L/λ_r = 2, 4, 8 (NaN where not run).
    pub a_r: [(f64, f64); 3],
    /// |ln(a_r(2) / a_r(largest L))|.
    pub log_error: f64,
}

/// The study's points (system II), read once.
pub fn points() -> &'static [FiniteSizePoint] {
    static SET: OnceLock<Vec<FiniteSizePoint>> = OnceLock::new();
    SET.get_or_init(|| parse(CSV))
}

fn parse(text: &str) -> Vec<FiniteSizePoint> {
    rows(text)
        .iter()
        .map(|row| {
            let pair = |l: u8| (number(row, &format!("a_r_L{l}")), number(row, &format!("a_r_L{l}_err")));
            FiniteSizePoint {
                thickness_qr: number(row, "thickness_qr"),
                gamma_factor: number(row, "gamma_factor"),
                gamma_glo: number(row, "gamma_glo"),
                p: number(row, "p"),
                a_r: [pair(2), pair(4), pair(8)],
                log_error: number(row, "log_error"),
            }
        })
        .filter(|p| p.p > 0.0 && p.log_error.is_finite())
        .collect()
}

/// The finite-size error at `place`: the nearest measured case within reach, interpolated
/// linearly in log p* between its loads (its end value within [`LOAD_REACH`] decades beyond
/// them); None where no case was measured near the scene.
pub fn log_error(place: Place) -> Option<f64> {
    let distance = |f: &FiniteSizePoint| case_distance(place, f.thickness_qr, f.gamma_glo);
    let nearest = points()
        .iter()
        .filter(|f| distance(f) <= CASE_REACH)
        .min_by(|a, b| distance(a).total_cmp(&distance(b)))?;
    let mut rows: Vec<&FiniteSizePoint> = points()
        .iter()
        .filter(|f| f.thickness_qr == nearest.thickness_qr && f.gamma_factor == nearest.gamma_factor)
        .collect();
    rows.sort_by(|a, b| a.p.total_cmp(&b.p));
    let (first, last) = (rows.first()?, rows.last()?);
    let p = place.p;
    if p <= first.p {
        return ((first.p / p).log10() <= LOAD_REACH).then_some(first.log_error);
    }
    if p >= last.p {
        return ((p / last.p).log10() <= LOAD_REACH).then_some(last.log_error);
    }
    let i = rows.iter().position(|r| r.p >= p)?;
    let (a, b) = (rows[i - 1], rows[i]);
    let w = (p / a.p).log10() / (b.p / a.p).log10();
    Some((1.0 - w) * a.log_error + w * b.log_error)
}
