//! The report of a GFMD run ([`crate::gfmd`]): the one spec every front end fills in
//! ([`GfmdSpec`]: the knobs of `asperity gfmd`, Python's `gfmd()`/`gfmd_cycle()` and the
//! explorer, with their defaults and ranges, checked before any work), the study around a
//! single run ([`GfmdStudy`]: its resolution ladder and the ensemble over seeds), and the rows
//! that `gfmd --format csv` writes for a single run, a sweep and a load cycle ([`GfmdRow`]).
//!
//! A row holds the columns of `asperity sweep` that GFMD measures, under the same names, then
//! GFMD's own (iterations, residual), then the theory on the same map's spectrum at the same
//! load. On a cycle the theory's columns follow GFMD's branch: on unloading rows its unloading
//! branch where it has two (inside a hysteresis window; σ̄_c* is left out there, the sweep
//! does not give it on that branch), on tensile rows its contact branch under tension (a_r and
//! σ̄_c*; the mean gap is not defined there), none beyond the theory's own pull-off.
//!
//! Serialised field names are those of `asperity gfmd --format json` and the CSV columns of
//! `gfmd --format csv` (a public interface).

use crate::error::{Error, Field, Result};
use crate::gfmd::cycle::{GfmdCycle, PathBranch};
use crate::gfmd::ladder::{Ensemble, Ladder};
use crate::gfmd::sweep::{GfmdSweep, GfmdSweepRow};
use crate::gfmd::{GfmdOptions, GfmdResult, GfmdSetup, GridSpec, Method};
use crate::input::preset::Preset;
use crate::input::scene::Scene;
use crate::surface::heightmap::Surface;
use crate::theory::cycle::TheoryPathRow;
use serde::Serialize;

pub use crate::fit::gfmd_reference::{check_ladder, check_seeds, LADDER_RANGE, MAX_SEEDS};
/// The default resolution ladder (λ_s/Δa of each rung).
pub const DEFAULT_LADDER: [f64; 3] = [4.0, 8.0, 16.0];
/// What a GFMD run is asked for, each knob's default that of `asperity gfmd`.
#[derive(Debug, Clone, PartialEq)]
pub struct GfmdSpec {
    /// Grid side N (None: the preset's `[gfmd]` grid); not with a given map.
    pub grid: Option<i64>,
    /// Seed of the random surface.
    pub seed: u64,
    /// Relative force residual to reach.
    pub tolerance: f64,
    /// Largest number of relaxation steps (None: the solver's default).
    pub max_iterations: Option<usize>,
    /// Bins of the Pr(σ*) histogram (None: the solver's default).
    pub bins: Option<usize>,
    /// The minimiser.
    pub method: Method,
    /// Rescale γ_s and ρ on the reduced grid to keep γ̃_glo and the Tabor parameter.
    pub rescale: bool,
    /// Realisations K (seeds S..S+K−1) of an ensemble; 1 for one run.
    pub seeds: usize,
    /// λ_s/Δa of the rungs of a resolution ladder (None: no ladder).
    pub ladder: Option<Vec<f64>>,
}

impl Default for GfmdSpec {
    fn default() -> Self {
        GfmdSpec {
            grid: None,
            seed: 1,
            tolerance: GfmdOptions::default().tolerance,
            max_iterations: None,
            bins: None,
            method: Method::Auto,
            rescale: true,
            seeds: 1,
            ladder: None,
        }
    }
}

impl GfmdSpec {
    /// The solver's options of this spec.
    pub fn options(&self) -> GfmdOptions {
        let d = GfmdOptions::default();
        GfmdOptions {
            tolerance: self.tolerance,
            max_iterations: self.max_iterations.unwrap_or(d.max_iterations),
            pr_bins: self.bins.unwrap_or(d.pr_bins),
            method: self.method,
            ..d
        }
    }

    /// The run's setup and options for `scene` of `preset`, on `surface` where a map is given,
    /// every knob checked before any work.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the field: a grid with a given map or N < 4, the solver's
    /// options ([`GfmdOptions::validate`]), Polonsky–Keer on a slab, K outside
    /// 1..=[`MAX_SEEDS`], a rung outside [`LADDER_RANGE`] or fewer than two distinct rungs.
    pub fn setup(&self, preset: &Preset, scene: &Scene, surface: Option<Surface>) -> Result<(GfmdSetup, GfmdOptions)> {
        if let (Some(n), Some(_)) = (self.grid, &surface) {
            return Err(Error::invalid(
                Field::Grid,
                n as f64,
                "none with a given map (its own grid)",
            ));
        }
        let grid = GridSpec::of_preset(preset, self.grid)?;
        let opts = self.options();
        opts.validate()?;
        self.method.check_on(scene)?;
        check_seeds(self.seeds)?;
        if let Some(ladder) = &self.ladder {
            check_ladder(ladder)?;
        }
        let setup = GfmdSetup {
            scene: scene.clone(),
            grid,
            seed: self.seed,
            surface,
            rescale: self.rescale,
        };
        Ok((setup, opts))
    }
}

/// A single run with its study: the object of `gfmd --extrapolate` / `--seeds K`.
#[derive(Debug, Serialize)]
pub struct GfmdStudy {
    /// The run at the preset's grid (seed S).
    #[serde(flatten)]
    pub base: GfmdResult,
    /// The ladder of seed S (None without a ladder).
    pub extrapolation: Option<Ladder>,
    /// Mean ± standard error over the seeds (None for K = 1).
    pub ensemble: Option<Ensemble>,
}

/// One row of `gfmd --format csv`: GFMD's measurements at one load
/// (a value not measured is NaN, an empty cell), then the theory's at that load (None where
/// it has none).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GfmdRow {
    /// GFMD's measurements (p, a_r, …, iterations, residual).
    #[serde(flatten)]
    pub row: GfmdSweepRow,
    /// The theory's a_r at this load (module docs for its branch).
    pub theory_a_r: Option<f64>,
    /// The theory's ū/h_rms.
    pub theory_mean_gap_rel: Option<f64>,
    /// The theory's σ̄_c*.
    pub theory_mean_contact_stress: Option<f64>,
    /// The branch of a load cycle's row (None for single runs and sweeps).
    pub branch: Option<PathBranch>,
}

impl GfmdRow {
    fn new(row: GfmdSweepRow, theory: [Option<f64>; 3], branch: Option<PathBranch>) -> GfmdRow {
        let [theory_a_r, theory_mean_gap_rel, theory_mean_contact_stress] = theory;
        GfmdRow {
            row,
            theory_a_r,
            theory_mean_gap_rel,
            theory_mean_contact_stress,
            branch,
        }
    }
}

/// The row of a single run (its elastic energy is not measured: NaN).
pub fn single_row(o: &GfmdResult) -> GfmdRow {
    let th = o.theory.as_ref();
    let row = GfmdSweepRow {
        p: o.pressure,
        a_r: o.stats.a_r,
        mean_gap_rel: o.mean_gap_rel,
        mean_gap: o.mean_gap,
        mean_contact_stress: o.stats.mean_contact_stress,
        elastic_energy: f64::NAN,
        converged: o.converged,
        contact_stress_variance: o.stats.contact_stress_variance,
        iterations: o.iterations,
        residual: o.residual,
    };
    let theory = [
        th.map(|t| t.stats.a_r),
        th.and_then(|t| t.mean_gap_rel),
        th.map(|t| t.stats.mean_contact_stress),
    ];
    GfmdRow::new(row, theory, None)
}

/// The rows of a load sweep, with the theory's sweep at the same loads.
pub fn sweep_rows(sw: &GfmdSweep) -> Vec<GfmdRow> {
    sw.rows
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let th = sw.theory.as_ref().and_then(|t| t.rows.get(k));
            let theory = [
                th.map(|t| t.a_r),
                th.map(|t| t.mean_gap_rel),
                th.map(|t| t.mean_contact_stress),
            ];
            GfmdRow::new(*r, theory, None)
        })
        .collect()
}

/// The theory's row under tension at GFMD's load `p` ≤ 0 (the same loads: 0, −p₁, −2p₁, …).
fn tensile_row(c: &GfmdCycle, p: f64) -> Option<&TheoryPathRow> {
    let t = c.theory_cycle.as_ref()?;
    t.rows
        .iter()
        .find(|r| r.p <= 0.0 && (r.p - p).abs() <= 1e-12 * p.abs().max(1e-300))
}

/// The rows of a load path, each with its branch and the theory on that branch (module docs).
pub fn cycle_rows(c: &GfmdCycle) -> Vec<GfmdRow> {
    c.rows
        .iter()
        .map(|r| {
            let g = &r.row;
            let unloading = r.branch == PathBranch::Unloading;
            let theory = if g.p > 0.0 {
                let th = c
                    .theory
                    .as_ref()
                    .and_then(|t| t.rows.iter().find(|t| (t.p / g.p - 1.0).abs() < 1e-12));
                let pick = |load: f64, unload: f64| if unloading && unload.is_finite() { unload } else { load };
                [
                    th.map(|t| pick(t.a_r, t.a_r_unloading)),
                    th.map(|t| pick(t.mean_gap_rel, t.mean_gap_unloading_rel)),
                    th.filter(|t| !(unloading && t.a_r_unloading.is_finite()))
                        .map(|t| t.mean_contact_stress),
                ]
            } else {
                let tr = tensile_row(c, g.p);
                [tr.map(|t| t.a_r), None, tr.map(|t| t.mean_contact_stress)]
            };
            GfmdRow::new(*g, theory, Some(r.branch))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn preset() -> Preset {
        Preset::resolve("system-1").unwrap()
    }

    #[test]
    fn the_default_spec_is_the_preset_grid_with_the_solver_defaults() {
        let p = preset();
        let scene = p.scene().unwrap();
        let (setup, opts) = GfmdSpec::default().setup(&p, &scene, None).unwrap();
        assert_eq!(setup.grid, GridSpec::of_preset(&p, None).unwrap());
        assert_eq!(opts, GfmdOptions::default());
        assert_eq!((setup.seed, setup.rescale), (1, true));
    }

    #[test]
    fn every_knob_is_checked_before_any_work() {
        let p = preset();
        let scene = p.scene().unwrap();
        let bad = |spec: GfmdSpec, key: &str| {
            let e = spec.setup(&p, &scene, None).unwrap_err();
            assert!(e.to_string().contains(key), "{key}: {e}");
        };
        bad(
            GfmdSpec {
                grid: Some(3),
                ..GfmdSpec::default()
            },
            "grid",
        );
        bad(
            GfmdSpec {
                seeds: 0,
                ..GfmdSpec::default()
            },
            "seeds",
        );
        bad(
            GfmdSpec {
                seeds: MAX_SEEDS + 1,
                ..GfmdSpec::default()
            },
            "seeds",
        );
        bad(
            GfmdSpec {
                tolerance: 2.0,
                ..GfmdSpec::default()
            },
            "tolerance",
        );
        bad(
            GfmdSpec {
                ladder: Some(vec![4.0, 4.0]),
                ..GfmdSpec::default()
            },
            "ladder",
        );
        bad(
            GfmdSpec {
                ladder: Some(vec![1.0, 4.0]),
                ..GfmdSpec::default()
            },
            "ladder",
        );
        let slab = scene.clone().with_thickness_qr(0.5).unwrap();
        let pk = GfmdSpec {
            method: Method::PolonskyKeer,
            ..GfmdSpec::default()
        };
        assert!(pk.setup(&p, &slab, None).is_err());
        let map = Surface::new(8, 8, 1e-7, (0..64).map(|i| (i as f64).sin() * 1e-9).collect()).unwrap();
        bad(
            GfmdSpec {
                grid: Some(8),
                ..GfmdSpec::default()
            },
            "grid",
        );
        assert!(GfmdSpec {
            grid: Some(8),
            ..GfmdSpec::default()
        }
        .setup(&p, &scene, Some(map))
        .is_err());
        assert!(check_ladder(&DEFAULT_LADDER).is_ok());
    }
}
