//! Pinned comparisons: \[S\] Fig. 8 (Pr(σ*) of a thin slab at several thicknesses) in two
//! keystrokes per thickness, the pins named by what differs, drawn under the current curve
//! and carried into the CSV (`e`) and SVG/PNG (`s`) exports, which share one file number.
//! With `ASPERITY_DOCS_IMG=DIR` the test also writes the PNGs of the pinned Fig. 8 and of the
//! scale view into DIR (the screenshots of docs/img).

use asperity::input::preset::Preset;
use asperity_cli::tui::app::{App, Param};
use asperity_cli::tui::charts::{self, ChartKind, Role};
use asperity_cli::tui::drive::{compute_now, Caches};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

fn key(a: &mut App, c: char) {
    asperity_cli::tui::drive::press(a, KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE));
}

#[test]
fn fig8_pins_round_trip_through_csv_and_svg() {
    let dir = std::env::temp_dir().join(format!("asperity-pins-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut a = App::new("system-2", Preset::resolve("system-2").unwrap()).unwrap();
    a.ui.show_timing = false;
    a.jobs.export_dir = dir.clone();
    a.set_charts([ChartKind::Pr, ChartKind::Thickness, ChartKind::Area]);
    let mut caches = Caches::default();
    for t in ["0.1", "0.4"] {
        a.set_typed(Param::Thickness, t).unwrap();
        compute_now(&mut a, &mut caches);
        key(&mut a, 'P');
    }
    assert_eq!(a.results.pins.len(), 2);
    a.set_typed(Param::Thickness, "inf").unwrap();
    compute_now(&mut a, &mut caches);
    let m = charts::build(&a, ChartKind::Pr);
    let names: Vec<&str> = m.series.iter().map(|s| s.name.as_str()).collect();
    assert!(
        names.contains(&"t·q_r=0.1") && names.contains(&"t·q_r=0.4"),
        "{names:?}"
    );
    // the pins lie under the current curve, each with its own role (colour)
    let pins: Vec<&charts::Series> = m.series.iter().filter(|s| matches!(s.role, Role::Pin(_))).collect();
    assert_eq!(pins.len(), 2);
    assert_ne!(pins[0].role, pins[1].role);
    let now = m.series.last().unwrap();
    assert!(now.role == Role::Theory && now.name == "t·q_r=∞", "{}", now.name);
    // the pinned curves are the curves shown at their thickness: a thinner slab has a wider
    // tensile part (its wall further out), so the pinned Pr differ from each other and from t = ∞
    assert_ne!(pins[0].points, pins[1].points);
    // the thickness chart carries them too; the area chart as well
    assert!(charts::build(&a, ChartKind::Thickness)
        .series
        .iter()
        .any(|s| s.name == "t·q_r=0.1"));

    // `e` then `s`: one number sequence
    let csv = asperity_cli::tui::effects::export::export(&a).unwrap();
    assert!(csv[0].ends_with("asperity-system-2-1.toml"), "{csv:?}");
    let pins_csv = csv.iter().find(|p| p.ends_with("-pins.csv")).expect("pins CSV");
    let text = std::fs::read_to_string(pins_csv).unwrap();
    let rows: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(rows[0], "pin,label,chart,x,y");
    for (i, t) in [(1, "0.1"), (2, "0.4")] {
        let want = format!("{i},t·q_r={t},pr,");
        let n = rows.iter().filter(|r| r.starts_with(&want)).count();
        assert_eq!(n, pins[i - 1].points.len(), "{want}");
    }
    // a pinned value read back equals the curve drawn
    let (x, y) = pins[0].points[pins[0].points.len() / 2];
    let row = format!(
        "1,t·q_r=0.1,pr,{},{}",
        asperity_cli::tui::effects::export::cell(x),
        asperity_cli::tui::effects::export::cell(y)
    );
    assert!(rows.contains(&row.as_str()), "{row}");
    let figs = asperity_cli::tui::effects::export::export_charts(&a).unwrap();
    assert!(figs[0].ends_with("asperity-system-2-2-pr.svg"), "{figs:?}");
    let svg = std::fs::read_to_string(&figs[0]).unwrap();
    assert!(
        svg.contains("t·q_r=0.1") && svg.contains("t·q_r=0.4"),
        "pins in the SVG legend"
    );
    // `u` unpins the newest, `U` all
    key(&mut a, 'u');
    assert_eq!(a.results.pins.len(), 1);
    key(&mut a, 'U');
    assert!(a.results.pins.is_empty());
    if let Ok(out) = std::env::var("ASPERITY_DOCS_IMG") {
        // the screenshots: the pinned Fig. 8 and the scale view, through the export path
        let out = std::path::PathBuf::from(out);
        let png = figs.iter().find(|p| p.ends_with("-pr.png")).unwrap();
        std::fs::copy(png, out.join("explorer-fig8-pins.png")).unwrap();
        let mut s = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        s.jobs.export_dir = dir.clone();
        s.set_charts([ChartKind::Scales, ChartKind::ScalesArea, ChartKind::Area]);
        compute_now(&mut s, &mut caches);
        key(&mut s, '[');
        key(&mut s, '[');
        let figs = asperity_cli::tui::effects::export::export_charts(&s).unwrap();
        for (kind, name) in [
            ("-scales.png", "explorer-scales.png"),
            ("-scales-area.png", "explorer-scales-area.png"),
        ] {
            let png = figs.iter().find(|p| p.ends_with(kind)).unwrap();
            std::fs::copy(png, out.join(name)).unwrap();
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
