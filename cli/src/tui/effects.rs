//! The effects of the explorer's updates: the theory request goes to the worker and a GFMD
//! run to its own thread (both by the event loop, [`super::run_app`]); here the files of `e`
//! and `s`. (`worker::compute_now` serves the requests on the calling thread, for tests.)

use super::export;
use super::state::{App, Effect};

/// Does the work the last keys asked for ([`App::effects`]), reporting in the status line.
/// `e` and `s` of one scene share a file number: the second key writes under the first's.
pub fn apply(app: &mut App) {
    for e in std::mem::take(&mut app.effects) {
        let name = export::safe_name(app);
        let reuse = app
            .last_export
            .as_ref()
            .filter(|(scene, n, _, done)| *scene == app.scene && *n == name && !done.contains(&e))
            .map(|l| l.2);
        let n = match reuse.map_or_else(|| export::next_number(&app.export_dir, &name), Ok) {
            Ok(n) => n,
            Err(err) => {
                app.fail(err);
                continue;
            }
        };
        let (verb, r) = match e {
            Effect::Export => ("exported", export::export_as(app, n)),
            Effect::SaveCharts => ("saved", export::export_charts_as(app, n)),
        };
        match r {
            Ok(paths) => {
                let mut done = reuse
                    .and_then(|_| app.last_export.take())
                    .map_or_else(Vec::new, |l| l.3);
                done.push(e);
                app.last_export = Some((app.scene.clone(), name, n, done));
                // `p` lists the exported scene
                let toml = paths.iter().find(|p| p.ends_with(".toml"));
                if let Some(t) = toml.filter(|t| !app.presets.iter().any(|x| &x.source == *t)) {
                    app.presets.push(super::state::PresetEntry {
                        source: t.clone(),
                        place: "exported".into(),
                    });
                }
                app.info(format!("{verb} {}", paths.join(", ")));
            }
            Err(e) => app.fail(e),
        }
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
        app.export_dir = dir.clone();
        super::super::worker::compute_now(&mut app, &mut Default::default());
        let press = |app: &mut App, e: Effect| {
            app.effects.push(e);
            apply(app);
            app.message.as_ref().map(|m| m.text.clone()).unwrap_or_default()
        };
        let s = press(&mut app, Effect::SaveCharts);
        assert!(s.contains("asperity-system-1-1-pr.svg"), "{s}");
        let e = press(&mut app, Effect::Export);
        assert!(e.contains("asperity-system-1-1.toml"), "{e}");
        // `p` lists the exported scene
        assert!(app
            .presets
            .iter()
            .any(|p| p.place == "exported" && p.source.ends_with("asperity-system-1-1.toml")));
        // a second e of the same scene never overwrites: the next number
        let e2 = press(&mut app, Effect::Export);
        assert!(e2.contains("asperity-system-1-2.toml"), "{e2}");
        let s2 = press(&mut app, Effect::SaveCharts);
        assert!(s2.contains("asperity-system-1-2-pr.svg"), "{s2}");
        // another scene: a new number
        app.set_typed(super::super::app::Param::Gamma, "0").unwrap();
        super::super::worker::compute_now(&mut app, &mut Default::default());
        let s3 = press(&mut app, Effect::SaveCharts);
        assert!(s3.contains("asperity-system-1-3-pr.svg"), "{s3}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
