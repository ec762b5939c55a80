//! The control net of a tensor-product surface: a rectangular grid of points c_{i,j},
//! validated once.
//!
//! The index i runs along u (the rows of [FJ-surfaces, §2, eq. (1)]'s matrix, i = 0, …, m)
//! and j along v (its columns, j = 0, …, n): row i holds c_{i,0}, …, c_{i,n}, the control
//! polygon of the curve in v that the point c_i(v) of the moving polygon follows
//! [FJ-surfaces, §1–2]; column j holds c_{0,j}, …, c_{m,j}. The points are stored row after
//! row, so a row is a slice.
//!
//! # Complexity
//!
//! Θ(mn·D) to build and validate; a row is borrowed in O(1), a column copied in Θ(mD).

use crate::spline::{Point, Scalar};
use crate::{limits, Error, Result};

/// A rectangular net of (m + 1) × (n + 1) control points c_{i,j} in R^D, every coordinate
/// finite: i = 0, …, m along u, j = 0, …, n along v.
///
/// ```
/// use compgeo::spline::Point;
/// use compgeo::surface::ControlNet;
///
/// let p = |x: f64, y: f64| Point::new([x, y, x * y]);
/// let net = ControlNet::new(vec![
///     vec![p(0.0, 0.0), p(0.0, 1.0), p(0.0, 2.0)],
///     vec![p(1.0, 0.0), p(1.0, 1.0), p(1.0, 2.0)],
/// ])?;
/// assert_eq!((net.rows(), net.columns()), (2, 3));
/// assert_eq!(net.get(1, 2), &p(1.0, 2.0));
/// assert_eq!(net.row(0), [p(0.0, 0.0), p(0.0, 1.0), p(0.0, 2.0)]);
/// assert_eq!(net.column(1), [p(0.0, 1.0), p(1.0, 1.0)]);
/// assert!(ControlNet::new(vec![vec![p(0.0, 0.0)], vec![]]).is_err()); // ragged
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ControlNet<S, const D: usize> {
    rows: usize,
    columns: usize,
    /// Row after row: c_{i,j} at i·columns + j.
    points: Vec<Point<S, D>>,
}

impl<S: Scalar, const D: usize> ControlNet<S, D> {
    /// The net of the given rows (row i is c_{i,0}, …, c_{i,n}).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no rows or an empty first row; [`Error::InvalidParameter`] named
    /// `"net"` for a row whose length differs from the first row's (naming the row and both
    /// lengths), or for a point with a NaN or infinite coordinate (naming i, j and the
    /// value); [`Error::LimitExceeded`] beyond [`MAX_POINTS`](crate::limits::MAX_POINTS)
    /// points.
    ///
    /// # Complexity
    ///
    /// Θ(mn·D) time, Θ(mn·D) space.
    pub fn new(rows: Vec<Vec<Point<S, D>>>) -> Result<Self> {
        let columns = rows.first().map_or(0, Vec::len);
        if columns == 0 {
            return Err(Error::Empty {
                what: "control net",
            });
        }
        for (i, row) in rows.iter().enumerate() {
            if row.len() != columns {
                return Err(Error::InvalidParameter {
                    name: "net",
                    reason: format!(
                        "row {i} has {} points but row 0 has {columns} (a control net is \
                         rectangular)",
                        row.len()
                    ),
                });
            }
        }
        let count = rows.len();
        Self::from_rows(count, columns, rows.into_iter().flatten().collect())
    }

    /// The net of `rows` × `columns` points given row after row (c_{i,j} at
    /// i·`columns` + j).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] if `rows` or `columns` is zero; [`Error::InvalidParameter`] named
    /// `"net"` if there are not `rows`·`columns` points; otherwise as [`ControlNet::new`].
    ///
    /// # Complexity
    ///
    /// Θ(mn·D) time, no auxiliary space.
    pub fn from_rows(rows: usize, columns: usize, points: Vec<Point<S, D>>) -> Result<Self> {
        if rows == 0 || columns == 0 {
            return Err(Error::Empty {
                what: "control net",
            });
        }
        let size = rows as u128 * columns as u128;
        limits::POINTS.check(size)?;
        if points.len() as u128 != size {
            return Err(Error::InvalidParameter {
                name: "net",
                reason: format!(
                    "{rows} × {columns} = {size} points expected, got {}",
                    points.len()
                ),
            });
        }
        for (k, p) in points.iter().enumerate() {
            if let Some(c) = p.coords().iter().find(|c| !c.is_finite()) {
                return Err(Error::InvalidParameter {
                    name: "net",
                    reason: format!(
                        "point ({}, {}) has a non-finite coordinate ({})",
                        k / columns,
                        k % columns,
                        c.to_f64()
                    ),
                });
            }
        }
        Ok(ControlNet {
            rows,
            columns,
            points,
        })
    }

    /// m + 1, the number of rows (points along u).
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// n + 1, the number of columns (points along v).
    pub fn columns(&self) -> usize {
        self.columns
    }

    /// c_{i,j}.
    ///
    /// # Panics
    ///
    /// If i > m or j > n (an index of the caller's own, as with slices).
    pub fn get(&self, i: usize, j: usize) -> &Point<S, D> {
        assert!(
            j < self.columns,
            "column {j} of a net with {}",
            self.columns
        );
        &self.points[i * self.columns + j]
    }

    /// Row i: c_{i,0}, …, c_{i,n} (the control polygon in v of the i-th point's path).
    ///
    /// # Panics
    ///
    /// If i > m.
    pub fn row(&self, i: usize) -> &[Point<S, D>] {
        &self.points[i * self.columns..(i + 1) * self.columns]
    }

    /// Column j: c_{0,j}, …, c_{m,j}, copied.
    ///
    /// # Panics
    ///
    /// If j > n.
    pub fn column(&self, j: usize) -> Vec<Point<S, D>> {
        assert!(
            j < self.columns,
            "column {j} of a net with {}",
            self.columns
        );
        self.points
            .iter()
            .skip(j)
            .step_by(self.columns)
            .cloned()
            .collect()
    }

    /// Every point, row after row.
    pub fn points(&self) -> &[Point<S, D>] {
        &self.points
    }

    /// The rows as vectors (the input form of [`ControlNet::new`]).
    pub fn to_rows(&self) -> Vec<Vec<Point<S, D>>> {
        self.points
            .chunks(self.columns)
            .map(<[Point<S, D>]>::to_vec)
            .collect()
    }

    /// The transposed net: c′_{j,i} = c_{i,j} (u and v exchanged).
    ///
    /// # Complexity
    ///
    /// Θ(mn·D) time and space.
    pub fn transposed(&self) -> Self {
        let points = (0..self.columns)
            .flat_map(|j| self.points.iter().skip(j).step_by(self.columns).cloned())
            .collect();
        ControlNet {
            rows: self.columns,
            columns: self.rows,
            points,
        }
    }

    /// The same net in `f64` (each coordinate rounded to nearest).
    pub fn to_f64(&self) -> ControlNet<f64, D> {
        ControlNet {
            rows: self.rows,
            columns: self.columns,
            points: self.points.iter().map(Point::to_f64).collect(),
        }
    }
}
