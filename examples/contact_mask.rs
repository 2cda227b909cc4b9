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

use asperity::gfmd::{self, GfmdOptions, Problem};
use asperity::surface::heightmap::Surface;
use std::sync::atomic::AtomicBool;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let [_, map, p_star, out] = &args[..] else {
        return Err("usage: contact_mask MAP.txt P_STAR OUT.bin".into());
    };
    let text = std::fs::read_to_string(map)?;
    let spacing: f64 = text
        .lines()
        .next()
        .and_then(|l| l.split("spacing ").nth(1))
        .and_then(|s| s.split_whitespace().next())
        .ok_or("no spacing in the map's header")?
        .parse()?;
    let n = text.lines().filter(|l| !l.starts_with('#')).count();
    let surface = Surface::parse(&text, map, n as f64 * spacing)?;
    let problem = Problem {
        surface: &surface,
        modulus: 1.0,
        thickness: f64::INFINITY,
        pressure: p_star.parse::<f64>()? * surface.rms_gradient(),
        gamma: 0.0,
        range: 1e-9,
    };
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
