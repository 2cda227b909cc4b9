//! `asperity figure`'s drawing of the library's figures ([`asperity::report::figure`]): a
//! figure as the one chart model ([`crate::chart::Chart`]), each series in the look of what it
//! shows ([`crate::looks`]: a model's curve in the model's colour, \[S\]'s values with the
//! reference marks, GFMD's points as everywhere), and as a table for reading.

use crate::chart::{Chart, Rgb, Scale, Series, SeriesStyle, Shape};
use crate::looks::{kind_slot, look, model_colour, Role, PIN_COLOURS, REFERENCE_MARKS};
use asperity::report::figure::table1::{Column, Table1};
use asperity::report::figure::{FigureData, SeriesKind, Style};

/// The line style of a series.
pub fn series_style(style: Style) -> SeriesStyle {
    match style {
        Style::Line => SeriesStyle::Line,
        Style::Points => SeriesStyle::Points,
        Style::Dashed => SeriesStyle::Dashed,
    }
}

/// The colour and file marker of what a series shows: a model's curve in its model's colour
/// (a later curve of a model already drawn, Fig. 8's thicknesses, in the pins' colours in
/// turn), a value of \[S\] of a model in the model's colour and the others in the text colour
/// with the reference marks in turn, Table 1's computed moments in model 3's colour.
pub fn series_look(kind: SeriesKind) -> (Rgb, Shape) {
    let role = |r: Role| look(r, 0, 0).ink.rgb();
    match kind {
        SeriesKind::Theory { model, repeat: None } => (model_colour(kind_slot(model)), Shape::Circle),
        SeriesKind::Theory { repeat: Some(i), .. } => (PIN_COLOURS[i % PIN_COLOURS.len()], Shape::Circle),
        SeriesKind::ClosedForm { second } => (role(if second { Role::Closed2 } else { Role::Closed }), Shape::Circle),
        SeriesKind::Paper { model, nth } => (
            model.map_or(role(Role::Reference), |k| model_colour(kind_slot(k))),
            REFERENCE_MARKS[nth % REFERENCE_MARKS.len()].1,
        ),
        SeriesKind::Gfmd => (role(Role::Gfmd), look(Role::Gfmd, 0, 0).shape),
        SeriesKind::GfmdTheory => (role(Role::GfmdTheory), look(Role::GfmdTheory, 0, 0).shape),
        SeriesKind::Moments { paper: true } => (role(Role::Reference), Shape::Circle),
        SeriesKind::Moments { paper: false } => (look(Role::Theory, 2, 0).ink.rgb(), Shape::Circle),
    }
}

/// The chart of a figure: each series in its look; a series that would look like an earlier
/// one gets the next line style or shape ([`crate::chart::tell_apart`]). On a log y axis with
/// [`FigureData::y_decades`], values more than that many decades below the largest are left
/// out (gaps), so the axis spans those decades.
pub fn chart(data: &FigureData) -> Chart {
    let floor = y_floor(data);
    let mut c = Chart::new(
        data.title.clone(),
        &data.x_label,
        &data.y_label,
        Scale::of(data.x_log),
        Scale::of(data.y_log),
    );
    c.series = data
        .series
        .iter()
        .map(|s| {
            let points = s
                .points
                .iter()
                .map(|p| (p.x, p.y.filter(|&y| y >= floor).unwrap_or(f64::NAN)))
                .collect();
            let (colour, shape) = series_look(s.kind);
            Series::painted(s.name.clone(), points, series_style(s.style), colour, shape)
        })
        .collect();
    c.tell_apart();
    c
}

/// The least value the chart draws: [`FigureData::y_decades`] below the largest finite value
/// on a log y axis, else −∞.
fn y_floor(data: &FigureData) -> f64 {
    let Some(d) = data.y_decades.filter(|_| data.y_log) else {
        return f64::NEG_INFINITY;
    };
    let top = data
        .series
        .iter()
        .flat_map(|s| &s.points)
        .filter_map(|p| p.y.filter(|y| y.is_finite()))
        .fold(f64::NEG_INFINITY, f64::max);
    if top > 0.0 {
        top / 10f64.powf(d)
    } else {
        f64::NEG_INFINITY
    }
}

/// A figure as a table for reading: one block per series.
pub fn table(data: &FigureData) -> String {
    let mut out = format!("{}\n(system: {})\n", data.title, data.preset);
    for s in &data.series {
        out.push_str(&format!("\n{}\n  {:>14}  {:>14}\n", s.name, "x", "y"));
        for p in &s.points {
            let y = p.y.map_or("–".to_string(), |y| format!("{y:.6e}"));
            out.push_str(&format!("  {:>14.6e}  {:>14}\n", p.x, y));
        }
    }
    if !data.notes.is_empty() {
        out.push_str("\nnotes:\n");
        for n in &data.notes {
            out.push_str(&format!("  {n}\n"));
        }
    }
    out.trim_end().to_string()
}

/// Table 1 as \[S\] prints it, computed values above \[S\]'s.
pub fn table1(t: &Table1) -> String {
    let f = |x: Option<f64>| x.map_or("–".to_string(), |v| format!("{v:.4}"));
    let mut out = format!(
        "[S] Table 1: system I, no adhesion, semi-infinite, p* = {}\n\n",
        t.pressure
    );
    out.push_str(&format!("{:<26}", ""));
    for c in &t.columns {
        out.push_str(&format!("{:>14}", c.column));
    }
    out.push('\n');
    let mut row = |label: &str, get: &dyn Fn(&Column) -> String| {
        out.push_str(&format!("{label:<26}"));
        for c in &t.columns {
            out.push_str(&format!("{:>14}", get(c)));
        }
        out.push('\n');
    };
    row("σ̄_c* (asperity)", &|c| f(c.mean_contact_stress));
    row("σ̄_c* ([S])", &|c| format!("{:.4}", c.paper_mean_contact_stress));
    row("⟨δσ_c²⟩* (asperity)", &|c| f(c.contact_stress_variance));
    row("⟨δσ_c²⟩* ([S])", &|c| {
        format!("{:.4}", c.paper_contact_stress_variance)
    });
    row("a_r (asperity)", &|c| f(c.a_r));
    for n in &t.notes {
        out.push_str(&format!("\n{n}"));
    }
    out.trim_end().to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use asperity::input::model::ModelKind;
    use asperity::report::figure::{compute, spec, DataPoint, DataSeries};

    /// A figure of one model 4 curve through `points` (x, y), on a log y axis with `y_decades`.
    fn one_curve(points: &[(f64, Option<f64>)], y_log: bool, y_decades: Option<f64>) -> FigureData {
        // Table 1's frame, its series replaced
        let mut data = Table1 {
            pressure: 0.01,
            columns: vec![],
            notes: vec![],
        }
        .figure();
        data.y_log = y_log;
        data.y_decades = y_decades;
        data.series = vec![DataSeries {
            name: "model 4".into(),
            style: Style::Line,
            kind: SeriesKind::Theory {
                model: ModelKind::Four,
                repeat: None,
            },
            points: points
                .iter()
                .map(|&(x, y)| DataPoint {
                    x,
                    y,
                    note: y.is_none().then(|| "did not converge".into()),
                })
                .collect(),
        }];
        data
    }

    #[test]
    fn a_point_without_a_value_is_a_gap_in_the_chart_and_a_dash_in_the_table() {
        let data = one_curve(&[(0.01, None), (0.1, Some(0.5))], false, None);
        // the chart gets a gap (NaN), which the renderers leave out
        assert!(chart(&data).series[0].points[0].1.is_nan());
        assert_eq!(crate::chart::flatten(&chart(&data)).series[0].colour, model_colour(3));
        assert!(table(&data).contains('–'));
    }

    #[test]
    fn a_log_axis_with_y_decades_draws_only_those_decades_and_the_data_keep_every_value() {
        let ys = [1e-300, 1e-4, 2e-3, 0.5, 2.0];
        let pts: Vec<(f64, Option<f64>)> = ys.iter().enumerate().map(|(i, &y)| (i as f64, Some(y))).collect();
        let mut data = one_curve(&pts, true, Some(3.0));
        // the floor is 2 / 10³ = 2e-3: 1e-300 and 1e-4 become gaps, 2e-3 stays
        let drawn: Vec<bool> = chart(&data).series[0].points.iter().map(|p| p.1.is_finite()).collect();
        assert_eq!(drawn, [false, false, true, true, true]);
        let (lo, hi) = crate::chart::axis_range(&crate::chart::flatten(&chart(&data)), false);
        assert!(lo > 1e-3 && hi < 3.0, "{lo} {hi}");
        assert_eq!(data.csv().lines().count(), 6);
        // on a linear axis, or without y_decades, every value is drawn
        data.y_decades = None;
        assert!(chart(&data).series[0].points.iter().all(|p| p.1 > 0.0));
        data.y_decades = Some(3.0);
        data.y_log = false;
        assert!(chart(&data).series[0].points.iter().all(|p| p.1 > 0.0));
    }

    #[test]
    fn figure_8_on_a_log_axis_lifts_the_thick_slabs_off_the_bottom_rows() {
        // the height of each curve's peak as a fraction of its axis
        let peaks = |id: &str| -> Vec<(String, f64)> {
            let chart = crate::chart::flatten(&chart(&compute::compute(&spec::resolve(id).unwrap(), None).unwrap()));
            let (lo, hi) = crate::chart::axis_range(&chart, false);
            let height = |y: f64| {
                if chart.y_log {
                    (y / lo).log10() / (hi / lo).log10()
                } else {
                    (y - lo) / (hi - lo)
                }
            };
            chart
                .series
                .iter()
                .map(|s| {
                    let top = s
                        .points
                        .iter()
                        .map(|p| p.1)
                        .filter(|y| y.is_finite())
                        .fold(0.0, f64::max);
                    (s.name.clone(), height(top))
                })
                .collect()
        };
        let linear = peaks("8");
        let log = peaks("8-log");
        assert_eq!(linear.len(), 4);
        for ((name, lin), (_, h)) in linear.iter().zip(&log).skip(2) {
            // t·q_r 1 and semi-infinite: on the bottom rows of the linear axis
            assert!(*lin < 0.1, "{name}: peak at {lin:.2} of the linear axis");
            assert!(*h > 0.4, "{name}: peak at {h:.2} of the log axis");
        }
        for (name, h) in &log {
            assert!(*h > 0.4, "{name}: peak at {h:.2} of the log axis");
        }
    }
}
