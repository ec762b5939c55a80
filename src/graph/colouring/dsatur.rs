//! DSatur (Brélaz): colour next the vertex whose neighbours already show the most colours.

use super::{check_colouring, Colouring, UNCOLOURED};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::graph::Graph;
use crate::util::Heap;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "colour",
    name: "dsatur",
    function: "graph::dsatur",
    file: "src/graph/colouring/dsatur.rs",
    summary: "the vertex with the most distinct neighbour colours next (Brélaz)",
    time: "O((n + m) log n)",
    space: "O(n + m)",
    operation: Some(Operation::Comparisons),
    counts: "heap comparisons; exactly 2m edge visits",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::MLogN, Operation::Comparisons)],
};

/// DSatur colouring; see [`dsatur_with`].
///
/// # Complexity
/// O((n + m) log n) time, O(n + n·k/64) auxiliary space for k colours.
///
/// ```
/// use compgeo::graph::{dsatur, Graph};
///
/// // The crown graph on 6 vertices: bipartite, and DSatur finds 2 colours.
/// let g = Graph::from_edges(6, &[[0, 3], [0, 5], [2, 1], [2, 5], [4, 1], [4, 3]])?;
/// assert_eq!(dsatur(&g).count, 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dsatur(g: &Graph) -> Colouring {
    dsatur_with(g, &mut NoCount)
}

/// DSatur (Brélaz): colour next the vertex with the most distinct colours among its
/// neighbours, counting its work.
///
/// The idea: the greedy scheme of the course (§2.1 "Algoritmo voraz", "Coloración de
/// vértices") with the candidate chosen as it goes: the uncoloured vertex of largest
/// saturation (distinct neighbour colours), ties to the larger degree, then the smaller id,
/// gets the first colour its neighbours lack. A binary heap holds (saturation, degree, id)
/// entries; an entry is pushed whenever a saturation grows and stale ones are skipped when
/// popped. Each vertex keeps a bit set of its neighbours' colours. DSatur colours every
/// bipartite graph with at most 2 colours.
///
/// # Complexity
/// O((n + m) log n) time for n vertices and m edges: at most n + 2m heap entries. Auxiliary
/// space O(n + m) for the heap and O(n·⌈k/64⌉) words for the colour sets, k the number of
/// colours.
///
/// # Counts
/// One `comparison` per comparison of heap entries and one `edge_visit` per neighbour looked
/// at (exactly 2m).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{dsatur_with, check_colouring, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]])?;
/// let mut c = Counts::default();
/// let colouring = dsatur_with(&g, &mut c);
/// assert_eq!(check_colouring(&g, &colouring.colour), Ok(()));
/// assert_eq!((colouring.count, c.edge_visits), (3, 10));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dsatur_with<C: Counter>(g: &Graph, c: &mut C) -> Colouring {
    let n = g.vertex_count();
    let mut colour = vec![UNCOLOURED; n];
    let mut saturation = vec![0u32; n];
    let mut words = 1usize;
    let mut seen = vec![0u64; n];
    let mut heap: Heap<(u32, u32, u32)> = Heap::with_capacity(n);
    // "Less" in the min-heap means "should be coloured sooner".
    let sooner = |a: &(u32, u32, u32), b: &(u32, u32, u32)| (a.0, a.1, b.2) > (b.0, b.1, a.2);
    for v in 0..n {
        heap.push((0, g.degree(v) as u32, v as u32), sooner, c);
    }
    let mut count = 0usize;
    while let Some((sat, _, v)) = heap.pop(sooner, c) {
        let v = v as usize;
        if colour[v] != UNCOLOURED || sat != saturation[v] {
            continue;
        }
        let row = &seen[v * words..(v + 1) * words];
        let k = first_zero(row);
        colour[v] = k as u32;
        if k + 1 > count {
            count = k + 1;
            if count > 64 * words {
                seen = widen(&seen, words, 2 * words);
                words *= 2;
            }
        }
        for &u in g.adjacent(v) {
            c.edge_visit();
            let u = u as usize;
            if colour[u] != UNCOLOURED {
                continue;
            }
            let (word, bit) = (u * words + k / 64, 1u64 << (k % 64));
            if seen[word] & bit == 0 {
                seen[word] |= bit;
                saturation[u] += 1;
                heap.push((saturation[u], g.degree(u) as u32, u as u32), sooner, c);
            }
        }
    }
    let colour: Vec<usize> = colour.into_iter().map(|k| k as usize).collect();
    debug_assert_eq!(check_colouring(g, &colour), Ok(()));
    Colouring { colour, count }
}

/// The first colour missing from a bit set.
fn first_zero(row: &[u64]) -> usize {
    row.iter()
        .enumerate()
        .find(|(_, &w)| w != u64::MAX)
        .map_or(64 * row.len(), |(i, w)| 64 * i + w.trailing_ones() as usize)
}

/// Copies per-vertex bit sets of `old` words into sets of `new` words.
fn widen(seen: &[u64], old: usize, new: usize) -> Vec<u64> {
    let n = seen.len() / old;
    let mut out = vec![0u64; n * new];
    for v in 0..n {
        out[v * new..v * new + old].copy_from_slice(&seen[v * old..(v + 1) * old]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dsatur_widens_its_colour_sets_past_64_colours() {
        let n = 130;
        let edges: Vec<[usize; 2]> = (0..n)
            .flat_map(|u| (u + 1..n).map(move |v| [u, v]))
            .collect();
        let g = Graph::from_edges(n, &edges).unwrap();
        let c = dsatur(&g);
        assert_eq!(c.count, n);
        assert_eq!(check_colouring(&g, &c.colour), Ok(()));
    }
}
