//! Export of a [`TriangleMesh`] in the two formats every viewer reads: Wavefront OBJ (vertex
//! positions `v`, normals `vn`, faces `f a//a b//b c//c` with 1-based indices) and ASCII STL
//! (one `facet normal … outer loop … endloop endfacet` per triangle, the facet normal being
//! the triangle's own).
//!
//! Numbers print in Rust's shortest round-trip form, so a reader recovers every `f64` of the
//! mesh exactly. The writers take any [`Write`]: a file, a buffer, standard output.
//!
//! # Complexity
//!
//! Θ(N + T) time for N vertices and T triangles, O(1) auxiliary space.

use super::tessellate::{triangle_normal, TriangleMesh};
use std::io::{self, Write};

impl TriangleMesh {
    /// Writes the mesh as Wavefront OBJ: a comment line, the `v` lines, the `vn` lines (one
    /// per vertex, in the same order) and one `f` line per triangle, each corner giving its
    /// vertex and normal index (1-based, the same number).
    ///
    /// # Errors
    ///
    /// Whatever `out` reports.
    ///
    /// # Complexity
    ///
    /// Θ(N + T) time, O(1) auxiliary space.
    ///
    /// ```
    /// use compgeo::surface::TriangleMesh;
    ///
    /// let mesh = TriangleMesh {
    ///     positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
    ///     normals: vec![[0.0, 0.0, 1.0]; 3],
    ///     triangles: vec![[0, 1, 2]],
    /// };
    /// let mut out = Vec::new();
    /// mesh.write_obj(&mut out)?;
    /// let text = String::from_utf8(out).unwrap();
    /// assert!(text.contains("v 1 0 0\n") && text.contains("f 1//1 2//2 3//3\n"));
    /// # Ok::<(), std::io::Error>(())
    /// ```
    pub fn write_obj<W: Write>(&self, out: &mut W) -> io::Result<()> {
        writeln!(
            out,
            "# compgeo tessellation: {} vertices, {} triangles",
            self.positions.len(),
            self.triangles.len()
        )?;
        for [x, y, z] in &self.positions {
            writeln!(out, "v {x} {y} {z}")?;
        }
        for [x, y, z] in &self.normals {
            writeln!(out, "vn {x} {y} {z}")?;
        }
        for [a, b, c] in &self.triangles {
            let (a, b, c) = (a + 1, b + 1, c + 1);
            writeln!(out, "f {a}//{a} {b}//{b} {c}//{c}")?;
        }
        Ok(())
    }

    /// Writes the mesh as ASCII STL named `name` (spaces become underscores, as the format's
    /// `solid name` line allows one word): one facet per triangle with the triangle's unit
    /// normal (zero for a degenerate triangle) and its three vertices.
    ///
    /// # Errors
    ///
    /// Whatever `out` reports.
    ///
    /// # Complexity
    ///
    /// Θ(T) time, O(1) auxiliary space.
    ///
    /// ```
    /// use compgeo::surface::TriangleMesh;
    ///
    /// let mesh = TriangleMesh {
    ///     positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
    ///     normals: vec![[0.0, 0.0, 1.0]; 3],
    ///     triangles: vec![[0, 1, 2]],
    /// };
    /// let mut out = Vec::new();
    /// mesh.write_stl("corner", &mut out)?;
    /// let text = String::from_utf8(out).unwrap();
    /// assert!(text.starts_with("solid corner\n  facet normal 0 0 1\n"));
    /// assert!(text.ends_with("endsolid corner\n"));
    /// # Ok::<(), std::io::Error>(())
    /// ```
    pub fn write_stl<W: Write>(&self, name: &str, out: &mut W) -> io::Result<()> {
        let name: String = name
            .chars()
            .map(|c| if c.is_whitespace() { '_' } else { c })
            .collect();
        writeln!(out, "solid {name}")?;
        for t in &self.triangles {
            let [a, b, c] = t.map(|k| self.positions[k]);
            let [nx, ny, nz] = triangle_normal(&a, &b, &c);
            writeln!(out, "  facet normal {nx} {ny} {nz}")?;
            writeln!(out, "    outer loop")?;
            for [x, y, z] in [a, b, c] {
                writeln!(out, "      vertex {x} {y} {z}")?;
            }
            writeln!(out, "    endloop")?;
            writeln!(out, "  endfacet")?;
        }
        writeln!(out, "endsolid {name}")
    }
}
