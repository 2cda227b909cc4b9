//! `asperity figure ID`: a figure or table of \[S\] as data, a text chart and SVG/PNG files
//! (the library's [`asperity::report::figure`], drawn by [`crate::figure`]).
//!
//! ```text
//! asperity figure --list
//! asperity figure 1|2|...|8|8-log|table-1|FILE.toml [--format chart|table|csv|json]
//!                 [--svg FILE] [--png FILE] [--gfmd [--grid N] [--seed S]] [--points N]
//!                 [--model 1,2,3,4,yp08,xu24]
//!                 [--surface FILE [--size L] [--height-unit U] [--periodic] | --psd FILE.csv]
//!                 [--qmin Q] [--qmax Q]
//! ```
//!
//! With `--surface` or `--psd` every curve of the figure is computed on the measured spectrum
//! instead of the preset's (its material, adhesion, pressures and thicknesses kept), and
//! `--gfmd` runs on the measured map.

use super::emit;
use crate::chart;
use crate::figure::{self as draw};
use asperity::error::{Error, Result};
use asperity::report::figure::compute::{self, GfmdChoice, Measured};
use asperity::report::figure::{self, spec, table1, RunProgress};
use clap::{Args, ValueEnum};
use std::path::PathBuf;

/// Output format of `figure`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FigureFormat {
    /// A text chart and the notes (plain text; works in pipes).
    Chart,
    /// The numbers, one block per series.
    Table,
    /// `series,x,y,note` (table-1: one row per column).
    Csv,
    /// One JSON object.
    Json,
}

/// Arguments of `figure`.
#[derive(Debug, Clone, Args)]
pub struct FigureArgs {
    /// The figure: one of `spec::ids()` or a figure TOML file (the help lists them).
    #[arg(help = spec::allowed())]
    pub id: Option<String>,
    /// Name every figure with one line.
    #[arg(long)]
    pub list: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = FigureFormat::Chart)]
    pub format: FigureFormat,
    /// Write the chart as SVG.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Write the chart as PNG.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Add the brute-force GFMD points where the figure has them.
    #[arg(long)]
    pub gfmd: bool,
    /// GFMD grid side N (default: the preset's reduced grid, 512 for both systems).
    #[arg(long, requires = "gfmd")]
    pub grid: Option<i64>,
    /// GFMD seed.
    #[arg(long, default_value_t = 1, requires = "gfmd")]
    pub seed: u64,
    /// Number of x values (or σ* samples) instead of the figure file's.
    #[arg(long)]
    pub points: Option<usize>,
    /// Width of the text chart in characters.
    #[arg(long, default_value_t = 100)]
    pub width: usize,
    /// Height of the text chart in lines.
    #[arg(long, default_value_t = 32)]
    pub height: usize,
    /// Add curves of these models: a comma-separated list of 1, 2, 3, 4, 5, yp08, xu24
    /// (e.g. figure 1 --model yp08,xu24; the variants need an adhesionless half-space figure).
    #[arg(long, value_delimiter = ',')]
    pub model: Vec<String>,
    /// A measured surface or PSD table instead of the preset's spectrum.
    #[command(flatten)]
    pub source: super::surface::SurfaceArgs,
}

/// The measured surface of `--surface`/`--psd` (None: the figure's preset spectrum).
fn measured(args: &FigureArgs) -> Result<Option<Measured>> {
    let (Some(spectrum), map) = args.source.spectrum_and_map()? else {
        return Ok(None);
    };
    if args.gfmd {
        if let Some(p) = &args.source.psd {
            return Err(Error::field(
                "--psd",
                p.display(),
                "none with --gfmd: GFMD needs a height map (--surface FILE)",
            ));
        }
        if let Some(n) = args.grid {
            return Err(Error::field(
                "--grid",
                n,
                "none with --surface: GFMD runs on the map's own grid",
            ));
        }
        if let Some(m) = map.as_ref().filter(|m| !m.is_square()) {
            return Err(Error::field(
                "--surface",
                format!("a {} x {} map", m.nx, m.ny),
                "an N x N map with --gfmd (GFMD runs on a square map)",
            ));
        }
    }
    Ok(Some(Measured { spectrum, map }))
}

/// Runs `work` with the figure's GFMD runs reported on stderr ([`super::progress`]): one step
/// per run, labelled with its p*, the solver's step and residual as it goes.
fn with_progress<T>(work: impl FnOnce(&mut dyn FnMut(RunProgress)) -> T) -> T {
    let opts = compute::gfmd_options();
    let mut steps: Option<super::progress::Steps> = None;
    work(&mut |r: RunProgress| {
        let steps = steps.get_or_insert_with(|| super::progress::Steps::new("figure", "GFMD run", r.runs));
        let label = super::progress::load_label(r.pressure);
        super::gfmd::report(steps, r.run, &r.solver, &opts, |_| Some(label.clone()));
    })
}

/// Runs `asperity figure`.
pub fn run(args: &FigureArgs) -> Result<()> {
    if args.list {
        for (id, d) in figure::list() {
            emit(&format!("{id:<8} {d}"));
        }
        return Ok(());
    }
    let Some(id) = args.id.as_deref() else {
        return Err(Error::field(
            "figure",
            "(none)",
            format!("{} (--list names them)", spec::allowed()),
        ));
    };
    let gfmd = if args.gfmd {
        // --grid's range is the table's, checked as the line is parsed
        let grid = args.grid.map(|n| n as usize);
        Some(GfmdChoice { grid, seed: args.seed })
    } else {
        None
    };
    let on = measured(args)?;
    let data = if id == spec::TABLE_1 {
        if let Some(m) = &on {
            return Err(Error::field(
                if args.source.psd.is_some() {
                    "--psd"
                } else {
                    "--surface"
                },
                m.name(),
                "none for table-1 (its rows are the paper's systems)",
            ));
        }
        if args.points.is_some() {
            return Err(Error::field("--points", args.points.unwrap_or(0), "none for table-1"));
        }
        let t = with_progress(|p| table1::compute(gfmd, p))?;
        match args.format {
            FigureFormat::Table => emit(&draw::table1(&t)),
            FigureFormat::Csv => emit(&t.csv()),
            FigureFormat::Json => emit(&serde_json::to_string_pretty(&t).expect("serialisable")),
            FigureFormat::Chart => {}
        }
        let fig = t.figure();
        if args.format == FigureFormat::Chart {
            emit(&draw::table1(&t));
            emit("");
            emit(chart::render_text(&draw::chart(&fig), args.width, args.height).trim_end());
        }
        fig
    } else {
        let allowed = "a figure (`figure --list`) or a figure TOML file";
        let mut s = spec::resolve(id).map_err(|e| super::parse::toml_under(e, "figure", allowed))?;
        if !spec::BUILTIN.iter().any(|(i, _)| *i == id) {
            eprintln!("asperity figure: read {id}");
        }
        if let Some(n) = args.points {
            s.points = n;
        }
        for m in &args.model {
            let kind: asperity::input::model::ModelKind = m.parse()?;
            if kind == asperity::input::model::ModelKind::Custom {
                return Err(Error::field(
                    "--model",
                    m,
                    asperity::input::model::ModelKind::named_list(),
                ));
            }
            s.curve.push(spec::CurveSpec::of_model(kind)?);
        }
        let data = with_progress(|p| compute::compute_on(&s, gfmd, on.as_ref(), p))?;
        match args.format {
            FigureFormat::Chart => {
                emit(chart::render_text(&draw::chart(&data), args.width, args.height).trim_end());
                for n in &data.notes {
                    emit(&format!("note: {n}"));
                }
            }
            FigureFormat::Table => emit(&draw::table(&data)),
            FigureFormat::Csv => emit(&data.csv()),
            FigureFormat::Json => emit(&serde_json::to_string_pretty(&data).expect("serialisable")),
        }
        data
    };
    let spec = draw::chart(&data);
    for (path, png) in [(&args.svg, false), (&args.png, true)] {
        if let Some(p) = path {
            let write = if png { chart::write_png } else { chart::write_svg };
            super::outfile::write(if png { "--png" } else { "--svg" }, p, |t| write(&spec, t))?;
            eprintln!("asperity figure: wrote {}", p.display());
        }
    }
    Ok(())
}
