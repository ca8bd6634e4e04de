//! The flange dimensions Sh, Sd and qR of a wheel profile, as the wheelset maintenance rules
//! define them.
//!
//! # Definitions
//!
//! EN 15313 (in-service wheelset maintenance) and UIC 510-2 measure a wheel's flange from
//! two references: the **inner face** of the wheel and the **taping line** (the measuring
//! circle), 70 mm from the inner face (`TAPING_LINE_FROM_INNER_FACE_MM`; `s = 0` of the
//! wheel side frame). The TSI for freight wagons draws the same three dimensions (Regulation
//! (EU) No 321/2013, 4.2.3.6.2, Figure 1, with their limits in Table 3; the German EBO,
//! Anlage 6, and the Austrian EisbBBV, Anlage 2, tabulate the same symbols):
//!
//! * **Sh, flange height**: the height of the flange tip (the highest point of the flange)
//!   above the profile's point on the taping line, `F(tip) - F(0)`;
//! * **Sd, flange thickness**: the lateral distance from the inner face to the flange's
//!   running flank, measured at the height `SD_HEIGHT_MM` (10 mm) above the taping-line
//!   point: `s_Sd + 70` where `F(s_Sd) = F(0) + 10` on the flank;
//! * **qR, flange slope dimension**: the lateral distance from the Sd point to the point of
//!   the same flank `QR_BELOW_TIP_MM` (2 mm) below the flange tip. A steep, sharp flange
//!   (small qR) can climb the tip of a switch blade.
//!
//! Both heights are taken relative to the profile's own taping-line point `F(0)`: a measured
//! wheel keeps its instrument's vertical origin (`F(0)` = 0.09 mm on Car7216), which drops
//! out of the differences.
//!
//! # The new S1002
//!
//! From the analytic definition (`profile::s1002`): Sh = 28.000 mm (the tip F(-55)
//! = 28 of arc R12 over F(0) = 0), Sd = 32.500 mm (F(-37.5) = 10 on arc R13) and qR =
//! 10.794 mm (F = 26 at s = -48.294 on arc R20), which EN 13715 rounds to 28, 32.5 and
//! 10.8 mm (unit tests below).
//!
//! # What is measured
//!
//! A wheel shop measures the wheel, not a filtered copy of it. A profile read from points
//! ([`Profile::points`]) is measured on those points joined by straight lines, whatever
//! `smoothing_wavelength_mm` the scene sets for the contact: the spline that filter gives
//! rounds the tip and the knees of the flank and moves Sd (by 0.11 mm on Car7216 with a 4 mm
//! filter), which next to a 33 mm limit decides a verdict. Straight lines between points 0.25 to 0.4
//! mm apart are within `h^2/(8R)` = 2e-3 mm of an R12 tip and closer still on the flanks, far
//! inside a gauge's 0.01 mm. A built-in profile is measured on its analytic definition.
//!
//! On the points: `F(0)` is the line between the two points around the taping line; the
//! tip is the highest point on the flange side (`s < 0`; the first one of equal heights);
//! each flank point is where the line first comes down through its height, walking from the
//! tip towards the field side.
//!
//! On a definition: the tip is the largest sample of the flange side (`s` from the domain's
//! start to the taping line) every 0.05 mm (`SCAN_STEP_MM`), refined by bisection on the
//! slope's sign change around it; each flank point is the first sample below its height
//! walking from the tip towards the field side, refined by bisection to 1e-9 mm
//! (`BISECTION_TOLERANCE_MM`).

use crate::profile::{Profile, ProfileKind};
use crate::track::TAPING_LINE_FROM_INNER_FACE_MM;
use std::fmt;

/// Height above the taping-line point at which the flange thickness Sd is measured (mm).
pub(crate) const SD_HEIGHT_MM: f64 = 10.0;
/// Depth below the flange tip of the second point of the qR dimension (mm).
pub(crate) const QR_BELOW_TIP_MM: f64 = 2.0;
/// Sampling step of the searches for the tip and the flank points (mm): finer than any
/// feature of a flange (the S1002 tip radius is 12 mm), 1400 samples over a 70 mm flange.
pub(crate) const SCAN_STEP_MM: f64 = 0.05;
/// Where the bisections stop (mm): far below any measurement's resolution (about 1e-3 mm).
pub(crate) const BISECTION_TOLERANCE_MM: f64 = 1e-9;

/// The flange dimensions of a wheel profile, with the points they were measured at.
///
/// # Frame and units
/// Millimetres, in the wheel's side frame: `s` from the taping line, positive towards the
/// field side (the flange at `s < 0`, the inner face at `s = -70`); `F` the radius increase,
/// positive towards the flange tip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlangeDimensions {
    /// Sh, flange height: `F(tip) - F(0)` (mm).
    pub sh_mm: f64,
    /// Sd, flange thickness: from the inner face to the flank at `F(0) + 10 mm` (mm).
    pub sd_mm: f64,
    /// qR: from the Sd point to the flank 2 mm below the tip (mm).
    pub qr_mm: f64,
    /// `F(0)`, the profile's height on the taping line (mm).
    pub taping_line_height_mm: f64,
    /// `s` of the flange tip (mm).
    pub tip_s_mm: f64,
    /// `s` of the Sd point (mm).
    pub sd_point_s_mm: f64,
    /// `s` of the flank point 2 mm below the tip (mm).
    pub qr_point_s_mm: f64,
}

/// Why a profile's flange dimensions cannot be measured.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum DimensionError {
    /// The profile is a rail.
    NotAWheel {
        /// The profile's name.
        profile: String,
    },
    /// The profile does not reach the taping line (`s = 0`) or has no flange side before it.
    TapingLineOutside {
        /// The profile's lateral extent `(s_min, s_max)` (mm).
        domain: (f64, f64),
    },
    /// The flange tip is not 10 mm (`SD_HEIGHT_MM`) above the taping-line point: no Sd point.
    FlangeTooLow {
        /// The height of the highest point of the flange side above `F(0)` (mm).
        sh_mm: f64,
    },
}

impl fmt::Display for DimensionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DimensionError::NotAWheel { profile } => {
                write!(f, "{profile} is a rail profile, not a wheel")
            }
            DimensionError::TapingLineOutside { domain } => write!(
                f,
                "the profile (s from {} to {} mm) does not span the flange and the taping line s = 0",
                domain.0, domain.1
            ),
            DimensionError::FlangeTooLow { sh_mm } => write!(
                f,
                "the flange rises only {sh_mm:.3} mm above the taping line, less than the {SD_HEIGHT_MM} mm where Sd is measured"
            ),
        }
    }
}

impl std::error::Error for DimensionError {}

/// The flange dimensions Sh, Sd and qR of `wheel` (see the [module docs](self) for the
/// definitions and their sources).
///
/// # Units
/// Millimetres.
///
/// # Errors
/// [`DimensionError`] when `wheel` is a rail, does not span the flange and the taping line,
/// or its flange is lower than the 10 mm where Sd is measured.
///
/// # Example
/// ```
/// use wheelrail::maintenance::flange_dimensions;
/// use wheelrail::profile::Profile;
/// let d = flange_dimensions(&Profile::s1002()).unwrap();
/// assert!((d.sh_mm - 28.0).abs() < 1e-9);
/// assert!((d.sd_mm - 32.5).abs() < 1e-4);
/// assert!((d.qr_mm - 10.8).abs() < 0.01);
/// ```
pub fn flange_dimensions(wheel: &Profile) -> Result<FlangeDimensions, DimensionError> {
    if wheel.kind() != ProfileKind::Wheel {
        return Err(DimensionError::NotAWheel {
            profile: wheel.name().to_string(),
        });
    }
    match wheel.points() {
        Some(points) => on_points(points),
        None => on_definition(wheel),
    }
}

/// The dimensions of the polyline through `points` (`[s, F]`, strictly increasing `s`, at
/// least two: a [`PointProfile`](crate::profile::read::PointProfile)'s invariants).
fn on_points(points: &[[f64; 2]]) -> Result<FlangeDimensions, DimensionError> {
    let domain = (points[0][0], points[points.len() - 1][0]);
    if !(domain.0 < 0.0 && domain.1 >= 0.0) {
        return Err(DimensionError::TapingLineOutside { domain });
    }
    // The first point at or beyond the taping line: 1 <= k < len by the test above.
    let k = points.partition_point(|p| p[0] < 0.0);
    let f0 = if points[k][0] == 0.0 {
        points[k][1]
    } else {
        interpolate(points[k - 1], points[k], |p| p[0], 0.0)[1]
    };
    let tip = (1..k).fold(0, |best, i| {
        if points[i][1] > points[best][1] {
            i
        } else {
            best
        }
    });
    let [tip_s_mm, tip_f] = points[tip];
    if tip_f - f0 < SD_HEIGHT_MM {
        // The line's highest point on the flange side is the taping-line point itself when
        // no point before it is higher: the flange rises 0 mm then.
        return Err(DimensionError::FlangeTooLow {
            sh_mm: (tip_f - f0).max(0.0),
        });
    }
    // Both levels lie above F(0) and at most at the tip: the line comes down through each
    // between the tip and point k (at the latest on the segment that holds s = 0).
    let descent = |level: f64| {
        let below = (tip + 1..=k).find(|&i| points[i][1] < level).unwrap_or(k);
        interpolate(points[below - 1], points[below], |p| p[1], level)[0]
    };
    let sd_point_s_mm = descent(f0 + SD_HEIGHT_MM);
    let qr_point_s_mm = descent(tip_f - QR_BELOW_TIP_MM);
    Ok(FlangeDimensions {
        sh_mm: tip_f - f0,
        sd_mm: sd_point_s_mm + TAPING_LINE_FROM_INNER_FACE_MM,
        qr_mm: sd_point_s_mm - qr_point_s_mm,
        taping_line_height_mm: f0,
        tip_s_mm,
        sd_point_s_mm,
        qr_point_s_mm,
    })
}

/// The point of the segment from `a` to `b` where `coordinate` takes `value` (which lies
/// between its values at `a` and `b`, and they differ).
fn interpolate(a: [f64; 2], b: [f64; 2], coordinate: fn(&[f64; 2]) -> f64, value: f64) -> [f64; 2] {
    let t = (value - coordinate(&a)) / (coordinate(&b) - coordinate(&a));
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

/// The dimensions of a built-in profile, from its analytic definition.
fn on_definition(wheel: &Profile) -> Result<FlangeDimensions, DimensionError> {
    let domain = wheel.domain();
    if !(domain.0 < 0.0 && domain.1 >= 0.0) {
        return Err(DimensionError::TapingLineOutside { domain });
    }
    let height = |s: f64| wheel.eval(s)[0];
    let f0 = height(0.0);
    let tip_s_mm = flange_tip(wheel, domain.0);
    let tip = height(tip_s_mm);
    if tip - f0 < SD_HEIGHT_MM {
        return Err(DimensionError::FlangeTooLow { sh_mm: tip - f0 });
    }
    // Both flank points lie between the tip and the taping line: F(tip) is above both
    // levels and F(0) below them.
    let sd_point_s_mm = first_descent(wheel, tip_s_mm, f0 + SD_HEIGHT_MM);
    let qr_point_s_mm = first_descent(wheel, tip_s_mm, tip - QR_BELOW_TIP_MM);
    Ok(FlangeDimensions {
        sh_mm: tip - f0,
        sd_mm: sd_point_s_mm + TAPING_LINE_FROM_INNER_FACE_MM,
        qr_mm: sd_point_s_mm - qr_point_s_mm,
        taping_line_height_mm: f0,
        tip_s_mm,
        sd_point_s_mm,
        qr_point_s_mm,
    })
}

/// `s` of the highest point of `wheel` between `s_min` and the taping line: the largest
/// sample, refined by bisection on the sign of the slope where it changes around it.
fn flange_tip(wheel: &Profile, s_min: f64) -> f64 {
    let n = (-s_min / SCAN_STEP_MM).ceil().max(1.0) as usize;
    let s_at = |i: usize| s_min + (-s_min) * i as f64 / n as f64;
    // The samples increase: a scan along the profile, to the bit as `eval` (with the scan of
    // `first_descent`, the dimensions of the 1001-point R-UIC519A wheel take 0.21 M
    // instructions instead of 0.32 M).
    let mut scan = wheel.scan();
    let best = (0..=n)
        .map(|i| (i, scan.eval_slope(s_at(i))[0]))
        .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a })
        .0;
    let (lo, hi) = (s_at(best.saturating_sub(1)), s_at((best + 1).min(n)));
    let slope = |s: f64| wheel.eval(s)[1];
    // Rising before the tip, falling after it; at an end of the bracket the slope may not
    // change sign (a tip on the domain's end, or a flat top): keep the best sample then.
    if !(slope(lo) > 0.0 && slope(hi) < 0.0) {
        return s_at(best);
    }
    let s = bisect(lo, hi, |s| slope(s) > 0.0);
    // The bisection follows the slope; keep the sample if rounding left it lower.
    if wheel.eval(s)[0] >= wheel.eval(s_at(best))[0] {
        s
    } else {
        s_at(best)
    }
}

/// The first `s` after `from` (towards the field side) where `wheel` comes down through
/// `level`: the first sample below it every [`SCAN_STEP_MM`], then bisection. `level` lies
/// below `F(from)` and above `F(0)`, so a crossing exists before the taping line.
fn first_descent(wheel: &Profile, from: f64, level: f64) -> f64 {
    let above = |s: f64| wheel.eval(s)[0] >= level;
    let n = (-from / SCAN_STEP_MM).ceil().max(1.0) as usize;
    let s_at = |i: usize| from + (-from) * i as f64 / n as f64;
    // The samples increase: a scan along the profile (see `flange_tip`).
    let mut scan = wheel.scan();
    let i = (1..=n)
        .find(|&i| {
            // Not `above`: below the level, or NaN.
            let v = scan.eval_slope(s_at(i))[0];
            v < level || v.is_nan()
        })
        .unwrap_or(n);
    bisect(s_at(i - 1), s_at(i), above)
}

/// The point where `inside` changes from true (at `lo`) to false (at `hi`), to
/// [`BISECTION_TOLERANCE_MM`].
fn bisect(mut lo: f64, mut hi: f64, inside: impl Fn(f64) -> bool) -> f64 {
    while hi - lo > BISECTION_TOLERANCE_MM {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if inside(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile::read::PointProfile;

    /// The new S1002 from its analytic definition: Sh = 28 exactly (the R12 arc's apex), Sd
    /// and qR from the closed forms of the arcs they fall on.
    #[test]
    fn s1002_gives_the_standard_dimensions() {
        let d = flange_dimensions(&Profile::s1002()).unwrap();
        // Tip: the apex of arc G (R12, centre (-55, 16)), F = 28 exactly. Measured: tip
        // 3.7e-10 mm, the Sd and qR points 2.7e-10 and 1.6e-10 mm, Sd 3.3e-8 mm off 32.5,
        // qR 1.8e-4 mm off 10.794; bounds about twice these.
        assert!((d.tip_s_mm + 55.0).abs() < 1e-9, "{d:?}");
        assert!((d.sh_mm - 28.0).abs() < 1e-12, "{d:?}");
        // Sd: arc D, F = AD - sqrt(BD^2 - (s + CD)^2) = 10.
        let (ad, bd, cd) = (16.446_f64, 13.0_f64, 26.210_665_f64);
        let s_sd = -cd - (bd * bd - (ad - 10.0).powi(2)).sqrt();
        assert!((d.sd_point_s_mm - s_sd).abs() < 6e-10, "{d:?} {s_sd}");
        // qR: arc F, F = AF + sqrt(BF^2 - (s + CF)^2) = 26, on its falling side.
        let (af, bf, cf) = (8.834_924_130_f64, 20.0_f64, 58.558_326_413_f64);
        let s_qr = -cf + (bf * bf - (26.0 - af).powi(2)).sqrt();
        assert!((d.qr_point_s_mm - s_qr).abs() < 4e-10, "{d:?} {s_qr}");
        // EN 13715's values, to the 0.01 mm the standard's one decimal allows.
        assert!((d.sd_mm - 32.5).abs() < 7e-8, "{d:?}");
        assert!((d.qr_mm - 10.8).abs() < 0.01, "{d:?}");
        assert!((d.qr_mm - 10.794).abs() < 4e-4, "{d:?}");
    }

    /// A profile read from points, fitted with the smoothing filter `wavelength_mm`.
    fn fitted(points: Vec<[f64; 2]>, wavelength_mm: f64) -> Profile {
        let p = PointProfile::from_points(ProfileKind::Wheel, "w", points).unwrap();
        Profile::from_points(p, wavelength_mm).unwrap()
    }

    /// A polyline whose dimensions follow by hand: F(0) = -1 on the line from (-30, 0.5) to
    /// (10, -1.5); the tip (-60, 30), Sh = 31; F = 9 first on the segment from (-40, 10.5)
    /// to (-38, 8.5) at s = -38.5 (the line rises back to 9.5 after it), Sd = 31.5; F = 28
    /// on the segment from the tip to (-40, 10.5) at s = -60 + 2 * 20 / 19.5. The same
    /// numbers to rounding with any smoothing: the points are measured, not the spline.
    #[test]
    fn a_polyline_gives_its_dimensions_by_hand_whatever_the_smoothing() {
        let points = vec![
            [-70.0, 0.0],
            [-60.0, 30.0],
            [-40.0, 10.5],
            [-38.0, 8.5],
            [-36.0, 9.5],
            [-30.0, 0.5],
            [10.0, -1.5],
            [20.0, -2.0],
            [30.0, -2.5],
            [40.0, -3.0],
            [50.0, -3.5],
        ];
        let s_qr = -60.0 + 2.0 * 20.0 / 19.5;
        for wavelength_mm in [0.0, 4.0, 20.0] {
            let d = flange_dimensions(&fitted(points.clone(), wavelength_mm)).unwrap();
            let want = [
                (d.taping_line_height_mm, -1.0),
                (d.tip_s_mm, -60.0),
                (d.sh_mm, 31.0),
                (d.sd_point_s_mm, -38.5),
                (d.sd_mm, 31.5),
                (d.qr_point_s_mm, s_qr),
                (d.qr_mm, -38.5 - s_qr),
            ];
            for (got, want) in want {
                // Rounding of a few operations on numbers below 100.
                assert!((got - want).abs() < 1e-12, "{wavelength_mm}: {d:?}");
            }
        }
    }

    /// S1002 sampled every 0.5 mm (`Profile::sample`: from s = -70, joints added) and lifted
    /// by 0.7 mm (an instrument's vertical origin, which drops out), with no filter and with
    /// the 4 and 20 mm filters a scene may set for the contact: the same numbers for every
    /// filter, and EN 13715's Sh 28, Sd 32.500 and qR 10.794 within the 0.01 mm a gauge
    /// reads. A sample falls on the tip's apex (s = -55) and one on the Sd point (s = -37.5,
    /// where the R13 arc gives F = 10 to 1e-5 mm); the qR point, F = 26 on the R20 arc, lies
    /// between samples, where the chord cuts under the arc and moves it by 3.8e-3 mm.
    #[test]
    fn a_sampled_s1002_gives_the_standard_dimensions_whatever_the_smoothing() {
        let points: Vec<[f64; 2]> = Profile::s1002()
            .sample(0.5)
            .iter()
            .map(|r| [r[0], r[1] + 0.7])
            .collect();
        let unfiltered = flange_dimensions(&fitted(points.clone(), 0.0)).unwrap();
        let d = unfiltered;
        assert!((d.taping_line_height_mm - 0.7).abs() < 1e-12, "{d:?}");
        assert!((d.sh_mm - 28.0).abs() < 1e-9, "{d:?}");
        // Measured 3.6e-8 mm off 32.5.
        assert!((d.sd_mm - 32.5).abs() < 8e-8, "{d:?}");
        // About twice the chord's 3.8e-3 mm; inside the 0.01 mm required.
        assert!((d.qr_mm - 10.794).abs() < 8e-3, "{d:?}");
        for wavelength_mm in [4.0, 20.0] {
            let d = flange_dimensions(&fitted(points.clone(), wavelength_mm)).unwrap();
            assert_eq!(d, unfiltered, "{wavelength_mm} mm filter");
        }
    }

    #[test]
    fn rails_and_short_or_flat_profiles_are_refused() {
        assert!(matches!(
            flange_dimensions(&Profile::uic60e1()),
            Err(DimensionError::NotAWheel { .. })
        ));
        let fitted = |points| fitted(points, 0.0);
        let tread_only = fitted(
            (0..=50)
                .map(|i| [f64::from(i), -0.05 * f64::from(i)])
                .collect(),
        );
        assert!(matches!(
            flange_dimensions(&tread_only),
            Err(DimensionError::TapingLineOutside { .. })
        ));
        // A flange only 8 mm high.
        let low = fitted(
            (0..=100)
                .map(|i| {
                    let s = -50.0 + f64::from(i);
                    [s, 8.0 * (-(s + 30.0).powi(2) / 50.0).exp()]
                })
                .collect(),
        );
        let e = flange_dimensions(&low).unwrap_err();
        assert!(matches!(e, DimensionError::FlangeTooLow { .. }), "{e}");
        assert!(e.to_string().contains("10 mm"), "{e}");
    }
}
