//! Andrew's monotone chain: the course's "variante" of Graham's scan, which sorts
//! lexicographically instead of by angle and scans the lower and upper chains.

use super::collinear::finish;
use super::graham::{push_left_turn, Move};
use super::lex::lex_sorted_items;
use super::HullOptions;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet};
use crate::trace::{record, Frame, NoObserver, Observer, TraceSize};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "hull",
    name: "monotone-chain",
    function: "hull::monotone_chain",
    file: "src/hull/monotone_chain.rs",
    summary: "lexicographic sort, then the lower and upper chains",
    time: "O(n log n)",
    space: "O(n)",
    operation: Some(Operation::Comparisons),
    counts: "those of the sort, plus n − 1 to merge duplicates",
    source: "[RD, §2.2]",
    claims: &[on("uniform-disk", Bound::NLogN, Operation::Comparisons)],
};

/// One of the monotone chain's two chains.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Chain {
    /// The lower chain, scanned from the lexicographically smallest point to the largest.
    Lower,
    /// The upper chain, scanned from the largest point back to the smallest.
    Upper,
}

/// A step of the monotone chain, as [`monotone_chain_trace`] records it. Indices are into the
/// input.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum ChainStep {
    /// The lexicographic sort is done (each distinct point once, by its smallest index).
    Sorted {
        /// The distinct points in lexicographic order.
        order: Vec<usize>,
    },
    /// The points are split by the line from the first to the last point (three or more
    /// distinct points only): each chain in the order it is scanned, both ends included.
    Split {
        /// The first point, the points strictly below the line, the last point.
        lower: Vec<usize>,
        /// The last point, the points strictly above the line (decreasing), the first point.
        upper: Vec<usize>,
    },
    /// `point` was pushed on the stack of `chain`.
    Push {
        /// The chain being scanned.
        chain: Chain,
        /// The pushed point.
        point: usize,
        /// The chain's stack after the push, bottom first.
        stack: Vec<usize>,
    },
    /// `point` was popped from the stack of `chain`: it does not turn strictly left.
    Pop {
        /// The chain being scanned.
        chain: Chain,
        /// The popped point.
        point: usize,
        /// The chain's stack after the pop, bottom first.
        stack: Vec<usize>,
    },
    /// Both chains are done: the result of [`monotone_chain`] (with the boundary points
    /// inserted if the options ask for them).
    Done {
        /// The hull, as [`monotone_chain`] returns it.
        hull: Vec<usize>,
    },
}

impl TraceSize for ChainStep {
    fn entries(&self) -> usize {
        match self {
            ChainStep::Sorted { order: v } | ChainStep::Done { hull: v } => v.len(),
            ChainStep::Split { lower, upper } => lower.len() + upper.len(),
            ChainStep::Push { stack, .. } | ChainStep::Pop { stack, .. } => 1 + stack.len(),
        }
    }
}

/// The convex hull of `points` by the monotone chain. See [`monotone_chain_with`].
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{monotone_chain, HullOptions};
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 0.0)].map(Point2::from);
/// assert_eq!(monotone_chain(&pts, HullOptions::default())?, [1, 2, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn monotone_chain(points: &[Point2], options: HullOptions) -> Result<Vec<usize>> {
    Ok(monotone_chain_with(
        &PointSet::new(points)?,
        options,
        &mut NoCount,
    ))
}

/// The convex hull of `points` by Andrew's monotone chain, recording its operations in
/// `counter`.
///
/// Idea: sort the points lexicographically (merging duplicates); the hull's boundary is the
/// lower chain from the first to the last point plus the upper chain back. The points
/// strictly below the line from first to last belong to the lower chain, those strictly
/// above to the upper. Each chain is
/// Graham's scan over the sorted list: push a point after popping every point that does
/// not make a strict left turn with it.
///
/// Follows [RD, §2.2] "Scan de Graham - Variante" (steps 1–4).
///
/// Output convention and degenerate inputs: see the [module docs](super). `keep_collinear`
/// inserts the boundary points afterwards (a binary search per point over the hull).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and h the number of hull vertices: time O(n log n) (the sort),
/// the scans O(n); auxiliary space O(n). With [`NoCount`] the sort is a radix sort from 384
/// points up (the same order, O(n) on random input, 1.2 to 1.9 times faster overall at 10³ to
/// 10⁶ points); a counter that records gets the comparison sort the counts below describe.
///
/// # Counts
///
/// Comparisons: those of the lexicographic sort, O(n log n), plus n − 1 to merge duplicates.
/// Orientation tests: m − 2 for m distinct points to split them between the chains, then at
/// most 2k − 3 for a chain of k points (each test pops a point or ends a push), at most
/// 3m in all. `keep_collinear` adds O(n log h) comparisons
/// and at most 2n orientation tests.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{monotone_chain_with, HullOptions};
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.2, 0.2)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// assert_eq!(monotone_chain_with(&set, HullOptions::default(), &mut counts), [0, 1, 2]);
/// assert!(counts.orientation_tests <= 3 * 4);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn monotone_chain_with<C: Counter>(
    points: &PointSet,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    monotone(points.points(), options, counter, &mut NoObserver)
}

/// The frames of the monotone chain on `points`: its own run, step by step.
///
/// The run is [`monotone_chain_with`]'s, told about each step: [`ChainStep::Sorted`] after
/// the lexicographic sort, [`ChainStep::Split`] with the points of each chain, then for the
/// lower chain and after it the upper chain one [`ChainStep::Push`] per point of the chain
/// and one [`ChainStep::Pop`] per point the scan removes, each with the stack after it, and
/// last [`ChainStep::Done`] with the hull [`monotone_chain`] returns. Each frame carries the
/// operations counted so far; the last frame's are those of [`monotone_chain_with`] with
/// [`Counts`](crate::count::Counts) (which sorts by comparisons).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the frames
/// would hold more than [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES) entries.
///
/// # Complexity
///
/// O(n log n) for the chains plus the frames: at most 3n of up to n indices, O(n²) time and
/// space.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{monotone_chain_trace, Chain, ChainStep, HullOptions};
///
/// let pts = [(0.0, 0.0), (2.0, -1.0), (4.0, 0.0), (2.0, 3.0), (1.0, -0.25)].map(Point2::from);
/// let frames = monotone_chain_trace(&pts, HullOptions::default())?;
/// assert_eq!(frames[0].step, ChainStep::Sorted { order: vec![0, 4, 1, 3, 2] });
/// assert_eq!(frames[1].step, ChainStep::Split { lower: vec![0, 4, 1, 2], upper: vec![2, 3, 0] });
/// // The lower chain pops 4 when 1 comes: 0, 4, 1 turn right.
/// let pops: Vec<usize> = frames
///     .iter()
///     .filter_map(|f| match f.step {
///         ChainStep::Pop { chain: Chain::Lower, point, .. } => Some(point),
///         _ => None,
///     })
///     .collect();
/// assert_eq!(pops, [4]);
/// assert_eq!(frames.last().unwrap().step, ChainStep::Done { hull: vec![0, 1, 2, 3] });
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn monotone_chain_trace(
    points: &[Point2],
    options: HullOptions,
) -> Result<Vec<Frame<ChainStep>>> {
    let points = PointSet::new(points)?;
    record(|counts, recorder| {
        let hull = monotone(points.points(), options, counts, recorder);
        Ok(ChainStep::Done { hull })
    })
}

/// The monotone chain, telling `obs` about each step.
fn monotone<C: Counter, O: Observer<ChainStep, C>>(
    points: &[Point2],
    options: HullOptions,
    counter: &mut C,
    obs: &mut O,
) -> Vec<usize> {
    let sorted = lex_sorted_items(points, 0..points.len(), counter);
    obs.step(counter, || ChainStep::Sorted {
        order: sorted.iter().map(|s| s.1).collect(),
    });
    let strict = observed_chains(&sorted, counter, obs);
    finish(points, sorted.iter().map(|s| s.1), strict, options, counter)
}

/// Andrew's chains over `sorted`, distinct points in lexicographic order: the strictly
/// convex hull, counter-clockwise from `sorted[0]`, as indices into the input.
///
/// The points strictly below the line from the first to the last point go to the lower
/// chain, those strictly above to the upper one, the rest (on the line) to neither: each
/// chain scans only its own points.
pub(super) fn chains<C: Counter>(sorted: &[(Point2, usize)], counter: &mut C) -> Vec<usize> {
    observed_chains(sorted, counter, &mut NoObserver)
}

/// [`chains`], telling `obs` about the split and each push and pop.
fn observed_chains<C: Counter, O: Observer<ChainStep, C>>(
    sorted: &[(Point2, usize)],
    counter: &mut C,
    obs: &mut O,
) -> Vec<usize> {
    let m = sorted.len();
    if m <= 2 {
        return sorted.iter().map(|s| s.1).collect();
    }
    let (a, b) = (sorted[0].0, sorted[m - 1].0);
    // Sized up front: growing by pushes reallocates, which dominates on Chan's small groups.
    let mut lower = Vec::with_capacity(m);
    let mut upper = Vec::with_capacity(m);
    lower.push(sorted[0]);
    upper.push(sorted[m - 1]);
    for &item in &sorted[1..m - 1] {
        match counter.orient2d(a, b, item.0) {
            Orientation::Clockwise => lower.push(item),
            Orientation::CounterClockwise => upper.push(item),
            Orientation::Collinear => {}
        }
    }
    lower.push(sorted[m - 1]);
    upper.push(sorted[0]);
    let upper_last = upper.len() - 1;
    upper[1..upper_last].reverse();
    obs.step(counter, || ChainStep::Split {
        lower: lower.iter().map(|s| s.1).collect(),
        upper: upper.iter().map(|s| s.1).collect(),
    });
    let mut hull = scan_chain(&lower, Chain::Lower, counter, obs);
    hull.pop();
    let mut top = scan_chain(&upper, Chain::Upper, counter, obs);
    top.pop();
    hull.extend(top);
    hull
}

/// Graham's scan over one chain whose points are all on one side of its end-to-end line:
/// the chain's strictly convex vertices, both ends included. The stack holds the points
/// themselves, so the scan reads them sequentially.
fn scan_chain<C: Counter, O: Observer<ChainStep, C>>(
    points: &[(Point2, usize)],
    chain: Chain,
    counter: &mut C,
    obs: &mut O,
) -> Vec<usize> {
    let mut stack: Vec<(Point2, usize)> = Vec::with_capacity(points.len());
    for &item in points {
        push_left_turn(
            &mut stack,
            2,
            item,
            |s| s.0,
            counter,
            |moved, stack, counter| {
                obs.step(counter, || {
                    let stack = stack.iter().map(|s| s.1).collect();
                    match moved {
                        Move::Push(s) => ChainStep::Push {
                            chain,
                            point: s.1,
                            stack,
                        },
                        Move::Pop(s) => ChainStep::Pop {
                            chain,
                            point: s.1,
                            stack,
                        },
                    }
                })
            },
        );
    }
    stack.into_iter().map(|s| s.1).collect()
}
