//! Green's function molecular dynamics (GFMD): the brute-force reference for the theory.
//!
//! ## Model (physics.md §2, §6)
//!
//! A rigid, rough substrate with heights h(r) (a [`Surface`](crate::surface::heightmap::Surface), periodic, N_x × N_y nodes of
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
//!
//! The minimiser is in [`fire`], the measurements in [`mod@measure`].
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
//! setting `cancel` makes the solver return [`Error::Cancelled`](crate::error::Error::Cancelled) within one step.

pub mod fire;
pub mod grid;
pub mod measure;
pub mod problem;
pub mod result;

pub use fire::{solve, DT_MAX};
pub use grid::{GfmdSetup, GridSpec};
pub use measure::{measure, Measurements};
pub use problem::{GfmdOptions, Problem, Progress, Solution};
pub use result::{run, GfmdResult, TheoryComparison};
