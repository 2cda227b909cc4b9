//! [`crate::gfmd::run()`] over ranks: the map by slabs, FIRE on slabs, the measurements and
//! the map's moments by ordered reductions, the theory on rank 0.

use super::comm::{share, Comm};
use super::fire::{solve_slab, SlabProblem};
use super::map::{self, Slab};
use super::slab_fft::SlabFft;
use crate::error::{Error, Field, Result};
use crate::gfmd::measure::measure_slab;
use crate::gfmd::reduction::{check_map_moments, reduce, Reduction};
use crate::gfmd::result::{body_and_load, scene_on_spectrum, theory_comparison};
use crate::gfmd::{GfmdOptions, GfmdResult, GfmdSetup, Progress, Stage};
use crate::input::scene::Scene;
use crate::surface::spectrum::{Discrete, Spectrum};
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// A map ready to solve on this rank: [`crate::gfmd::Prepared`] with the rank's rows only.
#[derive(Debug, Clone)]
pub struct PreparedSlab {
    /// The scene GFMD runs (reduced for a generated map).
    pub scene: Scene,
    /// This rank's rows of the map.
    pub slab: Slab,
    /// q_r of the map.
    pub q_r: f64,
    /// ḡ of the whole map.
    pub rms_gradient: f64,
    /// h_rms of the whole map (m).
    pub rms_height: f64,
    /// The map's discrete spectrum (every rank).
    pub spectrum: Discrete,
    /// The full and reduced invariants (None for a loaded map).
    pub reduction: Option<Reduction>,
}

impl PreparedSlab {
    /// The problem at reduced pressure `pressure`, as [`crate::gfmd::Prepared::problem`].
    pub fn problem(&self, pressure: f64) -> SlabProblem<'_> {
        let sc = &self.scene;
        let (thickness, pressure) = body_and_load(sc, self.q_r, self.rms_gradient, pressure);
        SlabProblem {
            slab: &self.slab,
            modulus: sc.modulus,
            thickness,
            pressure,
            gamma: sc.gamma,
            range: sc.range,
        }
    }

    /// The scene on the map's discrete spectrum, as [`crate::gfmd::Prepared::theory_scene`].
    pub fn theory_scene(&self, pressure: f64) -> Scene {
        scene_on_spectrum(&self.scene, &self.spectrum, pressure)
    }
}

/// [`crate::gfmd::prepare`] on this rank: a generated map by slabs; a given map (which every
/// rank was handed whole, e.g. read from a file) cut to the rank's rows.
///
/// # Errors
/// As [`crate::gfmd::prepare`]; [`Error::Invalid`] naming the grid when it has fewer rows
/// than ranks.
pub fn prepare_slab(comm: &dyn Comm, setup: &GfmdSetup) -> Result<PreparedSlab> {
    let scene = &setup.scene;
    let size = comm.size();
    match &setup.surface {
        Some(s) => {
            if !s.is_square() {
                return Err(Error::invalid_text(
                    Field::HeightMap,
                    format!("{} x {}", s.nx, s.ny),
                    "an N x N map",
                ));
            }
            check_ranks(s.nx, size)?;
            s.check_rough()?;
            let q_r = 2.0 * std::f64::consts::PI * setup.grid.system_size_ratio / s.size_x();
            let (y0, y1) = share(s.ny, size, comm.rank());
            Ok(PreparedSlab {
                scene: scene.clone(),
                slab: Slab::of_map(s, y0, y1),
                q_r,
                rms_gradient: s.rms_gradient(),
                rms_height: s.rms_height(),
                spectrum: s.discrete_spectrum(q_r)?,
                reduction: None,
            })
        }
        None => {
            let (red, mut reduction) = reduce(scene, &setup.grid, setup.rescale)?;
            let spec = match &red.spectrum {
                Spectrum::SelfAffine(sa) => *sa,
                _ => unreachable!("reduce gives a self-affine spectrum"),
            };
            check_ranks(setup.grid.n(), size)?;
            let slab = map::generate(comm, &spec, setup.grid.n(), setup.seed)?;
            let spectrum = map::discrete_spectrum(comm, &slab, spec.q_r())?;
            let mut fft = SlabFft::new(slab.nx, slab.ny, comm.rank(), size);
            let rms_gradient = map::rms_gradient(comm, &mut fft, &slab);
            let rms_height = map::rms_height(comm, &slab);
            check_map_moments(&mut reduction, &red, rms_height, rms_gradient, spectrum.clone());
            Ok(PreparedSlab {
                scene: red,
                slab,
                q_r: spec.q_r(),
                rms_gradient,
                rms_height,
                spectrum,
                reduction: Some(reduction),
            })
        }
    }
}

/// A grid of side `n` splits over `size` ranks when every rank gets at least one row and one
/// column of the half spectrum.
fn check_ranks(n: usize, size: usize) -> Result<()> {
    if n < size || n / 2 + 1 < size {
        return Err(Error::invalid(
            Field::Grid,
            n as f64,
            format!("N >= {size} (at least one row per rank on {size} ranks)"),
        ));
    }
    Ok(())
}

/// [`crate::gfmd::run()`] on this rank of `comm`: every rank calls it with the same setup and
/// options. Rank 0 returns the serial run's result (the map field `surface` is None: no rank
/// holds the map); the other ranks return it without the theory (`theory` None, which only
/// rank 0 evaluates).
///
/// # Errors
/// As [`crate::gfmd::run()`]; every rank returns the same error.
pub fn run_slab(
    comm: &dyn Comm,
    setup: &GfmdSetup,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<GfmdResult> {
    let t0 = Instant::now();
    let prep = prepare_slab(comm, setup)?;
    let scene = &prep.scene;
    let problem = prep.problem(scene.pressure);
    let sol = solve_slab(comm, &problem, opts, None, progress, cancel)?;
    let (nx, ny, da) = (prep.slab.nx, prep.slab.ny, prep.slab.spacing);
    let m = measure_slab(
        comm,
        &sol,
        opts,
        nx * ny,
        scene.modulus,
        prep.rms_gradient,
        prep.rms_height,
    );
    progress(Progress {
        stage: Stage::Theory,
        iteration: sol.iterations,
        residual: sol.residual,
        contact_fraction: m.stats.a_r,
    });
    let t_theory = Instant::now();
    let (theory, theory_error) = if comm.rank() == 0 {
        theory_comparison(Ok(prep.theory_scene(scene.pressure)), scene, cancel)?
    } else {
        (None, None)
    };
    let theory_elapsed_s = t_theory.elapsed().as_secs_f64();
    Ok(GfmdResult {
        stats: m.stats,
        mean_gap: m.mean_gap,
        mean_gap_rel: m.mean_gap_rel,
        iterations: sol.iterations,
        pk_iterations: sol.pk_iterations,
        residual: sol.residual,
        tolerance: opts.tolerance,
        elapsed_s: t0.elapsed().as_secs_f64(),
        solve_elapsed_s: sol.elapsed_s,
        theory_elapsed_s,
        grid: nx,
        converged: sol.residual <= opts.tolerance,
        seed: setup.surface.is_none().then_some(setup.seed),
        pressure: scene.pressure,
        pressure_pa: problem.pressure,
        thickness_qr: scene.thickness_qr.is_finite().then_some(scene.thickness_qr),
        gamma: scene.gamma,
        range_m: scene.range,
        system_size_m: nx as f64 * da,
        spacing_m: da,
        grid_spec: setup.surface.is_none().then_some(setup.grid),
        rms_gradient: prep.rms_gradient,
        rms_height_m: prep.rms_height,
        contact_nodes: m.contact_nodes,
        adhesion_resolution: if scene.gamma > 0.0 {
            scene.gamma / scene.modulus * da / (scene.range * scene.range)
        } else {
            0.0
        },
        theory,
        theory_error,
        reduction: prep.reduction.clone(),
        surface: None,
    })
}
