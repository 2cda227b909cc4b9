//! `asperity bench [--quick]`: speed against error for every solver (see
//! [`crate::benchmark`]). The full run writes BENCHMARKS.md in the working directory.

use crate::benchmark::{self, Report};
use asperity::error::{Error, Result};
use clap::Args;

/// Arguments of `bench`.
#[derive(Debug, Clone, Args)]
pub struct BenchArgs {
    /// Short ladders that fit in CI; fails if a default setting exceeds its error bound.
    #[arg(long)]
    pub quick: bool,
    /// Where the full run writes its report.
    #[arg(long, default_value = "BENCHMARKS.md")]
    pub output: String,
}

/// Refuses an `--output` the report could not be written to, before any ladder runs: an
/// empty name, a folder that does not exist, or a folder.
fn check_output(path: &str) -> Result<()> {
    let p = std::path::Path::new(path);
    let dir = match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => std::path::Path::new("."),
    };
    let why = if path.trim().is_empty() {
        Some("a file name")
    } else if p.is_dir() {
        Some("a file, not a folder")
    } else if !dir.is_dir() {
        Some("a file in an existing folder")
    } else {
        None
    };
    match why {
        Some(w) => Err(Error::field("--output", asperity::error::fmt_text(path), w)),
        None => Ok(()),
    }
}

/// Runs the benchmark ladders.
pub fn run(args: &BenchArgs) -> Result<()> {
    check_output(&args.output)?;
    let mut rep = Report::default();
    let mut add = |r: Report| {
        rep.rungs.extend(r.rungs);
        rep.hard_cases.extend(r.hard_cases);
    };
    let mut steps = super::progress::Steps::new("bench", "ladder", 4);
    steps.step(0, "adhesionless theory");
    add(benchmark::adhesionless(args.quick)?);
    steps.step(1, "adhesive theory");
    add(benchmark::adhesive(args.quick)?);
    steps.step(2, "load sweeps");
    add(benchmark::sweeps(args.quick)?);
    steps.step(3, "GFMD");
    add(benchmark::gfmd(args.quick)?);
    steps.finish();
    let tables = benchmark::markdown(&rep);
    super::emit(&tables);
    if !args.quick {
        // hand-written sections (from HAND_WRITTEN on) survive a regeneration
        let kept = std::fs::read_to_string(&args.output)
            .ok()
            .and_then(|old| old.find(crate::benchmark::HAND_WRITTEN).map(|i| old[i..].to_string()));
        let mut doc = crate::benchmark::document(&tables);
        if let Some(k) = kept {
            doc.push('\n');
            doc.push_str(&k);
        }
        super::outfile::write_bytes("--output", std::path::Path::new(&args.output), doc.as_bytes())?;
        eprintln!("asperity bench: wrote {}", args.output);
    }
    let failed: Vec<String> = rep
        .rungs
        .iter()
        .filter(|r| r.violates())
        .map(|r| {
            format!(
                "{} / {} / {}: error {:.2e} > bound {:.0e}",
                r.solver,
                r.case,
                r.setting,
                r.max_error(),
                r.bound.unwrap_or(0.0)
            )
        })
        .collect();
    if failed.is_empty() {
        Ok(())
    } else {
        Err(Error::NotConverged {
            solver: asperity::error::Solver::Bench,
            reason: format!(
                "{} default setting(s) exceed their error bound: {}",
                failed.len(),
                failed.join("; ")
            ),
        })
    }
}
