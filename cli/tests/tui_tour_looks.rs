//! Every tour caption against the screen it is shown on: a caption names a colour, a glyph or
//! a key only through a reference (`{look:NAME}`, `{key:KEY}`, see
//! `asperity_cli::tui::base::caption`), and
//!
//! - no colour word and no glyph of the table of looks stands bare in a caption (`+` and `·`
//!   are left to formulas: `0.35 + 0.65`, `t·q_r`);
//! - every look a caption names is drawn at its step, in one of its charts, with that colour
//!   and glyph, and (a point glyph) visible on a 200×60 screen, not covered by another mark;
//! - no key stands bare where a caption says what it does, every `{key:KEY}` has a
//!   `[[step.press]]`, and pressing the key at the step (after the keys before it, if the
//!   press names several) gives what the press says.

use asperity::input::preset::Preset;
use asperity_cli::looks::{self, look, Glyph, Ink, Role};
use asperity_cli::tui::app::App;
use asperity_cli::tui::base::caption::{self, Press};
use asperity_cli::tui::base::keys;
use asperity_cli::tui::charts;
use asperity_cli::tui::drive::{compute_now, Caches};
use asperity_cli::tui::tour::{Knob, Step, Tour, BUILTIN};
use asperity_cli::tui::view;
use ratatui::backend::TestBackend;
use ratatui::style::Color;
use ratatui::Terminal;

fn tours() -> Vec<Tour> {
    BUILTIN.iter().map(|(n, t)| Tour::parse(t, n).unwrap()).collect()
}

/// The explorer at step `i` of `tour`, everything its charts need computed.
fn app_at(tour: &Tour, i: usize) -> App {
    let first = &tour.steps[0];
    let mut a = App::new(&first.source, Preset::resolve(&first.source).unwrap()).unwrap();
    a.ui.show_timing = false;
    a.ui.color = true;
    a.jobs.export_dir = std::env::temp_dir();
    a.start_tour(tour.clone(), i);
    // the scale view plays from q_L: show its last frame, as after the play
    compute_now(&mut a, &mut Caches::default());
    a
}

/// Every glyph of the table of looks that a caption could name.
fn glyphs() -> Vec<char> {
    let mut out: Vec<char> = Vec::new();
    let mut roles: Vec<Role> = Role::NAMED.iter().map(|(_, r)| *r).collect();
    roles.extend((0..7).map(Role::Model));
    roles.extend((0..6).map(Role::Pin));
    roles.push(Role::Guide);
    roles.push(Role::GfmdTheory);
    for r in roles {
        for nth in 0..6 {
            if let Glyph::Char(c) = look(r, 0, nth).glyph {
                out.push(c);
            }
        }
    }
    for g in looks::MODEL_GLYPHS.iter().chain(&looks::PIN_GLYPHS) {
        out.push(g.symbol());
    }
    out.retain(|c| !matches!(c, '+' | '·'));
    out.sort();
    out.dedup();
    out
}

fn steps() -> Vec<(Tour, usize)> {
    let mut out = Vec::new();
    for t in tours() {
        for i in 0..t.steps.len() {
            out.push((t.clone(), i));
        }
    }
    out
}

/// Bare colours and glyphs of a step's caption.
fn bare_looks(step: &Step) -> Vec<String> {
    let glyphs = glyphs();
    let mut bad = Vec::new();
    for line in &step.caption_source {
        let text = caption::without_references(line);
        for w in text.split(|c: char| !c.is_alphabetic()) {
            if looks::COLOUR_WORDS.contains(&w.to_lowercase().as_str()) {
                bad.push(format!("colour \"{w}\""));
            }
        }
        for c in text.chars().filter(|c| glyphs.contains(c)) {
            bad.push(format!("glyph \"{c}\""));
        }
    }
    bad
}

/// Words after which a key names what it does.
const VERBS: [&str; 14] = [
    "turns", "turn", "adds", "add", "plays", "play", "steps", "step", "shows", "cycles", "toggles", "saves", "starts",
    "moves",
];

/// Keys a step's caption names bare: a multi-character key label anywhere (`h/l`, `Space`,
/// `⇧→`), a one-character key followed by a verb (`m turns`).
fn bare_keys(step: &Step) -> Vec<String> {
    let mut labels: Vec<&str> = keys::TABLE.iter().flat_map(|b| b.label.split(' ')).collect();
    labels.push("h/l");
    let mut bad = Vec::new();
    for line in &step.caption_source {
        let text = caption::without_references(line);
        let words: Vec<&str> = text
            .split_whitespace()
            .map(|w| w.trim_matches(|c: char| "(),.:;".contains(c)))
            .collect();
        for (i, w) in words.iter().enumerate() {
            if !labels.contains(w) {
                continue;
            }
            let long = w.chars().count() > 1;
            let then = words.get(i + 1).copied().unwrap_or("");
            let said = VERBS.contains(&then) || (*w == "[" && then == "and");
            if long || said {
                bad.push(format!("key \"{w}\" in \"{line}\""));
            }
        }
    }
    bad
}

#[test]
fn captions_name_colours_glyphs_and_keys_only_through_references() {
    let mut bad = Vec::new();
    for (t, i) in steps() {
        let s = &t.steps[i];
        for b in bare_looks(s).into_iter().chain(bare_keys(s)) {
            bad.push(format!("step {} \"{}\": bare {b}", i + 1, s.title));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The cells of a 200×60 screen of `a` showing `c` in `colour`.
fn cells(a: &App, c: char, colour: Color) -> usize {
    let mut t = Terminal::new(TestBackend::new(200, 60)).unwrap();
    t.draw(|f| view::draw(f, a)).unwrap();
    let buf = t.backend().buffer();
    buf.content()
        .iter()
        .filter(|cell| cell.symbol() == c.to_string() && cell.fg == colour)
        .count()
}

fn colour_of(ink: Ink) -> Color {
    match ink {
        Ink::Text => Color::Reset,
        Ink::Rgb(c) => Color::Rgb(c.0, c.1, c.2),
    }
}

#[test]
fn every_look_a_caption_names_is_drawn_so() {
    let mut bad = Vec::new();
    let mut seen = 0;
    for (t, i) in steps() {
        let s = &t.steps[i];
        let named: Vec<Role> = s
            .caption_source
            .iter()
            .flat_map(|l| caption::references(l))
            .filter(|(k, _)| k == "look")
            .map(|(_, n)| Role::named(&n).unwrap())
            .collect();
        if named.is_empty() {
            continue;
        }
        let a = app_at(&t, i);
        let models: Vec<_> = s.charts.iter().map(|k| charts::build(&a, *k)).collect();
        for role in named {
            seen += 1;
            let want = look(role, looks::model_slot(&a.params.scene.model()), 0);
            let mut drawn = 0;
            let mut keyed = 0;
            for m in &models {
                for (j, ser) in m.series.iter().enumerate() {
                    if ser.role == role && !asperity_cli::tui::charts::plot::runs(m, ser, m.yb, usize::MAX).is_empty() {
                        keyed += 1;
                        if m.series_look(j) == want {
                            drawn += 1;
                        }
                    }
                }
                for v in m.vlines.iter().filter(|v| v.role == role) {
                    keyed += 1;
                    if m.vline_look(v) == want {
                        drawn += 1;
                    }
                }
            }
            let what = format!("step {} \"{}\": {role:?}", i + 1, s.title);
            if drawn == 0 {
                bad.push(format!(
                    "{what} is not drawn as {} in its charts",
                    looks::describe(role, 0)
                ));
                continue;
            }
            if let Glyph::Char(c) = want.glyph {
                // the caption and each chart's key show the glyph too: the plot must add one
                let elsewhere = s.caption.iter().map(|l| l.matches(c).count()).sum::<usize>() + keyed;
                let on_screen = cells(&a, c, colour_of(want.ink));
                if on_screen <= elsewhere {
                    bad.push(format!(
                        "{what}: {c} is not visible in the plot ({on_screen} cells, {elsewhere} in keys and caption)"
                    ));
                }
            }
        }
    }
    assert!(seen >= 3, "{seen} looks named");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The value of a knob in `a`'s scene (the model by its number).
fn knob_value(a: &App, k: Knob) -> f64 {
    let s = &a.params.scene;
    match k {
        Knob::Preset => 0.0,
        Knob::Model => f64::from(s.model().number().unwrap_or(0)),
        Knob::Pressure => s.pressure(),
        Knob::Thickness => s.thickness_qr(),
        Knob::Gamma => s.surface_energy_j_m2(),
    }
}

/// Presses `p`'s keys at step `i`; Err says what differs from the claim.
fn verify_press(t: &Tour, i: usize, p: &Press) -> Result<(), String> {
    let mut a = app_at(t, i);
    let keys: Vec<&str> = p.key.split_whitespace().collect();
    let (last, first) = keys.split_last().unwrap();
    for k in first {
        asperity_cli::tui::drive::press(&mut a, keys::parse_label(k).unwrap());
        compute_now(&mut a, &mut Caches::default());
    }
    // the claims are about the last key
    let before: Vec<f64> = Knob::ALL.iter().map(|k| knob_value(&a, *k)).collect();
    let frame0 = a.ui.frame;
    asperity_cli::tui::drive::press(&mut a, keys::parse_label(last).unwrap());
    compute_now(&mut a, &mut Caches::default());
    let mut bad = Vec::new();
    if let Some(m) = p.model {
        let got = a.params.scene.model().number();
        if got != Some(m) {
            bad.push(format!("model {got:?}, not {m}"));
        }
    }
    if p.models.is_some_and(|m| m != a.ui.all_models) {
        bad.push(format!("all models {}", a.ui.all_models));
    }
    if p.compare.is_some_and(|c| c != a.ui.compare) {
        bad.push(format!("comparison {}", a.ui.compare));
    }
    for (name, up) in [(&p.raises, true), (&p.lowers, false)] {
        if let Some(k) = name.as_deref().and_then(Knob::parse) {
            let j = Knob::ALL.iter().position(|x| *x == k).unwrap();
            let (b, n) = (before[j], knob_value(&a, k));
            if (n > b) != up || n == b {
                bad.push(format!("{name:?} went from {b} to {n}"));
            }
        }
    }
    if let Some(d) = p.frame {
        let moved = match (frame0, a.ui.frame) {
            (Some(x), Some(y)) => (y as i64 - x as i64).signum() == i64::from(d.signum()),
            (None, Some(_)) => d < 0,
            _ => false,
        };
        if !moved {
            bad.push(format!("frame {frame0:?} → {:?}", a.ui.frame));
        }
    }
    if p.plays.is_some_and(|x| x != a.ui.playing) {
        bad.push(format!("playing {}", a.ui.playing));
    }
    let help = matches!(a.ui.overlay, asperity_cli::tui::model::ui::Overlay::Help);
    if p.help.is_some_and(|h| h != help) {
        bad.push(format!("help shown {help}"));
    }
    if p.branch.as_deref().is_some_and(|b| b != a.params.history.on.name()) {
        bad.push(format!(
            "on the {} branch at p* = {}",
            a.params.history.on.name(),
            a.params.scene.pressure()
        ));
    }
    if bad.is_empty() {
        Ok(())
    } else {
        Err(format!("{}: {}", p.says, bad.join(", ")))
    }
}

#[test]
fn every_key_a_caption_names_does_what_it_says() {
    let mut bad = Vec::new();
    let mut seen = 0;
    for (t, i) in steps() {
        let s = &t.steps[i];
        let what = format!("step {} \"{}\"", i + 1, s.title);
        for (_, name) in s
            .caption_source
            .iter()
            .flat_map(|l| caption::references(l))
            .filter(|(k, _)| k == "key")
        {
            let covered = s
                .presses
                .iter()
                .any(|p| name.split('/').any(|k| p.key.split_whitespace().last() == Some(k)));
            if !covered {
                bad.push(format!("{what}: {{key:{name}}} has no [[step.press]]"));
            }
        }
        for p in &s.presses {
            seen += 1;
            if let Err(e) = verify_press(&t, i, p) {
                bad.push(format!("{what}: {e}"));
            }
        }
    }
    assert!(seen >= 5, "{seen} presses");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
