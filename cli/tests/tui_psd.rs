//! The explorer's `psd` chart and the panel's `surface` row: on a preset's ideal spectrum the
//! drawn C(q) carries the spectrum's h_rms² = 2π∫q C dq (docs/physics.md §1) in closed form;
//! on a measured table the chart draws the table, the interpolant between its cut-offs and a
//! self-affine fit that recovers the H and q_r the table was written from; the panel names
//! the file. A scene on a measured table exports and reloads (with its table) exactly.

mod common;

use asperity::input::preset::Preset;
use asperity::surface::spectrum::Spectrum;
use asperity::surface::tabulated::{to_csv, Tabulated};
use asperity_cli::tui::app::App;
use asperity_cli::tui::charts::shared::Role;
use asperity_cli::tui::charts::{build, ChartKind};
use asperity_cli::tui::drive::{compute_now, Caches};
use asperity_cli::tui::view;
use ratatui::backend::TestBackend;
use ratatui::Terminal;

/// Relative agreement of the drawn spectrum's h_rms² with the library's: both are closed
/// forms of the same piecewise power law, so only round-off separates them.
const RMS_REL: f64 = 1e-9;
/// The fit's H against the H the table was written with (a table of the exact law: the fit's
/// only error is the golden-section search of q_r).
const HURST_ABS: f64 = 0.02;
/// The fit's q_r against the written one, relative.
const QR_REL: f64 = 0.05;

fn app(preset: &str) -> App {
    let mut a = App::new(preset, Preset::resolve(preset).unwrap()).unwrap();
    a.ui.show_timing = false;
    a.ui.color = false;
    a.jobs.export_dir = std::env::temp_dir();
    a
}

/// 2π∫q C dq over a piecewise power law through `pts` (log–log straight between points).
fn h_rms_sq(pts: &[(f64, f64)]) -> f64 {
    pts.windows(2)
        .map(|w| {
            let ((q0, c0), (q1, c1)) = (w[0], w[1]);
            let s = (c1 / c0).ln() / (q1 / q0).ln();
            // ∫ q·c0 (q/q0)^s dq from q0 to q1
            let e = s + 2.0;
            let v = if e.abs() < 1e-12 {
                c0 * q0 * q0 * (q1 / q0).ln()
            } else {
                c0 * q0 * q0 * ((q1 / q0).powf(e) - 1.0) / e
            };
            2.0 * std::f64::consts::PI * v
        })
        .sum()
}

#[test]
fn the_preset_spectrum_is_drawn_with_its_cut_offs() {
    let a = app("system-2");
    let m = build(&a, ChartKind::Psd);
    assert!(m.empty.is_none(), "{:?}", m.empty);
    let Spectrum::SelfAffine(sa) = a.params.scene.spectrum() else {
        unreachable!()
    };
    let th = m.series.iter().find(|s| s.role == Role::Theory).unwrap();
    let want = sa.moment(0);
    let got = h_rms_sq(&th.points);
    assert!((got / want - 1.0).abs() < RMS_REL, "{got} vs {want}");
    let xs: Vec<f64> = m.vlines.iter().map(|v| v.x).collect();
    for q in [sa.q_l(), sa.q_r(), sa.q_s()] {
        assert!(xs.contains(&q), "{q} not marked in {xs:?}");
    }
    assert!(m.title.contains("H=0.8"), "{}", m.title);
}

#[test]
fn a_measured_table_is_drawn_with_its_fit_and_named_in_the_panel() {
    let mut a = app("system-2");
    let Spectrum::SelfAffine(sa) = a.params.scene.spectrum().clone() else {
        unreachable!()
    };
    // the ideal law sampled at 41 log-spaced points from q_L to q_s (q_r among them)
    let (q, c) = common::ideal_table(&sa, 40);
    let path = std::env::temp_dir().join(format!("asperity-tui-psd-{}.csv", std::process::id()));
    std::fs::write(&path, to_csv(&q, &c)).unwrap();
    let t = Tabulated::load_csv(&path, None, None).unwrap();
    let _ = std::fs::remove_file(&path);
    a.params.scene.set_spectrum(Spectrum::Tabulated(t)).unwrap();
    a.params.base = a.params.scene.clone();
    let m = build(&a, ChartKind::Psd);
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    assert!(m.title.contains(&name), "{}", m.title);
    let table = m.series.iter().find(|s| s.role == Role::Reference).unwrap();
    assert_eq!(table.points.len(), q.len());
    let used = m.series.iter().find(|s| s.role == Role::Theory).unwrap();
    let want = sa.moment(0);
    assert!((h_rms_sq(&used.points) / want - 1.0).abs() < 1e-6);
    let fit = m.series.iter().find(|s| s.role == Role::Closed).unwrap();
    let h: f64 = fit.name["fit H=".len()..].split('±').next().unwrap().parse().unwrap();
    assert!((h - sa.hurst).abs() < HURST_ABS, "H {h} vs {}", sa.hurst);
    let q_r_fit = fit.points[1].0;
    assert!(
        (q_r_fit / sa.q_r() - 1.0).abs() < QR_REL,
        "q_r {q_r_fit} vs {}",
        sa.q_r()
    );
    // the panel names the file; the chart renders on a small screen
    a.ui.charts[0] = ChartKind::Psd;
    compute_now(&mut a, &mut Caches::default());
    for (w, h) in [(80, 24), (160, 48)] {
        let mut term = Terminal::new(TestBackend::new(w, h)).unwrap();
        term.draw(|f| view::draw(f, &a)).unwrap();
        let screen = term.backend().to_string();
        assert!(screen.contains("surface"), "{screen}");
        assert!(screen.contains(&name[..12]), "{screen}");
    }
}

/// The two-band map of the tests is not self-affine: no fit is drawn and the title says so,
/// while the table and the interpolant still are.
#[test]
fn a_table_that_is_not_self_affine_gets_no_fit() {
    let mut a = app("system-1");
    let q = [1e6, 2e6, 4e6, 8e6, 1.6e7, 3.2e7, 6.4e7];
    let c = [1e-40, 1e-30, 1e-40, 1e-40, 1e-31, 1e-40, 1e-40];
    let t = Tabulated::new(q.to_vec(), c.to_vec(), "bands.csv", None, None).unwrap();
    a.params.scene.set_spectrum(Spectrum::Tabulated(t)).unwrap();
    let m = build(&a, ChartKind::Psd);
    assert!(m.title.contains("not self-affine"), "{}", m.title);
    assert!(m.series.iter().all(|s| s.role != Role::Closed));
    assert!(m.series.iter().any(|s| s.role == Role::Theory));
}

/// A scene on a measured spectrum, exported with `e`: its files are named after the table,
/// its TOML says to reopen it with the table, and the TOML with the table (what
/// `asperity tui --preset X.toml --psd FILE` does) is the exported scene exactly; the preset's
/// reference values (another surface's) are not drawn over it.
#[test]
fn a_measured_scene_exports_and_reloads_exactly() {
    let mut a = app("system-2");
    let Spectrum::SelfAffine(sa) = a.params.scene.spectrum().clone() else {
        unreachable!()
    };
    let (q, c) = common::ideal_table(&sa, 40);
    let dir = std::env::temp_dir().join(format!("asperity-measured-export-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let table = dir.join("my-surface.csv");
    std::fs::write(&table, to_csv(&q, &c)).unwrap();
    let load = || Tabulated::load_csv(&table, None, None).unwrap();
    a.params.scene.set_spectrum(Spectrum::Tabulated(load())).unwrap();
    a.params.scene.set_pressure(0.003).unwrap();
    a.params.scene.set_thickness_qr(0.5).unwrap();
    a.params.base = a.params.scene.clone();
    a.jobs.export_dir = dir.clone();
    compute_now(&mut a, &mut Caches::default());
    let area = build(&a, ChartKind::Area);
    assert!(
        !area.series.iter().any(|s| s.role == Role::Reference),
        "system 2's references drawn"
    );
    let paths = asperity_cli::tui::effects::export::export(&a).unwrap();
    assert!(paths[0].ends_with("asperity-my-surface-1.toml"), "{paths:?}");
    let text = std::fs::read_to_string(&paths[0]).unwrap();
    assert!(text.contains(&format!("--surface {}", table.display())), "{text}");
    let back = Preset::load(std::path::Path::new(&paths[0])).unwrap();
    let mut scene = asperity_cli::tui::app::initial_scene(&back).unwrap();
    scene.set_spectrum(Spectrum::Tabulated(load())).unwrap();
    assert_eq!(scene, a.params.scene);
    let _ = std::fs::remove_dir_all(&dir);
}
