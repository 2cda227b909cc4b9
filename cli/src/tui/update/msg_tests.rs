//! Unit tests of [`update`], one message variant (and one reply variant) at a time: the next
//! state and the commands asked for. No terminal, no thread, no file: what an effect would
//! find is handed in as its message.

use super::update;
use crate::tui::base::data::{ScaleFrame, ScalesData, SweepData, ThicknessData};
use crate::tui::base::gfmd_view::GfmdView;
use crate::tui::base::kinds::ChartKind;
use crate::tui::base::progress::GfmdProgress;
use crate::tui::base::protocol::{point_key, scales_key, sweep_key, thickness_key, Reply};
use crate::tui::base::tour::{Tour, DEFAULT_TOUR};
use crate::tui::model::app::*;
use crate::tui::model::msg::{Msg, Written};
use asperity::error::Error;
use asperity::input::preset::Preset;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

fn app() -> App {
    let mut a = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
    a.ui.show_timing = false;
    a
}

/// An explorer whose first frame's computation was already taken.
fn idle() -> App {
    let mut a = app();
    let _ = a.take_request();
    a
}

fn key(a: &mut App, code: KeyCode) -> Vec<Command> {
    update(a, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)))
}

fn reply(a: &mut App, r: Reply) -> Vec<Command> {
    update(a, Msg::Reply(Box::new(r)))
}

/// The commands' names, in order (also the keys tests').
pub(super) fn names(cs: &[Command]) -> Vec<&'static str> {
    cs.iter()
        .map(|c| match c {
            Command::Compute(_) => "compute",
            Command::StartGfmd { .. } => "gfmd",
            Command::CancelGfmd(_) => "cancel",
            Command::Export(job) if job.charts => "save",
            Command::Export(_) => "export",
            Command::LoadPreset(_) => "preset",
            Command::LoadTour(_) => "tour",
            Command::Quit => "quit",
        })
        .collect()
}

fn oops() -> Error {
    Error::Unsupported("test error".into())
}

#[test]
fn a_key_changes_the_state_and_returns_the_computation() {
    let mut a = app();
    let _ = a.take_request();
    let p0 = a.params.scene.pressure();
    let cs = key(&mut a, KeyCode::Right);
    assert_eq!(names(&cs), ["compute"]);
    assert!(matches!(&cs[0], Command::Compute(r) if r.scene == a.params.scene));
    assert!(a.params.scene.pressure() > p0 && !a.has_pending());
    // a key that changes nothing computed asks for nothing
    assert!(key(&mut a, KeyCode::Down).is_empty());
    assert_eq!(names(&key(&mut a, KeyCode::Char('q'))), ["quit"]);
}

#[test]
fn file_and_gfmd_keys_return_their_commands() {
    let mut a = idle();
    assert_eq!(names(&key(&mut a, KeyCode::Char('e'))), ["export"]);
    assert_eq!(names(&key(&mut a, KeyCode::Char('s'))), ["save"]);
    let cs = key(&mut a, KeyCode::Char('g'));
    let [Command::StartGfmd { scene, .. }] = &cs[..] else {
        panic!("{cs:?}")
    };
    assert_eq!(*scene, a.params.scene);
    // g again cancels: the run is told to stop
    let cs = key(&mut a, KeyCode::Char('g'));
    let [Command::CancelGfmd(flag)] = &cs[..] else {
        panic!("{cs:?}")
    };
    assert!(
        !flag.load(std::sync::atomic::Ordering::Relaxed),
        "the update itself stops nothing"
    );
    assert_eq!(*a.jobs.gfmd(), GfmdState::Idle);
}

#[test]
fn a_preset_is_asked_for_and_taken_when_it_arrives() {
    let mut a = idle();
    key(&mut a, KeyCode::Char('p'));
    key(&mut a, KeyCode::Down);
    let cs = key(&mut a, KeyCode::Enter);
    let [Command::LoadPreset(source)] = &cs[..] else {
        panic!("{cs:?}")
    };
    // nothing changes until the effect answers
    assert_eq!(a.params.preset.name, "system-1");
    let source = source.clone();
    let result = Preset::resolve(&source);
    let cs = update(
        &mut a,
        Msg::PresetLoaded {
            source: source.clone(),
            result,
        },
    );
    assert_eq!(names(&cs), ["compute"]);
    assert_eq!(
        (a.params.source.as_str(), a.params.preset.name.as_str()),
        (source.as_str(), "system-2")
    );
    assert_eq!(a.params.scene, a.params.base);
    // one that cannot be read leaves everything as it is and says why
    let before = a.params.scene.clone();
    let result = Err(oops());
    update(
        &mut a,
        Msg::PresetLoaded {
            source: "nope".into(),
            result,
        },
    );
    assert_eq!(
        (a.params.scene.clone(), a.params.preset.name.as_str()),
        (before, "system-2")
    );
    assert!(a
        .ui
        .message
        .as_ref()
        .is_some_and(|m| m.error && m.text.contains("test error")));
}

#[test]
fn t_asks_for_the_tour_and_walks_it_when_it_arrives() {
    let mut a = idle();
    let cs = key(&mut a, KeyCode::Char('t'));
    assert!(matches!(&cs[..], [Command::LoadTour(n)] if n == DEFAULT_TOUR), "{cs:?}");
    assert!(a.ui.tour.is_none());
    update(&mut a, Msg::TourLoaded(Err(oops())));
    assert!(a.ui.tour.is_none() && a.ui.message.as_ref().is_some_and(|m| m.error));
    let tour = Tour::resolve(DEFAULT_TOUR).unwrap();
    let first = tour.steps[0].clone();
    update(&mut a, Msg::TourLoaded(Ok(tour)));
    assert_eq!(a.ui.tour.as_ref().map(|t| t.step), Some(0));
    assert_eq!((a.params.scene.clone(), a.ui.charts), (first.scene, first.charts));
    // t again leaves it
    assert!(key(&mut a, KeyCode::Char('t')).is_empty());
    assert!(a.ui.tour.is_none());
}

#[test]
fn a_tick_turns_the_spinner_and_plays_the_scale_view_to_its_end() {
    let mut a = idle();
    assert!(update(&mut a, Msg::Tick).is_empty());
    assert_eq!(a.ui.spinner, 1);
    let frame = |q_rel| ScaleFrame {
        q_rel,
        a_r: 0.1,
        sigma_a: 0.0,
        pr: Vec::new(),
    };
    a.results.set_scales(Ok(ScalesData {
        frames: vec![frame(1.0), frame(2.0), frame(4.0)],
        area: Vec::new(),
        wall: Vec::new(),
    }));
    a.ui.charts[0] = ChartKind::Scales;
    a.ui.playing = true;
    a.ui.frame = Some(0);
    update(&mut a, Msg::Tick);
    assert_eq!(a.ui.frame, Some(1));
    update(&mut a, Msg::Tick);
    update(&mut a, Msg::Tick);
    assert_eq!((a.ui.playing, a.ui.frame), (false, None), "the play stops at q_s");
}

#[test]
fn the_clock_is_the_loops_and_times_the_busy_state_and_the_gfmd_run() {
    let mut a = idle();
    assert_eq!(a.ui.now, None);
    assert_eq!(a.ui.elapsed_s(Some(std::time::Instant::now())), 0.0, "no clock yet");
    let t0 = std::time::Instant::now();
    assert!(update(&mut a, Msg::Clock(t0)).is_empty());
    assert_eq!(a.ui.now, Some(t0));
    // a request is busy since the loop's clock, not since a clock update read itself
    a.refresh();
    a.take_request().unwrap();
    assert_eq!(a.jobs.busy_since(), Some(t0));
    let later = t0 + std::time::Duration::from_millis(1500);
    update(&mut a, Msg::Clock(later));
    assert!((a.ui.elapsed_s(a.jobs.busy_since()) - 1.5).abs() < 1e-9);
    // an earlier instant than the clock's reads as no time, never negative
    assert_eq!(a.ui.elapsed_s(Some(later + std::time::Duration::from_secs(1))), 0.0);
    // the GFMD status line's time is the clock's since the run started
    a.ui.show_timing = true;
    let cs = key(&mut a, KeyCode::Char('g'));
    let [Command::StartGfmd { id, .. }] = cs[..] else {
        panic!("{cs:?}")
    };
    update(&mut a, Msg::GfmdStarted { id, grid: 32, at: t0 });
    let status = a.gfmd_status().unwrap();
    update(&mut a, Msg::Clock(later + std::time::Duration::from_secs(60)));
    assert_ne!(a.gfmd_status().unwrap(), status, "the status follows the loop's clock");
}

#[test]
fn replies_of_the_current_scene_are_kept_and_of_another_dropped() {
    let mut a = app();
    let (src, scene) = (a.params.source.clone(), a.params.scene.clone());
    // another γ_s: another point, sweep, gap, thickness sweep and scale view
    let mut other = scene.clone();
    other
        .set_surface_energy_j_m2(scene.surface_energy_j_m2() * 2.0 + 0.01)
        .unwrap();
    let range = a.range();
    // a point (an error is a result too)
    reply(
        &mut a,
        Reply::Point {
            gen: 1,
            key: point_key(&src, &other),
            result: Err(oops()),
        },
    );
    assert!(a.results.point().is_none());
    reply(
        &mut a,
        Reply::Point {
            gen: 1,
            key: point_key(&src, &scene),
            result: Err(oops()),
        },
    );
    assert!(matches!(a.results.point(), Some(Err(_))) && a.results.point_gen == 1);
    // a load sweep
    let sweep = || Ok(SweepData::default());
    reply(
        &mut a,
        Reply::Sweep {
            gen: 1,
            key: sweep_key(&src, &other, range),
            result: sweep(),
        },
    );
    assert!(a.results.sweep().is_none());
    reply(
        &mut a,
        Reply::Sweep {
            gen: 1,
            key: sweep_key(&src, &scene, range),
            result: sweep(),
        },
    );
    assert!(matches!(a.results.sweep(), Some(Ok(_))));
    // the mean gap
    reply(
        &mut a,
        Reply::Gap {
            gen: 1,
            key: point_key(&src, &other),
            result: Ok(9.0),
        },
    );
    assert_eq!(a.gap_value(), None);
    reply(
        &mut a,
        Reply::Gap {
            gen: 1,
            key: point_key(&src, &scene),
            result: Ok(1.5),
        },
    );
    assert_eq!(a.gap_value(), Some(1.5));
    // a thickness sweep
    let th = || Ok(ThicknessData::default());
    reply(
        &mut a,
        Reply::Thickness {
            gen: 1,
            key: thickness_key(&src, &other),
            result: th(),
        },
    );
    assert!(a.results.thickness().is_none());
    reply(
        &mut a,
        Reply::Thickness {
            gen: 1,
            key: thickness_key(&src, &scene),
            result: th(),
        },
    );
    assert!(matches!(a.results.thickness(), Some(Ok(_))));
    // the scale view
    reply(
        &mut a,
        Reply::Scales {
            gen: 1,
            key: scales_key(&src, &other),
            result: Err(oops()),
        },
    );
    assert!(a.results.scales().is_none());
    reply(
        &mut a,
        Reply::Scales {
            gen: 1,
            key: scales_key(&src, &scene),
            result: Err(oops()),
        },
    );
    assert!(a.results.scales().is_some());
}

#[test]
fn done_ends_the_busy_state_of_the_newest_request_only() {
    let mut a = app();
    let first = a.take_request().unwrap().gen;
    a.refresh();
    let second = a.take_request().unwrap().gen;
    assert!(a.jobs.busy());
    assert!(reply(&mut a, Reply::Done { gen: first }).is_empty());
    assert!(a.jobs.busy(), "an older request's end is not the newest's");
    reply(&mut a, Reply::Done { gen: second });
    assert!(!a.jobs.busy() && a.jobs.busy_since().is_none());
}

#[test]
fn gfmd_start_progress_and_end_follow_the_running_run_only() {
    let mut a = idle();
    let cs = key(&mut a, KeyCode::Char('g'));
    let [Command::StartGfmd { id, .. }] = cs[..] else {
        panic!("{cs:?}")
    };
    // another run's start says nothing; this one's names its grid
    let at = std::time::Instant::now();
    update(
        &mut a,
        Msg::GfmdStarted {
            id: id + 7,
            grid: 64,
            at,
        },
    );
    assert!(!a.ui.message.as_ref().is_some_and(|m| m.text.contains("64x64")));
    assert!(matches!(a.jobs.gfmd(), GfmdState::Running { started: None, .. }));
    update(&mut a, Msg::GfmdStarted { id, grid: 32, at });
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text.contains("32x32")));
    assert!(matches!(a.jobs.gfmd(), GfmdState::Running { started: Some(t), .. } if *t == at));
    // progress of the running run shows, and clears the start message
    let p = a.params.scene.pressure();
    reply(
        &mut a,
        Reply::GfmdProgress {
            id,
            progress: GfmdProgress::starting(p),
        },
    );
    assert!(a.ui.message.is_none() && a.gfmd_status().is_some());
    // another run's end is dropped; this one's is kept
    let view = || Ok(GfmdView::default());
    reply(
        &mut a,
        Reply::GfmdDone {
            id: id + 7,
            result: view(),
            elapsed_s: 1.0,
        },
    );
    assert!(matches!(a.jobs.gfmd(), GfmdState::Running { .. }));
    reply(
        &mut a,
        Reply::GfmdDone {
            id,
            result: view(),
            elapsed_s: 1.0,
        },
    );
    assert!(matches!(a.jobs.gfmd(), GfmdState::Done { result: Ok(_), .. }));
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text == "GFMD done"));
}

#[test]
fn written_files_keep_their_number_and_list_the_exported_scene() {
    let mut a = idle();
    let scene = a.params.scene.clone();
    let written = |charts: bool, number: u32, paths: &[&str]| Written {
        charts,
        scene: scene.clone(),
        name: "system-1".into(),
        number,
        result: Ok(paths.iter().map(|p| p.to_string()).collect()),
    };
    let (w1, w2) = (
        written(false, 3, &["x/a-3.csv", "x/a-3.toml"]),
        written(true, 3, &["x/a-3-pr.svg"]),
    );
    assert!(update(&mut a, Msg::Written(w1)).is_empty());
    assert!(a
        .ui
        .message
        .as_ref()
        .is_some_and(|m| m.text.starts_with("exported x/a-3.csv")));
    assert!(a
        .params
        .presets
        .iter()
        .any(|p| p.source == "x/a-3.toml" && p.place == "exported"));
    assert_eq!(
        a.jobs.last_export.as_ref().map(|l| (l.2, l.3)),
        Some((3, [true, false]))
    );
    update(&mut a, Msg::Written(w2));
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text.starts_with("saved")));
    assert_eq!(a.jobs.last_export.as_ref().map(|l| (l.2, l.3)), Some((3, [true, true])));
    // a failure says why and keeps what was written before
    let failed = Written {
        result: Err(oops()),
        ..written(false, 4, &[])
    };
    update(&mut a, Msg::Written(failed));
    assert!(a.ui.message.as_ref().is_some_and(|m| m.error));
    assert_eq!(a.jobs.last_export.as_ref().map(|l| l.2), Some(3));
}

#[test]
fn the_mouse_focuses_selects_and_steps_only_when_asked_for() {
    use crate::tui::model::msg::{Pointer, Target};
    let mut a = idle();
    let click = |t| Msg::Mouse(Pointer::Click(t));
    // off by default (`--mouse` turns it on)
    assert!(update(&mut a, click(Target::Chart(2))).is_empty());
    assert_eq!(a.ui.focus, 0);
    a.ui.mouse = true;
    update(&mut a, click(Target::Chart(2)));
    assert_eq!(a.ui.focus, 2);
    let t = a.knob_rows().iter().position(|p| *p == Param::Thickness).unwrap();
    update(&mut a, click(Target::Knob(t)));
    assert_eq!(a.selected_param(), Param::Thickness);
    update(&mut a, click(Target::Knob(99)));
    update(&mut a, click(Target::Elsewhere));
    assert_eq!((a.selected_param(), a.ui.focus), (Param::Thickness, 2));
    // the wheel steps the selected knob as ←→ do, and back exactly
    let p = a.knob_rows().iter().position(|p| *p == Param::Pressure).unwrap();
    update(&mut a, click(Target::Knob(p)));
    let p0 = a.params.scene.pressure();
    let cs = update(&mut a, Msg::Mouse(Pointer::WheelUp));
    assert!(a.params.scene.pressure() > p0 && names(&cs) == ["compute"]);
    update(&mut a, Msg::Mouse(Pointer::WheelDown));
    assert_eq!(a.params.scene.pressure(), p0);
    // typing or an overlay takes no mouse
    a.ui.overlay = Overlay::Help;
    update(&mut a, click(Target::Chart(1)));
    assert_eq!(a.ui.focus, 2);
}

#[test]
fn a_resize_is_kept_and_decides_whether_the_screen_is_too_small() {
    use crate::tui::base::wrap::MIN_SIZE;
    let mut a = idle();
    // unknown size (a test's state, before the first frame): keys act
    assert_eq!(a.ui.size, None);
    assert!(!a.ui.too_small());
    let (w, h) = MIN_SIZE;
    for (cols, rows, small) in [
        (w, h, false),
        (w - 1, h, true),
        (w, h - 1, true),
        (200, 60, false),
        (0, 0, true),
    ] {
        // a size that shows another chart computes it; nothing else is asked for
        let cs = update(&mut a, Msg::Resize { cols, rows });
        assert!(cs.iter().all(|c| matches!(c, Command::Compute(_))), "{cs:?}");
        assert_eq!(a.ui.size, Some((cols, rows)));
        assert_eq!(a.ui.too_small(), small, "{cols}×{rows}");
    }
}

#[test]
fn on_the_too_small_screen_only_q_and_ctrl_c_act() {
    let mut a = app();
    let _ = a.take_request();
    update(&mut a, Msg::Resize { cols: 50, rows: 15 });
    let before = format!("{:?}", a.ui);
    let p0 = a.params.scene.pressure();
    // the tour, the zoom, a knob step, typing, the help, the picker, Esc, a GFMD run, files
    for code in [
        KeyCode::Char('t'),
        KeyCode::Char('z'),
        KeyCode::Right,
        KeyCode::Down,
        KeyCode::Char('1'),
        KeyCode::Char('?'),
        KeyCode::F(1),
        KeyCode::Char('p'),
        KeyCode::Esc,
        KeyCode::Char('g'),
        KeyCode::Char('e'),
        KeyCode::Char('s'),
        KeyCode::Enter,
    ] {
        assert!(key(&mut a, code).is_empty(), "{code:?} asked for work unseen");
    }
    // nor the mouse (even where captured)
    a.ui.mouse = true;
    use crate::tui::model::msg::{Pointer, Target};
    assert!(update(&mut a, Msg::Mouse(Pointer::Click(Target::Chart(2)))).is_empty());
    assert!(update(&mut a, Msg::Mouse(Pointer::WheelUp)).is_empty());
    a.ui.mouse = false;
    assert_eq!(format!("{:?}", a.ui), before, "the screen's state is unchanged");
    assert_eq!(a.params.scene.pressure(), p0);
    assert!(!a.has_pending() && a.ui.tour.is_none() && !a.ui.zoom);
    // q quits (as the screen says), and so does Ctrl-C
    assert_eq!(names(&key(&mut a, KeyCode::Char('q'))), ["quit"]);
    let mut b = app();
    update(&mut b, Msg::Resize { cols: 30, rows: 8 });
    let ctrl_c = KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL);
    assert_eq!(names(&update(&mut b, Msg::Key(ctrl_c))), ["quit"]);
}

#[test]
fn q_quits_a_too_small_screen_while_a_value_is_typed_and_a_bigger_one_acts_again() {
    let mut a = app();
    key(&mut a, KeyCode::Char('1'));
    assert_eq!(a.ui.edit.as_deref(), Some("1"));
    // shrunk while typing: q quits (on a big screen it would cancel the field)
    update(&mut a, Msg::Resize { cols: 40, rows: 10 });
    assert_eq!(names(&key(&mut a, KeyCode::Char('q'))), ["quit"]);
    // grown again: the keys act as before
    let mut b = app();
    update(&mut b, Msg::Resize { cols: 40, rows: 10 });
    assert!(key(&mut b, KeyCode::Char('t')).is_empty());
    update(&mut b, Msg::Resize { cols: 80, rows: 24 });
    assert_eq!(names(&key(&mut b, KeyCode::Char('t'))), ["tour"]);
    assert!(key(&mut b, KeyCode::Char('z')).is_empty());
    assert!(b.ui.zoom);
}
