//! Cubic Bézier evaluation throughput: compgeo's generic `Bezier<f64, 2>` evaluation
//! (`Curve::eval`) against a hand-written `f64` cubic (the same Horner-type scheme of
//! [PPB, §2.3, Obs. 4] on a fixed array, and the plain Bernstein sum), kurbo's
//! `CubicBez::eval` and lyon_geom's `CubicBezierSegment::sample`, over 10⁶ parameters in
//! [0, 1]; then one evaluation by de Casteljau (Θ(n²)) and by Horner (Θ(n)) over log-spaced
//! degrees n.
//!
//! Measured on 2 cores shared with other builds (load 3–8): criterion's times move by ±30%
//! between runs of the group, so the ratios to kurbo below are each from one run. Run with
//! kurbo at 3.16 ms per 10⁶ parameters: `eval` 0.96×, `at` 1.02×, `eval_each` 0.99×, the
//! hand-written Horner cubic 0.95×, `horner_with` (validating, counting with `NoCount`)
//! 1.16×, lyon_geom 1.05×; another, kurbo 3.14 ms: 0.95×, 1.08×, 0.97×, 1.02×, 1.10×, 0.97×.
//! An interleaved harness (each variant in turn, 200 rounds, minimum time) gave kurbo
//! 1.98 ms, `eval` 1.01×, `at` 1.01×, `eval_each` 0.96×, hand-written 0.97×, `horner_with`
//! 0.90×. Before the changes of `spline/bezier/horner.rs`, `eval` was 1.58× and `eval_each` 1.33×
//! (quiet machine): the result's finiteness check went through the stack and integer
//! registers, the control points were reloaded from the heap at every call, results of
//! out-of-line paths were merged through memory, and `eval_each` spent a pre-pass per chunk
//! on bounding its parameters.

use compgeo::count::NoCount;
use compgeo::gen::{points, PointKind};
use compgeo::spline::{Bezier, Curve, Finite, Point};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use kurbo::ParamCurve;
use std::hint::black_box;

const PARAMETERS: usize = 1_000_000;

/// Seeded parameters in [0, 1) and a seeded cubic in the unit square.
fn inputs() -> (Vec<f64>, [[f64; 2]; 4]) {
    let ts = points(PointKind::UniformSquare, PARAMETERS, 11)
        .expect("generator")
        .into_iter()
        .map(|p| p.x)
        .collect();
    let c = points(PointKind::UniformSquare, 4, 3).expect("generator");
    (ts, [0, 1, 2, 3].map(|i| [c[i].x, c[i].y]))
}

/// The Horner-type scheme written out for one cubic in f64 (the same nesting as the generic
/// code: one factor 1 − t per step, no division), as a reference for what the generic code
/// should compile to.
#[inline]
fn horner_cubic(p: &[[f64; 2]; 4], t: f64) -> [f64; 2] {
    let u = 1.0 - t;
    let t2 = t * t;
    [0, 1].map(|j| {
        ((p[0][j] * u + 3.0 * t * p[1][j]) * u + 3.0 * t2 * p[2][j]) * u + t2 * t * p[3][j]
    })
}

/// The Bernstein sum written out: (1 − t)³ b₀ + 3(1 − t)² t b₁ + 3(1 − t) t² b₂ + t³ b₃.
#[inline]
fn bernstein_cubic(p: &[[f64; 2]; 4], t: f64) -> [f64; 2] {
    let u = 1.0 - t;
    let w = [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t];
    [0, 1].map(|j| w[0] * p[0][j] + w[1] * p[1][j] + w[2] * p[2][j] + w[3] * p[3][j])
}

fn bench_cubic(c: &mut Criterion) {
    let (ts, p) = inputs();
    let curve = Bezier::new(p.iter().map(|&q| Point::new(q)).collect()).expect("finite");
    let kp = |q: [f64; 2]| kurbo::Point::new(q[0], q[1]);
    let kurbo_curve = kurbo::CubicBez::new(kp(p[0]), kp(p[1]), kp(p[2]), kp(p[3]));
    let pt = |q: [f64; 2]| lyon_geom::point(q[0], q[1]);
    let lyon_curve = lyon_geom::CubicBezierSegment {
        from: pt(p[0]),
        ctrl1: pt(p[1]),
        ctrl2: pt(p[2]),
        to: pt(p[3]),
    };

    let mut group = c.benchmark_group("cubic_eval");
    group.throughput(Throughput::Elements(PARAMETERS as u64));
    group.sample_size(20);
    group.bench_function("compgeo_generic", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for t in black_box(&ts) {
                let q = curve.eval(t).expect("finite parameter");
                acc += q[0] + q[1];
            }
            acc
        })
    });
    let finite: Vec<Finite<f64>> = ts
        .iter()
        .map(|&t| Finite::new(t, "t").expect("finite"))
        .collect();
    group.bench_function("compgeo_generic_at", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for t in black_box(&finite) {
                let q = curve.at(t);
                acc += q[0] + q[1];
            }
            acc
        })
    });
    group.bench_function("compgeo_generic_eval_each", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            curve
                .eval_each(black_box(&ts), |q| acc += q[0] + q[1])
                .expect("finite parameters");
            acc
        })
    });
    group.bench_function("compgeo_horner_nocount", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for t in black_box(&ts) {
                let q = curve
                    .horner_with(t, &mut NoCount)
                    .expect("finite parameter");
                acc += q[0] + q[1];
            }
            acc
        })
    });
    group.bench_function("hand_written_horner", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &t in black_box(&ts) {
                let q = horner_cubic(&p, t);
                acc += q[0] + q[1];
            }
            acc
        })
    });
    group.bench_function("hand_written_bernstein", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &t in black_box(&ts) {
                let q = bernstein_cubic(&p, t);
                acc += q[0] + q[1];
            }
            acc
        })
    });
    group.bench_function("kurbo", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &t in black_box(&ts) {
                let q = kurbo_curve.eval(t);
                acc += q.x + q.y;
            }
            acc
        })
    });
    group.bench_function("lyon_geom", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &t in black_box(&ts) {
                let q = lyon_curve.sample(t);
                acc += q.x + q.y;
            }
            acc
        })
    });
    group.finish();
}

fn bench_degree(c: &mut Criterion) {
    let mut group = c.benchmark_group("bezier_eval_degree");
    for n in [4usize, 16, 64, 256] {
        for (kind, name) in [
            (PointKind::UniformSquare, "uniform"),
            (PointKind::Cocircular, "cocircular"),
        ] {
            let pts = points(kind, n + 1, 5).expect("generator");
            let curve = Bezier::new(pts.into_iter().map(Point::from).collect()).expect("finite");
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(
                BenchmarkId::new(format!("de_casteljau/{name}"), n),
                &curve,
                |b, c| b.iter(|| c.de_casteljau(black_box(&0.3)).expect("finite")),
            );
            group.bench_with_input(
                BenchmarkId::new(format!("horner/{name}"), n),
                &curve,
                |b, c| b.iter(|| c.horner(black_box(&0.3)).expect("finite")),
            );
        }
    }
    group.finish();
}

criterion_group!(benches, bench_cubic, bench_degree);
criterion_main!(benches);
