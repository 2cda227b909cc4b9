//! Files given to the commands, checked as files before any work: outputs that cannot be
//! written (a read-only file, a folder, a device, a name over 255 bytes) and inputs that are
//! no regular files (a FIFO, `/dev/zero` behind a `.txt` link) or not what they should be (a
//! map with decimal commas) are refused in one line naming the flag, exit 2, with no
//! computation started (`ASPERITY_FORBID_WORK` makes any computation panic). A repeated flag
//! is one line naming it and its values.

use std::path::{Path, PathBuf};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_asperity");

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-files-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs the binary with no computation allowed; returns (exit code, stderr).
fn refused(args: &[&str]) -> (i32, String) {
    let out = Command::new(BIN)
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .env("ASPERITY_FORBID_WORK", "1")
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The rule: exit 2, one line, naming `flag`.
fn check(args: &[&str], flag: &str, says: &str) {
    let (code, err) = refused(args);
    assert_eq!(code, 2, "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    assert!(err.contains(flag), "{args:?} names {flag}: {err}");
    assert!(err.contains(says), "{args:?} says {says:?}: {err}");
    assert!(err.chars().count() < 300, "{args:?}: {err}");
}

/// A small map in the text format, written to `d`.
fn map(d: &Path) -> String {
    let p = d.join("map.txt");
    let rows: Vec<String> = (0..8)
        .map(|i| {
            (0..8)
                .map(|j| format!("{:e}", ((i * 3 + j * 5) % 7) as f64 * 1e-9))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    std::fs::write(&p, rows.join("\n")).unwrap();
    p.display().to_string()
}

#[test]
fn outputs_that_cannot_be_written_are_refused_before_any_work() {
    let d = dir("out");
    let m = map(&d);
    let psd = |flag: &str, out: &str| {
        vec![
            "psd".to_string(),
            m.clone(),
            "--size".into(),
            "1e-6".into(),
            flag.into(),
            out.into(),
        ]
    };
    let run = |args: Vec<String>, flag: &str, says: &str| {
        let a: Vec<&str> = args.iter().map(String::as_str).collect();
        check(&a, flag, says);
    };
    // a folder, a name over 255 bytes
    let folder = d.join("charts.svg");
    std::fs::create_dir_all(&folder).unwrap();
    run(psd("--svg", folder.to_str().unwrap()), "--svg", "not a folder");
    let long = d.join(format!("{}.svg", "x".repeat(300)));
    run(psd("--svg", long.to_str().unwrap()), "--svg", "255 bytes");
    // a device
    if Path::new("/dev/full").exists() {
        let (code, err) = refused(&["psd", &m, "--size", "1e-6", "--png", "/dev/full"]);
        // /dev/full has no .png ending: refused by its extension or as a device, before work
        assert_eq!(code, 2, "{err}");
    }
    // a read-only file (root may write it anyway: then it is not refused, and not touched)
    let ro = d.join("old.svg");
    std::fs::write(&ro, "old").unwrap();
    let mut perm = std::fs::metadata(&ro).unwrap().permissions();
    perm.set_readonly(true);
    std::fs::set_permissions(&ro, perm).unwrap();
    let probe = std::fs::OpenOptions::new().append(true).open(&ro);
    if probe.is_err() {
        run(psd("--svg", ro.to_str().unwrap()), "--svg", "writable file");
    }
    assert_eq!(std::fs::read_to_string(&ro).unwrap(), "old", "never truncated");
    // --save-preset with an over-long name, on a command that would otherwise run a fit
    let toml = d.join(format!("{}.toml", "p".repeat(300)));
    check(
        &[
            "gauge",
            "--fit",
            "w0",
            "--reference",
            "eq18",
            "--save-preset",
            toml.to_str().unwrap(),
        ],
        "--save-preset",
        "255 bytes",
    );
    // nothing left behind
    let left: Vec<_> = std::fs::read_dir(&d).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left.len(), 3, "{left:?}");
}

#[test]
fn an_existing_output_is_replaced_whole() {
    let d = dir("replace");
    let m = map(&d);
    let svg = d.join("psd.svg");
    std::fs::write(&svg, "old").unwrap();
    let out = Command::new(BIN)
        .args(["psd", &m, "--size", "1e-6", "--svg", svg.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));
    // no temporary left next to it
    assert_eq!(std::fs::read_dir(&d).unwrap().count(), 2);
}

#[cfg(unix)]
#[test]
fn inputs_that_are_no_regular_files_are_refused_at_once() {
    let d = dir("in");
    let fifo = d.join("pipe.txt");
    let made = Command::new("mkfifo").arg(&fifo).status().is_ok_and(|s| s.success());
    if made {
        let f = fifo.to_str().unwrap();
        check(&["run", "--surface", f, "--size", "1e-6"], "--surface", "FIFO");
        check(&["run", "--psd", f], "--psd", "FIFO");
        check(&["psd", f, "--size", "1e-6"], "file", "FIFO");
    } else {
        eprintln!("SKIPPED the FIFO cases: mkfifo is not available");
    }
    let link = d.join("zero.txt");
    if std::os::unix::fs::symlink("/dev/zero", &link).is_ok() {
        check(&["psd", link.to_str().unwrap(), "--size", "1e-6"], "file", "device");
    }
    // a map with decimal commas: refused saying so, not read as twice the columns
    let comma = d.join("comma.txt");
    std::fs::write(&comma, "-4,2247e-08 1,0220e-07 3,1e-08\n2,2e-08 -1,5e-08 4,0e-08\n").unwrap();
    let (code, err) = refused(&["psd", comma.to_str().unwrap(), "--size", "1e-6"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("decimal comma") && err.trim_end().lines().count() == 1,
        "{err}"
    );
}

#[test]
fn a_repeated_flag_is_one_line_naming_it() {
    check(
        &["run", "--pressure", "0.01", "--pressure", "0.02"],
        "--pressure",
        "0.01, 0.02",
    );
    check(&["run", "--periodic", "--periodic"], "--periodic", "once");
}
