//! `index.html`: machine, summary table and charts, in one self-contained page that refers
//! to the SVG files next to it.

use std::fmt::Write;

use super::{problem_chart_file, Row};
use crate::complexity::{Machine, COUNT_TOLERANCE, TIME_TOLERANCE};

const STYLE: &str =
    "body{font-family:sans-serif;max-width:1700px;margin:1em auto;padding:0 1em;color:#222}\
table{border-collapse:collapse;margin:1em 0}\
th,td{border:1px solid #bbb;padding:.25em .6em;text-align:left}\
td.num{text-align:right;font-variant-numeric:tabular-nums}\
tr.exceeds td{background:#fde2dc}\
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
         <h1>compgeo complexity report</h1>\n"
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
    let _ = write!(
        h,
        "<h2>Summary</h2>\n<p>Exponents are least-squares slopes of log cost against log n. \
         The bound column gives the slope of log f(n) over the same sizes. The verdict compares \
         exact counts with the stated bound: <em>exceeds</em> when cost / f(n) grows faster \
         than n<sup>{COUNT_TOLERANCE}</sup> (time: n<sup>{TIME_TOLERANCE}</sup>). \
         The exact fallbacks are the predicate calls, at the largest size, that the \
         floating-point filter could not decide, with their share of the counted operation. \
         See <code>docs/complexity.md</code>.</p>\n<table>\n<tr><th>algorithm</th>\
         <th>problem</th><th>input</th><th>stated bound</th><th>counted operation</th>\
         <th>exponent of counts</th><th>exponent of bound</th><th>exponent of time</th>\
         <th>verdict</th><th>time verdict</th><th>exact fallbacks</th></tr>\n"
    );
    for r in rows {
        let counts = r.counts_fit.as_ref();
        let time = r.time_fit.as_ref();
        let verdict = counts.map(|f| f.verdict.name());
        let _ = writeln!(
            h,
            "<tr class=\"{}\"><td><a href=\"#{}\">{}</a></td><td>{}</td><td>{}</td><td>{}</td>\
             <td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>\
             <td>{}</td><td>{}</td><td class=\"num\">{}</td></tr>",
            verdict.unwrap_or(""),
            esc(&r.key.clone()),
            esc(&r.id),
            esc(&r.problem),
            esc(r.input.as_deref().unwrap_or("")),
            r.bound.map(|b| esc(b.as_str())).unwrap_or_default(),
            r.operation.map_or("", |o| o.name()),
            num(counts.map(|f| f.exponent)),
            num(counts.or(time).map(|f| f.bound_exponent)),
            num(r.time_exponent()),
            verdict.unwrap_or("-"),
            time.map_or("-", |f| f.verdict.name()),
            fallbacks(r),
        );
    }
    h.push_str("</table>\n");
    for problem in problems {
        let _ = write!(
            h,
            "<h2>{p}</h2>\n<img src=\"{f}\" alt=\"{p}: all algorithms\">\n<div>\n",
            p = esc(problem),
            f = esc(&problem_chart_file(problem)),
        );
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
