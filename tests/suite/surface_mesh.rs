//! Tessellation and mesh export: the mesh of a patch against the surface (every vertex is the
//! surface's point at its grid parameters, every normal the unit c_u × c_v there, every
//! triangle counter-clockwise seen from the normals' side), the fallback normals at a
//! collapsed edge (from the grid cells), and the OBJ and STL files read back by two maintained parsers, `tobj` and
//! `stl_io`, which must find the same vertices and triangles.

use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::Point;
use compgeo::surface::{
    tessellate, tessellate_at_with, BezierPatch, ControlNet, Surface, SurfaceDerivative,
    TriangleMesh,
};
use compgeo::Error;
use proptest::prelude::*;

/// A patch of bidegree (1..=3, 1..=3) in R³ whose first partials never vanish: a regular
/// grid in x, y with z perturbed by at most 1/8 (so coarse triangles still face the way the
/// surface's normals do).
fn patch() -> impl Strategy<Value = BezierPatch<f64, 3>> {
    (2usize..=4, 2usize..=4)
        .prop_flat_map(|(rows, columns)| {
            (
                Just((rows, columns)),
                prop::collection::vec(-8i64..=8, rows * columns),
            )
        })
        .prop_map(|((rows, columns), zs)| {
            let points = (0..rows * columns)
                .map(|k| {
                    let (i, j) = (k / columns, k % columns);
                    Point::new([i as f64, j as f64, zs[k] as f64 / 64.0])
                })
                .collect();
            BezierPatch::new(ControlNet::from_rows(rows, columns, points).unwrap()).unwrap()
        })
}

fn cross(a: &Point<f64, 3>, b: &Point<f64, 3>) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn the_mesh_samples_the_surface(s in patch(), nu in 1usize..=6, nv in 1usize..=6) {
        let mesh = tessellate(&s, nu, nv).unwrap();
        prop_assert_eq!(mesh.positions.len(), (nu + 1) * (nv + 1));
        prop_assert_eq!(mesh.triangles.len(), 2 * nu * nv);
        for i in 0..=nu {
            for j in 0..=nv {
                let (u, v) = (i as f64 / nu as f64, j as f64 / nv as f64);
                let k = i * (nv + 1) + j;
                let p = s.eval(&u, &v).unwrap();
                for (got, want) in mesh.positions[k].iter().zip(p.coords()) {
                    prop_assert!((got - want).abs() < 1e-12);
                }
                let n = cross(&s.partial_at(&u, &v, 1, 0).unwrap(), &s.partial_at(&u, &v, 0, 1).unwrap());
                let len = dot(&n, &n).sqrt();
                for (got, want) in mesh.normals[k].iter().zip(n) {
                    prop_assert!((got - want / len).abs() < 1e-12);
                }
            }
        }
        // Every triangle is counter-clockwise seen from its corners' normals, and every
        // vertex is used.
        let mut used = vec![false; mesh.positions.len()];
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|k| mesh.positions[k]);
            let e1 = Point::new([b[0] - a[0], b[1] - a[1], b[2] - a[2]]);
            let e2 = Point::new([c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
            let face = cross(&e1, &e2);
            for &k in t {
                prop_assert!(dot(&face, &mesh.normals[k]) > 0.0, "{:?} at {}", t, k);
                used[k] = true;
            }
        }
        prop_assert!(used.into_iter().all(|u| u));
    }

    #[test]
    fn obj_and_stl_read_back_the_same_mesh(s in patch(), nu in 1usize..=5, nv in 1usize..=5) {
        let mesh = tessellate(&s, nu, nv).unwrap();
        // tobj renumbers the vertices in the order the faces first use them: compare the
        // triangles corner by corner, and the vertex count.
        let (positions, triangles) = read_obj(&mesh);
        prop_assert_eq!(positions.len(), mesh.positions.len());
        prop_assert_eq!(triangles.len(), mesh.triangles.len());
        for (got, want) in triangles.iter().zip(&mesh.triangles) {
            for (g, w) in got.iter().zip(want) {
                prop_assert_eq!(positions[*g], mesh.positions[*w]);
            }
        }
        let stl = read_stl(&mesh);
        prop_assert_eq!(stl.len(), mesh.triangles.len());
        for (face, t) in stl.iter().zip(&mesh.triangles) {
            for (corner, &k) in face.iter().zip(t) {
                // STL stores f32.
                for (got, want) in corner.iter().zip(mesh.positions[k]) {
                    prop_assert_eq!(*got, want as f32);
                }
            }
        }
    }
}

/// The positions and triangles `tobj` reads from the OBJ text of `mesh`.
pub(crate) fn read_obj(mesh: &TriangleMesh) -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let mut text = Vec::new();
    mesh.write_obj(&mut text).unwrap();
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: false,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj_buf(&mut text.as_slice(), &options, |_| {
        Err(tobj::LoadError::GenericFailure)
    })
    .unwrap();
    assert_eq!(models.len(), 1);
    let m = &models[0].mesh;
    assert_eq!(m.normals.len(), m.positions.len());
    let positions = m.positions.chunks(3).map(|p| [p[0], p[1], p[2]]).collect();
    let triangles = m
        .indices
        .chunks(3)
        .map(|t| [t[0] as usize, t[1] as usize, t[2] as usize])
        .collect();
    (positions, triangles)
}

/// The triangles (three corners each) `stl_io` reads from the ASCII STL text of `mesh`.
fn read_stl(mesh: &TriangleMesh) -> Vec<[[f32; 3]; 3]> {
    let mut text = Vec::new();
    mesh.write_stl("patch", &mut text).unwrap();
    let indexed = stl_io::read_stl(&mut std::io::Cursor::new(text)).unwrap();
    indexed
        .faces
        .iter()
        .map(|f| f.vertices.map(|k| <[f32; 3]>::from(indexed.vertices[k])))
        .collect()
}

#[test]
fn a_collapsed_edge_takes_the_normals_of_its_cells() {
    // A triangle as a bilinear patch: the edge u = 0 collapsed to the apex (0, 0, 0), where
    // c_v vanishes, so c_u × c_v does too.
    let p = |x: i64, y: i64| Point::new([qi(x), qi(y), qi(0)]);
    let net = ControlNet::new(vec![vec![p(0, 0), p(0, 0)], vec![p(1, 0), p(1, 1)]]).unwrap();
    let s: BezierPatch<Q, 3> = BezierPatch::new(net).unwrap();
    let apex_normal = s.partial_at(&qi(0), &q(1, 2), 0, 1).unwrap();
    assert_eq!(apex_normal, Point::zero());
    let mut counts = Counts::default();
    let samples = [qi(0), q(1, 2), qi(1)];
    let mesh = tessellate_at_with(&s, &samples, &samples, &mut counts).unwrap();
    assert_eq!(counts.arithmetic_operations, 3 * 9);
    // Every normal is +z: the surface's where it has one, the cells' at the apex.
    for n in &mesh.normals {
        assert_eq!(*n, [0.0, 0.0, 1.0]);
    }
}

#[test]
fn bad_grids_are_named_errors() {
    let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
    let s = BezierPatch::new(
        ControlNet::new(vec![
            vec![p(0.0, 0.0), p(0.0, 1.0)],
            vec![p(1.0, 0.0), p(1.0, 1.0)],
        ])
        .unwrap(),
    )
    .unwrap();
    let name = |e: Error| match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("{other}"),
    };
    assert_eq!(name(tessellate(&s, 0, 3).unwrap_err()), "segments");
    let mut c = Counts::default();
    for (us, vs) in [
        (vec![0.0], vec![0.0, 1.0]),
        (vec![0.0, 0.0], vec![0.0, 1.0]),
        (vec![0.0, 1.0], vec![1.0, 0.5]),
        (vec![0.0, f64::NAN], vec![0.0, 1.0]),
    ] {
        assert_eq!(
            name(tessellate_at_with(&s, &us, &vs, &mut c).unwrap_err()),
            "samples"
        );
    }
    assert!(matches!(
        tessellate(&s, 1 << 14, 1 << 14),
        Err(Error::LimitExceeded { .. })
    ));
}
