//! Pinned curves (`P`): the theory curves of the visible charts kept, with the scene they
//! belong to, while the scene changes; every later chart of the same kind draws them under
//! its own curves, each named by what differs from the current scene (t·q_r = 0.1, model 4,
//! γ_s = 0, …). `u` unpins the newest, `U` all. Plain data and pure functions: the state
//! keeps the pins, the chart builder draws them ([`crate::tui::charts::build`]), `e`/`s` export
//! them.

use crate::numfmt::short;
use crate::tui::base::kinds::ChartKind;
use asperity::input::scene::Scene;

/// Most pins kept (each has its own colour; the oldest goes first).
pub const MAX_PINS: usize = 6;

/// One pin: a scene and its theory curves, per chart kind.
#[derive(Debug, Clone, PartialEq)]
pub struct Pin {
    /// The scene the curves belong to.
    pub scene: Scene,
    /// The theory curve of each chart that was visible, in data units.
    pub curves: Vec<(ChartKind, Vec<(f64, f64)>)>,
}

/// What differs between a pin's scene and the current one, in the explorer's words
/// ("t·q_r=0.1, model 4"); the pinned scene's thickness when nothing differs.
pub fn label(pin: &Scene, now: &Scene) -> String {
    let mut parts = Vec::new();
    if pin.model() != now.model() {
        parts.push(pin.model().label());
    }
    if pin.thickness_qr().to_bits() != now.thickness_qr().to_bits() {
        parts.push(format!("t·q_r={}", thickness(pin.thickness_qr())));
    }
    if pin.surface_energy_j_m2() != now.surface_energy_j_m2() {
        parts.push(format!("γ_s={}", short(pin.surface_energy_j_m2())));
    }
    if pin.pressure() != now.pressure() {
        parts.push(format!("p*={}", short(pin.pressure())));
    }
    if pin.spectrum() != now.spectrum()
        || pin.contact_modulus_pa() != now.contact_modulus_pa()
        || pin.range_m() != now.range_m()
    {
        parts.push("other surface".into());
    }
    if parts.is_empty() {
        format!("pin t·q_r={}", thickness(pin.thickness_qr()))
    } else {
        parts.join(", ")
    }
}

fn thickness(t: f64) -> String {
    if t.is_infinite() {
        "∞".into()
    } else {
        short(t)
    }
}

/// Removes the newest pin (or all); returns what the status line says.
pub fn unpin(pins: &mut Vec<Pin>, all: bool, now: &Scene) -> String {
    if all {
        let n = pins.len();
        pins.clear();
        return format!("{n} pins removed");
    }
    match pins.pop() {
        Some(p) => format!("unpinned {}", label(&p.scene, now)),
        None => "no pin: P pins the visible curves".into(),
    }
}
