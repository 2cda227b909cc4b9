//! Sweeps over one knob of a scene other than the load: the slab thickness t·q_r or the
//! surface energy γ_s, at the scene's p*.
//!
//! Each value is an independent scene, evaluated cold by [`engine::evaluate`] with the
//! caller's options (with [`engine::Options::default`] a point is bit for bit what
//! `asperity run` gives for the same scene), in parallel: the results do not depend on the
//! number of threads. A value whose solver does not converge is kept as an error and the
//! sweep goes on; invalid input ends it. The mean gap [S-12], optional because it needs an
//! adhesionless load sweep up to full contact per value, comes from [`gap::mean_gap_of`].
//!
//! Spacing: t·q_r is log-spaced (it spans decades, \[S\] Fig. 7 runs from 0.01 to ∞); γ_s is
//! spaced linearly (so that a sweep may start at γ_s = 0, the adhesionless limit).

use crate::error::{Error, Field, Result};
use crate::input::scene::{Scene, SURFACE_ENERGY_RANGE, THICKNESS_RANGE};
use crate::theory::engine::{self, Evaluation, Options};
use crate::theory::gap::{self, MeanGap};
use crate::theory::sweep::SweepRow;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// The knob a sweep turns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Knob {
    /// t·q_r (log-spaced).
    Thickness,
    /// γ_s in J/m² (linearly spaced).
    Gamma,
}

impl Knob {
    /// The field the knob sets (for error messages).
    pub fn field(self) -> Field {
        match self {
            Knob::Thickness => Field::Thickness,
            Knob::Gamma => Field::SurfaceEnergy,
        }
    }

    /// The scene with the knob set to `v`, its model resolved for the new scene (model 5's
    /// coefficients follow γ̃_glo, which both knobs move).
    pub fn apply(self, scene: &Scene, v: f64) -> Scene {
        let mut s = scene.clone();
        match self {
            Knob::Thickness => s.thickness_qr = v,
            Knob::Gamma => s.gamma = v,
        }
        s.resolve_model();
        s
    }
}

/// The values of a knob sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KnobSpec {
    /// Which knob.
    pub knob: Knob,
    /// First value.
    pub from: f64,
    /// Last value (above `from`, or equal with one point).
    pub to: f64,
    /// Number of values (1 ..= 10000).
    pub points: usize,
}

impl KnobSpec {
    /// Checks the range against the knob's allowed range.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming [`Field::SweepFrom`], [`Field::SweepTo`] or
    /// [`Field::SweepPoints`].
    pub fn validate(&self) -> Result<()> {
        let (lo, hi, what) = match self.knob {
            Knob::Thickness => (THICKNESS_RANGE.0, THICKNESS_RANGE.1, "t*q_r"),
            Knob::Gamma => (SURFACE_ENERGY_RANGE.0, SURFACE_ENERGY_RANGE.1, "gamma_s"),
        };
        let allowed = format!("{lo:e} <= {what} <= {hi:e}");
        for (field, v) in [(Field::SweepFrom, self.from), (Field::SweepTo, self.to)] {
            if !(v >= lo && v <= hi) {
                return Err(Error::invalid(field, v, allowed.clone()));
            }
        }
        crate::theory::sweep::check_points(self.points)?;
        if self.points > 1 && self.to <= self.from {
            return Err(Error::invalid(
                Field::SweepTo,
                self.to,
                format!(
                    "a value above the first {} (or a single point)",
                    crate::error::fmt_value(self.from)
                ),
            ));
        }
        Ok(())
    }

    /// The values, ascending: log-spaced for t·q_r, linear for γ_s.
    pub fn values(&self) -> Vec<f64> {
        if self.points == 1 {
            return vec![self.from];
        }
        let n = (self.points - 1) as f64;
        (0..self.points)
            .map(|i| {
                let t = i as f64 / n;
                // the ends exactly as given
                if i == 0 {
                    return self.from;
                }
                if i + 1 == self.points {
                    return self.to;
                }
                match self.knob {
                    Knob::Thickness => (self.from.ln() + t * (self.to / self.from).ln()).exp(),
                    Knob::Gamma => self.from + t * (self.to - self.from),
                }
            })
            .collect()
    }
}

/// One value of a knob sweep.
#[derive(Debug)]
pub struct KnobPoint {
    /// The knob's value.
    pub value: f64,
    /// The scene at that value.
    pub scene: Scene,
    /// The evaluation, or why the solver did not converge.
    pub result: std::result::Result<Evaluation, Error>,
    /// The mean gap (`None` when not asked for), or why it is unavailable.
    pub gap: std::result::Result<Option<MeanGap>, Error>,
}

impl KnobPoint {
    /// This point as a row of a load sweep at reduced pressure `pressure`, U* in units of
    /// `energy_unit` (J/m²): every number empty (NaN) where the solve failed, the gap's where it
    /// is unavailable or was not asked for (the reasons are in `result` and `gap`).
    pub fn row(&self, pressure: f64, energy_unit: f64) -> SweepRow {
        let mut r = SweepRow::empty(pressure);
        let Ok(e) = &self.result else { return r };
        r.a_r = e.stats.a_r;
        r.mean_contact_stress = e.stats.mean_contact_stress;
        r.contact_stress_variance = e.stats.contact_stress_variance;
        r.elastic_energy = e.elastic_energy;
        r.elastic_energy_reduced = e.elastic_energy / energy_unit;
        r.converged = true;
        r.a_r_unloading = e.unloading_a_r.unwrap_or(f64::NAN);
        r.branches = e.branches.len().max(1);
        if let Ok(Some(g)) = &self.gap {
            r.mean_gap_rel = g.relative;
            r.mean_gap = g.metres;
            r.mean_gap_error = g.error;
            r.mean_gap_lower_rel = g.lower;
            r.mean_gap_upper_rel = g.upper;
            r.contact_load = g.contact_load;
            if let Some(u) = g.unloading {
                r.mean_gap_unloading_rel = u.relative;
                r.mean_gap_unloading_error = u.error;
                r.mean_gap_unloading_lower_rel = u.lower;
                r.contact_load_unloading = u.contact_load;
            }
        }
        r
    }
}

/// Evaluates the scene at every value of `spec` (see the module docs); with `with_gap` the
/// mean gap too. Cancellation (`cancel` set) ends the call with [`Error::Cancelled`].
///
/// # Errors
/// [`Error::Invalid`] for a spec or options out of range, or a value that makes the scene
/// invalid (before any work); [`Error::Cancelled`]. A value whose solve does not converge is
/// kept in its [`KnobPoint::result`].
///
/// # Examples
/// ```
/// use asperity::input::preset::Preset;
/// use asperity::theory::engine::Options;
/// use asperity::theory::knob::{knob_sweep, Knob, KnobSpec};
///
/// // system II without adhesion: a thinner slab (traction-free far side, f(qt) → (qt)³/6
/// // [S-4]) gives way at long wavelengths, so more of it touches at the same load
/// let scene = Preset::resolve("system-2").unwrap().scene().unwrap().without_adhesion();
/// let spec = KnobSpec { knob: Knob::Thickness, from: 0.1, to: 10.0, points: 3 };
/// let pts = knob_sweep(&scene, &spec, &Options::default(), false, None).unwrap();
/// let a: Vec<f64> = pts.iter().map(|p| p.result.as_ref().unwrap().stats.a_r).collect();
/// assert!(a[0] > a[1] && a[1] > a[2]);
/// ```
pub fn knob_sweep(
    scene: &Scene,
    spec: &KnobSpec,
    opts: &Options,
    with_gap: bool,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<KnobPoint>> {
    spec.validate()?;
    opts.validate()?;
    let values = spec.values();
    // invalid input ends the call before any work
    for &v in &values {
        spec.knob.apply(scene, v).validate()?;
    }
    values
        .par_iter()
        .map(|&v| {
            if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
                return Err(Error::Cancelled);
            }
            let s = spec.knob.apply(scene, v);
            let result = match engine::evaluate_warm(&s, opts, None, cancel) {
                Err(Error::Cancelled) => return Err(Error::Cancelled),
                Err(e @ Error::NotConverged { .. }) => Err(e),
                Err(e) => return Err(e),
                Ok(ev) => Ok(ev),
            };
            let gap = match &result {
                Ok(ev) if with_gap => gap::mean_gap_of(&s, ev, opts).map(Some),
                _ => Ok(None),
            };
            Ok(KnobPoint {
                value: v,
                scene: s,
                result,
                gap,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;

    fn spec(knob: Knob, from: f64, to: f64, points: usize) -> KnobSpec {
        KnobSpec { knob, from, to, points }
    }

    /// The field a spec's validation names (None: valid, or another error).
    fn invalid_field(spec: &KnobSpec) -> Option<Field> {
        match spec.validate() {
            Err(Error::Invalid { field, .. }) => Some(field),
            _ => None,
        }
    }

    fn scene() -> Scene {
        let mut s = Preset::resolve("system-1").unwrap().scene().unwrap();
        s.gamma = 0.0;
        s
    }

    #[test]
    fn thickness_values_are_log_spaced_and_gamma_values_linear() {
        let t = spec(Knob::Thickness, 0.01, 1.0, 3);
        let v = t.values();
        assert!((v[1] / 0.1 - 1.0).abs() < 1e-14 && v[0] == 0.01 && v[2] == 1.0, "{v:?}");
        let g = spec(Knob::Gamma, 0.0, 0.1, 3);
        assert_eq!(g.values(), vec![0.0, 0.05, 0.1]);
    }

    #[test]
    fn bad_ranges_name_the_field() {
        let bad = spec(Knob::Thickness, 0.0, 1.0, 3);
        assert_eq!(invalid_field(&bad), Some(Field::SweepFrom));
        let bad = spec(Knob::Gamma, 0.1, 0.05, 3);
        assert_eq!(invalid_field(&bad), Some(Field::SweepTo));
    }

    #[test]
    fn each_point_is_the_engine_on_that_scene() {
        // independent reference: the engine called directly on the scene with the knob set
        let s = scene();
        let spec = spec(Knob::Thickness, 0.05, 5.0, 3);
        let pts = knob_sweep(&s, &spec, &Options::default(), false, None).unwrap();
        for p in &pts {
            let mut direct = s.clone();
            direct.thickness_qr = p.value;
            let e = engine::evaluate(&direct, &Options::default()).unwrap();
            assert_eq!(p.result.as_ref().unwrap().stats.a_r, e.stats.a_r);
        }
        // a thinner slab on a constant-stress base is softer at long wavelengths: more contact
        let a: Vec<f64> = pts.iter().map(|p| p.result.as_ref().unwrap().stats.a_r).collect();
        assert!(a[0] > a[1] && a[1] > a[2], "{a:?}");
    }

    #[test]
    fn model_5_is_resolved_for_each_value() {
        // the reference: the public setters, which resolve model 5 for the scene they make
        let base = Preset::resolve("system-2")
            .unwrap()
            .scene()
            .unwrap()
            .with_model(crate::input::model::Model::named(5).unwrap())
            .unwrap();
        for (knob, v) in [(Knob::Thickness, 0.15), (Knob::Gamma, 0.3)] {
            let swept = knob.apply(&base, v);
            let direct = match knob {
                Knob::Thickness => base.clone().with_thickness_qr(v),
                Knob::Gamma => base.clone().with_surface_energy_j_m2(v),
            }
            .unwrap();
            assert_eq!(swept.model(), direct.model(), "{knob:?} = {v}");
            assert_ne!(
                swept.model(),
                base.model(),
                "{knob:?} = {v}: model 5 moves with gamma_glo"
            );
        }
    }
}
