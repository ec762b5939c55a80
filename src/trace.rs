//! Step traces: the frames of an algorithm's own run, for step-by-step pictures and tables.
//!
//! A trace function (`hull::jarvis_trace`, `delaunay::lawson_trace`,
//! `graph::prim_trace`, ...) runs the very code of the algorithm's plain and `_with`
//! functions: the algorithm is written once, generic over an observer that it tells about each
//! step. The plain and `_with` functions pass an observer that ignores every step and never
//! builds one (the step is handed over as a closure that it does not call), so they pay
//! nothing for it; the trace function passes one that records a [`Frame`] per step, with the
//! operation [`Counts`] made so far. Nothing in a trace is re-derived: each frame is the
//! state of the run at that moment, and the last one holds the algorithm's result.
//!
//! Each algorithm has its own step type, whose variants say what happened (a point pushed on
//! Graham's stack, an edge flipped, a polygon averaged) and carry the state a picture needs,
//! as indices into the caller's input or as points.
//!
//! # Size
//!
//! A trace holds a copy of the state per step, so its size grows faster than the run: for
//! Jarvis's march on n points in convex position, n² frames each holding up to n indices.
//! Every trace function counts the entries it stores (one per frame, plus one per index or
//! point in it) and stops storing beyond [`TRACE_MAX_ENTRIES`], returning
//! [`Error::LimitExceeded`](crate::Error::LimitExceeded): the run itself is bounded by the
//! algorithm's complexity, the memory by the limit.
//!
//! ```
//! use compgeo::geometry::Point2;
//! use compgeo::hull::{graham_trace, GrahamStep, HullOptions};
//!
//! let pts = [(0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (2.0, 2.0), (0.0, 2.0)].map(Point2::from);
//! let frames = graham_trace(&pts, HullOptions::default())?;
//! assert!(matches!(frames[0].step, GrahamStep::Sorted { .. }));
//! let GrahamStep::Done { hull } = &frames[frames.len() - 1].step else { panic!() };
//! assert_eq!(hull, &[0, 1, 3, 4]);
//! assert!(frames[frames.len() - 1].counts.orientation_tests > 0);
//! # Ok::<(), compgeo::Error>(())
//! ```

use crate::count::Counts;
use crate::limits::TRACE_ENTRIES;
use crate::Result;

pub use crate::limits::TRACE_MAX_ENTRIES;

/// One step of an algorithm's run: what happened, and the operations made so far.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Frame<S> {
    /// The step, with the state after it (the algorithm's own step type).
    pub step: S,
    /// The operations the run had made when it reached this step, counted as the
    /// algorithm's `_with` function counts them.
    pub counts: Counts,
}

/// Watches an algorithm's steps. The algorithm calls [`Observer::step`] with its counter and
/// a closure that builds the step; [`NoObserver`] never calls the closure, [`Recorder`]
/// stores a [`Frame`].
pub(crate) trait Observer<S, C: ?Sized> {
    /// One step: `step` builds it, `counter` holds the operations so far.
    fn step(&mut self, counter: &C, step: impl FnOnce() -> S);
}

/// The observer that watches nothing: what the plain and `_with` functions pass.
pub(crate) struct NoObserver;

impl<S, C: ?Sized> Observer<S, C> for NoObserver {
    #[inline(always)]
    fn step(&mut self, _counter: &C, _step: impl FnOnce() -> S) {}
}

/// How many entries a step stores, for [`TRACE_MAX_ENTRIES`]: one per index or point it
/// holds (the frame itself counts one more).
pub(crate) trait TraceSize {
    /// The number of indices or points in the step.
    fn entries(&self) -> usize;
}

/// Runs `run` with a fresh [`Counts`] and [`Recorder`], records the step it returns as the
/// last frame (the algorithm's result, `Done`), and returns the frames: the body of every
/// trace function whose algorithm ends with a result step.
///
/// # Errors
/// Those of `run`, and [`Recorder::finish`]'s beyond [`TRACE_MAX_ENTRIES`].
pub(crate) fn record<S: TraceSize>(
    run: impl FnOnce(&mut Counts, &mut Recorder<S>) -> Result<S>,
) -> Result<Vec<Frame<S>>> {
    let mut counts = Counts::default();
    let mut recorder = Recorder::new();
    let last = run(&mut counts, &mut recorder)?;
    recorder.step(&counts, || last);
    recorder.finish()
}

/// The observer of a trace function: a frame per step, up to [`TRACE_MAX_ENTRIES`].
pub(crate) struct Recorder<S> {
    frames: Vec<Frame<S>>,
    entries: u128,
}

impl<S: TraceSize> Recorder<S> {
    /// An empty trace.
    pub(crate) fn new() -> Self {
        Recorder {
            frames: Vec::new(),
            entries: 0,
        }
    }

    /// The frames, or [`Error::LimitExceeded`](crate::Error::LimitExceeded) if they passed
    /// [`TRACE_MAX_ENTRIES`] (then the entries counted when the limit was passed).
    pub(crate) fn finish(self) -> Result<Vec<Frame<S>>> {
        TRACE_ENTRIES.check(self.entries)?;
        Ok(self.frames)
    }
}

impl<S: TraceSize> Observer<S, Counts> for Recorder<S> {
    fn step(&mut self, counter: &Counts, step: impl FnOnce() -> S) {
        if self.entries > TRACE_MAX_ENTRIES as u128 {
            return;
        }
        let step = step();
        self.entries += 1 + step.entries() as u128;
        if self.entries <= TRACE_MAX_ENTRIES as u128 {
            self.frames.push(Frame {
                step,
                counts: *counter,
            });
        } else {
            // Passed the limit: drop what was stored, the caller gets the error.
            self.frames = Vec::new();
        }
    }
}
