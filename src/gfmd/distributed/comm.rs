//! The message passing a distributed run needs, behind one small trait.
//!
//! [`Comm`] is what the slab solver asks of its transport: point-to-point messages of f64
//! words (the ordered sums of [`chain_sum`] and [`chain_fold`]), a variable all-to-all (the
//! transposes of the slab FFT) and a broadcast. [`Solo`] is one rank (no messages);
//! [`super::threads::ThreadComm`] runs N ranks as threads of one process (the tests);
//! `super::mpi_comm::MpiComm` (feature `mpi`) is MPI through rsmpi.
//!
//! ## Reductions that do not depend on the rank count
//!
//! A floating-point sum depends on its order. The serial solver adds node values in index
//! order (partial sums per fixed chunk of nodes, then the chunks in order); a distributed run
//! reproduces that order exactly by passing the running value from rank r to rank r + 1
//! ([`chain_fold`]: rank r folds its own part in order onto what it received, then sends it
//! on; the last rank broadcasts the total). Each rank's local work runs in parallel; only the
//! fold of a few numbers per rank is sequential (N − 1 message latencies per reduction). Maxima
//! and integer counts are exact in any order ([`all_max`], [`all_sum_counts`]).

use rustfft::num_complex::Complex64;

/// The transport of a distributed run: ranks 0..size, each holding one slab.
pub trait Comm {
    /// This rank.
    fn rank(&self) -> usize;
    /// Number of ranks.
    fn size(&self) -> usize;
    /// Sends `data` to rank `to`.
    fn send(&self, to: usize, data: &[f64]);
    /// Receives the next message from rank `from`.
    fn recv(&self, from: usize) -> Vec<f64>;
    /// All-to-all: `send` holds one block per destination rank in rank order
    /// (`send_counts[r]` words for rank r); `recv` gets one block per source rank in rank
    /// order (`recv_counts[r]` words from rank r).
    fn all_to_all_v(&self, send: &[f64], send_counts: &[usize], recv: &mut [f64], recv_counts: &[usize]);
    /// Copies `data` of rank `root` into `data` of every rank.
    fn broadcast(&self, root: usize, data: &mut [f64]);
}

/// One rank: a serial run through the distributed code path.
#[derive(Debug, Clone, Copy, Default)]
pub struct Solo;

impl Comm for Solo {
    fn rank(&self) -> usize {
        0
    }
    fn size(&self) -> usize {
        1
    }
    fn send(&self, _to: usize, _data: &[f64]) {
        unreachable!("Solo: a single rank sends no messages")
    }
    fn recv(&self, _from: usize) -> Vec<f64> {
        unreachable!("Solo: a single rank receives no messages")
    }
    fn all_to_all_v(&self, send: &[f64], _sc: &[usize], recv: &mut [f64], _rc: &[usize]) {
        recv.copy_from_slice(send);
    }
    fn broadcast(&self, _root: usize, _data: &mut [f64]) {}
}

/// Folds a state of `width` f64 words over the ranks in order: rank 0 starts from `init`,
/// every rank applies `step` to the state it received, and every rank returns the final
/// state (the last rank's, broadcast).
pub fn chain_fold(comm: &dyn Comm, init: Vec<f64>, step: &mut dyn FnMut(&mut Vec<f64>)) -> Vec<f64> {
    let (r, size) = (comm.rank(), comm.size());
    let mut state = if r == 0 { init } else { comm.recv(r - 1) };
    let width = state.len();
    step(&mut state);
    assert_eq!(state.len(), width, "chain_fold: the state keeps its width");
    if r + 1 < size {
        comm.send(r + 1, &state);
    }
    comm.broadcast(size - 1, &mut state);
    state
}

/// [`chain_fold`] with a state whose length may change from rank to rank (the final length
/// is broadcast first).
pub fn chain_fold_var(comm: &dyn Comm, init: Vec<f64>, step: &mut dyn FnMut(&mut Vec<f64>)) -> Vec<f64> {
    let (r, size) = (comm.rank(), comm.size());
    let mut state = if r == 0 { init } else { comm.recv(r - 1) };
    step(&mut state);
    if r + 1 < size {
        comm.send(r + 1, &state);
    }
    let mut len = [state.len() as f64];
    comm.broadcast(size - 1, &mut len);
    state.resize(len[0] as usize, 0.0);
    comm.broadcast(size - 1, &mut state);
    state
}

/// Σ of the values of every rank in rank order, added one by one as `Iterator::sum` adds
/// them on one machine (bit for bit the serial sum of the concatenated values).
pub fn chain_sum(comm: &dyn Comm, local: impl Iterator<Item = f64>) -> f64 {
    let mut local = Some(local);
    let empty: f64 = std::iter::empty::<f64>().sum();
    chain_fold(comm, vec![empty], &mut |s| {
        s[0] = local.take().expect("one step per rank").fold(s[0], |a, b| a + b);
    })[0]
}

/// Largest value over the ranks (exact in any order).
pub fn all_max(comm: &dyn Comm, x: f64) -> f64 {
    chain_fold(comm, vec![f64::NEG_INFINITY], &mut |s| s[0] = s[0].max(x))[0]
}

/// Smallest value over the ranks (exact in any order).
pub fn all_min(comm: &dyn Comm, x: f64) -> f64 {
    chain_fold(comm, vec![f64::INFINITY], &mut |s| s[0] = s[0].min(x))[0]
}

/// Element-wise sums of integer counts over the ranks (exact below 2⁵³).
pub fn all_sum_counts(comm: &dyn Comm, counts: &[usize]) -> Vec<usize> {
    let out = chain_fold(comm, vec![0.0; counts.len()], &mut |s| {
        for (a, &c) in s.iter_mut().zip(counts) {
            *a += c as f64;
        }
    });
    out.into_iter().map(|x| x as usize).collect()
}

/// Views complex values as pairs of f64 words (re, im).
pub fn as_words(c: &[Complex64]) -> &[f64] {
    // SAFETY: Complex64 is #[repr(C)] { re: f64, im: f64 }: 2·len f64 with the same alignment.
    unsafe { std::slice::from_raw_parts(c.as_ptr().cast::<f64>(), 2 * c.len()) }
}

/// Mutable view of complex values as pairs of f64 words (re, im).
pub fn as_words_mut(c: &mut [Complex64]) -> &mut [f64] {
    // SAFETY: as in `as_words`; the borrow is exclusive.
    unsafe { std::slice::from_raw_parts_mut(c.as_mut_ptr().cast::<f64>(), 2 * c.len()) }
}

/// The share `[lo, hi)` of `n` items of rank `r` of `size` (as even as possible, in order).
pub fn share(n: usize, size: usize, r: usize) -> (usize, usize) {
    (n * r / size, n * (r + 1) / size)
}

/// A raw pointer that may cross threads; used only for disjoint ranges of one slice.
#[derive(Clone, Copy)]
pub(crate) struct SendPtr(pub(crate) *mut f64);
// SAFETY: users touch disjoint ranges only (see the call sites).
unsafe impl Send for SendPtr {}
unsafe impl Sync for SendPtr {}
