//! Knot refinement: the same curve on a knot vector with many knots added, by Boehm's
//! insertion of every new knot in one backward pass.
//!
//! The problem: the control points ĉ₀, …, ĉ_{n+m−1} of s on the refined knots τ (the old knots
//! t with m new ones merged in). The idea: [PPB, §6.2] recommends inserting the knots one at a
//! time by Boehm's rule [PPB, §6.1] — each insertion of a knot x in the span μ keeps the
//! control points up to μ − d, replaces the next d by affine combinations of neighbours, and
//! shifts the rest up by one. Inserted from the largest knot to the smallest, the shifted
//! part above each insertion never changes again, so every point can be written straight to
//! its final place: the result is filled from the top down, old control points and knots
//! above the current knot are moved up by the number of new knots still to come, and each
//! new knot costs d combinations on the points just below it. Nothing is copied twice, and no
//! intermediate curve is built. This is the arrangement of Piegl and Tiller's Algorithm A5.4
//! (read for the idea, written anew).
//!
//! Each combination is (1 − α) ĉ_{j−1} + α ĉ_j with α the local coordinate of the new knot
//! in the support of the basis function [PPB, §6.1]; where the new knot equals a knot that
//! ends that support (the knot is already there, with multiplicity), α is 0 or 1, the point
//! is a copy and no division happens. Knots are compared exactly: a new knot a few ulps from an old one is
//! a new knot; an equal one raises the multiplicity, up to d.
//!
//! [`BSpline::oslo`] computes the same refinement by the Oslo algorithm; both equal the knots
//! inserted one by one with [`BSpline::insert`], exactly on rationals.
//!
//! Follows [PPB, §6.1–6.2] (Boehm's insertion, and the advice to refine by repeated
//! insertion) and Piegl and Tiller, *The NURBS Book* (2nd ed., 1997), §5.3, Algorithm A5.4.
//!
//! # Complexity
//!
//! Θ(m log m) comparisons to sort the new knots, a span search for the first and the last,
//! then Θ(n + m) moves and at most md combinations: O(m log m + log n + (n + m + md)D) time,
//! O((n + m)D) space.
//!
//! Invariants the tests check (exactly on rationals): the result equals the knots inserted one
//! by one with [`BSpline::insert`] and the Oslo algorithm's result, and the curve is unchanged
//! at every parameter.

use super::basis::{affine, ratios};
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::{Error, Result};

/// Knot refinement by one backward pass of Boehm's insertions, declared.
pub(crate) const REFINE: Declaration = Declaration {
    problem: "bspline",
    name: "refine",
    function: "spline::BSpline::refine",
    file: "src/spline/bspline/refine.rs",
    summary: "the same curve with m knots added, by Boehm's insertions from the largest knot down, each point written once",
    time: "O(m log m + log n + (n + m + md)D)",
    space: "O((n + m)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly Σ r(d − s) − r(r − 1)/2 affine combinations over the distinct new knots (r new copies, s old ones): md for new simple knots",
    source: "[PPB, §6.1–6.2]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The same curve on the knot vector with all of `new_knots` added (in any order, repeats
    /// allowed). See [`BSpline::refine_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"new_knots"` for a new knot that is NaN, infinite or
    /// outside the domain [t_d, t_n] (naming its index and value), or for a knot whose
    /// multiplicity would exceed the degree (naming the knot and the multiplicity);
    /// [`Error::LimitExceeded`] beyond [`MAX_KNOTS`](crate::limits::MAX_KNOTS);
    /// No overflow: every new control point is a convex combination of old ones, and with
    /// `f64` one that would round past `f64::MAX` is clamped between its two points.
    ///
    /// # Complexity
    ///
    /// O(m log m + log n + (n + m + md)D) time, O((n + m)D) space for m new knots.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 2.0)?;
    /// let c = vec![Point::new([0.0]), Point::new([2.0]), Point::new([2.0]), Point::new([0.0])];
    /// let s = BSpline::new(c, t)?;
    /// let r = s.refine(&[1.5, 0.5, 1.0])?; // any order
    /// assert_eq!(r.knots().knots(), [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0]);
    /// assert_eq!(r, s.insert(&0.5, 1)?.insert(&1.0, 1)?.insert(&1.5, 1)?);
    /// assert_eq!(r.eval(&0.75)?, s.eval(&0.75)?);
    /// let e = s.refine(&[1.0, 1.0]).unwrap_err(); // 1 is a knot already
    /// assert!(e.to_string().contains("multiplicity 3"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn refine(&self, new_knots: &[S]) -> Result<Self> {
        self.refine_with(new_knots, &mut NoCount)
    }

    /// The same curve on the knot vector with all of `new_knots` added, by Boehm's insertions
    /// in one backward pass, counting its operations.
    ///
    /// Idea: validate and sort the new knots x₀ ≤ … ≤ x_{m−1}; the control points up to the
    /// span of x₀ less d and the knots up to that span stay where they are, those from the
    /// span of x_{m−1} up move up by m. Then from the top down: old knots above the current
    /// new knot x move up (with the control points below them by d + 1), x takes the next
    /// place, and the d points below it become (1 − α) ĉ_{j−1} + α ĉ_j, α the local
    /// coordinate of x in the support of the new basis function j [PPB, §6.1]. An empty
    /// `new_knots` returns the curve unchanged.
    ///
    /// Follows [PPB, §6.1–6.2] and Piegl and Tiller's Algorithm A5.4.
    ///
    /// # Errors
    ///
    /// As [`BSpline::refine`].
    ///
    /// # Complexity
    ///
    /// O(m log m + log n + (n + m + md)D) time, O((n + m)D) space for m new knots.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// exactly Σ r(d − s) − r(r − 1)/2 over the distinct new knots, r the new copies and s the
    /// old multiplicity (as [`BSpline::insert_with`] counts r copies of one knot), so md for m
    /// new simple knots; the [`comparison`](Counter::comparison)s of the validation, the sort
    /// is not counted.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(3, 8, 0.0, 5.0)?;
    /// let s = BSpline::new((0..8).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// let r = s.refine_with(&[0.5, 2.5, 4.5], &mut c)?;
    /// // Three new simple knots of a cubic: 3 combinations each.
    /// assert_eq!((c.arithmetic_operations, r.control().len()), (9, 11));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn refine_with<C: Counter>(&self, new_knots: &[S], counter: &mut C) -> Result<Self> {
        let knots = self.knots();
        let x = checked_new_knots(knots, new_knots, counter)?;
        if x.is_empty() {
            return Ok(self.clone());
        }
        let (d, n, m) = (self.degree(), self.control().len(), x.len());
        let t = knots.knots();
        let c = self.control();
        let end = knots.bounds().1;
        // The spans of the smallest and the largest new knot.
        let a = knots.span_in_domain(&x[0], counter);
        let b = knots.span_in_domain(&x[m - 1], counter) + 1;

        let mut tau: Vec<S> = vec![S::zero(); t.len() + m];
        let mut q: Vec<Point<S, D>> = vec![Point::zero(); n + m];
        // Untouched below the first span, shifted by m above the last.
        q[..=a - d].clone_from_slice(&c[..=a - d]);
        q[b - 1 + m..].clone_from_slice(&c[b - 1..]);
        tau[..=a].clone_from_slice(&t[..=a]);
        tau[b + d + m..].clone_from_slice(&t[b + d..]);

        // i: the next old knot to place (top down); k: the next free place in τ.
        let (mut i, mut k) = (b + d - 1, b + d + m - 1);
        for xj in x.iter().rev() {
            // Old knots above xj go above it; an old copy of xj stays below it, except at the
            // end of the domain, where the new knot goes before the old copies of t_n (the
            // places Boehm's insertion gives them).
            while i > a && (t[i] > *xj || (t[i] == *xj && xj == end)) {
                q[k - d - 1] = c[i - d - 1].clone();
                tau[k] = t[i].clone();
                k -= 1;
                i -= 1;
            }
            q[k - d - 1] = q[k - d].clone();
            for l in 1..=d {
                let j = k - d + l;
                let (lo, hi) = (&t[i - d + l], &tau[k + l]);
                if hi == xj {
                    // The support ends at a copy of xj already in place: a copy, no division.
                    q[j - 1] = q[j].clone();
                } else if lo == xj {
                    // It starts at an old copy of xj: α = 1, the point stays.
                } else {
                    // α = (hi − xj)/(hi − lo) weighs ĉ_{j−1}; its complement ĉ_j.
                    let (alpha, beta) = local_coordinates(lo, xj, hi);
                    let p = Point::combine(&q[j - 1], &alpha, &q[j], &beta);
                    // Near f64::MAX a convex combination can round past it: recomputed.
                    q[j - 1] = if p.is_finite() {
                        p
                    } else {
                        affine(&q[j - 1], lo, xj, hi, &q[j])
                    };
                    counter.arithmetic_operation();
                }
            }
            tau[k] = xj.clone();
            k -= 1;
        }
        let refined = KnotVector::valid_by_construction(d, tau);
        BSpline::derived(q, refined, "knot refinement")
    }
}

/// ((hi − x)/(hi − lo), (x − lo)/(hi − lo)) for lo < x < hi, with one division: the
/// reciprocal of the width, each weight then within two roundings of its value (with `f64`).
/// Where the width or its reciprocal overflows (widths near the top of the range or
/// subnormal), [`ratios`] divides twice, halving first where it must.
fn local_coordinates<S: Scalar>(lo: &S, x: &S, hi: &S) -> (S, S) {
    let width = hi.clone() - lo;
    let inverse = S::one() / width;
    if !inverse.is_finite() || inverse.is_zero() {
        return ratios(lo, x, hi);
    }
    let right = (hi.clone() - x) * &inverse;
    let left = (x.clone() - lo) * &inverse;
    (right, left)
}

/// The new knots of a refinement, validated and sorted: each finite and in the domain
/// [t_d, t_n] (one pair of counted comparisons each), and no knot with a multiplicity above
/// the degree afterwards. Shared by [`BSpline::refine`] and [`BSpline::oslo`].
pub(super) fn checked_new_knots<S: Scalar, C: Counter>(
    knots: &KnotVector<S>,
    new_knots: &[S],
    counter: &mut C,
) -> Result<Vec<S>> {
    let d = knots.degree();
    let (start, end) = knots.bounds();
    for (i, x) in new_knots.iter().enumerate() {
        if !x.is_finite() {
            return Err(Error::InvalidParameter {
                name: "new_knots",
                reason: format!("new knot {i} is not finite ({})", x.to_f64()),
            });
        }
        counter.comparison();
        counter.comparison();
        if x < start || x > end {
            return Err(Error::InvalidParameter {
                name: "new_knots",
                reason: format!(
                    "new knot {i} ({}) is outside the domain [{}, {}]",
                    x.to_f64(),
                    start.to_f64(),
                    end.to_f64()
                ),
            });
        }
    }
    if new_knots.is_empty() {
        return Ok(Vec::new());
    }
    crate::limits::KNOTS.check(knots.knots().len() as u128 + new_knots.len() as u128)?;
    let mut sorted = new_knots.to_vec();
    // All finite, so the order is total.
    sorted.sort_by(|a, b| a.partial_cmp(b).expect("finite knots are ordered"));
    // The multiplicities by one merge of the two sorted lists.
    let t = knots.knots();
    let (mut first, mut old) = (0, 0);
    while first < sorted.len() {
        let value = &sorted[first];
        let run = sorted[first..].iter().take_while(|x| *x == value).count();
        while old < t.len() && t[old] < *value {
            old += 1;
        }
        let existing = t[old..].iter().take_while(|k| *k == value).count();
        if existing + run > d {
            return Err(Error::InvalidParameter {
                name: "new_knots",
                reason: format!(
                    "knot {} would have multiplicity {} ({existing} old, {run} new), more \
                     than the degree {d} (the curve would break there)",
                    sorted[first].to_f64(),
                    existing + run
                ),
            });
        }
        first += run;
    }
    Ok(sorted)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::Curve;

    #[test]
    fn refinement_equals_single_insertions_and_names_bad_knots() {
        let t = KnotVector::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
        let c = [0.0, 4.0, 1.0, 3.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        // Dyadic knots and points; the result is the same curve as the single insertions.
        let r = s.refine(&[2.5, 2.0, 4.0, 3.0]).unwrap();
        let one = s
            .insert(&2.0, 1)
            .and_then(|s| s.insert(&2.5, 1))
            .and_then(|s| s.insert(&3.0, 1))
            .and_then(|s| s.insert(&4.0, 1))
            .unwrap();
        assert_eq!(r.knots(), one.knots());
        for (p, q) in r.control().iter().zip(one.control()) {
            assert!(
                (p[0] - q[0]).abs() <= 1e-15 * q[0].abs().max(1.0),
                "{p:?} {q:?}"
            );
        }
        for u in [2.0, 2.25, 3.0, 3.75, 4.0] {
            let (a, b) = (r.eval(&u).unwrap()[0], s.eval(&u).unwrap()[0]);
            assert!((a - b).abs() <= 1e-14, "{u}: {a} vs {b}");
        }
        let e = s.refine(&[2.5, f64::NAN]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid new_knots: new knot 1 is not finite (NaN)"
        );
        let e = s.refine(&[1.5]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid new_knots: new knot 0 (1.5) is outside the domain [2, 4]"
        );
        // 3 is a simple knot: one more copy is allowed, two are not.
        assert!(s.refine(&[3.0, 2.75, 2.75]).is_ok());
        let e = s.refine(&[3.0, 3.0]).unwrap_err();
        assert!(
            e.to_string().contains("knot 3 would have multiplicity 3"),
            "{e}"
        );
        assert_eq!(s.refine(&[]).unwrap(), s);
    }

    #[test]
    fn subnormal_and_huge_widths_take_the_two_division_path() {
        // Knots 8 subnormal ulps apart: the reciprocal of the width overflows.
        let tiny = f64::from_bits(8);
        let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, tiny, 1.0, 1.0, 1.0]).unwrap();
        let c = [0.0, 1.0, 2.0, 3.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        let x = f64::from_bits(4);
        let r = s.refine(&[x]).unwrap();
        assert_eq!(r, s.insert(&x, 1).unwrap());
        assert!(r.control().iter().all(Point::is_finite));
        // Widths beyond the double range: the reciprocal is zero.
        let m = f64::MAX;
        let t = KnotVector::new(1, vec![-m, -m, m, m]).unwrap();
        let s = BSpline::new(vec![Point::new([-1.0]), Point::new([1.0])], t).unwrap();
        let r = s.refine(&[0.0]).unwrap();
        assert_eq!(r.control()[1], Point::new([0.0]));
    }
}
