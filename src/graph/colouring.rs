//! Greedy vertex colouring: the seed's O(n²) algorithm as printed, the O(n + m) greedy, the
//! vertex orders largest-first (Welsh–Powell) and smallest-last, and DSatur.
//!
//! A colouring gives each vertex a colour so that adjacent vertices differ (seed
//! `003_5b666ee3e15e6353.txt`, §2.1 "Coloración de vértices", Definitions 2.4–2.6). The greedy
//! scheme ("Algoritmo voraz aplicado a la coloración") takes the vertices in some order and
//! gives each the first colour none of its already coloured neighbours has; the order decides
//! how many colours it needs. Colours are numbered from 0 here (the seed's colour k is our
//! k − 1).
//!
//! The tests check every colouring with [`is_proper_colouring`], the seed's chromatic-number
//! facts (K_n, even and odd cycles, trees), the seed's count of n(n−1)/2 adjacency tests, and
//! DSatur against petgraph.

use super::graph::Graph;
use super::heap::Heap;
use crate::count::{Counter, NoCount};
use crate::error::{Error, Result};
use std::fmt;
use std::str::FromStr;

/// A vertex colouring.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Colouring {
    /// `colour[v]` is the colour of vertex `v`, in `0..count`.
    pub colour: Vec<usize>,
    /// The number of colours used (0 for the empty graph).
    pub count: usize,
}

/// The colouring strategies, by their command-line names.
///
/// ```
/// use compgeo::graph::ColouringAlgorithm;
///
/// assert_eq!("dsatur".parse::<ColouringAlgorithm>()?, ColouringAlgorithm::Dsatur);
/// assert_eq!(ColouringAlgorithm::LargestFirst.name(), "largest-first");
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ColouringAlgorithm {
    /// The seed's algorithm in vertex order ([`course_greedy_colouring`]), `course`.
    Course,
    /// The O(n + m) greedy in vertex order ([`greedy_colouring`]), `greedy`.
    Greedy,
    /// Greedy in [`largest_first_order`], `largest-first`.
    LargestFirst,
    /// Greedy in [`smallest_last_order`], `smallest-last`.
    SmallestLast,
    /// [`dsatur`], `dsatur`.
    Dsatur,
    /// [`dsatur_tabu`](super::dsatur_tabu): DSatur, then a tabu search for fewer colours,
    /// `dsatur-tabu`.
    DsaturTabu,
}

impl ColouringAlgorithm {
    /// Every strategy, in the order above.
    pub const ALL: [ColouringAlgorithm; 6] = [
        ColouringAlgorithm::Course,
        ColouringAlgorithm::Greedy,
        ColouringAlgorithm::LargestFirst,
        ColouringAlgorithm::SmallestLast,
        ColouringAlgorithm::Dsatur,
        ColouringAlgorithm::DsaturTabu,
    ];

    /// The kebab-case name.
    pub fn name(self) -> &'static str {
        match self {
            ColouringAlgorithm::Course => "course",
            ColouringAlgorithm::Greedy => "greedy",
            ColouringAlgorithm::LargestFirst => "largest-first",
            ColouringAlgorithm::SmallestLast => "smallest-last",
            ColouringAlgorithm::Dsatur => "dsatur",
            ColouringAlgorithm::DsaturTabu => "dsatur-tabu",
        }
    }
}

impl fmt::Display for ColouringAlgorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for ColouringAlgorithm {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        crate::error::algorithm_named(
            s,
            "colouring algorithm",
            &ColouringAlgorithm::ALL,
            ColouringAlgorithm::name,
        )
    }
}

/// Colours `g` with `strategy`; see [`colour_with`].
///
/// # Complexity
/// That of the strategy: O(n²) for `Course`, O(n + m) for the other greedy orders,
/// O((n + m) log n) for `Dsatur` and `DsaturTabu`.
///
/// ```
/// use compgeo::graph::{colour, is_proper_colouring, Graph, ColouringAlgorithm};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2], [2, 0]])?;
/// let c = colour(&g, ColouringAlgorithm::Dsatur);
/// assert_eq!(c.count, 3);
/// assert!(is_proper_colouring(&g, &c.colour));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn colour(g: &Graph, strategy: ColouringAlgorithm) -> Colouring {
    colour_with(g, strategy, &mut NoCount)
}

/// Colours `g` with `strategy`, counting as the chosen algorithm counts.
///
/// # Complexity
/// As [`colour`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{colour_with, Graph, ColouringAlgorithm};
///
/// let g = Graph::from_edges(4, &[[0, 1]])?;
/// let mut c = Counts::default();
/// assert_eq!(colour_with(&g, ColouringAlgorithm::Course, &mut c).count, 2);
/// assert_eq!(c.adjacency_tests, 6);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn colour_with<C: Counter>(g: &Graph, strategy: ColouringAlgorithm, c: &mut C) -> Colouring {
    let natural: Vec<usize> = match strategy {
        ColouringAlgorithm::Course | ColouringAlgorithm::Greedy => (0..g.vertex_count()).collect(),
        ColouringAlgorithm::LargestFirst => largest_first_order(g),
        ColouringAlgorithm::SmallestLast => smallest_last_order(g),
        ColouringAlgorithm::Dsatur => return dsatur_with(g, c),
        ColouringAlgorithm::DsaturTabu => return super::dsatur_tabu_with(g, c),
    };
    let result = match strategy {
        ColouringAlgorithm::Course => course_greedy_colouring_with(g, &natural, c),
        _ => greedy_colouring_with(g, &natural, c),
    };
    result.expect("the orders built here are permutations")
}

/// The seed's greedy colouring of `g` in the given vertex order; see
/// [`course_greedy_colouring_with`].
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"order"`) if `order` is not a permutation of `0..n`.
///
/// # Complexity
/// O(n² + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{course_greedy_colouring, Graph};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2]])?;
/// assert_eq!(course_greedy_colouring(&g, &[1, 0, 2])?.colour, [1, 0, 1]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn course_greedy_colouring(g: &Graph, order: &[usize]) -> Result<Colouring> {
    course_greedy_colouring_with(g, order, &mut NoCount)
}

/// The seed's greedy colouring exactly as printed, counting its adjacency tests.
///
/// The idea (`003_5b666ee3e15e6353.txt`, §2.1 "Coloración de vértices", "Algoritmo voraz
/// aplicado a la coloración de un grafo"): c(v₁) := first colour; for i = 2..n, S := the
/// colours of those v_j, j < i, adjacent to v_i (asking the adjacency question for every
/// j < i), and c(v_i) := the first colour not in S. Each adjacency question is O(1): the
/// neighbours of v_i are marked once before the questions are asked.
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"order"`) if `order` is not a permutation of `0..n`,
/// naming the position and vertex at fault.
///
/// # Complexity
/// O(n² + m) time for n vertices and m edges (the seed's analysis: n(n−1)/2 adjacency
/// questions, as many set-membership tests and additions, n² + 2n − 2 assignments); O(n)
/// auxiliary space.
///
/// # Counts
/// One `adjacency_test` per question "is v_j adjacent to v_i?": exactly n(n−1)/2.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{course_greedy_colouring_with, Graph};
///
/// let g = Graph::from_edges(5, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])?;
/// let mut c = Counts::default();
/// let colouring = course_greedy_colouring_with(&g, &[0, 1, 2, 3, 4], &mut c)?;
/// assert_eq!(colouring.colour, [0, 1, 0, 1, 2]);
/// assert_eq!(c.adjacency_tests, 10);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn course_greedy_colouring_with<C: Counter>(
    g: &Graph,
    order: &[usize],
    c: &mut C,
) -> Result<Colouring> {
    check_order(g, order)?;
    let n = g.vertex_count();
    let mut colour = vec![0usize; n];
    let mut adjacent_mark = vec![usize::MAX; n];
    let mut used = vec![usize::MAX; n + 1];
    let mut count = 0;
    for (i, &vi) in order.iter().enumerate() {
        for w in g.neighbours(vi) {
            adjacent_mark[w] = i;
        }
        for &vj in &order[..i] {
            c.adjacency_test();
            if adjacent_mark[vj] == i {
                used[colour[vj]] = i;
            }
        }
        let mut k = 0;
        while used[k] == i {
            k += 1;
        }
        colour[vi] = k;
        count = count.max(k + 1);
    }
    debug_assert!(is_proper_colouring(g, &colour));
    Ok(Colouring { colour, count })
}

/// Greedy colouring of `g` in the given vertex order in O(n + m); see
/// [`greedy_colouring_with`].
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"order"`) if `order` is not a permutation of `0..n`.
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{greedy_colouring, Graph};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2]])?;
/// assert_eq!(greedy_colouring(&g, &[0, 1, 2])?.colour, [0, 1, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn greedy_colouring(g: &Graph, order: &[usize]) -> Result<Colouring> {
    greedy_colouring_with(g, order, &mut NoCount)
}

/// The same colouring as the seed's greedy, computed in O(n + m).
///
/// The idea: the seed's algorithm (§2.1 "Coloración de vértices") asks about every earlier
/// vertex; it is enough to look at v_i's own neighbours. Their colours are stamped with i in
/// an array, and the first colour without the stamp is at most deg(v_i), so the search for
/// it costs O(deg v_i) too. The result equals [`course_greedy_colouring`]'s for the same order.
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"order"`) if `order` is not a permutation of `0..n`.
///
/// # Complexity
/// O(n + m) time for n vertices and m edges; O(n) auxiliary space. A greedy colouring uses
/// at most Δ + 1 colours (Δ the largest degree).
///
/// # Counts
/// One `vertex_visit` per vertex coloured and one `edge_visit` per neighbour looked at:
/// exactly n and 2m.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{greedy_colouring_with, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 3]])?;
/// let mut c = Counts::default();
/// // A path needs 2 colours, but this order makes the greedy use 3.
/// assert_eq!(greedy_colouring_with(&g, &[0, 3, 1, 2], &mut c)?.colour, [0, 1, 2, 0]);
/// assert_eq!((c.vertex_visits, c.edge_visits), (4, 6));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn greedy_colouring_with<C: Counter>(
    g: &Graph,
    order: &[usize],
    c: &mut C,
) -> Result<Colouring> {
    check_order(g, order)?;
    let n = g.vertex_count();
    let mut colour = vec![UNCOLOURED; n];
    let mut stamp = vec![u32::MAX; n + 1];
    let mut count = 0;
    for (i, &v) in order.iter().enumerate() {
        c.vertex_visit();
        for &w in g.adjacent(v) {
            c.edge_visit();
            let k = colour[w as usize];
            if k != UNCOLOURED {
                stamp[k as usize] = i as u32;
            }
        }
        let mut k = 0;
        while stamp[k] == i as u32 {
            k += 1;
        }
        colour[v] = k as u32;
        count = count.max(k + 1);
    }
    let colour: Vec<usize> = colour.into_iter().map(|k| k as usize).collect();
    debug_assert!(is_proper_colouring(g, &colour));
    Ok(Colouring { colour, count })
}

/// The largest-first (Welsh–Powell) order: vertices by decreasing degree; among vertices of
/// equal degree, the one with the most neighbours already in the order comes first.
///
/// Not in the seed, which colours in a given order and shows (§2.1 "Coloración de vértices",
/// the congress example) that a better order can save colours; this is the classic heuristic
/// order for [`greedy_colouring`].
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
    // start[d] = first position of degree d, laid out from the largest degree down.
    let mut start = vec![0usize; max_degree + 2];
    for v in 0..n {
        start[max_degree - g.degree(v) + 1] += 1;
    }
    for d in 1..start.len() {
        start[d] += start[d - 1];
    }
    let mut by_degree = vec![0; n];
    {
        let mut next = start.clone();
        for v in 0..n {
            let slot = &mut next[max_degree - g.degree(v)];
            by_degree[*slot] = v;
            *slot += 1;
        }
    }
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

/// The smallest-last (degeneracy) order: repeatedly remove a vertex of least remaining
/// degree; colour in the reverse order of removal.
///
/// Not in the seed; like [`largest_first_order`] it feeds the seed's greedy scheme (§2.1
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
    let mut bin = vec![0usize; max_degree + 1];
    for &d in &degree {
        bin[d] += 1;
    }
    let mut start = 0;
    for b in bin.iter_mut() {
        let size = *b;
        *b = start;
        start += size;
    }
    let mut sorted = vec![0usize; n];
    let mut pos = vec![0usize; n];
    {
        let mut next = bin.clone();
        for v in 0..n {
            pos[v] = next[degree[v]];
            sorted[pos[v]] = v;
            next[degree[v]] += 1;
        }
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
/// The idea: the greedy scheme of the seed (§2.1 "Algoritmo voraz", "Coloración de
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
/// use compgeo::graph::{dsatur_with, is_proper_colouring, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]])?;
/// let mut c = Counts::default();
/// let colouring = dsatur_with(&g, &mut c);
/// assert!(is_proper_colouring(&g, &colouring.colour));
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
    debug_assert!(is_proper_colouring(g, &colour));
    Colouring { colour, count }
}

/// Whether `colour` is a proper colouring of `g`: one colour per vertex and no edge whose
/// ends share a colour.
///
/// # Complexity
/// O(n + m) time, no auxiliary space.
///
/// ```
/// use compgeo::graph::{is_proper_colouring, Graph};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2]])?;
/// assert!(is_proper_colouring(&g, &[0, 1, 0]));
/// assert!(!is_proper_colouring(&g, &[0, 0, 1]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn is_proper_colouring(g: &Graph, colour: &[usize]) -> bool {
    colour.len() == g.vertex_count() && g.edges().all(|[u, v]| colour[u] != colour[v])
}

/// The colour of a vertex not yet coloured.
const UNCOLOURED: u32 = u32::MAX;

/// Checks that `order` is a permutation of the vertices.
fn check_order(g: &Graph, order: &[usize]) -> Result<()> {
    let n = g.vertex_count();
    if order.len() != n {
        return Err(Error::InvalidParameter {
            name: "order",
            reason: format!("{} vertices in the order, {n} in the graph", order.len()),
        });
    }
    let mut position = vec![usize::MAX; n];
    for (i, &v) in order.iter().enumerate() {
        if v >= n {
            return Err(Error::InvalidParameter {
                name: "order",
                reason: format!("position {i} names vertex {v}, but the graph has {n}"),
            });
        }
        if position[v] != usize::MAX {
            return Err(Error::InvalidParameter {
                name: "order",
                reason: format!("vertex {v} appears at positions {} and {i}", position[v]),
            });
        }
        position[v] = i;
    }
    Ok(())
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
    fn bad_orders_are_named() {
        let g = Graph::from_edges(3, &[[0, 1]]).unwrap();
        let e = greedy_colouring(&g, &[0, 1]).unwrap_err();
        assert!(e.to_string().contains("2 vertices in the order, 3"), "{e}");
        let e = course_greedy_colouring(&g, &[0, 2, 0]).unwrap_err();
        assert!(
            e.to_string()
                .contains("vertex 0 appears at positions 0 and 2"),
            "{e}"
        );
        let e = greedy_colouring(&g, &[0, 1, 5]).unwrap_err();
        assert!(e.to_string().contains("position 2 names vertex 5"), "{e}");
    }

    #[test]
    fn dsatur_widens_its_colour_sets_past_64_colours() {
        let n = 130;
        let edges: Vec<[usize; 2]> = (0..n)
            .flat_map(|u| (u + 1..n).map(move |v| [u, v]))
            .collect();
        let g = Graph::from_edges(n, &edges).unwrap();
        let c = dsatur(&g);
        assert_eq!(c.count, n);
        assert!(is_proper_colouring(&g, &c.colour));
    }
}
