//! The pinned unloading branch (docs/physics.md §6.6, `theory::unloading`): the adhesionless
//! limit retraces loading, the fold against the closed-form minimum of a linear table, input
//! validation, and the branch against GFMD's stored unloading rows on system II's slabs.

use asperity::fit::reference_set::reference_set;
use asperity::fit::set_gauge::cases_of;
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::theory::cycle::PathBranch;
use asperity::theory::engine::{evaluate, Options};
use asperity::theory::gap::DryGap;
use asperity::theory::unloading::{from_parts, pinned_unloading, PINNED_EXPONENT};
use asperity::tolerances::*;

/// GFMD's turning load in the reference set.
const P_MAX: f64 = 1e-2;

fn system2(t: f64, gamma_factor: f64) -> Scene {
    let s = Preset::resolve("system-2").unwrap().scene().unwrap();
    let g = s.surface_energy_j_m2() * gamma_factor;
    s.with_thickness_qr(t).unwrap().with_surface_energy_j_m2(g).unwrap()
}

#[test]
fn without_adhesion_unloading_retraces_loading() {
    let opts = Options::default();
    let scene = system2(0.3, 0.0);
    let b = pinned_unloading(&scene, P_MAX, PINNED_EXPONENT, &opts).unwrap();
    assert_eq!(b.pull_off, 0.0);
    for p in [1e-4, 1e-3, 5e-3] {
        let dry = evaluate(&scene.clone().with_pressure(p).unwrap(), &opts)
            .unwrap()
            .stats
            .a_r;
        let a = b.a_r_at(p).unwrap();
        assert!(
            (a / dry - 1.0).abs() < UNLOADING_RETRACE_REL,
            "p* {p}: {a} against {dry}"
        );
    }
    // a weak adhesion moves the branch off the adhesionless one by little, a strong one by much
    let weak = pinned_unloading(&system2(0.3, 0.01), P_MAX, PINNED_EXPONENT, &opts).unwrap();
    let strong = pinned_unloading(&system2(0.3, 1.0), P_MAX, PINNED_EXPONENT, &opts).unwrap();
    let (w, s, d) = (
        weak.a_r_at(1e-3).unwrap(),
        strong.a_r_at(1e-3).unwrap(),
        b.a_r_at(1e-3).unwrap(),
    );
    assert!(w >= d * (1.0 - UNLOADING_RETRACE_REL) && w < 1.5 * d, "{w} against {d}");
    assert!(s > 3.0 * d, "{s} against {d}");
}

/// A table with a₀ = c·p* exactly (log-linear interpolation is then exact).
fn linear_table(c: f64) -> DryGap {
    let (ln_p0, step) = ((1e-8f64).ln(), 0.1);
    let mut a_r = Vec::new();
    loop {
        let a = c * (ln_p0 + a_r.len() as f64 * step).exp();
        a_r.push(a.min(1.0));
        if a >= 1.0 {
            break;
        }
    }
    let n = a_r.len();
    DryGap {
        ln_p0,
        step,
        gap: vec![0.0; n],
        error: vec![0.0; n],
        a_r,
    }
}

#[test]
fn the_fold_is_the_minimum_of_the_closed_form_on_a_linear_table() {
    let c = 3.0;
    let dry = linear_table(c);
    for (a_t, beta) in [(0.2, 0.75), (0.05, 0.5), (0.6, 0.9)] {
        let b = from_parts(&dry, a_t, P_MAX, beta).unwrap();
        // p = a/c − κa^β: κ from the anchor, the minimum at a* = (βκc)^{1/(1−β)}
        let kappa = (a_t / c - P_MAX) / a_t.powf(beta);
        assert!((b.kappa / kappa - 1.0).abs() < 1e-12);
        let a_star = (beta * kappa * c).powf(1.0 / (1.0 - beta));
        let p_star = a_star / c * (1.0 - 1.0 / beta);
        assert!(
            (b.pull_off / p_star - 1.0).abs() < UNLOADING_FOLD_REL,
            "a_t {a_t}, beta {beta}: {} against {p_star}",
            b.pull_off
        );
        assert!(
            (b.pull_off_a_r / a_star - 1.0).abs() < 0.01,
            "{} against {a_star}",
            b.pull_off_a_r
        );
        // the branch: a_r ≤ 1, rising with the load, a_t at the turning load, none past the fold
        let mut last = 0.0;
        for i in 0..=200 {
            let p = b.pull_off + (P_MAX - b.pull_off) * i as f64 / 200.0;
            let a = b.a_r_at(p).unwrap();
            assert!(a <= 1.0 && a >= last * (1.0 - 1e-12), "p* {p}: {a} after {last}");
            last = a;
        }
        assert!((last / a_t - 1.0).abs() < 1e-12);
        assert!(b.a_r_at(p_star * 1.01).is_none());
    }
    // β = 1 on a linear table: p = (1/c − κ)a, a straight line through the turning state
    let b = from_parts(&dry, 0.2, P_MAX, 1.0).unwrap();
    assert_eq!(b.pull_off, 0.0);
    let a = b.a_r_at(P_MAX / 2.0).unwrap();
    assert!((a / 0.1 - 1.0).abs() < 1e-9, "{a}");
}

#[test]
fn inputs_out_of_range_are_refused_with_their_field() {
    let dry = linear_table(3.0);
    for (a_t, p, beta, field) in [
        (0.0, P_MAX, 0.75, "turning contact fraction"),
        (1.5, P_MAX, 0.75, "turning contact fraction"),
        (0.2, f64::NAN, 0.75, "turning load"),
        (0.2, 1e-9, 0.75, "turning load"),
        (0.2, P_MAX, 0.0, "detachment exponent"),
        (0.2, P_MAX, 1.2, "detachment exponent"),
    ] {
        let e = from_parts(&dry, a_t, p, beta).unwrap_err().to_string();
        assert!(e.contains(field), "{e}");
    }
}

#[test]
fn on_the_slabs_the_branch_holds_gfmds_unloading_contact_and_its_hysteresis() {
    let opts = Options::default();
    let points: Vec<_> = reference_set()
        .iter()
        .filter(|p| p.system == 2 && p.thickness_qr <= 0.3 && p.gamma_factor > 0.0)
        .copied()
        .collect();
    // the maps of a case differ only in their phases: one map's spectrum is the case's
    let cases = cases_of(&points, 1).unwrap();
    assert_eq!(cases.len(), 12);
    let of_case = |t: f64, g: f64| {
        points
            .iter()
            .filter(move |u| u.thickness_qr == t && u.gamma_factor == g)
    };
    let (mut sum, mut rows, mut gfmd_hyst, mut both_hyst) = (0.0, 0, 0, 0);
    for c in &cases {
        let scene = c.scenes[0].clone().with_model(Model::named(5).unwrap()).unwrap();
        let b = pinned_unloading(&scene, P_MAX, PINNED_EXPONENT, &opts).unwrap();
        let path = || of_case(c.thickness_qr, c.gamma_factor);
        for u in path().filter(|u| u.branch == PathBranch::Unloading && u.p < 0.999 * P_MAX) {
            let a = b
                .a_r_at(u.p)
                .unwrap_or_else(|| panic!("t*q_r {} x{}: detached at {}", c.thickness_qr, c.gamma_factor, u.p));
            sum += (a / u.a_r.0).ln().abs();
            rows += 1;
            let Some(l) = path().find(|l| l.branch == PathBranch::Loading && (l.p / u.p - 1.0).abs() < 1e-6) else {
                continue;
            };
            if u.a_r.0 / l.a_r.0 > UNLOADING_HYSTERESIS_RATIO {
                gfmd_hyst += 1;
                let loading = evaluate(&scene.clone().with_pressure(u.p).unwrap(), &opts)
                    .unwrap()
                    .stats
                    .a_r;
                if a / loading > UNLOADING_HYSTERESIS_RATIO {
                    both_hyst += 1;
                }
            }
        }
    }
    let mean = sum / rows as f64;
    assert!(rows > 130, "{rows} rows");
    eprintln!("mean |ln| {mean:.3} over {rows} rows; hysteresis at {both_hyst} of {gfmd_hyst} loads");
    assert!(
        mean < UNLOADING_PINNED_SLAB_MEAN_ABS_LN,
        "mean |ln| {mean} over {rows} rows"
    );
    let share = both_hyst as f64 / gfmd_hyst as f64;
    assert!(
        share >= UNLOADING_PINNED_HYSTERESIS_SHARE,
        "hysteresis at {both_hyst} of {gfmd_hyst} loads"
    );
}

#[test]
fn the_cycle_reports_the_pinned_branch_on_its_way_down_and_only_on_slabs() {
    use asperity::report::cycle::cycle;
    use asperity::report::sweep::Control;
    use asperity::theory::sweep::SweepSpec;
    let opts = Options::default();
    let loads = SweepSpec {
        from: 1e-3,
        to: P_MAX,
        points: 3,
    };
    let run = |scene: &Scene| {
        let mut quiet = |_: usize, _: usize| {};
        cycle(scene, "system-2", &loads, &opts, Control::none(&mut quiet)).unwrap()
    };
    let scene = system2(0.3, 1.0);
    let c = run(&scene);
    let b = pinned_unloading(&scene, P_MAX, PINNED_EXPONENT, &opts).unwrap();
    let mut down = 0;
    for r in &c.rows {
        if r.branch == PathBranch::Loading {
            assert!(r.a_r_unloading_pinned.is_none(), "{r:?}");
            continue;
        }
        match (b.a_r_at(r.p), r.a_r_unloading_pinned) {
            (None, got) => assert!(got.is_none(), "{r:?}"),
            (Some(expected), got) => {
                let got = got.unwrap_or_else(|| panic!("{r:?}: none, {expected} expected"));
                down += 1;
                assert!((got / expected - 1.0).abs() < 1e-12, "{r:?}: {expected}");
                // hysteresis: more contact on the way down than the theory's branch at the load
                assert!(got > r.a_r, "{r:?}");
            }
        }
    }
    assert_eq!(
        down, 2,
        "the two loads below the top (no tensile rows: the theory holds no tension here)"
    );
    // outside the measured range (the half-space) the cycle says nothing
    let thick = run(&system2(f64::INFINITY, 1.0));
    assert!(thick.rows.iter().all(|r| r.a_r_unloading_pinned.is_none()));
}
