//! The limit points of Lane–Riesenfeld subdivision: where each vertex of a polygon goes as
//! the rounds continue, in closed form.
//!
//! The problem: the polygons of the Lane–Riesenfeld algorithm of degree d converge to the
//! uniform spline s(u) = Σ c_j N^d(u − j) [PPB, §8.3, Obs. 3]; which point of s does vertex
//! i tend to? The idea: vertex i is the coefficient of N^d(u − i), whose support
//! [i, i + d + 1] is centred at u_i = i + (d + 1)/2, and every round keeps the refined
//! vertices' centres on the same parameters. So the limit point of vertex i is
//! s(u_i) = Σ_m c_{i+m} M(m), with the **limit stencil** M(m) = N^d(m + (d + 1)/2), the
//! centred uniform B-spline at the integers (a symmetric mask on m = −⌊d/2⌋, …, ⌊d/2⌋,
//! summing to 1). For d = 3 it is (1, 4, 1)/6, so vertex i goes to
//! (c_{i−1} + 4c_i + c_{i+1})/6; for Chaikin (d = 2) it is (1, 6, 1)/8; for d = 1 the vertex
//! stays. The values come from the recursion of the uniform B-splines
//! N^d(x) = (x N^{d−1}(x) + (d + 1 − x) N^{d−1}(x − 1))/d at the half-integers
//! [PPB, §8.1, §5.3].
//!
//! A closed polygon has a limit point for every vertex; an open one (the spline on the knots
//! 0, …, n + d, domain [d, n]) for the vertices ⌊d/2⌋, …, n − 1 − ⌊d/2⌋, whose stencil lies
//! inside it; the first is s(d) or s(d + ½) and the last s(n) or s(n − ½), by the parity of d.
//!
//! # Complexity
//!
//! Θ(d² + n·d·D) time, Θ(d + n·D) space.
//!
//! Invariants the tests check (exactly, on rationals): the limit points of a polygon after
//! any number of rounds are points of the [`BSpline`](crate::spline::BSpline) at dyadic
//! parameters, and the stencil sums to 1.

use super::mask::check_degree;
use super::{finite, validate_polygon, Mask, Topology};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::Result;

/// The limit points, declared.
pub(crate) const LIMIT_POINTS: Declaration = Declaration {
    problem: "subdivision",
    name: "limit-points",
    function: "spline::subdivision::limit_points",
    file: "src/spline/subdivision/limit.rs",
    summary: "where each vertex goes under Lane–Riesenfeld subdivision of degree d: the stencil of the centred B-spline at the integers, e.g. (1, 4, 1)/6 for cubics",
    time: "Θ(d² + n·d·D)",
    space: "Θ(d + n·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per stencil term: (2⌊d/2⌋ + 1) per limit point",
    source: "[PPB, §8.1, §8.3]",
    claims: &[on(
        "random-closed",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The limit stencil of Lane–Riesenfeld subdivision of degree d: the mask M(m) =
/// N^d(m + (d + 1)/2), m = −⌊d/2⌋, …, ⌊d/2⌋, of the limit point Σ_m c_{i+m} M(m) of vertex i.
///
/// # Errors
///
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) for degree 0;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) beyond
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
///
/// # Complexity
///
/// Θ(d²) time, Θ(d) space.
///
/// ```
/// use compgeo::spline::subdivision::limit_stencil;
///
/// let cubic = limit_stencil::<f64>(3)?;
/// assert_eq!(cubic.start(), -1);
/// assert_eq!(cubic.coefficients(), [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0]);
/// assert_eq!(limit_stencil::<f64>(2)?.coefficients(), [0.125, 0.75, 0.125]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn limit_stencil<S: Scalar>(degree: usize) -> Result<Mask<S>> {
    check_degree(degree)?;
    // values[m] = N^k(m/2) for m = 0, …, 2(d + 1); N^0 is 1 on [0, 1).
    let len = 2 * (degree + 1) + 1;
    let mut values = vec![S::zero(); len];
    values[0] = S::one();
    values[1] = S::one();
    for k in 1..=degree {
        let inv_k = S::from_ratio(1, k as i64);
        // Downwards, so N^{k−1}(m/2 − 1) = values[m − 2] is still the old value.
        for m in (0..len).rev() {
            let x = S::from_ratio(m as i64, 2);
            let mut v = x.clone() * &values[m];
            if m >= 2 {
                v += (S::from_i64(k as i64 + 1) - &x) * &values[m - 2];
            }
            values[m] = v * &inv_k;
        }
    }
    let h = degree / 2;
    // M(j) = N^d(j + (d + 1)/2): the entry 2j + d + 1, for j = −h, …, h.
    let stencil = (0..=2 * h)
        .map(|t| values[2 * t + degree + 1 - 2 * h].clone())
        .collect();
    Mask::new(-(h as i64), stencil)
}

/// The limit point of every vertex (closed) or of every vertex whose stencil fits (open:
/// vertices ⌊d/2⌋, …, n − 1 − ⌊d/2⌋) under Lane–Riesenfeld subdivision of degree d. See
/// [`limit_points_with`].
///
/// # Errors
///
/// As [`lane_riesenfeld`](super::lane_riesenfeld) (an open polygon needs d + 1 vertices).
///
/// # Complexity
///
/// Θ(d² + n·d·D) time, Θ(d + n·D) space.
///
/// ```
/// use compgeo::spline::subdivision::{limit_points, Topology};
/// use compgeo::spline::Point;
///
/// let p = [[0.0], [6.0], [12.0], [0.0]].map(Point::new);
/// // (c₀ + 4c₁ + c₂)/6 and (c₁ + 4c₂ + c₃)/6.
/// assert_eq!(limit_points(&p, 3, Topology::Open)?, [[6.0], [9.0]].map(Point::new));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn limit_points<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    degree: usize,
    topology: Topology,
) -> Result<Vec<Point<S, D>>> {
    limit_points_with(points, degree, topology, &mut NoCount)
}

/// [`limit_points`], counting one [`arithmetic_operation`](Counter::arithmetic_operation) per
/// stencil term.
///
/// Follows [PPB, §8.1] (the uniform B-splines) and [PPB, §8.3] (the convergence of the
/// control polygons).
///
/// # Errors
///
/// As [`limit_points`].
///
/// # Complexity
///
/// Θ(d² + n·d·D) time, Θ(d + n·D) space.
///
/// # Counts
///
/// (2⌊d/2⌋ + 1) per limit point: 3n for a closed cubic polygon of n vertices.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::subdivision::{limit_points_with, Topology};
/// use compgeo::spline::Point;
///
/// let p: Vec<Point<f64, 1>> = (0..10).map(|i| Point::new([i as f64])).collect();
/// let mut c = Counts::default();
/// let l = limit_points_with(&p, 3, Topology::Closed, &mut c)?;
/// assert_eq!((l.len(), c.arithmetic_operations), (10, 30));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn limit_points_with<S: Scalar, const D: usize, C: Counter>(
    points: &[Point<S, D>],
    degree: usize,
    topology: Topology,
    counter: &mut C,
) -> Result<Vec<Point<S, D>>> {
    check_degree(degree)?;
    validate_polygon(points, topology, degree + 1, "polygon")?;
    let stencil = limit_stencil::<S>(degree)?;
    let h = degree / 2;
    let n = points.len();
    let vertices = match topology {
        Topology::Closed => 0..n,
        Topology::Open => h..n - h,
    };
    let limits = vertices
        .map(|i| {
            let mut p = Point::zero();
            for (t, a) in stencil.coefficients().iter().enumerate() {
                // c_{i + t − h}, taken mod n on a closed polygon.
                let j = (i + n * (h / n + 1) + t - h) % n;
                counter.arithmetic_operation();
                p += &(points[j].clone() * a);
            }
            p
        })
        .collect();
    finite(limits, "limit points")
}
