//! Polygon meshes: validation (every violation rejected with the face or vertex named, and a
//! brute-force manifold checker agreeing on random face soups), the half-edge arrays against
//! brute-force adjacency, one-rings and boundary loops, the Euler characteristic of the
//! generated meshes, and OBJ reading and writing (round trips, `tobj` as a peer reader, a
//! named error for every malformed line, no panic on arbitrary bytes).

use compgeo::gen::{
    cube, irregular_disk, irregular_torus, mesh, quad_grid, quad_torus, triangle_grid,
    triangle_torus, MeshKind,
};
use compgeo::mesh::{read_obj, write_obj, MeshError, ObjProblem, PolygonMesh};
use compgeo::spline::Point;
use compgeo::Error;
use num_rational::BigRational;
use proptest::prelude::*;
use std::collections::{BTreeMap, BTreeSet};

type P = Point<f64, 3>;

fn p(x: f64, y: f64, z: f64) -> P {
    Point::new([x, y, z])
}

/// `n` vertices at distinct integer points (the positions play no part in validation).
fn verts(n: usize) -> Vec<P> {
    (0..n).map(|i| p(i as f64, (i * i) as f64, 0.0)).collect()
}

fn mesh_err(n: usize, faces: &[Vec<usize>]) -> MeshError {
    match PolygonMesh::new(verts(n), faces) {
        Err(Error::Mesh(e)) => e,
        other => panic!("expected a mesh error, got {other:?}"),
    }
}

#[test]
fn every_violation_is_rejected_with_the_face_named() {
    let sq = || vec![vec![0, 1, 2], vec![0, 2, 3]];
    assert_eq!(PolygonMesh::new(verts(4), &sq()).unwrap().face_count(), 2);

    assert_eq!(
        mesh_err(4, &[vec![0, 1, 2], vec![0, 2, 4]]),
        MeshError::VertexOutOfRange {
            face: 1,
            vertex: 4,
            vertices: 4
        }
    );
    assert_eq!(
        mesh_err(4, &[vec![0, 1, 2], vec![2, 3]]),
        MeshError::TooFewCorners {
            face: 1,
            corners: 2
        }
    );
    assert_eq!(
        mesh_err(5, &[vec![0, 1, 2], vec![0, 2, 3, 4, 2]]),
        MeshError::RepeatedVertex { face: 1, vertex: 2 }
    );
    // Three triangles on the edge 0 – 1 (two of them consistent with the first).
    assert_eq!(
        mesh_err(5, &[vec![0, 1, 2], vec![1, 0, 3], vec![1, 0, 4]]),
        MeshError::NonManifoldEdge {
            face: 2,
            from: 1,
            to: 0
        }
    );
    // The second triangle runs 0 → 2 like the first.
    assert_eq!(
        mesh_err(4, &[vec![0, 1, 2], vec![2, 0, 3]]),
        MeshError::InconsistentOrientation {
            face: 1,
            other: 0,
            from: 2,
            to: 0
        }
    );
    // A bow tie: two triangles meeting only at vertex 0.
    assert_eq!(
        mesh_err(5, &[vec![0, 1, 2], vec![0, 3, 4]]),
        MeshError::NonManifoldVertex { vertex: 0, face: 1 }
    );
    // Two closed fans at vertex 0: two tetrahedra glued at a vertex.
    let tet = |a: usize, b: usize, c: usize, d: usize| {
        vec![vec![a, c, b], vec![a, b, d], vec![b, c, d], vec![c, a, d]]
    };
    let mut two = tet(0, 1, 2, 3);
    two.extend(tet(0, 4, 5, 6));
    assert!(PolygonMesh::new(verts(4), &tet(0, 1, 2, 3)).is_ok());
    assert!(matches!(
        mesh_err(7, &two),
        MeshError::NonManifoldVertex {
            vertex: 0,
            face: 4 | 5 | 7
        }
    ));
    assert_eq!(mesh_err(5, &sq()), MeshError::IsolatedVertex { vertex: 4 });
    // Positions, emptiness, offsets.
    let mut bad = verts(4);
    bad[3] = p(0.0, f64::NAN, 0.0);
    assert!(matches!(
        PolygonMesh::new(bad, &sq()),
        Err(Error::NonFinite { index: 3, .. })
    ));
    let none: [[usize; 3]; 0] = [];
    assert_eq!(
        PolygonMesh::new(verts(3), &none),
        Err(Error::Empty {
            what: "polygon mesh"
        })
    );
    assert!(matches!(
        PolygonMesh::from_offsets(verts(3), &[0, 2], &[0, 1, 2]),
        Err(Error::InvalidParameter {
            name: "face offsets",
            ..
        })
    ));
    // The messages name the face.
    let e = PolygonMesh::new(verts(5), &[vec![0, 1, 2], vec![1, 0, 3], vec![1, 0, 4]]);
    assert_eq!(
        e.unwrap_err().to_string(),
        "face 2 is the third face on the edge 1 – 0 (non-manifold edge)"
    );
}

/// A brute-force reading of the rules: faces of ≥ 3 distinct in-range vertices, every
/// undirected edge on at most two faces and then in opposite directions, every vertex used,
/// and the faces at each vertex connected through the edges at that vertex.
fn brute_force_valid(n: usize, faces: &[Vec<usize>]) -> bool {
    if faces.is_empty() {
        return false;
    }
    for f in faces {
        let distinct: BTreeSet<_> = f.iter().collect();
        if f.len() < 3 || distinct.len() != f.len() || f.iter().any(|&v| v >= n) {
            return false;
        }
    }
    let mut directed: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for f in faces {
        for k in 0..f.len() {
            *directed.entry((f[k], f[(k + 1) % f.len()])).or_default() += 1;
        }
    }
    for (&(a, b), &count) in &directed {
        let back = directed.get(&(b, a)).copied().unwrap_or(0);
        if count > 1 || count + back > 2 {
            return false;
        }
    }
    for v in 0..n {
        let at: Vec<usize> = (0..faces.len())
            .filter(|&f| faces[f].contains(&v))
            .collect();
        if at.is_empty() {
            return false;
        }
        // Union the faces at v that share an edge at v.
        let mut group: Vec<usize> = (0..at.len()).collect();
        fn find(g: &mut [usize], x: usize) -> usize {
            let mut r = x;
            while g[r] != r {
                r = g[r];
            }
            g[x] = r;
            r
        }
        for i in 0..at.len() {
            for j in i + 1..at.len() {
                let nbrs = |f: &Vec<usize>| {
                    let k = f.iter().position(|&x| x == v).unwrap();
                    [f[(k + 1) % f.len()], f[(k + f.len() - 1) % f.len()]]
                };
                let (a, b) = (nbrs(&faces[at[i]]), nbrs(&faces[at[j]]));
                if a.iter().any(|x| b.contains(x)) {
                    let (ri, rj) = (find(&mut group, i), find(&mut group, j));
                    group[ri] = rj;
                }
            }
        }
        let roots: BTreeSet<usize> = (0..at.len()).map(|i| find(&mut group, i)).collect();
        if roots.len() != 1 {
            return false;
        }
    }
    true
}

/// Checks the half-edge arrays against the faces by brute force.
fn check_against_faces(mesh: &PolygonMesh<f64, 3>) {
    let t = mesh.topology();
    t.check().unwrap();
    let h_count = t.halfedge_count();
    let mut edges = BTreeSet::new();
    for h in 0..h_count {
        let (a, b) = (t.origin(h), t.destination(h));
        let brute: Vec<usize> = (0..h_count)
            .filter(|&g| t.origin(g) == b && t.destination(g) == a)
            .collect();
        assert_eq!(t.twin(h), brute.first().copied(), "twin of {h}");
        assert_eq!(t.next(t.prev(h)), h);
        assert!(t.face_halfedges(t.face(h)).contains(&h));
        edges.insert((a.min(b), a.max(b)));
    }
    assert_eq!(t.edge_count(), edges.len());
    let mut valence_sum = 0;
    for v in 0..t.vertex_count() {
        let brute: BTreeSet<usize> = edges
            .iter()
            .filter_map(|&(a, b)| (a == v).then_some(b).or((b == v).then_some(a)))
            .collect();
        let ring: Vec<usize> = t.neighbours(v).collect();
        assert_eq!(ring.iter().copied().collect::<BTreeSet<_>>(), brute, "v{v}");
        assert_eq!(ring.len(), brute.len());
        assert_eq!(t.valence(v), brute.len());
        valence_sum += t.valence(v);
        assert!(t.one_ring(v).all(|h| t.origin(h) == v));
    }
    assert_eq!(valence_sum, 2 * t.edge_count());
    let boundary: usize = (0..t.boundary_loop_count())
        .map(|i| t.boundary_loop(i).len())
        .sum();
    assert_eq!(
        boundary,
        (0..h_count).filter(|&h| t.is_boundary_halfedge(h)).count()
    );
}

#[test]
fn generated_meshes_have_the_stated_euler_characteristic_and_valid_arrays() {
    let cases: Vec<(PolygonMesh<f64, 3>, i64, usize)> = vec![
        (cube(), 2, 0),
        (quad_torus(5, 7).unwrap(), 0, 0),
        (triangle_torus(4, 3).unwrap(), 0, 0),
        (irregular_torus(8, 6, 11).unwrap(), 0, 0),
        (quad_grid(3, 4).unwrap(), 1, 1),
        (triangle_grid(2, 5).unwrap(), 1, 1),
        (irregular_disk(60, 5).unwrap(), 1, 1),
    ];
    for (m, chi, loops) in &cases {
        assert_eq!(m.euler_characteristic(), *chi);
        assert_eq!(m.topology().boundary_loop_count(), *loops);
        check_against_faces(m);
    }
    for kind in MeshKind::ALL {
        let m = mesh(kind, 300, 2).unwrap();
        assert!(m.face_count() >= 150, "{kind}");
        m.topology().check().unwrap();
    }
    let t = quad_torus(100, 100).unwrap();
    assert_eq!(
        (t.face_count(), t.edge_count(), t.vertex_count()),
        (10_000, 20_000, 10_000)
    );
    assert!(quad_torus(2, 5).is_err());
    assert!(mesh(MeshKind::QuadGrid, 0, 0).is_err());
}

fn soup() -> impl Strategy<Value = (usize, Vec<Vec<usize>>)> {
    (3usize..=7).prop_flat_map(|n| {
        (
            Just(n),
            prop::collection::vec(prop::collection::vec(0..n + 1, 2..=5), 1..=7),
        )
    })
}

/// Subsets of the faces of a closed triangulated torus, some of them reversed: most are
/// valid surfaces with boundary or meet at single vertices (bow ties).
fn torus_pieces() -> impl Strategy<Value = (usize, Vec<Vec<usize>>)> {
    let torus = triangle_torus(3, 4).unwrap();
    let faces: Vec<Vec<usize>> = (0..torus.face_count())
        .map(|f| torus.face_vertices(f).iter().map(|&v| v as usize).collect())
        .collect();
    let n = torus.vertex_count();
    prop::collection::vec((any::<bool>(), 0u8..8), faces.len()).prop_map(move |choice| {
        let mut kept: Vec<Vec<usize>> = Vec::new();
        for (face, &(keep, flip)) in faces.iter().zip(&choice) {
            if keep {
                let mut f = face.clone();
                if flip == 0 {
                    f.reverse();
                }
                kept.push(f);
            }
        }
        (n, kept)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// The same on pieces of a valid surface, which reach the valid and the non-manifold
    /// vertex cases far more often than random soups.
    #[test]
    fn validation_agrees_on_pieces_of_a_torus((n, faces) in torus_pieces()) {
        // Leave out the vertices no kept face uses, renumbering the rest.
        let mut id = vec![usize::MAX; n];
        let mut count = 0;
        for f in &faces {
            for &v in f {
                if id[v] == usize::MAX {
                    id[v] = count;
                    count += 1;
                }
            }
        }
        let faces: Vec<Vec<usize>> =
            faces.iter().map(|f| f.iter().map(|&v| id[v]).collect()).collect();
        let built = PolygonMesh::new(verts(count), &faces);
        prop_assert_eq!(built.is_ok(), brute_force_valid(count, &faces), "{:?}", built);
        if let Ok(m) = built {
            check_against_faces(&m);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// The validation accepts exactly the face lists the brute-force checker accepts, and an
    /// accepted mesh's arrays agree with the faces.
    #[test]
    fn validation_agrees_with_the_brute_force_checker((n, faces) in soup()) {
        let built = PolygonMesh::new(verts(n), &faces);
        prop_assert_eq!(built.is_ok(), brute_force_valid(n, &faces), "{:?}", built);
        if let Ok(m) = built {
            check_against_faces(&m);
        }
    }

    /// Arbitrary bytes never make the reader panic.
    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        let _ = read_obj::<f64>(&bytes[..]);
        let _ = read_obj::<BigRational>(&bytes[..]);
    }

    /// Lines made of OBJ's own tokens (the likelier way to reach deep paths) never panic,
    /// and whatever is accepted is a valid mesh.
    #[test]
    fn token_soups_never_panic(lines in prop::collection::vec(
        prop::collection::vec(prop::sample::select(vec![
            "v", "f", "vt", "vn", "#", "1", "2", "3", "-1", "-4", "0", "1/2", "1//3", "2/1/1",
            "/", "1.5e3", "nan", "inf", "\r", "l", "g", "x", "4", "-2", "1e999", "",
        ]), 0..6),
        0..12,
    )) {
        let text: String = lines.iter().map(|l| l.join(" ") + "\n").collect();
        if let Ok(m) = read_obj::<f64>(text.as_bytes()) {
            prop_assert!(m.topology().check().is_ok());
        }
    }
}

#[test]
fn obj_round_trips_and_agrees_with_tobj() {
    for m in [
        cube(),
        irregular_torus(6, 8, 4).unwrap(),
        irregular_disk(40, 9).unwrap(),
    ] {
        let mut text = Vec::new();
        write_obj(&m, &mut text).unwrap();
        assert_eq!(read_obj::<f64>(&text[..]).unwrap(), m);
        // The exact reader takes the shortest round-trip decimals to the same doubles.
        let exact = read_obj::<BigRational>(&text[..]).unwrap();
        let back: Vec<P> = exact.positions().iter().map(|q| q.to_f64()).collect();
        assert_eq!(back, m.positions());
        // tobj reads the same vertices and faces.
        let (models, _) = tobj::load_obj_buf(&mut &text[..], &tobj::LoadOptions::default(), |_| {
            Ok(Default::default())
        })
        .unwrap();
        let model = &models[0].mesh;
        let sizes: Vec<u32> = (0..m.face_count())
            .map(|f| m.topology().face_size(f) as u32)
            .collect();
        assert_eq!(model.face_arities, sizes);
        // tobj renumbers the vertices in the order the faces use them: compare corner by
        // corner.
        assert_eq!(model.indices.len(), m.topology().halfedge_count());
        for (&k, &v) in model.indices.iter().zip(m.topology().corners()) {
            let k = k as usize;
            assert_eq!(
                &model.positions[3 * k..3 * k + 3],
                m.position(v as usize).coords()
            );
        }
    }
}

#[test]
fn obj_reader_takes_every_corner_form_and_skips_what_carries_no_geometry() {
    let text = "mtllib x.mtl\n# comment \u{ff}\no thing\ng group\ns off\nusemtl m\n\
                v 0 0 0\nv 1 0 0 1\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\nvt 0 0\nvn 0 0 1\n\
                vp 0.5\n\n   \r\nf 1/1 2/1/1 3//1 -1 # a quad\r\n";
    let m = read_obj::<f64>(text.as_bytes()).unwrap();
    assert_eq!(m.face_vertices(0), [0, 1, 2, 3]);
    assert_eq!(m.position(2), &p(1.0, 1.0, 0.0));
    // Comments may hold any bytes.
    let mut bytes = b"# \xff\xfe\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".to_vec();
    assert!(read_obj::<f64>(&bytes[..]).is_ok());
    bytes[0] = b'v';
    assert!(read_obj::<f64>(&bytes[..]).is_err());
    // Exact coordinates for rationals.
    let q = read_obj::<BigRational>("v 0.1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".as_bytes()).unwrap();
    assert_eq!(q.position(0)[0], BigRational::new(1.into(), 10.into()));
}

#[test]
fn every_malformed_obj_line_is_named_with_its_line_number() {
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    let cases: Vec<(String, usize, ObjProblem)> = vec![
        (
            format!("{tri}f 1 2\n"),
            4,
            ObjProblem::TooFewCorners { got: 2 },
        ),
        (format!("{tri}f 1 2 0\n"), 4, ObjProblem::ZeroIndex),
        (
            format!("{tri}f 1 2 4\n"),
            4,
            ObjProblem::IndexOutOfRange {
                index: 4,
                vertices: 3,
                when: "in the file",
            },
        ),
        (
            format!("{tri}f -1 -2 -4\n"),
            4,
            ObjProblem::IndexOutOfRange {
                index: -4,
                vertices: 3,
                when: "read so far",
            },
        ),
        (
            format!("{tri}f 1 2 3/x\n"),
            4,
            ObjProblem::BadCorner {
                corner: "\"3/x\"".into(),
            },
        ),
        (
            format!("{tri}f 1 2 3/1/1/1\n"),
            4,
            ObjProblem::BadCorner {
                corner: "\"3/1/1/1\"".into(),
            },
        ),
        (
            "v 0 0\n".into(),
            1,
            ObjProblem::TooFewCoordinates { got: 2 },
        ),
        (
            format!("{tri}l 1 2\n"),
            4,
            ObjProblem::Unsupported {
                keyword: "\"l\"".into(),
            },
        ),
        (
            "v 0 \u{0}\n".into(),
            1,
            ObjProblem::BadNumber {
                reason: String::new(),
            },
        ),
        (
            "v 0 0 nan\n".into(),
            1,
            ObjProblem::BadNumber {
                reason: String::new(),
            },
        ),
        (
            "v 0 0 1e999\n".into(),
            1,
            ObjProblem::BadNumber {
                reason: String::new(),
            },
        ),
    ];
    for (text, line, problem) in cases {
        match read_obj::<f64>(text.as_bytes()) {
            Err(Error::Mesh(MeshError::Obj {
                line: l,
                problem: got,
            })) => {
                assert_eq!(l, line, "{text:?}");
                match (&got, &problem) {
                    (ObjProblem::BadNumber { .. }, ObjProblem::BadNumber { .. }) => {}
                    _ => assert_eq!(got, problem, "{text:?}"),
                }
            }
            other => panic!("{text:?}: {other:?}"),
        }
    }
    assert!(matches!(
        read_obj::<f64>(&b"v 0 0 0\n\xff\n"[..]),
        Err(Error::Mesh(MeshError::Obj {
            line: 2,
            problem: ObjProblem::NotUtf8
        }))
    ));
    // An empty file is an empty mesh; the mesh rules apply to what is read.
    assert_eq!(
        read_obj::<f64>(&b""[..]),
        Err(Error::Empty {
            what: "polygon mesh"
        })
    );
    assert_eq!(
        read_obj::<f64>(format!("{tri}v 5 5 5\nf 1 2 3\n").as_bytes()),
        Err(Error::Mesh(MeshError::IsolatedVertex { vertex: 3 }))
    );
}

#[test]
fn sizes_beyond_the_limits_are_refused_before_allocating() {
    use compgeo::limits::MAX_MESH_CORNERS;
    let e = quad_torus(MAX_MESH_CORNERS, 4).unwrap_err();
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
}
