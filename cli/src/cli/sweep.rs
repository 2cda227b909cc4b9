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

/// The CSV of `sweep` and `sweep --cycle`: the library's ([`asperity::report::csv`]), its
/// header and writers under the names the binary has always used.
pub use asperity::report::csv::{
    sweep as csv, theory_cycle as cycle_csv, SWEEP_HEADER as CSV_HEADER, THEORY_CYCLE_HEADER as CYCLE_CSV_HEADER,
};

/// One row of `sweep` (CSV columns and JSON keys): the library's report row.
pub use asperity::report::sweep::Row;

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
        (SweepFormat::Csv, Some(c)) => asperity::report::csv::sweep_cycle(out.pull_off.as_ref(), c),
        (SweepFormat::Csv, None) => csv(&out.rows),
        (SweepFormat::Json, _) => serde_json::to_string_pretty(&out).expect("serialisable"),
    })
}
