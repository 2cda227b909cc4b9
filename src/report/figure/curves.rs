//! The theory curves of a sweep figure (x = p*, t·q_r or γ_s): each x evaluated as `run`
//! evaluates it, refined where the curve bends ([`super::refine`]), and split into the
//! loading branch and, through a hysteresis window, the unloading branch.

use super::refine::{Axes, Refined, Sample};
use super::spec::{FigureSpec, XAxis, YAxis};
use super::{DataPoint, DataSeries, SeriesKind, Style};
use crate::error::Result;
use crate::input::scene::Scene;
use crate::theory::engine::{self, Options};
use crate::theory::gap;
use crate::theory::knob::{Knob, KnobSpec};
use crate::theory::sweep::{self, SweepSpec};
use rayon::prelude::*;

/// The x values of a sweep figure.
pub fn x_values(spec: &FigureSpec) -> Vec<f64> {
    let from = spec.from.unwrap_or(spec.to);
    match spec.x {
        XAxis::Pressure => SweepSpec {
            from,
            to: spec.to,
            points: spec.points,
        }
        .pressures(),
        XAxis::Thickness | XAxis::Gamma => KnobSpec {
            knob: if spec.x == XAxis::Thickness {
                Knob::Thickness
            } else {
                Knob::Gamma
            },
            from,
            to: spec.to,
            points: spec.points,
        }
        .values(),
        XAxis::Stress => Vec::new(),
    }
}

/// The x axis's quantity in notes.
pub(super) fn x_name(x: XAxis) -> &'static str {
    match x {
        XAxis::Pressure => "p*",
        XAxis::Thickness => "t·q_r",
        XAxis::Gamma => "γ_s",
        XAxis::Stress => "σ*",
    }
}

/// (a_r, σ̄_c*, ⟨δσ_c²⟩*) of an evaluation.
pub(super) fn y_of(y: YAxis, p: f64, a_r: f64, mean: f64, var: f64, gap: Option<f64>) -> Option<f64> {
    let v = match y {
        YAxis::AR => a_r,
        YAxis::AROverP => a_r / p,
        YAxis::MeanContactStress => mean,
        YAxis::ContactStressVariance => var,
        YAxis::MeanGapRel => gap?,
        YAxis::Pr => return None,
    };
    v.is_finite().then_some(v)
}

pub(super) fn point(x: f64, y: Option<f64>, note: Option<String>) -> DataPoint {
    DataPoint { x, y, note }
}

/// The evaluation of one theory curve at x: the loading branch's value, the unloading
/// branch's where a hysteresis window makes it distinct (a_r, a_r/p*, ū), and the number of
/// stable branches.
pub(super) fn sample_at(spec: &FigureSpec, scene: &Scene, x: f64) -> Sample {
    // the value `run` computes; a figure draws no error bar, so none is estimated
    let opts = Options {
        adhesion_error_estimate: false,
        ..Options::default()
    };
    let none = |note: String| Sample {
        x,
        y: None,
        y_unloading: None,
        stable: 0,
        note: Some(note),
    };
    let s = match spec.x {
        XAxis::Pressure => scene.clone().with_pressure(x),
        XAxis::Thickness => scene.clone().with_thickness_qr(x),
        XAxis::Gamma => scene.clone().with_surface_energy_j_m2(x),
        XAxis::Stress => Ok(scene.clone()),
    };
    let s = match s {
        Ok(s) => s,
        Err(e) => return none(e.to_string()),
    };
    let e = match engine::evaluate(&s, &opts) {
        Ok(e) => e,
        Err(e) => return none(e.to_string()),
    };
    let p = s.pressure();
    let (gap, gap_unloading) = if spec.y == YAxis::MeanGapRel {
        match gap::mean_gap_of(&s, &e, &opts) {
            Ok(g) => (Some(g.relative), g.unloading.map(|u| u.relative)),
            Err(err) => return none(err.to_string()),
        }
    } else {
        (None, None)
    };
    let st = &e.stats;
    let y = y_of(
        spec.y,
        p,
        st.a_r,
        st.mean_contact_stress,
        st.contact_stress_variance,
        gap,
    );
    let y_unloading = match spec.y {
        YAxis::AR => e.unloading_a_r,
        YAxis::AROverP => e.unloading_a_r.map(|a| a / p),
        YAxis::MeanGapRel => gap_unloading,
        _ => None,
    }
    .filter(|v| v.is_finite());
    Sample {
        x,
        y,
        y_unloading,
        stable: e.branches.iter().filter(|b| b.stable).count().max(1),
        note: y.is_none().then(|| "no value".to_string()),
    }
}

/// The scene at every x of the figure file, checked before any work (a value out of range is
/// an error of the figure, not a gap in a curve).
fn check_values(spec: &FigureSpec, scene: &Scene, xs: &[f64]) -> Result<()> {
    for &x in xs {
        match spec.x {
            XAxis::Pressure => scene.clone().with_pressure(x).map(|_| ())?,
            XAxis::Thickness => scene.clone().with_thickness_qr(x).map(|_| ())?,
            XAxis::Gamma => scene.clone().with_surface_energy_j_m2(x).map(|_| ())?,
            XAxis::Stress => {}
        }
    }
    Ok(())
}

/// A theory curve of a sweep figure before refinement: the load sweep for ū against p* (it
/// needs the sweep's shared energy table), else every x on its own, as `run` computes it.
pub(super) fn sweep_curve(spec: &FigureSpec, scene: &Scene) -> Result<Vec<Sample>> {
    let xs = x_values(spec);
    check_values(spec, scene, &xs)?;
    if spec.x == XAxis::Pressure && spec.y == YAxis::MeanGapRel {
        let sw = sweep::sweep(
            scene,
            &SweepSpec {
                from: xs[0],
                to: *xs.last().expect("points >= 2"),
                points: xs.len(),
            },
            &Options::default(),
            None,
        )?;
        return Ok(sw
            .rows
            .iter()
            .map(|r| {
                let y = r.mean_gap_rel.is_finite().then_some(r.mean_gap_rel);
                Sample {
                    x: r.p,
                    y,
                    y_unloading: r.mean_gap_unloading_rel.is_finite().then_some(r.mean_gap_unloading_rel),
                    stable: 1,
                    note: (!r.converged).then(|| "did not converge".to_string()),
                }
            })
            .collect());
    }
    Ok(xs.par_iter().map(|&x| sample_at(spec, scene, x)).collect())
}

/// The axes of a sweep figure for refinement: x over the file's range, y over every theory
/// curve's values.
pub(super) fn refine_axes(spec: &FigureSpec, curves: &[Vec<Sample>]) -> Axes {
    let xs = x_values(spec);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in curves.iter().flatten() {
        for v in [s.y, s.y_unloading].into_iter().flatten() {
            if v.is_finite() && (!spec.y_log || v > 0.0) {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
    }
    let (w, h) = super::refine::DRAWING_PX;
    Axes {
        x_log: spec.x_log,
        y_log: spec.y_log,
        x_range: (xs[0], *xs.last().unwrap_or(&xs[0])),
        y_range: (lo, hi),
        px: (f64::from(w), f64::from(h)),
    }
}

/// The series of a refined curve: the loading branch (broken where it ends at a window's
/// edge) and, where a hysteresis window makes it distinct, the unloading branch; notes on the
/// edges.
pub(super) fn branch_series(
    label: &str,
    kind: SeriesKind,
    r: &Refined,
    axes: &Axes,
    x_name: &str,
    notes: &mut Vec<String>,
) -> Vec<DataSeries> {
    let mut loading = Vec::with_capacity(r.samples.len() + r.breaks.len());
    for (i, s) in r.samples.iter().enumerate() {
        loading.push(point(s.x, s.y, s.note.clone()));
        if r.breaks.contains(&i) {
            let next = &r.samples[i + 1];
            let x = if axes.x_log {
                (s.x * next.x).sqrt()
            } else {
                0.5 * (s.x + next.x)
            };
            let note = format!(
                "{label}: the branch ends between {x_name} = {:.4e} and {:.4e}",
                s.x, next.x
            );
            loading.push(point(x, None, Some(note.clone())));
            notes.push(format!(
                "{note} (a hysteresis window's edge: the contact jumps there, the line is broken)"
            ));
        }
    }
    let mut out = vec![DataSeries {
        name: label.to_string(),
        style: Style::Line,
        points: loading,
        kind,
    }];
    if r.samples.iter().any(|s| s.y_unloading.is_some()) {
        let mut pts: Vec<DataPoint> = Vec::new();
        for s in &r.samples {
            match s.y_unloading {
                Some(u) => pts.push(point(s.x, Some(u), None)),
                // a break between two separate windows
                None if pts.last().is_some_and(|p| p.y.is_some()) => {
                    pts.push(point(s.x, None, Some("outside the hysteresis window".into())))
                }
                None => {}
            }
        }
        while pts.last().is_some_and(|p| p.y.is_none()) {
            pts.pop();
        }
        let inside: Vec<f64> = pts.iter().filter(|p| p.y.is_some()).map(|p| p.x).collect();
        notes.push(format!(
            "{label}: two stable branches (a hysteresis window) for {x_name} in [{:.4e}, {:.4e}]; the unloading \
             branch is drawn dashed",
            inside[0],
            inside[inside.len() - 1]
        ));
        // the same model's curve, dashed: one model, two branches
        out.push(DataSeries {
            name: format!("{label} (unloading)"),
            style: Style::Dashed,
            points: pts,
            kind,
        });
    }
    out
}
