//! Unit tests of the state and its updates (every key without a terminal).
#![allow(unused_imports)]

use crate::tui::base::data::*;
use crate::tui::base::keys::Action;
use crate::tui::base::kinds::ChartKind;
use crate::tui::base::protocol::{point_key, Reply};
use crate::tui::base::tour::Tour;
use crate::tui::effects::engine;
use crate::tui::model::app::*;
use asperity::error::{Error, Result};
use asperity::input::model::{Model, ModelKind};
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::sync::atomic::Ordering;

use ratatui::crossterm::event::KeyModifiers as M;

fn app() -> App {
    let p = Preset::resolve("system-1").unwrap();
    let mut a = App::new("system-1", p).unwrap();
    a.jobs.export_dir = std::env::temp_dir();
    a
}

use crate::tui::drive::take_compute;

fn key(a: &mut App, code: KeyCode) {
    crate::tui::drive::press(a, KeyEvent::new(code, M::NONE));
}

fn typed(a: &mut App, s: &str) {
    for c in s.chars() {
        key(a, KeyCode::Char(c));
    }
    key(a, KeyCode::Enter);
}

#[test]
fn log_and_linear_steps_are_on_a_grid() {
    assert!((log_step(0.01, 20.0, 1) - 10f64.powf(-1.95)).abs() < 1e-15);
    assert_eq!(log_step(log_step(0.01, 20.0, 1), 20.0, -1), 10f64.powf(-2.0));
    // off-grid goes to the neighbours
    let x = 0.0123;
    assert!(log_step(x, 20.0, 1) > x && log_step(x, 20.0, 1) < 0.0142);
    assert!(log_step(x, 20.0, -1) < x && log_step(x, 20.0, -1) > 0.0112);
    // coarse grid is a subset of the fine grid
    assert_eq!(log_step(1.0, 4.0, -1), log_step(1.0, 20.0, -5));
    assert!((lin_step(0.5, 0.1, 1) - 0.6).abs() < 1e-12);
    assert_eq!(lin_step(0.05, 0.1, -1), 0.0);
    assert!((lin_step(lin_step(0.3, 0.01, 1), 0.01, -1) - 0.3).abs() < 1e-12);
}

#[test]
fn pressure_steps_round_trip_exactly() {
    let mut a = app();
    assert_eq!(a.selected_param(), Param::Pressure);
    let p0 = a.params.scene.pressure();
    key(&mut a, KeyCode::Right);
    let p1 = a.params.scene.pressure();
    assert!(p1 > p0 && p1 < p0 * 1.2);
    key(&mut a, KeyCode::Left);
    assert_eq!(a.params.scene.pressure(), p0);
    crate::tui::drive::press(&mut a, KeyEvent::new(KeyCode::Right, M::SHIFT));
    assert!((a.params.scene.pressure() / p0 - 10f64.powf(0.25)).abs() < 1e-12);
    key(&mut a, KeyCode::PageDown);
    assert_eq!(a.params.scene.pressure(), p0);
}

#[test]
fn pressure_steps_return_to_the_presets_value() {
    // system-2's p* = 0.005 is not on the 10^(k/20) grid: → → ← gave 0.004467
    let p = Preset::resolve("system-2").unwrap();
    let mut a = App::new("system-2", p).unwrap();
    assert_eq!(a.params.scene.pressure(), 0.005);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Left);
    key(&mut a, KeyCode::Left);
    assert_eq!(a.params.scene.pressure(), 0.005);
    key(&mut a, KeyCode::Right);
    assert!((a.params.scene.pressure() / 0.005 - 10f64.powf(0.05)).abs() < 1e-12);
    // the coarse grid contains the preset's value too
    crate::tui::drive::press(&mut a, KeyEvent::new(KeyCode::Left, M::SHIFT));
    assert_eq!(a.params.scene.pressure(), 0.005);
    crate::tui::drive::press(&mut a, KeyEvent::new(KeyCode::Right, M::SHIFT));
    crate::tui::drive::press(&mut a, KeyEvent::new(KeyCode::Left, M::SHIFT));
    assert_eq!(a.params.scene.pressure(), 0.005);
}

#[test]
fn a_failed_point_keeps_the_load_charts_and_the_panel_agrees() {
    let mut a = app();
    crate::tui::drive::compute_now(&mut a, &mut Default::default());
    assert!(a.results.sweep().is_some_and(|s| s.is_ok()));
    let key_now = point_key(&a.params.source, &a.params.scene);
    a.on_reply(Reply::Point {
        gen: a.jobs.gen(),
        key: key_now,
        result: Err(Error::NotConverged {
            solver: asperity::error::Solver::AdhesiveSelfConsistency,
            reason: "test".into(),
        }),
    });
    assert!(a.results.sweep().is_some_and(|s| s.is_ok()), "the load charts stay");
    assert!(a.results.gap().is_some());
    assert!(a.compute_error().unwrap().contains("did not converge"));
}

#[test]
fn chart_selector_focus_and_models_ask_for_data() {
    let mut a = app();
    let _ = take_compute(&mut a);
    key(&mut a, KeyCode::Char('v'));
    assert_eq!(a.ui.charts[0], ChartKind::PrLog);
    key(&mut a, KeyCode::Char('f'));
    key(&mut a, KeyCode::Char('v'));
    assert_eq!(a.ui.charts[1], ChartKind::AreaRatio);
    for _ in 0..2 {
        key(&mut a, KeyCode::Char('v'));
    }
    assert_eq!(a.ui.charts[1], ChartKind::Scales);
    for _ in 0..2 {
        key(&mut a, KeyCode::Char('v'));
    }
    assert_eq!(a.ui.charts[1], ChartKind::Stress);
    key(&mut a, KeyCode::Char('f'));
    for _ in 0..6 {
        key(&mut a, KeyCode::Char('v'));
    }
    assert_eq!(a.ui.charts[2], ChartKind::Thickness);
    let r = take_compute(&mut a).expect("a new chart asks for its data");
    assert!(r.needs.thickness && r.needs.loads && r.needs.point);
    assert!(r.models.is_empty());
    key(&mut a, KeyCode::Char('M'));
    let r = take_compute(&mut a).unwrap();
    // models 1, 2, 4 and, on this adhesive scene, model 5 besides the current model 3
    let n: Vec<u8> = r.models.iter().filter_map(|m| m.number()).collect();
    assert_eq!(n, [1, 2, 4, 5]);
    // only what is visible is asked for
    a.set_charts([ChartKind::Pr, ChartKind::PrLog, ChartKind::Pr]);
    let r = take_compute(&mut a).unwrap();
    assert!(r.needs.point && !r.needs.loads && !r.needs.thickness);
}

#[test]
fn requests_carry_increasing_generations_and_only_on_change() {
    let mut a = app();
    let r1 = take_compute(&mut a).unwrap();
    assert!(take_compute(&mut a).is_none());
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Right);
    let r2 = take_compute(&mut a).unwrap();
    assert!(r2.gen > r1.gen);
    assert!(a.jobs.busy());
    // a stale point (from r1's scene) is dropped, the current one kept
    a.on_reply(Reply::Point {
        gen: r1.gen,
        key: point_key(&r1.source, &r1.scene),
        result: Err(Error::Cancelled),
    });
    assert!(a.results.point().is_none());
    a.on_reply(Reply::Done { gen: r1.gen });
    assert!(a.jobs.busy());
    a.on_reply(Reply::Done { gen: r2.gen });
    assert!(!a.jobs.busy());
}

#[test]
fn thickness_reaches_infinity_and_back() {
    let mut a = app();
    key(&mut a, KeyCode::Down); // t·q_r
    assert_eq!(a.selected_param(), Param::Thickness);
    assert!(a.params.scene.thickness_qr().is_infinite());
    key(&mut a, KeyCode::Left);
    assert_eq!(a.params.scene.thickness_qr(), THICKNESS_KEYS.1);
    key(&mut a, KeyCode::Right);
    assert!(a.params.scene.thickness_qr().is_infinite());
    typed(&mut a, "0.5");
    assert_eq!(a.params.scene.thickness_qr(), 0.5);
    key(&mut a, KeyCode::Enter);
    typed(&mut a, "inf");
    assert!(a.params.scene.thickness_qr().is_infinite());
}

#[test]
fn gamma_zero_is_off() {
    let mut a = app();
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    assert_eq!(a.selected_param(), Param::Gamma);
    // the preset's own surface energy is the default
    assert_eq!(a.params.scene.surface_energy_j_m2(), 0.05);
    for _ in 0..40 {
        key(&mut a, KeyCode::Left);
    }
    assert_eq!(a.params.scene.surface_energy_j_m2(), 0.0);
    key(&mut a, KeyCode::Left);
    assert_eq!(a.params.scene.surface_energy_j_m2(), 0.0);
    key(&mut a, KeyCode::Right);
    assert!(a.params.scene.surface_energy_j_m2() > 0.0);
}

#[test]
fn models_cycle_and_custom_rows_appear() {
    let mut a = app();
    assert_eq!(a.params.scene.model().number(), Some(3));
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().number(), Some(4));
    assert_eq!(a.knob_rows().len(), 5);
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().kind, ModelKind::Custom);
    assert_eq!(a.params.scene.model().c1, 0.65);
    assert_eq!(a.knob_rows().len(), 10);
    // edit c1 until W < 0 is refused with a message
    a.ui.selected = a.knob_rows().iter().position(|p| *p == Param::C1).unwrap();
    for _ in 0..10 {
        crate::tui::drive::press(&mut a, KeyEvent::new(KeyCode::Right, M::SHIFT));
    }
    assert!(a.params.scene.model().c1 <= 1.0);
    assert!(a.ui.message.as_ref().is_some_and(|m| m.error), "{:?}", a.ui.message);
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().number(), Some(5));
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().number(), Some(1));
    assert!(a.ui.selected < a.knob_rows().len());
}

#[test]
fn the_variants_of_the_literature_are_in_the_cycle_where_the_scene_takes_them() {
    // system 1 opens adhesive: from custom, m skips YP08 and Xu24, says why, and goes on to
    // model 5, then back to 1
    let mut a = app();
    key(&mut a, KeyCode::Char('m'));
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().kind, ModelKind::Custom);
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().number(), Some(5));
    let m = a.ui.message.clone().expect("the skip is explained");
    assert!(!m.error && m.text.contains("YP08 and Xu24 skipped"), "{}", m.text);
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().number(), Some(1));
    // and backwards on the model knob: 1 → 5 → custom (the variants skipped)
    a.ui.selected = a.knob_rows().iter().position(|p| *p == Param::Model).unwrap();
    key(&mut a, KeyCode::Left);
    assert_eq!(a.params.scene.model().number(), Some(5));
    key(&mut a, KeyCode::Left);
    assert_eq!(a.params.scene.model().kind, ModelKind::Custom);
    // on the adhesionless half-space they take their turn, with γ_f = 0.42, and M draws them
    let mut a = app();
    a.set_typed(Param::Gamma, "0").unwrap();
    for _ in 0..2 {
        key(&mut a, KeyCode::Char('m'));
    }
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().kind, ModelKind::Yp08);
    assert!((a.params.scene.model().fudge_gamma().unwrap() - 0.42).abs() < 1e-12);
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().kind, ModelKind::Xu24);
    // with a variant current, M draws both variants beside models 1–4
    let kinds: Vec<ModelKind> = crate::tui::base::kinds::overlay_models(&a.params.scene)
        .iter()
        .filter_map(|m| a.params.scene.clone().with_model(*m).ok())
        .map(|s| s.model().kind)
        .collect();
    assert!(
        kinds.contains(&ModelKind::Yp08) && kinds.contains(&ModelKind::Xu24),
        "{kinds:?}"
    );
    assert_eq!(kinds.len(), 6);
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().number(), Some(5));
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.params.scene.model().number(), Some(1));
    assert_eq!(crate::tui::base::kinds::overlay_models(&a.params.scene).len(), 4);
    // a slab is refused while a variant is current, and the scene stays as it was
    for _ in 0..5 {
        key(&mut a, KeyCode::Char('m'));
    }
    assert_eq!(a.params.scene.model().kind, ModelKind::Yp08);
    let before = a.params.scene.clone();
    assert!(a.set_typed(Param::Thickness, "1").is_err());
    assert_eq!(a.params.scene, before);
}

#[test]
fn typing_bad_values_keeps_the_scene_and_explains() {
    let mut a = app();
    let before = a.params.scene.clone();
    typed(&mut a, "-3");
    assert_eq!(a.params.scene, before);
    assert!(a.ui.message.as_ref().unwrap().text.contains("p*"));
    key(&mut a, KeyCode::Enter);
    typed(&mut a, "abc");
    assert_eq!(a.params.scene, before);
    typed(&mut a, "1e-3");
    assert_eq!(a.params.scene.pressure(), 1e-3);
    // Esc cancels typing without quitting
    key(&mut a, KeyCode::Char('5'));
    key(&mut a, KeyCode::Esc);
    assert!(!a.ui.quit && a.ui.edit.is_none());
    assert_eq!(a.params.scene.pressure(), 1e-3);
}

#[test]
fn reset_help_picker_and_quit() {
    let mut a = app();
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Char('r'));
    assert_eq!(a.params.scene, a.params.base);
    key(&mut a, KeyCode::Char('?'));
    assert_eq!(a.ui.overlay, Overlay::Help);
    // ↓↑ scroll the help, another key closes it (and forgets the scroll)
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('j'));
    key(&mut a, KeyCode::Up);
    assert_eq!((a.ui.overlay, a.ui.help_scroll), (Overlay::Help, 1));
    key(&mut a, KeyCode::Char('x'));
    assert_eq!((a.ui.overlay, a.ui.help_scroll), (Overlay::None, 0));
    key(&mut a, KeyCode::Char('p'));
    assert!(matches!(a.ui.overlay, Overlay::Presets(0)));
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.params.preset.name, "system-2");
    assert_eq!(a.ui.overlay, Overlay::None);
    key(&mut a, KeyCode::Char('a'));
    assert_eq!(a.ui.charts[1], ChartKind::AreaRatio);
    assert!(!a.ui.quit);
    // Esc cancels, never quits; q does
    key(&mut a, KeyCode::Esc);
    assert!(!a.ui.quit);
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text.contains("q quits")));
    key(&mut a, KeyCode::Char('q'));
    assert!(a.ui.quit);
    let mut b = app();
    crate::tui::drive::press(&mut b, KeyEvent::new(KeyCode::Char('c'), M::CONTROL));
    assert!(b.ui.quit);
    // q while typing cancels the field and keeps the scene; a second q quits
    let mut c = app();
    let before = c.params.scene.clone();
    key(&mut c, KeyCode::Char('5'));
    key(&mut c, KeyCode::Char('q'));
    assert_eq!((c.ui.edit.as_deref(), c.ui.quit), (None, false));
    assert_eq!(c.params.scene, before);
    key(&mut c, KeyCode::Char('q'));
    assert!(c.ui.quit);
}

#[test]
fn a_tour_step_selects_the_knob_its_caption_names() {
    let mut a = app();
    a.start_tour(Tour::resolve("wang-muser").unwrap(), 0);
    assert_eq!(a.selected_param(), Param::Pressure);
    let steps = &a.ui.tour.as_ref().unwrap().tour.steps;
    let jump = steps.iter().position(|s| s.title == "Jump into contact").unwrap();
    a.act(Action::Up);
    a.tour_go(jump as i32);
    let step = &a.ui.tour.as_ref().unwrap().tour.steps[jump];
    assert_eq!(step.select, Some(crate::tui::base::tour::Knob::Pressure));
    assert_eq!(a.selected_param(), Param::Pressure);
    a.tour_go(-2);
    assert_eq!(a.selected_param(), Param::Thickness);
}

#[test]
fn the_load_range_stays_while_p_stays_inside_it() {
    // stepping p* up from 1e-6 keeps 1e-6..1 (the cached sweep), leaving it resets
    let r = sticky_range(None, 1e-6);
    assert_eq!(r, chart_range(1e-6));
    assert_eq!(sticky_range(Some(r), 3e-4), r);
    assert_eq!(sticky_range(Some(r), 1.0), r);
    assert_eq!(sticky_range(Some(r), 3.0), chart_range(3.0));
    assert_eq!(sticky_range(Some(r), 1e-7), chart_range(1e-7));
    assert_ne!(chart_range(3e-4), r);
}

#[test]
fn chart_range_covers_p() {
    assert_eq!(chart_range(0.01), (1e-3, 1.0));
    let (a, b) = chart_range(3e-5);
    assert!(a <= 3e-5 && b == 1.0);
    let (a, b) = chart_range(20.0);
    assert!(a == 1e-3 && b >= 20.0);
    assert_eq!(chart_range(f64::NAN), (1e-3, 1.0));
}

/// A scale view of `n` frames (synthetic: the updates do not look at the numbers).
fn frames(n: usize) -> ScalesData {
    ScalesData {
        frames: (0..n)
            .map(|i| ScaleFrame {
                q_rel: 1.0 + i as f64,
                a_r: 1.0 / (1.0 + i as f64),
                sigma_a: 0.0,
                pr: vec![(0.0, 0.0), (1.0, 1.0)],
            })
            .collect(),
        area: Vec::new(),
        wall: Vec::new(),
    }
}

#[test]
fn the_scale_view_scrubs_plays_to_the_end_and_pauses() {
    let mut a = app();
    // no scale chart shown: the keys say how to get one
    key(&mut a, KeyCode::Char(']'));
    assert!(a.ui.message.as_ref().is_some_and(|m| m.text.contains("scales")));
    a.set_charts([ChartKind::Scales, ChartKind::ScalesArea, ChartKind::Area]);
    assert!(take_compute(&mut a).is_some_and(|r| r.needs.scales && r.needs.loads && !r.needs.point));
    a.results.set_scales(Ok(frames(4)));
    // opens at q_s, the last frame
    assert_eq!(a.scale_frame().map(|f| (f.0, f.1)), Some((3, 4)));
    key(&mut a, KeyCode::Char('['));
    key(&mut a, KeyCode::Char('['));
    assert_eq!(a.scale_frame().map(|f| f.0), Some(1));
    key(&mut a, KeyCode::Char(']'));
    key(&mut a, KeyCode::Char(']'));
    key(&mut a, KeyCode::Char(']'));
    assert_eq!(a.scale_frame().map(|f| f.0), Some(3), "stops at the last frame");
    // Space at the end plays from the first frame, one frame per tick, and stops at q_s
    key(&mut a, KeyCode::Char(' '));
    assert!(a.ui.playing && a.animating());
    assert_eq!(a.scale_frame().map(|f| f.0), Some(0));
    a.tick();
    a.tick();
    assert_eq!(a.scale_frame().map(|f| f.0), Some(2));
    key(&mut a, KeyCode::Char(' '));
    assert!(!a.ui.playing, "Space pauses");
    a.tick();
    assert_eq!(a.scale_frame().map(|f| f.0), Some(2), "a paused view stays");
    key(&mut a, KeyCode::Char(' '));
    a.tick();
    a.tick();
    assert!(!a.ui.playing && a.scale_frame().map(|f| f.0) == Some(3));
    // a scrub pauses a play
    key(&mut a, KeyCode::Char(' '));
    key(&mut a, KeyCode::Char('['));
    assert!(!a.ui.playing);
    // the charts name the frame
    let m = crate::tui::charts::build(&a, ChartKind::Scales);
    assert!(m.title.contains(" 1/4 "), "{}", m.title);
    // a reply for another scene is dropped, one for this scene kept
    let mut other = a.params.scene.clone();
    other.set_pressure(other.pressure() * 2.0).unwrap();
    a.on_reply(Reply::Scales {
        gen: 1,
        key: crate::tui::base::protocol::scales_key(&a.params.source, &other),
        result: Ok(frames(2)),
    });
    assert_eq!(a.scales_data().map(|d| d.frames.len()), Some(4));
    a.on_reply(Reply::Scales {
        gen: 1,
        key: crate::tui::base::protocol::scales_key(&a.params.source, &a.params.scene),
        result: Ok(frames(2)),
    });
    assert_eq!(a.scales_data().map(|d| d.frames.len()), Some(2));
    assert!(!a.scales_is_stale());
}

#[test]
fn typed_values_stay_on_their_own_grid_until_the_next_typed_value() {
    let mut a = app();
    key(&mut a, KeyCode::Down); // t·q_r
    assert_eq!(a.selected_param(), Param::Thickness);
    typed(&mut a, "0.123");
    key(&mut a, KeyCode::Right);
    let up = a.params.scene.thickness_qr();
    assert!((up / (0.123 * 10f64.powf(0.1)) - 1.0).abs() < 1e-12, "{up}");
    key(&mut a, KeyCode::Left);
    assert_eq!(
        a.params.scene.thickness_qr(),
        0.123,
        "back to the typed value, not to the preset's grid"
    );
    key(&mut a, KeyCode::Left);
    key(&mut a, KeyCode::Right);
    assert_eq!(a.params.scene.thickness_qr(), 0.123);
    // γ_s: its own anchor, the thickness keeps its own
    key(&mut a, KeyCode::Down);
    assert_eq!(a.selected_param(), Param::Gamma);
    typed(&mut a, "0.1256");
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Left);
    assert_eq!(a.params.scene.surface_energy_j_m2(), 0.1256);
    key(&mut a, KeyCode::Up);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Left);
    assert_eq!(a.params.scene.thickness_qr(), 0.123);
    // the next typed value anchors anew
    typed(&mut a, "0.2");
    key(&mut a, KeyCode::Left);
    key(&mut a, KeyCode::Right);
    assert_eq!(a.params.scene.thickness_qr(), 0.2);
    // a reset returns to the preset's grids
    key(&mut a, KeyCode::Char('r'));
    assert_eq!(a.params.anchors, Anchors::default());
    // the custom model's coefficients step on a grid through the typed value too
    let mut c = app();
    c.set_typed(Param::Model, "custom").unwrap();
    let row = c.knob_rows().iter().position(|p| *p == Param::C1).unwrap();
    c.ui.selected = row;
    key(&mut c, KeyCode::Enter);
    typed(&mut c, "-0.123");
    key(&mut c, KeyCode::Right);
    assert!(
        (c.params.scene.model().c1 - (-0.113)).abs() < 1e-12,
        "{}",
        c.params.scene.model().c1
    );
    key(&mut c, KeyCode::Left);
    assert_eq!(c.params.scene.model().c1, -0.123);
}

#[test]
fn j_and_k_scroll_a_cut_caption_and_a_new_step_starts_at_its_top() {
    let mut a = app();
    a.start_tour(Tour::resolve("wang-muser").unwrap(), 1);
    let most = crate::tui::base::wrap::caption_rows_at_most(&a.ui.tour.as_ref().unwrap().tour.steps[1].caption);
    for _ in 0..50 {
        key(&mut a, KeyCode::Char('J'));
    }
    assert_eq!(
        a.ui.caption_scroll,
        most - 1,
        "bounded by the caption's rows at the narrowest width"
    );
    key(&mut a, KeyCode::Char('K'));
    assert_eq!(a.ui.caption_scroll, most - 2);
    key(&mut a, KeyCode::Right);
    assert_eq!(a.ui.caption_scroll, 0);
}

#[test]
fn m_overlays_model_5_where_adhesion_sets_it_apart_from_model_3() {
    let mut a = app();
    assert!(a.params.scene.surface_energy_j_m2() > 0.0);
    take_compute(&mut a);
    key(&mut a, KeyCode::Char('M'));
    let r = take_compute(&mut a).unwrap();
    let five: Vec<&Model> = r.models.iter().filter(|m| m.number() == Some(5)).collect();
    assert_eq!(five.len(), 1, "{:?}", r.models);
    // the request carries model 5 as the scene resolves it (W(0) from its own γ̃_glo), so the
    // overlay's keys find the reply
    let scene = a.params.scene.clone().with_model(*five[0]).unwrap();
    assert_eq!(scene.model().kind, ModelKind::Five);
    assert_eq!(a.results.keys().overlays.len(), 5);
    // without adhesion model 5 is model 3: it is left out, not drawn over model 3
    a.set_typed(Param::Gamma, "0").unwrap();
    let r = take_compute(&mut a).unwrap();
    let n: Vec<u8> = r.models.iter().filter_map(|m| m.number()).collect();
    assert_eq!(n, [1, 2, 4]);
    // with model 5 current, the paper's four are overlaid besides it
    a.set_typed(Param::Gamma, "0.1").unwrap();
    while a.params.scene.model().number() != Some(5) {
        key(&mut a, KeyCode::Char('m'));
    }
    let r = take_compute(&mut a).unwrap();
    let n: Vec<u8> = r.models.iter().filter_map(|m| m.number()).collect();
    assert_eq!(n, [1, 2, 3, 4]);
}
