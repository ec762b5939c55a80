//! Catalog entries of [`crate::spline::beta`], both on `random-control`: n control points
//! uniform in the unit square, bias and tension drawn from the same seed (β₁ in [½, 2),
//! β₂ in [0, 4)).
//!
//! - evaluation at one parameter u (the first generated coordinate, scaled to the domain
//!   [0, n − 3]): the bisection over the n − 3 segments takes ⌊lg m⌋ or ⌈lg m⌉ comparisons,
//!   logarithmic; the arithmetic per point is constant (20 operations);
//! - recursive subdivision at c = ½ for a fixed k = 3 rounds: 256 + 32·(n − 3)·(2³ − 1)
//!   arithmetic operations, linear in the polygon; the output is (n − 3)·2ᵏ polygons, so k
//!   rounds grow like n·2ᵏ, linear in the output size.

use crate::complexity::{Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::{BetaParameters, BetaSpline, Point};

/// The input distribution: n random control points.
const RANDOM_CONTROL: &str = "random-control";

/// The rounds of the subdivision entry.
const ROUNDS: u32 = 3;

/// What a workload runs.
#[derive(Clone, Copy, Debug)]
enum Run {
    Eval,
    Subdivide,
}

/// One run on a random curve with n control points.
struct Sweep(Run);

/// The Beta-spline entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::spline::beta::declarations as b;
    vec![
        Entry::declared(&b::EVAL, RANDOM_CONTROL, Sweep(Run::Eval))
            .quick(64, 1 << 16)
            .full(64, 1 << 20),
        Entry::declared(&b::SUBDIVIDE, RANDOM_CONTROL, Sweep(Run::Subdivide))
            .quick(64, 1 << 12)
            .full(64, 1 << 16),
    ]
}

impl Workload for Sweep {
    type Input = (BetaSpline<f64, 2>, f64);
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let pts = points(PointKind::UniformSquare, n.max(4), seed)?;
        let (first, second) = (pts[0], pts[1]);
        let parameters = BetaParameters::new(0.5 + 1.5 * first.y, 4.0 * second.x)?;
        let control: Vec<Point<f64, 2>> = pts.into_iter().map(Point::from).collect();
        let curve = BetaSpline::new(parameters, control)?;
        let u = first.x * curve.segments() as f64;
        Ok((curve, u))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (curve, u) = input;
        match self.0 {
            Run::Eval => curve.eval_with(u, c).map(|_| 1),
            Run::Subdivide => curve.subdivide_with(&0.5, ROUNDS, c).map(|p| p.len()),
        }
    }
}
