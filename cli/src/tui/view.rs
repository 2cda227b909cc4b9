//! Rendering: a title bar, the parameter panel with read-outs, three charts (Pr(σ*), a_r(p*),
//! ū(p*)) and a status bar; the help and preset overlays; a "terminal too small" screen.
//! Pure function of the [`App`]; every chart goes through [`super::plot`].

use super::app::{App, GfmdState, Overlay, Param};
use super::charts::{self, ChartModel, Draw, Role, Series};
use super::keys;
use super::plot;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Block, Chart, Clear, Dataset, GraphType, Paragraph, Wrap};
use ratatui::Frame;

/// Smallest usable terminal.
pub const MIN_SIZE: (u16, u16) = (60, 20);

/// How long a computation runs before the spinner shows.
const SPINNER_DELAY: std::time::Duration = std::time::Duration::from_millis(150);

const SPINNER: [&str; 8] = ["⠋", "⠙", "⠹", "⠸", "⠼", "⠴", "⠦", "⠧"];

/// Colours (Okabe–Ito, colour-blind safe) or plain styles under `NO_COLOR`.
#[derive(Debug, Clone, Copy)]
pub struct Palette {
    color: bool,
}

impl Palette {
    fn fg(&self, r: u8, g: u8, b: u8) -> Style {
        if self.color {
            Style::default().fg(Color::Rgb(r, g, b))
        } else {
            Style::default()
        }
    }
    /// The theory curve (blue).
    pub fn theory(&self) -> Style {
        self.fg(0, 114, 178)
    }
    /// Reference curves (orange).
    pub fn reference(&self) -> Style {
        self.fg(230, 159, 0)
    }
    /// The current point (vermillion).
    pub fn current(&self) -> Style {
        self.fg(213, 94, 0)
    }
    /// The adhesionless comparison (bluish green).
    pub fn compare(&self) -> Style {
        self.fg(0, 158, 115)
    }
    /// The −σ_a* wall (reddish purple).
    pub fn wall(&self) -> Style {
        self.fg(204, 121, 167)
    }
    /// Guide lines (sky blue).
    pub fn guide(&self) -> Style {
        self.fg(86, 180, 233)
    }
    /// GFMD results (yellow; also told apart by the ▀ marker).
    pub fn gfmd(&self) -> Style {
        self.fg(240, 228, 66)
    }
    /// Errors.
    pub fn error(&self) -> Style {
        self.fg(213, 94, 0).add_modifier(Modifier::BOLD)
    }
    /// Plain text (the reference points).
    pub fn text(&self) -> Style {
        Style::default()
    }
    /// Dim text.
    pub fn dim(&self) -> Style {
        if self.color {
            Style::default().fg(Color::Gray)
        } else {
            Style::default()
        }
    }
}

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
    let is_hint =
        app.edit.is_none() && app.message.is_none() && app.compute_error().is_none() && app.compute_warning().is_none();
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
        Overlay::Help => draw_help(f, area, pal),
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
        Span::raw(format!("· {} · {} ", app.preset.name, app.scene.model.label())),
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

/// A value with `n` significant digits, compact.
pub fn sig(x: f64, n: usize) -> String {
    if !x.is_finite() {
        return plot::format_number(x);
    }
    if x == 0.0 {
        return "0".into();
    }
    let e = x.abs().log10().floor() as i32;
    if (-3..5).contains(&e) {
        let d = (n as i32 - 1 - e).max(0) as usize;
        format!("{x:.d$}")
    } else {
        format!("{x:.*e}", n.saturating_sub(1))
    }
}

fn param_value(app: &App, p: Param) -> String {
    let s = &app.scene;
    let m = &s.model;
    match p {
        Param::Preset => app.preset.name.clone(),
        Param::Model => m.label(),
        Param::Pressure => sig(s.pressure, 4),
        Param::Thickness => {
            if s.thickness_qr.is_infinite() {
                "∞".into()
            } else {
                sig(s.thickness_qr, 4)
            }
        }
        Param::Gamma => {
            if s.gamma == 0.0 {
                "0 (off)".into()
            } else {
                sig(s.gamma, 4)
            }
        }
        Param::C1 => sig(m.c1, 4),
        Param::C2 => sig(m.c2, 4),
        Param::Alpha => sig(m.alpha, 4),
        Param::KGriffith => sig(m.k_griffith, 4),
        Param::Cap => (if m.cap { "yes" } else { "no" }).into(),
    }
}

fn draw_panel(f: &mut Frame, area: Rect, app: &App, pal: Palette) {
    let mut lines: Vec<Line> = Vec::new();
    let sel = app.selected_param();
    for p in app.params() {
        let is_sel = p == sel;
        let value = match (&app.edit, is_sel) {
            (Some(buf), true) => format!("{buf}▏"),
            _ => param_value(app, p),
        };
        let text = format!("{}{}{}", if is_sel { "▶" } else { " " }, pad(p.label(), 9), value);
        let style = if is_sel {
            Style::default().add_modifier(Modifier::REVERSED)
        } else {
            Style::default()
        };
        lines.push(Line::from(Span::styled(text, style)));
    }
    lines.push(Line::from(Span::styled("─ results ─", pal.dim())));
    let pt = app.point.as_ref().and_then(|r| r.as_ref().ok());
    let dash = || "–".to_string();
    // values of an earlier scene stay while the new one computes: dimmed and marked ⋯
    let stale_point = app.point_is_stale() && pt.is_some();
    let stale_gap = app.gap_is_stale();
    let mut row_styled = |k: &str, v: String, stale: bool| {
        if stale {
            lines.push(Line::from(Span::styled(format!(" {}{v} ⋯", pad(k, 9)), pal.dim())));
        } else {
            lines.push(Line::from(format!(" {}{v}", pad(k, 9))));
        }
    };
    row_styled("a_r", pt.map_or_else(dash, |p| sig(p.a_r, 4)), stale_point);
    row_styled(
        "σ̄_c*",
        pt.map_or_else(dash, |p| sig(p.mean_contact_stress, 4)),
        stale_point,
    );
    let gap = match &app.gap {
        Some(Ok(g)) => sig(*g, 4),
        _ => dash(),
    };
    row_styled("ū/h_rms", gap, stale_gap && app.gap.is_some());
    row_styled("γ̃_glo", sig(app.scene.gamma_glo(), 3), false);
    let state = match &app.point {
        _ if stale_point || (app.busy && app.point.is_none()) => "computing…".to_string(),
        Some(Ok(p)) if p.preview => format!("{} · refining…", p.branch),
        Some(Ok(p)) => p.branch.clone(),
        Some(Err(_)) => "failed (see below)".into(),
        None => dash(),
    };
    row_styled("state", state, false);
    if let Some(p) = pt {
        for (k, v) in &p.extra {
            row_styled(k, v.clone(), stale_point);
        }
        // hysteresis: every branch at this load, ◀ the one shown
        for b in &p.branches {
            let mark = if b.shown { " ◀" } else { "" };
            let stab = if b.stable || b.name == "unstable" {
                ""
            } else {
                " (unstable)"
            };
            let text = format!(" {}{}{stab}{mark}", pad(&b.name, 10), sig(b.a_r, 4));
            let style = if stale_point { pal.dim() } else { Style::default() };
            lines.push(Line::from(Span::styled(text, style)));
        }
    }
    let mut row = |k: &str, v: String| lines.push(Line::from(format!(" {}{v}", pad(k, 9))));
    row(
        "err a_r",
        pt.map_or_else(dash, |p| {
            if p.error_estimate.is_finite() {
                format!("{:.1e}", p.error_estimate)
            } else {
                dash()
            }
        }),
    );
    match &app.gfmd {
        GfmdState::Idle => {}
        GfmdState::Running {
            iteration, residual, ..
        } => {
            let res = if residual.is_finite() {
                format!(", res {residual:.0e}")
            } else {
                String::new()
            };
            row(
                "GFMD",
                format!("{} {iteration} it{res}", SPINNER[app.spinner % SPINNER.len()]),
            );
        }
        GfmdState::Done { result: Err(e), .. } => row("GFMD", format!("failed: {e}")),
        GfmdState::Done { result: Ok(v), .. } => {
            if app.gfmd_for_scene().is_some() {
                row("GFMD a_r", sig(v.a_r, 4));
                row("GFMD σ̄c", sig(v.mean_contact_stress, 4));
                let th = v.theory_a_r.map_or("–".into(), |t| sig(t, 4));
                row("map th.", format!("{th} (N={})", v.grid));
                for (k, val) in &v.invariants {
                    row(k, val.clone());
                }
            } else {
                row("GFMD", "other scene (g reruns)".into());
            }
        }
    }
    row(
        "time",
        match pt {
            Some(p) if app.show_timing => format_time(p.elapsed_s),
            Some(_) => "(hidden)".into(),
            None => dash(),
        },
    );
    // the scene in physical units (shown when the panel is tall enough)
    let sc = &app.scene;
    lines.push(Line::from(Span::styled("─ scene ─", pal.dim())));
    for (k, v) in [
        ("p", si(sc.pressure * sc.stress_unit(), "Pa")),
        ("E*", si(sc.modulus, "Pa")),
        ("h_rms", si(sc.spectrum.rms_height(), "m")),
        ("ḡ", sig(sc.rms_gradient(), 4)),
        ("λ_r/λ_s", sig(sc.spectrum.q_s() / sc.spectrum.q_r(), 4)),
    ] {
        lines.push(Line::from(format!(" {}{v}", pad(k, 9))));
    }
    let block = Block::bordered().title(" parameters ");
    f.render_widget(Paragraph::new(lines).block(block), area);
}

/// A value with an SI prefix: 250.0 kPa, 0.7766 µm.
pub fn si(x: f64, unit: &str) -> String {
    if !x.is_finite() || x == 0.0 {
        return format!("{} {unit}", plot::format_number(x));
    }
    const PREFIXES: [(f64, &str); 9] = [
        (1e12, "T"),
        (1e9, "G"),
        (1e6, "M"),
        (1e3, "k"),
        (1.0, ""),
        (1e-3, "m"),
        (1e-6, "µ"),
        (1e-9, "n"),
        (1e-12, "p"),
    ];
    let a = x.abs();
    // a pressure below 1 Pa is written without prefix: "mPa" beside "MPa" misleads
    let smallest = if unit == "Pa" { 1.0 } else { 1e-12 };
    let (f, p) = PREFIXES
        .iter()
        .find(|(f, _)| a >= *f && *f >= smallest)
        .copied()
        .unwrap_or((smallest, if unit == "Pa" { "" } else { "p" }));
    let v = x / f;
    let text = if (1e-3..1e4).contains(&v.abs()) {
        trim_zeros(&sig(v, 4))
    } else {
        sig(v, 3)
    };
    format!("{text} {p}{unit}")
}

/// "250.0" → "250", "0.7770" → "0.777" (numbers without an exponent only).
fn trim_zeros(s: &str) -> String {
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// `s` padded with spaces to `w` display columns (combining accents take none).
fn pad(s: &str, w: usize) -> String {
    let n = Span::raw(s).width();
    format!("{s}{}", " ".repeat(w.saturating_sub(n)))
}

fn format_time(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.0} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.1} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
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
        _ => pal.wall(),
    }
}

/// Marker of model slot `i`: told apart without colour too.
const MODEL_MARKERS: [Marker; 5] = [
    Marker::Dot,
    Marker::Bar,
    Marker::Braille,
    Marker::Block,
    Marker::HalfBlock,
];

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
        Role::Model(i) => (model_style(pal, i), MODEL_MARKERS[i.min(4)], graph),
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
        Role::Wall => (pal.wall(), Marker::Bar, GraphType::Line),
        Role::Unloading => (pal.wall(), Marker::Dot, GraphType::Line),
        Role::JumpIn => (pal.current(), Marker::Bar, GraphType::Line),
        Role::PullOff => (pal.wall(), Marker::Bar, GraphType::Line),
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
            let y = inner.y + inner.height / 2;
            let h = (inner.y + inner.height - y).min(3);
            f.render_widget(
                Paragraph::new(msg.clone()).centered().wrap(Wrap { trim: true }),
                Rect::new(inner.x, y.saturating_sub(h / 2), inner.width, h),
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

/// Eq. (18) of \[S\] (see [`asperity::theory::closed_form::eq18_area`]).
pub fn eq18(p: f64) -> f64 {
    asperity::theory::closed_form::eq18_area(p)
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

fn draw_help(f: &mut Frame, area: Rect, pal: Palette) {
    let mut lines: Vec<Line> = help_lines().into_iter().map(Line::from).collect();
    lines.push(Line::from(Span::styled("any key closes this help", pal.dim())));
    let w = lines.iter().map(|l| l.width()).max().unwrap_or(20) as u16 + 4;
    let r = popup(area, w, lines.len() as u16 + 2);
    f.render_widget(Clear, r);
    f.render_widget(Paragraph::new(lines).block(Block::bordered().title(" keys ")), r);
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
