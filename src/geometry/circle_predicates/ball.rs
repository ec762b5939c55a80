//! Midpoint–radius arithmetic for the filters of the circle predicates: a value with a
//! rigorous bound on its distance to the exact result, through every rounding (underflow
//! included, by an absolute slack) and with overflow deciding nothing.

use super::{times_pow2, GROW, SLACK, U};
use crate::geometry::extended::exponent;
use std::cmp::Ordering;

/// A value and a bound on its distance to an exact real (midpoint–radius arithmetic): every
/// operation returns a ball that holds the exact result of the operation on any values in
/// its operands' balls. Non-finite parts (overflow) decide nothing.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ball {
    pub(super) mid: f64,
    pub(super) rad: f64,
}

impl Ball {
    /// `a − b` for doubles: rounding to nearest errs by at most `U` times the result (and
    /// not at all when the result is subnormal).
    #[inline]
    pub(super) fn diff(a: f64, b: f64) -> Ball {
        let mid = a - b;
        Ball {
            mid,
            rad: U * mid.abs(),
        }
    }

    /// Times `2^k`: exact unless it underflows (an error below 2^-1075, covered by SLACK).
    #[inline]
    pub(super) fn scaled(self, k: i32) -> Ball {
        Ball {
            mid: times_pow2(self.mid, k),
            rad: times_pow2(self.rad, k) + SLACK,
        }
    }

    #[inline]
    pub(super) fn add(self, o: Ball) -> Ball {
        let mid = self.mid + o.mid;
        Ball {
            mid,
            rad: (self.rad + o.rad + U * mid.abs()) * GROW + SLACK,
        }
    }

    #[inline]
    pub(super) fn sub(self, o: Ball) -> Ball {
        self.add(Ball {
            mid: -o.mid,
            rad: o.rad,
        })
    }

    /// `|xy − m₁m₂| <= r₁ |m₂| + |m₁| r₂ + r₁ r₂`, plus the product's rounding.
    #[inline]
    pub(super) fn mul(self, o: Ball) -> Ball {
        let mid = self.mid * o.mid;
        let rad =
            self.rad * o.mid.abs() + self.mid.abs() * o.rad + self.rad * o.rad + U * mid.abs();
        Ball {
            mid,
            rad: rad * GROW + SLACK,
        }
    }

    /// Exact (doubling changes only the exponent; overflow shows as infinity).
    #[inline]
    pub(super) fn twice(self) -> Ball {
        Ball {
            mid: 2.0 * self.mid,
            rad: 2.0 * self.rad,
        }
    }

    /// `|x / y − m₁ / m₂| <= (r₁ + |m₁ / m₂| r₂) / (|m₂| − r₂)` when `|m₂| > r₂`; `None`
    /// when the divisor's ball holds zero.
    #[inline]
    pub(super) fn div(self, o: Ball) -> Option<Ball> {
        let gap = o.mid.abs() - o.rad;
        // False for NaN too.
        let excludes_zero = gap > 0.0;
        if !excludes_zero {
            return None;
        }
        let mid = self.mid / o.mid;
        // |m1 / m2| <= |mid| (1 + U) + 2^-1075: SLACK stands for the underflow part.
        let rad = (self.rad + (mid.abs() + SLACK) * o.rad) / gap + U * mid.abs();
        Some(Ball {
            mid,
            rad: rad * GROW + SLACK,
        })
    }

    /// The sign of every value in the ball, if they share one.
    #[inline]
    pub(super) fn sign(self) -> Option<Ordering> {
        if self.mid > self.rad {
            Some(Ordering::Greater)
        } else if -self.mid > self.rad {
            Some(Ordering::Less)
        } else {
            None
        }
    }
}

/// The differences `x − y` of the pairs as balls, all times one power of two `2^k` that puts
/// the largest into `[1, 2)`, with `k`; `None` if they are all zero or one overflows.
#[inline]
pub(super) fn scaled_differences<const N: usize>(
    pairs: [(f64, f64); N],
) -> Option<([Ball; N], i32)> {
    let balls = pairs.map(|(x, y)| Ball::diff(x, y));
    let m = balls.iter().fold(0.0f64, |m, b| m.max(b.mid.abs()));
    // Written so that NaN fails too.
    if !(m > 0.0 && m < f64::INFINITY) {
        return None;
    }
    let k = -exponent(m);
    Some((balls.map(|b| b.scaled(k)), k))
}
