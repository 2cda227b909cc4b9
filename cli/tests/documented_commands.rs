//! Every `asperity …` command in the ```` ```sh ```` blocks of README.md and docs/*.md runs as
//! written and exits 0: each runs through `sh -c` (pipes and redirections as a reader would
//! type them) with the built binary first on the PATH, in document order, in a scratch folder
//! that holds the repository's `data/`, `presets/`, `figures/` and `tours/` (links), so that
//! relative paths read what the repository ships and the files the commands write (`fig7.svg`,
//! `gauged.toml`, …) land in the scratch folder, where a later command can read them, and not
//! in the repository. A command shown in two documents runs once. The interactive ones (the
//! explorer, the tour) are skipped by kind; every other skip (MPI, `bench --quick`, which
//! cli_bench.rs runs) is listed in [`SKIPPED`] with its reason: a skipped command not in the
//! list, or a listed one the docs no longer have, fails the test, so nothing is skipped
//! silently.
//!
//! Shown output is checked too: the text chart of figure 7 in docs/figures.md is what
//! `asperity figure 7 --width 92 --height 26` prints; the sample maps and PSD table under
//! data/samples/ are what the commands in data/samples/README.md write.
//!
//! Each command's wall time is printed (`cargo test -- --nocapture`): the examples are sized
//! to run in seconds on 2 cores; the docs state the full-size times beside them.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// The documented commands not run here, each with the reason.
const SKIPPED: &[(&str, &str)] = &[
    (
        "asperity bench --quick",
        "cli/tests/cli_bench.rs runs the same command (40 s) and checks its bounds",
    ),
    (
        "mpirun -np 4 target/release/asperity gfmd --preset system-2 --grid 1024",
        "MPI",
    ),
    (
        "mpirun -np 2 target/release/asperity gfmd --preset system-2 --from 1e-3 --to 0.1 --points 6",
        "MPI",
    ),
    (
        "mpirun -np 2 target/release/asperity gfmd --preset system-2 --cycle --from 1e-3 --to 1e-2 --points 3",
        "MPI",
    ),
];

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The documents whose ```sh blocks are read: README.md and docs/*.md, in name order.
fn documents() -> Vec<PathBuf> {
    let mut docs: Vec<PathBuf> = std::fs::read_dir(repo().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    docs.insert(0, repo().join("README.md"));
    docs
}

/// A shell line without its trailing comment (` # …` outside quotes).
fn strip_comment(line: &str) -> &str {
    let (mut single, mut double) = (false, false);
    let mut prev = ' ';
    for (i, c) in line.char_indices() {
        match c {
            '\'' if !double => single = !single,
            '"' if !single => double = !double,
            '#' if !single && !double && prev.is_whitespace() => return line[..i].trim_end(),
            _ => {}
        }
        prev = c;
    }
    line.trim_end()
}

/// The commands of the ```sh blocks of `text`: continuation lines joined, comments dropped.
fn sh_commands(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_sh = false;
    let mut pending = String::new();
    for line in text.lines() {
        let t = line.trim();
        if t.starts_with("```") {
            in_sh = !in_sh && t == "```sh";
            continue;
        }
        if !in_sh {
            continue;
        }
        let l = strip_comment(line);
        if let Some(head) = l.strip_suffix('\\') {
            pending.push_str(head.trim());
            pending.push(' ');
            continue;
        }
        pending.push_str(l.trim());
        let cmd = std::mem::take(&mut pending);
        if !cmd.is_empty() {
            out.push(cmd.split_whitespace().collect::<Vec<_>>().join(" "));
        }
    }
    out
}

/// Whether `cmd` runs asperity (directly, or as `target/…/asperity` under mpirun).
fn is_asperity(cmd: &str) -> bool {
    cmd == "asperity" || cmd.starts_with("asperity ") || cmd.contains("/asperity ")
}

/// Why a command is not run here (None: it is run).
fn skip_reason(cmd: &str) -> Option<&'static str> {
    if cmd.starts_with("mpirun") {
        return Some("MPI");
    }
    if let Some((_, why)) = SKIPPED.iter().find(|(c, _)| *c == cmd) {
        return Some(why);
    }
    match cmd.split_whitespace().nth(1) {
        None => Some("the explorer (interactive)"),
        Some("tui") | Some("tour") => Some("the explorer (interactive)"),
        Some(_) => None,
    }
}

/// Every documented asperity command, with the document it is in.
fn documented() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for doc in documents() {
        let name = doc.file_name().unwrap().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&doc).unwrap();
        for cmd in sh_commands(&text) {
            if is_asperity(&cmd) {
                out.push((name.clone(), cmd));
            }
        }
    }
    out
}

/// A scratch folder with links to what the repository ships.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-docs-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    for shipped in ["data", "presets", "figures", "tours"] {
        let target = repo().join(shipped).canonicalize().unwrap();
        #[cfg(unix)]
        std::os::unix::fs::symlink(&target, d.join(shipped)).unwrap();
        #[cfg(not(unix))]
        let _ = target;
    }
    d
}

/// The PATH with the built binary's folder first.
fn path_with_binary() -> std::ffi::OsString {
    let bin = Path::new(env!("CARGO_BIN_EXE_asperity"))
        .parent()
        .unwrap()
        .to_path_buf();
    let mut dirs = vec![bin];
    if let Some(p) = std::env::var_os("PATH") {
        dirs.extend(std::env::split_paths(&p));
    }
    std::env::join_paths(dirs).unwrap()
}

/// Runs `cmd` with `sh -c` in `dir`; returns (exit code, stdout, stderr, seconds).
fn shell(cmd: &str, dir: &Path) -> (i32, String, String, f64) {
    let t0 = Instant::now();
    let out = Command::new("sh")
        .arg("-c")
        .arg(cmd)
        .current_dir(dir)
        .env("PATH", path_with_binary())
        .output()
        .expect("sh runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        t0.elapsed().as_secs_f64(),
    )
}

#[test]
fn the_extractor_joins_continuations_and_drops_comments() {
    let text = "intro\n```sh\nasperity run --preset a   # one scene\nasperity gauge --fit w0 \\\n     --format json\n```\n```text\nasperity not a command\n```\n";
    assert_eq!(
        sh_commands(text),
        ["asperity run --preset a", "asperity gauge --fit w0 --format json"]
    );
    assert_eq!(
        strip_comment("asperity x --title 'a # b'  # c"),
        "asperity x --title 'a # b'"
    );
}

#[test]
#[cfg(unix)]
fn every_documented_command_runs_as_written() {
    let commands = documented();
    let skipped: Vec<&str> = commands
        .iter()
        .filter(|(_, c)| skip_reason(c).is_some())
        .map(|(_, c)| c.as_str())
        .collect();
    let listed: Vec<&str> = SKIPPED.iter().map(|(c, _)| *c).collect();
    // the interactive ones are skipped by kind; every other skip is listed, and every listed
    // one is still documented
    for c in &skipped {
        let interactive = skip_reason(c) == Some("the explorer (interactive)");
        assert!(
            interactive || listed.contains(c),
            "skipped but not listed in SKIPPED: {c}"
        );
    }
    for c in &listed {
        assert!(skipped.contains(c), "listed in SKIPPED but not documented: {c}");
    }
    let dir = scratch("run");
    let mut failures = Vec::new();
    let mut report = Vec::new();
    let mut ran = 0;
    let mut seen: Vec<&str> = Vec::new();
    for (doc, cmd) in &commands {
        if let Some(why) = skip_reason(cmd) {
            report.push(format!("  skipped ({why}): {cmd}"));
            continue;
        }
        // a command shown in two documents runs once
        if seen.contains(&cmd.as_str()) {
            report.push(format!("  ran above: {doc}: {cmd}"));
            continue;
        }
        seen.push(cmd);
        let (code, _out, err, s) = shell(cmd, &dir);
        ran += 1;
        report.push(format!("{s:7.2} s  {doc}: {cmd}"));
        if code != 0 {
            let last = err.lines().last().unwrap_or("").to_string();
            failures.push(format!("{doc}: `{cmd}` exited {code}: {last}"));
        }
    }
    eprintln!(
        "{} documented commands ({} distinct), {ran} run, {} skipped:\n{}",
        commands.len(),
        commands
            .iter()
            .map(|(_, c)| c.as_str())
            .collect::<std::collections::BTreeSet<_>>()
            .len(),
        skipped.len(),
        report.join("\n")
    );
    assert!(ran >= 25, "only {ran} commands run");
    assert!(
        failures.is_empty(),
        "documented commands that fail:\n{}",
        failures.join("\n")
    );
}

/// The text block that follows the line holding `marker` in `text`.
fn text_block_after(text: &str, marker: &str) -> String {
    let start = text.find(marker).unwrap_or_else(|| panic!("{marker} not found"));
    let rest = &text[start..];
    let open = rest.find("```text\n").expect("a text block follows") + "```text\n".len();
    let close = rest[open..].find("\n```").expect("the block ends");
    rest[open..open + close].to_string()
}

fn trimmed_lines(s: &str) -> Vec<String> {
    s.trim_end().lines().map(|l| l.trim_end().to_string()).collect()
}

#[test]
#[cfg(unix)]
fn the_figure_7_chart_in_the_docs_is_what_the_command_prints() {
    let cmd = "asperity figure 7 --width 92 --height 26";
    let doc = std::fs::read_to_string(repo().join("docs/figures.md")).unwrap();
    let shown = text_block_after(&doc, &format!("`{cmd}`"));
    let (code, out, err, _) = shell(cmd, &scratch("fig7"));
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        trimmed_lines(&shown),
        trimmed_lines(&out),
        "docs/figures.md shows another chart than `{cmd}` prints:\n{out}"
    );
}

#[test]
#[cfg(unix)]
fn the_samples_are_what_their_readme_says_writes_them() {
    let readme = std::fs::read_to_string(repo().join("data/samples/README.md")).unwrap();
    let dir = scratch("samples");
    let fresh = dir.join("fresh");
    std::fs::create_dir_all(&fresh).unwrap();
    let commands = sh_commands(&readme);
    assert!(commands.len() >= 4, "{commands:?}");
    let mut written = Vec::new();
    for cmd in &commands {
        // the same command, writing into the scratch folder and reading what it wrote there
        let here = cmd.replace("data/samples/", "fresh/");
        let (code, _, err, _) = shell(&here, &dir);
        assert_eq!(code, 0, "{here}: {err}");
        written.extend(
            here.split_whitespace()
                .filter(|w| w.starts_with("fresh/"))
                .map(|w| w.trim_start_matches("fresh/").to_string()),
        );
    }
    written.sort();
    written.dedup();
    for name in ["map.npy", "map.gsf", "map.txt", "psd.csv"] {
        assert!(
            written.iter().any(|w| w == name),
            "{name} is not written by data/samples/README.md"
        );
    }
    for name in &written {
        let shipped = std::fs::read(repo().join("data/samples").join(name)).unwrap();
        let made = std::fs::read(fresh.join(name)).unwrap();
        assert!(
            shipped == made,
            "data/samples/{name} is not what data/samples/README.md writes"
        );
    }
    let total: u64 = std::fs::read_dir(repo().join("data/samples"))
        .unwrap()
        .map(|e| e.unwrap().metadata().unwrap().len())
        .sum();
    eprintln!("data/samples: {total} bytes");
}
