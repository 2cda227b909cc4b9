//! Key presses → the next state: the overlays (help, preset picker) and the field being
//! typed take keys first; the tour takes ←/→ and Esc; a digit starts typing a value; every
//! other key is looked up in the key table ([`crate::tui::base::keys`]) and acted on.

use crate::tui::base::keys;
use crate::tui::model::app::*;
use crate::tui::update::scene::load_preset;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

impl App {
    /// Handles one key press; the command it asks for, if any.
    pub fn on_key(&mut self, ev: KeyEvent) -> Option<Command> {
        if ev.code == KeyCode::Char('c') && ev.modifiers.contains(KeyModifiers::CONTROL) {
            self.ui.quit = true;
            return None;
        }
        self.ui.message = None;
        if self.ui.edit.is_some() {
            return self.on_edit_key(ev);
        }
        match self.ui.overlay {
            Overlay::Help => {
                // ↓↑ (j k, PgDn PgUp) scroll, any other key closes the help; q still quits
                let n = crate::tui::base::keys::help_rows();
                match ev.code {
                    KeyCode::Down | KeyCode::Char('j') => self.ui.help_scroll = (self.ui.help_scroll + 1).min(n),
                    KeyCode::PageDown => self.ui.help_scroll = (self.ui.help_scroll + 8).min(n),
                    KeyCode::Up | KeyCode::Char('k') => self.ui.help_scroll = self.ui.help_scroll.saturating_sub(1),
                    KeyCode::PageUp => self.ui.help_scroll = self.ui.help_scroll.saturating_sub(8),
                    code => {
                        self.ui.overlay = Overlay::None;
                        self.ui.help_scroll = 0;
                        self.ui.quit = code == KeyCode::Char('q');
                    }
                }
                return None;
            }
            Overlay::Presets(cursor) => return self.on_picker_key(ev, cursor),
            Overlay::None => {}
        }
        if self.ui.tour.is_some()
            && ev
                .modifiers
                .intersection(KeyModifiers::SHIFT | KeyModifiers::CONTROL)
                .is_empty()
        {
            match ev.code {
                KeyCode::Left => self.tour_go(-1),
                KeyCode::Right => self.tour_go(1),
                KeyCode::Esc => self.leave_tour(),
                _ => return self.on_table_key(ev),
            }
            return None;
        }
        self.on_table_key(ev)
    }

    /// A key of no overlay, field or tour: a digit starts typing a value; the key table's
    /// keys act.
    fn on_table_key(&mut self, ev: KeyEvent) -> Option<Command> {
        if let KeyCode::Char(c) = ev.code {
            if (c.is_ascii_digit() || c == '.' || c == '-') && !ev.modifiers.contains(KeyModifiers::CONTROL) {
                self.ui.edit = Some(c.to_string());
                return None;
            }
        }
        self.act(keys::action_for(&ev)?)
    }

    /// Handles one key press while the terminal is too small ([`Ui::too_small`]): the keys
    /// that quit (q, Ctrl-C: the key table's [`keys::Action::Quit`]) quit, even while a value
    /// is typed; every other key does nothing, as the screen says.
    pub fn on_key_too_small(&mut self, ev: KeyEvent) {
        if keys::action_for(&ev) == Some(keys::Action::Quit) {
            self.ui.quit = true;
        }
    }

    pub(crate) fn on_edit_key(&mut self, ev: KeyEvent) -> Option<Command> {
        let buf = self.ui.edit.as_mut()?;
        match ev.code {
            // q cancels the field (a second q quits): no value contains a q
            KeyCode::Esc | KeyCode::Char('q') => self.ui.edit = None,
            KeyCode::Backspace => {
                buf.pop();
            }
            KeyCode::Enter => {
                let text = std::mem::take(buf);
                self.ui.edit = None;
                if !text.trim().is_empty() {
                    match self.set_typed(self.selected_param(), &text) {
                        Ok(cmd) => return cmd,
                        // in the panel's words (t·q_r, p*), not the preset's keys
                        Err(e) => self.fail(crate::tui::base::words::describe(&e)),
                    }
                }
            }
            KeyCode::Char(c) if buf.chars().count() < 64 => buf.push(c),
            _ => {}
        }
        None
    }

    pub(crate) fn on_picker_key(&mut self, ev: KeyEvent, cursor: usize) -> Option<Command> {
        let n = self.params.presets.len().max(1);
        match ev.code {
            KeyCode::Up | KeyCode::Char('k') => self.ui.overlay = Overlay::Presets((cursor + n - 1) % n),
            KeyCode::Down | KeyCode::Char('j') | KeyCode::Tab => self.ui.overlay = Overlay::Presets((cursor + 1) % n),
            KeyCode::Enter => {
                self.ui.overlay = Overlay::None;
                return self.params.presets.get(cursor).map(|e| load_preset(&e.source));
            }
            KeyCode::Char('q') => self.ui.quit = true,
            _ => self.ui.overlay = Overlay::None,
        }
        None
    }
}
