//! The explorer's `e` export: the loads CSV carries both branches of a hysteresis and its
//! edges, checked against the engine evaluated on its own at loads of the file; the GFMD CSV
//! carries the run, its sweep and the theory on the map.

use asperity::input::preset::Preset;
use asperity::theory::engine::{evaluate, Options};
use asperity::tolerances::CHART_ACCURACY_REL;
use asperity_cli::tui::app::{App, Param};
use asperity_cli::tui::effects::export::{export, gfmd_csv};
use asperity_cli::tui::model::data::GfmdView;
use asperity_cli::tui::model::kinds::ChartKind;

/// A CSV read back: header columns, rows of cells, `# key: value` lines.
type Csv = (Vec<String>, Vec<Vec<String>>, Vec<(String, String)>);

fn parse(csv: &str) -> Csv {
    let comments = csv
        .lines()
        .filter_map(|l| l.strip_prefix("# "))
        .filter_map(|l| l.split_once(": "))
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    let mut data = csv.lines().filter(|l| !l.starts_with('#'));
    let header = data.next().unwrap().split(',').map(String::from).collect();
    let rows = data.map(|l| l.split(',').map(String::from).collect()).collect();
    (header, rows, comments)
}

fn num(s: &str) -> Option<f64> {
    (!s.is_empty()).then(|| s.parse().unwrap())
}

#[test]
fn the_loads_csv_has_both_branches_and_the_window_edges() {
    let dir = std::env::temp_dir().join(format!("asperity-export-window-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // system II, model 3, a thin slab: a hysteresis window at small loads
    let mut app = App::new("system-2", Preset::resolve("system-2").unwrap()).unwrap();
    app.jobs.export_dir = dir.clone();
    app.set_typed(Param::Model, "3").unwrap();
    app.set_typed(Param::Thickness, "0.1").unwrap();
    app.set_typed(Param::Gamma, "0.1256").unwrap();
    app.set_typed(Param::Pressure, "1e-5").unwrap();
    app.set_charts([ChartKind::Area, ChartKind::Gap, ChartKind::Pr]);
    asperity_cli::tui::drive::compute_now(&mut app, &mut Default::default());
    let paths = export(&app).unwrap();
    let csv = std::fs::read_to_string(paths.iter().find(|p| p.ends_with("-loads.csv")).unwrap()).unwrap();
    let (header, rows, comments) = parse(&csv);
    let col = |name: &str| {
        header
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("{name}: {header:?}"))
    };
    // an edge outside the swept loads is written as such
    let edge = |k: &str| -> Option<f64> {
        let v = &comments
            .iter()
            .find(|(key, _)| key == k)
            .unwrap_or_else(|| panic!("{k}"))
            .1;
        (v != "none in the range").then(|| v.parse().unwrap_or_else(|_| panic!("{k}: {v}")))
    };
    let jump_in = edge("jump_in_pressure").expect("the contact jumps in inside the range");
    // this slab's contact holds down to zero load: the unloading branch reaches below the range
    let pull_off = edge("pull_off_pressure").unwrap_or(0.0);
    assert!(pull_off < jump_in, "pull-off {pull_off} below jump-in {jump_in}");
    let (p, a, au, gu) = (
        col("p"),
        col("a_r"),
        col("a_r_unloading"),
        col("mean_gap_unloading_rel"),
    );
    let mut inside = Vec::new();
    for r in &rows {
        let load = num(&r[p]).unwrap();
        match num(&r[au]) {
            Some(u) => {
                // the unloading branch exists only inside the window, above the loading one
                assert!(load >= pull_off * 0.97 && load <= jump_in * 1.03, "{load}: {r:?}");
                let loading = num(&r[a]).unwrap();
                assert!(u > loading, "unloading a_r {u} above loading {loading} at {load}");
                inside.push((load, loading, u));
            }
            None => assert!(
                load < pull_off * 1.03 || load > jump_in * 0.97,
                "no unloading branch at {load} inside [{pull_off}, {jump_in}]"
            ),
        }
        if let Some(g) = num(&r[gu]) {
            assert!(g >= 0.0, "a gap is never negative: {g}");
        }
    }
    assert!(inside.len() >= 3, "loads inside the window: {inside:?}");
    // both branches against the engine on its own, at a load in the middle of the window
    let (load, loading, unloading) = inside[inside.len() / 2];
    let mut s = app.params.scene.clone();
    s.set_pressure(load).unwrap();
    let ev = evaluate(&s, &Options::default()).unwrap();
    let u = ev
        .unloading_a_r
        .expect("the engine finds the unloading branch inside the window");
    assert!(
        (loading / ev.stats.a_r - 1.0).abs() < CHART_ACCURACY_REL,
        "{loading} vs {}",
        ev.stats.a_r
    );
    assert!((unloading / u - 1.0).abs() < CHART_ACCURACY_REL, "{unloading} vs {u}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_gfmd_csv_lists_the_run_its_sweep_and_the_theory_on_the_map() {
    let p = 0.01;
    let view = GfmdView {
        pressure: p,
        a_r: 0.02,
        mean_contact_stress: 0.5,
        gap_rel: 1.5,
        grid: 256,
        iterations: 400,
        theory_a_r: Some(0.021),
        sweep: vec![(p / 3.0, 0.007, 1.9), (p, 0.02, 1.5), (3.0 * p, 0.06, 1.1)],
        theory_sweep: vec![(p / 3.0, 0.0072, 1.95), (p, 0.021, 1.52), (3.0 * p, 0.061, 1.12)],
        ..GfmdView::default()
    };
    let (header, rows, _) = parse(&gfmd_csv(&view));
    assert_eq!(header, ["source", "p", "a_r", "mean_gap_rel", "mean_contact_stress"]);
    let of = |src: &str| rows.iter().filter(|r| r[0] == src).count();
    // the run's own load once per source, not twice
    assert_eq!(of("gfmd"), 3, "{rows:?}");
    assert_eq!(of("theory_on_map"), 3, "{rows:?}");
    let run = rows.iter().find(|r| r[0] == "gfmd" && num(&r[1]) == Some(p)).unwrap();
    assert_eq!(num(&run[4]), Some(0.5));
}

#[test]
fn the_thickness_csv_has_the_window_its_edges_and_the_reference() {
    use asperity::theory::engine::CHART_EDGE_REL;
    use asperity::theory::hysteresis::{knob_edges, EdgeKind};
    use asperity::theory::knob::{knob_sweep, Knob, KnobSpec};
    let dir = std::env::temp_dir().join(format!("asperity-export-thickness-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut app = App::new("system-2", Preset::resolve("system-2").unwrap()).unwrap();
    app.jobs.export_dir = dir.clone();
    app.set_typed(Param::Model, "3").unwrap();
    app.set_typed(Param::Gamma, "0.1256").unwrap();
    app.set_typed(Param::Pressure, "1e-5").unwrap();
    app.set_charts([ChartKind::Thickness, ChartKind::Pr, ChartKind::Area]);
    asperity_cli::tui::drive::compute_now(&mut app, &mut Default::default());
    let paths = export(&app).unwrap();
    let csv = std::fs::read_to_string(paths.iter().find(|p| p.ends_with("-thickness.csv")).unwrap()).unwrap();
    let (header, rows, comments) = parse(&csv);
    assert_eq!(header, ["thickness_qr", "a_r", "a_r_unloading", "a_r_adhesionless"]);
    let edge = |k: &str| -> f64 {
        let v = &comments
            .iter()
            .find(|(key, _)| key == k)
            .unwrap_or_else(|| panic!("{k}"))
            .1;
        v.split(' ')
            .next()
            .unwrap()
            .parse()
            .unwrap_or_else(|_| panic!("{k}: {v}"))
    };
    let (jump_in, pull_off) = (edge("jump_in_thickness_qr"), edge("pull_off_thickness_qr"));
    // the library's own edges, bisected to its default precision from a sweep of its own
    // (around the chart's window, fine enough to land inside it)
    let scene = app.params.scene.clone();
    let spec = KnobSpec {
        knob: Knob::Thickness,
        from: 0.9 * jump_in,
        to: 1.1 * pull_off,
        points: 24,
    };
    let pts = knob_sweep(&scene, &spec, &Options::default(), false, None).unwrap();
    let edges = knob_edges(&scene, Knob::Thickness, &pts, &Options::default().adhesion, None).unwrap();
    let want = |kind: EdgeKind| edges.iter().find(|e| e.kind == kind).unwrap().value;
    for (got, w) in [(jump_in, want(EdgeKind::JumpIn)), (pull_off, want(EdgeKind::PullOff))] {
        assert!((got / w - 1.0).abs() < 2.0 * CHART_EDGE_REL, "edge {got} vs {w}");
    }
    // the unloading branch only inside the window, above the loading one; the adhesionless
    // reference below both
    for r in &rows {
        let t = num(&r[0]).unwrap();
        if let Some(u) = num(&r[2]) {
            assert!(t > jump_in * 0.97 && t < pull_off * 1.03, "unloading at t·q_r {t}");
            assert!(u > num(&r[1]).unwrap(), "{r:?}");
        }
        if let (Some(a), Some(d)) = (num(&r[1]), num(&r[3])) {
            assert!(d <= a * (1.0 + CHART_ACCURACY_REL), "adhesion adds contact: {r:?}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
