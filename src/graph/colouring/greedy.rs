//! Greedy colouring in a given vertex order in O(n + m): only a vertex's own neighbours are
//! looked at.

use super::{check_colouring, check_order, Colouring, UNCOLOURED};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::graph::Graph;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "colour",
    name: "greedy",
    function: "graph::greedy_colouring",
    file: "src/graph/colouring/greedy.rs",
    summary: "the greedy colouring in vertex order, looking only at neighbours",
    time: "O(n + m)",
    space: "O(n)",
    operation: Some(Operation::EdgeVisits),
    counts: "exactly 2m edge visits",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::NPlusM, Operation::EdgeVisits)],
};

/// Greedy colouring of `g` in the given vertex order in O(n + m); see
/// [`greedy_colouring_with`].
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"order"`) if `order` is not a permutation of `0..n`.
///
/// # Complexity
/// O(n + m) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::graph::{greedy_colouring, Graph};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2]])?;
/// assert_eq!(greedy_colouring(&g, &[0, 1, 2])?.colour, [0, 1, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn greedy_colouring(g: &Graph, order: &[usize]) -> Result<Colouring> {
    greedy_colouring_with(g, order, &mut NoCount)
}

/// The same colouring as the course's greedy, computed in O(n + m).
///
/// The idea: the course's algorithm (§2.1 "Coloración de vértices") asks about every earlier
/// vertex; it is enough to look at v_i's own neighbours. Their colours are stamped with i in
/// an array, and the first colour without the stamp is at most deg(v_i), so the search for
/// it costs O(deg v_i) too. The result equals [`course_greedy_colouring`](super::course_greedy_colouring)'s for the same order.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"order"`) if `order` is not a permutation of `0..n`.
///
/// # Complexity
/// O(n + m) time for n vertices and m edges; O(n) auxiliary space. A greedy colouring uses
/// at most Δ + 1 colours (Δ the largest degree).
///
/// # Counts
/// One `vertex_visit` per vertex coloured and one `edge_visit` per neighbour looked at:
/// exactly n and 2m.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{greedy_colouring_with, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 3]])?;
/// let mut c = Counts::default();
/// // A path needs 2 colours, but this order makes the greedy use 3.
/// assert_eq!(greedy_colouring_with(&g, &[0, 3, 1, 2], &mut c)?.colour, [0, 1, 2, 0]);
/// assert_eq!((c.vertex_visits, c.edge_visits), (4, 6));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn greedy_colouring_with<C: Counter>(
    g: &Graph,
    order: &[usize],
    c: &mut C,
) -> Result<Colouring> {
    check_order(g, order)?;
    let n = g.vertex_count();
    let mut colour = vec![UNCOLOURED; n];
    let mut stamp = vec![u32::MAX; n + 1];
    let mut count = 0;
    for (i, &v) in order.iter().enumerate() {
        c.vertex_visit();
        for &w in g.adjacent(v) {
            c.edge_visit();
            let k = colour[w as usize];
            if k != UNCOLOURED {
                stamp[k as usize] = i as u32;
            }
        }
        let mut k = 0;
        while stamp[k] == i as u32 {
            k += 1;
        }
        colour[v] = k as u32;
        count = count.max(k + 1);
    }
    let colour: Vec<usize> = colour.into_iter().map(|k| k as usize).collect();
    debug_assert_eq!(check_colouring(g, &colour), Ok(()));
    Ok(Colouring { colour, count })
}
