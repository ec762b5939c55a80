//! The hybrid evolutionary algorithm of Galinier and Hao (HEA, 1999): a small population of
//! colourings, the greedy partition crossover, and the tabu search as the local step.
//!
//! To colour a graph with k colours, HEA keeps [`POPULATION`] assignments of k colours (not
//! necessarily proper) and repeats: choose two of them at random, cross them with the greedy
//! partition crossover (GPX), improve the offspring with a fixed number of tabu-search
//! iterations ([`TabuCol`]), and let it replace the worse of its two parents. GPX builds the
//! offspring one colour class at a time, alternating between the parents: it takes the
//! largest class left in the parent whose turn it is, and removes those vertices from both
//! parents; the vertices left after k classes take random colours. Large classes are the
//! parents' good part, and taking them whole keeps what the tabu search has built.
//!
//! Here HEA runs inside the descent the tabu search uses ([`reduce`](super::reduce)):
//! DSatur's k colours first, then k − 1, k − 2, … on the t-core, so it never returns more
//! colours than DSatur. For each target the first member comes from the best colouring so
//! far (its last class merged into the others) and the others from random-order greedy
//! colourings; every member is improved by the tabu search before the crossovers start, and
//! the target is reached as soon as any tabu search ends without conflicts. Every operation
//! is paid from the [`Budget`] in steps: the tabu iterations as in
//! [`dsatur_tabu_budget`](super::dsatur_tabu_budget), a new member n + 2m + n·k, a crossover
//! n + k², where n and m count the core's vertices and edges. The random choices come from
//! the seed, so a graph, a seed and a step budget give the same colouring on every machine.
//!
//! Source: P. Galinier and J.-K. Hao, *Hybrid evolutionary algorithms for graph coloring*,
//! Journal of Combinatorial Optimization 3(4), 379–397, 1999 (cited as \[GH99, HEA\] in
//! `docs/references.md`).
//!
//! The tests check every colouring with [`check_colouring`](super::check_colouring), that
//! HEA is never worse than DSatur and reaches the chromatic number of small queen and
//! Mycielski graphs, that a zero budget returns DSatur's colouring and that the same seed and
//! step budget give the same colouring, and that GPX gives every vertex a colour in range
//! with the parents' largest classes kept whole.

use super::budget::{Budget, Meter, SearchReport, SEARCH_SEED};
use super::reduce::{descend, Core};
use super::tabu::TabuCol;
use super::{dsatur_with, Colouring};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::gen::Rng;
use crate::graph::Graph;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "colour",
    name: "hea",
    function: "graph::hea",
    file: "src/graph/colouring/hea.rs",
    summary:
        "DSatur, then a hybrid evolutionary search (tabu search and greedy partition crossover)",
    time: "O((n + m) log n)",
    space: "O(n + m)",
    operation: Some(Operation::Comparisons),
    counts: "DSatur's heap comparisons plus at most 20(n + 2m) search steps",
    source: "[GH99, HEA]",
    claims: &[on("gnm-4n", Bound::MLogN, Operation::Comparisons)],
};

/// The number of colourings HEA keeps.
pub const POPULATION: usize = 10;

/// DSatur, then HEA with the default budget, [`Budget::default_for`]`(g)`; see [`hea_with`].
///
/// # Complexity
/// O((n + m) log n) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{check_colouring, dsatur, hea, Graph};
///
/// let g = Graph::from_edge_list(&graph(GraphKind::Gnm, 300, 1500, 7)?)?;
/// let c = hea(&g);
/// assert_eq!(check_colouring(&g, &c.colour), Ok(()));
/// assert!(c.count < dsatur(&g).count);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn hea(g: &Graph) -> Colouring {
    hea_with(g, &mut NoCount)
}

/// DSatur followed by HEA for fewer colours, with the default budget of
/// [`TABU_EFFORT`](super::TABU_EFFORT)·(n + 2m) steps and the seed [`SEARCH_SEED`],
/// counting the work of both. For a budget and seed of your own, see [`hea_budget`].
///
/// # Complexity
/// O((n + m) log n) time: DSatur's, plus at most 20·(n + 2m) search steps. Auxiliary space
/// O(n + m): DSatur's, the [`POPULATION`] colourings of the core and one tabu search's
/// tables (O(m), see [`dsatur_tabu_with`](super::dsatur_tabu_with)).
///
/// # Counts
/// DSatur's counts, plus one `comparison` per move the tabu search evaluates and one
/// `edge_visit` per neighbour it updates or looks at.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{hea_with, Graph};
///
/// // The 5-cycle needs 3 colours; DSatur finds them and the search cannot do better.
/// let g = Graph::from_edges(5, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])?;
/// let mut c = Counts::default();
/// assert_eq!(hea_with(&g, &mut c).count, 3);
/// assert!(c.edge_visits >= 10);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn hea_with<C: Counter>(g: &Graph, c: &mut C) -> Colouring {
    hea_budget_with(g, Budget::default_for(g), SEARCH_SEED, c)
        .expect("the default budget has a step cap")
        .0
}

/// DSatur, then HEA within `budget`, its random choices drawn from `seed`; see
/// [`hea_budget_with`].
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"budget"`) if
/// `budget` has neither a step cap nor a time limit.
///
/// # Complexity
/// O((n + m) log n + s) time for a budget of s steps; O(n + m) auxiliary space.
///
/// ```
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{check_colouring, dsatur, hea_budget, Budget, Graph};
///
/// // The 8 × 8 queen graph has chromatic number 9.
/// let g = Graph::from_edge_list(&graph(GraphKind::Queen, 8, 0, 0)?)?;
/// let (c, report) = hea_budget(&g, Budget::steps(50_000_000), 3)?;
/// assert_eq!(check_colouring(&g, &c.colour), Ok(()));
/// assert_eq!(c.count, 9);
/// assert!(report.best_step <= report.steps);
/// // The same seed and step budget give the same colouring.
/// assert_eq!(hea_budget(&g, Budget::steps(50_000_000), 3)?.0, c);
/// assert_eq!(hea_budget(&g, Budget::steps(0), 3)?.0, dsatur(&g));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn hea_budget(g: &Graph, budget: Budget, seed: u64) -> Result<(Colouring, SearchReport)> {
    hea_budget_with(g, budget, seed, &mut NoCount)
}

/// DSatur followed by the hybrid evolutionary search (Galinier and Hao, 1999) within
/// `budget`, its random choices drawn from `seed`, counting the work of both.
///
/// From DSatur's k colours the search asks for k − 1, k − 2, … on the t-core (see the
/// module notes): for each target it builds a population of [`POPULATION`] colourings, each
/// improved by the tabu search, then crosses two at random with the greedy partition
/// crossover, improves the offspring by the tabu search and lets it replace the worse parent,
/// until some tabu search ends without conflicts (the next target) or the budget ends. Each
/// tabu search makes at most 10·n iterations for a core of n vertices (at least 2 000),
/// except the first member's, which stops only after that many iterations without finding
/// fewer conflicts. It
/// returns the fewest colours reached, with a [`SearchReport`]. For a given seed and step
/// budget the result is the same on every machine; a time limit only cuts the same search
/// short.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"budget"`) if
/// `budget` has neither a step cap nor a time limit.
///
/// # Complexity
/// O((n + m) log n + s) time for s steps spent: a tabu iteration with c conflicting vertices
/// and k colours costs c·(k − 1) + (the moved vertex's degree) steps, a crossover n + k², a
/// new member n + 2m + n·k. Auxiliary space O(n + m).
///
/// # Counts
/// As [`hea_with`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{hea_budget_with, Budget, Graph};
///
/// let g = Graph::from_edge_list(&graph(GraphKind::Mycielski, 5, 0, 0)?)?;
/// let mut c = Counts::default();
/// let (colouring, report) = hea_budget_with(&g, Budget::steps(100_000), 7, &mut c)?;
/// assert_eq!(colouring.count, 5);
/// assert!(report.steps <= 100_000);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn hea_budget_with<C: Counter>(
    g: &Graph,
    budget: Budget,
    seed: u64,
    c: &mut C,
) -> Result<(Colouring, SearchReport)> {
    budget.check()?;
    let start = dsatur_with(g, c);
    let mut meter = Meter::new(&budget);
    let mut rng = Rng::new(seed);
    let best = descend(g, start, &mut meter, &mut rng, c, evolve);
    Ok((best, meter.report()))
}

/// The tabu iterations that improve one member: 10 per core vertex, at least 2 000.
fn local_iterations(core: &Core) -> u64 {
    (10 * core.len() as u64).max(2_000)
}

/// HEA for a proper colouring of `core` with `core.colours` colours, from the proper
/// colouring `best` of the whole graph with one colour more; `None` if the budget ends first.
fn evolve<C: Counter>(
    core: &Core,
    best: &[u32],
    meter: &mut Meter,
    rng: &mut Rng,
    c: &mut C,
) -> Option<Vec<u32>> {
    let iterations = local_iterations(core);
    let mut search = TabuCol::new(core);
    // Improves a member; `Ok` when the tabu search removed every conflict.
    let mut improve = |colour: &[u32], first: bool, meter: &mut Meter, rng: &mut Rng, c: &mut C| {
        search.load(colour, meter, c);
        let mut kept = Vec::new();
        // The first member searches on while it keeps improving: the plain tabu descent,
        // until it stalls.
        let (limit, patience) = if first {
            (u64::MAX, iterations)
        } else {
            (iterations, u64::MAX)
        };
        let fewest = search.run(limit, patience, Some(&mut kept), meter, rng, c);
        if fewest == 0 {
            Ok(kept)
        } else {
            Err((kept, fewest))
        }
    };
    let mut population: Vec<(Vec<u32>, u64)> = Vec::with_capacity(POPULATION);
    while population.len() < POPULATION {
        let member = if population.is_empty() {
            core.start_from(best, c)
        } else {
            random_greedy(core, meter, rng, c)
        };
        match improve(&member, population.is_empty(), meter, rng, c) {
            Ok(proper) => return Some(proper),
            Err(kept) => population.push(kept),
        }
        if meter.exhausted() {
            return None;
        }
    }
    loop {
        let a = rng.index(POPULATION);
        let b = (a + 1 + rng.index(POPULATION - 1)) % POPULATION;
        let child = gpx(&population[a].0, &population[b].0, core.colours, meter, rng);
        match improve(&child, false, meter, rng, c) {
            Ok(proper) => return Some(proper),
            Err(kept) => {
                let worse = if population[a].1 > population[b].1 {
                    a
                } else {
                    b
                };
                population[worse] = kept;
            }
        }
        if meter.exhausted() {
            return None;
        }
    }
}

/// A colouring of `core` with its `colours` colours, not necessarily proper: the vertices in
/// a random order each take the first colour none of their coloured neighbours has, or if
/// there is none the colour fewest of them have. Costs n + 2m + n·k steps (charged).
fn random_greedy<C: Counter>(core: &Core, meter: &mut Meter, rng: &mut Rng, c: &mut C) -> Vec<u32> {
    const NONE: u32 = u32::MAX;
    let (n, k) = (core.len(), core.colours);
    let mut order: Vec<u32> = (0..n as u32).collect();
    for i in (1..n).rev() {
        order.swap(i, rng.index(i + 1));
    }
    let mut colour = vec![NONE; n];
    let mut seen = vec![0u32; k];
    for &v in &order {
        let v = v as usize;
        for &u in core.neighbours(v) {
            c.edge_visit();
            if let Some(slot) = seen.get_mut(colour[u as usize] as usize) {
                *slot += 1;
            }
        }
        let least = (0..k).min_by_key(|&a| seen[a]).unwrap_or(0);
        colour[v] = least as u32;
        seen.iter_mut().for_each(|s| *s = 0);
    }
    meter.charge(n as u64 + core.edge_ends() + (n * k) as u64);
    colour
}

/// The greedy partition crossover of two colourings with `k` colours: for i in `0..k`, the
/// parent whose turn it is (`a` at even i, `b` at odd i) gives its largest class of vertices
/// not yet taken (the first of equals), whose vertices all take colour i; the vertices left
/// take random colours. O(n + k²), charged as n + k² steps.
fn gpx(a: &[u32], b: &[u32], k: usize, meter: &mut Meter, rng: &mut Rng) -> Vec<u32> {
    const NONE: u32 = u32::MAX;
    let n = a.len();
    let parents = [a, b];
    // The members of each class of each parent, by a counting sort.
    let classes: Vec<(Vec<usize>, Vec<u32>)> = parents
        .iter()
        .map(|p| {
            let mut start = vec![0usize; k + 1];
            for &x in p.iter() {
                start[x as usize + 1] += 1;
            }
            for x in 1..=k {
                start[x] += start[x - 1];
            }
            let mut members = vec![0u32; n];
            let mut next = start.clone();
            for (v, &x) in p.iter().enumerate() {
                members[next[x as usize]] = v as u32;
                next[x as usize] += 1;
            }
            (start, members)
        })
        .collect();
    // How many vertices not yet taken each class of each parent still holds.
    let mut left: Vec<Vec<usize>> = classes
        .iter()
        .map(|(start, _)| (0..k).map(|x| start[x + 1] - start[x]).collect())
        .collect();
    let mut child = vec![NONE; n];
    for i in 0..k {
        let (turn, other) = (i % 2, 1 - i % 2);
        let sizes = &left[turn];
        let largest = (0..k).fold(0, |best, x| if sizes[x] > sizes[best] { x } else { best });
        if left[turn][largest] == 0 {
            break;
        }
        let (start, members) = &classes[turn];
        for &v in &members[start[largest]..start[largest + 1]] {
            let v = v as usize;
            if child[v] == NONE {
                child[v] = i as u32;
                left[other][parents[other][v] as usize] -= 1;
            }
        }
        left[turn][largest] = 0;
    }
    for x in child.iter_mut().filter(|x| **x == NONE) {
        *x = rng.below(k as u64) as u32;
    }
    meter.charge((n + k * k) as u64);
    child
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gpx_takes_the_largest_classes_alternately() {
        // Parent a: classes {0, 1, 2, 3} and {4, 5}; parent b: {0, 4}, {1, 5}, ... with
        // k = 2: colour 0 is a's class {0, 1, 2, 3}; then b's largest class among 4 and 5
        // (each alone in its class now) is the first, {4}; vertex 5 is left.
        let a = [0, 0, 0, 0, 1, 1];
        let b = [0, 1, 1, 1, 0, 1];
        let mut meter = Meter::new(&Budget::steps(100));
        let mut rng = Rng::new(1);
        let child = gpx(&a, &b, 2, &mut meter, &mut rng);
        assert_eq!(&child[..5], &[0, 0, 0, 0, 1]);
        assert!(child[5] < 2);
        assert_eq!(meter.report().steps, 6 + 4);
    }

    #[test]
    fn gpx_of_a_colouring_with_itself_is_that_colouring_up_to_names() {
        let mut rng = Rng::new(9);
        for _ in 0..50 {
            let k = 1 + rng.index(6);
            let n = rng.index(40);
            let a: Vec<u32> = (0..n).map(|_| rng.below(k as u64) as u32).collect();
            let mut meter = Meter::new(&Budget::steps(u64::MAX));
            let child = gpx(&a, &a, k, &mut meter, &mut rng);
            // Same partition: two vertices share a colour in one exactly when in the other.
            for u in 0..n {
                for v in 0..n {
                    assert_eq!(a[u] == a[v], child[u] == child[v]);
                }
            }
        }
    }
}
