//! NURBS surfaces: tensor-product B-spline surfaces with positive weights, as the projection
//! of a B-spline surface in homogeneous coordinates.
//!
//! The problem: s(u, v) = Σ w_{i,j}·c_{i,j}·Nᵢ(u)Nⱼ(v) / Σ w_{i,j}·Nᵢ(u)Nⱼ(v) for a net of
//! points c_{i,j} with weights w_{i,j} > 0 on two knot vectors [SPL, §14], [PPB, §9.1]. The
//! idea, as for [`Nurbs`] curves: keep the homogeneous form, a [`BSplineSurface`] of the
//! weighted points (the numerator a) and one of the weights (the denominator w) on the same
//! knots; every linear operation (knot insertion, refinement, degree elevation, Bézier
//! conversion, isoparametric curves) is the B-spline surface's, run on both, and the point is
//! a(u, v)/w(u, v). On the domain the basis products are non-negative and sum to one, so
//! w ≥ min w_{i,j} > 0 and the division is always defined.
//!
//! Partial derivatives by the quotient rule in two variables (Piegl and Tiller, *The NURBS
//! Book*, 2nd ed., §4.5, eq. (4.20)): from a = w·s,
//! s^{(k,l)} = (a^{(k,l)} − Σ_{(i,j) ≠ (0,0), i ≤ k, j ≤ l} C(k,i)·C(l,j)·w^{(i,j)}·s^{(k−i,l−j)})/w.
//!
//! # Complexity
//!
//! Twice the B-spline surface's costs, plus one division per point; a partial derivative of
//! orders (r, s) needs the (r + 1)(s + 1) partials of a and w and O(r²s²D) for the quotient
//! rule.

use super::bezier_grid::BezierPatchGrid;
use super::bspline::BSplineSurface;
use super::direction::Direction;
use super::net::ControlNet;
use super::tensor_grid::tensor_point;
use super::traits::{Surface, SurfaceDerivative, SurfaceDomain};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::rational::weights::{homogeneous, project, validate_weights};
use crate::spline::{binomial, KnotVector, Nurbs, Point, Scalar};
use crate::{limits, Error, Result};

/// Evaluation of a NURBS surface, declared.
pub(crate) const NURBS_SURFACE_EVAL: Declaration = Declaration {
    problem: "nurbs-surface",
    name: "tensor-de-boor",
    function: "surface::NurbsSurface::de_boor",
    file: "src/surface/nurbs.rs",
    summary: "the B-spline surface evaluation on the weighted points and on the weights, then one division",
    time: "Θ((p² + p·q²)D)",
    space: "O((p + q)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "those of the B-spline surface evaluation, twice",
    source: "[SPL, §14], [PPB, §9.1]",
    claims: &[on("random-bidegree", Bound::Cubic, Operation::ArithmeticOperations)],
};

/// A NURBS surface of bidegree (p, q) in R^D: a net of M × N points with positive weights on
/// a knot vector in u serving M control points and one in v serving N.
///
/// ```
/// use compgeo::spline::{KnotVector, Point};
/// use compgeo::surface::{ControlNet, NurbsSurface, Surface};
///
/// // Bilinear: the weight 3 at one corner pulls the centre towards it.
/// let p = |x: f64, y: f64| Point::new([x, y]);
/// let net = ControlNet::new(vec![vec![p(0.0, 0.0), p(0.0, 1.0)], vec![p(1.0, 0.0), p(1.0, 1.0)]])?;
/// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
/// let s = NurbsSurface::new(net, vec![1.0, 1.0, 1.0, 3.0], t.clone(), t)?;
/// assert_eq!(s.eval(&0.5, &0.5)?, p(4.0 / 6.0, 4.0 / 6.0)); // (0 + 1 + 1 + 3·2)/6 per coordinate pair
/// assert!(NurbsSurface::new(s.net().clone(), vec![1.0, 0.0, 1.0, 1.0], s.u_knots().clone(), s.v_knots().clone()).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct NurbsSurface<S, const D: usize> {
    net: ControlNet<S, D>,
    /// Row after row, as the net's points.
    weights: Vec<S>,
    /// Σ s·w_{i,j}·c_{i,j}·NᵢNⱼ (s the power of two of the curve module's weights, one for exact
    /// scalars).
    numerator: BSplineSurface<S, D>,
    /// Σ s·w_{i,j}·NᵢNⱼ.
    denominator: BSplineSurface<S, 1>,
    scale: S,
}

impl<S: Scalar, const D: usize> NurbsSurface<S, D> {
    /// The surface of `net` with `weights` (row after row, one per point) on `u_knots` and
    /// `v_knots`.
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::new`]; [`Error::InvalidParameter`] named `"weights"` if there is
    /// not one weight per point, or naming the index and value of the first weight that is
    /// NaN, infinite, zero or negative; [`Error::Overflow`] if, with `f64`, a weighted
    /// coordinate is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(MN·D) time and space.
    pub fn new(
        net: ControlNet<S, D>,
        weights: Vec<S>,
        u_knots: KnotVector<S>,
        v_knots: KnotVector<S>,
    ) -> Result<Self> {
        validate_weights(&weights, net.points().len())?;
        let h = homogeneous(net.points(), &weights)?;
        let (m, n) = (net.rows(), net.columns());
        let numerator = BSplineSurface::new(
            ControlNet::from_rows(m, n, h.points)?,
            u_knots.clone(),
            v_knots.clone(),
        )?;
        let denominator =
            BSplineSurface::new(ControlNet::from_rows(m, n, h.weights)?, u_knots, v_knots)?;
        Ok(NurbsSurface {
            net,
            weights,
            numerator,
            denominator,
            scale: h.scale,
        })
    }

    /// The surface whose homogeneous form is computed from this one's (same scale, positive
    /// weights by construction).
    fn derived(
        &self,
        numerator: BSplineSurface<S, D>,
        denominator: BSplineSurface<S, 1>,
    ) -> Result<Self> {
        let control = project(numerator.net().points(), denominator.net().points());
        let weights: Vec<S> = denominator
            .net()
            .points()
            .iter()
            .map(|w| w[0].clone() / &self.scale)
            .collect();
        if !control.iter().all(Point::is_finite) || !weights.iter().all(S::is_finite) {
            return Err(Error::Overflow {
                what: "the control points of a NURBS surface",
            });
        }
        validate_weights(&weights, control.len())?;
        let net =
            ControlNet::from_rows(numerator.net().rows(), numerator.net().columns(), control)?;
        Ok(NurbsSurface {
            net,
            weights,
            numerator,
            denominator,
            scale: self.scale.clone(),
        })
    }

    /// The control net.
    pub fn net(&self) -> &ControlNet<S, D> {
        &self.net
    }

    /// The weights, row after row (w_{i,j} at i·N + j).
    pub fn weights(&self) -> &[S] {
        &self.weights
    }

    /// The knot vector in u.
    pub fn u_knots(&self) -> &KnotVector<S> {
        self.numerator.u_knots()
    }

    /// The knot vector in v.
    pub fn v_knots(&self) -> &KnotVector<S> {
        self.numerator.v_knots()
    }

    /// The bidegree (p, q).
    pub fn bidegree(&self) -> (usize, usize) {
        self.numerator.bidegree()
    }

    /// The homogeneous form: the B-spline surfaces of the weighted points s·w_{i,j}·c_{i,j}
    /// and of the weights s·w_{i,j} (s one for exact scalars, a power of two for `f64`).
    pub fn homogeneous(&self) -> (&BSplineSurface<S, D>, &BSplineSurface<S, 1>) {
        (&self.numerator, &self.denominator)
    }

    /// The point s(u, v). See [`NurbsSurface::de_boor_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` or `"v"` if a parameter is NaN, infinite or
    /// outside the domain.
    ///
    /// # Complexity
    ///
    /// Θ((p² + p·q²)D) time after the span searches, O((p + q)D) space.
    pub fn de_boor(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        self.de_boor_with(u, v, &mut NoCount)
    }

    /// The point s(u, v) in homogeneous coordinates, counting the arithmetic.
    ///
    /// Idea: [`BSplineSurface::de_boor_with`] on the numerator and on the denominator, then
    /// a(u, v)/w(u, v) with w ≥ min w_{i,j} > 0 [SPL, §14].
    ///
    /// # Errors
    ///
    /// As [`NurbsSurface::de_boor`].
    ///
    /// # Complexity
    ///
    /// Θ((p² + p·q²)D) time after the span searches.
    ///
    /// # Counts
    ///
    /// Those of [`BSplineSurface::de_boor_with`], twice; the division is not counted.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{ControlNet, NurbsSurface};
    ///
    /// let net = ControlNet::new((0..3).map(|i| (0..3).map(|j| Point::new([i as f64, j as f64])).collect()).collect())?;
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let s = NurbsSurface::new(net, vec![1.0; 9], t.clone(), t)?;
    /// let mut c = Counts::default();
    /// assert_eq!(s.de_boor_with(&0.5, &0.5, &mut c)?, Point::new([1.0, 1.0]));
    /// assert!(c.arithmetic_operations > 0);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_boor_with<C: Counter>(&self, u: &S, v: &S, counter: &mut C) -> Result<Point<S, D>> {
        let a = self.numerator.de_boor_with(u, v, counter)?;
        let w = self.denominator.de_boor_with(u, v, counter)?;
        Ok(a / &w[0])
    }

    /// The same surface with the knot `t` inserted `times` times in `direction`: the
    /// B-spline surface's insertion on both halves of the homogeneous form (the same α's, so
    /// Boehm's insertion in R^{D+1}) [SPL, §14], [PPB, §6.1].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::insert`].
    ///
    /// # Complexity
    ///
    /// Twice [`BSplineSurface::insert`]'s.
    ///
    /// ```
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{ControlNet, Direction, NurbsSurface, Surface};
    ///
    /// let net = ControlNet::new((0..3).map(|i| (0..3).map(|j| Point::new([i as f64, j as f64])).collect()).collect())?;
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let s = NurbsSurface::new(net, vec![1.0, 2.0, 1.0, 1.0, 4.0, 1.0, 1.0, 2.0, 1.0], t.clone(), t)?;
    /// let r = s.insert(Direction::U, &0.5, 1)?;
    /// assert_eq!(r.net().rows(), 4);
    /// assert_eq!(r.eval(&0.25, &0.75)?, s.eval(&0.25, &0.75)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn insert(&self, direction: Direction, t: &S, times: usize) -> Result<Self> {
        self.insert_with(direction, t, times, &mut NoCount)
    }

    /// [`NurbsSurface::insert`], counting the arithmetic of both insertions.
    ///
    /// # Errors
    ///
    /// As [`NurbsSurface::insert`].
    ///
    /// # Complexity
    ///
    /// As [`NurbsSurface::insert`].
    pub fn insert_with<C: Counter>(
        &self,
        direction: Direction,
        t: &S,
        times: usize,
        counter: &mut C,
    ) -> Result<Self> {
        let a = self.numerator.insert_with(direction, t, times, counter)?;
        let w = self.denominator.insert_with(direction, t, times, counter)?;
        self.derived(a, w)
    }

    /// The same surface with `new_knots` inserted in `direction`, by
    /// [`BSplineSurface::refine`] on both halves of the homogeneous form.
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::refine`].
    ///
    /// # Complexity
    ///
    /// Twice [`BSplineSurface::refine`]'s.
    pub fn refine(&self, direction: Direction, new_knots: &[S]) -> Result<Self> {
        let a = self.numerator.refine(direction, new_knots)?;
        let w = self.denominator.refine(direction, new_knots)?;
        self.derived(a, w)
    }

    /// The same surface with the degree in `direction` raised by `times`, by
    /// [`BSplineSurface::elevate`] on both halves of the homogeneous form [SPL, §14].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::elevate`].
    ///
    /// # Complexity
    ///
    /// Twice [`BSplineSurface::elevate`]'s.
    pub fn elevate(&self, direction: Direction, times: usize) -> Result<Self> {
        let a = self.numerator.elevate(direction, times)?;
        let w = self.denominator.elevate(direction, times)?;
        self.derived(a, w)
    }

    /// The rational Bézier patches in homogeneous form: the Bézier patches of the weighted
    /// points and of the weights ([`BSplineSurface::to_bezier`] on both halves); patch (a, b)
    /// of the surface is the first's divided by the second's.
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::to_bezier`].
    ///
    /// # Complexity
    ///
    /// Twice [`BSplineSurface::to_bezier`]'s.
    pub fn to_bezier_homogeneous(&self) -> Result<(BezierPatchGrid<S, D>, BezierPatchGrid<S, 1>)> {
        Ok((self.numerator.to_bezier()?, self.denominator.to_bezier()?))
    }

    /// The isoparametric curve where `fixed` is `value`, as a [`Nurbs`] curve: the
    /// B-spline surface's isoparametric curves of both halves, projected.
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::isocurve`].
    ///
    /// # Complexity
    ///
    /// Twice [`BSplineSurface::isocurve`]'s.
    ///
    /// ```
    /// use compgeo::spline::{Curve, KnotVector, Point};
    /// use compgeo::surface::{ControlNet, Direction, NurbsSurface, Surface};
    ///
    /// let net = ControlNet::new((0..3).map(|i| (0..3).map(|j| Point::new([i as f64, j as f64])).collect()).collect())?;
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let s = NurbsSurface::new(net, vec![1.0, 2.0, 1.0, 1.0, 4.0, 1.0, 1.0, 2.0, 1.0], t.clone(), t)?;
    /// let c = s.isocurve(Direction::V, &0.5)?;
    /// assert_eq!(c.eval(&0.25)?, s.eval(&0.25, &0.5)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn isocurve(&self, fixed: Direction, value: &S) -> Result<Nurbs<S, D>> {
        let a = self.numerator.isocurve(fixed, value)?;
        let w = self.denominator.isocurve(fixed, value)?;
        Nurbs::from_homogeneous(a, w)
    }
}

/// Defined on the rectangle of the knot vectors' domains, evaluated by
/// [`NurbsSurface::de_boor`].
impl<S: Scalar, const D: usize> Surface<S, D> for NurbsSurface<S, D> {
    fn domain(&self) -> SurfaceDomain<S> {
        self.numerator.domain()
    }

    /// The quotient of the homogeneous form's two points, each the sum of its non-zero
    /// basis products from one pair of bases (the same point as [`NurbsSurface::de_boor`],
    /// with less work).
    fn eval(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        // One pair of bases serves both halves: they share their knots.
        self.domain().check(u, v)?;
        let (bu, bv) = (self.u_knots().basis(u)?, self.v_knots().basis(v)?);
        let a = tensor_point(self.numerator.net(), &bu, &bv);
        let w = tensor_point(self.denominator.net(), &bu, &bv);
        let p = a / &w[0];
        if p.is_finite() {
            Ok(p)
        } else {
            Err(Error::Overflow {
                what: "NURBS surface point",
            })
        }
    }
}

/// The bivariate quotient rule on the partial derivatives of the numerator and the
/// denominator (module docs).
impl<S: Scalar, const D: usize> SurfaceDerivative<S, D> for NurbsSurface<S, D> {
    fn partial_at(&self, u: &S, v: &S, r: usize, s: usize) -> Result<Point<S, D>> {
        self.domain().check(u, v)?;
        limits::DEGREE.check(r as u128)?;
        limits::DEGREE.check(s as u128)?;
        let mut w = vec![vec![S::zero(); s + 1]; r + 1];
        for (k, row) in w.iter_mut().enumerate() {
            for (l, x) in row.iter_mut().enumerate() {
                *x = self.denominator.partial_at(u, v, k, l)?[0].clone();
            }
        }
        let mut table: Vec<Vec<Point<S, D>>> = vec![vec![Point::zero(); s + 1]; r + 1];
        for k in 0..=r {
            for l in 0..=s {
                let mut x = self.numerator.partial_at(u, v, k, l)?;
                for i in 0..=k {
                    for j in 0..=l {
                        if i == 0 && j == 0 {
                            continue;
                        }
                        let c = binomial::<S>(k, i) * &binomial::<S>(l, j) * &w[i][j];
                        x -= &(table[k - i][l - j].clone() * &c);
                    }
                }
                table[k][l] = x / &w[0][0];
            }
        }
        let d = table[r][s].clone();
        if d.is_finite() {
            Ok(d)
        } else {
            Err(Error::Overflow {
                what: "NURBS surface derivative",
            })
        }
    }

    fn first_partials_on_grid(&self, us: &[S], vs: &[S]) -> Result<Vec<[Point<S, D>; 3]>> {
        self.first_partials_grid(us, vs)
    }
}
