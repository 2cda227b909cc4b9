use super::*;
use crate::input::model::Model;
use crate::input::preset::Preset;
use crate::theory::hysteresis::{stable_branches, EDGE_REL};

/// The tour's "Jump into contact" scene: system II, model 3, γ_s = 0.1256 J/m², p* = 1e-4
/// (tours/wang-muser.toml), whose hysteresis window in t·q_r lies at 0.099–0.101.
pub(crate) fn jump_scene() -> Scene {
    Preset::resolve("system-2")
        .unwrap()
        .scene()
        .unwrap()
        .with_model(Model::named(3).unwrap())
        .unwrap()
        .with_surface_energy_j_m2(0.1256)
        .unwrap()
        .with_pressure(1e-4)
        .unwrap()
}

fn stable_count(scene: &Scene, t: f64) -> usize {
    let s = Knob::Thickness.apply(scene, t);
    let acc = Options::default().adhesion;
    stable_branches(&s, s.pressure, &acc, None).unwrap()
}

/// A thickness sweep whose step (×1.53 at 8 points, ×1.22 at 16) is far wider than the
/// window finds it by probing the jump of a_r between its neighbours: a jump-in edge below a
/// pull-off edge, two stable branches between them and one just outside each (the library's
/// own branch search at each thickness, independent of the probe: the reference), and the
/// rows stay the requested values.
#[test]
fn a_thickness_sweep_finds_the_window_narrower_than_its_step() {
    let scene = jump_scene();
    for points in [8, 16] {
        let spec = KnobSpec {
            knob: Knob::Thickness,
            from: 0.05,
            to: 1.0,
            points,
        };
        let r = knob(
            &scene,
            "system-2",
            Knob::Thickness,
            &[spec],
            &Options::default(),
            Control::none(&mut |_, _| {}),
        )
        .unwrap();
        assert_eq!(r.rows.len(), points);
        assert_eq!(r.over, Over::Thickness);
        let edge = |kind| {
            let e: Vec<f64> = r
                .window_edges
                .iter()
                .filter(|e| e.kind == kind)
                .map(|e| e.value)
                .collect();
            assert_eq!(e.len(), 1, "{points} points: {:?}", r.window_edges);
            e[0]
        };
        let (jump_in, pull_off) = (edge(EdgeKind::JumpIn), edge(EdgeKind::PullOff));
        assert!(
            0.09 < jump_in && jump_in < pull_off && pull_off < 0.11,
            "{points} points: {jump_in} {pull_off}"
        );
        let margin = 4.0 * EDGE_REL;
        assert_eq!(stable_count(&scene, (jump_in * pull_off).sqrt()), 2);
        assert_eq!(stable_count(&scene, jump_in * (1.0 - margin)), 1);
        assert_eq!(stable_count(&scene, pull_off * (1.0 + margin)), 1);
        // a_r jumps by orders of magnitude across the window between two rows
        let k = r
            .rows
            .iter()
            .position(|row| row.thickness_qr.unwrap() > pull_off)
            .unwrap();
        assert!(r.rows[k - 1].row.a_r > 100.0 * r.rows[k].row.a_r, "{:?}", r.rows);
    }
}

#[test]
fn uneven_values_run_one_at_a_time_and_bad_lists_name_their_field() {
    let scene = Preset::resolve("system-1").unwrap().scene().unwrap();
    assert_eq!(pressure_specs(&[1e-3, 1e-2, 1e-1], false).unwrap().len(), 1);
    assert_eq!(pressure_specs(&[1e-3, 2e-3, 1e-1], false).unwrap().len(), 3);
    let e = pressure_specs(&[1e-3, 2e-3, 1e-1], true).unwrap_err().to_string();
    assert!(e.contains("pressures") && e.contains("log-spaced"), "{e}");
    let e = pressure_specs(&[1e-2, 1e-3], false).unwrap_err().to_string();
    assert!(e.contains("pressures") && e.contains("ascending"), "{e}");
    assert_eq!(knob_specs(&scene, Knob::Gamma, &[0.0, 0.01, 0.02]).unwrap().len(), 1);
    let e = knob_specs(&scene, Knob::Thickness, &[]).unwrap_err().to_string();
    assert!(e.contains("thickness_qr"), "{e}");
    let e = knob_specs(&scene, Knob::Thickness, &[1.0, f64::INFINITY])
        .unwrap_err()
        .to_string();
    assert!(e.contains("finite"), "{e}");
    assert_eq!("thickness_qr".parse::<Over>().unwrap(), Over::Thickness);
    assert!("load".parse::<Over>().unwrap_err().to_string().contains("over"));
}
