//! The fleet's outputs as bytes: `fleet.csv` line by line (its `#` header, then one line
//! per row as rows complete), the fleet charts and the `index.html` page.
//! [`crate::app`] writes them.

use super::{CSV_FORMAT, OutputFile};
use crate::Error;
use crate::fleet::{Fleet, Row, Summary};
use crate::report::chart::{Chart, Figure, LegendPosition, Series};
use crate::report::table::format_number;
use crate::report::{self, FigureEntry, ReportPage, TableEntry};
use crate::scene::ImageFormat;

/// The summary columns after the parameters when the rows carry Hertz results.
const HERTZ_COLUMNS: [&str; 3] = ["max_p0_MPa", "max_p0_y_ws_mm", "max_p0_side"];

/// The header row's column names.
pub fn columns(fleet: &Fleet) -> Vec<String> {
    let mut c = vec!["id".to_string()];
    for role in fleet.inputs().roles() {
        c.push(format!("{role}_file"));
        c.push(format!("{role}_sha256"));
    }
    c.push("status".into());
    c.extend(parameter_rows(None).iter().map(|r| r.name.to_string()));
    if fleet.has_hertz() {
        c.extend(HERTZ_COLUMNS.iter().map(|s| s.to_string()));
    }
    c.push("undefined_status".into());
    c
}

/// The parameters' rows (names, units, definitions; values of `summary` or NaN).
fn parameter_rows(summary: Option<&Summary>) -> Vec<crate::conicity::pair::ParameterRow> {
    let undefined = crate::conicity::Parameters {
        method: crate::conicity::Method::Klingel,
        tan_gamma_e: [f64::NAN; 3],
        nonlinearity_per_mm: f64::NAN,
        equilibrium_mm: f64::NAN,
        flange_contact_left_mm: f64::NAN,
        flange_contact_right_mm: f64::NAN,
        contact_point_jumps: 0,
        sampling_artefacts: 0,
        delta_r_mm: [f64::NAN; 2],
        contact_angle_difference_rad: [f64::NAN; 2],
    };
    summary.map_or(undefined, |s| s.parameters).rows()
}

/// The `#` lines and the header row of `fleet.csv`. They depend on the template and the
/// kind of inputs only (not on the shard, the thread count or the time), so that the CSVs
/// of the parts of a sharded fleet concatenate to the whole one's.
pub fn csv_header(fleet: &Fleet, template_path: &str) -> String {
    let t = fleet.template();
    let sweep = format!(
        "{} to {} mm, {} positions",
        t.sweep.shifts_mm().first().copied().unwrap_or(f64::NAN),
        t.sweep.shifts_mm().last().copied().unwrap_or(f64::NAN),
        t.sweep.len()
    );
    let mut lines = vec![
        format!(
            "fleet assessment by wheelrail {}: template scene {template_path} (sweep {sweep}; computed per row: {})",
            env!("CARGO_PKG_VERSION"),
            fleet.describe_stages()
        ),
        "one row per profile or pair, in input order; status: ok, or why that row's files could not be assessed (the reader's message names the file and line); NaN where a value is undefined, with the reason in undefined_status".into(),
        format!(
            "the *_file columns name the profiles each row puts in place of the template's (a wheel profile on both wheels, mirrored by the right side frame); the others are the template's: wheels {}, rails {}",
            profile_names(&t.wheel_profiles),
            profile_names(&t.rail_profiles)
        ),
        super::tables::conicity_method_text(t.conicity.method).to_string(),
        "y lateral displacement of the wheelset, positive to the left (track frame); delta_r = r_left - r_right; units in the column names: _mm millimetres, _per_mm 1/mm, _rad radians, _MPa N/mm^2; tan_gamma_e dimensionless; contact_point_jumps and sampling_artefacts counts".into(),
    ];
    for r in parameter_rows(None) {
        lines.push(format!("{} ({}): {}", r.name, r.unit, r.definition));
    }
    if fleet.has_hertz() {
        lines.push(format!(
            "max_p0_MPa: the largest Hertz maximum pressure over the sweep and both wheels ({} method, {} contact, normal load {}, {} kN per wheel), at the wheelset shift max_p0_y_ws_mm on the wheel max_p0_side",
            t.hertz.method,
            t.hertz_contact.name(),
            t.hertz.normal_load.name(),
            t.wheel_load_n / 1000.0
        ));
    }
    let mut text: String = lines.iter().map(|l| format!("# {l}\n")).collect();
    text.push_str(&record(&columns(fleet)));
    text
}

fn profile_names(refs: &[crate::scene::ProfileRef; 2]) -> String {
    let name = |r: &crate::scene::ProfileRef| match r {
        crate::scene::ProfileRef::BuiltIn(n) => n.clone(),
        crate::scene::ProfileRef::File(p) => p.display().to_string(),
    };
    if refs[0] == refs[1] {
        name(&refs[0])
    } else {
        format!("{} (left), {} (right)", name(&refs[0]), name(&refs[1]))
    }
}

/// One CSV record (quoted where needed), ending with `\n`.
fn record(cells: &[String]) -> String {
    let mut writer = csv::WriterBuilder::new()
        .terminator(csv::Terminator::Any(b'\n'))
        .from_writer(Vec::new());
    // Writing into a Vec cannot fail.
    let expect = "CSV writer into memory";
    writer.write_record(cells).expect(expect);
    String::from_utf8(writer.into_inner().expect(expect)).expect("CSV of UTF-8 strings is UTF-8")
}

/// The line of `row` in `fleet.csv`: numbers as in every other CSV (10 significant digits,
/// the same text as a report's `parameters.csv`).
pub fn csv_line(fleet: &Fleet, row: &Row) -> String {
    let number = |v: f64| format_number(v, CSV_FORMAT);
    let mut cells = vec![row.id.clone()];
    for f in &row.files {
        cells.push(
            f.path
                .as_ref()
                .map(|p| p.display().to_string())
                .unwrap_or_default(),
        );
        cells.push(f.sha256.clone().unwrap_or_default());
    }
    let summary = row.outcome.as_ref().ok();
    cells.push(match &row.outcome {
        Ok(_) => "ok".into(),
        Err(e) => e.clone(),
    });
    let rows = parameter_rows(summary);
    let mut notes = Vec::new();
    for r in &rows {
        cells.push(if summary.is_some() {
            if r.unit == "count" {
                format!("{}", r.value)
            } else {
                number(r.value)
            }
        } else {
            "NaN".into()
        });
        if summary.is_some() && !r.value.is_finite() {
            notes.push(format!("{}: {}", r.name, r.undefined));
        }
    }
    if fleet.has_hertz() {
        match summary.and_then(|s| s.max_p0) {
            Some(m) => {
                cells.push(number(m.p0_mpa));
                cells.push(number(m.y_ws_mm));
                cells.push(m.side.name().to_string());
            }
            None => {
                cells.extend(["NaN".into(), "NaN".into(), String::new()]);
                if summary.is_some() {
                    notes.push("max_p0_MPa: no Hertz ellipse at any position".into());
                }
            }
        }
    }
    cells.push(notes.join("; "));
    record(&cells)
}

/// tan γe(3 mm) of a row, if it was assessed and the value is defined.
fn at3(row: &Row) -> Option<f64> {
    row.outcome
        .as_ref()
        .ok()
        .map(|s| s.parameters.tan_gamma_e[1])
        .filter(|v| v.is_finite())
}

/// The row with the largest tan γe(3 mm).
fn worst(rows: &[Row]) -> Option<&Row> {
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
                    w.id, s.parameters.tan_gamma_e[1]
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

/// Names and captions of the fleet figures.
const FIGURES: [(&str, &str); 3] = [
    (
        "fleet_conicity_histogram",
        "Distribution of the equivalent conicity tan γe(3 mm) over the fleet (bins of equal width; bins at or above the limit in the second colour, the limit [fleet] conicity_limit as a vertical line). Rows that failed or whose tan γe(3 mm) is undefined are not counted.",
    ),
    (
        "fleet_conicity_nonlinearity",
        "Each pair's tan γe(3 mm) against Polach's nonlinearity parameter NP = (tan γe(4 mm) - tan γe(2 mm)) / 2 mm: worn, conformal pairs sit at high conicity and negative NP. Pairs over the limit in the second colour; the worst pair (largest tan γe(3 mm)) named.",
    ),
    (
        "fleet_conicity_functions",
        "The equivalent conicity functions tan γe(ŷ) of all pairs overlaid (the scene's method), the worst pair highlighted and named, the limit dashed. A function ends where the motion would leave the swept Δr.",
    ),
];

/// The fleet's figures in the template's formats and `index.html`.
///
/// # Errors
/// [`Error::Other`] when a figure cannot be rendered.
pub fn render(
    fleet: &Fleet,
    rows: &[Row],
    template_path: &str,
    reports: bool,
) -> Result<Vec<OutputFile>, Error> {
    let t = fleet.template();
    let limit = t.fleet.conicity_limit;
    let charts = [
        histogram(rows, limit),
        conicity_against_nonlinearity(rows, limit),
        conicity_functions(rows, limit, t.conicity.method.name()),
    ];
    let mut files = Vec::new();
    let mut entries = Vec::new();
    for ((name, caption), chart) in FIGURES.iter().zip(&charts) {
        let mut entry = FigureEntry {
            name: (*name).to_string(),
            caption: (*caption).to_string(),
            svg: String::new(),
            png: String::new(),
        };
        for format in &t.formats {
            let fail = |e: report::chart::ChartError| Error::Other(format!("figure {name}: {e}"));
            let file = match format {
                ImageFormat::Svg => {
                    entry.svg = format!("{name}.svg");
                    OutputFile {
                        name: entry.svg.clone(),
                        bytes: report::render_svg(chart).map_err(fail)?.into_bytes(),
                    }
                }
                ImageFormat::Png => {
                    entry.png = format!("{name}.png");
                    OutputFile {
                        name: entry.png.clone(),
                        bytes: report::render_png(chart).map_err(fail)?,
                    }
                }
            };
            files.push(file);
        }
        entries.push(entry);
    }
    files.push(OutputFile {
        name: "index.html".into(),
        bytes: report::render_html(&page(fleet, rows, template_path, reports, entries))
            .into_bytes(),
    });
    Ok(files)
}

/// The rows shown in the page's table: those over the limit, or without a limit the ten of
/// highest tan γe(3 mm); at most [`MAX_LISTED`], highest first.
fn listed(rows: &[Row], limit: Option<f64>) -> Vec<&Row> {
    let mut v: Vec<&Row> = rows
        .iter()
        .filter(|r| at3(r).is_some_and(|x| limit.is_none_or(|l| x > l)))
        .collect();
    v.sort_by(|a, b| at3(b).unwrap_or(0.0).total_cmp(&at3(a).unwrap_or(0.0)));
    v.truncate(if limit.is_some() { MAX_LISTED } else { 10 });
    v
}

/// The most rows the page lists (the CSV holds them all).
const MAX_LISTED: usize = 200;

/// The page's summary lines: rows assessed and failed, the spread of tan γe(3 mm), the
/// pairs over the limit.
fn summary(rows: &[Row], failed: usize, limit: Option<f64>) -> Vec<String> {
    let mut values: Vec<f64> = rows.iter().filter_map(at3).collect();
    values.sort_by(f64::total_cmp);
    let quantile = |q: f64| values[((values.len() - 1) as f64 * q).round() as usize];
    let mut summary = vec![format!(
        "{} rows: {} assessed, {} failed (their status in fleet.csv says why).",
        rows.len(),
        rows.len() - failed,
        failed
    )];
    if !values.is_empty() {
        summary.push(format!(
            "tan γe(3 mm) over {} pairs: median {:.4}, 95th percentile {:.4}, largest {:.4} ({}).",
            values.len(),
            quantile(0.5),
            quantile(0.95),
            quantile(1.0),
            worst(rows).map_or("", |w| w.id.as_str())
        ));
    }
    match limit {
        Some(l) => summary.push(format!(
            "{} pairs over the limit tan γe(3 mm) > {l} ([fleet] conicity_limit).",
            rows.iter().filter(|r| at3(r).is_some_and(|x| x > l)).count()
        )),
        None => summary.push(
            "No limit set: [fleet] conicity_limit in the scene marks one in the charts and lists the pairs over it.".into(),
        ),
    }
    summary
}

/// The table of the pairs over the limit (the ten highest without one).
fn listed_table(
    rows: &[Row],
    limit: Option<f64>,
    has_hertz: bool,
    reports: bool,
) -> report::DataTable {
    let mut header = vec![
        "id".to_string(),
        "tan γe(3 mm)".into(),
        "NP (1/mm)".into(),
        "flange contact left, right (mm)".into(),
        "jumps".into(),
    ];
    if has_hertz {
        header.push("max p0 (MPa)".into());
    }
    let number = |v: f64, digits: usize| {
        if v.is_finite() {
            format!("{v:.digits$}")
        } else {
            "—".into()
        }
    };
    let table_rows: Vec<Vec<String>> = listed(rows, limit)
        .into_iter()
        .filter_map(|r| {
            let s = r.outcome.as_ref().ok()?;
            let p = &s.parameters;
            let mut cells = vec![
                r.id.clone(),
                number(p.tan_gamma_e[1], 4),
                number(p.nonlinearity_per_mm, 4),
                format!(
                    "{}, {}",
                    number(p.flange_contact_left_mm, 2),
                    number(p.flange_contact_right_mm, 2)
                ),
                p.contact_point_jumps.to_string(),
            ];
            if has_hertz {
                cells.push(s.max_p0.map_or("—".into(), |m| {
                    format!(
                        "{:.0} ({} wheel, y_ws = {} mm)",
                        m.p0_mpa,
                        m.side.name(),
                        m.y_ws_mm
                    )
                }));
            }
            if reports {
                cells[0] = format!("{} (report: {}/index.html)", r.id, r.id);
            }
            Some(cells)
        })
        .collect();
    let title = match limit {
        Some(l) => format!("Pairs over the limit tan γe(3 mm) > {l}"),
        None => "The ten pairs of highest tan γe(3 mm)".into(),
    };
    report::DataTable {
        title,
        header,
        rows: table_rows,
    }
}

/// The most failed rows the page names (the CSV holds them all).
const MAX_FAILED_LISTED: usize = 50;

/// One note per failed row (the first [`MAX_FAILED_LISTED`]).
fn failed_notes(failed: &[&Row]) -> Vec<String> {
    let mut notes: Vec<String> = failed
        .iter()
        .take(MAX_FAILED_LISTED)
        .map(|r| {
            format!(
                "{}: {}",
                r.id,
                r.outcome.as_ref().err().map_or("", String::as_str)
            )
        })
        .collect();
    if failed.len() > MAX_FAILED_LISTED {
        notes.push(format!(
            "... and {} more failed rows (fleet.csv lists all).",
            failed.len() - MAX_FAILED_LISTED
        ));
    }
    notes
}

fn page(
    fleet: &Fleet,
    rows: &[Row],
    template_path: &str,
    reports: bool,
    figures: Vec<FigureEntry>,
) -> ReportPage {
    let t = fleet.template();
    let limit = t.fleet.conicity_limit;
    let failed: Vec<&Row> = rows.iter().filter(|r| r.outcome.is_err()).collect();
    ReportPage {
        title: format!("Fleet assessment: {}", t.title),
        summary: summary(rows, failed.len(), limit),
        parameters: vec![
            ("template scene".into(), template_path.to_string()),
            (
                "sweep (mm)".into(),
                format!(
                    "{} to {}, {} positions",
                    t.sweep.shifts_mm().first().copied().unwrap_or(f64::NAN),
                    t.sweep.shifts_mm().last().copied().unwrap_or(f64::NAN),
                    t.sweep.len()
                ),
            ),
            ("equivalent conicity method".into(), t.conicity.method.name().into()),
            (
                "conicity limit".into(),
                limit.map_or("none".into(), |l| l.to_string()),
            ),
            ("computed per pair".into(), fleet.describe_stages()),
        ],
        provenance: vec![(
            "wheelrail".into(),
            format!("version {}", env!("CARGO_PKG_VERSION")),
        )],
        figures,
        tables: vec![TableEntry {
            name: "fleet".into(),
            file: "fleet.csv".into(),
            description: "one row per profile or pair: files, sha256, status, tan γe at 2, 3, 4 mm, nonlinearity, flange contact, jumps (units in the column names)".into(),
        }],
        data_tables: vec![listed_table(rows, limit, fleet.has_hertz(), reports)],
        notes: failed_notes(&failed),
        ..ReportPage::default()
    }
}
