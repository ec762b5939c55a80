//! Benchmarks of `compgeo::proximity` with the peers in the same groups, over log-spaced
//! sizes: uniform points in a square, clustered points, and an integer grid (the degenerate
//! case: every distance is tied with many others and every empty circle is a cocircular
//! quadruple).
//!
//! Every compgeo function is called as `*_with(&PointSet, &mut NoCount)` on a point set
//! validated once, outside the timed loop; every peer's input is converted outside it too
//! (the conversions a user would make once), and inputs a peer consumes are cloned in
//! criterion's untimed setup (`iter_batched`). Triangulations that answer with input indices
//! are built with spade's `bulk_load_stable` (the input order kept; 5–10% slower than
//! `bulk_load` by spade's own account).
//!
//! | group | compgeo | peers |
//! |---|---|---|
//! | `closest-pair/{kind}` | `delaunay`, `divide-and-conquer` | `spade-shortest-edge`: spade's triangulation, then its shortest edge; `rstar-nearest`: an R-tree, then every point's nearest other point |
//! | `all-nearest/{kind}` | `delaunay` | `spade-delaunay-edges`: spade's triangulation, then one pass over its edges; `rstar`: an R-tree, then a nearest-neighbour query per point |
//! | `nearest-build/{kind}` | `delaunay-walk` (`NearestSearch::new`) | `spade-last-used`, `spade-hierarchy`: spade's bulk load with its default hint generator and with `HierarchyHintGenerator`; `rstar`: `RTree::bulk_load` |
//! | `nearest-query/{kind}` | `delaunay-walk` (`NearestSearch::nearest`) | `nearest_neighbor` of the same three structures |
//! | `emst/{kind}` | `delaunay-kruskal` | `spade+petgraph-kruskal`: spade's triangulation, its edges weighted by squared length into a petgraph `UnGraph`, then `min_spanning_tree` |
//! | `empty-circle/{kind}` | `voronoi` | none |
//!
//! No crate we found computes a closest pair of a point set or a Euclidean minimum spanning
//! tree (on crates.io there are graph MSTs, k-d trees and R-trees, and the closest-pair and
//! EMST code of large numeric toolkits whose dependencies are out of proportion here), so
//! those peers are pipelines built from maintained crates the way a user would: spade
//! (Delaunay), rstar (the R-tree geo uses) and petgraph (Kruskal). They compare rounded
//! `f64` lengths where compgeo compares exactly. The largest empty circle has no peer at all.
//!
//! Throughput: n points in every group except `nearest-query`, whose throughput is its batch
//! of 10⁴ seeded queries, uniform in the bounding box of the points, the same batch for every
//! structure; ids are `BenchmarkId::new(name, n)` throughout. The default sizes keep a run to
//! minutes: 10³ to 10⁵ uniform points and 10⁴ to 10⁵ of the others; set
//! `COMPGEO_BENCH_BIG=1` to add n = 10⁶.
//!
//! Run one group with e.g. `cargo bench --bench proximity -- closest-pair/uniform-square`.
//!
//! One run of the whole bench on the 2-core machine (otherwise idle), 2026-12-01, criterion
//! medians; the last column is ours over the fastest peer (below 1: ours is faster):
//!
//! | group | n | ours | spade | rstar | ours / fastest |
//! |---|---|---|---|---|---|
//! | closest-pair/uniform-square (delaunay, divide-and-conquer) | 10⁵ | 68.5 ms, 75.0 ms | 132 ms | 175 ms | 0.52 |
//! | closest-pair/clustered | 10⁵ | 58.2 ms, 61.9 ms | 155 ms | 174 ms | 0.38 |
//! | closest-pair/grid | 10⁵ | 130 ms, 250 ms | 164 ms | 168 ms | 0.79 |
//! | all-nearest/uniform-square | 10⁵ | 82.8 ms | 190 ms | 182 ms | 0.45 |
//! | all-nearest/clustered | 10⁵ | 90.5 ms | 128 ms | 192 ms | 0.71 |
//! | all-nearest/grid | 10⁵ | 146 ms | 197 ms | 203 ms | 0.74 |
//! | nearest-build/uniform-square (last-used, hierarchy) | 10⁵ | 117 ms | 198 ms, 168 ms | 23.7 ms | 4.9 |
//! | nearest-build/grid | 10⁵ | 128 ms | 199 ms, 192 ms | 30.1 ms | 4.3 |
//! | nearest-query/uniform-square, 10⁴ queries | 10⁵ | 408 ms | 1.20 s, 44.7 ms | 17.6 ms | 23 |
//! | nearest-query/clustered | 10⁵ | 103 ms | 560 ms, 18.5 ms | 19.9 ms | 5.6 |
//! | nearest-query/grid | 10⁵ | 674 ms | 852 ms, 41.7 ms | 20.7 ms | 33 |
//! | emst/uniform-square (spade + petgraph) | 10⁵ | 254 ms | 307 ms | | 0.83 |
//! | emst/clustered | 10⁵ | 202 ms | 266 ms | | 0.76 |
//! | emst/grid | 10⁵ | 431 ms | 233 ms | | 1.85 |
//! | empty-circle/uniform-square, clustered, grid | 10⁵ | 114 ms, 86.9 ms, 155 ms | | | no peer |
//!
//! At 10³ and 10⁴ the ratios are similar (closest pair 0.44 to 0.64 on uniform points, the
//! Shamos divide and conquer the fastest of all there: 295 µs and 5.23 ms). Where we lost:
//! the `nearest-query` rows above were measured when a nearest query walked the Delaunay
//! graph from a hull vertex, O(√n) steps on uniform points; it now starts at a grid cell's
//! entry vertex, O(1) expected steps, measured against spade and kiddo at 10⁶ in
//! `benches/nearest.rs`. An R-tree is also cheaper to build than any triangulation. On the grid the EMST's Kruskal sorts every
//! Delaunay edge by its exact squared length, and the ties of the grid make that sort and
//! the union–find work harder than petgraph's on rounded weights.

use compgeo::count::NoCount;
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{BoundingBox, Point2, PointSet};
use compgeo::proximity::{
    all_nearest_neighbours_with, closest_pair_with, euclidean_mst_with, largest_empty_circle_with,
    ClosestPairAlgorithm, NearestSearch,
};
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use petgraph::graph::{NodeIndex, UnGraph};
use rstar::primitives::GeomWithData;
use rstar::RTree;
use spade::{
    DelaunayTriangulation, HierarchyHintGenerator, HintGenerator, LastUsedVertexHintGenerator,
    Triangulation as _,
};
use std::hint::black_box;
use std::time::Duration;

const SEED: u64 = 0x5EED_0008;
const QUERY_SEED: u64 = 0x5EED_0009;
const QUERIES: usize = 10_000;

/// Spade's Delaunay triangulation with the hint generator `L`.
type Spade<L> = DelaunayTriangulation<spade::Point2<f64>, (), (), (), L>;

/// A point in rstar's R-tree, carrying its input index.
type Site = GeomWithData<[f64; 2], usize>;

/// The inputs and their sizes: log-spaced, and n = 10⁶ when asked for.
fn inputs() -> Vec<(PointKind, Vec<usize>)> {
    let big = std::env::var_os("COMPGEO_BENCH_BIG").is_some();
    let with_big = |mut s: Vec<usize>| {
        if big {
            s.push(1_000_000);
        }
        s
    };
    vec![
        (
            PointKind::UniformSquare,
            with_big(vec![1_000, 10_000, 100_000]),
        ),
        (PointKind::Clustered, with_big(vec![10_000, 100_000])),
        (PointKind::Grid, with_big(vec![10_000, 100_000])),
    ]
}

fn configure(group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
}

fn spade_points(pts: &[Point2]) -> Vec<spade::Point2<f64>> {
    pts.iter().map(|p| spade::Point2::new(p.x, p.y)).collect()
}

fn rstar_sites(pts: &[Point2]) -> Vec<Site> {
    pts.iter()
        .enumerate()
        .map(|(i, p)| GeomWithData::new([p.x, p.y], i))
        .collect()
}

/// Spade's triangulation of `pts`, vertex `i` being input point `i` (no duplicates here).
fn spade_stable<L: HintGenerator<f64>>(pts: Vec<spade::Point2<f64>>) -> Spade<L> {
    Spade::<L>::bulk_load_stable(pts).expect("finite points")
}

fn squared_length(a: spade::Point2<f64>, b: spade::Point2<f64>) -> f64 {
    (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)
}

/// The shortest edge of spade's triangulation: the closest pair.
fn spade_closest_pair(pts: Vec<spade::Point2<f64>>) -> (f64, [usize; 2]) {
    let t = spade_stable::<LastUsedVertexHintGenerator>(pts);
    t.undirected_edges()
        .map(|e| {
            let [a, b] = e.vertices();
            (
                squared_length(a.position(), b.position()),
                [a.fix().index(), b.fix().index()],
            )
        })
        .min_by(|x, y| x.0.total_cmp(&y.0))
        .expect("two points")
}

/// Every point's nearest other point from spade's Delaunay edges.
fn spade_all_nearest(pts: Vec<spade::Point2<f64>>) -> Vec<usize> {
    let n = pts.len();
    let t = spade_stable::<LastUsedVertexHintGenerator>(pts);
    let mut best = vec![(f64::INFINITY, usize::MAX); n];
    for e in t.undirected_edges() {
        let [a, b] = e.vertices();
        let d = squared_length(a.position(), b.position());
        let (a, b) = (a.fix().index(), b.fix().index());
        if d < best[a].0 {
            best[a] = (d, b);
        }
        if d < best[b].0 {
            best[b] = (d, a);
        }
    }
    best.into_iter().map(|(_, i)| i).collect()
}

/// Every point's nearest other point from rstar's R-tree, with its squared distance.
fn rstar_all_nearest(sites: Vec<Site>) -> Vec<(f64, usize)> {
    let tree = RTree::bulk_load(sites);
    let mut out = vec![(f64::INFINITY, usize::MAX); tree.size()];
    for s in tree.iter() {
        // The first neighbour is the point itself (or a copy of it).
        let (other, d) = tree
            .nearest_neighbor_iter_with_distance_2(s.geom())
            .find(|(o, _)| o.data != s.data)
            .expect("two points");
        out[s.data] = (d, other.data);
    }
    out
}

/// The Euclidean minimum spanning tree from spade's triangulation and petgraph's Kruskal.
fn spade_petgraph_emst(pts: Vec<spade::Point2<f64>>) -> usize {
    let n = pts.len();
    let t = spade_stable::<LastUsedVertexHintGenerator>(pts);
    let mut g = UnGraph::<(), f64>::with_capacity(n, t.num_undirected_edges());
    for _ in 0..n {
        g.add_node(());
    }
    for e in t.undirected_edges() {
        let [a, b] = e.vertices();
        g.add_edge(
            NodeIndex::new(a.fix().index()),
            NodeIndex::new(b.fix().index()),
            squared_length(a.position(), b.position()),
        );
    }
    petgraph::algo::min_spanning_tree(&g).count()
}

/// The peers' closest pair is as long as compgeo's, up to the rounding of their lengths:
/// the pipelines answer the same question.
fn check_closest_pair(set: &PointSet<'_>, sp: Vec<spade::Point2<f64>>, sites: Vec<Site>) {
    let ours = closest_pair_with(set, ClosestPairAlgorithm::Delaunay, &mut NoCount)
        .expect("two points")
        .distance
        .to_f64()
        .expect("uniform points are close");
    let spade = spade_closest_pair(sp).0.sqrt();
    let rstar = rstar_all_nearest(sites)
        .into_iter()
        .map(|(d, _)| d)
        .fold(f64::INFINITY, f64::min)
        .sqrt();
    for theirs in [spade, rstar] {
        assert!(
            (theirs - ours).abs() <= 1e-12 * ours,
            "{theirs} against {ours}"
        );
    }
}

/// `QUERIES` seeded query points, uniform in the bounding box of `set`.
fn queries(set: &PointSet<'_>) -> Vec<Point2> {
    let BoundingBox { min, max } = set.bounding_box().expect("non-empty");
    points(PointKind::UniformSquare, QUERIES, QUERY_SEED)
        .expect("generator")
        .into_iter()
        .map(|q| Point2::new(min.x + q.x * (max.x - min.x), min.y + q.y * (max.y - min.y)))
        .collect()
}

fn closest_pairs(c: &mut Criterion) {
    for (kind, sizes) in inputs() {
        let mut group = c.benchmark_group(format!("closest-pair/{kind}"));
        configure(&mut group);
        for n in sizes {
            let pts = points(kind, n, SEED).expect("generator");
            let set = PointSet::new(&pts).expect("finite points");
            group.throughput(Throughput::Elements(n as u64));
            for algorithm in ClosestPairAlgorithm::ALL {
                group.bench_with_input(BenchmarkId::new(algorithm.name(), n), &set, |b, set| {
                    b.iter(|| {
                        closest_pair_with(black_box(set), algorithm, &mut NoCount)
                            .expect("two points")
                    })
                });
            }
            let sp = spade_points(&pts);
            let sites = rstar_sites(&pts);
            check_closest_pair(&set, sp.clone(), sites.clone());
            group.bench_with_input(BenchmarkId::new("spade-shortest-edge", n), &sp, |b, sp| {
                b.iter_batched(|| sp.clone(), spade_closest_pair, BatchSize::LargeInput)
            });
            group.bench_with_input(BenchmarkId::new("rstar-nearest", n), &sites, |b, s| {
                b.iter_batched(
                    || s.clone(),
                    |s| {
                        rstar_all_nearest(s)
                            .into_iter()
                            .enumerate()
                            .min_by(|x, y| x.1 .0.total_cmp(&y.1 .0))
                            .map(|(i, (_, j))| [i, j])
                    },
                    BatchSize::LargeInput,
                )
            });
        }
        group.finish();
    }
}

fn all_nearest(c: &mut Criterion) {
    for (kind, sizes) in inputs() {
        let mut group = c.benchmark_group(format!("all-nearest/{kind}"));
        configure(&mut group);
        for n in sizes {
            let pts = points(kind, n, SEED).expect("generator");
            let set = PointSet::new(&pts).expect("finite points");
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::new("delaunay", n), &set, |b, set| {
                b.iter(|| all_nearest_neighbours_with(black_box(set), &mut NoCount).unwrap())
            });
            let sp = spade_points(&pts);
            group.bench_with_input(BenchmarkId::new("spade-delaunay-edges", n), &sp, |b, sp| {
                b.iter_batched(|| sp.clone(), spade_all_nearest, BatchSize::LargeInput)
            });
            let sites = rstar_sites(&pts);
            group.bench_with_input(BenchmarkId::new("rstar", n), &sites, |b, s| {
                b.iter_batched(|| s.clone(), rstar_all_nearest, BatchSize::LargeInput)
            });
        }
        group.finish();
    }
}

fn nearest_build(c: &mut Criterion) {
    for (kind, sizes) in inputs() {
        let mut group = c.benchmark_group(format!("nearest-build/{kind}"));
        configure(&mut group);
        for n in sizes {
            let pts = points(kind, n, SEED).expect("generator");
            let set = PointSet::new(&pts).expect("finite points");
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::new("delaunay-walk", n), &set, |b, set| {
                b.iter(|| NearestSearch::new(black_box(set)).expect("points"))
            });
            let sp = spade_points(&pts);
            group.bench_with_input(BenchmarkId::new("spade-last-used", n), &sp, |b, sp| {
                b.iter_batched(
                    || sp.clone(),
                    spade_stable::<LastUsedVertexHintGenerator>,
                    BatchSize::LargeInput,
                )
            });
            group.bench_with_input(BenchmarkId::new("spade-hierarchy", n), &sp, |b, sp| {
                b.iter_batched(
                    || sp.clone(),
                    spade_stable::<HierarchyHintGenerator<f64>>,
                    BatchSize::LargeInput,
                )
            });
            let sites = rstar_sites(&pts);
            group.bench_with_input(BenchmarkId::new("rstar", n), &sites, |b, s| {
                b.iter_batched(|| s.clone(), RTree::bulk_load, BatchSize::LargeInput)
            });
        }
        group.finish();
    }
}

fn nearest_queries(c: &mut Criterion) {
    for (kind, sizes) in inputs() {
        let mut group = c.benchmark_group(format!("nearest-query/{kind}"));
        configure(&mut group);
        group.throughput(Throughput::Elements(QUERIES as u64));
        for n in sizes {
            let pts = points(kind, n, SEED).expect("generator");
            let set = PointSet::new(&pts).expect("finite points");
            let qs = queries(&set);
            let search = NearestSearch::new(&set).expect("points");
            group.bench_with_input(BenchmarkId::new("delaunay-walk", n), &qs, |b, qs| {
                b.iter(|| {
                    let mut acc = 0;
                    for &q in black_box(qs) {
                        acc ^= search.nearest(q).expect("finite query");
                    }
                    acc
                })
            });
            let sq: Vec<spade::Point2<f64>> = spade_points(&qs);
            let last_used = spade_stable::<LastUsedVertexHintGenerator>(spade_points(&pts));
            group.bench_with_input(BenchmarkId::new("spade-last-used", n), &sq, |b, sq| {
                b.iter(|| {
                    let mut acc = 0;
                    for &q in black_box(sq) {
                        acc ^= last_used.nearest_neighbor(q).expect("points").fix().index();
                    }
                    acc
                })
            });
            let hierarchy = spade_stable::<HierarchyHintGenerator<f64>>(spade_points(&pts));
            group.bench_with_input(BenchmarkId::new("spade-hierarchy", n), &sq, |b, sq| {
                b.iter(|| {
                    let mut acc = 0;
                    for &q in black_box(sq) {
                        acc ^= hierarchy.nearest_neighbor(q).expect("points").fix().index();
                    }
                    acc
                })
            });
            let tree = RTree::bulk_load(rstar_sites(&pts));
            let rq: Vec<[f64; 2]> = qs.iter().map(|q| [q.x, q.y]).collect();
            group.bench_with_input(BenchmarkId::new("rstar", n), &rq, |b, rq| {
                b.iter(|| {
                    let mut acc = 0;
                    for q in black_box(rq) {
                        acc ^= tree.nearest_neighbor(q).expect("points").data;
                    }
                    acc
                })
            });
        }
        group.finish();
    }
}

fn spanning_trees(c: &mut Criterion) {
    for (kind, sizes) in inputs() {
        let mut group = c.benchmark_group(format!("emst/{kind}"));
        configure(&mut group);
        for n in sizes {
            let pts = points(kind, n, SEED).expect("generator");
            let set = PointSet::new(&pts).expect("finite points");
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::new("delaunay-kruskal", n), &set, |b, set| {
                b.iter(|| euclidean_mst_with(black_box(set), &mut NoCount).unwrap())
            });
            let sp = spade_points(&pts);
            group.bench_with_input(
                BenchmarkId::new("spade+petgraph-kruskal", n),
                &sp,
                |b, sp| b.iter_batched(|| sp.clone(), spade_petgraph_emst, BatchSize::LargeInput),
            );
        }
        group.finish();
    }
}

fn empty_circles(c: &mut Criterion) {
    for (kind, sizes) in inputs() {
        let mut group = c.benchmark_group(format!("empty-circle/{kind}"));
        configure(&mut group);
        for n in sizes {
            let pts = points(kind, n, SEED).expect("generator");
            let set = PointSet::new(&pts).expect("finite points");
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::new("voronoi", n), &set, |b, set| {
                b.iter(|| largest_empty_circle_with(black_box(set), &mut NoCount).unwrap())
            });
        }
        group.finish();
    }
}

criterion_group!(
    benches,
    closest_pairs,
    all_nearest,
    nearest_build,
    nearest_queries,
    spanning_trees,
    empty_circles
);
criterion_main!(benches);
