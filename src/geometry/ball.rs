//! Midpoint–radius arithmetic: a value with a rigorous bound on its distance to the exact
//! result, through every rounding (underflow included, by an absolute slack) and with
//! overflow deciding nothing. The filters of the circle predicates and the certified
//! constructions (`construct.rs`) run on it.

use super::extended::{exponent, scale_by_pow2};
use super::predicates::UNDERFLOW_SLACK;
use std::cmp::Ordering;

/// The unit roundoff 2^-53: a rounding to nearest errs by at most `U` times the result.
pub(crate) const U: f64 = f64::EPSILON / 2.0;

/// Absolute slack for roundings that underflow (each errs by at most 2^-1075; the slack is
/// 2^-1000, a normal double, as arithmetic on subnormals is slow).
pub(crate) const SLACK: f64 = UNDERFLOW_SLACK;

/// Factor that covers the roundings of an error bound's own evaluation (at most six, each
/// relative `U`, where it is used).
pub(crate) const GROW: f64 = 1.0 + 8.0 * U;

/// `v · 2^k`, exact when the result is a normal double; one multiplication in the common
/// case.
#[inline]
pub(crate) fn times_pow2(v: f64, k: i32) -> f64 {
    if (-1022..=1023).contains(&k) {
        v * f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        scale_by_pow2(v, k)
    }
}

/// A value and a bound on its distance to an exact real (midpoint–radius arithmetic): every
/// operation returns a ball that holds the exact result of the operation on any values in
/// its operands' balls. Non-finite parts (overflow) decide nothing.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Ball {
    pub(crate) mid: f64,
    pub(crate) rad: f64,
}

impl Ball {
    /// `a − b` for doubles: rounding to nearest errs by at most `U` times the result (and
    /// not at all when the result is subnormal).
    #[inline]
    pub(crate) fn diff(a: f64, b: f64) -> Ball {
        let mid = a - b;
        Ball {
            mid,
            rad: U * mid.abs(),
        }
    }

    /// Times `2^k`: exact unless it underflows (an error below 2^-1075, covered by SLACK).
    #[inline]
    pub(crate) fn scaled(self, k: i32) -> Ball {
        Ball {
            mid: times_pow2(self.mid, k),
            rad: times_pow2(self.rad, k) + SLACK,
        }
    }

    #[inline]
    pub(crate) fn add(self, o: Ball) -> Ball {
        let mid = self.mid + o.mid;
        Ball {
            mid,
            rad: (self.rad + o.rad + U * mid.abs()) * GROW + SLACK,
        }
    }

    #[inline]
    pub(crate) fn sub(self, o: Ball) -> Ball {
        self.add(Ball {
            mid: -o.mid,
            rad: o.rad,
        })
    }

    /// `|xy − m₁m₂| <= r₁ |m₂| + |m₁| r₂ + r₁ r₂`, plus the product's rounding.
    #[inline]
    pub(crate) fn mul(self, o: Ball) -> Ball {
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
    pub(crate) fn twice(self) -> Ball {
        Ball {
            mid: 2.0 * self.mid,
            rad: 2.0 * self.rad,
        }
    }

    /// `|x / y − m₁ / m₂| <= (r₁ + |m₁ / m₂| r₂) / (|m₂| − r₂)` when `|m₂| > r₂`; `None`
    /// when the divisor's ball holds zero.
    #[inline]
    pub(crate) fn div(self, o: Ball) -> Option<Ball> {
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
    pub(crate) fn sign(self) -> Option<Ordering> {
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
pub(crate) fn scaled_differences<const N: usize>(
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
