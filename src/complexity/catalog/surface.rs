//! Catalog entries of [`crate::surface`]: one evaluation of a tensor-product Bézier patch of
//! bidegree (n, n) in R³ by each scheme (rows first, columns first, the tensor de Casteljau
//! algorithm), all Θ(n³) affine combinations (`random-bidegree`).
//!
//! The net's points are uniform in the unit cube (x and y from one seeded point set, z from
//! a second), and (u, v) is the first generated point, inside [0, 1)².
//!
//! `random-samples`: the tessellation of a random bicubic patch on a grid of k × k cells,
//! k = ⌊√n⌋, so about n vertices; three surface evaluations per vertex, linear in n.

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::Point;
use crate::surface::{tessellate_at_with, BezierPatch, ControlNet, TriangleMesh};

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
        Entry::declared(&s::TESSELLATE, "random-samples", Tessellate)
            .quick(64, 1 << 14)
            .full(64, 1 << 17),
    ]
}

/// A random patch of bidegree (n, n) in the unit cube.
fn random_patch(n: usize, seed: u64) -> Result<BezierPatch<f64, 3>> {
    let count = (n + 1) * (n + 1);
    let xy = points(PointKind::UniformSquare, count, seed)?;
    let z = points(PointKind::UniformSquare, count, seed ^ 1)?;
    let net: Vec<Point<f64, 3>> = xy
        .iter()
        .zip(&z)
        .map(|(a, b)| Point::new([a.x, a.y, b.x]))
        .collect();
    BezierPatch::new(ControlNet::from_rows(n + 1, n + 1, net)?)
}

/// The tessellation of a random bicubic patch with about n vertices.
struct Tessellate;

impl Workload for Tessellate {
    type Input = (BezierPatch<f64, 3>, Vec<f64>);
    type Output = TriangleMesh;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let k = (n as f64).sqrt().floor().max(1.0) as usize;
        let samples = (0..=k).map(|i| i as f64 / k as f64).collect();
        Ok((random_patch(3, seed)?, samples))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (patch, samples) = input;
        tessellate_at_with(patch, samples, samples, c)
    }
}

impl Workload for Evaluate {
    type Input = (BezierPatch<f64, 3>, f64, f64);
    type Output = Point<f64, 3>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        // (u, v): the first generated point, the same seed as the net's.
        let first = points(PointKind::UniformSquare, 1, seed)?[0];
        Ok((random_patch(n, seed)?, first.x, first.y))
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
