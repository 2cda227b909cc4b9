//! The theory's quantities that the unloading routes of physics.md §6.6 start from, on the
//! reference set's system II cases (the 256² reduced maps GFMD ran, one map per case: the maps
//! of a case differ only in their phases, so the theory, which reads the spectrum alone, is
//! the same on each):
//!
//! - `dry`: the adhesionless contact fraction a₀(p*) of the case's scene (γ_s = 0) on the
//!   uniform ln p* grid of the mean-gap table (`theory::gap::DryGap`), from p* = 10⁻⁷ to full
//!   contact: the load p_rep(a) that holds area a without adhesion is its inverse;
//! - `loading`: the adhesive theory (models 4 and 5) at GFMD's loads 10⁻⁴ … 10⁻² (7
//!   log-spaced): a_r of the loading branch, of the unloading branch where a window opens,
//!   the wall σ_a*(q_s), the tension the contact carries (p_c*), γ̃_glo, μ_T and
//!   σ0* = γ_s/(ρE*ḡ).
//!
//! `cargo run --example unloading_theory OUT.csv` writes the table that
//! `scripts/unloading-routes.py` reads (`data/reference/unloading-theory-256.csv`).
use asperity::fit::reference_set::reference_set;
use asperity::fit::set_gauge::cases_of;
use asperity::input::model::Model;
use asperity::theory::engine::{evaluate, Options};
use asperity::theory::gap::state::DryGap;
use rayon::prelude::*;
use std::fmt::Write as _;

/// GFMD's loads on the loading path.
const LOADS: [f64; 7] = [
    1e-4,
    2.1544346900e-4,
    4.6415888336e-4,
    1e-3,
    2.1544346900e-3,
    4.6415888336e-3,
    1e-2,
];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1).ok_or("usage: unloading_theory OUT.csv")?;
    let start = std::time::Instant::now();
    let opts = Options::default();
    let cases = cases_of(reference_set(), 1)?;
    let rows: Vec<String> = cases
        .par_iter()
        .map(|c| -> Result<String, asperity::Error> {
            let scene = &c.scenes[0];
            let mut s = String::new();
            let head = format!("{},{}", c.thickness_qr, c.gamma_factor);
            if c.gamma_factor == 0.0 {
                let dry = DryGap::new(scene, 1e-7, &opts)?;
                for (i, a) in dry.a_r.iter().enumerate() {
                    let p = (dry.ln_p0 + i as f64 * dry.step).exp();
                    writeln!(s, "{head},dry,0,{p:.10e},{a:.10e},,,,0,,").unwrap();
                }
                return Ok(s);
            }
            let sigma0 = scene.surface_energy_j_m2() / scene.range_m() / scene.stress_unit();
            for m in [4u8, 5] {
                let sc = scene.clone().with_model(Model::named(m)?)?;
                for &p in &LOADS {
                    let ev = evaluate(&sc.clone().with_pressure(p)?, &opts)?;
                    let unl = ev.unloading_a_r.map_or(String::new(), |a| format!("{a:.10e}"));
                    let load = ev.contact_loads.first().copied().unwrap_or(p);
                    writeln!(
                        s,
                        "{head},loading,{m},{p:.10e},{:.10e},{unl},{:.10e},{load:.10e},{:.6e},{:.6e},{sigma0:.6e}",
                        ev.stats.a_r,
                        ev.sigma_a,
                        ev.gamma_glo,
                        sc.tabor()
                    )
                    .unwrap();
                }
            }
            Ok(s)
        })
        .collect::<Result<_, _>>()?;
    let mut csv = String::from(
        "thickness_qr,gamma_factor,kind,model,p,a_r,a_r_unloading,sigma_a,contact_load,gamma_glo,tabor,sigma0\n",
    );
    for r in rows {
        csv += &r;
    }
    std::fs::write(&out, csv)?;
    println!("wrote {out} in {:.1} s", start.elapsed().as_secs_f64());
    Ok(())
}
