//! The track and wheelset dimensions, validated once by their constructors: a
//! [`TrackLayout`] that exists is a track (a gauge in use, a gauge point in the rail head, a
//! wheelset that fits the gauge, an inclination towards the track centre).

use crate::message::Number;
use std::fmt;

/// Distance from the inner face of a wheel to its taping line (EN 13715), mm.
pub(crate) const TAPING_LINE_FROM_INNER_FACE_MM: f64 = 70.0;

/// Standard gauge (mm): 1435.
pub(crate) const STANDARD_GAUGE_MM: f64 = 1435.0;
/// Depth below the top of rail at which the gauge is measured (mm, EN 13848-1): 14.
pub(crate) const GAUGE_POINT_DEPTH_MM: f64 = 14.0;
/// Distance between the inner faces of a standard wheelset's wheels (mm): 1360.
pub(crate) const STANDARD_FLANGE_BACK_MM: f64 = 1360.0;

/// The gauges accepted (mm): every gauge in use, from 381 mm minimum-gauge railways to
/// 1676 mm broad gauge, with margin. The wheelset is placed from it; 1e300 mm is not a track.
pub(crate) const GAUGE_RANGE_MM: (f64, f64) = (300.0, 2000.0);
/// The gauge-point depths accepted (mm, the lower end excluded): the gauge point lies in the
/// rail head, whose gauge face is about 30 mm deep on every standard rail (14 mm is the
/// usual depth, 10 mm on some older networks).
pub(crate) const GAUGE_POINT_DEPTH_RANGE_MM: (f64, f64) = (0.0, 30.0);
/// The flange-back distances accepted, as fractions of the gauge (the upper end excluded):
/// the wheels must sit between the rails (1360 / 1435 = 0.948 on standard gauge; 0.8 leaves
/// room for every gauge and wheelset standard).
pub(crate) const FLANGE_BACK_RANGE_OF_GAUGE: (f64, f64) = (0.8, 1.0);
/// The rail inclinations accepted (rad): upright to about 11 degrees towards the track
/// centre (1:40 is 0.025 rad, 1:20 is 0.05 rad); an outward or steeper tilt is not a track.
pub(crate) const INCLINATION_RANGE_RAD: (f64, f64) = (0.0, 0.2);

/// Why a track layout or an inclination is not accepted. Each variant names the quantity,
/// so that a caller (the scene file) can name the key it came from.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum LayoutError {
    /// An inclination's text is none of the accepted forms.
    InclinationText {
        /// The text as given.
        text: String,
    },
    /// An inclination outside `INCLINATION_RANGE_RAD` (or not finite).
    InclinationOutOfRange {
        /// The angle, rad.
        radians: f64,
    },
    /// A gauge outside `GAUGE_RANGE_MM` (or not finite).
    Gauge {
        /// The gauge, mm.
        gauge_mm: f64,
    },
    /// A gauge-point depth outside `GAUGE_POINT_DEPTH_RANGE_MM` (or not finite).
    GaugePointDepth {
        /// The depth, mm.
        depth_mm: f64,
    },
    /// A flange-back distance that does not fit the gauge (`FLANGE_BACK_RANGE_OF_GAUGE`).
    FlangeBack {
        /// The flange-back distance, mm.
        flange_back_mm: f64,
        /// The gauge, mm.
        gauge_mm: f64,
    },
}

impl fmt::Display for LayoutError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LayoutError::InclinationText { text } => write!(
                f,
                "inclination {text:?} not understood; expected \"1:40\", \"1:20\", \"1:30\", \"vertical\" or an angle in radians"
            ),
            LayoutError::InclinationOutOfRange { radians } => write!(
                f,
                "inclination {} rad; expected {} to {} rad towards the track centre",
                Number(*radians),
                INCLINATION_RANGE_RAD.0,
                INCLINATION_RANGE_RAD.1
            ),
            LayoutError::Gauge { gauge_mm } => write!(
                f,
                "{} mm is not a railway gauge; expected {} to {} mm",
                Number(*gauge_mm),
                GAUGE_RANGE_MM.0,
                GAUGE_RANGE_MM.1
            ),
            LayoutError::GaugePointDepth { depth_mm } => write!(
                f,
                "{} mm is not a gauge-point depth in the rail head (expected more than {} and at most {} mm, usually 14)",
                Number(*depth_mm),
                GAUGE_POINT_DEPTH_RANGE_MM.0,
                GAUGE_POINT_DEPTH_RANGE_MM.1
            ),
            LayoutError::FlangeBack {
                flange_back_mm,
                gauge_mm,
            } => write!(
                f,
                "{} mm does not fit a {} mm gauge (expected between 80 % of the gauge and the gauge)",
                Number(*flange_back_mm),
                Number(*gauge_mm)
            ),
        }
    }
}

impl std::error::Error for LayoutError {}

/// A rail inclination towards the track centre, as an angle in radians, within
/// `INCLINATION_RANGE_RAD`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inclination(pub(crate) f64);

impl Inclination {
    /// An upright rail (0 rad): the inclination of rail profile data given upright.
    pub const VERTICAL: Inclination = Inclination(0.0);

    /// The inclination of `radians` towards the track centre.
    ///
    /// # Errors
    /// [`LayoutError::InclinationOutOfRange`] outside `INCLINATION_RANGE_RAD` or for a
    /// non-finite angle.
    ///
    /// # Example
    /// ```
    /// use wheelrail::track::Inclination;
    /// assert_eq!(Inclination::from_radians(0.025).unwrap().radians(), 0.025);
    /// assert!(Inclination::from_radians(-0.025).is_err());
    /// ```
    pub fn from_radians(radians: f64) -> Result<Inclination, LayoutError> {
        if (INCLINATION_RANGE_RAD.0..=INCLINATION_RANGE_RAD.1).contains(&radians) {
            Ok(Inclination(radians))
        } else {
            Err(LayoutError::InclinationOutOfRange { radians })
        }
    }

    /// Parses `"1:40"`, `"1:20"`, `"vertical"` (or `"upright"`, `"0"`), or an angle in
    /// radians (`"0.025"`).
    ///
    /// # Errors
    /// [`LayoutError::InclinationText`] when the text is none of these,
    /// [`LayoutError::InclinationOutOfRange`] when the angle is outside
    /// `INCLINATION_RANGE_RAD`.
    ///
    /// # Example
    /// ```
    /// use wheelrail::track::Inclination;
    /// let i = Inclination::parse("1:40").unwrap();
    /// assert!((i.radians() - 0.0249948).abs() < 1e-7);
    /// ```
    pub fn parse(text: &str) -> Result<Inclination, LayoutError> {
        let t = text.trim();
        let not_understood = || LayoutError::InclinationText {
            text: text.to_string(),
        };
        let angle = if t.eq_ignore_ascii_case("vertical") || t.eq_ignore_ascii_case("upright") {
            0.0
        } else if let Some((one, n)) = t.split_once(':') {
            let one: f64 = one.trim().parse().map_err(|_| not_understood())?;
            let n: f64 = n.trim().parse().map_err(|_| not_understood())?;
            if !(one > 0.0 && n > 0.0 && one.is_finite() && n.is_finite()) {
                return Err(not_understood());
            }
            (one / n).atan()
        } else {
            t.parse::<f64>().map_err(|_| not_understood())?
        };
        Inclination::from_radians(angle)
    }

    /// The angle towards the track centre, rad.
    pub fn radians(self) -> f64 {
        self.0
    }
}

/// Dimensions of the track and wheelset layout (all mm), checked by [`TrackLayout::new`].
#[derive(Debug, Clone, PartialEq)]
pub struct TrackLayout {
    pub(crate) gauge_mm: f64,
    pub(crate) gauge_point_depth_mm: f64,
    pub(crate) inclination: Inclination,
    pub(crate) flange_back_mm: f64,
}

impl TrackLayout {
    /// A track of `gauge_mm` between the gauge points `gauge_point_depth_mm` below the top
    /// of rail, rails inclined by `inclination`, and a wheelset with `flange_back_mm`
    /// between its wheels' inner faces.
    ///
    /// # Errors
    /// [`LayoutError::Gauge`], [`LayoutError::GaugePointDepth`] or
    /// [`LayoutError::FlangeBack`] when a dimension is outside its range (see the
    /// constants of this module), checked in that order.
    ///
    /// # Example
    /// ```
    /// use wheelrail::track::{Inclination, TrackLayout};
    /// // Iberian broad gauge.
    /// let layout = TrackLayout::new(1668.0, 14.0, 1595.0, Inclination::parse("1:20").unwrap());
    /// assert_eq!(layout.unwrap().gauge_mm(), 1668.0);
    /// assert!(TrackLayout::new(1435.0, 14.0, 1500.0, Inclination::VERTICAL).is_err());
    /// ```
    pub fn new(
        gauge_mm: f64,
        gauge_point_depth_mm: f64,
        flange_back_mm: f64,
        inclination: Inclination,
    ) -> Result<TrackLayout, LayoutError> {
        if !(GAUGE_RANGE_MM.0..=GAUGE_RANGE_MM.1).contains(&gauge_mm) {
            return Err(LayoutError::Gauge { gauge_mm });
        }
        let (depth_lo, depth_hi) = GAUGE_POINT_DEPTH_RANGE_MM;
        if !(gauge_point_depth_mm > depth_lo && gauge_point_depth_mm <= depth_hi) {
            return Err(LayoutError::GaugePointDepth {
                depth_mm: gauge_point_depth_mm,
            });
        }
        let (lo, hi) = FLANGE_BACK_RANGE_OF_GAUGE;
        if !(lo * gauge_mm..hi * gauge_mm).contains(&flange_back_mm) {
            return Err(LayoutError::FlangeBack {
                flange_back_mm,
                gauge_mm,
            });
        }
        Ok(TrackLayout {
            gauge_mm,
            gauge_point_depth_mm,
            inclination,
            flange_back_mm,
        })
    }

    /// Standard gauge (1435 mm, measured 14 mm below the top of rail) and a standard
    /// wheelset (1360 mm between the wheels' inner faces), rails inclined by `inclination`.
    ///
    /// # Example
    /// ```
    /// use wheelrail::track::{Inclination, TrackLayout};
    /// let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
    /// assert_eq!(layout.gauge_mm(), 1435.0);
    /// assert_eq!(layout.taping_line_mm(), 750.0);
    /// ```
    pub fn standard(inclination: Inclination) -> TrackLayout {
        TrackLayout {
            gauge_mm: STANDARD_GAUGE_MM,
            gauge_point_depth_mm: GAUGE_POINT_DEPTH_MM,
            inclination,
            flange_back_mm: STANDARD_FLANGE_BACK_MM,
        }
    }

    /// Track gauge between the gauge points, mm.
    pub fn gauge_mm(&self) -> f64 {
        self.gauge_mm
    }

    /// Depth below the top of rail at which the gauge is measured, mm.
    pub fn gauge_point_depth_mm(&self) -> f64 {
        self.gauge_point_depth_mm
    }

    /// Rail inclination towards the track centre.
    pub fn inclination(&self) -> Inclination {
        self.inclination
    }

    /// Distance between the inner faces of the wheels (flange-back), mm.
    pub fn flange_back_mm(&self) -> f64 {
        self.flange_back_mm
    }

    /// Lateral position of the taping lines from the wheelset centre, `Y` in the side frame
    /// (mm).
    pub fn taping_line_mm(&self) -> f64 {
        0.5 * self.flange_back_mm + TAPING_LINE_FROM_INNER_FACE_MM
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inclination_parsing() {
        assert!(Inclination::parse("vertical").unwrap().radians().abs() < 1e-15);
        assert!((Inclination::parse("1:20").unwrap().radians() - 0.05f64.atan()).abs() < 1e-15);
        assert!((Inclination::parse("0.025").unwrap().radians() - 0.025).abs() < 1e-15);
        assert!(Inclination::parse("1:0").is_err());
        assert!(Inclination::parse("steep").is_err());
        assert!(Inclination::parse("-0.1").is_err());
        assert!(Inclination::parse("NaN").is_err());
    }

    #[test]
    fn layouts_out_of_range_name_the_dimension() {
        let v = Inclination::VERTICAL;
        assert!(matches!(
            TrackLayout::new(f64::NAN, 14.0, 1360.0, v),
            Err(LayoutError::Gauge { .. })
        ));
        assert!(matches!(
            TrackLayout::new(1435.0, 0.0, 1360.0, v),
            Err(LayoutError::GaugePointDepth { .. })
        ));
        assert!(matches!(
            TrackLayout::new(1435.0, 31.0, 1360.0, v),
            Err(LayoutError::GaugePointDepth { .. })
        ));
        assert!(matches!(
            TrackLayout::new(1435.0, 14.0, 1435.0, v),
            Err(LayoutError::FlangeBack { .. })
        ));
        assert_eq!(
            TrackLayout::new(1435.0, 14.0, 1360.0, v),
            Ok(TrackLayout::standard(v))
        );
    }
}
