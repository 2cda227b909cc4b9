//! The contact set of one adhesionless GFMD solve on a saved height map, for a node-by-node
//! comparison with another solver (scripts/pk-vs-tamaas.py):
//!
//! ```text
//! cargo run --release --example contact_mask -- MAP.txt P_STAR OUT.bin
//! ```
//!
//! MAP.txt is a map written by `asperity gfmd --save-surface` (its spacing from the header),
//! the body has E* = 1 Pa and the load is p* times the map's rms gradient; OUT.bin gets one
//! byte per node (1 = on the wall), rows along y. Prints the nodes in contact and the solve's
//! iterations and seconds.

mod saved_map;

use asperity::gfmd::{self, GfmdOptions};
use std::sync::atomic::AtomicBool;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let [_, map, p_star, out] = &args[..] else {
        return Err("usage: contact_mask MAP.txt P_STAR OUT.bin".into());
    };
    let surface = saved_map::load(map)?;
    let problem = saved_map::problem(&surface, p_star.parse::<f64>()?);
    let sol = gfmd::solve(&problem, &GfmdOptions::default(), &mut |_| {}, &AtomicBool::new(false))?;
    let mask: Vec<u8> = sol.on_wall.iter().map(|&w| w as u8).collect();
    std::fs::write(out, &mask)?;
    println!(
        "{{\"contact_nodes\": {}, \"iterations\": {}, \"pk_iterations\": {}, \"solve_elapsed_s\": {}}}",
        mask.iter().filter(|&&m| m == 1).count(),
        sol.iterations,
        sol.pk_iterations,
        sol.elapsed_s
    );
    Ok(())
}
