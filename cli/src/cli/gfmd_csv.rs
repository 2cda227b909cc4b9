//! `asperity gfmd --format csv`: one header for single runs, sweeps and cycles
//! ([`GFMD_CSV_HEADER`]), the rows of each.

use asperity::gfmd::sweep::GfmdSweep;
use asperity::gfmd::GfmdResult;

/// The CSV columns of `gfmd --format csv` (single runs and sweeps): the columns of `sweep`
/// that GFMD measures, under the same names, then GFMD's own (`iterations`, `residual`), then
/// the theory on the same map's spectrum (`theory_…`).
pub const GFMD_CSV_HEADER: &str = "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,\
contact_stress_variance,iterations,residual,theory_a_r,theory_mean_gap_rel,theory_mean_contact_stress";

/// A GFMD sweep as CSV: the theory sweep's columns, GFMD's extras, then the theory's a_r, ū/h_rms
/// and σ̄_c* on the same map.
pub fn sweep_csv(sw: &GfmdSweep) -> String {
    let mut out = String::from(GFMD_CSV_HEADER);
    for (k, r) in sw.rows.iter().enumerate() {
        let th = sw.theory.as_ref().and_then(|t| t.rows.get(k));
        out.push('\n');
        out.push_str(&csv_row(
            [
                r.p,
                r.a_r,
                r.mean_gap_rel,
                r.mean_gap,
                r.mean_contact_stress,
                r.elastic_energy,
            ],
            r.converged,
            (r.contact_stress_variance, r.iterations, r.residual),
            [
                th.map(|t| t.a_r),
                th.map(|t| t.mean_gap_rel),
                th.map(|t| t.mean_contact_stress),
            ],
        ));
    }
    out
}

/// A single GFMD run as CSV: [`GFMD_CSV_HEADER`] and one row. GFMD's elastic energy is
/// not measured by a single run (a sweep's rows carry it): that cell is empty.
pub fn single_csv(o: &GfmdResult) -> String {
    let th = o.theory.as_ref();
    format!(
        "{GFMD_CSV_HEADER}\n{}",
        csv_row(
            [
                o.pressure,
                o.stats.a_r,
                o.mean_gap_rel,
                o.mean_gap,
                o.stats.mean_contact_stress,
                f64::NAN,
            ],
            o.converged,
            (o.stats.contact_stress_variance, o.iterations, o.residual),
            [
                th.map(|t| t.stats.a_r),
                th.and_then(|t| t.mean_gap_rel),
                th.map(|t| t.stats.mean_contact_stress),
            ],
        )
    )
}

/// One CSV row of [`GFMD_CSV_HEADER`]; a value that is not available (or not finite) is an
/// empty cell.
pub(crate) fn csv_row(first: [f64; 6], converged: bool, solver: (f64, usize, f64), theory: [Option<f64>; 3]) -> String {
    let f = |x: Option<f64>| match x {
        Some(x) if x.is_finite() => format!("{x:e}"),
        _ => String::new(),
    };
    let mut cells: Vec<String> = first.iter().map(|&x| f(Some(x))).collect();
    cells.push(converged.to_string());
    cells.push(f(Some(solver.0)));
    cells.push(solver.1.to_string());
    cells.push(f(Some(solver.2)));
    cells.extend(theory.iter().map(|&x| f(x)));
    cells.join(",")
}
