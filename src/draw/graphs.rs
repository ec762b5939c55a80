//! Pictures of graphs: the vertices at given coordinates or on a circle, the edges, and on
//! request a colouring (one fill per colour class, with a legend), a spanning tree or forest
//! (Prim's, Kruskal's, Borůvka's edges highlighted) or a search tree (the parent edges of a
//! BFS or DFS).

use super::{bounds_of, check_indices, Layer, Picture, Role, CLASS_COLOURS};
use crate::error::{Error, Result};
use crate::geometry::Point2;
use crate::graph::{Colouring, Graph, Search};

/// What a graph picture shows over the graph.
#[derive(Debug, Clone, Copy)]
pub enum GraphOverlay<'a> {
    /// The graph alone.
    Plain,
    /// A colouring: each vertex filled with its class's colour ([`CLASS_COLOURS`]), one
    /// layer `colour-k` and one legend entry per class.
    Colouring(&'a Colouring),
    /// A spanning tree or forest, as the pairs of vertices of its edges (layer `tree`, blue).
    Tree(&'a [[usize; 2]]),
    /// A search from `start`: the edges from each reached vertex to its parent (layer
    /// `tree`), the start ringed.
    Search {
        /// The search's result.
        search: &'a Search,
        /// Where it started.
        start: usize,
    },
}

/// The positions of n vertices evenly spaced on the unit circle, counter-clockwise from the
/// top: vertex i at angle π/2 + 2πi/n (one vertex sits at the top).
///
/// # Complexity
/// Θ(n) time and space.
///
/// ```
/// use compgeo::draw::circle_layout;
///
/// let p = circle_layout(4);
/// assert_eq!(p.len(), 4);
/// assert!((p[0].y - 1.0).abs() < 1e-15 && (p[1].x + 1.0).abs() < 1e-15);
/// ```
pub fn circle_layout(n: usize) -> Vec<Point2> {
    (0..n)
        .map(|i| {
            let angle = std::f64::consts::FRAC_PI_2 + std::f64::consts::TAU * i as f64 / n as f64;
            Point2::new(angle.cos(), angle.sin())
        })
        .collect()
}

/// The graph `g` with its vertices at `positions` (from the input's points, or
/// [`circle_layout`]), its edges (grey), the vertices numbered when the picture shows
/// labels, and the `overlay`.
///
/// # Errors
/// [`Error::InvalidParameter`] named `"positions"` unless there is one finite position per
/// vertex, `"colouring"` unless the colouring gives each vertex a colour below its count,
/// `"tree"` if a tree edge names a vertex out of range, `"search"` if the search's parent
/// array is not one per vertex or the start is out of range.
///
/// # Complexity
/// O(n + m) time and output size for n vertices and m edges (labels add O(n²) for at most
/// [`LABEL_LIMIT`](super::LABEL_LIMIT) vertices).
///
/// ```
/// use compgeo::draw::{self, circle_layout, GraphOverlay};
/// use compgeo::graph::{colour, ColouringAlgorithm, Graph};
///
/// let g = Graph::from_edges(5, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])?; // C₅
/// let c = colour(&g, ColouringAlgorithm::Dsatur);
/// let picture = draw::graph(&g, &circle_layout(5), GraphOverlay::Colouring(&c))?;
/// let layers: Vec<(&str, usize)> = picture.layers().collect();
/// assert!(layers.contains(&("edges", 5)));
/// assert_eq!(layers.iter().filter(|(name, _)| name.starts_with("colour-")).count(), 3);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn graph(g: &Graph, positions: &[Point2], overlay: GraphOverlay<'_>) -> Result<Picture> {
    let n = g.vertex_count();
    if positions.len() != n {
        return Err(Error::InvalidParameter {
            name: "positions",
            reason: format!("{} positions for {n} vertices", positions.len()),
        });
    }
    if let Some(i) = positions
        .iter()
        .position(|p| !p.x.is_finite() || !p.y.is_finite())
    {
        return Err(Error::InvalidParameter {
            name: "positions",
            reason: format!("the position of vertex {i} is not finite"),
        });
    }
    let tree: Vec<[usize; 2]> = match overlay {
        GraphOverlay::Plain | GraphOverlay::Colouring(_) => Vec::new(),
        GraphOverlay::Tree(edges) => {
            check_indices("tree", edges.iter().flatten().copied(), n)?;
            edges.to_vec()
        }
        GraphOverlay::Search { search, start } => {
            if search.parent.len() != n || start >= n {
                return Err(Error::InvalidParameter {
                    name: "search",
                    reason: format!(
                        "{} parents and start {start} for {n} vertices",
                        search.parent.len()
                    ),
                });
            }
            check_indices("search", search.parent.iter().flatten().copied(), n)?;
            (0..n)
                .filter_map(|v| search.parent[v].map(|p| [p, v]))
                .collect()
        }
    };
    if let GraphOverlay::Colouring(c) = overlay {
        if c.colour.len() != n || c.colour.iter().any(|&k| k >= c.count) {
            return Err(Error::InvalidParameter {
                name: "colouring",
                reason: format!(
                    "{} colours for {n} vertices, each below the count {}",
                    c.colour.len(),
                    c.count
                ),
            });
        }
    }
    let bounds = bounds_of(positions);
    let title = match overlay {
        GraphOverlay::Plain => format!("graph of {n} vertices and {} edges", g.edge_count()),
        GraphOverlay::Colouring(c) => format!(
            "colouring of a graph of {n} vertices with {} colours",
            c.count
        ),
        GraphOverlay::Tree(_) => format!(
            "spanning forest of a graph of {n} vertices: {} edges",
            tree.len()
        ),
        GraphOverlay::Search { search, start } => format!(
            "search tree from vertex {start}: {} of {n} vertices reached",
            search.order.len()
        ),
    };
    let mut picture = Picture::new(&title, bounds, n);
    picture.segments(
        &Layer::new("edges", Role::Triangulation).legend(format!("{} edges", g.edge_count())),
        g.edges().map(|e| e.map(|v| positions[v])),
    );
    picture.segments(
        &Layer::new("tree", Role::Result).legend(format!("{} tree edges", tree.len())),
        tree.iter().map(|e| e.map(|v| positions[v])),
    );
    match overlay {
        GraphOverlay::Colouring(c) => {
            let mut classes = vec![Vec::new(); c.count];
            for (v, &k) in c.colour.iter().enumerate() {
                classes[k].push(positions[v]);
            }
            for (k, class) in classes.iter().enumerate() {
                picture.filled_points(
                    &Layer::new(&format!("colour-{k}"), Role::Input)
                        .legend(format!("colour {k} ({} vertices)", class.len())),
                    CLASS_COLOURS[k % CLASS_COLOURS.len()],
                    class.iter().copied(),
                );
            }
        }
        _ => {
            picture.points(
                &Layer::new("vertices", Role::Input).legend(format!("{n} vertices")),
                positions.iter().copied(),
            );
        }
    }
    if let GraphOverlay::Search { start, .. } = overlay {
        picture.rings(
            &Layer::new("start", Role::Highlight).legend("start"),
            [positions[start]],
        );
    }
    picture.labels(
        &Layer::new("labels", Role::Label).legend("vertex"),
        positions
            .iter()
            .enumerate()
            .map(|(v, &p)| (p, v.to_string())),
    );
    Ok(picture)
}
