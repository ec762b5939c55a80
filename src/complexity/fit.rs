//! Fitting measured growth against a stated bound, and the verdict.
//!
//! The course calls T(n) O(g(n)) when T(n) ≤ C·g(n) for every n ≥ n₀ (seed
//! [RD, ch. 2], "Complejidad de un algoritmo"): the ratio T(n)/g(n) stays
//! bounded. From measurements at sizes n₁ < ... < n_k the engine estimates the trend of that
//! ratio by least squares on a log-log scale:
//!
//! - the **exponent** is the slope of `ln cost` against `ln n` (2 for a quadratic algorithm);
//! - the **bound exponent** is the slope of `ln f(n)` against `ln n` over the same sizes (for
//!   O(n log n) between 64 and 4096 it is about 1.2, not 1: the log factor counts);
//! - the **excess** is the slope of `ln(cost / f(n))` against `ln n`, which by linearity of
//!   least squares equals exponent − bound exponent. It is about 0 when the bound is tight,
//!   negative when the algorithm grows more slowly (lower-order terms fading out, or a loose
//!   bound) and positive when the cost outgrows the bound.
//!
//! The verdict is [`Verdict::Exceeds`] when the excess is above a tolerance, else
//! [`Verdict::Consistent`]. Tolerances are in powers of n: an excess of 0.2 means the ratio
//! cost/f grows like n^0.2 over the measured range. `docs/complexity.md` justifies the values
//! of [`COUNT_TOLERANCE`] and [`TIME_TOLERANCE`] and what the test leaves undetected (a single
//! log factor).

use std::fmt;

use crate::complexity::Bound;
use crate::error::{Error, Result};

/// The fewest distinct sizes a fit accepts: below that, noise of ±20 % could fake a trend.
pub const MIN_SIZES: usize = 5;

/// Tolerance on the excess of exact operation counts: the verdict that counts.
///
/// With at least [`MIN_SIZES`] doubling sizes, ±20 % multiplicative noise can tilt the slope
/// by at most about 0.18, while a bound that is off by a polynomial factor n^a shows an excess
/// of about a (n² against O(n log n): about 0.8).
pub const COUNT_TOLERANCE: f64 = 0.2;

/// Tolerance on the excess of wall time, looser because caches and memory bandwidth bend
/// time curves that the operation counts do not show.
pub const TIME_TOLERANCE: f64 = 0.4;

/// Whether a measured cost grows no faster than its stated bound.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Verdict {
    /// The cost grows no faster than the bound (excess at most the tolerance).
    Consistent,
    /// The cost outgrows the bound by more than the tolerance.
    Exceeds,
}

/// One measured point: a size, the second size when the bound needs one, and a cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Observation {
    /// The input size n (at least 1).
    pub n: f64,
    /// The second size (h or m) the bound needs, if any.
    pub second: Option<f64>,
    /// The measured cost: an operation count or a time. Costs below 1 count as 1.
    pub cost: f64,
}

/// The outcome of fitting a series of observations against a bound.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// Slope of `ln cost` against `ln n`.
    pub exponent: f64,
    /// Slope of `ln f(n)` against `ln n` over the same sizes.
    pub bound_exponent: f64,
    /// Slope of `ln(cost / f(n))` against `ln n` (= `exponent - bound_exponent`).
    pub excess: f64,
    /// `cost / f(n)` for each observation, in the order given: flat when the bound is tight.
    pub normalised: Vec<f64>,
    /// The tolerance the verdict used.
    pub tolerance: f64,
    /// `Exceeds` when `excess > tolerance`.
    pub verdict: Verdict,
}

/// Fits `observations` against `bound` and judges them with `tolerance` (see the module docs).
///
/// # Errors
///
/// - [`Error::TooFew`] when fewer than [`MIN_SIZES`] distinct sizes are given;
/// - [`Error::InvalidParameter`] naming the observation when a size is below 1 or not finite,
///   a cost is negative or not finite, the bound needs a second size the observation lacks,
///   or f(n) is not positive; and when `tolerance` is negative or not finite.
///
/// # Complexity
///
/// O(k log k) time and O(k) auxiliary space for k observations (sorting sizes to count the
/// distinct ones).
///
/// # Example
///
/// ```
/// use compgeo::complexity::{fit, Bound, Observation, Verdict, COUNT_TOLERANCE};
///
/// // Bubble sort's n(n-1)/2 comparisons.
/// let obs: Vec<Observation> = [16.0, 32.0, 64.0, 128.0, 256.0]
///     .map(|n: f64| Observation { n, second: None, cost: n * (n - 1.0) / 2.0 })
///     .to_vec();
/// let quadratic = fit(Bound::Quadratic, &obs, COUNT_TOLERANCE).unwrap();
/// assert!((quadratic.exponent - 2.0).abs() < 0.05);
/// assert_eq!(quadratic.verdict, Verdict::Consistent);
/// let linear = fit(Bound::NLogN, &obs, COUNT_TOLERANCE).unwrap();
/// assert_eq!(linear.verdict, Verdict::Exceeds);
/// ```
pub fn fit(bound: Bound, observations: &[Observation], tolerance: f64) -> Result<Fit> {
    if !(tolerance.is_finite() && tolerance >= 0.0) {
        return Err(Error::InvalidParameter {
            name: "tolerance",
            reason: format!("{tolerance} is not a finite non-negative number"),
        });
    }
    let distinct = distinct_sizes(observations);
    if distinct < MIN_SIZES {
        return Err(Error::TooFew {
            what: "distinct sizes of a fit",
            needed: MIN_SIZES,
            got: distinct,
        });
    }
    let mut log_n = Vec::with_capacity(observations.len());
    let mut log_cost = Vec::with_capacity(observations.len());
    let mut log_f = Vec::with_capacity(observations.len());
    let mut normalised = Vec::with_capacity(observations.len());
    for (i, o) in observations.iter().enumerate() {
        let f = bound_value(bound, i, o)?;
        if !(o.cost.is_finite() && o.cost >= 0.0) {
            return Err(invalid(
                i,
                format!("cost {} is not finite and >= 0", o.cost),
            ));
        }
        let cost = o.cost.max(1.0);
        log_n.push(o.n.ln());
        log_cost.push(cost.ln());
        log_f.push(f.ln());
        normalised.push(cost / f);
    }
    let exponent = slope(&log_n, &log_cost);
    let bound_exponent = slope(&log_n, &log_f);
    let ratio: Vec<f64> = log_cost.iter().zip(&log_f).map(|(c, f)| c - f).collect();
    let excess = slope(&log_n, &ratio);
    let verdict = if excess > tolerance {
        Verdict::Exceeds
    } else {
        Verdict::Consistent
    };
    Ok(Fit {
        exponent,
        bound_exponent,
        excess,
        normalised,
        tolerance,
        verdict,
    })
}

/// The least-squares slope of `ys` against `xs` (both the same length, at least two distinct
/// `xs`; otherwise NaN).
///
/// ```
/// let s = compgeo::complexity::slope(&[0.0, 1.0, 2.0], &[1.0, 3.0, 5.0]);
/// assert!((s - 2.0).abs() < 1e-12);
/// ```
pub fn slope(xs: &[f64], ys: &[f64]) -> f64 {
    if xs.len() != ys.len() || xs.is_empty() {
        return f64::NAN;
    }
    let k = xs.len() as f64;
    let mx = xs.iter().sum::<f64>() / k;
    let my = ys.iter().sum::<f64>() / k;
    let sxy: f64 = xs.iter().zip(ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    if sxx > 0.0 {
        sxy / sxx
    } else {
        f64::NAN
    }
}

/// The number of bootstrap resamples behind [`exponent_interval`].
pub const BOOTSTRAP_RESAMPLES: usize = 1000;

/// A 95 % interval for the log-log slope of time, from the repetitions measured at each size.
///
/// `repeats[i]` holds the repeated measurements at size `sizes[i]` (the batch means of
/// [`measure`](crate::complexity::measure), criterion's samples). The point estimate of a size
/// is the median of its repetitions, so each of [`BOOTSTRAP_RESAMPLES`] resamples draws, at
/// every size, as many repetitions as were measured (with replacement), takes their median and
/// fits the slope of `ln time` against `ln n`; the interval is the 2.5th and 97.5th
/// percentile of those slopes (the percentile bootstrap). The resampling is seeded, so one
/// set of measurements always gives the same interval.
///
/// Exact operation counts need no interval: they are one deterministic run per size.
///
/// Returns `None` when fewer than two sizes have a positive finite repetition, or the sizes
/// do not differ.
///
/// # Complexity
///
/// O(B · Σ rᵢ log rᵢ) time for B resamples and rᵢ repetitions at size i; O(max rᵢ + k)
/// auxiliary space for k sizes.
///
/// # Example
///
/// ```
/// use compgeo::complexity::exponent_interval;
///
/// // Time doubles with n, give or take 5 %: the interval holds 1 and is narrow.
/// let sizes = [100.0, 200.0, 400.0, 800.0, 1600.0];
/// let repeats: Vec<Vec<f64>> = sizes
///     .iter()
///     .map(|n| vec![0.95 * n, 1.0 * n, 1.05 * n, 0.98 * n, 1.02 * n])
///     .collect();
/// let (lo, hi) = exponent_interval(&sizes, &repeats).unwrap();
/// assert!(lo <= 1.0 && 1.0 <= hi && hi - lo < 0.1);
/// ```
pub fn exponent_interval(sizes: &[f64], repeats: &[Vec<f64>]) -> Option<(f64, f64)> {
    let usable: Vec<(f64, Vec<f64>)> = sizes
        .iter()
        .zip(repeats)
        .filter(|(n, _)| n.is_finite() && **n >= 1.0)
        .map(|(&n, r)| {
            let positive: Vec<f64> = r
                .iter()
                .copied()
                .filter(|t| t.is_finite() && *t > 0.0)
                .collect();
            (n.ln(), positive)
        })
        .filter(|(_, r)| !r.is_empty())
        .collect();
    if usable.len() < 2 {
        return None;
    }
    let xs: Vec<f64> = usable.iter().map(|u| u.0).collect();
    let mut rng = crate::gen::Rng::new(0x5EED_B007);
    let mut draw = Vec::new();
    let mut ys = vec![0.0; usable.len()];
    let mut slopes = Vec::with_capacity(BOOTSTRAP_RESAMPLES);
    for _ in 0..BOOTSTRAP_RESAMPLES {
        for (y, (_, r)) in ys.iter_mut().zip(&usable) {
            draw.clear();
            draw.extend((0..r.len()).map(|_| r[rng.index(r.len())]));
            *y = median_of(&mut draw).ln();
        }
        let s = slope(&xs, &ys);
        if !s.is_finite() {
            return None;
        }
        slopes.push(s);
    }
    slopes.sort_by(f64::total_cmp);
    let at = |q: f64| slopes[((q * (slopes.len() - 1) as f64).round()) as usize];
    Some((at(0.025), at(0.975)))
}

/// The median of `values` (sorted in place); `values` is not empty.
pub(crate) fn median_of(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let k = values.len();
    if k % 2 == 1 {
        values[k / 2]
    } else {
        (values[k / 2 - 1] + values[k / 2]) / 2.0
    }
}

impl Verdict {
    /// `"consistent"` or `"exceeds"`, as written in `results.json`.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Consistent => "consistent",
            Verdict::Exceeds => "exceeds",
        }
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// f(n) or f(n, s) for observation `i`, checked to be a usable positive number.
fn bound_value(bound: Bound, i: usize, o: &Observation) -> Result<f64> {
    if !(o.n.is_finite() && o.n >= 1.0) {
        return Err(invalid(
            i,
            format!("size n = {} is not finite and >= 1", o.n),
        ));
    }
    let second = match bound.second_size() {
        None => None,
        Some(which) => match o.second {
            Some(s) if s.is_finite() && s >= 0.0 => Some(s),
            Some(s) => {
                return Err(invalid(
                    i,
                    format!("{} = {s} is not finite and >= 0", which.symbol()),
                ))
            }
            None => {
                return Err(invalid(
                    i,
                    format!(
                        "{bound} needs {} but the observation has none",
                        which.symbol()
                    ),
                ))
            }
        },
    };
    let f = bound.eval(o.n, second);
    if f.is_finite() && f > 0.0 {
        Ok(f)
    } else {
        Err(invalid(
            i,
            format!("{bound} evaluates to {f} at n = {}", o.n),
        ))
    }
}

fn invalid(index: usize, reason: String) -> Error {
    Error::InvalidParameter {
        name: "observation",
        reason: format!("observation {index}: {reason}"),
    }
}

fn distinct_sizes(observations: &[Observation]) -> usize {
    let mut ns: Vec<f64> = observations.iter().map(|o| o.n).collect();
    ns.sort_by(f64::total_cmp);
    ns.dedup();
    ns.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn series(f: impl Fn(f64) -> f64) -> Vec<Observation> {
        (4..10)
            .map(|k| {
                let n = f64::from(1u32 << k);
                Observation {
                    n,
                    second: None,
                    cost: f(n),
                }
            })
            .collect()
    }

    #[test]
    fn slope_of_exact_power_is_its_exponent() {
        let f = fit(Bound::Cubic, &series(|n| 5.0 * n.powi(3)), COUNT_TOLERANCE).unwrap();
        assert!((f.exponent - 3.0).abs() < 1e-9);
        assert!(f.excess.abs() < 1e-9);
        for r in &f.normalised {
            assert!((r - 5.0).abs() < 1e-9);
        }
    }

    #[test]
    fn zero_costs_count_as_one() {
        let f = fit(Bound::Linear, &series(|_| 0.0), COUNT_TOLERANCE).unwrap();
        assert_eq!(f.exponent, 0.0);
        assert_eq!(f.verdict, Verdict::Consistent);
    }

    #[test]
    fn rejects_bad_observations_by_index() {
        let mut obs = series(|n| n);
        obs[2].cost = f64::NAN;
        let e = fit(Bound::Linear, &obs, COUNT_TOLERANCE).unwrap_err();
        assert!(e.to_string().contains("observation 2"), "{e}");
        let e = fit(Bound::NH, &series(|n| n), COUNT_TOLERANCE).unwrap_err();
        assert!(e.to_string().contains("needs h"), "{e}");
        let e = fit(Bound::Linear, &series(|n| n)[..4], COUNT_TOLERANCE).unwrap_err();
        assert!(
            matches!(
                e,
                Error::TooFew {
                    needed: 5,
                    got: 4,
                    ..
                }
            ),
            "{e}"
        );
        let e = fit(Bound::Linear, &series(|n| n), -1.0).unwrap_err();
        assert!(e.to_string().contains("tolerance"), "{e}");
    }

    #[test]
    fn slope_without_spread_is_nan() {
        assert!(slope(&[1.0, 1.0], &[2.0, 3.0]).is_nan());
        assert!(slope(&[], &[]).is_nan());
    }
}
