//! `asperity gfmd --cycle` (and a sweep downwards): the labels of a load path's steps for its
//! progress. Its CSV is the library's ([`asperity::report::csv::gfmd_cycle`]).

use super::progress::load_label;
use asperity::gfmd::cycle::CycleSpec;
use asperity::theory::sweep::SweepSpec;

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
