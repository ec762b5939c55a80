//! Catalog entries of [`crate::mesh`]: two rounds of Catmull–Clark on a closed mesh of about
//! n faces, regular (`quad-torus`, every vertex of valence 4) or irregular
//! (`irregular-torus`: triangles, quadrilaterals and hexagons, valences 3 to 6); the same for
//! the midpoint scheme M₃ on the irregular torus; and the Catmull–Clark limit positions of
//! the irregular torus after one round (a quadrilateral mesh). For a fixed number of rounds
//! every count is linear in n: each round's operations are a fixed multiple of its corners,
//! and two rounds make 16 times as many.

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{mesh, MeshKind};
use crate::mesh::{catmull_clark, catmull_clark_limit_with, subdivide_with, PolygonMesh, Scheme};
use crate::spline::Point;

/// The rounds every subdivision entry runs.
const ROUNDS: usize = 2;

/// The mesh entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::mesh::declarations as m;
    let sized = |entry: Entry| entry.quick(64, 1 << 12).full(64, 1 << 15);
    let mut all: Vec<Entry> = Vec::new();
    for (declaration, scheme) in [
        (&m::CATMULL_CLARK, Scheme::CatmullClark),
        (&m::MIDPOINT_CUBIC, Scheme::MidpointCubic),
    ] {
        all.extend(
            super::claimed_entries(declaration, |kind: MeshKind| Subdivide { kind, scheme })
                .into_iter()
                .map(|(_, entry)| sized(entry)),
        );
    }
    let limit: &'static Declaration = &m::CATMULL_CLARK_LIMIT;
    all.extend(
        super::claimed_entries(limit, |kind: MeshKind| Limit { kind })
            .into_iter()
            .map(|(_, entry)| sized(entry)),
    );
    all
}

/// Two rounds of a scheme on a generated mesh of about n faces.
struct Subdivide {
    kind: MeshKind,
    scheme: Scheme,
}

impl Workload for Subdivide {
    type Input = PolygonMesh<f64, 3>;
    type Output = PolygonMesh<f64, 3>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        mesh(self.kind, n, seed)
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        subdivide_with(input, self.scheme, ROUNDS, c)
    }
}

/// The limit positions of a generated mesh of about n faces after one round.
struct Limit {
    kind: MeshKind,
}

impl Workload for Limit {
    type Input = PolygonMesh<f64, 3>;
    type Output = Vec<Point<f64, 3>>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        catmull_clark(&mesh(self.kind, n, seed)?, 1)
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        catmull_clark_limit_with(input, c)
    }
}
