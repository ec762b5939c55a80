//! `results.json`: the machine-readable report. Its shape is a contract documented in
//! `docs/complexity.md`; keys are only ever added, never renamed or removed.

use std::io;

use serde::Serialize;

use super::Row;
use crate::complexity::{Machine, COUNT_TOLERANCE, TIME_TOLERANCE};
use crate::count::Counts;

#[derive(Serialize)]
struct Results<'a> {
    machine: MachineJson<'a>,
    profile: &'a str,
    tolerances: Tolerances,
    verdict_counts: VerdictCounts,
    measured_algorithms: usize,
    algorithms: Vec<Algorithm<'a>>,
}

/// How many distinct algorithms `rows` measure with exact counts (compgeo's own; an algorithm
/// measured on several inputs or in several growths counts once).
pub(crate) fn measured_algorithms(rows: &[Row]) -> usize {
    let ids: std::collections::HashSet<&str> = rows
        .iter()
        .filter(|r| !r.peer && r.counts_fit.is_some())
        .map(|r| r.id.as_str())
        .collect();
    ids.len()
}

/// How many rows got each verdict of counts (rows without counts have none).
#[derive(Serialize, Default)]
pub(crate) struct VerdictCounts {
    pub consistent: usize,
    pub exceeds: usize,
    pub none: usize,
}

impl VerdictCounts {
    /// The tally of `rows`.
    pub(crate) fn of<'r>(rows: impl IntoIterator<Item = &'r Row>) -> VerdictCounts {
        let mut tally = VerdictCounts::default();
        for r in rows {
            match r.counts_fit.as_ref().map(|f| f.verdict) {
                Some(crate::complexity::Verdict::Consistent) => tally.consistent += 1,
                Some(crate::complexity::Verdict::Exceeds) => tally.exceeds += 1,
                None => tally.none += 1,
            }
        }
        tally
    }
}

#[derive(Serialize)]
struct MachineJson<'a> {
    cores: usize,
    os: &'a str,
    arch: &'a str,
    cpu: Option<&'a str>,
    compgeo_version: &'a str,
    build: &'a str,
}

#[derive(Serialize)]
struct Tolerances {
    counts: f64,
    time: f64,
}

#[derive(Serialize)]
struct Algorithm<'a> {
    id: &'a str,
    problem: &'a str,
    module: &'a str,
    role: &'static str,
    bound: Option<String>,
    input: Option<&'a str>,
    operation: Option<&'static str>,
    exponent_counts: Option<f64>,
    exponent_time: Option<f64>,
    exponent_time_interval: Option<[f64; 2]>,
    exponent_bound: Option<f64>,
    excess_counts: Option<f64>,
    excess_time: Option<f64>,
    verdict: Option<&'static str>,
    verdict_time: Option<&'static str>,
    samples: Vec<Sample<'a>>,
}

#[derive(Serialize)]
struct Sample<'a> {
    n: usize,
    m: Option<usize>,
    h: Option<usize>,
    time_ns: f64,
    time_repeats_ns: &'a [f64],
    ratio_to_compgeo: Option<f64>,
    counts: Option<&'a Counts>,
}

/// The text of `results.json` for `rows`.
pub(crate) fn results_json(machine: &Machine, profile: &str, rows: &[Row]) -> io::Result<String> {
    let results = Results {
        machine: MachineJson {
            cores: machine.cores,
            os: &machine.os,
            arch: &machine.arch,
            cpu: machine.cpu.as_deref(),
            compgeo_version: &machine.compgeo_version,
            build: &machine.build,
        },
        profile,
        tolerances: Tolerances {
            counts: COUNT_TOLERANCE,
            time: TIME_TOLERANCE,
        },
        verdict_counts: VerdictCounts::of(rows),
        measured_algorithms: measured_algorithms(rows),
        algorithms: rows.iter().map(algorithm).collect(),
    };
    serde_json::to_string_pretty(&results).map_err(io::Error::other)
}

fn algorithm(row: &Row) -> Algorithm<'_> {
    let counts = row.counts_fit.as_ref();
    let time = row.time_fit.as_ref();
    Algorithm {
        id: &row.id,
        problem: &row.problem,
        module: &row.module,
        role: if row.peer { "peer" } else { "compgeo" },
        bound: row.bound.map(|b| b.to_string()),
        input: row.input.as_deref(),
        operation: row.operation.map(|o| o.name()),
        exponent_counts: counts.map(|f| f.exponent),
        exponent_time: row.time_exponent(),
        exponent_time_interval: row.time_interval.map(|(lo, hi)| [lo, hi]),
        exponent_bound: counts.or(time).map(|f| f.bound_exponent),
        excess_counts: counts.map(|f| f.excess),
        excess_time: time.map(|f| f.excess),
        verdict: counts.map(|f| f.verdict.name()),
        verdict_time: time.map(|f| f.verdict.name()),
        samples: row
            .points
            .iter()
            .map(|p| Sample {
                n: p.n,
                m: p.m,
                h: p.h,
                time_ns: p.time_ns,
                time_repeats_ns: &p.time_repeats_ns,
                ratio_to_compgeo: p.ratio_to_compgeo,
                counts: p.counts.as_ref(),
            })
            .collect(),
    }
}
