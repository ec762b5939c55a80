//! `compgeo report`: measure every catalog entry and write the HTML/SVG/JSON report, or draw
//! the same charts from criterion's measurements. See `docs/complexity.md`.

use super::output::print_json;
use super::CliError;
use crate::complexity::report::{
    read_criterion, write_criterion_report, write_report, CriterionImport, UserBound,
};
use crate::complexity::{
    catalog, measure, Entry, Machine, Measurement, Profile, Settings, Verdict,
};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::io;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `compgeo report`.
#[derive(Debug, Args)]
pub(super) struct ReportArgs {
    /// Quick profile: small sizes, the whole catalog in a few minutes (the default)
    #[arg(long, conflicts_with = "full")]
    quick: bool,
    /// Full profile: larger sizes and more repetitions
    #[arg(long)]
    full: bool,
    /// Directory to write index.html, results.json and the SVG charts into
    #[arg(long, value_name = "DIR", default_value = "report")]
    out: PathBuf,
    /// Measure only the entries whose key (id/input, e.g. sort/insertion/sorted) contains PATTERN
    #[arg(long, value_name = "PATTERN")]
    only: Option<String>,
    /// Seed of the generated inputs
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Draw the charts from criterion's measurements under DIR (e.g. target/criterion) instead of measuring
    #[arg(long, value_name = "DIR", conflicts_with_all = ["quick", "full", "only"])]
    criterion: Option<PathBuf>,
    /// With --criterion: judge benchmarks whose id contains PATTERN against BOUND, e.g. 'sort/std=O(n log n)' (repeatable)
    #[arg(long, value_name = "PATTERN=BOUND", requires = "criterion", value_parser = parse_user_bound)]
    bound: Vec<UserBound>,
}

/// What `compgeo report` prints on stdout: where it wrote and how the verdicts came out.
#[derive(Debug, Serialize)]
struct Written {
    index: PathBuf,
    results: PathBuf,
    profile: String,
    /// Rows written: one per catalog entry (or criterion benchmark), as `results.json`'s
    /// `algorithms` array.
    algorithms: usize,
    /// Distinct algorithms among them measured with exact counts (`measured_algorithms`).
    measured_algorithms: usize,
    exceeds: Vec<String>,
    seconds: f64,
}

/// Runs `compgeo report`.
pub(super) fn run(args: ReportArgs) -> Result<(), CliError> {
    let start = Instant::now();
    let machine = Machine::current();
    let written = match &args.criterion {
        Some(dir) => from_criterion(dir, &args, &machine)?,
        None => measured(&args, &machine)?,
    };
    let written = Written {
        seconds: start.elapsed().as_secs_f64(),
        ..written
    };
    eprintln!(
        "wrote {} ({} entries measuring {} algorithms, {} exceeding their bound, {:.1} s)",
        written.index.display(),
        written.algorithms,
        written.measured_algorithms,
        written.exceeds.len(),
        written.seconds
    );
    print_json(&written)
}

fn measured(args: &ReportArgs, machine: &Machine) -> Result<Written, CliError> {
    let profile = if args.full {
        Profile::Full
    } else {
        Profile::Quick
    };
    let pattern = args.only.as_deref().unwrap_or("");
    let entries: Vec<Entry> = catalog()
        .into_iter()
        .filter(|e| e.matches(pattern))
        .collect();
    if entries.is_empty() {
        return Err(CliError::Usage(format!(
            "no catalog entry matches {pattern:?}; keys look like sort/insertion/sorted"
        )));
    }
    prepare_out(&args.out)?;
    let settings = Settings {
        seed: args.seed,
        ..Settings::for_profile(profile)
    };
    let total: usize = entries.iter().map(|e| e.sizes(profile).len()).sum();
    let bar = ProgressBar::new(total as u64);
    if let Ok(style) =
        ProgressStyle::with_template("{elapsed_precise} {wide_bar} {pos}/{len} {msg}")
    {
        bar.set_style(style);
    }
    let mut results: Vec<Measurement> = Vec::with_capacity(entries.len());
    for entry in &entries {
        let key = entry.info.key();
        let m = measure(entry, &entry.sizes(profile), &settings, &mut |p| {
            bar.set_message(format!("{key} n = {}", p.n));
            bar.inc(1);
        })
        .map_err(|e| CliError::Usage(format!("measuring {key}: {e}")))?;
        results.push(m);
    }
    bar.finish_and_clear();
    let index = write_report(&args.out, machine, profile, &results)
        .map_err(|e| write_error(&args.out, e))?;
    let exceeds = results
        .iter()
        .filter(|m| m.counts.verdict == Verdict::Exceeds)
        .map(|m| m.info.key())
        .collect();
    let written = written(&args.out, index, profile.name(), results.len(), exceeds);
    Ok(Written {
        measured_algorithms: results
            .iter()
            .map(|m| m.info.id.as_str())
            .collect::<std::collections::HashSet<_>>()
            .len(),
        ..written
    })
}

fn from_criterion(dir: &Path, args: &ReportArgs, machine: &Machine) -> Result<Written, CliError> {
    let import: CriterionImport = read_criterion(dir).map_err(|source| CliError::Read {
        path: dir.display().to_string(),
        source,
    })?;
    for (path, reason) in &import.skipped {
        eprintln!("skipped {}: {reason}", path.display());
    }
    if import.benchmarks.is_empty() {
        return Err(CliError::Usage(format!(
            "no criterion measurements with a numeric size under {}",
            dir.display()
        )));
    }
    prepare_out(&args.out)?;
    let infos: Vec<_> = catalog().into_iter().map(|e| e.info).collect();
    let index = write_criterion_report(&args.out, machine, &import, &infos, &args.bound)
        .map_err(|e| write_error(&args.out, e))?;
    Ok(written(
        &args.out,
        index,
        "criterion",
        import.benchmarks.len(),
        Vec::new(),
    ))
}

fn written(
    out: &Path,
    index: PathBuf,
    profile: &str,
    algorithms: usize,
    exceeds: Vec<String>,
) -> Written {
    Written {
        index,
        results: out.join("results.json"),
        profile: profile.to_string(),
        algorithms,
        measured_algorithms: 0,
        exceeds,
        seconds: 0.0,
    }
}

/// Makes sure the report can be written into `dir` before anything is measured: `dir` is
/// (or is created as) a directory in which a file can be created, and its `index.html` and
/// `results.json` are not directories. A report takes minutes; a typo in `--out` should not
/// cost them.
fn prepare_out(dir: &Path) -> Result<(), CliError> {
    let fail = |path: &Path, source| CliError::Write {
        path: format!("'{}'", path.display()),
        source,
    };
    if dir.exists() && !dir.is_dir() {
        return Err(fail(
            dir,
            io::Error::new(
                io::ErrorKind::AlreadyExists,
                "it exists and is not a directory",
            ),
        ));
    }
    std::fs::create_dir_all(dir).map_err(|e| fail(dir, e))?;
    for name in ["index.html", "results.json"] {
        let file = dir.join(name);
        if file.is_dir() {
            return Err(fail(
                &file,
                io::Error::new(io::ErrorKind::IsADirectory, "it is a directory"),
            ));
        }
    }
    // The probe proves the directory is writable (permissions, a read-only file system).
    let probe = dir.join(format!(".compgeo-report-probe-{}", std::process::id()));
    std::fs::File::create(&probe).map_err(|e| fail(dir, e))?;
    // The probe was created a moment ago; failing to remove it changes nothing above.
    let _ = std::fs::remove_file(&probe);
    Ok(())
}

/// A failure to write the report, naming its directory.
fn write_error(dir: &Path, source: io::Error) -> CliError {
    CliError::Write {
        path: format!("the report in '{}'", dir.display()),
        source,
    }
}

fn parse_user_bound(text: &str) -> Result<UserBound, String> {
    text.parse().map_err(|e: crate::Error| e.to_string())
}
