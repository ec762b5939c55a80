//! Compressed sparse rows of an undirected edge list, built by a two-pass counting sort: the
//! one adjacency builder behind [`Graph`](crate::graph::Graph),
//! [`WeightedGraph`](crate::graph::WeightedGraph) and the Delaunay graph of the proximity
//! problems.

/// The adjacency of `0..n` from an undirected edge list: row `v` is
/// `entries[offsets[v]..offsets[v + 1]]`, each entry the other end of an edge at `v` and the
/// edge's data, sorted by the other end, then by edge order. Self-loops are left out and
/// counted in `loops`.
#[derive(Debug, Clone)]
pub(crate) struct Csr<D> {
    pub(crate) offsets: Vec<usize>,
    pub(crate) entries: Vec<(u32, D)>,
    pub(crate) loops: usize,
}

impl<D: Copy + Default> Csr<D> {
    /// The rows of the `edges` (pairs of vertices below `n`, which the caller has checked,
    /// with their data); the iterator is walked twice.
    ///
    /// Pass 1 buckets every arc (source, data) by its target in edge order; pass 2 walks the
    /// targets in ascending order and appends each to its source's row, so every row comes
    /// out sorted without a comparison sort. O(n + m) time and space.
    pub(crate) fn undirected<I>(n: usize, edges: I) -> Csr<D>
    where
        I: Iterator<Item = ([usize; 2], D)> + Clone,
    {
        let mut offsets = vec![0usize; n + 1];
        let mut loops = 0;
        for ([u, v], _) in edges.clone() {
            if u == v {
                loops += 1;
            } else {
                offsets[u + 1] += 1;
                offsets[v + 1] += 1;
            }
        }
        for v in 1..offsets.len() {
            offsets[v] += offsets[v - 1];
        }
        let arcs = offsets[n];
        let mut by_target = vec![(0u32, D::default()); arcs];
        let mut next = offsets.clone();
        for ([u, v], data) in edges {
            if u != v {
                by_target[next[v]] = (u as u32, data);
                next[v] += 1;
                by_target[next[u]] = (v as u32, data);
                next[u] += 1;
            }
        }
        // Row sizes equal the bucket sizes (every arc has its reverse), so the same offsets
        // serve both passes.
        next.copy_from_slice(&offsets);
        let mut entries = vec![(0u32, D::default()); arcs];
        for t in 0..n {
            for &(s, data) in &by_target[offsets[t]..offsets[t + 1]] {
                let s = s as usize;
                entries[next[s]] = (t as u32, data);
                next[s] += 1;
            }
        }
        Csr {
            offsets,
            entries,
            loops,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_sorted_by_neighbour_then_edge_and_skip_loops() {
        let edges = [[2, 0], [0, 1], [0, 0], [0, 2], [1, 2]];
        let csr = Csr::undirected(3, edges.iter().enumerate().map(|(e, &p)| (p, e as u32)));
        let row = |v: usize| csr.entries[csr.offsets[v]..csr.offsets[v + 1]].to_vec();
        assert_eq!(row(0), [(1, 1), (2, 0), (2, 3)]);
        assert_eq!(row(1), [(0, 1), (2, 4)]);
        assert_eq!(row(2), [(0, 0), (0, 3), (1, 4)]);
        assert_eq!(csr.loops, 1);
    }
}
