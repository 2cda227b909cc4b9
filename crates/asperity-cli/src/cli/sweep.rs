//! `asperity sweep`: one row per load with a_r, ū/h_rms, ū, σ̄_c*, U and convergence
//! ([`asperity::theory::sweep`]).

use super::SceneArgs;
use asperity::error::Result;
use asperity::theory::engine::Options;
use asperity::theory::sweep::{self, Sweep, SweepSpec};
use clap::{Args, ValueEnum};
use serde::Serialize;

/// Output format of `sweep`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SweepFormat {
    /// Comma-separated, one header line then one row per load.
    Csv,
    /// One JSON object with `rows` (and the resolved scene).
    Json,
}

/// Arguments of `sweep`.
#[derive(Debug, Clone, Args)]
pub struct SweepArgs {
    /// Scene.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// First reduced pressure p*.
    #[arg(long, allow_hyphen_values = true)]
    pub from: f64,
    /// Last reduced pressure p*.
    #[arg(long, allow_hyphen_values = true)]
    pub to: f64,
    /// Number of log-spaced loads from --from to --to.
    #[arg(long, default_value_t = 64, allow_hyphen_values = true, value_parser = super::whole_number)]
    pub points: usize,
    /// Output format.
    #[arg(long, value_enum, default_value_t = SweepFormat::Csv)]
    pub format: SweepFormat,
}

/// The CSV header (the first seven columns are the public interface).
pub const CSV_HEADER: &str =
    "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,elastic_energy_reduced,mean_gap_error";

/// The JSON object printed by `sweep --format json`.
#[derive(Debug, Clone, Serialize)]
pub struct SweepOutput {
    /// Preset name.
    pub preset: String,
    /// Resolved inputs (pressure = --from).
    pub scene: asperity::input::scene::SceneSummary,
    /// The sweep.
    #[serde(flatten)]
    pub sweep: Sweep,
}

/// Formats a sweep as CSV.
pub fn csv(sw: &Sweep) -> String {
    let mut out = String::from(CSV_HEADER);
    // an unavailable value (a load that did not converge, or a gap below one) is left empty
    let f = |x: f64| if x.is_finite() { format!("{x:e}") } else { String::new() };
    for r in &sw.rows {
        out.push_str(&format!(
            "\n{:e},{},{},{},{},{},{},{},{}",
            r.p,
            f(r.a_r),
            f(r.mean_gap_rel),
            f(r.mean_gap),
            f(r.mean_contact_stress),
            f(r.elastic_energy),
            r.converged,
            f(r.elastic_energy_reduced),
            f(r.mean_gap_error)
        ));
    }
    out
}

/// Runs `asperity sweep`; returns the text to print.
pub fn run(args: &SweepArgs) -> Result<String> {
    let spec = SweepSpec {
        from: args.from,
        to: args.to,
        points: args.points,
    };
    spec.validate()?;
    let (preset, scene) = args.scene.resolve(Some(args.from))?;
    let sw = sweep::sweep(&scene, &spec, &Options::default(), None)?;
    if let Some(note) = &sw.note {
        eprintln!("asperity sweep: {note}");
    }
    Ok(match args.format {
        SweepFormat::Csv => csv(&sw),
        SweepFormat::Json => serde_json::to_string_pretty(&SweepOutput {
            preset: preset.name.clone(),
            scene: scene.summary(),
            sweep: sw,
        })
        .expect("serialisable"),
    })
}
