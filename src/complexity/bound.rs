//! Stated time bounds: the O-classes an algorithm can claim, and their growth functions f.
//!
//! The course ([RD, ch. 2], "Complejidad de un algoritmo") defines
//! the complexity T(n) of an algorithm as its number of operations in the worst case, and says
//! that T(n) is O(g(n)) when T(n) < C·g(n) for some constant C and every n ≥ n₀. A [`Bound`]
//! names g; [`Bound::eval`] computes it, so the engine can check that measured cost / g stays
//! bounded as n grows.
//!
//! Logarithms are base 2 with a floor: `lg x = log₂ max(x, 2)`, so `lg 1 = lg 2 = 1`. Without the
//! floor, O(n log n) would be 0 at n = 1 and O(n log h) would vanish for a hull of one point,
//! making cost / f(n) infinite; with it every f is at least 1 for sizes ≥ 1. The floor only
//! changes f for arguments below 2, which never decides a fit.

use std::fmt;
use std::str::FromStr;

use crate::error::{Error, Result};

/// A stated time bound, O(g) for one of the growth functions the course uses.
///
/// `n` is the input size (points, keys, vertices); `h` is the output size (hull vertices) and
/// `m` the number of edges of a graph. [`Bound::second_size`] says which of `h` and `m` a bound
/// needs.
///
/// ```
/// use compgeo::complexity::Bound;
///
/// let b: Bound = "O(n log n)".parse().unwrap();
/// assert_eq!(b, Bound::NLogN);
/// assert_eq!(b.to_string(), "O(n log n)");
/// assert_eq!(b.eval(1024.0, None), 10240.0);
/// assert_eq!(Bound::NH.eval(100.0, Some(7.0)), 700.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Bound {
    /// O(1): f = 1.
    Constant,
    /// O(log n): f = lg n.
    Log,
    /// O(√n): f = √n (a walk across a uniform point set, for instance).
    Sqrt,
    /// O(n): f = n.
    Linear,
    /// O(n log n): f = n lg n.
    NLogN,
    /// O(n²): f = n².
    Quadratic,
    /// O(n³): f = n³.
    Cubic,
    /// O(nh), output-sensitive (Jarvis march): f = n·h.
    NH,
    /// O(n log h), output-sensitive (Chan): f = n lg h.
    NLogH,
    /// O(n + m), linear in a graph (traversals): f = n + m.
    NPlusM,
    /// O(m log m) (Kruskal, dominated by sorting the edges): f = m lg m.
    MLogM,
    /// O(m log n) (Prim with a binary heap): f = m lg n.
    MLogN,
}

/// The second size a bound depends on besides n.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SecondSize {
    /// `h`, the size of the output (e.g. the number of hull vertices).
    Output,
    /// `m`, the number of edges of a graph.
    Edges,
}

impl Bound {
    /// Every bound, from slowest-growing to the second-size bounds.
    pub const ALL: [Bound; 12] = [
        Bound::Constant,
        Bound::Log,
        Bound::Sqrt,
        Bound::Linear,
        Bound::NLogN,
        Bound::Quadratic,
        Bound::Cubic,
        Bound::NH,
        Bound::NLogH,
        Bound::NPlusM,
        Bound::MLogM,
        Bound::MLogN,
    ];

    /// The growth function f(n) or f(n, s), where `s` is the second size (h or m, see
    /// [`Bound::second_size`]); logarithms are `lg x = log₂ max(x, 2)`.
    ///
    /// Sizes are expected to be at least 1. A bound that needs a second size returns NaN when
    /// `second` is `None`, so a missing h or m can never pass for a number; bounds that do not
    /// need one ignore `second`.
    pub fn eval(self, n: f64, second: Option<f64>) -> f64 {
        let s = second.unwrap_or(f64::NAN);
        match self {
            Bound::Constant => 1.0,
            Bound::Log => lg(n),
            Bound::Sqrt => n.sqrt(),
            Bound::Linear => n,
            Bound::NLogN => n * lg(n),
            Bound::Quadratic => n * n,
            Bound::Cubic => n * n * n,
            Bound::NH => n * s,
            Bound::NLogH => n * lg(s),
            Bound::NPlusM => n + s,
            Bound::MLogM => s * lg(s),
            Bound::MLogN => s * lg(n),
        }
    }

    /// Which second size the bound needs: `Some(Output)` for O(nh) and O(n log h),
    /// `Some(Edges)` for O(n + m), O(m log m) and O(m log n), `None` otherwise.
    pub fn second_size(self) -> Option<SecondSize> {
        match self {
            Bound::NH | Bound::NLogH => Some(SecondSize::Output),
            Bound::NPlusM | Bound::MLogM | Bound::MLogN => Some(SecondSize::Edges),
            _ => None,
        }
    }

    /// The text form, as written in `results.json` and parsed by [`FromStr`]: `"O(1)"`,
    /// `"O(log n)"`, `"O(sqrt n)"`, `"O(n)"`, `"O(n log n)"`, `"O(n^2)"`, `"O(n^3)"`, `"O(nh)"`,
    /// `"O(n log h)"`, `"O(n + m)"`, `"O(m log m)"`, `"O(m log n)"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Bound::Constant => "O(1)",
            Bound::Log => "O(log n)",
            Bound::Sqrt => "O(sqrt n)",
            Bound::Linear => "O(n)",
            Bound::NLogN => "O(n log n)",
            Bound::Quadratic => "O(n^2)",
            Bound::Cubic => "O(n^3)",
            Bound::NH => "O(nh)",
            Bound::NLogH => "O(n log h)",
            Bound::NPlusM => "O(n + m)",
            Bound::MLogM => "O(m log m)",
            Bound::MLogN => "O(m log n)",
        }
    }
}

impl SecondSize {
    /// The symbol of the size: `"h"` or `"m"` (also the key in `results.json`).
    pub fn symbol(self) -> &'static str {
        match self {
            SecondSize::Output => "h",
            SecondSize::Edges => "m",
        }
    }
}

impl fmt::Display for Bound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for Bound {
    type Err = Error;

    /// Parses the text of [`Bound::as_str`]. Spaces and letter case are not significant, so
    /// `"O(n log n)"`, `"o(nlogn)"` and `"O(n+m)"` are accepted.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming `bound` and the text when it is none of the bounds.
    fn from_str(text: &str) -> Result<Bound> {
        let key = squash(text);
        Bound::ALL
            .into_iter()
            .find(|b| squash(b.as_str()) == key)
            .ok_or_else(|| Error::InvalidParameter {
                name: "bound",
                reason: format!(
                    "{text:?} is not a known bound (expected one of {})",
                    Bound::ALL.map(Bound::as_str).join(", ")
                ),
            })
    }
}

/// `log₂ max(x, 2)`: the floored logarithm of the module docs (NaN stays NaN, which
/// `f64::max` would hide).
fn lg(x: f64) -> f64 {
    if x < 2.0 {
        1.0
    } else {
        x.log2()
    }
}

fn squash(text: &str) -> String {
    text.chars()
        .filter(|c| !c.is_whitespace())
        .flat_map(char::to_lowercase)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floored_log_is_one_at_one_and_two() {
        assert_eq!(lg(1.0), 1.0);
        assert_eq!(lg(2.0), 1.0);
        assert_eq!(lg(8.0), 3.0);
        assert_eq!(Bound::NLogH.eval(50.0, Some(1.0)), 50.0);
    }

    #[test]
    fn missing_second_size_is_nan_only_where_needed() {
        for b in Bound::ALL {
            let v = b.eval(64.0, None);
            assert_eq!(v.is_nan(), b.second_size().is_some(), "{b}");
        }
    }
}
