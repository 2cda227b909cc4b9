//! Operations on the grid values of the march (`propagator`): the grid x_j = j·h from the
//! wall, values vanishing at the wall and beyond the last node.
//!
//! - `shift`: the content moved by δ (the wall moved from −σ_a to −(σ_a + δ)),
//!   p_new(x) = p(x − δ), by [`SHIFT_POINTS`]-point Lagrange interpolation with the odd
//!   continuation through the wall (error O(h⁸ ∂⁸Pr));
//! - `refine`: the spacing halved (the same interpolation at the midpoints);
//! - `reoffset`: the grid's lower end moved with the distribution while the wall runs ahead.

// index loops mirror the formulas (nodes j) in this numerical module
#![allow(clippy::needless_range_loop)]

/// Points of the shift's Lagrange interpolation: the error per shift is O(h⁸ ∂⁸Pr), ~1e-9 of
/// Pr at 10 points per width (4 points gave ~1e-5 per shift, ~1e-3 after a march).
pub(super) const SHIFT_POINTS: usize = 8;

/// Shifts the grid content by δ (the wall moved from −σ_a to −(σ_a + δ)): p_new(x) = p(x − δ).
pub(super) fn shift(p: &mut Vec<f64>, h: f64, delta: f64) {
    if delta == 0.0 {
        return;
    }
    let n = p.len() - 1;
    // grow the grid so nothing falls off the far end
    let extra = if delta > 0.0 {
        (delta / h).ceil() as usize + 2
    } else {
        0
    };
    let old = p.clone();
    let new_n = n + extra;
    p.clear();
    p.resize(new_n + 1, 0.0);
    // every node shifts by the same fraction of a cell: one set of Lagrange weights
    let shift_cells = delta / h;
    let frac = (-shift_cells) - (-shift_cells).floor();
    let base = (-shift_cells).floor() as isize;
    let w = lagrange_weights(frac);
    for (j, pj) in p.iter_mut().enumerate().take(new_n).skip(1) {
        let t = j as f64 - shift_cells;
        if t <= 0.0 {
            continue; // below the old wall: no mass
        }
        *pj = interpolate_at(&old, &w, j as isize + base);
    }
    p[0] = 0.0;
    p[new_n] = 0.0;
}

/// The [`SHIFT_POINTS`]-point Lagrange weights for the point `frac` of a cell past node i
/// (nodes i − 3 … i + 4).
fn lagrange_weights(frac: f64) -> [f64; SHIFT_POINTS] {
    let half = SHIFT_POINTS as isize / 2;
    let mut w = [0.0f64; SHIFT_POINTS];
    for (l, wl) in w.iter_mut().enumerate() {
        let ol = l as f64 - (half - 1) as f64;
        let mut prod = 1.0;
        for jj in 0..SHIFT_POINTS {
            if jj != l {
                let oj = jj as f64 - (half - 1) as f64;
                prod *= (frac - oj) / (ol - oj);
            }
        }
        *wl = prod;
    }
    w
}

/// The interpolant with weights `w` ([`lagrange_weights`]) past node i of grid values that
/// vanish at the wall (node 0, odd continuation below it) and beyond the last node.
fn interpolate_at(old: &[f64], w: &[f64; SHIFT_POINTS], i: isize) -> f64 {
    let n = old.len() - 1;
    let val = |i: isize| -> f64 {
        if i < 0 {
            old.get((-i) as usize).map_or(0.0, |x| -x)
        } else if (i as usize) <= n {
            old[i as usize]
        } else {
            0.0
        }
    };
    let half = SHIFT_POINTS as isize / 2;
    w.iter()
        .enumerate()
        .map(|(l, wl)| wl * val(i + l as isize - (half - 1)))
        .sum()
}

/// Halves the spacing of a grid that starts at the wall: the new midpoints by the
/// [`SHIFT_POINTS`]-point Lagrange interpolation, odd continuation through the wall.
pub(super) fn refine(p: &mut Vec<f64>) {
    let n = p.len() - 1;
    let old = p.clone();
    let w = lagrange_weights(0.5);
    p.clear();
    p.resize(2 * n + 1, 0.0);
    for j in 0..n {
        p[2 * j] = old[j];
        p[2 * j + 1] = interpolate_at(&old, &w, j as isize);
    }
    p[0] = 0.0;
    p[2 * n] = 0.0;
}

/// Moves the grid's lower end x₀ = m·h: up to `margin` below the lowest node whose density
/// exceeds 1e-16 of the peak (in steps of at least 8 nodes, dropping negligible values), or
/// down (zeros prepended) when the distribution comes nearer; never below the wall.
pub(super) fn reoffset(p: &mut Vec<f64>, m: &mut usize, h: f64, margin: f64) {
    let peak = p.iter().fold(0.0f64, |a, &b| a.max(b.abs()));
    if peak.is_nan() || peak <= 0.0 {
        return;
    }
    let lo = p.iter().position(|&x| x.abs() > 1e-16 * peak).unwrap_or(0);
    let x_lo = (*m + lo) as f64 * h;
    let want = ((x_lo - margin) / h).floor().max(0.0) as usize;
    if want >= *m + 8 {
        p.drain(0..want - *m);
        p[0] = 0.0;
        *m = want;
    } else if want < *m {
        let add = *m - want;
        p.splice(0..0, std::iter::repeat_n(0.0, add));
        *m = want;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shift_is_exact_for_cubics_away_from_the_wall() {
        let h = 0.1;
        let mut p: Vec<f64> = (0..=40).map(|j| (j as f64 * h).powi(3) - (j as f64 * h)).collect();
        p[0] = 0.0;
        let last = p.len() - 1;
        p[last] = 0.0;
        let orig = p.clone();
        shift(&mut p, h, 0.037);
        for j in 3..35 {
            let x = j as f64 * h - 0.037;
            let want = x.powi(3) - x;
            assert!((p[j] - want).abs() < 1e-12, "{j}: {} vs {want}", p[j]);
        }
        let _ = orig;
    }

    #[test]
    fn refine_is_exact_for_odd_polynomials() {
        // x³ − x is odd through the wall: the 8-point interpolation with the odd continuation
        // reproduces it at the new midpoints (away from the far end, where the values stop)
        let h = 0.1;
        let f = |x: f64| x.powi(3) - 0.5 * x.powi(5);
        let mut p: Vec<f64> = (0..=40).map(|j| f(j as f64 * h)).collect();
        let last = p.len() - 1;
        p[last] = 0.0;
        refine(&mut p);
        assert_eq!(p.len(), 81);
        for (j, pj) in p.iter().enumerate().take(60) {
            let want = f(j as f64 * h / 2.0);
            assert!((pj - want).abs() < 1e-12, "{j}: {pj} vs {want}");
        }
    }
}
