//! What can be wrong with a polygon mesh or with the Wavefront OBJ text it is read from.
//!
//! Every violation is its own variant of [`MeshError`] and names where it is: the face (its
//! index in the caller's face list), the vertex, the edge as its two vertex indices, or the
//! line of the OBJ text. The crate's [`Error`](crate::Error) carries it as
//! [`Error::Mesh`](crate::Error::Mesh).

/// A violation of the rules a [`PolygonMesh`](super::PolygonMesh) obeys, or a malformed line
/// of OBJ text.
///
/// Vertex and face indices are 0-based, as the caller's arrays count them (an OBJ file's
/// 1-based indices are converted when it is read, and its errors name the line instead).
///
/// ```
/// use compgeo::mesh::{MeshError, PolygonMesh};
/// use compgeo::spline::Point;
/// use compgeo::Error;
///
/// let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
/// let square = vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
/// // Face 1 runs along the diagonal 0 → 2, as face 0 does.
/// let e = PolygonMesh::new(square, &[vec![0, 2, 3], vec![0, 2, 1]]).unwrap_err();
/// assert_eq!(
///     e,
///     Error::Mesh(MeshError::InconsistentOrientation { face: 1, other: 0, from: 0, to: 2 })
/// );
/// assert_eq!(
///     e.to_string(),
///     "face 1 runs along the edge 0 → 2 in the same direction as face 0 (inconsistent orientation)"
/// );
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshError {
    /// A face names a vertex the mesh does not have.
    #[error("face {face} names vertex {vertex}, but the mesh has only {vertices} vertices")]
    VertexOutOfRange {
        /// The face.
        face: usize,
        /// The vertex index it names.
        vertex: usize,
        /// How many vertices the mesh has.
        vertices: usize,
    },
    /// A face has fewer than three corners.
    #[error("face {face} has {corners} corners; a face needs at least 3")]
    TooFewCorners {
        /// The face.
        face: usize,
        /// How many corners it has.
        corners: usize,
    },
    /// A face visits a vertex twice (a degenerate face).
    #[error("face {face} visits vertex {vertex} twice (degenerate face)")]
    RepeatedVertex {
        /// The face.
        face: usize,
        /// The vertex it repeats.
        vertex: usize,
    },
    /// A third face uses an edge that two faces already share.
    #[error("face {face} is the third face on the edge {from} – {to} (non-manifold edge)")]
    NonManifoldEdge {
        /// The face (in the caller's order) that makes the edge's third use.
        face: usize,
        /// One end of the edge, as the face runs along it.
        from: usize,
        /// The other end.
        to: usize,
    },
    /// Two faces run along an edge in the same direction: their orientations disagree.
    #[error(
        "face {face} runs along the edge {from} → {to} in the same direction as face {other} \
         (inconsistent orientation)"
    )]
    InconsistentOrientation {
        /// The later of the two faces.
        face: usize,
        /// The earlier face.
        other: usize,
        /// Where both faces' half-edge starts.
        from: usize,
        /// Where both end.
        to: usize,
    },
    /// The faces around a vertex do not form one fan (two cones meeting at a point, or two
    /// boundary fans sharing a vertex): the surface is not a manifold there.
    #[error(
        "vertex {vertex} is non-manifold: face {face} is not in the fan of the vertex's \
         other faces"
    )]
    NonManifoldVertex {
        /// The vertex.
        vertex: usize,
        /// A face at the vertex outside the first fan found.
        face: usize,
    },
    /// A vertex no face uses. Isolated vertices are rejected: every vertex of a mesh has a
    /// one-ring, so subdivision rules never meet a vertex without neighbours.
    #[error("vertex {vertex} is used by no face (isolated vertex)")]
    IsolatedVertex {
        /// The vertex.
        vertex: usize,
    },
    /// A line of OBJ text that cannot be read.
    #[error("OBJ line {line}: {problem}")]
    Obj {
        /// The 1-based line number.
        line: usize,
        /// What is wrong with it.
        problem: ObjProblem,
    },
    /// A scheme for triangle meshes (Loop's) met a face that is not a triangle.
    #[error("face {face} has {corners} corners; this scheme needs a triangle mesh")]
    NotATriangle {
        /// The first face that is not a triangle.
        face: usize,
        /// How many corners it has.
        corners: usize,
    },
}

/// What is wrong with a line of Wavefront OBJ text (see [`read_obj`](super::read_obj)).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ObjProblem {
    /// The line is not valid UTF-8 (comments may hold any bytes; statements may not).
    #[error("not valid UTF-8")]
    NotUtf8,
    /// A statement this reader does not support (curves, surfaces, points, lines, ...).
    #[error("unsupported statement {keyword}")]
    Unsupported {
        /// The statement's keyword, quoted.
        keyword: String,
    },
    /// A `v` line with fewer than three coordinates.
    #[error("a vertex needs three coordinates, got {got}")]
    TooFewCoordinates {
        /// How many numbers the line has.
        got: usize,
    },
    /// A number that cannot be read.
    #[error("bad number: {reason}")]
    BadNumber {
        /// Why, with the text quoted.
        reason: String,
    },
    /// A face corner that is not `v`, `v/vt`, `v//vn` or `v/vt/vn` with integers.
    #[error("bad face corner {corner}")]
    BadCorner {
        /// The corner's text, quoted.
        corner: String,
    },
    /// A face corner with vertex index 0 (OBJ indices start at 1, negative ones count back
    /// from the last vertex read).
    #[error("vertex index 0 (OBJ indices start at 1)")]
    ZeroIndex,
    /// A face corner whose index names no vertex: beyond the vertices of the file, or a
    /// negative index reaching back before the first vertex.
    #[error("vertex index {index} names no vertex ({vertices} vertices {when})")]
    IndexOutOfRange {
        /// The index as written.
        index: i64,
        /// How many vertices there are.
        vertices: usize,
        /// "read so far" for a relative index, "in the file" for an absolute one.
        when: &'static str,
    },
    /// A face line with fewer than three corners.
    #[error("a face needs at least 3 corners, got {got}")]
    TooFewCorners {
        /// How many corners the line has.
        got: usize,
    },
    /// Reading failed (an I/O error of the underlying reader).
    #[error("read error: {message}")]
    Io {
        /// The I/O error's message.
        message: String,
    },
}
