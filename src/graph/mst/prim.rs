//! Prim's algorithm: the course's greedy tree, grown from one vertex by the lightest edge to a
//! new vertex.

use super::{edge_keys, finish, SpanningForest};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::graph::WeightedGraph;
use crate::trace::{record, Frame, NoObserver, Observer, TraceSize};
use crate::util::Heap;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "mst",
    name: "prim",
    function: "graph::prim",
    file: "src/graph/mst/prim.rs",
    summary: "the course's greedy tree: the lightest edge to a new vertex, from a binary heap",
    time: "O(m log m)",
    space: "O(n + m)",
    operation: Some(Operation::Comparisons),
    counts: "heap comparisons; O(m log n) on simple graphs",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::MLogN, Operation::Comparisons)],
};

/// A step of Prim's algorithm, as [`prim_trace`] records it.
#[derive(Debug, Clone, PartialEq)]
pub enum PrimStep {
    /// A new tree starts at `vertex` (the first at an end of the lightest edge, then one per
    /// further component, at its smallest vertex).
    Root {
        /// The tree's first vertex.
        vertex: usize,
    },
    /// The lightest edge left in the heap, `edge`, towards `to`, was taken out: accepted if
    /// `to` was new to the tree (the course's "lightest edge that adds a new vertex"),
    /// rejected if it was already in.
    Edge {
        /// The edge's index in the graph.
        edge: usize,
        /// The end of the edge that was outside the tree when the edge entered the heap.
        to: usize,
        /// Whether the edge joined the tree.
        accepted: bool,
        /// The edges of the forest so far, in the order they were accepted.
        tree: Vec<usize>,
    },
    /// The heap is empty in every component: the result of [`prim`].
    Done {
        /// The spanning forest, as [`prim`] returns it.
        forest: SpanningForest,
    },
}

impl TraceSize for PrimStep {
    fn entries(&self) -> usize {
        match self {
            PrimStep::Root { .. } => 1,
            PrimStep::Edge { tree, .. } => 3 + tree.len(),
            PrimStep::Done { forest } => forest.edges.len(),
        }
    }
}

/// Prim's algorithm; see [`prim_with`].
///
/// # Complexity
/// O(m log m) time (O(m log n) on simple graphs), O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{prim, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0]], &[4.0, 1.0, 2.0, 3.0])?;
/// let t = prim(&g);
/// assert_eq!(t.edges, [1, 2, 3]);
/// assert_eq!(t.weight, 6.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn prim(g: &WeightedGraph) -> SpanningForest {
    prim_with(g, &mut NoCount)
}

/// The course's greedy spanning tree (Prim's algorithm), counting its work.
///
/// The idea ([RD, §2.1] "Árbol Spanning Minimal", "Algoritmo voraz
/// aplicado a un Árbol Spanning Minimal"): take the lightest edge; then repeatedly add the
/// lightest edge that brings a new vertex into the tree, until no edge does. The tree grows
/// from an endpoint of the lightest edge (whose lightest edge is that one, so the first step
/// is the course's). A binary heap holds the edges leaving the tree, keyed by (weight, edge
/// index); edges whose far end joined the tree meanwhile are skipped when popped. When the
/// heap runs dry with vertices left, a new tree starts at the smallest vertex not yet
/// reached, which makes a minimum spanning forest.
///
/// # Complexity
/// O(m log m) time for n vertices and m edges, which is O(m log n) when there are no
/// parallel edges (m < n²); O(n + m) auxiliary space for the heap.
///
/// # Counts
/// One `comparison` per comparison of heap entries (the dominant work, at most
/// 2·m·⌈log₂(2m)⌉ + m) and one `edge_visit` per incidence looked at (exactly 2m minus the
/// self-loops' share).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{prim_with, WeightedGraph};
///
/// // Two components: a triangle and a single edge.
/// let g = WeightedGraph::from_edges(5, &[[0, 1], [1, 2], [0, 2], [3, 4]], &[1.0, 1.0, 5.0, 2.0])?;
/// let mut c = Counts::default();
/// let f = prim_with(&g, &mut c);
/// assert_eq!((f.edges, f.components), (vec![0, 1, 3], 2));
/// assert_eq!(f.weight, 4.0);
/// assert_eq!(c.edge_visits, 8);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn prim_with<C: Counter>(g: &WeightedGraph, c: &mut C) -> SpanningForest {
    prim_observed(g, c, &mut NoObserver)
}

/// The frames of Prim's algorithm on `g`: its own run, step by step.
///
/// The run is [`prim_with`]'s, told about each step: a [`PrimStep::Root`] per tree started,
/// one [`PrimStep::Edge`] per edge taken out of the heap (accepted or rejected, with the
/// forest so far), and last [`PrimStep::Done`] with the forest [`prim`] returns. Every edge
/// that is not a loop enters the heap exactly once (from the end that joins the tree first),
/// so there are as many edge frames as such edges. Each frame carries the operations
/// counted so far; the last frame's are those of [`prim_with`] with [`Counts`](crate::count::Counts).
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
/// use compgeo::graph::{prim_trace, PrimStep, WeightedGraph};
///
/// // A triangle 0-1 (weight 1), 1-2 (2), 2-0 (3): the edge 2-0 comes out of the heap last,
/// // when both ends are in the tree, and is rejected.
/// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [2, 0]], &[1.0, 2.0, 3.0])?;
/// let steps: Vec<PrimStep> = prim_trace(&g)?.into_iter().map(|f| f.step).collect();
/// assert_eq!(steps[0], PrimStep::Root { vertex: 0 });
/// assert_eq!(steps[1], PrimStep::Edge { edge: 0, to: 1, accepted: true, tree: vec![0] });
/// assert_eq!(steps[2], PrimStep::Edge { edge: 1, to: 2, accepted: true, tree: vec![0, 1] });
/// assert_eq!(steps[3], PrimStep::Edge { edge: 2, to: 2, accepted: false, tree: vec![0, 1] });
/// assert!(matches!(&steps[4], PrimStep::Done { forest } if forest.edges == [0, 1]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn prim_trace(g: &WeightedGraph) -> Result<Vec<Frame<PrimStep>>> {
    record(|counts, recorder| {
        let forest = prim_observed(g, counts, recorder);
        Ok(PrimStep::Done { forest })
    })
}

/// Prim's algorithm, telling `obs` about each tree started and each edge out of the heap.
fn prim_observed<C: Counter, O: Observer<PrimStep, C>>(
    g: &WeightedGraph,
    c: &mut C,
    obs: &mut O,
) -> SpanningForest {
    let n = g.vertex_count();
    let keys = edge_keys(g);
    let mut in_tree = vec![false; n];
    let mut chosen = Vec::with_capacity(n.saturating_sub(1));
    let mut heap: Heap<(u64, u32, u32)> = Heap::with_capacity(0);
    let first = (0..g.edge_count())
        .filter(|&e| g.endpoints(e)[0] != g.endpoints(e)[1])
        .min_by_key(|&e| (keys[e], e))
        .map_or(0, |e| g.endpoints(e)[0]);
    let mut components = 0;
    let starts = std::iter::once(first).chain(0..n);
    for root in starts {
        if root >= n || in_tree[root] {
            continue;
        }
        components += 1;
        obs.step(c, || PrimStep::Root { vertex: root });
        grow(g, &keys, root, &mut in_tree, &mut heap, c);
        while let Some((_, e, t)) = heap.pop(lighter, c) {
            let accepted = !in_tree[t as usize];
            if accepted {
                chosen.push(e as usize);
                grow(g, &keys, t as usize, &mut in_tree, &mut heap, c);
            }
            obs.step(c, || PrimStep::Edge {
                edge: e as usize,
                to: t as usize,
                accepted,
                tree: chosen.clone(),
            });
        }
    }
    finish(g, chosen, components)
}

/// Prim's step: `v` joins the tree and its edges to vertices outside go on the heap.
fn grow<C: Counter>(
    g: &WeightedGraph,
    keys: &[u64],
    v: usize,
    in_tree: &mut [bool],
    heap: &mut Heap<(u64, u32, u32)>,
    c: &mut C,
) {
    in_tree[v] = true;
    for &(t, e) in g.incidences_of(v) {
        c.edge_visit();
        if !in_tree[t as usize] {
            heap.push((keys[e as usize], e, t), lighter, c);
        }
    }
}

/// Prim's heap order: by weight key, then edge index.
fn lighter(a: &(u64, u32, u32), b: &(u64, u32, u32)) -> bool {
    (a.0, a.1) < (b.0, b.1)
}
