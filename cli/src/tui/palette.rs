//! The explorer's colours (none under `NO_COLOR`): one style per role of a series.

use ratatui::style::{Color, Modifier, Style};

/// Colours (Okabe–Ito, colour-blind safe) or plain styles under `NO_COLOR`.
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
    /// The theory curve (blue).
    pub fn theory(&self) -> Style {
        self.fg(0, 114, 178)
    }
    /// Reference curves (orange).
    pub fn reference(&self) -> Style {
        self.fg(230, 159, 0)
    }
    /// The current point (vermillion).
    pub fn current(&self) -> Style {
        self.fg(213, 94, 0)
    }
    /// The adhesionless comparison (bluish green).
    pub fn compare(&self) -> Style {
        self.fg(0, 158, 115)
    }
    /// The −σ_a* wall (reddish purple).
    pub fn wall(&self) -> Style {
        self.fg(204, 121, 167)
    }
    /// Guide lines (sky blue).
    pub fn guide(&self) -> Style {
        self.fg(86, 180, 233)
    }
    /// GFMD results (yellow; also told apart by the ▀ marker).
    pub fn gfmd(&self) -> Style {
        self.fg(240, 228, 66)
    }
    /// Pin `i` (greys and earth tones, apart from the roles' Okabe–Ito colours).
    pub fn pin(&self, i: usize) -> Style {
        const PINS: [(u8, u8, u8); 6] = [
            (150, 150, 150),
            (140, 86, 75),
            (127, 60, 141),
            (17, 119, 51),
            (68, 68, 68),
            (170, 170, 0),
        ];
        let (r, g, b) = PINS[i % PINS.len()];
        self.fg(r, g, b)
    }
    /// Errors.
    pub fn error(&self) -> Style {
        self.fg(213, 94, 0).add_modifier(Modifier::BOLD)
    }
    /// Plain text (the reference points).
    pub fn text(&self) -> Style {
        Style::default()
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
