//! The engine's results for the scene and the curves pinned (each with the key of the scene it was computed for).

use crate::tui::base::data::{PointData, ScalesData, SweepData, ThicknessData};
use crate::tui::base::protocol::{CacheKey, SceneKeys};
use crate::tui::model::pins::Pin;
use asperity::error::Result;
use std::collections::HashMap;

/// The engine's results for the scene and the curves pinned (each with the key of the scene it was computed for).
#[derive(Debug)]
pub struct Results {
    /// The other models' results (`M`): points, load sweeps and thickness sweeps in one store
    /// by cache key (the keys of [`SceneKeys::overlays`]; a kind's keys never equal another's);
    /// read it with [`Results::overlay_point`], [`Results::overlay_sweep`] and
    /// [`Results::overlay_thickness`].
    pub(crate) overlays: HashMap<CacheKey, Stored>,
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

/// One result of the other models' store (read with [`Results::overlay_point`] and its kin).
#[derive(Debug)]
pub enum Stored {
    /// A point.
    Point(Result<PointData>),
    /// A load sweep.
    Sweep(Result<SweepData>),
    /// A thickness sweep.
    Thickness(Result<ThicknessData>),
}

impl Results {
    /// The keys of the scene shown.
    pub fn keys(&self) -> &SceneKeys {
        &self.keys
    }

    /// The point stored under `key`, if one was computed without error.
    pub fn overlay_point(&self, key: &CacheKey) -> Option<&PointData> {
        match self.overlays.get(key) {
            Some(Stored::Point(Ok(p))) => Some(p),
            _ => None,
        }
    }

    /// The load sweep stored under `key`, if one was computed without error.
    pub fn overlay_sweep(&self, key: &CacheKey) -> Option<&SweepData> {
        match self.overlays.get(key) {
            Some(Stored::Sweep(Ok(s))) => Some(s),
            _ => None,
        }
    }

    /// The thickness sweep stored under `key`, if one was computed without error.
    pub fn overlay_thickness(&self, key: &CacheKey) -> Option<&ThicknessData> {
        match self.overlays.get(key) {
            Some(Stored::Thickness(Ok(t))) => Some(t),
            _ => None,
        }
    }

    /// Keeps `value` under `key`, forgetting everything when the store grows past a few
    /// hundred entries.
    pub(crate) fn store(&mut self, key: CacheKey, value: Stored) {
        if self.overlays.len() >= 256 {
            self.overlays.clear();
        }
        self.overlays.insert(key, value);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The store gives back what was stored under a key as the kind it was stored as, and
    /// nothing as another kind; it forgets everything past 256 entries rather than grow.
    #[test]
    fn the_store_keeps_each_kind_under_its_key() {
        let mut r = crate::tui::model::app::App::open(
            "system-1",
            asperity::input::preset::Preset::resolve("system-1").unwrap(),
            Vec::new(),
        )
        .unwrap()
        .results;
        let k = |i: u64| ("s".to_string(), i);
        let sweep = SweepData {
            p: vec![0.1],
            ..SweepData::default()
        };
        r.store(k(1), Stored::Sweep(Ok(sweep.clone())));
        r.store(k(2), Stored::Thickness(Ok(ThicknessData::default())));
        assert_eq!(r.overlay_sweep(&k(1)), Some(&sweep));
        assert!(r.overlay_thickness(&k(1)).is_none() && r.overlay_point(&k(1)).is_none());
        assert!(r.overlay_thickness(&k(2)).is_some() && r.overlay_sweep(&k(3)).is_none());
        for i in 3..300 {
            r.store(k(i), Stored::Sweep(Ok(SweepData::default())));
        }
        assert!(r.overlays.len() <= 256 && r.overlay_sweep(&k(1)).is_none());
        assert!(r.overlay_sweep(&k(299)).is_some());
    }
}
