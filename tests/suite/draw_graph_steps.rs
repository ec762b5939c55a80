//! The graph step pages (`compgeo::draw::search_steps`, `colouring_steps`, `prim_steps`,
//! `kruskal_steps`): parsed as XML, one frame per trace frame with the trace's counts; every
//! frame maps back to the graph's vertices; the last frame is the plain function's result
//! (search tree, colouring, spanning forest), not the trace's; the partial states are checked
//! against the graph itself (a colouring prefix that is proper and the final one's, Kruskal's
//! forest acyclic in every frame, a rejected edge inside one tree); and `draw graph --steps`.

use crate::draw_steps::{frames_of, listed, ShownFrame};
use compgeo::count::Counts;
use compgeo::draw::{circle_layout, colouring_steps, kruskal_steps, prim_steps, search_steps};
use compgeo::gen::{graph as generate, with_random_weights, GraphKind};
use compgeo::geometry::Point2;
use compgeo::graph::{
    course_greedy_colouring, course_greedy_colouring_trace, course_greedy_colouring_with, kruskal,
    kruskal_trace, kruskal_with, prim, prim_trace, prim_with, search, search_trace, search_with,
    CourseColouringStep, Graph, KruskalStep, PrimStep, SearchAlgorithm, SearchStep, UnionFind,
    WeightedGraph,
};
use compgeo::trace::Frame;
use compgeo::Error;
use std::collections::BTreeSet;

/// Where a frame draws each vertex, computed exactly and rounded once; a drawn point is the
/// vertex whose place is within the drawing's rounding of it (exactly one must be).
struct Places(Vec<[f64; 2]>);

impl Places {
    fn of(s: &ShownFrame, positions: &[Point2]) -> Places {
        let frame = s.svg.frame();
        Places(positions.iter().map(|&p| frame.picture_of(p)).collect())
    }

    fn vertex(&self, at: [f64; 2]) -> usize {
        let hits: Vec<usize> = (0..self.0.len())
            .filter(|&v| {
                let p = self.0[v];
                (p[0] - at[0]).abs() <= 0.051 && (p[1] - at[1]).abs() <= 0.051
            })
            .collect();
        assert_eq!(hits.len(), 1, "{at:?} maps back to {hits:?}");
        hits[0]
    }
}

/// The edges of layer `class` as vertex pairs `[min, max]`, in drawing order (none if the
/// frame has no such layer).
fn pairs(s: &ShownFrame, class: &str, positions: &[Point2]) -> Vec<[usize; 2]> {
    if !s.svg.has_layer(class) {
        return Vec::new();
    }
    let places = Places::of(s, positions);
    s.svg
        .subpaths(class)
        .iter()
        .map(|d| {
            assert_eq!(d.points.len(), 2);
            let [a, b] = [0, 1].map(|i| places.vertex(d.points[i]));
            [a.min(b), a.max(b)]
        })
        .collect()
}

/// The vertices of the discs or rings of layer `class`, sorted (none if the frame has no
/// such layer).
fn vertices(s: &ShownFrame, class: &str, positions: &[Point2]) -> Vec<usize> {
    if !s.svg.has_layer(class) {
        return Vec::new();
    }
    let places = Places::of(s, positions);
    let mut v: Vec<usize> = s
        .svg
        .circles(class)
        .iter()
        .map(|c| places.vertex([c[0], c[1]]))
        .collect();
    v.sort_unstable();
    v
}

fn sorted_pairs(edges: impl IntoIterator<Item = [usize; 2]>) -> BTreeSet<[usize; 2]> {
    edges
        .into_iter()
        .map(|[a, b]| [a.min(b), a.max(b)])
        .collect()
}

/// What every graph page shares: one frame per trace frame, in order, the first shown, the
/// kinds and counts of the trace, every vertex drawn and every edge of the graph drawn grey.
fn check_page<S>(
    html: &str,
    trace: &[Frame<S>],
    kind: impl Fn(&S) -> &'static str,
    positions: &[Point2],
    edges: &BTreeSet<[usize; 2]>,
) -> Vec<ShownFrame> {
    let shown = frames_of(html);
    assert_eq!(shown.len(), trace.len(), "one frame per trace frame");
    for (i, (s, f)) in shown.iter().zip(trace).enumerate() {
        assert_eq!(s.step, i);
        assert_eq!(s.hidden, i > 0);
        assert_eq!(s.kind, kind(&f.step), "frame {i}");
        assert_eq!(s.counts, listed(&f.counts), "frame {i}'s counts");
        let drawn: BTreeSet<[usize; 2]> = pairs(s, "edges", positions).into_iter().collect();
        assert_eq!(&drawn, edges, "frame {i}: the graph's edges");
        // Each vertex is a dot or a disc of a colour class, once.
        let dots = if s.svg.has_layer("vertices") {
            s.svg.subpaths("vertices")
        } else {
            Vec::new()
        };
        let places = Places::of(s, positions);
        let mut every: Vec<usize> = dots.iter().map(|d| places.vertex(d.points[0])).collect();
        for k in 0..positions.len() {
            every.extend(vertices(s, &format!("colour-{k}"), positions));
        }
        every.sort_unstable();
        every.dedup();
        assert_eq!(
            every.len(),
            positions.len(),
            "frame {i}: every vertex drawn"
        );
    }
    shown
}

/// Small graphs with their layouts: several components, a single vertex, the Petersen graph,
/// a path given coordinates on a line's zigzag, a seeded sparse graph.
fn graphs() -> Vec<(Graph, Vec<Point2>)> {
    let mut out = Vec::new();
    for list in [
        generate(GraphKind::Petersen, 10, 0, 1).unwrap(),
        generate(GraphKind::Gnm, 14, 18, 2).unwrap(),
        generate(GraphKind::Queen, 4, 0, 1).unwrap(),
        generate(GraphKind::Cycle, 7, 0, 1).unwrap(),
    ] {
        let g = Graph::from_edge_list(&list).unwrap();
        let layout = circle_layout(g.vertex_count());
        out.push((g, layout));
    }
    // Two components, one of them a lone vertex.
    let g = Graph::from_edges(6, &[[0, 1], [1, 2], [2, 0], [3, 4]]).unwrap();
    out.push((g, circle_layout(6)));
    // A path at given coordinates.
    let g = Graph::from_edges(5, &[[0, 1], [1, 2], [2, 3], [3, 4]]).unwrap();
    let zigzag = (0..5)
        .map(|i| Point2::new(i as f64, (i % 2) as f64))
        .collect();
    out.push((g, zigzag));
    out.push((Graph::from_edges(1, &[]).unwrap(), circle_layout(1)));
    out
}

fn edges_of(g: &Graph) -> BTreeSet<[usize; 2]> {
    sorted_pairs(g.edges())
}

#[test]
fn search_pages_show_q_the_reached_vertices_and_end_with_the_search_tree() {
    for (g, positions) in graphs() {
        for (kind, list) in [
            (SearchAlgorithm::Bfs, "queue"),
            (SearchAlgorithm::Dfs, "stack"),
        ] {
            for start in [0, g.vertex_count() - 1] {
                let trace = search_trace(&g, start, kind).unwrap();
                let html = search_steps(&g, &positions, kind, &trace)
                    .unwrap()
                    .to_html();
                let step_kind = |s: &SearchStep| match s {
                    SearchStep::Add { .. } => "add",
                    SearchStep::Remove { .. } => "remove",
                    SearchStep::Done { .. } => "done",
                };
                let shown = check_page(&html, &trace, step_kind, &positions, &edges_of(&g));
                // The tree grows by one graph edge per vertex added after the start, and
                // the reached vertices are the ends of the tree with the start.
                let mut tree = BTreeSet::new();
                for (s, f) in shown.iter().zip(&trace) {
                    let drawn_tree: BTreeSet<[usize; 2]> =
                        pairs(s, "tree", &positions).into_iter().collect();
                    match &f.step {
                        SearchStep::Add {
                            vertex,
                            parent,
                            list: q,
                        } => {
                            if let Some(p) = parent {
                                assert!(g.has_edge(*p, *vertex));
                                tree.insert([*p.min(vertex), *p.max(vertex)]);
                                assert_eq!(
                                    pairs(s, "added", &positions),
                                    [[*p.min(vertex), *p.max(vertex)]]
                                );
                                assert_eq!(vertices(s, "current", &positions), [*p]);
                            }
                            let mut q = q.clone();
                            q.sort_unstable();
                            assert_eq!(vertices(s, list, &positions), q);
                        }
                        SearchStep::Remove { vertex, list: q } => {
                            // Every neighbour of a removed vertex is reached.
                            let reached = vertices(s, "reached", &positions);
                            for w in g.neighbours(*vertex) {
                                assert!(reached.binary_search(&w).is_ok());
                            }
                            assert_eq!(vertices(s, "current", &positions), [*vertex]);
                            let mut q = q.clone();
                            q.sort_unstable();
                            assert_eq!(vertices(s, list, &positions), q);
                        }
                        SearchStep::Done { .. } => {}
                    }
                    if !matches!(f.step, SearchStep::Done { .. }) {
                        assert_eq!(drawn_tree, tree, "frame {}", s.step);
                    }
                    let mut ends: Vec<usize> = tree.iter().flatten().copied().collect();
                    ends.push(start);
                    ends.sort_unstable();
                    ends.dedup();
                    assert_eq!(vertices(s, "reached", &positions), ends);
                }
                // The last frame: the plain search's tree, reached set and start, and the
                // counted run's counts.
                let plain = search(&g, start, kind).unwrap();
                let last = shown.last().unwrap();
                assert_eq!(last.kind, "done");
                let expected = sorted_pairs(
                    (0..g.vertex_count()).filter_map(|v| plain.parent[v].map(|p| [p, v])),
                );
                let drawn: BTreeSet<[usize; 2]> =
                    pairs(last, "tree", &positions).into_iter().collect();
                assert_eq!(drawn, expected);
                let mut order = plain.order.clone();
                order.sort_unstable();
                assert_eq!(vertices(last, "reached", &positions), order);
                assert_eq!(vertices(last, "start", &positions), [start]);
                let mut counts = Counts::default();
                search_with(&g, start, kind, &mut counts).unwrap();
                assert_eq!(last.counts, listed(&counts));
            }
        }
    }
}

#[test]
fn colouring_pages_colour_one_vertex_per_frame_and_end_with_the_colouring() {
    for (g, positions) in graphs() {
        let n = g.vertex_count();
        let forward: Vec<usize> = (0..n).collect();
        let backward: Vec<usize> = (0..n).rev().collect();
        for order in [forward, backward] {
            let trace = course_greedy_colouring_trace(&g, &order).unwrap();
            let html = colouring_steps(&g, &positions, &trace).unwrap().to_html();
            let kind = |s: &CourseColouringStep| match s {
                CourseColouringStep::Coloured { .. } => "colour",
                CourseColouringStep::Done { .. } => "done",
            };
            let shown = check_page(&html, &trace, kind, &positions, &edges_of(&g));
            assert_eq!(shown.len(), n + 1);
            let plain = course_greedy_colouring(&g, &order).unwrap();
            // The fills of a frame, per vertex.
            let fills = |s: &ShownFrame| -> Vec<Option<usize>> {
                let mut fill = vec![None; n];
                for k in 0..n {
                    for v in vertices(s, &format!("colour-{k}"), &positions) {
                        assert_eq!(fill[v], None, "vertex {v} filled twice");
                        fill[v] = Some(k);
                    }
                }
                fill
            };
            for (i, s) in shown.iter().enumerate().take(n) {
                // Frame i: the first i + 1 vertices of the order are coloured, each with
                // its colour in the plain colouring (greedy colours never change), and
                // no other vertex is.
                let fill = fills(s);
                for (j, &v) in order.iter().enumerate() {
                    let want = (j <= i).then_some(plain.colour[v]);
                    assert_eq!(fill[v], want, "frame {i}, vertex {v}");
                }
                let v = order[i];
                assert_eq!(vertices(s, "current", &positions), [v]);
                // The dashed lines go to exactly the earlier vertices adjacent to v.
                let ruled = sorted_pairs(pairs(s, "ruled-out", &positions));
                let earlier = sorted_pairs(
                    order[..i]
                        .iter()
                        .filter(|&&u| g.has_edge(u, v))
                        .map(|&u| [u, v]),
                );
                assert_eq!(ruled, earlier, "frame {i}");
                // The course's count: i(i + 1)/2 adjacency questions after the i-th vertex.
                let tests = (i * (i + 1) / 2) as u64;
                let expected = listed(&Counts {
                    adjacency_tests: tests,
                    ..Counts::default()
                });
                assert_eq!(s.counts, expected);
            }
            let last = shown.last().unwrap();
            assert_eq!(last.kind, "done");
            let fill: Vec<usize> = fills(last).into_iter().map(Option::unwrap).collect();
            assert_eq!(fill, plain.colour);
            assert!(g.edges().all(|[u, v]| fill[u] != fill[v]), "proper");
            let mut counts = Counts::default();
            course_greedy_colouring_with(&g, &order, &mut counts).unwrap();
            assert_eq!(last.counts, listed(&counts));
        }
    }
}

/// Weighted graphs: seeded sparse ones (one disconnected), with ties and parallel edges, and
/// loops.
fn weighted_graphs() -> Vec<(WeightedGraph, Vec<Point2>)> {
    let mut out = Vec::new();
    for (n, m, seed) in [(9, 16, 1), (12, 14, 2), (7, 21, 3)] {
        let list = with_random_weights(generate(GraphKind::Gnm, n, m, seed).unwrap(), seed);
        let g = WeightedGraph::from_edge_list(&list).unwrap();
        out.push((g, circle_layout(n)));
    }
    // Equal weights, a parallel edge, a loop and an isolated vertex.
    let g = WeightedGraph::from_edges(
        6,
        &[[0, 1], [1, 2], [2, 0], [0, 1], [3, 3], [2, 3], [1, 3]],
        &[1.0, 1.0, 1.0, 0.5, 0.0, 2.0, 2.0],
    )
    .unwrap();
    out.push((g, circle_layout(6)));
    out
}

fn weighted_edges(g: &WeightedGraph) -> BTreeSet<[usize; 2]> {
    sorted_pairs(
        (0..g.edge_count())
            .map(|e| g.endpoints(e))
            .filter(|[u, v]| u != v),
    )
}

/// Whether `edges` form a forest: no edge joins two vertices already connected.
fn is_forest(n: usize, edges: &[[usize; 2]]) -> bool {
    let mut sets = UnionFind::new(n);
    edges.iter().all(|&[u, v]| sets.union(u, v))
}

#[test]
fn prim_pages_grow_one_tree_and_end_with_prims_forest() {
    for (g, positions) in weighted_graphs() {
        let n = g.vertex_count();
        let trace = prim_trace(&g).unwrap();
        let html = prim_steps(&g, &positions, &trace).unwrap().to_html();
        let kind = |s: &PrimStep| match s {
            PrimStep::Root { .. } => "root",
            PrimStep::Edge { accepted: true, .. } => "accept",
            PrimStep::Edge {
                accepted: false, ..
            } => "reject",
            PrimStep::Done { .. } => "done",
        };
        let shown = check_page(&html, &trace, kind, &positions, &weighted_edges(&g));
        let mut previous: Vec<[usize; 2]> = Vec::new();
        for (s, f) in shown.iter().zip(&trace) {
            let tree = pairs(s, "tree", &positions);
            assert!(is_forest(n, &tree), "frame {}", s.step);
            // Every edge is labelled with its weight.
            assert_eq!(s.svg.texts("weights").len(), weighted_edges_count(&g));
            let reached = vertices(s, "reached", &positions);
            match &f.step {
                PrimStep::Root { vertex } => {
                    assert_eq!(vertices(s, "current", &positions), [*vertex]);
                    assert!(reached.binary_search(vertex).is_ok());
                }
                PrimStep::Edge {
                    edge, to, accepted, ..
                } => {
                    let [u, v] = g.endpoints(*edge);
                    let e = [u.min(v), u.max(v)];
                    let was_in = previous.iter().flatten().any(|&w| w == *to);
                    if *accepted {
                        assert_eq!(pairs(s, "accepted", &positions), [e]);
                        assert!(pairs(s, "rejected", &positions).is_empty());
                        assert_eq!(tree.len(), previous.len() + 1);
                        assert!(!was_in, "an accepted edge brings a new vertex");
                    } else {
                        assert_eq!(pairs(s, "rejected", &positions), [e]);
                        assert_eq!(tree, previous);
                        // Both ends are already reached.
                        assert!(reached.binary_search(&u).is_ok());
                        assert!(reached.binary_search(&v).is_ok());
                    }
                }
                PrimStep::Done { .. } => {}
            }
            // The reached vertices are the tree's, with the roots.
            for &w in tree.iter().flatten() {
                assert!(reached.binary_search(&w).is_ok());
            }
            previous = tree;
        }
        let plain = prim(&g);
        let last = shown.last().unwrap();
        let expected = sorted_pairs(plain.edges.iter().map(|&e| g.endpoints(e)));
        assert_eq!(sorted_pairs(pairs(last, "tree", &positions)), expected);
        let mut counts = Counts::default();
        prim_with(&g, &mut counts);
        assert_eq!(last.counts, listed(&counts));
        let tree_len = plain.edges.len();
        assert!(last.caption.contains(&format!("{tree_len} edges")));
    }
}

fn weighted_edges_count(g: &WeightedGraph) -> usize {
    (0..g.edge_count())
        .filter(|&e| g.endpoints(e)[0] != g.endpoints(e)[1])
        .count()
}

#[test]
fn kruskal_pages_keep_a_forest_reject_only_cycles_and_end_with_kruskals_forest() {
    for (g, positions) in weighted_graphs() {
        let n = g.vertex_count();
        let trace = kruskal_trace(&g).unwrap();
        let html = kruskal_steps(&g, &positions, &trace).unwrap().to_html();
        let kind = |s: &KruskalStep| match s {
            KruskalStep::Sorted { .. } => "sorted",
            KruskalStep::Edge { accepted: true, .. } => "accept",
            KruskalStep::Edge {
                accepted: false, ..
            } => "reject",
            KruskalStep::Done { .. } => "done",
        };
        let shown = check_page(&html, &trace, kind, &positions, &weighted_edges(&g));
        let mut previous: Vec<[usize; 2]> = Vec::new();
        for (s, f) in shown.iter().zip(&trace) {
            // The accepted edges drawn so far form a forest in every frame.
            let forest = pairs(s, "tree", &positions);
            assert!(is_forest(n, &forest), "frame {}", s.step);
            if let KruskalStep::Edge { edge, accepted, .. } = &f.step {
                let [u, v] = g.endpoints(*edge);
                let e = [u.min(v), u.max(v)];
                // Whether u and v were in one tree of the forest drawn before: the edge
                // closes a cycle exactly then.
                let mut sets = UnionFind::new(n);
                for &[a, b] in &previous {
                    sets.union(a, b);
                }
                let cycle = sets.find(u) == sets.find(v);
                assert_eq!(*accepted, !cycle, "frame {}", s.step);
                if *accepted {
                    assert_eq!(pairs(s, "accepted", &positions), [e]);
                    let mut grown = previous.clone();
                    grown.push(e);
                    assert_eq!(sorted_pairs(forest.clone()), sorted_pairs(grown));
                } else {
                    assert_eq!(pairs(s, "rejected", &positions), [e]);
                    assert!(s.caption.contains("cycle"), "{}", s.caption);
                    assert_eq!(forest, previous);
                }
            }
            previous = forest;
        }
        let plain = kruskal(&g);
        let last = shown.last().unwrap();
        let expected = sorted_pairs(plain.edges.iter().map(|&e| g.endpoints(e)));
        assert_eq!(sorted_pairs(pairs(last, "tree", &positions)), expected);
        let mut counts = Counts::default();
        kruskal_with(&g, &mut counts);
        assert_eq!(last.counts, listed(&counts));
    }
}

#[test]
fn graph_pages_refuse_bad_positions_and_traces_by_name() {
    let g = Graph::from_edges(3, &[[0, 1], [1, 2]]).unwrap();
    let trace = search_trace(&g, 0, SearchAlgorithm::Bfs).unwrap();
    let named = |r: compgeo::Result<compgeo::draw::StepPage>, name: &str| match r {
        Err(Error::InvalidParameter { name: n, .. }) => assert_eq!(n, name),
        other => panic!("{:?}", other.map(|p| p.frames().len())),
    };
    named(
        search_steps(&g, &circle_layout(2), SearchAlgorithm::Bfs, &trace),
        "positions",
    );
    let mut nan = circle_layout(3);
    nan[2].y = f64::INFINITY;
    named(
        search_steps(&g, &nan, SearchAlgorithm::Bfs, &trace),
        "positions",
    );
    // A trace of a larger graph names vertices this graph does not have.
    let big = Graph::from_edges(5, &[[0, 4], [4, 3]]).unwrap();
    let other = search_trace(&big, 0, SearchAlgorithm::Dfs).unwrap();
    named(
        search_steps(&g, &circle_layout(3), SearchAlgorithm::Dfs, &other),
        "trace",
    );
    let colouring = course_greedy_colouring_trace(&big, &[0, 1, 2, 3, 4]).unwrap();
    named(colouring_steps(&g, &circle_layout(3), &colouring), "trace");
    let w = WeightedGraph::from_edges(2, &[[0, 1]], &[1.0]).unwrap();
    let wide = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [0, 2]], &[3.0, 2.0, 1.0]).unwrap();
    named(
        prim_steps(&w, &circle_layout(2), &prim_trace(&wide).unwrap()),
        "trace",
    );
    named(
        kruskal_steps(&w, &circle_layout(2), &kruskal_trace(&wide).unwrap()),
        "trace",
    );
    named(
        prim_steps(&w, &circle_layout(3), &prim_trace(&w).unwrap()),
        "positions",
    );
}

#[cfg(feature = "cli")]
mod cli {
    use super::*;
    use crate::common::{run, TempDir};
    use serde_json::Value;

    #[test]
    fn draw_graph_steps_writes_one_frame_per_trace_frame() {
        let dir = TempDir::new("draw-graph-steps");
        let list = with_random_weights(generate(GraphKind::Gnm, 8, 13, 4).unwrap(), 4);
        let g = Graph::from_edge_list(&list).unwrap();
        let w = WeightedGraph::from_edge_list(&list).unwrap();
        let edges: Vec<String> = list
            .edges
            .iter()
            .zip(list.weights.as_ref().unwrap())
            .map(|([u, v], x)| format!("[{u},{v},{x:?}]"))
            .collect();
        let input = dir.path("graph.json");
        std::fs::write(
            &input,
            format!("{{\"vertices\": 8, \"edges\": [{}]}}", edges.join(",")),
        )
        .unwrap();
        let input = input.to_str().unwrap();
        let order: Vec<usize> = (0..8).collect();
        let cases: [(&[&str], &str, usize); 5] = [
            (
                &["--bfs", "3"],
                "bfs",
                search_trace(&g, 3, SearchAlgorithm::Bfs).unwrap().len(),
            ),
            (
                &["--dfs", "0"],
                "dfs",
                search_trace(&g, 0, SearchAlgorithm::Dfs).unwrap().len(),
            ),
            (
                &["--colour", "course"],
                "course",
                course_greedy_colouring_trace(&g, &order).unwrap().len(),
            ),
            (&["--mst", "prim"], "prim", prim_trace(&w).unwrap().len()),
            (
                &["--mst", "kruskal"],
                "kruskal",
                kruskal_trace(&w).unwrap().len(),
            ),
        ];
        for (option, algorithm, frames) in cases {
            let out = dir.path(&format!("{algorithm}.html"));
            let out = out.to_str().unwrap();
            let mut args = vec!["draw", "graph", input, "--steps", "--out", out];
            args.extend(option);
            let (code, stdout, err) = run(&args, None);
            assert_eq!(code, 0, "{args:?}: {err}");
            let summary: Value = serde_json::from_str(stdout.trim()).unwrap();
            assert_eq!(summary["problem"], "graph");
            assert_eq!(summary["algorithm"], algorithm);
            assert_eq!(summary["vertices"], 8);
            assert_eq!(summary["frames"], frames);
            let html = std::fs::read_to_string(out).unwrap();
            assert_eq!(summary["bytes"], html.len());
            assert_eq!(frames_of(&html).len(), frames);
        }
        // Given coordinates: the frames are drawn at them.
        let points = dir.path("points.json");
        let at: Vec<Point2> = (0..8)
            .map(|i| Point2::new(i as f64, ((i * 5) % 8) as f64))
            .collect();
        let text: Vec<String> = at.iter().map(|p| format!("[{}, {}]", p.x, p.y)).collect();
        std::fs::write(&points, format!("[{}]", text.join(","))).unwrap();
        let (code, stdout, err) = run(
            &[
                "draw",
                "graph",
                input,
                "--points",
                points.to_str().unwrap(),
                "--mst",
                "kruskal",
                "--steps",
                "--out",
                "-",
            ],
            None,
        );
        assert_eq!(code, 0, "{err}");
        let shown = frames_of(&stdout);
        let expected = sorted_pairs(kruskal(&w).edges.iter().map(|&e| w.endpoints(e)));
        assert_eq!(
            sorted_pairs(pairs(shown.last().unwrap(), "tree", &at)),
            expected
        );

        // Untraced algorithms, no algorithm, and bad input are named errors.
        let unweighted = dir.path("plain.json");
        std::fs::write(
            &unweighted,
            "{\"vertices\": 3, \"edges\": [[0, 1], [1, 2]]}",
        )
        .unwrap();
        let unweighted = unweighted.to_str().unwrap();
        for (args, message) in [
            (
                vec!["--colour", "dsatur"],
                "error: --steps: no step trace for dsatur",
            ),
            (
                vec!["--mst", "boruvka"],
                "error: --steps: no step trace for boruvka",
            ),
            (vec![], "error: --steps on a graph needs an algorithm"),
            (vec!["--bfs", "8"], "error:"),
        ] {
            let mut all = vec!["draw", "graph", input, "--steps", "--out", "x.html"];
            all.extend(args);
            let (code, stdout, err) = run(&all, None);
            assert_eq!(code, 2, "{all:?}");
            assert!(stdout.is_empty());
            assert!(err.starts_with(message), "{all:?}: {err}");
            assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        }
        let (code, _, err) = run(
            &[
                "draw", "graph", unweighted, "--mst", "prim", "--steps", "--out", "x.html",
            ],
            None,
        );
        assert_eq!(code, 2);
        assert!(err.contains("weight"), "{err}");
        let (code, _, err) = run(
            &[
                "draw", "graph", "-", "--dfs", "0", "--steps", "--out", "x.html",
            ],
            Some("{\"vertices\": 2, \"edges\": [[0, 5]]}"),
        );
        assert_eq!(code, 2);
        assert!(err.starts_with("error:"), "{err}");
    }
}
