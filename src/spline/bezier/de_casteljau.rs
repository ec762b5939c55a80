//! De Casteljau's algorithm and what its triangle gives besides the point: subdivision at
//! any parameter, the blossom (polar form), and restriction to any interval by blossoming.
//!
//! The problem: the point b(t) of a Bézier curve, and the control points of the same
//! polynomial over another interval. The idea: repeated linear interpolation of the control
//! polygon, `bᵢᵏ⁺¹ = (1 − t) bᵢᵏ + t bᵢ₊₁ᵏ`, until one point is left; with a different
//! parameter at each level the scheme computes the blossom `b[u₁, …, uₙ]`, whose values at
//! `a, …, a, b, …, b` are the Bézier points over [a, b] (the fundamental theorem), and the
//! two borders of one triangle are the control polygons of the two halves at t.
//!
//! Follows [PPB, §2.3] (the algorithm), [PPB, §3.1–3.3] (the blossom, the fundamental
//! theorem, subdivision) and [RD, §3.2] ("Algoritmo de De Casteljau").
//!
//! # Complexity
//!
//! Θ(n²D) for a point, a split or a blossom value of a curve of degree n in R^D; Θ(n³D) for
//! a restriction (n + 1 blossom values); O(nD) auxiliary space.
//!
//! Invariants the tests check (exactly on rationals): de Casteljau = Horner = the Bernstein
//! sum, split pieces evaluate to the original, the blossom is symmetric, multi-affine, equals
//! the curve on its diagonal and gives the control points at 0s and 1s.

use super::curve::Bezier;
use super::reparametrised::Reparametrised;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, Counts, NoCount, Operation};
use crate::spline::curve::{check_interval, Curve, Subsegment};
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::trace::{Frame, NoObserver, Observer, Recorder, TraceSize};
use crate::{Error, Result};

/// One level of de Casteljau's scheme (its scaffolding at one parameter), as
/// [`Bezier::de_casteljau_trace`] records it.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct CasteljauLevel<S, const D: usize> {
    /// The level k, from 0 (the control polygon) to the degree n (the point b(t)).
    pub level: usize,
    /// The n + 1 − k points b₀ᵏ, …, bₙ₋ₖᵏ of the level.
    pub points: Vec<Point<S, D>>,
}

impl<S, const D: usize> TraceSize for CasteljauLevel<S, D> {
    fn entries(&self) -> usize {
        self.points.len()
    }
}

/// The split's [`Declaration`]: its name, bounds, counts, source and claims.
pub(crate) const SPLIT: Declaration = Declaration {
    problem: "bezier",
    name: "split",
    function: "spline::Bezier::split",
    file: "src/spline/bezier/de_casteljau.rs",
    summary: "the two halves at c, read off de Casteljau's triangle",
    time: "Θ(n²D)",
    space: "O(nD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)/2 affine combinations (one triangle)",
    source: "[PPB, §3.3]",
    claims: &[on(
        "random-degree",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

/// The blossom's [`Declaration`]: its name, bounds, counts, source and claims.
pub(crate) const BLOSSOM: Declaration = Declaration {
    problem: "bezier",
    name: "blossom",
    function: "spline::Bezier::blossom",
    file: "src/spline/bezier/de_casteljau.rs",
    summary: "the polar form by de Casteljau's scheme with distinct parameters",
    time: "Θ(n²D)",
    space: "O(nD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)/2 affine combinations per value",
    source: "[PPB, §3.2]",
    claims: &[on(
        "random-degree",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

/// De Casteljau's evaluation, declared: its name, bounds, counts, source and claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "bezier",
    name: "de-casteljau",
    function: "spline::Bezier::de_casteljau",
    file: "src/spline/bezier/de_casteljau.rs",
    summary: "repeated affine combinations of the control points",
    time: "Θ(n²D)",
    space: "O(nD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)/2 affine combinations per point",
    source: "[PPB, §2.3]",
    claims: &[on(
        "uniform-square",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> Bezier<S, D> {
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
    /// Follows [PPB, §2.3] and [RD, §3.2] ("Algoritmo de De Casteljau").
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
        Ok(self.de_casteljau_unchecked(t, counter))
    }

    /// The frames of de Casteljau's algorithm at `t`: its scaffolding, level by level, from
    /// its own run.
    ///
    /// The run is [`Bezier::de_casteljau_with`]'s, told about each level: frame k holds the
    /// points bᵢᵏ of level k (frame 0 the control polygon, frame n the single point b(t)),
    /// with the n + (n − 1) + … + (n − k + 1) affine combinations counted up to it; the last
    /// frame's counts are those of [`Bezier::de_casteljau_with`] with [`Counts`]. The first
    /// points of the levels are the control points of the piece over [0, t], the last ones
    /// (read backwards) those over [t, 1] ([`Bezier::split`]).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN or infinite;
    /// [`Error::LimitExceeded`] if the (n + 1)(n + 2)/2 points and n + 1 frames pass
    /// [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES).
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time and space (every point of the triangle is kept).
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([2.0, 4.0]), Point::new([4.0, 0.0])])?;
    /// let frames = b.de_casteljau_trace(&0.5)?;
    /// assert_eq!(frames.len(), 3);
    /// assert_eq!(frames[1].step.points, [Point::new([1.0, 2.0]), Point::new([3.0, 2.0])]);
    /// assert_eq!(frames[2].step.points, [b.de_casteljau(&0.5)?]);
    /// assert_eq!(frames[2].counts.arithmetic_operations, 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_casteljau_trace(&self, t: &S) -> Result<Vec<Frame<CasteljauLevel<S, D>>>> {
        validate_parameter(t, "t")?;
        let mut counts = Counts::default();
        let mut recorder = Recorder::new();
        let mut q = self.control().to_vec();
        recorder.step(&counts, || CasteljauLevel {
            level: 0,
            points: q.clone(),
        });
        observed_levels(
            &mut q,
            std::iter::repeat_n(t, self.degree()),
            &mut counts,
            &mut recorder,
        );
        recorder.finish()
    }

    /// The two halves of the curve at the parameter c: the control points of the same
    /// polynomial over [0, c] and over [c, 1], each as a curve with local parameter in [0, 1].
    ///
    /// Idea: in de Casteljau's triangle for b(c), the first points of the columns are the
    /// Bézier points over [0, c] and the last ones, read backwards, those over [c, 1]. Any c
    /// works, also outside [0, 1] (then one piece extends the curve).
    ///
    /// Follows [PPB, §3.3].
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
        self.split_with(c, &mut NoCount)
    }

    /// [`Bezier::split`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of the
    /// triangle: exactly n(n + 1)/2.
    ///
    /// # Errors
    ///
    /// As [`Bezier::split`].
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, O(nD) auxiliary space besides the output.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new((0..7).map(|i| Point::new([i as f64])).collect())?;
    /// let mut c = Counts::default();
    /// b.split_with(&0.3, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 21); // 6·7/2
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_with<C: Counter>(&self, c: &S, counter: &mut C) -> Result<(Self, Self)> {
        validate_parameter(c, "c")?;
        let (left, right) = self.split_counted(c, counter);
        Ok((
            Bezier::derived(left.into_control(), "split")?,
            Bezier::derived(right.into_control(), "split")?,
        ))
    }

    /// The control points of the same polynomial over the oriented interval [a, b]: the
    /// curve t ↦ b((1 − t) a + t b). Any finite a and b (a > b reverses, a = b gives a
    /// constant curve). [`Subsegment::subsegment`] is this restriction carried over [a, b].
    ///
    /// Idea: by the fundamental theorem the Bézier points over [a, b] are the blossom values
    /// `b[a, …, a, b, …, b]` with n − i arguments a and i arguments b.
    ///
    /// Follows [PPB, §3.2].
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
        control.push(self.blossom_unchecked(&args, &mut NoCount));
        for i in 1..=n {
            args[n - i] = b.clone();
            control.push(self.blossom_unchecked(&args, &mut NoCount));
        }
        Bezier::derived(control, "restrict")
    }

    /// The blossom (polar form) `b[u₁, …, uₙ]`: the unique symmetric, multi-affine function
    /// of n arguments whose diagonal `b[u, …, u]` is b(u).
    ///
    /// Idea: de Casteljau's algorithm with a different parameter at each level:
    /// `bᵢᵏ⁺¹ = (1 − uₖ₊₁) bᵢᵏ + uₖ₊₁ bᵢ₊₁ᵏ`.
    ///
    /// Follows [PPB, §3.1–3.2] (recurrence (1) of the fundamental theorem).
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
        self.blossom_with(args, &mut NoCount)
    }

    /// [`Bezier::blossom`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// exactly n(n + 1)/2, as for a point.
    ///
    /// # Errors
    ///
    /// As [`Bezier::blossom`].
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, O(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new((0..4).map(|i| Point::new([i as f64])).collect())?;
    /// let mut c = Counts::default();
    /// b.blossom_with(&[0.0, 0.5, 1.0], &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 6); // 3·4/2
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom_with<C: Counter>(&self, args: &[S], counter: &mut C) -> Result<Point<S, D>> {
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
        Ok(self.blossom_unchecked(args, counter))
    }
}

/// The piece of a Bézier curve over [a, b] in the global parameter: [`Bezier::restrict`] to
/// [a, b], reparametrised over [a, b] (Θ(n³D)).
impl<S: Scalar, const D: usize> Subsegment<S, D> for Bezier<S, D> {
    type Segment = Reparametrised<S, D>;

    fn subsegment(&self, a: &S, b: &S) -> Result<Reparametrised<S, D>> {
        check_interval(&self.domain(), a, b)?;
        Ok(Reparametrised::new_unchecked(
            self.restrict(a, b)?,
            a.clone(),
            b.clone(),
        ))
    }
}

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// De Casteljau's algorithm without validation (t finite), counting.
    pub(super) fn de_casteljau_unchecked<C: Counter>(&self, t: &S, counter: &mut C) -> Point<S, D> {
        let mut q = self.control().to_vec();
        de_casteljau_levels(&mut q, std::iter::repeat_n(t, self.degree()), counter);
        q.swap_remove(0)
    }

    /// The split without validation (c finite), counting its n(n + 1)/2 affine combinations
    /// (one de Casteljau triangle). The pieces may have non-finite points if, with `f64`, c
    /// is far outside [0, 1]: the caller checks.
    pub(crate) fn split_counted<C: Counter>(&self, c: &S, counter: &mut C) -> (Self, Self) {
        let n = self.degree();
        let mut q = self.control().to_vec();
        let mut left = Vec::with_capacity(n + 1);
        let mut right = Vec::with_capacity(n + 1);
        left.push(q[0].clone());
        right.push(q[n].clone());
        for k in 1..=n {
            de_casteljau_levels(&mut q[..=n - k + 1], [c], counter);
            left.push(q[0].clone());
            right.push(q[n - k].clone());
        }
        right.reverse();
        (Bezier::with_control(left), Bezier::with_control(right))
    }

    /// The control points over [a, b] (a < b, both finite) by two subdivisions instead of
    /// n + 1 blossoms: the right piece at a is the curve over [a, 1], whose left piece at
    /// (b − a)/(1 − a) is the curve over [a, b] (when a = 1, the left piece at b, then its
    /// right piece at 1/b). Exactly n(n + 1) affine combinations, counted; Θ(n²D) instead of
    /// [`Bezier::restrict`]'s Θ(n³D). Non-finite points are the caller's to check.
    pub(crate) fn restrict_by_splits<C: Counter>(&self, a: &S, b: &S, counter: &mut C) -> Self {
        debug_assert!(a < b);
        if a.clone() == S::one() {
            let (left, _) = self.split_counted(b, counter);
            left.split_counted(&(S::one() / b), counter).1
        } else {
            let (_, right) = self.split_counted(a, counter);
            let t = (b.clone() - a) / (S::one() - a);
            right.split_counted(&t, counter).0
        }
    }

    /// The blossom without validation (`args.len() == n`, all finite), counting.
    fn blossom_unchecked<C: Counter>(&self, args: &[S], counter: &mut C) -> Point<S, D> {
        let mut q = self.control().to_vec();
        de_casteljau_levels(&mut q, args, counter);
        q.swap_remove(0)
    }
}

/// Runs one level of de Casteljau's scheme per parameter on the points `q`: level k replaces
/// `q[i]` by `(1 − u) q[i] + u q[i + 1]` for the first `len − k` points, so after m levels
/// `q[0..len − m]` are the points of column m. One counted operation per affine combination.
#[inline]
pub(crate) fn de_casteljau_levels<'a, S, const D: usize, C>(
    q: &mut [Point<S, D>],
    params: impl IntoIterator<Item = &'a S>,
    counter: &mut C,
) where
    S: Scalar + 'a,
    C: Counter,
{
    observed_levels(q, params, counter, &mut NoObserver);
}

/// [`de_casteljau_levels`], telling `obs` about each level it completes (its points, level
/// 1 first).
#[inline]
fn observed_levels<'a, S, const D: usize, C, O>(
    q: &mut [Point<S, D>],
    params: impl IntoIterator<Item = &'a S>,
    counter: &mut C,
    obs: &mut O,
) where
    S: Scalar + 'a,
    C: Counter,
    O: Observer<CasteljauLevel<S, D>, C>,
{
    for (k, u) in params.into_iter().enumerate() {
        for i in 0..q.len() - k - 1 {
            q[i] = Point::lerp(&q[i], &q[i + 1], u);
            counter.arithmetic_operation();
        }
        obs.step(counter, || CasteljauLevel {
            level: k + 1,
            points: q[..q.len() - k - 1].to_vec(),
        });
    }
}
