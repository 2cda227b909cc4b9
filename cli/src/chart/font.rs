//! The font of PNG charts: a DejaVu Sans subset (`assets/fonts/`, Bitstream Vera licence, see
//! `LICENSE-DejaVu.txt` beside it; `make_subset.py` there rebuilds it), compiled into the
//! binary and registered with plotters once, so text renders on a machine with no fonts
//! installed. The SVG backend writes text as text but measures it with the same font to lay
//! out the axes.
//!
//! plotters draws each glyph at the pen position without shaping, so a combining mark (σ̄ is
//! σ followed by U+0304) would land after its base. The subset carries one composite glyph
//! per sequence the labels use, at a Private Use Area code point ([`COMPOSED`]), and
//! [`png_text`] substitutes them before the bitmap backend draws; SVG keeps the Unicode text.

use plotters::style::FontStyle;
use std::borrow::Cow;
use std::sync::Once;

/// The font file (about 90 KB).
pub(crate) static DEJAVU_SANS: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans-subset.ttf");

/// The family name the charts ask for.
pub(crate) const FAMILY: &str = "sans-serif";

/// Combining sequences drawn as one composite glyph of the bundled font: (sequence, its
/// Private Use Area code point). The same table is in `assets/fonts/make_subset.py`.
pub const COMPOSED: [(&str, char); 2] = [("σ\u{304}", '\u{E000}'), ("γ\u{303}", '\u{E001}')];

static REGISTER: Once = Once::new();

/// Registers the font under [`FAMILY`] (idempotent, thread-safe).
pub(crate) fn register() {
    REGISTER.call_once(|| {
        // the file is compiled in and tested below: a failure here is a build defect
        plotters::style::register_font(FAMILY, FontStyle::Normal, DEJAVU_SANS)
            .unwrap_or_else(|_| panic!("the bundled DejaVu Sans subset is not a valid font"));
    });
}

/// `text` as the bitmap backend must draw it: every sequence of [`COMPOSED`] replaced by its
/// composite glyph's code point.
pub fn png_text(text: &str) -> Cow<'_, str> {
    if !COMPOSED.iter().any(|(seq, _)| text.contains(seq)) {
        return Cow::Borrowed(text);
    }
    let mut out = text.to_string();
    for (seq, c) in COMPOSED {
        out = out.replace(seq, &c.to_string());
    }
    Cow::Owned(out)
}

/// Whether the bundled font maps `c` to a glyph (its `cmap`, formats 4 and 12).
pub fn has_glyph(c: char) -> bool {
    cmap_lookup(DEJAVU_SANS, u32::from(c)).is_some_and(|g| g != 0)
}

fn u16_at(b: &[u8], i: usize) -> Option<u16> {
    Some(u16::from_be_bytes(b.get(i..i + 2)?.try_into().ok()?))
}

fn u32_at(b: &[u8], i: usize) -> Option<u32> {
    Some(u32::from_be_bytes(b.get(i..i + 4)?.try_into().ok()?))
}

/// The glyph id of code point `c` in a TrueType font's Unicode `cmap` subtable.
fn cmap_lookup(font: &[u8], c: u32) -> Option<u16> {
    let tables = usize::from(u16_at(font, 4)?);
    let cmap = (0..tables)
        .map(|i| 12 + 16 * i)
        .find(|&r| font.get(r..r + 4) == Some(b"cmap"))
        .and_then(|r| u32_at(font, r + 8))? as usize;
    let subtables = usize::from(u16_at(font, cmap + 2)?);
    for i in 0..subtables {
        let rec = cmap + 4 + 8 * i;
        let (platform, encoding) = (u16_at(font, rec)?, u16_at(font, rec + 2)?);
        if !(platform == 0 || (platform == 3 && (encoding == 1 || encoding == 10))) {
            continue;
        }
        let st = cmap + u32_at(font, rec + 4)? as usize;
        match u16_at(font, st)? {
            4 => {
                let segs = usize::from(u16_at(font, st + 6)? / 2);
                let ends = st + 14;
                let starts = ends + 2 * segs + 2;
                let deltas = starts + 2 * segs;
                let offsets = deltas + 2 * segs;
                for s in 0..segs {
                    let (end, start) = (
                        u32::from(u16_at(font, ends + 2 * s)?),
                        u32::from(u16_at(font, starts + 2 * s)?),
                    );
                    if c < start || c > end {
                        continue;
                    }
                    let delta = u16_at(font, deltas + 2 * s)?;
                    let range = usize::from(u16_at(font, offsets + 2 * s)?);
                    if range == 0 {
                        return Some((c as u16).wrapping_add(delta));
                    }
                    let at = offsets + 2 * s + range + 2 * (c - start) as usize;
                    let g = u16_at(font, at)?;
                    return Some(if g == 0 { 0 } else { g.wrapping_add(delta) });
                }
            }
            12 => {
                let groups = u32_at(font, st + 12)? as usize;
                for k in 0..groups {
                    let g = st + 16 + 12 * k;
                    let (lo, hi, first) = (u32_at(font, g)?, u32_at(font, g + 4)?, u32_at(font, g + 8)?);
                    if (lo..=hi).contains(&c) {
                        return u16::try_from(first + (c - lo)).ok();
                    }
                }
            }
            _ => {}
        }
    }
    Some(0)
}

#[cfg(test)]
#[path = "font_tests.rs"]
mod tests;
