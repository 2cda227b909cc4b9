//! `Report`, the result of `evaluate` (`asperity run`), as frozen Python classes converted in
//! Rust from the library's [`PointReport`] (read from its serde value, the CLI's JSON object, so
//! that every attribute is the number `to_dict()` holds): every field a typed getter (floats,
//! ints, bools, strings; an unavailable optional number None, a number JSON cannot hold NaN),
//! every array a read-only float64 numpy array made once, the parts [`Pr`], [`Resolution`] and
//! each of [`BranchReport`]s classes of their own, the resolved inputs (`scene`) and the
//! reference set's verdict (`trust`) a [`Record`]. `to_dict()` gives the object of
//! `asperity run --format json` with the preset's name under `preset`; `Report(d)` makes the
//! report of such a dict again (how a pickled report returns).
//!
//! Units as in the library: stresses reduced by E*ḡ, gaps relative to h_rms where `_rel` and
//! in m for `mean_gap`, energies in J/m², times in s.

use crate::record::{array, record_methods, FromValue, Record};
use crate::value;
use asperity::report::point::PointReport;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;
use std::sync::Arc;

/// The number `d[k]` (NaN where null: a non-finite number, which JSON writes as null).
fn num(d: &Value, k: &str) -> f64 {
    d[k].as_f64().unwrap_or(f64::NAN)
}

/// The string `d[k]` (empty where absent).
fn text(d: &Value, k: &str) -> String {
    d[k].as_str().unwrap_or_default().to_string()
}

/// The numbers of the list `d[k]` as a read-only array (null as NaN).
fn floats(py: Python<'_>, d: &Value, k: &str) -> PyResult<Py<PyArray1<f64>>> {
    let items = d[k].as_array().map(Vec::as_slice).unwrap_or_default();
    array(py, items.iter().map(|x| x.as_f64().unwrap_or(f64::NAN)).collect())
}

/// `data[key]` of an object value (null where absent).
fn part(data: &Value, key: &str) -> Arc<Value> {
    Arc::new(data.get(key).cloned().unwrap_or(Value::Null))
}

/// A frozen class of two arrays (read from the keys of their names).
macro_rules! arrays_class {
    ($(#[$doc:meta])* $ty:ident { $(#[$da:meta])* $a:ident, $(#[$db:meta])* $b:ident }) => {
        $(#[$doc])*
        #[pyclass(module = "asperity._native", frozen)]
        pub struct $ty {
            $(#[$da])*
            #[pyo3(get)]
            $a: Py<PyArray1<f64>>,
            $(#[$db])*
            #[pyo3(get)]
            $b: Py<PyArray1<f64>>,
            data: Arc<Value>,
        }

        record_methods!($ty, None, {});

        impl FromValue for $ty {
            fn from_value(py: Python<'_>, data: Arc<Value>) -> PyResult<$ty> {
                Ok($ty {
                    $a: floats(py, &data, stringify!($a))?,
                    $b: floats(py, &data, stringify!($b))?,
                    data,
                })
            }
        }
    };
}

arrays_class!(
    /// Pr(σ*), the distribution of contact stresses: ∫ density dσ* = a_r [S-9, S-14].
    Pr {
        /// σ* (ascending; from −σ_a* with adhesion).
        sigma,
        /// Pr(σ*).
        density
    }
);

arrays_class!(
    /// a_r(q) along the resolution q_L → q_s.
    Resolution {
        /// q (1/m).
        q,
        /// a_r(q).
        a_r
    }
);

/// One branch of the adhesive solution at the load, with its mean gap (docs/physics.md §5.1).
#[pyclass(module = "asperity._native", frozen)]
pub struct BranchReport {
    /// "adhesionless", "loading", "unloading" or "unstable".
    #[pyo3(get)]
    branch: String,
    /// Whether a quasi-static path can follow it.
    #[pyo3(get)]
    stable: bool,
    /// Its relative contact area.
    #[pyo3(get)]
    a_r: f64,
    /// σ_a*(q_s), its adhesive wall.
    #[pyo3(get)]
    sigma_a: f64,
    /// γ(q_L)/γ_s at the coarsest scale.
    #[pyo3(get)]
    gamma_coarse: f64,
    /// Elastic energy per nominal area (J/m²).
    #[pyo3(get)]
    elastic_energy: f64,
    /// Self-consistency residual |γ(q_s)/γ_s − 1|.
    #[pyo3(get)]
    residual: f64,
    /// ū/h_rms (None for an unstable branch or when unavailable).
    #[pyo3(get)]
    mean_gap_rel: Option<f64>,
    /// The adhesionless gap at the same load.
    #[pyo3(get)]
    mean_gap_reversible_rel: Option<f64>,
    /// The bracket's lower end.
    #[pyo3(get)]
    mean_gap_lower_rel: Option<f64>,
    /// The bracket's upper end.
    #[pyo3(get)]
    mean_gap_upper_rel: Option<f64>,
    /// Estimated absolute error of `mean_gap_rel`.
    #[pyo3(get)]
    mean_gap_error: Option<f64>,
    /// The net load its contact carries, ∫σ*Pr dσ*.
    #[pyo3(get)]
    contact_load: Option<f64>,
    data: Arc<Value>,
}

record_methods!(BranchReport, None, {});

impl FromValue for BranchReport {
    fn from_value(_py: Python<'_>, data: Arc<Value>) -> PyResult<BranchReport> {
        let d = &*data;
        Ok(BranchReport {
            branch: text(d, "branch"),
            stable: d["stable"].as_bool().unwrap_or(false),
            a_r: num(d, "a_r"),
            sigma_a: num(d, "sigma_a"),
            gamma_coarse: num(d, "gamma_coarse"),
            elastic_energy: num(d, "elastic_energy"),
            residual: num(d, "residual"),
            mean_gap_rel: d["mean_gap_rel"].as_f64(),
            mean_gap_reversible_rel: d["mean_gap_reversible_rel"].as_f64(),
            mean_gap_lower_rel: d["mean_gap_lower_rel"].as_f64(),
            mean_gap_upper_rel: d["mean_gap_upper_rel"].as_f64(),
            mean_gap_error: d["mean_gap_error"].as_f64(),
            contact_load: d["contact_load"].as_f64(),
            data,
        })
    }
}

/// One scene at one load (`asperity.evaluate`): the fields of `asperity run --format json`.
///
/// Main fields (stresses reduced by E*ḡ, gaps by h_rms where `_rel`):
///
/// - `a_r`: relative contact area [S-3]; `mean_contact_stress` σ̄_c*;
///   `contact_stress_variance` ⟨δσ_c²⟩*; `pr.sigma`, `pr.density`: Pr(σ*) with
///   ∫Pr dσ* = a_r [S-9, S-14];
/// - `mean_gap` (m), `mean_gap_rel` with its bracket `mean_gap_lower_rel` ..
///   `mean_gap_upper_rel` and `mean_gap_error` [S-11, S-12];
/// - `branch`, `branches` (every branch at this load), `a_r_unloading` (the unloading
///   branch's a_r, the name a sweep's column has; `unloading_a_r` is its older alias),
///   `jump_in_pressure`, `pull_off_pressure` (the hysteresis window);
/// - `error_estimate` (absolute error of a_r), `converged`;
/// - `elapsed_s`, `elapsed_solve_s`, `elapsed_window_s`, `elapsed_gap_s` (timings, s);
/// - `scene` (the resolved inputs), `resolution` (a_r(q)), `trust` (the GFMD reference set).
///
/// Frozen: every field is made once (`r.pr.sigma is r.pr.sigma`) and its arrays are
/// read-only; `to_dict()` gives a fresh plain dict.
#[pyclass(module = "asperity._native", frozen)]
pub struct Report {
    /// The preset's name ("custom" for a scene built from keywords).
    #[pyo3(get)]
    preset: String,
    /// Relative contact area a_r [S-3].
    #[pyo3(get)]
    a_r: f64,
    /// σ̄_c*, the mean stress in the contact.
    #[pyo3(get)]
    mean_contact_stress: f64,
    /// ⟨δσ_c²⟩*, the contact stress variance (reduced by (E*ḡ)²).
    #[pyo3(get)]
    contact_stress_variance: f64,
    /// Pr(σ*).
    #[pyo3(get)]
    pr: Py<Pr>,
    /// Width Δ* of the stress distribution.
    #[pyo3(get)]
    width: f64,
    /// Whether the result meets the requested accuracy.
    #[pyo3(get)]
    converged: bool,
    /// Why `converged` is false (None when it is true).
    #[pyo3(get)]
    converged_note: Option<String>,
    /// Estimated absolute error of a_r.
    #[pyo3(get)]
    error_estimate: f64,
    /// Mean gap ū (m); None when unavailable.
    #[pyo3(get)]
    mean_gap: Option<f64>,
    /// ū/h_rms; None when unavailable.
    #[pyo3(get)]
    mean_gap_rel: Option<f64>,
    /// Lower end of ū/h_rms's bracket.
    #[pyo3(get)]
    mean_gap_lower_rel: Option<f64>,
    /// Upper end of ū/h_rms's bracket.
    #[pyo3(get)]
    mean_gap_upper_rel: Option<f64>,
    /// Estimated absolute error of `mean_gap_rel`.
    #[pyo3(get)]
    mean_gap_error: Option<f64>,
    /// p_c*, the net load the reported branch's contact carries.
    #[pyo3(get)]
    contact_load: Option<f64>,
    /// What `mean_gap_rel` is, in one line.
    #[pyo3(get)]
    mean_gap_about: String,
    /// Why the mean gap is None (None when it is given).
    #[pyo3(get)]
    mean_gap_note: Option<String>,
    /// Elastic energy per nominal area (J/m²) [S-11].
    #[pyo3(get)]
    elastic_energy: f64,
    /// σ_a*(q_s), the adhesive wall (0 without adhesion).
    #[pyo3(get)]
    sigma_a: f64,
    /// Contact area under tension.
    #[pyo3(get)]
    tensile_area: f64,
    /// 1 − a_r.
    #[pyo3(get)]
    detached_fraction: f64,
    /// Marches of the adhesive solver (0 without adhesion).
    #[pyo3(get)]
    iterations: usize,
    /// Self-consistency residual (0 without adhesion).
    #[pyo3(get)]
    residual: f64,
    /// "adhesionless", "loading" or "unloading": the reported branch.
    #[pyo3(get)]
    branch: String,
    /// a_r of a distinct unloading branch (None if none).
    #[pyo3(get)]
    a_r_unloading: Option<f64>,
    /// The older name of `a_r_unloading` (an alias).
    #[pyo3(get)]
    unloading_a_r: Option<f64>,
    /// Every branch at this load, lowest a_r first (empty without adhesion).
    #[pyo3(get)]
    branches: Py<PyList>,
    /// Inside a hysteresis window: p* of the jump into contact.
    #[pyo3(get)]
    jump_in_pressure: Option<f64>,
    /// Inside a hysteresis window: p* of the pull-off.
    #[pyo3(get)]
    pull_off_pressure: Option<f64>,
    /// Where the scene lies relative to the GFMD reference set.
    #[pyo3(get)]
    trust: Py<Record>,
    /// γ(q)/γ_s along `resolution.q` (empty without adhesion).
    #[pyo3(get)]
    gamma_q: Py<PyArray1<f64>>,
    /// σ_a*(q) along `resolution.q` (empty without adhesion).
    #[pyo3(get)]
    sigma_a_q: Py<PyArray1<f64>>,
    /// Wall time of the whole computation (s).
    #[pyo3(get)]
    elapsed_s: f64,
    /// Wall time of the solve (s).
    #[pyo3(get)]
    elapsed_solve_s: f64,
    /// Wall time of the hysteresis window's edges (s).
    #[pyo3(get)]
    elapsed_window_s: f64,
    /// Wall time of the mean gap (s).
    #[pyo3(get)]
    elapsed_gap_s: f64,
    /// The resolved inputs.
    #[pyo3(get)]
    scene: Py<Record>,
    /// a_r(q) along the resolution.
    #[pyo3(get)]
    resolution: Py<Resolution>,
    data: Arc<Value>,
}

impl Report {
    /// The report of `r` for the scene of preset `preset`, read from its serde value (the
    /// CLI's JSON), so that every attribute is the number `to_dict()` holds.
    pub fn new(py: Python<'_>, preset: &str, r: &PointReport) -> PyResult<Report> {
        Report::from_value(py, Arc::new(value::with_preset(preset, value::json(r)?)))
    }
}

impl FromValue for Report {
    /// The report of `run`'s JSON object (`to_dict()`: also how a pickled report returns).
    fn from_value(py: Python<'_>, data: Arc<Value>) -> PyResult<Report> {
        let d = &*data;
        let branches = d["branches"]
            .as_array()
            .map(Vec::as_slice)
            .unwrap_or_default()
            .iter()
            .map(|b| Py::new(py, BranchReport::from_value(py, Arc::new(b.clone()))?))
            .collect::<PyResult<Vec<_>>>()?;
        let o = |k: &str| d[k].as_f64();
        Ok(Report {
            preset: text(d, "preset"),
            a_r: num(d, "a_r"),
            mean_contact_stress: num(d, "mean_contact_stress"),
            contact_stress_variance: num(d, "contact_stress_variance"),
            pr: Py::new(py, Pr::from_value(py, part(d, "pr"))?)?,
            width: num(d, "width"),
            converged: d["converged"].as_bool().unwrap_or(false),
            converged_note: d["converged_note"].as_str().map(str::to_string),
            error_estimate: num(d, "error_estimate"),
            mean_gap: o("mean_gap"),
            mean_gap_rel: o("mean_gap_rel"),
            mean_gap_lower_rel: o("mean_gap_lower_rel"),
            mean_gap_upper_rel: o("mean_gap_upper_rel"),
            mean_gap_error: o("mean_gap_error"),
            contact_load: o("contact_load"),
            mean_gap_about: text(d, "mean_gap_about"),
            mean_gap_note: d["mean_gap_note"].as_str().map(str::to_string),
            elastic_energy: num(d, "elastic_energy"),
            sigma_a: num(d, "sigma_a"),
            tensile_area: num(d, "tensile_area"),
            detached_fraction: num(d, "detached_fraction"),
            iterations: d["iterations"].as_u64().unwrap_or(0) as usize,
            residual: num(d, "residual"),
            branch: text(d, "branch"),
            a_r_unloading: o("a_r_unloading"),
            unloading_a_r: o("unloading_a_r"),
            branches: PyList::new(py, branches)?.unbind(),
            jump_in_pressure: o("jump_in_pressure"),
            pull_off_pressure: o("pull_off_pressure"),
            trust: Py::new(py, Record::new(py, part(d, "trust"))?)?,
            gamma_q: floats(py, d, "gamma_q")?,
            sigma_a_q: floats(py, d, "sigma_a_q")?,
            elapsed_s: num(d, "elapsed_s"),
            elapsed_solve_s: num(d, "elapsed_solve_s"),
            elapsed_window_s: num(d, "elapsed_window_s"),
            elapsed_gap_s: num(d, "elapsed_gap_s"),
            scene: Py::new(py, Record::new(py, part(d, "scene"))?)?,
            resolution: Py::new(py, Resolution::from_value(py, part(d, "resolution"))?)?,
            data,
        })
    }
}

/// A number as the pairs show it: NaN where unavailable.
fn nan(x: Option<f64>) -> f64 {
    x.unwrap_or(f64::NAN)
}

const SHOWN: &[&str] = &[
    "preset",
    "a_r",
    "mean_contact_stress",
    "contact_stress_variance",
    "mean_gap_rel",
    "branch",
    "converged",
];

record_methods!(Report, Some(SHOWN), {
    /// (pull-off p*, jump-in p*) of the hysteresis window around the load (NaN: none).
    #[getter]
    fn window(&self) -> (f64, f64) {
        (nan(self.pull_off_pressure), nan(self.jump_in_pressure))
    }

    /// ⟨δσ_c²⟩*, the contact stress variance (reduced by (E*ḡ)²): an alias of
    /// `contact_stress_variance`, the preferred name.
    #[getter]
    fn variance(&self) -> f64 {
        self.contact_stress_variance
    }

    /// Wall times in s: `elapsed_s` (all), `elapsed_solve_s`, `elapsed_window_s`,
    /// `elapsed_gap_s`.
    #[getter]
    fn timings<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("elapsed_s", self.elapsed_s)?;
        d.set_item("elapsed_solve_s", self.elapsed_solve_s)?;
        d.set_item("elapsed_window_s", self.elapsed_window_s)?;
        d.set_item("elapsed_gap_s", self.elapsed_gap_s)?;
        Ok(d)
    }

    /// (lower, upper) ends of ū/h_rms's bracket (NaN where the gap is unavailable).
    #[getter]
    fn gap_bracket(&self) -> (f64, f64) {
        (nan(self.mean_gap_lower_rel), nan(self.mean_gap_upper_rel))
    }
});
