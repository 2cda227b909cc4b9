//! Progress on stderr off a terminal: a piped GFMD load cycle writes at least one plain
//! progress line per load (`asperity gfmd: load k/N (…)`), numbered in order, and `--quiet`
//! writes none while stdout is the same.

mod common;

/// A load cycle with adhesion on a 32² map of the sample preset (seconds).
const CYCLE: &[&str] = &[
    "gfmd",
    "--preset",
    "data/samples/sample.toml",
    "--grid",
    "32",
    "--cycle",
    "--from",
    "1e-3",
    "--to",
    "1e-2",
    "--points",
    "3",
    "--format",
    "csv",
];

fn progress_lines(stderr: &str) -> Vec<&str> {
    stderr
        .lines()
        .filter(|l| l.starts_with("asperity gfmd: load "))
        .collect()
}

/// The k of `asperity gfmd: load k/N …` (or `load k (…)` past the planned loads).
fn step_of(line: &str) -> usize {
    let rest = line.trim_start_matches("asperity gfmd: load ");
    let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
    digits.parse().unwrap()
}

#[test]
fn a_piped_cycle_reports_every_load_and_quiet_silences_it() {
    let out = common::asperity(CYCLE);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let rows = stdout.lines().filter(|l| !l.starts_with('#')).count() - 1;
    assert!(rows >= 5, "a cycle of 3 loads has 5 rows and tension: {rows}\n{stdout}");
    let lines = progress_lines(&stderr);
    assert!(
        lines.len() >= rows,
        "{} progress lines for {rows} loads:\n{stderr}",
        lines.len()
    );
    // every load from the first to the last is reported, in order
    let mut steps: Vec<usize> = lines.iter().map(|l| step_of(l)).collect();
    steps.dedup();
    assert_eq!(steps, (1..=steps.len()).collect::<Vec<_>>(), "{stderr}");
    assert!(steps.len() >= rows, "{stderr}");
    assert!(lines[0].contains("loading, p* = 0.001"), "{}", lines[0]);

    let mut quiet = CYCLE.to_vec();
    quiet.push("--quiet");
    let q = common::asperity(&quiet);
    let q_err = String::from_utf8_lossy(&q.stderr);
    assert!(q.status.success(), "{q_err}");
    assert!(progress_lines(&q_err).is_empty(), "--quiet still reports:\n{q_err}");
    assert_eq!(String::from_utf8_lossy(&q.stdout), stdout, "--quiet changes the result");
}
