//! Doo–Sabin subdivision (the midpoint scheme M₂ = 𝒜𝓡 of [PPB, §16.1]), exactly in
//! rationals: every new point is the centroid of its quadrilateral of 𝓡, built here from the
//! course's definitions of 𝓡 and 𝒜, and the weights form with the erratum b = 2 + 4/m
//! (whose rows sum to 1; the printed b = 4 + 4/m gives 5/4); on a regular quadrilateral grid,
//! closed and open, every round is biquadratic tensor Lane–Riesenfeld subdivision
//! (`ControlNet::lane_riesenfeld`); F′ = F + E + V on closed meshes and the stated counts
//! with a boundary, the Euler characteristic, the half-edge invariants; face centroids kept;
//! bad input gets named errors.

use crate::mesh_loop::exact;
use crate::spline_common::{q, qi, Q};
use crate::surface_subdivision::lattice_net;
use compgeo::count::Counts;
use compgeo::gen::{cube, irregular_disk, irregular_torus, quad_torus};
use compgeo::mesh::{
    doo_sabin, doo_sabin_limit_points, doo_sabin_weights, doo_sabin_with, subdivide, PolygonMesh,
    Scheme,
};
use compgeo::spline::subdivision::Topology;
use compgeo::spline::Point;
use compgeo::surface::ControlNet;
use compgeo::Error;

type P3 = Point<Q, 3>;

#[test]
fn the_weights_sum_to_one_with_the_erratum() {
    assert_eq!(
        doo_sabin_weights::<Q>(4).unwrap(),
        [q(9, 16), q(3, 16), q(1, 16), q(3, 16)]
    );
    for m in 3..=40i64 {
        let w = doo_sabin_weights::<Q>(m as usize).unwrap();
        assert_eq!(w.iter().fold(qi(0), |a, b| a + b), qi(1), "m = {m}");
        // a = 8 + 4/m, b = 2 + 4/m, the rest 4/m, over 16.
        assert_eq!(w[0], (qi(8) + q(4, m)) / qi(16));
        assert_eq!(w[1], (qi(2) + q(4, m)) / qi(16));
        // The printed b = 4 + 4/m [PPB, §16.4] would make the row sum 20/16.
        let printed = w[0].clone() + (qi(4) + q(4, m)) / qi(8) + q(4, m) * qi(m - 3) / qi(16);
        assert_eq!(printed, q(5, 4), "m = {m}");
    }
    assert!(matches!(
        doo_sabin_weights::<f64>(2),
        Err(Error::InvalidParameter {
            name: "corners",
            ..
        })
    ));
}

/// 𝒜𝓡 from the definitions of [PPB, §16.1]: 𝓡 joins each corner vᵢ of a face to its edges'
/// midpoints and the face's centroid c (quadrilateral vᵢ, ½(vᵢ + vᵢ₊₁), c, ½(vᵢ₋₁ + vᵢ)), and
/// 𝒜 puts a point at the centroid of each face of 𝓡's mesh: one per coarse corner.
fn averaged_refinement(mesh: &PolygonMesh<Q, 3>) -> Vec<P3> {
    let half = q(1, 2);
    let mut out = Vec::new();
    for f in 0..mesh.face_count() {
        let v: Vec<P3> = mesh
            .face_vertices(f)
            .iter()
            .map(|&i| mesh.position(i as usize).clone())
            .collect();
        let m = v.len();
        let c = v.iter().fold(Point::zero(), |s: P3, p| s + p) * q(1, m as i64);
        for i in 0..m {
            let (prev, next) = (&v[(i + m - 1) % m], &v[(i + 1) % m]);
            let quad = [
                v[i].clone(),
                (v[i].clone() + next) * &half,
                c.clone(),
                (prev.clone() + &v[i]) * &half,
            ];
            out.push(quad.iter().fold(Point::zero(), |s: P3, p| s + p) * q(1, 4));
        }
    }
    out
}

/// Meshes of every kind: closed and bounded, faces of 3 to 6 corners, valence 2 to 6.
fn meshes() -> Vec<(&'static str, PolygonMesh<f64, 3>)> {
    let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    let pillow = PolygonMesh::new(
        vec![p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)],
        &[[0, 1, 2], [0, 2, 1]],
    )
    .unwrap();
    let pentagon = PolygonMesh::new(
        vec![
            p(0., 0., 0.),
            p(2., 0., 0.),
            p(3., 2., 1.),
            p(1., 3., 0.),
            p(-1., 2., 2.),
        ],
        &[[0, 1, 2, 3, 4]],
    )
    .unwrap();
    vec![
        ("cube", cube()),
        ("pillow", pillow),
        ("pentagon", pentagon),
        ("quad torus", quad_torus(4, 5).unwrap()),
        ("irregular torus", irregular_torus(6, 6, 3).unwrap()),
        ("irregular disk", irregular_disk(30, 5).unwrap()),
    ]
}

#[test]
fn every_new_point_is_the_centroid_of_its_refined_quadrilateral() {
    for (name, mesh) in meshes() {
        let mut mesh = exact(&mesh);
        for round in 1..=2 {
            let child = doo_sabin(&mesh, 1).unwrap();
            assert_eq!(
                child.positions(),
                &averaged_refinement(&mesh)[..],
                "{name} {round}"
            );
            // The weights form gives the same points.
            let t = mesh.topology();
            for f in 0..mesh.face_count() {
                let corners = t.face_vertices(f);
                let m = corners.len();
                let w = doo_sabin_weights::<Q>(m).unwrap();
                for i in 0..m {
                    let p = (0..m).fold(Point::zero(), |s: P3, k| {
                        s + &(mesh.position(corners[(i + k) % m] as usize).clone() * &w[k])
                    });
                    let h = t.face_halfedges(f).start + i;
                    assert_eq!(child.position(h), &p, "{name} face {f} corner {i}");
                }
            }
            mesh = child;
        }
    }
}

/// Which child point of tensor Lane–Riesenfeld of degree 2 the corner at index a of the
/// cell starting at index i is: in one round b_{2i+2} = (3cᵢ + cᵢ₊₁)/4 and
/// b_{2i+3} = (cᵢ + 3cᵢ₊₁)/4 ([PPB, §8.4]'s indexing), shifted by −2 on an open direction.
fn lr_index(i: usize, a: usize, closed_len: Option<usize>) -> usize {
    let full = 2 * i + 2 + usize::from(a != i);
    match closed_len {
        Some(len) => full % (2 * len),
        None => full - 2,
    }
}

/// Checks that one Doo–Sabin round of a quad grid mesh is the biquadratic tensor round of
/// its net; `index` gives each mesh vertex's grid point; returns the child's indices.
fn check_grid_round(
    mesh: &PolygonMesh<Q, 3>,
    net: &ControlNet<Q, 3>,
    index: &[(usize, usize)],
    closed: bool,
) -> (PolygonMesh<Q, 3>, ControlNet<Q, 3>, Vec<(usize, usize)>) {
    let (m, n) = (net.rows(), net.columns());
    let topology = if closed {
        Topology::Closed
    } else {
        Topology::Open
    };
    let child = doo_sabin(mesh, 1).unwrap();
    let fine = net
        .lane_riesenfeld((2, 2), 1, (topology, topology))
        .unwrap();
    assert_eq!(child.vertex_count(), fine.rows() * fine.columns());
    let wrap = |a: usize, len: usize| if closed { a % len } else { a };
    let mut child_index = vec![(0, 0); child.vertex_count()];
    for f in 0..mesh.face_count() {
        let cell: Vec<(usize, usize)> = mesh
            .face_vertices(f)
            .iter()
            .map(|&v| index[v as usize])
            .collect();
        // The cell's first corner: the one from which the others are +e₁, +e₁ + e₂, +e₂.
        let (i, j) = *cell
            .iter()
            .find(|&&(i, j)| {
                let mut want = [
                    (i, j),
                    (wrap(i + 1, m), j),
                    (wrap(i + 1, m), wrap(j + 1, n)),
                    (i, wrap(j + 1, n)),
                ];
                let mut have = cell.clone();
                want.sort_unstable();
                have.sort_unstable();
                have == want
            })
            .expect("a grid cell");
        for (k, &(a, b)) in cell.iter().enumerate() {
            let len = |l: usize| closed.then_some(l);
            let (ci, cj) = (lr_index(i, a, len(m)), lr_index(j, b, len(n)));
            let h = mesh.topology().face_halfedges(f).start + k;
            assert_eq!(child.position(h), fine.get(ci, cj), "face {f} corner {k}");
            child_index[h] = (ci, cj);
        }
    }
    (child, fine, child_index)
}

#[test]
fn doo_sabin_on_a_regular_grid_is_biquadratic_tensor_subdivision() {
    for closed in [true, false] {
        let (m, n) = if closed { (4, 5) } else { (5, 4) };
        let net = lattice_net(m, n, 7);
        let id = |i: usize, j: usize| (i % m) * n + j % n;
        let mut faces = Vec::new();
        let (cells_i, cells_j) = if closed { (m, n) } else { (m - 1, n - 1) };
        for i in 0..cells_i {
            for j in 0..cells_j {
                faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
        let mut mesh = PolygonMesh::new(net.points().to_vec(), &faces).unwrap();
        let mut net = net;
        let mut index: Vec<(usize, usize)> = (0..m * n).map(|v| (v / n, v % n)).collect();
        for _ in 1..=2 {
            (mesh, net, index) = check_grid_round(&mesh, &net, &index, closed);
        }
    }
}

#[test]
fn counts_euler_characteristic_and_half_edges_per_round() {
    for (name, start) in meshes() {
        let mut mesh = start.clone();
        for round in 1..=3 {
            let t = mesh.topology();
            let inner_edges = (0..mesh.edge_count())
                .filter(|&e| !t.is_boundary_edge(e))
                .count();
            let inner: Vec<usize> = (0..mesh.vertex_count())
                .filter(|&v| !t.is_boundary_vertex(v))
                .collect();
            let folded = inner.iter().filter(|&&v| t.valence(v) == 2).count();
            let mut c = Counts::default();
            let child = doo_sabin_with(&mesh, 1, &mut c).unwrap();
            let h = t.halfedge_count();
            assert_eq!(
                (child.vertex_count(), child.edge_count(), child.face_count()),
                (
                    h,
                    2 * inner_edges + h - folded,
                    mesh.face_count() + inner_edges + inner.len() - folded
                ),
                "{name}, round {round}"
            );
            if t.is_closed() && folded == 0 {
                let (v, e, f) = (mesh.vertex_count(), mesh.edge_count(), mesh.face_count());
                assert_eq!(child.face_count(), f + e + v);
            }
            assert_eq!(c.arithmetic_operations, 5 * h as u64);
            assert_eq!(
                child.euler_characteristic(),
                start.euler_characteristic(),
                "{name}"
            );
            assert_eq!(child.topology().check(), Ok(()), "{name}, round {round}");
            assert!((0..child.face_count()).all(|g| child.topology().face_size(g) >= 3));
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
    }
    // After the first round every inner vertex has valence 4: closed meshes grow by 4.
    let once = doo_sabin(&cube(), 1).unwrap();
    let twice = doo_sabin(&once, 1).unwrap();
    assert_eq!(
        twice.topology().halfedge_count(),
        4 * once.topology().halfedge_count()
    );
}

#[test]
fn face_centroids_are_kept() {
    for (name, mesh) in meshes() {
        let mesh = exact(&mesh);
        let centroids = doo_sabin_limit_points(&mesh).unwrap();
        assert_eq!(centroids.len(), mesh.face_count());
        let twice = doo_sabin(&mesh, 2).unwrap();
        let later = doo_sabin_limit_points(&twice).unwrap();
        assert_eq!(later[..mesh.face_count()], centroids[..], "{name}");
    }
}

#[test]
fn bad_round_counts_and_overflow_are_named_errors() {
    let torus = quad_torus(4, 5).unwrap();
    for rounds in [30, 64, usize::MAX] {
        assert!(matches!(
            doo_sabin(&torus, rounds),
            Err(Error::LimitExceeded { .. })
        ));
    }
    // A single face does not grow; its rounds are bounded all the same.
    let p = |x: f64| Point::new([x, 0.0, 1.0]);
    let one = PolygonMesh::new(vec![p(0.0), p(1.0), p(3.0)], &[[0, 1, 2]]).unwrap();
    assert!(matches!(
        doo_sabin(&one, usize::MAX),
        Err(Error::LimitExceeded { .. })
    ));
    assert_eq!(doo_sabin(&one, 10).unwrap().face_count(), 1);
    let huge = PolygonMesh::new(
        vec![
            Point::new([f64::MAX, 0.0, 0.0]),
            Point::new([f64::MAX, 1.0, 0.0]),
            Point::new([f64::MAX, 0.0, 1.0]),
        ],
        &[[0, 1, 2]],
    )
    .unwrap();
    assert!(matches!(doo_sabin(&huge, 1), Err(Error::Overflow { .. })));
}

#[test]
fn the_scheme_family_runs_doo_sabin() {
    let mesh = irregular_disk(20, 1).unwrap();
    assert_eq!(
        subdivide(&mesh, Scheme::DooSabin, 2).unwrap(),
        doo_sabin(&mesh, 2).unwrap()
    );
    assert_eq!("doo-sabin".parse::<Scheme>().unwrap(), Scheme::DooSabin);
}
