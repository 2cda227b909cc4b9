//! The key of a chart, in its bottom border: one entry per named vertical marker and per drawn
//! series, each with its look's symbol (the glyph; a dashed line adds `╌`, a dotted one `┈`).
//! Where the names do not fit the chart's width they are abbreviated (`model 1` → `m1`,
//! `eq. (18)` → `eq18`, `jump-in` → `in`), then the spaces after the symbols go, then long
//! names are cut (a reference source is `ref`), and only then does the key wrap onto rows
//! at the top of the chart: no entry is ever left out.

use crate::looks::Look;
use crate::tui::charts::shared::{Chart, Draw, Role};
use crate::tui::view::palette::Palette;
use ratatui::text::{Line, Span};

/// One entry of a chart's key.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// The full name.
    pub name: String,
    /// What the series is.
    pub role: Role,
    /// Its colour and glyph.
    pub look: Look,
    /// Its line style (vertical markers: solid).
    pub draw: Draw,
}

impl Entry {
    /// The symbol: the glyph, with `╌` for a dashed and `┈` for a dotted line.
    pub fn symbol(&self) -> String {
        let g = self.look.glyph.symbol();
        match self.draw {
            Draw::Line | Draw::Points | Draw::Band => g.to_string(),
            Draw::Dashed | Draw::DashDot => format!("{g}╌"),
            Draw::Dotted => format!("{g}┈"),
        }
    }
}

/// The entries of `m`'s key when drawn with plane y bounds `yb`: the named vertical markers,
/// the series with something to draw, then the jump-in and pull-off markers.
pub fn entries(m: &Chart, yb: [f64; 2]) -> Vec<Entry> {
    let mut out = Vec::new();
    let mut last = Vec::new();
    for v in &m.vlines {
        if v.name.is_empty() || m.xs.forward(v.x).is_none() {
            continue;
        }
        let e = Entry {
            name: v.name.clone(),
            role: v.role,
            look: m.vline_look(v),
            draw: Draw::Line,
        };
        if matches!(v.role, Role::JumpIn | Role::PullOff) {
            last.push(e);
        } else {
            out.push(e);
        }
    }
    for (i, s) in m.series.iter().enumerate() {
        if crate::tui::charts::plot::runs(m, s, yb, usize::MAX).is_empty() {
            continue;
        }
        out.push(Entry {
            name: s.name.clone(),
            role: s.role,
            look: m.series_look(i),
            draw: s.style,
        });
    }
    out.extend(last);
    out
}

/// Most characters of an abbreviated name.
const SHORT: usize = 10;

/// A short form of a legend name: the usual words abbreviated, at most 10 characters.
pub fn abbreviate(name: &str) -> String {
    const WORDS: [(&str, &str); 22] = [
        ("theory on the GFMD map", "map"),
        ("eq. (18)", "eq18"),
        ("σ→0 asymptote", "σ→0"),
        ("large-σ asymptote", "σ→∞"),
        ("bracket (same a_r … same load)", "bracket"),
        ("unloading", "unl"),
        ("jump-in", "in"),
        ("pull-off", "off"),
        ("model ", "m"),
        ("custom", "cust"),
        ("theory", "th"),
        ("pin ", ""),
        ("t·q_r=", "t="),
        ("γ_s=", "γ="),
        ("p*=", "p="),
        ("−σ_a*", "−σa"),
        ("cut-offs", "cuts"),
        ("q/q_L = ", "q="),
        ("q = q_s", "q_s"),
        ("C(q) used", "C(q)"),
        ("other surface", "surf"),
        (", ", ","),
    ];
    let mut s = name.to_string();
    for (long, short) in WORDS {
        s = s.replace(long, short);
    }
    if let Some(fit) = s.strip_prefix("fit ") {
        s = fit.split('±').next().unwrap_or(fit).to_string();
    }
    if s.chars().count() > SHORT {
        s = s.chars().take(SHORT - 1).collect::<String>() + "…";
    }
    s
}

/// Most characters of a name cut to fit.
const TINY: usize = 7;

/// The shortest form of an entry's name: a reference source is `ref`, a jump marker keeps its
/// load (`in 0.030`); other names are abbreviated, without spaces, at most 7 characters.
pub fn tiny(e: &Entry) -> String {
    match e.role {
        Role::Reference => return "ref".into(),
        Role::JumpIn | Role::PullOff => return abbreviate(&e.name),
        _ => {}
    }
    let s: String = abbreviate(&e.name).chars().filter(|c| *c != ' ').collect();
    if s.chars().count() > TINY {
        s.chars().take(TINY - 1).collect::<String>() + "…"
    } else {
        s
    }
}

/// The key as at most `max_rows` lines of at most `width` columns: full names on one line
/// where they fit, else abbreviated names, else abbreviated names without the space after
/// each symbol, else the shortest names; where even those do not fit one line, the
/// abbreviated (else the shortest) names over as many lines as they need. Only where
/// `max_rows` lines cannot hold them does the last line end with `+N`, the entries left out.
pub fn lines(entries: &[Entry], width: usize, max_rows: usize, pal: Palette) -> Vec<Line<'static>> {
    if entries.is_empty() {
        return Vec::new();
    }
    let spans = |e: &Entry, level: u8| -> Vec<Span<'static>> {
        let style = pal.look(e.look);
        let text = match level {
            0 => format!(" {} ", e.name),
            1 => format!(" {} ", abbreviate(&e.name)),
            2 => format!("{} ", abbreviate(&e.name)),
            _ => format!("{} ", tiny(e)),
        };
        vec![Span::styled(e.symbol(), style), Span::raw(text)]
    };
    for level in 0..4 {
        let line = Line::from(entries.iter().flat_map(|e| spans(e, level)).collect::<Vec<_>>());
        if line.width() <= width {
            return vec![line];
        }
    }
    let wrap = |level: u8| -> Vec<Vec<Vec<Span<'static>>>> {
        let mut rows: Vec<Vec<Vec<Span<'static>>>> = vec![Vec::new()];
        let mut used = 0;
        for e in entries {
            let item = spans(e, level);
            let w: usize = item.iter().map(Span::width).sum();
            if used > 0 && used + w > width {
                rows.push(Vec::new());
                used = 0;
            }
            used += w;
            rows.last_mut().expect("non-empty").push(item);
        }
        rows
    };
    let to_lines = |rows: Vec<Vec<Vec<Span<'static>>>>| -> Vec<Line<'static>> {
        rows.into_iter()
            .map(|r| Line::from(r.into_iter().flatten().collect::<Vec<_>>()))
            .collect()
    };
    let max_rows = max_rows.max(1);
    for level in [2, 3] {
        let rows = wrap(level);
        if rows.len() <= max_rows {
            return to_lines(rows);
        }
    }
    // too many even so: the rows that fit, the last one ending with the count left out
    let mut rows = wrap(3);
    let mut left: usize = rows.drain(max_rows..).map(|r| r.len()).sum();
    let last = rows.last_mut().expect("max_rows >= 1");
    let row_width = |r: &Vec<Vec<Span<'static>>>| -> usize { r.iter().flatten().map(Span::width).sum() };
    while !last.is_empty() && row_width(last) + format!("+{left}").len() > width {
        last.pop();
        left += 1;
    }
    last.push(vec![Span::raw(format!("+{left}"))]);
    to_lines(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry(name: &str, role: Role, draw: Draw) -> Entry {
        Entry {
            name: name.into(),
            role,
            look: crate::looks::look(role, 2, 0),
            draw,
        }
    }

    #[test]
    fn a_long_key_is_abbreviated_then_wrapped_then_counted() {
        let pal = Palette { color: false };
        let text = |l: &[Line]| l.iter().map(|l| l.to_string()).collect::<Vec<_>>();
        let e = vec![
            entry("eq. (18)", Role::Closed, Draw::Dashed),
            entry("model 1", Role::Model(0), Draw::Line),
            entry("jump-in 0.030", Role::JumpIn, Draw::Line),
        ];
        assert_eq!(text(&lines(&e, 60, 1, pal)), ["⣿╌ eq. (18) • model 1 ╏ jump-in 0.030 "]);
        assert_eq!(text(&lines(&e, 25, 1, pal)), ["⣿╌ eq18 • m1 ╏ in 0.030 "]);
        assert_eq!(text(&lines(&e, 21, 1, pal)), ["⣿╌eq18 •m1 ╏in 0.030 "]);
        assert_eq!(text(&lines(&e, 14, 3, pal)), ["⣿╌eq18 •m1 ", "╏in 0.030 "]);
        // no room for a second line: what is left out is counted
        assert_eq!(text(&lines(&e, 14, 1, pal)), ["⣿╌eq18 •m1 +1"]);
    }

    #[test]
    fn names_abbreviate() {
        for (long, short) in [
            ("eq. (18)", "eq18"),
            ("model 1", "m1"),
            ("jump-in 0.21", "in 0.21"),
            ("pull-off 0.45", "off 0.45"),
            ("theory on the GFMD map", "map"),
            ("theory", "th"),
            ("t·q_r=0.1, model 4", "t=0.1,m4"),
            ("[S] Table 1, GFMD (65536^2)", "[S] Table…"),
            ("fit H=0.8±0.01", "H=0.8"),
            ("−σ_a*", "−σa"),
        ] {
            assert_eq!(abbreviate(long), short, "{long}");
        }
    }
}
