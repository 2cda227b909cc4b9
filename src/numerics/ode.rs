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

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const B1: f64 = 35.0 / 384.0;
const B3: f64 = 500.0 / 1113.0;
const B4: f64 = 125.0 / 192.0;
const B5: f64 = -2187.0 / 6784.0;
const B6: f64 = 11.0 / 84.0;
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;

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
            let k2 = f(s + C2 * h, y + h * A21 * k1);
            let k3 = f(s + C3 * h, y + h * (A31 * k1 + A32 * k2));
            let k4 = f(s + C4 * h, y + h * (A41 * k1 + A42 * k2 + A43 * k3));
            let k5 = f(s + C5 * h, y + h * (A51 * k1 + A52 * k2 + A53 * k3 + A54 * k4));
            let k6 = f(s + h, y + h * (A61 * k1 + A62 * k2 + A63 * k3 + A64 * k4 + A65 * k5));
            let y_new = y + h * (B1 * k1 + B3 * k3 + B4 * k4 + B5 * k5 + B6 * k6);
            let s_new = if last { s_end } else { s + h };
            let k7 = f(s_new, y_new);
            self.evaluations += 6;
            if !(y_new.is_finite() && k7.is_finite()) {
                return Err(Error::NotConverged {
                    solver: crate::error::Solver::VarianceOde,
                    reason: format!("non-finite value at s = {s:.6}"),
                });
            }
            let err = (h * (E1 * k1 + E3 * k3 + E4 * k4 + E5 * k5 + E6 * k6 + E7 * k7)).abs();
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
        let n = self.s.len();
        if n == 1 || s <= self.s[0] {
            return self.y[0];
        }
        if s >= self.s[n - 1] {
            return self.y[n - 1];
        }
        let i = self.s.partition_point(|&x| x <= s) - 1;
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
        let t2 = t * t;
        let t3 = t2 * t;
        let v =
            (2.0 * t3 - 3.0 * t2 + 1.0) * y0 + (t3 - 2.0 * t2 + t) * d0 + (-2.0 * t3 + 3.0 * t2) * y1 + (t3 - t2) * d1;
        v.clamp(y0, y1)
    }

    /// Cubic Hermite interpolation of y at s (clamped to the trajectory's range).
    pub fn eval(&self, s: f64) -> f64 {
        let n = self.s.len();
        if n == 1 || s <= self.s[0] {
            return self.y[0];
        }
        if s >= self.s[n - 1] {
            return self.y[n - 1];
        }
        let i = self.s.partition_point(|&x| x <= s) - 1;
        let (s0, s1) = (self.s[i], self.s[i + 1]);
        let h = s1 - s0;
        if h <= 0.0 {
            return self.y[i + 1];
        }
        let t = (s - s0) / h;
        let (y0, y1, d0, d1) = (self.y[i], self.y[i + 1], self.dy[i] * h, self.dy[i + 1] * h);
        let t2 = t * t;
        let t3 = t2 * t;
        (2.0 * t3 - 3.0 * t2 + 1.0) * y0 + (t3 - 2.0 * t2 + t) * d0 + (-2.0 * t3 + 3.0 * t2) * y1 + (t3 - t2) * d1
    }
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
