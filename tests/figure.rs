//! The figures of \[S\] computed through the library alone (`asperity::report::figure`, no
//! front end): Table 1's models against the values \[S\] prints, and figure 1's model 1 curve
//! against its closed form a_r = erf(√2 p*) (W ≡ 1 on a half-space, docs/reference-values.md).

use asperity::input::model::ModelKind;
use asperity::report::figure::{compute, spec, table1, SeriesKind, Style};
use asperity::tolerances::{MODEL1_ERF_REL, TABLE1_ABS};

#[test]
fn table_1_through_the_library_holds_the_values_s_prints() {
    let t = table1::compute(None, &mut |_| panic!("no GFMD run was asked for")).unwrap();
    // [S] Table 1 as printed: (column, σ̄_c*, ⟨δσ_c²⟩*)
    let paper = [
        ("GFMD", 0.4963, 0.0908),
        ("model 1", 0.6264, 0.1071),
        ("model 2", 0.4215, 0.0484),
        ("model 3", 0.4670, 0.0595),
    ];
    assert_eq!(t.columns.len(), paper.len());
    for (c, (name, mean, var)) in t.columns.iter().zip(paper) {
        assert_eq!(c.column, name);
        assert_eq!(
            (c.paper_mean_contact_stress, c.paper_contact_stress_variance),
            (mean, var)
        );
        if name == "GFMD" {
            assert_eq!(c.mean_contact_stress, None, "no GFMD without a choice");
            continue;
        }
        let (m, v) = (c.mean_contact_stress.unwrap(), c.contact_stress_variance.unwrap());
        assert!((m - mean).abs() < TABLE1_ABS, "{name}: σ̄_c* {m} against {mean}");
        assert!((v - var).abs() < TABLE1_ABS, "{name}: ⟨δσ_c²⟩* {v} against {var}");
        // σ̄_c* a_r = p* (the load the contact carries)
        assert!((m * c.a_r.unwrap() / t.pressure - 1.0).abs() < 1e-9, "{name}");
    }
    // as a figure: asperity's moments and [S]'s told apart by what they are
    let fig = t.figure();
    let paper_series: Vec<bool> = fig
        .series
        .iter()
        .map(|s| s.kind == SeriesKind::Moments { paper: true })
        .collect();
    assert_eq!(paper_series, [false, true, false, true]);
}

#[test]
fn figure_1_model_1_is_erf_and_eq18_is_a_dashed_closed_form() {
    let mut s = spec::resolve("1").unwrap();
    s.points = 3;
    let data = compute::compute(&s, None).unwrap();
    let model_1 = data.series.iter().find(|s| s.name == "model 1").unwrap();
    assert_eq!(
        model_1.kind,
        SeriesKind::Theory {
            model: ModelKind::One,
            repeat: None
        }
    );
    assert_eq!(model_1.style, Style::Line);
    // the file's three loads and the points refinement added where the curve bends
    assert!(model_1.points.len() >= 3);
    for p in &model_1.points {
        // y is a_r/p*
        let want = statrs::function::erf::erf(2f64.sqrt() * p.x) / p.x;
        let y = p.y.unwrap_or_else(|| panic!("model 1 at p* = {}: {:?}", p.x, p.note));
        assert!(
            (y / want - 1.0).abs() < MODEL1_ERF_REL,
            "p* = {}: {y} against {want}",
            p.x
        );
    }
    let eq18 = data.series.iter().find(|s| s.name.starts_with("eq. (18)")).unwrap();
    assert_eq!(
        (eq18.kind, eq18.style),
        (SeriesKind::ClosedForm { second: false }, Style::Dashed)
    );
    // the values [S] states are points, never a curve
    assert!(data
        .series
        .iter()
        .filter(|s| matches!(s.kind, SeriesKind::Paper { .. }))
        .all(|s| s.style == Style::Points));
}
