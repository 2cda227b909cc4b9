//! N ranks as threads of one process, talking over channels: the distributed solver's
//! transport for tests and for machines without MPI (same messages, same order, same results
//! as MPI ranks).

use super::comm::Comm;
use std::sync::mpsc::{channel, Receiver, Sender};

/// One rank's end of an in-process "world" of [`ThreadComm::world`] ranks.
#[derive(Debug)]
pub struct ThreadComm {
    rank: usize,
    /// `to[s]` sends to rank s.
    to: Vec<Sender<Vec<f64>>>,
    /// `from[s]` receives from rank s.
    from: Vec<Receiver<Vec<f64>>>,
}

impl ThreadComm {
    /// The `size` ends of a new world (give each to its own thread).
    pub fn world(size: usize) -> Vec<ThreadComm> {
        assert!(size >= 1, "ThreadComm: at least one rank");
        // one channel per ordered pair (a → b)
        let mut to: Vec<Vec<Sender<Vec<f64>>>> = (0..size).map(|_| Vec::with_capacity(size)).collect();
        let mut from: Vec<Vec<Receiver<Vec<f64>>>> = (0..size).map(|_| Vec::with_capacity(size)).collect();
        for row in to.iter_mut() {
            for inbox in from.iter_mut() {
                let (tx, rx) = channel();
                row.push(tx);
                inbox.push(rx);
            }
        }
        to.into_iter()
            .zip(from)
            .enumerate()
            .map(|(rank, (to, from))| ThreadComm { rank, to, from })
            .collect()
    }

    /// Runs `f` on `size` ranks (one thread each) and returns their results in rank order.
    pub fn run<T: Send>(size: usize, f: impl Fn(&ThreadComm) -> T + Sync) -> Vec<T> {
        let world = ThreadComm::world(size);
        let f = &f;
        std::thread::scope(|s| {
            let handles: Vec<_> = world.into_iter().map(|c| s.spawn(move || f(&c))).collect();
            handles.into_iter().map(|h| h.join().expect("rank thread")).collect()
        })
    }
}

impl Comm for ThreadComm {
    fn rank(&self) -> usize {
        self.rank
    }
    fn size(&self) -> usize {
        self.to.len()
    }
    fn send(&self, to: usize, data: &[f64]) {
        self.to[to].send(data.to_vec()).expect("rank alive");
    }
    fn recv(&self, from: usize) -> Vec<f64> {
        self.from[from].recv().expect("rank alive")
    }
    fn all_to_all_v(&self, send: &[f64], send_counts: &[usize], recv: &mut [f64], recv_counts: &[usize]) {
        let mut off = 0;
        for (s, &c) in send_counts.iter().enumerate() {
            self.send(s, &send[off..off + c]);
            off += c;
        }
        let mut off = 0;
        for (s, &c) in recv_counts.iter().enumerate() {
            let m = self.recv(s);
            assert_eq!(m.len(), c, "all_to_all_v: block size");
            recv[off..off + c].copy_from_slice(&m);
            off += c;
        }
    }
    fn broadcast(&self, root: usize, data: &mut [f64]) {
        if self.rank == root {
            for s in (0..self.size()).filter(|&s| s != root) {
                self.send(s, data);
            }
        } else {
            let m = self.recv(root);
            data.copy_from_slice(&m);
        }
    }
}
