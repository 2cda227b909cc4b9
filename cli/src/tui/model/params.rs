//! The scene's parameters: the presets, the preset, the scene being explored and the path of loads it took.

use crate::tui::model::history::LoadHistory;
use crate::tui::model::knobs::Anchors;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::heightmap::Surface;
use std::sync::Arc;

/// One entry of the preset picker.
#[derive(Debug, Clone, PartialEq)]
pub struct PresetEntry {
    /// Name or path passed to [`Preset::resolve`].
    pub source: String,
    /// Where it comes from ("built-in", a path).
    pub place: String,
}

/// The scene's parameters.
#[derive(Debug)]
pub struct Params {
    /// Presets the picker offers.
    pub presets: Vec<PresetEntry>,
    /// The current preset's source (name or path).
    pub source: String,
    /// The current preset.
    pub preset: Preset,
    /// The preset's scene (what `r` goes back to).
    pub base: Scene,
    /// The scene being explored.
    pub scene: Scene,
    /// Typed values that anchor their knob's grid (see [`Anchors`]).
    pub anchors: Anchors,
    /// The branch of a hysteresis the user's path has reached (`r` resets it).
    pub history: LoadHistory,
    /// The measured height map of `tui --surface` (its file name, as the tabulated spectrum
    /// names it, and the map): `g` runs GFMD on it while the scene is on its spectrum.
    pub map: Option<(String, Arc<Surface>)>,
    /// The measured surface the scene was opened on (`tui --surface`/`--psd` with their
    /// flags, or a preset's `[measured]`), which `e` writes into the scene's preset so that it
    /// reopens on it.
    pub measured: Option<asperity::input::preset::MeasuredSpec>,
}
