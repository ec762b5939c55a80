//! Catalog entries of [`crate::spline`]: one evaluation of a Bézier curve of degree n by each
//! scheme of [`Evaluation`] (de Casteljau's algorithm, n(n + 1)/2 affine combinations, Θ(n²);
//! the Horner-type scheme of [PPB, §2.3, Obs. 4], n + 1 point operations, Θ(n)); C² cubic
//! spline interpolation of n points (natural and periodic end conditions, Θ(n) by a
//! tridiagonal solve, [SPL, §3]).
//!
//! The counted operation is the arithmetic step on points
//! ([`Operation::ArithmeticOperations`]). Control points are uniform in the unit square and
//! the parameter is drawn from [0, 1) with the same seed. Degrees stay at most 512: beyond
//! about 1020 the binomial coefficients of Horner's scheme overflow `f64`.

use crate::complexity::{Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::bezier::{evaluate_with, Evaluation};
use crate::spline::{cubic_spline_tangents_with, Bezier, EndCondition, Point};

/// One evaluation of a random curve of degree n at a random parameter.
struct Evaluate(Evaluation);

/// The spline entries: every claim of the Bézier evaluation schemes and the cubic splines.
pub(super) fn entries() -> Vec<Entry> {
    let mut entries: Vec<Entry> = Evaluation::ALL
        .into_iter()
        .map(|scheme| {
            Entry::declared(
                scheme.declaration(),
                PointKind::UniformSquare.name(),
                Evaluate(scheme),
            )
            .quick(8, 256)
            .full(8, 512)
        })
        .collect();
    let cubic = [
        (crate::spline::interpolate::CUBIC_NATURAL, false),
        (crate::spline::interpolate::CUBIC_PERIODIC, true),
    ];
    for (declaration, periodic) in cubic {
        entries.push(
            Entry::declared(
                declaration,
                PointKind::UniformSquare.name(),
                Interpolate { periodic },
            )
            .quick(64, 1 << 12)
            .full(64, 1 << 16),
        );
    }
    entries
}

/// The tangents of the C² cubic spline through n random points at the knots 0, 1, ..., n − 1
/// (a periodic spline repeats the first point at the end).
struct Interpolate {
    periodic: bool,
}

impl Workload for Interpolate {
    type Input = (Vec<f64>, Vec<Point<f64, 2>>);
    type Output = Vec<Point<f64, 2>>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let mut pts: Vec<Point<f64, 2>> = points(PointKind::UniformSquare, n, seed)?
            .into_iter()
            .map(Point::from)
            .collect();
        if self.periodic {
            if let Some(&first) = pts.first() {
                pts.push(first);
            }
        }
        let knots = (0..pts.len()).map(|i| i as f64).collect();
        Ok((knots, pts))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (knots, pts) = input;
        let end = if self.periodic {
            EndCondition::Periodic
        } else {
            EndCondition::Natural
        };
        cubic_spline_tangents_with(knots, pts, &end, c)
    }
}

impl Workload for Evaluate {
    type Input = (Bezier<f64, 2>, f64);
    type Output = Point<f64, 2>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let pts = points(PointKind::UniformSquare, n + 1, seed)?;
        // The first generated coordinate is uniform in [0, 1): a parameter inside the segment.
        let t = pts[0].x;
        let curve = Bezier::new(pts.into_iter().map(Point::from).collect())?;
        Ok((curve, t))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (curve, t) = input;
        evaluate_with(curve, t, self.0, c)
    }
}
