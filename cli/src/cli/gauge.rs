//! `asperity gauge`: fit coefficients of the custom model to reference data
//! ([`asperity::fit`]), and `asperity compare`: every model against a reference set.
//!
//! ```text
//! asperity gauge --fit c1,c2[,alpha,k_griffith,w0] --reference eq18|gfmd|FILE.csv
//!                [--from P --to P --points N] [--pr FILE.csv] [--observables LIST] [scene flags]
//!                [--grid N --seed S --seeds K --extrapolate --ladder 4,8,16 --method M
//!                 --save-reference FILE.csv]   (gfmd only)
//!                [--format table|json] [--svg FILE] [--png FILE] [--save-preset FILE]
//! ```
//!
//! With `--reference eq18` the scene is made adhesionless and semi-infinite (the closed form
//! [S-18] describes only that case); with `--reference gfmd` it becomes the reduced scene that
//! GFMD runs ([`super::gauge_gfmd`]); a file reference is compared on the scene as given.

use super::gauge_gfmd::{self, GfmdRefArgs};
use super::{emit, Format, SceneArgs};
use crate::chart::{self, Chart, Scale, Series, SeriesStyle};
use crate::looks;
use asperity::error::{Error, Field, Result};
use asperity::fit::gfmd_reference::GfmdReference;
use asperity::fit::reference::{self, Observable, Reference};
use asperity::fit::{self, Fit, Param};
use asperity::input::model::Model;
use asperity::input::preset::{ModelSpec, Preset};
use asperity::input::scene::Scene;
use asperity::report::{self, gauge};
use clap::Args;
use std::path::{Path, PathBuf};

/// Reference options shared by `gauge` and `compare`.
#[derive(Debug, Clone, Args)]
pub struct ReferenceArgs {
    /// eq18 (the closed form [S-18] over --from..--to), gfmd (a GFMD load sweep of the scene
    /// over --from..--to) or a CSV file with columns p, a_r, a_r_err,
    /// mean_contact_stress(_err), mean_gap_rel(_err).
    #[arg(long)]
    pub reference: String,
    /// First p* of --reference eq18 (default 1e-3) or gfmd (default p*/2.5).
    #[arg(long)]
    pub from: Option<f64>,
    /// Last p* of --reference eq18 (default 1) or gfmd (default p*·2.5).
    #[arg(long)]
    pub to: Option<f64>,
    /// Number of log-spaced loads of --reference eq18 (default 31) or gfmd (default 4).
    #[arg(long)]
    pub points: Option<usize>,
    /// Pr(sigma*) histograms: a CSV file with columns p, sigma, density.
    #[arg(long)]
    pub pr: Option<PathBuf>,
    /// Fit only these observables of the reference: a comma-separated list of a_r,
    /// mean_contact_stress, mean_gap_rel, pr (default: all it holds).
    #[arg(long)]
    pub observables: Option<String>,
    /// GFMD options of --reference gfmd.
    #[command(flatten)]
    pub gfmd: GfmdRefArgs,
}

/// Arguments of `gauge`.
#[derive(Debug, Clone, Args)]
pub struct GaugeArgs {
    /// Scene (its model is the starting point).
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The coefficients to fit: a comma-separated list of c1, c2, alpha, k_griffith, w0.
    #[arg(long)]
    pub fit: String,
    /// The reference.
    #[command(flatten)]
    pub reference: ReferenceArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Write the before/after chart as SVG.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Write the before/after chart as PNG.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write a preset with the fitted custom model (the scene's preset otherwise).
    #[arg(long)]
    pub save_preset: Option<PathBuf>,
}

/// A file's cell error (`name: line N, column C`) under the flag that named the file.
fn under_flag(e: Error, flag: &str) -> Error {
    match e {
        Error::Invalid {
            field: Field::Other(k),
            value,
            allowed,
        } if !k.starts_with("--") => Error::Invalid {
            field: Field::Other(format!("{flag} {k}")),
            value,
            allowed,
        },
        e => e,
    }
}

/// The reference and the scene it is compared on (for `gfmd`, the scene GFMD runs), with the
/// GFMD run when it is one.
pub fn resolve_reference(
    args: &ReferenceArgs,
    preset: &Preset,
    scene_args: &SceneArgs,
    scene: &mut Scene,
) -> Result<(Reference, Option<GfmdReference>)> {
    if args.reference != "gfmd" {
        args.gfmd.refuse_unless_gfmd(&args.reference)?;
    }
    let loads = (args.from, args.to, args.points);
    let (mut r, gfmd) = if args.reference == "gfmd" {
        let map = scene_args.source.map()?;
        let g = gauge_gfmd::resolve(&args.gfmd, loads, preset, map, scene)?;
        (g.reference.clone(), Some(g))
    } else {
        let (r, sc) = gauge::reference(&args.reference, None, loads, scene).map_err(|e| {
            if args.reference == "eq18" {
                e
            } else {
                under_flag(e, "--reference")
            }
        })?;
        *scene = sc;
        (r, None)
    };
    if let Some(pr) = &args.pr {
        let (text, name) = gauge::read_table(pr, "pr")?;
        r.points
            .extend(reference::parse_pr_csv(&text, &name).map_err(|e| under_flag(e, "--pr"))?);
    }
    if let Some(list) = &args.observables {
        let keys: Vec<&str> = list.split(',').collect();
        gauge::keep_observables(&mut r, &keys).map_err(|e| match e {
            Error::Invalid { value, .. } => Error::field(
                "--observables",
                value,
                "a comma-separated list of a_r, mean_contact_stress, mean_gap_rel, pr held by the reference",
            ),
            e => e,
        })?;
    }
    Ok((r, gfmd))
}

/// The JSON object printed by `gauge --format json` (the library's report).
pub use asperity::report::gauge::GaugeReport as GaugeOutput;

/// Runs `asperity gauge`.
pub fn run(args: &GaugeArgs) -> Result<()> {
    let params = Param::parse_list(&args.fit)?;
    let (preset, mut scene) = args.scene.resolve(None)?;
    let (r, gfmd) = resolve_reference(&args.reference, &preset, &args.scene, &mut scene)?;
    let f = fit::fit(&scene, &r, &params)?;
    if args.svg.is_some() || args.png.is_some() {
        let models = [("before", f.start), ("after", f.model)];
        let spec = overlay(&scene, &r, &models, "gauge")?;
        write_charts(&spec, args.svg.as_deref(), args.png.as_deref())?;
    }
    let saved = match &args.save_preset {
        Some(path) => {
            save_preset(&preset, &scene, &f.model, path)?;
            Some(path.display().to_string())
        }
        None => None,
    };
    match args.format {
        Format::Json => {
            let out = GaugeOutput {
                reference: r.name.clone(),
                gfmd,
                fit: f,
                saved_preset: saved,
            };
            emit(&serde_json::to_string_pretty(&out).expect("serialisable"));
        }
        Format::Table => {
            let head = gfmd.as_ref().map_or(String::new(), gauge_gfmd::table);
            emit(&(head + &table(&r, &f, saved.as_deref())))
        }
    }
    Ok(())
}

fn table(r: &Reference, f: &Fit, saved: Option<&str>) -> String {
    let mut t = format!(
        "reference {} ({} points), starting from c1 = {}, c2 = {}, alpha = {}, k_G = {}\n\n",
        r.name, f.points, f.start.c1, f.start.c2, f.start.alpha, f.start.k_griffith
    );
    t += &format!(
        "{:<12} {:>14} {:>12} {:>12}\n",
        "parameter", "value", "std_error", "start"
    );
    for p in &f.params {
        t += &format!(
            "{:<12} {:>14.6} {:>12.2e} {:>12.6}\n",
            p.name, p.value, p.std_error, p.start
        );
    }
    if f.params.len() > 1 {
        t += "\ncorrelation\n";
        for (p, row) in f.params.iter().zip(&f.correlation) {
            t += &format!("{:<12}", p.name);
            for c in row {
                t += &format!(" {c:>8.4}");
            }
            t += "\n";
        }
    }
    t += &format!(
        "\n{:<20} {:>6} {:>12} {:>12} {:>12}\n",
        "observable", "points", "rms", "max |r|", "rms start"
    );
    for o in &f.residuals {
        t += &format!(
            "{:<20} {:>6} {:>12.3e} {:>12.3e} {:>12.3e}\n",
            o.observable, o.points, o.rms, o.max_abs, o.rms_start
        );
    }
    t += "(residuals relative to the value, or in standard errors where the reference gives them)\n";
    t += &format!("\nchi2 {:.4e}", f.chi2);
    if let Some(c) = f.chi2_reduced {
        t += &format!(", reduced chi2 {c:.4}");
    }
    t += &format!(
        "; condition number {:.3e}; {} evaluations in {:.2} s ({})\n",
        f.condition_number, f.evaluations, f.elapsed_s, f.termination
    );
    if let Some(s) = saved {
        t += &format!("preset written: {s}\n");
    }
    t
}

/// Writes a preset: the scene's preset with the scene's load, thickness, modulus, adhesion,
/// self-affine spectrum (the reduced one of `--reference gfmd`) and `model`.
pub fn save_preset(base: &Preset, scene: &Scene, model: &Model, path: &Path) -> Result<()> {
    let mut p = base.clone();
    p.load.pressure = scene.pressure();
    p.load.thickness_qr = scene.thickness_qr();
    p.material.contact_modulus_pa = scene.contact_modulus_pa();
    p.adhesion.surface_energy_j_m2 = scene.surface_energy_j_m2();
    p.adhesion.range_m = scene.range_m();
    if let asperity::surface::spectrum::Spectrum::SelfAffine(sa) = &scene.spectrum() {
        p.surface.system_size_m = sa.system_size;
        p.surface.rolloff_wavelength_m = sa.lambda_r;
        p.surface.short_wavelength_m = sa.lambda_s;
        p.surface.hurst = sa.hurst;
        p.surface.rms_gradient = Some(scene.spectrum().rms_gradient());
        p.surface.rms_height_m = None;
    }
    p.model = ModelSpec::of_model(model);
    p.name = path
        .file_stem()
        .map_or("gauged".into(), |s| s.to_string_lossy().into_owned());
    p.description = format!("{} (model gauged by asperity gauge)", base.description);
    let text = toml::to_string(&p).map_err(|e| Error::io("write preset", e))?;
    // the preset must read back as written
    Preset::parse(&text, &path.display().to_string())?;
    super::outfile::write_bytes("--save-preset", path, text.as_bytes())
}

fn y_of(o: Observable, p: f64, v: f64) -> f64 {
    if o == Observable::Area {
        v / p
    } else {
        v
    }
}

/// The reference as points and each model as a line, one chart per observable stacked in
/// one figure's series (a_r shown as a_r/p* like \[S\] Fig. 1).
pub fn overlay(scene: &Scene, r: &Reference, models: &[(&str, Model)], what: &str) -> Result<Chart> {
    let obs: Vec<Observable> = r.observables().into_iter().filter(|o| *o != Observable::Pr).collect();
    let first = obs.first().copied().unwrap_or(Observable::Area);
    let (lo, hi) = {
        let l = r.loads();
        (l[0], l[l.len() - 1])
    };
    let n = 61;
    let grid: Vec<f64> = if hi > lo {
        (0..n)
            .map(|i| (lo.ln() + (hi / lo).ln() * i as f64 / (n - 1) as f64).exp())
            .collect()
    } else {
        vec![lo]
    };
    let dense = Reference {
        name: "grid".into(),
        points: grid
            .iter()
            .map(|&p| reference::Observation {
                p,
                observable: first,
                value: 1.0,
                error: None,
                sigma: 0.0,
            })
            .collect(),
    };
    let mut series = vec![Series::new(
        format!("reference {}", r.name),
        r.points
            .iter()
            .filter(|o| o.observable == first)
            .map(|o| (o.p, y_of(first, o.p, o.value)))
            .collect(),
        looks::Role::Reference,
        SeriesStyle::Points,
    )];
    for (label, m) in models {
        let y = fit::predict(scene, m, &dense)?;
        series.push(Series::new(
            *label,
            grid.iter().zip(&y).map(|(&p, &v)| (p, y_of(first, p, v))).collect(),
            looks::Role::Model(looks::model_slot(m)),
            SeriesStyle::Line,
        ));
    }
    let y_label = match first {
        Observable::Area => "a_r / p*",
        Observable::MeanContactStress => "mean contact stress / (E* g)",
        Observable::MeanGapRel => "mean gap / h_rms",
        Observable::Pr => "Pr",
    };
    let mut c = Chart::new(
        format!("asperity {what}: {} against {}", y_label, r.name),
        "p* = p / (E* g)",
        y_label,
        Scale::of(hi > lo),
        Scale::Linear,
    );
    c.series = series;
    // two custom models (the start and the fit) share a colour: the second is dashed
    c.tell_apart();
    Ok(c)
}

/// Writes the chart files asked for.
pub fn write_charts(spec: &Chart, svg: Option<&Path>, png: Option<&Path>) -> Result<()> {
    if let Some(p) = svg {
        super::outfile::write("--svg", p, |tmp| chart::write_svg(spec, tmp))?;
    }
    if let Some(p) = png {
        super::outfile::write("--png", p, |tmp| chart::write_png(spec, tmp))?;
    }
    Ok(())
}

/// Arguments of `compare`.
#[derive(Debug, Clone, Args)]
pub struct CompareArgs {
    /// Scene.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The reference.
    #[command(flatten)]
    pub reference: ReferenceArgs,
    /// The models: a comma-separated list of 1, 2, 3, 4, 5, yp08, xu24.
    #[arg(long, default_value = "1,2,3,4,yp08,xu24")]
    pub models: String,
    /// Presets whose model joins the comparison (e.g. one written by gauge --save-preset).
    #[arg(long, value_delimiter = ',')]
    pub fitted: Vec<PathBuf>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Write the overlay chart as SVG.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Write the overlay chart as PNG.
    #[arg(long)]
    pub png: Option<PathBuf>,
}

/// The JSON object printed by `compare --format json` (the library's report).
pub use asperity::report::compare::CompareReport as CompareOutput;

/// Runs `asperity compare`.
pub fn compare(args: &CompareArgs) -> Result<()> {
    let (preset, mut scene) = args.scene.resolve(None)?;
    let (r, _) = resolve_reference(&args.reference, &preset, &args.scene, &mut scene)?;
    let mut models = report::compare::models(&args.models, &scene.model(), &Field::Other("--models".into()))?;
    for p in &args.fitted {
        let preset = Preset::load(p).map_err(|e| super::parse::preset_under_flag(e, "--fitted"))?;
        let name = p
            .file_stem()
            .map_or("fitted".into(), |s| s.to_string_lossy().into_owned());
        models.push((name, preset.model()?));
    }
    let out = report::compare::compare(&scene, &r, &models, super::render_error);
    if args.svg.is_some() || args.png.is_some() {
        let spec = overlay(&scene, &r, &out.scored(&models), "compare")?;
        write_charts(&spec, args.svg.as_deref(), args.png.as_deref())?;
    }
    match args.format {
        Format::Json => emit(&serde_json::to_string_pretty(&out).expect("serialisable")),
        Format::Table => {
            let obs: Vec<&str> = r.observables().iter().map(|o| o.key()).collect();
            let mut t = format!(
                "reference {} ({} values); mean and largest |model/reference - 1| (pr: L1 distance)\n\n{:<14}",
                r.name,
                r.points.len(),
                "model"
            );
            for o in &obs {
                t += &format!(" {:>26}", format!("{o} mean / max"));
            }
            t += "\n";
            for row in &out.models {
                t += &format!("{:<14}", row.model);
                match &row.note {
                    Some(n) => t += &format!(" {n}"),
                    None => {
                        for s in &row.scores {
                            t += &format!(" {:>26}", format!("{:.3e} / {:.3e}", s.mean, s.max));
                        }
                    }
                }
                t += "\n";
            }
            emit(&t);
        }
    }
    Ok(())
}
