//! Catalog entries of [`crate::surface`]: one evaluation of a tensor-product Bézier patch of
//! bidegree (n, n) in R³ by each scheme (rows first, columns first, the tensor de Casteljau
//! algorithm), all Θ(n³) affine combinations (`random-bidegree`).
//!
//! The net's points are uniform in the unit cube (x and y from one seeded point set, z from
//! a second), and (u, v) is the first generated point, inside [0, 1)².

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::Point;
use crate::surface::{BezierPatch, ControlNet};

/// The input distribution: a random net of bidegree (n, n).
const RANDOM_BIDEGREE: &str = "random-bidegree";

/// Which scheme evaluates the patch.
#[derive(Clone, Copy, Debug)]
enum Scheme {
    RowsFirst,
    ColumnsFirst,
    DeCasteljau,
}

/// One evaluation of a random patch of bidegree (n, n) at a random (u, v).
struct Evaluate(Scheme);

/// The surface entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::surface::declarations as s;
    let entry = |declaration: &'static Declaration, scheme: Scheme| {
        Entry::declared(declaration, RANDOM_BIDEGREE, Evaluate(scheme))
            .quick(4, 64)
            .full(4, 128)
    };
    vec![
        entry(&s::ROWS_FIRST, Scheme::RowsFirst),
        entry(&s::COLUMNS_FIRST, Scheme::ColumnsFirst),
        entry(&s::TENSOR_DE_CASTELJAU, Scheme::DeCasteljau),
    ]
}

impl Workload for Evaluate {
    type Input = (BezierPatch<f64, 3>, f64, f64);
    type Output = Point<f64, 3>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let count = (n + 1) * (n + 1);
        let xy = points(PointKind::UniformSquare, count, seed)?;
        let z = points(PointKind::UniformSquare, count, seed ^ 1)?;
        let net: Vec<Point<f64, 3>> = xy
            .iter()
            .zip(&z)
            .map(|(a, b)| Point::new([a.x, a.y, b.x]))
            .collect();
        let patch = BezierPatch::new(ControlNet::from_rows(n + 1, n + 1, net)?)?;
        Ok((patch, xy[0].x, xy[0].y))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (patch, u, v) = input;
        match self.0 {
            Scheme::RowsFirst => patch.rows_first_with(u, v, c),
            Scheme::ColumnsFirst => patch.columns_first_with(u, v, c),
            Scheme::DeCasteljau => patch.de_casteljau_with(u, v, c),
        }
    }
}
