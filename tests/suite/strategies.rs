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
