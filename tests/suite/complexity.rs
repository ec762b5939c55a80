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
        ("sqrt n", Bound::Sqrt, |_| None, |n, _| n.sqrt()),
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
        "O(sqrt n)",
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
                (Bound::Sqrt, n.sqrt()),
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

/// A test double: every pair of n keys compared once, n(n − 1)/2 comparisons.
struct AllPairs;

impl Workload for AllPairs {
    type Input = Vec<u64>;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> compgeo::Result<Vec<u64>> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ n as u64);
        Ok((0..n).map(|_| rng.random_range(0..1000)).collect())
    }

    fn run<C: Counter>(&self, keys: &mut Vec<u64>, c: &mut C) -> compgeo::Result<usize> {
        let mut equal = 0;
        for (i, a) in keys.iter().enumerate() {
            for b in &keys[i + 1..] {
                c.comparison();
                equal += usize::from(a == b);
            }
        }
        Ok(std::hint::black_box(equal))
    }
}

/// The double's declaration, with a false claim: O(n) for its quadratic loop.
static MISSTATED: compgeo::complexity::Declaration = compgeo::complexity::Declaration {
    problem: "pairs",
    name: "all",
    function: "tests::AllPairs",
    file: "tests/suite/complexity.rs",
    summary: "every pair compared once, declared linear by mistake",
    time: "O(n)",
    space: "O(1)",
    operation: Some(Operation::Comparisons),
    counts: "",
    source: "[RD, ch. 2]",
    claims: &[compgeo::complexity::on(
        "random",
        Bound::Linear,
        Operation::Comparisons,
    )],
};

#[test]
fn a_quadratic_loop_declared_linear_is_caught_as_exceeding() {
    let entry = Entry::declared(&MISSTATED, "random", AllPairs).quick(32, 512);
    assert_eq!(
        (entry.info.bound, &*entry.info.id),
        (Bound::Linear, "pairs/all")
    );
    let sizes = entry.sizes(compgeo::complexity::Profile::Quick);
    let m = measure(&entry, &sizes, &tiny_settings(), &mut |_| {}).unwrap();
    for s in &m.samples {
        assert_eq!(s.counts.comparisons, (s.n * (s.n - 1) / 2) as u64);
    }
    assert_eq!(m.counts.verdict, Verdict::Exceeds, "{:?}", m.counts);
    assert!((m.counts.exponent - 2.0).abs() < 0.1, "{:?}", m.counts);
    assert!(m.counts.excess > 0.8, "{:?}", m.counts);
    // The same loop declared quadratic passes: the verdict is about the claim.
    let honest = Entry::new(
        "pairs/all",
        Bound::Quadratic,
        Operation::Comparisons,
        AllPairs,
    );
    let m = measure(&honest, &sizes, &tiny_settings(), &mut |_| {}).unwrap();
    assert_eq!(m.counts.verdict, Verdict::Consistent, "{:?}", m.counts);
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

#[cfg(feature = "cli")]
use crate::common::TempDir;

#[cfg(feature = "cli")]
mod report {
    use super::*;
    use compgeo::complexity::report::{
        read_criterion, write_criterion_report, write_report, UserBound,
    };
    use compgeo::complexity::{Machine, Profile};
    use serde_json::Value;

    fn read_json(path: &std::path::Path) -> Value {
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
    }

    #[test]
    fn results_json_has_the_contract_shape() {
        let dir = TempDir::new("report");
        let ns = [8, 16, 32, 64, 128];
        let entries = [
            Entry::new("scan/prefix", Bound::NH, Operation::Comparisons, PrefixScan),
            Entry::new(
                "scan/prefix",
                Bound::Linear,
                Operation::Comparisons,
                PrefixScan,
            )
            .input("liar"),
        ];
        let measured: Vec<_> = entries
            .iter()
            .map(|e| measure(e, &ns, &tiny_settings(), &mut |_| {}).unwrap())
            .collect();
        let machine = Machine::current();
        let index = write_report(&dir.0, &machine, Profile::Quick, &measured).unwrap();
        assert_eq!(index, dir.0.join("index.html"));

        let json = read_json(&dir.0.join("results.json"));
        let m = &json["machine"];
        assert_eq!(m["cores"].as_u64(), Some(machine.cores as u64));
        for key in ["os", "arch", "compgeo_version"] {
            assert!(m[key].is_string(), "machine.{key}");
        }
        assert!(m.get("cpu").is_some());
        assert_eq!(json["profile"], "quick");
        let algorithms = json["algorithms"].as_array().unwrap();
        assert_eq!(algorithms.len(), 2);
        for (a, want) in algorithms.iter().zip(["consistent", "exceeds"]) {
            assert_eq!(a["id"], "scan/prefix");
            assert_eq!(a["problem"], "scan");
            assert_eq!(a["operation"], "comparisons");
            assert!(a["exponent_counts"].as_f64().unwrap() > 1.4);
            assert!(a["exponent_time"].as_f64().unwrap().is_finite());
            assert_eq!(a["verdict"], want);
            let samples = a["samples"].as_array().unwrap();
            assert_eq!(samples.len(), ns.len());
            for (s, &n) in samples.iter().zip(&ns) {
                assert_eq!(s["n"].as_u64(), Some(n as u64));
                assert!(s["m"].is_null());
                let h = (n as f64).sqrt() as u64;
                assert_eq!(s["h"].as_u64(), Some(h));
                assert!(s["time_ns"].as_f64().unwrap() > 0.0);
                let counts = s["counts"].as_object().unwrap();
                for op in Operation::ALL {
                    assert!(counts.contains_key(op.name()), "counts.{}", op.name());
                }
                assert_eq!(counts["comparisons"].as_u64(), Some(n as u64 * h));
            }
        }
        assert_eq!(algorithms[0]["bound"], "O(nh)");
        assert_eq!(algorithms[0]["input"], "random");
        assert_eq!(algorithms[1]["bound"], "O(n)");
        assert_eq!(algorithms[1]["input"], "liar");

        let html = std::fs::read_to_string(&index).unwrap();
        for file in [
            "scan-prefix-random.svg",
            "scan-prefix-liar.svg",
            "problem-scan.svg",
        ] {
            assert!(html.contains(&format!("src=\"{file}\"")), "{file} embedded");
            let svg = std::fs::read_to_string(dir.0.join(file)).unwrap();
            assert!(svg.starts_with("<svg") && svg.contains("<text"), "{file}");
        }
        let svg = std::fs::read_to_string(dir.0.join("scan-prefix-random.svg")).unwrap();
        for label in [
            "O(nh)",
            "comparisons",
            "time per run (ns)",
            "n (input size)",
        ] {
            assert!(svg.contains(label), "{label} on the growth chart");
        }
        assert!(html.contains("<td>exceeds</td>"));
        assert_eq!(json["verdict_counts"]["consistent"], 1);
        assert_eq!(json["verdict_counts"]["exceeds"], 1);
        assert_eq!(json["verdict_counts"]["none"], 0);
        // Two rows, one algorithm (the same id on two inputs).
        assert_eq!(json["measured_algorithms"], 1);
        assert!(html.contains("Algorithms measured with exact counts: 1. Rows: 2,"));
        for a in algorithms {
            assert_eq!(a["module"], "other", "scan is not a declared problem");
            assert_eq!(a["role"], "compgeo");
            let samples = a["samples"].as_array().unwrap();
            assert_eq!(
                samples[0]["time_repeats_ns"].as_array().unwrap().len(),
                tiny_settings().batches
            );
        }
        assert!(html.contains("other &mdash; 2 rows: 1 consistent, 1 exceeds"));
    }

    /// Writes a criterion-0.8-style measurement: `group/function/n/new/{benchmark,estimates}.json`.
    pub(super) fn fixture(
        root: &std::path::Path,
        group: &str,
        function: &str,
        n: usize,
        median: f64,
    ) {
        let dir = root
            .join(group.replace('/', "_"))
            .join(function)
            .join(n.to_string())
            .join("new");
        std::fs::create_dir_all(&dir).unwrap();
        let bench = serde_json::json!({
            "group_id": group, "function_id": function, "value_str": n.to_string(),
            "throughput": {"Elements": n},
            "full_id": format!("{group}/{function}/{n}"),
            "directory_name": format!("{}/{function}/{n}", group.replace('/', "_")),
            "title": format!("{group}/{function}/{n}"),
        });
        std::fs::write(dir.join("benchmark.json"), bench.to_string()).unwrap();
        let est = |v: f64| {
            serde_json::json!({
                "confidence_interval": {"confidence_level": 0.95, "lower_bound": v * 0.9, "upper_bound": v * 1.1},
                "point_estimate": v, "standard_error": v * 0.01,
            })
        };
        let estimates = serde_json::json!({
            "mean": est(median * 1.05), "median": est(median),
            "median_abs_dev": est(median * 0.01), "slope": null, "std_dev": est(median * 0.02),
        });
        std::fs::write(dir.join("estimates.json"), estimates.to_string()).unwrap();
    }

    #[test]
    fn criterion_import_groups_sizes_and_matches_the_catalog() {
        let root = TempDir::new("criterion");
        let ns = [64, 128, 256, 512, 1024, 2048];
        for &n in &ns {
            let x = n as f64;
            fixture(&root.0, "scan", "prefix", n, 3.0 * x * x.sqrt());
            fixture(&root.0, "scan", "other", n, 2.0 * x * x);
            fixture(&root.0, "scan/liar", "prefix", n, x * x);
        }
        // Criterion's HTML report directory and a non-numeric size are not measurements.
        std::fs::create_dir_all(root.0.join("scan/prefix/report/new")).unwrap();
        std::fs::write(root.0.join("scan/prefix/report/new/estimates.json"), "{}").unwrap();
        fixture(&root.0, "scan", "odd", 1, 5.0);
        let odd = root.0.join("scan/odd/1/new/benchmark.json");
        let text = std::fs::read_to_string(&odd)
            .unwrap()
            .replace("\"1\"", "\"tiny\"");
        std::fs::write(&odd, text.replace("{\"Elements\":1}", "null")).unwrap();
        std::fs::rename(root.0.join("scan/odd/1"), root.0.join("scan/odd/tiny")).unwrap();

        let import = read_criterion(&root.0).unwrap();
        let ids: Vec<String> = import.benchmarks.iter().map(|b| b.id()).collect();
        assert_eq!(ids, ["scan/liar/prefix", "scan/other", "scan/prefix"]);
        assert_eq!(import.skipped.len(), 1, "{:?}", import.skipped);
        assert!(import.skipped[0].0.ends_with("scan/odd/tiny/new"));
        let prefix = &import.benchmarks[2];
        assert_eq!(
            prefix.samples.iter().map(|s| s.0).collect::<Vec<_>>(),
            ns.to_vec()
        );
        assert_eq!(prefix.samples[0].1, 3.0 * 64.0 * 8.0, "median, not mean");

        let catalog = [
            Entry::new(
                "scan/prefix",
                Bound::NLogN,
                Operation::Comparisons,
                PrefixScan,
            )
            .input("random")
            .info,
            Entry::new(
                "scan/prefix",
                Bound::Linear,
                Operation::Comparisons,
                PrefixScan,
            )
            .input("liar")
            .info,
        ];
        let user: Vec<UserBound> = vec!["scan/other=O(n^2)".parse().unwrap()];
        let out = TempDir::new("criterion-out");
        let index =
            write_criterion_report(&out.0, &Machine::current(), &import, &catalog, &user).unwrap();
        assert!(index.is_file());
        let json = read_json(&out.0.join("results.json"));
        assert_eq!(json["profile"], "criterion");
        let algs = json["algorithms"].as_array().unwrap();
        let by_id = |id: &str| algs.iter().find(|a| a["id"] == id).unwrap();
        // x^1.5 against O(n log n) (matched via the catalog): within the time tolerance.
        let p = by_id("scan/prefix");
        assert_eq!(p["bound"], "O(n log n)");
        assert!(p["input"].is_null(), "the group names no input");
        assert!((p["exponent_time"].as_f64().unwrap() - 1.5).abs() < 1e-9);
        assert_eq!(p["verdict_time"], "consistent");
        assert!(p["verdict"].is_null() && p["exponent_counts"].is_null());
        assert!(p["samples"][0]["counts"].is_null());
        // The group names the input: matched to the "liar" entry, O(n) against x^2.
        let l = by_id("scan/liar/prefix");
        assert_eq!(l["input"], "liar");
        assert_eq!(l["verdict_time"], "exceeds");
        // No catalog entry: the user's bound.
        let o = by_id("scan/other");
        assert_eq!(o["bound"], "O(n^2)");
        assert!((o["exponent_time"].as_f64().unwrap() - 2.0).abs() < 1e-9);
        assert_eq!(o["verdict_time"], "consistent");
        for file in ["scan-prefix.svg", "scan-other.svg", "scan-liar-prefix.svg"] {
            assert!(out.0.join(file).is_file(), "{file}");
        }
        assert!(read_criterion(&root.0.join("missing")).is_err());
    }

    /// Writes criterion's `sample.json` (iteration counts and total times) next to a fixture.
    fn sample_fixture(
        root: &std::path::Path,
        group: &str,
        function: &str,
        n: usize,
        per_iter: &[f64],
    ) {
        let dir = root
            .join(group.replace('/', "_"))
            .join(function)
            .join(n.to_string())
            .join("new");
        let iters: Vec<f64> = (1..=per_iter.len()).map(|i| i as f64).collect();
        let times: Vec<f64> = per_iter.iter().zip(&iters).map(|(t, i)| t * i).collect();
        let sample = serde_json::json!({"sampling_mode": "Linear", "iters": iters, "times": times});
        std::fs::write(dir.join("sample.json"), sample.to_string()).unwrap();
    }

    #[test]
    fn criterion_peers_are_drawn_with_ratios_to_compgeo() {
        let root = TempDir::new("criterion-peers");
        let ns = [64, 128, 256, 512, 1024];
        for &n in &ns {
            let x = n as f64;
            fixture(&root.0, "scan", "prefix", n, 4.0 * x);
            fixture(&root.0, "scan", "other", n, 3.0 * x * x.sqrt());
            fixture(&root.0, "scan", "spade-bulk", n, 8.0 * x);
            fixture(&root.0, "scan", "std", n, 2.0 * x);
            sample_fixture(&root.0, "scan", "prefix", n, &[3.8 * x, 4.0 * x, 4.3 * x]);
        }
        let import = read_criterion(&root.0).unwrap();
        let prefix = import
            .benchmarks
            .iter()
            .find(|b| b.id() == "scan/prefix")
            .unwrap();
        assert_eq!(prefix.repeats.len(), ns.len());
        assert_eq!(prefix.repeats[0], [3.8 * 64.0, 4.0 * 64.0, 4.3 * 64.0]);
        assert!(compgeo::complexity::report::is_peer("spade-bulk"));
        assert!(compgeo::complexity::report::is_peer("std"));
        assert!(!compgeo::complexity::report::is_peer("prefix"));
        assert!(!compgeo::complexity::report::is_peer("geodesic"));

        let catalog = [Entry::new(
            "scan/prefix",
            Bound::Linear,
            Operation::Comparisons,
            PrefixScan,
        )
        .info];
        let out = TempDir::new("criterion-peers-out");
        let index =
            write_criterion_report(&out.0, &Machine::current(), &import, &catalog, &[]).unwrap();
        let json = read_json(&out.0.join("results.json"));
        let algs = json["algorithms"].as_array().unwrap();
        let by_id = |id: &str| algs.iter().find(|a| a["id"] == id).unwrap();
        for (id, role) in [
            ("scan/prefix", "compgeo"),
            ("scan/other", "compgeo"),
            ("scan/spade-bulk", "peer"),
            ("scan/std", "peer"),
        ] {
            assert_eq!(by_id(id)["role"], role, "{id}");
        }
        // compgeo's fastest at n is min(4n, 3n^1.5) = 4n from n = 2 on.
        for (i, &n) in ns.iter().enumerate() {
            let x = n as f64;
            let spade = by_id("scan/spade-bulk")["samples"][i]["ratio_to_compgeo"]
                .as_f64()
                .unwrap();
            let std = by_id("scan/std")["samples"][i]["ratio_to_compgeo"]
                .as_f64()
                .unwrap();
            assert!((spade - 4.0 * x / (8.0 * x)).abs() < 1e-12);
            assert!((std - 4.0 * x / (2.0 * x)).abs() < 1e-12);
            assert!(by_id("scan/prefix")["samples"][i]["ratio_to_compgeo"].is_null());
        }
        // A peer takes no bound from the catalog; the repetitions give an interval.
        assert!(by_id("scan/spade-bulk")["bound"].is_null());
        let interval = by_id("scan/prefix")["exponent_time_interval"]
            .as_array()
            .unwrap();
        let (lo, hi) = (interval[0].as_f64().unwrap(), interval[1].as_f64().unwrap());
        assert!(
            lo <= 1.0 + 1e-9 && 1.0 - 1e-9 <= hi && hi - lo < 0.2,
            "[{lo}, {hi}]"
        );
        assert!(
            by_id("scan/other")["exponent_time_interval"].is_null(),
            "no sample.json"
        );
        assert_eq!(json["verdict_counts"]["none"], 4);
        assert_eq!(
            json["measured_algorithms"], 0,
            "criterion rows have no counts"
        );
        let html = std::fs::read_to_string(&index).unwrap();
        assert!(
            html.contains("scan/spade-bulk (slope 1.00)"),
            "ratio table header"
        );
        assert!(
            html.contains("<td class=\"num\">0.50&times;</td>"),
            "spade ratio"
        );
        assert!(
            html.contains("<td class=\"num\">2.00&times;</td>"),
            "std ratio"
        );
        let chart = std::fs::read_to_string(out.0.join("problem-scan.svg")).unwrap();
        assert!(chart.contains("scan/std (peer), log-log slope 1.00"));
    }
}

#[test]
fn exponent_interval_brackets_the_true_exponent_and_widens_with_noise() {
    use compgeo::complexity::exponent_interval;
    let sizes: Vec<f64> = (6..12).map(|k| f64::from(1u32 << k)).collect();
    // Repetitions with multiplicative noise of the given amplitude around c·n^1.5.
    let repeats = |amplitude: f64, seed: u64| -> Vec<Vec<f64>> {
        sizes
            .iter()
            .enumerate()
            .map(|(i, n)| {
                (0..7u64)
                    .map(|r| {
                        let noise = with_noise(
                            &[Observation {
                                n: *n,
                                second: None,
                                cost: 1.0,
                            }],
                            seed ^ (i as u64 * 31 + r),
                            amplitude,
                        )[0]
                        .cost;
                        5.0 * n.powf(1.5) * noise
                    })
                    .collect()
            })
            .collect()
    };
    // Identical repetitions: every resample fits the same slope.
    let exact: Vec<Vec<f64>> = sizes.iter().map(|n| vec![n.powf(1.5); 5]).collect();
    let (lo, hi) = exponent_interval(&sizes, &exact).unwrap();
    assert!((lo - 1.5).abs() < 1e-12 && (hi - 1.5).abs() < 1e-12);
    let quiet = repeats(0.05, 7);
    let loud = repeats(0.4, 7);
    let (qlo, qhi) = exponent_interval(&sizes, &quiet).unwrap();
    let (llo, lhi) = exponent_interval(&sizes, &loud).unwrap();
    assert!(qlo <= 1.5 && 1.5 <= qhi, "[{qlo}, {qhi}] misses 1.5");
    assert!(qhi - qlo < lhi - llo, "more noise, wider interval");
    assert_eq!(
        exponent_interval(&sizes, &quiet),
        Some((qlo, qhi)),
        "seeded"
    );
    // One usable size, or nothing positive, gives no interval.
    assert_eq!(exponent_interval(&sizes[..1], &quiet[..1]), None);
    let empty: Vec<Vec<f64>> = sizes.iter().map(|_| vec![0.0, f64::NAN]).collect();
    assert_eq!(exponent_interval(&sizes, &empty), None);
}

#[test]
fn every_catalog_entry_is_unique_sized_and_consistent() {
    let all = compgeo::complexity::catalog();
    let mut keys: Vec<String> = all.iter().map(|e| e.info.key()).collect();
    keys.sort();
    let n = keys.len();
    keys.dedup();
    assert_eq!(keys.len(), n, "duplicate keys");
    let settings = Settings {
        batch_time: Duration::ZERO,
        batches: 1,
        ..Settings::default()
    };
    for entry in &all {
        let key = entry.info.key();
        assert!(
            key.starts_with(&format!("{}/", entry.info.problem)),
            "{key}"
        );
        for profile in [
            compgeo::complexity::Profile::Quick,
            compgeo::complexity::Profile::Full,
        ] {
            assert!(entry.sizes(profile).len() >= MIN_SIZES, "{key} {profile}");
        }
        // The first sizes of the quick profile: enough for a fit, small enough for a debug build.
        let sizes = &entry.sizes(compgeo::complexity::Profile::Quick)[..MIN_SIZES];
        let m = measure(entry, sizes, &settings, &mut |_| {}).unwrap();
        assert_eq!(
            m.counts.verdict,
            Verdict::Consistent,
            "{key}: {:?}",
            m.counts
        );
        assert!(
            m.counts.excess > -0.5,
            "{key}: the bound should be tight on its registered input: {:?}",
            m.counts
        );
    }
}

#[test]
fn sort_entries_cover_the_required_inputs() {
    let all = compgeo::complexity::catalog();
    let has = |key: &str| all.iter().any(|e| e.info.key() == key);
    for name in [
        "bubble",
        "selection",
        "insertion",
        "course-insertion",
        "binary-insertion",
        "course-binary-insertion",
        "merge",
        "heap",
        "quick",
    ] {
        assert!(has(&format!("sort/{name}/random")), "{name}");
    }
    for key in [
        "sort/insertion/sorted",
        "sort/insertion/reversed",
        "sort/course-insertion/sorted",
        "sort/course-insertion/reversed",
        "sort/quick/sorted",
    ] {
        assert!(has(key), "{key}");
    }
}

#[cfg(feature = "cli")]
mod cli {
    use super::TempDir;
    use crate::common::assert_rejected;
    use serde_json::Value;

    fn run(args: &[&str]) -> (i32, String, String) {
        crate::common::run(args, None)
    }

    fn assert_usage_error(args: &[&str], mentions: &str) {
        let err = assert_rejected(args, None);
        assert!(err.contains(mentions), "{args:?}: {err}");
    }

    #[test]
    fn report_measures_the_selected_entry_and_says_where_it_wrote() {
        let dir = TempDir::new("cli-report");
        let out_dir = dir.0.join("out");
        let out_arg = out_dir.to_str().unwrap();
        let (code, out, err) = run(&[
            "report",
            "--only",
            "sort/insertion/reversed",
            "--out",
            out_arg,
        ]);
        assert_eq!(code, 0, "{err}");
        assert!(err.contains("index.html"), "{err}");
        let printed: Value = serde_json::from_str(out.trim()).unwrap();
        assert_eq!(
            printed["index"],
            out_dir.join("index.html").to_str().unwrap()
        );
        assert_eq!(printed["algorithms"], 1);
        assert_eq!(printed["measured_algorithms"], 1);
        assert_eq!(printed["exceeds"], serde_json::json!([]));
        let results: Value =
            serde_json::from_str(&std::fs::read_to_string(out_dir.join("results.json")).unwrap())
                .unwrap();
        let a = &results["algorithms"][0];
        assert_eq!(a["id"], "sort/insertion");
        assert_eq!(a["input"], "reversed");
        assert_eq!(a["operation"], "comparisons");
        let e = a["exponent_counts"].as_f64().unwrap();
        assert!((e - 2.0).abs() < 0.1, "exponent {e}");
        // Reversed keys: every pair is an inversion, one comparison and one move each.
        for s in a["samples"].as_array().unwrap() {
            let n = s["n"].as_u64().unwrap();
            assert_eq!(s["counts"]["comparisons"].as_u64(), Some(n * (n - 1) / 2));
            assert_eq!(s["counts"]["moves"].as_u64(), Some(n * (n - 1) / 2));
        }
        assert!(out_dir.join("sort-insertion-reversed.svg").is_file());
        assert!(out_dir.join("problem-sort.svg").is_file());
    }

    #[test]
    fn report_rejects_bad_arguments_with_one_error_line() {
        assert_usage_error(&["report", "--only", "no/such/entry"], "no/such/entry");
        assert_usage_error(&["report", "--bound", "sort/std=O(n log n)"], "--criterion");
        assert_usage_error(
            &["report", "--criterion", "target", "--bound", "sort=O(2^n)"],
            "O(2^n)",
        );
        assert_usage_error(&["report", "--quick", "--full"], "--full");
        let missing = TempDir::new("cli-missing");
        let path = missing.0.join("absent");
        assert_usage_error(&["report", "--criterion", path.to_str().unwrap()], "absent");
    }

    #[test]
    fn report_draws_criterion_measurements() {
        let root = TempDir::new("cli-criterion");
        for n in [64usize, 128, 256, 512, 1024] {
            super::report::fixture(&root.0, "sort", "std", n, 5.0 * n as f64);
        }
        let out_dir = root.0.join("out");
        let (code, out, err) = run(&[
            "report",
            "--criterion",
            root.0.to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
            "--bound",
            "sort/std=O(n log n)",
        ]);
        assert_eq!(code, 0, "{err}");
        let printed: Value = serde_json::from_str(out.trim()).unwrap();
        assert_eq!(printed["profile"], "criterion");
        assert_eq!(printed["algorithms"], 1);
        let results: Value =
            serde_json::from_str(&std::fs::read_to_string(out_dir.join("results.json")).unwrap())
                .unwrap();
        let a = &results["algorithms"][0];
        assert_eq!(a["id"], "sort/std");
        assert_eq!(a["bound"], "O(n log n)");
        assert_eq!(a["verdict_time"], "consistent");
        assert!(out_dir.join("sort-std.svg").is_file());
    }
}
