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

use crate::count::{Counter, NoCount};
use crate::error::{Error, Result};
use crate::graph::Graph;
use std::fmt;
use std::str::FromStr;

mod course;
mod dsatur;
mod greedy;
mod largest_first;
mod smallest_last;
mod tabu;

pub use course::{course_greedy_colouring, course_greedy_colouring_with};
pub use dsatur::{dsatur, dsatur_with};
pub use greedy::{greedy_colouring, greedy_colouring_with};
pub use largest_first::largest_first_order;
pub use smallest_last::smallest_last_order;
pub use tabu::{dsatur_tabu, dsatur_tabu_with, tabu_recolour, tabu_recolour_with, TABU_EFFORT};

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
        ColouringAlgorithm::DsaturTabu => return dsatur_tabu_with(g, c),
    };
    let result = match strategy {
        ColouringAlgorithm::Course => course_greedy_colouring_with(g, &natural, c),
        _ => greedy_colouring_with(g, &natural, c),
    };
    result.expect("the orders built here are permutations")
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
