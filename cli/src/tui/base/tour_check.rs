//! A tour caption's claims as data: a quantity of the step's scene (with overrides) and what
//! the caption says about it (a value, bounds, or an order against another quantity or
//! scene). `cli/tests/tui_tour_claims.rs` evaluates every one with the engine.

use serde::Deserialize;

/// Quantities a [`Check`] can state (evaluated by the claims test with the engine):
/// `a_r`, `sigma_a` (σ_a* at q_s: the wall sits at −σ_a*), `a_r/p*`, `eq18/p*` (the closed form [S-18]), `mean_contact_stress` (σ̄_c*),
/// `gap_rel` (ū/h_rms), `width` (Δ* of the adhesionless Pr), `gamma_glo` (γ̃_glo),
/// `tensile_area` (∫ Pr over σ* < 0), `tensile_fraction` (tensile_area / a_r), `W` (the model's
/// W at `a_r`), `a_r_unloading` (the unloading branch at the load), `jump_in` (p* where the
/// loading branch ends, from a load sweep p*/10…10p*), `pr_linearity` (Pr(σ₁)/σ₁ over Pr(σ₂)/σ₂
/// at the first two stresses of the engine's grid), `reference:Q` (the preset's
/// `[[reference]]` value of quantity Q at the scene's p*).
pub const QUANTITIES: [&str; 14] = [
    "a_r",
    "sigma_a",
    "a_r/p*",
    "eq18/p*",
    "mean_contact_stress",
    "gap_rel",
    "width",
    "gamma_glo",
    "tensile_area",
    "tensile_fraction",
    "W",
    "a_r_unloading",
    "jump_in",
    "pr_linearity",
];

/// The other side of a comparison: the same quantity and scene unless overridden.
#[derive(Debug, Clone, PartialEq, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Side {
    /// Another quantity (default: the check's).
    pub quantity: Option<String>,
    /// Another model.
    pub model: Option<u8>,
    /// Another p*.
    pub pressure: Option<f64>,
    /// Another γ_s.
    pub gamma: Option<f64>,
    /// Another t·q_r.
    pub thickness_qr: Option<f64>,
}

/// A claim of a caption as data: a quantity of the step's scene (with overrides) and what the
/// caption says about it.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Check {
    /// The claim in words (shown when the check fails).
    pub says: String,
    /// See [`QUANTITIES`].
    pub quantity: String,
    /// Model instead of the step's.
    pub model: Option<u8>,
    /// p* instead of the step's.
    pub pressure: Option<f64>,
    /// γ_s instead of the step's.
    pub gamma: Option<f64>,
    /// t·q_r instead of the step's.
    pub thickness_qr: Option<f64>,
    /// a_r at which `W` is evaluated.
    pub a_r: Option<f64>,
    /// The stated value.
    pub value: Option<f64>,
    /// Relative tolerance of `value` and of `near` (0.005 when not given: a value quoted to
    /// three digits).
    pub rel: Option<f64>,
    /// Lower bound.
    pub min: Option<f64>,
    /// Upper bound.
    pub max: Option<f64>,
    /// The quantity lies below this one.
    pub below: Option<Side>,
    /// The quantity lies above this one.
    pub above: Option<Side>,
    /// The quantity lies within `rel` of this one.
    pub near: Option<Side>,
}

impl Check {
    /// The relative tolerance of `value` and `near`.
    pub fn rel(&self) -> f64 {
        self.rel.unwrap_or(0.005)
    }

    /// Checks the claim is well formed: known quantities, something stated, W with its a_r.
    pub fn validate(&self) -> std::result::Result<(), String> {
        let known = |q: &str| QUANTITIES.contains(&q) || q.strip_prefix("reference:").is_some_and(|r| !r.is_empty());
        if !known(&self.quantity) {
            return Err(format!(
                "quantity = {}; allowed {}, reference:QUANTITY",
                asperity::error::fmt_text(&self.quantity),
                QUANTITIES.join(", ")
            ));
        }
        for s in [&self.below, &self.above, &self.near].into_iter().flatten() {
            if let Some(q) = &s.quantity {
                if !known(q) {
                    return Err(format!(
                        "quantity = {} of a comparison; allowed {}",
                        asperity::error::fmt_text(q),
                        QUANTITIES.join(", ")
                    ));
                }
            }
        }
        if self.value.is_none()
            && self.min.is_none()
            && self.max.is_none()
            && self.below.is_none()
            && self.above.is_none()
            && self.near.is_none()
        {
            return Err("states nothing: give value, min, max, below, above or near".into());
        }
        if self.quantity == "W" && self.a_r.is_none() {
            return Err("W needs a_r".into());
        }
        if self.says.trim().is_empty() {
            return Err("says must not be empty".into());
        }
        Ok(())
    }
}
