//! Every size limit of the crate, in one place.
//!
//! A size that a caller gives as a number (a degree, a vertex count, how many points to
//! generate) or that the library derives from one (the edges of `K_n`) is checked against
//! one of these limits *before* anything is allocated, so that no argument and no input
//! number can make the library abort on a failed allocation or run without end. The error is
//! [`Error::LimitExceeded`], whose message names the limit: "graph edge count 268412865
//! exceeds MAX_EDGES = 67108864".
//!
//! The limits are generous: each is far beyond what the algorithms are useful for, and
//! chosen so that the memory a call needs at the limit stays within a few GiB. Sizes that
//! are simply the length of the caller's data (the points of a hull, the control points of
//! a curve) need no limit of their own beyond the ones below: the caller already holds
//! them.
//!
//! `docs/design.md` ("Size limits") has the same table with the reasons; a test compares
//! it with [`ALL`].
//!
//! ```
//! use compgeo::graph::Graph;
//! use compgeo::limits::MAX_VERTICES;
//! use compgeo::Error;
//!
//! let e = Graph::from_edges(MAX_VERTICES + 1, &[]).unwrap_err();
//! assert!(matches!(e, Error::LimitExceeded { limit: "MAX_VERTICES", .. }));
//! assert_eq!(e.to_string(), "graph vertex count 67108865 exceeds MAX_VERTICES = 67108864");
//! ```

use crate::{Error, Result};

/// The most points [`gen::points`](crate::gen::points) generates in one call: 2^26.
///
/// 16 bytes a point, so 1 GiB at the limit (the command line prints about 40 bytes of JSON
/// a point). It also keeps every exactly constructed kind exact: parabola `x^2 <= 2^52`,
/// collinear and grid coordinates below 2^53.
pub const MAX_POINTS: usize = 1 << 26;

/// The most points [`PointKind::Cocircular`](crate::gen::PointKind::Cocircular) produces:
/// 393 660, the lattice-point count `4 * 5 * 3^9` of the family's largest radius
/// `5^2 * 13 * 17 * 29 * 37 * 41 * 53 * 61 * 73 * 89`, whose points have integer
/// coordinates below 2^53.
pub const MAX_COCIRCULAR: usize = 393_660;

/// The most keys [`gen::sequence`](crate::gen::sequence) and
/// [`gen::sequence_f64`](crate::gen::sequence_f64) generate in one call: 2^26 (8 bytes a
/// key, 512 MiB).
pub const MAX_KEYS: usize = 1 << 26;

/// The most vertices a [`Graph`](crate::graph::Graph) or
/// [`WeightedGraph`](crate::graph::WeightedGraph) may have, and
/// [`gen::graph`](crate::gen::graph) generates: 2^26.
///
/// A graph is read as a number (`{"vertices": n, ...}`), so a few bytes of input could
/// otherwise ask for any amount of memory. Vertex ids are stored in 32 bits; the searches
/// and colourings keep a few arrays of 4 to 8 bytes per vertex, about 1 to 2 GiB at the
/// limit.
pub const MAX_VERTICES: usize = 1 << 26;

/// The most edges a graph may have, and [`gen::graph`](crate::gen::graph) generates: 2^26.
///
/// An edge costs about 40 bytes while a weighted graph is built (16 in the edge list, 8 for
/// its weight, 16 in the compressed adjacency), about 2.5 GiB at the limit. It bounds the
/// generated families by their edge count (`K_n` has n(n − 1)/2 edges, so `n <= 11 585`)
/// and still admits the Delaunay graph of 2·10^7 points (at most 3n − 6 edges) that the
/// Euclidean minimum spanning tree builds.
pub const MAX_EDGES: usize = 1 << 26;

/// The highest degree of a Bézier curve ([`Bezier::new`](crate::spline::Bezier::new),
/// [`Bezier::elevate_to`](crate::spline::Bezier::elevate_to)), of a Bernstein polynomial
/// ([`bernstein`](crate::spline::bernstein) and its siblings), of an interpolating
/// polynomial ([`lagrange`](crate::spline::lagrange), [`newton`](crate::spline::newton()),
/// [`newton_hermite`](crate::spline::newton_hermite)), and the highest derivative order
/// asked of a composite curve
/// ([`end_derivatives`](crate::spline::CompositeBezier::end_derivatives)): 2^16.
///
/// A degree is a number: `elevate_to(2^32)` would otherwise allocate 64 GiB. At the limit a
/// curve holds 65 537 control points, and the Θ(n²) algorithms on it (de Casteljau, Newton's
/// divided differences) take about 2^31 steps; no use of the Bernstein basis in `f64` comes
/// near (C(2^16, 2^15) has 19 726 digits).
pub const MAX_DEGREE: usize = 1 << 16;

/// The most unknowns of a dense linear system the interpolation module solves
/// ([`vandermonde`](crate::spline::vandermonde),
/// [`vandermonde_hermite`](crate::spline::vandermonde_hermite), and
/// [`fit_bezier`](crate::spline::fit_bezier), whose unknowns are the degree plus one, plus
/// two with clamped ends): 2^10.
///
/// The matrix has n² entries and Gaussian elimination takes Θ(n³) steps: 2^20 entries and
/// about 3.6·10^8 steps at the limit, and every doubling beyond it would multiply the time
/// by eight. (The systems are ill-conditioned long before: in `f64` a Vandermonde matrix of
/// a few dozen nodes already loses most digits.)
pub const MAX_DENSE_UNKNOWNS: usize = 1 << 10;

/// The most points [`Bezier::forward_differences`](crate::spline::Bezier::forward_differences)
/// computes in one call: 2^26. The count is a number; at the limit the points of a curve in
/// the plane take 1 GiB in `f64`.
pub const MAX_SAMPLES: usize = 1 << 26;

/// The longest input a sort's step table ([`sort::trace`](crate::sort::trace)) accepts:
/// 1000. Bubble sort's table has a row per comparison, n(n − 1)/2 of them; a trace is meant
/// for lists a reader can follow.
pub const TRACE_MAX_LEN: usize = 1000;

/// The most vertices a search's step table
/// ([`graph::search_trace`](crate::graph::search_trace)) accepts: 1000. Each row copies the
/// list Q, so a trace of n vertices holds up to 2n rows of up to n entries.
pub const TRACE_MAX_VERTICES: usize = 1000;

/// The most entries a step trace ([`trace`](crate::trace): `hull::graham_trace`,
/// `delaunay::lawson_trace`, `graph::prim_trace`, ...) stores: 2^20. A frame counts one, plus
/// one per index or point it holds. Traces copy the state at every step, so they grow faster
/// than the run (Jarvis's march on n points in convex position: n² frames of up to n
/// indices); a trace is meant for inputs a reader can follow, and about 100 MiB at the limit.
pub const TRACE_MAX_ENTRIES: usize = 1 << 20;

/// The most frames a step page ([`draw::StepPage`](crate::draw::StepPage), `draw --steps`)
/// holds: 4096. Each frame is a whole picture, so a page grows with frames times points; a
/// page is meant for a run a reader steps through.
pub const STEP_PAGE_MAX_FRAMES: usize = 4096;

/// The most points the incremental and divide-and-conquer Delaunay builders take: 2^29.
/// About 6n half-edges get 32-bit ids.
pub const MAX_TRIANGULATION_POINTS: usize = 1 << 29;

/// The most points Fortune's sweep takes: 2^28. Fewer than 6n events are ever queued, and
/// their ids are 32-bit.
pub const MAX_FORTUNE_POINTS: usize = 1 << 28;

/// The most segments [`Bezier::flatten`](crate::spline::Bezier::flatten) produces before it
/// reports that the tolerance is too small for the curve: 2^20.
pub const MAX_FLATTEN_SEGMENTS: usize = 1 << 20;

/// The most pairs of pieces [`intersections`](crate::spline::intersections) examines before
/// it reports that the curves overlap (or the tolerance is too small to separate their
/// intersections): 2^20.
pub const MAX_INTERSECTION_PAIRS: usize = 1 << 20;

/// The most values of a basis table: the Lagrange basis the command line's
/// `interpolate lagrange` prints (one per node and evaluation parameter, about 400 MB of JSON
/// at the limit: its input is two lists, and their lengths multiply), and the (k + 1)(d + 1)
/// derivatives of the B-spline basis that
/// [`KnotVector::basis_derivatives`](crate::spline::KnotVector::basis_derivatives) returns
/// (two numbers, the order and the degree, multiply): 2^24.
pub const MAX_BASIS_TABLE: usize = 1 << 24;

/// The most knots a knot-vector builder
/// ([`KnotVector::clamped_uniform`](crate::spline::KnotVector::clamped_uniform),
/// [`KnotVector::uniform`](crate::spline::KnotVector::uniform)) makes: n + d + 1 for n
/// control points of degree d, 2^26. The count is a number; 512 MiB of `f64` knots at the
/// limit.
pub const MAX_KNOTS: usize = 1 << 26;

/// The most vertices a subdivided polygon may have after its rounds
/// ([`lane_riesenfeld`](crate::spline::subdivision::lane_riesenfeld),
/// [`four_point`](crate::spline::subdivision::four_point),
/// [`Mask::refine`](crate::spline::subdivision::Mask::refine)): 2^24.
///
/// k rounds multiply the vertices by about 2^k, so a few bytes of input (`--rounds 40`) could
/// otherwise ask for any amount of memory; the rounds are refused before the first one runs.
/// 256 MiB of planar `f64` points at the limit (exact rationals take several times more).
pub const MAX_SUBDIVISION_POINTS: usize = 1 << 24;
/// The most control polygons [`BetaSpline::subdivide`](crate::spline::BetaSpline::subdivide)
/// returns: m·2ᵏ for m segments and k rounds, 2^20. The round count is a number, and each
/// round doubles the output; four points a polygon, 64 MiB of planar `f64` points at the limit.
pub const MAX_SUBDIVIDED_PIECES: usize = 1 << 20;

/// The most vertices a [`PolygonMesh`](crate::mesh::PolygonMesh) may have: 2^26. Vertex
/// ids are stored in 32 bits; an OBJ file is refused at its 2^26 + 1st `v` line, before it
/// is all read. 1.5 GiB of `f64` positions in R³ at the limit.
pub const MAX_MESH_VERTICES: usize = 1 << 26;

/// The most corners (half-edges, the sum of the face sizes) a
/// [`PolygonMesh`](crate::mesh::PolygonMesh) may have, given or produced by subdivision:
/// 2^26.
///
/// Each round of a subdivision scheme multiplies the corners by about four, so a round count
/// (`--rounds 20`) could otherwise ask for any amount of memory; the rounds are refused
/// before the first one runs. A half-edge takes 16 bytes of connectivity, 1 GiB at the
/// limit, plus the positions.
pub const MAX_MESH_CORNERS: usize = 1 << 26;

/// One limit: its constant's name, its value and what it bounds, as the error message and
/// the table in `docs/design.md` say them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limit {
    /// The constant's name in this module, e.g. `"MAX_EDGES"`.
    pub name: &'static str,
    /// Its value.
    pub max: usize,
    /// What it bounds, as the error names it: "graph edge count".
    pub what: &'static str,
}

impl Limit {
    /// `Ok(value)` as a `usize` if `value <= self.max`, else [`Error::LimitExceeded`]. Takes
    /// a `u128` so that a size computed from others (n(n − 1)/2, n²) is checked before it
    /// can overflow.
    pub(crate) fn check(self, value: u128) -> Result<usize> {
        if value <= self.max as u128 {
            Ok(value as usize)
        } else {
            Err(Error::LimitExceeded {
                what: self.what,
                value,
                limit: self.name,
                max: self.max,
            })
        }
    }
}

/// [`MAX_POINTS`].
pub(crate) const POINTS: Limit = Limit {
    name: "MAX_POINTS",
    max: MAX_POINTS,
    what: "generated point count",
};
/// [`MAX_COCIRCULAR`].
pub(crate) const COCIRCULAR: Limit = Limit {
    name: "MAX_COCIRCULAR",
    max: MAX_COCIRCULAR,
    what: "generated cocircular point count",
};
/// [`MAX_KEYS`].
pub(crate) const KEYS: Limit = Limit {
    name: "MAX_KEYS",
    max: MAX_KEYS,
    what: "generated key count",
};
/// [`MAX_VERTICES`].
pub(crate) const VERTICES: Limit = Limit {
    name: "MAX_VERTICES",
    max: MAX_VERTICES,
    what: "graph vertex count",
};
/// [`MAX_EDGES`].
pub(crate) const EDGES: Limit = Limit {
    name: "MAX_EDGES",
    max: MAX_EDGES,
    what: "graph edge count",
};
/// [`MAX_DEGREE`].
pub(crate) const DEGREE: Limit = Limit {
    name: "MAX_DEGREE",
    max: MAX_DEGREE,
    what: "curve degree or derivative order",
};
/// [`MAX_DENSE_UNKNOWNS`].
pub(crate) const DENSE_UNKNOWNS: Limit = Limit {
    name: "MAX_DENSE_UNKNOWNS",
    max: MAX_DENSE_UNKNOWNS,
    what: "dense linear system size",
};
/// [`MAX_SAMPLES`].
pub(crate) const SAMPLES: Limit = Limit {
    name: "MAX_SAMPLES",
    max: MAX_SAMPLES,
    what: "sampled point count",
};
/// [`TRACE_MAX_LEN`].
pub(crate) const TRACE_LEN: Limit = Limit {
    name: "TRACE_MAX_LEN",
    max: TRACE_MAX_LEN,
    what: "traced sort input length",
};
/// [`TRACE_MAX_VERTICES`].
pub(crate) const TRACE_VERTICES: Limit = Limit {
    name: "TRACE_MAX_VERTICES",
    max: TRACE_MAX_VERTICES,
    what: "traced search vertex count",
};
/// [`TRACE_MAX_ENTRIES`].
pub(crate) const TRACE_ENTRIES: Limit = Limit {
    name: "TRACE_MAX_ENTRIES",
    max: TRACE_MAX_ENTRIES,
    what: "step trace entry count",
};
/// [`STEP_PAGE_MAX_FRAMES`].
pub(crate) const STEP_PAGE_FRAMES: Limit = Limit {
    name: "STEP_PAGE_MAX_FRAMES",
    max: STEP_PAGE_MAX_FRAMES,
    what: "step page frame count",
};
/// [`MAX_TRIANGULATION_POINTS`].
pub(crate) const TRIANGULATION_POINTS: Limit = Limit {
    name: "MAX_TRIANGULATION_POINTS",
    max: MAX_TRIANGULATION_POINTS,
    what: "triangulated point count",
};
/// [`MAX_FORTUNE_POINTS`].
pub(crate) const FORTUNE_POINTS: Limit = Limit {
    name: "MAX_FORTUNE_POINTS",
    max: MAX_FORTUNE_POINTS,
    what: "Fortune sweep point count",
};
/// [`MAX_FLATTEN_SEGMENTS`].
pub(crate) const FLATTEN_SEGMENTS: Limit = Limit {
    name: "MAX_FLATTEN_SEGMENTS",
    max: MAX_FLATTEN_SEGMENTS,
    what: "flattened segment count",
};
/// [`MAX_INTERSECTION_PAIRS`].
pub(crate) const INTERSECTION_PAIRS: Limit = Limit {
    name: "MAX_INTERSECTION_PAIRS",
    max: MAX_INTERSECTION_PAIRS,
    what: "examined piece pair count",
};
/// [`MAX_BASIS_TABLE`].
pub(crate) const BASIS_TABLE: Limit = Limit {
    name: "MAX_BASIS_TABLE",
    max: MAX_BASIS_TABLE,
    what: "basis table size",
};
/// [`MAX_KNOTS`].
pub(crate) const KNOTS: Limit = Limit {
    name: "MAX_KNOTS",
    max: MAX_KNOTS,
    what: "built knot count",
};

/// [`MAX_SUBDIVISION_POINTS`].
pub(crate) const SUBDIVISION_POINTS: Limit = Limit {
    name: "MAX_SUBDIVISION_POINTS",
    max: MAX_SUBDIVISION_POINTS,
    what: "subdivided polygon point count",
};

/// [`MAX_SUBDIVIDED_PIECES`].
pub(crate) const SUBDIVIDED_PIECES: Limit = Limit {
    name: "MAX_SUBDIVIDED_PIECES",
    max: MAX_SUBDIVIDED_PIECES,
    what: "subdivided polygon count",
};

/// [`MAX_MESH_VERTICES`].
pub(crate) const MESH_VERTICES: Limit = Limit {
    name: "MAX_MESH_VERTICES",
    max: MAX_MESH_VERTICES,
    what: "mesh vertex count",
};

/// [`MAX_MESH_CORNERS`].
pub(crate) const MESH_CORNERS: Limit = Limit {
    name: "MAX_MESH_CORNERS",
    max: MAX_MESH_CORNERS,
    what: "mesh corner count",
};

/// Every limit, in the order of the table in `docs/design.md`.
pub const ALL: [Limit; 22] = [
    POINTS,
    COCIRCULAR,
    KEYS,
    VERTICES,
    EDGES,
    DEGREE,
    DENSE_UNKNOWNS,
    SAMPLES,
    TRACE_LEN,
    TRACE_VERTICES,
    TRACE_ENTRIES,
    STEP_PAGE_FRAMES,
    TRIANGULATION_POINTS,
    FORTUNE_POINTS,
    FLATTEN_SEGMENTS,
    INTERSECTION_PAIRS,
    BASIS_TABLE,
    KNOTS,
    SUBDIVISION_POINTS,
    SUBDIVIDED_PIECES,
    MESH_VERTICES,
    MESH_CORNERS,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_passes_the_limit_and_rejects_one_more() {
        assert_eq!(EDGES.check(MAX_EDGES as u128), Ok(MAX_EDGES));
        let e = EDGES.check(MAX_EDGES as u128 + 1).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!(
                "graph edge count {} exceeds MAX_EDGES = {MAX_EDGES}",
                MAX_EDGES + 1
            )
        );
        // Sizes computed in u128 beyond u64 are reported as they are.
        let e = DEGREE.check(u128::MAX).unwrap_err();
        assert!(e.to_string().contains(&u128::MAX.to_string()), "{e}");
    }

    #[test]
    fn names_are_unique() {
        for (i, a) in ALL.iter().enumerate() {
            assert!(ALL[i + 1..].iter().all(|b| b.name != a.name), "{}", a.name);
        }
    }
}
