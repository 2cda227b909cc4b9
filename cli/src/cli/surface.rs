//! The measured-surface flags shared by the theory commands and `gfmd`: `--surface FILE`
//! (a height map, format by extension, see [`asperity::surface::readers`]), `--psd FILE.csv`
//! (a PSD table, columns `q` and `psd`), `--size`, `--height-unit`, `--periodic`, `--qmin`,
//! `--qmax`; and `asperity psd`.

use super::emit;
use asperity::error::{Error, Field, Result};
use asperity::input::preset::MeasuredSpec;
use asperity::report::psd::{psd as psd_report, PsdReport};
use asperity::surface::heightmap::Surface;
use asperity::surface::psd::PsdOptions;
use asperity::surface::readers::{self, ReadOptions, Unit};
use asperity::surface::spectrum::{Spectrum, Tabulated};
use clap::{Args, ValueEnum};
use std::path::PathBuf;

/// `--height-unit`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum HeightUnitArg {
    /// nanometres
    Nm,
    /// micrometres
    Um,
    /// millimetres
    Mm,
    /// metres
    M,
}

impl HeightUnitArg {
    fn unit(self) -> Unit {
        match self {
            HeightUnitArg::Nm => Unit::Nm,
            HeightUnitArg::Um => Unit::Um,
            HeightUnitArg::Mm => Unit::Mm,
            HeightUnitArg::M => Unit::M,
        }
    }
}

/// Where the spectrum comes from when it is not the preset's.
#[derive(Debug, Clone, Default, Args)]
pub struct SurfaceArgs {
    /// Measured height map (.txt .asc .dat matrix, .xyz columns, .npy, .gsf): the theory runs
    /// on its PSD, gfmd on the map itself.
    #[arg(long)]
    pub surface: Option<PathBuf>,
    /// PSD table (CSV with columns q in 1/m and psd in m^4, as `asperity psd --format csv`
    /// writes) to run the theory on instead of the preset's spectrum.
    #[arg(long, conflicts_with = "surface")]
    pub psd: Option<PathBuf>,
    /// Side L of the --surface map in metres (its x side; overrides the file's).
    #[arg(long, requires = "surface")]
    pub size: Option<f64>,
    /// Unit of the --surface heights where the file states none (default m).
    #[arg(long, value_enum, requires = "surface")]
    pub height_unit: Option<HeightUnitArg>,
    /// The --surface map is periodic (generated or GFMD maps): no plane fit, no window.
    #[arg(long, requires = "surface")]
    pub periodic: bool,
    /// Lower cut-off of the tabulated spectrum in 1/m (default: the table's first q).
    #[arg(long)]
    pub qmin: Option<f64>,
    /// Upper cut-off of the tabulated spectrum in 1/m (default: the table's last q).
    #[arg(long)]
    pub qmax: Option<f64>,
}

impl SurfaceArgs {
    /// The flags a preset's `[measured]` section stands for.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `measured.height_unit` for a unit other than nm, um, mm, m.
    pub fn from_measured(m: &MeasuredSpec) -> Result<SurfaceArgs> {
        let height_unit =
            match &m.height_unit {
                Some(u) => Some(HeightUnitArg::from_str(u, true).map_err(|_| {
                    Error::invalid_text(Field::Other("measured.height_unit".into()), u, "nm, um, mm or m")
                })?),
                None => None,
            };
        Ok(SurfaceArgs {
            surface: m.map.as_ref().map(PathBuf::from),
            psd: m.psd.as_ref().map(PathBuf::from),
            size: m.size_m,
            height_unit,
            periodic: m.periodic,
            qmin: m.q_min_per_m,
            qmax: m.q_max_per_m,
        })
    }

    /// The `[measured]` section standing for these flags (None without `--surface`/`--psd`),
    /// the files as absolute paths so that the preset opens from any directory; a map's side
    /// is written as read (`map`'s x side), so a `--size` or the file's own is kept.
    pub fn to_measured(&self, map: Option<&Surface>) -> Option<MeasuredSpec> {
        let abs = |p: &PathBuf| {
            std::fs::canonicalize(p)
                .unwrap_or_else(|_| p.clone())
                .display()
                .to_string()
        };
        if self.surface.is_none() && self.psd.is_none() {
            return None;
        }
        Some(MeasuredSpec {
            map: self.surface.as_ref().map(abs),
            psd: self.psd.as_ref().map(abs),
            size_m: self.size.or_else(|| map.map(|m| m.spacing * m.nx as f64)),
            height_unit: self
                .height_unit
                .and_then(|u| u.to_possible_value())
                .map(|v| v.get_name().to_string()),
            periodic: self.periodic,
            q_min_per_m: self.qmin,
            q_max_per_m: self.qmax,
        })
    }

    fn read_options(&self) -> Result<ReadOptions> {
        // a preset's [measured] size comes here unparsed: the table's range, as --size's
        if let Some(l) = self.size {
            asperity::limits::check(Field::SystemSize, l)?;
        }
        Ok(ReadOptions {
            size: self.size,
            height_unit: self.height_unit.map(HeightUnitArg::unit),
        })
    }

    /// The --surface map, if one is given.
    pub fn map(&self) -> Result<Option<Surface>> {
        match &self.surface {
            Some(p) => Ok(Some(readers::read(p, &self.read_options()?)?)),
            None => {
                if self.size.is_some() || self.height_unit.is_some() || self.periodic {
                    return Err(Error::field(
                        "--size/--height-unit/--periodic",
                        "given",
                        "only with --surface FILE",
                    ));
                }
                Ok(None)
            }
        }
    }

    /// The tabulated spectrum of --psd or of the --surface map's PSD (None: the preset's).
    pub fn spectrum(&self) -> Result<Option<Spectrum>> {
        Ok(self.spectrum_and_map()?.0)
    }

    /// The tabulated spectrum (as [`Self::spectrum`]) and the --surface map it came from, the
    /// file read once.
    pub fn spectrum_and_map(&self) -> Result<(Option<Spectrum>, Option<Surface>)> {
        // a preset's [measured] cut-offs come here unparsed: the table's range, as the flags'
        for (field, v) in [(Field::QMin, self.qmin), (Field::QMax, self.qmax)] {
            if let Some(x) = v {
                asperity::limits::check(field, x)?;
            }
        }
        let map = self.map()?;
        let q_range = (self.qmin, self.qmax);
        let spectrum = if let Some(p) = &self.psd {
            Tabulated::load_csv(p, self.qmin, self.qmax).map(Spectrum::Tabulated)
        } else if let Some(s) = &map {
            s.check_rough().map_err(|e| self.name_the_map(e))?;
            let name = self
                .surface
                .as_ref()
                .map(|p| p.display().to_string())
                .unwrap_or_default();
            Spectrum::from_map(s, &self.psd_options(), q_range, &name).map_err(|e| self.name_the_map(e))
        } else {
            if self.qmin.is_some() || self.qmax.is_some() {
                return Err(Error::field("--qmin/--qmax", "given", "only with --psd or --surface"));
            }
            return Ok((None, None));
        };
        if let Ok(Spectrum::Tabulated(t)) = &spectrum {
            if let Some(rows) = t.resampled_from {
                eprintln!(
                    "asperity: {}: {rows} rows resampled once onto {} log-spaced q ({} per decade)",
                    t.source,
                    t.q.len(),
                    asperity::surface::tabulated::RESAMPLE_PER_DECADE
                );
            }
        }
        // the table's fields under the flag the user gave: --psd, or --surface for a map's
        let flag = if self.psd.is_some() { "--psd" } else { "--surface" };
        let spectrum = spectrum.map_err(|e| rename_table_fields(e, flag))?;
        Ok((Some(spectrum), map))
    }

    /// A check of the map's values, with the map's file name in front of what it says.
    pub fn name_the_map(&self, e: Error) -> Error {
        let name = self
            .surface
            .as_ref()
            .and_then(|p| p.file_name())
            .map(|n| n.to_string_lossy().into_owned());
        match (e, name) {
            (
                Error::Invalid {
                    field: Field::HeightMap,
                    value,
                    allowed,
                },
                Some(n),
            ) if !value.contains(&n) => Error::Invalid {
                field: Field::HeightMap,
                value: asperity::error::fmt_text(&format!("{n}: {value}")),
                allowed,
            },
            (e, _) => e,
        }
    }

    /// The PSD options of --periodic.
    pub fn psd_options(&self) -> PsdOptions {
        PsdOptions {
            periodic: self.periodic,
            ..PsdOptions::default()
        }
    }
}

/// The table's cut-off fields in the command line's words; the table itself as `source`,
/// the flag it came from.
fn rename_table_fields(e: Error, source: &str) -> Error {
    match e {
        Error::Invalid { field, value, allowed } => {
            let flag = match field.key() {
                "q_min" => "--qmin",
                "q_max" => "--qmax",
                "psd" => source,
                _ => return Error::Invalid { field, value, allowed },
            };
            Error::Invalid {
                field: asperity::error::Field::Other(flag.into()),
                value,
                allowed,
            }
        }
        e => e,
    }
}

/// Output format of `psd`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PsdFormat {
    /// Summary and the table, aligned.
    Table,
    /// CSV: q (1/m), psd (m^4).
    Csv,
    /// One JSON object: the summary keys and `table`.
    Json,
}

/// Arguments of `psd`.
#[derive(Debug, Clone, Args)]
pub struct PsdArgs {
    /// Height map (.txt .asc .dat .xyz .npy .gsf).
    pub file: PathBuf,
    /// Side L of the map in metres (its x side; overrides the file's).
    #[arg(long)]
    pub size: Option<f64>,
    /// Unit of the heights where the file states none (default m).
    #[arg(long, value_enum)]
    pub height_unit: Option<HeightUnitArg>,
    /// The map is periodic: no plane fit, no window.
    #[arg(long)]
    pub periodic: bool,
    /// Radial bins per decade of q.
    #[arg(long, default_value_t = 10.0)]
    pub bins_per_decade: f64,
    /// Output format.
    #[arg(long, value_enum, default_value_t = PsdFormat::Table)]
    pub format: PsdFormat,
    /// Write the log-log chart of C(q) with the fit to this SVG file.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Write the chart to this PNG file.
    #[arg(long)]
    pub png: Option<PathBuf>,
}

/// Runs `asperity psd`.
pub fn run_psd(args: &PsdArgs) -> Result<()> {
    let sa = SurfaceArgs {
        surface: Some(args.file.clone()),
        size: args.size,
        height_unit: args.height_unit,
        periodic: args.periodic,
        ..SurfaceArgs::default()
    };
    let named = |e| name_the_file(e, &args.file);
    let s = sa.map().map_err(named)?.expect("a file is given");
    let opts = PsdOptions {
        bins_per_decade: args.bins_per_decade,
        ..sa.psd_options()
    };
    // a map too small or flat is refused in the report before the analysis and any output
    let out = psd_report(&args.file.display().to_string(), &s, &opts).map_err(named)?;
    match args.format {
        PsdFormat::Json => emit(&serde_json::to_string_pretty(&out).expect("serialisable")),
        PsdFormat::Csv => {
            let (q, c) = out.columns();
            emit(asperity::surface::tabulated::to_csv(&q, &c).trim_end());
        }
        PsdFormat::Table => emit(&table(&out)),
    }
    let spec = chart(&out);
    for (path, png) in [(&args.svg, false), (&args.png, true)] {
        if let Some(p) = path {
            let flag = if png { "--png" } else { "--svg" };
            super::outfile::write(flag, p, |tmp| {
                if png {
                    crate::chart::write_png(&spec, tmp)
                } else {
                    crate::chart::write_svg(&spec, tmp)
                }
            })?;
            eprintln!("asperity psd: wrote {}", p.display());
        }
    }
    Ok(())
}

/// `psd` names its map by the positional FILE, not by `--surface` (which it has not), with
/// the file's name in front of what is wrong with it, and its bins by `--bins-per-decade`.
fn name_the_file(e: Error, file: &std::path::Path) -> Error {
    match e {
        Error::Invalid {
            field: Field::Other(k),
            value,
            allowed,
        } if k == "bins_per_decade" => Error::Invalid {
            field: Field::Other("--bins-per-decade".into()),
            value,
            allowed,
        },
        Error::Invalid {
            field: Field::HeightMap,
            value,
            allowed,
        } => {
            let name = file
                .file_name()
                .map_or_else(|| file.display().to_string(), |n| n.to_string_lossy().into_owned());
            let value = if value.contains(&name) {
                value
            } else {
                asperity::error::fmt_text(&format!("{name}: {value}"))
            };
            Error::Invalid {
                field: Field::Other("FILE".into()),
                value,
                allowed,
            }
        }
        e => e,
    }
}

fn chart(o: &PsdReport) -> crate::chart::Chart {
    use crate::chart::{Chart, Scale, Series, SeriesStyle};
    use crate::looks::Role;
    // the explorer's psd chart's roles: the table as reference points, the fit as a closed form
    let mut c = Chart::new(
        format!("PSD of {}", o.file),
        "q (1/m)",
        "C(q) (m^4)",
        Scale::Log10,
        Scale::Log10,
    );
    c.series.push(Series::new(
        "C(q), radial average",
        o.table.iter().map(|b| (b.q, b.psd)).collect(),
        Role::Reference,
        SeriesStyle::Points,
    ));
    if let (Some(f), Some(first), true) = (&o.fit, o.table.first(), o.self_affine) {
        // the fitted law through the bins: plateau to q_r, power law to q_s
        let c_r = o
            .table
            .iter()
            .filter(|b| b.q <= f.q_s)
            .map(|b| b.psd.ln() + f.exponent * (b.q / f.q_r).ln().max(0.0))
            .sum::<f64>()
            / o.table.iter().filter(|b| b.q <= f.q_s).count().max(1) as f64;
        let law = |q: f64| (c_r - f.exponent * (q / f.q_r).ln().max(0.0)).exp();
        c.series.push(Series::new(
            format!("self-affine fit, H = {}", crate::numfmt::sig(f.hurst, 3)),
            vec![(first.q, law(first.q)), (f.q_r, law(f.q_r)), (f.q_s, law(f.q_s))],
            Role::Closed,
            SeriesStyle::Dashed,
        ));
    }
    c
}

fn table(o: &PsdReport) -> String {
    let mut t = String::new();
    let mut line = |k: &str, v: String| t.push_str(&format!("{k:<24}{v}\n"));
    line("file", o.file.clone());
    line(
        "points",
        format!(
            "{} x {}{}",
            o.points[0],
            o.points[1],
            if o.line_scan {
                " (line scan: 1-D PSD converted to 2-D)"
            } else {
                ""
            }
        ),
    );
    line("system_size_m", format!("{:.6e}", o.system_size_m));
    line("detrend / window", format!("{} / {}", o.detrend, o.window));
    line("rms_height_m", format!("{:.6e}", o.rms_height_m));
    line("rms_gradient", crate::report::fixed(o.rms_gradient, 6));
    line("rms_curvature", format!("{:.6e} 1/m", o.rms_curvature));
    match (
        o.hurst,
        o.hurst_error,
        o.rolloff_wavelength_range_m,
        o.short_wavelength_range_m,
    ) {
        (Some(h), Some(e), Some(r), Some(s)) => {
            line("hurst", format!("{h:.4} +- {e:.4}"));
            if !o.self_affine {
                line(
                    "self_affine",
                    "no: H outside (0, 1], the fit does not describe the map".into(),
                );
            }
            line(
                "rolloff_wavelength_m",
                format!(
                    "{:.4e} (in [{:.4e}, {:.4e}])",
                    o.rolloff_wavelength_m.unwrap_or(f64::NAN),
                    r[0],
                    r[1]
                ),
            );
            line(
                "short_wavelength_m",
                format!(
                    "{:.4e} (in [{:.4e}, {:.4e}])",
                    o.short_wavelength_m.unwrap_or(f64::NAN),
                    s[0],
                    s[1]
                ),
            );
        }
        _ => line("fit", "none (fewer than four bins)".into()),
    }
    t.push_str(&format!("\n{:>14} {:>14} {:>8}\n", "q (1/m)", "psd (m^4)", "modes"));
    for b in &o.table {
        t.push_str(&format!("{:>14.6e} {:>14.6e} {:>8}\n", b.q, b.psd, b.modes));
    }
    t.trim_end().to_string()
}
