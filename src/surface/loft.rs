//! The bilinear patch through four points, and lofting: the surface through given curves
//! placed at given parameters.
//!
//! The problem [RD, §3.3]: curves C₀, …, C_{K−1} and parameters v₀ < … < v_{K−1}; find
//! S with S(·, v_k) = C_k (v-lofting; u-lofting places curves in v at values of u). The idea
//! [RD, §3.3]: write S(u, v) = Σ a_i(u)·B_i(v) in a basis B of the lofting direction;
//! the conditions Σ a_i(u)·B_i(v_k) = C_k(u) are one linear system whose solution curves a_i
//! are combinations of the C_k. When every C_k is a B-spline curve on the same knots with the
//! same degree, the a_i are too, and their control points are the same combinations of the
//! C_k's control points: control index by control index, one curve interpolation
//! ([`BSpline::interpolate_at_with`]) in the lofting direction, on B-splines of the chosen
//! knots (the Lagrange basis of the source is the case of one polynomial piece of degree
//! K − 1). Curves of different degrees or knots are first made compatible: each raised to the
//! highest degree ([`BSpline::elevate`]), then given the missing interior knots of the others
//! ([`BSpline::refine`]), which changes no curve.
//!
//! The bilinear patch [RD, §3.3, Def. 3.8] is the tensor interpolant of bidegree (1, 1)
//! through four corners: the Bézier patch whose net is those corners.
//!
//! # Complexity
//!
//! Making K curves of at most N control points compatible: O(K·(elevation + refinement));
//! the loft: N curve interpolations of K points, Θ(N·K(p² + pD)).

use super::bezier::BezierPatch;
use super::bspline::{rename, BSplineSurface};
use super::direction::Direction;
use super::interpolate::check_parameters;
use super::net::ControlNet;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{BSpline, KnotVector, Point, Scalar};
use crate::{Error, Result};

/// Lofting, declared.
pub(crate) const LOFT: Declaration = Declaration {
    problem: "surface-construct",
    name: "loft",
    function: "surface::BSplineSurface::loft",
    file: "src/surface/loft.rs",
    summary: "compatible curves (elevation, knot refinement), then one curve interpolation per control index",
    time: "Θ(N·K(p² + pD)) after making the curves compatible",
    space: "Θ(K·N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "those of the curve interpolations in the lofting direction",
    source: "[RD, §3.3]",
    claims: &[on("random-curves", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The bilinear patch with the corners c(0, 0) = `p00`, c(0, 1) = `p01`, c(1, 0) = `p10`,
    /// c(1, 1) = `p11` [RD, §3.3, Def. 3.8], [FJ-surfaces, §2].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"net"` for a NaN or infinite coordinate.
    ///
    /// # Complexity
    ///
    /// Θ(D).
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, Surface};
    ///
    /// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    /// let s = BezierPatch::bilinear(p(0.0, 0.0, 0.0), p(0.0, 1.0, 1.0), p(1.0, 0.0, 1.0), p(1.0, 1.0, 0.0))?;
    /// assert_eq!(s.eval(&1.0, &0.0)?, p(1.0, 0.0, 1.0));
    /// assert_eq!(s.eval(&0.5, &0.5)?, p(0.5, 0.5, 0.5));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bilinear(
        p00: Point<S, D>,
        p01: Point<S, D>,
        p10: Point<S, D>,
        p11: Point<S, D>,
    ) -> Result<Self> {
        BezierPatch::new(ControlNet::new(vec![vec![p00, p01], vec![p10, p11]])?)
    }
}

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The surface through `curves` placed at `params` in the direction `placed`: with
    /// [`Direction::V`] (v-lofting) the curves are curves in u and s(·, v_k) = C_k; with
    /// [`Direction::U`] they are curves in v and s(u_k, ·) = C_k. `knots` is the knot vector
    /// of the lofting direction (serving one control point per curve). See
    /// [`BSplineSurface::loft_with`].
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no curves; [`Error::InvalidParameter`] named `"curves"` if the
    /// curves have different domains or knots outside the domain that differ (they cannot be
    /// made compatible by knot insertion); as [`BSplineSurface::interpolate_at`] for
    /// `params` (named `"u parameters"` or `"v parameters"`) and `knots` (`"u knots"`,
    /// `"v knots"`); as [`BSpline::elevate`] and [`BSpline::refine`].
    ///
    /// # Complexity
    ///
    /// Θ(N·K(p² + pD)) after making the curves compatible, Θ(K·N·D) space.
    pub fn loft(
        curves: &[BSpline<S, D>],
        placed: Direction,
        params: &[S],
        knots: KnotVector<S>,
    ) -> Result<Self> {
        Self::loft_with(curves, placed, params, knots, &mut NoCount)
    }

    /// The lofted surface, counting the arithmetic.
    ///
    /// Idea: make the curves compatible (same degree, same knots), then interpolate, for each
    /// control index j, the j-th control points of the curves at the parameters in the lofting
    /// direction [RD, §3.3].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::loft`].
    ///
    /// # Complexity
    ///
    /// As [`BSplineSurface::loft`].
    ///
    /// # Counts
    ///
    /// Those of [`BSpline::interpolate_at_with`] on each control index (the compatibility
    /// step is not counted).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, Direction, Surface};
    ///
    /// // A line and a parabola in u, lofted linearly in v: a ruled surface.
    /// let line = BSpline::new(vec![Point::new([0.0, 0.0]), Point::new([2.0, 0.0])], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// let arch = BSpline::new(vec![Point::new([0.0, 1.0]), Point::new([1.0, 3.0]), Point::new([2.0, 1.0])], KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?)?;
    /// let s = BSplineSurface::loft_with(&[line.clone(), arch.clone()], Direction::V, &[0.0, 1.0], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?, &mut Counts::default())?;
    /// assert_eq!(s.bidegree(), (2, 1));
    /// assert_eq!(s.eval(&0.5, &0.0)?, line.eval(&0.5)?);
    /// assert_eq!(s.eval(&0.5, &1.0)?, arch.eval(&0.5)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn loft_with<C: Counter>(
        curves: &[BSpline<S, D>],
        placed: Direction,
        params: &[S],
        knots: KnotVector<S>,
        counter: &mut C,
    ) -> Result<Self> {
        if curves.is_empty() {
            return Err(Error::Empty {
                what: "curves to loft",
            });
        }
        let knots_name = match placed {
            Direction::U => "u knots",
            Direction::V => "v knots",
        };
        let params_name = match placed {
            Direction::U => "u parameters",
            Direction::V => "v parameters",
        };
        let k = curves.len();
        rename(knots.check_control_points(k), knots_name)?;
        check_parameters(params, k, params_name)?;
        rename(knots.check_schoenberg_whitney(params), params_name)?;
        let curves = make_compatible(curves)?;
        let along = curves[0].knots().clone();
        let n = along.control_points();
        // Column j of the net (in the lofting direction): the curves' j-th control points,
        // interpolated at the parameters.
        let mut columns = Vec::with_capacity(n * k);
        for j in 0..n {
            let points: Vec<Point<S, D>> = curves.iter().map(|c| c.control()[j].clone()).collect();
            let column = BSpline::interpolate_at_with(&points, params, knots.clone(), counter)?;
            columns.extend(column.into_parts().0);
        }
        // Row i of `by_index` is control index i of the curves: a curve of the net in the
        // lofting direction's transpose.
        let net = ControlNet::from_rows(n, k, columns)?;
        match placed {
            // Curves in v placed at u_k: the net's rows are indexed by u (the lofting).
            Direction::U => BSplineSurface::new(net.transposed(), knots, along),
            // Curves in u placed at v_k: rows indexed by the curves' control index.
            Direction::V => BSplineSurface::new(net, along, knots),
        }
    }
}

/// The curves with one degree (the highest) and one knot vector (every interior knot with the
/// highest multiplicity any curve has), unchanged as curves [PPB, §6.1, §6.4].
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"curves"` for different domains, or knots outside the
/// domain that still differ.
pub(crate) fn make_compatible<S: Scalar, const D: usize>(
    curves: &[BSpline<S, D>],
) -> Result<Vec<BSpline<S, D>>> {
    let first = curves[0].knots().bounds();
    for (k, c) in curves.iter().enumerate() {
        if c.knots().bounds() != first {
            let (a, b) = c.knots().bounds();
            return Err(Error::InvalidParameter {
                name: "curves",
                reason: format!(
                    "curve {k} is defined on [{}, {}] but curve 0 on [{}, {}]: lofted curves \
                     need one domain",
                    a.to_f64(),
                    b.to_f64(),
                    first.0.to_f64(),
                    first.1.to_f64()
                ),
            });
        }
    }
    let degree = curves.iter().map(BSpline::degree).max().unwrap_or(0);
    let elevated = curves
        .iter()
        .map(|c| c.elevate(degree - c.degree()))
        .collect::<Result<Vec<_>>>()?;
    // The highest multiplicity of every interior knot (strictly inside the domain).
    let (start, end) = (first.0.clone(), first.1.clone());
    let mut wanted: Vec<(S, usize)> = Vec::new();
    for c in &elevated {
        for (x, r) in c.knots().multiplicities() {
            if x <= start || x >= end {
                continue;
            }
            match wanted.iter_mut().find(|(y, _)| *y == x) {
                Some((_, s)) => *s = (*s).max(r),
                None => wanted.push((x, r)),
            }
        }
    }
    let refined = elevated
        .iter()
        .map(|c| {
            let mut missing = Vec::new();
            for (x, r) in &wanted {
                let have = c.knots().multiplicity(x);
                missing.extend(std::iter::repeat_n(x.clone(), r - have));
            }
            if missing.is_empty() {
                Ok(c.clone())
            } else {
                c.refine(&missing)
            }
        })
        .collect::<Result<Vec<_>>>()?;
    if let Some(k) = refined.iter().position(|c| c.knots() != refined[0].knots()) {
        return Err(Error::InvalidParameter {
            name: "curves",
            reason: format!(
                "curve {k} has knots outside the domain that differ from curve 0's (clamp the \
                 curves first): they cannot be made compatible by knot insertion"
            ),
        });
    }
    Ok(refined)
}
