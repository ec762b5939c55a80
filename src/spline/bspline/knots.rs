//! Knot vectors: validated once, with their builders, multiplicities, domain and span search.
//!
//! A [`KnotVector`] of degree d for n control points holds n + d + 1 knots
//! t₀ ≤ t₁ ≤ … ≤ t_{n+d} (the convention of the [module](super)), finite, with no knot
//! repeated more than d + 1 times and a non-empty domain [t_d, t_n]. Every comparison of knots
//! and parameters is exact: two knots are equal only when they are the same number, so
//! multiplicities are never merged by a tolerance.
//!
//! Follows [PPB, §5.1] (knot sequences and multiplicity), [PPB, §5.7] (the domain
//! [a_n, a_{m+1}] and the end knots that do not matter) and [SPL, §12–13] (the convention
//! without end knots, adapted by [`KnotVector::from_spl`]).
//!
//! # Complexity
//!
//! Validation and the builders take Θ(n + d) comparisons and field operations (averaging
//! Θ(n·d)); the span search O(log(n − d)) comparisons.

use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::curve::Domain;
use crate::spline::scalar::{validate_parameter, Scalar};
use crate::{limits, Error, Result};

/// A validated knot vector t₀ ≤ … ≤ t_{n+d} of degree d for n control points.
///
/// The invariants, checked once by every constructor: the degree is at most
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE); there are at least 2d + 2 knots (n ≥ d + 1
/// control points); every knot is finite; the knots never decrease; no knot occurs more than
/// d + 1 times; and the domain [t_d, t_n] is not a single point (t_d < t_n).
///
/// ```
/// use compgeo::spline::{Domain, KnotVector};
///
/// // A clamped cubic with 5 control points: 9 knots, one interior knot.
/// let t = KnotVector::new(3, vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0])?;
/// assert_eq!((t.degree(), t.control_points()), (3, 5));
/// assert_eq!(t.domain(), Domain::Interval { start: 0.0, end: 1.0 });
/// assert!(t.is_clamped());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct KnotVector<S> {
    degree: usize,
    knots: Vec<S>,
}

impl<S: Scalar> KnotVector<S> {
    /// The knot vector t₀, …, t_{n+d} of degree `degree`, validated; it serves
    /// n = `knots.len()` − d − 1 control points.
    ///
    /// # Errors
    ///
    /// - [`Error::LimitExceeded`] if `degree` exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE);
    /// - [`Error::TooFew`] with fewer than 2d + 2 knots;
    /// - [`Error::InvalidParameter`] named `"knots"` for a knot that is NaN or infinite, a knot
    ///   below its predecessor, a knot repeated more than d + 1 times, or an empty domain
    ///   (t_d = t_n); the message names the index and the value.
    ///
    /// # Complexity
    ///
    /// Θ(n + d) comparisons, no allocation beyond the vector it takes.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// let e = KnotVector::new(1, vec![0.0, 1.0, 0.5, 2.0]).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid knots: knot 2 (0.5) is below knot 1 (1)");
    /// let e = KnotVector::new(1, vec![0.0, 1.0, 1.0, 1.0, 2.0]).unwrap_err();
    /// assert!(e.to_string().contains("knots 1..=3 (1) have multiplicity 3"), "{e}");
    /// ```
    pub fn new(degree: usize, knots: Vec<S>) -> Result<Self> {
        validate(degree, &knots)?;
        Ok(KnotVector { degree, knots })
    }

    /// The knot vector of `degree` for `control_points` control points given in the
    /// convention of [SPL, §7, §12] (2n + N − 1 knots u₀, …, u_{2n+N−2} for n + N control
    /// points of degree n: the count is control points + degree − 1, with no end knots).
    ///
    /// The two end knots of this crate's convention, t₀ and t_{n+d}, influence no basis
    /// function on the domain [PPB, §5.7]; the adapter takes t₀ = u₀ and t_{n+d} = u_last, so
    /// tᵢ₊₁ = uᵢ, and SPL's basis function N_i (support [u_{i−1}, u_{i+n}]) is this crate's
    /// N_i (support [t_i, t_{i+d+1}]), with the same domain [u_{d−1}, u_{N+d−1}] = [t_d, t_n].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"degree"` for degree 0 (SPL's convention needs
    /// d ≥ 1); [`Error::TooFew`] with fewer than 2d knots; [`Error::InvalidParameter`] named
    /// `"knots"`, with SPL's index, for a non-finite or decreasing knot, an interior knot
    /// repeated more than d + 1 times or an end knot repeated more than d times (the adapter
    /// repeats it once more); otherwise the errors of [`KnotVector::new`].
    ///
    /// # Complexity
    ///
    /// Θ(n + d) comparisons, one copy of the knots.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// // SPL's clamped quadratic with 4 control points: 4 + 2 − 1 = 5 knots.
    /// let t = KnotVector::from_spl(2, &[0.0, 0.0, 1.0, 2.0, 2.0])?;
    /// assert_eq!(t.knots(), [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]);
    /// assert_eq!(t.to_spl(), [0.0, 0.0, 1.0, 2.0, 2.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_spl(degree: usize, knots: &[S]) -> Result<Self> {
        limits::DEGREE.check(degree as u128)?;
        if degree == 0 {
            return Err(Error::InvalidParameter {
                name: "degree",
                reason: "the SPL knot convention needs degree 1 or more, got 0".into(),
            });
        }
        if knots.len() < 2 * degree {
            return Err(Error::TooFew {
                what: "knots (SPL convention: control points + degree − 1)",
                needed: 2 * degree,
                got: knots.len(),
            });
        }
        check_finite_and_sorted(knots)?;
        let last = knots.len() - 1;
        for (first, run) in runs(knots) {
            let end = first + run - 1;
            let at_end = first == 0 || end == last;
            let most = if at_end { degree } else { degree + 1 };
            if run > most {
                return Err(multiplicity_error(
                    &knots[first],
                    first,
                    run,
                    most,
                    if at_end {
                        "degree at an end, where the adapter adds one more copy"
                    } else {
                        "degree + 1"
                    },
                ));
            }
        }
        let mut t = Vec::with_capacity(knots.len() + 2);
        t.push(knots[0].clone());
        t.extend_from_slice(knots);
        t.push(knots[last].clone());
        KnotVector::new(degree, t)
    }

    /// A knot vector its caller has built valid (a refinement of a valid one by knots
    /// checked to be in the domain and below multiplicity d + 1): the Θ(n + d) validation
    /// of [`KnotVector::new`] would run again over knots already checked, so it runs in debug
    /// builds only.
    pub(super) fn valid_by_construction(degree: usize, knots: Vec<S>) -> Self {
        debug_assert!(
            validate(degree, &knots).is_ok(),
            "an invalid derived knot vector"
        );
        KnotVector { degree, knots }
    }

    /// The clamped (open) uniform knot vector of `degree` for `control_points` control points
    /// over [start, end]: d + 1 copies of `start`, the n − d − 1 interior knots equally spaced,
    /// d + 1 copies of `end`. With n = d + 1 it is the Bézier case [PPB, §5.3, Obs. 1].
    ///
    /// Interior knots are `start + (i/(n − d))·(end − start)` (exact for rationals; for `f64`
    /// each is rounded once, and they never decrease).
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] if `degree` exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE)
    /// or the knot count n + d + 1 exceeds [`MAX_KNOTS`](crate::limits::MAX_KNOTS);
    /// [`Error::TooFew`] with fewer than d + 1 control points; [`Error::InvalidParameter`] if
    /// `start` or `end` is not finite, `start ≥ end`, or (`f64`) `end − start` overflows.
    ///
    /// # Complexity
    ///
    /// Θ(n + d) field operations and space.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::clamped_uniform(2, 5, 0.0, 3.0)?;
    /// assert_eq!(t.knots(), [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn clamped_uniform(degree: usize, control_points: usize, start: S, end: S) -> Result<Self> {
        let (n, d) = check_sizes(degree, control_points)?;
        let width = check_interval(&start, &end)?;
        let pieces = S::from_i64((n - d) as i64);
        let mut t = Vec::with_capacity(n + d + 1);
        t.extend(std::iter::repeat_n(start.clone(), d + 1));
        for i in 1..n - d {
            let s = S::from_i64(i as i64) / &pieces;
            t.push(below(start.clone() + s * &width, &end));
        }
        t.extend(std::iter::repeat_n(end, d + 1));
        KnotVector::new(degree, t)
    }

    /// The uniform (unclamped) knot vector of `degree` for `control_points` control points
    /// whose domain [t_d, t_n] is [start, end]: all n + d + 1 knots equally spaced with step
    /// h = (end − start)/(n − d), tᵢ = start + (i − d)·h, so d knots lie before `start` and d
    /// after `end`.
    ///
    /// # Errors
    ///
    /// As [`KnotVector::clamped_uniform`]; also [`Error::InvalidParameter`] if (`f64`) an
    /// outer knot overflows.
    ///
    /// # Complexity
    ///
    /// Θ(n + d) field operations and space.
    ///
    /// ```
    /// use compgeo::spline::{Domain, KnotVector};
    ///
    /// let t = KnotVector::uniform(2, 4, 0.0, 2.0)?;
    /// assert_eq!(t.knots(), [-2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0]);
    /// assert_eq!(t.domain(), Domain::Interval { start: 0.0, end: 2.0 });
    /// assert!(!t.is_clamped());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn uniform(degree: usize, control_points: usize, start: S, end: S) -> Result<Self> {
        let (n, d) = check_sizes(degree, control_points)?;
        let width = check_interval(&start, &end)?;
        let pieces = S::from_i64((n - d) as i64);
        let mut t = Vec::with_capacity(n + d + 1);
        for i in 0..=n + d {
            let t_i = if i == d {
                start.clone()
            } else if i == n {
                end.clone()
            } else {
                let s = S::from_i64(i as i64 - d as i64) / &pieces;
                let t_i = start.clone() + s * &width;
                if (d..n).contains(&i) {
                    below(t_i, &end)
                } else {
                    t_i
                }
            };
            t.push(t_i);
        }
        KnotVector::new(degree, t)
    }

    /// The clamped knot vector of `degree` for interpolation at the parameters
    /// ū₀ ≤ … ≤ ū_{n−1} (one per control point), by de Boor's averaging: d + 1 copies of ū₀,
    /// the interior knots t_{j+d} = (ū_j + … + ū_{j+d−1})/d for j = 1, …, n − d − 1, and
    /// d + 1 copies of ū_{n−1}. Each interior knot averages the d parameters it lies
    /// between, so for strictly increasing parameters t_i < ū_i < t_{i+d+1} at every
    /// interior parameter: the Schoenberg–Whitney condition of interpolation holds.
    ///
    /// Follows de Boor, *A Practical Guide to Splines* (1978), the averaging of the knot
    /// choice for interpolation (also Piegl and Tiller, *The NURBS Book*, eq. 9.8), on
    /// [PPB, §5.7]'s clamped vectors; the averages are the Greville-type means of
    /// [PPB, §5.8].
    ///
    /// For `f64` each average is the sum of the d quotients ūᵢ/d, so it cannot overflow, and
    /// is kept within [ū₀, ū_{n−1}].
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] if `degree` exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE);
    /// [`Error::InvalidParameter`] named `"degree"` for degree 0; [`Error::TooFew`] with fewer
    /// than d + 1 parameters; [`Error::InvalidParameter`] named `"parameters"` for a
    /// parameter that is not finite or decreases (naming its index and value) or for
    /// ū₀ = ū_{n−1}; the errors of [`KnotVector::new`] if repeated parameters give a knot of
    /// multiplicity above d + 1.
    ///
    /// # Complexity
    ///
    /// Θ(n·d) field operations, Θ(n + d) space.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::averaged(2, &[0.0, 1.0, 3.0, 4.0])?;
    /// assert_eq!(t.knots(), [0.0, 0.0, 0.0, 2.0, 4.0, 4.0, 4.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn averaged(degree: usize, parameters: &[S]) -> Result<Self> {
        limits::DEGREE.check(degree as u128)?;
        if degree == 0 {
            return Err(Error::InvalidParameter {
                name: "degree",
                reason: "averaging needs degree 1 or more, got 0".into(),
            });
        }
        let (n, d) = check_sizes(degree, parameters.len())?;
        check_finite_and_sorted(parameters).map_err(|e| match e {
            Error::InvalidParameter { reason, .. } => Error::InvalidParameter {
                name: "parameters",
                reason: reason.replace("knot", "parameter"),
            },
            other => other,
        })?;
        let (first, last) = (&parameters[0], &parameters[n - 1]);
        if first == last {
            return Err(Error::InvalidParameter {
                name: "parameters",
                reason: format!("all {n} parameters are equal ({})", first.to_f64()),
            });
        }
        let degree_s = S::from_i64(d as i64);
        let mut t = Vec::with_capacity(n + d + 1);
        t.extend(std::iter::repeat_n(first.clone(), d + 1));
        for j in 1..n - d {
            let mut mean = S::zero();
            for u in &parameters[j..j + d] {
                mean += u.clone() / &degree_s;
            }
            // Rounding cannot leave [ū₀, ū_{n−1}]; exactly it never does.
            if mean < *first {
                mean = first.clone();
            }
            t.push(below(mean, last));
        }
        t.extend(std::iter::repeat_n(last.clone(), d + 1));
        KnotVector::new(degree, t)
    }

    /// The degree d.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::clamped_uniform(3, 4, 0.0, 1.0)?.degree(), 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knots t₀, …, t_{n+d}.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?.knots(), [0.0, 0.0, 1.0, 1.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn knots(&self) -> &[S] {
        &self.knots
    }

    /// The knots without the two end knots: the convention of [SPL, §7] (control points +
    /// degree − 1 knots), the inverse of [`KnotVector::from_spl`].
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0])?;
    /// assert_eq!(t.to_spl(), [0.0, 1.0, 2.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_spl(&self) -> &[S] {
        &self.knots[1..self.knots.len() - 1]
    }

    /// The number n of control points (and of basis functions): knots − d − 1.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::uniform(2, 7, 0.0, 1.0)?.control_points(), 7);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn control_points(&self) -> usize {
        self.knots.len() - self.degree - 1
    }

    /// Checks that the vector serves exactly `count` control points (n + d + 1 knots).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"knots"` naming both counts.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let t = KnotVector::clamped_uniform(3, 6, 0.0, 1.0)?;
    /// assert!(t.check_control_points(6).is_ok());
    /// let e = t.check_control_points(5).unwrap_err();
    /// assert_eq!(
    ///     e.to_string(),
    ///     "invalid knots: 5 control points of degree 3 need 9 knots, got 10"
    /// );
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn check_control_points(&self, count: usize) -> Result<()> {
        if count == self.control_points() {
            Ok(())
        } else {
            Err(Error::InvalidParameter {
                name: "knots",
                reason: format!(
                    "{count} control points of degree {} need {} knots, got {}",
                    self.degree,
                    count as u128 + self.degree as u128 + 1,
                    self.knots.len()
                ),
            })
        }
    }

    /// The domain [t_d, t_n] of every spline on these knots, for clamped and unclamped
    /// vectors alike: the interval where the d + 1 basis functions of each span sum to one
    /// [PPB, §5.7].
    ///
    /// ```
    /// use compgeo::spline::{Domain, KnotVector};
    ///
    /// let t = KnotVector::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0])?;
    /// assert_eq!(t.domain(), Domain::Interval { start: 2.0, end: 3.0 });
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn domain(&self) -> Domain<S> {
        let (start, end) = self.bounds();
        Domain::Interval {
            start: start.clone(),
            end: end.clone(),
        }
    }

    /// The ends (t_d, t_n) of the domain.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let t = KnotVector::uniform(1, 3, 0.0, 1.0)?;
    /// assert_eq!(t.bounds(), (&0.0, &1.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bounds(&self) -> (&S, &S) {
        (&self.knots[self.degree], &self.knots[self.control_points()])
    }

    /// `true` if the first d + 1 knots are equal and so are the last d + 1 (an open or
    /// clamped vector: the curve starts at its first control point and ends at its last).
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert!(KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?.is_clamped());
    /// assert!(!KnotVector::uniform(2, 4, 0.0, 1.0)?.is_clamped());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn is_clamped(&self) -> bool {
        let (d, t) = (self.degree, &self.knots);
        let last = &t[t.len() - 1];
        t[..=d].iter().all(|k| *k == t[0]) && t[t.len() - d - 1..].iter().all(|k| k == last)
    }

    /// The distinct knots in increasing order, each with its multiplicity (how many times it
    /// occurs) [PPB, §5.1].
    ///
    /// # Complexity
    ///
    /// Θ(n + d) comparisons and O(n + d) space.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0])?;
    /// assert_eq!(t.multiplicities(), [(0.0, 3), (1.0, 2), (2.0, 3)]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn multiplicities(&self) -> Vec<(S, usize)> {
        runs(&self.knots)
            .map(|(first, run)| (self.knots[first].clone(), run))
            .collect()
    }

    /// How many knots equal `u` exactly (0 if `u` is not a knot).
    ///
    /// # Complexity
    ///
    /// O(log(n + d)) comparisons.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0])?;
    /// assert_eq!((t.multiplicity(&1.0), t.multiplicity(&0.5)), (2, 0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn multiplicity(&self, u: &S) -> usize {
        let below = self.knots.partition_point(|t| t < u);
        let upto = self.knots.partition_point(|t| t <= u);
        upto - below
    }

    /// The span of `u`: the index μ with t_μ ≤ u < t_{μ+1} and d ≤ μ < n, and at the end of
    /// the domain (u = t_n) the last non-empty span, the largest μ < n with t_μ < t_n (the
    /// closed last interval). The basis functions that do not vanish at u are
    /// N_{μ−d}, …, N_μ [PPB, §5.4].
    ///
    /// Idea: binary search over t_d, …, t_n with exact comparisons.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u` is NaN, infinite or outside the domain
    /// [t_d, t_n] (naming the value and the domain).
    ///
    /// # Complexity
    ///
    /// O(log(n − d)) time: at most ⌈log₂(n − d + 1)⌉ + 1 comparisons of u with a knot;
    /// O(1) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0])?;
    /// assert_eq!(t.span(&0.5)?, 2);
    /// assert_eq!(t.span(&1.0)?, 4); // right-continuous: t₄ = 1 ≤ u < t₅
    /// assert_eq!(t.span(&2.0)?, 4); // the closed last interval
    /// assert!(t.span(&2.5).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn span(&self, u: &S) -> Result<usize> {
        self.span_with(u, &mut NoCount)
    }

    /// [`KnotVector::span`], counting each comparison of `u` with a knot as a
    /// [`comparison`](Counter::comparison) (the domain check's two comparisons included).
    ///
    /// # Errors
    ///
    /// As [`KnotVector::span`].
    ///
    /// # Complexity
    ///
    /// O(log(n − d)) time, O(1) auxiliary space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::clamped_uniform(3, 1000, 0.0, 1.0)?;
    /// let mut c = Counts::default();
    /// let mu = t.span_with(&0.3, &mut c)?;
    /// assert!(t.knots()[mu] <= 0.3 && 0.3 < t.knots()[mu + 1]);
    /// assert!(c.comparisons <= 2 + 11);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn span_with<C: Counter>(&self, u: &S, counter: &mut C) -> Result<usize> {
        self.check_parameter(u, counter)?;
        Ok(self.span_in_domain(u, counter))
    }

    /// Checks that `u` is finite and in [t_d, t_n], counting two comparisons.
    pub(super) fn check_parameter<C: Counter>(&self, u: &S, counter: &mut C) -> Result<()> {
        validate_parameter(u, "u")?;
        counter.comparison();
        counter.comparison();
        let (start, end) = self.bounds();
        if u < start || u > end {
            return Err(self.domain().check(u, "u").unwrap_err());
        }
        Ok(())
    }

    /// The span of a `u` known to be in the domain.
    pub(super) fn span_in_domain<C: Counter>(&self, u: &S, counter: &mut C) -> usize {
        let (d, n) = (self.degree, self.control_points());
        let at_end = *u == self.knots[n];
        // Find the first index in d+1..=n whose knot is above u (or, at the end, not below
        // u); the span is the one before it. t_d ≤ u always holds, t_n > u unless at_end.
        let (mut lo, mut hi) = (d + 1, n);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            counter.comparison();
            let past = if at_end {
                self.knots[mid] >= *u
            } else {
                self.knots[mid] > *u
            };
            if past {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        lo - 1
    }
}

/// The span search, declared.
pub(crate) const SPAN: Declaration = Declaration {
    problem: "bspline",
    name: "span",
    function: "spline::KnotVector::span",
    file: "src/spline/bspline/knots.rs",
    summary: "the knot interval of a parameter by binary search with exact comparisons",
    time: "O(log(n − d))",
    space: "O(1)",
    operation: Some(Operation::Comparisons),
    counts: "at most ⌈log₂(n − d + 1)⌉ + 1 comparisons with knots, plus 2 for the domain",
    source: "[PPB, §5.4]",
    claims: &[on("random-control", Bound::Log, Operation::Comparisons)],
};

/// Checks the invariants of [`KnotVector`].
fn validate<S: Scalar>(degree: usize, knots: &[S]) -> Result<()> {
    limits::DEGREE.check(degree as u128)?;
    let needed = 2 * degree + 2;
    if knots.len() < needed {
        return Err(Error::TooFew {
            what: "knots (degree d needs 2d + 2)",
            needed,
            got: knots.len(),
        });
    }
    check_finite_and_sorted(knots)?;
    for (first, run) in runs(knots) {
        if run > degree + 1 {
            return Err(multiplicity_error(
                &knots[first],
                first,
                run,
                degree + 1,
                "degree + 1",
            ));
        }
    }
    let n = knots.len() - degree - 1;
    if knots[degree] == knots[n] {
        return Err(Error::InvalidParameter {
            name: "knots",
            reason: format!(
                "the domain [t_{degree}, t_{n}] = [{0}, {0}] is empty",
                knots[n].to_f64()
            ),
        });
    }
    Ok(())
}

/// Checks that every value is finite and none is below its predecessor (exact comparisons).
fn check_finite_and_sorted<S: Scalar>(knots: &[S]) -> Result<()> {
    if let Some(i) = knots.iter().position(|t| !t.is_finite()) {
        return Err(Error::InvalidParameter {
            name: "knots",
            reason: format!("knot {i} is not finite ({})", knots[i].to_f64()),
        });
    }
    if let Some(i) = knots.windows(2).position(|w| w[1] < w[0]) {
        return Err(Error::InvalidParameter {
            name: "knots",
            reason: format!(
                "knot {} ({}) is below knot {} ({})",
                i + 1,
                knots[i + 1].to_f64(),
                i,
                knots[i].to_f64()
            ),
        });
    }
    Ok(())
}

/// The runs of equal knots of a sorted slice: (index of the first, length).
fn runs<S: Scalar>(knots: &[S]) -> impl Iterator<Item = (usize, usize)> + '_ {
    let mut first = 0;
    std::iter::from_fn(move || {
        if first >= knots.len() {
            return None;
        }
        let start = first;
        while first < knots.len() && knots[first] == knots[start] {
            first += 1;
        }
        Some((start, first - start))
    })
}

/// The error of a knot repeated `run` times from index `first`, where `most` are allowed.
fn multiplicity_error<S: Scalar>(
    value: &S,
    first: usize,
    run: usize,
    most: usize,
    rule: &str,
) -> Error {
    Error::InvalidParameter {
        name: "knots",
        reason: format!(
            "knots {first}..={} ({}) have multiplicity {run}, more than {rule} = {most}",
            first + run - 1,
            value.to_f64()
        ),
    }
}

/// Checks a degree and a control-point count of a builder: the limits, and n ≥ d + 1.
fn check_sizes(degree: usize, control_points: usize) -> Result<(usize, usize)> {
    limits::DEGREE.check(degree as u128)?;
    limits::KNOTS.check(control_points as u128 + degree as u128 + 1)?;
    if control_points < degree + 1 {
        return Err(Error::TooFew {
            what: "control points (degree + 1 at least)",
            needed: degree + 1,
            got: control_points,
        });
    }
    Ok((control_points, degree))
}

/// Checks a builder's domain: finite ends, start < end, and a finite width (returned).
fn check_interval<S: Scalar>(start: &S, end: &S) -> Result<S> {
    validate_parameter(start, "start")?;
    validate_parameter(end, "end")?;
    if start >= end {
        return Err(Error::InvalidParameter {
            name: "end",
            reason: format!(
                "the domain needs start < end, got [{}, {}]",
                start.to_f64(),
                end.to_f64()
            ),
        });
    }
    let width = end.clone() - start;
    if !width.is_finite() {
        return Err(Error::InvalidParameter {
            name: "end",
            reason: format!(
                "the width of [{}, {}] is beyond the range of f64",
                start.to_f64(),
                end.to_f64()
            ),
        });
    }
    Ok(width)
}

/// `min(x, limit)`: keeps a rounded interior knot from passing the domain's end.
fn below<S: Scalar>(x: S, limit: &S) -> S {
    if x > *limit {
        limit.clone()
    } else {
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    #[test]
    fn validation_names_index_and_value() {
        let e = KnotVector::new(1, vec![0.0, f64::NAN, 1.0, 2.0]).unwrap_err();
        assert_eq!(e.to_string(), "invalid knots: knot 1 is not finite (NaN)");
        let e = KnotVector::new(1, vec![0.0, 1.0, f64::INFINITY, 2.0]).unwrap_err();
        assert_eq!(e.to_string(), "invalid knots: knot 2 is not finite (inf)");
        let e = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0]).unwrap_err();
        assert!(
            matches!(
                e,
                Error::TooFew {
                    needed: 6,
                    got: 5,
                    ..
                }
            ),
            "{e}"
        );
        let e = KnotVector::new(1, vec![0.0, 0.0, 0.0, 1.0]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid knots: knots 0..=2 (0) have multiplicity 3, more than degree + 1 = 2"
        );
        let e = KnotVector::new(2, vec![0.0, 1.0, 1.0, 1.0, 2.0, 3.0]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid knots: the domain [t_2, t_3] = [1, 1] is empty"
        );
        let e = KnotVector::new(limits::MAX_DEGREE + 1, vec![0.0; 4]).unwrap_err();
        assert!(matches!(
            e,
            Error::LimitExceeded {
                limit: "MAX_DEGREE",
                ..
            }
        ));
    }

    #[test]
    fn span_agrees_with_a_linear_scan() {
        let t =
            KnotVector::new(2, vec![-1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.5, 3.0, 3.0, 4.0]).unwrap();
        let (d, n) = (t.degree(), t.control_points());
        for k in 0..=60 {
            let u = k as f64 * 0.05;
            let mu = t.span(&u).unwrap();
            let k = t.knots();
            let scan = (d..n)
                .rfind(|&i| k[i] <= u && u < k[i + 1])
                .unwrap_or_else(|| (d..n).rfind(|&i| k[i] < k[i + 1]).unwrap());
            assert_eq!(mu, scan, "u = {u}");
        }
        assert!(t.span(&-0.01).is_err() && t.span(&3.01).is_err());
    }

    #[test]
    fn span_counts_at_most_a_logarithm_of_comparisons() {
        let t = KnotVector::clamped_uniform(3, 1 << 12, 0.0, 1.0).unwrap();
        for k in 0..=100 {
            let mut c = Counts::default();
            let u = k as f64 / 100.0;
            t.span_with(&u, &mut c).unwrap();
            assert!(c.comparisons <= 2 + 13, "{u}: {}", c.comparisons);
        }
    }

    #[test]
    fn builders_keep_the_domain_exactly() {
        let t = KnotVector::clamped_uniform(3, 10, 0.1, 0.7).unwrap();
        assert_eq!(t.bounds(), (&0.1, &0.7));
        let t = KnotVector::uniform(3, 10, 0.1, 0.7).unwrap();
        assert_eq!(t.bounds(), (&0.1, &0.7));
        assert!(KnotVector::uniform(3, 5, -f64::MAX, f64::MAX).is_err());
        assert!(KnotVector::clamped_uniform(3, 5, 1.0, 1.0).is_err());
        assert!(matches!(
            KnotVector::clamped_uniform(3, 3, 0.0, 1.0),
            Err(Error::TooFew {
                needed: 4,
                got: 3,
                ..
            })
        ));
        assert!(matches!(
            KnotVector::<f64>::clamped_uniform(1, usize::MAX, 0.0, 1.0),
            Err(Error::LimitExceeded {
                limit: "MAX_KNOTS",
                ..
            })
        ));
        // Near the top of the range the outer knots overflow: an error, not infinite knots.
        let e = KnotVector::uniform(2, 3, 0.0, 1e308).unwrap_err();
        assert!(e.to_string().contains("not finite"), "{e}");
    }

    #[test]
    fn averaging_follows_the_parameters() {
        let t = KnotVector::averaged(3, &[0.0, 0.1, 0.5, 0.6, 1.0, 1.0]).unwrap();
        let k = t.knots();
        assert_eq!(&k[..4], [0.0; 4]);
        assert_eq!(&k[6..], [1.0; 4]);
        assert!((k[4] - 0.4).abs() < 1e-15 && (k[5] - 0.7).abs() < 1e-15);
        let e = KnotVector::averaged(2, &[0.0, 0.5, 0.25, 1.0]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid parameters: parameter 2 (0.25) is below parameter 1 (0.5)"
        );
        assert!(KnotVector::averaged(0, &[0.0, 1.0]).is_err());
        assert!(KnotVector::averaged(2, &[1.0, 1.0, 1.0]).is_err());
    }

    #[test]
    fn the_spl_adapter_checks_its_own_indices() {
        let e = KnotVector::from_spl(2, &[0.0, 0.0, 0.0, 1.0, 2.0]).unwrap_err();
        assert!(
            e.to_string()
                .contains("knots 0..=2 (0) have multiplicity 3"),
            "{e}"
        );
        let e = KnotVector::from_spl(2, &[0.0, 1.0, 0.5, 2.0]).unwrap_err();
        assert!(
            e.to_string().contains("knot 2 (0.5) is below knot 1 (1)"),
            "{e}"
        );
        assert!(KnotVector::from_spl(0, &[0.0, 1.0]).is_err());
        assert!(matches!(
            KnotVector::from_spl(2, &[0.0, 1.0, 2.0]),
            Err(Error::TooFew {
                needed: 4,
                got: 3,
                ..
            })
        ));
    }
}
