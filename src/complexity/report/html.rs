//! `index.html`: machine, summary table and charts, in one self-contained page that refers
//! to the SVG files next to it.

use std::fmt::Write;

use super::json::{measured_algorithms, VerdictCounts};
use super::{problem_chart_file, Row};
use crate::complexity::{Machine, COUNT_TOLERANCE, TIME_TOLERANCE};

const STYLE: &str =
    "body{font-family:sans-serif;max-width:1700px;margin:1em auto;padding:0 1em;color:#222}\
table{border-collapse:collapse;margin:1em 0}\
th,td{border:1px solid #bbb;padding:.25em .6em;text-align:left}\
td.num{text-align:right;font-variant-numeric:tabular-nums}\
tr.exceeds td{background:#fde2dc}\
tr.module th{background:#eef2f8;font-size:1.05em}\
tr.peer td{color:#555;font-style:italic}\
img{max-width:100%;border:1px solid #ddd;margin:.5em 0}\
figure{display:inline-block;margin:.5em}";

/// The page for `rows`, grouped by `problems` (in that order).
pub(crate) fn index_html(
    machine: &Machine,
    profile: &str,
    rows: &[Row],
    problems: &[String],
) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>compgeo complexity report</title>\n<style>{STYLE}</style>\n</head>\n<body>\n\
         <h1>compgeo complexity report</h1>\n<p><a href=\"gallery.html\">Gallery</a>: a \
         picture of every geometric problem and the algorithms of the course step by step.</p>\n"
    );
    let _ = write!(
        h,
        "<h2>Machine</h2>\n<table>\n<tr><th>cores</th><td>{}</td></tr>\n\
         <tr><th>os / arch</th><td>{} / {}</td></tr>\n<tr><th>cpu</th><td>{}</td></tr>\n\
         <tr><th>compgeo</th><td>{} ({} build)</td></tr>\n<tr><th>profile</th><td>{}</td></tr>\n</table>\n",
        machine.cores,
        esc(&machine.os),
        esc(&machine.arch),
        esc(machine.cpu.as_deref().unwrap_or("unknown")),
        esc(&machine.compgeo_version),
        esc(&machine.build),
        esc(profile),
    );
    let all = VerdictCounts::of(rows);
    let _ = write!(
        h,
        "<h2>Summary</h2>\n<p>Algorithms measured with exact counts: {1}. Rows: {0}, <strong>{2} consistent</strong>, <strong>{3} exceeds</strong>, \
         {4} without counts (criterion imports and peers). Exponents are least-squares slopes of \
         log cost against log n; the exponent of time carries a 95 % interval bootstrapped from \
         the repetitions at each size (counts are exact, one run per size, and need none). \
         The bound column gives the slope of log f(n) over the same sizes. The verdict compares \
         exact counts with the stated bound: <em>exceeds</em> when cost / f(n) grows faster \
         than n<sup>{COUNT_TOLERANCE}</sup> (time: n<sup>{TIME_TOLERANCE}</sup>). \
         The exact fallbacks are the predicate calls, at the largest size, that the \
         floating-point filter could not decide, with their share of the counted operation. \
         See <code>docs/complexity.md</code>.</p>\n<table>\n<tr><th>algorithm</th>\
         <th>problem</th><th>input</th><th>stated bound</th><th>counted operation</th>\
         <th>exponent of counts</th><th>exponent of bound</th><th>exponent of time (95 %)</th>\
         <th>verdict</th><th>time verdict</th><th>exact fallbacks</th></tr>\n",
        rows.len(),
        measured_algorithms(rows),
        all.consistent,
        all.exceeds,
        all.none,
    );
    for module in modules(rows) {
        let members: Vec<&Row> = rows.iter().filter(|r| r.module == module).collect();
        let tally = VerdictCounts::of(members.iter().copied());
        let _ = writeln!(
            h,
            "<tr class=\"module\"><th colspan=\"11\">{} &mdash; {} {}: {} consistent, {} exceeds{}</th></tr>",
            esc(&module),
            members.len(),
            if members.len() == 1 { "row" } else { "rows" },
            tally.consistent,
            tally.exceeds,
            if tally.none > 0 {
                format!(", {} without counts", tally.none)
            } else {
                String::new()
            },
        );
        for r in members {
            summary_row(&mut h, r);
        }
    }
    h.push_str("</table>\n");
    for problem in problems {
        let _ = write!(
            h,
            "<h2>{p}</h2>\n<img src=\"{f}\" alt=\"{p}: all algorithms\">\n<div>\n",
            p = esc(problem),
            f = esc(&problem_chart_file(problem)),
        );
        ratio_table(&mut h, rows.iter().filter(|r| &r.problem == problem));
        for r in rows.iter().filter(|r| &r.problem == problem) {
            let _ = writeln!(
                h,
                "<figure id=\"{k}\"><img src=\"{f}\" alt=\"{k}\" width=\"820\"></figure>",
                k = esc(&r.key.clone()),
                f = esc(&r.chart_file()),
            );
        }
        h.push_str("</div>\n");
    }
    h.push_str("</body>\n</html>\n");
    h
}

/// The exact fallbacks at the largest size, with their share of the counted operation when
/// there are any: `"0"`, `"5 (0.03 %)"`; `"-"` without counts.
fn fallbacks(r: &Row) -> String {
    let Some(counts) = r.points.last().and_then(|p| p.counts) else {
        return "-".to_string();
    };
    let k = counts.exact_fallbacks;
    match r.operation.map(|op| counts.get(op)) {
        Some(total) if k > 0 && total > 0 => {
            format!("{k} ({:.2} %)", 100.0 * k as f64 / total as f64)
        }
        _ => k.to_string(),
    }
}

/// One row of the summary table.
fn summary_row(h: &mut String, r: &Row) {
    let counts = r.counts_fit.as_ref();
    let time = r.time_fit.as_ref();
    let verdict = counts.map(|f| f.verdict.name());
    let class = if r.peer {
        "peer"
    } else {
        verdict.unwrap_or("")
    };
    let time_exponent = match (r.time_exponent(), r.time_interval) {
        (Some(e), Some((lo, hi))) => format!("{e:.2} ({lo:.2}&ndash;{hi:.2})"),
        (e, _) => num(e),
    };
    let _ = writeln!(
        h,
        "<tr class=\"{class}\"><td><a href=\"#{}\">{}</a>{}</td><td>{}</td><td>{}</td><td>{}</td>\
         <td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>\
         <td>{}</td><td>{}</td><td class=\"num\">{}</td></tr>",
        esc(&r.key),
        esc(&r.id),
        if r.peer { " (peer)" } else { "" },
        esc(&r.problem),
        esc(r.input.as_deref().unwrap_or("")),
        r.bound.map(|b| esc(b.as_str())).unwrap_or_default(),
        r.operation.map_or("", |o| o.name()),
        num(counts.map(|f| f.exponent)),
        num(counts.or(time).map(|f| f.bound_exponent)),
        time_exponent,
        verdict.unwrap_or("-"),
        time.map_or("-", |f| f.verdict.name()),
        fallbacks(r),
    );
}

/// For a problem with peers: one line per size with compgeo's fastest time and each peer's
/// ratio (compgeo's time over the peer's: below 1 when compgeo is faster).
fn ratio_table<'r>(h: &mut String, members: impl Iterator<Item = &'r Row>) {
    let members: Vec<&Row> = members.collect();
    let peers: Vec<&Row> = members.iter().copied().filter(|r| r.peer).collect();
    let compgeo: Vec<&Row> = members.iter().copied().filter(|r| !r.peer).collect();
    if peers.is_empty() || compgeo.is_empty() {
        return;
    }
    let mut sizes: Vec<usize> = members
        .iter()
        .flat_map(|r| r.points.iter().map(|p| p.n))
        .collect();
    sizes.sort_unstable();
    sizes.dedup();
    h.push_str(
        "<p>compgeo against its peers in the same benchmark group: compgeo's fastest time \
         at each size, and each peer's ratio compgeo / peer (below 1: compgeo is faster).</p>\n\
         <table>\n<tr><th>n</th><th>compgeo fastest</th>",
    );
    for p in &peers {
        let _ = write!(
            h,
            "<th>{} (slope {})</th>",
            esc(&p.id),
            num(p.time_exponent())
        );
    }
    h.push_str("</tr>\n");
    for n in sizes {
        let fastest = compgeo
            .iter()
            .filter_map(|r| r.points.iter().find(|p| p.n == n).map(|p| (r, p.time_ns)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let _ = write!(
            h,
            "<tr><td class=\"num\">{n}</td><td>{}</td>",
            fastest.map_or_else(
                || "-".to_string(),
                |(r, t)| format!("{} ({})", esc(&r.id), duration(t))
            )
        );
        for p in &peers {
            let ratio = p
                .points
                .iter()
                .find(|q| q.n == n)
                .and_then(|q| q.ratio_to_compgeo);
            let _ = write!(
                h,
                "<td class=\"num\">{}</td>",
                ratio.map_or_else(|| "-".to_string(), |x| format!("{x:.2}&times;"))
            );
        }
        h.push_str("</tr>\n");
    }
    h.push_str("</table>\n");
}

/// A time in nanoseconds with a readable unit.
fn duration(ns: f64) -> String {
    if ns >= 1e9 {
        format!("{:.3} s", ns / 1e9)
    } else if ns >= 1e6 {
        format!("{:.3} ms", ns / 1e6)
    } else if ns >= 1e3 {
        format!("{:.3} µs", ns / 1e3)
    } else {
        format!("{ns:.1} ns")
    }
}

/// Modules in order of first appearance.
fn modules(rows: &[Row]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for r in rows {
        if !out.contains(&r.module) {
            out.push(r.module.clone());
        }
    }
    out
}

fn num(v: Option<f64>) -> String {
    v.map_or_else(|| "-".to_string(), |x| format!("{x:.2}"))
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_markup() {
        assert_eq!(esc("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
        assert_eq!(num(Some(1.994)), "1.99");
        assert_eq!(num(None), "-");
    }
}
