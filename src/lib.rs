//! # compgeo
//!
//! Exact computational-geometry and geometric-modelling algorithms that count their
//! operations and measure their own growth against their stated O-bounds.
//!
//! ## Module map
//!
//! | module | what it holds |
//! |---|---|
//! | [`geometry`] | [`Point2`](geometry::Point2), exact predicates, validation |
//! | [`count`] | the [`Counter`](count::Counter) trait, [`Counts`](count::Counts), [`NoCount`](count::NoCount) |
//! | [`error`] | the crate's [`Error`] and [`Result`] |
//! | [`gen`] | seeded workload generators: point sets, graphs, number sequences |
//! | [`complexity`] | stated bounds, the catalog of algorithms, measurement, fits and verdicts |
//! | [`sort`] | the course's sorts, O(n log n) references, radix sort for `f64`, step traces |
//!
//! ## Algorithms and their bounds
//!
//! n is the input size. Bounds are worst case unless marked otherwise; the counted operation
//! is the one each algorithm's `# Counts` section names.
//!
//! | algorithm | bound |
//! |---|---|
//! | [`sort::bubble_sort`] | Θ(n²) time, exactly n(n−1)/2 comparisons |
//! | [`sort::selection_sort`] | Θ(n²) time, exactly n(n−1)/2 comparisons |
//! | [`sort::insertion_sort`] | Θ(n²) time, at most n(n−1)/2 comparisons |
//! | [`sort::binary_insertion_sort`] | O(n log n) comparisons, O(n²) time (moves) |
//! | [`sort::merge_sort`] | Θ(n log n) time, at most n⌈log₂ n⌉ comparisons |
//! | [`sort::heap_sort`] | O(n log n) time, at most 2n log₂ n comparisons |
//! | [`sort::quick_sort`] | O(n log n) time (introsort), at most 6n log₂ n + n comparisons |
//! | [`sort::radix_sort_f64`] | Θ(n) time, 8 passes, no comparisons |
//!
//! ## Conventions
//!
//! The plane is oriented with y up: a counter-clockwise turn is positive. Every finite `f64`
//! is valid input; NaN and infinities are rejected with [`Error::NonFinite`].

pub mod calipers;
pub mod complexity;
pub mod count;
pub mod error;
pub mod gen;
pub mod geometry;
pub mod hull;
pub mod sort;

#[cfg(feature = "cli")]
pub mod cli;

pub use error::{Error, Result};
