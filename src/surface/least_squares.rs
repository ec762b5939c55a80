//! Least-squares approximation of scattered data by a B-spline surface or a Bézier patch of a
//! given bidegree, with a rank check.
//!
//! The problem: data points a_k with parameters (u_k, v_k), k = 0, …, K − 1, not on a grid;
//! find the net c minimising Σ_k ‖s(u_k, v_k) − a_k‖² over the surfaces on given knots
//! [FJ-surfaces, §7, eqs. (28)–(29)]. The idea: the system B·C = A of eq. (28) has one row
//! per datum, b_k = (Nᵢ(u_k)·Nⱼ(v_k))_{i,j}, and MN unknowns; its least-squares solution
//! solves the normal equations BᵗB·C = BᵗA (29), an MN × MN system assembled from the
//! non-zero basis products of each datum ((p + 1)(q + 1) of them) and solved by Gaussian
//! elimination. The solution is unique exactly when B has full column rank: a control point
//! whose basis product vanishes at every datum is named before the elimination; otherwise a
//! zero pivot (exact for rationals; for `f64` only an exactly zero one is seen, a nearly
//! singular system is not flagged) reports the rank deficiency. A Bézier patch is the
//! B-spline surface on the knots 0, …, 0, 1, …, 1.
//!
//! # Complexity
//!
//! Θ(K·(p + 1)²(q + 1)²) to assemble, Θ((MN)³ + (MN)²D) to solve; Θ((MN)² + MN·D) space.
//! The unknowns are capped by [`MAX_DENSE_UNKNOWNS`](crate::limits::MAX_DENSE_UNKNOWNS).

use super::bezier::BezierPatch;
use super::bspline::BSplineSurface;
use super::interpolate::unit_bezier_knots;
use super::net::ControlNet;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::interpolate::solve_dense_with;
use crate::spline::{validate_points, KnotVector, Point, Scalar};
use crate::{limits, Error, Result};

/// Least-squares surface approximation, declared.
pub(crate) const SURFACE_FIT: Declaration = Declaration {
    problem: "surface-construct",
    name: "least-squares",
    function: "surface::BSplineSurface::fit",
    file: "src/surface/least_squares.rs",
    summary: "normal equations of the tensor basis products at the data, dense Gaussian elimination",
    time: "Θ(K(p + 1)²(q + 1)² + (MN)³ + (MN)²D)",
    space: "Θ((MN)² + MN·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per entry of the normal equations updated, one per entry changed by elimination and per back-substitution term",
    source: "[FJ-surfaces, §7, eqs. (28)–(29)]",
    claims: &[on("random-scattered", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The least-squares surface on `u_knots` × `v_knots` for the data `points` at the
    /// parameters (`u_params[k]`, `v_params[k]`). See [`BSplineSurface::fit_with`].
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no data; [`Error::InvalidParameter`] named `"params"` if the
    /// counts of points and parameters differ; [`Error::NonFinite`] for a bad coordinate;
    /// [`Error::InvalidParameter`] named `"u parameters"` or `"v parameters"` for a NaN,
    /// infinite or out-of-domain parameter (naming its index); [`Error::LimitExceeded`]
    /// beyond [`MAX_DENSE_UNKNOWNS`](crate::limits::MAX_DENSE_UNKNOWNS) control points;
    /// [`Error::InvalidParameter`] named `"params"` if the fit is not unique: a control point
    /// whose basis function vanishes at every datum (naming it), or a rank-deficient system;
    /// [`Error::Overflow`] if, with `f64`, a control point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(K(p + 1)²(q + 1)² + (MN)³ + (MN)²D) time, Θ((MN)² + MN·D) space.
    pub fn fit(
        points: &[Point<S, D>],
        u_params: &[S],
        v_params: &[S],
        u_knots: KnotVector<S>,
        v_knots: KnotVector<S>,
    ) -> Result<Self> {
        Self::fit_with(points, u_params, v_params, u_knots, v_knots, &mut NoCount)
    }

    /// The least-squares surface, counting the arithmetic.
    ///
    /// Idea: assemble the normal equations BᵗB·C = BᵗA from the (p + 1)(q + 1) non-zero
    /// basis products of each datum and solve them by Gaussian elimination [FJ-surfaces, §7,
    /// eq. (29)]; a zero pivot means B has not full column rank.
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::fit`].
    ///
    /// # Complexity
    ///
    /// As [`BSplineSurface::fit`].
    ///
    /// # Counts
    ///
    /// Those of the basis values, one [`arithmetic_operation`](Counter::arithmetic_operation)
    /// per entry of the normal equations updated, and those of the elimination (one per
    /// entry changed, one per back-substitution term).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, Surface};
    ///
    /// // Samples of the plane z = x + 2y: the bilinear fit reproduces it.
    /// let (mut p, mut u, mut v) = (vec![], vec![], vec![]);
    /// for k in 0..9 {
    ///     let (x, y) = ((k % 3) as f64 / 2.0, (k / 3) as f64 / 2.0);
    ///     p.push(Point::new([x + 2.0 * y]));
    ///     u.push(x);
    ///     v.push(y);
    /// }
    /// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
    /// let s = BSplineSurface::fit_with(&p, &u, &v, t.clone(), t.clone(), &mut Counts::default())?;
    /// assert!((s.eval(&0.25, &0.75)?[0] - 1.75).abs() < 1e-12);
    /// // Data only on the line v = 0 cannot determine the net.
    /// let e = BSplineSurface::fit(&p[..3], &u[..3], &[0.0; 3], t.clone(), t).unwrap_err();
    /// assert!(e.to_string().contains("not unique"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn fit_with<C: Counter>(
        points: &[Point<S, D>],
        u_params: &[S],
        v_params: &[S],
        u_knots: KnotVector<S>,
        v_knots: KnotVector<S>,
        counter: &mut C,
    ) -> Result<Self> {
        if points.is_empty() {
            return Err(Error::Empty {
                what: "least-squares data",
            });
        }
        if u_params.len() != points.len() || v_params.len() != points.len() {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!(
                    "{} points need as many parameters, got {} in u and {} in v",
                    points.len(),
                    u_params.len(),
                    v_params.len()
                ),
            });
        }
        validate_points(points, "least-squares data")?;
        check_in_domain(u_params, &u_knots, "u parameters")?;
        check_in_domain(v_params, &v_knots, "v parameters")?;
        let (m, n) = (u_knots.control_points(), v_knots.control_points());
        let unknowns = m as u128 * n as u128;
        limits::DENSE_UNKNOWNS.check(unknowns)?;
        let size = m * n;
        let mut normal = vec![vec![S::zero(); size]; size];
        let mut rhs = vec![Point::<S, D>::zero(); size];
        for ((u, v), a) in u_params.iter().zip(v_params).zip(points) {
            let bu = u_knots.basis_with(u, counter)?;
            let bv = v_knots.basis_with(v, counter)?;
            // The datum's non-zero basis products, by unknown index i·N + j.
            let mut products = Vec::with_capacity(bu.values().len() * bv.values().len());
            for (x, nu) in bu.values().iter().enumerate() {
                for (y, nv) in bv.values().iter().enumerate() {
                    let index = (bu.first() + x) * n + bv.first() + y;
                    products.push((index, nu.clone() * nv));
                    counter.arithmetic_operation();
                }
            }
            for (r, br) in &products {
                for (c, bc) in &products {
                    normal[*r][*c] += &(br.clone() * bc);
                    counter.arithmetic_operation();
                }
                rhs[*r] += &(a.clone() * br);
                counter.arithmetic_operation();
            }
        }
        if let Some(k) = (0..size).find(|&k| normal[k][k].is_zero()) {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!(
                    "the fit is not unique: the basis function of control point ({}, {}) \
                     vanishes at every datum",
                    k / n,
                    k % n
                ),
            });
        }
        let control =
            solve_dense_with(normal, rhs, counter).ok_or_else(|| Error::InvalidParameter {
                name: "params",
                reason: format!(
                    "the fit is not unique: the {} data give a collocation matrix of rank below \
                 the {m} × {n} control points (the normal equations are singular)",
                    points.len()
                ),
            })?;
        if !control.iter().all(Point::is_finite) {
            return Err(Error::Overflow {
                what: "least-squares surface fit",
            });
        }
        BSplineSurface::new(ControlNet::from_rows(m, n, control)?, u_knots, v_knots)
    }
}

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The least-squares Bézier patch of bidegree (m, n) for the data `points` at the
    /// parameters (`u_params[k]`, `v_params[k]`) in [0, 1]². See [`BezierPatch::fit_with`].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::fit`] (parameters outside [0, 1] are refused);
    /// [`Error::LimitExceeded`] for a degree beyond
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
    ///
    /// # Complexity
    ///
    /// Θ(K(m + 1)²(n + 1)² + ((m + 1)(n + 1))³) time.
    pub fn fit(
        points: &[Point<S, D>],
        u_params: &[S],
        v_params: &[S],
        bidegree: (usize, usize),
    ) -> Result<Self> {
        Self::fit_with(points, u_params, v_params, bidegree, &mut NoCount)
    }

    /// The least-squares Bézier patch, counting the arithmetic.
    ///
    /// Idea: [`BSplineSurface::fit_with`] on the knots 0, …, 0, 1, …, 1, whose surfaces are
    /// the Bézier patches of the bidegree [FJ-surfaces, §7].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::fit`].
    ///
    /// # Complexity
    ///
    /// As [`BezierPatch::fit`].
    ///
    /// # Counts
    ///
    /// Those of [`BSplineSurface::fit_with`].
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::BezierPatch;
    ///
    /// // Four corners and the centre of a hyperbolic paraboloid z = uv: reproduced exactly.
    /// let (u, v) = ([0.0, 1.0, 0.0, 1.0, 0.5], [0.0, 0.0, 1.0, 1.0, 0.5]);
    /// let p: Vec<_> = u.iter().zip(&v).map(|(a, b)| Point::new([a * b])).collect();
    /// let s = BezierPatch::fit_with(&p, &u, &v, (1, 1), &mut Counts::default())?;
    /// assert_eq!(s.net().get(1, 1), &Point::new([1.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn fit_with<C: Counter>(
        points: &[Point<S, D>],
        u_params: &[S],
        v_params: &[S],
        (m, n): (usize, usize),
        counter: &mut C,
    ) -> Result<Self> {
        limits::DEGREE.check(m as u128)?;
        limits::DEGREE.check(n as u128)?;
        let s = BSplineSurface::fit_with(
            points,
            u_params,
            v_params,
            unit_bezier_knots(m + 1)?,
            unit_bezier_knots(n + 1)?,
            counter,
        )?;
        BezierPatch::new(s.net().clone())
    }
}

/// Every parameter finite and in the knots' domain, the first bad one named by its index.
fn check_in_domain<S: Scalar>(
    params: &[S],
    knots: &KnotVector<S>,
    name: &'static str,
) -> Result<()> {
    let domain = knots.domain();
    for (k, t) in params.iter().enumerate() {
        if domain.check(t, name).is_err() {
            let (a, b) = knots.bounds();
            return Err(Error::InvalidParameter {
                name,
                reason: format!(
                    "parameter {k} is {}, not a finite value of [{}, {}]",
                    t.to_f64(),
                    a.to_f64(),
                    b.to_f64()
                ),
            });
        }
    }
    Ok(())
}
