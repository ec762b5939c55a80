//! Step pages of the graph algorithms the course traces: breadth- and depth-first search,
//! the course's greedy colouring, and Prim's and Kruskal's spanning trees; one picture per
//! frame of the algorithm's own trace.
//!
//! Every picture of a page is drawn by the same body as the whole-result picture
//! ([`graph`](super::graph)), from a partial state: the vertices where the caller puts them
//! (the input's coordinates or [`circle_layout`](super::circle_layout)), the graph's edges
//! grey, the tree so far blue, the vertex or edge the step is about in vermillion, a rejected
//! edge or the neighbours that ruled colours out as orange dashes. The counts under each
//! picture are the operations the run had made by that step.

use super::graphs::{check_positions, scene_picture, Fill, Scene};
use super::hull_steps::list;
use super::steps::{StepFrame, StepPage};
use super::svg::{Layer, Picture, Role};
use super::{check_indices, value};
use crate::error::{Error, Result};
use crate::geometry::{Point2, WideFloat};
use crate::graph::{
    CourseColouringStep, Graph, KruskalStep, PrimStep, SearchAlgorithm, SearchStep, WeightedGraph,
};
use crate::trace::Frame;

/// The step page of a breadth- or depth-first search from its trace
/// ([`search_trace`](crate::graph::search_trace)): after each step, the vertices reached
/// (filled), the list Q (ringed), the tree edges so far, and the vertex whose turn it is; the
/// last frame is the search tree.
///
/// # Errors
/// [`Error::InvalidParameter`] named `"positions"` unless there is one finite position per
/// vertex, `"trace"` if a frame names a vertex outside the graph;
/// [`Error::LimitExceeded`] beyond
/// [`STEP_PAGE_MAX_FRAMES`](crate::limits::STEP_PAGE_MAX_FRAMES) frames.
///
/// # Complexity
/// O(f·(n + m)) time and output for f frames, n vertices and m edges.
///
/// ```
/// use compgeo::draw::{circle_layout, search_steps};
/// use compgeo::graph::{search_trace, Graph, SearchAlgorithm};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0]])?;
/// let trace = search_trace(&g, 0, SearchAlgorithm::Bfs)?;
/// let page = search_steps(&g, &circle_layout(4), SearchAlgorithm::Bfs, &trace)?;
/// assert_eq!(page.frames().len(), trace.len()); // 2 × 4 rows and the result
/// assert_eq!(page.frames()[1].kind, "add");
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn search_steps(
    g: &Graph,
    positions: &[Point2],
    algorithm: SearchAlgorithm,
    trace: &[Frame<SearchStep>],
) -> Result<StepPage> {
    let n = g.vertex_count();
    check_positions(n, positions)?;
    let edges: Vec<[usize; 2]> = g.edges().collect();
    let (name, list_name, end, about) = match algorithm {
        SearchAlgorithm::Bfs => (
            "Breadth-first search",
            "queue",
            "first",
            "Breadth-first search [RD, §2.1]: Q starts with the start vertex; while Q is not \
             empty, look at its first vertex x: if x has a neighbour not reached yet, append the \
             smallest such neighbour to Q, else remove x. The tree edges join each vertex to \
             the x that added it.",
        ),
        SearchAlgorithm::Dfs => (
            "Depth-first search",
            "stack",
            "last",
            "Depth-first search [RD, §2.1]: Q starts with the start vertex; while Q is not \
             empty, look at its last vertex x: if x has a neighbour not reached yet, push the \
             smallest such neighbour on Q, else pop x. The tree edges join each vertex to the \
             x that pushed it.",
        ),
    };
    let title = format!("{name} on a graph of {n} vertices");
    let mut page = StepPage::new(&title).about(about);
    let list_layer =
        || Layer::new(list_name, Role::Alternative.solid()).legend(format!("Q (a {list_name})"));
    let (mut tree, mut reached) = (Vec::new(), Vec::new());
    for frame in trace {
        let mut scene = Scene::default();
        let (kind, caption) = match &frame.step {
            SearchStep::Add {
                vertex,
                parent,
                list: q,
            } => {
                check_indices("trace", q.iter().chain(parent).chain([vertex]).copied(), n)?;
                reached.push(*vertex);
                scene.rings.push((list_layer(), q.clone()));
                let caption = match parent {
                    None => format!("Start at vertex {vertex}: Q = {}.", list(q)),
                    Some(x) => {
                        tree.push([*x, *vertex]);
                        scene.over.push((
                            Layer::new("added", Role::Highlight).legend("new tree edge"),
                            vec![[*x, *vertex]],
                        ));
                        scene.rings.push((current(), vec![*x]));
                        format!(
                            "Q's {end} vertex {x} has a neighbour not reached yet: add \
                             {vertex}. Q = {}.",
                            list(q)
                        )
                    }
                };
                ("add", caption)
            }
            SearchStep::Remove { vertex, list: q } => {
                check_indices("trace", q.iter().chain([vertex]).copied(), n)?;
                scene.rings.push((list_layer(), q.clone()));
                scene.rings.push((current(), vec![*vertex]));
                let q = if q.is_empty() {
                    "Q is empty".to_string()
                } else {
                    format!("Q = {}", list(q))
                };
                (
                    "remove",
                    format!("Every neighbour of {vertex} is reached: remove it. {q}."),
                )
            }
            SearchStep::Done { search } => {
                if search.parent.len() != n {
                    return Err(Error::InvalidParameter {
                        name: "trace",
                        reason: format!("{} parents for {n} vertices", search.parent.len()),
                    });
                }
                let parents = search.parent.iter().flatten();
                check_indices("trace", search.order.iter().chain(parents).copied(), n)?;
                tree = (0..n)
                    .filter_map(|v| search.parent[v].map(|p| [p, v]))
                    .collect();
                reached.clone_from(&search.order);
                if let Some(&start) = search.order.first() {
                    scene.rings.push((
                        Layer::new("start", Role::Highlight).legend("start"),
                        vec![start],
                    ));
                }
                (
                    "done",
                    format!(
                        "Q is empty: the search reached {} of {n} vertices, in the order {}; \
                         the tree has {} edges.",
                        search.order.len(),
                        list(&search.order),
                        tree.len()
                    ),
                )
            }
        };
        scene.tree.clone_from(&tree);
        scene.fill = Fill::Reached(reached.clone());
        let picture = scene_picture(&title, positions, &edges, &scene);
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The ring of the vertex a step is about.
fn current() -> Layer {
    Layer::new("current", Role::Highlight).legend("its turn")
}

/// The step page of the course's greedy colouring from its trace
/// ([`course_greedy_colouring_trace`](crate::graph::course_greedy_colouring_trace)): after
/// each step, the vertices coloured so far filled with their colours, the vertex just
/// coloured ringed, and dashed lines to its earlier neighbours, whose colours it could not
/// take.
///
/// # Errors
/// As [`search_steps`], and `"trace"` if a frame's colouring is not one per vertex.
///
/// # Complexity
/// O(f·(n + m)) time and output for f frames, n vertices and m edges.
///
/// ```
/// use compgeo::draw::{circle_layout, colouring_steps};
/// use compgeo::graph::{course_greedy_colouring_trace, Graph};
///
/// let g = Graph::from_edges(5, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])?; // C₅
/// let trace = course_greedy_colouring_trace(&g, &[0, 1, 2, 3, 4])?;
/// let page = colouring_steps(&g, &circle_layout(5), &trace)?;
/// assert_eq!(page.frames().len(), 6); // a frame per vertex and the result
/// assert!(page.frames()[4].caption.contains("gets colour 2"));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn colouring_steps(
    g: &Graph,
    positions: &[Point2],
    trace: &[Frame<CourseColouringStep>],
) -> Result<StepPage> {
    let n = g.vertex_count();
    check_positions(n, positions)?;
    let edges: Vec<[usize; 2]> = g.edges().collect();
    let title = format!("The course's greedy colouring of a graph of {n} vertices");
    let mut page = StepPage::new(&title).about(
        "Greedy colouring [RD, §2.1]: take the vertices in order; for each, ask about every \
         earlier vertex whether it is adjacent, collect the colours of those that are (S), and \
         give the vertex the first colour not in S. Colours are numbered from 0.",
    );
    for (i, frame) in trace.iter().enumerate() {
        let mut scene = Scene::default();
        let (kind, caption) = match &frame.step {
            CourseColouringStep::Coloured {
                vertex,
                colour,
                adjacent,
                colours,
            } => {
                check_colouring_of(n, colours.len())?;
                check_colours(n, colours.iter().flatten().copied().chain([*colour]))?;
                check_indices("trace", adjacent.iter().chain([vertex]).copied(), n)?;
                let count = colours.iter().flatten().map(|&k| k + 1).max().unwrap_or(0);
                scene.fill = Fill::Colours {
                    colour: colours.clone(),
                    count,
                };
                scene.over.push((
                    Layer::new("ruled-out", Role::Construction)
                        .legend("earlier neighbours: colours ruled out"),
                    adjacent.iter().map(|&u| [*vertex, u]).collect(),
                ));
                scene.rings.push((current(), vec![*vertex]));
                let mut taken: Vec<usize> = adjacent.iter().filter_map(|&u| colours[u]).collect();
                taken.sort_unstable();
                taken.dedup();
                let asked = match i {
                    0 => "the first vertex, nothing to ask".to_string(),
                    1 => "asked about 1 earlier vertex".to_string(),
                    i => format!("asked about {i} earlier vertices"),
                };
                let found = match adjacent.len() {
                    0 => "none is adjacent".to_string(),
                    k => format!(
                        "{k} adjacent, {}, with the colours S = {{{}}}",
                        list(adjacent),
                        taken
                            .iter()
                            .map(usize::to_string)
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                };
                let caption = if i == 0 {
                    format!("Vertex {vertex}, {asked}: it gets colour {colour}.")
                } else {
                    format!("Vertex {vertex}, {asked}: {found}, so it gets colour {colour}.")
                };
                ("colour", caption)
            }
            CourseColouringStep::Done { colouring } => {
                check_colouring_of(n, colouring.colour.len())?;
                check_colours(n, colouring.colour.iter().copied())?;
                let classes = colouring.colour.iter().map(|&k| k + 1).max();
                scene.fill = Fill::Colours {
                    colour: colouring.colour.iter().map(|&k| Some(k)).collect(),
                    count: colouring.count.max(classes.unwrap_or(0)),
                };
                let colours = match colouring.count {
                    1 => "1 colour".to_string(),
                    k => format!("{k} colours"),
                };
                ("done", format!("Every vertex is coloured: {colours}."))
            }
        };
        let picture = scene_picture(&title, positions, &edges, &scene);
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// Checks that a trace's colouring has one entry per vertex.
fn check_colouring_of(n: usize, entries: usize) -> Result<()> {
    if entries == n {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            name: "trace",
            reason: format!("a colouring of {entries} vertices for {n}"),
        })
    }
}

/// Checks that a trace's colours are below `n` (a colouring of n vertices needs at most n).
fn check_colours(n: usize, colours: impl IntoIterator<Item = usize>) -> Result<()> {
    match colours.into_iter().find(|&k| k >= n) {
        None => Ok(()),
        Some(k) => Err(Error::InvalidParameter {
            name: "trace",
            reason: format!("colour {k} for a graph of {n} vertices"),
        }),
    }
}

/// The step page of Prim's algorithm from its trace ([`prim_trace`](crate::graph::prim_trace)):
/// after each step, the tree so far and its vertices, and the edge taken out of the heap,
/// accepted (vermillion) or rejected (orange, dashed); every edge labelled with its weight.
///
/// # Errors
/// As [`search_steps`], and `"trace"` if a frame names an edge outside the graph.
///
/// # Complexity
/// O(f·(n + m)) time and output for f frames, n vertices and m edges.
///
/// ```
/// use compgeo::draw::{circle_layout, prim_steps};
/// use compgeo::graph::{prim_trace, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [2, 0]], &[1.0, 2.0, 3.0])?;
/// let trace = prim_trace(&g)?;
/// let page = prim_steps(&g, &circle_layout(3), &trace)?;
/// let kinds: Vec<&str> = page.frames().iter().map(|f| f.kind).collect();
/// assert_eq!(kinds, ["root", "accept", "accept", "reject", "done"]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn prim_steps(
    g: &WeightedGraph,
    positions: &[Point2],
    trace: &[Frame<PrimStep>],
) -> Result<StepPage> {
    let n = g.vertex_count();
    check_positions(n, positions)?;
    let title = format!("Prim's algorithm on a graph of {n} vertices");
    let mut page = StepPage::new(&title).about(
        "The course's greedy tree (Prim's algorithm) [RD, §2.1]: start at an end of the \
         lightest edge; then take the lightest edge that brings a new vertex into the tree, \
         until none does (a new tree starts in each further component). The edges leaving \
         the tree wait in a heap; an edge whose far end joined the tree meanwhile is rejected \
         when it comes out.",
    );
    let weighted = Weighted::of(g);
    let mut in_tree = vec![false; n];
    let (mut tree, mut roots) = (Vec::new(), 0);
    for frame in trace {
        let mut scene = weighted.scene();
        let (kind, caption) = match &frame.step {
            PrimStep::Root { vertex } => {
                check_indices("trace", [*vertex], n)?;
                in_tree[*vertex] = true;
                scene.rings.push((current(), vec![*vertex]));
                roots += 1;
                let which = match roots {
                    1 if weighted.edges.is_empty() => "the first vertex",
                    1 => "an end of the lightest edge",
                    _ => "the smallest vertex of a further component",
                };
                (
                    "root",
                    format!("A tree starts at vertex {vertex}, {which}."),
                )
            }
            PrimStep::Edge {
                edge,
                to,
                accepted,
                tree: so_far,
            } => {
                weighted.check(so_far.iter().chain([edge]))?;
                check_indices("trace", [*to], n)?;
                tree = weighted.pairs(so_far);
                let [u, v] = g.endpoints(*edge);
                if *accepted {
                    in_tree[*to] = true;
                    scene.over.push((accepted_layer(), vec![[u, v]]));
                } else {
                    scene.over.push((rejected_layer(), vec![[u, v]]));
                }
                let about = weighted.edge(*edge);
                if *accepted {
                    (
                        "accept",
                        format!(
                            "The lightest edge left in the heap, {about}, brings vertex {to} \
                             into the tree."
                        ),
                    )
                } else {
                    (
                        "reject",
                        format!(
                            "The lightest edge left in the heap, {about}: vertex {to} is \
                             already in the tree, so it is rejected."
                        ),
                    )
                }
            }
            PrimStep::Done { forest } => {
                weighted.check(&forest.edges)?;
                tree = weighted.pairs(&forest.edges);
                (
                    "done",
                    forest_caption(n, forest.components, tree.len(), forest.weight),
                )
            }
        };
        scene.tree.clone_from(&tree);
        let reached = (0..n).filter(|&v| in_tree[v]).collect();
        scene.fill = Fill::Reached(reached);
        let picture = weighted.picture(&title, positions, &scene);
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The step page of Kruskal's algorithm from its trace
/// ([`kruskal_trace`](crate::graph::kruskal_trace)): the edges in the order of the sort, then
/// after each edge examined the forest so far and the edge, accepted (it joins two trees,
/// vermillion) or rejected (it would close a cycle, orange, dashed); every edge labelled with
/// its weight.
///
/// # Errors
/// As [`prim_steps`].
///
/// # Complexity
/// O(f·(n + m)) time and output for f frames, n vertices and m edges.
///
/// ```
/// use compgeo::draw::{circle_layout, kruskal_steps};
/// use compgeo::graph::{kruskal_trace, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [2, 0]], &[1.0, 2.0, 3.0])?;
/// let trace = kruskal_trace(&g)?;
/// let page = kruskal_steps(&g, &circle_layout(3), &trace)?;
/// let kinds: Vec<&str> = page.frames().iter().map(|f| f.kind).collect();
/// assert_eq!(kinds, ["sorted", "accept", "accept", "done"]); // two edges span three vertices
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn kruskal_steps(
    g: &WeightedGraph,
    positions: &[Point2],
    trace: &[Frame<KruskalStep>],
) -> Result<StepPage> {
    let n = g.vertex_count();
    check_positions(n, positions)?;
    let title = format!("Kruskal's algorithm on a graph of {n} vertices");
    let mut page = StepPage::new(&title).about(
        "Kruskal's algorithm [RD, §2.1]: sort the edges by weight, then take each edge in \
         turn: it joins the forest if its ends lie in different trees, and is rejected if \
         they lie in the same tree (it would close a cycle). It stops when n − 1 edges are in.",
    );
    let weighted = Weighted::of(g);
    let mut tree = Vec::new();
    for frame in trace {
        let mut scene = weighted.scene();
        let (kind, caption) = match &frame.step {
            KruskalStep::Sorted { order } => {
                weighted.check(order)?;
                let shown: Vec<String> = order.iter().take(8).map(|&e| weighted.edge(e)).collect();
                let more = if order.len() > 8 { ", …" } else { "" };
                (
                    "sorted",
                    format!(
                        "The {} edges sorted by weight: {}{more}.",
                        order.len(),
                        shown.join(", ")
                    ),
                )
            }
            KruskalStep::Edge {
                edge,
                accepted,
                forest,
            } => {
                weighted.check(forest.iter().chain([edge]))?;
                tree = weighted.pairs(forest);
                let [u, v] = g.endpoints(*edge);
                let about = weighted.edge(*edge);
                if *accepted {
                    scene.over.push((accepted_layer(), vec![[u, v]]));
                    (
                        "accept",
                        format!("The next edge, {about}, joins two trees: it is accepted."),
                    )
                } else {
                    scene.over.push((rejected_layer(), vec![[u, v]]));
                    (
                        "reject",
                        format!(
                            "The next edge, {about}: {u} and {v} are already in one tree, so \
                             it would close a cycle and is rejected."
                        ),
                    )
                }
            }
            KruskalStep::Done { forest } => {
                weighted.check(&forest.edges)?;
                tree = weighted.pairs(&forest.edges);
                (
                    "done",
                    forest_caption(n, forest.components, tree.len(), forest.weight),
                )
            }
        };
        scene.tree.clone_from(&tree);
        let picture = weighted.picture(&title, positions, &scene);
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The layer of an accepted edge.
fn accepted_layer() -> Layer {
    Layer::new("accepted", Role::Highlight).legend("accepted")
}

/// The layer of a rejected edge.
fn rejected_layer() -> Layer {
    Layer::new("rejected", Role::Construction).legend("rejected")
}

/// The caption of a spanning forest.
fn forest_caption(n: usize, components: usize, edges: usize, weight: WideFloat) -> String {
    let what = if components <= 1 {
        "The minimum spanning tree".to_string()
    } else {
        format!("A minimum spanning forest of {components} trees")
    };
    format!(
        "{what}: {edges} edges joining {n} vertices, total weight {}.",
        value(weight)
    )
}

/// A weighted graph as its pictures show it: the edges that are not loops, each labelled
/// with its weight.
struct Weighted<'a> {
    g: &'a WeightedGraph,
    edges: Vec<[usize; 2]>,
    labels: Vec<([usize; 2], String)>,
}

impl<'a> Weighted<'a> {
    fn of(g: &'a WeightedGraph) -> Weighted<'a> {
        let shown: Vec<usize> = (0..g.edge_count())
            .filter(|&e| g.endpoints(e)[0] != g.endpoints(e)[1])
            .collect();
        Weighted {
            g,
            edges: shown.iter().map(|&e| g.endpoints(e)).collect(),
            labels: shown
                .iter()
                .map(|&e| (g.endpoints(e), value(WideFloat::from(g.weight(e)))))
                .collect(),
        }
    }

    /// A scene with the weights written on the edges.
    fn scene(&self) -> Scene {
        Scene {
            edge_labels: self.labels.clone(),
            ..Scene::default()
        }
    }

    /// Checks that every edge index is one of the graph's.
    fn check<'e>(&self, edges: impl IntoIterator<Item = &'e usize>) -> Result<()> {
        let m = self.g.edge_count();
        match edges.into_iter().find(|&&e| e >= m) {
            None => Ok(()),
            Some(e) => Err(Error::InvalidParameter {
                name: "trace",
                reason: format!("edge {e} is out of range for {m} edges"),
            }),
        }
    }

    /// The ends of each edge.
    fn pairs(&self, edges: &[usize]) -> Vec<[usize; 2]> {
        edges.iter().map(|&e| self.g.endpoints(e)).collect()
    }

    /// An edge for a caption: its ends and weight.
    fn edge(&self, e: usize) -> String {
        let [u, v] = self.g.endpoints(e);
        format!(
            "{u}–{v} (weight {})",
            value(WideFloat::from(self.g.weight(e)))
        )
    }

    fn picture(&self, title: &str, positions: &[Point2], scene: &Scene) -> Picture {
        scene_picture(title, positions, &self.edges, scene)
    }
}
