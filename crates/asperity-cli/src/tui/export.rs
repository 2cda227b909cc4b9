//! `e`: writes the current curves as CSV and the scene as a preset TOML (loadable again with
//! `--preset PATH`) into the export directory, under names that never overwrite:
//! `asperity-NAME-N-pr.csv`, `asperity-NAME-N-loads.csv`, `asperity-NAME-N.toml`.

use super::app::App;
use asperity::error::{Error, Result};
use asperity::input::model::ModelKind;
use asperity::input::preset::{ModelSpec, Preset, Variant};
use asperity::input::scene::Scene;
use std::fmt::Write as _;
use std::path::Path;

/// The preset describing `scene` (the current preset with load, thickness, model and γ_s
/// replaced).
pub fn scene_preset(base: &Preset, scene: &Scene) -> Preset {
    let mut p = base.clone();
    p.load.pressure = scene.pressure;
    p.load.thickness_qr = scene.thickness_qr;
    p.adhesion.surface_energy_j_m2 = scene.gamma;
    p.adhesion.range_m = scene.range;
    let m = scene.model;
    p.model = match m.kind {
        ModelKind::Custom => ModelSpec {
            variant: Variant::Name("custom".into()),
            c1: Some(m.c1),
            c2: Some(m.c2),
            alpha: Some(m.alpha),
            k_griffith: Some(m.k_griffith),
            cap: Some(m.cap),
        },
        _ => ModelSpec {
            variant: Variant::Number(i64::from(m.number().unwrap_or(3))),
            ..ModelSpec::default()
        },
    };
    p.description = format!("{} (exported from the explorer)", base.description);
    p
}

fn write(path: &Path, text: &str) -> Result<()> {
    std::fs::write(path, text).map_err(|e| Error::Io(format!("cannot write {}: {e}", path.display())))
}

/// Writes the files; returns their paths.
pub fn export(app: &App) -> Result<Vec<String>> {
    let name: String = app
        .preset
        .name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    let dir = &app.export_dir;
    let n = (1..10_000)
        .find(|n| !dir.join(format!("asperity-{name}-{n}.toml")).exists())
        .ok_or_else(|| Error::Io("too many exports in this directory".into()))?;
    let stem = format!("asperity-{name}-{n}");
    let mut paths = Vec::new();

    let preset = scene_preset(&app.preset, &app.scene);
    let toml_text = toml::to_string(&preset).map_err(|e| Error::Io(format!("cannot serialise the scene: {e}")))?;
    let header =
        format!("# Scene exported by the asperity explorer; open it with `asperity tui --preset {stem}.toml`.\n");
    let path = dir.join(format!("{stem}.toml"));
    write(&path, &(header + &toml_text))?;
    paths.push(path.display().to_string());

    if let Some(Ok(pt)) = &app.point {
        let mut t = String::from("sigma,density\n");
        for (s, d) in &pt.pr {
            let _ = writeln!(t, "{s:e},{d:e}");
        }
        let path = dir.join(format!("{stem}-pr.csv"));
        write(&path, &t)?;
        paths.push(path.display().to_string());
    }
    if let Some(Ok(sw)) = &app.sweep {
        let mut t = String::from("p,a_r,mean_gap_rel,mean_contact_stress\n");
        for i in 0..sw.p.len() {
            let _ = writeln!(
                t,
                "{:e},{:e},{:e},{:e}",
                sw.p[i], sw.a_r[i], sw.gap_rel[i], sw.mean_contact_stress[i]
            );
        }
        let path = dir.join(format!("{stem}-loads.csv"));
        write(&path, &t)?;
        paths.push(path.display().to_string());
    }
    Ok(paths)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn export_writes_three_files_without_overwriting() {
        let dir = std::env::temp_dir().join(format!("asperity-export-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut app = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        app.export_dir = dir.clone();
        crate::tui::worker::compute_now(&mut app, &mut Default::default());
        let first = export(&app).unwrap();
        assert_eq!(first.len(), 3, "{first:?}");
        let second = export(&app).unwrap();
        assert!(second[0].ends_with("asperity-system-1-2.toml"), "{second:?}");
        let csv = std::fs::read_to_string(&first[2]).unwrap();
        assert!(csv.starts_with("p,a_r,mean_gap_rel"));
        assert_eq!(csv.lines().count(), 1 + crate::tui::worker::SWEEP_POINTS);
        let back = Preset::load(std::path::Path::new(&first[0])).unwrap();
        assert_eq!(crate::tui::app::initial_scene(&back).unwrap(), app.scene);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn exported_scene_loads_back() {
        let p = Preset::resolve("system-1").unwrap();
        let mut s = p.scene().unwrap();
        s.pressure = 0.02;
        s.thickness_qr = f64::INFINITY;
        s.model = asperity::input::model::Model::custom(0.1, 0.2, 0.5, 1.5, true).unwrap();
        let text = toml::to_string(&scene_preset(&p, &s)).unwrap();
        let back = Preset::parse(&text, "export").unwrap().scene().unwrap();
        assert_eq!(back, s);
        s.thickness_qr = 0.5;
        s.model = asperity::input::model::Model::named(2).unwrap();
        let text = toml::to_string(&scene_preset(&p, &s)).unwrap();
        assert_eq!(Preset::parse(&text, "export").unwrap().scene().unwrap(), s);
    }
}
