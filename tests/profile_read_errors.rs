//! Profile readers against broken files: one fixture per broken condition (in
//! `tests/data/profiles/bad/`), each error naming the file and line.

use std::path::{Path, PathBuf};

use wheelrail::profile::ProfileKind::{self, Rail, Wheel};
use wheelrail::profile::read::{Axis, PointProfile, ReadError, read_profile};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/profiles")
        .join(name)
}

fn read(name: &str, kind: ProfileKind) -> Result<PointProfile, ReadError> {
    read_profile(&data(name), kind)
}

/// Asserts that the message starts with `path:line: ` (or `path: ` without a line).
fn assert_names_place(err: &ReadError, path: &Path, line: Option<usize>) {
    let msg = err.to_string();
    let place = match line {
        Some(l) => format!("{}:{l}: ", path.display()),
        None => format!("{}: ", path.display()),
    };
    assert!(
        msg.starts_with(&place),
        "message {msg:?} should start with {place:?}"
    );
    assert_eq!(err.line(), line, "{msg}");
}

// ---------------------------------------------------------------------------------------
// One fixture per broken condition
// ---------------------------------------------------------------------------------------

/// Reads `bad/<name>`, expects an error matching `is_expected` on `line`.
fn expect_bad(
    name: &str,
    kind: ProfileKind,
    line: Option<usize>,
    is_expected: fn(&ReadError) -> bool,
) {
    let path = data(&format!("bad/{name}"));
    let err = match read_profile(&path, kind) {
        Ok(p) => panic!("{name}: read {} points, expected an error", p.points.len()),
        Err(e) => e,
    };
    assert!(is_expected(&err), "{name}: unexpected error {err:?}");
    assert_names_place(&err, &path, line);
}

#[test]
fn empty_file() {
    expect_bad("empty.csv", Rail, None, |e| {
        matches!(e, ReadError::Empty { .. })
    });
}

#[test]
fn header_only() {
    expect_bad("header_only.csv", Rail, None, |e| {
        matches!(e, ReadError::NoPoints { .. })
    });
    expect_bad("header_only.ban", Rail, None, |e| {
        matches!(e, ReadError::NoPoints { .. })
    });
}

#[test]
fn too_few_points() {
    expect_bad("too_few_points.csv", Rail, None, |e| {
        matches!(
            e,
            ReadError::TooFewPoints {
                found: 5,
                min: 10,
                ..
            }
        )
    });
}

#[test]
fn non_numeric_value_reads_like_a_compiler_message() {
    let path = data("bad/non_numeric.csv");
    let err = read_profile(&path, Rail).unwrap_err();
    assert_eq!(
        err.to_string(),
        format!(
            "{}:6: non-numeric value \"abc\" in column 2 (expected a number in mm)",
            path.display()
        )
    );
}

#[test]
fn nan_or_infinite_value() {
    expect_bad("not_finite.csv", Rail, Some(7), |e| {
        matches!(e, ReadError::NonFinite { .. })
    });
}

#[test]
fn missing_field() {
    expect_bad("missing_field.csv", Rail, Some(5), |e| {
        matches!(e, ReadError::MissingField { column: 2, .. })
    });
}

#[test]
fn duplicate_point() {
    expect_bad("duplicate_point.csv", Rail, Some(8), |e| {
        matches!(
            e,
            ReadError::DuplicatePoint {
                previous_line: 7,
                ..
            }
        )
    });
}

#[test]
fn zig_zag_names_the_line() {
    expect_bad("zig_zag.csv", Rail, Some(9), |e| {
        matches!(
            e,
            ReadError::NonMonotonic {
                previous_line: 8,
                ..
            }
        )
    });
}

#[test]
fn units_in_the_header() {
    expect_bad("metres_header.csv", Rail, Some(1), |e| {
        matches!(
            e,
            ReadError::WrongUnits {
                column: 1,
                unit: "metres",
                ..
            }
        )
    });
    expect_bad("inches_header.csv", Rail, Some(1), |e| {
        matches!(e, ReadError::WrongUnits { unit: "inches", .. })
    });
    expect_bad("no_units.csv", Rail, Some(1), |e| {
        matches!(e, ReadError::MissingUnits { .. })
    });
    expect_bad("no_header.csv", Rail, Some(1), |e| {
        matches!(e, ReadError::MissingHeader { .. })
    });
}

#[test]
fn wrong_kind_in_the_csv_header() {
    expect_bad("wheel_header.csv", Rail, Some(1), |e| {
        matches!(
            e,
            ReadError::WrongKind {
                expected: Rail,
                found: Wheel,
                ..
            }
        )
    });
    // The same file is a fine wheel (extra column ignored).
    assert_eq!(
        read("bad/wheel_header.csv", Wheel).unwrap().points.len(),
        12
    );
}

#[test]
fn implausible_extents_suggest_the_unit() {
    expect_bad("metres_values.csv", Rail, None, |e| {
        matches!(
            e,
            ReadError::ImplausibleExtent {
                axis: Axis::Lateral,
                ..
            }
        ) && e.to_string().contains("metres")
    });
    expect_bad("micrometres_values.csv", Rail, None, |e| {
        matches!(
            e,
            ReadError::ImplausibleExtent {
                axis: Axis::Lateral,
                ..
            }
        ) && e.to_string().contains("micrometres")
    });
    expect_bad("too_tall.csv", Rail, None, |e| {
        matches!(
            e,
            ReadError::ImplausibleExtent {
                axis: Axis::Vertical,
                ..
            }
        )
    });
}

#[test]
fn simpack_structure_errors() {
    // No point.end / spline.end: the last line (21) is named.
    expect_bad(
        "truncated.prr",
        Rail,
        Some(21),
        |e| matches!(e, ReadError::Malformed { problem, .. } if problem.contains("point.end")),
    );
    // spline.begin inside the header block (header.end missing).
    expect_bad("misnested.prr", Rail, Some(5), |e| {
        matches!(e, ReadError::Malformed { .. })
    });
    // rotate = 1.5 degrees (units.ang.f = 180/pi) on line 8.
    expect_bad("rotated.prr", Rail, Some(8), |e| {
        matches!(e, ReadError::UnsupportedRotation { angle_rad, .. }
            if (angle_rad - 1.5_f64.to_radians()).abs() < 1e-12)
    });
    expect_bad("zero_units.prr", Rail, Some(8), |e| {
        matches!(
            e,
            ReadError::BadUnitFactor {
                key: "units.len.f",
                ..
            }
        )
    });
}

#[test]
fn miniprof_key_after_data() {
    expect_bad("key_after_data.ban", Rail, Some(10), |e| {
        matches!(e, ReadError::Malformed { .. })
    });
}
