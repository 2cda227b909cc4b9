//! The resolution march of the adhesive theory, solved the plain way: finite differences on a
//! fixed uniform σ* grid, implicit steps in the accumulated variance v, and the absorbing wall
//! σ* = −σ_a*(q) placed between nodes by the Shortley–Weller stencil.
//!
//! ```text
//! ∂Pr/∂v = ½ ∂²Pr/∂σ²  on σ > −σ_a(q),  Pr(−σ_a) = 0,  Pr(σ, q_L) = δ(σ − p*)     [S-5, S-7]
//! dv = W(a_r)^{2α} dB,  dB = f²q² dm/(4ḡ²)                                    [S-2, S-15]
//! a_r(q) = ∫_{−σ_a}^∞ Pr dσ                                                    [S-6]
//! ```
//!
//! Before the wall can matter (B ≤ (p*/Z)², Z = 9: the free Gaussian lies 9 widths above
//! σ* = 0 ≥ −σ_a, the mass it could have lost is < 1e-18) Pr is the free Gaussian N(p*, v)
//! with a_r = 1 and W(1) = 1, so v = B there. From that point on the grid carries Pr: node
//! spacing h ≤ √v/n (n = points per width), doubled by dropping every other node whenever
//! √v > 2nh; nodes from max(wall, p* − Z√v) to p* + Z√v (Pr is bounded by the free Gaussian,
//! so the cut-offs lose < 1e-18).
//!
//! Steps: at most `eps` in ΔB/B and 1/`steps_per_ln_q` in ln q, never across q_r, each split
//! into `split` equal parts (nested refinement). Each step is extrapolated backward Euler,
//! 2·BE(Δ/2)∘BE(Δ/2) − BE(Δ) (second order and L-stable for a fixed wall; the wall of each
//! backward-Euler solve sits at its end, so a moving wall leaves a first-order error: measured
//! in `tests/adhesion_oracle.rs`). Each step is implicit in a_r at its midpoint and end
//! (through W, and through the wall, whose γ divides by a_r): both are iterated to
//! |Δa| ≤ 1e-13·a. Δv and the energy integral use the trapezoid rule in a between the ends of
//! each half-step over exact (Gauss) integrals of the measure. The step in which the wall
//! turns on (σ_a ∝ √(J − J*) just after it) is split there, so that the square-root onset
//! starts on a node and the error stays smooth in the step size.

use super::physics::Physics;

/// Widths between the mean and the cut-offs of the grid.
pub const Z: f64 = 9.0;

/// The resolution of one march.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// Largest ΔB/B of a step (B: the unweighted accumulated variance).
    pub eps: f64,
    /// Most steps per unit of ln q.
    pub steps_per_ln_q: f64,
    /// Smallest number of grid nodes per width √v.
    pub points_per_width: f64,
    /// Each step of the (eps, steps_per_ln_q) path split into this many equal steps in q
    /// (nested refinement: the error expansion in 1/split is clean).
    pub split: usize,
}

impl Resolution {
    /// Every step divided by `k` and every node spacing by √k (errors fall by k: first order
    /// in the step, second order in h).
    pub fn refined(&self, k: f64) -> Resolution {
        Resolution {
            points_per_width: self.points_per_width * k.sqrt(),
            split: (self.split as f64 * k).round() as usize,
            ..*self
        }
    }
}

/// The resolution nodes and per-step integrals of a march (independent of the wall).
#[derive(Debug, Clone)]
pub struct Path {
    /// q_start, the first node carried by the grid (q_L before it: free Gaussian).
    pub q: Vec<f64>,
    /// ΔB of each step.
    pub db: Vec<f64>,
    /// ∫_step (qE*f/4) dm of each step (J/m²).
    pub de: Vec<f64>,
    /// B(q_start).
    pub b_start: f64,
    /// ∫_{q_L}^{q_start} (qE*f/4) dm.
    pub e_start: f64,
    /// ∫_{q_L}^{q_s} (qE*f/4) dm: u_ela^(f).
    pub e_full: f64,
}

impl Path {
    pub fn new(ph: &Physics, res: &Resolution) -> Path {
        let b_of = |a: f64, b: f64| ph.integrate(a, b, |q| ph.b_density(q));
        let e_of = |a: f64, b: f64| ph.integrate(a, b, |q| ph.e_density(q));
        let b_start = (ph.pressure / Z).powi(2);
        // q_start: B(q_start) = b_start, by bisection in ln(q − q_L)
        let total_b = integral_to(ph, ph.q_s, &|q| ph.b_density(q));
        assert!(
            total_b > b_start,
            "p* too large for the oracle (the wall never matters)"
        );
        let (mut lo, mut hi) = ((1e-300f64).ln(), (ph.q_s - ph.q_l).ln());
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if integral_to(ph, ph.q_l + mid.exp(), &|q| ph.b_density(q)) < b_start {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let q_start = (ph.q_l + hi.exp()).min(ph.q_s);
        let e_start = integral_to(ph, q_start, &|q| ph.e_density(q));
        let b_start_exact = integral_to(ph, q_start, &|q| ph.b_density(q));
        let mut q = vec![q_start];
        let (mut db, mut de) = (Vec::new(), Vec::new());
        let mut b = b_start_exact;
        let mut cur = q_start;
        let ratio = (1.0 / res.steps_per_ln_q).exp();
        let breaks = [ph.q_r, ph.q_s];
        while cur < ph.q_s * (1.0 - 1e-14) {
            let brk = breaks
                .iter()
                .copied()
                .find(|&x| x > cur * (1.0 + 1e-14))
                .unwrap_or(ph.q_s);
            let mut next = (cur * ratio).min(brk);
            if next > brk * (1.0 - 1e-12) {
                next = brk;
            }
            let mut inc = b_of(cur, next);
            while inc > res.eps * b {
                next = cur + 0.5 * (next - cur);
                inc = b_of(cur, next);
            }
            b += inc;
            let m = res.split.max(1);
            for i in 0..m {
                let a = cur + (next - cur) * i as f64 / m as f64;
                let z = if i + 1 == m {
                    next
                } else {
                    cur + (next - cur) * (i + 1) as f64 / m as f64
                };
                db.push(b_of(a, z));
                de.push(e_of(a, z));
                q.push(z);
            }
            cur = next;
        }
        let e_full = e_start + de.iter().sum::<f64>();
        Path {
            q,
            db,
            de,
            b_start: b_start_exact,
            e_start,
            e_full,
        }
    }
}

/// ∫_{q_L}^{q} g dm: 32 panels linear in q on the plateau part, 64 geometric ones on the
/// tail part.
fn integral_to(ph: &Physics, q: f64, g: &dyn Fn(f64) -> f64) -> f64 {
    let mut sum = 0.0;
    let top = q.min(ph.q_r);
    if top > ph.q_l {
        let w = (top - ph.q_l) / 32.0;
        for k in 0..32 {
            let a = ph.q_l + w * k as f64;
            let b = if k == 31 { top } else { a + w };
            sum += ph.integrate(a, b, g);
        }
    }
    if q > ph.q_r {
        let r = (q / ph.q_r).powf(1.0 / 64.0);
        for k in 0..64 {
            let a = ph.q_r * r.powi(k);
            let b = if k == 63 { q } else { ph.q_r * r.powi(k + 1) };
            sum += ph.integrate(a, b, g);
        }
    }
    sum
}

/// What a march returns.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// a_r(q_s).
    pub a_r: f64,
    /// ∫_{q_L}^{q_s} a_r W(a_r) (qE*f/4) dm (J/m²).
    pub energy: f64,
    /// v(q_s).
    pub v: f64,
    /// σ_a*(q_s).
    pub sigma_a: f64,
    /// a_r at the path nodes (a_r = 1 before q_start).
    pub a_nodes: Vec<f64>,
}

/// Pr on the grid: node j sits at σ* = j·h; `p[k]` is node `j0 + k`.
struct Grid {
    h: f64,
    j0: i64,
    p: Vec<f64>,
}

impl Grid {
    fn value(&self, j: i64) -> f64 {
        let k = j - self.j0;
        if k < 0 || k >= self.p.len() as i64 {
            0.0
        } else {
            self.p[k as usize]
        }
    }

    /// Makes nodes lo..=hi addressable (zeros where new).
    fn cover(&mut self, lo: i64, hi: i64) {
        if lo < self.j0 {
            let add = (self.j0 - lo) as usize;
            let mut v = vec![0.0; add];
            v.extend_from_slice(&self.p);
            self.p = v;
            self.j0 = lo;
        }
        let end = self.j0 + self.p.len() as i64 - 1;
        if hi > end {
            self.p.resize(self.p.len() + (hi - end) as usize, 0.0);
        }
    }

    /// Keeps the even nodes and doubles h.
    fn coarsen(&mut self) {
        let first = self.j0 + self.j0.rem_euclid(2);
        let mut p = Vec::new();
        let mut j = first;
        while j < self.j0 + self.p.len() as i64 {
            p.push(self.value(j));
            j += 2;
        }
        self.p = p;
        self.j0 = first / 2;
        self.h *= 2.0;
    }
}

/// One backward-Euler step of ½∂²/∂σ² over Δv on nodes lo..=hi, with Pr = 0 at distance
/// `delta` ∈ (0, h] below node lo and at node hi + 1. Returns the new values of lo..=hi.
fn implicit_step(old: &[f64], h: f64, delta: f64, dv: f64) -> Vec<f64> {
    let n = old.len();
    let r = 0.5 * dv / (h * h);
    // tridiagonal: sub[i] x[i−1] + diag[i] x[i] + sup[i] x[i+1] = old[i]
    let mut diag = vec![1.0 + 2.0 * r; n];
    let mut sub = vec![-r; n];
    let mut sup = vec![-r; n];
    // Shortley–Weller at the wall: Pr'' ≈ 2/(δ+h)·[(P₁ − P₀)/h − P₀/δ]
    let c = dv / (delta + h);
    diag[0] = 1.0 + c * (1.0 / h + 1.0 / delta);
    sup[0] = -c / h;
    sub[0] = 0.0;
    if n == 1 {
        sup[0] = 0.0;
    }
    // Thomas algorithm
    let mut cp = vec![0.0; n];
    let mut dp = vec![0.0; n];
    cp[0] = sup[0] / diag[0];
    dp[0] = old[0] / diag[0];
    for i in 1..n {
        let m = diag[i] - sub[i] * cp[i - 1];
        cp[i] = if i + 1 < n { sup[i] / m } else { 0.0 };
        dp[i] = (old[i] - sub[i] * dp[i - 1]) / m;
    }
    let mut x = vec![0.0; n];
    x[n - 1] = dp[n - 1];
    for i in (0..n - 1).rev() {
        x[i] = dp[i] - cp[i] * x[i + 1];
    }
    x
}

/// The trapezoid mass of values at nodes lo.. (spacing h), with Pr = 0 at distance δ below
/// the first node and one spacing above the last.
fn mass(x: &[f64], h: f64, delta: f64) -> f64 {
    let inner: f64 = x.windows(2).map(|w| 0.5 * (w[0] + w[1]) * h).sum();
    0.5 * delta * x[0] + inner + 0.5 * h * x[x.len() - 1]
}

/// The marched state between steps.
struct State {
    g: Grid,
    a: f64,
    v: f64,
    /// ∫_{q_L}^{q} a W (qE*f/4) dm.
    j: f64,
    sigma_a: f64,
    /// Change of a and ΔB over the last step (a start for the next step's iteration).
    last: (f64, f64),
}

/// The active nodes lo..=hi for a wall at σ* = `wpos` and variance v, and the distance δ
/// from node lo down to the Dirichlet point below it (the wall, or p* − Z√v).
fn window(h: f64, p: f64, wpos: f64, v: f64) -> (i64, i64, f64) {
    // first active node: above the wall (by more than a hair) and above p* − Z√v
    let mut lo = (wpos / h).floor() as i64 + 1;
    if (lo as f64) * h - wpos < 1e-9 * h {
        lo += 1;
    }
    let cut = ((p - Z * v.sqrt()) / h).ceil() as i64;
    let delta = if cut > lo {
        lo = cut;
        h
    } else {
        (lo as f64 * h - wpos).min(h)
    };
    let hi = ((p + Z * v.sqrt()) / h).ceil() as i64 + 1;
    (lo, hi, delta)
}

/// One backward-Euler solve over Δv from the values `value(j)` on the window.
fn be(value: impl Fn(i64) -> f64, h: f64, win: (i64, i64, f64), dv: f64) -> Vec<f64> {
    let (lo, hi, delta) = win;
    let old: Vec<f64> = (lo..=hi).map(value).collect();
    implicit_step(&old, h, delta, dv)
}

/// The grid holding `x` on lo.. and zeros elsewhere (nodes below lo absorbed).
fn with_values(g: &Grid, x: &[f64], lo: i64) -> Grid {
    let hi = lo + x.len() as i64 - 1;
    let mut out = Grid {
        h: g.h,
        j0: g.j0,
        p: g.p.clone(),
    };
    out.cover(lo - 1, hi + 1);
    let j0 = out.j0;
    for (i, val) in out.p.iter_mut().enumerate() {
        let j = j0 + i as i64;
        *val = if j < lo || j > hi { 0.0 } else { x[(j - lo) as usize] };
    }
    out
}

/// One step to q1: extrapolated backward Euler, P = 2·BE(Δ/2)∘BE(Δ/2) − BE(Δ)
/// (L-stable; the wall of the first half-step sits at the step's midpoint q_m). a_r at q_m
/// and at q1 enter the walls, W and the energy integral: both are iterated to a fixed point
/// (|Δa| ≤ 1e-13·a). (ΔB, ΔE) of the two halves are `halves`.
fn advance(
    ph: &Physics,
    st: &mut State,
    q: (f64, f64),
    halves: [(f64, f64); 2],
    wall: &dyn Fn(f64, f64, f64, f64) -> f64,
) {
    let p = ph.pressure;
    let two_alpha = 2.0 * ph.alpha;
    let wp = |a: f64| ph.w(a).max(0.0).powf(two_alpha);
    let (qm, q1) = q;
    let [(b1, e1), (b2, e2)] = halves;
    let g0 = ph.w(st.a) * st.a;
    let slope = if st.last.1 > 0.0 { st.last.0 / st.last.1 } else { 0.0 };
    let mut am = (st.a + slope * b1).clamp(0.0, 1.0);
    let mut a1 = (st.a + slope * (b1 + b2)).clamp(0.0, 1.0);
    let mut result = None;
    for _iter in 0..200 {
        // first half, wall at q_m
        let dv1 = 0.5 * (wp(st.a) + wp(am)) * b1;
        let vm = st.v + dv1;
        let jm = st.j + 0.5 * (g0 + am * ph.w(am)) * e1;
        let sm = wall(qm, vm, am, jm);
        let winm = window(st.g.h, p, -sm, vm);
        let h = st.g.h;
        let xm = be(|j| st.g.value(j), h, winm, dv1);
        let am_new = mass(&xm, st.g.h, winm.2);
        // second half, wall at q1
        let dv2 = 0.5 * (wp(am) + wp(a1)) * b2;
        let v1 = vm + dv2;
        let j1 = jm + 0.5 * (am * ph.w(am) + a1 * ph.w(a1)) * e2;
        let s1 = wall(q1, v1, a1, j1);
        let win = window(st.g.h, p, -s1, v1);
        // the first half's values: nodes below its window absorbed, none above it
        let mid_value = |j: i64| {
            let k = j - winm.0;
            if k < 0 || k >= xm.len() as i64 {
                0.0
            } else {
                xm[k as usize]
            }
        };
        let x2 = be(mid_value, h, win, dv2);
        // one full step over the same measure, wall at q1
        let dvf = 0.5 * (wp(st.a) + wp(a1)) * (b1 + b2);
        let xf = be(|j| st.g.value(j), h, win, dvf);
        let x: Vec<f64> = x2.iter().zip(&xf).map(|(h2, f)| 2.0 * h2 - f).collect();
        let a1_new = mass(&x, st.g.h, win.2);
        let tol = 1e-13 * a1_new.abs() + 1e-300;
        let done = (a1_new - a1).abs() <= tol && (am_new - am).abs() <= tol;
        result = Some((x, win.0, a1_new, v1, j1, s1));
        if done {
            break;
        }
        am = am_new;
        a1 = a1_new;
    }
    let (x, lo, a_new, v1, j1, sa) = result.unwrap();
    st.g = with_values(&st.g, &x, lo);
    st.last = (a_new - st.a, b1 + b2);
    st.a = a_new;
    st.v = v1;
    st.j = j1;
    st.sigma_a = sa;
}

/// One step to q1 between nodes: halves at the geometric midpoint.
fn advance_step(ph: &Physics, st: &mut State, q0: f64, q1: f64, wall: &dyn Fn(f64, f64, f64, f64) -> f64) {
    let qm = 0.5 * (q0 + q1);
    let b = |a: f64, z: f64| ph.integrate(a, z, |q| ph.b_density(q));
    let e = |a: f64, z: f64| ph.integrate(a, z, |q| ph.e_density(q));
    advance(ph, st, (qm, q1), [(b(q0, qm), e(q0, qm)), (b(qm, q1), e(qm, q1))], wall);
}

/// Marches Pr from q_L to q_s with the wall σ_a*(q, v, a, J) given by `wall` at each step's
/// end (a: a_r there, J: ∫_{q_L}^{q} aW(qE*f/4)dm there). `onset`: the J at which the wall
/// turns on (σ_a ∝ √(J − onset) just after it), if any: the step containing it is split there,
/// so that the square-root onset always starts on a node and the error stays smooth in the
/// step size.
pub fn march(
    ph: &Physics,
    path: &Path,
    res: &Resolution,
    wall: &dyn Fn(f64, f64, f64, f64) -> f64,
    onset: Option<f64>,
) -> Outcome {
    let p = ph.pressure;
    let v = path.b_start;
    let n_w = res.points_per_width;
    let h0 = v.sqrt() / n_w;
    // the free Gaussian, sampled
    let lo = ((p - Z * v.sqrt()) / h0).ceil() as i64;
    let hi = ((p + Z * v.sqrt()) / h0).floor() as i64;
    let norm = 1.0 / (2.0 * std::f64::consts::PI * v).sqrt();
    let g = Grid {
        h: h0,
        j0: lo,
        p: (lo..=hi)
            .map(|j| {
                let d = j as f64 * h0 - p;
                norm * (-d * d / (2.0 * v)).exp()
            })
            .collect(),
    };
    // a = W = 1 before q_start
    let mut st = State {
        g,
        a: 1.0,
        v,
        j: path.e_start,
        sigma_a: 0.0,
        last: (0.0, 0.0),
    };
    let mut a_nodes = vec![1.0];
    for k in 0..path.db.len() {
        let (q0, q1) = (path.q[k], path.q[k + 1]);
        let split = onset.and_then(|o| {
            // J grows by ≈ aW·∫e dm over the step: split where it reaches the onset
            let aw = st.a * ph.w(st.a);
            if st.j >= o || st.j + aw * path.de[k] * 1.5 < o {
                return None;
            }
            let need = (o - st.j) / aw;
            let (mut lo, mut hi) = (q0, q1);
            if ph.integrate(q0, q1, |q| ph.e_density(q)) < need {
                return None;
            }
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if ph.integrate(q0, mid, |q| ph.e_density(q)) < need {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let qs = 0.5 * (lo + hi);
            (qs > q0 && qs < q1).then_some(qs)
        });
        match split {
            Some(qs) => {
                advance_step(ph, &mut st, q0, qs, wall);
                advance_step(ph, &mut st, qs, q1, wall);
            }
            None => advance_step(ph, &mut st, q0, q1, wall),
        }
        a_nodes.push(st.a);
        if st.v.sqrt() > 2.0 * n_w * st.g.h {
            st.g.coarsen();
        }
        // keep the storage to the live window
        let first = st.g.p.iter().position(|&x| x != 0.0).unwrap_or(0);
        if first > 64 {
            st.g.p.drain(..first - 1);
            st.g.j0 += first as i64 - 1;
        }
    }
    Outcome {
        a_r: st.a,
        energy: st.j,
        v: st.v,
        sigma_a: st.sigma_a,
        a_nodes,
    }
}
