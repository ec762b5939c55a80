//! Seeded point sets: random distributions and the degenerate configurations that break
//! inexact geometry code.

use super::cocircular;
use super::gaussian::normal_pair;
use super::rng::Rng;
use crate::error::Result;
use crate::geometry::{cmp_dist, Point2};
use crate::limits;
use crate::util::named_enum;
use std::cmp::Ordering;

named_enum! {
    /// The distribution or configuration a point set is drawn from.
    ///
    /// Names (for the command line and reports) are kebab-case: `uniform-square`,
    /// `uniform-disk`, `gaussian`, `clustered`, `cocircular`, `parabola`, `grid`,
    /// `rotated-grid`, `near-duplicates`, `collinear`, `huge`, `tiny`. See [`points`] for what
    /// each kind produces.
    ///
    /// ```
    /// use compgeo::gen::PointKind;
    ///
    /// let kind: PointKind = "rotated-grid".parse()?;
    /// assert_eq!(kind, PointKind::RotatedGrid);
    /// assert_eq!(kind.name(), "rotated-grid");
    /// assert!("hexagon".parse::<PointKind>().is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum PointKind ("point kind") {
        /// Uniform in the unit square `[0, 1)^2`.
        UniformSquare = "uniform-square",
        /// Uniform in the open unit disk `x^2 + y^2 < 1`.
        UniformDisk = "uniform-disk",
        /// Independent standard normal coordinates (mean 0, standard deviation 1).
        Gaussian = "gaussian",
        /// A few tight clusters, alternately gaussian and uniform, with centres in `[0, 1)^2`.
        Clustered = "clustered",
        /// Distinct integer points exactly on one circle centred at the origin.
        Cocircular = "cocircular",
        /// `(x, x^2)` for consecutive integers `x`, in increasing `x`.
        Parabola = "parabola",
        /// An integer grid, about `sqrt(n)` by `sqrt(n)`.
        Grid = "grid",
        /// An integer lattice that is a rotated (and scaled) grid, not axis-aligned.
        RotatedGrid = "rotated-grid",
        /// Clusters of 2 to 4 points one ulp apart in x and/or y.
        NearDuplicates = "near-duplicates",
        /// Integer points exactly on one line.
        Collinear = "collinear",
        /// Magnitudes between 1e200 and 1e300, both signs.
        Huge = "huge",
        /// Magnitudes between 1e-300 and 1e-140 and subnormals, both signs.
        Tiny = "tiny",
    }
}

/// `n` points of the given kind, the same for the same `seed` on every machine.
///
/// Randomness comes from ChaCha8 seeded with `seed`, and every coordinate is computed with
/// correctly rounded IEEE operations (`+ - * / sqrt`) and exact bit manipulation only, so
/// the output is bit-identical across platforms (no libm `ln`, `sin`, `cos` or `exp`).
/// The kinds, for `n` points:
///
/// - `UniformSquare`: coordinates are independent multiples of 2^-53 in `[0, 1)`.
/// - `UniformDisk`: rejection sampling from `[-1, 1)^2` (multiples of 2^-52), keeping a
///   point when the exact [`cmp_dist`] says `|p| < 1`.
/// - `Gaussian`: Marsaglia's polar method with a logarithm built from `+ - * /` (see the
///   module docs); sigma 1.
/// - `Clustered`: `1 + floor(log2 n) / 2` clusters with centres uniform in `[0, 1)^2`;
///   even-numbered clusters are gaussian with sigma 0.02, odd-numbered ones uniform in a
///   square of side 0.1; each point picks a cluster uniformly.
/// - `Cocircular`: distinct integer points on `x^2 + y^2 = r^2` for the smallest radius of
///   the family `5, 5*13, 5*13*17, ..., 5*13*...*89, 5^2*13*...*89` (products of primes
///   `= 1 (mod 4)`, built as Gaussian-integer products) whose circle holds at least `n`
///   lattice points; a uniform random subset of them in random order. Every coordinate is
///   an integer below 2^53, so exact in `f64`. At most [`MAX_COCIRCULAR`] points.
/// - `Parabola`: `(x, x^2)` for the integers `x = -floor(n/2), ..., n - 1 - floor(n/2)`,
///   in increasing `x` (the adversarial insertion order from CGAL's hull tests); every
///   coordinate is exact.
/// - `Grid`: the first `n` points, row by row, of the grid `{0..cols-1} x {0..rows-1}` with
///   `cols = ceil(sqrt n)`, `rows = ceil(n / cols)`, in random order.
/// - `RotatedGrid`: the same grid points `(i, j)` mapped to `(4i - 3j, 3i + 4j)`, the
///   rotation by `atan(3/4)` (`cos = 4/5`, `sin = 3/5`) scaled by 5, in random order. The
///   result is exactly a lattice with integer coordinates (unscaled, the division by 5
///   would round).
/// - `NearDuplicates`: base points uniform in `[0, 1)^2`, each expanded into a cluster of
///   `(x, y)`, `(x+, y)`, `(x, y+)`, `(x+, y+)` (truncated to 2 or 3 of these for the last
///   clusters), where `x+` is the next `f64` above `x`; in random order. For `n >= 2`
///   every point has a partner exactly one ulp away in x and/or y.
/// - `Collinear`: `a + t d` for a random integer base `a` in `[-10^6, 10^6]^2`, a random
///   integer direction `d` with `d.x` in `1..=1000` and `d.y` in `-1000..=1000`, and
///   `t = 0, ..., n - 1` in random order: distinct integer points exactly on one line.
/// - `Huge`: each coordinate is `+-m 2^e` with `m` uniform in `[1, 2)` and `e` uniform in
///   `665..=995`, so `|c|` lies in `[2^665, 2^996)`, inside `[1e200, 1e300]`.
/// - `Tiny`: each coordinate is, with probability 7/8, `+-m 2^e` with `e` in `-996..=-467`
///   (`|c|` in `[2^-996, 2^-466)`, inside `[1e-300, 1e-140]`), else a nonzero subnormal.
///
/// `n = 0` gives an empty set for every kind.
///
/// # Errors
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `n` exceeds [`MAX_POINTS`](crate::limits::MAX_POINTS), or,
/// for `Cocircular`, [`MAX_COCIRCULAR`], before anything is allocated.
///
/// # Complexity
/// O(n) time and space for every kind except `Cocircular`, which builds the whole circle:
/// O(N) time and space with N the number of lattice points of the chosen radius,
/// N <= max(12, 3n).
///
/// Counts nothing: generators are workloads, not measured algorithms.
///
/// ```
/// use compgeo::gen::{points, PointKind};
/// use compgeo::geometry::{orient2d, Orientation};
///
/// let a = points(PointKind::Collinear, 50, 7)?;
/// assert_eq!(a, points(PointKind::Collinear, 50, 7)?);
/// assert!(a.iter().all(|&p| orient2d(a[0], a[1], p) == Orientation::Collinear));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn points(kind: PointKind, n: usize, seed: u64) -> Result<Vec<Point2>> {
    limits::POINTS.check(n as u128)?;
    let mut rng = Rng::new(seed);
    let pts = match kind {
        PointKind::UniformSquare => (0..n)
            .map(|_| Point2::new(rng.unit(), rng.unit()))
            .collect(),
        PointKind::UniformDisk => uniform_disk(&mut rng, n),
        PointKind::Gaussian => (0..n).map(|_| normal_pair(&mut rng).into()).collect(),
        PointKind::Clustered => clustered(&mut rng, n),
        PointKind::Cocircular => cocircular(&mut rng, n)?,
        PointKind::Parabola => parabola(n),
        PointKind::Grid => shuffled_grid(&mut rng, n, |i, j| (i, j)),
        PointKind::RotatedGrid => shuffled_grid(&mut rng, n, |i, j| (4 * i - 3 * j, 3 * i + 4 * j)),
        PointKind::NearDuplicates => near_duplicates(&mut rng, n),
        PointKind::Collinear => collinear(&mut rng, n),
        PointKind::Huge => (0..n)
            .map(|_| Point2::new(huge(&mut rng), huge(&mut rng)))
            .collect(),
        PointKind::Tiny => (0..n)
            .map(|_| Point2::new(tiny(&mut rng), tiny(&mut rng)))
            .collect(),
    };
    Ok(pts)
}

pub use crate::limits::MAX_COCIRCULAR;

fn uniform_disk(rng: &mut Rng, n: usize) -> Vec<Point2> {
    let origin = Point2::new(0.0, 0.0);
    let unit = Point2::new(1.0, 0.0);
    let mut pts = Vec::with_capacity(n);
    while pts.len() < n {
        let p = Point2::new(rng.symmetric_unit(), rng.symmetric_unit());
        if cmp_dist(origin, p, origin, unit) == Ordering::Less {
            pts.push(p);
        }
    }
    pts
}

fn clustered(rng: &mut Rng, n: usize) -> Vec<Point2> {
    if n == 0 {
        return Vec::new();
    }
    let clusters = 1 + n.ilog2() as usize / 2;
    let centres: Vec<(f64, f64)> = (0..clusters).map(|_| (rng.unit(), rng.unit())).collect();
    (0..n)
        .map(|_| {
            let c = rng.index(clusters);
            let (cx, cy) = centres[c];
            let (dx, dy) = if c % 2 == 0 {
                let (gx, gy) = normal_pair(rng);
                (0.02 * gx, 0.02 * gy)
            } else {
                (0.05 * rng.symmetric_unit(), 0.05 * rng.symmetric_unit())
            };
            Point2::new(cx + dx, cy + dy)
        })
        .collect()
}

fn cocircular(rng: &mut Rng, n: usize) -> Result<Vec<Point2>> {
    if n == 0 {
        return Ok(Vec::new());
    }
    limits::COCIRCULAR.check(n as u128)?;
    let (_, mut all) = cocircular::lattice_circle(n).expect("the family has MAX_COCIRCULAR points");
    rng.partial_shuffle(&mut all, n);
    // Integers below 2^53 convert to f64 exactly.
    Ok(all[..n]
        .iter()
        .map(|&(x, y)| Point2::new(x as f64, y as f64))
        .collect())
}

fn parabola(n: usize) -> Vec<Point2> {
    // n <= MAX_POINTS = 2^26 keeps |x| <= 2^25, so x^2 <= 2^50 is exact.
    let start = -((n / 2) as i64);
    (0..n as i64)
        .map(|i| {
            let x = (start + i) as f64;
            Point2::new(x, x * x)
        })
        .collect()
}

fn shuffled_grid(rng: &mut Rng, n: usize, map: impl Fn(i64, i64) -> (i64, i64)) -> Vec<Point2> {
    let cols = ceil_sqrt(n).max(1);
    let mut pts: Vec<Point2> = (0..n)
        .map(|k| {
            let (x, y) = map((k % cols) as i64, (k / cols) as i64);
            Point2::new(x as f64, y as f64)
        })
        .collect();
    rng.shuffle(&mut pts);
    pts
}

/// `ceil(sqrt(n))` in exact integer arithmetic.
pub(crate) fn ceil_sqrt(n: usize) -> usize {
    let s = n.isqrt();
    if s * s < n {
        s + 1
    } else {
        s
    }
}

fn near_duplicates(rng: &mut Rng, n: usize) -> Vec<Point2> {
    let mut sizes = vec![4; n / 4];
    match n % 4 {
        0 => {}
        1 if n >= 5 => {
            // 4 + 1 would leave a lone point: make it 3 + 2.
            sizes.pop();
            sizes.extend([3, 2]);
        }
        r => sizes.push(r),
    }
    let mut pts = Vec::with_capacity(n);
    for size in sizes {
        let (x, y) = (rng.unit(), rng.unit());
        let (xu, yu) = (x.next_up(), y.next_up());
        let variants = [(x, y), (xu, y), (x, yu), (xu, yu)];
        pts.extend(variants[..size].iter().map(|&p| Point2::from(p)));
    }
    rng.shuffle(&mut pts);
    pts
}

fn collinear(rng: &mut Rng, n: usize) -> Vec<Point2> {
    let (ax, ay) = (
        rng.range_i64(-1_000_000, 1_000_000),
        rng.range_i64(-1_000_000, 1_000_000),
    );
    let (dx, dy) = (rng.range_i64(1, 1000), rng.range_i64(-1000, 1000));
    let mut ts: Vec<i64> = (0..n as i64).collect();
    rng.shuffle(&mut ts);
    // |coordinates| <= 10^6 + 1000 * 2^27 < 2^53: exact.
    ts.into_iter()
        .map(|t| Point2::new((ax + t * dx) as f64, (ay + t * dy) as f64))
        .collect()
}

/// `+-m 2^e` with `m` uniform over the 2^52 significands in `[1, 2)` and `e` uniform in
/// `lo..=hi` (normal exponents), assembled from bits.
fn signed_binade(rng: &mut Rng, lo: i64, hi: i64) -> f64 {
    let exponent = (rng.range_i64(lo, hi) + 1023) as u64;
    let mantissa = rng.next_u64() >> 12;
    let sign = u64::from(rng.coin()) << 63;
    f64::from_bits(sign | exponent << 52 | mantissa)
}

fn huge(rng: &mut Rng) -> f64 {
    signed_binade(rng, 665, 995)
}

fn tiny(rng: &mut Rng) -> f64 {
    if rng.below(8) == 0 {
        // A nonzero subnormal: exponent field 0, random nonzero significand.
        let mantissa = 1 + rng.below((1 << 52) - 1);
        let sign = u64::from(rng.coin()) << 63;
        f64::from_bits(sign | mantissa)
    } else {
        signed_binade(rng, -996, -467)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ceil_sqrt_is_exact() {
        for n in 0..2000usize {
            let s = ceil_sqrt(n);
            assert!(s * s >= n);
            assert!(s == 0 || (s - 1) * (s - 1) < n);
        }
        let big = (1usize << 52) + 1;
        let s = ceil_sqrt(big);
        assert!(s * s >= big && (s - 1) * (s - 1) < big);
    }

    #[test]
    fn binades_land_in_their_ranges() {
        let mut rng = Rng::new(4);
        for _ in 0..2000 {
            let v = signed_binade(&mut rng, 665, 995).abs();
            assert!(v >= 2f64.powi(665) && v < 2f64.powi(996));
        }
    }

    #[test]
    fn near_duplicate_cluster_sizes_cover_n_without_lone_points() {
        for n in 0..40 {
            let mut rng = Rng::new(n as u64);
            assert_eq!(near_duplicates(&mut rng, n).len(), n);
        }
    }
}
