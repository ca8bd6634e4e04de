//! Rail wear: the vertical wear on the rail's centre line and the gauge-face wear at the
//! gauge-point depth below the top, of a measured rail against its nominal profile.
//!
//! # Definitions
//!
//! Both profiles are turned upright (the scene's `rail.profile_inclination` taken out) and
//! compared **in the frame their coordinates are given in**: a measured rail must be
//! referenced to the rail as its nominal profile is (a MiniProf or trolley measurement takes
//! its reference on the unworn rail foot or web; the built-in 60E1 has its origin on the
//! top of the rail's vertical axis). The worn head itself cannot give that reference: no
//! part of it is sure to be unworn, so the profiles are not fitted to each other.
//!
//! * the **top** is the nominal profile's highest point (upright);
//! * the **centre line** is the vertical halfway between the nominal head's two faces at
//!   the gauge-point depth below the top (the rail's vertical axis for a symmetric head:
//!   `y = 0` for the built-in 60E1);
//! * **vertical wear** `= z_nominal - z_measured` on the centre line, positive where
//!   material is gone;
//! * **gauge-face wear** `= y_measured - y_nominal` of the gauge faces at the gauge-point
//!   depth below the nominal top (the fixed point where the track gauge is measured, 14 mm
//!   by EN 13848-1; the scene's `track.gauge_point_depth_mm`), positive where the face has
//!   moved towards the field side (material gone). The gauge side is `y < 0` of the rail
//!   side frame.
//!
//! # Numerics
//!
//! Each crossing is bracketed by samples of the profile every 0.05 mm (`SCAN_STEP_MM`) and refined
//! by bisection on its profile coordinate to 1e-9 mm (`BISECTION_TOLERANCE_MM`); the upright point
//! of a profile coordinate is the exact rotation of the profile's point.

use crate::profile::{Profile, ProfileKind};
use crate::track::Inclination;
use nalgebra::{Point2, UnitComplex};
use std::fmt;

pub(crate) use super::dimensions::BISECTION_TOLERANCE_MM;

/// Sampling step of the searches along a rail profile (mm).
pub(crate) const SCAN_STEP_MM: f64 = 0.05;

/// The wear of a measured rail against its nominal profile.
///
/// # Frame and units
/// Millimetres, in the nominal rail's upright side frame: `y` lateral, positive towards the
/// field side (gauge side at `y < 0`), `z` height, up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RailWear {
    /// Vertical wear on the centre line, `z_nominal - z_measured` (mm, positive: worn).
    pub vertical_mm: f64,
    /// Gauge-face wear at the gauge-point depth below the nominal top, `y_measured -
    /// y_nominal` (mm, positive: worn).
    pub gauge_face_mm: f64,
    /// `y` of the centre line (mm).
    pub centre_line_y_mm: f64,
    /// Height of the nominal top (mm).
    pub top_z_mm: f64,
    /// Height at which the gauge faces are compared: the top less the gauge-point depth (mm).
    pub gauge_face_z_mm: f64,
}

/// Why a rail's wear cannot be measured.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum WearError {
    /// A profile is a wheel.
    NotARail {
        /// The profile's name.
        profile: String,
    },
    /// The nominal profile does not reach the gauge-point depth on both sides of its top.
    NominalTooShort {
        /// The nominal profile's name.
        profile: String,
    },
    /// The measured profile does not reach the centre line, or its gauge face does not
    /// reach the gauge-point depth below the nominal top.
    MeasuredTooShort {
        /// What is missing: `centre line` or `gauge face`.
        at: &'static str,
    },
    /// The nominal rail could not be read (the reader's message).
    NominalUnreadable {
        /// The reader's message, naming the file and line.
        message: String,
    },
}

impl fmt::Display for WearError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WearError::NotARail { profile } => {
                write!(f, "{profile} is a wheel profile, not a rail")
            }
            WearError::NominalTooShort { profile } => write!(
                f,
                "the nominal rail {profile} does not reach the gauge-point depth on both sides of its top"
            ),
            WearError::MeasuredTooShort { at: "centre line" } => {
                f.write_str("the measured rail does not reach the nominal rail's centre line")
            }
            WearError::NominalUnreadable { message } => {
                write!(f, "the nominal rail cannot be read: {message}")
            }
            WearError::MeasuredTooShort { at } => write!(
                f,
                "the measured rail's {at} does not reach the gauge-point depth below the nominal top"
            ),
        }
    }
}

impl std::error::Error for WearError {}

/// A rail profile turned upright: its points `(y, z)` by profile coordinate `u`.
struct Upright<'a> {
    profile: &'a Profile,
    rotation: UnitComplex<f64>,
}

impl Upright<'_> {
    fn point(&self, u: f64) -> [f64; 2] {
        let p = self.rotation * Point2::new(u, self.profile.eval(u)[0]);
        [p.x, p.y]
    }

    /// The samples' coordinates from `from` towards `to` every [`SCAN_STEP_MM`] (both
    /// included).
    fn walk(from: f64, to: f64) -> impl Iterator<Item = f64> {
        let n = ((to - from).abs() / SCAN_STEP_MM).ceil().max(1.0) as usize;
        (0..=n).map(move |i| from + (to - from) * i as f64 / n as f64)
    }

    /// The first `u` walking from `from` to `to` where `inside(point)` turns false, refined
    /// by bisection; `None` if it stays true.
    fn first_exit(&self, from: f64, to: f64, inside: impl Fn([f64; 2]) -> bool) -> Option<f64> {
        let mut last = from;
        for u in Upright::walk(from, to) {
            if !inside(self.point(u)) {
                let (mut a, mut b) = (last, u);
                while (b - a).abs() > BISECTION_TOLERANCE_MM {
                    let mid = 0.5 * (a + b);
                    if inside(self.point(mid)) {
                        a = mid;
                    } else {
                        b = mid;
                    }
                }
                return Some(0.5 * (a + b));
            }
            last = u;
        }
        None
    }

    /// `u` of the highest point: the largest sample, refined by golden-section search
    /// between its neighbours.
    fn top(&self) -> f64 {
        let (lo, hi) = self.profile.domain();
        let us: Vec<f64> = Upright::walk(lo, hi).collect();
        let best = (0..us.len())
            .max_by(|&a, &b| self.point(us[a])[1].total_cmp(&self.point(us[b])[1]))
            .unwrap_or(0);
        let (mut a, mut b) = (us[best.saturating_sub(1)], us[(best + 1).min(us.len() - 1)]);
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        while b - a > BISECTION_TOLERANCE_MM {
            let (c, d) = (b - ratio * (b - a), a + ratio * (b - a));
            if self.point(c)[1] >= self.point(d)[1] {
                b = d;
            } else {
                a = c;
            }
        }
        let u = 0.5 * (a + b);
        if self.point(u)[1] >= self.point(us[best])[1] {
            u
        } else {
            us[best]
        }
    }
}

/// The wear of `measured` against `nominal` (see the [module docs](self)): both given with
/// the inclination `profile_inclination` in their data, compared at `gauge_point_depth_mm`
/// below the nominal top.
///
/// # Units
/// Millimetres.
///
/// # Errors
/// [`WearError`] when a profile is a wheel, the nominal does not reach the gauge-point depth
/// on both sides, or the measured profile does not reach the centre line or the gauge face.
///
/// # Example
/// ```
/// use wheelrail::maintenance::rail_wear;
/// use wheelrail::profile::Profile;
/// use wheelrail::track::Inclination;
/// let rail = Profile::uic60e1();
/// let w = rail_wear(&rail, &rail, Inclination::VERTICAL, 14.0).unwrap();
/// assert!(w.vertical_mm.abs() < 1e-9 && w.gauge_face_mm.abs() < 1e-9);
/// assert!(w.centre_line_y_mm.abs() < 1e-6);
/// ```
pub fn rail_wear(
    measured: &Profile,
    nominal: &Profile,
    profile_inclination: Inclination,
    gauge_point_depth_mm: f64,
) -> Result<RailWear, WearError> {
    for p in [measured, nominal] {
        if p.kind() != ProfileKind::Rail {
            return Err(WearError::NotARail {
                profile: p.name().to_string(),
            });
        }
    }
    let rotation = UnitComplex::new(-profile_inclination.0);
    let nominal_up = Upright {
        profile: nominal,
        rotation,
    };
    let measured_up = Upright {
        profile: measured,
        rotation,
    };
    let u_top = nominal_up.top();
    let top_z_mm = nominal_up.point(u_top)[1];
    let face_z = top_z_mm - gauge_point_depth_mm;
    let (lo, hi) = nominal.domain();
    let above = |p: [f64; 2]| p[1] >= face_z;
    let too_short = || WearError::NominalTooShort {
        profile: nominal.name().to_string(),
    };
    let u_gauge = nominal_up
        .first_exit(u_top, lo, above)
        .ok_or_else(too_short)?;
    let u_field = nominal_up
        .first_exit(u_top, hi, above)
        .ok_or_else(too_short)?;
    let y_nominal_gauge = nominal_up.point(u_gauge)[0];
    let centre_line_y_mm = 0.5 * (y_nominal_gauge + nominal_up.point(u_field)[0]);
    let u_centre = nominal_up
        .first_exit(lo, hi, |p| p[0] < centre_line_y_mm)
        .ok_or_else(too_short)?;
    let z_nominal = nominal_up.point(u_centre)[1];

    let (lo, hi) = measured.domain();
    let short = |at| WearError::MeasuredTooShort { at };
    let measured_at = |u: f64| measured_up.point(u);
    if measured_at(lo)[0] > centre_line_y_mm {
        return Err(short("centre line"));
    }
    let u_centre = measured_up
        .first_exit(lo, hi, |p| p[0] < centre_line_y_mm)
        .ok_or_else(|| short("centre line"))?;
    let z_measured = measured_at(u_centre)[1];
    if z_measured < face_z {
        return Err(short("gauge face"));
    }
    let u_gauge = measured_up
        .first_exit(u_centre, lo, above)
        .ok_or_else(|| short("gauge face"))?;
    Ok(RailWear {
        vertical_mm: z_nominal - z_measured,
        gauge_face_mm: measured_at(u_gauge)[0] - y_nominal_gauge,
        centre_line_y_mm,
        top_z_mm,
        gauge_face_z_mm: face_z,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile::read::PointProfile;

    fn fitted(points: Vec<[f64; 2]>) -> Profile {
        let p = PointProfile::from_points(ProfileKind::Rail, "worn", points).unwrap();
        Profile::from_points(p, 0.0).unwrap()
    }

    /// 60E1 with a known amount of material taken off: the head planed flat 1.5 mm below
    /// its top, and the gauge corner cut back to a new 1:20 face that leaves the nominal
    /// head at `y = -33.5` and runs down and outwards (1 mm per 20 mm of depth): vertical
    /// wear 1.5 mm, gauge-face wear the new face's `y` 14 mm below the top less the
    /// nominal's (-35.9813 mm, reference/profiles.md, 4 decimals).
    #[test]
    fn material_taken_off_60e1_is_the_wear() {
        let nominal = Profile::uic60e1();
        let cut_y = -33.5;
        let cut_z = nominal.eval(cut_y)[0];
        // The new face, from 25 mm below the top up to where it meets the nominal head.
        let face = (0..=200).rev().map(|k| {
            let t = (-25.0 - cut_z) * f64::from(k) / 200.0;
            [cut_y + t / 20.0, cut_z + t]
        });
        let head = nominal
            .sample(0.05)
            .into_iter()
            .filter(|r| r[0] > cut_y + 1e-6)
            .map(|r| [r[0], r[1].min(-1.5)]);
        let worn = fitted(face.chain(head).collect());
        let w = rail_wear(&worn, &nominal, Inclination::VERTICAL, 14.0).unwrap();
        // Measured: vertical wear and the face's height exact, the gauge-face wear 3.4e-5 mm
        // off (the reference's 4 decimals), the centre line 5.8e-11 mm; bounds about twice.
        assert!((w.vertical_mm - 1.5).abs() < 1e-12, "{w:?}");
        let face_y = cut_y + (-14.0 - cut_z) / 20.0;
        let want = face_y - (-35.9813);
        assert!((w.gauge_face_mm - want).abs() < 7e-5, "{w:?} want {want}");
        assert!(w.centre_line_y_mm.abs() < 1.2e-10, "{w:?}");
        assert!((w.gauge_face_z_mm + 14.0).abs() < 1e-9, "{w:?}");
    }

    /// The same rail inclined 1:40 in its data and given with that inclination: no wear.
    /// The nominal sampled and inclined, measured against the upright built-in: the rotation
    /// is taken out, the wear is within the spline's error.
    #[test]
    fn the_profile_inclination_is_taken_out() {
        let nominal = Profile::uic60e1();
        let i40 = Inclination::parse("1:40").unwrap();
        let r = UnitComplex::new(i40.0);
        let points: Vec<[f64; 2]> = nominal
            .sample(0.05)
            .iter()
            .map(|s| {
                let p = r * Point2::new(s[0], s[1]);
                [p.x, p.y]
            })
            .collect();
        let inclined = fitted(points);
        let w = rail_wear(&inclined, &inclined, i40, 14.0).unwrap();
        // Measured: vertical wear exact, gauge-face wear 1.6e-10 mm, the centre line
        // 1.8e-4 mm (the spline through the 0.05 mm samples), the top 2.7e-14 mm; bounds
        // about twice these.
        assert!(
            w.vertical_mm.abs() < 1e-12 && w.gauge_face_mm.abs() < 4e-10,
            "{w:?}"
        );
        // The inclined copy's upright centre line is the built-in's axis.
        assert!(w.centre_line_y_mm.abs() < 4e-4, "{w:?}");
        assert!((w.top_z_mm).abs() < 1e-13, "{w:?}");
    }

    #[test]
    fn short_profiles_and_wheels_are_refused() {
        let nominal = Profile::uic60e1();
        let field_half: Vec<[f64; 2]> = nominal
            .sample(0.1)
            .iter()
            .filter(|r| r[0] > 5.0)
            .map(|r| [r[0], r[1]])
            .collect();
        let e = rail_wear(&fitted(field_half), &nominal, Inclination::VERTICAL, 14.0);
        assert_eq!(e, Err(WearError::MeasuredTooShort { at: "centre line" }));
        let crown: Vec<[f64; 2]> = nominal
            .sample(0.1)
            .iter()
            .filter(|r| r[0].abs() < 20.0)
            .map(|r| [r[0], r[1]])
            .collect();
        let e = rail_wear(&fitted(crown), &nominal, Inclination::VERTICAL, 14.0).unwrap_err();
        assert_eq!(e, WearError::MeasuredTooShort { at: "gauge face" });
        assert!(e.to_string().contains("gauge face"), "{e}");
        assert!(matches!(
            rail_wear(&Profile::s1002(), &nominal, Inclination::VERTICAL, 14.0),
            Err(WearError::NotARail { .. })
        ));
    }
}
