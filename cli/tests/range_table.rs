//! One range table for every front end ([`asperity::limits::FIELDS`], ranges by
//! [`asperity::limits::allowed`]): every flag of every command that takes a number names a
//! field of the table (enumerated from the parser itself), and every numeric key of a preset
//! (enumerated from the preset type's own serialisation, every option set) is a field of the
//! table, so that the command line, a preset and Python state one range for one quantity.

mod common;

use asperity::error::Field;
use asperity::limits::{allowed, FIELDS};
use asperity_cli::cli::flags::{self, Kind};

#[test]
fn every_number_flag_names_a_field_of_the_table() {
    let cmd = flags::command();
    let (mut numbers, mut broken) = (0, Vec::new());
    for sub in cmd.get_subcommands() {
        for arg in sub.get_arguments() {
            let name = flags::name_of(arg);
            if !arg.get_action().takes_values() || name == "--help" || name == "help" {
                continue;
            }
            let Some(row) = flags::lookup(sub.get_name(), &name) else {
                broken.push(format!("{} {name}: no row", sub.get_name()));
                continue;
            };
            match (row.kind.field(), &row.kind) {
                // a sweep's ends: the range of the knob --over names
                (Some(Field::SweepFrom | Field::SweepTo), Kind::SweepEnd(_)) => numbers += 1,
                (Some(f), _) if FIELDS.contains(&f) && allowed(&f).is_some() => numbers += 1,
                (Some(f), _) => broken.push(format!("{} {name}: {f} is not in the table", sub.get_name())),
                (None, Kind::Choice | Kind::Text(_) | Kind::InFile | Kind::OutFile(_) | Kind::OutText(_)) => {}
                (None, k) => broken.push(format!("{} {name}: {k:?} names no field", sub.get_name())),
            }
        }
    }
    assert!(numbers >= 60, "only {numbers} number flags");
    assert!(broken.is_empty(), "{}", broken.join("\n"));
}

#[test]
fn every_numeric_preset_key_is_a_field_of_the_table() {
    use asperity::input::preset::{MeasuredSpec, Preset};
    let mut all = Preset::resolve("system-2").unwrap();
    all.surface.rms_height_m = Some(1e-6);
    all.model = common::model_with_every_option();
    all.measured = Some(MeasuredSpec {
        size_m: Some(1e-6),
        q_min_per_m: Some(1e5),
        q_max_per_m: Some(1e8),
        ..MeasuredSpec::default()
    });
    let mut keys = Vec::new();
    common::leaves(&toml::Value::try_from(&all).unwrap(), "", &mut keys);
    // a key whose field is named differently: the measured map's side is the system's size
    let alias = |k: &str| match k {
        "measured.size_m" => Some(Field::SystemSize),
        _ => None,
    };
    let (mut n, mut broken) = (0, Vec::new());
    for (key, v) in &keys {
        if !(v.is_integer() || v.is_float()) {
            continue;
        }
        n += 1;
        let found = FIELDS.iter().find(|f| f.key() == key).cloned().or_else(|| alias(key));
        match found {
            Some(f) if allowed(&f).is_some() => {}
            _ => broken.push(key.clone()),
        }
    }
    assert!(n >= 20, "only {n} numeric keys");
    assert!(
        broken.is_empty(),
        "preset keys without a field of the table: {broken:?}"
    );
}
