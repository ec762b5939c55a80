//! Benchmarks of `compgeo::graph` with petgraph 0.8 in the same groups: BFS and DFS against
//! `Bfs`/`Dfs` on its `UnGraph`, DSatur and the colouring searches (with their default
//! budget, and with a fixed one in `colour-search`) against `dsatur_coloring`, and the spanning trees
//! against `min_spanning_tree` (Kruskal) and `min_spanning_tree_prim`.
//!
//! Inputs are seeded G(n, m) graphs with m = 10n (and uniform weights in [0, 1) for the
//! trees), plus grid graphs in the search group. Graphs are built once per size, outside the
//! timing, in both libraries' own types. The default sizes keep a full run to a few minutes;
//! set `COMPGEO_BENCH_BIG=1` to add n = 10⁶, m = 10⁷ (several GB of memory, minutes per
//! group). Run one group with e.g. `cargo bench --bench graph -- search`.
//!
//! Measured once on the development machine (2 cores shared with other builds; criterion
//! medians, 10 samples), G(n = 10⁶, m = 10⁷), petgraph 0.8.3:
//!
//! | group | compgeo | petgraph | ratio |
//! |---|---|---|---|
//! | BFS | 0.30 s | 3.43 s (`Bfs`) | 11× |
//! | DFS | 0.55 s | 3.39 s (`Dfs`) | 6.1× |
//! | DSatur | 6.4 s | 27.2 s (`dsatur_coloring`) | 4.3× |
//! | Kruskal | 0.93 s | 5.02 s (`min_spanning_tree`) | 5.4× |
//! | Prim | 5.8 s | 12.4 s (`min_spanning_tree_prim`) | 2.2× |
//! | Borůvka | 1.8 s | | |
//!
//! DSatur followed by the tabu search (`dsatur-tabu`), measured later on the same machine
//! (criterion medians; the 10⁶ row one timed run of each): 1.62 ms against petgraph's
//! 2.10 ms at n = 2^10 (0.77), 11.9 vs 27.5 ms at 2^13 (0.43), 137 vs 666 ms at 2^16 (0.21),
//! 0.94 vs 4.43 s at 2^18 (0.21), 7.8 vs 22.4 s at 10⁶ (0.35). All three colourings use 8
//! colours on these graphs.
//!
//! The `colour-search` group gives both searches a fixed budget of 10⁶ steps beside one
//! run of petgraph's `dsatur_coloring` (criterion medians, same machine, shared): at
//! n = 2^10 (m = 10n) 5.7 ms for `dsatur-tabu` and 5.3 ms for `hea` against petgraph's 3.7 ms;
//! at 2^13 19.5 and 16.1 ms against 61 ms. A step (one move evaluated or one neighbour
//! updated) costs a few nanoseconds; DSatur itself is most of the time at 2^13.
//!
//! On the 10⁶-vertex grid (m ≈ 2·10⁶, cache-friendly) BFS is 1.35× faster (41 vs 56 ms)
//! and DFS on par (15 vs 17 ms): petgraph's linked adjacency costs most on random graphs.

use compgeo::gen::{graph, with_random_weights, GraphKind};
use compgeo::graph::{
    bfs, colour_budget, dfs, dsatur, spanning_forest, Budget, ColouringAlgorithm, EdgeList, Graph,
    MstAlgorithm, WeightedGraph, SEARCH_SEED,
};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use petgraph::graph::{NodeIndex, UnGraph};
use petgraph::visit::{Bfs, Dfs};
use std::hint::black_box;
use std::time::Duration;

const SEED: u64 = 0x5EED_0004;
const DENSITY: usize = 10;

/// The vertex counts: log-spaced, and the acceptance size when asked for.
fn sizes() -> Vec<usize> {
    let mut s = vec![1 << 10, 1 << 13, 1 << 16, 1 << 18];
    if std::env::var_os("COMPGEO_BENCH_BIG").is_some() {
        s.push(1_000_000);
    }
    s
}

fn gnm(n: usize) -> EdgeList {
    graph(GraphKind::Gnm, n, DENSITY * n, SEED ^ n as u64).unwrap()
}

fn petgraph_of(list: &EdgeList) -> UnGraph<(), f64> {
    let mut g = UnGraph::with_capacity(list.vertices, list.edges.len());
    for _ in 0..list.vertices {
        g.add_node(());
    }
    let weights = list.weights.as_deref();
    for (e, &[u, v]) in list.edges.iter().enumerate() {
        let w = weights.map_or(1.0, |w| w[e]);
        g.add_edge(NodeIndex::new(u), NodeIndex::new(v), w);
    }
    g
}

fn search(c: &mut Criterion) {
    for (kind, label) in [
        (GraphKind::Gnm, "search-gnm"),
        (GraphKind::Grid, "search-grid"),
    ] {
        let mut group = c.benchmark_group(label);
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(500));
        for n in sizes() {
            let list = match kind {
                GraphKind::Gnm => gnm(n),
                _ => graph(kind, n, 0, SEED).unwrap(),
            };
            let ours = Graph::from_edge_list(&list).unwrap();
            let theirs = petgraph_of(&list);
            group.throughput(Throughput::Elements((n + list.edges.len()) as u64));
            group.bench_function(BenchmarkId::new("bfs", n), |b| {
                b.iter(|| bfs(black_box(&ours), 0).unwrap().order.len())
            });
            group.bench_function(BenchmarkId::new("petgraph-bfs", n), |b| {
                b.iter(|| {
                    let mut walk = Bfs::new(black_box(&theirs), NodeIndex::new(0));
                    let mut seen = 0usize;
                    while let Some(v) = walk.next(&theirs) {
                        seen += v.index() & 1;
                    }
                    seen
                })
            });
            group.bench_function(BenchmarkId::new("dfs", n), |b| {
                b.iter(|| dfs(black_box(&ours), 0).unwrap().order.len())
            });
            group.bench_function(BenchmarkId::new("petgraph-dfs", n), |b| {
                b.iter(|| {
                    let mut walk = Dfs::new(black_box(&theirs), NodeIndex::new(0));
                    let mut seen = 0usize;
                    while let Some(v) = walk.next(&theirs) {
                        seen += v.index() & 1;
                    }
                    seen
                })
            });
        }
        group.finish();
    }
}

fn colour(c: &mut Criterion) {
    let mut group = c.benchmark_group("colour");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500));
    for n in sizes() {
        let list = gnm(n);
        let ours = Graph::from_edge_list(&list).unwrap();
        let theirs = petgraph_of(&list);
        group.throughput(Throughput::Elements((n + list.edges.len()) as u64));
        group.bench_function(BenchmarkId::new("dsatur", n), |b| {
            b.iter(|| dsatur(black_box(&ours)).count)
        });
        group.bench_function(BenchmarkId::new("petgraph-dsatur", n), |b| {
            b.iter(|| petgraph::algo::dsatur_coloring(black_box(&theirs)).1)
        });
        for a in [
            ColouringAlgorithm::DsaturTabu,
            ColouringAlgorithm::Hea,
            ColouringAlgorithm::Greedy,
            ColouringAlgorithm::LargestFirst,
            ColouringAlgorithm::SmallestLast,
        ] {
            group.bench_function(BenchmarkId::new(a.name(), n), |b| {
                b.iter(|| compgeo::graph::colour(black_box(&ours), a).count)
            });
        }
    }
    group.finish();
}

fn mst(c: &mut Criterion) {
    let mut group = c.benchmark_group("mst");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500));
    for n in sizes() {
        let list = with_random_weights(gnm(n), SEED);
        let ours = WeightedGraph::from_edge_list(&list).unwrap();
        let theirs = petgraph_of(&list);
        group.throughput(Throughput::Elements(list.edges.len() as u64));
        for a in MstAlgorithm::ALL {
            group.bench_function(BenchmarkId::new(a.name(), n), |b| {
                b.iter(|| spanning_forest(black_box(&ours), a).weight)
            });
        }
        group.bench_function(BenchmarkId::new("petgraph-kruskal", n), |b| {
            b.iter(|| petgraph::algo::min_spanning_tree(black_box(&theirs)).count())
        });
        group.bench_function(BenchmarkId::new("petgraph-prim", n), |b| {
            b.iter(|| petgraph::algo::min_spanning_tree_prim(black_box(&theirs)).count())
        });
    }
    group.finish();
}

/// The searches with a fixed step budget beside petgraph's `dsatur_coloring` (the speed
/// baseline): G(n, 10n) at n = 2^10 and 2^13, 10⁶ steps each, so the search's cost per
/// step shows against one DSatur run. `cargo bench --bench graph -- colour-search`.
fn colour_search(c: &mut Criterion) {
    let mut group = c.benchmark_group("colour-search");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500));
    const STEPS: u64 = 1_000_000;
    for n in [1 << 10, 1 << 13] {
        let list = gnm(n);
        let ours = Graph::from_edge_list(&list).unwrap();
        let theirs = petgraph_of(&list);
        group.throughput(Throughput::Elements((n + list.edges.len()) as u64));
        group.bench_function(BenchmarkId::new("petgraph-dsatur", n), |b| {
            b.iter(|| petgraph::algo::dsatur_coloring(black_box(&theirs)).1)
        });
        for a in [ColouringAlgorithm::DsaturTabu, ColouringAlgorithm::Hea] {
            group.bench_function(BenchmarkId::new(a.name(), n), |b| {
                b.iter(|| {
                    colour_budget(black_box(&ours), a, Budget::steps(STEPS), SEARCH_SEED)
                        .unwrap()
                        .0
                        .count
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, search, colour, colour_search, mst);
criterion_main!(benches);
