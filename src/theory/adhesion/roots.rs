//! Every root of the scalar self-consistency H(C) = 0 of a scene (see `shooting`): the
//! branches of the adhesive solution at one load.
//!
//! H(−I_full) < 0 < H(γ_s), so the roots come in an odd number; H changes over many decades
//! of |C| (the onset of the walls moves from q_s to q_L as C goes from −I(q_s) to 0, and a
//! tiny positive C already puts a wall at the coarsest scale), so the scan runs in
//! w = asinh(C/c₀), logarithmic in |C| on both sides of 0, with c₀ a thousandth of the
//! coarsest step's full-contact energy (below that C no longer changes the walls):
//!
//! 1. scan H at [`SCAN_PER_DECADE`] points per decade of |C| on a grid of half the requested
//!    resolution (a quarter of the cost), bisect every cell that may hold a root (a bound from
//!    the monotone parts of H, see `scan`, unless H's curvature next to a narrow cell rules
//!    it out, see `smooth_cell`), and keep every sign change;
//! 2. take H at the requested resolution at the ends of each sign-change cell, widening the
//!    cell through the scan points (and merging it with the next) until H has the coarse
//!    scan's sign at both ends; where the region then shows fewer sign changes than the coarse
//!    scan did, bisect its cells at the requested resolution as the scan does (a pair still
//!    missing has merged there: a fold, dropped); refine every sign change with Brent's method
//!    in w to |H| ≤ tol·γ_s·a_r(q_s). Roots that do not alternate in sign (−…+) send the whole
//!    scan to the requested resolution;
//! 3. a root where H rises (H' > 0) is stable, one where it falls is the unstable middle
//!    branch of a hysteresis loop.
//!
//! With a warm start (the roots of a nearby load) each is re-bracketed next to its old C
//! first — or next to the C extrapolated from the two loads before (a sweep's path,
//! `strategy::solve_continued`) — from ±2 % in C, the far end moved on the side H(C_old)
//! points to, to just past the secant's guess through the last two probes (else 4× further),
//! up to a factor ~3; Brent's method starts from the last two probes. The scan runs only when
//! that fails or the brackets do not alternate in sign. On system II's thin slab inside a
//! hysteresis window (three roots) a tracked load took 40 marches with the blind 4× widening,
//! 21 with the secant, 14 with the extrapolated start; a full scan takes ~45.

use super::grid::build_grid;
use super::propagator::Marcher;
use super::shooter::{balance_floor, check_bounded, check_cancel, point, smooth_cell, Point, Scale, Shooter};
use super::shooting::{Record, Shot};
use super::walls::WallCoefficients;
use super::AdhesionAccuracy;
use crate::error::Result;
use crate::input::scene::Scene;
use std::sync::atomic::AtomicBool;

/// Scan points per decade of |C| before the refinement (at least 3 points): the bisection by
/// the monotone bound places the others. 0.5 (a point every 2 decades) spent most of a cold
/// solve on points far from any root; at 0.1 the branches of 2592 scenes (systems I and II,
/// models 1, 3, 4, t·q_r = 0.05…∞, 0.5–1.5 γ_s, p* = 1e-8…0.1) and of 1440 scenes around
/// the thin slab's folds (53 with several branches) are the same, for 15–25 % less time.
pub(super) const SCAN_PER_DECADE: f64 = 0.1;
/// Smallest scan cell in w = asinh(C/c₀) (about 10 % in C; the requested resolution moves a
/// root by about 5 %, so a finer coarse bracket is lost anyway). 0.03 gave the same branches
/// on the sets of [`SCAN_PER_DECADE`].
const SCAN_MIN_CELL: f64 = 0.1;
/// Widest reach in w of a warm bracket (a factor ~3 in C).
pub(super) const WARM_MAX: f64 = 1.15;
/// Most shots of a scan (coarse) or of the bisection of the regions (fine).
const SCAN_MAX: usize = 400;

/// One root of H: a branch of the scene.
pub(super) struct Root {
    /// C = γ(q_L) (J/m²).
    pub(super) c: f64,
    /// The recorded march at the root (requested resolution).
    pub(super) record: Record,
    /// H rises through the root.
    pub(super) stable: bool,
    /// |H|/(γ_s a_r(q_s)) at the root = |γ(q_s)/γ_s − 1|: the energy balance's mismatch
    /// (beyond its round-off where the tolerance lies below that, see `shooter::BALANCE_ULPS`).
    pub(super) h_rel: f64,
}

/// All roots of H for `scene` at resolution `acc`, lowest C first. `warm`: C values of a
/// nearby scene's roots, tried first; `trend`: the roots one step further back and the ratio
/// r of this step to that one, to start each warm bracket at w + r·(w − w_older) (linear
/// extrapolation in w). Returns the roots and the shots spent.
pub(super) fn find_roots(
    scene: &Scene,
    acc: &AdhesionAccuracy,
    warm: &[f64],
    trend: Option<(&[f64], f64)>,
    cancel: Option<&AtomicBool>,
) -> Result<(Vec<Root>, usize)> {
    let grid = build_grid(scene, acc.steps_per_ln_q);
    let mut fine = Shooter {
        m: Marcher::new(scene, &grid, *acc),
        coef: WallCoefficients::new(scene, &grid),
        shots: 0,
    };
    let gs = scene.gamma;
    let i_full = fine.m.full_energy();
    let e0 = if grid.e_scale > 0.0 { grid.e_scale } else { i_full }.max(1e-300);
    let scale = Scale { c0: 1e-3 * e0.min(gs) };
    let (w_lo, w_hi) = (scale.w(-i_full), scale.w(gs));
    let tol = acc.tol * gs;

    if let Some(roots) = warm_roots(&mut fine, &scale, warm, trend, (w_lo, w_hi), tol, cancel)? {
        check_bounded(&fine)?;
        let shots = fine.shots;
        if std::env::var_os("ASPERITY_DEBUG").is_some() {
            eprintln!("roots: warm, {shots} fine shots, {} roots", roots.len());
        }
        return Ok((roots, shots));
    }

    // coarse scan
    let coarse_acc = AdhesionAccuracy {
        steps_per_ln_q: (acc.steps_per_ln_q * 0.5).max(4.0),
        points_per_width: (acc.points_per_width * 0.5).max(3.0),
        ..*acc
    };
    let cgrid = build_grid(scene, coarse_acc.steps_per_ln_q);
    let mut coarse = Shooter {
        m: Marcher::new(scene, &cgrid, coarse_acc),
        coef: WallCoefficients::new(scene, &cgrid),
        shots: 0,
    };
    let pts = scan(&mut coarse, &scale, w_lo, w_hi, gs, cancel)?;
    let regions = sign_change_regions(&pts);
    let mut roots = refine_regions(&mut fine, &scale, &pts, regions, (gs, tol), cancel)?;
    // the whole sign pattern is −…+ with alternating roots; where a root moved beyond its
    // region at the fine resolution that fails, and the scan is repeated at the fine one
    let alternate = alternates(&roots);
    if !alternate {
        roots.clear();
        let fp = scan(&mut fine, &scale, w_lo, w_hi, gs, cancel)?;
        refine_sign_changes(&mut fine, &scale, &fp, tol, cancel, &mut roots)?;
    }
    if std::env::var_os("ASPERITY_DEBUG").is_some() {
        eprintln!(
            "roots: {} coarse shots ({} scan points), {} fine, {} roots{}",
            coarse.shots,
            pts.len(),
            fine.shots,
            roots.len(),
            if alternate { "" } else { " (fine scan)" }
        );
    }
    // the sign pattern is −…+: if every bracket was lost (roots that merge at the fine
    // resolution), the whole interval at the fine resolution still holds one
    if roots.is_empty() {
        let ha = fine.h(scale.c(w_lo)).h;
        let hb = fine.h(scale.c(w_hi)).h;
        roots.push(refine(&mut fine, &scale, w_lo, ha, w_hi, hb, tol, cancel)?);
    }
    check_bounded(&coarse)?;
    check_bounded(&fine)?;
    Ok((roots, fine.shots + coarse.shots / 4))
}

/// The warm start of [`find_roots`]: a bracket of up to ±[`WARM_MAX`] around each old root
/// (`warm`, moved along `trend` where given) at the fine resolution `s`, each refined by
/// Brent's method — or None where a bracket is not found or the brackets do not account for
/// the whole sign pattern (the lowest rises from −, consecutive roots alternate, the highest
/// ends at +): then the scan runs.
fn warm_roots(
    s: &mut Shooter<'_>,
    scale: &Scale,
    warm: &[f64],
    trend: Option<(&[f64], f64)>,
    (w_lo, w_hi): (f64, f64),
    tol: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Option<Vec<Root>>> {
    if warm.is_empty() {
        return Ok(None);
    }
    let mut found = Vec::new();
    for (i, &c) in warm.iter().enumerate() {
        check_cancel(cancel)?;
        let w0 = match trend {
            Some((older, r)) if older.len() == warm.len() => {
                let w = scale.w(c);
                w + r * (w - scale.w(older[i]))
            }
            _ => scale.w(c),
        }
        .clamp(w_lo, w_hi);
        match warm_bracket(s, scale, w0, i % 2 == 0, (w_lo, w_hi), WARM_MAX) {
            Some(br) => found.push(br),
            None => return Ok(None),
        }
    }
    // the warm roots must account for the whole sign pattern: lowest rises from −, and
    // consecutive roots alternate
    if found.is_empty() {
        return Ok(None);
    }
    let alternate = found
        .windows(2)
        .all(|p| (p[0].1 < 0.0) != (p[1].1 < 0.0) && p[0].2 < p[1].0);
    if !(alternate && found[0].1 < 0.0 && found[found.len() - 1].3 > 0.0) {
        return Ok(None);
    }
    let mut roots = Vec::with_capacity(found.len());
    for (a, ha, b, hb) in found {
        roots.push(refine(s, scale, a, ha, b, hb, tol, cancel)?);
    }
    Ok(Some(roots))
}

/// The regions of the coarse scan `pts` that hold its sign changes: (first point, last
/// point, number of sign changes), one per sign-change cell, cells that touch merged.
fn sign_change_regions(pts: &[Point]) -> Vec<(usize, usize, usize)> {
    let n = pts.len() - 1;
    let mut regions: Vec<(usize, usize, usize)> = Vec::new();
    for i in (0..n).filter(|&i| (pts[i].h < 0.0) != (pts[i + 1].h < 0.0)) {
        let (lo, hi) = (i, i + 1);
        match regions.last_mut() {
            Some(r) if lo <= r.1 => {
                r.1 = hi;
                r.2 += 1;
            }
            _ => regions.push((lo, hi, 1)),
        }
    }
    regions
}

/// The roots of the coarse scan's `regions` at the fine resolution `s` (`gs` = γ_s, `tol` as
/// in [`refine`]), lowest first. The fine resolution moves the roots, a fold's nearly merged
/// pair most: H is taken at the fine resolution at each region's scan points, and where that
/// shows fewer sign changes than the coarse scan did, the region's cells are bisected at the
/// fine resolution as the scan bisects (a pair that is still missing then has merged: a fold,
/// dropped). Consecutive sign changes of one sampled H alternate, so the roots of a region do
/// too.
fn refine_regions(
    s: &mut Shooter<'_>,
    scale: &Scale,
    pts: &[Point],
    regions: Vec<(usize, usize, usize)>,
    (gs, tol): (f64, f64),
    cancel: Option<&AtomicBool>,
) -> Result<Vec<Root>> {
    let n = pts.len() - 1;
    let mut roots = Vec::new();
    // a region is widened, one scan point at a time, until H at the fine resolution has the
    // coarse scan's sign at both its ends (a root moved out of it), swallowing the regions it
    // reaches; it never reaches back into the previous region
    let mut fine_pts: Vec<Option<Point>> = vec![None; pts.len()];
    let mut fine_at = |fine: &mut Shooter<'_>, i: usize| -> Point {
        *fine_pts[i].get_or_insert_with(|| point(fine, scale, pts[i].w, gs))
    };
    let mut floor = 0usize;
    let mut ri = 0usize;
    while ri < regions.len() {
        check_cancel(cancel)?;
        let (mut lo, mut hi, mut count) = regions[ri];
        lo = lo.max(floor);
        loop {
            if lo > floor && (fine_at(s, lo).h < 0.0) != (pts[lo].h < 0.0) {
                lo -= 1;
                continue;
            }
            if hi < n && (fine_at(s, hi).h < 0.0) != (pts[hi].h < 0.0) {
                hi += 1;
                while ri + 1 < regions.len() && regions[ri + 1].0 <= hi {
                    ri += 1;
                    hi = hi.max(regions[ri].1);
                    count += regions[ri].2;
                }
                continue;
            }
            break;
        }
        let mut fp: Vec<Point> = (lo..=hi).map(|i| fine_at(s, i)).collect();
        if sign_changes(&fp) < count {
            fp = bisect_cells(s, scale, fp, gs, cancel)?;
        }
        refine_sign_changes(s, scale, &fp, tol, cancel, &mut roots)?;
        floor = hi;
        ri += 1;
    }
    Ok(roots)
}

/// Whether `roots` make the whole sign pattern −…+: the lowest and the highest stable, stable
/// and unstable alternating.
fn alternates(roots: &[Root]) -> bool {
    roots.first().is_some_and(|r| r.stable)
        && roots.last().is_some_and(|r| r.stable)
        && roots.windows(2).all(|p| p[0].stable != p[1].stable)
}

/// Half-width in w of the first warm bracket (about 2 % in C): a neighbouring load's root
/// moves by less, so Brent's method starts close.
const WARM_FIRST: f64 = 0.02;
/// The secant's guess of a warm root is overshot by this factor and [`WARM_MARGIN`] in w, so
/// that the probe usually lands just past the root (a sign change next to it).
const WARM_OVERSHOOT: f64 = 1.15;
/// See [`WARM_OVERSHOOT`].
const WARM_MARGIN: f64 = 0.003;

/// A sign change of H next to w₀ (an old root; H rises through it when `rising`): H(w₀)
/// says on which side the root now lies, and that side's end moves out from ±[`WARM_FIRST`]
/// up to `max` (within [w_lo, w_hi]): to just past the secant's guess through the last two
/// probes where H approaches 0, else 4× further. Returns (a, H(a), b, H(b)) with a < b, the
/// last two probes (the tightest bracket seen), or None when no sign change lies within
/// `max` on that side.
pub(super) fn warm_bracket(
    s: &mut Shooter<'_>,
    scale: &Scale,
    w0: f64,
    rising: bool,
    (w_lo, w_hi): (f64, f64),
    max: f64,
) -> Option<(f64, f64, f64, f64)> {
    let h0 = s.h(scale.c(w0)).h;
    if h0 == 0.0 {
        return None;
    }
    let right = (h0 < 0.0) == rising;
    let (mut wp, mut hp) = (w0, h0);
    let mut d = WARM_FIRST.min(max);
    loop {
        let w = if right { (w0 + d).min(w_hi) } else { (w0 - d).max(w_lo) };
        if w == wp {
            return None;
        }
        let h = s.h(scale.c(w)).h;
        if (h < 0.0) != (h0 < 0.0) {
            return Some(if right { (wp, hp, w, h) } else { (w, h, wp, hp) });
        }
        if d >= max || w == w_lo || w == w_hi {
            return None;
        }
        // the secant through the last two probes, where H approaches 0 along them
        let step = (w - wp).abs();
        let guess = if h.abs() < hp.abs() {
            step * h.abs() / (hp.abs() - h.abs())
        } else {
            f64::INFINITY
        };
        let next = d + WARM_OVERSHOOT * guess + WARM_MARGIN;
        d = if next.is_finite() {
            next.clamp(d + WARM_MARGIN, 4.0 * d)
        } else {
            4.0 * d
        }
        .min(max);
        (wp, hp) = (w, h);
    }
}

/// The scan of H over [w_lo, w_hi]: [`SCAN_PER_DECADE`] points per decade of |C|, then every
/// cell that may hold a root bisected down to [`SCAN_MIN_CELL`]. F = C + I and G = γ_s a_r
/// both rise with C (more adhesion at the coarse scales means more contact at every scale),
/// so on a cell H lies in [F₀ − G₁, F₁ − G₀]: a cell whose bound excludes 0 holds no root and
/// is left alone, one whose bound includes 0 may hold a pair of roots and is bisected.
///
/// The first points run from w_lo up and stop at the first one where F > γ_s: G ≤ γ_s
/// (a_r ≤ 1) and F only rises, so H > 0 beyond it and no root lies there. Those marches are
/// the dearest of the scan (a wall from the coarsest scale on), and the flat stretch of H
/// around C = 0 was a third of a cold solve's time.
pub(super) fn scan(
    s: &mut Shooter<'_>,
    scale: &Scale,
    w_lo: f64,
    w_hi: f64,
    gs: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<Point>> {
    let cell = std::f64::consts::LN_10 / SCAN_PER_DECADE;
    let n0 = ((w_hi - w_lo) / cell).ceil().max(2.0) as usize; // at least 3 points
    let mut pts = Vec::with_capacity(4 * n0);
    for i in 0..=n0 {
        check_cancel(cancel)?;
        let p = point(s, scale, w_lo + (w_hi - w_lo) * i as f64 / n0 as f64, gs);
        pts.push(p);
        if p.f > gs {
            break;
        }
    }
    bisect_cells(s, scale, pts, gs, cancel)
}

/// The number of sign changes of H along `pts`.
fn sign_changes(pts: &[Point]) -> usize {
    pts.windows(2).filter(|p| (p[0].h < 0.0) != (p[1].h < 0.0)).count()
}

/// Bisects every cell of `pts` whose bound [F₀ − G₁, F₁ − G₀] on H includes 0, down to
/// [`SCAN_MIN_CELL`] or [`SCAN_MAX`] shots of `s`.
fn bisect_cells(
    s: &mut Shooter<'_>,
    scale: &Scale,
    mut pts: Vec<Point>,
    gs: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<Point>> {
    loop {
        let mut next = Vec::with_capacity(2 * pts.len());
        let mut split = false;
        for i in 0..pts.len() {
            next.push(pts[i]);
            if i + 1 == pts.len() || s.shots >= SCAN_MAX {
                continue;
            }
            let (p0, p1) = (pts[i], pts[i + 1]);
            let (lo, hi) = (p0.f - p1.g, p1.f - p0.g);
            if lo < 0.0 && hi > 0.0 && p1.w - p0.w > SCAN_MIN_CELL && !smooth_cell(&pts, i) {
                check_cancel(cancel)?;
                next.push(point(s, scale, 0.5 * (p0.w + p1.w), gs));
                split = true;
            }
        }
        pts = next;
        if !split {
            return Ok(pts);
        }
    }
}

/// Every sign change of H along `pts` refined (see [`refine`]) and appended to `roots`.
fn refine_sign_changes(
    s: &mut Shooter<'_>,
    scale: &Scale,
    pts: &[Point],
    tol: f64,
    cancel: Option<&AtomicBool>,
    roots: &mut Vec<Root>,
) -> Result<()> {
    for p in pts.windows(2) {
        if (p[0].h < 0.0) != (p[1].h < 0.0) {
            roots.push(refine(s, scale, p[0].w, p[0].h, p[1].w, p[1].h, tol, cancel)?);
        }
    }
    Ok(())
}

/// A bracket narrower than this in w (C to 1e-6 relative, far below any resolution's
/// error) across which H still changes by more than [`JUMP_SLOPE`] times what the first
/// bracket's mean slope predicts straddles a jump of the discrete H, not a root (where the
/// wall's onset crosses a step's end as C changes; `strategy::COLLAPSED`): Brent's method
/// stops there instead of bisecting on to round-off. Next to system II's thin-slab fold
/// (t·q_r = 0.1, p* = 2.29e-4, chart accuracy) a root sat on such a jump of 7e-7 J/m², and
/// the 30 bisections down to 1e-13 cost 180 ms (the marches on one side of the jump are
/// 30× dearer: the onset right at a step's end starts the wall at a speed that refines
/// the grid); the rule stops after 11.
const JUMP_WIDTH: f64 = 1e-6;
/// See [`JUMP_WIDTH`].
const JUMP_SLOPE: f64 = 100.0;

/// Interpolation steps (inverse quadratic, else secant) of [`refine`] after which the
/// bracket must have halved, else the next step bisects. Brent's own rule (each step at most
/// half the one before last) bisected where H rises steeply just past a root that the first
/// secant undershot (a cold solve at system II, t·q_r = 1, p* = 1e-6, chart accuracy: a
/// bracket of 1.9 in w, 14 marches, two of them 3–10 ms out in the steep part, where the
/// walls start at the coarsest scales). Such a slow turn instead stretches the interpolated
/// step past the root (2×, 4×, … at most to the midpoint), which brings the far end in:
/// 7 marches there.
const SLOW_STEPS: usize = 3;

/// Brent's method in w on a bracket [a, b] with H(a)·H(b) < 0, to |H| ≤ tol·a_r(q_s) (a
/// relative mismatch of the energy balance at q_s: |γ(q_s)/γ_s − 1| ≤ tol), a bracket
/// below round-off, or a bracket across a jump of H ([`JUMP_WIDTH`]); the root's march
/// recorded.
#[allow(clippy::too_many_arguments)]
pub(super) fn refine(
    s: &mut Shooter<'_>,
    scale: &Scale,
    a: f64,
    ha: f64,
    b: f64,
    hb: f64,
    tol: f64,
    cancel: Option<&AtomicBool>,
) -> Result<Root> {
    let stable = ha < 0.0;
    let gs = scale_gamma(s);
    // (w, H, a_r(q_s)); a_r unknown (NaN) for the bracket's given ends. Every shot is
    // recorded (the record costs a few vectors, a march to repeat costs ~1 ms): the best one's
    // record is the root's
    let (mut pa, mut pb) = ((a, ha, f64::NAN), (b, hb, f64::NAN));
    let mut records: Vec<(f64, Shot)> = Vec::new();
    if pa.1.abs() < pb.1.abs() {
        std::mem::swap(&mut pa, &mut pb);
    }
    let mut pc = pa;
    // the bracket's widths since the last bisection, and the stretch of a slow step
    let mut widths: Vec<f64> = Vec::new();
    let mut boost = 2.0;
    // the first bracket's mean slope, against which a jump of H shows (see JUMP_WIDTH)
    let mean_slope = (pb.1 - pa.1).abs() / (pb.0 - pa.0).abs();
    for _ in 0..s.m.acc.max_iterations {
        check_cancel(cancel)?;
        let ((a, fa, _), (b, fb, ab), (c, fc, _)) = (pa, pb, pc);
        let width = (b - a).abs();
        // where the tolerance lies below the balance's round-off (weak adhesion), the bracket
        // narrows down to w's own ulps: |H| then reaches that round-off
        let min_width = if tol * ab < balance_floor(scale, b) {
            4.0 * f64::EPSILON
        } else {
            1e-13
        };
        if fb.abs() <= tol * ab
            || width <= min_width * (1.0 + b.abs())
            || (width < JUMP_WIDTH && (fb - fa).abs() > JUMP_SLOPE * mean_slope * width)
        {
            break;
        }
        // inverse quadratic interpolation, else secant, with Brent's safeguards
        let mut x = if fa != fc && fb != fc {
            a * fb * fc / ((fa - fb) * (fa - fc))
                + b * fa * fc / ((fb - fa) * (fb - fc))
                + c * fa * fb / ((fc - fa) * (fc - fb))
        } else {
            b - fb * (b - a) / (fb - fa)
        };
        let lo = (3.0 * a + b) / 4.0;
        let outside = !((x > lo.min(b)) && (x < lo.max(b)));
        // slow: the bracket has not halved over the last SLOW_STEPS interpolations
        let slow = widths.len() >= SLOW_STEPS && width > 0.5 * widths[widths.len() - SLOW_STEPS];
        if outside || !x.is_finite() {
            x = 0.5 * (a + b);
            widths.clear();
        } else if slow {
            // one-sided convergence (the far end stays): the step stretched past the root,
            // `boost` times (doubling at each slow turn), at most to the midpoint
            let m = 0.5 * (a + b);
            let stretched = b + boost * (x - b);
            x = if (stretched - b).abs() < (m - b).abs() {
                stretched
            } else {
                m
            };
            boost *= 2.0;
            widths.clear();
        }
        if widths.last().is_some_and(|&w0| width <= 0.5 * w0) {
            boost = 2.0;
        }
        widths.push(width);
        s.shots += 1;
        let shot = s.m.shoot(&s.coef, scale.c(x), true);
        let px = (x, shot.h, shot.a_s);
        records.retain(|r| r.0 == pa.0 || r.0 == pb.0);
        records.push((x, shot));
        pc = pb;
        if (fa < 0.0) != (px.1 < 0.0) {
            pb = px;
        } else {
            pa = px;
        }
        if pa.1.abs() < pb.1.abs() {
            std::mem::swap(&mut pa, &mut pb);
        }
    }
    let shot = match records.into_iter().find(|r| r.0 == pb.0) {
        Some((_, shot)) => shot,
        None => {
            s.shots += 1;
            s.m.shoot(&s.coef, scale.c(pb.0), true)
        }
    };
    // the energy balance's relative mismatch; where the tolerance lies below the balance's
    // round-off (weak adhesion), the mismatch in excess of that round-off (see `balance_floor`)
    let rel = gs * shot.a_s.max(1e-300);
    let (h, floor) = (shot.h.abs(), balance_floor(scale, pb.0));
    let h_rel = if floor > tol * shot.a_s {
        (h - floor).max(0.0) / rel
    } else {
        h / rel
    };
    Ok(Root {
        c: shot.c,
        h_rel,
        record: shot.record.expect("recorded"),
        stable,
    })
}

fn scale_gamma(s: &Shooter<'_>) -> f64 {
    s.m.scene.gamma.max(1e-300)
}
