//! Every curve told apart. For every chart kind of the explorer, with every combination of
//! the overlays (all models `M`, the adhesionless comparison, a second reference source, a
//! GFMD run with its theory on the map, pins, a hysteresis), on an adhesionless, an
//! adhesive, a custom, a YP08 and a thin-slab scene and a measured spectrum:
//!
//! - no two entries of a chart's key share a colour and glyph, and no two share a glyph and
//!   line style (what tells them apart under `NO_COLOR`);
//! - the SVG/PNG series of the chart (`s`) share no colour and line style (points: shape),
//!   nor in the shades they are drawn in on white;
//! - a model is drawn in its colour, on screen and in the files;
//! - at 80×24 no key entry is lost.
//!
//! And `asperity figure`: every figure's series are told apart the same way, a model's first
//! curve has the model's colour in every figure, and its later curves (Fig. 8's thicknesses)
//! colours of their own.

mod common;

use asperity::input::model::ModelKind;
use asperity::input::preset::{Preset, ReferencePoint};
use asperity::surface::spectrum::Spectrum;
use asperity::surface::tabulated::Tabulated;
use asperity_cli::chart::{flatten, on_white, Flat, SeriesStyle};
use asperity_cli::looks::{model_colour, Ink, Role};
use asperity_cli::tui::app::{App, Param};
use asperity_cli::tui::base::data::SweepData;
use asperity_cli::tui::charts::plot;
use asperity_cli::tui::charts::{self, Chart, ChartKind};
use asperity_cli::tui::drive::{compute_now, Caches, Reply};
use asperity_cli::tui::effects::export::file_chart;
use asperity_cli::tui::model::pins::{Pin, MAX_PINS};
use asperity_cli::tui::view;
use asperity_cli::tui::view::legend::{self, Entry};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;
use std::collections::HashSet;

fn key(a: &mut App, c: char) {
    asperity_cli::tui::drive::press(a, KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE));
}

fn app(preset: &str) -> App {
    let mut a = App::new(preset, Preset::resolve(preset).unwrap()).unwrap();
    a.ui.show_timing = false;
    a.ui.color = false;
    a.jobs.export_dir = std::env::temp_dir();
    a
}

/// Computes what every chart kind needs, with all models.
fn compute_all(a: &mut App) {
    let mut caches = Caches::default();
    a.ui.all_models = true;
    a.ui.compare = true;
    for k in ChartKind::ALL {
        a.set_charts([k, ChartKind::Pr, ChartKind::Area]);
        compute_now(a, &mut caches);
    }
}

/// A finished GFMD run on the current scene (its histogram, load points and the theory on
/// its map).
fn with_gfmd(a: &mut App) {
    let id = common::start_gfmd(a);
    a.on_reply(Reply::GfmdDone {
        id,
        elapsed_s: 1.0,
        result: Ok(common::synthetic_gfmd(a.params.scene.pressure())),
    });
    assert!(a.gfmd_for_scene().is_some());
}

/// Pins of `MAX_PINS` other scenes, each with a curve on every chart kind (the current
/// curves, shifted).
fn pins(a: &App) -> Vec<Pin> {
    (0..MAX_PINS)
        .map(|i| {
            let f = 1.0 + 0.1 * (i as f64 + 1.0);
            let curves = ChartKind::ALL
                .into_iter()
                .filter_map(|k| {
                    let m = charts::build_own(a, k);
                    let s = m.series.iter().find(|s| s.points.len() > 1)?;
                    Some((k, s.points.iter().map(|&(x, y)| (x, y * f)).collect()))
                })
                .collect();
            let scene = a
                .params
                .scene
                .clone()
                .with_pressure(a.params.scene.pressure() * f)
                .unwrap();
            Pin { scene, curves }
        })
        .collect()
}

/// The app's reference points and a second source for every quantity and load the charts
/// draw.
fn second_source(a: &App) -> Vec<ReferencePoint> {
    let mut out = a.params.preset.reference.clone();
    for (q, v) in [("a_r", 0.025), ("mean_contact_stress", 0.45), ("mean_gap_rel", 1.4)] {
        for t in [None, Some(1.0)] {
            out.push(ReferencePoint {
                source: "lab".into(),
                quantity: q.into(),
                pressure: a.params.scene.pressure(),
                thickness_qr: t,
                gamma: Some(a.params.scene.surface_energy_j_m2()),
                model: None,
                value: v,
            });
        }
    }
    out
}

/// The app's load curves, and the same with a hysteresis: an unloading branch and the
/// jump-in and pull-off loads.
fn hysteresis(a: &App) -> Option<(SweepData, SweepData)> {
    let Some(Ok(sw)) = a.results.sweep() else {
        return None;
    };
    let (jump, pull) = (0.03, 0.005);
    let mut h = sw.clone();
    common::add_hysteresis(&mut h, jump, pull);
    h.gap_unloading = h.gap_rel.iter().map(|g| g - 0.2).collect();
    Some((sw.clone(), h))
}

/// The scenes: each computed with every overlay at hand.
fn scenes() -> Vec<(&'static str, App)> {
    let mut out = Vec::new();
    let mut a = app("system-1");
    a.set_typed(Param::Gamma, "0").unwrap();
    compute_all(&mut a);
    out.push(("adhesionless", a));
    let mut a = app("system-1");
    compute_all(&mut a);
    out.push(("adhesive", a));
    for (name, kind) in [("custom", ModelKind::Custom), ("YP08", ModelKind::Yp08)] {
        let mut a = app("system-1");
        a.set_typed(Param::Gamma, "0").unwrap();
        while a.params.scene.model().kind != kind {
            key(&mut a, 'm');
        }
        compute_all(&mut a);
        out.push((name, a));
    }
    let mut a = app("system-2");
    compute_all(&mut a);
    out.push(("thin slab", a));
    // a measured spectrum: the psd chart's table, interpolant, fit and cut-offs
    let mut a = app("system-2");
    let Spectrum::SelfAffine(sa) = a.params.scene.spectrum().clone() else {
        unreachable!()
    };
    let (q, c) = common::ideal_table(&sa, 40);
    let t = Tabulated::new(q, c, "measured.csv", None, None).unwrap();
    a.params.scene.set_spectrum(Spectrum::Tabulated(t)).unwrap();
    out.push(("measured spectrum", a));
    for (_, a) in out.iter_mut() {
        if a.results.sweep().is_some() {
            with_gfmd(a);
        }
    }
    out
}

/// Whether the key entries are told apart: colour and glyph (with colour), glyph and line
/// style and the key's symbol (without); the clashes.
fn clashes(entries: &[Entry]) -> Vec<String> {
    let mut out = Vec::new();
    let mut coloured = HashSet::new();
    let mut plain = HashSet::new();
    let mut symbols = HashSet::new();
    for e in entries {
        if !symbols.insert(e.symbol()) {
            out.push(format!("key symbol {} of {:?} ({:?})", e.symbol(), e.name, e.role));
        }
        if !coloured.insert((e.look.ink, e.look.glyph)) {
            out.push(format!("colour and glyph of {:?} ({:?})", e.name, e.role));
        }
        if !plain.insert((e.look.glyph, e.draw)) {
            out.push(format!("glyph and line of {:?} ({:?}) under NO_COLOR", e.name, e.role));
        }
    }
    out
}

/// The clashes of a file chart: colour and line style, points also shape; and the same with
/// the shade a colour is drawn in on the white page.
fn file_clashes(spec: &Flat) -> Vec<String> {
    let (mut seen, mut inked) = (HashSet::new(), HashSet::new());
    let mut out = Vec::new();
    for s in &spec.series {
        let shape = (s.style == SeriesStyle::Points).then_some(s.shape);
        if !seen.insert((s.colour, s.style, shape)) {
            out.push(format!("{:?} looks like an earlier series", s.name));
        }
        if !inked.insert((on_white(s.colour), s.style, shape)) {
            out.push(format!("{:?} looks like an earlier series on white", s.name));
        }
    }
    out
}

fn entries(m: &Chart) -> Vec<Entry> {
    legend::entries(m, plot::ticks(m.yb, m.ys, true).0)
}

#[test]
fn every_chart_with_every_overlay_tells_its_curves_apart() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for (scene, mut a) in scenes() {
        let (gfmd, all_pins, refs) = (a.jobs.gfmd().clone(), pins(&a), a.params.preset.reference.clone());
        let more_refs = second_source(&a);
        let sweeps = hysteresis(&a);
        for combo in 0..64u32 {
            let on = |bit: u32| combo & (1 << bit) != 0;
            a.ui.all_models = on(0);
            a.ui.compare = on(1);
            a.jobs.show_gfmd(if on(2) { gfmd.clone() } else { Default::default() });
            a.results.pins = if on(3) { all_pins.clone() } else { Vec::new() };
            a.params.preset.reference = if on(4) { more_refs.clone() } else { refs.clone() };
            if let Some((plain, hyst)) = &sweeps {
                a.results
                    .set_sweep(Ok(if on(5) { hyst.clone() } else { plain.clone() }));
            } else if on(5) {
                continue;
            }
            let what = format!(
                "{scene}{}{}{}{}{}{}",
                if on(0) { " +M" } else { "" },
                if on(1) { " +compare" } else { "" },
                if on(2) { " +GFMD" } else { "" },
                if on(3) { " +pins" } else { "" },
                if on(4) { " +refs" } else { "" },
                if on(5) { " +hysteresis" } else { "" }
            );
            for k in ChartKind::ALL {
                let m = charts::build(&a, k);
                if m.empty.is_some() {
                    continue;
                }
                checked += 1;
                let e = entries(&m);
                for c in clashes(&e) {
                    failures.push(format!("{what}, {k:?}: {c}"));
                }
                let spec = flatten(&file_chart(&m, "test"));
                for c in file_clashes(&spec) {
                    failures.push(format!("{what}, {k:?} (file): {c}"));
                }
                // a model is drawn in its colour, on screen and in the file (the file draws
                // its series in layers, so they are matched by name)
                for s in &m.series {
                    if let Role::Model(i) = s.role {
                        let want = model_colour(i);
                        let on_screen = e.iter().find(|e| e.name == s.name).map(|e| e.look.ink);
                        let in_file = spec.series.iter().find(|f| f.name == s.name).map(|f| f.colour);
                        if on_screen.is_some_and(|c| c != Ink::Rgb(want)) || in_file != Some(want) {
                            failures.push(format!("{what}, {k:?}: {} not in its colour", s.name));
                        }
                    }
                }
            }
        }
    }
    assert!(checked > 1000, "{checked} charts");
    assert!(
        failures.is_empty(),
        "{} clashes:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The text of the screen.
fn render(a: &App, w: u16, h: u16) -> String {
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| view::draw(f, a)).unwrap();
    t.backend().to_string()
}

/// The entries of the chart in panel `i` that the screen does not show (by symbol and full,
/// abbreviated or shortest name).
fn lost(a: &App, i: usize, screen: &str) -> Vec<String> {
    let mut out = Vec::new();
    for k in [a.ui.charts[i]] {
        let m = charts::build(a, k);
        for e in entries(&m) {
            let sym = e.symbol();
            let short = legend::abbreviate(&e.name);
            let forms = [
                format!("{sym} {}", e.name),
                format!("{sym} {short}"),
                format!("{sym}{short}"),
                format!("{sym}{}", legend::tiny(&e)),
            ];
            if !forms.iter().any(|f| screen.contains(f.as_str())) {
                out.push(format!("{k:?}: {}", e.name));
            }
        }
    }
    out
}

#[test]
fn at_80x24_no_key_entry_is_lost() {
    let mut scenes = scenes();
    let mut failures = Vec::new();
    for (scene, a) in scenes.iter_mut() {
        // every chart kind in every panel, with the overlays one uses at once: all models or
        // a hysteresis, a GFMD run, the comparison, two pins
        let two_pins: Vec<Pin> = pins(a).into_iter().take(2).collect();
        let sweeps = hysteresis(a);
        for (m, pins) in [(true, Vec::new()), (false, two_pins)] {
            a.ui.all_models = m;
            a.results.pins = pins;
            if let Some((plain, hyst)) = &sweeps {
                a.results.set_sweep(Ok(if m { plain.clone() } else { hyst.clone() }));
            }
            for k in ChartKind::ALL {
                for charts in [[k, k.cycle(1), k.cycle(2)], [k.cycle(1), k, k.cycle(2)]] {
                    a.set_charts(charts);
                    // at 80×24 one chart shows at a time: the focused one (f shows the next)
                    for focus in 0..3 {
                        a.ui.focus = focus;
                        let screen = render(a, 80, 24);
                        for l in lost(a, focus, &screen) {
                            failures.push(format!("{scene} M={m} {charts:?}: {l}"));
                        }
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}\n", failures.join("\n"));
}

#[test]
fn a_model_has_one_colour_in_every_figure_and_its_curves_are_told_apart() {
    use asperity::report::figure::compute::compute;
    use asperity::report::figure::spec::{FigureSpec, BUILTIN};
    let mut seen: Vec<(String, u8)> = Vec::new();
    for (id, text) in BUILTIN {
        let mut spec = FigureSpec::parse(text, id).unwrap();
        // few points: the looks, not the values, are under test
        spec.points = spec.points.min(if spec.from.is_none() { 41 } else { 3 });
        let data = compute(&spec, None).unwrap();
        let chart = flatten(&asperity_cli::figure::chart(&data));
        let clashes = file_clashes(&chart);
        assert!(clashes.is_empty(), "figure {id}: {clashes:?}");
        let mut colours = Vec::new();
        for (c, s) in spec.curve.iter().zip(&chart.series) {
            let n = c.model.or(spec.model).unwrap_or(3);
            if c.variant.is_some() {
                continue;
            }
            if seen.contains(&(id.to_string(), n)) {
                // a later curve of the same model (Fig. 8: thicknesses) in a colour of its own
                assert!(!colours.contains(&s.colour), "figure {id}: {} repeats a colour", s.name);
            } else {
                let want = model_colour(usize::from(n) - 1);
                assert_eq!(s.colour, want, "figure {id}: {} is not model {n}'s colour", s.name);
                seen.push((id.to_string(), n));
            }
            colours.push(s.colour);
        }
    }
    // model 3 in figures 1, 2 and 7 at least, model 4 in 7 and 8
    let figs = |n: u8| {
        seen.iter()
            .filter(|s| s.1 == n)
            .map(|s| s.0.clone())
            .collect::<HashSet<_>>()
    };
    assert!(figs(3).len() >= 3 && figs(4).len() >= 2, "{seen:?}");
}
