//! The lateral shifts of the wheelset a contact search sweeps: [`Sweep`], checked once when
//! it is made (finite, strictly increasing), so that no search has to check or sort them;
//! and the one decision of which positions a stage computes and which it mirrors
//! (`Mirror`), shared by the rigid search, the quasi-elastic pass and the Hertz sweep.

pub use crate::gap::yaw::YawModel;
use crate::message::Number;
use crate::track::Placement;
use std::fmt;

/// The largest yaw of the wheelset a sweep may reach (rad): 50 mrad, beyond the angle of
/// attack of a wheelset in the tightest curves (about 40 mrad at 150 m radius); a larger
/// value is almost certainly a unit mistake (degrees or milliradians for radians).
pub(crate) const MAX_YAW_RAD: f64 = 0.05;

/// The largest number of positions [`Sweep::range`] makes: a sweep of a million positions
/// is almost certainly a unit mistake (metres for millimetres) and would run for minutes.
pub(crate) const MAX_POSITIONS: usize = 100_001;

/// The smallest step of [`Sweep::range`] (mm): its positions are rounded to 1e-9 mm (clean
/// printed values, and opposite positions exactly opposite), so a step must be far above
/// that rounding for positions to stay distinct and evenly spaced; 1e-6 mm (a nanometre) is
/// a thousand roundings and far below any physical use.
pub(crate) const MIN_STEP_MM: f64 = 1e-6;

/// Shifts of a sweep opposite within this are mirror images of each other (mm): a sweep
/// computed as `from + i * step` or `from + (to - from) * i / (n - 1)` rounds the shifts of
/// one side differently from the other's by an ulp or so (2e-15 mm at 15 mm). A mirrored
/// position is reported at the sweep's own shift, at most this far from the shift it was
/// solved at: its contact moves by about as much (far below the roll solver's 1e-11 mm
/// residual), unless a jump lies in between, which no sweep resolves that finely.
const MIRRORED_SHIFT_MM: f64 = 1e-12;

/// Why shifts are no sweep.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SweepError {
    /// No shifts at all.
    Empty,
    /// A shift, or an end or the step of a range, is not a finite number.
    NonFinite {
        /// The offending value.
        value: f64,
    },
    /// A shift is not above the one before it (shifts must be strictly increasing).
    NotIncreasing {
        /// Its index in the sweep.
        index: usize,
        /// The shift (mm).
        shift_mm: f64,
        /// The shift before it (mm).
        previous_mm: f64,
    },
    /// A range's step is below 1e-6 mm (or not positive).
    StepTooSmall {
        /// The step (mm).
        step_mm: f64,
    },
    /// A range ends below its start.
    Reversed {
        /// Its start (mm).
        from_mm: f64,
        /// Its end (mm).
        to_mm: f64,
    },
    /// A yaw that is not finite, or reaches beyond ±0.05 rad (`MAX_YAW_RAD`) at an end of
    /// the sweep.
    Yaw {
        /// The yaw at that end (rad).
        yaw_rad: f64,
        /// The shift of that end (mm).
        y_ws_mm: f64,
    },
    /// A range of more than 100001 positions.
    TooManyPositions {
        /// The step (mm).
        step_mm: f64,
        /// The number of positions it gives.
        positions: f64,
    },
}

impl fmt::Display for SweepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            SweepError::Empty => f.write_str("a sweep needs at least one position"),
            SweepError::NonFinite { value } => {
                write!(f, "{} must be a finite number", Number(value))
            }
            SweepError::NotIncreasing {
                index,
                shift_mm,
                previous_mm,
            } => write!(
                f,
                "shift {index} ({} mm) is not above the one before it ({} mm): shifts must increase strictly",
                Number(shift_mm),
                Number(previous_mm)
            ),
            SweepError::StepTooSmall { step_mm } => write!(
                f,
                "{} mm is below {MIN_STEP_MM:e} mm: positions are rounded to 1e-9 mm and would repeat or be unevenly spaced",
                Number(step_mm)
            ),
            SweepError::Reversed { from_mm, to_mm } => write!(
                f,
                "{} is below the start {}: the sweep is empty",
                Number(to_mm),
                Number(from_mm)
            ),
            SweepError::Yaw { yaw_rad, y_ws_mm } => write!(
                f,
                "the yaw reaches {} mrad at the shift {} mm; at most {} mrad either way is a wheelset's yaw",
                Number(yaw_rad * 1e3),
                Number(y_ws_mm),
                Number(MAX_YAW_RAD * 1e3)
            ),
            SweepError::TooManyPositions { step_mm, positions } => write!(
                f,
                "{} mm gives {} positions; at most {MAX_POSITIONS} are allowed",
                Number(step_mm),
                Number(positions)
            ),
        }
    }
}

impl std::error::Error for SweepError {}

/// The lateral shifts `y_ws` of a sweep (mm, track frame: positive to the left): at least
/// one, finite and strictly increasing, as every contact search needs them.
///
/// Whether the shifts are symmetric about the centre (the `i`-th from either end opposite
/// within 1e-12 mm, an odd sweep's middle 0 within as much) is found once, here: on a
/// [mirror-symmetric](crate::track::Placement::is_mirror_symmetric) wheelset such a sweep
/// is solved from its middle on and the rest mirrored.
///
/// # Example
/// ```
/// use wheelrail::sweep::Sweep;
/// let sweep = Sweep::range(-15.0, 15.0, 0.1)?;
/// assert_eq!(sweep.len(), 301);
/// assert!(sweep.is_symmetric() && sweep.shifts_mm()[150] == 0.0);
/// assert!(Sweep::from_slice(&[0.0, 2.0, 1.0]).is_err());
/// # Ok::<(), wheelrail::sweep::SweepError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    shifts_mm: Vec<f64>,
    symmetric: bool,
    yaw: YawRule,
}

/// The yaw of the wheelset along a sweep: `psi(y_ws) = yaw_rad + yaw_rad_per_mm y_ws`, a
/// fixed yaw (a wheelset in a curve) and one that grows with the shift (as the Manchester
/// benchmark's case A-2.2 sets it), with the model of its outline ([`YawModel`]).
///
/// # Frames and signs
///
/// A right-hand rotation about the track's z (up): positive yaw turns the wheelset's
/// forward axis to the left (+y), moving the left wheel back (-x) and the right one forward.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct YawRule {
    yaw_rad: f64,
    yaw_rad_per_mm: f64,
    model: YawModel,
}

impl YawRule {
    /// No yaw.
    pub const NONE: YawRule = YawRule {
        yaw_rad: 0.0,
        yaw_rad_per_mm: 0.0,
        model: YawModel::Exact,
    };

    /// `psi(y_ws) = yaw_rad + yaw_rad_per_mm y_ws`; checked against a sweep by
    /// [`Sweep::with_yaw`].
    pub fn new(yaw_rad: f64, yaw_rad_per_mm: f64, model: YawModel) -> YawRule {
        YawRule {
            yaw_rad,
            yaw_rad_per_mm,
            model,
        }
    }

    /// The yaw at the shift `y_ws` (rad).
    #[inline]
    pub fn at(&self, y_ws: f64) -> f64 {
        self.yaw_rad + self.yaw_rad_per_mm * y_ws
    }

    /// The fixed part (rad).
    pub fn yaw_rad(&self) -> f64 {
        self.yaw_rad
    }

    /// The part that grows with the shift (rad/mm).
    pub fn yaw_rad_per_mm(&self) -> f64 {
        self.yaw_rad_per_mm
    }

    /// The model of the yawed wheel's outline.
    pub fn model(&self) -> YawModel {
        self.model
    }

    /// Whether the wheelset is yawed anywhere.
    pub fn is_yawed(&self) -> bool {
        self.yaw_rad != 0.0 || self.yaw_rad_per_mm != 0.0
    }

    /// Whether the yaw changes from position to position.
    pub fn varies(&self) -> bool {
        self.yaw_rad_per_mm != 0.0
    }

    /// Whether the yaw is odd in the shift (`psi(-y) = -psi(y)`: no fixed part), so that a
    /// mirror-symmetric wheelset's positions at `-y` are the images of those at `y`.
    pub fn is_odd(&self) -> bool {
        self.yaw_rad == 0.0
    }
}

impl Sweep {
    /// The sweep of `shifts_mm` (mm).
    ///
    /// # Errors
    /// [`SweepError::Empty`], [`SweepError::NonFinite`] or [`SweepError::NotIncreasing`].
    pub fn from_slice(shifts_mm: &[f64]) -> Result<Sweep, SweepError> {
        if shifts_mm.is_empty() {
            return Err(SweepError::Empty);
        }
        if let Some(&value) = shifts_mm.iter().find(|v| !v.is_finite()) {
            return Err(SweepError::NonFinite { value });
        }
        if let Some(i) = (1..shifts_mm.len()).find(|&i| shifts_mm[i] <= shifts_mm[i - 1]) {
            return Err(SweepError::NotIncreasing {
                index: i,
                shift_mm: shifts_mm[i],
                previous_mm: shifts_mm[i - 1],
            });
        }
        let n = shifts_mm.len();
        let opposite = |a: f64, b: f64| (a + b).abs() <= MIRRORED_SHIFT_MM;
        let symmetric = n >= 2
            && (0..n / 2).all(|i| opposite(shifts_mm[i], shifts_mm[n - 1 - i]))
            && (n.is_multiple_of(2) || shifts_mm[n / 2].abs() <= MIRRORED_SHIFT_MM);
        Ok(Sweep {
            shifts_mm: shifts_mm.to_vec(),
            symmetric,
            yaw: YawRule::NONE,
        })
    }

    /// This sweep with the wheelset yawed by `yaw` along it.
    ///
    /// # Errors
    /// [`SweepError::Yaw`] where the yaw is not finite or reaches beyond ±0.05 rad
    /// (`MAX_YAW_RAD`) at an end of the sweep.
    pub fn with_yaw(mut self, yaw: YawRule) -> Result<Sweep, SweepError> {
        for y_ws_mm in [self.shifts_mm[0], self.shifts_mm[self.shifts_mm.len() - 1]] {
            let yaw_rad = yaw.at(y_ws_mm);
            if yaw_rad.is_nan() || yaw_rad.abs() > MAX_YAW_RAD {
                return Err(SweepError::Yaw { yaw_rad, y_ws_mm });
            }
        }
        self.yaw = yaw;
        Ok(self)
    }

    /// The yaw of the wheelset along the sweep.
    pub fn yaw(&self) -> &YawRule {
        &self.yaw
    }

    /// The shifts `from_mm + i step_mm` up to `to_mm` (included when the step divides the
    /// range to within 1e-9 of a step), each computed from its index (not accumulated, so
    /// that 0 is hit exactly when it lies on the grid) and rounded to 1e-9 mm, so that
    /// printed values stay clean and opposite shifts are exactly opposite.
    ///
    /// # Errors
    /// [`SweepError::NonFinite`], [`SweepError::StepTooSmall`] (below 1e-6 mm),
    /// [`SweepError::Reversed`], [`SweepError::TooManyPositions`] (above 100001).
    pub fn range(from_mm: f64, to_mm: f64, step_mm: f64) -> Result<Sweep, SweepError> {
        if let Some(value) = [from_mm, to_mm, step_mm]
            .into_iter()
            .find(|v| !v.is_finite())
        {
            return Err(SweepError::NonFinite { value });
        }
        if step_mm < MIN_STEP_MM {
            return Err(SweepError::StepTooSmall { step_mm });
        }
        if to_mm < from_mm {
            return Err(SweepError::Reversed { from_mm, to_mm });
        }
        let n = ((to_mm - from_mm) / step_mm + 1e-9).floor();
        if n + 1.0 > MAX_POSITIONS as f64 {
            return Err(SweepError::TooManyPositions {
                step_mm,
                positions: n + 1.0,
            });
        }
        let shifts: Vec<f64> = (0..=n as usize)
            .map(|i| ((from_mm + i as f64 * step_mm) * 1e9).round() / 1e9)
            .collect();
        Sweep::from_slice(&shifts)
    }

    /// The shifts (mm), strictly increasing.
    pub fn shifts_mm(&self) -> &[f64] {
        &self.shifts_mm
    }

    /// The number of positions (at least one).
    #[allow(clippy::len_without_is_empty)]
    pub fn len(&self) -> usize {
        self.shifts_mm.len()
    }

    /// Whether the shifts are symmetric about the centre (see [`Sweep`]).
    pub fn is_symmetric(&self) -> bool {
        self.symmetric
    }
}

/// The positions of a sweep a stage computes when the wheelset is mirror-symmetric and the
/// sweep symmetric about the centre: those from the middle one on (`n / 2`); each position
/// `i` before it is the mirror image of position `n - 1 - i`.
///
/// The rigid search decides it ([`Mirror::of`]) and keeps it with its sweep; the stages
/// computed from a rigid sweep (quasi-elastic, Hertz) mirror where it did, since their
/// inputs are then exact mirror images.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Mirror {
    len: usize,
}

impl Mirror {
    /// `Some` where `sweep` on `placement` is solved from its middle on and mirrored:
    /// the placement [mirrors](Placement::mirrors) and the sweep is symmetric.
    ///
    /// The pose of a position is its shift and the roll solved for it, whose mirror image is
    /// the opposite shift and roll. A pose parameter given per position (a yaw `psi(y)`)
    /// joins the decision here: the image of `(y, psi)` is `(-y, -psi)`, so it must be odd
    /// in `y` for the images to be the positions before the middle.
    pub(crate) fn of(placement: &Placement, sweep: &Sweep) -> Option<Mirror> {
        (placement.mirrors() && sweep.is_symmetric() && sweep.yaw().is_odd())
            .then_some(Mirror { len: sweep.len() })
    }

    /// The first position computed: the middle one (`n / 2`).
    pub(crate) fn middle(self) -> usize {
        self.len / 2
    }

    /// The whole sweep's results from `solved`, the results from the middle position on,
    /// each position before it the image of its mirror position reported at its own shift
    /// (`y_ws(i)`).
    pub(crate) fn complete<T: Mirrored>(
        self,
        solved: Vec<T>,
        y_ws: impl Fn(usize) -> f64,
    ) -> Vec<T> {
        let middle = self.middle();
        debug_assert_eq!(solved.len(), self.len - middle);
        let images: Vec<T> = (0..middle)
            .map(|i| solved[self.len - 1 - i - middle].mirrored(y_ws(i)))
            .collect();
        let mut all = images;
        all.extend(solved);
        all
    }
}

/// A result at one position of a sweep with a mirror image: the result of a
/// mirror-symmetric wheelset at the opposite shift, which swaps the wheels and negates
/// track-frame lateral quantities (the roll, the contacts' `y`), side-frame quantities
/// unchanged (each side is computed in its own mirrored frame).
pub(crate) trait Mirrored {
    /// The mirror image, reported at the shift `y_ws`.
    fn mirrored(&self, y_ws: f64) -> Self;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shifts_are_checked() {
        assert_eq!(Sweep::from_slice(&[]), Err(SweepError::Empty));
        assert!(matches!(
            Sweep::from_slice(&[0.0, f64::NAN]),
            Err(SweepError::NonFinite { .. })
        ));
        assert!(matches!(
            Sweep::from_slice(&[0.0, 1.0, 1.0]),
            Err(SweepError::NotIncreasing { index: 2, .. })
        ));
        assert!(matches!(
            Sweep::range(0.0, 1.0, 0.0),
            Err(SweepError::StepTooSmall { .. })
        ));
        assert!(matches!(
            Sweep::range(1.0, 0.0, 0.1),
            Err(SweepError::Reversed { .. })
        ));
        assert!(matches!(
            Sweep::range(-100.0, 100.0, 1e-3),
            Err(SweepError::TooManyPositions { .. })
        ));
    }

    /// A range includes its end when the step divides it, its shifts are rounded to 1e-9
    /// mm, and symmetry is found within 1e-12 mm, not beyond.
    #[test]
    fn ranges_and_their_symmetry() {
        let sweep = Sweep::range(-15.0, 15.0, 0.1).unwrap();
        let s = sweep.shifts_mm();
        assert_eq!((s.len(), s[0], s[300]), (301, -15.0, 15.0));
        // Opposite to the bit: their sum is +0.
        assert!((0..301).all(|i| (s[i] + s[300 - i]).to_bits() == 0));
        assert!(sweep.is_symmetric());
        assert!(
            Sweep::from_slice(&[-1.0, 1.0 + 1e-13])
                .unwrap()
                .is_symmetric()
        );
        assert!(
            !Sweep::from_slice(&[-1.0, 1.0 + 1e-11])
                .unwrap()
                .is_symmetric()
        );
        assert!(!Sweep::from_slice(&[-1.0, 0.1, 1.0]).unwrap().is_symmetric());
        assert!(!Sweep::range(0.0, 15.0, 0.1).unwrap().is_symmetric());
        assert!(!Sweep::from_slice(&[0.0]).unwrap().is_symmetric());
    }
}
