//! Turns engine curves into series ratatui's `Chart` can draw correctly.
//!
//! ratatui 0.30's `Chart` has no log axes, places more than three axis labels wrongly, draws
//! NaN/±inf as strokes to the plot edge, joins every consecutive pair of a `Line` dataset and
//! draws nothing when an axis has min == max. Every workaround lives here, with unit tests:
//!
//! - [`Scale`]: linear or log10 axes; data are transformed before drawing, labels are written
//!   in data units ([`ticks`], with [`crate::numfmt`]).
//! - [`runs`]: a series of a [`Chart`] as the runs to draw.
//! - [`segments`]: drops points that are not finite (or not positive on a log axis) and splits
//!   the curve at every dropped point, so a gap is never bridged.
//! - [`decimate`]: keeps at most a few points per braille column.
//! - [`bounds`], [`guard`]: data bounds with padding; min == max or non-finite bounds widened.
//! - [`ticks`]: exactly two or three round labels (the upstream spacing bug starts at four).

use crate::numfmt::{nice_step, tick};

pub use crate::chart::Scale;
use crate::chart::{Chart, Series};

/// Plane points of series `s` of chart `m` drawn with y bounds `yb`, split at gaps, y outside
/// `yb` dropped when the chart clips, decimated to about `max_points`.
pub fn runs(m: &Chart, s: &Series, yb: [f64; 2], max_points: usize) -> Vec<Vec<(f64, f64)>> {
    let pts: Vec<(f64, f64)> = if m.clip_y {
        s.points
            .iter()
            .map(|&(x, y)| match m.ys.forward(y) {
                Some(v) if v >= yb[0] && v <= yb[1] => (x, y),
                _ => (x, f64::NAN),
            })
            .collect()
    } else {
        s.points.clone()
    };
    segments(&pts, m.xs, m.ys)
        .into_iter()
        .map(|r| decimate(&r, max_points))
        .collect()
}

/// Transforms `points` to the plane and splits them into drawable runs: every point that
/// cannot be drawn ends the current run. Runs of a single point are kept (drawn as a dot).
pub fn segments(points: &[(f64, f64)], xs: Scale, ys: Scale) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    for &(x, y) in points {
        match (xs.forward(x), ys.forward(y)) {
            (Some(u), Some(v)) => run.push((u, v)),
            _ => {
                if !run.is_empty() {
                    out.push(std::mem::take(&mut run));
                }
            }
        }
    }
    if !run.is_empty() {
        out.push(run);
    }
    out
}

/// Keeps at most about `max_points` points of a run (first and last always kept), by taking
/// the points of largest and smallest y in each of `max_points / 2` buckets, so spikes survive.
pub fn decimate(run: &[(f64, f64)], max_points: usize) -> Vec<(f64, f64)> {
    let max_points = max_points.max(4);
    if run.len() <= max_points {
        return run.to_vec();
    }
    let buckets = max_points / 2;
    let n = run.len();
    let mut out = Vec::with_capacity(max_points + 2);
    out.push(run[0]);
    for b in 0..buckets {
        let lo = 1 + b * (n - 2) / buckets;
        let hi = (1 + (b + 1) * (n - 2) / buckets).min(n - 1);
        if lo >= hi {
            continue;
        }
        let slice = &run[lo..hi];
        let (mut imin, mut imax) = (0, 0);
        for (i, p) in slice.iter().enumerate() {
            if p.1 < slice[imin].1 {
                imin = i;
            }
            if p.1 > slice[imax].1 {
                imax = i;
            }
        }
        let (a, c) = if imin <= imax { (imin, imax) } else { (imax, imin) };
        out.push(slice[a]);
        if c != a {
            out.push(slice[c]);
        }
    }
    out.push(run[n - 1]);
    out
}

/// Widens degenerate bounds: non-finite → [0, 1]; min == max → ± 0.5 (or ± 5 % of |x|).
pub fn guard(lo: f64, hi: f64) -> [f64; 2] {
    if !(lo.is_finite() && hi.is_finite()) {
        return [0.0, 1.0];
    }
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
    if hi - lo <= f64::EPSILON * lo.abs().max(hi.abs()).max(1e-300) {
        let d = if lo == 0.0 { 0.5 } else { 0.05 * lo.abs() };
        return [lo - d, hi + d];
    }
    [lo, hi]
}

/// Bounds of the y (or x, with `pick_x`) coordinates of all runs, padded by `pad` × range on
/// each side, guarded. `None` when there are no points.
pub fn bounds(runs: &[&[(f64, f64)]], pick_x: bool, pad: f64) -> Option<[f64; 2]> {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for run in runs {
        for &(x, y) in run.iter() {
            let v = if pick_x { x } else { y };
            if v.is_finite() {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
    }
    if lo > hi {
        return None;
    }
    let [lo, hi] = guard(lo, hi);
    let d = (hi - lo) * pad;
    Some(guard(lo - d, hi + d))
}

/// Round axis bounds and their labels (in data units) for plane bounds `b`:
///
/// - linear: multiples of a [`crate::numfmt::nice_step`]; with `three`, exactly two steps apart so the middle
///   label is round too;
/// - log10: whole decades; with `three`, an even number of decades (else two labels), so
///   every label is a power of ten.
///
/// The returned bounds always contain `b`.
pub fn ticks(b: [f64; 2], scale: Scale, three: bool) -> ([f64; 2], Vec<String>) {
    let [lo, hi] = guard(b[0], b[1]);
    match scale {
        Scale::Log10 => {
            let l = (lo + 1e-9).floor();
            let mut h = (hi - 1e-9).ceil();
            if h <= l {
                h = l + 1.0;
            }
            let n = (h - l).round() as i64;
            let labels = if three && n % 2 == 0 {
                vec![l, 0.5 * (l + h), h]
            } else {
                vec![l, h]
            };
            ([l, h], labels.into_iter().map(|v| tick(10f64.powf(v))).collect())
        }
        Scale::Linear => {
            // two labels: a finer step, so the bounds stay close to the data
            let parts = if three { 2.0 } else { 5.0 };
            let mut step = nice_step((hi - lo) / parts);
            loop {
                let l = (lo / step + 1e-9).floor() * step;
                let h = if three {
                    l + 2.0 * step
                } else {
                    (hi / step - 1e-9).ceil() * step
                };
                if h >= hi - 1e-9 * step || !step.is_finite() {
                    let clean = |v: f64| if v.abs() < 1e-9 * step { 0.0 } else { v };
                    let (l, h) = (clean(l), clean(h));
                    let labels = if three { vec![l, l + step, h] } else { vec![l, h] };
                    return ([l, h], labels.into_iter().map(|v| tick(clean(v))).collect());
                }
                step = nice_step(step * 1.0001);
            }
        }
    }
}

/// A band given as columns of points (each load's points share its x, from the lower to the
/// upper end) filled at the terminal's resolution: `cell` is the plane size of one cell
/// (x, y); the band is interpolated between neighbouring columns and sampled at half a cell
/// in both directions, so every cell it covers gets a mark (a band, not a checkerboard).
pub fn fill_band(points: &[(f64, f64)], xs: Scale, ys: Scale, cell: (f64, f64)) -> Vec<(f64, f64)> {
    // (x, lower, upper) per column, in the plane
    let mut cols: Vec<(f64, f64, f64)> = Vec::new();
    for r in segments(points, xs, ys) {
        for (u, v) in r {
            match cols.last_mut() {
                Some(c) if c.0 == u => {
                    c.1 = c.1.min(v);
                    c.2 = c.2.max(v);
                }
                _ => cols.push((u, v, v)),
            }
        }
    }
    let (dx, dy) = (0.5 / cell.0.max(1e-12), 0.5 / cell.1.max(1e-12));
    let mut out = Vec::new();
    let mut fill = |u: f64, lo: f64, hi: f64| {
        let n = ((hi - lo) / dy).ceil().clamp(0.0, 10_000.0) as usize;
        out.extend((0..=n).map(|k| (u, lo + (hi - lo) * k as f64 / n.max(1) as f64)));
    };
    for w in cols.windows(2) {
        let ((u0, l0, h0), (u1, l1, h1)) = (w[0], w[1]);
        let n = ((u1 - u0) / dx).ceil().clamp(1.0, 10_000.0) as usize;
        for k in 0..n {
            let t = k as f64 / n as f64;
            fill(u0 + (u1 - u0) * t, l0 + (l1 - l0) * t, h0 + (h1 - h0) * t);
        }
    }
    if let Some(&(u, l, h)) = cols.last() {
        fill(u, l, h);
    }
    out
}

/// A vertical line at plane x = `x` across plane bounds `y`, as a two-point run.
pub fn vertical(x: f64, y: [f64; 2]) -> Vec<(f64, f64)> {
    if x.is_finite() && y[0].is_finite() && y[1].is_finite() {
        vec![(x, y[0]), (x, y[1])]
    } else {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_scale_rejects_nonpositive_and_nonfinite() {
        assert_eq!(Scale::Log10.forward(100.0), Some(2.0));
        assert_eq!(Scale::Log10.forward(0.0), None);
        assert_eq!(Scale::Log10.forward(-1.0), None);
        assert_eq!(Scale::Log10.forward(f64::NAN), None);
        assert_eq!(Scale::Linear.forward(f64::INFINITY), None);
        assert_eq!(Scale::Linear.forward(-3.0), Some(-3.0));
        assert!((Scale::Log10.inverse(-3.0) - 1e-3).abs() < 1e-18);
    }

    #[test]
    fn segments_split_at_gaps() {
        let pts = [
            (1.0, 1.0),
            (2.0, f64::NAN),
            (3.0, 3.0),
            (4.0, 4.0),
            (5.0, f64::INFINITY),
            (6.0, 6.0),
        ];
        let s = segments(&pts, Scale::Linear, Scale::Linear);
        assert_eq!(
            s,
            vec![vec![(1.0, 1.0)], vec![(3.0, 3.0), (4.0, 4.0)], vec![(6.0, 6.0)]]
        );
        // log x drops x <= 0 and splits there
        let pts = [(0.1, 1.0), (0.0, 1.0), (10.0, 2.0), (100.0, 0.0)];
        let s = segments(&pts, Scale::Log10, Scale::Linear);
        assert_eq!(s, vec![vec![(-1.0, 1.0)], vec![(1.0, 2.0), (2.0, 0.0)]]);
        let s = segments(&pts, Scale::Log10, Scale::Log10);
        assert_eq!(s, vec![vec![(-1.0, 0.0)], vec![(1.0, 2f64.log10())]]);
        assert!(segments(&[], Scale::Linear, Scale::Linear).is_empty());
        assert!(segments(&[(f64::NAN, 1.0)], Scale::Linear, Scale::Linear).is_empty());
    }

    #[test]
    fn decimation_keeps_ends_and_extremes() {
        let run: Vec<(f64, f64)> = (0..10_000)
            .map(|i| (i as f64, if i == 5_003 { 100.0 } else { (i as f64 * 0.01).sin() }))
            .collect();
        let d = decimate(&run, 200);
        assert!(d.len() <= 202, "{}", d.len());
        assert_eq!(d[0], run[0]);
        assert_eq!(*d.last().unwrap(), run[9_999]);
        assert!(d.iter().any(|p| p.1 == 100.0), "the spike survives");
        assert!(d.windows(2).all(|w| w[1].0 > w[0].0), "x stays ordered");
        // short runs untouched
        assert_eq!(decimate(&run[..50], 200), run[..50].to_vec());
        assert_eq!(decimate(&run[..3], 0), run[..3].to_vec());
    }

    #[test]
    fn guards_and_bounds() {
        assert_eq!(guard(1.0, 1.0), [0.95, 1.05]);
        assert_eq!(guard(0.0, 0.0), [-0.5, 0.5]);
        assert_eq!(guard(f64::NAN, 1.0), [0.0, 1.0]);
        assert_eq!(guard(2.0, 1.0), [1.0, 2.0]);
        let a = [(0.0, 1.0), (1.0, 3.0)];
        let b = [(2.0, f64::NAN)];
        assert_eq!(bounds(&[&a, &b], false, 0.0), Some([1.0, 3.0]));
        assert_eq!(bounds(&[&a, &b], true, 0.5), Some([-1.0, 3.0]));
        assert_eq!(bounds(&[&b], false, 0.0), None);
        let one = [(1.0, 2.0)];
        let g = bounds(&[&one], false, 0.1).unwrap();
        assert!(g[0] < 2.0 && g[1] > 2.0);
    }

    #[test]
    fn a_band_covers_every_cell_between_its_columns() {
        // two loads 10 cells apart, the band 4 cells high: every cell of the rectangle marked
        let pts = [(1.0, 0.0), (1.0, 4.0), (11.0, 0.0), (11.0, 4.0)];
        let f = fill_band(&pts, Scale::Linear, Scale::Linear, (1.0, 1.0));
        for x in 1..11 {
            for y in 0..4 {
                let hit = f
                    .iter()
                    .any(|p| p.0 >= x as f64 && p.0 < x as f64 + 1.0 && p.1 >= y as f64 && p.1 < y as f64 + 1.0);
                assert!(hit, "cell ({x}, {y}) unmarked");
            }
        }
        assert!(f.iter().all(|p| p.1 >= 0.0 && p.1 <= 4.0 && p.0 >= 1.0 && p.0 <= 11.0));
        assert!(fill_band(&[], Scale::Linear, Scale::Linear, (1.0, 1.0)).is_empty());
    }

    #[test]
    fn vertical_marker() {
        assert_eq!(vertical(1.0, [0.0, 2.0]), vec![(1.0, 0.0), (1.0, 2.0)]);
        assert!(vertical(f64::NAN, [0.0, 2.0]).is_empty());
    }

    #[test]
    fn ticks_are_round() {
        let (b, l) = ticks([0.0, 0.87], Scale::Linear, true);
        assert_eq!(b, [0.0, 1.0]);
        assert_eq!(l, vec!["0", "0.5", "1"]);
        let (b, l) = ticks([-0.13, 0.61], Scale::Linear, true);
        assert!(b[0] <= -0.13 && b[1] >= 0.61, "{b:?}");
        assert_eq!(l, vec!["-1", "0", "1"]);
        let (b, l) = ticks([0.012, 0.0337], Scale::Linear, false);
        assert!(b[0] <= 0.012 && b[1] >= 0.0337, "{b:?} {l:?}");
        assert!(l.iter().all(|s| s.len() <= 5), "{l:?}");
        // log: whole decades, three labels only on an even count
        let (b, l) = ticks([-2.7, -0.2], Scale::Log10, true);
        assert_eq!(b, [-3.0, 0.0]);
        assert_eq!(l, vec!["0.001", "1"]);
        let (b, l) = ticks([-3.5, -0.2], Scale::Log10, true);
        assert_eq!(b, [-4.0, 0.0]);
        assert_eq!(l, vec!["1e-4", "0.01", "1"]);
        // degenerate input stays drawable
        let (b, _) = ticks([1.0, 1.0], Scale::Linear, true);
        assert!(b[1] > b[0]);
    }
}
