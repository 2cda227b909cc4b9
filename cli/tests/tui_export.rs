//! The explorer's `e` export: the loads CSV carries both branches of a hysteresis and its
//! edges, checked against the engine evaluated on its own at loads of the file; the GFMD CSV
//! carries the run, its sweep and the theory on the map.

use asperity::input::preset::Preset;
use asperity::theory::engine::{evaluate, Options};
use asperity::tolerances::CHART_ACCURACY_REL;
use asperity_cli::tui::app::{App, Param};
use asperity_cli::tui::base::gfmd_view::GfmdView;
use asperity_cli::tui::base::kinds::ChartKind;
use asperity_cli::tui::effects::export::{export, gfmd_csv};

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

/// The tour's jump-into-contact scene (system II, model 3, t·q_r = 0.1, γ_s = 0.1256 J/m²).
fn jump_in_scene(dir: &std::path::Path) -> App {
    let mut app = App::new("system-2", Preset::resolve("system-2").unwrap()).unwrap();
    app.jobs.export_dir = dir.to_path_buf();
    app.ui.show_timing = false;
    app.set_typed(Param::Pressure, "1e-5").unwrap();
    app.set_typed(Param::Model, "3").unwrap();
    app.set_typed(Param::Thickness, "0.1").unwrap();
    app.set_typed(Param::Gamma, "0.1256").unwrap();
    app.set_charts([ChartKind::Area, ChartKind::Pr, ChartKind::Gap]);
    // loaded from small p*, as the tour's step starts
    app.params.history.reset();
    app
}

fn go(app: &mut App, p: &str, caches: &mut asperity_cli::tui::drive::Caches) {
    app.set_typed(Param::Pressure, p).unwrap();
    asperity_cli::tui::drive::compute_now(app, caches);
}

/// The panel's rows as `(key, value)` (the first word after the key), at 160×48.
fn panel_rows(app: &App) -> Vec<(String, String)> {
    let mut t = ratatui::Terminal::new(ratatui::backend::TestBackend::new(160, 48)).unwrap();
    t.draw(|f| asperity_cli::tui::view::draw(f, app)).unwrap();
    let screen = t.backend().to_string();
    let mut rows = Vec::new();
    for line in screen.lines() {
        // the panel is the leftmost box: `"│ key      value   │ chart …`
        let Some(inner) = line.trim_start_matches('"').strip_prefix('│') else {
            continue;
        };
        let cell: String = inner.chars().take(32).collect();
        let cell = cell.split('│').next().unwrap_or("").to_string();
        let mut words = cell.split_whitespace();
        if let (Some(k), Some(v)) = (words.next(), words.next()) {
            // keys of two words ("ū load", "ū unload", "err a_r")
            let (k, v) = match (k, words.clone().next()) {
                ("ū" | "err", Some(v2)) => (format!("{k} {v}"), v2.to_string()),
                _ => (k.to_string(), v.to_string()),
            };
            rows.push((k, v));
        }
    }
    rows
}

fn row(rows: &[(String, String)], key: &str) -> String {
    rows.iter()
        .find(|(k, _)| k == key)
        .unwrap_or_else(|| panic!("no {key} row: {rows:?}"))
        .1
        .clone()
}

fn value(v: &str) -> f64 {
    v.parse().unwrap_or_else(|_| panic!("not a number: {v}"))
}

/// The unloading branch whole: at the tour's loads p* = 1e-4 and 2.24e-4, reached from below
/// (the loading branch) and from above (after the jump in at 3.16e-4), every row of the panel
/// — a_r, σ̄_c*, ū/h_rms and its bracket, the tensile area, the state — and the Pr chart are
/// the branch's the path is on, checked against the engine evaluated on that branch on its own
/// (`follow_unloading`); ū is never `–` on either.
#[test]
fn every_row_follows_the_branch_on_screen_from_below_and_from_above() {
    use asperity_cli::tui::charts::shared::{on_unloading, path_gap, path_gap_bracket, path_stress, shown_point};
    use asperity_cli::tui::model::history::Path;
    let dir = std::env::temp_dir().join(format!("asperity-export-branch-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut app = jump_in_scene(&dir);
    let mut caches = Default::default();
    let engine = |app: &App, unloading: bool| {
        let mut o = Options::default();
        o.adhesion.follow_unloading = unloading;
        evaluate(&app.params.scene, &o).unwrap()
    };
    let check = |app: &App, unloading: bool| {
        let p = app.params.scene.pressure();
        let ev = engine(app, unloading);
        let rows = panel_rows(app);
        let a_r = value(&row(&rows, "a_r"));
        assert!(
            (a_r / ev.stats.a_r - 1.0).abs() < 1e-3,
            "p* {p}, unloading {unloading}: a_r {a_r} vs the engine's {}",
            ev.stats.a_r
        );
        let stress = path_stress(app).unwrap();
        assert!(
            (stress / ev.stats.mean_contact_stress - 1.0).abs() < 1e-3,
            "p* {p}, unloading {unloading}: σ̄_c* {stress} vs {}",
            ev.stats.mean_contact_stress
        );
        // the share of the contact under tension, as the captions say it
        let tensile = value(row(&rows, "tensile").trim_end_matches('%'));
        let want = 100.0 * ev.tensile_area / ev.stats.a_r;
        assert!(
            (tensile / want - 1.0).abs() < 1e-2,
            "p* {p}, unloading {unloading}: tensile {tensile}% vs {want}%"
        );
        assert!(row(&rows, "state").starts_with(if unloading { "unloading" } else { "loading" }));
        let gap = row(&rows, "ū/h_rms");
        assert_ne!(gap, "–", "p* {p}, unloading {unloading}: {rows:?}");
        let g = path_gap(app).unwrap();
        if unloading {
            // the unloading branch's own bracket, on its own row
            let (lo, hi) = path_gap_bracket(app).unwrap();
            assert!(lo <= g * 1.001 && g <= hi * 1.001, "ū {g} in [{lo}, {hi}]");
            assert!(rows.iter().any(|(k, _)| k == "ū unload"), "{rows:?}");
        }
        assert_eq!(on_unloading(app), unloading);
        let pr = shown_point(app).unwrap();
        assert!((pr.a_r / ev.stats.a_r - 1.0).abs() < 1e-3);
        let title = asperity_cli::tui::charts::build(app, ChartKind::Pr).title;
        assert_eq!(title.contains("unloading branch"), unloading, "{title}");
        (a_r, g)
    };
    // from below: the loading branch
    let mut below = Vec::new();
    for p in ["1e-4", "2.24e-4"] {
        go(&mut app, p, &mut caches);
        assert_eq!(app.params.history.on, Path::Loading);
        below.push(check(&app, false));
    }
    // up past the jump-in load, then back down into the window
    go(&mut app, "3.16e-4", &mut caches);
    assert_eq!(app.params.history.on, Path::Unloading);
    for (k, p) in ["2.24e-4", "1e-4"].into_iter().enumerate() {
        go(&mut app, p, &mut caches);
        assert_eq!(app.params.history.on, Path::Unloading, "{p}");
        let (a, g) = check(&app, true);
        let (a0, g0) = below[1 - k];
        // the unloading branch holds more contact and a smaller gap than the loading one
        assert!(
            a > 3.0 * a0 && g < g0,
            "p* {p}: unloading ({a}, {g}) vs loading ({a0}, {g0})"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The `asperity` binary's `run --preset PATH --format json`.
fn run_json(preset: &str) -> serde_json::Value {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", "--preset", preset, "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Exports that reopen as they were, per branch: made at p* = 1e-4 on the loading branch
/// (reached from below) and on the unloading branch (reached from above), the scene TOML
/// records the branch (`[load] branch = "unloading"`, no key on the loading branch), and
/// `run --preset` of it and the explorer opened on it give the a_r the panel showed.
#[test]
fn an_export_reopens_on_its_branch() {
    use asperity_cli::tui::charts::shared::path_a_r;
    let dir = std::env::temp_dir().join(format!("asperity-export-reopen-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut app = jump_in_scene(&dir);
    let mut caches = Default::default();
    let mut made = Vec::new();
    for path in [&["1e-4"][..], &["3.16e-4", "2.24e-4", "1e-4"][..]] {
        for p in path {
            go(&mut app, p, &mut caches);
        }
        let shown = path_a_r(&app).unwrap();
        let paths = export(&app).unwrap();
        let toml = paths.iter().find(|p| p.ends_with(".toml")).unwrap().clone();
        let text = std::fs::read_to_string(&toml).unwrap();
        let unloading = path.len() > 1;
        assert_eq!(text.contains("branch = \"unloading\""), unloading, "{text}");
        let pr = std::fs::read_to_string(paths.iter().find(|p| p.ends_with("-pr.csv")).unwrap()).unwrap();
        let (_, _, comments) = parse(&pr);
        let branch = &comments.iter().find(|(k, _)| k == "branch").unwrap().1;
        assert_eq!(branch.starts_with("unloading"), unloading, "{branch}");
        made.push((toml, shown, unloading));
        app.set_typed(Param::Pressure, "1e-5").unwrap();
    }
    let (a_load, a_unload) = (made[0].1, made[1].1);
    assert!(a_unload > 5.0 * a_load, "{a_load} {a_unload}");
    for (toml, shown, unloading) in made {
        let run = run_json(&toml);
        let a = run["a_r"].as_f64().unwrap();
        assert!(
            (a / shown - 1.0).abs() < 1e-3,
            "run --preset {toml}: {a} vs the panel's {shown}"
        );
        assert_eq!(run["branch"], if unloading { "unloading" } else { "loading" });
        let mut back = App::new(&toml, Preset::resolve(&toml).unwrap()).unwrap();
        asperity_cli::tui::drive::compute_now(&mut back, &mut Default::default());
        let a = path_a_r(&back).unwrap();
        assert!((a / shown - 1.0).abs() < 1e-3, "tui --preset {toml}: {a} vs {shown}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// An export of a measured map reopens on it: made as `tui --surface MAP --size 1e-6
/// --periodic` opens the map (a side other than the file's 2 µm), the scene's `[measured]`
/// records the map with that side and its periodicity, `run --preset` of the export gives
/// the a_r the panel showed (and not the file's own side's), and the CSV names the map.
#[test]
fn an_export_of_a_measured_map_reopens_on_it() {
    use asperity::input::overrides::Overrides;
    use asperity_cli::cli::surface::SurfaceArgs;
    let dir = std::env::temp_dir().join(format!("asperity-export-map-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/two_bands.txt");
    let flags = SurfaceArgs {
        surface: Some(file.into()),
        size: Some(1e-6),
        periodic: true,
        ..SurfaceArgs::default()
    };
    // what `tui --surface` does: the scene on the map's spectrum, the flags kept
    let preset = Preset::resolve("system-1").unwrap();
    let mut app = App::new("system-1", preset).unwrap();
    app.jobs.export_dir = dir.clone();
    let (spectrum, map) = flags.spectrum_and_map().unwrap();
    let scene = app
        .params
        .scene
        .clone()
        .apply(&Overrides {
            spectrum,
            ..Overrides::default()
        })
        .unwrap();
    app.params.measured = flags.to_measured(map.as_ref());
    app.params.base = scene.clone();
    app.params.scene = scene;
    asperity_cli::tui::drive::compute_now(&mut app, &mut Default::default());
    let shown = asperity_cli::tui::charts::shared::path_a_r(&app).unwrap();
    let paths = export(&app).unwrap();
    let toml = paths.iter().find(|p| p.ends_with(".toml")).unwrap().clone();
    assert!(toml.contains("asperity-two_bands-"), "named after the map: {toml}");
    let back = Preset::resolve(&toml).unwrap();
    let m = back.measured.as_ref().expect("[measured] in the export");
    assert!(m.map.as_deref().is_some_and(|p| p.ends_with("two_bands.txt")), "{m:?}");
    assert_eq!((m.size_m, m.periodic), (Some(1e-6), true));
    let run = run_json(&toml);
    let a = run["a_r"].as_f64().unwrap();
    assert!(
        (a / shown - 1.0).abs() < 1e-3,
        "run --preset {toml}: {a} vs the panel's {shown}"
    );
    // the side kept: the rms gradient is the 1 µm map's, twice the file's own 2 µm one's
    let g = run["scene"]["rms_gradient"].as_f64().unwrap();
    let want = app.params.scene.rms_gradient();
    assert!((g / want - 1.0).abs() < 1e-9, "ḡ {g} vs the panel's scene's {want}");
    let own = SurfaceArgs {
        size: None,
        ..flags.clone()
    };
    let other = app
        .params
        .scene
        .clone()
        .apply(&Overrides {
            spectrum: own.spectrum_and_map().unwrap().0,
            ..Overrides::default()
        })
        .unwrap();
    assert!(
        (other.rms_gradient() / g - 0.5).abs() < 1e-6,
        "the file's own side: ḡ {} vs {g}",
        other.rms_gradient()
    );
    // the CSVs name the surface
    let pr = std::fs::read_to_string(paths.iter().find(|p| p.ends_with("-pr.csv")).unwrap()).unwrap();
    let (_, _, comments) = parse(&pr);
    let surface = &comments.iter().find(|(k, _)| k == "surface").expect("# surface:").1;
    assert!(surface.starts_with("two_bands.txt"), "{surface}");
    let _ = std::fs::remove_dir_all(&dir);
}
