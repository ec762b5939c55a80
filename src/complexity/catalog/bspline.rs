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
//!   only part of an evaluation that grows with n (⌈lg(n − d)⌉ + O(1) by bisection): the
//!   arithmetic of the basis and of its derivatives (up to order 2) stays constant, O(1); the
//!   conversion to Bézier pieces, elevation by one, the refinement at every span's midpoint
//!   (by one backward pass of Boehm's insertions, and by the Oslo algorithm), interpolation of n points (chord length), the least-squares fit of n points
//!   by n/4 + 4 control points, the C² cubic spline in B-spline form through n points at
//!   uniform parameters, the Greville abscissae and Marsden coefficients of the knot vector,
//!   and the antiderivative grow linearly in their arithmetic.
//! - `random-parameters`: n is the number of sorted parameters evaluated at once on a cubic
//!   with 64 control points (linear).
//!
//! The same sizes serve the rational curves: de Casteljau's scheme on a rational Bézier
//! curve of degree n (n(n + 1) affine combinations, both homogeneous halves) and the NURBS
//! insertion of one knot (2d) in `random-degree`; the NURBS refinement, elevation and
//! conversion to Bézier pieces in `random-control` (twice the B-spline counts, linear).
//! Besides them:
//!
//! - the basis derivatives up to order 2 grow as d² in `random-degree`, and all d of them
//!   as d³ (`all-derivatives`: d(d + 1)/2 + (d + 1)·d(d + 3)/2 steps);
//! - the banded solver on a diagonally dominant system, with l = u = 3 and n rows
//!   (`random-rows`, linear), or with 256 rows and l = u = n (`random-bandwidth`, Θ(n²));
//! - the B-spline from p Bézier pieces of degree d, p·d + 1 control points copied: n cubic
//!   pieces (`random-pieces`) or 4 pieces of degree n (`random-degree`), linear both.
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
use crate::spline::{
    BSpline, BandMatrix, CompositeBezier, EndCondition, KnotVector, Nurbs, Parameterisation, Point,
    RationalBezier,
};

/// The input distribution in which n is the degree.
const RANDOM_DEGREE: &str = "random-degree";
/// The input distribution in which n is the number of control (or data) points, degree 3.
const RANDOM_CONTROL: &str = "random-control";
/// The input distribution in which n is the number of sorted parameters, on a fixed cubic.
const RANDOM_PARAMETERS: &str = "random-parameters";

/// The number of control points of the fixed cubic of `random-parameters`.
const FIXED_CONTROL: usize = 64;
/// The input distribution in which n is the degree and every derivative is taken.
const ALL_DERIVATIVES: &str = "all-derivatives";
/// The input distribution in which n is the number of rows of a banded system.
const RANDOM_ROWS: &str = "random-rows";
/// The input distribution in which n is the half bandwidth of a banded system.
const RANDOM_BANDWIDTH: &str = "random-bandwidth";
/// The input distribution in which n is the number of Bézier pieces.
const RANDOM_PIECES: &str = "random-pieces";
/// The rows of the `random-bandwidth` system, and the bandwidth of the `random-rows` one.
const BAND_ROWS: usize = 256;
const BAND_WIDTH: usize = 3;
/// The pieces of the `random-degree` conversion from Bézier form.
const PIECES: usize = 4;

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
    BasisDerivatives,
    AllBasisDerivatives,
    RationalDeCasteljau,
    NurbsInsert,
    NurbsRefine,
    NurbsElevate,
    NurbsToBezier,
    BandRows,
    BandWidth,
    FromBezier,
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
    /// The curve with weights in [1/2, 3/2), for the NURBS runs.
    nurbs: Option<Nurbs<f64, 2>>,
    /// The control points with those weights as a rational Bézier curve.
    rational: Option<RationalBezier<f64, 2>>,
    /// A diagonally dominant banded system and its right-hand sides.
    band: Option<(BandMatrix<f64>, Vec<Point<f64, 2>>)>,
    /// Bézier pieces with matching ends.
    pieces: Option<CompositeBezier<f64, 2>>,
}

/// The B-spline entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::spline::bspline::declarations as b;
    use crate::spline::rational::declarations as r;
    use crate::spline::rational::NURBS_DE_BOOR;
    let entry = |declaration: &'static Declaration, run: Run, size: Size| {
        let input = match (size, run) {
            (Size::Degree, Run::AllBasisDerivatives) => ALL_DERIVATIVES,
            (Size::Degree, _) => RANDOM_DEGREE,
            (Size::Control, Run::BandRows) => RANDOM_ROWS,
            (Size::Control, Run::BandWidth) => RANDOM_BANDWIDTH,
            (Size::Control, Run::FromBezier) => RANDOM_PIECES,
            (Size::Control, _) => RANDOM_CONTROL,
            (Size::Parameters, _) => RANDOM_PARAMETERS,
        };
        let e = Entry::declared(declaration, input, Sweep { run, size });
        match (size, run) {
            (Size::Degree, Run::AllBasisDerivatives) => e.quick(4, 64).full(4, 256),
            // d(d + 1)/2 + 5(d + 1): the linear term fades from d = 16 on.
            (Size::Degree, Run::BasisDerivatives) => e.quick(16, 256).full(16, 512),
            (Size::Degree, _) => e.quick(4, 256).full(4, 512),
            (Size::Control, Run::BandWidth) => e.quick(4, 64).full(4, 128),
            (Size::Control, Run::DeBoor | Run::Span) => e.quick(64, 1 << 16).full(64, 1 << 20),
            // Constant arithmetic: seven sizes show it flat.
            (Size::Control, Run::Basis | Run::BasisDerivatives) => {
                e.quick(64, 1 << 12).full(64, 1 << 20)
            }
            (Size::Control, _) => e.quick(64, 1 << 12).full(64, 1 << 16),
            (Size::Parameters, _) => e.quick(64, 1 << 14).full(64, 1 << 18),
        }
    };
    vec![
        entry(&b::DE_BOOR, Run::DeBoor, Size::Degree),
        entry(&b::DE_BOOR, Run::DeBoor, Size::Control),
        entry(&b::BASIS, Run::Basis, Size::Degree),
        entry(&b::BASIS, Run::Basis, Size::Control),
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
        entry(&b::BASIS_DERIVATIVES, Run::BasisDerivatives, Size::Degree),
        entry(&b::BASIS_DERIVATIVES, Run::BasisDerivatives, Size::Control),
        entry(
            &b::BASIS_DERIVATIVES,
            Run::AllBasisDerivatives,
            Size::Degree,
        ),
        entry(&b::BANDED, Run::BandRows, Size::Control),
        entry(&b::BANDED, Run::BandWidth, Size::Control),
        entry(&b::FROM_BEZIER, Run::FromBezier, Size::Control),
        entry(&b::FROM_BEZIER, Run::FromBezier, Size::Degree),
        entry(
            &r::RATIONAL_DE_CASTELJAU,
            Run::RationalDeCasteljau,
            Size::Degree,
        ),
        entry(&r::NURBS_INSERT, Run::NurbsInsert, Size::Degree),
        entry(&r::NURBS_REFINE, Run::NurbsRefine, Size::Control),
        entry(&r::NURBS_ELEVATE, Run::NurbsElevate, Size::Control),
        entry(&r::NURBS_TO_BEZIER, Run::NurbsToBezier, Size::Control),
    ]
}

impl Workload for Sweep {
    type Input = Prepared;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Prepared> {
        let (degree, count) = match (self.size, self.run) {
            (Size::Degree, Run::FromBezier) => (n, PIECES * n + 1),
            (Size::Degree, _) => (n, 2 * (n + 1)),
            (Size::Control, Run::FromBezier) => (3, 3 * n + 1),
            (Size::Control, Run::BandWidth) => (3, BAND_ROWS),
            (Size::Control, _) => (3, n.max(4)),
            (Size::Parameters, _) => (3, FIXED_CONTROL),
        };
        let pts = points(PointKind::UniformSquare, count, seed)?;
        // Unit knot spacing for the derivatives, so that the d-th derivative of a curve of
        // degree 512 (about d!/∏ widths times 2^d) stays far inside the double range.
        let end = match self.run {
            Run::Derivatives | Run::AllBasisDerivatives => (count - degree) as f64,
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
            (_, Run::Refine | Run::Oslo | Run::NurbsRefine) => {
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
        let weights: Vec<f64> = pts.iter().map(|p| 0.5 + p.y).collect();
        let nurbs = match self.run {
            Run::NurbsDeBoor
            | Run::NurbsInsert
            | Run::NurbsRefine
            | Run::NurbsElevate
            | Run::NurbsToBezier => Some(Nurbs::new(
                data.clone(),
                weights.clone(),
                curve.knots().clone(),
            )?),
            _ => None,
        };
        let rational = match self.run {
            Run::RationalDeCasteljau => Some(RationalBezier::new(
                data[..=degree].to_vec(),
                weights[..=degree].to_vec(),
            )?),
            _ => None,
        };
        let band = match self.run {
            Run::BandRows => Some(band_system(&data, BAND_WIDTH)?),
            Run::BandWidth => Some(band_system(&data, n)?),
            _ => None,
        };
        let pieces = match self.run {
            Run::FromBezier => {
                // Consecutive pieces share their end points: piece i is points di..=d(i + 1).
                let p = (count - 1) / degree;
                let partition = (0..=p).map(|i| i as f64).collect();
                let control = (0..p)
                    .map(|i| data[degree * i..=degree * (i + 1)].to_vec())
                    .collect();
                Some(CompositeBezier::new(partition, control)?)
            }
            _ => None,
        };
        Ok(Prepared {
            curve,
            u,
            params,
            data,
            nurbs,
            rational,
            band,
            pieces,
        })
    }

    fn run<C: Counter>(&self, input: &mut Prepared, c: &mut C) -> Result<usize> {
        let Prepared {
            curve,
            u,
            params,
            data,
            nurbs,
            rational,
            band,
            pieces,
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
            Run::BasisDerivatives => curve.knots().basis_derivatives_with(u, 2, c)?.span(),
            Run::AllBasisDerivatives => {
                let d = curve.degree();
                curve.knots().basis_derivatives_with(u, d, c)?.span()
            }
            Run::RationalDeCasteljau => match rational {
                Some(r) => r.de_casteljau_with(u, c)?.coords()[0].to_bits() as usize,
                None => 0,
            },
            Run::NurbsInsert | Run::NurbsRefine | Run::NurbsElevate | Run::NurbsToBezier => {
                match nurbs {
                    Some(s) => match self.run {
                        Run::NurbsInsert => s.insert_with(u, 1, c)?.control().len(),
                        Run::NurbsRefine => s.refine_with(params, c)?.control().len(),
                        Run::NurbsElevate => s.elevate_with(1, c)?.control().len(),
                        _ => s.to_bezier_with(c)?.1.len(),
                    },
                    None => 0,
                }
            }
            Run::BandRows | Run::BandWidth => match band {
                // The solve consumes its matrix: the clone is part of the run (Θ(n(l + u))).
                Some((a, rhs)) => a.clone().solve_with(rhs.clone(), c)?.len(),
                None => 0,
            },
            Run::FromBezier => match pieces {
                Some(p) => BSpline::from_bezier_with(p, c)?.control().len(),
                None => 0,
            },
        })
    }
}

/// A banded system with `data.len()` rows and l = u = `width` (at most rows − 1): the
/// off-diagonal entries are coordinates of the data in [0, 1), the diagonal 2·width + 1, so
/// the matrix is strictly diagonally dominant and needs no pivoting; the data are the
/// right-hand sides.
fn band_system(
    data: &[Point<f64, 2>],
    width: usize,
) -> Result<(BandMatrix<f64>, Vec<Point<f64, 2>>)> {
    let n = data.len();
    let width = width.min(n - 1);
    let mut a = BandMatrix::zeros(n, width, width)?;
    for i in 0..n {
        for j in i.saturating_sub(width)..(i + width + 1).min(n) {
            let value = if i == j {
                (2 * width + 1) as f64
            } else {
                data[(i * 7 + j * 13) % n][(i + j) % 2]
            };
            a.set(i, j, value)?;
        }
    }
    Ok((a, data.to_vec()))
}
