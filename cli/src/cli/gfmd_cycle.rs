//! `asperity gfmd --cycle` (and a sweep downwards) as CSV: the columns of a GFMD sweep
//! ([`super::gfmd_csv::GFMD_CSV_HEADER`]) and `branch`, after `#` lines giving the pull-off and the
//! jump-in. The theory's columns are its branch at the same load: the unloading branch where
//! the theory has two (inside a hysteresis window) on unloading rows, and on tensile rows its
//! contact branch under tension (a_r and σ̄_c*; the mean gap is not defined there), empty
//! beyond the theory's own pull-off. Also the labels of a load path's steps for its progress.

use super::gfmd_csv::{csv_row, GFMD_CSV_HEADER};
use super::progress::load_label;
use asperity::gfmd::cycle::{CycleSpec, GfmdCycle, PathBranch};
use asperity::theory::cycle::TheoryPathRow;
use asperity::theory::sweep::SweepSpec;

/// The theory's row under tension at GFMD's load `p` ≤ 0 (the same loads: 0, −p₁, −2p₁, …).
fn tensile_row(c: &GfmdCycle, p: f64) -> Option<&TheoryPathRow> {
    let t = c.theory_cycle.as_ref()?;
    t.rows
        .iter()
        .find(|r| r.p <= 0.0 && (r.p - p).abs() <= 1e-12 * p.abs().max(1e-300))
}

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
    out.push_str(GFMD_CSV_HEADER);
    out.push_str(",branch");
    for r in &c.rows {
        let g = &r.row;
        let th = c
            .theory
            .as_ref()
            .and_then(|t| t.rows.iter().find(|t| (t.p / g.p - 1.0).abs() < 1e-12));
        let unloading = r.branch == PathBranch::Unloading;
        let pick = |load: f64, unload: f64| if unloading && unload.is_finite() { unload } else { load };
        let theory = if g.p > 0.0 {
            [
                th.map(|t| pick(t.a_r, t.a_r_unloading)),
                th.map(|t| pick(t.mean_gap_rel, t.mean_gap_unloading_rel)),
                th.filter(|t| !(unloading && t.a_r_unloading.is_finite()))
                    .map(|t| t.mean_contact_stress),
            ]
        } else {
            let tr = tensile_row(c, g.p);
            [tr.map(|t| t.a_r), None, tr.map(|t| t.mean_contact_stress)]
        };
        out.push('\n');
        out.push_str(&csv_row(
            [
                g.p,
                g.a_r,
                g.mean_gap_rel,
                g.mean_gap,
                g.mean_contact_stress,
                g.elastic_energy,
            ],
            g.converged,
            (g.contact_stress_variance, g.iterations, g.residual),
            theory,
        ));
        out.push(',');
        out.push_str(r.branch.name());
    }
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
