//! Catalog entries of [`crate::spline::bspline`] and the NURBS evaluation: each algorithm
//! measured in each of its sizes separately, so every growth is visible.
//!
//! - `random-degree`: n is the degree d, on a clamped uniform curve with 2(d + 1) control
//!   points in the unit square; the counted operation is the arithmetic step
//!   ([`Operation::ArithmeticOperations`]): de Boor's and the blossom's d(d + 1)/2 affine
//!   combinations, the basis's triangular scheme, insertion's d combinations, a split's
//!   d(d + 1)/2, NURBS de Boor's d(d + 1) (both homogeneous halves), and the removal of a
//!   knot inserted once at the parameter: d − 1 solved points and d combinations of the check;
//!   all d derivatives by the extended de Boor algorithm grow cubically (d(d + 1)(d + 2)/6
//!   differences).
//! - `random-control`: n is the number of control points (or data points) of a cubic on
//!   clamped uniform knots. The span search's comparisons ([`Operation::Comparisons`]) are the
//!   only part of an evaluation that grows with n (⌈lg(n − d)⌉ + O(1) by bisection); the
//!   conversion to Bézier pieces, elevation by one, the refinement at every span's midpoint
//!   (by one backward pass of Boehm's insertions, and by the Oslo algorithm), interpolation of n points (chord length), the least-squares fit of n points
//!   by n/4 + 4 control points, the C² cubic spline in B-spline form through n points at
//!   uniform parameters, the Greville abscissae and Marsden coefficients of the knot vector,
//!   and the antiderivative grow linearly in their arithmetic.
//! - `random-parameters`: n is the number of sorted parameters evaluated at once on a cubic
//!   with 64 control points (linear).
//!
//! The parameter (or the inserted knot, or the split) is the first generated coordinate,
//! uniform in [0, 1), drawn with the same seed as the control points.
//!
//! [`Operation::ArithmeticOperations`]: crate::count::Operation::ArithmeticOperations
//! [`Operation::Comparisons`]: crate::count::Operation::Comparisons

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::{BSpline, EndCondition, KnotVector, Nurbs, Parameterisation, Point};

/// The input distribution in which n is the degree.
const RANDOM_DEGREE: &str = "random-degree";
/// The input distribution in which n is the number of control (or data) points, degree 3.
const RANDOM_CONTROL: &str = "random-control";
/// The input distribution in which n is the number of sorted parameters, on a fixed cubic.
const RANDOM_PARAMETERS: &str = "random-parameters";

/// The number of control points of the fixed cubic of `random-parameters`.
const FIXED_CONTROL: usize = 64;

/// Which algorithm a workload runs.
#[derive(Clone, Copy, Debug)]
enum Run {
    DeBoor,
    Basis,
    Span,
    Insert,
    Blossom,
    Split,
    NurbsDeBoor,
    ToBezier,
    Elevate,
    Refine,
    Oslo,
    Interpolate,
    Fit,
    EvalSorted,
    Remove,
    Derivatives,
    CubicSpline,
    Greville,
    Marsden,
    Integral,
}

/// What n counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Size {
    Degree,
    Control,
    Parameters,
}

/// One call of `run` on random input of size n in `size`.
struct Sweep {
    run: Run,
    size: Size,
}

/// The prepared input: a curve, a parameter, and the data or parameters some runs need.
#[derive(Clone)]
struct Prepared {
    curve: BSpline<f64, 2>,
    u: f64,
    /// Blossom arguments, refinement knots, fitting or evaluation parameters.
    params: Vec<f64>,
    /// Data points to interpolate or fit.
    data: Vec<Point<f64, 2>>,
    /// The curve with weights in [1/2, 3/2), for the NURBS run.
    nurbs: Option<Nurbs<f64, 2>>,
}

/// The B-spline entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::spline::bspline::declarations as b;
    use crate::spline::rational::NURBS_DE_BOOR;
    let entry = |declaration: &'static Declaration, run: Run, size: Size| {
        let input = match size {
            Size::Degree => RANDOM_DEGREE,
            Size::Control => RANDOM_CONTROL,
            Size::Parameters => RANDOM_PARAMETERS,
        };
        let e = Entry::declared(declaration, input, Sweep { run, size });
        match (size, run) {
            (Size::Degree, _) => e.quick(4, 256).full(4, 512),
            (Size::Control, Run::DeBoor | Run::Span) => e.quick(64, 1 << 16).full(64, 1 << 20),
            (Size::Control, _) => e.quick(64, 1 << 12).full(64, 1 << 16),
            (Size::Parameters, _) => e.quick(64, 1 << 14).full(64, 1 << 18),
        }
    };
    vec![
        entry(&b::DE_BOOR, Run::DeBoor, Size::Degree),
        entry(&b::DE_BOOR, Run::DeBoor, Size::Control),
        entry(&b::BASIS, Run::Basis, Size::Degree),
        entry(&b::SPAN, Run::Span, Size::Control),
        entry(&b::INSERT, Run::Insert, Size::Degree),
        entry(&b::BLOSSOM, Run::Blossom, Size::Degree),
        entry(&b::SPLIT, Run::Split, Size::Degree),
        entry(&NURBS_DE_BOOR, Run::NurbsDeBoor, Size::Degree),
        entry(&b::TO_BEZIER, Run::ToBezier, Size::Control),
        entry(&b::ELEVATE, Run::Elevate, Size::Control),
        entry(&b::REFINE, Run::Refine, Size::Control),
        entry(&b::OSLO, Run::Oslo, Size::Control),
        entry(&b::INTERPOLATE, Run::Interpolate, Size::Control),
        entry(&b::FIT, Run::Fit, Size::Control),
        entry(&b::EVAL_SORTED, Run::EvalSorted, Size::Parameters),
        entry(&b::REMOVE, Run::Remove, Size::Degree),
        entry(&b::DERIVATIVES, Run::Derivatives, Size::Degree),
        entry(&b::CUBIC_SPLINE, Run::CubicSpline, Size::Control),
        entry(&b::GREVILLE, Run::Greville, Size::Control),
        entry(&b::MARSDEN, Run::Marsden, Size::Control),
        entry(&b::INTEGRAL, Run::Integral, Size::Control),
    ]
}

impl Workload for Sweep {
    type Input = Prepared;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Prepared> {
        let (degree, count) = match self.size {
            Size::Degree => (n, 2 * (n + 1)),
            Size::Control => (3, n.max(4)),
            Size::Parameters => (3, FIXED_CONTROL),
        };
        let pts = points(PointKind::UniformSquare, count, seed)?;
        // Unit knot spacing for the derivatives, so that the d-th derivative of a curve of
        // degree 512 (about d!/∏ widths times 2^d) stays far inside the double range.
        let end = match self.run {
            Run::Derivatives => (count - degree) as f64,
            _ => 1.0,
        };
        let u = pts[0].x * end;
        let data: Vec<Point<f64, 2>> = pts.iter().map(|&p| Point::from(p)).collect();
        let knots = KnotVector::clamped_uniform(degree, count, 0.0, end)?;
        let mut curve = BSpline::new(data.clone(), knots)?;
        if let Run::Remove = self.run {
            // A knot the curve can lose again: the parameter, inserted once.
            curve = curve.insert(&u, 1)?;
        }
        let params = match (self.size, self.run) {
            (Size::Degree, _) => pts.iter().take(degree).map(|p| p.x).collect(),
            (_, Run::Refine | Run::Oslo) => {
                let t = curve.knots().knots();
                (degree..count).map(|i| (t[i] + t[i + 1]) / 2.0).collect()
            }
            (_, Run::Fit | Run::CubicSpline) => {
                (0..count).map(|i| i as f64 / (count - 1) as f64).collect()
            }
            (Size::Parameters, _) => {
                let mut us: Vec<f64> = points(PointKind::UniformSquare, n, seed ^ 1)?
                    .iter()
                    .map(|p| p.x)
                    .collect();
                us.sort_by(f64::total_cmp);
                us
            }
            _ => Vec::new(),
        };
        let nurbs = match self.run {
            Run::NurbsDeBoor => {
                let weights = pts.iter().map(|p| 0.5 + p.y).collect();
                Some(Nurbs::new(data.clone(), weights, curve.knots().clone())?)
            }
            _ => None,
        };
        Ok(Prepared {
            curve,
            u,
            params,
            data,
            nurbs,
        })
    }

    fn run<C: Counter>(&self, input: &mut Prepared, c: &mut C) -> Result<usize> {
        let Prepared {
            curve,
            u,
            params,
            data,
            nurbs,
        } = input;
        // A small summary of each result keeps the optimiser from dropping the work.
        Ok(match self.run {
            Run::DeBoor => curve.de_boor_with(u, c)?.coords()[0].to_bits() as usize,
            Run::Basis => curve.knots().basis_with(u, c)?.span(),
            Run::Span => curve.knots().span_with(u, c)?,
            Run::Insert => curve.insert_with(u, 1, c)?.control().len(),
            Run::Blossom => curve.blossom_with(params, c)?.coords()[0].to_bits() as usize,
            Run::Split => curve.split_with(u, c)?.0.control().len(),
            Run::NurbsDeBoor => match nurbs {
                Some(s) => s.de_boor_with(u, c)?.coords()[0].to_bits() as usize,
                None => 0,
            },
            Run::ToBezier => curve.to_bezier_with(c)?.pieces().len(),
            Run::Elevate => curve.elevate_with(1, c)?.control().len(),
            Run::Refine => curve.refine_with(params, c)?.control().len(),
            Run::Oslo => curve.oslo_with(params, c)?.control().len(),
            Run::Interpolate => {
                BSpline::interpolate_with(data, 3, Parameterisation::ChordLength, c)?
                    .control()
                    .len()
            }
            Run::Fit => {
                let knots = KnotVector::clamped_uniform(3, data.len() / 4 + 4, 0.0, 1.0)?;
                BSpline::fit_with(data, params, knots, c)?.control().len()
            }
            Run::EvalSorted => curve.eval_sorted_with(params, c)?.len(),
            // Within 1e-9 (the points are in the unit square): rounding moves them slightly.
            Run::Remove => curve.remove_within_with(u, 1, &1e-9, c)?.control().len(),
            Run::Derivatives => {
                let d = curve.degree();
                curve.derivatives_with(u, d, c)?[d].coords()[0].to_bits() as usize
            }
            Run::CubicSpline => {
                BSpline::cubic_spline_with(data, params, &EndCondition::Natural, c)?
                    .control()
                    .len()
            }
            Run::Greville => curve.knots().greville_with(c).len(),
            Run::Marsden => curve.knots().marsden_with(u, c)?.len(),
            Run::Integral => curve.integral_with(c)?.control().len(),
        })
    }
}
