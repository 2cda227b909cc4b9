//! The font of PNG charts: a DejaVu Sans subset (`assets/fonts/`, Bitstream Vera licence, see
//! `LICENSE-DejaVu.txt` beside it), compiled into the binary and registered with plotters
//! once, so text renders on a machine with no fonts installed. The SVG backend writes text
//! as text but measures it with the same font to lay out the axes.

use plotters::style::FontStyle;
use std::sync::Once;

/// The font file (about 60 KB).
pub(crate) static DEJAVU_SANS: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans-subset.ttf");

/// The family name the charts ask for.
pub(crate) const FAMILY: &str = "sans-serif";

static REGISTER: Once = Once::new();

/// Registers the font under [`FAMILY`] (idempotent, thread-safe).
pub(crate) fn register() {
    REGISTER.call_once(|| {
        // the file is compiled in and tested below: a failure here is a build defect
        plotters::style::register_font(FAMILY, FontStyle::Normal, DEJAVU_SANS)
            .unwrap_or_else(|_| panic!("the bundled DejaVu Sans subset is not a valid font"));
    });
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_bundled_font_parses() {
        super::register();
    }
}
