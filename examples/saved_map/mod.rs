//! A height map saved by `asperity gfmd --save-surface`, read for the examples that compare
//! asperity's adhesionless solve with another solver's on the same file (scripts/pk-vs-tamaas.py).

use asperity::gfmd::Problem;
use asperity::surface::heightmap::Surface;

/// The map in `path`, its spacing from the header line.
pub fn load(path: &str) -> Result<Surface, Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path)?;
    let spacing: f64 = text
        .lines()
        .next()
        .and_then(|l| l.split("spacing ").nth(1))
        .and_then(|s| s.split_whitespace().next())
        .ok_or("no spacing in the map's header")?
        .parse()?;
    let n = text.lines().filter(|l| !l.starts_with('#')).count();
    Ok(Surface::parse(&text, path, n as f64 * spacing)?)
}

/// The adhesionless problem on `surface` that the script hands tamaas: a half-space of
/// E* = 1 Pa under the mean pressure p* times the map's rms gradient.
pub fn problem(surface: &Surface, p_star: f64) -> Problem<'_> {
    Problem {
        surface,
        modulus: 1.0,
        thickness: f64::INFINITY,
        pressure: p_star * surface.rms_gradient(),
        gamma: 0.0,
        range: 1e-9,
    }
}
