//! The moving-wall propagator: one march of Pr(σ, q) through the resolution steps for given
//! wall positions σ_a*(q_k) at the nodes [S-5, S-7], returning a_r at the nodes [S-6].
//!
//! In the wall's frame x = σ + σ_a the wall sits at x = 0 and a wall moving at speed
//! c = dσ_a/dv (v the accumulated variance, the march's "time") adds a drift:
//!
//! ```text
//! ∂p/∂v = ½ ∂²p/∂x² − c ∂p/∂x   on x > 0,   p(0, v) = 0
//! ```
//!
//! Each step moves the wall linearly in v from where it stands to the step's end node
//! (c constant over the step) and applies the exact solution operator of this problem
//! ([`Heat`]): p = e^{cx − c²v/2}u turns it into the heat equation for u with the same
//! Dirichlet end, whose image solution gives p(x, v) = [G_v * p̃](x − cv) with the weighted odd
//! extension p̃(−y) = −e^{−2cy}p(y) (weights ≤ 1 for c ≥ 0): a length-2N FFT, a heat factor and
//! a shift phase per mode, an inverse FFT. The only errors are the wall's path (linear in v
//! between the nodes: second order in the step), the spectral representation of p on the grid,
//! and Δv = W^{2α}(a)·b by RK4 in the variance measure B (c = δ/Δv is iterated until the wall
//! ends within 1e-3·δ of its node). A constant wall (c = 0) is the exact image solution, so
//! σ_a ≡ const is reproduced to round-off. Measured order in the step ≈ 2.0
//! (`tests/adhesion.rs`; a shift-then-heat splitting gives ≈ 1.3).
//!
//! A wall moving into the distribution (c < 0) would need weights e^{2|c|y} that grow: such a
//! step is Strang-split instead, half the shift (8-point Lagrange, odd continuation through the
//! wall, mass below it removed; `regrid`), the heat step with the wall held, the other half
//! (second order: 1.4e-6 at 24 steps per ln q on a receding test wall, where a first-order
//! shift-then-hold step gives 1e-3, `tests/adhesion.rs`).
//!
//! A wall running away from the distribution at speed c weights its image by e^{−2cy}. Right
//! after an onset σ_a ∝ √γ leaves zero at infinite speed, and at 10 points per width 2c·h
//! reached 15 in the first onset piece: the weighted extension was not resolved and the error
//! fell only like h² (2e-4 in a_r). Where 2c·h > `REFINE_DRIFT` (`wall_motion`) the grid is
//! refined (spacing halved by interpolation, `regrid`) before the step, and coarsened back by
//! the usual rule as √v grows: the same test wall then agrees with 80 points per width to 2e-7.
//!
//! While the wall has not moved (or is > 8.5√v away) the state is the mirror Gaussian about
//! the wall and no grid is used. On the grid, spacing h ~ √v/`points_per_width` (coarsened by
//! 2 as √v grows), the lower end x₀ = m·h follows the distribution when the wall runs ahead
//! of it (x₀ = 3√v below the point where the density falls under 1e-16 of its peak; the wall
//! then moves the grid by whole cells and the spectral shift does the rest), so the grid
//! holds ~25·`points_per_width` nodes however far σ_a is from p*: before, it reached from the
//! wall and held σ_a·`points_per_width`/√v nodes at tiny p* (~10× the cost of a march).

// index loops mirror the formulas (nodes j, steps k) in this numerical module
#![allow(clippy::needless_range_loop)]

use super::grid::{Grid, Step};
pub(super) use super::heat::Heat;
pub(super) use super::moments::state_moments;
use super::regrid::reoffset;
pub(super) use super::regrid::shift;
use super::wall_motion::WallMove;
use super::AdhesionAccuracy;
use crate::input::scene::Scene;
use statrs::function::erf::erf;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// The state of the march.
#[derive(Clone)]
pub(super) enum State {
    /// Mirror Gaussian about the wall (x = σ + wall ≥ 0), variance v.
    Analytic,
    /// Grid values at x_j = (m + j) h: the grid's lower end x₀ = m·h is the wall (m = 0) or,
    /// while the wall runs ahead of the distribution, a point below which the density is
    /// negligible (< 1e-16 of its peak 3√v further up), so that the grid does not fill the
    /// empty space between the wall and the distribution.
    Grid { h: f64, m: usize, p: Vec<f64> },
}

/// The variance increment of one march step: RK4 in the variance measure B for
/// du/dB = `rate(u)` from u = 0 over the step's `b`, with [`substeps`]. The analytic and the
/// grid stage both use it, so switching between them is continuous.
fn variance_step(rate: &dyn Fn(f64) -> f64, b_before: f64, b: f64) -> f64 {
    let nsub = substeps(b_before, b);
    let hb = b / nsub as f64;
    let mut u = 0.0;
    for _ in 0..nsub {
        let k1 = rate(u);
        let k2 = rate(u + 0.5 * hb * k1);
        let k3 = rate(u + 0.5 * hb * k2);
        let k4 = rate(u + hb * k3);
        u += hb * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
    }
    u
}

/// RK4 substeps of a march step: 8 while the accumulated variance measure is still small
/// against the step's (a_r falls fast there), else 1. A function of the grid only, never of
/// the shooting parameter C, so that H(C) stays continuous.
fn substeps(b_before: f64, b: f64) -> usize {
    if b_before < 4.0 * b {
        8
    } else {
        1
    }
}

/// Whether n has no prime factor above 5.
fn is_smooth(mut n: usize) -> bool {
    if n == 0 {
        return false;
    }
    for f in [2, 3, 5] {
        while n.is_multiple_of(f) {
            n /= f;
        }
    }
    n == 1
}

/// The smallest n' ≥ n with no prime factor above 5.
fn smooth_size(n: usize) -> usize {
    (n.max(1)..).find(|&k| is_smooth(k)).unwrap_or(n)
}

/// Mirror-Gaussian contact fraction at distance d from the wall with variance v.
pub(super) fn mirror_area(d: f64, v: f64) -> f64 {
    if d <= 0.0 {
        0.0
    } else if v <= 0.0 {
        1.0
    } else {
        erf(d / v.sqrt() * FRAC_1_SQRT_2)
    }
}

pub(super) fn gauss(x: f64, v: f64) -> f64 {
    (-x * x / (2.0 * v)).exp() / (2.0 * PI * v).sqrt()
}

/// The most a sub-piece of a step may add to the variance, relative to the variance before
/// it (see [`Marcher::advance`]).
const GROWTH_PER_PIECE: f64 = 3.0;

/// Pieces of a step after the onset of its wall (see [`Marcher::step_onset`]).
pub(super) const ONSET_PIECES: usize = 4;
/// The first sub-piece of a moving piece that starts from a delta (v = 0), as a fraction of
/// the piece.
const FIRST_PIECE: f64 = 1e-6;
/// A wall that grows past 1/`ONSET_GROWTH` times its value in one step (from zero, or from
/// a small positive γ at the step's start) follows the square root in pieces like an onset:
/// the limit C → 0 of γ(q_L) = C is then the same from both sides. 0.95 rather than 0.5 (a
/// doubling): the steps right after an onset, where σ_a still grows like a square root, are
/// the thin slab's largest step error (system II, model 4, t·q_r = 0.25, (24, 10): a_r off
/// by 3.3e-4 at 0.5, 1.3e-4 at 0.9, 6.3e-5 at 0.95, each for 20–30 % more time; on 216
/// scenes the worst error against a 4× finer run fell from 6.7e-4 at 0.9 to 2.4e-4).
const ONSET_GROWTH: f64 = 0.95;

/// The most nodes of a march's grid (with [`Marcher::max_nodes`]): about 20 MB of transform
/// buffers. The grid follows the distribution (~25·`points_per_width` nodes) and is refined to
/// at most `wall_motion::REFINE_MAX_NODES`, so a march that asks for more has lost the distribution (a
/// wall far from it that the grid cannot follow): it is cut here and flagged
/// ([`Marcher::overflow`]) instead of allocating without bound (a wall that jumps from 0 to
/// σ_a* = 1e7 in one step, as the root scan asks at p* = 1e-12, would need 9e9 nodes on a
/// grid that spans it).
const GRID_MAX_NODES: usize = 1 << 18;
pub(super) struct Marcher<'a> {
    pub(super) scene: &'a Scene,
    pub(super) grid: &'a Grid,
    pub(super) acc: AdhesionAccuracy,
    pub(super) heat: Heat,
    /// Test hook: start the grid at this step even if the wall has not moved.
    pub(super) force_grid_from: Option<usize>,
    /// p* of the march (the scene's unless a continuation varies it).
    pub(super) pressure: f64,
    /// Trial steps taken by shooting marches (a cost counter).
    pub(super) trials: usize,
    /// The mean of a_r W(a_r) over the e-measure of the last step taken (trial or not), where
    /// it was split in pieces (an onset); None for a step in one piece.
    pub(super) step_aw: Option<f64>,
    /// Set when a step would have needed a grid beyond [`Marcher::max_nodes`]: the grid was
    /// cut there, and the march's result is not to be trusted (the solve refuses).
    pub(super) overflow: bool,
}

impl<'a> Marcher<'a> {
    /// The most nodes a march's grid may hold: [`GRID_MAX_NODES`], or 400 per
    /// `points_per_width` where that is more (a grid spans ~25 widths at most, refined up to
    /// `wall_motion::REFINE_MAX_NODES` right after an onset).
    pub(super) fn max_nodes(&self) -> usize {
        GRID_MAX_NODES.max((400.0 * self.acc.points_per_width) as usize)
    }

    /// A marcher of `scene` on `grid` (no forced grid).
    pub(super) fn new(scene: &'a Scene, grid: &'a Grid, acc: AdhesionAccuracy) -> Self {
        Marcher {
            scene,
            grid,
            acc,
            heat: Heat::new(),
            force_grid_from: None,
            pressure: scene.pressure,
            trials: 0,
            step_aw: None,
            overflow: false,
        }
    }

    /// Marches the distribution through the steps with the given wall positions (σ_a* at the
    /// nodes, `walls[0]` at the start; `onsets[k]`: where the wall of step k leaves zero, see
    /// [`Marcher::step_onset`]), returning a_r at the nodes.
    pub(super) fn march(&mut self, walls: &[f64], onsets: &[Option<f64>]) -> Vec<f64> {
        let k_steps = self.grid.steps.len();
        let mut a_nodes = Vec::with_capacity(k_steps + 1);
        a_nodes.push(1.0);
        let mut cur = self.start(walls.first().copied().unwrap_or(0.0));
        for (k, &s_k) in walls.iter().skip(1).take(k_steps).enumerate() {
            let onset = onsets.get(k).copied().flatten();
            a_nodes.push(self.step_onset(&mut cur, s_k, onset, true));
        }
        a_nodes
    }

    /// The state before the first step (δ(σ − p*), the wall at `first_wall`).
    pub(super) fn start(&self, first_wall: f64) -> Cursor {
        Cursor {
            k: 0,
            v: 0.0,
            wall: first_wall,
            state: State::Analytic,
            b_cum: 0.0,
            a: 1.0,
        }
    }

    /// a_r after step `cur.k` with the wall moving to `s_k` (σ_a* at the step's end; `onset`
    /// as in [`Marcher::step_onset`]) — without changing `cur`: one trial of the step, for a
    /// wall that depends on the step's own end (the shooting march). Costs a forward
    /// transform (no inverse) unless the step is split at an onset.
    pub(super) fn trial(&mut self, cur: &Cursor, s_k: f64, onset: Option<f64>) -> f64 {
        let mut c = cur.clone();
        self.step_onset(&mut c, s_k, onset, false)
    }

    /// Advances `cur` by one step with the wall moving to `s_k` at its end, returns a_r at the
    /// step's end. `commit` = false skips writing the evolved grid back (only a_r is wanted;
    /// `cur` is then a throw-away copy). `onset`: for a wall that leaves zero inside the step,
    /// the fraction of the step (in the variance measure) where γ turns positive, after which σ_a ∝ √γ grows
    /// like the square root of the distance from it. The step is split at the onset and in
    /// [`ONSET_PIECES`] pieces graded as i² after it, the wall following the square root
    /// through their ends (linear in v within each): the wall's path then carries no O(√Δ)
    /// error at the onset. A wall that starts the step at w₀ > 0 but grows past w₀/ONSET_GROWTH in it
    /// (w₀ < [`ONSET_GROWTH`]·s_k: γ small at the start) is split the same way from the step's
    /// start, σ_a² running linearly from w₀² to s_k².
    pub(super) fn step_onset(&mut self, cur: &mut Cursor, s_k: f64, onset: Option<f64>, commit: bool) -> f64 {
        let k = cur.k;
        let st = self.grid.steps[k];
        if k > 0 {
            cur.b_cum += self.grid.steps[k - 1].b;
        }
        cur.k += 1;
        let b_cum = cur.b_cum;
        let w0 = cur.wall;
        let start = match onset {
            Some(s0) if s0 > 0.0 && s0 < 1.0 && w0 == 0.0 => s0,
            _ => 0.0,
        };
        if s_k > 0.0 && (start > 0.0 || w0 < ONSET_GROWTH * s_k) {
            // σ_a² ∝ γ grows linearly from the onset (or from w0²) through the step
            let mut pieces = Vec::with_capacity(ONSET_PIECES + 1);
            if start > 0.0 {
                pieces.push((start, 0.0));
            }
            for i in 1..=ONSET_PIECES {
                let t = i as f64 / ONSET_PIECES as f64;
                pieces.push((
                    start + (1.0 - start) * t * t,
                    (w0 * w0 + (s_k * s_k - w0 * w0) * t * t).sqrt(),
                ));
            }
            let (mut from, mut a) = (0.0, cur.a);
            let last = pieces.len() - 1;
            // ∫ a_r W(a_r) over the step's e-measure, piece by piece: a_r has a kink at the
            // onset (falling fast before it, hardly after), which the step's one-term rule
            // missed by up to 1 % of the step's energy on thin slabs
            let model = self.scene.model;
            let mut aw = 0.0;
            for (i, &(to, wall)) in pieces.iter().enumerate() {
                let b = st.b * (to - from);
                let a_from = a;
                a = self.advance(cur, wall, k, b, b_cum + st.b * from, commit || i < last);
                let am = 0.5 * (a_from + a);
                aw += am * model.w(am) * (st.e_fraction_of_b(to) - st.e_fraction_of_b(from));
                from = to;
            }
            self.step_aw = Some(aw);
            a
        } else {
            self.step_aw = None;
            self.advance(cur, s_k, k, st.b, b_cum, commit)
        }
    }

    /// One piece of a step: variance measure `b`, the wall moving to `s_k`.
    ///
    /// A piece much larger than the variance accumulated so far (a discrete spectrum's next
    /// shell after shells of negligible weight, a slab's first appreciable modes) is marched in
    /// sub-pieces that at most multiply the variance by 1 + [`GROWTH_PER_PIECE`], the wall
    /// moving in proportion to the variance measure: the grid's spacing follows √v of the
    /// state it holds, and one piece that took v from 1e-11 to 1e-4 would need √(1e-4/1e-11)
    /// ≈ 3000× more nodes than the distribution's width calls for (millions of nodes).
    fn advance(&mut self, cur: &mut Cursor, s_k: f64, k: usize, b: f64, b_cum: f64, commit: bool) -> f64 {
        let mut b_done = 0.0;
        loop {
            let left = b - b_done;
            let v = cur.v;
            let moving = s_k != cur.wall || !matches!(cur.state, State::Analytic);
            // dv/dB = W^{2α}(a_r) is of order 1: a piece of GROWTH_PER_PIECE·v in B adds about
            // that much variance
            // (from v = 0, a delta, a first sub-piece of FIRST_PIECE of the piece: the growth
            // pieces then follow the wall from where the distribution has a width)
            let piece = if moving && v > 0.0 && left > GROWTH_PER_PIECE * v * 1.5 {
                GROWTH_PER_PIECE * v
            } else if moving && v == 0.0 && b_done == 0.0 && s_k > cur.wall {
                FIRST_PIECE * left
            } else {
                left
            };
            let last = piece >= left;
            let wall = if last {
                s_k
            } else {
                cur.wall + (s_k - cur.wall) * piece / left
            };
            let a = self.advance_piece(cur, wall, k, piece, b_cum + b_done, commit || !last);
            b_done += piece;
            if last {
                return a;
            }
        }
    }

    /// [`Marcher::advance`] without the sub-division: the piece on the stage the march is
    /// on, the analytic one (the mirror Gaussian, its variance by RK4) until the wall moves
    /// near the distribution, then the grid ([`Marcher::grid_piece`]).
    fn advance_piece(&mut self, cur: &mut Cursor, s_k: f64, k: usize, b: f64, b_cum: f64, commit: bool) -> f64 {
        let p0 = self.pressure;
        let model = self.scene.model;
        let st = Step {
            b,
            ..self.grid.steps[k]
        };
        let v = cur.v;
        let forced = self.force_grid_from == Some(k) && v > 0.0;
        if cur.a <= 0.0 {
            // everything has crossed the wall (only under tension: p* + σ_a ≤ 0 at some
            // scale, physics.md §6.2); detached area never returns, whatever the wall does
            cur.wall = s_k;
            cur.v += st.b * model.broadening(0.0);
            return 0.0;
        }
        if let State::Analytic = cur.state {
            if s_k != cur.wall || forced {
                self.leave_analytic(cur, s_k, k, st.b);
            }
        }
        match &mut cur.state {
            State::Analytic => {
                // RK4 in B for dv/dB = W^{2α}(a(v)), a(v) = erf((p + σ_a)/√(2v))
                let d = p0 + cur.wall;
                let rate_at = |v0: f64| move |u: f64| model.broadening(mirror_area(d, v0 + u));
                cur.v += variance_step(&rate_at(v), b_cum, st.b);
                cur.a = mirror_area(d, cur.v);
                cur.a
            }
            State::Grid { .. } => self.grid_piece(cur, s_k, st.b, b_cum, commit),
        }
    }

    /// A wall about to move on the analytic stage (or a grid forced from step `k`): where the
    /// image is negligible before and after the piece (variance measure `b`), or nothing has
    /// diffused yet (still δ(σ − p*)), the wall moves freely; else the march switches to the
    /// grid, starting from the mirror Gaussian about the wall.
    fn leave_analytic(&mut self, cur: &mut Cursor, s_k: f64, k: usize, b: f64) {
        let p0 = self.pressure;
        let ppw = self.acc.points_per_width;
        let v = cur.v;
        let wall = cur.wall;
        let d_min = p0 + wall.min(s_k);
        let v_next = v + b;
        let far = d_min > 8.5 * v_next.sqrt();
        if (far || v == 0.0) && self.force_grid_from.is_none_or(|f| k < f) {
            cur.wall = s_k;
        } else {
            let h = v.sqrt() / ppw;
            let d = p0 + wall;
            let x_max = d + 10.0 * v.sqrt();
            let n = (x_max / h).ceil() as usize + 1;
            let p: Vec<f64> = (0..=n)
                .map(|j| {
                    if j == 0 || j == n {
                        0.0
                    } else {
                        let x = j as f64 * h;
                        gauss(x - d, v) - gauss(x + d, v)
                    }
                })
                .collect();
            cur.state = State::Grid { h, m: 0, p };
        }
    }

    /// One piece on the grid (variance measure `b`, the wall moving to `s_k`): the wall moved
    /// linearly in v from where it stands to `s_k` at drift c = δ/Δv, Δv from the rate at the
    /// piece's start, corrected until c·Δv hits δ (to 1e-3 of δ; the next step starts from
    /// where the wall ended); before the heat step the grid is refined, offset or shifted as
    /// the wall's motion asks ([`WallMove`]), and sized for the step. `commit` = false skips
    /// writing the evolved grid back.
    fn grid_piece(&mut self, cur: &mut Cursor, s_k: f64, b: f64, b_cum: f64, commit: bool) -> f64 {
        let State::Grid { h: h_ref, m, p } = &mut cur.state else {
            unreachable!("a grid piece of a march on the analytic stage")
        };
        let p0 = self.pressure;
        let v = cur.v;
        let w0 = cur.wall;
        let delta = s_k - w0;
        let dv_guess = self.scene.model.broadening(cur.a) * b;
        reoffset(p, m, *h_ref, 3.0 * (v + b).sqrt() + (-delta).max(0.0) + 2.0 * *h_ref);
        let mv = WallMove {
            target: s_k,
            delta,
            dv_guess,
            b,
            a: cur.a,
        };
        let h = mv.refine_grid(p, *m, *h_ref, p0 + cur.wall.max(s_k) + 10.0 * (v + b).sqrt());
        *h_ref = h;
        let (receding, overflow) = mv.apply(p, m, h, &mut cur.wall, self.max_nodes());
        if overflow {
            self.overflow = true;
        }
        let rest = if receding < 0.0 { 0.0 } else { s_k - cur.wall };
        // the grid reaches p + σ_a + 10√v after this step (beyond it the density is
        // below e⁻⁵⁰ of its peak)
        let need = p0 + cur.wall.max(s_k) + 10.0 * (v + b).sqrt() + 0.01 * rest.abs() + 2.0 * h;
        self.size_grid(p, *m, h, need);
        let (dv, drift) = self.heat_step(p, *m, h, rest, dv_guess, (b_cum, b));
        let mut a = self.heat.mass(dv).clamp(0.0, 1.0);
        cur.v += dv;
        cur.wall += drift * dv;
        if receding < 0.0 {
            // the second half-shift, and the mass after it (spectral again)
            self.heat.finish(p, dv);
            shift(p, h, receding);
            cur.wall += receding;
            self.heat.load(p, h, 0.0, 0.0);
            a = self.heat.mass(0.0).clamp(0.0, 1.0);
        }
        cur.a = a;
        if commit {
            if receding == 0.0 {
                self.heat.finish(p, dv);
            }
            if cur.v.sqrt() > 2.0 * self.acc.points_per_width * h {
                coarsen(p, m, h_ref);
            }
        }
        a
    }

    /// The grid `p` (offset `m`, spacing `h`) extended with zeros or cut to reach `need`, to
    /// an FFT-friendly size 2^a·3^b·5^c (the transform has length 2N, and a prime factor
    /// would cost a Rader transform), at most [`Marcher::max_nodes`]: beyond it the march is
    /// flagged and cut (see [`GRID_MAX_NODES`]), and the solve refuses.
    fn size_grid(&mut self, p: &mut Vec<f64>, m: usize, h: f64, need: f64) {
        let top = ((need / h).ceil() as usize + 1).saturating_sub(m).max(8);
        let n = smooth_size(top);
        let n = if n > self.max_nodes() {
            self.overflow = true;
            self.max_nodes()
        } else {
            n
        };
        p.resize(n + 1, 0.0);
        p[n] = 0.0;
    }

    /// The heat step of a grid piece (the grid `p`, offset `m`, spacing `h`; variance measure
    /// `b` after `b_cum` of the step): the drift c = `rest`/Δv, Δv by the same RK4 rule in B
    /// as the analytic stage with a(v) from the loaded coefficients (so the switch between
    /// the stages is continuous), c re-solved from the new Δv until c·Δv hits `rest` to 1e-3
    /// (at most 4 tries, from Δv ≈ `dv_guess`). Leaves the step loaded in the heat operator;
    /// returns Δv and c.
    fn heat_step(
        &mut self,
        p: &[f64],
        m: usize,
        h: f64,
        rest: f64,
        mut dv_guess: f64,
        (b_cum, b): (f64, f64),
    ) -> (f64, f64) {
        let model = self.scene.model;
        let mut drift = 0.0;
        let mut dv = 0.0;
        for attempt in 0..4 {
            if rest != 0.0 && dv_guess > 0.0 {
                drift = rest / dv_guess;
            }
            let ext = if m == 0 { 2.0 * drift } else { 0.0 };
            self.heat.load(p, h, ext, drift);
            let heat = &self.heat;
            let rate = |u: f64| model.broadening(heat.mass(u).clamp(0.0, 1.0));
            dv = variance_step(&rate, b_cum, b);
            if drift == 0.0 || (drift * dv - rest).abs() <= 1e-3 * rest.abs() || attempt == 3 {
                break;
            }
            dv_guess = dv;
        }
        (dv, drift)
    }
}

/// Coarsens the grid `p` (offset `m`, spacing `h`) by 2: every other node of the lattice
/// x = jh through the wall kept (padded by a zero where the offset or the end is odd). The
/// spacing follows √v of the distribution it holds, `points_per_width` nodes per width.
fn coarsen(p: &mut Vec<f64>, m: &mut usize, h: &mut f64) {
    if *m % 2 == 1 {
        p.insert(0, 0.0);
        *m -= 1;
    }
    if (p.len() - 1) % 2 == 1 {
        p.push(0.0);
    }
    let coarse: Vec<f64> = p.iter().step_by(2).copied().collect();
    *p = coarse;
    *m /= 2;
    *h *= 2.0;
}

/// Where a march stands between steps.
#[derive(Clone)]
pub(super) struct Cursor {
    /// The next step's index.
    pub(super) k: usize,
    /// Accumulated variance.
    pub(super) v: f64,
    /// The wall's current position σ_a*.
    pub(super) wall: f64,
    pub(super) state: State,
    /// Σ b of the steps before the previous one (the RK4 substep rule).
    b_cum: f64,
    /// a_r at the cursor's node.
    pub(super) a: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heat_matches_mirror_gaussian() {
        // a mirror Gaussian of variance v0 evolved by dv is the mirror Gaussian of v0 + dv
        let (d, v0, dv): (f64, f64, f64) = (0.3, 0.01, 0.02);
        let h = 0.1f64.sqrt() / 20.0;
        let n = ((d + 12.0 * (v0 + dv).sqrt()) / h).ceil() as usize;
        let mut p: Vec<f64> = (0..=n)
            .map(|j| {
                let x = j as f64 * h;
                if j == 0 || j == n {
                    0.0
                } else {
                    gauss(x - d, v0) - gauss(x + d, v0)
                }
            })
            .collect();
        let mass = Heat::new().apply(&mut p, h, dv);
        let v = v0 + dv;
        assert!((mass - erf(d / (2.0 * v).sqrt())).abs() < 1e-10, "{mass}");
        for (j, pj) in p.iter().enumerate() {
            let x = j as f64 * h;
            let exact = gauss(x - d, v) - gauss(x + d, v);
            assert!((pj - exact).abs() < 1e-12, "{j}: {pj} vs {exact}");
        }
    }
}
