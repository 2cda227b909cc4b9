use asperity::input::model::Model;
use asperity::input::preset::Preset;
use asperity::input::scene::Scene;
use asperity::theory::adhesion::{self, AdhesionAccuracy};

fn system(n: u8, model: u8) -> Scene {
    let mut s = Preset::resolve(&format!("system-{n}")).unwrap().scene().unwrap();
    s.model = Model::named(model).unwrap();
    s
}
fn acc(s: f64, p: f64) -> AdhesionAccuracy {
    AdhesionAccuracy { steps_per_ln_q: s, points_per_width: p, explore_branches: true, ..AdhesionAccuracy::default() }
}

#[test]
#[ignore]
fn diag() {
    let which = std::env::var("DIAG").unwrap_or_default();
    if which.contains("hard") {
        let base = system(1, 3);
        let glo = base.gamma_glo();
        let mut cases = Vec::new();
        for target in [0.01, 0.1, 1.0, 10.0] {
            let mut s = base.clone();
            s.gamma = base.gamma * target / glo;
            cases.push(s);
        }
        for t in [0.01, 0.1, 1.0] {
            let mut s = system(2, 4);
            s.thickness_qr = t;
            cases.push(s);
        }
        for p in [1e-5, 1.0] {
            let mut s = base.clone();
            s.pressure = p;
            cases.push(s);
        }
        let mut s = system(2, 4); s.thickness_qr = 0.15; s.pressure = 1e-4; cases.push(s);
        for (i, s) in cases.iter().enumerate() {
            for (st, pp) in [(24.0, 10.0), (12.0, 5.0)] {
                let r = adhesion::solve(s, &acc(st, pp), None, None);
                match r {
                    Ok(sol) => eprintln!("case {i} ({st},{pp}): a_r {:.6e} res {:.1e} branches {}", sol.a_r, sol.residual, sol.branches.len()),
                    Err(e) => eprintln!("case {i} ({st},{pp}): ERR {e}"),
                }
            }
        }
    }
    if which.contains("ladder") {
        for (n, model, t) in [(1u8, 3u8, f64::INFINITY), (2, 4, f64::INFINITY), (2, 4, 0.25)] {
            let mut s = system(n, model);
            s.thickness_qr = t;
            let a_ref = adhesion::solve(&s, &acc(192.0, 40.0), None, None).unwrap().a_r;
            for (st, pp) in [(6.0, 4.0), (8.0, 5.0), (12.0, 5.0), (12.0, 8.0), (16.0, 6.0), (16.0, 8.0), (24.0, 8.0), (24.0, 10.0), (32.0, 10.0), (48.0, 12.0), (48.0, 20.0)] {
                let a = AdhesionAccuracy { explore_branches: false, ..acc(st, pp) };
                let t0 = std::time::Instant::now();
                let mut nrep = 0;
                let mut sol = None;
                while t0.elapsed().as_secs_f64() < 0.3 || nrep < 3 {
                    sol = Some(adhesion::solve(&s, &a, None, None).unwrap());
                    nrep += 1;
                }
                let dt = t0.elapsed().as_secs_f64() / nrep as f64;
                let sol = sol.unwrap();
                eprintln!("sys {n} m {model} t {t} ({st},{pp}): a_r {:.8} err {:.2e} {:.2} ms shots {}", sol.a_r, (sol.a_r / a_ref - 1.0).abs(), dt * 1e3, sol.iterations);
            }
        }
    }
}
