//! One name per quantity: the public names (JSON keys, CSV columns, Python attributes) that
//! are kept as aliases of a preferred name, so that output read by earlier scripts stays
//! readable while every quantity has one name to use. Front ends write the alias beside the
//! preferred name with the same value where both belong to one output (GFMD's older names
//! stand alone in its output so far); their tests check that no other two public names name
//! one quantity.

/// A public name kept as an alias of the preferred one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Alias {
    /// The older name, still written (or read) where it was.
    pub alias: &'static str,
    /// The name to use: the same number everywhere it appears.
    pub preferred: &'static str,
    /// Where the alias appears.
    pub places: &'static str,
}

/// Every alias of the public interface.
pub const ALIASES: &[Alias] = &[
    Alias {
        alias: "unloading_a_r",
        preferred: "a_r_unloading",
        places: "asperity run --format json; Python's evaluate() result",
    },
    Alias {
        alias: "mean_gap_reversible_rel",
        preferred: "mean_gap_upper_rel",
        places: "each entry of branches in asperity run --format json",
    },
    Alias {
        alias: "solve_elapsed_s",
        preferred: "elapsed_solve_s",
        places: "asperity gfmd --format json (the preferred name is run's; gfmd does not yet write it beside)",
    },
    Alias {
        alias: "theory_a_r",
        preferred: "a_r_theory",
        places:
            "asperity gfmd --format csv (the preferred name is run's trust.nearest; gfmd does not yet write it beside)",
    },
    Alias {
        alias: "theory_mean_gap_rel",
        preferred: "mean_gap_rel_theory",
        places:
            "asperity gfmd --format csv (the preferred name is run's trust.nearest; gfmd does not yet write it beside)",
    },
    Alias {
        alias: "variance",
        preferred: "contact_stress_variance",
        places: "Python's evaluate() result",
    },
];

/// The preferred name of `name`: itself unless it is an alias.
pub fn preferred(name: &str) -> &str {
    ALIASES.iter().find(|a| a.alias == name).map_or(name, |a| a.preferred)
}

/// The words of a name, sorted (`unloading_a_r` and `a_r_unloading` give the same): two public
/// names with the same words name one quantity, and must be a name and its alias.
pub fn words(name: &str) -> Vec<&str> {
    let mut w: Vec<&str> = name.split('_').filter(|w| !w.is_empty()).collect();
    w.sort_unstable();
    w
}

/// The pairs of distinct names in `names` that share their words (see [`words`]) without one
/// being the other's alias: the quantities with two names.
pub fn clashes<'a>(names: &[&'a str]) -> Vec<(&'a str, &'a str)> {
    let mut out = Vec::new();
    for (i, a) in names.iter().enumerate() {
        for b in &names[i + 1..] {
            if a != b && words(a) == words(b) && preferred(a) != preferred(b) {
                out.push((*a, *b));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_alias_is_the_only_second_name_of_a_quantity() {
        assert_eq!(preferred("unloading_a_r"), "a_r_unloading");
        assert_eq!(preferred("a_r"), "a_r");
        assert!(clashes(&["unloading_a_r", "a_r_unloading", "a_r"]).is_empty());
        assert_eq!(
            clashes(&["gap_mean_rel", "mean_gap_rel"]),
            [("gap_mean_rel", "mean_gap_rel")]
        );
        // every alias names a different word set or is listed; no alias is itself preferred
        for a in ALIASES {
            assert!(ALIASES.iter().all(|b| b.alias != a.preferred), "{a:?}");
        }
    }
}
