//! Tabu search for a colouring with fewer colours (TabuCol), and DSatur followed by it.
//!
//! The greedy colourings of the course ([RD, §2.1] "Algoritmo voraz
//! aplicado a la coloración") stop at the first proper colouring their order gives. Local
//! search goes on from there: to try k − 1 colours, give the vertices of the last colour the
//! colour their neighbours use least, then move one conflicting vertex at a time to another
//! colour, always the move that leaves the fewest conflicting edges. A move's reverse is
//! forbidden ("tabu") for a while so the search does not cycle, unless it would reach fewer
//! conflicts than ever before. When no edge conflicts, k − 1 colours suffice and the search
//! tries k − 2. This is TabuCol (Hertz and de Werra, 1987) with the reactive tabu tenure of
//! Galinier and Hao (1999): a random 0–9 plus 0.6 times the number of conflicting vertices.
//!
//! The search keeps the incremental conflict table γ\[v\]\[a\] (how many neighbours of v
//! have colour a) and the conflicting vertices in an indexed set, so a move's change in
//! conflicts is γ\[v\]\[a\] − γ\[v\]\[colour of v\], read in O(1), and choosing the best move
//! scans only the rows of the conflicting vertices: O(|conflicting|·k) per iteration, plus
//! O(degree) to update the table after the move. Two colours are decided exactly, and only
//! the t-core is searched ([`reduce`](super::reduce)), so the tables take O(m) space.
//!
//! The work is paid from a [`Budget`] of steps (moves evaluated, neighbours updated, one
//! pass over the graph per target) and, optionally, time. The random choices (ties between
//! equal moves, tenures) come from a seed, so a graph, a seed and a step budget always give
//! the same colouring.
//!
//! The tests check every colouring with [`check_colouring`](super::check_colouring), that a
//! zero budget returns DSatur's colouring unchanged, that the same seed and steps give the
//! same colouring, that the search reaches the chromatic number of small graphs (brute
//! force) and of small queen and Mycielski graphs, and that the conflict table matches a
//! recount after random moves.

use super::budget::{Budget, Meter, SearchReport, SEARCH_SEED};
use super::reduce::{descend, renumbered, Core};
use super::{check_colouring, dsatur_with, Colouring};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::{Error, Result};
use crate::gen::Rng;
use crate::graph::Graph;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "colour",
    name: "dsatur-tabu",
    function: "graph::dsatur_tabu",
    file: "src/graph/colouring/tabu.rs",
    summary: "DSatur, then a tabu search for fewer colours",
    time: "O((n + m) log n)",
    space: "O(n + m)",
    operation: Some(Operation::Comparisons),
    counts: "DSatur's heap comparisons plus at most 20(n + 2m) search steps",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::MLogN, Operation::Comparisons)],
};

/// DSatur, then [`tabu_recolour`] with the default budget, [`Budget::default_for`]`(g)`;
/// see [`dsatur_tabu_with`].
///
/// # Complexity
/// O((n + m) log n) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{dsatur, dsatur_tabu, check_colouring, Graph};
///
/// let g = Graph::from_edge_list(&graph(GraphKind::Gnm, 300, 1500, 7)?)?;
/// let (plain, improved) = (dsatur(&g), dsatur_tabu(&g));
/// assert_eq!(check_colouring(&g, &improved.colour), Ok(()));
/// assert!(improved.count < plain.count);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dsatur_tabu(g: &Graph) -> Colouring {
    dsatur_tabu_with(g, &mut NoCount)
}

/// DSatur followed by a tabu search for fewer colours, counting the work of both.
///
/// [`dsatur_with`] gives a proper colouring with k colours; the tabu search then looks for
/// one with k − 1, k − 2, … colours until its budget of
/// [`TABU_EFFORT`](super::TABU_EFFORT)·(n + 2m) steps is spent, with the seed
/// [`SEARCH_SEED`]. The result never has more colours than DSatur's. On random G(n, m)
/// graphs of up to a thousand vertices it had fewer on more than half of those tried; on
/// graphs of 10⁵ vertices and more the budget seldom suffices to remove a colour. For a
/// budget and seed of your own, see [`dsatur_tabu_budget`].
///
/// # Complexity
/// O((n + m) log n) time: DSatur's, plus at most 20·(n + 2m) search steps. Auxiliary space
/// O(n + m): DSatur's, and a count and a tabu mark per colour for each vertex of the core.
///
/// # Counts
/// DSatur's counts, plus one `comparison` per move the search evaluates and one `edge_visit`
/// per neighbour it updates or looks at.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{dsatur_tabu_with, Graph};
///
/// // The 5-cycle needs 3 colours; DSatur finds them and the search cannot do better.
/// let g = Graph::from_edges(5, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])?;
/// let mut c = Counts::default();
/// assert_eq!(dsatur_tabu_with(&g, &mut c).count, 3);
/// assert!(c.edge_visits >= 10);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dsatur_tabu_with<C: Counter>(g: &Graph, c: &mut C) -> Colouring {
    dsatur_tabu_budget_with(g, Budget::default_for(g), SEARCH_SEED, c)
        .expect("the default budget has a step cap")
        .0
}

/// DSatur, then the tabu search within `budget`, its random choices drawn from `seed`; see
/// [`dsatur_tabu_budget_with`].
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"budget"`) if `budget` has neither a step cap nor a
/// time limit.
///
/// # Complexity
/// O((n + m) log n + s) time for a budget of s steps; O(n + m) auxiliary space.
///
/// ```
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{check_colouring, dsatur, dsatur_tabu_budget, Budget, Graph};
///
/// // The 7 × 7 queen graph: DSatur needs more than 7 colours, the search finds 7.
/// let g = Graph::from_edge_list(&graph(GraphKind::Queen, 7, 0, 0)?)?;
/// let (c, report) = dsatur_tabu_budget(&g, Budget::steps(5_000_000), 42)?;
/// assert_eq!(check_colouring(&g, &c.colour), Ok(()));
/// assert!(dsatur(&g).count > 7 && c.count == 7);
/// assert!(0 < report.best_step && report.best_step <= report.steps);
/// // A budget of zero steps returns DSatur's colouring.
/// assert_eq!(dsatur_tabu_budget(&g, Budget::steps(0), 42)?.0, dsatur(&g));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dsatur_tabu_budget(
    g: &Graph,
    budget: Budget,
    seed: u64,
) -> Result<(Colouring, SearchReport)> {
    dsatur_tabu_budget_with(g, budget, seed, &mut NoCount)
}

/// DSatur followed by the tabu search within `budget`, its random choices drawn from `seed`,
/// counting the work of both.
///
/// As [`dsatur_tabu_with`], with the budget and seed given: the search goes on from DSatur's
/// k colours to k − 1, k − 2, … until the steps or the time run out (whichever first), and
/// returns the fewest colours it reached with a [`SearchReport`] of the steps it spent and
/// the step at which it found that colouring. For a given seed and step budget the result is
/// the same on every machine; a time limit only cuts the same search short.
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"budget"`) if `budget` has neither a step cap nor a
/// time limit.
///
/// # Complexity
/// O((n + m) log n + s) time for s steps spent: an iteration with c conflicting vertices
/// and k colours costs c·(k − 1) steps to choose its move and the moved vertex's degree to
/// update the table. Auxiliary space O(n + m).
///
/// # Counts
/// As [`dsatur_tabu_with`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{dsatur_tabu_budget_with, Budget, Graph};
///
/// let g = Graph::from_edge_list(&graph(GraphKind::Mycielski, 5, 0, 0)?)?;
/// let mut c = Counts::default();
/// let (colouring, report) = dsatur_tabu_budget_with(&g, Budget::steps(100_000), 7, &mut c)?;
/// assert_eq!(colouring.count, 5);
/// assert!(report.steps <= 100_000);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dsatur_tabu_budget_with<C: Counter>(
    g: &Graph,
    budget: Budget,
    seed: u64,
    c: &mut C,
) -> Result<(Colouring, SearchReport)> {
    budget.check()?;
    let start = dsatur_with(g, c);
    let mut meter = Meter::new(&budget);
    let best = search(g, start, &mut meter, seed, c);
    Ok((best, meter.report()))
}

/// A colouring of `g` with as few colours as a tabu search finds within `budget` steps,
/// starting from the proper colouring `start`; see [`tabu_recolour_with`].
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"colouring"`) if `start` is not a proper colouring of
/// `g` with colours `0..start.count`, or has more colours than `g` has vertices.
///
/// # Complexity
/// O(n + m + budget) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{greedy_colouring, tabu_recolour, Graph};
///
/// // The 6-cycle in the order 0, 3, 1, 4, 2, 5: greedy needs 3 colours, 2 suffice.
/// let g = Graph::from_edges(6, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0]])?;
/// let greedy = greedy_colouring(&g, &[0, 3, 1, 4, 2, 5])?;
/// assert_eq!(greedy.count, 3);
/// assert_eq!(tabu_recolour(&g, &greedy, 1000)?.count, 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn tabu_recolour(g: &Graph, start: &Colouring, budget: u64) -> Result<Colouring> {
    tabu_recolour_with(g, start, budget, &mut NoCount)
}

/// Tabu search (TabuCol) for a proper colouring of `g` with fewer colours than `start`,
/// counting its work.
///
/// The colours of `start` are first renumbered to `0..count` in order of first use, dropping
/// unused ones. From k colours the search tries k − 1 on the (k − 1)-core (see the module
/// notes): the vertices of the last colour take the colour least used among their
/// neighbours, and then, while some edge joins two vertices of one colour, the search makes
/// the best move of a conflicting vertex to another colour that is not tabu (among equal
/// moves, one drawn uniformly). After moving v away from colour a, putting v back into a
/// stays tabu for a random 0–9 plus ⌊0.6·(conflicting vertices)⌋ iterations, unless that
/// would give fewer conflicts than ever before on this target. Two colours are tried
/// exactly, with a breadth-first 2-colouring. Setting up a target costs n + 2m steps of the
/// budget. The search stops when a target cannot be set up or fails within the budget, and
/// returns the best proper colouring it reached. Its random choices come from
/// [`SEARCH_SEED`].
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"colouring"`) if `start` is not a proper colouring of
/// `g` with colours `0..start.count`, or has more colours than `g` has vertices.
///
/// # Complexity
/// O(n + m + budget) time, O(n + m) auxiliary space: each target spends n + 2m steps of the
/// budget on its set-up, and each iteration with c conflicting vertices c·(k − 1) steps on
/// choosing its move (O(1) per candidate, read from the conflict table) and the moved
/// vertex's degree on updating the table. The tables have one entry per colour for each
/// vertex of the core, whose vertices all have at least that many neighbours.
///
/// # Counts
/// One `comparison` per move evaluated, one `edge_visit` per neighbour updated or looked at.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{colour, tabu_recolour_with, ColouringAlgorithm, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [2, 3]])?;
/// let natural = colour(&g, ColouringAlgorithm::Greedy);
/// let mut c = Counts::default();
/// let better = tabu_recolour_with(&g, &natural, 100, &mut c)?;
/// assert_eq!((natural.count, better.count), (2, 2));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn tabu_recolour_with<C: Counter>(
    g: &Graph,
    start: &Colouring,
    budget: u64,
    c: &mut C,
) -> Result<Colouring> {
    let n = g.vertex_count();
    let largest = start.colour.iter().max().copied();
    if start.count > n || largest.map_or(0, |k| k.saturating_add(1)) != start.count {
        return Err(Error::InvalidParameter {
            name: "colouring",
            reason: format!(
                "{} colours for a graph of {n} vertices, the largest colour being {}; \
                 expected colours 0..count with count at most the number of vertices",
                start.count,
                largest.map_or("none".to_string(), |k| k.to_string()),
            ),
        });
    }
    if check_colouring(g, &start.colour).is_err() {
        return Err(Error::InvalidParameter {
            name: "colouring",
            reason: format!(
                "not a proper colouring of the graph: {} colours for {n} vertices, or an edge \
                 whose ends share a colour",
                start.colour.len()
            ),
        });
    }
    let compact: Vec<u32> = start.colour.iter().map(|&k| k as u32).collect();
    let mut meter = Meter::new(&Budget::steps(budget));
    Ok(search(g, renumbered(&compact), &mut meter, SEARCH_SEED, c))
}

/// Lowers the colour count of the compact proper colouring `best` by tabu search, as far as
/// `meter` allows.
fn search<C: Counter>(
    g: &Graph,
    best: Colouring,
    meter: &mut Meter,
    seed: u64,
    c: &mut C,
) -> Colouring {
    let mut rng = Rng::new(seed);
    descend(
        g,
        best,
        meter,
        &mut rng,
        c,
        |core, colour, meter, rng, c| {
            let mut state = TabuCol::new(core);
            state.load(&core.start_from(colour, c), meter, c);
            let fewest = state.run(u64::MAX, u64::MAX, None, meter, rng, c);
            (fewest == 0).then_some(state.colour)
        },
    )
}

/// The state of the tabu search for a colouring of a core with `core.colours` colours.
pub(super) struct TabuCol<'a> {
    /// The graph searched.
    core: &'a Core,
    /// The number of colours, k.
    k: usize,
    /// The colour of each vertex, in `0..k`.
    colour: Vec<u32>,
    /// `gamma[v * k + a]`: how many neighbours of v have colour a.
    gamma: Vec<u32>,
    /// `tabu_until[v * k + a]`: the first iteration at which v may move back into a.
    tabu_until: Vec<u32>,
    /// The vertices with a neighbour of their own colour, in any order.
    conflicting: Vec<u32>,
    /// The position of each vertex in `conflicting`, or `NOT_CONFLICTING`.
    position: Vec<u32>,
    /// The number of edges whose ends share a colour.
    conflicts: u64,
    /// The current iteration (the clock of `tabu_until`).
    iteration: u32,
}

/// The position of a vertex that is not in the conflicting list.
const NOT_CONFLICTING: u32 = u32::MAX;

impl<'a> TabuCol<'a> {
    /// An empty search state for `core` (every vertex colour 0, no table yet); give it a
    /// colouring with [`TabuCol::load`] before running it.
    pub(super) fn new(core: &'a Core) -> Self {
        let (size, k) = (core.len(), core.colours);
        TabuCol {
            core,
            k,
            colour: vec![0; size],
            gamma: vec![0; size * k],
            tabu_until: vec![0; size * k],
            conflicting: Vec::new(),
            position: vec![NOT_CONFLICTING; size],
            conflicts: 0,
            iteration: 0,
        }
    }

    /// Starts over from `colour` (one colour in `0..k` per core vertex), with no move tabu:
    /// rebuilds the conflict table, at a cost of n·k + 2m steps (charged, not refused).
    pub(super) fn load<C: Counter>(&mut self, colour: &[u32], meter: &mut Meter, c: &mut C) {
        let k = self.k;
        debug_assert!(
            colour.len() == self.colour.len() && colour.iter().all(|&a| (a as usize) < k)
        );
        self.colour.copy_from_slice(colour);
        self.gamma.iter_mut().for_each(|x| *x = 0);
        for v in 0..self.colour.len() {
            let a = self.colour[v] as usize;
            for &u in self.core.neighbours(v) {
                c.edge_visit();
                self.gamma[u as usize * k + a] += 1;
            }
        }
        self.conflicting.clear();
        self.position.iter_mut().for_each(|p| *p = NOT_CONFLICTING);
        self.conflicts = 0;
        for v in 0..self.colour.len() {
            self.conflicts += u64::from(self.own_count(v));
            if self.own_count(v) > 0 {
                self.insert(v);
            }
        }
        self.conflicts /= 2;
        // Every tenure is below 10 + n: skipping that many iterations frees every move.
        let skip = 10 + self.colour.len() as u32;
        if self.iteration >= u32::MAX / 2 - skip {
            self.tabu_until.iter_mut().for_each(|t| *t = 0);
            self.iteration = 0;
        }
        self.iteration += skip;
        meter.charge((self.colour.len() * k) as u64 + self.core.edge_ends());
    }

    /// Makes at most `iterations` moves, stopping early when no edge conflicts, when
    /// `patience` iterations in a row have not lowered the fewest conflicts seen, or when the
    /// meter refuses the next iteration's evaluations. Returns the fewest conflicts seen
    /// (from the start of the run); if `best` is given it receives the colouring that had
    /// them.
    pub(super) fn run<C: Counter>(
        &mut self,
        iterations: u64,
        patience: u64,
        mut best: Option<&mut Vec<u32>>,
        meter: &mut Meter,
        rng: &mut Rng,
        c: &mut C,
    ) -> u64 {
        let k = self.k;
        let mut fewest = self.conflicts;
        if let Some(best) = best.as_deref_mut() {
            best.clone_from(&self.colour);
        }
        let (mut done, mut improved_at) = (0, 0);
        while self.conflicts > 0 && done < iterations && done - improved_at < patience {
            let evaluations = (self.conflicting.len() * (k - 1)) as u64;
            if !meter.spend(evaluations) {
                break;
            }
            for _ in 0..evaluations {
                c.comparison();
            }
            done += 1;
            self.iteration += 1;
            if self.iteration == u32::MAX / 2 {
                self.tabu_until.iter_mut().for_each(|t| *t = 0);
                self.iteration = 1;
            }
            let aspire_below = fewest as i64 - self.conflicts as i64;
            let Some((v, a)) = self.best_move(aspire_below, rng) else {
                continue;
            };
            let from = self.colour[v] as usize;
            let tenure = rng.below(10) as u32 + (self.conflicting.len() * 3 / 5) as u32;
            self.tabu_until[v * k + from] = self.iteration + tenure + 1;
            self.apply(v, a, c);
            meter.charge(self.core.neighbours(v).len() as u64);
            if self.conflicts < fewest {
                fewest = self.conflicts;
                improved_at = done;
                if let Some(best) = best.as_deref_mut() {
                    best.copy_from_slice(&self.colour);
                    meter.charge(self.colour.len() as u64);
                }
            }
        }
        fewest
    }

    /// The best move (v, a) of a conflicting vertex v to another colour a that is not tabu,
    /// or that changes the conflict count by less than `aspire_below`; of equal moves, one
    /// drawn uniformly (reservoir sampling). `None` if every move is tabu.
    fn best_move(&self, aspire_below: i64, rng: &mut Rng) -> Option<(usize, usize)> {
        let k = self.k;
        let mut best = None;
        let mut best_change = i64::MAX;
        let mut ties = 0u64;
        for &v in &self.conflicting {
            let v = v as usize;
            let here = self.colour[v] as usize;
            let row = &self.gamma[v * k..(v + 1) * k];
            let tabu = &self.tabu_until[v * k..(v + 1) * k];
            let stay = i64::from(row[here]);
            for (a, (&count, &until)) in row.iter().zip(tabu).enumerate() {
                let change = i64::from(count) - stay;
                if change > best_change
                    || a == here
                    || (until > self.iteration && change >= aspire_below)
                {
                    continue;
                }
                if change < best_change {
                    best_change = change;
                    ties = 1;
                    best = Some((v, a));
                } else {
                    ties += 1;
                    if rng.below(ties) == 0 {
                        best = Some((v, a));
                    }
                }
            }
        }
        best
    }

    /// Moves `v` to colour `a`, updating the table, the conflict count and the conflicting
    /// set (one `edge_visit` per neighbour). Moving `v` to its own colour changes nothing.
    fn apply<C: Counter>(&mut self, v: usize, a: usize, c: &mut C) {
        let k = self.k;
        let from = self.colour[v] as usize;
        if a == from {
            return;
        }
        let row = &self.gamma[v * k..(v + 1) * k];
        self.conflicts = (self.conflicts + u64::from(row[a])) - u64::from(row[from]);
        self.colour[v] = a as u32;
        for &u in self.core.neighbours(v) {
            c.edge_visit();
            let u = u as usize;
            self.gamma[u * k + from] -= 1;
            self.gamma[u * k + a] += 1;
            let own = self.colour[u] as usize;
            if own == from && self.gamma[u * k + from] == 0 {
                self.remove(u);
            } else if own == a && self.gamma[u * k + a] == 1 {
                self.insert(u);
            }
        }
        match (self.own_count(v) > 0, self.position[v] != NOT_CONFLICTING) {
            (true, false) => self.insert(v),
            (false, true) => self.remove(v),
            _ => {}
        }
    }

    /// How many neighbours of `v` share its colour.
    fn own_count(&self, v: usize) -> u32 {
        self.gamma[v * self.k + self.colour[v] as usize]
    }

    /// Adds `v` to the conflicting set.
    fn insert(&mut self, v: usize) {
        self.position[v] = self.conflicting.len() as u32;
        self.conflicting.push(v as u32);
    }

    /// Takes `v` out of the conflicting set.
    fn remove(&mut self, v: usize) {
        let at = self.position[v] as usize;
        let last = *self.conflicting.last().expect("v is listed") as usize;
        self.conflicting.swap_remove(at);
        self.position[last] = at as u32;
        self.position[v] = NOT_CONFLICTING;
    }

    /// Whether the table, the conflict count and the conflicting set match a recount from
    /// the colours: the tests' check after any sequence of moves.
    #[cfg(test)]
    fn consistent(&self) -> bool {
        let k = self.k;
        let n = self.colour.len();
        let mut gamma = vec![0u32; n * k];
        for v in 0..n {
            for &u in self.core.neighbours(v) {
                gamma[u as usize * k + self.colour[v] as usize] += 1;
            }
        }
        let conflicts: u64 = (0..n).map(|v| u64::from(self.own_count(v))).sum::<u64>() / 2;
        let listed = (0..n).all(|v| {
            let p = self.position[v];
            (self.own_count(v) > 0) == (p != NOT_CONFLICTING)
                && (p == NOT_CONFLICTING || self.conflicting[p as usize] as usize == v)
        });
        gamma == self.gamma
            && conflicts == self.conflicts
            && listed
            && self.conflicting.len() == (0..n).filter(|&v| self.own_count(v) > 0).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::{graph, GraphKind};

    #[test]
    fn the_start_state_counts_conflicts_of_the_reassigned_class() {
        // A triangle coloured 0, 1, 2 squeezed into 2 colours: exactly one conflicting edge.
        let g = Graph::from_edges(3, &[[0, 1], [1, 2], [2, 0]]).unwrap();
        let core = Core::new(&g, 2, &mut NoCount);
        let mut state = TabuCol::new(&core);
        let mut meter = Meter::new(&Budget::steps(100));
        state.load(
            &core.start_from(&[0, 1, 2], &mut NoCount),
            &mut meter,
            &mut NoCount,
        );
        assert_eq!(state.conflicts, 1);
        assert_eq!(state.conflicting.len(), 2);
        assert!(state.consistent());
    }

    /// The conflict table, the count and the set stay equal to a recount after random moves
    /// (any vertex, any colour) and after runs of the search, on random graphs and colourings.
    #[test]
    fn the_conflict_table_matches_a_recount_after_random_moves() {
        let mut rng = Rng::new(5);
        for seed in 0..40u64 {
            let n = 8 + seed as usize % 30;
            let m = (n * (n - 1) / 2) * (1 + seed as usize % 3) / 4;
            let g = Graph::from_edge_list(&graph(GraphKind::Gnm, n, m, seed).unwrap()).unwrap();
            let k = 2 + seed as usize % 4;
            let core = Core::new(&g, k, &mut NoCount);
            if core.len() == 0 {
                continue;
            }
            let mut state = TabuCol::new(&core);
            let mut meter = Meter::new(&Budget::steps(u64::MAX));
            let start: Vec<u32> = (0..core.len())
                .map(|_| rng.below(k as u64) as u32)
                .collect();
            state.load(&start, &mut meter, &mut NoCount);
            assert!(state.consistent(), "seed {seed} after loading");
            for step in 0..200 {
                let v = rng.index(core.len());
                let a = rng.index(k);
                state.apply(v, a, &mut NoCount);
                assert!(state.consistent(), "seed {seed} after move {step}");
            }
            let mut best = Vec::new();
            let fewest = state.run(
                300,
                u64::MAX,
                Some(&mut best),
                &mut meter,
                &mut rng,
                &mut NoCount,
            );
            assert!(state.consistent(), "seed {seed} after the search");
            let recount = g
                .edges()
                .filter(|&[u, v]| {
                    let (lu, lv) = (
                        core.vertex.binary_search(&(u as u32)),
                        core.vertex.binary_search(&(v as u32)),
                    );
                    matches!((lu, lv), (Ok(x), Ok(y)) if best[x] == best[y])
                })
                .count() as u64;
            assert_eq!(
                fewest, recount,
                "seed {seed}: the best colouring's conflicts"
            );
        }
    }
}
