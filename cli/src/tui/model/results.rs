//! The engine's results for the scene and the curves pinned (each with the key of the scene it was computed for).

use crate::tui::base::data::{PointData, ScalesData, SweepData, ThicknessData};
use crate::tui::base::protocol::{CacheKey, SceneKeys};
use crate::tui::model::pins::Pin;
use asperity::error::Result;
use std::collections::HashMap;

/// The engine's results for the scene and the curves pinned (each with the key of the scene it was computed for).
#[derive(Debug)]
pub struct Results {
    /// Results of the other models (`M`), by cache key.
    pub overlay_points: HashMap<CacheKey, Result<PointData>>,
    /// Load sweeps of the other models, by cache key.
    pub overlay_sweeps: HashMap<CacheKey, Result<SweepData>>,
    /// Thickness sweeps of the other models, by cache key.
    pub overlay_thickness: HashMap<CacheKey, Result<ThicknessData>>,
    /// a_r(t·q_r) at the current p*.
    pub thickness: Option<Result<ThicknessData>>,
    /// The key of the shown point (None: set directly, e.g. in tests).
    pub point_shown: Option<CacheKey>,
    /// The key of the shown load sweep.
    pub sweep_shown: Option<CacheKey>,
    /// The key of the shown gap.
    pub gap_shown: Option<CacheKey>,
    /// The key of the shown thickness sweep.
    pub thickness_shown: Option<CacheKey>,
    /// The scale view: Pr(σ*, q) frames from q_L to q_s.
    pub scales: Option<Result<ScalesData>>,
    /// The key of the shown scale view.
    pub scales_shown: Option<CacheKey>,
    /// Pinned curves (`P`), oldest first.
    pub pins: Vec<Pin>,
    /// The current point (for the current scene, or the last one while computing).
    pub point: Option<Result<PointData>>,
    /// Generation of the request whose reply set [`Results::point`].
    pub point_gen: u64,
    /// The load curves.
    pub sweep: Option<Result<SweepData>>,
    /// ū/h_rms at the current point.
    pub gap: Option<Result<f64>>,
    /// The keys of the scene shown, which the `*_shown` keys and the other models' results are
    /// compared with (kept current by [`crate::tui::model::app::App::rekey`]; read them with
    /// [`Results::keys`]).
    pub(in crate::tui::model) keys: SceneKeys,
}

impl Results {
    /// The keys of the scene shown.
    pub fn keys(&self) -> &SceneKeys {
        &self.keys
    }
}
