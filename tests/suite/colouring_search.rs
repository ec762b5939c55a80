//! The budgeted colouring searches (`dsatur-tabu` and `hea`): proper results, the budget's
//! contract (zero steps return DSatur's colouring, a seed and a step budget fix the result, a
//! time limit only cuts it short), quality against the chromatic number (brute force on small
//! graphs, the known χ of queen and Mycielski graphs), and the command line's `--effort`,
//! `--time` and `--seed`.

use compgeo::gen::{graph, GraphKind};
use compgeo::graph::*;
use compgeo::Error;
use proptest::prelude::*;
use std::time::Duration;

/// The two search strategies through their own entry points.
type Search = fn(&Graph, Budget, u64) -> compgeo::Result<(Colouring, SearchReport)>;
const SEARCHES: [(ColouringAlgorithm, Search); 2] = [
    (ColouringAlgorithm::DsaturTabu, dsatur_tabu_budget),
    (ColouringAlgorithm::Hea, hea_budget),
];

fn generated(kind: GraphKind, n: usize, m: usize, seed: u64) -> Graph {
    Graph::from_edge_list(&graph(kind, n, m, seed).unwrap()).unwrap()
}

/// One graph of every generated family, at a size where DSatur leaves room to search.
fn families() -> Vec<(String, Graph)> {
    let mut out = Vec::new();
    for (kind, n, m, seed) in [
        (GraphKind::Gnm, 120, 1500, 3),
        (GraphKind::Gnm, 300, 900, 4),
        (GraphKind::Grid, 200, 0, 0),
        (GraphKind::Complete, 12, 0, 0),
        (GraphKind::Cycle, 31, 0, 0),
        (GraphKind::Tree, 100, 0, 5),
        (GraphKind::Petersen, 10, 0, 0),
        (GraphKind::Mycielski, 6, 0, 0),
        (GraphKind::Queen, 7, 0, 0),
        (GraphKind::Crown, 20, 0, 0),
    ] {
        out.push((format!("{kind} n={n} m={m}"), generated(kind, n, m, seed)));
    }
    out
}

/// The chromatic number by trying 1, 2, … colours with backtracking: the oracle for small
/// graphs.
fn chromatic_number(g: &Graph) -> usize {
    fn extend(g: &Graph, colour: &mut Vec<usize>, k: usize) -> bool {
        let v = colour.len();
        if v == g.vertex_count() {
            return true;
        }
        for a in 0..k {
            if g.neighbours(v).all(|u| u >= v || colour[u] != a) {
                colour.push(a);
                if extend(g, colour, k) {
                    return true;
                }
                colour.pop();
            }
        }
        false
    }
    (0..=g.vertex_count())
        .find(|&k| extend(g, &mut Vec::new(), k))
        .expect("n colours always suffice")
}

#[test]
fn a_zero_step_budget_returns_the_dsatur_colouring() {
    for (name, g) in families() {
        let plain = dsatur(&g);
        for (strategy, search) in SEARCHES {
            let (c, report) = search(&g, Budget::steps(0), 1).unwrap();
            assert_eq!(c, plain, "{name}, {strategy}");
            assert_eq!(
                (report.steps, report.best_step),
                (0, 0),
                "{name}, {strategy}"
            );
            let (c, _) = search(&g, Budget::time(Duration::ZERO), 1).unwrap();
            assert_eq!(c, plain, "{name}, {strategy}: no time at all");
        }
    }
}

#[test]
fn a_seed_and_a_step_budget_fix_the_colouring() {
    for (name, g) in families() {
        for (strategy, search) in SEARCHES {
            for (steps, seed) in [(5_000, 1), (300_000, 2), (300_000, 3)] {
                let budget = Budget::steps(steps);
                let first = search(&g, budget, seed).unwrap();
                assert_eq!(
                    search(&g, budget, seed).unwrap(),
                    first,
                    "{name}, {strategy}"
                );
                assert_eq!(
                    colour_budget(&g, strategy, budget, seed).unwrap(),
                    first,
                    "{name}, {strategy}: the family's entry point"
                );
                // A time limit that does not end the search changes nothing.
                let timed = budget.and_time(Duration::from_secs(3600));
                assert_eq!(
                    search(&g, timed, seed).unwrap(),
                    first,
                    "{name}, {strategy}"
                );
                let (c, report) = first;
                assert_eq!(check_colouring(&g, &c.colour), Ok(()), "{name}, {strategy}");
                assert!(report.best_step <= report.steps && report.steps <= steps);
                assert!(!report.timed_out);
            }
        }
        // The plain functions are the searches with the default budget and seed.
        let default = Budget::default_for(&g);
        assert_eq!(
            dsatur_tabu(&g),
            dsatur_tabu_budget(&g, default, SEARCH_SEED).unwrap().0
        );
        assert_eq!(hea(&g), hea_budget(&g, default, SEARCH_SEED).unwrap().0);
        assert_eq!(colour(&g, ColouringAlgorithm::Hea), hea(&g), "{name}");
    }
}

#[test]
fn the_searches_are_never_worse_than_dsatur_on_the_generated_families() {
    for (name, g) in families() {
        let plain = dsatur(&g).count;
        for (strategy, search) in SEARCHES {
            for budget in [Budget::default_for(&g), Budget::steps(2_000_000)] {
                let (c, _) = search(&g, budget, 11).unwrap();
                assert_eq!(check_colouring(&g, &c.colour), Ok(()), "{name}, {strategy}");
                assert!(
                    c.count <= plain,
                    "{name}, {strategy}: {} > {plain}",
                    c.count
                );
                assert_eq!(c.count, c.colour.iter().max().map_or(0, |k| k + 1));
            }
        }
    }
}

/// The queen graphs queen5_5 … queen8_8 (χ = 5, 7, 7, 9) and the Mycielski graphs myciel3 …
/// myciel6 (M_4 … M_7, χ = 4 … 7) within a fixed number of steps: known chromatic numbers
/// that DSatur misses on the queens.
#[test]
fn the_searches_reach_the_chromatic_number_of_queen_and_mycielski_graphs() {
    let mut cases: Vec<(String, Graph, usize)> = [(5, 5), (6, 7), (7, 7), (8, 9)]
        .into_iter()
        .map(|(side, chi)| {
            (
                format!("queen{side}_{side}"),
                generated(GraphKind::Queen, side, 0, 0),
                chi,
            )
        })
        .collect();
    for k in 4..=7 {
        cases.push((
            format!("M_{k}"),
            generated(GraphKind::Mycielski, k, 0, 0),
            k,
        ));
    }
    for (name, g, chi) in cases {
        for (strategy, search) in SEARCHES {
            let (c, report) = search(&g, Budget::steps(20_000_000), 7).unwrap();
            assert_eq!(check_colouring(&g, &c.colour), Ok(()));
            assert_eq!(c.count, chi, "{name}, {strategy} ({report:?})");
        }
    }
}

/// The exact phase: queen graphs split into their rows, so at the target n the searches
/// either colour queen n×n with n colours (n = 7, 11, 12, 13, where χ = n) or prove that n colours
/// do not suffice (n = 6, 8, 9, 10, where χ = n + 1); either way the colouring is optimal and
/// the descent stops there, with most of a large budget unspent.
#[test]
fn the_exact_phase_settles_the_queens_up_to_queen13_13() {
    let budget = 4_000_000_000;
    for (side, chi) in [
        (6, 7),
        (7, 7),
        (8, 9),
        (9, 10),
        (10, 11),
        (11, 11),
        (12, 12),
        (13, 13),
    ] {
        let g = generated(GraphKind::Queen, side, 0, 0);
        for (strategy, search) in SEARCHES {
            let (c, report) = search(&g, Budget::steps(budget), 3).unwrap();
            assert_eq!(check_colouring(&g, &c.colour), Ok(()));
            assert_eq!(c.count, chi, "queen{side}_{side}, {strategy} ({report:?})");
            assert!(
                report.steps < budget / 2 && !report.timed_out,
                "queen{side}_{side}, {strategy}: the descent went on ({report:?})"
            );
        }
    }
}

#[test]
fn a_time_limit_alone_ends_the_search() {
    // G(125, 1/2) has no colouring with few colours, so only the time stops the descent.
    let g = generated(GraphKind::Gnm, 125, 125 * 124 / 4, 1);
    for (strategy, search) in SEARCHES {
        let (c, report) = search(&g, Budget::time(Duration::from_millis(200)), 1).unwrap();
        assert_eq!(check_colouring(&g, &c.colour), Ok(()), "{strategy}");
        assert!(
            report.timed_out && report.steps > 0,
            "{strategy}: {report:?}"
        );
        assert!(c.count <= dsatur(&g).count);
    }
}

#[test]
fn a_budget_without_limits_is_refused() {
    let g = generated(GraphKind::Cycle, 5, 0, 0);
    let endless = Budget {
        steps: None,
        time: None,
    };
    for (strategy, search) in SEARCHES {
        for result in [
            search(&g, endless, 0),
            colour_budget(&g, strategy, endless, 0),
        ] {
            assert!(
                matches!(result, Err(Error::InvalidParameter { name: "budget", .. })),
                "{strategy}: {result:?}"
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    /// On small random graphs both searches colour properly within any budget, never use
    /// more colours than DSatur, and with a moderate budget reach the chromatic number.
    #[test]
    fn small_graphs_get_their_chromatic_number(
        n in 1usize..=10,
        pairs in prop::collection::vec((0usize..10, 0usize..10), 0..30),
        steps in 0u64..2_000,
        seed in any::<u64>(),
    ) {
        let edges: Vec<[usize; 2]> = pairs.into_iter().map(|(u, v)| [u % n, v % n]).collect();
        let g = Graph::from_edges(n, &edges).unwrap();
        let chi = chromatic_number(&g);
        let plain = dsatur(&g).count;
        for (strategy, search) in SEARCHES {
            let (short, report) = search(&g, Budget::steps(steps), seed).unwrap();
            prop_assert_eq!(check_colouring(&g, &short.colour), Ok(()));
            prop_assert!(short.count <= plain && short.count >= chi);
            prop_assert!(report.steps <= steps);
            let (long, _) = search(&g, Budget::steps(200_000), seed).unwrap();
            prop_assert_eq!(check_colouring(&g, &long.colour), Ok(()));
            prop_assert_eq!(long.count, chi, "{}", strategy);
        }
    }
}

#[cfg(feature = "cli")]
mod cli {
    use super::*;
    use crate::common::{assert_rejected, run_json};

    const QUEEN6: &str = "queen6_6";

    fn queen_json() -> String {
        let list = graph(GraphKind::Queen, 6, 0, 0).unwrap();
        serde_json::json!({"vertices": list.vertices, "edges": list.edges}).to_string()
    }

    #[test]
    fn effort_time_and_seed_reach_the_search_and_its_report() {
        let g = generated(GraphKind::Queen, 6, 0, 0);
        let input = queen_json();
        for (strategy, search) in SEARCHES {
            let name = strategy.name();
            let args = [
                "colour",
                "--algorithm",
                name,
                "--effort",
                "400000",
                "--seed",
                "9",
                "-",
            ];
            let out = run_json(&args, Some(&input));
            let (c, report) = search(&g, Budget::steps(400_000), 9).unwrap();
            let colours: Vec<usize> = serde_json::from_value(out["colours"].clone()).unwrap();
            assert_eq!(colours, c.colour, "{QUEEN6}, {name}");
            assert_eq!(out["count"], c.count);
            assert_eq!(out["steps"], report.steps);
            assert_eq!(out["best_step"], report.best_step);
            assert_eq!(out["timed_out"], false);
            // A time limit with the steps: the same search unless the clock ends it first.
            let timed = run_json(
                &[
                    "colour",
                    "--algorithm",
                    name,
                    "--effort",
                    "400000",
                    "--seed",
                    "9",
                    "--time",
                    "600",
                    "-",
                ],
                Some(&input),
            );
            assert_eq!(timed["colours"], out["colours"]);
            // Time alone.
            let timed = run_json(
                &["colour", "--algorithm", name, "--time", "0.05", "-"],
                Some(&input),
            );
            assert!(timed["steps"].as_u64().is_some());
            // No budget: the plain strategy.
            let plain = run_json(&["colour", "--algorithm", name, "-"], Some(&input));
            let c = colour(&g, strategy);
            assert_eq!(plain["count"], c.count);
        }
        // Strategies that do not search print no report.
        let out = run_json(&["colour", "--algorithm", "dsatur", "-"], Some(&input));
        assert!(out.get("steps").is_none(), "{out}");
    }

    #[test]
    fn bad_budgets_exit_2_with_the_option_named() {
        let input = queen_json();
        for (option, value) in [
            ("--time", "-1"),
            ("--time", "NaN"),
            ("--time", "inf"),
            ("--time", "1e300"),
            ("--time", "soon"),
            ("--effort", "-5"),
            ("--effort", "1e6"),
            ("--effort", "99999999999999999999999"),
            ("--seed", "-1"),
            ("--seed", "x"),
        ] {
            let args = ["colour", "--algorithm", "hea", option, value, "-"];
            let err = assert_rejected(&args, Some(&input));
            assert!(
                err.contains(option) || err.contains(&option[2..]),
                "{option} {value}: {err}"
            );
        }
        let err = assert_rejected(
            &["colour", "--algorithm", "dsatur", "--effort", "10", "-"],
            Some(&input),
        );
        assert!(err.contains("dsatur-tabu and hea"), "{err}");
    }
}
