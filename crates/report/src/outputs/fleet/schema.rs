//! The schema of `fleet.csv`: its `#` lines and header row, one line per row, and the rows
//! as one [`Table`] (the same columns and numbers, for a library user).

use super::super::CSV_FORMAT;
use crate::table::format_number;
use crate::{ColumnData, Table, TableError};
use wheelrail::fleet::{Fleet, Inputs, Row, RowError, Summary};

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
pub(super) fn wheel_columns(inputs: Inputs) -> &'static [(&'static str, usize)] {
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
        super::super::tables::conicity_method_text(t.conicity().method()).to_string(),
        "y lateral displacement of the wheelset, positive to the left (track frame); delta_r = r_left - r_right; units in the column names: _mm millimetres, _per_mm 1/mm, _rad radians, _MPa N/mm^2; tan_gamma_e dimensionless; contact_point_jumps and sampling_artefacts counts".into(),
    ];
    let inputs = fleet.inputs();
    if inputs.has_wheels() {
        lines.push(format!(
            "sh_mm, sd_mm, qr_mm (per wheel for pairs: left_, right_): {}",
            super::super::tables::FLANGE_DIMENSIONS_TEXT
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
            super::super::tables::RAIL_WEAR_TEXT,
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
