//! Catmull–Clark subdivision and the midpoint scheme M₃, exactly on rationals: against
//! bicubic uniform B-spline subdivision (the curve code's Lane–Riesenfeld algorithm on the
//! rows and then the columns) on tori and grids, against a brute-force implementation of the
//! textbook rules on irregular meshes with boundary, against a literal A²R for M₃; the
//! counts V, E, F and the Euler characteristic per round; the limit stencil unchanged by a
//! round; the operation counts; OpenSubdiv (`opensubdiv-rs`) as a peer oracle.

use crate::spline_common::{qi, Q};
use compgeo::count::Counts;
use compgeo::gen::{cube, irregular_disk, irregular_torus, quad_grid, quad_torus};
use compgeo::mesh::{
    catmull_clark, catmull_clark_limit, catmull_clark_limit_with, catmull_clark_with,
    midpoint_cubic, midpoint_cubic_with, subdivide, MeshTopology, PolygonMesh, Scheme,
};
use compgeo::spline::subdivision::{lane_riesenfeld, limit_points, Topology};
use compgeo::spline::{Point, Scalar};
use compgeo::Error;
use std::collections::BTreeMap;

type P3 = Point<Q, 3>;

/// `mesh` with random small integer coordinates (exact), from `seed`.
fn randomised(mesh: &PolygonMesh<f64, 3>, seed: u64) -> PolygonMesh<Q, 3> {
    // xorshift64*: small, seeded, enough for test data.
    let mut state = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = move || {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 33) % 41
    };
    let positions: Vec<P3> = (0..mesh.vertex_count())
        .map(|_| Point::new(std::array::from_fn(|_| qi(next() as i64 - 20))))
        .collect();
    mesh.with_positions(positions).unwrap()
}

/// The faces as vertex lists.
fn faces(t: &MeshTopology) -> Vec<Vec<usize>> {
    (0..t.face_count())
        .map(|f| t.face_vertices(f).iter().map(|&v| v as usize).collect())
        .collect()
}

/// Closed Lane–Riesenfeld (cubic, one round) of every row and then every column of an
/// m × n periodic grid `c[i][j]`: entry [a][b] is the point of fine index (a − 2, b − 2)
/// (the closed output b_i = Σ c_j α_{i−2j} puts vertex j at 2j + 2).
fn tensor_closed(c: &[Vec<P3>]) -> Vec<Vec<P3>> {
    let rows: Vec<Vec<P3>> = c
        .iter()
        .map(|row| lane_riesenfeld(row, 3, 1, Topology::Closed).unwrap())
        .collect();
    transpose(
        &transpose(&rows)
            .iter()
            .map(|col| lane_riesenfeld(col, 3, 1, Topology::Closed).unwrap())
            .collect::<Vec<_>>(),
    )
}

fn transpose(a: &[Vec<P3>]) -> Vec<Vec<P3>> {
    (0..a[0].len())
        .map(|j| a.iter().map(|row| row[j].clone()).collect())
        .collect()
}

/// The fine grid index of the child point of every coarse element of an m × n torus (or
/// grid, with `wrap` false): vertex (i, j) at (2i, 2j), the edge to (i, j + 1) at
/// (2i, 2j + 1), the face of cell (i, j) at (2i + 1, 2j + 1); keyed by child vertex.
fn fine_index(
    t: &MeshTopology,
    m: usize,
    n: usize,
    id: impl Fn(usize) -> (usize, usize),
) -> Vec<(i64, i64)> {
    let (v, e) = (t.vertex_count(), t.edge_count());
    let mut out = vec![(0, 0); v + e + t.face_count()];
    for (k, slot) in out.iter_mut().enumerate().take(v) {
        let (i, j) = id(k);
        *slot = (2 * i as i64, 2 * j as i64);
    }
    // The midpoint index of a step between neighbours, modulo the sides.
    let mid = |a: usize, b: usize, side: usize| -> i64 {
        if a == b {
            2 * a as i64
        } else if (a + 1) % side == b {
            2 * a as i64 + 1
        } else {
            2 * b as i64 + 1
        }
    };
    for edge in 0..e {
        let [a, b] = t.edge_vertices(edge);
        let ((ia, ja), (ib, jb)) = (id(a), id(b));
        out[v + edge] = (mid(ia, ib, m), mid(ja, jb, n));
    }
    for f in 0..t.face_count() {
        let (i, j) = id(t.face_vertices(f)[0] as usize);
        out[v + e + f] = (2 * i as i64 + 1, 2 * j as i64 + 1);
    }
    out
}

#[test]
fn one_round_on_a_torus_is_bicubic_b_spline_subdivision() {
    for (m, n, seed) in [(3, 4, 1), (5, 3, 2), (6, 7, 3)] {
        let coarse = randomised(&quad_torus(m, n).unwrap(), seed);
        let grid: Vec<Vec<P3>> = (0..m)
            .map(|i| (0..n).map(|j| coarse.position(i * n + j).clone()).collect())
            .collect();
        let tensor = tensor_closed(&grid);
        let fine = catmull_clark(&coarse, 1).unwrap();
        let index = fine_index(coarse.topology(), m, n, |k| (k / n, k % n));
        for (child, &(a, b)) in index.iter().enumerate() {
            let (a, b) = (
                (a + 2).rem_euclid(2 * m as i64) as usize,
                (b + 2).rem_euclid(2 * n as i64) as usize,
            );
            assert_eq!(
                fine.position(child),
                &tensor[a][b],
                "{m}×{n}, child {child}"
            );
        }
        // All valences 4: the midpoint scheme is the same.
        assert_eq!(midpoint_cubic(&coarse, 1).unwrap(), fine);
    }
}

#[test]
fn on_a_grid_the_interior_is_bicubic_and_the_boundary_cubic() {
    let (rows, cols) = (4, 5);
    let coarse = randomised(&quad_grid(rows, cols).unwrap(), 7);
    let w = cols + 1;
    let grid: Vec<Vec<P3>> = (0..=rows)
        .map(|i| {
            (0..=cols)
                .map(|j| coarse.position(i * w + j).clone())
                .collect()
        })
        .collect();
    // Open Lane–Riesenfeld keeps fine indices 1, …, 2n − 3 of a polygon of n points.
    let open = |p: &[P3]| lane_riesenfeld(p, 3, 1, Topology::Open).unwrap();
    let rows_done: Vec<Vec<P3>> = grid.iter().map(|r| open(r)).collect();
    let tensor = transpose(
        &transpose(&rows_done)
            .iter()
            .map(|c| open(c))
            .collect::<Vec<_>>(),
    );
    let fine = catmull_clark(&coarse, 1).unwrap();
    let index = fine_index(coarse.topology(), usize::MAX, usize::MAX, |k| {
        (k / w, k % w)
    });
    let (last_a, last_b) = (2 * rows as i64, 2 * cols as i64);
    let mut compared = 0;
    for (child, &(a, b)) in index.iter().enumerate() {
        let p = fine.position(child);
        if (1..last_a).contains(&a) && (1..last_b).contains(&b) {
            assert_eq!(p, &tensor[a as usize - 1][b as usize - 1], "child {child}");
            compared += 1;
        }
        // The four sides are cubic B-spline curves of the boundary rows and columns.
        let side = |line: Vec<P3>, k: i64| open(&line)[k as usize - 1].clone();
        if a == 0 && (1..last_b).contains(&b) {
            assert_eq!(p, &side(grid[0].clone(), b));
        }
        if a == last_a && (1..last_b).contains(&b) {
            assert_eq!(p, &side(grid[rows].clone(), b));
        }
        if b == 0 && (1..last_a).contains(&a) {
            assert_eq!(p, &side(transpose(&grid)[0].clone(), a));
        }
        if b == last_b && (1..last_a).contains(&a) {
            assert_eq!(p, &side(transpose(&grid)[cols].clone(), a));
        }
    }
    assert_eq!(compared, (2 * rows - 1) * (2 * cols - 1));
    // The corners stay.
    for k in [0, cols, rows * w, rows * w + cols] {
        assert_eq!(fine.position(k), coarse.position(k));
    }
}

/// The textbook rules written out with brute-force adjacency (an edge map from vertex
/// pairs to faces), in the numbering of `catmull_clark`: vertex points, edge points in the
/// topology's edge order, face points.
fn brute_force_round(mesh: &PolygonMesh<Q, 3>, midpoint: bool) -> Vec<P3> {
    let t = mesh.topology();
    let p = mesh.positions();
    let faces = faces(t);
    let avg = |pts: &[P3]| {
        let mut s = P3::zero();
        for q in pts {
            s += q;
        }
        s * Q::from_ratio(1, pts.len() as i64)
    };
    let centroid: Vec<P3> = faces
        .iter()
        .map(|f| avg(&f.iter().map(|&v| p[v].clone()).collect::<Vec<_>>()))
        .collect();
    let mut edge_faces: BTreeMap<(usize, usize), Vec<usize>> = BTreeMap::new();
    for (fi, f) in faces.iter().enumerate() {
        for k in 0..f.len() {
            let (a, b) = (f[k], f[(k + 1) % f.len()]);
            edge_faces.entry((a.min(b), a.max(b))).or_default().push(fi);
        }
    }
    let boundary_nbrs = |v: usize| -> Vec<usize> {
        edge_faces
            .iter()
            .filter(|(&(a, b), fs)| fs.len() == 1 && (a == v || b == v))
            .map(|(&(a, b), _)| if a == v { b } else { a })
            .collect()
    };
    let mut out = Vec::new();
    for v in 0..p.len() {
        let around: Vec<usize> = (0..faces.len())
            .filter(|&f| faces[f].contains(&v))
            .collect();
        let nbrs: Vec<usize> = edge_faces
            .keys()
            .filter(|&&(a, b)| a == v || b == v)
            .map(|&(a, b)| if a == v { b } else { a })
            .collect();
        let bn = boundary_nbrs(v);
        out.push(if !bn.is_empty() {
            if around.len() == 1 {
                p[v].clone()
            } else {
                (p[bn[0]].clone() + &p[bn[1]] + &(p[v].clone() * qi(6))) * Q::from_ratio(1, 8)
            }
        } else {
            let n = nbrs.len() as i64;
            let q = avg(&around
                .iter()
                .map(|&f| centroid[f].clone())
                .collect::<Vec<_>>());
            let r = avg(&nbrs
                .iter()
                .map(|&w| (p[v].clone() + &p[w]) * Q::from_ratio(1, 2))
                .collect::<Vec<_>>());
            if midpoint {
                // A²R: v/4 + R/2 + Q/4.
                p[v].clone() * Q::from_ratio(1, 4)
                    + &(r * Q::from_ratio(1, 2))
                    + &(q * Q::from_ratio(1, 4))
            } else {
                (q + &(r * qi(2)) + &(p[v].clone() * qi(n - 3))) * Q::from_ratio(1, n)
            }
        });
    }
    for e in 0..t.edge_count() {
        let [a, b] = t.edge_vertices(e);
        let fs = &edge_faces[&(a.min(b), a.max(b))];
        let mid = (p[a].clone() + &p[b]) * Q::from_ratio(1, 2);
        out.push(match fs.len() {
            1 => mid,
            _ if midpoint => {
                // The average of the four quadrilaterals of RC at the midpoint.
                let mut s = P3::zero();
                for &f in fs {
                    let face = &faces[f];
                    for &x in &[a, b] {
                        let k = face.iter().position(|&y| y == x).unwrap();
                        let len = face.len();
                        let other = if face[(k + 1) % len] == a || face[(k + 1) % len] == b {
                            face[(k + len - 1) % len]
                        } else {
                            face[(k + 1) % len]
                        };
                        let m2 = (p[x].clone() + &p[other]) * Q::from_ratio(1, 2);
                        s += &((p[x].clone() + &mid + &centroid[f] + &m2) * Q::from_ratio(1, 4));
                    }
                }
                s * Q::from_ratio(1, 4)
            }
            _ => (p[a].clone() + &p[b] + &centroid[fs[0]] + &centroid[fs[1]]) * Q::from_ratio(1, 4),
        });
    }
    out.extend(centroid);
    out
}

#[test]
fn irregular_meshes_follow_the_textbook_rules_exactly() {
    let meshes = [
        randomised(&irregular_torus(6, 6, 5).unwrap(), 1),
        randomised(&irregular_disk(30, 2).unwrap(), 2),
        randomised(&cube(), 3),
    ];
    for mesh in &meshes {
        let fine = catmull_clark(mesh, 1).unwrap();
        assert_eq!(fine.positions(), &brute_force_round(mesh, false)[..]);
        let mid = midpoint_cubic(mesh, 1).unwrap();
        assert_eq!(mid.positions(), &brute_force_round(mesh, true)[..]);
        assert_eq!(mid.topology(), fine.topology());
        // A second round starts from quadrilaterals.
        let twice = catmull_clark(mesh, 2).unwrap();
        assert_eq!(twice.positions(), &brute_force_round(&fine, false)[..]);
    }
}

#[test]
fn counts_per_round_and_the_euler_characteristic() {
    let meshes = [
        irregular_torus(8, 6, 9).unwrap(),
        irregular_disk(50, 4).unwrap(),
        cube(),
        quad_grid(3, 2).unwrap(),
    ];
    for mesh in &meshes {
        let chi = mesh.euler_characteristic();
        let mut current = mesh.clone();
        for round in 1..=3 {
            let t = current.topology();
            let (v, e, f, h) = (
                t.vertex_count(),
                t.edge_count(),
                t.face_count(),
                t.halfedge_count(),
            );
            let next = catmull_clark(&current, 1).unwrap();
            let nt = next.topology();
            assert_eq!(
                (nt.vertex_count(), nt.edge_count(), nt.face_count()),
                (v + e + f, 2 * e + h, h)
            );
            assert!(nt.is_quad_mesh());
            if round > 1 {
                assert_eq!(nt.face_count(), 4 * f);
            }
            assert_eq!(next.euler_characteristic(), chi);
            assert_eq!(nt.boundary_loop_count(), t.boundary_loop_count());
            nt.check().unwrap();
            // The arrays are those of validating the child's face lists from scratch.
            let rebuilt = PolygonMesh::new(next.positions().to_vec(), &faces(nt)).unwrap();
            assert_eq!(rebuilt.topology().twins(), nt.twins());
            assert_eq!(rebuilt.topology().corners(), nt.corners());
            current = next;
        }
        assert_eq!(catmull_clark(mesh, 3).unwrap(), current);
    }
}

#[test]
fn operation_counts_are_as_documented() {
    for mesh in [
        irregular_disk(40, 6).unwrap(),
        irregular_torus(6, 8, 2).unwrap(),
        quad_grid(2, 3).unwrap(),
    ] {
        let t = mesh.topology();
        let boundary_vertex = |v: usize| t.is_boundary_vertex(v);
        let vi = (0..t.vertex_count())
            .filter(|&v| !boundary_vertex(v))
            .count();
        let vb = (0..t.vertex_count())
            .filter(|&v| boundary_vertex(v) && t.valence(v) > 2)
            .count();
        let eb = (0..t.edge_count())
            .filter(|&e| t.is_boundary_edge(e))
            .count();
        let ei = t.edge_count() - eb;
        let h = t.halfedge_count();
        let mut c = Counts::default();
        catmull_clark_with(&mesh, 1, &mut c).unwrap();
        assert_eq!(
            c.arithmetic_operations as usize,
            3 * h + 3 * vi + 4 * vb + 4 * ei + 2 * eb
        );
        let mut c = Counts::default();
        midpoint_cubic_with(&mesh, 1, &mut c).unwrap();
        assert_eq!(
            c.arithmetic_operations as usize,
            3 * h + 3 * vi + 4 * vb + 10 * ei + 2 * eb
        );
        // The limit stencil after one round (a quadrilateral mesh).
        let quads = catmull_clark(&mesh, 1).unwrap();
        let qt = quads.topology();
        let expected: usize = (0..qt.vertex_count())
            .map(|v| match (qt.is_boundary_vertex(v), qt.valence(v)) {
                (false, n) => 2 * n + 5,
                (true, 2) => 0,
                (true, _) => 4,
            })
            .sum();
        let mut c = Counts::default();
        catmull_clark_limit_with(&quads, &mut c).unwrap();
        assert_eq!(c.arithmetic_operations as usize, expected);
    }
}

#[test]
fn the_limit_stencil_is_unchanged_by_a_round() {
    let mut valences = std::collections::BTreeSet::new();
    for mesh in [
        randomised(&irregular_torus(6, 6, 8).unwrap(), 4),
        randomised(&irregular_disk(40, 3).unwrap(), 5),
        randomised(&cube(), 6),
        randomised(&quad_grid(3, 4).unwrap(), 7),
    ] {
        let quads = catmull_clark(&mesh, 1).unwrap();
        let before = catmull_clark_limit(&quads).unwrap();
        let finer = catmull_clark(&quads, 1).unwrap();
        let after = catmull_clark_limit(&finer).unwrap();
        // Child vertex v is the vertex point of v: its limit is v's.
        assert_eq!(&after[..before.len()], &before[..]);
        valences.extend((0..quads.vertex_count()).map(|v| quads.topology().valence(v)));
    }
    // Extraordinary vertices of valence 3, 5 and 6 were covered, inside and on the boundary.
    assert!(
        [2, 3, 4, 5, 6].iter().all(|n| valences.contains(n)),
        "{valences:?}"
    );
    assert!(matches!(
        catmull_clark_limit(&irregular_torus(6, 6, 8).unwrap()),
        Err(Error::InvalidParameter { name: "mesh", .. })
    ));
}

#[test]
fn the_limit_on_a_torus_is_the_tensor_curve_limit_and_rounds_converge_to_it() {
    let (m, n) = (5, 6);
    let coarse = randomised(&quad_torus(m, n).unwrap(), 11);
    let grid: Vec<Vec<P3>> = (0..m)
        .map(|i| (0..n).map(|j| coarse.position(i * n + j).clone()).collect())
        .collect();
    let rows: Vec<Vec<P3>> = grid
        .iter()
        .map(|r| limit_points(r, 3, Topology::Closed).unwrap())
        .collect();
    let tensor = transpose(
        &transpose(&rows)
            .iter()
            .map(|c| limit_points(c, 3, Topology::Closed).unwrap())
            .collect::<Vec<_>>(),
    );
    let limit = catmull_clark_limit(&coarse).unwrap();
    for i in 0..m {
        for j in 0..n {
            assert_eq!(limit[i * n + j], tensor[i][j]);
        }
    }
    // At an extraordinary vertex (the cube's corners) the rounds approach the limit
    // geometrically.
    let c = cube();
    let target = catmull_clark_limit(&catmull_clark(&c, 1).unwrap()).unwrap()[0];
    let mut last = f64::INFINITY;
    for rounds in 1..=6 {
        let p = catmull_clark(&c, rounds).unwrap().position(0).to_f64();
        let d = (p - target).norm_squared().sqrt();
        assert!(d < last / 2.0, "round {rounds}: {d} after {last}");
        last = d;
    }
    assert!(last < 1e-3);
}

#[test]
fn rounds_beyond_the_limit_are_refused_and_the_scheme_enum_dispatches() {
    let e = catmull_clark(&cube(), 20).unwrap_err();
    assert!(
        matches!(
            e,
            Error::LimitExceeded {
                limit: "MAX_MESH_CORNERS",
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(catmull_clark(&cube(), 0).unwrap(), cube());
    for scheme in Scheme::ALL {
        let mesh = irregular_disk(20, 1).unwrap();
        let direct = match scheme {
            Scheme::CatmullClark => catmull_clark(&mesh, 2).unwrap(),
            Scheme::MidpointCubic => midpoint_cubic(&mesh, 2).unwrap(),
            _ => continue,
        };
        assert_eq!(subdivide(&mesh, scheme, 2).unwrap(), direct);
    }
}

/// OpenSubdiv's refinement of `mesh`: `rounds` levels of `scheme` with the boundary rule
/// `boundary`; the peer oracle of Catmull–Clark here and of Loop in `mesh_loop`.
pub fn opensubdiv_refine(
    mesh: &PolygonMesh<f64, 3>,
    scheme: opensubdiv_rs::sdc::SchemeType,
    boundary: opensubdiv_rs::sdc::VtxBoundaryInterpolation,
    rounds: usize,
) -> Vec<[f64; 3]> {
    use opensubdiv_rs::far::{
        PrimvarRefiner, TopologyDescriptor, TopologyRefinerFactory, UniformOptions,
    };
    use opensubdiv_rs::sdc::Options;
    let t = mesh.topology();
    let sizes: Vec<usize> = (0..t.face_count()).map(|f| t.face_size(f)).collect();
    let descriptor = TopologyDescriptor::new(t.vertex_count(), &sizes, t.corners());
    let options = Options::default().with_vtx_boundary_interpolation(boundary);
    let mut refiner = TopologyRefinerFactory::create(descriptor, scheme, options).unwrap();
    refiner.refine_uniform(UniformOptions::new(rounds));
    let primvars = PrimvarRefiner::new(&refiner);
    let mut points: Vec<[f64; 3]> = mesh.positions().iter().map(|p| p.0).collect();
    for level in 1..=rounds {
        let mut refined = vec![[0.0; 3]; refiner.level(level).num_vertices()];
        primvars.interpolate(level, &points, &mut refined);
        points = refined;
    }
    points
}

/// Asserts that `ours` and OpenSubdiv's points `theirs` are the same set, each point of ours
/// within `close` of one of theirs in every coordinate.
pub fn assert_near_opensubdiv(ours: &PolygonMesh<f64, 3>, mut theirs: Vec<[f64; 3]>, close: f64) {
    assert_eq!(ours.vertex_count(), theirs.len());
    theirs.sort_by(|p, q| p[0].total_cmp(&q[0]));
    for p in ours.positions() {
        let p = p.0;
        let from = theirs.partition_point(|q| q[0] < p[0] - close);
        assert!(
            theirs[from..]
                .iter()
                .take_while(|q| q[0] <= p[0] + close)
                .any(|q| (0..3).all(|i| (p[i] - q[i]).abs() < close)),
            "no OpenSubdiv point near {p:?}"
        );
    }
}

/// OpenSubdiv's Catmull–Clark (sharp boundaries with pinned corners, the rules of
/// `catmull_clark`).
fn opensubdiv(mesh: &PolygonMesh<f64, 3>, rounds: usize) -> Vec<[f64; 3]> {
    use opensubdiv_rs::sdc::{SchemeType, VtxBoundaryInterpolation};
    opensubdiv_refine(
        mesh,
        SchemeType::Catmark,
        VtxBoundaryInterpolation::EdgeAndCorner,
        rounds,
    )
}

#[test]
fn opensubdiv_makes_the_same_points() {
    // OpenSubdiv keeps its weights in f32: 1/3, 1/5, ... differ from ours by about 1e-7.
    const CLOSE: f64 = 1e-6;
    for mesh in [
        irregular_disk(60, 8).unwrap(),
        irregular_torus(8, 8, 3).unwrap(),
        quad_grid(3, 4).unwrap(),
        cube(),
    ] {
        let ours = catmull_clark(&mesh, 2).unwrap();
        let theirs = opensubdiv(&mesh, 2);
        assert_near_opensubdiv(&ours, theirs, CLOSE);
    }
}
