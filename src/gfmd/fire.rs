//! The FIRE minimiser.
//!
//! FIRE (Bitzek et al., PRL 97, 170201, 2006) in the semi-implicit "FIRE 2.0" form (Guénolé
//! et al., Comput. Mater. Sci. 175, 109584, 2020), in real space, unit masses, with
//! projection: after every position update nodes below the wall are put on it and their
//! velocity set to zero (physics.md §6). Time step dt_max = [`DT_MAX`]/ω_max with ω_max² =
//! φ_max + γ/ρ² (the stiffest mode plus the largest curvature of v). The elastic force needs
//! one forward and one inverse real-to-complex FFT per step, planned once per run and fused
//! into one convolution ([`crate::numerics::fft2::RealFft2::convolve`]); node loops run on rayon for
//! large grids, with partial sums in a fixed order so that a seeded run is bit-for-bit
//! reproducible whatever the thread count. Internally lengths are in units of Δa and stresses
//! in units of E* (inputs and outputs are SI). Typical cost of FIRE alone at p* = 0.01,
//! tolerance 1e-8: ~300 steps on 128², ~475 on 512² (≈ 1 s), ~585 on 1024²; adhesion adds
//! ~10–100 %. Without adhesion, on a semi-infinite body, the default [`super::Method::Auto`]
//! uses Polonsky–Keer, which relaxes the contact in 60–160 CG iterations (256²–4096², two
//! convolutions each) and FIRE then finds the force residual already met (BENCHMARKS.md).
//! (A mass-weighted variant, m(q) ∝ φ(q) with the same projection, stalled at a residual of
//! order 1 on these problems, as physics.md §6 warns; it is not offered.)
//!
//! Start: w = max h everywhere (the flat body touches the highest summit), v = 0. Without
//! adhesion the minimum is unique. With adhesion the energy has many local minima (contact
//! hysteresis); the one reached is that of loading from first touch at the given p₀, and it
//! can differ noticeably between realisations at small p*.
//!
//! Convergence criterion: the relative force residual
//!
//! ```text
//! r = rms(F_P) / rms(σ)          (both over all nodes)
//! ```
//!
//! must fall below `tolerance` (default 1e-8). Since rms(σ) ≥ |⟨σ⟩| = p₀ at equilibrium, r
//! bounds the relative error of the load balance and of every non-contact node's stress.
//!

use super::{GfmdOptions, Problem, Progress, Solution, Stage};
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
/// Polonsky–Keer stops when the gap on the contact set and the overlap elsewhere are below
/// this × tolerance × h_rms; FIRE then checks the force residual.
pub const PK_GAP_TOL: f64 = 0.1;

/// Under tension with no node on the wall, contact is taken as lost once the largest possible
/// attraction (γ/ρ)e^{−g_min/ρ} has stayed below this fraction of |p₀| for [`DETACH_STEPS`]
/// steps: the mean force −p₀ − ⟨v′(g)⟩ then lifts the body, and lifting only weakens the
/// attraction (no equilibrium remains: past pull-off).
pub(crate) const DETACH_FRACTION: f64 = 0.5;
/// Consecutive steps the detachment condition must hold (see [`DETACH_FRACTION`]).
pub(crate) const DETACH_STEPS: usize = 20;

/// Per-chunk partial sums of the node loop (`gmin`: the smallest gap, in Δa).
#[derive(Debug, Clone, Copy)]
struct Sums {
    ff: f64,
    ss: f64,
    fv: f64,
    vv: f64,
    wall: usize,
    gmin: f64,
}

impl Default for Sums {
    fn default() -> Self {
        Sums {
            ff: 0.0,
            ss: 0.0,
            fv: 0.0,
            vv: 0.0,
            wall: 0,
            gmin: f64::INFINITY,
        }
    }
}

impl Sums {
    fn add(self, o: Sums) -> Sums {
        Sums {
            ff: self.ff + o.ff,
            ss: self.ss + o.ss,
            fv: self.fv + o.fv,
            vv: self.vv + o.vv,
            wall: self.wall + o.wall,
            gmin: self.gmin.min(o.gmin),
        }
    }
}

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

/// The solver state in internal units: lengths in Δa, stresses in E*.
struct State {
    n: usize,
    plan: RealFft2,
    /// φ(q)/n (half spectrum), the convolution kernel.
    kernel: SpectralKernel,
    h: Vec<f64>,
    w: Vec<f64>,
    v: Vec<f64>,
    f: Vec<f64>,
    conv: Vec<f64>,
    spec: Vec<Complex64>,
    p0: f64,
    /// γ/ρ and 1/ρ in internal units (0 without adhesion).
    adh_stress: f64,
    inv_range: f64,
    parallel: bool,
}

impl State {
    /// Computes forces and the projected force; returns the sums over nodes.
    fn forces(&mut self) -> Sums {
        // φ⋆w = IFFT[φ · FFT(w)/n]; `kernel` holds φ/n
        self.plan
            .convolve(&self.w, &self.kernel, &mut self.spec, &mut self.conv);
        let (p0, a, ir) = (self.p0, self.adh_stress, self.inv_range);
        let body = |f: &mut [f64], c: &[f64], w: &[f64], h: &[f64], v: &[f64]| -> Sums {
            let mut s = Sums::default();
            for i in 0..f.len() {
                let sigma = p0 + c[i];
                let g = w[i] - h[i];
                s.gmin = s.gmin.min(g);
                let mut fi = -sigma;
                // e^{−g/ρ} < 1e-17 beyond g = 40ρ: below round-off of every stress here
                if a > 0.0 && g * ir < EXP_CUTOFF {
                    fi -= a * (-g * ir).exp();
                }
                if g <= 0.0 {
                    s.wall += 1;
                    if fi < 0.0 {
                        fi = 0.0;
                    }
                }
                f[i] = fi;
                s.ff += fi * fi;
                s.ss += sigma * sigma;
                s.fv += fi * v[i];
                s.vv += v[i] * v[i];
            }
            s
        };
        if self.parallel {
            use rayon::prelude::*;
            let parts: Vec<Sums> = self
                .f
                .par_chunks_mut(CHUNK)
                .zip(self.conv.par_chunks(CHUNK))
                .zip(self.w.par_chunks(CHUNK))
                .zip(self.h.par_chunks(CHUNK))
                .zip(self.v.par_chunks(CHUNK))
                .map(|((((f, c), w), h), v)| body(f, c, w, h, v))
                .collect();
            parts.into_iter().fold(Sums::default(), Sums::add)
        } else {
            let mut tot = Sums::default();
            for k in (0..self.n).step_by(CHUNK) {
                let e = (k + CHUNK).min(self.n);
                let s = body(
                    &mut self.f[k..e],
                    &self.conv[k..e],
                    &self.w[k..e],
                    &self.h[k..e],
                    &self.v[k..e],
                );
                tot = tot.add(s);
            }
            tot
        }
    }

    /// v += dt F; v = (1−α)v + α|v|/|F| F; w += dt v; projection onto g ≥ 0. `vv` is |v + dt F|²
    /// (from the sums of the force pass, so that one pass over the nodes suffices).
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

    /// The relaxed configuration in SI units (`units`: Δa in m, E* in Pa; `steps`: the steps
    /// taken, of which Polonsky–Keer's, and the final residual), after a last progress report.
    fn solution(
        &self,
        (da, e): (f64, f64),
        (it, pk_steps, residual): (usize, usize, f64),
        t0: Instant,
        progress: &mut dyn FnMut(Progress),
    ) -> Solution {
        let st = self;
        let n = st.n;
        let gap: Vec<f64> = st.w.iter().zip(&st.h).map(|(w, h)| (w - h).max(0.0) * da).collect();
        let stress: Vec<f64> = st.conv.iter().map(|c| (st.p0 + c) * e).collect();
        let on_wall: Vec<bool> = st.w.iter().zip(&st.h).map(|(w, h)| w <= h).collect();
        progress(Progress {
            stage: Stage::Relax,
            iteration: it,
            residual,
            contact_fraction: on_wall.iter().filter(|&&b| b).count() as f64 / n as f64,
        });
        Solution {
            gap,
            stress,
            on_wall,
            iterations: it,
            pk_iterations: pk_steps,
            residual,
            elapsed_s: t0.elapsed().as_secs_f64(),
        }
    }

    /// Uphill step: w −= ½ dt v (projected), v = 0.
    fn retreat(&mut self, dt: f64) {
        for i in 0..self.n {
            self.w[i] = (self.w[i] - 0.5 * dt * self.v[i]).max(self.h[i]);
            self.v[i] = 0.0;
        }
    }
}

/// Relaxes the contact under load control. See the module docs for the model, the
/// minimiser and the convergence criterion.
pub fn solve(
    problem: &Problem<'_>,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Solution> {
    solve_from(problem, opts, None, progress, cancel)
}

/// [`solve`] from a given start: `start_gap` (m, one per node, e.g. the relaxed gap of a
/// neighbouring load) instead of the flat body touching the highest summit. With adhesion, or
/// with FIRE alone, FIRE relaxes from that start. Without adhesion and with Polonsky–Keer
/// ([`super::Method::uses_pk`]: the default on a half-space) the contact is relaxed by
/// Polonsky–Keer CG ([`super::pk`]) from the uniform pressure p₀ whatever the start (its
/// 20–160 iterations are fewer than a warm start took, see `pk_start`), and FIRE then checks,
/// and if needed finishes, the same force residual: the answer is then [`solve`]'s, bit for
/// bit.
pub fn solve_from(
    problem: &Problem<'_>,
    opts: &GfmdOptions,
    start_gap: Option<&[f64]>,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Solution> {
    match relax_from(problem, opts, start_gap, progress, cancel)? {
        Relaxation::Equilibrium(sol) => Ok(sol),
        Relaxation::ContactLost { iterations } => Err(Error::NotConverged {
            solver: crate::error::Solver::Gfmd,
            reason: format!(
                "contact lost after {iterations} steps: the tensile load is beyond what adhesion holds (past pull-off)"
            ),
        }),
    }
}

/// [`solve_from`], telling a loss of contact under tension ([`Relaxation::ContactLost`])
/// apart from an equilibrium; the load cycle ([`super::cycle`]) steps into tension with it.
pub fn relax_from(
    problem: &Problem<'_>,
    opts: &GfmdOptions,
    start_gap: Option<&[f64]>,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Relaxation> {
    crate::work::start();
    problem.validate()?;
    opts.validate()?;
    let t0 = Instant::now();
    let s = problem.surface;
    let (nx, ny, da) = (s.nx, s.ny, s.spacing);
    let n = nx * ny;
    let e = problem.modulus;
    let mut plan = RealFft2::new(nx, ny);
    let nh = plan.nh();
    let (phi, phi_max) = stiffness(problem, nh);
    let h: Vec<f64> = s.heights.iter().map(|x| x / da).collect();
    let (adh_stress, inv_range) = adhesion_units(problem, da);
    let mut w0 = start_positions(&h, start_gap, da)?;
    let mut pk_steps = 0;
    if problem.gamma == 0.0 && opts.method.uses_pk(n, problem.thickness.is_infinite()) {
        (w0, pk_steps) = pk_start(problem, opts, &mut plan, (&phi, &h), progress, cancel)?;
    }
    let omega = (phi_max + adh_stress * inv_range).sqrt();
    let dt_max = DT_MAX / omega;
    let dt_min = 0.02 * dt_max;
    let kernel = plan.kernel(&phi.iter().map(|p| p * (1.0 / n as f64)).collect::<Vec<_>>());
    let mut st = State {
        n,
        plan,
        kernel,
        w: w0,
        h,
        v: vec![0.0; n],
        f: vec![0.0; n],
        conv: vec![0.0; n],
        spec: vec![Complex64::new(0.0, 0.0); nh * ny],
        p0: problem.pressure / e,
        adh_stress,
        inv_range,
        parallel: n >= PARALLEL_MIN_NODES,
    };
    let mut dt = 0.5 * dt_max;
    let mut alpha = ALPHA_START;
    let mut n_pos = 0usize;
    let mut it = pk_steps;
    let mut detaching = 0usize;
    let residual;
    loop {
        let sums = st.forces();
        let r = if sums.ss > 0.0 {
            (sums.ff / sums.ss).sqrt()
        } else {
            f64::INFINITY
        };
        if !r.is_finite() || !sums.ff.is_finite() {
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
                contact_fraction: sums.wall as f64 / n as f64,
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
        let lifting = st.p0 < 0.0
            && sums.wall == 0
            && st.adh_stress * (-sums.gmin * st.inv_range).exp() < -DETACH_FRACTION * st.p0;
        detaching = if lifting { detaching + 1 } else { 0 };
        if detaching >= DETACH_STEPS {
            return Ok(Relaxation::ContactLost { iterations: it });
        }
        let vv = if sums.fv > 0.0 {
            n_pos += 1;
            if n_pos > N_DELAY {
                dt = (dt * F_INC).min(dt_max);
                alpha *= F_ALPHA;
            }
            sums.vv + 2.0 * dt * sums.fv + dt * dt * sums.ff
        } else {
            n_pos = 0;
            dt = (dt * F_DEC).max(dt_min);
            alpha = ALPHA_START;
            st.retreat(dt);
            dt * dt * sums.ff
        };
        st.advance(dt, alpha, sums.ff.sqrt(), vv);
        it += 1;
    }
    Ok(Relaxation::Equilibrium(st.solution(
        (da, e),
        (it, pk_steps, residual),
        t0,
        progress,
    )))
}

/// The stiffness φ(q) = q f(qt)/2 in units of E*/Δa on the half spectrum (nh × ny), and its
/// largest value.
fn stiffness(problem: &Problem<'_>, nh: usize) -> (Vec<f64>, f64) {
    let s = problem.surface;
    let (nx, ny, da) = (s.nx, s.ny, s.spacing);
    let mut phi = vec![0.0; nh * ny];
    let mut phi_max: f64 = 0.0;
    for kx in 0..nh {
        for ky in 0..ny {
            let q = wave_number_sq(kx, ky, nx, ny, da).sqrt();
            let p = 0.5 * q * da * slab_factor_at(q, problem.thickness);
            phi[ky * nh + kx] = p;
            phi_max = phi_max.max(p);
        }
    }
    (phi, phi_max)
}

/// γ/ρ in E* and 1/ρ in 1/Δa (both 0 without adhesion).
fn adhesion_units(problem: &Problem<'_>, da: f64) -> (f64, f64) {
    match problem.gamma > 0.0 {
        true => (problem.gamma / (problem.range * problem.modulus), da / problem.range),
        false => (0.0, 0.0),
    }
}

/// The body's start (in Δa): the flat body on the highest summit, or the heights plus a given
/// gap (m, one finite value per node).
fn start_positions(h: &[f64], start_gap: Option<&[f64]>, da: f64) -> Result<Vec<f64>> {
    let n = h.len();
    let hmax = h.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
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

/// Relaxes the hard wall with Polonsky–Keer (`phi`: the stiffness, `h`: the heights in Δa)
/// from the uniform pressure p₀, whatever start the caller has: the positions on or above the
/// heights and the iterations taken.
///
/// Polonsky–Keer does not start from the previous load's contact pressure: on a 32² system-I
/// sweep with 4 % load steps that start took 168–925 iterations at 10 of 19 loads and
/// 15 000–83 000 at the other 9, with the contact no longer changing, against 26–31 from the
/// uniform pressure (BENCHMARKS.md). From the uniform pressure each load of a sweep is also the
/// single run's answer, bit for bit.
fn pk_start(
    problem: &Problem<'_>,
    opts: &GfmdOptions,
    plan: &mut RealFft2,
    (phi, h): (&[f64], &[f64]),
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<(Vec<f64>, usize)> {
    let n = h.len();
    let e = problem.modulus;
    // all zero: `pk::relax` starts from p₀ on every node
    let p_start = vec![0.0; n];
    let h_rms = {
        let m = h.iter().sum::<f64>() / n as f64;
        (h.iter().map(|x| (x - m).powi(2)).sum::<f64>() / n as f64).sqrt()
    };
    let (w, its) = super::pk::relax(
        plan,
        phi,
        h,
        p_start,
        problem.pressure / e,
        PK_GAP_TOL * opts.tolerance * h_rms,
        opts.max_iterations,
        &mut |it, err, frac| {
            if it % opts.progress_every.max(1) == 0 {
                progress(Progress {
                    stage: Stage::Relax,
                    iteration: it,
                    residual: err / h_rms,
                    contact_fraction: frac,
                })
            }
        },
        cancel,
    )?;
    Ok((w.iter().zip(h).map(|(w, h)| w.max(*h)).collect(), its))
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
