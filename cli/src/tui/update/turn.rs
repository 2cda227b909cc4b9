//! Turning a knob: one step on its grid (←→ fine, ⇧←→ coarse) or a typed value. The grids
//! of p*, t·q_r and γ_s are logarithmic and anchored at the preset's value, or at the last
//! typed value ([`Anchors`]); the custom model's coefficients step linearly. Every new value is
//! validated by the scene's setters; one out of range leaves the scene as it is and says why.

use crate::tui::model::app::*;
use crate::tui::update::scene::load_preset;
use asperity::error::{Error, Result};
use asperity::input::model::Model;

impl App {
    /// The preset knob: asks for the next (or previous) preset of the picker's list.
    fn step_preset(&self, dir: i32) -> Option<Command> {
        let list = &self.params.presets;
        let n = list.len() as i32;
        (n > 0).then(|| {
            let cur = list.iter().position(|e| e.source == self.params.source).unwrap_or(0) as i32;
            load_preset(&list[(cur + dir).rem_euclid(n) as usize].source)
        })
    }

    /// One step of the selected knob; the preset knob's asks for the preset's file.
    pub(crate) fn step(&mut self, dir: i32, coarse: bool) -> Option<Command> {
        if self.selected_param() == Param::Preset {
            return self.step_preset(dir);
        }
        self.step_value(dir, coarse);
        None
    }

    /// One step of the selected knob's value (every knob but the preset's).
    fn step_value(&mut self, dir: i32, coarse: bool) {
        let pick = |s: (f64, f64)| if coarse { s.1 } else { s.0 };
        let mut s = self.params.scene.clone();
        let m = s.model();
        // a typed value anchors its knob's grid; else the preset's value does
        let param = self.selected_param();
        let typed = self.params.anchors.get(param);
        let lin = |x: f64, step: (f64, f64)| lin_step_from(x, typed.unwrap_or(0.0), pick(step), dir);
        match param {
            // a file to read: stepped by [`App::step`]
            Param::Preset => return,
            Param::Model => {
                self.cycle_model(dir);
                return;
            }
            Param::Pressure => {
                let p = log_step_from(
                    s.pressure(),
                    typed.unwrap_or(self.params.base.pressure()),
                    pick(PRESSURE_STEPS),
                    dir,
                );
                if let Err(e) = s.set_pressure(p.clamp(PRESSURE_KEYS.0, PRESSURE_KEYS.1)) {
                    return self.fail(e);
                }
            }
            Param::Thickness => {
                let t = s.thickness_qr();
                if let Err(e) = s.set_thickness_qr(if t.is_infinite() {
                    if dir > 0 {
                        t
                    } else {
                        THICKNESS_KEYS.1
                    }
                } else {
                    let v = log_step_from(
                        t,
                        typed.unwrap_or(self.params.base.thickness_qr()),
                        pick(THICKNESS_STEPS),
                        dir,
                    );
                    if v > THICKNESS_KEYS.1 * (1.0 + 1e-9) {
                        f64::INFINITY
                    } else {
                        v.max(THICKNESS_KEYS.0)
                    }
                }) {
                    return self.fail(e);
                }
            }
            Param::Gamma => {
                let g = s.surface_energy_j_m2();
                if let Err(e) = s.set_surface_energy_j_m2(if g == 0.0 {
                    if dir > 0 {
                        let pg = self.params.preset.adhesion.surface_energy_j_m2;
                        if pg > 0.0 {
                            pg
                        } else {
                            1e-2
                        }
                    } else {
                        0.0
                    }
                } else {
                    let v = log_step_from(
                        g,
                        typed.unwrap_or(self.params.preset.adhesion.surface_energy_j_m2),
                        pick(GAMMA_STEPS),
                        dir,
                    );
                    if v < GAMMA_KEYS.0 * (1.0 - 1e-9) {
                        0.0
                    } else {
                        v.min(GAMMA_KEYS.1)
                    }
                }) {
                    return self.fail(e);
                }
            }
            Param::C1 => {
                return self.try_model(Model::custom(
                    lin(m.c1, (0.01, 0.1)),
                    m.c2,
                    m.alpha,
                    m.k_griffith,
                    m.cap,
                ))
            }
            Param::C2 => {
                return self.try_model(Model::custom(
                    m.c1,
                    lin(m.c2, (0.01, 0.1)),
                    m.alpha,
                    m.k_griffith,
                    m.cap,
                ))
            }
            Param::Alpha => {
                let a = lin(m.alpha, (0.05, 0.25)).clamp(0.0, 4.0);
                return self.try_model(Model::custom(m.c1, m.c2, a, m.k_griffith, m.cap));
            }
            Param::KGriffith => {
                let k = lin(m.k_griffith, (0.1, 1.0));
                let k = if k <= 0.0 { m.k_griffith.min(0.1) } else { k };
                return self.try_model(Model::custom(m.c1, m.c2, m.alpha, k, m.cap));
            }
            Param::Cap => return self.try_model(Model::custom(m.c1, m.c2, m.alpha, m.k_griffith, !m.cap)),
        }
        self.try_scene(s);
    }

    /// Sets a parameter from typed text; a preset's name or path asks for its file.
    pub fn set_typed(&mut self, param: Param, text: &str) -> Result<Option<Command>> {
        if param == Param::Preset {
            // read by the effect; an error comes back with the preset
            return Ok(Some(load_preset(text.trim())));
        }
        self.set_typed_value(param, text).map(|()| None)
    }

    /// Sets a parameter other than the preset from typed text.
    fn set_typed_value(&mut self, param: Param, text: &str) -> Result<()> {
        let mut s = self.params.scene.clone();
        let m = s.model();
        let t = text.trim();
        match param {
            // a file to read: set by [`App::set_typed`]
            Param::Preset => return Ok(()),
            Param::Model => {
                s.set_model(Model::of_kind(t.parse::<asperity::input::model::ModelKind>()?, &m)?)?;
            }
            Param::Pressure => {
                let p = parse_number("p*", t)?;
                if p <= 0.0 {
                    return Err(Error::field("p*", t, "p* > 0"));
                }
                s.set_pressure(p)?;
            }
            Param::Thickness => s.set_thickness_qr(t.parse::<asperity::input::scene::ThicknessQr>()?.0)?,
            Param::Gamma => {
                let g = if t.eq_ignore_ascii_case("off") {
                    0.0
                } else {
                    parse_number("gamma", t)?
                };
                // below the energy balance's round-off the theory is the adhesionless one
                // (`Scene::is_adhesive`): such a γ_s would only look like adhesion
                let floor = asperity::input::scene::WEAK_ADHESION_GLO * s.full_contact_energy();
                if g > 0.0 && g <= floor {
                    return Err(Error::field(
                        "gamma",
                        t,
                        format!(
                            "0 (off) or above {} J/m², the least γ_s this surface's energy balance resolves",
                            crate::numfmt::sig(floor, 3)
                        ),
                    ));
                }
                s.set_surface_energy_j_m2(g)?
            }
            Param::C1 => s.set_model(Model::custom(
                parse_number("c1", t)?,
                m.c2,
                m.alpha,
                m.k_griffith,
                m.cap,
            )?)?,
            Param::C2 => s.set_model(Model::custom(
                m.c1,
                parse_number("c2", t)?,
                m.alpha,
                m.k_griffith,
                m.cap,
            )?)?,
            Param::Alpha => s.set_model(Model::custom(
                m.c1,
                m.c2,
                parse_number("alpha", t)?,
                m.k_griffith,
                m.cap,
            )?)?,
            Param::KGriffith => s.set_model(Model::custom(m.c1, m.c2, m.alpha, parse_number("k_G", t)?, m.cap)?)?,
            Param::Cap => s.set_model(Model::custom(m.c1, m.c2, m.alpha, m.k_griffith, parse_bool("cap", t)?)?)?,
        }
        // the typed value anchors its knob's grid (the arrows step from it)
        let nm = s.model();
        let v = match param {
            Param::Pressure => s.pressure(),
            Param::Thickness => s.thickness_qr(),
            Param::Gamma => s.surface_energy_j_m2(),
            Param::C1 => nm.c1,
            Param::C2 => nm.c2,
            Param::Alpha => nm.alpha,
            Param::KGriffith => nm.k_griffith,
            _ => f64::NAN,
        };
        self.params.anchors.typed(param, v);
        self.set_scene(s);
        Ok(())
    }
}
