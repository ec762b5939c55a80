//! One cubic Bézier evaluation per call, from a dependent crate: compgeo's `Curve::eval`
//! (validating the parameter, returning a `Result`), its `at` (a parameter checked once,
//! up front) and kurbo's `CubicBez::eval`, on the same curve and parameters.
//!
//! Each iteration evaluates the next parameter of a seeded list of 4096, with the parameter
//! and the result passed through `black_box`, so no two calls are merged or vectorised: the
//! cost measured is the cost of a call, as a user's loop that does something with each point
//! pays it. Run with `cargo bench -p compgeo-downstream`.
//!
//! Measured 2026-12-03 on the 2-core machine shared with four other builds (load average 7
//! to 9), three criterion runs of the group, medians per call:
//!
//! | run | `eval` | `at` | kurbo | `eval` / kurbo | `at` / kurbo |
//! |---|---|---|---|---|---|
//! | 1 | — | 11.6 ns | 19.9 ns | — | 0.58 |
//! | 2 | 9.9 ns | 8.8 ns | 19.5 ns | 0.51 | 0.45 |
//! | 3 | 10.9 ns | 8.8 ns | 19.9 ns | 0.55 | 0.44 |
//!
//! Three runs on 2026-12-06, quiet machine (load average about 1.5):
//!
//! | run | `eval` | `at` | kurbo | `eval` / kurbo | `at` / kurbo |
//! |---|---|---|---|---|---|
//! | 1 | 3.91 ns | 4.19 ns | 3.52 ns | 1.11 | 1.19 |
//! | 2 | 4.12 ns | 4.64 ns | 3.56 ns | 1.16 | 1.30 |
//! | 3 | 4.38 ns | 4.66 ns | 3.53 ns | 1.24 | 1.32 |
//!
//! Unloaded, every call is a few nanoseconds and kurbo's is the shortest: its `CubicBez`
//! is a cubic by type, while a compgeo curve checks its degree and the Horner bound on t
//! per call, a few instructions more than kurbo's.
//!
//! (Run 1's `eval` line was lost to the terminal.) Both evaluations are inlined into the
//! bench (kurbo's `eval` is `#[inline]`, compgeo's cubic `#[inline(always)]`); we have not
//! traced why kurbo's sum of Bernstein terms costs twice the nested form here, while the
//! in-crate bench over a slice of 10⁶ parameters (`benches/spline.rs`), where both loops are
//! vectorised, sees parity.

use compgeo::spline::{Curve, Finite};
use compgeo_downstream::{control_points, cubic_and_parameters};
use criterion::{criterion_group, criterion_main, Criterion};
use kurbo::ParamCurve;
use std::hint::black_box;

const PARAMETERS: usize = 4096;

fn per_call(c: &mut Criterion) {
    let (curve, ts) = cubic_and_parameters(PARAMETERS, 7);
    let p = control_points(&curve);
    let kp = |q: [f64; 2]| kurbo::Point::new(q[0], q[1]);
    let kurbo_curve = kurbo::CubicBez::new(kp(p[0]), kp(p[1]), kp(p[2]), kp(p[3]));
    let checked: Vec<Finite<f64>> = ts
        .iter()
        .map(|&t| Finite::new(t, "t").expect("finite"))
        .collect();

    let mut group = c.benchmark_group("downstream/cubic-per-call");
    let mut i = 0usize;
    group.bench_function("compgeo_eval", |b| {
        b.iter(|| {
            i = (i + 1) % PARAMETERS;
            black_box(curve.eval(black_box(&ts[i])).expect("finite parameter"))
        })
    });
    group.bench_function("compgeo_at", |b| {
        b.iter(|| {
            i = (i + 1) % PARAMETERS;
            black_box(curve.at(black_box(&checked[i])))
        })
    });
    group.bench_function("kurbo", |b| {
        b.iter(|| {
            i = (i + 1) % PARAMETERS;
            black_box(kurbo_curve.eval(black_box(ts[i])))
        })
    });
    group.finish();
}

criterion_group!(benches, per_call);
criterion_main!(benches);
