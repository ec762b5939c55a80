//! Bézier curves: evaluation (de Casteljau and Horner), derivatives, subdivision,
//! restriction and reparametrisation, reversal, the blossom and the bounding box.
//!
//! A curve of degree n in R^D is `b(t) = Σᵢ bᵢ Bᵢⁿ(t)` with control points b₀, …, bₙ
//! ([`Point<S, D>`]) and the Bernstein polynomials of [`bernstein`](super::bernstein()). The
//! parameter t is the local one: b₀ = b(0) and bₙ = b(1), and every method accepts any real t,
//! also outside [0, 1]. [`Reparametrised`] (in `reparametrised.rs`) carries a curve over a
//! global interval [a, b]. Batch evaluation, degree elevation, monomial conversion,
//! integration, flattening and forward differencing are in `bezier_ops.rs`; curve/curve
//! intersection in `intersect.rs`.
//!
//! Follows `000_f3201fe9758fe02a.txt` ch. 2 (§2.2 Bézier representation, §2.3 de Casteljau and
//! Obs. 4 Horner, §2.4 derivatives, §2.6 the tetrahedral algorithm) and ch. 3 (§3.1–3.3
//! blossom, fundamental theorem, subdivision), and `003_5b666ee3e15e6353.txt` §3.2.
//!
//! Invariants the tests check (exactly on rationals): partition of unity, endpoint
//! interpolation, symmetry, affine invariance, the convex-hull property, de Casteljau =
//! Horner, split pieces evaluate to the original, the blossom is symmetric, multi-affine and
//! equals the curve on its diagonal, derivative identities.

use super::bernstein::falling_factorial;
use super::horner::{horner_limit, in_registers, Polygon};
use super::reparametrised::Reparametrised;
use super::scalar::{validate_parameter, validate_points, Finite, Point, Scalar};
use crate::count::{Counter, NoCount};
use crate::{Error, Result};
use std::fmt::Debug;
use crate::complexity::{on, Bound, Declaration};
use crate::count::Operation;

/// De Casteljau's evaluation, declared: its name, bounds, counts, source and claims.
pub(crate) const DE_CASTELJAU: Declaration = Declaration {
    problem: "bezier",
    name: "de-casteljau",
    function: "spline::Bezier::de_casteljau",
    file: "src/spline/bezier.rs",
    summary: "repeated affine combinations of the control points",
    time: "Θ(n²D)",
    space: "O(nD)",
    operation: Operation::ArithmeticOperations,
    counts: "exactly n(n + 1)/2 affine combinations per point",
    source: "[PPB, §2.3]",
    claims: &[on("uniform-square", Bound::Quadratic, Operation::ArithmeticOperations)],
};

/// Horner's evaluation, declared: its name, bounds, counts, source and claims.
pub(crate) const HORNER: Declaration = Declaration {
    problem: "bezier",
    name: "horner",
    function: "spline::Bezier::horner",
    file: "src/spline/bezier.rs",
    summary: "the Bernstein form rewritten for a Horner scheme",
    time: "Θ(nD)",
    space: "O(D)",
    operation: Operation::ArithmeticOperations,
    counts: "n + 1 point operations per point",
    source: "[PPB, §2.3]",
    claims: &[on("uniform-square", Bound::Linear, Operation::ArithmeticOperations)],
};

/// A Bézier curve of degree n (n + 1 control points in R^D, over the scalar `S`).
///
/// Construct with [`Bezier::new`], which validates the control polygon; the fields are
/// private so a `Bezier` always has at least one control point, all finite.
///
/// ```
/// use compgeo::spline::{Bezier, Point};
///
/// let b = Bezier::new(vec![
///     Point::new([0.0, 0.0]),
///     Point::new([1.0, 2.0]),
///     Point::new([3.0, 2.0]),
///     Point::new([4.0, 0.0]),
/// ])?;
/// assert_eq!(b.degree(), 3);
/// assert_eq!(b.eval(&0.5)?, Point::new([2.0, 1.5]));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone)]
pub struct Bezier<S, const D: usize> {
    pub(super) control: Polygon<S, D>,
    /// A bound on |t| under which Horner's scheme provably stays within the `f64` range
    /// (negative if there is none; unused for exact scalars); see [`horner_limit`].
    pub(super) horner_limit: f64,
}

impl<S: PartialEq, const D: usize> PartialEq for Bezier<S, D> {
    fn eq(&self, other: &Self) -> bool {
        // The limit is a function of the control points.
        self.control.as_slice() == other.control.as_slice()
    }
}

impl<S: Debug, const D: usize> Debug for Bezier<S, D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Bezier")
            .field("control", &self.control.as_slice())
            .finish()
    }
}

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// The curve with the given control points b₀, …, bₙ (degree n = `control.len() − 1`).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no control points; [`Error::NonFinite`] naming the first control
    /// point with a NaN or infinite coordinate.
    ///
    /// # Complexity
    ///
    /// O(nD) to validate the points and to bound their coordinates (for the overflow check of
    /// the evaluations), plus O(D) for the scaled points of a cubic; no auxiliary space.
    pub fn new(control: Vec<Point<S, D>>) -> Result<Self> {
        validate_points(&control, "control polygon")?;
        Ok(Bezier::with_control(control))
    }

    /// The control points b₀, …, bₙ.
    #[inline]
    pub fn control(&self) -> &[Point<S, D>] {
        self.control.as_slice()
    }

    /// The control points, by value.
    pub fn into_control(self) -> Vec<Point<S, D>> {
        self.control.into_vec()
    }

    /// The degree n (the number of control points minus one).
    #[inline]
    pub fn degree(&self) -> usize {
        self.control().len() - 1
    }

    /// The same curve with `f64` coordinates (each rounded to the nearest double).
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if a coordinate is beyond the range of `f64`.
    pub fn to_f64(&self) -> Result<Bezier<f64, D>> {
        Bezier::derived(self.control().iter().map(Point::to_f64).collect(), "to_f64")
    }

    /// The curve of an `f64` curve's exact values in `S` (exact for rationals).
    pub fn from_f64(curve: &Bezier<f64, D>) -> Self {
        let control = curve
            .control()
            .iter()
            .map(|p| Point::from_f64(p).expect("a Bezier's control points are finite"))
            .collect();
        Bezier::with_control(control)
    }

    /// The point b(t), by the Horner-type scheme ([`Bezier::horner`]): the fast evaluation.
    ///
    /// Horner scales the control points by binomial coefficients, which can overflow `f64`
    /// for coordinates near the top of its range; then the result is recomputed by de
    /// Casteljau's algorithm, which only forms affine combinations. On `f64`, a value that is
    /// itself beyond the double range (t far outside [0, 1]) comes out infinite.
    ///
    /// Whether Horner's scheme can overflow is known before it runs: [`Bezier::new`] bounds
    /// |t| from the degree and the largest coordinate, and one comparison of t with that
    /// bound, which also rejects NaN and ±∞, decides between the plain scheme and the checked
    /// path (parameter validation, Horner, finiteness check, de Casteljau). Lines,
    /// quadratics and cubics keep their control points inside the curve value and are
    /// evaluated by closed forms compiled into the caller; other degrees by an out-of-line
    /// call.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time, O(D) auxiliary space (Θ(n²D) time and O(nD) space in the overflow case).
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// // b(t) = (t², t³) in the monomial basis.
    /// let b = Bezier::new(vec![
    ///     Point::new([0.0, 0.0]),
    ///     Point::new([0.0, 0.0]),
    ///     Point::new([1.0 / 3.0, 0.0]),
    ///     Point::new([1.0, 1.0]),
    /// ])?;
    /// assert_eq!(b.eval(&2.0)?, Point::new([4.0, 8.0]));
    /// assert_eq!(b.eval(&-10.0)?, Point::new([100.0, -1000.0]));
    /// assert!(b.eval(&f64::NAN).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    // Always inlined: a call would return the point through memory, and the caller's
    // loop could no longer keep the control points in registers (about 3× slower).
    #[inline(always)]
    pub fn eval(&self, t: &S) -> Result<Point<S, D>> {
        if self.horner_is_safe(t) {
            if let Some(p) = self.closed_form(t) {
                return Ok(p);
            }
        }
        self.eval_general_checked(t).map(in_registers)
    }

    /// The point b(t) at a parameter validated beforehand: [`Bezier::eval`] without the
    /// `Result`, for loops over many parameters checked once (or generated finite).
    ///
    /// # Complexity
    ///
    /// As [`Bezier::eval`]: Θ(nD) time, O(D) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Finite, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// let ts = [0.0, 0.5, 2.0].map(|t| Finite::new(t, "t")).into_iter().collect::<Result<Vec<_>, _>>()?;
    /// let ys: Vec<_> = ts.iter().map(|t| b.at(t)[0]).collect();
    /// assert_eq!(ys, [0.0, 0.25, 4.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    // Always inlined: a call would return the point through memory, and the caller's
    // loop could no longer keep the control points in registers (about 3× slower).
    #[inline(always)]
    pub fn at(&self, t: &Finite<S>) -> Point<S, D> {
        let t = t.get();
        if self.horner_is_safe(t) {
            if let Some(p) = self.closed_form(t) {
                return p;
            }
        }
        in_registers(self.eval_general(t))
    }

    /// The point b(t) by de Casteljau's algorithm. See [`Bezier::de_casteljau_with`].
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([1.0]), Point::new([0.0])])?;
    /// assert_eq!(b.de_casteljau(&0.5)?, Point::new([0.5]));
    /// assert_eq!(b.de_casteljau(&2.0)?, Point::new([-4.0])); // outside [0, 1]: 2t(1 − t)
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN or infinite.
    pub fn de_casteljau(&self, t: &S) -> Result<Point<S, D>> {
        self.de_casteljau_with(t, &mut NoCount)
    }

    /// The point b(t) by de Casteljau's algorithm, counting its affine combinations.
    ///
    /// Idea: replace the polygon b₀ᵏ, …, bₙ₋ₖᵏ by the points `bᵢᵏ⁺¹ = (1 − t) bᵢᵏ + t bᵢ₊₁ᵏ`
    /// until one point is left: b(t) = b₀ⁿ. For t in [0, 1] every step is a convex
    /// combination, which makes the scheme numerically stable; any other t works too.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.3 and `003_5b666ee3e15e6353.txt` §3.2
    /// ("Algoritmo de De Casteljau").
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time: exactly n(n + 1)/2 affine combinations of points; O(nD) auxiliary space
    /// (one copy of the polygon).
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// n(n + 1)/2.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new((0..5).map(|i| Point::new([i as f64])).collect())?;
    /// let mut c = Counts::default();
    /// b.de_casteljau_with(&0.25, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 10); // 4·5/2
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_casteljau_with<C: Counter>(&self, t: &S, counter: &mut C) -> Result<Point<S, D>> {
        validate_parameter(t, "t")?;
        let mut q = self.control().to_vec();
        for k in 1..q.len() {
            for i in 0..q.len() - k {
                q[i] = Point::lerp(&q[i], &q[i + 1], t);
                counter.arithmetic_operation();
            }
        }
        Ok(q.swap_remove(0))
    }

    /// The point b(t) by the Horner-type scheme. See [`Bezier::horner_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN or infinite.
    pub fn horner(&self, t: &S) -> Result<Point<S, D>> {
        self.horner_with(t, &mut NoCount)
    }

    /// The point b(t) by the Horner-type scheme of the seed, counting its point operations.
    ///
    /// Idea: `b(t) = (1 − t)ⁿ Σᵢ C(n, i) bᵢ sⁱ` with s = t/(1 − t) is a polynomial in s, and
    /// Horner's rule evaluates it with n multiply-adds. The seed notes that this fails near
    /// t = 1 and switches to the mirrored form there; here the factor (1 − t)ⁿ is instead
    /// distributed over the nesting, one factor (1 − t) per step:
    /// `(⋯((b₀(1 − t) + C(n,1) t b₁)(1 − t) + C(n,2) t² b₂)(1 − t) + ⋯) + tⁿ bₙ`.
    /// No division remains, so no parameter fails and no branch is taken: every real t,
    /// also outside [0, 1], costs the same n + 1 steps.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.3, Obs. 4.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time: n multiply-adds of points and one scaling, plus O(n) scalar operations
    /// (binomials from a table for n < 64, by their ratio recurrence above; a cubic keeps its
    /// scaled points 3b₁ and 3b₂ from construction); O(D) auxiliary space. On `f64` the
    /// binomials overflow for n above about 1020.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per multiply-add and one
    /// for the final scaling: n + 1.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new((0..5).map(|i| Point::new([(i * i) as f64])).collect())?;
    /// let mut c = Counts::default();
    /// let p = b.horner_with(&0.25, &mut c)?;
    /// assert_eq!(p, b.de_casteljau(&0.25)?);
    /// assert_eq!(c.arithmetic_operations, 5);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    #[inline]
    pub fn horner_with<C: Counter>(&self, t: &S, counter: &mut C) -> Result<Point<S, D>> {
        validate_parameter(t, "t")?;
        Ok(self.horner_unchecked(t, counter))
    }

    /// The two halves of the curve at the parameter c: the control points of the same
    /// polynomial over [0, c] and over [c, 1], each as a curve with local parameter in [0, 1].
    ///
    /// Idea: in de Casteljau's triangle for b(c), the first points of the columns are the
    /// Bézier points over [0, c] and the last ones, read backwards, those over [c, 1]. Any c
    /// works, also outside [0, 1] (then one piece extends the curve).
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §3.3.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `c` is NaN or infinite; [`Error::Overflow`] if c is so
    /// far outside [0, 1] that a control point is beyond the range of `f64`.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time (one de Casteljau triangle), O(nD) auxiliary space besides the output.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([4.0]), Point::new([0.0])])?;
    /// let (left, right) = b.split(&0.5)?;
    /// assert_eq!(left.control(), [Point::new([0.0]), Point::new([2.0]), Point::new([2.0])]);
    /// assert_eq!(right.control(), [Point::new([2.0]), Point::new([2.0]), Point::new([0.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split(&self, c: &S) -> Result<(Self, Self)> {
        validate_parameter(c, "c")?;
        let (left, right) = self.split_unchecked(c);
        Ok((
            Bezier::derived(left.into_control(), "split")?,
            Bezier::derived(right.into_control(), "split")?,
        ))
    }

    /// The control points of the same polynomial over the oriented interval [a, b]: the
    /// curve t ↦ b((1 − t) a + t b). Any finite a and b (a > b reverses, a = b gives a
    /// constant curve).
    ///
    /// Idea: by the fundamental theorem the Bézier points over [a, b] are the blossom values
    /// `b[a, …, a, b, …, b]` with n − i arguments a and i arguments b.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §3.2.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `a` or `b` is NaN or infinite; [`Error::Overflow`] if
    /// a new control point is beyond the range of `f64`.
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time (n + 1 blossom evaluations), O(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([1.0])])?;
    /// let r = b.restrict(&2.0, &3.0)?;
    /// assert_eq!(r.control(), [Point::new([2.0]), Point::new([3.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn restrict(&self, a: &S, b: &S) -> Result<Self> {
        validate_parameter(a, "a")?;
        validate_parameter(b, "b")?;
        let n = self.degree();
        let mut args = vec![a.clone(); n];
        let mut control = Vec::with_capacity(n + 1);
        control.push(self.blossom_unchecked(&args));
        for i in 1..=n {
            args[n - i] = b.clone();
            control.push(self.blossom_unchecked(&args));
        }
        Bezier::derived(control, "restrict")
    }

    /// The same curve traversed backwards: control points in reverse order, so the new curve
    /// at t is the old one at 1 − t.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.2 (symmetry of the Bézier representation).
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space for the copy.
    pub fn reversed(&self) -> Self {
        let mut control = self.control().to_vec();
        control.reverse();
        Bezier::with_control(control)
    }

    /// This curve over the global interval [a, b]; see [`Reparametrised`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `a` or `b` is NaN or infinite, or if `a ≥ b`.
    pub fn reparametrise(self, a: S, b: S) -> Result<Reparametrised<S, D>> {
        validate_parameter(&a, "a")?;
        validate_parameter(&b, "b")?;
        if a >= b {
            return Err(Error::InvalidParameter {
                name: "interval",
                reason: format!("needs a < b, got a = {} and b = {}", a.to_f64(), b.to_f64()),
            });
        }
        Ok(Reparametrised::new_unchecked(self, a, b))
    }

    /// The hodograph: the first derivative as a Bézier curve of degree n − 1 with control
    /// points n·Δbᵢ = n(bᵢ₊₁ − bᵢ). See [`Bezier::derivative`].
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] as for [`Bezier::derivative`].
    pub fn hodograph(&self) -> Result<Self> {
        self.derivative(1)
    }

    /// The r-th derivative curve: degree n − r with control points
    /// `n (n − 1) ⋯ (n − r + 1) Δʳbᵢ` (the zero curve of degree 0 when r > n).
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.4 and `003_5b666ee3e15e6353.txt` §3.2
    /// ("Derivadas").
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if a control point of the derivative is beyond the range of `f64`
    /// (differences of coordinates near ±1.8e308).
    ///
    /// # Complexity
    ///
    /// Θ(r·nD) time (r rounds of differences), O(nD) space for the result.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// // b(t) = t² has Bézier points 0, 0, 1; b' = 2t has 0, 2; b'' = 2.
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// assert_eq!(b.derivative(1)?.control(), [Point::new([0.0]), Point::new([2.0])]);
    /// assert_eq!(b.derivative(2)?.control(), [Point::new([2.0])]);
    /// assert_eq!(b.derivative(3)?.control(), [Point::new([0.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn derivative(&self, r: usize) -> Result<Self> {
        let n = self.degree();
        if r > n {
            return Ok(Bezier::with_control(vec![Point::zero()]));
        }
        let mut q = self.control().to_vec();
        forward_differences_in_place(&mut q, r);
        let factor: S = falling_factorial(n, r);
        for p in &mut q {
            *p = p.clone() * &factor;
        }
        Bezier::derived(q, "derivative")
    }

    /// A curve computed from a valid one: non-empty by construction, finite unless the
    /// computation overflowed `f64`.
    pub(crate) fn derived(control: Vec<Point<S, D>>, what: &'static str) -> Result<Self> {
        debug_assert!(!control.is_empty());
        if control.iter().all(Point::is_finite) {
            Ok(Bezier::with_control(control))
        } else {
            Err(Error::Overflow { what })
        }
    }

    /// The r-th derivative b⁽ʳ⁾(t) at one parameter, by the tetrahedral algorithm.
    ///
    /// Idea: differences commute with de Casteljau steps, so run n − r steps of de Casteljau,
    /// take r forward differences of the r + 1 points left and multiply by
    /// n (n − 1) ⋯ (n − r + 1). Zero when r > n.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.6.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, O(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// assert_eq!(b.derivative_at(&0.75, 1)?, Point::new([1.5])); // (t²)' = 2t
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn derivative_at(&self, t: &S, r: usize) -> Result<Point<S, D>> {
        validate_parameter(t, "t")?;
        let n = self.degree();
        if r > n {
            return Ok(Point::zero());
        }
        let mut q = self.control().to_vec();
        for k in 1..=n - r {
            for i in 0..q.len() - k {
                q[i] = Point::lerp(&q[i], &q[i + 1], t);
            }
        }
        q.truncate(r + 1);
        forward_differences_in_place(&mut q, r);
        Ok(q.swap_remove(0) * falling_factorial::<S>(n, r))
    }

    /// The blossom (polar form) `b[u₁, …, uₙ]`: the unique symmetric, multi-affine function
    /// of n arguments whose diagonal `b[u, …, u]` is b(u).
    ///
    /// Idea: de Casteljau's algorithm with a different parameter at each level:
    /// `bᵢᵏ⁺¹ = (1 − uₖ₊₁) bᵢᵏ + uₖ₊₁ bᵢ₊₁ᵏ`.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §3.1–3.2 (recurrence (1) of the fundamental theorem).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if the number of arguments is not the degree n, or one of
    /// them is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, O(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// // The blossom of t² is u₁u₂.
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// assert_eq!(b.blossom(&[3.0, 5.0])?, Point::new([15.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom(&self, args: &[S]) -> Result<Point<S, D>> {
        if args.len() != self.degree() {
            return Err(Error::InvalidParameter {
                name: "blossom arguments",
                reason: format!(
                    "a curve of degree {} needs {} arguments, got {}",
                    self.degree(),
                    self.degree(),
                    args.len()
                ),
            });
        }
        for u in args {
            validate_parameter(u, "blossom argument")?;
        }
        Ok(self.blossom_unchecked(args))
    }

    /// The axis-aligned box `[min bᵢ, max bᵢ]` (coordinate-wise) of the control points, which
    /// contains the curve segment b[0, 1] by the convex-hull property. Returns (min, max).
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.2, Obs. 2.
    ///
    /// # Complexity
    ///
    /// Θ(nD) comparisons, O(D) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0, 1.0]), Point::new([2.0, -1.0])])?;
    /// assert_eq!(b.bounding_box(), (Point::new([0.0, -1.0]), Point::new([2.0, 1.0])));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bounding_box(&self) -> (Point<S, D>, Point<S, D>) {
        bounding_box_of(self.control())
    }

    /// The curve with these control points (at least one, all finite), with its Horner
    /// bound.
    fn with_control(control: Vec<Point<S, D>>) -> Self {
        Bezier {
            horner_limit: horner_limit(&control),
            control: Polygon::new(control),
        }
    }

    /// The split without validation (c finite).
    pub(crate) fn split_unchecked(&self, c: &S) -> (Self, Self) {
        let n = self.degree();
        let mut q = self.control().to_vec();
        let mut left = Vec::with_capacity(n + 1);
        let mut right = Vec::with_capacity(n + 1);
        left.push(q[0].clone());
        right.push(q[n].clone());
        for k in 1..=n {
            for i in 0..=n - k {
                q[i] = Point::lerp(&q[i], &q[i + 1], c);
            }
            left.push(q[0].clone());
            right.push(q[n - k].clone());
        }
        right.reverse();
        (Bezier::with_control(left), Bezier::with_control(right))
    }

    /// The blossom without validation (`args.len() == n`, all finite).
    fn blossom_unchecked(&self, args: &[S]) -> Point<S, D> {
        let mut q = self.control().to_vec();
        for (k, u) in args.iter().enumerate() {
            for i in 0..q.len() - k - 1 {
                q[i] = Point::lerp(&q[i], &q[i + 1], u);
            }
        }
        q.swap_remove(0)
    }
}

/// The coordinate-wise minimum and maximum of a non-empty list of points.
pub(crate) fn bounding_box_of<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
) -> (Point<S, D>, Point<S, D>) {
    let mut lo = points[0].clone();
    let mut hi = points[0].clone();
    for p in &points[1..] {
        for j in 0..D {
            if p[j] < lo[j] {
                lo[j] = p[j].clone();
            }
            if p[j] > hi[j] {
                hi[j] = p[j].clone();
            }
        }
    }
    (lo, hi)
}

/// Replaces `q` by its r-th forward differences `Δʳqᵢ` (r ≤ len − 1; the list shrinks by r).
pub(crate) fn forward_differences_in_place<S: Scalar, const D: usize>(
    q: &mut Vec<Point<S, D>>,
    r: usize,
) {
    for _ in 0..r {
        for i in 0..q.len() - 1 {
            q[i] = q[i + 1].clone() - &q[i];
        }
        q.pop();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degree_zero_curve_is_constant() {
        let b = Bezier::new(vec![Point::new([2.0, -1.0])]).unwrap();
        for t in [-3.0, 0.0, 0.4, 1.0, 7.5] {
            assert_eq!(b.eval(&t).unwrap(), Point::new([2.0, -1.0]));
            assert_eq!(b.de_casteljau(&t).unwrap(), Point::new([2.0, -1.0]));
        }
        assert_eq!(b.hodograph().unwrap().control(), [Point::new([0.0, 0.0])]);
        assert_eq!(b.blossom(&[]).unwrap(), Point::new([2.0, -1.0]));
    }

    #[test]
    fn bad_parameters_are_errors() {
        let b = Bezier::new(vec![Point::new([0.0]), Point::new([1.0])]).unwrap();
        assert!(b.eval(&f64::NAN).is_err());
        assert!(b.split(&f64::INFINITY).is_err());
        assert!(b.blossom(&[0.5, 0.5]).is_err());
        assert!(b.clone().reparametrise(1.0, 1.0).is_err());
        assert!(b.reparametrise(2.0, 1.0).is_err());
        assert!(Bezier::<f64, 1>::new(vec![]).is_err());
    }
}
