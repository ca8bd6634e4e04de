//! The fleet's outputs as bytes: `fleet.csv` line by line (its `#` header, then one line
//! per row as rows complete), or its rows as one [`Table`] ([`table`]: the same columns and
//! numbers, for a library user); with the feature `cli`, the fleet charts and the
//! `index.html` page. The command line (`app`) writes them.

use super::CSV_FORMAT;
use super::OutputFile;
use crate::Error;
use crate::chart::{Chart, Figure, LegendPosition, Series};
use crate::table::format_number;
use crate::{ColumnData, Table, TableError};
use crate::{FigureEntry, ReportPage, TableEntry};
use wheelrail::fleet::{Fleet, Inputs, Row, RowError, Summary};
use wheelrail::scene::ImageFormat;

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
    c.extend(maintenance_columns(fleet.inputs()));
    c.extend(parameter_rows(None).iter().map(|r| r.name.to_string()));
    if fleet.has_hertz() {
        c.extend(HERTZ_COLUMNS.iter().map(|s| s.to_string()));
    }
    c.push("undefined_status".into());
    c
}

/// The wheel sides whose flange dimensions a row reports: `("", 0)` for one profile on both
/// wheels, `("left_", 0), ("right_", 1)` for pairs, none for a fleet of rails.
fn wheel_columns(inputs: Inputs) -> &'static [(&'static str, usize)] {
    match inputs {
        Inputs::Wheels => &[("", 0)],
        Inputs::Pairs { .. } => &[("left_", 0), ("right_", 1)],
        Inputs::Rails => &[],
    }
}

/// The rail sides whose wear a row reports, as [`wheel_columns`].
fn rail_columns(inputs: Inputs) -> &'static [(&'static str, usize)] {
    match inputs {
        Inputs::Rails => &[("", 0)],
        Inputs::Pairs { rails: true } => &[("left_", 0), ("right_", 1)],
        _ => &[],
    }
}

/// The flange dimension and rail wear columns of `inputs`, with `maintenance_status` after
/// the wheels' dimensions.
fn maintenance_columns(inputs: Inputs) -> Vec<String> {
    let mut c = Vec::new();
    for (prefix, _) in wheel_columns(inputs) {
        c.extend(["sh_mm", "sd_mm", "qr_mm"].map(|n| format!("{prefix}{n}")));
    }
    if inputs.has_wheels() {
        c.push("maintenance_status".into());
    }
    for (prefix, _) in rail_columns(inputs) {
        c.extend(["vertical_wear_mm", "gauge_face_wear_mm"].map(|n| format!("{prefix}{n}")));
    }
    c
}

/// The maintenance status of a row's wheels: `ok`, or each broken limit (`Sd 33.06 > 33
/// mm`), prefixed by the wheel for pairs, or why the dimensions are undefined.
pub fn maintenance_status(inputs: Inputs, summary: &Summary) -> String {
    let wheels = &summary.maintenance.wheels;
    match inputs {
        Inputs::Rails => String::new(),
        Inputs::Wheels => wheels[0].status(),
        Inputs::Pairs { .. } => {
            let parts: Vec<String> = ["left", "right"]
                .iter()
                .zip(wheels)
                .filter(|(_, w)| w.status() != "ok")
                .map(|(side, w)| format!("{side} wheel: {}", w.status()))
                .collect();
            if parts.is_empty() {
                "ok".into()
            } else {
                parts.join("; ")
            }
        }
    }
}

/// Whether a row's wheels break a maintenance limit (their dimensions defined).
fn breaks_a_limit(row: &Row) -> bool {
    row.outcome
        .as_ref()
        .is_ok_and(|s| s.maintenance.wheels.iter().any(|w| !w.breaches.is_empty()))
}

/// The parameters' rows (names, units, definitions; values of `summary` or NaN).
fn parameter_rows(summary: Option<&Summary>) -> Vec<wheelrail::conicity::ParameterRow> {
    let undefined =
        wheelrail::conicity::Parameters::undefined(wheelrail::conicity::ConicityMethod::Klingel);
    summary.map_or(undefined, |s| s.parameters).rows()
}

/// The `#` lines and the header row of `fleet.csv`. They depend on the template and the
/// kind of inputs only (not on the shard, the thread count or the time), so that the CSVs
/// of the parts of a sharded fleet concatenate to the whole one's.
pub fn csv_header(fleet: &Fleet, template_path: &str) -> String {
    let t = fleet.template();
    let sweep = format!(
        "{} to {} mm, {} positions",
        t.sweep().shifts_mm().first().copied().unwrap_or(f64::NAN),
        t.sweep().shifts_mm().last().copied().unwrap_or(f64::NAN),
        t.sweep().len()
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
            profile_names(t.wheel_profiles()),
            profile_names(t.rail_profiles())
        ),
        super::tables::conicity_method_text(t.conicity().method()).to_string(),
        "y lateral displacement of the wheelset, positive to the left (track frame); delta_r = r_left - r_right; units in the column names: _mm millimetres, _per_mm 1/mm, _rad radians, _MPa N/mm^2; tan_gamma_e dimensionless; contact_point_jumps and sampling_artefacts counts".into(),
    ];
    let inputs = fleet.inputs();
    if inputs.has_wheels() {
        lines.push(format!(
            "sh_mm, sd_mm, qr_mm (per wheel for pairs: left_, right_): {}",
            super::tables::FLANGE_DIMENSIONS_TEXT
        ));
        let radii = t.nominal_radius_mm();
        for (side, radius) in ["left", "right"].iter().zip(radii) {
            let l = wheelrail::maintenance::Limits::with_overrides(2.0 * radius, t.limits());
            lines.push(format!(
                "limits of the {side} wheel (nominal diameter {} mm): {}",
                2.0 * radius,
                l.describe()
            ));
        }
        lines.push("maintenance_status: ok, or each limit a wheel breaks (value and limit), or why its dimensions are undefined; a limit broken is a result: it does not change the status column or the exit code".into());
    }
    if inputs.has_rails() {
        lines.push(format!(
            "vertical_wear_mm, gauge_face_wear_mm (per rail for pairs: left_, right_) at the gauge-point depth {} mm: {}; the nominal rails: {}",
            t.layout().gauge_point_depth_mm(),
            super::tables::RAIL_WEAR_TEXT,
            t.nominal_rails().map_or_else(|| profile_names(t.rail_profiles()), profile_names)
        ));
    }
    for r in parameter_rows(None) {
        lines.push(format!("{} ({}): {}", r.name, r.unit, r.definition));
    }
    if fleet.has_hertz() {
        lines.push(format!(
            "max_p0_MPa: the largest Hertz maximum pressure over the sweep and both wheels ({} method, {} contact, normal load {}, {} kN per wheel), at the wheelset shift max_p0_y_ws_mm on the wheel max_p0_side",
            t.hertz().method(),
            t.hertz_contact().name(),
            t.hertz().normal_load().name(),
            t.wheel_load_n() / 1000.0
        ));
    }
    let mut text: String = lines.iter().map(|l| format!("# {l}\n")).collect();
    text.push_str(&record(&columns(fleet)));
    text
}

fn profile_names(refs: &[wheelrail::scene::ProfileRef; 2]) -> String {
    let name = |r: &wheelrail::scene::ProfileRef| match r {
        wheelrail::scene::ProfileRef::BuiltIn(n) => n.clone(),
        wheelrail::scene::ProfileRef::File(p) => p.display().to_string(),
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

/// One cell of a fleet row, as [`csv_line`] writes it and [`table`] holds it.
enum Cell {
    /// A number, written as every CSV writes numbers (10 significant digits).
    Number(f64),
    /// A count (`contact_point_jumps`), written as an integer (`NaN` when undefined).
    Count(f64),
    /// Text.
    Text(String),
}

impl Cell {
    fn text(&self) -> String {
        match self {
            Cell::Number(v) => format_number(*v, CSV_FORMAT),
            Cell::Count(v) => format!("{v}"),
            Cell::Text(t) => t.clone(),
        }
    }
}

/// The cells of `row`, in the order of [`columns`].
fn cells(fleet: &Fleet, row: &Row) -> Vec<Cell> {
    let mut cells = vec![Cell::Text(row.id.clone())];
    for f in &row.files {
        cells.push(Cell::Text(
            f.path
                .as_ref()
                .map(|p| p.display().to_string())
                .unwrap_or_default(),
        ));
        cells.push(Cell::Text(f.sha256.clone().unwrap_or_default()));
    }
    let summary = row.outcome.as_ref().ok();
    cells.push(Cell::Text(match &row.outcome {
        Ok(_) => "ok".into(),
        Err(e) => e.to_string(),
    }));
    let mut notes = Vec::new();
    let inputs = fleet.inputs();
    for &(_, k) in wheel_columns(inputs) {
        let d = summary.and_then(|s| s.maintenance.wheels[k].dimensions.as_ref().ok());
        for v in [d.map(|d| d.sh_mm), d.map(|d| d.sd_mm), d.map(|d| d.qr_mm)] {
            cells.push(Cell::Number(v.unwrap_or(f64::NAN)));
        }
    }
    if inputs.has_wheels() {
        cells.push(Cell::Text(
            summary.map_or_else(String::new, |s| maintenance_status(inputs, s)),
        ));
    }
    for &(prefix, k) in rail_columns(inputs) {
        let wear = summary
            .and_then(|s| s.maintenance.rails.as_ref())
            .map(|r| &r[k]);
        let (vertical, face) = match wear {
            Some(Ok(w)) => (w.vertical_mm, w.gauge_face_mm),
            Some(Err(e)) => {
                notes.push(format!(
                    "{prefix}vertical_wear_mm, {prefix}gauge_face_wear_mm: {e}"
                ));
                (f64::NAN, f64::NAN)
            }
            None => (f64::NAN, f64::NAN),
        };
        cells.extend([Cell::Number(vertical), Cell::Number(face)]);
    }
    let rows = parameter_rows(summary);
    for r in &rows {
        let value = if summary.is_some() { r.value } else { f64::NAN };
        cells.push(if r.unit == "count" {
            Cell::Count(value)
        } else {
            Cell::Number(value)
        });
        if summary.is_some() && !r.value.is_finite() {
            notes.push(format!("{}: {}", r.name, r.undefined));
        }
    }
    if fleet.has_hertz() {
        match summary.and_then(|s| s.max_p0) {
            Some(m) => {
                cells.push(Cell::Number(m.p0_mpa));
                cells.push(Cell::Number(m.y_ws_mm));
                cells.push(Cell::Text(m.side.name().to_string()));
            }
            None => {
                cells.extend([
                    Cell::Number(f64::NAN),
                    Cell::Number(f64::NAN),
                    Cell::Text(String::new()),
                ]);
                if summary.is_some() {
                    notes.push("max_p0_MPa: no Hertz ellipse at any position".into());
                }
            }
        }
    }
    cells.push(Cell::Text(notes.join("; ")));
    cells
}

/// The line of `row` in `fleet.csv`: numbers as in every other CSV (10 significant digits,
/// the same text as a report's `parameters.csv`).
pub fn csv_line(fleet: &Fleet, row: &Row) -> String {
    let cells: Vec<String> = cells(fleet, row).iter().map(Cell::text).collect();
    record(&cells)
}

/// The rows of `fleet.csv` as one table (without its `#` lines): the columns of
/// [`columns`], numbers as numbers (a count too), text as text. Its numbers are the
/// unrounded values whose 10 significant digits `fleet.csv` prints.
///
/// # Errors
/// [`TableError::LengthMismatch`] for a row whose files are not the fleet's (a row of
/// another fleet: a caller's bug).
pub fn table(fleet: &Fleet, rows: &[Row]) -> Result<Table, TableError> {
    let names = columns(fleet);
    // The cells of a failed row say which columns hold numbers: every row has the same
    // kinds of cells in the same places.
    let no_files = wheelrail::fleet::Item {
        id: String::new(),
        wheels: None,
        rails: None,
    };
    let kinds = cells(
        fleet,
        &fleet.failed_row(&no_files, RowError::new(String::new())),
    );
    let rows: Vec<Vec<Cell>> = rows.iter().map(|r| cells(fleet, r)).collect();
    if let Some(r) = rows.iter().find(|r| r.len() != names.len()) {
        return Err(TableError::LengthMismatch {
            column: format!("the cells of row {}", r[0].text()),
            expected: names.len(),
            found: r.len(),
        });
    }
    let mut t = Table::new();
    for (j, (name, kind)) in names.into_iter().zip(&kinds).enumerate() {
        let data = match kind {
            Cell::Number(_) | Cell::Count(_) => ColumnData::Numeric(
                rows.iter()
                    .map(|r| match &r[j] {
                        Cell::Number(v) | Cell::Count(v) => *v,
                        Cell::Text(_) => f64::NAN,
                    })
                    .collect(),
            ),
            Cell::Text(_) => ColumnData::Text(rows.iter().map(|r| r[j].text().into()).collect()),
        };
        t.push_column(name, data)?;
    }
    Ok(t)
}

/// tan γe(3 mm) of a row, if it was assessed and the value is defined.
fn at3(row: &Row) -> Option<f64> {
    row.outcome
        .as_ref()
        .ok()
        .map(|s| s.parameters.tan_gamma_e_3mm)
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

/// Name and caption of the flange dimensions figure.
const FLANGE_FIGURE: (&str, &str) = (
    "fleet_flange_dimensions",
    "Each wheel's flange thickness Sd against its flange height Sh (EN 15313: Sh the flange tip above the taping-line point, Sd from the inner face to the flank 10 mm above it), the maintenance limits of the template's wheel as a dashed box ([limits], by default the TSI's for its diameter). Wheels that break a limit, qR included, are named with the limits they break (five: the one furthest beyond a limit of each kind of breach, then the furthest; the table below and fleet.csv's maintenance_status have all). Wheels whose dimensions are undefined are not drawn.",
);

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
/// [`Error::Chart`] when a figure cannot be rendered.
pub fn render(
    fleet: &Fleet,
    rows: &[Row],
    template_path: &str,
    reports: bool,
) -> Result<Vec<OutputFile>, Error> {
    let t = fleet.template();
    let limit = t.fleet().conicity_limit();
    let mut charts = vec![
        histogram(rows, limit),
        conicity_against_nonlinearity(rows, limit),
        conicity_functions(rows, limit, t.conicity().method().name()),
    ];
    let mut names = FIGURES.to_vec();
    if fleet.inputs().has_wheels() {
        let limits = wheelrail::maintenance::Limits::with_overrides(
            2.0 * t.nominal_radius_mm()[0],
            t.limits(),
        );
        names.insert(0, FLANGE_FIGURE);
        charts.insert(0, flange_dimensions(rows, fleet.inputs(), &limits));
    }
    let mut files = Vec::new();
    let mut entries = Vec::new();
    for ((name, caption), chart) in names.iter().zip(&charts) {
        let mut entry = FigureEntry {
            name: (*name).to_string(),
            caption: (*caption).to_string(),
            svg: String::new(),
            png: String::new(),
        };
        for format in t.formats() {
            let fail = |e: crate::chart::ChartError| Error::Chart(name.to_string(), e);
            let file = match format {
                ImageFormat::Svg => {
                    entry.svg = format!("{name}.svg");
                    OutputFile {
                        name: entry.svg.clone(),
                        bytes: crate::render_svg(chart).map_err(fail)?.into_bytes(),
                    }
                }
                ImageFormat::Png => {
                    entry.png = format!("{name}.png");
                    OutputFile {
                        name: entry.png.clone(),
                        bytes: crate::render_png(chart).map_err(fail)?,
                    }
                }
            };
            files.push(file);
        }
        entries.push(entry);
    }
    files.push(OutputFile {
        name: "index.html".into(),
        bytes: crate::render_html(&page(fleet, rows, template_path, reports, entries)).into_bytes(),
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
) -> crate::DataTable {
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
                number(p.tan_gamma_e_3mm, 4),
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
    crate::DataTable {
        title,
        header,
        rows: table_rows,
    }
}

/// The page's lines on the wheels over a maintenance limit and the rails' wear.
fn maintenance_summary(rows: &[Row], inputs: Inputs) -> Vec<String> {
    let assessed: Vec<&Summary> = rows
        .iter()
        .filter_map(|r| r.outcome.as_ref().ok())
        .collect();
    let mut lines = Vec::new();
    if inputs.has_wheels() {
        let offenders = rows.iter().filter(|r| breaks_a_limit(r)).count();
        let undefined = assessed
            .iter()
            .filter(|s| s.maintenance.wheels.iter().any(|w| w.dimensions.is_err()))
            .count();
        lines.push(format!(
            "{offenders} of {} assessed rows have a wheel over a maintenance limit (Sh, Sd, qR; maintenance_status in fleet.csv){}; a limit broken is a result and leaves the row's status and the exit code as they are.",
            assessed.len(),
            if undefined > 0 {
                format!(", {undefined} with flange dimensions undefined")
            } else {
                String::new()
            }
        ));
    }
    if inputs.has_rails() {
        use wheelrail::maintenance::RailWear;
        let vertical: fn(&RailWear) -> f64 = |w| w.vertical_mm;
        let gauge_face: fn(&RailWear) -> f64 = |w| w.gauge_face_mm;
        for (name, of) in [("vertical wear", vertical), ("gauge-face wear", gauge_face)] {
            let largest = rows
                .iter()
                .filter_map(|r| {
                    let s = r.outcome.as_ref().ok()?;
                    let rails = s.maintenance.rails.as_ref()?;
                    let v = rails
                        .iter()
                        .filter_map(|w| w.as_ref().ok())
                        .map(of)
                        .fold(f64::NAN, f64::max);
                    v.is_finite().then_some((v, r.id.as_str()))
                })
                .max_by(|a, b| a.0.total_cmp(&b.0));
            if let Some((v, id)) = largest {
                lines.push(format!("Largest {name}: {v:.2} mm ({id})."));
            }
        }
    }
    lines
}

/// The table of the wheels over a maintenance limit (none for a fleet of rails).
fn maintenance_table(rows: &[Row], inputs: Inputs) -> Vec<crate::DataTable> {
    if !inputs.has_wheels() {
        return Vec::new();
    }
    let table_rows: Vec<Vec<String>> = rows
        .iter()
        .filter(|r| breaks_a_limit(r))
        .take(MAX_LISTED)
        .filter_map(|r| {
            let s = r.outcome.as_ref().ok()?;
            let mut cells = vec![r.id.clone()];
            for &(_, k) in wheel_columns(inputs) {
                let d = s.maintenance.wheels[k].dimensions.as_ref().ok();
                cells.push(d.map_or("—".into(), |d| {
                    format!("{:.2}, {:.2}, {:.2}", d.sh_mm, d.sd_mm, d.qr_mm)
                }));
            }
            cells.push(maintenance_status(inputs, s));
            Some(cells)
        })
        .collect();
    let mut header = vec!["id".to_string()];
    for (prefix, _) in wheel_columns(inputs) {
        let side = prefix.trim_end_matches('_');
        header.push(if side.is_empty() {
            "Sh, Sd, qR (mm)".into()
        } else {
            format!("{side} wheel Sh, Sd, qR (mm)")
        });
    }
    header.push("limits broken".into());
    vec![crate::DataTable {
        title: "Wheels over a maintenance limit".into(),
        header,
        rows: table_rows,
    }]
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
                r.outcome
                    .as_ref()
                    .err()
                    .map_or(String::new(), ToString::to_string)
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
    let limit = t.fleet().conicity_limit();
    let failed: Vec<&Row> = rows.iter().filter(|r| r.outcome.is_err()).collect();
    ReportPage {
        title: format!("Fleet assessment: {}", t.title()),
        summary: [
            maintenance_summary(rows, fleet.inputs()),
            summary(rows, failed.len(), limit),
        ]
        .concat(),
        parameters: vec![
            ("template scene".into(), template_path.to_string()),
            (
                "sweep (mm)".into(),
                format!(
                    "{} to {}, {} positions",
                    t.sweep().shifts_mm().first().copied().unwrap_or(f64::NAN),
                    t.sweep().shifts_mm().last().copied().unwrap_or(f64::NAN),
                    t.sweep().len()
                ),
            ),
            ("equivalent conicity method".into(), t.conicity().method().name().into()),
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
            description: "one row per profile or pair: files, sha256, status, flange dimensions Sh, Sd, qR and the limits broken (or rail wear), tan γe at 2, 3, 4 mm, nonlinearity, flange contact, jumps (units in the column names)".into(),
        }],
        data_tables: [
            maintenance_table(rows, fleet.inputs()),
            vec![listed_table(rows, limit, fleet.has_hertz(), reports)],
        ]
        .concat(),
        notes: failed_notes(&failed),
        ..ReportPage::default()
    }
}
