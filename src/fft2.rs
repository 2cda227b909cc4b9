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
}
