//! Height maps written to files, in the formats [`super::readers`] reads back (the format
//! chosen by the extension): heights and lengths in metres; the text formats keep every digit,
//! `.gsf` stores f32. A text map states its side (`# Width:`) and its spacing (asperity's own
//! header), so it is read back without being told its size.

use super::heightmap::Surface;
use super::readers::{format_of, Format, GSF_MAGIC};
use crate::error::{Error, Result};
use std::path::Path;

/// Writes a map in the format of `path`'s extension (heights and lengths in metres; `.gsf`
/// stores f32, the others every digit).
///
/// # Errors
/// [`Error::Invalid`] for an unknown extension, [`Error::Io`] when writing fails.
pub fn write(s: &Surface, path: &Path) -> Result<()> {
    let bytes = encode(s, format_of(path)?)?;
    std::fs::write(path, bytes).map_err(|e| Error::io_file("write", "surface", path, &e))
}

/// The bytes of a map in `format` (see [`write()`]).
///
/// # Errors
/// [`Error::Io`] if the NumPy encoder fails.
pub fn encode(s: &Surface, format: Format) -> Result<Vec<u8>> {
    Ok(match format {
        Format::Text => {
            let mut t = format!("# Width: {:e} m\n# Value units: m\n", s.size_x());
            t.push_str(&s.to_text());
            t.into_bytes()
        }
        Format::Xyz => {
            let mut t = String::new();
            for (k, h) in s.heights.iter().enumerate() {
                let (x, y) = ((k % s.nx) as f64 * s.spacing, (k / s.nx) as f64 * s.spacing);
                if s.ny == 1 {
                    t.push_str(&format!("{x:e} {h:e}\n"));
                } else {
                    t.push_str(&format!("{x:e} {y:e} {h:e}\n"));
                }
            }
            t.into_bytes()
        }
        Format::Npy => {
            use npyz::WriterBuilder;
            let mut buf = Vec::new();
            let shape: Vec<u64> = if s.ny == 1 {
                vec![s.nx as u64]
            } else {
                vec![s.ny as u64, s.nx as u64]
            };
            let io = |e: std::io::Error| Error::io("encode a NumPy array", e);
            let mut w = npyz::WriteOptions::new()
                .default_dtype()
                .shape(&shape)
                .writer(&mut buf)
                .begin_nd()
                .map_err(io)?;
            w.extend(s.heights.iter().copied()).map_err(io)?;
            w.finish().map_err(io)?;
            buf
        }
        Format::Gsf => {
            let mut b = format!(
                "{GSF_MAGIC}\nXRes = {}\nYRes = {}\nXReal = {:e}\nYReal = {:e}\nXYUnits = m\nZUnits = m\n",
                s.nx,
                s.ny,
                s.size_x(),
                s.size_y()
            )
            .into_bytes();
            let pad = 4 - b.len() % 4;
            b.extend(std::iter::repeat_n(0u8, pad));
            for h in &s.heights {
                b.extend((*h as f32).to_le_bytes());
            }
            b
        }
    })
}
