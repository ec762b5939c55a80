//! Loop subdivision of triangle meshes: every triangle split into four, every point an
//! affine combination of its coarse neighbours; the limit positions in closed form.
//!
//! The problem: a smooth surface from a triangle mesh of any connectivity. The idea
//! [PPB, §15.7–15.8, §16.8–16.9 Ex. 3]: on a regular triangular grid the three-direction
//! box spline of degree four (directions e₁, e₂, e₃ twice each) is refined by the linear
//! refinement 𝓡 (every triangle into four at its edges' midpoints) followed by Boehm's
//! symmetric averaging 𝒜₁𝒜₂𝒜₃; as masks, a new point on an edge is
//! ⅜(a + b) + ⅛(c + d) (a, b the edge's ends, c, d the vertices opposite it) and a new
//! point at a vertex v of valence n is (1 − nβ)v + βΣvᵢ over its neighbours vᵢ, with
//! β = 1/16 (α = 1 − nβ = 5/8) for n = 6. Loop generalised the vertex mask to any valence
//! [Loop 1987, in PPB, §16.9, Ex. 3]:
//!
//! β(n) = (1/n)(5/8 − (3/8 + ¼cos(2π/n))²),  α(n) = 1 − nβ(n) = 3/8 + (3/8 + ¼cos(2π/n))²,
//!
//! which lies inside the interval −¼cos(2π/n) < α(n) < ¾ + ¼cos(2π/n) of tangent-plane
//! continuity, and α(6) = 5/8. [`LoopWeights::Warren`] is Warren's rational choice
//! β = 3/(8n) for n > 3 and 3/16 for n ≤ 3.
//!
//! # Exact arithmetic and cos(2π/n)
//!
//! cos(2π/n) is rational only for n ∈ {1, 2, 3, 4, 6} (−½·… : 1, −1, −½, 0, ½). For those
//! valences the weights are exact (β(3) = 3/16, β(4) = 31/256, β(6) = 1/16). For any other
//! valence, cos(2π/n) is the `f64` value of the platform's cosine, converted **exactly** to
//! the scalar ([`Scalar::from_f64`]); β is computed from it in the scalar's arithmetic and the
//! centre weight is 1 − nβ in that arithmetic, so with exact rationals every vertex rule is an
//! exact affine combination (its weights sum to 1 exactly) of a β within about 10⁻¹⁶ of
//! Loop's. [`LoopWeights::Warren`] is rational throughout.
//!
//! # Boundaries
//!
//! A boundary edge's new point is its midpoint, and a boundary vertex's is (a + 6v + b)/8
//! with a and b its two neighbours along the boundary: the boundary polygon is subdivided as
//! a closed cubic B-spline (Lane–Riesenfeld of degree 3, [PPB, §8.4]) that depends on the
//! boundary alone, so meshes sharing a boundary stay joined. Interior edges and vertices use
//! the rules above even next to the boundary.
//!
//! An inner vertex of valence 2 (two triangles folded onto each other) is refined like any
//! other (β(2) = 39/128); the result's half-edges are valid, but two of its edges may join
//! the same two vertices, which a face list read back through validation does not allow.
//!
//! # Limit positions
//!
//! Each vertex converges to a point given by a left eigenvector of the local subdivision
//! matrix: (1 − nγ)v + γΣvᵢ with γ = β/(3/8 + nβ) inside (γ = 1/12 for n = 6, the
//! quartic box spline's value at a grid point), and (a + 4v + b)/6 on the boundary (the cubic
//! B-spline's). With the same β as the rounds, one round maps these weights to themselves
//! exactly, so the limit positions of a mesh and of its refinements agree exactly in
//! rationals, whatever the valence.
//!
//! # Complexity
//!
//! One round of a mesh with V vertices, E edges and F triangles: Θ((V + E + F)·D) time and
//! space; k rounds Θ(F·4^k·D), the last round dominating (F·4^k triangles). The connectivity
//! is built by index arithmetic from the coarse half-edges (`triangle_split.rs`).
//!
//! Invariants the tests check (exactly, on rationals): on a periodic regular triangular grid
//! every round is the quartic box-spline rule B₁₁₂ of [PPB, §15.7] (an oracle written from
//! the course's operators); counts F·4ᵏ, V + E, 2E + 3F per round and the Euler
//! characteristic kept; the half-edge invariants of every result; α(6) = 5/8 and α(n) in
//! Loop's interval; the boundary is cubic B-spline subdivision of the boundary polygon; the
//! limit positions are fixed by a round; non-triangle meshes are rejected by name.

use super::topology::MeshTopology;
use super::triangle_split::{triangle_corners, triangle_split};
use super::{MeshError, PolygonMesh};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};
use crate::{limits, Error, Result};

/// Loop subdivision, declared.
pub(crate) const LOOP: Declaration = Declaration {
    problem: "mesh-subdivision",
    name: "loop",
    function: "mesh::loop_subdivision",
    file: "src/mesh/loop_subdivision.rs",
    summary: "k rounds of Loop's scheme on a triangle mesh: every triangle into four, edge points ⅜, ⅜, ⅛, ⅛ and vertex points (1 − nβ)v + βΣvᵢ",
    time: "Θ(F·4^k·D) for F triangles",
    space: "Θ(F·4^k·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per stencil term: n + 1 per inner vertex of valence n, 3 per boundary vertex, 4 per inner edge, 2 per boundary edge; V + 6E per round on a closed mesh",
    source: "[PPB, §15.7–15.8, §16.8–16.9]",
    claims: &[
        on("triangle-torus", Bound::Linear, Operation::ArithmeticOperations),
        on(
            "irregular-torus",
            Bound::Linear,
            Operation::ArithmeticOperations,
        ),
    ],
};

/// Loop's limit positions, declared.
pub(crate) const LOOP_LIMIT: Declaration = Declaration {
    problem: "mesh-subdivision",
    name: "loop-limit",
    function: "mesh::loop_limit_points",
    file: "src/mesh/loop_subdivision.rs",
    summary: "where each vertex of a triangle mesh goes under Loop subdivision: (1 − nγ)v + γΣvᵢ with γ = β/(3/8 + nβ), (a + 4v + b)/6 on the boundary",
    time: "Θ((V + F)·D)",
    space: "Θ(V·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per stencil term: n + 1 per inner vertex of valence n, 3 per boundary vertex",
    source: "[PPB, §16.4–16.6, §16.9]",
    claims: &[on(
        "irregular-torus",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The vertex weights of Loop's scheme: β(n) on each of the n neighbours of an inner vertex
/// of valence n, α(n) = 1 − nβ(n) on the vertex.
///
/// ```
/// use compgeo::mesh::LoopWeights;
///
/// assert_eq!(LoopWeights::Loop.alpha::<f64>(6), 0.625);
/// assert_eq!(LoopWeights::Loop.beta::<f64>(3), 0.1875);
/// assert_eq!(LoopWeights::Warren.beta::<f64>(8), 3.0 / 64.0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LoopWeights {
    /// Loop's β(n) = (1/n)(5/8 − (3/8 + ¼cos(2π/n))²) [Loop 1987].
    #[default]
    Loop,
    /// Warren's β(n) = 3/(8n) for n > 3, 3/16 for n ≤ 3: rational for every valence.
    Warren,
}

impl LoopWeights {
    /// β(n), the weight of each neighbour of an inner vertex of valence n ≥ 1 (see the
    /// module docs for how cos(2π/n) is taken when it is irrational).
    ///
    /// # Panics
    ///
    /// If n = 0.
    ///
    /// # Complexity
    ///
    /// O(1).
    pub fn beta<S: Scalar>(self, n: usize) -> S {
        assert!(n > 0, "a vertex of valence 0 has no Loop weight");
        let count = S::from_i64(n as i64);
        match self {
            LoopWeights::Warren if n <= 3 => S::from_ratio(3, 16),
            LoopWeights::Warren => S::from_ratio(3, 8) / count,
            LoopWeights::Loop => {
                let c = cos_two_pi_over::<S>(n);
                let inner = S::from_ratio(3, 8) + c / S::from_i64(4);
                (S::from_ratio(5, 8) - inner.clone() * inner) / count
            }
        }
    }

    /// α(n) = 1 − nβ(n), the weight of an inner vertex of valence n ≥ 1 on its own new
    /// point: 5/8 for n = 6.
    ///
    /// # Panics
    ///
    /// If n = 0.
    ///
    /// # Complexity
    ///
    /// O(1).
    pub fn alpha<S: Scalar>(self, n: usize) -> S {
        S::one() - S::from_i64(n as i64) * self.beta::<S>(n)
    }
}

/// cos(2π/n): exact where it is rational, else the `f64` cosine converted exactly.
fn cos_two_pi_over<S: Scalar>(n: usize) -> S {
    match n {
        1 => S::one(),
        2 => S::from_i64(-1),
        3 => S::from_ratio(-1, 2),
        4 => S::zero(),
        6 => S::from_ratio(1, 2),
        _ => {
            let c = (2.0 * std::f64::consts::PI / n as f64).cos();
            S::from_f64(c).expect("a cosine is finite")
        }
    }
}

/// `rounds` rounds of Loop subdivision of a triangle mesh with Loop's weights. See
/// [`loop_subdivision_weighted_with`] (the algorithm, with the weights chosen).
///
/// The child of a round has the coarse vertices' new points first (vertex v stays v), then
/// one point per coarse edge (edge e becomes vertex V + e); its triangles are, for each
/// coarse triangle f, the three corner triangles 4f, 4f + 1, 4f + 2 and the middle one 4f + 3.
///
/// # Errors
///
/// [`Error::Mesh`] with [`MeshError::NotATriangle`] naming the first face that is not a
/// triangle; [`Error::LimitExceeded`] if the result would pass
/// [`MAX_MESH_VERTICES`](crate::limits::MAX_MESH_VERTICES) vertices or
/// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners, before the first round
/// runs; [`Error::Overflow`] if, with `f64`, a point overflows.
///
/// # Complexity
///
/// Θ(F·4^k·D) for F triangles; Θ(F·4^k·D) space.
///
/// ```
/// use compgeo::mesh::{loop_subdivision, PolygonMesh};
/// use compgeo::spline::Point;
///
/// // A tetrahedron: 4 triangles, every vertex of valence 3.
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let tetra = PolygonMesh::new(
///     vec![p(0.0, 0.0, 0.0), p(16.0, 0.0, 0.0), p(0.0, 16.0, 0.0), p(0.0, 0.0, 16.0)],
///     &[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
/// )?;
/// let once = loop_subdivision(&tetra, 1)?;
/// assert_eq!((once.vertex_count(), once.face_count()), (4 + 6, 16));
/// // Vertex 0 of valence 3: (1 − 3·3/16)·(0, 0, 0) + 3/16·((16, 0, 0) + (0, 16, 0) + (0, 0, 16)).
/// assert_eq!(once.position(0), &p(3.0, 3.0, 3.0));
/// let twice = loop_subdivision(&tetra, 2)?;
/// assert_eq!((twice.face_count(), twice.euler_characteristic()), (64, 2));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn loop_subdivision<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
) -> Result<PolygonMesh<S, D>> {
    loop_subdivision_weighted_with(mesh, rounds, LoopWeights::Loop, &mut NoCount)
}

/// [`loop_subdivision`] (Loop's weights), counting as [`loop_subdivision_weighted_with`].
///
/// # Errors
///
/// As [`loop_subdivision`].
///
/// # Complexity
///
/// Θ(F·4^k·D) for F triangles; Θ(F·4^k·D) space.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::triangle_torus;
/// use compgeo::mesh::loop_subdivision_with;
///
/// let torus = triangle_torus(4, 5)?; // 20 vertices, 60 edges, 40 triangles
/// let mut c = Counts::default();
/// let once = loop_subdivision_with(&torus, 1, &mut c)?;
/// assert_eq!(c.arithmetic_operations, 20 + 6 * 60);
/// assert_eq!((once.vertex_count(), once.edge_count(), once.face_count()), (80, 240, 160));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn loop_subdivision_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    loop_subdivision_weighted_with(mesh, rounds, LoopWeights::Loop, counter)
}

/// `rounds` rounds of Loop subdivision with the vertex weights `weights`. See
/// [`loop_subdivision_weighted_with`].
///
/// # Errors
///
/// As [`loop_subdivision`].
///
/// # Complexity
///
/// Θ(F·4^k·D) for F triangles; Θ(F·4^k·D) space.
///
/// ```
/// use compgeo::gen::triangle_torus;
/// use compgeo::mesh::{loop_subdivision, loop_subdivision_weighted, LoopWeights};
///
/// // Every vertex of valence 6: Warren's β(6) = 1/16 is Loop's.
/// let torus = triangle_torus(4, 5)?;
/// let warren = loop_subdivision_weighted(&torus, 2, LoopWeights::Warren)?;
/// assert_eq!(warren, loop_subdivision(&torus, 2)?);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn loop_subdivision_weighted<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
    weights: LoopWeights,
) -> Result<PolygonMesh<S, D>> {
    loop_subdivision_weighted_with(mesh, rounds, weights, &mut NoCount)
}

/// [`loop_subdivision_weighted`], counting one
/// [`arithmetic_operation`](Counter::arithmetic_operation) per stencil term.
///
/// Idea [PPB, §15.7, §16.9]: the new points from the coarse mesh's half-edge arrays (one
/// sweep over the half-edges sums every vertex's neighbours; one pass over the edges makes
/// the edge points; the boundary loops give the boundary vertices' neighbours), the child
/// connectivity by index arithmetic.
///
/// # Errors
///
/// As [`loop_subdivision`].
///
/// # Complexity
///
/// Θ(F·4^k·D) for F triangles; Θ(F·4^k·D) space.
///
/// # Counts
///
/// Per round: n + 1 for an inner vertex of valence n, 3 for a boundary vertex, 4 for an
/// inner edge and 2 for a boundary edge: V + 6E on a closed mesh (whose valences sum to 2E).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::triangle_grid;
/// use compgeo::mesh::{loop_subdivision_weighted_with, LoopWeights};
///
/// // 2 × 2 squares cut into 8 triangles: 9 vertices (1 inner of valence 6), 16 edges
/// // (8 inner).
/// let grid = triangle_grid(2, 2)?;
/// let mut c = Counts::default();
/// loop_subdivision_weighted_with(&grid, 1, LoopWeights::Warren, &mut c)?;
/// assert_eq!(c.arithmetic_operations, 7 + 8 * 3 + 8 * 4 + 8 * 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn loop_subdivision_weighted_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
    weights: LoopWeights,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    check_triangles(mesh.topology())?;
    check_rounds(mesh.topology(), rounds)?;
    let mut current = mesh.clone();
    for _ in 0..rounds {
        current = loop_round(&current, weights, counter)?;
    }
    Ok(current)
}

/// Where each vertex of a triangle mesh goes as Loop subdivision continues. See
/// [`loop_limit_points_with`].
///
/// # Errors
///
/// [`Error::Mesh`] with [`MeshError::NotATriangle`] naming the first face that is not a
/// triangle; [`Error::Overflow`] if, with `f64`, a point overflows.
///
/// # Complexity
///
/// Θ((V + F)·D) time, Θ(V·D) space.
///
/// ```
/// use compgeo::gen::triangle_torus;
/// use compgeo::mesh::{loop_limit_points, loop_subdivision, LoopWeights};
///
/// let torus = triangle_torus(4, 5)?;
/// let limits = loop_limit_points(&torus, LoopWeights::Loop)?;
/// assert_eq!(limits.len(), 20);
/// // A vertex keeps its limit position through a round (up to rounding in f64).
/// let once = loop_subdivision(&torus, 1)?;
/// let again = loop_limit_points(&once, LoopWeights::Loop)?;
/// for v in 0..20 {
///     for i in 0..3 {
///         assert!((limits[v][i] - again[v][i]).abs() < 1e-12);
///     }
/// }
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn loop_limit_points<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
    weights: LoopWeights,
) -> Result<Vec<Point<S, D>>> {
    loop_limit_points_with(mesh, weights, &mut NoCount)
}

/// [`loop_limit_points`], counting one [`arithmetic_operation`](Counter::arithmetic_operation)
/// per stencil term.
///
/// Idea [PPB, §16.4–16.6]: the limit of a vertex is the left eigenvector of eigenvalue 1 of
/// the subdivision matrix on its one-ring applied to the ring: (1 − nγ)v + γΣvᵢ with
/// γ = β/(3/8 + nβ) inside, (a + 4v + b)/6 on the boundary.
///
/// # Errors
///
/// As [`loop_limit_points`].
///
/// # Complexity
///
/// Θ((V + F)·D) time, Θ(V·D) space.
///
/// # Counts
///
/// n + 1 per inner vertex of valence n, 3 per boundary vertex: V + 2E on a closed mesh.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::triangle_torus;
/// use compgeo::mesh::{loop_limit_points_with, LoopWeights};
///
/// let mut c = Counts::default();
/// loop_limit_points_with(&triangle_torus(4, 5)?, LoopWeights::Warren, &mut c)?;
/// assert_eq!(c.arithmetic_operations, 20 + 2 * 60);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn loop_limit_points_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    weights: LoopWeights,
    counter: &mut C,
) -> Result<Vec<Point<S, D>>> {
    let t = mesh.topology();
    check_triangles(t)?;
    let pos = mesh.positions();
    let (sums, valences) = ring_sums(t, pos);
    let mut table = WeightTable::new(weights);
    let mut out: Vec<Point<S, D>> = Vec::with_capacity(pos.len());
    for (v, (sum, &n)) in sums.into_iter().zip(&valences).enumerate() {
        if t.is_boundary_vertex(v) {
            out.push(pos[v].clone()); // replaced by the boundary rule below
            continue;
        }
        let (beta, _) = table.get(n as usize);
        // γ = β/(3/8 + nβ), and the vertex keeps 1 − nγ.
        let nb = S::from_i64(i64::from(n)) * beta;
        let gamma = beta.clone() / (S::from_ratio(3, 8) + nb);
        let centre = S::one() - S::from_i64(i64::from(n)) * &gamma;
        for _ in 0..=n {
            counter.arithmetic_operation();
        }
        out.push(pos[v].clone() * &centre + &(sum * &gamma));
    }
    let (four, sixth) = (S::from_i64(4), S::from_ratio(1, 6));
    for_boundary_vertices(t, |a, v, b| {
        for _ in 0..3 {
            counter.arithmetic_operation();
        }
        out[v] = (pos[a].clone() + &(pos[v].clone() * &four) + &pos[b]) * &sixth;
    });
    finite(out)
}

/// One round: the new points, then the child connectivity.
fn loop_round<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    weights: LoopWeights,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    let t = mesh.topology();
    let pos = mesh.positions();
    let corners = t.corners();
    let twins = t.twins();
    let (sums, valences) = ring_sums(t, pos);
    let mut table = WeightTable::new(weights);
    let mut points: Vec<Point<S, D>> = Vec::with_capacity(t.vertex_count() + t.edge_count());
    // Vertex points: the inner rule for every vertex, replaced on the boundary below.
    for (v, (sum, &n)) in sums.into_iter().zip(&valences).enumerate() {
        if t.is_boundary_vertex(v) {
            points.push(pos[v].clone()); // replaced by the boundary rule below
            continue;
        }
        let (beta, alpha) = table.get(n as usize);
        for _ in 0..=n {
            counter.arithmetic_operation();
        }
        points.push(pos[v].clone() * alpha + &(sum * beta));
    }
    let (six, eighth) = (S::from_i64(6), S::from_ratio(1, 8));
    for_boundary_vertices(t, |a, v, b| {
        for _ in 0..3 {
            counter.arithmetic_operation();
        }
        points[v] = (pos[a].clone() + &(pos[v].clone() * &six) + &pos[b]) * &eighth;
    });
    // Edge points.
    let (three_eighths, half) = (S::from_ratio(3, 8), S::from_ratio(1, 2));
    for &s in t.edge_halfedges() {
        let s = s as usize;
        let [a, b, c] = triangle_corners(corners, s);
        let ends = pos[a].clone() + &pos[b];
        let twin = twins[s];
        if twin == super::NONE {
            counter.arithmetic_operation();
            counter.arithmetic_operation();
            points.push(ends * &half);
        } else {
            let [_, _, d] = triangle_corners(corners, twin as usize);
            for _ in 0..4 {
                counter.arithmetic_operation();
            }
            points.push(ends * &three_eighths + &((pos[c].clone() + &pos[d]) * &eighth));
        }
    }
    let points = finite(points)?;
    Ok(PolygonMesh::from_parts_unchecked(points, triangle_split(t)))
}

/// Every vertex's sum of the ends of its outgoing half-edges, and their number: for an inner
/// vertex, the sum of its n neighbours and n (one outgoing half-edge per neighbour). One
/// sweep over the half-edges of a triangle mesh.
fn ring_sums<S: Scalar, const D: usize>(
    t: &MeshTopology,
    pos: &[Point<S, D>],
) -> (Vec<Point<S, D>>, Vec<u32>) {
    let corners = t.corners();
    let mut sums = vec![Point::<S, D>::zero(); t.vertex_count()];
    let mut valences = vec![0u32; t.vertex_count()];
    for h in 0..corners.len() {
        let [v, w, _] = triangle_corners(corners, h);
        sums[v] += &pos[w];
        valences[v] += 1;
    }
    (sums, valences)
}

/// Calls `visit(a, v, b)` for every boundary vertex v with a before it and b after it along
/// its boundary loop.
fn for_boundary_vertices(t: &MeshTopology, mut visit: impl FnMut(usize, usize, usize)) {
    let corners = t.corners();
    for i in 0..t.boundary_loop_count() {
        let lp = t.boundary_loop(i);
        for (k, &g) in lp.iter().enumerate() {
            let following = lp[(k + 1) % lp.len()] as usize;
            let [a, v, _] = triangle_corners(corners, g as usize);
            let [_, b, _] = triangle_corners(corners, following);
            visit(a, v, b);
        }
    }
}

/// β(n) and α(n) for the valences met, each computed once.
struct WeightTable<S> {
    weights: LoopWeights,
    table: Vec<Option<(S, S)>>,
}

impl<S: Scalar> WeightTable<S> {
    fn new(weights: LoopWeights) -> Self {
        WeightTable {
            weights,
            table: Vec::new(),
        }
    }

    /// (β(n), α(n)) for an inner vertex, whose valence n is at least 2.
    fn get(&mut self, n: usize) -> (&S, &S) {
        if n >= self.table.len() {
            self.table.resize(n + 1, None);
        }
        let weights = self.weights;
        let entry = self.table[n].get_or_insert_with(|| (weights.beta(n), weights.alpha(n)));
        (&entry.0, &entry.1)
    }
}

/// [`Error::Mesh`] with [`MeshError::NotATriangle`] for the first face that is not a
/// triangle.
fn check_triangles(t: &MeshTopology) -> Result<()> {
    // Every face has at least three corners, so H = 3F means every face has three.
    if t.is_triangle_mesh() {
        return Ok(());
    }
    let face = (0..t.face_count())
        .find(|&f| t.face_size(f) != 3)
        .unwrap_or(0);
    Err(Error::Mesh(MeshError::NotATriangle {
        face,
        corners: t.face_size(face),
    }))
}

/// [`Error::LimitExceeded`] if `rounds` rounds would pass the mesh limits: per round
/// V′ = V + E, E′ = 2E + H, H′ = 4H.
fn check_rounds(t: &MeshTopology, rounds: usize) -> Result<()> {
    let (mut v, mut e, mut h) = (
        t.vertex_count() as u128,
        t.edge_count() as u128,
        t.halfedge_count() as u128,
    );
    for _ in 0..rounds {
        (v, e, h) = (v + e, 2 * e + h, 4 * h);
        limits::MESH_VERTICES.check(v)?;
        limits::MESH_CORNERS.check(h)?;
    }
    Ok(())
}

/// `points` if every coordinate is finite, else [`Error::Overflow`].
fn finite<S: Scalar, const D: usize>(points: Vec<Point<S, D>>) -> Result<Vec<Point<S, D>>> {
    if S::EXACT || points.iter().all(Point::is_finite) {
        Ok(points)
    } else {
        Err(Error::Overflow {
            what: "Loop subdivision",
        })
    }
}
