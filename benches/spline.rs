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
use compgeo::spline::interpolate::{
    cubic_spline, cubic_spline_tangents, estimate_tangents, hermite, lagrange, newton,
    parameterise, vandermonde, EndCondition, Parameterisation,
};
use compgeo::spline::{Bezier, Curve, CurveDerivative, Finite, Point};
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use kurbo::ParamCurve;
use ndarray::{Array1, Array2, RemoveAxis};
use ndarray_interp::interp1d::cubic_spline::{BoundaryCondition, CubicSpline};
use ndarray_interp::interp1d::Interp1DBuilder;
use std::hint::black_box;
use std::time::Duration;

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

/// The sum of the coordinates of `eval` at every parameter: what every evaluation bench
/// returns, so that no evaluation is optimised away.
fn coordinate_sum<T>(ts: &[T], mut eval: impl FnMut(&T) -> [f64; 2]) -> f64 {
    ts.iter()
        .map(|t| {
            let q = eval(t);
            q[0] + q[1]
        })
        .sum()
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
            coordinate_sum(black_box(&ts), |t| {
                curve.eval(t).expect("finite parameter").0
            })
        })
    });
    let finite: Vec<Finite<f64>> = ts
        .iter()
        .map(|&t| Finite::new(t, "t").expect("finite"))
        .collect();
    group.bench_function("compgeo_generic_at", |b| {
        b.iter(|| coordinate_sum(black_box(&finite), |t| curve.at(t).0))
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
            coordinate_sum(black_box(&ts), |t| {
                curve
                    .horner_with(t, &mut NoCount)
                    .expect("finite parameter")
                    .0
            })
        })
    });
    group.bench_function("hand_written_horner", |b| {
        b.iter(|| coordinate_sum(black_box(&ts), |&t| horner_cubic(&p, t)))
    });
    group.bench_function("hand_written_bernstein", |b| {
        b.iter(|| coordinate_sum(black_box(&ts), |&t| bernstein_cubic(&p, t)))
    });
    group.bench_function("kurbo", |b| {
        b.iter(|| {
            coordinate_sum(black_box(&ts), |&t| {
                let q = kurbo_curve.eval(t);
                [q.x, q.y]
            })
        })
    });
    group.bench_function("lyon_geom", |b| {
        b.iter(|| {
            coordinate_sum(black_box(&ts), |&t| {
                let q = lyon_curve.sample(t);
                [q.x, q.y]
            })
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

/// A point of the plane for the interpolation groups.
type P = Point<f64, 2>;

const INTERPOLATION_SEED: u64 = 0x5EED_000A;

/// How many parameters the evaluation groups evaluate per iteration.
const SPLINE_PARAMETERS: usize = 100_000;
const POLYNOMIAL_PARAMETERS: usize = 1_000;

/// The data of the spline groups: seeded points and their knots.
#[derive(Clone, Copy)]
enum SplineData {
    /// Uniform points in the square, knots 0, 1, 2, ...
    UniformKnots,
    /// Uniform points in the square, chord-length knots.
    ChordLength,
    /// The degenerate case: near-duplicate points (clusters one ulp apart) in lexicographic
    /// order, the knots of a cluster one ulp apart and those of consecutive clusters 1 apart,
    /// so gaps of about 10⁻¹⁶ relative to the knots sit next to gaps of 1. (Chord-length knots
    /// would not do: a chord of one ulp is absorbed when added to a knot near 1.)
    NearDuplicates,
}

impl SplineData {
    const ALL: [SplineData; 3] = [
        SplineData::UniformKnots,
        SplineData::ChordLength,
        SplineData::NearDuplicates,
    ];

    fn name(self) -> &'static str {
        match self {
            SplineData::UniformKnots => "uniform-knots",
            SplineData::ChordLength => "chord-length",
            SplineData::NearDuplicates => "near-duplicates",
        }
    }

    /// n points, the last equal to the first (a closed polygon, so that the periodic spline
    /// runs on the same data as the natural one), and their knots.
    fn closed(self, n: usize) -> (Vec<f64>, Vec<P>) {
        let kind = match self {
            SplineData::NearDuplicates => PointKind::NearDuplicates,
            _ => PointKind::UniformSquare,
        };
        let mut pts = points(kind, n - 1, INTERPOLATION_SEED).expect("generator");
        if let SplineData::NearDuplicates = self {
            pts.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        }
        pts.push(pts[0]);
        let pts: Vec<P> = pts.into_iter().map(P::from).collect();
        let knots = match self {
            SplineData::UniformKnots => parameterise(&pts, Parameterisation::Uniform),
            SplineData::ChordLength => parameterise(&pts, Parameterisation::ChordLength),
            SplineData::NearDuplicates => Ok(cluster_knots(&pts)),
        };
        (knots.expect("distinct consecutive points"), pts)
    }
}

/// Knots from 1 (so that an ulp is a normal gap), one ulp apart between points closer than
/// 10⁻⁹ in each coordinate, 1 apart otherwise.
fn cluster_knots(pts: &[P]) -> Vec<f64> {
    let mut knots = Vec::with_capacity(pts.len());
    let mut u = 1.0f64;
    knots.push(u);
    for w in pts.windows(2) {
        let near = (w[1][0] - w[0][0]).abs().max((w[1][1] - w[0][1]).abs()) < 1e-9;
        u = if near { u.next_up() } else { u + 1.0 };
        knots.push(u);
    }
    knots
}

/// `m` seeded parameters uniform in `[a, b)`.
fn parameters(m: usize, a: f64, b: f64) -> Vec<f64> {
    points(PointKind::UniformSquare, m, INTERPOLATION_SEED ^ 1)
        .expect("generator")
        .into_iter()
        .map(|p| a + p.x * (b - a))
        .collect()
}

/// The knots and points as ndarray-interp takes them: x, and one row per point.
fn to_ndarray(knots: &[f64], pts: &[P]) -> (Array1<f64>, Array2<f64>) {
    let flat: Vec<f64> = pts.iter().flat_map(|p| [p[0], p[1]]).collect();
    (
        Array1::from(knots.to_vec()),
        Array2::from_shape_vec((pts.len(), 2), flat).expect("n × 2"),
    )
}

/// ndarray-interp's cubic spline strategy with natural or periodic ends.
fn ndarray_spline<D: RemoveAxis>(periodic: bool) -> CubicSpline<f64, D> {
    CubicSpline::new().boundary(if periodic {
        BoundaryCondition::Periodic
    } else {
        BoundaryCondition::Natural
    })
}

/// The Catmull–Rom tangents that the `splines` crate uses: the central difference
/// `(p_{i+1} − p_{i−1}) / (u_{i+1} − u_{i−1})`, one-sided at the ends.
fn catmull_rom_tangents(knots: &[f64], pts: &[P]) -> Vec<P> {
    let n = pts.len();
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            let h = knots[b] - knots[a];
            P::new([(pts[b][0] - pts[a][0]) / h, (pts[b][1] - pts[a][1]) / h])
        })
        .collect()
}

fn interpolation_group<'a>(
    c: &'a mut Criterion,
    name: String,
) -> criterion::BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut group = c.benchmark_group(name);
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    group
}

const SPLINE_SIZES: [usize; 4] = [1_000, 10_000, 100_000, 1_000_000];

fn bench_cubic_spline(c: &mut Criterion) {
    for data in SplineData::ALL {
        let mut group = interpolation_group(c, format!("interpolate/cubic-spline/{}", data.name()));
        for n in SPLINE_SIZES {
            let (knots, pts) = data.closed(n);
            group.throughput(Throughput::Elements(n as u64));
            for (name, end) in [
                ("natural", EndCondition::Natural),
                ("periodic", EndCondition::Periodic),
            ] {
                group.bench_function(BenchmarkId::new(format!("{name}-tangents"), n), |b| {
                    b.iter(|| cubic_spline_tangents(black_box(&knots), &pts, &end).unwrap())
                });
                group.bench_function(BenchmarkId::new(name, n), |b| {
                    b.iter(|| cubic_spline(black_box(&knots), &pts, &end).unwrap())
                });
            }
            let (x, y) = to_ndarray(&knots, &pts);
            for (name, periodic) in [
                ("ndarray-interp-natural", false),
                ("ndarray-interp-periodic", true),
            ] {
                group.bench_function(BenchmarkId::new(name, n), |b| {
                    b.iter(|| {
                        Interp1DBuilder::new(black_box(y.view()))
                            .x(x.view())
                            .strategy(ndarray_spline(periodic))
                            .build()
                            .unwrap()
                    })
                });
            }
        }
        group.finish();
    }
}

fn bench_spline_eval(c: &mut Criterion) {
    for data in SplineData::ALL {
        let mut group = interpolation_group(c, format!("interpolate/spline-eval/{}", data.name()));
        group.throughput(Throughput::Elements(SPLINE_PARAMETERS as u64));
        for n in SPLINE_SIZES {
            let (knots, pts) = data.closed(n);
            let ts = parameters(SPLINE_PARAMETERS, knots[0], knots[n - 1]);
            let spline = cubic_spline(&knots, &pts, &EndCondition::Natural).unwrap();
            group.bench_function(BenchmarkId::new("natural-eval", n), |b| {
                b.iter(|| coordinate_sum(black_box(&ts), |t| spline.eval(t).unwrap().0))
            });
            group.bench_function(BenchmarkId::new("natural-derivative", n), |b| {
                b.iter(|| coordinate_sum(black_box(&ts), |t| spline.derivative_at(t, 1).unwrap().0))
            });
            let (x, y) = to_ndarray(&knots, &pts);
            let theirs = Interp1DBuilder::new(y.view())
                .x(x.view())
                .strategy(ndarray_spline(false))
                .build()
                .unwrap();
            let query = Array1::from(ts.clone());
            let mut out = Array2::<f64>::zeros((SPLINE_PARAMETERS, 2));
            group.bench_function(BenchmarkId::new("ndarray-interp-natural-eval", n), |b| {
                b.iter(|| {
                    theirs
                        .interp_array_into(black_box(&query), out.view_mut())
                        .unwrap()
                })
            });
        }
        group.finish();
    }
}

fn bench_hermite(c: &mut Criterion) {
    for data in SplineData::ALL {
        let mut build = interpolation_group(c, format!("interpolate/hermite/{}", data.name()));
        for n in SPLINE_SIZES {
            let (knots, pts) = data.closed(n);
            let tangents = catmull_rom_tangents(&knots, &pts);
            build.throughput(Throughput::Elements(n as u64));
            build.bench_function(BenchmarkId::new("estimate-tangents", n), |b| {
                b.iter(|| estimate_tangents(black_box(&knots), &pts).unwrap())
            });
            build.bench_function(BenchmarkId::new("hermite", n), |b| {
                b.iter(|| hermite(black_box(&knots), &pts, &tangents).unwrap())
            });
            let keys = splines_keys(&knots, &pts);
            build.bench_function(BenchmarkId::new("splines-from-vec", n), |b| {
                b.iter_batched(
                    || keys.clone(),
                    splines::Spline::from_vec,
                    BatchSize::LargeInput,
                )
            });
        }
        build.finish();
        let mut eval = interpolation_group(c, format!("interpolate/hermite-eval/{}", data.name()));
        eval.throughput(Throughput::Elements(SPLINE_PARAMETERS as u64));
        for n in SPLINE_SIZES {
            let (knots, pts) = data.closed(n);
            let tangents = catmull_rom_tangents(&knots, &pts);
            let ours = hermite(&knots, &pts, &tangents).unwrap();
            let theirs = splines::Spline::from_vec(splines_keys(&knots, &pts));
            // Catmull–Rom needs a key on either side: both are sampled on [u_1, u_{n−2}],
            // where the two curves are the same.
            let ts = parameters(SPLINE_PARAMETERS, knots[1], knots[n - 2]);
            for t in ts.iter().step_by(997) {
                let (q, r) = (ours.eval(t).unwrap(), theirs.sample(*t).unwrap());
                let scale = 1.0 + q[0].abs().max(q[1].abs());
                assert!((q[0] - r.x).abs().max((q[1] - r.y).abs()) <= 1e-9 * scale);
            }
            eval.bench_function(BenchmarkId::new("hermite-eval", n), |b| {
                b.iter(|| coordinate_sum(black_box(&ts), |t| ours.eval(t).unwrap().0))
            });
            eval.bench_function(BenchmarkId::new("splines-catmull-rom", n), |b| {
                b.iter(|| {
                    coordinate_sum(black_box(&ts), |&t| {
                        let q = theirs.sample(t).unwrap();
                        [q.x, q.y]
                    })
                })
            });
        }
        eval.finish();
    }
}

/// The points as Catmull–Rom keys of the `splines` crate, in glam's `DVec2`.
fn splines_keys(knots: &[f64], pts: &[P]) -> Vec<splines::Key<f64, glam::DVec2>> {
    knots
        .iter()
        .zip(pts)
        .map(|(&u, p)| {
            splines::Key::new(
                u,
                glam::DVec2::new(p[0], p[1]),
                splines::Interpolation::CatmullRom,
            )
        })
        .collect()
}

/// The nodes of the polynomial groups.
#[derive(Clone, Copy)]
enum Nodes {
    /// `i/(n − 1)` in [0, 1]: the classic ill-conditioned case (Runge).
    Equispaced,
    /// Chebyshev points of the second kind `(1 − cos(iπ/(n − 1)))/2` in [0, 1].
    Chebyshev,
    /// The degenerate case: n/2 equispaced nodes, each with a partner one ulp above it.
    UlpPairs,
}

impl Nodes {
    const ALL: [Nodes; 3] = [Nodes::Equispaced, Nodes::Chebyshev, Nodes::UlpPairs];

    fn name(self) -> &'static str {
        match self {
            Nodes::Equispaced => "equispaced",
            Nodes::Chebyshev => "chebyshev",
            Nodes::UlpPairs => "ulp-pairs",
        }
    }

    fn nodes(self, n: usize) -> Vec<f64> {
        let last = (n - 1) as f64;
        match self {
            Nodes::Equispaced => (0..n).map(|i| i as f64 / last).collect(),
            Nodes::Chebyshev => (0..n)
                .map(|i| (1.0 - (i as f64 * std::f64::consts::PI / last).cos()) / 2.0)
                .collect(),
            Nodes::UlpPairs => {
                let half = (n / 2 - 1) as f64;
                (0..n / 2)
                    .flat_map(|i| {
                        let u = 0.25 + i as f64 / half;
                        [u, f64::from_bits(u.to_bits() + 1)]
                    })
                    .collect()
            }
        }
    }
}

const POLYNOMIAL_SIZES: [usize; 4] = [4, 16, 64, 256];

/// The n points the polynomial groups interpolate (seeded, uniform in the unit square).
fn polynomial_points(n: usize) -> Vec<P> {
    points(PointKind::UniformSquare, n, INTERPOLATION_SEED)
        .expect("generator")
        .into_iter()
        .map(P::from)
        .collect()
}

fn bench_polynomial(c: &mut Criterion) {
    for nodes_kind in Nodes::ALL {
        let mut build = interpolation_group(
            c,
            format!("interpolate/polynomial-build/{}", nodes_kind.name()),
        );
        for n in POLYNOMIAL_SIZES {
            let nodes = nodes_kind.nodes(n);
            let pts = polynomial_points(n);
            build.throughput(Throughput::Elements(n as u64));
            build.bench_function(BenchmarkId::new("lagrange", n), |b| {
                b.iter(|| lagrange(black_box(&nodes), &pts).unwrap())
            });
            build.bench_function(BenchmarkId::new("newton", n), |b| {
                b.iter(|| newton(black_box(&nodes), &pts).unwrap())
            });
            // On the ulp pairs the elimination meets an exactly zero pivot and reports the
            // matrix singular, as documented: no Vandermonde ids there.
            if vandermonde(&nodes, &pts).is_ok() {
                build.bench_function(BenchmarkId::new("vandermonde", n), |b| {
                    b.iter(|| vandermonde(black_box(&nodes), &pts).unwrap())
                });
            }
        }
        build.finish();
        let mut eval = interpolation_group(
            c,
            format!("interpolate/polynomial-eval/{}", nodes_kind.name()),
        );
        eval.throughput(Throughput::Elements(POLYNOMIAL_PARAMETERS as u64));
        for n in POLYNOMIAL_SIZES {
            let nodes = nodes_kind.nodes(n);
            let pts = polynomial_points(n);
            let ts = parameters(POLYNOMIAL_PARAMETERS, nodes[0], nodes[n - 1]);
            let l = lagrange(&nodes, &pts).unwrap();
            let nf = newton(&nodes, &pts).unwrap();
            let v = vandermonde(&nodes, &pts);
            eval.bench_function(BenchmarkId::new("lagrange", n), |b| {
                b.iter(|| coordinate_sum(black_box(&ts), |t| l.eval(t).unwrap().0))
            });
            eval.bench_function(BenchmarkId::new("lagrange-aitken", n), |b| {
                b.iter(|| coordinate_sum(black_box(&ts), |t| l.aitken(t).unwrap().0))
            });
            eval.bench_function(BenchmarkId::new("newton", n), |b| {
                b.iter(|| coordinate_sum(black_box(&ts), |t| nf.eval(t).unwrap().0))
            });
            if let Ok(v) = v {
                eval.bench_function(BenchmarkId::new("vandermonde", n), |b| {
                    b.iter(|| coordinate_sum(black_box(&ts), |t| v.eval(t).unwrap().0))
                });
            }
        }
        eval.finish();
    }
}

criterion_group!(
    benches,
    bench_cubic,
    bench_degree,
    bench_cubic_spline,
    bench_spline_eval,
    bench_hermite,
    bench_polynomial
);
criterion_main!(benches);
