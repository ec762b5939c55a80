//! Catalog entries of [`crate::spline::beta`]. On `random-control`: n control points
//! uniform in the unit square, bias and tension drawn from the same seed (β₁ in [½, 2),
//! β₂ in [0, 4)).
//!
//! - evaluation at one parameter u (the first generated coordinate, scaled to the domain
//!   [0, n − 3]): the bisection over the n − 3 segments takes ⌊lg m⌋ or ⌈lg m⌉ comparisons,
//!   logarithmic; the arithmetic per point is constant (20 operations);
//! - recursive subdivision at c = ½ for a fixed k = 3 rounds: 256 + 32·(n − 3)·(2³ − 1)
//!   arithmetic operations, linear in the polygon; the output is (n − 3)·2ᵏ polygons, so k
//!   rounds grow like n·2ᵏ, linear in the output size;
//! - the check of every joint of such a curve (m − 1 joints of m = n − 3 segments, each
//!   from the segments' derivatives): three arithmetic operations per joint, linear.
//!
//! The basis and the subdivision matrices take no input that grows (the four functions of
//! one segment, four 4 × 4 matrices): their entries make n calls at n parameters
//! (`random-parameters`, t or c drawn from the seed), 16 and 256 operations each, Θ(n).

use crate::complexity::{Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::{is_beta_continuous_with, BetaParameters, BetaSpline, Point};

/// The input distribution: n random control points.
const RANDOM_CONTROL: &str = "random-control";

/// The rounds of the subdivision entry.
const ROUNDS: u32 = 3;

/// The input distribution: n random parameters.
const RANDOM_PARAMETERS: &str = "random-parameters";

/// What a workload runs.
#[derive(Clone, Copy, Debug)]
enum Run {
    Eval,
    Subdivide,
    Joints,
    Basis,
    Matrices,
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
        Entry::declared(&b::CONTINUITY, RANDOM_CONTROL, Sweep(Run::Joints))
            .quick(64, 1 << 12)
            .full(64, 1 << 16),
        Entry::declared(&b::BASIS, RANDOM_PARAMETERS, Sweep(Run::Basis))
            .quick(64, 1 << 12)
            .full(64, 1 << 16),
        Entry::declared(&b::MATRICES, RANDOM_PARAMETERS, Sweep(Run::Matrices))
            .quick(16, 256)
            .full(16, 1 << 12),
    ]
}

impl Workload for Sweep {
    /// The curve, a parameter on it, and the parameters of the calls (in [0, 1)).
    type Input = (BetaSpline<f64, 2>, f64, Vec<f64>);
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let pts = points(PointKind::UniformSquare, n.max(4), seed)?;
        let (first, second) = (pts[0], pts[1]);
        let parameters = BetaParameters::new(0.5 + 1.5 * first.y, 4.0 * second.x)?;
        let calls = pts.iter().map(|p| p.x).collect();
        let control: Vec<Point<f64, 2>> = pts.into_iter().map(Point::from).collect();
        let curve = BetaSpline::new(parameters, control)?;
        let u = first.x * curve.segments() as f64;
        Ok((curve, u, calls))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (curve, u, calls) = input;
        let parameters = curve.parameters();
        match self.0 {
            Run::Eval => curve.eval_with(u, c).map(|_| 1),
            Run::Subdivide => curve.subdivide_with(&0.5, ROUNDS, c).map(|p| p.len()),
            Run::Joints => {
                let mut joined = 0;
                for i in 1..curve.segments() {
                    let left = curve.segment_derivatives(i - 1, &1.0)?;
                    let right = curve.segment_derivatives(i, &0.0)?;
                    // Rounding may break an equality that holds exactly: count, do not assert.
                    joined += usize::from(is_beta_continuous_with(&left, &right, parameters, c));
                }
                Ok(joined)
            }
            Run::Basis => {
                let mut sum = 0.0;
                for t in calls.iter() {
                    sum += parameters.basis_with(t, c)?[1];
                }
                Ok(sum.to_bits() as usize)
            }
            Run::Matrices => {
                let mut sum = 0.0;
                for &t in calls.iter() {
                    // c in (0, 1): away from the ends, where a piece would be empty.
                    let m = parameters.subdivision_matrices_with(&(0.05 + 0.9 * t), c)?;
                    sum += m.left()[0][0];
                }
                Ok(sum.to_bits() as usize)
            }
        }
    }
}
