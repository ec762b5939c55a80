//! The smallest-last (degeneracy) vertex order for the greedy colouring.

use super::vertices_by_key;
use crate::complexity::{on, Bound, Declaration};
use crate::count::Operation;
use crate::graph::Graph;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "colour",
    name: "smallest-last",
    function: "graph::smallest_last_order",
    file: "src/graph/colouring/smallest_last.rs",
    summary: "greedy in smallest-last (degeneracy) order",
    time: "O(n + m)",
    space: "O(n)",
    operation: Some(Operation::EdgeVisits),
    counts: "the greedy colouring's 2m edge visits",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::NPlusM, Operation::EdgeVisits)],
};

/// The smallest-last (degeneracy) order: repeatedly remove a vertex of least remaining
/// degree; colour in the reverse order of removal.
///
/// Not in the course; like [`largest_first_order`](super::largest_first_order) it feeds the course's greedy scheme (§2.1
/// "Coloración de vértices") a better order.
///
/// Each vertex then has at most d earlier neighbours, d the graph's degeneracy (the
/// largest "least remaining degree" met), so greedy in this order uses at most d + 1
/// colours: 2 on forests with an edge, at most 3 on cycles, at most 6 on planar graphs.
/// Ties go to the vertex that reached the least degree first (a bucket queue).
///
/// # Complexity
/// O(n + m) time and O(n) auxiliary space (Matula–Beck bucket queue).
///
/// ```
/// use compgeo::graph::{smallest_last_order, Graph};
///
/// // A star with centre 0: the leaves go first, so the centre comes first in the order.
/// let g = Graph::from_edges(4, &[[0, 1], [0, 2], [0, 3]])?;
/// assert_eq!(smallest_last_order(&g)[0], 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn smallest_last_order(g: &Graph) -> Vec<usize> {
    let n = g.vertex_count();
    let mut degree: Vec<usize> = (0..n).map(|v| g.degree(v)).collect();
    let max_degree = degree.iter().copied().max().unwrap_or(0);
    // Vertices sorted by degree in `sorted`, `bin[d]` the first position of degree d,
    // `pos[v]` where v sits; removing the vertex at the front of the unprocessed part keeps
    // the array sorted when a neighbour's degree drops by swapping it to its bin's front.
    let (mut sorted, mut bin) = vertices_by_key(n, max_degree + 1, |v| degree[v]);
    bin.pop();
    let mut pos = vec![0usize; n];
    for (i, &v) in sorted.iter().enumerate() {
        pos[v] = i;
    }
    for i in 0..n {
        let v = sorted[i];
        for u in g.neighbours(v) {
            if degree[u] > degree[v] {
                let du = degree[u];
                let first = bin[du];
                let w = sorted[first];
                if u != w {
                    sorted.swap(pos[u], first);
                    pos[w] = pos[u];
                    pos[u] = first;
                }
                bin[du] += 1;
                degree[u] -= 1;
            }
        }
    }
    sorted.reverse();
    sorted
}
