//! Tables of named columns and their CSV form.
//!
//! A [`Table`] is what every stage hands to the writers: ordered, named columns of equal length,
//! each numeric or text, plus comment lines for the frame, unit and provenance statements that
//! belong above the header row. [`Table::to_csv`] turns it into bytes (as a `String`);
//! [`Table::parse_csv`] reads such a file back, for golden comparisons and for tools.
//!
//! # File format
//!
//! ```text
//! # frame: track, y positive to the left
//! # wheelrail 0.1.0
//! y_ws_mm,delta_r_mm,status
//! 0,0,ok
//! 0.5,0.0123,ok
//! 9.5,NaN,no contact
//! ```
//!
//! * Comment lines start with `#` and come only before the header row; the parser strips `#`
//!   and one following space.
//! * The header row names the columns; by the project's conventions each name carries its unit.
//! * Numbers are written in the shortest form that reads back to the same `f64`
//!   ([`NumberFormat::Shortest`], the default), so a round trip is exact and a changed value is a
//!   changed line in a diff. Not-a-number is `NaN`, infinities are `inf` and `-inf`.
//! * Text is quoted only when needed (commas, quotes, line breaks), as RFC 4180 says.

use std::borrow::Cow;
use std::fmt;

/// The values of one column: all numbers or all text.
#[derive(Debug, Clone, PartialEq)]
pub enum ColumnData {
    /// Numbers; `NaN` marks a value that could not be computed.
    Numeric(Vec<f64>),
    /// Free text, e.g. a status or a reason: borrowed where it is a fixed word (a status
    /// repeated on every row costs no allocation), owned otherwise.
    Text(Vec<Cow<'static, str>>),
}

impl ColumnData {
    /// Number of values.
    pub fn len(&self) -> usize {
        match self {
            ColumnData::Numeric(v) => v.len(),
            ColumnData::Text(v) => v.len(),
        }
    }

    /// `true` when the column has no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// `"numeric"` or `"text"`, for messages.
    pub fn kind(&self) -> &'static str {
        match self {
            ColumnData::Numeric(_) => "numeric",
            ColumnData::Text(_) => "text",
        }
    }
}

/// One named column of a [`Table`].
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Column name as written in the header row, unit included (`y_ws_mm`).
    pub name: String,
    /// The values.
    pub data: ColumnData,
}

/// How [`Table::to_csv_with`] writes numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NumberFormat {
    /// Shortest decimal that reads back to the identical `f64` (`0.1`, `760.53`, `1e-7`).
    /// Plain notation for magnitudes in [1e-4, 1e15), scientific otherwise.
    #[default]
    Shortest,
    /// Scientific notation with this many significant digits (`Significant(4)`: `7.605e2`),
    /// clamped to 1..=17. Use it for golden files that should not churn in the last digits
    /// when regenerated on another platform; 17 digits always round-trip.
    Significant(u8),
}

/// Errors of building or parsing a [`Table`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TableError {
    /// A column has a different length from the columns before it.
    LengthMismatch {
        /// The offending column.
        column: String,
        /// Length of the columns already in the table.
        expected: usize,
        /// Length of the offending column.
        found: usize,
    },
    /// Two columns have the same name.
    DuplicateColumn(String),
    /// A column name is empty, contains a line break, or starts with `#` (it would read back as a
    /// comment line).
    InvalidColumnName(String),
    /// The text has no header row.
    MissingHeader,
    /// The CSV text is malformed (e.g. a row with the wrong number of fields).
    Csv {
        /// 1-based line number in the text, when known.
        line: Option<u64>,
        /// What the CSV reader reported.
        message: String,
    },
}

impl fmt::Display for TableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TableError::LengthMismatch {
                column,
                expected,
                found,
            } => write!(
                f,
                "column `{column}` has {found} rows but the table has {expected}"
            ),
            TableError::DuplicateColumn(name) => write!(f, "duplicate column `{name}`"),
            TableError::InvalidColumnName(name) => write!(
                f,
                "invalid column name {name:?} (empty, line break, or leading `#`)"
            ),
            TableError::MissingHeader => f.write_str("CSV text has no header row"),
            TableError::Csv {
                line: Some(line),
                message,
            } => write!(f, "CSV line {line}: {message}"),
            TableError::Csv {
                line: None,
                message,
            } => write!(f, "CSV: {message}"),
        }
    }
}

impl std::error::Error for TableError {}

/// Ordered named columns of equal length, with comment lines written above the header row.
///
/// Build one with [`Table::builder`], write it with [`Table::to_csv`], read it back with
/// [`Table::parse_csv`].
///
/// # Examples
///
/// ```
/// use wheelrail_report::table::Table;
///
/// let table = Table::builder()
///     .comment("frame: track, y positive to the left")
///     .numeric("y_ws_mm", vec![0.0, 0.5, 9.5])
///     .numeric("delta_r_mm", vec![0.0, 0.0123, f64::NAN])
///     .text("status", ["ok", "ok", "no contact"])
///     .build()?;
/// let csv = table.to_csv();
/// assert_eq!(
///     csv,
///     "# frame: track, y positive to the left\n\
///      y_ws_mm,delta_r_mm,status\n\
///      0,0,ok\n\
///      0.5,0.0123,ok\n\
///      9.5,NaN,no contact\n"
/// );
/// let back = Table::parse_csv(&csv)?;
/// assert_eq!(back.numeric("y_ws_mm"), Some(&[0.0, 0.5, 9.5][..]));
/// assert!(back.numeric("delta_r_mm").unwrap()[2].is_nan());
/// assert_eq!(back.text("status").unwrap()[2], "no contact");
/// # Ok::<(), wheelrail_report::table::TableError>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Table {
    comments: Vec<String>,
    columns: Vec<Column>,
}

/// Collects comments and columns for a [`Table`]; [`TableBuilder::build`] checks them.
///
/// The first problem (length mismatch, duplicate or invalid name) is remembered and returned
/// by `build`, so a chain of calls needs a single `?`.
#[derive(Debug, Clone, Default)]
#[must_use = "call build() to get the table"]
pub struct TableBuilder {
    table: Table,
    error: Option<TableError>,
}

impl TableBuilder {
    /// Adds comment lines (one per line of `text`), written as `# text` above the header row.
    pub fn comment(mut self, text: impl AsRef<str>) -> Self {
        self.table.add_comment(text);
        self
    }

    /// Adds a numeric column.
    pub fn numeric(self, name: impl Into<String>, values: impl Into<Vec<f64>>) -> Self {
        self.column(name.into(), ColumnData::Numeric(values.into()))
    }

    /// Adds a text column.
    pub fn text<S: Into<Cow<'static, str>>>(
        self,
        name: impl Into<String>,
        values: impl IntoIterator<Item = S>,
    ) -> Self {
        let values = values.into_iter().map(Into::into).collect();
        self.column(name.into(), ColumnData::Text(values))
    }

    fn column(mut self, name: String, data: ColumnData) -> Self {
        if self.error.is_none()
            && let Err(e) = self.table.push_column(name, data)
        {
            self.error = Some(e);
        }
        self
    }

    /// Returns the table, or the first problem met while adding columns.
    ///
    /// # Errors
    ///
    /// [`TableError::LengthMismatch`], [`TableError::DuplicateColumn`] or
    /// [`TableError::InvalidColumnName`] for the first offending column.
    pub fn build(self) -> Result<Table, TableError> {
        match self.error {
            Some(e) => Err(e),
            None => Ok(self.table),
        }
    }
}

impl Table {
    /// An empty table (no comments, no columns, no rows).
    pub fn new() -> Self {
        Self::default()
    }

    /// Starts building a table; see [`TableBuilder`].
    pub fn builder() -> TableBuilder {
        TableBuilder::default()
    }

    /// Adds comment lines (one per line of `text`).
    pub fn add_comment(&mut self, text: impl AsRef<str>) {
        self.comments.extend(
            text.as_ref()
                .lines()
                .map(|l| l.trim_end_matches('\r').to_owned()),
        );
        if text.as_ref().is_empty() {
            self.comments.push(String::new());
        }
    }

    /// Appends a column.
    ///
    /// # Errors
    ///
    /// [`TableError::LengthMismatch`] if the table already has columns of another length,
    /// [`TableError::DuplicateColumn`] if the name is taken, [`TableError::InvalidColumnName`]
    /// if it is empty, contains a line break or starts with `#`.
    pub fn push_column(
        &mut self,
        name: impl Into<String>,
        data: ColumnData,
    ) -> Result<(), TableError> {
        let name = name.into();
        if name.is_empty() || name.starts_with('#') || name.contains(['\n', '\r']) {
            return Err(TableError::InvalidColumnName(name));
        }
        if self.column(&name).is_some() {
            return Err(TableError::DuplicateColumn(name));
        }
        if let Some(first) = self.columns.first()
            && first.data.len() != data.len()
        {
            return Err(TableError::LengthMismatch {
                column: name,
                expected: first.data.len(),
                found: data.len(),
            });
        }
        self.columns.push(Column { name, data });
        Ok(())
    }

    /// The comment lines, without the leading `# `.
    pub fn comments(&self) -> &[String] {
        &self.comments
    }

    /// The columns in order.
    pub fn columns(&self) -> &[Column] {
        &self.columns
    }

    /// The columns in order, taken out of the table: their values without a copy (the
    /// Python package hands them to NumPy so).
    pub fn into_columns(self) -> Vec<Column> {
        self.columns
    }

    /// The column names in order.
    pub fn column_names(&self) -> impl Iterator<Item = &str> {
        self.columns.iter().map(|c| c.name.as_str())
    }

    /// The column called `name`, if any.
    pub fn column(&self, name: &str) -> Option<&Column> {
        self.columns.iter().find(|c| c.name == name)
    }

    /// The values of numeric column `name`; `None` if absent or text.
    pub fn numeric(&self, name: &str) -> Option<&[f64]> {
        match &self.column(name)?.data {
            ColumnData::Numeric(v) => Some(v),
            ColumnData::Text(_) => None,
        }
    }

    /// The values of text column `name`; `None` if absent or numeric.
    pub fn text(&self, name: &str) -> Option<&[Cow<'static, str>]> {
        match &self.column(name)?.data {
            ColumnData::Text(v) => Some(v),
            ColumnData::Numeric(_) => None,
        }
    }

    /// Number of rows (0 for a table without columns).
    pub fn n_rows(&self) -> usize {
        self.columns.first().map_or(0, |c| c.data.len())
    }

    /// Number of columns.
    pub fn n_columns(&self) -> usize {
        self.columns.len()
    }

    /// The CSV text with numbers in [`NumberFormat::Shortest`]; see the [module docs](self).
    pub fn to_csv(&self) -> String {
        self.to_csv_with(NumberFormat::Shortest)
    }

    /// The CSV text with numbers written as `format` says.
    ///
    /// Lines end with `\n`. A table without columns gives only its comment lines.
    pub fn to_csv_with(&self, format: NumberFormat) -> String {
        String::from_utf8(self.to_csv_bytes(format)).expect("CSV of UTF-8 strings is UTF-8")
    }

    /// The bytes of [`Table::to_csv_with`]: the comment lines, then the header and the rows
    /// as the csv crate writes them (quotes only where a field needs them, `\n` after each
    /// record).
    pub(crate) fn to_csv_bytes(&self, format: NumberFormat) -> Vec<u8> {
        let mut bytes = Vec::new();
        for c in &self.comments {
            if c.is_empty() {
                bytes.extend_from_slice(b"#\n");
            } else {
                bytes.extend_from_slice(b"# ");
                bytes.extend_from_slice(c.as_bytes());
                bytes.push(b'\n');
            }
        }
        if self.columns.is_empty() {
            return bytes;
        }
        let mut writer = csv::WriterBuilder::new()
            .terminator(csv::Terminator::Any(b'\n'))
            .from_writer(bytes);
        // Writing into a Vec cannot fail, and every record has the header's length.
        let expect = "CSV writer into memory";
        writer.write_record(self.column_names()).expect(expect);
        // One record and one number's text, reused row by row.
        let mut record = csv::ByteRecord::with_capacity(0, self.columns.len());
        let mut number = String::new();
        for row in 0..self.n_rows() {
            record.clear();
            for c in &self.columns {
                match &c.data {
                    ColumnData::Numeric(v) => {
                        number.clear();
                        push_number(&mut number, v[row], format);
                        record.push_field(number.as_bytes());
                    }
                    ColumnData::Text(v) => record.push_field(v[row].as_bytes()),
                }
            }
            writer.write_byte_record(&record).expect(expect);
        }
        writer.into_inner().expect(expect)
    }

    /// Reads a table written by [`Table::to_csv`] (or any comma-separated file with a header).
    ///
    /// Leading lines starting with `#` become comments. A column is numeric when every cell
    /// (trimmed) parses as an `f64`, `NaN` and `inf` included, so a column of numbers and
    /// `NaN`s is numeric; otherwise it is text, cells kept verbatim. A column with no rows is
    /// numeric. Blank lines are skipped.
    ///
    /// # Errors
    ///
    /// [`TableError::MissingHeader`] if there is no header row, [`TableError::Csv`] for
    /// malformed CSV or a row with the wrong number of fields, [`TableError::DuplicateColumn`]
    /// and [`TableError::InvalidColumnName`] for a bad header.
    pub fn parse_csv(text: &str) -> Result<Table, TableError> {
        let mut table = Table::new();
        let mut rest = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut comment_lines = 0u64;
        while rest.starts_with('#') {
            let (line, tail) = rest.split_once('\n').unwrap_or((rest, ""));
            let line = line.trim_end_matches('\r');
            let body = line[1..].strip_prefix(' ').unwrap_or(&line[1..]);
            table.comments.push(body.to_owned());
            comment_lines += 1;
            rest = tail;
        }
        let mut reader = csv::ReaderBuilder::new()
            .has_headers(true)
            .from_reader(rest.as_bytes());
        let csv_error = |e: csv::Error| TableError::Csv {
            line: e.position().map(|p| p.line() + comment_lines),
            message: e.to_string(),
        };
        let header = reader.headers().map_err(csv_error)?.clone();
        if header.is_empty() {
            return Err(TableError::MissingHeader);
        }
        let mut cells: Vec<Vec<String>> = vec![Vec::new(); header.len()];
        for record in reader.records() {
            let record = record.map_err(csv_error)?;
            for (column, cell) in cells.iter_mut().zip(record.iter()) {
                column.push(cell.to_owned());
            }
        }
        for (name, column) in header.iter().zip(cells) {
            let numbers: Option<Vec<f64>> = column
                .iter()
                .map(|c| c.trim().parse::<f64>().ok())
                .collect();
            let data = match numbers {
                Some(v) => ColumnData::Numeric(v),
                None => ColumnData::Text(column.into_iter().map(Cow::Owned).collect()),
            };
            table.push_column(name, data)?;
        }
        Ok(table)
    }
}

/// Formats one number as [`Table::to_csv_with`] writes it.
///
/// # Examples
///
/// ```
/// use wheelrail_report::table::{format_number, NumberFormat};
///
/// assert_eq!(format_number(760.53, NumberFormat::Shortest), "760.53");
/// assert_eq!(format_number(1.5e-7, NumberFormat::Shortest), "1.5e-7");
/// assert_eq!(format_number(f64::NAN, NumberFormat::Shortest), "NaN");
/// assert_eq!(format_number(760.53, NumberFormat::Significant(3)), "7.61e2");
/// assert_eq!(format_number(-0.0, NumberFormat::Significant(3)), "-0.00e0");
/// ```
pub fn format_number(x: f64, format: NumberFormat) -> String {
    let mut out = String::new();
    push_number(&mut out, x, format);
    out
}

/// Appends [`format_number`]'s text of `x` to `out`: the standard library's formatting
/// (`{}` and `{:e}` are the shortest text that reads back to the same `f64`, `{:.N$e}` is
/// correctly rounded), with the spellings of the module docs for not-a-number and the
/// infinities.
fn push_number(out: &mut String, x: f64, format: NumberFormat) {
    use std::fmt::Write;
    if x.is_nan() {
        out.push_str("NaN");
        return;
    }
    if x.is_infinite() {
        out.push_str(if x > 0.0 { "inf" } else { "-inf" });
        return;
    }
    // Writing to a String cannot fail.
    let _ = match format {
        NumberFormat::Shortest => {
            let a = x.abs();
            if a == 0.0 || (1e-4..1e15).contains(&a) {
                write!(out, "{x}")
            } else {
                write!(out, "{x:e}")
            }
        }
        NumberFormat::Significant(n) => {
            let prec = usize::from(n.clamp(1, 17)) - 1;
            write!(out, "{x:.prec$e}")
        }
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shortest_format_round_trips_awkward_values() {
        let values = [
            0.1 + 0.2,
            -0.0,
            1e-300,
            f64::MIN_POSITIVE,
            5e-324,
            f64::MAX,
            123_456_789.123_456_79,
            9.999_999_999_999_999e14,
            1e15,
            1e-4,
            9.99e-5,
        ];
        for x in values {
            let s = format_number(x, NumberFormat::Shortest);
            let back: f64 = s.parse().unwrap();
            assert_eq!(back.to_bits(), x.to_bits(), "{x} written as {s}");
        }
    }

    #[test]
    fn significant_17_round_trips() {
        let x = 0.1 + 0.2;
        let s = format_number(x, NumberFormat::Significant(17));
        assert_eq!(s.parse::<f64>().unwrap().to_bits(), x.to_bits());
        assert_eq!(format_number(x, NumberFormat::Significant(0)), "3e-1");
    }

    #[test]
    fn special_values_keep_their_spelling() {
        // The reports' format (10 significant digits) and the default: NaN, the infinities
        // and a signed zero as the module docs spell them, so that they read back.
        for format in [NumberFormat::Significant(10), NumberFormat::Shortest] {
            assert_eq!(format_number(f64::NAN, format), "NaN");
            assert_eq!(format_number(f64::INFINITY, format), "inf");
            assert_eq!(format_number(f64::NEG_INFINITY, format), "-inf");
        }
        let ten = NumberFormat::Significant(10);
        assert_eq!(format_number(0.0, ten), "0.000000000e0");
        assert_eq!(format_number(-0.0, ten), "-0.000000000e0");
        assert_eq!(format_number(-1.5e-7, ten), "-1.500000000e-7");
        assert_eq!(format_number(-0.0, NumberFormat::Shortest), "-0");
        for text in ["NaN", "inf", "-inf", "-0.000000000e0"] {
            assert!(text.parse::<f64>().is_ok(), "{text}");
        }
    }

    #[test]
    fn quoting_is_the_csv_crates() {
        // Fields that need quotes (a comma, a quote, a line break) and a row of one empty
        // field (`""`, not a blank line) read back as they were.
        let t = Table::builder()
            .comment("c")
            .text("a", ["b,c", "say \"hi\"", "two\nlines", ""])
            .build()
            .unwrap();
        let csv = t.to_csv();
        assert_eq!(
            csv,
            "# c\na\n\"b,c\"\n\"say \"\"hi\"\"\"\n\"two\nlines\"\n\"\"\n"
        );
        assert_eq!(Table::parse_csv(&csv).unwrap(), t);
    }

    #[test]
    fn builder_reports_first_length_mismatch() {
        let err = Table::builder()
            .numeric("a_mm", vec![1.0, 2.0])
            .numeric("b_mm", vec![1.0])
            .text("c", ["x"])
            .build()
            .unwrap_err();
        assert_eq!(
            err,
            TableError::LengthMismatch {
                column: "b_mm".into(),
                expected: 2,
                found: 1
            }
        );
    }

    #[test]
    fn builder_rejects_duplicate_and_invalid_names() {
        let dup = Table::builder()
            .numeric("a", vec![])
            .text("a", Vec::<String>::new())
            .build();
        assert_eq!(dup.unwrap_err(), TableError::DuplicateColumn("a".into()));
        for bad in ["", "#x", "a\nb"] {
            let r = Table::builder().numeric(bad, vec![1.0]).build();
            assert_eq!(r.unwrap_err(), TableError::InvalidColumnName(bad.into()));
        }
    }

    #[test]
    fn empty_text_cells_and_single_column_round_trip() {
        let t = Table::builder()
            .text("status", ["", "no contact", ""])
            .build()
            .unwrap();
        let back = Table::parse_csv(&t.to_csv()).unwrap();
        assert_eq!(back, t);
    }

    #[test]
    fn wrong_field_count_names_the_line() {
        let err = Table::parse_csv("# c\na,b\n1,2\n3\n").unwrap_err();
        match err {
            TableError::Csv { line, .. } => assert_eq!(line, Some(4)),
            other => panic!("unexpected {other:?}"),
        }
    }

    #[test]
    fn empty_text_has_no_header() {
        assert_eq!(Table::parse_csv(""), Err(TableError::MissingHeader));
        assert_eq!(Table::parse_csv("# only\n"), Err(TableError::MissingHeader));
    }

    #[test]
    fn crlf_and_comment_without_space() {
        let t = Table::parse_csv("#c1\r\n# c2\r\nx_mm\r\n1\r\n").unwrap();
        assert_eq!(t.comments(), ["c1", "c2"]);
        assert_eq!(t.numeric("x_mm"), Some(&[1.0][..]));
    }
}
