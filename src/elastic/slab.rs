//! Slab factor f(qt) of an elastic slab of thickness t with a constant-stress (traction-free)
//! far side, [S-4]:
//!
//! ```text
//! f(x) = (cosh 2x − 2x² − 1) / (sinh 2x + 2x),   x = q·t
//! ```
//!
//! It multiplies E* in the surface stiffness of mode q, φ(q) = q E* f(qt) / 2 (physics.md §2).
//! Limits: f → 1 for x → ∞ (semi-infinite solid), f → x³/6 for x → 0 (thin plate). It does not
//! depend on Poisson's ratio.
//!
//! Numerics: the textbook form overflows for x ≳ 350 and loses every digit to cancellation
//! for x ≲ 1e-3. Below [`SERIES_SWITCH`] both numerator and denominator are summed as series
//! of positive terms with x³ factored out (no cancellation); above it the form divided by
//! e^{2x}/2 is used (no overflow). Both are accurate to a few ulps where they meet.

/// Below this x the power series is used, above it the exponentially scaled closed form.
pub const SERIES_SWITCH: f64 = 1.5;

/// Slab factor f(x) for x = q·t in [0, ∞]. `f64::INFINITY` gives exactly 1 (semi-infinite).
///
/// Returns NaN only for NaN input; negative x is treated as |x| (f is odd-symmetric in form
/// but thickness and wave number are non-negative by construction).
pub fn slab_factor(x: f64) -> f64 {
    let x = x.abs();
    if x.is_nan() {
        return f64::NAN;
    }
    if x > 30.0 {
        // 1 − f ≈ (4x² + 4x + 2)e^{−2x} < 1e-22: f = 1 to double precision (and 4x² would
        // overflow for x ≳ 1e154)
        return 1.0;
    }
    if x < SERIES_SWITCH {
        // num = Σ_{k≥2} (2x)^{2k}/(2k)! = x⁴ Σ_{k≥2} 2^{2k} x^{2k−4}/(2k)!
        // den = Σ_{k≥0} (2x)^{2k+1}/(2k+1)! + 2x = x (4 + Σ_{k≥1} 2^{2k+1} x^{2k}/(2k+1)!)
        let y = 4.0 * x * x; // (2x)²
                             // numerator series in y: Σ_{k≥2} y^{k-2} · 16 / (2k)!  (since 2^{2k} x^{2k-4} = 16 y^{k-2})
        let mut num = 0.0;
        let mut term = 16.0 / 24.0; // k = 2: 16/4!
        let mut k = 2.0_f64;
        while term > 1e-18 * num || num == 0.0 {
            num += term;
            // next: multiply by y / ((2k+1)(2k+2))
            term *= y / ((2.0 * k + 1.0) * (2.0 * k + 2.0));
            k += 1.0;
            if k > 60.0 {
                break;
            }
        }
        // denominator series: 4 + Σ_{k≥1} 2·y^k/(2k+1)!
        let mut den = 4.0;
        let mut term = 2.0 * y / 6.0; // k = 1: 2y/3!
        let mut k = 1.0_f64;
        while term > 1e-18 * den {
            den += term;
            term *= y / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
            k += 1.0;
            if k > 60.0 {
                break;
            }
        }
        x * x * x * num / den
    } else {
        let e2 = (-2.0 * x).exp();
        let e4 = e2 * e2;
        let num = 1.0 + e4 - (4.0 * x * x + 2.0) * e2;
        let den = 1.0 - e4 + 4.0 * x * e2;
        num / den
    }
}

/// The thickness of the elastic body in units of 1/q_r (t·q_r); `INFINITY` = semi-infinite.
///
/// Returns the slab factor at wave number q for a body of thickness `t_m` metres, skipping
/// the evaluation entirely for a semi-infinite body.
#[inline]
pub fn slab_factor_at(q: f64, t_m: f64) -> f64 {
    if t_m.is_infinite() {
        1.0
    } else {
        slab_factor(q * t_m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tolerances::SLAB_FACTOR_REL;

    fn naive(x: f64) -> f64 {
        ((2.0 * x).cosh() - 2.0 * x * x - 1.0) / ((2.0 * x).sinh() + 2.0 * x)
    }

    #[test]
    fn reference_table() {
        // reference-values.md, slab-factor table (6 significant digits)
        for (x, f) in [
            (0.1, 1.66333e-4),
            (0.5, 0.0198054),
            (1.0, 0.135457),
            (2.0, 0.585116),
            (5.0, 0.994466),
        ] {
            assert!(
                (slab_factor(x) / f - 1.0).abs() < 5e-6,
                "f({x}) = {} vs {f}",
                slab_factor(x)
            );
        }
    }

    #[test]
    fn matches_naive_form_where_it_is_accurate() {
        // The naive form loses ~ -log10(x) digits at small x and overflows at large x;
        // in [0.3, 30] it is good to ~1e-14.
        let mut x = 0.3;
        while x < 30.0 {
            let r = slab_factor(x) / naive(x) - 1.0;
            assert!(r.abs() < SLAB_FACTOR_REL, "x = {x}: rel diff {r}");
            x *= 1.07;
        }
    }

    #[test]
    fn both_branches_agree_at_the_switch() {
        for x in [1.2f64, 1.4, 1.5, 1.6, 1.8, 2.0] {
            // force the other branch by evaluating the series and the scaled form directly
            let e2 = (-2.0 * x).exp();
            let scaled = (1.0 + e2 * e2 - (4.0 * x * x + 2.0) * e2) / (1.0 - e2 * e2 + 4.0 * x * e2);
            let r = slab_factor(x) / scaled - 1.0;
            assert!(r.abs() < SLAB_FACTOR_REL, "x = {x}: {r}");
        }
    }

    #[test]
    fn thin_plate_limit_and_series() {
        // f = x³/6 · (1 + 2x²/15 + …)/(1 + x²/3 + …) = x³/6 (1 − x²/5 + O(x⁴))
        for x in [1e-8, 1e-5, 1e-3] {
            let expect = x * x * x / 6.0 * (1.0 - x * x / 5.0);
            assert!((slab_factor(x) / expect - 1.0).abs() < SLAB_FACTOR_REL, "x = {x}");
        }
        assert_eq!(slab_factor(0.0), 0.0);
        assert!(slab_factor(1e-200) >= 0.0);
    }

    #[test]
    fn semi_infinite_limit_and_no_overflow() {
        assert_eq!(slab_factor(f64::INFINITY), 1.0);
        for x in [50.0, 350.0, 1e3, 1e10, 1e300] {
            let f = slab_factor(x);
            assert!(f.is_finite() && (f - 1.0).abs() < 1e-12, "x = {x}: {f}");
        }
        // 1 − f ≈ (4x² + 4x + 2) e^{−2x} for large x
        let x = 20.0_f64;
        let expect = 1.0 - (4.0 * x * x + 4.0 * x + 2.0) * (-2.0 * x).exp();
        assert!((slab_factor(x) - expect).abs() < 1e-15);
    }

    #[test]
    fn monotone_and_bounded() {
        let mut prev = 0.0;
        let mut x = 1e-6;
        while x < 1e3 {
            let f = slab_factor(x);
            assert!(f >= prev && f <= 1.0, "x = {x}");
            prev = f;
            x *= 1.01;
        }
    }
}
