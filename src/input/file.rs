//! Input files read as regular files of bounded size: the guard every reader of the library
//! goes through (height maps, PSD tables, presets, reference tables) and the front ends'
//! flag checks call before any work.
//!
//! The file's metadata is read first (which never blocks): a FIFO, a character or block
//! device (`/dev/zero`, a terminal) or a socket is refused at once, as is a file over the
//! reader's cap, so neither a pipe that never ends nor an endless device is read; then at
//! most the cap plus one byte is read (a file that grows meanwhile is still bounded).

use crate::error::{Error, Field, Result};
use std::io::Read;
use std::path::Path;

/// Largest input file read (bytes): 1 GiB, above a 8192² map of f64 in NumPy (512 MiB) or
/// in text (~12 bytes a value, 800 MB).
pub const MAX_INPUT_BYTES: u64 = 1 << 30;

/// What kind of file system object `path` is when it is not a regular file ("a folder",
/// "a FIFO", "a device", "a socket"), or None for a regular file (links followed) or a path
/// that cannot be read (the read itself then reports why).
pub fn not_regular(path: &Path) -> Option<&'static str> {
    let m = std::fs::metadata(path).ok()?;
    let t = m.file_type();
    if t.is_file() {
        return None;
    }
    if t.is_dir() {
        return Some("a folder");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return Some("a FIFO");
        }
        if t.is_socket() {
            return Some("a socket");
        }
        if t.is_char_device() || t.is_block_device() {
            return Some("a device");
        }
    }
    Some("not a regular file")
}

/// Why `path` is not an input file of at most `cap` bytes (a regular file, see
/// [`not_regular`]), in the words of an `allowed`, or None when it is (or cannot be read:
/// the read reports that).
pub fn refusal(path: &Path, cap: u64) -> Option<String> {
    if let Some(kind) = not_regular(path) {
        return Some(format!("a regular file (this is {kind})"));
    }
    let len = std::fs::metadata(path).ok()?.len();
    (len > cap).then(|| format!("a file of at most {cap} bytes (this one has {len})"))
}

/// Reads `path` (a `what` file: "surface", "preset", …, named in errors) as a regular file of
/// at most `cap` bytes.
///
/// # Errors
/// [`Error::Invalid`] for `field` naming the file where it is not a regular file or is over
/// the cap; [`Error::Io`] where it cannot be read.
pub fn read_bounded(path: &Path, what: &str, field: Field, cap: u64) -> Result<Vec<u8>> {
    let name = || -> String {
        path.file_name()
            .map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned())
    };
    if let Some(why) = refusal(path, cap) {
        return Err(Error::invalid_text(field, name(), why));
    }
    let f = std::fs::File::open(path).map_err(|e| Error::io_file("read", what, path, &e))?;
    let mut bytes = Vec::new();
    f.take(cap + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Error::io_file("read", what, path, &e))?;
    if bytes.len() as u64 > cap {
        return Err(Error::invalid_text(
            field,
            name(),
            format!("a file of at most {cap} bytes"),
        ));
    }
    Ok(bytes)
}

/// [`read_bounded`] as UTF-8 text: a file that is not is refused saying what was expected
/// (`expected`, e.g. "a height map as rows of numbers").
///
/// # Errors
/// As [`read_bounded`], and [`Error::Invalid`] for bytes that are not UTF-8.
pub fn read_text(path: &Path, what: &str, field: Field, cap: u64, expected: &str) -> Result<String> {
    let bytes = read_bounded(path, what, field.clone(), cap)?;
    String::from_utf8(bytes).map_err(|e| {
        let n = path
            .file_name()
            .map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
        Error::invalid_text(
            field,
            format!("{n} (not UTF-8 text at byte {})", e.utf8_error().valid_up_to()),
            format!("UTF-8 text: {expected}"),
        )
    })
}

/// A number written with a decimal comma (`-4,2247e-08`) in a line of numbers separated by
/// blanks: its digits, else None. A comma is a separator of the text formats, so such a
/// line would read as twice the numbers (a map of the wrong shape and heights); a token
/// with one comma between digits, among blank-separated ones, is that.
pub fn decimal_comma(line: &str) -> Option<&str> {
    let toks: Vec<&str> = line.split_whitespace().collect();
    if toks.len() < 2 {
        return None;
    }
    toks.into_iter().find(|t| {
        let t = t.trim_end_matches(';');
        match t.split_once(',') {
            Some((int, frac)) => {
                let int = int.trim_start_matches(['+', '-']);
                !int.is_empty()
                    && int.bytes().all(|b| b.is_ascii_digit())
                    && frac.starts_with(|c: char| c.is_ascii_digit())
                    && !frac.contains(',')
                    && format!("{int}.{frac}").parse::<f64>().is_ok()
            }
            None => false,
        }
    })
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn devices_folders_and_oversized_files_are_refused_without_reading() {
        assert_eq!(
            refusal(Path::new("/dev/zero"), 10).as_deref(),
            Some("a regular file (this is a device)")
        );
        assert_eq!(
            refusal(Path::new("/"), 10).as_deref(),
            Some("a regular file (this is a folder)")
        );
        let f = std::env::temp_dir().join(format!("asperity-file-{}.txt", std::process::id()));
        std::fs::write(&f, "1 2 3\n").unwrap();
        assert_eq!(refusal(&f, 100), None);
        assert!(refusal(&f, 3).unwrap().contains("at most 3 bytes"));
        assert!(read_bounded(&f, "surface", Field::HeightMap, 3).is_err());
        assert_eq!(
            read_text(&f, "surface", Field::HeightMap, 100, "numbers").unwrap(),
            "1 2 3\n"
        );
        let _ = std::fs::remove_file(&f);
    }

    #[test]
    fn decimal_commas_are_told_from_separators() {
        assert_eq!(decimal_comma("-4,2247e-08 1,0220e-07"), Some("-4,2247e-08"));
        assert_eq!(decimal_comma("1.5, 2.5, 3.5"), None);
        assert_eq!(decimal_comma("1.5,2.5,3.5"), None);
        assert_eq!(decimal_comma("1, 2, 3"), None);
        assert_eq!(decimal_comma("4,5"), None);
    }
}
