//! Tensor-product B-spline surfaces: the type (a control net on two knot vectors, validated
//! once), evaluation and partial derivatives through the curve code.
//!
//! The problem: s(u, v) = Σᵢ Σⱼ c_{i,j} Nᵢᵖ(u) Nⱼ^q(v) for a net of M × N points on a knot
//! vector of M + p + 1 knots in u and one of N + q + 1 knots in v [PPB, §9.1, §9.2],
//! [FJ-surfaces, §1–2], on the rectangle [t_p, t_M] × [τ_q, τ_N] (the crate's knot
//! convention, see [`spline::bspline`](crate::spline::KnotVector)). The idea: row i of the net
//! is the control polygon of a B-spline curve in v on the v knots; its point at v is the
//! i-th control point of the curve s(·, v) in u. Only the p + 1 rows whose basis functions
//! do not vanish at u matter, so the point is Σ Nᵢᵖ(u)·rowᵢ(v) over those rows: p + 1 runs of
//! de Boor's algorithm ([`BSpline::de_boor_with`]) in v and one table of basis values in u.
//!
//! The surface keeps each row as a [`BSpline`] curve, so every row operation (evaluation,
//! derivatives, knot insertion in v, elevation in v, conversion to Bézier form in v) is the
//! curve code's, run once per row; the column operations build the columns' curves on the u
//! knots and run the same code on them. Nothing of de Boor's or Boehm's algorithm is copied.
//!
//! # Complexity
//!
//! Θ(MN·D) to build; one point Θ((p² + p·q²)D) after the span searches; a partial derivative
//! of orders (r, s) O(p² + p·r² + p(q² + q·s² + qD)) beyond that.
//!
//! Invariants the tests check (exactly on rationals): the point equals the sum of basis
//! products, the isoparametric curves' points, and the Bézier patches' after conversion;
//! partial derivatives equal those of the polynomial pieces.

use super::direction::Direction;
use super::net::ControlNet;
use super::traits::{Surface, SurfaceDerivative, SurfaceDomain};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{BSpline, CurveDerivative, KnotVector, Point, Scalar};
use crate::{Error, Result};

/// Evaluation of a B-spline surface, declared.
pub(crate) const TENSOR_DE_BOOR: Declaration = Declaration {
    problem: "bspline-surface",
    name: "tensor-de-boor",
    function: "surface::BSplineSurface::de_boor",
    file: "src/surface/bspline.rs",
    summary: "de Boor's algorithm in v on the p + 1 rows that matter, combined by the basis values in u",
    time: "Θ((p² + p·q²)D)",
    space: "O((p + q)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "(p + 1)·q(q + 1)/2 affine combinations off the v knots, plus the basis values' p(p + 1) operations",
    source: "[PPB, §9.1, §5.4], [FJ-surfaces, §2]",
    claims: &[on("random-bidegree", Bound::Cubic, Operation::ArithmeticOperations)],
};

/// A tensor-product B-spline surface of bidegree (p, q) in R^D: a [`ControlNet`] of M × N
/// points on a [`KnotVector`] of degree p serving M control points (u) and one of degree q
/// serving N (v), defined on [t_p, t_M] × [τ_q, τ_N].
///
/// ```
/// use compgeo::spline::{KnotVector, Point};
/// use compgeo::surface::{BSplineSurface, ControlNet, Surface};
///
/// // Bilinear in u (one interior knot), quadratic in v: the graph of z = x·y² pieces.
/// let net = ControlNet::new((0..3).map(|i| (0..3).map(|j| {
///     Point::new([i as f64, j as f64, (i * j) as f64])
/// }).collect()).collect())?;
/// let tu = KnotVector::new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0])?;
/// let tv = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
/// let s = BSplineSurface::new(net, tu, tv)?;
/// assert_eq!(s.bidegree(), (1, 2));
/// assert_eq!(s.eval(&2.0, &1.0)?, Point::new([2.0, 2.0, 4.0]));
/// assert!(s.eval(&2.5, &0.0).is_err()); // outside [0, 2] in u
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BSplineSurface<S, const D: usize> {
    net: ControlNet<S, D>,
    u_knots: KnotVector<S>,
    /// Row i as a curve in v on the v knots (so the v knots are `rows[0].knots()`).
    rows: Vec<BSpline<S, D>>,
}

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The surface of `net` on `u_knots` (serving `net.rows()` control points) and `v_knots`
    /// (serving `net.columns()`).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u knots"` or `"v knots"` if a knot vector serves
    /// another number of control points than the net has rows, respectively columns (naming
    /// both counts).
    ///
    /// # Complexity
    ///
    /// Θ(MN·D) time and space (the rows are kept as curves).
    pub fn new(
        net: ControlNet<S, D>,
        u_knots: KnotVector<S>,
        v_knots: KnotVector<S>,
    ) -> Result<Self> {
        rename(u_knots.check_control_points(net.rows()), "u knots")?;
        rename(v_knots.check_control_points(net.columns()), "v knots")?;
        let rows = (0..net.rows())
            .map(|i| BSpline::new(net.row(i).to_vec(), v_knots.clone()))
            .collect::<Result<Vec<_>>>()?;
        Ok(BSplineSurface { net, u_knots, rows })
    }

    /// The control net.
    pub fn net(&self) -> &ControlNet<S, D> {
        &self.net
    }

    /// The knot vector in u.
    pub fn u_knots(&self) -> &KnotVector<S> {
        &self.u_knots
    }

    /// The knot vector in v.
    pub fn v_knots(&self) -> &KnotVector<S> {
        self.rows[0].knots()
    }

    /// The knot vector of a direction.
    pub fn knots(&self, direction: Direction) -> &KnotVector<S> {
        match direction {
            Direction::U => self.u_knots(),
            Direction::V => self.v_knots(),
        }
    }

    /// The bidegree (p, q): p in u, q in v.
    pub fn bidegree(&self) -> (usize, usize) {
        (self.u_knots.degree(), self.v_knots().degree())
    }

    /// The rows of the net as B-spline curves in v (row i: c_{i,0}, …, c_{i,N−1}).
    pub fn row_curves(&self) -> &[BSpline<S, D>] {
        &self.rows
    }

    /// The columns of the net as B-spline curves in u (column j: c_{0,j}, …, c_{M−1,j}).
    ///
    /// # Complexity
    ///
    /// Θ(MN·D) time and space.
    pub fn column_curves(&self) -> Result<Vec<BSpline<S, D>>> {
        (0..self.net.columns())
            .map(|j| BSpline::new(self.net.column(j), self.u_knots.clone()))
            .collect()
    }

    /// The curves of a direction: the columns for u, the rows for v.
    pub fn curves(&self, direction: Direction) -> Result<Vec<BSpline<S, D>>> {
        match direction {
            Direction::U => self.column_curves(),
            Direction::V => Ok(self.rows.clone()),
        }
    }

    /// The surface whose curves in `direction` (see [`BSplineSurface::curves`]) are
    /// `curves`, all on the same knots, and whose knots in the other direction are this
    /// surface's: the way back from a curve operation run on every row or column.
    pub(crate) fn with_curves(
        &self,
        direction: Direction,
        curves: Vec<BSpline<S, D>>,
    ) -> Result<Self> {
        let knots = curves[0].knots().clone();
        debug_assert!(curves.iter().all(|c| *c.knots() == knots));
        let count = curves.len();
        let width = knots.control_points();
        let points: Vec<Point<S, D>> = curves.into_iter().flat_map(|c| c.into_parts().0).collect();
        match direction {
            Direction::V => {
                let net = ControlNet::from_rows(count, width, points)?;
                BSplineSurface::new(net, self.u_knots.clone(), knots)
            }
            Direction::U => {
                let net = ControlNet::from_rows(count, width, points)?.transposed();
                BSplineSurface::new(net, knots, self.v_knots().clone())
            }
        }
    }

    /// The same surface with u and v exchanged.
    ///
    /// # Complexity
    ///
    /// Θ(MN·D) time and space.
    pub fn transposed(&self) -> Result<Self> {
        BSplineSurface::new(
            self.net.transposed(),
            self.v_knots().clone(),
            self.u_knots.clone(),
        )
    }

    /// The point s(u, v). See [`BSplineSurface::de_boor_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` or `"v"` if a parameter is NaN, infinite or
    /// outside its knot vector's domain.
    ///
    /// # Complexity
    ///
    /// Θ((p² + p·q²)D) time after the span searches, O((p + q)D) space.
    pub fn de_boor(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        self.de_boor_with(u, v, &mut NoCount)
    }

    /// The point s(u, v), counting the arithmetic.
    ///
    /// Idea: at u only N_{μ−p}, …, N_μ are non-zero (μ the span of u); the point is
    /// Σ Nᵢ(u)·sᵢ(v) over those rows, where sᵢ is row i's curve in v, evaluated by de Boor's
    /// algorithm [PPB, §5.4, §9.1]. The sum is the tensor form of the double sum, with the
    /// other p + 1 − M rows' terms zero.
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::de_boor`].
    ///
    /// # Complexity
    ///
    /// Θ((p² + p·q²)D) time after the span searches, O((p + q)D) space.
    ///
    /// # Counts
    ///
    /// Those of [`KnotVector::basis_with`] at u, of [`BSpline::de_boor_with`] on each of the
    /// p + 1 rows at v, and one [`arithmetic_operation`](Counter::arithmetic_operation) per
    /// row for its term of the sum.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::BSplineSurface;
    /// use compgeo::surface::ControlNet;
    ///
    /// // Control points at 4× the Greville abscissae 0, 1/4, 3/4, 1: the surface is (4u, 4v).
    /// let g = [0.0, 1.0, 3.0, 4.0];
    /// let net = ControlNet::new((0..4).map(|i| (0..4).map(|j| Point::new([g[i], g[j]])).collect()).collect())?;
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?;
    /// let s = BSplineSurface::new(net, t.clone(), t)?;
    /// let mut c = Counts::default();
    /// assert_eq!(s.de_boor_with(&0.25, &0.75, &mut c)?, Point::new([1.0, 3.0]));
    /// assert!(c.arithmetic_operations > 0);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_boor_with<C: Counter>(&self, u: &S, v: &S, counter: &mut C) -> Result<Point<S, D>> {
        self.domain().check(u, v)?;
        let basis = self.u_knots.basis_with(u, counter)?;
        let mut sum = Point::zero();
        for (k, n) in basis.values().iter().enumerate() {
            let row = self.rows[basis.first() + k].de_boor_with(v, counter)?;
            sum += &(row * n);
            counter.arithmetic_operation();
        }
        if sum.is_finite() {
            Ok(sum)
        } else {
            Err(Error::Overflow {
                what: "B-spline surface point",
            })
        }
    }

    /// The same surface in `f64` (knots and coordinates rounded to nearest).
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::new`] and [`KnotVector::new`] if rounding merged knots into a
    /// vector that is no longer valid.
    pub fn to_f64(&self) -> Result<BSplineSurface<f64, D>> {
        let knots = |t: &KnotVector<S>| {
            KnotVector::new(t.degree(), t.knots().iter().map(Scalar::to_f64).collect())
        };
        BSplineSurface::new(
            self.net.to_f64(),
            knots(&self.u_knots)?,
            knots(self.v_knots())?,
        )
    }
}

/// Renames an [`Error::InvalidParameter`] (the curve code names its knots `"knots"`, its
/// parameters `"params"`; a surface has two of each).
pub(crate) fn rename<T>(result: Result<T>, name: &'static str) -> Result<T> {
    result.map_err(|e| match e {
        Error::InvalidParameter { reason, .. } => Error::InvalidParameter { name, reason },
        other => other,
    })
}

/// Defined on the rectangle of the two knot vectors' domains; evaluated by
/// [`BSplineSurface::de_boor`].
impl<S: Scalar, const D: usize> Surface<S, D> for BSplineSurface<S, D> {
    fn domain(&self) -> SurfaceDomain<S> {
        SurfaceDomain {
            u: self.u_knots.domain(),
            v: self.v_knots().domain(),
        }
    }

    /// The sum of the (p + 1)(q + 1) non-zero basis products (the same point as
    /// [`BSplineSurface::de_boor`], a third of its work for bicubics).
    fn eval(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        self.domain().check(u, v)?;
        let (bu, bv) = (self.u_knots.basis(u)?, self.v_knots().basis(v)?);
        let p = super::tensor_grid::tensor_point(self.net(), &bu, &bv);
        if p.is_finite() {
            Ok(p)
        } else {
            Err(Error::Overflow {
                what: "B-spline surface point",
            })
        }
    }
}

/// ∂^{r+s}s/∂u^r∂v^s(u, v) = Σ Nᵢ⁽ʳ⁾(u)·sᵢ⁽ˢ⁾(v): the s-th derivative of the p + 1 rows
/// that matter (the curve code's [`CurveDerivative::derivative_at`]) combined by the r-th
/// derivatives of the basis in u ([`KnotVector::basis_derivatives`]) [PPB, §5.6, §9.6]. From
/// the right at an interior knot, from the left at the end of the domain, as for curves.
impl<S: Scalar, const D: usize> SurfaceDerivative<S, D> for BSplineSurface<S, D> {
    fn partial_at(&self, u: &S, v: &S, r: usize, s: usize) -> Result<Point<S, D>> {
        self.domain().check(u, v)?;
        let p = self.u_knots.degree();
        if r > p {
            return Ok(Point::zero());
        }
        let basis = self.u_knots.basis_derivatives(u, r)?;
        let mut sum = Point::zero();
        for (k, n) in basis.order(r).iter().enumerate() {
            let row = self.rows[basis.first() + k].derivative_at(v, s)?;
            sum += &(row * n);
        }
        if sum.is_finite() {
            Ok(sum)
        } else {
            Err(Error::Overflow {
                what: "B-spline surface derivative",
            })
        }
    }

    fn first_partials_on_grid(&self, us: &[S], vs: &[S]) -> Result<Vec<[Point<S, D>; 3]>> {
        self.first_partials_grid(us, vs)
    }
}
