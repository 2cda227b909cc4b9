//! CPU time per adhesive `run` computation (the solve with its error estimate, inside a
//! hysteresis window the window's edges, and the mean gap of each branch) on seeded random
//! scenes: systems I and II, models
//! 1–4, t·q_r log-uniform in 1e-2…1e3 or ∞, γ_s log-uniform in 1e-3…1.5 J/m², p*
//! log-uniform in 1e-9…1. Prints every call and the slowest ten (BENCHMARKS.md):
//! `cargo run --release --example random_scenes -- [N] [SEED]`; with `hard` instead of N, the
//! hard grid of `run` (system II, models 3 and 4, t·q_r 0.08…0.2, p* 1e-6…1e-4, the preset's
//! γ_s).

use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::theory::{engine, gap, hysteresis};

/// CPU seconds of this process (all threads; the calls run one at a time).
fn cpu() -> f64 {
    let s = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let rest = s.rfind(')').map_or("", |i| &s[i + 2..]);
    let f: Vec<f64> = rest.split_whitespace().map(|x| x.parse().unwrap_or(0.0)).collect();
    (f.get(11).copied().unwrap_or(0.0) + f.get(12).copied().unwrap_or(0.0)) / 100.0
}

/// xorshift64*: a uniform number in [0, 1).
fn uniform(state: &mut u64) -> f64 {
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let hard = args.get(1).is_some_and(|a| a == "hard");
    let n: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(200);
    let mut state: u64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(28);
    let mut scenes = Vec::new();
    if hard {
        let g = Preset::resolve("system-2")
            .unwrap()
            .scene()
            .unwrap()
            .surface_energy_j_m2();
        for model in [3u8, 4] {
            for t in [0.08, 0.1, 0.12, 0.15, 0.2] {
                for p in [1e-6, 1e-5, 1e-4] {
                    scenes.push((2, model, t, g, p));
                }
            }
        }
    } else {
        for _ in 0..n {
            let system = if uniform(&mut state) < 0.5 { 1 } else { 2 };
            let model = 1 + (uniform(&mut state) * 4.0) as u8;
            let t = if uniform(&mut state) < 0.2 {
                f64::INFINITY
            } else {
                10f64.powf(-2.0 + 5.0 * uniform(&mut state))
            };
            let gamma = 10f64.powf(-3.0 + 3.176 * uniform(&mut state));
            let p = 10f64.powf(-9.0 * uniform(&mut state));
            scenes.push((system, model, t, gamma, p));
        }
    }
    let n = scenes.len();
    let opts = engine::Options::default();
    let mut rows = Vec::new();
    for (i, &(system, model, t, gamma, p)) in scenes.iter().enumerate() {
        let mut scene = Preset::resolve(&format!("system-{system}")).unwrap().scene().unwrap();
        scene.set_model(Model::named(model).unwrap()).unwrap();
        scene.set_thickness_qr(t).unwrap();
        scene.set_surface_energy_j_m2(gamma).unwrap();
        scene.set_pressure(p).unwrap();
        let c0 = cpu();
        let outcome = engine::evaluate(&scene, &opts).and_then(|ev| {
            let w = match ev.adhesive.as_deref() {
                Some(sol) if ev.branches.iter().filter(|b| b.stable).count() >= 2 => {
                    hysteresis::window_around_from(&scene, sol, &opts.adhesion, None)?
                }
                _ => None,
            };
            let g = gap::mean_gap_of(&scene, &ev, &opts).ok();
            Ok((ev.stats.a_r, ev.error_estimate, w.is_some(), g))
        });
        let spent = cpu() - c0;
        let what = match &outcome {
            Ok((a, e, w, g)) => {
                let (u, lo, hi, ue) = g.map_or((f64::NAN, f64::NAN, f64::NAN, f64::NAN), |g| {
                    (g.relative, g.lower, g.upper, g.error)
                });
                format!(
                    "a_r {a:.6e} +- {e:.1e} gap {u:.6e} +- {ue:.1e} [{lo:.6e}, {hi:.6e}]{}",
                    if *w { " (window)" } else { "" }
                )
            }
            Err(e) => format!("refused: {e}"),
        };
        let line = format!("system {system} model {model} t*q_r {t:.4e} gamma {gamma:.4e} p* {p:.4e}: {what}");
        println!("{i:4} {spent:6.2} s  {line}");
        rows.push((spent, line));
    }
    rows.sort_by(|a, b| b.0.total_cmp(&a.0));
    println!("slowest:");
    for (spent, line) in rows.iter().take(10) {
        println!("{spent:6.2} s  {line}");
    }
    let mut cpus: Vec<f64> = rows.iter().map(|r| r.0).collect();
    cpus.sort_by(f64::total_cmp);
    let at = |f: f64| cpus[((f * (n as f64 - 1.0)).round() as usize).min(n - 1)];
    println!(
        "CPU median {:.3} s, p95 {:.3} s, max {:.3} s",
        at(0.5),
        at(0.95),
        at(1.0)
    );
    let refused = rows.iter().filter(|r| r.1.contains("refused")).count();
    println!(
        "{n} scenes, {refused} refused, total {:.1} s CPU",
        rows.iter().map(|r| r.0).sum::<f64>()
    );
}
