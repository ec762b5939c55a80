//! Catalog entries of [`crate::surface`]: one evaluation of a tensor-product Bézier patch of
//! bidegree (n, n) in R³ by each scheme (rows first, columns first, the tensor de Casteljau
//! algorithm), all Θ(n³) affine combinations (`random-bidegree`).
//!
//! The net's points are uniform in the unit cube (x and y from one seeded point set, z from
//! a second), and (u, v) is the first generated point, inside [0, 1)².
//!
//! `random-samples`: the tessellation of a random bicubic patch on a grid of k × k cells,
//! k = ⌊√n⌋, so about n vertices; three surface evaluations per vertex, linear in n.
//!
//! The operations on a random patch of bidegree (n, n) (`random-bidegree`), each counted
//! exactly: the blossom at n + n random arguments, the restriction to a random sub-rectangle
//! of [0, 1]², the subdivisions at a random (u, v) inside, elevation to (2n, 2n), the twist
//! net, both monomial conversions, the bounding box (Θ(n²) comparisons), the Cʳ checks of the
//! patch against its own C^⌊n/2⌋ continuation (every order is computed before comparing)
//! and the C^⌊n/2⌋ continuations themselves. `random-samples` for [`normal`]: the normals of
//! a random bicubic patch at n parameter pairs, two partial derivatives each.

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::Point;
use crate::surface::{
    normal_with, tessellate_at_with, BezierPatch, ControlNet, Normal, TriangleMesh,
};

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
    let mut all = vec![
        entry(&s::ROWS_FIRST, Scheme::RowsFirst),
        entry(&s::COLUMNS_FIRST, Scheme::ColumnsFirst),
        entry(&s::TENSOR_DE_CASTELJAU, Scheme::DeCasteljau),
        Entry::declared(&s::TESSELLATE, "random-samples", Tessellate)
            .quick(64, 1 << 14)
            .full(64, 1 << 17),
        Entry::declared(&s::NORMAL, "random-samples", Normals)
            .quick(64, 1 << 12)
            .full(64, 1 << 15),
    ];
    let operations = [
        (&s::BLOSSOM, Op::Blossom),
        (&s::RESTRICT, Op::Restrict),
        (&s::SPLIT_U, Op::SplitU),
        (&s::SPLIT_V, Op::SplitV),
        (&s::SPLIT, Op::Split),
        (&s::ELEVATE_TO, Op::ElevateTo),
        (&s::DERIVATIVE_NET, Op::Twist),
        (&s::TO_MONOMIAL, Op::ToMonomial),
        (&s::FROM_MONOMIAL, Op::FromMonomial),
        (&s::BOUNDING_BOX, Op::BoundingBox),
        (&s::JOIN_U, Op::JoinU),
        (&s::JOIN_V, Op::JoinV),
        (&s::EXTEND_CR_U, Op::ExtendU),
        (&s::EXTEND_CR_V, Op::ExtendV),
    ];
    all.extend(operations.into_iter().map(|(declaration, op)| {
        Entry::declared(declaration, RANDOM_BIDEGREE, Operate(op))
            .quick(4, 64)
            .full(4, 128)
    }));
    all
}

/// An operation on a random patch of bidegree (n, n).
#[derive(Clone, Copy, Debug)]
enum Op {
    Blossom,
    Restrict,
    SplitU,
    SplitV,
    Split,
    ElevateTo,
    Twist,
    ToMonomial,
    FromMonomial,
    BoundingBox,
    JoinU,
    JoinV,
    ExtendU,
    ExtendV,
}

/// One operation on a random patch of bidegree (n, n), with random parameters.
struct Operate(Op);

/// What an operation returns: the runner keeps it so that nothing is optimised away, and
/// nobody reads it.
#[allow(dead_code)]
#[derive(Debug)]
enum Outcome {
    Point(Point<f64, 3>),
    Patches(Vec<BezierPatch<f64, 3>>),
    Grid(ControlNet<f64, 3>),
    Box(Point<f64, 3>, Point<f64, 3>),
    Join(Option<usize>),
}

/// The input of [`Operate`]: the patch, n random parameters in (0, 1) sorted, and the C^⌊n/2⌋
/// continuation along u and v (for the checks).
#[derive(Clone)]
struct OperateInput {
    patch: BezierPatch<f64, 3>,
    params: Vec<f64>,
    next_u: BezierPatch<f64, 3>,
    next_v: BezierPatch<f64, 3>,
}

/// The knots of the joins.
const KNOTS: [f64; 3] = [0.0, 1.0, 2.0];

impl Workload for Operate {
    type Input = OperateInput;
    type Output = Outcome;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let patch = random_patch(n, seed)?;
        // Parameters strictly inside (0, 1): the generator's points lie in [0, 1)².
        let mut params: Vec<f64> = points(PointKind::UniformSquare, n.max(2), seed ^ 2)?
            .iter()
            .map(|p| (p.x + 1.0) / 3.0)
            .collect();
        params.sort_by(f64::total_cmp);
        let r = n / 2;
        let free: Vec<Vec<Point<f64, 3>>> = patch.net().to_rows()[r + 1..].to_vec();
        let next_u = patch.extend_cr_u(r, &KNOTS, &free)?;
        let next_v = patch.extend_cr_v(r, &KNOTS, &free)?;
        Ok(OperateInput {
            patch,
            params,
            next_u,
            next_v,
        })
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let OperateInput {
            patch,
            params,
            next_u,
            next_v,
        } = input;
        let (m, n) = patch.bidegree();
        let (a, b) = (params[0], params[params.len() - 1]);
        let free: Vec<Vec<Point<f64, 3>>> = patch.net().to_rows()[m / 2 + 1..].to_vec();
        Ok(match self.0 {
            Op::Blossom => Outcome::Point(patch.blossom_with(&params[..m], &params[..n], c)?),
            Op::Restrict => Outcome::Patches(vec![patch.restrict_with(&a, &b, &a, &b, c)?]),
            Op::SplitU => {
                let (low, high) = patch.split_u_with(&a, c)?;
                Outcome::Patches(vec![low, high])
            }
            Op::SplitV => {
                let (low, high) = patch.split_v_with(&a, c)?;
                Outcome::Patches(vec![low, high])
            }
            Op::Split => Outcome::Patches(patch.split_with(&a, &b, c)?.to_vec()),
            Op::ElevateTo => Outcome::Patches(vec![patch.elevate_to_with(2 * m, 2 * n, c)?]),
            Op::Twist => Outcome::Patches(vec![patch.derivative_net_with(1, 1, c)?]),
            Op::ToMonomial => Outcome::Grid(patch.to_monomial_with(c)?),
            Op::FromMonomial => {
                Outcome::Patches(vec![BezierPatch::from_monomial_with(patch.net(), c)?])
            }
            Op::BoundingBox => {
                let (lo, hi) = patch.bounding_box_with(c);
                Outcome::Box(lo, hi)
            }
            Op::JoinU => Outcome::Join(patch.join_u_with(next_u, &KNOTS, &1e-9, c)?),
            Op::JoinV => Outcome::Join(patch.join_v_with(next_v, &KNOTS, &1e-9, c)?),
            Op::ExtendU => {
                Outcome::Patches(vec![patch.extend_cr_u_with(m / 2, &KNOTS, &free, c)?])
            }
            Op::ExtendV => {
                Outcome::Patches(vec![patch.extend_cr_v_with(n / 2, &KNOTS, &free, c)?])
            }
        })
    }
}

/// The normals of a random bicubic patch at n parameter pairs.
struct Normals;

impl Workload for Normals {
    type Input = (BezierPatch<f64, 3>, Vec<(f64, f64)>);
    type Output = Vec<Normal<f64>>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let at = points(PointKind::UniformSquare, n, seed ^ 3)?
            .iter()
            .map(|p| (p.x, p.y))
            .collect();
        Ok((random_patch(3, seed)?, at))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (patch, at) = input;
        at.iter()
            .map(|(u, v)| normal_with(patch, u, v, c))
            .collect()
    }
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
