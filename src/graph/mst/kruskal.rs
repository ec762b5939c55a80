//! Kruskal's algorithm: the edges in order of weight, each added when it joins two trees.

use super::{edge_keys, finish, SpanningForest};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::graph::{UnionFind, WeightedGraph};
use crate::trace::{record, Frame, NoObserver, Observer, TraceSize};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "mst",
    name: "kruskal",
    function: "graph::kruskal",
    file: "src/graph/mst/kruskal.rs",
    summary: "the edges by weight, each joining two trees of a union–find",
    time: "O(m log m)",
    space: "O(n + m)",
    operation: Some(Operation::Comparisons),
    counts: "those of the edge sort, then one edge visit per edge examined",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::MLogM, Operation::Comparisons)],
};

/// A step of Kruskal's algorithm, as [`kruskal_trace`] records it.
#[derive(Debug, Clone, PartialEq)]
pub enum KruskalStep {
    /// The edges that are not loops, sorted by (weight, index): the order they are examined
    /// in.
    Sorted {
        /// Edge indices, lightest first.
        order: Vec<usize>,
    },
    /// The next edge of the order was examined: accepted if its ends were in different
    /// trees of the forest, rejected (it would close a cycle) otherwise.
    Edge {
        /// The edge's index in the graph.
        edge: usize,
        /// Whether the edge joined the forest.
        accepted: bool,
        /// The edges of the forest so far, in the order they were accepted.
        forest: Vec<usize>,
    },
    /// The forest has n − 1 edges or the order is exhausted: the result of [`kruskal`].
    Done {
        /// The spanning forest, as [`kruskal`] returns it.
        forest: SpanningForest,
    },
}

impl TraceSize for KruskalStep {
    fn entries(&self) -> usize {
        match self {
            KruskalStep::Sorted { order } => order.len(),
            KruskalStep::Edge { forest, .. } => 2 + forest.len(),
            KruskalStep::Done { forest } => forest.edges.len(),
        }
    }
}

/// Kruskal's algorithm; see [`kruskal_with`].
///
/// # Complexity
/// O(m log m) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{kruskal, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0]], &[4.0, 1.0, 2.0, 3.0])?;
/// assert_eq!(kruskal(&g).edges, [1, 2, 3]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn kruskal(g: &WeightedGraph) -> SpanningForest {
    kruskal_with(g, &mut NoCount)
}

/// Kruskal's algorithm, counting its work.
///
/// The idea: the greedy scheme of the course (§2.1 "Algoritmo voraz") with the candidates
/// taken in order of weight over the whole graph rather than around one tree: sort the
/// edges by (weight, index), then add each edge whose ends lie in different trees of the
/// forest built so far, tested with union–find (union by rank, path compression). Stops as
/// soon as n − 1 edges are in.
///
/// # Complexity
/// O(m log m) time for m edges (the sort; the union–find work is O(m α(n))), which is
/// O(m log n) when there are no parallel edges; O(n + m) auxiliary space.
///
/// # Counts
/// One `comparison` per comparison of the sort (O(m log m)) and one `edge_visit` per edge
/// examined after it.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{kruskal_with, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [2, 0], [0, 0]], &[3.0, 1.0, 2.0, 0.0])?;
/// let mut c = Counts::default();
/// let t = kruskal_with(&g, &mut c);
/// assert_eq!(t.edges, [1, 2]);
/// assert_eq!(t.weight, 3.0);
/// assert!(c.comparisons > 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn kruskal_with<C: Counter>(g: &WeightedGraph, c: &mut C) -> SpanningForest {
    kruskal_observed(g, c, &mut NoObserver)
}

/// The frames of Kruskal's algorithm on `g`: its own run, step by step.
///
/// The run is [`kruskal_with`]'s, told about each step: [`KruskalStep::Sorted`] after the
/// sort, one [`KruskalStep::Edge`] per edge examined (accepted or rejected, with the forest
/// so far), and last [`KruskalStep::Done`] with the forest [`kruskal`] returns. Each frame
/// carries the operations counted so far; the last frame's are those of [`kruskal_with`]
/// with [`Counts`](crate::count::Counts).
///
/// # Errors
///
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the frames would hold more than
/// [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES) entries (m frames of up to n − 1
/// edges).
///
/// # Complexity
///
/// O(m log m) for the algorithm plus O(mn) time and space for the frames.
///
/// ```
/// use compgeo::graph::{kruskal_trace, KruskalStep, WeightedGraph};
///
/// // A square with a diagonal 0-2 (weight 1.5): 1-2 (1) and the diagonal go in, 2-3 (2)
/// // joins 3, then 3-0 (3) would close a cycle.
/// let g = WeightedGraph::from_edges(
///     4,
///     &[[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]],
///     &[4.0, 1.0, 2.0, 3.0, 1.5],
/// )?;
/// let steps: Vec<KruskalStep> = kruskal_trace(&g)?.into_iter().map(|f| f.step).collect();
/// assert_eq!(steps[0], KruskalStep::Sorted { order: vec![1, 4, 2, 3, 0] });
/// let accepted: Vec<bool> = steps
///     .iter()
///     .filter_map(|s| match s { KruskalStep::Edge { accepted, .. } => Some(*accepted), _ => None })
///     .collect();
/// assert_eq!(accepted, [true, true, true]); // three edges span four vertices: it stops
/// assert!(matches!(&steps[4], KruskalStep::Done { forest } if forest.edges == [1, 2, 4]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn kruskal_trace(g: &WeightedGraph) -> Result<Vec<Frame<KruskalStep>>> {
    record(|counts, recorder| {
        let forest = kruskal_observed(g, counts, recorder);
        Ok(KruskalStep::Done { forest })
    })
}

/// Kruskal's algorithm, telling `obs` about the sort and each edge examined.
fn kruskal_observed<C: Counter, O: Observer<KruskalStep, C>>(
    g: &WeightedGraph,
    c: &mut C,
    obs: &mut O,
) -> SpanningForest {
    let n = g.vertex_count();
    let keys = edge_keys(g);
    let edges = g.raw_edges();
    let mut order: Vec<(u64, u32)> = (0..edges.len())
        .filter(|&e| edges[e][0] != edges[e][1])
        .map(|e| (keys[e], e as u32))
        .collect();
    order.sort_unstable_by(|a, b| {
        c.comparison();
        a.cmp(b)
    });
    obs.step(c, || KruskalStep::Sorted {
        order: order.iter().map(|&(_, e)| e as usize).collect(),
    });
    let mut sets = UnionFind::new(n);
    let mut chosen = Vec::with_capacity(n.saturating_sub(1));
    for &(_, e) in &order {
        if chosen.len() + 1 >= n {
            break;
        }
        c.edge_visit();
        let [u, v] = edges[e as usize];
        let accepted = sets.union(u as usize, v as usize);
        if accepted {
            chosen.push(e as usize);
        }
        obs.step(c, || KruskalStep::Edge {
            edge: e as usize,
            accepted,
            forest: chosen.clone(),
        });
    }
    let components = n - chosen.len();
    finish(g, chosen, components)
}
