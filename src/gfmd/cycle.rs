//! GFMD through the adhesive cycle: quasi-static loading, unloading, and tension to pull-off.
//!
//! One map, load control, every load warm-started from the relaxed gap of the previous one
//! (the path is what a slow experiment does):
//!
//! 1. **loading**: from first touch at p*₁ = `from`, log-spaced up to `to` (as
//!    [`super::sweep::run_sweep`]);
//! 2. **unloading**: the same loads back down to `from` (a plain unloading sweep, `from > to`,
//!    relaxes at `from` from first touch and steps down to `to`);
//! 3. **tension** (a cycle with adhesion): p* = 0, then −p*₁, −2p*₁, −4p*₁, … until the body
//!    leaves the substrate ([`super::fire::Relaxation::ContactLost`]: no equilibrium with contact at that
//!    load), then bisections between the last load held and the first one lost, each
//!    warm-started from the last state held (so the path stays monotone), until the bracket is
//!    [`PULL_OFF_REL`] of the pull-off wide (at most [`PULL_OFF_BISECTIONS`]).
//!
//! The pull-off pressure is the most tensile mean pressure the contact sustained, with the
//! bracket (first load lost, last load held). Without adhesion a rough contact holds no
//! tension: the cycle stops at the smallest load, and the pull-off pressure is 0 (a note
//! says so). Under load control a contact can also jump: on loading, the largest
//! d ln a_r / d ln p* between neighbouring loads above [`JUMP_SLOPE`] is reported as the
//! jump-in load, with its bracket (a smooth adhesionless contact has a slope ≤ ≈ 1.1, [S-18]).
//!
//! Without adhesion the minimum at every load is unique, so unloading retraces loading to the
//! solver tolerance (tested); with adhesion unloading keeps more contact than loading at the
//! same load (contact hysteresis; tested).

use super::distributed::comm::{Comm, Solo};
use super::sweep::{GfmdSweepRow, LoadMap, Walker};
use super::{prepare, GfmdOptions, GfmdSetup, Progress, Stage};
use crate::error::{Error, Field, Result};
use crate::surface::heightmap::Surface;
pub use crate::theory::cycle::PathBranch;
use crate::theory::cycle::{path_through_tension, TheoryCycle};
use crate::theory::engine::Options;
use crate::theory::sweep::{self, Sweep, SweepSpec};
use serde::Serialize;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// The pull-off bracket is bisected until its width is at most this fraction of the pull-off
/// pressure (or [`PULL_OFF_BISECTIONS`] bisections).
pub const PULL_OFF_REL: f64 = 0.03;
/// Most bisections of the pull-off bracket after the first load lost.
pub const PULL_OFF_BISECTIONS: usize = 12;
/// A loading step whose d ln a_r / d ln p* exceeds this is a jump-in.
pub const JUMP_SLOPE: f64 = 3.0;
/// The tensile steps stop (contact lost for certain) once |p| exceeds this × the theoretical
/// strength γ/ρ of the interaction; the limit is never reached in practice.
const TENSION_LIMIT: f64 = 2.0;

/// The path of a cycle or a one-way sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleSpec {
    /// First load p* (> 0).
    pub from: f64,
    /// Turning load p* (> 0): above `from` for a cycle or a loading sweep, below it for an
    /// unloading sweep.
    pub to: f64,
    /// Log-spaced loads between them (≥ 2, or 1 for a cycle at one load).
    pub points: usize,
    /// Load to `to`, unload back to `from` and on into tension until pull-off.
    pub cycle: bool,
}

impl CycleSpec {
    /// Checks the loads as a sweep's (p* range, points); a cycle needs `to ≥ from`.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming [`Field::SweepFrom`], [`Field::SweepTo`] or
    /// [`Field::SweepPoints`].
    pub fn validate(&self) -> Result<()> {
        self.rising().validate()?;
        if self.cycle && self.to < self.from {
            return Err(Error::invalid(
                Field::SweepTo,
                self.to,
                format!(
                    "a turning load p* >= the first load {} for a cycle",
                    crate::error::fmt_value(self.from)
                ),
            ));
        }
        if !self.cycle && self.points > 1 && self.to == self.from {
            return Err(Error::invalid(
                Field::SweepTo,
                self.to,
                "a p* other than the first load (or a single point)",
            ));
        }
        Ok(())
    }

    /// The loads in increasing order.
    pub(crate) fn rising(&self) -> SweepSpec {
        let (lo, hi) = if self.from <= self.to {
            (self.from, self.to)
        } else {
            (self.to, self.from)
        };
        SweepSpec {
            from: lo,
            to: hi,
            points: if lo == hi { 1 } else { self.points },
        }
    }
}

/// One measured load of a path.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CycleRow {
    /// `loading` or `unloading`.
    pub branch: PathBranch,
    /// The load's measurements (the columns of a GFMD sweep).
    #[serde(flatten)]
    pub row: GfmdSweepRow,
}

/// A GFMD load path on one map, with its pull-off and jump-in, and the theory's sweep on the
/// same map over the positive loads (both branches inside a hysteresis window).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GfmdCycle {
    /// The loads in the order visited (tensile loads lost are not rows).
    pub rows: Vec<CycleRow>,
    /// The most tensile p* the contact sustained (0 without adhesion; null when the path had
    /// no tensile part).
    pub pull_off_pressure: Option<f64>,
    /// (the first p* lost, the last p* held): the pull-off lies between them.
    pub pull_off_bracket: Option<[f64; 2]>,
    /// The load at which loading jumped into more contact (null: no jump).
    pub jump_in_pressure: Option<f64>,
    /// (the load before the jump, the load after it).
    pub jump_in_bracket: Option<[f64; 2]>,
    /// Why the pull-off is as reported (no adhesion, or the tension limit).
    pub note: Option<String>,
    /// Grid side N.
    pub grid: usize,
    /// Seed (null for a loaded map).
    pub seed: Option<u64>,
    /// The reduced system's invariants (null for a loaded map).
    pub reduction: Option<super::reduction::Reduction>,
    /// The theory's sweep on the map's discrete spectrum over the positive loads.
    pub theory: Option<Sweep>,
    /// The theory's path on the same scene: loading, unloading and on into tension at GFMD's
    /// tensile loads (p* = 0, −p₁, −2p₁, …) to the theory's own pull-off (its
    /// `pull_off_pressure`), or the reason it stops.
    pub theory_cycle: Option<TheoryCycle>,
    /// Why `theory` is null.
    pub theory_error: Option<String>,
    /// Total solver steps (tensile loads lost included).
    pub iterations: usize,
    /// Wall time (s).
    pub elapsed_s: f64,
    /// The map the path ran on (not serialised; null over MPI ranks, where no rank holds it
    /// whole).
    #[serde(skip)]
    pub surface: Option<Surface>,
}

/// The GFMD part of a path: its rows, pull-off and jump-in.
pub(crate) struct PathWalk {
    rows: Vec<CycleRow>,
    pull_off: PullOff,
    jump_in: (Option<f64>, Option<[f64; 2]>),
}

impl PathWalk {
    /// The cycle of these rows with the theory's sweep beside them (`theory`: the sweep or
    /// why it is missing) and the map's facts.
    pub(crate) fn into_cycle(
        self,
        theory: TheoryBeside,
        map: (usize, Option<u64>, Option<super::reduction::Reduction>),
        iterations: usize,
        t0: Instant,
    ) -> GfmdCycle {
        GfmdCycle {
            rows: self.rows,
            pull_off_pressure: self.pull_off.pressure,
            pull_off_bracket: self.pull_off.bracket,
            jump_in_pressure: self.jump_in.0,
            jump_in_bracket: self.jump_in.1,
            note: self.pull_off.note,
            grid: map.0,
            seed: map.1,
            reduction: map.2,
            theory: theory.0,
            theory_cycle: theory.1,
            theory_error: theory.2,
            iterations,
            elapsed_s: t0.elapsed().as_secs_f64(),
            surface: None,
        }
    }
}

/// Walks the path of `spec` (see the module docs) with `solver`, then reports the
/// [`Stage::Theory`] progress before the theory's sweep.
///
/// # Errors
/// As [`run_cycle`] for the GFMD part.
pub(crate) fn walk<M: LoadMap>(
    solver: &mut Walker<'_, M>,
    spec: &CycleSpec,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<PathWalk> {
    let loads = spec.rising().pressures();
    let mut rows: Vec<CycleRow> = Vec::new();
    let push = |rows: &mut Vec<CycleRow>, branch, row| rows.push(CycleRow { branch, row });
    let held = |r: Option<GfmdSweepRow>, p: f64| {
        r.ok_or_else(|| Error::NotConverged {
            solver: crate::error::Solver::Gfmd,
            reason: format!("contact lost at the compressive load p* = {p:e}"),
        })
    };
    if spec.cycle || spec.from <= spec.to {
        for &p in &loads {
            let row = held(solver.step(p, rows.len(), progress, cancel)?, p)?;
            push(&mut rows, PathBranch::Loading, row);
        }
    } else {
        let top = *loads.last().expect("at least one load");
        let row = held(solver.step(top, 0, progress, cancel)?, top)?;
        push(&mut rows, PathBranch::Loading, row);
    }
    let unloading = spec.cycle || spec.from > spec.to;
    if unloading {
        for &p in loads.iter().rev().skip(1) {
            let row = held(solver.step(p, rows.len(), progress, cancel)?, p)?;
            push(&mut rows, PathBranch::Unloading, row);
        }
    }
    let jump_in = jump_in(&rows);
    let mut pull_off = PullOff::default();
    if spec.cycle {
        pull_off = tension(solver, loads[0], &mut rows, progress, cancel)?;
    }
    if let Some(last) = rows.last().map(|r| r.row) {
        progress(
            rows.len(),
            Progress {
                stage: Stage::Theory,
                iteration: last.iterations,
                residual: last.residual,
                contact_fraction: last.a_r,
            },
        );
    }
    Ok(PathWalk {
        rows,
        pull_off,
        jump_in,
    })
}

/// Runs the path of `spec` on the map of `setup` (see the module docs), then the theory's sweep
/// on the same map over the positive loads. `progress` gets the row index with each report.
///
/// # Errors
/// [`Error::Invalid`] for a spec out of range; as [`super::run()`] for a load that does not
/// converge; [`Error::Cancelled`] when `cancel` is set.
pub fn run_cycle(
    setup: &GfmdSetup,
    spec: &CycleSpec,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<GfmdCycle> {
    spec.validate()?;
    opts.validate()?;
    let t0 = Instant::now();
    let (prep, cycle) = cycle_on(&Solo, (prepare(setup)?, setup), spec, opts, progress, cancel, t0)?;
    Ok(GfmdCycle {
        surface: Some(prep.surface),
        ..cycle
    })
}

/// The path of `spec` walked on `prep` (this rank's part of the map of `setup`, on `comm`),
/// with the theory beside it, which rank 0 evaluates (None elsewhere); `t0` is the start of the
/// run. Returns the map with the cycle.
pub(crate) fn cycle_on<M: LoadMap>(
    comm: &dyn Comm,
    (prep, setup): (M, &GfmdSetup),
    spec: &CycleSpec,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
    t0: Instant,
) -> Result<(M, GfmdCycle)> {
    let mut walker = Walker::new(comm, prep, opts);
    let path = walk(&mut walker, spec, progress, cancel)?;
    let rising = spec.rising();
    let theory = if comm.rank() == 0 {
        theory_sweep(walker.prep.theory_scene(rising.from), &rising, cancel)?
    } else {
        (None, None, None)
    };
    let (grid, reduction) = walker.prep.grid_and_reduction();
    let map = (grid, setup.surface.is_none().then_some(setup.seed), reduction);
    let cycle = path.into_cycle(theory, map, walker.iterations, t0);
    Ok((walker.prep, cycle))
}

/// The theory beside a path: its sweep over the positive loads on the map's scene, the sweep's
/// path continued into tension to the theory's pull-off
/// ([`crate::theory::cycle::path_through_tension`]), or why the sweep is missing.
pub(crate) type TheoryBeside = (Option<Sweep>, Option<TheoryCycle>, Option<String>);

/// The theory beside a path (see [`TheoryBeside`]). Where the tensile continuation fails the
/// theory's cycle stops at the smallest load and its note says why.
///
/// # Errors
/// [`Error::Cancelled`] only (any other failure is reported beside the rows).
pub(crate) fn theory_sweep(
    scene: Result<crate::input::scene::Scene>,
    rising: &SweepSpec,
    cancel: &AtomicBool,
) -> Result<TheoryBeside> {
    let sc = match scene {
        Ok(sc) => sc,
        Err(e) => return Ok((None, None, Some(e.to_string()))),
    };
    let opts = Options::default();
    let sw = match sweep::sweep(&sc, rising, &opts, Some(cancel)) {
        Err(Error::Cancelled) => return Err(Error::Cancelled),
        Ok(s) => s,
        Err(e) => return Ok((None, None, Some(e.to_string()))),
    };
    let cycle = match path_through_tension(&sw, &sc, &opts.adhesion, Some(cancel)) {
        Err(Error::Cancelled) => return Err(Error::Cancelled),
        Ok(c) => c,
        Err(e) => {
            let mut c = crate::theory::cycle::path(&sw);
            c.note = format!("the theory's continuation into tension failed: {e}");
            c
        }
    };
    Ok((Some(sw), Some(cycle), None))
}

/// The pull-off found by [`tension`].
#[derive(Debug, Default)]
struct PullOff {
    pressure: Option<f64>,
    bracket: Option<[f64; 2]>,
    note: Option<String>,
}

/// Steps from the smallest load `p1` into tension until contact is lost, then bisects the
/// bracket (module docs, step 3); appends the loads held to `rows`.
fn tension<M: LoadMap>(
    solver: &mut Walker<'_, M>,
    p1: f64,
    rows: &mut Vec<CycleRow>,
    progress: &mut dyn FnMut(usize, Progress),
    cancel: &AtomicBool,
) -> Result<PullOff> {
    let Some(strength) = solver.strength() else {
        return Ok(PullOff {
            pressure: Some(0.0),
            bracket: None,
            note: Some("no adhesion: a rough contact holds no tension (pull-off at p* = 0)".into()),
        });
    };
    // no contact holds beyond the theoretical strength γ/ρ
    let mut held = p1;
    let mut lost = None;
    let mut p = 0.0;
    while p >= -TENSION_LIMIT * strength {
        match solver.step(p, rows.len(), progress, cancel)? {
            Some(row) => {
                rows.push(CycleRow {
                    branch: PathBranch::Unloading,
                    row,
                });
                held = p;
                p = if p == 0.0 { -p1 } else { 2.0 * p };
            }
            None => {
                lost = Some(p);
                break;
            }
        }
    }
    let Some(mut lost) = lost else {
        return Ok(PullOff {
            pressure: Some(held),
            bracket: None,
            note: Some(format!(
                "contact held up to {TENSION_LIMIT} x the interaction's strength gamma/rho: no pull-off found"
            )),
        });
    };
    for _ in 0..PULL_OFF_BISECTIONS {
        if held - lost <= PULL_OFF_REL * held.abs() {
            break;
        }
        let mid = 0.5 * (held + lost);
        match solver.step(mid, rows.len(), progress, cancel)? {
            Some(row) => {
                rows.push(CycleRow {
                    branch: PathBranch::Unloading,
                    row,
                });
                held = mid;
            }
            None => lost = mid,
        }
    }
    Ok(PullOff {
        pressure: Some(held),
        bracket: Some([lost, held]),
        note: None,
    })
}

/// The steepest loading step above [`JUMP_SLOPE`]: its upper load and its bracket.
fn jump_in(rows: &[CycleRow]) -> (Option<f64>, Option<[f64; 2]>) {
    let loading: Vec<&GfmdSweepRow> = rows
        .iter()
        .filter(|r| r.branch == PathBranch::Loading)
        .map(|r| &r.row)
        .collect();
    let mut best: Option<(f64, [f64; 2])> = None;
    for w in loading.windows(2) {
        let (a, b) = (w[0], w[1]);
        if a.a_r <= 0.0 || b.a_r <= 0.0 || b.p <= a.p {
            continue;
        }
        let slope = (b.a_r / a.a_r).ln() / (b.p / a.p).ln();
        if slope > JUMP_SLOPE && best.is_none_or(|(s, _)| slope > s) {
            best = Some((slope, [a.p, b.p]));
        }
    }
    match best {
        Some((_, br)) => (Some(br[1]), Some(br)),
        None => (None, None),
    }
}
