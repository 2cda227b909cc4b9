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
//!   then ū at the current p* (a one-point sweep, cancellable). Between parts the worker
//!   checks `latest` and abandons stale work; a cancelled part is neither sent nor cached.
//! - Results are cached in small LRUs keyed by the scene's parameters as bits (the sweep's
//!   key leaves out p*), so stepping p* reuses the sweep and toggling back is instant.
//! - Every reply carries its generation and its key; the UI keeps a reply only if the key is
//!   the one its current scene needs (so stale replies are dropped).

use super::data::{self, PointData, SweepData};
use asperity::error::{Error, Result};
use asperity::input::scene::Scene;
use asperity::theory::engine::{self, Options};
use asperity::theory::sweep::{self, SweepSpec};
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::Arc;

/// Points of the load sweeps (the charts show at most ~80 columns of braille, 2 dots each;
/// 64 points joined by lines are indistinguishable from more).
pub const SWEEP_POINTS: usize = 64;
/// Points of the sampled Pr(σ*).
pub const SIGMA_POINTS: usize = 241;

/// What the UI asks for.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    /// Generation (strictly increasing).
    pub gen: u64,
    /// Identity of the preset (its name or path) — the spectrum is keyed by this too.
    pub source: String,
    /// The scene at the current p*.
    pub scene: Scene,
    /// p* range of the load charts (log-spaced, [`SWEEP_POINTS`] points).
    pub range: (f64, f64),
}

/// A cache key: the preset's identity and the scene's parameters as bits.
pub type CacheKey = (String, Vec<u64>);

/// The key of everything that depends on the whole scene (p* included).
pub fn point_key(source: &str, scene: &Scene) -> CacheKey {
    let mut bits = scene_bits(scene);
    bits.push(scene.pressure.to_bits());
    (source.to_string(), bits)
}

/// The key of a load sweep: the scene without p*, plus the range.
pub fn sweep_key(source: &str, scene: &Scene, range: (f64, f64)) -> CacheKey {
    let mut bits = scene_bits(scene);
    bits.extend([range.0.to_bits(), range.1.to_bits(), SWEEP_POINTS as u64]);
    (source.to_string(), bits)
}

fn scene_bits(s: &Scene) -> Vec<u64> {
    let mut h = DefaultHasher::new();
    format!("{:?}", s.spectrum).hash(&mut h);
    let m = &s.model;
    vec![
        h.finish(),
        s.modulus.to_bits(),
        s.thickness_qr.to_bits(),
        s.gamma.to_bits(),
        s.range.to_bits(),
        m.number().map_or(0, u64::from),
        m.c1.to_bits(),
        m.c2.to_bits(),
        m.alpha.to_bits(),
        m.k_griffith.to_bits(),
        u64::from(m.cap),
    ]
}

/// What the worker sends back.
#[derive(Debug, Clone, PartialEq)]
pub enum Reply {
    /// The current point.
    Point {
        /// Generation of the request.
        gen: u64,
        /// [`point_key`].
        key: CacheKey,
        /// The evaluation, or the engine's error.
        result: Result<PointData>,
    },
    /// The load sweep of the charts.
    Sweep {
        /// Generation.
        gen: u64,
        /// [`sweep_key`].
        key: CacheKey,
        /// Curves, or the error.
        result: Result<SweepData>,
    },
    /// ū/h_rms at the current p*.
    Gap {
        /// Generation.
        gen: u64,
        /// [`point_key`].
        key: CacheKey,
        /// ū/h_rms, or the error.
        result: Result<f64>,
    },
    /// Progress of the background GFMD run `id`.
    GfmdProgress {
        /// Run id.
        id: u64,
        /// FIRE steps so far.
        iteration: usize,
        /// Current relative force residual.
        residual: f64,
    },
    /// The background GFMD run `id` finished (or failed, or was cancelled).
    GfmdDone {
        /// Run id.
        id: u64,
        /// The run, or its error.
        result: Result<data::GfmdView>,
    },
    /// Everything of this generation has been sent.
    Done {
        /// Generation.
        gen: u64,
    },
}

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
    sweeps: Lru<Result<SweepData>>,
    gaps: Lru<Result<f64>>,
}

impl Default for Caches {
    fn default() -> Self {
        Caches {
            points: Lru::new(64),
            sweeps: Lru::new(12),
            gaps: Lru::new(64),
        }
    }
}

fn point_options() -> Options {
    Options {
        sigma_points: SIGMA_POINTS,
        ..Options::default()
    }
}

fn evaluate_point(scene: &Scene, cancel: &AtomicBool) -> Result<PointData> {
    let ev = engine::evaluate_warm(scene, &point_options(), None, Some(cancel))?;
    let mut pd = PointData::from_evaluation(&ev);
    if scene.gamma > 0.0 {
        let mut s0 = scene.clone();
        s0.gamma = 0.0;
        // the comparison curve is optional: an error only hides it
        if let Ok(ev0) = engine::evaluate(&s0, &point_options()) {
            pd.adhesionless = Some(data::pr_points(&ev0));
        }
    }
    Ok(pd)
}

/// Serves one request: sends the point, the sweep and the gap (each from the cache when
/// there), then `Done`. Returns early, sending nothing more, as soon as `stale()` is true or a
/// sweep reports [`Error::Cancelled`].
pub fn process(
    req: &Request,
    caches: &mut Caches,
    cancel: &AtomicBool,
    stale: &dyn Fn() -> bool,
    send: &dyn Fn(Reply),
) {
    let gen = req.gen;
    let pkey = point_key(&req.source, &req.scene);
    let point = match caches.points.get(&pkey) {
        Some(p) => p,
        None => {
            let p = evaluate_point(&req.scene, cancel);
            if matches!(p, Err(Error::Cancelled)) {
                return;
            }
            caches.points.put(pkey.clone(), p.clone());
            p
        }
    };
    let failed = point.is_err();
    send(Reply::Point {
        gen,
        key: pkey.clone(),
        result: point,
    });
    if failed {
        send(Reply::Done { gen });
        return;
    }
    if stale() {
        return;
    }
    let skey = sweep_key(&req.source, &req.scene, req.range);
    let sw = match caches.sweeps.get(&skey) {
        Some(s) => s,
        None => {
            let spec = SweepSpec {
                from: req.range.0,
                to: req.range.1,
                points: SWEEP_POINTS,
            };
            match sweep::sweep(&req.scene, &spec, &Options::chart(), Some(cancel)) {
                Err(Error::Cancelled) => return,
                r => {
                    let r = r.map(|s| SweepData::from_sweep(&s));
                    caches.sweeps.put(skey.clone(), r.clone());
                    r
                }
            }
        }
    };
    let from_sweep = sw.as_ref().ok().and_then(|sd| interpolate_gap(sd, req.scene.pressure));
    send(Reply::Sweep {
        gen,
        key: skey,
        result: sw,
    });
    if stale() {
        return;
    }
    let gap = match caches.gaps.get(&pkey) {
        Some(g) => g,
        None if from_sweep.is_some() => Ok(from_sweep.unwrap_or_default()),
        None => {
            let p = req.scene.pressure;
            let spec = SweepSpec {
                from: p,
                to: p,
                points: 1,
            };
            match sweep::sweep(&req.scene, &spec, &Options::chart(), Some(cancel)) {
                Err(Error::Cancelled) => return,
                r => {
                    let g = r.and_then(|s| data::gap_of_sweep(&s));
                    caches.gaps.put(pkey.clone(), g.clone());
                    g
                }
            }
        }
    };
    send(Reply::Gap {
        gen,
        key: pkey,
        result: gap,
    });
    send(Reply::Done { gen });
}

/// ū/h_rms at p* from the chart sweep's rows ([`sweep::interpolate_in_ln_p`]), when p* lies
/// inside the swept range: it saves a separate gap computation (a sweep from p* to full
/// contact) on every step of p*.
pub fn interpolate_gap(sd: &SweepData, p: f64) -> Option<f64> {
    sweep::interpolate_in_ln_p(&sd.p, &sd.gap_rel, p)
}

/// Loads of the GFMD sweep drawn on the a_r and ū charts (p*/3 … 3p*).
pub const GFMD_SWEEP_POINTS: usize = 5;

/// Bins of the GFMD Pr(σ*) histogram drawn in the explorer.
pub const GFMD_CHART_BINS: usize = 80;

/// Runs GFMD on its own thread (the theory worker stays responsive), reporting progress at
/// most every 100 ms and the result at the end; `cancel` stops it between FIRE steps.
pub fn spawn_gfmd(
    id: u64,
    setup: asperity::gfmd::GfmdSetup,
    cancel: Arc<AtomicBool>,
    send: impl Fn(Reply) + Send + 'static,
) -> std::io::Result<()> {
    std::thread::Builder::new()
        .name("asperity-gfmd".into())
        .spawn(move || {
            let mut last = std::time::Instant::now();
            // a chart-sized histogram: ~10⁴ contact nodes on 512² give ~100 per bin
            let opts = asperity::gfmd::GfmdOptions {
                pr_bins: GFMD_CHART_BINS,
                ..asperity::gfmd::GfmdOptions::default()
            };
            let result = asperity::gfmd::run(
                &setup,
                &opts,
                &mut |p: asperity::gfmd::Progress| {
                    if last.elapsed() >= std::time::Duration::from_millis(100) {
                        last = std::time::Instant::now();
                        send(Reply::GfmdProgress {
                            id,
                            iteration: p.iteration,
                            residual: p.residual,
                        });
                    }
                },
                &cancel,
            );
            // then the same map over a decade of loads around p* (warm-started), with the
            // theory on the map's spectrum, for the a_r and ū charts
            let result = result.map(|r| {
                let view = data::GfmdView::from_result(&r);
                let p = setup.scene.pressure;
                let spec = asperity::theory::sweep::SweepSpec {
                    from: (p / 3.0).max(1e-6),
                    to: (3.0 * p).min(1.0).max(p / 3.0 * 1.01),
                    points: GFMD_SWEEP_POINTS,
                };
                match asperity::gfmd::sweep::run_sweep(&setup, &spec, &opts, &mut |_, _| {}, &cancel) {
                    Ok(sw) => view.with_sweep(&sw),
                    Err(_) => view,
                }
            });
            send(Reply::GfmdDone { id, result });
        })?;
    Ok(())
}

/// Serves every pending request of `app` on the calling thread, feeding the replies back
/// (no thread, no cancellation): for tests and deterministic rendering.
pub fn compute_now(app: &mut super::app::App, caches: &mut Caches) {
    while let Some(req) = app.take_request() {
        let replies = std::cell::RefCell::new(Vec::new());
        process(&req, caches, &AtomicBool::new(false), &|| false, &|r| {
            replies.borrow_mut().push(r)
        });
        for r in replies.into_inner() {
            app.on_reply(r);
        }
    }
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
        process(&req, &mut caches, cancel, &stale, reply);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gap_interpolation_is_exact_for_cubics_in_ln_p() {
        let p: Vec<f64> = (0..20).map(|i| 1e-3 * 1.4f64.powi(i)).collect();
        let f = |x: f64| 0.3 - 0.2 * x + 0.01 * x * x * x;
        let sd = SweepData {
            gap_rel: p.iter().map(|q| f(q.ln())).collect(),
            a_r: vec![0.0; 20],
            mean_contact_stress: vec![0.0; 20],
            p: p.clone(),
        };
        for x in [1.1e-3, 5e-3, 0.02, p[19]] {
            let got = interpolate_gap(&sd, x).unwrap();
            assert!((got - f(x.ln())).abs() < 1e-12, "{x}: {got}");
        }
        assert_eq!(interpolate_gap(&sd, 1e-4), None);
        assert_eq!(interpolate_gap(&sd, 1.0), None);
    }

    #[test]
    fn lru_evicts_least_recent() {
        let mut c: Lru<i32> = Lru::new(2);
        let k = |s: &str| (s.to_string(), vec![]);
        c.put(k("a"), 1);
        c.put(k("b"), 2);
        assert_eq!(c.get(&k("a")), Some(1));
        c.put(k("c"), 3);
        assert_eq!(c.get(&k("b")), None);
        assert_eq!(c.get(&k("a")), Some(1));
        assert_eq!(c.get(&k("c")), Some(3));
        assert_eq!(c.len(), 2);
    }

    fn request(gen: u64, p: f64) -> Request {
        let mut scene = asperity::input::preset::Preset::resolve("system-1")
            .unwrap()
            .scene()
            .unwrap();
        scene.gamma = 0.0;
        scene.pressure = p;
        Request {
            gen,
            source: "system-1".into(),
            scene,
            range: (1e-3, 1.0),
        }
    }

    fn serve(req: &Request, caches: &mut Caches, cancel: bool, stale: bool) -> Vec<Reply> {
        let out = std::cell::RefCell::new(Vec::new());
        process(req, caches, &AtomicBool::new(cancel), &|| stale, &|r| {
            out.borrow_mut().push(r)
        });
        out.into_inner()
    }

    fn kinds(replies: &[Reply]) -> Vec<&'static str> {
        replies
            .iter()
            .map(|r| match r {
                Reply::Point { result, .. } => {
                    if result.is_ok() {
                        "point"
                    } else {
                        "point-err"
                    }
                }
                Reply::Sweep { .. } => "sweep",
                Reply::Gap { .. } => "gap",
                Reply::Done { .. } => "done",
                Reply::GfmdProgress { .. } | Reply::GfmdDone { .. } => "gfmd",
            })
            .collect()
    }

    #[test]
    fn cancelled_or_stale_work_is_abandoned_and_cached_work_is_instant() {
        let mut c = Caches::default();
        let req = request(1, 0.01);
        // cancelled: the point (one engine call) is sent, the sweeps are abandoned
        assert_eq!(kinds(&serve(&req, &mut c, true, false)), ["point"]);
        assert!(c.sweeps.is_empty() && c.gaps.is_empty());
        // stale before the sweep
        assert_eq!(kinds(&serve(&req, &mut c, false, true)), ["point"]);
        // full
        let full = serve(&req, &mut c, false, false);
        assert_eq!(kinds(&full), ["point", "sweep", "gap", "done"]);
        // now everything comes from the caches, even with the cancel flag up
        let again = serve(&req, &mut c, true, false);
        assert_eq!(again, full);
        // a new p* reuses the sweep
        let other = serve(&request(2, 0.02), &mut c, false, false);
        assert_eq!(kinds(&other), ["point", "sweep", "gap", "done"]);
        assert_eq!(c.sweeps.len(), 1);
        if let (Reply::Gap { result: Ok(g1), .. }, Reply::Gap { result: Ok(g2), .. }) = (&full[2], &other[2]) {
            assert!(g2 < g1, "the gap closes with load: {g1} -> {g2}");
        } else {
            panic!("{full:?}");
        }
    }

    #[test]
    fn adhesive_error_is_reported_not_thrown() {
        let mut c = Caches::default();
        let mut req = request(1, 0.01);
        req.scene.gamma = 0.05;
        let r = serve(&req, &mut c, false, false);
        // until the adhesive solver lands the engine refuses; either way the UI gets a reply
        assert_eq!(r.last(), Some(&Reply::Done { gen: 1 }));
    }

    #[test]
    fn threaded_worker_ends_on_the_newest_generation() {
        let (tx, rx) = channel();
        let w = Worker::spawn(move |r| {
            let _ = tx.send(r);
        })
        .unwrap();
        for g in 1..=30 {
            w.submit(request(g, 1e-3 * g as f64));
        }
        let mut last_gen = 0;
        loop {
            let r = rx
                .recv_timeout(std::time::Duration::from_secs(60))
                .expect("worker reply");
            let gen = match &r {
                Reply::Point { gen, .. } | Reply::Sweep { gen, .. } | Reply::Gap { gen, .. } => *gen,
                Reply::Done { gen } => *gen,
                Reply::GfmdProgress { .. } | Reply::GfmdDone { .. } => unreachable!("the theory worker runs no GFMD"),
            };
            assert!(gen >= last_gen, "replies never go back in generation");
            last_gen = gen;
            if r == (Reply::Done { gen: 30 }) {
                break;
            }
        }
    }

    #[test]
    fn keys_separate_what_matters() {
        let scene = asperity::input::preset::Preset::resolve("system-1")
            .unwrap()
            .scene()
            .unwrap();
        let mut s2 = scene.clone();
        s2.pressure *= 2.0;
        assert_ne!(point_key("a", &scene), point_key("a", &s2));
        assert_eq!(sweep_key("a", &scene, (1e-3, 1.0)), sweep_key("a", &s2, (1e-3, 1.0)));
        assert_ne!(sweep_key("a", &scene, (1e-3, 1.0)), sweep_key("b", &scene, (1e-3, 1.0)));
        s2.thickness_qr = 1.0;
        assert_ne!(sweep_key("a", &scene, (1e-3, 1.0)), sweep_key("a", &s2, (1e-3, 1.0)));
    }
}
