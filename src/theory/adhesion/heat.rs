//! The exact step of the propagator (`propagator`): drift–diffusion on [0, X] with an
//! absorbing end at x = 0 and a constant drift c over the step (the wall moving linearly in
//! the variance v), by the image solution with weights e^{−2cy} and one FFT pair:
//!
//! ```text
//! ∂p/∂v = ½ ∂²p/∂x² − c ∂p/∂x,  p(0, v) = 0   ⇒   p(x, v) = [G_v * p̃](x − cv),
//! p̃(y) = p(y) (y > 0),  p̃(−y) = −e^{−2cy} p(y)
//! ```
//!
//! (p = e^{cx − c²v/2}u turns the problem into the heat equation for u with the same Dirichlet
//! end; completing the squares in the image kernel gives the weights.) c = 0 is the Dirichlet
//! heat semigroup (the mirror-Gaussian solution). Reduced units as in the parent module.

// index loops mirror the formulas (nodes j, modes k) in this numerical module
#![allow(clippy::needless_range_loop)]

use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::cell::RefCell;
use std::collections::HashMap;
use std::f64::consts::PI;
use std::sync::Arc;

thread_local! {
    /// The FFT plans of this thread by length, kept across marches and solves: the grid's
    /// size changes from step to step, and planning each size afresh for every solve
    /// (twiddles, AVX set-up) was 8 % of a cold solve at (8, 5). Each length is planned by a
    /// planner of its own: a shared planner builds a length from the sub-plans it already
    /// holds, so its plans (and the last bits of the results) depended on what it had
    /// planned before, i.e. on which solves a thread had run.
    static PLANS: RefCell<HashMap<usize, Pair>> = RefCell::new(HashMap::new());
}

/// Longest transform kept in [`PLANS`]: the usual grids are far shorter, and the few
/// refined for a fast wall (up to 2¹⁷) would otherwise hold their twiddles for the life of
/// the thread.
const CACHED_MAX: usize = 1 << 13;

/// The forward and inverse transforms of length m (see [`PLANS`]).
fn plans(m: usize) -> Pair {
    if m > CACHED_MAX {
        let mut planner = FftPlanner::new();
        return (planner.plan_fft_forward(m), planner.plan_fft_inverse(m));
    }
    PLANS.with(|cache| {
        cache
            .borrow_mut()
            .entry(m)
            .or_insert_with(|| {
                let mut planner = FftPlanner::new();
                (planner.plan_fft_forward(m), planner.plan_fft_inverse(m))
            })
            .clone()
    })
}

/// Interleaved recurrence chains of [`Heat::mass`] (its start values are written for 4).
const CHAINS: usize = 4;
/// The odd modes dropped from [`Heat::mass`] sum to below this fraction of the mass bound
/// |ĉ₀X| + Σ|terms| in magnitude (round-off of the sum is larger).
const TAIL: f64 = 1e-17;

/// Forward and inverse FFTs of one length.
type Plan = (usize, Arc<dyn Fft<f64>>, Arc<dyn Fft<f64>>);
/// A forward and an inverse FFT.
type Pair = (Arc<dyn Fft<f64>>, Arc<dyn Fft<f64>>);

/// The exact step of drift–diffusion on [0, X] with an absorbing (Dirichlet) end at 0 and a
/// constant drift c, for a grid of N intervals (c = 0: the Dirichlet heat semigroup).
///
/// ∂p/∂v = ½∂²p/∂x² − c ∂p/∂x, p(0) = 0, has the Green's function
/// G(x − y − cv) − e^{−2cy} G(x + y − cv) (images weighted by e^{−2cy}), so
/// p(x, v) = [G_v * p̃](x − cv) with the weighted odd extension p̃(−y) = −e^{−2cy} p(y): one
/// FFT of length 2N of p̃, heat factor exp(−½κ²v) and shift phase exp(−iκcv) per mode, one
/// inverse FFT. With `ext_rate` = 0 the extension is the plain odd one (c = 0, or a grid
/// whose lower end is not the wall and carries no density).
pub(super) struct Heat {
    plan: Option<Plan>,
    buf: Vec<Complex64>,
    scratch: Vec<Complex64>,
    /// −(4/κ_k)·ĉ_k per odd mode k = 1, 3, 5, … (the mass integral, see [`Heat::mass`]).
    terms: Vec<Complex64>,
    /// The odd modes' terms that matter: the rest of `terms` sums to below 1e-17 of the
    /// mass in magnitude (the loaded spectrum of a resolved density decays fast).
    cutoff: usize,
    /// ĉ₀·X: the mean mode's share of the mass.
    mean_mass: f64,
    /// Decay rate of mode 1, ½(π/X)²: mode k decays at k² times it.
    rate1: f64,
    /// The drift c (shift per unit variance).
    drift: f64,
    n: usize,
    x: f64,
}

impl Heat {
    pub(super) fn new() -> Self {
        Heat {
            plan: None,
            buf: Vec::new(),
            scratch: Vec::new(),
            terms: Vec::new(),
            cutoff: 0,
            mean_mass: 0.0,
            rate1: 0.0,
            drift: 0.0,
            n: 0,
            x: 0.0,
        }
    }

    /// Loads grid values p at x_j = j·h, j = 0..=N (p[0] = p[N] = 0) with the drift c and the
    /// extension weight exp(−`ext_rate`·y) (2c for the true wall at x = 0, 0 otherwise): one
    /// forward transform. Afterwards [`Heat::mass`] gives ∫_0^X p dx after any variance u in
    /// O(N), and [`Heat::finish`] writes the evolved values back.
    pub(super) fn load(&mut self, p: &[f64], h: f64, ext_rate: f64, drift: f64) {
        let n = p.len() - 1;
        let m = 2 * n;
        if self.plan.as_ref().map(|pl| pl.0) != Some(m) {
            let (fwd, inv) = plans(m);
            let len = fwd.get_inplace_scratch_len().max(inv.get_inplace_scratch_len());
            self.scratch.resize(len, Complex64::new(0.0, 0.0));
            self.plan = Some((m, fwd, inv));
        }
        let (_, fwd, _) = self.plan.as_ref().expect("planned");
        self.buf.clear();
        self.buf.resize(m, Complex64::new(0.0, 0.0));
        // exp(−ext_rate·j h) by recurrence
        let r = (-ext_rate * h).exp();
        let mut w = 1.0;
        for j in 1..n {
            w *= r;
            self.buf[j] = Complex64::new(p[j], 0.0);
            self.buf[m - j] = Complex64::new(-w * p[j], 0.0);
        }
        fwd.process_with_scratch(&mut self.buf, &mut self.scratch);
        let x = n as f64 * h;
        self.n = n;
        self.x = x;
        self.drift = drift;
        // ∫_{−a}^{X−a} e^{iκz} dz = 2i e^{−iκa}/κ for odd k, 0 for even k ≠ 0, X for k = 0;
        // the pair ±k gives −(4/κ) Im(ĉ_k e^{−iκa}): spectral, where the trapezoid rule is
        // O(h²) because p'(0) ≠ 0
        let inv_m = 1.0 / m as f64;
        self.mean_mass = self.buf[0].re * inv_m * x;
        self.terms.clear();
        for k in (1..n).step_by(2) {
            let kappa = k as f64 * PI / x;
            self.terms.push(self.buf[k] * (-4.0 * inv_m / kappa));
        }
        self.rate1 = 0.5 * (PI / x) * (PI / x);
        // drop the tail whose magnitudes sum to below TAIL of the mass bound
        let total: f64 = self.mean_mass.abs() + self.terms.iter().map(|c| c.re.abs() + c.im.abs()).sum::<f64>();
        let mut tail = 0.0;
        self.cutoff = self.terms.len();
        while self.cutoff > 0 {
            let c = self.terms[self.cutoff - 1];
            tail += c.re.abs() + c.im.abs();
            if tail > TAIL * total {
                break;
            }
            self.cutoff -= 1;
        }
    }

    /// ∫_0^X p dx after a further variance u (exact for the loaded trigonometric interpolant,
    /// up to the dropped tail of [`Heat::load`], below 1e-17 of the mass).
    ///
    /// exp(−r₁k²u) by recurrence, in [`CHAINS`] interleaved chains (modes k, k + 2·CHAINS, …
    /// in each, so that the chains' products and sums do not wait on each other): with
    /// E = exp(−r₁u), E^{(k+2L)²} = E^{k²}·E^{4Lk+4L²}, and the ratio grows by E^{8L²} per
    /// link; the shift phase exp(−ikθ) advances by exp(−2iLθ). One exp per call instead of
    /// one per mode.
    pub(super) fn mass(&self, u: f64) -> f64 {
        const L: usize = CHAINS;
        let terms = &self.terms[..self.cutoff];
        let e = (-self.rate1 * u).exp();
        // the chains start at modes 1, 3, 5, 7: E^{k²} and the ratio E^{16k+64}, by squaring
        let e2 = e * e;
        let e8 = e2 * e2 * e2 * e2;
        let e16 = e8 * e8;
        let e32 = e16 * e16;
        let e64 = e32 * e32;
        let grow = e64 * e64;
        let mut pow = [e, e8 * e, e16 * e8 * e, e32 * e16 * e];
        let mut ratio = [e64 * e16, e64 * e32 * e16, grow * e16, grow * e32 * e16];
        // beyond mode k_max, E^{k²} < 1e-300: nothing left
        let k_max = if self.rate1 * u > 0.0 {
            (690.0 / (self.rate1 * u)).sqrt()
        } else {
            f64::INFINITY
        };
        let len = terms
            .len()
            .min(((k_max + 1.0) * 0.5).min(terms.len() as f64) as usize + 1);
        let terms = &terms[..len];
        let mut sum = [0.0f64; L];
        let blocks = terms.chunks_exact(L);
        let rest = blocks.remainder();
        if self.drift == 0.0 {
            for block in blocks {
                for r in 0..L {
                    sum[r] += block[r].im * pow[r];
                    pow[r] *= ratio[r];
                    ratio[r] *= grow;
                }
            }
            for (r, c) in rest.iter().enumerate() {
                sum[r] += c.im * pow[r];
            }
        } else {
            let theta = PI * self.drift * u / self.x;
            // the phases exp(−ikθ) of modes 1, 3, 5, 7 and the step exp(−8iθ), from one sincos
            let p1 = Complex64::from_polar(1.0, -theta);
            let p2 = p1 * p1;
            let p3 = p2 * p1;
            let p5 = p3 * p2;
            let p7 = p5 * p2;
            let p4 = p2 * p2;
            let rot = p4 * p4;
            let mut re = [p1.re, p3.re, p5.re, p7.re];
            let mut im = [p1.im, p3.im, p5.im, p7.im];
            for block in blocks {
                for r in 0..L {
                    // Im(c·phase)
                    sum[r] += (block[r].re * im[r] + block[r].im * re[r]) * pow[r];
                    pow[r] *= ratio[r];
                    ratio[r] *= grow;
                    let nre = re[r] * rot.re - im[r] * rot.im;
                    im[r] = re[r] * rot.im + im[r] * rot.re;
                    re[r] = nre;
                }
            }
            for (r, c) in rest.iter().enumerate() {
                sum[r] += (c.re * im[r] + c.im * re[r]) * pow[r];
            }
        }
        self.mean_mass + sum.iter().sum::<f64>()
    }

    /// Writes the loaded values evolved by dv back into p.
    pub(super) fn finish(&mut self, p: &mut [f64], dv: f64) {
        let (n, x) = (self.n, self.x);
        let m = 2 * n;
        let (_, _, inv) = self.plan.as_ref().expect("loaded");
        // exp(−c k²)/m by the same recurrence as `mass`, applied to modes k and m − k (the
        // shift phase exp(∓ikθ) with them)
        let e = (-0.5 * dv * (PI / x) * (PI / x)).exp();
        let e2 = e * e;
        let theta = PI * self.drift * dv / x;
        let rot = Complex64::from_polar(1.0, -theta);
        let mut phase = Complex64::new(1.0, 0.0);
        let (mut pow, mut ratio) = (1.0 / m as f64, e);
        for k in 0..=n {
            if pow < 1e-300 {
                pow = 0.0; // and stays 0: no denormal arithmetic
            }
            if k == n {
                // the Nyquist mode: the real part of its shift
                self.buf[k] *= pow * phase.re;
            } else {
                self.buf[k] *= phase * pow;
                if k > 0 {
                    self.buf[m - k] *= phase.conj() * pow;
                }
            }
            if pow > 0.0 {
                pow *= ratio;
                ratio *= e2;
            }
            phase *= rot;
        }
        inv.process_with_scratch(&mut self.buf, &mut self.scratch);
        p[0] = 0.0;
        p[n] = 0.0;
        for j in 1..n {
            p[j] = self.buf[j].re;
        }
    }

    /// Evolves p by dv (no drift) and returns its integral.
    #[cfg(test)]
    pub(super) fn apply(&mut self, p: &mut [f64], h: f64, dv: f64) -> f64 {
        self.load(p, h, 0.0, 0.0);
        let mass = self.mass(dv);
        self.finish(p, dv);
        mass
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The point-source solution of drift–diffusion with an absorbing wall at 0 (started at
    /// y0 > 0, variance v, drift c): G(x − y0 − cv) − e^{−2c·y0} G(x + y0 − cv) — the
    /// classical image formula, sharing no code with the FFT step.
    fn source(x: f64, y0: f64, v: f64, c: f64) -> f64 {
        let g = |z: f64| (-z * z / (2.0 * v)).exp() / (2.0 * PI * v).sqrt();
        g(x - y0 - c * v) - (-2.0 * c * y0).exp() * g(x + y0 - c * v)
    }

    #[test]
    fn drift_step_matches_the_image_solution() {
        // from the exact state at v0 to v0 + dv with drift c: values and mass
        for (y0, v0, dv, c) in [
            (0.3f64, 0.02f64, 0.01f64, 2.0f64),
            (0.1, 0.01, 0.004, 8.0),
            (0.5, 0.05, 0.02, 0.5),
        ] {
            let h = v0.sqrt() / 20.0;
            let n = ((y0 + c * (v0 + dv) + 12.0 * (v0 + dv).sqrt()) / h).ceil() as usize;
            let mut p: Vec<f64> = (0..=n)
                .map(|j| {
                    if j == 0 || j == n {
                        0.0
                    } else {
                        source(j as f64 * h, y0, v0, c)
                    }
                })
                .collect();
            let mut heat = Heat::new();
            heat.load(&p, h, 2.0 * c, c);
            let mass = heat.mass(dv);
            heat.finish(&mut p, dv);
            let v = v0 + dv;
            let mut exact_mass = 0.0;
            for (j, pj) in p.iter().enumerate() {
                let exact = source(j as f64 * h, y0, v, c);
                assert!((pj - exact).abs() < 1e-9, "{j}: {pj} vs {exact}");
                exact_mass += exact * h;
            }
            // trapezoid of the exact solution (O(h²) at the wall) against the spectral mass
            assert!((mass - exact_mass).abs() < 1e-4, "{mass} vs {exact_mass}");
        }
    }
}
