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
//! t     = g + δ (G/G_old) t on S, 0 elsewhere;      G = Σ_S g²
//! r     = K⋆t − ⟨K⋆t⟩_S,   τ = Σ_S g t / Σ_S r t
//! p_S  −= τ t,  p = max(p, 0);  overlap O = {p = 0 (before the step), g < 0}: p_O = −τ g,
//!         δ = 0 if O is not empty (restart), else 1;   p ← p · p₀/⟨p⟩
//! ```
//!
//! This is the minimisation of the complementary energy ½p·Kp − p·h on {p ≥ 0, ⟨p⟩ = p₀}; two
//! convolutions per iteration (K⋆p and K⋆t). It stops when the gap on S and the overlap off S
//! are below `gap_tol` (internal length unit Δa); the FIRE solver then checks (and if needed
//! finishes) the same force residual as a FIRE-only run, so the answer's criterion does not
//! depend on the method ([`super::solve_from`]).

use crate::error::{Error, Result};
use crate::numerics::fft2::RealFft2;
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
    let mut spec = vec![Complex64::new(0.0, 0.0); plan.spectrum_len()];
    if !p.iter().any(|&x| x > 0.0) {
        p.iter_mut().for_each(|x| *x = p0);
    }
    let (mut u, mut g, mut t, mut r) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let (mut g_old, mut delta) = (1.0, 0.0);
    let par = n >= PARALLEL_MIN_NODES;
    let mut it = 0;
    loop {
        plan.convolve(&p, &comp, &mut spec, &mut u);
        let a = reduce(par, n, SUMS, |k| {
            let (mut sum, mut cnt) = (0.0, 0.0);
            for i in k {
                if p[i] > 0.0 {
                    sum += u[i] - h[i];
                    cnt += 1.0;
                }
            }
            [sum, cnt, 0.0, 0.0]
        });
        let cnt = a[1];
        let gbar = a[0] / cnt.max(1.0);
        let b = map_reduce(par, &mut g, [false, true, true, false], |o, gc| {
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
        });
        let gg = b[0];
        if !gg.is_finite() {
            return Err(Error::NotConverged {
                solver: crate::error::Solver::GfmdPolonskyKeer,
                reason: format!("non-finite gap after {it} iterations"),
            });
        }
        let err = b[1].max(b[2]);
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
        let beta = delta * gg / g_old;
        map_reduce(par, &mut t, SUMS, |o, tc| {
            for (j, ti) in tc.iter_mut().enumerate() {
                let i = o + j;
                *ti = if p[i] > 0.0 { g[i] + beta * *ti } else { 0.0 };
            }
            [0.0; 4]
        });
        g_old = gg;
        plan.convolve(&t, &comp, &mut spec, &mut r);
        // Σ_S r, Σ_S g t, Σ_S r t, Σ_S t: then Σ_S (r − r̄) t = Σ r t − r̄ Σ t
        let c = reduce(par, n, SUMS, |k| {
            let mut s = [0.0; 4];
            for i in k {
                if p[i] > 0.0 {
                    s[0] += r[i];
                    s[1] += g[i] * t[i];
                    s[2] += r[i] * t[i];
                    s[3] += t[i];
                }
            }
            s
        });
        let rbar = c[0] / cnt.max(1.0);
        let rt = c[2] - rbar * c[3];
        let tau = if rt > 0.0 { c[1] / rt } else { 0.0 };
        let d = map_reduce(par, &mut p, [false, true, false, false], |o, pc| {
            let (mut sum, mut overlap) = (0.0, 0.0);
            for (j, pi) in pc.iter_mut().enumerate() {
                let i = o + j;
                if *pi > 0.0 {
                    *pi = (*pi - tau * t[i]).max(0.0);
                } else if g[i] < 0.0 {
                    *pi = -tau * g[i];
                    overlap = 1.0;
                }
                sum += *pi;
            }
            [sum, overlap, 0.0, 0.0]
        });
        delta = if d[1] > 0.0 { 0.0 } else { 1.0 };
        let mean = d[0] / n as f64;
        if mean > 0.0 {
            let sc = p0 / mean;
            map_reduce(par, &mut p, SUMS, |_, pc| {
                pc.iter_mut().for_each(|x| *x *= sc);
                [0.0; 4]
            });
        }
        it += 1;
    }
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

/// Runs `f` over index chunks (in parallel when `par`) and combines the partials in order.
fn reduce(par: bool, n: usize, maxed: [bool; 4], f: impl Fn(std::ops::Range<usize>) -> [f64; 4] + Sync) -> [f64; 4] {
    let chunks = n.div_ceil(CHUNK);
    let run = |c: usize| f(c * CHUNK..((c + 1) * CHUNK).min(n));
    if par {
        use rayon::prelude::*;
        combine((0..chunks).into_par_iter().map(run).collect(), maxed)
    } else {
        combine((0..chunks).map(run).collect(), maxed)
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
