//! The GFMD job's clock, kept by its thread: which phase runs since when and how long the
//! finished ones took, turned into the progress reports the update shows
//! ([`GfmdProgress`], with the estimate of the time left, [`eta_s`]). The clock is read
//! here, in the effect, never in the state.

use crate::tui::base::progress::{eta_s, GfmdPhase, GfmdProgress};
use std::time::Instant;

/// The job's clock: which phase runs since when, and how long the finished ones took.
#[derive(Debug, Clone)]
pub struct Timeline {
    plan: Vec<GfmdPhase>,
    grid: usize,
    start: Instant,
    phase_start: Instant,
    done: Vec<f64>,
}

impl Timeline {
    /// A job with phases `plan` on an N = `grid` map, starting now.
    pub fn new(plan: Vec<GfmdPhase>, grid: usize) -> Timeline {
        let now = Instant::now();
        Timeline {
            plan,
            grid,
            start: now,
            phase_start: now,
            done: Vec::new(),
        }
    }

    /// Moves on to phase `index` (the phases between finish now); true when the phase changed.
    pub fn enter(&mut self, index: usize) -> bool {
        let index = index.min(self.plan.len().saturating_sub(1));
        if index <= self.done.len() {
            return false;
        }
        while self.done.len() < index {
            self.done.push(self.phase_start.elapsed().as_secs_f64());
            self.phase_start = Instant::now();
        }
        true
    }

    /// The report of the phase running now.
    pub fn report(&self, iteration: usize, residual: f64) -> GfmdProgress {
        let index = self.done.len().min(self.plan.len().saturating_sub(1));
        GfmdProgress {
            phase: self.plan[index],
            index,
            phases: self.plan.len(),
            grid: self.grid,
            iteration,
            residual,
            elapsed_s: self.start.elapsed().as_secs_f64(),
            eta_s: eta_s(&self.plan, &self.done, self.phase_start.elapsed().as_secs_f64()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::base::progress::plan;

    fn job() -> Vec<GfmdPhase> {
        plan(0.01, &[0.003, 0.01, 0.03])
    }

    #[test]
    fn the_timeline_records_finished_phases() {
        let mut t = Timeline::new(job(), 64);
        assert!(!t.enter(0));
        let r = t.report(10, 0.1);
        assert_eq!((r.index, r.phases, r.grid, r.eta_s), (0, 6, 64, None));
        // straight to load 1: relax and theory finished
        assert!(t.enter(2));
        assert!(!t.enter(2));
        let r = t.report(0, f64::NAN);
        assert_eq!(r.phase, GfmdPhase::Load { k: 0, n: 3, p: 0.003 });
        assert!(r.eta_s.is_some());
        // past the end stays on the last phase
        t.enter(99);
        assert_eq!(t.report(0, 0.0).phase, GfmdPhase::TheorySweep);
    }
}
