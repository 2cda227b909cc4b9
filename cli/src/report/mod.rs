//! How the binary writes the library's reports ([`asperity::report`]): `run`'s JSON object
//! and its table. The JSON keys are the report's field names (a public interface, pinned by
//! `cli/tests/public_keys.rs`), with the preset's name first.

use asperity::report::PointReport;
use asperity::theory::adhesion::Branch;
use serde::Serialize;

/// `run --format json`: the preset's name, then every field of the report.
pub fn point_json(preset: &str, out: &PointReport) -> String {
    #[derive(Serialize)]
    struct Run<'a> {
        preset: &'a str,
        #[serde(flatten)]
        report: &'a PointReport,
    }
    serde_json::to_string_pretty(&Run { preset, report: out }).expect("serialisable")
}

/// `x` with `decimals` digits after the point, or in scientific notation with as many
/// significant digits where the fixed form would hide it (a nonzero value that would print
/// as 0.000…, or one of 10⁷ and above): a table never shows a small contact area as zero.
///
/// # Examples
/// ```
/// use asperity_cli::report::fixed;
/// assert_eq!(fixed(0.25, 4), "0.2500");
/// assert_eq!(fixed(4.46e-9, 8), "4.46000000e-9");
/// assert_eq!(fixed(0.0, 6), "0.000000");
/// ```
pub fn fixed(x: f64, decimals: usize) -> String {
    let hidden = x != 0.0 && x.abs() < 10f64.powi(-(decimals.min(300) as i32 / 2).max(1));
    if x.is_finite() && (hidden || x.abs() >= 1e7) {
        format!("{x:.decimals$e}")
    } else {
        format!("{x:.decimals$}")
    }
}

/// `run --format table`: one line per quantity, names padded to a column.
pub fn point_table(preset: &str, out: &PointReport) -> String {
    let s = &out.scene;
    let mut t = String::new();
    let mut line = |k: &str, v: String| t.push_str(&format!("{k:<28}{v}\n"));
    line("preset", preset.to_string());
    line(
        "model",
        format!("{} (c1 = {}, c2 = {}, alpha = {})", s.model, s.c1, s.c2, s.alpha),
    );
    line("p*", format!("{:.6e}  ({:.4e} Pa)", s.pressure, s.pressure_pa));
    line(
        "t*q_r",
        match s.thickness_qr {
            Some(t) => format!("{t}"),
            None => "inf (semi-infinite)".into(),
        },
    );
    line(
        "gamma_s",
        format!("{} J/m^2 (gamma_glo = {})", s.gamma, fixed(s.gamma_glo, 4)),
    );
    line("a_r", fixed(out.stats.a_r, 8));
    line("mean_contact_stress*", fixed(out.stats.mean_contact_stress, 6));
    line("contact_stress_variance*", fixed(out.stats.contact_stress_variance, 6));
    line("width*", fixed(out.width, 6));
    line("error_estimate (a_r)", format!("{:.2e}", out.error_estimate));
    if let (Some(g), Some(r)) = (out.mean_gap, out.mean_gap_rel) {
        let err = out.mean_gap_error.map_or(String::new(), |e| format!(" +- {e:.1e}"));
        line("mean_gap", format!("{g:.6e} m (u/h_rms = {}{err})", fixed(r, 6)));
        if let (Some(lo), Some(hi), true) = (
            out.mean_gap_lower_rel,
            out.mean_gap_upper_rel,
            out.branch != Branch::Adhesionless,
        ) {
            line(
                "mean_gap bracket",
                format!(
                    "{} <= u/h_rms <= {} (same a_r / same load without adhesion); contact load p_c* = {:.4e}",
                    fixed(lo, 6),
                    fixed(hi, 6),
                    out.contact_load.unwrap_or(f64::NAN)
                ),
            );
        }
        line("mean_gap is", out.mean_gap_about.clone());
    } else if let Some(n) = &out.mean_gap_note {
        line("mean_gap", n.clone());
    }
    if out.branch != Branch::Adhesionless {
        line(
            "sigma_a*",
            format!("{} (wall at sigma* = -sigma_a*)", fixed(out.sigma_a, 6)),
        );
        line("tensile_area", format!("{:.6e}", out.tensile_area));
        line("branch", out.branch.to_string());
        if let Some(u) = out.a_r_unloading {
            line("a_r_unloading", format!("{} (a second, unloading branch)", fixed(u, 8)));
        }
        if out.branches.len() > 1 {
            let list: Vec<String> = out
                .branches
                .iter()
                .map(|b| {
                    let gap = b
                        .mean_gap_rel
                        .map_or(String::new(), |g| format!(" u/h_rms = {}", fixed(g, 4)));
                    format!(
                        "{} a_r = {} sigma_a* = {}{gap}",
                        b.state.branch,
                        fixed(b.state.a_r, 6),
                        fixed(b.state.sigma_a, 4)
                    )
                })
                .collect();
            line("branches", list.join("; "));
            let edge = |p: Option<f64>| p.map_or("beyond the allowed range".to_string(), |p| format!("{p:.4e}"));
            line(
                "hysteresis",
                format!(
                    "pull-off at p* = {}, jump-in at p* = {}: the loading history decides the branch",
                    edge(out.pull_off_pressure),
                    edge(out.jump_in_pressure)
                ),
            );
        }
        line(
            "iterations",
            format!("{} marches (residual {:.1e})", out.iterations, out.residual),
        );
    }
    line("elastic_energy", format!("{:.6e} J/m^2", out.elastic_energy));
    line("trust", out.trust.summary.clone());
    for (k, v) in out.pull_off.as_ref().map(pull_off_rows).unwrap_or_default() {
        line(k, v);
    }
    match &out.converged_note {
        Some(why) if !out.converged => line("converged", format!("false: {why}")),
        _ => line("converged", format!("{}", out.converged)),
    }
    line(
        "elapsed_s",
        format!(
            "{:.3e} (solve {:.3e}, window {:.3e}, gap {:.3e})",
            out.elapsed_s, out.elapsed_solve_s, out.elapsed_window_s, out.elapsed_gap_s
        ),
    );
    t.trim_end().to_string()
}

/// `run --pull-off --format table`'s rows: the three pull-offs and their trust.
fn pull_off_rows(po: &asperity::report::pull_off::PullOffReport) -> Vec<(&'static str, String)> {
    let opt = |x: Option<f64>| x.map_or("-".to_string(), |x| format!("{x:.3e}"));
    let mut rows = vec![
        (
            "pull-off",
            format!(
                "{:.3e} (tension bound {:.3e}); DMT routes: bam {}, gap-dmt {}; GFMD nearest {}",
                po.pull_off_pressure,
                po.tension_bound,
                opt(po.bam_pull_off_pressure),
                opt(po.gap_dmt_pull_off_pressure),
                opt(po.gfmd.map(|g| g.pull_off_pressure))
            ),
        ),
        ("pull-off trust", po.trust.summary.clone()),
        ("pull-off estimate", po.estimate.summary.clone()),
    ];
    rows.extend(po.notes.iter().map(|n| ("pull-off note", n.clone())));
    rows
}
