//! `asperity gfmd --format csv`: one header for single runs, sweeps and cycles
//! ([`GFMD_CSV_HEADER`]), the library's rows ([`asperity::report::gfmd`]) written as cells.

use asperity::gfmd::sweep::GfmdSweep;
use asperity::gfmd::GfmdResult;
use asperity::report::gfmd::{self, GfmdRow};

/// The CSV columns of `gfmd --format csv` (single runs and sweeps): the columns of `sweep`
/// that GFMD measures, under the same names, then GFMD's own (`iterations`, `residual`), then
/// the theory on the same map's spectrum (`theory_…`): [`GfmdRow`]'s fields.
pub const GFMD_CSV_HEADER: &str = "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,\
contact_stress_variance,iterations,residual,theory_a_r,theory_mean_gap_rel,theory_mean_contact_stress";

/// A GFMD sweep as CSV: the theory sweep's columns, GFMD's extras, then the theory's a_r, ū/h_rms
/// and σ̄_c* on the same map.
pub fn sweep_csv(sw: &GfmdSweep) -> String {
    rows_csv(GFMD_CSV_HEADER, &gfmd::sweep_rows(sw))
}

/// A single GFMD run as CSV: [`GFMD_CSV_HEADER`] and one row. GFMD's elastic energy is
/// not measured by a single run (a sweep's rows carry it): that cell is empty.
pub fn single_csv(o: &GfmdResult) -> String {
    rows_csv(GFMD_CSV_HEADER, &[gfmd::single_row(o)])
}

/// `header`, then one line per row.
pub(crate) fn rows_csv(header: &str, rows: &[GfmdRow]) -> String {
    let mut out = String::from(header);
    for r in rows {
        out.push('\n');
        out.push_str(&csv_row(r));
    }
    out
}

/// One CSV row of [`GFMD_CSV_HEADER`] (and `branch` for a cycle's row); a value that is not
/// available (or not finite) is an empty cell.
fn csv_row(row: &GfmdRow) -> String {
    let r = &row.row;
    let f = |x: Option<f64>| match x {
        Some(x) if x.is_finite() => format!("{x:e}"),
        _ => String::new(),
    };
    let mut cells: Vec<String> = [
        r.p,
        r.a_r,
        r.mean_gap_rel,
        r.mean_gap,
        r.mean_contact_stress,
        r.elastic_energy,
    ]
    .iter()
    .map(|&x| f(Some(x)))
    .collect();
    cells.push(r.converged.to_string());
    cells.push(f(Some(r.contact_stress_variance)));
    cells.push(r.iterations.to_string());
    cells.push(f(Some(r.residual)));
    cells.extend([row.theory_a_r, row.theory_mean_gap_rel, row.theory_mean_contact_stress].map(f));
    if let Some(b) = row.branch {
        cells.push(b.name().to_string());
    }
    cells.join(",")
}
