//! The CPU time of one adhesionless Polonsky–Keer solve on a saved height map, for the
//! thread-for-thread comparison with tamaas (scripts/pk-vs-tamaas.py, scripts/pk-time.sh):
//!
//! ```text
//! RAYON_NUM_THREADS=1 cargo run --release --example pk_time -- MAP.txt P_STAR [TOLERANCE]
//! ```
//!
//! MAP.txt is a map written by `asperity gfmd --save-surface` (its spacing from the header),
//! the body has E* = 1 Pa and the load is p* times the map's rms gradient (as the script
//! gives tamaas); TOLERANCE is the relative force residual (default 1e-8). Prints one JSON
//! object: the iterations (Polonsky–Keer's and in all), a_r, ū/h_rms, the contact nodes, the
//! final residual, and the solve's wall and CPU seconds (user + system of the process, all
//! threads, from `/proc/self/stat`; the map's reading is not in them).

mod saved_map;

use asperity::gfmd::{self, GfmdOptions, Method};
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// User + system CPU seconds of this process, from `/proc/self/stat` (fields 14 and 15, in
/// clock ticks of 1/100 s, the kernel's USER_HZ on Linux).
fn cpu_seconds() -> Result<f64, Box<dyn std::error::Error>> {
    let stat = std::fs::read_to_string("/proc/self/stat")?;
    // the command name (field 2) may hold spaces: count from the closing parenthesis
    let rest = stat.rsplit_once(')').ok_or("unreadable /proc/self/stat")?.1;
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f[11].parse::<f64>()? + f[12].parse::<f64>()?;
    Ok(ticks / 100.0)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let (map, p_star, tol) = match &args[..] {
        [_, m, p] => (m, p.parse::<f64>()?, 1e-8),
        [_, m, p, t] => (m, p.parse::<f64>()?, t.parse::<f64>()?),
        _ => return Err("usage: pk_time MAP.txt P_STAR [TOLERANCE]".into()),
    };
    let surface = saved_map::load(map)?;
    let problem = saved_map::problem(&surface, p_star);
    let opts = GfmdOptions {
        method: Method::PolonskyKeer,
        tolerance: tol,
        ..GfmdOptions::default()
    };
    let (c0, t0) = (cpu_seconds()?, Instant::now());
    let sol = gfmd::solve_from(&problem, &opts, None, &mut |_| {}, &AtomicBool::new(false))?;
    let (cpu, wall) = (cpu_seconds()? - c0, t0.elapsed().as_secs_f64());
    let m = gfmd::measure(&problem, &sol, &opts);
    println!(
        "{{\"pk_iterations\": {}, \"iterations\": {}, \"a_r\": {}, \"mean_gap_rel\": {}, \
         \"contact_nodes\": {}, \"residual\": {:e}, \"solve_wall_s\": {wall:.3}, \"solve_cpu_s\": {cpu:.2}}}",
        sol.pk_iterations, sol.iterations, m.stats.a_r, m.mean_gap_rel, m.contact_nodes, sol.residual
    );
    Ok(())
}
