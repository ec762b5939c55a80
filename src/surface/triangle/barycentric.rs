//! Barycentric coordinates on the reference triangle of a triangular patch: points
//! ([`Barycentric`], u + v + w = 1) and directions ([`BarycentricVector`], du + dv + dw = 0).
//!
//! A triangular Bézier patch is defined over a triangle p q r of the plane, and a point x of
//! the plane is named by its barycentric coordinates (u, v, w) with respect to it:
//! x = u·p + v·q + w·r, u + v + w = 1 [PPB, §10.1]. The difference of two such points is a
//! direction d = (du, dv, dw) with du + dv + dw = 0, the argument of directional derivatives
//! [PPB, §10.5]. Both are validated once, here: every coordinate finite, and the sum exactly
//! 1 or exactly 0. With `f64` "exactly" means the rounded sum `(u + v) + w`, so coordinates
//! such as (0.7, 0.2, 0.1) are refused (their sum rounds to 0.9999999999999999);
//! [`Barycentric::from_uv`] and [`BarycentricVector::from_uv`] derive the third coordinate
//! from the first two and succeed on every finite input whose third coordinate is finite.
//!
//! # Complexity
//!
//! O(1) time and space.

use crate::spline::Scalar;
use crate::{Error, Result};

/// Barycentric coordinates (u, v, w) of a point with respect to the reference triangle
/// p q r of a patch: the point u·p + v·q + w·r, with u + v + w = 1 exactly and every
/// coordinate finite. Coordinates outside [0, 1] name points outside the triangle.
///
/// ```
/// use compgeo::surface::Barycentric;
///
/// let x = Barycentric::new(0.25, 0.25, 0.5)?;
/// assert_eq!(x.coords(), &[0.25, 0.25, 0.5]);
/// assert_eq!(Barycentric::from_uv(0.25, 0.25)?, x); // w = 1 − u − v
/// assert!(Barycentric::new(0.5, 0.5, 0.5).is_err()); // the sum is 3/2
/// assert!(Barycentric::new(f64::NAN, 0.5, 0.5).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Barycentric<S>([S; 3]);

impl<S: Scalar> Barycentric<S> {
    /// The point with coordinates (u, v, w).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"barycentric"` if a coordinate is NaN or infinite,
    /// or if u + v + w is not exactly 1 (computed in `S`, so rounded for `f64`).
    pub fn new(u: S, v: S, w: S) -> Result<Self> {
        let coords = [u, v, w];
        check(&coords, "barycentric", S::one(), "1")?;
        Ok(Barycentric(coords))
    }

    /// The point (u, v, 1 − u − v).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"barycentric"` if u or v is NaN or infinite, or
    /// (with `f64`) if 1 − u − v overflows.
    pub fn from_uv(u: S, v: S) -> Result<Self> {
        let w = S::one() - &u - &v;
        let coords = [u, v, w];
        check_finite(&coords, "barycentric")?;
        Ok(Barycentric(coords))
    }

    /// The vertex `k` of the reference triangle (0: p, 1: q, 2: r): the unit coordinate
    /// vector e_k.
    ///
    /// # Panics
    ///
    /// If `k > 2`.
    pub fn vertex(k: usize) -> Self {
        assert!(k < 3, "a triangle has vertices 0, 1 and 2, not {k}");
        Barycentric(std::array::from_fn(|t| {
            if t == k {
                S::one()
            } else {
                S::zero()
            }
        }))
    }

    /// The coordinates [u, v, w].
    pub fn coords(&self) -> &[S; 3] {
        &self.0
    }

    /// The direction from `self` to `to`: `to − self`, whose coordinates sum to 0.
    pub fn to(&self, to: &Self) -> BarycentricVector<S> {
        BarycentricVector(std::array::from_fn(|t| to.0[t].clone() - &self.0[t]))
    }
}

/// A direction (du, dv, dw) in barycentric coordinates: the difference of two
/// [`Barycentric`] points, du + dv + dw = 0 exactly, every coordinate finite. Along the
/// direction d a patch has the directional derivative D_d b [PPB, §10.5]; with the reference
/// triangle p q r, d is the vector du·p + dv·q + dw·r of the plane.
///
/// ```
/// use compgeo::surface::{Barycentric, BarycentricVector};
///
/// let along_pq = BarycentricVector::new(-1.0, 1.0, 0.0)?; // q − p
/// assert_eq!(Barycentric::vertex(0).to(&Barycentric::vertex(1)), along_pq);
/// assert_eq!(BarycentricVector::from_uv(-1.0, 1.0)?, along_pq);
/// assert!(BarycentricVector::new(1.0, 1.0, 0.0).is_err()); // the sum is 2
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BarycentricVector<S>([S; 3]);

impl<S: Scalar> BarycentricVector<S> {
    /// The direction (du, dv, dw).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"direction"` if a coordinate is NaN or infinite,
    /// or if du + dv + dw is not exactly 0 (computed in `S`, so rounded for `f64`).
    pub fn new(du: S, dv: S, dw: S) -> Result<Self> {
        let coords = [du, dv, dw];
        check(&coords, "direction", S::zero(), "0")?;
        Ok(BarycentricVector(coords))
    }

    /// The direction (du, dv, −du − dv).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"direction"` if du or dv is NaN or infinite, or
    /// (with `f64`) if −du − dv overflows.
    pub fn from_uv(du: S, dv: S) -> Result<Self> {
        let dw = S::zero() - &du - &dv;
        let coords = [du, dv, dw];
        check_finite(&coords, "direction")?;
        Ok(BarycentricVector(coords))
    }

    /// The coordinates [du, dv, dw].
    pub fn coords(&self) -> &[S; 3] {
        &self.0
    }

    /// Coordinates already known to be finite and to sum to zero.
    pub(super) fn trusted(coords: [S; 3]) -> Self {
        BarycentricVector(coords)
    }
}

/// Every coordinate finite.
fn check_finite<S: Scalar>(coords: &[S; 3], name: &'static str) -> Result<()> {
    for (t, c) in coords.iter().enumerate() {
        if !c.is_finite() {
            return Err(Error::InvalidParameter {
                name,
                reason: format!(
                    "coordinate {} must be finite, got {}",
                    ["u", "v", "w"][t],
                    c.to_f64()
                ),
            });
        }
    }
    Ok(())
}

/// Every coordinate finite and their sum exactly `sum`.
fn check<S: Scalar>(coords: &[S; 3], name: &'static str, sum: S, says: &str) -> Result<()> {
    check_finite(coords, name)?;
    let total = coords[0].clone() + &coords[1] + &coords[2];
    if total == sum {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            name,
            reason: format!(
                "the coordinates ({}, {}, {}) must sum to exactly {says}, their sum is {}",
                coords[0].to_f64(),
                coords[1].to_f64(),
                coords[2].to_f64(),
                total.to_f64()
            ),
        })
    }
}
