//! CPU time of each part of `run` (solve, error estimate, window, gap) on given scenes.
use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::theory::{engine, gap, hysteresis};

fn cpu() -> f64 {
    let s = std::fs::read_to_string("/proc/self/stat").unwrap();
    let rest = &s[s.rfind(')').unwrap() + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    (f[11].parse::<f64>().unwrap() + f[12].parse::<f64>().unwrap()) / 100.0
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let opts = engine::Options::default();
    let mut scenes = Vec::new();
    if a.len() > 1 {
        scenes.push((
            a[1].parse::<u8>().unwrap(),
            a[2].parse::<f64>().unwrap(),
            a[3].parse::<f64>().ok(),
            a[4].parse::<f64>().unwrap(),
        ));
    } else {
        for model in [3u8, 4] {
            for t in [0.08, 0.1, 0.12, 0.15, 0.2] {
                for p in [1e-6, 1e-5, 1e-4] {
                    scenes.push((model, t, None, p));
                }
            }
        }
    }
    for (model, t, g, p) in scenes {
        let mut scene = Preset::resolve("system-2").unwrap().scene().unwrap();
        scene.model = Model::named(model).unwrap();
        scene.thickness_qr = t;
        if let Some(g) = g {
            scene.gamma = g;
        }
        scene.pressure = p;
        let mut o2 = opts;
        o2.adhesion_error_estimate = false;
        let c0 = cpu();
        let _ = engine::evaluate(&scene, &o2);
        let c1 = cpu();
        let ev = engine::evaluate(&scene, &opts);
        let c2 = cpu();
        let nst = ev
            .as_ref()
            .map(|ev| ev.branches.iter().filter(|b| b.stable).count())
            .unwrap_or(0);
        let w = match ev.as_ref().ok().and_then(|e| e.adhesive.as_deref()) {
            Some(sol) if nst >= 2 => hysteresis::window_around_from(&scene, sol, &opts.adhesion, None),
            _ => Ok(None),
        };
        let c3 = cpu();
        let jump = w.as_ref().ok().and_then(|w| w.and_then(|w| w.jump_in_pressure));
        let gp = gap::mean_gap_knowing(&scene, &opts, jump);
        let c4 = cpu();
        println!(
            "m{model} t{t} p{p:e}: solve {:.2} eval+est {:.2} window {:.2} gap {:.2} (cpu s) | a_r {:?} window {:?} gap {:?}",
            c1 - c0, c2 - c1, c3 - c2, c4 - c3,
            ev.map(|e| (e.stats.a_r, e.error_estimate, e.branches.len())), w.map(|w| w.map(|w| (w.pull_off_pressure, w.jump_in_pressure))), gp.map(|g| g.map(|g| g.relative))
        );
    }
}
