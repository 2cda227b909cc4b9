//! The files of `e` (curves as CSV, the scene as TOML) and `s` (the charts as SVG and PNG),
//! written for [`Command::Export`] and [`Command::SaveCharts`]; what was written goes back to
//! the update as [`Msg::Written`] (which keeps the file number and lists the exported scene).

use crate::tui::effects::export;
use crate::tui::model::app::{App, Command};
use crate::tui::model::msg::{Msg, Written};

/// Writes the files of `e` (`charts` false) or `s` (`charts` true). `e` and `s` of one scene
/// share a file number: the second key writes under the first's; a key pressed again on the
/// same scene writes under the next number (nothing is overwritten).
pub fn write(app: &App, charts: bool) -> Written {
    let k = usize::from(charts);
    let name = export::safe_name(app);
    let reuse = app
        .jobs
        .last_export
        .as_ref()
        .filter(|(scene, n, _, done)| *scene == app.params.scene && *n == name && !done[k])
        .map(|l| l.2);
    let number = reuse.map_or_else(|| export::next_number(&app.jobs.export_dir, &name), Ok);
    let (number, result) = match number {
        Ok(n) if charts => (n, export::export_charts_as(app, n)),
        Ok(n) => (n, export::export_as(app, n)),
        Err(e) => (0, Err(e)),
    };
    Written {
        charts,
        scene: app.params.scene.clone(),
        name,
        number,
        result,
    }
}

/// The message of a file command (None for the other commands).
pub fn run(app: &App, cmd: &Command) -> Option<Msg> {
    match cmd {
        Command::Export => Some(Msg::Written(write(app, false))),
        Command::SaveCharts => Some(Msg::Written(write(app, true))),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use asperity::input::preset::Preset;

    #[test]
    fn e_and_s_of_one_scene_share_a_number() {
        let dir = std::env::temp_dir().join(format!("asperity-effects-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut app = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        app.jobs.export_dir = dir.clone();
        crate::tui::drive::compute_now(&mut app, &mut Default::default());
        let press = |app: &mut App, e: Command| {
            let msg = run(app, &e).unwrap();
            crate::tui::update::update(app, msg);
            app.ui.message.as_ref().map(|m| m.text.clone()).unwrap_or_default()
        };
        let s = press(&mut app, Command::SaveCharts);
        assert!(s.contains("asperity-system-1-1-pr.svg"), "{s}");
        let e = press(&mut app, Command::Export);
        assert!(e.contains("asperity-system-1-1.toml"), "{e}");
        // `p` lists the exported scene
        assert!(app
            .params
            .presets
            .iter()
            .any(|p| p.place == "exported" && p.source.ends_with("asperity-system-1-1.toml")));
        // a second e of the same scene never overwrites: the next number
        let e2 = press(&mut app, Command::Export);
        assert!(e2.contains("asperity-system-1-2.toml"), "{e2}");
        let s2 = press(&mut app, Command::SaveCharts);
        assert!(s2.contains("asperity-system-1-2-pr.svg"), "{s2}");
        // another scene: a new number
        app.set_typed(crate::tui::model::app::Param::Gamma, "0").unwrap();
        crate::tui::drive::compute_now(&mut app, &mut Default::default());
        let s3 = press(&mut app, Command::SaveCharts);
        assert!(s3.contains("asperity-system-1-3-pr.svg"), "{s3}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
