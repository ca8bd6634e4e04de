//! Profile file readers: the project's CSV, SIMPACK `.prw`/`.prr` and MiniProf `.whl`/`.ban`.
//!
//! Every reader returns a [`PointProfile`]: points in the profile's own **side frame**, sorted
//! by strictly increasing lateral coordinate, checked by `validate`. Readers convert at the
//! edge (units, mirroring, origin of the lateral coordinate) and nowhere else; nothing
//! downstream needs to know which format a profile came from.
//!
//! # The side frame
//!
//! The lateral coordinate grows towards the **field side** (away from the track centre).
//!
//! * Wheel: `(s, F)`. `s` (mm) from the taping line (70 mm from the inner face of the wheel),
//!   the flange at `s < 0`; `F` (mm) the radius increase over the nominal radius, positive
//!   towards the flange tip. EN 13715 S1002: `F(0) = 0`, flange tip `F(-55) = 28`.
//! * Rail: `(y, z)`. `y` (mm) lateral, the gauge side at `y < 0` when the file's origin is on
//!   the head; `z` (mm) height, positive up. The origin is whatever the file has: placing the
//!   rail (finding its top and gauge point) is the job of [`crate::track`], not of the reader.
//!
//! # Formats and how they map to the side frame
//!
//! ## CSV (`.csv`, the project's own format)
//!
//! ```text
//! # optional comment lines, starting with '#' in the first column
//! s_mm,F_mm,tan_gamma,curvature_per_mm
//! -70.0,9.519259,...
//! ```
//!
//! One header row, then one point per row, comma-separated. The first two columns are the
//! lateral and the vertical coordinate **already in the side frame, in millimetres**; further
//! columns are ignored (the project writes its generated S1002 and UIC60 with `tan_gamma` and
//! `curvature_per_mm`). The first two header names must end in `_mm`: names ending in `_m`,
//! `_cm`, `_um` or `_in` are a [`ReadError::WrongUnits`], names without a unit a
//! [`ReadError::MissingUnits`]. `s_mm` in the first column declares a wheel and `y_mm` a
//! rail; either, read as the other kind, is a [`ReadError::WrongKind`]. Blank lines are
//! skipped.
//!
//! ## SIMPACK (`.prw` wheel, `.prr` rail)
//!
//! A `header.begin ... header.end` block (`type = 0` rail, `1` wheel; a mismatch with the
//! requested kind is a [`ReadError::WrongKind`]), then `spline.begin ... spline.end` holding
//! processing entries and `point.begin ... point.end` with rows `y z [weight]` (the weight is
//! ignored). `!` starts a comment anywhere outside a quoted string, so `!` at the start of a
//! point row comments that point out; `%` is accepted as well (CONTACT's `circ_r300.prr`
//! comments points out with it). Numbers may use Fortran's `D` exponent.
//!
//! The processing entries are applied in the order SIMPACK numbers them in the comments of
//! its own file template (`! 1: Minimum point distance`, `! 2: y shift`, `! 3: Rotation`,
//! `! 4: y boundary`, `! 5: y mirror`, `! 6: Inversion`, `! 7: Unit factor`, see
//! `MBench_S1002_v3.prw`), which is also the order in which CONTACT's `read_simpack_profile`
//! (E. Vollebregt, `eve70a/CONTACT`, `src/m_profile.f90`) applies them:
//!
//! 1. `point.dist.min`: a point closer than this to the previous kept point is dropped
//!    (only when > 0);
//! 2. `shift.y`, `shift.z`: added to the coordinates (file length units);
//! 3. `rotate` (angle unit `units.ang.f` per radian): only 0 is accepted, anything else is a
//!    [`ReadError::UnsupportedRotation`]: no source we could check documents its sign, and
//!    CONTACT refuses it too;
//! 4. `bound.y.min/max`: points outside are dropped; `bound.z.min/max`: z is clipped to the
//!    interval (each only when min < max; the benchmark files disable them with min = 1 >
//!    max = 0);
//! 5. `mirror.y`, `mirror.z` (0/1): negate y or z;
//! 6. `inversion` (0/1): reverse the point order (validation orders points anyway);
//! 7. `units.len.f` (length unit per metre, 1000 = mm; SIMPACK's SI default 1 = metres when
//!    absent): coordinates are multiplied by `1000 / units.len.f` to give mm.
//!
//! The result is SIMPACK's profile frame, which maps to the side frame as follows.
//!
//! * Wheel: `(s, F) = (y, z)`. Evidence: in `MBench_S1002_v3.prw` the stored y is `-s` with
//!   the flange at y > 0 and `mirror.y = 1`; after mirroring, the flange tip (largest z,
//!   28.0) is at y = -55 and z(0) = 0, as EN 13715 has it. `circ_r100.prw` (z = sqrt(100^2 -
//!   y^2) - 100, largest at y = 0) agrees: z grows away from the axle, like F.
//! * Rail: `(y, z_side) = (y, -z)`: SIMPACK's rail z points down. Evidence: in
//!   `MBench_UIC60_v3.prr` z is 0 at the crown and +38.5 at the foot of the gauge face,
//!   which is at y = -43.7 (the gauge side at y < 0 as in the side frame), and `circ_r300.prr`
//!   has z = 300 - sqrt(300^2 - y^2) >= 0.
//!
//! ## MiniProf (`.whl` wheel, `.ban` rail)
//!
//! A header, a blank line, then rows `X Y [more columns]`. The header is either `Key=Value`
//! lines (`ColumnDef=X,Y,A,C` says which columns hold X and Y; `XOffset`, `YOffset` are added
//! to X and Y as CONTACT does; other keys are ignored) or free text (`avg_wheel.whl`,
//! `Car7216_0001r.whl`). Lines starting with `"`, `!`, `%` or `#` are comments (CONTACT's
//! `read_miniprof_profile` treats the same four characters so; in `MBench_UIC60_v3.ban` a
//! leading `"` comments out 19 of the 495 points, in avg_HR.BAN it comments out header
//! keys). `#MINIWHEELPROF` on a line marks a wheel file. Without a blank line the data start
//! at the first line that consists of numbers only. Text after the declared columns is
//! ignored (avg_low2.ban annotates its last point).
//!
//! * Wheel: `(s, F) = (X - 70, Y)`. MiniProf measures wheels from the flange back (inner
//!   face): X = 0 on the inner face, growing towards the field side, and Y is the radius
//!   increase referred to the taping line, which EN 13715 puts 70 mm from the inner face.
//!   Evidence: in Car7216_0001r.whl and Car7358_0001r.whl the first points form a vertical
//!   line at X = 0 +- 0.16 mm (the inner face, Y from -23 up); Y(X = 70.1) = 0.09 and 0.11
//!   mm (Car7216, Car7358) and -0.00 (avg_wheel.whl); the flange tips (largest Y, 27.8, 27.0
//!   and 28.0 mm) lie at X = 15.9, 15.5 and 14.7, i.e. s = -54 to -55 like S1002's tip at
//!   s = -55. The vertical origin is kept as the file has it (F(0) = 0.09 mm for Car7216):
//!   it is the measuring instrument's reference, and no re-levelling is done here.
//! * Rail: `(y, z) = (-X, +-Y)`. MiniProf's X grows towards the gauge side: avg_low2.ban (a
//!   worn low rail) has its field-side lip (plastic flow, lateral minimum X = -53.6 at 4.8
//!   mm below the crown) at X < 0 and its gauge face (annotated "gauge face") at X > 0;
//!   avg_HR.BAN ends on a steep face at X = +46 mm; `MBench_UIC60_v3.ban` is the .prr with X
//!   = -y. Y is up in MiniProf's own files (avg_HR.BAN, avg_low2.ban: crown at Y = -0.2,
//!   faces down to Y = -34) but down in `MBench_UIC60_v3.ban` (Y = z of the .prr, +38.5 at
//!   the foot of the gauge face), so the direction is detected from the shape (see
//!   `validate`: the crest is inside the curve, the side faces at its ends). With this
//!   mapping `MBench_UIC60_v3.ban` gives exactly the points of `MBench_UIC60_v3.prr` (offset
//!   0: both files have their origin at the crown, XOffset = YOffset = 0), less the 19
//!   commented-out ones.
//!
//! MiniProf files include the end faces of the measured body (the flange back and the outer
//! face of a wheel, the side faces below a rail head, vertical or undercut). They are not
//! part of the profile as a function of its lateral coordinate and are dropped when they lie
//! in the shadow of the last point before them (see `validate`, step 3); everything else
//! that goes back laterally is an error naming its line. Measured files do zig-zag: both
//! 2020 wheels of the test data step back at the flange tip (Car7216_0001r.whl line 223 by
//! 0.6 mm, Car7358_0001r.whl line 216 by 0.01 mm) and avg_HR.BAN at the gauge corner (line
//! 135, 0.01 mm); by default they are refused rather than silently edited.
//!
//! # Dropping points that step back (opt-in)
//!
//! A caller that wants to run such files asks for it explicitly with
//! [`ReadOptions`]`{ step_back: `[`StepBack::Drop`]` }` and [`read_profile_with`] or
//! `parse_str_with`: walking outwards from the crest, every point that does not advance the
//! lateral coordinate beyond the points kept before it is dropped, as CONTACT's
//! `delete_foldback` option does (details in `validate`), and the lines of the dropped
//! points are listed in [`PointProfile::dropped_step_backs`] so that the caller can report
//! them. Files the default reader accepts read to the same points with nothing dropped.

mod csv;
mod error;
mod fields;
mod miniprof;
mod simpack;
pub(crate) mod validate;

use std::fmt;
use std::path::Path;

pub use error::{Axis, Field, ReadError};

use crate::profile::ProfileKind;

/// A supported profile file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ProfileFormat {
    /// The project's CSV (`.csv`), see the [module docs](self).
    Csv,
    /// SIMPACK `.prw` (wheel) / `.prr` (rail).
    Simpack,
    /// MiniProf `.whl` (wheel) / `.ban` (rail).
    MiniProf,
    /// Points given in memory ([`PointProfile::from_points`]), no file.
    Points,
}

impl ProfileFormat {
    /// The format an extension (without the dot, any case) names, and the profile kind the
    /// extension implies (`None` for `.csv`, which holds either).
    ///
    /// ```
    /// use wheelrail::profile::{ProfileKind, read::ProfileFormat};
    /// assert_eq!(
    ///     ProfileFormat::from_extension("PRR"),
    ///     Some((ProfileFormat::Simpack, Some(ProfileKind::Rail)))
    /// );
    /// assert_eq!(ProfileFormat::from_extension("txt"), None);
    /// ```
    pub fn from_extension(extension: &str) -> Option<(ProfileFormat, Option<ProfileKind>)> {
        match extension.to_ascii_lowercase().as_str() {
            "csv" => Some((ProfileFormat::Csv, None)),
            "prw" => Some((ProfileFormat::Simpack, Some(ProfileKind::Wheel))),
            "prr" => Some((ProfileFormat::Simpack, Some(ProfileKind::Rail))),
            "whl" => Some((ProfileFormat::MiniProf, Some(ProfileKind::Wheel))),
            "ban" => Some((ProfileFormat::MiniProf, Some(ProfileKind::Rail))),
            _ => None,
        }
    }

    /// A short lower-case name: `csv`, `simpack`, `miniprof`, `points`.
    pub fn name(self) -> &'static str {
        match self {
            ProfileFormat::Csv => "csv",
            ProfileFormat::Simpack => "simpack",
            ProfileFormat::MiniProf => "miniprof",
            ProfileFormat::Points => "points",
        }
    }
}

impl fmt::Display for ProfileFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What a reader does with a point whose lateral coordinate steps back (a zig-zag) and that
/// is not part of a measured end face.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum StepBack {
    /// The file is refused: [`ReadError::NonMonotonic`] or [`ReadError::DuplicatePoint`]
    /// naming the line (the default).
    #[default]
    Refuse,
    /// The point is dropped and its line listed in [`PointProfile::dropped_step_backs`]
    /// (see the [module docs](self#dropping-points-that-step-back-opt-in)).
    Drop,
}

/// Options of [`read_profile_with`] and `parse_str_with`; the default is what
/// [`read_profile`] and `parse_str` do.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct ReadOptions {
    pub(crate) step_back: StepBack,
}

impl ReadOptions {
    /// Reading with `step_back` done to points that step back (any choice is valid).
    pub const fn new(step_back: StepBack) -> ReadOptions {
        ReadOptions { step_back }
    }

    /// What is done with points that step back.
    pub fn step_back(&self) -> StepBack {
        self.step_back
    }
}

/// Where a profile came from: enough to tell two runs apart that read different files.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ProfileSource {
    /// The path as given to [`read_profile`], or the origin given to `parse_str`.
    pub path: String,
    /// SHA-256 of the file's bytes (of the text for `parse_str`), lower-case hex.
    pub sha256: String,
    /// The format it was read as.
    pub format: ProfileFormat,
}

/// A profile as sampled points in its side frame (see the [module docs](self)).
///
/// Invariants, established by the readers: at least
/// [`MIN_POINTS`](PointProfile::MIN_POINTS) points, all finite, sorted by strictly increasing
/// lateral coordinate.
#[derive(Debug, Clone, PartialEq)]
pub struct PointProfile {
    /// Wheel or rail; decides what the two coordinates mean.
    pub kind: ProfileKind,
    /// `[lateral, vertical]` in mm, side frame: `[s, F]` for a wheel, `[y, z]` for a rail.
    pub points: Vec<[f64; 2]>,
    /// The file it was read from.
    pub source: ProfileSource,
    /// 1-based lines of the points dropped because they stepped back (only with
    /// [`StepBack::Drop`]; empty otherwise). End faces of MiniProf files are not listed.
    pub dropped_step_backs: Vec<usize>,
}

impl PointProfile {
    /// The fewest points a profile may have: a spline through fewer cannot hold a tread and
    /// a flange (see the readers' checks).
    pub const MIN_POINTS: usize = validate::MIN_POINTS;

    /// A profile from points in memory, `[lateral, vertical]` in mm in the side frame (`[s,
    /// F]` for a wheel, `[y, z]` for a rail, see the [module docs](self)), checked as a file's
    /// points are: finite, at least a few, strictly increasing lateral coordinate (either
    /// order accepted), plausible extents in mm, a wheel's flange at `s < 0`. `name` stands
    /// for the file in messages, whose "line" numbers count the points from 1.
    ///
    /// # Errors
    /// The [`ReadError`] of the first failed check.
    ///
    /// # Example
    /// ```
    /// use wheelrail::profile::{Profile, ProfileKind, read::PointProfile};
    /// // A 1:20 coned tread from s = -20 to 40 mm with a 30 mm flange below s = -20.
    /// let points: Vec<[f64; 2]> = (0..=120)
    ///     .map(|i| -50.0 + 0.75 * f64::from(i))
    ///     .map(|s: f64| [s, if s < -20.0 { 1.0 + (-20.0 - s) } else { -s / 20.0 }])
    ///     .collect();
    /// let points = PointProfile::from_points(ProfileKind::Wheel, "cone", points)?;
    /// let wheel = Profile::from_points(points, 0.0)?;
    /// assert!((wheel.tan_gamma(10.0) - 0.05).abs() < 1e-9);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn from_points(
        kind: ProfileKind,
        name: &str,
        points: Vec<[f64; 2]>,
    ) -> Result<PointProfile, ReadError> {
        let bytes: Vec<u8> = points
            .iter()
            .flat_map(|p| [p[0].to_le_bytes(), p[1].to_le_bytes()])
            .flatten()
            .collect();
        let sha256 = sha256_hex(&bytes);
        let raw = points
            .iter()
            .enumerate()
            .map(|(i, p)| fields::RawPoint {
                lat: p[0],
                vert: p[1],
                line: i + 1,
            })
            .collect();
        let (points, dropped_step_backs) = validate::finish(raw, name, false, StepBack::Refuse)?;
        if kind == ProfileKind::Wheel {
            validate::check_flange_side(&points, name)?;
        }
        Ok(PointProfile {
            kind,
            points,
            source: ProfileSource {
                path: name.to_owned(),
                sha256,
                format: ProfileFormat::Points,
            },
            dropped_step_backs,
        })
    }

    /// The lateral and vertical coordinates as two columns (mm), e.g. to fit a
    /// smoothing spline as [`Profile::from_points`](crate::profile::Profile::from_points) does.
    pub fn columns(&self) -> (Vec<f64>, Vec<f64>) {
        self.points.iter().map(|p| (p[0], p[1])).unzip()
    }
}

/// Reads a wheel or rail profile file, choosing the reader by the file extension (`.csv`,
/// `.prw`/`.prr`, `.whl`/`.ban`, any case).
///
/// # Units
///
/// Returns millimetres in the side frame of `kind` whatever the file's units and axes.
///
/// # Errors
///
/// [`ReadError::Io`] if the file cannot be read, [`ReadError::UnknownFormat`] for another
/// extension, [`ReadError::WrongKind`] if the extension (`.prw`/`.whl` wheel, `.prr`/`.ban`
/// rail) or the file's contents declare the other kind, and every error of `parse_str`.
///
/// # Examples
///
/// ```
/// use std::path::Path;
/// use wheelrail::profile::{ProfileKind, read::read_profile};
///
/// let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/profiles/MBench_S1002_v3.prw");
/// let wheel = read_profile(&path, ProfileKind::Wheel)?;
/// // EN 13715 S1002: the flange tip is 28 mm above the taping line, at s = -55 mm.
/// let tip = wheel.points.iter().copied().fold([0.0, f64::MIN], |a, p| if p[1] > a[1] { p } else { a });
/// assert!((tip[1] - 28.0).abs() < 1e-3 && (tip[0] + 55.0).abs() < 0.2);
/// # Ok::<(), wheelrail::profile::read::ReadError>(())
/// ```
pub fn read_profile(path: &Path, kind: ProfileKind) -> Result<PointProfile, ReadError> {
    read_profile_with(path, kind, &ReadOptions::default())
}

/// [`read_profile`] with [`ReadOptions`], e.g. to read a measured file whose points zig-zag.
///
/// # Errors
///
/// As [`read_profile`]; with [`StepBack::Drop`] no [`ReadError::NonMonotonic`] or
/// [`ReadError::DuplicatePoint`] (the points are dropped), but [`ReadError::TooFewPoints`]
/// when too few remain.
///
/// # Examples
///
/// ```
/// use std::path::Path;
/// use wheelrail::profile::{ProfileKind, read::{read_profile, read_profile_with, ReadOptions, StepBack}};
///
/// let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/profiles/Car7216_0001r.whl");
/// // This measured wheel steps back by 0.6 mm at its flange tip (line 223).
/// assert!(read_profile(&path, ProfileKind::Wheel).is_err());
/// let options = ReadOptions::new(StepBack::Drop);
/// let wheel = read_profile_with(&path, ProfileKind::Wheel, &options)?;
/// assert!(wheel.dropped_step_backs.contains(&223));
/// assert!(wheel.points.windows(2).all(|w| w[1][0] > w[0][0]));
/// # Ok::<(), wheelrail::profile::read::ReadError>(())
/// ```
pub fn read_profile_with(
    path: &Path,
    kind: ProfileKind,
    options: &ReadOptions,
) -> Result<PointProfile, ReadError> {
    let origin = path.display().to_string();
    let extension = path
        .extension()
        .map(|e| e.to_string_lossy().into_owned())
        .unwrap_or_default();
    let Some((format, implied)) = ProfileFormat::from_extension(&extension) else {
        return Err(ReadError::UnknownFormat { origin, extension });
    };
    validate::check_kind(implied.map(|k| (k, None)), kind, &origin)?;
    let bytes = std::fs::read(path).map_err(|source| ReadError::Io {
        origin: origin.clone(),
        source,
    })?;
    // Measured files come from Windows tools and may carry Latin-1 text in header fields;
    // replacing undecodable bytes keeps the header readable and makes a bad byte inside a
    // number a NonNumeric error on its line. (A valid file, the usual case, is checked by
    // the standard library's faster validator first: the same text.)
    let text = match std::str::from_utf8(&bytes) {
        Ok(text) => std::borrow::Cow::Borrowed(text),
        Err(_) => String::from_utf8_lossy(&bytes),
    };
    parse_with_hash(&text, format, kind, &origin, sha256_hex(&bytes), options)
}

/// Parses profile text in a given format, as [`read_profile`] does after reading the file.
///
/// `origin` names the text in error messages and in [`ProfileSource::path`]. Never panics,
/// whatever the text.
///
/// # Errors
///
/// [`ReadError::Empty`] for blank text; the format's syntax errors
/// ([`ReadError::NonNumeric`], [`ReadError::NonFinite`], [`ReadError::MissingField`],
/// [`ReadError::Malformed`], [`ReadError::WrongUnits`], [`ReadError::MissingUnits`],
/// [`ReadError::MissingHeader`], [`ReadError::UnsupportedRotation`],
/// [`ReadError::BadUnitFactor`], [`ReadError::WrongKind`]); then the checks of `validate`
/// ([`ReadError::NoPoints`], [`ReadError::TooFewPoints`], [`ReadError::DuplicatePoint`],
/// [`ReadError::NonMonotonic`], [`ReadError::ImplausibleExtent`]).
///
/// # Examples
///
/// ```
/// use wheelrail::profile::{ProfileKind, read::{parse_str, ProfileFormat}};
///
/// // A rail crown of radius 300 mm, listed from the field side: the reader reorders it.
/// let mut text = String::from("# R300 crown\ny_mm,z_mm\n");
/// for i in (0..=20).rev() {
///     let y = -10.0 + i as f64;
///     text += &format!("{y},{}\n", (300.0_f64 * 300.0 - y * y).sqrt() - 300.0);
/// }
/// let rail = parse_str(&text, ProfileFormat::Csv, ProfileKind::Rail, "crown.csv")?;
/// assert_eq!(rail.points.len(), 21);
/// let [y, z] = rail.points[0];
/// assert!((y + 10.0).abs() < 1e-12 && (z - ((300.0_f64 * 300.0 - 100.0).sqrt() - 300.0)).abs() < 1e-12);
/// assert_eq!(rail.source.sha256.len(), 64);
/// # Ok::<(), wheelrail::profile::read::ReadError>(())
/// ```
pub fn parse_str(
    text: &str,
    format: ProfileFormat,
    kind: ProfileKind,
    origin: &str,
) -> Result<PointProfile, ReadError> {
    parse_str_with(text, format, kind, origin, &ReadOptions::default())
}

/// `parse_str` with [`ReadOptions`].
///
/// # Errors
///
/// As `parse_str`; with [`StepBack::Drop`] no [`ReadError::NonMonotonic`] or
/// [`ReadError::DuplicatePoint`], but [`ReadError::TooFewPoints`] when too few remain.
pub fn parse_str_with(
    text: &str,
    format: ProfileFormat,
    kind: ProfileKind,
    origin: &str,
    options: &ReadOptions,
) -> Result<PointProfile, ReadError> {
    parse_with_hash(
        text,
        format,
        kind,
        origin,
        sha256_hex(text.as_bytes()),
        options,
    )
}

fn parse_with_hash(
    text: &str,
    format: ProfileFormat,
    kind: ProfileKind,
    origin: &str,
    sha256: String,
    options: &ReadOptions,
) -> Result<PointProfile, ReadError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim().is_empty() {
        return Err(ReadError::Empty {
            origin: origin.to_owned(),
        });
    }
    let (raw, trim_faces) = match format {
        ProfileFormat::Csv => (csv::parse(text, kind, origin)?, false),
        ProfileFormat::Simpack => (simpack::parse(text, kind, origin)?, false),
        ProfileFormat::MiniProf => (miniprof::parse(text, kind, origin)?, true),
        ProfileFormat::Points => {
            return Err(ReadError::Malformed {
                origin: origin.to_owned(),
                line: 1,
                problem: "in-memory points are not a text format: use PointProfile::from_points"
                    .to_owned(),
            });
        }
    };
    let (points, dropped_step_backs) =
        validate::finish(raw, origin, trim_faces, options.step_back)?;
    if kind == ProfileKind::Wheel {
        validate::check_flange_side(&points, origin)?;
    }
    Ok(PointProfile {
        kind,
        points,
        source: ProfileSource {
            path: origin.to_owned(),
            sha256,
            format,
        },
        dropped_step_backs,
    })
}

/// SHA-256 of `bytes` as lower-case hex: the provenance hash of profile files and tables.
pub fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::{Digest, Sha256};
    use std::fmt::Write;
    Sha256::digest(bytes)
        .iter()
        .fold(String::with_capacity(64), |mut hex, b| {
            // Writing to a String cannot fail.
            let _ = write!(hex, "{b:02x}");
            hex
        })
}
