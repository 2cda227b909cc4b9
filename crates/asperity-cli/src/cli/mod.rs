//! Command-line interface: `asperity [tui]`, `asperity run`, `asperity sweep`, `asperity presets`.
//!
//! The headless commands print JSON or a table to stdout; errors go to stderr as one line
//! with a non-zero exit code. Flag names and JSON keys are a public interface.

use asperity::theory::engine;
pub mod bench;
pub mod gfmd;

use asperity::error::{Error, Result};
use asperity::input::model::Model;
use asperity::input::preset::{self, Preset};
use asperity::input::scene::{Scene, SceneSummary};
use asperity::theory::persson::Accuracy;
use clap::{Args, Parser, Subcommand, ValueEnum};
use serde::Serialize;
use std::io::IsTerminal;
use std::io::Write;

pub mod sweep;

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
    /// Open the terminal explorer (the default).
    Tui {
        /// Preset name (from presets/) or path to a preset TOML file.
        #[arg(long, default_value = preset::DEFAULT_PRESET)]
        preset: String,
    },
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
    /// Model variant: 1, 2, 3, 4 or custom (default: the preset's).
    #[arg(long)]
    pub model: Option<String>,
    /// Custom model: c1 of W(a) = 1 - c1(1-a^2) - c2(1-a^4) (implies --model custom).
    #[arg(long, allow_negative_numbers = true)]
    pub c1: Option<f64>,
    /// Custom model: c2 (implies --model custom).
    #[arg(long, allow_negative_numbers = true)]
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
    #[arg(long, allow_negative_numbers = true)]
    pub thickness: Option<String>,
    /// Surface energy gamma_s in J/m^2; 0 = no adhesion.
    #[arg(long, allow_negative_numbers = true)]
    pub gamma: Option<f64>,
}

/// Arguments of `run`.
#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    /// Scene.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Reduced pressure p* = p/(E* g) (default: the preset's reference load).
    #[arg(long, allow_negative_numbers = true)]
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
    /// Adhesive solver: fixed-point tolerance max|G(a) - a|/a_r.
    #[arg(long, default_value_t = asperity::theory::adhesion::AdhesionAccuracy::default().tol)]
    pub adhesion_tol: f64,
}

/// Parses a thickness: a positive number or `inf`/`infinity`.
pub fn parse_thickness(s: &str) -> Result<f64> {
    let t = s.trim().to_ascii_lowercase();
    if matches!(t.as_str(), "inf" | "infinity" | "∞" | "+inf") {
        return Ok(f64::INFINITY);
    }
    let v: f64 = t
        .parse()
        .map_err(|_| Error::field("--thickness", s, "a number t*q_r > 0, or inf"))?;
    if !(v.is_finite() && v > 0.0) {
        return Err(Error::field("--thickness", s, "a number t*q_r > 0, or inf"));
    }
    Ok(v)
}

/// Parses `--model`.
pub fn parse_model(s: &str) -> Result<Option<Model>> {
    match s.trim() {
        "custom" => Ok(None),
        n => match n.parse::<u8>() {
            Ok(k) => Model::named(k)
                .map(Some)
                .map_err(|_| Error::field("--model", s, "1, 2, 3, 4 or custom")),
            Err(_) => Err(Error::field("--model", s, "1, 2, 3, 4 or custom")),
        },
    }
}

impl SceneArgs {
    /// Loads the preset and applies the overrides. Returns the preset too.
    pub fn resolve(&self, pressure: Option<f64>) -> Result<(Preset, Scene)> {
        let preset = Preset::resolve(&self.preset)?;
        let mut scene = preset.scene()?;
        let mut model = scene.model;
        if let Some(m) = &self.model {
            match parse_model(m)? {
                Some(named) => model = named,
                None => model.kind = asperity::input::model::ModelKind::Custom,
            }
        }
        let custom = self.c1.is_some()
            || self.c2.is_some()
            || self.alpha.is_some()
            || self.k_griffith.is_some()
            || self.cap.is_some();
        if custom {
            if self.model.as_deref().is_some_and(|m| m != "custom") {
                return Err(Error::field(
                    "--model",
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
            )
            .map_err(|e| match e {
                Error::InvalidField { field, value, allowed } => Error::InvalidField {
                    field: format!("--{}", field.trim_start_matches("model.").replace('_', "-")),
                    value,
                    allowed,
                },
                e => e,
            })?;
        }
        scene.model = model;
        if let Some(t) = &self.thickness {
            scene.thickness_qr = parse_thickness(t)?;
        }
        if let Some(g) = self.gamma {
            if !(g.is_finite() && g >= 0.0) {
                return Err(Error::field("--gamma", g, "gamma >= 0 (J/m^2; 0 = no adhesion)"));
            }
            scene.gamma = g;
        }
        if let Some(p) = pressure {
            if !p.is_finite() || p <= 0.0 {
                return Err(Error::field("--pressure", p, "a reduced pressure p* > 0"));
            }
            scene.pressure = p;
        }
        scene.validate().map_err(|e| match e {
            Error::InvalidField { field, value, allowed }
                if ["pressure", "thickness", "gamma"].contains(&field.as_str()) =>
            {
                Error::InvalidField {
                    field: format!("--{field}"),
                    value,
                    allowed,
                }
            }
            e => e,
        })?;
        Ok((preset, scene))
    }
}

/// `pr` in the JSON output.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct PrTable {
    /// σ* grid.
    pub sigma: Vec<f64>,
    /// Pr(σ*), ∫density dσ* = a_r.
    pub density: Vec<f64>,
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
    /// Relative contact area.
    pub a_r: f64,
    /// σ̄_c* (reduced by E*ḡ).
    pub mean_contact_stress: f64,
    /// ⟨δσ_c²⟩* (reduced by (E*ḡ)²).
    pub contact_stress_variance: f64,
    /// Width Δ* of the stress distribution.
    pub width: f64,
    /// Whether the solver met its tolerance.
    pub converged: bool,
    /// Estimated absolute error of a_r.
    pub error_estimate: f64,
    /// Mean gap ū (m) by the energy route [S-12]; null when unavailable (p* <= 0).
    pub mean_gap: Option<f64>,
    /// ū/h_rms; null when unavailable.
    pub mean_gap_rel: Option<f64>,
    /// Why the mean gap is null (e.g. a load on the way to full contact where the adhesive
    /// fixed point did not converge); absent when it is given.
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
    /// Fixed-point iterations of the adhesive solver (0 without adhesion).
    pub iterations: usize,
    /// Fixed-point residual max|G(a) − a|/a_r (0 without adhesion).
    pub residual: f64,
    /// "adhesionless", "loading", "loading (continuation in gamma)" or "upper (from full contact)".
    pub branch: String,
    /// a_r of a distinct unloading branch (from full contact), null if none was found.
    pub unloading_a_r: Option<f64>,
    /// γ(q)/γ_s along `resolution.q` (empty without adhesion).
    pub gamma_q: Vec<f64>,
    /// σ_a*(q) along `resolution.q` (empty without adhesion).
    pub sigma_a_q: Vec<f64>,
    /// Wall time of the solve (s).
    pub elapsed_s: f64,
    /// Resolved inputs.
    pub scene: SceneSummary,
    /// Pr(σ*).
    pub pr: PrTable,
    /// a_r(q) along the resolution.
    pub resolution: ResolutionTable,
}

/// Evaluates one scene as `run` does.
pub fn evaluate(preset_name: &str, scene: &Scene, args: &RunArgs) -> Result<RunOutput> {
    if !(args.rtol > 0.0 && args.rtol < 1e-2) {
        return Err(Error::field("--rtol", args.rtol, "0 < rtol < 1e-2"));
    }
    if args.sigma_points < 2 || args.sigma_points > 1_000_000 {
        return Err(Error::field(
            "--sigma-points",
            args.sigma_points,
            "2 <= sigma-points <= 1000000",
        ));
    }
    for (name, v) in [
        ("--adhesion-steps", args.adhesion_steps),
        ("--adhesion-points", args.adhesion_points),
    ] {
        // the error estimate halves each: keep the halves valid
        if !(4.0..=1e4).contains(&v) {
            return Err(Error::field(name, v, "4 <= value <= 10000"));
        }
    }
    if let Some(s) = args.sigma_max {
        if !(s.is_finite() && s > 0.0) {
            return Err(Error::field("--sigma-max", s, "sigma* > 0"));
        }
    }
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
    let ev = engine::evaluate(scene, &opts)?;
    // the gap needs the loading branch at every load up to full contact: report why it is
    // missing rather than failing the whole run
    let (gap, mean_gap_note) = match asperity::theory::gap::mean_gap(scene, &opts) {
        Ok(None) => (None, Some("the mean gap is defined for p* > 0 only".to_string())),
        Ok(g) => (g, None),
        Err(e) => (None, Some(format!("mean gap unavailable: {e}"))),
    };
    Ok(RunOutput {
        preset: preset_name.to_string(),
        a_r: ev.a_r,
        mean_contact_stress: ev.mean_contact_stress,
        contact_stress_variance: ev.contact_stress_variance,
        width: ev.width,
        converged: ev.converged,
        error_estimate: ev.error_estimate,
        mean_gap: gap.map(|g| g.metres),
        mean_gap_rel: gap.map(|g| g.relative),
        mean_gap_note,
        elastic_energy: ev.elastic_energy,
        sigma_a: ev.sigma_a,
        tensile_area: ev.tensile_area,
        detached_fraction: ev.detached_fraction,
        iterations: ev.iterations,
        residual: ev.residual,
        branch: ev.branch.clone(),
        unloading_a_r: ev.unloading_a_r,
        gamma_q: ev.gamma_q.clone(),
        sigma_a_q: ev.sigma_a_q.clone(),
        elapsed_s: ev.elapsed_s,
        scene: scene.summary(),
        pr: PrTable {
            sigma: ev.pr.sigma,
            density: ev.pr.density,
        },
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
    line("a_r", format!("{:.8}", out.a_r));
    line("mean_contact_stress*", format!("{:.6}", out.mean_contact_stress));
    line(
        "contact_stress_variance*",
        format!("{:.6}", out.contact_stress_variance),
    );
    line("width*", format!("{:.6}", out.width));
    line("error_estimate (a_r)", format!("{:.2e}", out.error_estimate));
    if let (Some(g), Some(r)) = (out.mean_gap, out.mean_gap_rel) {
        line("mean_gap", format!("{g:.6e} m (u/h_rms = {r:.6})"));
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
        line(
            "iterations",
            format!("{} (residual {:.1e})", out.iterations, out.residual),
        );
    }
    line("elastic_energy", format!("{:.6e} J/m^2", out.elastic_energy));
    line("converged", format!("{}", out.converged));
    line("elapsed_s", format!("{:.3e}", out.elapsed_s));
    t.trim_end().to_string()
}

/// Runs the CLI; returns the process exit code.
pub fn main() -> i32 {
    let cli = Cli::parse();
    let result = match cli.command {
        None => tui_entry(preset::DEFAULT_PRESET),
        Some(Command::Tui { preset }) => tui_entry(&preset),
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
            eprintln!("asperity: {e}");
            2
        }
    }
}

fn tui_entry(preset_name: &str) -> Result<()> {
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
    crate::tui::run(preset_name, preset)
}
