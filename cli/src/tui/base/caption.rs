//! A tour caption's references and key claims: a caption names a look or a key only through a
//! reference that is rendered from the tables the explorer draws and dispatches with, so it
//! cannot name a colour, glyph or key that is not what the screen shows.
//!
//! - `{look:NAME}`: the colour and glyph of a series, rendered from [`crate::looks`]' table
//!   ([`describe`]): `{look:adhesionless}` → `light grey ·`, `{look:reference}` → `◆`. NAME
//!   is one of [`Role::NAMED`].
//! - `{key:KEY}`: a key, written as the key table writes it (`m`, `M`, `Space`, `⇧→`, `h/l`:
//!   several keys joined by `/`); each must be bound ([`keys::parse_label`]).
//! - `{chart:NAME}`: a chart of the step, by its tour name, read as "the a_r(p*) chart"
//!   ([`ChartKind::words`]); NAME must be among the step's `refers`, the charts the explorer
//!   shows first at every size.
//!
//! What a key does in a step is a claim like a number: a `[[step.press]]` table says which
//! key the caption names and what pressing it at the step gives (the model, the overlay of
//! all models, the comparison curve, the knob that moves and which way); the tour test
//! presses it in the explorer and checks.

use crate::looks::{describe, Role};
use crate::tui::base::keys;
use crate::tui::base::kinds::ChartKind;
use serde::Deserialize;

/// What pressing a key at a step gives (checked by the tour test in the explorer).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Press {
    /// The claim in words (shown when the check fails).
    pub says: String,
    /// The keys pressed, as `{key:KEY}` writes them, separated by spaces; the claims are
    /// about the last.
    pub key: String,
    /// The model number (1–5) after the press.
    pub model: Option<u8>,
    /// All models overlaid after the press.
    pub models: Option<bool>,
    /// The adhesionless comparison shown after the press.
    pub compare: Option<bool>,
    /// The knob (a name of `select`) whose value the press raises.
    pub raises: Option<String>,
    /// The knob whose value the press lowers.
    pub lowers: Option<String>,
    /// The scale view's frame moves to a finer (`1`) or coarser (`-1`) resolution.
    pub frame: Option<i32>,
    /// The scale view plays after the press.
    pub plays: Option<bool>,
    /// The branch of the load history after the press (`loading`, `unloading`).
    pub branch: Option<String>,
    /// The help (the keys and what each panel row is) shows after the press.
    pub help: Option<bool>,
}

/// A caption line with its references rendered (`model`: the slot of the step's model, the
/// theory's colour); Err names the bad reference.
pub fn render(line: &str, model: usize) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = line;
    while let Some(i) = rest.find('{') {
        out.push_str(&rest[..i]);
        let after = &rest[i + 1..];
        let end = after
            .find('}')
            .ok_or_else(|| format!("an unclosed reference \"{}\"", &rest[i..]))?;
        let (kind, name) = after[..end].split_once(':').ok_or_else(|| {
            format!(
                "\"{{{}}}\": write {{look:NAME}}, {{key:KEY}} or {{chart:NAME}}",
                &after[..end]
            )
        })?;
        match kind {
            "look" => {
                let role = Role::named(name).ok_or_else(|| {
                    let names: Vec<&str> = Role::NAMED.iter().map(|(n, _)| *n).collect();
                    format!("unknown look \"{name}\"; allowed {}", names.join(", "))
                })?;
                out.push_str(&describe(role, model));
            }
            "key" => {
                for k in name.split('/') {
                    if keys::parse_label(k).is_none() {
                        return Err(format!("unknown key \"{k}\" in {{key:{name}}}"));
                    }
                }
                out.push_str(name);
            }
            "chart" => {
                let k = ChartKind::parse(name).ok_or_else(|| {
                    let names: Vec<&str> = ChartKind::ALL.iter().map(|k| k.name()).collect();
                    format!(
                        "unknown chart \"{name}\" in {{chart:{name}}}; allowed {}",
                        names.join(", ")
                    )
                })?;
                out.push_str(&format!("the {} chart", k.words()));
            }
            other => return Err(format!("unknown reference \"{other}\"; allowed look, key, chart")),
        }
        rest = &after[end + 1..];
    }
    out.push_str(rest);
    Ok(out)
}

/// The references of a caption line: (kind, name) for each `{kind:name}`.
pub fn references(line: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find('{') {
        let after = &rest[i + 1..];
        let Some(end) = after.find('}') else { break };
        if let Some((k, n)) = after[..end].split_once(':') {
            out.push((k.to_string(), n.to_string()));
        }
        rest = &after[end + 1..];
    }
    out
}

/// A caption line without its references (what the test scans for bare colours and keys).
pub fn without_references(line: &str) -> String {
    let mut out = String::new();
    let mut rest = line;
    while let Some(i) = rest.find('{') {
        out.push_str(&rest[..i]);
        match rest[i..].find('}') {
            Some(end) => rest = &rest[i + end + 1..],
            None => {
                rest = "";
            }
        }
        out.push(' ');
    }
    out.push_str(rest);
    out
}

/// Checks a press table: its keys are bound, its knobs are among `knobs` (the names of a
/// step's `select`) and it claims something.
pub fn validate(p: &Press, knobs: &[&str]) -> Result<(), String> {
    if let Some(k) = p.key.split_whitespace().find(|k| keys::parse_label(k).is_none()) {
        return Err(format!("unknown key \"{k}\""));
    }
    if p.key.trim().is_empty() {
        return Err("key must not be empty".into());
    }
    for (key, knob) in [("raises", &p.raises), ("lowers", &p.lowers)] {
        if let Some(n) = knob.as_deref().filter(|n| !knobs.contains(n)) {
            return Err(format!(
                "{key} = {}: unknown knob; allowed {}",
                asperity::error::fmt_text(n),
                knobs.join(", ")
            ));
        }
    }
    if p.model.is_none()
        && p.models.is_none()
        && p.compare.is_none()
        && p.raises.is_none()
        && p.lowers.is_none()
        && p.frame.is_none()
        && p.plays.is_none()
        && p.branch.is_none()
        && p.help.is_none()
    {
        return Err("claims nothing: give model, models, compare, raises, lowers, frame, plays, branch or help".into());
    }
    if p.branch
        .as_deref()
        .is_some_and(|b| !matches!(b, "loading" | "unloading"))
    {
        return Err("branch: allowed loading, unloading".into());
    }
    if p.says.trim().is_empty() {
        return Err("says must not be empty".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn references_render_from_the_tables() {
        assert_eq!(
            render("{look:adhesionless}: no adhesion; {key:M} adds", 2).unwrap(),
            "light grey ·: no adhesion; M adds"
        );
        assert_eq!(render("{look:reference} is GFMD", 2).unwrap(), "◆ is GFMD");
        assert_eq!(render("turn it with {key:h/l}", 0).unwrap(), "turn it with h/l");
        assert_eq!(render("{look:theory}", 0).unwrap(), "orange ⣿");
        assert!(render("{look:green}", 0)
            .unwrap_err()
            .contains("unknown look \"green\""));
        assert!(render("{key:x}", 0).unwrap_err().contains("unknown key \"x\""));
        assert!(render("{look:theory", 0).is_err());
        assert_eq!(without_references("a {look:theory} b"), "a   b");
        assert_eq!(
            references("{look:a} and {key:m}"),
            [("look".into(), "a".into()), ("key".into(), "m".into())]
        );
    }
}
