//! Property tests over random scenes: the adhesionless theory never produces NaN or values
//! outside [0, 1], and a_r is monotone in p* and in t.

use asperity::input::model::Model;
use asperity::input::scene::Scene;
use asperity::surface::spectrum::{Normalisation, SelfAffine, Spectrum};
use asperity::theory::persson::{self, Accuracy};
use asperity::tolerances::DEFAULT_ACCURACY_REL;
use proptest::prelude::*;

fn scene(log_bw: f64, hurst: f64, ratio: f64, model: u8, p: f64, t: f64) -> Scene {
    let ls = 1e-7;
    let lr = ls * 10f64.powf(log_bw);
    let sa = SelfAffine::new(lr * ratio, lr, ls, hurst, Normalisation::RmsGradient(1.0)).unwrap();
    Scene::new(
        Spectrum::SelfAffine(sa),
        1e7,
        Model::named(model).unwrap(),
        p,
        t,
        0.0,
        1e-9,
    )
    .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn bounded_and_monotone(
        log_bw in 0.31f64..6.0,
        hurst in 0.05f64..0.95,
        ratio in 1.0f64..8.0,
        model in 1u8..=4,
        log_p in -8.0f64..1.0,
        log_t in -4.0f64..3.0,
        semi in any::<bool>(),
    ) {
        let p = 10f64.powf(log_p);
        let t = if semi { f64::INFINITY } else { 10f64.powf(log_t) };
        let acc = Accuracy::default();
        let s = scene(log_bw, hurst, ratio, model, p, t);
        let a = persson::solve(&s, &acc).unwrap();
        prop_assert!(a.a_r.is_finite() && (0.0..=1.0).contains(&a.a_r));
        prop_assert!(a.mean_contact_stress.is_finite() && a.contact_stress_variance >= 0.0);
        // more load → more contact
        let s2 = scene(log_bw, hurst, ratio, model, p * 1.5, t);
        let a2 = persson::solve(&s2, &acc).unwrap();
        prop_assert!(a2.a_r >= a.a_r * (1.0 - DEFAULT_ACCURACY_REL));
        // thinner slab → more contact
        if !semi {
            let s3 = scene(log_bw, hurst, ratio, model, p, t * 0.5);
            let a3 = persson::solve(&s3, &acc).unwrap();
            prop_assert!(a3.a_r >= a.a_r * (1.0 - DEFAULT_ACCURACY_REL));
        }
    }
}
