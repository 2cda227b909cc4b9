//! FIRE on slabs: the relaxation of [`crate::gfmd::fire::relax_from`] (the same code as the
//! serial run's) on this rank's rows, with the elastic force through the slab FFT
//! ([`super::slab_fft`]) and the force sums folded in the serial order
//! ([`super::comm::chain_fold`]), so that the sums, every position and the step count equal
//! the serial run's bit for bit for any number of ranks. What is the slabs' own here is the
//! kernel on the rank's columns.
//!
//! Polonsky–Keer ([`crate::gfmd::pk`]) is not distributed: a hard-wall run relaxes with FIRE
//! alone (the serial `Method::Fire`).

use super::comm::{all_max, Comm};
use super::map::Slab;
use super::slab_fft::SlabFft;
use crate::gfmd::relax::{stiffness_at, Convolver};
use crate::gfmd::Problem;

/// One contact problem on this rank's rows of the map (physical units, as
/// [`crate::gfmd::Problem`]).
pub type SlabProblem<'a> = Problem<'a, Slab>;

/// The convolution of the elastic force on this rank's columns of the half spectrum of an
/// nx × ny map of spacing Δa on a body of thickness `thickness` (m), and the map's largest
/// stiffness (every rank gets it).
pub(crate) fn slab_kernel(comm: &dyn Comm, (nx, ny, da): (usize, usize, f64), thickness: f64) -> (Convolver, f64) {
    let n = nx * ny;
    let fft = SlabFft::new(nx, ny, comm.rank(), comm.size());
    let (c0, c1) = fft.my_cols();
    let mut kernel = vec![0.0; (c1 - c0) * ny];
    let mut phi_max: f64 = 0.0;
    for kx in c0..c1 {
        for ky in 0..ny {
            let p = stiffness_at(kx, ky, (nx, ny, da), thickness);
            kernel[(kx - c0) * ny + ky] = p * (1.0 / n as f64);
            phi_max = phi_max.max(p);
        }
    }
    (Convolver::Slab(fft, kernel), all_max(comm, phi_max))
}
