//! The largest-first (Welsh–Powell) vertex order for the greedy colouring, with a tie rule
//! that keeps the order connected inside each class of equal degree.

use super::vertices_by_key;
use crate::complexity::{on, Bound, Declaration};
use crate::count::Operation;
use crate::graph::Graph;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "colour",
    name: "largest-first",
    function: "graph::largest_first_order",
    file: "src/graph/colouring/largest_first.rs",
    summary: "greedy in decreasing degree order (Welsh–Powell), connected within each degree",
    time: "O(n + m)",
    space: "O(n)",
    operation: Some(Operation::EdgeVisits),
    counts: "the greedy colouring's 2m edge visits",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::NPlusM, Operation::EdgeVisits)],
};

/// The largest-first (Welsh–Powell) order: vertices by decreasing degree; among vertices of
/// equal degree, the one with the most neighbours already in the order comes first.
///
/// Not in the course, which colours in a given order and shows (§2.1 "Coloración de vértices",
/// the congress example) that a better order can save colours; this is the classic heuristic
/// order for [`greedy_colouring`](super::greedy_colouring).
///
/// Welsh and Powell fix only the decreasing degrees. The tie rule here makes the order
/// *connected* inside a class of equal degree: a vertex with an already ordered neighbour is
/// preferred to one without (ties among those go to the vertex that reached its count first,
/// starting from ascending ids). On a regular graph (cycles, complete graphs, crown graphs)
/// the whole order is then connected in each component, and greedy in a connected order
/// colours a bipartite graph with 2 colours: each vertex after the first of its component
/// has an already coloured neighbour, all of them on the other side. So largest-first is no
/// longer fooled by crown graphs, which need n/2 colours in the natural order.
///
/// Greedy in this order uses at most max_i min(d_i + 1, i) colours, d_i the i-th largest
/// degree.
///
/// # Complexity
/// O(n + m) time and O(n) auxiliary space: a counting sort on the degrees, then in each
/// class of equal degree d a bucket queue on the count of ordered neighbours (0..=d), whose
/// entries move up one bucket per edge.
///
/// ```
/// use compgeo::graph::{largest_first_order, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [1, 3], [2, 3]])?;
/// assert_eq!(largest_first_order(&g), [1, 2, 3, 0]);
///
/// // The 6-cycle 0-1-2-3-4-5 numbered 0, 3, 1, 4, 2, 5 around the cycle: every degree is 2,
/// // and the order follows the cycle instead of the ids.
/// let g = Graph::from_edges(6, &[[0, 3], [3, 1], [1, 4], [4, 2], [2, 5], [5, 0]])?;
/// assert_eq!(largest_first_order(&g), [0, 3, 5, 1, 2, 4]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn largest_first_order(g: &Graph) -> Vec<usize> {
    let n = g.vertex_count();
    let max_degree = (0..n).map(|v| g.degree(v)).max().unwrap_or(0);
    // The degree classes laid out from the largest degree down.
    let (by_degree, start) = vertices_by_key(n, max_degree + 1, |v| max_degree - g.degree(v));
    let mut ordered_neighbours = vec![0usize; n];
    let mut ordered = vec![false; n];
    let mut order = Vec::with_capacity(n);
    let mut queue = BucketQueue::new(n, max_degree + 1);
    for class in start.windows(2).filter(|w| w[0] < w[1]) {
        let vertices = &by_degree[class[0]..class[1]];
        let degree = g.degree(vertices[0]);
        queue.clear(degree + 1);
        for &v in vertices {
            queue.push_back(v, ordered_neighbours[v]);
        }
        while let Some(v) = queue.pop_max() {
            ordered[v] = true;
            order.push(v);
            for u in g.neighbours(v) {
                if !ordered[u] {
                    ordered_neighbours[u] += 1;
                    if g.degree(u) == degree {
                        queue.remove(u, ordered_neighbours[u] - 1);
                        queue.push_back(u, ordered_neighbours[u]);
                    }
                }
            }
        }
    }
    order
}

/// Vertices in buckets by a small key, each bucket a doubly linked FIFO list, with the
/// largest non-empty key found by scanning down (keys only grow by one at a time, so the
/// scans cost O(number of pushes) overall).
struct BucketQueue {
    head: Vec<usize>,
    tail: Vec<usize>,
    next: Vec<usize>,
    prev: Vec<usize>,
    top: usize,
}

/// The end of a bucket list.
const NIL: usize = usize::MAX;

impl BucketQueue {
    fn new(vertices: usize, keys: usize) -> Self {
        BucketQueue {
            head: vec![NIL; keys],
            tail: vec![NIL; keys],
            next: vec![NIL; vertices],
            prev: vec![NIL; vertices],
            top: 0,
        }
    }

    /// Empties buckets `0..keys` (the only ones the next round uses).
    fn clear(&mut self, keys: usize) {
        self.head[..keys].fill(NIL);
        self.tail[..keys].fill(NIL);
        self.top = 0;
    }

    fn push_back(&mut self, v: usize, key: usize) {
        self.prev[v] = self.tail[key];
        self.next[v] = NIL;
        match self.tail[key] {
            NIL => self.head[key] = v,
            t => self.next[t] = v,
        }
        self.tail[key] = v;
        self.top = self.top.max(key);
    }

    fn remove(&mut self, v: usize, key: usize) {
        let (p, q) = (self.prev[v], self.next[v]);
        match p {
            NIL => self.head[key] = q,
            p => self.next[p] = q,
        }
        match q {
            NIL => self.tail[key] = p,
            q => self.prev[q] = p,
        }
    }

    /// The first vertex of the largest non-empty bucket, removed.
    fn pop_max(&mut self) -> Option<usize> {
        loop {
            let v = self.head[self.top];
            if v != NIL {
                self.remove(v, self.top);
                return Some(v);
            }
            if self.top == 0 {
                return None;
            }
            self.top -= 1;
        }
    }
}
