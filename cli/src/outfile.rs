//! Files the commands write (`--svg`, `--png`, `--save-preset`, `--save-reference`,
//! `--save-surface`, `--output`, the explorer's exports): checked as files before any work,
//! written atomically.
//!
//! [`refusal`] runs while the command line is parsed: the path must not be a folder, a device,
//! a FIFO or a socket; its name must fit the file system (at most 255 bytes); an existing
//! file is opened for appending (nothing is truncated or written), so a read-only or
//! immutable file is refused; a new file is created and removed at once, so a folder that
//! does not exist or cannot be written to is refused. Each refusal is one line naming the
//! flag, before the computation starts.
//!
//! [`write()`] writes the finished file next to its target (a hidden temporary name in the same
//! folder), flushes it to the disk and renames it over the target: an interrupted or failed
//! write (a full disk) leaves the old file whole and no temporary behind, and its error is one
//! line naming the flag.

use asperity::error::{fmt_text, Error, Result};
use std::fs::OpenOptions;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The longest file name most file systems take (bytes).
pub const NAME_MAX: usize = 255;

/// Why `path` cannot be written, in the words of a flag's message, or None when it can (an
/// existing regular file opened for appending, or a new one created and removed again).
pub fn refusal(path: &Path) -> Option<String> {
    if path.file_name().is_some_and(|n| n.len() > NAME_MAX) {
        return Some(format!("a file name of at most {NAME_MAX} bytes"));
    }
    match std::fs::metadata(path) {
        Ok(m) if m.is_dir() => Some("a file, not a folder".into()),
        Ok(m) if !m.is_file() => Some("a regular file (not a device, FIFO or socket)".into()),
        Ok(_) => OpenOptions::new()
            .append(true)
            .open(path)
            .err()
            .map(|e| format!("a writable file (opening it failed: {})", brief(&e))),
        Err(_) => {
            let dir = folder(path);
            if !dir.is_dir() {
                return Some("a file in an existing folder (no such folder)".into());
            }
            match OpenOptions::new().write(true).create_new(true).open(path) {
                Ok(f) => {
                    drop(f);
                    let _ = std::fs::remove_file(path);
                    None
                }
                Err(e) => Some(format!(
                    "a file name that can be created there (creating it failed: {})",
                    brief(&e)
                )),
            }
        }
    }
}

/// The folder `path` lies in ("." for a bare name).
fn folder(path: &Path) -> PathBuf {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// The system's message without its code ("Permission denied", not "… (os error 13)").
fn brief(e: &std::io::Error) -> String {
    let s = e.to_string();
    match s.find(" (os error") {
        Some(i) => s[..i].to_string(),
        None => s,
    }
}

/// Writes the file of flag `flag` at `path` atomically: `fill` writes the content to the
/// temporary path it is given (same folder), which is flushed to the disk and renamed over
/// `path` (a link is followed, so the file it points to is replaced). On any failure the
/// temporary is removed, the old file stays as it was, and the error names the flag.
///
/// # Errors
/// [`Error::Io`] whose action names the flag and the file.
pub fn write(flag: &str, path: &Path, fill: impl FnOnce(&Path) -> std::io::Result<()>) -> Result<()> {
    let target = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    let name = target
        .file_name()
        .map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned());
    // hidden, in the same folder, ending as the target does (the PNG encoder goes by the
    // extension), within NAME_MAX
    let chars: Vec<char> = name.chars().collect();
    let tail: String = chars[chars.len().saturating_sub(200)..].iter().collect();
    let tmp = folder(&target).join(format!(".asperity-{}-{tail}", std::process::id()));
    let fail = |e: std::io::Error| -> Error {
        let _ = std::fs::remove_file(&tmp);
        Error::Io {
            action: format!("write {flag} {}", fmt_text(&path.display().to_string())),
            kind: e.kind(),
            message: brief(&e),
        }
    };
    fill(&tmp).map_err(fail)?;
    let synced = OpenOptions::new().write(true).open(&tmp).and_then(|f| f.sync_all());
    synced.map_err(fail)?;
    if let Ok(m) = std::fs::metadata(&target) {
        let _ = std::fs::set_permissions(&tmp, m.permissions());
    }
    std::fs::rename(&tmp, &target).map_err(fail)
}

/// [`write()`] of bytes.
///
/// # Errors
/// As [`write()`].
pub fn write_bytes(flag: &str, path: &Path, bytes: &[u8]) -> Result<()> {
    write(flag, path, |tmp| {
        let mut f = OpenOptions::new().write(true).create_new(true).open(tmp)?;
        f.write_all(bytes)?;
        f.flush()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("asperity-outfile-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn folders_long_names_and_devices_are_refused_and_new_files_left_absent() {
        let d = dir("refusal");
        assert!(refusal(&d).unwrap().contains("not a folder"));
        assert!(refusal(&d.join("x".repeat(300))).unwrap().contains("255 bytes"));
        assert!(refusal(&d.join("no/such/x.svg")).unwrap().contains("no such folder"));
        if Path::new("/dev/null").exists() {
            assert!(refusal(Path::new("/dev/null")).unwrap().contains("regular file"));
        }
        let new = d.join("new.svg");
        assert_eq!(refusal(&new), None);
        assert!(!new.exists(), "the probe is removed");
        std::fs::write(&new, "old").unwrap();
        assert_eq!(refusal(&new), None);
        assert_eq!(std::fs::read_to_string(&new).unwrap(), "old", "nothing truncated");
    }

    #[test]
    fn a_failed_write_leaves_the_old_file_whole_and_no_temporary() {
        let d = dir("atomic");
        let f = d.join("keep.csv");
        std::fs::write(&f, "old").unwrap();
        let e = write("--save-reference", &f, |tmp| {
            std::fs::write(tmp, "half")?;
            Err(std::io::Error::other("disk full"))
        })
        .unwrap_err();
        assert!(e.to_string().contains("--save-reference"), "{e}");
        assert_eq!(std::fs::read_to_string(&f).unwrap(), "old");
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1, "no temporary left");
        write_bytes("--save-reference", &f, b"new").unwrap();
        assert_eq!(std::fs::read_to_string(&f).unwrap(), "new");
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1);
    }
}
