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
//! **Cold start.** Where the caller gives no pressure (every run of [`super::solve_from`]),
//! PK starts from a guess made from the heights (`gfmd::pk_start`: the few per cent highest
//! nodes, Persson's adhesionless a_r three times over) instead of p₀ on every node, which
//! spends its first ≈ 10 iterations shrinking S from the whole grid: 108 → 95 iterations on
//! system I at 1024², p* = 0.01, and 9 % fewer over p* = 1e-4…1 and 64²…512² (half as many
//! at p* = 1e-4, more in no case), the same contact set to the node and ū to 1e-10
//! (BENCHMARKS.md). Should the guess stall (its set already in equilibrium with an overlap
//! outside it, so that τ = 0 and no step adds the overlap, as for a single node), the run
//! starts afresh from p₀.
//!
//! **Cost.** Two convolutions per iteration, each fused with the node loop that feeds it or
//! reads it ([`RealFft2::convolve_rows`]). Once an update changes no node of S (no clipped
//! pressure, no overlap), p moved along t alone, so K⋆p follows as K⋆p − τ K⋆t and its
//! convolution is skipped; a stop reached that way is confirmed with a fresh K⋆p.
//!
//! S (a few per cent of the nodes at the loads of interest) is kept as a list of its nodes
//! (`gfmd::pk_support`): p and t are zero off S, so the fields to convolve are written from
//! it, the sums over S and the step visit its nodes only, and g is not stored (it is
//! u − h − ḡ where it is needed). What needs every node is the overlap test (the least
//! x = u − h off S, taken while a row of u is in the cache) and, when it finds one, the step in
//! the chunks that hold it, which lists the new S there as it goes (the other chunks keep their
//! nodes with p > 0). The sums are those the node-by-node loops take, in the same order
//! (Σ_S g² excepted: it is Σ (x − c)² − |S|(ḡ − c)² about the last ḡ, to one rounding of the
//! node-by-node sum), so a run is the same to the last digit of a_r and ū as one over every
//! node (BENCHMARKS.md).

use super::pk_support::{Contact, Support, CHUNK};
use crate::error::{Error, Result};
use crate::numerics::fft2::{RealFft2, SpectralKernel};
use rustfft::num_complex::Complex64;
use std::sync::atomic::{AtomicBool, Ordering};

/// Runs PK from the pressure `p` (internal units, E*; where it is all zero, from the guess of
/// `gfmd::pk_start`) and returns the elastic surface w (internal units, Δa) and the
/// iterations taken.
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
    let nx = pk.plan.nx();
    // a start guessed from the heights, given up for p₀ if it stalls (below)
    let mut guessed = !p.iter().any(|&x| x > 0.0);
    if guessed {
        p = super::pk_start::guess(h, nx, p0);
    }
    let mut set = Support::of(&p, nx);
    let (mut u, mut t, mut r) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut g_old = 0.0;
    // `scale`: the load rescaling not yet applied to p (nor to u when u is carried over);
    // `tau`: the last step, whose u −= τ K⋆t is applied when u is carried over; `shift`: the
    // last ḡ, the reference of the gap's sum of squares
    let (mut scale, mut carried, mut tau, mut shift) = (1.0, false, 0.0, 0.0);
    let mut it = 0;
    loop {
        // `off`: per chunk, a lower bound of x = u − h off S
        let (a, off) = match carried {
            true => pk.carry(&set, &mut p, &mut u, &r, (tau, scale), shift),
            false => pk.displacement(&set, &mut p, &mut u, scale, shift),
        };
        scale = 1.0;
        let cnt = a.count;
        let gbar = a.sum / cnt.max(1.0);
        let gap = a.gap(gbar);
        shift = gbar;
        if !gap.squares.is_finite() {
            return Err(Error::NotConverged {
                solver: crate::error::Solver::GfmdPolonskyKeer,
                reason: format!("non-finite gap after {it} iterations"),
            });
        }
        let err = gap.on.max(gap.overlap);
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
        let beta = if g_old > 0.0 { gap.squares / g_old } else { 0.0 };
        g_old = gap.squares;
        let mut c = pk.direction(&set, &mut t, &mut r, &u, gbar, beta);
        if c[1] <= 0.0 && beta > 0.0 {
            // not a descent direction: restart from the gap
            c = pk.direction(&set, &mut t, &mut r, &u, gbar, 0.0);
        }
        let rbar = c[0] / cnt.max(1.0);
        let rt = c[2] - rbar * c[3];
        tau = if rt > 0.0 { c[1] / rt } else { 0.0 };
        let overlap = gap.overlap > 0.0;
        if guessed && overlap && tau == 0.0 {
            // the guess is at equilibrium on its own set (e.g. a single node) and no step
            // would add the overlap to it: start afresh from p₀ on every node
            (guessed, g_old, carried) = (false, 0.0, false);
            p.iter_mut().for_each(|x| *x = p0);
            set = Support::of(&p, nx);
            it += 1;
            continue;
        }
        let d = match overlap {
            true => {
                // S changed: nodes joined (the overlap), and maybe left
                let (d, joined) = pk.step_all(&set, &mut p, &mut t, (&u, &off), gbar, tau);
                set = joined;
                d
            }
            false => pk.step(&set, &mut p, &mut t, tau),
        };
        if !overlap && d[1] > 0.0 {
            // S changed: nodes left (a clipped pressure)
            set.retain(&p, nx);
        }
        // u follows p without a convolution when p moved along t alone
        carried = !overlap && d[1] == 0.0;
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
    /// p ← scale·p, then u = K⋆p; returns the sums over the contact of x = u − h, and per
    /// chunk a lower bound of x off S.
    fn displacement(
        &mut self,
        set: &Support,
        p: &mut [f64],
        u: &mut [f64],
        scale: f64,
        shift: f64,
    ) -> (Contact, Vec<f64>) {
        let (nx, h) = (self.plan.nx(), self.h);
        let (_, parts) = self.plan.convolve_rows(
            p,
            &self.comp,
            &mut self.spec,
            u,
            |y, prow, row| {
                // p is zero off S
                row.fill(0.0);
                for &i in set.row(y) {
                    let k = i - y * nx;
                    prow[k] *= scale;
                    row[k] = prow[k];
                }
            },
            |y, _, urow| Contact::of(set.row(y), y * nx, urow, &h[y * nx..(y + 1) * nx], shift),
        );
        // a chunk's bound: the least of its rows' minima
        let n = h.len();
        let off = (0..n.div_ceil(CHUNK))
            .map(|c| {
                let rows = c * CHUNK / nx..=(((c + 1) * CHUNK).min(n) - 1) / nx;
                parts[rows].iter().fold(f64::INFINITY, |m, s| m.min(s.min_off))
            })
            .collect();
        (parts.into_iter().fold(Contact::EMPTY, Contact::then), off)
    }

    /// u ← (u − τ r)·scale and p ← scale·p (u carried over from the last step: K⋆p is
    /// linear); returns the sums over the contact of x = u − h, and per chunk the minimum of x
    /// off S.
    fn carry(
        &self,
        set: &Support,
        p: &mut [f64],
        u: &mut [f64],
        r: &[f64],
        (tau, scale): (f64, f64),
        shift: f64,
    ) -> (Contact, Vec<f64>) {
        let h = self.h;
        let parts = chunked(self.par, p, u, |c, o, pc, uc| {
            let nodes = set.chunk(c);
            for &i in nodes {
                pc[i - o] *= scale;
            }
            let m = uc.len();
            for (ui, &ri) in uc.iter_mut().zip(&r[o..o + m]) {
                *ui = (*ui - tau * ri) * scale;
            }
            Contact::of(nodes, o, uc, &h[o..o + m], shift)
        });
        let off = parts.iter().map(|s| s.min_off).collect();
        (parts.into_iter().fold(Contact::EMPTY, Contact::then), off)
    }

    /// t = g + β t on S (0 elsewhere), g = u − h − ḡ, and r = K⋆t; returns Σ_S r, Σ_S g t,
    /// Σ_S r t and Σ_S t (then Σ_S (r − r̄) t = Σ r t − r̄ Σ t).
    fn direction(&mut self, set: &Support, t: &mut [f64], r: &mut [f64], u: &[f64], gbar: f64, beta: f64) -> [f64; 4] {
        let (nx, h) = (self.plan.nx(), self.h);
        let (before, after) = self.plan.convolve_rows(
            t,
            &self.comp,
            &mut self.spec,
            r,
            |y, trow, row| {
                // t is zero off S
                row.fill(0.0);
                let (mut gt, mut st) = (0.0, 0.0);
                for &i in set.row(y) {
                    let k = i - y * nx;
                    let g = u[i] - h[i] - gbar;
                    let ti = g + beta * trow[k];
                    (trow[k], row[k]) = (ti, ti);
                    gt += g * ti;
                    st += ti;
                }
                [gt, st]
            },
            |y, trow, rrow| {
                let (mut sr, mut rt) = (0.0, 0.0);
                for &i in set.row(y) {
                    let k = i - y * nx;
                    sr += rrow[k];
                    rt += rrow[k] * trow[k];
                }
                [sr, rt]
            },
        );
        let mut s = [0.0; 4];
        for (b, a) in before.iter().zip(&after) {
            s[0] += a[0];
            s[1] += b[0];
            s[2] += a[1];
            s[3] += b[1];
        }
        s
    }

    /// p_S −= τ t with the projection p ≥ 0 (t = 0 where p drops to 0, so t stays 0 off S);
    /// returns Σ p and whether a pressure was clipped (then K⋆p is convolved afresh).
    fn step(&self, set: &Support, p: &mut [f64], t: &mut [f64], tau: f64) -> [f64; 2] {
        let parts = chunked(self.par, p, t, |c, o, pc, tc| step_on(set.chunk(c), o, pc, tc, tau));
        sum_and_flag(parts)
    }

    /// [`Pk::step`] when some node off S has g < 0: also p_O = −τ g on the overlap O, visiting
    /// every node of the chunks whose bound `off` of x off S is below ḡ (the others as `step`);
    /// returns also the new S, listed chunk by chunk as the step leaves it (no pass over p).
    fn step_all(
        &self,
        set: &Support,
        p: &mut [f64],
        t: &mut [f64],
        (u, off): (&[f64], &[f64]),
        gbar: f64,
        tau: f64,
    ) -> ([f64; 2], Support) {
        let h = self.h;
        let parts = chunked(self.par, p, t, |c, o, pc, tc| {
            if off[c] - gbar >= 0.0 {
                // no overlap here: g = fl(x − ḡ) ≥ fl(off − ḡ) ≥ 0 off S
                let d = step_on(set.chunk(c), o, pc, tc, tau);
                let kept = set.chunk(c).iter().copied().filter(|&i| pc[i - o] > 0.0).collect();
                return (d, kept);
            }
            let (mut sum, mut clipped, mut nodes) = (0.0, 0.0, Vec::new());
            for (j, (pi, ti)) in pc.iter_mut().zip(tc.iter_mut()).enumerate() {
                if *pi > 0.0 {
                    clipped = project(pi, ti, tau, clipped);
                } else {
                    let g = u[o + j] - h[o + j] - gbar;
                    if g < 0.0 {
                        *pi = -tau * g;
                    }
                }
                if *pi != 0.0 {
                    sum += *pi;
                }
                if *pi > 0.0 {
                    nodes.push(o + j);
                }
            }
            ([sum, clipped], nodes)
        });
        let (sums, lists): (Vec<[f64; 2]>, Vec<Vec<usize>>) = parts.into_iter().unzip();
        let set = Support::from_sorted(lists.concat(), p.len(), self.plan.nx());
        (sum_and_flag(sums), set)
    }
}

/// [`Pk::step`] on one chunk (nodes `o..`, values `p`, `t`), `nodes` the nodes of S in it.
fn step_on(nodes: &[usize], o: usize, p: &mut [f64], t: &mut [f64], tau: f64) -> [f64; 2] {
    let (mut sum, mut clipped) = (0.0, 0.0);
    for &i in nodes {
        let k = i - o;
        clipped = project(&mut p[k], &mut t[k], tau, clipped);
        // the zeros off S would not change the sum
        if p[k] != 0.0 {
            sum += p[k];
        }
    }
    [sum, clipped]
}

/// p −= τ t on a node of S, projected on p ≥ 0 (t zeroed where p drops to 0); returns 1 if p
/// was clipped, else `clipped`.
fn project(p: &mut f64, t: &mut f64, tau: f64, clipped: f64) -> f64 {
    let q = *p - tau * *t;
    *p = q.max(0.0);
    if *p == 0.0 {
        *t = 0.0;
    }
    if q < 0.0 {
        1.0
    } else {
        clipped
    }
}

/// The chunks' Σ p added in chunk order, and whether any chunk clipped.
fn sum_and_flag(parts: Vec<[f64; 2]>) -> [f64; 2] {
    parts.into_iter().fold([0.0; 2], |a, b| [a[0] + b[0], a[1].max(b[1])])
}

/// Grids with at least this many nodes run their node loops on rayon.
const PARALLEL_MIN_NODES: usize = 1 << 15;

/// `f(chunk, offset, x chunk, y chunk)` over matching chunks of [`CHUNK`] nodes of `x` and
/// `y`, the partials in chunk order.
fn chunked<T: Send>(
    par: bool,
    x: &mut [f64],
    y: &mut [f64],
    f: impl Fn(usize, usize, &mut [f64], &mut [f64]) -> T + Sync,
) -> Vec<T> {
    if par {
        use rayon::prelude::*;
        x.par_chunks_mut(CHUNK)
            .zip(y.par_chunks_mut(CHUNK))
            .enumerate()
            .map(|(c, (xc, yc))| f(c, c * CHUNK, xc, yc))
            .collect()
    } else {
        x.chunks_mut(CHUNK)
            .zip(y.chunks_mut(CHUNK))
            .enumerate()
            .map(|(c, (xc, yc))| f(c, c * CHUNK, xc, yc))
            .collect()
    }
}
