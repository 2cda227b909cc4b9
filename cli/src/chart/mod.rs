//! Charts for files and terminals: one model, [`Chart`] (title, axis titles, linear or log
//! [`Scale`]s, named series drawn as lines, dashed lines, points or bands, vertical markers),
//! built by the explorer's chart builders, `asperity figure`, `gauge` and `surface psd`, and
//! drawn four ways:
//!
//! - the explorer's terminal view (`tui::view`, ratatui);
//! - [`write_svg`]: an SVG file (plotters' SVG backend; text stays text, no font needed by
//!   the reader);
//! - [`write_png`]: a PNG file (plotters' bitmap backend; the text is rasterised with the
//!   DejaVu Sans subset shipped in `assets/fonts/`, registered on first use, so it works on
//!   a machine with no fonts installed);
//! - [`render_text`]: a plain-text character chart (no escape codes; it works when stdout
//!   is not a terminal).
//!
//! Points with a non-finite coordinate (a load that did not converge), and on a log axis
//! points ≤ 0, are left out; a line is broken where they were. Every series' look comes from
//! [`crate::looks`] (its role's, or one its producer fixed), so a model has the same colour
//! on screen and in every file; every series gets a legend entry with its name. Ticks are
//! round values of [`crate::numfmt`] (multiples of its one nice step; decades on log axes),
//! labelled by its one number writer, in every renderer. On the white page of a file a colour
//! too light to read is drawn darker ([`contrast`]).

pub mod contrast;
mod draw;
pub mod flat;
mod font;
pub mod model;
pub mod scale;
pub mod style;
mod text;

pub use contrast::on_white;
pub use flat::{flatten, Flat, FlatSeries};
pub use font::{has_glyph, png_text, COMPOSED};
pub use model::{Chart, Series, VLine};
pub use scale::Scale;
pub use style::{Rgb, SeriesStyle, Shape};
pub use text::render_text;

/// Tells apart the series that share a colour, the colour kept (a model has one colour in
/// every figure): a line with the colour and style of an earlier one takes the next free line
/// style (solid, dashed, dotted, dash-dotted), points with the colour and shape of earlier
/// ones the next free shape.
/// Series without a fixed look ([`Series::look`]) are left as they are ([`Chart::tell_apart`]
/// fixes every look first).
pub fn tell_apart(series: &mut [Series]) {
    for i in 1..series.len() {
        let (before, rest) = series.split_at_mut(i);
        let s = &mut rest[0];
        let Some(mut look) = s.look else { continue };
        let colour = look.ink.rgb();
        let clash = |style: SeriesStyle, shape: Shape| {
            before.iter().any(|e| {
                e.look.is_some_and(|l| {
                    l.ink.rgb() == colour && e.style == style && (style != SeriesStyle::Points || l.shape == shape)
                })
            })
        };
        if !clash(s.style, look.shape) {
            continue;
        }
        let free = if s.style == SeriesStyle::Points {
            Shape::ALL
                .into_iter()
                .find(|&shape| !clash(SeriesStyle::Points, shape))
                .map(|shape| (SeriesStyle::Points, shape))
        } else {
            SeriesStyle::LINES
                .into_iter()
                .find(|&style| !clash(style, look.shape))
                .map(|style| (style, look.shape))
        };
        if let Some((style, shape)) = free {
            look.shape = shape;
            (s.style, s.look) = (style, Some(look));
        }
    }
}

/// The outline of a band given as columns of points (at each x, points from its lower to its
/// upper end, as the terminal shades it): the lower ends left to right, then the upper ends
/// right to left. Non-finite points, or a step back in x, end a band (a NaN between the
/// outlines); a band of one column is a vertical segment.
pub fn band_outline(columns: &[(f64, f64)]) -> Vec<(f64, f64)> {
    // (x, lower, upper) per column, in runs
    let mut bands: Vec<Vec<(f64, f64, f64)>> = vec![Vec::new()];
    for &(x, y) in columns {
        let run = bands.last_mut().expect("non-empty");
        if !(x.is_finite() && y.is_finite()) {
            if !run.is_empty() {
                bands.push(Vec::new());
            }
            continue;
        }
        match run.last_mut() {
            Some(c) if c.0 == x => (c.1, c.2) = (c.1.min(y), c.2.max(y)),
            Some(c) if c.0 > x => bands.push(vec![(x, y, y)]),
            _ => run.push((x, y, y)),
        }
    }
    let mut out = Vec::new();
    for band in bands.iter().filter(|b| !b.is_empty()) {
        if !out.is_empty() {
            out.push((f64::NAN, f64::NAN));
        }
        out.extend(band.iter().map(|c| (c.0, c.1)));
        out.extend(band.iter().rev().map(|c| (c.0, c.2)));
    }
    out
}

/// Breaks a polyline into the strokes of an on/off `pattern` (lengths measured after scaling
/// x by `scale.0` and y by `scale.1`, so a pattern in pixels or cells follows the drawing):
/// the runs of points to draw as solid lines.
pub fn dashes(run: &[(f64, f64)], pattern: &[f64], scale: (f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let Some(&first) = run.first() else {
        return Vec::new();
    };
    if pattern.is_empty() || pattern.iter().any(|l| !(l.is_finite() && *l > 0.0)) {
        return vec![run.to_vec()];
    }
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut stroke = vec![first];
    let (mut k, mut left) = (0usize, pattern[0]);
    for w in run.windows(2) {
        let (a, b) = (w[0], w[1]);
        let len = ((b.0 - a.0) * scale.0).hypot((b.1 - a.1) * scale.1);
        if !len.is_finite() {
            continue;
        }
        let mut t = 0.0;
        while len - t > left {
            t += left;
            let f = t / len;
            let p = (a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1));
            if k % 2 == 0 {
                stroke.push(p);
                out.push(std::mem::take(&mut stroke));
            } else {
                stroke = vec![p];
            }
            k = (k + 1) % pattern.len();
            left = pattern[k];
        }
        left -= len - t;
        if k % 2 == 0 {
            stroke.push(b);
        }
    }
    if k % 2 == 0 && !stroke.is_empty() {
        out.push(stroke);
    }
    out
}

/// Size of the SVG drawing in pixels (the viewBox), the drawing the library refines a
/// figure's curves for.
pub const SVG_SIZE: (u32, u32) = asperity::report::figure::refine::DRAWING_PX;
/// Size of the PNG image in pixels (twice the SVG's, for slides).
pub const PNG_SIZE: (u32, u32) = (1600, 1120);

/// Writes `chart` as an SVG file.
pub fn write_svg(chart: &Chart, path: &std::path::Path) -> std::io::Result<()> {
    font::register();
    let root = plotters::prelude::SVGBackend::new(path, SVG_SIZE);
    draw::draw(root, &flatten(chart), 1.0)
}

/// Writes `chart` as a PNG file (its text with the composite glyphs of [`png_text`]).
pub fn write_png(chart: &Chart, path: &std::path::Path) -> std::io::Result<()> {
    font::register();
    let spec = flatten(chart);
    let text = |s: &String| png_text(s).into_owned();
    let spec = Flat {
        title: text(&spec.title),
        x_label: text(&spec.x_label),
        y_label: text(&spec.y_label),
        series: spec
            .series
            .iter()
            .map(|s| FlatSeries {
                name: text(&s.name),
                ..s.clone()
            })
            .collect(),
        ..spec.clone()
    };
    let root = plotters::prelude::BitMapBackend::new(path, PNG_SIZE);
    draw::draw(root, &spec, PNG_SIZE.0 as f64 / SVG_SIZE.0 as f64)
}

/// The points of a series that can be drawn on the given axes: finite, and > 0 on a log axis.
pub(crate) fn drawable(p: (f64, f64), x_log: bool, y_log: bool) -> bool {
    p.0.is_finite() && p.1.is_finite() && (!x_log || p.0 > 0.0) && (!y_log || p.1 > 0.0)
}

/// The data range of the drawable points of all series on one axis, padded (5 % of the
/// span, or a factor on a log axis); `(0, 1)` (or `(0.1, 1)`) when there are none.
pub(crate) fn axis_range(spec: &Flat, x_axis: bool) -> (f64, f64) {
    let log = if x_axis { spec.x_log } else { spec.y_log };
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in &spec.series {
        for &p in &s.points {
            if drawable(p, spec.x_log, spec.y_log) {
                let v = if x_axis { p.0 } else { p.1 };
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
    }
    if !lo.is_finite() {
        return if log { (0.1, 1.0) } else { (0.0, 1.0) };
    }
    if log {
        if hi <= lo * 1.0001 {
            return (lo / 2.0, hi * 2.0);
        }
        let pad = (hi / lo).powf(0.03);
        (lo / pad, hi * pad)
    } else {
        let span = hi - lo;
        if span <= 1e-12 * hi.abs().max(lo.abs()).max(1e-300) {
            let d = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
            return (lo - d, hi + d);
        }
        (lo - 0.05 * span, hi + 0.05 * span)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_zero_tick_reads_zero() {
        use crate::numfmt::tick;
        // a zero tick off by round-off reads 0 on a linear axis, not 1.73e-18
        assert_eq!(tick(draw::snap_zero(1.73e-18, 0.045, false)), "0");
        assert_eq!(tick(draw::snap_zero(1e-5, 0.045, false)), "1e-5");
        assert_eq!(tick(draw::snap_zero(1e-18, 1.0, true)), "1e-18");
    }

    #[test]
    fn a_band_of_columns_becomes_its_outline_one_polygon_per_run() {
        let nan = f64::NAN;
        let cols = [
            (1.0, 0.2),
            (1.0, 0.3),
            (1.0, 0.25),
            (2.0, 0.1),
            (2.0, 0.4),
            (nan, nan),
            (5.0, 1.0),
            (5.0, 2.0),
        ];
        let o = band_outline(&cols);
        assert_eq!(&o[..4], &[(1.0, 0.2), (2.0, 0.1), (2.0, 0.4), (1.0, 0.3)]);
        assert!(o[4].0.is_nan());
        assert_eq!(&o[5..], &[(5.0, 1.0), (5.0, 2.0)]);
        assert!(band_outline(&[(nan, 1.0)]).is_empty());
    }

    #[test]
    fn ranges_skip_gaps_and_non_positive_values_on_log_axes() {
        let mut chart = Chart::new("", "", "", Scale::Log10, Scale::Linear);
        chart.series.push(Series::painted(
            "a",
            vec![(0.0, 5.0), (1e-3, f64::NAN), (1e-2, 1.0), (1.0, 3.0)],
            SeriesStyle::Line,
            Rgb(0, 0, 0),
            Shape::Circle,
        ));
        let spec = flatten(&chart);
        let (x0, x1) = axis_range(&spec, true);
        assert!(x0 < 1e-2 && x0 > 5e-3 && x1 > 1.0 && x1 < 1.3, "{x0} {x1}");
        let (y0, y1) = axis_range(&spec, false);
        assert!((y0 - 0.9).abs() < 1e-12 && (y1 - 3.1).abs() < 1e-12, "{y0} {y1}");
    }

    #[test]
    fn dashes_follow_the_pattern_along_the_line() {
        let line = [(0.0, 0.0), (10.0, 0.0), (10.0, 4.0)];
        let d = dashes(&line, &[3.0, 2.0], (1.0, 1.0));
        // strokes of 3 every 5 along a path of length 14: [0,3] [5,8] [10,13]
        assert_eq!(d.len(), 3, "{d:?}");
        assert_eq!(d[0], vec![(0.0, 0.0), (3.0, 0.0)]);
        assert_eq!(d[1], vec![(5.0, 0.0), (8.0, 0.0)]);
        // the third starts at the corner and runs up it
        assert_eq!(d[2], vec![(10.0, 0.0), (10.0, 3.0)]);
        // scaled: y counts double, so the vertical leg holds more of the pattern
        let d = dashes(&line, &[3.0, 2.0], (1.0, 2.0));
        assert_eq!(d.len(), 4, "{d:?}");
        // a solid pattern or a single point
        assert_eq!(dashes(&line, &[], (1.0, 1.0)), vec![line.to_vec()]);
        assert_eq!(dashes(&line[..1], &[1.0, 1.0], (1.0, 1.0)), vec![vec![(0.0, 0.0)]]);
        assert!(dashes(&[], &[1.0, 1.0], (1.0, 1.0)).is_empty());
    }
}
