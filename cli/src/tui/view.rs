//! Rendering: a title bar, the parameter panel with read-outs, three charts (Pr(σ*), a_r(p*),
//! ū(p*)) and a status bar; the help and preset overlays; a "terminal too small" screen.
//! Pure function of the [`App`]; every chart goes through [`super::plot`].

use super::charts::{self, ChartModel, Draw, Role, Series};
use super::keys;
pub use super::palette::{Palette, SPINNER, SPINNER_DELAY};
use super::panel::draw_panel;
use super::plot;
use super::state::{App, Overlay};
pub use super::words::sig;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Block, Chart, Clear, Dataset, GraphType, Paragraph, Wrap};
use ratatui::Frame;
/// Smallest usable terminal.
pub const MIN_SIZE: (u16, u16) = (60, 20);

/// Draws the whole screen.
pub fn draw(f: &mut Frame, app: &App) {
    let area = f.area();
    let pal = Palette { color: app.color };
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        too_small(f, area);
        return;
    }
    let status_line = status_line(app, pal);
    // messages wrap onto up to STATUS_ROWS rows; the key hint is cut instead
    let is_hint = app.edit.is_none()
        && app.message.is_none()
        && app.compute_error().is_none()
        && app.compute_warning().is_none()
        && app.gfmd_status().is_none();
    let status_rows = if is_hint {
        1
    } else {
        wrapped_rows(status_line.width(), area.width).clamp(1, STATUS_ROWS)
    };
    let caption = caption_lines(app);
    let caption_rows = if caption.is_empty() {
        0
    } else {
        let w = area.width.saturating_sub(2);
        let rows: u16 = caption.iter().map(|l| wrapped_rows(l.width(), w)).sum();
        (rows + 2).min(area.height / 3)
    };
    let [title, body, cap, status] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(caption_rows),
        Constraint::Length(status_rows),
    ])
    .areas(area);
    draw_title(f, title, app, pal);
    f.render_widget(Paragraph::new(status_line).wrap(Wrap { trim: false }), status);
    if caption_rows > 0 {
        let mut block = Block::bordered();
        if let Some(t) = &app.tour {
            block = block
                .title(Line::from(vec![
                    Span::raw(format!(" tour {}/{} · ", t.step + 1, t.tour.steps.len())),
                    Span::styled(
                        t.tour.steps[t.step].title.clone(),
                        Style::default().add_modifier(Modifier::BOLD),
                    ),
                    Span::raw(" "),
                ]))
                .title_bottom(
                    Line::from(Span::styled(" ←→ steps · h l knobs · Esc leaves ", pal.dim())).right_aligned(),
                );
        }
        f.render_widget(Paragraph::new(caption).wrap(Wrap { trim: true }).block(block), cap);
    }
    let panel_w = match area.width {
        120.. => 34,
        80.. => 28,
        _ => 24,
    };
    let [panel, charts] = Layout::horizontal([Constraint::Length(panel_w), Constraint::Fill(1)]).areas(body);
    draw_panel(f, panel, app, pal);
    let [top, bottom] = Layout::vertical([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(charts);
    let [left, right] = Layout::horizontal([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(bottom);
    for (i, r) in [top, left, right].into_iter().enumerate() {
        let m = charts::build(app, app.charts[i]);
        render_model(f, r, &m, pal, i == app.focus);
    }
    match app.overlay {
        Overlay::Help => draw_help(f, area, app.help_scroll, pal),
        Overlay::Presets(cursor) => draw_picker(f, area, app, cursor, pal),
        Overlay::None => {}
    }
}

/// Most rows a status message may take (long engine messages wrap instead of being cut).
pub const STATUS_ROWS: u16 = 4;

/// Rows a text of `width` columns takes when wrapped at `cols`.
fn wrapped_rows(width: usize, cols: u16) -> u16 {
    let cols = usize::from(cols.max(1));
    width.div_ceil(cols).max(1) as u16
}

/// The tour's caption lines (the step's title and the keys are in the box's border).
fn caption_lines(app: &App) -> Vec<Line<'static>> {
    let Some(t) = &app.tour else { return Vec::new() };
    t.tour.steps[t.step]
        .caption
        .iter()
        .map(|c| Line::from(c.clone()))
        .collect()
}

fn too_small(f: &mut Frame, area: Rect) {
    let text = vec![
        Line::from("terminal too small"),
        Line::from(format!(
            "{}×{}, need {}×{}",
            area.width, area.height, MIN_SIZE.0, MIN_SIZE.1
        )),
        Line::from("q quits"),
    ];
    let h = (text.len() as u16).min(area.height);
    let y = area.y + area.height.saturating_sub(h) / 2;
    f.render_widget(Paragraph::new(text).centered(), Rect::new(area.x, y, area.width, h));
}

fn draw_title(f: &mut Frame, area: Rect, app: &App, pal: Palette) {
    let mut spans = vec![
        Span::styled(" asperity ", Style::default().add_modifier(Modifier::BOLD)),
        Span::raw(format!("· {} · {} ", app.preset.name, app.scene.model().label())),
    ];
    // the spinner only once a computation has taken a while (most take milliseconds)
    if app.show_timing && app.busy_since.is_some_and(|t| t.elapsed() >= SPINNER_DELAY) {
        spans.push(Span::styled(
            format!("{} computing", SPINNER[app.spinner % SPINNER.len()]),
            pal.guide(),
        ));
    }
    f.render_widget(Paragraph::new(Line::from(spans)), area);
    let hint = Line::from(Span::styled("? help  q quit ", pal.dim())).right_aligned();
    f.render_widget(Paragraph::new(hint), area);
}

fn status_line(app: &App, pal: Palette) -> Line<'static> {
    if let Some(buf) = &app.edit {
        Line::from(vec![
            Span::raw(format!(" {} = ", app.selected_param().label())),
            Span::styled(format!("{buf}▏"), Style::default().add_modifier(Modifier::BOLD)),
            Span::styled("  Enter applies, Esc cancels", pal.dim()),
        ])
    } else if let Some(m) = &app.message {
        Line::from(Span::styled(
            format!(" {}", m.text),
            if m.error { pal.error() } else { Style::default() },
        ))
    } else if let Some(e) = app.compute_error() {
        Line::from(Span::styled(format!(" {e}"), pal.error()))
    } else if let Some(w) = app.compute_warning() {
        Line::from(Span::raw(format!(" {w}")))
    } else if let Some(g) = app.gfmd_status() {
        Line::from(Span::raw(format!(" {g}")))
    } else if app.tour.is_some() {
        Line::from(Span::styled(
            " ←→ step  h l change  ↑↓ pick  v chart  f focus  M models  s save  Esc leaves tour",
            pal.dim(),
        ))
    } else {
        Line::from(Span::styled(
            " ↑↓ pick  ←→ change  m model  v chart  f focus  M models  t tour  g GFMD  c compare  a area  \
             e export  s save  p preset  r reset",
            pal.dim(),
        ))
    }
}

/// Colour of model slot `i` (Okabe–Ito: orange, bluish green, blue, vermillion, reddish
/// purple for models 1–4 and custom).
fn model_style(pal: Palette, i: usize) -> Style {
    match i {
        0 => pal.reference(),
        1 => pal.compare(),
        2 => pal.theory(),
        3 => pal.current(),
        5 => pal.pin(1),
        6 => pal.pin(2),
        _ => pal.wall(),
    }
}

/// Marker of model slot `i`: told apart without colour too (YP08 and Xu24, slots 5 and 6,
/// reuse the dot and the bar in their own colours and are named in the legend).
const MODEL_MARKERS: [Marker; 7] = [
    Marker::Dot,
    Marker::Bar,
    Marker::Braille,
    Marker::Block,
    Marker::HalfBlock,
    Marker::Dot,
    Marker::Bar,
];

/// Markers of the pins (with the pin colours, told apart without colour by the name).
const PIN_MARKERS: [Marker; 2] = [Marker::Braille, Marker::Dot];

/// The legend symbol of a marker.
fn marker_symbol(m: Marker) -> &'static str {
    match m {
        Marker::Dot => "•",
        Marker::Bar => "▄",
        Marker::Block => "█",
        Marker::HalfBlock => "▀",
        _ => "⣿",
    }
}

/// Style, marker and graph type of a series role.
fn look(pal: Palette, role: Role, draw: Draw) -> (Style, Marker, GraphType) {
    let graph = if draw == Draw::Points {
        GraphType::Scatter
    } else {
        GraphType::Line
    };
    match role {
        Role::Theory => (pal.theory(), Marker::Braille, graph),
        Role::Model(i) => (
            model_style(pal, i),
            MODEL_MARKERS[i.min(MODEL_MARKERS.len() - 1)],
            graph,
        ),
        Role::Compare => (pal.compare(), Marker::Dot, graph),
        Role::Closed => (pal.reference(), Marker::Dot, graph),
        Role::Closed2 => (pal.guide(), Marker::Dot, graph),
        Role::Reference => (
            pal.text().add_modifier(Modifier::BOLD),
            Marker::Block,
            GraphType::Scatter,
        ),
        Role::Gfmd => (pal.gfmd(), Marker::HalfBlock, GraphType::Scatter),
        Role::Current => (pal.current(), Marker::Block, GraphType::Scatter),
        Role::Guide => (pal.guide(), Marker::Braille, GraphType::Line),
        Role::Band => (pal.guide(), Marker::Braille, GraphType::Scatter),
        Role::Wall => (pal.wall(), Marker::Bar, GraphType::Line),
        Role::Unloading => (pal.wall(), Marker::Dot, GraphType::Line),
        Role::JumpIn => (pal.current(), Marker::Bar, GraphType::Line),
        Role::PullOff => (pal.wall(), Marker::Bar, GraphType::Line),
        Role::Pin(i) => (pal.pin(i), PIN_MARKERS[i % PIN_MARKERS.len()], GraphType::Line),
    }
}

/// A key entry for a chart title.
fn legend(sym: &str, name: &str, style: Style) -> Vec<Span<'static>> {
    vec![Span::styled(sym.to_string(), style), Span::raw(format!(" {name} "))]
}

/// Plane points of a series, split at gaps, y outside `yb` dropped when clipping, decimated.
fn runs_of(m: &ChartModel, s: &Series, yb: [f64; 2], max_points: usize) -> Vec<Vec<(f64, f64)>> {
    let pts: Vec<(f64, f64)> = if m.clip_y {
        s.points
            .iter()
            .map(|&(x, y)| match m.ys.forward(y) {
                Some(v) if v >= yb[0] && v <= yb[1] => (x, y),
                _ => (x, f64::NAN),
            })
            .collect()
    } else {
        s.points.clone()
    };
    plot::segments(&pts, m.xs, m.ys)
        .into_iter()
        .map(|r| plot::decimate(&r, max_points))
        .collect()
}

/// One drawable run: plane points, style, marker, graph type.
type Drawn = (Vec<(f64, f64)>, Style, Marker, GraphType);

/// Draws one chart model into `area`; `focused` highlights the panel the selector changes.
pub fn render_model(f: &mut Frame, area: Rect, m: &ChartModel, pal: Palette, focused: bool) {
    let mark = if focused { "▸" } else { "" };
    let mut title = vec![Span::raw(format!(" {mark}{} ", m.title))];
    if m.stale {
        title.push(Span::styled("⋯ updating ", pal.dim()));
    }
    let mut block = Block::bordered().title(Line::from(title));
    if focused {
        block = block.border_style(Style::default().add_modifier(Modifier::BOLD));
    }
    if let Some(msg) = &m.empty {
        let inner = block.inner(area);
        f.render_widget(block, area);
        if inner.height > 0 {
            // centred, over as many rows as the reason needs (a failure's whole message)
            let rows = wrapped_rows(Span::raw(msg.as_str()).width(), inner.width);
            // a row to spare where words wrap early
            let h = if rows > 1 { rows + 1 } else { rows }.min(inner.height);
            let y = inner.y + (inner.height - h) / 2;
            f.render_widget(
                Paragraph::new(msg.clone()).centered().wrap(Wrap { trim: true }),
                Rect::new(inner.x, y, inner.width, h),
            );
        }
        return;
    }
    let three_x = area.width >= 36;
    let three_y = area.height >= 12;
    let (xb, xl) = plot::ticks(m.xb, m.xs, three_x);
    let (yb, yl) = plot::ticks(m.yb, m.ys, three_y);
    let max_points = 4 * area.width as usize;
    let mut drawn: Vec<Drawn> = Vec::new();
    let mut key: Vec<Span<'static>> = Vec::new();
    // the jump markers of a hysteresis are named after the curves (a narrow panel cuts the key)
    let mut key_last: Vec<Span<'static>> = Vec::new();
    for v in &m.vlines {
        let (style, marker, graph) = look(pal, v.role, Draw::Line);
        if let Some(x) = m.xs.forward(v.x) {
            drawn.push((plot::vertical(x, yb), style, marker, graph));
            if !v.name.is_empty() {
                let entry = legend(marker_symbol(marker), &v.name, style);
                if matches!(v.role, Role::JumpIn | Role::PullOff) {
                    key_last.extend(entry);
                } else {
                    key.extend(entry);
                }
            }
        }
    }
    for s in &m.series {
        let (style, marker, graph) = look(pal, s.role, s.draw);
        let runs = runs_of(m, s, yb, max_points);
        if runs.is_empty() {
            continue;
        }
        for r in runs {
            drawn.push((r, style, marker, graph));
        }
        key.extend(legend(marker_symbol(marker), &s.name, style));
    }
    key.extend(key_last);
    if !key.is_empty() {
        block = block.title_bottom(Line::from(key));
    }
    let datasets: Vec<Dataset> = drawn
        .iter()
        .map(|(pts, style, marker, graph)| {
            Dataset::default()
                .data(pts)
                .style(*style)
                .marker(*marker)
                .graph_type(*graph)
        })
        .collect();
    let chart = Chart::new(datasets)
        .block(block)
        .x_axis(
            Axis::default()
                .title(Span::styled(m.x_label.clone(), pal.dim()))
                .bounds(xb)
                .labels(xl),
        )
        .y_axis(
            Axis::default()
                .title(Span::styled(m.y_label.clone(), pal.dim()))
                .bounds(yb)
                .labels(yl),
        )
        .legend_position(None);
    f.render_widget(chart, area);
}

fn popup(area: Rect, w: u16, h: u16) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    Rect::new(area.x + (area.width - w) / 2, area.y + (area.height - h) / 2, w, h)
}

/// The help lines, generated from the key table.
pub fn help_lines() -> Vec<String> {
    keys::TABLE
        .iter()
        .map(|b| format!("{:<11}{}", b.label, b.help))
        .collect()
}

/// The help: every row of the key table; where the terminal is too short, the rows scroll
/// (↓/↑, j/k) and the box's bottom line says how far.
fn draw_help(f: &mut Frame, area: Rect, scroll: usize, pal: Palette) {
    let rows: Vec<Line> = help_lines().into_iter().map(Line::from).collect();
    let n = rows.len();
    let w = rows.iter().map(|l| l.width()).max().unwrap_or(20).max(40) as u16 + 4;
    let room = (area.height.saturating_sub(3) as usize).max(1);
    let (lines, note) = if n < room {
        let mut lines = rows;
        lines.push(Line::from(Span::styled("any key closes this help", pal.dim())));
        (lines, String::new())
    } else {
        let top = scroll.min(n - room);
        let note = format!(" {}–{} of {n} · ↓↑ scroll · other keys close ", top + 1, top + room);
        (rows.into_iter().skip(top).take(room).collect(), note)
    };
    let r = popup(area, w, lines.len() as u16 + 2);
    f.render_widget(Clear, r);
    let mut block = Block::bordered().title(" keys ");
    if !note.is_empty() {
        block = block.title_bottom(Line::from(Span::styled(note, pal.dim())).right_aligned());
    }
    f.render_widget(Paragraph::new(lines).block(block), r);
}

fn draw_picker(f: &mut Frame, area: Rect, app: &App, cursor: usize, pal: Palette) {
    let mut lines: Vec<Line> = app
        .presets
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let text = format!("{} {:<14} {}", if i == cursor { "▶" } else { " " }, e.source, e.place);
            if i == cursor {
                Line::from(Span::styled(text, Style::default().add_modifier(Modifier::REVERSED)))
            } else {
                Line::from(text)
            }
        })
        .collect();
    lines.push(Line::from(Span::styled("↑↓ choose, Enter load, Esc close", pal.dim())));
    let w = lines.iter().map(|l| l.width()).max().unwrap_or(20) as u16 + 4;
    let r = popup(area, w, lines.len() as u16 + 2);
    f.render_widget(Clear, r);
    f.render_widget(Paragraph::new(lines).block(Block::bordered().title(" presets ")), r);
}
