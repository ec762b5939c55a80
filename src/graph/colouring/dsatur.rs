//! DSatur (Brélaz): colour next the vertex whose neighbours already show the most colours.

use super::{check_colouring, Colouring, UNCOLOURED};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::graph::Graph;
use crate::util::Heap;
use std::collections::HashSet;

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
/// O((n + m) log n) time, O(n + m) auxiliary space.
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
/// popped. DSatur colours every bipartite graph with at most 2 colours.
///
/// A vertex of degree d gets a colour at most d (it has at most d coloured neighbours), so
/// each vertex keeps a bit set of the neighbour colours `0..=d` only, ⌈(d + 1)/64⌉ words; the
/// rarer larger colours a neighbour of higher degree shows it go into one hash set of
/// (vertex, colour) pairs, at most one per edge. The sets take O(n + m) space whatever the
/// number of colours (one bit set of k colours per vertex would take n·k/64 words: 8 GiB
/// for 2^26 isolated vertices next to a clique of 1000).
///
/// # Complexity
/// O((n + m) log n) time for n vertices and m edges: at most n + 2m heap entries, and
/// expected O(1) per hash-set insertion. Auxiliary space O(n + m) for the heap and the
/// colour sets.
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
    // Vertex v's bit set of neighbour colours is low[start[v]..start[v + 1]], colours
    // 0..=degree(v) at least; larger ones are (v, colour) pairs in `high`.
    let mut start = Vec::with_capacity(n + 1);
    start.push(0usize);
    for v in 0..n {
        start.push(start[v] + g.degree(v) / 64 + 1);
    }
    let mut low = vec![0u64; start[n]];
    let mut high: HashSet<(u32, u32)> = HashSet::new();
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
        // At most degree(v) of the bits are set, so a zero lies within the set.
        let k = first_zero(&low[start[v]..start[v + 1]]);
        colour[v] = k as u32;
        count = count.max(k + 1);
        for &u in g.adjacent(v) {
            c.edge_visit();
            let u = u as usize;
            if colour[u] != UNCOLOURED {
                continue;
            }
            let word = start[u] + k / 64;
            let new = if word < start[u + 1] {
                let bit = 1u64 << (k % 64);
                let new = low[word] & bit == 0;
                low[word] |= bit;
                new
            } else {
                high.insert((u as u32, k as u32))
            };
            if new {
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

    /// DSatur by its definition, in O(n²) per step: the uncoloured vertex with the most
    /// distinct neighbour colours, then the larger degree, then the smaller id, gets the
    /// first colour its neighbours lack.
    fn dsatur_by_definition(g: &Graph) -> Vec<usize> {
        let n = g.vertex_count();
        let mut colour = vec![usize::MAX; n];
        for _ in 0..n {
            let key = |v: usize| {
                let seen: std::collections::BTreeSet<usize> = g
                    .neighbours(v)
                    .map(|u| colour[u])
                    .filter(|&k| k != usize::MAX)
                    .collect();
                (seen.len(), g.degree(v), std::cmp::Reverse(v))
            };
            let v = (0..n)
                .filter(|&v| colour[v] == usize::MAX)
                .max_by_key(|&v| key(v))
                .unwrap();
            let used: Vec<usize> = g.neighbours(v).map(|u| colour[u]).collect();
            colour[v] = (0..).find(|k| !used.contains(k)).unwrap();
        }
        colour
    }

    #[test]
    fn colours_above_a_vertex_degree_are_counted_once() {
        // Two cliques K_70 (colours beyond 64, the bit set of a vertex of degree below 64),
        // some random edges between them, and vertices of degree 2 to 4 joined to random
        // clique vertices and to each other: such a vertex often sees one high colour twice,
        // and counting it twice would change the order.
        let k = 70;
        for seed in 0..12 {
            let mut rng = crate::gen::Rng::new(seed);
            let mut edges: Vec<[usize; 2]> = Vec::new();
            for base in [0, k] {
                edges.extend((0..k).flat_map(|u| (u + 1..k).map(move |v| [base + u, base + v])));
            }
            for _ in 0..30 {
                edges.push([rng.index(k), k + rng.index(k)]);
            }
            let small = 2 * k;
            for j in 0..30 {
                for _ in 0..2 + rng.index(2) {
                    edges.push([small + j, rng.index(2 * k)]);
                }
                if j > 0 && rng.coin() {
                    edges.push([small + j, small + rng.index(j)]);
                }
            }
            let g = Graph::from_edges(small + 30, &edges).unwrap();
            let c = dsatur(&g);
            assert_eq!(check_colouring(&g, &c.colour), Ok(()));
            assert_eq!(c.colour, dsatur_by_definition(&g), "seed {seed}");
        }
        // A vertex that sees colour 64 twice, beyond its one-word bit set: clique vertex i of
        // K_70 gets colour i; T_i (i = 64..=69), joined to every clique vertex but i, gets
        // colour i too; X is joined to clique vertex 64, to T_64 and to Y; Y to clique
        // vertices 65 and 66. X has saturation 1 and Y 2, so Y is coloured first and takes 0;
        // counting colour 64 twice would tie them and X, the smaller id, would take 0.
        let mut edges: Vec<[usize; 2]> = (0..k)
            .flat_map(|u| (u + 1..k).map(move |v| [u, v]))
            .collect();
        for (t, i) in (64..k).enumerate() {
            edges.extend((0..k).filter(|&j| j != i).map(|j| [j, k + t]));
        }
        let (x, y) = (k + 6, k + 7);
        edges.extend([[64, x], [k, x], [x, y], [65, y], [66, y]]);
        let g = Graph::from_edges(k + 8, &edges).unwrap();
        let c = dsatur(&g);
        assert_eq!(c.colour[..k], (0..k).collect::<Vec<_>>());
        assert_eq!(c.colour[k..k + 6], [64, 65, 66, 67, 68, 69]);
        assert_eq!((c.colour[x], c.colour[y]), (1, 0));
        assert_eq!(c.colour, dsatur_by_definition(&g));
        for seed in 0..20 {
            let list =
                crate::gen::graph(crate::gen::GraphKind::Gnm, 40, 30 + 10 * seed, seed as u64)
                    .unwrap();
            let g = Graph::from_edge_list(&list).unwrap();
            assert_eq!(dsatur(&g).colour, dsatur_by_definition(&g), "seed {seed}");
        }
    }
}
