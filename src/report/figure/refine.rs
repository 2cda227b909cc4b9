//! Curves refined where they bend: a figure's theory curve starts on the figure file's x
//! values and gains points until the polyline it draws lies within [`CHORD_PX`] of the curve
//! at the default drawing size ([`DRAWING_PX`], the whole drawing taken as the plot, so the
//! true plot area is finer still), and window edges are located to one pixel in x.
//!
//! Each sample carries up to two branches (the loading branch and, inside a hysteresis window,
//! the unloading one) and the number of stable branches. Passes, until nothing is flagged or
//! [`MAX_POINTS`] is reached:
//!
//! - the chord error of the interval pairs around every interior point is estimated from
//!   three neighbours: the middle point's distance from the chord of the outer two, d, is
//!   4× the chord error of each half for a locally quadratic curve, so both halves are
//!   flagged where d/4 > [`CHORD_PX`] (in pixels, on the axes' own scales: log x, log y);
//! - an interval whose ends differ in the number of stable branches, or where a branch has a
//!   value at one end only, holds an edge: it is flagged until it is narrower than a pixel;
//! - flagged intervals wider than [`MIN_DX_PX`] get their midpoint (geometric on a log axis),
//!   all evaluated in parallel (the result does not depend on the thread count: the midpoints
//!   of a pass are fixed before any is evaluated).
//!
//! Where the ends of a pixel-narrow interval differ in the number of stable branches and the
//! loading branch's value jumps by more than [`JUMP_PX`], the branch ended there (the contact
//! jumps in, or snaps out): [`Refined::breaks`] lists those intervals so that the line is
//! drawn broken rather than as a vertical stroke.

use rayon::prelude::*;

/// The drawing the curves are refined for, in pixels (width, height): the default size of a
/// figure's SVG file.
pub const DRAWING_PX: (u32, u32) = (800, 560);
/// Largest distance between the drawn polyline and the curve, in pixels.
pub const CHORD_PX: f64 = 0.5;
/// Intervals narrower than this (pixels in x) are not split.
pub const MIN_DX_PX: f64 = 1.0;
/// A loading-branch step larger than this across an edge (pixels in y) is a jump.
pub const JUMP_PX: f64 = 3.0;
/// Most samples of one curve.
pub const MAX_POINTS: usize = 600;
/// Most refinement passes.
const MAX_PASSES: usize = 14;

/// One evaluation of the curve at x.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// x.
    pub x: f64,
    /// The loading branch's value (None: no value, with [`Sample::note`]).
    pub y: Option<f64>,
    /// The unloading branch's value where it is distinct (inside a hysteresis window).
    pub y_unloading: Option<f64>,
    /// Number of stable branches (1 outside a hysteresis window).
    pub stable: usize,
    /// Why there is no value.
    pub note: Option<String>,
}

/// The axes the curve is drawn on: the scales and the plane span in pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axes {
    /// Log x.
    pub x_log: bool,
    /// Log y.
    pub y_log: bool,
    /// Data range of x.
    pub x_range: (f64, f64),
    /// Data range of y.
    pub y_range: (f64, f64),
    /// Pixels across x and y.
    pub px: (f64, f64),
}

impl Axes {
    fn fx(&self, x: f64) -> f64 {
        let t = |v: f64| if self.x_log { v.ln() } else { v };
        let (a, b) = (t(self.x_range.0), t(self.x_range.1));
        (t(x) - a) / (b - a) * self.px.0
    }

    /// y in pixels (None: not drawable on this axis).
    fn fy(&self, y: Option<f64>) -> Option<f64> {
        let y = y.filter(|v| v.is_finite() && (!self.y_log || *v > 0.0))?;
        let t = |v: f64| if self.y_log { v.ln() } else { v };
        let (a, b) = (t(self.y_range.0), t(self.y_range.1));
        Some((t(y) - a) / (b - a) * self.px.1)
    }

    fn mid(&self, a: f64, b: f64) -> f64 {
        if self.x_log {
            (a * b).sqrt()
        } else {
            0.5 * (a + b)
        }
    }

    /// Whether `axes` can measure pixels (finite, non-degenerate ranges).
    fn usable(&self) -> bool {
        let ok = |r: (f64, f64), log: bool| r.0.is_finite() && r.1.is_finite() && r.1 > r.0 && (!log || r.0 > 0.0);
        ok(self.x_range, self.x_log) && ok(self.y_range, self.y_log)
    }
}

/// A refined curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Refined {
    /// The samples in ascending x.
    pub samples: Vec<Sample>,
    /// Indices i where the loading branch jumps between samples i and i + 1 (an edge).
    pub breaks: Vec<usize>,
}

/// The branches' values of a sample, in pixels.
fn values(axes: &Axes, s: &Sample) -> [Option<f64>; 2] {
    [axes.fy(s.y), axes.fy(s.y_unloading)]
}

/// Which intervals (i, i + 1) to split.
fn flagged(axes: &Axes, s: &[Sample]) -> Vec<usize> {
    let n = s.len();
    let mut flag = vec![false; n.saturating_sub(1)];
    let px: Vec<[Option<f64>; 2]> = s.iter().map(|v| values(axes, v)).collect();
    let xs: Vec<f64> = s.iter().map(|v| axes.fx(v.x)).collect();
    for i in 0..n.saturating_sub(1) {
        let edge = s[i].stable != s[i + 1].stable || (0..2).any(|k| px[i][k].is_some() != px[i + 1][k].is_some());
        // a failed evaluation is not an edge to chase
        let failed = s[i].y.is_none() || s[i + 1].y.is_none();
        if edge && !failed {
            flag[i] = true;
        }
    }
    for i in 1..n.saturating_sub(1) {
        let t = (xs[i] - xs[i - 1]) / (xs[i + 1] - xs[i - 1]);
        let bends = px[i - 1]
            .iter()
            .zip(&px[i])
            .zip(&px[i + 1])
            .any(|((a, m), b)| match (a, m, b) {
                (Some(a), Some(m), Some(b)) => (m - (a + t * (b - a))).abs() / 4.0 > CHORD_PX,
                _ => false,
            });
        if bends {
            flag[i - 1] = true;
            flag[i] = true;
        }
    }
    (0..flag.len())
        .filter(|&i| flag[i] && xs[i + 1] - xs[i] > MIN_DX_PX)
        .collect()
}

/// Refines the curve `eval` from the samples at `xs` (ascending) on `axes`.
pub fn refine(xs: &[f64], axes: &Axes, eval: &(dyn Fn(f64) -> Sample + Sync)) -> Refined {
    refine_from(xs.par_iter().map(|&x| eval(x)).collect(), axes, eval)
}

/// [`refine`] from samples already evaluated (ascending x).
pub fn refine_from(mut samples: Vec<Sample>, axes: &Axes, eval: &(dyn Fn(f64) -> Sample + Sync)) -> Refined {
    if axes.usable() {
        for _ in 0..MAX_PASSES {
            let todo = flagged(axes, &samples);
            if todo.is_empty() || samples.len() + todo.len() > MAX_POINTS {
                break;
            }
            let mids: Vec<f64> = todo.iter().map(|&i| axes.mid(samples[i].x, samples[i + 1].x)).collect();
            let new: Vec<Sample> = mids.par_iter().map(|&x| eval(x)).collect();
            samples.extend(new);
            samples.sort_by(|a, b| a.x.total_cmp(&b.x));
        }
    }
    let breaks = (0..samples.len().saturating_sub(1))
        .filter(|&i| {
            let (a, b) = (&samples[i], &samples[i + 1]);
            let step = match (axes.fy(a.y), axes.fy(b.y)) {
                (Some(u), Some(v)) => (u - v).abs(),
                _ => 0.0,
            };
            a.stable != b.stable && step > JUMP_PX
        })
        .collect();
    Refined { samples, breaks }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axes(y_range: (f64, f64)) -> Axes {
        Axes {
            x_log: true,
            y_log: false,
            x_range: (0.01, 10.0),
            y_range,
            px: (800.0, 560.0),
        }
    }

    fn plain(f: impl Fn(f64) -> f64 + Sync) -> impl Fn(f64) -> Sample + Sync {
        move |x| Sample {
            x,
            y: Some(f(x)),
            y_unloading: None,
            stable: 1,
            note: None,
        }
    }

    /// The largest distance (pixels) between the polyline and `f`, checked at 64 points inside
    /// every interval: the closed form is the oracle.
    fn worst_chord(r: &Refined, a: &Axes, f: impl Fn(f64) -> f64) -> f64 {
        let mut worst: f64 = 0.0;
        for w in r.samples.windows(2) {
            let (x0, x1) = (w[0].x, w[1].x);
            for j in 1..64 {
                let x = (x0.ln() + (x1.ln() - x0.ln()) * j as f64 / 64.0).exp();
                let t = (a.fx(x) - a.fx(x0)) / (a.fx(x1) - a.fx(x0));
                let line = a.fy(w[0].y).unwrap() * (1.0 - t) + a.fy(w[1].y).unwrap() * t;
                worst = worst.max((line - a.fy(Some(f(x))).unwrap()).abs());
            }
        }
        worst
    }

    fn grid(n: usize) -> Vec<f64> {
        (0..n).map(|i| 0.01 * 1000f64.powf(i as f64 / (n - 1) as f64)).collect()
    }

    #[test]
    fn a_steep_step_is_drawn_within_a_pixel() {
        // a_r falling from 0.75 to 0.05 over a few per cent in t·q_r, as model 3's at p* = 0.005
        let f = |x: f64| 0.05 + 0.35 * (1.0 - ((x / 0.16).ln() / 0.03).tanh());
        let a = axes((0.0, 0.8));
        let coarse = refine(&grid(13), &Axes { px: (1.0, 1.0), ..a }, &plain(f));
        assert_eq!(coarse.samples.len(), 13, "below a pixel nothing is refined");
        let r = refine(&grid(13), &a, &plain(f));
        let worst = worst_chord(&r, &a, f);
        assert!(
            worst <= 2.0 * CHORD_PX,
            "chord error {worst} px with {} points",
            r.samples.len()
        );
        assert!(r.samples.len() < 200, "{}", r.samples.len());
        assert!(r.breaks.is_empty(), "a continuous curve is not broken");
    }

    #[test]
    fn a_smooth_curve_gains_few_points() {
        let f = |x: f64| 0.02 + 0.01 * x.ln();
        let a = axes((-0.1, 0.1));
        let r = refine(&grid(13), &a, &plain(f));
        assert!(
            r.samples.len() <= 13,
            "a straight line on these axes needs no point: {}",
            r.samples.len()
        );
        let f = |x: f64| (x / 10.0).sqrt();
        let r = refine(&grid(13), &axes((0.0, 1.0)), &plain(f));
        assert!(worst_chord(&r, &axes((0.0, 1.0)), f) <= 2.0 * CHORD_PX);
    }

    #[test]
    fn a_window_is_located_to_a_pixel_and_its_jump_breaks_the_line() {
        // two stable branches for x in (0.0977, 0.1015): loading 0.002, unloading 0.41
        let (jump_in, pull_off) = (0.0977, 0.1015);
        let eval = |x: f64| {
            let inside = x > jump_in && x < pull_off;
            Sample {
                x,
                y: Some(if x <= jump_in { 0.6 } else { 0.002 }),
                y_unloading: inside.then_some(0.41),
                stable: if inside { 2 } else { 1 },
                note: None,
            }
        };
        let a = axes((0.0, 0.8));
        let r = refine(&grid(13), &a, &eval);
        assert_eq!(r.breaks.len(), 1, "{:?}", r.breaks);
        let i = r.breaks[0];
        let (x0, x1) = (r.samples[i].x, r.samples[i + 1].x);
        assert!(x0 <= jump_in && x1 > jump_in, "{x0} {x1}");
        assert!(a.fx(x1) - a.fx(x0) <= MIN_DX_PX, "the edge to a pixel");
        let unloading: Vec<f64> = r
            .samples
            .iter()
            .filter(|s| s.y_unloading.is_some())
            .map(|s| s.x)
            .collect();
        assert!(unloading.len() >= 2, "the window holds both branches: {unloading:?}");
        let last = unloading.last().unwrap();
        let next = r.samples.iter().find(|s| s.x > *last).unwrap().x;
        assert!(*last < pull_off && next >= pull_off && a.fx(next) - a.fx(*last) <= MIN_DX_PX);
    }

    #[test]
    fn failed_points_are_left_alone() {
        let eval = |x: f64| Sample {
            x,
            y: (x < 1.0).then_some(0.3),
            y_unloading: None,
            stable: 1,
            note: (x >= 1.0).then(|| "did not converge".into()),
        };
        let r = refine(&grid(13), &axes((0.0, 1.0)), &eval);
        assert_eq!(r.samples.len(), 13);
    }
}
