//! The power spectral density of a height map as the field computes it, and a self-affine fit.
//!
//! Steps (physics.md §1 for the conventions, §1.1 for the choices):
//!
//! 1. Detrend: subtract the least-squares mean plane a + b·x + c·y (a line for a line scan).
//!    A map declared periodic (generated or GFMD maps) loses only its mean: a plane would
//!    remove part of its longest modes.
//! 2. Window against leakage: a separable Hann window w(x)w(y), w = sin²(π(i + ½)/n),
//!    normalised to ⟨w²⟩ = 1 so that the variance is kept on average. Periodic maps: none.
//! 3. Periodogram: h̃(q) = FFT(w·h)/(n_x n_y), C(q) = A|h̃(q)|²/(2π)² (2-D, m⁴);
//!    C₁(q) = L|h̃(q)|²/(2π) (1-D line scan, m³).
//! 4. Radial average in log-spaced bins ([`PsdOptions::bins_per_decade`]) from q_L = 2π/L to
//!    the Nyquist wave number π/Δa: each bin holds the mean of C over its modes, at the
//!    geometric mean of their |q|. Bins without power (below 1e-20 of the largest) are dropped.
//! 5. A line scan's 1-D PSD is converted to the isotropic 2-D one with the self-affine factor
//!    C(q) = C₁(q)/q · Γ(1+H)/(√π Γ(H+½)), H from the fit of the 1-D PSD (exact for a power
//!    law C ∝ q^{−2(1+H)}, whose profiles have C₁ ∝ q^{−(1+2H)}; approximate near a roll-off).
//!
//! Moments: h_rms is the rms of the detrended map (not windowed); ḡ² = Σ_q q²|h̃|² and the
//! rms mean curvature κ = ½(Σ_q q⁴|h̃|²)^{1/2} (of ½∇²h, SurfaceTopography's convention) from
//! the windowed periodogram, summed over the modes (not the bins). For a line scan the values
//! are those of the isotropic surface: ḡ² = 2⟨h'²⟩, κ² = (2/3)⟨h''²⟩.
//!
//! Self-affine fit ([`fit_self_affine`]): ln C against ln q by weighted least squares (weight:
//! the number of modes of a bin) with the model C₀ for q < q_r, C₀(q/q_r)^{−β} above, β =
//! 2(1+H) (1+2H for a line scan); q_r is scanned over the bins and refined by golden section;
//! q_s is the last bin before C falls (for two bins) below a tenth of the power law through the
//! two bins before it (else the last bin). Uncertainties: H from the covariance of (ln C₀, β) scaled by the residual variance;
//! q_r from where the residual sum rises by one residual variance (Δχ² = 1); q_s to the next
//! bin.

use crate::error::{Error, Field, Result};
pub use crate::surface::fit::{fit_self_affine, SelfAffineFit};
use crate::surface::heightmap::{wave_number_sq, Surface};
use crate::surface::spectrum::{Spectrum, Tabulated};
use rustfft::num_complex::Complex64;
use serde::Serialize;
use std::f64::consts::PI;

/// How to compute a PSD.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PsdOptions {
    /// The map is periodic: no plane, no window (exact periodogram).
    pub periodic: bool,
    /// Log-spaced bins per decade of q.
    pub bins_per_decade: f64,
}

impl Default for PsdOptions {
    fn default() -> Self {
        PsdOptions {
            periodic: false,
            bins_per_decade: 10.0,
        }
    }
}

impl Spectrum {
    /// The tabulated spectrum of a measured map: the radial average of its PSD ([`analyse`]),
    /// cut to [q_min, q_max] (1/m) where given, `source` naming it. What the theory runs on for
    /// a map given to `--surface` or Python's `Scene.with_map`.
    ///
    /// # Errors
    /// [`Error::Invalid`] for a map that is not a contact problem ([`Surface::check_rough`]),
    /// and the table's own ([`Tabulated::new`]: cut-offs outside the table, too few rows).
    pub fn from_map(
        surface: &Surface,
        opts: &PsdOptions,
        q_range: (Option<f64>, Option<f64>),
        source: &str,
    ) -> Result<Spectrum> {
        surface.check_rough()?;
        let a = analyse(surface, opts)?;
        let (q, c): (Vec<f64>, Vec<f64>) = a.bins.iter().map(|b| (b.q, b.psd)).unzip();
        Ok(Spectrum::Tabulated(Tabulated::new(q, c, source, q_range.0, q_range.1)?))
    }
}

/// Allowed bins per decade.
pub const BINS_PER_DECADE_RANGE: (f64, f64) = (2.0, 100.0);

/// One radial bin.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PsdBin {
    /// Geometric mean |q| of the bin's modes (1/m).
    pub q: f64,
    /// Mean C(q) of the bin (m⁴, isotropic 2-D).
    pub psd: f64,
    /// Number of Fourier modes in the bin.
    pub modes: usize,
}

/// A map's PSD and its summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PsdAnalysis {
    /// The radial average, ascending q (isotropic 2-D C in m⁴).
    pub bins: Vec<PsdBin>,
    /// h_rms of the detrended map (m).
    pub rms_height: f64,
    /// ḡ, the rms gradient.
    pub rms_gradient: f64,
    /// The rms mean curvature ½(∇²h)_rms (1/m).
    pub rms_curvature: f64,
    /// The self-affine fit (None with fewer than 4 bins).
    pub fit: Option<SelfAffineFit>,
    /// The input was a line scan (1-D PSD converted to 2-D).
    pub line_scan: bool,
    /// "hann" or "none".
    pub window: &'static str,
    /// "mean plane" (or "mean line"), or "mean" for a periodic map.
    pub detrend: &'static str,
}

/// The PSD of a map (module docs).
///
/// # Errors
/// Those of [`check`], made before any work: a map too small or flat, bins per decade outside
/// [`BINS_PER_DECADE_RANGE`].
pub fn analyse(s: &Surface, opts: &PsdOptions) -> Result<PsdAnalysis> {
    let h = check(s, opts)?;
    let rms_height = rms(&h);
    crate::work::start();
    let (nx, ny, da) = (s.nx, s.ny, s.spacing);
    let line = ny == 1;
    let hw = if opts.periodic { h } else { hann(&h, nx, ny) };
    let mut plan = crate::numerics::fft2::RealFft2::new(nx, ny);
    let mut spec = vec![Complex64::new(0.0, 0.0); plan.spectrum_len()];
    plan.forward(&hw, &mut spec);
    let norm = 1.0 / (nx * ny) as f64;
    let (lx, ly) = (s.size_x(), s.size_y());
    // C per mode: A|h̃|²/(2π)² (2-D) or L|h̃|²/(2π) (1-D)
    let unit = if line {
        lx / (2.0 * PI)
    } else {
        lx * ly / (2.0 * PI).powi(2)
    };
    let q_lo = 2.0 * PI / lx.max(ly);
    let q_nyq = PI / da;
    let per_ln = opts.bins_per_decade / 10f64.ln();
    let nbins = ((q_nyq / q_lo).ln() * per_ln).floor() as usize + 1;
    let mut acc = vec![(0.0f64, 0.0f64, 0usize); nbins]; // (Σ C, Σ ln q, modes)
    let (mut m2, mut m4) = (0.0, 0.0);
    for ky in 0..ny {
        for kx in 0..plan.nh() {
            let q2 = wave_number_sq(kx, ky, nx, ny, da);
            if q2 == 0.0 {
                continue;
            }
            let p = (spec[ky * plan.nh() + kx] * norm).norm_sqr();
            let w = plan.weight(kx);
            m2 += w * q2 * p;
            m4 += w * q2 * q2 * p;
            let q = q2.sqrt();
            if q > q_nyq * (1.0 + 1e-12) {
                continue;
            }
            let b = (((q / q_lo).ln() * per_ln + 1e-9).floor().max(0.0) as usize).min(nbins - 1);
            let k = w as usize;
            acc[b].0 += w * p * unit;
            acc[b].1 += w * q.ln();
            acc[b].2 += k;
        }
    }
    let (rms_gradient, rms_curvature) = if line {
        ((2.0 * m2).sqrt(), (2.0 / 3.0 * m4).sqrt())
    } else {
        (m2.sqrt(), 0.5 * m4.sqrt())
    };
    let mut bins: Vec<PsdBin> = acc
        .iter()
        .filter(|a| a.2 > 0)
        .map(|a| PsdBin {
            q: (a.1 / a.2 as f64).exp(),
            psd: a.0 / a.2 as f64,
            modes: a.2,
        })
        .collect();
    let top = bins.iter().map(|b| b.psd).fold(0.0, f64::max);
    bins.retain(|b| b.psd > 1e-20 * top);
    let fit_of = |bins: &[PsdBin]| {
        let q: Vec<f64> = bins.iter().map(|b| b.q).collect();
        let c: Vec<f64> = bins.iter().map(|b| b.psd).collect();
        let w: Vec<f64> = bins.iter().map(|b| b.modes as f64).collect();
        fit_self_affine(&q, &c, &w)
    };
    let mut fit = fit_of(&bins);
    if line {
        // 1-D → isotropic 2-D with the self-affine factor at the fitted H (module docs)
        let hurst = fit.map_or(0.5, |f| ((f.exponent - 1.0) / 2.0).clamp(0.0, 1.0));
        let factor =
            statrs::function::gamma::gamma(1.0 + hurst) / (PI.sqrt() * statrs::function::gamma::gamma(hurst + 0.5));
        for b in &mut bins {
            b.psd *= factor / b.q;
        }
        fit = fit_of(&bins);
    }
    Ok(PsdAnalysis {
        bins,
        rms_height,
        rms_gradient,
        rms_curvature,
        fit,
        line_scan: line,
        window: if opts.periodic { "none" } else { "hann" },
        detrend: match (opts.periodic, line) {
            (true, _) => "mean",
            (false, true) => "mean line",
            (false, false) => "mean plane",
        },
    })
}

/// Heights minus their mean (periodic) or their least-squares plane (a line for ny = 1).
/// The fewest points of each side of a 2-D map, and of a line profile, that [`analyse`] takes:
/// after the mean plane is removed a smaller map leaves too few modes for a radial average.
pub const MIN_PSD_POINTS: usize = 4;

/// What [`analyse`] checks before any work: the bins per decade in their range, a map of at
/// least [`MIN_PSD_POINTS`] per side (a line profile: that many points) and some roughness
/// left once the mean plane (or, for a periodic map, the mean) is removed. Returns the
/// detrended heights.
///
/// # Errors
/// [`Error::Invalid`] for `bins_per_decade` or [`Field::HeightMap`] (its size, or a flat map).
pub fn check(s: &Surface, opts: &PsdOptions) -> Result<Vec<f64>> {
    crate::error::check_in(
        Field::Other("bins_per_decade".into()),
        opts.bins_per_decade,
        BINS_PER_DECADE_RANGE.0,
        BINS_PER_DECADE_RANGE.1,
    )?;
    if s.nx < MIN_PSD_POINTS || (s.ny != 1 && s.ny < MIN_PSD_POINTS) {
        return Err(Error::invalid_text(
            Field::HeightMap,
            format!("a {} x {} map", s.nx, s.ny),
            format!("a map of at least {MIN_PSD_POINTS} x {MIN_PSD_POINTS} points (a line profile: {MIN_PSD_POINTS}) for a spectrum"),
        ));
    }
    let h = detrend(s, opts.periodic);
    let rms_height = rms(&h);
    if rms_height.is_nan() || rms_height <= 0.0 {
        return Err(Error::invalid_text(
            Field::HeightMap,
            "a flat map",
            "a height map with some roughness",
        ));
    }
    Ok(h)
}

/// The root mean square of `h`.
fn rms(h: &[f64]) -> f64 {
    (h.iter().map(|x| x * x).sum::<f64>() / h.len() as f64).sqrt()
}

fn detrend(s: &Surface, periodic: bool) -> Vec<f64> {
    let (nx, ny) = (s.nx, s.ny);
    let n = (nx * ny) as f64;
    let mean = s.heights.iter().sum::<f64>() / n;
    if periodic {
        return s.heights.iter().map(|h| h - mean).collect();
    }
    // centred coordinates are orthogonal to 1 and to each other on a full grid
    let cx = |i: usize| i as f64 - (nx as f64 - 1.0) / 2.0;
    let cy = |j: usize| j as f64 - (ny as f64 - 1.0) / 2.0;
    let (mut sxh, mut syh, mut sxx, mut syy) = (0.0, 0.0, 0.0, 0.0);
    for j in 0..ny {
        for i in 0..nx {
            let h = s.heights[j * nx + i] - mean;
            sxh += cx(i) * h;
            syh += cy(j) * h;
            sxx += cx(i) * cx(i);
            syy += cy(j) * cy(j);
        }
    }
    let b = if sxx > 0.0 { sxh / sxx } else { 0.0 };
    let c = if syy > 0.0 { syh / syy } else { 0.0 };
    let mut out = Vec::with_capacity(nx * ny);
    for j in 0..ny {
        for i in 0..nx {
            out.push(s.heights[j * nx + i] - mean - b * cx(i) - c * cy(j));
        }
    }
    out
}

/// The map times the separable Hann window normalised to ⟨w²⟩ = 1 (module docs).
fn hann(h: &[f64], nx: usize, ny: usize) -> Vec<f64> {
    let w1 = |n: usize| -> Vec<f64> {
        if n == 1 {
            return vec![1.0];
        }
        let w: Vec<f64> = (0..n)
            .map(|i| (PI * (i as f64 + 0.5) / n as f64).sin().powi(2))
            .collect();
        let ms = w.iter().map(|x| x * x).sum::<f64>() / n as f64;
        w.iter().map(|x| x / ms.sqrt()).collect()
    };
    let (wx, wy) = (w1(nx), w1(ny));
    h.iter().enumerate().map(|(k, v)| v * wx[k % nx] * wy[k / nx]).collect()
}
