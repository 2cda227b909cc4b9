//! Plain-text charts: a character grid with one glyph per series, tick labels on both axes,
//! the axis titles and a legend. No colours or escape codes, so the output can be piped,
//! pasted into a README or compared in a test.

use super::{axis_range, drawable, flatten, Chart, Flat, SeriesStyle};
use crate::numfmt::{nice_ticks, tick};

/// Glyphs of the series, in order (then repeated).
pub const GLYPHS: [char; 10] = ['*', 'o', '+', 'x', '#', '@', '%', '&', '=', '~'];

/// Renders `chart` as text, `width` × `height` characters overall (at least 40 × 12).
pub fn render_text(chart: &Chart, width: usize, height: usize) -> String {
    let spec = &flatten(chart);
    let (width, height) = (width.max(40), height.max(12));
    let (x0, x1) = axis_range(spec, true);
    let (y0, y1) = axis_range(spec, false);
    let tx = |v: f64, lo: f64, hi: f64, log: bool| {
        if log {
            (v / lo).ln() / (hi / lo).ln()
        } else {
            (v - lo) / (hi - lo)
        }
    };
    let label = tick;
    let legend = legend_lines(spec, width);
    // rows: title, y title, plot, x axis line, x ticks, x title, legend
    let plot_h = height.saturating_sub(5 + legend.len()).max(4);
    let mut ylabels: Vec<String> = vec![String::new(); plot_h];
    for v in nice_ticks(y0, y1, spec.y_log, (plot_h / 4).max(2)) {
        let r = ((1.0 - tx(v, y0, y1, spec.y_log)) * (plot_h - 1) as f64).round();
        if r >= 0.0 && (r as usize) < plot_h {
            ylabels[r as usize] = label(v);
        }
    }
    let margin = ylabels.iter().map(|l| l.chars().count()).max().unwrap_or(1) + 1;
    let plot_w = width.saturating_sub(margin + 1).max(10);
    let mut grid = vec![vec![' '; plot_w]; plot_h];
    let cell = |p: (f64, f64)| -> (f64, f64) {
        (
            tx(p.0, x0, x1, spec.x_log) * (plot_w - 1) as f64,
            (1.0 - tx(p.1, y0, y1, spec.y_log)) * (plot_h - 1) as f64,
        )
    };
    let put = |grid: &mut Vec<Vec<char>>, c: (f64, f64), g: char| {
        let (cx, cy) = (c.0.round(), c.1.round());
        if cx >= 0.0 && cy >= 0.0 && (cx as usize) < plot_w && (cy as usize) < plot_h {
            grid[cy as usize][cx as usize] = g;
        }
    };
    // lines first, points on top
    for pass in [false, true] {
        for (i, s) in spec.series.iter().enumerate() {
            let g = GLYPHS[i % GLYPHS.len()];
            let points = s.style == SeriesStyle::Points;
            if points != pass {
                continue;
            }
            let mut prev: Option<(f64, f64)> = None;
            for &p in &s.points {
                if !drawable(p, spec.x_log, spec.y_log) {
                    prev = None;
                    continue;
                }
                let c = cell(p);
                if points {
                    put(&mut grid, c, g);
                    continue;
                }
                match prev {
                    None => put(&mut grid, c, g),
                    Some(a) => {
                        let steps = ((c.0 - a.0).abs().max((c.1 - a.1).abs()) * 2.0).ceil().max(1.0) as usize;
                        for k in 1..=steps {
                            // a broken line leaves columns empty: a dashed one every other
                            // stretch of two, a dotted one two of three, a dash-dotted one
                            // columns 3 and 5 of six
                            let t = k as f64 / steps as f64;
                            let q = (a.0 + t * (c.0 - a.0), a.1 + t * (c.1 - a.1));
                            let col = q.0.round() as i64;
                            let gap = match s.style {
                                SeriesStyle::Dashed => (col / 2) % 2 == 1,
                                SeriesStyle::Dotted => col % 3 != 0,
                                SeriesStyle::DashDot => matches!(col % 6, 3 | 5),
                                _ => false,
                            };
                            if gap {
                                continue;
                            }
                            put(&mut grid, q, g);
                        }
                    }
                }
                prev = Some(c);
            }
        }
    }
    let mut out = String::new();
    out.push_str(&spec.title);
    out.push('\n');
    out.push_str(&format!("{:>margin$} {}\n", "", spec.y_label, margin = margin));
    for (r, row) in grid.iter().enumerate() {
        let line: String = row.iter().collect();
        out.push_str(&format!("{:>m$}|{}\n", ylabels[r], line.trim_end(), m = margin));
    }
    out.push_str(&format!("{:>m$}+{}\n", "", "-".repeat(plot_w), m = margin));
    let ticks = x_tick_row(spec, (x0, x1), margin, plot_w);
    out.push_str(ticks.trim_end());
    out.push('\n');
    let axis = format!("{}{}", spec.x_label, if spec.x_log { "  (log)" } else { "" });
    let pad = (margin + 1 + plot_w / 2).saturating_sub(axis.chars().count() / 2);
    out.push_str(&format!("{:pad$}{axis}\n", "", pad = pad));
    for l in legend {
        out.push_str(&l);
        out.push('\n');
    }
    // nothing wider than asked for
    out.lines()
        .map(|l| {
            if l.chars().count() > width {
                let mut t: String = l.chars().take(width - 1).collect();
                t.push('…');
                t
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

/// The legend: one entry per series (glyph, name, line style), wrapped to `width`.
fn legend_lines(spec: &Flat, width: usize) -> Vec<String> {
    let mut legend: Vec<String> = vec![String::new()];
    for (i, s) in spec.series.iter().enumerate() {
        let entry = format!("{} {} ({})", GLYPHS[i % GLYPHS.len()], s.name, s.style.name());
        let last = legend.last_mut().expect("non-empty");
        if !last.is_empty() && last.chars().count() + 3 + entry.chars().count() > width {
            legend.push(entry);
        } else {
            if !last.is_empty() {
                last.push_str("   ");
            }
            last.push_str(&entry);
        }
    }
    legend
}

/// The x tick labels at round values, left out where they would overlap, under a plot of
/// `plot_w` columns after a `margin`.
fn x_tick_row(spec: &Flat, (x0, x1): (f64, f64), margin: usize, plot_w: usize) -> String {
    let tx = |v: f64| {
        if spec.x_log {
            (v / x0).ln() / (x1 / x0).ln()
        } else {
            (v - x0) / (x1 - x0)
        }
    };
    let mut ticks = vec![' '; plot_w + margin + 12];
    let mut free_from = 0usize;
    for v in nice_ticks(x0, x1, spec.x_log, (plot_w / 12).max(2)) {
        let t = tx(v);
        let text = tick(v);
        let pos = margin + 1 + (t * (plot_w - 1) as f64).round() as usize;
        let n = text.chars().count();
        let start = pos.saturating_sub(n / 2);
        if start < free_from || start + n > ticks.len() {
            continue;
        }
        ticks[pos] = '|';
        for (j, ch) in text.chars().enumerate() {
            ticks[start + j] = ch;
        }
        free_from = start + n + 2;
    }
    ticks.iter().collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart::{Rgb, Scale, Series, Shape};

    #[test]
    fn a_rising_line_runs_from_lower_left_to_upper_right() {
        let mut spec = Chart::new("t", "x (1)", "y (1)", Scale::Linear, Scale::Linear);
        let black = (Rgb(0, 0, 0), Shape::Circle);
        spec.series = vec![
            Series::painted("up", vec![(0.0, 0.0), (1.0, 1.0)], SeriesStyle::Line, black.0, black.1),
            Series::painted(
                "dots",
                vec![(0.5, f64::NAN), (1.0, 0.0)],
                SeriesStyle::Points,
                black.0,
                black.1,
            ),
        ];
        let text = render_text(&spec, 60, 20);
        let rows: Vec<&str> = text.lines().filter(|l| l.contains('|')).collect();
        let col = |l: &str, c: char| l.split_once('|').and_then(|(_, r)| r.find(c));
        let starred: Vec<&&str> = rows.iter().filter(|l| col(l, '*').is_some()).collect();
        let (top, bottom) = (starred.first().unwrap(), starred.last().unwrap());
        // the highest '*' is right of the lowest: the line rises
        assert!(col(top, '*').unwrap() > col(bottom, '*').unwrap() + 30, "{text}");
        // the point (1, 0) sits on the lowest starred row, at its right end
        assert!(bottom.trim_end().ends_with('o'), "{text}");
        // the gap (NaN) is not drawn: one 'o' only
        assert_eq!(
            text.matches('o').count() - "o dots (points)".matches('o').count() - "up (line)".matches('o').count(),
            1,
            "{text}"
        );
        assert!(
            text.contains("* up (line)") && text.contains("o dots (points)"),
            "{text}"
        );
        assert!(text.lines().all(|l| l.chars().count() <= 60), "{text}");
    }
}
