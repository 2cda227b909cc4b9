//! Model 5's change per octave of bandwidth (fit::bandwidth_gauge, docs/physics.md §3.6),
//! judged on GFMD points it was not fitted to: fitted on the bandwidth set's 512² cases of the
//! preset's γ_s (λ_r/λ_s = 32), it must predict the 1024² cases (64) better than the set's
//! gauge held at every bandwidth.

use asperity::fit::bandwidth_gauge::{bandwidth_residuals, fit_per_octave, full_system_cases};
use asperity::fit::reference_set::bandwidth_set;
use asperity::fit::set_gauge::{cases_of, is_gauge_point, set_errors, summarize, tabulate, CaseTable, ModelChoice};
use asperity::input::model::Model;
use asperity::input::model_five::{BandwidthGauge, Gauge, GAUGE};
use asperity::theory::engine::Options;
use asperity::tolerances::{MODEL5_BANDWIDTH_HELD_OUT, MODEL5_FULL_VS_MODEL4};

fn mean_abs(e: &[f64]) -> f64 {
    e.iter().map(|v| v.abs()).sum::<f64>() / e.len() as f64
}

#[test]
fn steps_per_octave_fitted_at_512_predict_1024() {
    let points: Vec<_> = bandwidth_set()
        .iter()
        .filter(|p| p.gamma_factor == 1.0 && (p.grid == 512 || p.grid == 1024))
        .copied()
        .collect();
    let cases = cases_of(&points, 1).unwrap();
    let nodes: Vec<f64> = (0..=6).map(|k| 0.1 + 0.15 * k as f64).collect();
    let tables = tabulate(&cases, &nodes, &Options::chart()).unwrap();
    let train: Vec<CaseTable> = tables.iter().filter(|t| t.grid == 512).cloned().collect();
    let test: Vec<CaseTable> = tables.iter().filter(|t| t.grid == 1024).cloned().collect();
    assert!(train.len() >= 5 && test.len() >= 5, "{} / {}", train.len(), test.len());
    assert!(test.iter().all(|t| (t.bandwidth / 64.0 - 1.0).abs() < 0.05));

    let fitted = fit_per_octave(&train, GAUGE).unwrap();
    let held = BandwidthGauge {
        at_set: GAUGE,
        per_octave: Gauge {
            base: 0.0,
            slope: 0.0,
            floor: 0.0,
        },
    };
    let (e_fit, e_held) = (
        mean_abs(&bandwidth_residuals(&test, &fitted)),
        mean_abs(&bandwidth_residuals(&test, &held)),
    );
    assert!(
        e_fit <= MODEL5_BANDWIDTH_HELD_OUT * e_held,
        "1024² held out: per octave {e_fit:.3}, set's gauge {e_held:.3}"
    );
}

/// What `run --model 5` computes, judged as the hidden points will be: the stored model 5 on
/// the full system II (λ_r/λ_s = 128, a bandwidth none of its tables was at) against the
/// widest GFMD of every adhesive case of the bandwidth set, beside model 4 on the same points.
#[test]
fn on_the_full_system_model_5_halves_model_4s_error() {
    let opts = Options::chart();
    let cases = full_system_cases().unwrap();
    assert_eq!(cases.len(), 21, "7 thicknesses x 3 adhesive γ_s");
    let mean = |m: Model| {
        let e = set_errors(&cases, &ModelChoice::Fixed(m), &opts).unwrap();
        summarize(&e, is_gauge_point)
    };
    let (five, four) = (mean(Model::named(5).unwrap()), mean(Model::named(4).unwrap()));
    assert_eq!(five.points, 84);
    assert!(
        five.a_r_mean <= MODEL5_FULL_VS_MODEL4 * four.a_r_mean,
        "full system: model 5 {:.3}, model 4 {:.3}",
        five.a_r_mean,
        four.a_r_mean
    );
}
