//! Reference data for gauging: the closed form [S-18, S-19], CSV files of a_r, σ̄_c*, ū/h_rms
//! against p*, and Pr(σ*) histograms.
//!
//! Reference CSV (one header line, `#` comments and blank lines skipped; column order free;
//! read by the `csv` crate, so a cell may be quoted as RFC 4180 says):
//!
//! ```text
//! p,a_r,a_r_err,mean_contact_stress,mean_contact_stress_err,mean_gap_rel,mean_gap_rel_err
//! ```
//!
//! `p` (p* = p/(E*ḡ)) and at least one observable column are required; an empty cell means
//! "not measured at this load". The other columns of `gfmd --format csv`
//! ([`GFMD_CSV_EXTRA_COLUMNS`]) are read past, so its output is a reference as written: rows
//! with `converged` false and a cycle's rows whose `branch` is not `loading` are skipped. Pr CSV: `p,sigma,density` (σ* reduced by E*ḡ, ∫density dσ* =
//! a_r), one row per bin, histograms grouped by p*. A bad cell is reported as one line naming
//! the file, the line, the column, the value and what is allowed.

use super::table::{records, Record};
use crate::error::{Error, Field, Result};
use crate::theory::closed_form::eq18_area;
use serde::Serialize;

/// A quantity the theory predicts and a reference may give.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Observable {
    /// Relative contact area a_r.
    Area,
    /// Mean contact stress σ̄_c* = p*/a_r (reduced by E*ḡ).
    MeanContactStress,
    /// Mean gap ū/h_rms.
    MeanGapRel,
    /// A bin of Pr(σ*).
    Pr,
}

impl Observable {
    /// The column name (and JSON key).
    pub fn key(self) -> &'static str {
        match self {
            Observable::Area => "a_r",
            Observable::MeanContactStress => "mean_contact_stress",
            Observable::MeanGapRel => "mean_gap_rel",
            Observable::Pr => "pr",
        }
    }

    /// Every observable, in [`Observable`] order.
    pub const ALL: [Observable; 4] = [
        Observable::Area,
        Observable::MeanContactStress,
        Observable::MeanGapRel,
        Observable::Pr,
    ];

    /// The observables a reference CSV may hold, in column order.
    pub const COLUMNS: [Observable; 3] = [Observable::Area, Observable::MeanContactStress, Observable::MeanGapRel];

    fn allowed(self) -> &'static str {
        match self {
            Observable::Area => "a number with 0 < a_r <= 1",
            Observable::MeanContactStress => "a finite number > 0",
            Observable::MeanGapRel => "a finite number >= 0",
            Observable::Pr => "a finite number >= 0",
        }
    }

    fn in_range(self, x: f64) -> bool {
        match self {
            Observable::Area => x > 0.0 && x <= 1.0,
            Observable::MeanContactStress => x.is_finite() && x > 0.0,
            Observable::MeanGapRel | Observable::Pr => x.is_finite() && x >= 0.0,
        }
    }
}

/// One reference value.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Observation {
    /// p*.
    pub p: f64,
    /// What is observed.
    pub observable: Observable,
    /// The value (reduced units).
    pub value: f64,
    /// Its standard error, if known.
    pub error: Option<f64>,
    /// σ* of a Pr bin (0 for the other observables).
    pub sigma: f64,
}

/// A reference set: observations, in file order.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reference {
    /// Where it comes from ("eq18", a file name, "gfmd").
    pub name: String,
    /// The values.
    pub points: Vec<Observation>,
}

impl Reference {
    /// The distinct loads, ascending.
    pub fn loads(&self) -> Vec<f64> {
        let mut ps: Vec<f64> = self.points.iter().map(|o| o.p).collect();
        ps.sort_by(f64::total_cmp);
        ps.dedup();
        ps
    }

    /// True when every observation carries a standard error.
    pub fn has_errors(&self) -> bool {
        !self.points.is_empty() && self.points.iter().all(|o| o.error.is_some())
    }

    /// The observables present, in [`Observable`] order.
    pub fn observables(&self) -> Vec<Observable> {
        let mut v: Vec<Observable> = self.points.iter().map(|o| o.observable).collect();
        v.sort();
        v.dedup();
        v
    }
}

/// [S-18] at `points` loads log-spaced from `from` to `to` (the adhesionless half-space).
///
/// # Errors
/// [`Error::Invalid`] for [`Field::SweepFrom`], [`Field::SweepTo`] or [`Field::SweepPoints`].
pub fn eq18(from: f64, to: f64, points: usize) -> Result<Reference> {
    let (lo, hi) = crate::input::scene::PRESSURE_RANGE;
    crate::error::check_in(Field::SweepFrom, from, lo, hi)?;
    crate::error::check_in(Field::SweepTo, to, from, hi)?;
    crate::theory::sweep::check_points(points)?;
    if to == from && points > 1 {
        return Err(Error::invalid(Field::SweepTo, to, "to > from for more than one point"));
    }
    if to > from && points < 2 {
        // one load has no spacing: the log-spaced loads need two ends
        let hi = crate::theory::sweep::SWEEP_POINTS_RANGE.1 as f64;
        return Err(Error::invalid(
            Field::SweepPoints,
            points as f64,
            format!(
                "{} (one point only with to = from)",
                crate::error::Range::whole(2.0, hi).describe("points")
            ),
        ));
    }
    let n = points;
    let points = (0..n)
        .map(|i| {
            let p = (from.ln() + (to / from).ln() * i as f64 / (n - 1) as f64).exp();
            Observation {
                p,
                observable: Observable::Area,
                value: eq18_area(p),
                error: None,
                sigma: 0.0,
            }
        })
        .collect();
    Ok(Reference {
        name: "eq18".into(),
        points,
    })
}

fn cell_error(source: &str, line: usize, column: &str, value: &str, allowed: &str) -> Error {
    Error::invalid_text(
        Field::Other(format!("{source}: line {line}, column {column}")),
        crate::error::fmt_text(value),
        allowed,
    )
}

/// The columns of `gfmd --format csv` (runs, sweeps, cycles) that a reference file may carry
/// besides its own: read past, so that GFMD's CSV is a reference as written (its rows that did
/// not converge, and a cycle's rows off the loading branch, are skipped).
pub const GFMD_CSV_EXTRA_COLUMNS: [&str; 10] = [
    "mean_gap",
    "elastic_energy",
    "converged",
    "contact_stress_variance",
    "iterations",
    "residual",
    "theory_a_r",
    "theory_mean_gap_rel",
    "theory_mean_contact_stress",
    "branch",
];

/// The columns `known` in words, each `_err` column folded into its value's ("a_r (and
/// a_r_err)" would double the list): the allowed part of a header error stays one short line.
fn columns_text(known: &[&str]) -> String {
    let values: Vec<&str> = known.iter().copied().filter(|c| !c.ends_with("_err")).collect();
    if values.len() == known.len() {
        values.join(", ")
    } else {
        format!("{} (each with an optional _err)", values.join(", "))
    }
}

/// The header's line and columns (the first of `recs`), each one of `known` or `extra`
/// (`extra` not named in the message).
fn header<'a>(source: &str, recs: &'a [Record], known: &[&str], extra: &[&str]) -> Result<(usize, Vec<&'a str>)> {
    let Some(Record { line: n, cells, .. }) = recs.first() else {
        return Err(cell_error(
            source,
            1,
            "(header)",
            "(empty file)",
            &format!("a header line naming the columns {}", columns_text(known)),
        ));
    };
    let (n, cols): (usize, Vec<&str>) = (*n, cells.iter().map(String::as_str).collect());
    for (i, c) in cols.iter().enumerate() {
        if !known.contains(c) && !extra.contains(c) {
            return Err(cell_error(
                source,
                n,
                &format!("{}", i + 1),
                c,
                &format!("one of {}", columns_text(known)),
            ));
        }
        if cols[..i].contains(c) {
            return Err(cell_error(source, n, c, c, "each column once"));
        }
    }
    Ok((n, cols))
}

/// The rows after the header: (line, the line as written, cells).
fn data_rows<'a>(recs: &'a [Record]) -> impl Iterator<Item = (usize, &'a str, Vec<&'a str>)> {
    recs.iter()
        .skip(1)
        .map(|r| (r.line, r.text, r.cells.iter().map(String::as_str).collect()))
}

fn number(source: &str, line: usize, column: &str, s: &str, allowed: &str) -> Result<f64> {
    s.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| cell_error(source, line, column, s, allowed))
}

fn load(source: &str, line: usize, s: &str) -> Result<f64> {
    let (lo, hi) = crate::input::scene::PRESSURE_RANGE;
    let allowed = format!("a number with {lo:e} <= p* <= {hi:e}");
    let p = number(source, line, "p", s, &allowed)?;
    if !(lo..=hi).contains(&p) {
        return Err(cell_error(source, line, "p", s, &allowed));
    }
    Ok(p)
}

/// Parses a reference CSV (module docs); `source` names it in errors.
///
/// # Errors
/// [`Error::Invalid`] naming `source: line N, column C` for a bad header, a bad or
/// out-of-range cell, a row with the wrong number of cells, or a file without data.
pub fn parse_csv(text: &str, source: &str) -> Result<Reference> {
    let known = [
        "p",
        "a_r",
        "a_r_err",
        "mean_contact_stress",
        "mean_contact_stress_err",
        "mean_gap_rel",
        "mean_gap_rel_err",
    ];
    let recs = records(text);
    let (hline, cols) = header(source, &recs, &known, &GFMD_CSV_EXTRA_COLUMNS)?;
    if !cols.contains(&"p") || !Observable::COLUMNS.iter().any(|o| cols.contains(&o.key())) {
        return Err(cell_error(
            source,
            hline,
            "(header)",
            &cols.join(","),
            "a column p and at least one of a_r, mean_contact_stress, mean_gap_rel",
        ));
    }
    for c in &cols {
        if let Some(base) = c.strip_suffix("_err") {
            if !cols.contains(&base) {
                return Err(cell_error(
                    source,
                    hline,
                    c,
                    c,
                    &format!("{c} only beside a column {base}"),
                ));
            }
        }
    }
    let mut points = Vec::new();
    for (n, l, cells) in data_rows(&recs) {
        if cells.len() != cols.len() {
            return Err(cell_error(
                source,
                n,
                "(row)",
                l,
                &format!("{} cells as in the header", cols.len()),
            ));
        }
        let at = |name: &str| cols.iter().position(|c| *c == name).map(|i| cells[i]);
        // GFMD's own CSV: a load that did not converge, or a cycle's row off the loading
        // branch (unloading, tension), is not a loading reference point
        if at("converged") == Some("false") || at("branch").is_some_and(|b| b != "loading") {
            continue;
        }
        let p = load(source, n, at("p").unwrap_or(""))?;
        for o in Observable::COLUMNS {
            let Some(v) = at(o.key()).filter(|v| !v.is_empty()) else {
                continue;
            };
            let value = number(source, n, o.key(), v, o.allowed())?;
            if !o.in_range(value) {
                return Err(cell_error(source, n, o.key(), v, o.allowed()));
            }
            let ek = format!("{}_err", o.key());
            let error = match at(&ek).filter(|e| !e.is_empty()) {
                Some(e) => {
                    let x = number(source, n, &ek, e, "a finite number > 0")?;
                    if x <= 0.0 {
                        return Err(cell_error(source, n, &ek, e, "a finite number > 0"));
                    }
                    Some(x)
                }
                None => None,
            };
            points.push(Observation {
                p,
                observable: o,
                value,
                error,
                sigma: 0.0,
            });
        }
    }
    if points.is_empty() {
        return Err(cell_error(
            source,
            hline + 1,
            "(data)",
            "(no rows)",
            "at least one row with a value",
        ));
    }
    Ok(Reference {
        name: source.to_string(),
        points,
    })
}

/// Parses a Pr(σ*) CSV (`p,sigma,density`) into [`Observable::Pr`] observations.
///
/// # Errors
/// As [`parse_csv`].
pub fn parse_pr_csv(text: &str, source: &str) -> Result<Vec<Observation>> {
    let recs = records(text);
    let (hline, cols) = header(source, &recs, &["p", "sigma", "density"], &[])?;
    if cols.len() != 3 {
        return Err(cell_error(
            source,
            hline,
            "(header)",
            &cols.join(","),
            "the columns p, sigma, density",
        ));
    }
    let mut out = Vec::new();
    for (n, l, cells) in data_rows(&recs) {
        if cells.len() != 3 {
            return Err(cell_error(source, n, "(row)", l, "3 cells as in the header"));
        }
        let at = |name: &str| cells[cols.iter().position(|c| *c == name).unwrap_or(0)];
        let p = load(source, n, at("p"))?;
        let sigma = number(source, n, "sigma", at("sigma"), "a finite number")?;
        let d = at("density");
        let density = number(source, n, "density", d, Observable::Pr.allowed())?;
        if density < 0.0 {
            return Err(cell_error(source, n, "density", d, Observable::Pr.allowed()));
        }
        out.push(Observation {
            p,
            observable: Observable::Pr,
            value: density,
            error: None,
            sigma,
        });
    }
    if out.is_empty() {
        return Err(cell_error(source, hline + 1, "(data)", "(no rows)", "at least one row"));
    }
    Ok(out)
}
