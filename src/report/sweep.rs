//! The report of a sweep over one knob of a scene: the load p* ([`crate::theory::sweep`]:
//! continuation, one shared gap table), the slab thickness t·q_r or the surface energy γ_s
//! ([`crate::theory::knob`]: each value its own scene at the scene's p*, exactly what
//! [`crate::report::point()`] gives for it). One row per value with a_r, ū/h_rms, ū, σ̄_c*,
//! ⟨δσ_c²⟩*, a_r/p*, the [S-18] reference, U, convergence and the trust read-out; the edges of
//! the hysteresis windows inside the range; with `cycle` the theory's path along a load cycle
//! ([`crate::theory::cycle::path_through_tension`]).
//!
//! Knob sweeps find a window narrower than their step by probing each jump of a_r between
//! neighbours ([`hysteresis::window_probes`]), the probe the explorer's thickness chart uses;
//! the probes' values bound the edges ([`hysteresis::knob_edges`]) but add no rows.
//!
//! A value that does not converge keeps its row with empty numbers (NaN, serialised as null)
//! and a one-line `reason`; invalid input fails the call before any work. The serialised
//! field names are those of `asperity sweep --format json` (a public interface).

use crate::error::{fmt_value, Error, Field, Result};
use crate::input::scene::{Scene, SceneSummary, PRESSURE_RANGE};
use crate::theory::closed_form::eq18_area;
use crate::theory::cycle::{path_through_tension, TheoryCycle};
use crate::theory::engine::Options;
use crate::theory::hysteresis::{self, EdgeKind, KnobEdge};
use crate::theory::knob::{knob_sweep, Knob, KnobPoint, KnobSpec};
use crate::theory::sweep::{self, one_line, SweepRow, SweepSpec};
use serde::Serialize;
use std::sync::atomic::AtomicBool;

/// The knob a sweep turns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Over {
    /// p* (log-spaced).
    Pressure,
    /// t·q_r (log-spaced), at the scene's p*.
    Thickness,
    /// γ_s in J/m² (linearly spaced), at the scene's p*.
    Gamma,
}

impl Over {
    /// The knob of a thickness or γ_s sweep; None for a load sweep.
    pub fn knob(self) -> Option<Knob> {
        match self {
            Over::Pressure => None,
            Over::Thickness => Some(Knob::Thickness),
            Over::Gamma => Some(Knob::Gamma),
        }
    }

    /// The sweep over `knob`.
    pub fn of(knob: Knob) -> Over {
        match knob {
            Knob::Thickness => Over::Thickness,
            Knob::Gamma => Over::Gamma,
        }
    }
}

impl std::str::FromStr for Over {
    type Err = Error;

    /// "pressure", "thickness" (or "thickness_qr"), "gamma" (or "surface_energy_j_m2").
    fn from_str(s: &str) -> Result<Over> {
        match s {
            "pressure" => Ok(Over::Pressure),
            "thickness" | "thickness_qr" => Ok(Over::Thickness),
            "gamma" | "surface_energy_j_m2" => Ok(Over::Gamma),
            other => Err(Error::invalid_text(
                Field::Other("over".into()),
                other,
                "pressure, thickness or gamma",
            )),
        }
    }
}

/// One row of a sweep. Unavailable numbers are NaN in `row` (null when serialised).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    /// The engine's row (p*, a_r, ū, σ̄_c*, U, converged, …, ⟨δσ_c²⟩*).
    #[serde(flatten)]
    pub row: SweepRow,
    /// a_r/p*.
    pub a_r_over_p: f64,
    /// a_r of [S-18] at this p*, where it applies (γ_s = 0, semi-infinite); else None.
    pub a_r_eq18: Option<f64>,
    /// t·q_r; None for a semi-infinite body.
    pub thickness_qr: Option<f64>,
    /// γ_s (J/m²).
    pub gamma: f64,
    /// Whether this row's scene lies inside asperity's GFMD reference set
    /// ([`crate::fit::trust`]).
    pub trust_inside: bool,
    /// Mean |ln(theory/GFMD)| of a_r measured at the reference set's nearest points.
    pub trust_a_r_log_error: f64,
    /// Why the row has no numbers (the solver's error, or why the mean gap is unavailable),
    /// on one line; None for a complete row.
    pub reason: Option<String>,
}

impl Row {
    /// The row of `row` for `scene` at the row's load (adds a_r/p*, [S-18] and the trust
    /// read-out).
    pub fn new(row: SweepRow, scene: &Scene) -> Row {
        let (thickness_qr, gamma) = (scene.thickness_qr(), scene.surface_energy_j_m2());
        let eq18 = (gamma == 0.0 && thickness_qr.is_infinite()).then(|| eq18_area(row.p));
        let at = scene.clone().with_pressure(row.p).unwrap_or_else(|_| scene.clone());
        let trust = crate::fit::trust::assess(&at);
        Row {
            row,
            a_r_over_p: row.a_r / row.p,
            a_r_eq18: eq18,
            thickness_qr: thickness_qr.is_finite().then_some(thickness_qr),
            gamma,
            trust_inside: trust.inside,
            trust_a_r_log_error: trust.a_r_log_error,
            reason: None,
        }
    }

    /// The row with `reason` (see [`Row::reason`]).
    pub fn with_reason(self, reason: Option<String>) -> Row {
        Row { reason, ..self }
    }
}

/// Everything a sweep reports (the object of `asperity sweep --format json`).
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct SweepReport {
    /// Preset name.
    pub preset: String,
    /// The swept knob.
    pub over: Over,
    /// Resolved inputs (at the first value).
    pub scene: SceneSummary,
    /// One row per value.
    pub rows: Vec<Row>,
    /// Engine evaluations spent.
    pub evaluations: usize,
    /// p* at which the contact is full (of the scene at the first value).
    pub full_contact_pressure: f64,
    /// Whether a_r rose and ū fell with the load (load sweeps; true for other knobs).
    pub monotone: bool,
    /// Loads (p*) of the rows that did not converge.
    pub failed_loads: Vec<f64>,
    /// Values of the swept knob whose rows did not converge.
    pub failed_values: Vec<f64>,
    /// What failed; absent when every value converged.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// Load sweeps: p* above which the loading branch no longer exists (the jump into
    /// contact), where the range holds it; None otherwise (and for other knobs).
    pub jump_in_pressure: Option<f64>,
    /// Load sweeps: p* below which the unloading branch no longer exists (pull-off), where
    /// the range holds it; None otherwise.
    pub pull_off_pressure: Option<f64>,
    /// The edges of hysteresis windows inside the range, in the swept knob's values,
    /// ascending within each kind ("jump_in": the small-contact branch ends there, the contact
    /// jumps in; "pull_off": the large-contact branch ends). Load sweeps: the edges above;
    /// thickness and γ_s sweeps: every edge between two neighbouring values (or a value and
    /// a probe inside a window, see the module docs) that differ in the number of stable
    /// branches, refined by bisection.
    pub window_edges: Vec<KnobEdge>,
    /// With `cycle`: the theory's path up, back down and on into tension (rows with
    /// `branch`), where the unloading branch ends, the theory's pull-off, and why the path
    /// stops where it does.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cycle: Option<TheoryCycle>,
    /// With `cycle`: the pull-off read-out around the cycle's pull-off (the DMT routes,
    /// GFMD's nearest measured pull-off and how far each was measured from GFMD,
    /// [`super::pull_off`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pull_off: Option<super::pull_off::PullOffReport>,
}

/// How a load cycle's loads are described where a list of loads is not log-spaced (a front end
/// may say it in its own words).
pub const CYCLE_LOADS_WORDS: &str = "for a load cycle (equal ratios from the first to the last)";

/// Where a sweep runs: the cancel flag (set: the sweep ends with [`Error::Cancelled`]) and a
/// progress callback called with (values done, values in all) before each part.
pub struct Control<'a> {
    /// Set when the caller wants the sweep to stop.
    pub cancel: Option<&'a AtomicBool>,
    /// Progress (done, total).
    pub progress: &'a mut dyn FnMut(usize, usize),
}

impl Control<'_> {
    /// No cancel flag, no progress.
    pub fn none(f: &mut dyn FnMut(usize, usize)) -> Control<'_> {
        Control {
            cancel: None,
            progress: f,
        }
    }
}

/// Whether `values` (ascending) are `spec`'s to 1e-9 relative.
fn same_values(values: &[f64], spec: &[f64]) -> bool {
    values.len() == spec.len()
        && values
            .iter()
            .zip(spec)
            .all(|(a, b)| a == b || (a - b).abs() <= 1e-9 * a.abs().max(b.abs()))
}

/// Checks that `values` is a non-empty ascending list (errors name `field`).
fn check_ascending(values: &[f64], field: &str) -> Result<()> {
    if values.is_empty() {
        return Err(Error::invalid_text(
            Field::Other(field.into()),
            "[] (empty)",
            "one or more values",
        ));
    }
    if let Some(w) = values.windows(2).find(|w| w[1] <= w[0] || w[1].is_nan()) {
        return Err(Error::invalid(
            Field::Other(field.into()),
            w[1],
            format!("strictly ascending values (after {})", fmt_value(w[0])),
        ));
    }
    Ok(())
}

/// The load sweeps that give the loads `pressures` (ascending): one sweep where they are
/// evenly log-spaced (as from, to and points give them), else one single-load sweep per value.
/// With `cycle` the loads must be one sweep's (the path follows the sweep's branches).
///
/// # Errors
/// [`Error::Invalid`] naming "pressures" (or the pressure) for an empty, unordered or
/// out-of-range list, or with `cycle` loads that are not log-spaced.
pub fn pressure_specs(pressures: &[f64], cycle: bool) -> Result<Vec<SweepSpec>> {
    check_ascending(pressures, "pressures")?;
    for &p in pressures {
        crate::error::check_in(Field::Pressure, p, PRESSURE_RANGE.0, PRESSURE_RANGE.1)?;
    }
    let n = pressures.len();
    let spec = SweepSpec {
        from: pressures[0],
        to: pressures[n - 1],
        points: n,
    };
    let even = spec.pressures();
    if same_values(pressures, &even) {
        return Ok(vec![spec]);
    }
    if cycle {
        let (k, &v) = pressures
            .iter()
            .enumerate()
            .find(|(k, p)| !same_values(&[**p], &[even[*k]]))
            .expect("a value off the log-spaced loads");
        return Err(Error::invalid(
            Field::Other("pressures".into()),
            v,
            format!(
                "log-spaced loads {CYCLE_LOADS_WORDS}: {} at position {k}",
                fmt_value(even[k])
            ),
        ));
    }
    Ok(pressures
        .iter()
        .map(|&p| SweepSpec {
            from: p,
            to: p,
            points: 1,
        })
        .collect())
}

/// The knob sweeps of `scene` that give the values `values` (ascending) of `knob`: one sweep
/// where they are evenly spaced (log-spaced t·q_r, linear γ_s), else one per value; every
/// value checked against the scene before any work.
///
/// # Errors
/// [`Error::Invalid`] naming "thickness_qr" or "surface_energy_j_m2" for an empty or
/// unordered list, an infinite t·q_r, or a value the scene does not allow.
pub fn knob_specs(scene: &Scene, knob: Knob, values: &[f64]) -> Result<Vec<KnobSpec>> {
    let field = match knob {
        Knob::Thickness => "thickness_qr",
        Knob::Gamma => "surface_energy_j_m2",
    };
    check_ascending(values, field)?;
    if let Some(&v) = values.iter().find(|v| knob == Knob::Thickness && !v.is_finite()) {
        return Err(Error::invalid(
            Field::Thickness,
            v,
            "a finite t*q_r in a sweep (the half-space: evaluate the scene with thickness_qr = inf)",
        ));
    }
    for &v in values {
        match knob {
            Knob::Thickness => scene.clone().with_thickness_qr(v).map(|_| ())?,
            Knob::Gamma => scene.clone().with_surface_energy_j_m2(v).map(|_| ())?,
        }
    }
    let n = values.len();
    let spec = KnobSpec {
        knob,
        from: values[0],
        to: values[n - 1],
        points: n,
    };
    if spec.validate().is_ok() && same_values(values, &spec.values()) {
        return Ok(vec![spec]);
    }
    Ok(values
        .iter()
        .map(|&v| KnobSpec {
            knob,
            from: v,
            to: v,
            points: 1,
        })
        .collect())
}

/// The edges of a load sweep's window as [`SweepReport::window_edges`] (ascending p*).
fn load_edges(pull_off: Option<f64>, jump_in: Option<f64>) -> Vec<KnobEdge> {
    [(pull_off, EdgeKind::PullOff), (jump_in, EdgeKind::JumpIn)]
        .into_iter()
        .filter_map(|(v, kind)| v.map(|value| KnobEdge { value, kind }))
        .collect()
}

/// The load sweep of `scene` (of the preset `preset`) over the loads of `specs` (one sweep, or
/// several run one after the other: [`pressure_specs`]), with the theory's path along the
/// load cycle when `cycle` and `specs` is one sweep.
///
/// # Errors
/// [`Error::Invalid`] for a spec or options out of range (before any work); what
/// [`sweep::sweep`] and [`path_through_tension`] return ([`Error::Cancelled`] included).
pub fn pressure(
    scene: &Scene,
    preset: &str,
    specs: &[SweepSpec],
    opts: &Options,
    cycle: bool,
    ctl: Control<'_>,
) -> Result<SweepReport> {
    for sp in specs {
        sp.validate()?;
    }
    opts.validate()?;
    let first = specs
        .first()
        .ok_or_else(|| Error::invalid_text(Field::Other("pressures".into()), "[] (empty)", "one or more values"))?;
    let n: usize = specs.iter().map(|s| s.points).sum();
    let scene = scene.clone().with_pressure(first.from)?;
    let single = specs.len() == 1;
    let mut out = SweepReport {
        preset: preset.to_string(),
        over: Over::Pressure,
        scene: scene.summary(),
        rows: Vec::with_capacity(n),
        evaluations: 0,
        full_contact_pressure: f64::NAN,
        monotone: true,
        failed_loads: Vec::new(),
        failed_values: Vec::new(),
        note: None,
        jump_in_pressure: None,
        pull_off_pressure: None,
        window_edges: Vec::new(),
        cycle: None,
        pull_off: None,
    };
    let mut notes = Vec::new();
    for (k, sp) in specs.iter().enumerate() {
        (ctl.progress)(if single { 0 } else { k }, n);
        let sw = sweep::sweep(&scene, sp, opts, ctl.cancel)?;
        if cycle && single {
            let c = path_through_tension(&sw, &scene, &opts.adhesion, ctl.cancel)?;
            out.pull_off = c.pull_off_pressure.map(|p| {
                let theory = super::pull_off::TheoryPullOff {
                    pull_off_pressure: p,
                    pull_off_bracket: c.pull_off_bracket.unwrap_or([p, p]),
                    tension_bound: c.tension_bound.unwrap_or(f64::NAN),
                };
                super::pull_off::read_out(&scene, theory)
            });
            out.cycle = Some(c);
        }
        for (r, why) in sw.rows.iter().zip(&sw.reasons) {
            out.rows.push(Row::new(*r, &scene).with_reason(why.clone()));
        }
        out.evaluations += sw.evaluations;
        if k == 0 {
            out.full_contact_pressure = sw.full_contact_pressure;
        }
        out.failed_loads.extend(&sw.failed_loads);
        notes.extend(sw.note.clone());
        if single {
            out.monotone = sw.monotone;
            out.jump_in_pressure = sw.jump_in_pressure;
            out.pull_off_pressure = sw.pull_off_pressure;
            out.window_edges = load_edges(sw.pull_off_pressure, sw.jump_in_pressure);
        }
    }
    if !single {
        let ok: Vec<&Row> = out.rows.iter().filter(|r| r.row.converged).collect();
        out.monotone = ok.windows(2).all(|w| {
            w[1].row.a_r >= w[0].row.a_r
                && w[1].row.mean_gap_rel.partial_cmp(&w[0].row.mean_gap_rel) != Some(std::cmp::Ordering::Greater)
        });
    }
    out.failed_values = out.failed_loads.clone();
    out.note = (!notes.is_empty()).then(|| notes.join("; "));
    Ok(out)
}

/// The knob sweep of `scene` (of the preset `preset`) over the values of `specs` (one sweep,
/// or several: [`knob_specs`]) at the scene's p*, each row what [`crate::report::point()`]
/// gives there, with the mean gap; the hysteresis windows' edges found between neighbours and
/// inside jumps of a_r (module docs).
///
/// # Errors
/// [`Error::Invalid`] for a spec, a value or options out of range (before any work);
/// [`Error::Cancelled`]; what [`hysteresis::knob_edges`] returns. A value that does not
/// converge keeps its row, empty, with the reason.
pub fn knob(
    scene: &Scene,
    preset: &str,
    knob: Knob,
    specs: &[KnobSpec],
    opts: &Options,
    ctl: Control<'_>,
) -> Result<SweepReport> {
    for sp in specs {
        sp.validate()?;
        for v in sp.values() {
            knob.apply(scene, v).validate()?;
        }
    }
    opts.validate()?;
    let first_value = specs
        .first()
        .map(|s| s.from)
        .ok_or_else(|| Error::invalid_text(Field::Other("values".into()), "[] (empty)", "one or more values"))?;
    let n: usize = specs.iter().map(|s| s.points).sum();
    let mut points: Vec<KnobPoint> = Vec::with_capacity(n);
    for sp in specs {
        (ctl.progress)(points.len(), n);
        points.extend(knob_sweep(scene, sp, opts, true, ctl.cancel)?);
    }
    let probes = if scene.gamma > 0.0 || knob == Knob::Gamma {
        hysteresis::window_probes(scene, knob, &points, opts, false, ctl.cancel)?
    } else {
        Vec::new()
    };
    let (points, given) = hysteresis::merge_probes(points, probes);
    let window_edges = hysteresis::knob_edges(scene, knob, &points, &opts.adhesion, ctl.cancel)?;
    let unit = crate::theory::energy::energy_unit(scene);
    let mut notes = Vec::new();
    let mut failed = Vec::new();
    let rows: Vec<Row> = points
        .iter()
        .zip(&given)
        .filter(|(_, given)| **given)
        .map(|(pt, _)| {
            let reason = match (&pt.result, &pt.gap) {
                (Err(e), _) => {
                    failed.push(pt.value);
                    Some(one_line(&e.to_string()))
                }
                (Ok(_), Err(e)) => Some(one_line(&format!("mean gap unavailable: {e}"))),
                (Ok(_), Ok(_)) => None,
            };
            if let Some(why) = &reason {
                notes.push(format!("value {:e}: {why}", pt.value));
            }
            Row::new(pt.row(scene.pressure(), unit), &pt.scene).with_reason(reason)
        })
        .collect();
    let note = (!notes.is_empty()).then(|| {
        format!(
            "{} of {} values did not converge or lack the gap; their cells are empty (null): {}",
            notes.len(),
            rows.len(),
            notes.join("; ")
        )
    });
    let first = knob.apply(scene, first_value);
    Ok(SweepReport {
        preset: preset.to_string(),
        over: Over::of(knob),
        scene: first.summary(),
        evaluations: rows.len(),
        rows,
        full_contact_pressure: crate::theory::gap::full_contact_pressure(&first),
        monotone: true,
        failed_loads: failed.iter().map(|_| scene.pressure()).collect(),
        failed_values: failed,
        note,
        jump_in_pressure: None,
        pull_off_pressure: None,
        window_edges,
        cycle: None,
        pull_off: None,
    })
}

#[cfg(test)]
#[path = "sweep_tests.rs"]
pub(crate) mod tests;
