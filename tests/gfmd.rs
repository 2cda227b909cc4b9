//! GFMD reference solver: closed forms (full-contact sinusoid, thin plate, Johnson's
//! partial contact), self-affine contact, reproducibility, hard cases, surface generator,
//! height-map files and the `asperity gfmd` command.

use asperity::error::{Error, Field};
use asperity::gfmd::{self, GfmdOptions, GfmdSetup, GridSpec, Problem};
use asperity::input::preset::Preset;
use asperity::numerics::fft2;
use asperity::surface::heightmap::{self, Surface};
use asperity::surface::spectrum::{Discrete, Normalisation, SelfAffine, Spectrum};
use asperity::theory::slab::slab_factor;
use asperity::tolerances::*;
use std::f64::consts::PI;

use std::sync::atomic::AtomicBool;

const E: f64 = 1e7;

fn no_cancel() -> AtomicBool {
    AtomicBool::new(false)
}

fn opts(tol: f64) -> GfmdOptions {
    GfmdOptions {
        tolerance: tol,
        ..GfmdOptions::default()
    }
}

/// h = Δ cos(2πk x/L) on an nx × ny grid of spacing da.
fn sinusoid(nx: usize, ny: usize, da: f64, k: usize, amp: f64) -> Surface {
    let h = (0..nx * ny)
        .map(|i| amp * (2.0 * PI * k as f64 * (i % nx) as f64 / nx as f64).cos())
        .collect();
    Surface::new(nx, ny, da, h).unwrap()
}

fn problem(s: &Surface, thickness: f64, pressure: f64) -> Problem<'_> {
    Problem {
        surface: s,
        modulus: E,
        thickness,
        pressure,
        gamma: 0.0,
        range: 1e-9,
    }
}

/// Full contact of one sinusoid: σ(x) = p₀ + φ(q)Δ cos(qx), every node on the wall.
fn full_contact_case(thickness_times_q: f64) -> (f64, f64) {
    let (n, da, k, amp) = (32, 1e-8, 2, 1e-9);
    let s = sinusoid(n, n, da, k, amp);
    let q = 2.0 * PI * k as f64 / (n as f64 * da);
    let t = if thickness_times_q.is_infinite() {
        f64::INFINITY
    } else {
        thickness_times_q / q
    };
    let phi = 0.5 * q * E * slab_factor(q * t);
    let p0 = 3.0 * phi * amp;
    let pr = problem(&s, t, p0);
    let sol = gfmd::solve(&pr, &opts(GFMD_TEST_RESIDUAL), &mut |_| {}, &no_cancel()).unwrap();
    assert!(sol.on_wall.iter().all(|&c| c), "full contact expected");
    let mut err: f64 = 0.0;
    let mut proj = 0.0;
    for (i, &sig) in sol.stress.iter().enumerate() {
        let c = (q * (i % n) as f64 * da).cos();
        err = err.max((sig - (p0 + phi * amp * c)).abs());
        proj += (sig - p0) * c;
    }
    let amplitude = proj * 2.0 / (n * n) as f64;
    (err / p0, amplitude / (E * amp))
}

#[test]
fn single_sinusoid_in_full_contact_has_the_exact_stress() {
    let (err, amp) = full_contact_case(f64::INFINITY);
    assert!(err < GFMD_FULL_CONTACT_REL, "max |σ − σ_exact|/p₀ = {err:e}");
    let q = 2.0 * PI * 2.0 / 32e-8;
    assert!((amp / (0.5 * q) - 1.0).abs() < GFMD_FULL_CONTACT_REL);
}

#[test]
fn thin_plate_limit_of_the_slab_stiffness() {
    // φ = qE*f(qt)/2 → E* q⁴ t³/12 for qt → 0 (f → x³/6)
    let x = 0.01;
    let (err, amp) = full_contact_case(x);
    assert!(err < GFMD_FULL_CONTACT_REL, "{err:e}");
    let q: f64 = 2.0 * PI * 2.0 / 32e-8;
    let t = x / q;
    let plate = q.powi(4) * t.powi(3) / 12.0; // in units of E*
    assert!((amp / plate - 1.0).abs() < GFMD_THIN_PLATE_REL, "{amp:e} vs {plate:e}");
}

/// Johnson's sinusoid h = Δ cos(2πx/λ), one period over `nx` nodes of Δa = Δ = 10 nm (two
/// rows): the map, Δa, λ = L and p_full = πE*Δ/λ, the load of full contact.
fn johnson(nx: usize) -> (Surface, f64, f64, f64) {
    let (da, amp) = (1e-8, 1e-8);
    let lambda = nx as f64 * da;
    (sinusoid(nx, 2, da, 1, amp), da, lambda, PI * E * amp / lambda)
}

#[test]
fn johnson_sinusoid_partial_contact_width() {
    // λ = L = 512 Δa: sin²(πc/λ) = p̄/p_full
    let nx = 512;
    let (s, da, lambda, p_full) = johnson(nx);
    for ratio in [0.1, 0.3, 0.6] {
        let pr = problem(&s, f64::INFINITY, ratio * p_full);
        let sol = gfmd::solve(&pr, &opts(1e-9), &mut |_| {}, &no_cancel()).unwrap();
        let width = sol.on_wall[..nx].iter().filter(|&&c| c).count() as f64 * da;
        let c_exact = lambda / PI * ratio.sqrt().asin();
        let rel = width / (2.0 * c_exact) - 1.0;
        eprintln!(
            "Johnson p/p_full = {ratio}: 2c = {width:e} vs {:e}, error {rel:+.2e}, {} steps",
            2.0 * c_exact,
            sol.iterations
        );
        assert!(
            rel.abs() < GFMD_JOHNSON_REL,
            "p/p_full = {ratio}: relative width error {rel:e}"
        );
        // contact is one contiguous patch around the crest x = 0
        assert!(sol.on_wall[0]);
        assert!(!sol.on_wall[nx / 2]);
    }
    // above p_full: full contact
    let pr = problem(&s, f64::INFINITY, 1.05 * p_full);
    let sol = gfmd::solve(&pr, &opts(1e-9), &mut |_| {}, &no_cancel()).unwrap();
    assert!(sol.on_wall.iter().all(|&c| c));
}

/// Johnson's pressure profile p(x) = (2p̄/S²) cos(πx/λ) √(S² − sin²(πx/λ)), S² = p̄/p_full:
/// (p/cos)² is linear in sin²(πx/λ). A least-squares fit over the inner contact nodes gives
/// the half-width c (intercept/slope) and the amplitude below the grid resolution.
#[test]
fn johnson_sinusoid_pressure_profile_at_128_points_per_wavelength() {
    let nx = 128;
    let (s, da, lambda, p_full) = johnson(nx);
    for ratio in [0.1, 0.3, 0.6, 0.9] {
        let pr = problem(&s, f64::INFINITY, ratio * p_full);
        let sol = gfmd::solve(&pr, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap();
        let (mut sx, mut sy, mut sxx, mut sxy, mut m) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for i in 0..nx {
            let x = if i <= nx / 2 { i as f64 } else { i as f64 - nx as f64 } * da;
            let s2 = (PI * x / lambda).sin().powi(2);
            // inner nodes only: the two nodes at each edge carry the O(Δa) edge error
            if sol.on_wall[i] && s2 < 0.8 * ratio {
                let y = (sol.stress[i] / (PI * x / lambda).cos()).powi(2);
                sx += s2;
                sy += y;
                sxx += s2 * s2;
                sxy += s2 * y;
                m += 1.0;
            }
        }
        let slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
        let intercept = (sy - slope * sx) / m;
        let c_fit = lambda / PI * (-intercept / slope).sqrt().asin();
        let c_exact = lambda / PI * ratio.sqrt().asin();
        let amp_fit = (-slope).sqrt();
        let amp_exact = 2.0 * p_full; // 2p̄/S² with S² = p̄/p_full
        eprintln!(
            "Johnson λ/Δa = 128, p/p_full = {ratio}: c error {:+.2e}, amplitude error {:+.2e}",
            c_fit / c_exact - 1.0,
            amp_fit / amp_exact - 1.0
        );
        assert!((c_fit / c_exact - 1.0).abs() < GFMD_JOHNSON_REL);
        assert!((amp_fit / amp_exact - 1.0).abs() < GFMD_JOHNSON_REL);
    }
}

fn system1_setup(n_spec: GridSpec, pressure: f64) -> GfmdSetup {
    let preset = Preset::resolve("system-1").unwrap();
    let mut scene = preset.scene().unwrap();
    scene.set_pressure(pressure).unwrap();
    scene.set_surface_energy_j_m2(0.0).unwrap();
    GfmdSetup {
        scene,
        grid: n_spec,
        seed: 7,
        surface: None,
        rescale: true,
    }
}

const SMALL: GridSpec = GridSpec {
    system_size_ratio: 2.0,
    bandwidth: 8.0,
    points_per_short_wavelength: 8.0,
};

#[test]
fn adhesionless_self_affine_contact_at_small_load() {
    let setup = system1_setup(SMALL, 0.01);
    let r = gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap();
    assert_eq!(r.grid, 128);
    assert!(r.converged && r.residual <= 1e-8);
    let ratio = r.stats.a_r / 0.01;
    eprintln!(
        "128²: a_r/p* = {ratio:.3}, σ̄_c* = {:.4}, var* = {:.4}, u/h_rms = {:.3}, {} steps; theory a_r = {:?}",
        r.stats.mean_contact_stress,
        r.stats.contact_stress_variance,
        r.mean_gap_rel,
        r.iterations,
        r.theory.as_ref().map(|t| t.stats.a_r)
    );
    assert!(ratio > GFMD_AR_OVER_P.0 && ratio < GFMD_AR_OVER_P.1, "a_r/p* = {ratio}");
    // force balance σ̄_c = p*/a_r
    assert!((r.stats.mean_contact_stress * r.stats.a_r / 0.01 - 1.0).abs() < GFMD_FORCE_BALANCE_REL);
    // ∫Pr dσ* = a_r
    let w = r.stats.pr.sigma[1] - r.stats.pr.sigma[0];
    let integral: f64 = r.stats.pr.density.iter().sum::<f64>() * w;
    assert!((integral / r.stats.a_r - 1.0).abs() < 1e-12);
    assert!(r.mean_gap > 0.0 && r.mean_gap_rel > 0.0 && r.mean_gap_rel.is_finite());
    // the theory ran on the same realisation
    let th = r.theory.as_ref().expect("adhesionless theory");
    assert!(th.stats.a_r > 0.005 && th.stats.a_r < 0.05);
    assert!(r.theory_error.is_none());
}

#[test]
fn converged_state_satisfies_the_stated_residual_independently() {
    // recompute the force balance from the returned fields: ⟨σ⟩ = p₀, and nodes off the wall
    // carry (almost) no stress
    let spec = SMALL
        .spectrum(&match Preset::resolve("system-1").unwrap().spectrum().unwrap() {
            Spectrum::SelfAffine(s) => s,
            _ => unreachable!(),
        })
        .unwrap();
    let s = heightmap::generate(&spec, 64, 3).unwrap();
    let p0 = 0.02 * E * s.rms_gradient();
    let pr = problem(&s, f64::INFINITY, p0);
    let sol = gfmd::solve(&pr, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap();
    let n = sol.stress.len() as f64;
    let rms = (sol.stress.iter().map(|x| x * x).sum::<f64>() / n).sqrt();
    let mean = sol.stress.iter().sum::<f64>() / n;
    assert!((mean / p0 - 1.0).abs() < 1e-12);
    let off: f64 = sol
        .stress
        .iter()
        .zip(&sol.on_wall)
        .filter(|(_, &c)| !c)
        .map(|(x, _)| x * x)
        .sum::<f64>();
    // off the wall F = −σ: its rms over all nodes is bounded by the residual
    assert!((off / n).sqrt() / rms <= 1e-8 * (1.0 + 1e-9));
    assert!(sol.gap.iter().all(|&g| g >= 0.0));
    assert!(sol.residual <= 1e-8);
}

#[test]
fn seeded_runs_are_bit_for_bit_reproducible() {
    let setup = system1_setup(SMALL, 0.01);
    let a = gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap();
    let b = gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap();
    assert_eq!(a.surface, b.surface);
    assert_eq!(a.stats.a_r.to_bits(), b.stats.a_r.to_bits());
    assert_eq!(
        a.stats.mean_contact_stress.to_bits(),
        b.stats.mean_contact_stress.to_bits()
    );
    assert_eq!(a.mean_gap.to_bits(), b.mean_gap.to_bits());
    assert_eq!(a.iterations, b.iterations);
    assert_eq!(a.stats.pr, b.stats.pr);
    let mut other = setup.clone();
    other.seed = 8;
    let c = gfmd::run(&other, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap();
    assert_ne!(a.surface, c.surface);
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    // 256² runs its FFTs and node loops on rayon; partial sums are added in a fixed order
    let grid = GridSpec {
        system_size_ratio: 2.0,
        bandwidth: 16.0,
        points_per_short_wavelength: 8.0,
    };
    let setup = system1_setup(grid, 0.01);
    let on = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap())
    };
    let (a, b) = (on(1), on(3));
    assert_eq!(a.grid, 256);
    assert_eq!(a.iterations, b.iterations);
    assert_eq!(a.stats.a_r.to_bits(), b.stats.a_r.to_bits());
    assert_eq!(a.mean_gap.to_bits(), b.mean_gap.to_bits());
    assert_eq!(
        a.stats.contact_stress_variance.to_bits(),
        b.stats.contact_stress_variance.to_bits()
    );
}

fn assert_finite(r: &gfmd::GfmdResult) {
    for x in [
        r.stats.a_r,
        r.stats.mean_contact_stress,
        r.stats.contact_stress_variance,
        r.mean_gap,
        r.residual,
    ] {
        assert!(x.is_finite(), "{r:?}");
    }
    assert!(r.stats.pr.density.iter().all(|x| x.is_finite()));
}

fn tiny() -> GridSpec {
    GridSpec {
        system_size_ratio: 2.0,
        bandwidth: 4.0,
        points_per_short_wavelength: 8.0,
    }
}

#[test]
fn hard_case_tiny_load_gives_a_handful_of_contacts() {
    let setup = system1_setup(tiny(), 1e-4);
    let r = gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap();
    assert_finite(&r);
    assert!(
        r.contact_nodes >= 1 && r.contact_nodes < 20,
        "{} contact nodes",
        r.contact_nodes
    );
    assert!((r.stats.mean_contact_stress * r.stats.a_r / 1e-4 - 1.0).abs() < GFMD_FORCE_BALANCE_REL);
}

#[test]
fn hard_case_full_contact_at_large_load() {
    let setup = system1_setup(tiny(), 20.0);
    let r = gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap();
    assert_finite(&r);
    assert_eq!(r.stats.a_r, 1.0);
    assert!((r.stats.mean_contact_stress / 20.0 - 1.0).abs() < 1e-9);
    assert_eq!(r.mean_gap, 0.0);
}

#[test]
fn hard_case_strong_adhesion_converges_or_reports() {
    let preset = Preset::resolve("system-2").unwrap();
    for gamma in [0.157, 1.5] {
        let mut scene = preset.scene().unwrap();
        scene.set_surface_energy_j_m2(gamma).unwrap();
        let setup = GfmdSetup {
            scene,
            grid: tiny(),
            seed: 1,
            surface: None,
            rescale: true,
        };
        let mut hard_wall = setup.clone();
        hard_wall.scene.set_surface_energy_j_m2(0.0).unwrap();
        let opts = GfmdOptions::default();
        match gfmd::run(&setup, &opts, &mut |_| {}, &no_cancel()) {
            Ok(r) => {
                assert_finite(&r);
                assert!(
                    r.converged && r.residual <= opts.tolerance,
                    "gamma {gamma}: {}",
                    r.residual
                );
                // adhesion pulls more of the map into contact than the hard wall alone
                let dry = gfmd::run(&hard_wall, &opts, &mut |_| {}, &no_cancel()).unwrap();
                assert!(
                    r.stats.a_r > dry.stats.a_r,
                    "gamma {gamma}: {} vs {}",
                    r.stats.a_r,
                    dry.stats.a_r
                );
                // the theory beside it, or the reason it is missing
                assert!(r.theory.is_some() != r.theory_error.is_some(), "gamma {gamma}");
            }
            // FIRE's one line: the residual against the tolerance after the step limit
            Err(Error::NotConverged { reason, .. }) => {
                assert!(
                    reason.contains("relative force residual") && reason.contains("steps"),
                    "{reason}"
                )
            }
            Err(e) => panic!("unexpected error {e}"),
        }
    }
}

#[test]
fn adhesion_increases_the_contact_area() {
    let preset = Preset::resolve("system-2").unwrap();
    let mut scene = preset.scene().unwrap();
    let mut run = |gamma: f64| {
        scene.set_surface_energy_j_m2(gamma).unwrap();
        let setup = GfmdSetup {
            scene: scene.clone(),
            grid: tiny(),
            seed: 2,
            surface: None,
            rescale: true,
        };
        gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap()
    };
    let dry = run(0.0);
    let sticky = run(0.157);
    assert!(
        sticky.stats.a_r > 1.5 * dry.stats.a_r,
        "{} vs {}",
        sticky.stats.a_r,
        dry.stats.a_r
    );
    // tensile stresses appear in contact
    assert!(sticky.stats.pr.sigma[0] < 0.0);
}

#[test]
fn hard_case_very_thin_slab() {
    let mut setup = system1_setup(tiny(), 0.01);
    setup.scene.set_thickness_qr(0.01).unwrap();
    match gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &no_cancel()) {
        Ok(r) => {
            assert_finite(&r);
            // a thin slab conforms: far more contact than the semi-infinite body
            assert!(r.stats.a_r > 0.1, "{}", r.stats.a_r);
        }
        Err(Error::NotConverged { .. }) => {}
        Err(e) => panic!("unexpected error {e}"),
    }
}

#[test]
fn cancellation_and_iteration_limit_are_reported() {
    let setup = system1_setup(tiny(), 0.01);
    let cancel = AtomicBool::new(true);
    let e = gfmd::run(&setup, &GfmdOptions::default(), &mut |_| {}, &cancel).unwrap_err();
    assert_eq!(e, Error::Cancelled);
    let o = GfmdOptions {
        max_iterations: 5,
        ..GfmdOptions::default()
    };
    let e = gfmd::run(&setup, &o, &mut |_| {}, &no_cancel()).unwrap_err();
    assert!(matches!(e, Error::NotConverged { .. }), "{e}");
    assert!(e.to_string().contains("max iterations"), "{e}");
    // progress is reported
    let mut calls = 0;
    gfmd::run(
        &setup,
        &GfmdOptions::default(),
        &mut |p| {
            calls += 1;
            assert!(p.residual.is_finite());
        },
        &no_cancel(),
    )
    .unwrap();
    assert!(calls >= 2);
}

#[test]
fn the_theory_on_the_map_is_announced_and_cancellable() {
    use asperity::gfmd::Stage;
    use asperity::theory::sweep::SweepSpec;
    use std::sync::atomic::Ordering;
    for gamma in [0.0, 0.05] {
        let mut setup = system1_setup(tiny(), 0.01);
        setup.scene.set_surface_energy_j_m2(gamma).unwrap();
        // one Theory report, the last, after the relaxation's
        let mut stages = Vec::new();
        let r = gfmd::run(
            &setup,
            &GfmdOptions::default(),
            &mut |p| stages.push(p.stage),
            &no_cancel(),
        )
        .unwrap();
        assert_eq!(stages.last(), Some(&Stage::Theory), "γ_s {gamma}");
        assert_eq!(stages.iter().filter(|s| **s == Stage::Theory).count(), 1);
        assert!(r.theory.is_some() && stages.len() >= 2);
        // the flag raised when the theory begins ends the run, which is not a result
        let cancel = AtomicBool::new(false);
        let e = gfmd::run(
            &setup,
            &GfmdOptions::default(),
            &mut |p| {
                if p.stage == Stage::Theory {
                    cancel.store(true, Ordering::Relaxed);
                }
            },
            &cancel,
        )
        .unwrap_err();
        assert_eq!(e, Error::Cancelled, "γ_s {gamma}");
        // the same for the theory's sweep of a GFMD sweep, announced with the number of loads
        let spec = SweepSpec {
            from: 0.005,
            to: 0.02,
            points: 3,
        };
        let cancel = AtomicBool::new(false);
        let mut announced = None;
        let e = gfmd::sweep::run_sweep(
            &setup,
            &spec,
            &GfmdOptions::default(),
            &mut |k, p| {
                if p.stage == Stage::Theory {
                    announced = Some(k);
                    cancel.store(true, Ordering::Relaxed);
                }
            },
            &cancel,
        )
        .unwrap_err();
        assert_eq!((e, announced), (Error::Cancelled, Some(3)), "γ_s {gamma}");
    }
}

#[test]
fn bad_inputs_name_the_field() {
    let s = sinusoid(16, 16, 1e-8, 1, 1e-9);
    let mut pr = problem(&s, f64::INFINITY, -1.0);
    let e = gfmd::solve(&pr, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap_err();
    assert_eq!(e.invalid_field(), Some(&Field::PressurePa), "{e}");
    pr.pressure = 1.0;
    pr.thickness = -1.0;
    let e = gfmd::solve(&pr, &GfmdOptions::default(), &mut |_| {}, &no_cancel()).unwrap_err();
    assert_eq!(e.invalid_field(), Some(&Field::Thickness), "{e}");
    pr.thickness = f64::INFINITY;
    let e = gfmd::solve(&pr, &opts(f64::NAN), &mut |_| {}, &no_cancel()).unwrap_err();
    assert_eq!(e.invalid_field(), Some(&Field::GfmdTolerance), "{e}");
    let e = SMALL.with_grid(8).unwrap_err();
    assert_eq!(e.invalid_field(), Some(&Field::Grid), "{e}");
    let flat = Surface::new(8, 8, 1e-8, vec![0.0; 64]).unwrap();
    let e = gfmd::solve(
        &problem(&flat, f64::INFINITY, 1.0),
        &GfmdOptions::default(),
        &mut |_| {},
        &no_cancel(),
    )
    .unwrap_err();
    assert_eq!(e.invalid_field(), Some(&Field::HeightMap), "{e}");
}

fn spec(n_ratio: f64) -> SelfAffine {
    SelfAffine::new(4e-6, 2e-6, 4e-6 / n_ratio, 0.8, Normalisation::RmsGradient(1.0)).unwrap()
}

#[test]
fn generated_surface_has_the_target_rms_gradient_exactly() {
    for (n, ratio) in [(64, 16.0), (128, 32.0), (96, 12.0)] {
        let sp = spec(ratio);
        let s = heightmap::generate(&sp, n, 11).unwrap();
        let d = Discrete::from_height_map(&s.heights, n, sp.system_size, sp.q_r()).unwrap();
        let target = Spectrum::SelfAffine(sp).rms_gradient();
        assert!((d.moment(2).sqrt() / target - 1.0).abs() < SURFACE_GBAR_REL);
        assert!((s.rms_gradient() / target - 1.0).abs() < SURFACE_GBAR_REL);
        // zero mean
        assert!(s.heights.iter().sum::<f64>().abs() / (n as f64) < 1e-12 * s.rms_height() * n as f64);
    }
}

#[test]
fn generated_surface_is_real_and_has_the_spectrum_shape() {
    // every mode: |h̃(q)|² A/(2π)² = s² C(q) with one common s (deterministic amplitudes); no
    // modes at q = 0 or beyond q_s. A non-Hermitian spectrum would lose half of some modes
    // when the real part is taken.
    let n = 64;
    let sp = spec(16.0);
    let s = heightmap::generate(&sp, n, 5).unwrap();
    let ft = fft2::forward_real(&s.heights, n);
    let area = sp.system_size.powi(2);
    let ql = 2.0 * PI / sp.system_size;
    let wrap = |i: usize| if i <= n / 2 { i as f64 } else { i as f64 - n as f64 };
    let mut scale: Option<f64> = None;
    let mut max_mode: f64 = 0.0;
    for c in &ft {
        max_mode = max_mode.max((c / (n * n) as f64).norm_sqr());
    }
    for i in 0..n {
        for j in 0..n {
            let q = ql * (wrap(i).powi(2) + wrap(j).powi(2)).sqrt();
            let m = (ft[i * n + j] / (n * n) as f64).norm_sqr();
            if q == 0.0 || q > sp.q_s() * (1.0 + 1e-12) {
                assert!(m < 1e-24 * max_mode, "mode ({i},{j}) should be empty: {m:e}");
                continue;
            }
            let ratio = m * area / (2.0 * PI).powi(2) / sp.psd(q);
            match scale {
                None => scale = Some(ratio),
                Some(s0) => assert!(
                    (ratio / s0 - 1.0).abs() < SURFACE_SHAPE_REL,
                    "({i},{j}): {ratio} vs {s0}"
                ),
            }
        }
    }
    // the scale is close to 1: the grid's modes nearly exhaust the continuum ḡ
    let s0 = scale.unwrap();
    assert!(s0 > 0.5 && s0 < 2.0, "{s0}");
}

#[test]
fn generator_is_seeded_and_checks_resolution() {
    let sp = spec(16.0);
    let a = heightmap::generate(&sp, 64, 1).unwrap();
    let b = heightmap::generate(&sp, 64, 1).unwrap();
    let c = heightmap::generate(&sp, 64, 2).unwrap();
    assert_eq!(a, b);
    assert_ne!(a, c);
    let e = heightmap::generate(&sp, 16, 1).unwrap_err();
    assert_eq!(e.invalid_field(), Some(&Field::Grid), "{e}");
}

#[test]
fn height_map_files_are_validated() {
    let e = Surface::parse("1 2 3\n4 5\n7 8 9\n", "m.txt", 1e-6)
        .unwrap_err()
        .to_string();
    assert!(e.contains("m.txt:2"), "{e}");
    let e = Surface::parse("1 2 3 4\n4 5 6 7\n", "m.txt", 1e-6)
        .unwrap_err()
        .to_string();
    assert!(e.contains("square"), "{e}");
    let e = Surface::parse("1 2 3 4\n4 NaN 6 7\n1 2 3 4\n1 2 3 4\n", "m.txt", 1e-6)
        .unwrap_err()
        .to_string();
    assert!(e.contains("m.txt:2") && e.contains("NaN"), "{e}");
    let e = Surface::parse("1 2 x 4\n", "m.txt", 1e-6).unwrap_err().to_string();
    assert!(e.contains("m.txt:1"), "{e}");
    let e = Surface::parse("# only a comment\n", "m.txt", 1e-6)
        .unwrap_err()
        .to_string();
    assert!(e.contains("empty"), "{e}");
    let ok = "# c\n1 2 3 4\n\n4 5 6 7\n1 2 3 4\n1 2 3 4\n";
    let s = Surface::parse(ok, "m.txt", 4e-6).unwrap();
    assert_eq!((s.nx, s.ny), (4, 4));
    assert!((s.spacing - 1e-6).abs() < 1e-20);
    let e = Surface::parse(ok, "m.txt", -1.0).unwrap_err();
    assert_eq!(e.invalid_field(), Some(&Field::SystemSize), "{e}");
    // a flat map, heights that overflow and a side that makes the slope vanish are the map's
    // fault, named as such (not a pressure that over- or underflows later)
    let flat = Surface::parse("1 1 1 1\n1 1 1 1\n1 1 1 1\n1 1 1 1\n", "m.txt", 1e-6).unwrap();
    let huge = Surface::parse("1e200 0 -1e200 0\n0 0 0 0\n1 2 3 4\n1 2 3 4\n", "m.txt", 1e-6).unwrap();
    let wide = Surface::parse("1e-9 0 -1e-9 0\n0 0 0 0\n1e-9 0 0 0\n0 0 0 0\n", "m.txt", 1e2).unwrap();
    for m in [flat, huge, wide] {
        let e = m.check_rough().unwrap_err();
        assert_eq!(e.invalid_field(), Some(&Field::HeightMap), "{e}");
    }
    let e = Surface::load(std::path::Path::new("/nonexistent/map.txt"), 1e-6)
        .unwrap_err()
        .to_string();
    assert!(e.contains("/nonexistent/map.txt"), "{e}");
}
