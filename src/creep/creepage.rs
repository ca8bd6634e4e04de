//! Creepages of a contact from the motion of the wheelset: Kalker's and CONTACT's
//! definitions, in the crate's track frame.
//!
//! # Definitions
//!
//! The rail is at rest; the wheelset's centre moves with velocity `(V, ẏ, 0)` (forward speed
//! `V`, lateral velocity `ẏ`), the wheelset turns about its axle at the pitch rate `ω` and
//! about its own vertical axis at the yaw rate `ψ̇`. The contact point `d` (from the
//! wheelset's centre) moves with the wheelset but not with its pitch: `v_c = (V, ẏ, 0) +
//! ψ̇ z_w × d`; the wheel's material there moves with `v = v_c + ω e × d` (`e` the axle,
//! `z_w` the wheelset's vertical axis). Following Kalker (1990, §1.2) and CONTACT, the
//! creepages are the velocity of the rail relative to the wheel over the rolling speed `V_r`,
//! in the patch's contact frame `(t_x, t_y, n)`:
//!
//! ```text
//! ξ = -v·t_x / V_r,   η = -v·t_y / V_r,   φ = -Ω·n / V_r   (1/mm)
//! ```
//!
//! with `Ω = ω e + ψ̇ z_w` and the rolling speed the mean of the speeds at which the rail's
//! and the wheel's material pass through the patch along the rail:
//! `V_r = ½ t_x·(v_c - ω e × d) ≈ ½ (V + ω r)`. Dividing by `V` instead would differ by the
//! factor `1 + ξ/2`: 1.1 % at the 2.3 % longitudinal creepage of A-2.2's left wheel at 8 mm,
//! where CONTACT's creepages agree with `V_r` to 0.13 % (test
//! `manchester_creepages_from_the_motion` in `crates/cli/tests/creep.rs`).
//!
//! # Frames and signs
//!
//! Track frame as in the crate docs: x forward, y left, z up. The wheelset is rolled by
//! `roll_rad` about x and then yawed by `yaw_rad` about its own vertical axis (CONTACT's
//! roll-yaw-pitch order; the two orders differ by a rotation of order `roll · yaw`, a few
//! 1e-4 rad): `R = Rx(roll) · Rz(yaw)`. Positive yaw turns the wheelset's forward axis
//! towards +y (left); positive pitch rate is forward rolling (right-handed about the axle,
//! which points left).
//!
//! The contact frame of a patch is the track frame turned about x by the patch's contact
//! angle `δ` (track frame, signed: the rotation from track z to the patch normal, positive
//! on the left wheel's tread and flange, negative on the right one's): `t_x = x` along the
//! rail, `t_y = (0, cos δ, sin δ)` in the tangent plane, `n = (0, -sin δ, cos δ)` the normal
//! out of the rail into the wheel. Both wheels use this one right-handed frame, so on a
//! symmetric wheelset at `y_ws = 0` the lateral creepage and the spin have opposite signs on
//! the two sides (as in CONTACT, whose frame is this one turned by π about x: `ξ` is the
//! same, `η` and `φ` change sign).
//!
//! The contact point is given in the wheelset's own frame (`R` applied): its lead `x_w`
//! along the wheelset's forward axis, its lateral position `y_w` along the axle, and the
//! rolling radius `r` there (its distance from the axle), so `d = R (x_w, y_w, -√(r² - x_w²))`.
//!
//! Not modelled: the wheelset's roll rate and vertical velocity (zero in quasi-static
//! sweeps; a roll rate would add `ρ̇ x` to `Ω`).

use super::CreepError;
use nalgebra::{Rotation3, Vector3};

/// The motion of a wheelset at one instant (track frame: x forward, y left, z up).
///
/// # Units
///
/// mm/s, rad/s, rad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// Forward speed `V` of the wheelset's centre, mm/s, positive.
    pub speed_mm_s: f64,
    /// Pitch rate `ω` about the axle, rad/s, positive rolling forward ([`Motion::free_rolling`]:
    /// `V / r_mean`).
    pub pitch_rate_rad_s: f64,
    /// Lateral velocity `ẏ` of the wheelset's centre, mm/s, positive to the left.
    pub lateral_velocity_mm_s: f64,
    /// Roll of the wheelset about x, rad (positive lifts the left wheel).
    pub roll_rad: f64,
    /// Yaw of the wheelset about its own vertical axis, rad (positive turns its forward axis
    /// to the left).
    pub yaw_rad: f64,
    /// Yaw rate about the wheelset's own vertical axis, rad/s.
    pub yaw_rate_rad_s: f64,
}

impl Motion {
    /// A free-rolling wheelset at speed `V` on a straight track: pitch rate `V / r_mean`
    /// with `r_mean` the mean rolling radius of its two wheels, no lateral or yaw velocity,
    /// no roll or yaw. Set the other fields to change that.
    ///
    /// # Units
    ///
    /// `speed_mm_s` in mm/s, `mean_rolling_radius_mm` in mm.
    ///
    /// # Example
    ///
    /// ```
    /// use wheelrail::creep::creepage::Motion;
    /// let m = Motion::free_rolling(2000.0, 460.0);
    /// assert!((m.pitch_rate_rad_s - 2000.0 / 460.0).abs() < 1e-15);
    /// ```
    pub fn free_rolling(speed_mm_s: f64, mean_rolling_radius_mm: f64) -> Motion {
        Motion {
            speed_mm_s,
            pitch_rate_rad_s: speed_mm_s / mean_rolling_radius_mm,
            lateral_velocity_mm_s: 0.0,
            roll_rad: 0.0,
            yaw_rad: 0.0,
            yaw_rate_rad_s: 0.0,
        }
    }

    /// The wheelset's orientation `R = Rx(roll) · Rz(yaw)` (module docs).
    fn orientation(&self) -> Rotation3<f64> {
        Rotation3::from_axis_angle(&Vector3::x_axis(), self.roll_rad)
            * Rotation3::from_axis_angle(&Vector3::z_axis(), self.yaw_rad)
    }
}

/// Where a patch touches the wheel, in the wheelset's own frame, and the patch's contact
/// angle in the track frame (module docs).
///
/// # Units
///
/// mm, rad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPoint {
    /// Lead `x_w` of the contact point along the wheelset's forward axis, ahead of the axle
    /// positive, mm.
    pub lead_mm: f64,
    /// Lateral position `y_w` along the axle from the wheelset's centre, mm (the left wheel
    /// near +750, the right one near -750 on standard gauge).
    pub lateral_mm: f64,
    /// Rolling radius `r`: the contact point's distance from the axle, mm.
    pub rolling_radius_mm: f64,
    /// Contact angle `δ` in the track frame, rad: the rotation about x from track z to the
    /// patch normal (module docs), within `(-π/2, π/2)`.
    pub contact_angle_rad: f64,
}

/// The creepages of one patch in its contact frame (module docs): the velocity of the rail
/// relative to the wheel over the rolling speed.
///
/// # Units
///
/// `xi`, `eta` dimensionless, `phi_per_mm` in 1/mm.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Creepages {
    /// Longitudinal creepage `ξ` (along `t_x`, the rail).
    pub xi: f64,
    /// Lateral creepage `η` (along `t_y`, in the tangent plane).
    pub eta: f64,
    /// Spin creepage `φ` (about the normal `n`, out of the rail), 1/mm.
    pub phi_per_mm: f64,
}

/// The creepages of the patch at `point` of a wheelset moving as `motion` (module docs).
///
/// # Units
///
/// As on [`Motion`] and [`ContactPoint`]; returns ξ, η dimensionless and φ in 1/mm.
///
/// # Errors
///
/// [`CreepError::NonFinite`] for a NaN or infinite input, [`CreepError::NonPositiveSpeed`]
/// unless `V > 0`, [`CreepError::NoRolling`] unless the rolling speed `V_r > 0` (a wheel
/// spun backwards faster than it runs does not roll), [`CreepError::BadRollingRadius`] unless `r > 0` and `|x_w| < r`,
/// [`CreepError::ContactAngle`] unless `|δ| < π/2`.
///
/// # Example
///
/// ```
/// use wheelrail::creep::creepage::{ContactPoint, Motion, creepages};
/// // A coned tread (δ = 0.05 rad) on a free-rolling wheelset, radius r = 461 mm against
/// // the mean r_m = 460 mm: with the rolling speed V_r = (V + ω r)/2 and ω = V/r_m,
/// // ξ = 2 (r - r_m)/(r + r_m), η = 0, φ = 2 sin δ/(r + r_m).
/// let point = ContactPoint {
///     lead_mm: 0.0,
///     lateral_mm: 750.0,
///     rolling_radius_mm: 461.0,
///     contact_angle_rad: 0.05,
/// };
/// let c = creepages(&Motion::free_rolling(10_000.0, 460.0), &point)?;
/// assert!((c.xi - 2.0 / 921.0).abs() < 1e-15);
/// assert!(c.eta.abs() < 1e-15);
/// assert!((c.phi_per_mm - 2.0 * 0.05_f64.sin() / 921.0).abs() < 1e-15);
/// # Ok::<(), wheelrail::creep::CreepError>(())
/// ```
pub fn creepages(motion: &Motion, point: &ContactPoint) -> Result<Creepages, CreepError> {
    for (quantity, value) in [
        ("speed", motion.speed_mm_s),
        ("pitch rate", motion.pitch_rate_rad_s),
        ("lateral velocity", motion.lateral_velocity_mm_s),
        ("roll", motion.roll_rad),
        ("yaw", motion.yaw_rad),
        ("yaw rate", motion.yaw_rate_rad_s),
        ("lead", point.lead_mm),
        ("lateral position", point.lateral_mm),
        ("rolling radius", point.rolling_radius_mm),
        ("contact angle", point.contact_angle_rad),
    ] {
        super::error::finite(quantity, value)?;
    }
    if motion.speed_mm_s <= 0.0 {
        return Err(CreepError::NonPositiveSpeed {
            speed_mm_s: motion.speed_mm_s,
        });
    }
    let (r, x_w) = (point.rolling_radius_mm, point.lead_mm);
    if !(r > 0.0 && x_w.abs() < r) {
        return Err(CreepError::BadRollingRadius {
            rolling_radius_mm: r,
            lead_mm: x_w,
        });
    }
    super::error::check_contact_angle(point.contact_angle_rad)?;

    let rotation = motion.orientation();
    // The contact point in the track frame: r from the axle, x_w ahead of it.
    let height = ((r - x_w) * (r + x_w)).sqrt();
    let d = rotation * Vector3::new(x_w, point.lateral_mm, -height);
    let axle = rotation * Vector3::y();
    let vertical = rotation * Vector3::z();
    let pitch = motion.pitch_rate_rad_s * axle;
    let contact_point = Vector3::new(motion.speed_mm_s, motion.lateral_velocity_mm_s, 0.0)
        + motion.yaw_rate_rad_s * vertical.cross(&d);
    let turning = pitch.cross(&d);
    let v = contact_point + turning;
    let rolling = 0.5 * (contact_point.x - turning.x);
    if !(rolling.is_finite() && rolling > 0.0) {
        return Err(CreepError::NoRolling {
            rolling_speed_mm_s: rolling,
        });
    }
    let (sin_d, cos_d) = point.contact_angle_rad.sin_cos();
    let t_y = Vector3::new(0.0, cos_d, sin_d);
    let n = Vector3::new(0.0, -sin_d, cos_d);
    let omega = pitch + motion.yaw_rate_rad_s * vertical;
    Ok(Creepages {
        xi: -v.x / rolling,
        eta: -v.dot(&t_y) / rolling,
        phi_per_mm: -omega.dot(&n) / rolling,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(lead: f64, lateral: f64, r: f64, delta: f64) -> ContactPoint {
        ContactPoint {
            lead_mm: lead,
            lateral_mm: lateral,
            rolling_radius_mm: r,
            contact_angle_rad: delta,
        }
    }

    #[test]
    fn a_centred_cylinder_rolls_freely() {
        // Cylinder of the mean radius, flat contact: no creepage at all.
        let c = creepages(
            &Motion::free_rolling(20_000.0, 460.0),
            &point(0.0, 750.0, 460.0, 0.0),
        )
        .unwrap();
        assert_eq!((c.xi, c.eta, c.phi_per_mm), (0.0, 0.0, 0.0));
    }

    #[test]
    fn lateral_velocity_and_yaw_give_the_textbook_creepages() {
        // The linearised wheelset's lateral creepage is ψ - ẏ/V (e.g. Wickens 2003, §2.3);
        // exactly, for a flat contact of the mean radius: the wheel's material moves with
        // (V, ẏ, 0) - ω r (cos ψ, sin ψ, 0) with ω r = V, the rolling speed is
        // V_r = (V + V cos ψ)/2, so η = -(ẏ - V sin ψ)/V_r and ξ = -(V - V cos ψ)/V_r.
        let (v, psi): (f64, f64) = (10_000.0, 1e-3);
        let mut m = Motion::free_rolling(v, 460.0);
        m.lateral_velocity_mm_s = 5.0;
        m.yaw_rad = psi;
        let c = creepages(&m, &point(0.0, 750.0, 460.0, 0.0)).unwrap();
        let rolling = 0.5 * v * (1.0 + psi.cos());
        assert!(
            (c.eta + (5.0 - v * psi.sin()) / rolling).abs() < 1e-15,
            "{}",
            c.eta
        );
        assert!((c.xi + v * (1.0 - psi.cos()) / rolling).abs() < 1e-15);
        // Yaw rate ψ̇: the left wheel's contact point (y_w = +750) moves back at ψ̇ y_w with
        // the wheel's material over it, so ξ = ψ̇ y_w / V_r with V_r = V - ψ̇ y_w / 2, and
        // the spin is -ψ̇ / V_r (the wheel turns left about n = z: the rail, relative to it,
        // to the right).
        let mut m = Motion::free_rolling(v, 460.0);
        m.yaw_rate_rad_s = 0.01;
        let c = creepages(&m, &point(0.0, 750.0, 460.0, 0.0)).unwrap();
        let rolling = v - 0.01 * 750.0 / 2.0;
        assert!((c.xi - 0.01 * 750.0 / rolling).abs() < 1e-15);
        assert!((c.phi_per_mm + 0.01 / rolling).abs() < 1e-18);
    }

    #[test]
    fn the_two_wheels_of_a_symmetric_wheelset_mirror() {
        // Left contact angle +δ at y_w = +750, right -δ at -750: ξ equal, η and φ opposite.
        let m = Motion::free_rolling(5000.0, 460.0);
        let left = creepages(&m, &point(0.3, 751.0, 459.0, 0.03)).unwrap();
        let right = creepages(&m, &point(0.3, -751.0, 459.0, -0.03)).unwrap();
        assert!((left.xi - right.xi).abs() < 1e-16);
        assert!((left.eta + right.eta).abs() < 1e-16);
        assert!((left.phi_per_mm + right.phi_per_mm).abs() < 1e-19);
        // A lead on a flange (δ = 1.2): the point x_w ahead of the axle moves down at ω x_w,
        // which the inclined t_y sees: η = ω x_w sin δ / V_r, V_r = (V + ω √(r² - x_w²))/2.
        let c = creepages(&m, &point(15.0, 720.0, 490.0, 1.2)).unwrap();
        let omega = 5000.0 / 460.0;
        let rolling = 0.5 * (5000.0 + omega * (490.0_f64.powi(2) - 225.0).sqrt());
        assert!((c.eta - omega * 15.0 * 1.2_f64.sin() / rolling).abs() < 1e-15);
    }

    #[test]
    fn bad_inputs_are_errors() {
        let m = Motion::free_rolling(5000.0, 460.0);
        let mut stopped = m;
        stopped.speed_mm_s = 0.0;
        assert!(matches!(
            creepages(&stopped, &point(0.0, 750.0, 460.0, 0.0)),
            Err(CreepError::NonPositiveSpeed { .. })
        ));
        let mut backwards = m;
        backwards.pitch_rate_rad_s = -20.0;
        assert!(matches!(
            creepages(&backwards, &point(0.0, 750.0, 460.0, 0.0)),
            Err(CreepError::NoRolling { .. })
        ));
        assert!(matches!(
            creepages(&m, &point(500.0, 750.0, 460.0, 0.0)),
            Err(CreepError::BadRollingRadius { .. })
        ));
        assert!(matches!(
            creepages(&m, &point(0.0, 750.0, 460.0, 1.6)),
            Err(CreepError::ContactAngle { .. })
        ));
        assert!(matches!(
            creepages(&m, &point(f64::NAN, 750.0, 460.0, 0.0)),
            Err(CreepError::NonFinite { .. })
        ));
    }
}
