//! The explorer's styles: the colours of [`crate::looks`]' table (none under `NO_COLOR`) and
//! the few the text uses.

use crate::looks::{Ink, Look};
use ratatui::style::{Color, Modifier, Style};

/// Colours, or plain styles under `NO_COLOR`.
#[derive(Debug, Clone, Copy)]
pub struct Palette {
    pub color: bool,
}

impl Palette {
    fn fg(&self, r: u8, g: u8, b: u8) -> Style {
        if self.color {
            Style::default().fg(Color::Rgb(r, g, b))
        } else {
            Style::default()
        }
    }
    /// The style of a series' look: its colour (the text colour for [`Ink::Text`]), bold
    /// where the look says so.
    pub fn look(&self, look: Look) -> Style {
        let s = match look.ink {
            Ink::Rgb(c) => self.fg(c.0, c.1, c.2),
            Ink::Text => Style::default(),
        };
        if look.bold {
            s.add_modifier(Modifier::BOLD)
        } else {
            s
        }
    }
    /// The spinner (sky blue).
    pub fn busy(&self) -> Style {
        self.fg(86, 180, 233)
    }
    /// Errors.
    pub fn error(&self) -> Style {
        self.fg(213, 94, 0).add_modifier(Modifier::BOLD)
    }
    /// Dim text.
    pub fn dim(&self) -> Style {
        if self.color {
            Style::default().fg(Color::Gray)
        } else {
            Style::default()
        }
    }
}

/// How long a computation runs before the spinner shows.
pub const SPINNER_DELAY: std::time::Duration = std::time::Duration::from_millis(150);

pub const SPINNER: [&str; 8] = ["⠋", "⠙", "⠹", "⠸", "⠼", "⠴", "⠦", "⠧"];
