//! The project's CSV profile format (defined in the [parent module docs](super)).

use std::io::Read;

use super::error::{Field, ReadError};
use super::fields::{self, RawPoint};
use crate::delimited::Separator;
use crate::profile::ProfileKind;

const EXPECTED: &str = "a number in mm";

/// Parses the CSV text into side-frame points (the file is in the side frame already).
///
/// Records are read by the `csv` crate: fields separated by commas, semicolons or tabs, as
/// the header line is ([`Separator::of_text`]; with semicolons or tabs a number may have a
/// decimal comma), quoted fields, lines starting with `#` as comments, blank lines skipped,
/// records of any length (further columns are ignored). The first record is the header,
/// checked here ([`check_header`]) so that its errors name its line; each record after it is
/// a point.
///
/// Two of the crate's ways are corrected. It reports a record on the line after the
/// previous record (blank and comment lines between them, and the line feed of a CRLF end,
/// not counted): the line here is counted from the record's first byte ([`LineCount`]).
/// And it reads a comment that ends the text without a line end as a record of one empty
/// field: the text is read with a line end after it.
pub(super) fn parse(
    text: &str,
    kind: ProfileKind,
    origin: &str,
) -> Result<Vec<RawPoint>, ReadError> {
    let separator = Separator::of_text(text);
    let line_end: &[u8] = if text.ends_with('\n') { b"" } else { b"\n" };
    let mut reader = ::csv::ReaderBuilder::new()
        .has_headers(false)
        .comment(Some(b'#'))
        .delimiter(separator.byte())
        .flexible(true)
        .from_reader(text.as_bytes().chain(line_end));
    let mut rows = Rows::new(kind, origin, separator);
    // The crate's positions increase: lines are counted on from the last record's start.
    let mut lines = LineCount::default();
    let mut line_at = |p: Option<&::csv::Position>| {
        p.map_or(0, |p| {
            lines.record_line(text, usize::try_from(p.byte()).unwrap_or(usize::MAX))
        })
    };
    // One record reused for every line: a fleet reads thousands of files.
    let mut record = ::csv::StringRecord::new();
    while reader
        .read_record(&mut record)
        .map_err(|e| ReadError::Malformed {
            origin: origin.to_owned(),
            line: line_at(e.position()),
            problem: format!("CSV syntax error: {e}"),
        })?
    {
        let line = line_at(record.position());
        rows.push(&record, line)?;
    }
    rows.finish()
}

/// The lines of a text counted up to a byte, on from where the last count ended.
#[derive(Default)]
struct LineCount {
    /// The byte counted up to, and the line ends before it.
    at: usize,
    ends: usize,
}

impl LineCount {
    /// The 1-based line of the record the `csv` crate read from byte `from` of `text` (at or
    /// after the last one asked for): the crate's position may lie on the line ends, blank
    /// lines and comment lines before the record, which are passed over. A line ends at
    /// `\n`, `\r\n` or a lone `\r`.
    fn record_line(&mut self, text: &str, from: usize) -> usize {
        let bytes = text.as_bytes();
        let mut at = from.min(bytes.len());
        loop {
            match bytes.get(at) {
                Some(b'\r' | b'\n') => at += 1,
                Some(b'#') if at == 0 || matches!(bytes[at - 1], b'\r' | b'\n') => {
                    // A comment, to the crate's end of it: the next line feed.
                    at += bytes[at..]
                        .iter()
                        .position(|&b| b == b'\n')
                        .unwrap_or(bytes.len() - at);
                }
                _ => break,
            }
        }
        if at < self.at {
            // Asked out of order: counted again from the start.
            *self = LineCount::default();
        }
        let start = self.at;
        self.ends += (start..at)
            .filter(|&i| {
                bytes[i] == b'\n' || (bytes[i] == b'\r' && bytes.get(i + 1) != Some(&b'\n'))
            })
            .count();
        self.at = at;
        self.ends + 1
    }
}

/// The records read so far: the header first, then one point per record.
struct Rows<'a> {
    kind: ProfileKind,
    origin: &'a str,
    separator: Separator,
    header_seen: bool,
    points: Vec<RawPoint>,
}

impl<'a> Rows<'a> {
    fn new(kind: ProfileKind, origin: &'a str, separator: Separator) -> Rows<'a> {
        Rows {
            kind,
            origin,
            separator,
            header_seen: false,
            points: Vec::new(),
        }
    }

    /// Takes `record` on 1-based `line`: the header, or a point. A point that does not read
    /// on a line holding another separator than the header's is a
    /// [`ReadError::SeparatorMismatch`].
    fn push(&mut self, record: &::csv::StringRecord, line: usize) -> Result<(), ReadError> {
        let fields = [field(record, 0), field(record, 1)];
        if !self.header_seen {
            check_header(fields, self.kind, self.origin, line)?;
            self.header_seen = true;
            return Ok(());
        }
        let value = |column: usize| match fields[column - 1] {
            None | Some("") => Err(ReadError::MissingField {
                origin: self.origin.to_owned(),
                line,
                column,
            }),
            Some(t) => fields::number(
                &self.separator.number_text(t),
                self.origin,
                line,
                Field::Column(column),
                EXPECTED,
            )
            .map_err(|e| match e {
                // The value as written, not as converted from a decimal comma.
                ReadError::NonNumeric { value, .. } if value.contains('.') && t.contains(',') => {
                    ReadError::NonNumeric {
                        origin: self.origin.to_owned(),
                        line,
                        field: Field::Column(column),
                        value: t.to_owned(),
                        expected: EXPECTED,
                    }
                }
                e => e,
            }),
        };
        let point = value(1).and_then(|lat| {
            Ok(RawPoint {
                lat,
                vert: value(2)?,
                line,
            })
        });
        match point {
            Ok(p) => {
                self.points.push(p);
                Ok(())
            }
            Err(e) => Err(
                match self.separator.other_in(&joined(record, self.separator)) {
                    Some(found) => ReadError::SeparatorMismatch {
                        origin: self.origin.to_owned(),
                        line,
                        header: self.separator,
                        found,
                    },
                    None => e,
                },
            ),
        }
    }

    /// The points, or [`ReadError::Empty`] for text of comments only.
    fn finish(self) -> Result<Vec<RawPoint>, ReadError> {
        if !self.header_seen {
            // Only comments: nothing to read.
            return Err(ReadError::Empty {
                origin: self.origin.to_owned(),
            });
        }
        Ok(self.points)
    }
}

/// The fields of `record` joined by `separator`: the line as written, less its quotes.
fn joined(record: &::csv::StringRecord, separator: Separator) -> String {
    record
        .iter()
        .collect::<Vec<_>>()
        .join(&separator.char().to_string())
}

/// Field `i` of `record` without surrounding whitespace (Unicode, as the csv crate's
/// `Trim::All` leaves a field: trimming here instead of in the reader spares it two copies
/// of every record).
fn field(record: &::csv::StringRecord, i: usize) -> Option<&str> {
    record.get(i).map(str::trim)
}

fn check_header(
    fields: [Option<&str>; 2],
    kind: ProfileKind,
    origin: &str,
    line: usize,
) -> Result<(), ReadError> {
    if fields[0].is_some_and(fields::is_number) {
        return Err(ReadError::MissingHeader {
            origin: origin.to_owned(),
            line,
        });
    }
    if fields[1].is_none() {
        return Err(ReadError::OneColumnHeader {
            origin: origin.to_owned(),
            line,
        });
    }
    for column in 1..=2 {
        let name = match fields[column - 1] {
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
    let first = fields[0].unwrap_or_default().to_ascii_lowercase();
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

    /// Line ends of every kind (LF, CRLF, a lone CR, none after the last line), a comment
    /// ending the text with or without a line end, quoted fields and a quote in a comment
    /// read to the same points on the same lines.
    #[test]
    fn line_ends_comments_and_quotes_read_to_the_points_on_their_lines() {
        for (text, first) in [
            ("y_mm,z_mm\n1,2\n3,4\n", 2),
            ("y_mm,z_mm\r\n1,2\r\n3,4\r\n", 2),
            ("y_mm,z_mm\r1,2\r3,4\r", 2),
            ("y_mm,z_mm\n1,2\n3,4", 2),
            ("y_mm,z_mm\n1,2\n3,4\n# the end", 2),
            ("y_mm,z_mm\n1,2\n3,4\n#c\r", 2),
            ("y_mm,z_mm\n\"1\",2\n3,\"4\"\n", 2),
            ("# a \"quote\"\ny_mm,z_mm\n1,2\n3,4\n", 3),
        ] {
            let points = parse(text, ProfileKind::Rail, "t.csv").unwrap();
            let got: Vec<(f64, f64, usize)> =
                points.iter().map(|p| (p.lat, p.vert, p.line)).collect();
            assert_eq!(got, [(1.0, 2.0, first), (3.0, 4.0, first + 1)], "{text:?}");
        }
        // A quoted field keeps its comma: "1,5" is one field, not a number.
        let quoted = parse("y_mm,z_mm\n\"1,5\",2\n", ProfileKind::Rail, "t.csv");
        assert!(
            matches!(&quoted, Err(ReadError::NonNumeric { line: 2, value, .. }) if value == "1,5"),
            "{quoted:?}"
        );
    }

    /// Semicolons and tabs, as the header has them, with decimal commas or points; in quoted
    /// fields too.
    #[test]
    fn semicolons_and_tabs_are_read_with_decimal_commas_or_points() {
        let want = [[-12.5, 3.25], [0.0, -1.0], [1.5, 2.0]];
        for (sep, text) in [
            (";", "s_mm;F_mm\n-12,5;3,25\n0;-1\n1.5 ; 2,0\n"),
            ("\t", "s_mm\tF_mm\r\n-12,5\t3,25\r\n0\t-1\r\n1.5\t2\r\n"),
            (
                ";",
                "# export\n\"s_mm\";\"F_mm\"\n\"-12,5\";3,25\n0;-1\n1,5;2\n",
            ),
        ] {
            let points = parse(text, ProfileKind::Wheel, "t.csv").unwrap();
            let got: Vec<[f64; 2]> = points.iter().map(|p| [p.lat, p.vert]).collect();
            assert_eq!(got, want, "{sep:?}: {text:?}");
        }
    }

    /// A row that does not read under its header's separator, and holds another, is refused
    /// naming both; a header of one column says so.
    #[test]
    fn a_mixed_separator_or_a_one_column_header_is_named() {
        for (text, line, message) in [
            (
                "s_mm,F_mm\n1,2\n1,5;2,5\n",
                3,
                "t.csv:3: this row separates its fields by semicolons, but the header by commas",
            ),
            (
                "s_mm;F_mm\n1;2\n1.5,2.5\n",
                3,
                "t.csv:3: this row separates its fields by commas, but the header by semicolons",
            ),
            (
                "s_mm\tF_mm\n1;2\n",
                2,
                "t.csv:2: this row separates its fields by semicolons, but the header by tabs",
            ),
            (
                "# c\ns_mm F_mm\n1 2\n",
                2,
                "t.csv:2: the header names one column; a profile CSV names two, separated by commas, semicolons or tabs",
            ),
        ] {
            let e = parse(text, ProfileKind::Wheel, "t.csv").unwrap_err();
            assert_eq!(e.line(), Some(line), "{text:?}");
            assert!(e.to_string().starts_with(message), "{text:?}: {e}");
        }
    }

    /// Errors and points name the line they are on, counting every line of the file:
    /// blank lines, comments and CRLF ends included, fields quoted or not (the crate's own
    /// count skips the first two and counts a CRLF file's rows one low).
    #[test]
    fn lines_are_the_file_lines() {
        let lines = |text: &str| match parse(text, ProfileKind::Rail, "t.csv") {
            Ok(points) => points.iter().map(|p| p.line).collect::<Vec<_>>(),
            Err(ReadError::NonNumeric { line, .. }) => vec![line],
            Err(e) => panic!("{e}"),
        };
        for end in ["\n", "\r\n"] {
            for quote in ["", "\""] {
                let text = ["# c", "y_mm,z_mm", "", "# c", "1,2", "", "3,4"]
                    .join(end)
                    .replace("3,", &format!("{quote}3{quote},"));
                assert_eq!(lines(&text), [5, 7], "{text:?}");
                let bad = format!("{text}{end}{end}# c{end}5,x{end}");
                assert_eq!(lines(&bad), [10], "{bad:?}");
            }
        }
    }
}
