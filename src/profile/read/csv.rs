//! The project's CSV profile format (defined in the [parent module docs](super)).

use super::error::{Field, ReadError};
use super::fields::{self, RawPoint};
use crate::profile::ProfileKind;

const EXPECTED: &str = "a number in mm";

/// Parses the CSV text into side-frame points (the file is in the side frame already).
pub(super) fn parse(
    text: &str,
    kind: ProfileKind,
    origin: &str,
) -> Result<Vec<RawPoint>, ReadError> {
    let mut reader = ::csv::ReaderBuilder::new()
        .has_headers(false)
        .comment(Some(b'#'))
        .flexible(true)
        .from_reader(text.as_bytes());
    let mut header_seen = false;
    let mut points = Vec::new();
    // One record reused for every line: a fleet reads thousands of files.
    let mut record = ::csv::StringRecord::new();
    while reader
        .read_record(&mut record)
        .map_err(|e| ReadError::Malformed {
            origin: origin.to_owned(),
            line: e
                .position()
                .map_or(0, |p| usize::try_from(p.line()).unwrap_or(usize::MAX)),
            problem: format!("CSV syntax error: {e}"),
        })?
    {
        let line = record
            .position()
            .map_or(0, |p| usize::try_from(p.line()).unwrap_or(usize::MAX));
        if !header_seen {
            check_header(&record, kind, origin, line)?;
            header_seen = true;
            continue;
        }
        let value = |column: usize| match field(&record, column - 1) {
            None | Some("") => Err(ReadError::MissingField {
                origin: origin.to_owned(),
                line,
                column,
            }),
            Some(t) => fields::number(t, origin, line, Field::Column(column), EXPECTED),
        };
        let lat = value(1)?;
        let vert = value(2)?;
        points.push(RawPoint { lat, vert, line });
    }
    if !header_seen {
        // Only comments: nothing to read.
        return Err(ReadError::Empty {
            origin: origin.to_owned(),
        });
    }
    Ok(points)
}

/// Field `i` of `record` without surrounding whitespace (Unicode, as the csv crate's
/// `Trim::All` leaves a field: trimming here instead of in the reader spares it two copies
/// of every record).
fn field(record: &::csv::StringRecord, i: usize) -> Option<&str> {
    record.get(i).map(str::trim)
}

fn check_header(
    record: &::csv::StringRecord,
    kind: ProfileKind,
    origin: &str,
    line: usize,
) -> Result<(), ReadError> {
    if field(record, 0).is_some_and(fields::is_number) {
        return Err(ReadError::MissingHeader {
            origin: origin.to_owned(),
            line,
        });
    }
    for column in 1..=2 {
        let name = match field(record, column - 1) {
            None | Some("") => {
                return Err(ReadError::MissingField {
                    origin: origin.to_owned(),
                    line,
                    column,
                });
            }
            Some(name) => name,
        };
        check_unit(name, origin, line, column)?;
    }
    let first = field(record, 0).unwrap_or_default().to_ascii_lowercase();
    let declared = match first.as_str() {
        "s_mm" => Some(ProfileKind::Wheel),
        "y_mm" => Some(ProfileKind::Rail),
        _ => None,
    };
    super::validate::check_kind(declared.map(|k| (k, Some(line))), kind, origin)
}

fn check_unit(name: &str, origin: &str, line: usize, column: usize) -> Result<(), ReadError> {
    let lower = name.to_ascii_lowercase();
    if lower.ends_with("_mm") {
        return Ok(());
    }
    let other = [
        ("_um", "micrometres"),
        ("_cm", "centimetres"),
        ("_m", "metres"),
        ("_in", "inches"),
    ]
    .into_iter()
    .find(|(suffix, _)| lower.ends_with(suffix));
    Err(match other {
        Some((_, unit)) => ReadError::WrongUnits {
            origin: origin.to_owned(),
            line,
            column,
            name: name.to_owned(),
            unit,
        },
        None => ReadError::MissingUnits {
            origin: origin.to_owned(),
            line,
            column,
            name: name.to_owned(),
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_and_header_are_read_without_surrounding_whitespace() {
        // ASCII and Unicode whitespace (no-break and ideographic spaces), as `Trim::All`.
        let text = "# c\n  y_mm\t, z_mm \n 1.5 ,\u{a0}-2.25\u{3000}\n2,3\n";
        let points = parse(text, ProfileKind::Rail, "t.csv").unwrap();
        let got: Vec<[f64; 2]> = points.iter().map(|p| [p.lat, p.vert]).collect();
        assert_eq!(got, [[1.5, -2.25], [2.0, 3.0]]);
        assert_eq!(points[0].line, 3);
        // A field of whitespace alone is missing.
        let missing = parse("y_mm,z_mm\n1,  \n", ProfileKind::Rail, "t.csv");
        assert!(matches!(
            missing,
            Err(ReadError::MissingField {
                line: 2,
                column: 2,
                ..
            })
        ));
    }
}
