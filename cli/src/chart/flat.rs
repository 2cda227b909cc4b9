//! A [`Chart`] as the text and file renderers draw it ([`Flat`]): every series with its look
//! resolved to a colour and a marker, the markers a file shows turned into series, and what
//! the terminal draws its own way given a file's form.
//!
//! - the −σ_a* wall, the jump-in and the pull-off markers become dashed vertical lines over
//!   the data's y range (> 0 on a log axis), one series (one legend entry) per role; guide
//!   lines (σ* = 0, the p* line) are left out;
//! - the current point is named "current …" (the file has no cursor to tell it apart);
//! - a band (columns of points on screen) becomes its outline ([`super::band_outline`]),
//!   filled;
//! - with [`Chart::clip_y`], points below the chart's y range are gaps, as on screen.

use super::model::{Chart, Series};
use super::style::{Rgb, SeriesStyle, Shape};
use crate::looks::Role;

/// One series as a file draws it.
#[derive(Debug, Clone, PartialEq)]
pub struct FlatSeries {
    /// Legend entry (also the SVG's text for this series).
    pub name: String,
    /// (x, y) in data units; non-finite points are gaps.
    pub points: Vec<(f64, f64)>,
    /// Line (solid, dashed, dotted, dash-dotted), points or a filled band.
    pub style: SeriesStyle,
    /// Colour.
    pub colour: Rgb,
    /// Marker of a [`SeriesStyle::Points`] series.
    pub shape: Shape,
}

/// A chart as the text and file renderers draw it.
#[derive(Debug, Clone, PartialEq)]
pub struct Flat {
    /// Title above the plot.
    pub title: String,
    /// x-axis title, with units.
    pub x_label: String,
    /// y-axis title, with units.
    pub y_label: String,
    /// Logarithmic x axis.
    pub x_log: bool,
    /// Logarithmic y axis.
    pub y_log: bool,
    /// The series, drawn in order (the legend lists them in the same order).
    pub series: Vec<FlatSeries>,
}

/// `chart` as the text and file renderers draw it (see the module docs).
pub fn flatten(chart: &Chart) -> Flat {
    let floor = chart.y_floor();
    let kept = |s: &Series| -> Vec<(f64, f64)> {
        s.points
            .iter()
            .map(|&(x, y)| {
                if y >= floor || !y.is_finite() {
                    (x, y)
                } else {
                    (x, f64::NAN)
                }
            })
            .collect()
    };
    let mut series = markers(chart, floor);
    for i in chart.draw_order() {
        let s = &chart.series[i];
        let look = chart.series_look(i);
        let mut points = kept(s);
        // the terminal shades a band with columns of points; a file fills its outline
        let style = if s.role == Role::Band {
            points = super::band_outline(&points);
            SeriesStyle::Band
        } else {
            s.style
        };
        series.push(FlatSeries {
            // the current point is p* on the load charts, q on the scale view's
            name: if s.role == Role::Current {
                format!("current {}", s.name)
            } else {
                s.name.clone()
            },
            points,
            style,
            colour: look.ink.rgb(),
            shape: look.shape,
        });
    }
    Flat {
        title: chart.title.clone(),
        x_label: chart.x_label.clone(),
        y_label: chart.y_label.clone(),
        x_log: chart.xs.is_log(),
        y_log: chart.ys.is_log(),
        series,
    }
}

/// The wall, jump-in and pull-off markers as dashed vertical lines over the data's y range
/// (from 0, or the least positive value on a log axis), one series per role.
fn markers(chart: &Chart, floor: f64) -> Vec<FlatSeries> {
    let ys = || {
        chart
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(|q| q.1))
            .filter(|y| y.is_finite())
    };
    let top = ys().filter(|y| *y >= floor).fold(f64::NEG_INFINITY, f64::max);
    let lo = if chart.ys.is_log() {
        ys().filter(|y| *y > 0.0).fold(f64::INFINITY, f64::min)
    } else {
        ys().filter(|y| *y >= floor).fold(f64::INFINITY, f64::min).min(0.0)
    };
    let mut out: Vec<FlatSeries> = Vec::new();
    let mut marked: Vec<(Role, usize)> = Vec::new();
    for v in &chart.vlines {
        let drawn = matches!(v.role, Role::Wall | Role::JumpIn | Role::PullOff);
        if !(drawn && lo.is_finite() && top.is_finite()) {
            continue;
        }
        let line = [(v.x, lo), (v.x, top)];
        match marked.iter().find(|(r, _)| *r == v.role) {
            Some(&(_, i)) => {
                let s = &mut out[i];
                s.points.push((f64::NAN, f64::NAN));
                s.points.extend(line);
                if s.name.is_empty() {
                    s.name = v.name.clone();
                }
            }
            None => {
                let look = chart.vline_look(v);
                marked.push((v.role, out.len()));
                out.push(FlatSeries {
                    name: v.name.clone(),
                    points: line.to_vec(),
                    style: SeriesStyle::Dashed,
                    colour: look.ink.rgb(),
                    shape: look.shape,
                });
            }
        }
    }
    out
}
