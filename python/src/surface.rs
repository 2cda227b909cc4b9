//! Height maps in and out: a numpy array (rows along y, heights in m) and the x side L in m
//! as a library [`Surface`] (Δa = L/n_x, square pixels), `read_surface` (the library's
//! readers: .txt .asc .dat .xyz .npy .gsf) and `psd` (the radial average of the map's PSD
//! [S-2] with h_rms, ḡ, the rms curvature and the self-affine fit, a record of
//! `asperity psd --format json`'s object).

use crate::errors;
use crate::record::Record;
use asperity::report;
use asperity::surface::heightmap::Surface;
use asperity::surface::psd::PsdOptions;
use asperity::surface::readers::{self, ReadOptions, Unit};
use numpy::{PyArray2, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Nothing where `size` is a length > 0, else the `InputError` naming `size` (`allowed`: the
/// range in words).
fn positive_size(py: Python<'_>, size: f64, allowed: &str) -> PyResult<()> {
    if size.is_finite() && size > 0.0 {
        return Ok(());
    }
    Err(errors::input(py, "size", &asperity::error::fmt_value(size), allowed))
}

/// The map of `heights` (shape (n_y, n_x), m) with x side `size_m` (m).
pub fn map_of(py: Python<'_>, heights: &PyReadonlyArray2<'_, f64>, size_m: f64) -> PyResult<Surface> {
    let a = heights.as_array();
    let (ny, nx) = a.dim();
    positive_size(py, size_m, "a length > 0 in metres (the map's x side)")?;
    let values: Vec<f64> = a.iter().copied().collect();
    errors::detached(py, || Surface::new(nx, ny, size_m / nx as f64, values))
}

/// The record of a GFMD result with `heights`, the map it walked on (m, rows along y), where
/// it has one.
pub fn on_map<T: serde::Serialize>(py: Python<'_>, x: &T, map: Option<Surface>) -> PyResult<Record> {
    Record::on_map(py, x, map.map(|m| heights_of(py, &m)).transpose()?.map(Bound::into_any))
}

/// The heights of `s` as a numpy array of shape (n_y, n_x).
pub fn heights_of<'py>(py: Python<'py>, s: &Surface) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows: Vec<Vec<f64>> = s.heights.chunks(s.nx).map(<[f64]>::to_vec).collect();
    PyArray2::from_vec2(py, &rows).map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))
}

/// `read_surface(path, size=None, height_unit=None)`: the map as a dict (`heights` (n_y, n_x)
/// in m, `size_m` the x side, `spacing_m`).
#[pyfunction]
#[pyo3(signature = (path, size = None, height_unit = None))]
pub fn read_surface<'py>(
    py: Python<'py>,
    path: std::path::PathBuf,
    size: Option<f64>,
    height_unit: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let unit = match height_unit {
        None => None,
        Some(u) => Some(Unit::parse(u).ok_or_else(|| errors::input(py, "height_unit", u, "m, mm, um, nm or pm"))?),
    };
    if let Some(l) = size {
        positive_size(py, l, "a length > 0 in metres")?;
    }
    let opts = ReadOptions {
        size,
        height_unit: unit,
    };
    let s = errors::detached(py, || readers::read(&path, &opts))?;
    let d = PyDict::new(py);
    d.set_item("heights", heights_of(py, &s)?)?;
    d.set_item("size_m", s.size_x())?;
    d.set_item("spacing_m", s.spacing)?;
    d.set_item("source", path.display().to_string())?;
    Ok(d)
}

/// `psd(heights, size_m, periodic, bins_per_decade)`: the PSD of a map (module docs).
#[pyfunction]
#[pyo3(name = "psd", signature = (heights, size_m, periodic = false, bins_per_decade = 10.0, source = "heights".to_string()))]
pub fn map_psd<'py>(
    py: Python<'py>,
    heights: PyReadonlyArray2<'py, f64>,
    size_m: f64,
    periodic: bool,
    bins_per_decade: f64,
    source: String,
) -> PyResult<Record> {
    let s = map_of(py, &heights, size_m)?;
    let opts = PsdOptions {
        periodic,
        bins_per_decade,
    };
    let r = errors::detached(py, || report::psd::psd(&source, &s, &opts))?;
    Record::of(py, &r)
}
