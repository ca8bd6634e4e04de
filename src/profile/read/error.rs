//! The error of every profile reader, one variant per broken condition.

use std::fmt;

use crate::profile::ProfileKind;

/// Where a bad value sits on its line: a numbered column or a `key = value` entry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Field {
    /// 1-based column of a data row.
    Column(usize),
    /// The value of a `key = value` (SIMPACK) or `Key=Value` (MiniProf) header entry.
    Key(String),
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Field::Column(c) => write!(f, "column {c}"),
            Field::Key(k) => write!(f, "key {k}"),
        }
    }
}

/// Which extent of a profile is implausible.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// The lateral coordinate (`s` of a wheel, `y` of a rail).
    Lateral,
    /// The vertical coordinate (`F` of a wheel, `z` of a rail).
    Vertical,
}

impl fmt::Display for Axis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Axis::Lateral => "lateral",
            Axis::Vertical => "vertical",
        })
    }
}

/// Error reading a profile file: why the file cannot be turned into a
/// [`PointProfile`](super::PointProfile).
///
/// Every variant carries `origin` (the path, or the name given to
/// the readers that parse text) and, where the problem sits on one line, its 1-based
/// `line`, so that [`Display`](fmt::Display) reads like a compiler message:
/// `profiles/w.csv:12: non-numeric value "abc" in column 2 (expected a number in mm)`.
#[derive(Debug)]
#[non_exhaustive]
pub enum ReadError {
    /// The file could not be read from disk.
    Io {
        /// The path that was opened.
        origin: String,
        /// The operating-system error.
        source: std::io::Error,
    },
    /// The file extension names no supported format.
    UnknownFormat {
        /// The path.
        origin: String,
        /// The extension found (empty if none).
        extension: String,
    },
    /// The file holds nothing but white space (and comments).
    Empty {
        /// The path.
        origin: String,
    },
    /// The file has a header (or a point block) but not a single point.
    NoPoints {
        /// The path.
        origin: String,
    },
    /// Fewer points than any profile needs.
    TooFewPoints {
        /// The path.
        origin: String,
        /// Points found (after dropping the measured end faces of a MiniProf file).
        found: usize,
        /// The minimum, [`MIN_POINTS`](super::PointProfile::MIN_POINTS).
        min: usize,
    },
    /// A field that must be a number is not one.
    NonNumeric {
        /// The path.
        origin: String,
        /// 1-based line number.
        line: usize,
        /// The column or key of the value.
        field: Field,
        /// The offending text.
        value: String,
        /// What was expected there, e.g. "a number in mm".
        expected: &'static str,
    },
    /// A number is NaN or infinite.
    NonFinite {
        /// The path.
        origin: String,
        /// 1-based line number.
        line: usize,
        /// The column or key of the value.
        field: Field,
        /// The offending text.
        value: String,
    },
    /// A data row has fewer fields than the format requires.
    MissingField {
        /// The path.
        origin: String,
        /// 1-based line number.
        line: usize,
        /// The 1-based column that is missing.
        column: usize,
    },
    /// Two consecutive points coincide (within
    /// `DUPLICATE_TOLERANCE_MM`).
    DuplicatePoint {
        /// The path.
        origin: String,
        /// Line of the second copy.
        line: usize,
        /// Line of the first copy.
        previous_line: usize,
    },
    /// The lateral coordinate goes back (or stands still) between two points: the profile is
    /// not a function of its lateral coordinate (zig-zag, loop, vertical or undercut face).
    NonMonotonic {
        /// The path.
        origin: String,
        /// Line of the point that goes back.
        line: usize,
        /// Line of the point before it (in lateral order).
        previous_line: usize,
        /// Lateral coordinate of the point that goes back, side frame, mm.
        lateral_mm: f64,
        /// Lateral coordinate of the point before it, side frame, mm.
        previous_lateral_mm: f64,
    },
    /// The profile is far too narrow, wide or tall to be in millimetres.
    ImplausibleExtent {
        /// The path.
        origin: String,
        /// Which extent.
        axis: Axis,
        /// The extent found, in the units the file was read in (taken as mm).
        extent_mm: f64,
        /// The plausible range, mm (lower bound 0 for the vertical extent).
        range_mm: (f64, f64),
    },
    /// The file describes the other kind of profile than the caller asked for.
    WrongKind {
        /// The path.
        origin: String,
        /// Line of the evidence (a SIMPACK `type`, a CSV header), if it is on a line.
        line: Option<usize>,
        /// The kind the caller asked for.
        expected: ProfileKind,
        /// The kind the file declares.
        found: ProfileKind,
    },
    /// A CSV column is declared in a unit other than millimetres.
    WrongUnits {
        /// The path.
        origin: String,
        /// 1-based line of the header row.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The column name found.
        name: String,
        /// The unit the name declares ("metres", "inches", ...).
        unit: &'static str,
    },
    /// A CSV column name does not say its unit.
    MissingUnits {
        /// The path.
        origin: String,
        /// 1-based line of the header row.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The column name found.
        name: String,
    },
    /// A CSV file starts with numbers instead of a header row.
    MissingHeader {
        /// The path.
        origin: String,
        /// 1-based line of the first row.
        line: usize,
    },
    /// A CSV header names one column: its fields are separated by none of the separators
    /// read (comma, semicolon, tab).
    OneColumnHeader {
        /// The path.
        origin: String,
        /// 1-based line of the header.
        line: usize,
    },
    /// A CSV row that does not read holds another separator than its header's: the file
    /// mixes separators (a spreadsheet export pasted into a file of another locale).
    SeparatorMismatch {
        /// The path.
        origin: String,
        /// 1-based line of the row.
        line: usize,
        /// The header's separator.
        header: crate::delimited::Separator,
        /// The separator found in the row.
        found: crate::delimited::Separator,
    },
    /// The file's structure is broken: misnested or unterminated SIMPACK blocks, a MiniProf
    /// header key among the data, a line that fits no rule of the format.
    Malformed {
        /// The path.
        origin: String,
        /// 1-based line number.
        line: usize,
        /// What is wrong, in words.
        problem: String,
    },
    /// A wheel profile whose flange lies on the field side (`s > 0`): the file describes the
    /// other wheel, or its lateral axis points the other way.
    Mirrored {
        /// The path.
        origin: String,
        /// Lateral coordinate of the highest point (the flange tip), side frame, mm.
        flange_tip_mm: f64,
    },
    /// A SIMPACK file asks for a profile rotation, which this reader does not apply.
    UnsupportedRotation {
        /// The path.
        origin: String,
        /// 1-based line of the `rotate` entry.
        line: usize,
        /// The rotation, converted to radians with `units.ang.f`.
        angle_rad: f64,
    },
    /// A SIMPACK unit factor (`units.len.f`, `units.ang.f`) is zero, negative or not finite.
    BadUnitFactor {
        /// The path.
        origin: String,
        /// 1-based line of the entry.
        line: usize,
        /// The key.
        key: &'static str,
        /// The value found.
        value: f64,
    },
}

impl ReadError {
    /// The path (or origin name) of the file the error is about.
    pub fn origin(&self) -> &str {
        match self {
            ReadError::Io { origin, .. }
            | ReadError::UnknownFormat { origin, .. }
            | ReadError::Empty { origin }
            | ReadError::NoPoints { origin }
            | ReadError::TooFewPoints { origin, .. }
            | ReadError::NonNumeric { origin, .. }
            | ReadError::NonFinite { origin, .. }
            | ReadError::MissingField { origin, .. }
            | ReadError::DuplicatePoint { origin, .. }
            | ReadError::NonMonotonic { origin, .. }
            | ReadError::ImplausibleExtent { origin, .. }
            | ReadError::Mirrored { origin, .. }
            | ReadError::WrongKind { origin, .. }
            | ReadError::WrongUnits { origin, .. }
            | ReadError::MissingUnits { origin, .. }
            | ReadError::MissingHeader { origin, .. }
            | ReadError::OneColumnHeader { origin, .. }
            | ReadError::SeparatorMismatch { origin, .. }
            | ReadError::Malformed { origin, .. }
            | ReadError::UnsupportedRotation { origin, .. }
            | ReadError::BadUnitFactor { origin, .. } => origin,
        }
    }

    /// The 1-based line the error is about, if it is about one line.
    pub fn line(&self) -> Option<usize> {
        match self {
            ReadError::NonNumeric { line, .. }
            | ReadError::NonFinite { line, .. }
            | ReadError::MissingField { line, .. }
            | ReadError::DuplicatePoint { line, .. }
            | ReadError::NonMonotonic { line, .. }
            | ReadError::WrongUnits { line, .. }
            | ReadError::MissingUnits { line, .. }
            | ReadError::MissingHeader { line, .. }
            | ReadError::OneColumnHeader { line, .. }
            | ReadError::SeparatorMismatch { line, .. }
            | ReadError::Malformed { line, .. }
            | ReadError::UnsupportedRotation { line, .. }
            | ReadError::BadUnitFactor { line, .. } => Some(*line),
            ReadError::WrongKind { line, .. } => *line,
            ReadError::Io { .. }
            | ReadError::UnknownFormat { .. }
            | ReadError::Empty { .. }
            | ReadError::NoPoints { .. }
            | ReadError::TooFewPoints { .. }
            | ReadError::ImplausibleExtent { .. }
            | ReadError::Mirrored { .. } => None,
        }
    }
}

// One arm per variant: the match is the list of the readers' messages, read and reviewed
// together, so it is kept whole (ARCHITECTURE.md).
impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.origin())?;
        if let Some(line) = self.line() {
            write!(f, ":{line}")?;
        }
        f.write_str(": ")?;
        match self {
            ReadError::Io { source, .. } => write!(f, "cannot read the file: {source}"),
            ReadError::UnknownFormat { extension, .. } => write!(
                f,
                "unknown profile format \"{extension}\" (expected .csv, .prw/.prr (SIMPACK) or \
                 .whl/.ban (MiniProf))"
            ),
            ReadError::Empty { .. } => f.write_str("the file is empty"),
            ReadError::NoPoints { .. } => {
                f.write_str("the file has a header but no profile points")
            }
            ReadError::TooFewPoints { found, min, .. } => write!(
                f,
                "only {found} profile points; a profile needs at least {min}"
            ),
            ReadError::NonNumeric {
                field,
                value,
                expected,
                ..
            } => write!(
                f,
                "non-numeric value \"{value}\" in {field} (expected {expected})"
            ),
            ReadError::NonFinite { field, value, .. } => write!(
                f,
                "value \"{value}\" in {field} is not a finite number (NaN or infinite)"
            ),
            ReadError::MissingField { column, .. } => write!(
                f,
                "missing value in column {column} (each point needs a lateral and a vertical \
                 coordinate)"
            ),
            ReadError::DuplicatePoint { previous_line, .. } => {
                write!(
                    f,
                    "duplicate point: the same as the point on line {previous_line}"
                )
            }
            ReadError::NonMonotonic {
                previous_line,
                lateral_mm,
                previous_lateral_mm,
                ..
            } => write!(
                f,
                "lateral coordinate {} mm does not increase after {} mm on line {previous_line}: \
                 the profile zig-zags, loops or has a vertical or undercut face, and is not a \
                 function of its lateral coordinate",
                Micrometres(*lateral_mm),
                Micrometres(*previous_lateral_mm)
            ),
            ReadError::Mirrored { flange_tip_mm, .. } => write!(
                f,
                "the profile looks mirrored: its flange tip is at s = {} mm, on the field side, \
                 but wheel profiles have the flange at s < 0 (towards the track centre): \
                 negate the lateral coordinate (SIMPACK: `mirror.y = 1`), or give this file \
                 as the other wheel's profile",
                Micrometres(*flange_tip_mm)
            ),
            ReadError::ImplausibleExtent {
                axis,
                extent_mm,
                range_mm,
                ..
            } => {
                let hint = match (axis, *extent_mm < range_mm.0) {
                    (Axis::Lateral, true) => {
                        "are the values in metres (or inches) instead of millimetres?"
                    }
                    _ => "are the values in micrometres, or another unit than millimetres?",
                };
                write!(
                    f,
                    "implausible {axis} extent {extent_mm} mm (a profile spans {} to {} mm): {hint}",
                    range_mm.0, range_mm.1
                )
            }
            ReadError::WrongKind {
                expected, found, ..
            } => write!(f, "a {found} profile given as {expected}"),
            ReadError::WrongUnits {
                column, name, unit, ..
            } => write!(
                f,
                "column {column} \"{name}\" is in {unit}; profile files must be in millimetres \
                 (convert the values and name the column like s_mm or y_mm)"
            ),
            ReadError::MissingUnits { column, name, .. } => write!(
                f,
                "column {column} \"{name}\" does not say its unit; name it with an _mm suffix \
                 (s_mm,F_mm for a wheel, y_mm,z_mm for a rail)"
            ),
            ReadError::MissingHeader { .. } => f.write_str(
                "the first row holds numbers, but a profile CSV starts with a header row naming \
                 the columns and their units (s_mm,F_mm for a wheel, y_mm,z_mm for a rail)",
            ),
            ReadError::OneColumnHeader { .. } => f.write_str(
                "the header names one column; a profile CSV names two, separated by commas, \
                 semicolons or tabs (s_mm,F_mm for a wheel, y_mm,z_mm for a rail)",
            ),
            ReadError::SeparatorMismatch { header, found, .. } => write!(
                f,
                "this row separates its fields by {}, but the header by {}: a file takes one \
                 separator throughout (commas with decimal points; semicolons or tabs with \
                 decimal commas or points)",
                found.plural(),
                header.plural()
            ),
            ReadError::Malformed { problem, .. } => f.write_str(problem),
            ReadError::UnsupportedRotation { angle_rad, .. } => write!(
                f,
                "profile rotation of {angle_rad} rad is not supported (the sign convention of \
                 SIMPACK's `rotate` is not documented in any source we could check); rotate the \
                 points themselves and set rotate = 0"
            ),
            ReadError::BadUnitFactor { key, value, .. } => write!(
                f,
                "{key} = {value} is not a usable unit factor (it must be a positive number, \
                 e.g. units.len.f = 1000 for millimetres)"
            ),
        }
    }
}

impl std::error::Error for ReadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ReadError::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

/// A length in mm as the files give it: rounded to 1e-6 mm (below any file's resolution),
/// so that a value moved by a conversion prints as `-54.105`, not `-54.105000000000004`.
struct Micrometres(f64);

impl fmt::Display for Micrometres {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let rounded = (self.0 * 1e6).round() / 1e6;
        if rounded.is_finite() {
            write!(f, "{rounded}")
        } else {
            write!(f, "{}", self.0)
        }
    }
}
