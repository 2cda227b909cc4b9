//! The trust read-out's band covers what it states: each case of the GFMD reference set is
//! left out in turn and the band at each of its loads is computed from the other cases
//! ([`asperity::fit::trust_band::band`]); the held-out GFMD a_r must lie within the band
//! around the theory's at [`TRUST_BAND_COVERAGE`] of the points where an error is claimed,
//! in every load band, and "no error known" may be said at no more than [`TRUST_UNKNOWN_MAX`]
//! of them. Done for the set's theory columns (model 4 on system II, 3 on system I) and for
//! model 5's own columns.

use asperity::fit::reference_set::{reference_set, ReferencePoint};
use asperity::fit::trust_band::{band, Place};
use asperity::theory::cycle::PathBranch;
use asperity::tolerances::{TRUST_BAND_COVERAGE, TRUST_UNKNOWN_MAX};

type Column = fn(&ReferencePoint) -> Option<(f64, f64, u8)>;

fn set_column(r: &ReferencePoint) -> Option<(f64, f64, u8)> {
    (r.theory_a_r > 0.0).then_some((r.theory_a_r, r.theory_mean_gap_rel, r.theory_model))
}

fn model5_column(r: &ReferencePoint) -> Option<(f64, f64, u8)> {
    (r.theory5_a_r > 0.0).then_some((r.theory5_a_r, r.theory5_mean_gap_rel, 5))
}

#[derive(Default, Debug)]
struct Tally {
    points: usize,
    unknown: usize,
    covered: usize,
}

/// Per load band (p* < 1e-3, p* ≥ 1e-3): the tally of held-out points.
fn held_out(column: Column) -> [Tally; 2] {
    let set: Vec<&ReferencePoint> = reference_set().iter().collect();
    let same_case = |a: &ReferencePoint, b: &ReferencePoint| {
        a.system == b.system && a.thickness_qr == b.thickness_qr && a.gamma_factor == b.gamma_factor
    };
    let mut tally = [Tally::default(), Tally::default()];
    for r in set.iter().filter(|r| r.branch == PathBranch::Loading && r.p > 0.0 && r.a_r.0 > 0.0) {
        let Some((theory, _, _)) = column(r) else { continue };
        let others: Vec<&ReferencePoint> = set.iter().copied().filter(|o| !same_case(o, r)).collect();
        let place = Place {
            p: r.p,
            gamma_glo: r.gamma_glo,
            thickness_qr: r.thickness_qr,
        };
        let b = band(&others, place, &column);
        let t = &mut tally[usize::from(r.p >= 1e-3 * (1.0 - 1e-9))];
        t.points += 1;
        if !b.known {
            t.unknown += 1;
        } else if (theory / r.a_r.0).ln().abs() <= b.half_width {
            t.covered += 1;
        }
    }
    tally
}

fn check(name: &str, column: Column) {
    for (band_name, t) in ["p* < 1e-3", "p* ≥ 1e-3"].iter().zip(held_out(column)) {
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
fn the_band_holds_held_out_gfmd_points_of_the_set() {
    check("set's columns", set_column);
}

#[test]
fn model_5s_band_holds_held_out_gfmd_points() {
    check("model 5", model5_column);
}
