//! Boehm's knot insertion: the same curve on a knot vector with one more knot, inserted once
//! or r times.
//!
//! The problem: the control points of s on the refined knots t₀, …, t_μ, û, t_{μ+1}, … The
//! idea: by the fundamental theorem the new control points are blossom values, and only d of
//! them change: ĉ_j = (1 − α_j) c_{j−1} + α_j c_j with α_j = (û − t_j)/(t_{j+d} − t_j) for
//! j = μ − d + 1, …, μ, the others are copied [PPB, §6.1]. These are the second column of de
//! Boor's scheme at û; inserting û r times gives the border c^1_{μ−d+1}, …, c^r_{μ−d+r}, …,
//! c^r_{μ−s}, …, c^1_{μ−s} of the first r columns (s the multiplicity û already has), so the
//! r-fold insertion runs r levels of de Boor's scheme once instead of r single insertions.
//!
//! Knots are compared exactly: a knot a few ulps from an existing one is a new knot, and a knot
//! equal to one raises its multiplicity, up to d. Beyond d the curve would lose continuity at
//! the knot, so that is refused with an error.
//!
//! Follows [PPB, §6.1] (Boehm's algorithm, the insertion as a column of de Boor's scheme,
//! Obs. 1), [SPL, §9] (insertion by the polar form, eq. (18)), and the r-fold arrangement of
//! Piegl and Tiller, *The NURBS Book* (2nd ed., 1997), Algorithm A5.1.
//!
//! # Complexity
//!
//! Θ(n + r) copies and exactly r(d − s) − r(r − 1)/2 affine combinations for r insertions
//! of a knot of multiplicity s (d for a single new knot): Θ((n + d + rd)D) time and space.
//!
//! Invariants the tests check (exactly on rationals): the curve is unchanged at every
//! parameter, single and repeated insertions agree, and the knots gain exactly r copies of û.

use super::de_boor::de_boor_level;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::{Error, Result};

/// Boehm's knot insertion, declared.
pub(crate) const INSERT: Declaration = Declaration {
    problem: "bspline",
    name: "insert",
    function: "spline::BSpline::insert",
    file: "src/spline/bspline/insert.rs",
    summary: "the same curve with a knot inserted r times, by r levels of de Boor's scheme",
    time: "Θ((n + d + rd)D)",
    space: "O((n + d + r)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly r(d − s) − r(r − 1)/2 affine combinations, s the knot's multiplicity before",
    source: "[PPB, §6.1]",
    claims: &[on(
        "random-degree",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The same curve with the knot `u` inserted `times` times. See [`BSpline::insert_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u` is NaN, infinite or outside the domain;
    /// [`Error::InvalidParameter`] named `"times"` if the multiplicity of `u` would exceed the
    /// degree (naming both); [`Error::LimitExceeded`] beyond
    /// [`MAX_KNOTS`](crate::limits::MAX_KNOTS). No overflow: every new control point is a
    /// convex combination of old ones, and with `f64` one that would round past `f64::MAX`
    /// is clamped between its two points, where the exact value lies.
    ///
    /// # Complexity
    ///
    /// Θ((n + d + rd)D) time, O((n + d + r)D) space for the new curve (r = `times`).
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?; // a Bézier parabola
    /// let c = vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([2.0, 0.0])];
    /// let s = BSpline::new(c, t)?;
    /// let r = s.insert(&0.5, 2)?; // subdivision: the two halves' Bézier points
    /// assert_eq!(r.knots().knots(), [0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0]);
    /// assert_eq!(r.control()[2], Point::new([1.0, 1.0]));
    /// assert_eq!(r.eval(&0.3)?, s.eval(&0.3)?);
    /// let e = r.insert(&0.5, 1).unwrap_err(); // multiplicity 3 would break the curve
    /// assert!(e.to_string().contains("multiplicity 3, more than the degree 2"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn insert(&self, u: &S, times: usize) -> Result<Self> {
        self.insert_with(u, times, &mut NoCount)
    }

    /// The same curve with the knot `u` inserted `times` times, counting the affine
    /// combinations.
    ///
    /// Idea: find the span μ of u (t_μ ≤ u < t_{μ+1}, the last non-empty span at the end of
    /// the domain) and the multiplicity s of u as the knot t_μ (0 if u lies inside the span).
    /// Keep c₀, …, c_{μ−d} and, shifted by r, c_{μ−s}, …, c_{n−1}; run r levels of de Boor's
    /// scheme on c_{μ−d}, …, c_{μ−s} with the weights α = (u − tᵢ)/(t_{i+d+1−k} − tᵢ) (as
    /// two ratios of knot distances, both in [0, 1]) and take the first and last point of
    /// each level, and the last level's middle, as the new control points [PPB, §6.1].
    /// `times = 0` returns the curve unchanged. The knot may be anywhere in the domain,
    /// a few ulps from an existing knot (a new knot, with its own tiny span) or equal to one
    /// (its multiplicity rises), as long as the multiplicity stays at most d.
    ///
    /// Follows [PPB, §6.1] and [SPL, §9, eq. (18)].
    ///
    /// # Errors
    ///
    /// As [`BSpline::insert`].
    ///
    /// # Complexity
    ///
    /// Θ((n + d + rd)D) time, O((n + d + r)D) space (r = `times`).
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// exactly r(d − s) − r(r − 1)/2, where s is the multiplicity of u before as the knot
    /// t_μ (0 for a new knot, so d for a single insertion, and 0 at the end of the domain,
    /// whose copies lie above the span), and the span search's
    /// [`comparison`](Counter::comparison)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(3, 6, 0.0, 3.0)?;
    /// let s = BSpline::new((0..6).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// let r = s.insert_with(&0.5, 1, &mut c)?;
    /// assert_eq!((c.arithmetic_operations, r.control().len()), (3, 7));
    /// let mut c = Counts::default();
    /// s.insert_with(&1.0, 2, &mut c)?; // an existing simple knot, twice: 2·2 − 1
    /// assert_eq!(c.arithmetic_operations, 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn insert_with<C: Counter>(&self, u: &S, times: usize, counter: &mut C) -> Result<Self> {
        let knots = self.knots();
        let span = knots.span_with(u, counter)?;
        if times == 0 {
            return Ok(self.clone());
        }
        let d = self.degree();
        let existing = knots.multiplicity(u);
        if existing as u128 + times as u128 > d as u128 {
            return Err(Error::InvalidParameter {
                name: "times",
                reason: format!(
                    "inserting {} {times} times gives multiplicity {}, more than the degree \
                     {d} (the curve would break there)",
                    u.to_f64(),
                    existing as u128 + times as u128
                ),
            });
        }
        crate::limits::KNOTS.check(knots.knots().len() as u128 + times as u128)?;
        let t = knots.knots();
        // s counts the copies of u at or below the span (none when u is inside it, or at the
        // closed end of the domain, where the copies lie above it).
        let s = if t[span] == *u { existing } else { 0 };
        let r = times;
        let n = self.control().len();
        let old = self.control();

        // New points: c₀, …, c_{μ−d}; the first point of levels 1, …, r − 1; the whole level
        // r; the last point of levels r − 1, …, 1; c_{μ−s}, …, c_{n−1} (n + r in all). The
        // scheme runs in place on c_{μ−d}, …, c_{μ−s} at the end of the new points: a level
        // k writes only its own points q[k..=m], so q[k − 1] keeps the first point of level
        // k − 1 and the front border builds itself; the back border is saved level by level.
        let mut control: Vec<Point<S, D>> = Vec::with_capacity(n + r);
        control.extend_from_slice(&old[..=span - s]);
        let m = d - s;
        let q = &mut control[span - d..];
        let mut tail = Vec::with_capacity(r - 1);
        for k in 1..=r {
            de_boor_level(t, d, span, k, u, q, counter);
            if k < r {
                tail.push(q[m].clone());
            }
        }
        control.extend(tail.into_iter().rev());
        control.extend_from_slice(&old[span - s..]);

        let mut new_knots = Vec::with_capacity(t.len() + r);
        new_knots.extend_from_slice(&t[..=span]);
        new_knots.extend(std::iter::repeat_n(u.clone(), r));
        new_knots.extend_from_slice(&t[span + 1..]);
        // Valid by construction: u is finite and in the domain, at or after t_μ and before
        // t_{μ+1} (or at the closed end), its multiplicity stays at most d, the count is
        // within the limit, and the domain [t_d, t_n] keeps both ends (μ ≥ d, μ < n).
        let new_knots = KnotVector::valid_by_construction(d, new_knots);
        // Only the r(d − s) − r(r − 1)/2 computed points can have overflowed: they are
        // c_{μ−d+1}, …, c_{μ−s+r−1} of the new polygon; the others are copies of valid ones.
        BSpline::derived_in(
            control,
            new_knots,
            span - d + 1..span - s + r,
            "knot insertion",
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::Curve;

    #[test]
    fn a_knot_next_to_an_existing_one_is_really_inserted() {
        let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0]).unwrap();
        let c = [0.0, 1.0, 3.0, 2.0, 5.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        let next = f64::from_bits(1.0f64.to_bits() + 1);
        let r = s.insert(&next, 1).unwrap();
        assert_eq!(r.knots().knots().len(), 9);
        assert_eq!(r.knots().multiplicity(&next), 1);
        for u in [0.0, 0.5, 1.0, next, 1.5, 2.0] {
            let (a, b) = (s.eval(&u).unwrap()[0], r.eval(&u).unwrap()[0]);
            assert!((a - b).abs() <= 1e-15 * a.abs().max(1.0), "{u}: {a} vs {b}");
        }
        let e = s.insert(&1.0, 1).unwrap_err();
        assert!(
            matches!(e, Error::InvalidParameter { name: "times", .. }),
            "{e}"
        );
        assert!(s.insert(&2.5, 1).is_err());
        assert_eq!(s.insert(&0.5, 0).unwrap(), s);
    }
}
