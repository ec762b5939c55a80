//! Seeded number sequences for the sorting algorithms.

use super::rng::Rng;
use crate::error::Result;
use crate::limits;
use crate::util::named_enum;

named_enum! {
    /// The order a sequence of keys comes in. See [`sequence`] for the values.
    ///
    /// Names are `random`, `sorted`, `reversed`, `few-distinct`.
    ///
    /// ```
    /// use compgeo::gen::SequenceKind;
    ///
    /// assert_eq!("few-distinct".parse::<SequenceKind>()?, SequenceKind::FewDistinct);
    /// assert_eq!(SequenceKind::Reversed.name(), "reversed");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum SequenceKind ("sequence kind") {
        /// Independent uniform keys.
        Random = "random",
        /// Strictly increasing keys.
        Sorted = "sorted",
        /// Strictly decreasing keys.
        Reversed = "reversed",
        /// Keys drawn from a set of 8 distinct values.
        FewDistinct = "few-distinct",
    }
}

/// The largest magnitude of a [`SequenceKind::Random`] key: 2^53, so every key is exact as
/// an `f64` too.
pub const RANDOM_KEY_BOUND: i64 = 1 << 53;

/// `n` integer keys of the given kind, the same for the same `seed` on every machine.
///
/// - `Random`: independent keys uniform in `[-2^53, 2^53]` ([`RANDOM_KEY_BOUND`]).
/// - `Sorted`: a strictly increasing random walk: a start uniform in `[-2^52, 0]` plus
///   gaps uniform in `1..=1024` (for every `n <= 2^32` all keys stay within `2^53`).
/// - `Reversed`: exactly `Sorted` with the same seed, reversed (strictly decreasing).
/// - `FewDistinct`: 8 distinct values uniform in `[-2^53, 2^53]`, each key one of them
///   chosen uniformly (so fewer than 8 may appear when `n` is small).
///
/// Sorting algorithms' worst and best cases (`Reversed`, `Sorted`) and duplicate handling
/// (`FewDistinct`) follow the course's sorting section ([RD, §2.1] "Algoritmos de
/// ordenación").
///
/// # Errors
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `n` exceeds
/// [`MAX_KEYS`](crate::limits::MAX_KEYS), before anything is allocated.
///
/// # Complexity
/// O(n) time and space.
///
/// Counts nothing: generators are workloads, not measured algorithms.
///
/// ```
/// use compgeo::gen::{sequence, SequenceKind};
///
/// let up = sequence(SequenceKind::Sorted, 100, 3)?;
/// assert!(up.windows(2).all(|w| w[0] < w[1]));
/// let mut down = sequence(SequenceKind::Reversed, 100, 3)?;
/// down.reverse();
/// assert_eq!(down, up);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn sequence(kind: SequenceKind, n: usize, seed: u64) -> Result<Vec<i64>> {
    limits::KEYS.check(n as u128)?;
    let mut rng = Rng::new(seed);
    Ok(match kind {
        SequenceKind::Random => (0..n).map(|_| random_key(&mut rng)).collect(),
        SequenceKind::Sorted => ascending(&mut rng, n),
        SequenceKind::Reversed => {
            let mut keys = ascending(&mut rng, n);
            keys.reverse();
            keys
        }
        SequenceKind::FewDistinct => {
            let mut values: Vec<i64> = Vec::with_capacity(8);
            while values.len() < 8 {
                let v = random_key(&mut rng);
                if !values.contains(&v) {
                    values.push(v);
                }
            }
            (0..n).map(|_| values[rng.index(8)]).collect()
        }
    })
}

/// `n` random finite `f64` keys of mixed signs and magnitudes, for float-sorting benches.
///
/// Each key is `+-m 2^e` with the sign fair, the significand `m` uniform over the 2^52
/// values in `[1, 2)` and `e` uniform in `-64..=63`: normal, nonzero, never NaN or
/// infinite, magnitudes in `[2^-64, 2^64)` across 128 binades. Bit-identical for the same
/// `seed` on every machine.
///
/// # Errors
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `n` exceeds
/// [`MAX_KEYS`](crate::limits::MAX_KEYS), before anything is allocated.
///
/// # Complexity
/// O(n) time and space.
///
/// ```
/// use compgeo::gen::sequence_f64;
///
/// let keys = sequence_f64(1000, 5)?;
/// assert!(keys.iter().all(|k| k.is_normal()));
/// assert!(keys.iter().any(|&k| k < 0.0) && keys.iter().any(|&k| k > 0.0));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn sequence_f64(n: usize, seed: u64) -> Result<Vec<f64>> {
    limits::KEYS.check(n as u128)?;
    let mut rng = Rng::new(seed);
    Ok((0..n)
        .map(|_| {
            let exponent = (rng.range_i64(-64, 63) + 1023) as u64;
            let mantissa = rng.next_u64() >> 12;
            let sign = u64::from(rng.coin()) << 63;
            f64::from_bits(sign | exponent << 52 | mantissa)
        })
        .collect())
}

fn random_key(rng: &mut Rng) -> i64 {
    rng.range_i64(-RANDOM_KEY_BOUND, RANDOM_KEY_BOUND)
}

fn ascending(rng: &mut Rng, n: usize) -> Vec<i64> {
    let mut key = rng.range_i64(-(1 << 52), 0);
    (0..n)
        .map(|_| {
            key += rng.range_i64(1, 1024);
            key
        })
        .collect()
}
