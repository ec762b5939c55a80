//! Catalog entries of [`crate::surface::triangle`]: the operations on a random triangular
//! Bézier patch of degree n in R³ (`random-degree`), each counted exactly.
//!
//! The patch's (n + 1)(n + 2)/2 points are uniform in the unit cube (x and y from one seeded
//! point set, z from a second). The evaluation point is inside the reference triangle: the
//! first generated point (a, b) of [0, 1)² gives (a/2, b/2, 1 − a/2 − b/2).
//!
//! Evaluation by de Casteljau is Θ(n³) affine combinations, by the Bernstein sum Θ(n²)
//! multiply-adds. The blossom takes n further points of the triangle, the derivative is the
//! second along the direction from the evaluation point to the last of them; subdivision is
//! at the evaluation point, the four-way split at the midpoints.

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::Point;
use crate::surface::{Barycentric, BarycentricVector, TriangularPatch};

/// The input distribution: a random patch of degree n.
const RANDOM_DEGREE: &str = "random-degree";

/// The triangular-patch entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::surface::triangle::declarations as t;
    let operations: [(&'static Declaration, Op); 6] = [
        (&t::DE_CASTELJAU, Op::DeCasteljau),
        (&t::BERNSTEIN_SUM, Op::BernsteinSum),
        (&t::BLOSSOM, Op::Blossom),
        (&t::DIRECTIONAL_DERIVATIVE, Op::Derivative),
        (&t::SUBDIVIDE, Op::Subdivide),
        (&t::SPLIT_FOUR, Op::SplitFour),
    ];
    operations
        .into_iter()
        .map(|(declaration, op)| {
            Entry::declared(declaration, RANDOM_DEGREE, Operate(op))
                .quick(4, 64)
                .full(4, 128)
        })
        .collect()
}

/// An operation on a random patch of degree n.
#[derive(Clone, Copy, Debug)]
enum Op {
    DeCasteljau,
    BernsteinSum,
    Blossom,
    Derivative,
    Subdivide,
    SplitFour,
}

/// One operation on a random patch of degree n at a random point of its triangle.
struct Operate(Op);

/// What an operation returns: the runner keeps it so that nothing is optimised away, and
/// nobody reads it.
#[allow(dead_code)]
#[derive(Debug)]
enum Outcome {
    Point(Point<f64, 3>),
    Patches(Vec<TriangularPatch<f64, 3>>),
}

/// The input of [`Operate`]: the patch, a point inside its triangle, n points of the
/// triangle for the blossom and a direction for the derivatives.
#[derive(Clone)]
struct OperateInput {
    patch: TriangularPatch<f64, 3>,
    at: Barycentric<f64>,
    args: Vec<Barycentric<f64>>,
    direction: BarycentricVector<f64>,
}

impl Workload for Operate {
    type Input = OperateInput;
    type Output = Outcome;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let inside = points(PointKind::UniformSquare, n + 1, seed ^ 2)?
            .iter()
            .map(|p| Barycentric::from_uv(p.x / 2.0, p.y / 2.0))
            .collect::<Result<Vec<_>>>()?;
        let first = inside[0].clone();
        let direction = first.to(&inside[n]);
        Ok(OperateInput {
            patch: random_patch(n, seed)?,
            at: first,
            args: inside[1..].to_vec(),
            direction,
        })
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let OperateInput {
            patch,
            at,
            args,
            direction,
        } = input;
        Ok(match self.0 {
            Op::DeCasteljau => Outcome::Point(patch.de_casteljau_with(at, c)),
            Op::BernsteinSum => Outcome::Point(patch.bernstein_sum_with(at, c)),
            Op::Blossom => Outcome::Point(patch.blossom_with(args, c)?),
            Op::Derivative => {
                let second = [direction.clone(), direction.clone()];
                Outcome::Point(patch.directional_derivative_with(at, &second, c))
            }
            Op::Subdivide => Outcome::Patches(patch.subdivide_with(at, c)?.to_vec()),
            Op::SplitFour => Outcome::Patches(patch.split_four_with(c)?.to_vec()),
        })
    }
}

/// A random patch of degree n in the unit cube.
fn random_patch(n: usize, seed: u64) -> Result<TriangularPatch<f64, 3>> {
    let count = (n + 1) * (n + 2) / 2;
    let xy = points(PointKind::UniformSquare, count, seed)?;
    let z = points(PointKind::UniformSquare, count, seed ^ 1)?;
    let net = xy
        .iter()
        .zip(&z)
        .map(|(a, b)| Point::new([a.x, a.y, b.x]))
        .collect();
    TriangularPatch::new(net)
}
