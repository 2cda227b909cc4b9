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
    let mut it = 0;
    loop {
        plan.convolve(&p, &comp, &mut spec, &mut u);
        let (mut sum, mut cnt) = (0.0, 0usize);
        for i in 0..n {
            if p[i] > 0.0 {
                sum += u[i] - h[i];
                cnt += 1;
            }
        }
        let gbar = sum / cnt.max(1) as f64;
        let (mut gg, mut gmax, mut over) = (0.0, 0.0f64, 0.0f64);
        for i in 0..n {
            g[i] = u[i] - h[i] - gbar;
            if p[i] > 0.0 {
                gg += g[i] * g[i];
                gmax = gmax.max(g[i].abs());
            } else {
                over = over.max(-g[i]);
            }
        }
        if !gg.is_finite() {
            return Err(Error::NotConverged {
                solver: "gfmd (Polonsky-Keer)".into(),
                reason: format!("non-finite gap after {it} iterations"),
            });
        }
        let err = gmax.max(over);
        if it % 10 == 0 {
            progress(it, err, cnt as f64 / n as f64);
        }
        if err <= gap_tol || it >= max_iterations {
            // nodes carrying pressure sit on the wall
            let w: Vec<f64> = (0..n).map(|i| if p[i] > 0.0 { h[i] } else { u[i] - gbar }).collect();
            return Ok((w, it));
        }
        if cancel.load(Ordering::Relaxed) {
            return Err(Error::Cancelled);
        }
        for i in 0..n {
            t[i] = if p[i] > 0.0 {
                g[i] + delta * (gg / g_old) * t[i]
            } else {
                0.0
            };
        }
        g_old = gg;
        plan.convolve(&t, &comp, &mut spec, &mut r);
        let (mut rs, mut gt) = (0.0, 0.0);
        for i in 0..n {
            if p[i] > 0.0 {
                rs += r[i];
                gt += g[i] * t[i];
            }
        }
        let rbar = rs / cnt.max(1) as f64;
        let mut rt = 0.0;
        for i in 0..n {
            if p[i] > 0.0 {
                rt += (r[i] - rbar) * t[i];
            }
        }
        let tau = if rt > 0.0 { gt / rt } else { 0.0 };
        let mut overlap = false;
        for i in 0..n {
            if p[i] > 0.0 {
                p[i] = (p[i] - tau * t[i]).max(0.0);
            } else if g[i] < 0.0 {
                p[i] = -tau * g[i];
                overlap = true;
            }
        }
        delta = if overlap { 0.0 } else { 1.0 };
        let mean = p.iter().sum::<f64>() / n as f64;
        if mean > 0.0 {
            let s = p0 / mean;
            p.iter_mut().for_each(|x| *x *= s);
        }
        it += 1;
    }
}
