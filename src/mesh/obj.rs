//! Wavefront OBJ text in and out: the polygon part of the format (`v` and `f` lines).
//!
//! [`read_obj`] reads vertex positions (`v x y z`, further numbers such as a weight or the
//! colours some exporters append are checked to be numbers and ignored) and faces (`f` with
//! corners written `v`, `v/vt`, `v//vn` or `v/vt/vn`, 1-based, or negative to count back
//! from the last vertex read). Comments (`#` to the end of the line), blank lines and `\r\n`
//! line ends are allowed; the statements that carry no geometry of a polygon mesh
//! (`vt`, `vn`, `vp`, `g`, `o`, `s`, `usemtl`, `mtllib`) are skipped; any other statement
//! (points, lines, curves, surfaces) is an error naming its keyword. Every malformed line is
//! a [`MeshError::Obj`] with its line number, and no input, whatever its bytes, makes the
//! reader panic (a test feeds it arbitrary bytes). The faces then go through the mesh's
//! validation ([`PolygonMesh::new`]), whose errors name the face by its index among the
//! file's `f` lines, counting from 0.
//!
//! [`write_obj`] writes `v` and `f` lines; coordinates print in Rust's shortest round-trip
//! form, so reading the text back gives the same `f64` mesh (exact rationals are rounded to
//! the nearest `f64` on the way out).
//!
//! # Complexity
//!
//! Reading: linear in the text, plus the mesh validation's O(V + H log d). Writing: O(V + H).

use super::{MeshError, ObjProblem, PolygonMesh};
use crate::spline::{read_scalar, ParseScalar, Point, Scalar};
use crate::util::quote;
use crate::{limits, Error, Result};
use std::io::{self, BufRead, Write};

/// Reads a polygon mesh from Wavefront OBJ text: vertex positions (`v x y z`; further numbers,
/// such as a weight or the colours some exporters append, are checked to be numbers and
/// ignored) and faces (`f` with corners written `v`, `v/vt`, `v//vn` or `v/vt/vn`, 1-based,
/// or negative to count back from the last vertex read). Comments (`#` to the end of the
/// line, any bytes), blank lines and `\r\n` line ends are allowed; `vt`, `vn`, `vp`, `g`,
/// `o`, `s`, `usemtl` and `mtllib` lines are skipped; any other statement (points, lines,
/// curves, surfaces) is an error naming its keyword. No input, whatever its bytes, makes the
/// reader panic. Coordinates are read into `S` exactly when `S` is exact (`0.1` is 1/10 for
/// `BigRational`). The faces then go through [`PolygonMesh::new`], whose errors name a face
/// by its index among the file's `f` lines, counting from 0.
///
/// # Errors
///
/// [`MeshError::Obj`] with the line number for a malformed or unsupported line, an index
/// that names no vertex, or an I/O error of `reader`; [`Error::LimitExceeded`] beyond
/// [`MAX_MESH_VERTICES`](crate::limits::MAX_MESH_VERTICES) vertices or
/// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners; otherwise the errors of
/// [`PolygonMesh::new`] (an empty mesh, a degenerate face, a non-manifold or inconsistently
/// oriented mesh, an isolated vertex).
///
/// # Complexity
///
/// Linear in the length of the text, plus O(V + H log d) for the validation (V vertices, H
/// corners, d the most corners at one vertex).
///
/// ```
/// use compgeo::mesh::read_obj;
///
/// let text = "# a square\r\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 -2//1 -1//1\n";
/// let mesh = read_obj::<f64>(text.as_bytes())?;
/// assert_eq!((mesh.vertex_count(), mesh.face_count()), (4, 1));
/// assert_eq!(mesh.face_vertices(0), [0, 1, 2, 3]);
/// assert_eq!(
///     read_obj::<f64>("v 0 0 0\nf 1 2 x\n".as_bytes()).unwrap_err().to_string(),
///     "OBJ line 2: bad face corner \"x\""
/// );
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn read_obj<S: Scalar + ParseScalar>(reader: impl BufRead) -> Result<PolygonMesh<S, 3>> {
    let mut reader = reader;
    let mut positions: Vec<Point<S, 3>> = Vec::new();
    let mut offsets = vec![0usize];
    let mut corners: Vec<usize> = Vec::new();
    // The line of every face, and the corners written as absolute indices (checked at the
    // end, when the vertex count is known).
    let mut face_lines: Vec<usize> = Vec::new();
    let mut absolute: Vec<(usize, i64)> = Vec::new();
    let mut buf = Vec::new();
    let mut line = 0usize;
    loop {
        buf.clear();
        line += 1;
        let read = reader.read_until(b'\n', &mut buf).map_err(|e| {
            obj_error(
                line,
                ObjProblem::Io {
                    message: e.to_string(),
                },
            )
        })?;
        if read == 0 {
            break;
        }
        // A comment runs to the end of the line; '#' is one byte in UTF-8, so the cut is
        // made before decoding and a comment may hold any bytes.
        let content = match buf.iter().position(|&b| b == b'#') {
            Some(i) => &buf[..i],
            None => &buf[..],
        };
        let text =
            std::str::from_utf8(content).map_err(|_| obj_error(line, ObjProblem::NotUtf8))?;
        let mut tokens = text.split_ascii_whitespace();
        let Some(keyword) = tokens.next() else {
            continue;
        };
        match keyword {
            "v" => {
                let mut coords = Vec::with_capacity(3);
                for token in tokens {
                    let x = read_scalar::<S>(token)
                        .map_err(|reason| obj_error(line, ObjProblem::BadNumber { reason }))?;
                    if coords.len() < 3 {
                        coords.push(x);
                    }
                }
                let Ok(coords) = <[S; 3]>::try_from(coords) else {
                    let got = text.split_ascii_whitespace().count() - 1;
                    return Err(obj_error(line, ObjProblem::TooFewCoordinates { got }));
                };
                limits::MESH_VERTICES.check(positions.len() as u128 + 1)?;
                positions.push(Point::new(coords));
            }
            "f" | "fo" => {
                let face_start = corners.len();
                for token in tokens {
                    let index = corner_index(token).ok_or_else(|| {
                        obj_error(
                            line,
                            ObjProblem::BadCorner {
                                corner: quote(token),
                            },
                        )
                    })?;
                    let vertex = match index {
                        0 => return Err(obj_error(line, ObjProblem::ZeroIndex)),
                        i if i > 0 => {
                            absolute.push((corners.len(), i));
                            (i - 1) as usize
                        }
                        i => {
                            let back = i.unsigned_abs();
                            if back > positions.len() as u64 {
                                return Err(obj_error(
                                    line,
                                    ObjProblem::IndexOutOfRange {
                                        index: i,
                                        vertices: positions.len(),
                                        when: "read so far",
                                    },
                                ));
                            }
                            positions.len() - back as usize
                        }
                    };
                    limits::MESH_CORNERS.check(corners.len() as u128 + 1)?;
                    corners.push(vertex);
                }
                let got = corners.len() - face_start;
                if got < 3 {
                    return Err(obj_error(line, ObjProblem::TooFewCorners { got }));
                }
                offsets.push(corners.len());
                face_lines.push(line);
            }
            "vt" | "vn" | "vp" | "g" | "o" | "s" | "usemtl" | "mtllib" => {}
            other => {
                return Err(obj_error(
                    line,
                    ObjProblem::Unsupported {
                        keyword: quote(other),
                    },
                ))
            }
        }
    }
    // Absolute indices may name vertices defined after the face; all must exist now.
    for &(corner, index) in &absolute {
        if corners[corner] >= positions.len() {
            let face = offsets.partition_point(|&o| o <= corner) - 1;
            return Err(obj_error(
                face_lines[face],
                ObjProblem::IndexOutOfRange {
                    index,
                    vertices: positions.len(),
                    when: "in the file",
                },
            ));
        }
    }
    PolygonMesh::from_offsets(positions, &offsets, &corners)
}

/// Writes `mesh` as Wavefront OBJ: a comment line with the counts, one `v` line per vertex
/// and one `f` line per face (1-based indices, counter-clockwise as stored). Coordinates are
/// printed as the nearest `f64` in shortest round-trip form.
///
/// # Errors
///
/// Whatever `out` reports.
///
/// # Complexity
///
/// O(V + H) time for V vertices and H corners, O(1) auxiliary space.
///
/// ```
/// use compgeo::mesh::{read_obj, write_obj, PolygonMesh};
/// use compgeo::spline::Point;
///
/// let p = |x: f64, y: f64| Point::new([x, y, 0.1]);
/// let mesh = PolygonMesh::new(vec![p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)], &[[0, 1, 2]])?;
/// let mut text = Vec::new();
/// write_obj(&mesh, &mut text).unwrap();
/// assert!(String::from_utf8(text.clone()).unwrap().ends_with("v 0 1 0.1\nf 1 2 3\n"));
/// assert_eq!(read_obj::<f64>(&text[..])?, mesh);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn write_obj<S: Scalar, W: Write>(mesh: &PolygonMesh<S, 3>, out: &mut W) -> io::Result<()> {
    writeln!(
        out,
        "# compgeo polygon mesh: {} vertices, {} faces",
        mesh.vertex_count(),
        mesh.face_count()
    )?;
    for p in mesh.positions() {
        let [x, y, z] = p.to_f64().0;
        writeln!(out, "v {x} {y} {z}")?;
    }
    let t = mesh.topology();
    for f in 0..t.face_count() {
        out.write_all(b"f")?;
        for &v in t.face_vertices(f) {
            write!(out, " {}", v as u64 + 1)?;
        }
        out.write_all(b"\n")?;
    }
    Ok(())
}

/// The vertex index of a face corner `v`, `v/vt`, `v//vn` or `v/vt/vn` (the texture and
/// normal indices, when present, must be integers too); `None` otherwise.
fn corner_index(token: &str) -> Option<i64> {
    let mut parts = token.split('/');
    let vertex = parts.next()?.parse::<i64>().ok()?;
    let mut rest = 0;
    for part in parts {
        rest += 1;
        if rest > 2 || (!part.is_empty() && part.parse::<i64>().is_err()) {
            return None;
        }
    }
    Some(vertex)
}

fn obj_error(line: usize, problem: ObjProblem) -> Error {
    Error::Mesh(MeshError::Obj { line, problem })
}
