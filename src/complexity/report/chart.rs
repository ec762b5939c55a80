//! Log-log SVG charts drawn with plotters' SVG back end (text as SVG `<text>`, so no font
//! files are needed).

use std::error::Error;
use std::io;
use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::Row;

type ChartResult = Result<(), Box<dyn Error>>;

const WIDTH: u32 = 820;
const HEIGHT: u32 = 520;
const COUNT_COLOUR: RGBColor = RGBColor(31, 90, 180);
const TIME_COLOUR: RGBColor = RGBColor(200, 60, 40);
const BOUND_COLOUR: RGBColor = RGBColor(90, 90, 90);
/// Distinguishable line colours for problem charts, cycled.
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 90, 180),
    RGBColor(200, 60, 40),
    RGBColor(40, 150, 70),
    RGBColor(150, 70, 170),
    RGBColor(230, 140, 20),
    RGBColor(20, 160, 170),
    RGBColor(120, 80, 40),
    RGBColor(220, 80, 150),
    RGBColor(110, 110, 110),
    RGBColor(160, 160, 30),
];

/// The chart of one row: counts (left axis) and time (right axis) against n, both log-log,
/// with the bound scaled to pass through the median sample. The right axis is the left one
/// times time/count at the median, so one bound curve serves both series.
pub(crate) fn growth_chart(path: &Path, row: &Row) -> io::Result<()> {
    draw_growth(path, row).map_err(|e| io::Error::other(format!("chart {}: {e}", path.display())))
}

/// The chart of one problem: time of every row (left panel) and counts of every row that has
/// them (right panel), against n, log-log.
pub(crate) fn problem_chart(path: &Path, problem: &str, rows: &[&Row]) -> io::Result<()> {
    draw_problem(path, problem, rows)
        .map_err(|e| io::Error::other(format!("chart {}: {e}", path.display())))
}

fn draw_growth(path: &Path, row: &Row) -> ChartResult {
    let ns: Vec<f64> = row.points.iter().map(|p| p.n as f64).collect();
    let times: Vec<f64> = row.points.iter().map(|p| p.time_ns.max(1e-3)).collect();
    let counts: Option<Vec<f64>> = row
        .op_counts()
        .map(|c| c.into_iter().map(|v| v.max(1.0)).collect());
    let mid = ns.len() / 2;
    // The primary axis shows counts when there are any, else time.
    let primary = counts.clone().unwrap_or_else(|| times.clone());
    let curve = bound_curve(row, &ns, &primary, mid);
    let time_scale = if counts.is_some() && !primary.is_empty() {
        times[mid] / primary[mid]
    } else {
        1.0
    };
    let mut all: Vec<f64> = primary.clone();
    all.extend(curve.iter().flat_map(|c| c.1.iter().map(|p| p.1)));
    if counts.is_some() {
        all.extend(times.iter().map(|t| t / time_scale));
    }
    let (y_lo, y_hi) = padded_range(&all, 1.8);
    let (x_lo, x_hi) = padded_range(&ns, 1.3);

    let root = SVGBackend::new(path, (WIDTH, HEIGHT)).into_drawing_area();
    root.fill(&WHITE)?;
    let title = match row.bound {
        Some(b) => format!("{}: {b}", row.key.clone()),
        None => row.key.clone(),
    };
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(48)
        .y_label_area_size(78)
        .right_y_label_area_size(if counts.is_some() { 78 } else { 0 })
        .build_cartesian_2d((x_lo..x_hi).log_scale().base(2.0), (y_lo..y_hi).log_scale())?
        .set_secondary_coord(
            (x_lo..x_hi).log_scale().base(2.0),
            (y_lo * time_scale..y_hi * time_scale).log_scale(),
        );
    let primary_desc = match (&counts, row.operation) {
        (Some(_), Some(op)) => format!("{} (count)", op.name()),
        _ => "time per run (ns)".to_string(),
    };
    draw_log_mesh(&mut chart, &primary_desc)?;
    if counts.is_some() {
        chart
            .configure_secondary_axes()
            .y_desc("time per run (ns)")
            .y_label_formatter(&|v| compact(*v))
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 16))
            .draw()?;
    }

    let primary_colour = if counts.is_some() {
        COUNT_COLOUR
    } else {
        TIME_COLOUR
    };
    let primary_label = match (&counts, row.operation) {
        (Some(_), Some(op)) => with_slope(op.name(), row.counts_fit.as_ref().map(|f| f.exponent)),
        _ => with_slope("time", row.time_exponent()),
    };
    let pts: Vec<(f64, f64)> = ns.iter().copied().zip(primary.iter().copied()).collect();
    chart.draw_series(LineSeries::new(pts.clone(), primary_colour.stroke_width(2)))?;
    chart
        .draw_series(
            pts.iter()
                .map(|&p| Circle::new(p, 4, primary_colour.filled())),
        )?
        .label(primary_label)
        .legend(move |(x, y)| Circle::new((x + 12, y), 4, primary_colour.filled()));
    if counts.is_some() {
        let tpts: Vec<(f64, f64)> = ns.iter().copied().zip(times.iter().copied()).collect();
        chart.draw_secondary_series(LineSeries::new(tpts.clone(), TIME_COLOUR.stroke_width(2)))?;
        chart
            .draw_secondary_series(
                tpts.iter()
                    .map(|&p| TriangleMarker::new(p, 5, TIME_COLOUR.filled())),
            )?
            .label(with_slope("time (right axis)", row.time_exponent()))
            .legend(|(x, y)| TriangleMarker::new((x + 12, y), 5, TIME_COLOUR.filled()));
    }
    if let Some((label, points)) = &curve {
        chart
            .draw_series(DashedLineSeries::new(
                points.iter().copied(),
                8,
                5,
                BOUND_COLOUR.stroke_width(2),
            ))?
            .label(label.clone())
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], BOUND_COLOUR));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .label_font(("sans-serif", 14))
        .draw()?;
    root.present()?;
    Ok(())
}

fn draw_problem(path: &Path, problem: &str, rows: &[&Row]) -> ChartResult {
    let with_counts: Vec<&Row> = rows
        .iter()
        .copied()
        .filter(|r| r.op_counts().is_some())
        .collect();
    let width = if with_counts.is_empty() {
        WIDTH
    } else {
        2 * WIDTH
    };
    let root = SVGBackend::new(path, (width, HEIGHT)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(
        &format!("{problem}: every algorithm and input"),
        ("sans-serif", 22),
    )?;
    let series_of = |r: &Row, counts: bool| -> Vec<(f64, f64)> {
        let ys: Vec<f64> = if counts {
            r.op_counts().unwrap_or_default()
        } else {
            r.points.iter().map(|p| p.time_ns).collect()
        };
        r.points
            .iter()
            .zip(ys)
            .map(|(p, y)| (p.n as f64, y.max(if counts { 1.0 } else { 1e-3 })))
            .collect()
    };
    // Peers (criterion imports) are dashed, and every time series shows its slope so the
    // growth of compgeo and of its peers reads off the legend.
    let time_series: Vec<Series> = rows
        .iter()
        .map(|r| Series {
            label: with_slope(
                &if r.peer {
                    format!("{} (peer)", r.key)
                } else {
                    r.key.clone()
                },
                r.time_exponent(),
            ),
            points: series_of(r, false),
            dashed: r.peer,
        })
        .collect();
    if with_counts.is_empty() {
        panel(&root, "time per run (ns)", &time_series)?;
    } else {
        let (left, right) = root.split_horizontally(WIDTH);
        panel(&left, "time per run (ns)", &time_series)?;
        let count_series: Vec<Series> = with_counts
            .iter()
            .map(|r| {
                let op = r.operation.map_or("count", |o| o.name());
                Series {
                    label: format!("{} [{op}]", r.key.clone()),
                    points: series_of(r, true),
                    dashed: false,
                }
            })
            .collect();
        panel(&right, "counted operations", &count_series)?;
    }
    root.present()?;
    Ok(())
}

/// One line of a problem chart.
struct Series {
    label: String,
    points: Vec<(f64, f64)>,
    /// Drawn dashed (a peer crate's benchmark).
    dashed: bool,
}

fn panel(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    y_desc: &str,
    series: &[Series],
) -> ChartResult {
    let xs: Vec<f64> = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.0))
        .collect();
    let ys: Vec<f64> = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .collect();
    let (x_lo, x_hi) = padded_range(&xs, 1.3);
    let (y_lo, y_hi) = padded_range(&ys, 2.0);
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .x_label_area_size(48)
        .y_label_area_size(78)
        .build_cartesian_2d((x_lo..x_hi).log_scale().base(2.0), (y_lo..y_hi).log_scale())?;
    draw_log_mesh(&mut chart, y_desc)?;
    for (i, s) in series.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        let pts = &s.points;
        if s.dashed {
            chart.draw_series(DashedLineSeries::new(
                pts.clone(),
                8,
                5,
                colour.stroke_width(2),
            ))?;
        } else {
            chart.draw_series(LineSeries::new(pts.clone(), colour.stroke_width(2)))?;
        }
        chart
            .draw_series(pts.iter().map(|&p| Circle::new(p, 3, colour.filled())))?
            .label(s.label.clone())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 24, y)], colour.stroke_width(3))
            });
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .label_font(("sans-serif", 13))
        .draw()?;
    Ok(())
}

/// The bound through the median sample of `ys`: a smooth curve when f depends on n only,
/// else a polyline through the samples (h or m vary with the input). `None` without a bound.
fn bound_curve(row: &Row, ns: &[f64], ys: &[f64], mid: usize) -> Option<(String, Vec<(f64, f64)>)> {
    let bound = row.bound?;
    let at_points = row.bound_values()?;
    let scale = ys.get(mid)? / at_points.get(mid)?;
    let label = format!("{bound}, scaled at n = {}", compact(ns[mid]));
    let points = if bound.second_size().is_none() {
        let (lo, hi) = (ns.first()?.ln(), ns.last()?.ln());
        (0..=64)
            .map(|i| {
                let n = (lo + (hi - lo) * f64::from(i) / 64.0).exp();
                (n, scale * bound.eval(n, None))
            })
            .collect()
    } else {
        ns.iter()
            .zip(&at_points)
            .map(|(&n, &f)| (n, scale * f))
            .collect()
    };
    Some((label, points))
}

/// `[min / pad, max * pad]` of the positive finite values (`[1, 10]` if there are none).
fn padded_range(values: &[f64], pad: f64) -> (f64, f64) {
    let finite = values.iter().copied().filter(|v| v.is_finite() && *v > 0.0);
    let lo = finite.clone().fold(f64::INFINITY, f64::min);
    let hi = finite.fold(0.0, f64::max);
    if lo.is_finite() && hi > 0.0 {
        (lo / pad, hi * pad)
    } else {
        (1.0, 10.0)
    }
}

fn with_slope(label: &str, slope: Option<f64>) -> String {
    match slope {
        Some(s) => format!("{label}, log-log slope {s:.2}"),
        None => label.to_string(),
    }
}

/// Short axis labels: integers below 100 000 exactly (`512`, `65536`), larger values with a
/// suffix and three significant digits (`131k`, `3M`, `1.5G`), fractions with two decimals.
fn compact(v: f64) -> String {
    if v < 1e5 && (v - v.round()).abs() < 1e-9 {
        return format!("{v:.0}");
    }
    let (scaled, suffix) = if v >= 1e12 {
        (v / 1e12, "T")
    } else if v >= 1e9 {
        (v / 1e9, "G")
    } else if v >= 1e6 {
        (v / 1e6, "M")
    } else if v >= 1e5 {
        (v / 1e3, "k")
    } else {
        (v, "")
    };
    let text = if scaled >= 100.0 {
        format!("{scaled:.0}")
    } else if scaled >= 10.0 {
        format!("{scaled:.1}")
    } else {
        format!("{scaled:.2}")
    };
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    };
    format!("{text}{suffix}")
}

/// The log-log mesh every chart shares: n on a base-2 axis, compact labels, no minor lines.
fn draw_log_mesh(
    chart: &mut ChartContext<'_, SVGBackend<'_>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>,
    y_desc: &str,
) -> ChartResult {
    chart
        .configure_mesh()
        .x_desc("n (input size)")
        .y_desc(y_desc)
        .x_label_formatter(&|v| compact(*v))
        .y_label_formatter(&|v| compact(*v))
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 16))
        .light_line_style(WHITE.mix(0.0))
        .draw()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compact_labels() {
        assert_eq!(compact(512.0), "512");
        assert_eq!(compact(65536.0), "65536");
        assert_eq!(compact(131_072.0), "131k");
        assert_eq!(compact(3e6), "3M");
        assert_eq!(compact(1.5e9), "1.5G");
        assert_eq!(compact(0.25), "0.25");
        assert_eq!(compact(2.5), "2.5");
    }

    #[test]
    fn padded_range_ignores_non_positive() {
        assert_eq!(padded_range(&[0.0, 2.0, 8.0, f64::NAN], 2.0), (1.0, 16.0));
        assert_eq!(padded_range(&[], 2.0), (1.0, 10.0));
    }
}
