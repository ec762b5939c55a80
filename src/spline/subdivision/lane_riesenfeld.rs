//! The Lane–Riesenfeld algorithm: uniform subdivision of a B-spline of degree d by doubling
//! every control point and then taking midpoints d times; Chaikin's algorithm is degree 2.
//!
//! The problem: the uniform spline s(u) = Σ c_j N^d(u − j) on the integers, written on the
//! half-integers, s(u) = Σ b_i N^d(2u − i). The idea [PPB, §8.2]: the B-spline of degree d
//! is the convolution of the one of degree d − 1 with the box N^0, so doubling
//! (b_{2j} = b_{2j+1} = c_j, the piecewise-constant case) followed by d passes of
//! b_i ← ½(b_{i−1} + b_i) gives the control points on the halved knots. In matrix form
//! S_d = D·M^d [PPB, §8.3], whose columns are the mask 2^{−d}·C(d + 1, i) [PPB, §8.4]
//! ([`Mask::lane_riesenfeld`](super::Mask::lane_riesenfeld)). Repeating it k times gives the
//! control polygon on the knots 2^{−k}ℤ, which converges to the curve [PPB, §8.3, Obs. 3].
//!
//! Closed polygons are periodic; an open one is the spline on the knots 0, …, n + d and
//! keeps its 2n − d control points on the halved knots (module docs of
//! [`subdivision`](super)).
//!
//! # Complexity
//!
//! Θ(d·N) time for k rounds, N ≤ n·2^k the output size; Θ(N·D) space.
//!
//! Invariants the tests check (exactly, on rationals): k rounds give the control polygon of
//! the same spline on the 2^k-refined uniform knots (compared with [`BSpline`] at dyadic
//! parameters), the result equals k rounds of the mask, and the counts below.
//!
//! [`BSpline`]: crate::spline::BSpline

use super::mask::check_degree;
use super::{finite, output_size, validate_polygon, Topology};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, Counts, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::trace::{Frame, NoObserver, Observer, Recorder, TraceSize};
use crate::Result;

/// A step of the Lane–Riesenfeld algorithm, as [`lane_riesenfeld_trace`] records it: the
/// polygon after it.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum LaneRiesenfeldStep<S, const D: usize> {
    /// The polygon the rounds start from.
    Input {
        /// The given polygon.
        polygon: Vec<Point<S, D>>,
    },
    /// Round `round` (from 1) doubled every vertex.
    Doubled {
        /// The round, from 1.
        round: usize,
        /// The doubled polygon.
        polygon: Vec<Point<S, D>>,
    },
    /// Pass `pass` (1 to d) of round `round` replaced every vertex by the midpoint of it and
    /// its predecessor (an open polygon loses its first vertex).
    Averaged {
        /// The round, from 1.
        round: usize,
        /// The pass of midpoints, from 1 to the degree.
        pass: usize,
        /// The polygon after the pass.
        polygon: Vec<Point<S, D>>,
    },
}

impl<S, const D: usize> TraceSize for LaneRiesenfeldStep<S, D> {
    fn entries(&self) -> usize {
        match self {
            LaneRiesenfeldStep::Input { polygon }
            | LaneRiesenfeldStep::Doubled { polygon, .. }
            | LaneRiesenfeldStep::Averaged { polygon, .. } => polygon.len(),
        }
    }
}

/// The Lane–Riesenfeld algorithm, declared.
pub(crate) const LANE_RIESENFELD: Declaration = Declaration {
    problem: "subdivision",
    name: "lane-riesenfeld",
    function: "spline::subdivision::lane_riesenfeld",
    file: "src/spline/subdivision/lane_riesenfeld.rs",
    summary: "k rounds of uniform B-spline subdivision of degree d: double every vertex, then d passes of midpoints (Chaikin for d = 2)",
    time: "Θ(d·N), N ≤ n·2^k the output size",
    space: "Θ(N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per midpoint: 2dm per round on a closed polygon of m vertices, 2dm − d(d + 1)/2 on an open one",
    source: "[PPB, §8.2–8.4]",
    claims: &[on(
        "random-closed",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// `rounds` rounds of the Lane–Riesenfeld algorithm of degree d on a polygon: the control
/// polygon of the same uniform spline of degree d on the knots 2^{−k}ℤ. See
/// [`lane_riesenfeld_with`].
///
/// # Errors
///
/// [`Error::Empty`](crate::Error::Empty), [`Error::NonFinite`](crate::Error::NonFinite) for a
/// bad vertex; [`Error::InvalidParameter`](crate::Error::InvalidParameter) for degree 0;
/// [`Error::TooFew`](crate::Error::TooFew) for a closed polygon of fewer than 3 vertices or
/// an open one of fewer than d + 1; [`Error::LimitExceeded`](crate::Error::LimitExceeded)
/// beyond [`MAX_DEGREE`](crate::limits::MAX_DEGREE) or if the output would pass
/// [`MAX_SUBDIVISION_POINTS`](crate::limits::MAX_SUBDIVISION_POINTS);
/// [`Error::Overflow`](crate::Error::Overflow) if, with `f64`, a vertex overflows.
///
/// # Complexity
///
/// Θ(d·N), N ≤ n·2^k the output size; Θ(N·D) space.
///
/// ```
/// use compgeo::spline::subdivision::{lane_riesenfeld, Topology};
/// use compgeo::spline::Point;
///
/// // Cubic: an edge's midpoint, then a vertex ⅛(c₀ + 6c₁ + c₂), alternately.
/// let p = [[0.0], [8.0], [16.0], [0.0]].map(Point::new);
/// let q = lane_riesenfeld(&p, 3, 1, Topology::Open)?;
/// assert_eq!(q, [[4.0], [8.0], [12.0], [13.0], [8.0]].map(Point::new));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lane_riesenfeld<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    degree: usize,
    rounds: usize,
    topology: Topology,
) -> Result<Vec<Point<S, D>>> {
    lane_riesenfeld_with(points, degree, rounds, topology, &mut NoCount)
}

/// Chaikin's algorithm: [`lane_riesenfeld`] of degree 2, which cuts every corner at ¼ and ¾
/// of its edges [PPB, §8.2, Obs. 1]; the limit is the uniform quadratic B-spline.
///
/// # Errors
///
/// As [`lane_riesenfeld`] (an open polygon needs 3 vertices).
///
/// # Complexity
///
/// Θ(N), N ≤ n·2^k the output size; Θ(N·D) space.
///
/// ```
/// use compgeo::spline::subdivision::{chaikin, Topology};
/// use compgeo::spline::Point;
///
/// let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]].map(Point::new);
/// let q = chaikin(&square, 1, Topology::Closed)?;
/// assert_eq!(q.len(), 8);
/// assert_eq!((q[2], q[3]), (Point::new([1.0, 0.0]), Point::new([3.0, 0.0])));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn chaikin<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    rounds: usize,
    topology: Topology,
) -> Result<Vec<Point<S, D>>> {
    lane_riesenfeld(points, 2, rounds, topology)
}

/// [`lane_riesenfeld`], counting one [`arithmetic_operation`](Counter::arithmetic_operation)
/// per midpoint.
///
/// Idea [PPB, §8.2–8.3]: each round doubles the vertices, then makes d passes of midpoints
/// b_i ← ½(b_{i−1} + b_i) in place. On a closed polygon every pass keeps its 2m vertices
/// (indices mod 2m) and the result is b_0, …, b_{2m−1} of b_i = Σ_j c_j α_{i−2j}; on an
/// open one every pass drops its first vertex, whose left neighbour does not exist, leaving
/// b_d, …, b_{2m−1}.
///
/// # Errors
///
/// As [`lane_riesenfeld`].
///
/// # Complexity
///
/// Θ(d·N), N ≤ n·2^k the output size; Θ(N·D) space.
///
/// # Counts
///
/// Per round on m vertices: 2dm on a closed polygon (so 2dn(2^k − 1) in all), and
/// 2dm − d(d + 1)/2 on an open one.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::subdivision::{lane_riesenfeld_with, Topology};
/// use compgeo::spline::Point;
///
/// let p: Vec<Point<f64, 2>> = (0..10).map(|i| Point::new([i as f64, 0.0])).collect();
/// let mut c = Counts::default();
/// let q = lane_riesenfeld_with(&p, 3, 2, Topology::Closed, &mut c)?;
/// assert_eq!((q.len(), c.arithmetic_operations), (40, 2 * 3 * 10 * 3));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lane_riesenfeld_with<S: Scalar, const D: usize, C: Counter>(
    points: &[Point<S, D>],
    degree: usize,
    rounds: usize,
    topology: Topology,
    counter: &mut C,
) -> Result<Vec<Point<S, D>>> {
    lane_riesenfeld_observed(points, degree, rounds, topology, counter, &mut NoObserver)
}

/// The frames of the Lane–Riesenfeld algorithm: its own run, step by step.
///
/// The run is [`lane_riesenfeld_with`]'s, told about each step: [`LaneRiesenfeldStep::Input`]
/// with the given polygon, then per round a [`LaneRiesenfeldStep::Doubled`] and d
/// [`LaneRiesenfeldStep::Averaged`], one per pass of midpoints: 1 + k(d + 1) frames for k
/// rounds. The last frame's polygon is the result of [`lane_riesenfeld`], and each frame
/// carries the midpoints counted so far; the last frame's counts are those of
/// [`lane_riesenfeld_with`] with [`Counts`].
///
/// # Errors
///
/// As [`lane_riesenfeld`]; [`Error::LimitExceeded`](crate::Error::LimitExceeded) also if the
/// polygons of all frames pass [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES)
/// points.
///
/// # Complexity
///
/// Θ(d·N) time and space, N ≤ n·2^k the output size: every pass's polygon is kept.
///
/// ```
/// use compgeo::spline::subdivision::{lane_riesenfeld_trace, LaneRiesenfeldStep, Topology};
/// use compgeo::spline::Point;
///
/// // Chaikin (degree 2) on a closed triangle: double, then two passes of midpoints.
/// let p = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]].map(Point::new);
/// let frames = lane_riesenfeld_trace(&p, 2, 1, Topology::Closed)?;
/// assert_eq!(frames.len(), 4);
/// let LaneRiesenfeldStep::Doubled { polygon, .. } = &frames[1].step else { panic!() };
/// assert_eq!(polygon[..2], [Point::new([0.0, 0.0]), Point::new([0.0, 0.0])]);
/// let LaneRiesenfeldStep::Averaged { pass: 2, polygon, .. } = &frames[3].step else { panic!() };
/// assert_eq!(polygon[2], Point::new([1.0, 0.0])); // a quarter along the first edge
/// assert_eq!(frames[3].counts.arithmetic_operations, 2 * 2 * 3);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lane_riesenfeld_trace<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    degree: usize,
    rounds: usize,
    topology: Topology,
) -> Result<Vec<Frame<LaneRiesenfeldStep<S, D>>>> {
    let mut counts = Counts::default();
    let mut recorder = Recorder::new();
    lane_riesenfeld_observed(points, degree, rounds, topology, &mut counts, &mut recorder)?;
    recorder.finish()
}

/// The algorithm, telling `obs` about the input and each doubling and pass.
fn lane_riesenfeld_observed<S, const D: usize, C, O>(
    points: &[Point<S, D>],
    degree: usize,
    rounds: usize,
    topology: Topology,
    counter: &mut C,
    obs: &mut O,
) -> Result<Vec<Point<S, D>>>
where
    S: Scalar,
    C: Counter,
    O: Observer<LaneRiesenfeldStep<S, D>, C>,
{
    check_degree(degree)?;
    validate_polygon(points, topology, degree + 1, "polygon")?;
    let d = degree as u128;
    match topology {
        Topology::Closed => output_size(points.len(), rounds, |m| 2 * m)?,
        Topology::Open => output_size(points.len(), rounds, |m| 2 * m - d)?,
    };
    let half = S::from_ratio(1, 2);
    let mut current = points.to_vec();
    obs.step(counter, || LaneRiesenfeldStep::Input {
        polygon: current.clone(),
    });
    for round in 1..=rounds {
        let mut b: Vec<Point<S, D>> = current
            .iter()
            .flat_map(|c| [c.clone(), c.clone()])
            .collect();
        obs.step(counter, || LaneRiesenfeldStep::Doubled {
            round,
            polygon: b.clone(),
        });
        for pass in 1..=degree {
            match topology {
                Topology::Closed => closed_midpoints(&mut b, &half, counter),
                Topology::Open => open_midpoints(&mut b, &half, counter),
            }
            obs.step(counter, || LaneRiesenfeldStep::Averaged {
                round,
                pass,
                polygon: b.clone(),
            });
        }
        current = b;
    }
    finite(current, "Lane–Riesenfeld subdivision")
}

/// One pass b_i ← ½(b_{i−1} + b_i), indices mod the length, in place from the end.
fn closed_midpoints<S: Scalar, const D: usize, C: Counter>(
    b: &mut [Point<S, D>],
    half: &S,
    counter: &mut C,
) {
    let last = b[b.len() - 1].clone();
    for i in (1..b.len()).rev() {
        b[i] = (b[i - 1].clone() + &b[i]) * half;
        counter.arithmetic_operation();
    }
    b[0] = (last + &b[0]) * half;
    counter.arithmetic_operation();
}

/// One pass b_i ← ½(b_{i−1} + b_i) for every i with a left neighbour: the vector loses its
/// first entry (entry i becomes ½(b_i + b_{i+1})).
fn open_midpoints<S: Scalar, const D: usize, C: Counter>(
    b: &mut Vec<Point<S, D>>,
    half: &S,
    counter: &mut C,
) {
    for i in 0..b.len() - 1 {
        b[i] = (b[i].clone() + &b[i + 1]) * half;
        counter.arithmetic_operation();
    }
    b.pop();
}
