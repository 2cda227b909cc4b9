//! One name per quantity: across the JSON keys of `run`, `sweep` (load and thickness), `gfmd`
//! and `psd` and the CSV columns of `sweep` and `gfmd`, no two distinct names name one quantity
//! (the same words in another order) unless one is the other's documented alias
//! ([`asperity::report::names::ALIASES`]), and an alias beside its preferred name carries the
//! same value.

mod common;

use asperity::report::names::{clashes, preferred, ALIASES};
use common::asperity_here_ok as out;
use std::collections::BTreeSet;

/// Every key of nested objects, arrays entered (each element's keys).
fn names(v: &serde_json::Value, out: &mut BTreeSet<String>) {
    match v {
        serde_json::Value::Object(o) => {
            for (k, x) in o {
                out.insert(k.clone());
                names(x, out);
            }
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| names(x, out)),
        _ => {}
    }
}

/// Every object in `v` holding an alias and its preferred name holds the same value under
/// both; returns how many such pairs it holds.
fn aliases_agree(v: &serde_json::Value, what: &str) -> usize {
    let mut seen = 0;
    match v {
        serde_json::Value::Object(o) => {
            for a in ALIASES {
                if let (Some(x), Some(y)) = (o.get(a.alias), o.get(a.preferred)) {
                    assert_eq!(x, y, "{what}: {} beside {}", a.alias, a.preferred);
                    seen += 1;
                }
            }
            seen += o.values().map(|x| aliases_agree(x, what)).sum::<usize>();
        }
        serde_json::Value::Array(a) => seen += a.iter().map(|x| aliases_agree(x, what)).sum::<usize>(),
        _ => {}
    }
    seen
}

/// The tour's "Jump into contact" scene, inside its hysteresis window: `run` has an unloading
/// branch there, so the alias `unloading_a_r` holds a number.
const JUMP: &[&str] = &[
    "--preset",
    "system-2",
    "--model",
    "3",
    "--thickness",
    "0.1",
    "--gamma",
    "0.1256",
    "--pressure",
    "1e-4",
];

#[test]
fn each_quantity_has_one_preferred_name_across_json_and_csv() {
    let run: serde_json::Value = serde_json::from_str(&out(&[&["run", "--format", "json"], JUMP].concat())).unwrap();
    assert!(run["a_r_unloading"].as_f64().is_some(), "{run}");
    assert!(aliases_agree(&run, "run") >= 2);
    let sweeps = [
        vec![
            "sweep", "--preset", "system-1", "--from", "0.01", "--to", "0.1", "--points", "2",
        ],
        vec![
            "sweep",
            "--preset",
            "system-2",
            "--over",
            "thickness",
            "--from",
            "0.5",
            "--to",
            "1",
            "--points",
            "2",
        ],
    ];
    let gfmd = ["gfmd", "--grid", "32", "--gamma", "0"];
    let psd = ["psd", "tests/fixtures/two_bands.txt"];
    let mut all = BTreeSet::new();
    names(&run, &mut all);
    for args in sweeps.iter().map(|a| a.as_slice()).chain([&gfmd[..], &psd[..]]) {
        let v: serde_json::Value = serde_json::from_str(&out(&[args, &["--format", "json"]].concat())).unwrap();
        aliases_agree(&v, args[0]);
        names(&v, &mut all);
    }
    for args in [&sweeps[0][..], &gfmd[..]] {
        let csv = out(&[args, &["--format", "csv"]].concat());
        let header = csv.lines().find(|l| !l.starts_with('#')).unwrap();
        all.extend(header.split(',').map(str::to_string));
    }
    let list: Vec<&str> = all.iter().map(String::as_str).collect();
    assert!(list.contains(&"a_r_unloading") && list.contains(&"contact_stress_variance"));
    assert_eq!(clashes(&list), Vec::<(&str, &str)>::new(), "one quantity, two names");
    // an alias is never the only name where it appears
    for a in ALIASES.iter().filter(|a| list.contains(&a.alias)) {
        assert!(list.contains(&a.preferred), "{a:?}");
        assert_eq!(preferred(a.alias), a.preferred);
    }
}
