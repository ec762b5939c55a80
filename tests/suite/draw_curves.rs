//! The pictures of curves, surfaces, meshes and graphs read back with an XML parser and
//! mapped to the world through the recorded frame: the curve's polyline is the curve
//! (against exact rational oracles: de Casteljau's levels from the Bernstein form, a clamped
//! B-spline against its Bézier curve, a uniform Beta-spline against its B-spline, a NURBS
//! arc against the circle), the control polygons are the control points, the knots are on
//! the curve, the projected wireframes are the projected surface points, the mesh edges are
//! the mesh's, the colour classes are the colouring's and proper, and the tree edges are the
//! tree's.

use crate::draw::{svg, Svg};
use crate::spline_common::{q, qi, Q};
use compgeo::draw::{self, circle_layout, sample_parameters, GraphOverlay, CLASS_COLOURS};
use compgeo::geometry::Point2;
use compgeo::graph::{
    colour, search, spanning_forest, ColouringAlgorithm, Graph, MstAlgorithm, SearchAlgorithm,
    WeightedGraph,
};
use compgeo::mesh::{catmull_clark, PolygonMesh};
use compgeo::spline::{
    BSpline, BetaParameters, BetaSpline, Bezier, Curve, KnotVector, Nurbs, Point, Scalar,
};
use compgeo::surface::{BezierPatch, ControlNet, Surface, TriangularPatch};
use compgeo::Error;
use proptest::prelude::*;
use std::collections::BTreeSet;

/// The plane point of an exact point in two or three dimensions, by the documented
/// projection (x, y, z) ↦ (x + k·y, z + k·y), k = √2/4, computed here in `f64`.
fn plane<S: Scalar, const D: usize>(p: &Point<S, D>) -> Point2 {
    let c: Vec<f64> = p.coords().iter().map(Scalar::to_f64).collect();
    match D {
        2 => Point2::new(c[0], c[1]),
        3 => {
            let k = 2f64.sqrt() / 4.0;
            Point2::new(c[0] + k * c[1], c[2] + k * c[1])
        }
        _ => unreachable!(),
    }
}

/// Asserts that the vertices drawn in subpath `k` of layer `class` are `expected`, in order.
fn assert_drawn(svg: &Svg, class: &str, k: usize, expected: &[Point2]) {
    let paths = svg.subpaths(class);
    let drawn = &paths[k].points;
    assert_eq!(drawn.len(), expected.len(), "{class}[{k}]");
    let frame = svg.frame();
    for (i, (at, p)) in drawn.iter().zip(expected).enumerate() {
        assert!(
            frame.maps_back(*at, *p),
            "{class}[{k}][{i}]: {at:?} vs {p:?}"
        );
    }
}

/// The dots of layer `class` (each a subpath `Mx yh0`), in order.
fn dots(svg: &Svg, class: &str) -> Vec<[f64; 2]> {
    svg.subpaths(class).iter().map(|s| s.points[0]).collect()
}

/// Level k of de Casteljau's scheme at t from the Bernstein form:
/// bᵢᵏ = Σⱼ C(k, j) tʲ (1 − t)^(k−j) bᵢ₊ⱼ.
fn bernstein_level(control: &[Point<Q, 2>], t: &Q, k: usize) -> Vec<Point<Q, 2>> {
    let s = qi(1) - t;
    (0..control.len() - k)
        .map(|i| {
            let mut p = Point::<Q, 2>::zero();
            let mut binomial = qi(1);
            for j in 0..=k {
                let mut w = binomial.clone();
                for _ in 0..j {
                    w *= t;
                }
                for _ in j..k {
                    w *= &s;
                }
                for c in 0..2 {
                    p[c] += w.clone() * &control[i + j][c];
                }
                binomial = binomial * qi((k - j) as i64) / qi(j as i64 + 1);
            }
            p
        })
        .collect()
}

fn planes<S: Scalar, const D: usize>(points: &[Point<S, D>]) -> Vec<Point2> {
    points.iter().map(plane).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn a_bezier_picture_draws_the_curve_its_polygon_and_de_casteljaus_levels(
        coords in prop::collection::vec((-50i64..50, -50i64..50), 2..8),
        (num, den) in (-8i64..24, 1i64..16),
    ) {
        let control: Vec<Point<Q, 2>> =
            coords.iter().map(|&(x, y)| Point::new([qi(x), qi(y)])).collect();
        let n = control.len() - 1;
        let t = q(num, den);
        let b = Bezier::new(control.clone()).unwrap();
        let svg = svg(&draw::bezier(&b, Some(&t)).unwrap());
        let curve: Vec<Point2> = sample_parameters(&[qi(0), qi(1)])
            .iter()
            .map(|u| plane(&bernstein_level(&control, u, n)[0]))
            .collect();
        assert_drawn(&svg, "curve", 0, &curve);
        assert_drawn(&svg, "control-polygon", 0, &planes(&control));
        // Level k + 1 of the scaffolding, n − k points, for k = 0, …, n − 2.
        let scaffolding = svg.subpaths("scaffolding");
        prop_assert_eq!(scaffolding.len(), n.saturating_sub(1));
        for k in 0..scaffolding.len() {
            let level = bernstein_level(&control, &t, k + 1);
            prop_assert_eq!(level.len(), n - k);
            assert_drawn(&svg, "scaffolding", k, &planes(&level));
        }
        let point = dots(&svg, "point");
        prop_assert_eq!(point.len(), 1);
        prop_assert!(svg.frame().maps_back(point[0], plane(&bernstein_level(&control, &t, n)[0])));
    }
}

#[test]
fn a_clamped_bspline_without_inner_knots_draws_its_bezier_curve_and_de_casteljaus_net() {
    // Knots 0⁴ 1⁴: the B-spline is the Bézier curve of its control points, and de Boor's net
    // at u is de Casteljau's triangle.
    let control: Vec<Point<Q, 2>> = [(0, 0), (2, 7), (5, -3), (9, 4)]
        .iter()
        .map(|&(x, y)| Point::new([qi(x), qi(y)]))
        .collect();
    let knots = KnotVector::clamped_uniform(3, 4, qi(0), qi(1)).unwrap();
    let s = BSpline::new(control.clone(), knots).unwrap();
    let u = q(2, 7);
    let svg = svg(&draw::bspline(&s, Some(&u)).unwrap());
    let curve: Vec<Point2> = sample_parameters(&[qi(0), qi(1)])
        .iter()
        .map(|t| plane(&bernstein_level(&control, t, 3)[0]))
        .collect();
    assert_drawn(&svg, "curve", 0, &curve);
    assert_drawn(&svg, "control-polygon", 0, &planes(&control));
    for k in 0..3 {
        assert_drawn(
            &svg,
            "de-boor-net",
            k,
            &planes(&bernstein_level(&control, &u, k)),
        );
    }
    let ends = dots(&svg, "knots");
    assert_eq!(ends.len(), 2);
    assert!(svg.frame().maps_back(ends[0], plane(&control[0])));
    assert!(svg.frame().maps_back(ends[1], plane(&control[3])));
}

#[test]
fn a_bspline_picture_marks_its_distinct_knots_on_the_curve() {
    // Degree 2, knots 0 0 0 1/3 1/3 2/3 1 1 1 (a double knot): four distinct knots.
    let knots: Vec<Q> = [
        (0, 1),
        (0, 1),
        (0, 1),
        (1, 3),
        (1, 3),
        (2, 3),
        (1, 1),
        (1, 1),
        (1, 1),
    ]
    .iter()
    .map(|&(n, d)| q(n, d))
    .collect();
    let control: Vec<Point<Q, 3>> = (0..6)
        .map(|i| Point::new([qi(i), qi(i * i % 5), qi(3 - i)]))
        .collect();
    let s = BSpline::new(control.clone(), KnotVector::new(2, knots).unwrap()).unwrap();
    let svg = svg(&draw::bspline(&s, None).unwrap());
    let distinct = [q(0, 1), q(1, 3), q(2, 3), q(1, 1)];
    let marked = dots(&svg, "knots");
    assert_eq!(marked.len(), distinct.len());
    for (at, u) in marked.iter().zip(&distinct) {
        assert!(svg.frame().maps_back(*at, plane(&s.eval(u).unwrap())));
    }
    let curve: Vec<Point2> = sample_parameters(&distinct)
        .iter()
        .map(|u| plane(&s.eval(u).unwrap()))
        .collect();
    assert_eq!(curve.len(), 3 * draw::SAMPLES_PER_PIECE + 1);
    assert_drawn(&svg, "curve", 0, &curve);
    assert_drawn(&svg, "control-polygon", 0, &planes(&control));
    assert!(svg.subpaths("de-boor-net").is_empty());
}

#[test]
fn a_nurbs_quarter_circle_is_drawn_on_the_circle() {
    let knots = KnotVector::clamped_uniform(2, 3, 0.0, 1.0).unwrap();
    let r = 1000.0;
    let control = vec![
        Point::new([r, 0.0]),
        Point::new([r, r]),
        Point::new([0.0, r]),
    ];
    let arc = Nurbs::new(
        control,
        vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
        knots,
    )
    .unwrap();
    let svg = svg(&draw::nurbs(&arc).unwrap());
    let frame = svg.frame();
    let curve = &svg.subpaths("curve")[0].points;
    assert_eq!(curve.len(), draw::SAMPLES_PER_PIECE + 1);
    for at in curve {
        // The point of the circle in the drawn vertex's direction maps back to it.
        let [x0, y0] = frame.picture_of(Point2::new(0.0, 0.0));
        let angle = (y0 - at[1]).atan2(at[0] - x0);
        let on = Point2::new(r * angle.cos(), r * angle.sin());
        assert!(frame.maps_back(*at, on), "{at:?}");
    }
}

#[test]
fn a_uniform_beta_spline_is_its_uniform_cubic_bspline() {
    // β₁ = 1, β₂ = 0: the uniform cubic B-spline, segment i on [i, i + 1] being the
    // B-spline with knots 0, 1, …, n + 3 on [i + 3, i + 4].
    let control: Vec<Point<Q, 2>> = [(0, 0), (3, 5), (6, -1), (9, 4), (12, 0), (15, 6)]
        .iter()
        .map(|&(x, y)| Point::new([qi(x), qi(y)]))
        .collect();
    let n = control.len();
    let beta =
        BetaSpline::new(BetaParameters::new(qi(1), qi(0)).unwrap(), control.clone()).unwrap();
    let knots = KnotVector::new(3, (0..n as i64 + 4).map(qi).collect()).unwrap();
    let b = BSpline::new(control.clone(), knots).unwrap();
    let svg = svg(&draw::beta(&beta).unwrap());
    let m = n - 3;
    let breaks: Vec<Q> = (0..=m as i64).map(qi).collect();
    let curve: Vec<Point2> = sample_parameters(&breaks)
        .iter()
        .map(|u| plane(&b.eval(&(u.clone() + qi(3))).unwrap()))
        .collect();
    assert_drawn(&svg, "curve", 0, &curve);
    let joints = dots(&svg, "joints");
    assert_eq!(joints.len(), m + 1);
    for (at, u) in joints.iter().zip(&breaks) {
        assert!(svg
            .frame()
            .maps_back(*at, plane(&b.eval(&(u.clone() + qi(3))).unwrap())));
    }
    assert_drawn(&svg, "control-polygon", 0, &planes(&control));
}

#[test]
fn subdivision_rounds_are_drawn_one_layer_each_and_the_input_numbered() {
    use compgeo::spline::subdivision::{lane_riesenfeld, Topology};
    let p: Vec<Point<Q, 2>> = [(0, 0), (8, 0), (8, 8), (0, 8), (-4, 4)]
        .iter()
        .map(|&(x, y)| Point::new([qi(x), qi(y)]))
        .collect();
    for topology in [Topology::Open, Topology::Closed] {
        let rounds: Vec<Vec<Point<Q, 2>>> = (0..=3)
            .map(|r| lane_riesenfeld(&p, 3, r, topology).unwrap())
            .collect();
        let svg = svg(&draw::subdivision("Lane–Riesenfeld", &rounds, topology).unwrap());
        assert_drawn(&svg, "control-polygon", 0, &planes(&p));
        for (r, round) in rounds.iter().enumerate().take(3).skip(1) {
            assert_drawn(&svg, &format!("round-{r}"), 0, &planes(round));
        }
        assert_drawn(&svg, "result", 0, &planes(&rounds[3]));
        let closed = topology == Topology::Closed;
        assert_eq!(svg.subpaths("result")[0].closed, closed);
        assert_eq!(svg.texts("labels"), ["0", "1", "2", "3", "4"]);
    }
}

#[test]
fn a_surface_wireframe_is_the_projected_surface_and_its_net() {
    let net: Vec<Vec<Point<Q, 3>>> = (0..3)
        .map(|i| {
            (0..4)
                .map(|j| Point::new([qi(j), qi(i), qi((i * j) % 3 - 1)]))
                .collect()
        })
        .collect();
    let net = ControlNet::new(net).unwrap();
    let patch = BezierPatch::new(net.clone()).unwrap();
    let lines = 3;
    let svg = svg(&draw::surface("Bézier patch", &patch, &net, lines).unwrap());
    let iso: Vec<Q> = (0..=lines as i64).map(|i| q(i, lines as i64)).collect();
    let along = sample_parameters(&iso);
    for (i, u) in iso.iter().enumerate() {
        let line: Vec<Point2> = along
            .iter()
            .map(|v| plane(&patch.eval(u, v).unwrap()))
            .collect();
        assert_drawn(&svg, "iso-u", i, &line);
        let line: Vec<Point2> = along
            .iter()
            .map(|w| plane(&patch.eval(w, u).unwrap()))
            .collect();
        assert_drawn(&svg, "iso-v", i, &line);
    }
    for i in 0..3 {
        assert_drawn(&svg, "control-net", i, &planes(net.row(i)));
    }
    for j in 0..4 {
        assert_drawn(&svg, "control-net", 3 + j, &planes(&net.column(j)));
    }
    // The projection keeps z up: the corner with the larger z is drawn higher.
    let top = svg
        .frame()
        .picture_of(plane(&Point::<f64, 3>::new([0.0, 0.0, 1.0])));
    let bottom = svg
        .frame()
        .picture_of(plane(&Point::<f64, 3>::new([0.0, 0.0, 0.0])));
    assert!(top[1] < bottom[1] && top[0] == bottom[0]);
}

#[test]
fn a_triangular_patch_wireframe_is_its_projected_barycentric_grid() {
    let n = 3;
    let points: Vec<Point<Q, 3>> = (0..(n + 1) * (n + 2) / 2)
        .map(|i| Point::new([qi(i as i64 % 4), qi(i as i64 / 4), q(i as i64 * 7 % 5, 2)]))
        .collect();
    let patch = TriangularPatch::new(points.clone()).unwrap();
    let s = 4usize;
    let svg = svg(&draw::triangular_patch(&patch, s).unwrap());
    let at = |i: usize, j: usize| {
        plane(
            &patch
                .eval(&q(i as i64, s as i64), &q(j as i64, s as i64))
                .unwrap(),
        )
    };
    for i in 0..s {
        let line: Vec<Point2> = (0..=s - i).map(|j| at(i, j)).collect();
        assert_drawn(&svg, "iso-u", i, &line);
        let line: Vec<Point2> = (0..=s - i).map(|k| at(k, i)).collect();
        assert_drawn(&svg, "iso-v", i, &line);
    }
    for m in 1..=s {
        let line: Vec<Point2> = (0..=m).map(|i| at(i, m - i)).collect();
        assert_drawn(&svg, "iso-w", m - 1, &line);
    }
    assert_eq!(svg.subpaths("control-net").len(), n * (n + 1) / 2);
    assert_eq!(dots(&svg, "control-points").len(), points.len());
}

/// The set of drawn segments of `class`, each as the pair of `positions` indices its ends
/// map back to (smaller first).
fn drawn_pairs(svg: &Svg, class: &str, positions: &[Point2]) -> Vec<[usize; 2]> {
    let frame = svg.frame();
    let find = |at: [f64; 2]| {
        let hits: Vec<usize> = (0..positions.len())
            .filter(|&i| frame.maps_back(at, positions[i]))
            .collect();
        assert_eq!(hits.len(), 1, "{at:?} maps back to {hits:?}");
        hits[0]
    };
    svg.subpaths(class)
        .iter()
        .map(|s| {
            assert_eq!(s.points.len(), 2);
            let [a, b] = [find(s.points[0]), find(s.points[1])];
            [a.min(b), a.max(b)]
        })
        .collect()
}

#[test]
fn mesh_pictures_draw_each_edge_once_with_the_coarse_mesh_under_the_fine() {
    let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    let cube = PolygonMesh::new(
        vec![
            p(0.0, 0.0, 0.0),
            p(1.0, 0.0, 0.0),
            p(1.0, 1.0, 0.0),
            p(0.0, 1.0, 0.0),
            p(0.0, 0.0, 1.0),
            p(1.0, 0.0, 1.0),
            p(1.0, 1.0, 1.0),
            p(0.0, 1.0, 1.0),
        ],
        &[
            [0, 3, 2, 1],
            [4, 5, 6, 7],
            [0, 1, 5, 4],
            [1, 2, 6, 5],
            [2, 3, 7, 6],
            [3, 0, 4, 7],
        ],
    )
    .unwrap();
    let fine = catmull_clark(&cube, 1).unwrap();
    let svg = svg(&draw::mesh(&cube, Some(&fine)).unwrap());
    let positions = planes(cube.positions());
    let drawn: BTreeSet<[usize; 2]> = drawn_pairs(&svg, "coarse", &positions)
        .into_iter()
        .collect();
    let t = cube.topology();
    let edges: BTreeSet<[usize; 2]> = (0..t.edge_count())
        .map(|e| {
            let [a, b] = t.edge_vertices(e);
            [a.min(b), a.max(b)]
        })
        .collect();
    assert_eq!(drawn, edges);
    assert_eq!(svg.subpaths("coarse").len(), 12);
    assert_eq!(svg.subpaths("edges").len(), fine.edge_count());
    let fine_positions = planes(fine.positions());
    let frame = svg.frame();
    for s in svg.subpaths("edges") {
        for at in s.points {
            assert!(fine_positions.iter().any(|&q| frame.maps_back(at, q)));
        }
    }
}

#[test]
fn graph_colourings_fill_each_class_with_its_colour_and_are_proper() {
    for (kind, n, m) in [
        (compgeo::gen::GraphKind::Petersen, 10, 0),
        (compgeo::gen::GraphKind::Gnm, 40, 120),
        (compgeo::gen::GraphKind::Crown, 12, 0),
    ] {
        let list = compgeo::gen::graph(kind, n, m, 7).unwrap();
        let g = Graph::from_edge_list(&list).unwrap();
        let positions = circle_layout(g.vertex_count());
        for algorithm in [ColouringAlgorithm::Dsatur, ColouringAlgorithm::LargestFirst] {
            let c = colour(&g, algorithm);
            let svg = svg(&draw::graph(&g, &positions, GraphOverlay::Colouring(&c)).unwrap());
            let frame = svg.frame();
            let mut drawn = vec![usize::MAX; g.vertex_count()];
            for k in 0..c.count {
                let class = format!("colour-{k}");
                assert_eq!(
                    svg.layer_attribute(&class, "fill").as_deref(),
                    Some(CLASS_COLOURS[k % CLASS_COLOURS.len()])
                );
                for [x, y, _] in svg.circles(&class) {
                    let v = (0..positions.len())
                        .find(|&v| frame.maps_back([x, y], positions[v]))
                        .expect("a disc on a vertex");
                    assert_eq!(drawn[v], usize::MAX, "vertex {v} drawn twice");
                    drawn[v] = k;
                }
            }
            assert_eq!(drawn, c.colour);
            assert!(g.edges().all(|[u, v]| drawn[u] != drawn[v]));
            assert_eq!(drawn_pairs(&svg, "edges", &positions).len(), g.edge_count());
        }
    }
}

#[test]
fn spanning_and_search_trees_are_drawn_as_their_edges() {
    let list = compgeo::gen::with_random_weights(
        compgeo::gen::graph(compgeo::gen::GraphKind::Gnm, 30, 70, 3).unwrap(),
        5,
    );
    let g = Graph::from_edge_list(&list).unwrap();
    let w = WeightedGraph::from_edge_list(&list).unwrap();
    // Coordinates given: a spiral, not a circle.
    let positions: Vec<Point2> = (0..30)
        .map(|i| {
            let a = i as f64 * 0.7;
            Point2::new((1.0 + i as f64) * a.cos(), (1.0 + i as f64) * a.sin())
        })
        .collect();
    for algorithm in [MstAlgorithm::Kruskal, MstAlgorithm::Prim] {
        let f = spanning_forest(&w, algorithm);
        let edges: Vec<[usize; 2]> = f.edges.iter().map(|&e| w.endpoints(e)).collect();
        let svg = svg(&draw::graph(&g, &positions, GraphOverlay::Tree(&edges)).unwrap());
        let drawn: BTreeSet<[usize; 2]> =
            drawn_pairs(&svg, "tree", &positions).into_iter().collect();
        let expected: BTreeSet<[usize; 2]> =
            edges.iter().map(|&[a, b]| [a.min(b), a.max(b)]).collect();
        assert_eq!(drawn, expected);
    }
    for kind in [SearchAlgorithm::Bfs, SearchAlgorithm::Dfs] {
        let s = search(&g, 4, kind).unwrap();
        let svg = svg(&draw::graph(
            &g,
            &positions,
            GraphOverlay::Search {
                search: &s,
                start: 4,
            },
        )
        .unwrap());
        let drawn: BTreeSet<[usize; 2]> =
            drawn_pairs(&svg, "tree", &positions).into_iter().collect();
        let expected: BTreeSet<[usize; 2]> = (0..30)
            .filter_map(|v| s.parent[v].map(|p| [p.min(v), p.max(v)]))
            .collect();
        assert_eq!(drawn, expected);
        assert_eq!(drawn.len(), s.order.len() - 1);
        let ring = svg.circles("start");
        assert!(svg
            .frame()
            .maps_back([ring[0][0], ring[0][1]], positions[4]));
    }
}

#[test]
fn bad_drawing_input_is_a_named_error() {
    let line = Bezier::new(vec![Point::new([0.0]), Point::new([1.0])]).unwrap();
    assert!(matches!(
        draw::bezier(&line, None),
        Err(Error::InvalidParameter {
            name: "dimension",
            ..
        })
    ));
    let b = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([1.0, 1.0])]).unwrap();
    assert!(matches!(
        draw::bezier(&b, Some(&f64::NAN)),
        Err(Error::InvalidParameter { name: "t", .. })
    ));
    // A curve whose points overflow far outside [0, 1] draws within [0, 1]; its scaffolding at
    // t = 1e300 does not fit in f64.
    let big = Bezier::new(vec![
        Point::new([0.0, 0.0]),
        Point::new([1e300, 1e300]),
        Point::new([0.0, 1e300]),
    ])
    .unwrap();
    assert!(draw::bezier(&big, None).is_ok());
    assert!(matches!(
        draw::bezier(&big, Some(&1e300)),
        Err(Error::Overflow { .. })
    ));
    let net = ControlNet::new(vec![vec![Point::new([0.0, 0.0, 0.0]); 2]; 2]).unwrap();
    let patch = BezierPatch::new(net.clone()).unwrap();
    for lines in [0, 5000] {
        assert!(matches!(
            draw::surface("patch", &patch, &net, lines),
            Err(Error::InvalidParameter { name: "lines", .. })
        ));
    }
    let g = Graph::from_edges(3, &[[0, 1], [1, 2]]).unwrap();
    assert!(matches!(
        draw::graph(&g, &circle_layout(2), GraphOverlay::Plain),
        Err(Error::InvalidParameter {
            name: "positions",
            ..
        })
    ));
    let mut nan = circle_layout(3);
    nan[1].x = f64::NAN;
    assert!(draw::graph(&g, &nan, GraphOverlay::Plain).is_err());
    let wrong = compgeo::graph::Colouring {
        colour: vec![0, 0, 5],
        count: 2,
    };
    assert!(matches!(
        draw::graph(&g, &circle_layout(3), GraphOverlay::Colouring(&wrong)),
        Err(Error::InvalidParameter {
            name: "colouring",
            ..
        })
    ));
    assert!(matches!(
        draw::graph(&g, &circle_layout(3), GraphOverlay::Tree(&[[0, 7]])),
        Err(Error::InvalidParameter { name: "tree", .. })
    ));
    let empty: Vec<Vec<Point<f64, 2>>> = Vec::new();
    assert!(
        draw::subdivision("none", &empty, compgeo::spline::subdivision::Topology::Open).is_err()
    );
}
