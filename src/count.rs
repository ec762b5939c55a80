//! Operation counting: the course measures complexity by counting operations.
//!
//! Every algorithm in compgeo is written once, generic over a [`Counter`]. Running it with
//! [`Counts`] records how many comparisons, swaps, orientation tests, ... it made; running it
//! with [`NoCount`] (what the plain functions do) compiles the counting away, so the default
//! path pays nothing for it (the `count` benchmark measures this).
//!
//! Counting happens at the boundary: the predicates of [`crate::geometry`] (through
//! [`crate::geometry::CountedPredicates`]) and the comparators of the sorting module increment
//! the counter, so algorithm bodies hold no counting code of their own.
//!
//! ```
//! use compgeo::count::{Counter, Counts, Operation};
//!
//! let mut c = Counts::default();
//! c.comparison();
//! c.comparison();
//! c.swap();
//! assert_eq!(c.comparisons, 2);
//! assert_eq!(c.get(Operation::Swaps), 1);
//! ```

use std::ops::{Add, AddAssign};

/// Something that records the elementary operations an algorithm performs.
///
/// Each method records one operation of its kind. Implementors: [`Counts`] (records) and
/// [`NoCount`] (does nothing, inlined away).
pub trait Counter {
    /// Whether this counter throws away what it is told, as [`NoCount`] does. An algorithm
    /// may then take a faster path whose operations are not the ones its docs count (the
    /// lexicographic sorts of the hull and Delaunay code become radix sorts, which make no
    /// comparisons); the result is the same on either path. `false` unless a counter says
    /// otherwise, so a counter that records sees the documented operations.
    ///
    /// ```
    /// use compgeo::count::{Counter, Counts, NoCount};
    ///
    /// assert!(NoCount::DISCARDS && !Counts::DISCARDS);
    /// ```
    const DISCARDS: bool = false;

    /// One comparison of two keys (sorting, searching, priority queues).
    fn comparison(&mut self);
    /// One exchange of two elements.
    fn swap(&mut self);
    /// One move (assignment) of an element, as in insertion sort's shifts.
    fn element_move(&mut self);
    /// One orientation (signed area) test.
    fn orientation_test(&mut self);
    /// One in-circle test.
    fn incircle_test(&mut self);
    /// One distance evaluation or comparison of distances.
    fn distance_evaluation(&mut self);
    /// One adjacency test ("are u and v adjacent?"), as the course's greedy colouring counts.
    fn adjacency_test(&mut self);
    /// One visit of an edge (a traversal looks at an adjacency entry).
    fn edge_visit(&mut self);
    /// One visit of a vertex (a traversal takes a vertex from its queue or stack).
    fn vertex_visit(&mut self);
    /// One arithmetic step on points: an affine combination of two points (a de Casteljau
    /// step) or a multiply-add of a point (a Horner step). Scalar bookkeeping is not counted.
    fn arithmetic_operation(&mut self);
    /// One call of an exact predicate that its floating-point filter could not decide, so
    /// that it ran an exact stage (integer, expansion or big-integer arithmetic). Recorded
    /// besides the call's own operation (an orientation test, ...), so the ratio of the two
    /// says how often a distribution of input needs exact arithmetic.
    fn exact_fallback(&mut self);
}

/// The counts of every kind of operation: a plain struct with named fields.
///
/// `Counts` is itself a [`Counter`], and counts from separate runs add up with `+`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Counts {
    /// Key comparisons.
    pub comparisons: u64,
    /// Exchanges of two elements.
    pub swaps: u64,
    /// Moves (assignments) of single elements.
    pub moves: u64,
    /// Orientation (signed area) tests.
    pub orientation_tests: u64,
    /// In-circle tests.
    pub incircle_tests: u64,
    /// Distance evaluations or comparisons.
    pub distance_evaluations: u64,
    /// Adjacency tests.
    pub adjacency_tests: u64,
    /// Edge visits.
    pub edge_visits: u64,
    /// Vertex visits.
    pub vertex_visits: u64,
    /// Arithmetic steps on points (affine combinations, multiply-adds).
    pub arithmetic_operations: u64,
    /// Predicate calls that needed an exact stage after the floating-point filter.
    pub exact_fallbacks: u64,
}

/// The kinds of operation [`Counts`] records, to name one of them (the complexity catalog
/// says which operation each algorithm's bound is about).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Operation {
    /// [`Counts::comparisons`].
    Comparisons,
    /// [`Counts::swaps`].
    Swaps,
    /// [`Counts::moves`].
    Moves,
    /// [`Counts::orientation_tests`].
    OrientationTests,
    /// [`Counts::incircle_tests`].
    IncircleTests,
    /// [`Counts::distance_evaluations`].
    DistanceEvaluations,
    /// [`Counts::adjacency_tests`].
    AdjacencyTests,
    /// [`Counts::edge_visits`].
    EdgeVisits,
    /// [`Counts::vertex_visits`].
    VertexVisits,
    /// [`Counts::arithmetic_operations`].
    ArithmeticOperations,
    /// [`Counts::exact_fallbacks`].
    ExactFallbacks,
}

impl Operation {
    /// Every operation, in the order of the fields of [`Counts`].
    pub const ALL: [Operation; 11] = [
        Operation::Comparisons,
        Operation::Swaps,
        Operation::Moves,
        Operation::OrientationTests,
        Operation::IncircleTests,
        Operation::DistanceEvaluations,
        Operation::AdjacencyTests,
        Operation::EdgeVisits,
        Operation::VertexVisits,
        Operation::ArithmeticOperations,
        Operation::ExactFallbacks,
    ];

    /// The field name in [`Counts`] (and in the JSON the CLI prints), e.g. `"orientation_tests"`.
    pub fn name(self) -> &'static str {
        match self {
            Operation::Comparisons => "comparisons",
            Operation::Swaps => "swaps",
            Operation::Moves => "moves",
            Operation::OrientationTests => "orientation_tests",
            Operation::IncircleTests => "incircle_tests",
            Operation::DistanceEvaluations => "distance_evaluations",
            Operation::AdjacencyTests => "adjacency_tests",
            Operation::EdgeVisits => "edge_visits",
            Operation::VertexVisits => "vertex_visits",
            Operation::ArithmeticOperations => "arithmetic_operations",
            Operation::ExactFallbacks => "exact_fallbacks",
        }
    }
}

impl Counts {
    /// The count of one kind of operation.
    pub fn get(&self, op: Operation) -> u64 {
        match op {
            Operation::Comparisons => self.comparisons,
            Operation::Swaps => self.swaps,
            Operation::Moves => self.moves,
            Operation::OrientationTests => self.orientation_tests,
            Operation::IncircleTests => self.incircle_tests,
            Operation::DistanceEvaluations => self.distance_evaluations,
            Operation::AdjacencyTests => self.adjacency_tests,
            Operation::EdgeVisits => self.edge_visits,
            Operation::VertexVisits => self.vertex_visits,
            Operation::ArithmeticOperations => self.arithmetic_operations,
            Operation::ExactFallbacks => self.exact_fallbacks,
        }
    }

    /// The sum of all counts.
    pub fn total(&self) -> u64 {
        Operation::ALL.iter().map(|&op| self.get(op)).sum()
    }
}

impl Counter for Counts {
    #[inline]
    fn comparison(&mut self) {
        self.comparisons += 1;
    }
    #[inline]
    fn swap(&mut self) {
        self.swaps += 1;
    }
    #[inline]
    fn element_move(&mut self) {
        self.moves += 1;
    }
    #[inline]
    fn orientation_test(&mut self) {
        self.orientation_tests += 1;
    }
    #[inline]
    fn incircle_test(&mut self) {
        self.incircle_tests += 1;
    }
    #[inline]
    fn distance_evaluation(&mut self) {
        self.distance_evaluations += 1;
    }
    #[inline]
    fn adjacency_test(&mut self) {
        self.adjacency_tests += 1;
    }
    #[inline]
    fn edge_visit(&mut self) {
        self.edge_visits += 1;
    }
    #[inline]
    fn vertex_visit(&mut self) {
        self.vertex_visits += 1;
    }
    #[inline]
    fn arithmetic_operation(&mut self) {
        self.arithmetic_operations += 1;
    }
    #[inline]
    fn exact_fallback(&mut self) {
        self.exact_fallbacks += 1;
    }
}

impl Add for Counts {
    type Output = Counts;
    fn add(mut self, rhs: Counts) -> Counts {
        self += rhs;
        self
    }
}

impl AddAssign for Counts {
    fn add_assign(&mut self, rhs: Counts) {
        self.comparisons += rhs.comparisons;
        self.swaps += rhs.swaps;
        self.moves += rhs.moves;
        self.orientation_tests += rhs.orientation_tests;
        self.incircle_tests += rhs.incircle_tests;
        self.distance_evaluations += rhs.distance_evaluations;
        self.adjacency_tests += rhs.adjacency_tests;
        self.edge_visits += rhs.edge_visits;
        self.vertex_visits += rhs.vertex_visits;
        self.arithmetic_operations += rhs.arithmetic_operations;
        self.exact_fallbacks += rhs.exact_fallbacks;
    }
}

/// The methods of a counter that records nothing: every one empty and inlined.
macro_rules! ignore_every_operation {
    () => {
        #[inline(always)]
        fn comparison(&mut self) {}
        #[inline(always)]
        fn swap(&mut self) {}
        #[inline(always)]
        fn element_move(&mut self) {}
        #[inline(always)]
        fn orientation_test(&mut self) {}
        #[inline(always)]
        fn incircle_test(&mut self) {}
        #[inline(always)]
        fn distance_evaluation(&mut self) {}
        #[inline(always)]
        fn adjacency_test(&mut self) {}
        #[inline(always)]
        fn edge_visit(&mut self) {}
        #[inline(always)]
        fn vertex_visit(&mut self) {}
        #[inline(always)]
        fn arithmetic_operation(&mut self) {}
        #[inline(always)]
        fn exact_fallback(&mut self) {}
    };
}

/// The counter that counts nothing: zero-sized, every method empty and inlined, so an
/// algorithm run with `NoCount` compiles to the uncounted code.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NoCount;

impl Counter for NoCount {
    const DISCARDS: bool = true;
    ignore_every_operation!();
}

/// A counter that records nothing yet, unlike [`NoCount`], leaves
/// [`DISCARDS`](Counter::DISCARDS) false, so an algorithm takes the path a counted run
/// takes: for timing that path (the benchmarks compare it with `NoCount`'s fast path, such as
/// the radix sort of points against the comparison sort).
///
/// ```
/// use compgeo::count::{Counter, Silent};
///
/// assert!(!Silent::DISCARDS);
/// assert_eq!(std::mem::size_of::<Silent>(), 0);
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Silent;

impl Counter for Silent {
    ignore_every_operation!();
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record_each(c: &mut impl Counter) {
        c.comparison();
        c.swap();
        c.element_move();
        c.orientation_test();
        c.incircle_test();
        c.distance_evaluation();
        c.adjacency_test();
        c.edge_visit();
        c.vertex_visit();
        c.arithmetic_operation();
        c.exact_fallback();
    }

    #[test]
    fn each_method_increments_its_own_field() {
        let mut c = Counts::default();
        record_each(&mut c);
        record_each(&mut c);
        for op in Operation::ALL {
            assert_eq!(c.get(op), 2, "{}", op.name());
        }
        assert_eq!(c.total(), 22);
    }

    #[test]
    fn counts_add_fieldwise() {
        let mut a = Counts::default();
        a.comparison();
        a.comparison();
        let mut b = Counts::default();
        b.comparison();
        b.incircle_test();
        let s = a + b;
        assert_eq!(s.comparisons, 3);
        assert_eq!(s.incircle_tests, 1);
        assert_eq!(s.total(), 4);
    }

    #[test]
    fn no_count_is_zero_sized() {
        assert_eq!(std::mem::size_of::<NoCount>(), 0);
        record_each(&mut NoCount);
    }
}
