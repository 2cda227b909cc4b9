//! The step grid of the resolution march: nodes q_k uniform in ln q per PSD segment (or the
//! shells of a discrete spectrum), and per step the variance measure
//! b = ∫_step f²q²dm/(4ḡ²) [S-2, S-15] and the full-contact elastic energy
//! e = ∫_step (qE*f/4) dm (J/m²) [S-11], each by two GL4 panels in ln q.

use crate::input::scene::Scene;
use crate::surface::spectrum::{Spectrum, GL4};
use crate::theory::slab::slab_factor_at;

/// One march step between two resolution nodes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Step {
    /// Midpoint wave number (geometric mean; for a discrete shell its |q|).
    pub(super) q_mid: f64,
    /// ∫_step f²q²dm/(4ḡ²): the step's variance increment for W = 1.
    pub(super) b: f64,
    /// ∫_step (qE*f/4) dm (J/m²): full-contact elastic energy of the step's modes.
    pub(super) e: f64,
    /// ln of the ratio of b's density in ln q at the step's end to that at its start (0 for
    /// a discrete shell).
    pub(super) b_slope: f64,
    /// The same for e.
    pub(super) e_slope: f64,
}

impl Step {
    /// The fraction of the step's b reached where its e reaches the fraction `x_e`, both
    /// densities taken log-linear in ln q over the step (second order in the step): with
    /// F_κ(x) = (e^{κx} − 1)/(e^κ − 1) the fraction of a measure whose log-density rises by κ,
    /// x_b = F_{κ_b}(F_{κ_e}⁻¹(x_e)).
    ///
    /// The onset of a wall inside a step is where C + I (linear in the e-measure) turns
    /// positive, while the march runs in b: in a thin slab's steps the two differ by a few
    /// per cent of the step (`shooting`).
    pub(super) fn b_fraction_of_e(&self, x_e: f64) -> f64 {
        remap(x_e, self.e_slope, self.b_slope)
    }

    /// The inverse of [`Step::b_fraction_of_e`]: the fraction of the step's e reached where
    /// its b reaches the fraction `x_b`.
    pub(super) fn e_fraction_of_b(&self, x_b: f64) -> f64 {
        remap(x_b, self.b_slope, self.e_slope)
    }
}

/// F_κ(x) = (e^{κx} − 1)/(e^κ − 1): the fraction of a measure whose log-density rises by κ
/// over the step, at the fraction x of the step in ln q.
fn fraction(x: f64, kappa: f64) -> f64 {
    if kappa.abs() < 1e-12 {
        x
    } else {
        (kappa * x).exp_m1() / kappa.exp_m1()
    }
}

/// F_to(F_from⁻¹(x)), clamped to [0, 1].
fn remap(x: f64, from: f64, to: f64) -> f64 {
    let x = x.clamp(0.0, 1.0);
    let x_s = if from.abs() < 1e-12 {
        x
    } else {
        (x * from.exp_m1()).ln_1p() / from
    };
    fraction(x_s, to).clamp(0.0, 1.0)
}

/// The step grid of a scene (q nodes and steps).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Grid {
    pub(super) q: Vec<f64>,
    pub(super) steps: Vec<Step>,
}

pub(super) fn build_grid(scene: &Scene, steps_per_ln_q: f64) -> Grid {
    let t = scene.thickness_m();
    let g2 = scene.spectrum.moment(2);
    let es = scene.modulus;
    match &scene.spectrum {
        Spectrum::SelfAffine(_) | Spectrum::Tabulated(_) => {
            let sa = &scene.spectrum;
            let bp = scene.spectrum.breakpoints();
            let mut q = vec![bp[0]];
            let mut steps = Vec::new();
            // ∫_{s0}^{s1} g(q) dm over ln q with 2 GL4 panels per step (the integrands are smooth)
            let integ = |s0: f64, s1: f64, g: &dyn Fn(f64) -> f64| -> f64 {
                let mut sum = 0.0;
                for half in 0..2 {
                    let a = s0 + (s1 - s0) * half as f64 / 2.0;
                    let bb = a + (s1 - s0) / 2.0;
                    for &(x, w) in &GL4 {
                        let s = 0.5 * (a + bb) + 0.5 * (bb - a) * x;
                        let qq = s.exp();
                        sum += 0.5 * (bb - a) * w * g(qq) * sa.dm_dlnq(qq);
                    }
                }
                sum
            };
            for w in bp.windows(2) {
                let (s0, s1) = (w[0].ln(), w[1].ln());
                let n = ((s1 - s0) * steps_per_ln_q).ceil().max(4.0) as usize;
                for k in 0..n {
                    let a = s0 + (s1 - s0) * k as f64 / n as f64;
                    let bb = s0 + (s1 - s0) * (k + 1) as f64 / n as f64;
                    let mid = 0.5 * (a + bb);
                    let bfun = |qq: f64| {
                        let f = slab_factor_at(qq, t);
                        f * f * qq * qq / (4.0 * g2)
                    };
                    let efun = |qq: f64| qq * es * slab_factor_at(qq, t) / 4.0;
                    // log-densities in ln q at the ends (dm/dln q is smooth inside a segment;
                    // taken just inside it, on the segment's side of a breakpoint)
                    let slope = |g: &dyn Fn(f64) -> f64| {
                        let nudge = 1e-9 * (bb - a);
                        let (qa, qb) = ((a + nudge).exp(), (bb - nudge).exp());
                        let (da, db) = (g(qa) * sa.dm_dlnq(qa), g(qb) * sa.dm_dlnq(qb));
                        if da > 0.0 && db > 0.0 {
                            (db / da).ln()
                        } else {
                            0.0
                        }
                    };
                    steps.push(Step {
                        q_mid: mid.exp(),
                        b: integ(a, bb, &bfun),
                        e: integ(a, bb, &efun),
                        b_slope: slope(&bfun),
                        e_slope: slope(&efun),
                    });
                    q.push(bb.exp());
                }
            }
            Grid { q, steps }
        }
        Spectrum::Discrete(d) => {
            let mut q = vec![d.modes[0].q];
            let mut steps = Vec::with_capacity(d.modes.len());
            for m in &d.modes {
                let f = slab_factor_at(m.q, t);
                let e = m.q * es * f / 4.0 * m.dm;
                steps.push(Step {
                    q_mid: m.q,
                    b: f * f * m.q * m.q * m.dm / (4.0 * g2),
                    e,
                    b_slope: 0.0,
                    e_slope: 0.0,
                });
                q.push(m.q);
            }
            Grid { q, steps }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fraction_maps_invert_each_other_and_match_the_measures() {
        let st = Step {
            q_mid: 1.0,
            b: 1.0,
            e: 1.0,
            b_slope: 0.7,
            e_slope: -0.3,
        };
        for x in [0.0, 0.1, 0.5, 0.93, 1.0] {
            assert!((st.e_fraction_of_b(st.b_fraction_of_e(x)) - x).abs() < 1e-14, "{x}");
            // the b fraction where e reaches x, by quadrature of the densities e^{κs}
            let x_s = (x * (-0.3f64).exp_m1()).ln_1p() / -0.3;
            let n = 20_000;
            let b_num: f64 = (0..n)
                .map(|i| ((i as f64 + 0.5) / n as f64 * x_s * 0.7).exp())
                .sum::<f64>()
                * x_s
                / n as f64;
            let b_all = 0.7f64.exp_m1() / 0.7;
            assert!((st.b_fraction_of_e(x) - b_num / b_all).abs() < 1e-8, "{x}");
        }
    }
}
