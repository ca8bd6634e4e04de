//! Maintenance limits of the flange dimensions, and which of them a wheel breaks.
//!
//! # The standard's limits (defaults)
//!
//! In-service limits for standard-gauge (1435 mm) wheelsets, by wheel diameter `D`, as the
//! TSI for freight wagons tabulates them (Regulation (EU) No 321/2013, 4.2.3.6.2, Table 3;
//! the TSI for locomotives and passenger rolling stock, Regulation (EU) No 1302/2014, has
//! the same values; EN 15313 applies them in maintenance):
//!
//! | dimension | `D` | minimum | maximum |
//! |---|---|---|---|
//! | Sd, flange thickness | `D > 840` mm | 22 | 33 |
//! | | `760 < D <= 840` | 25 | 33 |
//! | | `330 <= D <= 760` | 27.5 | 33 |
//! | Sh, flange height | `D > 760` mm | 27.5 | 36 |
//! | | `630 < D <= 760` | 29.5 | 36 |
//! | | `330 <= D <= 630` | 31.5 | 36 |
//! | qR | `D >= 330` mm | 6.5 | |
//!
//! The band `D > 840` mm (the 920 mm wheels of the scenes here) agrees with the national
//! tables that were checked against it: EBO Anlage 6 (Germany) and EisbBBV Anlage 2
//! (Austria) give Sd 22 to 33 mm for vehicles in cross-border traffic, Sh up to 36 mm and
//! qR at least 6.5 mm; EisbBBV's Sh minimum for `D >= 760` mm is 27.5 mm. Below 330 mm,
//! outside the TSI's range, the 330 mm band applies and its source says so.
//!
//! A scene's `[limits]` overrides any of them (`sh_min_mm`, `sh_max_mm`, `sd_min_mm`,
//! `sd_max_mm`, `qr_min_mm`): a limit remembers where it came from (`Limit::source`).

use super::dimensions::FlangeDimensions;
use std::fmt;

/// One limit of a flange dimension: its value and where it comes from.
#[derive(Debug, Clone, PartialEq)]
pub struct Limit {
    /// The limit (mm).
    pub value_mm: f64,
    /// The standard and band it comes from, or the scene key that set it.
    pub source: String,
}

/// The limits of a wheel's flange dimensions (see the [module docs](self)).
#[derive(Debug, Clone, PartialEq)]
pub struct Limits {
    /// Least flange height Sh.
    pub sh_min: Limit,
    /// Greatest flange height Sh.
    pub sh_max: Limit,
    /// Least flange thickness Sd.
    pub sd_min: Limit,
    /// Greatest flange thickness Sd.
    pub sd_max: Limit,
    /// Least qR.
    pub qr_min: Limit,
}

/// Values set by a scene's `[limits]`, each overriding the standard's (mm).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LimitOverrides {
    /// `sh_min_mm`.
    pub sh_min_mm: Option<f64>,
    /// `sh_max_mm`.
    pub sh_max_mm: Option<f64>,
    /// `sd_min_mm`.
    pub sd_min_mm: Option<f64>,
    /// `sd_max_mm`.
    pub sd_max_mm: Option<f64>,
    /// `qr_min_mm`.
    pub qr_min_mm: Option<f64>,
}

/// The TSI table the defaults come from.
const TSI: &str = "TSI WAG, Regulation (EU) No 321/2013, 4.2.3.6.2 Table 3";
/// The greatest flange thickness, every diameter (mm).
const SD_MAX_MM: f64 = 33.0;
/// The greatest flange height, every diameter (mm).
const SH_MAX_MM: f64 = 36.0;
/// The least qR, every diameter (mm).
const QR_MIN_MM: f64 = 6.5;
/// The least flange thickness by diameter: `(D above which it applies, Sd min)`, largest
/// wheels first; the last band reaches down to 330 mm.
const SD_MIN_BANDS: [(f64, f64, &str); 3] = [
    (840.0, 22.0, "D > 840 mm"),
    (760.0, 25.0, "760 < D <= 840 mm"),
    (f64::NEG_INFINITY, 27.5, "330 <= D <= 760 mm"),
];
/// The least flange height by diameter, as [`SD_MIN_BANDS`].
const SH_MIN_BANDS: [(f64, f64, &str); 3] = [
    (760.0, 27.5, "D > 760 mm"),
    (630.0, 29.5, "630 < D <= 760 mm"),
    (f64::NEG_INFINITY, 31.5, "330 <= D <= 630 mm"),
];
/// The smallest wheel diameter the TSI's table covers (mm).
const SMALLEST_DIAMETER_MM: f64 = 330.0;

impl Limits {
    /// The standard's limits for a wheel of diameter `diameter_mm` (see the [module
    /// docs](self)).
    ///
    /// # Example
    /// ```
    /// let l = wheelrail::maintenance::Limits::standard(920.0);
    /// assert_eq!((l.sd_min.value_mm, l.sd_max.value_mm), (22.0, 33.0));
    /// assert_eq!((l.sh_min.value_mm, l.sh_max.value_mm, l.qr_min.value_mm), (27.5, 36.0, 6.5));
    /// ```
    pub fn standard(diameter_mm: f64) -> Limits {
        let below = if diameter_mm < SMALLEST_DIAMETER_MM {
            format!("; D = {diameter_mm} mm is below the table's 330 mm: its smallest band")
        } else {
            String::new()
        };
        let banded = |bands: &[(f64, f64, &str); 3]| {
            let (_, value_mm, band) = bands
                .iter()
                .find(|(above, _, _)| diameter_mm > *above)
                .copied()
                .unwrap_or(bands[2]);
            Limit {
                value_mm,
                source: format!("{TSI}, {band}{below}"),
            }
        };
        let every = |value_mm: f64| Limit {
            value_mm,
            source: format!("{TSI}, every D >= 330 mm{below}"),
        };
        Limits {
            sh_min: banded(&SH_MIN_BANDS),
            sh_max: every(SH_MAX_MM),
            sd_min: banded(&SD_MIN_BANDS),
            sd_max: every(SD_MAX_MM),
            qr_min: every(QR_MIN_MM),
        }
    }

    /// The standard's limits for `diameter_mm` with the scene's `overrides` in place.
    pub fn with_overrides(diameter_mm: f64, overrides: &LimitOverrides) -> Limits {
        let mut limits = Limits::standard(diameter_mm);
        for (limit, value, key) in [
            (&mut limits.sh_min, overrides.sh_min_mm, "sh_min_mm"),
            (&mut limits.sh_max, overrides.sh_max_mm, "sh_max_mm"),
            (&mut limits.sd_min, overrides.sd_min_mm, "sd_min_mm"),
            (&mut limits.sd_max, overrides.sd_max_mm, "sd_max_mm"),
            (&mut limits.qr_min, overrides.qr_min_mm, "qr_min_mm"),
        ] {
            if let Some(v) = value {
                *limit = Limit {
                    value_mm: v,
                    source: format!("scene key limits.{key}"),
                };
            }
        }
        limits
    }

    /// Every limit with its scene key, in the order Sh, Sd, qR.
    pub fn each(&self) -> [(&'static str, &Limit); 5] {
        [
            ("sh_min_mm", &self.sh_min),
            ("sh_max_mm", &self.sh_max),
            ("sd_min_mm", &self.sd_min),
            ("sd_max_mm", &self.sd_max),
            ("qr_min_mm", &self.qr_min),
        ]
    }

    /// Every limit as `key = value (source)`, joined by `; `: what a table's header states.
    pub fn describe(&self) -> String {
        self.each()
            .iter()
            .map(|(key, limit)| format!("{key} = {} ({})", limit.value_mm, limit.source))
            .collect::<Vec<_>>()
            .join("; ")
    }

    /// The limits `dimensions` break, in the order Sh, Sd, qR (none: within limits). A value
    /// on a limit is within it.
    pub fn breaches(&self, dimensions: &FlangeDimensions) -> Vec<Breach> {
        let d = dimensions;
        let checks = [
            (Dimension::Sh, Bound::Min, d.sh_mm, &self.sh_min),
            (Dimension::Sh, Bound::Max, d.sh_mm, &self.sh_max),
            (Dimension::Sd, Bound::Min, d.sd_mm, &self.sd_min),
            (Dimension::Sd, Bound::Max, d.sd_mm, &self.sd_max),
            (Dimension::QR, Bound::Min, d.qr_mm, &self.qr_min),
        ];
        checks
            .into_iter()
            .filter(|(_, bound, value, limit)| match bound {
                Bound::Min => *value < limit.value_mm,
                Bound::Max => *value > limit.value_mm,
            })
            .map(|(dimension, bound, value_mm, limit)| Breach {
                dimension,
                bound,
                value_mm,
                limit_mm: limit.value_mm,
            })
            .collect()
    }
}

/// A flange dimension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dimension {
    /// Flange height.
    Sh,
    /// Flange thickness.
    Sd,
    /// The flange slope dimension qR.
    QR,
}

impl Dimension {
    /// `Sh`, `Sd` or `qR`.
    pub fn symbol(self) -> &'static str {
        match self {
            Dimension::Sh => "Sh",
            Dimension::Sd => "Sd",
            Dimension::QR => "qR",
        }
    }
}

/// Which side of its range a value left.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bound {
    /// Below the least value.
    Min,
    /// Above the greatest value.
    Max,
}

/// A limit broken: the dimension, the bound, the value and the limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Breach {
    /// The dimension.
    pub dimension: Dimension,
    /// Below its minimum or above its maximum.
    pub bound: Bound,
    /// The wheel's value (mm).
    pub value_mm: f64,
    /// The limit (mm).
    pub limit_mm: f64,
}

impl fmt::Display for Breach {
    /// `Sd 21.40 < 22 mm`: two decimals, the 0.01 mm a wheel gauge reads.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let op = match self.bound {
            Bound::Min => "<",
            Bound::Max => ">",
        };
        write!(
            f,
            "{} {:.2} {op} {} mm",
            self.dimension.symbol(),
            self.value_mm,
            self.limit_mm
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dims(sh_mm: f64, sd_mm: f64, qr_mm: f64) -> FlangeDimensions {
        FlangeDimensions {
            sh_mm,
            sd_mm,
            qr_mm,
            taping_line_height_mm: 0.0,
            tip_s_mm: -55.0,
            sd_point_s_mm: sd_mm - 70.0,
            qr_point_s_mm: sd_mm - 70.0 - qr_mm,
        }
    }

    #[test]
    fn bands_follow_the_diameter() {
        let at = |d: f64| {
            let l = Limits::standard(d);
            (l.sd_min.value_mm, l.sh_min.value_mm)
        };
        assert_eq!(at(920.0), (22.0, 27.5));
        assert_eq!(at(840.0), (25.0, 27.5));
        assert_eq!(at(800.0), (25.0, 27.5));
        assert_eq!(at(760.0), (27.5, 29.5));
        assert_eq!(at(630.0), (27.5, 31.5));
        assert_eq!(at(330.0), (27.5, 31.5));
        assert!(Limits::standard(300.0).sd_min.source.contains("below"));
        assert!(!Limits::standard(920.0).sd_min.source.contains("below"));
        assert!(Limits::standard(920.0).qr_min.source.contains("321/2013"));
    }

    #[test]
    fn breaches_name_each_limit_broken() {
        let l = Limits::standard(920.0);
        assert!(l.breaches(&dims(28.0, 32.5, 10.8)).is_empty());
        // On a limit is within it.
        assert!(l.breaches(&dims(27.5, 22.0, 6.5)).is_empty());
        let b = l.breaches(&dims(36.2, 21.4, 6.0));
        let text: Vec<String> = b.iter().map(ToString::to_string).collect();
        assert_eq!(
            text,
            ["Sh 36.20 > 36 mm", "Sd 21.40 < 22 mm", "qR 6.00 < 6.5 mm"]
        );
    }

    #[test]
    fn overrides_replace_the_standard_and_say_so() {
        let o = LimitOverrides {
            sd_min_mm: Some(24.0),
            ..LimitOverrides::default()
        };
        let l = Limits::with_overrides(920.0, &o);
        assert_eq!(l.sd_min.value_mm.to_bits(), 24f64.to_bits());
        assert_eq!(l.sd_min.source, "scene key limits.sd_min_mm");
        assert_eq!(l.sd_max, Limits::standard(920.0).sd_max);
        assert_eq!(l.breaches(&dims(28.0, 23.0, 10.0)).len(), 1);
    }
}
