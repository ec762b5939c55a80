//! The capabilities every surface type shares, as the curve traits of
//! [`spline`](crate::spline) are shared by every curve: a parametric surface has a domain in
//! each parameter and evaluates on it ([`Surface`]); where it is differentiable it has partial
//! derivatives of any orders at a parameter pair ([`SurfaceDerivative`]). Tests, tessellation
//! and pictures are written once over these traits.

use crate::spline::{Domain, Point, Scalar};
use crate::Result;

/// The parameters at which a surface is defined: a [`Domain`] in u and one in v (the whole
/// plane for a polynomial patch, a rectangle for a piecewise surface).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct SurfaceDomain<S> {
    /// The domain in u.
    pub u: Domain<S>,
    /// The domain in v.
    pub v: Domain<S>,
}

impl<S: Scalar> SurfaceDomain<S> {
    /// Checks that (u, v) is a parameter pair of the domain.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"u"` or `"v"` if
    /// the value is NaN, infinite or outside its interval.
    pub fn check(&self, u: &S, v: &S) -> Result<()> {
        self.u.check(u, "u")?;
        self.v.check(v, "v")
    }
}

/// A parametric surface in R^D over the scalar field `S`: its domain and its points.
///
/// The conventions are those of [`Curve`](crate::spline::Curve) in each parameter:
/// parameters are values of `S` compared exactly; evaluation returns `Result` and refuses NaN,
/// infinite and out-of-domain parameters with
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) naming `"u"` or `"v"`; with
/// `f64` a point beyond the double range comes out with infinite coordinates (exact scalars
/// never overflow). A tensor-product Bézier patch is a polynomial and evaluates on the whole
/// plane ([`Domain::Real`] in both parameters; its control net describes the piece over
/// [0, 1]²); a piecewise surface is defined on a rectangle.
///
/// ```
/// use compgeo::spline::{Domain, Point};
/// use compgeo::surface::{BezierPatch, ControlNet, Surface};
///
/// // The bilinear patch of the graph of f(u, v) = uv [FJ-surfaces, §2].
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let net = ControlNet::new(vec![
///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
///     vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
/// ])?;
/// let s = BezierPatch::new(net)?;
/// assert_eq!(s.domain().u, Domain::Real);
/// assert_eq!(s.eval(&0.5, &0.25)?, p(0.5, 0.25, 0.125));
/// assert!(s.eval(&f64::NAN, &0.0).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub trait Surface<S: Scalar, const D: usize> {
    /// The parameters at which the surface is defined.
    fn domain(&self) -> SurfaceDomain<S>;

    /// The point at (u, v).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"u"` or `"v"` if a
    /// parameter is NaN, infinite or outside the [`domain`](Surface::domain).
    fn eval(&self, u: &S, v: &S) -> Result<Point<S, D>>;
}

/// A surface with partial derivatives of any orders.
pub trait SurfaceDerivative<S: Scalar, const D: usize>: Surface<S, D> {
    /// The partial derivative ∂^{r+s}c/∂u^r∂v^s at (u, v) (orders 0, 0: the point itself;
    /// r = s = 1: the twist). At an interior knot of a piecewise surface it is taken from the
    /// right in that parameter (from the left at the domain's end), as for curves.
    ///
    /// # Errors
    ///
    /// As [`Surface::eval`]; [`Error::Overflow`](crate::Error::Overflow) if, with `f64`, the
    /// derivative is beyond the double range.
    fn partial_at(&self, u: &S, v: &S, r: usize, s: usize) -> Result<Point<S, D>>;

    /// The point and the first partials `[c, c_u, c_v]` at every pair of `us` × `vs`,
    /// row-major (entry i·|vs| + j at (uᵢ, vⱼ)): what [`tessellate`](super::tessellate)
    /// needs. The default calls [`Surface::eval`] and [`SurfaceDerivative::partial_at`] at
    /// every pair; the B-spline and NURBS surfaces compute each parameter's basis and its
    /// derivative once for the whole grid.
    ///
    /// # Errors
    ///
    /// As [`SurfaceDerivative::partial_at`].
    ///
    /// # Complexity
    ///
    /// Θ(N·E) for N pairs and E the cost of one evaluation (the default), Θ(N·D) space.
    fn first_partials_on_grid(&self, us: &[S], vs: &[S]) -> Result<Vec<[Point<S, D>; 3]>> {
        let mut out = Vec::with_capacity(us.len().saturating_mul(vs.len()));
        for u in us {
            for v in vs {
                out.push([
                    self.eval(u, v)?,
                    self.partial_at(u, v, 1, 0)?,
                    self.partial_at(u, v, 0, 1)?,
                ]);
            }
        }
        Ok(out)
    }
}
