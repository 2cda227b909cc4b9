//! How far to trust the theory for a scene: where the scene lies relative to asperity's GFMD
//! reference set ([`super::reference_set`]) and how far the theory was measured from brute
//! force at the nearest stored points.
//!
//! The scene is placed by three dimensionless numbers: p* (log), γ̃_glo [S-24] of the scene
//! (the slab's; it carries the thickness and the surface energy together) and the thinness
//! τ = log₁₀(1 + 1/(t·q_r)) (0 for a half-space, 1.04 at t·q_r = 0.1). Distance to a stored
//! point: √((Δlog₁₀p*)² + (Δγ̃_glo/0.1)² + (Δτ)²), so one step of the set (a factor ≈ 2 in
//! p*, a thickness, γ_s × 2 at the half-space) is about one unit. Inside the set means p* and
//! t·q_r inside the ranges the set covers and γ̃_glo at most its largest; outside, each
//! excess is named ("p* 1e-06 is 2.0 decades below the set's 1e-4").
//!
//! The error read-out is over the [`NEAREST`] nearest loading points that have a theory value:
//! the mean and largest |ln(theory/GFMD)| of a_r and of ū/h_rms, for the model the set's theory
//! columns hold (the preset's: 4 for system II, 3 for system I; model 5 has its own columns on
//! system II). For another model the numbers are still given, labelled with the model they were
//! measured for.
//!
//! An adhesive model 5 scene whose bandwidth λ_r/λ_s is nearer the full system's 128 than the
//! set's 16 (above √(16·128) ≈ 45) reads its error from the bandwidth set instead: model 5 on
//! the full system II against the widest GFMD of each case (1024², λ_r/λ_s = 64; 2048² for the
//! half-space at the preset's γ_s), a_r only. There the set's 256² maps would misstate it: the
//! gauge's measure γ̃_glo·√μ_T serves the wide bandwidths best (docs/physics.md §3.6).

use super::reference_set::{bandwidth_set, reference_set, ReferencePoint, SET_GRID};
use crate::input::scene::Scene;
use crate::theory::cycle::PathBranch;
use serde::Serialize;

/// Stored points the error read-out averages over.
pub const NEAREST: usize = 4;
/// γ̃_glo per unit of distance.
const GAMMA_GLO_UNIT: f64 = 0.1;

/// The ranges the reference set covers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SetRange {
    /// Smallest and largest positive p* stored.
    pub pressure: [f64; 2],
    /// Thinnest slab stored (t·q_r); the set also holds the half-space.
    pub thickness_qr_min: f64,
    /// Largest γ̃_glo stored.
    pub gamma_glo_max: f64,
    /// Grid side of the stored maps.
    pub grid: usize,
}

/// One stored point near the scene, with the theory's error there.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NearPoint {
    /// System of \[S\] (1 or 2).
    pub system: u8,
    /// t·q_r (null: a half-space).
    pub thickness_qr: Option<f64>,
    /// γ̃_glo.
    pub gamma_glo: f64,
    /// p*.
    pub p: f64,
    /// GFMD's a_r (mean over seeds).
    pub a_r_gfmd: f64,
    /// The theory's a_r on the same maps.
    pub a_r_theory: f64,
    /// GFMD's ū/h_rms.
    pub mean_gap_rel_gfmd: f64,
    /// The theory's ū/h_rms on the same maps (null where it has none).
    pub mean_gap_rel_theory: Option<f64>,
    /// Distance from the scene (see the module docs).
    pub distance: f64,
}

/// Where a scene lies relative to the reference set and the theory's measured error near it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trust {
    /// Inside the set's ranges.
    pub inside: bool,
    /// Each way the scene lies outside, in words (empty inside).
    pub outside: Vec<String>,
    /// The set's ranges.
    pub set: SetRange,
    /// The nearest stored loading points with a theory value.
    pub nearest: Vec<NearPoint>,
    /// The model whose error was measured there.
    pub measured_model: u8,
    /// Whether that is the scene's model.
    pub same_model: bool,
    /// Mean |ln(theory/GFMD)| of a_r over the nearest points.
    pub a_r_log_error: f64,
    /// Largest theory/GFMD (or GFMD/theory) ratio of a_r among them.
    pub a_r_worst_ratio: f64,
    /// Mean |ln(theory/GFMD)| of ū/h_rms (null where no point has a theory gap).
    pub mean_gap_log_error: Option<f64>,
    /// One line for a table.
    pub summary: String,
}

/// τ = log₁₀(1 + 1/(t·q_r)).
fn thinness(t: f64) -> f64 {
    (1.0 + 1.0 / t).log10()
}

fn distance(p: f64, glo: f64, tau: f64, r: &ReferencePoint) -> f64 {
    let dp = (p / r.p).log10();
    let dg = (glo - r.gamma_glo) / GAMMA_GLO_UNIT;
    let dt = tau - thinness(r.thickness_qr);
    (dp * dp + dg * dg + dt * dt).sqrt()
}

/// The ranges of the stored set.
pub fn set_range() -> SetRange {
    let set = reference_set();
    let pos = set.iter().filter(|r| r.p > 0.0);
    let (lo, hi) = pos
        .clone()
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), r| (lo.min(r.p), hi.max(r.p)));
    SetRange {
        pressure: [lo, hi],
        thickness_qr_min: set.iter().map(|r| r.thickness_qr).fold(f64::INFINITY, f64::min),
        gamma_glo_max: set
            .iter()
            .map(|r| r.gamma_glo)
            .filter(|g| g.is_finite())
            .fold(0.0, f64::max),
        grid: SET_GRID,
    }
}

/// The trust read-out of `scene` (see the module docs).
pub fn assess(scene: &Scene) -> Trust {
    let (p, t, glo) = (scene.pressure(), scene.thickness_qr(), scene.gamma_glo());
    let tau = thinness(t);
    let set = set_range();
    let mut outside = Vec::new();
    if p < set.pressure[0] {
        outside.push(format!(
            "p* {p:.3e} is {:.1} decades below the set's {:.0e}",
            (set.pressure[0] / p).log10(),
            set.pressure[0]
        ));
    } else if p > set.pressure[1] {
        outside.push(format!(
            "p* {p:.3e} is {:.1} decades above the set's {:.0e}",
            (p / set.pressure[1]).log10(),
            set.pressure[1]
        ));
    }
    if t < set.thickness_qr_min {
        outside.push(format!(
            "t·q_r {t:.3} is thinner than the set's {}",
            set.thickness_qr_min
        ));
    }
    if glo > set.gamma_glo_max {
        outside.push(format!(
            "γ̃_glo {glo:.3} is above the set's largest {:.3}",
            set.gamma_glo_max
        ));
    }
    if let Some(line) = model_five_bandwidth(scene) {
        outside.push(line);
    }
    // model 5 reads its own columns where the set has them, any other model the set's
    let five = scene.model().kind == crate::input::model::ModelKind::Five;
    let theory = |r: &ReferencePoint| -> (f64, f64, u8) {
        if five && r.theory5_a_r > 0.0 {
            (r.theory5_a_r, r.theory5_mean_gap_rel, 5)
        } else {
            (r.theory_a_r, r.theory_mean_gap_rel, r.theory_model)
        }
    };
    let bw = scene.spectrum().q_s() / scene.spectrum().q_r();
    let wide = five && scene.is_adhesive() && bw.is_finite() && bw > WIDE_BANDWIDTH;
    let points: Vec<&ReferencePoint> = if wide {
        widest_rows(bandwidth_set())
    } else {
        reference_set().iter().collect()
    };
    let mut near: Vec<(f64, &ReferencePoint)> = points
        .into_iter()
        .filter(|r| r.branch == PathBranch::Loading && r.p > 0.0 && theory(r).0 > 0.0 && r.a_r.0 > 0.0)
        .map(|r| (distance(p, glo, tau, r), r))
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    near.truncate(NEAREST);
    let nearest: Vec<NearPoint> = near
        .iter()
        .map(|&(d, r)| NearPoint {
            system: r.system,
            thickness_qr: r.thickness_qr.is_finite().then_some(r.thickness_qr),
            gamma_glo: r.gamma_glo,
            p: r.p,
            a_r_gfmd: r.a_r.0,
            a_r_theory: theory(r).0,
            mean_gap_rel_gfmd: r.mean_gap_rel.0,
            mean_gap_rel_theory: theory(r).1.is_finite().then_some(theory(r).1),
            distance: d,
        })
        .collect();
    let logs: Vec<f64> = nearest.iter().map(|n| (n.a_r_theory / n.a_r_gfmd).ln().abs()).collect();
    let a_r_log_error = logs.iter().sum::<f64>() / logs.len().max(1) as f64;
    let a_r_worst_ratio = logs.iter().cloned().fold(0.0, f64::max).exp();
    let gaps: Vec<f64> = nearest
        .iter()
        .filter_map(|n| n.mean_gap_rel_theory.map(|g| (g / n.mean_gap_rel_gfmd).ln().abs()))
        .collect();
    let mean_gap_log_error = (!gaps.is_empty()).then(|| gaps.iter().sum::<f64>() / gaps.len() as f64);
    let measured_model = near.first().map_or(4, |(_, r)| theory(r).2);
    let same_model = scene.model.number() == Some(measured_model);
    let mut summary = summary(
        &outside,
        measured_model,
        same_model,
        a_r_log_error,
        a_r_worst_ratio,
        mean_gap_log_error,
    );
    // the set's maps are narrower than most scenes: say at which bandwidth it was measured
    if wide {
        summary += " (model 5 on the full system II against GFMD at λ_r/λ_s = 64–128)";
    } else if bw > 1.5 * SET_BANDWIDTH && bw.is_finite() {
        summary += &format!(" (measured on the set's maps, λ_r/λ_s = {SET_BANDWIDTH:.0}; this scene has {bw:.0})");
    }
    Trust {
        inside: outside.is_empty(),
        outside,
        set,
        nearest,
        measured_model,
        same_model,
        a_r_log_error,
        a_r_worst_ratio,
        mean_gap_log_error,
        summary,
    }
}

/// Above this λ_r/λ_s an adhesive model 5 scene reads its error from the bandwidth set (see
/// the module docs): √(16·128), the midpoint in octaves of the set's and the full system's.
pub const WIDE_BANDWIDTH: f64 = 45.254_833_995_939_04;

/// The rows of each case's widest grid.
fn widest_rows(rows: &[ReferencePoint]) -> Vec<&ReferencePoint> {
    let widest = |r: &ReferencePoint| {
        rows.iter()
            .filter(|o| o.thickness_qr == r.thickness_qr && o.gamma_factor == r.gamma_factor)
            .map(|o| o.grid)
            .max()
            .unwrap_or(0)
    };
    rows.iter().filter(|r| r.grid == widest(r)).collect()
}

/// The bandwidth λ_r/λ_s of the set's grid (256² at L/λ_r = 2, λ_s/Δa = 8).
pub const SET_BANDWIDTH: f64 = crate::input::model_five::SET_BANDWIDTH;

/// Model 5's gauge was measured over λ_r/λ_s from [`SET_BANDWIDTH`] to
/// [`crate::input::model_five::BANDWIDTH_MEASURED`] (physics.md §3.6); on a scene whose
/// bandwidth q_s/q_r is more than 1.5× outside that range, one line saying so (the gauge is
/// held at its value at the nearer end).
fn model_five_bandwidth(scene: &Scene) -> Option<String> {
    use crate::input::model_five::BANDWIDTH_MEASURED;
    if scene.model().kind != crate::input::model::ModelKind::Five || !scene.is_adhesive() {
        return None;
    }
    let bw = scene.spectrum().q_s() / scene.spectrum().q_r();
    let outside = !(SET_BANDWIDTH / 1.5..=BANDWIDTH_MEASURED * 1.5).contains(&bw);
    (outside && bw.is_finite()).then(|| {
        format!(
            "model 5 was gauged against GFMD at λ_r/λ_s = {SET_BANDWIDTH:.0} to {BANDWIDTH_MEASURED:.0}, this scene has {bw:.0}: its gauge is held at the nearer end and was not checked there"
        )
    })
}

fn summary(outside: &[String], model: u8, same: bool, ar: f64, worst: f64, gap: Option<f64>) -> String {
    let place = if outside.is_empty() {
        "inside the GFMD reference set".to_string()
    } else {
        format!("outside the GFMD reference set: {}", outside.join("; "))
    };
    let gap = gap.map_or(String::new(), |g| {
        format!(", mean gap off by {:.0} %", 100.0 * (g.exp() - 1.0))
    });
    let whose = if same {
        format!("model {model}")
    } else {
        format!("model {model} (not this scene's model)")
    };
    format!(
        "{place}; {whose} vs GFMD at the {NEAREST} nearest points: a_r off by {:.0} % on average (worst {worst:.2}x){gap}",
        100.0 * (ar.exp() - 1.0)
    )
}
