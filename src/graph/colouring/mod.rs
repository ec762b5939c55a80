//! Greedy vertex colouring: the course's O(n²) algorithm as printed, the O(n + m) greedy, the
//! vertex orders largest-first (Welsh–Powell) and smallest-last, DSatur, and two searches
//! for fewer colours that start from DSatur: the tabu search (TabuCol) and the hybrid
//! evolutionary algorithm (HEA), both paid from a [`Budget`] of steps and time. Before each
//! target both try an exact search (`transversal.rs`) when the graph's core splits into
//! cliques of the target size, which can prove the colouring optimal and end the search; it
//! looks first among the colourings that an automorphism of the core maps to themselves
//! (`symmetry.rs`).
//!
//! A colouring gives each vertex a colour so that adjacent vertices differ (seed
//! [RD, §2.1] "Coloración de vértices", Definitions 2.4–2.6). The greedy
//! scheme ("Algoritmo voraz aplicado a la coloración") takes the vertices in some order and
//! gives each the first colour none of its already coloured neighbours has; the order decides
//! how many colours it needs. Colours are numbered from 0 here (the course's colour k is our
//! k − 1).
//!
//! The tests check every colouring with [`check_colouring`], the course's chromatic-number
//! facts (K_n, even and odd cycles, trees), the course's count of n(n−1)/2 adjacency tests, and
//! DSatur against petgraph.

use crate::complexity::algorithm_family;
use crate::count::{Counter, NoCount};
use crate::error::{Error, Result, Violation};
use crate::graph::Graph;

mod budget;
mod course;
mod dsatur;
mod greedy;
mod hea;
mod largest_first;
mod reduce;
mod smallest_last;
mod symmetry;
mod tabu;
mod transversal;

pub use budget::{Budget, SearchReport, CLOCK_STRIDE, SEARCH_SEED, TABU_EFFORT};

pub use course::{
    course_greedy_colouring, course_greedy_colouring_trace, course_greedy_colouring_with,
    CourseColouringStep,
};
pub use dsatur::{dsatur, dsatur_with};
pub use greedy::{greedy_colouring, greedy_colouring_with};
pub use hea::{hea, hea_budget, hea_budget_with, hea_with, POPULATION};
pub use largest_first::largest_first_order;
pub use smallest_last::smallest_last_order;
pub use tabu::{
    dsatur_tabu, dsatur_tabu_budget, dsatur_tabu_budget_with, dsatur_tabu_with, tabu_recolour,
    tabu_recolour_with,
};

/// A vertex colouring.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Colouring {
    /// `colour[v]` is the colour of vertex `v`, in `0..count`.
    pub colour: Vec<usize>,
    /// The number of colours used (0 for the empty graph).
    pub count: usize,
}

algorithm_family! {
    /// The colouring strategies, for callers that choose one at run time ([`colour`]).
    ///
    /// ```
    /// use compgeo::graph::ColouringAlgorithm;
    ///
    /// assert_eq!("dsatur".parse::<ColouringAlgorithm>()?, ColouringAlgorithm::Dsatur);
    /// assert_eq!(ColouringAlgorithm::LargestFirst.name(), "largest-first");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum ColouringAlgorithm ("colouring algorithm") {
        /// The course's algorithm in vertex order ([`course_greedy_colouring`]).
        Course = course::DECLARATION => course_in_vertex_order_with,
        /// The O(n + m) greedy in vertex order ([`greedy_colouring`]).
        Greedy = greedy::DECLARATION => greedy_in_vertex_order_with,
        /// Greedy in [`largest_first_order`].
        LargestFirst = largest_first::DECLARATION => greedy_largest_first_with,
        /// Greedy in [`smallest_last_order`].
        SmallestLast = smallest_last::DECLARATION => greedy_smallest_last_with,
        /// [`dsatur`].
        Dsatur = dsatur::DECLARATION => dsatur_with,
        /// [`dsatur_tabu`]: DSatur, then a tabu search for fewer colours.
        DsaturTabu = tabu::DECLARATION => dsatur_tabu_with,
        /// [`hea`]: DSatur, then the hybrid evolutionary search of Galinier and Hao.
        Hea = hea::DECLARATION => hea_with,
    }
    fn run_with[C: Counter](g: &Graph, c: &mut C) -> Colouring;
}

/// Colours `g` with `strategy`; see [`colour_with`].
///
/// # Complexity
/// That of the strategy ([`ColouringAlgorithm::declaration`]).
///
/// ```
/// use compgeo::graph::{colour, check_colouring, Graph, ColouringAlgorithm};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2], [2, 0]])?;
/// let c = colour(&g, ColouringAlgorithm::Dsatur);
/// assert_eq!(c.count, 3);
/// assert_eq!(check_colouring(&g, &c.colour), Ok(()));
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
    strategy.run_with(g, c)
}

/// Colours `g` with `strategy`, a search strategy spending `budget` with its random choices
/// drawn from `seed`; see [`colour_budget_with`].
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"budget"`) if `budget` has neither a step cap nor a
/// time limit.
///
/// # Complexity
/// That of the strategy, with the search's steps bounded by the budget.
///
/// ```
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{colour_budget, hea_budget, Budget, ColouringAlgorithm, Graph};
///
/// let g = Graph::from_edge_list(&graph(GraphKind::Queen, 6, 0, 0)?)?;
/// let budget = Budget::steps(1_000_000);
/// let (c, report) = colour_budget(&g, ColouringAlgorithm::Hea, budget, 5)?;
/// assert_eq!((c.clone(), report), hea_budget(&g, budget, 5)?);
/// // A strategy that does not search ignores the budget and spends nothing.
/// let (_, report) = colour_budget(&g, ColouringAlgorithm::Dsatur, budget, 5)?;
/// assert_eq!(report.steps, 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn colour_budget(
    g: &Graph,
    strategy: ColouringAlgorithm,
    budget: Budget,
    seed: u64,
) -> Result<(Colouring, SearchReport)> {
    colour_budget_with(g, strategy, budget, seed, &mut NoCount)
}

/// Colours `g` with `strategy`, counting as the chosen algorithm counts: the search
/// strategies ([`ColouringAlgorithm::is_search`]) run [`dsatur_tabu_budget_with`] or
/// [`hea_budget_with`] with `budget` and `seed`; the others ignore both and report no steps.
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"budget"`) if `budget` has neither a step cap nor a
/// time limit.
///
/// # Complexity
/// As [`colour_budget`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{colour_budget_with, Budget, ColouringAlgorithm, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0]])?;
/// let mut c = Counts::default();
/// let budget = Budget::steps(1000);
/// let (colouring, _) = colour_budget_with(&g, ColouringAlgorithm::DsaturTabu, budget, 1, &mut c)?;
/// assert_eq!(colouring.count, 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn colour_budget_with<C: Counter>(
    g: &Graph,
    strategy: ColouringAlgorithm,
    budget: Budget,
    seed: u64,
    c: &mut C,
) -> Result<(Colouring, SearchReport)> {
    match strategy {
        ColouringAlgorithm::DsaturTabu => dsatur_tabu_budget_with(g, budget, seed, c),
        ColouringAlgorithm::Hea => hea_budget_with(g, budget, seed, c),
        _ => {
            budget.check()?;
            Ok((colour_with(g, strategy, c), SearchReport::default()))
        }
    }
}

impl ColouringAlgorithm {
    /// Whether the strategy searches for fewer colours within a [`Budget`] (`dsatur-tabu`
    /// and `hea`), so that [`colour_budget`] passes it the budget and seed.
    ///
    /// ```
    /// use compgeo::graph::ColouringAlgorithm;
    ///
    /// assert!(ColouringAlgorithm::Hea.is_search() && !ColouringAlgorithm::Dsatur.is_search());
    /// ```
    pub fn is_search(self) -> bool {
        matches!(
            self,
            ColouringAlgorithm::DsaturTabu | ColouringAlgorithm::Hea
        )
    }
}

/// The course's greedy colouring in the vertex order `0..n`.
fn course_in_vertex_order_with<C: Counter>(g: &Graph, c: &mut C) -> Colouring {
    let order: Vec<usize> = (0..g.vertex_count()).collect();
    course_greedy_colouring_with(g, &order, c).expect("0..n is a permutation")
}

/// The greedy colouring in the vertex order `0..n`.
fn greedy_in_vertex_order_with<C: Counter>(g: &Graph, c: &mut C) -> Colouring {
    let order: Vec<usize> = (0..g.vertex_count()).collect();
    greedy_colouring_with(g, &order, c).expect("0..n is a permutation")
}

/// The greedy colouring in [`largest_first_order`].
fn greedy_largest_first_with<C: Counter>(g: &Graph, c: &mut C) -> Colouring {
    greedy_colouring_with(g, &largest_first_order(g), c).expect("the order is a permutation")
}

/// The greedy colouring in [`smallest_last_order`].
fn greedy_smallest_last_with<C: Counter>(g: &Graph, c: &mut C) -> Colouring {
    greedy_colouring_with(g, &smallest_last_order(g), c).expect("the order is a permutation")
}

/// Checks that `colour` is a proper colouring of `g`: one colour per vertex and no edge whose
/// ends share a colour.
///
/// # Errors
/// A [`Violation`] naming a wrong number of colours or the first edge whose ends share one.
///
/// # Complexity
/// O(n + m) time, no auxiliary space.
///
/// ```
/// use compgeo::graph::{check_colouring, Graph};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2]])?;
/// assert!(check_colouring(&g, &[0, 1, 0]).is_ok());
/// assert!(check_colouring(&g, &[0, 0, 1]).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn check_colouring(g: &Graph, colour: &[usize]) -> std::result::Result<(), Violation> {
    if colour.len() != g.vertex_count() {
        return Err(Violation::new(format!(
            "{} colours for {} vertices",
            colour.len(),
            g.vertex_count()
        )));
    }
    match g.edges().find(|&[u, v]| colour[u] == colour[v]) {
        Some([u, v]) => Err(Violation::new(format!(
            "edge [{u}, {v}] joins two vertices of colour {}",
            colour[u]
        ))),
        None => Ok(()),
    }
}

/// The colour of a vertex not yet coloured.
pub(super) const UNCOLOURED: u32 = u32::MAX;

/// Checks that `order` is a permutation of the vertices.
pub(super) fn check_order(g: &Graph, order: &[usize]) -> Result<()> {
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

/// The vertices `0..n` stably sorted by a key below `keys` (a counting sort), and `start`
/// with `start[k]` the first position of key `k` and `start[keys] = n`: the degree buckets
/// the largest-first and smallest-last orders start from. O(n + keys).
pub(super) fn vertices_by_key(
    n: usize,
    keys: usize,
    key: impl Fn(usize) -> usize,
) -> (Vec<usize>, Vec<usize>) {
    let mut start = vec![0usize; keys + 1];
    for v in 0..n {
        start[key(v) + 1] += 1;
    }
    for k in 1..start.len() {
        start[k] += start[k - 1];
    }
    let mut sorted = vec![0; n];
    let mut next = start.clone();
    for v in 0..n {
        let slot = &mut next[key(v)];
        sorted[*slot] = v;
        *slot += 1;
    }
    (sorted, start)
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
}
