//! Catalog entries of [`crate::spline::bspline`]: each B-spline algorithm measured in each of
//! its two sizes separately, so both growths are visible.
//!
//! - `random-degree`: n is the degree d, on a clamped uniform cubic-like curve with 2(d + 1)
//!   control points in the unit square; the counted operation is the arithmetic step
//!   ([`Operation::ArithmeticOperations`]): de Boor's d(d + 1)/2 affine combinations, the
//!   basis's triangular scheme, insertion's d combinations.
//! - `random-control`: n is the number of control points of a cubic on clamped uniform knots;
//!   the counted operation is the span search's comparison ([`Operation::Comparisons`]), the
//!   only part of an evaluation that grows with n (⌈lg(n − d)⌉ + O(1) by bisection).
//!
//! The parameter (or the inserted knot) is the first generated coordinate, uniform in [0, 1),
//! drawn with the same seed as the control points.
//!
//! [`Operation::ArithmeticOperations`]: crate::count::Operation::ArithmeticOperations
//! [`Operation::Comparisons`]: crate::count::Operation::Comparisons

use crate::complexity::{Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::{BSpline, KnotVector, Point};

/// The input distribution in which n is the degree.
pub(crate) const RANDOM_DEGREE: &str = "random-degree";
/// The input distribution in which n is the number of control points (degree 3).
pub(crate) const RANDOM_CONTROL: &str = "random-control";

/// Which B-spline algorithm a workload runs.
#[derive(Clone, Copy, Debug)]
enum Run {
    /// [`BSpline::de_boor_with`].
    DeBoor,
    /// [`KnotVector::basis_with`].
    Basis,
    /// [`KnotVector::span_with`].
    Span,
    /// [`BSpline::insert_with`], once.
    Insert,
}

/// One call of `run` on a random curve whose degree (`in_degree`) or number of control points
/// is n.
struct Sweep {
    run: Run,
    in_degree: bool,
}

/// The B-spline entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::spline::bspline::declarations as d;
    // n is the degree or the number of control points, as the input name says.
    let sweep = |run, in_degree| Sweep { run, in_degree };
    vec![
        Entry::declared(&d::DE_BOOR, RANDOM_DEGREE, sweep(Run::DeBoor, true))
            .quick(4, 256)
            .full(4, 512),
        Entry::declared(&d::DE_BOOR, RANDOM_CONTROL, sweep(Run::DeBoor, false))
            .quick(64, 1 << 16)
            .full(64, 1 << 20),
        Entry::declared(&d::BASIS, RANDOM_DEGREE, sweep(Run::Basis, true))
            .quick(4, 256)
            .full(4, 512),
        Entry::declared(&d::SPAN, RANDOM_CONTROL, sweep(Run::Span, false))
            .quick(64, 1 << 16)
            .full(64, 1 << 20),
        Entry::declared(&d::INSERT, RANDOM_DEGREE, sweep(Run::Insert, true))
            .quick(4, 256)
            .full(4, 512),
    ]
}

impl Workload for Sweep {
    type Input = (BSpline<f64, 2>, f64);
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let (degree, count) = if self.in_degree {
            (n, 2 * (n + 1))
        } else {
            (3, n.max(4))
        };
        let pts = points(PointKind::UniformSquare, count, seed)?;
        let u = pts[0].x;
        let knots = KnotVector::clamped_uniform(degree, count, 0.0, 1.0)?;
        let curve = BSpline::new(pts.into_iter().map(Point::from).collect(), knots)?;
        Ok((curve, u))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (curve, u) = input;
        // A small summary of the result keeps the optimiser from dropping the work.
        Ok(match self.run {
            Run::DeBoor => curve.de_boor_with(u, c)?.coords()[0].to_bits() as usize,
            Run::Basis => curve.knots().basis_with(u, c)?.span(),
            Run::Span => curve.knots().span_with(u, c)?,
            Run::Insert => curve.insert_with(u, 1, c)?.control().len(),
        })
    }
}
