//! BENCHMARKS.md from a [`Report`]: the ladders as markdown tables, the machine, the defaults
//! and why, and the hand-written part kept from the previous file.

use super::ladder::Report;

/// Renders the ladders as markdown tables (one per solver) and the hard cases.
pub fn markdown(rep: &Report) -> String {
    let mut out = String::new();
    let mut solvers: Vec<&str> = rep.rungs.iter().map(|r| r.solver.as_str()).collect();
    solvers.dedup();
    for solver in solvers {
        out.push_str(&format!("### {solver}\n\n"));
        out.push_str("| case | setting | default | median time | max rel. error | errors | memory |\n");
        out.push_str("|---|---|---|---|---|---|---|\n");
        for r in rep.rungs.iter().filter(|r| r.solver == solver) {
            let errs = r
                .errors
                .iter()
                .map(|(k, v)| format!("{k} {v:.1e}"))
                .collect::<Vec<_>>()
                .join(", ");
            out.push_str(&format!(
                "| {} | {} | {} | {} | {:.1e}{} | {} | {} |\n",
                r.case,
                r.setting,
                if r.default { "**yes**" } else { "" },
                fmt_time(r.median_s),
                r.max_error(),
                match r.bound {
                    Some(b) => format!(" (bound {b:.0e}{})", if r.violates() { ", **FAILED**" } else { "" }),
                    None => String::new(),
                },
                errs,
                r.memory_bytes.map_or("".into(), fmt_bytes),
            ));
        }
        out.push('\n');
    }
    if !rep.hard_cases.is_empty() {
        out.push_str("### Hard cases\n\n| solver | case | outcome | a_r | residual / error estimate | time |\n|---|---|---|---|---|---|\n");
        for h in &rep.hard_cases {
            out.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} |\n",
                h.solver,
                h.case,
                h.outcome,
                h.a_r.map_or("".into(), |a| format!("{a:.6e}")),
                h.residual.map_or("".into(), |a| format!("{a:.1e}")),
                fmt_time(h.time_s)
            ));
        }
        out.push('\n');
    }
    out
}

/// "12.3 µs", "4.5 ms", "1.23 s".
pub fn fmt_time(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

fn fmt_bytes(b: u64) -> String {
    if b < 1 << 20 {
        format!("{:.1} KiB", b as f64 / 1024.0)
    } else {
        format!("{:.1} MiB", b as f64 / (1 << 20) as f64)
    }
}

/// A one-line description of this machine (CPU model and core count).
pub fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    format!("{cpu}, {cores} cores available to the process")
}

/// Why each default is what it is (the knee of each speed–error curve below).
pub const DEFAULTS: &str = "## Defaults and why\n\n\
- **Adhesionless theory: rtol = 1e-7.** Errors fall ~100× per 100× rtol while the time grows \
~1.7×; at 1e-7 a_r is good to ~1e-8 in 12–30 µs, two orders below the 1e-6 target, and a tighter \
rtol buys nothing a user can see. (The mean gap's energy route evaluates U at rtol 1e-11: it \
differentiates U in p*.)\n\
- **Adhesive theory: 24 steps per ln q, 10 grid points per width.** The knee: halving both \
(12, 5) is 4× faster but its error is 2–10× larger on system 1; doubling (48, 20) costs 4× and \
is not reliably better, because the two resolutions pull the error in opposite directions \
(convergence is first order and not monotone). The error estimate of `run` therefore halves each \
resolution separately. The explorer's load curves use (12, 5) (`Options::chart()`), ~2e-3 in \
a_r and ū, well below a pixel.\n\
- **Load sweep: grid step ≤ 0.15 in ln p\\*** (each requested point on the grid, U table shared), \
4th-order energy route: ū to ~1e-4 against a 4× finer sweep.\n\
- **GFMD: residual 1e-8, λ_s/Δa = 8 (presets' 512² grid).** The solver converges to 1e-8 in a few \
hundred FIRE steps almost independently of N; the discretisation error of a_r is first order in \
Δa (8 % at λ_s/Δa = 8 against the extrapolated limit, 4 % at 16), so a finer residual is wasted; \
λ_s/Δa = 8 is the usual compromise of the field ([S]; physics.md §6) and runs in under a second.\n\n\
Hard cases (end of the tables): each either converges (residual stated) or fails with a message \
saying what did not converge; none gives NaN.\n";

/// The heading from which BENCHMARKS.md is written by hand (measurements too long for `bench`,
/// e.g. GFMD at 2048²); `asperity bench` keeps everything from it on when it rewrites the file.
pub const HAND_WRITTEN: &str = "## Measured by hand";

/// The BENCHMARKS.md document around the tables.
pub fn document(tables: &str) -> String {
    format!(
        "# Benchmarks: speed against error\n\n\
         Generated by `cargo run --release -- bench` (this file; `--quick` runs a short version in CI and \
         fails if a default setting exceeds its error bound).\n\n\
         Machine: {}.\n\n\
         Times are medians of repeated runs; errors are relative, against a much finer solution of the \
         same solver (and closed forms where they exist). The default of each solver is marked.\n\n{}\n{}",
        machine(),
        DEFAULTS,
        tables
    )
}
