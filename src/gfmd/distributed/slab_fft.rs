//! The 2-D real FFT of a field distributed by rows (slab decomposition).
//!
//! Rank r holds rows [y₀, y₁) of the nx × ny real field ([`share`] of ny). A forward transform
//! is: real-to-complex transforms of the rank's rows (nh = nx/2 + 1 values each), an all-to-all
//! transpose after which rank r holds whole columns kx ∈ [c₀, c₁) ([`share`] of nh, each column
//! contiguous, ky = 0..ny), and complex transforms of those columns. The inverse runs the same
//! steps backwards. The convolution φ⋆w of the solver multiplies by the kernel while the
//! columns are local, so a convolution costs two transposes of the half spectrum
//! (16·nh·ny bytes each, (N − 1)/N of it crossing the network).
//!
//! Every 1-D transform is the one [`RealFft2`](crate::numerics::fft2::RealFft2) applies to the
//! same row or column (same plans, same lengths), and the transposes only move numbers, so the
//! result equals the serial transform bit for bit whatever the number of ranks.

use super::comm::{as_words, as_words_mut, share, Comm};
use rustfft::num_complex::Complex64;
use std::sync::Arc;

/// Local rows (or columns) per rank above which the 1-D transforms run on rayon.
const PARALLEL_MIN_POINTS: usize = 1 << 15;

/// A planned slab-distributed real 2-D FFT (see the module docs).
pub struct SlabFft {
    nx: usize,
    ny: usize,
    nh: usize,
    rank: usize,
    r2c: Arc<dyn realfft::RealToComplex<f64>>,
    c2r: Arc<dyn realfft::ComplexToReal<f64>>,
    col_fwd: Arc<dyn rustfft::Fft<f64>>,
    col_inv: Arc<dyn rustfft::Fft<f64>>,
    /// The rank's rows of the half spectrum (row-major, nh per row).
    rowspec: Vec<Complex64>,
    transpose: Transpose,
    parallel: bool,
}

impl std::fmt::Debug for SlabFft {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "SlabFft({} x {}, rows {:?}, cols {:?})",
            self.nx,
            self.ny,
            self.my_rows(),
            self.my_cols()
        )
    }
}

impl SlabFft {
    /// Plans the transforms of an nx × ny field over `size` ranks, for rank `rank`. Needs
    /// ny ≥ size and nx/2 + 1 ≥ size (every rank holds some rows and some columns).
    pub fn new(nx: usize, ny: usize, rank: usize, size: usize) -> Self {
        let nh = nx / 2 + 1;
        assert!(
            ny >= size && nh >= size && rank < size,
            "SlabFft: grid too small for the ranks"
        );
        let mut rp = realfft::RealFftPlanner::<f64>::new();
        let mut cp = rustfft::FftPlanner::<f64>::new();
        let rows: Vec<_> = (0..size).map(|r| share(ny, size, r)).collect();
        let cols: Vec<_> = (0..size).map(|r| share(nh, size, r)).collect();
        let (y0, y1) = rows[rank];
        let (c0, c1) = cols[rank];
        let words = 2 * ((y1 - y0) * nh).max((c1 - c0) * ny);
        SlabFft {
            nx,
            ny,
            nh,
            rank,
            r2c: rp.plan_fft_forward(nx),
            c2r: rp.plan_fft_inverse(nx),
            col_fwd: cp.plan_fft_forward(ny),
            col_inv: cp.plan_fft_inverse(ny),
            rowspec: vec![Complex64::new(0.0, 0.0); (y1 - y0) * nh],
            parallel: nx * (y1 - y0) >= PARALLEL_MIN_POINTS,
            transpose: Transpose {
                width: nh,
                ny,
                rows,
                cols,
                send: vec![0.0; words],
                recv: vec![0.0; words],
            },
        }
    }

    /// This rank's rows [y₀, y₁) of the real field.
    pub fn my_rows(&self) -> (usize, usize) {
        self.transpose.rows[self.rank]
    }
    /// This rank's columns [c₀, c₁) of the half spectrum.
    pub fn my_cols(&self) -> (usize, usize) {
        self.transpose.cols[self.rank]
    }
    /// nx/2 + 1.
    pub fn nh(&self) -> usize {
        self.nh
    }
    /// Length of this rank's part of the half spectrum, (c₁ − c₀)·ny (layout
    /// `spec[(kx − c₀)·ny + ky]`).
    pub fn local_spectrum_len(&self) -> usize {
        let (c0, c1) = self.my_cols();
        (c1 - c0) * self.ny
    }
    /// Number of real values of this rank's rows.
    pub fn local_len(&self) -> usize {
        let (y0, y1) = self.my_rows();
        (y1 - y0) * self.nx
    }

    /// Unnormalised forward transform of the rank's rows `input` into its columns `spec`
    /// (layout of [`SlabFft::local_spectrum_len`]).
    pub fn forward(&mut self, comm: &dyn Comm, input: &[f64], spec: &mut [Complex64]) {
        assert!(
            input.len() == self.local_len() && spec.len() == self.local_spectrum_len(),
            "SlabFft::forward: sizes"
        );
        self.rows_forward(input);
        self.rows_to_cols(comm, spec);
        let fwd = self.col_fwd.clone();
        self.each_column(spec, &|col, scratch| fwd.process_with_scratch(col, scratch));
    }

    /// out = inverse(kernel · forward(input)), unnormalised (include 1/(nx·ny) in the kernel);
    /// `kernel` in the rank's column layout, `spec` scratch of that size. Equal bit for bit to
    /// [`RealFft2::convolve`](crate::numerics::fft2::RealFft2::convolve) on the whole field.
    pub fn convolve(
        &mut self,
        comm: &dyn Comm,
        input: &[f64],
        kernel: &[f64],
        spec: &mut [Complex64],
        out: &mut [f64],
    ) {
        assert!(
            kernel.len() == self.local_spectrum_len() && out.len() == self.local_len(),
            "SlabFft::convolve: sizes"
        );
        self.rows_forward(input);
        self.rows_to_cols(comm, spec);
        let (fwd, inv, ny) = (self.col_fwd.clone(), self.col_inv.clone(), self.ny);
        let go = |col: &mut [Complex64], k: &[f64], scratch: &mut [Complex64]| {
            fwd.process_with_scratch(col, scratch);
            for (x, &f) in col.iter_mut().zip(k) {
                *x *= f;
            }
            inv.process_with_scratch(col, scratch);
        };
        let scratch_len = fwd.get_inplace_scratch_len().max(inv.get_inplace_scratch_len());
        if self.parallel {
            use rayon::prelude::*;
            spec.par_chunks_mut(ny).zip(kernel.par_chunks(ny)).for_each_init(
                || vec![Complex64::new(0.0, 0.0); scratch_len],
                |s, (col, k)| go(col, k, s),
            );
        } else {
            let mut s = vec![Complex64::new(0.0, 0.0); scratch_len];
            for (col, k) in spec.chunks_mut(ny).zip(kernel.chunks(ny)) {
                go(col, k, &mut s);
            }
        }
        self.cols_to_rows(comm, spec);
        let (c2r, nx, nh) = (self.c2r.clone(), self.nx, self.nh);
        let rows = |(a, b): (&mut [f64], &mut [Complex64])| {
            let mut scratch = c2r.make_scratch_vec();
            // realfft zeroes the round-off imaginary parts of kx = 0 (and Nyquist) and reports
            // it, which is not an error here (as in the serial transform)
            let _ = c2r.process_with_scratch(b, a, &mut scratch);
        };
        if self.parallel {
            use rayon::prelude::*;
            out.par_chunks_mut(nx)
                .zip(self.rowspec.par_chunks_mut(nh))
                .for_each(rows);
        } else {
            out.chunks_mut(nx).zip(self.rowspec.chunks_mut(nh)).for_each(rows);
        }
    }

    fn rows_forward(&mut self, input: &[f64]) {
        let (r2c, nx, nh) = (self.r2c.clone(), self.nx, self.nh);
        let rows = |(a, b): (&[f64], &mut [Complex64])| {
            let mut scratch = r2c.make_scratch_vec();
            let mut row = a.to_vec();
            r2c.process_with_scratch(&mut row, b, &mut scratch)
                .expect("planned sizes");
        };
        if self.parallel {
            use rayon::prelude::*;
            input.par_chunks(nx).zip(self.rowspec.par_chunks_mut(nh)).for_each(rows);
        } else {
            input.chunks(nx).zip(self.rowspec.chunks_mut(nh)).for_each(rows);
        }
    }

    fn each_column(&self, spec: &mut [Complex64], f: &(dyn Fn(&mut [Complex64], &mut [Complex64]) + Sync)) {
        let n = self
            .col_fwd
            .get_inplace_scratch_len()
            .max(self.col_inv.get_inplace_scratch_len());
        if self.parallel {
            use rayon::prelude::*;
            spec.par_chunks_mut(self.ny)
                .for_each_init(|| vec![Complex64::new(0.0, 0.0); n], |s, col| f(col, s));
        } else {
            let mut s = vec![Complex64::new(0.0, 0.0); n];
            for col in spec.chunks_mut(self.ny) {
                f(col, &mut s);
            }
        }
    }

    /// The rank's spectrum rows → its spectrum columns (all ky).
    fn rows_to_cols(&mut self, comm: &dyn Comm, spec: &mut [Complex64]) {
        self.transpose.rows_to_cols(comm, &self.rowspec, spec);
    }

    /// The rank's spectrum columns → its spectrum rows.
    fn cols_to_rows(&mut self, comm: &dyn Comm, spec: &[Complex64]) {
        self.transpose.cols_to_rows(comm, spec, &mut self.rowspec);
    }
}

/// The all-to-all transpose of a `width`-wide complex array of `ny` rows between its two
/// layouts: rank r holds rows `rows[r]` (row-major) in one and columns `cols[r]` in the other,
/// each column contiguous over all `ny` rows (`out[(c − c₀)·ny + y]`). Holds the exchange
/// buffers.
pub struct Transpose {
    /// Row length of the array.
    pub width: usize,
    /// Number of rows.
    pub ny: usize,
    /// Each rank's rows [y₀, y₁).
    pub rows: Vec<(usize, usize)>,
    /// Each rank's columns [c₀, c₁).
    pub cols: Vec<(usize, usize)>,
    /// Words sent (reused between transposes).
    pub send: Vec<f64>,
    /// Words received (reused between transposes).
    pub recv: Vec<f64>,
}

impl Transpose {
    /// Rank `me`'s numbers of rows and of columns, and the words it holds for each rank in
    /// the row layout (2 · its rows · their columns) and in the column layout (2 · their rows ·
    /// its columns), with the send and receive buffers grown to hold the larger of the two
    /// totals.
    fn counts(&mut self, me: usize) -> ((usize, usize), Vec<usize>, Vec<usize>) {
        let (nl, nc) = (self.rows[me].1 - self.rows[me].0, self.cols[me].1 - self.cols[me].0);
        let by_row: Vec<usize> = self.cols.iter().map(|&(a, b)| 2 * nl * (b - a)).collect();
        let by_col: Vec<usize> = self.rows.iter().map(|&(a, b)| 2 * (b - a) * nc).collect();
        let words = by_row.iter().sum::<usize>().max(by_col.iter().sum());
        for buf in [&mut self.send, &mut self.recv] {
            buf.resize(words.max(buf.len()), 0.0);
        }
        ((nl, nc), by_row, by_col)
    }

    /// Sends the first `k` words of the send buffer, `sc[r]` of them to rank r, and receives
    /// `rc[r]` from rank r into the receive buffer.
    fn exchange(&mut self, comm: &dyn Comm, k: usize, sc: &[usize], rc: &[usize]) {
        let total_r: usize = rc.iter().sum();
        comm.all_to_all_v(&self.send[..k], sc, &mut self.recv[..total_r], rc);
    }

    /// Rows `rows[rank]` of the array (`rows_local`, row-major) → columns `cols[rank]` of it.
    pub fn rows_to_cols(&mut self, comm: &dyn Comm, rows_local: &[Complex64], out: &mut [Complex64]) {
        let ((nl, nc), sc, rc) = self.counts(comm.rank());
        let (width, ny) = (self.width, self.ny);
        let mut k = 0;
        for &(a, b) in &self.cols {
            for y in 0..nl {
                let w = as_words(&rows_local[y * width + a..y * width + b]);
                self.send[k..k + w.len()].copy_from_slice(w);
                k += w.len();
            }
        }
        self.exchange(comm, k, &sc, &rc);
        let mut k = 0;
        for &(a, b) in &self.rows {
            for y in a..b {
                for c in 0..nc {
                    out[c * ny + y] = Complex64::new(self.recv[k], self.recv[k + 1]);
                    k += 2;
                }
            }
        }
    }

    /// The inverse of [`Transpose::rows_to_cols`].
    pub fn cols_to_rows(&mut self, comm: &dyn Comm, cols_local: &[Complex64], out: &mut [Complex64]) {
        let ((nl, nc), rc, sc) = self.counts(comm.rank());
        let (width, ny) = (self.width, self.ny);
        let mut k = 0;
        for &(a, b) in &self.rows {
            for y in a..b {
                for c in 0..nc {
                    let z = cols_local[c * ny + y];
                    self.send[k] = z.re;
                    self.send[k + 1] = z.im;
                    k += 2;
                }
            }
        }
        self.exchange(comm, k, &sc, &rc);
        let mut k = 0;
        for &(a, b) in &self.cols {
            for y in 0..nl {
                let dst = as_words_mut(&mut out[y * width + a..y * width + b]);
                dst.copy_from_slice(&self.recv[k..k + dst.len()]);
                k += dst.len();
            }
        }
    }
}
