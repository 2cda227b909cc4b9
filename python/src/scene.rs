//! `SceneCore`: a validated [`Scene`] with the preset it came from (its name, its `[surface]`
//! for changes of the spectrum, its `[gfmd]` grid) and, for a measured surface, the map its
//! spectrum came from. Built by [`scene_from_preset`] (`Scene.preset`), [`scene_new`] (the
//! keyword constructor) and changed by `SceneCore.replace` (`Scene.replace`), each validated
//! by the library before it exists, exactly as the CLI resolves `--preset` and its flags
//! (`cli::SceneArgs::resolve`): the numbers equal `asperity run`'s for the same scene.
//!
//! Units as in the library: p* reduced by E*ḡ, t·q_r by the roll-off wave number (∞ for a
//! semi-infinite body), γ_s in J/m², ρ and lengths in m, E* in Pa.

use crate::errors;
use crate::surface::map_of;
use crate::value;
use asperity::error::Result;
use asperity::input::model::{Model, ModelKind};
use asperity::input::overrides::{ModelChanges, Overrides};
use asperity::input::preset::{AdhesionSpec, LoadSpec, MaterialSpec, ModelSpec, Preset, SurfaceSpec};
use asperity::input::scene::{Scene, ThicknessQr};
use asperity::surface::heightmap::Surface;
use asperity::surface::psd::PsdOptions;
use asperity::surface::spectrum::Spectrum;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::Arc;

/// A validated scene, its preset and the map of a measured spectrum.
#[pyclass(module = "asperity._native", frozen)]
#[derive(Clone)]
pub struct SceneCore {
    /// The preset (name, `[surface]`, `[gfmd]`); its scene fields are not read back.
    pub preset: Preset,
    /// The scene.
    pub scene: Scene,
    /// The measured map the spectrum came from (its PSD), if any.
    pub map: Option<Arc<Surface>>,
}

/// The keyword arguments of a change, read from a dict (None or absent: unchanged).
#[derive(Debug, Default)]
struct Changes {
    system_size_m: Option<f64>,
    rolloff_wavelength_m: Option<f64>,
    short_wavelength_m: Option<f64>,
    hurst: Option<f64>,
    rms_gradient: Option<f64>,
    rms_height_m: Option<f64>,
    contact_modulus_pa: Option<f64>,
    surface_energy_j_m2: Option<f64>,
    range_m: Option<f64>,
    pressure: Option<f64>,
    thickness_qr: Option<f64>,
    model: Option<String>,
    c1: Option<f64>,
    c2: Option<f64>,
    alpha: Option<f64>,
    k_griffith: Option<f64>,
    cap: Option<bool>,
    fudge_gamma: Option<f64>,
}

/// The names `Scene(...)` and `Scene.replace(...)` accept.
pub const NAMES: [&str; 18] = [
    "system_size_m",
    "rolloff_wavelength_m",
    "short_wavelength_m",
    "hurst",
    "rms_gradient",
    "rms_height_m",
    "contact_modulus_pa",
    "surface_energy_j_m2",
    "range_m",
    "pressure",
    "thickness_qr",
    "model",
    "c1",
    "c2",
    "alpha",
    "k_griffith",
    "cap",
    "fudge_gamma",
];

fn repr(v: &Bound<'_, PyAny>) -> String {
    v.repr().map(|r| r.to_string()).unwrap_or_else(|_| "?".into())
}

/// A number argument (an int or a float; a bool or anything else is refused).
fn number(py: Python<'_>, d: &Bound<'_, PyDict>, key: &str) -> PyResult<Option<f64>> {
    match d.get_item(key)? {
        None => Ok(None),
        Some(v) if v.is_none() => Ok(None),
        Some(v) => {
            if v.is_instance_of::<pyo3::types::PyBool>() {
                return Err(errors::input(py, key, &repr(&v), "a number"));
            }
            v.extract::<f64>()
                .map(Some)
                .map_err(|_| errors::input(py, key, &repr(&v), "a number"))
        }
    }
}

impl Changes {
    fn read(py: Python<'_>, d: &Bound<'_, PyDict>) -> PyResult<Changes> {
        for k in d.keys() {
            let k: String = k.extract()?;
            if !NAMES.contains(&k.as_str()) {
                return Err(pyo3::exceptions::PyTypeError::new_err(format!(
                    "unexpected keyword argument '{k}' (allowed: {})",
                    NAMES.join(", ")
                )));
            }
        }
        let model = match d.get_item("model")? {
            None => None,
            Some(v) if v.is_none() => None,
            Some(v) => {
                if let Ok(s) = v.extract::<String>() {
                    Some(s)
                } else if let (false, Ok(n)) = (v.is_instance_of::<pyo3::types::PyBool>(), v.extract::<i64>()) {
                    Some(n.to_string())
                } else {
                    return Err(errors::input(
                        py,
                        "model",
                        &repr(&v),
                        asperity::input::model::MODEL_NAMES,
                    ));
                }
            }
        };
        let thickness_qr = match d.get_item("thickness_qr")? {
            Some(v) if !v.is_none() => match v.extract::<String>() {
                Ok(s) => Some(s.parse::<ThicknessQr>().map_err(|e| errors::to_py(py, e))?.0),
                Err(_) => number(py, d, "thickness_qr")?,
            },
            _ => None,
        };
        let cap = match d.get_item("cap")? {
            Some(v) if !v.is_none() => Some(
                v.extract::<bool>()
                    .map_err(|_| errors::input(py, "cap", &repr(&v), "True or False"))?,
            ),
            _ => None,
        };
        let n = |k: &str| number(py, d, k);
        Ok(Changes {
            system_size_m: n("system_size_m")?,
            rolloff_wavelength_m: n("rolloff_wavelength_m")?,
            short_wavelength_m: n("short_wavelength_m")?,
            hurst: n("hurst")?,
            rms_gradient: n("rms_gradient")?,
            rms_height_m: n("rms_height_m")?,
            contact_modulus_pa: n("contact_modulus_pa")?,
            surface_energy_j_m2: n("surface_energy_j_m2")?,
            range_m: n("range_m")?,
            pressure: n("pressure")?,
            thickness_qr,
            model,
            c1: n("c1")?,
            c2: n("c2")?,
            alpha: n("alpha")?,
            k_griffith: n("k_griffith")?,
            cap,
            fudge_gamma: n("fudge_gamma")?,
        })
    }

    fn surface_changed(&self) -> bool {
        [
            self.system_size_m,
            self.rolloff_wavelength_m,
            self.short_wavelength_m,
            self.hurst,
            self.rms_gradient,
            self.rms_height_m,
        ]
        .iter()
        .any(Option::is_some)
    }
}

/// The changes to the model of `ch` ([`ModelChanges::apply`], as the CLI's `--model`, `--c1`..
/// and `--fudge-gamma`).
fn model_changes(ch: &Changes) -> Result<ModelChanges> {
    Ok(ModelChanges {
        kind: ch.model.as_deref().map(str::parse::<ModelKind>).transpose()?,
        c1: ch.c1,
        c2: ch.c2,
        alpha: ch.alpha,
        k_griffith: ch.k_griffith,
        cap: ch.cap,
        fudge_gamma: ch.fudge_gamma,
    })
}

impl SceneCore {
    /// This scene with `ch` applied, validated as a whole.
    fn changed(&self, ch: &Changes) -> Result<SceneCore> {
        let mut preset = self.preset.clone();
        let mut map = self.map.clone();
        let mut spectrum = None;
        if ch.surface_changed() {
            let s = &mut preset.surface;
            s.system_size_m = ch.system_size_m.unwrap_or(s.system_size_m);
            s.rolloff_wavelength_m = ch.rolloff_wavelength_m.unwrap_or(s.rolloff_wavelength_m);
            s.short_wavelength_m = ch.short_wavelength_m.unwrap_or(s.short_wavelength_m);
            s.hurst = ch.hurst.unwrap_or(s.hurst);
            if ch.rms_gradient.is_some() || ch.rms_height_m.is_some() {
                s.rms_gradient = ch.rms_gradient;
                s.rms_height_m = ch.rms_height_m;
            }
            spectrum = Some(preset.spectrum()?);
            map = None;
        }
        let o = Overrides {
            model_changes: model_changes(ch)?,
            pressure: ch.pressure,
            thickness_qr: ch.thickness_qr,
            surface_energy_j_m2: ch.surface_energy_j_m2,
            range_m: ch.range_m,
            contact_modulus_pa: ch.contact_modulus_pa,
            spectrum,
            ..Overrides::default()
        };
        let scene = self.scene.apply(&o)?;
        Ok(SceneCore { preset, scene, map })
    }
}

/// `Scene.preset(name_or_path)`: a built-in preset, `presets/NAME.toml` or a TOML file (with
/// its `[measured]` surface, [`crate::measured`]).
#[pyfunction]
pub fn scene_from_preset(py: Python<'_>, name_or_path: &str) -> PyResult<SceneCore> {
    // without the GIL: a `[measured]` map is read and analysed here
    errors::detached(py, || {
        let preset = Preset::resolve(name_or_path)?;
        let scene = preset.scene()?;
        // an export's measured surface, read as `run --preset` reads it
        crate::measured::apply(SceneCore {
            preset,
            scene,
            map: None,
        })
    })
}

/// `Scene(...)`: a scene from its fields (the keyword arguments of [`NAMES`]); the spectrum's
/// fields are required, the rest default to a semi-infinite, adhesionless model-3 scene at
/// p* = 0.01 (ρ = 1 nm).
#[pyfunction]
pub fn scene_new(py: Python<'_>, fields: &Bound<'_, PyDict>) -> PyResult<SceneCore> {
    let ch = Changes::read(py, fields)?;
    let need =
        |v: Option<f64>, k: &str| v.ok_or_else(|| pyo3::exceptions::PyTypeError::new_err(format!("Scene() needs {k}")));
    if ch.rms_gradient.is_none() && ch.rms_height_m.is_none() {
        return Err(pyo3::exceptions::PyTypeError::new_err(
            "Scene() needs rms_gradient or rms_height_m",
        ));
    }
    let preset = Preset {
        name: "custom".into(),
        description: "a scene built from keyword arguments".into(),
        surface: SurfaceSpec {
            system_size_m: need(ch.system_size_m, "system_size_m")?,
            rolloff_wavelength_m: need(ch.rolloff_wavelength_m, "rolloff_wavelength_m")?,
            short_wavelength_m: need(ch.short_wavelength_m, "short_wavelength_m")?,
            hurst: need(ch.hurst, "hurst")?,
            rms_gradient: ch.rms_gradient,
            rms_height_m: ch.rms_height_m,
        },
        material: MaterialSpec {
            contact_modulus_pa: need(ch.contact_modulus_pa, "contact_modulus_pa")?,
        },
        adhesion: AdhesionSpec {
            surface_energy_j_m2: ch.surface_energy_j_m2.unwrap_or(0.0),
            range_m: ch.range_m.unwrap_or(1e-9),
        },
        load: LoadSpec {
            pressure: ch.pressure.unwrap_or(0.01),
            thickness_qr: ch.thickness_qr.unwrap_or(f64::INFINITY),
            branch: None,
        },
        model: ModelSpec::default(),
        gfmd: None,
        reference: Vec::new(),
        measured: None,
    };
    errors::guard(py, || {
        // the surface first: its errors name its fields before anything else is checked
        let spectrum = preset.spectrum()?;
        let model = model_changes(&ch)?.apply(Model::named(3)?)?;
        let scene = Scene::new(
            spectrum,
            preset.material.contact_modulus_pa,
            model,
            preset.load.pressure,
            preset.load.thickness_qr,
            preset.adhesion.surface_energy_j_m2,
            preset.adhesion.range_m,
        )?;
        Ok(SceneCore {
            preset,
            scene,
            map: None,
        })
    })
}

#[pymethods]
impl SceneCore {
    /// A validated copy with the keyword arguments of `changes` applied.
    fn replace(&self, py: Python<'_>, changes: &Bound<'_, PyDict>) -> PyResult<SceneCore> {
        let ch = Changes::read(py, changes)?;
        errors::guard(py, || self.changed(&ch))
    }

    /// A copy on the PSD of a measured map (heights in m, rows along y; `size_m` the x side),
    /// as `--surface FILE` gives it: the radial average of the map's PSD [S-2] as a tabulated
    /// spectrum, cut to [qmin, qmax] (1/m) where given.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (heights, size_m, periodic = false, qmin = None, qmax = None, source = "heights".to_string()))]
    fn with_map(
        &self,
        py: Python<'_>,
        heights: numpy::PyReadonlyArray2<'_, f64>,
        size_m: f64,
        periodic: bool,
        qmin: Option<f64>,
        qmax: Option<f64>,
        source: String,
    ) -> PyResult<SceneCore> {
        let surface = map_of(py, &heights, size_m)?;
        // without the GIL: the map's PSD is the long part
        errors::detached(py, || {
            let opts = PsdOptions {
                periodic,
                ..PsdOptions::default()
            };
            let spectrum = Spectrum::from_map(&surface, &opts, (qmin, qmax), &source)?;
            let scene = self.scene.apply(&Overrides {
                spectrum: Some(spectrum),
                ..Overrides::default()
            })?;
            Ok(SceneCore {
                preset: self.preset.clone(),
                scene,
                map: Some(Arc::new(surface)),
            })
        })
    }

    /// The resolved inputs (the `scene` object of `asperity run --format json`) with the
    /// preset's name under `preset`.
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let d = value::ser(py, &self.scene.summary())?;
        d.set_item("preset", &self.preset.name)?;
        Ok(d)
    }

    /// The preset's name ("custom" for a scene built from keywords).
    #[getter]
    fn preset_name(&self) -> String {
        self.preset.name.clone()
    }

    /// The preset's fields as TOML-like nested dicts (for `Scene.fields()`).
    fn fields<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let s = &self.scene;
        let d = value::ser(py, &self.preset.surface)?;
        d.set_item("contact_modulus_pa", s.contact_modulus_pa())?;
        d.set_item("surface_energy_j_m2", s.surface_energy_j_m2())?;
        d.set_item("range_m", s.range_m())?;
        d.set_item("pressure", s.pressure())?;
        d.set_item("thickness_qr", s.thickness_qr())?;
        let m = s.model();
        d.set_item(
            "model",
            m.number().map_or_else(|| m.kind.name().to_string(), |n| n.to_string()),
        )?;
        d.set_item("c1", m.c1)?;
        d.set_item("c2", m.c2)?;
        d.set_item("alpha", m.alpha)?;
        d.set_item("k_griffith", m.k_griffith)?;
        d.set_item("cap", m.cap)?;
        d.set_item("spectrum", s.spectrum().kind().to_string())?;
        Ok(d)
    }

    fn __eq__(&self, other: &SceneCore) -> bool {
        self.scene == other.scene && self.preset.name == other.preset.name
    }
}
