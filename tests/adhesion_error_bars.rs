//! Honest error bars: the adhesive `error_estimate` of `engine::evaluate`
//! against the true error of a_r, measured two ways on seeded random scenes: against the slow
//! oracle (`oracle/`; only the difference beyond the oracle's own error bar counts) and
//! against a 4× finer run of the fast solver. The estimate must cover
//! the error on ≥ 95 % of the scenes and never fall more than 2× below it.
//!
//! The default test runs a small seeded set (a few seconds); the measured table of
//! BENCHMARKS.md comes from the large set:
//! `cargo test --release -p asperity --test adhesion_error_bars -- --ignored --nocapture`.

mod oracle;

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::surface::spectrum::{Normalisation, SelfAffine, Spectrum};
use asperity::theory::adhesion::{self, AdhesionAccuracy};
use asperity::theory::engine::{self, Options};
use asperity::tolerances::*;
use oracle::march::Resolution;
use oracle::physics::Physics;

/// splitmix64: a seeded stream of uniform numbers in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.next()).exp()
    }
}

/// A random scene around system I or II: H ∈ [0.5, 0.9], p* ∈ [1e-4, 0.1], γ_s ∈ [0.3, 3]×
/// the preset's, t·q_r = ∞ (one in three) or ∈ [0.25, 4], model 1–4 (the validated ranges,
/// away from the thin-slab jump below t·q_r ≈ 0.2 at small loads).
fn random_scene(rng: &mut Rng) -> Scene {
    let n = if rng.next() < 0.5 { 1 } else { 2 };
    let mut s = Preset::resolve(&format!("system-{n}")).unwrap().scene().unwrap();
    let Spectrum::SelfAffine(sa) = s.spectrum() else {
        unreachable!()
    };
    let hurst = 0.5 + 0.4 * rng.next();
    s.set_spectrum(Spectrum::SelfAffine(
        SelfAffine::new(
            sa.system_size,
            sa.lambda_r,
            sa.lambda_s,
            hurst,
            Normalisation::RmsGradient(1.0),
        )
        .unwrap(),
    ))
    .unwrap();
    s.set_pressure(rng.log_uniform(1e-4, 0.1)).unwrap();
    s.set_surface_energy_j_m2(s.surface_energy_j_m2() * rng.log_uniform(0.3, 3.0))
        .unwrap();
    s.set_thickness_qr(if rng.next() < 1.0 / 3.0 {
        f64::INFINITY
    } else {
        rng.log_uniform(0.25, 4.0)
    })
    .unwrap();
    s.set_model(Model::named(1 + (rng.next() * 4.0) as u8).unwrap())
        .unwrap();
    s
}

/// One scene's figures.
#[derive(Debug)]
struct Row {
    a_r: f64,
    estimate: f64,
    /// |a − oracle| (the oracle's own error bar alongside).
    err_oracle: f64,
    oracle_bar: f64,
    /// |a − a(4× finer)|.
    err_fine: f64,
}

/// Evaluates one scene both ways; None when the oracle sees several branches (a hysteresis
/// window, where "the" true value is ambiguous) or the fast solver does not converge.
fn measure(s: &Scene, res: &Resolution) -> Option<Row> {
    let ev = engine::evaluate(s, &Options::default()).ok()?;
    let fine = AdhesionAccuracy {
        steps_per_ln_q: 4.0 * AdhesionAccuracy::default().steps_per_ln_q,
        points_per_width: 4.0 * AdhesionAccuracy::default().points_per_width,
        explore_branches: false,
        ..AdhesionAccuracy::default()
    };
    let a_fine = adhesion::solve(s, &fine, None, None).ok()?.a_r;
    let o = oracle::solve::loading(&Physics::from_scene(s), res, 6);
    if o.all.len() != 1 {
        return None;
    }
    Some(Row {
        a_r: ev.stats.a_r,
        estimate: ev.error_estimate,
        err_oracle: (ev.stats.a_r - o.a_r).abs(),
        oracle_bar: o.error,
        err_fine: (ev.stats.a_r - a_fine).abs(),
    })
}

/// Ratios estimate/true error (oracle and finer run), printed as a table.
fn ratios(rows: &[Row]) -> (Vec<f64>, Vec<f64>) {
    eprintln!("| a_r | estimate | err vs oracle (± oracle) | est/(err − oracle bar) | err vs 4x finer | est/err |");
    eprintln!("|---|---|---|---|---|---|");
    let mut ro = Vec::new();
    let mut rf = Vec::new();
    for r in rows {
        // the oracle is not exact: only the part of the difference beyond its own error bar is
        // charged to the fast solver (as in the grid and 44-scene checks of `adhesion_oracle`);
        // a difference inside the oracle's bar counts as covered. The 4× finer run below has
        // no such allowance.
        let eo = (r.err_oracle - r.oracle_bar).max(0.0);
        ro.push(r.estimate / eo);
        rf.push(r.estimate / r.err_fine);
        eprintln!(
            "| {:.6} | {:.2e} | {:.2e} (±{:.1e}) | {:.2} | {:.2e} | {:.2} |",
            r.a_r,
            r.estimate,
            r.err_oracle,
            r.oracle_bar,
            r.estimate / eo,
            r.err_fine,
            r.estimate / r.err_fine
        );
    }
    (ro, rf)
}

fn check(ratios: &[f64], what: &str) {
    let covered = ratios.iter().filter(|&&r| r >= 1.0).count();
    let worst = ratios.iter().copied().fold(f64::INFINITY, f64::min);
    let mut sorted = ratios.to_vec();
    sorted.sort_by(f64::total_cmp);
    eprintln!(
        "{what}: {covered}/{} covered, worst ratio {worst:.2}, median {:.2}",
        ratios.len(),
        sorted[sorted.len() / 2]
    );
    assert!(
        covered as f64 >= ERROR_BAR_COVERAGE * ratios.len() as f64,
        "{what}: only {covered} of {} estimates cover the error: {sorted:?}",
        ratios.len()
    );
    assert!(
        worst >= ERROR_BAR_WORST_RATIO,
        "{what}: worst ratio {worst}: {sorted:?}"
    );
}

fn run_set(seed: u64, count: usize, res: &Resolution) {
    let mut rng = Rng(seed);
    let mut rows = Vec::new();
    let mut skipped = 0;
    for _ in 0..count {
        let s = random_scene(&mut rng);
        match measure(&s, res) {
            Some(r) => rows.push(r),
            None => skipped += 1,
        }
    }
    eprintln!(
        "{} scenes, {skipped} skipped (several branches or no fast convergence)",
        rows.len()
    );
    assert!(skipped * 5 <= count, "too many scenes skipped: {skipped} of {count}");
    let (ro, rf) = ratios(&rows);
    check(&ro, "against the oracle");
    check(&rf, "against a 4x finer run");
}

#[test]
fn error_estimate_covers_the_true_error_on_a_small_seeded_set() {
    // the oracle refined as in the large set: at its base resolution its own error (up to
    // ±7.8e-5 here) exceeded the fast solver's, and a scene's 3.75e-5 "error" against it was
    // the oracle's (1.9e-5 refined; 1.0e-5 against a 4× finer fast run)
    run_set(13, 5, &oracle_resolution().refined(2.0));
}

#[test]
#[ignore]
fn error_estimate_covers_the_true_error_on_a_large_seeded_set() {
    run_set(2026, 60, &oracle_resolution().refined(2.0));
}

fn oracle_resolution() -> Resolution {
    Resolution {
        eps: 0.1,
        steps_per_ln_q: 8.0,
        points_per_width: 12.0,
        split: 1,
    }
}
