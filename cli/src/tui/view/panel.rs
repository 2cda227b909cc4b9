//! The parameter panel: the knobs, the read-outs of the current point (a_r, σ̄_c*, ū/h_rms,
//! γ̃_glo, convergence, error, the trust read-out, time), the branches of a hysteresis window, the GFMD numbers and
//! the scene in physical units.

use crate::numfmt::sig;
use crate::tui::base::progress::format_secs;
use crate::tui::model::app::{App, GfmdState, Param};
use crate::tui::view::palette::{Palette, SPINNER};
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph};
use ratatui::Frame;

fn param_value(app: &App, p: Param) -> String {
    let s = &app.params.scene;
    let m = &s.model();
    match p {
        Param::Preset => app.params.preset.name.clone(),
        Param::Model => m.label(),
        Param::Pressure => sig(s.pressure(), 4),
        Param::Thickness => {
            if s.thickness_qr().is_infinite() {
                "∞".into()
            } else {
                sig(s.thickness_qr(), 4)
            }
        }
        Param::Gamma => {
            if s.surface_energy_j_m2() == 0.0 {
                "0 (off)".into()
            } else {
                sig(s.surface_energy_j_m2(), 4)
            }
        }
        Param::C1 => sig(m.c1, 4),
        Param::C2 => sig(m.c2, 4),
        Param::Alpha => sig(m.alpha, 4),
        Param::KGriffith => sig(m.k_griffith, 4),
        Param::Cap => (if m.cap { "yes" } else { "no" }).into(),
    }
}

pub fn draw_panel(f: &mut Frame, area: Rect, app: &App, pal: Palette) {
    let mut lines: Vec<Line> = Vec::new();
    let sel = app.selected_param();
    for p in app.knob_rows() {
        let is_sel = p == sel;
        let value = match (&app.ui.edit, is_sel) {
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
    if let Some(name) = surface_name(&app.params.scene) {
        lines.push(Line::from(format!(" {}{name}", pad("surface", 9))));
    }
    lines.push(Line::from(Span::styled("─ results ─", pal.dim())));
    let pt = app.results.point().and_then(|r| r.as_ref().ok());
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
    // the branch the load history has reached: every row below is that branch's (the point
    // evaluated on the unloading branch where the path is on it)
    use crate::tui::charts::shared as sh;
    let on_unloading = sh::on_unloading(app);
    let shown = sh::shown_point(app);
    let a_r = sh::path_a_r(app);
    row_styled("a_r", a_r.map_or_else(dash, |a| sig(a, 4)), stale_point);
    // inside a hysteresis window: the branch the load history reached, next to its a_r
    // (the branch alone where the reason does not fit: the status line said it)
    if pt.is_some_and(|p| !p.branches.is_empty()) {
        let label = app.params.history.label();
        let room = usize::from(area.width).saturating_sub(12);
        let v = if label.chars().count() <= room {
            label
        } else {
            app.params.history.on.name().to_string()
        };
        row_styled("path", v, stale_point);
    }
    // σ̄_c* = ∫σ*Pr dσ*/a_r of the branch the path is on
    let stress = sh::path_stress(app).map_or_else(dash, |s| sig(s, 4));
    row_styled("σ̄_c*", stress, stale_point);
    let gap = sh::path_gap(app).map_or_else(dash, |g| sig(g, 4));
    row_styled("ū/h_rms", gap, stale_gap && app.results.gap().is_some());
    // with adhesion: the bracket of the gap of the branch shown (docs/physics.md §5.1)
    if app.params.scene.is_adhesive() {
        if let Some((lo, hi)) = sh::path_gap_bracket(app) {
            // same a_r … same load
            let k = if on_unloading { "ū unload" } else { "ū load" };
            row_styled(k, format!("{}–{}", sig(lo, 3), sig(hi, 3)), stale_gap);
        }
    }
    row_styled("γ̃_glo", sig(app.params.scene.gamma_glo(), 3), false);
    if app.params.scene.is_adhesive() {
        row_styled("μ_T", sig(app.params.scene.tabor(), 3), false);
    }
    let state = match (app.results.point(), shown) {
        _ if stale_point || (app.jobs.busy() && app.results.point().is_none()) => "computing…".to_string(),
        (Some(Ok(_)), Some(p)) if p.preview => format!("{} · refining…", p.branch),
        (Some(Ok(_)), Some(p)) => p.branch.clone(),
        (Some(Err(_)), _) => "failed (see below)".into(),
        _ => dash(),
    };
    row_styled("state", state, false);
    if let Some(p) = shown {
        for (k, v) in &p.extra {
            row_styled(k, v.clone(), stale_point);
        }
    }
    if let Some(p) = pt {
        let style = if stale_point { pal.dim() } else { Style::default() };
        lines.extend(branch_lines(&p.branches, on_unloading, style));
    }
    let mut row = |k: &str, v: String| lines.push(Line::from(format!(" {}{v}", pad(k, 9))));
    row(
        "err a_r",
        shown.map_or_else(dash, |p| {
            if p.error_estimate.is_finite() {
                sig(p.error_estimate, 2)
            } else {
                dash()
            }
        }),
    );
    row("trust", trust_of(shown));
    for (k, v) in gfmd_rows(app) {
        row(&k, v);
    }
    row(
        "time",
        match pt {
            Some(p) if app.ui.show_timing => format_secs(p.elapsed_s),
            Some(_) => "(hidden)".into(),
            None => dash(),
        },
    );
    // the scene in physical units (shown when the panel is tall enough)
    lines.push(Line::from(Span::styled("─ scene ─", pal.dim())));
    lines.extend(scene_rows(&app.params.scene));
    let block = Block::bordered().title(" parameters ");
    f.render_widget(Paragraph::new(lines).block(block), area);
}

/// A hysteresis: every branch at this load, ◀ the one the load history is on.
fn branch_lines(
    branches: &[crate::tui::base::data::BranchRow],
    on_unloading: bool,
    style: Style,
) -> Vec<Line<'static>> {
    branches
        .iter()
        .map(|b| {
            let followed = if on_unloading { b.name == "unloading" } else { b.shown };
            let mark = if followed { " ◀" } else { "" };
            let stab = if b.stable || b.name == "unstable" {
                ""
            } else {
                " (unstable)"
            };
            let text = format!(" {}{}{stab}{mark}", pad(&b.name, 10), sig(b.a_r, 4));
            Line::from(Span::styled(text, style))
        })
        .collect()
}

/// The trust row: computed with the point by the worker, not while drawing (– until then).
fn trust_of(shown: Option<&crate::tui::base::data::PointData>) -> String {
    match shown.map(|p| p.trust.as_str()) {
        Some(t) if !t.is_empty() => t.to_string(),
        _ => "–".to_string(),
    }
}

/// The scene in physical units: p, E*, h_rms, ḡ, λ_r/λ_s.
fn scene_rows(sc: &asperity::input::scene::Scene) -> Vec<Line<'static>> {
    [
        ("p", si(sc.pressure() * sc.stress_unit(), "Pa")),
        ("E*", si(sc.contact_modulus_pa(), "Pa")),
        ("h_rms", si(sc.spectrum().rms_height(), "m")),
        ("ḡ", sig(sc.rms_gradient(), 4)),
        ("λ_r/λ_s", sig(sc.spectrum().q_s() / sc.spectrum().q_r(), 4)),
    ]
    .into_iter()
    .map(|(k, v)| Line::from(format!(" {}{v}", pad(k, 9))))
    .collect()
}

/// The panel's GFMD rows: while it runs the phase, the solver's steps and residual, the time
/// and the time left; when done its time and numbers (for the scene shown), or why it failed.
fn gfmd_rows(app: &App) -> Vec<(String, String)> {
    let mut v: Vec<(String, String)> = Vec::new();
    let mut row = |k: &str, val: String| v.push((k.to_string(), val));
    match app.jobs.gfmd() {
        GfmdState::Idle => {}
        GfmdState::Running { progress, started, .. } => {
            row(
                "GFMD",
                format!("{} {}", SPINNER[app.ui.spinner % SPINNER.len()], progress.phase.label()),
            );
            if let Some(p) = progress.phase.load() {
                row("  at p*", sig(p, 3));
            }
            if let Some(st) = progress.steps_text() {
                row("  steps", st);
            }
            if app.ui.show_timing {
                let t = app.ui.elapsed_s(*started);
                row("  time", format_secs(t));
                row(
                    "  left",
                    progress
                        .left_at(t)
                        .map_or_else(|| "estimating".into(), |l| format!("about {}", format_secs(l))),
                );
            }
        }
        GfmdState::Done { result, elapsed_s, .. } => {
            let took = if app.ui.show_timing {
                format!(" in {}", format_secs(*elapsed_s))
            } else {
                String::new()
            };
            match result {
                Err(e) => row("GFMD", format!("failed: {e}")),
                Ok(r) => {
                    row("GFMD", format!("done{took}"));
                    if app.gfmd_for_scene().is_some() {
                        row("GFMD a_r", sig(r.a_r, 4));
                        row("GFMD σ̄c", sig(r.mean_contact_stress, 4));
                        let th = r.theory_a_r.map_or("–".into(), |t| sig(t, 4));
                        row("map th.", format!("{th} (N={})", r.grid));
                        for (k, val) in &r.invariants {
                            row(k, val.clone());
                        }
                        if let Some(e) = &r.sweep_error {
                            row("sweep", format!("failed: {e}"));
                        }
                    } else {
                        row("  ", "other scene (g reruns)".into());
                    }
                }
            }
        }
    }
    v
}

pub use crate::tui::base::words::{surface_name, surface_name_of};

/// A value with an SI prefix: 250.0 kPa, 0.7766 µm.
pub fn si(x: f64, unit: &str) -> String {
    if !x.is_finite() || x == 0.0 {
        return format!("{} {unit}", crate::numfmt::short(x));
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
    format!("{} {p}{unit}", crate::numfmt::format(v, 4, true))
}

/// `s` padded with spaces to `w` display columns (combining accents take none).
fn pad(s: &str, w: usize) -> String {
    let n = Span::raw(s).width();
    format!("{s}{}", " ".repeat(w.saturating_sub(n)))
}
