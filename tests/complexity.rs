//! The complexity engine on synthetic series whose growth is known exactly: the verdicts must
//! separate true bounds from false ones, survive noise, lower-order terms and constant
//! factors; bounds must evaluate, print and parse consistently; measurement must count exactly.

use std::time::Duration;

use compgeo::complexity::{
    fit, measure, Bound, Entry, Observation, SecondSize, Settings, Verdict, Workload,
    COUNT_TOLERANCE, MIN_SIZES,
};
use compgeo::count::{Counter, Operation};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Doubling sizes `2^lo ..= 2^hi`.
fn sizes(lo: u32, hi: u32) -> Vec<f64> {
    (lo..=hi).map(|k| f64::from(1u32 << k)).collect()
}

/// A series with cost `cost(n, s)` where the second size is `second(n)`.
fn series(
    ns: &[f64],
    second: impl Fn(f64) -> Option<f64>,
    cost: impl Fn(f64, Option<f64>) -> f64,
) -> Vec<Observation> {
    ns.iter()
        .map(|&n| {
            let s = second(n);
            Observation {
                n,
                second: s,
                cost: cost(n, s),
            }
        })
        .collect()
}

fn with_noise(obs: &[Observation], seed: u64, amplitude: f64) -> Vec<Observation> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    obs.iter()
        .map(|o| Observation {
            cost: o.cost * rng.random_range(1.0 - amplitude..=1.0 + amplitude),
            ..*o
        })
        .collect()
}

fn verdict(bound: Bound, obs: &[Observation]) -> Verdict {
    fit(bound, obs, COUNT_TOLERANCE).unwrap().verdict
}

fn lg(x: f64) -> f64 {
    x.log2()
}

/// The second size of a synthetic series as a function of n.
type SecondFn = fn(f64) -> Option<f64>;
/// The cost of a synthetic series as a function of n and the second size.
type CostFn = fn(f64, Option<f64>) -> f64;
/// The synthetic families the tests use: a name, the true bound, the second size, the cost.
type Family = (&'static str, Bound, SecondFn, CostFn);

fn true_families() -> Vec<Family> {
    vec![
        ("n log n", Bound::NLogN, |_| None, |n, _| n * lg(n)),
        ("n^2", Bound::Quadratic, |_| None, |n, _| n * n),
        ("n^3", Bound::Cubic, |_| None, |n, _| n * n * n),
        ("n", Bound::Linear, |_| None, |n, _| n),
        ("1", Bound::Constant, |_| None, |_, _| 7.0),
        ("log n", Bound::Log, |_| None, |n, _| lg(n)),
        (
            "n h, h = sqrt n",
            Bound::NH,
            |n| Some(n.sqrt()),
            |n, h| n * h.unwrap(),
        ),
        ("n h, h = n", Bound::NH, Some, |n, h| n * h.unwrap()),
        // h independent of n: a pseudo-random function of n between 3 and n.
        (
            "n h, h scattered",
            Bound::NH,
            |n| Some(3.0 + (n * 0.618_033_988_7).fract() * (n - 3.0)),
            |n, h| n * h.unwrap(),
        ),
        (
            "n log h, h = sqrt n",
            Bound::NLogH,
            |n| Some(n.sqrt()),
            |n, h| n * lg(h.unwrap()),
        ),
        (
            "n + m, m = 4n",
            Bound::NPlusM,
            |n| Some(4.0 * n),
            |n, m| n + m.unwrap(),
        ),
        (
            "m log m, m = n^2 / 8",
            Bound::MLogM,
            |n| Some(n * n / 8.0),
            |_, m| m.unwrap() * lg(m.unwrap()),
        ),
        (
            "m log n, m = 3n",
            Bound::MLogN,
            |n| Some(3.0 * n),
            |n, m| m.unwrap() * lg(n),
        ),
    ]
}

#[test]
fn quadratic_series_registered_as_n_log_n_exceeds() {
    for ns in [sizes(4, 8), sizes(6, 11), sizes(8, 16)] {
        let obs = series(&ns, |_| None, |n, _| n * n);
        let f = fit(Bound::NLogN, &obs, COUNT_TOLERANCE).unwrap();
        assert_eq!(f.verdict, Verdict::Exceeds, "excess {}", f.excess);
        assert!(f.excess > 0.5, "excess {}", f.excess);
    }
}

#[test]
fn other_polynomial_overshoots_exceed() {
    let ns = sizes(6, 11);
    let cases: [(Bound, SecondFn, CostFn); 5] = [
        (Bound::Quadratic, |_| None, |n, _| n * n * n),
        (Bound::Linear, |_| None, |n, _| n * n.sqrt()),
        (Bound::NLogN, |n| Some(n), |n, _| n * n),
        (
            Bound::NH,
            |n| Some(n.sqrt()),
            |n, h| n * h.unwrap() * h.unwrap(),
        ),
        (Bound::Constant, |_| None, |n, _| n.sqrt()),
    ];
    for (bound, second, cost) in cases {
        let obs = series(&ns, second, cost);
        assert_eq!(verdict(bound, &obs), Verdict::Exceeds, "{bound}");
    }
}

#[test]
fn true_bounds_pass_with_exponent_of_the_bound() {
    for ns in [sizes(4, 8), sizes(6, 11), sizes(8, 18)] {
        for (name, bound, second, cost) in true_families() {
            let obs = series(&ns, second, cost);
            let f = fit(bound, &obs, COUNT_TOLERANCE).unwrap();
            assert_eq!(f.verdict, Verdict::Consistent, "{name}: {f:?}");
            assert!(
                (f.exponent - f.bound_exponent).abs() < 1e-9,
                "{name}: cost is exactly f, so the exponents agree: {f:?}"
            );
        }
    }
}

#[test]
fn twenty_percent_noise_never_flips_a_verdict() {
    let false_claims: Vec<Family> = vec![
        ("n^2 as n log n", Bound::NLogN, |_| None, |n, _| n * n),
        ("n^3 as n^2", Bound::Quadratic, |_| None, |n, _| n * n * n),
        ("n^2 as n", Bound::Linear, |_| None, |n, _| n * n),
        (
            "n h (h = n) as n log n",
            Bound::NLogN,
            |n| Some(n),
            |n, _| n * n,
        ),
    ];
    for ns in [sizes(6, 6 + MIN_SIZES as u32 - 1), sizes(6, 12)] {
        for seed in 0..300 {
            for (name, bound, second, cost) in true_families() {
                let obs = with_noise(&series(&ns, second, cost), seed, 0.2);
                let f = fit(bound, &obs, COUNT_TOLERANCE).unwrap();
                assert_eq!(f.verdict, Verdict::Consistent, "{name} seed {seed}: {f:?}");
            }
            for (name, bound, second, cost) in &false_claims {
                let obs = with_noise(&series(&ns, second, cost), seed, 0.2);
                let f = fit(*bound, &obs, COUNT_TOLERANCE).unwrap();
                assert_eq!(f.verdict, Verdict::Exceeds, "{name} seed {seed}: {f:?}");
            }
        }
    }
}

#[test]
fn worst_case_twenty_percent_noise_stays_within_tolerance() {
    // The most damaging noise pattern: -20 % on the smaller half, +20 % on the larger half.
    for k in MIN_SIZES as u32..=10 {
        let ns = sizes(6, 6 + k - 1);
        let half = ns.len() as f64 / 2.0;
        let obs: Vec<Observation> = ns
            .iter()
            .enumerate()
            .map(|(i, &n)| {
                let factor = match (i as f64 + 0.5).partial_cmp(&half).unwrap() {
                    std::cmp::Ordering::Less => 0.8,
                    std::cmp::Ordering::Equal => 1.0,
                    std::cmp::Ordering::Greater => 1.2,
                };
                Observation {
                    n,
                    second: None,
                    cost: factor * n * n,
                }
            })
            .collect();
        let f = fit(Bound::Quadratic, &obs, COUNT_TOLERANCE).unwrap();
        assert!(
            f.excess > 0.0 && f.excess <= COUNT_TOLERANCE,
            "{k} sizes: {f:?}"
        );
    }
}

#[test]
fn lower_order_terms_pass() {
    let ns = sizes(4, 12);
    let cases: [(Bound, CostFn); 5] = [
        (Bound::NLogN, |n, _| 3.0 * n * lg(n) + 50.0 * n),
        (Bound::NLogN, |n, _| n * lg(n) - n + 1.0),
        (Bound::Quadratic, |n, _| n * (n - 1.0) / 2.0),
        (Bound::Quadratic, |n, _| 0.25 * n * n + 100.0 * n + 1000.0),
        (Bound::Cubic, |n, _| n * n * n / 6.0 + 20.0 * n * n),
    ];
    for (bound, cost) in cases {
        let obs = series(&ns, |_| None, cost);
        let f = fit(bound, &obs, COUNT_TOLERANCE).unwrap();
        assert_eq!(f.verdict, Verdict::Consistent, "{bound}: {f:?}");
    }
}

#[test]
fn constant_factors_do_not_matter() {
    let ns = sizes(5, 12);
    for (name, bound, second, cost) in true_families() {
        let base = fit(bound, &series(&ns, second, cost), COUNT_TOLERANCE).unwrap();
        for scale in [1e-6, 0.5, 3.0, 1e9] {
            let scaled: Vec<Observation> = series(&ns, second, cost)
                .into_iter()
                .map(|o| Observation {
                    cost: (o.cost * scale).max(1.0),
                    ..o
                })
                .collect();
            let f = fit(bound, &scaled, COUNT_TOLERANCE).unwrap();
            if scaled.iter().all(|o| o.cost > 1.0) {
                assert!((f.excess - base.excess).abs() < 1e-9, "{name} x{scale}");
                for (a, b) in f.normalised.iter().zip(&base.normalised) {
                    assert!((a / b / scale - 1.0).abs() < 1e-9, "{name} x{scale}");
                }
            }
            assert_eq!(f.verdict, base.verdict, "{name} x{scale}");
        }
    }
    let quad = series(&ns, |_| None, |n, _| n * n);
    for scale in [1e-3, 1.0, 1e6] {
        let obs: Vec<Observation> = quad
            .iter()
            .map(|o| Observation {
                cost: o.cost * scale,
                ..*o
            })
            .collect();
        assert_eq!(verdict(Bound::NLogN, &obs), Verdict::Exceeds, "x{scale}");
    }
}

#[test]
fn bound_text_round_trips_and_is_the_json_text() {
    let expected = [
        "O(1)",
        "O(log n)",
        "O(n)",
        "O(n log n)",
        "O(n^2)",
        "O(n^3)",
        "O(nh)",
        "O(n log h)",
        "O(n + m)",
        "O(m log m)",
        "O(m log n)",
    ];
    assert_eq!(Bound::ALL.len(), expected.len());
    for (b, text) in Bound::ALL.into_iter().zip(expected) {
        assert_eq!(b.to_string(), text);
        assert_eq!(text.parse::<Bound>().unwrap(), b);
        assert_eq!(
            text.to_uppercase()
                .replace(' ', "")
                .parse::<Bound>()
                .unwrap(),
            b
        );
    }
    let err = "O(2^n)".parse::<Bound>().unwrap_err();
    assert!(err.to_string().contains("O(2^n)"), "{err}");
}

#[test]
fn bound_eval_matches_the_formulas() {
    let lgf = |x: f64| x.max(2.0).log2();
    for n in [1.0, 2.0, 3.0, 10.0, 1000.0, 1e6] {
        for s in [1.0, 2.0, 5.0, 4000.0] {
            let cases = [
                (Bound::Constant, 1.0),
                (Bound::Log, lgf(n)),
                (Bound::Linear, n),
                (Bound::NLogN, n * lgf(n)),
                (Bound::Quadratic, n.powi(2)),
                (Bound::Cubic, n.powi(3)),
                (Bound::NH, n * s),
                (Bound::NLogH, n * lgf(s)),
                (Bound::NPlusM, n + s),
                (Bound::MLogM, s * lgf(s)),
                (Bound::MLogN, s * lgf(n)),
            ];
            for (b, want) in cases {
                let got = b.eval(n, Some(s));
                assert!((got - want).abs() <= 1e-12 * want, "{b} at n={n}, s={s}");
                assert!(got >= 1.0, "{b} at n={n}, s={s}: f >= 1 for sizes >= 1");
            }
        }
    }
    assert_eq!(Bound::NLogN.eval(1.0, None), 1.0);
    assert_eq!(Bound::NH.second_size(), Some(SecondSize::Output));
    assert_eq!(Bound::MLogN.second_size(), Some(SecondSize::Edges));
    assert_eq!(Bound::Cubic.second_size(), None);
}

/// A synthetic algorithm with known counts: for each of n keys, scans a prefix of length
/// `h` (the "output", a seeded function of n) with one comparison per step.
struct PrefixScan;

impl Workload for PrefixScan {
    type Input = Vec<u64>;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> compgeo::Result<Vec<u64>> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ n as u64);
        Ok((0..n).map(|_| rng.random_range(0..1000)).collect())
    }

    fn run<C: Counter>(&self, keys: &mut Vec<u64>, c: &mut C) -> compgeo::Result<usize> {
        let h = (keys.len() as f64).sqrt() as usize;
        let mut hits = 0;
        for &k in keys.iter() {
            for &p in &keys[..h] {
                c.comparison();
                if p < k {
                    hits += 1;
                }
            }
        }
        std::hint::black_box(hits);
        Ok(h)
    }

    fn output_size(&self, _: &Vec<u64>, h: &usize) -> Option<usize> {
        Some(*h)
    }
}

fn tiny_settings() -> Settings {
    Settings {
        batch_time: Duration::from_micros(20),
        batches: 3,
        ..Settings::default()
    }
}

#[test]
fn measure_counts_exactly_and_reports_h() {
    let entry = Entry::new("scan/prefix", Bound::NH, Operation::Comparisons, PrefixScan);
    let ns = [16, 32, 64, 128, 256];
    let mut seen = Vec::new();
    let m = measure(&entry, &ns, &tiny_settings(), &mut |p| {
        seen.push((p.n, p.done, p.total))
    })
    .unwrap();
    assert_eq!(
        seen,
        [(16, 1, 5), (32, 2, 5), (64, 3, 5), (128, 4, 5), (256, 5, 5)]
    );
    for (s, &n) in m.samples.iter().zip(&ns) {
        let h = (n as f64).sqrt() as usize;
        assert_eq!(s.n, n);
        assert_eq!(s.h, Some(h));
        assert_eq!(s.m, None);
        assert_eq!(s.counts.comparisons, (n * h) as u64);
        assert_eq!(s.counts.total(), (n * h) as u64);
        assert!(s.time_ns > 0.0);
    }
    assert_eq!(m.counts.verdict, Verdict::Consistent);
    assert!((m.counts.exponent - 1.5).abs() < 0.02, "{:?}", m.counts);
    for r in &m.counts.normalised {
        assert!((r - 1.0).abs() < 1e-12);
    }
    // The same counts claimed as O(n) must be flagged.
    let liar = Entry::new(
        "scan/prefix",
        Bound::Linear,
        Operation::Comparisons,
        PrefixScan,
    );
    let m = measure(&liar, &ns, &tiny_settings(), &mut |_| {}).unwrap();
    assert_eq!(m.counts.verdict, Verdict::Exceeds);
}

#[test]
fn measure_rejects_too_few_sizes() {
    let entry = Entry::new("scan/prefix", Bound::NH, Operation::Comparisons, PrefixScan);
    let err = measure(&entry, &[16, 32, 64], &tiny_settings(), &mut |_| {}).unwrap_err();
    assert!(
        matches!(err, compgeo::Error::TooFew { got: 3, .. }),
        "{err}"
    );
}
