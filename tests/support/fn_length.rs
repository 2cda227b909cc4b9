//! Lengths of the functions of a Rust file, for the architecture tests of both crates (the
//! library's `tests/architecture.rs` and the binary's `cli/tests/architecture.rs` include this
//! file): a function runs from the line of its `fn` to the line of the brace that closes its
//! body, counted on the code with comments, strings and character literals blanked (so a
//! `'{'` or a `"}"` does not move the count). Functions without a body (trait declarations)
//! are skipped. Test modules (`#[cfg(test)] mod tests` to the end of the file) and
//! `*_tests.rs` files are the callers' to leave out.

/// The code of `text` with comments, string and char literal contents replaced by spaces
/// (line breaks kept, so line numbers stay).
pub fn blank(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let keep = |ch: char| if ch == '\n' { '\n' } else { ' ' };
    while i < c.len() {
        let ch = c[i];
        let next = c.get(i + 1).copied();
        if ch == '/' && next == Some('/') {
            while i < c.len() && c[i] != '\n' {
                out.push(' ');
                i += 1;
            }
        } else if ch == '/' && next == Some('*') {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    out.push(keep(c[i]));
                    i += 1;
                }
            }
        } else if ch == 'r' && (next == Some('"') || next == Some('#')) && !ident_before(&c, i) {
            // a raw string r"…", r#"…"#
            let mut j = i + 1;
            let mut hashes = 0;
            while c.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if c.get(j) != Some(&'"') {
                out.push(ch);
                i += 1;
                continue;
            }
            for _ in i..=j {
                out.push(' ');
            }
            i = j + 1;
            while i < c.len() {
                if c[i] == '"' && (0..hashes).all(|k| c.get(i + 1 + k) == Some(&'#')) {
                    for _ in 0..=hashes {
                        out.push(' ');
                    }
                    i += 1 + hashes;
                    break;
                }
                out.push(keep(c[i]));
                i += 1;
            }
        } else if ch == '"' {
            out.push(' ');
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    out.push(' ');
                    i += 1;
                }
                if i < c.len() {
                    out.push(keep(c[i]));
                    i += 1;
                }
            }
            out.push(' ');
            i += 1;
        } else if ch == '\'' {
            // a char literal ('x', '\n', '\u{7b}'), not a lifetime ('a)
            let end = if next == Some('\\') {
                (i + 2..c.len()).find(|&j| c[j] == '\'')
            } else if c.get(i + 2) == Some(&'\'') {
                Some(i + 2)
            } else {
                None
            };
            match end {
                Some(e) => {
                    for _ in i..=e {
                        out.push(' ');
                    }
                    i = e + 1;
                }
                None => {
                    out.push(ch);
                    i += 1;
                }
            }
        } else {
            out.push(ch);
            i += 1;
        }
    }
    out
}

fn ident_before(c: &[char], i: usize) -> bool {
    i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_')
}

/// (name, first line (1-based), lines) of every function with a body in `text`.
pub fn functions(text: &str) -> Vec<(String, usize, usize)> {
    let code = blank(text);
    let lines: Vec<&str> = code.lines().collect();
    let mut out = Vec::new();
    for (n, line) in lines.iter().enumerate() {
        let Some(at) = fn_keyword(line) else { continue };
        let name: String = line[at + 3..]
            .trim_start()
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if name.is_empty() {
            continue;
        }
        // the body: the first `{` before a `;` at depth 0 of (), <>-free scan
        let mut depth = 0i64;
        let mut opened = false;
        let mut paren = 0i64;
        'scan: for (m, l) in lines.iter().enumerate().skip(n) {
            let start = if m == n { at } else { 0 };
            for ch in l[start..].chars() {
                match ch {
                    '(' | '[' => paren += 1,
                    ')' | ']' => paren -= 1,
                    ';' if !opened && paren == 0 => break 'scan,
                    '{' => {
                        opened = true;
                        depth += 1;
                    }
                    '}' => {
                        depth -= 1;
                        if opened && depth == 0 {
                            out.push((name.clone(), n + 1, m - n + 1));
                            break 'scan;
                        }
                    }
                    _ => {}
                }
            }
        }
    }
    out
}

/// Longest function of either crate (lines, from `fn` to its closing brace).
pub const MAX_FN_LINES: usize = 120;

/// The functions of `files` longer than [`MAX_FN_LINES`], each as
/// `PLACE::NAME (line L, N lines)` with `place` naming its file; a file's test module
/// (`#[cfg(test)] mod tests` to the end of the file) is left out.
pub fn too_long<'a>(
    files: impl IntoIterator<Item = &'a std::path::PathBuf>,
    place: impl Fn(&std::path::Path) -> String,
) -> Vec<String> {
    let mut long = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(f).unwrap();
        let text = match text.find("#[cfg(test)]\nmod tests") {
            Some(i) => &text[..i],
            None => &text[..],
        };
        for (name, line, n) in functions(text) {
            if n > MAX_FN_LINES {
                long.push(format!("{}::{name} (line {line}, {n} lines)", place(f)));
            }
        }
    }
    long
}

/// Where `fn ` starts in a line, as a keyword (not `fn_x`, not in `Fn(`).
fn fn_keyword(line: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(k) = line[from..].find("fn ") {
        let at = from + k;
        let before = line[..at].chars().last();
        if before.is_none_or(|c| !(c.is_alphanumeric() || c == '_')) {
            return Some(at);
        }
        from = at + 3;
    }
    None
}

#[test]
fn the_scanner_counts_bodies_not_braces_in_strings() {
    let text = "fn a() {\n    let s = \"}\";\n    let c = '{';\n    // }\n}\nfn b(x: u8) -> u8;\npub(crate) fn c<'a>(x: &'a str) -> &'a str {\n    x\n}\n";
    assert_eq!(functions(text), [("a".to_string(), 1, 5), ("c".to_string(), 7, 3)]);
    let raw = "fn d() {\n    let s = r#\"{ \"# ;\n}\n";
    assert_eq!(functions(raw), [("d".to_string(), 1, 3)]);
}
