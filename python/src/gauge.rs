//! `gauge` from Python: fits coefficients of the custom model (c₁, c₂, α, k_G, W(0)) [S-17] to
//! a reference ([`asperity::fit::fit`], weighted least squares), as `asperity gauge --format
//! json` does: the reference is the closed form [S-18] (`"eq18"`, on the scene made
//! adhesionless and semi-infinite), a CSV file (columns p, a_r, a_r_err, mean_contact_stress,
//! mean_contact_stress_err, mean_gap_rel, mean_gap_rel_err) or the same CSV as text.

use crate::errors;
use crate::record::Record;
use crate::scene::SceneCore;
use crate::work;
use asperity::fit::{self, Param};
use asperity::report;
use pyo3::prelude::*;

/// `gauge(scene, fit, reference, ...)`: see the module docs; a record of `asperity gauge
/// --format json`'s object (`reference`, `gfmd` (None), the fit's fields, `saved_preset` (None)).
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
) -> PyResult<Record> {
    // without the GIL: a reference file is read and the reference scene resolved here
    let (r, sc) = errors::detached(py, || {
        let loads = (from_, to, points);
        let (mut r, sc) = report::gauge::reference(&reference, reference_csv.as_deref(), loads, &scene.scene)?;
        if let Some(list) = &observables {
            let keys: Vec<&str> = list.iter().map(String::as_str).collect();
            report::gauge::keep_observables(&mut r, &keys)?;
        }
        Ok((r, sc))
    })?;
    let params = errors::guard(py, || Param::parse_list(fit))?;
    let name = r.name.clone();
    let fit = work::run(py, progress.as_ref(), move |_| fit::fit(&sc, &r, &params))?;
    let out = report::gauge::GaugeReport {
        reference: name,
        gfmd: None,
        fit,
        saved_preset: None,
    };
    Record::of(py, &out)
}
