//! A ladder's rungs and hard cases as plain data, and what every ladder uses: the median wall
//! time, the relative error, the scenes of a case.

use asperity::error::Result;
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use serde::Serialize;
use std::time::Instant;

/// One rung of a ladder.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Rung {
    /// Solver name ("adhesionless theory", ...).
    pub solver: String,
    /// The case (preset, model, load, thickness).
    pub case: String,
    /// The accuracy setting of this rung.
    pub setting: String,
    /// Whether this rung is the solver's default.
    pub default: bool,
    /// Median wall time (s).
    pub median_s: f64,
    /// Number of timed runs.
    pub runs: usize,
    /// (quantity, relative error against the reference).
    pub errors: Vec<(String, f64)>,
    /// Bound on the largest error (checked on default rungs).
    pub bound: Option<f64>,
    /// Memory of the solution's working arrays (bytes), where meaningful.
    pub memory_bytes: Option<u64>,
}

impl Rung {
    /// Largest relative error of the rung.
    pub fn max_error(&self) -> f64 {
        self.errors.iter().map(|e| e.1).fold(0.0, f64::max)
    }
    /// True if the rung has a bound and exceeds it.
    pub fn violates(&self) -> bool {
        let e = self.max_error();
        self.bound.is_some_and(|b| e.is_nan() || e > b)
    }
}

/// A hard case and its outcome.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct HardCase {
    /// Solver.
    pub solver: String,
    /// Description of the case.
    pub case: String,
    /// Outcome: "converged", or the error message.
    pub outcome: String,
    /// Key number (a_r) if converged.
    pub a_r: Option<f64>,
    /// Error estimate / residual reported by the solver.
    pub residual: Option<f64>,
    /// Wall time (s).
    pub time_s: f64,
}

/// The whole report.
#[derive(Debug, Clone, Serialize, PartialEq, Default)]
pub struct Report {
    /// Ladders.
    pub rungs: Vec<Rung>,
    /// Hard cases.
    pub hard_cases: Vec<HardCase>,
}

/// Median wall time of `f` over `runs` runs (after one warm-up), in seconds.
pub fn median_time<T>(runs: usize, mut f: impl FnMut() -> T) -> f64 {
    std::hint::black_box(f());
    let mut t: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let t0 = Instant::now();
            std::hint::black_box(f());
            t0.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(|a, b| a.partial_cmp(b).unwrap());
    t[t.len() / 2]
}

/// |a/b − 1|, or |a| where the reference b is 0.
pub(super) fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        (a / b - 1.0).abs()
    }
}

/// The preset's scene with `model`, load p*, thickness t·q_r and no adhesion.
pub(super) fn scene_of(preset: &str, model: u8, p: f64, t: f64) -> Result<Scene> {
    let mut s = Preset::resolve(preset)?.scene()?;
    s.set_model(Model::named(model)?)?;
    s.set_pressure(p)?;
    s.set_thickness_qr(t)?;
    s = s.without_adhesion();
    Ok(s)
}

/// A thickness t·q_r in a case's name (`inf` for the half-space).
pub(super) fn fmt_t(t: f64) -> String {
    if t.is_infinite() {
        "inf".into()
    } else {
        format!("{t}")
    }
}
