//! The catalog: every algorithm of the crate registered with its stated bound.
//!
//! An [`Entry`] says what is measured (id, problem, input distribution), what is claimed (the
//! [`Bound`] and the counted [`Operation`]), at which sizes ([`SizeRange`] per [`Profile`]) and
//! how to run it (a [`Workload`]). [`catalog`] collects the entries of every module; each
//! problem registers its algorithms in one function of its own file in this directory
//! (`sort.rs` has `entries()`), so adding an algorithm is a few lines in one place.
//!
//! # Registering an algorithm
//!
//! Implement [`Workload`] once per problem (prepare an input for a size and a seed, run one
//! algorithm with any [`Counter`]), then list one [`Entry`] per algorithm and input:
//!
//! ```
//! use compgeo::complexity::{Bound, Entry, Workload};
//! use compgeo::count::{Counter, Operation};
//!
//! /// Linear search for the last key: n comparisons.
//! struct LastKey;
//!
//! impl Workload for LastKey {
//!     type Input = Vec<u64>;
//!     type Output = Option<usize>;
//!     fn prepare(&self, n: usize, _seed: u64) -> compgeo::Result<Vec<u64>> {
//!         Ok((0..n as u64).collect())
//!     }
//!     fn run<C: Counter>(&self, keys: &mut Vec<u64>, c: &mut C) -> compgeo::Result<Option<usize>> {
//!         let target = keys.len() as u64 - 1;
//!         Ok(keys.iter().position(|&k| {
//!             c.comparison();
//!             k == target
//!         }))
//!     }
//! }
//!
//! let entry = Entry::new("search/linear", Bound::Linear, Operation::Comparisons, LastKey)
//!     .input("sorted")
//!     .quick(64, 1024)
//!     .full(64, 1 << 16);
//! assert_eq!(entry.info.problem, "search");
//! assert_eq!(entry.quick.sizes(), [64, 128, 256, 512, 1024]);
//! ```

use crate::util::named_enum;
use std::fmt;
use std::hint::black_box;
use std::time::{Duration, Instant};

use crate::complexity::{Bound, Declaration};
use crate::count::{Counter, Counts, NoCount, Operation};
use crate::error::Result;

/// How to run one algorithm on generated input: the part of an [`Entry`] that is code.
///
/// The engine calls [`prepare`](Workload::prepare) once per size (untimed), then runs
/// [`run`](Workload::run) on fresh clones of that input: once with [`Counts`] to count, and
/// many times with [`NoCount`] to time. `run` is generic over the counter so the timed runs are
/// the uncounted code.
pub trait Workload {
    /// The prepared input; cloned for every run, so an algorithm may consume or reorder it.
    type Input: Clone;
    /// What the algorithm returns; kept alive until the timer stops, then dropped.
    type Output;

    /// Builds the input of size `n` from `seed` (deterministic).
    ///
    /// # Errors
    ///
    /// Whatever the generator reports, e.g. a size it cannot produce.
    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input>;

    /// Runs the algorithm once on `input`, recording its operations in `counter`.
    ///
    /// # Errors
    ///
    /// Whatever the algorithm reports; the engine stops and names the entry.
    fn run<C: Counter>(&self, input: &mut Self::Input, counter: &mut C) -> Result<Self::Output>;

    /// The output size h (e.g. hull vertices), for output-sensitive bounds. Default: none.
    fn output_size(&self, _input: &Self::Input, _output: &Self::Output) -> Option<usize> {
        None
    }

    /// The number of edges m of a graph input, for bounds in m. Default: none.
    fn edge_count(&self, _input: &Self::Input) -> Option<usize> {
        None
    }
}

/// What an entry is, without the code: identity, claim and counted operation.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Info {
    /// `problem/algorithm`, e.g. `"sort/bubble"` (algorithm names are the CLI's kebab-case).
    pub id: String,
    /// The problem, the part of `id` before the first `/`, e.g. `"sort"`.
    pub problem: String,
    /// The input generator, e.g. `"random"`, `"sorted"`, `"reversed"`.
    pub input: String,
    /// The stated time bound.
    pub bound: Bound,
    /// The operation whose count is checked against the bound.
    pub operation: Operation,
}

/// A geometric range of sizes: `min, 2·min, 4·min, ...` up to `max`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SizeRange {
    /// The smallest size.
    pub min: usize,
    /// The largest size allowed (reached when `max / min` is a power of two).
    pub max: usize,
}

named_enum! {
    /// Which size ranges a run uses: `"quick"` or `"full"`, as written in `results.json`.
    pub enum Profile ("profile") {
        /// Small sizes: the whole catalog in a few minutes on two cores.
        Quick = "quick",
        /// Larger sizes and more repetitions, for reports worth publishing.
        Full = "full",
    }
}

/// One registered algorithm on one input distribution.
pub struct Entry {
    /// Identity and claim.
    pub info: Info,
    /// Sizes of the quick profile.
    pub quick: SizeRange,
    /// Sizes of the full profile.
    pub full: SizeRange,
    workload: Box<dyn Erased>,
}

/// Every registered algorithm of the crate, problem by problem.
///
/// Entries are unique by [`Info::key`], and every entry has at least
/// [`MIN_SIZES`](crate::complexity::MIN_SIZES) sizes in each profile.
///
/// ```
/// let all = compgeo::complexity::catalog();
/// assert!(all.iter().any(|e| e.info.id == "sort/bubble" && e.info.input == "random"));
/// ```
pub fn catalog() -> Vec<Entry> {
    let mut all = Vec::new();
    all.extend(predicate::entries());
    all.extend(sort::entries());
    all.extend(graph::entries());
    all.extend(hull::entries());
    all.extend(spline::entries());
    all.extend(interpolate::entries());
    all.extend(bspline::entries());
    all.extend(subdivision::entries());
    all.extend(beta::entries());
    all.extend(surface::entries());
    all.extend(surface_spline::entries());
    all.extend(triangle::entries());
    all.extend(subdivision_surface::entries());
    all.extend(delaunay::entries());
    all.extend(proximity::entries());
    all.extend(mesh::entries());
    all
}

/// The entries of every claim `declaration` makes, each claim's input parsed as the
/// generator `K` it names and measured by `workload(kind)`; the kind comes back with its
/// entry for the sizes.
///
/// # Panics
///
/// If a claim names no generator of kind `K`: a programming error the catalog's tests catch.
fn claimed_entries<K, W>(
    declaration: &'static Declaration,
    workload: impl Fn(K) -> W,
) -> Vec<(K, Entry)>
where
    K: std::str::FromStr + Copy,
    W: Workload + 'static,
{
    declaration
        .claims
        .iter()
        .map(|claim| {
            let kind: K = claim.input.parse().unwrap_or_else(|_| {
                panic!(
                    "{} claims input {:?}, which names no generator here",
                    declaration.id(),
                    claim.input
                )
            });
            (
                kind,
                Entry::declared(declaration, claim.input, workload(kind)),
            )
        })
        .collect()
}

mod beta;
mod bspline;
mod delaunay;
mod graph;
mod hull;
mod interpolate;
mod mesh;
mod predicate;
mod proximity;
mod sort;
mod spline;
mod subdivision;
mod subdivision_surface;
mod surface;
mod surface_spline;
mod triangle;

/// The result of one counted run.
pub(crate) struct Counted {
    pub counts: Counts,
    pub h: Option<usize>,
    pub m: Option<usize>,
}

/// A workload with its types erased, so entries of different problems share one list.
trait Erased {
    fn prepare(&self, n: usize, seed: u64) -> Result<Box<dyn Prepared + '_>>;
}

/// An input prepared for one size, ready to be counted and timed.
pub(crate) trait Prepared {
    /// One run with [`Counts`] on a fresh clone.
    fn count(&self) -> Result<Counted>;
    /// `reps` runs with [`NoCount`], each on its own clone made before the clock starts;
    /// outputs are dropped after it stops.
    fn time(&self, reps: usize) -> Duration;
}

struct Holder<W: Workload>(W);

struct Ready<'a, W: Workload> {
    workload: &'a W,
    input: W::Input,
}

impl Info {
    /// `id/input`, unique in the catalog, e.g. `"sort/insertion/sorted"`;
    /// `--only` patterns match against it.
    pub fn key(&self) -> String {
        format!("{}/{}", self.id, self.input)
    }

    /// A file-name-safe form of [`Info::key`], e.g. `"sort-insertion-sorted"`.
    pub fn file_stem(&self) -> String {
        file_stem(&self.key())
    }
}

impl SizeRange {
    /// The range `min..=max`.
    ///
    /// # Panics
    ///
    /// If `min` is 0 or `max < min`: size ranges are constants of the catalog, so this is a
    /// programming error (in a `const` it fails the build).
    pub const fn new(min: usize, max: usize) -> SizeRange {
        assert!(min >= 1 && max >= min, "a size range needs 1 <= min <= max");
        SizeRange { min, max }
    }

    /// The sizes `min·2^k ≤ max`, increasing.
    pub fn sizes(&self) -> Vec<usize> {
        let mut out = Vec::new();
        let mut n = self.min.max(1);
        while n <= self.max {
            out.push(n);
            match n.checked_mul(2) {
                Some(next) => n = next,
                None => break,
            }
        }
        out
    }
}

impl Entry {
    /// Registers `workload` under `id` (`problem/algorithm`) with its stated `bound` and the
    /// `operation` whose count is checked against it.
    ///
    /// Defaults, changed with the builder methods: input `"random"`, quick sizes 2⁸..2¹⁴, full
    /// sizes 2⁸..2¹⁸.
    pub fn new<W: Workload + 'static>(
        id: &str,
        bound: Bound,
        operation: Operation,
        workload: W,
    ) -> Entry {
        let problem = id.split('/').next().unwrap_or(id).to_string();
        Entry {
            info: Info {
                id: id.to_string(),
                problem,
                input: "random".to_string(),
                bound,
                operation,
            },
            quick: SizeRange::new(1 << 8, 1 << 14),
            full: SizeRange::new(1 << 8, 1 << 18),
            workload: Box::new(Holder(workload)),
        }
    }

    /// Registers `workload` as the measurement of the claim `declaration` makes on `input`:
    /// the id, the stated bound and the counted operation are the declaration's, so the
    /// catalog states none of them again. Sizes as for [`Entry::new`].
    ///
    /// # Panics
    ///
    /// If `declaration` makes no claim on `input`: the catalog is a constant of the crate, so
    /// this is a programming error (the catalog's tests build every entry).
    pub fn declared<W: Workload + 'static>(
        declaration: &'static Declaration,
        input: &str,
        workload: W,
    ) -> Entry {
        let claim = declaration
            .claim(input)
            .unwrap_or_else(|| panic!("{} declares no claim on input {input:?}", declaration.id()));
        Entry::new(&declaration.id(), claim.bound, claim.operation, workload).input(claim.input)
    }

    /// Names the input distribution the workload generates (e.g. `"sorted"`).
    pub fn input(mut self, name: &str) -> Entry {
        self.info.input = name.to_string();
        self
    }

    /// Sets the quick profile's sizes to `min, 2·min, ... ≤ max` (see [`SizeRange::new`]).
    pub fn quick(mut self, min: usize, max: usize) -> Entry {
        self.quick = SizeRange::new(min, max);
        self
    }

    /// Sets the full profile's sizes to `min, 2·min, ... ≤ max` (see [`SizeRange::new`]).
    pub fn full(mut self, min: usize, max: usize) -> Entry {
        self.full = SizeRange::new(min, max);
        self
    }

    /// The sizes measured under `profile`.
    pub fn sizes(&self, profile: Profile) -> Vec<usize> {
        match profile {
            Profile::Quick => self.quick.sizes(),
            Profile::Full => self.full.sizes(),
        }
    }

    /// Whether `pattern` occurs in the entry's [`Info::key`] (an empty pattern matches all).
    pub fn matches(&self, pattern: &str) -> bool {
        self.info.key().contains(pattern)
    }

    /// Prepares the input of size `n` (untimed) for counting and timing.
    pub(crate) fn prepare(&self, n: usize, seed: u64) -> Result<Box<dyn Prepared + '_>> {
        self.workload.prepare(n, seed)
    }
}

impl fmt::Debug for Entry {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Entry")
            .field("info", &self.info)
            .field("quick", &self.quick)
            .field("full", &self.full)
            .finish_non_exhaustive()
    }
}

impl<W: Workload> Erased for Holder<W> {
    fn prepare(&self, n: usize, seed: u64) -> Result<Box<dyn Prepared + '_>> {
        let input = self.0.prepare(n, seed)?;
        Ok(Box::new(Ready {
            workload: &self.0,
            input,
        }))
    }
}

impl<W: Workload> Prepared for Ready<'_, W> {
    fn count(&self) -> Result<Counted> {
        let mut input = self.input.clone();
        let mut counts = Counts::default();
        let output = self.workload.run(&mut input, &mut counts)?;
        Ok(Counted {
            counts,
            h: self.workload.output_size(&input, &output),
            m: self.workload.edge_count(&self.input),
        })
    }

    fn time(&self, reps: usize) -> Duration {
        let mut inputs = vec![self.input.clone(); reps];
        let mut outputs = Vec::with_capacity(reps);
        let start = Instant::now();
        for input in &mut inputs {
            let out = self.workload.run(black_box(input), &mut NoCount);
            outputs.push(black_box(out));
        }
        let elapsed = start.elapsed();
        drop(black_box(outputs));
        elapsed
    }
}

/// Maps a key such as `sort/insertion/sorted` to `sort-insertion-sorted`: ASCII letters,
/// digits, `-` and `_` are kept, anything else becomes `-`.
pub(crate) fn file_stem(key: &str) -> String {
    key.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '-'
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_double_up_to_max() {
        assert_eq!(SizeRange::new(3, 30).sizes(), [3, 6, 12, 24]);
        assert_eq!(SizeRange::new(5, 5).sizes(), [5]);
        assert_eq!(
            SizeRange::new(usize::MAX / 2 + 1, usize::MAX).sizes().len(),
            1
        );
    }

    #[test]
    fn profile_round_trips_and_rejects_others() {
        for p in [Profile::Quick, Profile::Full] {
            assert_eq!(p.name().parse::<Profile>(), Ok(p));
        }
        let err = "fast".parse::<Profile>().unwrap_err();
        assert!(err.to_string().contains("`fast`"), "{err}");
    }

    #[test]
    fn file_stem_keeps_only_safe_characters() {
        assert_eq!(file_stem("sort/insertion/sorted"), "sort-insertion-sorted");
        assert_eq!(file_stem("a b<c>.d"), "a-b-c--d");
    }
}
