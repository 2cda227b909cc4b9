//! The FIRE minimiser on the whole map (the serial run): the set-up (stiffness, start,
//! Polonsky–Keer first on a hard wall) and the FIRE iterations of [`super::relax`] on one rank,
//! the same code that relaxes each rank's slab of a run over ranks ([`super::distributed`]).
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

use super::distributed::comm::{Comm, Solo};
use super::distributed::fire::slab_kernel;
use super::problem::{Layout, MapRows};
use super::relax::{adhesion_units, fire, start_positions, stiffness_at, Convolver, Start};
pub use super::relax::{Relaxation, DT_MAX};
use super::{GfmdOptions, Problem, Progress, Solution, Stage};
use crate::error::{Error, Result};
use crate::numerics::fft2::RealFft2;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// Polonsky–Keer stops when the gap on the contact set and the overlap elsewhere are below
/// this × tolerance × h_rms; FIRE then checks the force residual.
pub const PK_GAP_TOL: f64 = 0.1;

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
    relax_from(&Solo, problem, opts, start_gap, progress, cancel)?.equilibrium()
}

/// [`solve_from`] on any layout of the map, telling a loss of contact under tension
/// ([`Relaxation::ContactLost`]) apart from an equilibrium; the load cycle ([`super::cycle`])
/// steps into tension with it. On the whole map ([`Solo`]) Polonsky–Keer starts the hard wall
/// where [`super::Method::uses_pk`] says; on a rank's slab FIRE relaxes alone with the slab FFT
/// ([`super::distributed::fire`]), every rank calling it with the same problem and options, and
/// `start_gap` and the returned solution hold this rank's rows.
///
/// # Errors
/// As [`solve_from`]; [`Error::Unsupported`] for `Method::PolonskyKeer` on the hard wall of a
/// slab (not distributed).
pub fn relax_from<M: MapRows>(
    comm: &dyn Comm,
    problem: &Problem<'_, M>,
    opts: &GfmdOptions,
    start_gap: Option<&[f64]>,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<Relaxation> {
    crate::work::start();
    problem.validate(comm)?;
    opts.validate()?;
    let layout = problem.surface.layout();
    let whole = matches!(layout, Layout::Whole(_));
    if !whole && problem.gamma == 0.0 && opts.method == super::Method::PolonskyKeer {
        return Err(Error::Unsupported(
            "Polonsky-Keer is not distributed over ranks: use FIRE (or Auto, which is FIRE on ranks)".into(),
        ));
    }
    let t0 = Instant::now();
    let ((nx, ny, da), heights, offset) = layout.rows();
    let n = nx * ny;
    let e = problem.modulus;
    let h: Vec<f64> = heights.iter().map(|x| x / da).collect();
    let (adh_stress, inv_range) = adhesion_units(problem.gamma, problem.range, e, da);
    let mut w0 = start_positions(comm, &h, start_gap, da)?;
    let mut pk_steps = 0;
    let (conv, phi_max) = if whole {
        let mut plan = RealFft2::new(nx, ny);
        let (phi, phi_max) = stiffness((nx, ny, da), problem.thickness, plan.nh());
        if problem.gamma == 0.0 && opts.method.uses_pk(n, problem.thickness.is_infinite()) {
            let p0 = problem.pressure / e;
            (w0, pk_steps) = pk_start(p0, opts, &mut plan, (&phi, &h), progress, cancel)?;
        }
        let kernel = plan.kernel(&phi.iter().map(|p| p * (1.0 / n as f64)).collect::<Vec<_>>());
        (Convolver::Whole(plan, kernel), phi_max)
    } else {
        slab_kernel(comm, (nx, ny, da), problem.thickness)
    };
    let start = Start {
        nodes: n,
        offset,
        h,
        w: w0,
        loads: (problem.pressure / e, adh_stress, inv_range),
        omega_sq: phi_max + adh_stress * inv_range,
        steps: pk_steps,
        units: (da, e),
    };
    // the time of the whole relaxation, Polonsky–Keer's included
    Ok(match fire(comm, conv, start, opts, progress, cancel)? {
        Relaxation::Equilibrium(sol) => Relaxation::Equilibrium(Solution {
            elapsed_s: t0.elapsed().as_secs_f64(),
            ..sol
        }),
        lost => lost,
    })
}

/// The stiffness φ(q) = q f(qt)/2 in units of E*/Δa on the half spectrum (nh × ny) of an
/// nx × ny map of spacing Δa on a body of thickness `thickness` (m), and its largest value.
fn stiffness((nx, ny, da): (usize, usize, f64), thickness: f64, nh: usize) -> (Vec<f64>, f64) {
    let mut phi = vec![0.0; nh * ny];
    let mut phi_max: f64 = 0.0;
    for kx in 0..nh {
        for ky in 0..ny {
            let p = stiffness_at(kx, ky, (nx, ny, da), thickness);
            phi[ky * nh + kx] = p;
            phi_max = phi_max.max(p);
        }
    }
    (phi, phi_max)
}

/// Relaxes the hard wall with Polonsky–Keer (`phi`: the stiffness, `h`: the heights in Δa)
/// from its cold start (a pressure guessed from the heights, see [`super::pk`]), whatever start
/// the caller has: the positions on or above the heights and the iterations taken.
///
/// Polonsky–Keer does not start from the previous load's contact pressure: on a 32² system-I
/// sweep with 4 % load steps that start took 168–925 iterations at 10 of 19 loads and
/// 15 000–83 000 at the other 9, with the contact no longer changing, against 26–31 from the
/// uniform pressure (BENCHMARKS.md). From the cold start each load of a sweep is also the
/// single run's answer, bit for bit.
fn pk_start(
    p0: f64,
    opts: &GfmdOptions,
    plan: &mut RealFft2,
    (phi, h): (&[f64], &[f64]),
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<(Vec<f64>, usize)> {
    let n = h.len();
    // all zero: `pk::relax` starts from its guess made from the heights
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
        p0,
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
