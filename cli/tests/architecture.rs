//! The binary crate's shape, checked (the library's is checked by `tests/architecture.rs` at the
//! top): no import cycle between its modules, no file too long to read, and an explorer that
//! draws but never computes physics.
//!
//! Modules are the files under `cli/src/` (a folder's `mod.rs` is the folder's module). An
//! edge A → B is any `crate::B` or `super::B` path written in A's code (comments and
//! `#[cfg(test)]` modules and `*_tests.rs` files left out), B truncated to the longest module that exists; a `super::x`
//! that names no module is an edge to the parent module itself.

#[path = "../../tests/support/module_graph.rs"]
mod module_graph;

use module_graph::{find_cycle, paths_after, resolve, rust_files};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Longest file of the binary crate (lines).
const MAX_LINES: usize = 600;

/// The explorer's modules that may call the engine (the theory and GFMD jobs and the code
/// that turns their results into plain data); every other explorer module only draws,
/// steps knobs or writes files.
const COMPUTE: [&str; 4] = [
    "tui::effects::worker",
    "tui::effects::engine",
    "tui::base::data",
    "tui::base::gfmd_view",
];

/// The explorer's folders, lowest first (their rank): the base is what the state is made of
/// (the worker protocol, plain data, tours, the key table); the model is the state, plain
/// data; the charts are built from it; the update, the view and the effects each read the model
/// (and the charts) and never one another; the loop (`tui` itself, `tui::drive`, `tui::trace`)
/// is above them all. A module may import its own folder and folders of a lower rank only.
const LAYERS: [(&str, u8); 6] = [
    ("tui::base", 0),
    ("tui::model", 1),
    ("tui::charts", 2),
    ("tui::update", 3),
    ("tui::view", 3),
    ("tui::effects", 3),
];

/// The folder of an explorer module and its rank (the loop's modules rank above every folder).
fn layer_of(m: &str) -> Option<(&'static str, u8)> {
    if m != "tui" && !m.starts_with("tui::") {
        return None;
    }
    let found = LAYERS
        .iter()
        .find(|(f, _)| m == *f || m.starts_with(&format!("{f}::")))
        .copied();
    Some(found.unwrap_or(("tui", u8::MAX)))
}

/// The edges of `edges` that point to another folder of the same or a higher rank.
fn wrong_arrows(edges: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    let mut out = Vec::new();
    for (a, targets) in edges {
        let Some((fa, ra)) = layer_of(a) else { continue };
        for b in targets {
            let Some((fb, rb)) = layer_of(b) else { continue };
            if fa != fb && rb >= ra {
                out.push(format!("{a} → {b}"));
            }
        }
    }
    out
}

fn src_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// `src/tui/app.rs` → "tui::app"; `src/tui/mod.rs` → "tui"; `src/lib.rs`, `src/main.rs` → "".
fn module_of(path: &Path) -> String {
    module_graph::module_of(&src_dir(), path)
}

/// Code without comments and without the trailing `#[cfg(test)] mod tests` (tests may use
/// anything).
fn code_of(text: &str) -> String {
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => text,
    };
    module_graph::code_of(text)
}

struct Crate {
    files: BTreeMap<String, (PathBuf, String)>,
    edges: BTreeMap<String, BTreeSet<String>>,
}

fn load() -> Crate {
    let mut paths = Vec::new();
    rust_files(&src_dir(), &mut paths);
    let mut files = BTreeMap::new();
    for p in paths {
        let text = std::fs::read_to_string(&p).unwrap();
        // a module's tests in their own file (`#[path = "x_tests.rs"] mod tests;`) may use
        // anything, like an inline `mod tests`; its length still counts
        if p.to_string_lossy().ends_with("_tests.rs") {
            let text = format!(
                "#[cfg(test)]\nmod tests {{}}\n// {} lines\n{}",
                text.lines().count(),
                "\n".repeat(text.lines().count())
            );
            files.insert(module_of(&p), (p, text));
            continue;
        }
        files.insert(module_of(&p), (p, text));
    }
    let modules: BTreeSet<String> = files.keys().cloned().collect();
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (m, (path, text)) in &files {
        let code = code_of(text);
        let is_dir_module = path.file_name().is_some_and(|f| f == "mod.rs" || f == "lib.rs");
        // `super` of a file module is its folder's module; of a mod.rs, the folder above
        let parent = {
            let mut parts: Vec<&str> = m.split("::").filter(|s| !s.is_empty()).collect();
            if !is_dir_module || !parts.is_empty() {
                parts.pop();
            }
            parts.join("::")
        };
        let mut targets = BTreeSet::new();
        for p in paths_after(&code, "crate::") {
            if let Some(t) = resolve(&p, &modules) {
                targets.insert(t);
            }
        }
        for p in paths_after(&code, "super::") {
            let full = if parent.is_empty() {
                p.clone()
            } else {
                format!("{parent}::{p}")
            };
            match resolve(&full, &modules) {
                Some(t) if t != parent || p.is_empty() => {
                    targets.insert(t);
                }
                _ => {
                    targets.insert(parent.clone());
                }
            }
        }
        targets.remove(m);
        edges.insert(m.clone(), targets);
    }
    Crate { files, edges }
}

#[test]
fn no_import_cycle_between_the_modules_of_the_binary_crate() {
    let c = load();
    assert!(c.edges.len() > 20, "found only {} modules", c.edges.len());
    // the explorer's layers are edges of the graph
    assert!(c.edges["tui::update"].contains("tui::model::app"));
    assert!(c.edges["tui::view"].contains("tui::charts"));
    if let Some(cycle) = find_cycle(&c.edges) {
        panic!("import cycle: {}", cycle.join(" → "));
    }
}

#[test]
fn the_explorer_s_arrows_point_down_its_folders() {
    let c = load();
    for (f, _) in LAYERS {
        assert!(c.files.contains_key(f), "no folder {f}");
    }
    assert!(c.edges["tui::view"].contains("tui::model::app"));
    assert!(c.edges["tui::effects::files"].contains("tui::effects::export"));
    let wrong = wrong_arrows(&c.edges);
    assert!(
        wrong.is_empty(),
        "arrows up or sideways between the explorer's folders: {wrong:#?}"
    );
}

#[test]
fn the_checker_sees_an_arrow_up_or_sideways() {
    let mut e: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    e.insert("tui::model::app".into(), ["tui::model::knobs".to_string()].into());
    e.insert(
        "tui::view".into(),
        ["tui::model::app".to_string(), "tui::charts".to_string()].into(),
    );
    e.insert("tui".into(), ["tui::update".to_string()].into());
    assert!(wrong_arrows(&e).is_empty());
    e.insert("tui::model::knobs".into(), ["tui::update::turn".to_string()].into());
    e.insert(
        "tui::update".into(),
        ["tui::view::layout".to_string(), "tui::drive".to_string()].into(),
    );
    assert_eq!(
        wrong_arrows(&e),
        [
            "tui::model::knobs → tui::update::turn",
            "tui::update → tui::drive",
            "tui::update → tui::view::layout"
        ]
    );
}

#[test]
fn the_checker_sees_a_cycle_when_there_is_one() {
    let mut e: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    e.insert("a".into(), ["b".to_string()].into());
    e.insert("b".into(), ["c".to_string()].into());
    e.insert("c".into(), ["a".to_string()].into());
    assert_eq!(find_cycle(&e).unwrap(), ["a", "b", "c", "a"]);
    e.insert("c".into(), BTreeSet::new());
    assert!(find_cycle(&e).is_none());
    let modules: BTreeSet<String> = ["tui".into(), "tui::app".into()].into();
    assert_eq!(resolve("tui::app::App", &modules).as_deref(), Some("tui::app"));
    assert_eq!(
        paths_after("use super::{state::App, view};", "super::"),
        ["state::App", "view"]
    );
}

#[test]
fn no_file_of_the_binary_crate_is_longer_than_600_lines() {
    let c = load();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    let mut long = Vec::new();
    for (p, t) in c.files.values() {
        let rel = p.strip_prefix(root).unwrap().to_string_lossy().replace('\\', "/");
        let n = t.lines().count();
        if n > MAX_LINES {
            long.push(format!("{rel} ({n} lines)"));
        }
    }
    assert!(long.is_empty(), "files over {MAX_LINES} lines: {}", long.join(", "));
}

#[test]
fn the_explorer_draws_but_never_computes_physics() {
    let c = load();
    let mut seen = 0;
    for (m, (path, text)) in &c.files {
        if !m.starts_with("tui") {
            continue;
        }
        seen += 1;
        if COMPUTE.contains(&m.as_str()) {
            continue;
        }
        let code = code_of(text);
        for engine in [
            "asperity::theory",
            "asperity::gfmd",
            "asperity::elastic",
            "asperity::numerics",
        ] {
            assert!(
                !code.contains(engine),
                "{} uses {engine}: only {COMPUTE:?} may call the engine",
                path.display()
            );
        }
    }
    assert!(seen >= 10, "{seen} explorer modules");
}

#[path = "../../tests/support/fn_length.rs"]
mod fn_length;

#[test]
fn functions_of_the_binary_crate_stay_short() {
    let mut files = Vec::new();
    rust_files(&src_dir(), &mut files);
    let files = files.iter().filter(|f| !f.to_string_lossy().ends_with("_tests.rs"));
    let long = fn_length::too_long(files, module_of);
    assert!(
        long.is_empty(),
        "functions over {} lines: {long:#?}",
        fn_length::MAX_FN_LINES
    );
}

/// The pure parts of the explorer (the state, the update, the view and the chart builders)
/// read no clock and no file and start no thread: time enters as `Msg::Clock`, files as the
/// messages of the effects, and the effects run the threads.
#[test]
fn update_and_view_read_no_clock_and_no_file() {
    const IMPURE: [&str; 12] = [
        "Instant::now",
        ".elapsed()",
        "SystemTime",
        "std::fs",
        "File::",
        ".is_file()",
        "read_dir",
        "list_available",
        "::resolve(",
        "read_text",
        "thread::",
        "std::env",
    ];
    let c = load();
    let mut seen = 0;
    let mut found = Vec::new();
    for (m, (path, text)) in &c.files {
        let pure = ["tui::model", "tui::update", "tui::view", "tui::charts"]
            .iter()
            .any(|p| m == p || m.starts_with(&format!("{p}::")));
        if !pure || m.ends_with("_tests") {
            continue;
        }
        seen += 1;
        let code = code_of(text);
        for bad in IMPURE {
            if code.contains(bad) {
                found.push(format!("{} uses {bad}", path.display()));
            }
        }
    }
    assert!(
        seen > 30,
        "only {seen} files of the model, update, view and charts read"
    );
    assert!(found.is_empty(), "{}", found.join("\n"));
}
