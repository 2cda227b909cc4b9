//! The report of a gauge: the custom model's coefficients fitted to a reference
//! ([`crate::fit::fit`], weighted least squares), what `asperity gauge` prints and Python's
//! `gauge()` returns: the reference's name, the GFMD run that made it (where GFMD did), the
//! fitted values with their standard errors and correlations, the residuals per observable,
//! χ², and the preset written (where one was).
//!
//! The reference is assembled here for every front end ([`reference()`]):
//! - `eq18`: the closed form [S-18] over log-spaced loads ([`EQ18_LOADS`] by default), fitted
//!   on the scene made adhesionless and semi-infinite, the only case it describes;
//! - a CSV table (given as text, or a file read with a bounded size), compared on the scene as
//!   given; Pr(σ*) histograms join it from their own table;
//! - `gfmd`: the front end runs [`crate::fit::gfmd_reference`] itself (it reports progress);
//!   its grid and loads default as [`gfmd_grid`] and [`gfmd_loads`] say, and the fit runs on
//!   the reduced scene GFMD ran.
//!
//! [`keep_observables`] narrows a reference to the observables asked for. The serialised field
//! names are those of `asperity gauge --format json` (a public interface).

use crate::error::{Error, Field, Result};
use crate::fit::gfmd_reference::GfmdReference;
use crate::fit::reference::{self, Observable, Reference};
use crate::fit::Fit;
use crate::gfmd::GridSpec;
use crate::input::file::{read_text, MAX_INPUT_BYTES};
use crate::input::preset::Preset;
use crate::input::scene::Scene;
use crate::theory::sweep::SweepSpec;
use serde::Serialize;
use std::path::Path;

/// Default loads of the `eq18` reference: p* from, to, and the number of log-spaced points.
pub const EQ18_LOADS: (f64, f64, usize) = (1e-3, 1.0, 31);
/// Largest default grid side of a GFMD reference (a larger preset grid is narrowed to it,
/// keeping L/λ_r and λ_s/Δa).
pub const GFMD_DEFAULT_MAX_GRID: usize = 256;
/// Default number of loads of a GFMD reference.
pub const GFMD_DEFAULT_POINTS: usize = 4;
/// A GFMD reference's default loads span p*/span..p*·span around the scene's p*.
pub const GFMD_DEFAULT_SPAN: f64 = 2.5;

/// Everything a gauge reports.
#[derive(Debug, Clone, Serialize)]
pub struct GaugeReport {
    /// "eq18", "gfmd" or the table's name.
    pub reference: String,
    /// The GFMD run of a `gfmd` reference (grid, seeds, ladder, rows, reduction, iterations,
    /// elapsed_s); None for the other references.
    pub gfmd: Option<GfmdReference>,
    /// params, correlation, condition_number, residuals, chi2, chi2_reduced, points,
    /// evaluations, termination, model, start, elapsed_s.
    #[serde(flatten)]
    pub fit: Fit,
    /// The preset written, if any.
    pub saved_preset: Option<String>,
}

/// Reads a reference table given to `field` (a regular file of bounded size, UTF-8 CSV) and
/// names it by its file name.
pub fn read_table(path: &Path, field: &str) -> Result<(String, String)> {
    let text = read_text(
        path,
        "",
        Field::Other(field.into()),
        MAX_INPUT_BYTES,
        "a CSV table with a header line",
    )?;
    let name = path
        .file_name()
        .map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
    Ok((text, name))
}

/// The reference `name` and the scene the fit compares it on (module docs): `"eq18"` over
/// `loads` (each default from [`EQ18_LOADS`]); with `text`, that CSV table called `name`;
/// otherwise `name` is a CSV file's path. A `"gfmd"` reference is the front end's to run.
///
/// # Errors
/// The closed form's ([`reference::eq18`]) and the table's ([`reference::parse_csv`]); a
/// file that cannot be read, named by the field `reference`.
pub fn reference(
    name: &str,
    text: Option<&str>,
    loads: (Option<f64>, Option<f64>, Option<usize>),
    scene: &Scene,
) -> Result<(Reference, Scene)> {
    match (name, text) {
        (name, Some(text)) => Ok((reference::parse_csv(text, name)?, scene.clone())),
        ("eq18", None) => {
            let (from, to, points) = EQ18_LOADS;
            let r = reference::eq18(
                loads.0.unwrap_or(from),
                loads.1.unwrap_or(to),
                loads.2.unwrap_or(points),
            )?;
            // [S-18] is the adhesionless half-space
            Ok((r, scene.without_adhesion().half_space()))
        }
        (path, None) => {
            let (text, name) = read_table(Path::new(path), "reference")?;
            Ok((reference::parse_csv(&text, &name)?, scene.clone()))
        }
    }
}

/// Keeps only the observables named in `keys` (a_r, mean_contact_stress, mean_gap_rel, pr),
/// each of which the reference must hold.
///
/// # Errors
/// [`Error::Invalid`] naming the field `observables` for a name that is not one, or that
/// the reference does not hold.
pub fn keep_observables(r: &mut Reference, keys: &[&str]) -> Result<()> {
    let held = r.observables();
    let mut keep = Vec::new();
    for key in keys {
        let o = Observable::ALL
            .into_iter()
            .find(|o| o.key() == key.trim())
            .filter(|o| held.contains(o))
            .ok_or_else(|| {
                Error::invalid_text(
                    Field::Other("observables".into()),
                    keys.join(","),
                    "a list of a_r, mean_contact_stress, mean_gap_rel, pr held by the reference",
                )
            })?;
        keep.push(o);
    }
    r.points.retain(|o| keep.contains(&o.observable));
    Ok(())
}

/// The grid of a GFMD reference: `grid` N×N where given, else the preset's `[gfmd]` grid
/// narrowed to at most [`GFMD_DEFAULT_MAX_GRID`]².
///
/// # Errors
/// [`Error::Invalid`] naming the grid for N < 4 ([`GridSpec::of_preset`]).
pub fn gfmd_grid(preset: &Preset, grid: Option<i64>) -> Result<GridSpec> {
    let spec = GridSpec::of_preset(preset, grid)?;
    match grid {
        None if spec.n() > GFMD_DEFAULT_MAX_GRID => spec.with_grid(GFMD_DEFAULT_MAX_GRID),
        _ => Ok(spec),
    }
}

/// The loads of a GFMD reference around the scene's p*: each default from
/// [`GFMD_DEFAULT_SPAN`] and [`GFMD_DEFAULT_POINTS`].
pub fn gfmd_loads(scene: &Scene, loads: (Option<f64>, Option<f64>, Option<usize>)) -> SweepSpec {
    let p = scene.pressure();
    SweepSpec {
        from: loads.0.unwrap_or(p / GFMD_DEFAULT_SPAN),
        to: loads.1.unwrap_or(p * GFMD_DEFAULT_SPAN),
        points: loads.2.unwrap_or(GFMD_DEFAULT_POINTS),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;

    fn scene() -> Scene {
        Preset::resolve("system-1").unwrap().scene().unwrap()
    }

    #[test]
    fn eq18_runs_on_the_adhesionless_half_space_over_its_default_loads() {
        let (r, sc) = reference("eq18", None, (None, None, None), &scene()).unwrap();
        assert_eq!(sc.surface_energy_j_m2(), 0.0);
        assert!(sc.thickness_qr().is_infinite());
        let loads = r.loads();
        assert_eq!(loads.len(), EQ18_LOADS.2);
        let rel = |a: f64, b: f64| (a / b - 1.0).abs();
        assert!(rel(loads[0], EQ18_LOADS.0) < 1e-12 && rel(loads[loads.len() - 1], EQ18_LOADS.1) < 1e-12);
    }

    #[test]
    fn a_table_is_compared_on_the_scene_as_given_and_narrowed_by_name() {
        let text = "p,a_r,mean_gap_rel\n0.01,0.02,1.5\n0.02,0.04,1.2\n";
        let s = scene();
        let (mut r, sc) = reference("t.csv", Some(text), (None, None, None), &s).unwrap();
        assert_eq!(sc, s);
        assert_eq!(r.name, "t.csv");
        keep_observables(&mut r, &["mean_gap_rel"]).unwrap();
        assert_eq!(r.observables(), vec![Observable::MeanGapRel]);
        let e = keep_observables(&mut r, &["a_r"]).unwrap_err();
        assert!(e.to_string().contains("observables"), "{e}");
    }

    #[test]
    fn a_gfmd_reference_defaults_around_the_load_and_refuses_a_tiny_grid() {
        let s = scene();
        let l = gfmd_loads(&s, (None, None, None));
        assert_eq!(l.points, GFMD_DEFAULT_POINTS);
        assert!((l.from * GFMD_DEFAULT_SPAN / s.pressure() - 1.0).abs() < 1e-15);
        let p = Preset::resolve("system-1").unwrap();
        assert!(gfmd_grid(&p, None).unwrap().n() <= GFMD_DEFAULT_MAX_GRID);
        assert_eq!(gfmd_grid(&p, Some(32)).unwrap().n(), 32);
        assert!(gfmd_grid(&p, Some(3)).is_err());
    }
}
