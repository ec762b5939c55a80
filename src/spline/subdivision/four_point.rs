//! The four-point interpolating scheme of Dyn, Gregory and Levin with tension w.
//!
//! The problem: refine a polygon so that the polygons converge to a smooth curve *through*
//! the given points. The idea [PPB, §8.9] (in the standard form; the course's indices are
//! garbled, see the module docs of [`subdivision`](super)): keep every vertex,
//! p_{2i} ← p_i, and insert between p_i and p_{i+1}
//!
//! p_{2i+1} = −w p_{i−1} + (½ + w)(p_i + p_{i+1}) − w p_{i+2}.
//!
//! For w = 1/16 the new point is the value at i + ½ of the cubic through the four points, so
//! samples of a cubic at the integers map to its samples at the half-integers (cubic
//! precision, [PPB, §8.9, Obs. 6]). The difference scheme contracts for |w| < ¼, so the
//! polygons converge to a continuous curve, and the limit is C¹ for 0 < w < (√5 − 1)/8
//! [PPB, §8.10, Obs. 8]; any finite w is accepted.
//!
//! Closed polygons are periodic (n vertices become 2n). An open polygon gets one ghost point
//! at each end by cubic extrapolation, p_{−1} = 4p_0 − 6p_1 + 4p_2 − p_3 and
//! p_n = 4p_{n−1} − 6p_{n−2} + 4p_{n−3} − p_{n−4}, which the course does not treat: the ends
//! are interpolated, cubic precision holds up to them, and n vertices become 2n − 1.
//!
//! # Complexity
//!
//! Θ(N) time for k rounds, N ≤ n·2^k the output size; Θ(N·D) space.
//!
//! Invariants the tests check (exactly, on rationals): the polygon is interpolated, a cubic's
//! integer samples map to its half-integer samples for w = 1/16 (open and closed), and a
//! closed round equals a round of [`Mask::four_point`](super::Mask::four_point).

use super::{finite, output_size, validate_polygon, Topology};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::Result;

/// The four-point scheme, declared.
pub(crate) const FOUR_POINT: Declaration = Declaration {
    problem: "subdivision",
    name: "four-point",
    function: "spline::subdivision::four_point",
    file: "src/spline/subdivision/four_point.rs",
    summary: "k rounds of the interpolating four-point scheme with tension w (w = 1/16 reproduces cubics); open ends by cubic extrapolation",
    time: "Θ(N), N ≤ n·2^k the output size",
    space: "Θ(N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per inserted point and per ghost point: m per round on a closed polygon of m vertices, m + 1 on an open one",
    source: "[PPB, §8.9, §8.10]",
    claims: &[on(
        "random-closed",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// `rounds` rounds of the four-point scheme with tension w. See [`four_point_with`].
///
/// # Errors
///
/// [`Error::Empty`](crate::Error::Empty), [`Error::NonFinite`](crate::Error::NonFinite) for a
/// bad vertex; [`Error::InvalidParameter`](crate::Error::InvalidParameter) naming
/// `"tension"` if w is NaN or infinite; [`Error::TooFew`](crate::Error::TooFew) for a closed
/// polygon of fewer than 3 vertices or an open one of fewer than 4;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the output would pass
/// [`MAX_SUBDIVISION_POINTS`](crate::limits::MAX_SUBDIVISION_POINTS);
/// [`Error::Overflow`](crate::Error::Overflow) if, with `f64`, a vertex overflows.
///
/// # Complexity
///
/// Θ(N), N ≤ n·2^k the output size; Θ(N·D) space.
///
/// ```
/// use compgeo::spline::subdivision::{four_point, Topology};
/// use compgeo::spline::Point;
///
/// // Samples of u³ at 0, 1, 2, 3 become samples at 0, ½, 1, …, 3.
/// let p = [0.0, 1.0, 8.0, 27.0].map(|y| Point::new([y]));
/// let q = four_point(&p, &(1.0 / 16.0), 1, Topology::Open)?;
/// let cubes: Vec<_> = (0..7).map(|i| Point::new([(i as f64 / 2.0).powi(3)])).collect();
/// assert_eq!(q, cubes);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn four_point<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    tension: &S,
    rounds: usize,
    topology: Topology,
) -> Result<Vec<Point<S, D>>> {
    four_point_with(points, tension, rounds, topology, &mut NoCount)
}

/// [`four_point`], counting one [`arithmetic_operation`](Counter::arithmetic_operation) per
/// inserted point (a combination of four) and per ghost point.
///
/// Follows [PPB, §8.9] in the standard form.
///
/// # Errors
///
/// As [`four_point`].
///
/// # Complexity
///
/// Θ(N), N ≤ n·2^k the output size; Θ(N·D) space.
///
/// # Counts
///
/// Per round on m vertices: m on a closed polygon (n(2^k − 1) in all), m − 1 + 2 on an open
/// one.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::subdivision::{four_point_with, Topology};
/// use compgeo::spline::Point;
///
/// let p: Vec<Point<f64, 1>> = (0..6).map(|i| Point::new([i as f64])).collect();
/// let mut c = Counts::default();
/// let q = four_point_with(&p, &0.0625, 2, Topology::Open, &mut c)?;
/// assert_eq!((q.len(), c.arithmetic_operations), (21, 7 + 12));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn four_point_with<S: Scalar, const D: usize, C: Counter>(
    points: &[Point<S, D>],
    tension: &S,
    rounds: usize,
    topology: Topology,
    counter: &mut C,
) -> Result<Vec<Point<S, D>>> {
    validate_parameter(tension, "tension")?;
    validate_polygon(points, topology, 4, "polygon")?;
    match topology {
        Topology::Closed => output_size(points.len(), rounds, |m| 2 * m)?,
        Topology::Open => output_size(points.len(), rounds, |m| 2 * m - 1)?,
    };
    let w = tension.clone();
    let inner = S::from_ratio(1, 2) + &w;
    let insert = |a: &Point<S, D>, b: &Point<S, D>, c: &Point<S, D>, d: &Point<S, D>| {
        (b.clone() + c) * &inner - &((a.clone() + d) * &w)
    };
    let mut current = points.to_vec();
    for _ in 0..rounds {
        let m = current.len();
        let mut next = Vec::with_capacity(2 * m);
        match topology {
            Topology::Closed => {
                for i in 0..m {
                    let at = |k: usize| &current[(i + k) % m];
                    next.push(current[i].clone());
                    next.push(insert(at(m - 1), at(0), at(1), at(2)));
                    counter.arithmetic_operation();
                }
            }
            Topology::Open => {
                let before = ghost(&current[0], &current[1], &current[2], &current[3]);
                let after = ghost(
                    &current[m - 1],
                    &current[m - 2],
                    &current[m - 3],
                    &current[m - 4],
                );
                counter.arithmetic_operation();
                counter.arithmetic_operation();
                let at = |k: usize| -> &Point<S, D> {
                    // k is the index plus one: 0 is the ghost before, m + 1 the one after.
                    match k {
                        0 => &before,
                        k if k == m + 1 => &after,
                        k => &current[k - 1],
                    }
                };
                for (i, p) in current[..m - 1].iter().enumerate() {
                    next.push(p.clone());
                    next.push(insert(at(i), at(i + 1), at(i + 2), at(i + 3)));
                    counter.arithmetic_operation();
                }
                next.push(current[m - 1].clone());
            }
        }
        current = next;
    }
    finite(current, "four-point subdivision")
}

/// The value at −1 of the cubic through p_0, p_1, p_2, p_3 at 0, 1, 2, 3:
/// 4p_0 − 6p_1 + 4p_2 − p_3 (the fourth difference of a cubic is zero).
fn ghost<S: Scalar, const D: usize>(
    p0: &Point<S, D>,
    p1: &Point<S, D>,
    p2: &Point<S, D>,
    p3: &Point<S, D>,
) -> Point<S, D> {
    let four = S::from_i64(4);
    let six = S::from_i64(6);
    (p0.clone() + p2) * &four - &(p1.clone() * &six) - p3
}
