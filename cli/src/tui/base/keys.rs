//! The key table: the single source of truth for both dispatch ([`action_for`]) and the help
//! overlay (which renders [`TABLE`] row by row). Key names are a public interface.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// Everything a key can do in the main view.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    /// Select the previous parameter.
    Up,
    /// Select the next parameter.
    Down,
    /// Decrease the selected parameter (fine step).
    Dec,
    /// Increase the selected parameter (fine step).
    Inc,
    /// Decrease (coarse step).
    DecCoarse,
    /// Increase (coarse step).
    IncCoarse,
    /// Type a value for the selected parameter (also: start typing a digit).
    Edit,
    /// Cycle the model 1 → 2 → 3 → 4 → custom.
    CycleModel,
    /// Open the preset picker.
    Presets,
    /// Reset every parameter to the preset's.
    Reset,
    /// Export the current curves (CSV) and scene (TOML) into the working directory.
    Export,
    /// Switch the area chart between log a_r and a_r/p*.
    AreaMode,
    /// Show or hide the adhesionless comparison curve in the Pr chart.
    Compare,
    /// Start a GFMD run of the current scene in the background, or cancel the running one.
    Gfmd,
    /// Cycle the chart of the focused panel.
    Chart,
    /// Move the focus to the next chart panel.
    Focus,
    /// Overlay all models on the charts.
    Models,
    /// Start (or leave) the teaching tour.
    Tour,
    /// Save the visible charts as SVG and PNG.
    Save,
    /// Pin the theory curves of the visible charts.
    Pin,
    /// Remove the newest pin.
    Unpin,
    /// Remove every pin.
    UnpinAll,
    /// Scale view: one resolution step coarser.
    FramePrev,
    /// Scale view: one resolution step finer.
    FrameNext,
    /// Scale view: play the resolution from q_L to q_s, or pause.
    Play,
    /// Scroll the tour's caption down one line (where it is cut).
    CaptionDown,
    /// Scroll the tour's caption up one line.
    CaptionUp,
    /// Open or close this help.
    Help,
    /// Show the focused chart on the whole screen, or all panels again.
    Zoom,
    /// The Pr chart's density axis: linear or log.
    LogY,
    /// Cancel what runs (typing, an overlay, the tour, GFMD); never quits.
    Cancel,
    /// Quit.
    Quit,
}

/// The help's last row: where the manual is (the repository's docs/).
pub const MANUAL: &str = "manual     docs/explorer.md · docs/tour-format.md · docs/commands.md";

/// The panel's rows, one line each, for the help (after the keys): what each read-out is
/// (the help still fits 160×48 whole).
pub const PANEL_ROWS: &[(&str, &str)] = &[
    ("a_r", "contact area / nominal area (of the branch the path is on)"),
    ("σ̄_c*", "mean stress in contact, ∫σ*Pr dσ*/a_r, in units of E*ḡ"),
    ("ū/h_rms", "mean gap between the surfaces, in rms heights"),
    ("ū load", "ū's bracket: dry gap at the same a_r … at the same load"),
    ("γ̃_glo", "γ_s over the elastic energy of full contact [S-24]"),
    ("μ_T", "Tabor parameter: elastic neck height / range of adhesion"),
    ("state", "branch shown, solver marches (it), branches at this load"),
    ("σ_a*", "adhesive wall: contact holds tension down to σ* = −σ_a*"),
    ("tensile", "share of the contact area under tension (σ* < 0)"),
    ("err a_r", "estimated absolute error of a_r (discretisation)"),
    ("trust", "a_r error measured against GFMD near here; mN's: model N's"),
];

/// The help's header of [`PANEL_ROWS`].
pub const PANEL_HEADER: &str = "─ panel rows ─";

/// Rows of the help: the key table's, [`MANUAL`], then the panel's rows under their header.
pub fn help_rows() -> usize {
    TABLE.len() + 2 + PANEL_ROWS.len()
}

/// One key: a code plus the modifiers it needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Key(pub KeyCode, pub KeyModifiers);

const NONE: KeyModifiers = KeyModifiers::NONE;
const SHIFT: KeyModifiers = KeyModifiers::SHIFT;
const CTRL: KeyModifiers = KeyModifiers::CONTROL;

/// One row of the key table.
#[derive(Debug, Clone, Copy)]
pub struct Binding {
    /// The keys that trigger the action.
    pub keys: &'static [Key],
    /// How the keys are written in the help.
    pub label: &'static str,
    /// What happens.
    pub action: Action,
    /// One line of help.
    pub help: &'static str,
}

/// The key table of the main view.
pub const TABLE: &[Binding] = &[
    Binding {
        keys: &[Key(KeyCode::Up, NONE), Key(KeyCode::Char('k'), NONE)],
        label: "↑ k",
        action: Action::Up,
        help: "previous parameter",
    },
    Binding {
        keys: &[
            Key(KeyCode::Down, NONE),
            Key(KeyCode::Char('j'), NONE),
            Key(KeyCode::Tab, NONE),
        ],
        label: "↓ j Tab",
        action: Action::Down,
        help: "next parameter",
    },
    Binding {
        keys: &[Key(KeyCode::Left, NONE), Key(KeyCode::Char('h'), NONE)],
        label: "← h",
        action: Action::Dec,
        help: "decrease (fine; p*, t·q_r, γ_s step in log)",
    },
    Binding {
        keys: &[Key(KeyCode::Right, NONE), Key(KeyCode::Char('l'), NONE)],
        label: "→ l",
        action: Action::Inc,
        help: "increase (fine)",
    },
    Binding {
        keys: &[
            Key(KeyCode::Left, SHIFT),
            Key(KeyCode::PageDown, NONE),
            Key(KeyCode::Char('H'), NONE),
        ],
        label: "⇧← PgDn",
        action: Action::DecCoarse,
        help: "decrease (coarse)",
    },
    Binding {
        keys: &[
            Key(KeyCode::Right, SHIFT),
            Key(KeyCode::PageUp, NONE),
            Key(KeyCode::Char('L'), NONE),
        ],
        label: "⇧→ PgUp",
        action: Action::IncCoarse,
        help: "increase (coarse)",
    },
    Binding {
        keys: &[Key(KeyCode::Enter, NONE)],
        label: "0-9 Enter",
        action: Action::Edit,
        help: "type a value (inf, 0 = off), Enter applies, Esc or q cancels",
    },
    Binding {
        keys: &[Key(KeyCode::Char('m'), NONE)],
        label: "m",
        action: Action::CycleModel,
        help: "cycle model 1, 2, 3, 4, custom, YP08, Xu24, 5",
    },
    Binding {
        keys: &[Key(KeyCode::Char('p'), NONE)],
        label: "p",
        action: Action::Presets,
        help: "pick a preset",
    },
    Binding {
        keys: &[Key(KeyCode::Char('r'), NONE)],
        label: "r",
        action: Action::Reset,
        help: "reset to the preset",
    },
    Binding {
        keys: &[Key(KeyCode::Char('e'), NONE)],
        label: "e",
        action: Action::Export,
        help: "export curves (CSV) and scene (TOML) here",
    },
    Binding {
        keys: &[Key(KeyCode::Char('a'), NONE)],
        label: "a",
        action: Action::AreaMode,
        help: "area charts: log a_r / a_r/p*",
    },
    Binding {
        keys: &[Key(KeyCode::Char('c'), NONE)],
        label: "c",
        action: Action::Compare,
        help: "Pr chart: adhesionless comparison on/off",
    },
    Binding {
        keys: &[Key(KeyCode::Char('g'), NONE)],
        label: "g",
        action: Action::Gfmd,
        help: "GFMD of this scene (background; g again cancels)",
    },
    Binding {
        keys: &[Key(KeyCode::Char('v'), NONE)],
        label: "v",
        action: Action::Chart,
        help: "next chart in the focused panel (f moves the focus)",
    },
    Binding {
        keys: &[Key(KeyCode::Char('f'), NONE)],
        label: "f",
        action: Action::Focus,
        help: "focus the next chart panel",
    },
    Binding {
        keys: &[Key(KeyCode::Char('M'), NONE)],
        label: "M",
        action: Action::Models,
        help: "overlay all models (1-5, custom) on the charts",
    },
    Binding {
        keys: &[Key(KeyCode::Char('t'), NONE)],
        label: "t",
        action: Action::Tour,
        help: "teaching tour: ←→ steps, h l knobs, Esc leaves",
    },
    Binding {
        keys: &[Key(KeyCode::Char('s'), NONE)],
        label: "s",
        action: Action::Save,
        help: "save the visible charts as SVG and PNG here",
    },
    Binding {
        keys: &[Key(KeyCode::Char('P'), NONE)],
        label: "P",
        action: Action::Pin,
        help: "pin the visible curves (kept while the scene changes)",
    },
    Binding {
        keys: &[Key(KeyCode::Char('u'), NONE)],
        label: "u",
        action: Action::Unpin,
        help: "unpin the newest pin",
    },
    Binding {
        keys: &[Key(KeyCode::Char('U'), NONE)],
        label: "U",
        action: Action::UnpinAll,
        help: "unpin all",
    },
    Binding {
        keys: &[Key(KeyCode::Char('['), NONE)],
        label: "[",
        action: Action::FramePrev,
        help: "scale view: one resolution step coarser",
    },
    Binding {
        keys: &[Key(KeyCode::Char(']'), NONE)],
        label: "]",
        action: Action::FrameNext,
        help: "scale view: one resolution step finer",
    },
    Binding {
        keys: &[Key(KeyCode::Char(' '), NONE)],
        label: "Space",
        action: Action::Play,
        help: "scale view: play q from q_L to q_s, or pause",
    },
    Binding {
        keys: &[Key(KeyCode::Char('J'), NONE)],
        label: "J",
        action: Action::CaptionDown,
        help: "tour: scroll a cut caption down",
    },
    Binding {
        keys: &[Key(KeyCode::Char('K'), NONE)],
        label: "K",
        action: Action::CaptionUp,
        help: "tour: scroll the caption up",
    },
    Binding {
        keys: &[Key(KeyCode::Char('?'), NONE), Key(KeyCode::F(1), NONE)],
        label: "? F1",
        action: Action::Help,
        help: "this help",
    },
    Binding {
        keys: &[Key(KeyCode::Char('z'), NONE)],
        label: "z",
        action: Action::Zoom,
        help: "the focused chart full screen (z again: all panels)",
    },
    Binding {
        keys: &[Key(KeyCode::Char('y'), NONE)],
        label: "y",
        action: Action::LogY,
        help: "Pr chart: linear / log density axis (small distributions, tails)",
    },
    Binding {
        keys: &[Key(KeyCode::Esc, NONE)],
        label: "Esc",
        action: Action::Cancel,
        help: "cancel: typing, a list, the tour, a GFMD run (never quits)",
    },
    Binding {
        keys: &[Key(KeyCode::Char('q'), NONE), Key(KeyCode::Char('c'), CTRL)],
        label: "q ^C",
        action: Action::Quit,
        help: "quit",
    },
];

/// Whether `key` matches the event. Shift is ignored for characters (terminals disagree on
/// whether `?` or `L` carry it); other modifiers must match exactly.
pub fn matches(key: Key, ev: &KeyEvent) -> bool {
    if key.0 != ev.code {
        return false;
    }
    let relevant = KeyModifiers::SHIFT | KeyModifiers::CONTROL | KeyModifiers::ALT;
    let mut got = ev.modifiers & relevant;
    let mut want = key.1 & relevant;
    if matches!(ev.code, KeyCode::Char(_)) {
        got.remove(KeyModifiers::SHIFT);
        want.remove(KeyModifiers::SHIFT);
    }
    got == want
}

/// The action bound to a key event, from [`TABLE`].
pub fn action_for(ev: &KeyEvent) -> Option<Action> {
    TABLE
        .iter()
        .find(|b| b.keys.iter().any(|k| matches(*k, ev)))
        .map(|b| b.action)
}

/// The key event a caption's `{key:KEY}` names, written as the help writes keys (`m`,
/// `Space`, `⇧→`, `PgUp`, `F1`; `←`/`→` move along a tour): None where no action is bound to
/// it.
pub fn parse_label(label: &str) -> Option<KeyEvent> {
    let (code, m) = match label {
        "Space" => (KeyCode::Char(' '), NONE),
        "Enter" => (KeyCode::Enter, NONE),
        "Esc" => (KeyCode::Esc, NONE),
        "Tab" => (KeyCode::Tab, NONE),
        "PgUp" => (KeyCode::PageUp, NONE),
        "PgDn" => (KeyCode::PageDown, NONE),
        "F1" => (KeyCode::F(1), NONE),
        "↑" => (KeyCode::Up, NONE),
        "↓" => (KeyCode::Down, NONE),
        "←" => return Some(KeyEvent::new(KeyCode::Left, NONE)),
        "→" => return Some(KeyEvent::new(KeyCode::Right, NONE)),
        "⇧←" => (KeyCode::Left, SHIFT),
        "⇧→" => (KeyCode::Right, SHIFT),
        s => {
            let mut cs = s.chars();
            match (cs.next(), cs.next()) {
                (Some(c), None) => (KeyCode::Char(c), NONE),
                _ => return None,
            }
        }
    };
    let ev = KeyEvent::new(code, m);
    action_for(&ev).map(|_| ev)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ev(code: KeyCode, m: KeyModifiers) -> KeyEvent {
        KeyEvent::new(code, m)
    }

    #[test]
    fn dispatch_follows_the_table() {
        assert_eq!(action_for(&ev(KeyCode::Up, NONE)), Some(Action::Up));
        assert_eq!(action_for(&ev(KeyCode::Left, NONE)), Some(Action::Dec));
        assert_eq!(action_for(&ev(KeyCode::Left, SHIFT)), Some(Action::DecCoarse));
        assert_eq!(action_for(&ev(KeyCode::PageUp, NONE)), Some(Action::IncCoarse));
        assert_eq!(action_for(&ev(KeyCode::Char('?'), SHIFT)), Some(Action::Help));
        assert_eq!(action_for(&ev(KeyCode::Char('c'), CTRL)), Some(Action::Quit));
        assert_eq!(action_for(&ev(KeyCode::Char('c'), NONE)), Some(Action::Compare));
        assert_eq!(action_for(&ev(KeyCode::Char('q'), NONE)), Some(Action::Quit));
        assert_eq!(action_for(&ev(KeyCode::Char('x'), NONE)), None);
        assert_eq!(action_for(&ev(KeyCode::Left, CTRL)), None);
    }

    #[test]
    fn the_manual_the_help_names_exists() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        let pages: Vec<&str> = MANUAL.split_whitespace().filter(|w| w.ends_with(".md")).collect();
        assert_eq!(pages.len(), 3);
        for p in pages {
            assert!(root.join(p).is_file(), "{p}");
        }
    }

    #[test]
    fn every_key_is_bound_once() {
        let mut seen: Vec<Key> = Vec::new();
        for b in TABLE {
            assert!(!b.keys.is_empty() && !b.help.is_empty() && !b.label.is_empty());
            for k in b.keys {
                assert!(!seen.contains(k), "{k:?} bound twice");
                seen.push(*k);
            }
        }
    }
}
