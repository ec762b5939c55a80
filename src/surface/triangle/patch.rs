//! The triangular Bézier patch: its control points b_{ijk}, i + j + k = n, stored flat in
//! one documented order and validated once.
//!
//! A patch of degree n is b(u, v, w) = Σ b_{ijk} B^n_{ijk}(u, v, w) over the reference
//! triangle p q r, in barycentric coordinates [PPB, §10.2]; its control points are the
//! vertices of its Bézier net: b_{n00} = b(p), b_{0n0} = b(q), b_{00n} = b(r), and the points
//! with k = 0 are the control polygon of the edge from p to q.
//!
//! # Storage order
//!
//! The (n + 1)(n + 2)/2 points are stored row after row, the rows of constant k from k = 0
//! (the edge p q) to k = n (the vertex r), and within a row by increasing j:
//!
//! ```text
//! b_{n00}, b_{n−1,1,0}, …, b_{0n0},   b_{n−1,0,1}, …, b_{0,n−1,1},   …,   b_{00n}
//! ```
//!
//! the canonical listing of [PPB, §10.1, Fig. 10.2] read from its bottom row up. The point
//! b_{ijk} is at index k(2n + 3 − k)/2 + j ([`storage_index`]), the function L of
//! [PPB, §11.12, Exercise 5].
//!
//! # Complexity
//!
//! Θ(n²D) to build and validate; a point is found in O(1).

use super::barycentric::{Barycentric, BarycentricVector};
use super::de_casteljau::{combine3, level};
use crate::count::NoCount;
use crate::spline::{falling_factorial, Domain, Point, Scalar};
use crate::surface::{Surface, SurfaceDerivative, SurfaceDomain};
use crate::{limits, Error, Result};

/// A triangular Bézier patch of degree n in R^D: (n + 1)(n + 2)/2 finite control points
/// b_{ijk}, i + j + k = n, defined for every point of the plane of its reference triangle
/// p q r, b(u, v, w) = Σ b_{ijk} B^n_{ijk}(u, v, w) [PPB, §10.2].
///
/// The points are stored flat, row after row: the rows of constant k from k = 0 (the edge
/// p q) to k = n (the vertex r), each by increasing j,
/// b_{n00}, b_{n−1,1,0}, …, b_{0n0}, b_{n−1,0,1}, …, b_{0,n−1,1}, …, b_{00n}: the canonical
/// listing of [PPB, Fig. 10.2] read from its bottom row up. b_{ijk} is at index
/// k(2n + 3 − k)/2 + j ([`storage_index`]).
///
/// It is also a [`Surface`] in the parameters (u, v) with w = 1 − u − v: over the reference
/// triangle p = (1, 0), q = (0, 1), r = (0, 0) of the (u, v) plane, so that
/// [`SurfaceDerivative::partial_at`] gives ∂/∂u = D_{p−r} and ∂/∂v = D_{q−r}, and the
/// crate's [`normal`](crate::surface::normal) applies. (The generic
/// [`tessellate`](crate::surface::tessellate) samples the square [0, 1]² of that plane, half
/// of it beyond the edge p q; [`TriangularPatch::tessellate`] samples the triangle.)
///
/// ```
/// use compgeo::spline::Point;
/// use compgeo::surface::{Barycentric, Surface, TriangularPatch};
///
/// // The quadratic patch of the graph of z = u·v over the triangle (1, 0), (0, 1), (0, 0):
/// // uv = B_{110}/2, so its points are the abscissae (i/2, j/2) with the ordinate 1/2 at
/// // the middle of p q.
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let b = TriangularPatch::new(vec![
///     p(1.0, 0.0, 0.0), p(0.5, 0.5, 0.5), p(0.0, 1.0, 0.0),  // k = 0: the edge p q
///     p(0.5, 0.0, 0.0), p(0.0, 0.5, 0.0),                    // k = 1
///     p(0.0, 0.0, 0.0),                                      // k = 2: the vertex r
/// ])?;
/// assert_eq!(b.degree(), 2);
/// assert_eq!(b.get(1, 1, 0), Some(&p(0.5, 0.5, 0.5)));
/// let x = Barycentric::new(0.5, 0.25, 0.25)?;
/// assert_eq!(b.de_casteljau(&x), p(0.5, 0.25, 0.125));
/// assert_eq!(b.eval(&0.5, &0.25)?, p(0.5, 0.25, 0.125));
/// assert!(TriangularPatch::new(vec![p(0.0, 0.0, 0.0); 4]).is_err()); // 4 is no (n + 1)(n + 2)/2
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TriangularPatch<S, const D: usize> {
    degree: usize,
    points: Vec<Point<S, D>>,
}

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The patch of these control points in the storage order, its degree n found from their
    /// number (n + 1)(n + 2)/2.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no points; [`Error::InvalidParameter`] named `"control points"`
    /// if their number is not (n + 1)(n + 2)/2 for any n (1, 3, 6, 10, …);
    /// [`Error::LimitExceeded`] beyond [`MAX_POINTS`](crate::limits::MAX_POINTS) points;
    /// [`Error::NonFinite`] with the index of the first point with a NaN or infinite
    /// coordinate.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, no auxiliary space.
    pub fn new(points: Vec<Point<S, D>>) -> Result<Self> {
        if points.is_empty() {
            return Err(Error::Empty {
                what: "triangular control net",
            });
        }
        let count = points.len();
        limits::POINTS.check(count as u128)?;
        let degree = degree_of(count).ok_or_else(|| Error::InvalidParameter {
            name: "control points",
            reason: format!(
                "a triangular patch of degree n has (n + 1)(n + 2)/2 control points (1, 3, 6, \
                 10, …), got {count}"
            ),
        })?;
        Self::with_degree(degree, points)
    }

    /// The patch of degree n with these control points in the storage order.
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] if n exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE) or
    /// (n + 1)(n + 2)/2 exceeds [`MAX_POINTS`](crate::limits::MAX_POINTS), checked first;
    /// [`Error::InvalidParameter`] named `"control points"` unless there are
    /// (n + 1)(n + 2)/2 points; [`Error::NonFinite`] as for [`TriangularPatch::new`].
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, no auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::TriangularPatch;
    ///
    /// let b = TriangularPatch::with_degree(1, vec![Point::new([1.0]), Point::new([2.0]), Point::new([3.0])])?;
    /// assert_eq!(b.degree(), 1);
    /// assert!(TriangularPatch::with_degree(2, vec![Point::new([1.0]); 3]).is_err());
    /// assert!(TriangularPatch::with_degree(1 << 40, vec![Point::new([1.0]); 3]).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn with_degree(degree: usize, points: Vec<Point<S, D>>) -> Result<Self> {
        let count = check_degree(degree)?;
        if points.len() != count {
            return Err(Error::InvalidParameter {
                name: "control points",
                reason: format!(
                    "a triangular patch of degree {degree} has {count} control points, got {}",
                    points.len()
                ),
            });
        }
        for (index, p) in points.iter().enumerate() {
            if let Some(c) = p.coords().iter().find(|c| !c.is_finite()) {
                return Err(Error::NonFinite {
                    index,
                    value: c.to_f64(),
                });
            }
        }
        Ok(TriangularPatch { degree, points })
    }

    /// The patch of degree n whose points an algorithm computed from valid patches:
    /// [`Error::Overflow`] naming `what` if, with `f64`, a point came out non-finite.
    pub(super) fn derived(
        degree: usize,
        points: Vec<Point<S, D>>,
        what: &'static str,
    ) -> Result<Self> {
        debug_assert_eq!(points.len(), point_count(degree));
        if points.iter().all(Point::is_finite) {
            Ok(TriangularPatch { degree, points })
        } else {
            Err(Error::Overflow { what })
        }
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The control points in the storage order.
    pub fn points(&self) -> &[Point<S, D>] {
        &self.points
    }

    /// b_{ijk}, or `None` unless i + j + k = n.
    pub fn get(&self, i: usize, j: usize, k: usize) -> Option<&Point<S, D>> {
        storage_index(self.degree, [i, j, k]).map(|at| &self.points[at])
    }

    /// The same patch in `f64` (each coordinate rounded to nearest).
    pub fn to_f64(&self) -> TriangularPatch<f64, D> {
        TriangularPatch {
            degree: self.degree,
            points: self.points.iter().map(Point::to_f64).collect(),
        }
    }

    /// The same patch over the reference triangle with its vertices taken in the order
    /// `order`: vertex t of the new triangle is vertex `order[t]` of this one, so the new
    /// point with multi-index e is b_i with i_{order[t]} = e_t.
    pub(super) fn permuted(&self, order: [usize; 3]) -> Self {
        let n = self.degree;
        let points = multi_indices(n)
            .map(|e| {
                let mut i = [0; 3];
                for t in 0..3 {
                    i[order[t]] = e[t];
                }
                self.points[storage_index(n, i).expect("a permutation keeps i + j + k = n")].clone()
            })
            .collect();
        TriangularPatch { degree: n, points }
    }

    /// D_{d₁} ⋯ D_{d_r} b(x) by the blossom [PPB, §11.6]: r levels of differences with the
    /// directions, then n − r levels of de Casteljau at x, scaled by n!/(n − r)!; zero for
    /// r > n. The shared body of the derivatives and of [`Surface`]'s partials.
    pub(super) fn derivative_counted<C: crate::count::Counter>(
        &self,
        at: &Barycentric<S>,
        directions: &[BarycentricVector<S>],
        counter: &mut C,
    ) -> Point<S, D> {
        let n = self.degree;
        let r = directions.len();
        if r > n {
            return Point::zero();
        }
        let mut q = self.points.clone();
        for (l, d) in directions.iter().enumerate() {
            level(&mut q, n - l, d.coords(), counter);
        }
        for m in (1..=n - r).rev() {
            level(&mut q, m, at.coords(), counter);
        }
        let point = q.swap_remove(0);
        if r == 0 {
            point
        } else {
            counter.arithmetic_operation();
            point * falling_factorial::<S>(n, r)
        }
    }
}

/// The polynomial on the whole (u, v) plane, w = 1 − u − v: [`TriangularPatch::de_casteljau`],
/// Θ(n³D).
impl<S: Scalar, const D: usize> Surface<S, D> for TriangularPatch<S, D> {
    fn domain(&self) -> SurfaceDomain<S> {
        SurfaceDomain {
            u: Domain::Real,
            v: Domain::Real,
        }
    }

    fn eval(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        let at = uv_point(u, v)?;
        Ok(self.de_casteljau(&at))
    }
}

/// ∂^{r+s}b/∂u^r∂v^s = D_{p−r}^r D_{q−r}^s b: the blossom with r directions (1, 0, −1) and s
/// directions (0, 1, −1) [PPB, §11.6], Θ(n³D).
impl<S: Scalar, const D: usize> SurfaceDerivative<S, D> for TriangularPatch<S, D> {
    fn partial_at(&self, u: &S, v: &S, r: usize, s: usize) -> Result<Point<S, D>> {
        let at = uv_point(u, v)?;
        let (one, zero) = (S::one(), S::zero());
        let du = BarycentricVector::trusted([one.clone(), zero.clone(), -one.clone()]);
        let dv = BarycentricVector::trusted([zero, one.clone(), -one]);
        let mut directions = vec![du; r.min(self.degree + 1)];
        directions.extend(std::iter::repeat_n(dv, s.min(self.degree + 1)));
        let p = self.derivative_counted(&at, &directions, &mut NoCount);
        if p.is_finite() {
            Ok(p)
        } else {
            Err(Error::Overflow {
                what: "triangular patch derivative",
            })
        }
    }

    /// The point and both first partials from one de Casteljau scheme per pair: n − 1 levels
    /// leave b_{100}, b_{010}, b_{001}, whose combination at (u, v, w) is the point and whose
    /// differences times n are the partials [PPB, §10.5].
    fn first_partials_on_grid(&self, us: &[S], vs: &[S]) -> Result<Vec<[Point<S, D>; 3]>> {
        let mut out = Vec::with_capacity(us.len().saturating_mul(vs.len()));
        for u in us {
            for v in vs {
                out.push(self.point_and_partials(&uv_point(u, v)?, &mut NoCount));
            }
        }
        Ok(out)
    }
}

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// [b(x), ∂b/∂u, ∂b/∂v] at x, counting n(n + 1)(n + 2)/6 + 2 operations for n ≥ 1 (none
    /// for n = 0, whose partials are zero).
    pub(super) fn point_and_partials<C: crate::count::Counter>(
        &self,
        at: &Barycentric<S>,
        counter: &mut C,
    ) -> [Point<S, D>; 3] {
        let n = self.degree;
        if n == 0 {
            return [self.points[0].clone(), Point::zero(), Point::zero()];
        }
        let mut q = self.points.clone();
        for m in (2..=n).rev() {
            level(&mut q, m, at.coords(), counter);
        }
        // The degree-1 net b_{100}, b_{010}, b_{001} at indices 0, 1, 2.
        let point = combine3(&q[0], &q[1], &q[2], at.coords());
        let scale = S::from_i64(n as i64);
        let du = (q[0].clone() - &q[2]) * &scale;
        let dv = (q[1].clone() - &q[2]) * &scale;
        counter.arithmetic_operation();
        counter.arithmetic_operation();
        counter.arithmetic_operation();
        [point, du, dv]
    }
}

/// (u, v, 1 − u − v), its parameters named `"u"` and `"v"` as the surface traits do.
fn uv_point<S: Scalar>(u: &S, v: &S) -> Result<Barycentric<S>> {
    crate::spline::validate_parameter(u, "u")?;
    crate::spline::validate_parameter(v, "v")?;
    Barycentric::from_uv(u.clone(), v.clone())
}

/// (n + 1)(n + 2)/2, the number of control points of degree n.
pub(super) fn point_count(n: usize) -> usize {
    (n + 1) * (n + 2) / 2
}

/// The point count of degree n after checking n against
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE) and the count against
/// [`MAX_POINTS`](crate::limits::MAX_POINTS), before anything is allocated.
pub(super) fn check_degree(n: usize) -> Result<usize> {
    limits::DEGREE.check(n as u128)?;
    limits::POINTS.check((n as u128 + 1) * (n as u128 + 2) / 2)
}

/// The degree n with (n + 1)(n + 2)/2 = `count`, if there is one.
fn degree_of(count: usize) -> Option<usize> {
    // n ≈ √(2·count) − 1.5; the count is at most MAX_POINTS, so the root is exact enough to
    // land within one of n.
    let guess = ((2.0 * count as f64).sqrt() - 1.5).round().max(0.0) as usize;
    (guess.saturating_sub(1)..=guess + 1).find(|&n| point_count(n) == count)
}

/// The offset of row k (the points with that k) in the storage order of degree n:
/// k(2n + 3 − k)/2.
#[inline]
pub(super) fn row_offset(n: usize, k: usize) -> usize {
    k * (2 * n + 3 - k) / 2
}

/// The index of b_{ijk} in the storage order of degree n, or `None` unless i + j + k = n.
///
/// # Complexity
///
/// O(1).
///
/// ```
/// use compgeo::surface::triangle::storage_index;
///
/// // Degree 2: b200, b110, b020, b101, b011, b002.
/// assert_eq!(storage_index(2, [0, 2, 0]), Some(2));
/// assert_eq!(storage_index(2, [1, 0, 1]), Some(3));
/// assert_eq!(storage_index(2, [0, 0, 2]), Some(5));
/// assert_eq!(storage_index(2, [1, 1, 1]), None);
/// ```
pub fn storage_index(n: usize, [i, j, k]: [usize; 3]) -> Option<usize> {
    (i.checked_add(j)?.checked_add(k)? == n).then(|| row_offset(n, k) + j)
}

/// The multi-indices [i, j, k] of degree n in the storage order.
///
/// # Complexity
///
/// Θ(n²) for the whole iteration, O(1) space.
///
/// ```
/// use compgeo::surface::triangle::multi_indices;
///
/// let all: Vec<[usize; 3]> = multi_indices(1).collect();
/// assert_eq!(all, [[1, 0, 0], [0, 1, 0], [0, 0, 1]]);
/// ```
pub fn multi_indices(n: usize) -> impl Iterator<Item = [usize; 3]> {
    (0..=n).flat_map(move |k| (0..=n - k).map(move |j| [n - k - j, j, k]))
}
