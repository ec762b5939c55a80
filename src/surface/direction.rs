//! The parameter direction of an operation on a tensor-product surface.

/// Which parameter an operation acts on: a knot inserted in u acts on the columns of the net
/// (the curves in u), one inserted in v on its rows (the curves in v).
///
/// ```
/// use compgeo::surface::Direction;
///
/// assert_eq!(Direction::U.other(), Direction::V);
/// assert_eq!(Direction::V.name(), "v");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// The first parameter, u (the index i of the net, along its columns).
    U,
    /// The second parameter, v (the index j of the net, along its rows).
    V,
}

impl Direction {
    /// The other direction.
    pub fn other(self) -> Self {
        match self {
            Direction::U => Direction::V,
            Direction::V => Direction::U,
        }
    }

    /// `"u"` or `"v"`, the name errors give the parameter.
    pub fn name(self) -> &'static str {
        match self {
            Direction::U => "u",
            Direction::V => "v",
        }
    }
}
