//! The compact graph types every graph algorithm runs on: [`Graph`] (CSR adjacency of a
//! simple undirected graph) and [`WeightedGraph`] (the same with edge weights, parallel
//! edges kept).
//!
//! Both are built from an [`EdgeList`] (or a plain edge slice) in O(n + m) time with a
//! two-pass counting sort, so every neighbour list comes out in ascending vertex order:
//! traversals then follow the course's convention that "the first new neighbour" is the one
//! with the smallest id ([RD, §2.1] "Algoritmos de búsqueda").

use crate::error::{Error, Result};
use crate::limits;
use crate::util::Csr;

pub use crate::limits::{MAX_EDGES, MAX_VERTICES};

/// A graph as the edge list every graph algorithm builds from.
///
/// Vertices are `0..vertices`. Lists from [`crate::gen::graph`] are simple (each edge `[u, v]` has
/// `u < v`, no edge appears twice) and sorted lexicographically; lists read from users may
/// be neither, and the graph module validates them.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct EdgeList {
    /// Number of vertices; vertex ids are `0..vertices`.
    pub vertices: usize,
    /// The edges as vertex pairs.
    pub edges: Vec<[usize; 2]>,
    /// One weight per edge, in the order of `edges`, if the graph is weighted.
    pub weights: Option<Vec<f64>>,
}

/// A simple undirected graph in compressed sparse row form.
///
/// Vertices are `0..n`; the neighbours of `v` are one contiguous, strictly ascending slice.
/// Self-loops are dropped and parallel edges merged when the graph is built; both are
/// reported by [`Graph::loops_dropped`] and [`Graph::parallel_merged`], so nothing is lost
/// silently.
///
/// ```
/// use compgeo::graph::Graph;
///
/// let g = Graph::from_edges(4, &[[2, 0], [0, 1], [1, 0], [3, 3]])?;
/// assert_eq!((g.vertex_count(), g.edge_count()), (4, 2));
/// assert_eq!(g.neighbours(0).collect::<Vec<_>>(), [1, 2]);
/// assert_eq!((g.loops_dropped(), g.parallel_merged()), (1, 1));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Graph {
    offsets: Vec<usize>,
    targets: Vec<u32>,
    loops_dropped: usize,
    parallel_merged: usize,
}

/// An undirected graph with a finite weight on every edge, for spanning-tree algorithms.
///
/// Edges keep their input index (results name edges by it). Parallel edges are kept (a
/// spanning tree uses the lightest of them); self-loops are kept in the edge list but left
/// out of the adjacency, since no spanning tree can use one. Each vertex's incident edges
/// are stored in ascending order of the other endpoint, then of edge index.
///
/// ```
/// use compgeo::graph::WeightedGraph;
///
/// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [2, 2]], &[1.5, 2.0, 0.1])?;
/// assert_eq!((g.vertex_count(), g.edge_count()), (3, 3));
/// assert_eq!(g.endpoints(1), [1, 2]);
/// assert_eq!(g.weight(2), 0.1);
/// assert_eq!(g.incident(1).collect::<Vec<_>>(), [(0, 0), (2, 1)]);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct WeightedGraph {
    edges: Vec<[u32; 2]>,
    weights: Vec<f64>,
    offsets: Vec<usize>,
    /// `(other endpoint, edge index)` per incidence.
    incidences: Vec<(u32, u32)>,
}

impl Graph {
    /// Builds the graph on `vertices` vertices from its edges.
    ///
    /// # Errors
    /// [`Error::VertexOutOfRange`] naming the first edge with an endpoint `>= vertices`;
    /// [`Error::LimitExceeded`] if `vertices` exceeds [`MAX_VERTICES`] or the edges
    /// exceed [`MAX_EDGES`], before anything is allocated.
    ///
    /// # Complexity
    /// O(n + m) time, O(n + m) auxiliary space, for n vertices and m edges.
    pub fn from_edges(vertices: usize, edges: &[[usize; 2]]) -> Result<Self> {
        check_sizes(vertices, edges)?;
        let csr = Csr::undirected(vertices, edges.iter().map(|&e| (e, ())));
        let loops_dropped = csr.loops;
        let mut offsets = csr.offsets;
        let mut targets: Vec<u32> = csr.entries.into_iter().map(|(t, ())| t).collect();
        // Merge parallel edges: drop repeats inside each sorted list, compacting in place.
        let mut write = 0;
        let mut start = 0;
        for v in 0..vertices {
            let end = offsets[v + 1];
            let mut last = u32::MAX;
            for read in start..end {
                let t = targets[read];
                if t != last {
                    targets[write] = t;
                    write += 1;
                    last = t;
                }
            }
            start = end;
            offsets[v + 1] = write;
        }
        let removed = targets.len() - write;
        targets.truncate(write);
        targets.shrink_to_fit();
        Ok(Graph {
            offsets,
            targets,
            loops_dropped,
            parallel_merged: removed / 2,
        })
    }

    /// Builds the graph of an edge list, ignoring its weights.
    ///
    /// # Errors
    /// As [`Graph::from_edges`].
    ///
    /// # Complexity
    /// O(n + m) time and auxiliary space.
    pub fn from_edge_list(list: &EdgeList) -> Result<Self> {
        Graph::from_edges(list.vertices, &list.edges)
    }

    /// The number of vertices n.
    pub fn vertex_count(&self) -> usize {
        self.offsets.len() - 1
    }

    /// The number of distinct edges m (after dropping loops and merging parallels).
    pub fn edge_count(&self) -> usize {
        self.targets.len() / 2
    }

    /// The degree of `v`.
    ///
    /// # Panics
    /// If `v >= n` (an internal index, not user data).
    pub fn degree(&self, v: usize) -> usize {
        self.offsets[v + 1] - self.offsets[v]
    }

    /// The neighbours of `v` in ascending order.
    ///
    /// # Panics
    /// If `v >= n`.
    pub fn neighbours(&self, v: usize) -> impl ExactSizeIterator<Item = usize> + '_ {
        self.adjacent(v).iter().map(|&t| t as usize)
    }

    /// Whether `u` and `v` are adjacent, by binary search in `u`'s list: O(log deg u).
    ///
    /// # Panics
    /// If `u >= n` or `v >= n`.
    pub fn has_edge(&self, u: usize, v: usize) -> bool {
        assert!(v < self.vertex_count(), "vertex {v} out of range");
        self.adjacent(u).binary_search(&(v as u32)).is_ok()
    }

    /// Every edge once, as `[u, v]` with `u < v`, in lexicographic order.
    pub fn edges(&self) -> impl Iterator<Item = [usize; 2]> + '_ {
        (0..self.vertex_count()).flat_map(move |u| {
            self.neighbours(u)
                .filter(move |&v| v > u)
                .map(move |v| [u, v])
        })
    }

    /// How many self-loops the input had (dropped).
    pub fn loops_dropped(&self) -> usize {
        self.loops_dropped
    }

    /// How many input edges repeated an earlier one (merged).
    pub fn parallel_merged(&self) -> usize {
        self.parallel_merged
    }

    /// The raw neighbour slice of `v`, for the algorithms' inner loops.
    pub(crate) fn adjacent(&self, v: usize) -> &[u32] {
        &self.targets[self.offsets[v]..self.offsets[v + 1]]
    }

    /// Checks that `v` is a vertex, for functions that take a start vertex from the user.
    pub(crate) fn check_vertex(&self, v: usize) -> Result<()> {
        if v < self.vertex_count() {
            Ok(())
        } else {
            Err(Error::NoSuchVertex {
                vertex: v,
                vertices: self.vertex_count(),
            })
        }
    }
}

impl WeightedGraph {
    /// Builds the weighted graph on `vertices` vertices; `weights[i]` is the weight of
    /// `edges[i]`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"weights"`) if the lengths differ;
    /// [`Error::NonFiniteWeight`] naming the first NaN or infinite weight;
    /// [`Error::VertexOutOfRange`] naming the first edge with an endpoint `>= vertices`;
    /// [`Error::LimitExceeded`] for sizes beyond [`MAX_VERTICES`] / [`MAX_EDGES`].
    ///
    /// # Complexity
    /// O(n + m) time and auxiliary space.
    pub fn from_edges(vertices: usize, edges: &[[usize; 2]], weights: &[f64]) -> Result<Self> {
        if weights.len() != edges.len() {
            return Err(Error::InvalidParameter {
                name: "weights",
                reason: format!("{} weights for {} edges", weights.len(), edges.len()),
            });
        }
        if let Some((edge, &value)) = weights.iter().enumerate().find(|(_, w)| !w.is_finite()) {
            return Err(Error::NonFiniteWeight { edge, value });
        }
        check_sizes(vertices, edges)?;
        let csr = Csr::undirected(
            vertices,
            edges.iter().enumerate().map(|(e, &pair)| (pair, e as u32)),
        );
        Ok(WeightedGraph {
            edges: edges.iter().map(|&[u, v]| [u as u32, v as u32]).collect(),
            weights: weights.to_vec(),
            offsets: csr.offsets,
            incidences: csr.entries,
        })
    }

    /// Builds the weighted graph of an edge list.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"weights"`) if the list has no weights, and the
    /// errors of [`WeightedGraph::from_edges`].
    ///
    /// # Complexity
    /// O(n + m) time and auxiliary space.
    pub fn from_edge_list(list: &EdgeList) -> Result<Self> {
        let weights = list
            .weights
            .as_deref()
            .ok_or_else(|| Error::InvalidParameter {
                name: "weights",
                reason: "the graph has no edge weights".to_string(),
            })?;
        WeightedGraph::from_edges(list.vertices, &list.edges, weights)
    }

    /// The number of vertices n.
    pub fn vertex_count(&self) -> usize {
        self.offsets.len() - 1
    }

    /// The number of edges m, loops and parallel edges included.
    pub fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// The endpoints of edge `e` as given.
    ///
    /// # Panics
    /// If `e >= m`.
    pub fn endpoints(&self, e: usize) -> [usize; 2] {
        let [u, v] = self.edges[e];
        [u as usize, v as usize]
    }

    /// The weight of edge `e`.
    ///
    /// # Panics
    /// If `e >= m`.
    pub fn weight(&self, e: usize) -> f64 {
        self.weights[e]
    }

    /// Every weight, indexed by edge.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The edges incident to `v` (self-loops excluded) as `(other endpoint, edge index)`,
    /// sorted by other endpoint, then edge index.
    ///
    /// # Panics
    /// If `v >= n`.
    pub fn incident(&self, v: usize) -> impl ExactSizeIterator<Item = (usize, usize)> + '_ {
        self.incidences_of(v)
            .iter()
            .map(|&(t, e)| (t as usize, e as usize))
    }

    /// The raw edge array.
    pub(crate) fn raw_edges(&self) -> &[[u32; 2]] {
        &self.edges
    }

    /// The raw incidence slice of `v`.
    pub(crate) fn incidences_of(&self, v: usize) -> &[(u32, u32)] {
        &self.incidences[self.offsets[v]..self.offsets[v + 1]]
    }
}

/// Validates vertex ids and sizes before anything is allocated.
fn check_sizes(vertices: usize, edges: &[[usize; 2]]) -> Result<()> {
    limits::VERTICES.check(vertices as u128)?;
    limits::EDGES.check(edges.len() as u128)?;
    for (edge, &[u, v]) in edges.iter().enumerate() {
        let bad = if u >= vertices {
            Some(u)
        } else if v >= vertices {
            Some(v)
        } else {
            None
        };
        if let Some(vertex) = bad {
            return Err(Error::VertexOutOfRange {
                edge,
                vertex,
                vertices,
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn neighbour_lists_are_sorted_deduplicated_and_symmetric() {
        let edges = [[3, 1], [0, 3], [1, 3], [2, 0], [1, 1], [0, 2], [3, 0]];
        let g = Graph::from_edges(5, &edges).unwrap();
        assert_eq!(g.neighbours(0).collect::<Vec<_>>(), [2, 3]);
        assert_eq!(g.neighbours(1).collect::<Vec<_>>(), [3]);
        assert_eq!(g.neighbours(3).collect::<Vec<_>>(), [0, 1]);
        assert_eq!(g.degree(4), 0);
        assert_eq!(g.edges().collect::<Vec<_>>(), [[0, 2], [0, 3], [1, 3]]);
        assert_eq!((g.loops_dropped(), g.parallel_merged()), (1, 3));
        assert!(g.has_edge(3, 1) && !g.has_edge(1, 2));
    }

    #[test]
    fn bad_vertices_and_weights_are_named() {
        assert!(matches!(
            Graph::from_edges(3, &[[0, 1], [1, 7]]),
            Err(Error::VertexOutOfRange {
                edge: 1,
                vertex: 7,
                vertices: 3
            })
        ));
        let e = WeightedGraph::from_edges(3, &[[0, 1], [1, 2]], &[1.0, f64::NAN]).unwrap_err();
        assert!(matches!(e, Error::NonFiniteWeight { edge: 1, .. }), "{e}");
        let e = WeightedGraph::from_edges(3, &[[0, 1]], &[]).unwrap_err();
        assert!(matches!(
            e,
            Error::InvalidParameter {
                name: "weights",
                ..
            }
        ));
    }

    #[test]
    fn weighted_incidences_are_sorted_and_skip_loops() {
        let g = WeightedGraph::from_edges(3, &[[2, 0], [0, 1], [0, 0], [0, 2]], &[1.0; 4]).unwrap();
        assert_eq!(g.incident(0).collect::<Vec<_>>(), [(1, 1), (2, 0), (2, 3)]);
        assert_eq!(g.incident(2).collect::<Vec<_>>(), [(0, 0), (0, 3)]);
    }
}
