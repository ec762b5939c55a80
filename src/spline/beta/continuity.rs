//! The β-continuity (G²) conditions at the joint of two cubic segments.
//!
//! The problem: whether two pieces Q⁻ (ending at the joint) and Q⁺ (starting there) meet with
//! the geometric continuity of a Beta-spline with parameters β₁, β₂ [CCKS, §3]:
//!
//! 1. Q⁻ = Q⁺ (position);
//! 2. β₁·Q⁻′ = Q⁺′ (the tangent keeps its direction; the speed may change by β₁);
//! 3. β₁²·Q⁻″ + β₂·Q⁻′ = Q⁺″ (the curvature vector is continuous).
//!
//! With β₁ = 1 and β₂ = 0 they are C² continuity. The idea: compare the three pairs of
//! points exactly (no tolerance: with rationals the answer is exact; with `f64` rounding can
//! break an equality that holds mathematically).
//!
//! Follows [CCKS, §3] (after Barsky and Beatty).
//!
//! # Complexity
//!
//! O(D).
//!
//! Invariants the tests check: consecutive segments of every Beta-spline pass; a perturbed
//! point fails; a passing join with Q⁻′ ≠ 0 has equal curvature vectors from both sides.

use super::BetaParameters;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};

/// The joint check, declared.
pub(crate) const CONTINUITY: Declaration = Declaration {
    problem: "beta-spline",
    name: "beta-continuity",
    function: "spline::is_beta_continuous",
    file: "src/spline/beta/continuity.rs",
    summary:
        "whether two pieces meet with β-continuity: equal points, β₁Q⁻′ = Q⁺′, β₁²Q⁻″ + β₂Q⁻′ = Q⁺″",
    time: "O(D)",
    space: "O(D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly 3 point operations (β₁Q⁻′ and the two terms of β₁²Q⁻″ + β₂Q⁻′), then at most 3 comparisons of points",
    source: "[CCKS, §3]",
    claims: &[on(
        "random-control",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// `true` if the pieces meet with β-continuity (G² with the shape parameters β₁, β₂ of
/// `parameters`): `left` holds Q⁻, Q⁻′, Q⁻″ at the joint's left side and `right` Q⁺, Q⁺′, Q⁺″
/// at its right side [CCKS, §3, conditions i–iii].
///
/// # Complexity
///
/// O(D) time, O(D) space.
///
/// ```
/// use compgeo::spline::{is_beta_continuous, BetaParameters, Point};
///
/// let p = BetaParameters::new(2.0, 1.0)?;
/// let pt = |x: f64, y: f64| Point::new([x, y]);
/// let left = [pt(1.0, 1.0), pt(1.0, 0.0), pt(0.0, 1.0)];
/// // Q⁺′ = 2·(1, 0); Q⁺″ = 4·(0, 1) + 1·(1, 0).
/// let right = [pt(1.0, 1.0), pt(2.0, 0.0), pt(1.0, 4.0)];
/// assert!(is_beta_continuous(&left, &right, &p));
/// assert!(!is_beta_continuous(&left, &[pt(1.0, 1.0), pt(1.0, 0.0), pt(1.0, 4.0)], &p));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn is_beta_continuous<S: Scalar, const D: usize>(
    left: &[Point<S, D>; 3],
    right: &[Point<S, D>; 3],
    parameters: &BetaParameters<S>,
) -> bool {
    is_beta_continuous_with(left, right, parameters, &mut NoCount)
}

/// [`is_beta_continuous`], counting its three
/// [`arithmetic_operation`](Counter::arithmetic_operation)s on points (β₁Q⁻′, and β₁²Q⁻″ and
/// β₂Q⁻′ summed) and one [`comparison`](Counter::comparison) per pair of points compared,
/// in order, until one differs (at most three).
///
/// # Complexity
///
/// O(D) time, O(D) space.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{is_beta_continuous_with, BetaParameters, Point};
///
/// let p = BetaParameters::new(2.0, 1.0)?;
/// let pt = |x: f64, y: f64| Point::new([x, y]);
/// let left = [pt(1.0, 1.0), pt(1.0, 0.0), pt(0.0, 1.0)];
/// let mut c = Counts::default();
/// assert!(!is_beta_continuous_with(&left, &[pt(0.0, 1.0), pt(2.0, 0.0), pt(1.0, 4.0)], &p, &mut c));
/// assert_eq!((c.arithmetic_operations, c.comparisons), (3, 1)); // the points differ
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn is_beta_continuous_with<S: Scalar, const D: usize, C: Counter>(
    left: &[Point<S, D>; 3],
    right: &[Point<S, D>; 3],
    parameters: &BetaParameters<S>,
    counter: &mut C,
) -> bool {
    let b1 = parameters.beta1();
    let b2 = parameters.beta2();
    let tangent = left[1].clone() * b1;
    let curvature = left[2].clone() * &(b1.clone() * b1) + &(left[1].clone() * b2);
    for _ in 0..3 {
        counter.arithmetic_operation();
    }
    for (a, b) in [
        (&left[0], &right[0]),
        (&tangent, &right[1]),
        (&curvature, &right[2]),
    ] {
        counter.comparison();
        if a != b {
            return false;
        }
    }
    true
}
