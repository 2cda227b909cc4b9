//! A preset's `[measured]` section from Python (`Scene.preset` of a scene the explorer
//! exported from a measured map or PSD table): the map is read with the section's side,
//! height unit and periodicity and the theory runs on its PSD, or the PSD table is read, each
//! cut to the section's q range, exactly as `asperity run --preset` reads the section
//! (`--surface`/`--psd` with `--size`, `--height-unit`, `--periodic`, `--qmin`, `--qmax`).

use crate::scene::SceneCore;
use asperity::error::{Error, Field, Result};
use asperity::input::overrides::Overrides;
use asperity::input::preset::MeasuredSpec;
use asperity::surface::psd::{self, PsdOptions};
use asperity::surface::readers::{self, ReadOptions, Unit};
use asperity::surface::spectrum::{Spectrum, Tabulated};
use std::path::Path;
use std::sync::Arc;

/// The scene of `core` on the measured surface of its preset's `[measured]` section (the
/// scene unchanged without one).
///
/// # Errors
/// The readers' errors for the files; [`Error::Invalid`] naming `measured.height_unit` for a
/// unit the readers do not know.
pub fn apply(core: SceneCore) -> Result<SceneCore> {
    let Some(m) = core.preset.measured.clone() else {
        return Ok(core);
    };
    let (table, map) = table_of(&m)?;
    let scene = core.scene.apply(&Overrides {
        spectrum: Some(Spectrum::Tabulated(table)),
        ..Overrides::default()
    })?;
    Ok(SceneCore {
        scene,
        map: map.map(Arc::new),
        ..core
    })
}

/// The section's tabulated spectrum and the map it came from (None for a PSD table).
fn table_of(m: &MeasuredSpec) -> Result<(Tabulated, Option<asperity::surface::heightmap::Surface>)> {
    let (qmin, qmax) = (m.q_min_per_m, m.q_max_per_m);
    if let Some(p) = &m.psd {
        return Ok((Tabulated::load_csv(Path::new(p), qmin, qmax)?, None));
    }
    let Some(path) = &m.map else {
        return Err(Error::invalid_text(
            Field::Other("measured".into()),
            "neither map nor psd",
            "a map or a psd file",
        ));
    };
    let height_unit =
        match &m.height_unit {
            Some(u) => Some(Unit::parse(u).ok_or_else(|| {
                Error::invalid_text(Field::Other("measured.height_unit".into()), u, "nm, um, mm or m")
            })?),
            None => None,
        };
    let s = readers::read(
        Path::new(path),
        &ReadOptions {
            size: m.size_m,
            height_unit,
        },
    )?;
    s.check_rough()?;
    let a = psd::analyse(
        &s,
        &PsdOptions {
            periodic: m.periodic,
            ..PsdOptions::default()
        },
    )?;
    let (q, c): (Vec<f64>, Vec<f64>) = a.bins.iter().map(|b| (b.q, b.psd)).unzip();
    Ok((Tabulated::new(q, c, path, qmin, qmax)?, Some(s)))
}
