//! The compute worker: one long-lived thread owns the engine calls and the result caches.
//!
//! Protocol (generation numbers, after television/gitui):
//! - The UI numbers every [`Request`] with a strictly increasing generation. [`Worker::submit`]
//!   stores it in the shared `latest` (`AtomicU64`), raises the shared `cancel` flag and then
//!   sends the request.
//! - The worker blocks on its inbox, lowers `cancel`, drains the inbox keeping only the newest
//!   request (holding a key never queues a backlog) and skips it if `latest` has moved on.
//! - Work is done cheapest first, each part sent as soon as it is ready: the current point
//!   (Pr(σ*), a_r, …), then the load sweep of the charts (cancellable: `sweep` polls `cancel`),
//!   then ū at the current p* (read off the load sweep where one was computed, else
//!   [`point_gap`], cancellable); the scale view's snapshots (cancellable between frames) come
//!   right after the point when a visible chart needs them. A part no chart on screen needs
//!   (the request's [`Request::needs`]) is not computed. Between parts the worker checks
//!   `latest` and abandons stale work; a cancelled part is neither sent nor cached.
//! - Results are cached in small LRUs keyed by the scene's parameters as bits (the sweep's
//!   key leaves out p*), so stepping p* reuses the sweep and toggling back is instant.
//! - Every reply carries its generation and its key; the UI keeps a reply only if the key is
//!   the one its current scene needs (so stale replies are dropped).

use crate::tui::base::data::{PointData, ScalesData, SweepData, ThicknessData};
pub use crate::tui::base::protocol::*;
pub use crate::tui::effects::engine::panic_text;
use crate::tui::effects::engine::{evaluate_point, evaluate_preview};
pub use crate::tui::effects::engine::{
    interpolate_gap, load_sweep, point_gap, preview_sweep, scale_view, spawn_gfmd, thickness_sweep, PREVIEW_EDGE_REL,
};
use asperity::error::{Error, Result};
use asperity::input::scene::Scene;
use asperity::theory::sweep::SweepSpec;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::Arc;

/// A tiny least-recently-used cache (linear search; a few dozen entries).
#[derive(Debug)]
pub struct Lru<V> {
    cap: usize,
    items: Vec<(CacheKey, V)>,
}

impl<V: Clone> Lru<V> {
    /// An empty cache holding at most `cap` entries.
    pub fn new(cap: usize) -> Self {
        Lru {
            cap: cap.max(1),
            items: Vec::new(),
        }
    }

    /// The value for `key`, marking it most recently used.
    pub fn get(&mut self, key: &CacheKey) -> Option<V> {
        let i = self.items.iter().position(|(k, _)| k == key)?;
        let item = self.items.remove(i);
        let v = item.1.clone();
        self.items.push(item);
        Some(v)
    }

    /// Inserts, evicting the least recently used entry when full.
    pub fn put(&mut self, key: CacheKey, v: V) {
        self.items.retain(|(k, _)| *k != key);
        if self.items.len() >= self.cap {
            self.items.remove(0);
        }
        self.items.push((key, v));
    }

    /// Number of entries.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// Whether the cache is empty.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }
}

/// The worker's caches.
#[derive(Debug)]
pub struct Caches {
    points: Lru<Result<PointData>>,
    previews: Lru<Result<PointData>>,
    sweeps: Lru<Result<SweepData>>,
    gaps: Lru<Result<f64>>,
    thick: Lru<Result<ThicknessData>>,
    scales: Lru<Result<ScalesData>>,
}

impl Default for Caches {
    fn default() -> Self {
        Caches {
            points: Lru::new(64),
            previews: Lru::new(64),
            sweeps: Lru::new(12),
            gaps: Lru::new(64),
            thick: Lru::new(24),
            scales: Lru::new(8),
        }
    }
}

/// Serves one request: sends the point, the load sweep (if a visible chart needs it), the
/// gap, the thickness sweep (if needed), then the same for every further model (`M`), each
/// from the cache when there, then `Done`. Returns early, sending nothing more, as soon as
/// `stale()` is true or a computation reports [`Error::Cancelled`]. A failed point does not
/// stop the load charts: they do not depend on it.
///
/// Responsiveness (a key that moves p* or t·q_r through a jump into contact): an adhesive point
/// not in the cache is sent twice, first at chart accuracy ([`PointData::preview`], a few tens
/// of ms), then — after the charts' sweeps, which a newer key cancels — at full accuracy with
/// its error bar.
pub fn process(
    req: &Request,
    caches: &mut Caches,
    cancel: &AtomicBool,
    stale: &dyn Fn() -> bool,
    send: &dyn Fn(Reply),
) {
    let gen = req.gen;
    let refine =
        if req.scene.surface_energy_j_m2() > 0.0 && caches.points.get(&point_key(&req.source, &req.scene)).is_none() {
            if serve_preview(req, caches, cancel, send).is_none() {
                return;
            }
            true
        } else {
            let Some(_) = serve_point(req, &req.scene, true, caches, cancel, send) else {
                return;
            };
            false
        };
    if stale() {
        return;
    }
    if req.needs.scales && serve_scales(req, caches, cancel, send).is_none() {
        return;
    }
    if stale() {
        return;
    }
    let sw = if req.needs.loads {
        let Some(sw) = serve_sweep(req, &req.scene, true, caches, cancel, send) else {
            return;
        };
        Some(sw)
    } else {
        None
    };
    if stale() {
        return;
    }
    let from_sweep = sw
        .as_ref()
        .and_then(|r| r.as_ref().ok())
        .and_then(|sd| interpolate_gap(sd, req.scene.pressure()));
    let pkey = point_key(&req.source, &req.scene);
    let gap = match caches.gaps.get(&pkey) {
        Some(g) => g,
        None if from_sweep.is_some() => Ok(from_sweep.unwrap_or_default()),
        None => match point_gap(&req.scene, cancel) {
            Err(Error::Cancelled) => return,
            g => {
                caches.gaps.put(pkey.clone(), g.clone());
                g
            }
        },
    };
    send(Reply::Gap {
        gen,
        key: pkey,
        result: gap,
    });
    if req.needs.thickness {
        if stale() {
            return;
        }
        if serve_thickness(req, &req.scene, caches, cancel, send).is_none() {
            return;
        }
    }
    if refine {
        if stale() {
            return;
        }
        if serve_point(req, &req.scene, true, caches, cancel, send).is_none() {
            return;
        }
    }
    for scene in req.models.iter().filter_map(|m| req.with_model(m)) {
        for part in 0..3 {
            if stale() {
                return;
            }
            let done = match part {
                0 if req.needs.point => serve_point(req, &scene, false, caches, cancel, send).map(|_| ()),
                1 if req.needs.loads => serve_sweep(req, &scene, false, caches, cancel, send).map(|_| ()),
                2 if req.needs.thickness => serve_thickness(req, &scene, caches, cancel, send).map(|_| ()),
                _ => Some(()),
            };
            if done.is_none() {
                return;
            }
        }
    }
    send(Reply::Done { gen });
}

/// `pd` with the panel's short form of the trust read-out of `scene`
/// ([`asperity::fit::trust`]), on each branch it carries: the band within which GFMD's a_r was
/// measured from the theory's at this load and whose model it is, that no error is known at
/// this load, or that the scene lies outside the reference set (`run`'s `trust` line says how
/// far).
fn with_trust(mut pd: PointData, scene: &Scene) -> PointData {
    let t = asperity::fit::trust::assess(scene);
    let text = if !t.known {
        "no error known here".to_string()
    } else if !t.inside {
        "outside GFMD set".to_string()
    } else {
        let band = crate::numfmt::sig(t.a_r_band_ratio, 2);
        if t.same_model {
            format!("a_r ×/÷{band} (m{})", t.measured_model)
        } else {
            // the set measured another model here: say whose error it is
            format!("m{}'s a_r ×/÷{band}", t.measured_model)
        }
    };
    if let Some(u) = pd.unloading.as_mut() {
        u.trust = text.clone();
    }
    pd.trust = text;
    pd.pull_off = scene.is_adhesive().then(|| pull_off_line(scene, &t));
    pd
}

/// The pull-off read-out in one line for the a_r(p*) chart's title, from the stored set alone
/// (no solve): GFMD's pull-off at the nearest measured case and how much of it the theory's
/// pull-off was measured to hold near the scene ([`asperity::fit::pull_off_trust`]), then,
/// inside the measured range, the gauged estimate with its band (` · est. −0.001 ×/÷2.1`,
/// [`asperity::fit::pull_off_gauge`]; the view drops it first where the border is short).
/// `run --pull-off` computes the theory's own pull-off and the DMT routes'.
pub fn pull_off_line(scene: &Scene, t: &asperity::fit::trust::Trust) -> String {
    let est = asperity::fit::pull_off_gauge::estimate(scene);
    let tail = match (est.pull_off_pressure, est.band_factor) {
        (Some(p), Some(f)) => format!(
            "{}{} ×/÷{}",
            crate::tui::base::data::PULL_OFF_EST_SEGMENT,
            crate::numfmt::sig(p, 2),
            crate::numfmt::sig(f, 2)
        ),
        _ => String::new(),
    };
    measured_pull_off(scene, t) + &tail
}

/// GFMD's nearest pull-off and the share of it the theory was measured to hold.
fn measured_pull_off(scene: &Scene, t: &asperity::fit::trust::Trust) -> String {
    let read =
        asperity::fit::pull_off_trust::assess(scene.thickness_qr(), scene.gamma_glo(), scene.model().number(), true);
    match (t.pull_off, read.theory_ratio) {
        (Some(g), Some([_, 0.0])) => format!(
            "pull-off GFMD {}, m{} none of it",
            crate::numfmt::sig(g.pull_off_pressure, 2),
            read.measured_model
        ),
        (Some(g), Some([lo, hi])) => format!(
            "pull-off GFMD {}, m{} {}–{} % of it",
            crate::numfmt::sig(g.pull_off_pressure, 2),
            read.measured_model,
            crate::numfmt::sig(100.0 * lo, 1),
            crate::numfmt::sig(100.0 * hi, 1)
        ),
        (Some(g), None) => format!("pull-off GFMD {}", crate::numfmt::sig(g.pull_off_pressure, 2)),
        _ => "pull-off: no GFMD case near".into(),
    }
}

/// The chart-accuracy point of the request's scene (cached); `None` when cancelled.
fn serve_preview(req: &Request, caches: &mut Caches, cancel: &AtomicBool, send: &dyn Fn(Reply)) -> Option<()> {
    let key = point_key(&req.source, &req.scene);
    let point = match caches.previews.get(&key) {
        Some(p) => p,
        None => {
            let p = evaluate_preview(&req.scene, cancel, true).map(|pd| with_trust(pd, &req.scene));
            if matches!(p, Err(Error::Cancelled)) {
                return None;
            }
            caches.previews.put(key.clone(), p.clone());
            p
        }
    };
    send(Reply::Point {
        gen: req.gen,
        key,
        result: point,
    });
    Some(())
}

/// The point of `scene` (cached); `None` when cancelled.
fn serve_point(
    req: &Request,
    scene: &Scene,
    compare: bool,
    caches: &mut Caches,
    cancel: &AtomicBool,
    send: &dyn Fn(Reply),
) -> Option<Result<PointData>> {
    let key = point_key(&req.source, scene);
    let point = match caches.points.get(&key) {
        Some(p) => p,
        None => {
            let p = evaluate_point(scene, cancel, compare).map(|pd| with_trust(pd, scene));
            if matches!(p, Err(Error::Cancelled)) {
                return None;
            }
            caches.points.put(key.clone(), p.clone());
            p
        }
    };
    send(Reply::Point {
        gen: req.gen,
        key,
        result: point.clone(),
    });
    Some(point)
}

/// The load sweep of `scene` (cached); `None` when cancelled.
fn serve_sweep(
    req: &Request,
    scene: &Scene,
    preview: bool,
    caches: &mut Caches,
    cancel: &AtomicBool,
    send: &dyn Fn(Reply),
) -> Option<Result<SweepData>> {
    let key = sweep_key(&req.source, scene, req.range);
    let sw = match caches.sweeps.get(&key) {
        Some(s) => s,
        None => {
            // an adhesive sweep costs 0.1–0.3 s: a preview first ([`PREVIEW_POINTS`]), not
            // cached (a failed preview is left to the full sweep to report)
            if preview && scene.surface_energy_j_m2() > 0.0 {
                match preview_sweep(scene, req.range, cancel) {
                    Err(Error::Cancelled) => return None,
                    Ok(sd) => send(Reply::Sweep {
                        gen: req.gen,
                        key: key.clone(),
                        result: Ok(sd),
                    }),
                    Err(_) => {}
                }
            }
            let spec = SweepSpec {
                from: req.range.0,
                to: req.range.1,
                points: SWEEP_POINTS,
            };
            match load_sweep(scene, &spec, cancel) {
                Err(Error::Cancelled) => return None,
                r => {
                    caches.sweeps.put(key.clone(), r.clone());
                    r
                }
            }
        }
    };
    send(Reply::Sweep {
        gen: req.gen,
        key,
        result: sw.clone(),
    });
    Some(sw)
}

/// The scale view of the request's scene (cached); `None` when cancelled.
fn serve_scales(req: &Request, caches: &mut Caches, cancel: &AtomicBool, send: &dyn Fn(Reply)) -> Option<()> {
    let key = scales_key(&req.source, &req.scene);
    let sc = match caches.scales.get(&key) {
        Some(s) => s,
        None => match scale_view(&req.scene, cancel) {
            Err(Error::Cancelled) => return None,
            r => {
                caches.scales.put(key.clone(), r.clone());
                r
            }
        },
    };
    send(Reply::Scales {
        gen: req.gen,
        key,
        result: sc,
    });
    Some(())
}

/// The thickness sweep of `scene` (cached); `None` when cancelled.
fn serve_thickness(
    req: &Request,
    scene: &Scene,
    caches: &mut Caches,
    cancel: &AtomicBool,
    send: &dyn Fn(Reply),
) -> Option<()> {
    let key = thickness_key(&req.source, scene);
    let td = match caches.thick.get(&key) {
        Some(t) => t,
        None => match thickness_sweep(scene, cancel) {
            Err(Error::Cancelled) => return None,
            r => {
                caches.thick.put(key.clone(), r.clone());
                r
            }
        },
    };
    send(Reply::Thickness {
        gen: req.gen,
        key,
        result: td,
    });
    Some(())
}

/// Handle to the worker thread.
pub struct Worker {
    tx: Sender<Request>,
    latest: Arc<AtomicU64>,
    cancel: Arc<AtomicBool>,
}

impl Worker {
    /// Starts the thread; every reply goes to `reply` (which must not block for long).
    pub fn spawn(reply: impl Fn(Reply) + Send + 'static) -> std::io::Result<Worker> {
        let (tx, rx) = channel::<Request>();
        let latest = Arc::new(AtomicU64::new(0));
        let cancel = Arc::new(AtomicBool::new(false));
        let (l, c) = (latest.clone(), cancel.clone());
        std::thread::Builder::new()
            .name("asperity-worker".into())
            .spawn(move || run(rx, &l, &c, &reply))?;
        Ok(Worker { tx, latest, cancel })
    }

    /// Queues a request (never blocks). Older requests become stale at once.
    pub fn submit(&self, req: Request) {
        self.latest.store(req.gen, Ordering::SeqCst);
        self.cancel.store(true, Ordering::SeqCst);
        let _ = self.tx.send(req);
    }
}

fn run(rx: Receiver<Request>, latest: &AtomicU64, cancel: &AtomicBool, reply: &dyn Fn(Reply)) {
    let mut caches = Caches::default();
    while let Ok(mut req) = rx.recv() {
        // lower the flag first, then drain: a request submitted meanwhile is either drained
        // here or raises the flag again after this point
        cancel.store(false, Ordering::SeqCst);
        while let Ok(newer) = rx.try_recv() {
            req = newer;
        }
        let gen = req.gen;
        if latest.load(Ordering::SeqCst) != gen {
            continue;
        }
        let stale = || latest.load(Ordering::SeqCst) != gen;
        // a fault in the computation (a panic) becomes a message the explorer shows; the
        // caches may hold a half-written entry, so they start afresh
        let served = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            if std::env::var_os(TEST_FAULT).is_some() {
                panic!("{TEST_FAULT} is set: a fault injected for the tests");
            }
            process(&req, &mut caches, cancel, &stale, reply)
        }));
        if let Err(payload) = served {
            caches = Caches::default();
            reply(Reply::Fault {
                gen,
                message: format!("internal fault: {}", panic_text(payload.as_ref())),
            });
        }
    }
}

/// The environment variable that makes the worker fail on every request (a panic, caught
/// like any fault), for the tests that the explorer shows a fault and stays responsive.
pub const TEST_FAULT: &str = "ASPERITY_TEST_FAULT";

#[cfg(test)]
#[path = "worker_tests.rs"]
mod tests;
