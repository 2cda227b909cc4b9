//! Unit tests of the plain data of engine results.

use super::*;

fn state(branch: Branch, a_r: f64) -> BranchState {
    BranchState {
        branch,
        stable: branch != Branch::Unstable,
        a_r,
        sigma_a: 0.3,
        gamma_coarse: 0.5,
        residual: 0.0,
        elastic_energy: 1e-4,
    }
}

fn window(lo: f64, hi: f64) -> Vec<BranchState> {
    vec![
        state(Branch::Loading, lo),
        state(Branch::Unstable, 0.5 * (lo + hi)),
        state(Branch::Unloading, hi),
    ]
}

#[test]
fn unloading_curve_and_the_window_edges() {
    let p = [1e-4, 2e-4, 4e-4, 8e-4, 1.6e-3, 3.2e-3];
    let one = |a| vec![state(Branch::Loading, a)];
    let b = vec![
        one(0.01),
        window(0.02, 0.40),
        window(0.03, 0.41),
        one(0.45),
        one(0.47),
        one(0.5),
    ];
    let (u, jump, pull) = unloading_curve(&p, &b);
    assert!(u[0].is_nan() && u[3].is_nan() && u[5].is_nan(), "{u:?}");
    assert_eq!((u[1], u[2]), (0.40, 0.41));
    // edges at the geometric midpoints of the loads on either side
    let jump = jump.unwrap();
    let pull = pull.unwrap();
    assert!((jump / (4e-4f64 * 8e-4).sqrt() - 1.0).abs() < 1e-12, "{jump}");
    assert!((pull / (1e-4f64 * 2e-4).sqrt() - 1.0).abs() < 1e-12, "{pull}");
    // a window running past the range has no edge there; a failed load is no edge
    let b2 = vec![
        window(0.02, 0.4),
        window(0.03, 0.41),
        vec![],
        one(0.45),
        one(0.5),
        one(0.5),
    ];
    let (u2, jump2, pull2) = unloading_curve(&p, &b2);
    assert_eq!((jump2, pull2), (None, None));
    assert_eq!(u2.iter().filter(|a| a.is_finite()).count(), 2);
    // no hysteresis, no load: nothing
    let (u3, j3, p3) = unloading_curve(&p, &vec![one(0.1); 6]);
    assert!(u3.iter().all(|a| a.is_nan()) && j3.is_none() && p3.is_none());
    assert_eq!(unloading_curve(&[], &[]), (vec![], None, None));
    let sd = SweepData {
        p: p.to_vec(),
        a_r: vec![0.01; 6],
        ..SweepData::default()
    }
    .with_branches(&b);
    assert!(sd.has_hysteresis() && sd.jump_in == Some(jump));
}

#[test]
fn point_data_copies_the_evaluation() {
    let mut scene = asperity::input::preset::Preset::resolve("system-1")
        .unwrap()
        .scene()
        .unwrap();
    scene = scene.without_adhesion();
    let ev = asperity::theory::engine::evaluate(&scene, &asperity::theory::engine::Options::default()).unwrap();
    let pd = PointData::from_evaluation(&ev);
    assert_eq!(pd.a_r, ev.stats.a_r);
    assert_eq!(pd.pr.len(), ev.stats.pr.sigma.len());
    assert_eq!(pd.pr[3], (ev.stats.pr.sigma[3], ev.stats.pr.density[3]));
    assert_eq!(pd.branch, "converged");
    // adhesionless: no wall
    assert_eq!(pd.wall, None);
}
