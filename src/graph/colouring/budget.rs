//! The effort budget of the search-based colourings ([`dsatur_tabu_budget`] and
//! [`hea_budget`]), and the report of what a search spent.
//!
//! A search's work is measured in *steps*: one step is one move evaluated (a vertex and a
//! colour it might take), one neighbour updated after a move, one vertex or edge end of a
//! pass over the graph. A [`Budget`] caps the steps, the wall-clock time, or both, whichever
//! ends first. The steps decide the path of the search: for a given seed and step budget it
//! makes the same moves on every machine. The clock only cuts that path short: it is read
//! every [`CLOCK_STRIDE`] steps, between moves, and never feeds a choice.
//!
//! [`dsatur_tabu_budget`]: super::dsatur_tabu_budget
//! [`hea_budget`]: super::hea_budget

use crate::error::{Error, Result};
use crate::graph::Graph;
use std::time::{Duration, Instant};

/// The default step budget of the searches, in steps per vertex and per edge end: the plain
/// [`dsatur_tabu`](super::dsatur_tabu) and [`hea`](super::hea) run for 20·(n + 2m) steps on a
/// graph of n vertices and m edges ([`Budget::default_for`]).
///
/// With this budget DSatur and the tabu search together stay faster than petgraph's
/// `dsatur_coloring` at every size `benches/graph.rs` measures (G(n, 10n), n from 2^10 to
/// 2^18, 2 cores). A larger budget finds fewer colours on more graphs.
pub const TABU_EFFORT: u64 = 20;

/// The seed of the plain searches' random choices ([`dsatur_tabu`](super::dsatur_tabu),
/// [`hea`](super::hea), and [`colour`](super::colour) with a search strategy).
pub const SEARCH_SEED: u64 = 0x07AB_0C01;

/// How many steps pass between two readings of the clock: a few microseconds of search.
pub const CLOCK_STRIDE: u64 = 1 << 14;

/// How much a colouring search may spend: at most `steps` steps, at most `time` of wall
/// clock, whichever ends first. At least one of the two must be given.
///
/// ```
/// use compgeo::graph::{Budget, Graph};
/// use std::time::Duration;
///
/// let g = Graph::from_edges(3, &[[0, 1], [1, 2]])?;
/// assert_eq!(Budget::default_for(&g).steps, Some(20 * (3 + 4)));
/// let both = Budget { steps: Some(10_000), time: Some(Duration::from_secs(2)) };
/// assert_eq!(both, Budget::steps(10_000).and_time(Duration::from_secs(2)));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Budget {
    /// The most steps the search may take, or `None` for no cap on steps.
    pub steps: Option<u64>,
    /// The most wall-clock time the search may take, or `None` for no cap on time.
    pub time: Option<Duration>,
}

impl Budget {
    /// A budget of `steps` steps and no time limit: the search is then the same on every
    /// machine.
    pub fn steps(steps: u64) -> Self {
        Budget {
            steps: Some(steps),
            time: None,
        }
    }

    /// A budget of `time` of wall clock and no cap on steps.
    pub fn time(time: Duration) -> Self {
        Budget {
            steps: None,
            time: Some(time),
        }
    }

    /// This budget with the time limit `time` as well.
    pub fn and_time(self, time: Duration) -> Self {
        Budget {
            time: Some(time),
            ..self
        }
    }

    /// The budget of the plain searches: [`TABU_EFFORT`]·(n + 2m) steps, no time limit.
    pub fn default_for(g: &Graph) -> Self {
        Budget::steps(TABU_EFFORT.saturating_mul(pass(g)))
    }

    /// Checks that the budget ends: a step cap, a time limit or both.
    pub(super) fn check(&self) -> Result<()> {
        if self.steps.is_none() && self.time.is_none() {
            return Err(Error::InvalidParameter {
                name: "budget",
                reason: "neither a step budget nor a time limit: the search would not end"
                    .to_string(),
            });
        }
        Ok(())
    }
}

/// What a colouring search spent, beside the [`Colouring`](super::Colouring) it returns.
///
/// ```
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{dsatur_tabu_budget, Budget, Graph};
///
/// let g = Graph::from_edge_list(&graph(GraphKind::Queen, 6, 0, 0)?)?;
/// let (c, report) = dsatur_tabu_budget(&g, Budget::steps(200_000), 1)?;
/// assert!(report.best_step <= report.steps && report.steps <= 200_000);
/// assert!(!report.timed_out);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SearchReport {
    /// The steps the search spent (at most the step budget).
    pub steps: u64,
    /// The step count at which the returned colouring was found: 0 if it is the start.
    pub best_step: u64,
    /// Whether the time limit ended the search (rather than the steps or success).
    pub timed_out: bool,
}

/// The steps of one pass over `g`: n + 2m.
pub(super) fn pass(g: &Graph) -> u64 {
    (g.vertex_count() as u64).saturating_add(2 * g.edge_count() as u64)
}

/// The running account of a search against its [`Budget`].
#[derive(Debug)]
pub(super) struct Meter {
    /// Steps spent so far.
    spent: u64,
    /// The step cap (`u64::MAX` without one).
    limit: u64,
    /// When the time runs out, if it can.
    deadline: Option<Instant>,
    /// The step count at which the clock is next read.
    next_reading: u64,
    /// Whether the time limit has passed.
    timed_out: bool,
    /// The step count at which the best colouring so far was found.
    best_step: u64,
}

impl Meter {
    /// A fresh account; `budget` has been [checked](Budget::check).
    pub(super) fn new(budget: &Budget) -> Self {
        let start = Instant::now();
        Meter {
            spent: 0,
            limit: budget.steps.unwrap_or(u64::MAX),
            // A limit too far ahead for the clock's type is no limit.
            deadline: budget.time.and_then(|t| start.checked_add(t)),
            next_reading: 0,
            timed_out: false,
            best_step: 0,
        }
    }

    /// Spends `steps` if the budget still holds them and the time has not run out; `false`
    /// (spending nothing) otherwise.
    pub(super) fn spend(&mut self, steps: u64) -> bool {
        if self.timed_out || self.limit - self.spent < steps {
            return false;
        }
        if self.spent >= self.next_reading {
            if let Some(deadline) = self.deadline {
                if Instant::now() >= deadline {
                    self.timed_out = true;
                    return false;
                }
            }
            self.next_reading = self.spent.saturating_add(CLOCK_STRIDE);
        }
        self.spent += steps;
        true
    }

    /// An account for a phase that may spend at most half of what is left of this one: half
    /// the steps not yet spent and half the time left to the deadline. The phase's steps
    /// are charged back to this account with [`Meter::charge`].
    pub(super) fn half(&self) -> Meter {
        let now = Instant::now();
        Meter {
            spent: 0,
            limit: (self.limit - self.spent) / 2,
            deadline: self
                .deadline
                .map(|d| now + d.saturating_duration_since(now) / 2),
            next_reading: 0,
            timed_out: self.timed_out,
            best_step: 0,
        }
    }

    /// Spends `steps` already taken (the updates after a move), up to the step cap.
    pub(super) fn charge(&mut self, steps: u64) {
        self.spent = self.spent.saturating_add(steps).min(self.limit);
    }

    /// Whether the budget is spent or the time is up, as far as the last reading knows.
    pub(super) fn exhausted(&self) -> bool {
        self.timed_out || self.spent >= self.limit
    }

    /// Records that the best colouring so far was found now.
    pub(super) fn found_best(&mut self) {
        self.best_step = self.spent;
    }

    /// The report of the search so far.
    pub(super) fn report(&self) -> SearchReport {
        SearchReport {
            steps: self.spent,
            best_step: self.best_step,
            timed_out: self.timed_out,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_meter_refuses_what_the_budget_cannot_pay() {
        let mut m = Meter::new(&Budget::steps(10));
        assert!(m.spend(6));
        assert!(!m.spend(5));
        assert!(m.spend(4));
        assert!(m.exhausted());
        m.charge(3);
        assert_eq!(m.report().steps, 10);
        assert!(!m.report().timed_out);
    }

    #[test]
    fn a_passed_deadline_stops_the_meter_before_it_spends() {
        let mut m = Meter::new(&Budget::time(Duration::ZERO));
        assert!(!m.spend(1));
        assert!(m.exhausted());
        assert_eq!(
            m.report(),
            SearchReport {
                steps: 0,
                best_step: 0,
                timed_out: true
            }
        );
        // A deadline beyond what the clock can hold is no deadline.
        let mut m = Meter::new(&Budget::time(Duration::MAX));
        assert!(m.spend(u64::MAX));
    }

    #[test]
    fn a_budget_without_limits_is_rejected() {
        let none = Budget {
            steps: None,
            time: None,
        };
        assert!(matches!(
            none.check(),
            Err(Error::InvalidParameter { name: "budget", .. })
        ));
    }
}
