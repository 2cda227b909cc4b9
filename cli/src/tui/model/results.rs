//! The engine's results, in one store keyed by [`CacheKey`]: the current scene's point, load
//! sweep, gap, thickness sweep and scale view, and the other models' points and sweeps (`M`).
//! A result is stored under the key of the scene it was computed for; what the screen shows
//! of each kind is the entry under the key last received for the current model, which the view
//! compares with [`SceneKeys`] (computed once per scene change) to say "computing…" while a new
//! one is on its way. Nothing here hashes.

use crate::tui::base::data::{PointData, ScalesData, SweepData, ThicknessData};
use crate::tui::base::protocol::{CacheKey, SceneKeys};
use crate::tui::model::pins::Pin;
use asperity::error::Result;
use std::collections::HashMap;

/// The kinds of result (a point and its gap share the scene's key, so the kind is part of the
/// store's key).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Slot {
    /// The point.
    Point,
    /// The load sweep of the load charts.
    Sweep,
    /// ū/h_rms at the point.
    Gap,
    /// a_r(t·q_r) at the point's p*.
    Thickness,
    /// The scale view.
    Scales,
}

impl Slot {
    const ALL: [Slot; 5] = [Slot::Point, Slot::Sweep, Slot::Gap, Slot::Thickness, Slot::Scales];

    fn index(self) -> usize {
        self as usize
    }

    /// The key of this kind of result for the scene of `keys`.
    pub fn key_in(self, keys: &SceneKeys) -> &CacheKey {
        match self {
            Slot::Point | Slot::Gap => &keys.point,
            Slot::Sweep => &keys.sweep,
            Slot::Thickness => &keys.thickness,
            Slot::Scales => &keys.scales,
        }
    }
}

/// One stored result.
#[derive(Debug, Clone)]
pub enum Stored {
    /// A point.
    Point(Result<PointData>),
    /// A load sweep.
    Sweep(Result<SweepData>),
    /// ū/h_rms.
    Gap(Result<f64>),
    /// A thickness sweep.
    Thickness(Result<ThicknessData>),
    /// A scale view.
    Scales(Result<ScalesData>),
}

impl Stored {
    /// The kind of result this is.
    pub fn slot(&self) -> Slot {
        match self {
            Stored::Point(_) => Slot::Point,
            Stored::Sweep(_) => Slot::Sweep,
            Stored::Gap(_) => Slot::Gap,
            Stored::Thickness(_) => Slot::Thickness,
            Stored::Scales(_) => Slot::Scales,
        }
    }
}

/// Entries the store keeps before it forgets all but the shown ones.
const CAPACITY: usize = 256;

/// The engine's results and the curves pinned.
#[derive(Debug)]
pub struct Results {
    /// Every result, by kind and the key of the scene it was computed for.
    store: HashMap<(Slot, CacheKey), Stored>,
    /// Per kind, the key of the current model's result shown (the last received; it may be an
    /// earlier scene's while the new one is computed). None: none received yet.
    shown: [Option<CacheKey>; 5],
    /// Pinned curves (`P`), oldest first.
    pub pins: Vec<Pin>,
    /// Generation of the request whose reply set the point shown.
    pub point_gen: u64,
    /// The keys of the scene shown (kept current by [`crate::tui::model::app::App::rekey`]).
    pub(in crate::tui::model) keys: SceneKeys,
}

/// The shown result of one kind, typed: `$get` reads it, `$get_mut` changes it in place (a
/// test's edit), `$set` stores one for the current scene and shows it.
macro_rules! slot_access {
    ($slot:ident, $ty:ty, $get:ident, $get_mut:ident, $set:ident) => {
        /// The shown result of this kind (None: none received yet).
        pub fn $get(&self) -> Option<&Result<$ty>> {
            match self.shown_entry(Slot::$slot)? {
                Stored::$slot(r) => Some(r),
                _ => None,
            }
        }

        /// The shown result of this kind, to change in place.
        pub fn $get_mut(&mut self) -> Option<&mut Result<$ty>> {
            let key = self.shown[Slot::$slot.index()].clone()?;
            match self.store.get_mut(&(Slot::$slot, key))? {
                Stored::$slot(r) => Some(r),
                _ => None,
            }
        }

        /// Stores `value` as the current scene's result of this kind and shows it.
        pub fn $set(&mut self, value: Result<$ty>) {
            let key = Slot::$slot.key_in(&self.keys).clone();
            self.put(key, Stored::$slot(value), true);
        }
    };
}

impl Results {
    /// An empty store for the scene of `keys`.
    pub fn new(keys: SceneKeys) -> Results {
        Results {
            store: HashMap::new(),
            shown: Default::default(),
            pins: Vec::new(),
            point_gen: 0,
            keys,
        }
    }

    /// The keys of the scene shown.
    pub fn keys(&self) -> &SceneKeys {
        &self.keys
    }

    slot_access!(Point, PointData, point, point_mut, set_point);
    slot_access!(Sweep, SweepData, sweep, sweep_mut, set_sweep);
    slot_access!(Gap, f64, gap, gap_mut, set_gap);
    slot_access!(Thickness, ThicknessData, thickness, thickness_mut, set_thickness);
    slot_access!(Scales, ScalesData, scales, scales_mut, set_scales);

    /// Whether the shown result of `slot` belongs to an earlier scene (false where none is
    /// shown: the view then says "computing…" or nothing).
    pub fn is_stale(&self, slot: Slot) -> bool {
        self.shown[slot.index()]
            .as_ref()
            .is_some_and(|k| k != slot.key_in(&self.keys))
    }

    /// Whether the shown result of `slot` is the current scene's.
    pub fn is_current(&self, slot: Slot) -> bool {
        self.shown[slot.index()].as_ref() == Some(slot.key_in(&self.keys))
    }

    /// Forgets what is shown of `slot` (the store keeps the entry).
    pub fn unshow(&mut self, slot: Slot) {
        self.shown[slot.index()] = None;
    }

    fn shown_entry(&self, slot: Slot) -> Option<&Stored> {
        let key = self.shown[slot.index()].clone()?;
        self.store.get(&(slot, key))
    }

    /// The point stored under `key`, if one was computed without error.
    pub fn overlay_point(&self, key: &CacheKey) -> Option<&PointData> {
        match self.store.get(&(Slot::Point, key.clone())) {
            Some(Stored::Point(Ok(p))) => Some(p),
            _ => None,
        }
    }

    /// The load sweep stored under `key`, if one was computed without error.
    pub fn overlay_sweep(&self, key: &CacheKey) -> Option<&SweepData> {
        match self.store.get(&(Slot::Sweep, key.clone())) {
            Some(Stored::Sweep(Ok(s))) => Some(s),
            _ => None,
        }
    }

    /// The thickness sweep stored under `key`, if one was computed without error.
    pub fn overlay_thickness(&self, key: &CacheKey) -> Option<&ThicknessData> {
        match self.store.get(&(Slot::Thickness, key.clone())) {
            Some(Stored::Thickness(Ok(t))) => Some(t),
            _ => None,
        }
    }

    /// Keeps `value` under `key` (and shows it where `show`); past [`CAPACITY`] entries the
    /// store forgets all but the shown ones rather than grow.
    pub(crate) fn put(&mut self, key: CacheKey, value: Stored, show: bool) {
        let slot = value.slot();
        if self.store.len() >= CAPACITY {
            let shown: Vec<(Slot, CacheKey)> = Slot::ALL
                .iter()
                .filter_map(|&s| Some((s, self.shown[s.index()].clone()?)))
                .collect();
            self.store.retain(|k, _| shown.contains(k));
        }
        if show {
            self.shown[slot.index()] = Some(key.clone());
        }
        self.store.insert((slot, key), value);
    }

    /// Number of entries stored.
    pub fn len(&self) -> usize {
        self.store.len()
    }

    /// Whether nothing is stored.
    pub fn is_empty(&self) -> bool {
        self.store.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The store gives back what was stored under a key as the kind it was stored as, and
    /// nothing as another kind; past its capacity it forgets all but the shown entries.
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
        r.put(k(1), Stored::Sweep(Ok(sweep.clone())), false);
        r.put(k(2), Stored::Thickness(Ok(ThicknessData::default())), false);
        assert_eq!(r.overlay_sweep(&k(1)), Some(&sweep));
        assert!(r.overlay_thickness(&k(1)).is_none() && r.overlay_point(&k(1)).is_none());
        assert!(r.overlay_thickness(&k(2)).is_some() && r.overlay_sweep(&k(3)).is_none());
        for i in 3..300 {
            r.put(k(i), Stored::Sweep(Ok(SweepData::default())), false);
        }
        assert!(r.len() <= CAPACITY && r.overlay_sweep(&k(1)).is_none());
        assert!(r.overlay_sweep(&k(299)).is_some());
        // the shown point survives the clearing, and is current for its scene's key
        r.set_point(Err(asperity::error::Error::io("t", "x")));
        assert!(r.is_current(Slot::Point) && !r.is_stale(Slot::Point));
        for i in 300..700 {
            r.put(k(i), Stored::Sweep(Ok(SweepData::default())), false);
        }
        assert!(matches!(r.point(), Some(Err(_))));
        // a point and its gap share the scene's key, each kept as its own kind
        r.set_gap(Ok(0.5));
        assert!(matches!(r.gap(), Some(Ok(g)) if *g == 0.5) && r.point().is_some());
        r.unshow(Slot::Point);
        assert!(r.point().is_none() && !r.is_stale(Slot::Point));
    }
}
