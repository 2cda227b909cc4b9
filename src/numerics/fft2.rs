//! Two-dimensional FFTs on N×N periodic grids (row-major), built on rustfft.
//!
//! Unnormalised forward transform F(k) = Σ_r h(r) e^{−ik·r}; with the convention of
//! physics.md §1, h̃(q) = F(q)/N². This is the one place where that conversion is written.

use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;

/// Full complex forward 2-D FFT of a real N×N map (row-major).
pub fn forward_real(h: &[f64], n: usize) -> Vec<Complex64> {
    let mut data: Vec<Complex64> = h.iter().map(|&x| Complex64::new(x, 0.0)).collect();
    transform(&mut data, n, false);
    data
}

/// In-place 2-D FFT (forward or inverse, unnormalised) of an N×N complex array.
pub fn transform(data: &mut [Complex64], n: usize, inverse: bool) {
    assert_eq!(data.len(), n * n, "fft2: data must be N x N");
    let mut planner = FftPlanner::<f64>::new();
    let fft = if inverse {
        planner.plan_fft_inverse(n)
    } else {
        planner.plan_fft_forward(n)
    };
    // rows
    fft.process(data);
    // columns: transpose, transform rows, transpose back
    transpose(data, n);
    fft.process(data);
    transpose(data, n);
}

fn transpose(data: &mut [Complex64], n: usize) {
    for i in 0..n {
        for j in (i + 1)..n {
            data.swap(i * n + j, j * n + i);
        }
    }
}

/// Inverse 2-D FFT normalised by 1/N², so that `inverse(forward(h)) == h`.
pub fn inverse_normalised(data: &mut [Complex64], n: usize) {
    transform(data, n, true);
    let s = 1.0 / (n * n) as f64;
    for c in data.iter_mut() {
        *c *= s;
    }
}

/// A planned real-to-complex 2-D FFT of an `nx`×`ny` real field (row-major, `ny` rows of
/// `nx` values), for solvers that transform the same grid thousands of times. Plans and
/// buffers are made once in [`RealFft2::new`]; rows, and strips of columns, are transformed in
/// parallel (rayon) on large grids.
///
/// Spectrum layout: the half spectrum kx = 0..=nx/2, row-major, `spec[ky * nh + kx]` with
/// nh = nx/2 + 1 and ky = 0..ny (wrapped: ky > ny/2 means ky − ny). Both directions are
/// unnormalised (forward then inverse multiplies by nx·ny), as [`transform`]; mode (kx, ky)
/// equals `forward_real(h)[ky * nx + kx]` of the full transform of a square grid.
///
/// The column transforms gather strips of [`STRIP`] columns into a small contiguous buffer
/// (no full transposes: they cost a quarter of the run time on 1024² grids, the power-of-two
/// strides defeating the cache).
pub struct RealFft2 {
    nx: usize,
    ny: usize,
    nh: usize,
    r2c: std::sync::Arc<dyn realfft::RealToComplex<f64>>,
    c2r: std::sync::Arc<dyn realfft::ComplexToReal<f64>>,
    col_fwd: std::sync::Arc<dyn rustfft::Fft<f64>>,
    col_inv: std::sync::Arc<dyn rustfft::Fft<f64>>,
    parallel: bool,
}

impl std::fmt::Debug for RealFft2 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "RealFft2({} x {})", self.nx, self.ny)
    }
}

/// A real convolution kernel on the half spectrum of a [`RealFft2`], stored column by column
/// (`values[kx * len + ky]`) so that the column pass of a convolution reads it in order. Made
/// once per kernel with [`RealFft2::kernel`]. A kernel even in ky (k(kx, ky) = k(kx, ny − ky),
/// bit for bit, as every kernel of |q|) keeps ky = 0..=ny/2 only (`len` = ny/2 + 1 instead
/// of ny): the column pass then reads half as much.
#[derive(Debug, Clone)]
pub struct SpectralKernel {
    columns: Vec<f64>,
    len: usize,
}

/// Grids with at least this many points are transformed with rayon.
const PARALLEL_MIN_POINTS: usize = 1 << 15;

/// Columns per gathered strip of the column transforms.
pub const STRIP: usize = 16;

/// Padding (complex values) between the columns of a gathered strip.
const STRIP_PAD: usize = 4;

impl SpectralKernel {
    /// Whether this is a kernel of an `nh` × `ny` half spectrum.
    fn fits(&self, nh: usize, ny: usize) -> bool {
        (self.len == ny || self.len == ny / 2 + 1) && self.columns.len() == nh * self.len
    }

    /// Multiplies column `kx` of a spectrum (ky = 0..ny) by the kernel.
    fn apply(&self, kx: usize, col: &mut [Complex64]) {
        let ny = col.len();
        let k = &self.columns[kx * self.len..(kx + 1) * self.len];
        if self.len == ny {
            for (x, &f) in col.iter_mut().zip(k) {
                *x *= f;
            }
        } else {
            // ky = 0..=ny/2 as stored, then ny/2 + 1..ny from ny − ky = ny/2 − 1 (odd ny:
            // ny/2)..1
            let (low, high) = col.split_at_mut(ny / 2 + 1);
            for (x, &f) in low.iter_mut().zip(k) {
                *x *= f;
            }
            for (x, &f) in high.iter_mut().zip(k[1..ny - ny / 2].iter().rev()) {
                *x *= f;
            }
        }
    }
}

impl RealFft2 {
    /// Plans the transforms of an `nx`×`ny` grid (both ≥ 1).
    pub fn new(nx: usize, ny: usize) -> Self {
        assert!(nx >= 1 && ny >= 1, "RealFft2: empty grid");
        let mut rp = realfft::RealFftPlanner::<f64>::new();
        let mut cp = FftPlanner::<f64>::new();
        RealFft2 {
            nx,
            ny,
            nh: nx / 2 + 1,
            r2c: rp.plan_fft_forward(nx),
            c2r: rp.plan_fft_inverse(nx),
            col_fwd: cp.plan_fft_forward(ny),
            col_inv: cp.plan_fft_inverse(ny),
            parallel: nx * ny >= PARALLEL_MIN_POINTS,
        }
    }

    /// Number of points per row (fast index).
    pub fn nx(&self) -> usize {
        self.nx
    }
    /// Number of rows.
    pub fn ny(&self) -> usize {
        self.ny
    }
    /// nx/2 + 1, the number of kx stored.
    pub fn nh(&self) -> usize {
        self.nh
    }
    /// Length of the half spectrum, (nx/2 + 1)·ny.
    pub fn spectrum_len(&self) -> usize {
        self.nh * self.ny
    }
    /// Weight of stored mode kx in a sum over the full spectrum (1 for kx = 0 and, for even
    /// nx, kx = nx/2; 2 otherwise: the conjugate mode is not stored).
    pub fn weight(&self, kx: usize) -> f64 {
        if kx == 0 || (self.nx.is_multiple_of(2) && kx == self.nx / 2) {
            1.0
        } else {
            2.0
        }
    }

    /// The kernel with half-spectrum values `values` (row-major, `values[ky * nh + kx]`, the
    /// layout of [`RealFft2::forward`]'s output).
    pub fn kernel(&self, values: &[f64]) -> SpectralKernel {
        let (ny, nh) = (self.ny, self.nh);
        assert_eq!(values.len(), nh * ny, "RealFft2::kernel: size");
        let even = (1..ny).all(|ky| (0..nh).all(|kx| values[ky * nh + kx] == values[(ny - ky) * nh + kx]));
        let len = if even { ny / 2 + 1 } else { ny };
        let mut columns = vec![0.0; nh * len];
        for ky in 0..len {
            for kx in 0..nh {
                columns[kx * len + ky] = values[ky * nh + kx];
            }
        }
        SpectralKernel { columns, len }
    }

    /// Unnormalised forward transform of the real field `input` (nx·ny) into `spec` (half
    /// spectrum, row-major `spec[ky * nh + kx]`).
    pub fn forward(&mut self, input: &[f64], spec: &mut [Complex64]) {
        let (nx, ny, nh) = (self.nx, self.ny, self.nh);
        assert!(
            input.len() == nx * ny && spec.len() == nh * ny,
            "RealFft2::forward: sizes"
        );
        self.rows_forward(input, spec);
        columns(self.parallel, &*self.col_fwd, spec, nh, ny);
    }

    /// Unnormalised inverse transform of the half spectrum `spec` into the real field `out`.
    /// `spec` is used as scratch (its contents are destroyed).
    pub fn inverse(&mut self, spec: &mut [Complex64], out: &mut [f64]) {
        let (nx, ny, nh) = (self.nx, self.ny, self.nh);
        assert!(
            out.len() == nx * ny && spec.len() == nh * ny,
            "RealFft2::inverse: sizes"
        );
        columns(self.parallel, &*self.col_inv, spec, nh, ny);
        self.rows_inverse(spec, out);
    }
}

impl RealFft2 {
    /// Complex-to-real transforms of every row of `spec` into `out` (`spec` is overwritten:
    /// realfft uses its input as scratch).
    fn rows_inverse(&self, spec: &mut [Complex64], out: &mut [f64]) {
        let (nx, ny, nh) = (self.nx, self.ny, self.nh);
        let c2r = &self.c2r;
        let rows = |(rout, rin): (&mut [f64], &mut [Complex64])| {
            let mut scratch = c2r.make_scratch_vec();
            for (a, b) in rout.chunks_exact_mut(nx).zip(rin.chunks_exact_mut(nh)) {
                // the kx = 0 (and Nyquist) entries are real up to round-off; realfft zeroes
                // their imaginary parts and reports it, which is not an error here
                let _ = c2r.process_with_scratch(b, a, &mut scratch);
            }
        };
        run_chunks(self.parallel, out, nx, spec, nh, ny, rows);
    }

    /// Real-to-complex transforms of every row of `input` into `spec` (each row is copied into a
    /// small buffer first: realfft uses its input as scratch).
    fn rows_forward(&self, input: &[f64], spec: &mut [Complex64]) {
        let (nx, ny, nh) = (self.nx, self.ny, self.nh);
        let r2c = &self.r2c;
        let rows = |(rin, rout): (&[f64], &mut [Complex64])| {
            let mut scratch = r2c.make_scratch_vec();
            let mut row = vec![0.0; nx];
            for (a, b) in rin.chunks_exact(nx).zip(rout.chunks_exact_mut(nh)) {
                row.copy_from_slice(a);
                r2c.process_with_scratch(&mut row, b, &mut scratch)
                    .expect("planned sizes");
            }
        };
        if self.parallel {
            use rayon::prelude::*;
            let per = ny.div_ceil(rayon::current_num_threads().max(1) * 4).max(1);
            input
                .par_chunks(per * nx)
                .zip(spec.par_chunks_mut(per * nh))
                .for_each(rows);
        } else {
            rows((input, spec));
        }
    }

    /// Periodic convolution with a real, even-in-k kernel given in Fourier space:
    /// `out = inverse(kernel · forward(input))` (unnormalised: include 1/(nx·ny) in the
    /// kernel). `kernel` is made by [`RealFft2::kernel`], `spec` is scratch of
    /// [`RealFft2::spectrum_len`]. Same result, bit for bit, as `forward`, a multiplication and
    /// `inverse`, in fewer passes over memory.
    pub fn convolve(&mut self, input: &[f64], kernel: &SpectralKernel, spec: &mut [Complex64], out: &mut [f64]) {
        let (nx, ny, nh) = (self.nx, self.ny, self.nh);
        assert!(
            input.len() == nx * ny && out.len() == nx * ny && spec.len() == nh * ny && kernel.fits(nh, ny),
            "RealFft2::convolve: sizes"
        );
        self.rows_forward(input, spec);
        columns_with(
            self.parallel,
            &*self.col_fwd,
            Some((kernel, &*self.col_inv)),
            spec,
            nh,
            ny,
        );
        self.rows_inverse(spec, out);
    }
}

impl RealFft2 {
    /// [`RealFft2::convolve`] with work fused into its two row passes, while each row is in
    /// the cache, beside a caller's `side` field (nx·ny, split by rows as the input):
    /// `fill(y, side_row, row)` writes every value of row y of the field to convolve (it may
    /// change the side row too) and returns a partial result of row y, and `finish(y, side_row,
    /// out_row)` returns a second partial result of row y once its output is made. The partials
    /// come back one per row, in row order, so a caller that combines them in that order gets
    /// the same bits whatever the thread count. The convolution itself is the same, bit for
    /// bit, as `convolve` of the filled field.
    #[allow(clippy::too_many_arguments)]
    pub fn convolve_rows<A, B, P, F>(
        &mut self,
        side: &mut [f64],
        kernel: &SpectralKernel,
        spec: &mut [Complex64],
        out: &mut [f64],
        fill: P,
        finish: F,
    ) -> (Vec<A>, Vec<B>)
    where
        A: Copy + Default + Send,
        B: Copy + Default + Send,
        P: Fn(usize, &mut [f64], &mut [f64]) -> A + Sync,
        F: Fn(usize, &[f64], &[f64]) -> B + Sync,
    {
        let (nx, ny, nh) = (self.nx, self.ny, self.nh);
        assert!(
            side.len() == nx * ny && out.len() == nx * ny && spec.len() == nh * ny && kernel.fits(nh, ny),
            "RealFft2::convolve_rows: sizes"
        );
        let r2c = &self.r2c;
        let forward = |y0: usize, (rin, rout): (&mut [f64], &mut [Complex64]), parts: &mut [A]| {
            let mut scratch = r2c.make_scratch_vec();
            let mut row = vec![0.0; nx];
            for (k, (a, b)) in rin.chunks_exact_mut(nx).zip(rout.chunks_exact_mut(nh)).enumerate() {
                parts[k] = fill(y0 + k, a, &mut row);
                r2c.process_with_scratch(&mut row, b, &mut scratch)
                    .expect("planned sizes");
            }
        };
        let per = self.rows_per_block();
        let mut before = vec![A::default(); ny];
        if self.parallel {
            use rayon::prelude::*;
            side.par_chunks_mut(per * nx)
                .zip(spec.par_chunks_mut(per * nh))
                .zip(before.par_chunks_mut(per))
                .enumerate()
                .for_each(|(b, (blk, pt))| forward(b * per, blk, pt));
        } else {
            forward(0, (side, spec), &mut before);
        }
        columns_with(
            self.parallel,
            &*self.col_fwd,
            Some((kernel, &*self.col_inv)),
            spec,
            nh,
            ny,
        );
        let c2r = &self.c2r;
        let side = &*side;
        let inverse = |y0: usize, (rout, rin): (&mut [f64], &mut [Complex64]), parts: &mut [B]| {
            let mut scratch = c2r.make_scratch_vec();
            for (k, (a, b)) in rout.chunks_exact_mut(nx).zip(rin.chunks_exact_mut(nh)).enumerate() {
                let _ = c2r.process_with_scratch(b, a, &mut scratch);
                let y = y0 + k;
                parts[k] = finish(y, &side[y * nx..(y + 1) * nx], a);
            }
        };
        let mut after = vec![B::default(); ny];
        if self.parallel {
            use rayon::prelude::*;
            out.par_chunks_mut(per * nx)
                .zip(spec.par_chunks_mut(per * nh))
                .zip(after.par_chunks_mut(per))
                .enumerate()
                .for_each(|(b, (blk, pt))| inverse(b * per, blk, pt));
        } else {
            inverse(0, (out, spec), &mut after);
        }
        (before, after)
    }

    /// Rows per parallel block of the row passes (four blocks per thread).
    fn rows_per_block(&self) -> usize {
        self.ny.div_ceil(rayon::current_num_threads().max(1) * 4).max(1)
    }
}

/// Applies `f` to matching row blocks of a real (`rl` per row) and a complex (`cl` per row)
/// array of `rows` rows, in parallel blocks when asked.
fn run_chunks<F>(parallel: bool, real: &mut [f64], rl: usize, cplx: &mut [Complex64], cl: usize, rows: usize, f: F)
where
    F: Fn((&mut [f64], &mut [Complex64])) + Sync + Send,
{
    if parallel {
        use rayon::prelude::*;
        let per = rows.div_ceil(rayon::current_num_threads().max(1) * 4).max(1);
        real.par_chunks_mut(per * rl)
            .zip(cplx.par_chunks_mut(per * cl))
            .for_each(f);
    } else {
        f((real, cplx));
    }
}

/// A raw pointer that may cross threads; used only for disjoint column strips.
#[derive(Clone, Copy)]
struct SharedPtr(*mut Complex64);
// SAFETY: every strip touches a disjoint set of columns (see `columns`).
unsafe impl Send for SharedPtr {}
unsafe impl Sync for SharedPtr {}

/// Transforms every column (length `ny`) of the row-major `ny`×`nc` array `data` in place,
/// gathering [`STRIP`] columns at a time into a contiguous buffer.
fn columns(parallel: bool, fft: &dyn rustfft::Fft<f64>, data: &mut [Complex64], nc: usize, ny: usize) {
    columns_with(parallel, fft, None, data, nc, ny)
}

/// As [`columns`]; with `then = Some((kernel, inverse))` each strip is also multiplied by the
/// real `kernel` (column by column, as [`SpectralKernel`] stores it) and transformed back with `inverse` while it is in
/// the cache (a convolution in one pass over the spectrum).
fn columns_with(
    parallel: bool,
    fft: &dyn rustfft::Fft<f64>,
    then: Option<(&SpectralKernel, &dyn rustfft::Fft<f64>)>,
    data: &mut [Complex64],
    nc: usize,
    ny: usize,
) {
    assert_eq!(data.len(), nc * ny, "fft2 columns: sizes");
    if let Some((k, _)) = then {
        assert!(k.fits(nc, ny), "fft2 columns: kernel size");
    }
    let strips = nc.div_ceil(STRIP);
    let ptr = SharedPtr(data.as_mut_ptr());
    // a strip's columns lie `ld` apart in the buffer: a power-of-two stride (ny) would map all
    // of a row's STRIP writes to one cache set
    let ld = ny + STRIP_PAD;
    let scratch_len = fft
        .get_inplace_scratch_len()
        .max(then.map_or(0, |(_, i)| i.get_inplace_scratch_len()));
    let init = || {
        (
            vec![Complex64::new(0.0, 0.0); STRIP * ld],
            vec![Complex64::new(0.0, 0.0); scratch_len],
        )
    };
    let work = |(buf, scratch): &mut (Vec<Complex64>, Vec<Complex64>), strip: usize| {
        let p = ptr;
        let c0 = strip * STRIP;
        let w = STRIP.min(nc - c0);
        // SAFETY: columns c0..c0 + w of rows 0..ny lie inside `data` (len = ny·nc) and no other
        // strip reads or writes them; `data` outlives this call.
        unsafe {
            for r in 0..ny {
                let row = std::slice::from_raw_parts(p.0.add(r * nc + c0), w);
                for (c, &x) in row.iter().enumerate() {
                    *buf.get_unchecked_mut(c * ld + r) = x;
                }
            }
        }
        for c in 0..w {
            let col = &mut buf[c * ld..c * ld + ny];
            fft.process_with_scratch(col, scratch);
            if let Some((kernel, inverse)) = then {
                kernel.apply(c0 + c, col);
                inverse.process_with_scratch(col, scratch);
            }
        }
        // SAFETY: as above.
        unsafe {
            for r in 0..ny {
                let row = std::slice::from_raw_parts_mut(p.0.add(r * nc + c0), w);
                for (c, x) in row.iter_mut().enumerate() {
                    *x = *buf.get_unchecked(c * ld + r);
                }
            }
        }
    };
    if parallel {
        use rayon::prelude::*;
        (0..strips).into_par_iter().for_each_init(init, work);
    } else {
        let mut bufs = init();
        (0..strips).for_each(|s| work(&mut bufs, s));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_dc() {
        let n = 8;
        let h: Vec<f64> = (0..n * n).map(|k| ((k * 7919) % 13) as f64 - 6.0).collect();
        let mut f = forward_real(&h, n);
        let dc: f64 = h.iter().sum();
        assert!((f[0].re - dc).abs() < 1e-12 && f[0].im.abs() < 1e-12);
        inverse_normalised(&mut f, n);
        for (a, b) in f.iter().zip(&h) {
            assert!((a.re - b).abs() < 1e-12 && a.im.abs() < 1e-12);
        }
    }

    #[test]
    fn fused_row_passes_equal_the_plain_convolution_bit_for_bit() {
        for (nx, ny) in [(8, 8), (7, 5), (256, 256)] {
            let h: Vec<f64> = (0..nx * ny).map(|k| (((k * 7919) % 13) as f64 - 6.0) * 0.1).collect();
            let mut plan = RealFft2::new(nx, ny);
            let values: Vec<f64> = (0..plan.spectrum_len())
                .map(|k| 1.0 / (1.0 + (k % 11) as f64))
                .collect();
            let kernel = plan.kernel(&values);
            let mut spec = vec![Complex64::new(0.0, 0.0); plan.spectrum_len()];
            // plain: the input scaled beforehand, the row sums afterwards
            let scaled: Vec<f64> = h.iter().map(|x| x * 1.5).collect();
            let mut want = vec![0.0; nx * ny];
            plan.convolve(&scaled, &kernel, &mut spec, &mut want);
            let want_sums: Vec<[f64; 4]> = want
                .chunks(nx)
                .zip(scaled.chunks(nx))
                .map(|(o, i)| [o.iter().sum(), i.iter().sum(), 0.0, 0.0])
                .collect();
            // fused
            let mut input = h.clone();
            let mut got = vec![0.0; nx * ny];
            let (before, sums) = plan.convolve_rows(
                &mut input,
                &kernel,
                &mut spec,
                &mut got,
                |y, side, row| {
                    side.iter_mut().for_each(|x| *x *= 1.5);
                    row.copy_from_slice(side);
                    y
                },
                |_, i, o| [o.iter().sum(), i.iter().sum(), 0.0, 0.0],
            );
            assert_eq!(
                before,
                (0..ny).collect::<Vec<_>>(),
                "{nx}x{ny}: the prepare partials, in row order"
            );
            assert_eq!(input, scaled, "{nx}x{ny}: the prepared input stays");
            assert_eq!(got, want, "{nx}x{ny}: the convolution");
            assert_eq!(sums, want_sums, "{nx}x{ny}: the row partials, in row order");
        }
    }

    #[test]
    fn planned_real_fft_matches_full_transform_and_round_trips() {
        for (nx, ny) in [(8, 8), (12, 6), (7, 5), (256, 256)] {
            let h: Vec<f64> = (0..nx * ny).map(|k| (((k * 7919) % 13) as f64 - 6.0) * 0.1).collect();
            // reference: 1-D transforms along rows then columns of the complex field
            let mut full: Vec<Complex64> = h.iter().map(|&x| Complex64::new(x, 0.0)).collect();
            let mut p = FftPlanner::<f64>::new();
            let fx = p.plan_fft_forward(nx);
            fx.process(&mut full);
            let fy = p.plan_fft_forward(ny);
            for kx in 0..nx {
                let mut col: Vec<Complex64> = (0..ny).map(|y| full[y * nx + kx]).collect();
                fy.process(&mut col);
                for y in 0..ny {
                    full[y * nx + kx] = col[y];
                }
            }
            let mut plan = RealFft2::new(nx, ny);
            let mut spec = vec![Complex64::new(0.0, 0.0); plan.spectrum_len()];
            plan.forward(&h, &mut spec);
            for kx in 0..plan.nh() {
                for ky in 0..ny {
                    let d = spec[ky * plan.nh() + kx] - full[ky * nx + kx];
                    assert!(d.norm() < 1e-9, "{nx}x{ny} ({kx},{ky})");
                }
            }
            // convolve == forward · kernel · inverse, bit for bit, with a kernel stored whole
            // and with one even in ky (stored for ky ≤ ny/2)
            let nh = plan.nh();
            let odd: Vec<f64> = (0..plan.spectrum_len())
                .map(|k| 1.0 + (k % 7) as f64 * 0.25 + (k / nh) as f64 * 0.125)
                .collect();
            let even: Vec<f64> = (0..plan.spectrum_len())
                .map(|k| {
                    let (kx, ky) = (k % nh, k / nh);
                    1.0 / (1.0 + (kx * kx + ky.min(ny - ky).pow(2)) as f64)
                })
                .collect();
            for (values, half) in [(odd, false), (even, true)] {
                let kernel = plan.kernel(&values);
                assert_eq!(kernel.len, if half { ny / 2 + 1 } else { ny }, "{nx}x{ny}");
                let mut a = vec![0.0; nx * ny];
                let mut b = vec![0.0; nx * ny];
                let mut s2 = spec.clone();
                for (c, &k) in s2.iter_mut().zip(&values) {
                    *c *= k;
                }
                plan.inverse(&mut s2, &mut a);
                let mut scratch = vec![Complex64::new(0.0, 0.0); plan.spectrum_len()];
                plan.convolve(&h, &kernel, &mut scratch, &mut b);
                assert_eq!(a, b, "{nx}x{ny}, half stored: {half}");
            }
            let mut back = vec![0.0; nx * ny];
            plan.inverse(&mut spec, &mut back);
            let s = 1.0 / (nx * ny) as f64;
            for (a, b) in back.iter().zip(&h) {
                assert!((a * s - b).abs() < 1e-12);
            }
        }
    }
}
