//! Colours on the white page of SVG and PNG files. A colour chosen to be told apart on a
//! terminal can be too light to read on white (the GFMD yellow has a contrast of 1.3 : 1
//! there): lines and open markers of such a colour are drawn in a darker shade of the same
//! hue, and filled markers keep their colour inside an edge of that shade.
//!
//! Contrast is WCAG 2's ratio (L₁ + 0.05)/(L₂ + 0.05), with L the relative luminance
//! 0.2126 R + 0.7152 G + 0.0722 B of the linearised sRGB channels; white has L = 1.

use super::Rgb;

/// The least contrast with white of what a file draws (lines, edges, open markers).
pub const MIN_CONTRAST_ON_WHITE: f64 = 2.0;

/// The relative luminance of an sRGB colour (0 black … 1 white).
pub fn luminance(c: Rgb) -> f64 {
    let lin = |v: u8| {
        let s = f64::from(v) / 255.0;
        if s <= 0.04045 {
            s / 12.92
        } else {
            ((s + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * lin(c.0) + 0.7152 * lin(c.1) + 0.0722 * lin(c.2)
}

/// The contrast ratio of `c` with white (1 for white, 21 for black).
pub fn contrast_with_white(c: Rgb) -> f64 {
    1.05 / (luminance(c) + 0.05)
}

/// `c` where it reaches [`MIN_CONTRAST_ON_WHITE`]; else `c` scaled towards black, its hue
/// kept, by the least factor that reaches it.
pub fn on_white(c: Rgb) -> Rgb {
    if contrast_with_white(c) >= MIN_CONTRAST_ON_WHITE {
        return c;
    }
    let scaled = |k: f64| {
        let f = |v: u8| (f64::from(v) * k).round() as u8;
        Rgb(f(c.0), f(c.1), f(c.2))
    };
    // bisect the factor: `lo` always reaches the contrast (black does), `hi` never
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if contrast_with_white(scaled(mid)) >= MIN_CONTRAST_ON_WHITE {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    scaled(lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn luminance_and_contrast_at_the_ends() {
        assert!((luminance(Rgb(255, 255, 255)) - 1.0).abs() < 1e-12);
        assert_eq!(luminance(Rgb(0, 0, 0)), 0.0);
        assert!((contrast_with_white(Rgb(0, 0, 0)) - 21.0).abs() < 1e-12);
        // WCAG's mid grey: #777777 has 4.48 : 1 on white
        assert!((contrast_with_white(Rgb(0x77, 0x77, 0x77)) - 4.48).abs() < 0.01);
    }

    #[test]
    fn a_light_colour_is_darkened_in_its_hue_just_enough() {
        let yellow = Rgb(240, 228, 66);
        assert!(contrast_with_white(yellow) < 1.4);
        let d = on_white(yellow);
        assert!(contrast_with_white(d) >= MIN_CONTRAST_ON_WHITE);
        // one step lighter would not reach it: the least darkening
        let lighter = Rgb(d.0 + 1, d.1 + 1, d.2.saturating_add(1));
        assert!(contrast_with_white(lighter) < MIN_CONTRAST_ON_WHITE + 0.02);
        // the hue: channel ratios kept to rounding
        assert!((f64::from(d.1) / f64::from(d.0) - 228.0 / 240.0).abs() < 0.01);
        assert!((f64::from(d.2) / f64::from(d.0) - 66.0 / 240.0).abs() < 0.01);
    }

    #[test]
    fn a_colour_readable_on_white_is_kept() {
        for c in [Rgb(0, 114, 178), Rgb(213, 94, 0), Rgb(0, 0, 0), Rgb(150, 150, 150)] {
            assert_eq!(on_white(c), c);
        }
        // white itself becomes a grey that reads
        assert!(contrast_with_white(on_white(Rgb(255, 255, 255))) >= MIN_CONTRAST_ON_WHITE);
    }
}
