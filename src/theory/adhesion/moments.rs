//! The moments of a march's final stress distribution Pr(σ*, q_s) [S-6]: a_r, the mean
//! stress in contact σ̄_c*, its variance and the contact under tension, in closed form for the
//! mirror Gaussian and by an end-corrected trapezoid rule on the grid.

use super::propagator::State;
use statrs::function::erf::erf;

/// (a_r, σ̄_c*, variance, tensile area) of a march's final distribution `state`, sampled
/// as (`sigma`, `density`) with the wall at σ* = −`wall`.
pub(super) fn state_moments(
    state: &State,
    sigma: &[f64],
    density: &[f64],
    p0: f64,
    v: f64,
    wall: f64,
) -> Option<(f64, f64, f64, f64)> {
    if let State::Analytic = state {
        // closed forms of the mirror Gaussian about −wall (shift σ' = σ + wall)
        let d = p0 + wall;
        let sd = v.sqrt();
        let a = crate::theory::mirror::area(d, sd);
        if a <= 0.0 {
            return None;
        }
        let (m1, var) = crate::theory::mirror::contact_moments(d, sd);
        // tensile part: ∫_0^{wall} of the mirror density in σ'
        let tens = if wall > 0.0 && sd > 0.0 {
            let c = |x: f64| 0.5 * (erf((x - d) / (sd * 2f64.sqrt())) - erf((x + d) / (sd * 2f64.sqrt())));
            (c(wall) - c(0.0)).max(0.0)
        } else {
            0.0
        };
        return Some((a, m1 - wall, var, tens));
    }
    let h = sigma.get(1).map(|s1| s1 - sigma[0]).unwrap_or(0.0);
    // trapezoid with the Euler–Maclaurin end correction at the wall (f(0) = 0, f'(0) ≠ 0;
    // f'(0) from a one-sided 3-point difference): O(h³) instead of O(h²)
    let integrate = |f: &dyn Fn(usize) -> f64| -> f64 {
        let n = density.len();
        let sum: f64 = (0..n).map(f).sum::<f64>() * h;
        if n < 3 {
            return sum;
        }
        let d0 = (-3.0 * f(0) + 4.0 * f(1) - f(2)) / (2.0 * h);
        sum + h * h / 12.0 * d0
    };
    let m0 = integrate(&|j| density[j]);
    if m0.is_nan() || m0 <= 0.0 {
        return None;
    }
    let m1 = integrate(&|j| sigma[j] * density[j]) / m0;
    let m2 = integrate(&|j| (sigma[j] - m1) * (sigma[j] - m1) * density[j]) / m0;
    let tens: f64 = sigma
        .iter()
        .zip(density)
        .filter(|(s, _)| **s < 0.0)
        .map(|(_, p)| p)
        .sum::<f64>()
        * h;
    Some((m0, m1, m2.max(0.0), tens))
}
