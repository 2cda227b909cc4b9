//! Command-line interface: `asperity [tui]`, `asperity run`, `asperity sweep`, `asperity presets`.
//!
//! The headless commands print JSON or a table to stdout; errors go to stderr as one line
//! with a non-zero exit code. Flag names and JSON keys are a public interface.

use asperity::contact::ContactStats;
use asperity::theory::engine;
pub mod bench;
pub mod figure;
pub mod gauge;
pub mod gauge_gfmd;
pub mod gfmd;

use asperity::error::Field;
use asperity::error::{Error, Result};
use asperity::input::model::{Model, ModelKind};
use asperity::input::preset::{self, Preset};
use asperity::input::scene::ThicknessQr;
use asperity::input::scene::{Scene, SceneSummary};
use asperity::theory::persson::Accuracy;
use clap::{Args, Parser, Subcommand, ValueEnum};
use serde::Serialize;
use std::io::IsTerminal;
use std::io::Write;

pub mod parse;
pub mod surface;
pub mod sweep;

pub use parse::{clap_error_line, count, field_name, number, render_error, whole_number, whole_number_u64};

/// asperity: explore Persson's contact-mechanics theory of rough, adhesive, elastic contacts.
#[derive(Debug, Parser)]
#[command(name = "asperity", version, about, long_about = None)]
pub struct Cli {
    /// What to do; without a subcommand the terminal explorer opens.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Open the terminal explorer (the default), on a preset or on the scene the flags give.
    Tui(TuiArgs),
    /// Open the explorer in a teaching tour (tours/NAME.toml or built in).
    Tour(TourArgs),
    /// Evaluate the theory for one scene and print the result.
    Run(RunArgs),
    /// List the available presets.
    Presets,
    /// Speed against error for every solver; the full run writes BENCHMARKS.md.
    Bench(bench::BenchArgs),
    /// Sweep the load: one row per p* with a_r, mean gap, mean contact stress, elastic energy.
    Sweep(sweep::SweepArgs),
    /// Brute-force GFMD run on a reduced grid, compared with the theory on the same surface.
    Gfmd(gfmd::GfmdArgs),
    /// A figure or table of the paper (1-8, table-1): data, a text chart, SVG/PNG (--list names them).
    Figure(figure::FigureArgs),
    /// Fit coefficients of the custom model (c1, c2, alpha, k_griffith, w0) to reference data.
    Gauge(gauge::GaugeArgs),
    /// Every model (1-4, yp08, xu24, fitted presets) against a reference set: relative errors and an overlay.
    Compare(gauge::CompareArgs),
    /// The PSD of a measured height map: radial average, h_rms, rms gradient and curvature, self-affine fit.
    Psd(surface::PsdArgs),
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
    /// Model variant: 1, 2, 3, 4, custom, yp08 or xu24 (default: the preset's; yp08 and xu24
    /// are defined for the adhesionless half-space: --gamma 0 --thickness inf).
    #[arg(long, allow_hyphen_values = true, value_parser = parse::model)]
    pub model: Option<String>,
    /// Fitting parameter gamma_f of yp08/xu24: S(a) = gamma_f + (1 - gamma_f) a^2 (yp08) or a (xu24).
    #[arg(long, allow_hyphen_values = true)]
    pub fudge_gamma: Option<f64>,
    /// Custom model: c1 of W(a) = 1 - c1(1-a^2) - c2(1-a^4) (implies --model custom).
    #[arg(long, allow_hyphen_values = true, value_parser = number(Field::C1))]
    pub c1: Option<f64>,
    /// Custom model: c2 (implies --model custom).
    #[arg(long, allow_hyphen_values = true, value_parser = number(Field::C2))]
    pub c2: Option<f64>,
    /// Custom model: broadening exponent alpha, dp ~ W^alpha (implies --model custom).
    #[arg(long, allow_hyphen_values = true, value_parser = number(Field::Alpha))]
    pub alpha: Option<f64>,
    /// Custom model: Griffith prefactor k_G (implies --model custom).
    #[arg(long, allow_hyphen_values = true, value_parser = number(Field::KGriffith))]
    pub k_griffith: Option<f64>,
    /// Custom model: cap sigma_a at gamma_s/rho (true/false; implies --model custom).
    #[arg(long, allow_hyphen_values = true)]
    pub cap: Option<bool>,
    /// Thickness t*q_r, or inf for a semi-infinite body (default: the preset's).
    #[arg(long, allow_hyphen_values = true, value_parser = parse::thickness)]
    pub thickness: Option<String>,
    /// Surface energy gamma_s in J/m^2; 0 = no adhesion.
    #[arg(long, allow_hyphen_values = true, value_parser = number(Field::SurfaceEnergy))]
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
    #[arg(long, allow_hyphen_values = true, value_parser = number(Field::Pressure))]
    pub pressure: Option<f64>,
}

/// Arguments of `tour`.
#[derive(Debug, Clone, Args)]
pub struct TourArgs {
    /// Tour name (from tours/ or built in) or path to a tour TOML file.
    #[arg(default_value = crate::tui::tour::DEFAULT_TOUR, allow_hyphen_values = true)]
    pub tour: String,
    /// Step to start at (1 = the first).
    #[arg(long, default_value_t = 1, allow_hyphen_values = true, value_parser = parse::step)]
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
    #[arg(long, allow_hyphen_values = true, value_parser = number(Field::Pressure))]
    pub pressure: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Json, allow_hyphen_values = true)]
    pub format: Format,
    /// Number of sigma* points of the Pr(sigma*) table.
    #[arg(long, default_value_t = 201, allow_hyphen_values = true, value_parser = count(Field::SigmaPoints))]
    pub sigma_points: usize,
    /// Largest sigma* of the Pr table (default p* + 5 times the distribution's width).
    #[arg(long, allow_hyphen_values = true, value_parser = number(Field::SigmaMax))]
    pub sigma_max: Option<f64>,
    /// Relative tolerance of the variance ODE (accuracy knob).
    #[arg(long, default_value_t = Accuracy::default().rtol, allow_hyphen_values = true, value_parser = number(Field::Rtol))]
    pub rtol: f64,
    /// Adhesive solver: march steps per unit of ln q (accuracy knob; see BENCHMARKS.md).
    #[arg(long, default_value_t = asperity::theory::adhesion::AdhesionAccuracy::default().steps_per_ln_q, allow_hyphen_values = true, value_parser = number(Field::AdhesionSteps))]
    pub adhesion_steps: f64,
    /// Adhesive solver: grid points per standard deviation of Pr (accuracy knob).
    #[arg(long, default_value_t = asperity::theory::adhesion::AdhesionAccuracy::default().points_per_width, allow_hyphen_values = true, value_parser = number(Field::AdhesionPoints))]
    pub adhesion_points: f64,
    /// Adhesive solver: self-consistency tolerance |gamma(q_s)/gamma_s - 1| at each root.
    #[arg(long, default_value_t = asperity::theory::adhesion::AdhesionAccuracy::default().tol, allow_hyphen_values = true, value_parser = number(Field::AdhesionTol))]
    pub adhesion_tol: f64,
}

impl SceneArgs {
    /// Loads the preset and applies the overrides. Returns the preset too.
    pub fn resolve(&self, pressure: Option<f64>) -> Result<(Preset, Scene)> {
        let preset = Preset::resolve(&self.preset)?;
        let mut scene = preset.scene()?;
        let mut model = scene.model;
        if let Some(m) = &self.model {
            model = match m.parse::<ModelKind>()? {
                ModelKind::Custom => Model {
                    kind: ModelKind::Custom,
                    ..model
                },
                kind => Model::of_kind(kind, &model)?,
            };
        }
        let custom = self.c1.is_some()
            || self.c2.is_some()
            || self.alpha.is_some()
            || self.k_griffith.is_some()
            || self.cap.is_some();
        if custom {
            if self.model.as_deref().is_some_and(|m| m != "custom") {
                return Err(Error::invalid_text(
                    Field::Model,
                    self.model.as_deref().unwrap_or(""),
                    "custom when --c1/--c2/--alpha/--k-griffith/--cap are given",
                ));
            }
            model = Model::custom(
                self.c1.unwrap_or(model.c1),
                self.c2.unwrap_or(model.c2),
                self.alpha.unwrap_or(model.alpha),
                self.k_griffith.unwrap_or(model.k_griffith),
                self.cap.unwrap_or(model.cap),
            )?;
        }
        if let Some(g) = self.fudge_gamma {
            if !model.kind.is_fudge_variant() {
                return Err(Error::invalid_text(
                    Field::Model,
                    model.kind.name(),
                    "yp08 or xu24 when --fudge-gamma is given",
                ));
            }
            model = Model::fudge(model.kind, g)?;
        }
        scene.model = model;
        if let Some(t) = &self.thickness {
            scene.thickness_qr = t.parse::<ThicknessQr>()?.0;
        }
        if let Some(g) = self.gamma {
            scene.gamma = g;
        }
        if let Some(p) = pressure {
            scene.pressure = p;
        }
        if let Some(spectrum) = self.source.spectrum()? {
            scene.spectrum = spectrum;
        }
        scene.validate()?;
        Ok((preset, scene))
    }
}

/// `resolution` in the JSON output.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ResolutionTable {
    /// q (1/m).
    pub q: Vec<f64>,
    /// a_r(q).
    pub a_r: Vec<f64>,
}

/// The JSON object printed by `asperity run`.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RunOutput {
    /// Preset name.
    pub preset: String,
    /// `a_r`, `mean_contact_stress` (reduced by E*ḡ), `contact_stress_variance` (by (E*ḡ)²)
    /// and `pr` = {`sigma`, `density`}, ∫density dσ* = a_r.
    #[serde(flatten)]
    pub stats: ContactStats,
    /// Width Δ* of the stress distribution.
    pub width: f64,
    /// Whether the solver met its tolerance.
    pub converged: bool,
    /// Estimated absolute error of a_r.
    pub error_estimate: f64,
    /// Mean gap ū (m) of the loading branch: the adhesionless gap [S-12] at the load the
    /// branch's contact carries (without adhesion: the energy route itself; docs/physics.md §5.1); null
    /// when unavailable.
    pub mean_gap: Option<f64>,
    /// ū/h_rms; null when unavailable.
    pub mean_gap_rel: Option<f64>,
    /// Lower end of ū/h_rms's bracket: the adhesionless gap at the load that gives the same
    /// a_r (no higher than `mean_gap_rel`); equal to `mean_gap_rel` without adhesion; null
    /// when the gap is.
    pub mean_gap_lower_rel: Option<f64>,
    /// Upper end of the bracket: the adhesionless gap at the same load; null when the gap is.
    pub mean_gap_upper_rel: Option<f64>,
    /// Estimated absolute error of `mean_gap_rel` (quadrature and interpolation); null when
    /// the gap is.
    pub mean_gap_error: Option<f64>,
    /// p_c*: the net force the loading branch's contact carries per nominal area, ∫σ*Pr dσ*
    /// (p* plus the tension of the contact edges; p* without adhesion); null when the gap is.
    pub contact_load: Option<f64>,
    /// One line saying what `mean_gap_rel` is.
    pub mean_gap_about: String,
    /// Why the mean gap is null (e.g. a load on the way to full contact where the adhesive
    /// solve did not converge); absent when it is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean_gap_note: Option<String>,
    /// Elastic energy U per nominal area (J/m²) [S-11].
    pub elastic_energy: f64,
    /// σ_a*(q_s): the adhesive wall at σ* = −σ_a* (0 without adhesion).
    pub sigma_a: f64,
    /// Contact area under tension, ∫_{−σ_a}^0 Pr dσ*.
    pub tensile_area: f64,
    /// 1 − a_r: the fraction that left the contact through the wall.
    pub detached_fraction: f64,
    /// Marches of the adhesive solver (0 without adhesion).
    pub iterations: usize,
    /// Self-consistency residual |γ(q_s)/γ_s − 1| (0 without adhesion).
    pub residual: f64,
    /// "adhesionless", or "loading": the branch a loading history reaches.
    pub branch: String,
    /// a_r of a distinct unloading branch (the highest stable one), null if none.
    pub unloading_a_r: Option<f64>,
    /// Every branch at this load, lowest a_r first: branch ("loading", "unstable",
    /// "unloading"), stable, a_r, sigma_a, gamma_coarse (γ(q_L)/γ_s), elastic_energy,
    /// residual (the branch's |γ(q_s)/γ_s − 1|), mean_gap_rel, mean_gap_reversible_rel,
    /// mean_gap_lower_rel, mean_gap_upper_rel, mean_gap_error, contact_load. Empty
    /// without adhesion.
    pub branches: Vec<RunBranch>,
    /// Inside a hysteresis window (two stable branches at this load): p* above which the
    /// loading branch no longer exists (jump into contact); null outside a window or when
    /// the window runs past the allowed range of p*.
    pub jump_in_pressure: Option<f64>,
    /// Inside a hysteresis window: p* below which the unloading branch no longer exists
    /// (pull-off); null outside a window or when it runs past the allowed range.
    pub pull_off_pressure: Option<f64>,
    /// γ(q)/γ_s along `resolution.q` (empty without adhesion).
    pub gamma_q: Vec<f64>,
    /// σ_a*(q) along `resolution.q` (empty without adhesion).
    pub sigma_a_q: Vec<f64>,
    /// Wall time of the whole computation of the command (s): the solve with its error
    /// estimate, the hysteresis window and the mean gap (the parts follow).
    pub elapsed_s: f64,
    /// Wall time of the solve at p* with its error estimate (s).
    pub elapsed_solve_s: f64,
    /// Wall time of the hysteresis window's edges (s; 0 outside a window).
    pub elapsed_window_s: f64,
    /// Wall time of the mean gap (s).
    pub elapsed_gap_s: f64,
    /// Resolved inputs.
    pub scene: SceneSummary,
    /// a_r(q) along the resolution.
    pub resolution: ResolutionTable,
}

/// One branch in `run`'s `branches`: its state and its mean gap.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RunBranch {
    /// branch, stable, a_r, sigma_a, gamma_coarse, elastic_energy, residual.
    #[serde(flatten)]
    pub state: asperity::theory::adhesion::BranchState,
    /// ū/h_rms of this branch: the adhesionless gap at the load its contact carries (docs/physics.md
    /// §5.1); null for an unstable branch (no quasi-static path follows it) or when
    /// unavailable.
    pub mean_gap_rel: Option<f64>,
    /// The adhesionless gap at the same load (the bracket's upper end, the same for every
    /// branch: the dissipation-free route [S-12] of the scene without adhesion); null as
    /// `mean_gap_rel`.
    pub mean_gap_reversible_rel: Option<f64>,
    /// The bracket's lower end: the adhesionless gap at the load with this branch's a_r;
    /// null as `mean_gap_rel`.
    pub mean_gap_lower_rel: Option<f64>,
    /// The bracket's upper end (= `mean_gap_reversible_rel`); null as `mean_gap_rel`.
    pub mean_gap_upper_rel: Option<f64>,
    /// Estimated absolute error of `mean_gap_rel`; null as `mean_gap_rel`.
    pub mean_gap_error: Option<f64>,
    /// The net force the branch's contact carries per nominal area, ∫σ*Pr dσ*; null as
    /// `mean_gap_rel`.
    pub contact_load: Option<f64>,
}

/// The branches of an evaluation with their gaps (`gap`: the run's mean gap, which holds the
/// loading branch's and, inside a hysteresis window, the unloading branch's).
fn run_branches(ev: &engine::Evaluation, gap: Option<&asperity::theory::gap::MeanGap>) -> Vec<RunBranch> {
    use asperity::theory::adhesion::Branch;
    use asperity::theory::gap::BranchGap;
    ev.branches
        .iter()
        .map(|b| {
            let g: Option<BranchGap> = match (b.branch, gap) {
                (Branch::Loading, Some(g)) if b.stable => Some(BranchGap {
                    relative: g.relative,
                    error: g.error,
                    lower: g.lower,
                    upper: g.upper,
                    contact_load: g.contact_load,
                }),
                (Branch::Unloading, Some(g)) => g.unloading,
                _ => None,
            };
            RunBranch {
                state: b.clone(),
                mean_gap_rel: g.map(|g| g.relative),
                mean_gap_reversible_rel: g.map(|g| g.upper),
                mean_gap_lower_rel: g.map(|g| g.lower),
                mean_gap_upper_rel: g.map(|g| g.upper),
                mean_gap_error: g.map(|g| g.error),
                contact_load: g.map(|g| g.contact_load),
            }
        })
        .collect()
}

/// What `mean_gap_rel` is, in one line.
pub fn mean_gap_about(adhesive: bool) -> String {
    if adhesive {
        "mean_gap_rel: the adhesionless gap at the load the branch's contact carries (p* + the pull of its edges) \
         (docs/physics.md 5.1), bracketed by the adhesionless gap at the load with the same a_r \
         (lower) and at the same load (upper)"
            .into()
    } else {
        "mean_gap_rel: the energy route of Persson theory, integral of dU/p from p* to full contact [S-12]".into()
    }
}

/// Evaluates one scene as `run` does.
pub fn evaluate(preset_name: &str, scene: &Scene, args: &RunArgs) -> Result<RunOutput> {
    let opts = engine::Options {
        accuracy: Accuracy {
            rtol: args.rtol,
            ..Accuracy::default()
        },
        sigma_points: args.sigma_points,
        sigma_max: args.sigma_max,
        adhesion: asperity::theory::adhesion::AdhesionAccuracy {
            steps_per_ln_q: args.adhesion_steps,
            points_per_width: args.adhesion_points,
            tol: args.adhesion_tol,
            ..asperity::theory::adhesion::AdhesionAccuracy::default()
        },
        ..engine::Options::default()
    };
    opts.validate()?;
    let t0 = std::time::Instant::now();
    let ev = engine::evaluate(scene, &opts)?;
    let t_solve = t0.elapsed().as_secs_f64();
    // inside a hysteresis window: its edges (a few more solves, only then)
    let window = match ev.adhesive.as_deref() {
        Some(sol) if ev.branches.iter().filter(|b| b.stable).count() >= 2 => {
            asperity::theory::hysteresis::window_around_from(scene, sol, &opts.adhesion, None)?
        }
        _ => None,
    };
    let t_window = t0.elapsed().as_secs_f64();
    // the gap of each branch from its own state at this load and the adhesionless table of
    // the scene: report why it is missing rather than failing the whole run
    let (gap, mean_gap_note) = match asperity::theory::gap::mean_gap_of(scene, &ev, &opts) {
        Ok(g) => (Some(g), None),
        Err(e) => (None, Some(format!("mean gap unavailable: {e}"))),
    };
    let elapsed_s = t0.elapsed().as_secs_f64();
    Ok(RunOutput {
        preset: preset_name.to_string(),
        stats: ev.stats.clone(),
        width: ev.width,
        // a solver that misses its tolerance returns an error, never a result
        converged: true,
        error_estimate: ev.error_estimate,
        mean_gap: gap.map(|g| g.metres),
        mean_gap_rel: gap.map(|g| g.relative),
        mean_gap_lower_rel: gap.map(|g| g.lower),
        mean_gap_upper_rel: gap.map(|g| g.upper),
        mean_gap_error: gap.map(|g| g.error),
        contact_load: gap.map(|g| g.contact_load),
        mean_gap_about: mean_gap_about(scene.gamma > 0.0),
        mean_gap_note,
        elastic_energy: ev.elastic_energy,
        sigma_a: ev.sigma_a,
        tensile_area: ev.tensile_area,
        detached_fraction: ev.detached_fraction,
        iterations: ev.iterations,
        residual: ev.residual,
        branch: ev.branch.to_string(),
        unloading_a_r: ev.unloading_a_r,
        branches: run_branches(&ev, gap.as_ref()),
        jump_in_pressure: window.and_then(|w| w.jump_in_pressure),
        pull_off_pressure: window.and_then(|w| w.pull_off_pressure),
        gamma_q: ev.gamma_q.clone(),
        sigma_a_q: ev.sigma_a_q.clone(),
        elapsed_s,
        elapsed_solve_s: t_solve,
        elapsed_window_s: t_window - t_solve,
        elapsed_gap_s: elapsed_s - t_window,
        scene: scene.summary(),
        resolution: ResolutionTable {
            q: ev.resolution.iter().map(|r| r.q).collect(),
            a_r: ev.resolution.iter().map(|r| r.a_r).collect(),
        },
    })
}

/// Writes a line to stdout; a closed pipe (`asperity run | head`) is not an error.
pub fn emit(text: &str) {
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "{text}");
}

fn run_table(out: &RunOutput) -> String {
    let s = &out.scene;
    let mut t = String::new();
    let mut line = |k: &str, v: String| t.push_str(&format!("{k:<28}{v}\n"));
    line("preset", out.preset.clone());
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
    line("gamma_s", format!("{} J/m^2 (gamma_glo = {:.4})", s.gamma, s.gamma_glo));
    line("a_r", format!("{:.8}", out.stats.a_r));
    line("mean_contact_stress*", format!("{:.6}", out.stats.mean_contact_stress));
    line(
        "contact_stress_variance*",
        format!("{:.6}", out.stats.contact_stress_variance),
    );
    line("width*", format!("{:.6}", out.width));
    line("error_estimate (a_r)", format!("{:.2e}", out.error_estimate));
    if let (Some(g), Some(r)) = (out.mean_gap, out.mean_gap_rel) {
        let err = out.mean_gap_error.map_or(String::new(), |e| format!(" +- {e:.1e}"));
        line("mean_gap", format!("{g:.6e} m (u/h_rms = {r:.6}{err})"));
        if let (Some(lo), Some(hi), true) = (
            out.mean_gap_lower_rel,
            out.mean_gap_upper_rel,
            out.branch != "adhesionless",
        ) {
            line(
                "mean_gap bracket",
                format!(
                    "{lo:.6} <= u/h_rms <= {hi:.6} (same a_r / same load without adhesion); contact load p_c* = {:.4e}",
                    out.contact_load.unwrap_or(f64::NAN)
                ),
            );
        }
        line("mean_gap is", out.mean_gap_about.clone());
    } else if let Some(n) = &out.mean_gap_note {
        line("mean_gap", n.clone());
    }
    if out.branch != "adhesionless" {
        line("sigma_a*", format!("{:.6} (wall at sigma* = -sigma_a*)", out.sigma_a));
        line("tensile_area", format!("{:.6e}", out.tensile_area));
        line("branch", out.branch.clone());
        if let Some(u) = out.unloading_a_r {
            line("unloading_a_r", format!("{u:.8} (a second, unloading branch)"));
        }
        if out.branches.len() > 1 {
            let list: Vec<String> = out
                .branches
                .iter()
                .map(|b| {
                    let gap = b.mean_gap_rel.map_or(String::new(), |g| format!(" u/h_rms = {g:.4}"));
                    format!(
                        "{} a_r = {:.6} sigma_a* = {:.4}{gap}",
                        b.state.branch, b.state.a_r, b.state.sigma_a
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
    line("converged", format!("{}", out.converged));
    line(
        "elapsed_s",
        format!(
            "{:.3e} (solve {:.3e}, window {:.3e}, gap {:.3e})",
            out.elapsed_s, out.elapsed_solve_s, out.elapsed_window_s, out.elapsed_gap_s
        ),
    );
    t.trim_end().to_string()
}

/// Runs the CLI; returns the process exit code.
pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
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
            eprintln!("asperity: {}", clap_error_line(&e));
            return 2;
        }
    };
    let result = match cli.command {
        None => tui_entry(preset::DEFAULT_PRESET, None, None),
        Some(Command::Tui(args)) => args
            .scene
            .resolve(args.pressure)
            .and_then(|(_, scene)| tui_entry(&args.scene.preset, Some(scene), None)),
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
        Some(Command::Sweep(args)) => sweep::run(&args).map(|text| emit(&text)),
        Some(Command::Gfmd(args)) => gfmd::run(&args),
        Some(Command::Figure(args)) => figure::run(&args),
        Some(Command::Gauge(args)) => gauge::run(&args),
        Some(Command::Compare(args)) => gauge::compare(&args),
        Some(Command::Psd(args)) => surface::run_psd(&args),
        Some(Command::Run(args)) => args.scene.resolve(args.pressure).and_then(|(preset, scene)| {
            let out = evaluate(&preset.name, &scene, &args)?;
            match args.format {
                Format::Json => emit(&serde_json::to_string_pretty(&out).expect("serialisable")),
                Format::Table => emit(&run_table(&out)),
            }
            Ok(())
        }),
    };
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("asperity: {}", render_error(&e));
            2
        }
    }
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
    let t = Tour::resolve(&args.tour)?;
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
    tui_entry(&source, None, Some((t, args.step as usize - 1)))
}

fn tui_entry(
    preset_name: &str,
    scene: Option<asperity::input::scene::Scene>,
    tour: Option<(crate::tui::tour::Tour, usize)>,
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
    if let Some(s) = scene {
        app.base = s.clone();
        app.scene = s;
    }
    if let Some((t, step)) = tour {
        app.start_tour(t, step);
    }
    crate::tui::run_app(app)
}
