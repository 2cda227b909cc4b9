//! The file commands of the explorer's updates ([`Command::Export`] `e`, [`Command::SaveCharts`]
//! `s`), run by the event loop ([`super::run_app`]) like the worker's and GFMD's commands.

use crate::tui::effects::export;
use crate::tui::model::app::{App, Command, PresetEntry};

/// Runs a file command, reporting in the status line (other commands are the loop's).
/// `e` and `s` of one scene share a file number: the second key writes under the first's.
pub fn run(app: &mut App, cmd: &Command) {
    let k = match cmd {
        Command::Export => 0,
        Command::SaveCharts => 1,
        _ => return,
    };
    let name = export::safe_name(app);
    let reuse = app
        .jobs
        .last_export
        .as_ref()
        .filter(|(scene, n, _, done)| *scene == app.params.scene && *n == name && !done[k])
        .map(|l| l.2);
    let n = match reuse.map_or_else(|| export::next_number(&app.jobs.export_dir, &name), Ok) {
        Ok(n) => n,
        Err(err) => return app.fail(err),
    };
    let (verb, r) = if k == 0 {
        ("exported", export::export_as(app, n))
    } else {
        ("saved", export::export_charts_as(app, n))
    };
    match r {
        Ok(paths) => {
            let mut done = reuse
                .and_then(|_| app.jobs.last_export.take())
                .map_or([false; 2], |l| l.3);
            done[k] = true;
            app.jobs.last_export = Some((app.params.scene.clone(), name, n, done));
            // `p` lists the exported scene
            let toml = paths.iter().find(|p| p.ends_with(".toml"));
            if let Some(t) = toml.filter(|t| !app.params.presets.iter().any(|x| &x.source == *t)) {
                app.params.presets.push(PresetEntry {
                    source: t.clone(),
                    place: "exported".into(),
                });
            }
            app.info(format!("{verb} {}", paths.join(", ")));
        }
        Err(e) => app.fail(e),
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
            run(app, &e);
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
