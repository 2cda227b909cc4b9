//! `asperity gfmd --cycle` (and a sweep downwards) as CSV: the columns of a GFMD sweep
//! ([`super::gfmd_csv::GFMD_CSV_HEADER`]) and `branch`, after `#` lines giving the pull-off and the
//! jump-in; the rows, with the theory on GFMD's branch, are the library's
//! ([`asperity::report::gfmd::cycle_rows`]). Also the labels of a load path's steps for its
//! progress.

use super::gfmd_csv::{rows_csv, GFMD_CSV_HEADER};
use super::progress::load_label;
use asperity::gfmd::cycle::{CycleSpec, GfmdCycle};
use asperity::report::gfmd;
use asperity::theory::sweep::SweepSpec;

/// The CSV of a GFMD load path (see the module docs).
pub fn cycle_csv(c: &GfmdCycle) -> String {
    let f = |x: f64| format!("{x:e}");
    let mut out = String::new();
    if let Some(p) = c.pull_off_pressure {
        out.push_str(&format!("# pull_off_pressure: {}\n", f(p)));
    }
    if let Some([lost, held]) = c.pull_off_bracket {
        out.push_str(&format!("# pull_off_bracket: {} {}\n", f(lost), f(held)));
    }
    if let Some(p) = c.jump_in_pressure {
        out.push_str(&format!("# jump_in_pressure: {}\n", f(p)));
    }
    if let Some(n) = &c.note {
        out.push_str(&format!("# note: {n}\n"));
    }
    if let Some(t) = &c.theory_cycle {
        if let Some(p) = t.pull_off_pressure {
            out.push_str(&format!("# theory_pull_off_pressure: {}\n", f(p)));
        }
        out.push_str(&format!("# theory_note: {}\n", t.note));
    }
    out.push_str(&rows_csv(&format!("{GFMD_CSV_HEADER},branch"), &gfmd::cycle_rows(c)));
    out
}

/// The loads of a load path in the order GFMD walks them (the tension steps that follow a
/// cycle are not known in advance).
pub fn path_labels(spec: &CycleSpec) -> Vec<String> {
    let rising = SweepSpec {
        from: spec.from.min(spec.to),
        to: spec.from.max(spec.to),
        points: spec.points,
    }
    .pressures();
    let top = rising.len().saturating_sub(1);
    let mut out = Vec::new();
    if spec.cycle || spec.from <= spec.to {
        out.extend(rising.iter().map(|&p| format!("loading, {}", load_label(p))));
    } else {
        out.push(format!("loading, {}", load_label(rising[top])));
    }
    if spec.cycle || spec.from > spec.to {
        out.extend(
            rising[..top]
                .iter()
                .rev()
                .map(|&p| format!("unloading, {}", load_label(p))),
        );
    }
    out
}

/// The label of step `k` of a load path: its load, or a tension step past the listed loads.
pub fn path_label(labels: &[String], k: usize) -> Option<String> {
    Some(
        labels
            .get(k)
            .cloned()
            .unwrap_or_else(|| "tension, towards pull-off".into()),
    )
}
