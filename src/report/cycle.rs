//! The report of the theory's load cycle, what `asperity sweep --cycle` prints (under `cycle`
//! in its JSON, or as its CSV) and Python's `cycle()` returns: the path up the loading branch
//! over log-spaced loads, back down the unloading branch while it exists and on into tension
//! to the theory's pull-off ([`crate::theory::cycle::path_through_tension`]), with where the
//! unloading branch ends, the jump-in, the pull-off and its bracket, and why the path stops;
//! on the way down each row also carries the pinned unloading branch's a_r on slabs
//! ([`crate::theory::unloading`], physics.md §6.6).
//!
//! The path runs on the load sweep's own continuation ([`super::sweep::pressure`]), so the
//! cycle and the sweep beside it share one gap table. The serialised field names are those of
//! the `cycle` object of `asperity sweep --cycle --format json` (a public interface).

use super::sweep::{self, Control};
use crate::error::{Error, Result};
use crate::input::scene::Scene;
use crate::theory::engine::Options;
use crate::theory::sweep::SweepSpec;

pub use crate::theory::cycle::{PathBranch, TheoryCycle as CycleReport, TheoryPathRow as CycleRow};

/// The theory's path along the load cycle of `scene` over `loads` (module docs); `preset`
/// names the scene's preset in the sweep it runs on.
///
/// # Errors
/// Invalid loads or options (before any work); [`Error::Cancelled`] when `ctl` cancels.
pub fn cycle(scene: &Scene, preset: &str, loads: &SweepSpec, opts: &Options, ctl: Control<'_>) -> Result<CycleReport> {
    loads.validate()?;
    let report = sweep::pressure(scene, preset, &[*loads], opts, true, ctl)?;
    report
        .cycle
        .ok_or_else(|| Error::Unsupported("a load sweep without its cycle".into()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;

    /// The cycle is the one the load sweep with `cycle` carries, row for row.
    #[test]
    fn the_cycle_is_the_load_sweeps_own() {
        let scene = Preset::resolve("system-2").unwrap().scene().unwrap();
        let loads = SweepSpec {
            from: 1e-3,
            to: 1e-2,
            points: 4,
        };
        let opts = Options::default();
        let mut quiet = |_: usize, _: usize| {};
        let c = cycle(&scene, "system-2", &loads, &opts, Control::none(&mut quiet)).unwrap();
        let mut quiet = |_: usize, _: usize| {};
        let sw = sweep::pressure(&scene, "system-2", &[loads], &opts, true, Control::none(&mut quiet)).unwrap();
        let expected = sw.cycle.unwrap();
        assert_eq!(c.rows, expected.rows);
        assert_eq!(c.pull_off_pressure, expected.pull_off_pressure);
        assert!(c.rows.iter().any(|r| r.branch == PathBranch::Unloading));
        let bad = SweepSpec { points: 0, ..loads };
        assert!(cycle(&scene, "system-2", &bad, &opts, Control::none(&mut quiet)).is_err());
    }
}
