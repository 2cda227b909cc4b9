//! The report of a height map's power spectral density: what `asperity psd` prints and
//! Python's `psd()` returns. The map's moments (h_rms, ḡ, the rms curvature), the self-affine
//! fit read as wavelengths (λ_r = 2π/q_r, λ_s = 2π/q_s, each with the range the fit allows)
//! and whether the fit describes the map, the conventions used (window, detrending) and the
//! radial average itself ([`crate::surface::psd::analyse`]).
//!
//! A map whose moments cannot be measured (flat, or heights whose squares overflow) is refused
//! before the analysis, naming the map, so that no front end prints inf or null where `run`
//! refuses the same map. The serialised field names are those of `asperity psd --format
//! json` (a public interface).

use crate::error::{fmt_value, Error, Field, Result};
use crate::surface::heightmap::Surface;
use crate::surface::psd::{self, PsdBin, PsdOptions, SelfAffineFit};
use crate::surface::spectrum::HURST_RANGE;
use serde::Serialize;

/// Everything `psd` reports of one map.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct PsdReport {
    /// The map's name (its file, or what the caller calls it).
    pub file: String,
    /// Points per row and rows (1 for a line scan).
    pub points: [usize; 2],
    /// Side L (m) of the x direction.
    pub system_size_m: f64,
    /// h_rms (m).
    pub rms_height_m: f64,
    /// ḡ.
    pub rms_gradient: f64,
    /// rms mean curvature ½∇²h (1/m).
    pub rms_curvature: f64,
    /// Fitted H (None without a fit).
    pub hurst: Option<f64>,
    /// Its standard error.
    pub hurst_error: Option<f64>,
    /// 2π/q_r of the fit (m).
    pub rolloff_wavelength_m: Option<f64>,
    /// [low, high] of λ_r (m).
    pub rolloff_wavelength_range_m: Option<[f64; 2]>,
    /// 2π/q_s of the fit (m).
    pub short_wavelength_m: Option<f64>,
    /// [low, high] of λ_s (m).
    pub short_wavelength_range_m: Option<[f64; 2]>,
    /// Whether the fit describes the map: a fit exists and its H lies in the self-affine range
    /// (0, 1]; false for e.g. two separate bands of roughness, whose "H" means nothing.
    pub self_affine: bool,
    /// Whether the map was a line scan (1-D PSD converted to 2-D).
    pub line_scan: bool,
    /// The window ("hann" or "none").
    pub window: String,
    /// The detrending.
    pub detrend: String,
    /// Elapsed time (s).
    pub elapsed_s: f64,
    /// The radial average: q (1/m), psd (m⁴), modes.
    pub table: Vec<PsdBin>,
    /// The fit in wave numbers (for a chart of the fitted law); not serialised.
    #[serde(skip)]
    pub fit: Option<SelfAffineFit>,
}

impl PsdReport {
    /// The wave numbers and C(q) of the radial average.
    pub fn columns(&self) -> (Vec<f64>, Vec<f64>) {
        self.table.iter().map(|b| (b.q, b.psd)).unzip()
    }
}

/// The PSD report of `surface`, called `file` in the report and in errors (module docs).
///
/// # Errors
/// [`Error::Invalid`] naming the height map for a flat map or one whose moments overflow;
/// `bins_per_decade` outside [`psd::BINS_PER_DECADE_RANGE`].
pub fn psd(file: &str, surface: &Surface, opts: &PsdOptions) -> Result<PsdReport> {
    let start = std::time::Instant::now();
    // too small or flat: refused before the analysis
    psd::check(surface, opts)?;
    check_measurable(surface, file)?;
    let a = psd::analyse(surface, opts)?;
    let two_pi = 2.0 * std::f64::consts::PI;
    let f = a.fit.as_ref();
    Ok(PsdReport {
        file: file.to_string(),
        points: [surface.nx, surface.ny],
        system_size_m: surface.size_x(),
        rms_height_m: a.rms_height,
        rms_gradient: a.rms_gradient,
        rms_curvature: a.rms_curvature,
        hurst: f.map(|f| f.hurst),
        hurst_error: f.map(|f| f.hurst_error),
        rolloff_wavelength_m: f.map(|f| two_pi / f.q_r),
        rolloff_wavelength_range_m: f.map(|f| [two_pi / f.q_r_high, two_pi / f.q_r_low]),
        short_wavelength_m: f.map(|f| two_pi / f.q_s),
        short_wavelength_range_m: f.map(|f| [two_pi / f.q_s_high, two_pi / f.q_s]),
        self_affine: f.is_some_and(|f| (HURST_RANGE.0..=HURST_RANGE.1).contains(&f.hurst)),
        line_scan: a.line_scan,
        window: a.window.to_string(),
        detrend: a.detrend.to_string(),
        elapsed_s: start.elapsed().as_secs_f64(),
        table: a.bins,
        fit: a.fit,
    })
}

/// Refuses a map whose moments cannot be measured: a flat one, or heights whose squares
/// overflow (1e200 m), named by `file`'s last component.
fn check_measurable(s: &Surface, file: &str) -> Result<()> {
    let name = std::path::Path::new(file)
        .file_name()
        .map_or_else(|| file.to_string(), |n| n.to_string_lossy().into_owned());
    if s.heights.iter().all(|&h| h == s.heights[0]) {
        return Err(Error::invalid_text(
            Field::HeightMap,
            format!("{name}: a flat map"),
            "a height map with some roughness (a flat map has no spectrum)",
        ));
    }
    let (h, g) = (s.rms_height(), s.rms_gradient());
    if h.is_finite() && g.is_finite() {
        return Ok(());
    }
    Err(Error::invalid_text(
        Field::HeightMap,
        format!(
            "{name}: a map of rms height {} m, rms gradient {}",
            fmt_value(h),
            fmt_value(g)
        ),
        "a map whose heights' squares are finite (|h| below about 1e150; check the heights' unit)",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A periodic cosine: h_rms = A/√2 and ḡ = A·k/√2 exactly (one mode, no window).
    #[test]
    fn a_cosine_reports_its_moments() {
        let (n, l, amp) = (32usize, 1e-6, 1e-9);
        let k = 2.0 * std::f64::consts::PI * 2.0 / l;
        let da = l / n as f64;
        let heights: Vec<f64> = (0..n * n).map(|i| amp * (k * (i % n) as f64 * da).cos()).collect();
        let s = Surface::new(n, n, da, heights).unwrap();
        let opts = PsdOptions {
            periodic: true,
            ..PsdOptions::default()
        };
        let r = psd("dir/cos.txt", &s, &opts).unwrap();
        let tol = crate::tolerances::REPORT_PSD_MOMENT_REL;
        assert!(
            (r.rms_height_m / (amp / 2f64.sqrt()) - 1.0).abs() < tol,
            "{}",
            r.rms_height_m
        );
        assert!(
            (r.rms_gradient / (amp * k / 2f64.sqrt()) - 1.0).abs() < tol,
            "{}",
            r.rms_gradient
        );
        assert_eq!(r.points, [n, n]);
        assert_eq!(r.file, "dir/cos.txt");
        assert_eq!(r.columns().0.len(), r.table.len());
    }

    #[test]
    fn a_flat_map_is_refused_by_its_name() {
        let s = Surface::new(4, 4, 1e-7, vec![1e-9; 16]).unwrap();
        let e = psd("dir/flat.txt", &s, &PsdOptions::default()).unwrap_err();
        assert!(e.to_string().contains("flat.txt: a flat map"), "{e}");
        let huge: Vec<f64> = (0..16).map(|i| if i == 0 { 1e200 } else { 0.0 }).collect();
        let s = Surface::new(4, 4, 1e-7, huge).unwrap();
        let e = psd("huge.txt", &s, &PsdOptions::default()).unwrap_err();
        assert!(e.to_string().contains("rms gradient"), "{e}");
    }
}
