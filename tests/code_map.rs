//! The code map in docs/README.md, checked against the tree: every `.rs` file under `src/`,
//! `cli/src/` and `python/src/` is named in it, and every file it names exists.
//!
//! The map is a set of ```` ```text ```` blocks whose first line is a root (`src/`,
//! `cli/src/`, `python/src/`). Inside a block an entry is a line indented by two spaces per
//! level whose first word ends in `/` (a folder, its entries one level deeper) or `.rs` (a
//! file); a line indented deeper than the next level is a description's continuation.

#[path = "support/module_graph.rs"]
mod module_graph;

use std::collections::BTreeSet;
use std::path::PathBuf;

const ROOTS: [&str; 3] = ["src/", "cli/src/", "python/src/"];

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The files a code-map block names, as paths relative to the repository root.
fn parse_block(lines: &[&str], out: &mut BTreeSet<String>) {
    let root = lines[0].trim();
    // the folders open at each level (index 0: the root)
    let mut stack: Vec<String> = vec![root.to_string()];
    for line in &lines[1..] {
        let indent = line.len() - line.trim_start().len();
        let word = line.split_whitespace().next().unwrap_or("");
        let is_entry = indent % 2 == 0
            && indent >= 2
            && indent / 2 <= stack.len()
            && (word.ends_with(".rs") || word.ends_with('/'))
            && word.chars().all(|c| c.is_ascii_alphanumeric() || "_./".contains(c));
        if !is_entry {
            continue;
        }
        let level = indent / 2;
        stack.truncate(level);
        let path = format!("{}{word}", stack.concat());
        if word.ends_with('/') {
            stack.push(word.to_string());
        } else {
            assert!(
                out.insert(path.clone()),
                "docs/README.md names {path} twice in its code map"
            );
        }
    }
}

/// The files docs/README.md's code map names, and the roots it has a block for.
fn mapped() -> (BTreeSet<String>, BTreeSet<String>) {
    let text = std::fs::read_to_string(repo().join("docs/README.md")).unwrap();
    let mut files = BTreeSet::new();
    let mut roots = BTreeSet::new();
    let mut block: Option<Vec<&str>> = None;
    for line in text.lines() {
        match &mut block {
            None if line.trim() == "```text" => block = Some(Vec::new()),
            None => {}
            Some(b) if line.trim() == "```" => {
                if b.first().is_some_and(|r| ROOTS.contains(&r.trim())) {
                    roots.insert(b[0].trim().to_string());
                    parse_block(b, &mut files);
                }
                block = None;
            }
            Some(b) => b.push(line),
        }
    }
    (files, roots)
}

#[test]
fn the_code_map_names_every_source_file_and_no_other() {
    let (named, roots) = mapped();
    assert_eq!(
        roots,
        ROOTS.iter().map(|r| r.to_string()).collect(),
        "docs/README.md has a code-map block for each source tree"
    );
    let mut files = Vec::new();
    for r in ROOTS {
        module_graph::rust_files(&repo().join(r), &mut files);
    }
    // as paths relative to the repository root, with `/`
    let tree: BTreeSet<String> = files
        .iter()
        .map(|p| p.strip_prefix(repo()).unwrap().to_string_lossy().replace('\\', "/"))
        .collect();
    let missing: Vec<_> = tree.difference(&named).collect();
    let stale: Vec<_> = named.difference(&tree).collect();
    assert!(
        missing.is_empty(),
        "source files the code map in docs/README.md leaves out: {missing:?}"
    );
    assert!(
        stale.is_empty(),
        "files the code map in docs/README.md names that do not exist: {stale:?}"
    );
    // the parser reads the map, not nothing: the whole tree is there
    assert!(named.len() >= 150, "{} files named", named.len());
}

#[test]
fn the_parser_reads_folders_files_and_continuations() {
    let block = [
        "src/",
        "  a.rs             one",
        "  b/               a folder",
        "    c.rs             two, with",
        "                     d.rs, a continuation",
        "    e/               deeper",
        "      f.rs             three",
        "  g.rs             back at the top",
    ];
    let mut out = BTreeSet::new();
    parse_block(&block, &mut out);
    let want: BTreeSet<String> = ["src/a.rs", "src/b/c.rs", "src/b/e/f.rs", "src/g.rs"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(out, want);
}
