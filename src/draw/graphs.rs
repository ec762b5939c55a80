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
    check_positions(n, positions)?;
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
    let mut scene = Scene {
        tree,
        ..Scene::default()
    };
    match overlay {
        GraphOverlay::Colouring(c) => {
            scene.fill = Fill::Colours {
                colour: c.colour.iter().map(|&k| Some(k)).collect(),
                count: c.count,
            }
        }
        GraphOverlay::Search { start, .. } => scene.rings.push((
            Layer::new("start", Role::Highlight).legend("start"),
            vec![start],
        )),
        GraphOverlay::Plain | GraphOverlay::Tree(_) => {}
    }
    let edges: Vec<[usize; 2]> = g.edges().collect();
    Ok(scene_picture(&title, positions, &edges, &scene))
}

/// Checks that there is one finite position per vertex of a graph of `n` vertices.
///
/// # Errors
/// [`Error::InvalidParameter`] named `"positions"`.
pub(super) fn check_positions(n: usize, positions: &[Point2]) -> Result<()> {
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
    Ok(())
}

/// How the vertices of a graph picture are drawn.
#[derive(Debug, Clone, Default)]
pub(super) enum Fill {
    /// Every vertex a dot (layer `vertices`).
    #[default]
    Plain,
    /// The coloured vertices filled with their class's colour (layers `colour-k` for k below
    /// `count`), the others dots (layer `vertices`, drawn only if there are some).
    Colours {
        /// Each vertex's colour, `None` for those not coloured (yet).
        colour: Vec<Option<usize>>,
        /// The number of classes drawn.
        count: usize,
    },
    /// Every vertex a dot, and these vertices filled in the result's colour (layer
    /// `reached`).
    Reached(Vec<usize>),
}

/// What a graph picture draws over the graph's edges: the state of a result ([`graph`]) or
/// of one step of an algorithm (the step pages), so both are drawn by [`scene_picture`].
#[derive(Debug, Clone, Default)]
pub(super) struct Scene {
    /// Edges drawn over the graph's edges and under the tree, each layer with its pairs of
    /// vertices.
    pub under: Vec<(Layer, Vec<[usize; 2]>)>,
    /// The tree or forest so far (layer `tree`, blue).
    pub tree: Vec<[usize; 2]>,
    /// Edges drawn over the tree.
    pub over: Vec<(Layer, Vec<[usize; 2]>)>,
    /// How the vertices are drawn.
    pub fill: Fill,
    /// Vertices ringed, each layer with its vertices.
    pub rings: Vec<(Layer, Vec<usize>)>,
    /// A text at the middle of each of these edges (layer `weights`), after the vertices'
    /// numbers.
    pub edge_labels: Vec<([usize; 2], String)>,
}

/// The picture of a graph of `positions.len()` vertices with `edges` at `positions` (checked
/// by the caller, as every index in `scene`), and the `scene` over it: the one body of every
/// graph picture, whole or step by step.
pub(super) fn scene_picture(
    title: &str,
    positions: &[Point2],
    edges: &[[usize; 2]],
    scene: &Scene,
) -> Picture {
    let n = positions.len();
    let at = |pairs: &[[usize; 2]]| -> Vec<[Point2; 2]> {
        pairs.iter().map(|e| e.map(|v| positions[v])).collect()
    };
    let mut picture = Picture::new(title, bounds_of(positions), n);
    picture.segments(
        &Layer::new("edges", Role::Triangulation).legend(format!("{} edges", edges.len())),
        at(edges),
    );
    for (layer, pairs) in &scene.under {
        picture.segments(layer, at(pairs));
    }
    picture.segments(
        &Layer::new("tree", Role::Result).legend(format!("{} tree edges", scene.tree.len())),
        at(&scene.tree),
    );
    for (layer, pairs) in &scene.over {
        picture.segments(layer, at(pairs));
    }
    match &scene.fill {
        Fill::Plain | Fill::Reached(_) => {
            picture.points(
                &Layer::new("vertices", Role::Input).legend(format!("{n} vertices")),
                positions.iter().copied(),
            );
        }
        Fill::Colours { colour, count } => {
            let mut classes = vec![Vec::new(); *count];
            let mut uncoloured = Vec::new();
            for (v, k) in colour.iter().enumerate() {
                match k {
                    Some(k) => classes[*k].push(positions[v]),
                    None => uncoloured.push(positions[v]),
                }
            }
            if !uncoloured.is_empty() {
                picture.points(
                    &Layer::new("vertices", Role::Input)
                        .legend(format!("{} not coloured yet", uncoloured.len())),
                    uncoloured,
                );
            }
            for (k, class) in classes.iter().enumerate() {
                picture.filled_points(
                    &Layer::new(&format!("colour-{k}"), Role::Input).legend(match class.len() {
                        1 => format!("colour {k} (1 vertex)"),
                        size => format!("colour {k} ({size} vertices)"),
                    }),
                    CLASS_COLOURS[k % CLASS_COLOURS.len()],
                    class.iter().copied(),
                );
            }
        }
    }
    if let Fill::Reached(reached) = &scene.fill {
        picture.filled_points(
            &Layer::new("reached", Role::Result).legend(format!("{} reached", reached.len())),
            Role::Result.colour(),
            reached.iter().map(|&v| positions[v]),
        );
    }
    for (layer, vertices) in &scene.rings {
        picture.rings(layer, vertices.iter().map(|&v| positions[v]));
    }
    picture.labels(
        &Layer::new("labels", Role::Label).legend("vertex"),
        positions
            .iter()
            .enumerate()
            .map(|(v, &p)| (p, v.to_string())),
    );
    if !scene.edge_labels.is_empty() {
        picture.labels(
            &Layer::new("weights", Role::Label).legend("edge weight"),
            scene.edge_labels.iter().map(|([u, v], text)| {
                let (p, q) = (positions[*u], positions[*v]);
                (
                    Point2::new(0.5 * p.x + 0.5 * q.x, 0.5 * p.y + 0.5 * q.y),
                    text.clone(),
                )
            }),
        );
    }
    picture
}
