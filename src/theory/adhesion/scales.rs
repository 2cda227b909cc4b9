//! The theory scale by scale: snapshots of Pr(σ*, q) as the resolution q runs from q_L to
//! q_s, read off the engine's own march (physics.md §4; [S-5, S-7, S-8]).
//!
//! Resolution acts as time: Pr starts as δ(σ* − p*) at q_L and diffuses in the accumulated
//! variance v(q) [S-2, S-15], absorbed at the wall σ* = −σ_a*(q) [S-5, S-7] that the
//! scale-dependent surface energy sets [S-8]; a_r(q) = ∫Pr dσ* [S-6]. Reduced units as the
//! module: σ* = σ/(E*ḡ), v = V/(E*ḡ)².
//!
//! Nothing here solves anything new. With γ_s > 0 the self-consistent root C = γ(q_L) of
//! the solution is marched again by the same shooting march (`shooting`) over the first K
//! steps of the same grid: the march is causal (the wall of a step depends on coarser scales
//! and the step's own end only), so its state after K steps is the solution's Pr at q_K, and
//! the last snapshot is the solution's final Pr. Without adhesion the walls stay at zero and
//! the march's mirror Gaussian of variance v(q) is read at each frame. A frame costs one march
//! of its K steps (the whole view about frames/2 marches, read-only).

use super::grid::{build_grid, Grid};
use super::propagator::{gauss, shift, Cursor, Marcher, State};
use super::walls::{sigma_at, WallCoefficients};
use super::{AdhesionAccuracy, AdhesiveSolution};
use crate::error::{Error, Result};
use crate::input::scene::Scene;
use std::sync::atomic::{AtomicBool, Ordering};

/// Where the frames sample Pr(σ*).
#[derive(Debug, Clone, Copy)]
pub enum Sampling<'a> {
    /// `n` points (at least 2) from the farthest wall −max σ_a*(q) to p* + 5√v(q_s), shared by
    /// every frame, so that an axis stays put while the resolution runs.
    Points(usize),
    /// At these σ* (ascending).
    At(&'a [f64]),
}

/// Pr(σ*, q) at one resolution.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// Resolution q (1/m).
    pub q: f64,
    /// Index of q among the march's nodes (0 = q_L).
    pub node: usize,
    /// a_r(q) = ∫Pr dσ* (the march's own mass).
    pub a_r: f64,
    /// v(q), the accumulated broadening.
    pub v: f64,
    /// σ_a*(q): the wall sits at σ* = −σ_a*.
    pub sigma_a: f64,
    /// Pr(σ*, q) at [`Scales::sigma`] (0 below the wall).
    pub density: Vec<f64>,
}

/// The snapshots of a scene and the whole resolution path.
#[derive(Debug, Clone, PartialEq)]
pub struct Scales {
    /// σ* of every frame's density.
    pub sigma: Vec<f64>,
    /// The frames, coarse to fine; the last at q_s.
    pub frames: Vec<Snapshot>,
    /// The march's nodes q (1/m), q_L to q_s.
    pub q: Vec<f64>,
    /// a_r at the nodes.
    pub a_q: Vec<f64>,
    /// σ_a* at the nodes (zeros without adhesion).
    pub sigma_a_q: Vec<f64>,
}

/// Snapshots of Pr(σ*, q) at `frames` resolutions spread evenly over the march's nodes (in
/// ln q), the last at q_s. With γ_s > 0 `solution` is the adhesive solution of `scene` at
/// accuracy `acc` (its loading branch is shown); `None` solves it. `cancel` is checked
/// between frames.
///
/// # Errors
/// The scene's or accuracy's own check, [`Error::Cancelled`], the solver's errors, and
/// [`Error::NotConverged`] when `solution` was computed on another grid than `acc`'s.
pub fn snapshots(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    solution: Option<&AdhesiveSolution>,
    frames: usize,
    sampling: Sampling<'_>,
    cancel: Option<&AtomicBool>,
) -> Result<Scales> {
    scene.validate()?;
    acc.validate()?;
    let grid = build_grid(scene, acc.steps_per_ln_q);
    let n = grid.steps.len();
    let frames = frames.clamp(1, n.max(1));
    let nodes: Vec<usize> = (1..=frames).map(|f| (f * n).div_ceil(frames).max(1)).collect();
    let cancelled = || cancel.is_some_and(|c| c.load(Ordering::Relaxed));
    // (node, state, wall the density is read with)
    let mut states: Vec<(usize, Cursor, f64)> = Vec::with_capacity(frames);
    let (a_q, sigma_a_q);
    if scene.is_adhesive() {
        let solved;
        let sol = match solution {
            Some(s) => s,
            None => {
                solved = super::solve(scene, acc, None, cancel)?;
                &solved
            }
        };
        if sol.q.len() != grid.q.len() {
            return Err(Error::NotConverged {
                solver: crate::error::Solver::ScaleSnapshots,
                reason: format!(
                    "the solution has {} resolution nodes, the accuracy's grid {}",
                    sol.q.len(),
                    grid.q.len()
                ),
            });
        }
        // the loading branch: the lowest stable root (as the solve chooses)
        let chosen = sol.branches.iter().position(|b| b.stable).unwrap_or(0);
        let c = sol.branches.get(chosen).map_or(0.0, |b| b.gamma_coarse) * scene.gamma;
        for &k in &nodes {
            if cancelled() {
                return Err(Error::Cancelled);
            }
            let part = Grid {
                q: grid.q[..=k].to_vec(),
                steps: grid.steps[..k].to_vec(),
                e_scale: grid.e_scale,
            };
            let coef = WallCoefficients::new(scene, &part);
            let mut m = Marcher::new(scene, &part, *acc);
            let shot = m.shoot(&coef, c, true);
            let rec = shot.record.ok_or_else(|| Error::NotConverged {
                solver: crate::error::Solver::ScaleSnapshots,
                reason: "the march kept no record".into(),
            })?;
            let wall = sigma_at(scene, grid.q[k], rec.gamma_nodes.last().copied().unwrap_or(0.0));
            states.push((k, rec.end, wall));
        }
        a_q = sol.a_q.clone();
        sigma_a_q = sol.sigma_a_q.clone();
    } else {
        let mut m = Marcher::new(scene, &grid, *acc);
        let mut cur = m.start(0.0);
        let mut a = vec![1.0];
        for k in 0..n {
            a.push(m.step_onset(&mut cur, 0.0, None, true));
            if nodes.contains(&(k + 1)) {
                if cancelled() {
                    return Err(Error::Cancelled);
                }
                states.push((k + 1, cur.clone(), 0.0));
            }
        }
        a_q = a;
        sigma_a_q = vec![0.0; grid.q.len()];
    }
    let sigma = match sampling {
        Sampling::At(s) => s.to_vec(),
        Sampling::Points(points) => {
            let lo = -states.iter().map(|s| s.2).fold(0.0, f64::max);
            let v_s = states.last().map_or(0.0, |s| s.1.v);
            let hi = scene.pressure + 5.0 * v_s.sqrt().max(1e-12);
            let points = points.max(2);
            (0..points)
                .map(|i| lo + (hi - lo) * i as f64 / (points - 1) as f64)
                .collect()
        }
    };
    let frames = states
        .into_iter()
        .map(|(k, cur, wall)| Snapshot {
            q: grid.q[k],
            node: k,
            a_r: cur.a,
            v: cur.v,
            sigma_a: wall,
            density: sample(&cur, wall, scene.pressure, &sigma),
        })
        .collect();
    Ok(Scales {
        sigma,
        frames,
        q: grid.q,
        a_q,
        sigma_a_q,
    })
}

/// Pr of a march state at σ*, with the wall moved to −`wall` (as the solution's final
/// distribution is read): the mirror Gaussian about the wall, or the grid's values (linear
/// between nodes).
fn sample(cur: &Cursor, wall: f64, p0: f64, sigma: &[f64]) -> Vec<f64> {
    match &cur.state {
        State::Analytic => {
            let w = cur.wall;
            let d = p0 + w;
            sigma
                .iter()
                .map(|&s| {
                    let x = s + w;
                    if x <= 0.0 || cur.v <= 0.0 {
                        0.0
                    } else {
                        gauss(x - d, cur.v) - gauss(x + d, cur.v)
                    }
                })
                .collect()
        }
        State::Grid { h, m, p } => {
            let h = *h;
            let mut p: Vec<f64> = std::iter::repeat_n(0.0, *m).chain(p.iter().copied()).collect();
            shift(&mut p, h, wall - cur.wall);
            sigma
                .iter()
                .map(|&s| {
                    let x = (s + wall) / h;
                    if x < 0.0 {
                        return 0.0;
                    }
                    let j = x.floor() as usize;
                    let t = x - j as f64;
                    // a node hit to rounding reads the node itself
                    let (t, j) = if t > 1.0 - 1e-9 { (0.0, j + 1) } else { (t, j) };
                    let at = |i: usize| p.get(i).copied().unwrap_or(0.0);
                    if t < 1e-9 {
                        at(j)
                    } else {
                        (1.0 - t) * at(j) + t * at(j + 1)
                    }
                })
                .collect()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;
    use crate::surface::spectrum::Spectrum;
    use crate::theory::engine::{evaluate, Options};
    use statrs::function::erf::erf;

    /// The last frame against the engine's own Pr at q_s: the same march at the same root, so
    /// equal up to the root's C passing through γ(q_L)/γ_s and back (a few ulps) — 1e-9 of the
    /// peak density and of a_r.
    const SAME_MARCH_REL: f64 = 1e-9;
    /// Adhesionless frames against erf(p*/√(2v(q))) with v(q) in closed form (model 1, W ≡ 1:
    /// v is the sum of the steps' Gauss–Legendre integrals, ~1e-13): 1e-10 relative.
    const MODEL1_FRAMES_REL: f64 = 1e-10;
    /// The march's RK4 variance (model 3, W depends on a_r) against the engine's adaptive ODE
    /// at q_s: both second-order-or-better in steps of 1/12 in ln q; measured ≤ 1e-6.
    const MARCH_VS_ODE_REL: f64 = 1e-5;

    fn system(n: u8, model: u8) -> Scene {
        let mut s = Preset::resolve(&format!("system-{n}")).unwrap().scene().unwrap();
        s.model = crate::input::model::Model::named(model).unwrap();
        s
    }

    fn last_frame_matches(scene: &Scene, rel: f64) {
        let opts = Options::chart();
        let e = evaluate(scene, &opts).unwrap();
        let sc = snapshots(scene, &opts.adhesion, None, 24, Sampling::At(&e.stats.pr.sigma), None).unwrap();
        let last = sc.frames.last().unwrap();
        assert_eq!(last.node, sc.q.len() - 1);
        assert!(
            (last.a_r - e.stats.a_r).abs() <= rel * e.stats.a_r,
            "{} {}",
            last.a_r,
            e.stats.a_r
        );
        assert!((last.sigma_a - e.sigma_a).abs() <= rel * e.sigma_a.max(1e-300) + 1e-15);
        let peak = e.stats.pr.density.iter().fold(0.0f64, |m, &d| m.max(d));
        for (i, (d, r)) in last.density.iter().zip(&e.stats.pr.density).enumerate() {
            assert!((d - r).abs() <= rel * peak, "σ* = {}: {d} vs {r}", e.stats.pr.sigma[i]);
        }
        // a_r(q) falls (mass only leaves through the wall) and starts at 1
        assert_eq!(sc.a_q[0], 1.0);
        assert!(sc.a_q.windows(2).all(|w| w[1] <= w[0] + 1e-12));
    }

    #[test]
    fn last_frame_is_the_engine_solution_with_adhesion() {
        last_frame_matches(&system(1, 3), SAME_MARCH_REL);
        let mut thin = system(2, 3);
        thin.thickness_qr = 0.5;
        last_frame_matches(&thin, SAME_MARCH_REL);
    }

    #[test]
    fn last_frame_is_the_engine_solution_without_adhesion() {
        let mut s = system(1, 3);
        s.gamma = 0.0;
        last_frame_matches(&s, MARCH_VS_ODE_REL);
    }

    #[test]
    fn adhesionless_model_1_frames_follow_erf() {
        let mut s = system(1, 1);
        s.gamma = 0.0;
        let acc = Options::chart().adhesion;
        let sc = snapshots(&s, &acc, None, 16, Sampling::Points(101), None).unwrap();
        let Spectrum::SelfAffine(sa) = &s.spectrum else {
            panic!("self-affine preset")
        };
        // ∫_{q_L}^{q} q² dm = 2πC₀ ∫ q³ (plateau) + 2πC₀ q_r^{2+2H} ∫ q^{1−2H} (tail), over ḡ²
        let (ql, qr, h) = (sa.q_l(), sa.q_r(), sa.hurst);
        let m2 = |q: f64| {
            let pl = (q.min(qr).powi(4) - ql.powi(4)) / 4.0;
            let k = 2.0 - 2.0 * h;
            let tail = if q > qr {
                qr.powf(2.0 + 2.0 * h) * (q.powf(k) - qr.powf(k)) / k
            } else {
                0.0
            };
            2.0 * std::f64::consts::PI * sa.c0 * (pl + tail)
        };
        let g2 = m2(sa.q_s());
        assert_eq!(sc.frames.len(), 16);
        for f in &sc.frames {
            let v = m2(f.q) / (4.0 * g2);
            let want = erf(s.pressure / (2.0 * v).sqrt());
            assert!(
                (f.a_r - want).abs() <= MODEL1_FRAMES_REL * want,
                "q = {}: {} vs {want}",
                f.q,
                f.a_r
            );
            assert!((f.v - v).abs() <= MODEL1_FRAMES_REL * v);
            assert_eq!(f.sigma_a, 0.0);
        }
        // Pr broadens: its width grows frame by frame
        assert!(sc.frames.windows(2).all(|w| w[1].v > w[0].v));
    }

    #[test]
    fn a_cancelled_view_says_so() {
        let stop = AtomicBool::new(true);
        let acc = Options::chart().adhesion;
        for gamma in [0.05, 0.0] {
            let mut s = system(1, 3);
            s.gamma = gamma;
            let r = snapshots(&s, &acc, None, 8, Sampling::Points(11), Some(&stop));
            assert!(matches!(r, Err(Error::Cancelled)), "γ_s = {gamma}");
        }
    }
}
