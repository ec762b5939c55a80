//! The bivariate Bernstein basis on a triangle, and a patch evaluated as its Bernstein sum.
//!
//! The problem: the values B^n_{ijk}(u, v, w) = n!/(i! j! k!) uⁱ vʲ wᵏ, i + j + k = n, the
//! terms of the trinomial expansion of 1 = (u + v + w)ⁿ [PPB, §10.1], and the point
//! b(x) = Σ b_{ijk} B^n_{ijk}(u, v, w) [PPB, §10.2]. The idea: the powers of u, v and w once
//! (3(n + 1) values), the multinomial coefficients C(n, k)·C(n − k, j) row by row, one
//! product per basis value; then one multiply-add of a point per term. Exact with rationals,
//! so the values sum to exactly 1 at every (u, v, w) with u + v + w = 1.
//!
//! # Complexity
//!
//! Θ(n²) scalar operations for the basis, Θ(n²D) more for the sum; Θ(n²) space.
//!
//! Invariants the tests check (exactly on rationals): the basis sums to 1; the sum equals de
//! Casteljau's point; B^n_{ijk} at the vertices is 1 or 0 [PPB, §10.1].

use super::barycentric::Barycentric;
use super::patch::{check_degree, TriangularPatch};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};
use crate::Result;

/// Evaluation by the Bernstein sum, declared.
pub(crate) const BERNSTEIN_SUM: Declaration = Declaration {
    problem: "triangular-patch",
    name: "bernstein-sum",
    function: "surface::TriangularPatch::bernstein_sum",
    file: "src/surface/triangle/basis.rs",
    summary: "the (n + 1)(n + 2)/2 basis values from three power tables, one multiply-add per term",
    time: "Θ(n²D)",
    space: "Θ(n²)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)(n + 2)/2 multiply-adds of points",
    source: "[PPB, §10.1–10.2]",
    claims: &[on(
        "random-degree",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

/// The Bernstein polynomials of degree n at x = (u, v, w), in the storage order of
/// [`TriangularPatch`] (rows of constant k, j increasing): entry k(2n + 3 − k)/2 + j is
/// B^n_{ijk}(u, v, w) = n!/(i! j! k!) uⁱ vʲ wᵏ [PPB, §10.1].
///
/// # Errors
///
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if n exceeds
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE) or (n + 1)(n + 2)/2 exceeds
/// [`MAX_POINTS`](crate::limits::MAX_POINTS), before anything is allocated.
///
/// # Complexity
///
/// Θ(n²) time and space.
///
/// ```
/// use compgeo::surface::Barycentric;
/// use compgeo::surface::triangle::bernstein_basis;
///
/// // Degree 2 at (1/2, 1/4, 1/4): u², 2uv, v², 2uw, 2vw, w².
/// let b = bernstein_basis(2, &Barycentric::new(0.5, 0.25, 0.25)?)?;
/// assert_eq!(b, [0.25, 0.25, 0.0625, 0.25, 0.125, 0.0625]);
/// assert_eq!(b.iter().sum::<f64>(), 1.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bernstein_basis<S: Scalar>(n: usize, at: &Barycentric<S>) -> Result<Vec<S>> {
    let count = check_degree(n)?;
    let [u, v, w] = at.coords();
    let powers = |x: &S| {
        let mut p = Vec::with_capacity(n + 1);
        p.push(S::one());
        for e in 1..=n {
            p.push(p[e - 1].clone() * x);
        }
        p
    };
    let (pu, pv, pw) = (powers(u), powers(v), powers(w));
    let mut out = Vec::with_capacity(count);
    // C(n, k) by C(n, k + 1) = C(n, k)(n − k)/(k + 1), and C(n − k, j) the same way along
    // the row: integers at every step, so exact for rationals.
    let mut outer = S::one();
    for k in 0..=n {
        let mut inner = outer.clone();
        for j in 0..=n - k {
            out.push(inner.clone() * &pu[n - k - j] * &pv[j] * &pw[k]);
            inner = inner * S::from_i64((n - k - j) as i64) / S::from_i64(j as i64 + 1);
        }
        outer = outer * S::from_i64((n - k) as i64) / S::from_i64(k as i64 + 1);
    }
    Ok(out)
}

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The point b(x) as the Bernstein sum Σ b_{ijk} B^n_{ijk}(x). See
    /// [`TriangularPatch::bernstein_sum_with`].
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, Θ(n²) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new(vec![Point::new([3.0]), Point::new([5.0]), Point::new([7.0])])?;
    /// let x = Barycentric::new(0.5, 0.25, 0.25)?;
    /// assert_eq!(b.bernstein_sum(&x), b.de_casteljau(&x));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bernstein_sum(&self, at: &Barycentric<S>) -> Point<S, D> {
        self.bernstein_sum_with(at, &mut NoCount)
    }

    /// The Bernstein sum, counting one multiply-add of a point per term.
    ///
    /// Idea: the basis values of [`bernstein_basis`] (powers once, multinomial coefficients
    /// by their ratios), then Σ b_{ijk} B^n_{ijk} [PPB, §10.2]. Unlike de Casteljau's
    /// scheme the terms are not convex combinations of points, so with `f64` it may round
    /// more far from the triangle.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, Θ(n²) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per term: exactly
    /// (n + 1)(n + 2)/2 (the basis values are scalar bookkeeping).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new(vec![Point::new([1.0]); 10])?; // degree 3
    /// let mut c = Counts::default();
    /// assert_eq!(b.bernstein_sum_with(&Barycentric::new(0.5, 0.25, 0.25)?, &mut c), Point::new([1.0]));
    /// assert_eq!(c.arithmetic_operations, 10);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bernstein_sum_with<C: Counter>(
        &self,
        at: &Barycentric<S>,
        counter: &mut C,
    ) -> Point<S, D> {
        let basis = bernstein_basis(self.degree(), at)
            .expect("a valid patch's degree is within the limits");
        let mut sum = Point::zero();
        for (b, weight) in self.points().iter().zip(&basis) {
            sum += &(b.clone() * weight);
            counter.arithmetic_operation();
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::power as pow;

    #[test]
    fn the_basis_is_the_trinomial_expansion() {
        let at = Barycentric::new(0.5, 0.125, 0.375).unwrap();
        let [u, v, w] = at.coords();
        let b = bernstein_basis(3, &at).unwrap();
        // Fig. 10.2: w³; 3uw², 3vw²; 3u²w, 6uvw, 3v²w; u³, 3u²v, 3uv², v³, bottom row first.
        let want = [
            pow(u, 3),
            3.0 * u * u * v,
            3.0 * u * v * v,
            pow(v, 3),
            3.0 * u * u * w,
            6.0 * u * v * w,
            3.0 * v * v * w,
            3.0 * u * w * w,
            3.0 * v * w * w,
            pow(w, 3),
        ];
        assert_eq!(b, want);
    }
}
