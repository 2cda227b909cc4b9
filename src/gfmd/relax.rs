//! FIRE, written once over the rows a rank holds: the whole map on one rank (the serial run,
//! [`super::fire`]) or one slab of rows of a run over ranks ([`super::distributed::fire`]).
//!
//! FIRE (Bitzek et al., PRL 97, 170201, 2006) in the semi-implicit "FIRE 2.0" form (Guénolé
//! et al., Comput. Mater. Sci. 175, 109584, 2020), in real space, unit masses, with
//! projection: after every position update nodes below the wall are put on it and their
//! velocity set to zero (physics.md §6); the model, the time step and the convergence
//! criterion are described in [`super::fire`]. Lengths are in units of Δa and stresses in
//! units of E*.
//!
//! The elastic force φ⋆w is one convolution per step: [`RealFft2::convolve`] on the whole map
//! (one rank), the slab-distributed FFT ([`SlabFft`]) over ranks; the two give the same bits.
//! The sums of a step (F², σ², F·v, v², the nodes on the wall) are added within fixed chunks of
//! `CHUNK` nodes (global index order) and the chunk sums in order: each rank splits its
//! node range at the same global chunk boundaries and sums its pieces in parallel; the fold
//! ([`chain_fold`]) passes (total, open chunk's partial) from rank to rank: a piece that starts
//! inside a chunk continues the partial it received (its terms added in node order), a piece
//! that closes a chunk adds it to the total. The sums, hence dt, α, every position and the step
//! count, do not depend on the number of ranks or threads, bit for bit.
//!
//! Under tension the loss of contact is detected from the smallest gap, reduced over the ranks
//! (exact in any order) only while no node is on the wall under a tensile load.

use super::distributed::comm::{all_max, all_min, all_sum_counts, chain_fold, Comm};
use super::distributed::slab_fft::SlabFft;
use super::{GfmdOptions, Progress, Solution, Stage};
use crate::error::{Error, Result};
use crate::numerics::fft2::{RealFft2, SpectralKernel};
use crate::surface::heightmap::wave_number_sq;
use crate::theory::slab::slab_factor_at;
use rustfft::num_complex::Complex64;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// dt_max·ω_max of the FIRE integrator (semi-implicit Euler is stable below 2; 1.3 took the
/// fewest steps on system I/II test grids, 1.0 about 10 % more, 1.9 several times more).
pub const DT_MAX: f64 = 1.3;
/// FIRE: steps with positive power before dt grows and α shrinks (Bitzek N_min).
pub(crate) const N_DELAY: usize = 5;
/// FIRE: dt growth factor.
pub(crate) const F_INC: f64 = 1.1;
/// FIRE: dt shrink factor after an uphill step.
pub(crate) const F_DEC: f64 = 0.5;
/// FIRE: initial mixing α.
pub(crate) const ALPHA_START: f64 = 0.1;
/// FIRE: α decay factor.
pub(crate) const F_ALPHA: f64 = 0.99;
/// Beyond g/ρ = this the attraction is dropped (e^{−40} ≈ 4e-18).
pub(crate) const EXP_CUTOFF: f64 = 40.0;
/// Node-loop chunk (fixed, so that partial sums are added in the same order every run).
pub(crate) const CHUNK: usize = 4096;
/// Grids with at least this many nodes run their node loops on rayon.
pub(crate) const PARALLEL_MIN_NODES: usize = 1 << 15;

/// Under tension with no node on the wall, contact is taken as lost once the largest possible
/// attraction (γ/ρ)e^{−g_min/ρ} has stayed below this fraction of |p₀| for [`DETACH_STEPS`]
/// steps: the mean force −p₀ − ⟨v′(g)⟩ then lifts the body, and lifting only weakens the
/// attraction (no equilibrium remains: past pull-off).
pub(crate) const DETACH_FRACTION: f64 = 0.5;
/// Consecutive steps the detachment condition must hold (see [`DETACH_FRACTION`]).
pub(crate) const DETACH_STEPS: usize = 20;

/// What a relaxation under load control ends in.
#[derive(Debug, Clone, PartialEq)]
pub enum Relaxation {
    /// An equilibrium within the tolerance.
    Equilibrium(Solution),
    /// Under a tensile load (p₀ < 0, with adhesion) the body left the substrate: no
    /// equilibrium with contact exists at this load (past pull-off).
    ContactLost {
        /// Steps taken until detachment was certain.
        iterations: usize,
    },
}

impl Relaxation {
    /// The equilibrium, or [`Error::NotConverged`] saying that contact was lost (past
    /// pull-off).
    ///
    /// # Errors
    /// As said, for [`Relaxation::ContactLost`].
    pub fn equilibrium(self) -> Result<Solution> {
        match self {
            Relaxation::Equilibrium(sol) => Ok(sol),
            Relaxation::ContactLost { iterations } => Err(Error::NotConverged {
                solver: crate::error::Solver::Gfmd,
                reason: format!(
                    "contact lost after {iterations} steps: the tensile load is beyond what adhesion holds (past pull-off)"
                ),
            }),
        }
    }
}

/// The convolution φ⋆w of the rows a rank holds, with its kernel φ(q)/n.
pub(crate) enum Convolver {
    /// The whole map (one rank): the kernel in [`RealFft2`]'s layout.
    Whole(RealFft2, SpectralKernel),
    /// One slab of rows: the kernel in the rank's column layout ([`SlabFft::convolve`]).
    Slab(SlabFft, Vec<f64>),
}

impl Convolver {
    /// Length of the scratch spectrum.
    fn spectrum_len(&self) -> usize {
        match self {
            Convolver::Whole(plan, _) => plan.spectrum_len(),
            Convolver::Slab(fft, _) => fft.local_spectrum_len(),
        }
    }

    fn convolve(&mut self, comm: &dyn Comm, input: &[f64], spec: &mut [Complex64], out: &mut [f64]) {
        match self {
            Convolver::Whole(plan, kernel) => plan.convolve(input, kernel, spec, out),
            Convolver::Slab(fft, kernel) => fft.convolve(comm, input, kernel, spec, out),
        }
    }
}

/// Where a relaxation starts and what it acts on (internal units), besides the convolution.
pub(crate) struct Start {
    /// Nodes of the whole map.
    pub(crate) nodes: usize,
    /// Global index of this rank's first node.
    pub(crate) offset: usize,
    /// This rank's heights (Δa).
    pub(crate) h: Vec<f64>,
    /// This rank's start positions w ≥ h (Δa).
    pub(crate) w: Vec<f64>,
    /// p₀ (E*), γ/ρ (E*) and 1/ρ (1/Δa); the last two 0 without adhesion.
    pub(crate) loads: (f64, f64, f64),
    /// The largest ω² of the map (φ_max + γ/ρ², internal units).
    pub(crate) omega_sq: f64,
    /// Steps already taken (Polonsky–Keer's), counted on from here.
    pub(crate) steps: usize,
    /// Δa (m) and E* (Pa), to return the solution in SI units.
    pub(crate) units: (f64, f64),
}

/// φ(q) = q f(qt)/2 (E*/Δa) of the mode (kx, ky) of an nx × ny map of spacing `da` on a body
/// of thickness `thickness` (m).
pub(crate) fn stiffness_at(kx: usize, ky: usize, (nx, ny, da): (usize, usize, f64), thickness: f64) -> f64 {
    let q = wave_number_sq(kx, ky, nx, ny, da).sqrt();
    0.5 * q * da * slab_factor_at(q, thickness)
}

/// γ/ρ in E* and 1/ρ in 1/Δa (both 0 without adhesion), from γ (J/m²), ρ (m), E* (Pa), Δa (m).
pub(crate) fn adhesion_units(gamma: f64, range: f64, modulus: f64, da: f64) -> (f64, f64) {
    match gamma > 0.0 {
        true => (gamma / (range * modulus), da / range),
        false => (0.0, 0.0),
    }
}

/// The body's start on this rank's rows (in Δa): the flat body on the highest summit of the
/// whole map, or the heights plus a given gap (m, one finite value per node of the rank).
///
/// # Errors
/// [`Error::Unsupported`] for a start gap of the wrong length or with a non-finite value.
pub(crate) fn start_positions(comm: &dyn Comm, h: &[f64], start_gap: Option<&[f64]>, da: f64) -> Result<Vec<f64>> {
    let n = h.len();
    let hmax = all_max(comm, h.iter().cloned().fold(f64::NEG_INFINITY, f64::max));
    let mut w0 = vec![hmax; n];
    if let Some(g) = start_gap {
        if g.len() != n || g.iter().any(|x| !x.is_finite()) {
            return Err(Error::Unsupported(format!(
                "a start gap needs {n} finite values (got {})",
                g.len()
            )));
        }
        for i in 0..n {
            w0[i] = h[i] + (g[i] / da).max(0.0);
        }
    }
    Ok(w0)
}

/// Relaxes from `start` with FIRE (see the module docs); every rank calls it with the same
/// options, and the returned [`Solution`] holds this rank's rows.
///
/// # Errors
/// [`Error::NotConverged`] when the force diverges or the steps run out;
/// [`Error::Cancelled`] when `cancel` is set.
pub(crate) fn fire(
    comm: &dyn Comm,
    conv: Convolver,
    start: Start,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Relaxation> {
    let t0 = Instant::now();
    let nl = start.h.len();
    let (p0, adh_stress, inv_range) = start.loads;
    let (da, e) = start.units;
    let dt_max = DT_MAX / start.omega_sq.sqrt();
    let mut st = State {
        comm,
        n: start.nodes,
        offset: start.offset,
        spec: vec![Complex64::new(0.0, 0.0); conv.spectrum_len()],
        fft: conv,
        w: start.w,
        h: start.h,
        v: vec![0.0; nl],
        f: vec![0.0; nl],
        conv: vec![0.0; nl],
        p0,
        adh_stress,
        inv_range,
        pieces: pieces(start.offset, nl),
        parallel: nl >= PARALLEL_MIN_NODES,
        detached_at: 0,
    };
    let Some((it, residual)) = relax(&mut st, opts, (dt_max, start.steps), progress, cancel)? else {
        return Ok(Relaxation::ContactLost {
            iterations: st.detached_at,
        });
    };
    let gap: Vec<f64> = st.w.iter().zip(&st.h).map(|(w, h)| (w - h).max(0.0) * da).collect();
    let stress: Vec<f64> = st.conv.iter().map(|c| (st.p0 + c) * e).collect();
    let on_wall: Vec<bool> = st.w.iter().zip(&st.h).map(|(w, h)| w <= h).collect();
    let walls = all_sum_counts(comm, &[on_wall.iter().filter(|&&b| b).count()])[0];
    progress(Progress {
        stage: Stage::Relax,
        iteration: it,
        residual,
        contact_fraction: walls as f64 / st.n as f64,
    });
    Ok(Relaxation::Equilibrium(Solution {
        gap,
        stress,
        on_wall,
        iterations: it,
        pk_iterations: start.steps,
        residual,
        elapsed_s: t0.elapsed().as_secs_f64(),
    }))
}

/// Sums of one piece of nodes: F², σ², F·v, v², nodes on the wall.
type Sums = [f64; 5];

fn add(a: Sums, b: Sums) -> Sums {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3], a[4] + b[4]]
}

struct State<'c> {
    comm: &'c dyn Comm,
    n: usize,
    offset: usize,
    fft: Convolver,
    h: Vec<f64>,
    w: Vec<f64>,
    v: Vec<f64>,
    f: Vec<f64>,
    conv: Vec<f64>,
    spec: Vec<Complex64>,
    p0: f64,
    adh_stress: f64,
    inv_range: f64,
    /// Local pieces [a, b) split at the global chunk boundaries.
    pieces: Vec<(usize, usize)>,
    parallel: bool,
    /// The step at which contact was lost (set by [`relax`]).
    detached_at: usize,
}

impl State<'_> {
    fn forces(&mut self) -> Sums {
        self.fft.convolve(self.comm, &self.w, &mut self.spec, &mut self.conv);
        let (p0, a, ir) = (self.p0, self.adh_stress, self.inv_range);
        let body = |f: &mut [f64], c: &[f64], w: &[f64], h: &[f64], v: &[f64]| -> Sums {
            let mut s = [0.0; 5];
            for i in 0..f.len() {
                let sigma = p0 + c[i];
                let g = w[i] - h[i];
                let mut fi = -sigma;
                if a > 0.0 && g * ir < EXP_CUTOFF {
                    fi -= a * (-g * ir).exp();
                }
                if g <= 0.0 {
                    s[4] += 1.0;
                    if fi < 0.0 {
                        fi = 0.0;
                    }
                }
                f[i] = fi;
                s[0] += fi * fi;
                s[1] += sigma * sigma;
                s[2] += fi * v[i];
                s[3] += v[i] * v[i];
            }
            s
        };
        let parts: Vec<Sums> = if self.parallel {
            use rayon::prelude::*;
            let fp = super::distributed::comm::SendPtr(self.f.as_mut_ptr());
            let (conv, w, h, v) = (&self.conv, &self.w, &self.h, &self.v);
            self.pieces
                .par_iter()
                .map(|&(s, e)| {
                    let p = fp;
                    // SAFETY: the pieces are disjoint ranges of `f`, which outlives this loop.
                    let f = unsafe { std::slice::from_raw_parts_mut(p.0.add(s), e - s) };
                    body(f, &conv[s..e], &w[s..e], &h[s..e], &v[s..e])
                })
                .collect()
        } else {
            let mut out = Vec::with_capacity(self.pieces.len());
            for &(s, e) in &self.pieces {
                out.push(body(
                    &mut self.f[s..e],
                    &self.conv[s..e],
                    &self.w[s..e],
                    &self.h[s..e],
                    &self.v[s..e],
                ));
            }
            out
        };
        let (n, off) = (self.n, self.offset);
        let st = chain_fold(self.comm, vec![0.0; 10], &mut |st| {
            let mut tot: Sums = st[..5].try_into().expect("5");
            let mut part: Sums = st[5..].try_into().expect("5");
            for (k, &(s, e)) in self.pieces.iter().enumerate() {
                let piece = if (off + s) % CHUNK != 0 {
                    // continues the chunk the previous rank left open, in node order
                    let mut q = part;
                    for i in s..e {
                        let (fi, vi) = (self.f[i], self.v[i]);
                        let sigma = p0 + self.conv[i];
                        if self.w[i] - self.h[i] <= 0.0 {
                            q[4] += 1.0;
                        }
                        q[0] += fi * fi;
                        q[1] += sigma * sigma;
                        q[2] += fi * vi;
                        q[3] += vi * vi;
                    }
                    q
                } else {
                    parts[k]
                };
                if (off + e) % CHUNK == 0 || off + e == n {
                    tot = add(tot, piece);
                    part = [0.0; 5];
                } else {
                    part = piece;
                }
            }
            st[..5].copy_from_slice(&tot);
            st[5..].copy_from_slice(&part);
        });
        st[..5].try_into().expect("5")
    }

    fn advance(&mut self, dt: f64, alpha: f64, fnorm: f64, vv: f64) {
        let mix = if fnorm > 0.0 {
            alpha * vv.max(0.0).sqrt() / fnorm
        } else {
            0.0
        };
        let step = |v: &mut [f64], w: &mut [f64], f: &[f64], h: &[f64]| {
            for i in 0..v.len() {
                let vi = (1.0 - alpha) * (v[i] + dt * f[i]) + mix * f[i];
                let wi = w[i] + dt * vi;
                if wi <= h[i] {
                    w[i] = h[i];
                    v[i] = 0.0;
                } else {
                    w[i] = wi;
                    v[i] = vi;
                }
            }
        };
        if self.parallel {
            use rayon::prelude::*;
            self.v
                .par_chunks_mut(CHUNK)
                .zip(self.w.par_chunks_mut(CHUNK))
                .zip(self.f.par_chunks(CHUNK))
                .zip(self.h.par_chunks(CHUNK))
                .for_each(|(((v, w), f), h)| step(v, w, f, h));
        } else {
            step(&mut self.v, &mut self.w, &self.f, &self.h);
        }
    }

    /// Whether the body is lifting off (the serial solver's test): a tensile load, no node on
    /// the wall (`walls` of the whole map) and the largest possible attraction
    /// (γ/ρ)e^{−g_min/ρ} below [`DETACH_FRACTION`] × |p₀|. The smallest gap is reduced over
    /// the ranks only when the first two hold (every rank takes the same branch).
    fn lifting(&self, walls: f64) -> bool {
        if !(self.p0 < 0.0 && walls == 0.0) {
            return false;
        }
        let local = self.w.iter().zip(&self.h).fold(f64::INFINITY, |m, (w, h)| m.min(w - h));
        let gmin = all_min(self.comm, local);
        self.adh_stress * (-gmin * self.inv_range).exp() < -DETACH_FRACTION * self.p0
    }

    fn retreat(&mut self, dt: f64) {
        for i in 0..self.w.len() {
            self.w[i] = (self.w[i] - 0.5 * dt * self.v[i]).max(self.h[i]);
            self.v[i] = 0.0;
        }
    }
}

/// The pieces of the local range [0, len) of global offset `off`, split where the global
/// index is a multiple of [`CHUNK`].
fn pieces(off: usize, len: usize) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut s = 0;
    while s < len {
        let next = ((off + s) / CHUNK + 1) * CHUNK - off;
        let e = next.min(len);
        out.push((s, e));
        s = e;
    }
    out
}

/// The FIRE iterations from the state's start, counting on from `steps`: the step count and
/// the final residual, or `None` when contact was lost under tension (the step count in
/// `st.detached_at`).
fn relax(
    st: &mut State<'_>,
    opts: &GfmdOptions,
    (dt_max, steps): (f64, usize),
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Option<(usize, f64)>> {
    let n = st.n;
    let dt_min = 0.02 * dt_max;
    let mut dt = 0.5 * dt_max;
    let mut alpha = ALPHA_START;
    let mut n_pos = 0usize;
    let mut it = steps;
    let mut detaching = 0usize;
    let residual;
    loop {
        let sums = st.forces();
        let (ff, ss, fv, vvs) = (sums[0], sums[1], sums[2], sums[3]);
        let r = if ss > 0.0 { (ff / ss).sqrt() } else { f64::INFINITY };
        if !r.is_finite() || !ff.is_finite() {
            return Err(Error::NotConverged {
                solver: crate::error::Solver::Gfmd,
                reason: format!("non-finite force after {it} steps (diverged)"),
            });
        }
        if it.is_multiple_of(opts.progress_every.max(1)) {
            progress(Progress {
                stage: Stage::Relax,
                iteration: it,
                residual: r,
                contact_fraction: sums[4] / n as f64,
            });
        }
        if r <= opts.tolerance {
            residual = r;
            break;
        }
        if cancel.load(Ordering::Relaxed) {
            return Err(Error::Cancelled);
        }
        if it >= opts.max_iterations {
            return Err(out_of_steps(r, opts.tolerance, it));
        }
        detaching = if st.lifting(sums[4]) { detaching + 1 } else { 0 };
        if detaching >= DETACH_STEPS {
            st.detached_at = it;
            return Ok(None);
        }
        let vv = if fv > 0.0 {
            n_pos += 1;
            if n_pos > N_DELAY {
                dt = (dt * F_INC).min(dt_max);
                alpha *= F_ALPHA;
            }
            vvs + 2.0 * dt * fv + dt * dt * ff
        } else {
            n_pos = 0;
            dt = (dt * F_DEC).max(dt_min);
            alpha = ALPHA_START;
            st.retreat(dt);
            dt * dt * ff
        };
        st.advance(dt, alpha, ff.sqrt(), vv);
        it += 1;
    }
    Ok(Some((it, residual)))
}

/// The error of a relaxation that used up its steps at residual `r`.
fn out_of_steps(r: f64, tolerance: f64, it: usize) -> Error {
    Error::NotConverged {
        solver: crate::error::Solver::Gfmd,
        reason: format!(
            "relative force residual {r:.3e} > tolerance {tolerance:.1e} after {it} steps (max iterations)"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_split_at_global_chunks() {
        assert_eq!(pieces(0, 2 * CHUNK), vec![(0, CHUNK), (CHUNK, 2 * CHUNK)]);
        assert_eq!(pieces(100, CHUNK), vec![(0, CHUNK - 100), (CHUNK - 100, CHUNK)]);
        assert_eq!(pieces(5, 10), vec![(0, 10)]);
        assert!(pieces(0, 0).is_empty());
    }
}
