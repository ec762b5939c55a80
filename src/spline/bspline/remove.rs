//! Knot removal, the inverse of insertion: the same curve on a knot vector with fewer copies
//! of a knot, when the curve allows it.
//!
//! The problem: remove one copy of the interior knot u = t_r (r the index of its last copy, s
//! its multiplicity) and find control points c′ on the smaller vector t′ with the same curve.
//! The idea: inserting u into t′ must give back c, and by Boehm's formula [PPB, §6.1] that is
//! c_j = (1 − α_j) c′_{j−1} + α_j c′_j, α_j = (u − t_j)/(t_{j+d+1} − t_j), for
//! j = r − d, …, r − s, with the other c′ copies of c. These are d − s + 1 equations for the
//! d − s unknowns c′_{r−d}, …, c′_{r−s−1}: one too many, and the curve is representable on t′
//! exactly when they are consistent, that is when it is C^{d−s+1} at u and not only the
//! C^{d−s} the knot vector guarantees ([PPB, §6.1, Obs. 3] runs the same identity backwards
//! for a single B-spline). The unknowns are solved from both ends towards the middle, as
//! Piegl and Tiller's Algorithm A5.8 arranges it (the left sweep divides by α_j, the right one
//! by 1 − α_j; the sweeps meet where α_j passes 1/2, so neither divides by a small weight),
//! and the result is then checked by inserting u back and comparing with the original control
//! points:
//!
//! - [`BSpline::remove`] compares exactly: with rationals, insert-then-remove gives the
//!   original control points back and a knot that cannot be removed is reported with the
//!   continuity the curve really has there; with `f64` the removal succeeds only when the
//!   rounded arithmetic happens to reproduce the control points exactly;
//! - [`BSpline::remove_within`] accepts a removal when no control point of the reconstruction
//!   is farther than a tolerance from the original one (a Euclidean distance between control
//!   points, not a tolerance on knots, which stay exact). The two curves on the original
//!   knots differ by Σ (ĉ_j − c_j) N_j(u), and the basis functions are non-negative and sum
//!   to one, so the curve itself moves by at most the tolerance, everywhere.
//!
//! Removing a knot `times` times repeats the step; each step is checked by re-inserting all
//! copies removed so far, so the tolerance bounds the total move.
//!
//! Follows [PPB, §6.1] (Boehm's insertion, inverted) and Piegl and Tiller, *The NURBS Book*
//! (2nd ed., 1997), §5.4 and Algorithm A5.8 (read for the idea; written anew).
//!
//! # Complexity
//!
//! For r removals: each solves at most d unknowns and each check re-inserts the copies removed
//! so far, Θ(n + d) copies and at most d + 1 combinations per copy: O(r²(n + d)D) time and
//! O((n + d)D) space (r ≤ d + 1).
//!
//! Invariants the tests check (exactly on rationals): insert-then-remove returns identical
//! control points, and a knot whose removal would change the curve gives the error.

use super::basis::ratios;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// Knot removal, declared.
pub(crate) const REMOVE: Declaration = Declaration {
    problem: "bspline",
    name: "remove",
    function: "spline::BSpline::remove",
    file: "src/spline/bspline/remove.rs",
    summary: "the same curve with a knot removed r times when it is representable without it, checked by re-insertion",
    time: "O(r²(n + d)D)",
    space: "O((n + d)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "per removal of a knot of multiplicity s ≤ d: d − s solved points, and d − sᵢ + 1 combinations per re-inserted copy of multiplicity sᵢ",
    source: "[PPB, §6.1]",
    claims: &[on("random-degree", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The same curve with the knot `u` removed `times` times, when the curve is exactly
    /// representable on the smaller knot vector. See [`BSpline::remove_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u` is NaN or infinite, not a knot, or not
    /// inside the domain (t_d, t_n) (an end of the domain, clamped or not, cannot be removed:
    /// the domain would change); named `"times"` if `times` exceeds the multiplicity of `u`,
    /// or if a removal would change the curve (the message names the knot, how many removals
    /// succeeded, the largest move of a control point, and the continuity the curve has at
    /// `u`).
    ///
    /// # Complexity
    ///
    /// O(r²(n + d)D) time, O((n + d)D) space (r = `times`).
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 2.0)?;
    /// let c = vec![Point::new([0.0]), Point::new([2.0]), Point::new([4.0]), Point::new([0.0])];
    /// let s = BSpline::new(c, t)?;
    /// let r = s.insert(&0.5, 1)?;
    /// assert_eq!(r.remove(&0.5, 1)?, s); // insert-then-remove: the same control points
    /// let e = s.remove(&1.0, 1).unwrap_err(); // s is C¹ at 1 but not C²
    /// assert!(e.to_string().contains("0 of 1 removals succeeded"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn remove(&self, u: &S, times: usize) -> Result<Self> {
        self.remove_with(u, times, &mut NoCount)
    }

    /// The same curve with the knot `u` removed `times` times, counting the operations.
    ///
    /// Idea: for each removal, find the last copy t_r = u and the multiplicity s, solve the
    /// d − s new control points from both ends of the window c_{r−d−1}, …, c_{r−s+1} towards
    /// the middle, then insert u back (as many times as it has been removed) and compare the
    /// control points with the original ones exactly [PPB, §6.1]. A knot of multiplicity
    /// d + 1 (where the curve may jump) loses a copy when its two control points c_{r−d−1}
    /// and c_{r−d} are equal. `times = 0` returns the curve unchanged.
    ///
    /// Follows [PPB, §6.1] and Piegl and Tiller's Algorithm A5.8.
    ///
    /// # Errors
    ///
    /// As [`BSpline::remove`].
    ///
    /// # Complexity
    ///
    /// O(r²(n + d)D) time, O((n + d)D) space (r = `times`).
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per solved control point
    /// (d − s for a removal at multiplicity s ≤ d) and per combination of the check (d − sᵢ + 1
    /// for each copy re-inserted at multiplicity sᵢ ≤ d).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // The line s(u) = u (control points at the Greville abscissae 0, 1, 3, 4).
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 2.0, 4.0, 4.0, 4.0])?;
    /// let s = BSpline::new([0.0, 1.0, 3.0, 4.0].map(|x| Point::new([x])).to_vec(), t)?;
    /// // Removing the simple knot 2: 1 point solved, 2 combinations to check.
    /// let mut c = Counts::default();
    /// let r = s.remove_with(&2.0, 1, &mut c)?;
    /// assert_eq!((c.arithmetic_operations, r.control().len()), (3, 3));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn remove_with<C: Counter>(&self, u: &S, times: usize, counter: &mut C) -> Result<Self> {
        self.remove_checked(u, times, None, counter)
    }

    /// The curve with the knot `u` removed `times` times, accepting each removal whose
    /// reconstruction moves no control point farther than `tolerance` from the original one.
    ///
    /// The tolerance is a Euclidean distance between control points (in the units of the
    /// coordinates), not a tolerance on knots: the knots stay exact, and `u` must be one of
    /// them. The original curve and the result differ by at most `tolerance` at every
    /// parameter: on the original knots the two curves differ by Σ (ĉ_j − c_j) N_j(u), and
    /// the basis functions are non-negative and sum to one. With a zero tolerance it is
    /// [`BSpline::remove`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::remove`] (the move reported is the one beyond the tolerance);
    /// [`Error::InvalidParameter`] named `"tolerance"` if it is negative, NaN or infinite.
    ///
    /// # Complexity
    ///
    /// O(r²(n + d)D) time, O((n + d)D) space (r = `times`).
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(3, 5, 0.0, 1.0)?;
    /// // The line 6u (control points 6 times the Greville abscissae), its end moved by 1e-9.
    /// let c = [0.0, 1.0, 3.0, 5.0, 6.0 + 1e-9].map(|x| Point::new([x])).to_vec();
    /// let s = BSpline::new(c, t)?;
    /// assert!(s.remove(&0.5, 1).is_err()); // not a cubic polynomial, by 1e-9
    /// let r = s.remove_within(&0.5, 1, &1e-8)?;
    /// assert_eq!(r.control().len(), 4);
    /// assert!((r.eval(&0.3)?[0] - s.eval(&0.3)?[0]).abs() <= 1e-8);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn remove_within(&self, u: &S, times: usize, tolerance: &S) -> Result<Self> {
        self.remove_within_with(u, times, tolerance, &mut NoCount)
    }

    /// [`BSpline::remove_within`], counting the operations as [`BSpline::remove_with`] does.
    ///
    /// # Errors
    ///
    /// As [`BSpline::remove_within`].
    ///
    /// # Complexity
    ///
    /// O(r²(n + d)D) time, O((n + d)D) space (r = `times`).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?;
    /// let s = BSpline::new(vec![Point::new([0.0]), Point::new([1.25]), Point::new([2.0])], t)?;
    /// let mut c = Counts::default();
    /// let r = s.remove_within_with(&1.0, 1, &0.25, &mut c)?; // the corner moves by 0.25
    /// assert_eq!((r.control().len(), c.arithmetic_operations), (2, 1));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn remove_within_with<C: Counter>(
        &self,
        u: &S,
        times: usize,
        tolerance: &S,
        counter: &mut C,
    ) -> Result<Self> {
        if !tolerance.is_finite() || *tolerance < S::zero() {
            return Err(Error::InvalidParameter {
                name: "tolerance",
                reason: format!(
                    "the tolerance must be finite and non-negative, got {}",
                    tolerance.to_f64()
                ),
            });
        }
        self.remove_checked(u, times, Some(tolerance), counter)
    }

    /// The removal with its check: exact (`None`) or within a distance.
    fn remove_checked<C: Counter>(
        &self,
        u: &S,
        times: usize,
        tolerance: Option<&S>,
        counter: &mut C,
    ) -> Result<Self> {
        validate_parameter(u, "u")?;
        let knots = self.knots();
        let d = self.degree();
        let s = knots.multiplicity(u);
        if s == 0 {
            return Err(Error::InvalidParameter {
                name: "u",
                reason: format!("{} is not a knot", u.to_f64()),
            });
        }
        let (start, end) = knots.bounds();
        if u <= start || u >= end {
            let reason = if knots.is_clamped() && (u == start || u == end) {
                format!(
                    "{} is an end of the clamped domain [{}, {}]; its copies clamp the curve \
                     there and cannot be removed",
                    u.to_f64(),
                    start.to_f64(),
                    end.to_f64()
                )
            } else {
                format!(
                    "the knot {} is not inside the domain ({}, {}); removing it would change \
                     the domain",
                    u.to_f64(),
                    start.to_f64(),
                    end.to_f64()
                )
            };
            return Err(Error::InvalidParameter { name: "u", reason });
        }
        if times > s {
            return Err(Error::InvalidParameter {
                name: "times",
                reason: format!(
                    "cannot remove the knot {} {times} times: its multiplicity is {s}",
                    u.to_f64()
                ),
            });
        }
        // levels[k]: the curve after k removals (levels[0] = self).
        let mut levels: Vec<BSpline<S, D>> = vec![self.clone()];
        for k in 1..=times {
            let current = &levels[k - 1];
            let reduced = remove_once(current, u, counter)?;
            // Insert u back k times and compare with the original control points.
            let mut back = reduced.control().to_vec();
            for level in levels.iter().rev() {
                back = reinsert_once(level.knots(), &back, u, counter);
            }
            if let Some((j, far)) = first_mismatch(&back, self.control(), tolerance) {
                let have = d as i64 - s as i64 + k as i64 - 1;
                let continuity = if S::EXACT {
                    format!("the curve is C^{have} there, not C^{}", have + 1)
                } else {
                    format!(
                        "with rounded arithmetic the curve is not shown to be C^{} there",
                        have + 1
                    )
                };
                return Err(Error::InvalidParameter {
                    name: "times",
                    reason: format!(
                        "knot {} (multiplicity {s}): {} of {times} removals succeeded; the \
                         next would move control point {j} by {far:e}{}, so {continuity}",
                        u.to_f64(),
                        k - 1,
                        match tolerance {
                            Some(tol) => format!(", more than the tolerance {:e}", tol.to_f64()),
                            None => String::new(),
                        }
                    ),
                });
            }
            levels.push(reduced);
        }
        Ok(levels.pop().expect("at least the curve itself"))
    }
}

/// One removal of the last copy of the interior knot `u`, without a check: the unknowns
/// c′_{r−d}, …, c′_{r−s−1} solved from both ends (with multiplicity d + 1, the midpoint of the
/// two control points at the jump).
fn remove_once<S: Scalar, const D: usize, C: Counter>(
    curve: &BSpline<S, D>,
    u: &S,
    counter: &mut C,
) -> Result<BSpline<S, D>> {
    let t = curve.knots().knots();
    let d = curve.degree();
    let c = curve.control();
    let n = c.len();
    let r = t.partition_point(|k| k <= u) - 1;
    let s = curve.knots().multiplicity(u);
    let mut out: Vec<Point<S, D>> = Vec::with_capacity(n - 1);
    if s > d {
        // Multiplicity d + 1: c′_{r−d−1} replaces both sides of the jump.
        out.extend_from_slice(&c[..r - d - 1]);
        let (a, b) = (&c[r - d - 1], &c[r - d]);
        out.push(if a == b {
            a.clone()
        } else {
            Point::lerp(a, b, &S::from_ratio(1, 2))
        });
        out.extend_from_slice(&c[r - d + 1..]);
    } else {
        // The unknowns c′_k, k = lo..hi (hi exclusive). The weights α_j do not increase with
        // j (their knots t_j ≤ u ≤ t_{j+d+1} both move up), so the left sweep, dividing by
        // α_j, takes the equations with α_j ≥ 1/2 and the right sweep, dividing by 1 − α_j,
        // the others: no division by a small weight (next to a knot a few ulps away, α can be
        // 1e-16), and each step at most doubles an error.
        let (lo, hi) = (r - d, r - s);
        let half = S::from_ratio(1, 2);
        let mid = (lo..hi)
            .take_while(|&j| ratios(&t[j], u, &t[j + d + 1]).1 >= half)
            .count()
            + lo;
        let mut middle: Vec<Point<S, D>> = vec![Point::zero(); hi - lo];
        let mut prev = c[lo - 1].clone();
        for j in lo..mid {
            // c_j = (1 − α) c′_{j−1} + α c′_j ⇒ c′_j = (c_j − (1 − α) c′_{j−1})/α, α > 0.
            let (right, left) = ratios(&t[j], u, &t[j + d + 1]);
            let next = Point::combine(&c[j], &(S::one() / &left), &prev, &(-(right / &left)));
            counter.arithmetic_operation();
            middle[j - lo] = next.clone();
            prev = next;
        }
        let mut after = c[r - s + 1].clone();
        for j in (mid + 1..=hi).rev() {
            // c_j = (1 − α) c′_{j−1} + α c′_j ⇒ c′_{j−1} = (c_j − α c′_j)/(1 − α), α < 1.
            let (right, left) = ratios(&t[j], u, &t[j + d + 1]);
            let next = Point::combine(&c[j], &(S::one() / &right), &after, &(-(left / &right)));
            counter.arithmetic_operation();
            middle[j - 1 - lo] = next.clone();
            after = next;
        }
        out.extend_from_slice(&c[..lo]);
        out.extend(middle);
        out.extend_from_slice(&c[r - s + 1..]);
    }
    let mut knots = t.to_vec();
    knots.remove(r);
    let knots = KnotVector::new(d, knots)?;
    BSpline::derived(out, knots, "knot removal")
}

/// The control points on `knots` (which have u as a knot) from those on `knots` without its
/// last copy of u: Boehm's insertion of u, once, with no multiplicity limit (so it also
/// rebuilds a knot of multiplicity d + 1).
fn reinsert_once<S: Scalar, const D: usize, C: Counter>(
    knots: &KnotVector<S>,
    reduced: &[Point<S, D>],
    u: &S,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let t = knots.knots();
    let d = knots.degree();
    let r = t.partition_point(|k| k <= u) - 1;
    let s = knots.multiplicity(u);
    let mut out = Vec::with_capacity(reduced.len() + 1);
    out.extend_from_slice(&reduced[..r - d]);
    for j in r - d..(r + 1).saturating_sub(s).max(r - d) {
        let (right, left) = ratios(&t[j], u, &t[j + d + 1]);
        out.push(Point::combine(&reduced[j - 1], &right, &reduced[j], &left));
        counter.arithmetic_operation();
    }
    // j ≥ r − s + 1: ĉ_j = c′_{j−1} (for s = d + 1 from j = r − d on).
    let from = (r + 1).saturating_sub(s).max(r - d);
    out.extend_from_slice(&reduced[from - 1..]);
    out
}

/// The first index where `a` and `b` differ (exactly, or by more than `tolerance`), with the
/// distance (as `f64`, for the message).
fn first_mismatch<S: Scalar, const D: usize>(
    a: &[Point<S, D>],
    b: &[Point<S, D>],
    tolerance: Option<&S>,
) -> Option<(usize, f64)> {
    a.iter().zip(b).enumerate().find_map(|(j, (p, q))| {
        let ok = match tolerance {
            None => p == q,
            Some(tol) => within(p, q, tol),
        };
        (!ok).then(|| (j, distance_f64(p, q)))
    })
}

/// ‖p − q‖ ≤ tol, exactly for rationals and without overflow for `f64`: with m the largest
/// coordinate difference, Σ (Δᵢ/m)² ≤ (tol/m)².
fn within<S: Scalar, const D: usize>(p: &Point<S, D>, q: &Point<S, D>, tol: &S) -> bool {
    let diff: Vec<S> = (0..D).map(|i| p[i].clone() - &q[i]).collect();
    if diff.iter().any(|x| !x.is_finite()) {
        return false;
    }
    let m = diff
        .iter()
        .map(Scalar::abs)
        .fold(S::zero(), |m, x| if x > m { x } else { m });
    if m.is_zero() {
        return true;
    }
    if m > *tol {
        return false;
    }
    let mut sum = S::zero();
    for x in &diff {
        let y = x.clone() / &m;
        sum += y.clone() * &y;
    }
    let bound = tol.clone() / &m;
    sum <= bound.clone() * &bound
}

/// ‖p − q‖ as the nearest `f64` (scaled, so it overflows only beyond the double range).
fn distance_f64<S: Scalar, const D: usize>(p: &Point<S, D>, q: &Point<S, D>) -> f64 {
    let diff: Vec<f64> = (0..D).map(|i| (p[i].clone() - &q[i]).to_f64()).collect();
    let m = diff.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * diff.iter().map(|x| (x / m) * (x / m)).sum::<f64>().sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_jump_knot_loses_a_copy_only_where_the_curve_is_continuous() {
        // Degree 1 with a double knot at 1: c₁ and c₂ meet there.
        let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0]).unwrap();
        let c = [0.0, 1.0, 1.0, 3.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        let r = s.remove(&1.0, 1).unwrap();
        assert_eq!(r.knots().knots(), [0.0, 0.0, 1.0, 2.0, 2.0]);
        assert_eq!(r.control(), [0.0, 1.0, 3.0].map(|x| Point::new([x])));
        // The kink at 1 stays: C⁰, not C¹.
        let e = r.remove(&1.0, 1).unwrap_err();
        assert!(e.to_string().contains("not shown to be C^1 there"), "{e}");
        let jump = BSpline::new(
            [0.0, 1.0, 2.0, 3.0].map(|x| Point::new([x])).to_vec(),
            s.knots().clone(),
        )
        .unwrap();
        let e = jump.remove(&1.0, 1).unwrap_err();
        assert!(e.to_string().contains("0 of 1 removals"), "{e}");
        assert!(jump.remove_within(&1.0, 1, &0.5).is_ok());
        assert!(jump.remove_within(&1.0, 1, &0.4).is_err());
    }
}
