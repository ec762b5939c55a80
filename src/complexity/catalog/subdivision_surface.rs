//! Catalog entries of the subdivision surfaces on regular nets (`random-torus`): a closed
//! net (a torus) of ⌈n/8⌉ × 8 random points in the unit cube, so about n points, refined by
//! three rounds of tensor Lane–Riesenfeld subdivision of bidegree (3, 3) (the regular case
//! of Catmull–Clark, 64 times as many points out), and its bicubic limit points. For a
//! fixed number of rounds both counts are linear in n: 2·7·(3·MN + 3·MN·8) midpoints and
//! 3·MN + 3·MN stencil terms for M × N = ⌈n/8⌉ × 8.

use crate::complexity::{Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::subdivision::Topology;
use crate::spline::Point;
use crate::surface::ControlNet;

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
    use crate::surface::declarations as s;
    vec![
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
    ]
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
