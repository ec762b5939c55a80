//! The circle-event queue of Fortune's sweep: a calendar of height buckets in front of a
//! binary heap.
//!
//! A binary heap of every pending event pays O(log q) comparisons per pop for a queue of q
//! events, most of them far above the sweep line (and about two in five of them false
//! alarms that will only be skipped). The sweep only ever needs the events just above the
//! line, so this queue keeps only those in the heap (the *near* events) and parks the rest,
//! in O(1) each, in buckets of equal height between the lowest and the highest site. When
//! the sweep reaches a bucket, its events move into the heap; the false alarms among them
//! are dropped on the way without a heap operation.
//!
//! The order stays exact: an event is parked in the bucket of the lower end of its
//! estimate's interval (see [`TopEstimate`]), buckets are numbered by a monotone function of
//! the height, and the heap's first event is only taken for the first event of all when the
//! upper end of its interval falls in a bucket already moved, so that every parked event's
//! exact top is strictly above its own. The heap compares events exactly, as before.

use super::beach_line::NIL;
use crate::count::Counter;
use crate::geometry::sweep_predicates::TopEstimate;
use crate::util::Heap;

/// A circle event as the queue holds it (16 bytes): the estimate of its circle's top (see
/// [`TopEstimate`]) and its id, which the sweep uses to find the event's sites (ids are
/// slots reused once an event has left the queue).
#[derive(Debug, Clone, Copy)]
pub(super) struct Event {
    pub(super) top: f64,
    pub(super) err: f32,
    /// Matches the arc's pending event while the event is still valid.
    pub(super) id: u32,
}

const _: () = assert!(std::mem::size_of::<Event>() == 16);

impl Event {
    /// The estimate of the event's top.
    #[inline]
    pub(super) fn estimate(&self) -> TopEstimate {
        TopEstimate {
            top: self.top,
            err: self.err,
        }
    }

    /// A height at or below the exact top: the estimate's lower end, rounded down.
    #[inline]
    fn lower(&self) -> f64 {
        // `top − err` rounded to nearest may land above the exact difference by half an
        // ulp; one ulp down is below it (and -inf for an estimate that decides nothing).
        (self.top - self.err as f64).next_down()
    }

    /// A height at or above the exact top: the estimate's upper end, rounded up.
    #[inline]
    fn upper(&self) -> f64 {
        (self.top + self.err as f64).next_up()
    }
}

/// A monotone map of a coordinate onto `count` buckets of equal width between two values
/// (the queue's heights; the sweep's hints for locating sites by x).
#[derive(Debug, Clone, Copy)]
pub(super) struct Buckets {
    origin: f64,
    /// Buckets per unit.
    scale: f64,
    last: usize,
}

impl Buckets {
    /// About `count` buckets (at least one) from `low` to `high` (finite, `low <= high`);
    /// one bucket if the range is empty or too narrow to divide.
    pub(super) fn new(low: f64, high: f64, count: usize) -> Buckets {
        let count = count.max(1);
        let scale = count as f64 / (high - low);
        if scale.is_finite() && scale > 0.0 {
            Buckets {
                origin: low,
                scale,
                last: count - 1,
            }
        } else {
            Buckets {
                origin: low,
                scale: 0.0,
                last: 0,
            }
        }
    }

    /// The number of buckets.
    #[inline]
    pub(super) fn count(&self) -> usize {
        self.last + 1
    }

    /// The bucket of `v`: a non-decreasing function of `v` (a subtraction and a product by
    /// a non-negative constant, both monotone under rounding, then the floor, clamped to
    /// the buckets; -inf gives the first, +inf and NaN the last).
    #[inline]
    pub(super) fn of(&self, v: f64) -> usize {
        let t = (v - self.origin) * self.scale;
        if t >= 0.0 {
            // `as` saturates: huge values land in the last bucket.
            (t as usize).min(self.last)
        } else if t.is_nan() {
            self.last
        } else {
            0
        }
    }
}

impl Buckets {
    /// A value every value at or below which maps to a bucket before `b`: -inf for the
    /// first bucket, +inf past the last, otherwise the largest double below the boundary
    /// computed (found by stepping down from it, since the map rounds) or, failing that
    /// within a few steps, a value below the first bucket's lower end.
    pub(super) fn all_before(&self, b: usize) -> f64 {
        if b == 0 {
            return f64::NEG_INFINITY;
        }
        if b > self.last {
            return f64::INFINITY;
        }
        // Here scale > 0 (a single bucket has last == 0).
        let mut v = self.origin + b as f64 / self.scale;
        for _ in 0..64 {
            if self.of(v) < b {
                return v;
            }
            v = v.next_down();
        }
        // Below the origin every value maps to bucket 0 < b.
        self.origin.next_down()
    }
}

/// A parked event: its estimate and the next event of its bucket ([`NIL`] at the end).
#[derive(Debug, Clone, Copy)]
struct Parked {
    top: f64,
    err: f32,
    next: u32,
}

/// The first queued event, as [`EventQueue::settle`] finds it: pass it back to
/// [`EventQueue::take`] to remove it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Front {
    pub(super) event: Event,
    /// Whether it is the head of the near events' sorted run (otherwise their heap's top).
    in_run: bool,
}

/// The near events: a run of events each queued at or after the one queued before it
/// (along a row of sites, and on integer grids, events tied in height arrive in their
/// order on the sweep line), and a heap for the others. The run's head and the heap's top
/// compete for first place.
#[derive(Debug)]
struct Near {
    run: Vec<Event>,
    /// The run's first event not yet taken.
    head: usize,
    heap: Heap<Event>,
    /// Whether an event whose estimate overlaps the run's last one is compared exactly to
    /// join the run (see [`EventQueue::with_exact_ties`]).
    exact_ties: bool,
}

impl Near {
    /// Queues `e` at the end of the run if it is not before the run's last event (one
    /// comparison), in the heap otherwise. An estimate that decides nothing goes to the
    /// heap: as the run's last event it would make every later push compare exactly.
    #[inline]
    fn push<C: Counter>(
        &mut self,
        e: Event,
        less: impl Fn(&Event, &Event) -> bool,
        counter: &mut C,
    ) {
        if e.err == f32::INFINITY {
            self.heap.push(e, less, counter);
            return;
        }
        if self.head == self.run.len() {
            self.run.clear();
            self.head = 0;
            self.run.push(e);
            return;
        }
        let last = self.run[self.run.len() - 1];
        counter.comparison();
        // The estimates first. When they overlap, the exact order only if it is cheap:
        // otherwise (big integers) the heap's own path compares the event with fewer
        // events that close to it.
        let after_last = match last.estimate().is_below(&e.estimate()) {
            Some(below) => below,
            None => self.exact_ties && !less(&e, &last),
        };
        if after_last {
            self.run.push(e);
        } else {
            self.heap.push(e, less, counter);
        }
    }

    /// The first near event (one comparison when both the run and the heap hold some).
    #[inline]
    fn front<C: Counter>(
        &self,
        less: impl Fn(&Event, &Event) -> bool,
        counter: &mut C,
    ) -> Option<Front> {
        let run = self.run.get(self.head);
        match (run, self.heap.peek()) {
            (None, None) => None,
            (Some(&r), None) => Some(Front {
                event: r,
                in_run: true,
            }),
            (None, Some(&h)) => Some(Front {
                event: h,
                in_run: false,
            }),
            (Some(&r), Some(&h)) => {
                counter.comparison();
                // The run first on a tie: either order is an order of the events.
                Some(if less(&h, &r) {
                    Front {
                        event: h,
                        in_run: false,
                    }
                } else {
                    Front {
                        event: r,
                        in_run: true,
                    }
                })
            }
        }
    }

    #[cfg(test)]
    fn is_empty(&self) -> bool {
        self.head == self.run.len() && self.heap.peek().is_none()
    }
}

/// The queue: the near events in an exact order, the others in buckets by height.
#[derive(Debug)]
pub(super) struct EventQueue {
    near: Near,
    /// The first parked event of each bucket, or [`NIL`]; bucket `b` holds the events whose
    /// lower end maps to `b` (see [`bucket`](Self::bucket)).
    heads: Vec<u32>,
    /// The parked events by id (only the slots of parked events are meaningful).
    parked: Vec<Parked>,
    /// The number of parked events.
    parked_count: usize,
    /// Scratch space for the ids of the bucket being moved.
    moving: Vec<u32>,
    /// The first bucket not yet moved into the heap: every parked event's lower end maps to
    /// this bucket or a later one.
    current: usize,
    /// Every height at or below this maps to a bucket before `current` (see
    /// [`Buckets::all_before`]): a test without the bucket arithmetic.
    moved_below: f64,
    /// The buckets' heights.
    buckets: Buckets,
}

impl EventQueue {
    /// An empty queue for a sweep over sites with heights from `lowest` to `highest`
    /// (finite, `lowest <= highest`), with about `buckets` buckets in between (at least
    /// one; a single bucket makes the queue a plain heap after the first event).
    pub(super) fn new(lowest: f64, highest: f64, buckets: usize) -> EventQueue {
        let buckets = Buckets::new(lowest, highest, buckets);
        EventQueue {
            near: Near {
                run: Vec::with_capacity(64),
                head: 0,
                heap: Heap::with_capacity(64),
                exact_ties: false,
            },
            heads: vec![NIL; buckets.count()],
            parked: Vec::new(),
            parked_count: 0,
            moving: Vec::new(),
            current: 0,
            moved_below: f64::NEG_INFINITY,
            buckets,
        }
    }

    /// The queue, where an event whose estimate overlaps the last one of the near
    /// events' run is compared exactly to join the run: for sites whose exact comparisons
    /// are cheap and whose events tie in height often (small-integer sets: grids).
    /// Otherwise such an event goes to the heap.
    pub(super) fn with_exact_ties(mut self) -> EventQueue {
        self.near.exact_ties = true;
        self
    }

    /// Whether no event is queued.
    #[cfg(test)]
    fn is_empty(&self) -> bool {
        self.near.is_empty() && self.parked_count == 0
    }

    /// The bucket of height `y` (see [`Buckets::of`]).
    #[inline]
    fn bucket(&self, y: f64) -> usize {
        self.buckets.of(y)
    }

    /// Whether an estimate with the error bound `err` spans more than a bucket's height:
    /// such an event would meet the events of several buckets in the heap and be compared
    /// exactly with each, so it is worth a tight estimate first (see
    /// [`TopEstimate::exact`]). Never for a single bucket.
    #[inline]
    pub(super) fn is_wide(&self, err: f32) -> bool {
        err as f64 * self.buckets.scale > 1.0
    }

    /// Queues `e`: in the heap (O(log q) comparisons by `less`, counted) if its bucket has
    /// been moved already, otherwise parked in O(1).
    #[inline]
    pub(super) fn push<C: Counter>(
        &mut self,
        e: Event,
        less: impl Fn(&Event, &Event) -> bool,
        counter: &mut C,
    ) {
        let lower = e.lower();
        let b = if lower <= self.moved_below {
            0
        } else {
            self.bucket(lower)
        };
        if b < self.current {
            self.near.push(e, less, counter);
            return;
        }
        let slot = e.id as usize;
        if slot >= self.parked.len() {
            let filler = Parked {
                top: 0.0,
                err: 0.0,
                next: NIL,
            };
            self.parked.resize(slot + 1, filler);
        }
        self.parked[slot] = Parked {
            top: e.top,
            err: e.err,
            next: self.heads[b],
        };
        self.heads[b] = e.id;
        self.parked_count += 1;
    }

    /// Moves buckets into the near events until their first is the first of all, or every
    /// parked event is provably above `horizon` (the next site's height; +inf for none),
    /// and returns that first near event: compared with the next site, it decides what comes
    /// next. Parked events for which `pending` is false are dropped, their ids appended to
    /// `dropped`.
    #[inline]
    pub(super) fn settle<C: Counter>(
        &mut self,
        horizon: f64,
        pending: impl Fn(u32) -> bool,
        dropped: &mut Vec<u32>,
        less: impl Fn(&Event, &Event) -> bool,
        counter: &mut C,
    ) -> Option<Front> {
        loop {
            let front = self.near.front(&less, counter);
            if self.parked_count == 0 {
                return front;
            }
            if let Some(f) = front {
                // Every parked event's lower end maps to `current` or later, so it is above
                // this upper end (the bucket map does not decrease).
                if f.event.upper() <= self.moved_below {
                    return front;
                }
            }
            if horizon <= self.moved_below {
                return front; // every parked event is above the next site
            }
            // The bucket's list runs from its latest event to its first: it is taken in
            // the order the events were queued, which along a row of sites is their order
            // on the sweep line too (so tied events go to the run, not the heap).
            let mut id = std::mem::replace(&mut self.heads[self.current], NIL);
            while id != NIL {
                self.moving.push(id);
                id = self.parked[id as usize].next;
            }
            self.parked_count -= self.moving.len();
            for &id in self.moving.iter().rev() {
                if pending(id) {
                    let p = self.parked[id as usize];
                    let e = Event {
                        top: p.top,
                        err: p.err,
                        id,
                    };
                    self.near.push(e, &less, counter);
                } else {
                    dropped.push(id);
                }
            }
            self.moving.clear();
            self.current += 1;
            self.moved_below = self.buckets.all_before(self.current);
        }
    }

    /// Removes `front`, the first event as [`settle`](Self::settle) returned it (with no
    /// event queued since).
    #[inline]
    pub(super) fn take<C: Counter>(
        &mut self,
        front: Front,
        less: impl Fn(&Event, &Event) -> bool,
        counter: &mut C,
    ) {
        if front.in_run {
            self.near.head += 1;
        } else {
            self.near.heap.pop(less, counter);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::NoCount;
    use crate::gen::Rng;

    /// Records the exact key of event `id`, and returns an estimate of it off by `off`
    /// (at most half of `err`, either way) with the bound `err`.
    fn event(keys: &mut Vec<f64>, key: f64, err: f64, off: f64, id: u32) -> Event {
        if keys.len() <= id as usize {
            keys.resize(id as usize + 1, 0.0);
        }
        keys[id as usize] = key;
        let top = key + off.clamp(-0.5, 0.5) * err;
        Event {
            top,
            err: err as f32,
            id,
        }
    }

    /// A sweep-like run: keys only ever pushed at or above the last key taken, some events
    /// cancelled while queued, and the order checked against the exact keys. Returns the
    /// number of events taken.
    fn run(buckets: usize, err: f64, seed: u64) -> usize {
        let mut rng = Rng::new(seed);
        let mut queue = EventQueue::new(0.0, 100.0, buckets);
        if seed % 2 == 0 {
            queue = queue.with_exact_ties();
        }
        let mut keys = Vec::new();
        let mut cancelled = Vec::new();
        let mut dropped = Vec::new();
        let mut next_id = 0u32;
        let mut sweep = 0.0f64;
        let mut taken = 0;
        let mut live = 0;
        for step in 0..4000 {
            // A few new events just above the sweep, some far above, some beyond the range.
            for _ in 0..rng.index(3) {
                let ahead = match rng.index(10) {
                    0 => 500.0 * rng.unit(),
                    1..=3 => 0.0,
                    _ => 2.0 * rng.unit(),
                };
                let key = sweep + ahead;
                let off = rng.symmetric_unit() / 2.0;
                let e = event(&mut keys, key, err, off, next_id);
                cancelled.push(rng.index(3) == 0);
                queue.push(
                    e,
                    |x, y| keys[x.id as usize] < keys[y.id as usize],
                    &mut NoCount,
                );
                next_id += 1;
                live += 1;
            }
            // The next "site" at the current sweep height plus a little.
            let horizon = if step < 3500 {
                sweep + rng.unit()
            } else {
                f64::INFINITY
            };
            let less = |x: &Event, y: &Event| keys[x.id as usize] < keys[y.id as usize];
            let front = queue.settle(
                horizon,
                |id| !cancelled[id as usize],
                &mut dropped,
                less,
                &mut NoCount,
            );
            let Some(front) = front else {
                assert!(queue.is_empty() || horizon.is_finite());
                if horizon.is_finite() {
                    sweep = sweep.max(horizon);
                }
                continue;
            };
            let first_key = keys[front.event.id as usize];
            if first_key > horizon {
                // The site comes first; nothing parked may be below it.
                sweep = horizon;
                continue;
            }
            queue.take(front, less, &mut NoCount);
            let e = front.event;
            // Nothing still queued, parked or near, is below the taken key.
            assert!(first_key >= sweep, "out of order at step {step}");
            sweep = first_key;
            live -= 1;
            if !cancelled[e.id as usize] {
                taken += 1;
            }
        }
        // Drain, checking the order to the end.
        let less = |x: &Event, y: &Event| keys[x.id as usize] < keys[y.id as usize];
        let pending = |id: u32| !cancelled[id as usize];
        while let Some(front) =
            queue.settle(f64::INFINITY, pending, &mut dropped, less, &mut NoCount)
        {
            queue.take(front, less, &mut NoCount);
            let e = front.event;
            let key = keys[e.id as usize];
            assert!(key >= sweep);
            sweep = key;
            live -= 1;
            if !cancelled[e.id as usize] {
                taken += 1;
            }
        }
        assert!(queue.is_empty());
        // Every event was taken or dropped, and only cancelled ones were dropped.
        assert_eq!(live, dropped.len());
        assert!(dropped.iter().all(|&id| cancelled[id as usize]));
        let wanted = cancelled.iter().filter(|&&c| !c).count();
        assert_eq!(taken, wanted);
        taken
    }

    #[test]
    fn events_come_out_in_exact_order_with_any_bucket_count() {
        for buckets in [1, 2, 7, 100, 10_000] {
            for (seed, err) in [(1, 0.0), (2, 1e-3), (3, 0.7), (4, 30.0)] {
                assert!(run(buckets, err, seed) > 1000, "{buckets} {err}");
            }
        }
    }

    #[test]
    fn an_estimate_that_decides_nothing_waits_in_the_heap() {
        // err = inf: lower end -inf (the first bucket), upper end +inf (the last).
        let mut queue = EventQueue::new(0.0, 10.0, 10);
        let less = |x: &Event, y: &Event| x.id < y.id;
        let undecided = Event {
            top: 0.0,
            err: f32::INFINITY,
            id: 0,
        };
        let high = Event {
            top: 9.5,
            err: 0.0,
            id: 1,
        };
        queue.push(high, less, &mut NoCount);
        queue.push(undecided, less, &mut NoCount);
        let mut dropped = Vec::new();
        let mut taken = Vec::new();
        while let Some(front) =
            queue.settle(f64::INFINITY, |_| true, &mut dropped, less, &mut NoCount)
        {
            // Its upper end is in the last bucket: every bucket had to move first.
            assert_eq!(queue.current, 10);
            queue.take(front, less, &mut NoCount);
            taken.push(front.event.id);
        }
        assert_eq!(taken, [0, 1]);
        assert!(queue.is_empty() && dropped.is_empty());
    }

    #[test]
    fn a_flat_height_range_gives_one_bucket() {
        for (lo, hi) in [(3.0, 3.0), (0.0, f64::MIN_POSITIVE / 4.0)] {
            let queue = EventQueue::new(lo, hi, 1000);
            assert_eq!(queue.heads.len(), 1);
            assert_eq!(queue.bucket(f64::MAX), 0);
        }
        assert_eq!(Buckets::new(0.0, 1.0, 0).count(), 1);
        // all_before(b) maps below b, and the next double up does not (here the boundaries
        // are exact).
        let tenths = Buckets::new(0.25, 1e6 + 0.25, 10_000_000);
        for b in [1, 2, 3, 7, 1000, 9_999_999] {
            let v = tenths.all_before(b);
            assert!(tenths.of(v) < b, "{b}");
            assert!(tenths.of(v.next_up()) >= b, "{b}");
        }
        assert_eq!(tenths.all_before(0), f64::NEG_INFINITY);
        assert_eq!(tenths.all_before(10_000_000), f64::INFINITY);
        assert_eq!(Buckets::new(5.0, 5.0, 9).all_before(1), f64::INFINITY);
        let queue = EventQueue::new(0.0, 1.0, 4);
        let buckets: Vec<usize> = [f64::NEG_INFINITY, -1.0, 0.0, 0.3, 0.5, 0.99, 1.0, 1e300]
            .map(|y| queue.bucket(y))
            .to_vec();
        assert_eq!(buckets, [0, 0, 0, 1, 2, 3, 3, 3]);
        assert_eq!(queue.bucket(f64::NAN), 3);
    }
}
