//! Catalog entries of [`crate::surface::triangle`]: the operations on a random triangular
//! Bézier patch of degree n in R³ (`random-degree`), each counted exactly, and the
//! tessellation of a random cubic patch into about n vertices (`random-samples`, linear).
//!
//! The patch's (n + 1)(n + 2)/2 points are uniform in the unit cube (x and y from one seeded
//! point set, z from a second). The evaluation point is inside the reference triangle: the
//! first generated point (a, b) of [0, 1)² gives (a/2, b/2, 1 − a/2 − b/2).
//!
//! Evaluation by de Casteljau is Θ(n³) affine combinations, by the Bernstein sum Θ(n²)
//! multiply-adds. The blossom takes n further points of the triangle, the derivative is the
//! second along the direction from the evaluation point to the last of them; subdivision is
//! at the evaluation point, the four-way split at the midpoints. Elevation goes to degree
//! 2n; the Cʳ check compares the patch with its C^⌊n/2⌋ continuation across p q (with
//! s = p + q − r; every row is computed before comparing), and the continuation itself is
//! measured with the same r. The conversion to tensor form takes the patch, the conversion
//! from it a random tensor patch of bidegree (n, n) (its points from a second seed), whose
//! two halves have degree 2n.

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::Point;
use crate::surface::{
    Barycentric, BarycentricVector, BezierPatch, ControlNet, TriangleMesh, TriangularPatch,
};

/// The input distribution: a random patch of degree n.
const RANDOM_DEGREE: &str = "random-degree";

/// The triangular-patch entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::surface::triangle::declarations as t;
    let operations: [(&'static Declaration, Op); 11] = [
        (&t::DE_CASTELJAU, Op::DeCasteljau),
        (&t::BERNSTEIN_SUM, Op::BernsteinSum),
        (&t::BLOSSOM, Op::Blossom),
        (&t::DIRECTIONAL_DERIVATIVE, Op::Derivative),
        (&t::SUBDIVIDE, Op::Subdivide),
        (&t::SPLIT_FOUR, Op::SplitFour),
        (&t::ELEVATE_TO, Op::ElevateTo),
        (&t::JOIN_ORDER, Op::JoinOrder),
        (&t::EXTEND_CR, Op::ExtendCr),
        (&t::TO_TENSOR, Op::ToTensor),
        (&t::FROM_TENSOR, Op::FromTensor),
    ];
    let mut all: Vec<Entry> = operations
        .into_iter()
        .map(|(declaration, op)| {
            Entry::declared(declaration, RANDOM_DEGREE, Operate(op))
                .quick(4, 64)
                .full(4, 128)
        })
        .collect();
    all.push(
        Entry::declared(&t::TESSELLATE, "random-samples", Tessellate)
            .quick(64, 1 << 14)
            .full(64, 1 << 17),
    );
    all
}

/// The tessellation of a random cubic patch with about n vertices: m = ⌊√(2n)⌋ segments
/// per edge, (m + 1)(m + 2)/2 vertices.
struct Tessellate;

impl Workload for Tessellate {
    type Input = (TriangularPatch<f64, 3>, usize);
    type Output = TriangleMesh;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let m = ((2 * n) as f64).sqrt().floor().max(1.0) as usize;
        Ok((random_patch(3, seed)?, m))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (patch, m) = input;
        patch.tessellate_with(*m, c)
    }
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
    ElevateTo,
    JoinOrder,
    ExtendCr,
    ToTensor,
    FromTensor,
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
    Tensor(BezierPatch<f64, 3>),
    Join(Option<usize>),
}

/// The input of [`Operate`]: the patch, a point inside its triangle, n points of the
/// triangle for the blossom, a direction for the derivatives, the patch's C^⌊n/2⌋
/// continuation across p q (for the check) and a tensor patch of bidegree (n, n).
#[derive(Clone)]
struct OperateInput {
    patch: TriangularPatch<f64, 3>,
    at: Barycentric<f64>,
    args: Vec<Barycentric<f64>>,
    direction: BarycentricVector<f64>,
    next: TriangularPatch<f64, 3>,
    tensor: BezierPatch<f64, 3>,
}

/// The far vertex of the joins: s = p + q − r, across p q from r.
fn far_vertex() -> Barycentric<f64> {
    Barycentric::from_uv(1.0, 1.0).expect("finite")
}

/// The free points of a C^⌊n/2⌋ continuation: the patch's own last rows.
fn free_points(patch: &TriangularPatch<f64, 3>) -> Vec<Point<f64, 3>> {
    let n = patch.degree();
    let r = n / 2;
    let free = (n - r) * (n - r + 1) / 2;
    patch.points()[patch.points().len() - free..].to_vec()
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
        let patch = random_patch(n, seed)?;
        let next = patch.extend_cr(&far_vertex(), n / 2, &free_points(&patch))?;
        let square = random_patch(2 * n + 1, seed ^ 3)?;
        let tensor = BezierPatch::new(ControlNet::from_rows(
            n + 1,
            n + 1,
            square.points()[..(n + 1) * (n + 1)].to_vec(),
        )?)?;
        Ok(OperateInput {
            patch,
            at: first,
            args: inside[1..].to_vec(),
            direction,
            next,
            tensor,
        })
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let OperateInput {
            patch,
            at,
            args,
            direction,
            next,
            tensor,
        } = input;
        let n = patch.degree();
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
            Op::ElevateTo => Outcome::Patches(vec![patch.elevate_to_with(2 * n, c)?]),
            Op::JoinOrder => Outcome::Join(patch.join_order_with(next, &far_vertex(), &1e-9, c)?),
            Op::ExtendCr => Outcome::Patches(vec![patch.extend_cr_with(
                &far_vertex(),
                n / 2,
                &free_points(patch),
                c,
            )?]),
            Op::ToTensor => Outcome::Tensor(patch.to_tensor_with(c)?),
            Op::FromTensor => {
                Outcome::Patches(TriangularPatch::from_tensor_with(tensor, c)?.to_vec())
            }
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
