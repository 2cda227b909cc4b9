//! The mean gap with adhesion against GFMD (docs/physics.md §5.1): the theory's estimate on the
//! same map's discrete spectrum against GFMD's ⟨g⟩, with and without adhesion.

use asperity::gfmd::{self, GfmdOptions, GfmdSetup, GridSpec};
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::theory::engine::{evaluate, Options};
use asperity::theory::gap;
use asperity::tolerances::*;
use std::sync::atomic::AtomicBool;

/// One GFMD load: p*, a_r, ⟨g⟩/h_rms, the compressive force ⟨max(σ, 0)⟩* and the tensile
/// force ⟨min(σ, 0)⟩* per nominal area.
#[derive(Debug, Clone, Copy)]
struct GfmdPoint {
    p: f64,
    a_r: f64,
    gap: f64,
    compressive: f64,
    tensile: f64,
}

/// GFMD (FIRE) on one map at increasing loads, each warm-started from the previous (a loading
/// path).
fn gfmd_loading(setup: &GfmdSetup, ps: &[f64]) -> Vec<GfmdPoint> {
    let prep = gfmd::prepare(setup).unwrap();
    let opts = GfmdOptions {
        method: gfmd::problem::Method::Fire,
        ..GfmdOptions::default()
    };
    let cancel = AtomicBool::new(false);
    let mut start: Option<Vec<f64>> = None;
    let mut out = Vec::new();
    for &p in ps {
        let pr = prep.problem(p);
        let sol = gfmd::solve_from(&pr, &opts, start.as_deref(), &mut |_| {}, &cancel).unwrap();
        let m = gfmd::measure(&pr, &sol, &opts);
        let unit = m.stress_unit;
        let n = sol.stress.len() as f64;
        let compressive = sol.stress.iter().map(|s| s.max(0.0)).sum::<f64>() / n / unit;
        let tensile = sol.stress.iter().map(|s| s.min(0.0)).sum::<f64>() / n / unit;
        out.push(GfmdPoint {
            p,
            a_r: m.stats.a_r,
            gap: m.mean_gap_rel,
            compressive,
            tensile,
        });
        start = Some(sol.gap);
    }
    out
}

fn setup(preset: &str, t: f64, gamma: Option<f64>, grid: Option<GridSpec>) -> GfmdSetup {
    let pre = Preset::resolve(preset).unwrap();
    let mut scene: Scene = pre.scene().unwrap();
    scene.set_thickness_qr(t).unwrap();
    if let Some(g) = gamma {
        scene.set_surface_energy_j_m2(g).unwrap();
    }
    GfmdSetup {
        scene,
        grid: grid.unwrap_or_else(|| GridSpec::from_preset(pre.gfmd.as_ref().unwrap())),
        seed: 1,
        surface: None,
        rescale: true,
    }
}

/// The 12 scenes of the comparison: (preset, t·q_r, loads).
fn scenes() -> Vec<(&'static str, f64, Vec<f64>)> {
    let mut v: Vec<(&'static str, f64, Vec<f64>)> = [f64::INFINITY, 0.3, 0.15, 0.1]
        .into_iter()
        .map(|t| ("system-2", t, vec![1e-3, 5e-3, 2e-2]))
        .collect();
    v.push(("system-1", f64::INFINITY, vec![0.01, 0.05]));
    v
}

/// The reduced map of the comparison: the presets' [gfmd] grid, L/λ_r = 2, λ_r/λ_s = 32,
/// λ_s/Δa = 8 (512²; γ_s and ρ rescaled to keep γ̃_glo and the Tabor parameter), seed 1.
const MAP: GridSpec = GridSpec {
    system_size_ratio: 2.0,
    bandwidth: 32.0,
    points_per_short_wavelength: 8.0,
};

/// By hand: GFMD (FIRE, residual 1e-8) on 512² maps ([`MAP`]) for the 14 points, with and
/// without adhesion, written to `tests/fixtures/gap_gfmd_512.csv`.
/// `cargo test --release --test gap_gfmd -- --ignored --nocapture gfmd_cache`
#[test]
#[ignore]
fn gfmd_cache_by_hand() {
    let mut csv = String::from("preset,thickness_qr,adhesion,p,a_r,gap_rel,compressive,tensile\n");
    for (name, t, ps) in scenes() {
        for adh in [false, true] {
            let s = setup(name, t, (!adh).then_some(0.0), Some(MAP));
            let t0 = std::time::Instant::now();
            let rows = gfmd_loading(&s, &ps);
            eprintln!("{name} t={t} adh={adh}: {:.1} s", t0.elapsed().as_secs_f64());
            for r in rows {
                let line = format!(
                    "{name},{t},{},{:e},{:.6},{:.6},{:.6e},{:.6e}\n",
                    adh as u8, r.p, r.a_r, r.gap, r.compressive, r.tensile
                );
                eprint!("{line}");
                csv.push_str(&line);
            }
        }
    }
    std::fs::write(
        concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/gap_gfmd_512.csv"),
        csv,
    )
    .unwrap();
}

/// One row of the cached GFMD table.
#[derive(Debug, Clone)]
struct Cached {
    preset: String,
    t: f64,
    adhesion: bool,
    point: GfmdPoint,
}

fn read_cache() -> Vec<Cached> {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/gap_gfmd_512.csv")).unwrap();
    text.lines()
        .skip(1)
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let x = |i: usize| f[i].parse::<f64>().unwrap();
            Cached {
                preset: f[0].into(),
                t: if f[1] == "inf" { f64::INFINITY } else { x(1) },
                adhesion: f[2] == "1",
                point: GfmdPoint {
                    p: x(3),
                    a_r: x(4),
                    gap: x(5),
                    compressive: x(6),
                    tensile: x(7),
                },
            }
        })
        .collect()
}

/// ∫ over σ > lo.. of σ·Pr on a sampled curve (trapezoid), split at 0: (tensile, compressive).
fn split_force(pr: &asperity::contact::PrCurve) -> (f64, f64) {
    let (mut neg, mut pos) = (0.0, 0.0);
    for w in pr.sigma.windows(2).zip(pr.density.windows(2)) {
        let ((s0, s1), (d0, d1)) = ((w.0[0], w.0[1]), (w.1[0], w.1[1]));
        let f = 0.5 * (s0 * d0 + s1 * d1) * (s1 - s0);
        if 0.5 * (s0 + s1) < 0.0 {
            neg += f;
        } else {
            pos += f;
        }
    }
    (neg, pos)
}

/// Exploration by hand: the candidate load mappings of physics.md §5.1 on the cached GFMD
/// points (A: p* + X, the load the contact carries — the one chosen; B: its compressive part
/// alone; C: the load with the same a_r; D: p* + the tension inside the contact).
#[test]
#[ignore]
fn explore_mappings_by_hand() {
    let cache = read_cache();
    let opts = Options::default();
    for c in cache.iter().filter(|c| c.adhesion) {
        let zero = cache
            .iter()
            .find(|z| !z.adhesion && z.preset == c.preset && z.t == c.t && z.point.p == c.point.p)
            .unwrap();
        // GFMD: adhesionless gap at the compressive force, by log-interpolation over the cached
        // adhesionless loads of this map
        let prep = gfmd::prepare(&setup(&c.preset, c.t, None, Some(MAP))).unwrap();
        let th = prep.theory_scene(c.point.p).unwrap();
        let mut th0 = th.clone();
        th0.set_surface_energy_j_m2(0.0).unwrap();
        let u0 = |p: f64| {
            let mut s = th0.clone();
            s.set_pressure(p).unwrap();
            gap::mean_gap(&s, &opts).unwrap().relative
        };
        let a0 = |p: f64| {
            let mut s = th0.clone();
            s.set_pressure(p).unwrap();
            evaluate(&s, &opts).unwrap().stats.a_r
        };
        let ev = evaluate(&th, &opts).unwrap();
        let (neg, pos) = split_force(&ev.stats.pr);
        let p0 = c.point.p;
        let x = pos + neg - p0;
        // a_r-matched load
        let (mut lo, mut hi) = (p0, 10.0 * p0);
        while a0(hi) < ev.stats.a_r && hi < 10.0 {
            hi *= 4.0;
        }
        for _ in 0..40 {
            let m = (lo * hi).sqrt();
            if a0(m) < ev.stats.a_r {
                lo = m
            } else {
                hi = m
            }
        }
        let p_ar = (lo * hi).sqrt();
        let g0 = u0(p0);
        println!(
            "{} t={} p={:.0e} | GFMD a0 {:.4} a {:.4} u0 {:.4} u {:.4} ratio {:.3} Fc/p {:.3} dmt {:.4} | th a0 {:.4} a {:.4} X/p {:.3} Tc/p {:.3} u0 {:.4} | A {:.4} B {:.4} C(ar) {:.4} D {:.4} | old {:.4} lower {:.4}",
            c.preset, c.t, p0, zero.point.a_r, c.point.a_r, zero.point.gap, c.point.gap, c.point.gap / zero.point.gap,
            c.point.compressive / p0, zero.point.gap * u0(c.point.compressive) / u0(p0),
            a0(p0), ev.stats.a_r, x / p0, -neg / p0, g0,
            u0(p0 + x), u0(pos), u0(p_ar), u0(p0 - neg),
            gap::mean_gap(&th, &opts).map_or(f64::NAN, |g| g.relative),
            gap::mean_gap(&th, &opts).map_or(f64::NAN, |g| g.lower),
        );
    }
}

/// One point of the comparison: GFMD and the theory (on the same map's discrete spectrum) with
/// and without adhesion.
#[derive(Debug, Clone, Copy)]
struct Compared {
    t: f64,
    p: f64,
    gfmd_dry: GfmdPoint,
    gfmd_adh: GfmdPoint,
    theory_dry_a: f64,
    theory_dry: f64,
    theory_a: f64,
    theory: gap::MeanGap,
}

impl Compared {
    fn err_dry(&self) -> f64 {
        self.theory_dry / self.gfmd_dry.gap - 1.0
    }
    fn err(&self) -> f64 {
        self.theory.relative / self.gfmd_adh.gap - 1.0
    }
    /// The targets: on the half-space within 10 % of GFMD; on slabs no worse than the
    /// adhesionless theory on the same map plus 10 points; the sign of the adhesion effect.
    fn check(&self, half_space_target: bool) -> Result<(), String> {
        let sign_gfmd = self.gfmd_adh.gap < self.gfmd_dry.gap;
        let sign_theory = self.theory.relative < self.theory_dry;
        if sign_gfmd != sign_theory {
            return Err(format!("sign of the adhesion effect: {self:?}"));
        }
        let limit = if self.t.is_infinite() && half_space_target {
            GAP_GFMD_HALF_SPACE_REL
        } else {
            self.err_dry().abs() + GAP_GFMD_SLAB_EXTRA
        };
        if self.err().abs() > limit {
            return Err(format!("error {:.3} > {limit:.3}: {self:?}", self.err()));
        }
        Ok(())
    }
    fn row(&self, preset: &str) -> String {
        let t = if self.t.is_infinite() {
            "∞".to_string()
        } else {
            format!("{}", self.t)
        };
        let g = &self.theory;
        format!(
            "| {preset} | {t} | {:.0e} | {:.4} | {:.4} | {:.4} ({:+.1} %) | {:.4} | {:.4} | {:.4} | {:.4} ({:+.1} %) | [{:.4}, {:.4}] | {:.4} | {:.2} |",
            self.p,
            self.gfmd_dry.gap,
            self.gfmd_adh.gap,
            self.theory_dry,
            100.0 * self.err_dry(),
            self.gfmd_adh.gap / self.gfmd_dry.gap,
            g.relative / self.theory_dry,
            self.gfmd_adh.a_r,
            g.relative,
            100.0 * self.err(),
            g.lower,
            g.upper,
            self.theory_a,
            g.contact_load / self.p,
        )
    }
}

const TABLE_HEAD: &str = "| system | t·q_r | p* | GFMD ū₀ | GFMD ū | theory ū₀ (err) | GFMD ū/ū₀ | theory ū/ū₀ | GFMD a_r | theory ū (err) | theory bracket | theory a_r | p_c/p* |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|";

/// The theory on the map's discrete spectrum at GFMD's points.
fn compare(s_adh: &GfmdSetup, t: f64, dry: &[GfmdPoint], adh: &[GfmdPoint]) -> Vec<Compared> {
    let prep = gfmd::prepare(s_adh).unwrap();
    let opts = Options::default();
    dry.iter()
        .zip(adh)
        .map(|(d, a)| {
            let th = prep.theory_scene(a.p).unwrap();
            let mut th0 = th.clone();
            th0.set_surface_energy_j_m2(0.0).unwrap();
            let g = gap::mean_gap(&th, &opts).unwrap();
            Compared {
                t,
                p: a.p,
                gfmd_dry: *d,
                gfmd_adh: *a,
                theory_dry_a: evaluate(&th0, &opts).unwrap().stats.a_r,
                theory_dry: gap::mean_gap(&th0, &opts).unwrap().relative,
                theory_a: evaluate(&th, &opts).unwrap().stats.a_r,
                theory: g,
            }
        })
        .collect()
}

/// GFMD against the theory on small maps (128²: L/λ_r = 2, λ_r/λ_s = 8, λ_s/Δa = 8; system II
/// with γ̃_glo and μ_T kept), half-space at p* = 5e-3 and 2e-2, t·q_r = 0.3 at 5e-3: adhesion lowers
/// the gap in both, and the theory's adhesive gap misses GFMD's by no more than its
/// adhesionless gap does plus 10 points.
#[test]
fn theory_and_gfmd_agree_on_the_adhesive_gap_on_small_maps() {
    let small = GridSpec {
        system_size_ratio: 2.0,
        bandwidth: 8.0,
        points_per_short_wavelength: 8.0,
    };
    // (t·q_r = 0.3 at 2e-2 misses by 2 points on this map: +12.4 % where the adhesionless
    // theory is +0.1 %; on the 512² map it is −4.1 % against +4.6 %)
    for (t, ps) in [(f64::INFINITY, vec![5e-3, 2e-2]), (0.3, vec![5e-3])] {
        let adh = setup("system-2", t, None, Some(small));
        let dry = gfmd_loading(&setup("system-2", t, Some(0.0), Some(small)), &ps);
        let wet = gfmd_loading(&adh, &ps);
        for c in compare(&adh, t, &dry, &wet) {
            eprintln!("{}", c.row("II (128²)"));
            c.check(false).unwrap();
        }
    }
}

/// The points that miss the error targets (the sign is right at all of them), with the
/// reason (BENCHMARKS.md): (system, t·q_r, p*).
const KNOWN_MISSES: [(&str, f64, f64); 6] = [
    // the thin slabs at small loads: the theory's a_r is 2× GFMD's (its jump into contact is
    // too abrupt, [S] §3.2), and the gap follows the contact it has
    ("system-2", 0.15, 1e-3),
    ("system-2", 0.15, 5e-3),
    ("system-2", 0.1, 1e-3),
    ("system-2", 0.1, 5e-3),
    // theory a_r 0.78 against GFMD's 0.64, and adhesion lowering GFMD's gap by 64 %, the
    // theory's by 53 %
    ("system-2", 0.1, 2e-2),
    // the adhesionless theory itself is 12.7 % above GFMD on this map; the adhesive one 13.3 %
    ("system-1", f64::INFINITY, 1e-2),
];

/// The slow version (BENCHMARKS.md): the 14 points on the cached 512² GFMD results
/// (`gfmd_cache_by_hand`), the theory on the same maps, printed as a markdown table. The sign
/// of the adhesion effect must be right everywhere, the error targets everywhere but
/// at [`KNOWN_MISSES`] (and there they must still miss: an improvement updates the list).
/// `cargo test --release --test gap_gfmd -- --ignored --nocapture twelve`
#[test]
#[ignore]
fn twelve_scenes_against_cached_gfmd() {
    let cache = read_cache();
    println!("{TABLE_HEAD}");
    let mut failures = Vec::new();
    for (name, t, ps) in scenes() {
        let pick = |adh: bool| -> Vec<GfmdPoint> {
            ps.iter()
                .map(|&p| {
                    cache
                        .iter()
                        .find(|c| {
                            c.preset == name && c.t == t && c.adhesion == adh && (c.point.p / p - 1.0).abs() < 1e-9
                        })
                        .unwrap_or_else(|| panic!("{name} t = {t} p = {p} adhesion {adh} not cached"))
                        .point
                })
                .collect()
        };
        let rows = compare(&setup(name, t, None, Some(MAP)), t, &pick(false), &pick(true));
        for c in rows {
            println!("{}", c.row(if name == "system-1" { "I" } else { "II" }));
            eprintln!("  theory a_r without adhesion {:.4}", c.theory_dry_a);
            let known = KNOWN_MISSES.contains(&(name, t, c.p));
            match c.check(true) {
                Err(e) if e.starts_with("sign") || !known => failures.push(e),
                Ok(()) if known => failures.push(format!("meets the targets now: {c:?}")),
                _ => {}
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
