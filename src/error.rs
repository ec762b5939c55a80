//! The crate's one error type.
//!
//! Every public function that takes user data returns [`Result`]. Messages name the offending
//! index or value so that a user can find the bad record in their own input.

/// Everything that can be wrong with the data handed to a compgeo algorithm.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A point has a NaN or infinite coordinate. Every finite `f64` is valid input.
    #[error("point {index} has a non-finite coordinate ({value})")]
    NonFinite {
        /// Index of the point in the caller's input.
        index: usize,
        /// The offending coordinate value (NaN, `inf` or `-inf`).
        value: f64,
    },
    /// The input is empty but the answer needs at least one element.
    #[error("{what} is empty")]
    Empty {
        /// What was empty, e.g. "point set" or "graph".
        what: &'static str,
    },
    /// The input has fewer elements than the problem needs.
    #[error("{what} needs at least {needed} elements, got {got}")]
    TooFew {
        /// What was too small, e.g. "point set".
        what: &'static str,
        /// The minimum number of elements.
        needed: usize,
        /// How many elements were given.
        got: usize,
    },
    /// An edge names a vertex that the graph does not have.
    #[error("edge {edge} names vertex {vertex}, but the graph has only {vertices} vertices")]
    VertexOutOfRange {
        /// Index of the edge in the caller's edge list.
        edge: usize,
        /// The vertex id that is out of range.
        vertex: usize,
        /// Number of vertices of the graph.
        vertices: usize,
    },
    /// A vertex given as an argument (a start vertex, say) does not exist.
    #[error("vertex {vertex} does not exist: the graph has {vertices} vertices")]
    NoSuchVertex {
        /// The vertex id that was asked for.
        vertex: usize,
        /// Number of vertices of the graph.
        vertices: usize,
    },
    /// An edge weight is NaN or infinite.
    #[error("edge {edge} has a non-finite weight ({value})")]
    NonFiniteWeight {
        /// Index of the edge in the caller's edge list.
        edge: usize,
        /// The offending weight.
        value: f64,
    },
    /// A result is finite mathematically but beyond the range of `f64` (a derivative or a
    /// restriction of a curve whose coordinates are near the top of the double range).
    #[error("the result of {what} is beyond the range of f64")]
    Overflow {
        /// The operation, e.g. "derivative".
        what: &'static str,
    },
    /// A size beyond one of the documented limits of [`crate::limits`] (a degree, a vertex
    /// or edge count, how many points to generate), found before anything is allocated.
    #[error("{what} {value} exceeds {limit} = {max}")]
    LimitExceeded {
        /// What the size counts, e.g. "graph edge count".
        what: &'static str,
        /// The size asked for (computed exactly, so it may exceed `usize`).
        value: u128,
        /// The limit's constant in [`crate::limits`], e.g. `"MAX_EDGES"`.
        limit: &'static str,
        /// The limit's value.
        max: usize,
    },
    /// A parameter is outside its valid domain (a knot vector that decreases, a size of zero,
    /// a Beta-spline parameter that makes the basis degenerate, ...).
    #[error("invalid {name}: {reason}")]
    InvalidParameter {
        /// The parameter's name as the caller knows it.
        name: &'static str,
        /// Why it is invalid, with the value.
        reason: String,
    },
    /// A polygon mesh that is not a valid oriented manifold (the violation names the face,
    /// vertex or edge), or Wavefront OBJ text that cannot be read (the line number).
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
    /// A line of a text format that cannot be read (a DIMACS graph, an edge list), with its
    /// 1-based number.
    #[error("{format} line {line}: {problem}")]
    Syntax {
        /// The format, e.g. "DIMACS".
        format: &'static str,
        /// The 1-based line number (one past the last line for something missing at the end).
        line: usize,
        /// What is wrong, quoting the offending text.
        problem: String,
    },
}

/// A broken invariant, found by one of the crate's checkers
/// ([`check_strictly_convex_ccw`](crate::hull::check_strictly_convex_ccw),
/// [`check_delaunay`](crate::delaunay::check_delaunay),
/// [`check_colouring`](crate::graph::check_colouring), ...): which property fails, and where
/// (the indices involved).
///
/// ```
/// use compgeo::graph::{check_colouring, Graph};
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2]])?;
/// let v = check_colouring(&g, &[0, 0, 1]).unwrap_err();
/// assert_eq!(v.to_string(), "edge [0, 1] joins two vertices of colour 0");
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{reason}")]
pub struct Violation {
    /// The property that fails, with the indices involved.
    pub reason: String,
}

impl Violation {
    /// The violation described by `reason`.
    pub fn new(reason: impl Into<String>) -> Violation {
        Violation {
            reason: reason.into(),
        }
    }
}

/// `Result` with the crate's [`enum@Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// Finds the item named `s` among `all` (the `FromStr` of the crate's name enums), or an
/// [`Error::InvalidParameter`] named `parameter` that lists the valid names:
/// "unknown {what} `s`; valid names: a, b, c".
pub(crate) fn named<A: Copy>(
    s: &str,
    parameter: &'static str,
    what: &str,
    all: &[A],
    name: impl Fn(A) -> &'static str,
) -> Result<A> {
    all.iter()
        .copied()
        .find(|&a| name(a) == s)
        .ok_or_else(|| Error::InvalidParameter {
            name: parameter,
            reason: format!(
                "unknown {what} `{s}`; valid names: {}",
                all.iter().map(|&a| name(a)).collect::<Vec<_>>().join(", ")
            ),
        })
}

/// [`named`] for the `FromStr` of every `Algorithm` enum: the parameter is `"algorithm"`.
pub(crate) fn algorithm_named<A: Copy>(
    s: &str,
    what: &str,
    all: &[A],
    name: impl Fn(A) -> &'static str,
) -> Result<A> {
    named(s, "algorithm", what, all, name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_index_and_value() {
        let e = Error::NonFinite {
            index: 3,
            value: f64::NAN,
        };
        assert_eq!(e.to_string(), "point 3 has a non-finite coordinate (NaN)");
        let e = Error::NonFinite {
            index: 0,
            value: f64::NEG_INFINITY,
        };
        assert_eq!(e.to_string(), "point 0 has a non-finite coordinate (-inf)");
        let e = Error::VertexOutOfRange {
            edge: 2,
            vertex: 9,
            vertices: 5,
        };
        assert_eq!(
            e.to_string(),
            "edge 2 names vertex 9, but the graph has only 5 vertices"
        );
    }
}
