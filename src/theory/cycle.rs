//! The theory along a load cycle: the branches of a load sweep ([`super::sweep`]) in the order
//! a quasi-static path visits them, as GFMD's cycle does ([`crate::gfmd::cycle`]).
//!
//! Loading from the smallest load up to the largest follows the loading branch (the lowest
//! stable root of §4 of physics.md, `a_r`); unloading back down stays on the unloading branch
//! (the highest stable root, `a_r_unloading`) while it exists, and where it ends (the
//! window's lower edge, the sweep's `pull_off_pressure`) the contact drops to the only
//! branch left. [`path_through_tension`] continues the path below the smallest load p₁ into
//! tension as GFMD's cycle does, p* = 0, −p₁, −2p₁, … ([`crate::theory::adhesion::pull_off`],
//! physics.md §6.2), to the theory's pull-off; [`path`] alone stops at p₁, and
//! [`TheoryCycle::note`] says in one line why the path ends where it does.

use super::adhesion::{pull_off, AdhesionAccuracy, TensilePullOff};
use super::engine::Options;
use super::sweep::{Sweep, SweepRow};
use crate::error::Result;
use crate::input::scene::Scene;
use serde::Serialize;
use std::sync::atomic::AtomicBool;

/// Relative precision of the theory's pull-off (GFMD's cycle bisects to the same 3 %).
pub const PULL_OFF_REL: f64 = 0.03;

/// Which way the load was moving when a row was measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum PathBranch {
    /// Rising load (from first touch).
    Loading,
    /// Falling load, through tension to pull-off.
    Unloading,
}

impl PathBranch {
    /// `loading` or `unloading`.
    pub fn name(self) -> &'static str {
        match self {
            PathBranch::Loading => "loading",
            PathBranch::Unloading => "unloading",
        }
    }
}

/// One load of the theory's path.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TheoryPathRow {
    /// Which way the load moves.
    pub branch: PathBranch,
    /// p*.
    pub p: f64,
    /// a_r of the branch the path is on.
    pub a_r: f64,
    /// ū/h_rms of that branch (null where it has none).
    pub mean_gap_rel: f64,
    /// σ̄_c* of that branch; null on the unloading branch inside a hysteresis window (the
    /// sweep reports σ̄_c* of the loading branch only).
    pub mean_contact_stress: f64,
    /// Whether the value is the theory's unloading branch (true) or its loading/only branch.
    pub on_unloading_branch: bool,
    /// On the unloading and tensile rows of [`path_through_tension`]: a_r of the pinned
    /// unloading branch from the path's top load ([`super::unloading`], physics.md §6.6);
    /// null on loading rows, below that branch's pull-off, and on bodies thicker than
    /// t·q_r = [`super::unloading::PINNED_THICKEST_QR`], where it was not measured to hold.
    pub a_r_unloading_pinned: Option<f64>,
}

/// The theory's path over a cycle's positive loads.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TheoryCycle {
    /// Loading rows (increasing p*), then unloading rows (decreasing p*).
    pub rows: Vec<TheoryPathRow>,
    /// The load below which the unloading branch no longer exists, where the range holds it
    /// (the theory's pull-off on the positive side); null otherwise.
    pub unloading_branch_ends: Option<f64>,
    /// The load above which the loading branch no longer exists (jump-in), where the range
    /// holds it.
    pub jump_in_pressure: Option<f64>,
    /// The theory's pull-off where the path was continued into tension: the most tensile p*
    /// its contact branch holds (≤ 0; 0 where no contact branch exists at p* = 0); null for
    /// [`path`] alone.
    pub pull_off_pressure: Option<f64>,
    /// (the first p* lost, the last p* held) around `pull_off_pressure`, as GFMD's
    /// `pull_off_bracket`.
    pub pull_off_bracket: Option<[f64; 2]>,
    /// The most tension any contact branch could hold, min(σ_a*(q_L; γ_s), γ_s/ρ) (the
    /// coarsest scale's Griffith stress, physics.md §6.2), where the path was continued.
    pub tension_bound: Option<f64>,
    /// Why the path stops where it does.
    pub note: String,
}

/// The theory's path over the loads of `sweep` (see the module docs): up, then down.
pub fn path(sweep: &Sweep) -> TheoryCycle {
    let load = |r: &SweepRow| TheoryPathRow {
        branch: PathBranch::Loading,
        p: r.p,
        a_r: r.a_r,
        mean_gap_rel: r.mean_gap_rel,
        mean_contact_stress: r.mean_contact_stress,
        on_unloading_branch: false,
        a_r_unloading_pinned: None,
    };
    let mut rows: Vec<TheoryPathRow> = sweep.rows.iter().map(load).collect();
    for r in sweep.rows.iter().rev().skip(1) {
        let unloading = r.a_r_unloading.is_finite();
        rows.push(if unloading {
            TheoryPathRow {
                branch: PathBranch::Unloading,
                p: r.p,
                a_r: r.a_r_unloading,
                mean_gap_rel: r.mean_gap_unloading_rel,
                mean_contact_stress: f64::NAN,
                on_unloading_branch: true,
                a_r_unloading_pinned: None,
            }
        } else {
            TheoryPathRow {
                branch: PathBranch::Unloading,
                ..load(r)
            }
        });
    }
    let lowest = sweep.rows.first().map_or(f64::NAN, |r| r.p);
    let still_unloading = sweep.rows.first().is_some_and(|r| r.a_r_unloading.is_finite());
    let note = if still_unloading {
        format!(
            "the theory's unloading branch still exists at the smallest load p* = {lowest:e}: its pull-off lies below, \
             at p* <= 0, beyond this path (the path through tension continues it: docs/physics.md §6.2)"
        )
    } else {
        format!(
            "this path stops at the smallest load p* = {lowest:e} (the path through tension continues it: docs/physics.md §6.2)"
        )
    };
    TheoryCycle {
        rows,
        unloading_branch_ends: sweep.pull_off_pressure,
        jump_in_pressure: sweep.jump_in_pressure,
        pull_off_pressure: None,
        pull_off_bracket: None,
        tension_bound: None,
        note,
    }
}

/// [`path`] continued into tension (see the module docs): after the unloading rows, the
/// contact branch of `scene` (the sweep's scene) at p* = 0, −p₁, −2p₁, … down to its pull-off,
/// p₁ the sweep's smallest load; the mean gap is not defined there (null).
///
/// # Errors
/// As [`pull_off`].
pub fn path_through_tension(
    sweep: &Sweep,
    scene: &Scene,
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<TheoryCycle> {
    let mut cycle = path(sweep);
    let Some(p1) = sweep.rows.first().map(|r| r.p) else {
        return Ok(cycle);
    };
    if scene.gamma <= 0.0 {
        add_pinned(&mut cycle, sweep, scene, acc);
        cycle.pull_off_pressure = Some(0.0);
        cycle.note =
            "without adhesion the contact holds no tension: the theory's path ends at p* -> 0 (pull-off 0)".into();
        return Ok(cycle);
    }
    let po = pull_off(scene, p1, PULL_OFF_REL, acc, cancel)?;
    cycle.rows.extend(po.path.iter().map(|s| TheoryPathRow {
        branch: PathBranch::Unloading,
        p: s.pressure,
        a_r: s.a_r,
        mean_gap_rel: f64::NAN,
        mean_contact_stress: s.mean_contact_stress,
        on_unloading_branch: true,
        a_r_unloading_pinned: None,
    }));
    add_pinned(&mut cycle, sweep, scene, acc);
    cycle.note = tension_note(&po);
    cycle.pull_off_pressure = Some(po.pressure);
    cycle.pull_off_bracket = Some([po.lost, po.pressure]);
    cycle.tension_bound = Some(po.bound);
    Ok(cycle)
}

/// The pinned unloading branch's a_r on the path's unloading and tensile rows, from the top
/// of the sweep (its largest load and the loading a_r there).
fn add_pinned(cycle: &mut TheoryCycle, sweep: &Sweep, scene: &Scene, acc: &AdhesionAccuracy) {
    let Some(top) = sweep.rows.last() else {
        return;
    };
    let opts = Options {
        adhesion: *acc,
        ..Options::default()
    };
    let down: Vec<usize> = (0..cycle.rows.len())
        .filter(|&i| cycle.rows[i].branch == PathBranch::Unloading)
        .collect();
    let loads: Vec<f64> = down.iter().map(|&i| cycle.rows[i].p).collect();
    let a = super::unloading::pinned_on_path(scene, top.p, top.a_r, &loads, &opts);
    for (&i, v) in down.iter().zip(a) {
        cycle.rows[i].a_r_unloading_pinned = v.is_finite().then_some(v);
    }
}

/// One line on where the tensile path ended and why.
fn tension_note(po: &TensilePullOff) -> String {
    if po.path.is_empty() {
        format!(
            "the theory has no contact branch at p* = 0: its contact ends at p* -> 0+ (a_r falls to zero with the load), \
             so its pull-off is 0 (no tension held; the most any contact branch could hold is {:.3e}, docs/physics.md §6.2)",
            po.bound
        )
    } else {
        format!(
            "the theory's contact branch holds tension down to p* = {:.3e} (lost at {:.3e}); no contact branch can hold \
             more than {:.3e}, the coarsest scale's Griffith stress; the mean gap is not defined under tension \
             (docs/physics.md §6.2)",
            po.pressure, po.lost, po.bound
        )
    }
}
