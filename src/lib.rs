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
//!
//! ## Conventions
//!
//! The plane is oriented with y up: a counter-clockwise turn is positive. Every finite `f64`
//! is valid input; NaN and infinities are rejected with [`Error::NonFinite`].

pub mod complexity;
pub mod count;
pub mod error;
pub mod gen;
pub mod geometry;

#[cfg(feature = "cli")]
pub mod cli;

pub use error::{Error, Result};
