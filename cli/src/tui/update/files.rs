//! What `e` and `s` wrote → the next state: the file number the other key reuses, the
//! exported scene listed by `p`, the paths (or the error) in the status line.

use crate::tui::model::app::{App, PresetEntry};
use crate::tui::model::msg::Written;

impl App {
    /// Takes the outcome of a file command.
    pub fn written(&mut self, w: Written) {
        let k = usize::from(w.charts);
        let paths = match w.result {
            Ok(paths) => paths,
            Err(e) => return self.fail(e),
        };
        let same = |l: &(asperity::input::scene::Scene, String, u32, [bool; 2])| {
            l.0 == w.scene && l.1 == w.name && l.2 == w.number
        };
        let mut done = self.jobs.last_export.take().filter(same).map_or([false; 2], |l| l.3);
        done[k] = true;
        self.jobs.last_export = Some((w.scene, w.name, w.number, done));
        // `p` lists the exported scene
        let toml = paths.iter().find(|p| p.ends_with(".toml"));
        if let Some(t) = toml.filter(|t| !self.params.presets.iter().any(|x| &x.source == *t)) {
            self.params.presets.push(PresetEntry {
                source: t.clone(),
                place: "exported".into(),
            });
        }
        let verb = if w.charts { "saved" } else { "exported" };
        self.info(format!("{verb} {}", paths.join(", ")));
    }
}
