//! FIRE on slabs: [`crate::gfmd::fire`]'s minimiser with every node loop over the rank's rows,
//! the elastic force through the slab FFT ([`super::slab_fft`]) and the force sums folded in
//! the serial order ([`super::comm::chain_fold`]).
//!
//! The serial solver adds the per-node terms of F², σ², F·v and v² within fixed chunks of
//! 4096 nodes (global index order) and then the chunk sums in order. Here each rank splits
//! its node range at the same global chunk boundaries and sums its pieces in parallel; the
//! fold then passes (total, open chunk's partial) from rank to rank: a piece that starts inside
//! a chunk continues the partial it received (its terms added in node order), a piece that
//! closes a chunk adds it to the total. The sums, hence dt, α, every position and the step
//! count, equal the serial run's bit for bit for any number of ranks.
//!
//! Under tension the loss of contact is detected as in the serial solver
//! ([`crate::gfmd::fire::relax_from`]): the smallest gap enters through an all-reduce of
//! minima (exact in any order), only while no node is on the wall under a tensile load.
//!
//! Polonsky–Keer ([`crate::gfmd::pk`]) is not distributed: a hard-wall run relaxes with FIRE
//! alone (the serial `Method::Fire`).

use super::comm::{all_max, all_min, all_sum_counts, chain_fold, Comm};
use super::map::Slab;
use super::slab_fft::SlabFft;
use crate::error::{Error, Result};
use crate::gfmd::fire::{
    Relaxation, ALPHA_START, CHUNK, DETACH_FRACTION, DETACH_STEPS, DT_MAX, EXP_CUTOFF, F_ALPHA, F_DEC, F_INC, N_DELAY,
    PARALLEL_MIN_NODES,
};
use crate::gfmd::{GfmdOptions, Progress, Solution, Stage};
use crate::surface::heightmap::wave_number_sq;
use crate::theory::slab::slab_factor_at;
use rustfft::num_complex::Complex64;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// One contact problem on a slab (physical units, as [`crate::gfmd::Problem`]).
#[derive(Debug, Clone, Copy)]
pub struct SlabProblem<'a> {
    /// This rank's rows of the substrate.
    pub slab: &'a Slab,
    /// Contact modulus E* (Pa).
    pub modulus: f64,
    /// Slab thickness t (m); `f64::INFINITY` = semi-infinite.
    pub thickness: f64,
    /// Nominal pressure p₀ (Pa).
    pub pressure: f64,
    /// Surface energy γ (J/m²).
    pub gamma: f64,
    /// Range ρ (m).
    pub range: f64,
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
    fft: SlabFft,
    kernel: Vec<f64>,
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
        self.fft
            .convolve(self.comm, &self.w, &self.kernel, &mut self.spec, &mut self.conv);
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
            let fp = super::comm::SendPtr(self.f.as_mut_ptr());
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

/// [`crate::gfmd::solve_from`] with FIRE on this rank's slab: `start_gap` (m) is this rank's
/// rows of the start; the returned [`Solution`] holds this rank's rows. Every rank must call
/// it with the same problem and options.
///
/// # Errors
/// As [`crate::gfmd::solve_from`]; [`Error::Unsupported`] for `Method::PolonskyKeer` on a hard
/// wall (not distributed).
pub fn solve_slab(
    comm: &dyn Comm,
    problem: &SlabProblem<'_>,
    opts: &GfmdOptions,
    start_gap: Option<&[f64]>,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Solution> {
    match relax_slab_from(comm, problem, opts, start_gap, progress, cancel)? {
        Relaxation::Equilibrium(sol) => Ok(sol),
        Relaxation::ContactLost { iterations } => Err(Error::NotConverged {
            solver: crate::error::Solver::Gfmd,
            reason: format!(
                "contact lost after {iterations} steps: the tensile load is beyond what adhesion holds (past pull-off)"
            ),
        }),
    }
}

/// [`solve_slab`], telling a loss of contact under tension apart from an equilibrium, as
/// [`crate::gfmd::fire::relax_from`] does (the load cycle over ranks steps into tension with
/// it).
///
/// # Errors
/// As [`solve_slab`].
pub fn relax_slab_from(
    comm: &dyn Comm,
    problem: &SlabProblem<'_>,
    opts: &GfmdOptions,
    start_gap: Option<&[f64]>,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Relaxation> {
    crate::work::start();
    crate::gfmd::problem::check_loads(
        problem.modulus,
        problem.thickness,
        problem.pressure,
        problem.gamma,
        problem.range,
    )?;
    let (lo, hi) = problem
        .slab
        .heights
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| (a.min(h), b.max(h)));
    if all_min(comm, lo) == all_max(comm, hi) {
        return Err(Error::invalid_text(
            crate::error::Field::HeightMap,
            "a flat map",
            "a height map with some roughness",
        ));
    }
    opts.validate()?;
    if problem.gamma == 0.0 && opts.method == crate::gfmd::Method::PolonskyKeer {
        return Err(Error::Unsupported(
            "Polonsky-Keer is not distributed over ranks: use FIRE (or Auto, which is FIRE on ranks)".into(),
        ));
    }
    let t0 = Instant::now();
    let s = problem.slab;
    let (nx, ny, da) = (s.nx, s.ny, s.spacing);
    let n = nx * ny;
    let e = problem.modulus;
    let fft = SlabFft::new(nx, ny, comm.rank(), comm.size());
    let (c0, c1) = fft.my_cols();
    let mut kernel = vec![0.0; (c1 - c0) * ny];
    let mut phi_max: f64 = 0.0;
    for kx in c0..c1 {
        for ky in 0..ny {
            let q = wave_number_sq(kx, ky, nx, ny, da).sqrt();
            let p = 0.5 * q * da * slab_factor_at(q, problem.thickness);
            kernel[(kx - c0) * ny + ky] = p * (1.0 / n as f64);
            phi_max = phi_max.max(p);
        }
    }
    let phi_max = all_max(comm, phi_max);
    let h: Vec<f64> = s.heights.iter().map(|x| x / da).collect();
    let hmax = all_max(comm, h.iter().cloned().fold(f64::NEG_INFINITY, f64::max));
    let (adh_stress, inv_range) = if problem.gamma > 0.0 {
        (problem.gamma / (problem.range * e), da / problem.range)
    } else {
        (0.0, 0.0)
    };
    let nl = h.len();
    let mut w0 = vec![hmax; nl];
    if let Some(g) = start_gap {
        if g.len() != nl || g.iter().any(|x| !x.is_finite()) {
            return Err(Error::Unsupported(format!(
                "a start gap needs {nl} finite values on this rank (got {})",
                g.len()
            )));
        }
        for i in 0..nl {
            w0[i] = h[i] + (g[i] / da).max(0.0);
        }
    }
    let omega = (phi_max + adh_stress * inv_range).sqrt();
    let dt_max = DT_MAX / omega;
    let spec_len = fft.local_spectrum_len();
    let mut st = State {
        comm,
        n,
        offset: s.offset(),
        fft,
        kernel,
        w: w0,
        h,
        v: vec![0.0; nl],
        f: vec![0.0; nl],
        conv: vec![0.0; nl],
        spec: vec![Complex64::new(0.0, 0.0); spec_len],
        p0: problem.pressure / e,
        adh_stress,
        inv_range,
        pieces: pieces(s.offset(), nl),
        parallel: nl >= PARALLEL_MIN_NODES,
        detached_at: 0,
    };
    let Some((it, residual)) = relax(&mut st, opts, dt_max, progress, cancel)? else {
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
        contact_fraction: walls as f64 / n as f64,
    });
    Ok(Relaxation::Equilibrium(Solution {
        gap,
        stress,
        on_wall,
        iterations: it,
        pk_iterations: 0,
        residual,
        elapsed_s: t0.elapsed().as_secs_f64(),
    }))
}

/// The FIRE iterations from the state's start (see [`crate::gfmd::fire`]): the step count and
/// the final residual, or `None` when contact was lost under tension (the step count in
/// `st.detached_at`).
fn relax(
    st: &mut State<'_>,
    opts: &GfmdOptions,
    dt_max: f64,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Option<(usize, f64)>> {
    let n = st.n;
    let dt_min = 0.02 * dt_max;
    let mut dt = 0.5 * dt_max;
    let mut alpha = ALPHA_START;
    let mut n_pos = 0usize;
    let mut it = 0usize;
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
            return Err(Error::NotConverged {
                solver: crate::error::Solver::Gfmd,
                reason: format!(
                    "relative force residual {r:.3e} > tolerance {:.1e} after {it} steps (max iterations)",
                    opts.tolerance
                ),
            });
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
