//! The `parallel` feature (compiled only with it): every parallel path gives what the
//! sequential path gives, bit for bit, on inputs on both sides of the threshold (2¹⁶ items),
//! in the default pool and, for the radix sorts, in pools of 1, 2 and 3 threads on skewed
//! input.
//! The sequential results come from the same functions run with a recording counter
//! ([`Silent`]), which the parallel paths leave alone, or from an independent sort.

use compgeo::count::{NoCount, Silent};
use compgeo::delaunay::{
    check_delaunay, divide_and_conquer_with, dual, incremental, incremental_with, voronoi,
    Triangulation,
};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{comparison_sorted_lex, parallel_sorted_lex, Point2, PointSet};
use compgeo::hull::{
    akl_toussaint, akl_toussaint_with, convex_hull, convex_hull_with, Algorithm, HullOptions,
};
use compgeo::sort::{radix_sort_f64, radix_sort_f64_with};

/// Sizes just below, at and well above the threshold.
const SIZES: [usize; 4] = [1000, 65_535, 65_536, 150_000];

const KINDS: [PointKind; 8] = [
    PointKind::UniformSquare,
    PointKind::Clustered,
    PointKind::Grid,
    PointKind::NearDuplicates,
    PointKind::Collinear,
    PointKind::Cocircular,
    PointKind::Huge,
    PointKind::Tiny,
];

fn bits(items: &[(Point2, usize)]) -> Vec<(u64, u64, usize)> {
    items
        .iter()
        .map(|(p, i)| (p.x.to_bits(), p.y.to_bits(), *i))
        .collect()
}

/// `pts` with every point repeated (a copy of each, in a shuffled place) and some zeros
/// negated, so that ties on the key and on -0.0/0.0 are common.
fn with_duplicates(pts: &[Point2], seed: u64) -> Vec<Point2> {
    let mut rng = Rng(seed);
    let mut out: Vec<Point2> = pts.iter().chain(pts).copied().collect();
    for i in (1..out.len()).rev() {
        let j = (rng.next_u64() % (i as u64 + 1)) as usize;
        out.swap(i, j);
    }
    for p in out.iter_mut().step_by(7) {
        if p.x == 0.0 {
            p.x = -0.0;
        }
    }
    out
}

fn inputs() -> Vec<(String, Vec<Point2>)> {
    let mut all = Vec::new();
    for kind in KINDS {
        for n in SIZES {
            all.push((format!("{kind}, n = {n}"), points(kind, n, 21).unwrap()));
        }
    }
    let half = points(PointKind::Grid, 40_000, 22).unwrap();
    all.push(("grid with duplicates".into(), with_duplicates(&half, 3)));
    let half = points(PointKind::UniformDisk, 70_000, 23).unwrap();
    all.push(("disk with duplicates".into(), with_duplicates(&half, 4)));
    all
}

#[test]
fn the_parallel_lexicographic_sort_is_the_comparison_sort() {
    for (what, pts) in inputs() {
        assert_eq!(
            bits(&parallel_sorted_lex(&pts)),
            bits(&comparison_sorted_lex(&pts)),
            "{what}"
        );
    }
}

#[test]
fn the_parallel_f64_radix_sort_is_the_sequential_one() {
    let mut rng = Rng(5);
    let specials = [
        0.0,
        -0.0,
        f64::NAN,
        -f64::NAN,
        f64::INFINITY,
        5e-324,
        -1.0,
        1.0,
    ];
    for n in SIZES {
        let v: Vec<f64> = (0..n)
            .map(|k| match k % 5 {
                0 => specials[(rng.next_u64() % 8) as usize],
                1 => (rng.next_u64() % 100) as f64,
                _ => f64::from_bits(rng.next_u64()),
            })
            .collect();
        let mut parallel = v.clone();
        radix_sort_f64(&mut parallel);
        let mut sequential = v.clone();
        radix_sort_f64_with(&mut sequential, &mut Silent);
        let mut oracle = v;
        oracle.sort_unstable_by(f64::total_cmp);
        let b = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(b(&parallel), b(&oracle), "n = {n}");
        assert_eq!(b(&sequential), b(&oracle), "n = {n}");
    }
}

/// Runs `f` in rayon pools of 1, 2 and 3 threads (1: the sequential path; 3: more chunks
/// and buckets in flight than cores) and returns the three results.
fn in_pools<T: Send>(f: impl Fn() -> T + Sync) -> Vec<T> {
    [1, 2, 3]
        .into_iter()
        .map(|k| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(k)
                .build()
                .unwrap();
            pool.install(&f)
        })
        .collect()
}

/// Skewed `f64` inputs of `n` keys: all equal, two values, one value with a few others (one
/// huge bucket), the specials (NaNs of both signs and payloads, ±0, ±∞, subnormals), uniform
/// in [0, 1) (half the keys in the top binade), and keys equal in their top 40 bits.
fn skewed_floats(n: usize, rng: &mut Rng) -> Vec<(&'static str, Vec<f64>)> {
    let specials = [
        0.0,
        -0.0,
        f64::NAN,
        -f64::NAN,
        f64::from_bits(0x7FF0_0000_0000_0001),
        f64::from_bits(0xFFF8_0000_0000_0123),
        f64::INFINITY,
        f64::NEG_INFINITY,
        5e-324,
        -5e-324,
        f64::MIN_POSITIVE / 3.0,
        -f64::MIN_POSITIVE,
    ];
    let one = 1.0f64.to_bits();
    vec![
        ("all equal", vec![-2.5; n]),
        (
            "two values",
            (0..n)
                .map(|_| if rng.next_u64() % 2 == 0 { 0.0 } else { -0.0 })
                .collect(),
        ),
        (
            "one huge bucket",
            (0..n)
                .map(|k| if k % 97 == 0 { k as f64 } else { 1.0 })
                .collect(),
        ),
        (
            "specials",
            (0..n)
                .map(|_| specials[(rng.next_u64() % 12) as usize])
                .collect(),
        ),
        (
            "unit",
            (0..n)
                .map(|_| (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
                .collect(),
        ),
        (
            "equal top bits",
            (0..n)
                .map(|_| f64::from_bits(one + (rng.next_u64() & 0xFF_FFFF)))
                .collect(),
        ),
    ]
}

/// The bits of `v` sorted by `radix_sort_f64` in pools of 1, 2 and 3 threads.
fn sorted_in_every_pool(v: &[f64]) -> Vec<Vec<u64>> {
    in_pools(|| {
        let mut w = v.to_vec();
        radix_sort_f64(&mut w);
        w.iter().map(|x| x.to_bits()).collect()
    })
}

#[test]
fn the_parallel_f64_radix_sort_is_the_sequential_one_on_skewed_input_in_every_pool() {
    let mut rng = Rng(6);
    let b = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    for n in [65_535, 65_536, 300_000] {
        for (what, v) in skewed_floats(n, &mut rng) {
            let mut oracle = v.clone();
            oracle.sort_unstable_by(f64::total_cmp);
            let mut sequential = v.clone();
            radix_sort_f64_with(&mut sequential, &mut Silent);
            assert_eq!(b(&sequential), b(&oracle), "sequential, {what}, n = {n}");
            for (k, sorted) in sorted_in_every_pool(&v).into_iter().enumerate() {
                assert_eq!(sorted, b(&oracle), "{} threads, {what}, n = {n}", k + 1);
            }
        }
    }
}

/// From 2^21 keys the `f64` sort takes its parallel path (below, the two threads gained
/// nothing on the benchmark machine): at that size, the uniform and the special keys.
#[test]
fn the_parallel_f64_radix_sort_is_the_sequential_one_from_two_million_keys() {
    let mut rng = Rng(7);
    let b = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let n = 1 << 21;
    for (what, v) in skewed_floats(n, &mut rng)
        .into_iter()
        .filter(|(what, _)| ["unit", "specials"].contains(what))
    {
        let mut oracle = v.clone();
        oracle.sort_unstable_by(f64::total_cmp);
        for (k, sorted) in sorted_in_every_pool(&v).into_iter().enumerate() {
            assert_eq!(sorted, b(&oracle), "{} threads, {what}", k + 1);
        }
    }
}

#[test]
fn the_parallel_lexicographic_sort_is_the_comparison_sort_on_skewed_input_in_every_pool() {
    let mut rng = Rng(7);
    for n in [65_535, 65_536, 200_000] {
        let mut coordinate = |m: u64| (rng.next_u64() % m) as f64;
        let skewed: Vec<(&str, Vec<Point2>)> = vec![
            ("all equal", vec![Point2::new(-1.5, 3.0); n]),
            (
                "equal x",
                (0..n).map(|_| Point2::new(7.0, coordinate(1000))).collect(),
            ),
            (
                "two points, signed zeros",
                (0..n)
                    .map(|k| match k % 3 {
                        0 => Point2::new(0.0, -0.0),
                        1 => Point2::new(-0.0, 0.0),
                        _ => Point2::new(1.0, 1.0),
                    })
                    .collect(),
            ),
            (
                "one huge bucket",
                (0..n)
                    .map(|k| {
                        let x = if k % 50 == 0 {
                            coordinate(1 << 40)
                        } else {
                            1.0
                        };
                        Point2::new(x, coordinate(1 << 20) * 1e-9)
                    })
                    .collect(),
            ),
            (
                "duplicates",
                (0..n)
                    .map(|_| Point2::new(coordinate(300), coordinate(300)))
                    .collect(),
            ),
            (
                "subnormals and huge",
                (0..n)
                    .map(|_| {
                        let x = f64::from_bits(coordinate(1 << 30) as u64);
                        let y = if coordinate(2) == 0.0 {
                            f64::MAX
                        } else {
                            -1e300
                        };
                        Point2::new(x, y)
                    })
                    .collect(),
            ),
        ];
        for (what, pts) in skewed {
            let expected = bits(&comparison_sorted_lex(&pts));
            for (k, sorted) in in_pools(|| parallel_sorted_lex(&pts))
                .into_iter()
                .enumerate()
            {
                assert_eq!(
                    bits(&sorted),
                    expected,
                    "{} threads, {what}, n = {n}",
                    k + 1
                );
            }
        }
    }
}

#[test]
fn parallel_hulls_equal_the_sequential_ones() {
    for (what, pts) in inputs() {
        let set = PointSet::new(&pts).unwrap();
        for keep_collinear in [false, true] {
            let options = HullOptions { keep_collinear };
            let parallel = akl_toussaint(&pts, options).unwrap();
            assert_eq!(
                parallel,
                akl_toussaint_with(&set, options, &mut Silent),
                "akl-toussaint, {what}, {keep_collinear}"
            );
            // The sequential monotone chain: the same hull by another algorithm.
            let chain = convex_hull_with(&set, Algorithm::MonotoneChain, options, &mut Silent);
            assert_eq!(
                convex_hull(&pts, Algorithm::MonotoneChain, options).unwrap(),
                chain,
                "monotone chain, {what}, {keep_collinear}"
            );
            assert_eq!(parallel, chain, "akl-toussaint, {what}, {keep_collinear}");
        }
    }
}

#[test]
fn the_parallel_point_set_check_names_the_first_bad_point_and_keeps_the_box() {
    let pts = points(PointKind::Gaussian, 150_000, 8).unwrap();
    let set = PointSet::new(&pts).unwrap();
    // The box by an independent fold.
    let fold =
        |f: fn(f64, f64) -> f64, c: fn(&Point2) -> f64| pts.iter().map(c).fold(c(&pts[0]), f);
    let b = set.bounding_box().unwrap();
    assert_eq!(b.min.x, fold(f64::min, |p| p.x));
    assert_eq!(b.min.y, fold(f64::min, |p| p.y));
    assert_eq!(b.max.x, fold(f64::max, |p| p.x));
    assert_eq!(b.max.y, fold(f64::max, |p| p.y));
    for bad in [
        [0, 149_999],
        [40_000, 140_000],
        [98_303, 98_304],
        [70_000, 70_000],
    ] {
        let mut broken = pts.clone();
        broken[bad[1]].x = f64::NAN;
        broken[bad[0]].y = f64::INFINITY;
        match PointSet::new(&broken) {
            Err(compgeo::Error::NonFinite { index, value }) => {
                assert_eq!(index, bad[0], "{bad:?}");
                assert!(if bad[0] == bad[1] {
                    value.is_nan()
                } else {
                    value.is_infinite()
                });
            }
            other => panic!("{bad:?}: {other:?}"),
        }
    }
    // Signed zeros: the first of equal extremes is kept.
    let mut zeros = vec![Point2::new(1.0, 1.0); 100_000];
    zeros[50_000] = Point2::new(-0.0, -0.0);
    zeros[80_000] = Point2::new(0.0, 0.0);
    let b = PointSet::new(&zeros).unwrap().bounding_box().unwrap();
    assert!(b.min.x.is_sign_negative() && b.min.y.is_sign_negative());
}

/// The triangles as sorted vertex triples, each rotated to start at its least vertex.
fn triangle_set(t: &Triangulation) -> Vec<[usize; 3]> {
    let mut all: Vec<[usize; 3]> = t
        .triangles
        .chunks(3)
        .map(|c| {
            let k = (0..3).min_by_key(|&k| c[k]).unwrap();
            [c[k], c[(k + 1) % 3], c[(k + 2) % 3]]
        })
        .collect();
    all.sort_unstable();
    all
}

#[test]
fn parallel_delaunay_paths_equal_the_sequential_ones() {
    // Uniform points: no four cocircular, so the triangulation is unique and every builder
    // must give the same triangles.
    for n in [65_535, 65_536, 150_000] {
        let pts = points(PointKind::UniformSquare, n, 31).unwrap();
        let set = PointSet::new(&pts).unwrap();
        let parallel = incremental(&pts).unwrap();
        check_delaunay(&pts, &parallel).unwrap();
        let sequential = divide_and_conquer_with(&set, &mut Silent).unwrap();
        assert_eq!(
            triangle_set(&parallel),
            triangle_set(&sequential),
            "n = {n}"
        );
        // The divide and conquer's own sort: parallel with NoCount.
        let fast = divide_and_conquer_with(&set, &mut NoCount).unwrap();
        assert_eq!(fast, sequential, "n = {n}");
    }
    // A grid (cocircular everywhere): the builders may break ties differently, so the
    // exact checker judges, and the same builder must not depend on the path.
    let pts = points(PointKind::Grid, 90_000, 32).unwrap();
    let set = PointSet::new(&pts).unwrap();
    check_delaunay(&pts, &incremental(&pts).unwrap()).unwrap();
    assert_eq!(
        divide_and_conquer_with(&set, &mut NoCount).unwrap(),
        divide_and_conquer_with(&set, &mut Silent).unwrap()
    );
}

/// From 2¹⁹ points the incremental builder triangulates two halves (on two threads here)
/// and merges them: the triangulation is the same in pools of 1, 2 and 3 threads and with a
/// recording counter (the halves one after the other), on clustered input and on a grid
/// with duplicates (cocircular points everywhere), and the exact checker accepts it.
#[test]
fn split_delaunay_builds_equal_the_sequential_ones() {
    let grid = points(PointKind::Grid, 265_000, 51).unwrap();
    for (what, pts) in [
        (
            "clustered",
            points(PointKind::Clustered, 530_000, 52).unwrap(),
        ),
        ("grid with duplicates", with_duplicates(&grid, 7)),
    ] {
        assert!(pts.len() >= 1 << 19, "{what}: too small to split");
        let builds = in_pools(|| incremental(&pts).unwrap());
        assert_eq!(builds[1], builds[0], "{what}, 2 threads");
        assert_eq!(builds[2], builds[0], "{what}, 3 threads");
        let set = PointSet::new(&pts).unwrap();
        let counted = incremental_with(&set, &mut Silent).unwrap();
        assert_eq!(counted, builds[0], "{what}, counted");
        check_delaunay(&pts, &builds[0]).unwrap();
    }
}

/// The Voronoi cells (the builder's own dual, and the dual of a given triangulation) are
/// the same in pools of 1, 2 and 3 threads: circumcentres and walks in parallel change
/// nothing, on inputs large enough to take the parallel path (2¹⁶ triangles), with
/// duplicates and cocircular points among them.
#[test]
fn parallel_voronoi_cells_equal_the_sequential_ones() {
    let grid = points(PointKind::Grid, 40_000, 41).unwrap();
    let disk = points(PointKind::UniformDisk, 40_000, 42).unwrap();
    for (what, pts) in [
        (
            "uniform",
            points(PointKind::UniformSquare, 40_000, 43).unwrap(),
        ),
        (
            "clustered",
            points(PointKind::Clustered, 60_000, 44).unwrap(),
        ),
        ("grid with duplicates", with_duplicates(&grid, 5)),
        ("disk with duplicates", with_duplicates(&disk, 6)),
    ] {
        let diagrams = in_pools(|| voronoi(&pts).unwrap());
        assert!(diagrams[0].vertices.len() >= 1 << 16, "{what}: too small");
        assert_eq!(diagrams[1], diagrams[0], "{what}, 2 threads");
        assert_eq!(diagrams[2], diagrams[0], "{what}, 3 threads");
        let t = incremental(&pts).unwrap();
        let duals = in_pools(|| dual(&pts, &t).unwrap());
        assert_eq!(duals[1], duals[0], "{what}, dual, 2 threads");
        assert_eq!(duals[2], duals[0], "{what}, dual, 3 threads");
    }
}

/// SplitMix64: a small deterministic source for the test data.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}
