//! The library's shape, checked: no import cycle between its modules, no front end's
//! vocabulary in it (no clap, no ratatui, no `--flag` names in messages), no file too long to
//! read.
//!
//! Modules are the files under `src/` (a folder's `mod.rs` is the folder's module). An edge
//! A → B is any `crate::B` path written in A (in `use` or inline), B truncated to a module
//! that exists. Re-export shims (`pub use crate::x` as the only reference) count as edges too,
//! so a cycle cannot hide behind one.

#[path = "support/module_graph.rs"]
mod module_graph;

use module_graph::{code_of, find_cycle, paths_after, resolve, rust_files};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn src_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn module_of(path: &Path) -> String {
    module_graph::module_of(&src_dir(), path)
}

fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let mut files = Vec::new();
    rust_files(&src_dir(), &mut files);
    let modules: BTreeSet<String> = files.iter().map(|f| module_of(f)).collect();
    let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in &files {
        let from = module_of(f);
        let code = code_of(&std::fs::read_to_string(f).unwrap());
        // tests inside a module may reach anywhere; they are not part of the layering
        let code = code.split("#[cfg(test)]").next().unwrap_or("").to_string();
        for path in paths_after(&code, "crate::") {
            // the longest prefix that is a module
            if let Some(to) = resolve(&path, &modules) {
                if to != from && !from.starts_with(&format!("{to}::")) && !to.starts_with(&format!("{from}::")) {
                    g.entry(from.clone()).or_default().insert(to);
                }
            }
        }
    }
    g
}

#[test]
fn the_cycle_finder_finds_a_planted_cycle() {
    let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    g.entry("a".into()).or_default().insert("b".into());
    g.entry("b".into()).or_default().insert("c".into());
    assert_eq!(find_cycle(&g), None);
    g.entry("c".into()).or_default().insert("a".into());
    assert_eq!(find_cycle(&g).map(|c| c.len()), Some(4));
    assert_eq!(
        paths_after(
            "use crate::theory::{gap::X, loads};\nlet y = crate::error::Field::Hurst;",
            "crate::"
        ),
        vec!["theory::gap::X", "theory::loads", "error::Field::Hurst"]
    );
}

#[test]
fn library_modules_form_no_import_cycle() {
    let g = graph();
    assert!(g.contains_key("theory::sweep"), "the scanner found no edges: {g:?}");
    assert!(g["theory::sweep"].contains("theory::gap"));
    if let Some(c) = find_cycle(&g) {
        panic!("import cycle between library modules: {}", c.join(" → "));
    }
}

#[test]
fn library_has_no_front_end_vocabulary() {
    let mut files = Vec::new();
    rust_files(&src_dir(), &mut files);
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for word in ["clap::", "ratatui", "crossterm"] {
                assert!(!code.contains(word), "{}:{}: {word} in the library", f.display(), n + 1);
            }
            // a CLI flag inside a string: errors name a `Field`, each front end renders it
            assert!(
                !line.contains("\"--"),
                "{}:{}: a CLI flag in the library: {line}",
                f.display(),
                n + 1
            );
        }
    }
}

#[test]
fn library_files_stay_readable() {
    // one idea per file: nothing much over 600 lines
    const MAX_LINES: usize = 650;
    let mut files = Vec::new();
    rust_files(&src_dir(), &mut files);
    let long: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let n = std::fs::read_to_string(f).unwrap().lines().count();
            (n > MAX_LINES).then(|| format!("{} ({n} lines)", f.display()))
        })
        .collect();
    assert!(long.is_empty(), "files over {MAX_LINES} lines: {long:?}");
}

#[path = "support/fn_length.rs"]
mod fn_length;

#[test]
fn library_functions_stay_short() {
    let mut files = Vec::new();
    rust_files(&src_dir(), &mut files);
    let root = src_dir().parent().unwrap().to_path_buf();
    let long = fn_length::too_long(&files, |f| f.strip_prefix(&root).unwrap().display().to_string());
    assert!(
        long.is_empty(),
        "functions over {} lines: {long:#?}",
        fn_length::MAX_FN_LINES
    );
}
