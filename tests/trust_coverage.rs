//! The trust read-out's band covers what it states: each case of the GFMD reference set is
//! left out in turn and the band the read-out states at each of its loads is computed from the
//! other cases ([`asperity::fit::trust::stated_band`]: their errors, GFMD's standard error and
//! finite-size error); the held-out GFMD a_r must lie within the band around the theory's at
//! [`TRUST_BAND_COVERAGE`] of the points where an error is claimed, in every decade of load,
//! and "no error known" may be said at no more than [`TRUST_UNKNOWN_MAX`] of them. Done for
//! each model's own theory columns (models 1–5 of the small-load set; where a point has none,
//! the column the read-out falls back to).

use asperity::fit::reference_set::{combined_set, ReferencePoint};
use asperity::fit::trust::{stated_band, theory_column};
use asperity::fit::trust_band::Place;
use asperity::theory::cycle::PathBranch;
use asperity::tolerances::{TRUST_BAND_COVERAGE, TRUST_UNKNOWN_MAX};

#[derive(Default, Debug)]
struct Tally {
    points: usize,
    unknown: usize,
    covered: usize,
}

/// The load bands the coverage is required in: one per decade of p*.
const BANDS: [(&str, f64, f64); 3] = [
    ("1e-5 ≤ p* < 1e-4", 1e-5, 1e-4),
    ("1e-4 ≤ p* < 1e-3", 1e-4, 1e-3),
    ("1e-3 ≤ p* ≤ 1e-2", 1e-3, 1.01e-2),
];

/// Per load band ([`BANDS`]): the tally of held-out points.
fn held_out(model: u8) -> [Tally; 3] {
    let column = theory_column(Some(model));
    let set: Vec<&ReferencePoint> = combined_set().iter().collect();
    let same_case = |a: &ReferencePoint, b: &ReferencePoint| {
        a.system == b.system && a.thickness_qr == b.thickness_qr && a.gamma_factor == b.gamma_factor
    };
    let mut tally = [Tally::default(), Tally::default(), Tally::default()];
    for r in set
        .iter()
        .filter(|r| r.branch == PathBranch::Loading && r.p > 0.0 && r.a_r.0 > 0.0)
    {
        let Some((theory, _, _)) = column(r) else { continue };
        let others: Vec<&ReferencePoint> = set.iter().copied().filter(|o| !same_case(o, r)).collect();
        let place = Place {
            p: r.p,
            gamma_glo: r.gamma_glo,
            thickness_qr: r.thickness_qr,
        };
        let (b, _) = stated_band(&others, place, Some(model));
        let Some(k) = BANDS
            .iter()
            .position(|b| r.p >= b.1 * (1.0 - 1e-9) && r.p < b.2 * (1.0 - 1e-9))
        else {
            continue;
        };
        let t = &mut tally[k];
        t.points += 1;
        if !b.known {
            t.unknown += 1;
        } else if (theory / r.a_r.0).ln().abs() <= b.half_width {
            t.covered += 1;
        }
    }
    tally
}

fn check(model: u8) {
    let name = format!("model {model}");
    for ((band_name, _, _), t) in BANDS.iter().zip(held_out(model)) {
        let claimed = t.points - t.unknown;
        let coverage = t.covered as f64 / claimed.max(1) as f64;
        let unknown = t.unknown as f64 / t.points.max(1) as f64;
        eprintln!("{name}, {band_name}: {t:?}: coverage {coverage:.3}, unknown {unknown:.3}");
        assert!(t.points > 10, "{name}, {band_name}: too few points ({t:?})");
        assert!(
            coverage >= TRUST_BAND_COVERAGE,
            "{name}, {band_name}: the band holds {coverage:.3} of held-out points ({t:?})"
        );
        assert!(
            unknown <= TRUST_UNKNOWN_MAX,
            "{name}, {band_name}: no error known at {unknown:.3} of held-out points ({t:?})"
        );
    }
}

#[test]
fn model_3s_band_holds_held_out_gfmd_points() {
    check(3);
}

#[test]
fn model_4s_band_holds_held_out_gfmd_points() {
    check(4);
}

#[test]
fn model_5s_band_holds_held_out_gfmd_points() {
    check(5);
}
