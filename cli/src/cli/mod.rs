//! Command-line interface: `asperity [tui]`, `asperity run`, `asperity sweep`, `asperity presets`.
//!
//! The headless commands print JSON or a table to stdout; errors go to stderr as one line
//! with a non-zero exit code. Flag names and JSON keys are a public interface.

use asperity::theory::engine;
pub mod bench;
pub mod clap_line;
pub mod figure;
pub mod gauge;
pub mod gauge_gfmd;
pub mod gfmd;
pub mod gfmd_cycle;
pub mod gfmd_mpi;

use asperity::error::Field;
use asperity::error::{Error, Result};
use asperity::input::model::ModelKind;
use asperity::input::overrides::{AccuracyKnobs, ModelChanges, Overrides};
use asperity::input::preset::{self, Preset};
use asperity::input::scene::Scene;
use asperity::input::scene::ThicknessQr;
use asperity::surface::heightmap::Surface;
use asperity::theory::persson::Accuracy;
use clap::{Args, Parser, Subcommand, ValueEnum};
use std::io::IsTerminal;
use std::io::Write;

pub mod flags;
pub mod heartbeat;
pub use crate::outfile;
pub mod parse;
pub mod progress;
pub mod surface;
pub mod surface_generate;
pub mod sweep;

pub use clap_line::clap_error_line;
pub use parse::{count, field_name, number, render_error, whole_number_u64};

/// asperity: explore Persson's contact-mechanics theory of rough, adhesive, elastic contacts.
#[derive(Debug, Parser)]
#[command(name = "asperity", version, about, long_about = None)]
pub struct Cli {
    /// What to do; without a subcommand the terminal explorer opens.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// No progress on stderr (bars and progress lines; errors and notes still print).
    #[arg(long, global = true)]
    pub quiet: bool,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Open the terminal explorer (the default), on a preset or on the scene the flags give.
    Tui(TuiArgs),
    /// Open the explorer in a teaching tour (tours/NAME.toml or built in).
    Tour(TourArgs),
    /// Evaluate the theory for one scene and print the result (exit status 0; 3 when it is
    /// printed but not converged, the reason in `converged_note` and on stderr; 2 bad input).
    Run(RunArgs),
    /// List the available presets.
    Presets,
    /// Speed against error for every solver; the full run writes BENCHMARKS.md.
    Bench(bench::BenchArgs),
    /// Sweep the load: one row per p* with a_r, mean gap, mean contact stress, elastic energy.
    Sweep(sweep::SweepArgs),
    /// Brute-force GFMD run on a reduced grid, compared with the theory on the same surface.
    Gfmd(gfmd::GfmdArgs),
    /// A figure or table of the paper: data, a text chart, SVG/PNG (--list names them).
    Figure(figure::FigureArgs),
    /// Fit coefficients of the custom model (c1, c2, alpha, k_griffith, w0) to reference data.
    Gauge(gauge::GaugeArgs),
    /// Every model (1-5, yp08, xu24, fitted presets) against a reference set: relative errors and an overlay.
    Compare(gauge::CompareArgs),
    /// The PSD of a measured height map: radial average, h_rms, rms gradient and curvature, self-affine fit.
    Psd(surface::PsdArgs),
    /// Make a surface: `surface generate` writes a seeded self-affine height map (.txt .asc .dat .xyz .npy .gsf).
    Surface(surface_generate::SurfaceCmdArgs),
}

/// Output format of `run`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// One JSON object.
    Json,
    /// Human-readable table.
    Table,
}

/// The scene knobs shared by `run`, `sweep`, `gfmd`.
#[derive(Debug, Clone, Args)]
pub struct SceneArgs {
    /// Preset name (from presets/) or path to a preset TOML file.
    #[arg(long, default_value = preset::DEFAULT_PRESET)]
    pub preset: String,
    /// Model variant: 1, 2, 3, 4, 5, custom, yp08 or xu24 (default: the preset's; yp08 and xu24
    /// are defined for the adhesionless half-space: --gamma 0 --thickness inf).
    #[arg(long)]
    pub model: Option<String>,
    /// Fitting parameter gamma_f of yp08/xu24: S(a) = gamma_f + (1 - gamma_f) a^2 (yp08) or a (xu24).
    #[arg(long)]
    pub fudge_gamma: Option<f64>,
    /// Custom model: c1 of W(a) = 1 - c1(1-a^2) - c2(1-a^4) (implies --model custom).
    #[arg(long)]
    pub c1: Option<f64>,
    /// Custom model: c2 (implies --model custom).
    #[arg(long)]
    pub c2: Option<f64>,
    /// Custom model: broadening exponent alpha, dp ~ W^alpha (implies --model custom).
    #[arg(long)]
    pub alpha: Option<f64>,
    /// Custom model: Griffith prefactor k_G (implies --model custom).
    #[arg(long)]
    pub k_griffith: Option<f64>,
    /// Custom model: cap sigma_a at gamma_s/rho (true/false; implies --model custom).
    #[arg(long)]
    pub cap: Option<bool>,
    /// Thickness t*q_r, or inf for a semi-infinite body (default: the preset's).
    #[arg(long)]
    pub thickness: Option<String>,
    /// Surface energy gamma_s in J/m^2; 0 = no adhesion.
    #[arg(long)]
    pub gamma: Option<f64>,
    /// A measured surface or PSD table instead of the preset's spectrum.
    #[command(flatten)]
    pub source: surface::SurfaceArgs,
}

/// Arguments of `tui`: the scene flags of `run`.
#[derive(Debug, Clone, Args)]
pub struct TuiArgs {
    /// Scene.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Reduced pressure p* = p/(E* g) (default: the preset's reference load).
    #[arg(long)]
    pub pressure: Option<f64>,
    /// Use the mouse: a click focuses a chart or picks a knob, the wheel steps the selected
    /// knob (off by default: the terminal's own selection and scrolling stay).
    #[arg(long)]
    pub mouse: bool,
}

/// Arguments of `tour`.
#[derive(Debug, Clone, Args)]
pub struct TourArgs {
    /// Tour name (from tours/ or built in) or path to a tour TOML file.
    #[arg(default_value = crate::tui::tour::DEFAULT_TOUR)]
    pub tour: String,
    /// Step to start at (1 = the first).
    #[arg(long, default_value_t = 1)]
    pub step: i64,
    /// List the available tours and exit.
    #[arg(long)]
    pub list: bool,
}

/// Arguments of `run`.
#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    /// Scene.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Reduced pressure p* = p/(E* g) (default: the preset's reference load).
    #[arg(long)]
    pub pressure: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Json)]
    pub format: Format,
    /// Number of sigma* points of the Pr(sigma*) table.
    #[arg(long, default_value_t = 201)]
    pub sigma_points: usize,
    /// Largest sigma* of the Pr table (default p* + 5 times the distribution's width).
    #[arg(long)]
    pub sigma_max: Option<f64>,
    /// Relative tolerance of the variance ODE (accuracy knob).
    #[arg(long, default_value_t = Accuracy::default().rtol)]
    pub rtol: f64,
    /// Adhesive solver: march steps per unit of ln q (accuracy knob; see BENCHMARKS.md).
    #[arg(long, default_value_t = asperity::theory::adhesion::AdhesionAccuracy::default().steps_per_ln_q)]
    pub adhesion_steps: f64,
    /// Adhesive solver: grid points per standard deviation of Pr (accuracy knob).
    #[arg(long, default_value_t = asperity::theory::adhesion::AdhesionAccuracy::default().points_per_width)]
    pub adhesion_points: f64,
    /// Adhesive solver: self-consistency tolerance |gamma(q_s)/gamma_s - 1| at each root.
    #[arg(long, default_value_t = asperity::theory::adhesion::AdhesionAccuracy::default().tol)]
    pub adhesion_tol: f64,
    /// Add the pull-off read-out (`pull_off`): the theory's pull-off in tension, the two DMT
    /// routes' and GFMD's nearest measured one, each with how far it was measured from GFMD
    /// (docs/physics.md 6.2-6.3; 0.1-3 s more).
    #[arg(long)]
    pub pull_off: bool,
}

impl SceneArgs {
    /// Loads the preset and applies the overrides. Returns the preset too.
    pub fn resolve(&self, pressure: Option<f64>) -> Result<(Preset, Scene)> {
        self.resolve_with_map(pressure)
            .map(|(preset, scene, _)| (preset, scene))
    }

    /// The measured-surface flags of the scene: these flags' where `--surface` or `--psd` is
    /// given, else the preset's `[measured]` section's (a scene exported from a measured
    /// surface), else none.
    pub fn surface_args(&self, preset: &Preset) -> Result<surface::SurfaceArgs> {
        match &preset.measured {
            Some(m) if self.source.surface.is_none() && self.source.psd.is_none() => {
                let mut a = surface::SurfaceArgs::from_measured(m)?;
                // the cut-offs given on the command line win
                a.qmin = self.source.qmin.or(a.qmin);
                a.qmax = self.source.qmax.or(a.qmax);
                Ok(a)
            }
            _ => Ok(self.source.clone()),
        }
    }

    /// As [`Self::resolve`], with the --surface map the scene's spectrum came from (the file
    /// read once).
    pub fn resolve_with_map(&self, pressure: Option<f64>) -> Result<(Preset, Scene, Option<Surface>)> {
        let preset = Preset::resolve(&self.preset).map_err(|e| parse::preset_under_flag(e, "--preset"))?;
        let scene = preset.scene()?;
        let model_changes = ModelChanges {
            kind: self.model.as_deref().map(str::parse::<ModelKind>).transpose()?,
            c1: self.c1,
            c2: self.c2,
            alpha: self.alpha,
            k_griffith: self.k_griffith,
            cap: self.cap,
            fudge_gamma: self.fudge_gamma,
        };
        let (spectrum, map) = self.surface_args(&preset)?.spectrum_and_map()?;
        let overrides = Overrides {
            model_changes,
            thickness_qr: self
                .thickness
                .as_deref()
                .map(str::parse::<ThicknessQr>)
                .transpose()?
                .map(|t| t.0),
            surface_energy_j_m2: self.gamma,
            pressure,
            spectrum,
            ..Overrides::default()
        };
        let scene = scene.apply(&overrides)?;
        Ok((preset, scene, map))
    }
}

/// The engine's options of `run` from its accuracy flags ([`AccuracyKnobs::options`]).
pub fn run_options(args: &RunArgs) -> engine::Options {
    AccuracyKnobs {
        sigma_points: Some(args.sigma_points),
        sigma_max: args.sigma_max,
        rtol: Some(args.rtol),
        adhesion_steps: Some(args.adhesion_steps),
        adhesion_points: Some(args.adhesion_points),
        adhesion_tol: Some(args.adhesion_tol),
    }
    .options()
}

/// Writes a line to stdout; a closed pipe (`asperity run | head`) is not an error.
pub fn emit(text: &str) {
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "{text}");
}

/// Exit status of `run` when the result is printed in full but does not meet the requested
/// accuracy (`converged: false`, with `converged_note` saying why): 0 is a converged result,
/// 2 bad input or a failed computation (one line on stderr), 3 this.
pub const EXIT_NOT_CONVERGED: i32 = 3;

/// Runs the CLI; returns the process exit code.
pub fn main() -> i32 {
    if std::env::var_os(FORBID_WORK_ENV).is_some() {
        asperity::work::forbid();
    }
    let code = run_cli();
    if let Some(path) = std::env::var_os(WORK_LOG_ENV) {
        // how many computations started: 0 for input refused up front (checked by the tests)
        let line = format!("work started: {}\n", asperity::work::started());
        let _ = std::fs::write(path, line);
    }
    code
}

/// An environment variable naming a file where the binary writes, on exit, how many
/// computations (theory, GFMD, PSD, surface generation) it started: the tests check that
/// refused input started none.
pub const WORK_LOG_ENV: &str = "ASPERITY_WORK_LOG";

/// An environment variable that, when set, makes any computation panic as it starts (the
/// tests that feed bad input: it must be refused before any work).
pub const FORBID_WORK_ENV: &str = "ASPERITY_FORBID_WORK";

/// Whether this process is an MPI rank other than 0 (by the launchers' environment: Open MPI,
/// MPICH/PMI, PMIx, MVAPICH, Slurm): an error every rank meets alike (a bad command line) is
/// then printed once, by rank 0; the exit code is every rank's.
fn secondary_rank() -> bool {
    [
        "OMPI_COMM_WORLD_RANK",
        "PMI_RANK",
        "PMIX_RANK",
        "MV2_COMM_WORLD_RANK",
        "SLURM_PROCID",
    ]
    .iter()
    .find_map(|v| std::env::var(v).ok())
    .is_some_and(|r| r.trim() != "0")
}

fn run_cli() -> i32 {
    use clap::FromArgMatches;
    let cli = match flags::command()
        .try_get_matches()
        .and_then(|m| Cli::from_arg_matches(&m))
    {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion)
                || e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            {
                let _ = e.print();
                return if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                    2
                } else {
                    0
                };
            }
            if !secondary_rank() {
                eprintln!("asperity: {}", clap_error_line(&e));
            }
            return 2;
        }
    };
    progress::set_quiet(cli.quiet);
    let mut unconverged = false;
    let result = match cli.command {
        None => tui_entry(preset::DEFAULT_PRESET, None, None, false),
        Some(Command::Tui(args)) => args
            .scene
            .resolve_with_map(args.pressure)
            .and_then(|(preset, scene, map)| {
                // the measured surface, for an export to reopen it
                let measured = args.scene.surface_args(&preset)?.to_measured(map.as_ref());
                tui_entry(&args.scene.preset, Some((scene, map, measured)), None, args.mouse)
            }),
        Some(Command::Tour(args)) => tour_entry(&args),
        Some(Command::Presets) => {
            for (name, place) in preset::list_available() {
                let desc = Preset::resolve(&name)
                    .map(|p| p.description)
                    .unwrap_or_else(|e| format!("(invalid: {e})"));
                emit(&format!("{name:<12} {place:<28} {desc}"));
            }
            Ok(())
        }
        Some(Command::Bench(args)) => bench::run(&args),
        Some(Command::Sweep(args)) => {
            let beat = heartbeat::start("sweep");
            let text = sweep::run(&args);
            drop(beat);
            text.map(|text| emit(&text))
        }
        // on several MPI ranks (feature mpi) the distributed run, else the serial one
        Some(Command::Gfmd(args)) => gfmd_mpi::on_ranks(&args).unwrap_or_else(|| gfmd::run(&args)),
        Some(Command::Figure(args)) => figure::run(&args),
        Some(Command::Gauge(args)) => gauge::run(&args),
        Some(Command::Compare(args)) => gauge::compare(&args),
        Some(Command::Psd(args)) => surface::run_psd(&args),
        Some(Command::Surface(args)) => surface_generate::run(&args),
        Some(Command::Run(args)) => args.scene.resolve(args.pressure).and_then(|(preset, scene)| {
            let beat = heartbeat::start("run");
            let mut opts = run_options(&args);
            // a scene exported on the unloading branch (`[load] branch = "unloading"`) reports it
            opts.adhesion.follow_unloading = preset.follows_unloading();
            let out = if args.pull_off {
                asperity::report::point::point_with_pull_off(&scene, &opts)
            } else {
                asperity::report::point(&scene, &opts)
            };
            drop(beat);
            let out = out?;
            match args.format {
                Format::Json => emit(&crate::report::point_json(&preset.name, &out)),
                Format::Table => emit(&crate::report::point_table(&preset.name, &out)),
            }
            if let Some(note) = pr_range_note(args.sigma_max, &out.stats) {
                eprintln!("asperity run: note: {note}");
            }
            if let Some(why) = out.converged_note.as_deref().filter(|_| !out.converged) {
                eprintln!("asperity run: not converged: {why}");
                unconverged = true;
            }
            Ok(())
        }),
    };
    match result {
        Ok(()) if unconverged => EXIT_NOT_CONVERGED,
        Ok(()) => 0,
        Err(e) => {
            if !secondary_rank() {
                eprintln!("asperity: {}", render_error(&e));
            }
            2
        }
    }
}

/// The share of the contact the tabulated Pr holds, where `--sigma-max` cut it below most of
/// it (under 90 % of a_r): a note naming the flag, so that a table that does not add up to
/// a_r is never printed silently.
fn pr_range_note(sigma_max: Option<f64>, stats: &asperity::contact::ContactStats) -> Option<String> {
    let (max, a_r) = (sigma_max?, stats.a_r);
    let held = stats.pr.integral();
    (a_r > 0.0 && held.is_finite() && held < 0.9 * a_r).then(|| {
        format!(
            "the Pr table up to --sigma-max {} holds {:.0} % of the contact (integral {:.3} of a_r {:.3}); raise --sigma-max to tabulate the rest",
            asperity::error::fmt_value(max),
            100.0 * held / a_r,
            held,
            a_r
        )
    })
}

fn tour_entry(args: &TourArgs) -> Result<()> {
    use crate::tui::tour::{self, Tour};
    if args.list {
        for (name, place) in tour::list_available() {
            let desc = Tour::resolve(&name)
                .map(|t| format!("{} ({} steps)", t.title, t.steps.len()))
                .unwrap_or_else(|e| format!("(invalid: {e})"));
            emit(&format!("{name:<12} {place:<28} {desc}"));
        }
        return Ok(());
    }
    let allowed = "a tour (`tour --list`) or a tour TOML file";
    let t = Tour::resolve(&args.tour).map_err(|e| parse::toml_under(e, "tour", allowed))?;
    if !tour::BUILTIN.iter().any(|(n, _)| *n == args.tour) {
        eprintln!("asperity tour: read {}", args.tour);
    }
    let n = t.steps.len();
    if args.step < 1 || args.step as usize > n {
        return Err(Error::invalid_text(
            Field::Other("--step".into()),
            args.step,
            format!("1 <= step <= {n}"),
        ));
    }
    let first = &t.steps[0];
    let source = first.source.clone();
    tui_entry(&source, None, Some((t, args.step as usize - 1)), false)
}

/// Opens the explorer on the preset, on `scene` where one is given (with the measured map
/// its spectrum came from, for GFMD), walking `tour` from a step where one is given; `mouse`
/// captures the mouse.
fn tui_entry(
    preset_name: &str,
    scene: Option<(Scene, Option<Surface>, Option<preset::MeasuredSpec>)>,
    tour: Option<(crate::tui::tour::Tour, usize)>,
    mouse: bool,
) -> Result<()> {
    // Validate the preset first so a bad one gives the same error as the CLI.
    let preset = Preset::resolve(preset_name)?;
    if !std::io::stdout().is_terminal() {
        eprintln!(
            "asperity: stdout is not a terminal, so the explorer cannot open.\n\
             For scripts use the headless commands, e.g.\n  \
             asperity run --preset {preset_name} --format json\n  \
             asperity sweep --preset {preset_name} --from 1e-3 --to 1 --points 50\n  \
             asperity presets"
        );
        return Err(Error::Unsupported("the terminal explorer needs a terminal".into()));
    }
    let mut app = crate::tui::app::App::new(preset_name, preset)?;
    app.ui.mouse = mouse;
    if let Some((s, map, measured)) = scene {
        app.params.measured = measured;
        if let (asperity::surface::spectrum::Spectrum::Tabulated(t), Some(m)) = (s.spectrum(), map) {
            app.params.map = Some((t.source.clone(), std::sync::Arc::new(m)));
        }
        app.params.base = s.clone();
        app.params.scene = s;
    }
    if let Some((t, step)) = tour {
        app.start_tour(t, step);
    }
    crate::tui::run_app(app)
}
