//! The course's greedy colouring exactly as printed: every earlier vertex is asked about.

use super::{check_colouring, check_order, Colouring};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::graph::Graph;
use crate::trace::{record, Frame, NoObserver, Observer, TraceSize};

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

/// A step of the course's greedy colouring, as [`course_greedy_colouring_trace`] records it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CourseColouringStep {
    /// The vertex `vertex`, the `i`-th of the order (from 0), got colour `colour`: the first
    /// colour not in S, the colours of the earlier vertices found adjacent to it. Every
    /// earlier vertex of the order was asked about (i adjacency tests).
    Coloured {
        /// The vertex coloured.
        vertex: usize,
        /// The colour it got (from 0).
        colour: usize,
        /// The earlier vertices of the order adjacent to it, in the order they were asked
        /// about; their colours make up S.
        adjacent: Vec<usize>,
        /// The colouring so far, per vertex: `None` for those still to come.
        colours: Vec<Option<usize>>,
    },
    /// Every vertex is coloured: the result of [`course_greedy_colouring`].
    Done {
        /// The colouring, as [`course_greedy_colouring`] returns it.
        colouring: Colouring,
    },
}

impl TraceSize for CourseColouringStep {
    fn entries(&self) -> usize {
        match self {
            CourseColouringStep::Coloured {
                adjacent, colours, ..
            } => 2 + adjacent.len() + colours.len(),
            CourseColouringStep::Done { colouring } => colouring.colour.len(),
        }
    }
}

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
    Ok(course(g, order, c, &mut NoObserver))
}

/// The frames of the course's greedy colouring of `g` in `order`: its own run, step by step.
///
/// The run is [`course_greedy_colouring_with`]'s, told about each step: one
/// [`CourseColouringStep::Coloured`] per vertex in the order (the vertex, its colour, the
/// earlier vertices found adjacent, the colouring so far), then
/// [`CourseColouringStep::Done`] with the colouring [`course_greedy_colouring`] returns. Each
/// frame carries the operations counted so far: after the i-th vertex (from 0), exactly
/// i(i + 1)/2 adjacency tests.
///
/// # Errors
///
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"order"`) if `order`
/// is not a permutation of `0..n`; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if
/// the frames would hold more than [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES)
/// entries (each frame copies the colouring: n frames of n entries).
///
/// # Complexity
///
/// O(n² + m) time and O(n² + m) space for the frames.
///
/// ```
/// use compgeo::graph::{course_greedy_colouring_trace, CourseColouringStep, Graph};
///
/// // The path 0 - 1 - 2, coloured in the order 1, 0, 2.
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2]])?;
/// let frames = course_greedy_colouring_trace(&g, &[1, 0, 2])?;
/// assert_eq!(
///     frames[1].step,
///     CourseColouringStep::Coloured {
///         vertex: 0,
///         colour: 1,
///         adjacent: vec![1],
///         colours: vec![Some(1), Some(0), None],
///     }
/// );
/// assert_eq!(frames[2].counts.adjacency_tests, 3); // 0 + 1 + 2 questions
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn course_greedy_colouring_trace(
    g: &Graph,
    order: &[usize],
) -> Result<Vec<Frame<CourseColouringStep>>> {
    check_order(g, order)?;
    record(|counts, recorder| {
        let colouring = course(g, order, counts, recorder);
        Ok(CourseColouringStep::Done { colouring })
    })
}

/// The course's algorithm on a checked order, telling `obs` about each vertex coloured.
fn course<C: Counter, O: Observer<CourseColouringStep, C>>(
    g: &Graph,
    order: &[usize],
    c: &mut C,
    obs: &mut O,
) -> Colouring {
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
        obs.step(c, || CourseColouringStep::Coloured {
            vertex: vi,
            colour: k,
            adjacent: order[..i]
                .iter()
                .copied()
                .filter(|&vj| adjacent_mark[vj] == i)
                .collect(),
            colours: {
                let mut so_far = vec![None; n];
                for &v in &order[..=i] {
                    so_far[v] = Some(colour[v]);
                }
                so_far
            },
        });
    }
    debug_assert_eq!(check_colouring(g, &colour), Ok(()));
    Colouring { colour, count }
}
