//! Interpolation and fitting: polynomial interpolants in three forms (power basis by the
//! Vandermonde system, Lagrange with Aitken's scheme, Newton's divided differences, also with
//! derivative data), piecewise cubic Hermite curves, C² cubic and C¹ quadratic splines,
//! least-squares Bézier fits, and the parameterisations and tangent estimates they start from.
//!
//! Every function takes its arguments in one order, **parameters (nodes or partition), then
//! points, then options**, validates them once and returns a curve that implements the
//! curve traits of [`crate::spline`]: a polynomial form ([`Polynomial`], [`LagrangeForm`],
//! [`NewtonForm`], defined on the whole line and agreeing exactly with rationals), or a
//! [`CompositeBezier`](super::CompositeBezier) over the partition (Hermite and the splines),
//! or a [`Bezier`](super::Bezier) (the fit). The sources are [PPB, ch. 4], [RD, §3.1–3.2]
//! and [SPL, §2–4].
//!
//! | file | problem | time (n + 1 data in R^D) |
//! |---|---|---|
//! | `polynomial.rs` | [`Polynomial`], [`vandermonde`], [`vandermonde_hermite`] [RD, §3.1], [PPB, §4.1] | Θ(n³ + n²D) |
//! | `lagrange.rs` | [`LagrangeForm`], [`lagrange`], [`lagrange_basis`], Aitken's scheme [PPB, §4.2] | Θ(n² + nD) per evaluation |
//! | `newton.rs` | [`NewtonForm`], [`newton`], [`newton_hermite`] (confluent nodes) [PPB, §4.3–4.4] | Θ(n²D), Θ(nD) per evaluation |
//! | `hermite.rs` | piecewise cubic [`hermite`] [RD, §3.2], [PPB, §4.5] | Θ(nD) |
//! | `cubic_spline.rs` | C² [`cubic_spline`]: natural, clamped, Bessel, periodic ([`EndCondition`]) [SPL, §3] | Θ(nD) |
//! | `quadratic_spline.rs` | C¹ [`quadratic_spline`], [`closed_quadratic_spline`] [SPL, §2] | Θ(nD) |
//! | `least_squares.rs` | [`fit_bezier`], weighted and end-clamped ([`FitOptions`]) [PPB, §4.6–4.7] | Θ(m n² + n³) for m points, degree n |
//! | `parameterise.rs` | [`parameterise`] ([`Parameterisation`]), [`estimate_tangents`] [PPB, §4.5] | Θ(nD) |
//! | `linear.rs`, `validate.rs` | the shared linear solvers and data checks | |

mod cubic_spline;
mod hermite;
mod lagrange;
mod least_squares;
pub(crate) mod linear;
mod newton;
mod parameterise;
mod polynomial;
mod quadratic_spline;
mod validate;

use crate::complexity::Declaration;

/// The C² cubic spline's tangents with natural ends, declared (the report measures them).
pub(crate) const CUBIC_NATURAL: &Declaration = &cubic_spline::NATURAL;
/// The C² cubic spline's tangents with periodic ends, declared (the report measures them).
pub(crate) const CUBIC_PERIODIC: &Declaration = &cubic_spline::PERIODIC;

/// The interpolation and fitting algorithms, declared.
pub(crate) const DECLARATIONS: [&Declaration; 13] = [
    &declarations::VANDERMONDE,
    &declarations::VANDERMONDE_HERMITE,
    &declarations::LAGRANGE,
    &declarations::AITKEN,
    &declarations::NEWTON,
    &declarations::NEWTON_HERMITE,
    &declarations::HERMITE,
    &declarations::QUADRATIC,
    &declarations::CLOSED_QUADRATIC,
    &declarations::CUBIC,
    CUBIC_NATURAL,
    CUBIC_PERIODIC,
    &declarations::LEAST_SQUARES,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::cubic_spline::CUBIC;
    pub(crate) use super::hermite::HERMITE;
    pub(crate) use super::lagrange::{AITKEN, LAGRANGE};
    pub(crate) use super::least_squares::LEAST_SQUARES;
    pub(crate) use super::newton::{NEWTON, NEWTON_HERMITE};
    pub(crate) use super::polynomial::{VANDERMONDE, VANDERMONDE_HERMITE};
    pub(crate) use super::quadratic_spline::{CLOSED_QUADRATIC, QUADRATIC};
}

pub use cubic_spline::{
    cubic_spline, cubic_spline_tangents, cubic_spline_tangents_with, cubic_spline_with,
    EndCondition,
};
pub use hermite::{hermite, hermite_with};
pub use lagrange::{lagrange, lagrange_basis, lagrange_with, LagrangeForm};
pub use least_squares::{fit_bezier, fit_bezier_with, FitOptions};
pub use newton::{newton, newton_hermite, newton_hermite_with, newton_with, NewtonForm};
pub use parameterise::{estimate_tangents, parameterise, Parameterisation};
pub use polynomial::{
    vandermonde, vandermonde_hermite, vandermonde_hermite_with, vandermonde_with, HermiteNode,
    Polynomial,
};
pub use quadratic_spline::{
    closed_quadratic_spline, closed_quadratic_spline_with, quadratic_spline, quadratic_spline_with,
};

pub(crate) use linear::{eliminate_below, pivot, solve_dense_with};
pub(crate) use validate::check_partition;
