//! Integration tests of `compgeo::sort`: the course's operation counts, agreement with the
//! standard library's sorts (stability included, floats in the total order, radix bit for
//! bit), and the course's step tables reproduced by `trace`.

use compgeo::count::{Counts, NoCount};
use compgeo::sort::{
    binary_insertion_sort_with, bubble_sort, bubble_sort_with, course_binary_insertion_sort_with,
    course_insertion_sort_with, heap_sort_with, insertion_sort_with, merge_sort_with,
    quick_sort_with, radix_sort_f64, radix_sort_f64_with, selection_sort_with, sort_with, trace,
    Algorithm, TRACE_MAX_LEN,
};
use compgeo::Error;
use proptest::prelude::*;
use std::cmp::Ordering;

// ---------------------------------------------------------------------------------------------
// Oracles
// ---------------------------------------------------------------------------------------------

fn counts_of(algorithm: Algorithm, v: &[i64]) -> (Vec<i64>, Counts) {
    let mut v = v.to_vec();
    let mut c = Counts::default();
    sort_with(&mut v, algorithm, i64::cmp, &mut c);
    (v, c)
}

/// Pairs `i < j` with `v[i] > v[j]`, by brute force.
fn inversions(v: &[i64]) -> u64 {
    let mut count = 0;
    for i in 0..v.len() {
        for j in i + 1..v.len() {
            if v[i] > v[j] {
                count += 1;
            }
        }
    }
    count
}

fn pairs(n: u64) -> u64 {
    n * n.saturating_sub(1) / 2
}

fn floor_log2(k: u64) -> u64 {
    u64::from(k.ilog2())
}

fn ceil_log2(k: u64) -> u64 {
    u64::from(k.next_power_of_two().trailing_zeros())
}

/// Merge sort's worst case by its recurrence: W(m) = W(⌊m/2⌋) + W(⌈m/2⌉) + m − 1.
fn merge_worst(m: u64) -> u64 {
    if m < 2 {
        0
    } else {
        merge_worst(m / 2) + merge_worst(m - m / 2) + m - 1
    }
}

/// Merge sort on sorted input: each merge compares the right run's head with the whole left
/// run, B(m) = B(⌊m/2⌋) + B(⌈m/2⌉) + ⌊m/2⌋.
fn merge_sorted_input(m: u64) -> u64 {
    if m < 2 {
        0
    } else {
        merge_sorted_input(m / 2) + merge_sorted_input(m - m / 2) + m / 2
    }
}

/// Positions placed by all merges: M(m) = M(⌊m/2⌋) + M(⌈m/2⌉) + m.
fn merge_moves(m: u64) -> u64 {
    if m < 2 {
        0
    } else {
        merge_moves(m / 2) + merge_moves(m - m / 2) + m
    }
}

/// Heap sort: 2 comparisons per level of every sift-down.
fn heap_bound(n: u64) -> u64 {
    if n < 2 {
        return 0;
    }
    2 * (n - u64::from(n.count_ones())) + 2 * (1..n).map(floor_log2).sum::<u64>()
}

fn n_log2_n(n: u64) -> f64 {
    if n < 2 {
        0.0
    } else {
        n as f64 * (n as f64).log2()
    }
}

/// Cycles of the permutation that sorts `v` (distinct values).
fn cycles_of_sorting_permutation(v: &[i64]) -> u64 {
    let mut sorted = v.to_vec();
    sorted.sort_unstable();
    let target: Vec<usize> = v
        .iter()
        .map(|x| sorted.binary_search(x).expect("present"))
        .collect();
    let mut seen = vec![false; v.len()];
    let mut cycles = 0;
    for start in 0..v.len() {
        if !seen[start] {
            cycles += 1;
            let mut i = start;
            while !seen[i] {
                seen[i] = true;
                i = target[i];
            }
        }
    }
    cycles
}

/// The float values a sort must place correctly: signed zeros, subnormals, infinities, NaNs
/// of both signs with payloads, any bit pattern, and small ranges that force duplicates.
fn any_float() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<u64>().prop_map(f64::from_bits),
        prop::sample::select(vec![
            0.0,
            -0.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            -f64::NAN,
            f64::from_bits(0x7FF0_0000_0000_0001),
            f64::from_bits(0xFFF0_0000_DEAD_BEEF),
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::MAX,
            f64::MIN,
        ]),
        (1u64..1 << 52).prop_map(f64::from_bits),
        (1u64..1 << 52).prop_map(|m| -f64::from_bits(m)),
        (-4i32..4).prop_map(|i| f64::from(i) * 0.5),
    ]
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

// ---------------------------------------------------------------------------------------------
// The course's counts
// ---------------------------------------------------------------------------------------------

#[test]
fn small_sizes_have_the_seed_counts() {
    for n in 0..=40u64 {
        let increasing: Vec<i64> = (0..n as i64).collect();
        let decreasing: Vec<i64> = (0..n as i64).rev().collect();

        for v in [&increasing, &decreasing] {
            let (_, c) = counts_of(Algorithm::Bubble, v);
            assert_eq!(c.comparisons, pairs(n), "bubble n={n}");
            let (_, c) = counts_of(Algorithm::Selection, v);
            assert_eq!(c.comparisons, pairs(n), "selection n={n}");
        }

        // Scanning from the back: reversed input compares with (and shifts) every prefix
        // element, sorted input stops at the first.
        let (_, c) = counts_of(Algorithm::Insertion, &decreasing);
        assert_eq!(
            (c.comparisons, c.moves),
            (pairs(n), pairs(n)),
            "insertion n={n}"
        );
        let (_, c) = counts_of(Algorithm::Insertion, &increasing);
        assert_eq!(
            (c.comparisons, c.moves),
            (n.saturating_sub(1), 0),
            "insertion n={n}"
        );

        // The course's table scans from the front: the mirror image.
        let (_, c) = counts_of(Algorithm::CourseInsertion, &increasing);
        assert_eq!(
            (c.comparisons, c.moves),
            (pairs(n), 0),
            "course insertion n={n}"
        );
        let (_, c) = counts_of(Algorithm::CourseInsertion, &decreasing);
        assert_eq!(
            (c.comparisons, c.moves),
            (n.saturating_sub(1), pairs(n)),
            "course insertion n={n}"
        );

        // Bisection: at most the sum of ceil(log2 k) for k = 2..=n on every input; a
        // decreasing prefix of size k costs floor(log2 k) + 1 = ceil(log2(k + 1)) per step.
        let bound: u64 = (2..=n).map(ceil_log2).sum();
        for v in [&increasing, &decreasing] {
            let (_, c) = counts_of(Algorithm::BinaryInsertion, v);
            assert!(c.comparisons <= bound, "bisection n={n}: {c:?}");
        }
        let (_, c) = counts_of(Algorithm::BinaryInsertion, &decreasing);
        let always_left: u64 = (1..n).map(|k| floor_log2(k) + 1).sum();
        assert_eq!(
            (c.comparisons, c.moves),
            (always_left, pairs(n)),
            "bisection n={n}"
        );
        assert_eq!(always_left, bound, "n={n}");

        let (_, c) = counts_of(Algorithm::CourseBinaryInsertion, &increasing);
        let always_right: u64 = (1..n).map(|k| floor_log2(k) + 1).sum();
        assert_eq!(
            (c.comparisons, c.moves),
            (always_right, 0),
            "bisection n={n}"
        );
        let (_, c) = counts_of(Algorithm::CourseBinaryInsertion, &decreasing);
        let always_left: u64 = (1..n).map(|k| ceil_log2(k) + 1).sum();
        assert_eq!(
            (c.comparisons, c.moves),
            (always_left, pairs(n)),
            "course bisection n={n}"
        );

        let (_, c) = counts_of(Algorithm::Merge, &increasing);
        assert_eq!(c.comparisons, merge_sorted_input(n), "merge n={n}");
        assert_eq!(c.moves, merge_moves(n), "merge n={n}");
        assert_eq!(c.swaps, 0, "merge n={n}");
    }
}

#[test]
fn merge_sort_worst_case_closed_form_matches_its_recurrence() {
    for n in 1..=2000u64 {
        let c = ceil_log2(n);
        assert_eq!(merge_worst(n), n * c + 1 - (1 << c), "n={n}");
        assert!(merge_moves(n) <= n * c, "n={n}");
    }
}

#[test]
fn heap_sort_bound_is_below_two_n_log_n() {
    for n in 2..=5000u64 {
        assert!((heap_bound(n) as f64) <= 2.0 * n_log2_n(n), "n={n}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn quadratic_sorts_count_as_the_seed_says(
        v in prop::collection::vec(-20i64..20, 0..200),
    ) {
        let n = v.len() as u64;
        let inv = inversions(&v);

        let (_, c) = counts_of(Algorithm::Bubble, &v);
        prop_assert_eq!(c.comparisons, pairs(n));
        prop_assert_eq!(c.swaps, inv);

        let (_, c) = counts_of(Algorithm::Selection, &v);
        prop_assert_eq!(c.comparisons, pairs(n));
        prop_assert!(c.swaps <= n.saturating_sub(1));

        // Step k compares x = v[k] with the prefix elements not greater than x, then with
        // the first greater one if there is one.
        let expected: u64 = (1..v.len())
            .map(|k| {
                let not_greater = v[..k].iter().filter(|&&y| y <= v[k]).count() as u64;
                if not_greater < k as u64 { not_greater + 1 } else { k as u64 }
            })
            .sum();
        let (_, c) = counts_of(Algorithm::CourseInsertion, &v);
        prop_assert_eq!(c.comparisons, expected);
        prop_assert_eq!(c.moves, inv);

        // From the back, step k compares with the greater prefix elements, then with the
        // first not greater one if there is one.
        let expected: u64 = (1..v.len())
            .map(|k| {
                let greater = v[..k].iter().filter(|&&y| y > v[k]).count() as u64;
                if greater < k as u64 { greater + 1 } else { k as u64 }
            })
            .sum();
        let (_, c) = counts_of(Algorithm::Insertion, &v);
        prop_assert_eq!(c.comparisons, expected);
        prop_assert_eq!(c.moves, inv);

        let (_, c) = counts_of(Algorithm::BinaryInsertion, &v);
        let low: u64 = (1..n).map(floor_log2).sum();
        let high: u64 = (2..=n).map(ceil_log2).sum();
        prop_assert!(low <= c.comparisons && c.comparisons <= high, "{:?}", c);
        prop_assert_eq!(c.moves, inv);

        let (_, c) = counts_of(Algorithm::CourseBinaryInsertion, &v);
        let low: u64 = (1..n).map(|k| floor_log2(k) + 1).sum();
        let high: u64 = (1..n).map(|k| ceil_log2(k) + 1).sum();
        prop_assert!(low <= c.comparisons && c.comparisons <= high, "{:?}", c);
        prop_assert_eq!(c.moves, inv);
    }

    #[test]
    fn selection_swaps_are_between_n_minus_cycles_and_n_minus_one(
        v in Just((0..150i64).collect::<Vec<_>>()).prop_shuffle(),
    ) {
        let n = v.len() as u64;
        let (_, c) = counts_of(Algorithm::Selection, &v);
        prop_assert!(c.swaps >= n - cycles_of_sorting_permutation(&v));
        prop_assert!(c.swaps < n);
    }

    #[test]
    fn n_log_n_sorts_stay_within_their_bounds(
        v in prop::collection::vec(any::<i64>(), 0..600),
        small in prop::collection::vec(0i64..4, 0..600),
    ) {
        for v in [&v, &small] {
            let n = v.len() as u64;
            let (_, c) = counts_of(Algorithm::Merge, v);
            prop_assert!(c.comparisons <= merge_worst(n));
            prop_assert!(c.comparisons <= n * ceil_log2(n.max(1)));
            prop_assert_eq!(c.moves, merge_moves(n));
            prop_assert!(c.swaps <= n.saturating_sub(1));

            let (_, c) = counts_of(Algorithm::Heap, v);
            prop_assert!(c.comparisons <= heap_bound(n));
            prop_assert!(c.comparisons as f64 <= 2.0 * n_log2_n(n));

            let (_, c) = counts_of(Algorithm::Quick, v);
            prop_assert!(c.comparisons as f64 <= 6.0 * n_log2_n(n) + n as f64);
        }
    }

    #[test]
    fn merge_swaps_are_n_minus_cycles(
        v in Just((0..300i64).collect::<Vec<_>>()).prop_shuffle(),
    ) {
        let (_, c) = counts_of(Algorithm::Merge, &v);
        prop_assert_eq!(c.swaps, v.len() as u64 - cycles_of_sorting_permutation(&v));
    }
}

#[test]
fn quicksort_stays_n_log_n_on_patterned_input() {
    let n = 20_000i64;
    let patterns: [Vec<i64>; 6] = [
        (0..n).collect(),
        (0..n).rev().collect(),
        vec![3; n as usize],
        (0..n).map(|i| i % 5).collect(),
        (0..n).map(|i| i.min(n - i)).collect(),
        (0..n).map(|i| (i * 7919) % 101).collect(),
    ];
    for v in patterns {
        let (sorted, c) = counts_of(Algorithm::Quick, &v);
        let mut expected = v.clone();
        expected.sort_unstable();
        assert_eq!(sorted, expected);
        assert!(
            (c.comparisons as f64) < 1.5 * n_log2_n(n as u64),
            "{} comparisons on input starting {:?}",
            c.comparisons,
            &v[..4]
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Agreement with the standard library
// ---------------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn every_algorithm_agrees_with_std_sort(
        v in prop::collection::vec(any::<i64>(), 0..200),
        few in prop::collection::vec(-3i64..3, 0..200),
    ) {
        for v in [v, few] {
            let mut expected = v.clone();
            expected.sort();
            for algorithm in Algorithm::ALL {
                let mut got = v.clone();
                sort_with(&mut got, algorithm, i64::cmp, &mut NoCount);
                prop_assert_eq!(&got, &expected, "{}", algorithm);
            }
        }
    }

    #[test]
    fn stable_algorithms_keep_equal_keys_in_input_order(
        keys in prop::collection::vec(0u8..6, 0..200),
    ) {
        let tagged: Vec<(u8, usize)> = keys.iter().copied().zip(0..).collect();
        let by_key = |a: &(u8, usize), b: &(u8, usize)| a.0.cmp(&b.0);
        let mut stable = tagged.clone();
        stable.sort_by(by_key);
        let mut all_sorted = tagged.clone();
        all_sorted.sort();
        for algorithm in Algorithm::ALL {
            let mut got = tagged.clone();
            sort_with(&mut got, algorithm, by_key, &mut NoCount);
            if algorithm.is_stable() {
                prop_assert_eq!(&got, &stable, "{}", algorithm);
            } else {
                prop_assert!(got.windows(2).all(|w| w[0].0 <= w[1].0), "{}", algorithm);
                got.sort();
                prop_assert_eq!(&got, &all_sorted, "{} lost or duplicated elements", algorithm);
            }
        }
    }

    #[test]
    fn float_path_agrees_with_sort_by_total_cmp(
        v in prop::collection::vec(any_float(), 0..200),
    ) {
        let mut expected = v.clone();
        expected.sort_by(f64::total_cmp);
        for algorithm in Algorithm::ALL {
            let mut got = v.clone();
            sort_with(&mut got, algorithm, f64::total_cmp, &mut NoCount);
            prop_assert_eq!(bits(&got), bits(&expected), "{}", algorithm);
        }
    }

    #[test]
    fn radix_agrees_bitwise_with_sort_unstable_by_total_cmp(
        v in prop::collection::vec(any_float(), 0..2000),
    ) {
        let mut expected = v.clone();
        expected.sort_unstable_by(f64::total_cmp);
        let mut got = v.clone();
        let mut c = Counts::default();
        radix_sort_f64_with(&mut got, &mut c);
        prop_assert_eq!(bits(&got), bits(&expected));
        let n = v.len() as u64;
        // The linear bounds radix_sort_f64_with documents.
        prop_assert!(c.moves <= 24 * n && 2 * c.comparisons <= 15 * n, "{:?}", c);
    }

    /// Floats that differ only in chosen bits: ties on the top bits, long runs of equal keys
    /// and keys that agree on whole bytes, which the counting passes skip.
    #[test]
    fn radix_agrees_on_keys_varying_in_chosen_bits(
        v in prop::collection::vec(any::<u64>(), 1..3000),
        mask in any::<u64>(),
        low in 0u32..64,
    ) {
        let base = v[0];
        // Either the masked bits or only the low `low` bits of the mask vary.
        let mask = if low % 2 == 0 { mask } else { mask & ((1u64 << low) - 1) };
        let mut x: Vec<f64> = v
            .iter()
            .map(|&b| f64::from_bits((b & mask) | (base & !mask)))
            .collect();
        let mut expected = x.clone();
        expected.sort_unstable_by(f64::total_cmp);
        let n = x.len() as u64;
        let mut c = Counts::default();
        radix_sort_f64_with(&mut x, &mut c);
        prop_assert_eq!(bits(&x), bits(&expected));
        prop_assert!(c.moves <= 24 * n && 2 * c.comparisons <= 15 * n, "{:?}", c);
    }
}

#[test]
fn dispatch_matches_the_named_functions() {
    let v: Vec<i64> = (0..97).map(|i| (i * 37) % 41 - 20).collect();
    type Named = fn(&mut [i64], fn(&i64, &i64) -> Ordering, &mut Counts);
    let named: [(Algorithm, Named); 9] = [
        (Algorithm::Bubble, bubble_sort_with),
        (Algorithm::Selection, selection_sort_with),
        (Algorithm::Insertion, insertion_sort_with),
        (Algorithm::CourseInsertion, course_insertion_sort_with),
        (Algorithm::BinaryInsertion, binary_insertion_sort_with),
        (
            Algorithm::CourseBinaryInsertion,
            course_binary_insertion_sort_with,
        ),
        (Algorithm::Merge, merge_sort_with),
        (Algorithm::Heap, heap_sort_with),
        (Algorithm::Quick, quick_sort_with),
    ];
    for (algorithm, f) in named {
        let (by_enum, c1) = counts_of(algorithm, &v);
        let mut by_name = v.clone();
        let mut c2 = Counts::default();
        f(&mut by_name, i64::cmp, &mut c2);
        assert_eq!(by_enum, by_name, "{algorithm}");
        assert_eq!(c1, c2, "{algorithm}");
        assert!(c1.comparisons > 0, "{algorithm}");
    }
}

#[test]
fn radix_sorts_large_random_input() {
    // xorshift: deterministic bit patterns over the whole f64 range, NaNs included.
    let mut s = 0x9E37_79B9_7F4A_7C15u64;
    let mut v: Vec<f64> = (0..100_000)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            f64::from_bits(s)
        })
        .collect();
    let mut expected = v.clone();
    expected.sort_unstable_by(f64::total_cmp);
    radix_sort_f64(&mut v);
    assert_eq!(bits(&v), bits(&expected));
}

#[test]
fn radix_sorts_the_benchmark_inputs() {
    // The inputs of benches/sort.rs (group radix-f64), past the in-place partition threshold:
    // mixed signs and 128 binades; uniform in [0, 1), most keys in the top few binades.
    let n = 200_000;
    let mixed = compgeo::gen::sequence_f64(n, 3).unwrap();
    let unit: Vec<f64> = compgeo::gen::points(compgeo::gen::PointKind::UniformSquare, n / 2, 3)
        .unwrap()
        .iter()
        .flat_map(|p| [p.x, p.y])
        .collect();
    for mut v in [mixed, unit] {
        let mut expected = v.clone();
        expected.sort_unstable_by(f64::total_cmp);
        let mut c = Counts::default();
        radix_sort_f64_with(&mut v, &mut c);
        assert_eq!(bits(&v), bits(&expected));
        assert!(c.moves <= 24 * n as u64 && 2 * c.comparisons <= 15 * n as u64);
    }
}

#[test]
fn plain_entry_point_uses_ord() {
    let mut v = vec!["pear", "apple", "fig", "apple"];
    bubble_sort(&mut v);
    assert_eq!(v, ["apple", "apple", "fig", "pear"]);
}

// ---------------------------------------------------------------------------------------------
// The course's tables ([RD, §2.1] "Algoritmos de ordenación")
// ---------------------------------------------------------------------------------------------

/// The rows of a two-column table: the text after the first `:` of each line.
fn after_colon(line: &str) -> &str {
    line.split_once(':').map_or("", |(_, rest)| rest.trim())
}

#[test]
fn bubble_trace_matches_the_seed_table() {
    let table = trace(Algorithm::Bubble, &[7, 3, 5, 1]).unwrap();
    let lines: Vec<&str> = table.lines().collect();
    // "Orden inicial 7 3 5 1", "Después de la 1ª comparación: 3 7", ..., "Orden final: 1 3 5 7".
    let seed = [
        ("Initial order", "7 3 5 1"),
        ("After comparison 1", "3 7"),
        ("After comparison 2", "5 7"),
        ("After comparison 3", "1 7"),
        ("After pass 1", "3 5 1 7"),
        ("After comparison 4", "3 5"),
        ("After comparison 5", "1 5"),
        ("After pass 2", "3 1 5 7"),
        ("After comparison 6", "1 3"),
        ("After pass 3 (the last)", "1 3 5 7"),
        ("Final order", "1 3 5 7"),
    ];
    assert_eq!(lines.len(), seed.len() + 2, "{table}");
    assert_eq!(lines[0], "Bubble sort of 7 3 5 1");
    for (line, (label, list)) in lines[1..].iter().zip(seed) {
        assert!(line.starts_with(label), "{line}");
        assert_eq!(after_colon(line), list, "{line}");
    }
    // n(n-1)/2 = 6 comparisons; the table exchanges at every comparison but the 4th.
    assert_eq!(lines[12], "Comparisons: 6, swaps: 5, moves: 0");
}

#[test]
fn selection_trace_matches_the_seed_table() {
    let table = trace(Algorithm::Selection, &[1, 3, 2, 9, 5, 4]).unwrap();
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(lines[0], "Selection sort of 1 3 2 9 5 4");
    assert_eq!(lines[1], "L = {1, 3, 2, 9, 5, 4}");
    // The course: minimum x1 = 1, L := {3, 2, 9, 5, 4}; minimum x3, x2 = 2 and x3 = 3,
    // L := {3, 9, 5, 4}; minimum x3, no operation, L := {9, 5, 4}; minimum x6, x6 = 9 and
    // x4 = 4, L := {5, 9}; minimum x5, no operation, finished; output {1, 2, 3, 4, 5, 9}.
    let seed: [(&str, &[&str], &str); 5] = [
        ("x1 = 1", &["no exchange"], "L := {3, 2, 9, 5, 4}"),
        ("x3", &["x2 = 2", "x3 = 3"], "L := {3, 9, 5, 4}"),
        ("x3", &["no exchange"], "L := {9, 5, 4}"),
        ("x6", &["x4 = 4", "x6 = 9"], "L := {5, 9}"),
        ("x5", &["no exchange"], "the algorithm has finished"),
    ];
    for (k, (line, (minimum, facts, rest))) in lines[2..].iter().zip(seed).enumerate() {
        assert!(line.starts_with(&format!("Step {}: ", k + 1)), "{line}");
        assert!(
            line.contains(&format!("minimum of L is {minimum}")),
            "{line}"
        );
        for fact in facts {
            assert!(line.contains(fact), "{line}");
        }
        assert!(line.ends_with(rest), "{line}");
    }
    assert_eq!(lines[7], "Output: {1, 2, 3, 4, 5, 9}");
    assert_eq!(lines[8], "Comparisons: 15, swaps: 2, moves: 0");
    assert_eq!(lines.len(), 9);
}

#[test]
fn sequential_insertion_trace_matches_the_seed_table() {
    let table = trace(Algorithm::CourseInsertion, &[7, 3, 5, 1, 4, 6]).unwrap();
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(lines[0], "Insertion sort (sequential) of 7 3 5 1 4 6");
    // The course: "3 7 pues 3 < 7", "3 5 7 pues 5 > 3 y 5 < 7", ...
    let seed = [
        ("7", ""),
        ("3 7", "3 < 7"),
        ("3 5 7", "5 > 3 and 5 < 7"),
        ("1 3 5 7", "1 < 3"),
        ("1 3 4 5 7", "4 > 1, 4 > 3 and 4 < 5"),
        ("1 3 4 5 6 7", "6 > 1, 6 > 3, 6 > 4, 6 > 5 and 6 < 7"),
    ];
    for (line, (list, since)) in lines[1..].iter().zip(seed) {
        let (got_list, got_since) = match line.split_once("  since ") {
            Some((l, s)) => (l.trim(), s),
            None => (line.trim(), ""),
        };
        assert_eq!((got_list, got_since), (list, since), "{line}");
    }
    // 1 + 2 + 1 + 3 + 5 comparisons, the course's clauses; 8 shifts (inversions).
    assert_eq!(lines[7], "Comparisons: 12, swaps: 0, moves: 8");
    assert_eq!(lines.len(), 8);
}

#[test]
fn bisection_trace_reproduces_the_seed_block() {
    // The course's block, verbatim but for its "a , b" spacing inside braces.
    let seed = "\
{7}
3 ↦ {7} :
    3 < 7 ⇒ {3 , 7}

{3 , 7}
5 ↦ {3 | 7} :
    5 < 7 ⇒ 5 ↦ {3} :
        5 > 3 ⇒ {3 , 5}

{3 , 5 , 7}
1 ↦ {3 , 5 | 7} :
    1 < 7 ⇒ 1 ↦ {3 | 5} :
        1 < 5 ⇒ 1 ↦ {3} :
            1 < 3 ⇒ {1 , 3}

{1 , 3 , 5 , 7}
4 ↦ {1 , 3 | 5 , 7} :
    4 < 5 ⇒ 4 ↦ {1 | 3} :
        4 > 3 ⇒ 4 ↦ {3} :
            4 > 3 ⇒ {3 , 4}

{1 , 3 , 4 , 5 , 7}
6 ↦ {1 , 3 , 4 | 5 , 7} :
    6 > 5 ⇒ 6 ↦ {5 | 7} :
        6 < 7 ⇒ 6 ↦ {5} :
            6 > 5 ⇒ {5 , 6}

{1 , 3 , 4 , 5 , 6 , 7}
"
    .replace(" , ", ", ");
    let table = trace(Algorithm::CourseBinaryInsertion, &[7, 3, 5, 1, 4, 6]).unwrap();
    let (head, rest) = table.split_once('\n').unwrap();
    assert_eq!(head, "Insertion sort (bisection) of 7 3 5 1 4 6");
    let body = rest.strip_suffix("Comparisons: 12, swaps: 0, moves: 8\n");
    assert_eq!(body, Some(seed.as_str()), "{table}");
}

/// The usual variants on the course's list: same rows, their own comparisons.
#[test]
fn back_scan_and_optimal_bisection_traces_show_their_own_comparisons() {
    let table = trace(Algorithm::Insertion, &[7, 3, 5, 1, 4, 6]).unwrap();
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(
        lines[0],
        "Insertion sort (sequential, from the back) of 7 3 5 1 4 6"
    );
    let rows = [
        ("7", ""),
        ("3 7", "3 < 7"),
        ("3 5 7", "5 < 7 and 5 > 3"),
        ("1 3 5 7", "1 < 7, 1 < 5 and 1 < 3"),
        ("1 3 4 5 7", "4 < 7, 4 < 5 and 4 > 3"),
        ("1 3 4 5 6 7", "6 < 7 and 6 > 5"),
    ];
    for (line, (list, since)) in lines[1..].iter().zip(rows) {
        let (got_list, got_since) = match line.split_once("  since ") {
            Some((l, s)) => (l.trim(), s),
            None => (line.trim(), ""),
        };
        assert_eq!((got_list, got_since), (list, since), "{line}");
    }
    assert_eq!(lines[7], "Comparisons: 11, swaps: 0, moves: 8");

    // The compared element leaves the run: 10 comparisons where the course's table makes 12.
    let expected = "\
{7}
3 ↦ {7} :
    3 < 7 ⇒ {3, 7}

{3, 7}
5 ↦ {3 | 7} :
    5 < 7 ⇒ 5 ↦ {3} :
        5 > 3 ⇒ {3, 5}

{3, 5, 7}
1 ↦ {3 | 5, 7} :
    1 < 5 ⇒ 1 ↦ {3} :
        1 < 3 ⇒ {1, 3}

{1, 3, 5, 7}
4 ↦ {1, 3 | 5, 7} :
    4 < 5 ⇒ 4 ↦ {1 | 3} :
        4 > 3 ⇒ {3, 4}

{1, 3, 4, 5, 7}
6 ↦ {1, 3 | 4, 5, 7} :
    6 > 4 ⇒ 6 ↦ {5 | 7} :
        6 < 7 ⇒ 6 ↦ {5} :
            6 > 5 ⇒ {5, 6}

{1, 3, 4, 5, 6, 7}
";
    let table = trace(Algorithm::BinaryInsertion, &[7, 3, 5, 1, 4, 6]).unwrap();
    let (head, rest) = table.split_once('\n').unwrap();
    assert_eq!(
        head,
        "Insertion sort (bisection, fewest comparisons) of 7 3 5 1 4 6"
    );
    let body = rest.strip_suffix("Comparisons: 10, swaps: 0, moves: 8\n");
    assert_eq!(body, Some(expected), "{table}");
}

#[test]
fn reference_sort_traces_end_sorted_and_show_real_steps() {
    let input = [7, 3, 5, 1, 4, 6];
    let merge = trace(Algorithm::Merge, &input).unwrap();
    let rows: Vec<&str> = merge.lines().filter(|l| l.starts_with("Merge {")).collect();
    // A merge per internal node of the recursion: n - 1 of them, the last one everything.
    assert_eq!(rows.len(), input.len() - 1, "{merge}");
    assert!(rows[4].ends_with("→ {1, 3, 4, 5, 6, 7}"), "{merge}");

    let heap = trace(Algorithm::Heap, &input).unwrap();
    let extractions = heap.lines().filter(|l| l.starts_with("Maximum ")).count();
    assert_eq!(extractions, input.len() - 1, "{heap}");
    assert!(heap.contains("Heap built:"), "{heap}");

    let quick = trace(Algorithm::Quick, &input).unwrap();
    assert!(
        quick.lines().any(|l| l.starts_with("Partition x1..x6")),
        "{quick}"
    );

    for table in [merge, heap, quick] {
        let final_row = table
            .lines()
            .find(|l| l.starts_with("Final order:"))
            .unwrap();
        assert_eq!(after_colon(final_row), "1 3 4 5 6 7", "{table}");
    }
}

#[test]
fn trace_totals_equal_the_counted_sort() {
    let input: Vec<i64> = (0..40).map(|i| (i * 17) % 23).collect();
    for algorithm in Algorithm::ALL {
        let table = trace(algorithm, &input).unwrap();
        let (_, c) = counts_of(algorithm, &input);
        let totals = format!(
            "Comparisons: {}, swaps: {}, moves: {}",
            c.comparisons, c.swaps, c.moves
        );
        assert_eq!(table.lines().last(), Some(totals.as_str()), "{algorithm}");
    }
}

#[test]
fn trace_handles_empty_and_single_input() {
    for algorithm in Algorithm::ALL {
        for input in [&[][..], &[42][..]] {
            let table = trace(algorithm, input).unwrap();
            assert_eq!(
                table.lines().last(),
                Some("Comparisons: 0, swaps: 0, moves: 0")
            );
        }
    }
}

#[test]
fn trace_rejects_inputs_too_long_to_read() {
    let long = vec![0; TRACE_MAX_LEN + 1];
    let err = trace(Algorithm::Merge, &long).unwrap_err();
    assert!(matches!(
        err,
        Error::LimitExceeded {
            limit: "TRACE_MAX_LEN",
            ..
        }
    ));
    let msg = err.to_string();
    assert!(msg.contains(&(TRACE_MAX_LEN + 1).to_string()), "{msg}");
    assert!(trace(Algorithm::Merge, &long[1..]).is_ok());
}

#[test]
fn unknown_algorithm_name_is_a_clear_error() {
    let err = "shell".parse::<Algorithm>().unwrap_err();
    assert_eq!(
        err.to_string(),
        "invalid algorithm: unknown sorting algorithm `shell`; valid names: bubble, selection, \
         insertion, course-insertion, binary-insertion, course-binary-insertion, merge, heap, quick"
    );
}
