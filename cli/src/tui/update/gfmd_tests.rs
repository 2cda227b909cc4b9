//! Unit tests of `g` and the GFMD job's replies (no thread: the replies are made here).

use crate::tui::base::gfmd_view::GfmdView;
use crate::tui::base::protocol::{GfmdProgress, Reply};
use crate::tui::effects::engine as jobs;
use crate::tui::model::app::*;
use asperity::error::Error;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::heightmap::Surface;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

fn app() -> App {
    let p = Preset::resolve("system-1").unwrap();
    let mut a = App::new("system-1", p).unwrap();
    // the first frame's computation, asked for and done
    let gen = a.take_request().unwrap().gen;
    a.on_reply(Reply::Done { gen });
    a
}

fn key(a: &mut App, code: KeyCode) -> Vec<Command> {
    crate::tui::drive::press(a, KeyEvent::new(code, KeyModifiers::NONE))
}

/// The GFMD run a key's commands start: its id, scene, measured map and cancel flag.
type Start = (u64, Scene, Option<Arc<Surface>>, Arc<AtomicBool>);

fn started(cs: Vec<Command>) -> Option<Start> {
    cs.into_iter().find_map(|c| match c {
        Command::StartGfmd {
            id, scene, map, cancel, ..
        } => Some((id, scene, map, cancel)),
        _ => None,
    })
}

/// A progress report of run `id` in phase `index` of a five-load job at p* = 0.01.
fn report(index: usize, iteration: usize, residual: f64) -> GfmdProgress {
    let plan = crate::tui::base::progress::plan(0.01, &jobs::gfmd_sweep_spec(0.01).pressures());
    GfmdProgress {
        phase: plan[index],
        index,
        phases: plan.len(),
        grid: 512,
        iteration,
        residual,
        elapsed_s: 1.0,
        eta_s: Some(40.0),
    }
}

fn shown_progress(a: &App) -> Option<&GfmdProgress> {
    match a.jobs.gfmd() {
        GfmdState::Running { progress, .. } => Some(progress),
        _ => None,
    }
}

#[test]
fn g_starts_and_cancels_a_gfmd_run() {
    let mut a = app();
    let cs = key(&mut a, KeyCode::Char('g'));
    assert!(matches!(a.jobs.gfmd(), GfmdState::Running { .. }));
    assert!(a.animating(), "the panel's clock ticks while GFMD runs");
    let (id, scene, map, cancel) = started(cs).expect("a run to start");
    assert!(map.is_none(), "the preset's spectrum: a generated map");
    assert_eq!(scene, a.params.scene);
    let setup = jobs::gfmd_setup(&a.params.preset, &scene, None);
    assert_eq!(setup.grid.n(), 512);
    // progress of this run is shown; a stale run's is not
    a.on_reply(Reply::GfmdProgress {
        id,
        progress: report(0, 120, 1e-3),
    });
    assert_eq!(shown_progress(&a).map(|p| p.iteration), Some(120));
    a.on_reply(Reply::GfmdProgress {
        id: id + 7,
        progress: report(3, 999, 1.0),
    });
    assert_eq!(shown_progress(&a).map(|p| p.iteration), Some(120));
    // g again cancels
    let cs = key(&mut a, KeyCode::Char('g'));
    assert!(cancel.load(Ordering::Relaxed));
    assert_eq!(*a.jobs.gfmd(), GfmdState::Idle);
    assert!(started(cs).is_none());
    // a finished run is shown for its own scene only
    let (id, ..) = started(key(&mut a, KeyCode::Char('g'))).unwrap();
    let view = GfmdView {
        pressure: a.params.scene.pressure(),
        a_r: 0.02,
        mean_contact_stress: 0.5,
        gap_rel: 1.5,
        pr: vec![(0.1, 0.01), (0.2, 0.02)],
        grid: 512,
        iterations: 400,
        elapsed_s: 0.5,
        theory_a_r: Some(0.021),
        ..GfmdView::default()
    };
    a.on_reply(Reply::GfmdDone {
        id,
        result: Ok(view.clone()),
        elapsed_s: 49.8,
    });
    assert_eq!(a.gfmd_for_scene(), Some(&view));
    key(&mut a, KeyCode::Right); // p* changes: the result belongs to another scene
    assert_eq!(a.gfmd_for_scene(), None);
}

#[test]
fn gfmd_progress_phases_and_the_time_it_took() {
    let mut a = app();
    let (id, ..) = started(key(&mut a, KeyCode::Char('g'))).unwrap();
    // the start: relaxing, no residual yet, no estimate
    let p = shown_progress(&a).unwrap();
    assert_eq!(p.phase.label(), "relax at p*");
    assert_eq!(p.eta_s, None);
    // load 2 of 5 (phase 3): shown in the panel's words and the status line
    a.on_reply(Reply::GfmdProgress {
        id,
        progress: report(3, 732, 3e-5),
    });
    assert!(a.ui.message.is_none(), "the start message gives way to the progress");
    let p = shown_progress(&a).unwrap();
    assert_eq!(
        (p.phase.label(), p.steps_text()),
        ("load 2/5".into(), Some("732 it, res 3e-5".into()))
    );
    a.ui.show_timing = false;
    assert_eq!(
        a.gfmd_status().unwrap(),
        "GFMD 512²: load 2 of 5 (p* = 0.00577): 732 it, res 3e-5 · g cancels"
    );
    a.ui.show_timing = true;
    assert!(a.gfmd_status().unwrap().contains("left · g cancels"));
    // the end: "done in X s" in the status line and kept with the result
    a.on_reply(Reply::GfmdDone {
        id,
        result: Ok(GfmdView {
            pressure: a.params.scene.pressure(),
            ..GfmdView::default()
        }),
        elapsed_s: 49.8,
    });
    assert_eq!(a.ui.message.as_ref().unwrap().text, "GFMD done in 50 s");
    assert!(matches!(a.jobs.gfmd(), GfmdState::Done { elapsed_s, .. } if *elapsed_s == 49.8));
    assert_eq!(a.gfmd_status(), None);
    assert!(!a.animating());
}

#[test]
fn replies_of_a_cancelled_gfmd_run_are_dropped() {
    let mut a = app();
    let (old, ..) = started(key(&mut a, KeyCode::Char('g'))).unwrap();
    key(&mut a, KeyCode::Char('g')); // cancel
                                     // its late replies change nothing while idle
    a.on_reply(Reply::GfmdProgress {
        id: old,
        progress: report(2, 10, 0.1),
    });
    a.on_reply(Reply::GfmdDone {
        id: old,
        result: Err(Error::Cancelled),
        elapsed_s: 3.0,
    });
    assert_eq!(*a.jobs.gfmd(), GfmdState::Idle);
    // nor once a new run started
    let (new, ..) = started(key(&mut a, KeyCode::Char('g'))).unwrap();
    assert_ne!(new, old);
    a.on_reply(Reply::GfmdProgress {
        id: old,
        progress: report(5, 500, 1e-6),
    });
    a.on_reply(Reply::GfmdDone {
        id: old,
        result: Ok(GfmdView::default()),
        elapsed_s: 3.0,
    });
    assert!(matches!(a.jobs.gfmd(), GfmdState::Running { id, .. } if *id == new));
    assert_eq!(shown_progress(&a).unwrap().iteration, 0);
    // a failure of the running one is kept with its reason and time
    a.on_reply(Reply::GfmdDone {
        id: new,
        result: Err(Error::io("export", "test")),
        elapsed_s: 2.0,
    });
    assert!(matches!(a.jobs.gfmd(), GfmdState::Done { result: Err(e), .. } if e.contains("test")));
    assert!(a
        .ui
        .message
        .as_ref()
        .unwrap()
        .text
        .starts_with("GFMD failed after 2.0 s"));
}

#[test]
fn the_gfmd_start_message_goes_when_the_run_ends() {
    let mut a = app();
    let cs = key(&mut a, KeyCode::Char('g'));
    assert!(a.ui.message.as_ref().unwrap().text.starts_with("GFMD started"));
    let (id, ..) = started(cs).unwrap();
    a.on_reply(Reply::GfmdDone {
        id,
        result: Err(Error::Cancelled),
        elapsed_s: 1.0,
    });
    assert!(a.ui.message.is_none());
}

/// `tui --surface FILE`: `g` runs GFMD on the measured map while the scene is on the map's
/// spectrum, and on a generated map once the scene is back on the preset's.
#[test]
fn g_on_a_measured_surface_runs_on_its_map() {
    use asperity::surface::psd::{analyse, PsdOptions};
    use asperity::surface::readers::{read, ReadOptions};
    use asperity::surface::spectrum::{Spectrum, Tabulated};
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/two_bands.txt");
    let map = read(std::path::Path::new(path), &ReadOptions::default()).unwrap();
    let psd = analyse(
        &map,
        &PsdOptions {
            periodic: true,
            ..PsdOptions::default()
        },
    )
    .unwrap();
    let (q, c): (Vec<f64>, Vec<f64>) = psd.bins.iter().map(|b| (b.q, b.psd)).unzip();
    let table = Tabulated::new(q, c, path, None, None).unwrap();
    let mut a = app();
    a.params.scene = a
        .params
        .scene
        .clone()
        .with_spectrum(Spectrum::Tabulated(table.clone()))
        .unwrap();
    a.params.map = Some((path.to_string(), std::sync::Arc::new(map)));
    let (_, scene, map, _) = started(key(&mut a, KeyCode::Char('g'))).expect("a run to start");
    // the run carries the measured map it is set up from
    let setup = jobs::gfmd_setup(&a.params.preset, &scene, map.as_deref());
    assert_eq!(setup.surface.as_ref().map(|s| (s.nx, s.ny)), Some((32, 32)));
    assert_eq!(jobs::grid_side(&setup), 32);
    // a table of another name is not this map's spectrum
    let mut other = table;
    other.source = "other.csv".into();
    let s = scene.clone().with_spectrum(Spectrum::Tabulated(other)).unwrap();
    assert!(a.map_of(&s).is_none());
    // the preset's spectrum: a generated map
    let s = scene.with_spectrum(a.params.preset.spectrum().unwrap()).unwrap();
    assert!(a.map_of(&s).is_none());
    assert_eq!(
        jobs::grid_side(&jobs::gfmd_setup(&a.params.preset, &s, a.map_of(&s))),
        512
    );
}
