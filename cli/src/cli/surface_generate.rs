//! `asperity surface generate`: a seeded self-affine height map made by the generator GFMD
//! uses ([`asperity::surface::heightmap::generate`]: Fourier filtering with deterministic
//! amplitudes and random phases, docs/physics.md §1) and written in any format asperity reads,
//! chosen by the extension of `--output` ([`asperity::surface::writers`]).
//!
//! ```text
//! asperity surface generate --output FILE [--grid N] [--size L_m] [--hurst H]
//!     [--rolloff-wavelength M] [--short-wavelength M] [--rms-gradient G | --rms-height M]
//!     [--seed S] [--non-periodic] [--format table|json]
//! ```
//!
//! The map is periodic and its discrete rms gradient ḡ equals `--rms-gradient` (or its h_rms
//! equals `--rms-height`) to round-off. `--non-periodic` cuts the N×N map out of a 2N×2N
//! periodic one of twice the side, as a measured map would be
//! ([`asperity::surface::generate`], shared with Python's `generate_surface`): the window's
//! own h_rms and ḡ (by differences inside it) are printed, not forced.

use super::emit;
use asperity::error::{Error, Field, Result};
use asperity::surface::generate::{window_rms_gradient, MapRequest};
use asperity::surface::heightmap::Surface;
use clap::{Args, ValueEnum};
use serde::Serialize;
use std::path::PathBuf;

/// What `asperity surface` does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SurfaceAction {
    /// Generate a self-affine height map and write it to --output.
    Generate,
}

/// Output format of the summary `surface generate` prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum GenerateFormat {
    /// The summary, aligned.
    Table,
    /// One JSON object.
    Json,
}

/// Arguments of `asperity surface`.
#[derive(Debug, Clone, Args)]
pub struct SurfaceCmdArgs {
    /// What to do: generate.
    #[arg(value_enum)]
    pub action: SurfaceAction,
    /// The file to write (.txt .asc .dat .xyz .npy .gsf: the format by the extension).
    #[arg(long)]
    pub output: PathBuf,
    /// Grid side N (the map is N x N).
    #[arg(long, default_value_t = 256)]
    pub grid: i64,
    /// Side L of the map in metres.
    #[arg(long, default_value_t = 1e-4)]
    pub size: f64,
    /// Hurst exponent H of the self-affine range.
    #[arg(long, default_value_t = 0.8)]
    pub hurst: f64,
    /// Roll-off wavelength lambda_r in metres (default L/2).
    #[arg(long)]
    pub rolloff_wavelength: Option<f64>,
    /// Short-wavelength cut-off lambda_s in metres (default 4 L/N: four points per lambda_s).
    #[arg(long)]
    pub short_wavelength: Option<f64>,
    /// rms gradient g of the map (default 1).
    #[arg(long, conflicts_with = "rms_height")]
    pub rms_gradient: Option<f64>,
    /// rms height h_rms of the map in metres (instead of --rms-gradient).
    #[arg(long)]
    pub rms_height: Option<f64>,
    /// Seed of the random phases (the same seed gives the same map on every platform).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Cut the map out of a periodic one of twice the side: not periodic, as a measured map.
    #[arg(long)]
    pub non_periodic: bool,
    /// Output format of the summary on stdout.
    #[arg(long, value_enum, default_value_t = GenerateFormat::Table)]
    pub format: GenerateFormat,
}

/// The JSON of `surface generate`: what was asked and what the written map has.
#[derive(Debug, Serialize)]
pub struct GenerateOutput {
    /// The file written.
    pub file: String,
    /// Grid side N.
    pub grid: usize,
    /// Side L (m).
    pub system_size_m: f64,
    /// Grid spacing (m).
    pub spacing_m: f64,
    /// H.
    pub hurst: f64,
    /// λ_r (m).
    pub rolloff_wavelength_m: f64,
    /// λ_s (m).
    pub short_wavelength_m: f64,
    /// The map's h_rms (m).
    pub rms_height_m: f64,
    /// The map's rms gradient ḡ (periodic: spectral; not periodic: differences inside it).
    pub rms_gradient: f64,
    /// Whether the map is periodic.
    pub periodic: bool,
    /// The seed.
    pub seed: u64,
    /// Wall time (s).
    pub elapsed_s: f64,
}

/// The library's request of these flags.
fn request(args: &SurfaceCmdArgs) -> MapRequest {
    MapRequest {
        grid: args.grid,
        size: args.size,
        hurst: args.hurst,
        rolloff_wavelength: args.rolloff_wavelength,
        short_wavelength: args.short_wavelength,
        rms_gradient: args.rms_gradient,
        rms_height: args.rms_height,
        seed: args.seed,
        periodic: !args.non_periodic,
    }
}

/// The library's fields in this command's flags.
fn flag_names(e: Error) -> Error {
    match e {
        Error::Invalid { field, value, allowed } => {
            let flag = match field {
                Field::RolloffWavelength => "--rolloff-wavelength",
                Field::ShortWavelength => "--short-wavelength",
                Field::Hurst => "--hurst",
                Field::RmsGradient => "--rms-gradient",
                Field::RmsHeight => "--rms-height",
                field => return Error::Invalid { field, value, allowed },
            };
            Error::Invalid {
                field: Field::Other(flag.into()),
                value,
                allowed,
            }
        }
        e => e,
    }
}

/// The map the flags ask for (see the module docs).
pub fn make(args: &SurfaceCmdArgs) -> Result<Surface> {
    request(args).make().map_err(flag_names)
}

/// Runs `asperity surface generate`.
pub fn run(args: &SurfaceCmdArgs) -> Result<()> {
    let start = std::time::Instant::now();
    let s = make(args)?;
    asperity::surface::writers::write(&s, &args.output)?;
    let spec = request(args).spectrum(args.size).map_err(flag_names)?;
    let out = GenerateOutput {
        file: args.output.display().to_string(),
        grid: s.nx,
        system_size_m: s.size_x(),
        spacing_m: s.spacing,
        hurst: spec.hurst,
        rolloff_wavelength_m: spec.lambda_r,
        short_wavelength_m: spec.lambda_s,
        rms_height_m: s.rms_height(),
        rms_gradient: if args.non_periodic {
            window_rms_gradient(&s)
        } else {
            s.rms_gradient()
        },
        periodic: !args.non_periodic,
        seed: args.seed,
        elapsed_s: start.elapsed().as_secs_f64(),
    };
    match args.format {
        GenerateFormat::Json => emit(&serde_json::to_string_pretty(&out).expect("serialisable")),
        GenerateFormat::Table => emit(&table(&out)),
    }
    Ok(())
}

fn table(o: &GenerateOutput) -> String {
    let f = |x: f64| crate::numfmt::format(x, 6, true);
    [
        ("file", o.file.clone()),
        ("grid", format!("{0} x {0}", o.grid)),
        ("system_size_m", f(o.system_size_m)),
        ("spacing_m", f(o.spacing_m)),
        ("hurst", f(o.hurst)),
        ("rolloff_wavelength_m", f(o.rolloff_wavelength_m)),
        ("short_wavelength_m", f(o.short_wavelength_m)),
        ("rms_height_m", f(o.rms_height_m)),
        ("rms_gradient", f(o.rms_gradient)),
        ("periodic", o.periodic.to_string()),
        ("seed", o.seed.to_string()),
        ("elapsed_s", format!("{:.3}", o.elapsed_s)),
    ]
    .iter()
    .map(|(k, v)| format!("{k:<24}{v}"))
    .collect::<Vec<_>>()
    .join("\n")
}
