//! Reduced grids: L/λ_r, λ_r/λ_s and λ_s/Δa of a brute-force run, the reduced spectrum, and the
//! inputs of [`super::run()`].

use crate::error::{Error, Field, Range, Result};
use crate::input::scene::Scene;
use crate::surface::heightmap::{self, Surface};
use crate::surface::spectrum::{Normalisation, SelfAffine, Spectrum};
use serde::Serialize;

/// The reduced grid of a brute-force run: L/λ_r, λ_r/λ_s and λ_s/Δa, so N = their product.
/// λ_s and the normalisation (ḡ) of the full spectrum are kept, L and λ_r shrink: the scales
/// where adhesion acts stay as they are.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GridSpec {
    /// L/λ_r.
    pub system_size_ratio: f64,
    /// λ_r/λ_s.
    pub bandwidth: f64,
    /// λ_s/Δa.
    pub points_per_short_wavelength: f64,
}

impl GridSpec {
    /// The reduced grid of a preset without a `[gfmd]` table: L/λ_r = 2, λ_r/λ_s = 32,
    /// λ_s/Δa = 8 (512²).
    pub const DEFAULT: GridSpec = GridSpec {
        system_size_ratio: 2.0,
        bandwidth: 32.0,
        points_per_short_wavelength: 8.0,
    };

    /// The grid of `preset` (its `[gfmd]` table, else [`GridSpec::DEFAULT`]), on an N×N grid
    /// where `n` is given ([`GridSpec::with_grid`]).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming [`Field::Grid`] for N < 4 or a grid `with_grid` refuses.
    pub fn of_preset(preset: &crate::input::preset::Preset, n: Option<i64>) -> Result<Self> {
        let grid = preset
            .gfmd
            .as_ref()
            .map(GridSpec::from_preset)
            .unwrap_or(GridSpec::DEFAULT);
        match n {
            Some(n) if n < 4 => Err(Error::invalid(Field::Grid, n as f64, "an integer N >= 4")),
            Some(n) => grid.with_grid(n as usize),
            None => Ok(grid),
        }
    }

    /// The preset's `[gfmd]` table.
    pub fn from_preset(g: &crate::input::preset::GfmdSpec) -> Self {
        GridSpec {
            system_size_ratio: g.system_size_ratio as f64,
            bandwidth: g.bandwidth as f64,
            points_per_short_wavelength: g.points_per_short_wavelength as f64,
        }
    }

    /// Grid side N.
    pub fn n(&self) -> usize {
        (self.system_size_ratio * self.bandwidth * self.points_per_short_wavelength).round() as usize
    }

    /// The same L/λ_r and λ_s/Δa on an N×N grid (the bandwidth λ_r/λ_s adapts).
    pub fn with_grid(&self, n: usize) -> Result<Self> {
        let bw = n as f64 / (self.system_size_ratio * self.points_per_short_wavelength);
        if !(4..=heightmap::MAX_GRID).contains(&n) || bw <= 1.0 {
            return Err(Error::invalid(
                Field::Grid,
                n as f64,
                format!(
                    "{} < N <= {} (L/lambda_r = {} and lambda_s/da = {} need lambda_r > lambda_s)",
                    (self.system_size_ratio * self.points_per_short_wavelength) as usize,
                    heightmap::MAX_GRID,
                    self.system_size_ratio,
                    self.points_per_short_wavelength
                ),
            ));
        }
        Ok(GridSpec { bandwidth: bw, ..*self })
    }

    /// The reduced spectrum: same H, λ_s and ḡ as `full`, λ_r = bandwidth·λ_s, L = ratio·λ_r.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the grid's own field ([`Field::GfmdBandwidth`] for
    /// λ_r/λ_s ≤ 1 or beyond the spectrum's limit, [`Field::GfmdSizeRatio`] for L/λ_r < 1), never
    /// the surface's: the surface the user set is valid, the reduction of it is what fails.
    pub fn spectrum(&self, full: &SelfAffine) -> Result<SelfAffine> {
        if !(self.system_size_ratio >= 1.0 && self.system_size_ratio.is_finite()) {
            return Err(Error::invalid(
                Field::GfmdSizeRatio,
                self.system_size_ratio,
                Range::closed(1.0, 4096.0),
            ));
        }
        let lambda_r = self.bandwidth * full.lambda_s;
        let l = self.system_size_ratio * lambda_r;
        let g = Spectrum::SelfAffine(*full).rms_gradient();
        SelfAffine::new(l, lambda_r, full.lambda_s, full.hurst, Normalisation::RmsGradient(g)).map_err(|e| match e {
            Error::Invalid { .. } => Error::invalid(
                Field::GfmdBandwidth,
                self.bandwidth,
                "1 < bandwidth (lambda_r/lambda_s of the reduced grid) <= 1e8, with lambda_r and L in 1e-12..1e3 m",
            ),
            other => other,
        })
    }
}

/// Inputs of [`super::run()`].
#[derive(Debug, Clone)]
pub struct GfmdSetup {
    /// The scene: E*, p*, t·q_r, γ_s, ρ, and the model used for the theory comparison. Its
    /// spectrum must be self-affine when the map is generated.
    pub scene: Scene,
    /// The reduced grid (ignored, except L/λ_r for q_r, when `surface` is given).
    pub grid: GridSpec,
    /// Seed of the random phases.
    pub seed: u64,
    /// A given map (square) instead of a generated one.
    pub surface: Option<Surface>,
    /// Rescale γ_s and ρ on the reduced grid to keep γ̃_glo and the Tabor parameter of the
    /// full system ([`super::reduction`]); false keeps them as given.
    pub rescale: bool,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;

    #[test]
    fn preset_grid_and_its_reduced_spectrum() {
        let p = Preset::resolve("system-1").unwrap();
        let g = GridSpec::from_preset(p.gfmd.as_ref().unwrap());
        assert_eq!(g.n(), 512);
        assert_eq!(p.gfmd_grid(), Some(512));
        let full = match p.spectrum().unwrap() {
            Spectrum::SelfAffine(s) => s,
            _ => unreachable!(),
        };
        let r = g.spectrum(&full).unwrap();
        assert_eq!(r.lambda_s, full.lambda_s);
        assert!((r.lambda_r / r.lambda_s - 32.0).abs() < 1e-12);
        assert!((r.system_size / r.lambda_r - 2.0).abs() < 1e-12);
        assert!((Spectrum::SelfAffine(r).rms_gradient() - 1.0).abs() < 1e-12);
        // --grid keeps L/λ_r and λ_s/Δa
        let h = g.with_grid(256).unwrap();
        assert_eq!(h.n(), 256);
        assert!((h.bandwidth - 16.0).abs() < 1e-12);
        assert!(g.with_grid(16).is_err());
        // a reduction that cannot be built blames the grid's field, not the surface's
        for (bad, field) in [
            (GridSpec { bandwidth: 1.0, ..g }, Field::GfmdBandwidth),
            (GridSpec { bandwidth: 0.5, ..g }, Field::GfmdBandwidth),
            (
                GridSpec {
                    system_size_ratio: 0.5,
                    ..g
                },
                Field::GfmdSizeRatio,
            ),
        ] {
            let e = bad.spectrum(&full).unwrap_err();
            assert_eq!(e.invalid_field(), Some(&field), "{e}");
        }
    }
}
