//! Tests of the GFMD job of `g` on real grids: its phases in order, and that cancelling it in
//! any phase ends its thread within half a second (the latency the explorer promises; the
//! measured values are in BENCHMARKS.md).

use super::*;
use crate::tui::base::progress::{GfmdPhase, GfmdProgress};
use asperity::input::preset::Preset;
use std::sync::mpsc::channel;
use std::time::{Duration, Instant};

/// Longest time from raising the cancel flag to the end of the GFMD thread.
const CANCEL_LATENCY_S: f64 = 0.5;

/// The explorer's GFMD setup of system I's opening scene (adhesive), on an N×N grid.
fn setup(n: usize) -> asperity::gfmd::GfmdSetup {
    let preset = Preset::resolve("system-1").unwrap();
    let scene = crate::tui::model::app::initial_scene(&preset).unwrap();
    let mut s = gfmd_setup(&preset, &scene, None);
    s.grid = s.grid.with_grid(n).unwrap();
    s
}

/// Runs the job on its thread and raises its cancel flag at the first report `when` accepts;
/// returns the seconds from the flag to the end of the thread, and that report.
fn cancel_latency(setup: &asperity::gfmd::GfmdSetup, when: &dyn Fn(&GfmdProgress) -> bool) -> (f64, GfmdProgress) {
    let cancel = Arc::new(AtomicBool::new(false));
    let (tx, rx) = channel();
    let thread = spawn_gfmd(1, setup.clone(), cancel.clone(), move |r| {
        let _ = tx.send(r);
    })
    .unwrap();
    let mut flagged: Option<(Instant, GfmdProgress)> = None;
    loop {
        match rx.recv_timeout(Duration::from_secs(300)).expect("the job reports") {
            Reply::GfmdProgress { progress, .. } if flagged.is_none() && when(&progress) => {
                cancel.store(true, std::sync::atomic::Ordering::Relaxed);
                flagged = Some((Instant::now(), progress));
            }
            Reply::GfmdDone { result, .. } => {
                let (t, at) = flagged.expect("the job ended before the point to cancel it");
                thread.join().unwrap();
                let latency = t.elapsed().as_secs_f64();
                assert!(matches!(result, Err(Error::Cancelled)), "{result:?}");
                return (latency, at);
            }
            _ => {}
        }
    }
}

/// [`cancel_latency`] within [`CANCEL_LATENCY_S`], measured again once where a loaded machine
/// delayed the first.
fn assert_prompt(what: &str, setup: &asperity::gfmd::GfmdSetup, when: &dyn Fn(&GfmdProgress) -> bool) {
    let (t, at) = cancel_latency(setup, when);
    eprintln!(
        "GFMD cancel in {what} ({}, {}²): {:.1} ms",
        at.phase.label(),
        setup.grid.n(),
        t * 1e3
    );
    if t <= CANCEL_LATENCY_S {
        return;
    }
    let (t2, _) = cancel_latency(setup, when);
    eprintln!("  again: {:.1} ms", t2 * 1e3);
    assert!(t2 <= CANCEL_LATENCY_S, "cancel in {what} took {t:.3} s, then {t2:.3} s");
}

#[test]
fn cancel_during_the_relaxation_on_the_default_grid_ends_the_job_promptly() {
    // the preset's own 512² grid, a few hundred FIRE steps in (the relaxation takes seconds)
    let s = setup(512);
    assert_eq!(
        s.grid.n(),
        gfmd_setup(&Preset::resolve("system-1").unwrap(), &s.scene, None)
            .grid
            .n()
    );
    assert_prompt("the relaxation", &s, &|p| {
        matches!(p.phase, GfmdPhase::Relax { .. }) && p.iteration >= 100
    });
}

#[test]
fn cancel_in_every_later_phase_ends_the_job_promptly() {
    let s = setup(128);
    assert_prompt("the theory at p*", &s, &|p| p.phase == GfmdPhase::Theory);
    // at the report that enters the load (reports within a phase are spaced in time, and a
    // 128² load on an idle machine can relax before the next one): the cancel lands in it
    assert_prompt("a load of the sweep", &s, &|p| {
        matches!(p.phase, GfmdPhase::Load { k: 1, .. })
    });
    assert_prompt("the theory's sweep", &s, &|p| p.phase == GfmdPhase::TheorySweep);
}

#[test]
fn the_job_reports_every_phase_in_order_and_ends_with_the_sweep() {
    let s = setup(64);
    let (tx, rx) = channel();
    let thread = spawn_gfmd(3, s.clone(), Arc::new(AtomicBool::new(false)), move |r| {
        let _ = tx.send(r);
    })
    .unwrap();
    let mut seen: Vec<usize> = Vec::new();
    let mut estimates = 0;
    let view = loop {
        match rx.recv_timeout(Duration::from_secs(300)).expect("the job reports") {
            Reply::GfmdProgress { id, progress } => {
                assert_eq!(id, 3);
                assert_eq!((progress.phases, progress.grid), (2 + GFMD_SWEEP_POINTS + 1, 64));
                if seen.last() != Some(&progress.index) {
                    seen.push(progress.index);
                }
                estimates += usize::from(progress.eta_s.is_some());
                // no estimate before the relaxation and the theory at p* have finished
                assert_eq!(progress.eta_s.is_some(), progress.index >= 2, "{progress:?}");
            }
            Reply::GfmdDone { id, result, elapsed_s } => {
                assert_eq!(id, 3);
                assert!(elapsed_s > 0.0);
                break result.unwrap();
            }
            other => panic!("{other:?}"),
        }
    };
    thread.join().unwrap();
    assert_eq!(seen, (0..2 + GFMD_SWEEP_POINTS + 1).collect::<Vec<_>>());
    assert!(estimates > 0);
    assert_eq!(view.sweep.len(), GFMD_SWEEP_POINTS);
    assert_eq!(view.sweep_error, None);
    let spec = gfmd_sweep_spec(s.scene.pressure());
    for (row, p) in view.sweep.iter().zip(spec.pressures()) {
        assert_eq!(row.0, p);
    }
}
