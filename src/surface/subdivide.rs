//! Restriction of a Bézier patch to a sub-rectangle, and subdivision into two or four
//! patches, by the curve code row by row and column by column.
//!
//! The problem: the control net of the same polynomial over [a, b] × [c, d] (the patch
//! t ↦ c((1 − s)a + s b, (1 − t)c + t d)), and the nets of the pieces of [0, 1]² cut at
//! u = t or v = t. The idea: by the fundamental theorem the new points are blossom values
//! c[a^{m−i} b^i; c^{n−j} d^j] [FJ-surfaces, §4, eq. (13)], [PPB, §9.3], and as the blossom
//! is taken rows first, so is the restriction: every row's curve restricted to [c, d] in v,
//! then every column of the result restricted to [a, b] in u. Each curve restriction is two
//! subdivisions (de Casteljau triangles) of the curve code, and a subdivision of the patch
//! reads the halves of every column's (or row's) triangle [PPB, §9.5, Obs. 8].
//!
//! # Complexity
//!
//! Restriction Θ((m + 1)(n + 1)(m + n)D); `split_u` Θ((n + 1)m²D), `split_v` Θ((m + 1)n²D),
//! `split` Θ((n + 1)m² + (m + 1)n²)D; Θ(mnD) space for the results.
//!
//! Invariants the tests check (exactly on rationals): the pieces evaluate to the patch after
//! the affine change of parameters, and the restricted net is the blossom at a's and b's.

use super::bezier::BezierPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{validate_parameter, Bezier, Point, Scalar};
use crate::{Error, Result};

/// Restriction to a sub-rectangle, declared.
pub(crate) const RESTRICT: Declaration = Declaration {
    problem: "bezier-patch",
    name: "restrict",
    function: "surface::BezierPatch::restrict",
    file: "src/surface/subdivide.rs",
    summary:
        "every row restricted to [c, d], then every column to [a, b], each by two subdivisions",
    time: "Θ((m + 1)(n + 1)(m + n)D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (m + 1)n(n + 1) + (n + 1)m(m + 1) affine combinations",
    source: "[FJ-surfaces, §4], [PPB, §9.3]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// Subdivision at u = t, declared.
pub(crate) const SPLIT_U: Declaration = Declaration {
    problem: "bezier-patch",
    name: "split-u",
    function: "surface::BezierPatch::split_u",
    file: "src/surface/subdivide.rs",
    summary: "the two halves at u = t from one de Casteljau triangle per column",
    time: "Θ((n + 1)m²D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)m(m + 1)/2 affine combinations",
    source: "[PPB, §9.5], [PPB, §3.3]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// Subdivision at v = t, declared.
pub(crate) const SPLIT_V: Declaration = Declaration {
    problem: "bezier-patch",
    name: "split-v",
    function: "surface::BezierPatch::split_v",
    file: "src/surface/subdivide.rs",
    summary: "the two halves at v = t from one de Casteljau triangle per row",
    time: "Θ((m + 1)n²D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (m + 1)n(n + 1)/2 affine combinations",
    source: "[PPB, §9.5], [PPB, §3.3]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// Subdivision into four, declared.
pub(crate) const SPLIT: Declaration = Declaration {
    problem: "bezier-patch",
    name: "split",
    function: "surface::BezierPatch::split",
    file: "src/surface/subdivide.rs",
    summary: "the four pieces at (u, v): split at u, then both halves at v",
    time: "Θ(((n + 1)m² + (m + 1)n²)D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)m(m + 1)/2 + (m + 1)n(n + 1) affine combinations",
    source: "[PPB, §9.5], [PPB, §3.3]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The same polynomial over [a, b] × [c, d], as a patch over [0, 1]²: its point at
    /// (s, t) is this patch's point at ((1 − s)a + s b, (1 − t)c + t d). See
    /// [`BezierPatch::restrict_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"a"`, `"b"`, `"c"` or `"d"` for a NaN or infinite
    /// bound, named `"u interval"` unless a < b and `"v interval"` unless c < d (any finite
    /// rectangle, also beyond [0, 1]², which extends the patch); [`Error::Overflow`] if, with
    /// `f64`, a new point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)(n + 1)(m + n)D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    /// let s = BezierPatch::new(ControlNet::new(vec![
    ///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
    ///     vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
    /// ])?)?;
    /// let r = s.restrict(&0.5, &1.0, &0.0, &0.5)?;
    /// assert_eq!(r.net().get(0, 0), &p(0.5, 0.0, 0.0));
    /// assert_eq!(r.eval(&0.5, &0.5)?, s.eval(&0.75, &0.25)?);
    /// assert!(s.restrict(&1.0, &0.5, &0.0, &0.5).is_err()); // a > b
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn restrict(&self, a: &S, b: &S, c: &S, d: &S) -> Result<Self> {
        self.restrict_with(a, b, c, d, &mut NoCount)
    }

    /// The restriction to [a, b] × [c, d], counting its affine combinations.
    ///
    /// Idea: the new net is the blossom c[a^{m−i} b^i; c^{n−j} d^j] [FJ-surfaces, §4, eq.
    /// (13)]; taken rows first, that is every row's curve restricted to [c, d], then every
    /// column of the result restricted to [a, b] (the two-step example of [FJ-surfaces, §4]).
    /// Each curve is restricted by two subdivisions of the curve code (over [a, 1], then the
    /// piece of that over [a, b]), Θ(n²) per curve instead of n + 1 blossoms.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::restrict`].
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)(n + 1)(m + n)D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// two de Casteljau triangles per row and per column, exactly
    /// (m + 1)n(n + 1) + (n + 1)m(m + 1).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// let r = s.restrict_with(&0.0, &0.5, &0.5, &1.0, &mut c)?;
    /// assert_eq!(r.net().get(0, 0), &Point::new([0.0, 1.5]));
    /// assert_eq!(c.arithmetic_operations, 3 * 12 + 4 * 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn restrict_with<C: Counter>(
        &self,
        a: &S,
        b: &S,
        c: &S,
        d: &S,
        counter: &mut C,
    ) -> Result<Self> {
        check_interval(a, b, ("a", "b"), "u interval")?;
        check_interval(c, d, ("c", "d"), "v interval")?;
        let (m, n) = self.bidegree();
        let rows: Vec<Bezier<S, D>> = self
            .row_curves()?
            .iter()
            .map(|row| row.restrict_by_splits(c, d, counter))
            .collect();
        let columns: Vec<Vec<Point<S, D>>> = (0..=n)
            .map(|j| {
                let column: Vec<Point<S, D>> =
                    rows.iter().map(|r| r.control()[j].clone()).collect();
                Bezier::new(column)
                    .map(|curve| curve.restrict_by_splits(a, b, counter).into_control())
            })
            .collect::<Result<_>>()
            .map_err(|_| Error::Overflow {
                what: "restricted patch",
            })?;
        BezierPatch::derived(m + 1, n + 1, from_columns(&columns), "restricted patch")
    }

    /// The two pieces at u = t: over [0, t] and over [t, 1] in u, each as a patch over
    /// [0, 1]². See [`BezierPatch::split_u_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` unless 0 < t < 1 (NaN and infinities
    /// included).
    ///
    /// # Complexity
    ///
    /// Θ((n + 1)m²D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// let rows = (0..3).map(|i| (0..2).map(|j| Point::new([(i * i) as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?;
    /// let (low, high) = s.split_u(&0.25)?;
    /// assert_eq!(low.eval(&1.0, &0.5)?, s.eval(&0.25, &0.5)?);
    /// assert_eq!(high.eval(&0.0, &0.5)?, s.eval(&0.25, &0.5)?);
    /// assert!(s.split_u(&1.0).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_u(&self, t: &S) -> Result<(Self, Self)> {
        self.split_u_with(t, &mut NoCount)
    }

    /// The two pieces at u = t, counting the affine combinations.
    ///
    /// Idea: each column is a curve in u; its de Casteljau triangle at t holds the control
    /// points of its two halves [PPB, §3.3], and the halves of the columns are the columns of
    /// the two pieces [PPB, §9.5, Obs. 8].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::split_u`].
    ///
    /// # Complexity
    ///
    /// Θ((n + 1)m²D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// Exactly (n + 1)m(m + 1)/2 [`arithmetic_operation`](Counter::arithmetic_operation)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// let (low, _) = s.split_u_with(&0.5, &mut c)?;
    /// assert_eq!(low.net().get(2, 0), &Point::new([1.0, 0.0]));
    /// assert_eq!(c.arithmetic_operations, 4 * 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_u_with<C: Counter>(&self, t: &S, counter: &mut C) -> Result<(Self, Self)> {
        check_inside(t, "u")?;
        let (m, n) = self.bidegree();
        let (low, high): (Vec<_>, Vec<_>) = self
            .column_curves()
            .iter()
            .map(|column| {
                let (l, h) = column.split_counted(t, counter);
                (l.into_control(), h.into_control())
            })
            .unzip();
        Ok((
            BezierPatch::derived(m + 1, n + 1, from_columns(&low), "split patch")?,
            BezierPatch::derived(m + 1, n + 1, from_columns(&high), "split patch")?,
        ))
    }

    /// The two pieces at v = t: over [0, t] and over [t, 1] in v, each as a patch over
    /// [0, 1]². See [`BezierPatch::split_v_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"v"` unless 0 < t < 1.
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)n²D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// let rows = (0..2).map(|i| (0..3).map(|j| Point::new([i as f64, (j * j) as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?;
    /// let (low, high) = s.split_v(&0.5)?;
    /// assert_eq!(low.eval(&0.5, &0.5)?, s.eval(&0.5, &0.25)?);
    /// assert_eq!(high.eval(&0.5, &0.5)?, s.eval(&0.5, &0.75)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_v(&self, t: &S) -> Result<(Self, Self)> {
        self.split_v_with(t, &mut NoCount)
    }

    /// The two pieces at v = t, counting the affine combinations: the mirror of
    /// [`BezierPatch::split_u_with`], one de Casteljau triangle per row.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::split_v`].
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)n²D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// Exactly (m + 1)n(n + 1)/2 [`arithmetic_operation`](Counter::arithmetic_operation)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// s.split_v_with(&0.5, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 3 * 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_v_with<C: Counter>(&self, t: &S, counter: &mut C) -> Result<(Self, Self)> {
        check_inside(t, "v")?;
        let (m, n) = self.bidegree();
        let mut low = Vec::with_capacity((m + 1) * (n + 1));
        let mut high = Vec::with_capacity((m + 1) * (n + 1));
        for row in self.row_curves()? {
            let (l, h) = row.split_counted(t, counter);
            low.extend(l.into_control());
            high.extend(h.into_control());
        }
        Ok((
            BezierPatch::derived(m + 1, n + 1, low, "split patch")?,
            BezierPatch::derived(m + 1, n + 1, high, "split patch")?,
        ))
    }

    /// The four pieces at (u, v), in the order [0, u] × [0, v], [0, u] × [v, 1],
    /// [u, 1] × [0, v], [u, 1] × [v, 1], each as a patch over [0, 1]². See
    /// [`BezierPatch::split_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` or `"v"` unless 0 < u < 1 and 0 < v < 1.
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)m² + (m + 1)n²)D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// let rows = (0..3).map(|i| (0..3).map(|j| Point::new([i as f64, (i * j) as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?;
    /// let [_, _, _, top] = s.split(&0.5, &0.5)?;
    /// assert_eq!(top.eval(&0.5, &0.5)?, s.eval(&0.75, &0.75)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split(&self, u: &S, v: &S) -> Result<[Self; 4]> {
        self.split_with(u, v, &mut NoCount)
    }

    /// The four pieces at (u, v), counting the affine combinations: [`split_u_with`] at u,
    /// then [`split_v_with`] on both halves.
    ///
    /// [`split_u_with`]: BezierPatch::split_u_with
    /// [`split_v_with`]: BezierPatch::split_v_with
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::split`].
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)m² + (m + 1)n²)D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// Exactly (n + 1)m(m + 1)/2 + (m + 1)n(n + 1)
    /// [`arithmetic_operation`](Counter::arithmetic_operation)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// s.split_with(&0.5, &0.5, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 4 * 3 + 3 * 12);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_with<C: Counter>(&self, u: &S, v: &S, counter: &mut C) -> Result<[Self; 4]> {
        check_inside(u, "u")?;
        check_inside(v, "v")?;
        let (low, high) = self.split_u_with(u, counter)?;
        let (a, b) = low.split_v_with(v, counter)?;
        let (c, d) = high.split_v_with(v, counter)?;
        Ok([a, b, c, d])
    }
}

/// The points of a net, row after row, from its columns (all of one length).
pub(super) fn from_columns<S: Scalar, const D: usize>(
    columns: &[Vec<Point<S, D>>],
) -> Vec<Point<S, D>> {
    let rows = columns.first().map_or(0, Vec::len);
    (0..rows)
        .flat_map(|i| columns.iter().map(move |column| column[i].clone()))
        .collect()
}

/// Both bounds finite and `lo < hi`.
fn check_interval<S: Scalar>(
    lo: &S,
    hi: &S,
    names: (&'static str, &'static str),
    interval: &'static str,
) -> Result<()> {
    validate_parameter(lo, names.0)?;
    validate_parameter(hi, names.1)?;
    if lo < hi {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            name: interval,
            reason: format!(
                "[{}, {}] is not an interval: {} < {} is required",
                lo.to_f64(),
                hi.to_f64(),
                names.0,
                names.1
            ),
        })
    }
}

/// A subdivision parameter strictly inside (0, 1).
fn check_inside<S: Scalar>(t: &S, name: &'static str) -> Result<()> {
    validate_parameter(t, name)?;
    if S::zero() < *t && *t < S::one() {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            name,
            reason: format!(
                "a subdivision parameter lies strictly inside (0, 1), got {}",
                t.to_f64()
            ),
        })
    }
}
