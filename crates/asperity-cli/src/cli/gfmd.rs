//! `asperity gfmd`: one brute-force GFMD run of a scene on a reduced grid (see
//! [`asperity::gfmd`]), compared with the theory on the same realisation.
//!
//! ```text
//! asperity gfmd --preset NAME|PATH [--grid N] [--seed S] [--surface FILE --size L_m]
//!               [--pressure P] [--thickness T] [--gamma G] [--tolerance TOL]
//!               [--format json|table] [--save-surface FILE]
//! ```

use super::{emit, Format, SceneArgs};
use asperity::error::{Error, Field, Result};
use asperity::gfmd::{self, GfmdOptions, GfmdResult, GfmdSetup, GridSpec, Progress};
use asperity::surface::heightmap::Surface;
use clap::Args;
use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

/// Default reduced grid when a preset has no `[gfmd]` table.
pub const DEFAULT_GRID: GridSpec = GridSpec {
    system_size_ratio: 2.0,
    bandwidth: 32.0,
    points_per_short_wavelength: 8.0,
};

/// Arguments of `gfmd`.
#[derive(Debug, Clone, Args)]
pub struct GfmdArgs {
    /// Scene (preset, model for the theory, thickness, gamma).
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Reduced pressure p* = p/(E* g), g the map's rms gradient (default: the preset's).
    #[arg(long, allow_hyphen_values = true)]
    pub pressure: Option<f64>,
    /// Grid side N (default: the preset's [gfmd] grid); keeps L/lambda_r and lambda_s/da.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "surface")]
    pub grid: Option<i64>,
    /// Seed of the random surface.
    #[arg(long, default_value_t = 1, allow_hyphen_values = true, value_parser = super::whole_number_u64)]
    pub seed: u64,
    /// Height map to use instead of a generated one (text matrix, metres, one row per line).
    #[arg(long, requires = "size")]
    pub surface: Option<PathBuf>,
    /// Side L of the --surface map in metres.
    #[arg(long, requires = "surface", allow_hyphen_values = true)]
    pub size: Option<f64>,
    /// Write the height map used to this file (text matrix).
    #[arg(long)]
    pub save_surface: Option<PathBuf>,
    /// Relative force residual to reach.
    #[arg(long, default_value = "1e-8", allow_hyphen_values = true)]
    pub tolerance: f64,
    /// Largest number of FIRE steps.
    #[arg(long, default_value_t = GfmdOptions::default().max_iterations, allow_hyphen_values = true, value_parser = super::whole_number)]
    pub max_iterations: usize,
    /// Number of bins of the Pr(sigma*) histogram.
    #[arg(long, default_value_t = GfmdOptions::default().pr_bins, allow_hyphen_values = true, value_parser = super::whole_number)]
    pub bins: usize,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Json)]
    pub format: Format,
}

/// Builds the setup and options from the arguments.
pub fn setup(args: &GfmdArgs) -> Result<(GfmdSetup, GfmdOptions)> {
    let (preset, scene) = args.scene.resolve(args.pressure)?;
    let mut grid = preset.gfmd.as_ref().map(GridSpec::from_preset).unwrap_or(DEFAULT_GRID);
    if let Some(n) = args.grid {
        if n < 4 {
            return Err(Error::invalid(Field::Grid, n as f64, "an integer N >= 4"));
        }
        grid = grid.with_grid(n as usize)?;
    }
    let surface = match (&args.surface, args.size) {
        (Some(p), Some(l)) => {
            let s = Surface::load(p, l)?;
            s.check_rough()?;
            Some(s)
        }
        _ => None,
    };
    let opts = GfmdOptions {
        tolerance: args.tolerance,
        max_iterations: args.max_iterations,
        pr_bins: args.bins,
        ..GfmdOptions::default()
    };
    opts.validate()?;
    Ok((
        GfmdSetup {
            scene,
            grid,
            seed: args.seed,
            surface,
        },
        opts,
    ))
}

/// Runs `asperity gfmd`.
pub fn run(args: &GfmdArgs) -> Result<()> {
    let (setup, opts) = setup(args)?;
    let cancel = AtomicBool::new(false);
    let tty = std::io::stderr().is_terminal();
    let start = Instant::now();
    let mut last = Instant::now();
    let mut shown = false;
    let mut bar = |p: Progress| {
        if tty && start.elapsed() > Duration::from_millis(500) && last.elapsed() > Duration::from_millis(100) {
            last = Instant::now();
            shown = true;
            let mut e = std::io::stderr().lock();
            let _ = write!(
                e,
                "\rgfmd: step {:>7}  residual {:.2e} (target {:.0e})  contact {:.4}  {:.1} s ",
                p.iteration,
                p.residual,
                opts.tolerance,
                p.contact_fraction,
                start.elapsed().as_secs_f64()
            );
            let _ = e.flush();
        }
    };
    let result = gfmd::run(&setup, &opts, &mut bar, &cancel);
    if shown {
        eprintln!();
    }
    let out = result?;
    if out.adhesion_resolution > 0.25 {
        eprintln!(
            "asperity gfmd: note: (gamma/E*)*da/rho^2 = {:.3} > 0.25: the attraction is under-resolved on this grid \
             (physics.md §6); raise points_per_short_wavelength in the preset [gfmd] table",
            out.adhesion_resolution
        );
    }
    if let (Some(path), Some(s)) = (&args.save_surface, &out.surface) {
        s.save(path)?;
    }
    match args.format {
        Format::Json => emit(&serde_json::to_string_pretty(&out).expect("serialisable")),
        Format::Table => emit(&table(&out)),
    }
    Ok(())
}

fn table(o: &GfmdResult) -> String {
    let mut t = String::new();
    let mut line = |k: &str, v: String| t.push_str(&format!("{k:<28}{v}\n"));
    line(
        "grid",
        format!(
            "{0} x {0} (spacing {1:.4e} m, L = {2:.4e} m)",
            o.grid, o.spacing_m, o.system_size_m
        ),
    );
    line("seed", o.seed.map_or("(loaded map)".into(), |s| s.to_string()));
    line("p*", format!("{:.6e}  ({:.4e} Pa)", o.pressure, o.pressure_pa));
    line(
        "t*q_r",
        o.thickness_qr.map_or("inf (semi-infinite)".into(), |t| t.to_string()),
    );
    line("gamma_s", format!("{} J/m^2", o.gamma));
    let th = o.theory.as_ref();
    let both = |g: f64, t: Option<f64>| match t {
        Some(t) => format!("{g:<14.6}theory {t:.6}"),
        None => format!("{g:.6}"),
    };
    line("a_r", both(o.stats.a_r, th.map(|t| t.stats.a_r)));
    line(
        "mean_contact_stress*",
        both(o.stats.mean_contact_stress, th.map(|t| t.stats.mean_contact_stress)),
    );
    line(
        "contact_stress_variance*",
        both(
            o.stats.contact_stress_variance,
            th.map(|t| t.stats.contact_stress_variance),
        ),
    );
    line(
        "mean_gap",
        format!("{:.6e} m (u/h_rms = {:.6})", o.mean_gap, o.mean_gap_rel),
    );
    if let Some(e) = &o.theory_error {
        line("theory", format!("unavailable: {e}"));
    }
    line("iterations", o.iterations.to_string());
    line(
        "residual",
        format!("{:.2e} (tolerance {:.0e})", o.residual, o.tolerance),
    );
    line("elapsed_s", format!("{:.3}", o.elapsed_s));
    t.trim_end().to_string()
}
