//! The kernel's cost: compgeo's exact predicates against bare `robust` on in-window input
//! (the window check must not make them slower), the price of the slow paths on extreme
//! magnitudes, and the no-op counter against no counter at all.

use compgeo::count::{Counter, Counts, NoCount};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{cmp_dist, incircle, orient2d, CountedPredicates, Orientation, Point2};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::hint::black_box;

const N: usize = 4096;

fn coord(p: Point2) -> robust::Coord<f64> {
    robust::Coord { x: p.x, y: p.y }
}

fn scaled(kind: PointKind, factor: f64) -> Vec<Point2> {
    points(kind, N, 7)
        .expect("generator")
        .into_iter()
        .map(|p| Point2::new(p.x * factor, p.y * factor))
        .collect()
}

/// Orientation of every consecutive triple.
fn orient_all(pts: &[Point2]) -> usize {
    pts.windows(3)
        .filter(|w| orient2d(w[0], w[1], w[2]) == Orientation::CounterClockwise)
        .count()
}

fn orient_all_robust(pts: &[Point2]) -> usize {
    pts.windows(3)
        .filter(|w| robust::orient2d(coord(w[0]), coord(w[1]), coord(w[2])) > 0.0)
        .count()
}

fn orient_all_counted<C: Counter>(pts: &[Point2], counter: &mut C) -> usize {
    pts.windows(3)
        .filter(|w| counter.orient2d(w[0], w[1], w[2]) == Orientation::CounterClockwise)
        .count()
}

fn bench_orient2d(c: &mut Criterion) {
    let mut group = c.benchmark_group("orient2d");
    group.throughput(Throughput::Elements(N as u64 - 2));
    let inputs = [
        (
            "uniform",
            points(PointKind::UniformSquare, N, 7).expect("generator"),
        ),
        ("grid", points(PointKind::Grid, N, 7).expect("generator")),
        (
            "collinear",
            points(PointKind::Collinear, N, 7).expect("generator"),
        ),
    ];
    for (name, pts) in &inputs {
        group.bench_with_input(BenchmarkId::new("compgeo", name), pts, |b, p| {
            b.iter(|| orient_all(black_box(p)))
        });
        group.bench_with_input(BenchmarkId::new("robust", name), pts, |b, p| {
            b.iter(|| orient_all_robust(black_box(p)))
        });
    }
    // Outside robust's safe window: rescaled (all near 1e300) and big-integer (mixed) paths.
    let huge = scaled(PointKind::UniformSquare, 1e300);
    group.bench_with_input(BenchmarkId::new("compgeo", "near-1e300"), &huge, |b, p| {
        b.iter(|| orient_all(black_box(p)))
    });
    let mut mixed = scaled(PointKind::UniformSquare, 1e300);
    for (i, p) in mixed.iter_mut().enumerate().filter(|(i, _)| i % 2 == 0) {
        *p = Point2::new(
            p.x * 1e-300 * 1e-300 * (i as f64 + 1.0),
            p.y * 1e-300 * 1e-300,
        );
    }
    group.bench_with_input(
        BenchmarkId::new("compgeo", "mixed-1e300-1e-300"),
        &mixed,
        |b, p| b.iter(|| orient_all(black_box(p))),
    );
    group.finish();
}

fn bench_incircle(c: &mut Criterion) {
    let mut group = c.benchmark_group("incircle");
    group.throughput(Throughput::Elements(N as u64 - 3));
    for (name, pts) in [
        (
            "uniform",
            points(PointKind::UniformSquare, N, 7).expect("generator"),
        ),
        (
            "cocircular",
            points(PointKind::Cocircular, N, 7).expect("generator"),
        ),
    ] {
        group.bench_with_input(BenchmarkId::new("compgeo", name), &pts, |b, p| {
            b.iter(|| {
                black_box(p)
                    .windows(4)
                    .filter(|w| {
                        incircle(w[0], w[1], w[2], w[3]) == compgeo::geometry::InCircle::Inside
                    })
                    .count()
            })
        });
        group.bench_with_input(BenchmarkId::new("robust", name), &pts, |b, p| {
            b.iter(|| {
                black_box(p)
                    .windows(4)
                    .filter(|w| {
                        robust::incircle(coord(w[0]), coord(w[1]), coord(w[2]), coord(w[3])) > 0.0
                    })
                    .count()
            })
        });
    }
    group.finish();
}

fn bench_cmp_dist(c: &mut Criterion) {
    let mut group = c.benchmark_group("cmp_dist");
    group.throughput(Throughput::Elements(N as u64 - 3));
    for (name, pts) in [
        (
            "uniform",
            points(PointKind::UniformSquare, N, 7).expect("generator"),
        ),
        ("grid", points(PointKind::Grid, N, 7).expect("generator")),
    ] {
        group.bench_with_input(BenchmarkId::new("compgeo", name), &pts, |b, p| {
            b.iter(|| {
                black_box(p)
                    .windows(4)
                    .filter(|w| cmp_dist(w[0], w[1], w[2], w[3]).is_lt())
                    .count()
            })
        });
        // The rounded comparison, for scale: fast but wrong on ties and extremes.
        group.bench_with_input(BenchmarkId::new("rounded-f64", name), &pts, |b, p| {
            b.iter(|| {
                black_box(p)
                    .windows(4)
                    .filter(|w| {
                        let d = |a: Point2, b: Point2| (b.x - a.x).powi(2) + (b.y - a.y).powi(2);
                        d(w[0], w[1]) < d(w[2], w[3])
                    })
                    .count()
            })
        });
    }
    group.finish();
}

/// The no-op counter must cost nothing: the same loop with no counter, with `NoCount`, and
/// with real `Counts`.
fn bench_counter(c: &mut Criterion) {
    let mut group = c.benchmark_group("counter");
    group.throughput(Throughput::Elements(N as u64 - 2));
    let pts = points(PointKind::UniformSquare, N, 7).expect("generator");
    group.bench_function("no-counter", |b| b.iter(|| orient_all(black_box(&pts))));
    group.bench_function("NoCount", |b| {
        b.iter(|| orient_all_counted(black_box(&pts), &mut NoCount))
    });
    group.bench_function("Counts", |b| {
        b.iter(|| {
            let mut counts = Counts::default();
            let n = orient_all_counted(black_box(&pts), &mut counts);
            (n, black_box(counts))
        })
    });
    group.finish();
}

criterion_group!(
    benches,
    bench_orient2d,
    bench_incircle,
    bench_cmp_dist,
    bench_counter
);
criterion_main!(benches);
