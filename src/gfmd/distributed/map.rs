//! The height map by slabs: every rank generates only its rows, and the map's moments (h_rms,
//! ḡ, the discrete spectrum for the theory) are computed without any rank holding the map.
//!
//! Generation is [`crate::surface::heightmap::generate`]'s Fourier filtering ([`crate::surface::heightmap`]
//! module docs) step for step: every rank walks the modes in the serial order and draws the
//! same SplitMix64 numbers (a draw costs a few integer operations), keeping the modes of its
//! rows and the conjugates that land in them; the rescaling to the target ḡ uses the same
//! ordered sum (it depends on the amplitudes only, not on the random phases); the inverse 2-D
//! transform is the serial one's row and column transforms with an all-to-all transpose in
//! between ([`super::slab_fft`]). The slab equals the serial map's rows bit for bit.

use super::comm::{chain_fold, chain_fold_var, chain_sum, share, Comm};
use super::slab_fft::{SlabFft, Transpose};
use crate::error::{Error, Field, Result};
use crate::surface::heightmap::{fourier_rows, wave_number_sq};
use crate::surface::spectrum::{Discrete, SelfAffine};
use rustfft::num_complex::Complex64;
use std::collections::BTreeMap;

/// Rows [y₀, y₁) of an nx × ny periodic height map (metres, row-major).
#[derive(Debug, Clone, PartialEq)]
pub struct Slab {
    /// Points per row.
    pub nx: usize,
    /// Rows of the whole map.
    pub ny: usize,
    /// Lattice spacing Δa (m).
    pub spacing: f64,
    /// First row held.
    pub y0: usize,
    /// One past the last row held.
    pub y1: usize,
    /// Heights of rows y₀..y₁ (m), `heights[(y − y₀)·nx + x]`.
    pub heights: Vec<f64>,
}

impl Slab {
    /// Rows `[y0, y1)` of a whole map (to hand a loaded map to the ranks).
    pub fn of_map(s: &crate::surface::heightmap::Surface, y0: usize, y1: usize) -> Slab {
        Slab {
            nx: s.nx,
            ny: s.ny,
            spacing: s.spacing,
            y0,
            y1,
            heights: s.heights[y0 * s.nx..y1 * s.nx].to_vec(),
        }
    }
    /// Global index of the first node held.
    pub fn offset(&self) -> usize {
        self.y0 * self.nx
    }
    /// Number of nodes of the whole map.
    pub fn nodes(&self) -> usize {
        self.nx * self.ny
    }
}

/// This rank's rows of [`heightmap::generate`]`(spec, n, seed)`, bit for bit (module docs).
///
/// # Errors
/// As [`heightmap::generate`].
///
/// [`heightmap::generate`]: crate::surface::heightmap::generate
pub fn generate(comm: &dyn Comm, spec: &SelfAffine, n: usize, seed: u64) -> Result<Slab> {
    let size = comm.size();
    let rows: Vec<_> = (0..size).map(|r| share(n, size, r)).collect();
    let (y0, y1) = rows[comm.rank()];
    let (mut ht, da) = fourier_rows(spec, n, seed, (y0, y1))?;
    complex_transform(comm, &mut ht, n, &rows, true);
    let heights: Vec<f64> = ht.iter().map(|c| c.re).collect();
    let bad = heights.iter().any(|h| !h.is_finite()) as usize;
    if super::comm::all_sum_counts(comm, &[bad])[0] > 0 {
        return Err(Error::invalid_text(
            Field::HeightMap,
            "a non-finite height",
            "finite heights",
        ));
    }
    Ok(Slab {
        nx: n,
        ny: n,
        spacing: da,
        y0,
        y1,
        heights,
    })
}

/// The unnormalised complex 2-D transform of an n × n array held by rows (`rows[rank]`):
/// [`crate::numerics::fft2::transform`]'s row and column transforms, distributed.
fn complex_transform(comm: &dyn Comm, data: &mut [Complex64], n: usize, rows: &[(usize, usize)], inverse: bool) {
    let mut planner = rustfft::FftPlanner::<f64>::new();
    let fft = if inverse {
        planner.plan_fft_inverse(n)
    } else {
        planner.plan_fft_forward(n)
    };
    let size = comm.size();
    let cols: Vec<_> = (0..size).map(|r| share(n, size, r)).collect();
    let (c0, c1) = cols[comm.rank()];
    fft.process(data);
    let mut colsbuf = vec![Complex64::new(0.0, 0.0); (c1 - c0) * n];
    let mut t = Transpose {
        width: n,
        ny: n,
        rows: rows.to_vec(),
        cols,
        send: Vec::new(),
        recv: Vec::new(),
    };
    t.rows_to_cols(comm, data, &mut colsbuf);
    fft.process(&mut colsbuf);
    t.cols_to_rows(comm, &colsbuf, data);
}

/// h_rms about the mean (m): [`Surface::rms_height`] of the whole map, bit for bit.
///
/// [`Surface::rms_height`]: crate::surface::heightmap::Surface::rms_height
pub fn rms_height(comm: &dyn Comm, s: &Slab) -> f64 {
    let n = s.nodes() as f64;
    let mean = chain_sum(comm, s.heights.iter().copied()) / n;
    (chain_sum(comm, s.heights.iter().map(|h| (h - mean).powi(2))) / n).sqrt()
}

/// Discrete rms gradient ḡ: [`Surface::rms_gradient`] of the whole map, bit for bit (the
/// serial sum runs over kx outer, ky inner: after the transpose each rank holds a run of kx).
///
/// [`Surface::rms_gradient`]: crate::surface::heightmap::Surface::rms_gradient
pub fn rms_gradient(comm: &dyn Comm, fft: &mut SlabFft, s: &Slab) -> f64 {
    let mut spec = vec![Complex64::new(0.0, 0.0); fft.local_spectrum_len()];
    fft.forward(comm, &s.heights, &mut spec);
    let (nx, ny) = (s.nx, s.ny);
    let norm = 1.0 / (nx * ny) as f64;
    let (c0, c1) = fft.my_cols();
    let weight = |kx: usize| {
        if kx == 0 || (nx.is_multiple_of(2) && kx == nx / 2) {
            1.0
        } else {
            2.0
        }
    };
    let total = chain_fold(comm, vec![0.0], &mut |st| {
        for kx in c0..c1 {
            for ky in 0..ny {
                let q2 = wave_number_sq(kx, ky, nx, ny, s.spacing);
                st[0] += weight(kx) * q2 * (spec[(kx - c0) * ny + ky] * norm).norm_sqr();
            }
        }
    });
    total[0].sqrt()
}

/// The discrete spectrum of the (square) map: [`Discrete::from_height_map`] of the whole
/// map, bit for bit: the full complex transform by slabs, then Σ|h̃|² per |k|² added in the
/// serial (row-major) order by passing the partial sums from rank to rank. Every rank gets it.
///
/// # Errors
/// As [`Discrete::from_height_map`] (a flat map).
pub fn discrete_spectrum(comm: &dyn Comm, s: &Slab, q_r: f64) -> Result<Discrete> {
    let n = s.nx;
    let size = comm.size();
    let rows: Vec<_> = (0..size).map(|r| share(n, size, r)).collect();
    let mut data: Vec<Complex64> = s.heights.iter().map(|&x| Complex64::new(x, 0.0)).collect();
    complex_transform(comm, &mut data, n, &rows, false);
    // the state: (k², Σ) pairs of the bins met so far, ascending in k²
    let flat = chain_fold_var(comm, Vec::new(), &mut |st| {
        let mut by_k2: BTreeMap<i64, f64> = st.chunks(2).map(|p| (p[0] as i64, p[1])).collect();
        Discrete::add_mode_sums(&data, s.y0..s.y1, n, &mut by_k2);
        *st = by_k2.into_iter().flat_map(|(k, v)| [k as f64, v]).collect();
    });
    let by_k2: BTreeMap<i64, f64> = flat.chunks(2).map(|p| (p[0] as i64, p[1])).collect();
    Discrete::from_mode_sums(by_k2, s.nx as f64 * s.spacing, q_r)
}
