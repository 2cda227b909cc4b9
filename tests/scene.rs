//! The scene as a validated value: every way to build or change it checks its ranges once,
//! an error leaves it as it was, and equal scenes are equal cache keys.

mod common;

use asperity::error::{Error, Field};
use asperity::input::model::{Model, ModelKind};
use asperity::input::overrides::Overrides;
use asperity::input::scene::{Scene, PRESSURE_RANGE, SURFACE_ENERGY_RANGE, THICKNESS_RANGE};
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};

/// A change of one input that may be refused.
type Setter = Box<dyn Fn(&mut Scene) -> asperity::Result<()>>;

fn hash(s: &Scene) -> u64 {
    let mut h = DefaultHasher::new();
    s.hash(&mut h);
    h.finish()
}

#[test]
fn each_setter_checks_its_range_and_leaves_the_scene_on_an_error() {
    let s = common::system(2, 3);
    let bad: [(Field, Setter); 6] = [
        (Field::Pressure, Box::new(|s| s.set_pressure(PRESSURE_RANGE.1 * 2.0))),
        (Field::Pressure, Box::new(|s| s.set_pressure(f64::NAN))),
        (
            Field::Thickness,
            Box::new(|s| s.set_thickness_qr(THICKNESS_RANGE.0 / 2.0)),
        ),
        (
            Field::SurfaceEnergy,
            Box::new(|s| s.set_surface_energy_j_m2(-SURFACE_ENERGY_RANGE.1)),
        ),
        (Field::Range, Box::new(|s| s.set_range_m(0.0))),
        (
            Field::ContactModulus,
            Box::new(|s| s.set_contact_modulus_pa(f64::INFINITY)),
        ),
    ];
    for (field, set) in bad {
        let mut t = s.clone();
        let e = set(&mut t).unwrap_err();
        assert_eq!(e.invalid_field(), Some(&field), "{e}");
        assert_eq!(t, s, "{field:?}: the scene changed on an error");
    }
    // in range: the value is taken
    let t = s.clone().with_pressure(3e-4).unwrap().with_thickness_qr(0.2).unwrap();
    assert_eq!((t.pressure(), t.thickness_qr()), (3e-4, 0.2));
}

#[test]
fn overrides_are_validated_together_not_one_by_one() {
    // YP08 is defined on the adhesionless half-space only: on system II (adhesive) the model
    // alone is refused, the model with γ_s = 0 in one set of overrides is taken
    let s = common::system(2, 3);
    let yp08 = Model::fudge(ModelKind::Yp08, 0.42).unwrap();
    assert!(matches!(s.clone().with_model(yp08), Err(Error::Unsupported(_))));
    let o = Overrides {
        model: Some(yp08),
        surface_energy_j_m2: Some(0.0),
        ..Overrides::default()
    };
    let t = s.apply(&o).unwrap();
    assert_eq!((t.model(), t.surface_energy_j_m2()), (yp08, 0.0));
    assert!(Overrides::default().is_empty() && !o.is_empty());
    assert_eq!(s.apply(&Overrides::default()).unwrap(), s);
}

#[test]
fn equal_scenes_are_equal_keys() {
    let a = common::system(1, 3);
    let b = a.clone().with_surface_energy_j_m2(-0.0).unwrap();
    let c = a.clone().with_surface_energy_j_m2(0.0).unwrap();
    assert_eq!(b, c);
    assert_eq!(hash(&b), hash(&c));
    let d = c.clone().with_pressure(c.pressure() * 1.5).unwrap();
    assert_ne!(c, d);
    assert_ne!(hash(&c), hash(&d));
    // the adhesionless twin and the half-space are always valid
    assert_eq!(a.without_adhesion().surface_energy_j_m2(), 0.0);
    assert!(common::at(2, 4, 0.1, 0.05, 1e-4)
        .half_space()
        .thickness_qr()
        .is_infinite());
}
