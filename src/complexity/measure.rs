//! Measuring an entry: exact counts and wall time at geometrically growing sizes.
//!
//! For every size n the engine prepares the input once (untimed), runs the algorithm once on a
//! fresh clone with [`Counts`] (exact counts, and h or m when the workload reports them), then
//! times it with [`NoCount`](crate::count::NoCount):
//!
//! 1. **calibrate**: run batches of k runs, each on its own clone made before the clock
//!    starts, growing k until one batch lasts [`Settings::batch_time`] (or k reaches
//!    [`Settings::max_batch_elements`] / n, to bound memory);
//! 2. **measure**: run [`Settings::batches`] batches of k runs; the time of a size is the
//!    median over batches of the batch mean (total / k).
//!
//! Batching makes sizes of a few dozen elements measurable (one run is shorter than the
//! clock's resolution); the median discards batches hit by interruptions. Inputs and outputs go
//! through [`std::hint::black_box`] so the optimiser can neither precompute nor discard a run.

use std::time::Duration;

use crate::complexity::catalog::{Entry, Info, Prepared, Profile};
use crate::complexity::fit::{
    exponent_interval, fit, median_of, Fit, Observation, COUNT_TOLERANCE, TIME_TOLERANCE,
};
use crate::complexity::Bound;
use crate::count::Counts;
use crate::error::Result;

/// The measurement of one entry at one size.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// The input size.
    pub n: usize,
    /// The output size h, when the workload reports it.
    pub h: Option<usize>,
    /// The number of edges m, when the workload reports it.
    pub m: Option<usize>,
    /// Wall time of one uncounted run, in nanoseconds (median of batch means).
    pub time_ns: f64,
    /// The batch means the median was taken over, in nanoseconds, in the order measured:
    /// the repetitions behind [`Measurement::time_interval`].
    pub time_repeats_ns: Vec<f64>,
    /// Exact counts of one run.
    pub counts: Counts,
}

/// How long and how often to time each size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Settings {
    /// Seed handed to every workload's generator.
    pub seed: u64,
    /// Calibration target: the shortest duration of one timed batch.
    pub batch_time: Duration,
    /// Number of timed batches per size (the median is taken over them).
    pub batches: usize,
    /// Cap on k·n, the elements cloned for one batch of k runs at size n.
    pub max_batch_elements: usize,
}

/// Where a run is: passed to the progress callback after each size.
#[derive(Debug, Clone, Copy)]
pub struct Progress<'a> {
    /// The entry being measured.
    pub info: &'a Info,
    /// The size just measured.
    pub n: usize,
    /// Sizes of this entry measured so far (1-based).
    pub done: usize,
    /// Sizes of this entry in total.
    pub total: usize,
}

/// An entry's samples and the fits of its counts and times against its bound.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    /// What was measured.
    pub info: Info,
    /// One sample per size, increasing n.
    pub samples: Vec<Sample>,
    /// Fit of the counted operation, with [`COUNT_TOLERANCE`]: the verdict.
    pub counts: Fit,
    /// Fit of wall time, with [`TIME_TOLERANCE`]: reported alongside.
    pub time: Fit,
    /// A 95 % interval of the exponent of time, bootstrapped from the repetitions of each
    /// size ([`exponent_interval`]); `None` with fewer than two usable sizes.
    pub time_interval: Option<(f64, f64)>,
}

/// Measures `entry` at one size: exact counts of one run and the median time per run.
///
/// # Errors
///
/// What the entry's generator or algorithm reports.
///
/// # Complexity
///
/// One counted run, then runs until about `(batches + 2) · batch_time` has elapsed (at least
/// `batches + 1` runs); auxiliary space k clones of the input and k outputs, k ≤
/// `max(1, max_batch_elements / n)`.
pub fn measure_size(entry: &Entry, n: usize, settings: &Settings) -> Result<Sample> {
    let prepared = entry.prepare(n, settings.seed)?;
    let counted = prepared.count()?;
    let time_repeats_ns = batch_means(prepared.as_ref(), n, settings);
    Ok(Sample {
        n,
        h: counted.h,
        m: counted.m,
        time_ns: median_of(&mut time_repeats_ns.clone()),
        time_repeats_ns,
        counts: counted.counts,
    })
}

/// Measures `entry` at each of `sizes` and fits counts and time against its bound;
/// `progress` is called after each size.
///
/// Measure a catalog entry under a profile with `measure(entry, &entry.sizes(profile), ...)`.
///
/// # Errors
///
/// What the entry's generator or algorithm reports, and the errors of [`fit`] (fewer than
/// [`MIN_SIZES`](crate::complexity::MIN_SIZES) sizes; a bound in h or m whose workload does not
/// report that size).
///
/// # Complexity
///
/// [`measure_size`] once per size.
///
/// # Example
///
/// ```
/// use std::time::Duration;
/// use compgeo::complexity::{measure, Bound, Entry, Settings, Verdict, Workload};
/// use compgeo::count::{Counter, Operation};
///
/// /// Compares every pair once: n(n-1)/2 comparisons.
/// struct AllPairs;
/// impl Workload for AllPairs {
///     type Input = usize;
///     type Output = ();
///     fn prepare(&self, n: usize, _seed: u64) -> compgeo::Result<usize> {
///         Ok(n)
///     }
///     fn run<C: Counter>(&self, n: &mut usize, c: &mut C) -> compgeo::Result<()> {
///         for i in 0..*n {
///             for _ in i + 1..*n {
///                 c.comparison();
///             }
///         }
///         Ok(())
///     }
/// }
///
/// let entry = Entry::new("pairs/all", Bound::Quadratic, Operation::Comparisons, AllPairs);
/// let settings = Settings { batch_time: Duration::from_micros(20), batches: 3, ..Settings::default() };
/// let m = measure(&entry, &[8, 16, 32, 64, 128], &settings, &mut |_| {}).unwrap();
/// assert_eq!(m.samples[4].counts.comparisons, 128 * 127 / 2);
/// assert_eq!(m.counts.verdict, Verdict::Consistent);
/// ```
pub fn measure(
    entry: &Entry,
    sizes: &[usize],
    settings: &Settings,
    progress: &mut dyn FnMut(Progress<'_>),
) -> Result<Measurement> {
    let mut samples = Vec::with_capacity(sizes.len());
    for (i, &n) in sizes.iter().enumerate() {
        samples.push(measure_size(entry, n, settings)?);
        progress(Progress {
            info: &entry.info,
            n,
            done: i + 1,
            total: sizes.len(),
        });
    }
    Measurement::new(entry.info.clone(), samples)
}

impl Sample {
    /// The second size `bound` needs (h or m) as a number, if the sample has it.
    pub fn second(&self, bound: Bound) -> Option<f64> {
        use crate::complexity::SecondSize;
        let s = match bound.second_size()? {
            SecondSize::Output => self.h?,
            SecondSize::Edges => self.m?,
        };
        Some(s as f64)
    }
}

impl Settings {
    /// The settings a profile uses: quick = 2 ms batches, 5 of them; full = 10 ms batches,
    /// 11 of them. Both use seed 1 and at most 2²⁰ cloned elements per batch.
    pub fn for_profile(profile: Profile) -> Settings {
        match profile {
            Profile::Quick => Settings::default(),
            Profile::Full => Settings {
                batch_time: Duration::from_millis(10),
                batches: 11,
                ..Settings::default()
            },
        }
    }
}

impl Default for Settings {
    /// The quick profile's settings.
    fn default() -> Settings {
        Settings {
            seed: 1,
            batch_time: Duration::from_millis(2),
            batches: 5,
            max_batch_elements: 1 << 20,
        }
    }
}

impl Measurement {
    /// Fits `samples` of the entry described by `info`: counts of `info.operation` with
    /// [`COUNT_TOLERANCE`], times with [`TIME_TOLERANCE`].
    ///
    /// # Errors
    ///
    /// The errors of [`fit`].
    pub fn new(info: Info, samples: Vec<Sample>) -> Result<Measurement> {
        let observe = |cost: &dyn Fn(&Sample) -> f64| -> Vec<Observation> {
            samples
                .iter()
                .map(|s| Observation {
                    n: s.n as f64,
                    second: s.second(info.bound),
                    cost: cost(s),
                })
                .collect()
        };
        let counts = fit(
            info.bound,
            &observe(&|s| s.counts.get(info.operation) as f64),
            COUNT_TOLERANCE,
        )?;
        let time = fit(info.bound, &observe(&|s| s.time_ns), TIME_TOLERANCE)?;
        let sizes: Vec<f64> = samples.iter().map(|s| s.n as f64).collect();
        let repeats: Vec<Vec<f64>> = samples.iter().map(|s| s.time_repeats_ns.clone()).collect();
        let time_interval = exponent_interval(&sizes, &repeats);
        Ok(Measurement {
            info,
            samples,
            counts,
            time,
            time_interval,
        })
    }
}

/// The mean time per run of each of `settings.batches` timed batches, in nanoseconds.
fn batch_means(prepared: &dyn Prepared, n: usize, settings: &Settings) -> Vec<f64> {
    let cap = (settings.max_batch_elements / n.max(1)).max(1);
    let target = settings.batch_time.as_secs_f64();
    let mut k = 1usize;
    loop {
        let t = prepared.time(k).as_secs_f64();
        if t >= target || k >= cap {
            break;
        }
        let factor = if t > 0.0 {
            (1.2 * target / t).clamp(2.0, 16.0)
        } else {
            16.0
        };
        k = ((k as f64 * factor).ceil() as usize).min(cap);
    }
    (0..settings.batches.max(1))
        .map(|_| prepared.time(k).as_nanos() as f64 / k as f64)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even() {
        assert_eq!(median_of(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median_of(&mut [4.0, 1.0, 3.0, 2.0]), 2.5);
    }
}
