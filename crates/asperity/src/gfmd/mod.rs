//! Green's function molecular dynamics (GFMD): the brute-force reference for the theory.
//!
//! ## Model (physics.md §2, §6)
//!
//! A rigid, rough substrate with heights h(r) (a [`Surface`], periodic, N_x × N_y nodes of
//! spacing Δa) is pressed against a linearly elastic body whose surface sits at w(r) above it;
//! the gap is g = w − h ≥ 0. The energy per nominal area is
//!
//! ```text
//! E[w] = ½ Σ_{q≠0} φ(q) |w̃(q)|²  +  p₀ w̃(0)  +  ⟨v(g)⟩,      φ(q) = q E* f(qt) / 2
//! ```
//!
//! with w̃ = FFT(w)/(N_x N_y) (physics.md §1), f the slab factor of a body of thickness t with a
//! constant-stress far side ([`crate::theory::slab`]; f = 1 for a semi-infinite body). The q = 0 mode
//! has no stiffness: it carries the external load p₀ (load control). Interactions: a hard wall
//! g ≥ 0 (imposed by projection) and, when γ > 0, the attraction v(g) = −γ e^{−g/ρ} (tensile
//! stress γ/ρ at contact).
//!
//! The nodal force per node area (a stress) is F(r) = −p₀ − (φ⋆w)(r) − v′(g(r)),
//! (φ⋆w)(r) = Σ_q φ(q) w̃(q) e^{iq·r}. On nodes that sit on the wall (g = 0) a force pushing
//! into the wall (F < 0) is the wall's reaction and is removed (projected force F_P). The
//! interfacial stress (compressive positive) is σ(r) = p₀ + (φ⋆w)(r); its mean is p₀ at
//! equilibrium.
//!
//! ## Minimiser
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
//! in units of E* (inputs and outputs are SI). Typical cost at p* = 0.01, tolerance 1e-8:
//! ~300 steps on 128², ~475 on 512² (≈ 1 s), ~585 on 1024²; adhesion adds ~10–100 %.
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
//! ## Measurements ([`measure`]; reduced units σ* = σ/(E*ḡ), ḡ the map's discrete rms gradient)
//!
//! - contact: a node is in contact when it sits on the hard wall (g = 0 after projection, or
//!   g ≤ `contact_gap` if that is set > 0). With adhesion the contact stress can be tensile,
//!   down to −γ/ρ; nodes off the wall feel the attraction but are not counted;
//! - a_r: fraction of nodes in contact; σ̄_c*, ⟨δσ_c²⟩*: mean and variance of σ* over contact
//!   nodes (without adhesion σ̄_c = p₀/a_r to within the residual);
//! - Pr(σ*): histogram of σ* over contact nodes, counts divided by all nodes and by the bin
//!   width, so that ∫Pr dσ* = a_r exactly;
//! - ū = ⟨g⟩ over all nodes (m), and ū/h_rms.
//!
//! ## Library API (what the TUI calls from a worker thread)
//!
//! - [`solve`]`(&Problem, &GfmdOptions, progress, cancel) -> Result<Solution>`: the solver on
//!   a given map, physical units.
//! - [`run`]`(&GfmdSetup, &GfmdOptions, progress, cancel) -> Result<GfmdResult>`: a scene and
//!   a reduced grid: generates (or takes) the map, solves, measures, and evaluates the theory
//!   on the map's own discrete spectrum for a like-for-like comparison (theory `None` with the
//!   reason when the engine cannot evaluate the scene).
//!
//! `progress` is called every [`GfmdOptions::progress_every`] steps with a [`Progress`];
//! setting `cancel` makes the solver return [`Error::Cancelled`] within one step.

use crate::contact::{ContactStats, PrCurve};
use crate::error::{Error, Result};
use crate::input::scene::Scene;
use crate::numerics::fft2::RealFft2;
use crate::surface::heightmap::{self, wave_number_sq, Surface};
use crate::surface::spectrum::{Normalisation, SelfAffine, Spectrum};
use crate::theory::engine;
use crate::theory::slab::slab_factor_at;
use rustfft::num_complex::Complex64;
use serde::Serialize;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// dt_max·ω_max of the FIRE integrator (semi-implicit Euler is stable below 2; 1.3 took the
/// fewest steps on system I/II test grids, 1.0 about 10 % more, 1.9 several times more).
pub const DT_MAX: f64 = 1.3;
/// FIRE: steps with positive power before dt grows and α shrinks (Bitzek N_min).
const N_DELAY: usize = 5;
/// FIRE: dt growth factor.
const F_INC: f64 = 1.1;
/// FIRE: dt shrink factor after an uphill step.
const F_DEC: f64 = 0.5;
/// FIRE: initial mixing α.
const ALPHA_START: f64 = 0.1;
/// FIRE: α decay factor.
const F_ALPHA: f64 = 0.99;
/// Beyond g/ρ = this the attraction is dropped (e^{−40} ≈ 4e-18).
const EXP_CUTOFF: f64 = 40.0;
/// Node-loop chunk (fixed, so that partial sums are added in the same order every run).
const CHUNK: usize = 4096;
/// Grids with at least this many nodes run their node loops on rayon.
const PARALLEL_MIN_NODES: usize = 1 << 15;

/// Solver options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GfmdOptions {
    /// Relative force residual to reach (see the module docs).
    pub tolerance: f64,
    /// Give up (with [`Error::NotConverged`]) after this many FIRE steps.
    pub max_iterations: usize,
    /// Number of bins of the Pr(σ*) histogram.
    pub pr_bins: usize,
    /// Call the progress callback every this many steps.
    pub progress_every: usize,
    /// Nodes with a gap at most this (m) count as contact; 0 = on the hard wall.
    pub contact_gap: f64,
}

impl Default for GfmdOptions {
    fn default() -> Self {
        GfmdOptions {
            tolerance: 1e-8,
            max_iterations: 200_000,
            pr_bins: 400,
            progress_every: 50,
            contact_gap: 0.0,
        }
    }
}

impl GfmdOptions {
    /// Checks the options, naming the field.
    pub fn validate(&self) -> Result<()> {
        if !(self.tolerance.is_finite() && self.tolerance >= 1e-14 && self.tolerance < 1.0) {
            return Err(Error::field("--tolerance", self.tolerance, "1e-14 <= tolerance < 1"));
        }
        if self.max_iterations == 0 {
            return Err(Error::field("--max-iterations", 0, "an integer >= 1"));
        }
        if !(1..=1_000_000).contains(&self.pr_bins) {
            return Err(Error::field("--bins", self.pr_bins, "1 <= bins <= 1000000"));
        }
        if !(self.contact_gap.is_finite() && self.contact_gap >= 0.0) {
            return Err(Error::field("contact_gap", self.contact_gap, "a gap >= 0 (m)"));
        }
        Ok(())
    }
}

/// One contact problem in physical units.
#[derive(Debug, Clone, Copy)]
pub struct Problem<'a> {
    /// The rigid rough substrate.
    pub surface: &'a Surface,
    /// Contact modulus E* (Pa).
    pub modulus: f64,
    /// Slab thickness t (m); `f64::INFINITY` = semi-infinite.
    pub thickness: f64,
    /// Nominal pressure p₀ (Pa), > 0.
    pub pressure: f64,
    /// Surface energy γ (J/m²); 0 = hard wall only.
    pub gamma: f64,
    /// Range ρ of the attraction (m); unused when γ = 0.
    pub range: f64,
}

impl Problem<'_> {
    /// Checks every field.
    pub fn validate(&self) -> Result<()> {
        if !(self.modulus.is_finite() && self.modulus > 0.0) {
            return Err(Error::field(
                "material.contact_modulus_pa",
                self.modulus,
                "a finite modulus > 0 (Pa)",
            ));
        }
        if self.thickness.is_nan() || self.thickness <= 0.0 {
            return Err(Error::field("--thickness", self.thickness, "t > 0, or inf"));
        }
        if !(self.pressure.is_finite() && self.pressure > 0.0) {
            return Err(Error::field("--pressure", self.pressure, "a pressure p > 0"));
        }
        if !(self.gamma.is_finite() && self.gamma >= 0.0) {
            return Err(Error::field("--gamma", self.gamma, "gamma >= 0 (J/m^2)"));
        }
        if self.gamma > 0.0 && !(self.range.is_finite() && self.range > 0.0) {
            return Err(Error::field("adhesion.range_m", self.range, "a finite length > 0 (m)"));
        }
        if self.surface.heights.iter().all(|&h| h == self.surface.heights[0]) {
            return Err(Error::field(
                "surface",
                "a flat map",
                "a height map with some roughness",
            ));
        }
        Ok(())
    }
}

/// A progress report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// FIRE steps so far.
    pub iteration: usize,
    /// Current relative force residual.
    pub residual: f64,
    /// Current fraction of nodes on the wall.
    pub contact_fraction: f64,
}

/// The relaxed configuration.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Gap g(r) = w − h (m), ≥ 0.
    pub gap: Vec<f64>,
    /// Interfacial stress σ(r) = p₀ + (φ⋆w)(r) (Pa, compressive positive).
    pub stress: Vec<f64>,
    /// Nodes on the hard wall.
    pub on_wall: Vec<bool>,
    /// FIRE steps taken.
    pub iterations: usize,
    /// Final relative force residual.
    pub residual: f64,
    /// Wall time of the solve (s).
    pub elapsed_s: f64,
}

/// Per-chunk partial sums of the node loop.
#[derive(Debug, Clone, Copy, Default)]
struct Sums {
    ff: f64,
    ss: f64,
    fv: f64,
    vv: f64,
    wall: usize,
}

impl Sums {
    fn add(self, o: Sums) -> Sums {
        Sums {
            ff: self.ff + o.ff,
            ss: self.ss + o.ss,
            fv: self.fv + o.fv,
            vv: self.vv + o.vv,
            wall: self.wall + o.wall,
        }
    }
}

/// The solver state in internal units: lengths in Δa, stresses in E*.
struct State {
    n: usize,
    plan: RealFft2,
    /// φ(q)/n (half spectrum), the convolution kernel.
    kernel: Vec<f64>,
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
    problem.validate()?;
    opts.validate()?;
    let t0 = Instant::now();
    let s = problem.surface;
    let (nx, ny, da) = (s.nx, s.ny, s.spacing);
    let n = nx * ny;
    let e = problem.modulus;
    let plan = RealFft2::new(nx, ny);
    let nh = plan.nh();
    // stiffness in units of E*/Δa
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
    let h: Vec<f64> = s.heights.iter().map(|x| x / da).collect();
    let hmax = h.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let (adh_stress, inv_range) = if problem.gamma > 0.0 {
        (problem.gamma / (problem.range * e), da / problem.range)
    } else {
        (0.0, 0.0)
    };
    let omega = (phi_max + adh_stress * inv_range).sqrt();
    let dt_max = DT_MAX / omega;
    let dt_min = 0.02 * dt_max;
    let mut st = State {
        n,
        plan,
        kernel: phi.iter().map(|p| p * (1.0 / n as f64)).collect(),
        w: vec![hmax; n],
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
    let mut it = 0usize;
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
                solver: "gfmd".into(),
                reason: format!("non-finite force after {it} steps (diverged)"),
            });
        }
        if it.is_multiple_of(opts.progress_every.max(1)) {
            progress(Progress {
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
            return Err(Error::NotConverged {
                solver: "gfmd".into(),
                reason: format!(
                    "relative force residual {r:.3e} > tolerance {:.1e} after {it} steps (max iterations)",
                    opts.tolerance
                ),
            });
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
    let gap: Vec<f64> = st.w.iter().zip(&st.h).map(|(w, h)| (w - h).max(0.0) * da).collect();
    let stress: Vec<f64> = st.conv.iter().map(|c| (st.p0 + c) * e).collect();
    let on_wall: Vec<bool> = st.w.iter().zip(&st.h).map(|(w, h)| w <= h).collect();
    progress(Progress {
        iteration: it,
        residual,
        contact_fraction: on_wall.iter().filter(|&&b| b).count() as f64 / n as f64,
    });
    Ok(Solution {
        gap,
        stress,
        on_wall,
        iterations: it,
        residual,
        elapsed_s: t0.elapsed().as_secs_f64(),
    })
}

/// Measured quantities of a relaxed contact (reduced stresses by E*ḡ of the map).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measurements {
    /// The fraction of nodes in contact, σ̄_c* and ⟨δσ_c²⟩* over contact nodes, and the Pr(σ*)
    /// histogram (bin centres, ∫ = a_r).
    #[serde(flatten)]
    pub stats: ContactStats,
    /// ū = ⟨g⟩ (m).
    pub mean_gap: f64,
    /// ū/h_rms.
    pub mean_gap_rel: f64,
    /// Number of contact nodes.
    pub contact_nodes: usize,
    /// The stress unit E*ḡ (Pa).
    pub stress_unit: f64,
}

/// Measures a relaxed contact (see the module docs for the definitions).
pub fn measure(problem: &Problem<'_>, sol: &Solution, opts: &GfmdOptions) -> Measurements {
    let s = problem.surface;
    let n = sol.gap.len();
    let unit = problem.modulus * s.rms_gradient();
    let contact: Vec<bool> = sol
        .on_wall
        .iter()
        .zip(&sol.gap)
        .map(|(&w, &g)| w || (opts.contact_gap > 0.0 && g <= opts.contact_gap))
        .collect();
    let stresses: Vec<f64> = sol
        .stress
        .iter()
        .zip(&contact)
        .filter(|(_, &c)| c)
        .map(|(&x, _)| x / unit)
        .collect();
    let nc = stresses.len();
    let (mean, var) = if nc > 0 {
        let m = stresses.iter().sum::<f64>() / nc as f64;
        (m, stresses.iter().map(|x| (x - m).powi(2)).sum::<f64>() / nc as f64)
    } else {
        (0.0, 0.0)
    };
    let mean_gap = sol.gap.iter().sum::<f64>() / n as f64;
    let pr = if nc > 0 {
        let lo = stresses.iter().cloned().fold(0.0, f64::min);
        let hi = stresses.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        let bins = opts.pr_bins.max(1);
        let width = if hi > lo {
            (hi - lo) / bins as f64 * (1.0 + 1e-12)
        } else {
            hi.abs().max(1e-12)
        };
        let mut counts = vec![0usize; bins];
        for &x in &stresses {
            let k = (((x - lo) / width) as usize).min(bins - 1);
            counts[k] += 1;
        }
        PrCurve {
            sigma: (0..bins).map(|k| lo + (k as f64 + 0.5) * width).collect(),
            density: counts.iter().map(|&c| c as f64 / (n as f64 * width)).collect(),
        }
    } else {
        PrCurve::default()
    };
    Measurements {
        stats: ContactStats {
            a_r: nc as f64 / n as f64,
            mean_contact_stress: mean,
            contact_stress_variance: var,
            pr,
        },
        mean_gap,
        mean_gap_rel: mean_gap / s.rms_height(),
        contact_nodes: nc,
        stress_unit: unit,
    }
}

/// The reduced grid of a brute-force run: L/λ_r, λ_r/λ_s and λ_s/Δa, so N = their product.
/// λ_s and the normalisation (ḡ) of the full spectrum are kept, L and λ_r shrink: the scales
/// where adhesion acts stay as they are.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GridSpec {
    /// L/λ_r.
    pub system_size_ratio: f64,
    /// λ_r/λ_s.
    pub bandwidth: f64,
    /// λ_s/Δa.
    pub points_per_short_wavelength: f64,
}

impl GridSpec {
    /// The preset's `[gfmd]` table.
    pub fn from_preset(g: &crate::input::preset::GfmdSpec) -> Self {
        GridSpec {
            system_size_ratio: g.system_size_ratio as f64,
            bandwidth: g.bandwidth as f64,
            points_per_short_wavelength: g.points_per_short_wavelength as f64,
        }
    }

    /// Grid side N.
    pub fn n(&self) -> usize {
        (self.system_size_ratio * self.bandwidth * self.points_per_short_wavelength).round() as usize
    }

    /// The same L/λ_r and λ_s/Δa on an N×N grid (the bandwidth λ_r/λ_s adapts).
    pub fn with_grid(&self, n: usize) -> Result<Self> {
        let bw = n as f64 / (self.system_size_ratio * self.points_per_short_wavelength);
        if !(4..=heightmap::MAX_GRID).contains(&n) || bw <= 1.0 {
            return Err(Error::field(
                "--grid",
                n,
                format!(
                    "{} < N <= {} (L/lambda_r = {} and lambda_s/da = {} need lambda_r > lambda_s)",
                    (self.system_size_ratio * self.points_per_short_wavelength) as usize,
                    heightmap::MAX_GRID,
                    self.system_size_ratio,
                    self.points_per_short_wavelength
                ),
            ));
        }
        Ok(GridSpec { bandwidth: bw, ..*self })
    }

    /// The reduced spectrum: same H, λ_s and ḡ as `full`, λ_r = bandwidth·λ_s, L = ratio·λ_r.
    pub fn spectrum(&self, full: &SelfAffine) -> Result<SelfAffine> {
        let lambda_r = self.bandwidth * full.lambda_s;
        let l = self.system_size_ratio * lambda_r;
        let g = Spectrum::SelfAffine(*full).rms_gradient();
        SelfAffine::new(l, lambda_r, full.lambda_s, full.hurst, Normalisation::RmsGradient(g))
    }
}

/// Inputs of [`run`].
#[derive(Debug, Clone)]
pub struct GfmdSetup {
    /// The scene: E*, p*, t·q_r, γ_s, ρ, and the model used for the theory comparison. Its
    /// spectrum must be self-affine when the map is generated.
    pub scene: Scene,
    /// The reduced grid (ignored, except L/λ_r for q_r, when `surface` is given).
    pub grid: GridSpec,
    /// Seed of the random phases.
    pub seed: u64,
    /// A given map (square) instead of a generated one.
    pub surface: Option<Surface>,
}

/// The theory on the same realisation (its discrete spectrum).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TheoryComparison {
    /// a_r, σ̄_c*, ⟨δσ_c²⟩* and Pr(σ*) of the theory.
    #[serde(flatten)]
    pub stats: ContactStats,
    /// Width Δ* of the stress distribution.
    pub width: f64,
    /// Model label.
    pub model: String,
}

/// Everything a GFMD run reports (the JSON of `asperity gfmd`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GfmdResult {
    /// The fraction of nodes in contact, σ̄_c* and ⟨δσ_c²⟩* (reduced by E*ḡ of the map) and
    /// the Pr(σ*) histogram (bin centres, ∫ = a_r).
    #[serde(flatten)]
    pub stats: ContactStats,
    /// ū (m).
    pub mean_gap: f64,
    /// ū/h_rms.
    pub mean_gap_rel: f64,
    /// FIRE steps.
    pub iterations: usize,
    /// Final relative force residual.
    pub residual: f64,
    /// Requested tolerance.
    pub tolerance: f64,
    /// Wall time of the whole run (s).
    pub elapsed_s: f64,
    /// Wall time of the solver alone (s).
    pub solve_elapsed_s: f64,
    /// Wall time of the theory evaluation (s).
    pub theory_elapsed_s: f64,
    /// Grid side N.
    pub grid: usize,
    /// Whether the tolerance was met (always true in a returned result: a run that does not
    /// converge is an error).
    pub converged: bool,
    /// Seed (null for a loaded map).
    pub seed: Option<u64>,
    /// p*.
    pub pressure: f64,
    /// p (Pa).
    pub pressure_pa: f64,
    /// t·q_r (null = semi-infinite).
    pub thickness_qr: Option<f64>,
    /// γ (J/m²).
    pub gamma: f64,
    /// ρ (m).
    pub range_m: f64,
    /// L (m).
    pub system_size_m: f64,
    /// Δa (m).
    pub spacing_m: f64,
    /// Reduced grid geometry of a generated map (null for a loaded map).
    pub grid_spec: Option<GridSpec>,
    /// ḡ of the map.
    pub rms_gradient: f64,
    /// h_rms of the map (m).
    pub rms_height_m: f64,
    /// Number of contact nodes.
    pub contact_nodes: usize,
    /// (γ/E*)·Δa/ρ², should stay below ≈ 0.25 (physics.md §6); 0 without adhesion.
    pub adhesion_resolution: f64,
    /// Theory on the same map (null if it could not be evaluated).
    pub theory: Option<TheoryComparison>,
    /// Why `theory` is null.
    pub theory_error: Option<String>,
    /// The map (not serialised).
    #[serde(skip)]
    pub surface: Option<Surface>,
}

/// Generates (or takes) the map, relaxes the contact, measures it and evaluates the theory on
/// the map's discrete spectrum. See the module docs.
pub fn run(
    setup: &GfmdSetup,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<GfmdResult> {
    let t0 = Instant::now();
    let scene = &setup.scene;
    scene.validate()?;
    let (surf, q_r) = match &setup.surface {
        Some(s) => {
            if !s.is_square() {
                return Err(Error::field(
                    "--surface",
                    format!("{} x {}", s.nx, s.ny),
                    "an N x N map",
                ));
            }
            let q_r = 2.0 * std::f64::consts::PI * setup.grid.system_size_ratio / s.size_x();
            (s.clone(), q_r)
        }
        None => {
            let full = match &scene.spectrum {
                Spectrum::SelfAffine(sa) => sa,
                Spectrum::Discrete(_) => {
                    return Err(Error::Unsupported(
                        "generating a map needs a self-affine spectrum; give --surface".into(),
                    ))
                }
            };
            let red = setup.grid.spectrum(full)?;
            (heightmap::generate(&red, setup.grid.n(), setup.seed)?, red.q_r())
        }
    };
    let gbar = surf.rms_gradient();
    let thickness = if scene.thickness_qr.is_infinite() {
        f64::INFINITY
    } else {
        scene.thickness_qr / q_r
    };
    let problem = Problem {
        surface: &surf,
        modulus: scene.modulus,
        thickness,
        pressure: scene.pressure * scene.modulus * gbar,
        gamma: scene.gamma,
        range: scene.range,
    };
    let sol = solve(&problem, opts, progress, cancel)?;
    let m = measure(&problem, &sol, opts);
    // theory on the same realisation
    let t_theory = Instant::now();
    let (theory, theory_error) = match surf.discrete_spectrum(q_r).and_then(|d| {
        let th_scene = Scene {
            spectrum: Spectrum::Discrete(d),
            ..scene.clone()
        };
        engine::evaluate(&th_scene, &engine::Options::default())
    }) {
        Ok(ev) => (
            Some(TheoryComparison {
                stats: ev.stats,
                width: ev.width,
                model: scene.model.label(),
            }),
            None,
        ),
        Err(e) => (None, Some(e.to_string())),
    };
    let grid_spec = setup.surface.is_none().then_some(setup.grid);
    let theory_elapsed_s = t_theory.elapsed().as_secs_f64();
    Ok(GfmdResult {
        stats: m.stats,
        mean_gap: m.mean_gap,
        mean_gap_rel: m.mean_gap_rel,
        iterations: sol.iterations,
        residual: sol.residual,
        tolerance: opts.tolerance,
        elapsed_s: t0.elapsed().as_secs_f64(),
        solve_elapsed_s: sol.elapsed_s,
        theory_elapsed_s,
        grid: surf.nx,
        converged: true,
        seed: setup.surface.is_none().then_some(setup.seed),
        pressure: scene.pressure,
        pressure_pa: problem.pressure,
        thickness_qr: scene.thickness_qr.is_finite().then_some(scene.thickness_qr),
        gamma: scene.gamma,
        range_m: scene.range,
        system_size_m: surf.size_x(),
        spacing_m: surf.spacing,
        grid_spec,
        rms_gradient: gbar,
        rms_height_m: surf.rms_height(),
        contact_nodes: m.contact_nodes,
        adhesion_resolution: if scene.gamma > 0.0 {
            scene.gamma / scene.modulus * surf.spacing / (scene.range * scene.range)
        } else {
            0.0
        },
        theory,
        theory_error,
        surface: Some(surf),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;

    #[test]
    fn preset_grid_and_its_reduced_spectrum() {
        let p = Preset::resolve("system-1").unwrap();
        let g = GridSpec::from_preset(p.gfmd.as_ref().unwrap());
        assert_eq!(g.n(), 512);
        assert_eq!(p.gfmd_grid(), Some(512));
        let full = match p.spectrum().unwrap() {
            Spectrum::SelfAffine(s) => s,
            _ => unreachable!(),
        };
        let r = g.spectrum(&full).unwrap();
        assert_eq!(r.lambda_s, full.lambda_s);
        assert!((r.lambda_r / r.lambda_s - 32.0).abs() < 1e-12);
        assert!((r.system_size / r.lambda_r - 2.0).abs() < 1e-12);
        assert!((Spectrum::SelfAffine(r).rms_gradient() - 1.0).abs() < 1e-12);
        // --grid keeps L/λ_r and λ_s/Δa
        let h = g.with_grid(256).unwrap();
        assert_eq!(h.n(), 256);
        assert!((h.bandwidth - 16.0).abs() < 1e-12);
        assert!(g.with_grid(16).is_err());
    }

    #[test]
    fn options_are_validated() {
        assert!(GfmdOptions::default().validate().is_ok());
        for o in [
            GfmdOptions {
                tolerance: 0.0,
                ..GfmdOptions::default()
            },
            GfmdOptions {
                max_iterations: 0,
                ..GfmdOptions::default()
            },
            GfmdOptions {
                pr_bins: 0,
                ..GfmdOptions::default()
            },
            GfmdOptions {
                contact_gap: f64::NAN,
                ..GfmdOptions::default()
            },
        ] {
            assert!(matches!(o.validate(), Err(Error::InvalidField { .. })));
        }
    }
}
