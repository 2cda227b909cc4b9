//! The self-consistency as one scalar equation: the causal ("shooting") march in
//! C = γ(q_L) (physics.md §4).
//!
//! The energy balance [S-9, S-14] couples every scale to every finer one:
//!
//! ```text
//! a_r(q)γ(q) = a_r(q_s)γ_s − ∫_q^{q_s} a_r W(a_r) (q'E*f/4) dm(q')
//! ```
//!
//! With C := a_r(q_s)γ_s − ∫_{q_L}^{q_s} a_r W (qE*f/4) dm (= γ(q_L), since a_r(q_L) = 1) the
//! same balance reads forward, a_r(q)γ(q) = C + ∫_{q_L}^{q} a_r W (q'E*f/4) dm(q'): given the
//! scalar C, the wall σ_a(q) of every step depends only on coarser scales and on the step's
//! own end. The march runs from q_L to q_s once, and the self-consistency of the whole
//! function a_r(q) becomes the root of
//!
//! ```text
//! H(C) = C + I(C) − γ_s a_r(q_s; C),     I(C) = ∫_{q_L}^{q_s} a_r W (qE*f/4) dm   (J/m²)
//! ```
//!
//! H(−I_full) < 0 (the walls stay at zero: γ < 0 everywhere) and H(γ_s) ≥ 0 (I ≥ 0,
//! a_r ≤ 1), with I_full the full-contact value of I, so a root always exists in
//! [−I_full, γ_s]; several roots are several branches of the same scene (hysteresis).
//!
//! Each step moves the wall to σ_a at its end node (linearly in v, see `propagator`; `walls`);
//! the end node's γ needs the step's own a_r: a trial of the step with the wall of the
//! geometrically extrapolated a_r predicts it, and the step is taken with the wall of the
//! predicted end (predictor–corrector: second order in the step, and a fixed number of trials
//! keeps H(C) a smooth function of C for the root finder). Iterating the trial to convergence
//! instead changed a_r by at most 1.2e-5 relative (median 1e-7) on the thin-slab grid of `tests/adhesion.rs` at 1.6× the
//! cost (measured with the walls at the steps' means).

use super::propagator::{Cursor, Marcher};
use super::walls::WallCoefficients;

/// One shooting march.
pub(super) struct Shot {
    /// C (J/m²).
    pub(super) c: f64,
    /// H(C) (J/m²).
    pub(super) h: f64,
    /// a_r(q_s).
    pub(super) a_s: f64,
    /// The rising part of H: F = C + I (J/m²); H = F − γ_s a_r(q_s).
    pub(super) f: f64,
    /// The march in full (only when recorded).
    pub(super) record: Option<Record>,
}

/// Everything a recorded shooting march saw.
#[derive(Clone)]
pub(super) struct Record {
    /// a_r at the nodes.
    pub(super) a_nodes: Vec<f64>,
    /// v at the nodes.
    pub(super) v_nodes: Vec<f64>,
    /// γ at the nodes (J/m², unclipped: (C + I(q))/a_r(q)).
    pub(super) gamma_nodes: Vec<f64>,
    /// I = Σ ā W(ā) e over all steps (J/m²).
    pub(super) energy: f64,
    /// The state after the last step.
    pub(super) end: Cursor,
}

/// γ of a node from the accumulated energy: (C + I)/a, or −1 (no wall) without contact.
fn gamma_raw(c: f64, energy: f64, a: f64) -> f64 {
    if a > 0.0 {
        (c + energy) / a
    } else {
        -1.0
    }
}

impl Marcher<'_> {
    /// The full-contact energy I_full = Σ W(1)·e over the steps (J/m²): the lower end of the
    /// bracket of C.
    pub(super) fn full_energy(&self) -> f64 {
        let w1 = self.scene.model.w(1.0);
        self.grid.steps.iter().map(|s| w1 * s.e).sum()
    }

    /// The shooting march for C (see the module docs); with `record`, all of it.
    pub(super) fn shoot(&mut self, coef: &WallCoefficients, c: f64, record: bool) -> Shot {
        let model = self.scene.model;
        let grid = self.grid;
        let k_steps = grid.steps.len();
        let cap = if record { k_steps + 1 } else { 0 };
        let (mut a_nodes, mut v_nodes, mut gamma_nodes) = (
            Vec::with_capacity(cap),
            Vec::with_capacity(cap),
            Vec::with_capacity(cap),
        );
        if record {
            a_nodes.push(1.0);
            v_nodes.push(0.0);
            gamma_nodes.push(c);
        }
        let (mut a_prev, mut a) = (1.0f64, 1.0f64);
        let mut energy = 0.0f64;
        let mut cur: Cursor = self.start(coef.node(0, c));
        // γ that set the wall at the current node (C at the first): the next step's onset
        // is judged from it, so that the wall at a node and the onset after it agree (the
        // recorded γ, from the step's actual end, can differ in sign near a threshold, and a
        // step whose wall starts just above zero would then grow from its start while one
        // just below waited for the onset: a jump of H in C)
        let mut g_node = c;
        for k in 0..k_steps {
            let e = grid.steps[k].e;
            let g0 = g_node;
            // the step's energy ∫ a_r W de: one midpoint term, or the pieces' sum where the
            // step was split at an onset (`aw`, see `Marcher::step_aw`)
            let step_energy = |a_end: f64, aw: Option<f64>| -> f64 {
                let am = 0.5 * (a + a_end);
                aw.unwrap_or(am * model.w(am)) * e
            };
            // γ at the step's end for a given end value of a_r (and split energy)
            let end_gamma_aw =
                |a_end: f64, aw: Option<f64>| -> f64 { gamma_raw(c, energy + step_energy(a_end, aw), a_end) };
            let end_gamma = |a_end: f64| end_gamma_aw(a_end, None);
            let wall_for = |a_end: f64| coef.node(k + 1, end_gamma(a_end));
            // γ at the step's end cannot turn positive (ā W(ā) ≤ 1): no wall, no trial
            // where γ turns positive, if it does in this step: where C + I = ∫a_r W de crosses
            // zero, as a fraction of the step's b (the march's measure; `Step`). (γ = (C + I)/a_r
            // interpolated linearly put the onset off by the relative fall of a_r in the step.)
            let step = grid.steps[k];
            let onset_for = |a_end: f64| -> Option<f64> {
                let g1 = end_gamma(a_end);
                (g0 <= 0.0 && g1 > 0.0).then(|| {
                    // before the onset a_r W falls at the previous step's rate r₁ (a_r falls
                    // fast there, hardly after it): x_e solves r₀x + r₁x²/2 = −(C + I)/e;
                    // where that has no root in [0, 1], a_r W at the step's mean
                    let need = -(c + energy) / e;
                    let r0 = a * model.w(a);
                    let r1 = (r0 - a_prev * model.w(a_prev)).min(0.0);
                    let disc = r0 * r0 + 2.0 * r1 * need;
                    let x = if r1 < 0.0 && disc >= 0.0 {
                        need / (0.5 * (r0 + disc.sqrt()))
                    } else if r0 > 0.0 {
                        need / r0
                    } else {
                        f64::NAN
                    };
                    let x_e = if (0.0..=1.0).contains(&x) {
                        x
                    } else {
                        let rise = step_energy(a_end, None);
                        if rise > 0.0 {
                            -(c + energy) / rise
                        } else {
                            0.0
                        }
                    };
                    step.b_fraction_of_e(x_e)
                })
            };
            let wall = if g0 <= 0.0 && c + energy + e <= 0.0 {
                g_node = end_gamma(a);
                (0.0, None)
            } else {
                // predictor–corrector: a trial with the wall of the extrapolated end value
                // gives the step's end, and the step is taken with the wall of that end (a
                // fixed number of trials keeps H(C) smooth; second order in the step)
                let guess = if a_prev > 0.0 { (a * a / a_prev).min(1.0) } else { a };
                let end = self.trial(&cur, wall_for(guess), onset_for(guess));
                let aw = self.step_aw;
                self.trials += 1;
                g_node = end_gamma_aw(end, aw);
                (coef.node(k + 1, g_node), onset_for(end))
            };
            let a_next = self.step_onset(&mut cur, wall.0, wall.1, true);
            energy += step_energy(a_next, self.step_aw);
            a_prev = a;
            a = a_next;
            if record {
                a_nodes.push(a);
                v_nodes.push(cur.v);
                gamma_nodes.push(gamma_raw(c, energy, a));
            }
        }
        Shot {
            c,
            h: c + energy - self.scene.gamma * a,
            a_s: a,
            f: c + energy,
            record: record.then_some(Record {
                a_nodes,
                v_nodes,
                gamma_nodes,
                energy,
                end: cur,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::grid::build_grid;
    use super::super::AdhesionAccuracy;
    use super::*;
    use crate::input::model::Model;
    use crate::input::preset::Preset;

    /// Prints dense H(C) scans of hard scenes (sign changes only):
    /// `cargo test -p asperity --lib shooting -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn scan_h() {
        for (model, t, p, frac) in [
            (3u8, 0.1, 1e-5, 0.8),
            (3, 0.1, 1e-5, 1.0),
            (4, 0.15, 1e-5, 1.0),
            (3, 0.15, 1e-3, 1.0),
            (4, 0.2, 1e-4, 1.0),
        ] {
            let mut scene = Preset::resolve("system-2").unwrap().scene().unwrap();
            scene.model = Model::named(model).unwrap();
            scene.thickness_qr = t;
            scene.pressure = p;
            scene.gamma *= frac;
            let acc = AdhesionAccuracy::default();
            let grid = build_grid(&scene, acc.steps_per_ln_q);
            let mut m = Marcher::new(&scene, &grid, acc);
            let coef = WallCoefficients::new(&scene, &grid);
            let g = scene.gamma;
            println!("model {model} t {t} p {p} gamma x{frac}");
            let mut prev: Option<(f64, f64, f64)> = None;
            let mut n = 0;
            for i in 0..=600 {
                // C/γ from −1 to +1, logarithmic in |C| between 1e-7 and 1
                let u = -1.0 + 2.0 * i as f64 / 600.0;
                let c = g * u.signum() * 10f64.powf(-7.0 * (1.0 - u.abs()));
                let s = m.shoot(&coef, c, false);
                n += 1;
                if let Some((pc, ph, pa)) = prev {
                    if (ph < 0.0) != (s.h < 0.0) {
                        println!(
                            "  sign change C/g {:+.4e}..{:+.4e}  a_s {pa:.4e}..{:.4e}",
                            pc / g,
                            c / g,
                            s.a_s
                        );
                    }
                }
                prev = Some((c, s.h, s.a_s));
            }
            let _ = n;
        }
    }
}
