//! Tensor-product surfaces against `truck-geometry` (`NurbsSurface`, `BSplineSurface`) and
//! `curvo` (`NurbsSurface3D`), in the same groups and on the same data: one seeded bicubic
//! NURBS surface of 20 × 20 control points over the unit square (heights and weights in
//! [0.5, 2) seeded) on clamped knot vectors with 16 seeded interior knots each way, and one
//! seeded bicubic Bézier patch.
//!
//! - `surface/nurbs-eval`: the NURBS surface at 10⁶ seeded parameter pairs, one call per
//!   pair (ours: `Surface::eval`; truck: `subs`; curvo: `point_at`);
//! - `surface/nurbs-grid`: the NURBS surface on the 1000 × 1000 grid of evenly spaced
//!   parameters over its domain (ours: `NurbsSurface::eval_grid`, each parameter's basis once;
//!   truck: `subs` at every grid point, its only way; curvo: `regular_sample_points`);
//! - `surface/bezier-eval`: the bicubic Bézier patch at 10⁶ pairs (ours: `eval`, and the
//!   tensor de Casteljau algorithm; truck and curvo: the patch as a B-spline surface on the
//!   knots 0, 0, 0, 0, 1, 1, 1, 1);
//! - `surface/tessellate`: the NURBS surface as a 100 × 100-cell mesh with normals (ours:
//!   `tessellate`; curvo: `regular_tessellate`, the same grid of points, normals and faces).
//!
//! Each group first checks that the libraries agree within 1e-9, so the times compare the
//! same work. Run one group with e.g. `cargo bench --bench surface -- surface/nurbs-grid`.
//!
//! Point estimates (2026-12-03, the 2-core machine, load about 1–2; each group at its
//! latest change):
//!
//! | group | compgeo | truck-geometry | curvo | ours/truck | ours/curvo |
//! |---|---|---|---|---|---|
//! | NURBS, 10⁶ calls | `eval` 164 ms | `subs` 484 ms | `point_at` 142 ms | 0.34 | 1.16 |
//! | NURBS, 1000 × 1000 grid | `eval_grid` 19.3 ms | `subs` 457 ms | `regular_sample_points` 24.9 ms | 0.042 | 0.78 |
//! | Bézier bicubic, 10⁶ calls | `eval` 76.7 ms, `de_casteljau` 75.5 ms | `subs` 113 ms | `point_at` 71.0 ms | 0.68 | 1.08 |
//! | tessellate, 101 × 101 vertices | `tessellate` 0.82 ms | (none) | `regular_tessellate` 4.09 ms | | 0.20 |
//!
//! The target of issue 16 holds: the grid at 0.042× truck's per-point time and below curvo's
//! grid sampling. One call per point stays near curvo's (each call computes both bases in
//! fresh vectors). `tessellate` asks the surface for its points and first partials on the
//! whole grid (`SurfaceDerivative::first_partials_on_grid`), which spline surfaces answer
//! from each parameter's basis and derivative computed once: 55 ms before, when every
//! vertex ran `eval` and two `partial_at` (the exact quotient rule for NURBS).

use compgeo::gen::{points, PointKind};
use compgeo::spline::{KnotVector, Point};
use compgeo::surface::{tessellate, BezierPatch, ControlNet, NurbsSurface, Surface};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use curvo::prelude::NurbsSurface3D;
use std::hint::black_box;
use std::time::Duration;
use truck_geometry::prelude::{
    BSplineSurface as TruckBSplineSurface, KnotVec, NurbsSurface as TruckNurbsSurface, Vector4,
};

const DEGREE: usize = 3;
const SIDE: usize = 20;
const PAIRS: usize = 1_000_000;
const GRID: usize = 1000;
const CELLS: usize = 100;
const SEED: u64 = 0x5EED_0016;

/// How far apart the libraries' results may be (absolute; coordinates are below 2).
const AGREEMENT: f64 = 1e-9;

/// `m` seeded values in [0, 1).
fn unit(m: usize, seed: u64) -> Vec<f64> {
    points(PointKind::UniformSquare, m, seed)
        .expect("generator")
        .into_iter()
        .map(|p| p.x)
        .collect()
}

/// Clamped cubic knots with `SIDE − DEGREE − 1` seeded distinct interior knots.
fn knots(seed: u64) -> Vec<f64> {
    let mut interior = unit(SIDE - DEGREE - 1, seed);
    interior.sort_by(f64::total_cmp);
    let mut t = vec![0.0; DEGREE + 1];
    t.extend(interior);
    t.extend([1.0; DEGREE + 1]);
    assert!(
        t[DEGREE..=SIDE].windows(2).all(|w| w[0] < w[1]),
        "distinct interior knots"
    );
    t
}

/// The control points (row i along u) and weights of the NURBS surface.
fn net_and_weights() -> (Vec<Vec<[f64; 3]>>, Vec<Vec<f64>>) {
    let heights = unit(SIDE * SIDE, SEED ^ 2);
    let weights = unit(SIDE * SIDE, SEED ^ 3);
    let step = 1.0 / (SIDE - 1) as f64;
    let net = (0..SIDE)
        .map(|i| {
            (0..SIDE)
                .map(|j| {
                    [
                        i as f64 * step,
                        j as f64 * step,
                        0.5 + 1.5 * heights[i * SIDE + j],
                    ]
                })
                .collect()
        })
        .collect();
    let w = (0..SIDE)
        .map(|i| {
            (0..SIDE)
                .map(|j| 0.5 + 1.5 * weights[i * SIDE + j])
                .collect()
        })
        .collect();
    (net, w)
}

/// The NURBS surface in each library.
struct Surfaces {
    ours: NurbsSurface<f64, 3>,
    truck: TruckNurbsSurface<Vector4>,
    curvo: NurbsSurface3D<f64>,
}

fn nurbs() -> Surfaces {
    let (net, w) = net_and_weights();
    let (tu, tv) = (knots(SEED ^ 4), knots(SEED ^ 5));
    let ours = NurbsSurface::new(
        ControlNet::new(
            net.iter()
                .map(|row| row.iter().map(|&p| Point::new(p)).collect())
                .collect(),
        )
        .expect("valid net"),
        w.concat(),
        KnotVector::new(DEGREE, tu.clone()).expect("valid knots"),
        KnotVector::new(DEGREE, tv.clone()).expect("valid knots"),
    )
    .expect("valid surface");
    let homogeneous = |i: usize, j: usize| {
        let (p, w) = (net[i][j], w[i][j]);
        [p[0] * w, p[1] * w, p[2] * w, w]
    };
    let truck = TruckNurbsSurface::new(TruckBSplineSurface::new(
        (KnotVec::from(tu.clone()), KnotVec::from(tv.clone())),
        (0..SIDE)
            .map(|i| {
                (0..SIDE)
                    .map(|j| {
                        let [x, y, z, w] = homogeneous(i, j);
                        Vector4::new(x, y, z, w)
                    })
                    .collect()
            })
            .collect(),
    ));
    let curvo = NurbsSurface3D::new(
        DEGREE,
        DEGREE,
        tu,
        tv,
        (0..SIDE)
            .map(|i| {
                (0..SIDE)
                    .map(|j| {
                        let [x, y, z, w] = homogeneous(i, j);
                        nalgebra::Point4::new(x, y, z, w)
                    })
                    .collect()
            })
            .collect(),
    );
    Surfaces { ours, truck, curvo }
}

/// `n` seeded parameter pairs in [0, 1)².
fn pairs(n: usize, seed: u64) -> Vec<(f64, f64)> {
    points(PointKind::UniformSquare, n, seed)
        .expect("generator")
        .into_iter()
        .map(|p| (p.x, p.y))
        .collect()
}

/// `n + 1` evenly spaced parameters over [0, 1], the ends exact.
fn even(n: usize) -> Vec<f64> {
    (0..=n).map(|i| i as f64 / n as f64).collect()
}

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= AGREEMENT)
}

fn group<'a>(
    c: &'a mut Criterion,
    name: &str,
) -> criterion::BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut group = c.benchmark_group(name);
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    group
}

fn bench_nurbs_eval(c: &mut Criterion) {
    let Surfaces { ours, truck, curvo } = nurbs();
    let uv = pairs(PAIRS, SEED ^ 6);
    for &(u, v) in uv.iter().step_by(997).chain(&[(0.0, 0.0), (1.0, 1.0)]) {
        let p = ours.eval(&u, &v).expect("in the domain");
        let (r, s) = (truck.subs(u, v), curvo.point_at(u, v));
        assert!(close(*p.coords(), [r.x, r.y, r.z]), "truck at ({u}, {v})");
        assert!(close(*p.coords(), [s.x, s.y, s.z]), "curvo at ({u}, {v})");
    }
    let mut group = group(c, "surface/nurbs-eval");
    group.throughput(Throughput::Elements(PAIRS as u64));
    group.bench_function("compgeo_eval", |b| {
        b.iter(|| {
            black_box(&uv)
                .iter()
                .map(|(u, v)| ours.eval(u, v).expect("in the domain")[2])
                .sum::<f64>()
        })
    });
    group.bench_function("truck_subs", |b| {
        b.iter(|| {
            black_box(&uv)
                .iter()
                .map(|&(u, v)| truck.subs(u, v).z)
                .sum::<f64>()
        })
    });
    group.bench_function("curvo_point_at", |b| {
        b.iter(|| {
            black_box(&uv)
                .iter()
                .map(|&(u, v)| curvo.point_at(u, v).z)
                .sum::<f64>()
        })
    });
    group.finish();
}

fn bench_nurbs_grid(c: &mut Criterion) {
    let Surfaces { ours, truck, curvo } = nurbs();
    let ts = even(GRID - 1);
    let grid = ours.eval_grid(&ts, &ts).expect("in the domain");
    let sampled = curvo.regular_sample_points(GRID - 1, GRID - 1);
    for i in (0..GRID).step_by(37).chain([GRID - 1]) {
        for j in (0..GRID).step_by(41).chain([GRID - 1]) {
            let p = *grid[i * GRID + j].coords();
            let r = truck.subs(ts[i], ts[j]);
            let s = sampled[i][j];
            assert!(close(p, [r.x, r.y, r.z]), "truck at ({i}, {j})");
            assert!(close(p, [s.x, s.y, s.z]), "curvo at ({i}, {j})");
        }
    }
    let mut group = group(c, "surface/nurbs-grid");
    group.throughput(Throughput::Elements((GRID * GRID) as u64));
    group.bench_function("compgeo_eval_grid", |b| {
        b.iter(|| {
            ours.eval_grid(black_box(&ts), black_box(&ts))
                .expect("in the domain")
                .iter()
                .map(|p| p[2])
                .sum::<f64>()
        })
    });
    group.bench_function("truck_subs", |b| {
        b.iter(|| {
            let ts = black_box(&ts);
            ts.iter()
                .flat_map(|&u| ts.iter().map(move |&v| (u, v)))
                .map(|(u, v)| truck.subs(u, v).z)
                .sum::<f64>()
        })
    });
    group.bench_function("curvo_regular_sample_points", |b| {
        b.iter(|| {
            curvo
                .regular_sample_points(black_box(GRID - 1), GRID - 1)
                .iter()
                .flatten()
                .map(|p| p.z)
                .sum::<f64>()
        })
    });
    group.finish();
}

fn bench_bezier_eval(c: &mut Criterion) {
    let heights = unit(16, SEED ^ 7);
    let rows: Vec<Vec<[f64; 3]>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| [i as f64 / 3.0, j as f64 / 3.0, heights[4 * i + j]])
                .collect()
        })
        .collect();
    let ours = BezierPatch::new(
        ControlNet::new(
            rows.iter()
                .map(|r| r.iter().map(|&p| Point::new(p)).collect())
                .collect(),
        )
        .expect("valid net"),
    )
    .expect("valid patch");
    let bezier_knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let truck = TruckBSplineSurface::new(
        (
            KnotVec::from(bezier_knots.clone()),
            KnotVec::from(bezier_knots.clone()),
        ),
        rows.iter()
            .map(|r| {
                r.iter()
                    .map(|p| truck_geometry::prelude::Point3::new(p[0], p[1], p[2]))
                    .collect()
            })
            .collect(),
    );
    let curvo = NurbsSurface3D::new(
        3,
        3,
        bezier_knots.clone(),
        bezier_knots,
        rows.iter()
            .map(|r| {
                r.iter()
                    .map(|p| nalgebra::Point4::new(p[0], p[1], p[2], 1.0))
                    .collect()
            })
            .collect(),
    );
    let uv = pairs(PAIRS, SEED ^ 8);
    for &(u, v) in uv.iter().step_by(997) {
        let p = *ours.eval(&u, &v).expect("any parameter").coords();
        let r = truck_geometry::prelude::ParametricSurface::subs(&truck, u, v);
        let s = curvo.point_at(u, v);
        assert!(close(p, [r.x, r.y, r.z]), "truck at ({u}, {v})");
        assert!(close(p, [s.x, s.y, s.z]), "curvo at ({u}, {v})");
    }
    let mut group = group(c, "surface/bezier-eval");
    group.throughput(Throughput::Elements(PAIRS as u64));
    group.bench_function("compgeo_eval", |b| {
        b.iter(|| {
            black_box(&uv)
                .iter()
                .map(|(u, v)| ours.eval(u, v).expect("any parameter")[2])
                .sum::<f64>()
        })
    });
    group.bench_function("compgeo_de_casteljau", |b| {
        b.iter(|| {
            black_box(&uv)
                .iter()
                .map(|(u, v)| ours.de_casteljau(u, v).expect("any parameter")[2])
                .sum::<f64>()
        })
    });
    group.bench_function("truck_subs", |b| {
        b.iter(|| {
            black_box(&uv)
                .iter()
                .map(|&(u, v)| truck_geometry::prelude::ParametricSurface::subs(&truck, u, v).z)
                .sum::<f64>()
        })
    });
    group.bench_function("curvo_point_at", |b| {
        b.iter(|| {
            black_box(&uv)
                .iter()
                .map(|&(u, v)| curvo.point_at(u, v).z)
                .sum::<f64>()
        })
    });
    group.finish();
}

fn bench_tessellate(c: &mut Criterion) {
    let Surfaces { ours, curvo, .. } = nurbs();
    let mesh = tessellate(&ours, CELLS, CELLS).expect("a valid grid");
    let theirs = curvo.regular_tessellate(CELLS, CELLS);
    assert_eq!(mesh.positions.len(), theirs.points().len());
    for (p, q) in mesh.positions.iter().zip(theirs.points()) {
        assert!(
            close(*p, [q.x, q.y, q.z]),
            "the same vertices in the same order"
        );
    }
    let mut group = group(c, "surface/tessellate");
    group.throughput(Throughput::Elements(((CELLS + 1) * (CELLS + 1)) as u64));
    group.bench_function("compgeo_tessellate", |b| {
        b.iter(|| {
            tessellate(&ours, black_box(CELLS), CELLS)
                .expect("a valid grid")
                .triangles
                .len()
        })
    });
    group.bench_function("curvo_regular_tessellate", |b| {
        b.iter(|| {
            curvo
                .regular_tessellate(black_box(CELLS), CELLS)
                .faces()
                .len()
        })
    });
    group.finish();
}

criterion_group!(
    benches,
    bench_nurbs_eval,
    bench_nurbs_grid,
    bench_bezier_eval,
    bench_tessellate
);
criterion_main!(benches);
