//! A self-affine height map as a user asks for it (`asperity surface generate` and Python's
//! `generate_surface`): grid side N, side L, H, λ_r, λ_s, h_rms or ḡ, seed, periodic or not,
//! made by the generator GFMD uses ([`heightmap::generate`]: Fourier filtering with
//! deterministic amplitudes and random phases, docs/physics.md §1).
//!
//! A periodic map's discrete rms gradient ḡ equals the requested one (or its h_rms the
//! requested h_rms) to round-off. A non-periodic map is the N×N corner of a 2N×2N periodic map
//! of twice the side (the same spectrum, normalised as above), its mean removed, as a measured
//! map would be: its own h_rms and ḡ (by differences inside it, [`window_rms_gradient`]) are
//! what it has, not forced.

use super::heightmap::{self, Surface};
use super::spectrum::{Normalisation, SelfAffine};
use crate::error::{Error, Field, Result};

/// What a generated map is asked to be.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapRequest {
    /// Grid side N (the map is N×N).
    pub grid: i64,
    /// Side L (m).
    pub size: f64,
    /// Hurst exponent H.
    pub hurst: f64,
    /// λ_r (m); None: L/2.
    pub rolloff_wavelength: Option<f64>,
    /// λ_s (m); None: 4 L/N (four points per λ_s).
    pub short_wavelength: Option<f64>,
    /// ḡ; None (and no h_rms): 1.
    pub rms_gradient: Option<f64>,
    /// h_rms (m), instead of ḡ.
    pub rms_height: Option<f64>,
    /// Seed of the random phases.
    pub seed: u64,
    /// Periodic (false: cut out of a map of twice the side).
    pub periodic: bool,
}

impl MapRequest {
    /// The requested spectrum on a map of side `l` (the map's own or its parent's).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the spectrum's field out of range.
    pub fn spectrum(&self, l: f64) -> Result<SelfAffine> {
        let n = self.grid as f64;
        let lambda_r = self.rolloff_wavelength.unwrap_or(self.size / 2.0);
        let lambda_s = self.short_wavelength.unwrap_or(4.0 * self.size / n);
        SelfAffine::new(l, lambda_r, lambda_s, self.hurst, self.normalisation())
    }

    fn normalisation(&self) -> Normalisation {
        match self.rms_height {
            Some(h) => Normalisation::RmsHeight(h),
            None => Normalisation::RmsGradient(self.rms_gradient.unwrap_or(1.0)),
        }
    }

    /// Rescales the periodic map `s` so that its h_rms or ḡ is the requested one.
    fn normalise(&self, s: Surface) -> Result<Surface> {
        let factor = match self.normalisation() {
            Normalisation::RmsHeight(h) => h / s.rms_height(),
            Normalisation::RmsGradient(g) => g / s.rms_gradient(),
        };
        let heights = s.heights.iter().map(|h| h * factor).collect();
        Surface::new(s.nx, s.ny, s.spacing, heights)
    }

    /// The map (see the module docs).
    ///
    /// # Errors
    /// [`Error::Invalid`] for a grid outside 4..=[`heightmap::MAX_GRID`] or too coarse for
    /// λ_s, or a spectrum field out of range (checked on the map's own side first, so that
    /// the message names the lengths as given).
    pub fn make(&self) -> Result<Surface> {
        if !(4..=heightmap::MAX_GRID as i64).contains(&self.grid) {
            return Err(Error::invalid(
                Field::Grid,
                self.grid as f64,
                format!("4 <= N <= {}", heightmap::MAX_GRID),
            ));
        }
        let n = self.grid as usize;
        let spec = self.spectrum(self.size)?;
        if self.periodic {
            return self.normalise(heightmap::generate(&spec, n, self.seed)?);
        }
        let wide = self.spectrum(2.0 * self.size)?;
        let parent = self.normalise(heightmap::generate(&wide, 2 * n, self.seed)?)?;
        let heights: Vec<f64> = (0..n)
            .flat_map(|i| parent.heights[i * 2 * n..i * 2 * n + n].iter().copied())
            .collect();
        let mean = heights.iter().sum::<f64>() / (n * n) as f64;
        Surface::new(n, n, parent.spacing, heights.iter().map(|h| h - mean).collect())
    }
}

/// The rms gradient of a map that is not periodic: forward differences inside the window
/// (the spectral ḡ would count the jump across its edges).
pub fn window_rms_gradient(s: &Surface) -> f64 {
    let (nx, ny, h) = (s.nx, s.ny, &s.heights);
    let (mut sum, mut count) = (0.0, 0usize);
    for i in 0..ny.saturating_sub(1) {
        for j in 0..nx.saturating_sub(1) {
            let dx = (h[i * nx + j + 1] - h[i * nx + j]) / s.spacing;
            let dy = (h[(i + 1) * nx + j] - h[i * nx + j]) / s.spacing;
            sum += dx * dx + dy * dy;
            count += 1;
        }
    }
    (sum / count.max(1) as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn request(periodic: bool) -> MapRequest {
        MapRequest {
            grid: 32,
            size: 1e-4,
            hurst: 0.8,
            rolloff_wavelength: None,
            short_wavelength: None,
            rms_gradient: Some(0.5),
            rms_height: None,
            seed: 3,
            periodic,
        }
    }

    #[test]
    fn periodic_map_has_the_requested_gradient_and_the_window_is_a_corner() {
        let s = request(true).make().unwrap();
        assert_eq!((s.nx, s.ny), (32, 32));
        assert!((s.rms_gradient() - 0.5).abs() < 1e-9);
        let w = request(false).make().unwrap();
        assert_eq!((w.nx, w.ny), (32, 32));
        assert!((w.spacing - s.spacing).abs() < 1e-18);
        assert!(w.heights.iter().sum::<f64>().abs() < 1e-9 * w.rms_height() * 1024.0);
        assert!(window_rms_gradient(&w) > 0.0);
    }

    #[test]
    fn grid_out_of_range_names_the_grid() {
        let mut r = request(true);
        r.grid = 2;
        assert!(matches!(r.make(), Err(Error::Invalid { field: Field::Grid, .. })));
    }
}
