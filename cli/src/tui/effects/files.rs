//! The files of `e` (curves as CSV, the scene as TOML) and `s` (the charts as SVG and PNG),
//! written for [`Command::Export`] from the data it carries; what was written goes back to
//! the update as [`Msg::Written`] (which keeps the file number and lists the exported scene).

use crate::tui::effects::export;
use crate::tui::model::command::{Command, ExportJob};
use crate::tui::model::msg::{Msg, Written};

/// Writes the files of `job`. `e` and `s` of one scene share a file number: the second key
/// writes under the first's ([`ExportJob::reuse`]); a key pressed again on the same scene
/// writes under the next number (nothing is overwritten).
pub fn write(job: &ExportJob) -> Written {
    let number = job.reuse.map_or_else(|| export::next_number(&job.dir, &job.name), Ok);
    let (number, result) = match number {
        Ok(n) if job.charts => (n, export::export_charts_as(job, n)),
        Ok(n) => (n, export::export_as(job, n)),
        Err(e) => (0, Err(e)),
    };
    Written {
        charts: job.charts,
        scene: job.scene.clone(),
        name: job.name.clone(),
        number,
        result,
    }
}

/// The message of a file command (None for the other commands).
pub fn run(cmd: &Command) -> Option<Msg> {
    match cmd {
        Command::Export(job) => Some(Msg::Written(write(job))),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::charts::snapshot::export_job;
    use crate::tui::model::app::App;
    use asperity::input::preset::Preset;

    #[test]
    fn e_and_s_of_one_scene_share_a_number() {
        let dir = std::env::temp_dir().join(format!("asperity-effects-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut app = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        app.jobs.export_dir = dir.clone();
        crate::tui::drive::compute_now(&mut app, &mut Default::default());
        let press = |app: &mut App, charts: bool| {
            let msg = run(&Command::Export(Box::new(export_job(app, charts)))).unwrap();
            crate::tui::update::update(app, msg);
            app.ui.message.as_ref().map(|m| m.text.clone()).unwrap_or_default()
        };
        let s = press(&mut app, true);
        assert!(s.contains("asperity-system-1-1-pr.svg"), "{s}");
        let e = press(&mut app, false);
        assert!(e.contains("asperity-system-1-1.toml"), "{e}");
        // `p` lists the exported scene
        assert!(app
            .params
            .presets
            .iter()
            .any(|p| p.place == "exported" && p.source.ends_with("asperity-system-1-1.toml")));
        // a second e of the same scene never overwrites: the next number
        let e2 = press(&mut app, false);
        assert!(e2.contains("asperity-system-1-2.toml"), "{e2}");
        let s2 = press(&mut app, true);
        assert!(s2.contains("asperity-system-1-2-pr.svg"), "{s2}");
        // another scene: a new number
        app.set_typed(crate::tui::model::app::Param::Gamma, "0").unwrap();
        crate::tui::drive::compute_now(&mut app, &mut Default::default());
        let s3 = press(&mut app, true);
        assert!(s3.contains("asperity-system-1-3-pr.svg"), "{s3}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
