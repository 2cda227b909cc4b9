//! The reports as CSV, as every front end writes them: `sweep` ([`sweep`]), `sweep --cycle`
//! ([`theory_cycle`], with the pull-off read-out: [`sweep_cycle`]), and GFMD's single runs, sweeps and cycles ([`gfmd_single`],
//! [`gfmd_sweep`], [`gfmd_cycle`]). The headers are a public interface (pinned by the binary's
//! tests); the rows are the reports' own ([`super::sweep::Row`], [`super::gfmd::GfmdRow`]).
//!
//! A number is written as `{:e}` (shortest round trip); a value that is not available (a load
//! that did not converge, a gap below one, a theory that failed) or not finite is an empty
//! cell. The records are written by the `csv` crate ([`table`]): a cell holding a comma, a
//! quote or a line break is quoted as RFC 4180 says. A load path starts with `#` lines naming
//! its pull-off and jump-in.

use super::gfmd::{self, GfmdRow};
use super::pull_off::PullOffReport;
use super::sweep::Row;
use crate::gfmd::cycle::GfmdCycle;
use crate::gfmd::sweep::GfmdSweep;
use crate::gfmd::GfmdResult;
use crate::theory::cycle::TheoryCycle;

/// The columns of `sweep` (the first nine are the load sweep's first columns; the rest came with
/// sweeps over t·q_r and γ_s).
pub const SWEEP_HEADER: &str = "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,\
elastic_energy_reduced,mean_gap_error,contact_stress_variance,a_r_over_p,a_r_eq18,thickness_qr,gamma,\
a_r_unloading,branches,mean_gap_lower_rel,mean_gap_upper_rel,contact_load,mean_gap_unloading_rel,\
mean_gap_unloading_error,mean_gap_unloading_lower_rel,contact_load_unloading,trust_inside,trust_a_r_log_error,reason";

/// The columns of `sweep --cycle`.
pub const THEORY_CYCLE_HEADER: &str =
    "branch,p,a_r,mean_gap_rel,mean_contact_stress,on_unloading_branch,a_r_unloading_pinned";

/// The columns of GFMD's single runs and sweeps: the columns of `sweep` that GFMD measures,
/// under the same names, then GFMD's own (`iterations`, `residual`), then the theory on the
/// same map's spectrum (`theory_…`): [`GfmdRow`]'s fields. A load path adds `branch`.
pub const GFMD_HEADER: &str = "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,\
contact_stress_variance,iterations,residual,theory_a_r,theory_mean_gap_rel,theory_mean_contact_stress";

/// A number's cell: `{:e}`, or empty when it is not finite.
pub fn cell(x: f64) -> String {
    if x.is_finite() {
        format!("{x:e}")
    } else {
        String::new()
    }
}

/// An optional number's cell: empty when absent or not finite.
pub fn opt_cell(x: Option<f64>) -> String {
    x.map_or(String::new(), cell)
}

/// The line `header`, then one line per row of cells, written by the `csv` crate (a cell is
/// quoted where it holds a comma, a quote or a line break); lines end in `\n`, the last one
/// without it.
pub fn table(header: &str, rows: impl IntoIterator<Item = Vec<String>>) -> String {
    let mut w = csv::WriterBuilder::new().flexible(true).from_writer(Vec::new());
    let records = std::iter::once(header.split(',').map(str::to_string).collect()).chain(rows);
    for cells in records {
        // writing into memory: the only failure would be an allocation's, which aborts
        w.write_record(&cells).expect("a CSV record written to memory");
    }
    let bytes = w.into_inner().expect("a CSV table flushed to memory");
    let mut out = String::from_utf8(bytes).expect("CSV cells are UTF-8 strings");
    out.pop();
    out
}

/// `sweep`'s rows under [`SWEEP_HEADER`].
pub fn sweep(rows: &[Row]) -> String {
    let f = cell;
    table(
        SWEEP_HEADER,
        rows.iter().map(|row| {
            let r = &row.row;
            vec![
                format!("{:e}", r.p),
                f(r.a_r),
                f(r.mean_gap_rel),
                f(r.mean_gap),
                f(r.mean_contact_stress),
                f(r.elastic_energy),
                r.converged.to_string(),
                f(r.elastic_energy_reduced),
                f(r.mean_gap_error),
                f(r.contact_stress_variance),
                f(row.a_r_over_p),
                opt_cell(row.a_r_eq18),
                row.thickness_qr.map_or("inf".to_string(), f),
                f(row.gamma),
                f(r.a_r_unloading),
                r.branches.to_string(),
                f(r.mean_gap_lower_rel),
                f(r.mean_gap_upper_rel),
                f(r.contact_load),
                f(r.mean_gap_unloading_rel),
                f(r.mean_gap_unloading_error),
                f(r.mean_gap_unloading_lower_rel),
                f(r.contact_load_unloading),
                row.trust_inside.to_string(),
                f(row.trust_a_r_log_error),
                row.reason.clone().unwrap_or_default(),
            ]
        }),
    )
}

/// The `#` lines of a load path: `key: value` for each value present.
fn comments(lines: &[(&str, Option<String>)]) -> String {
    lines
        .iter()
        .filter_map(|(k, v)| v.as_ref().map(|v| format!("# {k}: {v}\n")))
        .collect()
}

/// A pull-off bracket's pair of numbers (the load it was lost at, the load it held at), each
/// written by `f`.
fn bracket(b: Option<[f64; 2]>, f: fn(f64) -> String) -> Option<String> {
    b.map(|[lost, held]| format!("{} {}", f(lost), f(held)))
}

/// A number as `{:e}`, finite or not (a GFMD path's loads are).
fn sci(x: f64) -> String {
    format!("{x:e}")
}

/// The pull-off read-out's `#` lines ([`super::pull_off::PullOffReport`]): each route's
/// pull-off (empty where it did not converge), GFMD's nearest with its standard error, the
/// trust's summary, the gauged estimate with its band (empty outside the measured range) and
/// its summary.
pub fn pull_off_comments(p: &PullOffReport) -> String {
    comments(&[
        ("bam_pull_off_pressure", Some(opt_cell(p.bam_pull_off_pressure))),
        ("gap_dmt_pull_off_pressure", Some(opt_cell(p.gap_dmt_pull_off_pressure))),
        (
            "gfmd_pull_off_pressure",
            p.gfmd
                .map(|g| format!("{} {}", cell(g.pull_off_pressure), opt_cell(g.pull_off_pressure_err))),
        ),
        ("pull_off_trust", Some(p.trust.summary.clone())),
        (
            "pull_off_estimate",
            Some(format!(
                "{} {} {}",
                opt_cell(p.estimate.pull_off_pressure),
                opt_cell(p.estimate.band.map(|b| b[0])),
                opt_cell(p.estimate.band.map(|b| b[1]))
            )),
        ),
        ("pull_off_estimate_summary", Some(p.estimate.summary.clone())),
    ])
}

/// `sweep --cycle` with its pull-off read-out: [`pull_off_comments`] where the report carries
/// one, then [`theory_cycle`].
pub fn sweep_cycle(pull_off: Option<&PullOffReport>, c: &TheoryCycle) -> String {
    pull_off.map_or(String::new(), pull_off_comments) + &theory_cycle(c)
}

/// `sweep --cycle`: `#` lines (where the unloading branch ends, the jump-in, the pull-off, why
/// the path stops), then the rows under [`THEORY_CYCLE_HEADER`].
pub fn theory_cycle(c: &TheoryCycle) -> String {
    let mut out = comments(&[
        ("unloading_branch_ends", c.unloading_branch_ends.map(cell)),
        ("jump_in_pressure", c.jump_in_pressure.map(cell)),
        ("pull_off_pressure", c.pull_off_pressure.map(cell)),
        ("pull_off_bracket", bracket(c.pull_off_bracket, cell)),
        ("tension_bound", c.tension_bound.map(cell)),
        ("note", Some(c.note.clone())),
    ]);
    out.push_str(&table(
        THEORY_CYCLE_HEADER,
        c.rows.iter().map(|r| {
            vec![
                r.branch.name().to_string(),
                cell(r.p),
                cell(r.a_r),
                cell(r.mean_gap_rel),
                cell(r.mean_contact_stress),
                r.on_unloading_branch.to_string(),
                opt_cell(r.a_r_unloading_pinned),
            ]
        }),
    ));
    out
}

/// `header`, then one line per GFMD row: [`GFMD_HEADER`]'s cells (and `branch` for a load
/// path's row).
pub fn gfmd_rows(header: &str, rows: &[GfmdRow]) -> String {
    table(
        header,
        rows.iter().map(|row| {
            let r = &row.row;
            let mut cells: Vec<String> = [
                r.p,
                r.a_r,
                r.mean_gap_rel,
                r.mean_gap,
                r.mean_contact_stress,
                r.elastic_energy,
            ]
            .map(cell)
            .to_vec();
            cells.push(r.converged.to_string());
            cells.push(cell(r.contact_stress_variance));
            cells.push(r.iterations.to_string());
            cells.push(cell(r.residual));
            cells.extend([row.theory_a_r, row.theory_mean_gap_rel, row.theory_mean_contact_stress].map(opt_cell));
            if let Some(b) = row.branch {
                cells.push(b.name().to_string());
            }
            cells
        }),
    )
}

/// A GFMD sweep under [`GFMD_HEADER`]: GFMD's rows with the theory's a_r, ū/h_rms and σ̄_c* on
/// the same map.
pub fn gfmd_sweep(sw: &GfmdSweep) -> String {
    gfmd_rows(GFMD_HEADER, &gfmd::sweep_rows(sw))
}

/// A single GFMD run under [`GFMD_HEADER`]: one row. A single run does not measure GFMD's
/// elastic energy (a sweep's rows carry it): that cell is empty.
pub fn gfmd_single(o: &GfmdResult) -> String {
    gfmd_rows(GFMD_HEADER, &[gfmd::single_row(o)])
}

/// A GFMD load path: `#` lines giving the pull-off, its bracket, the jump-in, the notes and the
/// theory's pull-off, then the rows (with the theory on GFMD's branch) under [`GFMD_HEADER`]
/// and `branch`.
pub fn gfmd_cycle(c: &GfmdCycle) -> String {
    let t = c.theory_cycle.as_ref();
    let mut out = comments(&[
        ("pull_off_pressure", c.pull_off_pressure.map(sci)),
        ("pull_off_bracket", bracket(c.pull_off_bracket, sci)),
        ("jump_in_pressure", c.jump_in_pressure.map(sci)),
        ("note", c.note.clone()),
        ("theory_pull_off_pressure", t.and_then(|t| t.pull_off_pressure).map(sci)),
        ("theory_note", t.map(|t| t.note.clone())),
    ]);
    out.push_str(&gfmd_rows(&format!("{GFMD_HEADER},branch"), &gfmd::cycle_rows(c)));
    out
}

#[cfg(test)]
mod tests {
    use super::table;

    #[test]
    fn table_quotes_cells_as_rfc_4180_says_and_ends_without_a_line_break() {
        let rows = vec![
            vec!["plain".to_string(), "1e-3".to_string(), String::new()],
            vec!["a, b".to_string(), "say \"hi\"".to_string(), "two\nlines".to_string()],
        ];
        let want = "x,y,z\nplain,1e-3,\n\"a, b\",\"say \"\"hi\"\"\",\"two\nlines\"";
        assert_eq!(table("x,y,z", rows), want);
        assert_eq!(table("x,y,z", Vec::new()), "x,y,z");
    }
}
