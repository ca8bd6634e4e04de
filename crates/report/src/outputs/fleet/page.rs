//! The fleet's `index.html` page: summary lines, the pairs over the limit, the wheels over a
//! maintenance limit, the failed rows.

use super::charts::{at3, worst};
use super::schema::{maintenance_status, wheel_columns};
use crate::{FigureEntry, ReportPage, TableEntry};
use wheelrail::fleet::{Fleet, Inputs, Row, Summary};

/// Whether a row's wheels break a maintenance limit (their dimensions defined).
fn breaks_a_limit(row: &Row) -> bool {
    row.outcome
        .as_ref()
        .is_ok_and(|s| s.maintenance.wheels.iter().any(|w| !w.breaches.is_empty()))
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

/// The page of the fleet `rows` run through the template `template_path`, its figures
/// `figures`.
pub(super) fn page(
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
