//! `gauge --reference gfmd` / `compare --reference gfmd`: the GFMD load sweep that gauge runs
//! itself ([`asperity::fit::gfmd_reference`]), with the flags of `asperity gfmd` (same names,
//! same parsers).
//!
//! Default grid and loads: the library's ([`asperity::report::gauge::gfmd_grid`],
//! [`asperity::report::gauge::gfmd_loads`]): the preset's `[gfmd]` grid at most
//! [`DEFAULT_MAX_GRID`]², loads log-spaced around the scene's p*.

use super::gfmd::MethodArg;
use super::parse;
use super::progress::Steps;
use asperity::error::{Error, Result};
use asperity::fit::gfmd_reference::{self, GfmdReference, GfmdReferenceSpec, Stage};
use asperity::gfmd::{GfmdOptions, GfmdSetup, Method, Progress};
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::report::gauge;
use asperity::surface::heightmap::Surface;
use clap::Args;
use std::sync::atomic::AtomicBool;

/// Largest default grid side of `--reference gfmd` (the library's).
pub use asperity::report::gauge::GFMD_DEFAULT_MAX_GRID as DEFAULT_MAX_GRID;

/// The GFMD options of `--reference gfmd` (as in `asperity gfmd`).
#[derive(Debug, Clone, Args)]
pub struct GfmdRefArgs {
    /// --reference gfmd: grid side N (default: the grid of the preset's gfmd table, at most 256).
    #[arg(long)]
    pub grid: Option<i64>,
    /// --reference gfmd: seed of the first random surface.
    #[arg(long)]
    pub seed: Option<u64>,
    /// --reference gfmd: K realisations (seeds S..S+K-1); their standard errors weight the fit.
    #[arg(long)]
    pub seeds: Option<usize>,
    /// --reference gfmd: a ladder of resolutions (--ladder) per load, extrapolated to da -> 0.
    #[arg(long)]
    pub extrapolate: bool,
    /// --reference gfmd: points per short wavelength lambda_s/da of the --extrapolate ladder.
    #[arg(long, value_delimiter = ',', default_value = "4,8,16", requires = "extrapolate")]
    pub ladder: Vec<f64>,
    /// --reference gfmd: minimiser (auto, pk or fire; see gfmd --method).
    #[arg(long, value_enum)]
    pub method: Option<MethodArg>,
    /// --reference gfmd: write the reference (mean and standard error per load) as CSV.
    #[arg(long)]
    pub save_reference: Option<std::path::PathBuf>,
}

impl GfmdRefArgs {
    /// The flags given that only `--reference gfmd` takes: refused with another reference.
    pub fn refuse_unless_gfmd(&self, reference: &str) -> Result<()> {
        let given: [(&str, Option<String>); 6] = [
            ("--grid", self.grid.map(|x| x.to_string())),
            ("--seed", self.seed.map(|x| x.to_string())),
            ("--seeds", self.seeds.map(|x| x.to_string())),
            ("--extrapolate", self.extrapolate.then(|| "true".into())),
            ("--method", self.method.map(|m| format!("{m:?}").to_ascii_lowercase())),
            (
                "--save-reference",
                self.save_reference.as_ref().map(|p| p.display().to_string()),
            ),
        ];
        for (flag, v) in given {
            if let Some(v) = v {
                return Err(Error::field(
                    flag,
                    v,
                    format!("only with --reference gfmd (not --reference {reference})"),
                ));
            }
        }
        Ok(())
    }
}

/// Runs the GFMD reference of the scene (on `surface` when a map is given): loads `from..to` (`points`), defaults as in the
/// module docs. Replaces `scene` by the scene GFMD runs (the fit's scene).
pub fn resolve(
    args: &GfmdRefArgs,
    loads: (Option<f64>, Option<f64>, Option<usize>),
    preset: &Preset,
    surface: Option<Surface>,
    scene: &mut Scene,
) -> Result<GfmdReference> {
    let grid = gauge::gfmd_grid(preset, args.grid)?;
    let spec = GfmdReferenceSpec {
        loads: gauge::gfmd_loads(scene, loads),
        seeds: args.seeds.unwrap_or(1),
        ladder: args.extrapolate.then(|| args.ladder.clone()),
    };
    parse::refuse_pk_on_slab(args.method == Some(MethodArg::Pk), scene)?;
    let opts = GfmdOptions {
        method: args.method.map_or(Method::Auto, Method::from),
        ..GfmdOptions::default()
    };
    let setup = GfmdSetup {
        scene: scene.clone(),
        grid,
        seed: args.seed.unwrap_or(1),
        surface,
        rescale: true,
    };
    let cancel = AtomicBool::new(false);
    let rungs = spec.ladder.as_ref().map_or(1, Vec::len);
    let total = spec.seeds * rungs * spec.loads.points;
    let mut steps = Steps::new("gauge", "gfmd load", total);
    let mut report = |st: &Stage, pr: Progress| {
        let k = (st.seed_index * st.rungs + st.rung) * st.loads + st.load;
        let rung = if st.rungs > 1 {
            format!("rung {}/{}, ", st.rung + 1, st.rungs)
        } else {
            String::new()
        };
        let label = format!(
            "seed {}/{}, {rung}{}^2, load {}/{}",
            st.seed_index + 1,
            st.seeds,
            st.grid,
            st.load + 1,
            st.loads
        );
        steps.step(k, &label);
        steps.detail(&format!("step {}, contact {:.4}", pr.iteration, pr.contact_fraction));
    };
    let out = gfmd_reference::gfmd_reference(&setup, &spec, &opts, &mut report, &cancel);
    steps.finish();
    let out = out?;
    if let Some(path) = &args.save_reference {
        let csv = gfmd_reference::to_csv(&out.rows, out.scene.surface_energy_j_m2() > 0.0);
        super::outfile::write_bytes("--save-reference", path, csv.as_bytes())?;
    }
    *scene = out.scene.clone();
    Ok(out)
}

/// The GFMD block of `gauge`'s table.
pub fn table(g: &GfmdReference) -> String {
    let mut t = format!(
        "GFMD reference: grid {}^2, seeds {:?}{}, {} steps in {:.1} s (fitted on the reduced scene GFMD ran)\n",
        g.grid,
        g.seeds,
        g.ladder.as_ref().map_or(String::new(), |l| format!(
            ", extrapolated da -> 0 over lambda_s/da = {l:?}"
        )),
        g.iterations,
        g.elapsed_s
    );
    let e = |x: Option<f64>| x.map_or("-".to_string(), |x| format!("{x:.2e}"));
    t += &format!(
        "{:>12} {:>12} {:>10} {:>12} {:>10} {:>12} {:>10}\n",
        "p*", "a_r", "+-", "sigma_c*", "+-", "u/h_rms", "+-"
    );
    for r in &g.rows {
        t += &format!(
            "{:>12.4e} {:>12.6} {:>10} {:>12.6} {:>10} {:>12.6} {:>10}\n",
            r.p,
            r.a_r,
            e(r.a_r_err),
            r.mean_contact_stress,
            e(r.mean_contact_stress_err),
            r.mean_gap_rel,
            e(r.mean_gap_rel_err)
        );
    }
    t + "\n"
}
