//! The complexity engine: every algorithm proves its own growth.
//!
//! The course measures the complexity of an algorithm by counting its operations as the input
//! grows ([RD, ch. 2], "Complejidad de un algoritmo"). This module
//! turns that into a measurement:
//!
//! | step | item |
//! |---|---|
//! | what an algorithm claims | [`Bound`] (O(1) ... O(m log n)), evaluated by [`Bound::eval`] |
//! | what is registered | [`Entry`]: id, problem, input, bound, counted [`Operation`](crate::count::Operation), sizes, [`Workload`] |
//! | how it is measured | [`measure`]: exact counts and median wall time at doubling sizes |
//! | how it is judged | [`fit`]: log-log slopes, cost / f(n), [`Verdict`] |
//! | where it was measured | [`Machine`] |
//!
//! The HTML/SVG/JSON report built on top of this is [`report`] (feature `cli`, used by
//! `compgeo report`); the engine itself needs no optional dependency. `docs/complexity.md`
//! explains the method, the tolerances and the report.

mod bound;
mod catalog;
mod declaration;
mod fit;
mod machine;
mod measure;
#[cfg(feature = "cli")]
pub mod report;

pub use bound::{Bound, SecondSize};
pub use catalog::{catalog, Entry, Info, Profile, SizeRange, Workload};
pub(crate) use declaration::algorithm_family;
pub use declaration::{declarations, label, on, table, Claim, Declaration};
pub use fit::{
    exponent_interval, fit, slope, Fit, Observation, Verdict, BOOTSTRAP_RESAMPLES, COUNT_TOLERANCE,
    MIN_SIZES, TIME_TOLERANCE,
};
pub use machine::Machine;
pub use measure::{measure, measure_size, Measurement, Progress, Sample, Settings};
