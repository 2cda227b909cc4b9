//! How the grid stage of the march (`propagator`) moves the wall in one piece, before the
//! heat step: the grid x_j = (m + j)h with the wall at x = 0 (see `propagator::State`), the
//! wall to move by δ = σ_a*(end) − σ_a*(start) over a variance Δv ≈ W^{2α}(a_r)·b, i.e. at
//! the drift speed
//!
//! ```text
//! c = δ/Δv,   image weight e^{−2cy} on the odd extension (propagator's module docs)
//! ```
//!
//! - a wall running away from the distribution (c > 0) on a grid that starts at it: where
//!   2c·h > `REFINE_DRIFT` the weighted extension is not resolved, and the grid is refined
//!   (spacing halved, `regrid::refine`) unless the image carries a negligible mass
//!   ([`image_mass`] ≤ `IMAGE_NEGLIGIBLE`·a_r);
//! - a wall running away by more than `RUNAWAY_SPAN` spans of the grid with a negligible
//!   image leaves the distribution behind: the grid is offset by whole cells (m grows) and
//!   the heat step is free diffusion;
//! - a grid that does not start at the wall (m > 0): the wall moves by whole cells through m,
//!   the rest of a cell spectrally (the heat step's drift);
//! - a wall moving into the distribution (c < 0): half the shift now (`regrid::shift`), the
//!   other half after the heat step (Strang splitting, second order);
//! - no variance to move in (Δv = 0): the whole shift now.

use super::regrid::{refine, shift};

/// The largest 2c·h on a grid that starts at the wall: the image of a wall running away at
/// speed c is weighted by e^{−2cy}, which must not fall by more than e^{−2} per cell (finer:
/// the grid is refined). Measured on a prescribed σ_a ∝ √(q-onset) wall (system 1, model 1,
/// 24 steps per ln q, 10 points per width): a_r error 2.1e-4 without, 2e-7 with; 2c·h reached
/// 15 in the first onset piece.
const REFINE_DRIFT: f64 = 2.0;
/// The grid is refined no further than this many nodes.
const REFINE_MAX_NODES: usize = 1 << 16;
/// No refinement for [`REFINE_DRIFT`] where the image the refinement would resolve carries
/// less than this fraction of the contact area ([`image_mass`]): next to the wall the density
/// is then nil (the wall has run ahead of the distribution), and its speed alone had refined
/// the grid to 27 000 nodes for nothing (an onset right at a step's end: system II,
/// t·q_r = 0.1, p* = 2.29e-4, marches 30× dearer than their neighbours). Where the refinement
/// matters the image carries 1e-5–3e-3 of it.
const IMAGE_NEGLIGIBLE: f64 = 1e-9;

/// A wall that runs away by more than this many times the span of the grid in one piece,
/// carrying a negligible image ([`IMAGE_NEGLIGIBLE`]), leaves the distribution behind: the
/// step is free diffusion and the grid is offset instead of stretched (see
/// [`WallMove::apply`]).
const RUNAWAY_SPAN: f64 = 4.0;

/// Zero nodes put below the content of a grid that a runaway wall leaves behind: ten standard
/// deviations of the step's spread (variance `dv`) and the shift's stencil.
fn runaway_pad(dv: f64, h: f64) -> usize {
    (10.0 * dv.sqrt() / h).ceil() as usize + 8
}

/// The mass ∫₀^∞ e^{−2cy} p(y) dy of the weighted image of a wall running away at speed c
/// from the grid values `p` (p[0] = 0 at the wall, spacing h), where 2c·h ≫ 1: p'(0)/(4c²),
/// with p'(0) the steepest chord from the wall over the first four nodes (a bound where the
/// first node is flat).
fn image_mass(p: &[f64], h: f64, c: f64) -> f64 {
    let slope = (1..p.len().min(5)).map(|j| p[j] / (j as f64 * h)).fold(0.0, f64::max);
    slope / (4.0 * c * c)
}

/// One piece's move of the wall on the grid (module docs).
pub(super) struct WallMove {
    /// σ_a* at the piece's end.
    pub(super) target: f64,
    /// δ = target − σ_a* at the piece's start.
    pub(super) delta: f64,
    /// Δv of the piece from the rate at its start, W^{2α}(a_r)·b.
    pub(super) dv_guess: f64,
    /// The piece's variance measure b.
    pub(super) b: f64,
    /// a_r at the piece's start.
    pub(super) a: f64,
}

impl WallMove {
    /// The spacing after refining the grid `p` (offset `m`, spacing `h`) for a wall running
    /// away from it: halved until 2c·h ≤ [`REFINE_DRIFT`], where the image carries more than
    /// [`IMAGE_NEGLIGIBLE`] of a_r, and bounded by [`REFINE_MAX_NODES`] both on `p` and on the
    /// grid the step will need up to `reach` (a wall jumping far in a tiny piece must not ask
    /// for 1e9 nodes). The coarsening after the heat step undoes it as the wall slows.
    pub(super) fn refine_grid(&self, p: &mut Vec<f64>, m: usize, mut h: f64, reach: f64) -> f64 {
        let (delta, dv_guess) = (self.delta, self.dv_guess);
        if m == 0 && delta > 0.0 && dv_guess > 0.0 && image_mass(p, h, delta / dv_guess) > IMAGE_NEGLIGIBLE * self.a {
            while 2.0 * delta / dv_guess * h > REFINE_DRIFT
                && p.len() < REFINE_MAX_NODES
                && reach / (0.5 * h) < REFINE_MAX_NODES as f64
            {
                refine(p);
                h *= 0.5;
            }
        }
        h
    }

    /// Moves the wall (at `wall`) and the grid `p` (offset `m`, spacing `h`) as far as they
    /// move before the heat step (module docs). Returns the second half of a receding wall's
    /// shift, due after the heat step (0 otherwise), and whether the shift would have grown
    /// the grid beyond `max_nodes` (then it is not done and the march is flagged).
    pub(super) fn apply(
        &self,
        p: &mut Vec<f64>,
        m: &mut usize,
        h: f64,
        wall: &mut f64,
        max_nodes: usize,
    ) -> (f64, bool) {
        let (delta, dv_guess) = (self.delta, self.dv_guess);
        let mut receding = 0.0;
        let mut overflow = false;
        // a wall that runs away from the distribution by more than RUNAWAY_SPAN times
        // the grid's span, so fast that its image carries a negligible mass: the step
        // is free diffusion carried `delta` from the wall (the image dropped, an error
        // below IMAGE_NEGLIGIBLE of a_r), the grid offset by whole cells as for a wall
        // ahead of the distribution, with zeros below the content for the step's
        // spread. A grid that spanned the whole new distance from the wall to the
        // distribution would need σ_a*/h nodes: the root scan puts σ_a* at 1e4 after
        // one step at p* = 1e-9 (γ = (C + I)/a_r at tiny a_r), 9e6 nodes, and 9e9 at
        // p* = 1e-12
        let runaway = *m == 0 && delta > 0.0 && dv_guess > 0.0 && {
            let span = (p.len() - 1) as f64 * h;
            let pad = runaway_pad(self.b.max(dv_guess), h);
            delta > RUNAWAY_SPAN * span
                && (delta / h).floor() >= pad as f64
                && image_mass(p, h, delta / dv_guess) <= IMAGE_NEGLIGIBLE * self.a
        };
        if runaway {
            let pad = runaway_pad(self.b.max(dv_guess), h);
            let cells = (delta / h).floor();
            p.splice(0..0, std::iter::repeat_n(0.0, pad));
            *m = cells as usize - pad;
            *wall += cells * h;
        } else if delta != 0.0 && *m > 0 {
            // the distribution is far from the wall: move it by whole cells through
            // the grid's offset, by the remaining fraction of a cell spectrally
            let cells = (delta / h).floor();
            let new_m = *m as f64 + cells;
            if new_m < 0.0 {
                p.splice(0..0, std::iter::repeat_n(0.0, (-new_m) as usize));
                *m = 0;
            } else {
                *m = new_m as usize;
            }
            *wall += cells * h;
        } else if delta < 0.0 {
            // a wall moving into the distribution: the weighted extension would grow
            // as exp(2|c|y); Strang splitting instead: half the shift (8-point
            // Lagrange, mass below the wall removed), the heat step with the wall
            // held, the other half (second order: the state inside the step is off
            // by ± half a shift's loss at its ends, which cancels in ∫W(a)dB)
            shift(p, h, 0.5 * delta);
            *wall += 0.5 * delta;
            receding = 0.5 * delta;
        } else if delta != 0.0 && dv_guess <= 0.0 {
            // no variance to move the wall in: shift, then the (empty) heat step
            // (a shift that would grow the grid beyond its bound is flagged instead)
            if delta / h > max_nodes as f64 {
                overflow = true;
            } else {
                shift(p, h, delta);
            }
            *wall = self.target;
        }
        (receding, overflow)
    }
}
