//! Integer points exactly on one circle, from products of Gaussian primes.
//!
//! A prime `p = 1 (mod 4)` is a sum of two squares, `p = a^2 + b^2 = (a + bi)(a - bi)`.
//! For `r = p_1^{k_1} ... p_s^{k_s}`, every Gaussian integer `z` with `|z|^2 = r^2` is a
//! unit times `prod_i (a_i + b_i i)^{j_i} (a_i - b_i i)^{2 k_i - j_i}` for some
//! `0 <= j_i <= 2 k_i`, and these are all distinct, so the circle `x^2 + y^2 = r^2` holds
//! exactly `4 prod_i (2 k_i + 1)` lattice points. We build them by multiplying out those
//! products in exact integer arithmetic instead of scanning for solutions.

/// Primes `p = 1 (mod 4)` in increasing order with `p = a^2 + b^2`, as `(p, a, b)`.
const GAUSSIAN_PRIMES: [(i128, i128, i128); 10] = [
    (5, 1, 2),
    (13, 2, 3),
    (17, 1, 4),
    (29, 2, 5),
    (37, 1, 6),
    (41, 4, 5),
    (53, 2, 7),
    (61, 5, 6),
    (73, 3, 8),
    (89, 5, 8),
];

/// The radius family, smallest first: `(r, factorisation as (prime index, exponent))`.
///
/// The first ten radii are the products of the first `k` primes above (`4 * 3^k` points);
/// the last is `5^2 * 13 * ... * 89`, about 5.1e15 < 2^53, with `4 * 5 * 3^9 = 393,660`
/// points.
const RADII: [&[(usize, u32)]; 11] = [
    &[(0, 1)],
    &[(0, 1), (1, 1)],
    &[(0, 1), (1, 1), (2, 1)],
    &[(0, 1), (1, 1), (2, 1), (3, 1)],
    &[(0, 1), (1, 1), (2, 1), (3, 1), (4, 1)],
    &[(0, 1), (1, 1), (2, 1), (3, 1), (4, 1), (5, 1)],
    &[(0, 1), (1, 1), (2, 1), (3, 1), (4, 1), (5, 1), (6, 1)],
    &[
        (0, 1),
        (1, 1),
        (2, 1),
        (3, 1),
        (4, 1),
        (5, 1),
        (6, 1),
        (7, 1),
    ],
    &[
        (0, 1),
        (1, 1),
        (2, 1),
        (3, 1),
        (4, 1),
        (5, 1),
        (6, 1),
        (7, 1),
        (8, 1),
    ],
    &[
        (0, 1),
        (1, 1),
        (2, 1),
        (3, 1),
        (4, 1),
        (5, 1),
        (6, 1),
        (7, 1),
        (8, 1),
        (9, 1),
    ],
    &[
        (0, 2),
        (1, 1),
        (2, 1),
        (3, 1),
        (4, 1),
        (5, 1),
        (6, 1),
        (7, 1),
        (8, 1),
        (9, 1),
    ],
];

/// The smallest radius of the family whose circle holds at least `n` lattice points, and
/// all of those points, as exact integers `(x, y)` with `x^2 + y^2 = r^2`. `None` if
/// `n > MAX_COCIRCULAR` (the last radius's count).
pub(crate) fn lattice_circle(n: usize) -> Option<(i64, Vec<(i64, i64)>)> {
    let factors = RADII.iter().find(|f| count(f) >= n)?;
    let mut radius: i128 = 1;
    let mut points: Vec<(i128, i128)> = vec![(1, 0)];
    for &(prime, exponent) in factors.iter() {
        let (p, a, b) = GAUSSIAN_PRIMES[prime];
        radius *= p.pow(exponent);
        let total = 2 * exponent;
        // pi^j * conj(pi)^(total - j) for j = 0..=total.
        let choices: Vec<(i128, i128)> = (0..=total)
            .map(|j| {
                let mut z = (1, 0);
                for _ in 0..j {
                    z = mul(z, (a, b));
                }
                for _ in j..total {
                    z = mul(z, (a, -b));
                }
                z
            })
            .collect();
        points = points
            .iter()
            .flat_map(|&z| choices.iter().map(move |&w| mul(z, w)))
            .collect();
    }
    // The four units 1, i, -1, -i rotate by quarter turns.
    let units = [(1, 0), (0, 1), (-1, 0), (0, -1)];
    let all = points
        .iter()
        .flat_map(|&z| units.iter().map(move |&u| mul(z, u)))
        .map(|(x, y)| (to_i64(x), to_i64(y)))
        .collect();
    Some((to_i64(radius), all))
}

/// Number of lattice points on the circle of the radius with these factors.
fn count(factors: &[(usize, u32)]) -> usize {
    factors
        .iter()
        .map(|&(_, k)| 2 * k as usize + 1)
        .product::<usize>()
        * 4
}

fn mul((a, b): (i128, i128), (c, d): (i128, i128)) -> (i128, i128) {
    (a * c - b * d, a * d + b * c)
}

fn to_i64(v: i128) -> i64 {
    // Every component is bounded by the radius, which the family keeps below 2^53.
    i64::try_from(v).expect("cocircular coordinates are below 2^53 by construction")
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    #[test]
    fn gaussian_primes_are_sums_of_two_squares() {
        for (p, a, b) in GAUSSIAN_PRIMES {
            assert_eq!(a * a + b * b, p);
            assert_eq!(p % 4, 1);
            assert!((2..p).take_while(|d| d * d <= p).all(|d| p % d != 0));
        }
    }

    #[test]
    fn counts_grow_and_end_at_the_maximum() {
        let counts: Vec<usize> = RADII.iter().map(|f| count(f)).collect();
        assert!(counts.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(*counts.last().unwrap(), crate::limits::MAX_COCIRCULAR);
        assert!(lattice_circle(crate::limits::MAX_COCIRCULAR + 1).is_none());
    }

    #[test]
    fn every_radius_gives_its_count_of_distinct_exact_points() {
        // The larger radii are checked by the integration tests through `points`.
        for n in [1, 12, 13, 36, 100, 108, 324, 972, 2916] {
            let (r, pts) = lattice_circle(n).unwrap();
            assert!(pts.len() >= n);
            let r2 = i128::from(r) * i128::from(r);
            for &(x, y) in &pts {
                assert_eq!(i128::from(x).pow(2) + i128::from(y).pow(2), r2);
            }
            let distinct: HashSet<_> = pts.iter().collect();
            assert_eq!(distinct.len(), pts.len());
            // Brute-force lattice count on the circle for the small radii: the oracle.
            if r <= 1105 {
                let brute = (-r..=r)
                    .filter(|&x| {
                        let rest = r * r - x * x;
                        let y = (rest as f64).sqrt() as i64;
                        y * y == rest
                    })
                    .map(|x| if x.abs() == r { 1 } else { 2 })
                    .sum::<usize>();
                assert_eq!(brute, pts.len(), "r = {r}");
            }
        }
    }

    #[test]
    fn largest_radius_fits_in_f64_exactly() {
        let factors = RADII.last().unwrap();
        let r: i128 = factors
            .iter()
            .map(|&(i, k)| GAUSSIAN_PRIMES[i].0.pow(k))
            .product();
        assert!(r < 1 << 53);
    }
}
