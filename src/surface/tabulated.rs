//! A tabulated isotropic PSD C(q): a measured spectrum (from a height map, or a table written by
//! a topography tool) fed to the theory instead of the ideal self-affine one.
//!
//! Between the table's points C is interpolated linearly in (ln q, ln C), i.e. as a power law
//! on each interval, so that a table of a piecewise power law (e.g. the self-affine PSD with
//! roll-off, physics.md §1, sampled at q_L, q_r, q_s and any points between) is reproduced
//! exactly. C = 0 outside the cut-offs [q_min, q_max], which are the table's ends unless the
//! caller narrows them. Units: q in 1/m, C in m⁴ in the convention h_rms² = 2π∫q C dq
//! (contact.engineering/SurfaceTopography tabulate C_ST = (2π)² C).
//!
//! The continuum quadratures ([`crate::surface::spectrum::Spectrum::nodes`]) are split at the
//! table's kinks: the interior points where the log–log slope changes by more than
//! [`KINK_SLOPE`] (a self-affine table's only kink is q_r), plus the cut-offs. Moments
//! ∫qⁿ dm are exact sums of power-law integrals over the intervals.
//!
//! The roll-off wave number q_r (the unit of reduced thicknesses t·q_r) is the fitted roll-off
//! of [`crate::surface::fit::fit_self_affine`] on the table inside the cut-offs.

use crate::error::{fmt_value, Error, Field, Result};
use crate::surface::ranges::{LENGTH_RANGE_M, RMS_GRADIENT_RANGE};
use std::f64::consts::PI;

/// A change of the log–log slope larger than this at a table point splits the quadrature there.
pub const KINK_SLOPE: f64 = 0.25;
/// Largest q_max/q_min of a table (as λ_r/λ_s of a self-affine spectrum).
pub const MAX_TABLE_BANDWIDTH: f64 = 1e8;
/// A table of more rows than this is resampled once onto [`RESAMPLE_PER_DECADE`] log-spaced
/// bins per decade of q (at most 1 601 nodes over the largest bandwidth), so that the cost of
/// every quadrature after it does not grow with the number of rows.
pub const MAX_TABLE_ROWS: usize = 4096;
/// Bins per decade of q of a resampled table.
pub const RESAMPLE_PER_DECADE: f64 = 200.0;

/// A tabulated PSD (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Tabulated {
    /// Wave numbers (1/m), strictly ascending.
    pub q: Vec<f64>,
    /// C(q) (m⁴), > 0.
    pub psd: Vec<f64>,
    /// Lower cut-off (1/m).
    pub q_min: f64,
    /// Upper cut-off (1/m).
    pub q_max: f64,
    /// Roll-off wave number (1/m), the unit of t·q_r.
    pub q_r: f64,
    /// Where the table came from (a file name), for output.
    pub source: String,
    /// The number of rows of a table resampled onto log-spaced bins ([`MAX_TABLE_ROWS`]);
    /// None when the rows are used as given.
    pub resampled_from: Option<usize>,
    /// Quadrature breakpoints: q_min, the kinks inside, q_max.
    kinks: Vec<f64>,
}

impl Tabulated {
    /// Builds a table. `q_min`/`q_max` narrow the cut-offs (None: the table's ends).
    ///
    /// # Errors
    /// [`Error::Invalid`] for fewer than two points, q not strictly ascending or not > 0, C not
    /// finite and > 0 (named by the table's row, `source:row N`), cut-offs outside the table or
    /// crossed, a bandwidth above [`MAX_TABLE_BANDWIDTH`], or an rms gradient outside
    /// [`RMS_GRADIENT_RANGE`].
    pub fn new(q: Vec<f64>, psd: Vec<f64>, source: &str, q_min: Option<f64>, q_max: Option<f64>) -> Result<Self> {
        let bad = |what: String| {
            Error::invalid_text(
                Field::Other("psd".into()),
                what,
                "a table of q (1/m) ascending and psd (m^4) > 0, two rows or more",
            )
        };
        if q.len() != psd.len() || q.len() < 2 {
            return Err(bad(format!("{source}: {} rows", q.len().min(psd.len()))));
        }
        for i in 0..q.len() {
            if !(q[i].is_finite() && q[i] > 0.0) {
                return Err(bad(format!(
                    "{source}: row {}: q = {} (not > 0)",
                    i + 1,
                    fmt_value(q[i])
                )));
            }
            if !(psd[i].is_finite() && psd[i] > 0.0) {
                return Err(bad(format!(
                    "{source}: row {}: psd = {} (not finite and > 0)",
                    i + 1,
                    fmt_value(psd[i])
                )));
            }
            if i > 0 && q[i] <= q[i - 1] {
                return Err(bad(format!(
                    "{source}: row {}: q = {} not above the previous row's",
                    i + 1,
                    fmt_value(q[i])
                )));
            }
        }
        let rows = q.len();
        let (q, psd) = if rows > MAX_TABLE_ROWS {
            resample(&q, &psd)
        } else {
            (q, psd)
        };
        let (lo, hi) = (q[0], q[q.len() - 1]);
        let q_min = q_min.unwrap_or(lo);
        let q_max = q_max.unwrap_or(hi);
        let range = format!("{} <= q <= {} (1/m, the table's ends)", fmt_value(lo), fmt_value(hi));
        if !(lo * (1.0 - 1e-12)..hi).contains(&q_min) {
            return Err(Error::invalid(Field::Other("q_min".into()), q_min, range));
        }
        if q_max.is_nan() || q_max > hi * (1.0 + 1e-12) || q_max <= q_min {
            return Err(Error::invalid(
                Field::Other("q_max".into()),
                q_max,
                format!("q_min < q <= {} (1/m)", fmt_value(hi)),
            ));
        }
        let (q_min, q_max) = (q_min.max(lo), q_max.min(hi));
        if q_max / q_min > MAX_TABLE_BANDWIDTH {
            return Err(bad(format!(
                "{source}: a bandwidth q_max/q_min = {}",
                fmt_value(q_max / q_min)
            )));
        }
        let (lmin, lmax) = (2.0 * PI / LENGTH_RANGE_M.1, 2.0 * PI / LENGTH_RANGE_M.0);
        if q_min < lmin || q_max > lmax {
            return Err(bad(format!(
                "{source}: q outside [{}, {}] 1/m",
                fmt_value(lmin),
                fmt_value(lmax)
            )));
        }
        let mut t = Tabulated {
            q,
            psd,
            q_min,
            q_max,
            q_r: q_min,
            source: source.to_string(),
            resampled_from: (rows > MAX_TABLE_ROWS).then_some(rows),
            kinks: Vec::new(),
        };
        t.kinks = t.find_kinks();
        let g = t.moment(2).sqrt();
        let (glo, ghi) = RMS_GRADIENT_RANGE;
        if !(glo..=ghi).contains(&g) {
            return Err(Error::invalid_text(
                Field::RmsGradient,
                format!("{} (of the table {source})", fmt_value(g)),
                format!(
                    "{} <= rms gradient <= {} (check the units: q in 1/m, psd in m^4)",
                    fmt_value(glo),
                    fmt_value(ghi)
                ),
            ));
        }
        let (qs, cs): (Vec<f64>, Vec<f64>) =
            t.q.iter()
                .zip(&t.psd)
                .filter(|(&x, _)| (t.q_min..=t.q_max).contains(&x))
                .map(|(&x, &c)| (x, c))
                .unzip();
        let weights = vec![1.0; qs.len()];
        if let Some(fit) = crate::surface::fit::fit_self_affine(&qs, &cs, &weights) {
            t.q_r = fit.q_r.clamp(t.q_min, t.q_max);
        }
        Ok(t)
    }

    /// The table's index i with q[i] ≤ x < q[i+1] (clamped to the intervals).
    fn interval(&self, x: f64) -> usize {
        self.q
            .partition_point(|&v| v <= x)
            .saturating_sub(1)
            .min(self.q.len() - 2)
    }

    /// Log–log slope of interval i.
    fn slope(&self, i: usize) -> f64 {
        (self.psd[i + 1] / self.psd[i]).ln() / (self.q[i + 1] / self.q[i]).ln()
    }

    fn find_kinks(&self) -> Vec<f64> {
        let mut k = vec![self.q_min];
        for i in 1..self.q.len() - 1 {
            let x = self.q[i];
            if x > self.q_min && x < self.q_max && (self.slope(i) - self.slope(i - 1)).abs() > KINK_SLOPE {
                k.push(x);
            }
        }
        k.push(self.q_max);
        k
    }

    /// Quadrature breakpoints (q_min, kinks, q_max).
    pub fn breakpoints(&self) -> &[f64] {
        &self.kinks
    }

    /// C(q) in m⁴ (0 outside [q_min, q_max]).
    pub fn psd_at(&self, x: f64) -> f64 {
        if !(self.q_min..=self.q_max).contains(&x) {
            return 0.0;
        }
        let i = self.interval(x);
        let f = (x / self.q[i]).ln() / (self.q[i + 1] / self.q[i]).ln();
        self.psd[i] * (f * (self.psd[i + 1] / self.psd[i]).ln()).exp()
    }

    /// ∫ qⁿ dm = 2π ∫ q^{n+1} C dq over [q_min, q_max], exact for the power-law intervals.
    pub fn moment(&self, n: i32) -> f64 {
        let mut sum = 0.0;
        for i in 0..self.q.len() - 1 {
            let a = self.q[i].max(self.q_min);
            let b = self.q[i + 1].min(self.q_max);
            if b <= a {
                continue;
            }
            // C = C(a)(q/a)^s on [a, b]: ∫ q^{n+1} C dq = C(a) a^{k} expm1(k ln(b/a))/k, k = n+2+s
            let s = self.slope(i);
            let k = n as f64 + 2.0 + s;
            let l = (b / a).ln();
            let part = if (k * l).abs() < 1e-12 { l } else { (k * l).exp_m1() / k };
            sum += self.psd_at(a) * a.powf(n as f64 + 2.0) * part;
        }
        2.0 * PI * sum
    }

    /// Parses a table as written by `asperity psd` (CSV with a header naming the columns `q`
    /// and `psd`; other columns are ignored; `#` lines are comments).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `source:line` and what is wrong, or the table's checks
    /// ([`Tabulated::new`]).
    pub fn parse_csv(text: &str, source: &str, q_min: Option<f64>, q_max: Option<f64>) -> Result<Self> {
        let bad = |line: usize, what: String| {
            Error::invalid_text(
                Field::Other("psd".into()),
                format!("{source}:{line}: {what}"),
                "a CSV table with columns q (1/m) and psd (m^4)",
            )
        };
        let mut cols: Option<(usize, usize)> = None;
        let (mut q, mut c) = (Vec::new(), Vec::new());
        for (i, line) in text.lines().enumerate() {
            let t = line.trim();
            if t.is_empty() || t.starts_with('#') {
                continue;
            }
            match cols {
                None => {
                    let cells: Vec<&str> = t.split(',').map(str::trim).collect();
                    let find = |name: &str| cells.iter().position(|c| c.eq_ignore_ascii_case(name));
                    match (find("q"), find("psd")) {
                        (Some(a), Some(b)) => cols = Some((a, b)),
                        _ => {
                            let head: String = t.chars().take(40).collect();
                            let more = if head.len() < t.len() { "..." } else { "" };
                            return Err(bad(
                                i + 1,
                                format!("header '{head}{more}' has no columns named q and psd"),
                            ));
                        }
                    }
                }
                Some((a, b)) => {
                    // the two cells found in one pass over the line, without collecting its
                    // cells (a table may have 10⁶ rows)
                    let (mut qa, mut cb) = (None, None);
                    for (k, cell) in t.split(',').enumerate() {
                        if k == a {
                            qa = Some(cell.trim());
                        }
                        if k == b {
                            cb = Some(cell.trim());
                        }
                    }
                    let cell = |k: usize, s: Option<&str>| -> Result<f64> {
                        let s = s.ok_or_else(|| {
                            bad(
                                i + 1,
                                format!("{} cells, column {} missing", t.split(',').count(), k + 1),
                            )
                        })?;
                        s.parse::<f64>()
                            .map_err(|_| bad(i + 1, format!("'{s}' (not a number)")))
                    };
                    q.push(cell(a, qa)?);
                    c.push(cell(b, cb)?);
                }
            }
        }
        if cols.is_none() {
            return Err(bad(1, "an empty file".into()));
        }
        Tabulated::new(q, c, source, q_min, q_max)
    }

    /// Reads a CSV table from a file (see [`Tabulated::parse_csv`]).
    ///
    /// # Errors
    /// [`Error::Io`] when the file cannot be read; the parse errors otherwise.
    pub fn load_csv(path: &std::path::Path, q_min: Option<f64>, q_max: Option<f64>) -> Result<Self> {
        use crate::input::file::{read_text, MAX_INPUT_BYTES};
        let field = crate::error::Field::Other("psd".into());
        let text = read_text(path, "", field, MAX_INPUT_BYTES, "a PSD table as lines of q, C(q)")?;
        // errors name the file by its name (a long path would be shortened past it); the
        // table keeps the whole path as its source
        let name = path
            .file_name()
            .map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
        let mut t = Tabulated::parse_csv(&text, &name, q_min, q_max)?;
        t.source = path.display().to_string();
        Ok(t)
    }
}

/// A long table (ascending q, C > 0) on log-spaced bins of width ln 10/[`RESAMPLE_PER_DECADE`]:
/// each bin's rows become one node at the mean of their ln q with the mean of their ln C
/// (exact for a power law inside the bin; a noisy table is averaged, not aliased), the first
/// and the last row kept as the cut-offs. One pass over the rows.
fn resample(q: &[f64], psd: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let n = q.len();
    let (l0, width) = (q[0].ln(), std::f64::consts::LN_10 / RESAMPLE_PER_DECADE);
    let (mut qs, mut cs) = (vec![q[0]], vec![psd[0]]);
    let (mut bin, mut sum_q, mut sum_c, mut count) = (usize::MAX, 0.0, 0.0, 0.0);
    fn flush(sum_q: f64, sum_c: f64, count: f64, qs: &mut Vec<f64>, cs: &mut Vec<f64>) {
        if count > 0.0 {
            qs.push((sum_q / count).exp());
            cs.push((sum_c / count).exp());
        }
    }
    for i in 1..n - 1 {
        let (lq, lc) = (q[i].ln(), psd[i].ln());
        let b = ((lq - l0) / width) as usize;
        if b != bin {
            flush(sum_q, sum_c, count, &mut qs, &mut cs);
            (bin, sum_q, sum_c, count) = (b, 0.0, 0.0, 0.0);
        }
        sum_q += lq;
        sum_c += lc;
        count += 1.0;
    }
    flush(sum_q, sum_c, count, &mut qs, &mut cs);
    qs.push(q[n - 1]);
    cs.push(psd[n - 1]);
    // a bin's mean lies strictly inside its ends: the nodes ascend (an equal neighbour, from
    // rounding at the ends, is dropped)
    let mut keep_q = Vec::with_capacity(qs.len());
    let mut keep_c = Vec::with_capacity(qs.len());
    for (x, c) in qs.into_iter().zip(cs) {
        if keep_q.last().is_none_or(|&p| x > p) {
            keep_q.push(x);
            keep_c.push(c);
        }
    }
    (keep_q, keep_c)
}

/// A table as CSV: header `q,psd`, then one row per point, shortest round-trip decimals (a
/// written table reads back bit for bit).
pub fn to_csv(q: &[f64], psd: &[f64]) -> String {
    let mut s = String::from("q,psd\n");
    for (x, c) in q.iter().zip(psd) {
        s.push_str(&format!("{x:e},{c:e}\n"));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::spectrum::{Normalisation, SelfAffine, Spectrum};

    #[test]
    fn a_self_affine_table_has_the_closed_form_moments_and_its_kink() {
        let sa = SelfAffine::new(100e-6, 20e-6, 0.1e-6, 0.8, Normalisation::RmsGradient(1.0)).unwrap();
        let mut q: Vec<f64> = (0..=40)
            .map(|k| sa.q_l() * (sa.q_s() / sa.q_l()).powf(k as f64 / 40.0))
            .collect();
        q.push(sa.q_r());
        q.sort_by(f64::total_cmp);
        q.dedup();
        *q.last_mut().unwrap() = sa.q_s();
        let c: Vec<f64> = q.iter().map(|&x| sa.psd(x)).collect();
        let t = Tabulated::parse_csv(&to_csv(&q, &c), "mem", None, None).unwrap();
        assert_eq!(t.breakpoints(), &[sa.q_l(), sa.q_r(), sa.q_s()]);
        assert_eq!(t.q_r, sa.q_r());
        let exact = Spectrum::SelfAffine(sa);
        for n in [0, 2, 4] {
            assert!((t.moment(n) / exact.moment(n) - 1.0).abs() < 1e-12, "n = {n}");
        }
        for &x in &[sa.q_l() * 1.3, sa.q_r() * 2.7, sa.q_s() * 0.99] {
            assert!((t.psd_at(x) / sa.psd(x) - 1.0).abs() < 1e-12);
        }
        assert_eq!(t.psd_at(sa.q_s() * 1.01), 0.0);
    }

    #[test]
    fn a_long_table_is_resampled_once_and_keeps_its_moments() {
        let sa = SelfAffine::new(100e-6, 20e-6, 0.1e-6, 0.8, Normalisation::RmsGradient(1.0)).unwrap();
        let exact = Spectrum::SelfAffine(sa);
        for rows in [MAX_TABLE_ROWS + 1, 100_000] {
            let q: Vec<f64> = (0..rows)
                .map(|k| sa.q_l() * (sa.q_s() / sa.q_l()).powf(k as f64 / (rows - 1) as f64))
                .collect();
            let c: Vec<f64> = q.iter().map(|&x| sa.psd(x)).collect();
            let t = Tabulated::new(q, c, "mem", None, None).unwrap();
            assert_eq!(t.resampled_from, Some(rows));
            let decades = (sa.q_s() / sa.q_l()).log10();
            assert!(t.q.len() as f64 <= RESAMPLE_PER_DECADE * decades + 3.0, "{}", t.q.len());
            assert_eq!((t.q_min, t.q_max), (sa.q_l(), sa.q_s()));
            // the power law is exact inside each bin; the bin around the kink q_r is off
            for n in [0, 2, 4] {
                let rel = (t.moment(n) / exact.moment(n) - 1.0).abs();
                assert!(
                    rel < crate::tolerances::RESAMPLED_TABLE_REL,
                    "rows {rows}, n = {n}: {rel:e}"
                );
            }
        }
        let short = Tabulated::new(vec![1e4, 1e5, 1e6], vec![1e-30, 1e-32, 1e-34], "mem", None, None).unwrap();
        assert_eq!(short.resampled_from, None);
    }

    #[test]
    fn bad_tables_name_the_row() {
        for (text, needle) in [
            ("q,psd\n1,1\n", "1 rows"),
            ("q,psd\n1,1\n2,0\n", "row 2"),
            ("q,psd\n2,1\n1,1\n", "row 2"),
            ("x,y\n1,1\n", "no columns named q and psd"),
            ("q,psd\n1,a\n", "mem:2: 'a'"),
            ("", "empty"),
        ] {
            let e = Tabulated::parse_csv(text, "mem", None, None).unwrap_err().to_string();
            assert!(e.contains(needle), "{text:?}: {e}");
        }
    }
}
