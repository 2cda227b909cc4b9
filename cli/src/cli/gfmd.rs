//! `asperity gfmd`: one brute-force GFMD run of a scene on a reduced grid (see
//! [`asperity::gfmd`]), compared with the theory on the same realisation.
//!
//! ```text
//! asperity gfmd --preset NAME|PATH [--grid N] [--seed S] [--surface FILE --size L_m]
//!               [--pressure P] [--thickness T] [--gamma G] [--tolerance TOL]
//!               [--format json|table|csv] [--save-surface FILE] [--raw-adhesion]
//!               [--extrapolate [--ladder 4,8,16]] [--seeds K] [--from P --to P --points N]
//! ```

use super::progress::{load_label, Steps};
use super::{emit, SceneArgs};
use asperity::error::{Error, Result};
use asperity::gfmd::cycle::CycleSpec;
use asperity::gfmd::distributed::{Job, Outcome};
use asperity::gfmd::ladder::{Ensemble, Extrapolated, Ladder, MeanSe};
use asperity::gfmd::reduction::{Invariants, Reduction};
use asperity::gfmd::{self, GfmdOptions, GfmdResult, GfmdSetup, GridSpec, Progress, Stage};
use asperity::report::gfmd::GfmdSpec;
use asperity::theory::sweep::SweepSpec;
use clap::Args;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;

/// Default reduced grid when a preset has no `[gfmd]` table (the library's).
pub const DEFAULT_GRID: GridSpec = GridSpec::DEFAULT;

/// Output formats of `gfmd`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum GfmdFormat {
    /// One JSON object.
    Json,
    /// Human-readable table (a load sweep: CSV).
    Table,
    /// CSV with [`GFMD_CSV_HEADER`]: one row per load (a single run: one row).
    Csv,
}

/// `gfmd --format csv`: the library's header and writers ([`asperity::report::csv`]) under the
/// names the binary has always used.
pub use asperity::report::csv::{gfmd_single as single_csv, gfmd_sweep as sweep_csv, GFMD_HEADER as GFMD_CSV_HEADER};

/// Arguments of `gfmd`.
#[derive(Debug, Clone, Args)]
pub struct GfmdArgs {
    /// Scene (preset, model for the theory, thickness, gamma).
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Reduced pressure p* = p/(E* g), g the map's rms gradient (default: the preset's).
    #[arg(long)]
    pub pressure: Option<f64>,
    /// Grid side N (default: the preset's [gfmd] grid); keeps L/lambda_r and lambda_s/da.
    #[arg(long, conflicts_with = "surface")]
    pub grid: Option<i64>,
    /// Seed of the random surface.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Write the height map used to this file (text matrix).
    #[arg(long)]
    pub save_surface: Option<PathBuf>,
    /// Relative force residual to reach.
    #[arg(long, default_value = "1e-8")]
    pub tolerance: f64,
    /// Largest number of FIRE steps.
    #[arg(long, default_value_t = GfmdOptions::default().max_iterations)]
    pub max_iterations: usize,
    /// Number of bins of the Pr(sigma*) histogram.
    #[arg(long, default_value_t = GfmdOptions::default().pr_bins)]
    pub bins: usize,
    /// Output format.
    #[arg(long, value_enum, default_value_t = GfmdFormat::Json)]
    pub format: GfmdFormat,
    /// Minimiser: auto (pk on a half-space, fire on slabs), pk
    /// (Polonsky-Keer CG for the hard wall, FIRE with adhesion) or fire (FIRE alone).
    #[arg(long, value_enum, default_value_t = MethodArg::Auto)]
    pub method: MethodArg,
    /// Keep gamma_s and rho as given on the reduced grid (default: rescale them so that the
    /// reduced system keeps gamma_glo and the Tabor parameter of the full one).
    #[arg(long)]
    pub raw_adhesion: bool,
    /// Run a ladder of resolutions (--ladder) on the same map and extrapolate to da -> 0.
    #[arg(long, conflicts_with = "surface")]
    pub extrapolate: bool,
    /// Points per short wavelength lambda_s/da of the --extrapolate ladder.
    #[arg(long, value_delimiter = ',', default_value = "4,8,16", requires = "extrapolate")]
    pub ladder: Vec<f64>,
    /// Repeat over K realisations (seeds S..S+K-1) and report mean +- standard error.
    #[arg(long, default_value_t = 1, conflicts_with = "surface")]
    pub seeds: usize,
    /// Load sweep: first p* (warm-started loads from --from to --to).
    #[arg(long, requires = "to", conflicts_with_all = ["extrapolate", "pressure", "seeds"])]
    pub from: Option<f64>,
    /// Load sweep: last p*.
    #[arg(long, requires = "from")]
    pub to: Option<f64>,
    /// Load sweep: number of log-spaced loads.
    #[arg(long, default_value_t = 8, requires = "from")]
    pub points: usize,
    /// Load cycle: load from --from up to --to, unload back down and on into tension until the
    /// contact is lost (pull-off, with adhesion); rows carry their branch.
    #[arg(long, requires = "from")]
    pub cycle: bool,
}

/// `--method`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MethodArg {
    /// Polonsky-Keer on a half-space, FIRE on slabs and with adhesion.
    Auto,
    /// Polonsky-Keer CG, FIRE to check (FIRE alone with adhesion).
    Pk,
    /// FIRE alone.
    Fire,
}

impl From<MethodArg> for asperity::gfmd::Method {
    fn from(m: MethodArg) -> Self {
        match m {
            MethodArg::Auto => asperity::gfmd::Method::Auto,
            MethodArg::Pk => asperity::gfmd::Method::PolonskyKeer,
            MethodArg::Fire => asperity::gfmd::Method::Fire,
        }
    }
}

/// Largest K of `--seeds`, the allowed rungs of `--ladder` (the library's).
pub use asperity::report::gfmd::{LADDER_RANGE, MAX_SEEDS};

/// The JSON of `gfmd --extrapolate` / `--seeds K` (the library's report).
pub use asperity::report::gfmd::GfmdStudy as StudyOutput;

/// Builds the setup and options from the arguments.
pub fn setup(args: &GfmdArgs) -> Result<(GfmdSetup, GfmdOptions)> {
    if args.scene.source.psd.is_some() {
        return Err(Error::field(
            "--psd",
            args.scene
                .source
                .psd
                .as_ref()
                .map_or(String::new(), |p| p.display().to_string()),
            "none for gfmd: it needs a height map (--surface FILE)",
        ));
    }
    // the --surface map (its roughness checked with its spectrum)
    let (preset, scene, surface) = args.scene.resolve_with_map(args.pressure)?;
    let spec = GfmdSpec {
        grid: args.grid,
        seed: args.seed,
        tolerance: args.tolerance,
        max_iterations: Some(args.max_iterations),
        bins: Some(args.bins),
        method: args.method.into(),
        rescale: !args.raw_adhesion,
        seeds: args.seeds,
        ladder: args.extrapolate.then(|| args.ladder.clone()),
    };
    spec.setup(&preset, &scene, surface)
}

/// What `args` ask GFMD to do: a load path (`--cycle`, or `--from` above `--to`), a load
/// sweep (`--from` and `--to`), or one run.
pub fn job(args: &GfmdArgs) -> Job {
    match (args.from, args.to) {
        (Some(from), Some(to)) if args.cycle || to < from => Job::Cycle(CycleSpec {
            from,
            to,
            points: args.points,
            cycle: args.cycle,
        }),
        (Some(from), Some(to)) => Job::Sweep(SweepSpec {
            from,
            to,
            points: args.points,
        }),
        _ => Job::Run,
    }
}

/// A load sweep's or path's output in `format` (a table is the CSV); a single run's as
/// [`table`] and [`single_csv`] write it (without the study over seeds or resolutions).
pub fn path_output(out: Outcome, format: GfmdFormat) -> String {
    let json = |v: serde_json::Result<String>| v.expect("serialisable");
    match (out, format) {
        (Outcome::Cycle(c), GfmdFormat::Json) => json(serde_json::to_string_pretty(&c)),
        (Outcome::Cycle(c), _) => asperity::report::csv::gfmd_cycle(&c),
        (Outcome::Sweep(sw), GfmdFormat::Json) => json(serde_json::to_string_pretty(&sw)),
        (Outcome::Sweep(sw), _) => sweep_csv(&sw),
        (Outcome::Run(r), GfmdFormat::Json) => json(serde_json::to_string_pretty(&r)),
        (Outcome::Run(r), GfmdFormat::Table) => table(&r),
        (Outcome::Run(r), GfmdFormat::Csv) => single_csv(&r),
    }
}

/// Runs `asperity gfmd`.
/// On several MPI ranks the caller runs [`super::gfmd_mpi::on_ranks`] instead.
pub fn run(args: &GfmdArgs) -> Result<()> {
    let (setup, opts) = setup(args)?;
    let cancel = AtomicBool::new(false);
    match job(args) {
        Job::Cycle(spec) => {
            let labels = super::gfmd_cycle::path_labels(&spec);
            let mut steps = Steps::new("gfmd", "load", labels.len());
            let c = gfmd::cycle::run_cycle(
                &setup,
                &spec,
                &opts,
                &mut |k, p| report(&mut steps, k, &p, &opts, |k| super::gfmd_cycle::path_label(&labels, k)),
                &cancel,
            );
            steps.finish();
            emit(&path_output(Outcome::Cycle(Box::new(c?)), args.format));
            return Ok(());
        }
        Job::Sweep(spec) => {
            let loads = spec.pressures();
            let mut steps = Steps::new("gfmd", "load", loads.len());
            let sw = gfmd::sweep::run_sweep(
                &setup,
                &spec,
                &opts,
                &mut |k, p| report(&mut steps, k, &p, &opts, |k| loads.get(k).map(|&p| load_label(p))),
                &cancel,
            );
            steps.finish();
            emit(&path_output(Outcome::Sweep(Box::new(sw?)), args.format));
            return Ok(());
        }
        Job::Run => {}
    }
    let pressure = setup.scene.pressure();
    let mut steps = Steps::new("gfmd", "run", 1);
    let result = gfmd::run(
        &setup,
        &opts,
        &mut |p| report(&mut steps, 0, &p, &opts, |_| Some(load_label(pressure))),
        &cancel,
    );
    steps.finish();
    let study = result.and_then(|base| {
        if !args.extrapolate && args.seeds == 1 {
            return Ok((base, None, None));
        }
        let ladder = args.extrapolate.then_some(args.ladder.as_slice());
        let ex = match ladder {
            Some(l) => {
                let mut steps = Steps::new("gfmd", "rung", l.len());
                let label = |k: usize| l.get(k).map(|x| format!("lambda_s/da = {x}"));
                let r = gfmd::ladder::run_ladder(
                    &setup,
                    l,
                    &opts,
                    &mut |k, p| report(&mut steps, k, &p, &opts, label),
                    &cancel,
                );
                steps.finish();
                Some(r?)
            }
            None => None,
        };
        let ens = if args.seeds > 1 {
            let mut steps = Steps::new("gfmd", "seed", args.seeds);
            let label = |k: usize| Some(format!("seed {}", args.seed + k as u64));
            let r = gfmd::ladder::run_seeds(
                &setup,
                args.seeds,
                ladder,
                &opts,
                &mut |k, p| report(&mut steps, k, &p, &opts, label),
                &cancel,
            );
            steps.finish();
            Some(r?)
        } else {
            None
        };
        Ok((base, ex, ens))
    });
    let (out, extrapolation, ensemble) = study?;
    print_run(args, out, extrapolation, ensemble)
}

/// One progress report of a GFMD run: step `k` (its label from `label`) and what the solver
/// is doing.
pub fn report(steps: &mut Steps, k: usize, p: &Progress, opts: &GfmdOptions, label: impl Fn(usize) -> Option<String>) {
    if p.stage == Stage::Theory {
        // the theory reports nothing while it runs: say what the wait is for
        steps.detail("the theory on the map's spectrum");
        return;
    }
    steps.step(k, &label(k).unwrap_or_default());
    steps.detail(&format!(
        "step {}, residual {:.1e} (target {:.0e}), contact {:.4}",
        p.iteration, p.residual, opts.tolerance, p.contact_fraction
    ));
}

/// Prints a single run with its study (ladder, seeds) as the format asks, after the notes.
fn print_run(
    args: &GfmdArgs,
    out: GfmdResult,
    extrapolation: Option<Ladder>,
    ensemble: Option<Ensemble>,
) -> Result<()> {
    if let Some(r) = out.reduction.as_ref().filter(|r| !r.rescaled && r.full.gamma > 0.0) {
        eprintln!(
            "asperity gfmd: note: --raw-adhesion: gamma_glo {:.3} on this grid against {:.3} in the full system",
            r.reduced.gamma_glo, r.full.gamma_glo
        );
    }
    if out.adhesion_resolution > 0.25 {
        eprintln!(
            "asperity gfmd: note: (gamma/E*)*da/rho^2 = {:.3} > 0.25: the attraction is under-resolved on this grid \
             (physics.md §6); raise points_per_short_wavelength in the preset [gfmd] table",
            out.adhesion_resolution
        );
    }
    if let (Some(path), Some(s)) = (&args.save_surface, &out.surface) {
        super::outfile::write_bytes("--save-surface", path, s.to_text().as_bytes())?;
    }
    if args.format == GfmdFormat::Csv {
        emit(&single_csv(&out));
        return Ok(());
    }
    let mut text = match args.format {
        GfmdFormat::Table => table(&out),
        GfmdFormat::Json | GfmdFormat::Csv => String::new(),
    };
    if args.format == GfmdFormat::Table {
        if let Some(l) = &extrapolation {
            text.push_str(&ladder_table(l));
        }
        if let Some(e) = &ensemble {
            text.push_str(&ensemble_table(e));
        }
        emit(&text);
    } else if extrapolation.is_some() || ensemble.is_some() {
        let study = StudyOutput {
            base: out,
            extrapolation,
            ensemble,
        };
        emit(&serde_json::to_string_pretty(&study).expect("serialisable"));
    } else {
        emit(&serde_json::to_string_pretty(&out).expect("serialisable"));
    }
    Ok(())
}

fn pm(x: &Extrapolated) -> String {
    format!("{:.6} +- {:.1e} (finest {:.6})", x.limit, x.error, x.finest)
}

fn ladder_table(l: &Ladder) -> String {
    let mut t = String::from("\ncontinuum limit (da -> 0)\n");
    for r in &l.rungs {
        t.push_str(&format!(
            "  lambda_s/da = {:<6} N = {:<6} a_r {:.6}  sigma_c* {:.6}  u/h_rms {:.6}  ({} steps)\n",
            r.points_per_short_wavelength, r.grid, r.a_r, r.mean_contact_stress, r.mean_gap_rel, r.iterations
        ));
    }
    let mut line = |k: &str, v: String| t.push_str(&format!("{k:<28}{v}\n"));
    line("a_r (limit)", pm(&l.a_r));
    line("mean_contact_stress* (limit)", pm(&l.mean_contact_stress));
    line("contact_stress_variance*", pm(&l.contact_stress_variance));
    line("mean_gap_rel (limit)", pm(&l.mean_gap_rel));
    t
}

fn ensemble_table(e: &Ensemble) -> String {
    let mut t = format!(
        "\n{} seeds ({}), mean +- standard error\n",
        e.seeds.len(),
        if e.extrapolated {
            "continuum limits"
        } else {
            "this grid"
        }
    );
    let mut line = |k: &str, m: &MeanSe| {
        t.push_str(&format!(
            "{k:<28}{:.6} +- {:.1e}\n",
            m.mean,
            m.standard_error.unwrap_or(f64::NAN)
        ))
    };
    line("a_r", &e.a_r);
    line("mean_contact_stress*", &e.mean_contact_stress);
    line("contact_stress_variance*", &e.contact_stress_variance);
    line("mean_gap_rel", &e.mean_gap_rel);
    if let Some(x) = e.a_r_extrapolation_error {
        t.push_str(&format!("{:<28}{x:.1e}\n", "a_r extrapolation error"));
    }
    t
}

/// The full and reduced systems' invariants side by side, and what was kept.
pub fn reduction_table(r: &Reduction) -> String {
    let mut t = format!("{:<28}{:<14}{:<14}\n", "invariant", "full", "reduced (run)");
    let thick = |x: Option<f64>| x.map_or("inf".to_string(), |v| format!("{v:.4}"));
    let (e4, f4) = (|x: f64| format!("{x:.4e}"), |x: f64| format!("{x:.4}"));
    // an invariant's row: its name, then `cell` of the full and of the reduced system
    let row = |k: &'static str, cell: &dyn Fn(&Invariants) -> String| (k, cell(&r.full), cell(&r.reduced));
    for (k, a, b) in [
        row("p*", &|s| e4(s.pressure)),
        row("gamma_glo", &|s| f4(s.gamma_glo)),
        row("Tabor mu_T", &|s| f4(s.tabor)),
        row("t*q_r", &|s| thick(s.thickness_qr)),
        row("L/lambda_r", &|s| num(s.system_size_ratio)),
        row("lambda_r/lambda_s", &|s| num(s.bandwidth)),
        row("gamma/(rho E* g)", &|s| f4(s.tensile_stress)),
        row("gamma_s (J/m^2)", &|s| e4(s.gamma)),
        row("rho (m)", &|s| e4(s.range_m)),
    ] {
        t.push_str(&format!("  {k:<26}{a:<14}{b:<14}\n"));
    }
    t.push_str(&format!("{:<28}{}\n", "kept", r.kept.join(", ")));
    for n in &r.not_kept {
        t.push_str(&format!("{:<28}{n}\n", "not kept"));
    }
    t
}

/// A ratio or an input in the table: six significant digits, trailing zeros dropped (a
/// ratio computed as 200.0000000000000332 reads 200), as [`crate::numfmt`] writes numbers.
fn num(x: f64) -> String {
    crate::numfmt::format(x, 6, true)
}

/// The human-readable table of one run.
pub fn table(o: &GfmdResult) -> String {
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
    line("t*q_r", o.thickness_qr.map_or("inf (semi-infinite)".into(), num));
    line("gamma_s", format!("{} J/m^2", num(o.gamma)));
    let th = o.theory.as_ref();
    let both = |g: f64, t: Option<f64>| match t {
        Some(t) => format!(
            "{:<14}theory {}",
            crate::report::fixed(g, 6),
            crate::report::fixed(t, 6)
        ),
        None => crate::report::fixed(g, 6),
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
        format!(
            "{:.6e} m (u/h_rms = {:.6}{})",
            o.mean_gap,
            o.mean_gap_rel,
            th.and_then(|t| t.mean_gap_rel)
                .map_or(String::new(), |g| format!(", theory {g:.6}"))
        ),
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
    if let Some(r) = &o.reduction {
        t.push_str(&reduction_table(r));
    }
    t.trim_end().to_string()
}

/// A value parser for one rung of `gfmd --ladder` (λ_s/Δa in [`LADDER_RANGE`]).
pub fn ladder_rung(s: &str) -> std::result::Result<f64, String> {
    let (lo, hi) = LADDER_RANGE;
    let r = asperity::error::Range::closed(lo, hi);
    match s.trim().parse::<f64>() {
        Ok(x) if r.contains(x) => Ok(x),
        _ => Err(r.describe("lambda_s/da")),
    }
}
