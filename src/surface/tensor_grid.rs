//! A tensor-product spline on a grid of parameters, with each parameter's basis computed
//! once: the kernel of the B-spline and NURBS surfaces' grid evaluation.
//!
//! The problem: the points Σₖ Σₗ Nₖ(uᵢ) Mₗ(vⱼ) c_{k,l} for every pair of a list of u
//! parameters and a list of v parameters (a rendering grid, a tessellation). The idea: the
//! sum is a curve in v whose control points are curves in u [FJ-surfaces, §1–2], so for each
//! uᵢ first collapse the net's rows into one row of points qₗ = Σₖ Nₖ(uᵢ) c_{k,l} (the
//! control polygon of the isoparametric curve at uᵢ), then for each vⱼ take the d_v + 1
//! non-zero terms Σₗ Mₗ(vⱼ) qₗ. The basis of every vⱼ is computed once, before the rows, so
//! a point costs d_v + 1 multiply-adds of points; a row of the grid adds the isoparametric
//! curve's n_v(d_u + 1).

use super::{BSplineSurface, ControlNet, NurbsSurface, Surface};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Basis, BasisDerivatives, KnotVector, Point, Scalar};
use crate::{limits, Error, Result};

/// [`BSplineSurface::eval_grid`], declared.
pub(crate) const BSPLINE_GRID: Declaration = Declaration {
    problem: "bspline-surface",
    name: "grid",
    function: "surface::BSplineSurface::eval_grid",
    file: "src/surface/tensor_grid.rs",
    summary: "every pair of two parameter lists, each parameter's basis once, the isoparametric curve of each u once",
    time: "Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²)",
    space: "Θ(N_u·N_v·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one multiply-add of points per term: (q + 1) per point and N(p + 1) per u, plus the basis values' p(p + 1)/2 per u and q(q + 1)/2 per v",
    source: "[FJ-surfaces, §1–2], [PPB, §9.1]",
    claims: &[on("grid-rows", Bound::Linear, Operation::ArithmeticOperations)],
};

/// [`NurbsSurface::eval_grid`], declared.
pub(crate) const NURBS_GRID: Declaration = Declaration {
    problem: "nurbs-surface",
    name: "grid",
    function: "surface::NurbsSurface::eval_grid",
    file: "src/surface/tensor_grid.rs",
    summary: "the homogeneous form's two grids, then one division per point",
    time: "Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²)",
    space: "Θ(N_u·N_v·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts:
        "those of the two B-spline grids (the weighted points and the weights) and one per division",
    source: "[FJ-surfaces, §1–2], [SPL, §14]",
    claims: &[on(
        "grid-rows",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The points s(uᵢ, vⱼ) for every uᵢ in `us` and vⱼ in `vs`, row-major (entry
    /// i·|vs| + j), in any order of the parameters. See [`BSplineSurface::eval_grid_with`].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::eval_grid_with`].
    ///
    /// # Complexity
    ///
    /// Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²) time for N_u × N_v
    /// parameters, N columns and bidegree (p, q); Θ(N_u·N_v·D) space for the output.
    ///
    /// ```
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet, Surface};
    ///
    /// let net = ControlNet::new((0..4).map(|i| (0..3).map(|j| {
    ///     Point::new([i as f64, j as f64, (i * j) as f64])
    /// }).collect()).collect())?;
    /// let s = BSplineSurface::new(
    ///     net,
    ///     KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?,
    ///     KnotVector::clamped_uniform(1, 3, 0.0, 1.0)?,
    /// )?;
    /// let (us, vs) = ([0.0, 0.25, 1.0], [0.5, 0.0]);
    /// let grid = s.eval_grid(&us, &vs)?;
    /// assert_eq!(grid.len(), 6);
    /// assert_eq!(grid[2 * 2 + 1], s.eval(&1.0, &0.0)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval_grid(&self, us: &[S], vs: &[S]) -> Result<Vec<Point<S, D>>> {
        self.eval_grid_with(us, vs, &mut NoCount)
    }

    /// [`BSplineSurface::eval_grid`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per multiply-add of points and
    /// the basis computations' own ([`KnotVector::basis_with`]).
    ///
    /// Idea: the surface at u is a curve in v whose control points are the net's columns
    /// evaluated at u [FJ-surfaces, §1–2]; so for each uᵢ, combine the p + 1 rows that matter
    /// into that curve's N control points once, then evaluate it at every vⱼ from the q + 1
    /// basis values of vⱼ, computed once for the whole grid.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"u"` for a
    /// parameter (of either list) that is NaN, infinite or outside its knot vector's domain;
    /// [`Error::LimitExceeded`](crate::Error::LimitExceeded) beyond
    /// [`MAX_SAMPLES`](crate::limits::MAX_SAMPLES) points, before anything is allocated;
    /// [`Error::Overflow`] if, with `f64`, a point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²) time, Θ(N_u·N_v·D) space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet};
    ///
    /// let net = ControlNet::new(vec![vec![Point::new([0.0]); 4]; 4])?;
    /// let t = KnotVector::clamped_uniform(3, 4, 0.0, 1.0)?;
    /// let s = BSplineSurface::new(net, t.clone(), t)?;
    /// let mut c = Counts::default();
    /// s.eval_grid_with(&[0.5; 10], &[0.5; 20], &mut c)?;
    /// // Per u: 4 columns of 4 terms and the basis (6); per v: its basis (6); per point: 4.
    /// assert_eq!(c.arithmetic_operations, 10 * (16 + 6) + 20 * 6 + 200 * 4);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval_grid_with<C: Counter>(
        &self,
        us: &[S],
        vs: &[S],
        counter: &mut C,
    ) -> Result<Vec<Point<S, D>>> {
        let grid = tensor_grid_with(self.net(), self.u_knots(), self.v_knots(), us, vs, counter)?;
        if grid.iter().all(Point::is_finite) {
            Ok(grid)
        } else {
            Err(Error::Overflow {
                what: "B-spline surface point",
            })
        }
    }
}

impl<S: Scalar, const D: usize> NurbsSurface<S, D> {
    /// The points s(uᵢ, vⱼ) for every uᵢ in `us` and vⱼ in `vs`, row-major (entry
    /// i·|vs| + j). See [`NurbsSurface::eval_grid_with`].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::eval_grid_with`].
    ///
    /// # Complexity
    ///
    /// Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²) time, Θ(N_u·N_v·D) space.
    ///
    /// ```
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{ControlNet, NurbsSurface, Surface};
    ///
    /// let net = ControlNet::new((0..3).map(|i| (0..3).map(|j| Point::new([i as f64, j as f64])).collect()).collect())?;
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let s = NurbsSurface::new(net, vec![1.0, 2.0, 1.0, 1.0, 4.0, 1.0, 1.0, 2.0, 1.0], t.clone(), t)?;
    /// let grid = s.eval_grid(&[0.0, 0.5], &[0.25, 1.0])?;
    /// assert_eq!(grid[1 * 2 + 0], s.eval(&0.5, &0.25)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval_grid(&self, us: &[S], vs: &[S]) -> Result<Vec<Point<S, D>>> {
        self.eval_grid_with(us, vs, &mut NoCount)
    }

    /// [`NurbsSurface::eval_grid`], counting the arithmetic: the grids of both halves of the
    /// homogeneous form ([`BSplineSurface::eval_grid_with`]) and one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per division.
    ///
    /// Idea: the weighted points and the weights are B-spline surfaces on the same knots
    /// [SPL, §14]; their grids divided point by point are the rational surface's (every
    /// weight positive, so no division by zero).
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::eval_grid_with`].
    ///
    /// # Complexity
    ///
    /// Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²) time, Θ(N_u·N_v·D) space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{ControlNet, NurbsSurface};
    ///
    /// let net = ControlNet::new(vec![vec![Point::new([1.0, 2.0]); 3]; 3])?;
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let s = NurbsSurface::new(net, vec![3.0; 9], t.clone(), t)?;
    /// let mut c = Counts::default();
    /// assert_eq!(s.eval_grid_with(&[0.5], &[0.5], &mut c)?, [Point::new([1.0, 2.0])]);
    /// // Each half: 3 columns of 3 terms, two bases of 3, 3 terms; then the division.
    /// assert_eq!(c.arithmetic_operations, 2 * (9 + 3 + 3 + 3) + 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval_grid_with<C: Counter>(
        &self,
        us: &[S],
        vs: &[S],
        counter: &mut C,
    ) -> Result<Vec<Point<S, D>>> {
        let (numerator, denominator) = self.homogeneous();
        let a = numerator.eval_grid_with(us, vs, counter)?;
        let w = denominator.eval_grid_with(us, vs, counter)?;
        let grid: Vec<Point<S, D>> = a
            .into_iter()
            .zip(&w)
            .map(|(a, w)| {
                counter.arithmetic_operation();
                a / &w[0]
            })
            .collect();
        if grid.iter().all(Point::is_finite) {
            Ok(grid)
        } else {
            Err(Error::Overflow {
                what: "NURBS surface point",
            })
        }
    }
}

/// The tensor-product spline with control net `net` (row k along u, column l along v) on
/// the knot vectors `ku` (for the rows) and `kv` (for the columns), at every pair (uᵢ, vⱼ),
/// row-major: entry i·|vs| + j is the point at (uᵢ, vⱼ). The parameters may come in any
/// order. One [`arithmetic_operation`](Counter::arithmetic_operation) per multiply-add of a
/// point, besides the basis computations' own counts.
///
/// # Errors
///
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"u"` for a parameter
/// that is NaN or outside the domain (as [`KnotVector::basis`]);
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) beyond
/// [`MAX_SAMPLES`](crate::limits::MAX_SAMPLES) points, before anything is allocated.
///
/// # Complexity
///
/// Θ(N_u·N_v·(d_v + 1)·E + N_u·n_v·(d_u + 1)·E + (N_u·d_u² + N_v·d_v²)) for N_u × N_v
/// parameters, n_v columns and points of E coordinates; Θ(N_u·N_v·E) space for the output.
pub(crate) fn tensor_grid_with<S: Scalar, const E: usize, C: Counter>(
    net: &ControlNet<S, E>,
    ku: &KnotVector<S>,
    kv: &KnotVector<S>,
    us: &[S],
    vs: &[S],
    counter: &mut C,
) -> Result<Vec<Point<S, E>>> {
    limits::SAMPLES.check(us.len() as u128 * vs.len() as u128)?;
    let v_bases = vs
        .iter()
        .map(|v| kv.basis_with(v, counter))
        .collect::<Result<Vec<Basis<S>>>>()?;
    let mut out = Vec::with_capacity(us.len() * vs.len());
    let mut row = vec![Point::<S, E>::zero(); net.columns()];
    for u in us {
        let b = ku.basis_with(u, counter)?;
        for (l, q) in row.iter_mut().enumerate() {
            *q = weighted_sum(b.values(), b.first(), |k| net.get(k, l), counter);
        }
        for m in &v_bases {
            out.push(weighted_sum(m.values(), m.first(), |l| &row[l], counter));
        }
    }
    Ok(out)
}

/// The tensor-product spline and its first partials `[c, c_u, c_v]` at every pair of `us`
/// × `vs`, row-major, from each parameter's basis and first derivatives (`bases`, computed
/// once); the same scheme as [`tensor_grid_with`], with the derivative rows beside the
/// value rows.
///
/// # Complexity
///
/// Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²) time, Θ(N_u·N_v·D) space.
pub(crate) fn tensor_grid_first_partials<S: Scalar, const E: usize>(
    net: &ControlNet<S, E>,
    bases: &FirstDerivativeBases<S>,
) -> Vec<[Point<S, E>; 3]> {
    let FirstDerivativeBases {
        u: u_bases,
        v: v_bases,
    } = bases;
    let mut out = Vec::with_capacity(u_bases.len() * v_bases.len());
    let mut values = vec![Point::<S, E>::zero(); net.columns()];
    let mut slopes = values.clone();
    for b in u_bases {
        for l in 0..net.columns() {
            let column = |k: usize| net.get(k, l);
            values[l] = weighted_sum(b.order(0), b.first(), column, &mut NoCount);
            slopes[l] = weighted_sum(b.order(1), b.first(), column, &mut NoCount);
        }
        for m in v_bases {
            let (m0, m1, first) = (m.order(0), m.order(1), m.first());
            out.push([
                weighted_sum(m0, first, |l| &values[l], &mut NoCount),
                weighted_sum(m0, first, |l| &slopes[l], &mut NoCount),
                weighted_sum(m1, first, |l| &values[l], &mut NoCount),
            ]);
        }
    }
    out
}

/// The values and first derivatives of the non-zero basis functions at every parameter of
/// a grid, computed once and shared by the two halves of a NURBS surface's homogeneous form.
pub(crate) struct FirstDerivativeBases<S> {
    u: Vec<BasisDerivatives<S>>,
    v: Vec<BasisDerivatives<S>>,
}

impl<S: Scalar> FirstDerivativeBases<S> {
    /// The bases of `us` on `ku` and of `vs` on `kv`.
    ///
    /// # Errors
    ///
    /// As [`KnotVector::basis_derivatives`];
    /// [`Error::LimitExceeded`](crate::Error::LimitExceeded) beyond
    /// [`MAX_SAMPLES`](crate::limits::MAX_SAMPLES) grid points, before anything is allocated.
    fn new(ku: &KnotVector<S>, kv: &KnotVector<S>, us: &[S], vs: &[S]) -> Result<Self> {
        limits::SAMPLES.check(us.len() as u128 * vs.len() as u128)?;
        let of = |t: &KnotVector<S>, xs: &[S]| {
            xs.iter()
                .map(|x| t.basis_derivatives(x, 1))
                .collect::<Result<Vec<_>>>()
        };
        Ok(FirstDerivativeBases {
            u: of(ku, us)?,
            v: of(kv, vs)?,
        })
    }
}

/// Checks every parameter of a grid against the surface's domain, naming it `"u"` or `"v"`.
fn check_grid<S: Scalar>(domain: &super::SurfaceDomain<S>, us: &[S], vs: &[S]) -> Result<()> {
    let (Some(u0), Some(v0)) = (us.first(), vs.first()) else {
        return Ok(());
    };
    us.iter().try_for_each(|u| domain.check(u, v0))?;
    vs.iter().try_for_each(|v| domain.check(u0, v))
}

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// [`SurfaceDerivative::first_partials_on_grid`] by the bases and first derivatives of
    /// every parameter, once.
    pub(super) fn first_partials_grid(&self, us: &[S], vs: &[S]) -> Result<Vec<[Point<S, D>; 3]>> {
        check_grid(&self.domain(), us, vs)?;
        let bases = FirstDerivativeBases::new(self.u_knots(), self.v_knots(), us, vs)?;
        let grid = tensor_grid_first_partials(self.net(), &bases);
        if grid.iter().flatten().all(Point::is_finite) {
            Ok(grid)
        } else {
            Err(Error::Overflow {
                what: "B-spline surface point or partial",
            })
        }
    }
}

impl<S: Scalar, const D: usize> NurbsSurface<S, D> {
    /// [`SurfaceDerivative::first_partials_on_grid`] by the quotient rule on the grids of the
    /// homogeneous form: c = a/w, c_u = (a_u − w_u·c)/w, c_v = (a_v − w_v·c)/w [SPL, §14].
    pub(super) fn first_partials_grid(&self, us: &[S], vs: &[S]) -> Result<Vec<[Point<S, D>; 3]>> {
        let (numerator, denominator) = self.homogeneous();
        check_grid(&numerator.domain(), us, vs)?;
        // One set of bases serves both halves: they share their knots.
        let bases = FirstDerivativeBases::new(self.u_knots(), self.v_knots(), us, vs)?;
        let a = tensor_grid_first_partials(numerator.net(), &bases);
        let w = tensor_grid_first_partials(denominator.net(), &bases);
        let grid: Vec<[Point<S, D>; 3]> = a
            .into_iter()
            .zip(&w)
            .map(|([a, a_u, a_v], [w, w_u, w_v])| {
                let c = a / &w[0];
                let c_u = (a_u - &(c.clone() * &w_u[0])) / &w[0];
                let c_v = (a_v - &(c.clone() * &w_v[0])) / &w[0];
                [c, c_u, c_v]
            })
            .collect();
        if grid.iter().flatten().all(Point::is_finite) {
            Ok(grid)
        } else {
            Err(Error::Overflow {
                what: "NURBS surface point or partial",
            })
        }
    }
}

/// The tensor-product spline at one pair (u, v) from the bases `bu` of u and `bv` of v:
/// Σₖ Σₗ Nₖ(u) Mₗ(v) c_{k,l} over the (p + 1)(q + 1) terms that do not vanish; what `eval`
/// of the B-spline and NURBS surfaces runs (their declared algorithm, de Boor on the rows,
/// costs a triangle of affine combinations per row instead of one multiply-add per term).
///
/// # Complexity
///
/// Θ((p + 1)(q + 1)D) time, O(D) space.
pub(crate) fn tensor_point<S: Scalar, const E: usize>(
    net: &ControlNet<S, E>,
    bu: &Basis<S>,
    bv: &Basis<S>,
) -> Point<S, E> {
    let mut sum = Point::<S, E>::zero();
    for (k, nk) in bu.values().iter().enumerate() {
        let row = net.row(bu.first() + k);
        let q = weighted_sum(bv.values(), bv.first(), |l| &row[l], &mut NoCount);
        sum += &(q * nk);
    }
    sum
}

/// Σₖ wₖ · point(first + k), one counted multiply-add per term.
fn weighted_sum<'a, S: Scalar + 'a, const E: usize, C: Counter>(
    weights: &[S],
    first: usize,
    point: impl Fn(usize) -> &'a Point<S, E>,
    counter: &mut C,
) -> Point<S, E> {
    let mut sum = Point::<S, E>::zero();
    for (k, w) in weights.iter().enumerate() {
        counter.arithmetic_operation();
        sum += &(point(first + k).clone() * w);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::{Counts, NoCount};
    use crate::spline::{BSpline, Curve};

    /// A bidegree (2, 3) net of 4 × 5 points in R² on clamped knots with an interior knot.
    fn setup() -> (ControlNet<f64, 2>, KnotVector<f64>, KnotVector<f64>) {
        let rows = (0..4)
            .map(|k| {
                (0..5)
                    .map(|l| Point::new([k as f64 + 0.25 * l as f64, (k * l) as f64 - 1.5]))
                    .collect()
            })
            .collect();
        let ku = KnotVector::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]).unwrap();
        let kv = KnotVector::clamped_uniform(3, 5, 0.0, 2.0).unwrap();
        (ControlNet::new(rows).unwrap(), ku, kv)
    }

    #[test]
    fn the_grid_is_the_curve_of_curves() {
        let (net, ku, kv) = setup();
        let us = [0.0, 0.3, 0.5, 0.75, 1.0];
        let vs = [2.0, 0.1, 1.0, 1.5];
        let mut c = Counts::default();
        let grid = tensor_grid_with(&net, &ku, &kv, &us, &vs, &mut c).unwrap();
        assert_eq!(grid.len(), us.len() * vs.len());
        for (i, u) in us.iter().enumerate() {
            // The isoparametric curve at u: every column evaluated at u, as a curve in v.
            let column = |l: usize| BSpline::new(net.column(l), ku.clone()).unwrap();
            let q: Vec<Point<f64, 2>> = (0..5).map(|l| column(l).eval(u).unwrap()).collect();
            let curve = BSpline::new(q, kv.clone()).unwrap();
            for (j, v) in vs.iter().enumerate() {
                let want = curve.eval(v).unwrap();
                let got = &grid[i * vs.len() + j];
                assert!((got[0] - want[0]).abs() < 1e-13 && (got[1] - want[1]).abs() < 1e-13);
            }
        }
        // Per u: 5 columns of 3 terms; per point: 4 terms.
        let basis = us.len() * 3 + vs.len() * 6;
        assert_eq!(
            c.arithmetic_operations as usize,
            us.len() * (5 * 3 + vs.len() * 4) + basis
        );
    }

    #[test]
    fn bad_parameters_are_errors() {
        let (net, ku, kv) = setup();
        assert!(tensor_grid_with(&net, &ku, &kv, &[f64::NAN], &[0.0], &mut NoCount).is_err());
        assert!(tensor_grid_with(&net, &ku, &kv, &[0.0], &[2.5], &mut NoCount).is_err());
        assert!(tensor_grid_with(&net, &ku, &kv, &[], &[0.0], &mut NoCount)
            .unwrap()
            .is_empty());
    }
}
