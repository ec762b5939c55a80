//! Uniform subdivision of polygons: the Lane–Riesenfeld algorithm of any degree (Chaikin's
//! algorithm is degree 2), the four-point interpolating scheme, subdivision masks with their
//! difference schemes, and the limit points of uniform B-spline subdivision.
//!
//! # Indexing: one round, one mask
//!
//! A round maps a polygon c to a polygon b with twice as many vertices, each new vertex an
//! affine combination of old ones with fixed weights, the **mask** α [PPB, §8.4, §8.8]:
//!
//! b_i = Σ_j c_j α_{i−2j}, the characteristic polynomial α(z) = Σ_k α_k z^k ([`Mask`]).
//!
//! For the Lane–Riesenfeld algorithm of degree d the mask is α_i = 2^{−d}·C(d + 1, i),
//! i = 0, …, d + 1, and with this indexing the uniform spline Σ c_j N^d(u − j) on the integers
//! equals Σ b_i N^d(2u − i) on the half-integers [PPB, §8.2–8.4]: the new polygon is the
//! control polygon of the *same* spline on the halved knots. The four-point scheme's mask is
//! centred (α_{±3} = −w, α_{±1} = ½ + w, α_0 = 1): b_{2i} = c_i and
//! b_{2i+1} = −w c_{i−1} + (½ + w)(c_i + c_{i+1}) − w c_{i+2} [PPB, §8.9, §8.10].
//!
//! # Closed and open polygons
//!
//! The course subdivides bi-infinite polygons. A **closed** polygon of n vertices is the
//! periodic one (indices mod n), and a round gives exactly 2n vertices, b_0, …, b_{2n−1} in
//! the indexing above. An **open** polygon keeps what its data determine:
//!
//! - Lane–Riesenfeld of degree d: c_0, …, c_{n−1} are the control points of the uniform
//!   spline on the knots 0, 1, …, n + d, whose domain is [d, n]; a round returns b_d, …,
//!   b_{2n−1}, the 2n − d control points of that spline on the halved knots (the ones whose
//!   B-splines meet the domain). The curve is unchanged and the polygon's ends move inwards,
//!   towards s(d) and s(n): the ends are *not* interpolated (Chaikin's open polygon loses its
//!   two end corners). After k rounds there are 2^k(n − d) + d vertices. It needs n ≥ d + 1.
//! - The four-point scheme: each end gets one ghost point by cubic extrapolation,
//!   c_{−1} = 4c_0 − 6c_1 + 4c_2 − c_3 (and its mirror at the end), so the new point next to
//!   an end is, for w = 1/16, the value of the cubic through the first four points; the end
//!   points are interpolated, cubic precision holds up to the ends, and a round gives 2n − 1
//!   vertices. This end rule is not in the course (it treats bi-infinite polygons only). It
//!   needs n ≥ 4.
//!
//! A closed polygon needs at least 3 vertices for every scheme.
//!
//! | file | problem | time |
//! |---|---|---|
//! | `mask.rs` | [`Mask`]: the characteristic polynomial of a scheme, [`Mask::lane_riesenfeld`], [`Mask::four_point`], one or k rounds of any mask ([`Mask::refine`]) [PPB, §8.4, §8.8] | Θ(L·N) |
//! | `lane_riesenfeld.rs` | [`lane_riesenfeld`] (doubling, then d rounds of midpoints; its steps: [`lane_riesenfeld_trace`]), [`chaikin`] [PPB, §8.2–8.4] | Θ(d·N) |
//! | `four_point.rs` | [`four_point`]: the interpolating four-point scheme with tension w [PPB, §8.9] | Θ(N) |
//! | `limit.rs` | [`limit_stencil`], [`limit_points`]: where each vertex goes in the limit, exactly [PPB, §8.1, §8.3] | Θ(d² + n·d·D) |
//! | `difference.rs` | [`Mask::difference`], [`Mask::divided_difference`], [`Mask::norm`]: the difference schemes of the convergence analysis [PPB, §8.6–8.8, §8.10] | Θ(L) |
//!
//! Here n is the input's vertex count, k the number of rounds, N ≤ n·2^k the output's, L the
//! mask's length and D the dimension. The output grows like n·2^k, so k rounds are refused
//! with [`Error::LimitExceeded`] naming
//! [`MAX_SUBDIVISION_POINTS`](crate::limits::MAX_SUBDIVISION_POINTS) before anything beyond
//! it is allocated.
//!
//! # Errata of the course text
//!
//! [PPB, §8.9] prints the four-point rule with garbled indices (p_{2i−1}^{k+1} = p_{i+2}^k and
//! a combination of p_{i−3}, …, p_i); its characteristic polynomial in §8.10,
//! −w + (½ + w)z² + z³ + (½ + w)z⁴ − wz⁶, is z³ times the standard form's above, with the
//! same w (so w = 1/16 is the tension with cubic precision in both). §8.10 then writes
//! γ(z) = 2β(z)/(1 + z) but prints the coefficients of β(z)/(1 + z); the divided-difference
//! scheme 2β(z)/(1 + z) is −2w + 4wz + (1 − 4w)z² + 4wz³ − 2wz⁴, twice the printed one (whose
//! coefficients sum to ½, where 2β(1)/2 = 1). The tests check both against
//! [`Mask::difference`] and [`Mask::divided_difference`].
//!
//! ```
//! use compgeo::spline::subdivision::{chaikin, Topology};
//! use compgeo::spline::Point;
//!
//! // One round of Chaikin's algorithm on an open polygon cuts every corner at ¼ and ¾.
//! let p = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0]].map(Point::new);
//! let q = chaikin(&p, 1, Topology::Open)?;
//! assert_eq!(q, [[1.0, 0.0], [3.0, 0.0], [4.0, 1.0], [4.0, 3.0]].map(Point::new));
//! # Ok::<(), compgeo::Error>(())
//! ```

mod difference;
mod four_point;
mod lane_riesenfeld;
mod limit;
mod mask;

use crate::spline::scalar::{validate_points, Point, Scalar};
use crate::{Error, Result};

/// The subdivision algorithms, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 5] = [
    &lane_riesenfeld::LANE_RIESENFELD,
    &four_point::FOUR_POINT,
    &mask::REFINE,
    &limit::LIMIT_POINTS,
    &difference::DIFFERENCE,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::difference::DIFFERENCE;
    pub(crate) use super::four_point::FOUR_POINT;
    pub(crate) use super::lane_riesenfeld::LANE_RIESENFELD;
    pub(crate) use super::limit::LIMIT_POINTS;
    pub(crate) use super::mask::REFINE;
}

pub use four_point::{four_point, four_point_with};
pub use lane_riesenfeld::{
    chaikin, lane_riesenfeld, lane_riesenfeld_trace, lane_riesenfeld_with, LaneRiesenfeldStep,
};
pub use limit::{limit_points, limit_points_with, limit_stencil};
pub use mask::Mask;

/// Whether a polygon closes on itself (its indices taken mod n) or has two ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Topology {
    /// Two ends: the first and last vertices have one neighbour each.
    Open,
    /// Closed: the last vertex is joined to the first.
    Closed,
}

/// The fewest vertices a closed polygon may have.
const MIN_CLOSED: usize = 3;

/// Validates a polygon: not empty, every coordinate finite, at least `open` vertices if open
/// and [`MIN_CLOSED`] if closed.
fn validate_polygon<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    topology: Topology,
    open: usize,
    what: &'static str,
) -> Result<()> {
    validate_points(points, what)?;
    let needed = match topology {
        Topology::Open => open,
        Topology::Closed => MIN_CLOSED,
    };
    if points.len() < needed {
        return Err(Error::TooFew {
            what,
            needed,
            got: points.len(),
        });
    }
    Ok(())
}

/// The vertex count after `rounds` rounds, each mapping m vertices to `next(m)` (which must
/// grow strictly, so the loop ends once the limit is passed), checked against
/// [`MAX_SUBDIVISION_POINTS`](crate::limits::MAX_SUBDIVISION_POINTS) after every round.
pub(crate) fn output_size(n: usize, rounds: usize, next: impl Fn(u128) -> u128) -> Result<usize> {
    let mut m = n as u128;
    for _ in 0..rounds {
        m = next(m);
        crate::limits::SUBDIVISION_POINTS.check(m)?;
    }
    Ok(m as usize)
}

/// `points` if every coordinate is finite, else [`Error::Overflow`]: with `f64`, affine
/// combinations of points near the top of the double range can overflow.
fn finite<S: Scalar, const D: usize>(
    points: Vec<Point<S, D>>,
    what: &'static str,
) -> Result<Vec<Point<S, D>>> {
    if S::EXACT || points.iter().all(Point::is_finite) {
        Ok(points)
    } else {
        Err(Error::Overflow { what })
    }
}
