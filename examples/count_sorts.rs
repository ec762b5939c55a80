//! Watch the course's sorts grow: comparisons of every sorting algorithm on random keys of
//! doubling size, next to n(n-1)/2 and n log2 n.
//!
//! Run with `cargo run --release --example count_sorts`.

use compgeo::count::Counts;
use compgeo::gen::{sequence, SequenceKind};
use compgeo::sort::{sort_with, Algorithm};

fn main() {
    let sizes = [16usize, 32, 64, 128, 256, 512, 1024];
    print!("{:>18}", "n");
    for n in sizes {
        print!("{n:>9}");
    }
    println!();
    for algorithm in Algorithm::ALL {
        print!("{:>18}", algorithm.name());
        for n in sizes {
            let mut keys = sequence(SequenceKind::Random, n, 1).expect("n is far below MAX_KEYS");
            let mut counts = Counts::default();
            sort_with(&mut keys, algorithm, i64::cmp, &mut counts);
            assert!(keys.windows(2).all(|w| w[0] <= w[1]));
            print!("{:>9}", counts.comparisons);
        }
        println!();
    }
    print!("{:>18}", "n(n-1)/2");
    for n in sizes {
        print!("{:>9}", n * (n - 1) / 2);
    }
    println!();
    print!("{:>18}", "n log2 n");
    for n in sizes {
        print!("{:>9}", n * n.ilog2() as usize);
    }
    println!();
}
