//! The isoparametric curves of a B-spline surface, as B-spline curves.
//!
//! The problem: the curves s(u₀, ·) and s(·, v₀) on the surface. The idea [FJ-surfaces, §2],
//! [PPB, §9.1]: s(·, v₀) = Σᵢ rowᵢ(v₀)·Nᵢ(u) is the B-spline curve on the u knots whose
//! control points are the rows' points at v₀ (de Boor's algorithm on every row);
//! s(u₀, ·) = Σⱼ (Σᵢ Nᵢ(u₀)·c_{i,j})·Nⱼ(v) is the curve on the v knots whose control points
//! are the columns' points at u₀, combinations of the p + 1 rows whose basis functions do
//! not vanish at u₀.
//!
//! # Complexity
//!
//! s(·, v₀): Θ(M·q²·D) after the span searches; s(u₀, ·): Θ(p² + p·N·D).

use super::bspline::BSplineSurface;
use super::direction::Direction;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{BSpline, Point, Scalar};
use crate::{Error, Result};

/// The isoparametric curves of a B-spline surface, declared.
pub(crate) const SURFACE_ISOCURVE: Declaration = Declaration {
    problem: "bspline-surface",
    name: "isoparametric",
    function: "surface::BSplineSurface::isocurve",
    file: "src/surface/bspline_iso.rs",
    summary: "de Boor on every row (a curve in u), or the basis in u applied to p + 1 rows (a curve in v)",
    time: "Θ(M·q²·D) at v₀, Θ(p² + p·N·D) at u₀",
    space: "Θ(M·D) or Θ(N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "those of de Boor's algorithm on each row, or of the basis plus one per point and row",
    source: "[FJ-surfaces, §2], [PPB, §9.1]",
    claims: &[on("random-net", Bound::Linear, Operation::ArithmeticOperations), on("random-columns", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The isoparametric curve where the parameter `fixed` is `value`: s(value, ·) (a curve
    /// in v) for [`Direction::U`], s(·, value) (a curve in u) for [`Direction::V`]. See
    /// [`BSplineSurface::isocurve_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` or `"v"` if `value` is NaN, infinite or
    /// outside that parameter's domain; [`Error::Overflow`] if, with `f64`, a control point is
    /// beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(M·q²·D) at v₀, Θ(p² + p·N·D) at u₀, after the span searches; Θ(M·D) or Θ(N·D)
    /// space.
    pub fn isocurve(&self, fixed: Direction, value: &S) -> Result<BSpline<S, D>> {
        self.isocurve_with(fixed, value, &mut NoCount)
    }

    /// The isoparametric curve, counting the arithmetic.
    ///
    /// Idea: with v fixed, the rows' points at v (de Boor) are the control points in u; with
    /// u fixed, the columns' points at u, Σᵢ Nᵢ(u)·c_{i,j} over the p + 1 rows that matter
    /// [FJ-surfaces, §2], [PPB, §9.1].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::isocurve`].
    ///
    /// # Complexity
    ///
    /// As [`BSplineSurface::isocurve`].
    ///
    /// # Counts
    ///
    /// v fixed: those of [`BSpline::de_boor_with`] on every row. u fixed: those of
    /// [`KnotVector::basis_with`](crate::spline::KnotVector::basis_with) and one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per row and control point.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{Curve, KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet, Direction, Surface};
    ///
    /// let net = ControlNet::new((0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64, (i * j) as f64])).collect()).collect())?;
    /// let s = BSplineSurface::new(net, KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?, KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?)?;
    /// let c = s.isocurve_with(Direction::U, &0.25, &mut Counts::default())?;
    /// assert_eq!(c.knots(), s.v_knots());
    /// assert_eq!(c.eval(&0.75)?, s.eval(&0.25, &0.75)?);
    /// let d = s.isocurve(Direction::V, &0.75)?;
    /// assert_eq!(d.eval(&0.25)?, s.eval(&0.25, &0.75)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn isocurve_with<C: Counter>(
        &self,
        fixed: Direction,
        value: &S,
        counter: &mut C,
    ) -> Result<BSpline<S, D>> {
        let control: Vec<Point<S, D>> = match fixed {
            Direction::V => {
                self.v_knots().domain().check(value, "v")?;
                self.row_curves()
                    .iter()
                    .map(|row| row.de_boor_with(value, counter))
                    .collect::<Result<_>>()?
            }
            Direction::U => {
                self.u_knots().domain().check(value, "u")?;
                let basis = self.u_knots().basis_with(value, counter)?;
                let mut control = vec![Point::zero(); self.net().columns()];
                for (k, n) in basis.values().iter().enumerate() {
                    for (c, p) in control.iter_mut().zip(self.net().row(basis.first() + k)) {
                        *c += &(p.clone() * n);
                        counter.arithmetic_operation();
                    }
                }
                control
            }
        };
        if !control.iter().all(Point::is_finite) {
            return Err(Error::Overflow {
                what: "isoparametric curve",
            });
        }
        BSpline::new(control, self.knots(fixed.other()).clone())
    }
}
