//! One GFMD run of a scene: generate (or take) the map, relax, measure, and evaluate the theory
//! on the map's own discrete spectrum.

use super::distributed::comm::{Comm, Solo};
use super::fire::relax_from;
use super::measure::measure_slab;
use super::problem::MapRows;
use super::reduction::{reduce, Reduction};
use super::sweep::LoadMap;
use super::{GfmdOptions, GfmdSetup, GridSpec, Problem, Progress, Stage};
use crate::contact::ContactStats;
use crate::error::{Error, Field, Result};
use crate::input::scene::Scene;
use crate::surface::heightmap::{self, Surface};
use crate::surface::shells::THEORY_SHELL_LN;
use crate::surface::spectrum::{Discrete, Spectrum};
use crate::theory::engine;
use crate::theory::gap;
use serde::Serialize;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

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
    /// ū (m) on the map's spectrum: the energy route [S-12], with adhesion at the load the
    /// loading branch's contact carries (physics.md §5.1; null where unavailable).
    pub mean_gap: Option<f64>,
    /// ū/h_rms (null where unavailable).
    pub mean_gap_rel: Option<f64>,
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
    /// Solver steps: Polonsky–Keer iterations plus FIRE steps.
    pub iterations: usize,
    /// Of which Polonsky–Keer iterations (0 with adhesion or `Method::Fire`).
    pub pk_iterations: usize,
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
    /// Whether the final relative force residual is within the tolerance (a run that cannot
    /// meet it returns an error instead, so a returned result has it).
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
    /// The full system's invariants beside the reduced system's, and which were kept (null for
    /// a loaded map). `gamma` and `range_m` above are the values GFMD ran with.
    pub reduction: Option<Reduction>,
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
///
/// # Errors
/// [`Error::Invalid`] for a grid or map that cannot be built (naming the grid's field);
/// [`Error::NotConverged`] when the relaxation misses its tolerance within its step limit;
/// [`Error::Cancelled`] when `cancel` is set, in the relaxation or in the theory. A theory
/// that cannot be evaluated on the map is not an error: it is `theory: None` with the reason
/// in `theory_error`.
///
/// `progress` gets the relaxation's reports ([`super::Stage::Relax`]), then one
/// [`super::Stage::Theory`] report before the theory on the map.
///
/// # Examples
/// ```
/// use asperity::gfmd::{self, GfmdOptions, GfmdSetup, GridSpec};
/// use asperity::input::preset::Preset;
/// use std::sync::atomic::AtomicBool;
///
/// // a 64² map of system I's reduced spectrum without adhesion at p* = 0.05
/// let scene = Preset::resolve("system-1").unwrap().scene().unwrap().without_adhesion();
/// let setup = GfmdSetup {
///     scene: scene.with_pressure(0.05).unwrap(),
///     grid: GridSpec { system_size_ratio: 2.0, bandwidth: 4.0, points_per_short_wavelength: 8.0 },
///     seed: 1,
///     surface: None,
///     rescale: true,
/// };
/// let r = gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &AtomicBool::new(false)).unwrap();
/// assert_eq!(r.grid, 64);
/// assert!(r.converged && r.stats.a_r > 0.0 && r.stats.a_r < 1.0);
/// ```
pub fn run(
    setup: &GfmdSetup,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
) -> Result<GfmdResult> {
    let t0 = Instant::now();
    let prep = prepare(setup)?;
    let r = run_on(&Solo, &prep, setup, opts, progress, cancel, t0)?;
    Ok(GfmdResult {
        surface: Some(prep.surface),
        ..r
    })
}

/// [`run()`] on `prep`, this rank's part of the map of `setup` (`comm` joining the ranks):
/// relaxes, measures and (on rank 0; None elsewhere) evaluates the theory on the map; `t0` is
/// the start of the run. The map is not in the result.
pub(crate) fn run_on<M: LoadMap>(
    comm: &dyn Comm,
    prep: &M,
    setup: &GfmdSetup,
    opts: &GfmdOptions,
    progress: &mut dyn FnMut(Progress),
    cancel: &AtomicBool,
    t0: Instant,
) -> Result<GfmdResult> {
    let (scene, rms_gradient, rms_height) = prep.scene_and_moments();
    let problem = prep.problem(scene.pressure);
    let sol = relax_from(comm, &problem, opts, None, progress, cancel)?.equilibrium()?;
    let ((nx, ny, da), _, _) = problem.surface.layout().rows();
    let m = measure_slab(comm, &sol, opts, nx * ny, scene.modulus, rms_gradient, rms_height);
    progress(Progress {
        stage: Stage::Theory,
        iteration: sol.iterations,
        residual: sol.residual,
        contact_fraction: m.stats.a_r,
    });
    // theory on the same realisation
    let t_theory = Instant::now();
    let (theory, theory_error) = if comm.rank() == 0 {
        theory_comparison(prep.theory_scene(scene.pressure), scene, cancel)?
    } else {
        (None, None)
    };
    let theory_elapsed_s = t_theory.elapsed().as_secs_f64();
    let (grid, reduction) = prep.grid_and_reduction();
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
        grid,
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
        rms_gradient,
        rms_height_m: rms_height,
        contact_nodes: m.contact_nodes,
        adhesion_resolution: if scene.gamma > 0.0 {
            scene.gamma / scene.modulus * da / (scene.range * scene.range)
        } else {
            0.0
        },
        theory,
        theory_error,
        reduction,
        surface: None,
    })
}

/// A map ready to solve: the (reduced) scene, the map, and what the reduction kept.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// The scene GFMD runs: the reduced one (γ_s, ρ rescaled when asked), or the given one
    /// for a loaded map.
    pub scene: Scene,
    /// The map.
    pub surface: Surface,
    /// q_r of the map (for t·q_r and the theory's discrete spectrum).
    pub q_r: f64,
    /// ḡ of the map.
    pub rms_gradient: f64,
    /// The full and reduced invariants (None for a loaded map).
    pub reduction: Option<Reduction>,
}

impl Prepared {
    /// The problem at reduced pressure `pressure` (p* by the map's ḡ).
    pub fn problem(&self, pressure: f64) -> Problem<'_> {
        problem_on(&self.surface, &self.scene, (self.q_r, self.rms_gradient), pressure)
    }

    /// The scene on the map's own discrete spectrum at p* = `pressure` (for the theory),
    /// its mode groups merged into shells of [`THEORY_SHELL_LN`] in ln q with the same
    /// moments ([`crate::surface::shells`]).
    pub fn theory_scene(&self, pressure: f64) -> Result<Scene> {
        let d = self.surface.discrete_spectrum(self.q_r)?;
        Ok(scene_on_spectrum(&self.scene, &d, pressure))
    }
}

/// The problem of `scene` at p* = `pressure` on `map` (the whole map or a rank's rows of it)
/// with q_r and ḡ = `rms_gradient` of the whole map: the body's thickness t (m; ∞ for a
/// half-space) and the load p₀ (Pa) from t·q_r and p*.
pub(crate) fn problem_on<'a, M>(
    map: &'a M,
    scene: &Scene,
    (q_r, rms_gradient): (f64, f64),
    pressure: f64,
) -> Problem<'a, M> {
    let thickness = if scene.thickness_qr.is_infinite() {
        f64::INFINITY
    } else {
        scene.thickness_qr / q_r
    };
    Problem {
        surface: map,
        modulus: scene.modulus,
        thickness,
        pressure: pressure * scene.modulus * rms_gradient,
        gamma: scene.gamma,
        range: scene.range,
    }
}

/// `scene` on a map's discrete spectrum `d` at p* = `pressure`, its mode groups merged into
/// shells of [`THEORY_SHELL_LN`] in ln q (the whole map and its slabs).
pub(crate) fn scene_on_spectrum(scene: &Scene, d: &Discrete, pressure: f64) -> Scene {
    let mut scene = Scene {
        spectrum: Spectrum::Discrete(d.coarse_grained(THEORY_SHELL_LN)),
        pressure,
        ..scene.clone()
    };
    scene.resolve_model();
    scene
}

/// Generates (or takes and checks) the map of `setup`, reducing the scene to its grid (see
/// [`super::reduction`]).
pub fn prepare(setup: &GfmdSetup) -> Result<Prepared> {
    let scene = &setup.scene;
    match &setup.surface {
        Some(s) => {
            let q_r = given_map(s, setup, 1)?;
            Ok(Prepared {
                scene: scene.clone(),
                surface: s.clone(),
                q_r,
                rms_gradient: s.rms_gradient(),
                reduction: None,
            })
        }
        None => {
            let (red, reduction) = reduce(scene, &setup.grid, setup.rescale)?;
            let spec = match &red.spectrum {
                Spectrum::SelfAffine(sa) => *sa,
                _ => unreachable!("reduce gives a self-affine spectrum"),
            };
            let surface = heightmap::generate(&spec, setup.grid.n(), setup.seed)?;
            let mut reduction = reduction;
            super::reduction::check_map(&mut reduction, &red, &surface, spec.q_r())?;
            Ok(Prepared {
                rms_gradient: surface.rms_gradient(),
                q_r: spec.q_r(),
                scene: red,
                surface,
                reduction: Some(reduction),
            })
        }
    }
}

/// The q_r of the map given to `setup`, checked for a run on `ranks` ranks: square, rough,
/// and at least one row and one column of the half spectrum per rank.
///
/// # Errors
/// [`Error::Invalid`] naming the map or the grid.
pub(crate) fn given_map(s: &Surface, setup: &GfmdSetup, ranks: usize) -> Result<f64> {
    if !s.is_square() {
        return Err(Error::invalid_text(
            Field::HeightMap,
            format!("{} x {}", s.nx, s.ny),
            "an N x N map",
        ));
    }
    check_ranks(s.nx, ranks)?;
    s.check_rough()?;
    Ok(2.0 * std::f64::consts::PI * setup.grid.system_size_ratio / s.size_x())
}

/// A grid of side `n` splits over `size` ranks when every rank gets at least one row and one
/// column of the half spectrum.
pub(crate) fn check_ranks(n: usize, size: usize) -> Result<()> {
    if n < size || n / 2 + 1 < size {
        return Err(Error::invalid(
            Field::Grid,
            n as f64,
            format!("N >= {size} (at least one row per rank on {size} ranks)"),
        ));
    }
    Ok(())
}

/// The theory beside GFMD: the scene `th` on the map's spectrum evaluated (a_r, the stresses,
/// ū), or the reason it could not be (`scene` gives the model label).
///
/// # Errors
/// Only [`Error::Cancelled`]; every other failure is the returned reason.
pub fn theory_comparison(
    th: Result<Scene>,
    scene: &Scene,
    cancel: &AtomicBool,
) -> Result<(Option<TheoryComparison>, Option<String>)> {
    Ok(
        match th.and_then(|th| {
            // the block shows a_r, the stresses and ū, not the adhesive error estimate: its
            // three probe solves are skipped
            let opts = engine::Options {
                adhesion_error_estimate: false,
                ..engine::Options::default()
            };
            let ev = engine::evaluate_warm(&th, &opts, None, Some(cancel))?;
            let g = gap::mean_gap_of_cancellable(&th, &ev, &opts, Some(cancel));
            if matches!(g, Err(Error::Cancelled)) {
                return Err(Error::Cancelled);
            }
            Ok((ev, g))
        }) {
            Err(Error::Cancelled) => return Err(Error::Cancelled),
            Ok((ev, g)) => (
                Some(TheoryComparison {
                    stats: ev.stats,
                    width: ev.width,
                    model: scene.model.label(),
                    mean_gap: g.as_ref().ok().map(|g| g.metres),
                    mean_gap_rel: g.as_ref().ok().map(|g| g.relative),
                }),
                None,
            ),
            Err(e) => (None, Some(e.to_string())),
        },
    )
}
