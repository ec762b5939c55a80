//! Step tables of the sorting algorithms, laid out like the course's tables.
//!
//! The rows come from the real algorithms: [`trace`] runs the same code as `X_sort_with`,
//! with an observer that the algorithm calls at each step and a comparator that records the
//! comparisons it is asked to make. Nothing is re-derived here.

use super::binary_insertion::binary_insertion;
use super::bubble::bubble;
use super::course_binary_insertion::course_binary_insertion;
use super::course_insertion::course_insertion;
use super::heap::heap;
use super::insertion::insertion;
use super::merge::merge;
use super::quick::quick;
use super::selection::selection;
use super::{Algorithm, Counted, Observer, Step};
use crate::count::Counts;
use crate::Result;
use std::cell::RefCell;
use std::cmp::Ordering;
use std::fmt::Write;

pub use crate::limits::TRACE_MAX_LEN;

/// Sorts a copy of `input` with `algorithm` and returns its step table as plain text.
///
/// The first line names the algorithm and the input; the last one gives the totals,
/// `Comparisons: c, swaps: s, moves: m`, counted as `X_sort_with` counts them. The rows in
/// between reproduce the layout of the course's tables ([RD, §2.1]
/// "Algoritmos de ordenación"), in English:
///
/// - bubble: `Initial order`, then `After comparison k` with the compared pair as it stands
///   after the comparison (and exchange), `After pass i` with the whole list, `Final order`;
/// - selection: `L = {…}`, then per step the position and value of the minimum, the exchange
///   made (or `no exchange`) and the rest of the list `L := {…}`, and `Output: {…}`;
/// - insertion (both kinds): the sorted list after each insertion and, after `since`, the
///   comparisons that placed the new element (for `CourseInsertion`, the course's "pues"
///   clauses);
/// - binary insertion (both kinds): per step the sorted list `{…}` and the bisection, one
///   indented line per comparison, written like the course: `x ↦ {left | right} :` and
///   `x < e ⇒ …` (`CourseBinaryInsertion` reproduces the course's table).
///
/// The O(n log n) references get one row per top-level step: merge sort a row per merge
/// (`Merge {…} + {…} → {…}`), heap sort the heap after construction and after each
/// extraction (`heap | sorted suffix`), quicksort a row per partition
/// (`left | pivot | right`), per short range sorted directly and per range handed to heap
/// sort. Positions `x1, x2, …` count from 1, as in the course.
///
/// # Errors
///
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `input` has more than [`TRACE_MAX_LEN`] values (bubble sort's
/// table has a row per comparison, n(n−1)/2 of them). Every shorter list, empty included,
/// is traced.
///
/// # Complexity
///
/// With n = `input.len()`: the algorithm's time plus the size of the table, which holds O(n²)
/// values for every algorithm (bubble sort's n(n−1)/2 comparison rows, or about n rows of up
/// to n values); space the same as the text.
///
/// ```
/// use compgeo::sort::{trace, Algorithm};
///
/// let table = trace(Algorithm::Bubble, &[7, 3, 5, 1])?;
/// let rows: Vec<&str> = table.lines().collect();
/// assert_eq!(rows[0], "Bubble sort of 7 3 5 1");
/// assert!(rows[2].starts_with("After comparison 1:") && rows[2].ends_with(" 3 7"));
/// assert_eq!(*rows.last().unwrap(), "Comparisons: 6, swaps: 5, moves: 0");
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn trace(algorithm: Algorithm, input: &[i64]) -> Result<String> {
    crate::limits::TRACE_LEN.check(input.len() as u128)?;
    let log = RefCell::new(Vec::new());
    let cmp = |a: &i64, b: &i64| {
        let ord = a.cmp(b);
        log.borrow_mut().push((*a, *b, ord));
        ord
    };
    let mut counts = Counts::default();
    let mut ops = Counted::new(cmp, &mut counts);
    let mut v = input.to_vec();
    let title = match algorithm {
        Algorithm::Bubble => "Bubble sort",
        Algorithm::Selection => "Selection sort",
        Algorithm::Insertion => "Insertion sort (sequential, from the back)",
        Algorithm::CourseInsertion => "Insertion sort (sequential)",
        Algorithm::BinaryInsertion => "Insertion sort (bisection, fewest comparisons)",
        Algorithm::CourseBinaryInsertion => "Insertion sort (bisection)",
        Algorithm::Merge => "Merge sort",
        Algorithm::Heap => "Heap sort",
        Algorithm::Quick => "Quicksort",
    };
    let mut out = format!("{title} of {}\n", list(input));
    match algorithm {
        Algorithm::Bubble => {
            let mut rows = BubbleRows::new(input);
            bubble(&mut v, &mut ops, &mut rows);
            rows.finish(&v, &mut out);
        }
        Algorithm::Selection => {
            let mut rows = SelectionRows::default();
            selection(&mut v, &mut ops, &mut rows);
            rows.finish(input, &v, &mut out);
        }
        Algorithm::Insertion => {
            let mut rows = InsertionRows::new(input, &log);
            insertion(&mut v, &mut ops, &mut rows);
            rows.table.render(&mut out);
        }
        Algorithm::CourseInsertion => {
            let mut rows = InsertionRows::new(input, &log);
            course_insertion(&mut v, &mut ops, &mut rows);
            rows.table.render(&mut out);
        }
        Algorithm::BinaryInsertion => {
            let mut rows = BisectionRows::new(&log);
            binary_insertion(&mut v, &mut ops, &mut rows);
            rows.finish(&v, &mut out);
        }
        Algorithm::CourseBinaryInsertion => {
            let mut rows = BisectionRows::new(&log);
            course_binary_insertion(&mut v, &mut ops, &mut rows);
            rows.finish(&v, &mut out);
        }
        Algorithm::Merge => {
            let mut rows = MergeRows::default();
            merge(&mut v, &mut ops, &mut rows);
            rows.finish(&v, &mut out);
        }
        Algorithm::Heap => {
            let mut rows = Table::default();
            heap(&mut v, &mut ops, &mut rows);
            rows.push("Final order:", list(&v));
            rows.render(&mut out);
        }
        Algorithm::Quick => {
            let mut rows = Table::default();
            quick(&mut v, &mut ops, &mut rows);
            rows.push("Final order:", list(&v));
            rows.render(&mut out);
        }
    }
    // Writing to a String cannot fail.
    let _ = writeln!(
        out,
        "Comparisons: {}, swaps: {}, moves: {}",
        counts.comparisons, counts.swaps, counts.moves
    );
    Ok(out)
}

/// Values separated by spaces, as in the course's bubble and insertion tables.
fn list(v: &[i64]) -> String {
    if v.is_empty() {
        return "(empty)".to_string();
    }
    v.iter().map(i64::to_string).collect::<Vec<_>>().join(" ")
}

/// Values in braces, as in the course's selection and bisection tables.
fn set(v: &[i64]) -> String {
    let inner: Vec<String> = v.iter().map(i64::to_string).collect();
    format!("{{{}}}", inner.join(", "))
}

/// `a < b`, `a = b` or `a > b`.
fn relation((a, b, ord): (i64, i64, Ordering)) -> String {
    let op = match ord {
        Ordering::Less => '<',
        Ordering::Equal => '=',
        Ordering::Greater => '>',
    };
    format!("{a} {op} {b}")
}

/// Two columns, the first padded to a common width.
#[derive(Default)]
struct Table {
    rows: Vec<(String, String)>,
}

impl Table {
    fn push(&mut self, first: impl Into<String>, second: impl Into<String>) {
        self.rows.push((first.into(), second.into()));
    }

    fn render(&self, out: &mut String) {
        let width = self
            .rows
            .iter()
            .map(|(a, _)| a.chars().count())
            .max()
            .unwrap_or(0);
        for (a, b) in &self.rows {
            let line = format!("{a:<width$}  {b}");
            out.push_str(line.trim_end());
            out.push('\n');
        }
    }
}

/// Heap sort and quicksort: one row per step.
impl Observer<i64> for Table {
    fn step(&mut self, v: &[i64], step: Step<'_>) {
        match step {
            Step::HeapBuilt => self.push("Heap built:", list(v)),
            Step::Extracted { end } => self.push(
                format!("Maximum {} to x{}:", v[end], end + 1),
                format!("{} | {}", list(&v[..end]), list(&v[end..])),
            ),
            Step::Partitioned { lo, hi, pivot } => self.push(
                format!("Partition x{}..x{}, pivot {}:", lo + 1, hi, v[pivot]),
                format!(
                    "{} | {} | {}",
                    list(&v[lo..pivot]),
                    v[pivot],
                    list(&v[pivot + 1..hi])
                ),
            ),
            Step::ShortSorted { lo, hi } => self.push(
                format!("Sort x{}..x{} directly:", lo + 1, hi),
                list(&v[lo..hi]),
            ),
            Step::HeapFallback { lo, hi } => self.push(
                format!("Depth limit, heap sort x{}..x{}:", lo + 1, hi),
                list(&v[lo..hi]),
            ),
            _ => {}
        }
    }
}

struct BubbleRows {
    table: Table,
    comparisons: usize,
    passes: usize,
}

impl BubbleRows {
    fn new(input: &[i64]) -> Self {
        let mut table = Table::default();
        table.push("Initial order:", list(input));
        BubbleRows {
            table,
            comparisons: 0,
            passes: input.len().saturating_sub(1),
        }
    }

    fn finish(mut self, v: &[i64], out: &mut String) {
        self.table.push("Final order:", list(v));
        self.table.render(out);
    }
}

impl Observer<i64> for BubbleRows {
    fn step(&mut self, v: &[i64], step: Step<'_>) {
        match step {
            Step::Compared { j } => {
                self.comparisons += 1;
                let label = format!("After comparison {}:", self.comparisons);
                self.table.push(label, list(&v[j..j + 2]));
            }
            Step::PassDone { pass } => {
                let last = if pass == self.passes {
                    " (the last)"
                } else {
                    ""
                };
                self.table
                    .push(format!("After pass {pass}{last}:"), list(v));
            }
            _ => {}
        }
    }
}

#[derive(Default)]
struct SelectionRows {
    table: Table,
}

impl SelectionRows {
    fn finish(mut self, input: &[i64], v: &[i64], out: &mut String) {
        let _ = writeln!(out, "L = {}", set(input));
        self.table.push(format!("Output: {}", set(v)), "");
        self.table.render(out);
    }
}

impl Observer<i64> for SelectionRows {
    fn step(&mut self, v: &[i64], step: Step<'_>) {
        if let Step::Selected { i, min } = step {
            let (a, m) = (i + 1, min + 1);
            let what = if min == i {
                format!("Step {a}: the minimum of L is x{a} = {}, no exchange", v[i])
            } else {
                format!(
                    "Step {a}: the minimum of L is x{m}, exchange: x{a} = {}, x{m} = {}",
                    v[i], v[min]
                )
            };
            let rest = if i + 2 == v.len() {
                "the algorithm has finished".to_string()
            } else {
                format!("L := {}", set(&v[i + 1..]))
            };
            self.table.push(what, rest);
        }
    }
}

struct InsertionRows<'l> {
    table: Table,
    log: &'l RefCell<Vec<(i64, i64, Ordering)>>,
}

impl<'l> InsertionRows<'l> {
    fn new(input: &[i64], log: &'l RefCell<Vec<(i64, i64, Ordering)>>) -> Self {
        let mut table = Table::default();
        if let Some(first) = input.first() {
            table.push(first.to_string(), "");
        }
        InsertionRows { table, log }
    }
}

impl Observer<i64> for InsertionRows<'_> {
    fn step(&mut self, v: &[i64], step: Step<'_>) {
        if let Step::Inserted { k, .. } = step {
            let made: Vec<String> = self.log.borrow_mut().drain(..).map(relation).collect();
            let reason = match made.split_last() {
                Some((last, [])) => format!("since {last}"),
                Some((last, rest)) => format!("since {} and {last}", rest.join(", ")),
                None => String::new(),
            };
            self.table.push(list(&v[..=k]), reason);
        }
    }
}

/// One bisection step: the run searched, split before `mid`.
struct Probe {
    left: Vec<i64>,
    right: Vec<i64>,
}

struct BisectionRows<'l> {
    log: &'l RefCell<Vec<(i64, i64, Ordering)>>,
    lines: Vec<String>,
    probes: Vec<Probe>,
}

impl<'l> BisectionRows<'l> {
    fn new(log: &'l RefCell<Vec<(i64, i64, Ordering)>>) -> Self {
        BisectionRows {
            log,
            lines: Vec::new(),
            probes: Vec::new(),
        }
    }

    fn finish(self, v: &[i64], out: &mut String) {
        for line in &self.lines {
            out.push_str(line);
            out.push('\n');
        }
        if !self.lines.is_empty() {
            out.push('\n');
        }
        let _ = writeln!(out, "{}", set(v));
    }
}

impl Observer<i64> for BisectionRows<'_> {
    fn step(&mut self, v: &[i64], step: Step<'_>) {
        match step {
            Step::Probe { k, lo, mid, hi } => {
                if self.probes.is_empty() {
                    if k > 1 {
                        self.lines.push(String::new());
                    }
                    self.lines.push(set(&v[..k]));
                }
                self.probes.push(Probe {
                    left: v[lo..mid].to_vec(),
                    right: v[mid..hi].to_vec(),
                });
            }
            Step::Inserted { pos, .. } => {
                let x = v[pos];
                let made: Vec<(i64, i64, Ordering)> = self.log.borrow_mut().drain(..).collect();
                let run = |p: &Probe| {
                    if p.left.is_empty() {
                        format!("{x} ↦ {} :", set(&p.right))
                    } else {
                        let left = set(&p.left);
                        let right = set(&p.right);
                        // "{3, 5}" and "{7}" become "{3, 5 | 7}".
                        format!("{x} ↦ {} | {} :", &left[..left.len() - 1], &right[1..])
                    }
                };
                self.lines.push(run(&self.probes[0]));
                for (depth, &c) in made.iter().enumerate() {
                    let next = match self.probes.get(depth + 1) {
                        Some(p) => run(p),
                        None => {
                            let e = c.1;
                            if c.2 == Ordering::Less {
                                set(&[x, e])
                            } else {
                                set(&[e, x])
                            }
                        }
                    };
                    let indent = "    ".repeat(depth + 1);
                    self.lines.push(format!("{indent}{} ⇒ {next}", relation(c)));
                }
                self.probes.clear();
            }
            _ => {}
        }
    }
}

#[derive(Default)]
struct MergeRows {
    table: Table,
    left: Vec<i64>,
    right: Vec<i64>,
}

impl MergeRows {
    fn finish(mut self, v: &[i64], out: &mut String) {
        self.table.push("Final order:", list(v));
        self.table.render(out);
    }
}

impl Observer<i64> for MergeRows {
    fn step(&mut self, v: &[i64], step: Step<'_>) {
        match step {
            Step::Merging { left, right } => {
                self.left = left.iter().map(|&p| v[p]).collect();
                self.right = right.iter().map(|&p| v[p]).collect();
            }
            Step::Merged { run } => {
                let merged: Vec<i64> = run.iter().map(|&p| v[p]).collect();
                self.table.push(
                    format!("Merge {} + {}", set(&self.left), set(&self.right)),
                    format!("→ {}", set(&merged)),
                );
            }
            _ => {}
        }
    }
}
