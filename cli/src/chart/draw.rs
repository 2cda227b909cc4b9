//! The plotters drawing shared by the SVG and PNG backends: one generic routine over the
//! backend and the (linear or logarithmic) axis types.

use super::font::FAMILY;
use super::{axis_range, dashes, drawable, on_white, Flat, SeriesStyle, Shape};
use crate::numfmt::{nice_ticks, tick};
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::Shift;
use plotters::prelude::*;

fn io_err<E: std::fmt::Display>(e: E) -> std::io::Error {
    std::io::Error::other(format!("chart: {e}"))
}

/// Draws `spec` on `backend` (font sizes and line widths times `scale`) and writes the file.
pub(crate) fn draw<DB: DrawingBackend>(backend: DB, spec: &Flat, scale: f64) -> std::io::Result<()> {
    let root = backend.into_drawing_area();
    root.fill(&WHITE).map_err(io_err)?;
    let (x0, x1) = axis_range(spec, true);
    let (y0, y1) = axis_range(spec, false);
    // the ticks of the one nice-ticks routine (labels and bold grid lines), finer ones for
    // the light grid
    let (bx, by) = (ticks(x0, x1, spec.x_log, 8), ticks(y0, y1, spec.y_log, 8));
    let (lx, ly) = (ticks(x0, x1, spec.x_log, 40), ticks(y0, y1, spec.y_log, 40));
    match (spec.x_log, spec.y_log) {
        (false, false) => plot(&root, spec, scale, (x0..x1).ticked(bx, lx), (y0..y1).ticked(by, ly)),
        (true, false) => plot(
            &root,
            spec,
            scale,
            (x0..x1).log_scale().ticked(bx, lx),
            (y0..y1).ticked(by, ly),
        ),
        (false, true) => plot(
            &root,
            spec,
            scale,
            (x0..x1).ticked(bx, lx),
            (y0..y1).log_scale().ticked(by, ly),
        ),
        (true, true) => plot(
            &root,
            spec,
            scale,
            (x0..x1).log_scale().ticked(bx, lx),
            (y0..y1).log_scale().ticked(by, ly),
        ),
    }?;
    root.present().map_err(io_err)
}

/// An axis whose ticks are given: `bold` labelled (with a bold grid line), `light` the
/// light grid (plotters' own `WithKeyPoints` loses the label formatting of an f64 axis).
struct Ticked<R: Ranged<ValueType = f64>> {
    inner: R,
    bold: Vec<f64>,
    light: Vec<f64>,
}

impl<R: Ranged<ValueType = f64>> Ranged for Ticked<R> {
    type ValueType = f64;
    type FormatOption = DefaultFormatting;

    fn range(&self) -> std::ops::Range<f64> {
        self.inner.range()
    }

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }

    fn axis_pixel_range(&self, limit: (i32, i32)) -> std::ops::Range<i32> {
        self.inner.axis_pixel_range(limit)
    }
}

/// `.ticked(bold, light)` on anything that is an f64 axis.
trait Tick: AsRangedCoord<Value = f64> + Sized {
    fn ticked(self, bold: Vec<f64>, light: Vec<f64>) -> Ticked<Self::CoordDescType> {
        Ticked {
            inner: self.into(),
            bold,
            light,
        }
    }
}

impl<T: AsRangedCoord<Value = f64>> Tick for T {}

/// About `n` tick values in [lo, hi] ([`nice_ticks`]); on a log axis with `n` beyond the
/// decades, every 1–9 × 10^k in range (the light grid).
fn ticks(lo: f64, hi: f64, log: bool, n: usize) -> Vec<f64> {
    if !log || n <= 8 || !(lo > 0.0 && hi > lo) {
        return nice_ticks(lo, hi, log, n);
    }
    let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    (a..=b)
        .flat_map(|k| (1..10).map(move |m| f64::from(m) * 10f64.powi(k)))
        .filter(|v| *v >= lo && *v <= hi)
        .collect()
}

/// The runs of consecutive drawable points (a line is broken at a gap).
fn runs(points: &[(f64, f64)], x_log: bool, y_log: bool) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for &p in points {
        if drawable(p, x_log, y_log) {
            out.last_mut().expect("non-empty").push(p);
        } else if !out.last().expect("non-empty").is_empty() {
            out.push(Vec::new());
        }
    }
    out.retain(|r| !r.is_empty());
    out
}

/// The corner of the plot with the fewest points near it, for the legend.
fn legend_corner(spec: &Flat) -> SeriesLabelPosition {
    let (x0, x1) = axis_range(spec, true);
    let (y0, y1) = axis_range(spec, false);
    let norm = |v: f64, lo: f64, hi: f64, log: bool| {
        if log {
            (v / lo).ln() / (hi / lo).ln()
        } else {
            (v - lo) / (hi - lo)
        }
    };
    // (upper?, right?) → count of points in that 45 % × 45 % corner
    let mut count = [[0usize; 2]; 2];
    for s in &spec.series {
        for &p in &s.points {
            if !drawable(p, spec.x_log, spec.y_log) {
                continue;
            }
            let (u, v) = (norm(p.0, x0, x1, spec.x_log), norm(p.1, y0, y1, spec.y_log));
            for (i, upper) in [true, false].into_iter().enumerate() {
                for (j, right) in [true, false].into_iter().enumerate() {
                    let in_y = if upper { v > 0.55 } else { v < 0.45 };
                    let in_x = if right { u > 0.55 } else { u < 0.45 };
                    if in_x && in_y {
                        count[i][j] += 1;
                    }
                }
            }
        }
    }
    let order = [
        ((0, 0), SeriesLabelPosition::UpperRight),
        ((0, 1), SeriesLabelPosition::UpperLeft),
        ((1, 0), SeriesLabelPosition::LowerRight),
        ((1, 1), SeriesLabelPosition::LowerLeft),
    ];
    order
        .into_iter()
        .min_by_key(|((i, j), _)| count[*i][*j])
        .map(|(_, pos)| pos)
        .unwrap_or(SeriesLabelPosition::UpperRight)
}

/// `v` as 0 where it is zero up to round-off on a linear axis of length `span`.
pub(crate) fn snap_zero(v: f64, span: f64, log: bool) -> f64 {
    if !log && v.abs() <= 1e-9 * span.abs() {
        0.0
    } else {
        v
    }
}

fn plot<DB, X, Y>(root: &DrawingArea<DB, Shift>, spec: &Flat, scale: f64, x: X, y: Y) -> std::io::Result<()>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let px = |v: f64| (v * scale).round() as i32;
    let font = |size: f64| (FAMILY, size * scale);
    let mut chart = ChartBuilder::on(root)
        .caption(&spec.title, font(20.0))
        .margin(px(14.0))
        .x_label_area_size(px(52.0))
        .y_label_area_size(px(74.0))
        .build_cartesian_2d(x, y)
        .map_err(io_err)?;
    // a tick at zero on a linear axis comes out of the tick arithmetic as ±1e-18 or so
    let (x0, x1) = axis_range(spec, true);
    let (y0, y1) = axis_range(spec, false);
    let fmt_x = |v: &f64| tick(snap_zero(*v, x1 - x0, spec.x_log));
    let fmt_y = |v: &f64| tick(snap_zero(*v, y1 - y0, spec.y_log));
    chart
        .configure_mesh()
        .x_desc(spec.x_label.as_str())
        .y_desc(spec.y_label.as_str())
        .x_labels(8)
        .y_labels(8)
        .x_label_formatter(&fmt_x)
        .y_label_formatter(&fmt_y)
        .label_style(font(14.0))
        .axis_desc_style(font(16.0))
        .light_line_style(RGBColor(244, 244, 244))
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()
        .map_err(io_err)?;
    let width = px(2.0).max(1) as u32;
    let marker = px(4.0).max(2);
    // one unit of a dash pattern: about a line's width
    let unit = 2.5 * scale;
    let half = px(10.0);
    for s in &spec.series {
        // lines, edges and open markers in a shade that reads on white; fills in the colour
        let ink = on_white(s.colour);
        let c = RGBColor(ink.0, ink.1, ink.2);
        let fill = RGBColor(s.colour.0, s.colour.1, s.colour.2);
        let line = ShapeStyle::from(&c).stroke_width(width);
        let runs = runs(&s.points, spec.x_log, spec.y_log);
        let name = s.name.clone();
        if s.style == SeriesStyle::Band {
            // each run one translucent polygon, under the curves drawn after it
            let shade = ShapeStyle::from(&fill.mix(0.35)).filled();
            chart
                .draw_series(runs.into_iter().map(|r| Polygon::new(r, shade)))
                .map_err(io_err)?
                .label(name)
                .legend(move |(lx, ly)| Rectangle::new([(lx, ly - half / 2), (lx + 2 * half, ly + half / 2)], shade));
            continue;
        }
        if s.style == SeriesStyle::Points {
            let pts: Vec<(f64, f64)> = runs.into_iter().flatten().collect();
            let lp = move |(lx, ly): (i32, i32)| (lx + half, ly);
            let open = ShapeStyle::from(&c).stroke_width(width);
            let filled = ShapeStyle::from(&fill).filled();
            let edge = ShapeStyle::from(&c).stroke_width((width / 2).max(1));
            let (m, t) = (marker, marker + 1);
            let h = t * 3 / 4;
            // the shape at every point and in the legend (offsets in pixels)
            macro_rules! marks {
                ($shape:expr) => {{
                    chart
                        .draw_series(pts.into_iter().map(|p| EmptyElement::at(p) + $shape))
                        .map_err(io_err)?
                        .label(name)
                        .legend(move |p| EmptyElement::at(lp(p)) + $shape);
                }};
                // a filled shape inside its edge (the same outline in the edge's style)
                ($fill:expr, $edge:expr) => {{
                    chart
                        .draw_series(pts.into_iter().map(|p| EmptyElement::at(p) + $fill + $edge))
                        .map_err(io_err)?
                        .label(name)
                        .legend(move |p| EmptyElement::at(lp(p)) + $fill + $edge);
                }};
            }
            let diamond = vec![(0, -t), (t, 0), (0, t), (-t, 0), (0, -t)];
            let up = vec![(0, -t), (t, h), (-t, h), (0, -t)];
            let down = vec![(0, t), (t, -h), (-t, -h), (0, t)];
            match s.shape {
                Shape::Circle => marks!(Circle::new((0, 0), m, filled), Circle::new((0, 0), m, edge)),
                Shape::Square => marks!(Rectangle::new([(-m, -m), (m, m)], open)),
                Shape::Diamond => marks!(
                    Polygon::new(diamond.clone(), filled),
                    PathElement::new(diamond.clone(), edge)
                ),
                Shape::Triangle => marks!(Polygon::new(up.clone(), filled), PathElement::new(up.clone(), edge)),
                Shape::TriangleDown => marks!(Polygon::new(down.clone(), filled), PathElement::new(down.clone(), edge)),
                // both strokes as one path through the centre
                Shape::Cross => marks!(PathElement::new(vec![(-t, -t), (t, t), (0, 0), (-t, t), (t, -t)], open)),
                Shape::Plus => marks!(PathElement::new(vec![(-t, 0), (t, 0), (0, 0), (0, -t), (0, t)], open)),
            }
            continue;
        }
        line_series(root, &mut chart, &runs, name, s.style, line, (unit, half))?;
    }
    chart
        .configure_series_labels()
        .position(legend_corner(spec))
        .legend_area_size(px(30.0))
        .label_font(font(14.0))
        .background_style(WHITE.mix(0.85))
        .border_style(RGBColor(160, 160, 160))
        .draw()
        .map_err(io_err)?;
    Ok(())
}

/// A line series: its runs as strokes of its pattern (in pixels, so a dash is as long on a
/// log axis as on a linear one) and its legend entry; `unit` is a pattern unit, `half` half
/// the legend sample's length (pixels).
fn line_series<'a, DB, CT>(
    root: &DrawingArea<DB, Shift>,
    chart: &mut ChartContext<'a, DB, CT>,
    runs: &[Vec<(f64, f64)>],
    name: String,
    style: SeriesStyle,
    line: ShapeStyle,
    (unit, half): (f64, i32),
) -> std::io::Result<()>
where
    DB: DrawingBackend + 'a,
    CT: CoordTranslate<From = (f64, f64)>,
{
    let pattern: Vec<f64> = style.pattern().unwrap_or(&[]).iter().map(|l| l * unit).collect();
    // the strokes in pixels, so a dash is as long on a log axis as on a linear one
    for run in runs {
        let pixels: Vec<(f64, f64)> = run
            .iter()
            .map(|p| {
                let b = chart.as_coord_spec().translate(p);
                (f64::from(b.0), f64::from(b.1))
            })
            .collect();
        for stroke in dashes(&pixels, &pattern, (1.0, 1.0)) {
            root.draw(&PathElement::new(pixel_path(&stroke), line))
                .map_err(io_err)?;
        }
    }
    // the legend's sample: the pattern over 2·half pixels (at most four strokes)
    let sample = dashes(&[(0.0, 0.0), (f64::from(2 * half), 0.0)], &pattern, (1.0, 1.0));
    let stroke = |k: usize| pixel_path(sample.get(k).or(sample.last()).map_or(&[][..], |v| v.as_slice()));
    let strokes = [stroke(0), stroke(1), stroke(2), stroke(3)];
    // an empty series still gets its legend entry
    chart
        .draw_series(Vec::<PathElement<(f64, f64)>>::new())
        .map_err(io_err)?
        .label(name)
        .legend(move |(lx, ly)| {
            let at = |k: usize| strokes[k].iter().map(|q| (q.0, q.1)).collect::<Vec<_>>();
            EmptyElement::at((lx, ly))
                + PathElement::new(at(0), line)
                + PathElement::new(at(1), line)
                + PathElement::new(at(2), line)
                + PathElement::new(at(3), line)
        });
    Ok(())
}

/// A stroke's points rounded to pixels.
fn pixel_path(stroke: &[(f64, f64)]) -> Vec<(i32, i32)> {
    stroke
        .iter()
        .map(|q| (q.0.round() as i32, q.1.round() as i32))
        .collect()
}
