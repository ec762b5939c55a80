//! `compgeo mesh subdivide --scheme loop|doo-sabin`: the mesh written or printed is the
//! library's (`loop_subdivision`, `doo_sabin`, exactly with `--exact`), the summary counts
//! F·4ᵏ triangles for Loop and F + E + V faces for a round of Doo–Sabin on a closed mesh, and
//! a mesh Loop cannot take or an absurd round count exits 2 with one `error:` line naming it.

#![cfg(all(feature = "cli", feature = "exact"))]

use crate::common::{assert_rejected, run, run_json};
use crate::mesh_loop::fans;
use crate::spline_common::Q;
use compgeo::gen::{cube, irregular_disk};
use compgeo::mesh::{doo_sabin, loop_subdivision, read_obj, write_obj, PolygonMesh};

fn obj_text<S: compgeo::spline::Scalar>(mesh: &PolygonMesh<S, 3>) -> String {
    let mut out = Vec::new();
    write_obj(mesh, &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

#[test]
fn loop_writes_the_library_result() {
    let disk = fans(&irregular_disk(30, 8).unwrap());
    let text = obj_text(&disk);
    let v = run_json(
        &[
            "mesh",
            "subdivide",
            "--scheme",
            "loop",
            "--rounds",
            "2",
            "-",
        ],
        Some(&text),
    );
    let expected = loop_subdivision(&disk, 2).unwrap();
    assert_eq!(v["scheme"], "loop");
    assert_eq!(v["output"]["faces"], 16 * disk.face_count());
    assert_eq!(v["output"]["vertices"], expected.vertex_count());
    assert_eq!(v["output"]["euler_characteristic"], 1);
    let positions = v["positions"].as_array().unwrap();
    for (json, p) in positions.iter().zip(expected.positions()) {
        for k in 0..3 {
            assert_eq!(json[k].as_f64().unwrap(), p[k]);
        }
    }
    let faces = v["faces"].as_array().unwrap();
    assert_eq!(faces.len(), expected.face_count());
    assert_eq!(
        faces[5],
        serde_json::json!(expected.face_vertices(5).to_vec())
    );
    // --out -: the OBJ text of the same mesh.
    let (code, out, err) = run(
        &[
            "mesh",
            "subdivide",
            "--scheme",
            "loop",
            "--rounds",
            "2",
            "-",
            "--out",
            "-",
        ],
        Some(&text),
    );
    assert_eq!(code, 0, "{err}");
    let written = read_obj::<f64>(out.as_bytes()).unwrap();
    assert_eq!(written.positions(), expected.positions());
    assert_eq!(written.topology().corners(), expected.topology().corners());
}

#[test]
fn doo_sabin_is_exact_with_exact() {
    // Coordinates with tenths: exact only in rationals.
    let text = "v 0 0 0.1\nv 1 0 0\nv 1 1 0.3\nv 0 1 0\nv 2 0 0.7\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\n";
    let v = run_json(
        &["mesh", "subdivide", "--scheme", "doo-sabin", "--exact", "-"],
        Some(text),
    );
    let exact = read_obj::<Q>(text.as_bytes()).unwrap();
    let expected = doo_sabin(&exact, 1).unwrap();
    // Two faces sharing one edge: two face-faces and one edge-face.
    assert_eq!(v["output"]["faces"], 3);
    let positions = v["positions"].as_array().unwrap();
    assert_eq!(positions.len(), expected.vertex_count());
    for (json, q) in positions.iter().zip(expected.positions()) {
        let coords: Vec<Q> = json
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c.as_str().unwrap().parse().unwrap())
            .collect();
        assert_eq!(&coords[..], q.coords());
    }
    // On the closed cube: F + E + V = 26 faces.
    let v = run_json(
        &["mesh", "subdivide", "--scheme", "doo-sabin", "-"],
        Some(&obj_text(&cube())),
    );
    assert_eq!(v["output"]["faces"], 6 + 12 + 8);
    assert_eq!(v["output"]["euler_characteristic"], 2);
    assert!(v["counts"]["arithmetic_operations"].as_u64().unwrap() == 5 * 24);
}

#[test]
fn meshes_a_scheme_cannot_take_exit_2() {
    let cube_text = obj_text(&cube());
    let err = assert_rejected(
        &["mesh", "subdivide", "--scheme", "loop", "-"],
        Some(&cube_text),
    );
    assert!(
        err.contains("face 0 has 4 corners; this scheme needs a triangle mesh"),
        "{err}"
    );
    for scheme in ["loop", "doo-sabin"] {
        let text = obj_text(&fans(&cube()));
        let err = assert_rejected(
            &[
                "mesh",
                "subdivide",
                "--scheme",
                scheme,
                "--rounds",
                "40",
                "-",
            ],
            Some(&text),
        );
        assert!(err.contains("MAX_MESH_CORNERS"), "{scheme}: {err}");
    }
}
