//! The binary height-map formats of [`super`]: NumPy `.npy` (1-D or 2-D, f64, f32,
//! i64, i32, i16; rows = y) and Gwyddion's simple field `.gsf` (`Key = Value` header, NUL
//! padding to a multiple of 4 bytes, XRes·YRes little-endian f32). Errors name the byte offset.

use super::{bad, Raw, Unit};
use crate::error::Result;

/// Fails on the first height that is not finite, `at` naming its place in the file.
fn all_finite(values: &[f64], source: &str, allowed: &str, at: impl Fn(usize) -> String) -> Result<()> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(k) => Err(bad(source, at(k), "a height that is not finite", allowed)),
        None => Ok(()),
    }
}

pub(super) fn parse_npy(bytes: &[u8], source: &str) -> Result<Raw> {
    const ALLOWED: &str = "a 1-D or 2-D NumPy array of floats or integers";
    let file = npyz::NpyFile::new(bytes)
        .map_err(|e| bad(source, "byte 0".into(), format!("not a NumPy file ({e})"), ALLOWED))?;
    let shape = file.shape().to_vec();
    let fortran = file.order() == npyz::Order::Fortran;
    let (ny, nx) = match shape.as_slice() {
        [n] => (1usize, *n as usize),
        [r, c] => (*r as usize, *c as usize),
        s => {
            return Err(bad(
                source,
                "header".into(),
                format!("an array of shape {s:?}"),
                ALLOWED,
            ))
        }
    };
    let dtype = file.dtype();
    let values: Vec<f64> = match file.data::<f64>() {
        Ok(r) => r.collect::<std::io::Result<_>>(),
        Err(_) => {
            let file = npyz::NpyFile::new(bytes).map_err(|e| bad(source, "byte 0".into(), e, ALLOWED))?;
            let ts = match &dtype {
                npyz::DType::Plain(t) => t.to_string(),
                other => format!("{:?}", other.descr()),
            };
            macro_rules! widen {
                ($t:ty) => {
                    file.data::<$t>()
                        .map_err(|_| bad(source, "header".into(), format!("dtype {ts}"), ALLOWED))?
                        .map(|v| v.map(|x| x as f64))
                        .collect::<std::io::Result<_>>()
                };
            }
            match ts.get(1..).unwrap_or("") {
                "f4" => widen!(f32),
                "i8" => widen!(i64),
                "i4" => widen!(i32),
                "i2" => widen!(i16),
                _ => return Err(bad(source, "header".into(), format!("dtype {ts}"), ALLOWED)),
            }
        }
    }
    .map_err(|e| {
        bad(
            source,
            "data".into(),
            format!("truncated or unreadable data ({e})"),
            ALLOWED,
        )
    })?;
    if values.len() != nx * ny {
        return Err(bad(
            source,
            "data".into(),
            format!("{} values for shape {shape:?}", values.len()),
            ALLOWED,
        ));
    }
    let values = if fortran && ny > 1 {
        (0..nx * ny).map(|k| values[(k % nx) * ny + k / nx]).collect()
    } else {
        values
    };
    all_finite(&values, source, ALLOWED, |k| format!("element {k}"))?;
    Ok(Raw {
        nx,
        ny,
        values,
        size_x: None,
        size_y: None,
        size_unit: None,
        height_unit: None,
    })
}

/// The first line of a Gwyddion simple field.
pub(crate) const GSF_MAGIC: &str = "Gwyddion Simple Field 1.0";

pub(super) fn parse_gsf(bytes: &[u8], source: &str) -> Result<Raw> {
    const ALLOWED: &str = "a Gwyddion simple field (header, NUL padding, little-endian f32 data)";
    if !bytes.starts_with(GSF_MAGIC.as_bytes()) {
        return Err(bad(source, "byte 0".into(), format!("no '{GSF_MAGIC}' line"), ALLOWED));
    }
    let nul = bytes.iter().position(|&b| b == 0).ok_or_else(|| {
        bad(
            source,
            format!("byte {}", bytes.len()),
            "no NUL padding after the header",
            ALLOWED,
        )
    })?;
    let header = std::str::from_utf8(&bytes[..nul]).map_err(|e| {
        bad(
            source,
            format!("byte {}", e.valid_up_to()),
            "a header that is not UTF-8",
            ALLOWED,
        )
    })?;
    let data_at = nul.div_ceil(4) * 4 + if nul.is_multiple_of(4) { 4 } else { 0 };
    let mut keys = std::collections::HashMap::new();
    for (i, line) in header.lines().enumerate().skip(1) {
        let t = line.trim();
        if t.is_empty() {
            continue;
        }
        let (k, v) = t.split_once('=').ok_or_else(|| {
            bad(
                source,
                format!("{}", i + 1),
                format!("'{t}' (not Key = Value)"),
                ALLOWED,
            )
        })?;
        keys.insert(k.trim().to_string(), (v.trim().to_string(), i + 1));
    }
    let num = |k: &str| -> Result<Option<f64>> {
        keys.get(k)
            .map(|(v, line)| {
                v.parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite() && *x > 0.0)
                    .ok_or_else(|| bad(source, format!("{line}"), format!("{k} = {v}"), "a number > 0"))
            })
            .transpose()
    };
    let res = |k: &str| -> Result<usize> {
        match num(k)? {
            Some(v) if v.fract() == 0.0 => Ok(v as usize),
            _ => Err(bad(
                source,
                "header".into(),
                format!("{k} missing or not a whole number"),
                ALLOWED,
            )),
        }
    };
    let (nx, ny) = (res("XRes")?, res("YRes")?);
    let unit = |k: &str| -> Result<Option<Unit>> {
        keys.get(k)
            .map(|(v, line)| {
                Unit::parse(v)
                    .ok_or_else(|| bad(source, format!("{line}"), format!("{k} = {v}"), "m, mm, um, nm or pm"))
            })
            .transpose()
    };
    let need = nx.checked_mul(ny).and_then(|n| n.checked_mul(4)).unwrap_or(usize::MAX);
    let have = bytes.len().saturating_sub(data_at);
    if have < need {
        return Err(bad(
            source,
            format!("byte {}", bytes.len()),
            format!("{have} data bytes, {need} needed for {nx} x {ny} f32"),
            ALLOWED,
        ));
    }
    let values: Vec<f64> = bytes[data_at..data_at + need]
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64)
        .collect();
    all_finite(&values, source, ALLOWED, |k| format!("byte {}", data_at + 4 * k))?;
    Ok(Raw {
        nx,
        ny,
        values,
        size_x: num("XReal")?,
        size_y: num("YReal")?,
        size_unit: Some(unit("XYUnits")?.unwrap_or(Unit::M)),
        height_unit: unit("ZUnits")?,
    })
}
