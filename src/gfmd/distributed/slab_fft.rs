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
    rows: Vec<(usize, usize)>,
    cols: Vec<(usize, usize)>,
    rank: usize,
    r2c: Arc<dyn realfft::RealToComplex<f64>>,
    c2r: Arc<dyn realfft::ComplexToReal<f64>>,
    col_fwd: Arc<dyn rustfft::Fft<f64>>,
    col_inv: Arc<dyn rustfft::Fft<f64>>,
    /// The rank's rows of the half spectrum (row-major, nh per row).
    rowspec: Vec<Complex64>,
    send: Vec<f64>,
    recv: Vec<f64>,
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
            send: vec![0.0; words],
            recv: vec![0.0; words],
            parallel: nx * (y1 - y0) >= PARALLEL_MIN_POINTS,
            rows,
            cols,
        }
    }

    /// This rank's rows [y₀, y₁) of the real field.
    pub fn my_rows(&self) -> (usize, usize) {
        self.rows[self.rank]
    }
    /// This rank's columns [c₀, c₁) of the half spectrum.
    pub fn my_cols(&self) -> (usize, usize) {
        self.cols[self.rank]
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
        transpose_rows_to_cols(
            comm,
            &self.rowspec,
            self.nh,
            self.ny,
            &self.rows,
            &self.cols,
            &mut self.send,
            &mut self.recv,
            spec,
        );
    }

    /// The rank's spectrum columns → its spectrum rows.
    fn cols_to_rows(&mut self, comm: &dyn Comm, spec: &[Complex64]) {
        transpose_cols_to_rows(
            comm,
            spec,
            self.nh,
            self.ny,
            &self.rows,
            &self.cols,
            &mut self.send,
            &mut self.recv,
            &mut self.rowspec,
        );
    }
}

/// Rows [y₀, y₁) of a `width`-wide complex array (row-major) → columns [c₀, c₁) of it, each
/// column contiguous over all `ny` rows (`out[(c − c₀)·ny + y]`).
#[allow(clippy::too_many_arguments)]
pub fn transpose_rows_to_cols(
    comm: &dyn Comm,
    rows_local: &[Complex64],
    width: usize,
    ny: usize,
    rows: &[(usize, usize)],
    cols: &[(usize, usize)],
    send: &mut Vec<f64>,
    recv: &mut Vec<f64>,
    out: &mut [Complex64],
) {
    let me = comm.rank();
    let (y0, y1) = rows[me];
    let (c0, c1) = cols[me];
    let nl = y1 - y0;
    let sc: Vec<usize> = cols.iter().map(|&(a, b)| 2 * nl * (b - a)).collect();
    let rc: Vec<usize> = rows.iter().map(|&(a, b)| 2 * (b - a) * (c1 - c0)).collect();
    send.resize(sc.iter().sum::<usize>().max(send.len()), 0.0);
    recv.resize(rc.iter().sum::<usize>().max(recv.len()), 0.0);
    let mut k = 0;
    for &(a, b) in cols {
        for y in 0..nl {
            let w = as_words(&rows_local[y * width + a..y * width + b]);
            send[k..k + w.len()].copy_from_slice(w);
            k += w.len();
        }
    }
    let total_r: usize = rc.iter().sum();
    comm.all_to_all_v(&send[..k], &sc, &mut recv[..total_r], &rc);
    let nc = c1 - c0;
    let mut k = 0;
    for &(a, b) in rows {
        for y in a..b {
            for c in 0..nc {
                out[c * ny + y] = Complex64::new(recv[k], recv[k + 1]);
                k += 2;
            }
        }
    }
}

/// The inverse of [`transpose_rows_to_cols`].
#[allow(clippy::too_many_arguments)]
pub fn transpose_cols_to_rows(
    comm: &dyn Comm,
    cols_local: &[Complex64],
    width: usize,
    ny: usize,
    rows: &[(usize, usize)],
    cols: &[(usize, usize)],
    send: &mut Vec<f64>,
    recv: &mut Vec<f64>,
    out: &mut [Complex64],
) {
    let me = comm.rank();
    let (y0, y1) = rows[me];
    let (c0, c1) = cols[me];
    let nl = y1 - y0;
    let nc = c1 - c0;
    let sc: Vec<usize> = rows.iter().map(|&(a, b)| 2 * (b - a) * nc).collect();
    let rc: Vec<usize> = cols.iter().map(|&(a, b)| 2 * nl * (b - a)).collect();
    send.resize(sc.iter().sum::<usize>().max(send.len()), 0.0);
    recv.resize(rc.iter().sum::<usize>().max(recv.len()), 0.0);
    let mut k = 0;
    for &(a, b) in rows {
        for y in a..b {
            for c in 0..nc {
                let z = cols_local[c * ny + y];
                send[k] = z.re;
                send[k + 1] = z.im;
                k += 2;
            }
        }
    }
    let total_r: usize = rc.iter().sum();
    comm.all_to_all_v(&send[..k], &sc, &mut recv[..total_r], &rc);
    let mut k = 0;
    for &(a, b) in cols {
        for y in 0..nl {
            let dst = as_words_mut(&mut out[y * width + a..y * width + b]);
            dst.copy_from_slice(&recv[k..k + dst.len()]);
            k += dst.len();
        }
    }
}
