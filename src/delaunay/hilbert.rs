//! The insertion order of the incremental builder: biased randomized insertion order (BRIO)
//! with a Hilbert-curve sort inside each round.
//!
//! Each point draws a round from a geometric distribution (half of the points in the last
//! round, a quarter in the one before, ...), so every round is a random sample about twice
//! the size of everything before it: Amenta, Choi and Rote's BRIO, which keeps the expected
//! number of flips O(n) on every input, including points on a parabola in x order. Inside a
//! round the points follow a Hilbert curve over their bounding box (or, beside a few far
//! points, the box of the others: [`curve_bounds`]), so consecutive points are close and the
//! walk from one to the next is short. The order only affects speed;
//! correctness never depends on it.

use crate::gen::Rng;
use crate::geometry::{BoundingBox, Point2};
use crate::util::{range_of_most, sorted_sample};

/// The seed of the BRIO rounds (any fixed value: the rounds need only be independent of the
/// input).
const BRIO_SEED: u64 = 0x5EED_DE1A_0000_0001;

/// Bits per axis of the Hilbert grid: 2^32 cells, far more than the points of any round.
const BITS: u32 = 16;

/// The local ids `0..points.len()` in insertion order; `bounds` is the points' bounding box.
///
/// O(n log n) time (sorts of 64-bit keys), O(n) auxiliary space. Deterministic: the
/// rounds come from the crate's random source with a fixed seed.
pub(super) fn brio_order(points: &[Point2], bounds: Option<BoundingBox>) -> Vec<u32> {
    brio_order_labelled(points, bounds, &|i| i as u32)
}

/// [`brio_order`] with `label(i)` in place of the local id `i`; `label` must increase with
/// `i`, so that the order is the same (the keys break ties by it). A subset's points can
/// so be ordered under their ids in the whole set without a second pass.
pub(super) fn brio_order_labelled(
    points: &[Point2],
    bounds: Option<BoundingBox>,
    label: &(impl Fn(usize) -> u32 + Sync),
) -> Vec<u32> {
    #[cfg(feature = "parallel")]
    return brio_order_from(points, bounds, crate::parallel::THRESHOLD, label);
    #[cfg(not(feature = "parallel"))]
    brio_order_from(points, bounds, usize::MAX, label)
}

/// [`brio_order_labelled`], in parallel from `threshold` points up (feature `parallel`).
#[cfg_attr(not(feature = "parallel"), allow(unused_variables))]
fn brio_order_from(
    points: &[Point2],
    bounds: Option<BoundingBox>,
    threshold: usize,
    label: &(impl Fn(usize) -> u32 + Sync),
) -> Vec<u32> {
    let n = points.len();
    let Some(bounds) = bounds else {
        return Vec::new();
    };
    let grid = Grid::over(bounds);
    // Rounds: the last one holds about n/2 points, the first one about 32.
    let rounds = (usize::BITS - n.leading_zeros()).saturating_sub(5) as usize;
    let mut rng = Rng::new(BRIO_SEED);
    // Per point: its round and (Hilbert index << 32 | id); then a counting sort by round
    // and a sort of plain u64 keys inside each round.
    #[cfg(feature = "parallel")]
    if n >= threshold {
        return par_brio_order(points, &grid, rounds, &mut rng, label);
    }
    let mut round_of = Vec::with_capacity(n);
    let mut sizes = vec![0usize; rounds + 1];
    let mut bits = 0u64;
    let keys: Vec<u64> = points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let round = round_of_point(i, rounds, &mut bits, &mut rng);
            round_of.push(round as u8);
            sizes[round] += 1;
            (grid.curve_index(*p) << 32) | u64::from(label(i))
        })
        .collect();
    let mut start = Vec::with_capacity(rounds + 2);
    start.push(0);
    for size in &sizes {
        start.push(start.last().copied().unwrap_or(0) + size);
    }
    let mut fill = start.clone();
    let mut sorted = vec![0u64; n];
    for (key, &round) in keys.iter().zip(&round_of) {
        sorted[fill[round as usize]] = *key;
        fill[round as usize] += 1;
    }
    drop((keys, round_of));
    for r in 0..=rounds {
        sorted[start[r]..start[r + 1]].sort_unstable();
    }
    // A fresh exact-size array (collecting in place would keep the 64-bit capacity).
    sorted.iter().map(|&key| key as u32).collect()
}

/// The BRIO round of point `i` (drawn in order of `i`): the last round with probability 1/2,
/// the one before with 1/4, and so on. One 64-bit draw serves two points, 32 bits each;
/// `bits` carries the draw from an even `i` to the next.
fn round_of_point(i: usize, rounds: usize, bits: &mut u64, rng: &mut Rng) -> usize {
    *bits = if i % 2 == 0 {
        rng.next_u64()
    } else {
        *bits >> 32
    };
    rounds - ((*bits as u32).trailing_zeros() as usize).min(rounds)
}

/// [`brio_order`] on all the threads (feature `parallel`): the rounds drawn in input order
/// from the same random source, the curve indices computed and each round's keys sorted in
/// parallel. The keys are distinct (they hold the ids), so the order is the sequential one.
#[cfg(feature = "parallel")]
fn par_brio_order(
    points: &[Point2],
    grid: &Grid,
    rounds: usize,
    rng: &mut Rng,
    label: &(impl Fn(usize) -> u32 + Sync),
) -> Vec<u32> {
    use rayon::prelude::*;
    let n = points.len();
    let mut bits = 0u64;
    let round_of: Vec<u8> = (0..n)
        .map(|i| round_of_point(i, rounds, &mut bits, rng) as u8)
        .collect();
    let keys: Vec<u64> = points
        .par_iter()
        .enumerate()
        .map(|(i, p)| (grid.curve_index(*p) << 32) | u64::from(label(i)))
        .collect();
    let mut start = vec![0usize; rounds + 2];
    for &round in &round_of {
        start[round as usize + 1] += 1;
    }
    for r in 0..=rounds {
        start[r + 1] += start[r];
    }
    let mut fill = start.clone();
    let mut sorted = vec![0u64; n];
    for (key, &round) in keys.iter().zip(&round_of) {
        sorted[fill[round as usize]] = *key;
        fill[round as usize] += 1;
    }
    for r in 0..=rounds {
        sorted[start[r]..start[r + 1]].par_sort_unstable();
    }
    sorted.into_par_iter().map(|key| key as u32).collect()
}

/// The box to lay the Hilbert grid over for `points` (whose bounding box is `bounds`): the
/// bounding box itself, except along an axis where it is more than four times as wide as
/// the range from the 1/64 to the 63/64 quantile of a sample of at most 1024 points; there
/// that range. A few far points would otherwise put all the others in one or two of the
/// grid's 2^16 columns, where the order inside a BRIO round falls back to the ids and the
/// walks grow to O(√n) steps (3 · 10⁵ points in a box 10⁻⁶ wide beside one point at 10⁸
/// took 8 s, 50 times as long as uniform points). Points outside the box go to its border
/// cells. The large sample is only taken when the same range of a sample of 64 points
/// is not empty and already spans less than a quarter of the box along an axis (not on
/// uniform or clustered input). Both ranges are [`range_of_most`].
///
/// O(1) time when the 64 points span the box, O(n / s + s log s) for a sample of s points
/// otherwise; O(s) auxiliary space.
pub(super) fn curve_bounds(points: &[Point2], bounds: Option<BoundingBox>) -> Option<BoundingBox> {
    let bounds = bounds?;
    let axis = |coordinate: fn(&Point2) -> f64, low: f64, high: f64| {
        let most = |size: usize, cut: usize| {
            let sample = sorted_sample(points, size, coordinate);
            range_of_most(sample.len(), |i| sample[i], cut, (low, high), 4.0)
        };
        // 64 points without their two extremes at each end first.
        most(64, 32)
            .and_then(|_| most(1024, 64))
            .unwrap_or((low, high))
    };
    let (min_x, max_x) = axis(|p| p.x, bounds.min.x, bounds.max.x);
    let (min_y, max_y) = axis(|p| p.y, bounds.min.y, bounds.max.y);
    Some(BoundingBox {
        min: Point2::new(min_x, min_y),
        max: Point2::new(max_x, max_y),
    })
}

/// The ids `0..points.len()` sorted along the Hilbert curve over the points' [`curve_bounds`]
/// (ties by id).
///
/// O(n log n) time, O(n) auxiliary space; O(n log r) for points that come as r runs already
/// in curve order, as the BRIO rounds do (the stable sort merges natural runs).
pub(crate) fn curve_order(points: &[Point2]) -> Vec<u32> {
    let Some(bounds) = curve_bounds(points, BoundingBox::of(points)) else {
        return Vec::new();
    };
    let grid = Grid::over(bounds);
    let mut keys: Vec<u64> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (grid.curve_index(*p) << 32) | i as u64)
        .collect();
    keys.sort();
    keys.into_iter().map(|key| key as u32).collect()
}

/// A grid of square cells over a bounding box, `2^BITS` along its wider side, in halved
/// coordinates (the width of `[-MAX, MAX]` would overflow).
struct Grid {
    half_min_x: f64,
    half_min_y: f64,
    /// Cells per halved unit, along both axes.
    scale: f64,
}

impl Grid {
    /// The grid over a bounding box.
    fn over(bounds: BoundingBox) -> Grid {
        let (min_x, min_y, max_x, max_y) = (bounds.min.x, bounds.min.y, bounds.max.x, bounds.max.y);
        let cells = f64::from((1u32 << BITS) - 1);
        // Square cells: one scale for both axes, the wider axis' (a zero scale is a zero
        // width). In a box much higher than wide, cells of the box's own shape would make
        // the curve's neighbours far apart across the short side's many columns.
        let (scale_x, scale_y) = (
            grid_scale(min_x, max_x, cells),
            grid_scale(min_y, max_y, cells),
        );
        let scale = match (scale_x > 0.0, scale_y > 0.0) {
            (true, true) => scale_x.min(scale_y),
            _ => scale_x.max(scale_y),
        };
        Grid {
            half_min_x: 0.5 * min_x,
            half_min_y: 0.5 * min_y,
            scale,
        }
    }

    /// The position of `p`'s cell along the Hilbert curve.
    #[inline]
    fn curve_index(&self, p: Point2) -> u64 {
        // `as` saturates below 0, and the clamp keeps points past the box (or rounded past
        // its end) in its border cells: the index reads only the low BITS bits.
        let last = (1u32 << BITS) - 1;
        let gx = (((0.5 * p.x - self.half_min_x) * self.scale) as u32).min(last);
        let gy = (((0.5 * p.y - self.half_min_y) * self.scale) as u32).min(last);
        hilbert_index(gx, gy)
    }
}

/// The factor that maps `0.5 * (v - min)` onto `[0, cells]`, 0 for an empty range (also the
/// nearest-point search's grid of entry vertices).
pub(crate) fn grid_scale(min: f64, max: f64, cells: f64) -> f64 {
    let half_width = 0.5 * max - 0.5 * min;
    if half_width > 0.0 {
        let scale = cells / half_width;
        // A subnormal width makes the quotient infinite; the largest finite scale still
        // spreads the points as far as doubles allow.
        if scale.is_finite() {
            scale
        } else {
            f64::MAX
        }
    } else {
        0.0
    }
}

/// The position of cell `(x, y)` along the Hilbert curve over the `2^BITS` by `2^BITS` grid:
/// four levels (eight bits of the index) per lookup in [`STEP`].
fn hilbert_index(x: u32, y: u32) -> u64 {
    let mut state = 0usize;
    let mut d = 0u64;
    let mut shift = BITS;
    while shift > 0 {
        shift -= 4;
        let xy = (((x >> shift) & 15) << 4 | ((y >> shift) & 15)) as usize;
        let entry = STEP[(state << 8) | xy];
        d = (d << 8) | u64::from(entry & 0xFF);
        state = usize::from(entry >> 8);
    }
    d
}

/// For each orientation state (see [`level`]) and four bits of x and of y: the eight index
/// bits of those four levels (low byte) and the state after them (high byte).
static STEP: [u16; 4 * 256] = step_table();

const fn step_table() -> [u16; 4 * 256] {
    let mut table = [0u16; 4 * 256];
    let mut state = 0;
    while state < 4 {
        let mut xy = 0;
        while xy < 256 {
            let (mut s, mut d) = (state as u32, 0u32);
            let mut bit = 4;
            while bit > 0 {
                bit -= 1;
                let (digit, next) = level(s, (xy >> (4 + bit)) & 1, (xy >> bit) & 1);
                d = (d << 2) | digit;
                s = next;
            }
            table[(state << 8) | xy as usize] = (d | (s << 8)) as u16;
            xy += 1;
        }
        state += 1;
    }
    table
}

/// One level of the curve. The sub-square's orientation is a state of two flags, bit 0
/// "axes swapped" and bit 1 "both axes reflected" (they commute, so every composition is
/// one of the four states). Returns the level's two index bits and the next state.
const fn level(state: u32, bx: u32, by: u32) -> (u32, u32) {
    let (swapped, reflected) = (state & 1, state >> 1);
    let cross = (bx ^ by) & swapped;
    let (tx, ty) = (bx ^ cross ^ reflected, by ^ cross ^ reflected);
    // The lower half in y turns the sub-square: a swap, plus a reflection on the right.
    let low = 1 ^ ty;
    let next = (swapped ^ low) | ((reflected ^ (low & tx)) << 1);
    ((3 * tx) ^ ty, next)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hilbert_index_visits_neighbouring_cells_in_turn() {
        // Along the curve, consecutive indices are cells one step apart.
        let side = 1u32 << 6;
        let scale = 1u32 << (BITS - 6);
        let mut cells: Vec<(u64, u32, u32)> = (0..side)
            .flat_map(|x| (0..side).map(move |y| (x, y)))
            .map(|(x, y)| (hilbert_index(x * scale, y * scale), x, y))
            .collect();
        cells.sort_unstable();
        for w in cells.windows(2) {
            let (dx, dy) = (w[0].1.abs_diff(w[1].1), w[0].2.abs_diff(w[1].2));
            assert_eq!(dx + dy, 1, "{w:?}");
        }
    }

    #[test]
    fn curve_order_sorts_by_curve_index_then_id() {
        let mut rng = Rng::new(7);
        let mut pts: Vec<Point2> = (0..500)
            .map(|_| {
                let mut u = || rng.unit();
                Point2::new(u() * 10.0 - 5.0, u() * 1e-3)
            })
            .collect();
        pts.extend_from_within(..50);
        let order = curve_order(&pts);
        let mut seen = order.clone();
        seen.sort_unstable();
        assert_eq!(seen, (0..pts.len() as u32).collect::<Vec<_>>());
        let grid = Grid::over(BoundingBox::of(&pts).unwrap());
        let key = |i: u32| (grid.curve_index(pts[i as usize]), i);
        assert!(order.windows(2).all(|w| key(w[0]) < key(w[1])));
        // Equal points share a cell, so somewhere the tie is broken by id.
        assert!(order
            .windows(2)
            .any(|w| key(w[0]).0 == key(w[1]).0 && w[0] < w[1]));
        assert!(curve_order(&[]).is_empty());
    }

    /// The parallel order is the sequential one, on both sides of the threshold and on
    /// inputs with repeated points.
    #[cfg(feature = "parallel")]
    #[test]
    fn parallel_order_equals_the_sequential_one() {
        use crate::gen::{points, PointKind};
        for kind in [
            PointKind::UniformSquare,
            PointKind::Grid,
            PointKind::Clustered,
        ] {
            for n in [0, 1, 100, 70_000] {
                let pts = points(kind, n, 9).unwrap();
                let bounds = BoundingBox::of(&pts);
                assert_eq!(
                    brio_order_from(&pts, bounds, 0, &|i| i as u32),
                    brio_order_from(&pts, bounds, usize::MAX, &|i| i as u32),
                    "{kind}, n = {n}"
                );
            }
        }
    }

    #[test]
    fn order_is_a_permutation_even_for_extreme_ranges() {
        let pts = [
            Point2::new(f64::MAX, -f64::MAX),
            Point2::new(-f64::MAX, f64::MAX),
            Point2::new(5e-324, 0.0),
            Point2::new(0.0, -5e-324),
        ];
        let mut order = brio_order(&pts, BoundingBox::of(&pts));
        order.sort_unstable();
        assert_eq!(order, [0, 1, 2, 3]);
        let tiny = [
            Point2::new(5e-324, 0.0),
            Point2::new(0.0, 1e-323),
            Point2::new(0.0, 0.0),
        ];
        let mut order = brio_order(&tiny, BoundingBox::of(&tiny));
        order.sort_unstable();
        assert_eq!(order, [0, 1, 2]);
    }

    #[test]
    fn curve_bounds_leave_out_a_few_far_points_only() {
        let mut rng = Rng::new(5);
        let square: Vec<Point2> = (0..5000)
            .map(|_| Point2::new(rng.unit(), rng.unit()))
            .collect();
        // Spread points: their own bounding box, exactly (the order does not change).
        let bounds = BoundingBox::of(&square);
        assert_eq!(curve_bounds(&square, bounds), bounds);
        // Far points first and last (where every sample looks): the box of the others
        // along each stretched axis, cut at quantiles inside the unit square.
        let mut far = square.clone();
        far[0] = Point2::new(1e9, 0.5);
        far[4999] = Point2::new(-1e9, 1e8);
        let trimmed = curve_bounds(&far, BoundingBox::of(&far)).unwrap();
        for v in [trimmed.min.x, trimmed.max.x, trimmed.min.y, trimmed.max.y] {
            assert!((0.0..1.0).contains(&v), "{trimmed:?}");
        }
        assert!(trimmed.max.x - trimmed.min.x > 0.9 && trimmed.max.y - trimmed.min.y > 0.9);
        // Along an axis the far points do not stretch, the bounding box's own range.
        let mut tall = square.clone();
        tall[0] = Point2::new(0.5, 1e9);
        let kept = curve_bounds(&tall, BoundingBox::of(&tall)).unwrap();
        assert_eq!(
            (kept.min.x, kept.max.x),
            (bounds.unwrap().min.x, bounds.unwrap().max.x)
        );
        assert!(kept.max.y < 1.0);
        // Most points on one line: nothing left after the cut, the whole box.
        let mut line: Vec<Point2> = (0..1000).map(|i| Point2::new(i as f64, 0.0)).collect();
        line[500] = Point2::new(500.0, 1e9);
        assert_eq!(
            curve_bounds(&line, BoundingBox::of(&line)),
            BoundingBox::of(&line)
        );
        assert_eq!(curve_bounds(&[], None), None);
    }

    #[test]
    fn the_grid_has_square_cells() {
        // A box 1000 times higher than wide: cells as wide as they are high, so the box
        // spans 65 columns of the 65536 rows' width (cells of the box's own shape would be
        // a thousand times taller than wide, and the curve's neighbours far apart in y).
        let bounds = BoundingBox {
            min: Point2::new(0.0, 0.0),
            max: Point2::new(1e-3, 1.0),
        };
        let grid = Grid::over(bounds);
        let cell = |v: f64, half_min: f64| ((0.5 * v - half_min) * grid.scale) as u32;
        assert_eq!(cell(1.0, grid.half_min_y), (1 << BITS) - 1);
        assert_eq!(cell(1e-3, grid.half_min_x), 65);
        // Points past the box (left out by `curve_bounds`) go to its border cells: the
        // index of a far corner is that of the grid's corner, not of a wrapped cell.
        let last = (1u32 << BITS) - 1;
        for (far, x, y) in [
            (Point2::new(50.0, 0.5), last, cell(0.5, grid.half_min_y)),
            (Point2::new(-5.0, 3.0), 0, last),
        ] {
            assert_eq!(grid.curve_index(far), hilbert_index(x, y), "{far:?}");
        }
        // A flat box (zero height): the width's scale.
        let flat = Grid::over(BoundingBox {
            min: Point2::new(0.0, 2.0),
            max: Point2::new(1.0, 2.0),
        });
        assert!(flat.scale > 0.0);
    }
}
