//! `asperity sweep`: one row per value of the swept knob with a_r, ū/h_rms, ū, σ̄_c*,
//! ⟨δσ_c²⟩*, a_r/p*, the [S-18] reference, U and convergence.
//!
//! The library's report ([`asperity::report::sweep`]) written as CSV or JSON: `--over
//! pressure` (the default) sweeps p* (continuation, one shared gap table); `--over thickness`
//! (t·q_r, log-spaced) and `--over gamma` (γ_s, linear) evaluate each value as its own scene
//! at `--pressure`, each point exactly what `run` gives for it, and find the hysteresis
//! windows between and inside the steps.

use super::SceneArgs;
use asperity::error::{Error, Field, Result};
use asperity::report::sweep::{self, SweepReport};
use asperity::theory::engine::Options;
use asperity::theory::knob::{Knob, KnobSpec};
use asperity::theory::sweep::SweepSpec;
use clap::{Args, ValueEnum};

/// Output format of `sweep`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SweepFormat {
    /// Comma-separated, one header line then one row per load.
    Csv,
    /// One JSON object with `rows` (and the resolved scene).
    Json,
}

/// The knob a sweep turns (the flag's values; the report's is [`asperity::report::Over`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Over {
    /// p* (log-spaced).
    Pressure,
    /// t·q_r (log-spaced), at --pressure.
    Thickness,
    /// γ_s in J/m² (linearly spaced), at --pressure.
    Gamma,
}

/// Arguments of `sweep`.
#[derive(Debug, Clone, Args)]
pub struct SweepArgs {
    /// Scene.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The knob to sweep: pressure (p*), thickness (t*q_r) or gamma (gamma_s, J/m^2).
    #[arg(long, value_enum, default_value_t = Over::Pressure)]
    pub over: Over,
    /// First value of the swept knob.
    #[arg(long)]
    pub from: f64,
    /// Last value of the swept knob.
    #[arg(long)]
    pub to: f64,
    /// Number of values from --from to --to (log-spaced; linear for gamma).
    #[arg(long, default_value_t = 64)]
    pub points: usize,
    /// Reduced pressure p* of a thickness or gamma sweep (default: the preset's).
    #[arg(long)]
    pub pressure: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = SweepFormat::Csv)]
    pub format: SweepFormat,
    /// Load sweeps: the theory along a load cycle (up on the loading branch, back down on the
    /// unloading branch while it exists), as `gfmd --cycle` walks it.
    #[arg(long)]
    pub cycle: bool,
}

/// The CSV header (the first nine columns are the public interface of the load sweep; the
/// rest were added with `--over`).
pub const CSV_HEADER: &str = "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,\
elastic_energy_reduced,mean_gap_error,contact_stress_variance,a_r_over_p,a_r_eq18,thickness_qr,gamma,\
a_r_unloading,branches,mean_gap_lower_rel,mean_gap_upper_rel,contact_load,mean_gap_unloading_rel,\
mean_gap_unloading_error,mean_gap_unloading_lower_rel,contact_load_unloading,trust_inside,trust_a_r_log_error,reason";

/// One row of `sweep` (CSV columns and JSON keys): the library's report row.
pub use asperity::report::sweep::Row;

/// A CSV field: as is, or quoted (RFC 4180) when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// Formats rows as CSV.
pub fn csv(rows: &[Row]) -> String {
    let mut out = String::from(CSV_HEADER);
    // an unavailable value (a load that did not converge, or a gap below one) is left empty
    let f = |x: f64| if x.is_finite() { format!("{x:e}") } else { String::new() };
    let o = |x: Option<f64>| x.map_or(String::new(), f);
    for row in rows {
        let r = &row.row;
        out.push_str(&format!(
            "\n{:e},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.p,
            f(r.a_r),
            f(r.mean_gap_rel),
            f(r.mean_gap),
            f(r.mean_contact_stress),
            f(r.elastic_energy),
            r.converged,
            f(r.elastic_energy_reduced),
            f(r.mean_gap_error),
            f(r.contact_stress_variance),
            f(row.a_r_over_p),
            o(row.a_r_eq18),
            row.thickness_qr.map_or("inf".to_string(), f),
            f(row.gamma),
            f(r.a_r_unloading),
            r.branches,
            f(r.mean_gap_lower_rel),
            f(r.mean_gap_upper_rel),
            f(r.contact_load),
            f(r.mean_gap_unloading_rel),
            f(r.mean_gap_unloading_error),
            f(r.mean_gap_unloading_lower_rel),
            f(r.contact_load_unloading),
            row.trust_inside,
            f(row.trust_a_r_log_error),
            row.reason.as_deref().map_or(String::new(), csv_field),
        ));
    }
    out
}

/// Runs the sweep `args` asks for ([`asperity::report::sweep`]); returns the JSON object
/// (rows included).
pub fn compute(args: &SweepArgs) -> Result<SweepReport> {
    if args.cycle && args.over != Over::Pressure {
        return Err(Error::field(
            "--cycle",
            "set",
            "only with --over pressure (a load cycle runs over p*)",
        ));
    }
    let opts = Options::default();
    let mut quiet = |_: usize, _: usize| {};
    let knob = match args.over {
        Over::Pressure => {
            if let Some(p) = args.pressure {
                return Err(Error::invalid(
                    Field::Pressure,
                    p,
                    "only with --over thickness or --over gamma (a load sweep runs from --from to --to)",
                ));
            }
            let spec = SweepSpec {
                from: args.from,
                to: args.to,
                points: args.points,
            };
            spec.validate()?;
            let (preset, scene) = args.scene.resolve(Some(args.from))?;
            return sweep::pressure(
                &scene,
                &preset.name,
                &[spec],
                &opts,
                args.cycle,
                sweep::Control::none(&mut quiet),
            );
        }
        Over::Thickness => Knob::Thickness,
        Over::Gamma => Knob::Gamma,
    };
    let spec = KnobSpec {
        knob,
        from: args.from,
        to: args.to,
        points: args.points,
    };
    spec.validate()?;
    let (preset, scene) = args.scene.resolve(args.pressure)?;
    sweep::knob(
        &scene,
        &preset.name,
        knob,
        &[spec],
        &opts,
        sweep::Control::none(&mut quiet),
    )
}

/// Runs `asperity sweep`; returns the text to print.
pub fn run(args: &SweepArgs) -> Result<String> {
    let out = compute(args)?;
    if let Some(note) = &out.note {
        eprintln!("asperity sweep: {note}");
    }
    Ok(match (args.format, &out.cycle) {
        (SweepFormat::Csv, Some(c)) => out.pull_off.as_ref().map_or(String::new(), |p| p.csv_lines()) + &cycle_csv(c),
        (SweepFormat::Csv, None) => csv(&out.rows),
        (SweepFormat::Json, _) => serde_json::to_string_pretty(&out).expect("serialisable"),
    })
}

/// The CSV of `sweep --cycle`: `#` lines (where the unloading branch ends, the jump-in, why the
/// path stops), then `branch,p,a_r,mean_gap_rel,mean_contact_stress,on_unloading_branch`.
pub fn cycle_csv(c: &asperity::theory::cycle::TheoryCycle) -> String {
    let f = |x: f64| if x.is_finite() { format!("{x:e}") } else { String::new() };
    let mut out = String::new();
    if let Some(p) = c.unloading_branch_ends {
        out.push_str(&format!("# unloading_branch_ends: {}\n", f(p)));
    }
    if let Some(p) = c.jump_in_pressure {
        out.push_str(&format!("# jump_in_pressure: {}\n", f(p)));
    }
    if let Some(p) = c.pull_off_pressure {
        out.push_str(&format!("# pull_off_pressure: {}\n", f(p)));
    }
    if let Some([lost, held]) = c.pull_off_bracket {
        out.push_str(&format!("# pull_off_bracket: {} {}\n", f(lost), f(held)));
    }
    if let Some(b) = c.tension_bound {
        out.push_str(&format!("# tension_bound: {}\n", f(b)));
    }
    out.push_str(&format!("# note: {}\n", c.note));
    out.push_str(CYCLE_CSV_HEADER);
    for r in &c.rows {
        out.push_str(&format!(
            "\n{},{},{},{},{},{}",
            r.branch.name(),
            f(r.p),
            f(r.a_r),
            f(r.mean_gap_rel),
            f(r.mean_contact_stress),
            r.on_unloading_branch
        ));
    }
    out
}

/// The columns of `sweep --cycle --format csv`.
pub const CYCLE_CSV_HEADER: &str = "branch,p,a_r,mean_gap_rel,mean_contact_stress,on_unloading_branch";
