//! The terminal explorer (`asperity`, `asperity tui --preset P`).
//!
//! State, update, effects — each in files that show it (no module imports one above it):
//!
//! - state: [`state`] (the scene, the knobs, the charts, the results shown: plain data),
//!   [`knobs`] (the panel's parameters and their pure stepping), [`kinds`] (the chart kinds),
//!   [`pins`] (pinned curves and their names),
//!   [`protocol`] (requests, replies and cache keys of the worker), [`tour`] (teaching tours,
//!   TOML files in `tours/`), [`caption`] (a caption's checked references to looks and
//!   keys), [`tour_check`] (a caption's claims as data), [`data`] (the plain data of engine results), [`progress`] (the GFMD job's phases,
//!   progress reports and the estimate of the time left).
//! - update: [`update`] (a key or a reply → the next state plus effects), [`history`] (the
//!   branch of a hysteresis the user's path has reached), [`turn`] (a knob
//!   stepped on its grid or typed), [`models`] (the model picked or cycled), [`update_gfmd`]
//!   (`g` and the GFMD job's replies), [`keys`] (the key table, used for dispatch and for the
//!   `?` help).
//! - effects: [`command`] (the work an update asks for, one enum the event loop runs),
//!   [`worker`] (the compute thread: generations, cancellation, caches), [`jobs`]
//!   (the engine jobs: point, sweeps, GFMD), [`effects`] (the files of `e` and `s`),
//!   [`export`] (CSV + TOML, SVG + PNG).
//! - drawing: [`charts`], [`chart_model`], [`charts_load`] (the charts as plain data, drawn by
//!   [`view`] and saved by `s`), [`layout`] (where the panels go), [`view`], [`legend`] (a chart's
//!   key), [`panel`], [`palette`] (the terminal styles of [`crate::looks`]' table), [`plot`] (the
//!   chart workarounds: log axes, NaN, labels, bounds), [`words`] (numbers and errors in words).
//! - [`app`]: the state under the name the front ends use.
//!
//! Only [`worker`], [`jobs`] and [`data`] call the engine (`cli/tests/architecture.rs`).
//!
//! The event loop blocks on one channel that carries key/resize events (from an input
//! thread) and worker replies; it redraws after each batch of messages, and ticks (for the
//! spinner, and the GFMD job's clock) only while the worker is busy or GFMD runs, so an idle
//! explorer uses no CPU. The terminal is
//! restored on every exit path: a drop guard on return, ratatui's panic hook on panic.
//!
//! `ASPERITY_PANIC_KEY=C` makes the key C panic (for the test that the terminal is restored
//! after a panic).
//!
//! `ASPERITY_TRACE=FILE` appends lines per generation with the time from the key press to the
//! first frame showing the current point (`point_drawn_ms`), the load charts of the current
//! scene (`charts_drawn_ms`: an adhesive scene's preview sweep, see `worker::PREVIEW_POINTS`),
//! the load charts from the full sweep (`charts_final_ms`), and the frame after which nothing
//! is left to compute (`all_drawn_ms`: the point refined to full accuracy, the other charts).

pub mod charts;
pub mod drive;
pub mod effects;
pub mod model;
pub mod update;
pub mod view;

/// The state under the names the front ends use.
pub use model::{app, tour};

use asperity::error::{Error, Result};
use asperity::input::preset::Preset;
use effects::{engine as jobs, worker::Worker};
use model::app::{self as app_state, App};
use model::command::Command;
use model::protocol::{self, Reply};
use ratatui::crossterm::event::{self, Event, KeyEventKind};
use std::io::Write;
use std::sync::mpsc::{channel, RecvTimeoutError};
use std::time::{Duration, Instant};

/// Spinner period while busy.
const TICK: Duration = Duration::from_millis(100);

enum Msg {
    Input(Event),
    Reply(Box<Reply>),
    InputClosed,
}

/// Restores the terminal when dropped (every return path of [`run`]).
struct TerminalGuard;

impl Drop for TerminalGuard {
    fn drop(&mut self) {
        ratatui::restore();
    }
}

/// Whether colour is wanted: not when `NO_COLOR` is set to anything non-empty.
pub fn use_color() -> bool {
    std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// Latency trace (see the module docs).
struct Trace {
    file: Option<std::fs::File>,
    started: Option<(u64, Instant)>,
    point_logged: bool,
    charts_logged: bool,
    final_logged: bool,
}

impl Trace {
    fn new() -> Trace {
        let file = std::env::var_os("ASPERITY_TRACE")
            .and_then(|p| std::fs::OpenOptions::new().create(true).append(true).open(p).ok());
        Trace {
            file,
            started: None,
            point_logged: false,
            charts_logged: false,
            final_logged: false,
        }
    }

    fn after_draw(&mut self, app: &App) {
        let (Some(f), Some((gen, t0))) = (self.file.as_mut(), self.started) else {
            return;
        };
        if gen != app.jobs.gen {
            return;
        }
        let ms = t0.elapsed().as_secs_f64() * 1e3;
        if !self.point_logged && app.results.point.is_some() && app.results.point_gen >= gen {
            let _ = writeln!(f, "gen {gen} point_drawn_ms {ms:.2}");
            self.point_logged = true;
        }
        let load_key = protocol::sweep_key(&app.params.source, &app.params.scene, app.range());
        let shown = app.results.point_gen >= gen && app.results.sweep_shown.as_ref() == Some(&load_key);
        if !self.charts_logged && shown {
            let _ = writeln!(f, "gen {gen} charts_drawn_ms {ms:.2}");
            self.charts_logged = true;
        }
        let preview = app
            .results
            .sweep
            .as_ref()
            .is_some_and(|s| s.as_ref().is_ok_and(|s| s.preview));
        if !self.final_logged && shown && !preview {
            let _ = writeln!(f, "gen {gen} charts_final_ms {ms:.2}");
            self.final_logged = true;
        }
        if !app.jobs.busy {
            let _ = writeln!(f, "gen {gen} all_drawn_ms {ms:.2}");
            self.started = None;
        }
    }
}

/// Opens the explorer on `preset` (resolved from `source`) and runs until the user quits.
pub fn run(source: &str, preset: Preset) -> Result<()> {
    run_app(App::new(source, preset)?)
}

/// Runs the explorer on a prepared [`App`] (a scene from flags, a tour) until the user quits.
pub fn run_app(mut app: App) -> Result<()> {
    app.ui.color = use_color();
    let (tx, rx) = channel::<Msg>();
    let reply_tx = tx.clone();
    let reply_tx_for_gfmd = tx.clone();
    let worker = Worker::spawn(move |r| {
        let _ = reply_tx.send(Msg::Reply(Box::new(r)));
    })
    .map_err(|e| Error::io("start the worker thread", e))?;

    let _guard = TerminalGuard;
    let mut terminal = ratatui::try_init().map_err(|e| Error::io("open the terminal", e))?;
    std::thread::Builder::new()
        .name("asperity-input".into())
        .spawn(move || loop {
            match event::read() {
                Ok(ev) => {
                    if tx.send(Msg::Input(ev)).is_err() {
                        return;
                    }
                }
                Err(_) => {
                    let _ = tx.send(Msg::InputClosed);
                    return;
                }
            }
        })
        .map_err(|e| Error::io("start the input thread", e))?;

    let gfmd_tx = reply_tx_for_gfmd;
    let mut trace = Trace::new();
    let panic_key = std::env::var("ASPERITY_PANIC_KEY").ok().and_then(|k| k.chars().next());
    loop {
        // the one route out of the update: its commands, run in order
        for cmd in app.take_commands() {
            match cmd {
                Command::Compute(req) => {
                    if trace.started.is_none_or(|(g, _)| g != req.gen) && trace.file.is_some() {
                        trace.started = Some((req.gen, Instant::now()));
                        trace.point_logged = false;
                        trace.charts_logged = false;
                        trace.final_logged = false;
                    }
                    // a point already current stays on screen until replaced
                    worker.submit(req);
                }
                Command::StartGfmd { id, scene, cancel } => {
                    let tx = gfmd_tx.clone();
                    let setup = jobs::gfmd_setup(&app.params.preset, &scene, app.map_of(&scene));
                    app.ui.message = Some(app_state::Message {
                        text: format!("GFMD started on a {0}x{0} grid (g cancels)", jobs::grid_side(&setup)),
                        error: false,
                    });
                    jobs::spawn_gfmd(id, setup, cancel, move |r| {
                        let _ = tx.send(Msg::Reply(Box::new(r)));
                    })
                    .map_err(|e| Error::io("start the GFMD thread", e))?;
                }
                Command::Export | Command::SaveCharts => effects::files::run(&mut app, &cmd),
                Command::Quit => return Ok(()),
            }
        }
        terminal
            .draw(|f| view::draw(f, &app))
            .map_err(|e| Error::io("draw", e))?;
        trace.after_draw(&app);
        // block until something happens (tick only while busy or playing)
        let first = if app.animating() {
            match rx.recv_timeout(TICK) {
                Ok(m) => Some(m),
                Err(RecvTimeoutError::Timeout) => None,
                Err(RecvTimeoutError::Disconnected) => return Ok(()),
            }
        } else {
            match rx.recv() {
                Ok(m) => Some(m),
                Err(_) => return Ok(()),
            }
        };
        let Some(first) = first else {
            app.tick();
            continue;
        };
        // handle everything already queued before the next frame
        let mut next = Some(first);
        while let Some(msg) = next {
            match msg {
                Msg::Input(Event::Key(k)) if k.kind != KeyEventKind::Release => {
                    let t0 = Instant::now();
                    if panic_key.is_some_and(|c| k.code == event::KeyCode::Char(c)) {
                        panic!("ASPERITY_PANIC_KEY pressed");
                    }
                    app.on_key(k);
                    if app.has_pending() {
                        trace.started = Some((app.jobs.gen + 1, t0));
                        trace.point_logged = false;
                        trace.charts_logged = false;
                        trace.final_logged = false;
                    }
                }
                Msg::Input(_) => {}
                Msg::Reply(r) => app.on_reply(*r),
                Msg::InputClosed => return Ok(()),
            }
            if app.ui.quit {
                break;
            }
            next = rx.try_recv().ok();
        }
    }
}
