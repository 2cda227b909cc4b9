//! The terminal explorer (`asperity`, `asperity tui --preset P`).
//!
//! One typed update loop (the Elm shape), in folders that show it; no module imports one in a
//! folder above it (`cli/tests/architecture.rs` checks the arrows):
//!
//! - [`base`]: what the state is made of: the worker's protocol, the plain data of the
//!   engine's results, chart kinds, tours, the key table; imports nothing else of the explorer.
//! - [`model`]: the state as plain data, [`model::app::App`] in four parts (the scene's
//!   parameters, the UI, the results, the jobs), and the [`model::msg::Msg`]s and
//!   [`model::command::Command`]s that cross it; reads no file and no clock; reads `base`.
//! - [`charts`]: the charts as plain data, built from the state (drawn by the view, saved by
//!   `s`); reads the model.
//! - [`update`]: `update(state, msg) -> Vec<Command>`, pure; reads and changes the model.
//! - [`view`]: draws the state; reads the model and the charts.
//! - [`effects`]: runs the commands (the compute worker, GFMD threads, files read and
//!   written) and turns what they find into messages; reads the model.
//! - this module: the event loop, which feeds messages to the update, runs its commands and
//!   draws; [`drive`] does the same without a terminal (tests), [`trace`] times it.
//!
//! Only [`effects::worker`], [`effects::engine`] and [`base::data`] call the engine
//! (`cli/tests/architecture.rs`).
//!
//! The event loop blocks on one channel that carries key/resize events (from an input
//! thread) and worker and GFMD replies; it redraws after each batch of messages, and ticks (for the
//! spinner, and the GFMD job's clock) only while the worker is busy or GFMD runs, so an idle
//! explorer uses no CPU. The terminal is
//! restored on every exit path: a drop guard on return, ratatui's panic hook on a panic of the
//! event loop; a panic of another thread leaves the screen alone and reaches the panel as a
//! message (`effects::worker`, `ASPERITY_TEST_FAULT` injects one for the tests).
//!
//! `ASPERITY_PANIC_KEY=C` makes the key C panic (for the test that the terminal is restored
//! after a panic).
//!
//! `ASPERITY_TRACE=FILE` appends lines per generation with the time from the key press to the
//! first frame showing the current point (`point_drawn_ms`), the load charts of the current
//! scene (`charts_drawn_ms`: an adhesive scene's preview sweep, see `worker::PREVIEW_POINTS`),
//! the load charts from the full sweep (`charts_final_ms`), and the frame after which nothing
//! is left to compute (`all_drawn_ms`: the point refined to full accuracy, the other charts).

pub mod base;
pub mod charts;
pub mod drive;
pub mod effects;
pub mod model;
pub mod trace;
pub mod update;
pub mod view;

/// The state under the names the front ends use.
pub use base::tour;
pub use model::app;

use asperity::error::{Error, Result};
use asperity::input::preset::Preset;
use base::protocol::Reply;
use effects::worker::Worker;
use model::app::App;
use model::command::Command;
use model::msg::Msg;
use ratatui::crossterm::event::{self, Event, KeyEventKind};
use std::collections::VecDeque;
use std::sync::mpsc::{channel, RecvTimeoutError, Sender};
use std::time::{Duration, Instant};
use trace::Trace;

/// Spinner period while busy.
const TICK: Duration = Duration::from_millis(100);

/// What the loop's channel carries: the terminal's events and the threads' replies.
enum Incoming {
    Input(Event),
    Reply(Box<Reply>),
    InputClosed,
}

/// Restores the terminal when dropped (every return path of [`run`]): releases the mouse if
/// it was captured.
struct TerminalGuard {
    mouse: bool,
}

impl Drop for TerminalGuard {
    fn drop(&mut self) {
        if self.mouse {
            let _ = ratatui::crossterm::execute!(std::io::stdout(), event::DisableMouseCapture);
        }
        ratatui::restore();
        // the faults of other threads, held back while the screen was the explorer's
        if let Ok(mut held) = HELD_PANICS.lock() {
            for line in held.drain(..) {
                eprintln!("asperity: {line}");
            }
        }
    }
}

/// Panics of threads other than the event loop's (the worker, GFMD, rayon's), held while the
/// explorer owns the screen and printed once the terminal is restored (at most a few).
static HELD_PANICS: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());

/// Installs the explorer's panic hook over ratatui's (which restores the terminal, then
/// prints): a panic of the event loop's thread takes ratatui's hook, so the terminal is
/// restored before the message; a panic of another thread leaves the screen alone (its
/// fault reaches the panel as a message, see `effects::worker`) and is printed after the
/// explorer closes.
fn install_panic_hook() {
    let event_loop = std::thread::current().id();
    let restore_and_print = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if std::thread::current().id() == event_loop {
            if let Ok(mut held) = HELD_PANICS.lock() {
                held.clear();
            }
            restore_and_print(info);
        } else if let Ok(mut held) = HELD_PANICS.lock() {
            if held.len() < 4 {
                let name = std::thread::current().name().unwrap_or("a thread").to_string();
                held.push(format!("{name} failed: {info}").replace('\n', " "));
            }
        }
    }));
}

/// The update's message of a mouse event (`--mouse`): where a left click lands on the screen
/// drawn now ([`view::hit::hit`]); the wheel; None for the rest (moves, drags, other buttons).
fn pointer(app: &App, area: ratatui::layout::Rect, ev: event::MouseEvent) -> Option<Msg> {
    use event::{MouseButton, MouseEventKind};
    use model::msg::Pointer;
    let p = match ev.kind {
        MouseEventKind::Down(MouseButton::Left) => Pointer::Click(view::hit::hit(app, area, ev.column, ev.row)),
        MouseEventKind::ScrollUp => Pointer::WheelUp,
        MouseEventKind::ScrollDown => Pointer::WheelDown,
        _ => return None,
    };
    Some(Msg::Mouse(p))
}

/// Whether colour is wanted: not when `NO_COLOR` is set to anything non-empty.
pub fn use_color() -> bool {
    std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// Opens the explorer on `preset` (resolved from `source`) and runs until the user quits.
pub fn run(source: &str, preset: Preset) -> Result<()> {
    run_app(App::new(source, preset)?)
}

/// Starts the input thread: every terminal event goes to `tx`.
fn spawn_input(tx: Sender<Incoming>) -> Result<()> {
    std::thread::Builder::new()
        .name("asperity-input".into())
        .spawn(move || loop {
            match event::read() {
                Ok(ev) => {
                    if tx.send(Incoming::Input(ev)).is_err() {
                        return;
                    }
                }
                Err(_) => {
                    let _ = tx.send(Incoming::InputClosed);
                    return;
                }
            }
        })
        .map(|_| ())
        .map_err(|e| Error::io("start the input thread", e))
}

/// Runs the commands of the updates (the computation of the current scene first) and feeds
/// what the effects found back to the update, until nothing is left; true when one is `Quit`.
fn run_commands(
    app: &mut App,
    todo: &mut Vec<Command>,
    worker: &Worker,
    replies: &Sender<Incoming>,
    trace: &mut Trace,
) -> Result<bool> {
    let mut inbox = VecDeque::new();
    loop {
        let cmds: Vec<Command> = std::mem::take(todo);
        // a burst of updates computes once: the last computation asked for supersedes the rest
        let last = cmds.iter().rposition(|c| matches!(c, Command::Compute(_)));
        for (i, cmd) in cmds.into_iter().enumerate() {
            match cmd {
                Command::Compute(_) if Some(i) != last => {}
                Command::Compute(req) => {
                    if trace.started.is_none_or(|(g, _)| g != req.gen) && trace.file.is_some() {
                        trace.start(req.gen, Instant::now());
                    }
                    // a point already current stays on screen until replaced
                    worker.submit(req);
                }
                Command::Quit => return Ok(true),
                cmd @ Command::StartGfmd { .. } => {
                    let tx = replies.clone();
                    let started = effects::start_gfmd(cmd, move |r| {
                        let _ = tx.send(Incoming::Reply(Box::new(r)));
                    })?;
                    inbox.extend(started);
                }
                cmd => inbox.extend(effects::run_now(&cmd)),
            }
        }
        let Some(msg) = inbox.pop_front() else {
            return Ok(false);
        };
        todo.extend(update::update(app, msg));
    }
}

/// Runs the explorer on a prepared [`App`] (a scene from flags, a tour) until the user quits.
pub fn run_app(mut app: App) -> Result<()> {
    app.ui.color = use_color();
    let (tx, rx) = channel::<Incoming>();
    let reply_tx = tx.clone();
    let replies = tx.clone();
    let worker = Worker::spawn(move |r| {
        let _ = reply_tx.send(Incoming::Reply(Box::new(r)));
    })
    .map_err(|e| Error::io("start the worker thread", e))?;

    let _guard = TerminalGuard { mouse: app.ui.mouse };
    let mut terminal = ratatui::try_init().map_err(|e| Error::io("open the terminal", e))?;
    install_panic_hook();
    if app.ui.mouse {
        ratatui::crossterm::execute!(std::io::stdout(), event::EnableMouseCapture)
            .map_err(|e| Error::io("capture the mouse", e))?;
    }
    spawn_input(tx)?;
    // the update knows the terminal's size (a key on the "too small" screen only quits)
    let size = terminal.size().map_err(|e| Error::io("read the terminal size", e))?;
    let mut todo: Vec<Command> = update::update(
        &mut app,
        Msg::Resize {
            cols: size.width,
            rows: size.height,
        },
    );

    let mut trace = Trace::from_env();
    let panic_key = std::env::var("ASPERITY_PANIC_KEY").ok().and_then(|k| k.chars().next());
    // the one route out of the update: its commands, run in order before the next frame
    loop {
        if run_commands(&mut app, &mut todo, &worker, &replies, &mut trace)? {
            return Ok(());
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
        todo.extend(update::update(&mut app, Msg::Clock(Instant::now())));
        let Some(first) = first else {
            todo.extend(update::update(&mut app, Msg::Tick));
            continue;
        };
        // handle everything already queued before the next frame
        let mut next = Some(first);
        while let Some(incoming) = next {
            let msg = match incoming {
                Incoming::Input(Event::Key(k)) if k.kind != KeyEventKind::Release => {
                    if panic_key.is_some_and(|c| k.code == event::KeyCode::Char(c)) {
                        panic!("ASPERITY_PANIC_KEY pressed");
                    }
                    Some((Msg::Key(k), Some(Instant::now())))
                }
                Incoming::Input(Event::Mouse(m)) if app.ui.mouse => {
                    let size = terminal.size().map_err(|e| Error::io("read the terminal size", e))?;
                    pointer(&app, ratatui::layout::Rect::new(0, 0, size.width, size.height), m).map(|m| (m, None))
                }
                Incoming::Input(Event::Resize(cols, rows)) => Some((Msg::Resize { cols, rows }, None)),
                Incoming::Input(_) => None,
                Incoming::Reply(r) => Some((Msg::Reply(r), None)),
                Incoming::InputClosed => return Ok(()),
            };
            if let Some((msg, pressed)) = msg {
                let cmds = update::update(&mut app, msg);
                let asked = cmds.iter().rev().find_map(|c| match c {
                    Command::Compute(r) => Some(r.gen),
                    _ => None,
                });
                if let (Some(t0), Some(gen)) = (pressed, asked) {
                    trace.start(gen, t0);
                }
                todo.extend(cmds);
            }
            if todo.iter().any(|c| matches!(c, Command::Quit)) {
                break;
            }
            next = rx.try_recv().ok();
        }
    }
}
