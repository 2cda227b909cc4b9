//! The knobs of the parameter panel ([`Param`]) and their pure stepping: log grids anchored
//! at the preset's value (so stepping away and back returns to it exactly), the linear grids of
//! the custom model's coefficients, typed numbers (a typed value anchors its knob's grid until
//! the next typed value, see [`Anchors`]), and the load charts' p* range.

use asperity::error::{Error, Result};

/// An adjustable parameter (a row of the parameter panel).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// The preset.
    Preset,
    /// Model 1–4 or custom.
    Model,
    /// p*.
    Pressure,
    /// t·q_r (∞ = semi-infinite).
    Thickness,
    /// γ_s (0 = off).
    Gamma,
    /// Custom c₁.
    C1,
    /// Custom c₂.
    C2,
    /// Custom α.
    Alpha,
    /// Custom k_G.
    KGriffith,
    /// Custom σ_a cap.
    Cap,
}

impl Param {
    /// Label in the panel.
    pub fn label(self) -> &'static str {
        match self {
            Param::Preset => "preset",
            Param::Model => "model",
            Param::Pressure => "p*",
            Param::Thickness => "t·q_r",
            Param::Gamma => "γ_s J/m²",
            Param::C1 => "c1",
            Param::C2 => "c2",
            Param::Alpha => "alpha",
            Param::KGriffith => "k_G",
            Param::Cap => "cap σ_a",
        }
    }
}

pub(crate) const BASIC: [Param; 5] = [
    Param::Preset,
    Param::Model,
    Param::Pressure,
    Param::Thickness,
    Param::Gamma,
];

pub(crate) const CUSTOM: [Param; 5] = [Param::C1, Param::C2, Param::Alpha, Param::KGriffith, Param::Cap];

/// Steps per decade of the log-stepped parameters (fine, coarse).
pub const PRESSURE_STEPS: (f64, f64) = (20.0, 4.0);

/// p* range reachable with the arrow keys (typing reaches the engine's whole range).
pub const PRESSURE_KEYS: (f64, f64) = (1e-6, 1e2);

/// Steps per decade of t·q_r.
pub const THICKNESS_STEPS: (f64, f64) = (10.0, 2.0);

/// t·q_r range of the arrow keys; one step above the top is ∞.
pub const THICKNESS_KEYS: (f64, f64) = (1e-2, 1e4);

/// Steps per decade of γ_s.
pub const GAMMA_STEPS: (f64, f64) = (10.0, 2.0);

/// γ_s range of the arrow keys (J/m²); one step below the bottom is 0 (off).
pub const GAMMA_KEYS: (f64, f64) = (1e-4, 1.0);

/// The p* range of the load charts for a current p*: at least 1e-3..1, widened to whole
/// decades that include p*.
pub fn chart_range(p: f64) -> (f64, f64) {
    let (lo, hi) = asperity::input::scene::PRESSURE_RANGE;
    let p = if p.is_finite() && p > 0.0 { p } else { 1e-2 };
    let a = 10f64.powf(p.log10().floor()).min(1e-3).max(lo);
    let b = 10f64.powf(p.log10().ceil()).max(1.0).min(hi);
    (a, b)
}

/// The p* range of the load charts after p* moved to `p`: the previous range while it still
/// holds p (stepping p* then reuses the cached load sweep: on system II's thin slab each
/// decade boundary crossed cost a new sweep, ~0.85 s, where a step inside the range redraws
/// every chart in 0.09–0.14 s), else [`chart_range`] of p (not the union: a wider range costs
/// more loads).
pub fn sticky_range(prev: Option<(f64, f64)>, p: f64) -> (f64, f64) {
    match prev {
        Some((a, b)) if p >= a && p <= b => (a, b),
        _ => chart_range(p),
    }
}

/// Next grid value of a log-stepped parameter: `steps` grid points up (or down) from `x` on
/// the grid of `per_decade` points per decade. Off-grid values go to the neighbouring point.
pub fn log_step(x: f64, per_decade: f64, steps: i32) -> f64 {
    log_step_from(x, 1.0, per_decade, steps)
}

/// [`log_step`] on the grid anchor·10^(k/per_decade), which contains `anchor` (the preset's
/// value), so stepping away and back returns to it exactly.
pub fn log_step_from(x: f64, anchor: f64, per_decade: f64, steps: i32) -> f64 {
    let anchor = if anchor.is_finite() && anchor > 0.0 {
        anchor
    } else {
        1.0
    };
    let u = (x / anchor).log10() * per_decade;
    let k = if steps > 0 {
        (u + 1e-9).floor() + steps as f64
    } else {
        (u - 1e-9).ceil() + steps as f64
    };
    if k == 0.0 {
        anchor
    } else {
        anchor * 10f64.powf(k / per_decade)
    }
}

/// An additive step on a grid of `step` (values snap to the grid, so toggling back is exact).
pub fn lin_step(x: f64, step: f64, steps: i32) -> f64 {
    lin_step_from(x, 0.0, step, steps)
}

/// [`lin_step`] on the grid anchor + k·step, which contains `anchor` (a typed value).
pub fn lin_step_from(x: f64, anchor: f64, step: f64, steps: i32) -> f64 {
    let anchor = if anchor.is_finite() { anchor } else { 0.0 };
    let u = (x - anchor) / step;
    let k = if steps > 0 {
        (u + 1e-9).floor() + steps as f64
    } else {
        (u - 1e-9).ceil() + steps as f64
    };
    let v = if k == 0.0 { anchor } else { anchor + k * step };
    // −0 → 0
    if v == 0.0 {
        0.0
    } else {
        v
    }
}

/// The typed values that anchor their knob's grid: after typing t·q_r = 0.123 the arrows step
/// 0.123 → 0.155 → 0.123 on the grid 0.123·10^(k/10), not on the preset's grid (which would
/// lose the typed value at the first step). A new typed value replaces its knob's anchor; a
/// preset, a reset or a tour step clears them all (the preset's grids again).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Anchors {
    /// p*.
    pub pressure: Option<f64>,
    /// t·q_r (finite).
    pub thickness: Option<f64>,
    /// γ_s (> 0).
    pub gamma: Option<f64>,
    /// The custom model's c₁, c₂, α, k_G.
    pub coefficients: [Option<f64>; 4],
}

impl Anchors {
    /// The anchor of `param`'s grid, if a value was typed for it.
    pub fn get(&self, param: Param) -> Option<f64> {
        match param {
            Param::Pressure => self.pressure,
            Param::Thickness => self.thickness,
            Param::Gamma => self.gamma,
            Param::C1 => self.coefficients[0],
            Param::C2 => self.coefficients[1],
            Param::Alpha => self.coefficients[2],
            Param::KGriffith => self.coefficients[3],
            Param::Preset | Param::Model | Param::Cap => None,
        }
    }

    /// Records a typed value of `param`; a value that is no grid point (t·q_r = ∞, γ_s = 0:
    /// the ends of the arrows' range) anchors nothing.
    pub fn typed(&mut self, param: Param, v: f64) {
        let usable = v.is_finite() && (v > 0.0 || !matches!(param, Param::Pressure | Param::Thickness | Param::Gamma));
        let v = usable.then_some(v);
        match param {
            Param::Pressure => self.pressure = v,
            Param::Thickness => self.thickness = v,
            Param::Gamma => self.gamma = v,
            Param::C1 => self.coefficients[0] = v,
            Param::C2 => self.coefficients[1] = v,
            Param::Alpha => self.coefficients[2] = v,
            Param::KGriffith => self.coefficients[3] = v,
            Param::Preset | Param::Model | Param::Cap => {}
        }
    }
}

pub(crate) fn parse_number(field: &str, s: &str) -> Result<f64> {
    s.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| Error::field(field, s, "a number"))
}

pub(crate) fn parse_bool(field: &str, s: &str) -> Result<bool> {
    match s.trim().to_ascii_lowercase().as_str() {
        "1" | "y" | "yes" | "true" | "on" => Ok(true),
        "0" | "n" | "no" | "false" | "off" => Ok(false),
        _ => Err(Error::field(field, s, "yes or no")),
    }
}

/// The panel row of a tour step's knob.
pub fn knob_param(k: crate::tui::base::tour::Knob) -> Param {
    use crate::tui::base::tour::Knob;
    match k {
        Knob::Preset => Param::Preset,
        Knob::Model => Param::Model,
        Knob::Pressure => Param::Pressure,
        Knob::Thickness => Param::Thickness,
        Knob::Gamma => Param::Gamma,
    }
}
