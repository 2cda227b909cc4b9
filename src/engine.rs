//! The engine facade: one call evaluates a scene with whatever the scene needs (the
//! adhesionless mirror-Gaussian path when γ_s = 0, the adhesive solver otherwise) and returns
//! the quantities every front end shows. The CLI and the TUI call only this (and the sweep).

use crate::error::{Error, Result};
use crate::persson::{self, Accuracy, ResolutionPoint};
use crate::scene::Scene;
use serde::Serialize;
use std::time::Instant;

/// Options of one evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Accuracy of the adhesionless variance ODE.
    pub accuracy: Accuracy,
    /// Number of σ* points of the sampled Pr(σ*).
    pub sigma_points: usize,
    /// Largest σ* of the sample (None: p* + 5Δ*).
    pub sigma_max: Option<f64>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            accuracy: Accuracy::default(),
            sigma_points: 201,
            sigma_max: None,
        }
    }
}

/// Pr(σ*) sampled on a grid (reduced units; ∫density dσ* = a_r).
#[derive(Debug, Clone, Serialize, PartialEq, Default)]
pub struct PrCurve {
    /// σ* grid (ascending; starts at −σ_a* when adhesion is on).
    pub sigma: Vec<f64>,
    /// Pr(σ*).
    pub density: Vec<f64>,
}

/// The result of one evaluation.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Evaluation {
    /// Relative contact area a_r(q_s).
    pub a_r: f64,
    /// σ̄_c* (reduced by E*ḡ).
    pub mean_contact_stress: f64,
    /// ⟨δσ_c²⟩* (reduced by (E*ḡ)²).
    pub contact_stress_variance: f64,
    /// Width of the final stress distribution Δ* (adhesionless: √v(q_s)).
    pub width: f64,
    /// Pr(σ*).
    pub pr: PrCurve,
    /// a_r(q) along the resolution.
    pub resolution: Vec<ResolutionPoint>,
    /// Whether the solver met its tolerance (an unconverged result is never returned as Ok
    /// with `converged = true`).
    pub converged: bool,
    /// Estimated absolute error of a_r.
    pub error_estimate: f64,
    /// Elastic energy U per nominal area (J/m²) [S-11]; see [`crate::energy`].
    pub elastic_energy: f64,
    /// Wall time (s).
    pub elapsed_s: f64,
}

/// Evaluates a scene.
pub fn evaluate(scene: &Scene, opts: &Options) -> Result<Evaluation> {
    scene.validate()?;
    let t0 = Instant::now();
    if scene.gamma > 0.0 {
        return Err(Error::Unsupported(format!(
            "gamma = {} J/m^2 (adhesion) is not yet supported by this build; use gamma 0",
            scene.gamma
        )));
    }
    let sol = persson::solve(scene, &opts.accuracy)?;
    let sigma_max = match opts.sigma_max {
        Some(s) if s.is_finite() && s > 0.0 => s,
        Some(s) => return Err(Error::field("sigma_max", s, "sigma* > 0")),
        None => sol.default_sigma_max(),
    };
    let (sigma, density) = sol.sample(sigma_max, opts.sigma_points);
    let elastic_energy = crate::energy::elastic_energy(scene, |q| sol.area_at(q));
    Ok(Evaluation {
        a_r: sol.a_r,
        mean_contact_stress: sol.mean_contact_stress,
        contact_stress_variance: sol.contact_stress_variance,
        width: sol.width,
        pr: PrCurve { sigma, density },
        resolution: sol.resolution,
        converged: true,
        error_estimate: sol.error_estimate,
        elastic_energy,
        elapsed_s: t0.elapsed().as_secs_f64(),
    })
}
