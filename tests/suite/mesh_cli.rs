//! `compgeo mesh subdivide`: the JSON summary and the mesh it prints or writes equal the
//! library's result (an OBJ file read back, the JSON positions exact with `--exact`), `--out -`
//! writes OBJ to stdout, and bad meshes, bad OBJ lines and bad arguments exit 2 with one
//! `error:` line naming the face or the line.

#![cfg(all(feature = "cli", feature = "exact"))]

use crate::common::{assert_rejected, run, run_json};
use crate::spline_common::Q;
use compgeo::gen::{cube, irregular_disk};
use compgeo::mesh::{catmull_clark, midpoint_cubic, read_obj, write_obj, PolygonMesh};
use compgeo::spline::Point;
use std::path::PathBuf;

/// A scratch directory of this test process.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("compgeo-mesh-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// The same positions and faces (the edge numbering of a mesh read from a file is its own).
fn assert_same_mesh(a: &PolygonMesh<f64, 3>, b: &PolygonMesh<f64, 3>) {
    assert!(a.positions() == b.positions(), "positions differ");
    assert!(
        a.topology().face_offsets() == b.topology().face_offsets(),
        "faces differ"
    );
    assert!(
        a.topology().corners() == b.topology().corners(),
        "corners differ"
    );
}

fn obj_text(mesh: &PolygonMesh<f64, 3>) -> String {
    let mut out = Vec::new();
    write_obj(mesh, &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

#[test]
fn subdivide_writes_the_library_result_and_summarises_it() {
    let disk = irregular_disk(30, 3).unwrap();
    let input = scratch("disk.obj");
    std::fs::write(&input, obj_text(&disk)).unwrap();
    let output = scratch("fine.obj");
    let args = [
        "mesh",
        "subdivide",
        "--scheme",
        "catmull-clark",
        "--rounds",
        "2",
        input.to_str().unwrap(),
        "--out",
        output.to_str().unwrap(),
    ];
    let v = run_json(&args, None);
    let expected = catmull_clark(&disk, 2).unwrap();
    let written = read_obj::<f64>(std::fs::read(&output).unwrap().as_slice()).unwrap();
    assert_same_mesh(&written, &expected);
    assert_eq!(v["scheme"], "catmull-clark");
    assert_eq!(v["rounds"], 2);
    assert_eq!(v["input"]["faces"], disk.face_count());
    assert_eq!(v["output"]["faces"], expected.face_count());
    assert_eq!(v["output"]["vertices"], expected.vertex_count());
    assert_eq!(v["output"]["edges"], expected.edge_count());
    assert_eq!(v["output"]["boundary_loops"], 1);
    assert_eq!(v["output"]["euler_characteristic"], 1);
    assert!(v["counts"]["arithmetic_operations"].as_u64().unwrap() > 0);
    assert_eq!(v["out"], output.to_str().unwrap());
    assert!(v.get("positions").is_none());
}

#[test]
fn without_out_the_mesh_is_in_the_json_and_exact_with_exact() {
    // Coordinates with tenths: exact only in rationals.
    let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    let text = "v 0 0 0\nv 1 0 0.1\nv 1 1 0\nv 0 1 0.3\nf 1 2 3 4\n";
    let v = run_json(&["mesh", "subdivide", "-", "--exact"], Some(text));
    let exact = read_obj::<Q>(text.as_bytes()).unwrap();
    let expected = catmull_clark(&exact, 1).unwrap();
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
    let faces = v["faces"].as_array().unwrap();
    assert_eq!(faces.len(), 4);
    assert_eq!(
        faces[0],
        serde_json::json!(expected.face_vertices(0).to_vec())
    );
    // In f64 the numbers are JSON numbers.
    let v = run_json(&["mesh", "subdivide", "-"], Some(text));
    let first = &v["positions"][0];
    let mesh = PolygonMesh::new(
        vec![
            p(0.0, 0.0, 0.0),
            p(1.0, 0.0, 0.1),
            p(1.0, 1.0, 0.0),
            p(0.0, 1.0, 0.3),
        ],
        &[[0, 1, 2, 3]],
    )
    .unwrap();
    let fine = catmull_clark(&mesh, 1).unwrap();
    assert_eq!(first[2].as_f64().unwrap(), fine.position(0)[2]);
}

#[test]
fn out_dash_writes_obj_to_stdout_and_schemes_are_chosen_by_name() {
    let text = obj_text(&cube());
    let (code, out, err) = run(
        &[
            "mesh",
            "subdivide",
            "--scheme",
            "midpoint-cubic",
            "--rounds",
            "2",
            "-",
            "--out",
            "-",
        ],
        Some(&text),
    );
    assert_eq!(code, 0, "{err}");
    assert!(err.is_empty());
    let written = read_obj::<f64>(out.as_bytes()).unwrap();
    assert_same_mesh(&written, &midpoint_cubic(&cube(), 2).unwrap());
}

#[test]
fn bad_meshes_and_arguments_exit_2_naming_the_problem() {
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
    let cases = [
        (
            format!("{tri}f 1 2 3\nf 2 1 4\nf 1 2 4\n"),
            "face 2 is the third face on the edge",
        ),
        (
            format!("{tri}f 1 2 3\nf 3 2 4\nf 1 2 4\n"),
            "(inconsistent orientation)",
        ),
        (
            format!("{tri}f 1 2 9\n"),
            "OBJ line 5: vertex index 9 names no vertex",
        ),
        (format!("{tri}f 1 2 3\n"), "vertex 3 is used by no face"),
        (format!("{tri}f 1 2 2\n"), "face 0 visits vertex 1 twice"),
        ("v 0 0 nan\n".to_string(), "OBJ line 1: bad number"),
        (
            "curv 0 1 1 2\n".to_string(),
            "unsupported statement \"curv\"",
        ),
        (String::new(), "polygon mesh is empty"),
    ];
    for (text, needle) in cases {
        let err = assert_rejected(&["mesh", "subdivide", "-"], Some(&text));
        assert!(err.contains(needle), "{text:?}: {err}");
    }
    let cube_text = obj_text(&cube());
    let err = assert_rejected(
        &["mesh", "subdivide", "--scheme", "butterfly", "-"],
        Some(&cube_text),
    );
    assert!(err.contains("catmull-clark"), "{err}");
    let err = assert_rejected(
        &["mesh", "subdivide", "--rounds", "40", "-"],
        Some(&cube_text),
    );
    assert!(err.contains("MAX_MESH_CORNERS"), "{err}");
    let err = assert_rejected(&["mesh", "subdivide", "/nonexistent/x.obj"], None);
    assert!(err.contains("cannot read"), "{err}");
    let err = assert_rejected(
        &["mesh", "subdivide", "-", "--out", "/nonexistent/dir/y.obj"],
        Some(&cube_text),
    );
    assert!(err.contains("cannot write"), "{err}");
}
