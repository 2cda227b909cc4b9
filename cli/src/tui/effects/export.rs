//! `e`: writes the current curves as CSV and the scene as a preset TOML (loadable again with
//! `--preset PATH`) into the export directory, under names that never overwrite:
//! `asperity-NAME-N-pr.csv`, `asperity-NAME-N-loads.csv` (both branches of a hysteresis and
//! its edges, [`loads_csv`]), `asperity-NAME-N-gfmd.csv` (after `g`, [`gfmd_csv`]),
//! `asperity-NAME-N-thickness.csv` (with the thickness chart shown, [`thickness_csv`]),
//! `asperity-NAME-N-pins.csv` (pinned curves), `asperity-NAME-N-scales.csv` (the scale view)
//! and `asperity-NAME-N.toml`. The CSVs start with `#` lines describing the scene;
//! unavailable values are empty cells.
//!
//! `s`: writes the visible charts as SVG and PNG (`asperity-NAME-N-CHART.svg|png`) through
//! the chart renderer ([`crate::chart`]), from the same [`Chart`]s the screen shows.
//!
//! Both write an [`ExportJob`]: the data the update took from the state when the key was
//! pressed ([`crate::tui::charts::snapshot::export_job`]); nothing here reads the state.

use crate::chart;
use crate::tui::base::data::{SweepData, ThicknessData};
use crate::tui::base::gfmd_view::GfmdView;
use crate::tui::charts::snapshot::export_job;
pub use crate::tui::charts::snapshot::safe_name;
use crate::tui::charts::Chart;
use crate::tui::model::app::App;
use crate::tui::model::command::ExportJob;
use asperity::error::{Error, Result};
use asperity::input::preset::{LoadBranch, ModelSpec, Preset};
use asperity::input::scene::Scene;
use std::fmt::Write as _;
use std::path::Path;

/// The preset describing `scene` (the current preset with load, thickness, model and γ_s
/// replaced).
pub fn scene_preset(base: &Preset, scene: &Scene) -> Preset {
    let mut p = base.clone();
    p.load.pressure = scene.pressure();
    p.load.thickness_qr = scene.thickness_qr();
    p.adhesion.surface_energy_j_m2 = scene.surface_energy_j_m2();
    p.adhesion.range_m = scene.range_m();
    // the preset's own spelling of the model (custom coefficients, YP08/Xu24 with γ_f)
    p.model = ModelSpec::of_model(&scene.model());
    p.description = format!("{} (exported from the explorer)", base.description);
    p
}

/// A CSV cell: empty where the value is unavailable (the library's, as `asperity sweep` writes it).
pub use asperity::report::csv::cell;
use asperity::report::csv::table;

/// `# key: value` lines describing the scene, for the top of every exported CSV.
pub fn scene_comment(job: &ExportJob, name: &str) -> String {
    let s = &job.scene;
    let t = if s.thickness_qr().is_infinite() {
        "inf".to_string()
    } else {
        format!("{}", s.thickness_qr())
    };
    // the surface: the measured one by its file, else the preset's
    let surface = match crate::tui::base::words::surface_name(s) {
        Some(file) => format!("# surface: {file} (measured; the preset below gives the material, adhesion and load)\n"),
        None => String::new(),
    };
    let branch = if job.unloading {
        "unloading (the contact jumped in at a higher load)"
    } else {
        "loading"
    };
    format!(
        "# asperity explorer export {name}\n{surface}# preset: {} ({})\n# model: {}\n# pressure: {}\n# thickness_qr: {t}\n\
         # gamma_j_m2: {}\n# range_m: {}\n# branch: {branch}\n# reduced units: stresses by E*g = {} Pa, gap by h_rms = {} m\n",
        job.preset.name,
        job.source,
        s.model().label(),
        s.pressure(),
        s.surface_energy_j_m2(),
        s.range_m(),
        s.stress_unit(),
        s.spectrum().rms_height()
    )
}

fn write(path: &Path, text: &str) -> Result<()> {
    // atomically: an interrupted export leaves no half-written file
    crate::outfile::write_bytes("export", path, text.as_bytes())
}

/// `e` of the current scene under the next free number; returns the paths written.
pub fn export(app: &App) -> Result<Vec<String>> {
    let job = export_job(app, false);
    export_as(&job, next_number(&job.dir, &job.name)?)
}

/// Writes the files of `e` as `asperity-NAME-N…`; returns their paths.
pub fn export_as(job: &ExportJob, n: u32) -> Result<Vec<String>> {
    let name = &job.name;
    let dir = &job.dir;
    let stem = format!("asperity-{name}-{n}");
    let mut paths = Vec::new();

    let mut preset = scene_preset(&job.preset, &job.scene);
    preset.name = stem.clone();
    // the branch on screen: an export made on the unloading branch reopens on it
    preset.load.branch = job.unloading.then_some(LoadBranch::Unloading);
    // a measured surface: its file, side and periodicity, as the flags that read it
    preset.measured = job.measured.clone();
    let toml_text = toml::to_string(&preset).map_err(|e| Error::io("serialise the scene", e))?;
    let header = match &job.scene.spectrum() {
        asperity::surface::spectrum::Spectrum::Tabulated(t) if preset.measured.is_some() => format!(
            "# Scene exported by the asperity explorer on the measured spectrum of {src}.\n\
             # [measured] names its file with the side and periodicity it was read with; [surface] is\n\
             # the preset's, unused while [measured] is there. Open it with `asperity tui --preset {stem}.toml`.\n",
            src = t.source
        ),
        asperity::surface::spectrum::Spectrum::Tabulated(t) => format!(
            "# Scene exported by the asperity explorer on the measured spectrum of {src}.\n\
             # A preset names no surface file: [surface] below is the preset's, not the scene's.\n\
             # Open the scene with `asperity tui --preset {stem}.toml --surface {src}` (--psd for a PSD table).\n",
            src = t.source
        ),
        _ => format!("# Scene exported by the asperity explorer; open it with `asperity tui --preset {stem}.toml`.\n"),
    };
    let path = dir.join(format!("{stem}.toml"));
    write(&path, &(header + &toml_text))?;
    paths.push(path.display().to_string());

    // the distribution of the branch on screen
    if let Some(pr) = &job.pr {
        let mut t = scene_comment(job, &stem);
        t.push_str("sigma,density\n");
        for (s, d) in pr {
            let _ = writeln!(t, "{},{}", cell(*s), cell(*d));
        }
        let path = dir.join(format!("{stem}-pr.csv"));
        write(&path, &t)?;
        paths.push(path.display().to_string());
    }
    if let Some(sw) = &job.sweep {
        let path = dir.join(format!("{stem}-loads.csv"));
        write(&path, &(scene_comment(job, &stem) + &loads_csv(sw)))?;
        paths.push(path.display().to_string());
    }
    if let Some(th) = &job.thickness {
        let path = dir.join(format!("{stem}-thickness.csv"));
        write(&path, &(scene_comment(job, &stem) + &thickness_csv(th)))?;
        paths.push(path.display().to_string());
    }
    if let Some(g) = job.gfmd.as_ref().filter(|g| !g.sweep.is_empty() || g.a_r.is_finite()) {
        let path = dir.join(format!("{stem}-gfmd.csv"));
        write(&path, &(scene_comment(job, &stem) + &gfmd_csv(g)))?;
        paths.push(path.display().to_string());
    }
    if !job.pins.is_empty() {
        // the pinned curves, each named by what differs from the exported scene
        let mut t = scene_comment(job, &stem);
        t.push_str("pin,label,chart,x,y\n");
        for (i, p) in job.pins.iter().enumerate() {
            let label = crate::tui::model::pins::label(&p.scene, &job.scene).replace(',', ";");
            for (k, pts) in &p.curves {
                for (x, y) in pts {
                    let _ = writeln!(t, "{},{label},{},{},{}", i + 1, k.name(), cell(*x), cell(*y));
                }
            }
        }
        let path = dir.join(format!("{stem}-pins.csv"));
        write(&path, &t)?;
        paths.push(path.display().to_string());
    }
    if let Some(sd) = &job.scales {
        // the scale view: every frame's Pr(σ*, q), long format
        let mut t = scene_comment(job, &stem);
        t.push_str("frame,q_over_q_l,a_r_q,sigma_a_q,sigma,density\n");
        for (i, f) in sd.frames.iter().enumerate() {
            for (s, d) in &f.pr {
                let _ = writeln!(
                    t,
                    "{},{},{},{},{},{}",
                    i + 1,
                    cell(f.q_rel),
                    cell(f.a_r),
                    cell(f.sigma_a),
                    cell(*s),
                    cell(*d)
                );
            }
        }
        let path = dir.join(format!("{stem}-scales.csv"));
        write(&path, &t)?;
        paths.push(path.display().to_string());
    }
    Ok(paths)
}

/// Column at `i` of a per-load column that may be empty (no such curve): an empty cell then.
fn at(v: &[f64], i: usize) -> f64 {
    v.get(i).copied().unwrap_or(f64::NAN)
}

/// The load curves as CSV: the loading branch (a_r, ū/h_rms with its bracket, σ̄_c*), the
/// unloading branch inside a hysteresis window (empty cells elsewhere), and the window's
/// edges as `#` lines (`# jump_in_pressure: …`: above it the loading branch no longer
/// exists; `# pull_off_pressure: …`: below it the unloading branch no longer exists). The
/// column names are `asperity sweep`'s.
pub fn loads_csv(sw: &SweepData) -> String {
    let mut t = String::new();
    let edge = |x: Option<f64>| x.map_or_else(|| "none in the range".to_string(), |v| format!("{v:e}"));
    let _ = writeln!(t, "# jump_in_pressure: {}", edge(sw.jump_in));
    let _ = writeln!(t, "# pull_off_pressure: {}", edge(sw.pull_off));
    let rows = (0..sw.p.len()).map(|i| {
        let mut r: Vec<String> = [sw.p[i], sw.a_r[i], sw.gap_rel[i], sw.mean_contact_stress[i]]
            .map(cell)
            .to_vec();
        r.push(sw.converged.get(i).copied().unwrap_or(false).to_string());
        r.extend([&sw.gap_lower, &sw.gap_upper, &sw.a_r_unloading, &sw.gap_unloading].map(|v| cell(at(v, i))));
        r
    });
    t + &table(
        "p,a_r,mean_gap_rel,mean_contact_stress,converged,mean_gap_lower_rel,mean_gap_upper_rel,\
         a_r_unloading,mean_gap_unloading_rel",
        rows,
    ) + "\n"
}

/// The thickness chart as CSV (with the thickness chart shown): a_r against t·q_r at the
/// scene's p* — the loading branch, the unloading branch inside a hysteresis window (empty
/// cells elsewhere), the adhesionless reference — and the windows' edges as `#` lines
/// (`# jump_in_thickness_qr: …` where the small contact ends, thinner; `#
/// pull_off_thickness_qr: …` where the large one ends, thicker); `# a_r_half_space:` is t = ∞.
pub fn thickness_csv(th: &ThicknessData) -> String {
    let list = |v: &[f64]| {
        if v.is_empty() {
            "none in the range".to_string()
        } else {
            v.iter().map(|x| format!("{x:e}")).collect::<Vec<_>>().join(" ")
        }
    };
    let mut t = String::new();
    let _ = writeln!(t, "# a_r_half_space: {}", cell(th.a_r_inf));
    let _ = writeln!(t, "# jump_in_thickness_qr: {}", list(&th.jump_in));
    let _ = writeln!(t, "# pull_off_thickness_qr: {}", list(&th.pull_off));
    let rows = (0..th.t.len()).map(|i| {
        let dry = th.adhesionless.as_deref().map_or(f64::NAN, |d| at(d, i));
        [th.t[i], th.a_r[i], at(&th.a_r_unloading, i), dry].map(cell).to_vec()
    });
    t + &table("thickness_qr,a_r,a_r_unloading,a_r_adhesionless", rows) + "\n"
}

/// The GFMD results of the scene as CSV, long format: `source` is `gfmd` (the run at p* and
/// the loads of its sweep) or `theory_on_map` (the theory on the map's own discrete spectrum
/// at the same loads: the like-for-like comparison).
pub fn gfmd_csv(g: &GfmdView) -> String {
    let t = format!(
        "# GFMD on a {n}x{n} grid, {it} steps at p* = {p:e}\n",
        n = g.grid,
        it = g.iterations,
        p = g.pressure
    );

    let mut rows: Vec<(&str, f64, f64, f64, f64)> = vec![("gfmd", g.pressure, g.a_r, g.gap_rel, g.mean_contact_stress)];
    // the sweep's middle load is the run itself
    let other = |p: f64| (p / g.pressure - 1.0).abs() > 1e-9;
    rows.extend(
        g.sweep
            .iter()
            .filter(|r| other(r.0))
            .map(|r| ("gfmd", r.0, r.1, r.2, f64::NAN)),
    );
    if let Some(a) = g.theory_a_r {
        rows.push(("theory_on_map", g.pressure, a, f64::NAN, f64::NAN));
    }
    rows.extend(
        g.theory_sweep
            .iter()
            .filter(|r| other(r.0) || g.theory_a_r.is_none())
            .map(|r| ("theory_on_map", r.0, r.1, r.2, f64::NAN)),
    );
    rows.sort_by(|a, b| a.0.cmp(b.0).then(a.1.total_cmp(&b.1)));
    let cells = rows
        .into_iter()
        .map(|(src, p, a, u, s)| [src.to_string(), cell(p), cell(a), cell(u), cell(s)].to_vec());
    t + &table("source,p,a_r,mean_gap_rel,mean_contact_stress", cells) + "\n"
}

/// The chart `m` as the `s` export writes it: the same value the view drew, its title
/// followed by the scene (`scene_note`). The file renderer draws it its own way
/// ([`crate::chart::flat`]).
pub fn file_chart(m: &Chart, scene_note: &str) -> Chart {
    Chart {
        title: format!("{} — {scene_note}", m.title),
        ..m.clone()
    }
}

/// The file number of the next `e` or `s`: one past the highest number of any
/// `asperity-NAME-N…` file in `dir`, so the two keys share one sequence and never overwrite.
pub fn next_number(dir: &Path, name: &str) -> Result<u32> {
    let prefix = format!("asperity-{name}-");
    let highest = std::fs::read_dir(dir)
        .map_err(|e| Error::io_file("read", "", dir, &e))?
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let f = e.file_name().to_string_lossy().into_owned();
            let rest = f.strip_prefix(&prefix)?;
            let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
            let after = rest[digits.len()..].chars().next();
            // NAME-N.ext or NAME-N-part.ext (a preset named like NAME-2 does not count)
            matches!(after, Some('.') | Some('-'))
                .then(|| digits.parse::<u32>().ok())
                .flatten()
        })
        .max()
        .unwrap_or(0);
    if highest >= 9_999 {
        return Err(Error::io("export", "too many exports in this directory"));
    }
    Ok(highest + 1)
}

/// `s`: writes the visible charts (each once) as SVG and PNG into the export directory, as
/// `asperity-NAME-N-CHART.svg|png` (N never overwrites); returns the paths.
pub fn export_charts(app: &App) -> Result<Vec<String>> {
    let job = export_job(app, true);
    export_charts_as(&job, next_number(&job.dir, &job.name)?)
}

/// The charts of `s` ([`ExportJob::figures`]) under number `n`.
pub fn export_charts_as(job: &ExportJob, n: u32) -> Result<Vec<String>> {
    let models = &job.figures;
    if models.is_empty() {
        return Err(Error::Unsupported("no chart to save yet (nothing computed)".into()));
    }
    let name = &job.name;
    let dir = &job.dir;
    let sc = &job.scene;
    let t = if sc.thickness_qr().is_infinite() {
        "∞".to_string()
    } else {
        crate::numfmt::short(sc.thickness_qr())
    };
    let system = crate::tui::base::words::surface_name(sc).unwrap_or_else(|| job.preset.name.clone());
    let note = format!(
        "{}, {}, t·q_r = {t}, γ_s = {} J/m²",
        system,
        sc.model().label(),
        crate::numfmt::short(sc.surface_energy_j_m2())
    );
    let mut paths = Vec::new();
    for (k, m) in models {
        let spec = file_chart(m, &note);
        for (ext, write) in [
            ("svg", chart::write_svg as fn(&Chart, &Path) -> std::io::Result<()>),
            ("png", chart::write_png),
        ] {
            let path = dir.join(format!("asperity-{name}-{n}-{}.{ext}", k.name()));
            crate::outfile::write("save", &path, |tmp| write(&spec, tmp))?;
            paths.push(path.display().to_string());
        }
    }
    Ok(paths)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::base::kinds::ChartKind;

    #[test]
    fn export_writes_three_files_without_overwriting() {
        let dir = std::env::temp_dir().join(format!("asperity-export-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut app = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        app.jobs.export_dir = dir.clone();
        crate::tui::drive::compute_now(&mut app, &mut Default::default());
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
        // the first five columns are the public interface; the rest extend it
        assert!(
            rows[0].starts_with("p,a_r,mean_gap_rel,mean_contact_stress,converged,"),
            "{}",
            rows[0]
        );
        assert_eq!(rows.len(), 1 + crate::tui::effects::worker::SWEEP_POINTS);
        assert_eq!(rows[1].split(',').nth(4), Some("true"), "{}", rows[1]);
        assert!(!csv.contains("NaN") && !csv.contains("0.000e0"));
        let back = Preset::load(std::path::Path::new(&first[0])).unwrap();
        assert_eq!(crate::tui::model::app::initial_scene(&back).unwrap(), app.params.scene);
        // the exported scene is named after its file, not the stock preset
        assert_eq!(back.name, "asperity-system-1-1");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn s_saves_the_visible_charts_as_svg_and_png() {
        let dir = std::env::temp_dir().join(format!("asperity-svg-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut app = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        app.jobs.export_dir = dir.clone();
        app.set_typed(crate::tui::model::app::Param::Gamma, "0").unwrap();
        app.set_charts([ChartKind::PrLog, ChartKind::AreaRatio, ChartKind::PrLog]);
        crate::tui::drive::compute_now(&mut app, &mut Default::default());
        let paths = export_charts(&app).unwrap();
        assert_eq!(paths.len(), 4, "{paths:?}");
        assert!(paths[0].ends_with("asperity-system-1-1-pr-loglog.svg"), "{paths:?}");
        let svg = std::fs::read_to_string(&paths[0]).unwrap();
        for name in ["σ→0 asymptote", "large-σ asymptote", "theory"] {
            assert!(svg.contains(name), "{name}");
        }
        let svg = std::fs::read_to_string(&paths[2]).unwrap();
        assert!(svg.contains("eq. (18)") && svg.contains("[S] Table 1"), "{svg}");
        assert!(std::fs::read(&paths[3]).unwrap().starts_with(b"\x89PNG"));
        let again = export_charts(&app).unwrap();
        assert!(again[0].ends_with("asperity-system-1-2-pr-loglog.svg"), "{again:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_named_variant_exports_as_itself() {
        use asperity::input::model::{Model, ModelKind};
        let base = Preset::resolve("system-1").unwrap();
        let mut scene = base.scene().unwrap();
        scene.set_surface_energy_j_m2(0.0).unwrap();
        let m = Model::fudge(ModelKind::Yp08, 0.42).unwrap();
        scene.set_model(m).unwrap();
        let back = scene_preset(&base, &scene).scene().unwrap();
        assert_eq!(back.model(), m);
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
        s.set_pressure(0.02).unwrap();
        s.set_thickness_qr(f64::INFINITY).unwrap();
        s.set_model(asperity::input::model::Model::custom(0.1, 0.2, 0.5, 1.5, true).unwrap())
            .unwrap();
        let text = toml::to_string(&scene_preset(&p, &s)).unwrap();
        let back = Preset::parse(&text, "export").unwrap().scene().unwrap();
        assert_eq!(back, s);
        s.set_thickness_qr(0.5).unwrap();
        s.set_model(asperity::input::model::Model::named(2).unwrap()).unwrap();
        let text = toml::to_string(&scene_preset(&p, &s)).unwrap();
        assert_eq!(Preset::parse(&text, "export").unwrap().scene().unwrap(), s);
    }
}
