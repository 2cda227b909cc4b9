//! `asperity figure`: the figures and Table 1 of \[S\], computed on the paper's systems with
//! the paper's models, as data (table, CSV, JSON), a text chart, and SVG/PNG files.
//!
//! Figures 1–8 are described by TOML files ([`spec`], `figures/` in the repository, built
//! into the binary); Table 1 is [`table1`]. [`compute`] evaluates the curves, [`FigureData`]
//! holds the result and turns into the one chart model, [`crate::chart::Chart`].

pub mod compute;
mod curves;
pub mod refine;
pub mod spec;
pub mod table1;

use crate::chart::{Chart, Rgb, Scale, Series, SeriesStyle, Shape};
use serde::Serialize;

/// One point of a series; `y` is None where the solver did not converge (with the reason).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DataPoint {
    /// x.
    pub x: f64,
    /// y (null: no value).
    pub y: Option<f64>,
    /// Why there is no value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// One series of a figure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DataSeries {
    /// Legend label.
    pub name: String,
    /// How it is drawn.
    #[serde(serialize_with = "style_name")]
    pub style: SeriesStyle,
    /// The points.
    pub points: Vec<DataPoint>,
    /// Colour in SVG/PNG (a model's from [`crate::looks`]).
    #[serde(skip)]
    pub colour: Rgb,
    /// Marker of points in SVG/PNG.
    #[serde(skip)]
    pub shape: Shape,
}

fn style_name<S: serde::Serializer>(s: &SeriesStyle, ser: S) -> Result<S::Ok, S::Error> {
    ser.serialize_str(s.name())
}

/// A computed figure (the JSON of `asperity figure ID --format json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FigureData {
    /// Figure id.
    pub id: String,
    /// Title.
    pub title: String,
    /// Preset (system) name.
    pub preset: String,
    /// The measured surface or PSD table the curves are of (absent: the preset's spectrum).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spectrum_source: Option<String>,
    /// x-axis title with units.
    pub x_label: String,
    /// y-axis title with units.
    pub y_label: String,
    /// Log x axis.
    pub x_log: bool,
    /// Log y axis.
    pub y_log: bool,
    /// On a log y axis, the decades the chart draws below the largest value (the data keep
    /// every value).
    #[serde(skip)]
    pub y_decades: Option<f64>,
    /// Theory curves, closed forms, \[S\] values, GFMD points.
    pub series: Vec<DataSeries>,
    /// Scalars, grids and anything that did not converge.
    pub notes: Vec<String>,
}

impl FigureData {
    /// The chart of this figure: each series in its colour; a series that would look like
    /// an earlier one (a second curve of one model) gets the next line style or shape
    /// ([`crate::chart::tell_apart`]). On a log y axis with [`FigureData::y_decades`], values
    /// more than that many decades below the largest are left out (gaps), so the axis spans
    /// those decades.
    pub fn chart(&self) -> Chart {
        let floor = self.y_floor();
        let mut c = Chart::new(
            self.title.clone(),
            &self.x_label,
            &self.y_label,
            Scale::of(self.x_log),
            Scale::of(self.y_log),
        );
        c.series = self
            .series
            .iter()
            .map(|s| {
                let points = s
                    .points
                    .iter()
                    .map(|p| (p.x, p.y.filter(|&y| y >= floor).unwrap_or(f64::NAN)))
                    .collect();
                Series::painted(s.name.clone(), points, s.style, s.colour, s.shape)
            })
            .collect();
        c.tell_apart();
        c
    }

    /// The least value the chart draws: [`FigureData::y_decades`] below the largest finite
    /// value on a log y axis, else −∞.
    fn y_floor(&self) -> f64 {
        let Some(d) = self.y_decades.filter(|_| self.y_log) else {
            return f64::NEG_INFINITY;
        };
        let top = self
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

    /// CSV: `series,x,y,note`, one row per point; no value is an empty cell.
    pub fn csv(&self) -> String {
        let mut out = String::from("series,x,y,note");
        let q = |s: &str| {
            if s.contains([',', '"', '\n']) {
                format!("\"{}\"", s.replace('"', "\"\""))
            } else {
                s.to_string()
            }
        };
        for s in &self.series {
            for p in &s.points {
                out.push_str(&format!(
                    "\n{},{:e},{},{}",
                    q(&s.name),
                    p.x,
                    p.y.map_or(String::new(), |y| format!("{y:e}")),
                    q(p.note.as_deref().unwrap_or(""))
                ));
            }
        }
        out
    }

    /// A table for reading: one block per series.
    pub fn table(&self) -> String {
        let mut out = format!("{}\n(system: {})\n", self.title, self.preset);
        for s in &self.series {
            out.push_str(&format!("\n{}\n  {:>14}  {:>14}\n", s.name, "x", "y"));
            for p in &s.points {
                let y = p.y.map_or("–".to_string(), |y| format!("{y:.6e}"));
                out.push_str(&format!("  {:>14.6e}  {:>14}\n", p.x, y));
            }
        }
        if !self.notes.is_empty() {
            out.push_str("\nnotes:\n");
            for n in &self.notes {
                out.push_str(&format!("  {n}\n"));
            }
        }
        out.trim_end().to_string()
    }
}

/// The figures `asperity figure --list` names: (id, one line).
pub fn list() -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = spec::BUILTIN
        .iter()
        .map(|(id, text)| {
            let d = spec::FigureSpec::parse(text, id)
                .map(|s| s.description)
                .unwrap_or_else(|e| format!("(invalid: {e})"));
            (id.to_string(), d)
        })
        .collect();
    out.push((spec::TABLE_1.into(), table1::DESCRIPTION.into()));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_without_a_value_is_an_empty_cell_with_its_note() {
        let data = FigureData {
            id: "x".into(),
            title: "t".into(),
            preset: "system-2".into(),
            spectrum_source: None,
            x_label: "x".into(),
            y_label: "y".into(),
            x_log: true,
            y_log: false,
            y_decades: None,
            series: vec![DataSeries {
                name: "model 4".into(),
                style: SeriesStyle::Line,
                colour: crate::looks::model_colour(3),
                shape: Shape::Circle,
                points: vec![
                    DataPoint {
                        x: 0.01,
                        y: None,
                        note: Some("adhesive solver did not converge: stalled, residual 1e-2".into()),
                    },
                    DataPoint {
                        x: 0.1,
                        y: Some(0.5),
                        note: None,
                    },
                ],
            }],
            notes: vec![],
        };
        let csv = data.csv();
        assert_eq!(
            csv.lines().nth(1),
            Some("model 4,1e-2,,\"adhesive solver did not converge: stalled, residual 1e-2\"")
        );
        assert_eq!(csv.lines().nth(2), Some("model 4,1e-1,5e-1,"));
        let json = serde_json::to_value(&data).unwrap();
        assert!(json["series"][0]["points"][0]["y"].is_null());
        assert!(!serde_json::to_string(&data).unwrap().contains("NaN"));
        // the chart gets a gap (NaN), which the renderers leave out
        assert!(data.chart().series[0].points[0].1.is_nan());
        assert!(data.table().contains('–'));
    }

    #[test]
    fn a_log_axis_with_y_decades_draws_only_those_decades_and_the_data_keep_every_value() {
        let pts = |ys: &[f64]| -> Vec<DataPoint> {
            ys.iter()
                .enumerate()
                .map(|(i, &y)| DataPoint {
                    x: i as f64,
                    y: Some(y),
                    note: None,
                })
                .collect()
        };
        let mut data = FigureData {
            id: "x".into(),
            title: "t".into(),
            preset: "system-2".into(),
            spectrum_source: None,
            x_label: "x".into(),
            y_label: "y".into(),
            x_log: false,
            y_log: true,
            y_decades: Some(3.0),
            series: vec![DataSeries {
                name: "a".into(),
                style: SeriesStyle::Line,
                colour: crate::looks::model_colour(3),
                shape: Shape::Circle,
                points: pts(&[1e-300, 1e-4, 2e-3, 0.5, 2.0]),
            }],
            notes: vec![],
        };
        // the floor is 2 / 10³ = 2e-3: 1e-300 and 1e-4 become gaps, 2e-3 stays
        let drawn: Vec<bool> = data.chart().series[0].points.iter().map(|p| p.1.is_finite()).collect();
        assert_eq!(drawn, [false, false, true, true, true]);
        let (lo, hi) = crate::chart::axis_range(&crate::chart::flatten(&data.chart()), false);
        assert!(lo > 1e-3 && hi < 3.0, "{lo} {hi}");
        assert_eq!(data.csv().lines().count(), 6);
        // on a linear axis, or without y_decades, every value is drawn
        data.y_decades = None;
        assert!(data.chart().series[0].points.iter().all(|p| p.1 > 0.0));
        data.y_decades = Some(3.0);
        data.y_log = false;
        assert!(data.chart().series[0].points.iter().all(|p| p.1 > 0.0));
    }

    #[test]
    fn figure_8_on_a_log_axis_lifts_the_thick_slabs_off_the_bottom_rows() {
        // the height of each curve's peak as a fraction of its axis
        let peaks = |id: &str| -> Vec<(String, f64)> {
            let chart = crate::chart::flatten(&compute::compute(&spec::resolve(id).unwrap(), None).unwrap().chart());
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
