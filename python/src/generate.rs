//! Surfaces made and written from Python: `generate_surface` ([`MapRequest::make`], the
//! generator of `asperity surface generate` and of GFMD's maps) and `write_surface`
//! ([`asperity::surface::writers::write`]: every format the readers read, chosen by the
//! extension). The arguments arrive checked against the range table by `asperity/_args.py`;
//! the library checks them again as a whole (λ_s against the grid, λ_r against L).

use crate::errors;
use crate::surface::{heights_of, map_of};
use asperity::surface::generate::{window_rms_gradient, MapRequest};
use numpy::PyReadonlyArray2;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `generate_surface(...)`: the map as a dict (`heights` (N, N) in m, rows along y, `size_m`,
/// `spacing_m`, `rms_height_m`, `rms_gradient` (periodic: spectral; not periodic: by
/// differences inside the map), `hurst`, `rolloff_wavelength_m`, `short_wavelength_m`,
/// `periodic`, `seed`).
#[pyfunction]
#[pyo3(signature = (grid, size_m, hurst, rolloff_wavelength_m, short_wavelength_m, rms_gradient, rms_height_m, seed, periodic))]
#[allow(clippy::too_many_arguments)]
pub fn generate_surface<'py>(
    py: Python<'py>,
    grid: i64,
    size_m: f64,
    hurst: f64,
    rolloff_wavelength_m: Option<f64>,
    short_wavelength_m: Option<f64>,
    rms_gradient: Option<f64>,
    rms_height_m: Option<f64>,
    seed: u64,
    periodic: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let request = MapRequest {
        grid,
        size: size_m,
        hurst,
        rolloff_wavelength: rolloff_wavelength_m,
        short_wavelength: short_wavelength_m,
        rms_gradient,
        rms_height: rms_height_m,
        seed,
        periodic,
    };
    let (s, spec) = errors::guard(py, || {
        let spec = request.spectrum(size_m)?;
        Ok((py.detach(|| request.make())?, spec))
    })?;
    let d = PyDict::new(py);
    d.set_item("heights", heights_of(py, &s)?)?;
    d.set_item("size_m", s.size_x())?;
    d.set_item("spacing_m", s.spacing)?;
    d.set_item("rms_height_m", s.rms_height())?;
    d.set_item(
        "rms_gradient",
        if periodic {
            s.rms_gradient()
        } else {
            window_rms_gradient(&s)
        },
    )?;
    d.set_item("hurst", spec.hurst)?;
    d.set_item("rolloff_wavelength_m", spec.lambda_r)?;
    d.set_item("short_wavelength_m", spec.lambda_s)?;
    d.set_item("periodic", periodic)?;
    d.set_item("seed", seed)?;
    Ok(d)
}

/// `write_surface(heights, size_m, path)`: writes the map (m, rows along y; `size_m` its x
/// side) in the format of `path`'s extension (.txt .asc .dat .xyz .npy .gsf).
#[pyfunction]
pub fn write_surface(
    py: Python<'_>,
    heights: PyReadonlyArray2<'_, f64>,
    size_m: f64,
    path: std::path::PathBuf,
) -> PyResult<()> {
    let s = map_of(py, &heights, size_m)?;
    errors::guard(py, || asperity::surface::writers::write(&s, &path))
}
