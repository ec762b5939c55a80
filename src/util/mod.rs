//! Small internals shared by several modules, each written once: the counted binary heap, the
//! order-preserving integer key of an `f64`, the compressed adjacency lists of an edge list,
//! a binary search over positions, the range of most of a set of values (without a few far
//! ones), and the quoting of user text in error messages.

mod csr;
mod heap;
mod quote;
mod range;

/// Declares an enum of named kinds (generator kinds, report profiles): the variants with
/// their kebab-case names, `ALL`, `name`, `Display` and `FromStr` (an unknown name gives the
/// crate's "unknown {what} `x`; valid names: ..." error, with `what` as the parameter's
/// name). The algorithm families have their own macro, which takes the names from the
/// algorithms' declarations.
macro_rules! named_enum {
    (
        $(#[$meta:meta])*
        pub enum $kind:ident ($what:literal) {
            $( $(#[$vmeta:meta])* $variant:ident = $name:literal ),+ $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum $kind {
            $( $(#[$vmeta])* $variant, )+
        }

        impl $kind {
            /// Every kind, in declaration order.
            pub const ALL: [$kind; [$($name),+].len()] = [ $( $kind::$variant ),+ ];

            /// The kebab-case name, as accepted by `FromStr`.
            pub fn name(self) -> &'static str {
                match self {
                    $( $kind::$variant => $name, )+
                }
            }
        }

        impl ::std::fmt::Display for $kind {
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.write_str(self.name())
            }
        }

        impl ::std::str::FromStr for $kind {
            type Err = $crate::Error;

            /// Parses a kebab-case name; an unknown name gives
            /// [`Error::InvalidParameter`]($crate::Error::InvalidParameter) listing the
            /// valid ones.
            fn from_str(s: &str) -> $crate::Result<Self> {
                $crate::error::named(s, $what, $what, &$kind::ALL, $kind::name)
            }
        }
    };
}

pub(crate) use named_enum;

pub(crate) use csr::Csr;
pub(crate) use heap::Heap;
pub(crate) use quote::quote;
pub(crate) use range::{range_of_most, sorted_sample};

/// The `u64` whose integer order is the order of `f64::total_cmp` on `x`: the sign bit set for
/// non-negative values, every bit flipped for negative ones (a monotone bijection on the bit
/// patterns, no arithmetic on the values). Radix sort, Kruskal's edge ranks and the hull's
/// lexicographic keys compare these instead of floats.
#[inline(always)]
pub(crate) fn order_key(x: f64) -> u64 {
    let bits = x.to_bits();
    // All ones for negative floats, only the sign bit for the others.
    let flip = (((bits as i64) >> 63) as u64) | (1 << 63);
    bits ^ flip
}

/// The inverse of [`order_key`].
#[inline(always)]
pub(crate) fn from_order_key(key: u64) -> f64 {
    // Keys with the top bit set came from non-negative floats: undo the flips of `order_key`.
    let flip = if key >> 63 == 1 { 1 << 63 } else { u64::MAX };
    f64::from_bits(key ^ flip)
}

/// The first position `k` in `range` for which `before(k)` is false, given that it is true on
/// a prefix of the range: a binary search over positions, for predicates that look at more
/// than one element (a position and its neighbour, or a position taken modulo a cycle's
/// length), which `slice::partition_point` cannot express. It asks at most
/// ⌈log₂(len + 1)⌉ questions, so counted predicates inside `before` count exactly that.
pub(crate) fn partition_point(
    range: std::ops::Range<usize>,
    mut before: impl FnMut(usize) -> bool,
) -> usize {
    let (mut lo, mut hi) = (range.start, range.end);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if before(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_order_as_total_cmp_and_invert() {
        let values = [
            f64::from_bits(0xFFF8_0000_0000_0001), // a negative NaN with a payload
            -f64::NAN,
            f64::NEG_INFINITY,
            -f64::MAX,
            -1e300,
            -3.5,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            f64::MIN_POSITIVE,
            1.0,
            1.0 + f64::EPSILON,
            f64::MAX,
            f64::INFINITY,
            f64::NAN,
        ];
        for &a in &values {
            assert_eq!(from_order_key(order_key(a)).to_bits(), a.to_bits());
            for &b in &values {
                assert_eq!(order_key(a).cmp(&order_key(b)), a.total_cmp(&b), "{a} {b}");
            }
        }
    }

    #[test]
    fn partition_point_agrees_with_a_scan_and_asks_logarithmically_often() {
        for len in 0..40usize {
            for split in 0..=len {
                let mut asked = 0;
                let k = partition_point(3..3 + len, |k| {
                    asked += 1;
                    k < 3 + split
                });
                assert_eq!(k, 3 + split);
                assert!(
                    asked <= (usize::BITS - len.leading_zeros()) as usize,
                    "{len}"
                );
            }
        }
    }
}
