//! Height maps on periodic grids: seeded random self-affine surfaces, and loading/saving maps
//! as text.
//!
//! A [`Surface`] holds `ny` rows of `nx` heights h(x, y) in metres (row-major, `heights[y·nx +
//! x]`) on a square lattice of spacing Δa, periodic in both directions; the system is
//! L_x × L_y = nx·Δa × ny·Δa. Generated and loaded maps are square (N×N); the solver also takes
//! N_x × N_y strips (e.g. a profile varying along x only).
//!
//! ## Generation by Fourier filtering (physics.md §1, §6)
//!
//! With h̃(q) = (1/A)∫d²r e^{−iq·r} h(r) and C(q) = A⟨|h̃|²⟩/(2π)², every mode q = (2π/L)(m, n)
//! with 0 < |q| ≤ q_s gets the deterministic amplitude |h̃(q)| = √(C(q)(2π)²/A) and a phase
//! drawn uniformly from [0, 2π); h̃(−q) = h̃(q)* (Hermitian, so the map is real); modes that are
//! their own conjugate (Nyquist) get a random sign; q = 0 and |q| > q_s are zero. The whole
//! spectrum is then rescaled so that the discrete rms gradient ḡ² = Σ_q |q|²|h̃(q)|² equals the
//! target ḡ of the continuum spectrum exactly. The random numbers come from a SplitMix64
//! generator ([`SplitMix64`]): a seed gives the same map bit for bit on every platform.
//!
//! ## Text format
//!
//! One row (fixed y) per line, heights in metres separated by whitespace; blank lines and
//! lines starting with `#` are ignored. The physical size L is not in the file (the caller gives
//! it).

use crate::error::{check_in, Error, Field, Result};
use crate::surface::spectrum::{Discrete, SelfAffine, LENGTH_RANGE_M, RMS_GRADIENT_RANGE};
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;
use std::path::Path;

/// Largest grid side accepted. A GFMD run holds about 100 bytes per node (1024²: 100 MB), so
/// 8192² needs about 7 GB.
pub const MAX_GRID: usize = 8192;

/// SplitMix64 (Steele, Lea & Flood 2014): a tiny, fast, well-mixed 64-bit generator; enough
/// for random phases and fully reproducible.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// Generator seeded with `seed`.
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1) with 53 random bits.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// A periodic height map.
#[derive(Debug, Clone, PartialEq)]
pub struct Surface {
    /// Points per row (x).
    pub nx: usize,
    /// Rows (y).
    pub ny: usize,
    /// Lattice spacing Δa (m).
    pub spacing: f64,
    /// Heights (m), `heights[y * nx + x]`.
    pub heights: Vec<f64>,
}

impl Surface {
    /// Builds a map, checking sizes, spacing and finiteness.
    pub fn new(nx: usize, ny: usize, spacing: f64, heights: Vec<f64>) -> Result<Self> {
        if nx < 2 || ny < 1 || nx > MAX_GRID || ny > MAX_GRID {
            return Err(Error::invalid_text(
                Field::Grid,
                format!("{nx} x {ny}"),
                format!("2 <= nx <= {MAX_GRID}, 1 <= ny <= {MAX_GRID}"),
            ));
        }
        if heights.len() != nx * ny {
            return Err(Error::invalid_text(
                Field::HeightMap,
                format!("{} values", heights.len()),
                format!("nx * ny = {} values", nx * ny),
            ));
        }
        if !(spacing.is_finite() && spacing > 0.0) {
            return Err(Error::invalid(
                Field::SystemSize,
                spacing * nx as f64,
                "a finite length > 0 (m)",
            ));
        }
        if let Some(bad) = heights.iter().position(|x| !x.is_finite()) {
            return Err(Error::invalid(
                Field::Other(format!("surface[{}][{}]", bad / nx, bad % nx)),
                heights[bad],
                "a finite height (m)",
            ));
        }
        Ok(Surface {
            nx,
            ny,
            spacing,
            heights,
        })
    }

    /// L_x = nx·Δa (m).
    pub fn size_x(&self) -> f64 {
        self.nx as f64 * self.spacing
    }
    /// L_y = ny·Δa (m).
    pub fn size_y(&self) -> f64 {
        self.ny as f64 * self.spacing
    }
    /// Whether the map is N×N.
    pub fn is_square(&self) -> bool {
        self.nx == self.ny
    }

    /// h_rms about the mean (m).
    pub fn rms_height(&self) -> f64 {
        let n = self.heights.len() as f64;
        let mean = self.heights.iter().sum::<f64>() / n;
        (self.heights.iter().map(|h| (h - mean).powi(2)).sum::<f64>() / n).sqrt()
    }

    /// Discrete rms gradient ḡ = (Σ_q |q|²|h̃(q)|²)^{1/2} (spectral, exact for the periodic
    /// map).
    pub fn rms_gradient(&self) -> f64 {
        let mut plan = crate::numerics::fft2::RealFft2::new(self.nx, self.ny);
        let mut spec = vec![Complex64::new(0.0, 0.0); plan.spectrum_len()];
        plan.forward(&self.heights, &mut spec);
        let norm = 1.0 / (self.nx * self.ny) as f64;
        let mut s = 0.0;
        for kx in 0..plan.nh() {
            for ky in 0..self.ny {
                let q2 = wave_number_sq(kx, ky, self.nx, self.ny, self.spacing);
                s += plan.weight(kx) * q2 * (spec[ky * plan.nh() + kx] * norm).norm_sqr();
            }
        }
        s.sqrt()
    }

    /// The discrete spectrum of a square map (for the theory on the same realisation).
    pub fn discrete_spectrum(&self, q_r: f64) -> Result<Discrete> {
        if !self.is_square() {
            return Err(Error::Unsupported(format!(
                "the theory needs an N x N map (this one is {} x {})",
                self.nx, self.ny
            )));
        }
        Discrete::from_height_map(&self.heights, self.nx, self.size_x(), q_r)
    }

    /// Checks that the map can be a contact problem: not flat, and a discrete rms gradient ḡ
    /// (which sets the stress unit E*ḡ) that is finite and inside
    /// [`RMS_GRADIENT_RANGE`] (heights of 1e200 m, or a side of 1e300 m, fail here rather than
    /// as a pressure that over- or underflows).
    pub fn check_rough(&self) -> Result<()> {
        if self.heights.iter().all(|&h| h == self.heights[0]) {
            return Err(Error::invalid_text(
                Field::HeightMap,
                "a flat map",
                "a height map with some roughness",
            ));
        }
        let g = self.rms_gradient();
        let (lo, hi) = RMS_GRADIENT_RANGE;
        if !(g >= lo && g <= hi && self.rms_height().is_finite()) {
            return Err(Error::invalid_text(
                Field::HeightMap,
                // the measured gradient to 4 digits: a message, not a result
                format!(
                    "a map of rms gradient {g:.3e} (side L = {} m)",
                    crate::error::fmt_value(self.size_x())
                ),
                format!(
                    "a map whose rms gradient lies in [{}, {}] (check the heights' unit and L)",
                    crate::error::fmt_value(lo),
                    crate::error::fmt_value(hi)
                ),
            ));
        }
        Ok(())
    }

    /// Parses the text format; `source` names the file in errors; `size` is the side L (m)
    /// of the (square) map.
    pub fn parse(text: &str, source: &str, size: f64) -> Result<Surface> {
        let bad = |line: usize, what: String| {
            Error::invalid_text(
                Field::HeightMap,
                format!("{source}:{line}: {what}"),
                "a square matrix of finite heights (m), one row per line",
            )
        };
        let mut rows: Vec<Vec<f64>> = Vec::new();
        let mut first_line = 0;
        for (i, line) in text.lines().enumerate() {
            let t = line.trim();
            if t.is_empty() || t.starts_with('#') {
                continue;
            }
            let mut row = Vec::new();
            for tok in t.split_whitespace() {
                let v: f64 = tok.parse().map_err(|_| bad(i + 1, format!("'{tok}' (not a number)")))?;
                if !v.is_finite() {
                    return Err(bad(i + 1, format!("'{tok}' (not finite)")));
                }
                row.push(v);
            }
            if let Some(r0) = rows.first() {
                if row.len() != r0.len() {
                    return Err(bad(
                        i + 1,
                        format!("a row of {} values (line {} has {})", row.len(), first_line, r0.len()),
                    ));
                }
            } else {
                first_line = i + 1;
            }
            rows.push(row);
        }
        if rows.is_empty() {
            return Err(bad(1, "an empty file".into()));
        }
        let (ny, nx) = (rows.len(), rows[0].len());
        if nx != ny {
            return Err(Error::invalid_text(
                Field::HeightMap,
                format!("{source}: {ny} rows x {nx} columns"),
                "a square N x N matrix",
            ));
        }
        if nx < 4 {
            return Err(Error::invalid_text(
                Field::HeightMap,
                format!("{source}: {nx} x {nx}"),
                "N >= 4",
            ));
        }
        check_in(Field::SystemSize, size, LENGTH_RANGE_M.0, LENGTH_RANGE_M.1)?;
        Surface::new(nx, ny, size / nx as f64, rows.concat())
    }

    /// Reads a map from a file (text format); `size` is the side L (m).
    pub fn load(path: &Path, size: f64) -> Result<Surface> {
        use crate::input::file::{read_text, MAX_INPUT_BYTES};
        let expected = "a height map as rows of numbers";
        let text = read_text(path, "surface", Field::HeightMap, MAX_INPUT_BYTES, expected)?;
        Surface::parse(&text, &path.display().to_string(), size)
    }

    /// The text format (17 significant digits: loading gives the same map bit for bit).
    pub fn to_text(&self) -> String {
        let mut s = String::with_capacity(self.heights.len() * 25);
        s.push_str(&format!(
            "# asperity height map: {} x {} points, spacing {:e} m, heights in m\n",
            self.nx, self.ny, self.spacing
        ));
        for row in self.heights.chunks(self.nx) {
            let line: Vec<String> = row.iter().map(|h| format!("{h:.16e}")).collect();
            s.push_str(&line.join(" "));
            s.push('\n');
        }
        s
    }

    /// Writes the map in the text format.
    pub fn save(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_text()).map_err(|e| Error::io_file("write", "surface", path, &e))
    }
}

/// |q|² of stored mode (kx, ky) of an nx×ny grid with spacing `da` (kx ≥ 0, ky wrapped).
pub fn wave_number_sq(kx: usize, ky: usize, nx: usize, ny: usize, da: f64) -> f64 {
    let my = if ky <= ny / 2 { ky as f64 } else { ky as f64 - ny as f64 };
    let qx = 2.0 * PI * kx as f64 / (nx as f64 * da);
    let qy = 2.0 * PI * my / (ny as f64 * da);
    qx * qx + qy * qy
}

/// A seeded random self-affine N×N map of the spectrum `spec` (side L = `spec.system_size`),
/// see the module docs. Needs at least two points per λ_s (q_s below the Nyquist wave
/// number π/Δa).
pub fn generate(spec: &SelfAffine, n: usize, seed: u64) -> Result<Surface> {
    crate::work::start();
    let (mut ht, da) = fourier_rows(spec, n, seed, (0, n))?;
    // h(r) = Σ_q h̃(q) e^{iq·r}: the unnormalised inverse transform
    crate::numerics::fft2::transform(&mut ht, n, true);
    let heights: Vec<f64> = ht.iter().map(|c| c.re).collect();
    Surface::new(n, n, da, heights)
}

/// Rows `y0..y1` of the Fourier amplitudes h̃ of [`generate`]'s n × n map (row-major, scaled
/// to the spectrum's ḡ), and Δa (m). Every mode is drawn in the same order whatever the rows,
/// so that a rank's rows equal the whole map's bit for bit (the map by slabs of a run over
/// ranks, `gfmd::distributed::map`).
///
/// # Errors
/// As [`generate`].
pub(crate) fn fourier_rows(
    spec: &SelfAffine,
    n: usize,
    seed: u64,
    (y0, y1): (usize, usize),
) -> Result<(Vec<Complex64>, f64)> {
    let l = spec.system_size;
    if !(4..=MAX_GRID).contains(&n) {
        return Err(Error::invalid(Field::Grid, n as f64, format!("4 <= N <= {MAX_GRID}")));
    }
    let da = l / n as f64;
    if spec.lambda_s < 2.0 * da * (1.0 - 1e-12) {
        return Err(Error::invalid(
            Field::Grid,
            n as f64,
            format!(
                "N >= 2 L/lambda_s = {} (at least two points per short wavelength)",
                (2.0 * l / spec.lambda_s).ceil()
            ),
        ));
    }
    let area = l * l;
    let qs = spec.q_s();
    let ql = 2.0 * PI / l;
    let wrap = |i: usize| -> i64 {
        if i <= n / 2 {
            i as i64
        } else {
            i as i64 - n as i64
        }
    };
    let mine = |i: usize| (y0..y1).contains(&i);
    let mut rng = SplitMix64::new(seed);
    let mut ht = vec![Complex64::new(0.0, 0.0); (y1 - y0) * n];
    let mut g2 = 0.0;
    // row index i ↔ y, column j ↔ x; the conjugate of (i, j) is (−i, −j) mod n
    for i in 0..n {
        for j in 0..n {
            let (ci, cj) = ((n - i) % n, (n - j) % n);
            let (k, ck) = (i * n + j, ci * n + cj);
            if ck < k {
                continue; // set together with its conjugate
            }
            let (mi, mj) = (wrap(i) as f64, wrap(j) as f64);
            let q = ql * (mi * mi + mj * mj).sqrt();
            if q == 0.0 || q > qs * (1.0 + 1e-12) {
                continue;
            }
            let amp = (spec.psd(q.min(qs)) * (2.0 * PI).powi(2) / area).sqrt();
            if ck == k {
                let sign = if rng.next_u64() >> 63 == 0 { 1.0 } else { -1.0 };
                if mine(i) {
                    ht[(i - y0) * n + j] = Complex64::new(sign * amp, 0.0);
                }
                g2 += q * q * amp * amp;
            } else {
                let phase = 2.0 * PI * rng.next_f64();
                let c = Complex64::from_polar(amp, phase);
                if mine(i) {
                    ht[(i - y0) * n + j] = c;
                }
                if mine(ci) {
                    ht[(ci - y0) * n + cj] = c.conj();
                }
                g2 += 2.0 * q * q * amp * amp;
            }
        }
    }
    if g2 == 0.0 {
        return Err(Error::invalid(
            Field::Grid,
            n as f64,
            "a grid resolving at least one mode below q_s",
        ));
    }
    let scale = spec.moment(2).sqrt() / g2.sqrt();
    for c in ht.iter_mut() {
        *c *= scale;
    }
    Ok((ht, da))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::spectrum::Normalisation;

    #[test]
    fn splitmix_reference_values() {
        // first outputs of SplitMix64 seeded with 0 (reference implementation)
        let mut r = SplitMix64::new(0);
        assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(r.next_u64(), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn text_round_trip_is_exact() {
        let spec = SelfAffine::new(1e-6, 0.5e-6, 0.125e-6, 0.8, Normalisation::RmsGradient(1.0)).unwrap();
        let s = generate(&spec, 16, 3).unwrap();
        let back = Surface::parse(&s.to_text(), "mem", 1e-6).unwrap();
        assert_eq!(back.heights, s.heights);
        assert!((back.spacing - s.spacing).abs() < 1e-30);
    }
}
