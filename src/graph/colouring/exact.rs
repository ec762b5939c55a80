//! An exact search for a colouring with t colours: backtracking with propagation over the
//! neighbours and over cliques of t vertices.
//!
//! Local search struggles when the target equals the size of the largest cliques and the
//! graph has many of them: every colour class must then meet every such clique exactly once,
//! a rigid structure (the optimal colourings of the n × n queen graphs with n colours, for
//! example, split the board into n sets of n non-attacking queens). A backtracking search
//! that reasons over those cliques finds such colourings quickly. Each vertex keeps the set
//! of colours still open to it (a bit set; the search takes t ≤ 64). Colouring a vertex
//! removes its colour from its neighbours' sets; a vertex left with one colour takes it
//! (forced); a vertex left with none is a dead end. Over each clique of exactly t vertices,
//! a colour open to one vertex only must go there, and a colour open to none is a dead end
//! (the same reasoning as a Sudoku's "only place" rule). The search branches on the vertex
//! with the fewest open colours (ties: the most neighbours), trying its colours in turn, and
//! undoes its changes from a trail when a branch fails. The colours of the first clique are
//! fixed to 0..t at the root, which loses no colouring up to renaming.
//!
//! The search is complete: given enough steps it finds a colouring with t colours or shows
//! that none exists. Its steps are the neighbours updated, the clique members looked at and
//! the vertices scanned to choose a branch; it stops when the budget or its own step limit
//! ends first.
//!
//! The tests check that every colouring returned is proper, that "none exists" agrees with
//! brute force on small graphs, and that the search colours queen graphs with as many
//! colours as a row has squares.

use super::budget::Meter;
use super::reduce::Core;
use crate::count::Counter;

/// What the exact search concluded.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Outcome {
    /// A proper colouring of the core with t colours, by local id.
    Found(Vec<u32>),
    /// No colouring with t colours exists.
    Impossible,
    /// The steps ran out first.
    Unfinished,
}

/// The largest number of colours the exact search takes (one bit each in a word).
pub(super) const MAX_COLOURS: usize = 64;

/// Searches for a proper colouring of `core` with `core.colours` colours, propagating over
/// `cliques` (each of exactly that many vertices), for at most `limit` steps of `meter`.
pub(super) fn exact_colouring<C: Counter>(
    core: &Core,
    cliques: &[Vec<u32>],
    limit: u64,
    meter: &mut Meter,
    c: &mut C,
) -> Outcome {
    let t = core.colours;
    if t == 0 || t > MAX_COLOURS {
        return Outcome::Unfinished;
    }
    let mut search = Search::new(core, cliques);
    search.run(limit, meter, c)
}

/// A bit set of colours.
type Colours = u64;

/// A branch of the search: the trail length before it, its choices (a vertex and the one
/// colour it takes), and the next choice to try.
type Frame = (usize, Vec<(u32, Colours)>, usize);

/// The state of the backtracking search.
struct Search<'a> {
    core: &'a Core,
    cliques: &'a [Vec<u32>],
    /// All t colours.
    full: Colours,
    /// The colours still open to each vertex.
    open: Vec<Colours>,
    /// Whether each vertex has been coloured (its one open colour removed from its
    /// neighbours).
    done: Vec<bool>,
    /// The changes made, to undo them: a vertex with the open set it had, or with the high
    /// bit set, a vertex whose `done` was set.
    trail: Vec<(u32, Colours)>,
    /// Vertices with one open colour, not yet done.
    queue: Vec<u32>,
    /// Steps spent since the last payment to the meter.
    unpaid: u64,
}

/// The high bit of a trail entry's vertex: the entry undoes `done`.
const DONE_FLAG: u32 = 1 << 31;

impl<'a> Search<'a> {
    fn new(core: &'a Core, cliques: &'a [Vec<u32>]) -> Self {
        let t = core.colours;
        let full = if t == 64 { u64::MAX } else { (1u64 << t) - 1 };
        Search {
            core,
            cliques,
            full,
            open: vec![full; core.len()],
            done: vec![false; core.len()],
            trail: Vec::new(),
            queue: Vec::new(),
            unpaid: 0,
        }
    }

    /// Restricts the open colours of `v` to `to` (a subset), recording the change.
    fn set(&mut self, v: usize, to: Colours) {
        if self.open[v] != to {
            self.trail.push((v as u32, self.open[v]));
            self.open[v] = to;
            if to.count_ones() == 1 && !self.done[v] {
                self.queue.push(v as u32);
            }
        }
    }

    /// Undoes the changes back to trail length `mark`.
    fn undo(&mut self, mark: usize) {
        while self.trail.len() > mark {
            let (v, old) = self.trail.pop().expect("longer than the mark");
            if v & DONE_FLAG != 0 {
                self.done[(v & !DONE_FLAG) as usize] = false;
            } else {
                self.open[v as usize] = old;
            }
        }
        self.queue.clear();
    }

    /// Propagates the queued forced colours and the cliques' only places; `false` at a
    /// dead end.
    fn propagate<C: Counter>(&mut self, c: &mut C) -> bool {
        loop {
            while let Some(v) = self.queue.pop() {
                let v = v as usize;
                if self.done[v] {
                    continue;
                }
                let colour = self.open[v];
                if colour.count_ones() != 1 {
                    return false;
                }
                self.done[v] = true;
                self.trail.push((v as u32 | DONE_FLAG, 0));
                let core = self.core;
                let neighbours = core.neighbours(v);
                self.unpaid += neighbours.len() as u64;
                for &u in neighbours {
                    c.edge_visit();
                    let u = u as usize;
                    let open = self.open[u];
                    if open & colour != 0 {
                        if open == colour {
                            return false;
                        }
                        self.set(u, open & !colour);
                    }
                }
            }
            let mut placed = false;
            for q in 0..self.cliques.len() {
                let clique = &self.cliques[q];
                self.unpaid += clique.len() as u64;
                let (mut once, mut twice) = (0, 0);
                for &v in clique {
                    let open = self.open[v as usize];
                    twice |= once & open;
                    once |= open;
                }
                if once != self.full {
                    return false;
                }
                let mut only = once & !twice;
                while only != 0 {
                    let bit = only & only.wrapping_neg();
                    only &= only - 1;
                    // The member it was open to may have been given another colour
                    // that had no other place either: a dead end.
                    let Some(v) = clique
                        .iter()
                        .map(|&v| v as usize)
                        .find(|&v| self.open[v] & bit != 0)
                    else {
                        return false;
                    };
                    if self.open[v] != bit {
                        self.set(v, bit);
                        placed = true;
                    }
                }
            }
            if !placed && self.queue.is_empty() {
                return true;
            }
        }
    }

    /// The choices to branch on, `None` when every vertex is done: the undone vertex with
    /// the fewest open colours (then the most neighbours, then the first) and its colours,
    /// or, if fewer, the places left in a clique for a colour not yet placed there (the
    /// fewest, then the first clique and colour): either way one of the choices must hold.
    fn choose(&mut self) -> Option<Vec<(u32, Colours)>> {
        let mut best: Option<(u32, usize, usize)> = None;
        self.unpaid += self.open.len() as u64;
        for v in 0..self.open.len() {
            if self.done[v] {
                continue;
            }
            let (count, degree) = (self.open[v].count_ones(), self.core.neighbours(v).len());
            let better = match best {
                None => true,
                Some((c, d, _)) => count < c || (count == c && degree > d),
            };
            if better {
                best = Some((count, degree, v));
            }
        }
        let (fewest, _, v) = best?;
        // The clique and colour with the fewest places left, if fewer than `fewest`.
        let mut place: Option<(u32, usize, Colours)> = None;
        let mut places = [0u32; MAX_COLOURS];
        for (q, clique) in self.cliques.iter().enumerate() {
            self.unpaid += clique.len() as u64;
            places[..self.core.colours].iter_mut().for_each(|p| *p = 0);
            for &u in clique {
                let u = u as usize;
                if self.done[u] {
                    continue;
                }
                let mut open = self.open[u];
                while open != 0 {
                    places[open.trailing_zeros() as usize] += 1;
                    open &= open - 1;
                }
            }
            for (a, &count) in places[..self.core.colours].iter().enumerate() {
                let limit = place.map_or(fewest, |(c, _, _)| c);
                if count >= 2 && count < limit {
                    place = Some((count, q, 1 << a));
                }
            }
        }
        Some(match place {
            Some((_, q, bit)) => self.cliques[q]
                .iter()
                .filter(|&&u| !self.done[u as usize] && self.open[u as usize] & bit != 0)
                .map(|&u| (u, bit))
                .collect(),
            None => {
                let mut open = self.open[v];
                let mut choices = Vec::new();
                while open != 0 {
                    let bit = open & open.wrapping_neg();
                    choices.push((v as u32, bit));
                    open &= !bit;
                }
                choices
            }
        })
    }

    fn run<C: Counter>(&mut self, limit: u64, meter: &mut Meter, c: &mut C) -> Outcome {
        let mut spent = 0u64;
        // Fix the first clique's colours: any colouring can be renamed to agree.
        if let Some(first) = self.cliques.first() {
            for (i, &v) in first.iter().enumerate() {
                self.set(v as usize, 1 << i);
            }
        }
        if !self.propagate(c) {
            return Outcome::Impossible;
        }
        // Each frame: the trail length before the branch, the vertex, the colours left to try.
        // Each frame: the trail length before the branch, its choices, the next to try.
        let mut stack: Vec<Frame> = Vec::new();
        let mut next = self.choose();
        loop {
            if self.unpaid > 0 {
                if spent.saturating_add(self.unpaid) > limit || !meter.spend(self.unpaid) {
                    return Outcome::Unfinished;
                }
                spent += self.unpaid;
                self.unpaid = 0;
            }
            match next {
                Some(choices) => stack.push((self.trail.len(), choices, 0)),
                None => {
                    let colour = self
                        .open
                        .iter()
                        .map(|&open| open.trailing_zeros())
                        .collect();
                    return Outcome::Found(colour);
                }
            }
            // Try the next choice of the top frame, popping exhausted frames.
            loop {
                let Some((mark, choices, at)) = stack.last_mut() else {
                    return Outcome::Impossible;
                };
                let mark = *mark;
                let Some(&(v, bit)) = choices.get(*at) else {
                    stack.pop();
                    continue;
                };
                *at += 1;
                self.undo(mark);
                self.set(v as usize, bit);
                if self.propagate(c) {
                    break;
                }
            }
            next = self.choose();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::NoCount;
    use crate::gen::{graph, GraphKind};
    use crate::graph::colouring::budget::Budget;
    use crate::graph::colouring::clique::cliques_of_size;
    use crate::graph::{check_colouring, Graph};

    fn generated(kind: GraphKind, n: usize, m: usize, seed: u64) -> Graph {
        Graph::from_edge_list(&graph(kind, n, m, seed).unwrap()).unwrap()
    }

    /// Whether `g` has a proper colouring with `k` colours, by plain backtracking.
    fn colourable(g: &Graph, k: usize) -> bool {
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
        extend(g, &mut Vec::new(), k)
    }

    /// The exact search on the t-core of `g`, with or without the cliques of size t.
    fn solve(g: &Graph, t: usize, with_cliques: bool) -> (Core, Outcome) {
        let core = Core::new(g, t, &mut NoCount);
        let cliques = if with_cliques {
            cliques_of_size(&core, t, &mut NoCount).0
        } else {
            Vec::new()
        };
        let mut meter = Meter::new(&Budget::steps(u64::MAX));
        let outcome = exact_colouring(&core, &cliques, u64::MAX, &mut meter, &mut NoCount);
        (core, outcome)
    }

    /// On random graphs, the search finds a colouring with t colours exactly when brute force
    /// says one exists, with and without the cliques; what it finds is proper.
    #[test]
    fn the_search_agrees_with_brute_force() {
        for seed in 0..80u64 {
            let n = 4 + seed as usize % 9;
            let m = (n * (n - 1) / 2) * (1 + seed as usize % 4) / 5;
            let g = generated(GraphKind::Gnm, n, m, seed);
            for t in 3..=5 {
                for with_cliques in [false, true] {
                    let (core, outcome) = solve(&g, t, with_cliques);
                    let expected = colourable(&g, t);
                    match outcome {
                        Outcome::Found(colour) => {
                            assert!(expected, "seed {seed}, t {t}: found a colouring");
                            assert!(colour.iter().all(|&a| (a as usize) < t));
                            for v in 0..core.len() {
                                for &u in core.neighbours(v) {
                                    assert_ne!(colour[v], colour[u as usize], "seed {seed}");
                                }
                            }
                        }
                        Outcome::Impossible => assert!(!expected, "seed {seed}, t {t}"),
                        Outcome::Unfinished => panic!("seed {seed}: an unlimited search ends"),
                    }
                }
            }
        }
    }

    /// The n × n queen graph with n colours: found for n = 5 and 7, shown impossible for
    /// n = 4 and 6.
    #[test]
    fn queen_boards_with_as_many_colours_as_a_row() {
        for (side, possible) in [(4, false), (5, true), (6, false), (7, true)] {
            let g = generated(GraphKind::Queen, side, 0, 0);
            let (core, outcome) = solve(&g, side, true);
            assert_eq!(core.len(), side * side);
            match outcome {
                Outcome::Found(colour) => {
                    assert!(possible, "{side}");
                    let colour: Vec<usize> = colour.iter().map(|&a| a as usize).collect();
                    assert_eq!(check_colouring(&g, &colour), Ok(()));
                }
                other => assert!(!possible && other == Outcome::Impossible, "{side}"),
            }
        }
    }

    #[test]
    fn a_step_limit_stops_the_search_unfinished() {
        let g = generated(GraphKind::Queen, 8, 0, 0);
        let core = Core::new(&g, 8, &mut NoCount);
        let cliques = cliques_of_size(&core, 8, &mut NoCount).0;
        let mut meter = Meter::new(&Budget::steps(u64::MAX));
        let outcome = exact_colouring(&core, &cliques, 1000, &mut meter, &mut NoCount);
        assert_eq!(outcome, Outcome::Unfinished);
        assert!(meter.report().steps <= 1000);
    }
}
