//! Height spectra: the isotropic self-affine PSD with roll-off, and the discrete spectrum of
//! an actual height map.
//!
//! Conventions (physics.md §1): h̃(q) = (1/A)∫d²r e^{−iq·r} h(r); C(q) = A⟨|h̃(q)|²⟩/(2π)²;
//! Σ_q F(q) → (A/(2π)²)∫d²q F(q). Every sum over modes is written here as an integral over the
//! "height-variance measure"
//!
//! ```text
//! dm(q) = 2π q C(q) dq          (continuum)        dm = Σ_{|q'| = q} |h̃(q')|²   (discrete)
//! ```
//!
//! so that h_rms² = ∫dm, ḡ² = ∫q² dm (rms gradient), κ_L² = ∫q⁴ dm (rms Laplacian).
//!
//! Self-affine PSD with roll-off: C = C₀ on q_L ≤ q < q_r, C₀(q/q_r)^{−2(1+H)} on
//! q_r ≤ q ≤ q_s, 0 elsewhere; q_L = 2π/L, q_r = 2π/λ_r, q_s = 2π/λ_s. Moments are known in
//! closed form ([`SelfAffine::moment`]); integrals of other functions use composite 8-point
//! Gauss–Legendre panels in ln q, split at q_r (where C has a kink), at most
//! [`PANEL_WIDTH_LN`] wide, which is exact to ~1e-14 for the power laws involved at any
//! bandwidth λ_r/λ_s up to 10⁶ and beyond.

use crate::error::{check_in, Error, Field, Result};
pub use crate::surface::tabulated::Tabulated;
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;

pub use crate::surface::ranges::{HURST_RANGE, LENGTH_RANGE_M, RMS_GRADIENT_RANGE, RMS_HEIGHT_RANGE_M};

/// Largest width of one Gauss–Legendre panel in ln q.
pub const PANEL_WIDTH_LN: f64 = 0.25;

/// 4-point Gauss–Legendre nodes and weights on [−1, 1] (the one copy in the crate).
pub const GL4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// 8-point Gauss–Legendre nodes (positive half) and weights on [−1, 1] (the one copy).
pub const GL8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// How a self-affine spectrum is normalised.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Normalisation {
    /// Target rms gradient ḡ (dimensionless).
    RmsGradient(f64),
    /// Target rms height h_rms (m).
    RmsHeight(f64),
}

/// Isotropic self-affine PSD with roll-off. Lengths in metres, C in m⁴.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SelfAffine {
    /// System size L (m).
    pub system_size: f64,
    /// Roll-off wavelength λ_r (m).
    pub lambda_r: f64,
    /// Short-wavelength cut-off λ_s (m).
    pub lambda_s: f64,
    /// Hurst exponent H.
    pub hurst: f64,
    /// Plateau value C₀ (m⁴), set by the normalisation.
    pub c0: f64,
}

impl SelfAffine {
    /// Builds and normalises the spectrum. Requires 0 < λ_s < λ_r ≤ L and 0 < H ≤ 1.
    pub fn new(system_size: f64, lambda_r: f64, lambda_s: f64, hurst: f64, norm: Normalisation) -> Result<Self> {
        for (field, v) in [
            (Field::SystemSize, system_size),
            (Field::RolloffWavelength, lambda_r),
            (Field::ShortWavelength, lambda_s),
        ] {
            check_in(field, v, LENGTH_RANGE_M.0, LENGTH_RANGE_M.1)?;
        }
        if lambda_r > system_size {
            return Err(Error::invalid(
                Field::RolloffWavelength,
                lambda_r,
                format!(
                    "0 < rolloff_wavelength_m <= system_size_m = {}",
                    crate::error::fmt_value(system_size)
                ),
            ));
        }
        if lambda_s >= lambda_r {
            return Err(Error::invalid(
                Field::ShortWavelength,
                lambda_s,
                format!(
                    "0 < short_wavelength_m < rolloff_wavelength_m = {}",
                    crate::error::fmt_value(lambda_r)
                ),
            ));
        }
        if lambda_r / lambda_s > 1e8 {
            return Err(Error::invalid(
                Field::ShortWavelength,
                lambda_s,
                "a bandwidth rolloff_wavelength_m/short_wavelength_m <= 1e8",
            ));
        }
        check_in(Field::Hurst, hurst, HURST_RANGE.0, HURST_RANGE.1)?;
        let mut s = SelfAffine {
            system_size,
            lambda_r,
            lambda_s,
            hurst,
            c0: 1.0,
        };
        match norm {
            Normalisation::RmsGradient(g) => {
                check_in(Field::RmsGradient, g, RMS_GRADIENT_RANGE.0, RMS_GRADIENT_RANGE.1)?;
                s.c0 = g * g / s.moment(2);
            }
            Normalisation::RmsHeight(h) => {
                check_in(Field::RmsHeight, h, RMS_HEIGHT_RANGE_M.0, RMS_HEIGHT_RANGE_M.1)?;
                s.c0 = h * h / s.moment(0);
            }
        }
        Ok(s)
    }

    /// q_L = 2π/L.
    pub fn q_l(&self) -> f64 {
        2.0 * PI / self.system_size
    }
    /// q_r = 2π/λ_r.
    pub fn q_r(&self) -> f64 {
        2.0 * PI / self.lambda_r
    }
    /// q_s = 2π/λ_s.
    pub fn q_s(&self) -> f64 {
        2.0 * PI / self.lambda_s
    }

    /// C(q) in m⁴ (0 outside [q_L, q_s]).
    pub fn psd(&self, q: f64) -> f64 {
        let (ql, qr, qs) = (self.q_l(), self.q_r(), self.q_s());
        if q < ql || q > qs {
            0.0
        } else if q < qr {
            self.c0
        } else {
            self.c0 * (q / qr).powf(-2.0 * (1.0 + self.hurst))
        }
    }

    /// dm/d(ln q) = 2π q² C(q).
    #[inline]
    pub fn dm_dlnq(&self, q: f64) -> f64 {
        2.0 * PI * q * q * self.psd(q)
    }

    /// M_n = 2π ∫ q^{n+1} C(q) dq = ∫ qⁿ dm, in closed form (n = 0: h_rms², 2: ḡ², 4: κ_L²).
    pub fn moment(&self, n: i32) -> f64 {
        let (ql, qr, qs) = (self.q_l(), self.q_r(), self.q_s());
        let e = n as f64 + 2.0;
        // plateau: C0 (q_r^e − q_L^e)/e, written with expm1 for accuracy when q_L ≈ q_r
        let plateau = qr.powf(e) * (-(e * (ql / qr).ln()).exp_m1()) / e;
        // tail: C0 q_r^{2+2H} ∫ q^{n−1−2H} dq = C0 q_r^{e} expm1(k ln(q_s/q_r))/k, k = n − 2H
        let k = n as f64 - 2.0 * self.hurst;
        let l = (qs / qr).ln();
        let tail = if k.abs() < 1e-12 { l } else { (k * l).exp_m1() / k };
        2.0 * PI * self.c0 * (plateau + qr.powf(e) * tail)
    }
}

/// One group of modes with the same |q| of a discrete spectrum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mode {
    /// |q| (1/m).
    pub q: f64,
    /// Σ |h̃|² over the modes with this |q| (m²).
    pub dm: f64,
}

/// The discrete spectrum of a periodic height map: groups of modes sorted by |q|.
#[derive(Debug, Clone, PartialEq)]
pub struct Discrete {
    /// System size L (m).
    pub system_size: f64,
    /// Roll-off wave number used for reduced thickness t·q_r (1/m).
    pub q_r: f64,
    /// Mode groups, ascending in q, q = 0 excluded, dm > 0.
    pub modes: Vec<Mode>,
}

impl Discrete {
    /// Spectrum of an N×N periodic height map `h` (row-major, metres) of side `system_size`.
    /// h̃ = FFT(h)/N² (physics.md §1). `q_r` is the roll-off wave number to use for reduced
    /// thicknesses (pass q_L if the map has no roll-off).
    pub fn from_height_map(h: &[f64], n: usize, system_size: f64, q_r: f64) -> Result<Self> {
        if n < 2 || h.len() != n * n {
            return Err(Error::invalid_text(
                Field::HeightMap,
                format!("{} values", h.len()),
                format!("an N x N map with N >= 2 (N = {n})"),
            ));
        }
        if let Some(bad) = h.iter().position(|x| !x.is_finite()) {
            return Err(Error::invalid(
                Field::Other(format!("surface[{}][{}]", bad / n, bad % n)),
                h[bad],
                "a finite height",
            ));
        }
        if !(system_size.is_finite() && system_size > 0.0) {
            check_in(Field::SystemSize, system_size, LENGTH_RANGE_M.0, LENGTH_RANGE_M.1)?;
        }
        let spec = crate::numerics::fft2::forward_real(h, n);
        let mut by_k2 = std::collections::BTreeMap::new();
        Discrete::add_mode_sums(&spec, 0..n, n, &mut by_k2);
        Discrete::from_mode_sums(by_k2, system_size, q_r)
    }

    /// Adds Σ|h̃|² per |k|² = m_x² + m_y² of the rows `rows` of an N×N map's complex
    /// transform to `by_k2` (k = 0 left out): `spec` holds those rows (row-major, `n` wide),
    /// unnormalised (h̃ = entry/N²). Row by row in order, so that partial sums passed on over
    /// consecutive rows add up bit for bit as one pass over the whole map does.
    pub fn add_mode_sums(
        spec: &[Complex64],
        rows: std::ops::Range<usize>,
        n: usize,
        by_k2: &mut std::collections::BTreeMap<i64, f64>,
    ) {
        let norm = 1.0 / (n * n) as f64;
        let wrap = |i: usize| -> i64 {
            if i <= n / 2 {
                i as i64
            } else {
                i as i64 - n as i64
            }
        };
        let y0 = rows.start;
        for i in rows {
            let mi = wrap(i);
            for j in 0..n {
                let mj = wrap(j);
                let k2 = mi * mi + mj * mj;
                if k2 == 0 {
                    continue;
                }
                let c = spec[(i - y0) * n + j] * norm;
                *by_k2.entry(k2).or_insert(0.0) += c.norm_sqr();
            }
        }
    }

    /// The spectrum from Σ|h̃|² per |k|² = m_x² + m_y² (integer wave vectors of an N×N map of side
    /// `system_size`, k = 0 excluded), as [`Discrete::from_height_map`] groups them.
    pub fn from_mode_sums(by_k2: std::collections::BTreeMap<i64, f64>, system_size: f64, q_r: f64) -> Result<Self> {
        let ql = 2.0 * PI / system_size;
        // drop FFT round-off (|h̃|² at ~1e-32 of the total is numerical zero)
        let total: f64 = by_k2.values().sum();
        let modes = by_k2
            .into_iter()
            .filter(|&(_, dm)| dm > 1e-30 * total)
            .map(|(k2, dm)| Mode {
                q: ql * (k2 as f64).sqrt(),
                dm,
            })
            .collect::<Vec<_>>();
        if modes.is_empty() {
            return Err(Error::invalid_text(
                Field::HeightMap,
                "a flat map",
                "a height map with some roughness",
            ));
        }
        Ok(Discrete {
            system_size,
            q_r,
            modes,
        })
    }

    /// ∫ qⁿ dm = Σ qⁿ |h̃|².
    pub fn moment(&self, n: i32) -> f64 {
        self.modes.iter().map(|m| m.q.powi(n) * m.dm).sum()
    }
}

/// A height spectrum; the theory runs on each.
#[derive(Debug, Clone, PartialEq)]
pub enum Spectrum {
    /// Ideal continuum PSD.
    SelfAffine(SelfAffine),
    /// Modes of an actual surface.
    Discrete(Discrete),
    /// A tabulated continuum PSD (a measured spectrum), log–log interpolated.
    Tabulated(Tabulated),
}

/// Hashes the spectrum by the bit patterns of its parameters (or modes), so equal spectra
/// hash equally (a cache key for front ends; −0.0 and 0.0 hash differently, which is harmless
/// for a cache).
impl std::hash::Hash for Spectrum {
    fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
        match self {
            Spectrum::SelfAffine(s) => {
                0u8.hash(h);
                for x in [s.system_size, s.lambda_r, s.lambda_s, s.hurst, s.c0] {
                    x.to_bits().hash(h);
                }
            }
            Spectrum::Discrete(d) => {
                1u8.hash(h);
                d.system_size.to_bits().hash(h);
                d.q_r.to_bits().hash(h);
                for m in &d.modes {
                    m.q.to_bits().hash(h);
                    m.dm.to_bits().hash(h);
                }
            }
            Spectrum::Tabulated(t) => {
                2u8.hash(h);
                for x in t.q.iter().chain(&t.psd).chain([&t.q_min, &t.q_max, &t.q_r]) {
                    x.to_bits().hash(h);
                }
            }
        }
    }
}

impl Spectrum {
    /// Smallest wave number q_L.
    pub fn q_l(&self) -> f64 {
        match self {
            Spectrum::SelfAffine(s) => s.q_l(),
            Spectrum::Discrete(d) => 2.0 * PI / d.system_size,
            Spectrum::Tabulated(t) => t.q_min,
        }
    }
    /// Roll-off wave number q_r.
    pub fn q_r(&self) -> f64 {
        match self {
            Spectrum::SelfAffine(s) => s.q_r(),
            Spectrum::Discrete(d) => d.q_r,
            Spectrum::Tabulated(t) => t.q_r,
        }
    }
    /// Largest wave number q_s.
    pub fn q_s(&self) -> f64 {
        match self {
            Spectrum::SelfAffine(s) => s.q_s(),
            Spectrum::Discrete(d) => d.modes.last().map_or(0.0, |m| m.q),
            Spectrum::Tabulated(t) => t.q_max,
        }
    }
    /// ∫ qⁿ dm.
    pub fn moment(&self, n: i32) -> f64 {
        match self {
            Spectrum::SelfAffine(s) => s.moment(n),
            Spectrum::Discrete(d) => d.moment(n),
            Spectrum::Tabulated(t) => t.moment(n),
        }
    }
    /// h_rms (m).
    pub fn rms_height(&self) -> f64 {
        self.moment(0).sqrt()
    }
    /// ḡ, the rms gradient.
    pub fn rms_gradient(&self) -> f64 {
        self.moment(2).sqrt()
    }
    /// κ_L, the rms Laplacian (1/m).
    pub fn rms_laplacian(&self) -> f64 {
        self.moment(4).sqrt()
    }
    /// The breakpoints of the continuum PSD in increasing order (q_L, q_r, q_s), collapsing
    /// q_L = q_r. Empty for a discrete spectrum.
    pub fn breakpoints(&self) -> Vec<f64> {
        match self {
            Spectrum::SelfAffine(s) => {
                if s.q_r() > s.q_l() * (1.0 + 1e-12) {
                    vec![s.q_l(), s.q_r(), s.q_s()]
                } else {
                    vec![s.q_l(), s.q_s()]
                }
            }
            Spectrum::Tabulated(t) => t.breakpoints().to_vec(),
            Spectrum::Discrete(_) => vec![],
        }
    }

    /// Whether the spectrum is a continuum PSD (self-affine or tabulated), integrated by
    /// quadrature between [`Spectrum::breakpoints`], rather than a set of modes.
    pub fn is_continuum(&self) -> bool {
        !matches!(self, Spectrum::Discrete(_))
    }

    /// dm/d(ln q) = 2π q² C(q) of a continuum spectrum (0 for a discrete one).
    #[inline]
    pub fn dm_dlnq(&self, q: f64) -> f64 {
        match self {
            Spectrum::SelfAffine(s) => s.dm_dlnq(q),
            Spectrum::Tabulated(t) => 2.0 * PI * q * q * t.psd_at(q),
            Spectrum::Discrete(_) => 0.0,
        }
    }

    /// C(q) in m⁴ of a continuum spectrum (0 for a discrete one).
    pub fn psd(&self, q: f64) -> f64 {
        match self {
            Spectrum::SelfAffine(s) => s.psd(q),
            Spectrum::Tabulated(t) => t.psd_at(q),
            Spectrum::Discrete(_) => 0.0,
        }
    }

    /// What the spectrum is, for output: "self-affine", "discrete" (a map's modes) or
    /// "tabulated".
    pub fn kind(&self) -> &'static str {
        match self {
            Spectrum::SelfAffine(_) => "self-affine",
            Spectrum::Discrete(_) => "discrete",
            Spectrum::Tabulated(_) => "tabulated",
        }
    }

    /// Quadrature nodes (q, dm) such that Σ F(q)·dm ≈ ∫ F dm. For the continuum PSD: composite
    /// 8-point Gauss–Legendre in ln q, split at the breakpoints, panels at most `panel_width`
    /// wide in ln q. For a discrete spectrum: the modes themselves (exact).
    pub fn nodes(&self, panel_width: f64) -> Vec<Mode> {
        match self {
            Spectrum::Discrete(d) => d.modes.clone(),
            Spectrum::SelfAffine(_) | Spectrum::Tabulated(_) => {
                let bp = self.breakpoints();
                let mut out = Vec::new();
                for w in bp.windows(2) {
                    let (a, b) = (w[0].ln(), w[1].ln());
                    let panels = ((b - a) / panel_width).ceil().max(1.0) as usize;
                    let h = (b - a) / panels as f64;
                    for p in 0..panels {
                        let mid = a + (p as f64 + 0.5) * h;
                        let mut push = |x: f64, wt: f64| {
                            let lnq = mid + 0.5 * h * x;
                            // keep each node strictly inside its segment (C is discontinuous in slope)
                            let q = lnq.exp().clamp(w[0], w[1]);
                            out.push(Mode {
                                q,
                                dm: 0.5 * h * wt * self.dm_dlnq_in(q, w[0], w[1]),
                            });
                        };
                        for &(x, wt) in GL8.iter().rev() {
                            push(-x, wt);
                        }
                        for &(x, wt) in GL8.iter() {
                            push(x, wt);
                        }
                    }
                }
                out
            }
        }
    }

    /// ∫ F(q) dm using [`Spectrum::nodes`] with [`PANEL_WIDTH_LN`].
    pub fn integrate(&self, f: impl Fn(f64) -> f64) -> f64 {
        self.nodes(PANEL_WIDTH_LN).iter().map(|m| f(m.q) * m.dm).sum()
    }
}

impl Spectrum {
    /// dm/dln q of a continuum spectrum on the segment [lo, hi] (see [`SelfAffine`]'s).
    fn dm_dlnq_in(&self, q: f64, lo: f64, hi: f64) -> f64 {
        match self {
            Spectrum::SelfAffine(s) => s.dm_dlnq_in(q, lo, hi),
            other => other.dm_dlnq(q),
        }
    }
}

impl SelfAffine {
    /// dm/dln q on the segment [lo, hi]: the branch of C is chosen by the segment, not by
    /// comparing q with q_r, so that nodes rounding onto q_r use the right side.
    fn dm_dlnq_in(&self, q: f64, lo: f64, hi: f64) -> f64 {
        let qr = self.q_r();
        let c = if hi <= qr * (1.0 + 1e-12) && lo < qr {
            self.c0
        } else {
            self.c0 * (q / qr).powf(-2.0 * (1.0 + self.hurst))
        };
        2.0 * PI * q * q * c
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tolerances::QUADRATURE_REL;

    fn system1() -> SelfAffine {
        SelfAffine::new(100e-6, 20e-6, 0.1e-6, 0.8, Normalisation::RmsGradient(1.0)).unwrap()
    }

    #[test]
    fn system1_derived_numbers() {
        // systems.md: h_rms = 0.777 µm for system I, 0.523 µm for system II
        let s = Spectrum::SelfAffine(system1());
        assert!((s.rms_gradient() - 1.0).abs() < 1e-14);
        assert!((s.rms_height() / 0.777e-6 - 1.0).abs() < 1e-3, "{}", s.rms_height());
        let s2 = SelfAffine::new(25.6e-6, 12.8e-6, 0.1e-6, 0.8, Normalisation::RmsGradient(1.0)).unwrap();
        assert!((Spectrum::SelfAffine(s2).rms_height() / 0.523e-6 - 1.0).abs() < 2e-3);
    }

    #[test]
    fn quadrature_matches_closed_form_moments_at_every_bandwidth() {
        for bw in [2.0, 10.0, 200.0, 1e4, 1e6] {
            for h in [0.05, 0.3, 0.5, 0.8, 0.95, 1.0] {
                let sa = SelfAffine::new(4e-6 * bw, 2e-6 * bw, 2e-6, h, Normalisation::RmsGradient(1.0)).unwrap();
                let s = Spectrum::SelfAffine(sa);
                for n in [0, 2, 4] {
                    let quad = s.integrate(|q| q.powi(n));
                    let exact = s.moment(n);
                    assert!(
                        (quad / exact - 1.0).abs() < QUADRATURE_REL,
                        "bw {bw} H {h} n {n}: {quad} vs {exact}"
                    );
                }
            }
        }
    }

    #[test]
    fn rms_height_normalisation() {
        let sa = SelfAffine::new(1e-3, 1e-4, 1e-6, 0.5, Normalisation::RmsHeight(1e-6)).unwrap();
        assert!((Spectrum::SelfAffine(sa).rms_height() - 1e-6).abs() < 1e-20);
    }

    #[test]
    fn invalid_geometry_names_the_field() {
        let e = SelfAffine::new(1.0, 0.1, 0.2, 0.8, Normalisation::RmsGradient(1.0)).unwrap_err();
        assert!(e.to_string().contains("surface.short_wavelength_m"), "{e}");
        let e = SelfAffine::new(-1.0, 0.1, 0.01, 0.8, Normalisation::RmsGradient(1.0)).unwrap_err();
        assert!(e.to_string().contains("surface.system_size_m"), "{e}");
        let e = SelfAffine::new(1.0, 0.1, 0.01, f64::NAN, Normalisation::RmsGradient(1.0)).unwrap_err();
        assert!(e.to_string().contains("surface.hurst"), "{e}");
    }

    #[test]
    fn discrete_spectrum_of_a_single_sinusoid() {
        // h = A cos(2π·3x/L): two modes (±3, 0) each with |h̃| = A/2 → dm = A²/2 at q = 3 q_L
        let n = 32;
        let l = 1e-6;
        let a = 1e-8;
        let h: Vec<f64> = (0..n * n)
            .map(|k| a * (2.0 * PI * 3.0 * (k % n) as f64 / n as f64).cos())
            .collect();
        let d = Discrete::from_height_map(&h, n, l, 2.0 * PI / l).unwrap();
        assert_eq!(d.modes.len(), 1);
        let m = d.modes[0];
        assert!((m.q / (3.0 * 2.0 * PI / l) - 1.0).abs() < 1e-14);
        assert!((m.dm / (a * a / 2.0) - 1.0).abs() < 1e-12);
        // Parseval: Σ dm = mean of h² (zero-mean map)
        let ms: f64 = h.iter().map(|x| x * x).sum::<f64>() / (n * n) as f64;
        assert!((d.moment(0) / ms - 1.0).abs() < 1e-12);
    }
}
