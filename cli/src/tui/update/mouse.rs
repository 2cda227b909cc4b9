//! The opt-in mouse (`--mouse`) → the next state: a click on a chart focuses it (as `f`
//! does), a click on a knob's row selects it (as ↑↓ do), the wheel steps the selected knob
//! one fine step (as ←→ do). The view placed the click ([`crate::tui::model::msg::Target`]);
//! while typing or under an overlay the mouse does nothing.

use crate::tui::model::app::{App, Command, Overlay};
use crate::tui::model::msg::{Pointer, Target};

impl App {
    /// Takes a mouse event.
    pub fn on_mouse(&mut self, p: Pointer) -> Option<Command> {
        if !self.ui.mouse || self.ui.edit.is_some() || self.ui.overlay != Overlay::None {
            return None;
        }
        self.ui.message = None;
        match p {
            Pointer::Click(Target::Chart(i)) => self.ui.focus = i.min(2),
            Pointer::Click(Target::Knob(r)) if r < self.knob_rows().len() => self.ui.selected = r,
            Pointer::Click(_) => {}
            Pointer::WheelUp => return self.step(1, false),
            Pointer::WheelDown => return self.step(-1, false),
        }
        None
    }
}
