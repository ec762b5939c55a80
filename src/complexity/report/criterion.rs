//! Growth charts from criterion's own measurements.
//!
//! criterion 0.8 saves each benchmark `BenchmarkId::new(function, n)` of group `group` under
//! `DIR/<group>/<function>/<n>/new/`, where `benchmark.json` holds the unsanitised
//! `group_id`, `function_id` and `value_str`, and `estimates.json` holds the statistics of one
//! iteration in nanoseconds (`median.point_estimate`, `mean.point_estimate`, ...). The import
//! takes the median (robust to outliers; the mean when there is no median), reads n from
//! `value_str` (else the throughput's element count, else the directory name) and groups the
//! sizes of one `group/function` into one series. `sample.json` next to it holds criterion's
//! repetitions (`times[i] / iters[i]` nanoseconds per iteration), from which the report
//! bootstraps an interval for the exponent of time.
//!
//! Benchmarks of peer crates ([`PEERS`]) measured in the same group as compgeo's are drawn
//! on the group's chart with their exponents, and every size gets the ratio of compgeo's
//! fastest time in the group to the peer's time.

use std::io;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use serde_json::Value;

use super::{bare_exponent, module_of, write_rows, Point, Row};
use crate::complexity::{
    exponent_interval, fit, Bound, Info, Machine, Observation, TIME_TOLERANCE,
};
use crate::error::Error;

/// One criterion benchmark function measured at several sizes.
#[derive(Debug, Clone, PartialEq)]
pub struct CriterionBenchmark {
    /// criterion's group id, e.g. `"sort"`.
    pub group: String,
    /// criterion's function id, e.g. `"bubble"` (none for `bench_with_input` on a group).
    pub function: Option<String>,
    /// `(n, nanoseconds per iteration)`, increasing n.
    pub samples: Vec<(usize, f64)>,
    /// criterion's repetitions at each size of `samples` (nanoseconds per iteration of
    /// each sample), empty where `sample.json` is missing.
    pub repeats: Vec<Vec<f64>>,
}

/// Benchmark function names that measure a peer crate rather than compgeo: a function id
/// that starts with one of these, followed by nothing or a non-alphanumeric character
/// (`spade-bulk-load`, `geo-convex-hull`, `truck_subs`, `spade+petgraph-kruskal`), is a peer.
pub const PEERS: [&str; 18] = [
    "curvo",
    "delaunator",
    "geo",
    "glam",
    "kiddo",
    "kurbo",
    "lyon",
    "lyon_geom",
    "nalgebra",
    "ndarray",
    "opensubdiv",
    "petgraph",
    "robust",
    "rstar",
    "spade",
    "splines",
    "std",
    "truck",
];

/// Whether the benchmark function `function` measures a peer crate (see [`PEERS`]).
pub fn is_peer(function: &str) -> bool {
    PEERS.iter().any(|p| {
        function.strip_prefix(p).is_some_and(|rest| {
            rest.chars()
                .next()
                .is_none_or(|c| !c.is_ascii_alphanumeric())
        })
    })
}

/// What [`read_criterion`] found.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CriterionImport {
    /// Benchmarks with at least one numeric size, sorted by id.
    pub benchmarks: Vec<CriterionBenchmark>,
    /// Measurement directories that could not be used, with the reason (no numeric size,
    /// unreadable JSON, no point estimate).
    pub skipped: Vec<(PathBuf, String)>,
}

/// A bound given by the user for benchmarks whose id contains `pattern`
/// (command line: `--bound 'sort/std=O(n log n)'`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UserBound {
    /// Substring of the benchmark id (`group/function`).
    pub pattern: String,
    /// The bound to draw and judge against.
    pub bound: Bound,
}

/// Reads every `new/estimates.json` under `dir` (criterion's output directory, usually
/// `target/criterion`), skipping criterion's own `report` directories.
///
/// # Errors
///
/// I/O errors reading `dir` itself or its subdirectories; a `NotFound` error when `dir` does
/// not exist. Unusable measurements are listed in [`CriterionImport::skipped`], not errors.
pub fn read_criterion(dir: &Path) -> io::Result<CriterionImport> {
    if !dir.is_dir() {
        return Err(io::Error::new(
            io::ErrorKind::NotFound,
            format!("{} is not a directory", dir.display()),
        ));
    }
    let mut found = Vec::new();
    find_new_dirs(dir, &mut found)?;
    found.sort();
    let mut import = CriterionImport::default();
    for new_dir in found {
        match read_one(dir, &new_dir) {
            Ok((group, function, n, ns)) => {
                let repeats = read_repeats(&new_dir);
                match import
                    .benchmarks
                    .iter_mut()
                    .find(|b| b.group == group && b.function == function)
                {
                    Some(b) => {
                        b.samples.push((n, ns));
                        b.repeats.push(repeats);
                    }
                    None => import.benchmarks.push(CriterionBenchmark {
                        group,
                        function,
                        samples: vec![(n, ns)],
                        repeats: vec![repeats],
                    }),
                }
            }
            Err(reason) => import.skipped.push((new_dir, reason)),
        }
    }
    for b in &mut import.benchmarks {
        let mut both: Vec<((usize, f64), Vec<f64>)> = b
            .samples
            .drain(..)
            .zip(std::mem::take(&mut b.repeats))
            .collect();
        both.sort_by_key(|s| s.0 .0);
        (b.samples, b.repeats) = both.into_iter().unzip();
    }
    import.benchmarks.sort_by_key(CriterionBenchmark::id);
    Ok(import)
}

/// Writes the report of criterion measurements into `out` (charts of time against n, the
/// summary table and `results.json` with `"profile": "criterion"`); returns the path of
/// `index.html`.
///
/// Each benchmark gets its bound from the first matching [`UserBound`], else from the
/// catalog entry it matches (see [`CriterionBenchmark::matching`]), else none: then it is
/// plotted without a bound line and without a verdict. A time verdict needs
/// [`MIN_SIZES`](crate::complexity::MIN_SIZES) sizes and a bound in n alone (criterion knows no h or m).
///
/// # Errors
///
/// As [`write_report`](super::write_report).
pub fn write_criterion_report(
    out: &Path,
    machine: &Machine,
    import: &CriterionImport,
    catalog: &[Info],
    user: &[UserBound],
) -> io::Result<PathBuf> {
    let mut rows: Vec<Row> = import
        .benchmarks
        .iter()
        .map(|b| {
            let id = b.id();
            let matched = b.matching(catalog);
            let peer = b.function.as_deref().is_some_and(is_peer);
            let bound = user
                .iter()
                .find(|u| id.contains(&u.pattern))
                .map(|u| u.bound)
                .or(matched.filter(|_| !peer).map(|i| i.bound));
            let points: Vec<Point> = b
                .samples
                .iter()
                .enumerate()
                .map(|(i, &(n, ns))| Point {
                    n,
                    h: None,
                    m: None,
                    time_ns: ns,
                    time_repeats_ns: b.repeats.get(i).cloned().unwrap_or_default(),
                    ratio_to_compgeo: None,
                    counts: None,
                })
                .collect();
            let time_fit = bound.and_then(|bound| {
                let obs: Vec<Observation> = b
                    .samples
                    .iter()
                    .map(|&(n, ns)| Observation {
                        n: n as f64,
                        second: None,
                        cost: ns,
                    })
                    .collect();
                fit(bound, &obs, TIME_TOLERANCE).ok()
            });
            let sizes: Vec<f64> = points.iter().map(|p| p.n as f64).collect();
            let repeats: Vec<Vec<f64>> = points.iter().map(|p| p.time_repeats_ns.clone()).collect();
            let module = match (matched, peer) {
                (Some(i), false) => module_of(&i.id, &i.problem),
                _ => module_of(&id, &b.group),
            };
            Row {
                problem: b.group.clone(),
                module,
                peer,
                input: matched
                    .filter(|i| !peer && b.names_input(&i.input))
                    .map(|i| i.input.clone()),
                bound,
                operation: None,
                bare_time_exponent: bare_exponent(&points),
                time_interval: exponent_interval(&sizes, &repeats),
                points,
                counts_fit: None,
                time_fit,
                key: id.clone(),
                id,
            }
        })
        .collect();
    set_ratios_to_compgeo(&mut rows);
    write_rows(out, machine, "criterion", &rows)
}

/// Sets every peer point's [`Point::ratio_to_compgeo`]: compgeo's fastest time at that size
/// in the same group (over every compgeo row that has the size) over the peer's time.
fn set_ratios_to_compgeo(rows: &mut [Row]) {
    let compgeo: Vec<(String, usize, f64)> = rows
        .iter()
        .filter(|r| !r.peer)
        .flat_map(|r| r.points.iter().map(|p| (r.problem.clone(), p.n, p.time_ns)))
        .collect();
    for row in rows.iter_mut().filter(|r| r.peer) {
        for p in &mut row.points {
            let fastest = compgeo
                .iter()
                .filter(|(g, n, _)| g == &row.problem && *n == p.n)
                .map(|c| c.2)
                .min_by(f64::total_cmp);
            p.ratio_to_compgeo = fastest.map(|t| t / p.time_ns);
        }
    }
}

impl CriterionBenchmark {
    /// `group/function`, or `group` when there is no function id.
    pub fn id(&self) -> String {
        match &self.function {
            Some(f) => format!("{}/{f}", self.group),
            None => self.group.clone(),
        }
    }

    /// The catalog entry this benchmark measures, if any: an entry whose id is the
    /// benchmark's id, or whose algorithm name (after the `/`) is the function id while its
    /// problem starts the group id (groups such as `sort-sorted` or `sort/reversed`). Among
    /// several entries the one whose input the group names (see
    /// [`CriterionBenchmark::names_input`]) wins, else the `random` one, else the first. The
    /// bound of an entry on another input is still the algorithm's bound; the report then
    /// leaves the input empty rather than claim one.
    pub fn matching<'a>(&self, catalog: &'a [Info]) -> Option<&'a Info> {
        let id = self.id();
        let function = self.function.as_deref()?;
        let candidates: Vec<&Info> = catalog
            .iter()
            .filter(|i| {
                i.id == id
                    || (i.id.split('/').nth(1) == Some(function)
                        && self.group.starts_with(&i.problem))
            })
            .collect();
        candidates
            .iter()
            .find(|i| self.names_input(&i.input))
            .or_else(|| candidates.iter().find(|i| i.input == "random"))
            .or(candidates.first())
            .copied()
    }

    /// Whether the group id names `input` after its problem prefix (`sort-few-distinct`
    /// names `few-distinct`; `sort` names nothing).
    pub fn names_input(&self, input: &str) -> bool {
        let rest = self
            .group
            .split_once(|c: char| !c.is_ascii_alphanumeric())
            .map_or("", |(_, rest)| rest);
        !input.is_empty() && rest.contains(input)
    }
}

impl FromStr for UserBound {
    type Err = Error;

    /// Parses `PATTERN=BOUND`, e.g. `sort/std=O(n log n)`.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming `bound` when there is no `=` or the bound is not
    /// one of [`Bound::ALL`].
    fn from_str(text: &str) -> Result<UserBound, Error> {
        let (pattern, bound) = text
            .split_once('=')
            .ok_or_else(|| Error::InvalidParameter {
                name: "bound",
                reason: format!("{text:?} is not PATTERN=BOUND, e.g. 'sort/std=O(n log n)'"),
            })?;
        Ok(UserBound {
            pattern: pattern.to_string(),
            bound: bound.parse()?,
        })
    }
}

fn find_new_dirs(dir: &Path, out: &mut Vec<PathBuf>) -> io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if !path.is_dir() {
            continue;
        }
        match path.file_name().and_then(|n| n.to_str()) {
            Some("report") => {}
            Some("new") if path.join("estimates.json").is_file() => out.push(path),
            _ => find_new_dirs(&path, out)?,
        }
    }
    Ok(())
}

/// `(group, function, n, nanoseconds)` of one `new` directory, or why it is unusable.
fn read_one(root: &Path, new_dir: &Path) -> Result<(String, Option<String>, usize, f64), String> {
    let estimates = read_json(&new_dir.join("estimates.json"))?;
    let ns = ["median", "mean"]
        .iter()
        .find_map(|k| estimates[k]["point_estimate"].as_f64())
        .filter(|v| v.is_finite() && *v > 0.0)
        .ok_or("estimates.json has no positive median or mean point estimate")?;
    let components: Vec<String> = new_dir
        .parent()
        .and_then(|p| p.strip_prefix(root).ok())
        .map(|rel| {
            rel.components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    let bench_file = new_dir.join("benchmark.json");
    let (group, function, value, elements) = if bench_file.is_file() {
        let b = read_json(&bench_file)?;
        let group = b["group_id"]
            .as_str()
            .ok_or("benchmark.json has no group_id")?
            .to_string();
        let elements = b["throughput"]
            .as_object()
            .and_then(|t| t.get("Elements").or_else(|| t.get("ElementsAndBytes")))
            .and_then(|e| e.as_u64().or_else(|| e["elements"].as_u64()));
        (
            group,
            b["function_id"].as_str().map(str::to_string),
            b["value_str"].as_str().map(str::to_string),
            elements,
        )
    } else {
        match components.as_slice() {
            [group, value] => (group.clone(), None, Some(value.clone()), None),
            [group @ .., function, value] if !group.is_empty() => (
                group.join("/"),
                Some(function.clone()),
                Some(value.clone()),
                None,
            ),
            _ => return Err("cannot tell group and size from the path".to_string()),
        }
    };
    let n = value
        .as_deref()
        .and_then(parse_size)
        .or(elements.and_then(|e| usize::try_from(e).ok()))
        .or_else(|| components.last().and_then(|c| parse_size(c)))
        .ok_or("no numeric input size (value, throughput or directory name)")?;
    Ok((group, function, n, ns))
}

/// criterion's repetitions in `new_dir/sample.json` as nanoseconds per iteration; empty
/// when the file is missing or unreadable (the median alone is still usable).
fn read_repeats(new_dir: &Path) -> Vec<f64> {
    let Ok(sample) = read_json(&new_dir.join("sample.json")) else {
        return Vec::new();
    };
    let numbers = |key: &str| -> Vec<f64> {
        sample[key]
            .as_array()
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default()
    };
    numbers("times")
        .iter()
        .zip(numbers("iters"))
        .filter(|(t, i)| t.is_finite() && i.is_finite() && *i > 0.0)
        .map(|(t, i)| t / i)
        .collect()
}

fn parse_size(text: &str) -> Option<usize> {
    text.trim().parse::<usize>().ok().filter(|&n| n >= 1)
}

fn read_json(path: &Path) -> Result<Value, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Operation;

    fn info(id: &str, input: &str) -> Info {
        Info {
            id: id.to_string(),
            problem: id.split('/').next().unwrap().to_string(),
            input: input.to_string(),
            bound: Bound::Quadratic,
            operation: Operation::Comparisons,
        }
    }

    #[test]
    fn matching_prefers_input_named_in_group_then_random() {
        let cat = [
            info("sort/insertion", "sorted"),
            info("sort/insertion", "random"),
            info("sort/insertion", "reversed"),
            info("sort/bubble", "random"),
        ];
        let bench = |g: &str, f: &str| CriterionBenchmark {
            group: g.to_string(),
            function: Some(f.to_string()),
            samples: vec![],
            repeats: vec![],
        };
        assert_eq!(
            bench("sort", "insertion").matching(&cat).unwrap().input,
            "random"
        );
        assert_eq!(
            bench("sort/reversed", "insertion")
                .matching(&cat)
                .unwrap()
                .input,
            "reversed"
        );
        assert_eq!(
            bench("sort_sorted", "insertion")
                .matching(&cat)
                .unwrap()
                .input,
            "sorted"
        );
        assert_eq!(
            bench("sort", "bubble").matching(&cat).unwrap().id,
            "sort/bubble"
        );
        assert!(bench("sort", "std").matching(&cat).is_none());
        assert!(bench("hull", "bubble").matching(&cat).is_none());
    }

    #[test]
    fn user_bound_parses_pattern_and_bound() {
        let u: UserBound = "sort/std=O(n log n)".parse().unwrap();
        assert_eq!(u.pattern, "sort/std");
        assert_eq!(u.bound, Bound::NLogN);
        assert!("sort/std".parse::<UserBound>().is_err());
        assert!("x=O(n!)".parse::<UserBound>().is_err());
    }

    #[test]
    fn sizes_must_be_positive_integers() {
        assert_eq!(parse_size(" 1024 "), Some(1024));
        assert_eq!(parse_size("0"), None);
        assert_eq!(parse_size("small"), None);
    }
}
