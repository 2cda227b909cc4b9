//! Adaptive Dormand–Prince 5(4) integration of a scalar ODE y' = F(s, y), with a recorded
//! trajectory for dense (cubic Hermite) output and a running sum of local error estimates.
//!
//! Used for the variance ODE of the adhesionless theory (`theory::persson`), where s = ln q
//! is the resolution and y = V the accumulated stress variance.

use crate::error::{Error, Result};

/// Step-size control settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Control {
    /// Relative tolerance per step.
    pub rtol: f64,
    /// Absolute tolerance per step.
    pub atol: f64,
    /// Hard cap on accepted + rejected steps.
    pub max_steps: usize,
}

/// The accepted points of an integration.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Trajectory {
    /// Independent variable at accepted points (ascending).
    pub s: Vec<f64>,
    /// Solution at accepted points.
    pub y: Vec<f64>,
    /// Derivative F(s, y) at accepted points.
    pub dy: Vec<f64>,
    /// Σ |local error estimate| over accepted steps.
    pub err_sum: f64,
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub evaluations: usize,
}

/// The Dormand–Prince 5(4) tableau: nodes `C[i]` and weights `A[i]` of stage i+1 (stage 1 is
/// the derivative at the step's start), the fifth-order weights `B` of stages 1–6 and the error
/// weights `E` (fifth minus embedded fourth order) of stages 1–7 (stage 7: the derivative at
/// the step's end). Stage 2 enters no sum (its weights are 0).
const C: [f64; 6] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0];
const A: [&[f64]; 6] = [
    &[],
    &[1.0 / 5.0],
    &[3.0 / 40.0, 9.0 / 40.0],
    &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
    &[19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0],
    &[
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
    ],
];
const B: [f64; 6] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Σ wᵢ·kᵢ over the non-zero weights, summed from the first stage on.
fn weighted(w: &[f64], k: &[f64]) -> f64 {
    w.iter()
        .zip(k)
        .skip(1)
        .filter(|(w, _)| **w != 0.0)
        .fold(w[0] * k[0], |acc, (w, k)| acc + w * k)
}

impl Trajectory {
    /// Starts a trajectory at (s0, y0).
    pub fn start(s0: f64, y0: f64, f: &mut impl FnMut(f64, f64) -> f64) -> Self {
        let mut t = Trajectory::default();
        t.s.push(s0);
        t.y.push(y0);
        t.dy.push(f(s0, y0));
        t.evaluations = 1;
        t
    }

    /// Last point (s, y).
    pub fn last(&self) -> (f64, f64) {
        (*self.s.last().unwrap(), *self.y.last().unwrap())
    }

    /// Integrates from the last point to `s_end`, appending accepted points. `h0` is the
    /// first trial step. Fails if the step count exceeds `ctl.max_steps` or a non-finite
    /// value appears.
    pub fn advance(&mut self, s_end: f64, h0: f64, ctl: &Control, f: &mut impl FnMut(f64, f64) -> f64) -> Result<()> {
        let (mut s, mut y) = self.last();
        let mut k1 = *self.dy.last().unwrap();
        let mut h = h0.min(s_end - s).max(1e-300);
        let mut count = 0usize;
        while s < s_end {
            count += 1;
            if count > ctl.max_steps {
                return Err(Error::NotConverged {
                    solver: crate::error::Solver::VarianceOde,
                    reason: format!("more than {} steps at s = {s:.6}, step {h:.3e}", ctl.max_steps),
                });
            }
            let last = s + h >= s_end;
            if last {
                h = s_end - s;
            }
            // Stages 2–6 (stage 2 as (h·a₂₁)·k₁), then the fifth-order step.
            let mut k = [k1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
            k[1] = f(s + C[1] * h, y + h * A[1][0] * k1);
            for i in 2..6 {
                k[i] = f(s + C[i] * h, y + h * weighted(A[i], &k));
            }
            let y_new = y + h * weighted(&B, &k);
            let s_new = if last { s_end } else { s + h };
            k[6] = f(s_new, y_new);
            let k7 = k[6];
            self.evaluations += 6;
            if !(y_new.is_finite() && k7.is_finite()) {
                return Err(Error::NotConverged {
                    solver: crate::error::Solver::VarianceOde,
                    reason: format!("non-finite value at s = {s:.6}"),
                });
            }
            let err = (h * weighted(&E, &k)).abs();
            let scale = ctl.atol + ctl.rtol * y.abs().max(y_new.abs());
            let ratio = err / scale;
            let factor = if ratio == 0.0 {
                5.0
            } else {
                (0.9 * ratio.powf(-0.2)).clamp(0.2, 5.0)
            };
            if ratio <= 1.0 {
                s = s_new;
                y = y_new;
                k1 = k7;
                self.s.push(s);
                self.y.push(y);
                self.dy.push(k7);
                self.err_sum += err;
                self.accepted += 1;
                h *= factor;
            } else {
                self.rejected += 1;
                h *= factor.min(1.0);
            }
        }
        Ok(())
    }

    /// The suggested next step: the last accepted step length (or `fallback`).
    pub fn last_step(&self, fallback: f64) -> f64 {
        let n = self.s.len();
        if n >= 2 {
            self.s[n - 1] - self.s[n - 2]
        } else {
            fallback
        }
    }

    /// Monotone cubic Hermite interpolation of a non-decreasing y at s (clamped to the
    /// trajectory's range): the end slopes of each interval are limited as Fritsch & Carlson
    /// (1980), so the interpolant never leaves [y_i, y_{i+1}]. Where a step is well resolved
    /// (slopes below 3Δy/h) it equals [`Trajectory::eval`].
    pub fn eval_monotone(&self, s: f64) -> f64 {
        let i = match self.interval(s) {
            Ok(i) => i,
            Err(end) => return end,
        };
        let (s0, s1) = (self.s[i], self.s[i + 1]);
        let h = s1 - s0;
        let (y0, y1) = (self.y[i], self.y[i + 1]);
        let dy = y1 - y0;
        if h <= 0.0 || dy <= 0.0 {
            return y1.min(y0.max(y1));
        }
        let t = (s - s0) / h;
        let d0 = (self.dy[i] * h).clamp(0.0, 3.0 * dy);
        let d1 = (self.dy[i + 1] * h).clamp(0.0, 3.0 * dy);
        hermite(t, y0, d0, y1, d1).clamp(y0, y1)
    }

    /// Cubic Hermite interpolation of y at s (clamped to the trajectory's range).
    pub fn eval(&self, s: f64) -> f64 {
        let i = match self.interval(s) {
            Ok(i) => i,
            Err(end) => return end,
        };
        let (s0, s1) = (self.s[i], self.s[i + 1]);
        let h = s1 - s0;
        if h <= 0.0 {
            return self.y[i + 1];
        }
        let t = (s - s0) / h;
        let (y0, y1, d0, d1) = (self.y[i], self.y[i + 1], self.dy[i] * h, self.dy[i + 1] * h);
        hermite(t, y0, d0, y1, d1)
    }

    /// The step holding `s`: `Ok(i)` for s in (s_i, s_{i+1}), `Err(y)` at or beyond an end of
    /// the trajectory (or on a one-point trajectory) with that end's y, where the interpolants
    /// clamp.
    fn interval(&self, s: f64) -> std::result::Result<usize, f64> {
        let n = self.s.len();
        if n == 1 || s <= self.s[0] {
            return Err(self.y[0]);
        }
        if s >= self.s[n - 1] {
            return Err(self.y[n - 1]);
        }
        Ok(self.s.partition_point(|&x| x <= s) - 1)
    }
}

/// The cubic Hermite interpolant at t ∈ [0, 1] with values y0, y1 and slopes d0, d1 (per unit
/// t) at its ends.
fn hermite(t: f64, y0: f64, d0: f64, y1: f64, d1: f64) -> f64 {
    let t2 = t * t;
    let t3 = t2 * t;
    (2.0 * t3 - 3.0 * t2 + 1.0) * y0 + (t3 - 2.0 * t2 + t) * d0 + (-2.0 * t3 + 3.0 * t2) * y1 + (t3 - t2) * d1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponential_growth_to_tolerance() {
        let ctl = Control {
            rtol: 1e-10,
            atol: 1e-14,
            max_steps: 10_000,
        };
        let mut f = |_s: f64, y: f64| y;
        let mut t = Trajectory::start(0.0, 1.0, &mut f);
        t.advance(3.0, 0.1, &ctl, &mut f).unwrap();
        let (_, y) = t.last();
        assert!((y / 3f64.exp() - 1.0).abs() < 1e-8);
        // dense output
        assert!((t.eval(1.234) / 1.234f64.exp() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn stiff_switch_is_resolved_by_rejection() {
        // y' = 1 until y reaches 1e-12, then 0.5: y(1) = 0.5 + 0.5e-12
        let ctl = Control {
            rtol: 1e-9,
            atol: 1e-22,
            max_steps: 100_000,
        };
        let mut f = |_s: f64, y: f64| if y < 1e-12 { 1.0 } else { 0.5 };
        let mut t = Trajectory::start(0.0, 0.0, &mut f);
        t.advance(1.0, 0.01, &ctl, &mut f).unwrap();
        let (_, y) = t.last();
        assert!((y - 0.5).abs() < 1e-8, "{y}");
    }
}
