//! Benchmarks of `compgeo::hull` against the `geo` crate's `ConvexHull` (Quickhull) and
//! `graham_hull`, in the same groups, over log-spaced sizes: uniform points in a square (few
//! hull vertices), points on a circle (every point a vertex) and collinear points (the
//! degenerate case). The diameter group (the hull alone against hull + calipers) is in
//! `benches/calipers.rs`, with its ids and inputs unchanged.
//!
//! Run one group with e.g. `cargo bench --bench hull -- hull/uniform-square`.
//!
//! Medians measured on the 2-core machine shared with other builds (2026-11-22):
//!
//! | group, n | fastest compgeo | geo `ConvexHull` | ratio |
//! |---|---|---|---|
//! | uniform-square, 10⁶ | akl-toussaint 4.6–5.1 ms | 33–34 ms | 6.7–7.3× |
//! | cocircular (h = n), 10⁵ | monotone-chain 12.4–14.7 ms | 24.8–29.8 ms | 2.0× |
//! | collinear, 10⁵ | quickhull 5.2 ms | 4.9 ms | 0.95× |
//!
//! After the hull's sort moved to integer keys and the chains stopped copying (2026-11-23),
//! same machine, other builds running (geo's own time varied 2–3× between runs, so compare
//! ratios within a run):
//!
//! | group, n | compgeo | geo `ConvexHull` | ratio |
//! |---|---|---|---|
//! | uniform-square, 10⁶ | akl-toussaint 9.2 ms | 77 ms | 8.4× |
//! | cocircular (h = n), 10⁵ | monotone-chain 10.9 ms | 62 ms | 5.7× |
//! | cocircular (h = n), 10⁵ | chan 128 ms | 62 ms | 0.49× |
//! | uniform-square, 10⁶ | chan 459 ms | 77 ms | 0.17× |
//!
//! An earlier run of the same code under heavier load: monotone-chain 23.4 ms against geo's
//! 78.7 ms on the circle (3.4×). Chan's algorithm then rebuilt the group hulls for every guess
//! of h (m = 4, 16, 256, 65 536), and on 10⁵ points on a circle the round with m = 65 536 ran
//! 65 536 wrapping steps before it gave up.
//!
//! Chan's hull reworked (2026-12-03; first guess 256, each group filtered by Akl–Toussaint,
//! the next round built from the group hulls' vertices, marches cut at the cost of the next
//! round, at most two groups merged into one; the Akl–Toussaint filter tests only the edges
//! facing the box sides a point is beyond). Medians of 15 interleaved runs in one process, 2
//! cores under heavy load from other builds, so only the ratios mean something:
//!
//! | input, n | chan / monotone-chain | chan / akl-toussaint |
//! |---|---|---|
//! | uniform-disk, 10⁶ | 0.52–0.57 | 1.60–1.91 |
//! | uniform-disk, 10⁵ | 0.81–0.93 | 1.33–1.86 |
//! | cocircular (h = n), 10⁵ | 2.36–2.73 | 0.98–1.06 |
//!
//! Then (same day) Chan's hull filters all points by Akl–Toussaint before its rounds (the
//! filter stops testing when the first 1024 points nearly all survive), and a first guess
//! whose first four groups are mostly hull vertices restarts with the next guess. Medians of
//! 21 interleaved runs, two runs, load average 2.8 then 9.8:
//!
//! | input, n | chan / monotone-chain | chan / akl-toussaint |
//! |---|---|---|
//! | uniform-disk, 10⁶ | 0.32, 0.33 | 0.95, 1.03 |
//! | uniform-disk, 10⁵ | 0.30, 0.35 | 1.04, 0.96 |
//! | cocircular (h = n), 10⁵ | 1.30, 1.33 | (1.26, 1.32) |
//!
//! (The bracketed ratios were taken while Akl–Toussaint's own filter also stopped early on
//! convex input; only Chan's does now, so Akl–Toussaint is slower there than they say.)
//! On a disk, what is left after the filter (a tenth of the points, in a thin ring) is
//! sorted by both: Chan's first groups of it are mostly hull vertices, so it takes the one
//! group of the larger guess, which is Akl–Toussaint's sort. Chan can only match
//! Akl–Toussaint there, not beat it: the filter, common to both, is most of the time.
//!
//! The `hull/uniform-disk` group has the same inputs for criterion.
//!
//! Criterion medians on 2026-12-06 (quiet machine), sequential then with `--features
//! parallel`: uniform-disk 10⁶: chan 31.6 ms, akl-toussaint 29.9 ms, monotone-chain
//! 103.2 ms (0.31× the chain, 1.06× Akl–Toussaint); 10⁵: 3.07, 2.78, 5.67 ms (0.54×,
//! 1.10×). With `parallel` at 10⁶: 34.0, 21.8, 124.0 ms (Akl–Toussaint's parallel radix
//! sort of its survivors has no counterpart in Chan's march); cocircular 10⁵: chan 6.50 ms
//! against the chain's 6.15 ms (1.06×).
//!
//! Then Chan's hull orders the filter's survivors by octant before grouping them (a group
//! of a thin ring's points then lies along one arc, and its hull is small). Uniform disk,
//! 10⁶, 21 interleaved rounds in one process, fastest of each, two processes: chan /
//! akl-toussaint 0.88 and 0.89 (28.2–28.6 ms against 32.0 ms; the filter alone 18.5 ms),
//! from 1.03 before.

use compgeo::count::{NoCount, Silent};
use compgeo::delaunay::{triangulate_with, Algorithm as Builder};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{cmp_lex, comparison_sorted_lex, radix_sorted_lex, Point2, PointSet};
use compgeo::hull::{convex_hull, convex_hull_with, Algorithm, HullOptions};
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use geo::{ConvexHull, Coord, MultiPoint, Point};
use std::hint::black_box;
use std::time::Duration;

const SEED: u64 = 0x5EED_0005;

fn to_geo(pts: &[Point2]) -> MultiPoint<f64> {
    pts.iter().map(|p| Point::new(p.x, p.y)).collect()
}

fn to_coords(pts: &[Point2]) -> Vec<Coord<f64>> {
    pts.iter().map(|p| Coord { x: p.x, y: p.y }).collect()
}

fn hulls(c: &mut Criterion) {
    let groups: [(PointKind, &[usize]); 4] = [
        (
            PointKind::UniformSquare,
            &[1_000, 10_000, 100_000, 1_000_000],
        ),
        (PointKind::UniformDisk, &[10_000, 100_000, 1_000_000]),
        (PointKind::Cocircular, &[1_000, 10_000, 100_000]),
        (PointKind::Collinear, &[1_000, 100_000]),
    ];
    let ours = [
        Algorithm::AklToussaint,
        Algorithm::MonotoneChain,
        Algorithm::Graham,
        Algorithm::Quickhull,
        Algorithm::Chan,
    ];
    for (kind, sizes) in groups {
        let mut group = c.benchmark_group(format!("hull/{kind}"));
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        for &n in sizes {
            let pts = points(kind, n, SEED).expect("generator");
            group.throughput(Throughput::Elements(n as u64));
            for algorithm in ours {
                group.bench_with_input(BenchmarkId::new(algorithm.name(), n), &pts, |b, pts| {
                    b.iter(|| convex_hull(black_box(pts), algorithm, HullOptions::default()))
                });
            }
            if n <= 10_000 || kind != PointKind::Cocircular {
                group.bench_with_input(BenchmarkId::new("jarvis", n), &pts, |b, pts| {
                    b.iter(|| {
                        convex_hull(black_box(pts), Algorithm::Jarvis, HullOptions::default())
                    })
                });
            }
            let multi = to_geo(&pts);
            group.bench_with_input(BenchmarkId::new("geo-convex-hull", n), &multi, |b, m| {
                b.iter(|| black_box(m).convex_hull())
            });
            let coords = to_coords(&pts);
            group.bench_with_input(BenchmarkId::new("geo-graham-hull", n), &coords, |b, v| {
                b.iter_batched_ref(
                    || v.clone(),
                    |v| geo::algorithm::convex_hull::graham_hull(v, false),
                    BatchSize::LargeInput,
                )
            });
        }
        group.finish();
    }
}

/// The inputs of the `lex-sort` groups.
const LEX_KINDS: [PointKind; 5] = [
    PointKind::UniformSquare,
    PointKind::UniformDisk,
    PointKind::Gaussian,
    PointKind::Clustered,
    PointKind::Grid,
];
const LEX_SIZES: [usize; 4] = [1_000, 10_000, 100_000, 1_000_000];

/// The items sorted by `cmp_lex` and index, as the divide-and-conquer builder sorted them
/// before the radix sort.
fn cmp_lex_sorted(points: &[Point2]) -> Vec<(Point2, usize)> {
    let mut items: Vec<(Point2, usize)> = points.iter().copied().zip(0..).collect();
    items.sort_unstable_by(|a, b| cmp_lex(a.0, b.0).then(a.1.cmp(&b.1)));
    items
}

/// The lexicographic sort of the hull and Delaunay code alone, from the points to the sorted
/// `(point, index)` items: the radix sort `NoCount` runs take (`radix`), the comparison sort
/// counted runs take (`sort-unstable`: `(key, index)` pairs, then the points gathered), and
/// `sort_unstable_by` with `cmp_lex` on the items (`cmp-lex`).
fn lex_sorts(c: &mut Criterion) {
    for kind in LEX_KINDS {
        let mut group = c.benchmark_group(format!("lex-sort/{kind}"));
        group.sample_size(10);
        for n in LEX_SIZES {
            let pts = points(kind, n, SEED).expect("generator");
            group.throughput(Throughput::Elements(n as u64));
            type Sort = fn(&[Point2]) -> Vec<(Point2, usize)>;
            let sorts: [(&str, Sort); 3] = [
                ("radix", radix_sorted_lex),
                ("sort-unstable", comparison_sorted_lex),
                ("cmp-lex", cmp_lex_sorted),
            ];
            for (name, sort) in sorts {
                group.bench_with_input(BenchmarkId::new(name, n), &pts, |b, pts| {
                    b.iter(|| sort(black_box(pts)))
                });
            }
        }
        group.finish();
    }
}

/// Whole algorithms with each sort: `radix` runs with `NoCount`, `sort-unstable` with
/// [`Silent`], so the two differ in the sort alone. (Akl–Toussaint, which sorts only its
/// survivors, measured no faster with the radix sort and now always compares; its numbers
/// are in docs/design.md.)
fn lex_sort_algorithms(c: &mut Criterion) {
    for kind in &LEX_KINDS[..] {
        let kind = *kind;
        if kind == PointKind::Clustered {
            continue;
        }
        let mut group = c.benchmark_group(format!("lex-sort-hull/{kind}"));
        group.sample_size(10);
        for n in LEX_SIZES {
            let pts = points(kind, n, SEED).expect("generator");
            let set = PointSet::new(&pts).expect("finite");
            group.throughput(Throughput::Elements(n as u64));
            for algorithm in [Algorithm::MonotoneChain, Algorithm::Chan] {
                let id = |sort: &str| BenchmarkId::new(format!("{algorithm}/{sort}"), n);
                let options = HullOptions::default();
                group.bench_function(id("radix"), |b| {
                    b.iter(|| convex_hull_with(black_box(&set), algorithm, options, &mut NoCount))
                });
                group.bench_function(id("sort-unstable"), |b| {
                    b.iter(|| convex_hull_with(black_box(&set), algorithm, options, &mut Silent))
                });
            }
        }
        group.finish();
        let mut group = c.benchmark_group(format!("lex-sort-delaunay/{kind}"));
        group.sample_size(10);
        for n in LEX_SIZES {
            let pts = points(kind, n, SEED).expect("generator");
            let set = PointSet::new(&pts).expect("finite");
            group.throughput(Throughput::Elements(n as u64));
            for builder in [Builder::DivideAndConquer, Builder::Fortune, Builder::Lawson] {
                // Fortune's sweep takes seconds at 10⁶ points, Lawson's flips grow faster
                // than n log n: smaller sizes only.
                if (builder == Builder::Fortune && n > 100_000)
                    || (builder == Builder::Lawson && n > 10_000)
                {
                    continue;
                }
                let id = |sort: &str| BenchmarkId::new(format!("{builder}/{sort}"), n);
                group.bench_function(id("radix"), |b| {
                    b.iter(|| triangulate_with(black_box(&set), builder, &mut NoCount))
                });
                group.bench_function(id("sort-unstable"), |b| {
                    b.iter(|| triangulate_with(black_box(&set), builder, &mut Silent))
                });
            }
        }
        group.finish();
    }
}

criterion_group!(benches, hulls, lex_sorts, lex_sort_algorithms);
criterion_main!(benches);
