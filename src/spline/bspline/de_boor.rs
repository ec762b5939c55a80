//! De Boor's algorithm: the point s(u) of a B-spline curve by repeated affine combinations of
//! its control points, and its trace (the de Boor net, level by level).
//!
//! The problem: the point s(u) = Σ cᵢ Nᵢ(u) without computing the basis. The idea: on the span
//! t_μ ≤ u < t_{μ+1} only c_{μ−d}, …, c_μ matter, and the recursion of the basis regroups the
//! sum into d levels of affine combinations
//! c_i^k = (1 − α) c_{i−1}^{k−1} + α c_i^{k−1}, α = (u − tᵢ)/(t_{i+d+1−k} − tᵢ),
//! i = μ − d + k, …, μ, until the one point c_μ^d = s(u) is left [PPB, §5.4]. Each α lies in
//! [0, 1], so every step is a convex combination. At a knot u = t_μ of multiplicity r the
//! points c_{μ−r+1}, …, c_μ have basis functions that vanish at u, and the scheme stops r
//! levels early: c_{μ−r}^{d−r} = s(u) (with r ≥ d, the control point c_{μ−d} itself).
//!
//! Follows [PPB, §5.4] (the algorithm and its triangular scheme), [SPL, §5, §7] (de Boor's
//! algorithm as repeated de Casteljau steps on the polar form) and [PPB, §6.1] (its columns
//! are the control points after inserting u).
//!
//! # Complexity
//!
//! Θ(d²D) per point after the O(log(n − d)) span search: exactly d(d + 1)/2 affine
//! combinations when u is not a knot, (d − r)(d − r + 1)/2 at a knot of multiplicity r;
//! O(dD) auxiliary space (O(d²D) for the trace).
//!
//! Invariants the tests check (exactly on rationals): de Boor equals Σ cᵢ Nᵢ(u) from the basis
//! at every parameter, the counts above, and the net's last point is the curve's.

use super::BSpline;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, Counts, NoCount, Operation};
use crate::spline::bspline::basis::affine;
use crate::spline::scalar::{Point, Scalar};
use crate::trace::{Frame, NoObserver, Observer, Recorder, TraceSize};
use crate::Result;

/// De Boor's evaluation, declared.
pub(crate) const DE_BOOR: Declaration = Declaration {
    problem: "bspline",
    name: "de-boor",
    function: "spline::BSpline::de_boor",
    file: "src/spline/bspline/de_boor.rs",
    summary: "the point of a B-spline curve by repeated affine combinations of d + 1 control points",
    time: "Θ(d²D)",
    space: "O(dD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly d(d + 1)/2 affine combinations per point off the knots, (d − r)(d − r + 1)/2 at a knot of multiplicity r",
    source: "[PPB, §5.4]",
    claims: &[on("random-degree", Bound::Quadratic, Operation::ArithmeticOperations), on("random-control", Bound::Log, Operation::Comparisons)],
};

/// One level of de Boor's scheme at one parameter (a row of the de Boor net, as the course
/// draws it [PPB, §5.4, Fig. 5.6]), as [`BSpline::de_boor_trace`] records it.
///
/// Level k holds the points c_i^k for i = μ − d + k, …, μ − r (μ the span, r the
/// multiplicity of u as a knot, at most d): level 0 is the control points the parameter
/// depends on, the last level d − r the single point s(u). By [PPB, §6.1] the first and the
/// last point of each level are the new control points after inserting u.
///
/// ```
/// use compgeo::spline::{BSpline, KnotVector, Point};
///
/// // The uniform quadratic on 0, 1, …, 5 at u = 2.5: levels 0, 1 and 2.
/// let t = KnotVector::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0])?;
/// let c = vec![Point::new([0.0]), Point::new([4.0]), Point::new([8.0])];
/// let frames = BSpline::new(c, t)?.de_boor_trace(&2.5)?;
/// let level = &frames[1].step;
/// assert_eq!((level.level, level.span, level.multiplicity, level.first()), (1, 2, 0, 1));
/// assert_eq!(level.points, [Point::new([3.0]), Point::new([5.0])]);
/// assert_eq!(frames[2].step.points, [Point::new([4.0])]);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct DeBoorLevel<S, const D: usize> {
    /// The level k, from 0 (the control points c_{μ−d}, …, c_{μ−r}) to d − r (the point
    /// s(u)).
    pub level: usize,
    /// The span μ of the parameter (t_μ ≤ u < t_{μ+1}, or the last non-empty span at t_n).
    pub span: usize,
    /// The multiplicity r of u as the knot t_μ (0 when u is not a knot, and at the end of
    /// the domain), at most d: the levels the scheme skips.
    pub multiplicity: usize,
    /// The d − r + 1 − k points c^k_{μ−d+k}, …, c^k_{μ−r} of the level.
    pub points: Vec<Point<S, D>>,
}

impl<S, const D: usize> DeBoorLevel<S, D> {
    /// The index i of the level's first point c_i^k: μ − d + k (at level 0, the index of the
    /// first control point the point s(u) depends on).
    ///
    /// ```
    /// # use compgeo::spline::{BSpline, KnotVector, Point};
    /// let s = BSpline::new(vec![Point::new([0.0]); 3], KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?)?;
    /// let frames = s.de_boor_trace(&1.5)?;
    /// assert_eq!((frames[0].step.first(), frames[1].step.first()), (1, 2));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn first(&self) -> usize {
        self.span + 1 - self.multiplicity - self.points.len()
    }
}

impl<S, const D: usize> TraceSize for DeBoorLevel<S, D> {
    fn entries(&self) -> usize {
        self.points.len()
    }
}

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The point s(u) by de Boor's algorithm. See [`BSpline::de_boor_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"u"` if `u` is NaN,
    /// infinite or outside the domain [t_d, t_n].
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time after the O(log(n − d)) span search, O(dD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0])?;
    /// let c = vec![Point::new([0.0]), Point::new([4.0]), Point::new([8.0])];
    /// let s = BSpline::new(c, t)?;
    /// assert_eq!(s.de_boor(&2.0)?, Point::new([2.0])); // at a knot: the midpoint of c₀c₁
    /// assert!(s.de_boor(&1.5).is_err()); // outside [t₂, t₃] = [2, 3]
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_boor(&self, u: &S) -> Result<Point<S, D>> {
        self.de_boor_with(u, &mut NoCount)
    }

    /// The point s(u) by de Boor's algorithm, counting its affine combinations.
    ///
    /// Idea: find the span μ, copy c_{μ−d}, …, c_{μ−r} (r the multiplicity of u as the knot
    /// t_μ, 0 if u is not a knot, at most d) and replace them level by level by the affine
    /// combinations c_i^k = (1 − α) c_{i−1}^{k−1} + α c_i^{k−1} with
    /// α = (u − tᵢ)/(t_{i+d+1−k} − tᵢ), each weight computed as its own ratio of two knot
    /// distances (both in [0, 1], so knots a subnormal distance apart do not overflow). With
    /// `f64` a combination of two coordinates near `f64::MAX` that rounds past it is clamped
    /// back between them, where the exact value lies, so the point is always finite. At
    /// the end of the domain the last non-empty span is used (the closed last interval), and
    /// at an interior knot the span on its right (right-continuous).
    ///
    /// Follows [PPB, §5.4].
    ///
    /// # Errors
    ///
    /// As [`BSpline::de_boor`].
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time after the O(log(n − d)) span search: exactly d(d + 1)/2 affine combinations
    /// when u is not a knot (and at the end of the domain), (d − r)(d − r + 1)/2 at a knot of
    /// multiplicity r (so d(d − 1)/2 at a simple knot and none at a knot of multiplicity d);
    /// O(dD) auxiliary space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination, and
    /// the span search's [`comparison`](Counter::comparison)s
    /// ([`KnotVector::span_with`](super::KnotVector::span_with)).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::uniform(3, 8, 0.0, 1.0)?;
    /// let s = BSpline::new((0..8).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// s.de_boor_with(&0.3, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 6); // 3·4/2
    /// let mut c = Counts::default();
    /// s.de_boor_with(&0.4, &mut c)?; // a simple knot: one level fewer
    /// assert_eq!(c.arithmetic_operations, 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_boor_with<C: Counter>(&self, u: &S, counter: &mut C) -> Result<Point<S, D>> {
        let (span, r) = self.locate(u, counter)?;
        // Up to degree 5 the d − r + 1 points of the scheme live in an array of exactly that
        // length on the stack: an allocation per point cost more than the arithmetic of a
        // cubic. The arithmetic, and so every result, is the same on both paths.
        Ok(match self.degree() - r {
            0 => self.de_boor_on_stack::<1, C>(span, r, u, counter),
            1 => self.de_boor_on_stack::<2, C>(span, r, u, counter),
            2 => self.de_boor_on_stack::<3, C>(span, r, u, counter),
            3 => self.de_boor_on_stack::<4, C>(span, r, u, counter),
            4 => self.de_boor_on_stack::<5, C>(span, r, u, counter),
            5 => self.de_boor_on_stack::<6, C>(span, r, u, counter),
            m => {
                let mut q = self.window(span, r);
                self.de_boor_levels(span, r, u, &mut q, counter, &mut NoObserver);
                q.swap_remove(m)
            }
        })
    }

    /// The scheme of [`BSpline::de_boor_with`] on an array of the N = d − r + 1 points of
    /// level 0 (the caller matches N to the span and multiplicity).
    #[inline]
    fn de_boor_on_stack<const N: usize, C: Counter>(
        &self,
        span: usize,
        r: usize,
        u: &S,
        counter: &mut C,
    ) -> Point<S, D> {
        let window = &self.control()[span - self.degree()..=span - r];
        let mut q: [Point<S, D>; N] = std::array::from_fn(|j| window[j].clone());
        self.de_boor_levels(span, r, u, &mut q, counter, &mut NoObserver);
        q.into_iter().next_back().expect("N = d − r + 1 ≥ 1 points")
    }

    /// The frames of de Boor's algorithm at `u`: the de Boor net, level by level, from its
    /// own run.
    ///
    /// The run is [`BSpline::de_boor_with`]'s, told about each level: frame k holds level k
    /// ([`DeBoorLevel`]; frame 0 the d − r + 1 control points that matter, found by the span
    /// search, the last frame d − r the single point s(u)), with the comparisons of the span
    /// search and the affine combinations counted up to it; the last frame's counts are
    /// those of [`BSpline::de_boor_with`] with [`Counts`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::de_boor`]; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if
    /// the (d + 1)(d + 2)/2 points and d + 1 frames pass
    /// [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES).
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time and space (the (d + 1)(d + 2)/2 points of the net) after the
    /// O(log(n − d)) span search.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?; // a Bézier parabola
    /// let c = vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([2.0, 0.0])];
    /// let s = BSpline::new(c, t)?;
    /// let frames = s.de_boor_trace(&0.5)?;
    /// assert_eq!(frames.len(), 3);
    /// assert_eq!(frames[1].step.points, [Point::new([0.5, 1.0]), Point::new([1.5, 1.0])]);
    /// assert_eq!(frames[2].step.points, [Point::new([1.0, 1.0])]);
    /// let mut counts = Counts::default();
    /// s.de_boor_with(&0.5, &mut counts)?;
    /// assert_eq!(frames[2].counts, counts);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_boor_trace(&self, u: &S) -> Result<Vec<Frame<DeBoorLevel<S, D>>>> {
        let mut counts = Counts::default();
        let (span, r) = self.locate(u, &mut counts)?;
        let mut recorder = Recorder::new();
        let mut q = self.window(span, r);
        recorder.step(&counts, || DeBoorLevel {
            level: 0,
            span,
            multiplicity: r,
            points: q.clone(),
        });
        self.de_boor_levels(span, r, u, &mut q, &mut counts, &mut recorder);
        recorder.finish()
    }

    /// The span μ of `u` (checked) and the multiplicity r ≤ d of u as the knot t_μ.
    fn locate<C: Counter>(&self, u: &S, counter: &mut C) -> Result<(usize, usize)> {
        let span = self.knots().span_with(u, counter)?;
        let t = self.knots().knots();
        let d = self.degree();
        let r = (0..d).take_while(|&j| t[span - j] == *u).count();
        Ok((span, r))
    }

    /// The control points c_{μ−d}, …, c_{μ−r} of level 0.
    fn window(&self, span: usize, r: usize) -> Vec<Point<S, D>> {
        let d = self.degree();
        self.control()[span - d..=span - r].to_vec()
    }

    /// Runs levels 1, …, d − r of the scheme on `q` (level 0, d − r + 1 points), telling
    /// `obs` about each level; `q[k..]` holds level k afterwards, so the last point of `q`
    /// is s(u).
    #[inline]
    fn de_boor_levels<C: Counter, O: Observer<DeBoorLevel<S, D>, C>>(
        &self,
        span: usize,
        r: usize,
        u: &S,
        q: &mut [Point<S, D>],
        counter: &mut C,
        obs: &mut O,
    ) {
        let d = self.degree();
        let t = self.knots().knots();
        let m = d - r; // levels to run
        debug_assert_eq!(q.len(), m + 1);
        for k in 1..=m {
            de_boor_level(t, d, span, k, u, q, counter);
            obs.step(counter, || DeBoorLevel {
                level: k,
                span,
                multiplicity: r,
                points: q[k..].to_vec(),
            });
        }
    }
}

/// Level `k` of the de Boor scheme in place, shared by evaluation and insertion: with
/// `q[k − 1..]` holding level k − 1 of the points c_{μ−d+k−1}, … (μ = `span`, degree `d`),
/// afterwards `q[k..]` holds level k. It goes down so each combination reads level k − 1;
/// one affine combination (counted) per point.
pub(super) fn de_boor_level<S: Scalar, const D: usize, C: Counter>(
    t: &[S],
    d: usize,
    span: usize,
    k: usize,
    u: &S,
    q: &mut [Point<S, D>],
    counter: &mut C,
) {
    for j in (k..q.len()).rev() {
        let i = span - d + j;
        let (lo, hi) = (&t[i], &t[i + d + 1 - k]);
        q[j] = affine(&q[j - 1], lo, u, hi, &q[j]);
        counter.arithmetic_operation();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;
    use crate::spline::KnotVector;

    #[test]
    fn counts_drop_with_the_multiplicity_of_the_knot() {
        // Degree 3 with knots of multiplicity 1, 2, 3 at 1, 2, 3.
        let t = KnotVector::new(
            3,
            vec![
                0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0, 4.0, 4.0, 4.0, 4.0,
            ],
        )
        .unwrap();
        let s = BSpline::new((0..10).map(|i| Point::new([i as f64])).collect(), t).unwrap();
        for (u, ops) in [(0.5, 6), (1.0, 3), (2.0, 1), (3.0, 0), (3.5, 6), (4.0, 6)] {
            let mut c = Counts::default();
            s.de_boor_with(&u, &mut c).unwrap();
            assert_eq!(c.arithmetic_operations, ops, "u = {u}");
            let frames = s.de_boor_trace(&u).unwrap();
            let last = &frames[frames.len() - 1];
            assert_eq!(last.step.points, [s.de_boor(&u).unwrap()]);
            assert_eq!(frames.len(), 4 - last.step.multiplicity);
            assert_eq!(last.counts.arithmetic_operations, ops);
        }
        // At the triple knot the curve passes through c_{μ−3}.
        assert_eq!(s.de_boor(&3.0).unwrap(), Point::new([6.0]));
        assert_eq!(s.de_boor(&4.0).unwrap(), Point::new([9.0]));
    }

    #[test]
    fn knots_of_multiplicity_d_plus_one_take_the_right_piece() {
        let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0]).unwrap();
        let c = [0.0, 1.0, 5.0, 6.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        assert_eq!(s.de_boor(&1.0).unwrap(), Point::new([5.0]));
        let frames = s.de_boor_trace(&1.0).unwrap();
        let level = &frames[0].step;
        assert_eq!((level.span, level.multiplicity, level.first()), (3, 1, 2));
    }
}
