//! Every tour caption true on the screens a class meets: each step is opened at 80×24,
//! 120×40 and 160×48 (the terminal's size sent first, so only the charts on screen are
//! computed, as in the explorer), drawn, and
//!
//! - every chart the caption refers to (the step's `refers`, each `{chart:NAME}` among them)
//!   is on screen;
//! - every look the caption names (`{look:NAME}`) is drawn in a chart it refers to, in more
//!   cells of its colour and glyph than the chart's key gives it (a line at least
//!   [`MIN_LINE_CELLS`]): a curve that lies under another, or off the plot, fails;
//! - no chart or line style is named bare (`chart`, `dashed`, `solid`, `dotted`): a caption
//!   names them only through `{chart:NAME}` and `{look:NAME}`, which are checked here;
//! - two looks the caption contrasts (`contrast` of the step) do not share their cells: in
//!   at most half of the columns where both are drawn do they meet in a row.

use asperity::input::preset::Preset;
use asperity_cli::looks::{look, model_slot, Glyph, Ink, Role};
use asperity_cli::tui::app::App;
use asperity_cli::tui::base::caption;
use asperity_cli::tui::charts::{self, Draw};
use asperity_cli::tui::drive::{compute_now, send, Caches};
use asperity_cli::tui::model::msg::Msg;
use asperity_cli::tui::tour::{Tour, BUILTIN};
use asperity_cli::tui::view::{self, Palette};
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::Terminal;
use std::collections::BTreeSet;

/// The sizes a class meets: a projector, a laptop, a wide screen.
const SIZES: [(u16, u16); 3] = [(80, 24), (120, 40), (160, 48)];

/// Cells a line a caption names must show beyond its key's.
const MIN_LINE_CELLS: usize = 4;

/// Words that name a chart or a line style: a caption says them through references only.
const BARE: [&str; 6] = ["chart", "dashed", "solid", "dotted", "dash", "dashes"];

/// The explorer at step `i` of `tour` on a `cols`×`rows` terminal, what it shows computed.
fn app_at(tour: &Tour, i: usize, cols: u16, rows: u16) -> App {
    let first = &tour.steps[0];
    let mut a = App::new(&first.source, Preset::resolve(&first.source).unwrap()).unwrap();
    a.ui.show_timing = false;
    a.ui.color = true;
    a.jobs.export_dir = std::env::temp_dir();
    send(&mut a, Msg::Resize { cols, rows });
    a.start_tour(tour.clone(), i);
    compute_now(&mut a, &mut Caches::default());
    a
}

fn colour_of(ink: Ink) -> Color {
    match ink {
        Ink::Text => Color::Reset,
        Ink::Rgb(c) => Color::Rgb(c.0, c.1, c.2),
    }
}

/// The cells of `r` (its border with the chart's key included) showing `role`'s look in a chart whose model is `slot`.
fn cells_of(buf: &Buffer, r: Rect, role: Role, slot: usize) -> Vec<(u16, u16)> {
    let want = look(role, slot, 0);
    let colour = colour_of(want.ink);
    let mut out = Vec::new();
    for y in r.y..r.y + r.height {
        for x in r.x..r.x + r.width {
            let c = &buf[(x, y)];
            let glyph_ok = match want.glyph {
                Glyph::Char(g) => c.symbol() == g.to_string(),
                _ => c.symbol() != " ",
            };
            if c.fg == colour && glyph_ok {
                out.push((x, y));
            }
        }
    }
    out
}

/// Whether two sets of cells meet in a row in more than half the columns where both are drawn
/// (within a column either side: one may cover the other where they meet).
fn share_cells(a: &[(u16, u16)], b: &[(u16, u16)]) -> bool {
    let rows = |s: &[(u16, u16)], x: u16| -> BTreeSet<u16> {
        s.iter().filter(|c| c.0 + 1 >= x && c.0 <= x + 1).map(|c| c.1).collect()
    };
    let cols: BTreeSet<u16> = a.iter().map(|c| c.0).collect();
    let (mut both, mut met) = (0, 0);
    for &x in &cols {
        let (ra, rb) = (rows(a, x), rows(b, x));
        if rb.is_empty() {
            continue;
        }
        both += 1;
        if ra.iter().any(|y| rb.contains(y)) {
            met += 1;
        }
    }
    both > 0 && 2 * met > both
}

/// A look drawn in a chart on screen: the look, the chart's index, its cells.
type Drawn = (Role, usize, Vec<(u16, u16)>);

/// What is wrong with step `i` of `t` at `cols`×`rows` (empty: its caption is true there).
fn check_step(t: &Tour, i: usize, cols: u16, rows: u16) -> Vec<String> {
    let s = &t.steps[i];
    let what = format!("step {} \"{}\" at {cols}×{rows}", i + 1, s.title);
    let a = app_at(t, i, cols, rows);
    let mut term = Terminal::new(TestBackend::new(cols, rows)).unwrap();
    term.draw(|f| view::draw(f, &a)).unwrap();
    let buf = term.backend().buffer().clone();
    let (_, scr) = view::screen_of(&a, Rect::new(0, 0, cols, rows), Palette { color: true });
    let shown: Vec<usize> = scr.charts.iter().map(|c| c.1).collect();
    let mut bad = Vec::new();
    for j in &s.refers {
        if !shown.contains(j) {
            bad.push(format!(
                "{what}: the caption's chart {} is not on screen",
                s.charts[*j].name()
            ));
        }
    }
    let slot = model_slot(&a.params.scene.model());
    let named: Vec<Role> = s
        .caption_source
        .iter()
        .flat_map(|l| caption::references(l))
        .filter(|(k, _)| k == "look")
        .filter_map(|(_, n)| Role::named(&n))
        .collect();
    let contrasted = s.contrasts.iter().flat_map(|(x, y)| [*x, *y]);
    let mut roles: Vec<Role> = named.into_iter().chain(contrasted).collect();
    roles.sort_by_key(|r| format!("{r:?}"));
    roles.dedup();
    // the cells of each look, in each chart on screen
    let mut drawn: Vec<Drawn> = Vec::new();
    for &role in &roles {
        let mut seen = Vec::new();
        for (r, j) in scr.charts.iter().filter(|(_, j)| s.refers.contains(j)) {
            let m = charts::build(&a, a.ui.charts[*j]);
            let series: Vec<&charts::Series> = m.series.iter().filter(|x| x.role == role).collect();
            let lines = m.vlines.iter().filter(|v| v.role == role).count();
            if series.is_empty() && lines == 0 {
                continue;
            }
            let cells = cells_of(&buf, *r, role, slot);
            // the key shows each series' glyph once
            let keyed = series.len() + lines;
            let points = series.iter().all(|x| x.style == Draw::Points) && lines == 0;
            let need = if points { keyed + 1 } else { keyed + MIN_LINE_CELLS };
            seen.push(format!("{} cells of {need} in {}", cells.len(), s.charts[*j].name()));
            if cells.len() >= need {
                drawn.push((role, *j, cells));
            }
        }
        if !drawn.iter().any(|d| d.0 == role) {
            bad.push(format!(
                "{what}: {role:?} is not visible in a chart the caption refers to ({})",
                seen.join(", ")
            ));
        }
    }
    for (x, y) in &s.contrasts {
        for (rx, j, cx) in &drawn {
            for (ry, k, cy) in &drawn {
                if rx == x && ry == y && j == k && (share_cells(cx, cy) || share_cells(cy, cx)) {
                    bad.push(format!(
                        "{what}: {x:?} and {y:?} share their cells in {}",
                        s.charts[*j].name()
                    ));
                }
            }
        }
    }
    bad
}

#[test]
fn captions_name_no_chart_or_line_style_bare() {
    let mut bad = Vec::new();
    for (name, text) in BUILTIN {
        let t = Tour::parse(text, name).unwrap();
        for (i, s) in t.steps.iter().enumerate() {
            for line in &s.caption_source {
                let text = caption::without_references(line);
                for w in text.split(|c: char| !c.is_alphabetic()) {
                    if BARE.contains(&w.to_lowercase().as_str()) {
                        bad.push(format!("step {} \"{}\": bare \"{w}\" in \"{line}\"", i + 1, s.title));
                    }
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn every_caption_is_true_at_80x24_120x40_and_160x48() {
    let mut bad = Vec::new();
    let mut contrasts = 0;
    for (name, text) in BUILTIN {
        let t = Tour::parse(text, name).unwrap();
        for i in 0..t.steps.len() {
            contrasts += t.steps[i].contrasts.len();
            for (cols, rows) in SIZES {
                bad.extend(check_step(&t, i, cols, rows));
            }
        }
    }
    assert!(contrasts >= 3, "{contrasts} contrasts checked");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn the_checker_sees_curves_on_one_row() {
    let a = [(10, 5), (11, 5), (12, 5), (13, 5)];
    let b = [(10, 5), (12, 5), (14, 5)];
    assert!(share_cells(&a, &b));
    let c = [(10, 9), (11, 9), (12, 8), (13, 8)];
    assert!(!share_cells(&a, &c));
    assert!(!share_cells(&a, &[]));
}

#[test]
#[ignore = "prints one step's screen: TOUR_STEP=N TOUR_SIZE=80x24"]
fn print_a_step() {
    let t = match std::env::var("TOUR_FILE") {
        Ok(f) => Tour::resolve(&f).unwrap(),
        Err(_) => Tour::parse(BUILTIN[0].1, BUILTIN[0].0).unwrap(),
    };
    let i: usize = std::env::var("TOUR_STEP").unwrap().parse().unwrap();
    let size = std::env::var("TOUR_SIZE").unwrap_or("80x24".into());
    let (c, r) = size.split_once('x').unwrap();
    let (cols, rows) = (c.parse().unwrap(), r.parse().unwrap());
    let a = app_at(&t, i - 1, cols, rows);
    let mut term = Terminal::new(TestBackend::new(cols, rows)).unwrap();
    term.draw(|f| view::draw(f, &a)).unwrap();
    let buf = term.backend().buffer();
    for y in 0..rows {
        let line: String = (0..cols).map(|x| buf[(x, y)].symbol().to_string()).collect();
        println!("{line}");
    }
    println!("{:?}", check_step(&t, i - 1, cols, rows));
}
