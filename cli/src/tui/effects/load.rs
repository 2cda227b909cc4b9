//! Reading a preset or a tour (a name built in, or a file) for the update, which never reads
//! files itself: [`Command::LoadPreset`] and [`Command::LoadTour`] are run here and their
//! outcome goes back as [`Msg::PresetLoaded`] and [`Msg::TourLoaded`]. A fresh explorer
//! ([`App::new`]) is opened here too: its preset picker lists the preset files found.

use crate::tui::base::tour::Tour;
use crate::tui::model::app::App;
use crate::tui::model::command::Command;
use crate::tui::model::msg::Msg;
use asperity::input::preset::Preset;

impl App {
    /// A fresh explorer on `preset` (resolved from `source`), its picker listing the presets
    /// built in and those under `presets/` in the working directory.
    pub fn new(source: &str, preset: Preset) -> asperity::error::Result<App> {
        App::open(source, preset, asperity::input::preset::list_available())
    }
}

/// The message of a load command (None for the other commands).
pub fn run(cmd: &Command) -> Option<Msg> {
    match cmd {
        Command::LoadPreset(source) => Some(Msg::PresetLoaded {
            source: source.clone(),
            result: Preset::resolve(source),
        }),
        Command::LoadTour(name) => Some(Msg::TourLoaded(Tour::resolve(name))),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_preset_and_a_tour_come_back_as_messages() {
        match run(&Command::LoadPreset("system-2".into())) {
            Some(Msg::PresetLoaded { source, result }) => {
                assert_eq!(source, "system-2");
                assert_eq!(result.unwrap().name, "system-2");
            }
            other => panic!("{other:?}"),
        }
        let Some(Msg::PresetLoaded { result, .. }) = run(&Command::LoadPreset("no-such-preset".into())) else {
            panic!("a message")
        };
        assert!(result.is_err());
        let Some(Msg::TourLoaded(t)) = run(&Command::LoadTour("wang-muser".into())) else {
            panic!("a message")
        };
        assert!(!t.unwrap().steps.is_empty());
        assert!(run(&Command::CancelGfmd(Default::default())).is_none() && run(&Command::Quit).is_none());
    }
}
