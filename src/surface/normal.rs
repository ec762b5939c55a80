//! The normal of any differentiable surface in R³, with a first-order answer where the
//! partial derivatives are parallel.
//!
//! The problem: a normal vector at c(u, v). The idea: c_u × c_v is normal wherever the
//! partials are independent [FJ-surfaces, §6]. Where that product vanishes (a collapsed edge
//! such as the pole of a sphere patch, or a corner with aligned control points) the surface
//! may still have a tangent plane that this parametrisation does not show at that point.
//! Then the normal at nearby parameters, n(u + h, v + k) = c_u × c_v at the moved point,
//! starts with its first-order terms h·A + k·B, where
//!
//! A = ∂n/∂u = c_uu × c_v + c_u × c_uv,   B = ∂n/∂v = c_uv × c_v + c_u × c_vv,
//!
//! so the normals approaching from the direction (h, k) tend to the direction of h·A + k·B
//! whenever that is not zero. [`Normal::Degenerate`] returns A and B (exactly, in the
//! surface's scalar); [`Normal::towards`] picks the limit from a side. For a pole at the
//! edge u = 0 (c_v ≡ 0 there) B is zero and A = c_u × c_uv: the normal from inside the patch.
//!
//! The function only asks for [`SurfaceDerivative`], so every surface type of the crate uses
//! it.
//!
//! # Complexity
//!
//! Two partial derivatives and a cross product at a regular point, five partials and four
//! cross products at a degenerate one: Θ(E) for E the cost of one partial derivative.

use super::traits::SurfaceDerivative;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};
use crate::Result;

/// The normal, declared.
pub(crate) const NORMAL: Declaration = Declaration {
    problem: "surface",
    name: "normal",
    function: "surface::normal",
    file: "src/surface/normal.rs",
    summary: "c_u × c_v, or the first-order terms of the normal where it vanishes",
    time: "Θ(E) for E the cost of one partial derivative",
    space: "O(1)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per partial derivative taken: exactly 2 at a regular point, 5 at a degenerate one",
    source: "[FJ-surfaces, §6]",
    claims: &[on(
        "random-samples",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// A normal of a surface at one parameter pair, as [`normal`] finds it.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Normal<S> {
    /// c_u × c_v, not zero (not normalised: its length is that of the product, exact with
    /// rationals).
    Regular(Point<S, 3>),
    /// c_u × c_v is zero: the partials are parallel or one of them vanishes. The normal at
    /// (u + h, v + k) is h·`along_u` + k·`along_v` up to terms of second order, so its
    /// direction from the side (h, k) tends to that of h·`along_u` + k·`along_v` when that
    /// is not zero ([`Normal::towards`]). Both zero: no first-order information either.
    Degenerate {
        /// ∂(c_u × c_v)/∂u = c_uu × c_v + c_u × c_uv.
        along_u: Point<S, 3>,
        /// ∂(c_u × c_v)/∂v = c_uv × c_v + c_u × c_vv.
        along_v: Point<S, 3>,
    },
}

impl<S: Scalar> Normal<S> {
    /// Whether c_u × c_v is not zero.
    pub fn is_regular(&self) -> bool {
        matches!(self, Normal::Regular(_))
    }

    /// The normal direction seen from the side (h, k) of the parameter pair: the regular
    /// normal itself, or h·`along_u` + k·`along_v` at a degenerate point; `None` if that is
    /// zero.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::Normal;
    ///
    /// let n = Normal::Degenerate { along_u: Point::new([0.0, 0.0, 2.0]), along_v: Point::zero() };
    /// assert_eq!(n.towards(&1.0, &0.0), Some(Point::new([0.0, 0.0, 2.0])));
    /// assert_eq!(n.towards(&-1.0, &0.0), Some(Point::new([0.0, 0.0, -2.0])));
    /// assert_eq!(n.towards(&0.0, &1.0), None);
    /// ```
    pub fn towards(&self, h: &S, k: &S) -> Option<Point<S, 3>> {
        let n = match self {
            Normal::Regular(n) => n.clone(),
            Normal::Degenerate { along_u, along_v } => {
                along_u.clone() * h.clone() + &(along_v.clone() * k.clone())
            }
        };
        (!n.coords().iter().all(Scalar::is_zero)).then_some(n)
    }
}

/// The normal of `surface` at (u, v). See [`normal_with`].
///
/// # Errors
///
/// As the surface's [`partial_at`](SurfaceDerivative::partial_at): a parameter NaN,
/// infinite or outside the domain.
///
/// # Complexity
///
/// Θ(E) for E the cost of one partial derivative, O(1) auxiliary space.
///
/// ```
/// use compgeo::spline::Point;
/// use compgeo::surface::{normal, BezierPatch, ControlNet, Normal};
///
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// // z = uv: c_u × c_v = (1, 0, v) × (0, 1, u) = (−v, −u, 1).
/// let s = BezierPatch::new(ControlNet::new(vec![
///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
///     vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
/// ])?)?;
/// assert_eq!(normal(&s, &0.5, &0.25)?, Normal::Regular(p(-0.25, -0.5, 1.0)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn normal<S: Scalar, F: SurfaceDerivative<S, 3>>(
    surface: &F,
    u: &S,
    v: &S,
) -> Result<Normal<S>> {
    normal_with(surface, u, v, &mut NoCount)
}

/// The normal of `surface` at (u, v), counting the partial derivatives taken.
///
/// Idea: c_u × c_v [FJ-surfaces, §6]; where it is exactly zero, the derivatives of the
/// normal field, ∂n/∂u = c_uu × c_v + c_u × c_uv and ∂n/∂v = c_uv × c_v + c_u × c_vv (the
/// product rule), which give the normals of the nearby points to first order (see the
/// module documentation). With `f64` "exactly zero" is a rounded test: a nearly degenerate
/// point comes out [`Normal::Regular`] with a tiny vector.
///
/// # Errors
///
/// As [`normal`].
///
/// # Complexity
///
/// Θ(E) for E the cost of one partial derivative, O(1) auxiliary space.
///
/// # Counts
///
/// One [`arithmetic_operation`](Counter::arithmetic_operation) per partial derivative taken
/// (the cross products are not counted): exactly 2 at a regular point, 5 at a degenerate
/// one.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::Point;
/// use compgeo::surface::{normal_with, BezierPatch, ControlNet, Normal};
///
/// // A triangle as a bilinear patch with the edge u = 0 collapsed to the origin.
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let s = BezierPatch::new(ControlNet::new(vec![
///     vec![p(0.0, 0.0, 0.0), p(0.0, 0.0, 0.0)],
///     vec![p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
/// ])?)?;
/// let mut c = Counts::default();
/// let n = normal_with(&s, &0.0, &0.5, &mut c)?;
/// assert!(!n.is_regular());
/// assert_eq!(n.towards(&1.0, &0.0), Some(p(0.0, 0.0, 1.0)));
/// assert_eq!(c.arithmetic_operations, 5);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn normal_with<S: Scalar, F: SurfaceDerivative<S, 3>, C: Counter>(
    surface: &F,
    u: &S,
    v: &S,
    counter: &mut C,
) -> Result<Normal<S>> {
    let cu = surface.partial_at(u, v, 1, 0)?;
    let cv = surface.partial_at(u, v, 0, 1)?;
    counter.arithmetic_operation();
    counter.arithmetic_operation();
    let n = cross(&cu, &cv);
    if !n.coords().iter().all(Scalar::is_zero) {
        return Ok(Normal::Regular(n));
    }
    let cuu = surface.partial_at(u, v, 2, 0)?;
    let cuv = surface.partial_at(u, v, 1, 1)?;
    let cvv = surface.partial_at(u, v, 0, 2)?;
    counter.arithmetic_operation();
    counter.arithmetic_operation();
    counter.arithmetic_operation();
    Ok(Normal::Degenerate {
        along_u: cross(&cuu, &cv) + &cross(&cu, &cuv),
        along_v: cross(&cuv, &cv) + &cross(&cu, &cvv),
    })
}

/// The cross product a × b.
pub(crate) fn cross<S: Scalar>(a: &Point<S, 3>, b: &Point<S, 3>) -> Point<S, 3> {
    let p = |i: usize, j: usize| a[i].clone() * &b[j] - a[j].clone() * &b[i];
    Point::new([p(1, 2), p(2, 0), p(0, 1)])
}
