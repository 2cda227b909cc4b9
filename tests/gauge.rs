//! Gauging: [S]'s c₁, c₂ recovered from eq. (18), a synthetic round trip with noise of known
//! size, and fits that cannot succeed saying why.

mod common;

use asperity::error::Error;
use asperity::fit::reference::{self, Observable, Observation, Reference};
use asperity::fit::{self, Param};
use asperity::input::model::Model;
use asperity::input::scene::Scene;
use asperity::tolerances::*;

/// A reference named `name` of the observations given.
fn reference_of(name: &str, points: impl IntoIterator<Item = Observation>) -> Reference {
    Reference {
        name: name.into(),
        points: points.into_iter().collect(),
    }
}

/// An observation without a stated error: `observable` at p* = `p` (at σ* = `sigma` for Pr).
fn exact(p: f64, observable: Observable, value: f64, sigma: f64) -> Observation {
    Observation {
        p,
        observable,
        value,
        error: None,
        sigma,
    }
}

fn half_space(model: Model) -> Scene {
    common::dry(1, model).half_space()
}

/// [S] §2.3: model 3's c₁ = −2/9, c₂ = 2/3 "adjusted to closely match a_r(p*)/p* from
/// Equation (18)" over Fig. 1's range p* = 1e-3 … 1. Started from model 1 (c₁ = c₂ = 0).
#[test]
fn eq18_recovers_model_3() {
    let r = reference::eq18(1e-3, 1.0, 31).unwrap();
    let f = fit::fit(&half_space(Model::named(1).unwrap()), &r, &[Param::C1, Param::C2]).unwrap();
    let (c1, c2) = (&f.params[0], &f.params[1]);
    eprintln!(
        "c1 = {} ± {}, c2 = {} ± {}, corr {:?}, rms {}, cond {}, {} evals, {:.2} s",
        c1.value,
        c1.std_error,
        c2.value,
        c2.std_error,
        f.correlation,
        f.residuals[0].rms,
        f.condition_number,
        f.evaluations,
        f.elapsed_s
    );
    // the data pin W(0) = 1 − c₁ − c₂ (the small-p* slope of a_r): 5/9 for model 3
    let rho = f.correlation[0][1];
    let w0 = 1.0 - c1.value - c2.value;
    let se_w0 = (c1.std_error.powi(2) + c2.std_error.powi(2) + 2.0 * rho * c1.std_error * c2.std_error).sqrt();
    eprintln!("W(0) = {w0} ± {se_w0}");
    assert!((w0 - 5.0 / 9.0).abs() < 2.0 * se_w0, "W(0) = {w0} ± {se_w0}");
    // c₁ − c₂ is nearly free (correlation ≈ −1): [S]'s pair lies ~3σ along it (docs/physics.md §3.5)
    assert!(rho < -0.99, "{rho}");
    assert!((c1.value + 2.0 / 9.0).abs() < EQ18_GAUGE_ABS, "c1 = {}", c1.value);
    assert!((c2.value - 2.0 / 3.0).abs() < EQ18_GAUGE_ABS, "c2 = {}", c2.value);
    assert!((c1.value + 2.0 / 9.0).abs() < 4.0 * c1.std_error && (c2.value - 2.0 / 3.0).abs() < 4.0 * c2.std_error);
    // the fit is better than model 3 everywhere it is measured: rms relative residual
    let m3 = fit::predict(&half_space(Model::named(3).unwrap()), &Model::named(3).unwrap(), &r).unwrap();
    let rms3 = (m3
        .iter()
        .zip(&r.points)
        .map(|(y, o)| (y / o.value - 1.0).powi(2))
        .sum::<f64>()
        / 31.0)
        .sqrt();
    assert!(
        f.residuals[0].rms <= rms3 * (1.0 + 1e-9),
        "{} vs model 3 {rms3}",
        f.residuals[0].rms
    );
    assert!(f.residuals[0].rms < 0.02, "rms {}", f.residuals[0].rms);
    assert!(f.chi2_reduced.is_none());
}

/// Data from the custom model at known (c₁, c₂) plus Gaussian noise of known relative size;
/// with the errors given, the fit recovers the truth within 2 standard errors for each seed
/// and its reduced χ² is near 1.
#[test]
fn synthetic_round_trip() {
    let truth = Model::custom(0.3, 0.25, 0.5, 1.0, false).unwrap();
    let clean = reference::eq18(1e-3, 1.0, 25).unwrap();
    let scene = half_space(truth);
    let y = fit::predict(&scene, &truth, &clean).unwrap();
    let noise = 0.01;
    let mut chi2 = Vec::new();
    for seed in 1..=5u64 {
        // Box–Muller on a SplitMix64 stream
        let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let mut uniform = || {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        };
        let points: Vec<_> = clean
            .points
            .iter()
            .zip(&y)
            .map(|(o, &v)| {
                let g = (-2.0 * (1.0 - uniform()).ln()).sqrt() * (2.0 * std::f64::consts::PI * uniform()).cos();
                Observation {
                    value: v * (1.0 + noise * g),
                    error: Some(noise * v),
                    ..*o
                }
            })
            .collect();
        let r = reference_of(&format!("synthetic {seed}"), points);
        let f = fit::fit(&half_space(Model::named(1).unwrap()), &r, &[Param::C1, Param::C2]).unwrap();
        for (p, t) in f.params.iter().zip([0.3, 0.25]) {
            assert!(
                (p.value - t).abs() < 2.0 * p.std_error,
                "seed {seed}: {} = {} ± {} vs {t}",
                p.name,
                p.value,
                p.std_error
            );
        }
        chi2.push(f.chi2_reduced.unwrap());
    }
    // 5 fits with 23 degrees of freedom each: the mean reduced χ² is 1 ± 0.13
    let mean = chi2.iter().sum::<f64>() / chi2.len() as f64;
    assert!((mean - 1.0).abs() < 0.5, "{chi2:?}");
}

#[test]
fn unidentifiable_parameters_are_named() {
    // k_G does nothing without adhesion: an infinite condition number naming k_griffith
    let r = reference::eq18(1e-3, 1.0, 11).unwrap();
    let e = fit::fit(
        &half_space(Model::named(1).unwrap()),
        &r,
        &[Param::C1, Param::KGriffith],
    )
    .unwrap_err();
    let t = e.to_string();
    assert!(
        matches!(e, Error::NotConverged { .. }) && t.contains("k_griffith") && t.contains("condition number"),
        "{t}"
    );
    // a single load cannot tell c₁ from c₂... unless it has more points than parameters
    let r1 = reference_of("one", [exact(0.01, Observable::Area, 0.02, 0.0)]);
    let e = fit::fit(&half_space(Model::named(1).unwrap()), &r1, &[Param::C1, Param::C2]).unwrap_err();
    assert!(e.to_string().contains("more points than fitted parameters"), "{e}");
}

#[test]
fn unreachable_reference_is_refused() {
    // a_r = 1 at every load: W would have to vanish; the best fit leaves the model's range
    let points = [1e-3, 1e-2, 0.1, 0.5].map(|p| exact(p, Observable::Area, 1.0, 0.0));
    let r = reference_of("full", points);
    let e = fit::fit(&half_space(Model::named(1).unwrap()), &r, &[Param::C1]).unwrap_err();
    assert!(
        matches!(e, Error::NotConverged { .. }) && e.to_string().contains("outside what the model can reach"),
        "{e}"
    );
}

#[test]
fn bad_reference_files_name_line_and_column() {
    for (text, want) in [
        ("", "line 1, column (header)"),
        ("p,area\n0.01,0.02\n", "line 1, column 2"),
        ("p\n0.01\n", "line 1, column (header)"),
        ("p,a_r\n0.01,0.02\n0.02,x\n", "line 3, column a_r = x"),
        (
            "p,a_r\n0.01,0.02\n0.02,1.5\n",
            "line 3, column a_r = 1.5: allowed a number with 0 < a_r <= 1",
        ),
        ("# c\np,a_r\n-1,0.02\n", "line 3, column p = -1"),
        ("p,a_r,a_r_err\n0.01,0.02,0\n", "line 2, column a_r_err = 0"),
        ("p,a_r\n0.01,0.02,3\n", "line 2, column (row)"),
        ("p,a_r_err\n0.01,0.02\n", "line 1, column (header)"),
        ("p,a_r\n", "line 2, column (data)"),
    ] {
        let e = reference::parse_csv(text, "ref.csv").unwrap_err().to_string();
        assert!(e.contains(&format!("ref.csv: {want}")), "{text:?}: {e}");
        assert_eq!(e.lines().count(), 1);
    }
    for (text, want) in [
        ("p,sigma\n", "line 1, column (header)"),
        ("p,sigma,density\n0.01,0.1,-2\n", "line 2, column density = -2"),
    ] {
        let e = reference::parse_pr_csv(text, "pr.csv").unwrap_err().to_string();
        assert!(e.contains(&format!("pr.csv: {want}")), "{text:?}: {e}");
    }
    let ok = reference::parse_csv("p,a_r,a_r_err,mean_gap_rel\n0.01,0.02,0.001,\n0.1,,,1.5\n", "ok.csv").unwrap();
    assert_eq!(ok.points.len(), 2);
    assert_eq!(ok.observables(), vec![Observable::Area, Observable::MeanGapRel]);
}

#[test]
fn w0_is_one_minus_c1_minus_c2() {
    // fitting (w₀, c₂) is a reparametrisation of (c₁, c₂): same optimum, w₀ = 1 − c₁ − c₂,
    // with the standard error the covariance of (c₁, c₂) gives
    let r = reference::eq18(1e-3, 1.0, 21).unwrap();
    let s = half_space(Model::named(1).unwrap());
    let a = fit::fit(&s, &r, &[Param::C1, Param::C2]).unwrap();
    let b = fit::fit(&s, &r, &[Param::W0, Param::C2]).unwrap();
    let w0 = 1.0 - a.params[0].value - a.params[1].value;
    assert!((b.params[0].value - w0).abs() < 1e-5, "{} vs {w0}", b.params[0].value);
    assert!((b.model.c1 - a.model.c1).abs() < 1e-4 && (b.model.c2 - a.model.c2).abs() < 1e-4);
    let (s1, s2, rho) = (a.params[0].std_error, a.params[1].std_error, a.correlation[0][1]);
    let se = (s1 * s1 + s2 * s2 + 2.0 * rho * s1 * s2).sqrt();
    assert!(
        (b.params[0].std_error / se - 1.0).abs() < 0.05,
        "{} vs {se}",
        b.params[0].std_error
    );
}

#[test]
fn gap_and_pr_observables_follow_the_theory() {
    use asperity::fit::compare;
    use asperity::theory::engine::Options;
    use asperity::theory::persson::{self, Accuracy};
    use asperity::theory::sweep::{self, SweepSpec};
    // mean gaps: predict (a 48-row sweep, cubic in ln p*) against a sweep on the loads
    let m3 = Model::named(3).unwrap();
    let s = half_space(m3);
    let spec = SweepSpec {
        from: 1e-3,
        to: 0.3,
        points: 6,
    };
    let sw = sweep::sweep(&s, &spec, &Options::default(), None).unwrap();
    let gaps = sw
        .rows
        .iter()
        .map(|row| exact(row.p, Observable::MeanGapRel, row.mean_gap_rel, 0.0));
    let r = reference_of("gaps", gaps);
    let y = fit::predict(&s, &m3, &r).unwrap();
    for (v, o) in y.iter().zip(&r.points) {
        assert!(
            (v / o.value - 1.0).abs() < SWEEP_REFINEMENT_REL,
            "p* {}: {v} vs {}",
            o.p,
            o.value
        );
    }
    // Pr histograms: model 3's own Pr has an L1 distance ~0 from model 3, not from model 1
    let mut s1 = s.clone();
    s1.set_pressure(0.01).unwrap();
    let sol = persson::solve(&s1, &Accuracy::default()).unwrap();
    let (sig, den) = sol.sample(2.0, 101);
    let r = reference_of(
        "pr",
        sig.iter()
            .zip(&den)
            .map(|(&sigma, &value)| exact(0.01, Observable::Pr, value, sigma)),
    );
    let own = compare::score(&s, &m3, &r).unwrap();
    let other = compare::score(&s, &Model::named(1).unwrap(), &r).unwrap();
    assert_eq!(own[0].observable, "pr");
    assert!(own[0].mean < 1e-4, "{own:?}");
    // at least the difference of the areas, 0.0237 − 0.0214 ([S] §3.1)
    assert!(other[0].mean > 0.002, "{other:?}");
}

#[test]
fn data_too_noisy_to_pin_a_parameter_say_so() {
    // standard errors of 10 on a_r ≤ 1: no coefficient is determined
    let r = reference::eq18(1e-3, 1.0, 11).unwrap();
    let with_error = |name: &str, error: &dyn Fn(&Observation) -> f64| {
        reference_of(
            name,
            r.points.iter().map(|o| Observation {
                error: Some(error(o)),
                ..*o
            }),
        )
    };
    let noisy = with_error("noisy", &|_| 10.0);
    let e = fit::fit(&half_space(Model::named(1).unwrap()), &noisy, &[Param::C1])
        .unwrap_err()
        .to_string();
    assert!(e.contains("cannot pin down c1"), "{e}");
    // with errors of 1 % the same fit is determined
    let fine = with_error("fine", &|o| 0.01 * o.value);
    assert!(fit::fit(&half_space(Model::named(1).unwrap()), &fine, &[Param::C1]).is_ok());
}

/// `gfmd_reference` with a resolution ladder on one seed: each load's value is the Δa → 0
/// limit of the same map's sweeps at every rung (run here one by one with `run_sweep` and
/// extrapolated by `ladder::extrapolate`), and its error is the extrapolation error alone
/// (no seed-to-seed term for K = 1).
#[test]
fn gfmd_reference_with_a_ladder_is_the_extrapolated_sweeps() {
    use asperity::fit::gfmd_reference::{gfmd_reference, GfmdReferenceSpec};
    use asperity::gfmd::ladder::extrapolate;
    use asperity::gfmd::sweep::run_sweep;
    use asperity::gfmd::{GfmdOptions, GfmdSetup, GridSpec};
    use asperity::input::preset::Preset;
    use asperity::theory::sweep::SweepSpec;
    use std::sync::atomic::AtomicBool;
    let scene = Preset::resolve("system-2").unwrap().scene().unwrap().without_adhesion();
    let grid = GridSpec {
        system_size_ratio: 2.0,
        bandwidth: 4.0,
        points_per_short_wavelength: 4.0,
    };
    let setup = GfmdSetup {
        scene,
        grid,
        seed: 3,
        surface: None,
        rescale: true,
    };
    let loads = SweepSpec {
        from: 0.01,
        to: 0.04,
        points: 2,
    };
    let rungs = [4.0, 8.0];
    let opts = GfmdOptions::default();
    let cancel = AtomicBool::new(false);
    let spec = GfmdReferenceSpec {
        loads,
        seeds: 1,
        ladder: Some(rungs.to_vec()),
    };
    let g = gfmd_reference(&setup, &spec, &opts, &mut |_, _| {}, &cancel).unwrap();
    let sweeps: Vec<_> = rungs
        .iter()
        .map(|&pts| {
            let s = GfmdSetup {
                grid: GridSpec {
                    points_per_short_wavelength: pts,
                    ..grid
                },
                ..setup.clone()
            };
            run_sweep(&s, &loads, &opts, &mut |_, _| {}, &cancel).unwrap()
        })
        .collect();
    // Δa at fixed λ_s: the grids' own spacings
    let h: Vec<f64> = sweeps.iter().map(|s| 1.0 / s.grid as f64).collect();
    assert_eq!(g.rows.len(), 2);
    for (k, row) in g.rows.iter().enumerate() {
        let a: Vec<f64> = sweeps.iter().map(|s| s.rows[k].a_r).collect();
        let u: Vec<f64> = sweeps.iter().map(|s| s.rows[k].mean_gap_rel).collect();
        let (ea, eu) = (extrapolate(&h, &a).unwrap(), extrapolate(&h, &u).unwrap());
        for (what, got, want) in [
            ("a_r", row.a_r, ea.limit),
            ("a_r_err", row.a_r_err.unwrap(), ea.error),
            ("mean_gap_rel", row.mean_gap_rel, eu.limit),
            ("mean_gap_rel_err", row.mean_gap_rel_err.unwrap(), eu.error),
        ] {
            assert!(
                (got / want - 1.0).abs() < GFMD_REFERENCE_ROWS_REL,
                "load {k} {what}: {got} vs {want}"
            );
        }
    }
    // without adhesion: a_r and ū/h_rms, σ̄_c* = p*/a_r left out
    let obs = g.reference.observables();
    assert_eq!(obs, vec![Observable::Area, Observable::MeanGapRel]);
}
