//! The figures and Table 1 of \[S\] as typed data: `asperity figure`'s report, computed on the
//! paper's systems with the paper's models (or on a measured spectrum).
//!
//! Figures 1–8 are described by TOML files ([`spec`], `figures/` in the repository, built
//! into the library); Table 1 is [`table1`]. [`compute`] evaluates the curves (each point as
//! `run` evaluates it, `curves.rs`, refined where a curve bends, [`refine`]), the closed forms,
//! the values \[S\] states and the GFMD points; [`FigureData`] holds the result.
//!
//! The data say what each series is ([`SeriesKind`]: which model's curve, which closed form,
//! which value of \[S\], GFMD) and how it is drawn in words ([`Style`]); colours, markers and
//! charts are the front ends'. Serialised field names are those of `asperity figure ID
//! --format json` (a public interface).

pub mod compute;
mod curves;
pub mod refine;
pub mod spec;
pub mod table1;

use crate::gfmd;
use crate::input::model::ModelKind;
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

/// How a series is drawn, as the JSON names it (`style`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Style {
    /// A solid line through the points (a theory curve, a loading branch).
    Line,
    /// Markers only (GFMD points, values \[S\] states).
    Points,
    /// A dashed line (a closed form, an unloading branch).
    Dashed,
}

/// What a series shows; a front end picks its colour and marker from it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesKind {
    /// A theory curve of `model`. `repeat` numbers the later curves of a model already drawn
    /// (Fig. 8: one model at several thicknesses), from 0 across the figure; None for the
    /// first curve of its model.
    Theory {
        /// The model.
        model: ModelKind,
        /// Which further curve of an already drawn model this is.
        repeat: Option<usize>,
    },
    /// A closed form; `second` for the large-stress asymptote of Pr, told apart from the
    /// small-stress one.
    ClosedForm {
        /// The second closed form of a figure.
        second: bool,
    },
    /// Values \[S\] states: the `nth` source of the figure, of `model` where the file says so.
    Paper {
        /// The model the values are of.
        model: Option<ModelKind>,
        /// The source's index among the figure's sources.
        nth: usize,
    },
    /// GFMD's points.
    Gfmd,
    /// The theory on the GFMD map's own spectrum.
    GfmdTheory,
    /// Table 1 as a figure: asperity's moments (`paper` false, model 3 is the one gauged) or
    /// \[S\]'s.
    Moments {
        /// \[S\]'s values.
        paper: bool,
    },
}

/// One series of a figure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DataSeries {
    /// Legend label.
    pub name: String,
    /// How it is drawn.
    pub style: Style,
    /// The points.
    pub points: Vec<DataPoint>,
    /// What it shows.
    #[serde(skip)]
    pub kind: SeriesKind,
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
    /// On a log y axis, the decades a chart draws below the largest value (the data keep
    /// every value).
    #[serde(skip)]
    pub y_decades: Option<f64>,
    /// Theory curves, closed forms, \[S\] values, GFMD points.
    pub series: Vec<DataSeries>,
    /// Scalars, grids and anything that did not converge.
    pub notes: Vec<String>,
}

impl FigureData {
    /// CSV: `series,x,y,note`, one row per point; no value is an empty cell.
    pub fn csv(&self) -> String {
        use super::csv::{cell, opt_cell, table};
        let rows = self.series.iter().flat_map(|s| {
            s.points.iter().map(|p| {
                let note = p.note.clone().unwrap_or_default();
                vec![s.name.clone(), cell(p.x), opt_cell(p.y), note]
            })
        });
        table("series,x,y,note", rows)
    }
}

/// A report of a figure's GFMD runs: run `run` (from 0) of `runs`, at p* `pressure`, with the
/// solver's own report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunProgress {
    /// Which run.
    pub run: usize,
    /// How many runs the figure plans.
    pub runs: usize,
    /// The run's p*.
    pub pressure: f64,
    /// The solver's report.
    pub solver: gfmd::Progress,
}

/// The figures a front end lists: (id, one line).
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
        let point = |x: f64, y: Option<f64>, note: Option<&str>| DataPoint {
            x,
            y,
            note: note.map(str::to_string),
        };
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
                style: Style::Line,
                kind: SeriesKind::Theory {
                    model: ModelKind::Four,
                    repeat: None,
                },
                points: vec![
                    point(
                        0.01,
                        None,
                        Some("adhesive solver did not converge: stalled, residual 1e-2"),
                    ),
                    point(0.1, Some(0.5), None),
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
        assert_eq!(json["series"][0]["style"], "line");
        assert!(json["series"][0].get("kind").is_none());
        assert!(!serde_json::to_string(&data).unwrap().contains("NaN"));
    }
}
