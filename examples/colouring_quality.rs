//! The colouring-quality table of `docs/colouring.md`: DSatur, DSatur with the tabu search
//! and HEA on the queen graphs queen5_5 … queen13_13, the Mycielski graphs myciel3 …
//! myciel7 and G(n, ½) samples at the sizes of the DIMACS graphs DSJC125.5 … DSJC1000.5,
//! each search with the same budget.
//!
//! Run with `cargo run --release --example colouring_quality -- --time 10` (seconds per
//! search; add `--steps S` for a step budget, `--only NAME` for the rows whose name contains
//! NAME, `--seed S` for the searches' seed). The graphs are generated with fixed seeds, so the
//! table is the same on every machine when only `--steps` is given; with `--time` the searches
//! stop after the same moves wherever the clock stops them.

use compgeo::gen::{graph, GraphKind};
use compgeo::graph::{
    check_colouring, colour_budget, dsatur, Budget, ColouringAlgorithm, Graph, SEARCH_SEED,
};
use std::time::{Duration, Instant};

/// The seed of the G(n, ½) samples (the n-vertex sample uses `GNP_SEED + n`).
const GNP_SEED: u64 = 0xD51C;

fn main() {
    let mut time = None;
    let mut steps = None;
    let mut only = String::new();
    let mut seed = SEARCH_SEED;
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let value = args
            .next()
            .unwrap_or_else(|| usage(&format!("{flag} needs a value")));
        match flag.as_str() {
            "--time" => {
                let secs: f64 = value.parse().unwrap_or_else(|_| usage("--time SECONDS"));
                if !(secs.is_finite() && secs >= 0.0) {
                    usage("--time must be a non-negative number of seconds");
                }
                time = Some(Duration::from_secs_f64(secs));
            }
            "--steps" => steps = Some(value.parse().unwrap_or_else(|_| usage("--steps N"))),
            "--seed" => seed = value.parse().unwrap_or_else(|_| usage("--seed S")),
            "--only" => only = value,
            _ => usage(&format!("unknown option {flag}")),
        }
    }
    let budget = Budget { steps, time };
    if steps.is_none() && time.is_none() {
        usage("give --time SECONDS, --steps N or both");
    }
    println!(
        "| graph | n | m | best known | dsatur | dsatur-tabu | time (s) | best step | hea | time (s) | best step |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for (name, g, known) in instances() {
        if !name.contains(&only) {
            continue;
        }
        let plain = dsatur(&g).count;
        let mut row = format!(
            "| {name} | {} | {} | {known} | {plain} |",
            g.vertex_count(),
            g.edge_count()
        );
        for strategy in [ColouringAlgorithm::DsaturTabu, ColouringAlgorithm::Hea] {
            let clock = Instant::now();
            let (c, report) = colour_budget(&g, strategy, budget, seed).expect("a budget is given");
            let secs = clock.elapsed().as_secs_f64();
            check_colouring(&g, &c.colour).expect("every colouring is proper");
            row += &format!(" {} | {secs:.1} | {} |", c.count, report.best_step);
        }
        println!("{row}");
    }
}

/// The graphs of the table with the best known colour counts (the chromatic number where it
/// is known): queen graphs from the DIMACS list, Mycielski graphs (myciel k is M_{k+1}, of
/// chromatic number k + 1), and the best colourings published for the DSJC graphs of the same
/// size and density.
fn instances() -> Vec<(String, Graph, String)> {
    let mut out = Vec::new();
    let queen_chi = [5, 7, 7, 9, 10, 11, 11, 12, 13];
    for (side, chi) in (5..=13).zip(queen_chi) {
        let g = generated(GraphKind::Queen, side, 0, 0);
        out.push((format!("queen{side}_{side}"), g, chi.to_string()));
    }
    for k in 3..=7 {
        let g = generated(GraphKind::Mycielski, k + 1, 0, 0);
        out.push((format!("myciel{k}"), g, (k + 1).to_string()));
    }
    for (n, known) in [(125, 17), (250, 28), (500, 47), (1000, 82)] {
        let m = n * (n - 1) / 4;
        let g = generated(GraphKind::Gnm, n, m, GNP_SEED + n as u64);
        out.push((format!("G({n}, 1/2)"), g, format!("{known} (DSJC{n}.5)")));
    }
    out
}

fn generated(kind: GraphKind, n: usize, m: usize, seed: u64) -> Graph {
    Graph::from_edge_list(&graph(kind, n, m, seed).expect("the sizes are valid"))
        .expect("generated graphs are valid")
}

fn usage(problem: &str) -> ! {
    eprintln!("error: {problem}");
    eprintln!("usage: colouring_quality [--time SECONDS] [--steps N] [--seed S] [--only NAME]");
    std::process::exit(2);
}
