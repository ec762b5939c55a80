//! The report: SVG charts, an HTML page and `results.json` (feature `cli`).
//!
//! [`write_report`] turns the [`Measurement`]s of a run into
//!
//! - `DIR/results.json`, the machine-readable results (shape in `docs/complexity.md`);
//! - one SVG per entry (`sort-bubble-random.svg`): log-log counts and time against the stated
//!   bound, scaled to pass through the counts at the median size;
//! - one SVG per problem (`problem-sort.svg`): its entries' times and counts side by side;
//! - `DIR/index.html`: the machine, the summary table and every chart;
//! - `DIR/gallery.html` and `DIR/gallery/`: a picture per geometric problem and the step
//!   pages of the traced algorithms, on small seeded workloads.
//!
//! [`read_criterion`] and [`write_criterion_report`] draw the same growth charts from the
//! estimates that criterion saved under `target/criterion`.

mod chart;
mod criterion;
mod gallery;
mod html;
mod json;

use std::io;
use std::path::{Path, PathBuf};

use crate::complexity::catalog::file_stem;
use crate::complexity::{slope, Bound, Fit, Machine, Measurement, Profile};
use crate::count::{Counts, Operation};

pub use criterion::{
    is_peer, read_criterion, write_criterion_report, CriterionBenchmark, CriterionImport,
    UserBound, PEERS,
};

/// Writes the report of `measurements` (run under `profile` on `machine`) into `dir`,
/// creating it if needed, and returns the path of `index.html`.
///
/// # Errors
///
/// I/O errors creating the directory or writing a file (chart errors are reported as I/O
/// errors naming the chart).
///
/// # Complexity
///
/// O(total samples) time plus the rendering of one chart per entry and per problem.
pub fn write_report(
    dir: &Path,
    machine: &Machine,
    profile: Profile,
    measurements: &[Measurement],
) -> io::Result<PathBuf> {
    let rows: Vec<Row> = measurements.iter().map(Row::from_measurement).collect();
    write_rows(dir, machine, profile.name(), &rows)
}

/// One chart-and-table row: an entry measured by the engine, or a benchmark imported from
/// criterion (then without counts, and with a bound only if one was matched or given).
#[derive(Debug, Clone)]
pub(crate) struct Row {
    /// Unique among rows: `id/input` for measured entries, the benchmark id for criterion.
    pub key: String,
    pub id: String,
    pub problem: String,
    /// The crate module the algorithm lives in (`hull`, `spline`, ...), see [`module_of`].
    pub module: String,
    /// Whether the row measures a peer crate rather than compgeo (criterion imports only).
    pub peer: bool,
    pub input: Option<String>,
    pub bound: Option<Bound>,
    pub operation: Option<Operation>,
    pub points: Vec<Point>,
    pub counts_fit: Option<Fit>,
    pub time_fit: Option<Fit>,
    /// Exponent of time when no bound (hence no fit) is available.
    pub bare_time_exponent: Option<f64>,
    /// 95 % bootstrap interval of the exponent of time, from the repetitions.
    pub time_interval: Option<(f64, f64)>,
}

/// One size of a [`Row`].
#[derive(Debug, Clone)]
pub(crate) struct Point {
    pub n: usize,
    pub h: Option<usize>,
    pub m: Option<usize>,
    pub time_ns: f64,
    /// The repeated measurements behind `time_ns` (batch means, criterion samples).
    pub time_repeats_ns: Vec<f64>,
    /// For a peer: compgeo's fastest time at this size in the same group divided by the
    /// peer's time (below 1 when compgeo is faster).
    pub ratio_to_compgeo: Option<f64>,
    pub counts: Option<Counts>,
}

impl Row {
    fn from_measurement(m: &Measurement) -> Row {
        Row {
            key: m.info.key(),
            id: m.info.id.clone(),
            problem: m.info.problem.clone(),
            module: module_of(&m.info.id, &m.info.problem),
            peer: false,
            input: Some(m.info.input.clone()),
            bound: Some(m.info.bound),
            operation: Some(m.info.operation),
            points: m
                .samples
                .iter()
                .map(|s| Point {
                    n: s.n,
                    h: s.h,
                    m: s.m,
                    time_ns: s.time_ns,
                    time_repeats_ns: s.time_repeats_ns.clone(),
                    ratio_to_compgeo: None,
                    counts: Some(s.counts),
                })
                .collect(),
            counts_fit: Some(m.counts.clone()),
            time_fit: Some(m.time.clone()),
            bare_time_exponent: None,
            time_interval: m.time_interval,
        }
    }

    /// File name of the row's chart.
    pub fn chart_file(&self) -> String {
        format!("{}.svg", file_stem(&self.key))
    }

    /// The counted operation's value at each point, if the row has counts.
    pub fn op_counts(&self) -> Option<Vec<f64>> {
        let op = self.operation?;
        self.points
            .iter()
            .map(|p| p.counts.map(|c| c.get(op) as f64))
            .collect()
    }

    /// Exponent of time: from the fit when there is one, else the bare log-log slope.
    pub fn time_exponent(&self) -> Option<f64> {
        self.time_fit
            .as_ref()
            .map(|f| f.exponent)
            .or(self.bare_time_exponent)
    }

    /// The bound's value at each point (with the point's h or m), if there is a bound and
    /// every point has the second size it needs.
    pub fn bound_values(&self) -> Option<Vec<f64>> {
        let bound = self.bound?;
        self.points
            .iter()
            .map(|p| {
                let second = match bound.second_size() {
                    None => None,
                    Some(crate::complexity::SecondSize::Output) => Some(p.h? as f64),
                    Some(crate::complexity::SecondSize::Edges) => Some(p.m? as f64),
                };
                let f = bound.eval(p.n as f64, second);
                (f.is_finite() && f > 0.0).then_some(f)
            })
            .collect()
    }
}

/// The crate module of the algorithm `id` (`problem/name`) of `problem`: the first path
/// segment of its declaration's function (`hull::graham_scan` is in `hull`); for an id that
/// is not declared (a criterion benchmark of a peer, say) the module of the declared problem
/// that `problem` starts with, the longest such; else `"other"`.
pub(crate) fn module_of(id: &str, problem: &str) -> String {
    let declared = crate::complexity::declarations();
    let module = |function: &str| function.split("::").next().unwrap_or(function).to_string();
    if let Some(d) = declared.iter().find(|d| d.id() == id) {
        return module(d.function);
    }
    declared
        .iter()
        .filter(|d| problem.starts_with(d.problem))
        .max_by_key(|d| d.problem.len())
        .map_or_else(|| "other".to_string(), |d| module(d.function))
}

/// File name of a problem's comparison chart.
pub(crate) fn problem_chart_file(problem: &str) -> String {
    format!("problem-{}.svg", file_stem(problem))
}

/// The log-log slope of time against n, for rows without a fit.
pub(crate) fn bare_exponent(points: &[Point]) -> Option<f64> {
    let xs: Vec<f64> = points.iter().map(|p| (p.n as f64).ln()).collect();
    let ys: Vec<f64> = points.iter().map(|p| p.time_ns.max(1.0).ln()).collect();
    let s = slope(&xs, &ys);
    s.is_finite().then_some(s)
}

/// Writes JSON, charts and HTML for `rows`; returns the path of `index.html`.
pub(crate) fn write_rows(
    dir: &Path,
    machine: &Machine,
    profile: &str,
    rows: &[Row],
) -> io::Result<PathBuf> {
    std::fs::create_dir_all(dir)?;
    std::fs::write(
        dir.join("results.json"),
        json::results_json(machine, profile, rows)?,
    )?;
    for row in rows {
        chart::growth_chart(&dir.join(row.chart_file()), row)?;
    }
    let problems = problems(rows);
    for problem in &problems {
        let members: Vec<&Row> = rows.iter().filter(|r| &r.problem == problem).collect();
        chart::problem_chart(&dir.join(problem_chart_file(problem)), problem, &members)?;
    }
    gallery::write_gallery(dir)?;
    let index = dir.join("index.html");
    std::fs::write(&index, html::index_html(machine, profile, rows, &problems))?;
    Ok(index)
}

/// Problems in order of first appearance.
fn problems(rows: &[Row]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for r in rows {
        if !out.contains(&r.problem) {
            out.push(r.problem.clone());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::module_of;

    #[test]
    fn module_of_reads_the_declared_function() {
        assert_eq!(module_of("hull/graham", "hull"), "hull");
        assert_eq!(module_of("sort/bubble", "sort"), "sort");
        // Not declared: the module of the declared problem the group starts with.
        assert_eq!(
            module_of("delaunay/uniform/spade-bulk-load", "delaunay/uniform"),
            "delaunay"
        );
        assert_eq!(module_of("scan/prefix", "scan"), "other");
    }
}
