//! Benchmarks of `compgeo::calipers`: the rotating calipers on a hull computed once
//! (`ConvexPolygon::hull`, outside the timed loop), the diameter by brute force at small
//! sizes, and the minimum-area rectangle against the `geo` crate's `MinimumRotatedRect`, in
//! the same groups, over log-spaced sizes.
//!
//! Inputs (seeded): points on a circle (`cocircular`, every point a hull vertex, h = n),
//! uniform points in a square (`uniform-square`, h = O(log n) expected, so the calipers on
//! the hull cost next to nothing there) and, the degenerate case, a centrally symmetric set
//! on one circle (`symmetric-cocircular`: the points of a cocircular set in one half-plane
//! and their mirror images through the centre, about n points): every hull edge has a parallel
//! partner, every caliper step meets an exact tie of its angle test, and every antipodal pair
//! of edges is parallel.
//!
//! Groups `calipers/{kind}` (every id `BenchmarkId::new(name, n)`, throughput n input
//! points):
//!
//! | id | what is timed |
//! |---|---|
//! | `hull` | `ConvexPolygon::hull` alone: the cost the other calipers ids skip |
//! | `antipodal-pairs`, `diameter`, `width`, `min-area-rectangle` | the method on the precomputed hull: Θ(h) |
//! | `diameter-brute-force` | every pair of the point set, Θ(n²): n ≤ 10⁴ only |
//! | `hull+min-area-rectangle` | `ConvexPolygon::hull`, then `min_area_rectangle`, from the point set |
//! | `geo-minimum-rotated-rect` | geo's `MinimumRotatedRect` on a `MultiPoint` of the same points |
//! | `geo-minimum-rotated-rect-on-hull` | geo's `MinimumRotatedRect` on the hull as a `Polygon` |
//!
//! The two comparisons with geo: `hull+min-area-rectangle` against
//! `geo-minimum-rotated-rect` is the fair one, both from the raw points, since geo always
//! computes its own hull (Quickhull) first; `min-area-rectangle` against
//! `geo-minimum-rotated-rect-on-hull` starts both from the hull, but geo still recomputes the
//! hull of the polygon's h vertices before its rectangle. geo's rectangle projects every hull
//! vertex on every hull edge, Θ(h²), against the calipers' Θ(h); on the circles (h = n) it
//! therefore runs only for n ≤ 10⁴. The width and the antipodal pairs have no peer: geo and
//! the other crates we know offer neither.
//!
//! The `diameter/uniform-square` group moved here from `benches/hull.rs` with its ids
//! unchanged (`hull-alone`, `hull+calipers`: `convex_hull` by Akl–Toussaint against
//! `diameter` with `DiameterAlgorithm::Calipers`, validation and hull included), so earlier
//! figures stay comparable.
//!
//! Run one group with e.g. `cargo bench --bench calipers -- calipers/cocircular`.
//!
//! Figures from `benches/hull.rs` for the diameter group, on the 2-core machine shared with
//! other builds: 10⁶ uniform points, hull + calipers 5.25 ms against 4.86 ms for the hull
//! alone (1.08×), 2026-11-22; under heavier load 15.9 ms against 14.8 ms (1.08×),
//! 2026-11-23.
//!
//! One run of the whole bench on the 2-core machine (otherwise idle, load average below 1),
//! 2026-12-01, criterion medians:
//!
//! | group, n | hull | antipodal pairs | diameter | width | min-area rectangle | hull + rectangle | geo from the points | geo / ours |
//! |---|---|---|---|---|---|---|---|---|
//! | cocircular, 10³ | 70.4 µs | 25.9 µs | 74.2 µs | 162 µs | 188 µs | 272 µs | 3.70 ms | 13.6 |
//! | cocircular, 10⁴ | 1.22 ms | 364 µs | 1.13 ms | 2.33 ms | 2.39 ms | 3.49 ms | 329 ms | 94 |
//! | cocircular, 10⁵ | 15.2 ms | 4.17 ms | 16.2 ms | 29.8 ms | 43.3 ms | 56.2 ms | not run (Θ(h²)) | |
//! | uniform-square, 10³ | 14.8 µs | 0.50 µs | 0.41 µs | 2.09 µs | 2.17 µs | 12.1 µs | 35.0 µs | 2.9 |
//! | uniform-square, 10⁴ | 66.0 µs | 0.41 µs | 0.55 µs | 2.69 µs | 3.85 µs | 65.3 µs | 365 µs | 5.6 |
//! | uniform-square, 10⁵ | 582 µs | 0.45 µs | 0.68 µs | 3.37 µs | 3.30 µs | 704 µs | 4.48 ms | 6.4 |
//! | uniform-square, 10⁶ | 6.10 ms | 0.79 µs | 1.19 µs | 5.10 µs | 5.53 µs | 5.69 ms | 46.4 ms | 8.2 |
//! | symmetric-cocircular, 10³ | 84.9 µs | 88.9 µs | 213 µs | 313 µs | 330 µs | 443 µs | 4.16 ms | 9.4 |
//! | symmetric-cocircular, 10⁴ | 1.15 ms | 767 µs | 2.23 ms | 2.47 ms | 3.17 ms | 4.39 ms | 346 ms | 79 |
//! | symmetric-cocircular, 10⁵ | 14.5 ms | 14.5 ms | 35.2 ms | 59.2 ms | 47.6 ms | 68.9 ms | not run | |
//!
//! The brute-force diameter: 2.40 ms, 240 ms (cocircular, 10³, 10⁴), 2.28 ms, 298 ms
//! (uniform), against the calipers' 74 µs and 1.13 ms on the cocircular hulls. Starting from
//! the hull, geo's rectangle took 3.29 ms and 323 ms on the cocircular hulls (our 188 µs and
//! 2.39 ms) and 4.06 µs to 8.47 µs on the small uniform hulls (our 2.2 µs to 5.5 µs). The
//! exact ties of the symmetric set cost the calipers 1.1× to 3.5× the cocircular times.
//! `diameter/uniform-square`, 10⁶: hull + calipers 10.7 ms against 9.76 ms for the hull
//! alone (1.10×; at 10⁴, 74.4 µs against 98.1 µs, within this run's noise).

use compgeo::calipers::{diameter, diameter_brute_force_with, ConvexPolygon, DiameterAlgorithm};
use compgeo::count::NoCount;
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{Point2, PointSet};
use compgeo::hull::{convex_hull, Algorithm, HullOptions};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use geo::{LineString, MinimumRotatedRect, MultiPoint, Point, Polygon};
use std::hint::black_box;
use std::time::Duration;

const SEED: u64 = 0x5EED_0007;

/// The seed of the diameter group, as it was in `benches/hull.rs`: the same inputs as the
/// earlier figures.
const DIAMETER_SEED: u64 = 0x5EED_0005;

/// The largest n at which the Θ(n²) brute force runs.
const BRUTE_FORCE_MAX: usize = 10_000;

/// The largest h at which geo's Θ(h²) rectangle runs.
const GEO_MAX_HULL: usize = 20_000;

/// The inputs of the calipers groups.
#[derive(Clone, Copy, PartialEq)]
enum Input {
    Kind(PointKind),
    SymmetricCocircular,
}

impl Input {
    fn name(self) -> String {
        match self {
            Input::Kind(kind) => kind.to_string(),
            Input::SymmetricCocircular => "symmetric-cocircular".to_string(),
        }
    }

    fn points(self, n: usize) -> Vec<Point2> {
        match self {
            Input::Kind(kind) => points(kind, n, SEED).expect("generator"),
            Input::SymmetricCocircular => symmetric_cocircular(n),
        }
    }
}

/// About n integer points on one circle centred at the origin, closed under p ↦ −p: those of
/// n cocircular points in the open upper half-plane (with the positive x-axis), and their
/// mirror images (exact: negation), which lie in the other half.
fn symmetric_cocircular(n: usize) -> Vec<Point2> {
    points(PointKind::Cocircular, n, SEED)
        .expect("generator")
        .into_iter()
        .filter(|p| p.y > 0.0 || (p.y == 0.0 && p.x > 0.0))
        .flat_map(|p| [p, Point2::new(-p.x, -p.y)])
        .collect()
}

fn to_geo(pts: &[Point2]) -> MultiPoint<f64> {
    pts.iter().map(|p| Point::new(p.x, p.y)).collect()
}

/// The hull as a geo polygon, its ring closed.
fn hull_polygon(hull: &ConvexPolygon<'_>) -> Polygon<f64> {
    let pts = hull.points();
    let mut ring: Vec<(f64, f64)> = hull
        .vertices()
        .iter()
        .map(|&i| (pts[i].x, pts[i].y))
        .collect();
    ring.push(ring[0]);
    Polygon::new(LineString::from(ring), Vec::new())
}

fn calipers(c: &mut Criterion) {
    let groups: [(Input, &[usize]); 3] = [
        (
            Input::Kind(PointKind::Cocircular),
            &[1_000, 10_000, 100_000],
        ),
        (
            Input::Kind(PointKind::UniformSquare),
            &[1_000, 10_000, 100_000, 1_000_000],
        ),
        (Input::SymmetricCocircular, &[1_000, 10_000, 100_000]),
    ];
    for (input, sizes) in groups {
        let mut group = c.benchmark_group(format!("calipers/{}", input.name()));
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        for &n in sizes {
            let pts = input.points(n);
            let set = PointSet::new(&pts).expect("finite points");
            let hull = ConvexPolygon::hull(&set);
            let h = hull.vertices().len();
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::new("hull", n), &set, |b, set| {
                b.iter(|| ConvexPolygon::hull(black_box(set)))
            });
            group.bench_with_input(BenchmarkId::new("antipodal-pairs", n), &hull, |b, p| {
                b.iter(|| black_box(p).antipodal_pairs())
            });
            group.bench_with_input(BenchmarkId::new("diameter", n), &hull, |b, p| {
                b.iter(|| black_box(p).diameter().expect("non-empty"))
            });
            group.bench_with_input(BenchmarkId::new("width", n), &hull, |b, p| {
                b.iter(|| black_box(p).width().expect("non-empty"))
            });
            group.bench_with_input(BenchmarkId::new("min-area-rectangle", n), &hull, |b, p| {
                b.iter(|| black_box(p).min_area_rectangle().expect("non-empty"))
            });
            if n <= BRUTE_FORCE_MAX {
                group.bench_with_input(
                    BenchmarkId::new("diameter-brute-force", n),
                    &set,
                    |b, set| {
                        b.iter(|| {
                            diameter_brute_force_with(black_box(set), &mut NoCount)
                                .expect("non-empty")
                        })
                    },
                );
            }
            group.bench_with_input(
                BenchmarkId::new("hull+min-area-rectangle", n),
                &set,
                |b, set| {
                    b.iter(|| {
                        ConvexPolygon::hull(black_box(set))
                            .min_area_rectangle()
                            .expect("non-empty")
                    })
                },
            );
            if h <= GEO_MAX_HULL {
                let multi = to_geo(&pts);
                group.bench_with_input(
                    BenchmarkId::new("geo-minimum-rotated-rect", n),
                    &multi,
                    |b, m| b.iter(|| black_box(m).minimum_rotated_rect().expect("non-empty")),
                );
                let polygon = hull_polygon(&hull);
                group.bench_with_input(
                    BenchmarkId::new("geo-minimum-rotated-rect-on-hull", n),
                    &polygon,
                    |b, p| b.iter(|| black_box(p).minimum_rotated_rect().expect("non-empty")),
                );
            }
        }
        group.finish();
    }
}

fn diameters(c: &mut Criterion) {
    let mut group = c.benchmark_group("diameter/uniform-square");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for n in [10_000, 1_000_000] {
        let pts = points(PointKind::UniformSquare, n, DIAMETER_SEED).expect("generator");
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("hull-alone", n), &pts, |b, pts| {
            b.iter(|| {
                convex_hull(
                    black_box(pts),
                    Algorithm::AklToussaint,
                    HullOptions::default(),
                )
            })
        });
        group.bench_with_input(BenchmarkId::new("hull+calipers", n), &pts, |b, pts| {
            b.iter(|| diameter(black_box(pts), DiameterAlgorithm::Calipers))
        });
    }
    group.finish();
}

criterion_group!(benches, calipers, diameters);
criterion_main!(benches);
