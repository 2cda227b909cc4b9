//! The analytic self-affine C(q) written as a table, for the tests that check the theory on a
//! tabulated spectrum against the analytic one (`tests/surfaces.rs` and
//! `cli/tests/cli_surface.rs` include this file).

use asperity::surface::spectrum::SelfAffine;

/// The library's PSD CSV of `sa`'s C(q) at q_L, q_r, q_s and `points` log-spaced steps from
/// q_L to q_s (q_r inserted where it falls, near-equal wave numbers merged).
pub fn ideal_csv(sa: &SelfAffine, points: usize) -> String {
    let mut q: Vec<f64> = (0..=points)
        .map(|k| sa.q_l() * (sa.q_s() / sa.q_l()).powf(k as f64 / points as f64))
        .collect();
    q.push(sa.q_r());
    q.sort_by(f64::total_cmp);
    q.dedup_by(|a, b| (*a / *b - 1.0).abs() < 1e-9);
    q[0] = sa.q_l();
    *q.last_mut().unwrap() = sa.q_s();
    let c: Vec<f64> = q.iter().map(|&x| sa.psd(x)).collect();
    asperity::surface::tabulated::to_csv(&q, &c)
}
