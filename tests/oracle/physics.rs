//! The scene's numbers, re-derived here from the paper: the self-affine PSD and its measure
//! dm = 2πqC(q)dq, the rms gradient ḡ² = ∫q²dm, the slab factor f(qt) [S-4], the weight
//! function W(a) [S-17] and the Griffith wall σ_a = k_G√(qE*fγ) [S-8] (capped at γ_s/ρ where
//! the model says so). Only the scene's input parameters are read from the library; every
//! formula and quadrature is written here again (5-point Gauss–Legendre in q, series or
//! exponentially scaled closed form for f).

use asperity::input::scene::Scene;
use asperity::surface::spectrum::Spectrum;
use std::f64::consts::PI;

/// 5-point Gauss–Legendre on [−1, 1] (nodes, weights).
const GL5: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// Everything the oracle needs from a scene, in SI units (stresses reduced where said).
#[derive(Debug, Clone, Copy)]
pub struct Physics {
    pub q_l: f64,
    pub q_r: f64,
    pub q_s: f64,
    pub hurst: f64,
    pub c0: f64,
    /// E* (Pa).
    pub modulus: f64,
    /// γ_s (J/m²).
    pub gamma: f64,
    /// ρ (m).
    pub range: f64,
    /// p* (reduced).
    pub pressure: f64,
    /// Slab thickness t (m), ∞ for a half-space.
    pub thickness: f64,
    pub c1: f64,
    pub c2: f64,
    pub alpha: f64,
    pub k_griffith: f64,
    pub cap: bool,
    /// ḡ, from this module's own quadrature.
    pub gbar: f64,
}

impl Physics {
    /// Reads the scene's parameters (self-affine spectra only).
    pub fn from_scene(s: &Scene) -> Physics {
        let Spectrum::SelfAffine(sa) = &s.spectrum() else {
            panic!("the oracle handles self-affine spectra only");
        };
        let q_r = 2.0 * PI / sa.lambda_r;
        let mut p = Physics {
            q_l: 2.0 * PI / sa.system_size,
            q_r,
            q_s: 2.0 * PI / sa.lambda_s,
            hurst: sa.hurst,
            c0: sa.c0,
            modulus: s.contact_modulus_pa(),
            gamma: s.surface_energy_j_m2(),
            range: s.range_m(),
            pressure: s.pressure(),
            thickness: if s.thickness_qr().is_infinite() {
                f64::INFINITY
            } else {
                s.thickness_qr() / q_r
            },
            c1: s.model().c1,
            c2: s.model().c2,
            alpha: s.model().alpha,
            k_griffith: s.model().k_griffith,
            cap: s.model().cap,
            gbar: 1.0,
        };
        p.gbar = p.integrate_panels(|q| q * q).sqrt();
        p
    }

    /// C(q) (m⁴).
    pub fn psd(&self, q: f64) -> f64 {
        if q < self.q_l || q > self.q_s {
            0.0
        } else if q <= self.q_r {
            self.c0
        } else {
            self.c0 * (q / self.q_r).powf(-2.0 - 2.0 * self.hurst)
        }
    }

    /// dm/dq = 2πqC(q).
    pub fn dm_dq(&self, q: f64) -> f64 {
        2.0 * PI * q * self.psd(q)
    }

    /// f(qt) of [S-4]: the power series of numerator and denominator below x = 1 (all terms
    /// positive, no cancellation), the form scaled by e^{−2x} above.
    pub fn slab(&self, q: f64) -> f64 {
        slab_factor(q * self.thickness)
    }

    /// W(a) = 1 − c₁(1 − a²) − c₂(1 − a⁴) [S-17].
    pub fn w(&self, a: f64) -> f64 {
        let a2 = a * a;
        1.0 - self.c1 * (1.0 - a2) - self.c2 * (1.0 - a2 * a2)
    }

    /// The reduced Griffith stress σ_a* at resolution q for a surface energy γ (J/m²).
    pub fn sigma_a(&self, q: f64, gamma: f64) -> f64 {
        if gamma <= 0.0 {
            return 0.0;
        }
        let mut s = self.k_griffith * (q * self.modulus * self.slab(q) * gamma).sqrt();
        if self.cap {
            s = s.min(self.gamma / self.range);
        }
        s / (self.modulus * self.gbar)
    }

    /// ∫_{a}^{b} g(q) dm by 5-point Gauss–Legendre in q (one panel: the caller keeps [a, b]
    /// on one side of q_r and narrow).
    pub fn integrate(&self, a: f64, b: f64, g: impl Fn(f64) -> f64) -> f64 {
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        GL5.iter()
            .map(|&(x, w)| {
                let q = mid + half * x;
                w * g(q) * self.dm_dq(q)
            })
            .sum::<f64>()
            * half
    }

    /// ∫_{q_L}^{q_s} g dm on 400 panels per segment, geometric in q.
    pub fn integrate_panels(&self, g: impl Fn(f64) -> f64) -> f64 {
        let mut sum = 0.0;
        for (lo, hi) in [(self.q_l, self.q_r), (self.q_r, self.q_s)] {
            if hi <= lo {
                continue;
            }
            let n = 400;
            let r = (hi / lo).powf(1.0 / n as f64);
            for k in 0..n {
                let a = lo * r.powi(k);
                let b = if k + 1 == n { hi } else { lo * r.powi(k + 1) };
                sum += self.integrate(a, b, &g);
            }
        }
        sum
    }

    /// Per unit dm: the unweighted variance increment f²q²/(4ḡ²) [S-2, S-15].
    pub fn b_density(&self, q: f64) -> f64 {
        let f = self.slab(q);
        f * f * q * q / (4.0 * self.gbar * self.gbar)
    }

    /// Per unit dm: the full-contact elastic energy qE*f/4 (J/m² per m² of dm) [S-10].
    pub fn e_density(&self, q: f64) -> f64 {
        q * self.modulus * self.slab(q) / 4.0
    }
}

/// f(x) = (cosh 2x − 2x² − 1)/(sinh 2x + 2x) [S-4]; f(∞) = 1.
pub fn slab_factor(x: f64) -> f64 {
    if x.is_infinite() {
        return 1.0;
    }
    if x < 1.0 {
        // cosh 2x − 1 − 2x² = Σ_{k≥2} (2x)^{2k}/(2k)!,  sinh 2x + 2x = 4x + Σ_{k≥1} (2x)^{2k+1}/(2k+1)!
        let y = 2.0 * x;
        let (mut num, mut den) = (0.0, 2.0 * y);
        let mut term = y; // y^n/n! for n = 1
        for n in 2..60 {
            term *= y / n as f64;
            if n % 2 == 0 {
                if n >= 4 {
                    num += term;
                }
            } else {
                den += term;
            }
            if term < 1e-18 * num.max(1e-300) && n > 6 {
                break;
            }
        }
        num / den
    } else {
        let e = (-2.0 * x).exp();
        (1.0 + e * e - 2.0 * (2.0 * x * x + 1.0) * e) / (1.0 - e * e + 4.0 * x * e)
    }
}
