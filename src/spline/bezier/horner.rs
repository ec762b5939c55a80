//! Horner-type evaluation of Bézier curves, the crate's fast evaluation, and what makes it
//! fast on `f64`.
//!
//! The problem: the point b(t) in Θ(n) instead of de Casteljau's Θ(n²). The idea: write
//! `b(t) = (1 − t)ⁿ Σᵢ C(n, i) bᵢ sⁱ` with s = t/(1 − t) and nest it as Horner's rule does,
//! with the factor (1 − t)ⁿ distributed over the nesting so that no division remains. What
//! makes it fast: closed forms for degrees 1 to 3 and a loop with tabulated binomials above;
//! the control polygon's storage (lines, quadratics and cubics inline, cubics with their
//! binomially scaled points); the bound on |t| under which no step can overflow, fixed when
//! the curve is built; and the checked path beyond it (de Casteljau's algorithm when
//! Horner's scheme overflows).
//!
//! Follows [PPB, §2.3, Obs. 4].
//!
//! # Complexity
//!
//! Θ(nD) time and O(D) auxiliary space per point (Θ(n²D) and O(nD) in the overflow case).
//!
//! The entry points are [`Curve::eval`] (the [`Curve`] implementation of [`Bezier`]),
//! [`Bezier::at`], [`Bezier::eval_each`], [`Bezier::horner`] and [`Bezier::horner_with`]. The
//! `spline` benchmark compares them with a hand-written `f64` cubic, kurbo and lyon_geom.

use super::curve::Bezier;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::curve::{Curve, Domain};
use crate::spline::scalar::{binomial, validate_parameter, Finite, Point, Scalar, BINOMIAL_ROWS};
use crate::{Error, Result};

/// Horner's evaluation, declared: its name, bounds, counts, source and claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "bezier",
    name: "horner",
    function: "spline::Bezier::horner",
    file: "src/spline/bezier/horner.rs",
    summary: "the Bernstein form rewritten for a Horner scheme",
    time: "Θ(nD)",
    space: "O(D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "n + 1 point operations per point",
    source: "[PPB, §2.3]",
    claims: &[on(
        "uniform-square",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// A control polygon: lines, quadratics and cubics inline, other degrees on the heap.
///
/// Inline, the points of a borrowed curve are part of the borrowed value, which the compiler
/// knows nothing modifies during the borrow: a loop evaluating the curve loads them once,
/// even though the loop also contains the (rare) out-of-line calls of the checked path. On
/// the heap they would be reloaded at every evaluation. The variant is also the degree
/// dispatch of the closed forms.
#[derive(Clone)]
pub(super) enum Polygon<S, const D: usize> {
    Line([Point<S, D>; 2]),
    Quadratic([Point<S, D>; 3]),
    /// With 3b₁ and 3b₂, the scaled points of Horner's nesting, computed once.
    Cubic([Point<S, D>; 4], [Point<S, D>; 2]),
    /// Degree 0, or degree 4 and more.
    Other(Vec<Point<S, D>>),
}

impl<S: Scalar, const D: usize> Polygon<S, D> {
    /// The polygon of these points (at least one).
    pub(super) fn new(control: Vec<Point<S, D>>) -> Self {
        match <[_; 2]>::try_from(control) {
            Ok(b) => Polygon::Line(b),
            Err(control) => match <[_; 3]>::try_from(control) {
                Ok(b) => Polygon::Quadratic(b),
                Err(control) => match <[_; 4]>::try_from(control) {
                    Ok(b) => {
                        let three = S::from_i64(3);
                        let scaled = [b[1].clone() * &three, b[2].clone() * &three];
                        Polygon::Cubic(b, scaled)
                    }
                    Err(control) => Polygon::Other(control),
                },
            },
        }
    }

    /// The points, by value.
    pub(super) fn into_vec(self) -> Vec<Point<S, D>> {
        match self {
            Polygon::Line(b) => b.into(),
            Polygon::Quadratic(b) => b.into(),
            Polygon::Cubic(b, _) => b.into(),
            Polygon::Other(b) => b,
        }
    }
}

impl<S, const D: usize> Polygon<S, D> {
    /// The points b₀, …, bₙ.
    #[inline]
    pub(super) fn as_slice(&self) -> &[Point<S, D>] {
        match self {
            Polygon::Line(b) => b,
            Polygon::Quadratic(b) => b,
            Polygon::Cubic(b, _) => b,
            Polygon::Other(b) => b,
        }
    }
}

/// A Bézier curve evaluates at every real parameter, by Horner's scheme.
impl<S: Scalar, const D: usize> Curve<S, D> for Bezier<S, D> {
    /// [`Domain::Real`]: the polynomial is defined everywhere; the control polygon describes
    /// its segment over [0, 1].
    fn domain(&self) -> Domain<S> {
        Domain::Real
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
    /// use compgeo::spline::{Bezier, Curve, Point};
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
    fn eval(&self, t: &S) -> Result<Point<S, D>> {
        if self.horner_is_safe(t) {
            if let Some(p) = self.closed_form(t) {
                return Ok(p);
            }
        }
        self.eval_general_checked(t).map(in_registers)
    }
}

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// The point b(t) at a parameter validated beforehand: [`Curve::eval`] without the
    /// `Result`, for loops over many parameters checked once (or generated finite).
    ///
    /// # Complexity
    ///
    /// As [`Curve::eval`]: Θ(nD) time, O(D) auxiliary space.
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

    /// Calls `f(b(tᵢ))` for every parameter tᵢ in order: [`Curve::eval`] over a batch, for
    /// sampling a curve densely (plotting, tables).
    ///
    /// Idea: the degree is looked at once, so lines, quadratics and cubics run their closed
    /// form of the Horner nesting in a loop of their own, with the control points held in
    /// local variables (registers, for `f64`). Per parameter, one comparison with the curve's
    /// Horner bound (see [`Curve::eval`]) rules out NaN, ±∞ and any overflow; parameters
    /// that fail it take the checked path, out of line.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming the index of the first NaN or infinite parameter. As
    /// with [`Iterator::try_for_each`], `f` has then been called for every parameter before
    /// that one, in order, and for none after it.
    ///
    /// # Complexity
    ///
    /// Θ(m·nD) time for m parameters, O(D) auxiliary space (as [`Curve::eval`] per
    /// parameter, overflow case included).
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// let mut ys = Vec::new();
    /// b.eval_each(&[0.0, 0.5, 2.0], |p| ys.push(p[0]))?;
    /// assert_eq!(ys, [0.0, 0.25, 4.0]);
    ///
    /// ys.clear();
    /// assert!(b.eval_each(&[0.5, f64::NAN, 1.0], |p| ys.push(p[0])).is_err());
    /// assert_eq!(ys, [0.25]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    #[inline]
    pub fn eval_each<F: FnMut(Point<S, D>)>(&self, ts: &[S], mut f: F) -> Result<()> {
        if let Some([b0, c1, c2, b3]) = self.cubic_horner_points() {
            let (b0, c1, c2, b3) = (b0.clone(), c1.clone(), c2.clone(), b3.clone());
            return self.each_with(ts, &mut f, |t| {
                horner_cubic(&b0, &c1, &c2, &b3, t, &(S::one() - t))
            });
        }
        match self.control() {
            [b0, b1] => {
                let (b0, b1) = (b0.clone(), b1.clone());
                self.each_with(ts, &mut f, |t| horner_line(&b0, &b1, t, &(S::one() - t)))
            }
            [b0, b1, b2] => {
                let (b0, b1, b2) = (b0.clone(), b1.clone(), b2.clone());
                self.each_with(ts, &mut f, |t| {
                    horner_quadratic(&b0, &b1, &b2, t, &(S::one() - t))
                })
            }
            _ => self.each_with(ts, &mut f, |t| in_registers(self.eval_general(t))),
        }
    }

    /// The point b(t) by the Horner-type scheme. See [`Bezier::horner_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN or infinite.
    pub fn horner(&self, t: &S) -> Result<Point<S, D>> {
        self.horner_with(t, &mut NoCount)
    }

    /// The point b(t) by the Horner-type scheme of the course, counting its point operations.
    ///
    /// Idea: `b(t) = (1 − t)ⁿ Σᵢ C(n, i) bᵢ sⁱ` with s = t/(1 − t) is a polynomial in s, and
    /// Horner's rule evaluates it with n multiply-adds. The course notes that this fails near
    /// t = 1 and switches to the mirrored form there; here the factor (1 − t)ⁿ is instead
    /// distributed over the nesting, one factor (1 − t) per step:
    /// `(⋯((b₀(1 − t) + C(n,1) t b₁)(1 − t) + C(n,2) t² b₂)(1 − t) + ⋯) + tⁿ bₙ`.
    /// No division remains, so no parameter fails: every real t, also outside [0, 1], costs
    /// the same n + 1 steps.
    ///
    /// A power of t formed on its own can leave the range of `f64` where its term does not
    /// (t² is 0 for |t| below 1.5e-162, ∞ above 1.3e154), so the scheme avoids the ones
    /// that can underflow: a quadratic multiplies
    /// b₂ by t twice, a cubic nests its lower half in 1 − t and its upper half in t, and from
    /// degree 4 on the nesting is the mirrored one, in t with the powers of 1 − t, wherever
    /// |t| ≤ |1 − t|, so that the powers formed are those of the larger of the two, at least
    /// 1/2 in magnitude. Where the result is still not finite (partial sums that overflow
    /// although they cancel, far outside [0, 1], or a cubic's stored 3bᵢ beyond `f64::MAX`),
    /// the point is recomputed by de Casteljau's algorithm, which only forms affine
    /// combinations, as [`Curve::eval`] does; within the bound on |t| that [`Bezier::new`]
    /// fixes (see [`Curve::eval`]) that never happens.
    ///
    /// Follows [PPB, §2.3, Obs. 4].
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
    /// binomials overflow for n above about 1020. Where de Casteljau's algorithm takes over,
    /// Θ(n²D) time and O(nD) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per multiply-add and one
    /// for the final scaling: n + 1. Where de Casteljau's algorithm takes over, its n(n + 1)/2
    /// affine combinations as well.
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
    ///
    /// // The zero quadratic far outside [0, 1]: t² overflows, (0·t)·t does not.
    /// let zero = Bezier::new(vec![Point::new([0.0]); 3])?;
    /// assert_eq!(zero.horner(&1.55e231)?, Point::new([0.0]));
    /// // A cubic whose stored 3b₁ overflows: Horner's scheme gives ∞ · 0 at t = 1, so de
    /// // Casteljau's algorithm gives the point b₃ (and its 3·4/2 combinations are counted).
    /// let big = Bezier::new([0.0, 1e308, 0.0, 5.0].map(|x| Point::new([x])).to_vec())?;
    /// let mut c = Counts::default();
    /// assert_eq!(big.horner_with(&1.0, &mut c)?, Point::new([5.0]));
    /// assert_eq!(c.arithmetic_operations, 4 + 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    #[inline]
    pub fn horner_with<C: Counter>(&self, t: &S, counter: &mut C) -> Result<Point<S, D>> {
        validate_parameter(t, "t")?;
        Ok(self.horner_or_de_casteljau(t, counter))
    }
}

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// `true` if Horner's scheme at `t` provably stays within the `f64` range, which needs t
    /// finite: always for exact scalars, else `|t|` at most the bound of [`horner_limit`].
    #[inline(always)]
    pub(crate) fn horner_is_safe(&self, t: &S) -> bool {
        S::EXACT || t.abs_at_most(self.horner_limit)
    }

    /// Degrees 1 to 3 by the closed forms of Horner's nesting (`None` for other degrees),
    /// for a `t` within the Horner bound.
    #[inline(always)]
    pub(super) fn closed_form(&self, t: &S) -> Option<Point<S, D>> {
        match &self.control {
            Polygon::Line([b0, b1]) => Some(horner_line(b0, b1, t, &(S::one() - t))),
            Polygon::Quadratic([b0, b1, b2]) => {
                Some(horner_quadratic(b0, b1, b2, t, &(S::one() - t)))
            }
            Polygon::Cubic([b0, _, _, b3], [c1, c2]) => {
                Some(horner_cubic(b0, c1, c2, b3, t, &(S::one() - t)))
            }
            Polygon::Other(_) => None,
        }
    }

    /// For a cubic, b₀, 3b₁, 3b₂ and b₃: the points [`horner_cubic`] takes.
    #[inline(always)]
    pub(crate) fn cubic_horner_points(&self) -> Option<[&Point<S, D>; 4]> {
        match &self.control {
            Polygon::Cubic([b0, _, _, b3], [c1, c2]) => Some([b0, c1, c2, b3]),
            _ => None,
        }
    }

    /// [`Curve::eval`] where [`Bezier::closed_form`] does not apply: validates `t`, then
    /// [`Bezier::eval_general`]. Out of line, so that evaluation loops stay small.
    #[inline(never)]
    pub(super) fn eval_general_checked(&self, t: &S) -> Result<Point<S, D>> {
        validate_parameter(t, "t")?;
        Ok(self.eval_general(t))
    }

    /// The point b(t) for a finite t, any degree: [`Bezier::horner_or_de_casteljau`]. Out of
    /// line: the evaluations inline only the closed forms.
    #[inline(never)]
    pub(crate) fn eval_general(&self, t: &S) -> Point<S, D> {
        self.horner_or_de_casteljau(t, &mut NoCount)
    }

    /// The point b(t) for a finite t, counting: Horner's scheme if its result is finite
    /// (always within the Horner bound), else de Casteljau's algorithm (which only forms
    /// affine combinations). An overflow never comes back to a finite value (∞ stays ∞ or
    /// becomes NaN), so a finite result has not overflowed on the way.
    #[inline(always)]
    fn horner_or_de_casteljau<C: Counter>(&self, t: &S, counter: &mut C) -> Point<S, D> {
        let p = self.horner_unchecked(t, counter);
        if p.is_finite() {
            return p;
        }
        self.de_casteljau_unchecked(t, counter)
    }

    /// Horner's scheme of Obs. 4 without validation (t finite), counting.
    #[inline(always)]
    pub(crate) fn horner_unchecked<C: Counter>(&self, t: &S, counter: &mut C) -> Point<S, D> {
        let n = self.degree();
        counter.arithmetic_operation();
        if n == 0 {
            return self.control()[0].clone();
        }
        // Lines, quadratics and cubics, the common case, get the same nesting unrolled with
        // their binomials as constants: no loop, no table, no bounds checks.
        if let Some(p) = self.closed_form(t) {
            for _ in 0..n {
                counter.arithmetic_operation();
            }
            return p;
        }
        in_registers(self.horner_loop(t, S::one() - t, counter))
    }

    /// Horner's nesting for degree n ≥ 4 (one counted step is already recorded).
    ///
    /// The nesting multiplies the sum by one of t and u = 1 − t step by step and forms the
    /// powers of the other on their own; those are the powers of the larger in magnitude,
    /// at least 1/2 (as |t| + |u| ≥ 1), so they cannot underflow below degree 1023. With the
    /// powers of the smaller, tⁱ alone would be 0 for a tiny t where C(n, i) tⁱ bᵢ is not.
    /// The mirrored nesting is the same scheme on the reversed polygon with t and u swapped:
    /// `(⋯((bₙt + C(n,1) u bₙ₋₁)t + C(n,2) u² bₙ₋₂)t + ⋯) + uⁿ b₀`.
    fn horner_loop<C: Counter>(&self, t: &S, u: S, counter: &mut C) -> Point<S, D> {
        let b = self.control();
        if t.abs() <= u.abs() {
            nest(b.iter().rev(), t, &u, counter)
        } else {
            nest(b.iter(), &u, t, counter)
        }
    }

    /// [`Bezier::eval_each`]'s loop for one evaluation `g` (a closed form, or Horner's
    /// scheme): `g` where the Horner bound allows it, the checked path elsewhere.
    #[inline(always)]
    fn each_with<F, G>(&self, ts: &[S], f: &mut F, g: G) -> Result<()>
    where
        F: FnMut(Point<S, D>),
        G: Fn(&S) -> Point<S, D>,
    {
        for (i, t) in ts.iter().enumerate() {
            let p = if self.horner_is_safe(t) {
                g(t)
            } else {
                in_registers(self.eval_each_slow(i, t)?)
            };
            f(p);
        }
        Ok(())
    }

    /// The checked evaluation of parameter number `index`, out of line (it never sees `f`, so
    /// the caller's closure state can stay in registers).
    #[cold]
    #[inline(never)]
    fn eval_each_slow(&self, index: usize, t: &S) -> Result<Point<S, D>> {
        if !t.is_finite() {
            return Err(Error::InvalidParameter {
                name: "t",
                reason: format!("parameter {index} must be finite, got {}", t.to_f64()),
            });
        }
        Ok(self.eval_general(t))
    }
}

/// `Σᵢ C(n, i) yⁱ xⁿ⁻ⁱ pᵢ` for the points p₀, …, pₙ (n ≥ 4; one counted step is already
/// recorded) by Horner's nesting in x with the powers of y formed on their own:
/// `(⋯((p₀x + C(n,1) y p₁)x + C(n,2) y² p₂)x + ⋯) + yⁿ pₙ`.
fn nest<'a, S: Scalar + 'a, const D: usize, C: Counter>(
    mut points: impl ExactSizeIterator<Item = &'a Point<S, D>>,
    x: &S,
    y: &S,
    counter: &mut C,
) -> Point<S, D> {
    let n = points.len() - 1;
    let first = points.next().expect("n + 1 ≥ 5 points");
    // acc = Σ_{j<i} C(n, j) yʲ xⁱ⁻ʲ pⱼ after step i; yi = yⁱ.
    let mut yi = S::one();
    let mut acc = first.clone() * x;
    // Past the table, C(n, i) = C(n, i − 1)·(n − i + 1)/i keeps each step O(1).
    let mut c = S::one();
    for (i, pi) in points
        .by_ref()
        .take(n - 1)
        .enumerate()
        .map(|(k, p)| (k + 1, p))
    {
        yi = yi * y;
        let coefficient = if n < BINOMIAL_ROWS {
            binomial::<S>(n, i)
        } else {
            c = c * S::from_i64((n - i + 1) as i64) / S::from_i64(i as i64);
            c.clone()
        };
        acc = (acc + &(pi.clone() * (yi.clone() * coefficient))) * x;
        counter.arithmetic_operation();
    }
    counter.arithmetic_operation();
    let last = points.next().expect("the last point");
    acc + &(last.clone() * (yi * y))
}

/// `p` itself. For `f64`, taken apart and put together again coordinate by coordinate: where
/// a point returned in memory by an out-of-line call (the checked path, Horner's loop) meets
/// one computed in registers, the compiler then merges the two in registers, instead of
/// storing the register one to memory and loading it back on every evaluation (which
/// measurably slowed down evaluation loops). For exact scalars, a plain move.
#[inline(always)]
pub(crate) fn in_registers<S: Scalar, const D: usize>(p: Point<S, D>) -> Point<S, D> {
    if S::EXACT {
        p
    } else {
        Point(std::array::from_fn(|i| p.0[i].clone()))
    }
}

/// Horner's nesting of degree 1, `b₀u + b₁t` (u = 1 − t).
#[inline(always)]
pub(crate) fn horner_line<S: Scalar, const D: usize>(
    b0: &Point<S, D>,
    b1: &Point<S, D>,
    t: &S,
    u: &S,
) -> Point<S, D> {
    b0.clone() * u + &(b1.clone() * t)
}

/// Horner's nesting of degree 2, `(b₀u + 2t b₁)u + (b₂t)t` (u = 1 − t).
///
/// The point b₂ is multiplied by t twice rather than by t²: t² alone leaves the range of
/// `f64` where b₂t² need not (t² is 0 for |t| below 1.5e-162 even when b₂ is 1e300, ∞ for
/// |t| above 1.3e154 even when b₂ is 0), while (b₂t)t underflows or overflows only where the
/// term itself does.
#[inline(always)]
pub(crate) fn horner_quadratic<S: Scalar, const D: usize>(
    b0: &Point<S, D>,
    b1: &Point<S, D>,
    b2: &Point<S, D>,
    t: &S,
    u: &S,
) -> Point<S, D> {
    let two_t = S::from_i64(2) * t;
    (b0.clone() * u + &(b1.clone() * two_t)) * u + &(b2.clone() * t * t)
}

/// Horner's nesting of degree 3 from both ends, `(b₀u + c₁t)u·u + (c₂u + b₃t)t·t`
/// (u = 1 − t) with the scaled points c₁ = 3b₁ and c₂ = 3b₂: the lower half nested in u,
/// the upper in t.
///
/// No power of t or u is formed on its own, so nothing leaves the range of `f64` unless a
/// term itself does (the one-sided nesting `((b₀u + c₁t)u + c₂t²)u + b₃t³` lost c₂t² at
/// t = 1.76e-243, where t² is 0 but 3b₂t² is 1e-264 for b₂ = 1.13e221). The price: two
/// more multiplications per coordinate than the one-sided nesting with t² and t³ formed once;
/// the two halves are independent chains.
#[inline(always)]
pub(crate) fn horner_cubic<S: Scalar, const D: usize>(
    b0: &Point<S, D>,
    c1: &Point<S, D>,
    c2: &Point<S, D>,
    b3: &Point<S, D>,
    t: &S,
    u: &S,
) -> Point<S, D> {
    let low = b0.clone() * u + &(c1.clone() * t);
    let high = c2.clone() * u + &(b3.clone() * t);
    low * u * u + &(high * t * t)
}

/// The bound on |t| stored in a curve: for |t| at most this value, every intermediate of
/// Horner's scheme ([`Bezier::horner_unchecked`], closed forms and loop) is finite in `f64`.
/// Negative when no parameter is safe; irrelevant (+∞) for exact scalars.
///
/// Why: with M' = max(1, largest |coordinate|) and w = |t| + |1 − t| ≥ 1, the partial sums
/// Σⱼ C(n, j) tʲ (1 − t)ⁱ⁻ʲ bⱼ of the nesting (and those of the mirrored nesting, t and
/// 1 − t swapped, and the cubic's halves and their products with t or 1 − t), the scalars
/// C(n, i) tⁱ (or C(n, i) (1 − t)ⁱ) and the ratio recurrence's C(n, i − 1)(n − i + 1) are
/// all at most (n + 1) 2ⁿ M' wⁿ, as w is symmetric in t and 1 − t, so
/// `2ⁿ⁺¹ (n + 1) M' wⁿ ≤ f64::MAX` leaves a factor 2 for rounding. With K = f64::MAX /
/// (2ⁿ⁺¹ (n + 1) M') ≥ 1 and W = 2^⌊⌊log₂ K⌋ / n⌋ (so Wⁿ ≤ K, read off K's exponent: no
/// `powf` on the way, as curves are built by the thousand when flattening or intersecting),
/// it holds for |t| ≤ (W − 1)/2, since w ≤ 2|t| + 1. Degree 0 evaluates to b₀ for any
/// finite t.
pub(super) fn horner_limit<S: Scalar, const D: usize>(control: &[Point<S, D>]) -> f64 {
    let n = control.len() - 1;
    if S::EXACT {
        return f64::INFINITY;
    }
    if n == 0 {
        return f64::MAX;
    }
    let mut m = 1.0f64;
    for p in control {
        for c in p.coords() {
            m = m.max(c.to_f64().abs());
        }
    }
    // 2^(n+1) is +∞ for n ≥ 1023, and then K = 0.
    let k = f64::MAX / (2f64.powi((n + 1).min(2000) as i32) * (n + 1) as f64 * m);
    if k < 1.0 {
        return -1.0;
    }
    // K ≥ 1 is a normal double: its exponent field is ⌊log₂ K⌋ + 1023.
    let log2_k = (k.to_bits() >> 52) as usize - 1023;
    let w = f64::from_bits(((log2_k / n + 1023) as u64) << 52);
    (w - 1.0) / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::Rng;

    /// Deterministic coordinates of magnitude up to `m`, both signs, some zero.
    fn polygon(n: usize, m: f64, seed: u64) -> Vec<Point<f64, 2>> {
        let mut rng = Rng::new(seed);
        let mut next = || {
            let s = rng.next_u64();
            let r = (s >> 11) as f64 / (1u64 << 53) as f64;
            if s % 7 == 0 {
                0.0
            } else {
                (2.0 * r - 1.0) * m
            }
        };
        (0..=n).map(|_| Point::new([next(), next()])).collect()
    }

    #[test]
    fn no_horner_step_overflows_within_the_bound() {
        let magnitudes = [0.0, 1e-300, 1.0, 1e10, 1e100, 1e250, 1e300, 1e306, f64::MAX];
        let degrees = (1..=12).chain([20, 40, 63, 64, 65, 100, 300, 1000, 1030]);
        let mut fast = 0;
        for n in degrees {
            for (k, &m) in magnitudes.iter().enumerate() {
                let b = Bezier::new(polygon(n, m, (n * 31 + k) as u64)).unwrap();
                let limit = b.horner_limit;
                if limit < 0.0 {
                    continue;
                }
                fast += 1;
                for t in [
                    limit,
                    -limit,
                    limit * 0.999,
                    -limit * 0.5,
                    0.0,
                    0.5,
                    1.0,
                    -1.0,
                ] {
                    if t.abs() > limit {
                        continue;
                    }
                    assert!(b.horner_is_safe(&t), "n = {n}, M = {m}, t = {t}");
                    let p = b.horner_unchecked(&t, &mut NoCount);
                    assert!(p.is_finite(), "n = {n}, M = {m}, t = {t}: {p:?}");
                }
                // Just past the bound the fast path is not taken.
                let beyond = limit * 1.01 + 1e-300;
                assert!(!b.horner_is_safe(&beyond) && !b.horner_is_safe(&-beyond));
            }
        }
        assert!(
            fast > 100,
            "the bound should admit most of these curves, got {fast}"
        );
        assert!(!Bezier::new(polygon(3, 1.0, 1))
            .unwrap()
            .horner_is_safe(&f64::NAN));
        assert!(!Bezier::new(polygon(0, 1.0, 1))
            .unwrap()
            .horner_is_safe(&f64::INFINITY));
    }

    #[test]
    fn the_bound_admits_every_usual_parameter() {
        // A cubic in the unit square: everything up to |t| ≈ 1e100 is on the fast path.
        assert!(Bezier::new(polygon(3, 1.0, 5)).unwrap().horner_limit > 1e100);
        // Degree 63 (the last tabulated row) in a box of size 1e6 still covers [−100, 100].
        assert!(Bezier::new(polygon(63, 1e6, 5)).unwrap().horner_limit > 100.0);
        // Coordinates near the top of the range: only the checked path.
        assert!(Bezier::new(polygon(3, 1e307, 5)).unwrap().horner_limit < 0.0);
        // Exact scalars never overflow; a constant curve ignores t.
        assert_eq!(horner_limit::<f64, 1>(&[Point::new([f64::MAX])]), f64::MAX);
    }

    #[test]
    fn polygons_keep_their_points_and_cubics_their_scaled_points() {
        for n in 0..8 {
            let pts = polygon(n, 10.0, n as u64);
            let b = Bezier::new(pts.clone()).unwrap();
            assert_eq!(b.control(), &pts[..]);
            assert_eq!(b.clone().into_control(), pts);
            assert_eq!(format!("{b:?}"), format!("Bezier {{ control: {pts:?} }}"));
            let inline = !matches!(b.control, Polygon::Other(_));
            assert_eq!(inline, (1..=3).contains(&n), "n = {n}");
            if let Some([b0, c1, c2, b3]) = b.cubic_horner_points() {
                assert_eq!(
                    [*b0, *c1, *c2, *b3],
                    [pts[0], pts[1] * 3.0, pts[2] * 3.0, pts[3]]
                );
            }
        }
    }
}
