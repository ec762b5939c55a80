//! Exact geometric predicates for every finite `f64` input.
//!
//! Each predicate runs in up to three stages:
//!
//! 1. **Filter.** The determinant in plain floating point with a forward error bound
//!    (Shewchuk's, plus an absolute slack for products that underflow). If the rounded value
//!    clears the bound its sign is exact. Overflow gives `inf` or NaN, which never clears the
//!    bound. Almost every call on ordinary input ends here, at the cost of the bare formula.
//!    When it fails, `orient2d` and `incircle` first try integer arithmetic: if every coordinate is an
//!    integer below 2^29 (grids, lattices) the determinant is exact in `i64` / `i128`.
//! 2. **Exact stage in the safe window.** If every nonzero operand has magnitude in the
//!    predicate's safe exponent window (see [`DEGREE_2`], [`DEGREE_4`]), floating-point
//!    expansion arithmetic is exact: `robust`'s adaptive stages for `orient2d` and
//!    `incircle`, this crate's expansions for `cmp_dist` and `cross_sign`.
//! 3. **Outside the window**, [`super::extended`] rescales the operands by an exact power of
//!    two when their exponents allow, and otherwise evaluates the polynomial in big integers
//!    on the exact binary values of the doubles.
//!
//! Stages 2 and 3 live in `#[cold]` functions so the filter inlines into callers' loops.

use super::expansion::{two_diff, Expansion};
use super::extended::{self, Predicate};
use super::{BoundingBox, Point2, PointSet};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// Declares an exact predicate: O(1) per call, counted as the operation it is. Its claims
/// are on workloads of n calls (Θ(n) in all), one per point distribution in `claims`; the
/// calls that need an exact stage are counted besides, as exact fallbacks.
pub(super) const fn predicate(
    name: &'static str,
    function: &'static str,
    file: &'static str,
    summary: &'static str,
    operation: Operation,
    claims: &'static [crate::complexity::Claim],
) -> Declaration {
    Declaration {
        problem: "predicate",
        name,
        function,
        file,
        summary,
        time: "O(1)",
        space: "O(1)",
        operation: Some(operation),
        counts: "one per call; calls the floating-point filter cannot decide also count as exact fallbacks",
        source: "[Shewchuk, §4]",
        claims,
    }
}

/// n calls on each of `kinds` (point distributions), Θ(n) in `operation`.
macro_rules! calls_on {
    ($operation:expr; $($kind:literal),+) => {
        &[$(on($kind, Bound::Linear, $operation)),+]
    };
}
pub(super) use calls_on;

/// The predicates of this file, declared.
pub(super) const DECLARATIONS: [Declaration; 5] = [
    predicate(
        "orient2d",
        "geometry::orient2d",
        "src/geometry/predicates.rs",
        "the side of a line a point lies on",
        Operation::OrientationTests,
        calls_on!(Operation::OrientationTests; "uniform-disk", "grid", "collinear", "huge"),
    ),
    predicate(
        "incircle",
        "geometry::incircle",
        "src/geometry/predicates.rs",
        "inside, on or outside the circle through three points",
        Operation::IncircleTests,
        calls_on!(Operation::IncircleTests; "uniform-disk", "grid", "collinear", "tiny"),
    ),
    predicate(
        "cmp-dist",
        "geometry::cmp_dist",
        "src/geometry/predicates.rs",
        "which of two distances is longer",
        Operation::DistanceEvaluations,
        calls_on!(Operation::DistanceEvaluations; "uniform-disk", "grid", "huge"),
    ),
    predicate(
        "cross-sign",
        "geometry::cross_sign",
        "src/geometry/predicates.rs",
        "whether one direction turns left or right of another",
        Operation::OrientationTests,
        calls_on!(Operation::OrientationTests; "uniform-disk", "collinear"),
    ),
    predicate(
        "cmp-lex",
        "geometry::cmp_lex",
        "src/geometry/predicates.rs",
        "the lexicographic order of two points",
        Operation::Comparisons,
        calls_on!(Operation::Comparisons; "uniform-disk", "grid"),
    ),
];

/// The turn made by three points, or the side of a directed line a point is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// A left turn (positive signed area): the third point is left of the directed line.
    CounterClockwise,
    /// A right turn (negative signed area): the third point is right of the directed line.
    Clockwise,
    /// Zero signed area: the points are on one line (or coincide).
    Collinear,
}

impl Orientation {
    /// The orientation of the same points in reverse order.
    ///
    /// ```
    /// use compgeo::geometry::Orientation;
    /// assert_eq!(Orientation::Clockwise.reversed(), Orientation::CounterClockwise);
    /// assert_eq!(Orientation::Collinear.reversed(), Orientation::Collinear);
    /// ```
    pub fn reversed(self) -> Orientation {
        match self {
            Orientation::CounterClockwise => Orientation::Clockwise,
            Orientation::Clockwise => Orientation::CounterClockwise,
            Orientation::Collinear => Orientation::Collinear,
        }
    }

    pub(crate) fn from_sign(sign: i32) -> Orientation {
        match sign.cmp(&0) {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Less => Orientation::Clockwise,
            Ordering::Equal => Orientation::Collinear,
        }
    }
}

/// Where a point lies relative to a circle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InCircle {
    /// Strictly inside.
    Inside,
    /// Exactly on the circle.
    On,
    /// Strictly outside.
    Outside,
}

impl InCircle {
    fn from_sign(sign: i32) -> InCircle {
        match sign.cmp(&0) {
            Ordering::Greater => InCircle::Inside,
            Ordering::Less => InCircle::Outside,
            Ordering::Equal => InCircle::On,
        }
    }
}

/// A safe exponent window: every nonzero operand has magnitude in `[2^min, 2^(max+1))`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Window {
    pub(crate) min_exp: i32,
    pub(crate) max_exp: i32,
    low: f64,
    high: f64,
}

impl Window {
    const fn new(min_exp: i32, max_exp: i32) -> Window {
        Window {
            min_exp,
            max_exp,
            low: pow2(min_exp),
            high: pow2(max_exp + 1),
        }
    }

    #[inline(always)]
    fn contains_all<const N: usize>(&self, coords: &[f64; N]) -> bool {
        // A fixed-size fold with `&` unrolls into branch-free comparisons.
        coords.iter().fold(true, |ok, &v| {
            let m = v.abs();
            ok & ((m >= self.low) & (m < self.high) | (m == 0.0))
        })
    }
}

/// `2^e` for `-1022 <= e <= 1023`.
pub(crate) const fn pow2(e: i32) -> f64 {
    assert!(-1022 <= e && e <= 1023, "pow2 takes a normal exponent");
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// Window of the degree-2 predicates (`orient2d`, `cmp_dist`, `cross_sign`): products of two
/// differences stay below 2^804, and their rounding errors, multiples of 2^-704, stay normal.
pub(crate) const DEGREE_2: Window = Window::new(-300, 400);

/// Window of `incircle` (degree 4): the lifted terms stay below 2^812 and the smallest
/// rounding errors of the exact stage, multiples of 2^-776, stay normal.
pub(crate) const DEGREE_4: Window = Window::new(-142, 200);

/// Shewchuk's bound for the rounded value of `p*q - r*s` with `p, q, r, s` rounded
/// differences: `(3 + 16 eps) eps` with `eps = 2^-53`.
const CROSS_ERRBOUND: f64 = (3.0 + 16.0 * (f64::EPSILON / 2.0)) * (f64::EPSILON / 2.0);

/// Absolute slack for rounding errors of operations that underflow: each is at most 2^-1075,
/// and no filter adds more than a few of them. 2^-1000 is far more than needed, but it is a
/// normal double: arithmetic on subnormals is slow on common hardware, and ordinary inputs
/// never come near it.
pub(crate) const UNDERFLOW_SLACK: f64 = pow2(-1000);

/// Added to each minor's permanent in `incircle`'s filter: 2^-900 times the error bound is
/// still 2^70 times the largest underflow error it has to cover, per unit of lift.
const MINOR_SLACK: f64 = pow2(-900);

/// `incircle`'s filter bound `(10 + 96 eps) eps` (Shewchuk's `iccerrboundA`).
const INCIRCLE_ERRBOUND: f64 = (10.0 + 96.0 * (f64::EPSILON / 2.0)) * (f64::EPSILON / 2.0);

/// Bound for the rounded `(p^2 + q^2) - (r^2 + s^2)` with rounded differences: each sum of
/// squares carries at most about `4 eps` relative error, the final subtraction one more `eps`;
/// `6 eps` leaves room for the rounding of the bound itself.
const DIST_ERRBOUND: f64 = 6.0 * (f64::EPSILON / 2.0);

fn sign_of(x: f64) -> i32 {
    (x > 0.0) as i32 - (x < 0.0) as i32
}

/// The orientation of the triple `(a, b, c)`: the sign of the signed area
/// `(b - a) x (c - a)`, exact for every finite input.
///
/// [`Orientation::CounterClockwise`] means `c` is strictly left of the directed line from `a`
/// to `b` (y up), [`Orientation::Clockwise`] strictly right, [`Orientation::Collinear`] on it.
///
/// # Complexity
/// O(1): a floating-point filter; near-degenerate input takes an exact adaptive stage, and
/// operands outside the safe window a rescaled or big-integer path.
///
/// ```
/// use compgeo::geometry::{orient2d, Orientation, Point2};
///
/// let a = Point2::new(0.0, 0.0);
/// let b = Point2::new(1.0, 1.0);
/// assert_eq!(orient2d(a, b, Point2::new(0.0, 1.0)), Orientation::CounterClockwise);
/// assert_eq!(orient2d(a, b, Point2::new(1.0, 0.0)), Orientation::Clockwise);
/// // Exact for every finite input, however large or small:
/// assert_eq!(orient2d(a, b, Point2::new(1e300, 1e300)), Orientation::Collinear);
/// assert_eq!(orient2d(a, b, Point2::new(5e-324, 0.0)), Orientation::Clockwise);
/// ```
#[inline]
pub fn orient2d(a: Point2, b: Point2, c: Point2) -> Orientation {
    orient2d_with(a, b, c, &mut NoCount)
}

/// [`orient2d`], counting one [`orientation_test`](Counter::orientation_test) and, when the
/// filter cannot decide, one [`exact_fallback`](Counter::exact_fallback).
///
/// # Complexity
/// O(1), as for [`orient2d`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{orient2d_with, Orientation, Point2};
///
/// let mut c = Counts::default();
/// let (a, b) = (Point2::new(0.0, 0.0), Point2::new(1.0, 1.0));
/// assert_eq!(orient2d_with(a, b, Point2::new(0.0, 1.0), &mut c), Orientation::CounterClockwise);
/// assert_eq!(orient2d_with(a, b, Point2::new(3.0, 3.0), &mut c), Orientation::Collinear);
/// assert_eq!((c.orientation_tests, c.exact_fallbacks), (2, 1)); // the tie needs the exact stage
/// ```
#[inline]
pub fn orient2d_with<C: Counter + ?Sized>(
    a: Point2,
    b: Point2,
    c: Point2,
    counter: &mut C,
) -> Orientation {
    orient2d_bounded(a, b, c, f64::INFINITY, counter)
}

/// [`orient2d_with`], first trying `static_bound` (a bound no smaller than the per-call one,
/// see [`BoxPredicates`]; infinity to skip it).
#[inline(always)]
fn orient2d_bounded<C: Counter + ?Sized>(
    a: Point2,
    b: Point2,
    c: Point2,
    static_bound: f64,
    counter: &mut C,
) -> Orientation {
    counter.orientation_test();
    let left = (a.x - c.x) * (b.y - c.y);
    let right = (a.y - c.y) * (b.x - c.x);
    let det = left - right;
    if det > static_bound {
        return Orientation::CounterClockwise;
    }
    if -det > static_bound {
        return Orientation::Clockwise;
    }
    cross_filter(left, right).unwrap_or_else(|| {
        counter.exact_fallback();
        Orientation::from_sign(exact_sign(
            Predicate::Orient2d,
            &[a.x, a.y, b.x, b.y, c.x, c.y],
        ))
    })
}

/// Where `d` lies relative to the circle through `a`, `b`, `c`, exact for every finite input.
///
/// The answer is for a counter-clockwise triangle `a, b, c`; for a clockwise one
/// [`InCircle::Inside`] and [`InCircle::Outside`] swap (the predicate is the sign of the
/// lifted determinant). If `a, b, c` are collinear the "circle" is their line, and the
/// answer tells the side of the line `d` is on ([`InCircle::On`] if `d` is on it too).
///
/// # Complexity
/// O(1), as for [`orient2d`].
///
/// ```
/// use compgeo::geometry::{incircle, InCircle, Point2};
///
/// let (a, b, c) = (Point2::new(0.0, 0.0), Point2::new(2.0, 0.0), Point2::new(0.0, 2.0));
/// assert_eq!(incircle(a, b, c, Point2::new(1.0, 1.0)), InCircle::Inside);
/// assert_eq!(incircle(a, b, c, Point2::new(2.0, 2.0)), InCircle::On);
/// assert_eq!(incircle(a, b, c, Point2::new(3.0, 3.0)), InCircle::Outside);
/// ```
#[inline]
pub fn incircle(a: Point2, b: Point2, c: Point2, d: Point2) -> InCircle {
    incircle_with(a, b, c, d, &mut NoCount)
}

/// [`incircle`], counting one [`incircle_test`](Counter::incircle_test) and, when the filter
/// cannot decide, one [`exact_fallback`](Counter::exact_fallback).
///
/// # Complexity
/// O(1), as for [`orient2d`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{incircle_with, InCircle, Point2};
///
/// let mut c = Counts::default();
/// let (a, b, d) = (Point2::new(0.0, 0.0), Point2::new(2.0, 0.0), Point2::new(0.0, 2.0));
/// assert_eq!(incircle_with(a, b, d, Point2::new(1.0, 1.0), &mut c), InCircle::Inside);
/// assert_eq!(incircle_with(a, b, d, Point2::new(2.0, 2.0), &mut c), InCircle::On);
/// assert_eq!((c.incircle_tests, c.exact_fallbacks), (2, 1));
/// ```
#[inline]
pub fn incircle_with<C: Counter + ?Sized>(
    a: Point2,
    b: Point2,
    c: Point2,
    d: Point2,
    counter: &mut C,
) -> InCircle {
    incircle_bounded(a, b, c, d, f64::INFINITY, counter)
}

/// [`orient2d`] and [`incircle`] for points of one set, with what is known of the whole set
/// precomputed: bounds of [`orient2d`]'s and [`incircle`]'s filters that hold for every
/// three or four points in the set's bounding box, so the per-call bounds can be skipped (a
/// "static" filter, as in Shewchuk's and CGAL's predicates), and whether the set is
/// small-integer, in which case both predicates are exact in plain floating point.
///
/// Why it is safe: each per-call bound is a sum of products of rounded absolute differences
/// of coordinates, every one at most the rounded width `w` of the box (rounding is
/// monotone). Evaluating the same expression with every difference replaced by `w`, in the
/// same order, therefore gives a number no smaller than any per-call bound, and a
/// determinant that clears it clears the per-call one, with the same sign. When it does
/// not, [`BoxPredicates::orient2d_with`] and [`BoxPredicates::incircle_with`] go on with
/// the per-call bound and the exact stages, so every answer is the one [`orient2d`] or
/// [`incircle`] gives.
///
/// Small-integer sets: if every coordinate is an integer and the box is at most
/// [`EXACT_INTEGER_WIDTH`] = 2^12 wide on both axes, every difference of coordinates is an
/// integer of at most 2^12, every product and lift at most 2^25 and the in-circle
/// determinant at most 12 * 2^48 < 2^53 in absolute value, so every operation of both
/// determinants is exact and their signs need no filter (integer grids, where cocircular
/// quadruples and collinear triples are everywhere, would otherwise take the exact stages).
#[derive(Debug, Clone, Copy)]
pub(crate) struct BoxPredicates {
    /// The static bound of [`orient2d`]'s filter.
    orient_bound: f64,
    /// The static bound of [`incircle`]'s filter.
    bound: f64,
    exact: bool,
}

/// The widest box of integer points whose determinants [`BoxPredicates`] evaluates exactly.
const EXACT_INTEGER_WIDTH: f64 = 4096.0;

impl BoxPredicates {
    /// The predicates for the points of `set`, with the bounds taken from the box the set
    /// recorded when it was built: O(1), plus, for a box at most [`EXACT_INTEGER_WIDTH`]
    /// wide, a pass that looks for non-integer coordinates (it stops at the first).
    pub(crate) fn for_set(set: &PointSet<'_>) -> BoxPredicates {
        let Some(bounds) = set.bounding_box() else {
            return BoxPredicates::unusable();
        };
        let mut predicates = BoxPredicates::over(bounds);
        predicates.exact = bounds.max.x - bounds.min.x <= EXACT_INTEGER_WIDTH
            && bounds.max.y - bounds.min.y <= EXACT_INTEGER_WIDTH
            && set.iter().all(|p| p.x == p.x.trunc() && p.y == p.y.trunc());
        predicates
    }

    /// The bounds for points in `bounds` (infinite, so never used, if the box's width
    /// overflows).
    pub(crate) fn over(bounds: BoundingBox) -> BoxPredicates {
        let w = (bounds.max.x - bounds.min.x).max(bounds.max.y - bounds.min.y);
        let product = w * w;
        // The shape of `cross_filter`'s bound with every |difference| = w.
        let orient_bound = CROSS_ERRBOUND * (product + product) + UNDERFLOW_SLACK;
        // The shape of `incircle_bounded`'s bound with every |difference| = w.
        let minor = product + product;
        let lift = product + product;
        let term = (minor + MINOR_SLACK) * lift;
        let permanent = term + term + term;
        BoxPredicates {
            orient_bound,
            bound: INCIRCLE_ERRBOUND * permanent + UNDERFLOW_SLACK,
            exact: false,
        }
    }

    /// Whether the set is small-integer (every coordinate an integer, the box at most
    /// 2^12 wide on both axes), so that low-degree polynomials of its coordinates'
    /// differences are exact in plain floating point.
    pub(crate) fn is_small_integer(&self) -> bool {
        self.exact
    }

    /// A filter that never decides (for callers with no box).
    pub(crate) fn unusable() -> BoxPredicates {
        BoxPredicates {
            orient_bound: f64::INFINITY,
            bound: f64::INFINITY,
            exact: false,
        }
    }

    /// [`incircle_with`] for four points in the filter's box: the same answer and counts.
    #[inline(always)]
    pub(crate) fn incircle_with<C: Counter + ?Sized>(
        &self,
        a: Point2,
        b: Point2,
        c: Point2,
        d: Point2,
        counter: &mut C,
    ) -> InCircle {
        if self.exact {
            counter.incircle_test();
            let (adx, ady, bdx, bdy) = (a.x - d.x, a.y - d.y, b.x - d.x, b.y - d.y);
            let (cdx, cdy) = (c.x - d.x, c.y - d.y);
            let alift = adx * adx + ady * ady;
            let blift = bdx * bdx + bdy * bdy;
            let clift = cdx * cdx + cdy * cdy;
            let det = alift * (bdx * cdy - cdx * bdy)
                + blift * (cdx * ady - adx * cdy)
                + clift * (adx * bdy - bdx * ady);
            return InCircle::from_sign(sign_of(det));
        }
        incircle_bounded(a, b, c, d, self.bound, counter)
    }

    /// [`orient2d_with`] for three points of the set: the same answer and counts.
    #[inline(always)]
    pub(crate) fn orient2d_with<C: Counter + ?Sized>(
        &self,
        a: Point2,
        b: Point2,
        c: Point2,
        counter: &mut C,
    ) -> Orientation {
        if self.exact {
            counter.orientation_test();
            let det = (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
            return Orientation::from_sign(sign_of(det));
        }
        orient2d_bounded(a, b, c, self.orient_bound, counter)
    }
}

/// [`incircle_with`], first trying `static_bound` (a bound no smaller than the per-call one,
/// see [`BoxPredicates`]; infinity to skip it).
#[inline(always)]
fn incircle_bounded<C: Counter + ?Sized>(
    a: Point2,
    b: Point2,
    c: Point2,
    d: Point2,
    static_bound: f64,
    counter: &mut C,
) -> InCircle {
    counter.incircle_test();
    let (adx, ady, bdx, bdy) = (a.x - d.x, a.y - d.y, b.x - d.x, b.y - d.y);
    let (cdx, cdy) = (c.x - d.x, c.y - d.y);
    let (bc, cb) = (bdx * cdy, cdx * bdy);
    let (ca, ac) = (cdx * ady, adx * cdy);
    let (ab, ba) = (adx * bdy, bdx * ady);
    let alift = adx * adx + ady * ady;
    let blift = bdx * bdx + bdy * bdy;
    let clift = cdx * cdx + cdy * cdy;
    let det = alift * (bc - cb) + blift * (ca - ac) + clift * (ab - ba);
    if det > static_bound {
        return InCircle::Inside;
    }
    if -det > static_bound {
        return InCircle::Outside;
    }
    let (pa, pb, pc) = (
        bc.abs() + cb.abs(),
        ca.abs() + ac.abs(),
        ab.abs() + ba.abs(),
    );
    // An underflowed degree-2 term (absolute error below 2^-1074) is later multiplied by a
    // lift or by a minor, and every minor is at most the sum of two lifts
    // (|xy| <= (x^2 + y^2) / 2). Adding MINOR_SLACK to each minor's permanent puts
    // `eps * MINOR_SLACK * (alift + blift + clift)` into the bound, which covers both; the
    // constant covers underflow in the final products and sums.
    let permanent =
        (pa + MINOR_SLACK) * alift + (pb + MINOR_SLACK) * blift + (pc + MINOR_SLACK) * clift;
    let bound = INCIRCLE_ERRBOUND * permanent + UNDERFLOW_SLACK;
    if det > bound {
        return InCircle::Inside;
    }
    if -det > bound {
        return InCircle::Outside;
    }
    counter.exact_fallback();
    InCircle::from_sign(exact_sign(
        Predicate::Incircle,
        &[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y],
    ))
}

/// Compares the squared distances `|ab|^2` and `|cd|^2`, exact for every finite input.
///
/// `Ordering::Less` means `a` and `b` are strictly closer to each other than `c` and `d`.
/// No distance is ever rounded, so ties are detected exactly.
///
/// # Complexity
/// O(1): a floating-point filter, then an exact expansion of at most 32 terms.
///
/// ```
/// use compgeo::geometry::{cmp_dist, Point2};
/// use std::cmp::Ordering;
///
/// let o = Point2::new(0.0, 0.0);
/// // 3-4-5: |(0,0)-(3,4)| = |(0,0)-(5,0)| exactly.
/// assert_eq!(cmp_dist(o, Point2::new(3.0, 4.0), o, Point2::new(5.0, 0.0)), Ordering::Equal);
/// assert_eq!(cmp_dist(o, Point2::new(3.0, 4.0), o, Point2::new(0.0, 6.0)), Ordering::Less);
/// ```
#[inline]
pub fn cmp_dist(a: Point2, b: Point2, c: Point2, d: Point2) -> Ordering {
    cmp_dist_with(a, b, c, d, &mut NoCount)
}

/// [`cmp_dist`], counting one [`distance_evaluation`](Counter::distance_evaluation) and,
/// when the filter cannot decide, one [`exact_fallback`](Counter::exact_fallback).
///
/// # Complexity
/// O(1), as for [`cmp_dist`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{cmp_dist_with, Point2};
/// use std::cmp::Ordering;
///
/// let mut c = Counts::default();
/// let o = Point2::new(0.0, 0.0);
/// let d = cmp_dist_with(o, Point2::new(3.0, 4.0), o, Point2::new(5.0, 0.0), &mut c);
/// assert_eq!(d, Ordering::Equal);
/// assert_eq!((c.distance_evaluations, c.exact_fallbacks), (1, 1));
/// ```
#[inline]
pub fn cmp_dist_with<C: Counter + ?Sized>(
    a: Point2,
    b: Point2,
    c: Point2,
    d: Point2,
    counter: &mut C,
) -> Ordering {
    counter.distance_evaluation();
    let (abx, aby, cdx, cdy) = (b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y);
    let ab = abx * abx + aby * aby;
    let cd = cdx * cdx + cdy * cdy;
    let diff = ab - cd;
    let bound = DIST_ERRBOUND * (ab + cd) + UNDERFLOW_SLACK;
    if diff > bound {
        Ordering::Greater
    } else if -diff > bound {
        Ordering::Less
    } else {
        counter.exact_fallback();
        exact_sign(
            Predicate::CmpDist,
            &[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y],
        )
        .cmp(&0)
    }
}

/// The sign of the cross product `(b - a) x (d - c)` of two edge vectors, exact for every
/// finite input.
///
/// [`Orientation::CounterClockwise`] means the direction `d - c` is obtained from `b - a` by a
/// counter-clockwise turn of less than half a revolution; [`Orientation::Collinear`] means the
/// edges are parallel (or one is a single point). Rotating calipers compare edge directions
/// with it, without forming the rounded point `a + (d - c)`.
///
/// # Complexity
/// O(1): a floating-point filter, then an exact expansion of at most 16 terms.
///
/// ```
/// use compgeo::geometry::{cross_sign, Orientation, Point2};
///
/// let p = |x, y| Point2::new(x, y);
/// assert_eq!(cross_sign(p(0.0, 0.0), p(1.0, 0.0), p(5.0, 5.0), p(5.0, 6.0)), Orientation::CounterClockwise);
/// assert_eq!(cross_sign(p(0.0, 0.0), p(2.0, 2.0), p(7.0, 1.0), p(8.0, 2.0)), Orientation::Collinear);
/// ```
#[inline]
pub fn cross_sign(a: Point2, b: Point2, c: Point2, d: Point2) -> Orientation {
    cross_sign_with(a, b, c, d, &mut NoCount)
}

/// [`cross_sign`], counting one [`orientation_test`](Counter::orientation_test) and, when
/// the filter cannot decide, one [`exact_fallback`](Counter::exact_fallback).
///
/// # Complexity
/// O(1), as for [`cross_sign`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{cross_sign_with, Orientation, Point2};
///
/// let p = |x, y| Point2::new(x, y);
/// let mut c = Counts::default();
/// let s = cross_sign_with(p(0.0, 0.0), p(2.0, 2.0), p(7.0, 1.0), p(8.0, 2.0), &mut c);
/// assert_eq!(s, Orientation::Collinear);
/// assert_eq!((c.orientation_tests, c.exact_fallbacks), (1, 1));
/// ```
#[inline]
pub fn cross_sign_with<C: Counter + ?Sized>(
    a: Point2,
    b: Point2,
    c: Point2,
    d: Point2,
    counter: &mut C,
) -> Orientation {
    counter.orientation_test();
    let left = (b.x - a.x) * (d.y - c.y);
    let right = (b.y - a.y) * (d.x - c.x);
    cross_filter(left, right).unwrap_or_else(|| {
        counter.exact_fallback();
        let coords = [a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y];
        Orientation::from_sign(exact_sign(Predicate::CrossSign, &coords))
    })
}

/// The filter of the degree-2 cross products: the sign of the rounded `left - right` when it
/// clears the error bound, `None` when only an exact stage can tell.
#[inline(always)]
fn cross_filter(left: f64, right: f64) -> Option<Orientation> {
    let det = left - right;
    let bound = CROSS_ERRBOUND * (left.abs() + right.abs()) + UNDERFLOW_SLACK;
    if det > bound {
        Some(Orientation::CounterClockwise)
    } else if -det > bound {
        Some(Orientation::Clockwise)
    } else {
        None
    }
}

/// Lexicographic order of points: by x, then by y. `-0.0` and `0.0` compare equal.
///
/// The comparison is exact (it compares coordinates, it computes nothing). For NaN
/// coordinates, which a [`PointSet`](super::PointSet) rejects, the order is unspecified.
///
/// # Complexity
/// O(1).
///
/// ```
/// use compgeo::geometry::{cmp_lex, Point2};
/// use std::cmp::Ordering;
///
/// assert_eq!(cmp_lex(Point2::new(0.0, 5.0), Point2::new(1.0, 0.0)), Ordering::Less);
/// assert_eq!(cmp_lex(Point2::new(1.0, 0.0), Point2::new(1.0, -1.0)), Ordering::Greater);
/// assert_eq!(cmp_lex(Point2::new(-0.0, 0.0), Point2::new(0.0, -0.0)), Ordering::Equal);
/// ```
#[inline]
pub fn cmp_lex(a: Point2, b: Point2) -> Ordering {
    cmp_lex_with(a, b, &mut NoCount)
}

/// [`cmp_lex`], counting one [`comparison`](Counter::comparison). It has no exact stage to
/// fall back to: comparing coordinates is exact.
///
/// # Complexity
/// O(1).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{cmp_lex_with, Point2};
/// use std::cmp::Ordering;
///
/// let mut c = Counts::default();
/// assert_eq!(cmp_lex_with(Point2::new(1.0, 0.0), Point2::new(1.0, 2.0), &mut c), Ordering::Less);
/// assert_eq!((c.comparisons, c.exact_fallbacks), (1, 0));
/// ```
#[inline]
pub fn cmp_lex_with<C: Counter + ?Sized>(a: Point2, b: Point2, counter: &mut C) -> Ordering {
    counter.comparison();
    cmp_coordinate(a.x, b.x).then_with(|| cmp_coordinate(a.y, b.y))
}

#[inline]
fn cmp_coordinate(a: f64, b: f64) -> Ordering {
    if a < b {
        Ordering::Less
    } else if a > b {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}

/// Stages 2 and 3: the exact sign when the filter could not decide. Each predicate gets its
/// own cold copy, so the dispatch on `predicate` folds away and the window check unrolls.
#[cold]
#[inline(never)]
fn exact_sign<const N: usize>(predicate: Predicate, coords: &[f64; N]) -> i32 {
    if let Some(sign) = small_integer_sign(predicate, coords) {
        return sign;
    }
    if predicate.window().contains_all(coords) {
        sign_in_window(predicate, coords)
    } else {
        extended::sign(predicate, coords)
    }
}

/// Coordinates below this magnitude that are integers make every difference an integer
/// below 2^30, so `orient2d` fits in `i64` and `incircle` in `i128` exactly.
const SMALL_INTEGER: f64 = pow2(29);

/// The exact sign of `orient2d` or `incircle` in integer arithmetic when every coordinate is
/// an integer of magnitude below 2^29 (integer grids and lattices: their ties, which the
/// filter cannot decide, are common), `None` otherwise. Each difference is then an exact
/// integer below 2^30: `orient2d`'s products stay below 2^60, `incircle`'s lifts and minors
/// below 2^61 and its terms below 2^122.
#[inline(always)]
fn small_integer_sign(predicate: Predicate, coords: &[f64]) -> Option<i32> {
    let small = coords
        .iter()
        .all(|&v| v.abs() < SMALL_INTEGER && (v as i64) as f64 == v);
    if !small {
        return None;
    }
    let c = |i: usize| coords[i] as i64;
    match predicate {
        Predicate::Orient2d => {
            let (acx, acy) = (c(0) - c(4), c(1) - c(5));
            let (bcx, bcy) = (c(2) - c(4), c(3) - c(5));
            Some((acx * bcy - acy * bcx).signum() as i32)
        }
        Predicate::Incircle => {
            let d = |i: usize| (i128::from(c(2 * i) - c(6)), i128::from(c(2 * i + 1) - c(7)));
            let ((ax, ay), (bx, by), (cx, cy)) = (d(0), d(1), d(2));
            let lift = |x: i128, y: i128| x * x + y * y;
            let det = lift(ax, ay) * (bx * cy - cx * by)
                + lift(bx, by) * (cx * ay - ax * cy)
                + lift(cx, cy) * (ax * by - bx * ay);
            Some(det.signum() as i32)
        }
        Predicate::CmpDist | Predicate::CrossSign => None,
    }
}

/// The exact sign for operands inside the predicate's window (also used after rescaling).
#[inline(always)]
pub(crate) fn sign_in_window(predicate: Predicate, coords: &[f64]) -> i32 {
    let p = |i: usize| robust::Coord {
        x: coords[2 * i],
        y: coords[2 * i + 1],
    };
    match predicate {
        Predicate::Orient2d => sign_of(robust::orient2d(p(0), p(1), p(2))),
        Predicate::Incircle => sign_of(robust::incircle(p(0), p(1), p(2), p(3))),
        Predicate::CmpDist => cmp_dist_in_window(coords),
        Predicate::CrossSign => cross_sign_in_window(coords),
    }
}

fn cmp_dist_in_window(coords: &[f64]) -> i32 {
    let &[ax, ay, bx, by, cx, cy, dx, dy] = coords else {
        unreachable!("cmp_dist takes four points")
    };
    let neg = |(hi, lo): (f64, f64)| (-hi, -lo);
    let (abx, aby) = (two_diff(bx, ax), two_diff(by, ay));
    let (cdx, cdy) = (two_diff(dx, cx), two_diff(dy, cy));
    let mut sum = Expansion::new();
    sum.add_product2(abx, abx);
    sum.add_product2(aby, aby);
    sum.add_product2(cdx, neg(cdx));
    sum.add_product2(cdy, neg(cdy));
    sum.signum()
}

fn cross_sign_in_window(coords: &[f64]) -> i32 {
    let &[ax, ay, bx, by, cx, cy, dx, dy] = coords else {
        unreachable!("cross_sign takes four points")
    };
    let (abx, aby) = (two_diff(bx, ax), two_diff(by, ay));
    let (cdx, cdy) = (two_diff(dx, cx), two_diff(dy, cy));
    let mut sum = Expansion::new();
    sum.add_product2(abx, cdy);
    sum.add_product2((-aby.0, -aby.1), cdx);
    sum.signum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;
    use crate::gen::Rng;

    /// Every quadruple of `pts` (up to `limit` of them, drawn at random): the box filter
    /// answers as `incircle` does and counts one in-circle test.
    /// Also `orient2d` on the first three; returns whether the set took the small-integer
    /// path.
    fn filter_agrees(pts: &[Point2], limit: usize) -> bool {
        let filter = BoxPredicates::for_set(&PointSet::new(pts).unwrap());
        let mut rng = Rng::new(11);
        let mut counts = Counts::default();
        for k in 0..limit {
            let pick = |rng: &mut Rng| pts[rng.below(pts.len() as u64) as usize];
            let [a, b, c, d] = [(); 4].map(|_| pick(&mut rng));
            let got = filter.incircle_with(a, b, c, d, &mut counts);
            assert_eq!(got, incircle(a, b, c, d), "{a:?} {b:?} {c:?} {d:?}");
            assert_eq!(counts.incircle_tests, k as u64 + 1);
            let got = filter.orient2d_with(a, b, c, &mut counts);
            assert_eq!(got, orient2d(a, b, c), "{a:?} {b:?} {c:?}");
            assert_eq!(counts.orientation_tests, k as u64 + 1);
        }
        filter.exact
    }

    #[test]
    fn small_integer_sets_take_the_plain_path_and_agree() {
        // The widest grid allowed, offset far from the origin: every determinant of the
        // corners and the middle points is at its largest.
        let side = EXACT_INTEGER_WIDTH;
        let mut pts: Vec<Point2> = [0.0, 1.0, side / 2.0, side - 1.0, side]
            .into_iter()
            .flat_map(|x| [0.0, 1.0, side / 2.0, side - 1.0, side].map(|y| (x, y)))
            .map(|(x, y)| Point2::new(x - 1e9, y + 3e12))
            .collect();
        assert!(filter_agrees(&pts, 20_000));
        // One step wider, or one coordinate off the integers: the general path.
        pts.push(Point2::new(side + 1.0 - 1e9, 3e12));
        assert!(!filter_agrees(&pts, 2000));
        pts.pop();
        pts.push(Point2::new(0.5 - 1e9, 3e12));
        assert!(!filter_agrees(&pts, 2000));
    }

    #[test]
    fn box_filter_agrees_with_incircle_at_every_scale() {
        let mut rng = Rng::new(5);
        for scale in [1e-310, 1e-200, 1e-9, 1.0, 3e5, 1e150, 1e300] {
            let pts: Vec<Point2> = (0..200)
                .map(|_| Point2::new(rng.unit() * scale, (rng.unit() - 0.5) * scale))
                .collect();
            filter_agrees(&pts, 4000);
        }
        // A box as wide as the doubles go: the width overflows and the filter never decides.
        let wide = [
            (-f64::MAX, 0.0),
            (f64::MAX, 1.0),
            (0.0, f64::MAX),
            (1.0, -1.0),
        ]
        .map(Point2::from);
        filter_agrees(&wide, 500);
        let over = BoxPredicates::over(BoundingBox::of(&wide).unwrap());
        assert_eq!(
            (over.orient_bound, over.bound),
            (f64::INFINITY, f64::INFINITY)
        );
    }

    #[test]
    fn box_filter_agrees_on_cocircular_and_nearly_cocircular_points() {
        // An integer grid: many quadruples lie exactly on one circle.
        let grid: Vec<Point2> = (0..12)
            .flat_map(|x| (0..12).map(move |y| Point2::new(f64::from(x), f64::from(y))))
            .collect();
        filter_agrees(&grid, 20_000);
        // The same grid nudged by one ulp here and there, and a small cluster far from the
        // box's corner (small determinants against a large box).
        let mut nudged = grid.clone();
        for (i, p) in nudged.iter_mut().enumerate() {
            if i % 3 == 0 {
                p.x = p.x.next_up();
            }
            if i % 5 == 0 {
                p.y = p.y.next_down();
            }
        }
        nudged
            .extend((0..30).map(|i| {
                Point2::new(1e6 + f64::from(i % 6) * 1e-7, 1e6 + f64::from(i / 6) * 1e-7)
            }));
        filter_agrees(&nudged, 20_000);
    }

    #[test]
    fn box_filter_bound_is_small_on_a_unit_box() {
        let unit = [(0.0, 0.0), (1.0, 1.0)].map(Point2::from);
        let over = BoxPredicates::over(BoundingBox::of(&unit).unwrap());
        assert!(over.bound > 0.0 && over.bound < 1e-13, "{}", over.bound);
        assert!(
            over.orient_bound > 0.0 && over.orient_bound < 1e-15,
            "{}",
            over.orient_bound
        );
    }
}
