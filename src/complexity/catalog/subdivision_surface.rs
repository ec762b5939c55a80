//! Catalog entries of the subdivision surfaces on regular nets (`random-torus`): a closed
//! net (a torus) of ⌈n/8⌉ × 8 random points in the unit cube, so about n points, refined by
//! three rounds of tensor Lane–Riesenfeld subdivision of bidegree (3, 3) (the regular case
//! of Catmull–Clark, 64 times as many points out), and its bicubic limit points. For a
//! fixed number of rounds both counts are linear in n: 2·7·(3·MN + 3·MN·8) midpoints and
//! 3·MN + 3·MN stencil terms for M × N = ⌈n/8⌉ × 8.
//!
//! The mesh schemes run two rounds on a closed mesh of about n faces from
//! [`gen::mesh`](crate::gen::mesh): Loop on the triangle torus (`triangle-torus`, every
//! vertex of valence 6) and on the irregular torus with every face cut into a fan of
//! triangles from its first corner (`irregular-torus`, valences 3 to 12); Doo–Sabin on the
//! quadrilateral torus (`quad-torus`) and the irregular torus as generated (triangles,
//! quadrilaterals and hexagons); the limit points of the same irregular tori. For a fixed
//! number of rounds every count is linear in n (each round's stencil terms are a fixed
//! multiple of its corners, which grow by 4 per round).

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{mesh, points, MeshKind, PointKind};
use crate::mesh::{
    doo_sabin_limit_points_with, doo_sabin_with, loop_limit_points_with, loop_subdivision_with,
    LoopWeights, PolygonMesh,
};
use crate::spline::subdivision::Topology;
use crate::spline::Point;
use crate::surface::ControlNet;

/// The rounds of the mesh entries.
const MESH_ROUNDS: usize = 2;

/// The rounds of the subdivision entries.
const ROUNDS: usize = 3;

/// The bidegree of the tensor entries.
const BIDEGREE: (usize, usize) = (3, 3);

/// The columns of the random torus.
const COLUMNS: usize = 8;

/// A torus in both directions.
const TORUS: (Topology, Topology) = (Topology::Closed, Topology::Closed);

/// The subdivision-surface entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::mesh::declarations as m;
    use crate::surface::declarations as s;
    let mut all = vec![
        Entry::declared(
            &s::NET_LANE_RIESENFELD,
            "random-torus",
            Torus { limit: false },
        )
        .quick(64, 1 << 12)
        .full(64, 1 << 15),
        Entry::declared(&s::NET_LIMIT_POINTS, "random-torus", Torus { limit: true })
            .quick(64, 1 << 14)
            .full(64, 1 << 18),
    ];
    let sized = |entry: Entry| entry.quick(64, 1 << 12).full(64, 1 << 15);
    let schemes: [(&'static Declaration, Run); 4] = [
        (&m::LOOP, Run::Loop),
        (&m::LOOP_LIMIT, Run::LoopLimit),
        (&m::DOO_SABIN, Run::DooSabin),
        (&m::DOO_SABIN_LIMIT, Run::DooSabinLimit),
    ];
    for (declaration, run) in schemes {
        all.extend(
            super::claimed_entries(declaration, |kind: MeshKind| Mesh { kind, run })
                .into_iter()
                .map(|(_, entry)| sized(entry)),
        );
    }
    all
}

/// What runs on a generated mesh.
#[derive(Clone, Copy, Debug)]
enum Run {
    Loop,
    LoopLimit,
    DooSabin,
    DooSabinLimit,
}

/// A scheme on a generated mesh of about n faces (cut into triangles for Loop).
struct Mesh {
    kind: MeshKind,
    run: Run,
}

/// What a mesh entry returns.
#[allow(dead_code)] // kept alive until the timer stops, never read
enum Outcome {
    Mesh(Box<PolygonMesh<f64, 3>>),
    Points(Vec<Point<f64, 3>>),
}

impl Workload for Mesh {
    type Input = PolygonMesh<f64, 3>;
    type Output = Outcome;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let generated = mesh(self.kind, n, seed)?;
        match self.run {
            Run::Loop | Run::LoopLimit => fan_triangulated(&generated),
            Run::DooSabin | Run::DooSabinLimit => Ok(generated),
        }
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let weights = LoopWeights::Loop;
        Ok(match self.run {
            Run::Loop => Outcome::Mesh(Box::new(loop_subdivision_with(input, MESH_ROUNDS, c)?)),
            Run::LoopLimit => Outcome::Points(loop_limit_points_with(input, weights, c)?),
            Run::DooSabin => Outcome::Mesh(Box::new(doo_sabin_with(input, MESH_ROUNDS, c)?)),
            Run::DooSabinLimit => Outcome::Points(doo_sabin_limit_points_with(input, c)?),
        })
    }
}

/// The mesh with every face cut into the fan of triangles from its first corner.
fn fan_triangulated(m: &PolygonMesh<f64, 3>) -> Result<PolygonMesh<f64, 3>> {
    let mut faces = Vec::with_capacity(m.topology().halfedge_count());
    for f in 0..m.face_count() {
        let c = m.face_vertices(f);
        for k in 1..c.len() - 1 {
            faces.push([c[0] as usize, c[k] as usize, c[k + 1] as usize]);
        }
    }
    PolygonMesh::new(m.positions().to_vec(), &faces)
}

/// Three rounds of bicubic subdivision of a random torus of about n points, or its limit
/// points.
struct Torus {
    limit: bool,
}

impl Workload for Torus {
    type Input = ControlNet<f64, 3>;
    type Output = ControlNet<f64, 3>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let rows = n.div_ceil(COLUMNS).max(3);
        let xy = points(PointKind::UniformSquare, rows * COLUMNS, seed)?;
        let z = points(PointKind::UniformSquare, rows * COLUMNS, seed ^ 1)?;
        let cube = xy
            .iter()
            .zip(&z)
            .map(|(a, b)| Point::new([a.x, a.y, b.x]))
            .collect();
        ControlNet::from_rows(rows, COLUMNS, cube)
    }

    fn run<C: Counter>(&self, net: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        if self.limit {
            net.limit_points_with(BIDEGREE, TORUS, c)
        } else {
            net.lane_riesenfeld_with(BIDEGREE, ROUNDS, TORUS, c)
        }
    }
}
