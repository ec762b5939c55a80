//! Breadth-first and depth-first search from a start vertex: visit order, the spanning tree
//! as a parent array, connected components, and the course's add/remove trace of the list Q
//! (the [`trace`](crate::trace) frames of the searches' own run).
//!
//! Both searches follow the course's scheme ([RD, §2.1] "Algoritmos de
//! búsqueda"): keep a list Q holding the start; look at the first (BFS, a queue) or the last
//! (DFS, a stack) vertex x of Q; if x is adjacent to a new vertex y, append y, else remove x.
//! "A new vertex" is the smallest unvisited neighbour, since neighbour lists are ascending.
//! Each vertex keeps a cursor into its neighbour list, so every edge is looked at twice in
//! total (once from each end) and the searches run in O(n + m) without recursion.
//!
//! The tests check that every vertex of the start's component is visited exactly once, that
//! the parent array is a tree of graph edges rooted at the start, the course's two tables, and
//! that a trace has 2·n_c + 1 frames ending with the plain search's result and the counted
//! run's counts.

use super::graph::Graph;
use crate::complexity::{algorithm_family, on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::{Result, Violation};
use crate::trace::{record, Frame, NoObserver, Observer, TraceSize};
use std::fmt::Write;

/// Breadth-first search's [`Declaration`]: its name, bounds, counts, source and claims.
const BFS: Declaration = Declaration {
    problem: "search",
    name: "bfs",
    function: "graph::bfs",
    file: "src/graph/traverse.rs",
    summary: "breadth-first: Q is a queue",
    time: "O(n + m)",
    space: "O(n)",
    operation: Some(Operation::EdgeVisits),
    counts: "exactly 2m edge visits on a connected graph",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::NPlusM, Operation::EdgeVisits)],
};

/// Depth-first search's [`Declaration`]: its name, bounds, counts, source and claims.
const DFS: Declaration = Declaration {
    problem: "search",
    name: "dfs",
    function: "graph::dfs",
    file: "src/graph/traverse.rs",
    summary: "depth-first: Q is a stack",
    time: "O(n + m)",
    space: "O(n)",
    operation: Some(Operation::EdgeVisits),
    counts: "exactly 2m edge visits on a connected graph",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::NPlusM, Operation::EdgeVisits)],
};

algorithm_family! {
    /// The two searches, by the list discipline of Q ([`search`], [`search_trace`]).
    ///
    /// ```
    /// use compgeo::graph::SearchAlgorithm;
    ///
    /// assert_eq!("dfs".parse::<SearchAlgorithm>()?, SearchAlgorithm::Dfs);
    /// assert_eq!(SearchAlgorithm::Bfs.declaration().time, "O(n + m)");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum SearchAlgorithm ("search algorithm") {
        /// Breadth-first ([`bfs`], the course's B.E.A.): Q is a queue, look at its first
        /// vertex.
        Bfs = BFS => bfs_with,
        /// Depth-first ([`dfs`], the course's B.E.P.): Q is a stack, look at its last
        /// vertex.
        Dfs = DFS => dfs_with,
    }
    fn run_with[C: Counter](g: &Graph, start: usize, c: &mut C) -> Result<Search>;
}

pub use crate::limits::TRACE_MAX_VERTICES;

/// The search of `g` from `start` by `algorithm`: the same as calling [`bfs`] or [`dfs`].
///
/// # Errors
/// [`Error::NoSuchVertex`](crate::Error::NoSuchVertex) if `start` is not a vertex of `g`.
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{search, Graph, SearchAlgorithm};
///
/// let g = Graph::from_edges(4, &[[0, 1], [0, 2], [1, 3]])?;
/// assert_eq!(search(&g, 0, SearchAlgorithm::Bfs)?.order, [0, 1, 2, 3]);
/// assert_eq!(search(&g, 0, SearchAlgorithm::Dfs)?.order, [0, 1, 3, 2]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn search(g: &Graph, start: usize, algorithm: SearchAlgorithm) -> Result<Search> {
    search_with(g, start, algorithm, &mut NoCount)
}

/// [`search`], recording the searched vertices and edges in `counter`.
///
/// # Errors
/// [`Error::NoSuchVertex`](crate::Error::NoSuchVertex) if `start` is not a vertex of `g`.
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
pub fn search_with<C: Counter>(
    g: &Graph,
    start: usize,
    algorithm: SearchAlgorithm,
    counter: &mut C,
) -> Result<Search> {
    algorithm.run_with(g, start, counter)
}

/// The result of a search from one start vertex.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Search {
    /// The vertices in the order the search reached them, the start first. Exactly the
    /// start's connected component.
    pub order: Vec<usize>,
    /// `parent[v]` is the vertex from which the search reached `v`: the spanning tree of the
    /// component, rooted at the start. `None` for the start and for vertices not reached.
    pub parent: Vec<Option<usize>>,
}

/// A step of a search, as [`search_trace`] records it: the rows of the course's table
/// (a vertex added to Q or removed from it, with Q after the step), then the result.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SearchStep {
    /// `vertex` was appended to Q (the course's "Añadir").
    Add {
        /// The vertex added: the search reached it.
        vertex: usize,
        /// The vertex whose neighbour it is, the one Q was looked at for (its parent in the
        /// search tree); `None` for the start.
        parent: Option<usize>,
        /// Q after the step, first element first.
        list: Vec<usize>,
    },
    /// `vertex` left Q: it has no unreached neighbour left (the course's "Quitar").
    Remove {
        /// The vertex removed.
        vertex: usize,
        /// Q after the step, first element first.
        list: Vec<usize>,
    },
    /// Q is empty: the result of [`bfs`] or [`dfs`].
    Done {
        /// The search, as [`bfs`] or [`dfs`] returns it.
        search: Search,
    },
}

impl TraceSize for SearchStep {
    fn entries(&self) -> usize {
        match self {
            SearchStep::Add { list, .. } => 2 + list.len(),
            SearchStep::Remove { list, .. } => 1 + list.len(),
            SearchStep::Done { search } => search.order.len() + search.parent.len(),
        }
    }
}

/// The connected components of a graph.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Components {
    /// `label[v]` is the component of `v`, numbered `0..count` in order of their smallest
    /// vertex.
    pub label: Vec<usize>,
    /// The number of components (0 for the empty graph).
    pub count: usize,
}

/// Breadth-first search from `start`; see [`bfs_with`].
///
/// # Errors
/// [`Error::NoSuchVertex`](crate::Error::NoSuchVertex) if `start >= n` (every start is missing from the empty graph).
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{bfs, Graph};
///
/// // The path 0 - 1 - 2 plus the edge 0 - 3.
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [0, 3]])?;
/// let s = bfs(&g, 0)?;
/// assert_eq!(s.order, [0, 1, 3, 2]);
/// assert_eq!(s.parent, [None, Some(0), Some(1), Some(0)]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bfs(g: &Graph, start: usize) -> Result<Search> {
    bfs_with(g, start, &mut NoCount)
}

/// Breadth-first search from `start`, counting its work.
///
/// The idea: the course's B.E.A. ([RD, §2.1] "Algoritmos de búsqueda"):
/// Q is a queue; while it is not empty, its first vertex x adds its new neighbours one by one
/// in ascending order, then leaves Q. The visit order is the order of arrival in Q, and each
/// vertex's parent is the x that added it, so depths in the tree are graph distances from the
/// start.
///
/// # Errors
/// [`Error::NoSuchVertex`](crate::Error::NoSuchVertex) if `start >= n`.
///
/// # Complexity
/// O(n + m) time for n vertices and m edges (each vertex enters Q once, each edge is looked
/// at once from each end); O(n) auxiliary space.
///
/// # Counts
/// One `vertex_visit` per vertex taken from Q and one `edge_visit` per neighbour looked at:
/// on a component with n_c vertices and m_c edges, exactly n_c and 2·m_c.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{bfs_with, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 0]])?;
/// let mut c = Counts::default();
/// let s = bfs_with(&g, 2, &mut c)?;
/// assert_eq!(s.order, [2, 0, 1]);
/// assert_eq!((c.vertex_visits, c.edge_visits), (3, 6));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bfs_with<C: Counter>(g: &Graph, start: usize, c: &mut C) -> Result<Search> {
    g.check_vertex(start)?;
    Ok(bfs_observed(g, start, c, &mut NoObserver))
}

/// Depth-first search from `start`; see [`dfs_with`].
///
/// # Errors
/// [`Error::NoSuchVertex`](crate::Error::NoSuchVertex) if `start >= n`.
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{dfs, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [0, 3]])?;
/// let s = dfs(&g, 0)?;
/// assert_eq!(s.order, [0, 1, 2, 3]);
/// assert_eq!(s.parent, [None, Some(0), Some(1), Some(0)]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dfs(g: &Graph, start: usize) -> Result<Search> {
    dfs_with(g, start, &mut NoCount)
}

/// Depth-first search from `start`, counting its work.
///
/// The idea: the course's B.E.P. ([RD, §2.1] "Algoritmos de búsqueda"):
/// Q is a stack; while it is not empty, look at its last vertex x: if x has a new neighbour,
/// push the smallest one, else pop x. Each stacked vertex keeps a cursor into its neighbour
/// list, so no neighbour is looked at twice from the same vertex. Iterative: the depth of the
/// tree is limited by memory, not by the call stack.
///
/// # Errors
/// [`Error::NoSuchVertex`](crate::Error::NoSuchVertex) if `start >= n`.
///
/// # Complexity
/// O(n + m) time for n vertices and m edges; O(n) auxiliary space (the stack).
///
/// # Counts
/// One `vertex_visit` per vertex pushed and one `edge_visit` per neighbour looked at: on a
/// component with n_c vertices and m_c edges, exactly n_c and 2·m_c.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{dfs_with, Graph};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2], [2, 0]])?;
/// let mut c = Counts::default();
/// let s = dfs_with(&g, 0, &mut c)?;
/// assert_eq!(s.parent, [None, Some(0), Some(1)]);
/// assert_eq!((c.vertex_visits, c.edge_visits), (3, 6));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dfs_with<C: Counter>(g: &Graph, start: usize, c: &mut C) -> Result<Search> {
    g.check_vertex(start)?;
    Ok(dfs_observed(g, start, c, &mut NoObserver))
}

/// The frames of a search of `g` from `start`: its own run, step by step, as the course's
/// table has it.
///
/// The run is [`bfs_with`]'s or [`dfs_with`]'s, told about each step: one
/// [`SearchStep::Add`] per vertex appended to Q and one [`SearchStep::Remove`] per vertex
/// removed, each with Q after it (exactly the rows of the course's tables, [RD, §2.1]
/// "Algoritmos de búsqueda", columns Añadir / Quitar / Q), then [`SearchStep::Done`] with the
/// search [`bfs`] or [`dfs`] returns. The first frame adds the start, and a component of n_c
/// vertices gives 2·n_c + 1 frames. The visit order is the order of the added vertices. Each
/// frame carries the operations counted so far; the last frame's are those of the `_with`
/// function with [`Counts`](crate::count::Counts). [`trace_table`] prints the rows.
///
/// # Errors
/// [`Error::NoSuchVertex`](crate::Error::NoSuchVertex) if `start >= n`;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the graph has more than
/// [`TRACE_MAX_VERTICES`] vertices (each row copies the list Q).
///
/// # Complexity
/// O(n + m + n_c²) time and O(n + n_c²) space for the frames.
///
/// ```
/// use compgeo::graph::{search_trace, Graph, SearchAlgorithm, SearchStep};
///
/// let g = Graph::from_edges(3, &[[0, 1], [0, 2]])?;
/// let frames = search_trace(&g, 0, SearchAlgorithm::Dfs)?;
/// let added: Vec<usize> = frames
///     .iter()
///     .filter_map(|f| match f.step {
///         SearchStep::Add { vertex, .. } => Some(vertex),
///         _ => None,
///     })
///     .collect();
/// assert_eq!(added, [0, 1, 2]);
/// // 1 was removed before 2 was added
/// assert_eq!(frames[2].step, SearchStep::Remove { vertex: 1, list: vec![0] });
/// assert!(matches!(&frames[6].step, SearchStep::Done { search } if search.order == added));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn search_trace(
    g: &Graph,
    start: usize,
    kind: SearchAlgorithm,
) -> Result<Vec<Frame<SearchStep>>> {
    g.check_vertex(start)?;
    crate::limits::TRACE_VERTICES.check(g.vertex_count() as u128)?;
    record(|counts, recorder| {
        let search = match kind {
            SearchAlgorithm::Bfs => bfs_observed(g, start, counts, recorder),
            SearchAlgorithm::Dfs => dfs_observed(g, start, counts, recorder),
        };
        Ok(SearchStep::Done { search })
    })
}

/// Prints a search's frames as the course's three-column table, `Add`, `Remove`, `Q`,
/// tab-separated, one row per added or removed vertex (the last frame, the result, prints
/// nothing), with `-` for an empty cell and `∅` for an empty Q; `name` writes a vertex (the
/// course uses letters). Q's vertices are run together when every name is a single letter, as
/// in the seed (`abce`), and separated by spaces otherwise.
///
/// ```
/// use compgeo::graph::{search_trace, trace_table, Graph, SearchAlgorithm};
///
/// let g = Graph::from_edges(2, &[[0, 1]])?;
/// let frames = search_trace(&g, 0, SearchAlgorithm::Bfs)?;
/// let letter = |v: usize| char::from(b'a' + v as u8).to_string();
/// assert_eq!(
///     trace_table(&frames, letter),
///     "Add\tRemove\tQ\na\t-\ta\nb\t-\tab\n-\ta\tb\n-\tb\t∅\n"
/// );
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn trace_table(frames: &[Frame<SearchStep>], name: impl Fn(usize) -> String) -> String {
    let mut out = String::from("Add\tRemove\tQ\n");
    let cell = |v: Option<usize>| v.map_or_else(|| "-".to_string(), &name);
    for frame in frames {
        let (added, removed, list) = match &frame.step {
            SearchStep::Add { vertex, list, .. } => (Some(*vertex), None, list),
            SearchStep::Remove { vertex, list } => (None, Some(*vertex), list),
            SearchStep::Done { .. } => continue,
        };
        let list: String = if list.is_empty() {
            "∅".to_string()
        } else {
            let names: Vec<String> = list.iter().map(|&v| name(v)).collect();
            // Single letters read like the course's "abce"; numbers and longer names need a
            // separator.
            let single_letter = |s: &String| {
                let mut chars = s.chars();
                chars.next().is_some_and(char::is_alphabetic) && chars.next().is_none()
            };
            let sep = if names.iter().all(single_letter) {
                ""
            } else {
                " "
            };
            names.join(sep)
        };
        let _ = writeln!(out, "{}\t{}\t{}", cell(added), cell(removed), list);
    }
    out
}

/// The connected components, found by breadth-first search from each unvisited vertex in
/// ascending order.
///
/// The course's remark (§2.1 "Algoritmos de búsqueda"): a search that reaches every vertex has
/// built a spanning tree, so the graph is connected.
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{components, Graph};
///
/// let g = Graph::from_edges(5, &[[0, 3], [1, 4]])?;
/// let c = components(&g);
/// assert_eq!((c.count, c.label), (3, vec![0, 1, 2, 0, 1]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn components(g: &Graph) -> Components {
    let n = g.vertex_count();
    let mut label = vec![usize::MAX; n];
    let mut queue = Vec::new();
    let mut count = 0;
    for s in 0..n {
        if label[s] != usize::MAX {
            continue;
        }
        label[s] = count;
        queue.clear();
        queue.push(s);
        let mut head = 0;
        while head < queue.len() {
            let x = queue[head];
            head += 1;
            for y in g.neighbours(x) {
                if label[y] == usize::MAX {
                    label[y] = count;
                    queue.push(y);
                }
            }
        }
        count += 1;
    }
    Components { label, count }
}

/// Whether the graph is connected: one search from vertex 0 reaches every vertex. The
/// empty graph counts as connected.
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{is_connected, Graph};
///
/// assert!(is_connected(&Graph::from_edges(3, &[[0, 1], [2, 1]])?));
/// assert!(!is_connected(&Graph::from_edges(3, &[[0, 1]])?));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn is_connected(g: &Graph) -> bool {
    match bfs(g, 0) {
        Ok(s) => s.order.len() == g.vertex_count(),
        Err(_) => true,
    }
}

/// Checks that `search` is a valid search result from `start`: `order` lists distinct
/// vertices starting with `start`, each non-start vertex's parent is a graph neighbour that
/// appears earlier in `order`, the vertices outside `order` have no parent, and `order` is
/// closed under adjacency (a whole component).
///
/// # Errors
/// A [`Violation`] naming the first vertex at fault and why.
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{bfs, check_search_tree, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2]])?;
/// let mut s = bfs(&g, 1)?;
/// assert!(check_search_tree(&g, 1, &s).is_ok());
/// s.parent[2] = Some(0); // not an edge
/// let bad = check_search_tree(&g, 1, &s).unwrap_err();
/// assert!(bad.to_string().starts_with("vertex 2"), "{bad}");
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn check_search_tree(
    g: &Graph,
    start: usize,
    search: &Search,
) -> std::result::Result<(), Violation> {
    let n = g.vertex_count();
    let bad = |reason: String| Err(Violation::new(reason));
    if search.parent.len() != n {
        return bad(format!("{} parents for {n} vertices", search.parent.len()));
    }
    if search.order.first() != Some(&start) {
        return bad(format!("the order does not start at {start}"));
    }
    let mut rank = vec![usize::MAX; n];
    for (i, &v) in search.order.iter().enumerate() {
        if v >= n {
            return bad(format!("vertex {v} (position {i}) is out of range"));
        }
        if rank[v] != usize::MAX {
            return bad(format!("vertex {v} is visited twice"));
        }
        rank[v] = i;
    }
    for v in 0..n {
        let reached = rank[v] != usize::MAX;
        match search.parent[v] {
            None if v != start && reached => {
                return bad(format!("vertex {v} was reached but has no parent"))
            }
            None => {}
            Some(_) if v == start => return bad(format!("the start {v} has a parent")),
            Some(_) if !reached => {
                return bad(format!("vertex {v} has a parent but was not reached"))
            }
            Some(p) if p >= n || rank[p] >= rank[v] || !g.has_edge(p, v) => {
                return bad(format!(
                    "vertex {v} has parent {p}, which is not an earlier neighbour"
                ))
            }
            Some(_) => {}
        }
        if reached {
            if let Some(y) = g.neighbours(v).find(|&y| rank[y] == usize::MAX) {
                return bad(format!(
                    "vertex {v} was reached but its neighbour {y} was not"
                ));
            }
        }
    }
    Ok(())
}

/// Breadth-first search from a valid `start`, telling `obs` about each vertex added to Q and
/// removed from it.
fn bfs_observed<C: Counter, O: Observer<SearchStep, C>>(
    g: &Graph,
    start: usize,
    c: &mut C,
    obs: &mut O,
) -> Search {
    let n = g.vertex_count();
    let mut parent = vec![NONE; n];
    // The visit order doubles as the queue: Q is order[head..].
    let mut order: Vec<u32> = Vec::with_capacity(n);
    parent[start] = start as u32;
    order.push(start as u32);
    obs.step(c, || SearchStep::Add {
        vertex: start,
        parent: None,
        list: vec![start],
    });
    let mut head = 0;
    while head < order.len() {
        let x = order[head] as usize;
        c.vertex_visit();
        for &y in g.adjacent(x) {
            c.edge_visit();
            if parent[y as usize] == NONE {
                parent[y as usize] = x as u32;
                order.push(y);
                obs.step(c, || SearchStep::Add {
                    vertex: y as usize,
                    parent: Some(x),
                    list: widen(&order[head..]),
                });
            }
        }
        // x stays first in Q while it adds its neighbours, then leaves.
        head += 1;
        obs.step(c, || SearchStep::Remove {
            vertex: x,
            list: widen(&order[head..]),
        });
    }
    finish(order, parent, start)
}

/// Depth-first search from a valid `start`, telling `obs` about each vertex pushed on Q and
/// popped from it.
fn dfs_observed<C: Counter, O: Observer<SearchStep, C>>(
    g: &Graph,
    start: usize,
    c: &mut C,
    obs: &mut O,
) -> Search {
    let n = g.vertex_count();
    let mut parent = vec![NONE; n];
    let mut order: Vec<u32> = Vec::with_capacity(n);
    // (vertex, how many of its neighbours have been looked at)
    let mut stack: Vec<(u32, u32)> = Vec::new();
    let list = |stack: &[(u32, u32)]| stack.iter().map(|&(v, _)| v as usize).collect();
    parent[start] = start as u32;
    order.push(start as u32);
    c.vertex_visit();
    stack.push((start as u32, 0));
    obs.step(c, || SearchStep::Add {
        vertex: start,
        parent: None,
        list: vec![start],
    });
    while let Some(top) = stack.last_mut() {
        let x = top.0 as usize;
        let adjacent = g.adjacent(x);
        let mut cursor = top.1 as usize;
        let mut next = None;
        while cursor < adjacent.len() {
            let y = adjacent[cursor];
            cursor += 1;
            c.edge_visit();
            if parent[y as usize] == NONE {
                next = Some(y);
                break;
            }
        }
        top.1 = cursor as u32;
        match next {
            Some(y) => {
                parent[y as usize] = x as u32;
                order.push(y);
                c.vertex_visit();
                stack.push((y, 0));
                obs.step(c, || SearchStep::Add {
                    vertex: y as usize,
                    parent: Some(x),
                    list: list(&stack),
                });
            }
            None => {
                stack.pop();
                obs.step(c, || SearchStep::Remove {
                    vertex: x,
                    list: list(&stack),
                });
            }
        }
    }
    finish(order, parent, start)
}

/// Compact vertex ids as `usize`.
fn widen(vertices: &[u32]) -> Vec<usize> {
    vertices.iter().map(|&v| v as usize).collect()
}

/// "No parent yet" in the searches' compact parent arrays.
const NONE: u32 = u32::MAX;

/// Converts the compact arrays of a search into a [`Search`].
fn finish(order: Vec<u32>, parent: Vec<u32>, start: usize) -> Search {
    Search {
        order: order.into_iter().map(|v| v as usize).collect(),
        parent: parent
            .into_iter()
            .enumerate()
            .map(|(v, p)| (p != NONE && v != start).then_some(p as usize))
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;

    #[test]
    fn a_missing_start_is_an_error() {
        let g = Graph::from_edges(0, &[]).unwrap();
        assert!(matches!(
            bfs(&g, 0),
            Err(Error::NoSuchVertex {
                vertex: 0,
                vertices: 0
            })
        ));
        let g = Graph::from_edges(2, &[[0, 1]]).unwrap();
        assert!(dfs(&g, 2).is_err());
        assert!(search_trace(&g, 5, SearchAlgorithm::Dfs).is_err());
    }

    #[test]
    fn a_long_path_does_not_overflow_the_stack() {
        let n = 200_000;
        let edges: Vec<[usize; 2]> = (1..n).map(|i| [i - 1, i]).collect();
        let g = Graph::from_edges(n, &edges).unwrap();
        let s = dfs(&g, 0).unwrap();
        assert_eq!(s.order.len(), n);
        assert_eq!(s.parent[n - 1], Some(n - 2));
    }
}
