//! The bundled font: it parses, maps every character the chart and figure labels use, and
//! draws σ̄, γ̃ and ū in a PNG as one letter with its mark above, not beside.

use super::*;
use plotters::prelude::*;

#[test]
fn the_bundled_font_parses() {
    register();
}

#[test]
fn the_composite_glyphs_and_their_parts_are_in_the_font() {
    for (seq, c) in COMPOSED {
        assert!(has_glyph(c), "{seq}: U+{:04X}", u32::from(c));
        assert!(seq.chars().all(has_glyph), "{seq}");
        assert_eq!(png_text(&format!("x {seq}_c*")), format!("x {c}_c*"));
    }
    assert!(has_glyph('ū') && has_glyph('μ') && has_glyph('ḡ') && has_glyph('²'));
    // the lookup says no for what the subset left out
    assert!(!has_glyph('⣿') && !has_glyph('\u{E0FF}'));
    assert!(matches!(png_text("a_r"), Cow::Borrowed(_)));
}

/// Non-ASCII characters inside the string literals of `text` (comment lines left out).
fn literal_chars(text: &str, out: &mut std::collections::BTreeMap<char, String>, file: &str) {
    for line in text.lines() {
        let t = line.trim_start();
        if t.starts_with("//") || t.starts_with('#') && !t.contains('"') {
            continue;
        }
        let mut inside = false;
        let mut prev = ' ';
        for c in line.chars() {
            if c == '"' && prev != '\\' {
                inside = !inside;
            } else if inside && !c.is_ascii() {
                out.entry(c).or_insert_with(|| format!("{file}: {}", line.trim()));
            }
            prev = c;
        }
    }
}

/// The files whose strings end up in chart and figure files: titles, axis titles, legend
/// names (the explorer's chart builders, the figure specs and presets, the model names).
const LABEL_SOURCES: [&str; 20] = [
    "src/chart/mod.rs",
    "src/chart/flat.rs",
    "src/numfmt.rs",
    "src/chart/draw.rs",
    "../src/report/figure/mod.rs",
    "../src/report/figure/compute.rs",
    "../src/report/figure/spec.rs",
    "../src/report/figure/table1.rs",
    "src/tui/charts/mod.rs",
    "src/tui/charts/load.rs",
    "src/tui/charts/psd.rs",
    "src/tui/charts/scales.rs",
    "src/tui/charts/shared.rs",
    "src/tui/effects/export.rs",
    "src/tui/base/kinds.rs",
    "src/tui/model/pins.rs",
    "src/tui/charts/plot.rs",
    "src/tui/base/words.rs",
    "../src/input/model.rs",
    "../src/input/preset.rs",
];

#[test]
fn every_character_of_the_labels_has_a_glyph() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut chars = std::collections::BTreeMap::new();
    for f in LABEL_SOURCES {
        let text = std::fs::read_to_string(root.join(f)).unwrap();
        literal_chars(&text, &mut chars, f);
    }
    for dir in ["../figures", "../presets"] {
        for e in std::fs::read_dir(root.join(dir)).unwrap() {
            let p = e.unwrap().path();
            let text = std::fs::read_to_string(&p).unwrap();
            literal_chars(&text, &mut chars, &p.display().to_string());
        }
    }
    // what the explorer's `s` writes for every chart of a computed scene
    let mut app = crate::tui::app::App::new(
        "system-1",
        asperity::input::preset::Preset::resolve("system-1").unwrap(),
    )
    .unwrap();
    crate::tui::drive::compute_now(&mut app, &mut Default::default());
    for k in crate::tui::base::kinds::ChartKind::ALL {
        let chart =
            crate::tui::effects::export::file_chart(&crate::tui::charts::build(&app, k), "γ_s = 0.05 J/m², t·q_r = ∞");
        let spec = crate::chart::flatten(&chart);
        let mut text = vec![spec.title, spec.x_label, spec.y_label];
        text.extend(spec.series.into_iter().map(|s| s.name));
        for t in text {
            for c in t.chars().filter(|c| !c.is_ascii()) {
                chars.entry(c).or_insert_with(|| format!("{k:?}: {t}"));
            }
        }
    }
    assert!(chars.contains_key(&'ū') && chars.contains_key(&'\u{304}'), "{chars:?}");
    let missing: Vec<String> = chars
        .iter()
        .filter(|(c, _)| !has_glyph(**c))
        .map(|(c, w)| format!("{c:?} (U+{:04X}) in {w}", u32::from(*c)))
        .collect();
    assert!(
        missing.is_empty(),
        "no glyph in the bundled font for:\n{}",
        missing.join("\n")
    );
}

/// The inked box (x0, y0, x1, y1) of `text` drawn at 60 px on a white bitmap.
fn ink(text: &str) -> (usize, usize, usize, usize) {
    register();
    let (w, h) = (400usize, 160usize);
    let mut buf = vec![255u8; w * h * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w as u32, h as u32)).into_drawing_area();
        let style = TextStyle::from((FAMILY, 60.0)).color(&BLACK);
        root.draw_text(text, &style, (20, 40)).unwrap();
        root.present().unwrap();
    }
    let (mut x0, mut y0, mut x1, mut y1) = (w, h, 0, 0);
    for y in 0..h {
        for x in 0..w {
            if buf[3 * (y * w + x)] < 128 {
                (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
            }
        }
    }
    assert!(x1 > x0, "{text:?} drew nothing");
    (x0, y0, x1, y1)
}

#[test]
fn marked_letters_draw_the_mark_over_the_letter() {
    for (base, seq) in [("σ", "σ\u{304}"), ("γ", "γ\u{303}")] {
        let plain = ink(base);
        let marked = ink(&png_text(seq));
        // as wide as the letter (the mark is over it, not after it), and taller (the mark)
        assert!(marked.2.abs_diff(plain.2) <= 2, "{seq}: {marked:?} against {plain:?}");
        assert!(
            marked.1 + 5 < plain.1,
            "{seq}: no mark above: {marked:?} against {plain:?}"
        );
        // drawn as two code points, the mark would land beside the letter
        let raw = ink(seq);
        assert!(raw.2 > plain.2 + 5, "{seq}: {raw:?}");
    }
    // ū is a glyph of its own (it used to be missing, and nothing was drawn)
    let (u, u_bar) = (ink("u"), ink("ū"));
    assert!(
        u_bar.1 + 5 < u.1 && u_bar.2.abs_diff(u.2) <= 2,
        "{u_bar:?} against {u:?}"
    );
    // a whole label: μ_T, ū/h_rms, σ̄_c*, γ̃ each draw (no character is dropped)
    let label = png_text("σ̄_c* ū/h_rms γ̃ μ_T");
    let width = |t: &str| ink(t).2 - ink(t).0;
    assert!(width(&label) > width("σ_c* u/h_rms γ μ_T") - 3, "{label}");
}
