//! The course's greedy colouring exactly as printed: every earlier vertex is asked about.

use super::{check_colouring, check_order, Colouring};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::graph::Graph;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "colour",
    name: "course",
    function: "graph::course_greedy_colouring",
    file: "src/graph/colouring/course.rs",
    summary: "the course's greedy colouring as printed, in vertex order",
    time: "O(n² + m)",
    space: "O(n)",
    operation: Some(Operation::AdjacencyTests),
    counts: "exactly n(n − 1)/2 adjacency tests",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::Quadratic, Operation::AdjacencyTests)],
};

/// The course's greedy colouring of `g` in the given vertex order; see
/// [`course_greedy_colouring_with`].
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"order"`) if `order` is not a permutation of `0..n`.
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

/// The course's greedy colouring exactly as printed, counting its adjacency tests.
///
/// The idea ([RD, §2.1] "Coloración de vértices", "Algoritmo voraz
/// aplicado a la coloración de un grafo"): c(v₁) := first colour; for i = 2..n, S := the
/// colours of those v_j, j < i, adjacent to v_i (asking the adjacency question for every
/// j < i), and c(v_i) := the first colour not in S. Each adjacency question is O(1): the
/// neighbours of v_i are marked once before the questions are asked.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"order"`) if `order` is not a permutation of `0..n`,
/// naming the position and vertex at fault.
///
/// # Complexity
/// O(n² + m) time for n vertices and m edges (the course's analysis: n(n−1)/2 adjacency
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
    debug_assert_eq!(check_colouring(g, &colour), Ok(()));
    Ok(Colouring { colour, count })
}
