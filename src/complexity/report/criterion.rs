//! Growth charts from criterion's own measurements.
//!
//! criterion 0.8 saves each benchmark `BenchmarkId::new(function, n)` of group `group` under
//! `DIR/<group>/<function>/<n>/new/`, where `benchmark.json` holds the unsanitised
//! `group_id`, `function_id` and `value_str`, and `estimates.json` holds the statistics of one
//! iteration in nanoseconds (`median.point_estimate`, `mean.point_estimate`, ...). The import
//! takes the median (robust to outliers; the mean when there is no median), reads n from
//! `value_str` (else the throughput's element count, else the directory name) and groups the
//! sizes of one `group/function` into one series.

use std::io;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use serde_json::Value;

use super::{bare_exponent, write_rows, Point, Row};
use crate::complexity::{fit, Bound, Info, Machine, Observation, TIME_TOLERANCE};
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
                match import
                    .benchmarks
                    .iter_mut()
                    .find(|b| b.group == group && b.function == function)
                {
                    Some(b) => b.samples.push((n, ns)),
                    None => import.benchmarks.push(CriterionBenchmark {
                        group,
                        function,
                        samples: vec![(n, ns)],
                    }),
                }
            }
            Err(reason) => import.skipped.push((new_dir, reason)),
        }
    }
    for b in &mut import.benchmarks {
        b.samples.sort_by_key(|s| s.0);
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
    let rows: Vec<Row> = import
        .benchmarks
        .iter()
        .map(|b| {
            let id = b.id();
            let matched = b.matching(catalog);
            let bound = user
                .iter()
                .find(|u| id.contains(&u.pattern))
                .map(|u| u.bound)
                .or(matched.map(|i| i.bound));
            let points: Vec<Point> = b
                .samples
                .iter()
                .map(|&(n, ns)| Point {
                    n,
                    h: None,
                    m: None,
                    time_ns: ns,
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
            Row {
                problem: b.group.clone(),
                input: matched
                    .filter(|i| b.names_input(&i.input))
                    .map(|i| i.input.clone()),
                bound,
                operation: None,
                bare_time_exponent: bare_exponent(&points),
                points,
                counts_fit: None,
                time_fit,
                key: id.clone(),
                id,
            }
        })
        .collect();
    write_rows(out, machine, "criterion", &rows)
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
