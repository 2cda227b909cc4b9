//! Table 1 of \[S\]: the first and second moment of the contact stress, system I without
//! adhesion at p* = 0.01, semi-infinite: GFMD (65536² in \[S\]) and models 1–3.

use super::compute::{curve_scene, gfmd_run, GfmdChoice};
use super::spec::Overrides;
use super::{DataPoint, DataSeries, FigureData, RunProgress, SeriesKind, Style};
use crate::error::Result;
use crate::input::preset::Preset;
use crate::theory::engine::{self, Options};
use serde::Serialize;

/// One line for the list of figures.
pub const DESCRIPTION: &str =
    "Table 1: σ̄_c* and ⟨δσ_c²⟩* at p* = 0.01, models 1-3 against [S]'s values (system I, no adhesion)";

/// \[S\] Table 1: (column, σ̄_c*, ⟨δσ_c²⟩*); docs/reference-values.md.
pub const PAPER: [(&str, f64, f64); 4] = [
    ("GFMD", 0.4963, 0.0908),
    ("model 1", 0.6264, 0.1071),
    ("model 2", 0.4215, 0.0484),
    ("model 3", 0.4670, 0.0595),
];

/// The load of Table 1.
pub const PRESSURE: f64 = 0.01;

/// One column of the table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Column {
    /// "model 1" … or "GFMD (N²)".
    pub column: String,
    /// Computed σ̄_c* (null: not computed).
    pub mean_contact_stress: Option<f64>,
    /// Computed ⟨δσ_c²⟩*.
    pub contact_stress_variance: Option<f64>,
    /// Computed a_r.
    pub a_r: Option<f64>,
    /// \[S\]'s σ̄_c*.
    pub paper_mean_contact_stress: f64,
    /// \[S\]'s ⟨δσ_c²⟩*.
    pub paper_contact_stress_variance: f64,
}

/// Table 1 (the JSON of `asperity figure table-1 --format json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table1 {
    /// p*.
    pub pressure: f64,
    /// GFMD, model 1, model 2, model 3.
    pub columns: Vec<Column>,
    /// Grid and anything that failed.
    pub notes: Vec<String>,
}

/// Computes Table 1 (GFMD on the chosen grid with `gfmd`, its run reporting to `progress`).
pub fn compute(gfmd: Option<GfmdChoice>, progress: &mut dyn FnMut(RunProgress)) -> Result<Table1> {
    let preset = Preset::resolve("system-1")?;
    let fig = Overrides {
        pressure: Some(PRESSURE),
        gamma: Some(0.0),
        thickness_qr: Some(f64::INFINITY),
        model: None,
    };
    let mut columns = Vec::new();
    let mut notes = Vec::new();
    let (name, m, v) = PAPER[0];
    let mut g = Column {
        column: "GFMD".into(),
        mean_contact_stress: None,
        contact_stress_variance: None,
        a_r: None,
        paper_mean_contact_stress: m,
        paper_contact_stress_variance: v,
    };
    if let Some(choice) = gfmd {
        let scene = curve_scene(&preset, &fig, &Overrides::default())?;
        match gfmd_run(&preset, &scene, (choice, None), (0, 1), progress) {
            Ok(r) => {
                g.column = format!("{name} ({}²)", r.grid);
                g.mean_contact_stress = Some(r.stats.mean_contact_stress);
                g.contact_stress_variance = Some(r.stats.contact_stress_variance);
                g.a_r = Some(r.stats.a_r);
                notes.push(format!(
                    "GFMD: {}² grid (the preset's reduced grid unless another grid was asked for; [S]: 65536²), seed {}",
                    r.grid, choice.seed
                ));
            }
            Err(e) => notes.push(format!("GFMD: {e}")),
        }
    }
    columns.push(g);
    for (k, &(name, m, v)) in PAPER.iter().enumerate().skip(1) {
        let scene = curve_scene(
            &preset,
            &fig,
            &Overrides {
                model: Some(k as u8),
                ..Overrides::default()
            },
        )?;
        let e = engine::evaluate(&scene, &Options::default())?;
        columns.push(Column {
            column: name.into(),
            mean_contact_stress: Some(e.stats.mean_contact_stress),
            contact_stress_variance: Some(e.stats.contact_stress_variance),
            a_r: Some(e.stats.a_r),
            paper_mean_contact_stress: m,
            paper_contact_stress_variance: v,
        });
    }
    Ok(Table1 {
        pressure: PRESSURE,
        columns,
        notes,
    })
}

impl Table1 {
    /// CSV: one row per column.
    pub fn csv(&self) -> String {
        use crate::report::csv::{cell, opt_cell, table};
        let rows = self.columns.iter().map(|c| {
            let computed = [c.mean_contact_stress, c.contact_stress_variance, c.a_r].map(opt_cell);
            let paper = [c.paper_mean_contact_stress, c.paper_contact_stress_variance].map(cell);
            [vec![c.column.clone()], computed.to_vec(), paper.to_vec()].concat()
        });
        table(
            "column,mean_contact_stress,contact_stress_variance,a_r,paper_mean_contact_stress,paper_contact_stress_variance",
            rows,
        )
    }

    /// As a figure: the moments against the column (0 = GFMD, 1–3 = models), computed as
    /// lines-less points beside \[S\]'s.
    pub fn figure(&self) -> FigureData {
        let pts = |get: &dyn Fn(&Column) -> Option<f64>| -> Vec<DataPoint> {
            self.columns
                .iter()
                .enumerate()
                .map(|(i, c)| DataPoint {
                    x: i as f64,
                    y: get(c),
                    note: None,
                })
                .collect()
        };
        let series = vec![
            ("σ̄_c* (asperity)", pts(&|c| c.mean_contact_stress)),
            ("σ̄_c* [S] Table 1", pts(&|c| Some(c.paper_mean_contact_stress))),
            ("⟨δσ_c²⟩* (asperity)", pts(&|c| c.contact_stress_variance)),
            ("⟨δσ_c²⟩* [S] Table 1", pts(&|c| Some(c.paper_contact_stress_variance))),
        ]
        .into_iter()
        .map(|(n, p)| DataSeries {
            kind: SeriesKind::Moments {
                paper: n.contains("[S]"),
            },
            name: n.into(),
            style: Style::Points,
            points: p,
        })
        .collect();
        FigureData {
            id: "table-1".into(),
            title: "[S] Table 1: moments of the contact stress, system I, p* = 0.01 (x: 0 = GFMD, 1-3 = model)".into(),
            preset: "system-1".into(),
            spectrum_source: None,
            x_label: "column (0 = GFMD, 1, 2, 3 = model)".into(),
            y_label: "σ̄_c* and ⟨δσ_c²⟩* (reduced by E*ḡ, (E*ḡ)²)".into(),
            x_log: false,
            y_log: false,
            y_decades: None,
            series,
            notes: self.notes.clone(),
        }
    }
}
