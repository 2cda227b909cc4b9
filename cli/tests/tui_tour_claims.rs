//! Every claim of every shipped tour caption, checked against the engine.
//!
//! A caption's numbers and comparisons are written beside it in the tour file as
//! `[[step.check]]` tables (see `asperity_cli::tui::tour`); this test evaluates each quantity
//! on the step's scene (with the check's overrides) with the engine and the explorer's own
//! load sweep, and asserts what the caption says: a value within its relative tolerance,
//! bounds, or an order against another quantity or scene. It also checks that every number
//! a caption quotes is covered by a check, that a step selects the knob its caption tells the
//! class to turn, and that a caption citing GFMD shows GFMD data (the preset's reference
//! points or the GFMD points the library stores for the scene) in one of its charts.

use asperity::input::model::Model;
use asperity::input::preset::ReferencePoint;
use asperity::input::scene::Scene;
use asperity::theory::closed_form;
use asperity::theory::engine::{self, Options};
use asperity::theory::sweep::SweepSpec;
use asperity_cli::tui::base::stored_gfmd::stored_gfmd;
use asperity_cli::tui::charts::ChartKind;
use asperity_cli::tui::effects::worker;
use asperity_cli::tui::tour::{Check, Knob, Side, Step, Tour, BUILTIN};
use std::sync::atomic::AtomicBool;

/// The step's scene with a check's (or a comparison's) overrides.
fn scene_of(step: &Step, model: Option<u8>, p: Option<f64>, g: Option<f64>, t: Option<f64>) -> Scene {
    let mut s = step.scene.clone();
    if let Some(m) = model {
        s.set_model(Model::named(m).unwrap()).unwrap();
    }
    if let Some(p) = p {
        s.set_pressure(p).unwrap();
    }
    if let Some(g) = g {
        s.set_surface_energy_j_m2(g).unwrap();
    }
    if let Some(t) = t {
        s.set_thickness_qr(t).unwrap();
    }
    s
}

/// The reference points the explorer draws for `scene`: the preset's, then the GFMD points
/// the library stores for the scene's case.
fn shown_references(step: &Step, scene: &Scene) -> Vec<ReferencePoint> {
    let mut out = step.preset.reference.clone();
    out.extend(stored_gfmd(&step.preset, scene));
    out
}

/// The engine's value of `quantity` at `scene` (`a_r` for `W`).
fn quantity(step: &Step, q: &str, scene: &Scene, a_r: Option<f64>) -> f64 {
    let p = scene.pressure();
    if let Some(r) = q.strip_prefix("reference:") {
        let hits: Vec<f64> = shown_references(step, scene)
            .iter()
            .filter(|x| x.quantity == r && (x.pressure / p - 1.0).abs() < 1e-9)
            .map(|x| x.value)
            .collect();
        assert_eq!(hits.len(), 1, "one reference {r} at p* = {p} in {}", step.source);
        return hits[0];
    }
    match q {
        "eq18/p*" => return closed_form::eq18_area(p) / p,
        "W" => return scene.model().w(a_r.unwrap()),
        "gap_rel" | "jump_in" => {
            let spec = SweepSpec {
                from: p / 10.0,
                to: p * 10.0,
                points: 3,
            };
            let sw = worker::load_sweep(scene, &spec, &AtomicBool::new(false)).unwrap();
            if q == "jump_in" {
                return sw.jump_in.expect("a jump into contact within p*/10 .. 10 p*");
            }
            assert!((sw.p[1] / p - 1.0).abs() < 1e-9);
            return sw.gap_rel[1];
        }
        _ => {}
    }
    let ev = engine::evaluate(scene, &Options::default()).unwrap();
    match q {
        "a_r" => ev.stats.a_r,
        "a_r/p*" => ev.stats.a_r / p,
        "sigma_a" => ev.sigma_a,
        "mean_contact_stress" => ev.stats.mean_contact_stress,
        "width" => ev.width,
        "gamma_glo" => ev.gamma_glo,
        "tensile_area" => ev.tensile_area,
        "tensile_fraction" => ev.tensile_area / ev.stats.a_r,
        "a_r_unloading" => ev.unloading_a_r.expect("an unloading branch at this load"),
        "pr_linearity" => {
            let pr = &ev.stats.pr;
            let i = pr.sigma.iter().position(|&s| s > 0.0).unwrap();
            (pr.density[i] / pr.sigma[i]) / (pr.density[i + 1] / pr.sigma[i + 1])
        }
        other => panic!("unknown quantity {other}"),
    }
}

fn side_value(step: &Step, c: &Check, side: &Side) -> f64 {
    let s = scene_of(
        step,
        side.model.or(c.model),
        side.pressure.or(c.pressure),
        side.gamma.or(c.gamma),
        side.thickness_qr.or(c.thickness_qr),
    );
    quantity(step, side.quantity.as_deref().unwrap_or(&c.quantity), &s, c.a_r)
}

/// Evaluates one check; Err says which claim failed and by how much.
fn verify(step: &Step, c: &Check) -> Result<(), String> {
    let scene = scene_of(step, c.model, c.pressure, c.gamma, c.thickness_qr);
    let v = quantity(step, &c.quantity, &scene, c.a_r);
    let fail = |what: String| Err(format!("step \"{}\": \"{}\": {what}", step.title, c.says));
    if !v.is_finite() {
        return fail(format!("{} is {v}", c.quantity));
    }
    if let Some(x) = c.value {
        if (v - x).abs() > c.rel() * x.abs().max(1e-300) {
            return fail(format!("{} = {v:.6} is not {x} ± {}", c.quantity, c.rel() * x.abs()));
        }
    }
    if c.min.is_some_and(|m| v < m) || c.max.is_some_and(|m| v > m) {
        return fail(format!("{} = {v:.6e} outside [{:?}, {:?}]", c.quantity, c.min, c.max));
    }
    if let Some(s) = &c.below {
        let o = side_value(step, c, s);
        if v >= o {
            return fail(format!("{v:.6} is not below {o:.6}"));
        }
    }
    if let Some(s) = &c.above {
        let o = side_value(step, c, s);
        if v <= o {
            return fail(format!("{v:.6} is not above {o:.6}"));
        }
    }
    if let Some(s) = &c.near {
        let o = side_value(step, c, s);
        if (v - o).abs() > c.rel() * o.abs() {
            return fail(format!("{v:.6} is not within {} of {o:.6}", c.rel()));
        }
    }
    Ok(())
}

fn tours() -> Vec<Tour> {
    BUILTIN.iter().map(|(n, t)| Tour::parse(t, n).unwrap()).collect()
}

#[test]
fn every_caption_claim_holds_in_the_engine() {
    let mut failures = Vec::new();
    let mut n = 0;
    for tour in tours() {
        for step in &tour.steps {
            for c in &step.checks {
                n += 1;
                if let Err(e) = verify(step, c) {
                    failures.push(e);
                }
            }
        }
    }
    assert!(n >= 30, "only {n} checks");
    assert!(
        failures.is_empty(),
        "{} of {n} claims fail:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The numbers a caption quotes (decimals like 0.0214, 1.60 or 1e-4; not equation or figure
/// numbers, [S-n] citations or the p*, γ_s and t·q_r that set the scene).
fn quoted_numbers(caption: &str) -> Vec<String> {
    let mut out = Vec::new();
    let chars: Vec<char> = caption.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let starts = chars[i].is_ascii_digit() && (i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '-'));
        if !starts {
            i += 1;
            continue;
        }
        let mut j = i;
        while j < chars.len() && (chars[j].is_ascii_digit() || chars[j] == '.' || chars[j] == 'e' || chars[j] == '-') {
            j += 1;
        }
        let tok: String = chars[i..j]
            .iter()
            .collect::<String>()
            .trim_end_matches(['.', '-', 'e'])
            .to_string();
        if tok.contains('.') || tok.contains('e') {
            out.push(tok);
        }
        i = j.max(i + 1);
    }
    out
}

#[test]
fn every_quoted_number_is_checked_or_sets_the_scene() {
    for tour in tours() {
        for step in &tour.steps {
            let s = &step.scene;
            for tok in quoted_numbers(&step.caption.join(" ")) {
                let x: f64 = tok.parse().unwrap();
                let close = |y: f64| (x - y).abs() <= 0.006 * y.abs().max(1e-300) || (x - y).abs() < 1e-12;
                let c = step.checks.iter().any(|c| {
                    c.value.is_some_and(close)
                        || c.min.is_some_and(close)
                        || c.max.is_some_and(close)
                        || c.pressure.is_some_and(close)
                        || c.thickness_qr.is_some_and(|t| close(t) || (x - t).abs() < 0.01)
                        || c.gamma.is_some_and(close)
                        || c.a_r.is_some_and(close)
                });
                // the scene's own knobs, the paper's model coefficients (the models' definitions)
                let scene = close(s.pressure()) || close(s.surface_energy_j_m2()) || close(s.thickness_qr());
                let coefficient = [0.55, 0.35, 0.65, 0.5].iter().any(|&y| close(y));
                assert!(
                    c || scene || coefficient,
                    "step \"{}\" quotes {tok} without a check",
                    step.title
                );
            }
        }
    }
}

#[test]
fn a_step_selects_the_knob_its_caption_says_to_turn() {
    let knobs = [
        ("turn p*", Knob::Pressure),
        ("turn t·q_r", Knob::Thickness),
        ("turn γ_s", Knob::Gamma),
        ("turns the model", Knob::Model),
    ];
    let mut seen = 0;
    for tour in tours() {
        for step in &tour.steps {
            let cap = step.caption.join(" ").to_lowercase();
            let told: Vec<Knob> = knobs.iter().filter(|(w, _)| cap.contains(w)).map(|(_, k)| *k).collect();
            assert!(told.len() <= 1, "step \"{}\" tells to turn several knobs", step.title);
            if let Some(k) = told.first() {
                seen += 1;
                assert_eq!(step.select, Some(*k), "step \"{}\"", step.title);
            }
        }
    }
    assert!(seen >= 4, "{seen} steps tell which knob to turn");
}

/// What the explorer draws as a preset's reference points (see `charts`): the a_r charts and
/// the load charts of their own quantity.
fn shows_reference(kind: ChartKind, quantity: &str) -> bool {
    kind.reference_quantity() == Some(quantity)
}

#[test]
fn a_caption_citing_gfmd_shows_gfmd_data() {
    let mut seen = 0;
    for tour in tours() {
        for step in &tour.steps {
            if !step.caption.join(" ").contains("GFMD") {
                continue;
            }
            seen += 1;
            let s = &step.scene;
            let shown = shown_references(step, s).iter().any(|r| {
                r.gamma.is_none_or(|g| g == s.surface_energy_j_m2())
                    && step.charts.iter().any(|k| shows_reference(*k, &r.quantity))
            });
            assert!(
                shown,
                "step \"{}\" cites GFMD but none of its charts shows GFMD data",
                step.title
            );
        }
    }
    assert!(seen >= 2);
}

#[test]
fn the_quoted_number_scanner_finds_decimals_only() {
    assert_eq!(
        quoted_numbers("Fig. 2: a_r = 0.0214 [S-17] at p* = 1e-4, model 3, 12 %, t·q_r = 0.4."),
        ["0.0214", "1e-4", "0.4"]
    );
}
