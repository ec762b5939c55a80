//! Benchmarks of `compgeo::sort`: every algorithm against the standard library's sorts, one
//! group per input kind, over log-spaced sizes; and the `f64` radix sort against
//! `sort_unstable_by(f64::total_cmp)`.
//!
//! Run one group with e.g. `cargo bench --bench sort -- sort-random` or `-- radix`.

use compgeo::sort::{radix_sort_f64, Algorithm};
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
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

    /// A deterministic input of `n` keys of this kind.
    fn input(self, n: usize) -> Vec<u64> {
        let mut rng = ChaCha8Rng::seed_from_u64(SEED ^ n as u64);
        match self {
            Kind::Random => (0..n).map(|_| rng.random()).collect(),
            Kind::Sorted => (0..n as u64).collect(),
            Kind::Reversed => (0..n as u64).rev().collect(),
            Kind::FewDistinct => (0..n).map(|_| rng.random_range(0..4)).collect(),
        }
    }
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
            let input = kind.input(n);
            group.throughput(Throughput::Elements(n as u64));
            for algorithm in Algorithm::ALL {
                if quadratic(algorithm) && n > QUADRATIC_MAX {
                    continue;
                }
                group.bench_with_input(BenchmarkId::new(algorithm.name(), n), &input, |b, v| {
                    b.iter_batched_ref(
                        || v.clone(),
                        |v| algorithm.sort_with(v, u64::cmp, &mut compgeo::count::NoCount),
                        BatchSize::LargeInput,
                    )
                });
            }
            group.bench_with_input(BenchmarkId::new("std-sort", n), &input, |b, v| {
                b.iter_batched_ref(|| v.clone(), |v| v.sort(), BatchSize::LargeInput)
            });
            group.bench_with_input(BenchmarkId::new("std-sort-unstable", n), &input, |b, v| {
                b.iter_batched_ref(|| v.clone(), |v| v.sort_unstable(), BatchSize::LargeInput)
            });
        }
        group.finish();
    }
}

/// Uniform in [-1, 1): both signs, so every one of the radix sort's eight bytes varies.
fn random_f64(n: usize) -> Vec<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(SEED ^ 0xF64);
    (0..n).map(|_| rng.random_range(-1.0..1.0)).collect()
}

fn radix(c: &mut Criterion) {
    let mut group = c.benchmark_group("radix-f64");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    for n in [1_000, 10_000, 100_000, 1_000_000] {
        let input = random_f64(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("radix", n), &input, |b, v| {
            b.iter_batched_ref(|| v.clone(), |v| radix_sort_f64(v), BatchSize::LargeInput)
        });
        group.bench_with_input(
            BenchmarkId::new("std-sort-unstable-total-cmp", n),
            &input,
            |b, v| {
                b.iter_batched_ref(
                    || v.clone(),
                    |v| v.sort_unstable_by(f64::total_cmp),
                    BatchSize::LargeInput,
                )
            },
        );
    }
    group.finish();
}

criterion_group!(benches, sorts, radix);
criterion_main!(benches);
