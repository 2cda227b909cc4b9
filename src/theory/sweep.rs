//! Load sweeps: a_r(p*), ū(p*)/h_rms, σ̄_c*(p*) and U(p*) on a log-spaced p* range.
//!
//! One sweep evaluates the scene ([`crate::theory::engine::evaluate`]) on a single uniform grid in
//! ln p*: the requested points (from `from` to `to`, log-spaced), refined by an integer factor
//! when their spacing exceeds the options' `sweep_step_ln` ([`SWEEP_STEP_LN`] by default,
//! [`CHART_SWEEP_STEP_LN`] for charts), and extended with the same step up
//! to full contact. Without adhesion the mean gap at every requested point then comes from one
//! cumulative pass over that table of U (physics.md §5; [`crate::theory::gap::GapTable`]);
//! with adhesion each row's branches are mapped onto one adhesionless table of the scene from
//! the first load (the gap at the load each branch's contact carries, physics.md §5.1;
//! [`crate::theory::gap::DryGap`]); nothing is evaluated twice. A 64-point chart
//! sweep of system 1 from p* = 1e-3 to 1 costs 64 + 13 engine evaluations.
//!
//! The loads run in parallel (rayon) in a fixed pattern ([`crate::theory::loads`]: a full
//! branch scan every few loads, the root tracked in between), so a sweep gives the same
//! numbers, bit for bit, on any number of threads. With adhesion each load reports every
//! branch: `a_r` is the loading branch (the lowest stable one), `a_r_unloading` the unloading
//! branch where a hysteresis window makes it distinct, and the window's edges — the jump-in
//! and pull-off loads ([`crate::theory::window`]) — are refined by bisection where the
//! sweep's grid holds them.
//!
//! Cancellation: the caller may pass an `AtomicBool`; when it is set the sweep stops between
//! evaluations and returns [`Error::Cancelled`].

use crate::error::{Error, Field, Result};
use crate::input::scene::{Scene, PRESSURE_RANGE};
use crate::theory::engine::Options;
use crate::theory::gap::{self, GapTable};
use crate::theory::window;
use serde::Serialize;
use std::sync::atomic::AtomicBool;

pub use crate::theory::engine::{CHART_SWEEP_STEP_LN, SWEEP_STEP_LN};

/// The load range of a sweep (reduced pressures, log-spaced).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepSpec {
    /// First p*.
    pub from: f64,
    /// Last p* (≥ from; equal only with one point).
    pub to: f64,
    /// Number of points (≥ 1).
    pub points: usize,
}

/// Allowed number of points of any sweep (loads, a knob, a reference): one range everywhere.
pub const SWEEP_POINTS_RANGE: (usize, usize) = (1, 100_000);

/// [`Error::Invalid`] for [`Field::SweepPoints`] outside [`SWEEP_POINTS_RANGE`].
pub(crate) fn check_points(points: usize) -> Result<()> {
    if (SWEEP_POINTS_RANGE.0..=SWEEP_POINTS_RANGE.1).contains(&points) {
        Ok(())
    } else {
        Err(Error::invalid(
            Field::SweepPoints,
            points as f64,
            crate::error::Range::whole(SWEEP_POINTS_RANGE.0 as f64, SWEEP_POINTS_RANGE.1 as f64),
        ))
    }
}

impl SweepSpec {
    /// The sweep of the same range `ratio` times finer: row k of this one is row ratio·k of it
    /// (the reference of [`Sweep::max_errors_against`]).
    pub fn refined(&self, ratio: usize) -> SweepSpec {
        SweepSpec {
            points: ratio * (self.points - 1) + 1,
            ..*self
        }
    }

    /// Checks the range against the engine's pressure range.
    pub fn validate(&self) -> Result<()> {
        let allowed = format!("{:e} <= p* <= {:e}", PRESSURE_RANGE.0, PRESSURE_RANGE.1);
        for (field, v) in [(Field::SweepFrom, self.from), (Field::SweepTo, self.to)] {
            if !(v >= PRESSURE_RANGE.0 && v <= PRESSURE_RANGE.1) {
                return Err(Error::invalid(field, v, allowed.clone()));
            }
        }
        check_points(self.points)?;
        if self.points > 1 && self.to <= self.from {
            return Err(Error::invalid(
                Field::SweepTo,
                self.to,
                format!(
                    "a p* above the first load {} (or a single point)",
                    crate::error::fmt_value(self.from)
                ),
            ));
        }
        Ok(())
    }

    /// The requested loads.
    pub fn pressures(&self) -> Vec<f64> {
        if self.points == 1 {
            return vec![self.from];
        }
        let (a, b) = (self.from.ln(), self.to.ln());
        (0..self.points)
            .map(|i| (a + (b - a) * i as f64 / (self.points - 1) as f64).exp())
            .collect()
    }
}

/// One load of a sweep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SweepRow {
    /// p*.
    pub p: f64,
    /// a_r(q_s).
    pub a_r: f64,
    /// ū/h_rms.
    pub mean_gap_rel: f64,
    /// ū (m).
    pub mean_gap: f64,
    /// σ̄_c* (reduced by E*ḡ).
    pub mean_contact_stress: f64,
    /// U (J/m²) [S-11].
    pub elastic_energy: f64,
    /// Whether the engine converged at this load.
    pub converged: bool,
    /// U* = U/(E*ḡh_rms).
    pub elastic_energy_reduced: f64,
    /// Estimated absolute quadrature error of ū/h_rms.
    pub mean_gap_error: f64,
    /// ⟨δσ_c²⟩* (reduced by (E*ḡ)²).
    pub contact_stress_variance: f64,
    /// Lower bound of ū/h_rms on loading (the reversible route made admissible; physics.md
    /// §5.1); equal to `mean_gap_rel` without adhesion up to quadrature error.
    pub mean_gap_lower_rel: f64,
    /// a_r of the unloading branch where it differs from the loading one (inside a hysteresis
    /// window); NaN (`null`) elsewhere. The loading curve is `a_r`; the unloading curve is
    /// `a_r_unloading` where given, else `a_r`.
    pub a_r_unloading: f64,
    /// Number of solutions at this load (1 without adhesion or hysteresis, 3 inside a window:
    /// loading, unstable, unloading; 0 where the solver did not converge).
    pub branches: usize,
    /// Upper end of the gap's bracket: the adhesionless gap ū₀(p*)/h_rms at the same load
    /// (physics.md §5.1); equal to `mean_gap_rel` without adhesion.
    pub mean_gap_upper_rel: f64,
    /// p_c* of the loading branch: the net force its contact carries per nominal area, at which
    /// its gap is the adhesionless one (p* without adhesion).
    pub contact_load: f64,
    /// ū/h_rms of the unloading branch where it differs from the loading one (inside a
    /// hysteresis window); NaN (`null`) elsewhere.
    pub mean_gap_unloading_rel: f64,
    /// Its estimated absolute error; NaN as `mean_gap_unloading_rel`.
    pub mean_gap_unloading_error: f64,
    /// Lower end of its bracket (its upper end is `mean_gap_upper_rel`); NaN as
    /// `mean_gap_unloading_rel`.
    pub mean_gap_unloading_lower_rel: f64,
    /// p_c* of the unloading branch; NaN as `mean_gap_unloading_rel`.
    pub contact_load_unloading: f64,
}

impl SweepRow {
    /// The row of a load whose solver did not converge: every number empty (NaN, `null` in
    /// JSON), `converged` false.
    pub fn empty(p: f64) -> SweepRow {
        SweepRow {
            p,
            a_r: f64::NAN,
            mean_gap_rel: f64::NAN,
            mean_gap: f64::NAN,
            mean_contact_stress: f64::NAN,
            elastic_energy: f64::NAN,
            converged: false,
            elastic_energy_reduced: f64::NAN,
            mean_gap_error: f64::NAN,
            contact_stress_variance: f64::NAN,
            mean_gap_lower_rel: f64::NAN,
            a_r_unloading: f64::NAN,
            branches: 0,
            mean_gap_upper_rel: f64::NAN,
            contact_load: f64::NAN,
            mean_gap_unloading_rel: f64::NAN,
            mean_gap_unloading_error: f64::NAN,
            mean_gap_unloading_lower_rel: f64::NAN,
            contact_load_unloading: f64::NAN,
        }
    }
}

/// The result of a sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sweep {
    /// One row per requested load, in increasing p*.
    pub rows: Vec<SweepRow>,
    /// Number of engine evaluations spent (requested loads + refinement + extension).
    pub evaluations: usize,
    /// p* at which the contact is full (the top of the gap grid).
    pub full_contact_pressure: f64,
    /// Whether every monotonicity the physics implies held (a_r increasing, ū decreasing)
    /// over the rows with numbers; false flags a branch change (e.g. an adhesive jump).
    pub monotone: bool,
    /// Requested loads whose solver did not converge (their rows are null).
    pub failed_loads: Vec<f64>,
    /// One entry per row: why the row is empty (the solver's error on one line), None for a
    /// converged row. Front ends print it beside the row.
    #[serde(skip)]
    pub reasons: Vec<Option<String>>,
    /// What failed and what it means for the other rows; absent when every load converged.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// The part of `note` that concerns the mean gap alone: why rows with a_r have no ū (a gap
    /// table that cannot be built, loads that are not one stable branch); None when every
    /// converged row has its gap.
    #[serde(skip)]
    pub gap_note: Option<String>,
    /// p* above which the loading branch no longer exists (the jump into contact on loading),
    /// where the sweep's range holds a hysteresis window's upper edge; to
    /// the options' `edge_rel` ([`crate::theory::window::EDGE_REL`] by default).
    pub jump_in_pressure: Option<f64>,
    /// p* below which the unloading branch no longer exists (pull-off on unloading), where
    /// the range holds the window's lower edge.
    pub pull_off_pressure: Option<f64>,
}

impl Sweep {
    /// Largest relative errors of a_r and ū (where ū > 1e-3 h_rms) of this sweep against a
    /// sweep of the same range `ratio` times finer (row k here is row ratio·k of `fine`).
    pub fn max_errors_against(&self, fine: &Sweep, ratio: usize) -> (f64, f64) {
        let rel = |a: f64, b: f64| if b == 0.0 { a.abs() } else { (a / b - 1.0).abs() };
        let (mut ea, mut eg) = (0.0f64, 0.0f64);
        for (k, r) in self.rows.iter().enumerate() {
            let f = &fine.rows[ratio * k];
            ea = ea.max(rel(r.a_r, f.a_r));
            if f.mean_gap_rel > 1e-3 {
                eg = eg.max(rel(r.mean_gap_rel, f.mean_gap_rel));
            }
        }
        (ea, eg)
    }
}

pub use crate::theory::loads::{energies, evaluate_node, evaluations, node_results};

/// `text` on one line (line breaks become "; ").
pub fn one_line(text: &str) -> String {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ")
}

/// Runs a sweep (see the module docs).
///
/// # Errors
/// [`Error::Invalid`] for a spec out of range ([`SweepSpec::validate`]) or options out of
/// range; [`Error::Cancelled`] when `cancel` is set. A load whose solve does not converge is
/// kept as a row marked unconverged (and listed in [`Sweep::failed_loads`]), not an error.
///
/// # Examples
/// ```
/// use asperity::input::preset::Preset;
/// use asperity::theory::engine::Options;
/// use asperity::theory::sweep::{sweep, SweepSpec};
///
/// let scene = Preset::resolve("system-1").unwrap().scene().unwrap().without_adhesion();
/// let spec = SweepSpec { from: 1e-3, to: 0.1, points: 5 };
/// let sw = sweep(&scene, &spec, &Options::default(), None).unwrap();
/// assert_eq!(sw.rows.len(), 5);
/// // more load, more contact and a smaller gap
/// assert!(sw.rows.windows(2).all(|w| w[1].a_r > w[0].a_r && w[1].mean_gap_rel < w[0].mean_gap_rel));
/// ```
pub fn sweep(scene: &Scene, spec: &SweepSpec, opts: &Options, cancel: Option<&AtomicBool>) -> Result<Sweep> {
    crate::work::start();
    spec.validate()?;
    let mut s0 = scene.clone();
    s0.pressure = spec.from;
    s0.validate()?;
    let SweepGrid { ps, step, m, p_full } = SweepGrid::new(scene, spec, opts);
    let n = ps.len();
    let evs = node_results(scene, &ps, opts, cancel)?;
    let unit = crate::theory::energy::energy_unit(scene);
    // the hysteresis window: the first run of grid loads with two stable branches, each edge
    // inside the grid refined by bisection between its two grid loads
    let branches: Vec<Option<&[_]>> = evs
        .iter()
        .map(|e| e.as_ref().ok().map(|e| e.branches.as_slice()))
        .collect();
    let window = window::window_on_branches(scene, &ps, &branches, &opts.adhesion, opts.edge_rel, cancel)?;
    let (jump_in_pressure, pull_off_pressure) = (window.jump_in_pressure, window.pull_off_pressure);
    // the mean gap (physics.md §5.1): without adhesion the energy route on this grid's own
    // table; with adhesion the load each branch's contact carries on the adhesionless table of the scene
    let (gaps, gap_note) = if scene.is_adhesive() {
        adhesive_gaps(scene, spec.from, &ps, m, &evs, opts, cancel)?
    } else {
        dry_sweep_gaps(scene, &ps, step, &evs, unit)?
    };
    let h_rms = scene.spectrum.rms_height();
    let mut failed_loads = Vec::new();
    let reasons: Vec<Option<String>> = (0..spec.points)
        .map(|k| evs[k * m].as_ref().err().map(|e| one_line(&e.to_string())))
        .collect();
    let rows: Vec<SweepRow> = (0..spec.points)
        .map(|k| {
            let i = k * m;
            match &evs[i] {
                Ok(e) => converged_row(ps[i], e, gaps[i], h_rms, unit),
                Err(_) => {
                    failed_loads.push(ps[i]);
                    SweepRow::empty(ps[i])
                }
            }
        })
        .collect();
    let note = failure_note(scene, &ps, &evs);
    let note = match (note, gap_note.clone()) {
        (Some(a), Some(b)) => Some(format!("{a}; {b}")),
        (a, b) => a.or(b),
    };
    let monotone = is_monotone(&rows);
    Ok(Sweep {
        rows,
        evaluations: n,
        full_contact_pressure: p_full,
        monotone,
        failed_loads,
        reasons,
        note,
        gap_note,
        jump_in_pressure,
        pull_off_pressure,
    })
}

/// The loads a sweep evaluates: one uniform grid in ln p* through the requested points,
/// refined by an integer factor m where their spacing exceeds the options' `sweep_step_ln`,
/// and extended with the same step to full contact (and to 9 loads at least) for the gap
/// table (module docs).
struct SweepGrid {
    /// The grid's loads: requested point k is load k·m, exactly as [`SweepSpec::pressures`]
    /// computes it.
    ps: Vec<f64>,
    /// The grid's step in ln p*.
    step: f64,
    /// The refinement factor m.
    m: usize,
    /// p* of full contact ([`gap::full_contact_pressure`]).
    p_full: f64,
}

impl SweepGrid {
    fn new(scene: &Scene, spec: &SweepSpec, opts: &Options) -> SweepGrid {
        let x0 = spec.from.ln();
        let (step, m) = if spec.points > 1 {
            let hs = (spec.to / spec.from).ln() / (spec.points - 1) as f64;
            let m = (hs / opts.sweep_step_ln).ceil().max(1.0) as usize;
            (hs / m as f64, m)
        } else {
            (gap::GAP_STEP_LN, 1)
        };
        let p_full = gap::full_contact_pressure(scene);
        let last_req = (spec.points - 1) * m;
        let x_top = p_full.ln().max(spec.to.ln());
        let mut n = last_req + 1;
        while x0 + (n - 1) as f64 * step < x_top - 1e-12 || n < 9 {
            n += 1;
        }
        let requested = spec.pressures();
        let ps: Vec<f64> = (0..n)
            .map(|i| {
                if i % m == 0 && i / m < spec.points {
                    // requested points exactly as the spec computes them
                    requested[i / m]
                } else {
                    (x0 + i as f64 * step).exp()
                }
            })
            .map(|p: f64| p.min(PRESSURE_RANGE.1))
            .collect();
        SweepGrid { ps, step, m, p_full }
    }
}

/// Per grid load, the mean gap of each branch with adhesion: the load its contact carries on
/// one adhesionless table of the scene from `p_lo` (physics.md §5.1), at the requested loads
/// only (every m-th); a table that cannot be built leaves every row without a gap and says
/// why in the note.
fn adhesive_gaps(
    scene: &Scene,
    p_lo: f64,
    ps: &[f64],
    m: usize,
    evs: &[Result<crate::theory::engine::Evaluation>],
    opts: &Options,
    cancel: Option<&AtomicBool>,
) -> Result<(NodeGaps, Option<String>)> {
    let n = ps.len();
    match gap::DryGap::new_cancellable(scene, p_lo, opts, cancel) {
        Ok(dry) => {
            let gaps = (0..n)
                .map(|i| match &evs[i] {
                    Ok(e) if i % m == 0 => gap::branch_gaps(&dry, ps[i], e).ok(),
                    _ => None,
                })
                .collect();
            Ok((gaps, None))
        }
        Err(Error::Cancelled) => Err(Error::Cancelled),
        Err(e) => Ok((vec![None; n], Some(format!("mean gap unavailable: {e}")))),
    }
}

/// The row of a converged load at p*: the evaluation's statistics with the loading branch's
/// gap (and the unloading branch's, where a hysteresis window makes it distinct); a gap that
/// is unknown leaves its columns NaN.
fn converged_row(
    p: f64,
    e: &crate::theory::engine::Evaluation,
    gaps: Option<(gap::BranchGap, Option<gap::BranchGap>)>,
    h_rms: f64,
    unit: f64,
) -> SweepRow {
    let nan = f64::NAN;
    let (l, u) = gaps.unwrap_or((
        gap::BranchGap {
            relative: nan,
            error: nan,
            lower: nan,
            upper: nan,
            contact_load: nan,
        },
        None,
    ));
    let un = |f: fn(&gap::BranchGap) -> f64| u.as_ref().map_or(nan, f);
    SweepRow {
        p,
        a_r: e.stats.a_r,
        mean_gap_rel: l.relative,
        mean_gap: l.relative * h_rms,
        mean_contact_stress: e.stats.mean_contact_stress,
        elastic_energy: e.elastic_energy,
        converged: true,
        elastic_energy_reduced: e.elastic_energy / unit,
        mean_gap_error: l.error,
        contact_stress_variance: e.stats.contact_stress_variance,
        mean_gap_lower_rel: l.lower,
        a_r_unloading: e.unloading_a_r.unwrap_or(f64::NAN),
        branches: e.branches.len().max(1),
        mean_gap_upper_rel: l.upper,
        contact_load: l.contact_load,
        mean_gap_unloading_rel: un(|b| b.relative),
        mean_gap_unloading_error: un(|b| b.error),
        mean_gap_unloading_lower_rel: un(|b| b.lower),
        contact_load_unloading: un(|b| b.contact_load),
    }
}

/// What failed and what it means for the other rows: how many grid loads did not converge,
/// the first one's error, and without adhesion that the gap (which integrates over every load
/// above) is unknown at and below the highest of them; None when every load converged.
fn failure_note(scene: &Scene, ps: &[f64], evs: &[Result<crate::theory::engine::Evaluation>]) -> Option<String> {
    let n = ps.len();
    evs.iter().rposition(|e| e.is_err()).map(|f| {
        let first_err = evs
            .iter()
            .find_map(|e| e.as_ref().err())
            .map(|e| e.to_string())
            .unwrap_or_default();
        // without adhesion the gap integrates over every load above; with adhesion each row's
        // gap is its own state's
        let below = if scene.is_adhesive() {
            String::new()
        } else {
            format!(
                ", and the mean gap is unknown at and below p* = {:.6e}, the highest of them",
                ps[f]
            )
        };
        format!(
            "{} of {} loads did not converge (the first: {first_err}); their rows are empty (null){below}",
            evs.iter().filter(|e| e.is_err()).count(),
            n,
        )
    })
}

/// Whether a_r rises and ū falls (where both rows have one) over the rows with numbers.
fn is_monotone(rows: &[SweepRow]) -> bool {
    let finite: Vec<&SweepRow> = rows.iter().filter(|r| r.a_r.is_finite()).collect();
    finite.windows(2).all(|w| {
        w[1].a_r >= w[0].a_r
            && (!w[0].mean_gap_rel.is_finite()
                || !w[1].mean_gap_rel.is_finite()
                || w[1].mean_gap_rel <= w[0].mean_gap_rel)
    })
}

/// Per grid load, the gap of the loading branch and of the unloading one where distinct (None
/// where unknown).
type NodeGaps = Vec<Option<(gap::BranchGap, Option<gap::BranchGap>)>>;

/// Per grid load, the adhesionless mean gap by the energy route on the sweep's own table (see
/// the module docs), and a note where part of it is unknown: below the highest failed load,
/// or below a load where the stored energy falls (not one stable branch).
fn dry_sweep_gaps(
    scene: &Scene,
    ps: &[f64],
    step: f64,
    evs: &[Result<crate::theory::engine::Evaluation>],
    unit: f64,
) -> Result<(NodeGaps, Option<String>)> {
    let n = ps.len();
    let last_fail = evs.iter().rposition(|e| e.is_err());
    let mut first_ok = last_fail.map_or(0, |f| f + 1);
    let stored: Vec<f64> = evs
        .iter()
        .map(|e| e.as_ref().map_or(f64::NAN, |e| gap::stored_energy(scene, e) / unit))
        .collect();
    let mut gap_note = None;
    if n - first_ok >= 4 {
        if let Some(j) = gap::route::last_decrease(&stored[first_ok..]) {
            gap_note = Some(format!(
                "the stored elastic energy falls between p* = {:.6e} and {:.6e} (the loads are not one \
                 stable branch there): the mean gap is unknown at and below the first of them",
                ps[first_ok + j],
                ps[first_ok + j + 1]
            ));
            first_ok += j + 1;
        }
    }
    let mut gaps = vec![None; n];
    if n - first_ok >= 4 {
        // a gap table that cannot be built leaves the rows without a gap, as `run` does
        let table = match GapTable::from_energy(ps[first_ok].ln(), step, stored[first_ok..].to_vec()) {
            Ok(t) => t,
            Err(Error::Cancelled) => return Err(Error::Cancelled),
            Err(e) => {
                let why = format!("mean gap unavailable: {e}");
                return Ok((gaps, Some(gap_note.map_or(why.clone(), |g| format!("{g}; {why}")))));
            }
        };
        for i in first_ok..n {
            let g = table.gap[i - first_ok];
            gaps[i] = Some((
                gap::BranchGap {
                    relative: g,
                    error: table.error[i - first_ok],
                    lower: g,
                    upper: g,
                    contact_load: ps[i],
                },
                None,
            ));
        }
    }
    Ok((gaps, gap_note))
}

/// A sweep column `values` at p* by cubic Lagrange interpolation in ln p* on the four nearest
/// rows of `ps` (ascending); `None` outside [ps₀, ps_last], with fewer than four rows, or where
/// a neighbouring value is missing (NaN). A sweep's rows are ≤ [`SWEEP_STEP_LN`] apart, so for
/// a smooth column the error is O(h⁴) ≈ 5e-4 of its fourth derivative in ln p*: far below the
/// chart accuracy. Exact for cubics in ln p*.
pub fn interpolate_in_ln_p(ps: &[f64], values: &[f64], p: f64) -> Option<f64> {
    let n = ps.len().min(values.len());
    if n < 4 || !(p >= ps[0] && p <= ps[n - 1]) {
        return None;
    }
    let x = p.ln();
    let i = ps[..n].partition_point(|&q| q < p).clamp(2, n - 2);
    let idx = [i - 2, i - 1, i, i + 1];
    let mut sum = 0.0;
    for &a in &idx {
        let mut w = 1.0;
        for &b in &idx {
            if a != b {
                w *= (x - ps[b].ln()) / (ps[a].ln() - ps[b].ln());
            }
        }
        sum += w * values[a];
    }
    sum.is_finite().then_some(sum)
}
