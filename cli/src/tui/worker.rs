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

use super::charts::Needs;
use super::data::{self, PointData, SweepData, ThicknessData};
use asperity::error::{Error, Result};
use asperity::input::model::Model;
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
/// Points of the quick first load sweep of an adhesive scene, drawn while the full one runs:
/// every third p* of the full sweep's [`SWEEP_POINTS`], at the U-table step
/// [`PREVIEW_STEP_LN`] (no refinement over the ≤ 6 decades of a chart range), with the window
/// edges to [`PREVIEW_EDGE_REL`]. On system II's thin slab inside its hysteresis window
/// (t·q_r = 0.1, γ_s = 0.1256 J/m², 1e-5…1) it costs about half the full sweep (~100 ms
/// against ~200 ms of solves).
pub const PREVIEW_POINTS: usize = 22;
/// Largest U-table step (ln p*) of the preview sweep ([`PREVIEW_POINTS`]).
pub const PREVIEW_STEP_LN: f64 = 1.0;
/// Precision (relative, in p*) of the preview's window edges: the largest the engine allows,
/// about its load step (a jump drawn within a braille dot or two of the full sweep's, which
/// refines it to `Options::chart`'s 3 %). Refining to 3 % took a third of the preview.
pub const PREVIEW_EDGE_REL: f64 = asperity::theory::engine::EDGE_REL_RANGE.1;
/// Points of the sampled Pr(σ*).
pub const SIGMA_POINTS: usize = 241;
/// t·q_r range of the thickness chart (\[S\] Fig. 7 spans about this).
pub const THICKNESS_RANGE: (f64, f64) = (1e-2, 1e2);
/// Points of the thickness chart (4 per decade).
pub const THICKNESS_POINTS: usize = 17;

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
    /// What the visible charts need.
    pub needs: Needs,
    /// Further models to compute what the charts need for (`M`), the current one excluded.
    pub models: Vec<Model>,
}

impl Request {
    /// The scene with another model.
    pub fn with_model(&self, m: &Model) -> Scene {
        let mut s = self.scene.clone();
        s.model = *m;
        s
    }
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

/// The key of a thickness sweep: the scene without t·q_r, with p*.
pub fn thickness_key(source: &str, scene: &Scene) -> CacheKey {
    let mut s = scene.clone();
    s.thickness_qr = f64::NAN;
    let mut bits = scene_bits(&s);
    bits.extend([scene.pressure.to_bits(), THICKNESS_POINTS as u64, u64::MAX]);
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
    /// a_r against t·q_r at the current p*.
    Thickness {
        /// Generation.
        gen: u64,
        /// [`thickness_key`].
        key: CacheKey,
        /// Curves, or the error.
        result: Result<ThicknessData>,
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
    previews: Lru<Result<PointData>>,
    sweeps: Lru<Result<SweepData>>,
    gaps: Lru<Result<f64>>,
    thick: Lru<Result<ThicknessData>>,
}

impl Default for Caches {
    fn default() -> Self {
        Caches {
            points: Lru::new(64),
            previews: Lru::new(64),
            sweeps: Lru::new(12),
            gaps: Lru::new(64),
            thick: Lru::new(24),
        }
    }
}

fn point_options() -> Options {
    Options {
        sigma_points: SIGMA_POINTS,
        ..Options::default()
    }
}

/// The quick first answer of an adhesive point ([`PointData::preview`]): chart accuracy
/// ([`Options::chart`]: half the resolution in both directions, no error estimate) with the
/// search for every branch, so the panel lists the branches at once.
fn preview_options() -> Options {
    let mut o = Options::chart();
    o.sigma_points = SIGMA_POINTS;
    o.adhesion.explore_branches = true;
    o
}

/// The adhesive point at chart accuracy (see [`preview_options`]), with the adhesionless
/// comparison when `compare`.
fn evaluate_preview(scene: &Scene, cancel: &AtomicBool, compare: bool) -> Result<PointData> {
    let ev = engine::evaluate_warm(scene, &preview_options(), None, Some(cancel))?;
    let mut pd = PointData::at(&ev, scene.pressure);
    pd.error_estimate = f64::NAN;
    pd.preview = true;
    if compare {
        add_comparison(&mut pd, scene);
    }
    Ok(pd)
}

fn add_comparison(pd: &mut PointData, scene: &Scene) {
    let mut s0 = scene.clone();
    s0.gamma = 0.0;
    // the comparison curve is optional: an error only hides it
    if let Ok(ev0) = engine::evaluate(&s0, &point_options()) {
        pd.adhesionless = Some(data::pr_points(&ev0));
    }
}

fn evaluate_point(scene: &Scene, cancel: &AtomicBool, compare: bool) -> Result<PointData> {
    let mut pd = match engine::evaluate_warm(scene, &point_options(), None, Some(cancel)) {
        Ok(ev) => PointData::at(&ev, scene.pressure),
        Err(e @ Error::NotConverged { .. }) if scene.gamma > 0.0 => {
            // the self-consistency may have converged while its error check did not (the edge
            // of a jump into contact): show it, without an error bar, and say why
            let opts = Options {
                adhesion_error_estimate: false,
                ..point_options()
            };
            match engine::evaluate_warm(scene, &opts, None, Some(cancel)) {
                Ok(ev) => {
                    let mut pd = PointData::at(&ev, scene.pressure);
                    pd.error_estimate = f64::NAN;
                    pd.branch.push_str(", no error bar");
                    pd.warning = Some(e.to_string());
                    pd
                }
                Err(Error::Cancelled) => return Err(Error::Cancelled),
                _ => return Err(e),
            }
        }
        Err(e) => return Err(e),
    };
    if compare && scene.gamma > 0.0 {
        add_comparison(&mut pd, scene);
    }
    Ok(pd)
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
    let refine = if req.scene.gamma > 0.0 && caches.points.get(&point_key(&req.source, &req.scene)).is_none() {
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
        .and_then(|sd| interpolate_gap(sd, req.scene.pressure));
    let pkey = point_key(&req.source, &req.scene);
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
    for m in &req.models {
        let scene = req.with_model(m);
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

/// The chart-accuracy point of the request's scene (cached); `None` when cancelled.
fn serve_preview(req: &Request, caches: &mut Caches, cancel: &AtomicBool, send: &dyn Fn(Reply)) -> Option<()> {
    let key = point_key(&req.source, &req.scene);
    let point = match caches.previews.get(&key) {
        Some(p) => p,
        None => {
            let p = evaluate_preview(&req.scene, cancel, true);
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
            let p = evaluate_point(scene, cancel, compare);
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
            if preview && scene.gamma > 0.0 {
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

/// The load curves of the charts at chart accuracy: the loading branch with ū and σ̄_c*, and
/// with adhesion the unloading branch and the jump-in and pull-off loads ([`sweep::sweep`]).
pub fn load_sweep(scene: &Scene, spec: &SweepSpec, cancel: &AtomicBool) -> Result<SweepData> {
    Ok(SweepData::from_sweep(&sweep::sweep(
        scene,
        spec,
        &Options::chart(),
        Some(cancel),
    )?))
}

/// The quick first load curves of `scene` over `range` ([`PREVIEW_POINTS`]).
pub fn preview_sweep(scene: &Scene, range: (f64, f64), cancel: &AtomicBool) -> Result<SweepData> {
    let spec = SweepSpec {
        from: range.0,
        to: range.1,
        points: PREVIEW_POINTS,
    };
    let opts = Options {
        sweep_step_ln: PREVIEW_STEP_LN,
        edge_rel: PREVIEW_EDGE_REL,
        ..Options::chart()
    };
    let mut sd = SweepData::from_sweep(&sweep::sweep(scene, &spec, &opts, Some(cancel))?);
    sd.preview = true;
    Ok(sd)
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

/// a_r at [`THICKNESS_POINTS`] log-spaced t·q_r in [`THICKNESS_RANGE`] and at t = ∞ (chart
/// accuracy, each solve warm-started from the neighbouring thickness); a thickness where the
/// solver fails is a gap (NaN), not an error. With adhesion also the adhesionless curve.
pub fn thickness_sweep(scene: &Scene, cancel: &AtomicBool) -> Result<ThicknessData> {
    let t = data::log_grid(THICKNESS_RANGE.0, THICKNESS_RANGE.1, THICKNESS_POINTS);
    let opts = Options {
        sigma_points: 2,
        ..Options::chart()
    };
    let at = |th: f64, gamma: f64, warm: Option<&engine::Evaluation>| {
        let mut s = scene.clone();
        s.thickness_qr = th;
        s.gamma = gamma;
        engine::evaluate_warm(&s, &opts, warm, Some(cancel))
    };
    let mut a_r = Vec::with_capacity(t.len());
    // from thick to thin: the thick slab is the easier start
    let mut warm: Option<engine::Evaluation> = None;
    for &th in t.iter().rev() {
        match at(th, scene.gamma, warm.as_ref()) {
            Ok(ev) => {
                a_r.push(ev.stats.a_r);
                warm = Some(ev);
            }
            Err(Error::Cancelled) => return Err(Error::Cancelled),
            Err(_) => {
                a_r.push(f64::NAN);
                warm = None;
            }
        }
    }
    a_r.reverse();
    let a_r_inf = match at(f64::INFINITY, scene.gamma, None) {
        Ok(ev) => ev.stats.a_r,
        Err(Error::Cancelled) => return Err(Error::Cancelled),
        Err(_) => f64::NAN,
    };
    let adhesionless = if scene.gamma > 0.0 {
        let mut v = Vec::with_capacity(t.len());
        for &th in &t {
            match at(th, 0.0, None) {
                Ok(ev) => v.push(ev.stats.a_r),
                Err(Error::Cancelled) => return Err(Error::Cancelled),
                Err(_) => v.push(f64::NAN),
            }
        }
        Some(v)
    } else {
        None
    };
    if a_r.iter().all(|a| !a.is_finite()) {
        return Err(Error::NotConverged {
            solver: "thickness sweep".into(),
            reason: "no thickness converged".into(),
        });
    }
    Ok(ThicknessData {
        t,
        a_r,
        a_r_inf,
        adhesionless,
    })
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
            converged: vec![true; 20],
            p: p.clone(),
            ..SweepData::default()
        };
        for x in [1.1e-3, 5e-3, 0.02, p[19]] {
            let got = interpolate_gap(&sd, x).unwrap();
            assert!((got - f(x.ln())).abs() < 1e-12, "{x}: {got}");
        }
        assert_eq!(interpolate_gap(&sd, 1e-4), None);
        assert_eq!(interpolate_gap(&sd, 1.0), None);
    }

    #[test]
    fn thickness_sweep_tends_to_the_semi_infinite_body() {
        let mut scene = asperity::input::preset::Preset::resolve("system-2")
            .unwrap()
            .scene()
            .unwrap();
        let t0 = std::time::Instant::now();
        let td = thickness_sweep(&scene, &AtomicBool::new(false)).unwrap();
        eprintln!("system-2 thickness sweep: {:.2} s", t0.elapsed().as_secs_f64());
        assert_eq!(td.t.len(), THICKNESS_POINTS);
        assert!((td.t[0] / THICKNESS_RANGE.0 - 1.0).abs() < 1e-12);
        // the thickest slab (t·q_r = 100) is the semi-infinite body to chart accuracy
        let last = *td.a_r.last().unwrap();
        assert!((last / td.a_r_inf - 1.0).abs() < 1e-2, "{last} vs {}", td.a_r_inf);
        // without adhesion a thinner slab is more compliant: a_r grows as t shrinks
        let a0 = td.adhesionless.as_ref().unwrap();
        assert!(a0.windows(2).all(|w| w[0] >= w[1] * (1.0 - 1e-6)), "{a0:?}");
        // adhesion adds contact
        assert!(
            td.a_r
                .iter()
                .zip(a0)
                .filter(|(a, _)| a.is_finite())
                .all(|(a, b)| a >= b),
            "{td:?}"
        );
        // cancelled: nothing
        assert!(matches!(
            thickness_sweep(&scene, &AtomicBool::new(true)),
            Err(Error::Cancelled)
        ));
        scene.gamma = 0.0;
        assert!(thickness_sweep(&scene, &AtomicBool::new(false))
            .unwrap()
            .adhesionless
            .is_none());
    }

    #[test]
    #[ignore = "slow (~30 s on a loaded 2-core machine: a hard adhesive case); cargo test -- --ignored"]
    fn a_point_without_error_bar_is_shown_with_the_reason() {
        // system II, t·q_r = 0.1, p* = 1e-5: the self-consistency converges but neither
        // resolution check does (the engine refuses; `run` prints the converged a_r in its
        // message). The explorer shows that a_r, without an error bar, and says why.
        let mut scene = asperity::input::preset::Preset::resolve("system-2")
            .unwrap()
            .scene()
            .unwrap();
        scene.thickness_qr = 0.1;
        scene.pressure = 1e-5;
        let pd = evaluate_point(&scene, &AtomicBool::new(false), false).unwrap();
        let Some(msg) = pd.warning.clone() else {
            eprintln!("SKIPPED: the engine now estimates this point's error");
            return;
        };
        // the a_r in the panel is the one in the engine's message (6 digits)
        let quoted: f64 = msg
            .split("a_r = ")
            .nth(1)
            .and_then(|r| r.split(',').next())
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("no a_r in {msg}"));
        assert!((pd.a_r - quoted).abs() < 1e-6, "{} vs {quoted}", pd.a_r);
        assert!(pd.error_estimate.is_nan());
        assert!(pd.branch.ends_with("no error bar"), "{}", pd.branch);
        assert!(msg.contains("neither resolution check"), "{msg}");
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
            needs: Needs {
                point: true,
                loads: true,
                thickness: false,
            },
            models: Vec::new(),
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
                Reply::Thickness { .. } => "thickness",
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
    fn an_adhesive_point_comes_first_at_chart_accuracy_then_refined() {
        let mut c = Caches::default();
        let mut req = request(1, 0.01);
        req.scene.gamma = 0.05;
        let r = serve(&req, &mut c, false, false);
        // the load curves too come first as a preview (fewer loads), then in full
        assert_eq!(kinds(&r), ["point", "sweep", "sweep", "gap", "point", "done"]);
        let (Reply::Sweep { result: Ok(quick), .. }, Reply::Sweep { result: Ok(full), .. }) = (&r[1], &r[2]) else {
            panic!("{r:?}");
        };
        assert!(quick.preview && !full.preview);
        assert_eq!((quick.p.len(), full.p.len()), (PREVIEW_POINTS, SWEEP_POINTS));
        // the preview's loads are the full sweep's every third (both log-spaced over the range)
        for (k, p) in quick.p.iter().enumerate() {
            let q = full.p[3 * k];
            assert!((p / q - 1.0).abs() < 1e-12, "{p} vs {q}");
            assert!((quick.a_r[k] / full.a_r[3 * k] - 1.0).abs() < 1e-6, "{k}");
        }
        let (Reply::Point { result: Ok(first), .. }, Reply::Point { result: Ok(last), .. }) = (&r[0], &r[4]) else {
            panic!("{r:?}");
        };
        assert!(first.preview && first.error_estimate.is_nan());
        assert!(!last.preview && last.error_estimate.is_finite());
        // chart accuracy: a_r to ~2e-3 relative (engine::Options::chart)
        assert!(
            (first.a_r / last.a_r - 1.0).abs() < 1e-2,
            "{} vs {}",
            first.a_r,
            last.a_r
        );
        assert!(first.adhesionless.is_some() && first.wall.is_some());
        // the refined point is cached: the next time it comes at once, alone
        let again = serve(&req, &mut c, false, false);
        assert_eq!(kinds(&again), ["point", "sweep", "gap", "done"]);
        assert_eq!(again[0], r[4]);
        // stale after the preview: only the preview is sent, nothing refined is cached
        let mut c2 = Caches::default();
        assert_eq!(kinds(&serve(&req, &mut c2, false, true)), ["point"]);
        assert!(c2.points.is_empty() && c2.previews.len() == 1);
    }

    #[test]
    fn the_load_curves_carry_both_branches_and_the_jump() {
        // system 2, model 3, t·q_r = 0.1, γ_s = 0.8 × the preset's: a hysteresis window from
        // below p* = 1e-6 to the jump-in load near 2.4e-4 (loading a_r ≈ 0.03 at 1e-4,
        // unloading ≈ 0.43)
        let mut scene = asperity::input::preset::Preset::resolve("system-2")
            .unwrap()
            .scene()
            .unwrap();
        scene.model = Model::named(3).unwrap();
        scene.thickness_qr = 0.1;
        scene.gamma = 0.8 * 0.157;
        let spec = SweepSpec {
            from: 1e-4,
            to: 1e-3,
            points: 9,
        };
        let sd = load_sweep(&scene, &spec, &AtomicBool::new(false)).unwrap();
        assert_eq!(sd.a_r_unloading.len(), sd.p.len());
        assert!(sd.a_r_unloading[0] > 0.3 && sd.a_r_unloading[0] < 0.6, "{sd:?}");
        assert!(sd.a_r[0] < 0.1, "{sd:?}");
        assert!(sd.a_r_unloading.last().is_some_and(|a| a.is_nan()), "{sd:?}");
        assert_eq!(sd.pull_off, None, "the window runs below the range");
        let jump = sd.jump_in.expect("the jump-in load lies in the range");
        // independently: full-accuracy points a little below and above it (every branch
        // searched): two stable branches below, one above
        let stable = |p: f64| {
            let mut s = scene.clone();
            s.pressure = p;
            let ev = engine::evaluate(&s, &Options::default()).unwrap();
            ev.branches.iter().filter(|b| b.stable).count()
        };
        assert_eq!(stable(jump / 1.1), 2, "below {jump}");
        assert_eq!(stable(jump * 1.1), 1, "above {jump}");
        // the explorer's preview of the same range (PREVIEW_POINTS loads, its edge to
        // PREVIEW_EDGE_REL) shows both branches and a jump within its precision of the full
        // sweep's
        let quick = preview_sweep(&scene, (spec.from, spec.to), &AtomicBool::new(false)).unwrap();
        assert!(
            quick.preview && quick.a_r_unloading[0] > 0.3 && quick.a_r[0] < 0.1,
            "{quick:?}"
        );
        let quick_jump = quick.jump_in.expect("the preview's jump-in");
        assert!(
            (quick_jump / jump).ln().abs() < PREVIEW_EDGE_REL,
            "{quick_jump} vs {jump}"
        );
        let cancelled = load_sweep(&scene, &spec, &AtomicBool::new(true));
        assert!(matches!(cancelled, Err(Error::Cancelled)));
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
                Reply::Point { gen, .. }
                | Reply::Sweep { gen, .. }
                | Reply::Gap { gen, .. }
                | Reply::Thickness { gen, .. } => *gen,
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
