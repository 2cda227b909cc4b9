//! Numbers as the front ends write them: one routine ([`format()`]) behind every tick label
//! (terminal, text chart, SVG/PNG), legend name, caption and panel value, one for durations
//! ([`duration`]), and one for round tick values ([`nice_step`], [`nice_ticks`]).
//!
//! A number is rounded to a number of significant digits, then written in fixed notation
//! where its magnitude lies in [10⁻³, 10⁴) (`0.0125`, `350`) and as `m e k` otherwise
//! (`2.5e-5`, `1e6`), where the digits left of the point are all kept (`1234`, not `1230`);
//! trailing zeros are dropped unless the caller wants a fixed width
//! ([`sig`]). Zero is `0` (also −0), NaN `–`, ±∞ `∞`/`-∞`. The magnitude is taken after
//! rounding, so 9.9996e-4 at four digits is `0.001`, not `10.00e-4`.

/// Magnitudes written without an exponent: [`FIXED_FROM`, `FIXED_TO`).
pub const FIXED_FROM: f64 = 1e-3;
/// The upper end of the fixed-notation range (exclusive).
pub const FIXED_TO: f64 = 1e4;

/// `x` rounded to `digits` (≥ 1) significant digits.
pub fn round_sig(x: f64, digits: usize) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let digits = digits.clamp(1, 17) as i32;
    let e = x.abs().log10().floor() as i32;
    // divide by a power of ten rather than multiply by its (inexact) reciprocal
    let k = digits - 1 - e;
    let r = if k >= 0 {
        let f = 10f64.powi(k);
        (x * f).round() / f
    } else {
        let f = 10f64.powi(-k);
        (x / f).round() * f
    };
    if r.is_finite() {
        r
    } else {
        x
    }
}

/// The one number writer: `x` to `digits` significant digits, trailing zeros dropped when
/// `trim` (see the module docs for the notation).
pub fn format(x: f64, digits: usize, trim: bool) -> String {
    if x.is_nan() {
        return "–".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "∞".into() } else { "-∞".into() };
    }
    if x == 0.0 {
        return "0".into();
    }
    let digits = digits.clamp(1, 17);
    let r = round_sig(x, digits);
    if (FIXED_FROM..FIXED_TO).contains(&r.abs()) {
        let e = r.abs().log10().floor() as i32;
        // the digits left of the point are all kept (1234 at three digits is 1234)
        let decimals = (digits as i32 - 1 - e).max(0) as usize;
        let s = format!("{x:.decimals$}");
        return if trim { trim_zeros(s) } else { s };
    }
    // Rust writes the exponent form exactly (subnormals too): 1.2345e-5 → "1.23e-5"
    let s = format!("{r:.*e}", digits - 1);
    let (mantissa, exp) = s.split_once('e').unwrap_or((s.as_str(), "0"));
    let mantissa = if trim {
        trim_zeros(mantissa.to_string())
    } else {
        mantissa.to_string()
    };
    format!("{mantissa}e{exp}")
}

/// A number in few characters (three significant digits, trimmed): `0.0123`, `2.5e-5`,
/// `350`, `1234`. The explorer's legends, titles and captions and the export notes.
pub fn short(x: f64) -> String {
    format(x, 3, true)
}

/// A tick label: a round value in up to four significant digits, trimmed (`0.001`, `0.5`,
/// `1.025`, `1e-5`).
pub fn tick(x: f64) -> String {
    format(x, 4, true)
}

/// A value with exactly `n` significant digits (trailing zeros kept, so a value that is
/// stepped keeps its width): `0.5000`, `1.234e-5`.
pub fn sig(x: f64, n: usize) -> String {
    format(x, n, false)
}

fn trim_zeros(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// A duration in seconds: "350 µs", "12 ms", "0.4 s", "12 s", "2 min 05 s"; "–" when
/// negative or not finite.
pub fn duration(s: f64) -> String {
    if !s.is_finite() || s < 0.0 {
        return "–".into();
    }
    if s < 1e-3 {
        format!("{:.0} µs", s * 1e6)
    } else if s < 0.1 {
        format!("{:.0} ms", s * 1e3)
    } else if s < 10.0 {
        format!("{s:.1} s")
    } else if s < 60.0 {
        format!("{s:.0} s")
    } else {
        let m = (s / 60.0).floor();
        format!("{m:.0} min {:02.0} s", (s - 60.0 * m).floor())
    }
}

/// A 1–2–2.5–5 × 10^k step not smaller than `x` (> 0; 1 otherwise).
pub fn nice_step(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let e = 10f64.powf(x.log10().floor());
    for m in [1.0, 2.0, 2.5, 5.0, 10.0] {
        if m * e >= x * (1.0 - 1e-12) {
            return m * e;
        }
    }
    10.0 * e
}

/// About `n` round tick values in [lo, hi]: decades (and 2, 5 times them when there are
/// fewer than three) on a log axis, multiples of a [`nice_step`] on a linear one.
pub fn nice_ticks(lo: f64, hi: f64, log: bool, n: usize) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite() && hi > lo) || (log && lo <= 0.0) {
        return vec![lo];
    }
    if log {
        let (a, b) = (lo.log10().ceil() as i32, hi.log10().floor() as i32);
        let decades = b - a + 1;
        let step = ((decades as f64 / n.max(1) as f64).ceil() as i32).max(1);
        let mut out: Vec<f64> = (a..=b).filter(|k| (k - a) % step == 0).map(|k| 10f64.powi(k)).collect();
        if out.len() < 3 {
            out.clear();
            for k in (lo.log10().floor() as i32)..=(hi.log10().ceil() as i32) {
                for m in [1.0, 2.0, 5.0] {
                    let v = m * 10f64.powi(k);
                    if v >= lo && v <= hi {
                        out.push(v);
                    }
                }
            }
        }
        return out;
    }
    let step = nice_step((hi - lo) / n.max(1) as f64);
    // v = k·step, rounded to the step's digits so that 0.6 is 0.6 (not 0.6000000000000001)
    let digits = (-step.log10().floor()).max(0.0) as i32 + 2;
    let value = |k: i64| {
        let f = 10f64.powi(digits);
        ((k as f64 * step) * f).round() / f
    };
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    (first..=last).map(value).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_numbers() {
        assert_eq!(short(0.0), "0");
        assert_eq!(short(-0.0), "0");
        assert_eq!(short(f64::NAN), "–");
        assert_eq!(short(f64::INFINITY), "∞");
        assert_eq!(short(f64::NEG_INFINITY), "-∞");
        assert_eq!(short(1234.0), "1234");
        assert_eq!(short(1234.6), "1235");
        assert_eq!(short(12.34), "12.3");
        assert_eq!(short(-0.5), "-0.5");
        assert_eq!(short(0.0123), "0.0123");
        assert_eq!(short(0.005), "0.005");
        assert_eq!(short(2.5e-5), "2.5e-5");
        assert_eq!(short(1.2345e-5), "1.23e-5");
        assert_eq!(short(1e6), "1e6");
        assert_eq!(short(-3.0e7), "-3e7");
        assert_eq!(short(1e300), "1e300");
        assert_eq!(short(5e-324), "4.94e-324");
    }

    #[test]
    fn ticks_and_fixed_widths() {
        assert_eq!(tick(0.001), "0.001");
        assert_eq!(tick(0.5), "0.5");
        assert_eq!(tick(2.0), "2");
        assert_eq!(tick(1e-5), "1e-5");
        assert_eq!(tick(2.5e-5), "2.5e-5");
        assert_eq!(tick(-0.25), "-0.25");
        assert_eq!(tick(1.025), "1.025");
        assert_eq!(tick(1e4), "1e4");
        assert_eq!(tick(0.30000000000000004), "0.3");
        assert_eq!(sig(0.5, 4), "0.5000");
        assert_eq!(sig(250.0, 4), "250.0");
        assert_eq!(sig(1.2345e-5, 4), "1.235e-5");
        assert_eq!(sig(-2.0, 3), "-2.00");
    }

    #[test]
    fn rounding_up_crosses_into_the_next_decade_cleanly() {
        assert_eq!(tick(9.9996e-4), "0.001");
        assert_eq!(short(9999.7), "1e4");
        assert_eq!(short(0.09996), "0.1");
        assert_eq!(sig(9.9996, 4), "10.00");
    }

    /// Reading a number back gives the value to its digits; the order of written numbers
    /// is the order of the values; the sign is kept.
    #[test]
    fn round_trip_order_and_sign() {
        let mut values = Vec::new();
        for k in -300..=300 {
            for m in [1.0, 1.2345, 2.5, 3.3333, 9.87654] {
                values.push(m * 10f64.powi(k));
            }
        }
        for &v in &values {
            for digits in [1, 3, 4, 6] {
                for x in [v, -v] {
                    let s = format(x, digits, true);
                    let back: f64 = s.parse().unwrap_or_else(|_| panic!("{x} → {s}"));
                    let tol = 0.51 * 10f64.powi(1 - digits as i32) * x.abs();
                    assert!((back - x).abs() <= tol.max(1e-323), "{x} at {digits} → {s}");
                    assert_eq!(back.is_sign_negative(), x < 0.0, "{x} → {s}");
                    assert_eq!(
                        s.parse::<f64>().unwrap(),
                        format(back, digits, true).parse::<f64>().unwrap()
                    );
                }
            }
        }
        let sorted: Vec<f64> = values.iter().map(|&v| short(v).parse().unwrap()).collect();
        assert!(sorted.windows(2).all(|w| w[0] <= w[1]));
    }

    #[test]
    fn durations() {
        assert_eq!(duration(3.5e-4), "350 µs");
        assert_eq!(duration(0.012), "12 ms");
        assert_eq!(duration(0.42), "0.4 s");
        assert_eq!(duration(12.4), "12 s");
        assert_eq!(duration(125.0), "2 min 05 s");
        assert_eq!(duration(f64::NAN), "–");
        assert_eq!(duration(-1.0), "–");
    }

    #[test]
    fn steps_and_ticks_are_round() {
        assert_eq!(nice_step(0.3), 0.5);
        assert_eq!(nice_step(0.02), 0.02);
        assert_eq!(nice_step(0.021), 0.025);
        assert_eq!(nice_step(f64::NAN), 1.0);
        assert_eq!(nice_ticks(-0.05, 1.05, false, 6), vec![0.0, 0.2, 0.4, 0.6, 0.8, 1.0]);
        assert_eq!(nice_ticks(8e-4, 1.2, true, 8), vec![1e-3, 1e-2, 1e-1, 1.0]);
        assert_eq!(nice_ticks(0.3, 4.0, true, 8), vec![0.5, 1.0, 2.0]);
        assert_eq!(nice_ticks(1.0, 1.0, false, 4), vec![1.0]);
        assert_eq!(nice_ticks(0.0, 1.0, false, 4), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(nice_ticks(-3e-5, 1.1e-4, false, 3), vec![0.0, 5e-5, 1e-4]);
        assert_eq!(nice_ticks(1.0, 1.04, false, 2), vec![1.0, 1.02, 1.04]);
        assert_eq!(nice_ticks(-1.0, 1.0, true, 4), vec![-1.0]);
        for t in nice_ticks(-0.05, 1.05, false, 6) {
            assert_eq!(tick(t).len(), if t == 0.0 || t == 1.0 { 1 } else { 3 }, "{t}");
        }
    }
}
