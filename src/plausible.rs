//! What a wheel, a rail and their contact can be: the accepted range of each physical input,
//! in one table shared by the scene's keys and the commands that take the same quantities
//! (`wheelrail hertz`), so that a value gets the same verdict and the same words wherever it
//! is given.
//!
//! A value outside its range is refused with what it is not, the range, and, where
//! the value would be in range in another unit, the likely unit mistake: a radius of 0.46 mm
//! "is likely 0.46 m = 460 mm", a Young's modulus of 210000 GPa "likely 210000 MPa = 210
//! GPa".
//!
//! To add a quantity: a [`Range`] constant here with its reason; the scene key or flag that
//! takes it calls [`Range::check`] and puts its own name before the message.
//!
//! # Example
//!
//! ```
//! use wheelrail::plausible::RADIUS_MM;
//! assert_eq!(RADIUS_MM.check(-13.0), Ok(-13.0)); // a concave flange root
//! let e = RADIUS_MM.check(0.46).unwrap_err();
//! assert_eq!(
//!     e.to_string(),
//!     "0.46 mm is not a principal radius of a wheel or rail surface; expected |r| >= 1 mm \
//!      (inf for a straight direction); likely a unit mistake: 0.46 m = 460 mm"
//! );
//! ```

use crate::message::Number;
use std::fmt;

/// The values a quantity accepts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bounds {
    /// `min <= v <= max`.
    Closed(f64, f64),
    /// `min <= v < max`.
    HalfOpen(f64, f64),
    /// Either sign, `min <= |v| <= max`; `max` infinite admits `±inf`.
    Magnitude(f64, f64),
}

impl Bounds {
    fn contains(self, v: f64) -> bool {
        match self {
            Bounds::Closed(lo, hi) => v >= lo && v <= hi,
            Bounds::HalfOpen(lo, hi) => v >= lo && v < hi,
            Bounds::Magnitude(lo, hi) => v.abs() >= lo && v.abs() <= hi,
        }
    }
}

/// A unit a value may have been given in by mistake: the value in that unit times
/// `factor` is the value in the range's unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mistake {
    /// The unit, as written after a number (`m`, `MPa`).
    pub unit: &'static str,
    /// Range units per mistaken unit (1000 mm per m).
    pub factor: f64,
}

/// The accepted values of one physical quantity and how a value outside them is reported.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// What an accepted value is, after "is not" in messages: "a wheel load".
    pub what: &'static str,
    /// The unit, as written after a number; empty for a ratio.
    pub unit: &'static str,
    /// The quantity's symbol in the range's text (`|r| >= 1 mm`, `0 <= poisson < 0.5`).
    pub symbol: &'static str,
    /// The accepted values.
    pub bounds: Bounds,
    /// Said after the range, in brackets, where the range needs a reason in place.
    pub note: Option<&'static str>,
    /// Units a value outside the range may have been given in, tried in order.
    pub mistakes: &'static [Mistake],
}

/// A value outside its [`Range`]; its `Display` is the message.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Implausible {
    /// The value given.
    pub value: f64,
    /// The range it is outside.
    pub range: &'static Range,
}

impl Range {
    /// `v` if it is within the range, else what is wrong with it.
    ///
    /// # Errors
    ///
    /// [`Implausible`] for a value outside the range (NaN included).
    pub fn check(&'static self, v: f64) -> Result<f64, Implausible> {
        if self.bounds.contains(v) {
            Ok(v)
        } else {
            Err(Implausible {
                value: v,
                range: self,
            })
        }
    }

    /// The accepted values in words: `1 to 1000 GPa`, `0 <= poisson < 0.5`.
    pub fn expected(&self) -> String {
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        let symbol = self.symbol;
        match self.bounds {
            Bounds::Closed(lo, hi) => format!("{} to {}{unit}", Number(lo), Number(hi)),
            Bounds::HalfOpen(lo, hi) => {
                format!("{} <= {symbol} < {}{unit}", Number(lo), Number(hi))
            }
            Bounds::Magnitude(lo, hi) if hi.is_infinite() => {
                format!("|{symbol}| >= {}{unit}", Number(lo))
            }
            Bounds::Magnitude(lo, hi) if lo <= 0.0 => format!("|{symbol}| <= {}{unit}", Number(hi)),
            Bounds::Magnitude(lo, hi) => {
                format!("{} <= |{symbol}| <= {}{unit}", Number(lo), Number(hi))
            }
        }
    }
}

impl Implausible {
    /// The first of the range's [`Mistake`]s under which the value would be accepted, and
    /// the value it would then be (in the range's unit).
    pub fn likely_mistake(&self) -> Option<(Mistake, f64)> {
        self.range
            .mistakes
            .iter()
            .map(|&m| (m, readable(self.value * m.factor)))
            .find(|&(_, v)| self.range.bounds.contains(v))
    }
}

/// `v` to 12 significant digits, so that a converted value prints as the user would write
/// it (460, not 460.00000000000006).
fn readable(v: f64) -> f64 {
    format!("{v:.11e}").parse().unwrap_or(v)
}

impl fmt::Display for Implausible {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r = self.range;
        let space = if r.unit.is_empty() { "" } else { " " };
        write!(
            f,
            "{}{space}{} is not {}; expected {}",
            Number(self.value),
            r.unit,
            r.what,
            r.expected()
        )?;
        if let Some(note) = r.note {
            write!(f, " ({note})")?;
        }
        if let Some((m, v)) = self.likely_mistake() {
            write!(
                f,
                "; likely a unit mistake: {} {} = {}{space}{}",
                Number(self.value),
                m.unit,
                Number(v),
                r.unit
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for Implausible {}

/// The wheel load of a scene (`load.wheel_load_kN`, kN): 1 N, the lower end of the loads the
/// Hertz solution is tested at (`tests/stress_hertz.rs`; a lighter wheel only touches its rail),
/// to 1 MN, ten times the heaviest axle loads. A value above reads as newtons.
pub const WHEEL_LOAD_KN: Range = Range {
    what: "a wheel load",
    unit: "kN",
    symbol: "load",
    bounds: Bounds::Closed(1e-3, 1e3),
    note: None,
    mistakes: &[Mistake {
        unit: "N",
        factor: 1e-3,
    }],
};

/// A normal load in newtons (`wheelrail hertz --load`): the range of [`WHEEL_LOAD_KN`] in N.
/// A value below reads as kilonewtons.
pub const NORMAL_LOAD_N: Range = Range {
    what: "a wheel load",
    unit: "N",
    symbol: "load",
    bounds: Bounds::Closed(1.0, 1e6),
    note: None,
    mistakes: &[Mistake {
        unit: "kN",
        factor: 1e3,
    }],
};

/// Young's modulus of a wheel or rail body (GPa): polymers used on model rigs (a few GPa) to
/// tungsten carbide (about 700 GPa), with margin; railway steels are about 210 GPa. Above,
/// a value reads as megapascals or pascals.
pub const YOUNG_GPA: Range = Range {
    what: "the Young's modulus of a wheel or rail material",
    unit: "GPa",
    symbol: "E",
    bounds: Bounds::Closed(1.0, 1000.0),
    note: None,
    mistakes: &[
        Mistake {
            unit: "MPa",
            factor: 1e-3,
        },
        Mistake {
            unit: "Pa",
            factor: 1e-9,
        },
    ],
};

/// Poisson's ratio of a wheel or rail body, `[0, 0.5)`: the mathematical range is
/// `(-1, 0.5)`, but no wheel or rail material has a negative ratio (steels 0.27 to 0.30,
/// polymers up to 0.45; negative ratios belong to auxetic foams), and near -1 the combined
/// modulus `E/(1-ν²)` grows without bound. 0.5 (incompressible) is excluded by Hertz's
/// formula itself.
pub const POISSON: Range = Range {
    what: "the Poisson's ratio of a wheel or rail material",
    unit: "",
    symbol: "poisson",
    bounds: Bounds::HalfOpen(0.0, 0.5),
    note: Some("negative ratios are auxetic foams, 0.5 is incompressible"),
    // A percentage (30 for 0.3) is not named: 0.5 would read as 0.5 % = 0.005.
    mistakes: &[],
};

/// A principal radius of curvature of a wheel or rail surface (mm, convex positive, `inf`
/// for a straight direction): at least 1 mm in magnitude. The sharpest radii of wheel and
/// rail profiles are about 10 mm (flange root, gauge corner); below 1 mm a radius is an
/// edge or reads as metres.
pub const RADIUS_MM: Range = Range {
    what: "a principal radius of a wheel or rail surface",
    unit: "mm",
    symbol: "r",
    bounds: Bounds::Magnitude(1.0, f64::INFINITY),
    note: Some("inf for a straight direction"),
    mistakes: &[Mistake {
        unit: "m",
        factor: 1e3,
    }],
};

/// A curvature (1/mm) of a wheel or rail surface or a relative curvature of their contact:
/// at most 1/mm in magnitude (a radius of 1 mm, [`RADIUS_MM`]); above, it reads as 1/m.
pub const CURVATURE_PER_MM: Range = Range {
    what: "a curvature of a wheel or rail surface",
    unit: "1/mm",
    symbol: "curvature",
    bounds: Bounds::Magnitude(0.0, 1.0),
    note: None,
    mistakes: &[Mistake {
        unit: "1/m",
        factor: 1e-3,
    }],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_in_range_pass_unchanged() {
        for (range, v) in [
            (&WHEEL_LOAD_KN, 70.0),
            (&WHEEL_LOAD_KN, 1e-3),
            (&WHEEL_LOAD_KN, 1e3),
            (&NORMAL_LOAD_N, 7e4),
            (&YOUNG_GPA, 210.0),
            (&POISSON, 0.0),
            (&POISSON, 0.3),
            (&RADIUS_MM, 460.0),
            (&RADIUS_MM, -12.0),
            (&RADIUS_MM, f64::INFINITY),
            (&RADIUS_MM, f64::NEG_INFINITY),
            (&CURVATURE_PER_MM, 0.0),
            (&CURVATURE_PER_MM, -1.0),
        ] {
            assert_eq!(range.check(v).map(f64::to_bits), Ok(v.to_bits()), "{v}");
        }
    }

    #[test]
    fn values_outside_name_the_range_and_the_likely_unit_mistake() {
        for (range, v, message) in [
            (
                &WHEEL_LOAD_KN,
                70000.0,
                "70000 kN is not a wheel load; expected 0.001 to 1000 kN; likely a unit mistake: 70000 N = 70 kN",
            ),
            (
                &NORMAL_LOAD_N,
                0.07,
                "0.07 N is not a wheel load; expected 1 to 1000000 N; likely a unit mistake: 0.07 kN = 70 N",
            ),
            (
                &YOUNG_GPA,
                210000.0,
                "210000 GPa is not the Young's modulus of a wheel or rail material; expected 1 to 1000 GPa; likely a unit mistake: 210000 MPa = 210 GPa",
            ),
            (
                &YOUNG_GPA,
                2.1e11,
                "210000000000 GPa is not the Young's modulus of a wheel or rail material; expected 1 to 1000 GPa; likely a unit mistake: 210000000000 Pa = 210 GPa",
            ),
            (
                &POISSON,
                -0.5,
                "-0.5 is not the Poisson's ratio of a wheel or rail material; expected 0 <= poisson < 0.5 (negative ratios are auxetic foams, 0.5 is incompressible)",
            ),
            (
                &CURVATURE_PER_MM,
                2.17,
                "2.17 1/mm is not a curvature of a wheel or rail surface; expected |curvature| <= 1 1/mm; likely a unit mistake: 2.17 1/m = 0.00217 1/mm",
            ),
            (
                &RADIUS_MM,
                0.0,
                "0 mm is not a principal radius of a wheel or rail surface; expected |r| >= 1 mm (inf for a straight direction)",
            ),
            (
                &RADIUS_MM,
                f64::NAN,
                "NaN mm is not a principal radius of a wheel or rail surface; expected |r| >= 1 mm (inf for a straight direction)",
            ),
        ] {
            let e = range.check(v).unwrap_err();
            assert_eq!(e.to_string(), message);
        }
    }

    #[test]
    fn no_mistake_is_named_when_no_unit_brings_the_value_in_range() {
        // 1e-5 m is 0.01 mm: still no radius.
        let e = RADIUS_MM.check(1e-5).unwrap_err();
        assert_eq!(e.likely_mistake(), None);
        // A value above the range read in a smaller unit only grows.
        assert_eq!(YOUNG_GPA.check(0.5).unwrap_err().likely_mistake(), None);
    }
}
