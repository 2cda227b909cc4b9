//! The theory along a load cycle: the branches of a load sweep ([`super::sweep`]) in the order
//! a quasi-static path visits them, as GFMD's cycle does ([`crate::gfmd::cycle`]).
//!
//! Loading from the smallest load up to the largest follows the loading branch (the lowest
//! stable root of §4 of physics.md, `a_r`); unloading back down stays on the unloading branch
//! (the highest stable root, `a_r_unloading`) while it exists, and where it ends (the
//! window's lower edge, the sweep's `pull_off_pressure`) the contact drops to the only
//! branch left. Below the smallest load the theory is not continued: its tensile
//! continuation (p* < 0, physics.md §6.2) is derived but not computed, and [`TheoryCycle::note`]
//! says so in one line.

use super::sweep::{Sweep, SweepRow};
use serde::Serialize;

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
             at p* <= 0, where the theory is not continued (docs/physics.md §6.2)"
        )
    } else {
        format!(
            "the theory is not continued below the smallest load p* = {lowest:e} into tension (docs/physics.md §6.2)"
        )
    };
    TheoryCycle {
        rows,
        unloading_branch_ends: sweep.pull_off_pressure,
        jump_in_pressure: sweep.jump_in_pressure,
        note,
    }
}
