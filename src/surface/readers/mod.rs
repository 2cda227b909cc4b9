//! Height maps from files, the format chosen by the file's extension:
//!
//! | extension | format | lateral size | height unit |
//! |---|---|---|---|
//! | `.txt` `.asc` `.dat` | text matrix: one row (fixed y) per line, whitespace-separated; `#` lines are comments, where Gwyddion's text export's `# Width: 10.0 µm` and `# Value units: m` are read, and asperity's own `# asperity height map: … spacing Δa m` | `# Width:` line, else nx·Δa of asperity's header, else the caller's | `# Value units:`, else the caller's, else m |
//! | `.xyz` | columns `x y z` (or `x z` for a line scan), whitespace, comma or semicolon separated, on a regular grid in any order | n·Δx from the coordinates, in the heights' unit | the caller's, else m |
//! | `.npy` | NumPy array, 2-D (rows = y) or 1-D (a line scan); f64, f32, i64, i32, i16 | the caller's | the caller's, else m |
//! | `.gsf` | Gwyddion simple field: `Gwyddion Simple Field 1.0`, `Key = Value` lines (XRes, YRes, XReal, YReal, XYUnits, ZUnits), NUL padding to a multiple of 4 bytes, XRes·YRes little-endian f32 | XReal | ZUnits, else the caller's, else m |
//!
//! A lateral size given by the caller overrides the file's (it is the x side, n_x·Δa). Maps need
//! square pixels (Δx = Δy). A single row (or a single column, or `x z` columns) is a line scan:
//! a [`Surface`] with ny = 1. Instrument formats (x3p, sdf, opd, datx…): no maintained Rust
//! crate reads one, so none is read here; export to `.gsf` or `.xyz` (Gwyddion reads them all).
//!
//! Errors name the file, the line (text formats) or byte offset (binary ones) and what is wrong.

mod binary;

use crate::error::{fmt_value, Error, Field, Result};
use crate::surface::heightmap::{Surface, MAX_GRID};
use crate::surface::spectrum::LENGTH_RANGE_M;
pub(crate) use binary::GSF_MAGIC;
use binary::{parse_gsf, parse_npy};
use std::path::Path;

/// A length unit of heights or coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unit {
    /// metre
    M,
    /// millimetre
    Mm,
    /// micrometre
    Um,
    /// nanometre
    Nm,
    /// picometre
    Pm,
}

impl Unit {
    /// Metres per unit.
    pub fn metres(self) -> f64 {
        match self {
            Unit::M => 1.0,
            Unit::Mm => 1e-3,
            Unit::Um => 1e-6,
            Unit::Nm => 1e-9,
            Unit::Pm => 1e-12,
        }
    }
    /// Parses `m`, `mm`, `um` (`µm`, `μm`), `nm`, `pm`.
    pub fn parse(s: &str) -> Option<Unit> {
        match s.trim() {
            "m" => Some(Unit::M),
            "mm" => Some(Unit::Mm),
            "um" | "µm" | "μm" => Some(Unit::Um),
            "nm" => Some(Unit::Nm),
            "pm" => Some(Unit::Pm),
            _ => None,
        }
    }
}

/// What the caller knows about a file.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ReadOptions {
    /// Lateral size (m) of the x side; overrides the file's.
    pub size: Option<f64>,
    /// Unit of the heights where the file does not state one.
    pub height_unit: Option<Unit>,
}

/// The formats, by extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// `.txt`, `.asc`, `.dat`.
    Text,
    /// `.xyz`.
    Xyz,
    /// `.npy`.
    Npy,
    /// `.gsf`.
    Gsf,
}

/// The format of a file name, or an error naming the allowed extensions.
///
/// # Errors
/// [`Error::Invalid`] for an unknown extension.
pub fn format_of(path: &Path) -> Result<Format> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    match ext.as_str() {
        "txt" | "asc" | "dat" => Ok(Format::Text),
        "xyz" => Ok(Format::Xyz),
        "npy" => Ok(Format::Npy),
        "gsf" => Ok(Format::Gsf),
        _ => Err(Error::invalid_text(
            Field::HeightMap,
            path.display().to_string(),
            "a file ending in .txt, .asc, .dat, .xyz, .npy or .gsf",
        )),
    }
}

pub(super) fn bad(source: &str, at: String, what: impl std::fmt::Display, allowed: &str) -> Error {
    Error::invalid_text(Field::HeightMap, format!("{source}:{at}: {what}"), allowed.to_string())
}

/// Reads a height map (module docs).
///
/// # Errors
/// [`Error::Io`] when the file cannot be read, [`Error::Invalid`] naming the file, the place
/// and the fault otherwise.
pub fn read(path: &Path, opts: &ReadOptions) -> Result<Surface> {
    let format = format_of(path)?;
    let bytes =
        crate::input::file::read_bounded(path, "surface", Field::HeightMap, crate::input::file::MAX_INPUT_BYTES)?;
    // errors name the file by its name (the folder is the caller's, and a long one would
    // crowd out what is wrong)
    let name = path
        .file_name()
        .map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
    parse(&bytes, format, &name, opts)
}

/// Parses a height map held in memory; `source` names it in errors.
///
/// # Errors
/// As [`read`].
pub fn parse(bytes: &[u8], format: Format, source: &str, opts: &ReadOptions) -> Result<Surface> {
    let text = |b: &[u8]| -> Result<String> {
        String::from_utf8(b.to_vec()).map_err(|e| {
            bad(
                source,
                format!("byte {}", e.utf8_error().valid_up_to()),
                "not UTF-8 text",
                "a text file",
            )
        })
    };
    let raw = match format {
        Format::Text => parse_text(&text(bytes)?, source)?,
        Format::Xyz => parse_xyz(&text(bytes)?, source)?,
        Format::Npy => parse_npy(bytes, source)?,
        Format::Gsf => parse_gsf(bytes, source)?,
    };
    raw.into_surface(source, opts)
}

/// A grid as read, before units and size are applied.
pub(super) struct Raw {
    pub(super) nx: usize,
    pub(super) ny: usize,
    pub(super) values: Vec<f64>,
    /// Lateral x side in the file's length unit (`size_unit`) or metres.
    pub(super) size_x: Option<f64>,
    pub(super) size_y: Option<f64>,
    /// Unit of the lateral size; None: the heights' unit.
    pub(super) size_unit: Option<Unit>,
    /// Unit of the heights stated in the file.
    pub(super) height_unit: Option<Unit>,
}

impl Raw {
    fn into_surface(self, source: &str, opts: &ReadOptions) -> Result<Surface> {
        let (nx, ny) = (self.nx, self.ny);
        if nx > MAX_GRID || ny > MAX_GRID || nx < 2 {
            return Err(bad(
                source,
                "shape".into(),
                format!("{nx} x {ny} points"),
                &format!("2 <= points per row <= {MAX_GRID}, rows <= {MAX_GRID}"),
            ));
        }
        let zu = self.height_unit.or(opts.height_unit).unwrap_or(Unit::M);
        let lu = self.size_unit.unwrap_or(zu);
        let size = match (opts.size, self.size_x) {
            (Some(l), _) => l,
            (None, Some(l)) => l * lu.metres(),
            (None, None) => {
                return Err(Error::invalid_text(
                    Field::SystemSize,
                    format!("none ({source} gives no lateral size)"),
                    "the map's x side L in metres",
                ))
            }
        };
        if opts.size.is_some() {
            crate::error::check_in(Field::SystemSize, size, LENGTH_RANGE_M.0, LENGTH_RANGE_M.1)?;
        } else if !(LENGTH_RANGE_M.0..=LENGTH_RANGE_M.1).contains(&size) {
            // the file's own size: blame the file, not a flag the caller never gave
            return Err(bad(
                source,
                "size".into(),
                format!("a lateral side of {} m", fmt_value(size)),
                &format!(
                    "a side {} m <= L <= {} m",
                    fmt_value(LENGTH_RANGE_M.0),
                    fmt_value(LENGTH_RANGE_M.1)
                ),
            ));
        }
        let spacing = size / nx as f64;
        if let (None, Some(sy), true) = (opts.size, self.size_y, ny > 1) {
            let dy = sy * lu.metres() / ny as f64;
            if ((dy / spacing) - 1.0).abs() > 1e-3 {
                return Err(bad(
                    source,
                    "size".into(),
                    format!("pixels of {} m x {} m", fmt_value(spacing), fmt_value(dy)),
                    "square pixels (equal spacing in x and y)",
                ));
            }
        }
        let f = zu.metres();
        Surface::new(nx, ny, spacing, self.values.into_iter().map(|v| v * f).collect())
    }
}

const TEXT_ALLOWED: &str = "a matrix of finite heights, one row per line, the same number in each";

/// A length with unit, e.g. `10.000 µm`.
fn length_with_unit(s: &str) -> Option<(f64, Option<Unit>)> {
    let mut it = s.split_whitespace();
    let v: f64 = it.next()?.parse().ok()?;
    Some((v, it.next().and_then(Unit::parse)))
}

/// Refuses a line with a decimal comma ([`crate::input::file::decimal_comma`]), saying so.
fn refuse_decimal_comma(line: &str, source: &str, i: usize) -> Result<()> {
    match crate::input::file::decimal_comma(line) {
        Some(tok) => Err(bad(
            source,
            format!("{}", i + 1),
            format!("'{tok}' (a decimal comma)"),
            "numbers with a decimal point (1.5e-08, not 1,5e-08), separated by blanks, commas or semicolons",
        )),
        None => Ok(()),
    }
}

fn parse_text(text: &str, source: &str) -> Result<Raw> {
    let mut rows: Vec<Vec<f64>> = Vec::new();
    let (mut width, mut height, mut zunit) = (None, None, None);
    let mut spacing: Option<(f64, Option<Unit>)> = None;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if let Some(c) = t.strip_prefix('#') {
            // Gwyddion's text export header
            let c = c.trim();
            if let Some(v) = c.strip_prefix("Width:") {
                width = length_with_unit(v);
            } else if let Some(v) = c.strip_prefix("asperity height map:") {
                // the header `Surface::to_text` writes: `N x M points, spacing Δa m, ...`
                spacing = v
                    .split(',')
                    .find_map(|part| part.trim().strip_prefix("spacing"))
                    .and_then(length_with_unit);
            } else if let Some(v) = c.strip_prefix("Height:") {
                height = length_with_unit(v);
            } else if let Some(v) = c.strip_prefix("Value units:") {
                zunit = Some(Unit::parse(v).ok_or_else(|| {
                    bad(
                        source,
                        format!("{}", i + 1),
                        format!("height unit '{}'", v.trim()),
                        "m, mm, um, nm or pm",
                    )
                })?);
            }
            continue;
        }
        if t.is_empty() {
            continue;
        }
        refuse_decimal_comma(t, source, i)?;
        let mut row = Vec::new();
        for tok in t
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|s| !s.is_empty())
        {
            let v: f64 = tok.parse().map_err(|_| {
                bad(
                    source,
                    format!("{}", i + 1),
                    format!("'{tok}' (not a number)"),
                    TEXT_ALLOWED,
                )
            })?;
            if !v.is_finite() {
                return Err(bad(
                    source,
                    format!("{}", i + 1),
                    format!("'{tok}' (not finite)"),
                    TEXT_ALLOWED,
                ));
            }
            row.push(v);
        }
        if let Some(r0) = rows.first() {
            if row.len() != r0.len() {
                return Err(bad(
                    source,
                    format!("{}", i + 1),
                    format!("a row of {} values (the first has {})", row.len(), r0.len()),
                    TEXT_ALLOWED,
                ));
            }
        }
        rows.push(row);
    }
    if rows.is_empty() {
        return Err(bad(source, "1".into(), "no data", TEXT_ALLOWED));
    }
    let (mut ny, mut nx) = (rows.len(), rows[0].len());
    if nx == 1 {
        // a single column: a line scan
        (nx, ny) = (ny, 1);
    }
    let values = rows.concat();
    // without a `# Width:` line, asperity's own header gives the side as nx spacings
    let width = width.or_else(|| spacing.map(|(da, u)| (da * nx as f64, u)));
    Ok(Raw {
        nx,
        ny,
        values,
        size_x: width.map(|w| w.0),
        size_y: height.map(|h| h.0),
        size_unit: width.map(|w| w.1.unwrap_or(Unit::M)),
        height_unit: zunit,
    })
}

fn parse_xyz(text: &str, source: &str) -> Result<Raw> {
    const ALLOWED: &str = "columns x y z (or x z) of finite numbers on a regular grid";
    let mut pts: Vec<Vec<f64>> = Vec::new();
    let mut lines = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        refuse_decimal_comma(t, source, i)?;
        let mut row = Vec::with_capacity(3);
        for tok in t
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|s| !s.is_empty())
        {
            let v: f64 = tok
                .parse()
                .map_err(|_| bad(source, format!("{}", i + 1), format!("'{tok}' (not a number)"), ALLOWED))?;
            if !v.is_finite() {
                return Err(bad(
                    source,
                    format!("{}", i + 1),
                    format!("'{tok}' (not finite)"),
                    ALLOWED,
                ));
            }
            row.push(v);
        }
        let want = pts.first().map_or(row.len(), |r| r.len());
        if !(row.len() == 2 || row.len() == 3) || row.len() != want {
            return Err(bad(
                source,
                format!("{}", i + 1),
                format!("{} columns", row.len()),
                ALLOWED,
            ));
        }
        pts.push(row);
        lines.push(i + 1);
    }
    if pts.len() < 2 {
        return Err(bad(source, "1".into(), format!("{} points", pts.len()), ALLOWED));
    }
    let line_scan = pts[0].len() == 2;
    // the regular axis of one coordinate: sorted distinct values, equally spaced
    let axis = |k: usize| -> Result<(f64, f64, usize)> {
        let mut v: Vec<f64> = pts.iter().map(|p| p[k]).collect();
        v.sort_by(f64::total_cmp);
        let span = v[v.len() - 1] - v[0];
        v.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * span.abs().max(f64::MIN_POSITIVE));
        let n = v.len();
        if n < 2 {
            return Ok((v[0], 1.0, 1));
        }
        let d = span / (n - 1) as f64;
        if let Some(w) = v.windows(2).find(|w| ((w[1] - w[0]) / d - 1.0).abs() > 1e-3) {
            return Err(bad(
                source,
                "grid".into(),
                format!("uneven spacing at {} = {}", ["x", "y"][k], fmt_value(w[1])),
                ALLOWED,
            ));
        }
        Ok((v[0], d, n))
    };
    let (x0, dx, nx) = axis(0)?;
    let (y0, dy, ny) = if line_scan { (0.0, dx, 1) } else { axis(1)? };
    if nx * ny != pts.len() {
        return Err(bad(
            source,
            "grid".into(),
            format!("{} points for a {nx} x {ny} grid", pts.len()),
            ALLOWED,
        ));
    }
    let mut values = vec![f64::NAN; nx * ny];
    for (p, line) in pts.iter().zip(&lines) {
        let i = ((p[0] - x0) / dx).round() as usize;
        let j = if line_scan {
            0
        } else {
            ((p[1] - y0) / dy).round() as usize
        };
        let k = j * nx + i;
        if !values[k].is_nan() {
            return Err(bad(source, format!("{line}"), "a repeated grid point", ALLOWED));
        }
        values[k] = p[p.len() - 1];
    }
    Ok(Raw {
        nx,
        ny,
        values,
        size_x: Some(dx * nx as f64),
        size_y: Some(dy * ny as f64),
        size_unit: None,
        height_unit: None,
    })
}
