//! Model 5 (input::model_five) against asperity's GFMD reference set (fit::set_gauge,
//! docs/physics.md §3.6): the stored gauge is what the set gives, it is model 3 without
//! adhesion, and cross-validated — refitted with one thickness or one γ_s left out — its error
//! on the left-out cases is measured against model 4's on the same points.

use asperity::fit::set_gauge::{
    cross_validate, fit_gauge, is_gauge_point, set_errors, summarize, system_two_cases, tabulate, CaseTable,
    ModelChoice, SetCase,
};
use asperity::input::model::Model;
use asperity::input::model_five::{adhesion_measure, BANDWIDTH_GAUGE, GAUGE};
use asperity::input::preset::Preset;
use asperity::theory::engine::Options;
use asperity::tolerances::{MODEL5_GAUGE_REFIT_ABS, MODEL5_VS_MODEL4, MODEL5_VS_MODEL4_GAMMA_OUT};

/// Mean |e_a| of model 4 on the gauge points of the cases `keep` selects.
fn model4_mean(cases: &[SetCase], keep: impl Fn(&SetCase) -> bool, opts: &Options) -> (f64, usize) {
    let sel: Vec<SetCase> = cases.iter().filter(|c| keep(c)).cloned().collect();
    let e = set_errors(&sel, &ModelChoice::Fixed(Model::named(4).unwrap()), opts).unwrap();
    let s = summarize(&e, is_gauge_point);
    (s.a_r_mean, s.points)
}

#[test]
fn the_gauge_is_the_sets_and_cross_validates_against_model_4() {
    let opts = Options::chart();
    let cases = system_two_cases(1).unwrap();
    let nodes: Vec<f64> = (0..=12).map(|k| 0.1 + 0.075 * k as f64).collect();
    let tables: Vec<CaseTable> = tabulate(&cases, &nodes, &opts).unwrap();
    assert_eq!(tables.len(), 21, "7 thicknesses x 3 adhesive γ_s");

    // the stored gauge is the set's least-squares optimum
    let g = fit_gauge(&tables).unwrap();
    for (got, want, name) in [
        (g.base, GAUGE.base, "w_b"),
        (g.slope, GAUGE.slope, "w_s"),
        (g.floor, GAUGE.floor, "w_f"),
    ] {
        assert!(
            (got - want).abs() <= MODEL5_GAUGE_REFIT_ABS,
            "{name}: refit {got:.4}, stored {want:.4}"
        );
    }

    // leave one thickness out: pooled held-out error against model 4's on the same points
    let pooled = |folds: &[(f64, usize)]| {
        let n: usize = folds.iter().map(|f| f.1).sum();
        folds.iter().map(|f| f.0 * f.1 as f64).sum::<f64>() / n as f64
    };
    let (mut m5, mut m4) = (Vec::new(), Vec::new());
    for t in [f64::INFINITY, 1.0, 0.5, 0.3, 0.2, 0.15, 0.1] {
        let f = cross_validate(&tables, Some(t), None).unwrap();
        m5.push((f.held_out_mean, f.held_out_points));
        m4.push(model4_mean(
            &cases,
            |c| c.thickness_qr == t && c.gamma_factor > 0.0,
            &opts,
        ));
    }
    let (e5, e4) = (pooled(&m5), pooled(&m4));
    assert!(
        e5 <= MODEL5_VS_MODEL4 * e4,
        "thickness left out: model 5 {e5:.3}, model 4 {e4:.3}"
    );

    // leave one γ_s out
    let (mut m5, mut m4) = (Vec::new(), Vec::new());
    for f in [0.5, 1.0, 2.0] {
        let fold = cross_validate(&tables, None, Some(f)).unwrap();
        m5.push((fold.held_out_mean, fold.held_out_points));
        m4.push(model4_mean(&cases, |c| c.gamma_factor == f, &opts));
    }
    let (e5, e4) = (pooled(&m5), pooled(&m4));
    assert!(
        e5 <= MODEL5_VS_MODEL4_GAMMA_OUT * e4,
        "γ_s left out: model 5 {e5:.3}, model 4 {e4:.3}"
    );
}

#[test]
fn model_5_follows_the_scene_and_is_model_3_without_adhesion() {
    let preset = Preset::resolve("system-2").unwrap();
    let five = Model::named(5).unwrap();
    let scene = preset.scene().unwrap().with_model(five).unwrap();
    let m = scene.model();
    // W(0) is the gauge's w₀ at the scene's bandwidth (the full system: λ_r/λ_s = 128) and
    // adhesion measure γ̃_glo·√μ_T, up to the crossover's e^{−γ̃/γ_c} (γ̃ = 0.1: 5e-5 of model
    // 3's)
    let bw = scene.spectrum().q_s() / scene.spectrum().q_r();
    assert!((bw - 128.0).abs() < 1e-9);
    let measure = adhesion_measure(scene.gamma_glo(), scene.tabor());
    assert!((measure / (scene.gamma_glo() * scene.tabor().sqrt()) - 1.0).abs() < 1e-12);
    assert!((m.w(0.0) - BANDWIDTH_GAUGE.at(bw).w0(measure)).abs() < 1e-4);
    // more surface energy at the same γ̃_glo is a larger μ_T, so a larger W(0): a thicker slab
    // with twice γ_s against a thinner one of the same γ̃_glo
    let stronger = scene
        .clone()
        .with_surface_energy_j_m2(2.0 * scene.surface_energy_j_m2())
        .unwrap();
    assert!(stronger.tabor() > scene.tabor() * 1.5);
    assert!(stronger.model().w(0.0) > m.w(0.0));
    // a thinner slab has more γ̃_glo, so a larger W(0); without adhesion model 3
    let thin = scene.clone().with_thickness_qr(0.15).unwrap();
    assert!(thin.gamma_glo() > scene.gamma_glo());
    assert!(thin.model().w(0.0) > m.w(0.0));
    let dry = thin.without_adhesion();
    let m3 = Model::named(3).unwrap();
    assert_eq!(
        (dry.model().c1, dry.model().c2, dry.model().alpha),
        (m3.c1, m3.c2, m3.alpha)
    );
    // the adhesionless half-space: identical to model 3 (Table 1, eq. 18 unchanged)
    let sys1 = Preset::resolve("system-1")
        .unwrap()
        .scene()
        .unwrap()
        .without_adhesion()
        .half_space();
    let opts = Options::default();
    let a5 = asperity::theory::engine::evaluate(&sys1.clone().with_model(five).unwrap(), &opts).unwrap();
    let a3 = asperity::theory::engine::evaluate(&sys1.with_model(m3).unwrap(), &opts).unwrap();
    assert_eq!(a5.stats, a3.stats);
}

#[test]
fn the_trust_read_out_says_where_model_5s_gauge_was_not_measured() {
    let preset = Preset::resolve("system-2").unwrap();
    let five = Model::named(5).unwrap();
    let named = |scene: &asperity::input::scene::Scene| {
        asperity::fit::trust::assess(scene)
            .outside
            .iter()
            .any(|l| l.contains("model 5 was gauged"))
    };
    // the full system II (λ_r/λ_s = 128) and its 256² reduction (16): inside the measured range
    let full = preset.scene().unwrap().with_model(five).unwrap();
    assert!(!named(&full));
    let grid = asperity::gfmd::GridSpec::from_preset(preset.gfmd.as_ref().unwrap())
        .with_grid(256)
        .unwrap();
    let (red, _) = asperity::gfmd::reduction::reduce(&full, &grid, true).unwrap();
    assert!(!named(&red));
    // system I (λ_r/λ_s = 200, adhesive): beyond it, named; model 4 there: not
    let sys1 = Preset::resolve("system-1").unwrap().scene().unwrap();
    assert!(named(&sys1.clone().with_model(five).unwrap()));
    assert!(!named(&sys1.with_model(Model::named(4).unwrap()).unwrap()));
}
