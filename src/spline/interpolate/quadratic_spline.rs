//! C¹ piecewise quadratic (parabolic) interpolation, open and closed.
//!
//! Follows [SPL, §2] ("Parábolas C1 a trozos"): piece i has the control points
//! `c_{2i}, c_{2i+1}, c_{2i+2}` over `[u_i, u_{i+1}]`, the joints are the data
//! (`c_{2i} = a_i`), and C¹ continuity at `u_i` is relation (2),
//! `c_{2i} = (Δu_i c_{2i−1} + Δu_{i−1} c_{2i+1}) / (Δu_{i−1} + Δu_i)`. An open curve through
//! `N + 1` points has one degree of freedom left (system (4) has `N − 1` equations for `N`
//! unknowns): the course fixes it with a tangent at one end. A closed curve closes the system
//! cyclically (5); its matrix is regular for an odd number of pieces and singular for an even
//! number, whatever the knots (the course: "regular for N even", counting N + 1 pieces).
//!
//! The open spline is only as well conditioned as the course warns: each inner point reflects
//! the previous one through a data point with the ratio `Δu_i/Δu_{i−1}`, so a perturbation of
//! the start tangent travels along the whole curve.
//!
//! # Complexity
//!
//! Θ(ND) time and space for N + 1 points in R^D (one pass; the closed spline solves its
//! cyclic system by telescoping, also in one pass).

use super::validate::{check_knots_and_points, overflow, singular};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::spline::CompositeBezier;
use crate::{Error, Result};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and claims.
pub(crate) const QUADRATIC: Declaration = Declaration {
    problem: "interpolate",
    name: "quadratic-spline",
    function: "spline::quadratic_spline",
    file: "src/spline/interpolate/quadratic_spline.rs",
    summary: "the C¹ parabolic spline with a tangent at one end",
    time: "Θ(N·D)",
    space: "Θ(N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly N point operations for N pieces: one per inner Bézier point",
    source: "[SPL, §2]",
    claims: &[on(
        "random-points",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and claims.
pub(crate) const CLOSED_QUADRATIC: Declaration = Declaration {
    problem: "interpolate",
    name: "closed-quadratic-spline",
    function: "spline::closed_quadratic_spline",
    file: "src/spline/interpolate/quadratic_spline.rs",
    summary: "the closed C¹ parabolic spline",
    time: "Θ(N·D)",
    space: "Θ(N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly 2N point operations for N pieces: N − 1 for the recurrence, one for the closing condition, N for the inner points",
    source: "[SPL, §2]",
    claims: &[on("random-points", Bound::Linear, Operation::ArithmeticOperations)],
};

/// The C¹ quadratic spline through `points` at the knots `partition` whose first derivative at
/// `u_0` is `start_tangent` ([SPL, §2]).
///
/// The idea: `c_1 = a_0 + Δu_0 v / 2` (a parabola's end derivative is `2 (c_1 − c_0)/Δu`),
/// then relation (2) solved for the next inner point,
/// `c_{2i+1} = a_i + (Δu_i/Δu_{i−1}) (a_i − c_{2i−1})`, piece by piece.
///
/// # Errors
///
/// [`Error::TooFew`] for fewer than two points; [`Error::InvalidParameter`] for mismatched
/// lengths or a non-finite, non-increasing partition; [`Error::NonFinite`] for a bad
/// coordinate (of the tangent: index `points.len()`).
///
/// # Complexity
///
/// Θ(N·D) time and space for `N + 1` points in R^D.
///
/// ```
/// use compgeo::spline::{quadratic_spline, Curve, Point};
///
/// // Samples of the parabola u² with its slope 0 at u = 0 give the parabola back.
/// let pts: Vec<_> = [0.0, 1.0, 4.0, 9.0].iter().map(|&y| Point::new([y])).collect();
/// let c = quadratic_spline(&[0.0, 1.0, 2.0, 3.0], &pts, &Point::new([0.0]))?;
/// assert_eq!(c.eval(&2.5)?, Point::new([6.25]));
/// assert!(c.is_c(1, &0.0));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn quadratic_spline<S: Scalar, const D: usize>(
    partition: &[S],
    points: &[Point<S, D>],
    start_tangent: &Point<S, D>,
) -> Result<CompositeBezier<S, D>> {
    quadratic_spline_with(partition, points, start_tangent, &mut NoCount)
}

/// [`quadratic_spline`], counting one [`arithmetic_operation`](Counter::arithmetic_operation)
/// per inner Bézier point (the first from the tangent, each next one by reflection): exactly
/// N for N pieces.
///
/// # Errors
///
/// As [`quadratic_spline`].
///
/// # Complexity
///
/// Θ(N·D) time and space for `N + 1` points in R^D.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{quadratic_spline_with, Point};
///
/// let pts: Vec<_> = [0.0, 1.0, 4.0, 9.0].iter().map(|&y| Point::new([y])).collect();
/// let mut c = Counts::default();
/// quadratic_spline_with(&[0.0, 1.0, 2.0, 3.0], &pts, &Point::new([0.0]), &mut c)?;
/// assert_eq!(c.arithmetic_operations, 3);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn quadratic_spline_with<S: Scalar, const D: usize, C: Counter>(
    partition: &[S],
    points: &[Point<S, D>],
    start_tangent: &Point<S, D>,
    counter: &mut C,
) -> Result<CompositeBezier<S, D>> {
    check_knots_and_points(partition, points, 2)?;
    if let Some(c) = start_tangent.coords().iter().find(|c| !c.is_finite()) {
        return Err(Error::NonFinite {
            index: points.len(),
            value: c.to_f64(),
        });
    }
    let n = points.len() - 1;
    let h: Vec<S> = partition.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    let mut inner = Vec::with_capacity(n);
    inner.push(points[0].clone() + &(start_tangent.clone() * (h[0].clone() / S::from_i64(2))));
    counter.arithmetic_operation();
    for i in 1..n {
        let ratio = h[i].clone() / &h[i - 1];
        let reflected = (points[i].clone() - &inner[i - 1]) * ratio;
        inner.push(points[i].clone() + &reflected);
        counter.arithmetic_operation();
    }
    build(partition, points, inner)
}

/// The closed C¹ quadratic spline through `points` (first and last equal) at the knots
/// `partition`: `N` pieces, C¹ also where the curve closes ([SPL, §2], relations (5)).
///
/// The idea: write every inner point as `c_{2i+1} = A_i + B_i c_1` by the recurrence of
/// [`quadratic_spline`], then the C¹ condition at the closing point fixes `c_1`. The factors
/// telescope to `B_i = (−1)ⁱ Δu_i/Δu_0`, so the closing coefficient
/// `Δu_0 B_{N−1} + Δu_{N−1} = (1 + (−1)^{N−1}) Δu_{N−1}` is `2 Δu_{N−1}` for an odd number N of
/// pieces and zero for an even one: a closed C¹ parabolic spline through an even number of
/// points exists only for special data and is never unique.
///
/// # Errors
///
/// [`Error::TooFew`] for fewer than three points (two pieces); [`Error::InvalidParameter`]
/// (`"points"`) if the first and last points differ or the number of pieces is even (the
/// system is singular), (`"partition"`) for a non-finite, non-increasing partition; mismatched lengths and bad
/// coordinates as [`quadratic_spline`].
///
/// # Complexity
///
/// Θ(N·D) time and space.
///
/// ```
/// use compgeo::spline::{closed_quadratic_spline, Point};
///
/// // A triangle's corners, three pieces: a smooth closed curve.
/// let p = |x: f64, y: f64| Point::new([x, y]);
/// let pts = [p(0.0, 0.0), p(4.0, 0.0), p(0.0, 4.0), p(0.0, 0.0)];
/// let c = closed_quadratic_spline(&[0.0, 1.0, 2.0, 3.0], &pts)?;
/// assert!(c.is_c(1, &1e-12));
/// // Four pieces: singular.
/// let square = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(0.0, 0.0)];
/// assert!(closed_quadratic_spline(&[0.0, 1.0, 2.0, 3.0, 4.0], &square).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closed_quadratic_spline<S: Scalar, const D: usize>(
    partition: &[S],
    points: &[Point<S, D>],
) -> Result<CompositeBezier<S, D>> {
    closed_quadratic_spline_with(partition, points, &mut NoCount)
}

/// [`closed_quadratic_spline`], counting one
/// [`arithmetic_operation`](Counter::arithmetic_operation) per point computed: the N − 1
/// points Aᵢ of the recurrence, the right-hand side of the closing condition, and the N inner
/// Bézier points, exactly 2N for N pieces.
///
/// # Errors
///
/// As [`closed_quadratic_spline`].
///
/// # Complexity
///
/// Θ(N·D) time and space.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{closed_quadratic_spline_with, Point};
///
/// let p = |x: f64, y: f64| Point::new([x, y]);
/// let pts = [p(0.0, 0.0), p(4.0, 0.0), p(0.0, 4.0), p(0.0, 0.0)];
/// let mut c = Counts::default();
/// closed_quadratic_spline_with(&[0.0, 1.0, 2.0, 3.0], &pts, &mut c)?;
/// assert_eq!(c.arithmetic_operations, 2 * 3);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closed_quadratic_spline_with<S: Scalar, const D: usize, C: Counter>(
    partition: &[S],
    points: &[Point<S, D>],
    counter: &mut C,
) -> Result<CompositeBezier<S, D>> {
    check_knots_and_points(partition, points, 3)?;
    let n = points.len() - 1;
    if points[0] != points[n] {
        return Err(Error::InvalidParameter {
            name: "points",
            reason: "a closed spline needs its first and last points equal".to_string(),
        });
    }
    let h: Vec<S> = partition.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    // inner_i = a[i] + b[i] * c_1.
    let mut a = vec![Point::zero()];
    let mut b = vec![S::one()];
    for i in 1..n {
        let ratio = h[i].clone() / &h[i - 1];
        // c_{2i+1} = a_i (1 + r) − r c_{2i−1}
        let next_a = points[i].clone() * (S::one() + &ratio) - &(a[i - 1].clone() * &ratio);
        let next_b = -(b[i - 1].clone() * &ratio);
        a.push(next_a);
        b.push(next_b);
        counter.arithmetic_operation();
    }
    // At the closing point: (Δu_{N−1} + Δu_0) a_0 = Δu_0 c_{2N−1} + Δu_{N−1} c_1.
    if n % 2 == 0 {
        return Err(singular(
            "points",
            &format!(
                "a closed C1 quadratic spline with an even number of pieces ({n}) is singular \
                 (SPL §2): give an odd number of pieces"
            ),
        ));
    }
    let coefficient = h[0].clone() * &b[n - 1] + &h[n - 1];
    let rhs = points[0].clone() * (h[n - 1].clone() + &h[0]) - &(a[n - 1].clone() * &h[0]);
    let first = rhs / &coefficient;
    counter.arithmetic_operation();
    for _ in 0..n {
        counter.arithmetic_operation();
    }
    let inner: Vec<Point<S, D>> = a
        .into_iter()
        .zip(b)
        .map(|(ai, bi)| ai + &(first.clone() * &bi))
        .collect();
    build(partition, points, inner)
}

/// The composite curve with pieces `a_i, inner_i, a_{i+1}`.
fn build<S: Scalar, const D: usize>(
    partition: &[S],
    points: &[Point<S, D>],
    inner: Vec<Point<S, D>>,
) -> Result<CompositeBezier<S, D>> {
    if inner.iter().any(|p| !p.is_finite()) {
        return Err(overflow());
    }
    let pieces = inner
        .into_iter()
        .enumerate()
        .map(|(i, c)| vec![points[i].clone(), c, points[i + 1].clone()])
        .collect();
    CompositeBezier::new(partition.to_vec(), pieces)
}
