//! Polonsky–Keer's cold start: a contact pressure guessed from the heights alone.
//!
//! From the uniform pressure p₀ on every node the first ≈ 10 iterations of
//! [`super::pk::relax`] only shrink the contact set S from all nodes to a few times its final
//! size, each at the cost of two convolutions and of node loops over a set as large as the
//! grid. The guess starts S there: the k = κ·a_r⁰·N highest nodes, a_r⁰ = √(8/π) p₀/h'_rms
//! the adhesionless contact area of Persson's theory at small loads (physics.md §2), with a
//! pressure ∝ √(h − d) above the height d of the (k + 1)-th highest node (the Hertzian
//! profile of a summit pressed by h − d), scaled to the mean p₀. κ = 3 leaves room for the
//! theory's underestimate of a_r at these loads (≈ 0.75× the GFMD a_r on system I at
//! p* = 0.01) and for the nodes that the relaxation drops. Any start in {p ≥ 0, ⟨p⟩ = p₀}
//! leads to the same minimum (the complementary energy is convex): the guess changes the
//! path, not the answer (BENCHMARKS.md: 108 → 95 iterations on system I at 1024², p* = 0.01,
//! the same contact set to the node).

/// Head room of the guessed contact over the theory's a_r (κ above).
const HEAD_ROOM: f64 = 3.0;

/// The cold start of [`super::pk::relax`] on heights `h` (rows of `nx` nodes, in Δa) at the
/// mean pressure `p0` (E*): zero off the k highest nodes, √(h − d) on them, mean `p0`; the
/// uniform `p0` where that set would hold every node (large loads) or cannot be formed (a
/// flat map, p₀ ≤ 0).
pub(crate) fn guess(h: &[f64], nx: usize, p0: f64) -> Vec<f64> {
    let n = h.len();
    let uniform = vec![p0; n];
    let grad = rms_gradient(h, nx);
    let fraction = HEAD_ROOM * (8.0 / std::f64::consts::PI).sqrt() * p0 / grad;
    if !(fraction > 0.0 && fraction < 1.0) {
        return uniform;
    }
    let k = ((fraction * n as f64) as usize).max(1);
    let mut sorted = h.to_vec();
    let d = *sorted.select_nth_unstable_by(n - k - 1, |a, b| a.total_cmp(b)).1;
    let mut p: Vec<f64> = h.iter().map(|&x| if x > d { (x - d).sqrt() } else { 0.0 }).collect();
    let sum: f64 = p.iter().sum();
    if !(sum > 0.0 && sum.is_finite()) {
        return uniform;
    }
    let scale = p0 * n as f64 / sum;
    p.iter_mut().for_each(|x| *x *= scale);
    p
}

/// The rms gradient of heights on rows of `nx` nodes (spacing 1), by forward differences on
/// the periodic grid.
fn rms_gradient(h: &[f64], nx: usize) -> f64 {
    let n = h.len();
    let ny = n / nx;
    let mut s = 0.0;
    for y in 0..ny {
        let row = &h[y * nx..(y + 1) * nx];
        let next = &h[(y + 1) % ny * nx..((y + 1) % ny + 1) * nx];
        for x in 0..nx {
            let (dx, dy) = (row[(x + 1) % nx] - row[x], next[x] - row[x]);
            s += dx * dx + dy * dy;
        }
    }
    (s / n as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gfmd::pk;
    use crate::gfmd::relax::stiffness_at;
    use crate::numerics::fft2::RealFft2;
    use crate::surface::heightmap;
    use crate::surface::spectrum::SelfAffine;
    use crate::tolerances::PK_COLD_START_W;
    use std::sync::atomic::AtomicBool;

    /// From the guess and from the uniform p₀ Polonsky–Keer ends on the same contact set, node
    /// for node, and the same surface to within the solver's gap tolerance, in no more
    /// iterations, at a small and a moderate load on a self-affine 128² map.
    #[test]
    fn the_cold_start_ends_where_the_uniform_start_ends() {
        let nx = 128;
        let spec = SelfAffine {
            system_size: nx as f64,
            lambda_r: 64.0,
            lambda_s: 4.0,
            hurst: 0.8,
            c0: 1.0,
        };
        let h = heightmap::generate(&spec, nx, 3).unwrap().heights;
        let n = h.len();
        let mut plan = RealFft2::new(nx, nx);
        let nh = plan.nh();
        let phi: Vec<f64> = (0..nh * nx)
            .map(|k| stiffness_at(k % nh, k / nh, (nx, nx, 1.0), f64::INFINITY))
            .collect();
        let mean = h.iter().sum::<f64>() / n as f64;
        let h_rms = (h.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64).sqrt();
        let tol = 1e-9 * h_rms;
        for p_star in [1e-3, 0.02] {
            let p0 = p_star * rms_gradient(&h, nx);
            let mut run = |p: Vec<f64>| {
                let no = AtomicBool::new(false);
                pk::relax(&mut plan, &phi, &h, p, p0, tol, 10_000, &mut |_, _, _| {}, &no).unwrap()
            };
            let (w_cold, it_cold) = run(vec![0.0; n]);
            let (w_flat, it_flat) = run(vec![p0; n]);
            let on = |w: &[f64]| -> Vec<bool> { w.iter().zip(&h).map(|(w, h)| w == h).collect() };
            let contact = on(&w_flat).iter().filter(|&&c| c).count();
            assert!(contact > 10 && contact < n / 5, "p* {p_star}: {contact} nodes");
            assert_eq!(on(&w_cold), on(&w_flat), "p* {p_star}: the contact sets");
            let dw = w_cold
                .iter()
                .zip(&w_flat)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(
                dw <= PK_COLD_START_W * tol,
                "p* {p_star}: |Δw| = {:.2} tolerances",
                dw / tol
            );
            assert!(
                it_cold <= it_flat,
                "p* {p_star}: {it_cold} against {it_flat} iterations"
            );
        }
    }

    /// The guess carries the mean pressure on the highest nodes only, ordered as the heights,
    /// and falls back to the uniform pressure at large loads and on a flat map.
    #[test]
    fn the_guess_loads_the_highest_nodes_with_the_mean_pressure() {
        let nx = 64;
        let h: Vec<f64> = (0..nx * nx)
            .map(|i| ((i % nx) as f64 * 0.3).sin() * 2.0 + ((i / nx) as f64 * 0.7).cos())
            .collect();
        // rms gradient ≈ 0.6 here: a_r⁰ ≈ 0.01, the guess ≈ 3 %
        let p0 = 0.01;
        let p = guess(&h, nx, p0);
        let on: Vec<usize> = (0..h.len()).filter(|&i| p[i] > 0.0).collect();
        let mean = p.iter().sum::<f64>() / h.len() as f64;
        assert!((mean / p0 - 1.0).abs() < 1e-12, "mean {mean}");
        assert!(on.len() > 20 && on.len() < h.len() / 10, "{} nodes", on.len());
        let lowest_on = on.iter().map(|&i| h[i]).fold(f64::INFINITY, f64::min);
        assert!((0..h.len()).all(|i| p[i] > 0.0 || h[i] <= lowest_on));
        for (&i, &j) in on.iter().zip(&on[1..]) {
            assert_eq!(h[i] < h[j], p[i] < p[j]);
        }
        assert!(guess(&h, nx, 1.0).iter().all(|&x| x == 1.0));
        assert!(guess(&vec![0.5; 256], 16, p0).iter().all(|&x| x == p0));
    }
}
