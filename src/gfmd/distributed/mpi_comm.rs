//! [`Comm`] over MPI (rsmpi on the system's MPICH or OpenMPI): one rank per process of
//! `mpirun -np N`.

use super::comm::Comm;
use mpi::datatype::{Partition, PartitionMut};
use mpi::traits::*;

/// The MPI world of this process. Made once per process ([`MpiComm::init`]); MPI is finalised
/// when it is dropped.
pub struct MpiComm {
    world: mpi::topology::SimpleCommunicator,
    _universe: mpi::environment::Universe,
}

impl std::fmt::Debug for MpiComm {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "MpiComm(rank {} of {})", self.rank(), self.size())
    }
}

impl MpiComm {
    /// Initialises MPI (None if it was initialised before in this process).
    pub fn init() -> Option<MpiComm> {
        let universe = mpi::initialize()?;
        Some(MpiComm {
            world: universe.world(),
            _universe: universe,
        })
    }
}

fn counts(c: &[usize]) -> (Vec<i32>, Vec<i32>) {
    let n: Vec<i32> = c
        .iter()
        .map(|&x| i32::try_from(x).expect("MPI count below 2^31"))
        .collect();
    let mut d = Vec::with_capacity(c.len());
    let mut acc = 0i32;
    for &x in &n {
        d.push(acc);
        acc = acc.checked_add(x).expect("MPI displacement below 2^31");
    }
    (n, d)
}

impl Comm for MpiComm {
    fn rank(&self) -> usize {
        self.world.rank() as usize
    }
    fn size(&self) -> usize {
        self.world.size() as usize
    }
    fn send(&self, to: usize, data: &[f64]) {
        self.world.process_at_rank(to as i32).send(data);
    }
    fn recv(&self, from: usize) -> Vec<f64> {
        self.world.process_at_rank(from as i32).receive_vec::<f64>().0
    }
    fn all_to_all_v(&self, send: &[f64], send_counts: &[usize], recv: &mut [f64], recv_counts: &[usize]) {
        let (sc, sd) = counts(send_counts);
        let (rc, rd) = counts(recv_counts);
        let sp = Partition::new(send, sc, sd);
        let mut rp = PartitionMut::new(recv, rc, rd);
        self.world.all_to_all_varcount_into(&sp, &mut rp);
    }
    fn broadcast(&self, root: usize, data: &mut [f64]) {
        self.world.process_at_rank(root as i32).broadcast_into(data);
    }
}
