//! The GFMD job of `g` as plain data: its phases (the relaxation at p*, the theory on the map,
//! each load of the sweep, the theory's sweep on the map), a progress report, the estimate of
//! the time left, the job's state in the explorer ([`GfmdState`]), and the words the panel and
//! the status line show.
//!
//! Estimate of the time left ([`eta_s`]): each phase still to run is given the duration of
//! a finished phase like it, the phase running now its estimate less what it has run:
//! - the first load starts cold, like the relaxation at p*: the relaxation's duration;
//! - a later load is warm-started from the one below: the last finished warm load's duration
//!   (loads at higher p* take fewer steps, so the latest is the nearest), the relaxation's
//!   before one has finished. The cold first load is no guide to them: on a thin slab
//!   (t·q_r 0.1) it takes four times as long as a warm one;
//! - the theory's sweep: [`THEORY_SWEEP_FACTOR`] times the theory at p*.
//!
//! Until the relaxation and the theory at p* have both finished there is no estimate
//! ("estimating").

use crate::tui::base::gfmd_view::GfmdView;
use asperity::input::scene::Scene;

/// One phase of the GFMD job, in the order the job runs them ([`plan`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GfmdPhase {
    /// Relaxing the contact at the scene's p* from first touch.
    Relax {
        /// p*.
        p: f64,
    },
    /// The theory on the map's own spectrum at p*.
    Theory,
    /// Load `k` (from 0) of the `n` of the sweep on the same map, warm-started from load k − 1.
    Load {
        /// Index of the load.
        k: usize,
        /// Number of loads.
        n: usize,
        /// p* of the load.
        p: f64,
    },
    /// The theory's sweep on the map's spectrum over the same loads.
    TheorySweep,
}

impl GfmdPhase {
    /// A few words for the panel: "relax at p*", "theory on map", "load 2/5", "theory sweep".
    pub fn label(&self) -> String {
        match self {
            GfmdPhase::Relax { .. } => "relax at p*".into(),
            GfmdPhase::Theory => "theory on map".into(),
            GfmdPhase::Load { k, n, .. } => format!("load {}/{n}", k + 1),
            GfmdPhase::TheorySweep => "theory sweep".into(),
        }
    }

    /// The load of a relaxation (None for the theory's phases).
    pub fn load(&self) -> Option<f64> {
        match self {
            GfmdPhase::Relax { p } | GfmdPhase::Load { p, .. } => Some(*p),
            _ => None,
        }
    }

    /// What the status line says the job is doing.
    pub fn sentence(&self) -> String {
        let p = |p: &f64| crate::numfmt::sig(*p, 3);
        match self {
            GfmdPhase::Relax { p: x } => format!("relaxing at p* = {}", p(x)),
            GfmdPhase::Theory => "the theory on the map's spectrum at p*".into(),
            GfmdPhase::Load { k, n, p: x } => format!("load {} of {n} (p* = {})", k + 1, p(x)),
            GfmdPhase::TheorySweep => "the theory's sweep on the map".into(),
        }
    }
}

/// The phases of a job at p* = `p` whose sweep runs the loads `loads`.
pub fn plan(p: f64, loads: &[f64]) -> Vec<GfmdPhase> {
    let n = loads.len();
    let mut v = vec![GfmdPhase::Relax { p }, GfmdPhase::Theory];
    v.extend(loads.iter().enumerate().map(|(k, &p)| GfmdPhase::Load { k, n, p }));
    v.push(GfmdPhase::TheorySweep);
    v
}

/// The theory's sweep on the map costs about this many times the theory at p* (the default
/// preset's 512² map: 2.1 s against 0.18 s, test profile, 2 cores).
pub const THEORY_SWEEP_FACTOR: f64 = 12.0;

/// A progress report of the GFMD job.
#[derive(Debug, Clone, PartialEq)]
pub struct GfmdProgress {
    /// The phase running.
    pub phase: GfmdPhase,
    /// Its index in the job's [`plan`] (from 0).
    pub index: usize,
    /// Number of phases of the job.
    pub phases: usize,
    /// Grid side N of the map (0 before the first report).
    pub grid: usize,
    /// Solver steps of the phase so far (Polonsky–Keer iterations plus FIRE steps).
    pub iteration: usize,
    /// The relative force residual (NaN before the first report).
    pub residual: f64,
    /// Seconds since the job started.
    pub elapsed_s: f64,
    /// Seconds left ([`eta_s`]); None while estimating.
    pub eta_s: Option<f64>,
}

impl GfmdProgress {
    /// The report of a job that has just started at p*.
    pub fn starting(p: f64) -> GfmdProgress {
        GfmdProgress {
            phase: GfmdPhase::Relax { p },
            index: 0,
            phases: 0,
            grid: 0,
            iteration: 0,
            residual: f64::NAN,
            elapsed_s: 0.0,
            eta_s: None,
        }
    }

    /// "601 it, res 1e-8" (None in the theory's phases, which take no solver steps).
    pub fn steps_text(&self) -> Option<String> {
        self.phase.load()?;
        Some(if self.residual.is_finite() {
            format!("{} it, res {:.0e}", self.iteration, self.residual)
        } else {
            format!("{} it", self.iteration)
        })
    }

    /// The seconds left at `elapsed` seconds (the report's estimate less the time since it
    /// was made).
    pub fn left_at(&self, elapsed: f64) -> Option<f64> {
        self.eta_s.map(|e| (e - (elapsed - self.elapsed_s).max(0.0)).max(0.0))
    }

    /// The status line: "GFMD 512²: load 2 of 5 (p* = 0.00577): 732 it, res 3e-5 · 12 s,
    /// about 38 s left · g cancels" (the times at `elapsed` seconds; without them where None).
    pub fn status_text(&self, elapsed: Option<f64>) -> String {
        let mut s = "GFMD ".to_string();
        if self.grid > 0 {
            s.push_str(&format!("{}²: ", self.grid));
        }
        s.push_str(&self.phase.sentence());
        if let Some(st) = self.steps_text() {
            s.push_str(&format!(": {st}"));
        }
        if let Some(t) = elapsed {
            s.push_str(&format!(" · {}", time_text(t, self.left_at(t))));
        }
        s.push_str(" · g cancels");
        s
    }
}

/// Seconds left of a job with phases `plan`, of which the first `done.len()` have finished
/// (`done[i]` the duration of `plan[i]`) and the next has run `current_elapsed` seconds, by
/// the rules of the module docs. None until the relaxation and the theory at p* have finished.
pub fn eta_s(plan: &[GfmdPhase], done: &[f64], current_elapsed: f64) -> Option<f64> {
    let of = |want: fn(&GfmdPhase) -> bool| -> Vec<f64> {
        plan.iter()
            .zip(done)
            .filter(|(p, _)| want(p))
            .map(|(_, d)| *d)
            .collect()
    };
    let relax = of(|p| matches!(p, GfmdPhase::Relax { .. })).first().copied()?;
    let theory = of(|p| matches!(p, GfmdPhase::Theory)).first().copied()?;
    let warm = of(|p| matches!(p, GfmdPhase::Load { k, .. } if *k > 0))
        .last()
        .copied()
        .unwrap_or(relax);
    let estimate = |p: &GfmdPhase| match p {
        GfmdPhase::Relax { .. } | GfmdPhase::Load { k: 0, .. } => relax,
        GfmdPhase::Theory => theory,
        GfmdPhase::Load { .. } => warm,
        GfmdPhase::TheorySweep => THEORY_SWEEP_FACTOR * theory,
    };
    let mut rest = plan.iter().skip(done.len());
    let current = rest.next().map_or(0.0, |p| (estimate(p) - current_elapsed).max(0.0));
    Some(current + rest.map(estimate).sum::<f64>())
}

pub use crate::numfmt::duration as format_secs;

/// "12 s, about 38 s left", or "3.2 s, estimating the time left".
pub fn time_text(elapsed: f64, left: Option<f64>) -> String {
    match left {
        Some(l) => format!("{}, about {} left", format_secs(elapsed), format_secs(l)),
        None => format!("{}, estimating the time left", format_secs(elapsed)),
    }
}

/// The state of the background GFMD run.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum GfmdState {
    /// None started (or the last was cancelled).
    #[default]
    Idle,
    /// Running: id, the scene it runs, its last progress report, when it started.
    Running {
        /// Run id.
        id: u64,
        /// The scene it runs.
        scene: Scene,
        /// The last report: phase, solver steps, residual, time left.
        progress: GfmdProgress,
        /// When its thread started (the panel's clock runs between reports; None until the
        /// effect that starts it says so).
        started: Option<std::time::Instant>,
    },
    /// Finished: the scene it ran, its outcome and how long it took.
    Done {
        /// The scene it ran.
        scene: Scene,
        /// The result, or the error.
        result: std::result::Result<GfmdView, String>,
        /// Seconds the whole job took (relaxation, sweep and the theory on the map).
        elapsed_s: f64,
    },
}

/// Whether two scenes describe the same physical system (GFMD does not depend on the model).
pub(crate) fn same_system(a: &Scene, b: &Scene) -> bool {
    a.spectrum() == b.spectrum()
        && a.contact_modulus_pa() == b.contact_modulus_pa()
        && a.pressure() == b.pressure()
        && a.thickness_qr().to_bits() == b.thickness_qr().to_bits()
        && a.surface_energy_j_m2() == b.surface_energy_j_m2()
        && a.range_m() == b.range_m()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn job() -> Vec<GfmdPhase> {
        plan(0.01, &[0.003, 0.01, 0.03])
    }

    #[test]
    fn the_plan_is_relax_theory_loads_theory_sweep() {
        let p = job();
        assert_eq!(p.len(), 6);
        assert_eq!(p[0], GfmdPhase::Relax { p: 0.01 });
        assert_eq!(p[1], GfmdPhase::Theory);
        assert_eq!(p[3], GfmdPhase::Load { k: 1, n: 3, p: 0.01 });
        assert_eq!(p[5], GfmdPhase::TheorySweep);
        assert_eq!(p[3].label(), "load 2/3");
        assert_eq!(p[0].label(), "relax at p*");
        assert_eq!(p[1].load(), None);
    }

    #[test]
    fn no_estimate_until_relax_and_theory_have_finished() {
        let p = job();
        assert_eq!(eta_s(&p, &[], 3.0), None);
        assert_eq!(eta_s(&p, &[6.0], 0.1), None);
        // then: three loads at the relaxation's 6 s, the theory's sweep at 12 × 0.2 s
        let e = eta_s(&p, &[6.0, 0.2], 0.0).unwrap();
        assert!((e - (3.0 * 6.0 + 12.0 * 0.2)).abs() < 1e-12, "{e}");
    }

    #[test]
    fn loads_are_estimated_from_the_finished_loads_less_the_time_run() {
        let p = job();
        // the cold first load took 8 s; the warm ones are estimated from the relaxation's 6 s
        let e = eta_s(&p, &[6.0, 0.2, 8.0], 1.0).unwrap();
        assert!((e - (5.0 + 6.0 + 2.4)).abs() < 1e-12, "{e}");
        // the warm load 2 took 10 s; load 3 has run 4 s of its 10
        let e = eta_s(&p, &[6.0, 0.2, 8.0, 10.0], 4.0).unwrap();
        assert!((e - (6.0 + 2.4)).abs() < 1e-12, "{e}");
        // a phase running over its estimate counts as finishing now
        let e = eta_s(&p, &[6.0, 0.2, 8.0, 10.0], 30.0).unwrap();
        assert!((e - 2.4).abs() < 1e-12, "{e}");
        // in the last phase
        let e = eta_s(&p, &[6.0, 0.2, 8.0, 10.0, 9.0], 1.0).unwrap();
        assert!((e - 1.4).abs() < 1e-12, "{e}");
    }

    /// The estimate at the start of each load and of the theory's sweep, against the time the
    /// job then really took, on recorded jobs: `durations` of the phases of a five-load plan.
    fn worst_ratio(durations: &[f64]) -> f64 {
        let p = plan(0.01, &[0.0033, 0.0058, 0.01, 0.017, 0.03]);
        assert_eq!(p.len(), durations.len());
        (2..durations.len())
            .map(|i| {
                let e = eta_s(&p, &durations[..i], 0.0).unwrap();
                let actual: f64 = durations[i..].iter().sum();
                (e / actual).max(actual / e)
            })
            .fold(1.0, f64::max)
    }

    /// How far off (as a factor either way) the estimate may be from the first load on.
    const ETA_FACTOR: f64 = 2.0;

    #[test]
    fn the_estimate_is_within_a_factor_two_on_recorded_jobs() {
        // system I with t·q_r 0.1 on 256² (2 shared cores, test profile): the cold first load
        // takes 7.75 s, the warm ones 3.2 s and then 1.9 s; taking the mean of the finished
        // loads made the estimate on entering load 2 32 s against 9.9 s
        let thin = [3.54, 0.09, 7.75, 3.21, 1.89, 1.90, 1.98, 0.93];
        let r = worst_ratio(&thin);
        assert!(r <= ETA_FACTOR, "thin slab: off by a factor {r}");
        // the default preset (t·q_r ∞) on 512², from BENCHMARKS.md: warm loads gain little
        let thick = [5.86, 0.19, 9.49, 10.93, 7.25, 6.58, 5.96, 2.89];
        let r = worst_ratio(&thick);
        assert!(r <= ETA_FACTOR, "semi-infinite: off by a factor {r}");
    }

    #[test]
    fn durations_and_times_in_words() {
        assert_eq!(format_secs(0.012), "12 ms");
        assert_eq!(format_secs(0.42), "0.4 s");
        assert_eq!(format_secs(12.4), "12 s");
        assert_eq!(format_secs(125.0), "2 min 05 s");
        assert_eq!(format_secs(f64::NAN), "–");
        assert_eq!(time_text(12.0, Some(38.0)), "12 s, about 38 s left");
        assert_eq!(time_text(3.21, None), "3.2 s, estimating the time left");
    }

    #[test]
    fn the_status_line_names_the_phase_steps_and_times() {
        let pr = GfmdProgress {
            phase: GfmdPhase::Load { k: 1, n: 5, p: 0.00577 },
            index: 3,
            phases: 8,
            grid: 512,
            iteration: 732,
            residual: 3e-5,
            elapsed_s: 10.0,
            eta_s: Some(40.0),
        };
        assert_eq!(
            pr.status_text(Some(12.0)),
            "GFMD 512²: load 2 of 5 (p* = 0.00577): 732 it, res 3e-5 · 12 s, about 38 s left · g cancels"
        );
        assert_eq!(pr.left_at(100.0), Some(0.0));
        let th = GfmdProgress {
            phase: GfmdPhase::Theory,
            ..pr.clone()
        };
        assert_eq!(th.steps_text(), None);
        assert_eq!(
            GfmdProgress { grid: 0, ..th }.status_text(None),
            "GFMD the theory on the map's spectrum at p* · g cancels"
        );
        let start = GfmdProgress::starting(0.01);
        assert_eq!(start.steps_text().as_deref(), Some("0 it"));
        assert_eq!(start.left_at(1.0), None);
    }
}
