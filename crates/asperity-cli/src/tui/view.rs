//! Rendering: a title bar, the parameter panel with read-outs, three charts (Pr(σ*), a_r(p*),
//! ū(p*)) and a status bar; the help and preset overlays; a "terminal too small" screen.
//! Pure function of the [`App`]; every chart goes through [`super::plot`].

use super::app::{App, AreaMode, GfmdState, Overlay, Param};
use super::keys;
use super::plot::{self, Scale};
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
    // messages may take two rows; the key hint is cut instead
    let is_hint = app.edit.is_none() && app.message.is_none() && app.compute_error().is_none();
    let status_rows = if !is_hint && status_line.width() > area.width as usize {
        2
    } else {
        1
    };
    let [title, body, status] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(status_rows),
    ])
    .areas(area);
    draw_title(f, title, app, pal);
    f.render_widget(Paragraph::new(status_line).wrap(Wrap { trim: false }), status);
    let panel_w = match area.width {
        120.. => 34,
        80.. => 28,
        _ => 24,
    };
    let [panel, charts] = Layout::horizontal([Constraint::Length(panel_w), Constraint::Fill(1)]).areas(body);
    draw_panel(f, panel, app, pal);
    let [top, bottom] = Layout::vertical([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(charts);
    let [left, right] = Layout::horizontal([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(bottom);
    draw_pr(f, top, app, pal);
    draw_area(f, left, app, pal);
    draw_gap(f, right, app, pal);
    match app.overlay {
        Overlay::Help => draw_help(f, area, pal),
        Overlay::Presets(cursor) => draw_picker(f, area, app, cursor, pal),
        Overlay::None => {}
    }
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
    } else {
        Line::from(Span::styled(
            " ↑↓ pick  ←→ change  0-9 type  m model  p preset  a area  e export  r reset",
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
    let mut row = |k: &str, v: String| lines.push(Line::from(format!(" {}{v}", pad(k, 9))));
    row("a_r", pt.map_or_else(dash, |p| sig(p.a_r, 4)));
    row("σ̄_c*", pt.map_or_else(dash, |p| sig(p.mean_contact_stress, 4)));
    let gap = match &app.gap {
        Some(Ok(g)) if pt.is_some() => sig(*g, 4),
        _ => dash(),
    };
    row("ū/h_rms", gap);
    row("γ̃_glo", sig(app.scene.gamma_glo(), 3));
    row(
        "state",
        pt.map_or_else(|| if app.busy { "…".into() } else { dash() }, |p| p.branch.clone()),
    );
    if let Some(p) = pt {
        for (k, v) in &p.extra {
            row(k, v.clone());
        }
    }
    row("err a_r", pt.map_or_else(dash, |p| format!("{:.1e}", p.error_estimate)));
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
    let (f, p) = PREFIXES.iter().find(|(f, _)| a >= *f).copied().unwrap_or((1e-12, "p"));
    format!("{} {p}{unit}", sig(x / f, 4))
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

/// A drawable curve (owned points in plane coordinates).
struct Curve {
    points: Vec<(f64, f64)>,
    style: Style,
    marker: Marker,
    graph: GraphType,
}

/// Adds `data` (data coordinates) as one curve per drawable run.
fn add_runs(
    out: &mut Vec<Curve>,
    data: &[(f64, f64)],
    (xs, ys): (Scale, Scale),
    max_points: usize,
    (style, marker, graph): (Style, Marker, GraphType),
) {
    for run in plot::segments(data, xs, ys) {
        out.push(Curve {
            points: plot::decimate(&run, max_points),
            style,
            marker,
            graph,
        });
    }
}

/// A key entry for a chart title.
fn legend(sym: &str, name: &str, style: Style) -> Vec<Span<'static>> {
    vec![Span::styled(sym.to_string(), style), Span::raw(format!(" {name} "))]
}

#[allow(clippy::too_many_arguments)]
fn render_chart(
    f: &mut Frame,
    area: Rect,
    title: Vec<Span<'static>>,
    key: Vec<Span<'static>>,
    curves: &[Curve],
    xb: [f64; 2],
    yb: [f64; 2],
    xs: Scale,
    ys: Scale,
    empty: Option<String>,
) {
    let mut block = Block::bordered().title(Line::from(title));
    if !key.is_empty() {
        block = block.title_bottom(Line::from(key));
    }
    if let Some(msg) = empty {
        let inner = block.inner(area);
        f.render_widget(block, area);
        if inner.height > 0 {
            let y = inner.y + inner.height / 2;
            let msg = if msg.chars().count() > inner.width as usize {
                "no data".to_string()
            } else {
                msg
            };
            f.render_widget(Paragraph::new(msg).centered(), Rect::new(inner.x, y, inner.width, 1));
        }
        return;
    }
    let datasets: Vec<Dataset> = curves
        .iter()
        .map(|c| {
            Dataset::default()
                .data(&c.points)
                .style(c.style)
                .marker(c.marker)
                .graph_type(c.graph)
        })
        .collect();
    let three_x = area.width >= 36;
    let chart = Chart::new(datasets)
        .block(block)
        .x_axis(Axis::default().bounds(xb).labels(plot::axis_labels(xb, xs, three_x)))
        .y_axis(
            Axis::default()
                .bounds(yb)
                .labels(plot::axis_labels(yb, ys, area.height >= 12)),
        )
        .legend_position(None);
    f.render_widget(chart, area);
}

fn empty_message(app: &App, have_data: bool) -> Option<String> {
    if have_data {
        None
    } else if app.busy {
        Some("computing…".into())
    } else if app.compute_error().is_some() {
        Some("no data: see the status line".into())
    } else {
        Some("no data".into())
    }
}

fn draw_pr(f: &mut Frame, area: Rect, app: &App, pal: Palette) {
    let max_points = 4 * area.width as usize;
    let pt = app.point.as_ref().and_then(|r| r.as_ref().ok());
    let mut curves = Vec::new();
    let title = vec![Span::raw(format!(" Pr(σ*) at p* = {} ", sig(app.scene.pressure, 3)))];
    let mut key = Vec::new();
    if let Some(p) = pt {
        let (xs, ys) = (Scale::Linear, Scale::Linear);
        let compare = p.adhesionless.as_ref().filter(|_| app.compare);
        let gfmd = app.gfmd_for_scene();
        let mut runs: Vec<&[(f64, f64)]> = vec![&p.pr];
        if let Some(c) = compare {
            runs.push(c);
        }
        if let Some(g) = gfmd {
            runs.push(&g.pr);
        }
        let xb = plot::bounds(&runs, true, 0.0).unwrap_or([0.0, 1.0]);
        let xb = match p.wall {
            Some(w) if w.is_finite() => plot::guard(xb[0].min(w), xb[1].max(w)),
            _ => xb,
        };
        let ytop = plot::bounds(&runs, false, 0.0).map_or(1.0, |b| b[1]).max(0.0);
        let yb = plot::guard(0.0, ytop * 1.05);
        if let Some(c) = compare {
            add_runs(
                &mut curves,
                c,
                (xs, ys),
                max_points,
                (pal.compare(), Marker::Dot, GraphType::Line),
            );
            key.extend(legend("•", "γ_s=0", pal.compare()));
        }
        if xb[0] < 0.0 && xb[1] > 0.0 {
            // σ* = 0 separates tension from compression
            curves.push(Curve {
                points: plot::vertical(0.0, yb),
                style: pal.guide(),
                marker: Marker::Braille,
                graph: GraphType::Line,
            });
        }
        if let Some(w) = p.wall {
            curves.push(Curve {
                points: plot::vertical(w, yb),
                style: pal.wall(),
                marker: Marker::Bar,
                graph: GraphType::Line,
            });
            key.extend(legend("▄", "−σ_a*", pal.wall()));
        }
        if let Some(g) = gfmd {
            let pts: Vec<(f64, f64)> = g.pr.iter().copied().filter(|(_, d)| *d > 0.0).collect();
            curves.push(Curve {
                points: plot::decimate(&pts, max_points),
                style: pal.gfmd(),
                marker: Marker::HalfBlock,
                graph: GraphType::Scatter,
            });
            key.extend(legend("▀", "GFMD", pal.gfmd()));
        }
        add_runs(
            &mut curves,
            &p.pr,
            (xs, ys),
            max_points,
            (pal.theory(), Marker::Braille, GraphType::Line),
        );
        key.extend(legend("⣿", "theory", pal.theory()));
        render_chart(f, area, title, key, &curves, xb, yb, xs, ys, None);
    } else {
        render_chart(
            f,
            area,
            title,
            vec![],
            &[],
            [0.0, 1.0],
            [0.0, 1.0],
            Scale::Linear,
            Scale::Linear,
            empty_message(app, false),
        );
    }
}

/// Eq. (18) of \[S\]: a_r = erf(1.9p*)(1 − a₀²) + a₀³ with a₀ = erf(1.45p*) (adhesionless,
/// semi-infinite).
pub fn eq18(p: f64) -> f64 {
    asperity::theory::closed_form::eq18_area(p)
}

/// Whether eq. (18) describes the scene.
pub fn eq18_applies(app: &App) -> bool {
    app.scene.gamma == 0.0 && app.scene.thickness_qr.is_infinite()
}

fn current_marker(curves: &mut Vec<Curve>, pal: Palette, x: f64, y: Option<f64>, yb: [f64; 2]) {
    curves.insert(
        0,
        Curve {
            points: plot::vertical(x, yb),
            style: pal.guide(),
            marker: Marker::Braille,
            graph: GraphType::Line,
        },
    );
    if let Some(y) = y.filter(|y| y.is_finite()) {
        curves.push(Curve {
            points: vec![(x, y)],
            style: pal.current(),
            marker: Marker::Block,
            graph: GraphType::Scatter,
        });
    }
}

fn draw_area(f: &mut Frame, area: Rect, app: &App, pal: Palette) {
    let max_points = 4 * area.width as usize;
    let (xs, ys) = match app.area_mode {
        AreaMode::Log => (Scale::Log10, Scale::Log10),
        AreaMode::Ratio => (Scale::Log10, Scale::Linear),
    };
    let y_of = |p: f64, a: f64| match app.area_mode {
        AreaMode::Log => a,
        AreaMode::Ratio => a / p,
    };
    let title = vec![Span::raw(match app.area_mode {
        AreaMode::Log => " a_r(p*) ".to_string(),
        AreaMode::Ratio => " a_r/p* ".to_string(),
    })];
    let sw = app.sweep.as_ref().and_then(|r| r.as_ref().ok());
    let Some(sw) = sw else {
        render_chart(
            f,
            area,
            title,
            vec![],
            &[],
            [0.0, 1.0],
            [0.0, 1.0],
            xs,
            ys,
            empty_message(app, false),
        );
        return;
    };
    let theory: Vec<(f64, f64)> = sw.p.iter().zip(&sw.a_r).map(|(&p, &a)| (p, y_of(p, a))).collect();
    let reference: Vec<(f64, f64)> = if eq18_applies(app) {
        sw.p.iter().map(|&p| (p, y_of(p, eq18(p)))).collect()
    } else {
        Vec::new()
    };
    let mut curves = Vec::new();
    add_runs(
        &mut curves,
        &reference,
        (xs, ys),
        max_points,
        (pal.reference(), Marker::Dot, GraphType::Line),
    );
    add_runs(
        &mut curves,
        &theory,
        (xs, ys),
        max_points,
        (pal.theory(), Marker::Braille, GraphType::Line),
    );
    let all: Vec<&[(f64, f64)]> = curves.iter().map(|c| c.points.as_slice()).collect();
    let xb = plot::bounds(&all, true, 0.0).unwrap_or([0.0, 1.0]);
    let mut yb = plot::bounds(&all, false, 0.05).unwrap_or([0.0, 1.0]);
    match app.area_mode {
        AreaMode::Ratio => yb = plot::guard(0.0, yb[1]),
        // a_r <= 1: no padding above log10(1) = 0
        AreaMode::Log if yb[1] > 0.0 && yb[0] < 0.0 => yb = plot::guard(yb[0], 0.0),
        AreaMode::Log => {}
    }
    let p = app.scene.pressure;
    let pt = app.point.as_ref().and_then(|r| r.as_ref().ok());
    if let Some(x) = xs.forward(p) {
        let y = pt.and_then(|pt| ys.forward(y_of(p, pt.a_r)));
        current_marker(&mut curves, pal, x, y, yb);
    }
    let mut key = legend("⣿", "theory", pal.theory());
    if !reference.is_empty() {
        key.extend(legend("•", "eq.18", pal.reference()));
    }
    if let Some(g) = app.gfmd_for_scene() {
        // GFMD and the theory on GFMD's own (reduced) map: a second system, drawn apart from
        // the full scene's theory curve
        let pts: Vec<(f64, f64)> = std::iter::once((g.pressure, g.a_r))
            .chain(g.sweep.iter().map(|&(p, a, _)| (p, a)))
            .filter_map(|(p, a)| Some((xs.forward(p)?, ys.forward(y_of(p, a))?)))
            .collect();
        let th: Vec<(f64, f64)> = g
            .theory_sweep
            .iter()
            .filter_map(|&(p, a, _)| Some((xs.forward(p)?, ys.forward(y_of(p, a))?)))
            .collect();
        if th.len() > 1 {
            curves.push(Curve {
                points: th,
                style: pal.gfmd(),
                marker: Marker::Dot,
                graph: GraphType::Line,
            });
            key.extend(legend("•", "map th.", pal.gfmd()));
        }
        if !pts.is_empty() {
            curves.push(Curve {
                points: pts,
                style: pal.gfmd(),
                marker: Marker::HalfBlock,
                graph: GraphType::Scatter,
            });
            key.extend(legend("▀", "GFMD", pal.gfmd()));
        }
    }
    key.extend(legend("█", "p*", pal.current()));
    render_chart(f, area, title, key, &curves, xb, yb, xs, ys, None);
}

fn draw_gap(f: &mut Frame, area: Rect, app: &App, pal: Palette) {
    let max_points = 4 * area.width as usize;
    let (xs, ys) = (Scale::Log10, Scale::Linear);
    let title = vec![Span::raw(" ū/h_rms(p*) ")];
    let sw = app.sweep.as_ref().and_then(|r| r.as_ref().ok());
    let Some(sw) = sw else {
        render_chart(
            f,
            area,
            title,
            vec![],
            &[],
            [0.0, 1.0],
            [0.0, 1.0],
            xs,
            ys,
            empty_message(app, false),
        );
        return;
    };
    let theory: Vec<(f64, f64)> = sw.p.iter().copied().zip(sw.gap_rel.iter().copied()).collect();
    let mut curves = Vec::new();
    add_runs(
        &mut curves,
        &theory,
        (xs, ys),
        max_points,
        (pal.theory(), Marker::Braille, GraphType::Line),
    );
    let all: Vec<&[(f64, f64)]> = curves.iter().map(|c| c.points.as_slice()).collect();
    let xb = plot::bounds(&all, true, 0.0).unwrap_or([0.0, 1.0]);
    let ytop = plot::bounds(&all, false, 0.05).map_or(1.0, |b| b[1]);
    let yb = plot::guard(0.0, ytop);
    let p = app.scene.pressure;
    if let Some(x) = xs.forward(p) {
        let y = match &app.gap {
            Some(Ok(g)) => Some(*g),
            _ => None,
        };
        current_marker(&mut curves, pal, x, y, yb);
    }
    let mut key = legend("⣿", "theory", pal.theory());
    if let Some(g) = app.gfmd_for_scene() {
        let pts: Vec<(f64, f64)> = std::iter::once((g.pressure, g.gap_rel))
            .chain(g.sweep.iter().map(|&(p, _, u)| (p, u)))
            .filter_map(|(p, u)| Some((xs.forward(p)?, ys.forward(u)?)))
            .collect();
        let th: Vec<(f64, f64)> = g
            .theory_sweep
            .iter()
            .filter_map(|&(p, _, u)| Some((xs.forward(p)?, ys.forward(u)?)))
            .collect();
        if th.len() > 1 {
            curves.push(Curve {
                points: th,
                style: pal.gfmd(),
                marker: Marker::Dot,
                graph: GraphType::Line,
            });
            key.extend(legend("•", "map th.", pal.gfmd()));
        }
        curves.push(Curve {
            points: pts,
            style: pal.gfmd(),
            marker: Marker::HalfBlock,
            graph: GraphType::Scatter,
        });
        key.extend(legend("▀", "GFMD", pal.gfmd()));
    }
    key.extend(legend("█", "p*", pal.current()));
    render_chart(f, area, title, key, &curves, xb, yb, xs, ys, None);
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
