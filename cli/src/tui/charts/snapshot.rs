//! What `e` and `s` write, taken from the state when the key is pressed
//! ([`crate::tui::model::command::ExportJob`]): the scene and its preset, the branch shown,
//! the curves the screen shows and, for `s`, the visible charts built as the view builds
//! them. The effect ([`crate::tui::effects::files`]) writes it without reading the state.

use crate::tui::charts::{self, shared, ChartKind};
use crate::tui::model::app::App;
use crate::tui::model::command::ExportJob;
use asperity::surface::spectrum::Spectrum;

/// The files of `e` (`charts` false) or `s` (`charts` true) of the current scene. `e` and `s`
/// of one scene share a file number: the second key reuses the first's ([`ExportJob::reuse`]).
pub fn export_job(app: &App, charts: bool) -> ExportJob {
    let k = usize::from(charts);
    let name = safe_name(app);
    let reuse = app
        .jobs
        .last_export
        .as_ref()
        .filter(|(scene, n, _, done)| *scene == app.params.scene && *n == name && !done[k])
        .map(|l| l.2);
    let tabulated = matches!(app.params.scene.spectrum(), Spectrum::Tabulated(_));
    let measured = if tabulated {
        app.params
            .measured
            .clone()
            .or_else(|| app.params.preset.measured.clone())
    } else {
        None
    };
    let mut figures = Vec::new();
    if charts {
        for k in app.ui.charts {
            if !figures.iter().any(|(f, _)| *f == k) {
                let m = charts::build(app, k);
                if m.empty.is_none() {
                    figures.push((k, m));
                }
            }
        }
    }
    ExportJob {
        charts,
        dir: app.jobs.export_dir.clone(),
        name,
        reuse,
        scene: app.params.scene.clone(),
        preset: app.params.preset.clone(),
        source: app.params.source.clone(),
        measured,
        unloading: shared::on_unloading(app),
        pr: shared::shown_point(app).map(|p| p.pr.clone()),
        sweep: app.results.sweep().and_then(|r| r.as_ref().ok()).cloned(),
        thickness: app
            .results
            .thickness()
            .and_then(|r| r.as_ref().ok())
            .filter(|_| app.ui.charts.contains(&ChartKind::Thickness))
            .cloned(),
        gfmd: app.gfmd_for_scene().cloned(),
        pins: app.results.pins.clone(),
        scales: app.scales_data().filter(|_| app.shows_scales()).cloned(),
        figures,
    }
}

/// The scene's name as a file name (`asperity-NAME-N…`): the measured surface's file stem,
/// else the preset's name.
pub fn safe_name(app: &App) -> String {
    let surface = crate::tui::base::words::surface_name(&app.params.scene)
        .map(|f| f.rsplit_once('.').map_or(f.clone(), |(stem, _)| stem.to_string()));
    surface
        .unwrap_or_else(|| app.params.preset.name.clone())
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}
