//! The net-pressure curve p*(p_rep) of a DMT route: its folds (pull-off, jump-in), the
//! hysteresis window between them, and the branches at given loads (physics.md §6.3).

use super::{BranchPoint, BranchState, Route, RouteResult};
use crate::error::{Error, Result, Solver};

/// One node of the curve (p_rep ascending = ū descending).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NetPoint {
    /// The repulsive load the contact carries, p_rep*.
    pub contact_load: f64,
    /// The attraction p_att*.
    pub attraction: f64,
    /// The external load p* = p_rep* − p_att*.
    pub pressure: f64,
    /// ū/h_rms = ū₀(p_rep).
    pub gap: f64,
    /// a_r = a₀(p_rep).
    pub a_r: f64,
}

/// The window of loads on which the loading (far) and the unloading (contact) branch coexist.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hysteresis {
    /// The unloading branch's fold: below it the contact jumps off (the pull-off where < 0).
    pub lower: f64,
    /// The loading branch's fold, the jump-in: above it the far state snaps into contact.
    pub upper: f64,
    /// The far branch's state at the jump-in.
    pub at_jump_in: BranchState,
}

/// A fold of the curve refined by the parabola through the node and its neighbours: the
/// extreme p* and the fractional node index where it lies.
fn fold(c: &[NetPoint], k: usize) -> (f64, f64) {
    if k == 0 || k + 1 >= c.len() {
        return (c[k].pressure, k as f64);
    }
    let (a, b, d) = (c[k - 1].pressure, c[k].pressure, c[k + 1].pressure);
    let curv = a - 2.0 * b + d;
    if curv == 0.0 {
        return (b, k as f64);
    }
    let t = (0.5 * (a - d) / curv).clamp(-1.0, 1.0);
    (b + 0.5 * t * (d - a) + 0.5 * t * t * curv, k as f64 + t)
}

/// The state at a fractional node index (ln p_rep and ū linear, ln a_r linear).
fn state_at(c: &[NetPoint], x: f64) -> BranchState {
    let x = x.clamp(0.0, (c.len() - 1) as f64);
    let i = (x.floor() as usize).min(c.len().saturating_sub(2));
    let f = x - i as f64;
    let (u, v) = (&c[i], &c[(i + 1).min(c.len() - 1)]);
    let lin = |a: f64, b: f64| a + f * (b - a);
    let ln_lin = |a: f64, b: f64| {
        if a > 0.0 && b > 0.0 {
            lin(a.ln(), b.ln()).exp()
        } else {
            lin(a, b)
        }
    };
    BranchState {
        contact_load: ln_lin(u.contact_load, v.contact_load),
        a_r: ln_lin(u.a_r, v.a_r),
        gap: lin(u.gap, v.gap),
    }
}

/// The state with external load `p` on the monotone stretch `lo..=hi` of nodes (p rising
/// with the index); the end node's state outside it.
fn on_stretch(c: &[NetPoint], lo: usize, hi: usize, p: f64) -> BranchState {
    if p <= c[lo].pressure {
        return state_at(c, lo as f64);
    }
    if p >= c[hi].pressure {
        return state_at(c, hi as f64);
    }
    let i = lo + c[lo..=hi].partition_point(|n| n.pressure <= p) - 1;
    let (a, b) = (c[i].pressure, c[(i + 1).min(hi)].pressure);
    let f = if b > a { (p - a) / (b - a) } else { 0.0 };
    state_at(c, i as f64 + f)
}

/// The folds, the pull-off and the branches at `loads` of a tabulated curve.
pub(super) fn assemble(route: Route, c: Vec<NetPoint>, loads: &[f64]) -> Result<RouteResult> {
    let n = c.len();
    if n < 3
        || c.iter()
            .any(|p| !(p.pressure.is_finite() && p.gap.is_finite() && p.a_r.is_finite()))
    {
        return Err(Error::NotConverged {
            solver: Solver::Theory,
            reason: format!("{} route: the net-pressure table is not finite", route.name()),
        });
    }
    // the contact branch: from full contact down while p falls
    let mut k_min = n - 1;
    while k_min > 0 && c[k_min - 1].pressure < c[k_min].pressure {
        k_min -= 1;
    }
    if k_min == 0 && c[0].pressure < 0.0 {
        return Err(Error::NotConverged {
            solver: Solver::Theory,
            reason: format!(
                "{} route: the net pressure still falls at the table's far end (p_rep* = {:e}); lower p_lo",
                route.name(),
                c[0].contact_load
            ),
        });
    }
    // the far branch (only where the far end pushes, p → 0⁺ as ū → ∞): up while p rises
    let mut k_max = 0;
    while k_max + 1 < n && c[k_max + 1].pressure > c[k_max].pressure {
        k_max += 1;
    }
    let folded = k_min > 0;
    let window = folded && c[0].pressure > 0.0 && k_max < k_min;
    let (p_min, x_min) = if folded { fold(&c, k_min) } else { (c[0].pressure, 0.0) };
    let hysteresis = window.then(|| {
        let (p_max, x_max) = fold(&c, k_max);
        Hysteresis {
            lower: p_min,
            upper: p_max,
            at_jump_in: state_at(&c, x_max),
        }
    });
    let pull_off = p_min.min(0.0);
    let at_pull_off = (folded && p_min < 0.0).then(|| state_at(&c, x_min));
    let branch = loads
        .iter()
        .map(|&p| {
            let contact = (p >= p_min || (!folded && p > 0.0)).then(|| on_stretch(&c, k_min, n - 1, p));
            let far = match hysteresis {
                Some(h) if p > 0.0 && p <= h.upper => Some(on_stretch(&c, 0, k_max, p)),
                _ => None,
            };
            BranchPoint {
                pressure: p,
                unloading: contact.or(far),
                loading: if p <= 0.0 { None } else { far.or(contact) },
            }
        })
        .collect();
    Ok(RouteResult {
        route,
        pull_off,
        at_pull_off,
        hysteresis,
        branch,
        curve: c,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A curve p(x) on nodes x = 0..n with a_r = x + 1, ū = n − x.
    fn curve(p: impl Fn(f64) -> f64, n: usize) -> Vec<NetPoint> {
        (0..n)
            .map(|i| {
                let x = i as f64;
                NetPoint {
                    contact_load: (x + 1.0) * 1e-3,
                    attraction: 0.0,
                    pressure: p(x),
                    gap: n as f64 - x,
                    a_r: (x + 1.0) * 1e-3,
                }
            })
            .collect()
    }

    #[test]
    fn a_cubic_curve_has_its_folds_at_the_extrema_and_branches_on_either_side() {
        // y = (x − 9)/10 ∈ [−0.9, 2]: p = y³ − y + 0.2 rises from 0.37 at the far end to its
        // maximum at y = −1/√3, falls to its minimum at y = 1/√3, then rises
        let f = |x: f64| {
            let y = (x - 9.0) / 10.0;
            y * y * y - y + 0.2
        };
        let r = assemble(Route::BearingArea, curve(f, 30), &[0.3, 0.1, -0.1, -0.5, 1.0]).unwrap();
        let y0 = 1.0 / 3f64.sqrt();
        let (lo, hi) = (y0.powi(3) - y0 + 0.2, -y0.powi(3) + y0 + 0.2);
        let h = r.hysteresis.unwrap();
        assert!((h.lower - lo).abs() < 1e-3, "{} vs {lo}", h.lower);
        assert!((h.upper - hi).abs() < 1e-3, "{} vs {hi}", h.upper);
        assert!((r.pull_off - h.lower).abs() < 1e-15 && r.pull_off < 0.0);
        let s = r.at_pull_off.unwrap();
        assert!((s.gap - (30.0 - 9.0 - 10.0 * y0)).abs() < 0.2, "{s:?}");
        let b = r.branch[0];
        assert!(b.loading.unwrap().a_r < b.unloading.unwrap().a_r, "{b:?}");
        // in tension: only the unloading branch, and nothing below the pull-off
        assert!(r.branch[2].loading.is_none() && r.branch[2].unloading.is_some());
        assert!(r.branch[3].unloading.is_none());
        // above the window both are the contact branch
        assert_eq!(r.branch[4].loading, r.branch[4].unloading);
    }

    #[test]
    fn a_monotone_curve_has_no_pull_off_and_a_far_end_in_tension_is_an_error() {
        let r = assemble(
            Route::GapDistribution,
            curve(|x| 1e-3 * (x + 1.0), 20),
            &[0.005, -0.001],
        )
        .unwrap();
        assert_eq!(r.pull_off, 0.0);
        assert!(r.hysteresis.is_none() && r.at_pull_off.is_none());
        assert_eq!(r.branch[0].loading, r.branch[0].unloading);
        assert!(r.branch[1].unloading.is_none());
        assert!(assemble(Route::BearingArea, curve(|x| x - 3.0, 20), &[]).is_err());
        assert!(assemble(Route::BearingArea, curve(|_| f64::NAN, 20), &[]).is_err());
    }
}
