//! `asperity figure`: curves refined where they bend and drawn through hysteresis windows,
//! checked against the engine evaluated on its own between the figure's points and against
//! `sweep --over thickness`'s window edges (found by a bisection on the number of stable
//! branches, not by the figure's refinement).

mod common;

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::theory::engine::{evaluate, Options};
use asperity::tolerances::FIGURE_CHORD_PX;
use common::asperity_here_ok as ok;
use serde_json::Value;

/// The default chart's height in pixels (the SVG's, `chart::SVG_SIZE`).
const HEIGHT_PX: f64 = 560.0;

/// (x, y) of a series of a figure's JSON; y None where there is no value.
fn series<'a>(fig: &'a Value, name: &str) -> Vec<(f64, Option<f64>, &'a str)> {
    fig["series"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == name)
        .unwrap_or_else(|| panic!("no series {name}"))["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            (
                p["x"].as_f64().unwrap(),
                p["y"].as_f64(),
                p["note"].as_str().unwrap_or(""),
            )
        })
        .collect()
}

#[test]
fn figure_7_is_drawn_within_a_pixel_of_the_theory() {
    let fig: Value = serde_json::from_str(&ok(&["figure", "7", "--format", "json"])).unwrap();
    let curves = [
        ("model 3", 3, None),
        ("model 4", 4, None),
        ("adhesionless (model 4)", 4, Some(0.0)),
    ];
    let all: Vec<f64> = curves
        .iter()
        .flat_map(|c| series(&fig, c.0))
        .filter_map(|p| p.1)
        .collect();
    let span = all.iter().cloned().fold(f64::MIN, f64::max) - all.iter().cloned().fold(f64::MAX, f64::min);
    let base = Preset::resolve("system-2")
        .unwrap()
        .scene()
        .unwrap()
        .with_pressure(0.005)
        .unwrap();
    for (name, model, gamma) in curves {
        let pts: Vec<(f64, f64)> = series(&fig, name).iter().filter_map(|p| Some((p.0, p.1?))).collect();
        assert!(
            pts.len() > 13,
            "{name}: refined beyond the file's 13 thicknesses: {}",
            pts.len()
        );
        // the steepest intervals, where a coarse curve kinks
        let mut steep: Vec<usize> = (0..pts.len() - 1).collect();
        steep.sort_by(|&i, &j| {
            let d = |k: usize| (pts[k + 1].1 - pts[k].1).abs();
            d(j).total_cmp(&d(i))
        });
        for &i in steep.iter().take(3) {
            let ((x0, y0), (x1, y1)) = (pts[i], pts[i + 1]);
            let xm = (x0 * x1).sqrt();
            let mut s = base.clone().with_model(Model::named(model).unwrap()).unwrap();
            s = s.with_thickness_qr(xm).unwrap();
            if let Some(g) = gamma {
                s = s.with_surface_energy_j_m2(g).unwrap();
            }
            let want = evaluate(&s, &Options::default()).unwrap().stats.a_r;
            let line = 0.5 * (y0 + y1);
            let px = (line - want).abs() / span * HEIGHT_PX;
            assert!(
                px <= FIGURE_CHORD_PX,
                "{name} between t·q_r {x0} and {x1}: line {line}, theory {want}: {px:.2} px"
            );
        }
    }
}

#[test]
fn a_hysteresis_window_is_drawn_with_both_branches_and_its_edges() {
    let fig: Value =
        serde_json::from_str(&ok(&["figure", "tests/fixtures/fig-window.toml", "--format", "json"])).unwrap();
    let loading = series(&fig, "model 3");
    let unloading = series(&fig, "model 3 (unloading)");
    let style = fig["series"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == "model 3 (unloading)")
        .unwrap()["style"]
        .clone();
    assert_eq!(style, "dashed");
    // the window's edges as `sweep` finds them
    let sw: Value = serde_json::from_str(&ok(&[
        "sweep",
        "--preset",
        "system-2",
        "--model",
        "3",
        "--gamma",
        "0.1256",
        "--pressure",
        "1e-5",
        "--over",
        "thickness",
        "--from",
        "0.03",
        "--to",
        "1",
        "--points",
        "30",
        "--format",
        "json",
    ]))
    .unwrap();
    let edge = |kind: &str| {
        sw["window_edges"]
            .as_array()
            .unwrap()
            .iter()
            .find(|e| e["kind"] == kind)
            .unwrap()["value"]
            .as_f64()
            .unwrap()
    };
    let (jump_in, pull_off) = (edge("jump_in"), edge("pull_off"));
    // one pixel of the default chart along this log axis (0.03 … 1 over 800 px)
    let pixel = (1.0f64 / 0.03).ln() / 800.0;
    let inside: Vec<f64> = unloading.iter().filter(|p| p.1.is_some()).map(|p| p.0).collect();
    let (first, last) = (inside[0], inside[inside.len() - 1]);
    assert!(
        (first / jump_in).ln().abs() <= 2.0 * pixel,
        "unloading from {first}, jump-in at {jump_in}"
    );
    assert!(
        (last / pull_off).ln().abs() <= 2.0 * pixel,
        "unloading to {last}, pull-off at {pull_off}"
    );
    // the loading line is broken where its branch ends, at the jump-in edge
    let breaks: Vec<f64> = loading.iter().filter(|p| p.1.is_none()).map(|p| p.0).collect();
    assert_eq!(breaks.len(), 1, "{loading:?}");
    assert!(
        (breaks[0] / jump_in).ln().abs() <= pixel,
        "break at {}, jump-in at {jump_in}",
        breaks[0]
    );
    assert!(loading.iter().any(|p| p.2.contains("branch ends")));
    // inside the window the unloading branch holds more contact than the loading one
    for (x, u, _) in unloading.iter().filter(|p| p.1.is_some()) {
        let l = loading.iter().find(|p| p.0 == *x).and_then(|p| p.1).unwrap();
        assert!(u.unwrap() > 10.0 * l, "t·q_r {x}: unloading {u:?}, loading {l}");
    }
}
