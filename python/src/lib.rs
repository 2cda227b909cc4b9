//! `asperity._native`: the extension module of the `asperity` Python package (PyO3, abi3 for
//! CPython >= 3.9). A thin layer on the library: every function here calls the library's own
//! (the same calls as the `asperity` binary's commands) and hands its result to Python as a
//! frozen result class converted in Rust: a `Report`, or a `Record` of the library's report
//! (GFMD's, a PSD's, a gauge's, a sweep's), each with the keys of the CLI's JSON. The documented API (classes `Scene`, `SweepResult`, ...,
//! docstrings with units and \[S\] equation numbers) is the pure-Python package in
//! `python/asperity/`; this module is its engine.
//!
//! - [`scene`]: the validated scene (`Scene.preset`, `Scene(...)`, `Scene.replace`);
//! - [`theory`]: `evaluate` ([`asperity::report::point()`], a [`report::Report`]), `sweep` (loads, t·q_r, γ_s),
//!   `cycle` (the theory's path along a load cycle), `pull_off` (the pull-off read-out);
//! - [`gfmd`]: one GFMD run on a generated or given map; [`gfmd_cycle`]: GFMD's load cycle
//!   through tension to pull-off;
//! - [`surface`]: `read_surface`, `psd`; [`generate`]: `generate_surface`, `write_surface`;
//!   [`measured`]: a preset's `[measured]` section;
//! - [`args`]: the library's range table for the Python side of every argument;
//! - [`gauge`]: fitting the custom model to a reference;
//! - [`work`]: long work off the GIL, cancelled by Ctrl-C;
//! - [`report`]: `Report`, `evaluate`'s result, a frozen class converted from the library's
//!   report; [`record`]: result parts read as attributes, built once;
//! - [`errors`]: the library's typed errors as Python exceptions; [`value`]: serde values as
//!   Python objects (pythonize).

pub mod args;
pub mod errors;
pub mod gauge;
pub mod generate;
pub mod gfmd;
pub mod gfmd_cycle;
pub mod measured;
pub mod record;
pub mod report;
pub mod scene;
pub mod surface;
pub mod theory;
pub mod value;
pub mod work;

use pyo3::prelude::*;

/// Panics on purpose, for the tests of the panic boundary: `where_ = "worker"` on the worker
/// thread of [`work::run`], anything else on the calling thread (inside [`errors::guard`]).
#[pyfunction]
fn _panic(py: Python<'_>, where_: &str) -> PyResult<()> {
    if where_ == "worker" {
        work::run(py, None, |_| -> asperity::Result<()> {
            panic!("test panic on the worker")
        })
    } else {
        errors::guard(py, || -> asperity::Result<()> {
            panic!("test panic on the calling thread")
        })
    }
}

/// Sleeps `seconds` on the worker, in steps of 10 ms that watch the cancel flag (for the tests
/// of cancellation: returns the seconds slept).
#[pyfunction]
#[pyo3(signature = (seconds, progress = None))]
fn _sleep(py: Python<'_>, seconds: f64, progress: Option<Bound<'_, PyAny>>) -> PyResult<f64> {
    work::run(py, progress.as_ref(), move |ctx| {
        let t0 = std::time::Instant::now();
        while t0.elapsed().as_secs_f64() < seconds {
            if ctx.cancel.load(std::sync::atomic::Ordering::Relaxed) {
                return Err(asperity::Error::Cancelled);
            }
            ctx.report(work::Info {
                stage: "sleep",
                ..work::Info::default()
            });
            std::thread::sleep(std::time::Duration::from_millis(10));
        }
        Ok(t0.elapsed().as_secs_f64())
    })
}

/// The module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<scene::SceneCore>()?;
    m.add_class::<record::Record>()?;
    m.add_class::<report::Report>()?;
    m.add_class::<report::Pr>()?;
    m.add_class::<report::Resolution>()?;
    m.add_class::<report::BranchReport>()?;
    m.add_function(wrap_pyfunction!(scene::scene_from_preset, m)?)?;
    m.add_function(wrap_pyfunction!(scene::scene_new, m)?)?;
    m.add_function(wrap_pyfunction!(theory::evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(theory::run_sweep, m)?)?;
    m.add_function(wrap_pyfunction!(theory::run_cycle, m)?)?;
    m.add_function(wrap_pyfunction!(theory::run_pull_off, m)?)?;
    m.add_function(wrap_pyfunction!(gfmd::run_gfmd, m)?)?;
    m.add_function(wrap_pyfunction!(gfmd_cycle::run_gfmd_cycle, m)?)?;
    m.add_function(wrap_pyfunction!(surface::read_surface, m)?)?;
    m.add_function(wrap_pyfunction!(surface::map_psd, m)?)?;
    m.add_function(wrap_pyfunction!(gauge::run_gauge, m)?)?;
    m.add_function(wrap_pyfunction!(generate::generate_surface, m)?)?;
    m.add_function(wrap_pyfunction!(generate::write_surface, m)?)?;
    m.add_function(wrap_pyfunction!(args::allowed, m)?)?;
    m.add(
        "ADHESION_RESOLUTION_MAX",
        asperity::gfmd::reduction::ADHESION_RESOLUTION_MAX,
    )?;
    m.add_function(wrap_pyfunction!(_panic, m)?)?;
    m.add_function(wrap_pyfunction!(_sleep, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
