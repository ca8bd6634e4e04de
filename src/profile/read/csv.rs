//! The project's CSV profile format (defined in the [parent module docs](super)).

use super::error::{Field, ReadError};
use super::fields::{self, RawPoint};
use crate::delimited::Separator;
use crate::profile::ProfileKind;

const EXPECTED: &str = "a number in mm";

/// Parses the CSV text into side-frame points (the file is in the side frame already).
///
/// Fields are separated by commas, semicolons or tabs, as the header line is
/// ([`Separator::of_header`]); with semicolons or tabs a number may have a decimal comma.
///
/// Text whose lines hold no quote and no carriage return but before a line feed (every
/// file the project and its users' spreadsheets write) is split into lines and fields
/// directly ([`parse_plain`]); anything else goes through the `csv` crate
/// ([`parse_quoted`]). The two read plain text to the same points and the same errors,
/// each naming its true 1-based line (the test `plain_lines_read_as_the_csv_crate_reads_them`);
/// the direct path spares the crate's reader set-up and record copies: 0.8 M of the 2.6 M
/// instructions the two 1000-point profiles of the EN 15302 scene of `benches/data` took
/// to parse. A line of two numbers in the fast path's form is read in one pass
/// ([`point_row`]).
pub(super) fn parse(
    text: &str,
    kind: ProfileKind,
    origin: &str,
) -> Result<Vec<RawPoint>, ReadError> {
    let separator = Separator::of_text(text);
    parse_plain(text, kind, origin, separator)
        .unwrap_or_else(|| parse_quoted(text, kind, origin, separator))
}

/// [`parse`] of plain text, or `None` at the first line that is not plain: one with a
/// quote (which the crate would read as the start of a quoted field) or a carriage return
/// but before its line feed (a line end of its own). An error before such a line is the
/// crate's error too.
///
/// As the crate reads plain text: records end at `\n` (a `\r` before it dropped), empty
/// lines are skipped, a line starting with `#` is a comment (whatever it holds), and
/// fields are split at every `separator`.
fn parse_plain(
    text: &str,
    kind: ProfileKind,
    origin: &str,
    separator: Separator,
) -> Option<Result<Vec<RawPoint>, ReadError>> {
    let mut rows = Rows::new(kind, origin, separator);
    let bytes = text.as_bytes();
    // The start of the line, and its 1-based number.
    let (mut at, mut number) = (0, 1);
    // As `text.split('\n')`: the piece after a final line feed is an empty line (skipped).
    while at < bytes.len() {
        if rows.header_seen
            && let Some((lat, vert, next)) = point_row(&bytes[at..], separator.byte())
        {
            rows.points.push(RawPoint {
                lat,
                vert,
                line: number,
            });
            (at, number) = (at + next, number + 1);
            continue;
        }
        let end = bytes[at..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |n| at + n);
        let line = &text[at..end];
        (at, number) = (end + 1, number + 1);
        let line = line.strip_suffix('\r').unwrap_or(line);
        if line.contains('\r') {
            return None;
        }
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if let Err(e) = rows.push(first_two_fields(line, separator.byte())?, line, number - 1) {
            return Some(Err(e));
        }
    }
    Some(rows.finish())
}

/// The point of a plain data line at the start of `bytes` when it is two numbers that
/// [`fields::decimal_prefix`] reads, each between optional spaces, with the `separator`
/// between them and after them only a line end or a separator and more fields without a
/// quote or a carriage return: `(lateral, vertical, length of the line with its end)`.
/// `None` for any other line (a header, a comment, a blank line, a decimal comma, an error),
/// which [`Rows::push`] then reads as before.
///
/// A line this accepts reads the same through [`first_two_fields`] and [`Rows::push`]: its
/// two fields, trimmed, are the numbers' text, which `str::parse` reads to the same value.
/// Why: splitting the text into lines, each line into fields, trimming them and giving
/// each to `str::parse` made the parse of the two 1001-point EN 15302 reference files
/// (`tests/data/en15302/`) 3.10 M instructions; this pass, with [`fields::decimal_prefix`],
/// makes it 1.16 M, and with its eight-bytes-at-a-time reading 0.98 M (callgrind, the
/// `report` of the E1 scene).
fn point_row(bytes: &[u8], separator: u8) -> Option<(f64, f64, usize)> {
    let spaces = |from: usize| {
        from + bytes[from..]
            .iter()
            .position(|&b| b != b' ')
            .unwrap_or(bytes.len() - from)
    };
    let mut at = spaces(0);
    let (lat, used) = fields::decimal_prefix(&bytes[at..])?;
    at = spaces(at + used);
    if bytes.get(at) != Some(&separator) {
        return None;
    }
    at = spaces(at + 1);
    let (vert, used) = fields::decimal_prefix(&bytes[at..])?;
    at = spaces(at + used);
    // The line's end: further fields are passed over, as long as they are plain.
    if bytes.get(at) == Some(&separator) {
        at += bytes[at..]
            .iter()
            .position(|&b| matches!(b, b'\n' | b'\r' | b'"'))
            .unwrap_or(bytes.len() - at);
    }
    match bytes.get(at..).unwrap_or_default() {
        [] => Some((lat, vert, at)),
        [b'\n', ..] | [b'\r'] => Some((lat, vert, at + 1)),
        [b'\r', b'\n', ..] => Some((lat, vert, at + 2)),
        _ => None,
    }
}

/// The first two fields of a record's `line`, split at `separator`, without surrounding
/// whitespace (`None` past its end), or `None` when the line holds a quote (not plain, see
/// [`parse_plain`]). One pass over the bytes: the separators and quotes looked for are
/// ASCII, so they are never part of a multi-byte character.
fn first_two_fields(line: &str, separator: u8) -> Option<[Option<&str>; 2]> {
    let mut commas = [line.len(); 2];
    let mut found = 0;
    for (i, &b) in line.as_bytes().iter().enumerate() {
        match b {
            b'"' => return None,
            b if b == separator && found < 2 => {
                commas[found] = i;
                found += 1;
            }
            _ => {}
        }
    }
    let first = line[..commas[0]].trim();
    let second = (found > 0).then(|| line[commas[0] + 1..commas[1]].trim());
    Some([Some(first), second])
}

/// [`parse`] through the `csv` crate: quoted fields, lone carriage returns.
///
/// Two of the crate's ways are corrected. It reports a record on the line after the
/// previous record (blank and comment lines between them, and the line feed of a CRLF end,
/// not counted): the line here is counted from the record's first byte ([`LineCount`]).
/// And it reads a comment that ends the text without a line end as a record of one empty
/// field: the text is given a line end first.
fn parse_quoted(
    text: &str,
    kind: ProfileKind,
    origin: &str,
    separator: Separator,
) -> Result<Vec<RawPoint>, ReadError> {
    let ended;
    let text = if text.ends_with('\n') {
        text
    } else {
        ended = format!("{text}\n");
        &ended
    };
    let mut reader = ::csv::ReaderBuilder::new()
        .has_headers(false)
        .comment(Some(b'#'))
        .delimiter(separator.byte())
        .flexible(true)
        .from_reader(text.as_bytes());
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
        let joined = record
            .iter()
            .collect::<Vec<_>>()
            .join(&separator.char().to_string());
        rows.push([field(&record, 0), field(&record, 1)], &joined, line)?;
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

    /// Takes the record `text` on 1-based `line` whose first two fields, without
    /// surrounding whitespace, are `fields` (`None` past the record's end): the header, or
    /// a point. A point that does not read on a line holding another separator than the
    /// header's is a [`ReadError::SeparatorMismatch`].
    fn push(
        &mut self,
        fields: [Option<&str>; 2],
        text: &str,
        line: usize,
    ) -> Result<(), ReadError> {
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
            Err(e) => Err(match self.separator.other_in(text) {
                Some(found) => ReadError::SeparatorMismatch {
                    origin: self.origin.to_owned(),
                    line,
                    header: self.separator,
                    found,
                },
                None => e,
            }),
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

    /// The separator `parse` reads `text` with.
    fn separator(text: &str) -> Separator {
        Separator::of_text(text)
    }

    /// Both readers' outcome on `text`: the points with their lines, or the error's message
    /// and variant.
    fn outcomes(text: &str) -> [String; 2] {
        let show = |r: Result<Vec<RawPoint>, ReadError>| match r {
            Ok(points) => format!("{points:?}"),
            Err(e) => format!("{e} / {e:?}"),
        };
        [
            show(
                parse_plain(text, ProfileKind::Rail, "t.csv", separator(text)).expect("plain text"),
            ),
            show(parse_quoted(
                text,
                ProfileKind::Rail,
                "t.csv",
                separator(text),
            )),
        ]
    }

    #[test]
    fn plain_lines_read_as_the_csv_crate_reads_them() {
        // Lines of every kind the plain path splits itself, joined at random (SplitMix64):
        // comments, blank lines, CRLF ends, whitespace, missing and extra fields, words,
        // non-finite numbers, headers of both kinds and wrong units.
        let good = [
            "y_mm,z_mm",
            "# comment",
            "#",
            "",
            " ",
            "\t",
            "1.5,-2.25",
            " 2 ,\u{a0}3\u{3000}",
            "4,5,6,7",
            "1e3,2D-1",
            "1;2",
            "1\t2",
        ];
        let bad = [
            "s_mm,F_mm",
            "y_cm,z_mm",
            "y,z",
            " y_mm , z_mm ,extra",
            "8",
            "9,",
            ",10",
            "abc,1",
            "1,nan",
            "1,inf",
            "1,1e999",
            "  # not a comment",
            "1,2 # c",
            "\u{feff}y_mm,z_mm",
            ",",
            "1,,2",
            "y_mm;z_mm",
            "y_mm\tz_mm",
            "1,5;2,5",
            "y_mm",
        ];
        let ends = ["\n", "\r\n"];
        let mut rng = crate::rng::SplitMix64::new(15);
        let mut pick = |from: &[&'static str]| from[(rng.next_u64() % from.len() as u64) as usize];
        let mut texts = Vec::new();
        for round in 0..3000 {
            let mut text = String::new();
            let mut end = "";
            for line in 0..round % 9 {
                // Mostly a valid file: a header, then points, comments and blank lines.
                let piece = match (line, round % 3) {
                    (0, 0) => "y_mm,z_mm",
                    (_, 0 | 1) if line % 5 != 4 => pick(&good),
                    _ => pick(&bad),
                };
                text += piece;
                end = pick(&ends);
                text += end;
            }
            if round % 2 == 0 {
                // Without a line end after the last line.
                text.truncate(text.len() - end.len());
            }
            texts.push(text);
        }
        let mut errors = 0;
        for text in &texts {
            let [plain, quoted] = outcomes(text);
            assert_eq!(plain, quoted, "{text:?}");
            errors += usize::from(plain.contains(" / "));
        }
        // Both outcomes are exercised.
        assert!(
            errors > 100 && errors < texts.len() - 100,
            "{errors} errors"
        );
    }

    /// Lines at the edges of the one-pass reading of two numbers ([`point_row`]) read as
    /// the `csv` crate reads them, at the end of the text and before another line.
    #[test]
    fn lines_of_two_numbers_read_as_the_csv_crate_reads_them() {
        for line in [
            " 1.5 , -2 ",
            "-0,1.e1,x",
            "1,2,3",
            "12345678901234567890,1e-30",
            "1.5x,2",
            "1,2x",
            "1e,2",
            "1 2,3",
            "1,2 3",
            "1,\t2",
            "1;2",
        ] {
            for end in ["", "\n", "\r\n", "\n3,4\n"] {
                let text = format!("y_mm,z_mm\n{line}{end}");
                let [plain, quoted] = outcomes(&text);
                assert_eq!(plain, quoted, "{text:?}");
            }
        }
    }

    #[test]
    fn quotes_and_lone_carriage_returns_in_records_go_through_the_csv_crate() {
        let plain = |text| parse_plain(text, ProfileKind::Rail, "t.csv", separator(text)).is_some();
        assert!(!plain("y_mm,z_mm\n\"1\",2\n"));
        assert!(!plain("y_mm,z_mm\r1,2\n"));
        assert!(!plain("y_mm,z_mm\n1,2\r3,4\n"));
        assert!(!plain("y_mm,z_mm\n1,2,\"3\"\n"));
        assert!(!plain("# a \"quote\"\ry_mm,z_mm\n1,2\n"));
        // Plain: a CRLF end, a carriage return that ends the text (the record ends there
        // either way), a quote in a comment, a comment ending the text.
        for text in [
            "y_mm,z_mm\r\n1,2\r\n",
            "y_mm,z_mm\n1,2\r",
            "y_mm,z_mm\n1,2\n#c\r",
            "# a \"quote\"\ny_mm,z_mm\n1,2\n",
            "y_mm,z_mm\n1,2\n# the end",
        ] {
            let [plain, quoted] = outcomes(text);
            assert_eq!(plain, quoted, "{text:?}");
        }
        // A quoted field keeps its comma: "1,5" is one field, not a number.
        let quoted = parse("y_mm,z_mm\n\"1,5\",2\n", ProfileKind::Rail, "t.csv");
        assert!(
            matches!(&quoted, Err(ReadError::NonNumeric { line: 2, value, .. }) if value == "1,5"),
            "{quoted:?}"
        );
    }

    /// Semicolons and tabs, as the header has them, with decimal commas or points; on the
    /// quoted path too.
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
    /// blank lines, comments and CRLF ends included, on both paths (the crate's own count
    /// skips the first two and counts a CRLF file's rows one low).
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
