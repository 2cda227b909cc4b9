//! The contact set of [`super::pk::relax`] as a list of its nodes, and the sums over it.
//!
//! S = {p > 0} holds a few per cent of the nodes at the loads of interest: the fields to
//! convolve are written from the list, and the sums over S visit its nodes only. Off S the one
//! quantity needed is the least x = u − h (the overlap test), taken in lanes. The sums are
//! those a loop over every node takes, in the same order (Σ_S g² excepted, see [`Contact::gap`]).

/// Node-loop chunk: partial results are combined in chunk order, so a run is bit-for-bit the
/// same whatever the thread count.
pub(super) const CHUNK: usize = 4096;

/// The contact set S = {p > 0}: its nodes in order, and where each row and each chunk of
/// [`CHUNK`] nodes starts among them.
pub(super) struct Support {
    pub(super) nodes: Vec<usize>,
    rows: Vec<usize>,
    chunks: Vec<usize>,
}

impl Support {
    /// S of `p` on rows of `nx` nodes.
    pub(super) fn of(p: &[f64], nx: usize) -> Support {
        let nodes = (0..p.len()).filter(|&i| p[i] > 0.0).collect();
        Support::indexed(nodes, p.len(), nx)
    }

    /// S less the nodes where p has dropped to 0.
    pub(super) fn retain(&mut self, p: &[f64], nx: usize) {
        let mut nodes = std::mem::take(&mut self.nodes);
        nodes.retain(|&i| p[i] > 0.0);
        *self = Support::indexed(nodes, p.len(), nx);
    }

    /// S of the nodes `nodes` (in increasing order) of a field of `n` values on rows of `nx`.
    pub(super) fn from_sorted(nodes: Vec<usize>, n: usize, nx: usize) -> Support {
        debug_assert!(nodes.windows(2).all(|w| w[0] < w[1]));
        Support::indexed(nodes, n, nx)
    }

    fn indexed(nodes: Vec<usize>, n: usize, nx: usize) -> Support {
        let starts = |step: usize| -> Vec<usize> {
            let mut k = 0;
            (0..=n.div_ceil(step))
                .map(|b| {
                    while k < nodes.len() && nodes[k] < b * step {
                        k += 1;
                    }
                    k
                })
                .collect()
        };
        let (rows, chunks) = (starts(nx), starts(CHUNK));
        Support { nodes, rows, chunks }
    }

    /// The nodes of S in row y.
    pub(super) fn row(&self, y: usize) -> &[usize] {
        &self.nodes[self.rows[y]..self.rows[y + 1]]
    }

    /// The nodes of S in chunk c.
    pub(super) fn chunk(&self, c: usize) -> &[usize] {
        &self.nodes[self.chunks[c]..self.chunks[c + 1]]
    }
}

/// Sums over a stretch of nodes of x = u − h: over the contact S (p > 0) its sum, count,
/// extremes and the sums of x − c and (x − c)² about a reference c; off S its minimum.
#[derive(Debug, Clone, Copy)]
pub(super) struct Contact {
    pub(super) sum: f64,
    pub(super) count: f64,
    max_on: f64,
    min_on: f64,
    pub(super) min_off: f64,
    dev: f64,
    dev_sq: f64,
}

impl Default for Contact {
    fn default() -> Self {
        Contact::EMPTY
    }
}

/// The gap g = x − ḡ measured from [`Contact`]: Σ_S g², max_S |g| and the largest overlap
/// off S (max −g, 0 when there is none).
pub(super) struct Gap {
    pub(super) squares: f64,
    pub(super) on: f64,
    pub(super) overlap: f64,
}

impl Contact {
    pub(super) const EMPTY: Contact = Contact {
        sum: 0.0,
        count: 0.0,
        max_on: f64::NEG_INFINITY,
        min_on: f64::INFINITY,
        min_off: f64::INFINITY,
        dev: 0.0,
        dev_sq: 0.0,
    };

    /// The sums over the stretch of nodes `o..o + u.len()` (`u`, `h` its values), `nodes`
    /// the nodes of S in it, `c` the reference of the squares.
    pub(super) fn of(nodes: &[usize], o: usize, u: &[f64], h: &[f64], c: f64) -> Contact {
        let mut s = Contact::EMPTY;
        let mut from = 0;
        for &i in nodes {
            let k = i - o;
            s.min_off = s.min_off.min(min_difference(&u[from..k], &h[from..k]));
            from = k + 1;
            let x = u[k] - h[k];
            s.sum += x;
            s.count += 1.0;
            s.max_on = s.max_on.max(x);
            s.min_on = s.min_on.min(x);
            s.dev += x - c;
            s.dev_sq += (x - c) * (x - c);
        }
        s.min_off = s.min_off.min(min_difference(&u[from..], &h[from..]));
        s
    }

    /// The sums over this stretch and the next one.
    pub(super) fn then(self, b: Contact) -> Contact {
        Contact {
            sum: self.sum + b.sum,
            count: self.count + b.count,
            max_on: self.max_on.max(b.max_on),
            min_on: self.min_on.min(b.min_on),
            min_off: self.min_off.min(b.min_off),
            dev: self.dev + b.dev,
            dev_sq: self.dev_sq + b.dev_sq,
        }
    }

    /// The gap about ḡ = `gbar`: the extremes of g are those of x less ḡ, the same as taken
    /// node by node (rounding keeps the order); with the sums taken about c, Σ_S g² =
    /// Σ (x − c)² − |S| d², d = Σ (x − c)/|S| = ḡ − c, accurate while d is not much larger than
    /// the gap (c is the last iteration's ḡ).
    pub(super) fn gap(&self, gbar: f64) -> Gap {
        let (on, squares) = if self.count > 0.0 {
            let d = self.dev / self.count;
            let on = (self.max_on - gbar).max(-(self.min_on - gbar)).max(0.0);
            (on, (self.dev_sq - self.count * d * d).max(0.0))
        } else {
            (0.0, 0.0)
        };
        let overlap = if self.min_off < f64::INFINITY {
            (-(self.min_off - gbar)).max(0.0)
        } else {
            0.0
        };
        Gap { squares, on, overlap }
    }
}

/// min (u − h) over a stretch (+∞ when empty), in lanes: a minimum does not depend on the
/// order.
fn min_difference(u: &[f64], h: &[f64]) -> f64 {
    let mut lanes = [f64::INFINITY; LANES];
    let (uc, hc) = (u.chunks_exact(LANES), h.chunks_exact(LANES));
    let tail = uc
        .remainder()
        .iter()
        .zip(hc.remainder())
        .fold(f64::INFINITY, |m, (&ui, &hi)| m.min(ui - hi));
    for (u, h) in uc.zip(hc) {
        for k in 0..LANES {
            let x = u[k] - h[k];
            lanes[k] = if x < lanes[k] { x } else { lanes[k] };
        }
    }
    lanes.iter().fold(tail, |m, &x| m.min(x))
}

/// Nodes per lane group of [`min_difference`].
const LANES: usize = 8;
#[cfg(test)]
mod tests {
    use super::*;

    /// The contact list's sums by rows and by chunks against one loop over every node: the
    /// same count and extremes of g (bit for bit), Σ_S x and Σ_S g² to rounding, on stretches
    /// that S starts, ends and breaks.
    #[test]
    fn contact_list_sums_equal_a_loop_over_every_node() {
        let (n, nx) = (2 * CHUNK + 37, 61);
        let p: Vec<f64> = (0..n)
            .map(|i| match (i * 7919) % 11 < 3 || i == 0 || i == n - 1 {
                true => 1.0 + (i % 5) as f64,
                false => 0.0,
            })
            .collect();
        let u: Vec<f64> = (0..n).map(|i| ((i * 104_729) % 1009) as f64 * 1e-3).collect();
        let h: Vec<f64> = (0..n).map(|i| ((i * 7) % 13) as f64 * 0.07).collect();
        let set = Support::of(&p, nx);
        assert_eq!(set.nodes.len(), p.iter().filter(|&&x| x > 0.0).count());
        let by = |len: usize| {
            (0..n.div_ceil(len))
                .map(|b| {
                    let (o, e) = (b * len, ((b + 1) * len).min(n));
                    let nodes = if len == nx { set.row(b) } else { set.chunk(b) };
                    assert!(nodes.iter().all(|&i| (o..e).contains(&i)));
                    Contact::of(nodes, o, &u[o..e], &h[o..e], 0.3)
                })
                .fold(Contact::EMPTY, Contact::then)
        };
        for a in [by(nx), by(CHUNK)] {
            let gbar = a.sum / a.count;
            let (mut sum, mut squares, mut on, mut overlap) = (0.0, 0.0, 0.0f64, 0.0f64);
            for i in 0..n {
                let g = u[i] - h[i] - gbar;
                if p[i] > 0.0 {
                    (sum, squares, on) = (sum + (u[i] - h[i]), squares + g * g, on.max(g.abs()));
                } else {
                    overlap = overlap.max(-g);
                }
            }
            let gap = a.gap(gbar);
            assert_eq!(a.count, set.nodes.len() as f64);
            assert_eq!((gap.on, gap.overlap), (on, overlap));
            assert!(overlap > 0.0 && on > 0.0);
            assert!((a.sum / sum - 1.0).abs() < 1e-12, "{} against {sum}", a.sum);
            assert!(
                (gap.squares / squares - 1.0).abs() < 1e-12,
                "{} against {squares}",
                gap.squares
            );
        }
    }
}
