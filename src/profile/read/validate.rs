//! Checks every reader applies to the points it read, in the side frame, before a
//! [`PointProfile`](super::PointProfile) exists.
//!
//! In order:
//!
//! 1. at least one point ([`ReadError::NoPoints`]) and at least [`MIN_POINTS`]
//!    ([`ReadError::TooFewPoints`]), all finite after the reader's conversions
//!    ([`ReadError::NonFinite`]);
//! 2. orientation: a file listed from the field side towards the flange/gauge side is
//!    reversed (that is fine, only the order changes);
//! 3. for measured MiniProf files only, the end faces are dropped: the flange-back and outer
//!    faces of a wheel, the side faces below a rail head. They are vertical or undercut, so
//!    their lateral coordinate jitters or goes back, and no contact happens there. From the
//!    crest (the highest point: flange tip or rail crown) the run of strictly increasing
//!    lateral coordinate is followed to each side; where it stops early, the remaining end
//!    points are dropped if they lie in the shadow of the last kept point (the anchor):
//!    every one lower than the anchor and sticking out beyond it (away from the crest) by no
//!    more than [`END_FACE_LATERAL_JITTER_MM`]. Otherwise the step where the run stopped is
//!    reported (step 4), so a zig-zag at a flange tip names its line;
//! 4. consecutive points closer than [`DUPLICATE_TOLERANCE_MM`] in both coordinates are a
//!    [`ReadError::DuplicatePoint`]; any other step that does not increase the lateral
//!    coordinate is a [`ReadError::NonMonotonic`] naming the line. On request
//!    ([`StepBack::Drop`]) steps 3 and 4 are lenient: walking outwards from the crest on
//!    each side, a point that does not advance the lateral coordinate beyond every point kept
//!    before it (or repeats the last one) is dropped and its line recorded, as CONTACT's
//!    `delete_foldback` option does (E. Vollebregt, `eve70a/CONTACT`, matlab
//!    `modify_profile.m`), unless the rest of that side is an end face in the shadow of the
//!    last kept point, which is trimmed as in step 3. A file that steps 3 and 4 accept reads
//!    to the same points with nothing dropped;
//! 5. extents: the lateral extent must lie in [`LATERAL_EXTENT_MM`], the vertical extent below
//!    [`MAX_VERTICAL_EXTENT_MM`] ([`ReadError::ImplausibleExtent`]).

use super::StepBack;
use super::error::{Axis, Field, ReadError};
use super::fields::RawPoint;
use crate::profile::ProfileKind;

/// Fewest points a profile may have. A wheel tread with flange or a rail head with its gauge
/// corner cannot be described by fewer; the real files have hundreds. This is a sanity floor
/// that catches truncated files, not a quality criterion.
pub(crate) const MIN_POINTS: usize = 10;

/// Two consecutive points closer than this in both coordinates are the same point written
/// twice. Far below any real spacing (the closest pair in `MBench_UIC60_v3.prr` is 2e-6 mm
/// apart laterally and 5e-5 mm vertically) and far above rounding of values printed with
/// eight significant digits.
pub(crate) const DUPLICATE_TOLERANCE_MM: f64 = 1e-9;

/// Plausible lateral extent of a profile, mm. A rail head is about 72 mm wide, a wheel from
/// the flange back to the outer face about 140 mm; a profile narrower than 5 mm is almost
/// certainly in metres (0.14) and one wider than 1000 mm in micrometres. (Inches, 5.5 for a
/// wheel, slip through this check; the CSV header and SIMPACK unit factor catch those.)
pub(crate) const LATERAL_EXTENT_MM: (f64, f64) = (5.0, 1000.0);

/// Largest plausible vertical extent of a profile, mm: a rail section is 172 mm high, a
/// measured wheel a few tens of millimetres.
pub(crate) const MAX_VERTICAL_EXTENT_MM: f64 = 500.0;

/// Lateral scatter, mm, that MiniProf shows on a vertical face: up to 0.16 mm on the flange
/// backs of Car7216_0001r.whl and Car7358_0001r.whl. A dropped end-face point may stick out
/// this much beyond the last kept point (step 3 of the module docs).
pub(crate) const END_FACE_LATERAL_JITTER_MM: f64 = 0.2;

/// Points kept by [`finish`], and the lines of the points it dropped because they stepped
/// back ([`StepBack::Drop`] only; end faces are not counted).
pub(crate) type Finished = (Vec<[f64; 2]>, Vec<usize>);

/// Runs the checks listed in the module docs and returns the points sorted by strictly
/// increasing lateral coordinate.
///
/// `trim_faces` enables [`trim_end_faces`] (MiniProf measurements only); `step_back` says
/// whether a step back is an error or dropped ([`drop_step_backs`]).
///
/// # Errors
///
/// One [`ReadError`] variant per failed check, as listed in the module docs.
pub(crate) fn finish(
    mut points: Vec<RawPoint>,
    origin: &str,
    trim_faces: bool,
    step_back: StepBack,
) -> Result<Finished, ReadError> {
    if points.is_empty() {
        return Err(ReadError::NoPoints {
            origin: origin.to_owned(),
        });
    }
    check_count(points.len(), origin)?;
    // The parsers reject NaN and infinities in the file; this catches values that overflow
    // in a reader's conversions (offsets, unit factors).
    if let Some(p) = points
        .iter()
        .find(|p| !(p.lat.is_finite() && p.vert.is_finite()))
    {
        return Err(ReadError::NonFinite {
            origin: origin.to_owned(),
            line: p.line,
            field: Field::Column(if p.lat.is_finite() { 2 } else { 1 }),
            value: "(overflows after conversion to the side frame)".to_owned(),
        });
    }
    if let (Some(first), Some(last)) = (points.first(), points.last())
        && first.lat > last.lat
    {
        points.reverse();
    }
    let mut dropped = Vec::new();
    match step_back {
        StepBack::Refuse if trim_faces => points = trim_end_faces(points, origin)?,
        StepBack::Refuse => {}
        StepBack::Drop => (points, dropped) = drop_step_backs(points, trim_faces),
    }
    check_count(points.len(), origin)?;
    check_monotonic(&points, origin)?;
    check_extents(&points, origin)?;
    Ok((points.iter().map(|p| [p.lat, p.vert]).collect(), dropped))
}

/// Height of the highest point of a wheel profile above its field-side end beyond which
/// that point is a flange (a tread rises by a few millimetres at most; a flange by about 28).
pub(crate) const FLANGE_RISE_MM: f64 = 10.0;

/// `Ok` unless a wheel profile in the side frame has its flange on the field side: the
/// highest point at `s > 0`, more than [`FLANGE_RISE_MM`] above the profile's end at the
/// smallest `s` (so a tread-only section on the field side passes).
pub(super) fn check_flange_side(points: &[[f64; 2]], origin: &str) -> Result<(), ReadError> {
    let Some(&[_, first_height]) = points.first() else {
        return Ok(());
    };
    let top = points
        .iter()
        .copied()
        .max_by(|a, b| a[1].total_cmp(&b[1]))
        .unwrap_or([0.0, first_height]);
    if top[0] > 0.0 && top[1] - first_height > FLANGE_RISE_MM {
        return Err(ReadError::Mirrored {
            origin: origin.to_owned(),
            flange_tip_mm: top[0],
        });
    }
    Ok(())
}

/// `Ok` unless the file declares a kind (`declared`: the kind and the line that says so,
/// `None` for the extension) other than the `expected` one: a rail file read as a wheel.
pub(super) fn check_kind(
    declared: Option<(ProfileKind, Option<usize>)>,
    expected: ProfileKind,
    origin: &str,
) -> Result<(), ReadError> {
    match declared {
        Some((found, line)) if found != expected => Err(ReadError::WrongKind {
            origin: origin.to_owned(),
            line,
            expected,
            found,
        }),
        _ => Ok(()),
    }
}

fn check_count(found: usize, origin: &str) -> Result<(), ReadError> {
    if found < MIN_POINTS {
        return Err(ReadError::TooFewPoints {
            origin: origin.to_owned(),
            found,
            min: MIN_POINTS,
        });
    }
    Ok(())
}

fn check_monotonic(points: &[RawPoint], origin: &str) -> Result<(), ReadError> {
    for pair in points.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let same_place = (b.lat - a.lat).abs() <= DUPLICATE_TOLERANCE_MM
            && (b.vert - a.vert).abs() <= DUPLICATE_TOLERANCE_MM;
        if same_place {
            return Err(ReadError::DuplicatePoint {
                origin: origin.to_owned(),
                line: b.line.max(a.line),
                previous_line: b.line.min(a.line),
            });
        }
        if b.lat <= a.lat {
            return Err(ReadError::NonMonotonic {
                origin: origin.to_owned(),
                line: b.line,
                previous_line: a.line,
                lateral_mm: b.lat,
                previous_lateral_mm: a.lat,
            });
        }
    }
    Ok(())
}

fn check_extents(points: &[RawPoint], origin: &str) -> Result<(), ReadError> {
    let lateral = match (points.first(), points.last()) {
        (Some(a), Some(b)) => b.lat - a.lat,
        _ => 0.0,
    };
    if !(LATERAL_EXTENT_MM.0..=LATERAL_EXTENT_MM.1).contains(&lateral) {
        return Err(ReadError::ImplausibleExtent {
            origin: origin.to_owned(),
            axis: Axis::Lateral,
            extent_mm: lateral,
            range_mm: LATERAL_EXTENT_MM,
        });
    }
    let (lo, hi) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.vert), hi.max(p.vert))
        });
    let vertical = hi - lo;
    if vertical > MAX_VERTICAL_EXTENT_MM {
        return Err(ReadError::ImplausibleExtent {
            origin: origin.to_owned(),
            axis: Axis::Vertical,
            extent_mm: vertical,
            range_mm: (0.0, MAX_VERTICAL_EXTENT_MM),
        });
    }
    Ok(())
}

/// Drops the end faces of a measured profile: the flange-back and outer faces of a MiniProf
/// wheel, the side faces below a MiniProf rail head; reports any other step back.
///
/// These faces are vertical or undercut, so their lateral coordinate jitters or goes back,
/// and they cannot be part of a profile `F(s)` or `z(y)`. Starting from the crest (the
/// highest point: flange tip or rail crown), the run of strictly increasing lateral
/// coordinate is followed to each side. Where it stops early, the remaining end points are
/// dropped if they are an end face in the shadow of the last kept point (the anchor): every
/// one of them lower than the anchor and sticking out beyond it (away from the crest) by no
/// more than [`END_FACE_LATERAL_JITTER_MM`]. No body approaching from outside can touch such
/// points before the anchor. This covers the vertical flange-back faces of the measured
/// wheels, the outer face of Car7358_0001r.whl (leaning 1.1 mm inwards over 15.5 mm) and the
/// undercut gauge face and field-side lip of the worn avg_low2.ban.
///
/// # Errors
///
/// Where the remaining points are not an end face (a zig-zag on the tread or at the flange
/// tip), [`ReadError::DuplicatePoint`] or [`ReadError::NonMonotonic`] for the step where the
/// run from the crest stops: the line that breaks the profile.
pub(crate) fn trim_end_faces(
    points: Vec<RawPoint>,
    origin: &str,
) -> Result<Vec<RawPoint>, ReadError> {
    let n = points.len();
    let Some(crest) = (0..n).max_by(|&i, &j| points[i].vert.total_cmp(&points[j].vert)) else {
        return Ok(points);
    };
    let mut last = crest;
    while last + 1 < n && points[last + 1].lat > points[last].lat {
        last += 1;
    }
    let mut first = crest;
    while first > 0 && points[first - 1].lat < points[first].lat {
        first -= 1;
    }
    // `outward` is -1 for the tail before the run (smaller lateral), +1 after it.
    let is_face = |tail: &[RawPoint], anchor: RawPoint, outward: f64| {
        tail.iter().all(|p| {
            p.vert < anchor.vert && outward * (p.lat - anchor.lat) <= END_FACE_LATERAL_JITTER_MM
        })
    };
    if first > 0 && !is_face(&points[..first], points[first], -1.0) {
        // In increasing lateral order the step is points[first - 1] -> points[first].
        check_monotonic(&points[first - 1..=first], origin)?;
    }
    if last + 1 < n && !is_face(&points[last + 1..], points[last], 1.0) {
        check_monotonic(&points[last..=last + 1], origin)?;
    }
    Ok(points[first..=last].to_vec())
}

/// Drops the points that step back ([`StepBack::Drop`]): the lenient counterpart of
/// [`trim_end_faces`] and step 4, for measured profiles that zig-zag (both 2020 wheels of the
/// test data at the flange tip, avg_HR.BAN at the gauge corner). Returns the kept points and
/// the lines of the dropped ones, in the order met.
///
/// As CONTACT's `delete_foldback` option (E. Vollebregt, `eve70a/CONTACT`, matlab
/// `modify_profile.m`) does, the walk starts at the crest (the highest point: flange tip or
/// rail crown) and goes outwards on each side; a point is kept when it advances the lateral
/// coordinate beyond every point kept before it on that side (and is not the same point,
/// [`DUPLICATE_TOLERANCE_MM`]), and dropped otherwise. With `trim_faces` (MiniProf), where a
/// point does not advance, the rest of that side is first tested as an end face in the
/// shadow of the last kept point, exactly as [`trim_end_faces`] does, and removed (not
/// counted as dropped) if it is one. So every file the strict reader accepts reads to the
/// same points, with nothing dropped.
pub(crate) fn drop_step_backs(
    points: Vec<RawPoint>,
    trim_faces: bool,
) -> (Vec<RawPoint>, Vec<usize>) {
    let n = points.len();
    let Some(crest) = (0..n).max_by(|&i, &j| points[i].vert.total_cmp(&points[j].vert)) else {
        return (points, Vec::new());
    };
    // For each side, extremes of the points from index i to that side's end, so that the
    // end-face test is O(1): (highest vertical, furthest outward lateral).
    let mut after = vec![(f64::NEG_INFINITY, f64::NEG_INFINITY); n + 1];
    for i in (0..n).rev() {
        after[i] = (
            after[i + 1].0.max(points[i].vert),
            after[i + 1].1.max(points[i].lat),
        );
    }
    let mut before = vec![(f64::NEG_INFINITY, f64::INFINITY); n];
    for i in 0..n {
        let prev = if i > 0 { before[i - 1] } else { before[0] };
        before[i] = (prev.0.max(points[i].vert), prev.1.min(points[i].lat));
    }
    let advances = |anchor: RawPoint, p: RawPoint, outward: f64| {
        let same_place = (p.lat - anchor.lat).abs() <= DUPLICATE_TOLERANCE_MM
            && (p.vert - anchor.vert).abs() <= DUPLICATE_TOLERANCE_MM;
        outward * (p.lat - anchor.lat) > 0.0 && !same_place
    };
    let mut dropped = Vec::new();
    // Field/gauge side after the crest (increasing lateral).
    let mut tail = Vec::new();
    let mut anchor = points[crest];
    for i in crest + 1..n {
        let p = points[i];
        if advances(anchor, p, 1.0) {
            tail.push(p);
            anchor = p;
        } else if trim_faces
            && after[i].0 < anchor.vert
            && after[i].1 - anchor.lat <= END_FACE_LATERAL_JITTER_MM
        {
            break;
        } else {
            dropped.push(p.line);
        }
    }
    // The other side, walked from the crest towards index 0 (decreasing lateral).
    let mut head = Vec::new();
    anchor = points[crest];
    for i in (0..crest).rev() {
        let p = points[i];
        if advances(anchor, p, -1.0) {
            head.push(p);
            anchor = p;
        } else if trim_faces
            && before[i].0 < anchor.vert
            && anchor.lat - before[i].1 <= END_FACE_LATERAL_JITTER_MM
        {
            break;
        } else {
            dropped.push(p.line);
        }
    }
    head.reverse();
    head.push(points[crest]);
    head.extend(tail);
    (head, dropped)
}

/// Decides whether a MiniProf rail file has its vertical axis up (MiniProf's own convention,
/// avg_HR.BAN, avg_low2.ban) or down (MBench_UIC60_v3.ban, converted from SIMPACK).
///
/// A rail head's crest is inside the measured curve and the ends run down the side faces, so
/// with the axis up the minimum lies near an end and the maximum inside; with the axis down
/// the other way round. "Near an end" is the first or last 10 % of the points (as CONTACT's
/// `check_z_pos_down` does). When neither pattern holds, MiniProf's convention (up) is taken.
pub(crate) fn rail_vertical_is_up(verticals: &[f64]) -> bool {
    let n = verticals.len();
    if n < 2 {
        return true;
    }
    let arg = |better: fn(f64, f64) -> bool| {
        (1..n).fold(0, |best, i| {
            if better(verticals[i], verticals[best]) {
                i
            } else {
                best
            }
        })
    };
    let i_max = arg(|a, b| a > b);
    let i_min = arg(|a, b| a < b);
    let near_end = |i: usize| i * 10 < n || i * 10 >= 9 * n;
    !near_end(i_max) || near_end(i_min)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(xy: &[(f64, f64)]) -> Vec<RawPoint> {
        xy.iter()
            .enumerate()
            .map(|(i, &(lat, vert))| RawPoint {
                lat,
                vert,
                line: i + 1,
            })
            .collect()
    }

    fn arc(n: usize) -> Vec<(f64, f64)> {
        (0..n)
            .map(|i| {
                let y = -20.0 + 40.0 * i as f64 / (n - 1) as f64;
                (y, -y * y / 600.0)
            })
            .collect()
    }

    #[test]
    fn reversed_input_is_reordered() {
        let mut xy = arc(20);
        xy.reverse();
        let out = finish(pts(&xy), "t", false, StepBack::Refuse).unwrap();
        assert!(out.0.windows(2).all(|w| w[1][0] > w[0][0]));
    }

    #[test]
    fn zig_zag_names_its_line() {
        let mut xy = arc(20);
        xy[7].0 = xy[5].0;
        let err = finish(pts(&xy), "t", false, StepBack::Refuse).unwrap_err();
        assert!(
            matches!(
                err,
                ReadError::NonMonotonic {
                    line: 8,
                    previous_line: 7,
                    ..
                }
            ),
            "{err:?}"
        );
    }

    #[test]
    fn end_faces_are_dropped_but_zig_zags_reported() {
        let mut xy = arc(20);
        // A vertical face with 0.05 mm lateral scatter hanging off the last point.
        let (y_end, z_end) = xy[19];
        for k in 1..6 {
            let scatter = if k % 2 == 0 { 0.05 } else { -0.05 };
            xy.push((y_end + scatter, z_end - k as f64));
        }
        assert_eq!(trim_end_faces(pts(&xy), "t").unwrap().len(), 20);
        // An undercut (going back under the last point) is in its shadow: dropped too.
        let mut undercut = arc(20);
        for k in 1..6 {
            undercut.push((y_end - 0.6 * k as f64, z_end - k as f64));
        }
        assert_eq!(trim_end_faces(pts(&undercut), "t").unwrap().len(), 20);
        // A step back followed by points sticking out further is a zig-zag: an error there.
        let mut zig = arc(20);
        zig.push((y_end - 0.1, z_end - 0.1));
        zig.push((y_end + 1.0, z_end - 0.5));
        assert!(matches!(
            finish(pts(&zig), "t", true, StepBack::Refuse),
            Err(ReadError::NonMonotonic {
                line: 21,
                previous_line: 20,
                ..
            })
        ));
    }

    #[test]
    fn dropping_step_backs_keeps_what_strict_accepts_and_drops_zig_zags() {
        // An end face in the shadow is trimmed the same way, nothing counted as dropped.
        let mut faced = arc(20);
        let (y_end, z_end) = faced[19];
        for k in 1..6 {
            faced.push((
                y_end + if k % 2 == 0 { 0.05 } else { -0.05 },
                z_end - k as f64,
            ));
        }
        let strict = finish(pts(&faced), "t", true, StepBack::Refuse).unwrap();
        let lenient = finish(pts(&faced), "t", true, StepBack::Drop).unwrap();
        assert_eq!(strict.0, lenient.0);
        assert!(lenient.1.is_empty());
        // A zig-zag on either side of the crest: the points that do not advance are dropped
        // and named by line; the duplicate too.
        let mut zig = arc(20);
        zig[15].0 = zig[13].0 - 0.01; // after the crest (index 10): steps back
        zig[3].0 = zig[5].0 + 0.01; // before it, walked towards index 0: steps back
        zig.insert(8, zig[7]); // a duplicate (lines 8, 9); lines shift by one after it
        assert!(finish(pts(&zig), "t", false, StepBack::Refuse).is_err());
        let (points, dropped) = finish(pts(&zig), "t", false, StepBack::Drop).unwrap();
        assert_eq!(points.len(), 18);
        assert!(points.windows(2).all(|w| w[1][0] > w[0][0]));
        let mut lines = dropped.clone();
        lines.sort_unstable();
        // Before the crest the walk meets the second copy (line 9) first and drops line 8.
        assert_eq!(lines, vec![4, 8, 17], "{dropped:?}");
    }

    #[test]
    fn rail_vertical_direction() {
        let up: Vec<f64> = arc(50).iter().map(|p| p.1).collect();
        let mut with_face = up.clone();
        with_face.extend([-5.0, -10.0, -20.0]);
        assert!(rail_vertical_is_up(&with_face));
        let down: Vec<f64> = with_face.iter().map(|z| -z).collect();
        assert!(!rail_vertical_is_up(&down));
    }
}
