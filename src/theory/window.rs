//! The hysteresis window of an adhesive scene in p*: the loads where two stable branches
//! coexist ([`crate::theory::adhesion`] finds every branch at a load), and its edges.
//!
//! On loading (p* rising from small values) the contact follows the lowest stable branch until
//! that branch ends at a fold, the **jump-in** load, and jumps to the upper branch. On
//! unloading it stays on the highest stable branch down to its own fold, the **pull-off**
//! load (below it only the lower branch is left), so between pull-off and jump-in the state
//! depends on the history. Both edges are found by bisection in ln p* on "two or more stable
//! branches at this load", to [`EDGE_REL`] in p* (or a caller's precision: [`edge_to`]).
//!
//! An edge is a fold: the branch that ends there meets the unstable branch, and near it
//! their roots C₁, C₂ of the self-consistency (`adhesion`) approach each other as
//! √|p* − p_fold| (the normal form of a fold), so (C₂ − C₁)² is linear in ln p* to first
//! order. Where the loads inside the window next to an edge are known ([`window_on_branches`],
//! [`window_around`]) the edge search therefore aims: the line through the last two inside
//! loads' (ln p*, (C₂ − C₁)²) crosses zero at a guess of the edge, and two loads `rel`
//! apart around the guess are solved side by side (rayon); when the first is inside and
//! the second outside, the edge lies between them and the search ends after one round.
//! Otherwise the bracket shrinks to whichever side failed, the new inside loads refine the
//! line, and the next round solves the bracket's thirds side by side (as does every round
//! without a guess) before aiming again. On system II, model 3, t·q_r = 0.1, 0.8 γ_s (chart
//! accuracy, edge to 3 %) the jump-in takes one or two rounds of two solves side by side,
//! where bisection takes three solves in a row (~60 ms).
//!
//! This module depends only on the adhesive solver, so that the sweep and the mean gap (which
//! place the loading branch's jump into contact) can use it; [`crate::theory::hysteresis`]
//! re-exports it and adds the window's edges in the other knobs.

use crate::error::Result;
use crate::input::scene::{Scene, PRESSURE_RANGE};
use crate::theory::adhesion::{self, AdhesionAccuracy, AdhesiveSolution, BranchState};
use serde::Serialize;
use std::sync::atomic::AtomicBool;

/// Relative precision of a window edge in p* (bisection in ln p*); a sweep's edges are
/// refined to its options' `edge_rel` instead (this by default, coarser for charts).
pub const EDGE_REL: f64 = crate::theory::engine::EDGE_REL;

/// The hysteresis window around a load (edges `None` where the window runs past the allowed
/// range of p*, or the sweep's range).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Window {
    /// p* below which the unloading branch no longer exists.
    pub pull_off_pressure: Option<f64>,
    /// p* above which the loading branch no longer exists.
    pub jump_in_pressure: Option<f64>,
}

/// The number of stable branches of `scene` at p*.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn stable_branches(scene: &Scene, p: f64, acc: &AdhesionAccuracy, cancel: Option<&AtomicBool>) -> Result<usize> {
    Ok(stable_count(&branches_at(scene, p, acc, cancel)?))
}

/// Every branch of `scene` at p* (a full root scan).
fn branches_at(scene: &Scene, p: f64, acc: &AdhesionAccuracy, cancel: Option<&AtomicBool>) -> Result<Vec<BranchState>> {
    let mut s = scene.clone();
    s.pressure = p;
    let acc = AdhesionAccuracy {
        explore_branches: true,
        ..*acc
    };
    Ok(adhesion::solve(&s, &acc, None, cancel)?.branches)
}

/// The pair of roots (C₁ < C₂, J/m²) that merges at `fold`, at a load with three or more
/// roots, and whether H rises through the lower one (see [`adhesion::pair_at`]).
fn fold_pair(branches: &[BranchState], gamma: f64, fold: Fold) -> Option<((f64, f64), bool)> {
    let mut c: Vec<f64> = branches.iter().map(|b| b.gamma_coarse * gamma).collect();
    if c.len() < 3 {
        return None;
    }
    c.sort_by(f64::total_cmp);
    let n = c.len();
    Some(match fold {
        Fold::Lower => ((c[0], c[1]), true),
        Fold::Upper => ((c[n - 2], c[n - 1]), false),
    })
}

/// The pair of `fold` at p*, tracked from `pair` at a nearby load ([`adhesion::pair_at`]),
/// at the self-consistency's counting tolerance.
fn pair_near(
    scene: &Scene,
    p: f64,
    pair: ((f64, f64), bool),
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<Option<((f64, f64), bool)>> {
    let mut s = scene.clone();
    s.pressure = p;
    Ok(adhesion::pair_at(&s, acc, pair.0, pair.1, cancel)?.map(|c| (c, pair.1)))
}

fn stable_count(branches: &[BranchState]) -> usize {
    branches.iter().filter(|b| b.stable).count()
}

/// Which edge of a window: the pair of roots that merges there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Fold {
    /// The lowest stable root meets the unstable one above it (jump-in).
    Lower,
    /// The highest stable root meets the unstable one below it (pull-off).
    Upper,
}

/// (C₂ − C₁)²/γ_s² of the pair of roots that merges at `fold`, at a load with three or more
/// roots (see the module docs).
fn pair_gap2(branches: &[BranchState], fold: Fold) -> Option<f64> {
    let mut c: Vec<f64> = branches.iter().map(|b| b.gamma_coarse).collect();
    if c.len() < 3 {
        return None;
    }
    c.sort_by(f64::total_cmp);
    let n = c.len();
    let d = match fold {
        Fold::Lower => c[1] - c[0],
        Fold::Upper => c[n - 1] - c[n - 2],
    };
    Some(d * d)
}

/// The zero of the line through the two known inside points (ln p*, (C₂ − C₁)²) nearest the
/// edge, on the outside side of the nearest (`dir`: +1 where the outside lies at larger p*).
fn fold_guess(known: &[(f64, f64)], dir: f64) -> Option<f64> {
    let mut k: Vec<(f64, f64)> = known.to_vec();
    // nearest the edge first
    k.sort_by(|a, b| (b.0 * dir).total_cmp(&(a.0 * dir)));
    let (&(x1, d1), &(x2, d2)) = (k.first()?, k.get(1)?);
    // the pair closes towards the edge: d falls from x2 to x1
    (d2 > d1 && (x1 - x2) * dir > 0.0).then(|| x1 + d1 * (x1 - x2) / (d2 - d1))
}

/// The edge between `inside` (≥ 2 stable branches) and `outside` (one): bisection in ln p*
/// to [`EDGE_REL`]; the geometric midpoint of the last bracket.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn edge(
    scene: &Scene,
    inside: f64,
    outside: f64,
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<f64> {
    edge_to(scene, inside, outside, acc, EDGE_REL, cancel)
}

/// [`edge`] to a relative precision `rel` in p* instead of [`EDGE_REL`].
///
/// # Errors
/// As [`adhesion::solve`].
pub fn edge_to(
    scene: &Scene,
    inside: f64,
    outside: f64,
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<f64> {
    bisect(inside, outside, true, rel, |p| stable_branches(scene, p, acc, cancel))
}

/// The edge between `inside` and `outside` (p*) to `rel` in p*, aimed by the fold's normal
/// form (module docs) from `known` inside loads (ln p*, (C₂ − C₁)²/γ_s²): rounds of two
/// solves side by side, around the guess or at the bracket's thirds. The geometric midpoint
/// of the last bracket.
fn edge_aimed(
    scene: &Scene,
    (inside, outside): (f64, f64),
    known: Vec<(f64, f64)>,
    fold: Fold,
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<f64> {
    let probe = |x: f64| -> Result<(bool, Option<f64>)> {
        let b = branches_at(scene, x.exp(), acc, cancel)?;
        Ok((stable_count(&b) >= 2, pair_gap2(&b, fold)))
    };
    let (mut a, mut b) = (inside.ln(), outside.ln());
    let dir = (b - a).signum();
    let mut known = known;
    let mut aim = true;
    // (the bracket is done at rel, give or take round-off of the pair's placement)
    while (b - a).abs() > rel * (1.0 + 1e-9) {
        let width = (b - a).abs();
        // two loads side by side: rel apart around the guess (clamped into the bracket: the
        // discrete H loses the pair a little before the normal form closes it), or at the
        // bracket's thirds after an aimed round that did not end the search
        let guess = fold_guess(&known, dir).filter(|_| aim && width > 2.0 * rel);
        let (t_lo, t_hi) = match guess {
            Some(g) => {
                let t = ((g - a) * dir - 0.5 * rel).clamp(0.1 * rel, width - 1.1 * rel);
                (t, t + rel)
            }
            None => (width / 3.0, 2.0 * width / 3.0),
        };
        aim = guess.is_none();
        let (lo, hi) = (a + t_lo * dir, a + t_hi * dir);
        let (rl, rh) = rayon::join(|| probe(lo), || probe(hi));
        let ((in_lo, d_lo), (in_hi, d_hi)) = (rl?, rh?);
        if in_lo {
            a = lo;
            known.extend(d_lo.map(|d| (lo, d)));
            if in_hi {
                a = hi;
                known.extend(d_hi.map(|d| (hi, d)));
            } else {
                b = hi;
            }
        } else {
            b = lo;
        }
    }
    Ok((0.5 * (a + b)).exp())
}

/// The edge between `inside` (p*, where the pair of roots `pair` of its fold exists) and
/// `outside`, to `rel` in p*: rounds of two loads side by side at the bracket's thirds, each
/// asking whether the pair persists, tracked from the nearest inside load
/// ([`adhesion::pair_at`]: 4–8 marches instead of a solve's 30–40 for every branch). The
/// geometric midpoint of the last bracket.
fn edge_tracked(
    scene: &Scene,
    (inside, outside): (f64, f64),
    pair: ((f64, f64), bool),
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<f64> {
    let (mut a, mut b) = (inside.ln(), outside.ln());
    let mut pair = pair;
    while (b - a).abs() > rel * (1.0 + 1e-9) {
        let (lo, hi) = (a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0);
        let (rl, rh) = rayon::join(
            || pair_near(scene, lo.exp(), pair, acc, cancel),
            || pair_near(scene, hi.exp(), pair, acc, cancel),
        );
        match (rl?, rh?) {
            (Some(_), Some(ph)) => {
                a = hi;
                pair = ph;
            }
            (Some(pl), None) => {
                a = lo;
                b = hi;
                pair = pl;
            }
            (None, _) => b = lo,
        }
    }
    Ok((0.5 * (a + b)).exp())
}

/// Bisection of a window edge between `inside` (`count` ≥ 2) and `outside`: in ln x when
/// `log` (to `rel` in x), else in x (to `rel` of the larger end); the midpoint of the last
/// bracket.
pub(crate) fn bisect(
    inside: f64,
    outside: f64,
    log: bool,
    rel: f64,
    mut count: impl FnMut(f64) -> Result<usize>,
) -> Result<f64> {
    let to = |x: f64| if log { x.ln() } else { x };
    let from = |y: f64| if log { y.exp() } else { y };
    let (mut a, mut b) = (to(inside), to(outside));
    let tol = if log {
        rel
    } else {
        rel * inside.abs().max(outside.abs())
    };
    while (a - b).abs() > tol {
        let m = 0.5 * (a + b);
        if count(from(m))? >= 2 {
            a = m;
        } else {
            b = m;
        }
    }
    Ok(from(0.5 * (a + b)))
}

/// The hysteresis window on an ascending grid of loads `ps` whose every branch was solved
/// (`stable[i]`: the number of stable branches at `ps[i]`, `None` where the solve failed):
/// the first run of loads with two or more stable branches, each edge that lies inside the
/// grid (its neighbour outside the run solved) refined to `rel` in rounds of two solves side
/// by side at the bracket's thirds, the two edges side by side (rayon); with the branches
/// themselves [`window_on_branches`] aims at the fold instead. A window that opens and closes
/// between two grid loads is not seen.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn window_on_grid(
    scene: &Scene,
    ps: &[f64],
    stable: &[Option<usize>],
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Window> {
    let none: Vec<Option<&[BranchState]>> = vec![None; stable.len()];
    window_of(scene, ps, stable, &none, acc, rel, cancel)
}

/// [`window_on_grid`] from every branch at each load (`None` where the solve failed): the
/// edges are aimed by the fold's normal form from the two inside loads next to each (module
/// docs), one round of two solves side by side where the guess holds.
///
/// # Errors
/// As [`adhesion::solve`].
pub fn window_on_branches(
    scene: &Scene,
    ps: &[f64],
    branches: &[Option<&[BranchState]>],
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Window> {
    let stable: Vec<Option<usize>> = branches.iter().map(|b| b.map(stable_count)).collect();
    window_of(scene, ps, &stable, branches, acc, rel, cancel)
}

fn window_of(
    scene: &Scene,
    ps: &[f64],
    stable: &[Option<usize>],
    branches: &[Option<&[BranchState]>],
    acc: &AdhesionAccuracy,
    rel: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Window> {
    let two = |i: usize| stable[i].is_some_and(|c| c >= 2);
    let mut w = Window {
        pull_off_pressure: None,
        jump_in_pressure: None,
    };
    let n = ps.len().min(stable.len());
    if let Some(first) = (0..n).find(|&i| two(i)) {
        let last = first + (first..n).take_while(|&i| two(i)).count() - 1;
        // the two inside loads next to an edge that know their pair of roots
        let known = |near: usize, far: Option<usize>, fold: Fold| -> Vec<(f64, f64)> {
            [Some(near), far.filter(|&f| two(f))]
                .into_iter()
                .flatten()
                .filter_map(|i| {
                    let d = branches.get(i).copied().flatten().and_then(|b| pair_gap2(b, fold))?;
                    Some((ps[i].ln(), d))
                })
                .collect()
        };
        let refine = |inside: usize, outside: Option<usize>, far: Option<usize>, fold: Fold| -> Result<Option<f64>> {
            match outside.filter(|&o| o < n && stable[o].is_some()) {
                Some(o) => edge_aimed(
                    scene,
                    (ps[inside], ps[o]),
                    known(inside, far, fold),
                    fold,
                    acc,
                    rel,
                    cancel,
                )
                .map(Some),
                None => Ok(None),
            }
        };
        let (pull_off, jump_in) = rayon::join(
            || refine(first, first.checked_sub(1), Some(first + 1), Fold::Upper),
            || refine(last, Some(last + 1), last.checked_sub(1), Fold::Lower),
        );
        w.pull_off_pressure = pull_off?;
        w.jump_in_pressure = jump_in?;
    }
    Ok(w)
}

/// Factor in p* of the steps outwards from a load inside a window to bracket its edges.
pub const WINDOW_STEP: f64 = 4.0;

/// The window around the scene's own load when it lies inside one (two stable branches),
/// else `None`: see [`window_around_from`], after a solve at p* that finds every branch.
///
/// # Errors
/// As [`adhesion::solve`]: [`crate::Error::NotConverged`] when a branch or an edge cannot
/// be resolved, [`crate::Error::Cancelled`].
///
/// # Examples
/// ```
/// use asperity::input::preset::Preset;
/// use asperity::theory::adhesion::AdhesionAccuracy;
/// use asperity::theory::window::window_around;
///
/// // system II, model 3, a thin slab (t·q_r = 0.1) at 0.8 γ_s and p* = 1e-5: two stable
/// // branches, between a pull-off below and a jump into contact above
/// let s = Preset::resolve("system-2").unwrap().scene().unwrap();
/// let s = s.with_model(asperity::input::model::Model::named(3).unwrap()).unwrap();
/// let g = 0.8 * s.surface_energy_j_m2();
/// let s = s.with_thickness_qr(0.1).unwrap().with_surface_energy_j_m2(g).unwrap().with_pressure(1e-5).unwrap();
/// let w = window_around(&s, &AdhesionAccuracy::default(), None).unwrap().unwrap();
/// assert!(w.jump_in_pressure.unwrap() > 1e-5);
/// assert!(w.pull_off_pressure.map_or(true, |p| p < 1e-5));
/// ```
pub fn window_around(scene: &Scene, acc: &AdhesionAccuracy, cancel: Option<&AtomicBool>) -> Result<Option<Window>> {
    if !scene.is_adhesive() {
        return Ok(None);
    }
    let all = AdhesionAccuracy {
        explore_branches: true,
        ..*acc
    };
    let at_p0 = adhesion::solve(scene, &all, None, cancel)?;
    window_around_from(scene, &at_p0, acc, cancel)
}

/// The window around the scene's own load from its solution `at_p0` (every branch found, as
/// `run`'s evaluation has it), `None` outside a window: steps outwards by factors of
/// [`WINDOW_STEP`] in p* while the pair of roots that merges at the edge persists (tracked
/// from the last load inside, [`adhesion::pair_at`]; where it is lost, a solve for every
/// branch decides), then the edge by rounds of two tracked loads side by side at the
/// bracket's thirds, to [`EDGE_REL`]. An edge is `None` where the window reaches the end of
/// the load range (`PRESSURE_RANGE`): in particular a pull-off that needs a tensile load (one
/// solve at that end says so).
///
/// # Errors
/// As [`adhesion::solve`].
pub fn window_around_from(
    scene: &Scene,
    at_p0: &AdhesiveSolution,
    acc: &AdhesionAccuracy,
    cancel: Option<&AtomicBool>,
) -> Result<Option<Window>> {
    let p0 = scene.pressure;
    if !scene.is_adhesive() || stable_count(&at_p0.branches) < 2 {
        return Ok(None);
    }
    let gamma = scene.gamma;
    let bound = |up: bool| -> Result<Option<f64>> {
        // the unloading branch of a strongly adhesive scene often holds at every positive load
        // (pull-off needs a tensile load): one solve at the end of the load range says so
        let end = if up { PRESSURE_RANGE.1 } else { PRESSURE_RANGE.0 };
        if stable_branches(scene, end, acc, cancel)? >= 2 {
            return Ok(None);
        }
        // loading ends at the lower pair's fold (above p0), unloading at the upper's
        let fold = if up { Fold::Lower } else { Fold::Upper };
        let Some(mut pair) = fold_pair(&at_p0.branches, gamma, fold) else {
            return Ok(None);
        };
        let mut inside = p0;
        loop {
            let next = if up { inside * WINDOW_STEP } else { inside / WINDOW_STEP };
            let next = if up { next.min(end) } else { next.max(end) };
            if next == end {
                return edge_tracked(scene, (inside, next), pair, acc, EDGE_REL, cancel).map(Some);
            }
            let tracked = match pair_near(scene, next, pair, acc, cancel)? {
                Some(p) => Some(p),
                // lost: a solve for every branch decides (the pair may have moved further
                // than the tracking reaches over a factor WINDOW_STEP)
                None => {
                    let b = branches_at(scene, next, acc, cancel)?;
                    if stable_count(&b) >= 2 {
                        fold_pair(&b, gamma, fold)
                    } else {
                        None
                    }
                }
            };
            match tracked {
                Some(p) => {
                    pair = p;
                    inside = next;
                }
                None => return edge_tracked(scene, (inside, next), pair, acc, EDGE_REL, cancel).map(Some),
            }
        }
    };
    // side by side: the pull-off's check at the bottom of the load range is the dearest solve
    let (pull_off, jump_in) = rayon::join(|| bound(false), || bound(true));
    Ok(Some(Window {
        pull_off_pressure: pull_off?,
        jump_in_pressure: jump_in?,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fold_guess_is_the_zero_of_the_line_through_the_two_nearest_loads() {
        // (C₂ − C₁)² = 2·(x_f − x) with x_f = 0.3: exact for any two points; a third, farther
        // point with another slope is ignored (the two nearest the edge count)
        let d2 = |x: f64| 2.0 * (0.3 - x);
        let known = [(-1.0, 9.0), (0.1, d2(0.1)), (-0.2, d2(-0.2))];
        let g = fold_guess(&known, 1.0).unwrap();
        assert!((g - 0.3).abs() < 1e-12, "{g}");
        // mirrored: the edge below the inside loads (pull-off), x_f = −0.3
        let up = |x: f64| 2.0 * (x + 0.3);
        let g = fold_guess(&[(0.5, up(0.5)), (0.1, up(0.1))], -1.0).unwrap();
        assert!((g + 0.3).abs() < 1e-12, "{g}");
        // a pair that opens towards the edge, or a single load: no guess
        assert_eq!(fold_guess(&[(0.1, 1.0), (0.2, 2.0)], 1.0), None);
        assert_eq!(fold_guess(&[(0.1, 1.0)], 1.0), None);
    }
}
