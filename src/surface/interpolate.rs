//! Tensor-product interpolation of a grid of points: Bézier patches and B-spline surfaces
//! through a_{i,j} = s(u_i, v_j), rows first, then columns.
//!
//! The problem: M × N data points a_{i,j} and parameters u₀ < … < u_{M−1},
//! v₀ < … < v_{N−1}; find the net c with s(u_i, v_j) = a_{i,j}. In matrix form
//! B_U·C·B_Vᵗ = A with the collocation matrices B_U (rows Nₖ(u_i)) and B_V [FJ-surfaces, §7,
//! eq. (27)]. The idea [FJ-surfaces, §7]: instead of one system of MN unknowns, solve
//! C̃·B_Vᵗ = A, that is interpolate every row of the data by a curve in v (its control points
//! are row i of C̃ = B_U·C), then B_U·C = C̃, that is interpolate every column of C̃ by a
//! curve in u. Both steps are the curve interpolation of the crate
//! ([`BSpline::interpolate_at_with`]): collocation after the Schoenberg–Whitney check, banded
//! elimination. A Bézier patch of bidegree (M − 1, N − 1) is the B-spline surface on the
//! knots 0, …, 0, 1, …, 1, so its interpolation is the same with those knots (and parameters
//! in [0, 1]).
//!
//! # Complexity
//!
//! M curve interpolations of N points and N of M: Θ(M(N q² + N q D) + N(M p² + M p D)) for
//! bidegree (p, q); Θ(MN·D) space.

use super::bezier::BezierPatch;
use super::bspline::{rename, BSplineSurface};
use super::net::ControlNet;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::interpolate::check_partition;
use crate::spline::{parameterise, BSpline, KnotVector, Parameterisation, Point, Scalar};
use crate::{Error, Result};

/// Tensor-product interpolation, declared.
pub(crate) const SURFACE_INTERPOLATE: Declaration = Declaration {
    problem: "surface-construct",
    name: "interpolate",
    function: "surface::BSplineSurface::interpolate_at",
    file: "src/surface/interpolate.rs",
    summary: "curve interpolation of every data row in v, then of every column of the result in u",
    time: "Θ(M·N·(p² + q² + (p + q)D))",
    space: "Θ(MN·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "those of the M curve interpolations in v and the N in u",
    source: "[FJ-surfaces, §7], [PPB, §6.7, §9.1]",
    claims: &[on(
        "random-grid",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The B-spline surface on `u_knots` × `v_knots` through the data: s(u_i, v_j) =
    /// `data`(i, j). See [`BSplineSurface::interpolate_at_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u knots"` or `"v knots"` if a knot vector does not
    /// serve as many control points as the data has rows, respectively columns;
    /// [`Error::InvalidParameter`] named `"u parameters"` or `"v parameters"` for another
    /// number of parameters, a NaN or infinite one, one outside the knots' domain, a repeated
    /// or decreasing one, or parameters that break the Schoenberg–Whitney condition (naming
    /// the index); [`Error::Overflow`] if, with `f64`, a control point is beyond the double
    /// range.
    ///
    /// # Complexity
    ///
    /// Θ(M·N·(p² + q² + (p + q)D)) time, Θ(MN·D) space.
    ///
    /// ```
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet, Surface};
    ///
    /// let data = ControlNet::new((0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64, ((i + j) % 2) as f64])).collect()).collect())?;
    /// let (u, v) = ([0.0, 0.5, 1.0], [0.0, 0.25, 0.75, 1.0]);
    /// let s = BSplineSurface::interpolate_at(&data, &u, &v, KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?, KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?)?;
    /// assert!((s.eval(&0.5, &0.25)?[2] - 0.0).abs() < 1e-12);
    /// assert!((s.eval(&1.0, &0.75)?[2] - 0.0).abs() < 1e-12);
    /// assert!((s.eval(&0.5, &0.75)?[2] - 1.0).abs() < 1e-12);
    /// let e = BSplineSurface::interpolate_at(&data, &[0.0, 0.0, 1.0], &v, s.u_knots().clone(), s.v_knots().clone()).unwrap_err();
    /// assert!(e.to_string().starts_with("invalid u parameters"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn interpolate_at(
        data: &ControlNet<S, D>,
        u_params: &[S],
        v_params: &[S],
        u_knots: KnotVector<S>,
        v_knots: KnotVector<S>,
    ) -> Result<Self> {
        Self::interpolate_at_with(data, u_params, v_params, u_knots, v_knots, &mut NoCount)
    }

    /// The interpolating surface, counting the arithmetic.
    ///
    /// Idea: interpolate every row of the data at the v parameters (the rows of C̃ = B_U·C),
    /// then every column of C̃ at the u parameters [FJ-surfaces, §7]; the curve interpolation
    /// is [`BSpline::interpolate_at_with`].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::interpolate_at`].
    ///
    /// # Complexity
    ///
    /// As [`BSplineSurface::interpolate_at`].
    ///
    /// # Counts
    ///
    /// Those of [`BSpline::interpolate_at_with`] on the M rows and the N columns.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet};
    ///
    /// let data = ControlNet::new((0..2).map(|i| (0..2).map(|j| Point::new([i as f64, j as f64])).collect()).collect())?;
    /// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
    /// let mut c = Counts::default();
    /// let s = BSplineSurface::interpolate_at_with(&data, &[0.0, 1.0], &[0.0, 1.0], t.clone(), t, &mut c)?;
    /// assert_eq!(s.net(), &data); // bilinear through its corners: the net is the data
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn interpolate_at_with<C: Counter>(
        data: &ControlNet<S, D>,
        u_params: &[S],
        v_params: &[S],
        u_knots: KnotVector<S>,
        v_knots: KnotVector<S>,
        counter: &mut C,
    ) -> Result<Self> {
        let (m, n) = (data.rows(), data.columns());
        rename(u_knots.check_control_points(m), "u knots")?;
        rename(v_knots.check_control_points(n), "v knots")?;
        check_parameters(u_params, m, "u parameters")?;
        check_parameters(v_params, n, "v parameters")?;
        rename(u_knots.check_schoenberg_whitney(u_params), "u parameters")?;
        rename(v_knots.check_schoenberg_whitney(v_params), "v parameters")?;
        // C̃: every data row interpolated in v.
        let mut tilde = Vec::with_capacity(m * n);
        for i in 0..m {
            let row =
                BSpline::interpolate_at_with(data.row(i), v_params, v_knots.clone(), counter)?;
            tilde.extend(row.into_parts().0);
        }
        let tilde = ControlNet::from_rows(m, n, tilde)?;
        // C: every column of C̃ interpolated in u.
        let mut columns = Vec::with_capacity(n * m);
        for j in 0..n {
            let column =
                BSpline::interpolate_at_with(&tilde.column(j), u_params, u_knots.clone(), counter)?;
            columns.extend(column.into_parts().0);
        }
        let net = ControlNet::from_rows(n, m, columns)?.transposed();
        BSplineSurface::new(net, u_knots, v_knots)
    }

    /// The B-spline surface of bidegree (p, q) through the data at parameters computed from
    /// it: each row's parameters by `parameterisation`, scaled to [0, 1], averaged over the
    /// rows for v (and the columns' over the columns for u); knots by averaging the
    /// parameters ([`KnotVector::averaged`]) [PPB, §4.5, §6.7].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::interpolate_at`]; [`Error::InvalidParameter`] named `"points"` if
    /// two consecutive points of a row or column coincide (a chord of length zero), and as
    /// [`KnotVector::averaged`] for a degree not below the number of points.
    ///
    /// # Complexity
    ///
    /// Θ(MN·D) for the parameters, then as [`BSplineSurface::interpolate_at`].
    ///
    /// ```
    /// use compgeo::spline::{Parameterisation, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet, Surface};
    ///
    /// let data = ControlNet::new((0..4).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64, (i * j) as f64])).collect()).collect())?;
    /// let s = BSplineSurface::interpolate(&data, (3, 3), Parameterisation::Uniform)?;
    /// // Uniform parameters 0, 1/3, 2/3, 1; z = xy is bicubic, reproduced.
    /// assert!((s.eval(&(1.0 / 3.0), &(2.0 / 3.0))?[2] - 2.0).abs() < 1e-12);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn interpolate(
        data: &ControlNet<S, D>,
        (p, q): (usize, usize),
        parameterisation: Parameterisation,
    ) -> Result<Self> {
        let rows: Vec<Vec<Point<S, D>>> = data.to_rows();
        let columns: Vec<Vec<Point<S, D>>> = (0..data.columns()).map(|j| data.column(j)).collect();
        let v_params = averaged_parameters(&rows, parameterisation)?;
        let u_params = averaged_parameters(&columns, parameterisation)?;
        let u_knots = rename(KnotVector::averaged(p, &u_params), "u knots")?;
        let v_knots = rename(KnotVector::averaged(q, &v_params), "v knots")?;
        Self::interpolate_at(data, &u_params, &v_params, u_knots, v_knots)
    }
}

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The Bézier patch of bidegree (M − 1, N − 1) through the data: c(u_i, v_j) =
    /// `data`(i, j), for parameters in [0, 1] (where the net describes the patch). See
    /// [`BezierPatch::interpolate_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u parameters"` or `"v parameters"` for another
    /// number of parameters than rows, respectively columns, a NaN or infinite one, one
    /// outside [0, 1] or one not above its predecessor; [`Error::Overflow`] if, with `f64`, a
    /// control point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(M·N²·(N + D) + N·M²·(M + D)) time (banded elimination with full bands), Θ(MN·D)
    /// space.
    pub fn interpolate(data: &ControlNet<S, D>, u_params: &[S], v_params: &[S]) -> Result<Self> {
        Self::interpolate_with(data, u_params, v_params, &mut NoCount)
    }

    /// The interpolating Bézier patch, counting the arithmetic.
    ///
    /// Idea: the B-spline surface interpolation ([`BSplineSurface::interpolate_at_with`]) on
    /// the knots 0, …, 0, 1, …, 1 (M times each in u, N in v), whose surfaces are exactly the
    /// Bézier patches of that bidegree [FJ-surfaces, §7], [PPB, §5.7].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::interpolate`].
    ///
    /// # Complexity
    ///
    /// As [`BezierPatch::interpolate`].
    ///
    /// # Counts
    ///
    /// Those of [`BSplineSurface::interpolate_at_with`].
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// let data = ControlNet::new((0..3).map(|i| (0..3).map(|j| Point::new([i as f64, j as f64, (i * j) as f64])).collect()).collect())?;
    /// let s = BezierPatch::interpolate_with(&data, &[0.0, 0.5, 1.0], &[0.0, 0.5, 1.0], &mut Counts::default())?;
    /// assert_eq!(s.eval(&0.5, &0.5)?, Point::new([1.0, 1.0, 1.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn interpolate_with<C: Counter>(
        data: &ControlNet<S, D>,
        u_params: &[S],
        v_params: &[S],
        counter: &mut C,
    ) -> Result<Self> {
        let (m, n) = (data.rows(), data.columns());
        let u_knots = unit_bezier_knots(m)?;
        let v_knots = unit_bezier_knots(n)?;
        let s = BSplineSurface::interpolate_at_with(
            data, u_params, v_params, u_knots, v_knots, counter,
        )?;
        BezierPatch::new(s.net().clone())
    }
}

/// The knots 0, …, 0, 1, …, 1 (`count` times each) of a Bézier curve with `count` control
/// points as a B-spline on [0, 1].
pub(crate) fn unit_bezier_knots<S: Scalar>(count: usize) -> Result<KnotVector<S>> {
    KnotVector::clamped_uniform(count - 1, count, S::zero(), S::one())
}

/// `count` finite, strictly increasing parameters.
pub(crate) fn check_parameters<S: Scalar>(
    params: &[S],
    count: usize,
    name: &'static str,
) -> Result<()> {
    if params.len() != count {
        return Err(Error::InvalidParameter {
            name,
            reason: format!(
                "{} parameters for {count} rows or columns of data",
                params.len()
            ),
        });
    }
    check_partition(params, 1, name)
}

/// Each curve's parameters scaled to [0, 1], averaged over the curves [PPB, §4.5].
fn averaged_parameters<S: Scalar, const D: usize>(
    curves: &[Vec<Point<S, D>>],
    parameterisation: Parameterisation,
) -> Result<Vec<S>> {
    let count = curves[0].len();
    if count == 1 {
        return Ok(vec![S::zero()]);
    }
    let mut sum = vec![S::zero(); count];
    for curve in curves {
        let params = parameterise(curve, parameterisation)?;
        let last = params[count - 1].clone();
        for (s, t) in sum.iter_mut().zip(&params) {
            *s += &(t.clone() / &last);
        }
    }
    let k = S::from_i64(curves.len() as i64);
    let mut params: Vec<S> = sum.into_iter().map(|s| s / &k).collect();
    // Exactly 0 and 1 at the ends (the averages of exact 0s and 1s may round otherwise).
    params[0] = S::zero();
    params[count - 1] = S::one();
    Ok(params)
}
