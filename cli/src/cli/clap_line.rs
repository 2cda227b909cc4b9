//! The command line's parse errors in one line (clap's errors in the shape of the other input
//! errors): the flag and the value with what is allowed, a repeated flag with its values, a
//! missing flag with the flags given that require it.

use super::flags;

/// A command-line parse error in one line, in the same shape as the other input errors:
/// `invalid --flag = value: allowed …` where clap knows the flag and value, else clap's
/// first line.
pub fn clap_error_line(e: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue};
    let text = |k| match e.get(k) {
        Some(ContextValue::String(s)) => Some(s.clone()),
        _ => None,
    };
    if let (Some(arg), Some(value)) = (text(ContextKind::InvalidArg), text(ContextKind::InvalidValue)) {
        let flag = arg.split_whitespace().next().unwrap_or(&arg).to_string();
        // a positional argument, `[FIGURE]` or `<FILE>`: by its name, `figure`, `file`
        let flag = if flag.starts_with(['[', '<']) {
            flag.trim_matches(|c| matches!(c, '[' | ']' | '<' | '>' | '.'))
                .to_ascii_lowercase()
        } else {
            flag
        };
        let allowed = match e.get(ContextKind::ValidValue) {
            Some(ContextValue::Strings(v)) => v.join(", "),
            _ => std::error::Error::source(e)
                .map(|s| s.to_string())
                .unwrap_or_else(|| "see --help".into()),
        };
        return format!(
            "invalid {flag} = {}: allowed {allowed}",
            asperity::error::fmt_text(&value)
        );
    }
    if e.kind() == clap::error::ErrorKind::MissingRequiredArgument {
        if let Some(ContextValue::Strings(missing)) = e.get(ContextKind::InvalidArg) {
            let names: Vec<&str> = missing
                .iter()
                .map(|m| m.split_whitespace().next().unwrap_or(m))
                .collect();
            let args: Vec<String> = std::env::args().collect();
            let by = requirers(&names, &args);
            let by = if by.is_empty() {
                "the other flags given".to_string()
            } else {
                by.join(", ")
            };
            return format!("missing {}: required by {by} (see --help)", names.join(", "));
        }
    }
    if e.kind() == clap::error::ErrorKind::ArgumentConflict {
        if let (Some(arg), Some(prior)) = (text(ContextKind::InvalidArg), text(ContextKind::PriorArg)) {
            if arg == prior {
                let flag = arg.split_whitespace().next().unwrap_or(&arg).to_string();
                return repeated_flag(&flag, &std::env::args().collect::<Vec<_>>());
            }
        }
    }
    let rendered = e.to_string();
    let first = rendered.lines().next().unwrap_or("").trim();
    let first = first.strip_prefix("error: ").unwrap_or(first);
    if e.kind() == clap::error::ErrorKind::UnknownArgument {
        // name the command whose flags are allowed
        // (the usage line names the command, then the arguments given: keep the command)
        let cmd: Vec<&str> = rendered
            .lines()
            .find_map(|l| l.trim().strip_prefix("Usage: "))
            .map(|u| {
                u.split_whitespace()
                    .take_while(|w| !w.starts_with(['-', '<', '[']))
                    .collect()
            })
            .unwrap_or_default();
        let cmd = if cmd.is_empty() {
            "asperity".to_string()
        } else {
            cmd.join(" ")
        };
        return format!("{first}: allowed the flags of `{cmd} --help`");
    }
    first.to_string()
}

/// The flags of the command line `args` that require one of `missing`: each given flag left
/// out in turn (with its value), the line parsed again; a flag is a requirer when the
/// requirement is then gone.
fn requirers(missing: &[&str], args: &[String]) -> Vec<String> {
    let still_missing = |line: &[String]| match flags::command().try_get_matches_from(line) {
        Err(e) if e.kind() == clap::error::ErrorKind::MissingRequiredArgument => e.to_string(),
        _ => String::new(),
    };
    let mut found = Vec::new();
    for (i, a) in args.iter().enumerate().skip(1) {
        let Some(flag) = a.strip_prefix("--").map(|f| f.split('=').next().unwrap_or(f)) else {
            continue;
        };
        let flag = format!("--{flag}");
        if missing.contains(&flag.as_str()) || found.contains(&flag) {
            continue;
        }
        // the flag and, given as a separate word, its value
        let takes_next = !a.contains('=') && args.get(i + 1).is_some_and(|v| !v.starts_with("--"));
        let end = if takes_next { i + 2 } else { i + 1 };
        let line: Vec<String> = args[..i].iter().chain(&args[end.min(args.len())..]).cloned().collect();
        let text = still_missing(&line);
        if !missing.iter().any(|m| text.contains(m)) {
            found.push(flag);
        }
    }
    found
}

/// The message of a flag given more than once (`args`: the command line): every flag takes
/// one value, so a repeated one is refused (not the last taken silently), naming the values.
pub fn repeated_flag(flag: &str, args: &[String]) -> String {
    let with_eq = format!("{flag}=");
    let mut values = Vec::new();
    let mut it = args.iter().peekable();
    while let Some(a) = it.next() {
        if let Some(v) = a.strip_prefix(&with_eq) {
            values.push(asperity::error::fmt_text(v));
        } else if a == flag {
            if let Some(v) = it.peek().filter(|v| !v.starts_with("--")) {
                values.push(asperity::error::fmt_text(v));
            }
        }
    }
    if values.len() >= 2 {
        format!("repeated {flag} = {}: allowed once (one value)", values.join(", "))
    } else {
        format!("repeated {flag}: allowed once")
    }
}
