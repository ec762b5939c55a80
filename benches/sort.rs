//! Benchmarks of `compgeo::sort`: every algorithm against the standard library's sorts, one
//! group per input kind, over log-spaced sizes; and the `f64` radix sort against
//! `sort_unstable_by(f64::total_cmp)`.
//!
//! Run one group with e.g. `cargo bench --bench sort -- sort-random` or `-- radix`.

use compgeo::count::NoCount;
use compgeo::sort::{radix_sort_f64, Algorithm};
use criterion::measurement::WallTime;
use criterion::{
    criterion_group, criterion_main, BatchSize, BenchmarkGroup, BenchmarkId, Criterion, Throughput,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Duration;

/// The quadratic sorts stop here; the others go on to the largest size.
const QUADRATIC_MAX: usize = 1 << 12;
const SIZES: [usize; 7] = [1 << 4, 1 << 6, 1 << 8, 1 << 10, 1 << 12, 1 << 14, 1 << 16];
const SEED: u64 = 0x5EED_0003;

#[derive(Clone, Copy)]
enum Kind {
    Random,
    Sorted,
    Reversed,
    FewDistinct,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Random => "random",
            Kind::Sorted => "sorted",
            Kind::Reversed => "reversed",
            Kind::FewDistinct => "few-distinct",
        }
    }

    /// A deterministic input of `n` keys of this kind, drawn from `rng` when it is random.
    fn input(self, n: usize, rng: &mut ChaCha8Rng) -> Vec<u64> {
        match self {
            Kind::Random => (0..n).map(|_| rng.random()).collect(),
            Kind::Sorted => (0..n as u64).collect(),
            Kind::Reversed => (0..n as u64).rev().collect(),
            Kind::FewDistinct => (0..n).map(|_| rng.random_range(0..4)).collect(),
        }
    }
}

/// Benchmarks `sort` on inputs of `kind` and size `n`. Random kinds get a fresh input for
/// every iteration (outside the timing): repeating one input lets the branch predictor learn
/// its comparisons, which made branchy sorts look several times faster up to n = 4096. Every
/// sort draws from the same seeded sequence of inputs.
fn bench<F>(group: &mut BenchmarkGroup<'_, WallTime>, name: &str, kind: Kind, n: usize, mut sort: F)
where
    F: FnMut(&mut Vec<u64>),
{
    let mut rng = ChaCha8Rng::seed_from_u64(SEED ^ n as u64);
    let fixed = kind.input(n, &mut rng);
    let fresh = matches!(kind, Kind::Random | Kind::FewDistinct);
    group.bench_function(BenchmarkId::new(name, n), |b| {
        b.iter_batched_ref(
            || {
                if fresh {
                    kind.input(n, &mut rng)
                } else {
                    fixed.clone()
                }
            },
            &mut sort,
            BatchSize::LargeInput,
        )
    });
}

fn quadratic(algorithm: Algorithm) -> bool {
    matches!(
        algorithm,
        Algorithm::Bubble
            | Algorithm::Selection
            | Algorithm::Insertion
            | Algorithm::BinaryInsertion
    )
}

fn sorts(c: &mut Criterion) {
    for kind in [
        Kind::Random,
        Kind::Sorted,
        Kind::Reversed,
        Kind::FewDistinct,
    ] {
        let mut group = c.benchmark_group(format!("sort-{}", kind.name()));
        group
            .sample_size(20)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        for n in SIZES {
            group.throughput(Throughput::Elements(n as u64));
            for algorithm in Algorithm::ALL {
                if quadratic(algorithm) && n > QUADRATIC_MAX {
                    continue;
                }
                bench(&mut group, algorithm.name(), kind, n, |v| {
                    algorithm.sort_with(v, u64::cmp, &mut NoCount)
                });
            }
            bench(&mut group, "std-sort", kind, n, |v| v.sort());
            bench(&mut group, "std-sort-unstable", kind, n, |v| {
                v.sort_unstable()
            });
        }
        group.finish();
    }
}

/// Uniform in [-1, 1): both signs, so every one of the radix sort's eight bytes varies.
fn random_f64(n: usize, rng: &mut ChaCha8Rng) -> Vec<f64> {
    (0..n).map(|_| rng.random_range(-1.0..1.0)).collect()
}

fn radix(c: &mut Criterion) {
    let mut group = c.benchmark_group("radix-f64");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    type Sort = fn(&mut Vec<f64>);
    let peers: [(&str, Sort); 2] = [
        ("radix", |v| radix_sort_f64(v)),
        ("std-sort-unstable-total-cmp", |v| {
            v.sort_unstable_by(f64::total_cmp)
        }),
    ];
    for n in [1_000, 10_000, 100_000, 1_000_000] {
        group.throughput(Throughput::Elements(n as u64));
        for (name, sort) in peers {
            let mut rng = ChaCha8Rng::seed_from_u64(SEED ^ 0xF64 ^ n as u64);
            group.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter_batched_ref(|| random_f64(n, &mut rng), sort, BatchSize::LargeInput)
            });
        }
    }
    group.finish();
}

criterion_group!(benches, sorts, radix);
criterion_main!(benches);
