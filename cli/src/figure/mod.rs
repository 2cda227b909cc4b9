//! `asperity figure`: the figures and Table 1 of \[S\], computed on the paper's systems with
//! the paper's models, as data (table, CSV, JSON), a text chart, and SVG/PNG files.
//!
//! Figures 1–8 are described by TOML files ([`spec`], `figures/` in the repository, built
//! into the binary); Table 1 is [`table1`]. [`compute`] evaluates the curves, [`FigureData`]
//! holds the result and turns into a [`crate::chart::ChartSpec`].

pub mod compute;
mod curves;
pub mod refine;
pub mod spec;
pub mod table1;

use crate::chart::{tell_apart, ChartSpec, Rgb, Series, SeriesStyle, Shape};
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
    /// Theory curves, closed forms, \[S\] values, GFMD points.
    pub series: Vec<DataSeries>,
    /// Scalars, grids and anything that did not converge.
    pub notes: Vec<String>,
}

impl FigureData {
    /// The chart of this figure: each series in its colour; a series that would look like
    /// an earlier one (a second curve of one model) gets the next line style or shape
    /// ([`crate::chart::tell_apart`]).
    pub fn chart(&self) -> ChartSpec {
        let mut series: Vec<Series> = self
            .series
            .iter()
            .map(|s| Series {
                name: s.name.clone(),
                points: s.points.iter().map(|p| (p.x, p.y.unwrap_or(f64::NAN))).collect(),
                style: s.style,
                colour: s.colour,
                shape: s.shape,
            })
            .collect();
        tell_apart(&mut series);
        ChartSpec {
            title: self.title.clone(),
            x_label: self.x_label.clone(),
            y_label: self.y_label.clone(),
            x_log: self.x_log,
            y_log: self.y_log,
            series,
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
    out.push(("table-1".into(), table1::DESCRIPTION.into()));
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
}
