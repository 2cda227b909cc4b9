//! A discrete spectrum coarse-grained into thin shells of ln q with the same moments.
//!
//! The theory marches over a [`Discrete`] spectrum one mode group (one |q|) per step; an N×N
//! map has ~N²/10 groups (25 000 at 512²), so an adhesive solve on it costs hundreds of
//! continuum solves. The groups are therefore merged within shells of width δ in ln q
//! (boundaries at q_L·e^{kδ}, k = 0, 1, …) into the two-point Gauss rule of the shell's
//! measure in x = q²: with weights dm_i = Σ|h̃|² at x_i, the two nodes x± and weights w±
//! reproduce
//!
//! ```text
//! Σ_shell x_iᵏ dm_i = w₊ x₊ᵏ + w₋ x₋ᵏ,   k = 0, 1, 2, 3,
//! ```
//!
//! so h_rms² = Σ dm (k = 0), ḡ² = Σ q² dm (k = 1) and the mean-square curvature
//! Σ q⁴ dm / 4 (k = 2) of the whole spectrum are kept to round-off, shell by shell; the nodes
//! lie inside their shell (a Gauss rule of a positive measure), so the merged spectrum is
//! ascending in q as the march needs. Any other smooth weight g(q) (the slab factor f(qt),
//! q³ of the elastic energy) is integrated with a relative error of order (δ²/4)² per shell.
//! A shell that holds one group keeps it as it is, so the sparse long-wavelength end (where
//! each |q| is its own shell) is unchanged.

use crate::surface::spectrum::{Discrete, Mode};

/// The shell width in ln q of the theory on a map's spectrum (`gfmd`'s `theory` block): two
/// modes per shell, 192 steps per e-fold of q at most. Against every mode group (system II at
/// t = ∞ and t·q_r = 0.3 with adhesion, system I without, the presets' 512² maps) a_r and σ̄_c*
/// move by ≤ 3.4e-5 and ū by ≤ 4.4e-4 relative (1/24: 4.3e-4 and 5.6e-3), at 1/5–1/50 of the
/// time (BENCHMARKS.md).
pub const THEORY_SHELL_LN: f64 = 1.0 / 96.0;

impl Discrete {
    /// The spectrum merged into shells of width `width_ln_q` in ln q, two modes per shell
    /// with the shell's moments Σ q^{2k} dm, k = 0…3 (module docs). A width ≤ 0 or not
    /// finite returns the spectrum unchanged.
    pub fn coarse_grained(&self, width_ln_q: f64) -> Discrete {
        if !(width_ln_q.is_finite() && width_ln_q > 0.0) || self.modes.is_empty() {
            return self.clone();
        }
        let q0 = self.modes[0].q;
        let shell = |q: f64| ((q / q0).ln() / width_ln_q + 1e-9).floor() as i64;
        let mut modes = Vec::with_capacity(self.modes.len().min(1024));
        let mut start = 0;
        while start < self.modes.len() {
            let k = shell(self.modes[start].q);
            let end = start
                + self.modes[start..]
                    .iter()
                    .position(|m| shell(m.q) != k)
                    .unwrap_or(self.modes.len() - start);
            merge(&self.modes[start..end], &mut modes);
            start = end;
        }
        Discrete {
            system_size: self.system_size,
            q_r: self.q_r,
            modes,
        }
    }
}

/// Appends the two-point Gauss rule in x = q² of the groups `g` (or the group itself when
/// there is one, or the spread is at round-off).
fn merge(g: &[Mode], out: &mut Vec<Mode>) {
    if g.len() == 1 {
        out.push(g[0]);
        return;
    }
    // central moments about the mean x̄, scaled by x̄ (differences of nearby q² would lose
    // digits otherwise)
    let m0: f64 = g.iter().map(|m| m.dm).sum();
    let xbar = g.iter().map(|m| m.q * m.q * m.dm).sum::<f64>() / m0;
    let (mut var, mut skew) = (0.0, 0.0);
    for m in g {
        let y = (m.q * m.q - xbar) / xbar;
        var += y * y * m.dm;
        skew += y * y * y * m.dm;
    }
    var /= m0;
    skew /= m0;
    if var <= 1e-28 {
        out.push(Mode { q: xbar.sqrt(), dm: m0 });
        return;
    }
    // nodes: the roots of y² − (μ₃/μ₂) y − μ₂ (orthogonal to 1 and y under the measure);
    // weights from Σw = m0, Σw y = 0
    let c = skew / var;
    let root = (c * c + 4.0 * var).sqrt();
    let (y_lo, y_hi) = (0.5 * (c - root), 0.5 * (c + root));
    let w_lo = m0 * y_hi / (y_hi - y_lo);
    let w_hi = m0 - w_lo;
    for (y, w) in [(y_lo, w_lo), (y_hi, w_hi)] {
        out.push(Mode {
            q: (xbar * (1.0 + y)).sqrt(),
            dm: w,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spectrum() -> Discrete {
        // a dense set of groups with a power-law weight, as a map's spectrum has
        let modes = (1..4000)
            .map(|k| {
                let q = (k as f64).sqrt();
                Mode {
                    q,
                    dm: q.powf(-3.6) * (1.0 + 0.3 * ((k * 7919) % 13) as f64 / 13.0),
                }
            })
            .collect();
        Discrete {
            system_size: 1.0,
            q_r: 1.0,
            modes,
        }
    }

    #[test]
    fn keeps_the_even_moments_and_the_order() {
        let d = spectrum();
        let c = d.coarse_grained(0.02);
        assert!(c.modes.len() < d.modes.len() / 5);
        assert!(c.modes.windows(2).all(|w| w[1].q > w[0].q));
        assert!(c.modes.iter().all(|m| m.dm > 0.0));
        for n in [0, 2, 4, 6] {
            let (a, b) = (d.moment(n), c.moment(n));
            assert!((a - b).abs() <= 1e-12 * a, "moment {n}: {a} vs {b}");
        }
        // odd moments to the shells' quadrature error
        let (a, b) = (d.moment(3), c.moment(3));
        assert!((a - b).abs() <= 1e-6 * a, "moment 3: {a} vs {b}");
    }
}
