//! The number types and points the spline kernels compute with.
//!
//! Every curve kernel is written once, generic over a [`Scalar`] (the field its arithmetic runs
//! in) and over the dimension `D` of its control points ([`Point<S, D>`], a point of R^D).
//! Two scalars are provided:
//!
//! - `f64`, the fast path: hardware arithmetic, rounded;
//! - `num_rational::BigRational` (feature `exact`), arbitrary-precision rationals: every
//!   operation is exact, so identities such as "the two halves of a split curve evaluate to the
//!   original" hold with `==`, and the course texts' worked examples can be reproduced digit for digit.
//!
//! ## Why `[S; D]`
//!
//! A point is a fixed-size array `[S; D]` with the dimension a const generic, not a `Vec<S>`:
//! for `f64` the coordinates live on the stack (or in registers), the loops over coordinates
//! have a compile-time trip count and unroll, and de Casteljau's scratch space is one array of
//! points with no allocation per point: the generic cubic compiles to the same packed
//! instructions as a hand-written `f64` one. What a curve with a run-time degree adds per
//! evaluation is kept to a branch on the degree and one comparison of t with a bound fixed
//! when the curve is built (see [`Bezier::eval`](super::Bezier::eval)); the `spline`
//! benchmark compares [`Bezier::eval`](super::Bezier::eval), [`Bezier::at`](super::Bezier::at)
//! and [`Bezier::eval_each`](super::Bezier::eval_each) with a hand-written cubic and kurbo.
//! Callers whose dimension is only known at run time (the command line) dispatch on it once.
//!
//! ```
//! use compgeo::spline::{Point, Scalar};
//!
//! let a = Point::new([0.0, 2.0]);
//! let b = Point::new([4.0, 6.0]);
//! assert_eq!(Point::lerp(&a, &b, &0.25), Point::new([1.0, 3.0]));
//! assert_eq!(f64::from_ratio(3, 4), 0.75);
//! ```

use crate::{Error, Result};
use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, Index, IndexMut, Mul, Neg, Sub, SubAssign};

/// A field the spline kernels compute in: `f64` (rounded, fast) or, with the feature `exact`,
/// `BigRational` (exact).
///
/// Arithmetic takes the left operand by value and the right one by reference or value, so a
/// kernel written as `a.clone() * &b` clones nothing for `f64` (which is `Copy`) and one
/// rational for `BigRational`. Comparisons (`PartialOrd`) are total on the values the kernels
/// accept: `f64` input is validated finite at every public boundary.
pub trait Scalar:
    Clone
    + Debug
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
    + AddAssign
    + SubAssign
    + for<'a> AddAssign<&'a Self>
    + for<'a> SubAssign<&'a Self>
{
    /// `true` if every field operation is exact (rationals), `false` if it rounds (`f64`).
    const EXACT: bool;

    /// The additive identity.
    fn zero() -> Self;

    /// The multiplicative identity.
    fn one() -> Self;

    /// The integer `n` (rounded to the nearest `f64` when `|n| > 2^53`).
    fn from_i64(n: i64) -> Self;

    /// The ratio `num / den` (for `f64`, the quotient of the two rounded integers).
    ///
    /// # Panics
    ///
    /// If `den == 0`. Kernels only call it with nonzero constants (binomial coefficients,
    /// degrees); user-supplied ratios go through [`parse_scalar`](super::parse_scalar()).
    fn from_ratio(num: i64, den: i64) -> Self;

    /// The value of a finite `f64`, exactly (every finite double is a rational number);
    /// `None` for NaN and infinities.
    fn from_f64(x: f64) -> Option<Self>;

    /// The nearest `f64` (for rationals far outside the double range, ±∞ or 0).
    fn to_f64(&self) -> f64;

    /// `false` only for NaN and infinities, which no rational can be.
    fn is_finite(&self) -> bool;

    /// `true` if the value is zero.
    fn is_zero(&self) -> bool {
        *self == Self::zero()
    }

    /// `|self| ≤ limit`, for a `limit` that is not NaN; `false` if `self` is NaN.
    ///
    /// The evaluation fast paths call it once per parameter against a bound fixed when the
    /// curve was built (for `f64` it is one comparison); the default compares exactly in
    /// `Self`.
    fn abs_at_most(&self, limit: f64) -> bool {
        self.is_finite()
            && Self::from_f64(limit).map_or(limit == f64::INFINITY, |l| self.abs() <= l)
    }

    /// The absolute value.
    fn abs(&self) -> Self {
        if *self < Self::zero() {
            -self.clone()
        } else {
            self.clone()
        }
    }
}

/// A point (or vector) of R^D with coordinates in the scalar field `S`.
///
/// Control points, values and derivatives of curves are all `Point`s. The arithmetic a curve
/// needs is here: `+`, `-`, negation, scaling by a scalar (`p * s`, `p / s`), affine
/// combinations ([`Point::lerp`], [`Point::combine`]) and the dot product.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Point<S, const D: usize>(pub [S; D]);

impl<S: Scalar, const D: usize> Point<S, D> {
    /// The point with the given coordinates.
    #[inline]
    pub fn new(coords: [S; D]) -> Self {
        Point(coords)
    }

    /// The origin (the zero vector).
    #[inline]
    pub fn zero() -> Self {
        Point(std::array::from_fn(|_| S::zero()))
    }

    /// The coordinates.
    #[inline]
    pub fn coords(&self) -> &[S; D] {
        &self.0
    }

    /// `(1 − t)·a + t·b`: the point that divides `ab` in the ratio `t : 1 − t` (any `t`,
    /// also outside [0, 1]). With `t = 0` it is `a` and with `t = 1` it is `b`, exactly.
    #[inline]
    pub fn lerp(a: &Self, b: &Self, t: &S) -> Self {
        let s = S::one() - t;
        Self::combine(a, &s, b, t)
    }

    /// The linear combination `s·a + t·b`.
    #[inline]
    pub fn combine(a: &Self, s: &S, b: &Self, t: &S) -> Self {
        Point(std::array::from_fn(|i| {
            s.clone() * &a.0[i] + t.clone() * &b.0[i]
        }))
    }

    /// The dot product `Σ aᵢ·bᵢ`.
    pub fn dot(&self, other: &Self) -> S {
        let mut acc = S::zero();
        for i in 0..D {
            acc += self.0[i].clone() * &other.0[i];
        }
        acc
    }

    /// The squared Euclidean norm `Σ aᵢ²` (exact for rationals; no square root is taken).
    pub fn norm_squared(&self) -> S {
        self.dot(self)
    }

    /// The point with each coordinate converted to the nearest `f64`.
    pub fn to_f64(&self) -> Point<f64, D> {
        Point(std::array::from_fn(|i| self.0[i].to_f64()))
    }

    /// The point with the exact values of finite `f64` coordinates; `None` if one is NaN or
    /// infinite.
    pub fn from_f64(p: &Point<f64, D>) -> Option<Self> {
        let mut out = Self::zero();
        for i in 0..D {
            out.0[i] = S::from_f64(p.0[i])?;
        }
        Some(out)
    }

    /// `true` if every coordinate is finite.
    pub fn is_finite(&self) -> bool {
        self.0.iter().all(Scalar::is_finite)
    }
}

impl<const D: usize> Copy for Point<f64, D> {}

impl<S, const D: usize> Index<usize> for Point<S, D> {
    type Output = S;
    #[inline]
    fn index(&self, i: usize) -> &S {
        &self.0[i]
    }
}

impl<S, const D: usize> IndexMut<usize> for Point<S, D> {
    #[inline]
    fn index_mut(&mut self, i: usize) -> &mut S {
        &mut self.0[i]
    }
}

impl<S: Scalar, const D: usize> Add for Point<S, D> {
    type Output = Self;
    #[inline]
    fn add(self, rhs: Self) -> Self {
        self + &rhs
    }
}

impl<S: Scalar, const D: usize> Add<&Point<S, D>> for Point<S, D> {
    type Output = Self;
    #[inline]
    fn add(mut self, rhs: &Self) -> Self {
        self += rhs;
        self
    }
}

impl<S: Scalar, const D: usize> AddAssign<&Point<S, D>> for Point<S, D> {
    #[inline]
    fn add_assign(&mut self, rhs: &Self) {
        for (a, b) in self.0.iter_mut().zip(&rhs.0) {
            *a += b;
        }
    }
}

impl<S: Scalar, const D: usize> Sub for Point<S, D> {
    type Output = Self;
    #[inline]
    fn sub(self, rhs: Self) -> Self {
        self - &rhs
    }
}

impl<S: Scalar, const D: usize> Sub<&Point<S, D>> for Point<S, D> {
    type Output = Self;
    #[inline]
    fn sub(mut self, rhs: &Self) -> Self {
        self -= rhs;
        self
    }
}

impl<S: Scalar, const D: usize> SubAssign<&Point<S, D>> for Point<S, D> {
    #[inline]
    fn sub_assign(&mut self, rhs: &Self) {
        for (a, b) in self.0.iter_mut().zip(&rhs.0) {
            *a -= b;
        }
    }
}

impl<S: Scalar, const D: usize> Neg for Point<S, D> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Point(self.0.map(|a| -a))
    }
}

impl<S: Scalar, const D: usize> Mul<&S> for Point<S, D> {
    type Output = Self;
    #[inline]
    fn mul(self, s: &S) -> Self {
        Point(self.0.map(|a| a * s))
    }
}

impl<S: Scalar, const D: usize> Mul<S> for Point<S, D> {
    type Output = Self;
    #[inline]
    fn mul(self, s: S) -> Self {
        self * &s
    }
}

impl<S: Scalar, const D: usize> Div<&S> for Point<S, D> {
    type Output = Self;
    #[inline]
    fn div(self, s: &S) -> Self {
        Point(self.0.map(|a| a / s))
    }
}

impl<S: Scalar, const D: usize> Div<S> for Point<S, D> {
    type Output = Self;
    #[inline]
    fn div(self, s: S) -> Self {
        self / &s
    }
}

impl From<crate::geometry::Point2> for Point<f64, 2> {
    fn from(p: crate::geometry::Point2) -> Self {
        Point([p.x, p.y])
    }
}

impl From<Point<f64, 2>> for crate::geometry::Point2 {
    fn from(p: Point<f64, 2>) -> Self {
        crate::geometry::Point2::new(p.0[0], p.0[1])
    }
}

impl Scalar for f64 {
    const EXACT: bool = false;
    #[inline(always)]
    fn zero() -> Self {
        0.0
    }
    #[inline(always)]
    fn one() -> Self {
        1.0
    }
    #[inline]
    fn from_i64(n: i64) -> Self {
        n as f64
    }
    #[inline]
    fn from_ratio(num: i64, den: i64) -> Self {
        assert!(den != 0, "from_ratio: zero denominator");
        num as f64 / den as f64
    }
    #[inline]
    fn from_f64(x: f64) -> Option<Self> {
        x.is_finite().then_some(x)
    }
    #[inline(always)]
    fn to_f64(&self) -> f64 {
        *self
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
    #[inline]
    fn abs(&self) -> Self {
        f64::abs(*self)
    }
    #[inline(always)]
    fn abs_at_most(&self, limit: f64) -> bool {
        // NaN compares false; in floating point this is two instructions off the critical
        // path, where a test on the bit pattern would move t to an integer register first.
        f64::abs(*self) <= limit
    }
}

#[cfg(feature = "exact")]
mod rational {
    use super::Scalar;
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use num_traits::{Signed, ToPrimitive, Zero};

    impl Scalar for BigRational {
        const EXACT: bool = true;
        fn zero() -> Self {
            <BigRational as Zero>::zero()
        }
        fn one() -> Self {
            BigRational::from_integer(BigInt::from(1))
        }
        fn from_i64(n: i64) -> Self {
            BigRational::from_integer(BigInt::from(n))
        }
        fn from_ratio(num: i64, den: i64) -> Self {
            assert!(den != 0, "from_ratio: zero denominator");
            BigRational::new(BigInt::from(num), BigInt::from(den))
        }
        fn from_f64(x: f64) -> Option<Self> {
            BigRational::from_float(x)
        }
        fn to_f64(&self) -> f64 {
            ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
        }
        fn is_finite(&self) -> bool {
            true
        }
        fn is_zero(&self) -> bool {
            <BigRational as Zero>::is_zero(self)
        }
        fn abs(&self) -> Self {
            Signed::abs(self)
        }
    }
}

/// A scalar known to be finite: a parameter validated once, so that functions taking it
/// need no `Result` (see [`Bezier::at`](super::Bezier::at)).
///
/// ```
/// use compgeo::spline::Finite;
///
/// let t = Finite::new(0.25, "t")?;
/// assert_eq!(*t.get(), 0.25);
/// assert!(Finite::new(f64::NAN, "t").is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Finite<S>(S);

impl<S: Scalar> Finite<S> {
    /// The value, if it is finite.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming `name` if `value` is NaN or infinite.
    #[inline]
    pub fn new(value: S, name: &'static str) -> Result<Self> {
        validate_parameter(&value, name)?;
        Ok(Finite(value))
    }

    /// The value.
    #[inline]
    pub fn get(&self) -> &S {
        &self.0
    }

    /// The value, by value.
    #[inline]
    pub fn into_inner(self) -> S {
        self.0
    }
}
/// Validates that every coordinate of every point is finite.
///
/// # Errors
///
/// [`Error::Empty`] naming `what` for no points; [`Error::NonFinite`] with the index of the
/// first point that has a NaN or infinite coordinate.
pub fn validate_points<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    what: &'static str,
) -> Result<()> {
    if points.is_empty() {
        return Err(Error::Empty { what });
    }
    for (index, p) in points.iter().enumerate() {
        if let Some(c) = p.0.iter().find(|c| !c.is_finite()) {
            return Err(Error::NonFinite {
                index,
                value: c.to_f64(),
            });
        }
    }
    Ok(())
}

/// Validates one parameter value (a `t`, an interval end): it must be finite.
///
/// # Errors
///
/// [`Error::InvalidParameter`] naming `name` if the value is NaN or infinite.
#[inline]
pub fn validate_parameter<S: Scalar>(t: &S, name: &'static str) -> Result<()> {
    if t.is_finite() {
        Ok(())
    } else {
        Err(non_finite_parameter(name, t.to_f64()))
    }
}

/// The error of [`validate_parameter`], out of line so the check stays small in hot loops.
#[cold]
#[inline(never)]
fn non_finite_parameter(name: &'static str, value: f64) -> Error {
    Error::InvalidParameter {
        name,
        reason: format!("must be finite, got {value}"),
    }
}

/// The binomial coefficient C(n, k) in `S` (zero when `k > n`): from a table of exact
/// integers for n < 64, else by the multiplicative formula, whose partial products
/// C(n − k + i, i) are integers, so it is exact for rationals and for `f64` as long as they
/// stay below 2^53.
///
/// # Complexity
///
/// O(1) for n < 64, else O(min(k, n − k)) field operations.
///
/// ```
/// use compgeo::spline::binomial;
///
/// assert_eq!(binomial::<f64>(5, 2), 10.0);
/// assert_eq!(binomial::<f64>(3, 4), 0.0);
/// ```
#[inline]
pub fn binomial<S: Scalar>(n: usize, k: usize) -> S {
    if k > n {
        return S::zero();
    }
    if n < BINOMIAL_ROWS {
        return S::from_i64(BINOMIALS[n * (n + 1) / 2 + k] as i64);
    }
    let k = k.min(n - k);
    let mut c = S::one();
    for i in 1..=k {
        c = c * S::from_i64((n - k + i) as i64) / S::from_i64(i as i64);
    }
    c
}

/// Rows 0..63 of Pascal's triangle (all fit in an i64), row n starting at n(n + 1)/2.
pub(crate) const BINOMIAL_ROWS: usize = 64;

static BINOMIALS: [u64; BINOMIAL_ROWS * (BINOMIAL_ROWS + 1) / 2] = pascal();

const fn pascal() -> [u64; BINOMIAL_ROWS * (BINOMIAL_ROWS + 1) / 2] {
    let mut table = [0u64; BINOMIAL_ROWS * (BINOMIAL_ROWS + 1) / 2];
    let mut n = 0;
    while n < BINOMIAL_ROWS {
        let row = n * (n + 1) / 2;
        table[row] = 1;
        table[row + n] = 1;
        let mut k = 1;
        while k < n {
            let prev = (n - 1) * n / 2;
            table[row + k] = table[prev + k - 1] + table[prev + k];
            k += 1;
        }
        n += 1;
    }
    table
}

/// The falling factorial `n (n − 1) ⋯ (n − r + 1)` (r factors; 1 for r = 0, and 0 for
/// r > n): the factor of an r-th derivative of a polynomial of degree n, and n! for r = n.
pub(crate) fn falling_factorial<S: Scalar>(n: usize, r: usize) -> S {
    let mut f = S::one();
    for k in 0..r.min(n + 1) {
        f = f * S::from_i64((n - k) as i64);
    }
    f
}

/// `xᵏ`, by k − 1 multiplications.
pub(crate) fn power<S: Scalar>(x: &S, k: usize) -> S {
    let mut p = S::one();
    for _ in 0..k {
        p = p * x;
    }
    p
}

/// For rounded scalars, the power of two `2^−e` that brings the largest coordinate of
/// `vectors` into `[1, 2)` (e clamped to ±1020 so the factor is a normal double); one for
/// exact scalars and for all-zero input. Multiplying by it is exact unless a coordinate
/// underflows, which only happens to coordinates below 2^−1074 relative to the largest.
pub(crate) fn pow2_scale<S: Scalar, const D: usize>(vectors: &[&Point<S, D>]) -> S {
    if S::EXACT {
        return S::one();
    }
    let max = vectors
        .iter()
        .flat_map(|v| v.coords().iter())
        .fold(0.0f64, |m, c| m.max(c.to_f64().abs()));
    if max == 0.0 || !max.is_finite() {
        return S::one();
    }
    let e = (max.log2().floor() as i32).clamp(-1020, 1020);
    S::from_f64(2f64.powi(-e)).unwrap_or_else(S::one)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomials_match_pascal_and_the_product_formula() {
        for n in 0..70usize {
            for k in 1..n {
                let lhs: f64 = binomial(n, k);
                let rhs: f64 = binomial::<f64>(n - 1, k - 1) + binomial::<f64>(n - 1, k);
                // Exact below 2^53; beyond it both sides are rounded once or twice.
                assert!((lhs - rhs).abs() <= lhs * 1e-15, "C({n},{k})");
            }
            assert_eq!(binomial::<f64>(n, 0), 1.0);
            assert_eq!(binomial::<f64>(n, n + 1), 0.0);
        }
        assert_eq!(BINOMIALS[63 * 64 / 2 + 31], 916_312_070_471_295_267);
        assert_eq!(falling_factorial::<f64>(5, 2), 20.0);
        assert_eq!(falling_factorial::<f64>(4, 4), 24.0);
        assert_eq!(falling_factorial::<f64>(2, 3), 0.0);
        assert_eq!(power(&3.0, 4), 81.0);
    }

    #[test]
    fn point_arithmetic_is_coordinatewise() {
        let a = Point::new([1.0, -2.0, 3.0]);
        let b = Point::new([0.5, 4.0, -1.0]);
        assert_eq!(a + b, Point::new([1.5, 2.0, 2.0]));
        assert_eq!(a - b, Point::new([0.5, -6.0, 4.0]));
        assert_eq!(-a * 2.0, Point::new([-2.0, 4.0, -6.0]));
        assert_eq!(a.dot(&b), 0.5 - 8.0 - 3.0);
        assert_eq!(Point::lerp(&a, &b, &0.0), a);
        assert_eq!(Point::lerp(&a, &b, &1.0), b);
    }

    #[test]
    fn validation_names_the_bad_point() {
        let pts = [Point::new([0.0, 1.0]), Point::new([f64::NAN, 0.0])];
        match validate_points(&pts, "control polygon") {
            Err(Error::NonFinite { index: 1, .. }) => {}
            other => panic!("{other:?}"),
        }
        let empty: [Point<f64, 2>; 0] = [];
        assert_eq!(
            validate_points(&empty, "control polygon"),
            Err(Error::Empty {
                what: "control polygon"
            })
        );
        assert!(validate_parameter(&f64::INFINITY, "t").is_err());
    }

    #[test]
    fn abs_at_most_is_the_comparison_of_absolute_values() {
        let tiny = f64::from_bits(1); // the smallest subnormal
        let values = [0.0, -0.0, tiny, -tiny, 0.5, -1.0, 3.0, f64::MAX, f64::MIN];
        let values = values
            .into_iter()
            .chain([f64::INFINITY, f64::NEG_INFINITY, f64::NAN]);
        let limits = [-1.0, -0.0, 0.0, tiny, 1.0, 3.0, f64::MAX, f64::INFINITY];
        for x in values {
            for limit in limits {
                let want = !x.is_nan() && x.abs() <= limit;
                assert_eq!(x.abs_at_most(limit), want, "|{x}| ≤ {limit}");
                #[cfg(feature = "exact")]
                if let Some(r) = <num_rational::BigRational as Scalar>::from_f64(x) {
                    assert_eq!(r.abs_at_most(limit), want, "rational |{x}| ≤ {limit}");
                }
            }
        }
    }
}
