//! Unit tests of the keys added for the classroom: `z`, Esc, `c` and `y`, the commands each
//! key asks for, typed values out of range, pins of an unchanged scene; only the charts a
//! terminal shows (`f`, `z`, a resize) are computed.

use crate::tui::base::kinds::ChartKind;
use crate::tui::model::app::*;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

fn app() -> App {
    let p = asperity::input::preset::Preset::resolve("system-1").unwrap();
    let mut a = App::new("system-1", p).unwrap();
    a.jobs.export_dir = std::env::temp_dir();
    a
}

fn key(a: &mut App, code: KeyCode) -> Vec<Command> {
    crate::tui::drive::press(a, KeyEvent::new(code, KeyModifiers::NONE))
}

fn typed(a: &mut App, s: &str) {
    for c in s.chars() {
        key(a, KeyCode::Char(c));
    }
    key(a, KeyCode::Enter);
}

#[test]
fn z_zooms_the_focused_chart_and_esc_cancels_without_quitting() {
    let mut a = app();
    key(&mut a, KeyCode::Char('f'));
    key(&mut a, KeyCode::Char('z'));
    assert!(a.ui.zoom && a.ui.focus == 1);
    // Esc leaves the zoom, then has nothing to cancel and says q quits
    key(&mut a, KeyCode::Esc);
    assert!(!a.ui.zoom && !a.ui.quit);
    key(&mut a, KeyCode::Esc);
    assert!(!a.ui.quit);
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text.contains("q quits")));
    // F1 is ? (the help)
    key(&mut a, KeyCode::F(1));
    assert_eq!(a.ui.overlay, Overlay::Help);
}

#[test]
fn c_explains_itself_without_adhesion_and_y_turns_the_pr_axis() {
    let mut a = app();
    assert!(a.params.scene.is_adhesive() && a.ui.compare);
    key(&mut a, KeyCode::Char('c'));
    assert!(!a.ui.compare);
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text.contains("hidden")));
    typed_gamma_off(&mut a);
    key(&mut a, KeyCode::Char('c'));
    assert!(!a.ui.compare, "nothing to compare: c changes nothing");
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text.contains("has none")));
    assert!(!a.ui.log_pr);
    key(&mut a, KeyCode::Char('y'));
    assert!(a.ui.log_pr);
}

fn typed_gamma_off(a: &mut App) {
    a.set_typed(Param::Gamma, "0").unwrap();
    assert!(!a.params.scene.is_adhesive());
}

#[test]
fn work_leaves_the_update_as_commands() {
    let kinds = super::msg_tests::names;
    let mut a = app();
    // the first frame computes
    assert!(a.take_request().is_some());
    assert!(a.take_request().is_none());
    // a knob: each step asks for the computation of its scene (the loop submits the last)
    assert_eq!(kinds(&key(&mut a, KeyCode::Right)), ["compute"]);
    let cs = key(&mut a, KeyCode::Right);
    let [Command::Compute(r)] = &cs[..] else {
        panic!("{cs:?}")
    };
    assert_eq!(r.scene, a.params.scene);
    // e, s, g: each returns its command, carrying its data; nothing is kept in the state
    let cs = key(&mut a, KeyCode::Char('e'));
    let [Command::Export(job)] = &cs[..] else {
        panic!("{cs:?}")
    };
    assert!(!job.charts && job.scene == a.params.scene, "{job:?}");
    assert_eq!(job.name, "system-1");
    assert_eq!(job.dir, a.jobs.export_dir);
    assert_eq!(kinds(&key(&mut a, KeyCode::Char('s'))), ["save"]);
    assert_eq!(kinds(&key(&mut a, KeyCode::Char('g'))), ["gfmd"]);
    // g cancels the running one; g g starts one and stops it again
    assert_eq!(kinds(&key(&mut a, KeyCode::Char('g'))), ["cancel"]);
    assert_eq!(kinds(&key(&mut a, KeyCode::Char('g'))), ["gfmd"]);
    assert_eq!(kinds(&key(&mut a, KeyCode::Char('g'))), ["cancel"]);
    // q: quit
    assert_eq!(kinds(&key(&mut a, KeyCode::Char('q'))), ["quit"]);
}

#[test]
fn a_typed_value_out_of_range_is_named_by_its_knob() {
    let mut a = app();
    // select t·q_r and type a negative thickness
    let i = a.knob_rows().iter().position(|p| *p == Param::Thickness).unwrap();
    a.ui.selected = i;
    typed(&mut a, "-1");
    let m = a.ui.message.as_ref().expect("an error").text.clone();
    assert!(m.contains("t·q_r") && !m.contains("load.thickness_qr"), "{m}");
    let i = a.knob_rows().iter().position(|p| *p == Param::Pressure).unwrap();
    a.ui.selected = i;
    typed(&mut a, "1e9");
    let m = a.ui.message.as_ref().expect("an error").text.clone();
    assert!(m.contains("p*") && !m.contains("load.pressure"), "{m}");
}

#[test]
fn a_pin_of_the_unchanged_scene_neither_repeats_nor_renames_the_curve() {
    let mut a = app();
    crate::tui::drive::compute_now(&mut a, &mut Default::default());
    key(&mut a, KeyCode::Char('P'));
    assert_eq!(a.results.pins.len(), 1);
    // the current curve keeps its name while the scene is the pinned one
    let m = crate::tui::charts::build(&a, ChartKind::Pr);
    assert!(
        m.series.iter().any(|s| s.name == "theory"),
        "{:?}",
        m.series.iter().map(|s| &s.name).collect::<Vec<_>>()
    );
    key(&mut a, KeyCode::Char('P'));
    assert_eq!(a.results.pins.len(), 1);
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text.contains("pinned already")));
}

/// Compute what is shown: at 80×24 one chart shows (the focused one) and the request asks only
/// for what that chart needs; `f` bringing another chart on screen, and a resize to 160×48
/// that shows all three, ask for the rest; going back to 80×24 asks for nothing.
#[test]
fn only_the_charts_shown_are_asked_for() {
    use crate::tui::model::msg::Msg;
    let mut a = app();
    a.set_charts([ChartKind::Pr, ChartKind::Area, ChartKind::Thickness]);
    crate::tui::drive::send(&mut a, Msg::Resize { cols: 80, rows: 24 });
    assert_eq!(a.shown_charts(), vec![0]);
    let req = crate::tui::drive::take_compute(&mut a).expect("a request");
    assert!(
        req.needs.point && !req.needs.loads && !req.needs.thickness,
        "{:?}",
        req.needs
    );
    // a message that shows nothing new asks for nothing
    crate::tui::drive::send(&mut a, Msg::Clock(std::time::Instant::now()));
    assert!(crate::tui::drive::take_compute(&mut a).is_none());
    // f: the area chart comes on screen, and with it the load sweep
    key(&mut a, KeyCode::Char('f'));
    assert_eq!(a.shown_charts(), vec![1]);
    let req = crate::tui::drive::take_compute(&mut a).expect("the chart now shown is asked for");
    assert!(req.needs.loads && !req.needs.thickness, "{:?}", req.needs);
    // 160×48 shows all three: the thickness sweep too
    crate::tui::drive::send(&mut a, Msg::Resize { cols: 160, rows: 48 });
    assert_eq!(a.shown_charts(), vec![0, 1, 2]);
    let req = crate::tui::drive::take_compute(&mut a).expect("the charts now shown are asked for");
    assert!(req.needs.loads && req.needs.thickness, "{:?}", req.needs);
    // back to one chart: nothing more to compute
    crate::tui::drive::send(&mut a, Msg::Resize { cols: 80, rows: 24 });
    assert!(crate::tui::drive::take_compute(&mut a).is_none());
    // z at 160×48: the focused chart alone
    crate::tui::drive::send(&mut a, Msg::Resize { cols: 160, rows: 48 });
    key(&mut a, KeyCode::Char('z'));
    assert_eq!(a.shown_charts(), vec![1]);
}

#[test]
fn a_gamma_below_the_resolvable_floor_is_refused_with_one_line() {
    let mut a = app();
    let before = a.params.scene.surface_energy_j_m2();
    let e = a.set_typed(Param::Gamma, "1e-300").unwrap_err().to_string();
    assert!(e.contains("gamma") && e.contains("1e-300") && e.contains("J/m²"), "{e}");
    assert!(!e.contains('\n'), "{e}");
    assert_eq!(a.params.scene.surface_energy_j_m2(), before);
    // just above the floor adhesion registers; 0 and off stay allowed
    let floor = asperity::input::scene::WEAK_ADHESION_GLO * a.params.scene.full_contact_energy();
    a.set_typed(Param::Gamma, &format!("{:e}", floor * 4.0)).unwrap();
    assert!(a.params.scene.is_adhesive());
    a.set_typed(Param::Gamma, "0").unwrap();
    a.set_typed(Param::Gamma, "off").unwrap();
    assert_eq!(a.params.scene.surface_energy_j_m2(), 0.0);
}

#[test]
fn the_keys_are_computed_once_per_scene_change_and_the_view_hashes_nothing() {
    use crate::tui::base::protocol::{point_key, sweep_key, SceneKeys};
    let mut a = app();
    key(&mut a, KeyCode::Char('y'));
    let before = a.results.keys().clone();
    // a key that changes neither the scene nor the load range keeps them
    key(&mut a, KeyCode::Char('y'));
    assert_eq!(*a.results.keys(), before);
    // a knob step: the new scene's keys, as computed from scratch
    key(&mut a, KeyCode::Right);
    let k = a.results.keys();
    assert_ne!(k.point, before.point);
    assert_eq!(k, &SceneKeys::of(&a.params.source, &a.params.scene, a.range()));
    assert_eq!(k.point, point_key(&a.params.source, &a.params.scene));
    assert_eq!(k.sweep, sweep_key(&a.params.source, &a.params.scene, a.range()));
    // the view and the chart builders compare these keys; they compute none
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/tui");
    let mut read = 0;
    for dir in ["view", "charts"] {
        for e in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = e.unwrap().path();
            let text = std::fs::read_to_string(&path).unwrap();
            read += 1;
            for bad in [
                "point_key(",
                "sweep_key(",
                "thickness_key(",
                "scales_key(",
                "SceneKeys::of",
                ".hash(",
            ] {
                assert!(!text.contains(bad), "{} computes a key: {bad}", path.display());
            }
        }
    }
    assert!(read > 10, "{read} files read");
}
