//! Snapshot tests of the explorer's screen (ratatui TestBackend + insta), at the minimum
//! comfortable size (80×24) and a large one (160×48), plus overlays, tiny sizes and bad data.
//! Rendering is deterministic: results are computed synchronously and timings are hidden.

mod common;

use asperity::input::preset::Preset;
use asperity_cli::tui::app::App;
use asperity_cli::tui::base::data::SweepData;
use asperity_cli::tui::charts::ChartKind;
use asperity_cli::tui::drive::{compute_now, Caches};
use asperity_cli::tui::view;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;

fn app(preset: &str) -> App {
    let mut a = App::new(preset, Preset::resolve(preset).unwrap()).unwrap();
    a.ui.show_timing = false;
    a.ui.color = false;
    a.jobs.export_dir = std::env::temp_dir();
    compute_now(&mut a, &mut Caches::default());
    a
}

fn render(app: &App, w: u16, h: u16) -> String {
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| view::draw(f, app)).unwrap();
    t.backend().to_string()
}

/// Draws without reading the buffer back (TestBackend's Display cannot show width 0).
fn draw_only(app: &App, w: u16, h: u16) {
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| view::draw(f, app)).unwrap();
}

fn key(a: &mut App, code: KeyCode) {
    asperity_cli::tui::drive::press(a, KeyEvent::new(code, KeyModifiers::NONE));
}

#[test]
fn system1_adhesionless() {
    let mut a = app("system-1");
    // select γ_s and type 0 (off)
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('0'));
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.params.scene.surface_energy_j_m2(), 0.0);
    compute_now(&mut a, &mut Caches::default());
    assert!(a.results.point().is_some_and(|p| p.is_ok()));
    assert!(a.results.sweep().is_some_and(|p| p.is_ok()));
    insta::assert_snapshot!("system1_80x24", render(&a, 80, 24));
    insta::assert_snapshot!("system1_160x48", render(&a, 160, 48));
    // the smallest size the explorer draws in full
    insta::assert_snapshot!("system1_60x20", render(&a, 60, 20));
}

#[test]
fn system1_with_adhesion() {
    // the preset's own γ_s is the default
    let a = app("system-1");
    assert_eq!(a.params.scene.surface_energy_j_m2(), 0.05);
    assert!(a.results.point().is_some_and(|p| p.is_ok()));
    insta::assert_snapshot!("system1_adhesion_80x24", render(&a, 80, 24));
    insta::assert_snapshot!("system1_adhesion_160x48", render(&a, 160, 48));
}

#[test]
fn help_custom_ratio_and_small() {
    let mut a = app("system-1");
    key(&mut a, KeyCode::Char('?'));
    let help = render(&a, 80, 24);
    insta::assert_snapshot!("help_80x24", help);
    // the help is generated from the key table; at 80×24 it scrolls to its last row
    let lines = view::help_lines();
    // every row is reachable by scrolling
    let mut seen = help.clone();
    for _ in 0..lines.len() {
        key(&mut a, KeyCode::Char('j'));
        seen.push_str(&render(&a, 80, 24));
    }
    let end = render(&a, 80, 24);
    assert!(end.contains(lines.last().unwrap().trim_end()), "{end}");
    for line in &lines {
        assert!(seen.contains(line.trim_end()), "{line}");
    }
    // at 160×48 it shows whole
    let tall = render(&a, 160, 48);
    assert!(lines.iter().all(|l| tall.contains(l.trim_end())), "{tall}");
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('m'));
    key(&mut a, KeyCode::Char('m'));
    key(&mut a, KeyCode::Char('a'));
    compute_now(&mut a, &mut Caches::default());
    insta::assert_snapshot!("custom_ratio_80x24", render(&a, 80, 24));
    key(&mut a, KeyCode::Char('p'));
    let picker = render(&a, 80, 24);
    assert!(picker.contains(" presets ") && picker.contains("system-2"), "{picker}");
    key(&mut a, KeyCode::Esc);
    let small = render(&a, 40, 10);
    assert!(small.contains("terminal too small"));
}

#[test]
fn tiny_sizes_and_bad_data_do_not_panic() {
    let mut a = app("system-1");
    for w in (0..=90).step_by(7) {
        for h in (0..=30).step_by(3) {
            draw_only(&a, w, h);
        }
    }
    // curves full of NaN/inf/zeros, a degenerate point
    a.results.set_sweep(Ok(SweepData {
        p: vec![f64::NAN, 0.0, 1e-3, 1e-2, f64::INFINITY, 1.0],
        a_r: vec![1.0, f64::NAN, 0.0, -1.0, 0.5, 0.5],
        gap_rel: vec![f64::NAN; 6],
        gap_lower: vec![f64::NAN, 0.0, 1.0, f64::INFINITY, -1.0, 2.0],
        gap_upper: vec![0.5, f64::NAN, 0.5, 1.0, f64::INFINITY, 3.0],
        gap_unloading: vec![f64::NAN, -1.0, 0.0, f64::INFINITY, 1.0, f64::NAN],
        mean_contact_stress: vec![0.0; 6],
        converged: vec![false; 6],
        a_r_unloading: vec![f64::NAN, 0.9, f64::INFINITY, -1.0, 0.7, f64::NAN],
        jump_in: Some(f64::NAN),
        pull_off: Some(0.0),
        preview: false,
        gap_note: None,
    }));
    a.results
        .set_thickness(Ok(asperity_cli::tui::base::data::ThicknessData {
            t: vec![f64::NAN, 0.0, 1e-2, 1e-1, f64::INFINITY, 1.0],
            a_r: vec![1.0, f64::NAN, 0.0, -1.0, 0.5, 0.5],
            a_r_inf: f64::NAN,
            adhesionless: Some(vec![f64::NAN; 6]),
            a_r_unloading: vec![f64::NAN, 0.9, f64::INFINITY, -1.0, 0.7],
            jump_in: vec![f64::NAN, 0.0, -1.0],
            pull_off: vec![f64::INFINITY],
        }));
    if let Some(Ok(p)) = a.results.point_mut() {
        p.pr = vec![(0.0, 0.0), (f64::NAN, 1.0), (1.0, f64::INFINITY)];
        p.wall = Some(f64::NAN);
        p.a_r = f64::NAN;
    }
    for (w, h) in [(80, 24), (61, 20), (200, 60)] {
        render(&a, w, h);
    }
    key(&mut a, KeyCode::Char('a'));
    render(&a, 80, 24);
    // every chart of the selector, with the bad data, everywhere, with all models
    key(&mut a, KeyCode::Char('M'));
    for _ in 0..ChartKind::ALL.len() {
        for _ in 0..3 {
            key(&mut a, KeyCode::Char('v'));
            key(&mut a, KeyCode::Char('f'));
        }
        for (w, h) in [(80, 24), (60, 20), (200, 60)] {
            render(&a, w, h);
        }
    }
    a.results.set_sweep(Ok(SweepData::default()));
    a.results.unshow(asperity_cli::tui::model::results::Slot::Point);
    render(&a, 80, 24);
}

/// The adhesive view with a made-up point (a tensile part down to a wall at −σ_a* = −0.3 and
/// the adhesionless comparison) until the engine reports one: checks the negative σ* range,
/// the σ* = 0 guide and the wall marker.
#[test]
fn adhesive_view_with_a_synthetic_point() {
    let mut a = app("system-1");
    if let Some(Ok(p)) = a.results.point_mut() {
        let comparison = p.pr.clone();
        p.pr = (0..=200)
            .map(|i| {
                let s = -0.3 + 2.0 * i as f64 / 200.0;
                (s, 0.04 * (-(s - 0.3) * (s - 0.3) / 0.2).exp())
            })
            .collect();
        p.wall = Some(-0.3);
        p.adhesionless = Some(comparison);
        p.extra = vec![("σ_a*".into(), "0.3000".into())];
    }
    insta::assert_snapshot!("synthetic_adhesive_80x24", render(&a, 80, 24));
    a.ui.compare = false;
    let s = render(&a, 80, 24);
    assert!(!s.contains("γ_s=0"));
}

#[test]
fn gfmd_overlay_with_a_synthetic_run() {
    use asperity_cli::tui::base::gfmd_view::GfmdView;
    use asperity_cli::tui::drive::Reply;
    use asperity_cli::tui::{base::progress, effects::engine as jobs};
    let mut a = app("system-1");
    let id = common::start_gfmd(&mut a);
    let plan = progress::plan(
        a.params.scene.pressure(),
        &jobs::gfmd_sweep_spec(a.params.scene.pressure()).pressures(),
    );
    a.on_reply(Reply::GfmdProgress {
        id,
        progress: progress::GfmdProgress {
            phase: plan[0],
            index: 0,
            phases: plan.len(),
            grid: 512,
            iteration: 250,
            residual: 3e-4,
            elapsed_s: 1.0,
            eta_s: None,
        },
    });
    insta::assert_snapshot!("gfmd_running_80x24", render(&a, 80, 24));
    a.on_reply(Reply::GfmdDone {
        id,
        result: Ok(GfmdView {
            invariants: vec![("GFMD γ̃".into(), "0.024 (full 0.024)".into())],
            ..common::synthetic_gfmd(a.params.scene.pressure())
        }),
        elapsed_s: 49.8,
    });
    let screen = render(&a, 80, 24);
    assert!(screen.contains("GFMD a_r 0.04180"), "{screen}");
    assert!(screen.contains("× GFMD"), "{screen}");
    insta::assert_snapshot!("gfmd_done_80x24", screen);
}

/// Sets the three panels and computes what they need.
fn show(a: &mut App, charts: [ChartKind; 3]) {
    a.set_charts(charts);
    a.ui.all_models = false;
    compute_now(a, &mut Caches::default());
}

fn adhesionless(preset: &str) -> App {
    let mut a = app(preset);
    a.set_typed(asperity_cli::tui::app::Param::Gamma, "0").unwrap();
    compute_now(&mut a, &mut Caches::default());
    a
}

/// The new charts of the selector, each at 80×24 and 160×48: Pr(σ*) log–log with the
/// asymptotes ([S] Fig. 3), a_r/p* with eq. (18) (Fig. 1), σ̄_c*(p*) (Fig. 5), ū(p*) (Fig. 6),
/// a_r(t·q_r) (Fig. 7) and the reference points of Table 1.
#[test]
fn new_charts() {
    let mut a = adhesionless("system-1");
    show(&mut a, [ChartKind::PrLog, ChartKind::AreaRatio, ChartKind::Stress]);
    let s = render(&a, 80, 24);
    assert!(s.contains("σ→0 asymptote") || s.contains("•"), "{s}");
    insta::assert_snapshot!("charts_prlog_ratio_stress_80x24", s);
    let s = render(&a, 160, 48);
    for needle in [
        "log–log",
        "σ→0 asymptote",
        "large-σ asymptote",
        "eq. (18)",
        "a_r/p*",
        "σ̄_c*(p*)",
        "[S] Table 1",
    ] {
        assert!(s.contains(needle), "{needle}: {s}");
    }
    insta::assert_snapshot!("charts_prlog_ratio_stress_160x48", s);

    let mut b = app("system-2");
    show(&mut b, [ChartKind::Thickness, ChartKind::Gap, ChartKind::Area]);
    assert!(b.results.thickness().is_some_and(|t| t.is_ok()));
    let s = render(&b, 160, 48);
    for needle in ["a_r(t·q_r) at p* = 0.00500", "t·q_r", "γ_s=0", "t=∞", "ū/h_rms(p*)"] {
        assert!(s.contains(needle), "{needle}: {s}");
    }
    insta::assert_snapshot!("charts_thickness_gap_area_160x48", s);
    insta::assert_snapshot!("charts_thickness_gap_area_80x24", render(&b, 80, 24));
}

/// `M`: every model on the current chart, each named in the key with its own marker.
#[test]
fn all_models_overlay() {
    let mut a = adhesionless("system-1");
    a.set_charts([ChartKind::AreaRatio, ChartKind::Pr, ChartKind::Stress]);
    key(&mut a, KeyCode::Char('M'));
    assert!(a.ui.all_models);
    compute_now(&mut a, &mut Caches::default());
    let s = render(&a, 160, 48);
    for needle in ["• model 1", "▄ model 2", "⣿ model 3", "█ model 4"] {
        assert!(s.contains(needle), "{needle}: {s}");
    }
    insta::assert_snapshot!("all_models_160x48", s);
    insta::assert_snapshot!("all_models_80x24", render(&a, 80, 24));
    // with the custom model selected, it joins as the fifth
    key(&mut a, KeyCode::Char('m'));
    key(&mut a, KeyCode::Char('m'));
    compute_now(&mut a, &mut Caches::default());
    assert!(render(&a, 160, 48).contains("▀ custom"));
}

/// `M` on an adhesive slab: model 5 joins models 1–4 with its own colour and marker.
#[test]
fn all_models_on_an_adhesive_slab() {
    let mut a = app("system-2");
    a.set_typed(asperity_cli::tui::app::Param::Thickness, "0.15").unwrap();
    assert!(a.params.scene.surface_energy_j_m2() > 0.0);
    a.set_charts([ChartKind::AreaRatio, ChartKind::Gap, ChartKind::Area]);
    key(&mut a, KeyCode::Char('M'));
    compute_now(&mut a, &mut Caches::default());
    let s = render(&a, 160, 48);
    for needle in ["• model 1", "▄ model 2", "⣿ model 3", "█ model 4", "∗ model 5"] {
        assert!(s.contains(needle), "{needle}: {s}");
    }
    insta::assert_snapshot!("all_models_adhesive_slab_160x48", s);
    insta::assert_snapshot!("all_models_adhesive_slab_80x24", render(&a, 80, 24));
}

/// The tour's step before the closing one: models 4 and 5 on a thin adhesive slab against the GFMD points the
/// library stores for it.
#[test]
fn tour_step_theory_against_brute_force() {
    use asperity_cli::tui::tour::Tour;
    let mut a = app("system-1");
    let tour = Tour::resolve("wang-muser").unwrap();
    let step = tour.steps.len() - 2;
    a.start_tour(tour, step);
    compute_now(&mut a, &mut Caches::default());
    assert_eq!(a.params.scene.model().number(), Some(5));
    let s = render(&a, 160, 48);
    for needle in [
        "Theory against brute force",
        "∗ model 5",
        "█ model 4",
        "◆ GFMD (1024^2)",
    ] {
        assert!(s.contains(needle), "{needle}: {s}");
    }
    insta::assert_snapshot!("tour_step13_160x48", s);
    insta::assert_snapshot!("tour_step13_80x24", render(&a, 80, 24));
}

/// A tour step: the preset state, its charts and the caption box.
#[test]
fn tour_step() {
    use asperity_cli::tui::tour::Tour;
    let mut a = app("system-1");
    a.start_tour(Tour::resolve("wang-muser").unwrap(), 2);
    compute_now(&mut a, &mut Caches::default());
    assert_eq!(a.ui.charts[0], ChartKind::AreaRatio);
    assert!(a.ui.all_models && a.params.scene.surface_energy_j_m2() == 0.0);
    let s = render(&a, 80, 24);
    assert!(s.contains("tour 3/14") && s.contains("How much area?"), "{s}");
    insta::assert_snapshot!("tour_step3_80x24", s);
    insta::assert_snapshot!("tour_step3_160x48", render(&a, 160, 48));
    // every size, tiny ones included, draws without a panic
    for (w, h) in [(60, 20), (61, 21), (200, 60), (80, 10), (20, 5), (1, 1)] {
        draw_only(&a, w, h);
    }
    // → moves on, ← back, a knob still turns (h), Esc leaves with the scene kept
    key(&mut a, KeyCode::Right);
    assert_eq!(a.ui.tour.as_ref().unwrap().step, 3);
    key(&mut a, KeyCode::Left);
    assert_eq!(a.ui.tour.as_ref().unwrap().step, 2);
    let p = a.params.scene.pressure();
    key(&mut a, KeyCode::Char('l'));
    assert!(a.params.scene.pressure() > p);
    key(&mut a, KeyCode::Esc);
    assert!(a.ui.tour.is_none() && !a.ui.quit);
    assert!(!render(&a, 80, 24).contains("tour 2/10"));
}

/// Chart defects that must not return: a negative gap is drawn (the ū axis does not start at 0), values of
/// an earlier scene are marked while the new one computes, long messages wrap instead of being
/// cut, and the hint bar names g and c.
#[test]
fn defects_gap_axis_stale_values_long_messages_hints() {
    let mut a = adhesionless("system-1");
    a.set_charts([ChartKind::Gap, ChartKind::Area, ChartKind::Stress]);
    if let Some(Ok(sw)) = a.results.sweep_mut() {
        for g in sw.gap_rel.iter_mut() {
            *g -= 2.0;
        }
    }
    let s = render(&a, 160, 48);
    assert!(
        s.contains("│-") || s.contains("┃-"),
        "the ū axis shows negative values: {s}"
    );
    // stale: one step of p*, nothing computed yet
    let hint = render(&a, 160, 48);
    assert!(hint.contains("g GFMD") && hint.contains("c compare"), "{hint}");
    key(&mut a, KeyCode::Right);
    assert!(a.point_is_stale() && a.gap_is_stale());
    let s = render(&a, 80, 24);
    assert!(s.contains("⋯") && s.contains("computing…"), "{s}");
    compute_now(&mut a, &mut Caches::default());
    assert!(!a.point_is_stale());
    assert!(!render(&a, 80, 24).contains("⋯"));
    // a long message wraps over up to four rows
    asperity_cli::tui::drive::press(&mut a, KeyEvent::new(KeyCode::Enter, KeyModifiers::NONE));
    for c in "x".repeat(10).chars() {
        key(&mut a, KeyCode::Char(c));
    }
    let long = format!("{} END", "word ".repeat(50));
    a.ui.edit = None;
    a.ui.message = Some(asperity_cli::tui::app::Message {
        text: long,
        error: true,
    });
    let s = render(&a, 80, 24);
    assert!(s.contains("END"), "{s}");
}

/// A hysteresis on the a_r(p*) chart — the loading curve jumping into contact, the
/// unloading curve (dashed, in the key) over the window, the jump-in and pull-off loads as
/// vertical markers named with their p*, and the branches at the current load in the panel;
/// the same in the SVG export. Synthetic sweep (the engine's is tested in the library).
#[test]
fn hysteresis_on_the_area_chart() {
    use asperity_cli::tui::base::data::BranchRow;
    let mut a = adhesionless("system-1");
    a.set_charts([ChartKind::Area, ChartKind::AreaRatio, ChartKind::Gap]);
    compute_now(&mut a, &mut Caches::default());
    let (jump, pull) = (0.03, 0.005);
    if let Some(Ok(sw)) = a.results.sweep_mut() {
        let n = sw.p.len();
        sw.a_r =
            sw.p.iter()
                .map(|&p| if p < jump { 0.8 * p } else { (0.5 + 0.3 * p).min(1.0) })
                .collect();
        common::add_hysteresis(sw, jump, pull);
        assert_eq!(sw.a_r_unloading.len(), n);
    }
    if let Some(Ok(p)) = a.results.point_mut() {
        p.branches = vec![
            BranchRow {
                name: "loading".into(),
                a_r: 0.008,
                stable: true,
                shown: true,
            },
            BranchRow {
                name: "unstable".into(),
                a_r: 0.21,
                stable: false,
                shown: false,
            },
            BranchRow {
                name: "unloading".into(),
                a_r: 0.453,
                stable: true,
                shown: false,
            },
        ];
    }
    let m = asperity_cli::tui::charts::build(&a, ChartKind::Area);
    use asperity_cli::tui::charts::Role;
    let un = m
        .series
        .iter()
        .find(|s| s.role == Role::Unloading)
        .expect("unloading curve");
    assert!(un.points.iter().filter(|q| q.1.is_finite()).count() > 5);
    assert!(m.vlines.iter().any(|v| v.role == Role::JumpIn && v.x == jump));
    assert!(m.vlines.iter().any(|v| v.role == Role::PullOff && v.x == pull));
    let s = render(&a, 160, 48);
    for needle in [
        "◦╌ unloading",
        "jump-in 0.030",
        "pull-off 0.0050",
        "loading   0.008000 ◀",
        "unstable  0.2100",
        "unloading 0.4530",
    ] {
        assert!(s.contains(needle), "{needle}: {s}");
    }
    insta::assert_snapshot!("hysteresis_160x48", s);
    insta::assert_snapshot!("hysteresis_80x24", render(&a, 80, 24));
    for (w, h) in [(60, 20), (61, 21), (20, 5), (1, 1)] {
        draw_only(&a, w, h);
    }
    // the export draws the same: the unloading curve and both markers as dashed series
    let spec = asperity_cli::chart::flatten(&asperity_cli::tui::effects::export::file_chart(&m, "test"));
    for name in ["unloading", "jump-in 0.030", "pull-off 0.0050"] {
        let s = spec
            .series
            .iter()
            .find(|s| s.name == name)
            .unwrap_or_else(|| panic!("{name}"));
        assert_eq!(s.style, asperity_cli::chart::SeriesStyle::Dashed, "{name}");
        assert!(
            s.points.iter().filter(|q| q.0.is_finite() && q.1 > 0.0).count() >= 2,
            "{name}"
        );
    }
    let dir = std::env::temp_dir().join(format!("asperity-hysteresis-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    a.jobs.export_dir = dir.clone();
    let paths = asperity_cli::tui::effects::export::export_charts(&a).unwrap();
    let svg = paths.iter().find(|p| p.ends_with("-area.svg")).expect("area svg");
    let text = std::fs::read_to_string(svg).unwrap();
    assert!(text.contains("unloading") && text.contains("jump-in") && text.contains("pull-off"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The scale view ([S-5, S-7, S-8]): Pr(σ*, q) at a middle resolution with the wall −σ_a*(q)
/// and the final Pr beside it, a_r(q) along the march; the tour's first step opens on it and
/// plays it.
#[test]
fn scale_view() {
    let mut a = app("system-1");
    show(&mut a, [ChartKind::Scales, ChartKind::ScalesArea, ChartKind::Area]);
    let n = a.scale_frame().map(|f| f.1).expect("frames");
    // two steps before q_s: with γ_s = 0.05 the wall appears only at the finest scales
    for _ in 0..2 {
        key(&mut a, KeyCode::Char('['));
    }
    assert_eq!(a.scale_frame().map(|f| f.0), Some(n - 3));
    let s = render(&a, 160, 48);
    for needle in ["Pr(σ*, q) q/q_L=", "q = q_s", "−σ_a*(q)", "a_r(q)=", "σ_a*(q)="] {
        assert!(s.contains(needle), "{needle}: {s}");
    }
    insta::assert_snapshot!("scales_160x48", s);
    insta::assert_snapshot!("scales_80x24", render(&a, 80, 24));
    // the tour's first step: the adhesionless march of model 1, played from q_L
    use asperity_cli::tui::tour::Tour;
    let mut t = app("system-1");
    t.start_tour(Tour::resolve("wang-muser").unwrap(), 1);
    compute_now(&mut t, &mut Caches::default());
    assert!(t.ui.playing && t.scale_frame().map(|f| f.0) == Some(0));
    let s = render(&t, 80, 24);
    assert!(s.contains("tour 2/14") && s.contains("1/48 ▶"), "{s}");
    insta::assert_snapshot!("tour_step2_80x24", s);
    for (w, h) in [(60, 20), (20, 5), (1, 1)] {
        draw_only(&t, w, h);
    }
}

/// A quantity that fails blanks only its own chart and says why in its title: the custom
/// model with c2 = −1 on system I has a_r and σ̄_c* at every load of the chart but no mean gap
/// (the stored elastic energy falls: not one stable branch), so the ū chart is empty with the
/// reason while the a_r and σ̄_c* charts draw; the status line names the error once.
#[test]
fn a_failed_mean_gap_blanks_only_its_own_chart() {
    use asperity_cli::tui::app::Param;
    use asperity_cli::tui::charts::{build, Role};
    let mut a = app("system-1");
    a.set_typed(Param::Model, "custom").unwrap();
    a.set_typed(Param::C2, "-1").unwrap();
    a.set_charts([ChartKind::Gap, ChartKind::Area, ChartKind::Stress]);
    compute_now(&mut a, &mut Caches::default());
    assert!(
        a.results.sweep().is_some_and(|s| s.is_ok()),
        "the load sweep itself converged"
    );
    let gap = build(&a, ChartKind::Gap);
    assert!(
        gap.title.contains("· failed: the stored elastic energy falls"),
        "{}",
        gap.title
    );
    let body = gap.empty.as_deref().expect("the gap chart is empty");
    assert!(body.starts_with("no data: ") && body.contains("mean gap"), "{body}");
    for kind in [ChartKind::Area, ChartKind::AreaRatio, ChartKind::Stress] {
        let m = build(&a, kind);
        assert!(m.empty.is_none() && !m.title.contains("failed"), "{kind:?}: {m:?}");
        let theory = m
            .series
            .iter()
            .find(|s| s.role == Role::Theory)
            .expect("a theory curve");
        assert!(
            theory.points.iter().filter(|p| p.1.is_finite()).count() > 10,
            "{kind:?}"
        );
    }
    // the Pr chart of the converged point draws too
    assert!(build(&a, ChartKind::Pr).empty.is_none());
    let status = a.compute_error().expect("the status line names the error");
    assert!(status.starts_with("mean gap: "), "{status}");
    let s = render(&a, 160, 48);
    assert_eq!(s.matches("mean gap: ").count(), 1, "{s}");
    assert!(s.contains("ū/h_rms(p*) · failed"), "{s}");
}

/// The thickness chart of a scene with a hysteresis window across t·q_r (system II, model 3,
/// γ_s = 0.1256 J/m², p* = 1e-5: two stable branches near t·q_r = 0.1) draws the unloading
/// branch there and marks the window's edges; checked against the engine called directly.
#[test]
fn the_thickness_chart_marks_the_hysteresis_window() {
    use asperity::theory::engine::{evaluate, Options};
    use asperity_cli::tui::app::Param;
    use asperity_cli::tui::charts::{build, Role};
    let mut a = app("system-2");
    a.set_typed(Param::Model, "3").unwrap();
    a.set_typed(Param::Gamma, "0.1256").unwrap();
    a.set_typed(Param::Pressure, "1e-5").unwrap();
    a.set_charts([ChartKind::Thickness, ChartKind::Area, ChartKind::Gap]);
    compute_now(&mut a, &mut Caches::default());
    let td = a.results.thickness().unwrap().as_ref().unwrap().clone();
    let m = build(&a, ChartKind::Thickness);
    let un = m
        .series
        .iter()
        .find(|s| s.role == Role::Unloading && s.name == "unloading")
        .expect("the unloading branch is drawn");
    let jump = m
        .vlines
        .iter()
        .find(|v| v.role == Role::JumpIn)
        .expect("a jump-in edge");
    let pull = m
        .vlines
        .iter()
        .find(|v| v.role == Role::PullOff)
        .expect("a pull-off edge");
    eprintln!("window t·q_r {} … {}; unloading {:?}", jump.x, pull.x, un.points);
    // thinning the slab adds contact: the small contact ends on the thin side
    assert!(
        jump.x < pull.x && jump.name.starts_with("jump-in t·q_r "),
        "{jump:?} {pull:?}"
    );
    let scene = |t: f64| a.params.scene.clone().with_thickness_qr(t).unwrap();
    let engine = |t: f64| evaluate(&scene(t), &Options::default()).unwrap();
    // inside the window (the chart's thickness with an unloading point): both branches agree
    // with the engine's
    let k = td
        .a_r_unloading
        .iter()
        .position(|u| u.is_finite())
        .expect("a thickness inside");
    let (t_in, ev) = (td.t[k], engine(td.t[k]));
    assert!(jump.x < t_in && t_in < pull.x);
    let u = ev
        .unloading_a_r
        .expect("two stable branches at the engine's accuracy too");
    assert!(
        (td.a_r_unloading[k] / u - 1.0).abs() < 1e-2,
        "{} vs {u}",
        td.a_r_unloading[k]
    );
    assert!(
        (td.a_r[k] / ev.stats.a_r - 1.0).abs() < 1e-2,
        "{} vs {}",
        td.a_r[k],
        ev.stats.a_r
    );
    assert!(un.points.contains(&(t_in, td.a_r_unloading[k])));
    // outside, a decade thicker: one branch, the chart's a_r, no unloading point
    let k = td.t.iter().position(|&t| t >= 10.0 * pull.x).unwrap();
    let ev = engine(td.t[k]);
    assert_eq!(ev.unloading_a_r, None);
    assert!(td.a_r_unloading[k].is_nan());
    assert!(
        (td.a_r[k] / ev.stats.a_r - 1.0).abs() < 1e-2,
        "{} vs {}",
        td.a_r[k],
        ev.stats.a_r
    );
    // just past each edge only one stable branch is left: the large contact on the thin side,
    // the small one on the thick side
    let (thin, thick) = (engine(jump.x * 0.95), engine(pull.x * 1.05));
    assert_eq!((thin.unloading_a_r, thick.unloading_a_r), (None, None));
    assert!(
        thin.stats.a_r > 10.0 * thick.stats.a_r,
        "{} {}",
        thin.stats.a_r,
        thick.stats.a_r
    );
    let s = render(&a, 160, 48);
    for needle in ["unloading", "jump-in t·q_r", "pull-off t·q_r"] {
        assert!(s.contains(needle), "{needle}: {s}");
    }
}

#[test]
fn zoomed_chart_and_log_pr() {
    // z: the focused chart over the whole body, at the classroom sizes
    let mut a = app("system-1");
    key(&mut a, KeyCode::Char('z'));
    insta::assert_snapshot!("zoom_80x24", render(&a, 80, 24));
    insta::assert_snapshot!("zoom_200x60", render(&a, 200, 60));
    // y: the Pr chart's density on a log axis
    key(&mut a, KeyCode::Char('y'));
    let s = render(&a, 200, 60);
    assert!(s.contains("1e-"), "{s}");
    insta::assert_snapshot!("zoom_log_pr_200x60", s);
}

/// The tour's hysteresis step followed along a load path: up through the window (⇧→ twice)
/// and back down into it (h three times): the panel, the a_r chart's ● and the Pr chart's
/// title say the unloading branch.
#[test]
fn hysteresis_followed_along_the_load_path() {
    use asperity_cli::tui::tour::Tour;
    let mut a = app("system-2");
    a.start_tour(Tour::resolve("wang-muser").unwrap(), 11);
    compute_now(&mut a, &mut Caches::default());
    for code in [
        KeyCode::Char('L'),
        KeyCode::Char('L'),
        KeyCode::Char('h'),
        KeyCode::Char('h'),
        KeyCode::Char('h'),
    ] {
        key(&mut a, code);
        compute_now(&mut a, &mut Caches::default());
    }
    let s = render(&a, 200, 60);
    assert!(
        s.contains("unloading (jumped in)") && s.contains("loading branch"),
        "{s}"
    );
    insta::assert_snapshot!("hysteresis_followed_200x60", s);
    insta::assert_snapshot!("hysteresis_followed_80x24", render(&a, 80, 24));
}

/// The gap's bracket: shaded with columns of points on screen, one filled band in the files
/// (not a column of markers per load).
#[test]
fn the_gap_bracket_is_a_filled_band_in_the_files() {
    use asperity_cli::chart::SeriesStyle;
    use asperity_cli::tui::charts::{self, Role};
    let a = app("system-1");
    let m = charts::build(&a, ChartKind::Gap);
    let band = m
        .series
        .iter()
        .find(|s| s.role == Role::Band)
        .expect("a bracket with adhesion");
    assert_eq!(band.style, SeriesStyle::Points);
    let spec = asperity_cli::chart::flatten(&asperity_cli::tui::effects::export::file_chart(&m, "test"));
    let file = spec.series.iter().find(|s| s.name == band.name).unwrap();
    assert_eq!(file.style, SeriesStyle::Band);
    // its outline: every column's lower end left to right, then its upper end back
    let columns: Vec<f64> = band.points.iter().map(|p| p.0).fold(Vec::new(), |mut v, x| {
        if v.last() != Some(&x) {
            v.push(x);
        }
        v
    });
    assert_eq!(file.points.len(), 2 * columns.len(), "{:?}", file.points);
    let n = columns.len();
    for (k, &x) in columns.iter().enumerate() {
        let col: Vec<f64> = band.points.iter().filter(|p| p.0 == x).map(|p| p.1).collect();
        let lo = col.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = col.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert_eq!(file.points[k], (x, lo));
        assert_eq!(file.points[2 * n - 1 - k], (x, hi));
    }
    // the SVG draws it as one polygon, not a marker per point
    let svg = std::env::temp_dir().join(format!("asperity-band-{}.svg", std::process::id()));
    asperity_cli::chart::write_svg(&asperity_cli::tui::effects::export::file_chart(&m, "test"), &svg).unwrap();
    let text = std::fs::read_to_string(&svg).unwrap();
    let _ = std::fs::remove_file(&svg);
    assert!(
        text.matches("<circle").count() < band.points.len() / 4,
        "markers for the band"
    );
    assert!(text.contains("<polygon"), "no filled band");
}

#[test]
fn the_too_small_screen_is_drawn_exactly_where_the_update_ignores_keys() {
    use asperity_cli::tui::model::ui::too_small;
    let a = app("system-1");
    let (w, h) = view::MIN_SIZE;
    for (cols, rows) in [(w, h), (w - 1, h), (w, h - 1), (w + 20, h + 4), (50, 15), (40, 4)] {
        let s = render(&a, cols, rows);
        assert_eq!(
            s.contains("terminal too small"),
            too_small(cols, rows),
            "{cols}×{rows}\n{s}"
        );
    }
    // where it has room, the screen says that other keys do nothing
    let s = render(&a, 50, 15);
    assert!(s.contains("q quits") && s.contains(view::TOO_SMALL_OTHER_KEYS), "{s}");
    // where not, it still says how to quit
    let s = render(&a, 30, 3);
    assert!(s.contains("q quits") && !s.contains("other keys"), "{s}");
}

/// The `s` export hands the file renderer the chart the view drew: the same value (its title
/// followed by the scene), each series in the file in the view's colour, style and marker, the
/// text chart of that value names every series, and every tick label on screen is a round
/// value written by the one number formatter.
#[test]
fn the_export_is_the_chart_the_view_drew() {
    use asperity_cli::chart::{flatten, render_text, Chart, SeriesStyle};
    use asperity_cli::numfmt;
    use asperity_cli::tui::charts::{self, plot, Role};
    use asperity_cli::tui::effects::export::file_chart;
    let mut a = app("system-1");
    let mut checked = 0;
    for all_models in [false, true] {
        a.ui.all_models = all_models;
        compute_now(&mut a, &mut Caches::default());
        for k in ChartKind::ALL {
            let m = charts::build(&a, k);
            if m.empty.is_some() {
                continue;
            }
            checked += 1;
            let file = file_chart(&m, "system-1, model 3");
            assert_eq!(file.title, format!("{} — system-1, model 3", m.title), "{k:?}");
            assert_eq!(
                Chart {
                    title: m.title.clone(),
                    ..file.clone()
                },
                m,
                "{k:?}"
            );
            // the file's series: the markers it draws, then the view's series in order
            let flat = flatten(&file);
            let markers = flat.series.len() - m.series.len();
            for (i, s) in m.series.iter().enumerate() {
                let (f, look) = (&flat.series[markers + i], m.series_look(i));
                assert!(f.name.ends_with(&s.name), "{k:?}: {} / {}", f.name, s.name);
                assert_eq!(f.colour, look.ink.rgb(), "{k:?}: {}", s.name);
                if s.role == Role::Band {
                    assert_eq!(f.style, SeriesStyle::Band, "{k:?}: {}", s.name);
                } else {
                    assert_eq!(f.style, s.style, "{k:?}: {}", s.name);
                }
                if s.style == SeriesStyle::Points {
                    assert_eq!(f.shape, look.shape, "{k:?}: {}", s.name);
                }
            }
            let text = render_text(&file, 400, 60);
            for f in flat.series.iter().filter(|f| !f.name.is_empty()) {
                assert!(
                    text.contains(&format!("{} ({})", f.name, f.style.name())),
                    "{k:?}: {}\n{text}",
                    f.name
                );
            }
            for three in [false, true] {
                let (_, xl) = plot::ticks(m.xb, m.xs, three);
                let (_, yl) = plot::ticks(m.yb, m.ys, three);
                for l in xl.iter().chain(&yl) {
                    let v: f64 = l.parse().unwrap_or_else(|_| panic!("{k:?}: {l}"));
                    assert_eq!(numfmt::tick(v), *l, "{k:?}");
                }
            }
        }
    }
    assert!(checked >= 12, "{checked}");
}
