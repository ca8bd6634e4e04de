//! MiniProf `.whl` / `.ban` profiles; format and frame mapping in the
//! [parent module docs](super).

use super::error::{Field, ReadError};
use super::fields::{self, RawPoint};
use super::validate;
use crate::profile::ProfileKind;

const EXPECTED: &str = "a number in mm";

/// Lateral distance from the inner face (flange back) of a wheel to its taping line, mm
/// (EN 13715; the crate docs' standard-gauge layout).
pub(crate) const TAPING_LINE_FROM_INNER_FACE_MM: f64 = 70.0;

/// Characters that start a comment line (CONTACT's `read_miniprof_profile` uses the same).
const COMMENT_STARTS: [char; 4] = ['"', '!', '%', '#'];

/// The marker MiniProf writes on the first line of wheel files.
const WHEEL_MARKER: &str = "#MINIWHEELPROF";

/// Parses a MiniProf file and returns its points in the side frame of `kind`.
pub(super) fn parse(
    text: &str,
    kind: ProfileKind,
    origin: &str,
) -> Result<Vec<RawPoint>, ReadError> {
    let mut in_header = true;
    let mut saw_content = false;
    let mut column_x = 0;
    let mut column_y = 1;
    let mut offset = [0.0; 2];
    // (X, Y, line) in file axes.
    let mut rows: Vec<(f64, f64, usize)> = Vec::new();

    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let content = raw.trim();
        if content.starts_with(WHEEL_MARKER) && kind == ProfileKind::Rail {
            return Err(ReadError::WrongKind {
                origin: origin.to_owned(),
                line: Some(line),
                expected: kind,
                found: ProfileKind::Wheel,
            });
        }
        if content.is_empty() {
            // The blank line after the header starts the data.
            if saw_content {
                in_header = false;
            }
            continue;
        }
        if content.starts_with(COMMENT_STARTS) {
            continue;
        }
        saw_content = true;
        if in_header {
            let all_numbers = {
                let mut count = 0;
                let all = fields::tokens(content).all(|t| {
                    count += 1;
                    fields::is_number(t)
                });
                all && count >= 2
            };
            if !all_numbers {
                if let Some((key, value)) = content.split_once('=') {
                    header_entry(
                        key.trim(),
                        value.trim(),
                        origin,
                        line,
                        &mut column_x,
                        &mut column_y,
                        &mut offset,
                    )?;
                }
                // Free-text header lines (avg_wheel.whl, Car7216_0001r.whl) carry no data.
                continue;
            }
            // Data without the blank line before them (plain two-column files).
            in_header = false;
        }
        if content.contains('=')
            && fields::tokens(content)
                .next()
                .is_some_and(|t| !fields::is_number(t))
        {
            return Err(ReadError::Malformed {
                origin: origin.to_owned(),
                line,
                problem: format!("header entry `{content}` after the data started"),
            });
        }
        let tokens: Vec<&str> = fields::tokens(content).collect();
        let value = |column: usize| match tokens.get(column) {
            Some(t) => fields::number(t, origin, line, Field::Column(column + 1), EXPECTED),
            None => Err(ReadError::MissingField {
                origin: origin.to_owned(),
                line,
                column: column + 1,
            }),
        };
        // Read in column order, so that the first bad column is the one reported.
        let (x, y) = if column_x < column_y {
            let x = value(column_x)?;
            (x, value(column_y)?)
        } else {
            let y = value(column_y)?;
            (value(column_x)?, y)
        };
        rows.push((x + offset[0], y + offset[1], line));
    }
    if !saw_content {
        return Err(ReadError::Empty {
            origin: origin.to_owned(),
        });
    }
    Ok(to_side_frame(&rows, kind))
}

/// Handles one `Key=Value` header line: the column layout and offsets; other keys are
/// ignored (MiniProf writes dozens: instrument, alarms, location, ...).
fn header_entry(
    key: &str,
    value: &str,
    origin: &str,
    line: usize,
    column_x: &mut usize,
    column_y: &mut usize,
    offset: &mut [f64; 2],
) -> Result<(), ReadError> {
    match key {
        "ColumnDef" => {
            let names: Vec<&str> = value.split(',').map(str::trim).collect();
            let find = |name: &str| names.iter().position(|n| n.eq_ignore_ascii_case(name));
            match (find("X"), find("Y")) {
                (Some(x), Some(y)) => {
                    *column_x = x;
                    *column_y = y;
                }
                _ => {
                    return Err(ReadError::Malformed {
                        origin: origin.to_owned(),
                        line,
                        problem: format!("ColumnDef={value} does not name both X and Y columns"),
                    });
                }
            }
        }
        "XOffset" | "Xoffset" | "YOffset" | "Yoffset" => {
            // Empty values (avg_low2.ban: `XOffset=`) mean no offset.
            let v = if value.is_empty() {
                0.0
            } else {
                fields::number(value, origin, line, Field::Key(key.to_owned()), EXPECTED)?
            };
            offset[usize::from(key.starts_with('Y'))] = v;
        }
        _ => {}
    }
    Ok(())
}

/// MiniProf axes -> side frame (evidence in the parent module docs).
fn to_side_frame(rows: &[(f64, f64, usize)], kind: ProfileKind) -> Vec<RawPoint> {
    match kind {
        ProfileKind::Wheel => rows
            .iter()
            .map(|&(x, y, line)| RawPoint {
                lat: x - TAPING_LINE_FROM_INNER_FACE_MM,
                vert: y,
                line,
            })
            .collect(),
        ProfileKind::Rail => {
            let verticals: Vec<f64> = rows.iter().map(|r| r.1).collect();
            let up = if validate::rail_vertical_is_up(&verticals) {
                1.0
            } else {
                -1.0
            };
            rows.iter()
                .map(|&(x, y, line)| RawPoint {
                    lat: -x,
                    vert: up * y,
                    line,
                })
                .collect()
        }
    }
}
