//! The contact problem and the solver's options, progress reports and relaxed configuration
//! (see the [module docs](super) for the model).

use super::distributed::comm::{all_max, all_min, Comm};
use super::distributed::map::Slab;
use crate::error::{Bound, Error, Field, Range, Result};
use crate::surface::heightmap::{Surface, MAX_GRID};

/// The minimiser.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Polonsky–Keer where it is cheaper, FIRE elsewhere: PK for the hard wall of a
    /// semi-infinite body on grids of at most [`PK_MAX_NODES`] nodes (every generated grid:
    /// system I at p* = 0.01 takes 108, 126 and 159 PK iterations at 1024², 2048² and 4096²,
    /// where FIRE takes ≈ 600–1 000 steps; at 4096² PK is 4× faster); FIRE alone on slabs and
    /// with adhesion (BENCHMARKS.md). On a slab PK's iterations grow as the slab thins
    /// (system II, 256², p* = 0.009: 54 on a half-space, 342 at t·q_r = 1, 19 138 at 0.3, where
    /// FIRE needs 446–661 steps, 160× faster at 0.3).
    #[default]
    Auto,
    /// Polonsky–Keer constrained CG for the hard wall, FIRE to check and finish (FIRE alone
    /// with adhesion). 2–5× fewer FFTs than FIRE alone up to 1024² on a half-space
    /// (BENCHMARKS.md).
    PolonskyKeer,
    /// FIRE alone.
    Fire,
}

/// The names of [`Method`]'s variants as front ends take them (`auto`, `pk`, `fire`).
pub const METHOD_NAMES: [&str; 3] = ["auto", "pk", "fire"];

impl std::str::FromStr for Method {
    type Err = Error;

    /// `auto`, `pk` (Polonsky–Keer) or `fire` ([`METHOD_NAMES`]).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the field `method` and the allowed names.
    fn from_str(s: &str) -> Result<Method> {
        match s {
            "auto" => Ok(Method::Auto),
            "pk" => Ok(Method::PolonskyKeer),
            "fire" => Ok(Method::Fire),
            other => Err(Error::invalid_text(
                Field::Other("method".into()),
                other,
                crate::error::Allowed::choices(METHOD_NAMES),
            )),
        }
    }
}

/// Largest grid (nodes) on which [`Method::Auto`] uses Polonsky–Keer: the largest generated
/// grid, [`MAX_GRID`]². A measured map with more nodes relaxes with FIRE, whose memory per node
/// is smaller.
pub const PK_MAX_NODES: usize = MAX_GRID * MAX_GRID;

impl Method {
    /// Refuses Polonsky–Keer on a slab, before any step: its constrained CG does not reach the
    /// tolerance on a body of finite thickness (residual 0.2–0.98 after every step of the
    /// limit), where FIRE ([`Method::Auto`] picks it there) converges in a few hundred steps.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `method` for [`Method::PolonskyKeer`] when `scene`'s t·q_r is
    /// finite.
    pub fn check_on(self, scene: &crate::input::scene::Scene) -> Result<()> {
        let t = scene.thickness_qr();
        if self == Method::PolonskyKeer && t.is_finite() {
            return Err(Error::invalid_text(
                Field::Other("method".into()),
                format!("pk on a slab (t·q_r = {})", crate::error::fmt_value(t)),
                "auto or fire on a slab (Polonsky-Keer converges on a semi-infinite body only)",
            ));
        }
        Ok(())
    }

    /// Whether a hard-wall run (no adhesion) on `nodes` grid nodes of a body that is
    /// `semi_infinite` (else a slab) relaxes with Polonsky–Keer.
    pub fn uses_pk(self, nodes: usize, semi_infinite: bool) -> bool {
        match self {
            Method::Auto => semi_infinite && nodes <= PK_MAX_NODES,
            Method::PolonskyKeer => true,
            Method::Fire => false,
        }
    }
}

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
    /// The minimiser.
    pub method: Method,
}

impl Default for GfmdOptions {
    fn default() -> Self {
        GfmdOptions {
            tolerance: 1e-8,
            max_iterations: 200_000,
            pr_bins: 400,
            progress_every: 50,
            contact_gap: 0.0,
            method: Method::default(),
        }
    }
}

/// Allowed relative force residual of a GFMD relaxation.
pub const TOLERANCE_RANGE: Range = Range {
    lo: Bound::Inclusive(1e-14),
    hi: Bound::Exclusive(1.0),
    whole: false,
};
/// Allowed iteration limit.
pub const MAX_ITERATIONS_RANGE: Range = Range {
    lo: Bound::Inclusive(1.0),
    hi: Bound::Unbounded,
    whole: true,
};
/// Allowed number of histogram bins of Pr(σ*).
pub const BINS_RANGE: Range = Range::whole(1.0, 1e6);
/// Allowed initial contact gap (m).
pub const CONTACT_GAP_RANGE: Range = Range::at_least(0.0);

impl GfmdOptions {
    /// Checks the options, naming the field.
    ///
    /// # Errors
    /// [`Error::Invalid`] for [`Field::GfmdTolerance`], [`Field::MaxIterations`],
    /// [`Field::Bins`] or [`Field::ContactGap`] outside its range.
    pub fn validate(&self) -> Result<()> {
        TOLERANCE_RANGE.check(Field::GfmdTolerance, self.tolerance)?;
        MAX_ITERATIONS_RANGE.check(Field::MaxIterations, self.max_iterations as f64)?;
        BINS_RANGE.check(Field::Bins, self.pr_bins as f64)?;
        CONTACT_GAP_RANGE.check(Field::ContactGap, self.contact_gap)?;
        Ok(())
    }
}

/// One contact problem in physical units, on the whole map (`M` = [`Surface`], the serial run)
/// or on one rank's rows of it (`M` = [`super::distributed::map::Slab`]).
#[derive(Debug)]
pub struct Problem<'a, M = Surface> {
    /// The rigid rough substrate (this rank's rows of it on a slab).
    pub surface: &'a M,
    /// Contact modulus E* (Pa).
    pub modulus: f64,
    /// Slab thickness t (m); `f64::INFINITY` = semi-infinite.
    pub thickness: f64,
    /// Nominal pressure p₀ (Pa): > 0, or ≤ 0 (tension) with adhesion.
    pub pressure: f64,
    /// Surface energy γ (J/m²); 0 = hard wall only.
    pub gamma: f64,
    /// Range ρ of the attraction (m); unused when γ = 0.
    pub range: f64,
}

impl<M> Clone for Problem<'_, M> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<M> Copy for Problem<'_, M> {}

/// The map of a [`Problem`] as this rank holds it.
#[derive(Debug, Clone, Copy)]
pub enum Layout<'a> {
    /// The whole map (the serial run: Polonsky–Keer and the whole map's FFT run on it).
    Whole(&'a Surface),
    /// One rank's rows of the map (a run over ranks: FIRE with the slab FFT).
    Slab(&'a Slab),
}

impl<'a> Layout<'a> {
    /// (nx, ny, Δa) of the whole map, this rank's heights (m) and the index of its first node
    /// in the whole map.
    pub fn rows(self) -> ((usize, usize, f64), &'a [f64], usize) {
        match self {
            Layout::Whole(s) => ((s.nx, s.ny, s.spacing), &s.heights, 0),
            Layout::Slab(s) => ((s.nx, s.ny, s.spacing), &s.heights, s.offset()),
        }
    }
}

/// A map a [`Problem`] is posed on: the whole map, or one rank's rows of it.
pub trait MapRows {
    /// How this rank holds the map.
    fn layout(&self) -> Layout<'_>;
}

impl MapRows for Surface {
    fn layout(&self) -> Layout<'_> {
        Layout::Whole(self)
    }
}

impl MapRows for Slab {
    fn layout(&self) -> Layout<'_> {
        Layout::Slab(self)
    }
}

impl<M: MapRows> Problem<'_, M> {
    /// Checks every field; the map (all ranks' rows, `comm` joining them:
    /// [`super::distributed::Solo`] for the whole map) must not be flat. Every rank gets the
    /// same answer.
    pub fn validate(&self, comm: &dyn Comm) -> Result<()> {
        check_loads(self.modulus, self.thickness, self.pressure, self.gamma, self.range)?;
        let (_, heights, _) = self.surface.layout().rows();
        let (lo, hi) = heights
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| (a.min(h), b.max(h)));
        if all_min(comm, lo) == all_max(comm, hi) {
            return Err(Error::invalid_text(
                Field::HeightMap,
                "a flat map",
                "a height map with some roughness",
            ));
        }
        Ok(())
    }
}

/// Checks the fields of a [`Problem`] other than the map: E*, t, p₀, γ and ρ.
pub fn check_loads(modulus: f64, thickness: f64, pressure: f64, gamma: f64, range: f64) -> Result<()> {
    if !(modulus.is_finite() && modulus > 0.0) {
        return Err(Error::invalid(
            Field::ContactModulus,
            modulus,
            "a finite modulus > 0 (Pa)",
        ));
    }
    if thickness.is_nan() || thickness <= 0.0 {
        return Err(Error::invalid(
            Field::Thickness,
            thickness,
            "a thickness t > 0 (m), or inf",
        ));
    }
    // tension (p ≤ 0) is held by adhesion alone: allowed only with it (the load cycle)
    let tension_allowed = gamma > 0.0;
    if !(pressure.is_finite() && (pressure > 0.0 || tension_allowed)) {
        return Err(Error::invalid(
            Field::PressurePa,
            pressure,
            if tension_allowed {
                "a finite pressure (Pa)"
            } else {
                "a finite pressure p > 0 (Pa); tension needs adhesion"
            },
        ));
    }
    if !(gamma.is_finite() && gamma >= 0.0) {
        return Err(Error::invalid(Field::SurfaceEnergy, gamma, "gamma >= 0 (J/m^2)"));
    }
    if gamma > 0.0 && !(range.is_finite() && range > 0.0) {
        return Err(Error::invalid(Field::Range, range, "a finite length > 0 (m)"));
    }
    Ok(())
}

/// What a run is doing when it reports progress.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Stage {
    /// Relaxing the contact (Polonsky–Keer, then FIRE): the report's step and residual move.
    #[default]
    Relax,
    /// The relaxation is done and the theory on the map's spectrum is being evaluated (one
    /// report, with the relaxation's last step and residual): [`super::run()`] and
    /// [`super::sweep::run_sweep`] say so before their theory, which reports nothing while it
    /// runs.
    Theory,
}

/// A progress report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// What the run is doing.
    pub stage: Stage,
    /// FIRE steps so far.
    pub iteration: usize,
    /// Current relative force residual (while Polonsky–Keer runs: its largest gap error on the
    /// contact set or overlap elsewhere, relative to h_rms).
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
    /// Steps taken: Polonsky–Keer iterations plus FIRE steps.
    pub iterations: usize,
    /// Of which Polonsky–Keer iterations (two convolutions each; a FIRE step costs one).
    pub pk_iterations: usize,
    /// Final relative force residual.
    pub residual: f64,
    /// Wall time of the solve (s).
    pub elapsed_s: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

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
            assert!(matches!(o.validate(), Err(Error::Invalid { .. })));
        }
    }
}
