//! `gauge` from Python: fits coefficients of the custom model (c₁, c₂, α, k_G, W(0)) [S-17] to
//! a reference ([`asperity::fit::fit`], weighted least squares), as `asperity gauge --format
//! json` does: the reference is the closed form [S-18] (`"eq18"`, on the scene made
//! adhesionless and semi-infinite), a CSV file (columns p, a_r, a_r_err, mean_contact_stress,
//! mean_contact_stress_err, mean_gap_rel, mean_gap_rel_err) or the same CSV as text.

use crate::errors;
use crate::scene::SceneCore;
use crate::value;
use crate::work;
use asperity::error::Error;
use asperity::fit::reference::{self, Observable};
use asperity::fit::{self, Param};
use pyo3::prelude::*;

/// `gauge(scene, fit, reference, ...)`: see the module docs; the keys of `asperity gauge
/// --format json` (`reference`, `gfmd` (None), the fit's fields, `saved_preset` (None)).
#[pyfunction]
#[pyo3(name = "gauge", signature = (scene, fit, reference = "eq18".to_string(), reference_csv = None, from_ = None, to = None, points = None, observables = None, progress = None))]
#[allow(clippy::too_many_arguments)]
pub fn run_gauge<'py>(
    py: Python<'py>,
    scene: &SceneCore,
    fit: &str,
    reference: String,
    reference_csv: Option<String>,
    from_: Option<f64>,
    to: Option<f64>,
    points: Option<usize>,
    observables: Option<Vec<String>>,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (name, r, sc) = errors::guard(py, || {
        let mut sc = scene.scene.clone();
        let mut r = match (reference.as_str(), &reference_csv) {
            (name, Some(text)) => reference::parse_csv(text, name)?,
            ("eq18", None) => {
                sc = sc.without_adhesion().half_space();
                reference::eq18(from_.unwrap_or(1e-3), to.unwrap_or(1.0), points.unwrap_or(31))?
            }
            (path, None) => {
                let p = std::path::Path::new(path);
                let text = std::fs::read_to_string(p).map_err(|e| Error::io_file("read", "reference", p, &e))?;
                let name = p
                    .file_name()
                    .map_or(path.to_string(), |n| n.to_string_lossy().into_owned());
                reference::parse_csv(&text, &name)?
            }
        };
        if let Some(list) = &observables {
            let allowed = "a list of a_r, mean_contact_stress, mean_gap_rel, pr held by the reference";
            let mut keep = Vec::new();
            for t in list {
                let o = Observable::ALL
                    .into_iter()
                    .find(|o| o.key() == t.trim())
                    .filter(|o| r.observables().contains(o))
                    .ok_or_else(|| Error::field("observables", list.join(","), allowed))?;
                keep.push(o);
            }
            r.points.retain(|o| keep.contains(&o.observable));
        }
        Ok((r.name.clone(), r, sc))
    })?;
    let params = errors::guard(py, || Param::parse_list(fit))?;
    let f = work::run(py, progress.as_ref(), move |_| fit::fit(&sc, &r, &params))?;
    let d = value::ser(py, &f)?;
    d.set_item("reference", name)?;
    d.set_item("gfmd", py.None())?;
    d.set_item("saved_preset", py.None())?;
    Ok(d)
}
