//! End to end: the real binary in a real pseudo-terminal (tmux). Starts the explorer, changes
//! p*, switches the model, opens and closes the help, quits, and checks the screen and the
//! exit status. Skipped, with a message, when tmux is not installed. Also: the headless
//! behaviour (stdout not a terminal, bad preset).

use std::process::Command;
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_asperity");

struct Tmux {
    socket: String,
}

impl Tmux {
    /// A detached 120×40 session on its own socket running the explorer (with `env` before
    /// the command) in `dir`, then printing its exit status.
    fn start(name: &str, dir: &std::path::Path, env: &str) -> Tmux {
        Tmux::start_with(name, dir, env, "tui --preset system-1")
    }

    /// Like [`Tmux::start`] with other arguments of the binary.
    fn start_with(name: &str, dir: &std::path::Path, env: &str, args: &str) -> Tmux {
        let t = Tmux {
            socket: format!("asperity-e2e-{name}-{}", std::process::id()),
        };
        // after the explorer: its exit status and whether the tty is back in canonical mode
        let command =
            format!("{env} {BIN} {args}; echo EXIT=$?; stty -a | grep -o -- '-*icanon' | sed 's/^/TTY=/'; sleep 60");
        let out = t.cmd(&[
            "new-session",
            "-d",
            "-x",
            "120",
            "-y",
            "40",
            "-s",
            "main",
            "-c",
            dir.to_str().unwrap(),
            &command,
        ]);
        assert!(out.status.success(), "tmux: {}", String::from_utf8_lossy(&out.stderr));
        t
    }

    fn cmd(&self, args: &[&str]) -> std::process::Output {
        Command::new("tmux")
            .arg("-u")
            .arg("-L")
            .arg(&self.socket)
            .args(args)
            .output()
            .expect("run tmux")
    }

    fn screen(&self) -> String {
        String::from_utf8_lossy(&self.cmd(&["capture-pane", "-p", "-t", "main"]).stdout).into_owned()
    }

    fn keys(&self, keys: &[&str]) {
        let mut args = vec!["send-keys", "-t", "main"];
        args.extend_from_slice(keys);
        assert!(self.cmd(&args).status.success());
    }

    /// Polls the screen until `pred` holds (10 s at most); returns the screen.
    fn wait(&self, what: &str, pred: impl Fn(&str) -> bool) -> String {
        let t0 = Instant::now();
        loop {
            let s = self.screen();
            if pred(&s) {
                return s;
            }
            if t0.elapsed() > Duration::from_secs(10) {
                panic!("timed out waiting for {what}; screen:\n{s}");
            }
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}

/// A frame that shows a solved point: "converged" (adhesionless) or the adhesive branch.
fn solved(s: &str) -> bool {
    s.contains("converged") || s.contains("loading (")
}

impl Drop for Tmux {
    fn drop(&mut self) {
        let _ = self.cmd(&["kill-server"]);
    }
}

fn have_tmux() -> bool {
    Command::new("tmux")
        .arg("-V")
        .output()
        .is_ok_and(|o| o.status.success())
}

#[test]
fn explorer_in_tmux() {
    if !have_tmux() {
        eprintln!("SKIPPED explorer_in_tmux: tmux is not installed (apt-get install tmux)");
        return;
    }
    let dir = std::env::temp_dir().join(format!("asperity-e2e-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let t = Tmux::start("main", &dir, "");
    let s = t.wait("the first frame with results", |s| s.contains("a_r(p*)") && solved(s));
    assert!(s.contains("system-1") && s.contains("model 3"), "{s}");
    // colour by default (the NO_COLOR test checks the opposite)
    let styled = String::from_utf8_lossy(&t.cmd(&["capture-pane", "-e", "-p", "-t", "main"]).stdout).into_owned();
    assert!(styled.contains("[38;"), "{styled}");

    // p* is selected: one fine step up, 10^(-1.95)
    t.keys(&["Right"]);
    t.wait("p* = 0.01122", |s| s.contains("0.01122") && solved(s));

    // cycle the model
    t.keys(&["m"]);
    t.wait("model 4", |s| s.contains("model 4"));

    // help from the key table, any key closes it
    t.keys(&["?"]);
    t.wait("the help", |s| {
        s.contains("previous parameter") && s.contains("cycle model")
    });
    t.keys(&["x"]);
    t.wait("the help to close", |s| !s.contains("previous parameter"));

    // typing a value
    t.keys(&["5", "e", "-", "3", "Enter"]);
    t.wait("p* = 0.005", |s| s.contains("0.005000"));

    // export writes into the working directory
    t.keys(&["e"]);
    t.wait("the export paths", |s| s.contains("exported"));
    assert!(dir.join("asperity-system-1-1.toml").is_file());
    assert!(dir.join("asperity-system-1-1-pr.csv").is_file());

    t.keys(&["q"]);
    let s = t.wait("a clean exit", |s| s.contains("TTY="));
    assert!(s.contains("EXIT=0") && s.contains("TTY=icanon"), "{s}");
    // the alternate screen is gone: the explorer's frame is no longer visible
    assert!(!s.contains("parameters"), "{s}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn no_color_and_too_small_in_tmux() {
    if !have_tmux() {
        eprintln!("SKIPPED no_color_and_too_small_in_tmux: tmux is not installed");
        return;
    }
    let t = Tmux::start("nocolor", &std::env::temp_dir(), "NO_COLOR=1");
    t.wait("the first frame", solved);
    let styled = String::from_utf8_lossy(&t.cmd(&["capture-pane", "-e", "-p", "-t", "main"]).stdout).into_owned();
    assert!(solved(&styled), "{styled}");
    assert!(!styled.contains("[38;"), "NO_COLOR: no foreground colours\n{styled}");
    t.cmd(&["resize-window", "-t", "main", "-x", "50", "-y", "15"]);
    t.wait("the too-small screen", |s| {
        s.contains("terminal too small") && s.contains("other keys wait")
    });
    // keys the screen does not offer do nothing unseen: no tour, no zoom, no typed value
    t.keys(&["t", "z", "5"]);
    t.cmd(&["resize-window", "-t", "main", "-x", "120", "-y", "40"]);
    let acted = |s: &str| s.contains("tour 1/") || s.contains("z: all panels") || s.contains("Enter applies");
    let s = t.wait("the explorer again", |s| solved(s) || acted(s));
    assert!(solved(&s) && !acted(&s), "{s}");
    assert!(
        !s.contains("tour 1/") && !s.contains("z: all panels") && !s.contains("Enter applies"),
        "{s}"
    );
    t.keys(&["C-c"]);
    let s = t.wait("a clean exit", |s| s.contains("EXIT="));
    assert!(s.contains("EXIT=0"), "{s}");
}

#[test]
fn terminal_restored_after_a_panic() {
    if !have_tmux() {
        eprintln!("SKIPPED terminal_restored_after_a_panic: tmux is not installed");
        return;
    }
    let t = Tmux::start("panic", &std::env::temp_dir(), "ASPERITY_PANIC_KEY=Z");
    t.wait("the first frame", solved);
    t.keys(&["Z"]);
    let s = t.wait("the exit", |s| s.contains("TTY="));
    assert!(s.contains("EXIT=101"), "a panic exits with 101\n{s}");
    assert!(s.contains("TTY=icanon"), "raw mode is off again\n{s}");
    assert!(
        s.contains("ASPERITY_PANIC_KEY pressed"),
        "the panic message is visible\n{s}"
    );
    assert!(!s.contains("parameters"), "the alternate screen is gone\n{s}");
}

#[test]
fn a_worker_fault_is_shown_and_q_quits() {
    if !have_tmux() {
        eprintln!("SKIPPED a_worker_fault_is_shown_and_q_quits: tmux is not installed");
        return;
    }
    let t = Tmux::start("fault", &std::env::temp_dir(), "ASPERITY_TEST_FAULT=1");
    let s = t.wait("the fault on the panel", |s| s.contains("internal fault"));
    assert!(
        !s.contains("panicked"),
        "the worker's panic is not painted over the screen\n{s}"
    );
    // Esc never quits; q does, with the terminal restored
    t.keys(&["Escape"]);
    // apart from the Escape, else the terminal reads ESC q as Alt-q
    std::thread::sleep(Duration::from_millis(500));
    t.keys(&["q"]);
    let s = t.wait("the exit", |s| s.contains("TTY="));
    assert!(s.contains("EXIT=0"), "{s}");
    assert!(s.contains("TTY=icanon"), "raw mode is off again\n{s}");
    assert!(!s.contains("parameters"), "the alternate screen is gone\n{s}");
}

#[test]
fn the_weakest_surface_energy_then_q_in_tmux() {
    if !have_tmux() {
        eprintln!("SKIPPED the_weakest_surface_energy_then_q_in_tmux: tmux is not installed");
        return;
    }
    let t = Tmux::start_with(
        "weak",
        &std::env::temp_dir(),
        "",
        "tui --preset system-2 --gamma 1e-320",
    );
    t.wait("the first frame with results", |s| s.contains("a_r(p*)") && solved(s));
    t.keys(&["q"]);
    let s = t.wait("the exit", |s| s.contains("TTY="));
    assert!(s.contains("EXIT=0") && s.contains("TTY=icanon"), "{s}");
}

#[test]
fn not_a_terminal_explains_the_headless_commands() {
    let out = Command::new(BIN).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("not a terminal") && err.contains("asperity run") && err.contains("asperity sweep"),
        "{err}"
    );
}

#[test]
fn bad_preset_is_the_cli_error() {
    let out = Command::new(BIN)
        .args(["tui", "--preset", "no-such-preset"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let tui_err = String::from_utf8_lossy(&out.stderr).into_owned();
    let run = Command::new(BIN)
        .args(["run", "--preset", "no-such-preset"])
        .output()
        .unwrap();
    assert_eq!(tui_err, String::from_utf8_lossy(&run.stderr));
    assert!(tui_err.contains("no-such-preset"), "{tui_err}");
}

/// `asperity tour`: walks the shipped tour (→ ←, a knob turned inside a step), saves the
/// charts of the last step with `s` (SVG that parses and names the series, PNG), Esc leaves.
#[test]
fn tour_in_tmux() {
    if !have_tmux() {
        eprintln!("SKIPPED tour_in_tmux: tmux is not installed");
        return;
    }
    let dir = std::env::temp_dir().join(format!("asperity-e2e-tour-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let t = Tmux::start_with("tour", &dir, "", "tour");
    let s = t.wait("the first step", |s| s.contains("tour 1/14") && solved(s));
    assert!(
        s.contains("What the explorer computes") && s.contains("Persson theory"),
        "{s}"
    );
    for (i, title) in [
        (2, "Roughness, scale by scale"),
        (3, "How much area?"),
        (4, "The stress distribution"),
        (5, "What no W(a_r) can fix"),
    ] {
        t.keys(&["Right"]);
        let s = t.wait(title, |s| s.contains(&format!("tour {i}/14")) && solved(s));
        assert!(s.contains(title), "{s}");
    }
    let s = t.screen();
    assert!(s.contains("Pr(σ*) log–log") && s.contains("σ→0 asymptote"), "{s}");
    // a knob still turns inside a step (p* is selected: l steps it up)
    t.keys(&["l"]);
    t.wait("p* = 0.01122", |s| s.contains("0.01122") && s.contains("tour 5/14"));
    t.keys(&["Left"]);
    t.wait("step 4", |s| s.contains("tour 4/14") && s.contains("0.01000"));
    // through the adhesive steps to the jump into contact
    for i in 5..=12 {
        t.keys(&["Right"]);
        t.wait("the next step", |s| s.contains(&format!("tour {i}/14")));
    }
    let s = t.wait("the jump-in step solved", |s| {
        s.contains("Jump into contact") && solved(s)
    });
    assert!(s.contains("system-2") && s.contains("a_r(t·q_r)"), "{s}");
    // s: the visible charts as SVG (and PNG) next to the CSV export, paths in the status line
    t.wait("every chart of the step", |s| {
        s.contains("t=∞") && (s.contains("● p*") || s.contains("●p*"))
    });
    t.keys(&["s"]);
    let s = t.wait("the saved charts", |s| s.contains("saved"));
    assert!(s.contains("asperity-system-2-1-pr.svg"), "{s}");
    for (chart, names) in [
        ("pr", &["theory", "γ_s=0", "−σ_a*"][..]),
        ("thickness", &["theory", "γ_s=0", "t=∞"][..]),
        ("area", &["theory", "current p*"][..]),
    ] {
        let svg = dir.join(format!("asperity-system-2-1-{chart}.svg"));
        let text = std::fs::read_to_string(&svg).unwrap_or_else(|e| panic!("{}: {e}", svg.display()));
        let doc = roxmltree::Document::parse(&text).expect("the SVG parses as XML");
        let texts: Vec<&str> = doc.descendants().filter_map(|n| n.text()).collect();
        for name in names {
            assert!(
                texts.iter().any(|t| t.contains(name)),
                "{chart}: no series {name:?} in {texts:?}"
            );
        }
        assert!(dir.join(format!("asperity-system-2-1-{chart}.png")).is_file());
    }
    // the step before the closing one: models 4 and 5 against the GFMD points the library stores
    t.keys(&["Right"]);
    let s = t.wait("the brute-force step solved", |s| {
        s.contains("tour 13/14") && s.contains("Theory against brute force") && solved(s)
    });
    assert!(s.contains("model 5") && s.contains("t·q_r = 0.15"), "{s}");
    t.wait("the stored GFMD points in a key", |s| s.contains("◆ GFMD ("));
    t.keys(&["Escape"]);
    t.wait("the tour to end", |s| {
        s.contains("left the tour") && !s.contains("tour 13/14")
    });
    t.keys(&["q"]);
    let s = t.wait("a clean exit", |s| s.contains("TTY="));
    assert!(s.contains("EXIT=0") && s.contains("TTY=icanon"), "{s}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `asperity tui` takes the scene flags of `run`.
#[test]
fn tui_takes_the_scene_flags_in_tmux() {
    if !have_tmux() {
        eprintln!("SKIPPED tui_takes_the_scene_flags_in_tmux: tmux is not installed");
        return;
    }
    let t = Tmux::start_with(
        "flags",
        &std::env::temp_dir(),
        "",
        "tui --preset system-2 --model 3 --pressure 0.02 --thickness 1 --gamma 0",
    );
    let s = t.wait("the scene of the flags", solved);
    assert!(
        s.contains("system-2") && s.contains("model 3") && s.contains("0.02000"),
        "{s}"
    );
    assert!(s.contains("0 (off)"), "{s}");
    t.keys(&["q"]);
    t.wait("a clean exit", |s| s.contains("EXIT=0"));
}

/// `asperity tui --surface FILE`: the theory on the map's spectrum, the file named in the
/// panel, the `psd` chart reachable with `v`.
#[test]
fn tui_on_a_measured_surface_in_tmux() {
    if !have_tmux() {
        eprintln!("SKIPPED tui_on_a_measured_surface_in_tmux: tmux is not installed");
        return;
    }
    let t = Tmux::start_with(
        "surface",
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")),
        "",
        "tui --surface tests/fixtures/two_bands.txt --periodic --gamma 0",
    );
    let s = t.wait("the scene of the map", solved);
    assert!(s.contains("surface  two_bands.txt"), "{s}");
    // `g` runs GFMD on the map itself: the a_r of `gfmd --surface` on the same scene
    t.keys(&["g"]);
    let s = t.wait("GFMD on the map", |s| s.contains("GFMD a_r"));
    let shown: f64 = s
        .lines()
        .find_map(|l| l.split("GFMD a_r").nth(1))
        .and_then(|r| r.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no GFMD a_r in {s}"));
    let out = Command::new(BIN)
        .args([
            "gfmd",
            "--surface",
            "tests/fixtures/two_bands.txt",
            "--periodic",
            "--gamma",
            "0",
        ])
        .args(["--format", "json"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let want = v["a_r"].as_f64().unwrap();
    assert!(
        (shown / want - 1.0).abs() < 1e-3,
        "explorer {shown}, gfmd --surface {want}"
    );
    assert!(s.contains("(N=32)"), "the map's own grid: {s}");
    // the focused panel shows `pr`: nine steps of the selector reach `psd`
    t.keys(&["v", "v", "v", "v", "v", "v", "v", "v", "v"]);
    t.wait("the psd chart", |s| s.contains("C(q) of two_bands.txt"));
    t.keys(&["q"]);
    t.wait("a clean exit", |s| s.contains("EXIT=0"));
}

#[test]
fn tui_and_tour_flags_are_validated_like_run() {
    let out = Command::new(BIN).args(["tui", "--pressure", "-1"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        err.trim(),
        "asperity: invalid --pressure = -1: allowed 1e-12 <= pressure <= 1000"
    );
    let out = Command::new(BIN).args(["tui", "--model", "9"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--model"));
    let out = Command::new(BIN).args(["tour", "--step", "99"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr).trim(),
        "asperity: invalid --step = 99: allowed 1 <= step <= 14"
    );
    let out = Command::new(BIN).args(["tour", "no-such-tour"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("tour = no-such-tour: allowed wang-muser"));
    let out = Command::new(BIN).args(["tour", "--list"]).output().unwrap();
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("wang-muser"));
    // a bad tour file: one line with the line number and the key
    let dir = std::env::temp_dir().join(format!("asperity-bad-tour-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("bad.toml");
    std::fs::write(
        &f,
        "name = \"x\"\ntitle = \"y\"\n\n[[step]]\ntitle = \"a\"\ncharts = [\"pr\", \"nope\"]\ncaption = \"a\\nb\"\n",
    )
    .unwrap();
    let out = Command::new(BIN).args(["tour", f.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 6: step[0].charts: unknown chart \"nope\""), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The scale view in the real binary: the tour's first step opens on it and plays it to q_s
/// (one frame per tick, without any key), `[` steps back, Space plays again.
#[test]
fn scale_view_plays_in_tmux() {
    if !have_tmux() {
        eprintln!("SKIPPED scale_view_plays_in_tmux: tmux is not installed (apt-get install tmux)");
        return;
    }
    let dir = std::env::temp_dir().join(format!("asperity-e2e-scales-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let t = Tmux::start("scales", &dir, "");
    t.wait("the first frame with results", |s| s.contains("a_r(p*)") && solved(s));
    // pin two thicknesses (Fig. 8): t·q_r = 0.1, P, t·q_r = 0.4, P, back to ∞
    t.keys(&["Down"]);
    for (v, n) in [("0.1", 1), ("0.4", 2)] {
        let mut k: Vec<&str> = v.split("").filter(|c| !c.is_empty()).collect();
        k.push("Enter");
        t.keys(&k);
        t.wait("the thin slab solved", |s| {
            s.contains(&format!("t·q_r    {v}")) && solved(s)
        });
        std::thread::sleep(Duration::from_millis(300));
        t.keys(&["P"]);
        t.wait("the pin", |s| s.contains(&format!("pinned ({n} of 6)")));
    }
    t.keys(&["Enter", "i", "n", "f", "Enter"]);
    let s = t.wait("both pins drawn at t = ∞", |s| {
        s.contains("t·q_r=0.1") && s.contains("t·q_r=0.4") && s.contains("t·q_r    ∞") && solved(s)
    });
    assert!(s.contains("t·q_r=∞"), "the current curve named too: {s}");
    // the tour opens on what the explorer computes; its second step plays the scale view
    t.keys(&["t"]);
    t.wait("the opening step", |s| s.contains("tour 1/14"));
    t.keys(&["Right"]);
    t.wait("the scale view playing", |s| {
        s.contains("Pr(σ*, q) q/q_L=") && s.contains("/48 ▶")
    });
    let s = t.wait("the play to reach q_s", |s| {
        s.contains(" 48/48 ") && !s.contains("/48 ▶")
    });
    assert!(s.contains("tour 2/14"), "{s}");
    t.keys(&["["]);
    t.wait("one frame back", |s| s.contains(" 47/48 "));
    t.keys(&["Space"]);
    t.wait("playing on", |s| s.contains("/48 ▶") || s.contains(" 48/48 "));
    t.keys(&["Escape"]);
    t.wait("the tour to close", |s| !s.contains("tour 2/14"));
    t.keys(&["q"]);
    let s = t.wait("a clean exit", |s| s.contains("TTY="));
    assert!(s.contains("EXIT=0") && s.contains("TTY=icanon"), "{s}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The load history: at the jump-into-contact step, p* stepped up through the hysteresis
/// window jumps in; stepped back down into the window the explorer stays on the unloading
/// branch (a_r ≈ 0.43, not the loading branch's 0.09) and says why; `r` goes back.
#[test]
fn hysteresis_followed_in_tmux() {
    if !have_tmux() {
        eprintln!("SKIPPED hysteresis_followed_in_tmux: tmux is not installed");
        return;
    }
    let dir = std::env::temp_dir().join(format!("asperity-e2e-hyst-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let t = Tmux::start_with("hyst", &dir, "", "tour --step 12");
    t.wait("the jump-in step", |s| s.contains("tour 12/14") && solved(s));
    // ⇧→ twice (L is the same key): 1e-4 → 1.78e-4 → 3.16e-4, above jump-in
    t.keys(&["L"]);
    t.keys(&["L"]);
    t.wait("the jump in", |s| s.contains("the loading branch ended at p*"));
    // back down (h, fine steps) to 2.24e-4, inside the window
    t.keys(&["h", "h", "h"]);
    let s = t.wait("the unloading branch inside the window", |s| {
        s.contains("unloading (jumped in)") && s.contains("2.239e-4") && solved(s)
    });
    let a_r: f64 = s
        .lines()
        .find_map(|l| l.split("│ a_r").nth(1))
        .and_then(|v| v.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no a_r row:\n{s}"));
    assert!(
        (0.40..0.47).contains(&a_r),
        "a_r {a_r} is not the unloading branch's:\n{s}"
    );
    t.keys(&["r"]);
    t.wait("the reset", |s| {
        s.contains("loading (from small p*)") || !s.contains("jumped in")
    });
    t.keys(&["q"]);
    let s = t.wait("a clean exit", |s| s.contains("TTY="));
    assert!(s.contains("EXIT=0"), "{s}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn mouse_in_tmux_with_the_flag() {
    if !have_tmux() {
        eprintln!("SKIPPED mouse_in_tmux_with_the_flag: tmux is not installed (apt-get install tmux)");
        return;
    }
    let dir = std::env::temp_dir().join(format!("asperity-e2e-mouse-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let t = Tmux::start_with("mouse", &dir, "", "tui --preset system-1 --mouse");
    t.wait("the first frame with results", |s| s.contains("a_r(p*)") && solved(s));
    // the terminal's SGR mouse reports, as a terminal sends them: the wheel up over a chart
    // steps the selected knob (p*) one fine step, as → does
    t.keys(&["-l", "\x1b[<64;70;20M"]);
    t.wait("p* = 0.01122", |s| s.contains("0.01122") && solved(s));
    t.keys(&["-l", "\x1b[<65;70;20M"]);
    t.wait("p* back to 0.01", |s| !s.contains("0.01122") && solved(s));
    t.keys(&["q"]);
    t.wait("the exit status", |s| s.contains("EXIT=0"));
}
