//! What the explorer and its worker say to each other: a [`Request`] (a generation, the
//! scene, what the visible charts need), the [`Reply`]s, and the cache keys that tie a reply
//! to the scene it belongs to. Plain data, shared by the state and the worker.

use crate::tui::base::data::{PointData, ScalesData, SweepData, ThicknessData};
use crate::tui::base::kinds::Needs;
pub use crate::tui::base::progress::GfmdProgress;
use asperity::error::Result;
use asperity::input::model::Model;
use asperity::input::scene::Scene;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};

/// Points of the load sweeps (the charts show at most ~80 columns of braille, 2 dots each;
/// 64 points joined by lines are indistinguishable from more).
pub const SWEEP_POINTS: usize = 64;

/// Points of the quick first load sweep of an adhesive scene, drawn while the full one runs:
/// every third p* of the full sweep's [`SWEEP_POINTS`], at the U-table step
/// [`PREVIEW_STEP_LN`] (no refinement over the ≤ 6 decades of a chart range), with the window
/// edges to [`crate::tui::effects::engine::PREVIEW_EDGE_REL`]. On system II's thin slab inside its hysteresis window
/// (t·q_r = 0.1, γ_s = 0.1256 J/m², 1e-5…1) it costs about half the full sweep (~100 ms
/// against ~200 ms of solves).
pub const PREVIEW_POINTS: usize = 22;

/// Largest U-table step (ln p*) of the preview sweep ([`PREVIEW_POINTS`]).
pub const PREVIEW_STEP_LN: f64 = 1.0;

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
    /// The scene with another model; None where the scene does not take it (a variant
    /// defined on the adhesionless half-space only, on an adhesive or slab scene).
    pub fn with_model(&self, m: &Model) -> Option<Scene> {
        self.scene.clone().with_model(*m).ok()
    }
}

/// A cache key: the preset's identity and a hash of what the result depends on (the scene's
/// own `Hash`: every input by bit pattern, so equal scenes share a key).
pub type CacheKey = (String, u64);

/// Hashes with a fixed hasher (keys are compared within one process only).
fn key_of(source: &str, f: impl FnOnce(&mut DefaultHasher)) -> CacheKey {
    let mut h = DefaultHasher::new();
    f(&mut h);
    (source.to_string(), h.finish())
}

/// The key of everything that depends on the whole scene (p* included).
pub fn point_key(source: &str, scene: &Scene) -> CacheKey {
    key_of(source, |h| {
        0u8.hash(h);
        scene.hash(h);
    })
}

/// The key of a load sweep: the scene without p*, plus the range.
pub fn sweep_key(source: &str, scene: &Scene, range: (f64, f64)) -> CacheKey {
    key_of(source, |h| {
        1u8.hash(h);
        scene.hash_without_pressure(h);
        [range.0.to_bits(), range.1.to_bits(), SWEEP_POINTS as u64].hash(h);
    })
}

/// The key of a thickness sweep: the scene without t·q_r, with p*.
pub fn thickness_key(source: &str, scene: &Scene) -> CacheKey {
    let s = scene.half_space();
    key_of(source, |h| {
        2u8.hash(h);
        s.hash(h);
        (THICKNESS_POINTS as u64).hash(h);
    })
}

/// Frames of the scale view (Pr(σ*, q) snapshots from q_L to q_s): 48 frames played at 10
/// per second take about 5 s, and neighbouring frames differ by ~1/48 of the march in ln q.
pub const SCALE_FRAMES: usize = 48;

/// The key of the scale view: the whole scene (p* included).
pub fn scales_key(source: &str, scene: &Scene) -> CacheKey {
    key_of(source, |h| {
        3u8.hash(h);
        scene.hash(h);
        (SCALE_FRAMES as u64, SIGMA_POINTS as u64).hash(h);
    })
}

/// The cache keys of the scene shown: computed once when the preset, the scene or the load
/// charts' range changes ([`SceneKeys::is_for`] compares without hashing), so the view and
/// the chart builders compare keys and hash nothing.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneKeys {
    /// The preset's identity, the scene and the range the keys were computed for.
    of: (String, Scene, (f64, f64)),
    /// [`point_key`] of the scene (the point, the gap).
    pub point: CacheKey,
    /// [`sweep_key`] of the scene and range.
    pub sweep: CacheKey,
    /// [`thickness_key`] of the scene.
    pub thickness: CacheKey,
    /// [`scales_key`] of the scene.
    pub scales: CacheKey,
    /// The other models the scene takes (`M`), each with its point, sweep and thickness keys.
    pub overlays: Vec<(Model, [CacheKey; 3])>,
}

impl SceneKeys {
    /// The keys of `scene` of preset `source` with the load charts over `range`.
    pub fn of(source: &str, scene: &Scene, range: (f64, f64)) -> SceneKeys {
        let overlays = crate::tui::base::kinds::overlay_models(scene)
            .into_iter()
            .filter_map(|m| {
                let s = scene.clone().with_model(m).ok()?;
                Some((
                    m,
                    [
                        point_key(source, &s),
                        sweep_key(source, &s, range),
                        thickness_key(source, &s),
                    ],
                ))
            })
            .collect();
        SceneKeys {
            of: (source.to_string(), scene.clone(), range),
            point: point_key(source, scene),
            sweep: sweep_key(source, scene, range),
            thickness: thickness_key(source, scene),
            scales: scales_key(source, scene),
            overlays,
        }
    }

    /// Whether these are the keys of `scene` of `source` over `range` (compared, not hashed).
    pub fn is_for(&self, source: &str, scene: &Scene, range: (f64, f64)) -> bool {
        self.of.0 == source && self.of.1 == *scene && self.of.2 == range
    }

    /// The point, sweep and thickness keys of model `m` on the scene (None: a model the scene
    /// does not take, or not among the overlaid ones).
    pub fn of_model(&self, m: &Model) -> Option<&[CacheKey; 3]> {
        self.overlays.iter().find(|(o, _)| o == m).map(|(_, k)| k)
    }
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
    /// The scale view of the current scene.
    Scales {
        /// Generation.
        gen: u64,
        /// [`scales_key`].
        key: CacheKey,
        /// The frames, or the error.
        result: Result<ScalesData>,
    },
    /// Progress of the background GFMD run `id`: its phase, solver steps, residual, time.
    GfmdProgress {
        /// Run id.
        id: u64,
        /// The report.
        progress: GfmdProgress,
    },
    /// The background GFMD run `id` finished (or failed, or was cancelled).
    GfmdDone {
        /// Run id.
        id: u64,
        /// The run, or its error.
        result: Result<crate::tui::base::gfmd_view::GfmdView>,
        /// Seconds the whole job took.
        elapsed_s: f64,
    },
    /// The worker failed on this generation's request (a fault in the computation, caught):
    /// the explorer shows `message` where the results would be, and stays responsive.
    Fault {
        /// Generation.
        gen: u64,
        /// What failed, in one line.
        message: String,
    },
    /// Everything of this generation has been sent.
    Done {
        /// Generation.
        gen: u64,
    },
}
