//! Snapshot tests of the explorer's screen (ratatui TestBackend + insta), at the minimum
//! comfortable size (80×24) and a large one (160×48), plus overlays, tiny sizes and bad data.
//! Rendering is deterministic: results are computed synchronously and timings are hidden.

use asperity::input::preset::Preset;
use asperity_cli::tui::app::App;
use asperity_cli::tui::data::SweepData;
use asperity_cli::tui::view;
use asperity_cli::tui::worker::{compute_now, Caches};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;

fn app(preset: &str) -> App {
    let mut a = App::new(preset, Preset::resolve(preset).unwrap()).unwrap();
    a.show_timing = false;
    a.color = false;
    a.export_dir = std::env::temp_dir();
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
    a.on_key(KeyEvent::new(code, KeyModifiers::NONE));
}

#[test]
fn system1_adhesionless() {
    let mut a = app("system-1");
    // select γ_s and type 0 (off)
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('0'));
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.scene.gamma, 0.0);
    compute_now(&mut a, &mut Caches::default());
    assert!(a.point.as_ref().is_some_and(|p| p.is_ok()));
    assert!(a.sweep.as_ref().is_some_and(|p| p.is_ok()));
    insta::assert_snapshot!("system1_80x24", render(&a, 80, 24));
    insta::assert_snapshot!("system1_160x48", render(&a, 160, 48));
    // the smallest size the explorer draws in full
    insta::assert_snapshot!("system1_60x20", render(&a, 60, 20));
}

#[test]
fn system1_with_adhesion() {
    // the preset's own γ_s is the default
    let a = app("system-1");
    assert_eq!(a.scene.gamma, 0.05);
    assert!(a.point.as_ref().is_some_and(|p| p.is_ok()));
    insta::assert_snapshot!("system1_adhesion_80x24", render(&a, 80, 24));
    insta::assert_snapshot!("system1_adhesion_160x48", render(&a, 160, 48));
}

#[test]
fn help_custom_ratio_and_small() {
    let mut a = app("system-1");
    key(&mut a, KeyCode::Char('?'));
    let help = render(&a, 80, 24);
    // the help is generated from the key table
    for line in view::help_lines() {
        assert!(help.contains(line.trim_end()), "{line}");
    }
    insta::assert_snapshot!("help_80x24", help);
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
    a.sweep = Some(Ok(SweepData {
        p: vec![f64::NAN, 0.0, 1e-3, 1e-2, f64::INFINITY, 1.0],
        a_r: vec![1.0, f64::NAN, 0.0, -1.0, 0.5, 0.5],
        gap_rel: vec![f64::NAN; 6],
        mean_contact_stress: vec![0.0; 6],
    }));
    if let Some(Ok(p)) = a.point.as_mut() {
        p.pr = vec![(0.0, 0.0), (f64::NAN, 1.0), (1.0, f64::INFINITY)];
        p.wall = Some(f64::NAN);
        p.a_r = f64::NAN;
    }
    for (w, h) in [(80, 24), (61, 20), (200, 60)] {
        render(&a, w, h);
    }
    key(&mut a, KeyCode::Char('a'));
    render(&a, 80, 24);
    a.sweep = Some(Ok(SweepData::default()));
    a.point = None;
    render(&a, 80, 24);
}

/// The adhesive view with a made-up point (a tensile part down to a wall at −σ_a* = −0.3 and
/// the adhesionless comparison) until the engine reports one: checks the negative σ* range,
/// the σ* = 0 guide and the wall marker.
#[test]
fn adhesive_view_with_a_synthetic_point() {
    let mut a = app("system-1");
    if let Some(Ok(p)) = a.point.as_mut() {
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
    a.compare = false;
    let s = render(&a, 80, 24);
    assert!(!s.contains("γ_s=0"));
}

#[test]
fn gfmd_overlay_with_a_synthetic_run() {
    use asperity_cli::tui::data::GfmdView;
    use asperity_cli::tui::worker::Reply;
    let mut a = app("system-1");
    key(&mut a, KeyCode::Char('g'));
    let (id, _, _) = a.take_gfmd_request().expect("g starts a run");
    a.on_reply(Reply::GfmdProgress {
        id,
        iteration: 250,
        residual: 3e-4,
    });
    insta::assert_snapshot!("gfmd_running_80x24", render(&a, 80, 24));
    // a histogram shaped like the theory, a little wider
    let pr: Vec<(f64, f64)> = (0..60)
        .map(|i| {
            let s = -0.5 + 2.2 * (i as f64 + 0.5) / 60.0;
            (s, 0.04 * (-(s - 0.3) * (s - 0.3) / 0.3).exp())
        })
        .collect();
    a.on_reply(Reply::GfmdDone {
        id,
        result: Ok(GfmdView {
            pressure: a.scene.pressure,
            a_r: 0.0418,
            mean_contact_stress: 0.2434,
            gap_rel: 1.4,
            pr,
            grid: 512,
            iterations: 475,
            elapsed_s: 1.0,
            theory_a_r: Some(0.0299),
            sweep: vec![(0.0033, 0.015, 2.0), (0.03, 0.11, 0.9)],
            theory_sweep: vec![(0.0033, 0.011, 2.1), (0.01, 0.03, 1.5), (0.03, 0.09, 0.95)],
            invariants: vec![("GFMD γ̃".into(), "0.024 (full 0.024)".into())],
        }),
    });
    let screen = render(&a, 80, 24);
    assert!(screen.contains("GFMD a_r 0.04180"), "{screen}");
    assert!(screen.contains("▀ GFMD"), "{screen}");
    insta::assert_snapshot!("gfmd_done_80x24", screen);
}
