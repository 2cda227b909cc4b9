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

/// A CSV cell: empty where the value is unavailable (as `asperity sweep` writes it).
pub fn cell(x: f64) -> String {
    if x.is_finite() {
        format!("{x:e}")
    } else {
        String::new()
    }
}

/// `# key: value` lines describing the scene, for the top of every exported CSV.
pub fn scene_comment(app: &App, name: &str) -> String {
    let s = &app.scene;
    let t = if s.thickness_qr.is_infinite() {
        "inf".to_string()
    } else {
        format!("{}", s.thickness_qr)
    };
    format!(
        "# asperity explorer export {name}\n# preset: {} ({})\n# model: {}\n# pressure: {}\n# thickness_qr: {t}\n\
         # gamma_j_m2: {}\n# range_m: {}\n# reduced units: stresses by E*g = {} Pa, gap by h_rms = {} m\n",
        app.preset.name,
        app.source,
        s.model.label(),
        s.pressure,
        s.gamma,
        s.range,
        s.stress_unit(),
        s.spectrum.rms_height()
    )
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

    let mut preset = scene_preset(&app.preset, &app.scene);
    preset.name = stem.clone();
    let toml_text = toml::to_string(&preset).map_err(|e| Error::Io(format!("cannot serialise the scene: {e}")))?;
    let header =
        format!("# Scene exported by the asperity explorer; open it with `asperity tui --preset {stem}.toml`.\n");
    let path = dir.join(format!("{stem}.toml"));
    write(&path, &(header + &toml_text))?;
    paths.push(path.display().to_string());

    if let Some(Ok(pt)) = &app.point {
        let mut t = scene_comment(app, &stem);
        t.push_str("sigma,density\n");
        for (s, d) in &pt.pr {
            let _ = writeln!(t, "{},{}", cell(*s), cell(*d));
        }
        let path = dir.join(format!("{stem}-pr.csv"));
        write(&path, &t)?;
        paths.push(path.display().to_string());
    }
    if let Some(Ok(sw)) = &app.sweep {
        let mut t = scene_comment(app, &stem);
        t.push_str("p,a_r,mean_gap_rel,mean_contact_stress,converged\n");
        for i in 0..sw.p.len() {
            let _ = writeln!(
                t,
                "{},{},{},{},{}",
                cell(sw.p[i]),
                cell(sw.a_r[i]),
                cell(sw.gap_rel[i]),
                cell(sw.mean_contact_stress[i]),
                sw.converged.get(i).copied().unwrap_or(false)
            );
        }
        let path = dir.join(format!("{stem}-loads.csv"));
        write(&path, &t)?;
        paths.push(path.display().to_string());
    }
    Ok(paths)
}

/// `s`: writes the visible charts as SVG and PNG next to the CSV export; returns the paths.
pub fn export_charts(_app: &App) -> Result<Vec<String>> {
    Err(Error::Unsupported("chart export needs the chart renderer".into()))
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
        // scene metadata as comments, then the columns of `sweep` (empty cells, converged)
        assert!(
            csv.starts_with("# asperity explorer export asperity-system-1-1\n# preset: system-1"),
            "{csv}"
        );
        assert!(csv.contains("# pressure: 0.01\n"), "{csv}");
        let rows: Vec<&str> = csv.lines().filter(|l| !l.starts_with('#')).collect();
        assert_eq!(rows[0], "p,a_r,mean_gap_rel,mean_contact_stress,converged");
        assert_eq!(rows.len(), 1 + crate::tui::worker::SWEEP_POINTS);
        assert!(rows[1].ends_with(",true"), "{}", rows[1]);
        assert!(!csv.contains("NaN") && !csv.contains("0.000e0"));
        let back = Preset::load(std::path::Path::new(&first[0])).unwrap();
        assert_eq!(crate::tui::app::initial_scene(&back).unwrap(), app.scene);
        // the exported scene is named after its file, not the stock preset
        assert_eq!(back.name, "asperity-system-1-1");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn unavailable_values_are_empty_cells() {
        assert_eq!(cell(f64::NAN), "");
        assert_eq!(cell(f64::INFINITY), "");
        assert_eq!(cell(0.0), "0e0");
        assert_eq!(cell(0.25), "2.5e-1");
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
