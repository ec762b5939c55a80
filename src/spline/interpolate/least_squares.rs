//! Least-squares fitting of a Bézier curve to points at given parameters, optionally weighted
//! and optionally interpolating the first and last points.
//!
//! The problem: the Bézier curve of a given degree closest to more points than it can
//! interpolate. The idea: the control points are the unknowns of `C X = P` with the Bernstein
//! matrix `C_ij = B_jⁿ(u_i)`; the least-squares solution solves the normal equations, bordered
//! by the interpolation constraints when the ends are clamped.
//!
//! Follows [PPB, §4.6] (the residual `R = C X − P`, one column per coordinate, Obs. 10; the
//! weighted sum `Σ w_i² r_i²`) and [PPB, §4.7] (the theorem: the residual is minimal under
//! the constraint `D x = q` for the solution of the bordered system (2),
//! `[CᵀC Dᵀ; D 0] [x; y] = [Cᵀp; q]`, and with weights (3), `CᵀW²C` and `CᵀW²p`; without
//! constraints the normal equations `CᵀC x = Cᵀp`, Obs. 11).
//!
//! # Complexity
//!
//! Θ(m·n² + n³ + m·n·D) time and Θ(n² + m·n + n·D) space for m points and degree n.

use super::linear::solve_dense_with;
use super::validate::{check_dense, check_finite_nodes, check_nodes_and_points, singular};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::spline::{bernstein_all, Bezier};
use crate::{Error, Result};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and claims.
pub(crate) const LEAST_SQUARES: Declaration = Declaration {
    problem: "fit",
    name: "least-squares",
    function: "spline::fit_bezier",
    file: "src/spline/interpolate/least_squares.rs",
    summary: "the Bézier curve nearest to points in the least-squares sense",
    time: "Θ(m·n² + n³ + m·n·D)",
    space: "Θ(n² + m·n + n·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "(n + 1)(n + 2) per data point for the normal equations, then the dense solve's count for n + 1 unknowns",
    source: "[PPB, §4.7]",
    claims: &[on("random-points", Bound::Linear, Operation::ArithmeticOperations), on("random-degree", Bound::Cubic, Operation::ArithmeticOperations)],
};

/// What a least-squares fit may add to plain Gauss normal equations.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct FitOptions<S> {
    /// Weights `w_i` of the points: the fit minimises `Σ w_i² ‖r_i‖²` ([PPB, §4.6]). `None`
    /// weighs every point 1.
    pub weights: Option<Vec<S>>,
    /// Interpolate the first and the last point exactly: the constraint `b_0 = p_1`,
    /// `b_n = p_m` of the bordered system (2).
    pub clamp_ends: bool,
}

/// The Bézier curve of degree `degree` over [0, 1] that fits `points` at the parameters
/// `params` best in the least-squares sense ([PPB, §4.7]).
///
/// The idea: the control points are the unknowns of the linear system `C X = P` with the
/// Bernstein matrix `C_ij = B_jⁿ(u_i)`; with more points than unknowns the residual is
/// minimised by the solution of the normal equations `CᵀW²C X = CᵀW²P`, bordered by the
/// interpolation constraints when the ends are clamped. The system is solved by Gaussian
/// elimination, exactly with rationals: a curve whose points lie on a Bézier curve of the
/// same degree is recovered exactly.
///
/// # Errors
///
/// [`Error::Empty`] for no points; [`Error::InvalidParameter`] for mismatched lengths
/// (`"points"`, `"weights"`), a non-finite parameter (`"params"`) or weight (`"weights"`), or
/// data that do not determine the curve (`"params"`: fewer distinct parameters than the
/// degree needs, so the normal equations are singular); [`Error::NonFinite`] for a bad
/// coordinate; [`Error::LimitExceeded`] if the system's `degree + 1` unknowns (plus two with
/// clamped ends) exceed [`MAX_DENSE_UNKNOWNS`](crate::limits::MAX_DENSE_UNKNOWNS), before it
/// is allocated.
///
/// # Complexity
///
/// Θ(m·n² + n³ + m·n·D) time and Θ(n² + m·n + n·D) auxiliary space for m points and degree n.
///
/// ```
/// use compgeo::spline::{fit_bezier, FitOptions, Point};
///
/// // Samples of y = 2x + 1 with noise orthogonal to 1 and x: the fit is the line itself.
/// let params = [0.0, 0.25, 0.5, 0.75, 1.0];
/// let pts: Vec<_> = [1.0, 1.75, 1.5, 2.75, 3.0]
///     .iter()
///     .zip(&params)
///     .map(|(&y, &x)| Point::new([x, y]))
///     .collect();
/// let line = fit_bezier(&params, &pts, 1, &FitOptions::default())?;
/// let (b0, b1) = (line.control()[0], line.control()[1]);
/// assert!((b0[1] - 1.0).abs() < 1e-12 && (b1[1] - 3.0).abs() < 1e-12);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn fit_bezier<S: Scalar, const D: usize>(
    params: &[S],
    points: &[Point<S, D>],
    degree: usize,
    options: &FitOptions<S>,
) -> Result<Bezier<S, D>> {
    fit_bezier_with(params, points, degree, options, &mut NoCount)
}

/// [`fit_bezier`], counting one [`arithmetic_operation`](Counter::arithmetic_operation) per
/// entry of the normal equations updated by a data point ((n + 1)² in the matrix and n + 1
/// on the right, so (n + 1)(n + 2) per point), then those of the dense solve: one per entry
/// a row operation changes and per back-substitution term, (N − 1)N(2N − 1)/6 + N(N − 1) +
/// N(N + 1)/2 for its N = n + 1 unknowns (n + 3 with clamped ends) when no entry below a
/// pivot vanishes. The Bernstein values are scalar bookkeeping, not counted.
///
/// # Errors
///
/// As [`fit_bezier`].
///
/// # Complexity
///
/// Θ(m·n² + n³ + m·n·D) time and Θ(n² + m·n + n·D) auxiliary space for m points and degree n.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{fit_bezier_with, FitOptions, Point};
///
/// let params = [0.0, 0.25, 0.5, 0.75, 1.0];
/// let pts: Vec<_> = params.iter().map(|&x| Point::new([x, x * x])).collect();
/// let mut c = Counts::default();
/// fit_bezier_with(&params, &pts, 1, &FitOptions::default(), &mut c)?;
/// // Five points of 2·3 updates, then the 2 × 2 solve: 3 changed entries and 1 + 2 terms.
/// assert_eq!(c.arithmetic_operations, 5 * 6 + 3 + 3);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn fit_bezier_with<S: Scalar, const D: usize, C: Counter>(
    params: &[S],
    points: &[Point<S, D>],
    degree: usize,
    options: &FitOptions<S>,
    counter: &mut C,
) -> Result<Bezier<S, D>> {
    check_nodes_and_points(params, points).map_err(|e| match e {
        Error::Empty { .. } => Error::Empty { what: "points" },
        other => other,
    })?;
    check_finite_nodes(params, "params")?;
    let m = points.len();
    let n = degree;
    let weights2: Vec<S> = match &options.weights {
        None => vec![S::one(); m],
        Some(w) => {
            if w.len() != m {
                return Err(Error::InvalidParameter {
                    name: "weights",
                    reason: format!("{} weights for {m} points", w.len()),
                });
            }
            check_finite_nodes(w, "weights")?;
            w.iter().map(|x| x.clone() * x).collect()
        }
    };
    // Normal equations CᵀW²C x = CᵀW²p, accumulated row by row of C.
    let constraints = if options.clamp_ends { 2 } else { 0 };
    let size = n.saturating_add(1 + constraints);
    check_dense(size)?;
    let mut matrix = vec![vec![S::zero(); size]; size];
    let mut rhs = vec![Point::<S, D>::zero(); size];
    for ((u, p), w2) in params.iter().zip(points).zip(&weights2) {
        let row = bernstein_all(n, u)?;
        for (j, bj) in row.iter().enumerate() {
            let wj = bj.clone() * w2;
            for (entry, bk) in matrix[j].iter_mut().zip(&row) {
                *entry += wj.clone() * bk;
            }
            rhs[j] += &(p.clone() * &wj);
            for _ in 0..=row.len() {
                counter.arithmetic_operation();
            }
        }
    }
    if options.clamp_ends {
        // Rows D = [e_0; e_n], columns Dᵀ; right-hand side q = (p_1, p_m).
        for (c, (index, value)) in [(0, &points[0]), (n, &points[m - 1])]
            .into_iter()
            .enumerate()
        {
            matrix[n + 1 + c][index] = S::one();
            matrix[index][n + 1 + c] = S::one();
            rhs[n + 1 + c] = value.clone();
        }
    }
    let mut solution = solve_dense_with(matrix, rhs, counter).ok_or_else(|| {
        singular(
            "params",
            &format!(
                "the points do not determine a curve of degree {n}: too few distinct parameters"
            ),
        )
    })?;
    solution.truncate(n + 1);
    if solution.iter().any(|p| !p.is_finite()) {
        return Err(singular(
            "params",
            "the normal equations are numerically singular",
        ));
    }
    Bezier::new(solution)
}
