//! Degree elevation of a triangular patch.
//!
//! The problem: the control points of the same polynomial as a patch of degree m > n. The
//! idea: the blossom c[x₀, …, x_n] = 1/(n + 1) Σ_l b[x₀, …, x̂_l, …, x_n] (x_l left out) is
//! symmetric, multi-affine and equal to b on its diagonal, so it is the blossom of b as a
//! polynomial of degree n + 1, and its values at the vertices give the elevated points
//! [PPB, §11.8]:
//!
//! b′_j = (j₀ b_{j−e₀} + j₁ b_{j−e₁} + j₂ b_{j−e₂}) / (n + 1),  |j| = n + 1,
//!
//! one affine combination per new point (a term with j_t = 0 is absent). Elevation to m
//! repeats it m − n times; the nets converge to the surface as m grows [PPB, §11.9].
//!
//! # Complexity
//!
//! Θ((m³ − n³)D) time, Θ(m²D) space.
//!
//! Invariants the tests check (exactly on rationals): the elevated patch is the same
//! polynomial (equal values everywhere in the plane); elevation by steps agrees with Zhou's
//! formula [PPB, §11.9]; the counts.

use super::patch::{check_degree, point_count, row_offset, TriangularPatch};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};
use crate::{Error, Result};

/// Degree elevation, declared.
pub(crate) const ELEVATE_TO: Declaration = Declaration {
    problem: "triangular-patch",
    name: "elevate-to",
    function: "surface::TriangularPatch::elevate_to",
    file: "src/surface/triangle/elevate.rs",
    summary: "elevation by one, b′_j = Σ_t j_t b_{j−e_t}/(n + 1), repeated up to the target degree",
    time: "Θ((m³ − n³)D)",
    space: "Θ(m²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (m + 1)(m + 2)(m + 3)/6 − (n + 1)(n + 2)(n + 3)/6 affine combinations, one per new point",
    source: "[PPB, §11.8]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The same polynomial as a patch of degree n + 1 [PPB, §11.8]: b′_j =
    /// (j₀ b_{j−e₀} + j₁ b_{j−e₁} + j₂ b_{j−e₂})/(n + 1). See
    /// [`TriangularPatch::elevate_to_with`].
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::elevate_to`] with m = n + 1.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time and space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::TriangularPatch;
    ///
    /// let b = TriangularPatch::new(vec![Point::new([0.0]), Point::new([3.0]), Point::new([6.0])])?;
    /// let e = b.elevate()?;
    /// // Degree 2: b200, b110, b020, b101, b011, b002.
    /// assert_eq!(e.points(), [0.0, 1.5, 3.0, 3.0, 4.5, 6.0].map(|x| Point::new([x])));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate(&self) -> Result<Self> {
        self.elevate_to_with(self.degree().saturating_add(1), &mut NoCount)
    }

    /// The same polynomial as a patch of degree m ≥ n. See
    /// [`TriangularPatch::elevate_to_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"degree"` if m < n (that would be degree
    /// reduction, an approximation); [`Error::LimitExceeded`] if m exceeds
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE) or (m + 1)(m + 2)/2 exceeds
    /// [`MAX_POINTS`](crate::limits::MAX_POINTS), before anything is allocated;
    /// [`Error::Overflow`] if, with `f64`, a point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((m³ − n³)D) time, Θ(m²D) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new((0..6).map(|k| Point::new([k as f64])).collect())?;
    /// let e = b.elevate_to(5)?;
    /// assert_eq!(e.degree(), 5);
    /// let x = Barycentric::new(0.5, 0.25, 0.25)?;
    /// assert_eq!(e.de_casteljau(&x), b.de_casteljau(&x));
    /// assert!(b.elevate_to(1).is_err());
    /// assert!(b.elevate_to(1 << 20).is_err()); // beyond MAX_DEGREE
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_to(&self, m: usize) -> Result<Self> {
        self.elevate_to_with(m, &mut NoCount)
    }

    /// Degree elevation to m, counting its affine combinations.
    ///
    /// Idea: the blossom of degree n + 1 averaging b with one argument left out
    /// [PPB, §11.8], evaluated at the vertices: each new point combines the at most three
    /// old points one index below it, with weights j_t/(n + 1) summing to one; repeated up to
    /// degree m.
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::elevate_to`].
    ///
    /// # Complexity
    ///
    /// Θ((m³ − n³)D) time, Θ(m²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per new point: degree d + 1
    /// has (d + 2)(d + 3)/2 of them, exactly (m + 1)(m + 2)(m + 3)/6 − (n + 1)(n + 2)(n + 3)/6
    /// in all.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::TriangularPatch;
    ///
    /// let b = TriangularPatch::new(vec![Point::new([2.0]); 3])?; // degree 1
    /// let mut c = Counts::default();
    /// let e = b.elevate_to_with(3, &mut c)?;
    /// assert_eq!(e.points(), vec![Point::new([2.0]); 10]);
    /// assert_eq!(c.arithmetic_operations, 6 + 10);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_to_with<C: Counter>(&self, m: usize, counter: &mut C) -> Result<Self> {
        let n = self.degree();
        if m < n {
            return Err(Error::InvalidParameter {
                name: "degree",
                reason: format!("cannot elevate a triangular patch of degree {n} to degree {m}"),
            });
        }
        check_degree(m)?;
        let mut points = self.points().to_vec();
        for d in n..m {
            points = elevate_once(&points, d, counter);
        }
        Self::derived(m, points, "triangular degree elevation")
    }
}

/// The net of degree d + 1 of the net `b` of degree d: one combination per new point.
fn elevate_once<S: Scalar, const D: usize, C: Counter>(
    b: &[Point<S, D>],
    d: usize,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let e = d + 1;
    let mut out = Vec::with_capacity(point_count(e));
    // Degrees are at most MAX_DEGREE = 2^16, so the ratios fit in an i64.
    let weight = |c: usize| S::from_ratio(c as i64, e as i64);
    for k in 0..=e {
        for j in 0..=e - k {
            let i = e - k - j;
            let mut p = Point::zero();
            if i > 0 {
                p += &(b[row_offset(d, k) + j].clone() * weight(i));
            }
            if j > 0 {
                p += &(b[row_offset(d, k) + j - 1].clone() * weight(j));
            }
            if k > 0 {
                p += &(b[row_offset(d, k - 1) + j].clone() * weight(k));
            }
            out.push(p);
            counter.arithmetic_operation();
        }
    }
    out
}
