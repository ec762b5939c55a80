//! The proptest strategies the suites share: point sets biased towards the inputs that break
//! geometry code.

use compgeo::geometry::Point2;
use proptest::prelude::*;
use std::ops::{Range, RangeInclusive};

/// Integer points with both coordinates in `coords`, `len` of them: on a coarse lattice,
/// duplicates, collinear triples and cocircular quadruples are common.
pub fn lattice(
    coords: RangeInclusive<i32>,
    len: Range<usize>,
) -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((coords.clone(), coords), len).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Point2::new(f64::from(x), f64::from(y)))
            .collect()
    })
}

/// Points uniform in `[-r, r)²`, `len` of them: general position, almost surely.
pub fn uniform(r: f64, len: Range<usize>) -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-r..r, -r..r), len)
        .prop_map(|v| v.into_iter().map(Point2::from).collect())
}

/// Points whose coordinates mix magnitudes from subnormal (2^-1074) to near `f64::MAX`
/// (2^1000 times a small integer), `len` of them, with signs and zeros.
pub fn mixed_magnitudes(len: Range<usize>) -> impl Strategy<Value = Vec<Point2>> {
    let coord = (
        -1i32..=1,
        1u32..4,
        prop::sample::select(vec![-1074, -600, -3, 0, 5, 300, 1000]),
    )
        .prop_map(|(sign, m, e)| f64::from(sign) * f64::from(m) * 2f64.powi(e));
    prop::collection::vec((coord.clone(), coord), len)
        .prop_map(|v| v.into_iter().map(Point2::from).collect())
}

/// Finite coordinates at the ends of the double range and between: `±f64::MAX` and a few
/// ulps below it, powers of two times small integers from 2^-1074 to 2^1020, subnormals, and
/// any finite double. Differences, lengths and areas of such points overflow `f64` or
/// underflow it.
pub fn extreme_coordinate() -> impl Strategy<Value = f64> {
    let pow2 = |e: i32| {
        if e >= -1022 {
            f64::from_bits(((e + 1023) as u64) << 52)
        } else {
            f64::from_bits(1 << (e + 1074))
        }
    };
    let signed = |v: f64, negative: bool| if negative { -v } else { v };
    prop_oneof![
        (0u64..4, any::<bool>())
            .prop_map(move |(k, n)| signed(f64::from_bits(f64::MAX.to_bits() - k), n)),
        (
            -8i32..=8,
            prop::sample::select(vec![-1074, -1060, -1022, -500, -1, 0, 1, 500, 1000, 1020])
        )
            .prop_map(move |(m, e)| f64::from(m) * pow2(e)),
        (1u64..1 << 20, any::<bool>()).prop_map(move |(k, n)| signed(f64::from_bits(k), n)),
        any::<f64>().prop_filter("finite", |v| v.is_finite()),
    ]
}

/// `len` points with [`extreme_coordinate`] coordinates.
pub fn extreme_points(len: Range<usize>) -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((extreme_coordinate(), extreme_coordinate()), len)
        .prop_map(|v| v.into_iter().map(Point2::from).collect())
}
