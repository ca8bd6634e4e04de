//! Profile readers against real files (CONTACT's benchmark and measured profiles, unchanged,
//! in `tests/data/profiles/`), one fixture per broken condition (`tests/data/profiles/bad/`),
//! and property tests that no input makes a parser panic.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use wheelrail::profile::ProfileKind::{self, Rail, Wheel};
use wheelrail::profile::read::{PointProfile, ProfileFormat, ReadError, parse_str, read_profile};
use wheelrail::profile::spline::{SmoothingSpline, curvature, default_lambda};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/profiles")
        .join(name)
}

fn read(name: &str, kind: ProfileKind) -> Result<PointProfile, ReadError> {
    read_profile(&data(name), kind)
}

fn spline(profile: &PointProfile, lambda: f64) -> SmoothingSpline {
    let (x, y) = profile.columns();
    SmoothingSpline::fit(&x, &y, lambda).expect("validated profiles always fit")
}

/// Asserts two side-frame points agree within `tol_mm` in both coordinates.
fn assert_point(got: [f64; 2], want: [f64; 2], tol_mm: f64) {
    assert!(
        (got[0] - want[0]).abs() <= tol_mm && (got[1] - want[1]).abs() <= tol_mm,
        "{got:?} vs {want:?} (tolerance {tol_mm} mm)"
    );
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
// EN 13715 S1002 and UIC60 from the Manchester benchmark files
// ---------------------------------------------------------------------------------------

/// EN 13715 check values are given to 1e-3 mm in the brief (kept: the brief's requirement);
/// the benchmark file agrees with the standard's piecewise definition to about 2e-6 mm
/// (NOTICE.md) and the interpolating spline adds less than 1e-5 mm at its 0.39 mm spacing
/// (measured at most 3.0e-6 mm at the four check values).
const EN13715_CHECK_TOL_MM: f64 = 1e-3;

#[test]
fn s1002_prw_gives_en13715_check_values() {
    let wheel = read("MBench_S1002_v3.prw", Wheel).unwrap();
    assert_eq!(wheel.kind, Wheel);
    assert_eq!(wheel.source.format, ProfileFormat::Simpack);
    assert_eq!(wheel.source.sha256.len(), 64);
    // 400 rows, the first (the vertical tangent at s = -70) commented out with `!`.
    assert_eq!(wheel.points.len(), 399);
    let s = spline(&wheel, 0.0);
    // profiles.md: F(0) = 0, F(-37.5) = 10, flange tip F(-55) = 28, F(60) = -2.635676.
    for (s_mm, f_mm) in [(0.0, 0.0), (-37.5, 10.0), (-55.0, 28.0), (60.0, -2.635676)] {
        let f = s.eval(s_mm)[0];
        assert!(
            (f - f_mm).abs() < EN13715_CHECK_TOL_MM,
            "F({s_mm}) = {f}, EN 13715: {f_mm}"
        );
    }
    // Tread slope at the taping line, profiles.md: F'(0) = -0.03359 (given to 4 digits;
    // measured 4.6e-6 off).
    assert!((s.eval(0.0)[1] + 0.03359).abs() < 1e-5);
    // The flange tip is the highest point, at s = -55 (within the 0.39 mm point spacing;
    // measured 0.11 mm, 4.8e-4 mm in height).
    let tip = highest(&wheel);
    assert!((tip[0] + 55.0).abs() < 0.2 && (tip[1] - 28.0).abs() < EN13715_CHECK_TOL_MM);
}

fn highest(p: &PointProfile) -> [f64; 2] {
    p.points
        .iter()
        .copied()
        .fold([f64::NAN, f64::NEG_INFINITY], |a, q| {
            if q[1] > a[1] { q } else { a }
        })
}

/// Bisection for the crown (slope 0) of a rail spline between `a` and `b`.
fn crown(s: &SmoothingSpline, mut a: f64, mut b: f64) -> f64 {
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        if s.eval(m)[1] > 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Gauge point: where the gauge face crosses 14 mm below the top (linear interpolation
/// between the points, as the face is nearly vertical there).
fn gauge_point(rail: &PointProfile, z_top: f64) -> f64 {
    let depth = z_top - 14.0;
    let i = rail.points.iter().position(|p| p[1] >= depth).unwrap();
    let ([y0, z0], [y1, z1]) = (rail.points[i - 1], rail.points[i]);
    y0 + (y1 - y0) * (depth - z0) / (z1 - z0)
}

/// Reference value (the project's reference notes, outside this repository): the MBench
/// UIC60 file (inclined 1:40) has its gauge point at y = -43.031; the linear interpolation
/// across the 0.03 mm point spacing on the face puts it 4.4e-4 mm off (measured).
const GAUGE_POINT_TOL_MM: f64 = 1e-3;

#[test]
fn uic60_prr_has_top_at_origin_and_gauge_point_at_43_031() {
    let rail = read("MBench_UIC60_v3.prr", Rail).unwrap();
    assert_eq!(rail.points.len(), 495);
    let s = spline(&rail, 0.0);
    let y_top = crown(&s, -5.0, 5.0);
    let z_top = s.eval(y_top)[0];
    // NOTICE.md: origin at the highest point of the inclined head. Measured: y_top =
    // 0.006 mm (the crown is flat: 1e-7 mm of height per 0.006 mm there), z_top = 7.3e-8 mm,
    // within the rounding of the file's points (printed to 1e-6 mm near the top), which
    // is the bound.
    assert!(y_top.abs() < 0.01, "crown at y = {y_top}");
    assert!(z_top.abs() < 5e-7, "crown at z = {z_top}");
    // The gauge side is at y < 0 and z is up: the foot of the gauge face is 38.5 mm down.
    assert!(rail.points[0][0] < -43.0 && rail.points[0][1] < -38.0);
    let y_gauge = gauge_point(&rail, z_top);
    assert!(
        (y_gauge + 43.031).abs() < GAUGE_POINT_TOL_MM,
        "gauge point at y = {y_gauge}"
    );
}

/// Both files print the same values with eight significant digits; mapped, they must agree
/// to rounding of the parse.
const SAME_POINT_TOL_MM: f64 = 1e-9;

#[test]
fn uic60_ban_is_the_prr_after_mapping() {
    let prr = read("MBench_UIC60_v3.prr", Rail).unwrap();
    let ban = read("MBench_UIC60_v3.ban", Rail).unwrap();
    assert_eq!(ban.source.format, ProfileFormat::MiniProf);
    // XYPoints=495; 19 rows start with `"` (commented out, as CONTACT reads them).
    assert_eq!(ban.points.len(), 495 - 19);
    // Every .ban point is a .prr point, in order, with offset 0 (both origins at the crown).
    let mut prr_points = prr.points.iter();
    for b in &ban.points {
        let found = prr_points.any(|p| {
            (p[0] - b[0]).abs() < SAME_POINT_TOL_MM && (p[1] - b[1]).abs() < SAME_POINT_TOL_MM
        });
        assert!(found, "ban point {b:?} is not in the prr");
    }
    assert_point(ban.points[0], prr.points[0], SAME_POINT_TOL_MM);
    assert_point(
        ban.points[ban.points.len() - 1],
        prr.points[prr.points.len() - 1],
        SAME_POINT_TOL_MM,
    );
}

// ---------------------------------------------------------------------------------------
// Curvature of the analytic circle files
// ---------------------------------------------------------------------------------------

/// Within this distance of the ends the natural end condition (f'' = 0) and the 4 mm filter
/// of the default smoothing dominate the curvature; the check stays inside.
const END_MARGIN_MM: f64 = 10.0;

/// Largest curvature error (relative to 1/R) over the circle files' interior with the
/// default smoothing. Measured: 1.2e-4 (circ_r300.prr, 0.3 mm spacing) and 6.5e-4
/// (circ_r100.prw, 0.1 mm spacing; its values are rounded to 1e-6 mm and its centre point
/// is 49 nm below the circle, see the next test).
const CIRCLE_CURVATURE_REL_TOL: f64 = 1e-3;

/// circ_r300.prr (rail, z down in the file) and circ_r100.prw (wheel): a convex crown and a
/// crowned tread both have curvature -1/R in their side frames (y up for the rail, F towards
/// the flange tip for the wheel).
#[test]
fn circle_files_give_curvature_minus_one_over_r() {
    for (name, kind, radius) in [
        ("circ_r300.prr", Rail, 300.0),
        ("circ_r100.prw", Wheel, 100.0),
    ] {
        let profile = read(name, kind).unwrap();
        let (x, _) = profile.columns();
        let s = spline(&profile, default_lambda(&x));
        let (a, b) = s.domain();
        let (a, b) = (a + END_MARGIN_MM, b - END_MARGIN_MM);
        let worst = (0..=2000)
            .map(|k| {
                let t = a + (b - a) * f64::from(k) / 2000.0;
                let [_, d1, d2] = s.eval(t);
                (curvature(d1, d2) * radius + 1.0).abs()
            })
            .fold(0.0, f64::max);
        println!("{name}: max relative curvature error {worst:.2e}");
        assert!(worst < CIRCLE_CURVATURE_REL_TOL, "{name}: {worst}");
    }
}

/// A data defect worth knowing: circ_r100.prw stores every value 4.9e-5 mm above the circle
/// except the centre point (0, 0). Interpolating, that 49 nm dip flips the sign of the
/// curvature at s = 0 (measured +0.0115 1/mm instead of -0.01); the default smoothing
/// absorbs it (measured -0.009993).
#[test]
fn circ_r100_centre_dip_needs_smoothing() {
    let wheel = read("circ_r100.prw", Wheel).unwrap();
    let [_, d1, d2] = spline(&wheel, 0.0).eval(0.0);
    assert!(curvature(d1, d2) > 0.0);
    let (x, _) = wheel.columns();
    let [_, d1, d2] = spline(&wheel, default_lambda(&x)).eval(0.0);
    assert!((curvature(d1, d2) * 100.0 + 1.0).abs() < CIRCLE_CURVATURE_REL_TOL);
}

// ---------------------------------------------------------------------------------------
// Measured MiniProf profiles
// ---------------------------------------------------------------------------------------

#[test]
fn avg_wheel_whl_is_measured_from_the_flange_back() {
    let wheel = read("avg_wheel.whl", Wheel).unwrap();
    // Free-text header; 728 rows of X Y 0.000; the last 57 are the outer face at X = 139.70
    // below the first one (dropped as an end face).
    assert_eq!(wheel.points.len(), 671);
    let first = wheel.points[0];
    let last = wheel.points[wheel.points.len() - 1];
    assert!(
        (first[0] + 68.45).abs() < SAME_POINT_TOL_MM,
        "X = 1.55 is s = -68.45"
    );
    assert!((last[0] - 69.70).abs() < SAME_POINT_TOL_MM && (last[1] + 18.19).abs() < 1e-9);
    // Flange tip: X = 14.73, Y = 28.03 in the file, so s = -55.27 like S1002's -55.
    let tip = highest(&wheel);
    assert!((tip[0] + 55.27).abs() < SAME_POINT_TOL_MM && (tip[1] - 28.03).abs() < 1e-9);
    // The taping line (X = 70.02 in the file) has Y = -0.00: F(0) = 0 within the file's
    // 0.01 mm resolution.
    let at_taping = wheel
        .points
        .iter()
        .min_by(|a, b| a[0].abs().total_cmp(&b[0].abs()))
        .unwrap();
    assert!(at_taping[0].abs() < 0.05 && at_taping[1].abs() < 0.005);
}

/// Both measured 2020 wheels zig-zag at the flange tip (the lateral coordinate goes back by
/// 0.6 and 0.01 mm); by the reader's contract that is an error naming the line.
#[test]
fn measured_wheels_with_flange_tip_zig_zags_are_refused() {
    for (name, line, previous) in [
        ("Car7216_0001r.whl", 223, 222),
        ("Car7358_0001r.whl", 216, 215),
    ] {
        let err = read(name, Wheel).unwrap_err();
        assert!(
            matches!(err, ReadError::NonMonotonic { line: l, previous_line: p, .. } if l == line && p == previous),
            "{err}"
        );
        assert_names_place(&err, &data(name), Some(line));
    }
}

#[test]
fn avg_hr_ban_zig_zag_at_the_gauge_corner_is_refused() {
    // Lines 135/136: X = 29.27 then 29.26 at the same height (upper-case extension).
    let err = read("avg_HR.BAN", Rail).unwrap_err();
    assert!(
        matches!(
            err,
            ReadError::NonMonotonic {
                line: 135,
                previous_line: 136,
                ..
            }
        ),
        "{err}"
    );
    assert_names_place(&err, &data("avg_HR.BAN"), Some(135));
}

#[test]
fn avg_low2_ban_drops_its_undercut_faces() {
    let rail = read("avg_low2.ban", Rail).unwrap();
    // MiniProf's Y is up here: the crown is the highest point, 0.22 mm below Y = 0.
    let top = highest(&rail);
    assert!((top[1] + 0.22).abs() < 1e-9 && (top[0] - 19.19).abs() < 1e-9);
    // Gauge side (X > 0 in the file, y < 0 here) ends at the most protruding point of the
    // gauge face, X = 25.59 at Y = -11.77 (line 490); the undercut below it is dropped.
    assert_point(rail.points[0], [-25.59, -11.77], SAME_POINT_TOL_MM);
    // Field side ends at the tip of the lip, X = -54.06.
    assert!((rail.points[rail.points.len() - 1][0] - 54.06).abs() < 1e-9);
}

// ---------------------------------------------------------------------------------------
// Kind, format and file errors
// ---------------------------------------------------------------------------------------

#[test]
fn extension_declares_the_kind() {
    let path = data("MBench_S1002_v3.prw");
    let err = read_profile(&path, Rail).unwrap_err();
    assert!(matches!(
        err,
        ReadError::WrongKind {
            line: None,
            expected: Rail,
            found: Wheel,
            ..
        }
    ));
    assert_names_place(&err, &path, None);
    assert!(err.to_string().ends_with("a wheel profile given as rail"));
}

#[test]
fn simpack_type_must_match_the_kind() {
    // A .prw file whose header says type = 0 (rail), line 4.
    let path = data("bad/rail_type_in.prw");
    let err = read_profile(&path, Wheel).unwrap_err();
    assert!(matches!(
        err,
        ReadError::WrongKind {
            expected: Wheel,
            found: Rail,
            ..
        }
    ));
    assert_names_place(&err, &path, Some(4));
    assert!(err.to_string().ends_with("a rail profile given as wheel"));
}

#[test]
fn miniprof_wheel_marker_in_a_ban_file_is_the_wrong_kind() {
    let path = data("bad/wheel_marker.ban");
    let err = read_profile(&path, Rail).unwrap_err();
    assert!(matches!(err, ReadError::WrongKind { found: Wheel, .. }));
    assert_names_place(&err, &path, Some(1));
}

#[test]
fn unknown_extension_and_missing_file() {
    let path = data("NOTICE.md");
    let err = read_profile(&path, Rail).unwrap_err();
    assert!(matches!(err, ReadError::UnknownFormat { ref extension, .. } if extension == "md"));
    assert_names_place(&err, &path, None);
    let path = data("no_such_profile.csv");
    let err = read_profile(&path, Rail).unwrap_err();
    assert!(matches!(err, ReadError::Io { .. }));
    assert_names_place(&err, &path, None);
}

// ---------------------------------------------------------------------------------------
// Format details on inline text
// ---------------------------------------------------------------------------------------

/// Crown R300 points: (y, depth below the top), mm.
fn crown_points() -> Vec<(f64, f64)> {
    (0..12)
        .map(|i| {
            let y = -11.0 + 2.0 * f64::from(i);
            (y, 300.0 - (300.0_f64 * 300.0 - y * y).sqrt())
        })
        .collect()
}

#[test]
fn reversed_file_is_reordered() {
    // The crown listed from the field side (y = 11 first) is fine: it is reversed.
    let reversed = read("bad/reversed.csv", Rail).unwrap();
    assert_eq!(reversed.points.len(), 12);
    for (got, (y, depth)) in reversed.points.iter().zip(crown_points()) {
        // The fixture prints 6 decimals.
        assert!(
            (got[0] - y).abs() < 1e-6 && (got[1] + depth).abs() < 1e-6,
            "{got:?}"
        );
    }
}

/// SIMPACK processing in its numbered order: the y bound applies to shifted values, the
/// shift is in file units (metres here), `!` comments a point out, a point closer than
/// `point.dist.min` is dropped, the weight column and Fortran exponents are read.
#[test]
fn simpack_processing_order_and_units() {
    let mut rows = String::new();
    for (i, (y, depth)) in crown_points().iter().enumerate() {
        // Metres; z up in the file (mirror.z = 1 turns it into SIMPACK's z down).
        rows += &format!("  {:.9e}  {:.9e}  1.0\n", y / 1000.0, -depth / 1000.0);
        if i == 5 {
            rows += &format!("  {:.9e}  {:.9e}\n", (y + 1e-4) / 1000.0, -depth / 1000.0);
            rows += "! 0.5 0.5  a commented-out point\n";
        }
    }
    let rows = rows.replacen("e-3", "D-3", 1);
    let text = format!(
        "header.begin\n type = 0\nheader.end\nspline.begin\n\
         point.dist.min = 1e-6 ! m\n shift.y = 0.001\n bound.y.min = -1\n bound.y.max = 0.0115\n\
         mirror.y = 1\n mirror.z = 1\n inversion = 1\n units.len.f = 1\n\
         point.begin\n{rows}point.end\nspline.end\n"
    );
    let rail = parse_str(&text, ProfileFormat::Simpack, Rail, "inline.prr").unwrap();
    // Shifted by 1 mm, the last crown point (y = 11 -> 12 mm) falls outside bound.y.max = 11.5
    // mm; unshifted it would have stayed. Mirrored, y = -(y_file + 1).
    let expected: Vec<[f64; 2]> = crown_points()[..11]
        .iter()
        .rev()
        .map(|&(y, depth)| [-(y + 1.0), -depth])
        .collect();
    assert_eq!(rail.points.len(), expected.len());
    for (got, want) in rail.points.iter().zip(&expected) {
        assert!(
            (got[0] - want[0]).abs() < 1e-6 && (got[1] - want[1]).abs() < 1e-6,
            "{got:?} vs {want:?}"
        );
    }
}

/// MiniProf rail with a `Key=Value` header: ColumnDef puts X third, XOffset shifts X, and
/// Y up (MiniProf's own convention) is recognised from the shape.
#[test]
fn miniprof_columndef_offset_and_vertical_direction() {
    let mut text = String::from("Filename=inline.ban\nXOffset=2.0\nYOffset=\nColumnDef=A,Y,X\n\n");
    for (y, depth) in crown_points() {
        // X grows towards the gauge side: X = -y - 2 so that X + XOffset = -y.
        text += &format!("0.1 {} {}\n", -depth, -y - 2.0);
    }
    let rail = parse_str(&text, ProfileFormat::MiniProf, Rail, "inline.ban").unwrap();
    for (got, (y, depth)) in rail.points.iter().zip(crown_points()) {
        assert!(
            (got[0] - y).abs() < 1e-12 && (got[1] + depth).abs() < 1e-12,
            "{got:?}"
        );
    }
    // The same file with Y down (like MBench_UIC60_v3.ban) gives the same profile.
    let flipped = text.replace("0.1 -", "0.1 ");
    let rail_down = parse_str(&flipped, ProfileFormat::MiniProf, Rail, "inline.ban").unwrap();
    assert_eq!(rail_down.points.len(), rail.points.len());
    for (down, up) in rail_down.points.iter().zip(&rail.points) {
        assert_point(*down, *up, 1e-12);
    }
}

/// A MiniProf file without the blank line after its header: data start at the first line
/// of numbers only.
#[test]
fn miniprof_without_blank_line() {
    let mut text = String::from("MINIPROF 101 148 1994 3 24\n32.58 37.11 14.71  (Sd/Sh/qR)\n");
    for x in 0..12 {
        let x = 20.0 + 10.0 * f64::from(x);
        text += &format!("{x} {}\n", 0.05 * (70.0 - x));
    }
    let wheel = parse_str(&text, ProfileFormat::MiniProf, Wheel, "inline.whl").unwrap();
    assert_eq!(wheel.points.len(), 12);
    assert_point(wheel.points[0], [-50.0, 2.5], SAME_POINT_TOL_MM);
}

// ---------------------------------------------------------------------------------------
// No input makes a parser panic
// ---------------------------------------------------------------------------------------

const FORMATS: [ProfileFormat; 3] = [
    ProfileFormat::Csv,
    ProfileFormat::Simpack,
    ProfileFormat::MiniProf,
];

fn parse_all(text: &str) {
    for format in FORMATS {
        for kind in [Wheel, Rail] {
            if let Ok(p) = parse_str(text, format, kind, "fuzz") {
                assert!(p.points.len() >= 10);
                assert!(p.points.windows(2).all(|w| w[1][0] > w[0][0]));
                assert!(p.points.iter().flatten().all(|v| v.is_finite()));
            }
        }
    }
}

/// Lines that drive the parsers into their deeper paths.
fn plausible_line() -> impl Strategy<Value = String> {
    let keyword = prop::sample::select(vec![
        "header.begin",
        "header.end",
        "spline.begin",
        "spline.end",
        "point.begin",
        "point.end",
        "type = 0",
        "type = 1",
        "type = 7",
        "mirror.y = 1",
        "mirror.z = 1",
        "inversion = 1",
        "units.len.f = 1000",
        "units.len.f = 1",
        "units.len.f = 0",
        "units.len.f = 1e-300",
        "units.ang.f = 1e-300",
        "rotate = 0",
        "rotate = 0.1",
        "shift.y = 1e308",
        "bound.y.min = -5",
        "bound.y.max = 5",
        "bound.z.min = -1",
        "bound.z.max = 1",
        "point.dist.min = 0.5",
        "ColumnDef=X,Y",
        "ColumnDef=Y",
        "ColumnDef=A,C,Y,X",
        "XOffset=1e308",
        "YOffset=",
        "#MINIWHEELPROF",
        "",
        "y_mm,z_mm",
        "s_mm,F_mm,x",
        "y_m,z_m",
        "\"1 2",
        "! 1 2",
        "% 1 2",
        "1.0D+03 2",
        "nan inf",
        "'quoted ! text'",
    ])
    .prop_map(str::to_owned);
    let row = (
        any::<f64>(),
        any::<f64>(),
        prop::sample::select(vec![" ", ",", "\t", " , "]),
    )
        .prop_map(|(a, b, sep)| format!("{a}{sep}{b}"));
    let small_row = (-100.0..100.0_f64, -50.0..50.0_f64).prop_map(|(a, b)| format!("{a} {b}"));
    prop_oneof![keyword, row, small_row.clone(), small_row, "[ -~]{0,30}"]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn parsers_never_panic_on_arbitrary_text(text in "\\PC{0,400}") {
        parse_all(&text);
    }

    #[test]
    fn parsers_never_panic_on_arbitrary_bytes(bytes in prop::collection::vec(any::<u8>(), 0..600)) {
        parse_all(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn parsers_never_panic_on_plausible_lines(lines in prop::collection::vec(plausible_line(), 0..80)) {
        parse_all(&lines.join("\n"));
    }

    #[test]
    fn spline_fit_never_panics(
        steps in prop::collection::vec(1e-6..5.0_f64, 1..60),
        ys in prop::collection::vec(-1e3..1e3_f64, 60),
        lambda in prop_oneof![Just(0.0), 0.0..1e6_f64],
    ) {
        let mut x = vec![0.0];
        for s in &steps {
            x.push(x[x.len() - 1] + s);
        }
        let y = &ys[..x.len()];
        if let Ok(s) = SmoothingSpline::fit(&x, y, lambda) {
            let (a, b) = s.domain();
            for k in 0..=20 {
                let t = a + (b - a) * f64::from(k) / 20.0;
                prop_assert!(s.eval(t).iter().all(|v| v.is_finite()));
            }
        }
    }
}

/// A real wheel file (EN 15302's R-UIC519A) as a European spreadsheet exports it:
/// semicolons with decimal commas, tabs with decimal commas, semicolons with points, each
/// read to the same points as the file with commas (issue 32: `s_mm;F_mm` used to give
/// "missing value in column 2").
#[test]
fn spreadsheet_exports_with_semicolons_and_tabs_read_as_the_csv() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/en15302/R-UIC519A.csv");
    let text = std::fs::read_to_string(&path).unwrap();
    let want = parse_str(&text, ProfileFormat::Csv, Wheel, "commas.csv")
        .unwrap()
        .columns();
    let export = |separator: &str, decimal: &str| -> String {
        text.lines()
            .map(|l| {
                if l.starts_with('#') {
                    l.to_string()
                } else {
                    l.split(',')
                        .map(|f| f.replace('.', decimal))
                        .collect::<Vec<_>>()
                        .join(separator)
                }
            })
            .collect::<Vec<_>>()
            .join("\r\n")
    };
    for (separator, decimal) in [(";", ","), ("\t", ","), (";", ".")] {
        let exported = export(separator, decimal);
        let got = parse_str(&exported, ProfileFormat::Csv, Wheel, "export.csv")
            .unwrap_or_else(|e| panic!("{separator:?} {decimal:?}: {e}"))
            .columns();
        assert_eq!(got, want, "{separator:?} with {decimal:?}");
    }
    // A file whose rows switch to semicolons under a header of commas is refused naming both.
    let mixed = text.replacen("\n-69.86500,", "\n-69.86500;", 1);
    let e = parse_str(&mixed, ProfileFormat::Csv, Wheel, "mixed.csv").unwrap_err();
    assert!(
        e.to_string()
            .contains("separates its fields by semicolons, but the header by commas"),
        "{e}"
    );
}
