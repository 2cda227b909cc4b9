//! Polonsky–Keer constrained conjugate gradients for the hard wall (no adhesion).
//!
//! Polonsky & Keer, Wear 231, 206 (1999), on the periodic FFT grid as in tamaas's
//! `PolonskyKeerRey` (Frérot, Anciaux & Molinari): the unknown is the contact pressure p ≥ 0
//! with ⟨p⟩ = p₀ (load control); the elastic surface is w = w̄ + K⋆p with the compliance
//! K(q) = 1/φ(q) (q ≠ 0; the q = 0 mode is the free rigid-body position w̄). The gap is
//! g = w − h. On the set S = {p > 0} the gap must vanish: w̄ = −⟨K⋆p − h⟩_S, and
//!
//! ```text
//! g_i   = (K⋆p)_i − h_i − ⟨K⋆p − h⟩_S              (the gap, 0 on S at the solution)
//! t     = g + (G/G_old) t on S, 0 elsewhere;        G = Σ_S g²
//! r     = K⋆t − ⟨K⋆t⟩_S,   τ = Σ_S g t / Σ_S r t
//! p_S  −= τ t,  p = max(p, 0);  overlap O = {p = 0 (before the step), g < 0}: p_O = −τ g;
//!         p ← p · p₀/⟨p⟩
//! ```
//!
//! This is the minimisation of the complementary energy ½p·Kp − p·h on {p ≥ 0, ⟨p⟩ = p₀}. It
//! stops when the gap on S and the overlap off S are below `gap_tol` (internal length unit
//! Δa); the FIRE solver then checks (and if needed finishes) the same force residual as a
//! FIRE-only run, so the answer's criterion does not depend on the method
//! ([`super::solve_from`]).
//!
//! **No restart when nodes join S.** Polonsky & Keer (and tamaas) restart the conjugate
//! directions (t = g) whenever the overlap O is not empty; that turns most of a run into
//! steepest descent while S is still being found, and the iteration count grows with the grid
//! (system I at p* = 0.01: 153 iterations at 1024², 338 at 2048²). Here t keeps its conjugate
//! part and is reset only when it stops being a descent direction (Σ_S g t ≤ 0): 108 and 126
//! iterations on the same maps, the same contact set to the node (BENCHMARKS.md).
//!
//! **Cost.** Two convolutions per iteration, each fused with the node loop that feeds it or
//! reads it ([`RealFft2::convolve_rows`]). Once an update changes no node of S (no clipped
//! pressure, no overlap), p moved along t alone, so K⋆p follows as K⋆p − τ K⋆t and its
//! convolution is skipped; a stop reached that way is confirmed with a fresh K⋆p.

use crate::error::{Error, Result};
use crate::numerics::fft2::{RealFft2, SpectralKernel};
use rustfft::num_complex::Complex64;
use std::sync::atomic::{AtomicBool, Ordering};

/// Runs PK from the pressure `p` (internal units, E*; replaced by p₀ where it is all zero)
/// and returns the elastic surface w (internal units, Δa) and the iterations taken.
/// `phi` is the stiffness on the half spectrum (E*/Δa), `h` the heights (Δa).
#[allow(clippy::too_many_arguments)]
pub fn relax(
    plan: &mut RealFft2,
    phi: &[f64],
    h: &[f64],
    mut p: Vec<f64>,
    p0: f64,
    gap_tol: f64,
    max_iterations: usize,
    progress: &mut dyn FnMut(usize, f64, f64),
    cancel: &AtomicBool,
) -> Result<(Vec<f64>, usize)> {
    crate::work::start();
    let n = h.len();
    let comp: Vec<f64> = phi
        .iter()
        .map(|&f| if f > 0.0 { 1.0 / (f * n as f64) } else { 0.0 })
        .collect();
    let (comp, spec) = (plan.kernel(&comp), vec![Complex64::new(0.0, 0.0); plan.spectrum_len()]);
    let mut pk = Pk {
        plan,
        comp,
        h,
        spec,
        par: n >= PARALLEL_MIN_NODES,
    };
    if !p.iter().any(|&x| x > 0.0) {
        p.iter_mut().for_each(|x| *x = p0);
    }
    let (mut u, mut g, mut t, mut r) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut g_old = 0.0;
    // `scale`: the load rescaling not yet applied to p (nor to u when u is carried over)
    let (mut scale, mut carried) = (1.0, false);
    let mut it = 0;
    loop {
        let a = match carried {
            true => pk.rescale_carried(&mut p, &mut u, scale),
            false => pk.displacement(&mut p, &mut u, scale),
        };
        scale = 1.0;
        let cnt = a[1];
        let gbar = a[0] / cnt.max(1.0);
        let b = pk.gap(&mut g, &u, &p, gbar);
        let gg = b[0];
        if !gg.is_finite() {
            return Err(Error::NotConverged {
                solver: crate::error::Solver::GfmdPolonskyKeer,
                reason: format!("non-finite gap after {it} iterations"),
            });
        }
        let err = b[1].max(b[2]);
        if err <= gap_tol && carried {
            // confirm the stop with a fresh K⋆p
            carried = false;
            continue;
        }
        if it % 10 == 0 {
            progress(it, err, cnt / n as f64);
        }
        if err <= gap_tol || it >= max_iterations {
            // nodes carrying pressure sit on the wall
            let w: Vec<f64> = (0..n).map(|i| if p[i] > 0.0 { h[i] } else { u[i] - gbar }).collect();
            return Ok((w, it));
        }
        if cancel.load(Ordering::Relaxed) {
            return Err(Error::Cancelled);
        }
        let beta = if g_old > 0.0 { gg / g_old } else { 0.0 };
        g_old = gg;
        let mut c = pk.direction(&mut t, &mut r, &p, &g, beta);
        if c[1] <= 0.0 && beta > 0.0 {
            // not a descent direction: restart from the gap
            c = pk.direction(&mut t, &mut r, &p, &g, 0.0);
        }
        let rbar = c[0] / cnt.max(1.0);
        let rt = c[2] - rbar * c[3];
        let tau = if rt > 0.0 { c[1] / rt } else { 0.0 };
        let d = pk.step(&mut p, &mut u, &t, &r, &g, tau);
        carried = d[1] == 0.0 && d[2] == 0.0;
        let mean = d[0] / n as f64;
        if mean > 0.0 {
            scale = p0 / mean;
        }
        it += 1;
    }
}

/// The fixed parts of a run: the plan, the compliance kernel, the heights, the scratch
/// spectrum and whether node loops go parallel.
struct Pk<'a> {
    plan: &'a mut RealFft2,
    comp: SpectralKernel,
    h: &'a [f64],
    spec: Vec<Complex64>,
    par: bool,
}

impl Pk<'_> {
    /// p ← scale·p, then u = K⋆p; returns Σ_S (u − h) and |S|.
    fn displacement(&mut self, p: &mut [f64], u: &mut [f64], scale: f64) -> [f64; 4] {
        let (nx, h) = (self.plan.nx(), self.h);
        let parts = self.plan.convolve_rows(
            p,
            &self.comp,
            &mut self.spec,
            u,
            |_, row| row.iter_mut().for_each(|x| *x *= scale),
            |y, prow, urow| on_contact_sums(prow, urow, &h[y * nx..(y + 1) * nx]),
        );
        combine(parts, SUMS)
    }

    /// p ← scale·p and u ← scale·u (u carried over from the last step: K⋆p is linear);
    /// returns Σ_S (u − h) and |S|.
    fn rescale_carried(&self, p: &mut [f64], u: &mut [f64], scale: f64) -> [f64; 4] {
        let h = self.h;
        map_reduce2(self.par, p, u, SUMS, |o, pc, uc| {
            pc.iter_mut().for_each(|x| *x *= scale);
            uc.iter_mut().for_each(|x| *x *= scale);
            on_contact_sums(pc, uc, &h[o..o + pc.len()])
        })
    }

    /// g = u − h − ḡ; returns Σ_S g², max_S |g| and the largest overlap off S.
    fn gap(&self, g: &mut [f64], u: &[f64], p: &[f64], gbar: f64) -> [f64; 4] {
        let h = self.h;
        map_reduce(self.par, g, [false, true, true, false], |o, gc| {
            let (mut gg, mut gmax, mut over) = (0.0, 0.0f64, 0.0f64);
            for (j, gi) in gc.iter_mut().enumerate() {
                let i = o + j;
                *gi = u[i] - h[i] - gbar;
                if p[i] > 0.0 {
                    gg += *gi * *gi;
                    gmax = gmax.max(gi.abs());
                } else {
                    over = over.max(-*gi);
                }
            }
            [gg, gmax, over, 0.0]
        })
    }

    /// t = g + β t on S (0 elsewhere) and r = K⋆t; returns Σ_S r, Σ_S g t, Σ_S r t and Σ_S t
    /// (then Σ_S (r − r̄) t = Σ r t − r̄ Σ t).
    fn direction(&mut self, t: &mut [f64], r: &mut [f64], p: &[f64], g: &[f64], beta: f64) -> [f64; 4] {
        let nx = self.plan.nx();
        let parts = self.plan.convolve_rows(
            t,
            &self.comp,
            &mut self.spec,
            r,
            |y, row| {
                let o = y * nx;
                for (k, ti) in row.iter_mut().enumerate() {
                    *ti = if p[o + k] > 0.0 { g[o + k] + beta * *ti } else { 0.0 };
                }
            },
            |y, trow, rrow| {
                let o = y * nx;
                let mut s = [0.0; 4];
                for (k, (&ti, &ri)) in trow.iter().zip(rrow).enumerate() {
                    if p[o + k] > 0.0 {
                        s[0] += ri;
                        s[1] += g[o + k] * ti;
                        s[2] += ri * ti;
                        s[3] += ti;
                    }
                }
                s
            },
        );
        combine(parts, SUMS)
    }

    /// p_S −= τ t with the projection p ≥ 0, p_O = −τ g on the overlap, and u −= τ K⋆t;
    /// returns Σ p, whether O was not empty and whether a pressure was clipped (then u is
    /// stale and the next K⋆p is convolved).
    fn step(&self, p: &mut [f64], u: &mut [f64], t: &[f64], r: &[f64], g: &[f64], tau: f64) -> [f64; 4] {
        map_reduce2(self.par, p, u, SUMS, |o, pc, uc| {
            let (mut sum, mut overlap, mut clipped) = (0.0, 0.0, 0.0);
            for (j, (pi, ui)) in pc.iter_mut().zip(uc.iter_mut()).enumerate() {
                let i = o + j;
                if *pi > 0.0 {
                    let q = *pi - tau * t[i];
                    if q < 0.0 {
                        clipped = 1.0;
                    }
                    *pi = q.max(0.0);
                } else if g[i] < 0.0 {
                    *pi = -tau * g[i];
                    overlap = 1.0;
                }
                *ui -= tau * r[i];
                sum += *pi;
            }
            [sum, overlap, clipped, 0.0]
        })
    }
}

/// Σ (u − h) and the number of nodes over the nodes of a stretch that carry pressure.
fn on_contact_sums(p: &[f64], u: &[f64], h: &[f64]) -> [f64; 4] {
    let (mut sum, mut cnt) = (0.0, 0.0);
    for ((&pi, &ui), &hi) in p.iter().zip(u).zip(h) {
        if pi > 0.0 {
            sum += ui - hi;
            cnt += 1.0;
        }
    }
    [sum, cnt, 0.0, 0.0]
}

/// Node-loop chunk: partial results are combined in chunk order, so a run is bit-for-bit the
/// same whatever the thread count.
const CHUNK: usize = 4096;
/// Grids with at least this many nodes run their node loops on rayon.
const PARALLEL_MIN_NODES: usize = 1 << 15;

/// Combines per-chunk partials in chunk order: slot k is a maximum where `maxed[k]`, else a sum.
fn combine(parts: Vec<[f64; 4]>, maxed: [bool; 4]) -> [f64; 4] {
    parts.into_iter().fold([0.0; 4], |mut a, b| {
        for k in 0..4 {
            a[k] = if maxed[k] { a[k].max(b[k]) } else { a[k] + b[k] };
        }
        a
    })
}

/// Slots that are all sums.
const SUMS: [bool; 4] = [false; 4];

/// Like [`map_reduce`], over matching mutable chunks of `x` and `y`.
fn map_reduce2(
    par: bool,
    x: &mut [f64],
    y: &mut [f64],
    maxed: [bool; 4],
    f: impl Fn(usize, &mut [f64], &mut [f64]) -> [f64; 4] + Sync,
) -> [f64; 4] {
    if par {
        use rayon::prelude::*;
        combine(
            x.par_chunks_mut(CHUNK)
                .zip(y.par_chunks_mut(CHUNK))
                .enumerate()
                .map(|(c, (xc, yc))| f(c * CHUNK, xc, yc))
                .collect(),
            maxed,
        )
    } else {
        combine(
            x.chunks_mut(CHUNK)
                .zip(y.chunks_mut(CHUNK))
                .enumerate()
                .map(|(c, (xc, yc))| f(c * CHUNK, xc, yc))
                .collect(),
            maxed,
        )
    }
}

/// Like [`reduce`], over mutable chunks of `x` (`f` gets the chunk's offset).
fn map_reduce(
    par: bool,
    x: &mut [f64],
    maxed: [bool; 4],
    f: impl Fn(usize, &mut [f64]) -> [f64; 4] + Sync,
) -> [f64; 4] {
    if par {
        use rayon::prelude::*;
        combine(
            x.par_chunks_mut(CHUNK)
                .enumerate()
                .map(|(c, xc)| f(c * CHUNK, xc))
                .collect(),
            maxed,
        )
    } else {
        combine(
            x.chunks_mut(CHUNK)
                .enumerate()
                .map(|(c, xc)| f(c * CHUNK, xc))
                .collect(),
            maxed,
        )
    }
}
