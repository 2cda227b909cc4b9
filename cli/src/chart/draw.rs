//! The plotters drawing shared by the SVG and PNG backends: one generic routine over the
//! backend and the (linear or logarithmic) axis types.

use super::font::FAMILY;
use super::{axis_range, drawable, tick_label, ChartSpec, SeriesStyle};
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Series colours (Okabe–Ito, readable by colour-blind readers and in greyscale print),
/// then repeated.
const COLOURS: [RGBColor; 8] = [
    RGBColor(0, 0, 0),
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(120, 120, 120),
];

/// Colour of series `i`.
pub(crate) fn colour(i: usize) -> RGBColor {
    COLOURS[i % COLOURS.len()]
}

fn io_err<E: std::fmt::Display>(e: E) -> std::io::Error {
    std::io::Error::other(format!("chart: {e}"))
}

/// Draws `spec` on `backend` (font sizes and line widths times `scale`) and writes the file.
pub(crate) fn draw<DB: DrawingBackend>(backend: DB, spec: &ChartSpec, scale: f64) -> std::io::Result<()> {
    let root = backend.into_drawing_area();
    root.fill(&WHITE).map_err(io_err)?;
    let (x0, x1) = axis_range(spec, true);
    let (y0, y1) = axis_range(spec, false);
    match (spec.x_log, spec.y_log) {
        (false, false) => plot(&root, spec, scale, x0..x1, y0..y1),
        (true, false) => plot(&root, spec, scale, (x0..x1).log_scale(), y0..y1),
        (false, true) => plot(&root, spec, scale, x0..x1, (y0..y1).log_scale()),
        (true, true) => plot(&root, spec, scale, (x0..x1).log_scale(), (y0..y1).log_scale()),
    }?;
    root.present().map_err(io_err)
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
fn legend_corner(spec: &ChartSpec) -> SeriesLabelPosition {
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

fn plot<DB, X, Y>(root: &DrawingArea<DB, Shift>, spec: &ChartSpec, scale: f64, x: X, y: Y) -> std::io::Result<()>
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
    let fmt = |v: &f64| tick_label(*v);
    chart
        .configure_mesh()
        .x_desc(spec.x_label.as_str())
        .y_desc(spec.y_label.as_str())
        .x_labels(8)
        .y_labels(8)
        .x_label_formatter(&fmt)
        .y_label_formatter(&fmt)
        .label_style(font(14.0))
        .axis_desc_style(font(16.0))
        .light_line_style(RGBColor(244, 244, 244))
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()
        .map_err(io_err)?;
    let width = px(2.0).max(1) as u32;
    let marker = px(4.0).max(2);
    let mut point_series = 0usize;
    for (i, s) in spec.series.iter().enumerate() {
        let c = colour(i);
        let style = ShapeStyle::from(&c).stroke_width(width);
        let runs = runs(&s.points, spec.x_log, spec.y_log);
        let name = s.name.clone();
        match s.style {
            SeriesStyle::Line | SeriesStyle::Dashed => {
                let dashed = s.style == SeriesStyle::Dashed;
                let (dash, gap) = (px(7.0), px(5.0));
                let mut first = true;
                // an empty series still gets its legend entry
                let runs = if runs.is_empty() { vec![Vec::new()] } else { runs };
                for run in runs {
                    let anno = if dashed {
                        chart.draw_series(DashedLineSeries::new(run, dash, gap, style))
                    } else {
                        chart.draw_series(LineSeries::new(run, style))
                    }
                    .map_err(io_err)?;
                    if first {
                        let half = px(10.0);
                        let anno = anno.label(name.clone());
                        if dashed {
                            anno.legend(move |(lx, ly)| {
                                EmptyElement::at((lx, ly))
                                    + PathElement::new(vec![(0, 0), (half * 2 / 5, 0)], style)
                                    + PathElement::new(vec![(half * 3 / 5, 0), (half, 0)], style)
                                    + PathElement::new(vec![(half * 7 / 5, 0), (half * 2, 0)], style)
                            });
                        } else {
                            anno.legend(move |(lx, ly)| {
                                EmptyElement::at((lx, ly)) + PathElement::new(vec![(0, 0), (half * 2, 0)], style)
                            });
                        }
                        first = false;
                    }
                }
            }
            SeriesStyle::Points => {
                let shape = point_series % 4;
                point_series += 1;
                let pts: Vec<(f64, f64)> = runs.into_iter().flatten().collect();
                let open = ShapeStyle::from(&c).stroke_width(width);
                let filled = ShapeStyle::from(&c).filled();
                let m = marker;
                let lp = move |(lx, ly): (i32, i32)| (lx + px(10.0), ly);
                match shape {
                    0 => {
                        chart
                            .draw_series(pts.into_iter().map(|p| Circle::new(p, m, filled)))
                            .map_err(io_err)?
                            .label(name)
                            .legend(move |c| Circle::new(lp(c), m, filled));
                    }
                    1 => {
                        chart
                            .draw_series(pts.into_iter().map(|p| TriangleMarker::new(p, m + 1, filled)))
                            .map_err(io_err)?
                            .label(name)
                            .legend(move |c| TriangleMarker::new(lp(c), m + 1, filled));
                    }
                    2 => {
                        chart
                            .draw_series(
                                pts.into_iter()
                                    .map(|p| EmptyElement::at(p) + Rectangle::new([(-m, -m), (m, m)], open)),
                            )
                            .map_err(io_err)?
                            .label(name)
                            .legend(move |c| EmptyElement::at(lp(c)) + Rectangle::new([(-m, -m), (m, m)], open));
                    }
                    _ => {
                        chart
                            .draw_series(pts.into_iter().map(|p| Cross::new(p, m + 1, open)))
                            .map_err(io_err)?
                            .label(name)
                            .legend(move |c| Cross::new(lp(c), m + 1, open));
                    }
                }
            }
        }
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
