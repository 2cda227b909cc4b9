//! Whether the pair of roots of H that merges at a fold (an edge of a hysteresis window,
//! `theory::window`) still exists at a load, tracked from where the pair was at a nearby load.
//!
//! Near a fold two roots of H(C) (`shooting`), one where H rises and one where it falls,
//! approach each other and vanish. Each is re-bracketed next to its old C as a warm solve does
//! (`roots::warm_bracket`), without refining it: the pair exists when both sign changes are
//! found, in order, and then the scene has at least two stable branches (H < 0 at the lowest
//! C and > 0 at the highest, so a rising root lies beyond a falling one on either side). A
//! solve that finds every branch costs 30–40 marches at a thin slab's fold; this 4–8.

use super::grid::build_grid;
use super::propagator::Marcher;
use super::roots::{warm_bracket, WARM_MAX};
use super::shooter::{check_bounded, Scale, Shooter};
use super::walls::WallCoefficients;
use super::AdhesionAccuracy;
use crate::error::{Error, Result};
use crate::input::scene::Scene;
use std::sync::atomic::{AtomicBool, Ordering};

/// The pair of roots (C₁ < C₂, J/m²) of `scene` next to `pair`, the pair at a nearby load;
/// `rising_first`: H rises through the lower root (the lower fold of a window, where the
/// loading branch ends) or falls through it (the upper fold, where the unloading branch
/// ends). `None` where either sign change is not found within the warm reach (a factor ~3 in
/// C) or they come out of order: the pair has merged. The returned C are the linear zeros of
/// H in the brackets (to the bracket's width, a few per cent).
///
/// # Errors
/// [`Error::Invalid`] for a bad scene, [`Error::Cancelled`], and [`Error::NotConverged`]
/// where a march needs a grid beyond its bound.
pub fn pair_at(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    pair: (f64, f64),
    rising_first: bool,
    cancel: Option<&AtomicBool>,
) -> Result<Option<(f64, f64)>> {
    let grid = build_grid(scene, acc.steps_per_ln_q);
    let mut s = Shooter {
        m: Marcher::new(scene, &grid, *acc),
        coef: WallCoefficients::new(scene, &grid),
        shots: 0,
    };
    let gs = scene.gamma;
    let i_full = s.m.full_energy();
    let e0 = if grid.e_scale > 0.0 { grid.e_scale } else { i_full }.max(1e-300);
    // the root scan's variable (`roots::find_roots`)
    let scale = Scale { c0: 1e-3 * e0.min(gs) };
    let (w_lo, w_hi) = (scale.w(-i_full), scale.w(gs));
    let mut found = Vec::with_capacity(2);
    for (c, rising) in [(pair.0, rising_first), (pair.1, !rising_first)] {
        if cancel.is_some_and(|f| f.load(Ordering::Relaxed)) {
            return Err(Error::Cancelled);
        }
        let w0 = scale.w(c).clamp(w_lo, w_hi);
        match warm_bracket(&mut s, &scale, w0, rising, (w_lo, w_hi), WARM_MAX) {
            Some(br) => found.push(br),
            None => break,
        }
    }
    check_bounded(&s)?;
    if found.len() < 2 || found[0].2 > found[1].0 {
        return Ok(None);
    }
    // the linear zero of H in each bracket
    let zero = |(a, ha, b, hb): (f64, f64, f64, f64)| scale.c(a - ha * (b - a) / (hb - ha));
    Ok(Some((zero(found[0]), zero(found[1]))))
}
