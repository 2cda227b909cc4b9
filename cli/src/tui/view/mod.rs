//! Rendering: a title bar, the parameter panel with read-outs, the chart panels (three, or
//! fewer where the terminal is short: [`crate::tui::view::layout`]), the tour's caption and a status bar;
//! the help and preset overlays; a "terminal too small" screen.
//! Pure function of the [`App`]; every chart goes through [`crate::tui::charts::plot`].

pub mod hit;
pub mod layout;
pub mod legend;
pub mod palette;
pub mod panel;

use crate::chart::dashes;
use crate::looks::Glyph;
pub use crate::numfmt::sig;
use crate::tui::base::keys;
use crate::tui::charts::plot;
use crate::tui::charts::{self, Draw, Role};
use crate::tui::model::app::{App, Overlay};
pub use crate::tui::view::layout::MIN_SIZE;
pub use crate::tui::view::palette::{Palette, SPINNER, SPINNER_DELAY};
use crate::tui::view::panel::draw_panel;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Block, BorderType, Chart, Clear, Dataset, GraphType, Paragraph, Wrap};
use ratatui::Frame;

/// Draws the whole screen.
pub fn draw(f: &mut Frame, app: &App) {
    let area = f.area();
    let pal = Palette { color: app.ui.color };
    if crate::tui::model::ui::too_small(area.width, area.height) {
        too_small(f, area);
        return;
    }
    let (status_line, scr) = screen_of(app, area, pal);
    draw_title(f, scr.title, app, pal);
    f.render_widget(Paragraph::new(status_line).wrap(Wrap { trim: false }), scr.status);
    if scr.caption.height > 0 {
        let mut block = Block::bordered();
        if let Some(t) = &app.ui.tour {
            let keys = if scr.caption_scrolls() {
                format!(
                    " J K scroll {}–{} of {} · ←→ steps · Esc leaves ",
                    scr.caption_top + 1,
                    scr.caption_top + scr.caption_visible().len(),
                    scr.caption_lines.len()
                )
            } else {
                " ←→ steps · h l knobs · Esc leaves ".to_string()
            };
            block = block
                .title(Line::from(vec![
                    Span::raw(format!(" tour {}/{} · ", t.step + 1, t.tour.steps.len())),
                    Span::styled(
                        t.tour.steps[t.step].title.clone(),
                        Style::default().add_modifier(Modifier::BOLD),
                    ),
                    Span::raw(" "),
                ]))
                .title_bottom(Line::from(Span::styled(keys, pal.dim())).right_aligned());
        }
        let lines: Vec<Line> = scr.caption_visible().iter().map(|l| Line::from(l.clone())).collect();
        f.render_widget(Paragraph::new(lines).block(block), scr.caption);
    }
    if app.ui.zoom {
        // the focused chart over the panel and the other charts (z, Esc: back)
        let body = scr.charts.iter().fold(scr.panel, |u, (r, _)| u.union(*r));
        let i = app.ui.focus.min(2);
        let mut m = charts::build(app, app.ui.charts[i]);
        m.title = format!("{} · z: all panels", m.title);
        render_model(f, body, &m, pal, true);
    } else {
        draw_body(f, &scr, app, pal);
    }
    match app.ui.overlay {
        Overlay::Help => draw_help(f, area, app.ui.help_scroll, pal),
        Overlay::Presets(cursor) => draw_picker(f, area, app, cursor, pal),
        Overlay::None => {}
    }
}

/// The status line and where everything goes on a terminal of `area` (also where a mouse
/// click lands: [`hit::hit`]).
pub fn screen_of(app: &App, area: Rect, pal: Palette) -> (Line<'static>, layout::Screen) {
    let mut status_line = status_line(app, pal);
    // messages wrap onto up to STATUS_ROWS rows; the key hint is cut instead
    let is_hint = app.ui.edit.is_none()
        && app.ui.message.is_none()
        && app.compute_error().is_none()
        && app.compute_warning().is_none()
        && app.gfmd_status().is_none();
    let status_rows = if is_hint {
        // a hint wider than the screen is cut and says so
        status_line = cut_hint(&status_line, usize::from(area.width), pal);
        1
    } else {
        wrapped_rows(status_line.width(), area.width).clamp(1, STATUS_ROWS)
    };
    let caption = caption_text(app);
    let panel_w = crate::tui::base::wrap::panel_cols(area.width);
    let scr = layout::screen(
        area,
        &caption,
        app.ui.caption_scroll,
        status_rows,
        panel_w,
        app.ui.focus,
    );
    (status_line, scr)
}

/// A hint line cut to `cols` columns, ending in `…` where it was cut.
fn cut_hint(line: &Line<'static>, cols: usize, pal: Palette) -> Line<'static> {
    if line.width() <= cols {
        return line.clone();
    }
    let text: String = line.spans.iter().map(|s| s.content.as_ref()).collect();
    let mut out = String::new();
    for c in text.chars() {
        if Span::raw(format!("{out}{c}…")).width() > cols {
            break;
        }
        out.push(c);
    }
    Line::from(Span::styled(format!("{}…", out.trim_end()), pal.dim()))
}

/// The parameter panel and the chart panels.
fn draw_body(f: &mut Frame, scr: &layout::Screen, app: &App, pal: Palette) {
    draw_panel(f, scr.panel, app, pal);
    let shown = scr.charts.len();
    for (r, i) in &scr.charts {
        let mut m = charts::build(app, app.ui.charts[*i]);
        if shown == 1 {
            // one chart at a time on a small terminal: which one, and how to see the others
            m.title = format!("{}/3 (f next) · {}", i + 1, m.title);
        }
        // the pull-off read-out in a title goes where the border has no room for it: its
        // estimate first, then the whole read-out
        let room = usize::from(r.width.saturating_sub(4));
        for cut in [crate::tui::base::data::PULL_OFF_EST_SEGMENT, " · pull-off"] {
            if let Some(k) = m.title.find(cut).filter(|_| m.title.chars().count() > room) {
                m.title.truncate(k);
            }
        }
        render_model(f, *r, &m, pal, *i == app.ui.focus && shown > 1);
    }
}

/// Most rows a status message may take (long engine messages wrap instead of being cut).
pub const STATUS_ROWS: u16 = 4;

/// Rows a text of `width` columns takes when wrapped at `cols`.
fn wrapped_rows(width: usize, cols: u16) -> u16 {
    let cols = usize::from(cols.max(1));
    width.div_ceil(cols).max(1) as u16
}

/// The tour's caption (the step's title and the keys are in the box's border).
fn caption_text(app: &App) -> Vec<String> {
    app.ui
        .tour
        .as_ref()
        .map(|t| t.tour.steps[t.step].caption.clone())
        .unwrap_or_default()
}

/// What the "terminal too small" screen says last, where it has room: the update takes no
/// other key there ([`crate::tui::model::ui::too_small`]).
pub const TOO_SMALL_OTHER_KEYS: &str = "other keys wait for a bigger terminal";

fn too_small(f: &mut Frame, area: Rect) {
    let mut text = vec![
        Line::from("terminal too small"),
        Line::from(format!(
            "{}×{}, need {}×{}",
            area.width, area.height, MIN_SIZE.0, MIN_SIZE.1
        )),
        Line::from("q quits"),
    ];
    if area.height > text.len() as u16 && usize::from(area.width) >= TOO_SMALL_OTHER_KEYS.len() {
        text.push(Line::from(TOO_SMALL_OTHER_KEYS));
    }
    let h = (text.len() as u16).min(area.height);
    let y = area.y + area.height.saturating_sub(h) / 2;
    f.render_widget(Paragraph::new(text).centered(), Rect::new(area.x, y, area.width, h));
}

fn draw_title(f: &mut Frame, area: Rect, app: &App, pal: Palette) {
    let mut spans = vec![
        Span::styled(" asperity ", Style::default().add_modifier(Modifier::BOLD)),
        Span::raw(format!(
            "· {} · {} ",
            app.params.preset.name,
            app.params.scene.model().label()
        )),
    ];
    // the spinner only once a computation has taken a while (most take milliseconds)
    if app.ui.show_timing
        && app.jobs.busy_since().is_some()
        && app.ui.elapsed_s(app.jobs.busy_since()) >= SPINNER_DELAY.as_secs_f64()
    {
        spans.push(Span::styled(
            format!("{} computing", SPINNER[app.ui.spinner % SPINNER.len()]),
            pal.busy(),
        ));
    }
    f.render_widget(Paragraph::new(Line::from(spans)), area);
    let hint = Line::from(Span::styled("? help  q quit ", pal.dim())).right_aligned();
    f.render_widget(Paragraph::new(hint), area);
}

fn status_line(app: &App, pal: Palette) -> Line<'static> {
    if let Some(buf) = &app.ui.edit {
        Line::from(vec![
            Span::raw(format!(" {} = ", app.selected_param().label())),
            Span::styled(format!("{buf}▏"), Style::default().add_modifier(Modifier::BOLD)),
            Span::styled("  Enter applies, Esc cancels", pal.dim()),
        ])
    } else if let Some(m) = &app.ui.message {
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
    } else if app.ui.tour.is_some() {
        Line::from(Span::styled(
            " ←→ step  h l change  ↑↓ pick  v chart  f focus  M models  s save  Esc leaves tour",
            pal.dim(),
        ))
    } else {
        Line::from(Span::styled(
            " ↑↓ pick  ←→ change  m model  v chart  f focus  z zoom  M models  t tour  g GFMD  c compare  \
             a area  e export  s save  p preset  r reset  Esc cancel  q quit",
            pal.dim(),
        ))
    }
}

/// ratatui's marker of a glyph.
fn marker(g: Glyph) -> Marker {
    match g {
        Glyph::Braille => Marker::Braille,
        Glyph::Dot => Marker::Dot,
        Glyph::Bar => Marker::Bar,
        Glyph::Block => Marker::Block,
        Glyph::HalfBlock => Marker::HalfBlock,
        Glyph::Quadrant => Marker::Quadrant,
        Glyph::Char(c) => Marker::Custom(c),
    }
}

/// One drawable run: plane points, style, marker, graph type.
type Drawn = (Vec<(f64, f64)>, Style, Marker, GraphType);

/// Draws one chart model into `area`; `focused` highlights the panel the selector changes.
pub fn render_model(f: &mut Frame, area: Rect, m: &crate::chart::Chart, pal: Palette, focused: bool) {
    let mark = if focused { "▸" } else { "" };
    let mut title = vec![Span::raw(format!(" {mark}{} ", m.title))];
    if m.stale {
        title.push(Span::styled("⋯ updating ", pal.dim()));
    }
    let mut block = Block::bordered().title(Line::from(title));
    if focused {
        // the focused panel: a thick border (seen without colour too), bold
        block = block
            .border_type(BorderType::Thick)
            .border_style(Style::default().add_modifier(Modifier::BOLD));
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
    let three_y = area.height >= 12 && !m.fit_y;
    let (xb, xl) = plot::ticks(m.xb, m.xs, three_x);
    let (yb, yl) = plot::ticks(m.yb, m.ys, three_y);
    let max_points = 4 * area.width as usize;
    // a broken line's pattern is in cells: plane units per cell of the plot (about)
    let label_w = yl.iter().map(|l| l.chars().count()).max().unwrap_or(1) as f64 + 1.0;
    let cols = (f64::from(area.width) - 2.0 - label_w).max(4.0);
    let rows = (f64::from(area.height) - 4.0).max(2.0);
    let cell = (cols / (xb[1] - xb[0]), rows / (yb[1] - yb[0]));
    let mut drawn: Vec<Drawn> = Vec::new();
    for v in &m.vlines {
        let lk = m.vline_look(v);
        if let Some(x) = m.xs.forward(v.x) {
            drawn.push((plot::vertical(x, yb), pal.look(lk), marker(lk.glyph), GraphType::Line));
        }
    }
    for i in m.draw_order() {
        let s = &m.series[i];
        let lk = m.series_look(i);
        let (style, mk) = (pal.look(lk), marker(lk.glyph));
        if s.role == Role::Band {
            // a shaded range: every cell between its lower and upper ends marked
            let fill = plot::fill_band(&s.points, m.xs, m.ys, cell);
            drawn.push((fill, style, mk, GraphType::Scatter));
            continue;
        }
        for r in plot::runs(m, s, yb, max_points) {
            if s.style == Draw::Points {
                drawn.push((r, style, mk, GraphType::Scatter));
            } else if let Some(p) = s.style.pattern() {
                // a broken line as its strokes, each a line of its own
                drawn.extend(dashes(&r, p, cell).into_iter().map(|d| (d, style, mk, GraphType::Line)));
            } else {
                drawn.push((r, style, mk, GraphType::Line));
            }
        }
    }
    // the key: one line in the bottom border, the rest (a long key) on the chart's top rows,
    // leaving the plot at least three
    let inner = block.inner(area);
    let max_rows = 1 + usize::from(inner.height.saturating_sub(3));
    let key = legend::lines(
        &legend::entries(m, yb),
        usize::from(area.width.saturating_sub(2)),
        max_rows,
        pal,
    );
    let mut plot_area = area;
    if let Some((first, more)) = key.split_first() {
        block = block.title_bottom(first.clone());
        if !more.is_empty() {
            let n = more.len() as u16;
            f.render_widget(block.clone(), area);
            f.render_widget(
                Paragraph::new(more.to_vec()),
                Rect::new(inner.x, inner.y, inner.width, n),
            );
            plot_area = Rect::new(inner.x, inner.y + n, inner.width, inner.height - n);
        }
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
    let mut chart = Chart::new(datasets)
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
    if plot_area == area {
        chart = chart.block(block);
    }
    f.render_widget(chart, plot_area);
}

fn popup(area: Rect, w: u16, h: u16) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    Rect::new(area.x + (area.width - w) / 2, area.y + (area.height - h) / 2, w, h)
}

/// The help lines, generated from the key table, then what each panel row is.
pub fn help_lines() -> Vec<String> {
    let pad = |s: &str| format!("{s}{}", " ".repeat(11usize.saturating_sub(Span::raw(s).width())));
    keys::TABLE
        .iter()
        .map(|b| format!("{:<11}{}", b.label, b.help))
        .chain(std::iter::once(keys::MANUAL.to_string()))
        .chain(std::iter::once(keys::PANEL_HEADER.to_string()))
        .chain(keys::PANEL_ROWS.iter().map(|(k, v)| format!("{}{v}", pad(k))))
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
        .params
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
