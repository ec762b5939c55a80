//! Seeded polygon meshes: regular grids and tori (the regular cases every subdivision scheme
//! must reproduce), a cube (extraordinary vertices of valence 3), and irregular meshes with
//! vertices of many valences and faces of several sizes.
//!
//! Coordinates come from integer arithmetic and correctly rounded `+ - * /` only: the tori's
//! circles use a Taylor series rather than the platform's `sin` and `cos`, so every mesh is
//! bit-identical on every machine.

use super::rng::Rng;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::mesh::PolygonMesh;
use crate::spline::Point;
use crate::util::named_enum;
use crate::{limits, Error};

named_enum! {
    /// The family a generated polygon mesh belongs to (see [`mesh`]).
    ///
    /// ```
    /// use compgeo::gen::MeshKind;
    ///
    /// assert_eq!("quad-torus".parse::<MeshKind>()?, MeshKind::QuadTorus);
    /// assert!("teapot".parse::<MeshKind>().is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum MeshKind ("mesh kind") {
        /// A planar grid of unit squares ([`quad_grid`]): boundary, interior valence 4.
        QuadGrid = "quad-grid",
        /// A planar grid of unit squares each cut along the same diagonal
        /// ([`triangle_grid`]): boundary, interior valence 6.
        TriangleGrid = "triangle-grid",
        /// A closed torus of quadrilaterals ([`quad_torus`]): every vertex of valence 4.
        QuadTorus = "quad-torus",
        /// A closed torus of triangles ([`triangle_torus`]): every vertex of valence 6.
        TriangleTorus = "triangle-torus",
        /// A closed torus of triangles, quadrilaterals and hexagons with vertices of
        /// valence 3 to 6 ([`irregular_torus`]), seeded.
        IrregularTorus = "irregular-torus",
        /// A disk of triangles and quadrilaterals over random points (a Delaunay
        /// triangulation with random pairs of triangles merged), seeded
        /// ([`irregular_disk`]): many valences and a boundary.
        IrregularDisk = "irregular-disk",
    }
}

/// A mesh of `kind` with about `faces` faces (the grids and tori take the nearest shape at
/// least that large: a quad torus of 10⁴ faces is 100 × 100), from `seed` where random.
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"faces"` for 0 faces; [`Error::LimitExceeded`] beyond
/// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners.
///
/// # Complexity
///
/// O(F) time and space for F faces (O(F log F) for the irregular disk, which triangulates).
///
/// ```
/// use compgeo::gen::{mesh, MeshKind};
///
/// let torus = mesh(MeshKind::QuadTorus, 10_000, 0)?;
/// assert_eq!((torus.face_count(), torus.euler_characteristic()), (10_000, 0));
/// let disk = mesh(MeshKind::IrregularDisk, 1000, 7)?;
/// assert_eq!(disk.euler_characteristic(), 1);
/// assert_eq!(disk, mesh(MeshKind::IrregularDisk, 1000, 7)?);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn mesh(kind: MeshKind, faces: usize, seed: u64) -> Result<PolygonMesh<f64, 3>> {
    if faces == 0 {
        return Err(Error::InvalidParameter {
            name: "faces",
            reason: "a mesh needs at least one face".into(),
        });
    }
    limits::MESH_CORNERS.check(4 * faces as u128)?;
    // The smallest side s with s² ≥ n (and at least `min`).
    let side = |n: usize, min: usize| ceil_sqrt(n).max(min);
    match kind {
        MeshKind::QuadGrid => {
            let s = side(faces, 1);
            quad_grid(s, faces.div_ceil(s))
        }
        MeshKind::TriangleGrid => {
            let s = side(faces.div_ceil(2), 1);
            triangle_grid(s, faces.div_ceil(2).div_ceil(s))
        }
        MeshKind::QuadTorus => {
            let s = side(faces, 3);
            quad_torus(s, faces.div_ceil(s).max(3))
        }
        MeshKind::TriangleTorus => {
            let s = side(faces.div_ceil(2), 3);
            triangle_torus(s, faces.div_ceil(2).div_ceil(s).max(3))
        }
        MeshKind::IrregularTorus => {
            let s = side(faces, 4);
            irregular_torus(s, faces.div_ceil(s).max(4), seed)
        }
        MeshKind::IrregularDisk => irregular_disk(faces.div_ceil(2).max(3), seed),
    }
}

/// A planar grid of `rows` × `cols` unit squares in the plane z = 0: vertex
/// `i·(cols + 1) + j` at (j, i, 0), face `i·cols + j` the square
/// [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)], counter-clockwise seen from +z.
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"size"` if a side is 0; [`Error::LimitExceeded`]
/// beyond [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners.
///
/// ```
/// use compgeo::gen::quad_grid;
///
/// let g = quad_grid(2, 3)?;
/// assert_eq!((g.vertex_count(), g.edge_count(), g.face_count()), (12, 17, 6));
/// assert_eq!(g.face_vertices(0), [0, 1, 5, 4]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn quad_grid(rows: usize, cols: usize) -> Result<PolygonMesh<f64, 3>> {
    check_sides(rows, cols, 1, 4)?;
    let id = |i: usize, j: usize| i * (cols + 1) + j;
    let mut faces = Vec::with_capacity(rows * cols);
    for i in 0..rows {
        for j in 0..cols {
            faces.push([id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)]);
        }
    }
    PolygonMesh::new(grid_positions(rows, cols), &faces)
}

/// The grid of [`quad_grid`] with every square cut along its diagonal (i, j) – (i + 1, j + 1)
/// into the triangles [(i, j), (i, j + 1), (i + 1, j + 1)] and [(i, j), (i + 1, j + 1),
/// (i + 1, j)] (faces 2(i·cols + j) and 2(i·cols + j) + 1): the three-directional grid, every
/// interior vertex of valence 6.
///
/// # Errors
///
/// As [`quad_grid`].
///
/// ```
/// use compgeo::gen::triangle_grid;
///
/// let g = triangle_grid(3, 3)?;
/// assert_eq!(g.face_count(), 18);
/// assert_eq!(g.topology().valence(5), 6); // the interior vertex (1, 1)
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn triangle_grid(rows: usize, cols: usize) -> Result<PolygonMesh<f64, 3>> {
    check_sides(rows, cols, 1, 6)?;
    let id = |i: usize, j: usize| i * (cols + 1) + j;
    let mut faces = Vec::with_capacity(2 * rows * cols);
    for i in 0..rows {
        for j in 0..cols {
            faces.push([id(i, j), id(i, j + 1), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i + 1, j)]);
        }
    }
    PolygonMesh::new(grid_positions(rows, cols), &faces)
}

/// The cube [−1, 1]³ as six quadrilaterals, counter-clockwise seen from outside: vertex
/// `4x + 2y + z` (x, y, z ∈ {0, 1}) at (2x − 1, 2y − 1, 2z − 1). Every vertex has valence 3.
///
/// ```
/// use compgeo::gen::cube;
///
/// let c = cube();
/// assert_eq!((c.vertex_count(), c.edge_count(), c.face_count()), (8, 12, 6));
/// assert_eq!(c.euler_characteristic(), 2);
/// ```
pub fn cube() -> PolygonMesh<f64, 3> {
    let positions = (0..8)
        .map(|k| {
            let bit = |b: usize| if k >> b & 1 == 1 { 1.0 } else { -1.0 };
            Point::new([bit(2), bit(1), bit(0)])
        })
        .collect();
    let faces = [
        [0, 1, 3, 2], // x = −1
        [4, 6, 7, 5], // x = +1
        [0, 4, 5, 1], // y = −1
        [2, 3, 7, 6], // y = +1
        [0, 2, 6, 4], // z = −1
        [1, 5, 7, 3], // z = +1
    ];
    PolygonMesh::new(positions, &faces).expect("the cube is a valid closed mesh")
}

/// A torus of `m` × `n` quadrilaterals (`m` around the axis, `n` around the tube), major
/// radius 2 and minor radius 1 about the z axis: vertex `i·n + j` at angle 2πi/m around the
/// axis and 2πj/n around the tube; face `i·n + j` is
/// [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)] (indices modulo m and n),
/// counter-clockwise seen from outside. Closed, every vertex of valence 4, Euler
/// characteristic 0.
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"size"` if a side is below 3 (two rows would join a
/// vertex to itself along two different edges); [`Error::LimitExceeded`] beyond
/// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners.
///
/// ```
/// use compgeo::gen::quad_torus;
///
/// let t = quad_torus(8, 5)?;
/// assert_eq!((t.vertex_count(), t.edge_count(), t.face_count()), (40, 80, 40));
/// assert!(t.topology().is_closed());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn quad_torus(m: usize, n: usize) -> Result<PolygonMesh<f64, 3>> {
    check_sides(m, n, 3, 4)?;
    PolygonMesh::new(torus_positions(m, n), &torus_cells(m, n))
}

/// The torus of [`quad_torus`] with every quadrilateral cut along its diagonal
/// (i, j) – (i + 1, j + 1): 2mn triangles, every vertex of valence 6.
///
/// # Errors
///
/// As [`quad_torus`].
///
/// ```
/// use compgeo::gen::triangle_torus;
///
/// let t = triangle_torus(6, 4)?;
/// assert_eq!((t.face_count(), t.euler_characteristic()), (48, 0));
/// assert!((0..24).all(|v| t.topology().valence(v) == 6));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn triangle_torus(m: usize, n: usize) -> Result<PolygonMesh<f64, 3>> {
    check_sides(m, n, 3, 6)?;
    let faces: Vec<[usize; 3]> = torus_cells(m, n)
        .into_iter()
        .flat_map(|[a, b, c, d]| [[a, b, c], [a, c, d]])
        .collect();
    PolygonMesh::new(torus_positions(m, n), &faces)
}

/// The torus of [`quad_torus`] made irregular from `seed`: in rows i of even index (below
/// m − 1), a random third of the pairs of cells (i, j), (i, j + 1) with j even are merged
/// into hexagons (their two shared-edge vertices drop to valence 3); a random third of the
/// remaining cells are cut into two triangles along (i, j) – (i + 1, j + 1) (those vertices
/// rise to valence 5 or 6). Closed, Euler characteristic 0, faces of 3, 4 and 6 corners.
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"size"` if a side is below 4; [`Error::LimitExceeded`]
/// beyond [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners.
///
/// ```
/// use compgeo::gen::irregular_torus;
///
/// let t = irregular_torus(10, 10, 3)?;
/// assert_eq!(t.euler_characteristic(), 0);
/// let valences: Vec<usize> = (0..100).map(|v| t.topology().valence(v)).collect();
/// assert!(valences.contains(&3) && valences.contains(&4) && valences.contains(&5));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn irregular_torus(m: usize, n: usize, seed: u64) -> Result<PolygonMesh<f64, 3>> {
    check_sides(m, n, 4, 6)?;
    let cells = torus_cells(m, n);
    let mut rng = Rng::new(seed);
    let mut faces: Vec<Vec<usize>> = Vec::with_capacity(2 * m * n);
    for i in 0..m {
        let mut j = 0;
        while j < n {
            let [a, b, c, d] = cells[i * n + j];
            let pair = i % 2 == 0 && i + 1 < m && j % 2 == 0 && j + 1 < n;
            if pair && rng.below(3) == 0 {
                // Cells (i, j) = [a, b, c, d] and (i, j + 1) = [d, c, c', d'] without the
                // edge c – d: the hexagon [a, b, c, c', d', d].
                let [_, _, c2, d2] = cells[i * n + j + 1];
                faces.push(vec![a, b, c, c2, d2, d]);
                j += 2;
                continue;
            }
            if rng.below(3) == 0 {
                faces.push(vec![a, b, c]);
                faces.push(vec![a, c, d]);
            } else {
                faces.push(vec![a, b, c, d]);
            }
            j += 1;
        }
    }
    PolygonMesh::new(torus_positions(m, n), &faces)
}

/// A disk over `points` random points in the unit square (from
/// [`PointKind::UniformSquare`] and `seed`): their Delaunay triangulation with about a third
/// of the triangles merged with a neighbour into quadrilaterals (seeded), lifted to random
/// heights z ∈ [0, 1/4). Vertices of many valences, one boundary loop (Euler
/// characteristic 1); vertices no triangle uses (duplicates) are left out.
///
/// # Errors
///
/// [`Error::TooFew`] below 3 points; the errors of [`points`].
///
/// ```
/// use compgeo::gen::irregular_disk;
///
/// let d = irregular_disk(200, 1)?;
/// assert_eq!(d.topology().boundary_loop_count(), 1);
/// assert!(d.face_count() > 200);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn irregular_disk(points_count: usize, seed: u64) -> Result<PolygonMesh<f64, 3>> {
    if points_count < 3 {
        return Err(Error::TooFew {
            what: "irregular disk points",
            needed: 3,
            got: points_count,
        });
    }
    limits::MESH_CORNERS.check(6 * points_count as u128)?;
    let pts = points(PointKind::UniformSquare, points_count, seed)?;
    let t = crate::delaunay::incremental(&pts)?;
    let tri_count = t.triangle_count();
    if tri_count == 0 {
        return Err(Error::TooFew {
            what: "irregular disk triangles",
            needed: 1,
            got: 0,
        });
    }
    let mut rng = Rng::with_stream(seed, 1);
    let mut order: Vec<usize> = (0..tri_count).collect();
    rng.shuffle(&mut order);
    let mut merged = vec![false; tri_count];
    let mut faces: Vec<Vec<usize>> = Vec::with_capacity(tri_count);
    for &a in &order {
        if merged[a] || rng.below(3) != 0 {
            continue;
        }
        let k = rng.index(3);
        let e = 3 * a + k;
        let opposite = t.halfedges[e];
        if opposite == crate::delaunay::EMPTY || merged[opposite / 3] {
            continue;
        }
        let b = opposite / 3;
        // Triangle a is (p, q, r) from e = p → q, triangle b has q → p and its third corner s:
        // the quadrilateral [p, s, q, r].
        let p = t.triangles[e];
        let q = t.triangles[3 * a + (k + 1) % 3];
        let r = t.triangles[3 * a + (k + 2) % 3];
        let s = t.triangles[3 * b + (opposite % 3 + 2) % 3];
        faces.push(vec![p, s, q, r]);
        merged[a] = true;
        merged[b] = true;
    }
    for (triangle, _) in t.triangles.chunks(3).zip(&merged).filter(|(_, &m)| !m) {
        faces.push(triangle.to_vec());
    }
    // Keep only the vertices some face uses, in their original order.
    let mut new_id = vec![usize::MAX; pts.len()];
    for face in &faces {
        for &v in face {
            new_id[v] = 0;
        }
    }
    let mut positions = Vec::new();
    let mut heights = Rng::with_stream(seed, 2);
    for (v, id) in new_id.iter_mut().enumerate() {
        if *id == 0 {
            *id = positions.len();
            positions.push(Point::new([pts[v].x, pts[v].y, heights.unit() / 4.0]));
        }
    }
    for face in &mut faces {
        for v in face.iter_mut() {
            *v = new_id[*v];
        }
    }
    PolygonMesh::new(positions, &faces)
}

/// Both sides at least `min`, and the corners (`per_cell` a cell at most) within the limit.
fn check_sides(a: usize, b: usize, min: usize, per_cell: u128) -> Result<()> {
    if a < min || b < min {
        return Err(Error::InvalidParameter {
            name: "size",
            reason: format!("each side needs at least {min} cells, got {a} × {b}"),
        });
    }
    limits::MESH_CORNERS.check(a as u128 * b as u128 * per_cell)?;
    Ok(())
}

/// The vertices of a (rows + 1) × (cols + 1) grid at (j, i, 0), row by row.
fn grid_positions(rows: usize, cols: usize) -> Vec<Point<f64, 3>> {
    (0..=rows)
        .flat_map(|i| (0..=cols).map(move |j| Point::new([j as f64, i as f64, 0.0])))
        .collect()
}

/// The cells of an m × n torus grid as quadrilaterals, cell i·n + j first.
fn torus_cells(m: usize, n: usize) -> Vec<[usize; 4]> {
    let id = |i: usize, j: usize| (i % m) * n + j % n;
    (0..m)
        .flat_map(|i| (0..n).map(move |j| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]))
        .collect()
}

/// The torus of major radius 2 and minor radius 1: vertex i·n + j at the angles 2πi/m and
/// 2πj/n.
fn torus_positions(m: usize, n: usize) -> Vec<Point<f64, 3>> {
    let around: Vec<(f64, f64)> = (0..m).map(|i| cos_sin(i, m)).collect();
    let tube: Vec<(f64, f64)> = (0..n).map(|j| cos_sin(j, n)).collect();
    let mut out = Vec::with_capacity(m * n);
    for &(cu, su) in &around {
        for &(cv, sv) in &tube {
            let r = 2.0 + cv;
            out.push(Point::new([r * cu, r * su, sv]));
        }
    }
    out
}

/// (cos θ, sin θ) for θ = 2πk/n, by Taylor series on θ reduced to (−π, π] (only correctly
/// rounded operations, so the same bits everywhere; accurate to a few ulps).
fn cos_sin(k: usize, n: usize) -> (f64, f64) {
    let k = k % n;
    // k/n in (−1/2, 1/2].
    let signed = if 2 * k > n {
        k as f64 - n as f64
    } else {
        k as f64
    };
    let x = 2.0 * std::f64::consts::PI * signed / n as f64;
    let x2 = x * x;
    let (mut c, mut s) = (1.0, 1.0);
    // Horner from the 30th term down: cos = Σ (−x²)^i / (2i)!, sin = x Σ (−x²)^i / (2i + 1)!.
    for i in (1..=30).rev() {
        let i = f64::from(i);
        c = 1.0 - x2 / ((2.0 * i - 1.0) * (2.0 * i)) * c;
        s = 1.0 - x2 / ((2.0 * i) * (2.0 * i + 1.0)) * s;
    }
    (c, x * s)
}

/// ⌈√n⌉, exactly.
fn ceil_sqrt(n: usize) -> usize {
    super::points::ceil_sqrt(n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cos_sin_is_close_to_the_platform_functions() {
        for n in [3, 4, 7, 100, 1000] {
            for k in 0..n {
                let (c, s) = cos_sin(k, n);
                let t = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
                assert!((c - t.cos()).abs() < 1e-14 && (s - t.sin()).abs() < 1e-14);
            }
        }
        assert_eq!(cos_sin(0, 5), (1.0, 0.0));
    }
}
