//! The fleet's charts: the distribution of tan γe(3 mm), tan γe(3 mm) against the
//! nonlinearity parameter, the conicity functions overlaid, and Sd against Sh.

use super::schema::wheel_columns;
use crate::chart::{Chart, Figure, LegendPosition, Series};
use wheelrail::fleet::{Inputs, Row};

/// tan γe(3 mm) of a row, if it was assessed and the value is defined.
pub(super) fn at3(row: &Row) -> Option<f64> {
    row.outcome
        .as_ref()
        .ok()
        .map(|s| s.parameters.tan_gamma_e_3mm)
        .filter(|v| v.is_finite())
}

/// The row with the largest tan γe(3 mm).
pub(super) fn worst(rows: &[Row]) -> Option<&Row> {
    rows.iter()
        .filter(|r| at3(r).is_some())
        .max_by(|a, b| at3(a).unwrap_or(0.0).total_cmp(&at3(b).unwrap_or(0.0)))
}

const AT3_LABEL: &str = "equivalent conicity tan γe(3 mm) (dimensionless)";

/// The distribution of tan γe(3 mm) over the fleet: a histogram outline, the limit marked.
pub fn histogram(rows: &[Row], limit: Option<f64>) -> Figure {
    let values: Vec<f64> = rows.iter().filter_map(at3).collect();
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let mut chart = Chart::new(
        format!("Distribution of tan γe(3 mm) over {} pairs", values.len()),
        AT3_LABEL,
        "pairs per bin (count)",
    );
    if !values.is_empty() {
        // About 2 sqrt(n) bins, at most 40, on a width rounded to 1, 2 or 5 times a power of 10.
        let span = (hi - lo).max(1e-3);
        let raw = span / (2.0 * (values.len() as f64).sqrt()).clamp(5.0, 40.0);
        let p = 10f64.powf(raw.log10().floor());
        let width = [1.0, 2.0, 5.0, 10.0]
            .into_iter()
            .map(|m| m * p)
            .find(|w| *w >= raw)
            .unwrap_or(10.0 * p);
        let first = (lo / width).floor() * width;
        let n = (((hi - first) / width).floor() as usize + 1).max(1);
        let mut counts = vec![0usize; n];
        for v in &values {
            counts[(((v - first) / width).floor() as usize).min(n - 1)] += 1;
        }
        // Step outlines: along the top of the bins, down to 0 at the ends of each run.
        let mut below: Vec<(f64, f64)> = Vec::new();
        let mut above: Vec<(f64, f64)> = Vec::new();
        for (i, &c) in counts.iter().enumerate() {
            let (x0, x1) = (first + i as f64 * width, first + (i + 1) as f64 * width);
            // A bin at or above the limit is drawn in the second colour.
            let outline = if limit.is_some_and(|l| x0 >= l - 1e-12) {
                &mut above
            } else {
                &mut below
            };
            if outline.is_empty() {
                outline.push((x0, 0.0));
            }
            outline.extend([(x0, c as f64), (x1, c as f64)]);
        }
        for outline in [&mut below, &mut above] {
            if let Some(&(x, _)) = outline.last() {
                outline.push((x, 0.0));
            }
        }
        if !below.is_empty() {
            chart = chart.series(Series::line("pairs", below).color(0));
        }
        if !above.is_empty() {
            chart = chart.series(Series::line("pairs in bins over the limit", above).color(1));
        }
        let top = counts.iter().copied().max().unwrap_or(1) as f64;
        chart = chart.y_range(0.0, 1.15 * top);
    }
    if let Some(l) = limit {
        chart = chart.vline(l, format!("limit {l}"));
    }
    Figure::single(chart.legend(LegendPosition::Auto))
}

/// tan γe(3 mm) against the nonlinearity parameter, the pairs over the limit and the worst
/// pair marked.
pub fn conicity_against_nonlinearity(rows: &[Row], limit: Option<f64>) -> Figure {
    let point = |r: &Row| -> Option<(f64, f64)> {
        let s = r.outcome.as_ref().ok()?;
        let y = s.parameters.nonlinearity_per_mm;
        at3(r).filter(|_| y.is_finite()).map(|x| (x, y))
    };
    let over = |r: &Row| limit.is_some_and(|l| at3(r).is_some_and(|v| v > l));
    let within: Vec<(f64, f64)> = rows.iter().filter(|r| !over(r)).filter_map(point).collect();
    let above: Vec<(f64, f64)> = rows.iter().filter(|r| over(r)).filter_map(point).collect();
    let mut chart = Chart::new(
        "tan γe(3 mm) against the nonlinearity parameter",
        AT3_LABEL,
        "nonlinearity parameter NP (1/mm)",
    )
    .series(Series::markers(format!("pairs ({})", within.len()), within).color(0));
    if !above.is_empty() {
        chart = chart
            .series(Series::markers(format!("over the limit ({})", above.len()), above).color(1));
    }
    if let Some(w) = worst(rows)
        && let Some(p) = point(w)
    {
        chart = chart.series(Series::markers(format!("worst: {}", w.id), vec![p]).color(6));
    }
    if let Some(l) = limit {
        chart = chart.vline(l, format!("limit {l}"));
    }
    Figure::single(chart.legend(LegendPosition::Auto))
}

/// The equivalent conicity functions of all pairs overlaid, the worst pair highlighted,
/// the limit as a dashed line.
pub fn conicity_functions(rows: &[Row], limit: Option<f64>, method: &str) -> Figure {
    let mut chart = Chart::new(
        format!("Equivalent conicity functions ({method})"),
        "amplitude of the kinematic motion ŷ (mm)",
        "equivalent conicity tan γe (dimensionless)",
    );
    let worst = worst(rows);
    let assessed: Vec<&Row> = rows.iter().filter(|r| r.outcome.is_ok()).collect();
    let mut x_max: f64 = 0.0;
    for (i, r) in assessed.iter().enumerate() {
        let Ok(s) = &r.outcome else { continue };
        if worst.is_some_and(|w| w.id == r.id) {
            continue;
        }
        x_max = s.conicity.iter().map(|p| p.0).fold(x_max, f64::max);
        let label = if i == 0 {
            format!("pairs ({})", assessed.len())
        } else {
            String::new()
        };
        chart = chart.series(Series::line(label, s.conicity.clone()).color(5));
    }
    if let Some(w) = worst
        && let Ok(s) = &w.outcome
    {
        x_max = s.conicity.iter().map(|p| p.0).fold(x_max, f64::max);
        chart = chart.series(
            Series::line(
                format!(
                    "worst: {} (tan γe(3 mm) = {:.3})",
                    w.id, s.parameters.tan_gamma_e_3mm
                ),
                s.conicity.clone(),
            )
            .color(1),
        );
    }
    chart = chart.vline(3.0, "ŷ = 3 mm");
    if let Some(l) = limit
        && x_max > 0.0
    {
        chart = chart.series(
            Series::line(format!("limit {l}"), vec![(0.0, l), (x_max, l)])
                .color(6)
                .dashed(),
        );
    }
    Figure::single(chart.legend(LegendPosition::Auto))
}

/// The most wheels over a limit the Sd-against-Sh chart names one by one in its legend,
/// those furthest beyond a limit (one palette colour each, besides the wheels within the
/// limits, the limit box and the rest); the others share one entry (the page's table and
/// fleet.csv list them all).
const MAX_NAMED_OFFENDERS: usize = 5;

/// Each wheel's flange thickness Sd against its flange height Sh, the limit box of the
/// template's left wheel drawn dashed, the wheels that break a limit (qR included) named.
pub fn flange_dimensions(
    rows: &[Row],
    inputs: Inputs,
    limits: &wheelrail::maintenance::Limits,
) -> Figure {
    let (within, offenders) = flange_points(rows, inputs);
    let (sh_min, sh_max) = (limits.sh_min.value_mm, limits.sh_max.value_mm);
    let (sd_min, sd_max) = (limits.sd_min.value_mm, limits.sd_max.value_mm);
    let box_points = vec![
        (sh_min, sd_min),
        (sh_max, sd_min),
        (sh_max, sd_max),
        (sh_min, sd_max),
        (sh_min, sd_min),
    ];
    let total = within.len() + offenders.len();
    // The whole box and every wheel, with a margin.
    let all = within.iter().chain(offenders.iter().map(|o| &o.point));
    let (x_lo, x_hi, y_lo, y_hi) = all.fold((sh_min, sh_max, sd_min, sd_max), |r, p| {
        (r.0.min(p.0), r.1.max(p.0), r.2.min(p.1), r.3.max(p.1))
    });
    let mut chart = Chart::new(
        format!("Flange thickness against flange height, {total} wheels"),
        "flange height Sh (mm)",
        "flange thickness Sd (mm)",
    )
    .series(
        Series::line(
            format!(
                "limits Sh {sh_min} to {sh_max} mm, Sd {sd_min} to {sd_max} mm (qR at least {} mm)",
                limits.qr_min.value_mm
            ),
            box_points,
        )
        .color(6)
        .dashed(),
    )
    .series(Series::markers(format!("within the limits ({})", within.len()), within).color(0));
    let named = offenders.len().min(MAX_NAMED_OFFENDERS);
    for (i, o) in offenders.iter().take(named).enumerate() {
        chart = chart.series(Series::markers(o.label.clone(), vec![o.point]).color(1 + i));
    }
    if offenders.len() > named {
        let rest: Vec<(f64, f64)> = offenders[named..].iter().map(|o| o.point).collect();
        chart = chart.series(
            Series::markers(format!("{} more wheels over a limit", rest.len()), rest).color(7),
        );
    }
    let margin = 0.5;
    Figure::single(
        chart
            .x_range(x_lo - margin, x_hi + margin)
            .y_range(y_lo - margin, y_hi + margin)
            .legend(LegendPosition::Auto),
    )
}

/// A wheel that breaks a maintenance limit, in the flange chart.
struct Offender {
    /// Its name and the limits it breaks.
    label: String,
    /// `(Sh, Sd)` (mm).
    point: (f64, f64),
    /// How far beyond its limit it lies (mm).
    beyond: f64,
    /// Which limits it breaks (the kind of breach).
    kind: String,
}

/// The `(Sh, Sd)` of every wheel of the fleet with defined dimensions: those within the
/// limits, and the offenders, furthest beyond a limit first with the worst of each kind of
/// breach (Sh too low, Sd too thick, ...) before the rest, so that every kind is named.
fn flange_points(rows: &[Row], inputs: Inputs) -> (Vec<(f64, f64)>, Vec<Offender>) {
    let mut within = Vec::new();
    let mut offenders: Vec<Offender> = Vec::new();
    for r in rows {
        let Ok(s) = &r.outcome else { continue };
        for &(prefix, k) in wheel_columns(inputs) {
            let w = &s.maintenance.wheels[k];
            let Ok(d) = &w.dimensions else { continue };
            let point = (d.sh_mm, d.sd_mm);
            if w.breaches.is_empty() {
                within.push(point);
                continue;
            }
            let side = prefix.trim_end_matches('_');
            let who = if side.is_empty() {
                r.id.clone()
            } else {
                format!("{} {side}", r.id)
            };
            offenders.push(Offender {
                label: format!("{who}: {}", w.status()),
                point,
                beyond: w
                    .breaches
                    .iter()
                    .map(|b| (b.value_mm - b.limit_mm).abs())
                    .fold(0.0, f64::max),
                kind: w
                    .breaches
                    .iter()
                    .map(|b| format!("{:?}{:?}", b.dimension, b.bound))
                    .collect(),
            });
        }
    }
    offenders.sort_by(|a, b| b.beyond.total_cmp(&a.beyond));
    let mut kinds = std::collections::HashSet::new();
    let (mut first, rest): (Vec<_>, Vec<_>) = offenders
        .into_iter()
        .partition(|o| kinds.insert(o.kind.clone()));
    first.extend(rest);
    (within, first)
}
