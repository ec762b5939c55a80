//! Loop subdivision, exactly in rationals: on a periodic regular triangular grid every round
//! is the quartic box-spline rule B₁₁₂ of [PPB, §15.7] (the oracle in
//! `surface_subdivision.rs`, written from the course's operators), positions and
//! triangles; V, E, F per round and the Euler characteristic on closed and bounded irregular
//! meshes, with the half-edge invariants of every result; the weights (α(6) = 5/8, Loop's
//! interval, exact affine rules for every valence); the boundary polygon subdivided as a
//! closed cubic B-spline (the curve Lane–Riesenfeld algorithm as the oracle); the limit
//! positions fixed by a round; the operation counts; OpenSubdiv (`opensubdiv-rs`) as a peer
//! oracle in `f64`; bad input gets named errors.

use crate::spline_common::{q, qi, Q};
use crate::surface_subdivision::{lattice_net, quartic_box_spline_round, Grid};
use compgeo::count::Counts;
use compgeo::gen::{irregular_disk, irregular_torus, quad_grid, triangle_torus};
use compgeo::mesh::{
    loop_limit_points, loop_limit_points_with, loop_subdivision, loop_subdivision_weighted,
    loop_subdivision_with, subdivide, LoopWeights, MeshError, PolygonMesh, Scheme,
};
use compgeo::spline::subdivision::{lane_riesenfeld, Topology};
use compgeo::spline::{Point, Scalar};
use compgeo::Error;
use proptest::prelude::*;

type P3 = Point<Q, 3>;

const WEIGHTS: [LoopWeights; 2] = [LoopWeights::Loop, LoopWeights::Warren];

/// The mesh with exact rational positions.
pub fn exact(m: &PolygonMesh<f64, 3>) -> PolygonMesh<Q, 3> {
    let positions = m
        .positions()
        .iter()
        .map(|p| Point::from_f64(p).unwrap())
        .collect();
    m.with_positions(positions).unwrap()
}

/// The mesh with every face cut into the fan of triangles from its first corner.
pub fn fans<S: Scalar>(m: &PolygonMesh<S, 3>) -> PolygonMesh<S, 3> {
    let mut faces = Vec::new();
    for f in 0..m.face_count() {
        let c = m.face_vertices(f);
        for k in 1..c.len() - 1 {
            faces.push([c[0] as usize, c[k] as usize, c[k + 1] as usize]);
        }
    }
    PolygonMesh::new(m.positions().to_vec(), &faces).unwrap()
}

/// The periodic m × n triangular grid of [PPB, §15.7] as a mesh: vertex i·n + j at lattice
/// point (i, j) (irregular integer positions), triangles (i, j), (i + 1, j), (i + 1, j + 1)
/// and (i, j), (i + 1, j + 1), (i, j + 1); with the same points as a grid.
fn triangular_torus(m: usize, n: usize, seed: i64) -> (PolygonMesh<Q, 3>, Grid<P3>) {
    let net = lattice_net(m, n, seed);
    let id = |i: usize, j: usize| (i % m) * n + j % n;
    let mut faces = Vec::new();
    for i in 0..m {
        for j in 0..n {
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    let mesh = PolygonMesh::new(net.points().to_vec(), &faces).unwrap();
    (mesh, net.to_rows())
}

/// The step from a to b on a cycle of `len`: −1, 0 or 1.
fn step(a: usize, b: usize, len: usize) -> isize {
    match (b + len - a) % len {
        0 => 0,
        1 => 1,
        d if d == len - 1 => -1,
        d => panic!("{a} and {b} are {d} apart on a cycle of {len}"),
    }
}

#[test]
fn loop_on_a_regular_triangular_torus_is_the_quartic_box_spline() {
    for weights in WEIGHTS {
        let (mut mesh, mut grid) = triangular_torus(4, 5, 3);
        let (mut gm, mut gn) = (4usize, 5usize);
        let mut index: Vec<(usize, usize)> = (0..20).map(|v| (v / 5, v % 5)).collect();
        let start = mesh.clone();
        for round in 1..=3 {
            let child = loop_subdivision_weighted(&mesh, 1, weights).unwrap();
            grid = quartic_box_spline_round(&grid);
            let t = mesh.topology();
            let (v_count, (m2, n2)) = (mesh.vertex_count(), (2 * gm, 2 * gn));
            // Old vertex (i, j) is new point (2i, 2j); the point on the edge from (i, j) to
            // (i, j) + d is new point (2i, 2j) + d [PPB, §15.7].
            let child_index: Vec<(usize, usize)> = (0..child.vertex_count())
                .map(|w| {
                    if w < v_count {
                        let (i, j) = index[w];
                        (2 * i, 2 * j)
                    } else {
                        let [a, b] = t.edge_vertices(w - v_count);
                        let ((ia, ja), (ib, jb)) = (index[a], index[b]);
                        let di = step(ia, ib, gm);
                        let dj = step(ja, jb, gn);
                        (
                            (2 * ia as isize + di).rem_euclid(m2 as isize) as usize,
                            (2 * ja as isize + dj).rem_euclid(n2 as isize) as usize,
                        )
                    }
                })
                .collect();
            let mut hit = vec![false; m2 * n2];
            for (w, &(i, j)) in child_index.iter().enumerate() {
                assert_eq!(
                    child.position(w),
                    &grid[i][j],
                    "{weights:?} round {round} vertex {w}"
                );
                assert!(!hit[i * n2 + j], "two vertices at grid point ({i}, {j})");
                hit[i * n2 + j] = true;
            }
            assert!(hit.iter().all(|&h| h));
            // Every triangle is a grid triangle of the refined grid, counter-clockwise.
            for f in 0..child.face_count() {
                let c: Vec<(usize, usize)> = child
                    .face_vertices(f)
                    .iter()
                    .map(|&v| child_index[v as usize])
                    .collect();
                let d =
                    |a: (usize, usize), b: (usize, usize)| (step(a.0, b.0, m2), step(a.1, b.1, n2));
                let ok = (0..3).any(|r| {
                    let (p, q1, r1) = (c[r], c[(r + 1) % 3], c[(r + 2) % 3]);
                    matches!((d(p, q1), d(p, r1)), ((1, 0), (1, 1)) | ((1, 1), (0, 1)))
                });
                assert!(ok, "round {round}: face {f} = {c:?} is not a grid triangle");
            }
            mesh = child;
            index = child_index;
            (gm, gn) = (m2, n2);
        }
        // k rounds at once are the rounds one by one.
        assert_eq!(loop_subdivision_weighted(&start, 3, weights).unwrap(), mesh);
    }
}

/// The triangle meshes of the structural tests: closed and bounded, regular and not.
fn triangle_meshes() -> Vec<(&'static str, PolygonMesh<f64, 3>)> {
    let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    let tetra = PolygonMesh::new(
        vec![p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.), p(0., 0., 1.)],
        &[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    )
    .unwrap();
    let triangle = PolygonMesh::new(
        vec![p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)],
        &[[0, 1, 2]],
    )
    .unwrap();
    // Two triangles folded onto each other: a closed mesh whose vertices have valence 2.
    let pillow = PolygonMesh::new(
        vec![p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)],
        &[[0, 1, 2], [0, 2, 1]],
    )
    .unwrap();
    vec![
        ("tetrahedron", tetra),
        ("triangle", triangle),
        ("pillow", pillow),
        ("triangle torus", triangle_torus(4, 5).unwrap()),
        ("irregular torus", fans(&irregular_torus(6, 6, 5).unwrap())),
        ("irregular disk", fans(&irregular_disk(40, 2).unwrap())),
    ]
}

/// The stencil terms of a round as the docs count them, from the coarse mesh.
fn expected_ops(m: &PolygonMesh<f64, 3>) -> u64 {
    let t = m.topology();
    let vertices: usize = (0..m.vertex_count())
        .map(|v| {
            if t.is_boundary_vertex(v) {
                3
            } else {
                t.valence(v) + 1
            }
        })
        .sum();
    let edges: usize = (0..m.edge_count())
        .map(|e| if t.is_boundary_edge(e) { 2 } else { 4 })
        .sum();
    (vertices + edges) as u64
}

#[test]
fn counts_euler_characteristic_and_half_edges_per_round() {
    for (name, start) in triangle_meshes() {
        let mut mesh = start.clone();
        for round in 1..=3 {
            let mut c = Counts::default();
            let child = loop_subdivision_with(&mesh, 1, &mut c).unwrap();
            let (v, e, f) = (mesh.vertex_count(), mesh.edge_count(), mesh.face_count());
            assert_eq!(
                (child.vertex_count(), child.edge_count(), child.face_count()),
                (v + e, 2 * e + 3 * f, 4 * f),
                "{name}, round {round}"
            );
            assert_eq!(child.euler_characteristic(), start.euler_characteristic());
            assert_eq!(child.topology().check(), Ok(()), "{name}, round {round}");
            assert_eq!(
                child.topology().boundary_loop_count(),
                start.topology().boundary_loop_count()
            );
            assert_eq!(
                c.arithmetic_operations,
                expected_ops(&mesh),
                "{name}, round {round}"
            );
            // The child is what validation makes of its own face list, except for the
            // pillow, whose refinement has two edges between the same two vertices (its
            // middle triangles share their corners): valid half-edges, but not a face list
            // the validation accepts.
            if name == "pillow" {
                mesh = child;
                continue;
            }
            let faces: Vec<Vec<usize>> = (0..child.face_count())
                .map(|g| child.face_vertices(g).iter().map(|&v| v as usize).collect())
                .collect();
            let rebuilt = PolygonMesh::new(child.positions().to_vec(), &faces).unwrap();
            assert_eq!(
                rebuilt.topology().twins(),
                child.topology().twins(),
                "{name}"
            );
            mesh = child;
        }
        assert_eq!(mesh.face_count(), start.face_count() * 64);
    }
}

#[test]
fn the_weights_alpha_six_is_five_eighths_and_every_rule_is_affine() {
    assert_eq!(LoopWeights::Loop.alpha::<Q>(6), q(5, 8));
    assert_eq!(LoopWeights::Loop.beta::<Q>(6), q(1, 16));
    assert_eq!(LoopWeights::Loop.beta::<Q>(3), q(3, 16));
    assert_eq!(LoopWeights::Loop.beta::<Q>(4), q(31, 256));
    assert_eq!(LoopWeights::Warren.beta::<Q>(6), q(1, 16));
    assert_eq!(LoopWeights::Warren.beta::<Q>(3), q(3, 16));
    assert_eq!(LoopWeights::Warren.beta::<Q>(7), q(3, 56));
    for n in 2..=60usize {
        for w in WEIGHTS {
            // Exactly affine, even where cos(2π/n) is irrational.
            let sum = w.alpha::<Q>(n) + qi(n as i64) * w.beta::<Q>(n);
            assert_eq!(sum, qi(1), "{w:?}, n = {n}");
        }
        // Loop's formula, evaluated in f64 independently.
        let c = (2.0 * std::f64::consts::PI / n as f64).cos();
        let beta = (0.625 - (0.375 + 0.25 * c).powi(2)) / n as f64;
        let exact_beta = LoopWeights::Loop.beta::<Q>(n).to_f64();
        assert!((exact_beta - beta).abs() <= 1e-16, "n = {n}");
        // Loop's interval of tangent-plane continuity [PPB, §16.9, Ex. 3].
        if n >= 3 {
            for w in WEIGHTS {
                let alpha = w.alpha::<f64>(n);
                assert!(
                    -0.25 * c < alpha && alpha < 0.75 + 0.25 * c,
                    "{w:?}, n = {n}"
                );
            }
        }
    }
}

/// `b` equals `a` rotated by some offset.
fn is_rotation(a: &[P3], b: &[P3]) -> bool {
    a.len() == b.len() && (0..a.len()).any(|r| (0..a.len()).all(|k| a[(k + r) % a.len()] == b[k]))
}

#[test]
fn the_boundary_is_subdivided_as_a_closed_cubic_b_spline() {
    for seed in [1, 2, 3] {
        let mut mesh = exact(&fans(&irregular_disk(30, seed).unwrap()));
        for round in 1..=2 {
            for weights in WEIGHTS {
                let child = loop_subdivision_weighted(&mesh, 1, weights).unwrap();
                let (t, ct) = (mesh.topology(), child.topology());
                assert_eq!(ct.boundary_loop_count(), t.boundary_loop_count());
                for i in 0..t.boundary_loop_count() {
                    let polygon: Vec<P3> = t
                        .boundary_loop(i)
                        .iter()
                        .map(|&h| mesh.position(t.origin(h as usize)).clone())
                        .collect();
                    let oracle = lane_riesenfeld(&polygon, 3, 1, Topology::Closed).unwrap();
                    // The child loop through the coarse loop's vertices.
                    let first = t.origin(t.boundary_loop(i)[0] as usize);
                    let lp = (0..ct.boundary_loop_count())
                        .map(|k| ct.boundary_loop(k))
                        .find(|lp| lp.iter().any(|&h| ct.origin(h as usize) == first))
                        .unwrap();
                    let refined: Vec<P3> = lp
                        .iter()
                        .map(|&h| child.position(ct.origin(h as usize)).clone())
                        .collect();
                    assert!(
                        is_rotation(&oracle, &refined),
                        "seed {seed} round {round} loop {i}"
                    );
                }
            }
            mesh = loop_subdivision_weighted(&mesh, 1, LoopWeights::Loop).unwrap();
        }
    }
}

#[test]
fn limit_positions_are_fixed_by_a_round() {
    let meshes = [
        exact(&fans(&irregular_torus(6, 6, 11).unwrap())),
        exact(&fans(&irregular_disk(30, 4).unwrap())),
    ];
    for mesh in meshes {
        let valences: Vec<usize> = (0..mesh.vertex_count())
            .map(|v| mesh.topology().valence(v))
            .collect();
        assert!(
            valences.contains(&5) || valences.contains(&7),
            "an irrational cos(2π/n)"
        );
        for weights in WEIGHTS {
            let before = loop_limit_points(&mesh, weights).unwrap();
            let child = loop_subdivision_weighted(&mesh, 1, weights).unwrap();
            let after = loop_limit_points(&child, weights).unwrap();
            assert_eq!(after[..mesh.vertex_count()], before[..], "{weights:?}");
        }
    }
    // The regular value: v/2 + Σvᵢ/12, the quartic box spline at a grid point.
    let (mesh, grid) = triangular_torus(4, 5, 1);
    let limits = loop_limit_points(&mesh, LoopWeights::Loop).unwrap();
    for i in 0..4 {
        for j in 0..5 {
            let ring = [(1, 0), (0, 1), (1, 1), (3, 0), (0, 4), (3, 4)];
            let sum = ring.iter().fold(Point::zero(), |s: P3, &(di, dj)| {
                s + &grid[(i + di) % 4][(j + dj) % 5]
            });
            let expected = grid[i][j].clone() * q(1, 2) + &(sum * q(1, 12));
            assert_eq!(limits[i * 5 + j], expected, "({i}, {j})");
        }
    }
    let mut c = Counts::default();
    let torus = triangle_torus(4, 5).unwrap();
    loop_limit_points_with(&torus, LoopWeights::Loop, &mut c).unwrap();
    assert_eq!(c.arithmetic_operations, 20 + 2 * 60);
}

#[test]
fn bad_meshes_and_round_counts_are_named_errors() {
    let quads = quad_grid(2, 3).unwrap();
    let e = Error::Mesh(MeshError::NotATriangle {
        face: 0,
        corners: 4,
    });
    assert_eq!(loop_subdivision(&quads, 1).unwrap_err(), e);
    assert_eq!(loop_limit_points(&quads, LoopWeights::Loop).unwrap_err(), e);
    let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
    let mixed = PolygonMesh::new(
        vec![
            p(0., 0.),
            p(1., 0.),
            p(1., 1.),
            p(0., 1.),
            p(2., 0.),
            p(2., 1.),
        ],
        &[vec![0, 1, 2], vec![0, 2, 3], vec![1, 4, 5, 2]],
    )
    .unwrap();
    assert_eq!(
        loop_subdivision_weighted(&mixed, 1, LoopWeights::Warren).unwrap_err(),
        Error::Mesh(MeshError::NotATriangle {
            face: 2,
            corners: 4
        })
    );
    // Zero rounds of a quad mesh are still refused: the scheme does not apply.
    assert!(loop_subdivision_weighted(&quads, 0, LoopWeights::Loop).is_err());
    let torus = triangle_torus(4, 5).unwrap();
    for rounds in [12, 64, usize::MAX] {
        assert!(matches!(
            loop_subdivision(&torus, rounds),
            Err(Error::LimitExceeded { .. })
        ));
    }
    let huge = PolygonMesh::new(
        vec![
            Point::new([f64::MAX, 0.0, 0.0]),
            Point::new([f64::MAX, 1.0, 0.0]),
            Point::new([f64::MAX, 0.0, 1.0]),
        ],
        &[[0, 1, 2]],
    )
    .unwrap();
    assert!(matches!(
        loop_subdivision(&huge, 1),
        Err(Error::Overflow { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// Random disks: the result is a valid mesh of the stated size, the boundary its cubic
    /// B-spline refinement, and f64 agrees with the exact result to rounding.
    #[test]
    fn random_disks_subdivide_to_valid_meshes(seed in 0u64..1000, points in 8usize..40) {
        let mesh = fans(&irregular_disk(points, seed).unwrap());
        let child = loop_subdivision_weighted(&mesh, 2, LoopWeights::Loop).unwrap();
        prop_assert_eq!(child.topology().check(), Ok(()));
        prop_assert_eq!(child.face_count(), 16 * mesh.face_count());
        prop_assert_eq!(child.euler_characteristic(), 1);
        let exact_child = loop_subdivision_weighted(&exact(&mesh), 2, LoopWeights::Loop).unwrap();
        for (a, b) in child.positions().iter().zip(exact_child.positions()) {
            for k in 0..3 {
                prop_assert!((a[k] - b[k].to_f64()).abs() <= 1e-12 * (1.0 + a[k].abs()));
            }
        }
    }
}

/// OpenSubdiv's Loop refinement of `mesh` (`rounds` levels, boundary edges sharp and
/// boundary corners smooth, `EdgeOnly`: the crease rule (1, 6, 1)/8 at every boundary
/// vertex, as ours): the peer oracle.
fn opensubdiv_loop(mesh: &PolygonMesh<f64, 3>, rounds: usize) -> Vec<[f64; 3]> {
    use opensubdiv_rs::sdc::{SchemeType, VtxBoundaryInterpolation};
    crate::catmull_clark::opensubdiv_refine(
        mesh,
        SchemeType::Loop,
        VtxBoundaryInterpolation::EdgeOnly,
        rounds,
    )
}

#[test]
fn opensubdiv_makes_the_same_points() {
    // OpenSubdiv keeps its weights in f32: where β is not dyadic ours differ by about 1e-8.
    const CLOSE: f64 = 1e-6;
    for mesh in [
        triangle_torus(5, 6).unwrap(),
        fans(&irregular_torus(8, 8, 3).unwrap()),
        fans(&irregular_disk(50, 6).unwrap()),
    ] {
        let ours = loop_subdivision(&mesh, 2).unwrap();
        let theirs = opensubdiv_loop(&mesh, 2);
        crate::catmull_clark::assert_near_opensubdiv(&ours, theirs, CLOSE);
    }
}

#[test]
fn the_scheme_family_runs_loop() {
    let mesh = fans(&irregular_disk(20, 1).unwrap());
    assert_eq!(
        subdivide(&mesh, Scheme::Loop, 2).unwrap(),
        loop_subdivision_weighted(&mesh, 2, LoopWeights::Loop).unwrap()
    );
    assert_eq!("loop".parse::<Scheme>().unwrap(), Scheme::Loop);
}
