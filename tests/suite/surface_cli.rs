//! The `compgeo surface` command against the library: points, partial derivatives and meshes
//! as the library computes them (exactly with `--exact`), the OBJ and STL files read back by
//! `tobj` and `stl_io`, and bad nets and parameters exiting with code 2 and one `error:` line
//! naming what is wrong.
#![cfg(all(feature = "cli", feature = "exact"))]

use crate::common::{assert_rejected, run_json};
use crate::spline_common::{q, Q};
use compgeo::spline::{BSpline, Curve, KnotVector, Parameterisation, Point};
use compgeo::surface::{
    normal, tessellate, BSplineSurface, BezierPatch, ControlNet, Normal, NurbsSurface, Surface,
    SurfaceDerivative,
};
use serde_json::Value;

/// A bidegree (2, 3) net in R³ with fractions, as the command reads it.
const NET: &str = r#"[[[0,0,0],[0,1,"1/2"],[0,2,-1],[0,3,0]],
                      [[1,0,1],[1,1,"2/3"],[1,2,2],[1,3,"-1/4"]],
                      [[2,0,0],[2,1,1],[2,2,"3/5"],[2,3,1]]]"#;

fn number(v: &Value) -> Q {
    v.as_str().unwrap().parse().unwrap()
}

fn point3(v: &Value) -> Point<Q, 3> {
    let c: Vec<Q> = v.as_array().unwrap().iter().map(number).collect();
    Point::new([c[0].clone(), c[1].clone(), c[2].clone()])
}

/// The same net in the library.
fn patch() -> BezierPatch<Q, 3> {
    let text: Vec<Vec<Vec<Value>>> = serde_json::from_str(NET).unwrap();
    let rows = text
        .iter()
        .map(|row| {
            row.iter()
                .map(|p| {
                    let c: Vec<Q> = p
                        .iter()
                        .map(|x| match x {
                            Value::String(s) => s.parse().unwrap(),
                            other => crate::spline_common::qi(other.as_i64().unwrap()),
                        })
                        .collect();
                    Point::new([c[0].clone(), c[1].clone(), c[2].clone()])
                })
                .collect()
        })
        .collect();
    BezierPatch::new(ControlNet::new(rows).unwrap()).unwrap()
}

#[test]
fn eval_and_derivatives_match_the_library_exactly() {
    let s = patch();
    for (u, v) in [(q(1, 3), q(1, 2)), (q(0, 1), q(1, 1)), (q(-1, 2), q(7, 5))] {
        let (us, vs) = (u.to_string(), v.to_string());
        for algorithm in ["rows-first", "columns-first", "de-casteljau"] {
            let out = run_json(
                &[
                    "surface",
                    "eval",
                    "--net",
                    NET,
                    "--u",
                    &us,
                    "--v",
                    &vs,
                    "--algorithm",
                    algorithm,
                    "--exact",
                ],
                None,
            );
            assert_eq!(
                point3(&out["point"]),
                s.eval(&u, &v).unwrap(),
                "{algorithm}"
            );
            assert_eq!(out["bidegree"], serde_json::json!([2, 3]));
            assert!(out["counts"]["arithmetic_operations"].as_u64().unwrap() > 0);
        }
        for (r, t) in [(1, 0), (0, 1), (1, 1), (2, 3), (3, 0)] {
            let out = run_json(
                &[
                    "surface",
                    "derivative",
                    "--net",
                    NET,
                    "--u",
                    &us,
                    "--v",
                    &vs,
                    "--order-u",
                    &r.to_string(),
                    "--order-v",
                    &t.to_string(),
                    "--exact",
                ],
                None,
            );
            assert_eq!(
                point3(&out["derivative"]),
                s.partial_at(&u, &v, r, t).unwrap(),
                "order ({r}, {t})"
            );
        }
    }
}

/// A printed patch: its bidegree and net.
fn patch_of(out: &Value) -> BezierPatch<Q, 3> {
    let rows = out["net"]
        .as_array()
        .unwrap()
        .iter()
        .map(|row| row.as_array().unwrap().iter().map(point3).collect())
        .collect();
    let p = BezierPatch::new(ControlNet::new(rows).unwrap()).unwrap();
    let bidegree: (usize, usize) = serde_json::from_value(out["bidegree"].clone()).unwrap();
    assert_eq!(p.bidegree(), bidegree);
    p
}

#[test]
fn restrict_elevate_and_normal_match_the_library_exactly() {
    let s = patch();
    let out = run_json(
        &[
            "surface", "restrict", "--net", NET, "--u0", "1/4", "--u1", "2", "--v0", "-1/3",
            "--v1", "1/2", "--exact",
        ],
        None,
    );
    let r = patch_of(&out);
    assert_eq!(
        r,
        s.restrict(&q(1, 4), &q(2, 1), &q(-1, 3), &q(1, 2)).unwrap()
    );
    // The restricted patch at (0, 1) is the surface at (1/4, 1/2).
    assert_eq!(
        r.eval(&q(0, 1), &q(1, 1)).unwrap(),
        s.eval(&q(1, 4), &q(1, 2)).unwrap()
    );
    let out = run_json(
        &[
            "surface", "elevate", "--net", NET, "--by-u", "2", "--by-v", "1", "--exact",
        ],
        None,
    );
    let e = patch_of(&out);
    assert_eq!(e.bidegree(), (4, 4));
    assert_eq!(e, s.elevate_to(4, 4).unwrap());
    for (u, v) in [(q(1, 3), q(2, 7)), (q(3, 2), q(-1, 5))] {
        assert_eq!(e.eval(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
        let out = run_json(
            &[
                "surface",
                "normal",
                "--net",
                NET,
                "--u",
                &u.to_string(),
                "--v",
                &v.to_string(),
                "--exact",
            ],
            None,
        );
        assert_eq!(out["regular"], true);
        assert_eq!(
            Normal::Regular(point3(&out["normal"])),
            normal(&s, &u, &v).unwrap()
        );
    }
    // A collapsed edge: the row u = 0 is one point, so c_v vanishes there.
    let collapsed = "[[[0,0,0],[0,0,0]],[[1,0,0],[1,1,1]]]";
    let out = run_json(
        &[
            "surface", "normal", "--net", collapsed, "--u", "0", "--v", "1/2", "--exact",
        ],
        None,
    );
    assert_eq!(out["regular"], false);
    let rows = vec![
        vec![Point::new([q(0, 1), q(0, 1), q(0, 1)]); 2],
        vec![
            Point::new([q(1, 1), q(0, 1), q(0, 1)]),
            Point::new([q(1, 1), q(1, 1), q(1, 1)]),
        ],
    ];
    let c = BezierPatch::new(ControlNet::new(rows).unwrap()).unwrap();
    match normal(&c, &q(0, 1), &q(1, 2)).unwrap() {
        Normal::Degenerate { along_u, along_v } => {
            assert_eq!(point3(&out["along_u"]), along_u);
            assert_eq!(point3(&out["along_v"]), along_v);
        }
        other => panic!("{other:?}"),
    }
}

/// A printed B-spline surface.
fn spline_of(out: &Value) -> BSplineSurface<Q, 3> {
    let rows = out["net"]
        .as_array()
        .unwrap()
        .iter()
        .map(|row| row.as_array().unwrap().iter().map(point3).collect())
        .collect();
    let (p, q): (usize, usize) = serde_json::from_value(out["bidegree"].clone()).unwrap();
    let knots = |name: &str, d: usize| {
        let t: Vec<Q> = out[name].as_array().unwrap().iter().map(number).collect();
        KnotVector::new(d, t).unwrap()
    };
    BSplineSurface::new(
        ControlNet::new(rows).unwrap(),
        knots("knots_u", p),
        knots("knots_v", q),
    )
    .unwrap()
}

#[test]
fn spline_surfaces_and_constructions_match_the_library_exactly() {
    let net = patch().net().clone();
    let tu = KnotVector::new(2, [0, 0, 0, 1, 1, 1].map(crate::spline_common::qi).to_vec()).unwrap();
    let tv = KnotVector::new(
        2,
        vec![
            q(0, 1),
            q(0, 1),
            q(0, 1),
            q(1, 3),
            q(1, 1),
            q(1, 1),
            q(1, 1),
        ],
    )
    .unwrap();
    let s = BSplineSurface::new(net.clone(), tu.clone(), tv.clone()).unwrap();
    let weights: Vec<Q> = (0..12).map(|k| q(k % 3 + 1, 2)).collect();
    let n = NurbsSurface::new(net, weights, tu, tv).unwrap();
    let spline_args = [
        "--degree-u",
        "2",
        "--degree-v",
        "2",
        "--knots-v",
        "[0,0,0,\"1/3\",1,1,1]",
    ];
    let weights_json =
        "[[\"1/2\",1,\"3/2\",\"1/2\"],[1,\"3/2\",\"1/2\",1],[\"3/2\",\"1/2\",1,\"3/2\"]]";
    for (u, v) in [(q(1, 3), q(1, 2)), (q(1, 1), q(1, 3)), (q(0, 1), q(1, 1))] {
        let (us, vs) = (u.to_string(), v.to_string());
        let mut args = vec![
            "surface", "eval", "--net", NET, "--u", &us, "--v", &vs, "--exact",
        ];
        args.extend(spline_args);
        let out = run_json(&args, None);
        assert_eq!(point3(&out["point"]), s.eval(&u, &v).unwrap());
        args.extend(["--weights", weights_json]);
        let out = run_json(&args, None);
        assert_eq!(point3(&out["point"]), n.eval(&u, &v).unwrap());
        let mut args = vec![
            "surface",
            "derivative",
            "--net",
            NET,
            "--u",
            &us,
            "--v",
            &vs,
        ];
        args.extend([
            "--order-u",
            "1",
            "--order-v",
            "1",
            "--exact",
            "--weights",
            weights_json,
        ]);
        args.extend(spline_args);
        let out = run_json(&args, None);
        assert_eq!(
            point3(&out["derivative"]),
            n.partial_at(&u, &v, 1, 1).unwrap()
        );
    }
    // Elevation keeps the surface.
    let mut args = vec![
        "surface", "elevate", "--net", NET, "--by-u", "1", "--by-v", "2", "--exact",
    ];
    args.extend(spline_args);
    let e = spline_of(&run_json(&args, None));
    assert_eq!(e.bidegree(), (3, 4));
    for (u, v) in [(q(1, 5), q(2, 3)), (q(7, 8), q(1, 9))] {
        assert_eq!(e.eval(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
    }

    // Interpolation: the library's surface, through every data point at uniform parameters.
    let out = run_json(
        &[
            "surface",
            "interpolate",
            "--points",
            NET,
            "--degree-u",
            "2",
            "--degree-v",
            "2",
            "--parameterisation",
            "uniform",
            "--exact",
        ],
        None,
    );
    let i = spline_of(&out);
    assert_eq!(
        i,
        BSplineSurface::interpolate(patch().net(), (2, 2), Parameterisation::Uniform).unwrap()
    );
    for r in 0..3 {
        for c in 0..4 {
            assert_eq!(
                &i.eval(&q(r, 2), &q(c, 3)).unwrap(),
                patch().net().get(r as usize, c as usize)
            );
        }
    }

    // Least squares on samples of a bilinear patch gives the patch back.
    let bilinear = BezierPatch::new(
        ControlNet::new(vec![
            vec![
                Point::new([q(0, 1), q(0, 1), q(1, 1)]),
                Point::new([q(0, 1), q(1, 1), q(2, 1)]),
            ],
            vec![
                Point::new([q(1, 1), q(0, 1), q(3, 1)]),
                Point::new([q(1, 1), q(1, 1), q(-1, 1)]),
            ],
        ])
        .unwrap(),
    )
    .unwrap();
    let params: Vec<(Q, Q)> = [(0, 0), (1, 0), (0, 1), (1, 1), (1, 2), (2, 1)]
        .iter()
        .map(|&(a, b)| (q(a, 2), q(b, 2)))
        .collect();
    let json_list = |v: Vec<String>| format!("[{}]", v.join(","));
    let pts = json_list(
        params
            .iter()
            .map(|(u, v)| {
                let p = bilinear.eval(u, v).unwrap();
                json_list(p.coords().iter().map(|x| format!("\"{x}\"")).collect())
            })
            .collect(),
    );
    let uv = json_list(
        params
            .iter()
            .map(|(u, v)| format!("[\"{u}\",\"{v}\"]"))
            .collect(),
    );
    let out = run_json(
        &[
            "surface",
            "fit",
            "--points",
            &pts,
            "--params",
            &uv,
            "--control-u",
            "2",
            "--control-v",
            "2",
            "--degree-u",
            "1",
            "--degree-v",
            "1",
            "--exact",
        ],
        None,
    );
    let fitted = spline_of(&out);
    assert_eq!(fitted.net(), bilinear.net());

    // Lofting: the surface passes through every curve at its parameter.
    let out = run_json(
        &[
            "surface",
            "loft",
            "--curves",
            NET,
            "--degree-u",
            "2",
            "--degree-v",
            "3",
            "--exact",
        ],
        None,
    );
    let l = spline_of(&out);
    for (k, row) in patch().net().to_rows().into_iter().enumerate() {
        let t = KnotVector::clamped_uniform(3, 4, q(0, 1), q(1, 1)).unwrap();
        let curve = BSpline::new(row, t).unwrap();
        for v in [q(0, 1), q(2, 7), q(1, 1)] {
            assert_eq!(
                l.eval(&q(k as i64, 2), &v).unwrap(),
                curve.eval(&v).unwrap()
            );
        }
    }
}

#[test]
fn tessellate_prints_the_librarys_mesh_and_writes_files_viewers_read() {
    // With --exact both compute in rationals and round once: the same doubles.
    let mesh = tessellate(&patch(), 3, 5).unwrap();
    let out = run_json(
        &[
            "surface",
            "tessellate",
            "--net",
            NET,
            "--u-segments",
            "3",
            "--v-segments",
            "5",
            "--exact",
        ],
        None,
    );
    assert_eq!(out["vertices"], 4 * 6);
    assert_eq!(out["triangles"], 3 * 5 * 2);
    let positions: Vec<[f64; 3]> = serde_json::from_value(out["positions"].clone()).unwrap();
    let normals: Vec<[f64; 3]> = serde_json::from_value(out["normals"].clone()).unwrap();
    let triangles: Vec<[usize; 3]> = serde_json::from_value(out["indices"].clone()).unwrap();
    assert_eq!(
        (positions, normals, triangles),
        (
            mesh.positions.clone(),
            mesh.normals.clone(),
            mesh.triangles.clone()
        )
    );

    let dir = std::env::temp_dir().join(format!("compgeo-surface-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (obj, stl) = (dir.join("patch.obj"), dir.join("patch.stl"));
    let out = run_json(
        &[
            "surface",
            "tessellate",
            "--net",
            NET,
            "--u-segments",
            "3",
            "--v-segments",
            "5",
            "--obj",
            obj.to_str().unwrap(),
            "--stl",
            stl.to_str().unwrap(),
            "--exact",
        ],
        None,
    );
    assert_eq!(out["obj"], obj.to_str().unwrap());
    assert!(out.get("positions").is_none());
    let options = tobj::LoadOptions {
        single_index: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj(&obj, &options).unwrap();
    let m = &models[0].mesh;
    assert_eq!(m.indices.len(), 3 * mesh.triangles.len());
    for (k, t) in m.indices.chunks(3).zip(&mesh.triangles) {
        for (&index, &want) in k.iter().zip(t) {
            let i = index as usize;
            assert_eq!(&m.positions[3 * i..3 * i + 3], &mesh.positions[want]);
        }
    }
    let mut file = std::fs::File::open(&stl).unwrap();
    let read = stl_io::read_stl(&mut file).unwrap();
    assert_eq!(read.faces.len(), mesh.triangles.len());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn f64_eval_agrees_with_the_exact_one() {
    let s = patch();
    let out = run_json(
        &[
            "surface", "eval", "--net", NET, "--u", "0.25", "--v", "0.75",
        ],
        None,
    );
    let exact = s.eval(&q(1, 4), &q(3, 4)).unwrap();
    for (got, want) in out["point"].as_array().unwrap().iter().zip(exact.coords()) {
        let want: f64 = num_traits::ToPrimitive::to_f64(want).unwrap();
        assert!((got.as_f64().unwrap() - want).abs() <= 1e-15 * want.abs().max(1.0));
    }
}

#[test]
fn bad_nets_and_parameters_exit_2_naming_the_problem() {
    for (args, message) in [
        (
            vec![
                "surface",
                "eval",
                "--net",
                "[[[0,0],[1]]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "point (0, 1) has 1 coordinates, but point (0, 0) has 2",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                "[[[0,0]],[[1,1],[2,2]]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "row 1 has 2 points, but row 0 has 1",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                "[[[0,\"x\"]]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "control point (0, 0), coordinate 1",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                "[[[0,1e400]]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "control point (0, 0), coordinate 1",
        ),
        (
            vec!["surface", "eval", "--net", NET, "--u", "NaN", "--v", "0"],
            "invalid u",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                "[[[1,2,3,4,5]]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "5 coordinates",
        ),
        (
            vec!["surface", "tessellate", "--net", "[[[0,0],[1,1]]]"],
            "three dimensions",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                NET,
                "--weights",
                "[[1,1,1,1],[1,0,1,1],[1,1,1,1]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "weight",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                NET,
                "--weights",
                "[[1,1,1,1],[1,1,1]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "weights must form a grid",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                NET,
                "--degree-u",
                "2",
                "--knots-u",
                "[0,0,0,1,1,1,1]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "knots",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                NET,
                "--degree-u",
                "2",
                "--u",
                "2",
                "--v",
                "0",
            ],
            "outside",
        ),
        (
            vec![
                "surface",
                "eval",
                "--net",
                NET,
                "--degree-u",
                "2",
                "--u",
                "0",
                "--v",
                "0",
                "--algorithm",
                "rows-first",
            ],
            "de Boor",
        ),
        (
            vec![
                "surface",
                "restrict",
                "--net",
                NET,
                "--degree-u",
                "2",
                "--u0",
                "0",
                "--u1",
                "1",
                "--v0",
                "0",
                "--v1",
                "1",
            ],
            "Bézier patches",
        ),
        (
            vec![
                "surface",
                "interpolate",
                "--points",
                "[[[0,0,0],[0,0,0]],[[1,0,0],[1,1,1]]]",
                "--degree-u",
                "1",
                "--degree-v",
                "1",
            ],
            "coincide",
        ),
        (
            vec![
                "surface",
                "fit",
                "--points",
                "[[0,0,0]]",
                "--params",
                "[[0,0],[1,1]]",
                "--control-u",
                "2",
                "--control-v",
                "2",
                "--degree-u",
                "1",
                "--degree-v",
                "1",
            ],
            "params",
        ),
        (
            vec![
                "surface",
                "normal",
                "--net",
                "[[[0,0],[1,1]]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "three dimensions",
        ),
        (
            vec![
                "surface", "restrict", "--net", NET, "--u0", "1", "--u1", "0", "--v0", "0", "--v1",
                "1",
            ],
            "a < b",
        ),
        (
            vec![
                "surface", "restrict", "--net", NET, "--u0", "0", "--u1", "1", "--v0", "0", "--v1",
                "inf",
            ],
            "v1",
        ),
        (
            vec!["surface", "tessellate", "--net", NET, "--u-segments", "0"],
            "segments",
        ),
        (
            vec![
                "surface",
                "tessellate",
                "--net",
                NET,
                "--obj",
                "/nonexistent/dir/x.obj",
            ],
            "cannot write",
        ),
    ] {
        let err = assert_rejected(&args, None);
        assert!(err.contains(message), "{args:?}: {err}");
    }
}
