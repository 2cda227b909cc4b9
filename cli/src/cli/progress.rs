//! Progress of long work on stderr, for every command that can take more than a couple of
//! seconds (GFMD runs, sweeps and cycles, `gauge`/`compare --reference gfmd`, `figure --gfmd`,
//! `bench`): the work is a number of steps (loads, seeds, rungs, stages), each reported as it
//! starts.
//!
//! - On a terminal: a bar (indicatif) with the step, the total, the elapsed time and an
//!   estimate of the time left, and a message that the solver updates (its step count and
//!   residual); the bar is cleared when the work ends.
//! - Off a terminal (a pipe, a file, CI): one plain line per step as it starts, `asperity gfmd:
//!   load 3/7 (p* = 0.001), 4.2 s, about 6 s left`, and a line every [`LINE_EVERY_S`] seconds
//!   within a long step, so a log shows that the work goes on and how far it is.
//! - `--quiet` ([`set_quiet`]): nothing, neither bar nor lines (errors and notes still print).
//!
//! The time left is the mean time of the finished steps times the steps left (none before
//! the first step ends); steps past the planned total (the tension steps of a load cycle,
//! whose number is not known in advance) are numbered without a total or a time left.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Seconds between the plain lines of one long step off a terminal.
pub const LINE_EVERY_S: f64 = 10.0;

static QUIET: AtomicBool = AtomicBool::new(false);

/// Silences progress for the rest of the process (`--quiet`).
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, Ordering::Relaxed);
}

/// Whether `--quiet` was given.
pub fn is_quiet() -> bool {
    QUIET.load(Ordering::Relaxed)
}

enum Mode {
    Quiet,
    /// On a terminal: the bar, drawn from the first step on (a command that turns out to have
    /// no steps draws nothing).
    Bar(Option<ProgressBar>),
    Lines,
}

/// A bar for `name`'s steps on stderr.
fn bar(name: &'static str, total: usize) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
    let style = ProgressStyle::with_template(
        "asperity {prefix}: {wide_msg} {bar:24} {pos}/{len} [{elapsed}, about {eta} left]",
    )
    .expect("a valid template");
    bar.set_style(style);
    bar.set_prefix(name);
    bar.enable_steady_tick(Duration::from_millis(200));
    bar
}

/// The progress of one command's steps (see the module docs).
pub struct Steps {
    name: &'static str,
    unit: &'static str,
    total: usize,
    planned: usize,
    current: Option<usize>,
    label: String,
    started: Instant,
    step_started: Instant,
    finished_s: f64,
    finished: usize,
    last_line: Instant,
    mode: Mode,
}

impl Steps {
    /// The progress of command `name` (`gfmd`) over `total` steps called `unit` (`load`): a bar
    /// on a terminal, lines elsewhere, nothing with `--quiet`.
    pub fn new(name: &'static str, unit: &'static str, total: usize) -> Steps {
        let mode = if is_quiet() {
            Mode::Quiet
        } else if std::io::stderr().is_terminal() {
            Mode::Bar(None)
        } else {
            Mode::Lines
        };
        let now = Instant::now();
        Steps {
            name,
            unit,
            total: total.max(1),
            planned: total.max(1),
            current: None,
            label: String::new(),
            started: now,
            step_started: now,
            finished_s: 0.0,
            finished: 0,
            last_line: now,
            mode,
        }
    }

    /// Whether anything is shown (not `--quiet`).
    pub fn shown(&self) -> bool {
        !matches!(self.mode, Mode::Quiet)
    }

    /// The seconds left as the finished steps' mean predicts (None before one finished).
    fn left_s(&self) -> Option<f64> {
        let beyond = self.current.is_some_and(|k| k >= self.planned);
        (self.finished > 0 && !beyond)
            .then(|| self.finished_s / self.finished as f64 * (self.total - self.finished.min(self.total)) as f64)
    }

    fn line(&mut self, extra: &str) {
        let k = self.current.map_or(0, |k| k + 1);
        // past the planned steps (a cycle's tension) the total is not known
        let mut l = if k > self.planned {
            format!("asperity {}: {} {k}", self.name, self.unit)
        } else {
            format!("asperity {}: {} {k}/{}", self.name, self.unit, self.total)
        };
        if !self.label.is_empty() {
            l.push_str(&format!(" ({})", self.label));
        }
        if !extra.is_empty() {
            l.push_str(&format!(": {extra}"));
        }
        l.push_str(&format!(
            ", {}",
            crate::numfmt::duration(self.started.elapsed().as_secs_f64())
        ));
        if let Some(s) = self.left_s() {
            l.push_str(&format!(", about {} left", crate::numfmt::duration(s)));
        }
        eprintln!("{l}");
        self.last_line = Instant::now();
    }

    /// Step `k` (from 0) with its `label` (`p* = 0.001`) is under way: a new step ends the
    /// last one (its time counts for the estimate) and is shown at once.
    pub fn step(&mut self, k: usize, label: &str) {
        if self.current == Some(k) {
            return;
        }
        let now = Instant::now();
        if self.current.is_some() {
            self.finished_s += now.duration_since(self.step_started).as_secs_f64();
            self.finished += 1;
        }
        self.current = Some(k);
        self.step_started = now;
        self.label = label.to_string();
        if k + 1 > self.total {
            self.total = k + 1;
        }
        let (name, total) = (self.name, self.total);
        match &mut self.mode {
            Mode::Quiet => {}
            Mode::Bar(slot) => {
                let bar = slot.get_or_insert_with(|| bar(name, total));
                bar.set_length(self.total as u64);
                bar.set_position(k as u64);
                bar.set_message(format!("{} {} ({label})", self.unit, k + 1));
            }
            Mode::Lines => self.line(""),
        }
    }

    /// What the current step is doing (`step 1200, residual 3e-6`): the bar's message on a
    /// terminal; off it a line when the step has run [`LINE_EVERY_S`] since the last line.
    pub fn detail(&mut self, text: &str) {
        match &self.mode {
            Mode::Quiet | Mode::Bar(None) => {}
            Mode::Bar(Some(bar)) => {
                let k = self.current.map_or(0, |k| k + 1);
                let label = if self.label.is_empty() {
                    String::new()
                } else {
                    format!(" ({})", self.label)
                };
                bar.set_message(format!("{} {k}{label}: {text}", self.unit));
            }
            Mode::Lines => {
                if self.last_line.elapsed().as_secs_f64() >= LINE_EVERY_S {
                    self.line(text);
                }
            }
        }
    }

    /// The work is done: the bar is cleared (the lines stay as they are).
    pub fn finish(self) {
        if let Mode::Bar(Some(bar)) = &self.mode {
            bar.finish_and_clear();
        }
    }
}

impl Drop for Steps {
    fn drop(&mut self) {
        if let Mode::Bar(Some(bar)) = &self.mode {
            if !bar.is_finished() {
                bar.finish_and_clear();
            }
        }
    }
}

/// A load p* as the progress lines write it (`p* = 0.001`, `p* = -2e-4`).
pub fn load_label(p: f64) -> String {
    format!("p* = {}", crate::numfmt::short(p))
}
