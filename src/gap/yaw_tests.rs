//! The outline of a yawed wheel against brute force over its surface, its derivatives,
//! cell bounds and inverse, the unyawed and small-angle cases, and the contact of an arc
//! wheel on an inclined plane in closed form.

use super::*;
use crate::profile::Profile;
use crate::track::{Inclination, PlacedWheel, TrackLayout};

fn s1002() -> PlacedWheel {
    let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
    PlacedWheel::place(Profile::s1002(), 460.0, &layout).unwrap()
}

/// The lowest point of the yawed wheel's surface over the lateral position `y` (side
/// frame, relative to the axle), by brute force over the surface: for each angle of a
/// fine grid about the bottom, the circle through `y` found by bisection on the profile
/// coordinate, then the lowest of those refined by golden section in the angle. Its
/// height, the profile coordinate and the x of the point.
fn brute_lowest(wheel: &PlacedWheel, psi: f64, y: f64) -> (f64, f64, f64) {
    let (sn, cs) = psi.sin_cos();
    let (lo, hi) = wheel.profile().domain();
    // Point of the circle at s and angle beta from the bottom (beta > 0 towards -e1).
    let point = |s: f64, beta: f64| {
        let p = wheel.at(s);
        let r = -p.z;
        // P = Yw a + r (-sin beta e1 + cos beta e2).
        let px = -p.y * sn - r * beta.sin() * cs;
        let py = p.y * cs - r * beta.sin() * sn;
        let pz = -r * beta.cos();
        [px, py, pz]
    };
    // At a fixed angle, P_y grows with s (nearly dP_y/ds = cos psi): bisection.
    let at_angle = |beta: f64| -> Option<(f64, f64, f64)> {
        let (mut a, mut b) = (lo, hi);
        if point(a, beta)[1] > y || point(b, beta)[1] < y {
            return None;
        }
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if point(m, beta)[1] < y {
                a = m;
            } else {
                b = m;
            }
        }
        let s = 0.5 * (a + b);
        let p = point(s, beta);
        Some((p[2], s, p[0]))
    };
    let height = |beta: f64| at_angle(beta).map_or(f64::INFINITY, |v| v.0);
    let grid: Vec<f64> = (-400..=400).map(|k| 0.5 * f64::from(k) / 400.0).collect();
    let best = grid
        .iter()
        .copied()
        .min_by(|a, b| height(*a).total_cmp(&height(*b)))
        .unwrap();
    let (mut a, mut b) = (best - 0.5 / 400.0, best + 0.5 / 400.0);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if height(c) < height(d) {
            b = d;
        } else {
            a = c;
        }
    }
    // The height is flat in the angle to its rounding (1e-11 mm over 2e-7 rad): the
    // vertex of the parabola through three heights 1e-5 rad apart places the angle to
    // about 1e-9 rad.
    let (b0, h) = (0.5 * (a + b), 1e-5);
    let (zm, z0, zp) = (height(b0 - h), height(b0), height(b0 + h));
    let vertex = b0 + 0.5 * h * (zm - zp) / (zm - 2.0 * z0 + zp);
    at_angle(vertex).unwrap()
}

/// The closed-form outline is the lowest point of the yawed surface over its lateral
/// position, found by brute force over the surface (module docs): height to 1e-9 mm,
/// profile coordinate and x to 1e-5 mm (the brute force finds the angle of a minimum
/// flat in it to about 1e-9 rad, r times that in x); on the
/// S1002 tread, flange root and flange, at yaws up to 50 mrad either way.
#[test]
fn the_outline_is_the_lowest_point_of_the_surface() {
    let wheel = s1002();
    for psi in [-0.05, -0.024, 0.005, 0.03] {
        let yaw = Yaw::new(1.0, psi, YawModel::Exact);
        for s in [-33.0, -28.0, -20.0, -10.0, 0.0, 12.0, 30.0] {
            let p = yaw.outline(wheel.at(s)).unwrap();
            let (z, s_brute, x_brute) = brute_lowest(&wheel, psi, p.y);
            assert!((z - p.z).abs() < 1e-9, "psi {psi} s {s}: {} vs {z}", p.z);
            assert!((s - s_brute).abs() < 1e-5, "psi {psi} s {s}: {s_brute}");
            let x = yaw.x(&wheel.at(s));
            assert!(
                (x - x_brute).abs() < 1e-5,
                "psi {psi} s {s}: x {x} vs {x_brute}"
            );
        }
    }
}

/// The outline's slope, `dY/ds` and second derivative are its derivatives: central
/// differences of the outline's own points agree to their truncation (1e-7 relative).
#[test]
fn the_outline_derivatives_are_its_differences() {
    let wheel = s1002();
    let yaw = Yaw::new(-1.0, 0.03, YawModel::Exact);
    let h = 1e-4;
    for k in 0..60 {
        let s = -34.0 + 1.1 * f64::from(k);
        let at = |s: f64| yaw.outline(wheel.at(s)).unwrap();
        let (m, p, c) = (at(s - h), at(s + h), at(s));
        let dy = (p.y - m.y) / (2.0 * h);
        let slope = (p.z - m.z) / (p.y - m.y);
        assert!(
            (dy - c.dy_ds).abs() < 1e-7,
            "s {s}: dy/ds {dy} vs {}",
            c.dy_ds
        );
        assert!(
            (slope - c.slope).abs() < 1e-7 * c.slope.abs().max(1.0),
            "s {s}: slope {slope} vs {}",
            c.slope
        );
        let d2 = (p.slope - m.slope) / (p.y - m.y);
        assert!(
            (d2 - c.d2).abs() < 1e-5 * c.d2.abs().max(1e-3),
            "s {s}: d2 {d2} vs {}",
            c.d2
        );
    }
}

/// The profile point recovered from its outline point is the profile point, to rounding
/// (1e-12 relative), on S1002 at yaws up to 50 mrad.
#[test]
fn the_profile_point_of_an_outline_point_is_the_profile_point() {
    let wheel = s1002();
    for psi in [-0.05, 0.01, 0.03] {
        let yaw = Yaw::new(1.0, psi, YawModel::Exact);
        for k in 0..100 {
            let p = wheel.at(-60.0 + 1.1 * f64::from(k));
            let Some(o) = yaw.outline(p) else { continue };
            let back = yaw.profile_point(&o);
            for (a, b) in [
                (back.y, p.y),
                (back.z, p.z),
                (back.slope, p.slope),
                (back.d2, p.d2),
            ] {
                assert!(
                    (a - b).abs() <= 1e-12 * b.abs().max(1.0),
                    "psi {psi}: {back:?} vs {p:?}"
                );
            }
        }
    }
}

/// Without yaw, and in the small-angle form, the outline is the profile point itself.
#[test]
fn no_yaw_keeps_the_profile() {
    let wheel = s1002();
    for yaw in [Yaw::NONE, Yaw::new(1.0, 0.02, YawModel::SmallAngle)] {
        let p = wheel.at(-12.0);
        assert_eq!(yaw.outline(p), Some(p));
    }
    assert_eq!(Yaw::NONE.lead(&wheel.at(-30.0)).abs().to_bits(), 0);
}

/// The lead is `r tan(gamma) tan(psi)` (gamma the unyawed contact angle, the tangent
/// of the profile's slope), and the outline's contact angle `tan(gamma) / (cos psi w)`:
/// on the flange (tan gamma 2.3 near s = -30) at 24 mrad 1.0018 times the profile's.
#[test]
fn lead_and_angle_on_the_flange() {
    let wheel = s1002();
    let p = wheel.at(-30.0);
    let yaw = Yaw::new(1.0, 0.024, YawModel::Exact);
    let r = -p.z;
    assert!((yaw.lead(&p) - r * p.slope * 0.024f64.tan()).abs() < 1e-12);
    let o = yaw.outline(p).unwrap();
    let w = (1.0 - (p.slope * 0.024f64.tan()).powi(2)).sqrt();
    assert!((o.slope - p.slope / (0.024f64.cos() * w)).abs() < 1e-15);
}

/// The cell bounds hold every outline point of dense samples of the cell, on S1002 cells
/// of 0.25 mm and 2 mm at yaws up to 40 mrad.
#[test]
fn outline_cells_hold_their_points() {
    let wheel = s1002();
    let (lo, hi) = wheel.profile().domain();
    let joints = wheel.profile().joints();
    for psi in [-0.04, 0.01, 0.03] {
        let yaw = Yaw::new(1.0, psi, YawModel::Exact);
        for h in [0.25, 2.0] {
            let mut a = lo;
            while a + h <= hi {
                let b = a + h;
                let Some(c) = yaw.outline_cell(wheel.cell(a, b, &joints), h) else {
                    a += 0.7 * h;
                    continue;
                };
                for k in 0..=100 {
                    let s = a + h * f64::from(k) / 100.0;
                    let Some(p) = yaw.outline(wheel.at(s)) else {
                        continue;
                    };
                    assert!(
                        c.z.0 <= p.z && p.z <= c.z.1,
                        "psi {psi} [{a}, {b}] z {}",
                        p.z
                    );
                    assert!(
                        c.d.d1.0 <= -p.slope && -p.slope <= c.d.d1.1,
                        "psi {psi} [{a}, {b}] slope {}: {:?}",
                        -p.slope,
                        c.d.d1
                    );
                    assert!(
                        c.d.d2.0 <= -p.d2 && -p.d2 <= c.d.d2.1,
                        "psi {psi} [{a}, {b}] d2 {}: {:?}",
                        -p.d2,
                        c.d.d2
                    );
                }
                a += 0.7 * h;
            }
        }
    }
}

/// The radius of the arc wheel's profile, mm.
const ARC_RADIUS_MM: f64 = 100.0;
/// The nominal radius of the arc wheel, mm.
const ARC_NOMINAL_RADIUS_MM: f64 = 460.0;
/// The slope of the plane rail's head (falling 1:10 towards the field side).
const PLANE_SLOPE: f64 = -0.1;

/// A wheel whose profile is a circular arc of [`ARC_RADIUS_MM`] about the taping line (a
/// torus) on a rail whose head is a plane of slope [`PLANE_SLOPE`], both as point
/// profiles (the arc sampled every 0.1 mm), on a track without inclination.
fn arc_wheel_on_a_plane() -> crate::track::SidePair {
    use crate::profile::ProfileKind;
    use crate::profile::read::PointProfile;
    use crate::track::{PlacedRail, SidePair};
    let radius = ARC_RADIUS_MM;
    let arc: Vec<[f64; 2]> = (-400..=400)
        .map(|k| {
            let s = 0.1 * f64::from(k);
            [s, (radius * radius - s * s).sqrt() - radius]
        })
        .collect();
    let plane: Vec<[f64; 2]> = (0..=600)
        .map(|k| [0.1 * f64::from(k), -0.01 * f64::from(k)])
        .collect();
    let wheel = PointProfile::from_points(ProfileKind::Wheel, "arc R100", arc).unwrap();
    let rail = PointProfile::from_points(ProfileKind::Rail, "plane 1:10", plane).unwrap();
    let layout = TrackLayout::standard(Inclination::VERTICAL);
    SidePair::new(
        PlacedWheel::place(
            Profile::from_points(wheel, 0.0).unwrap(),
            ARC_NOMINAL_RADIUS_MM,
            &layout,
        )
        .unwrap(),
        PlacedRail::place(
            Profile::from_points(rail, 0.0).unwrap(),
            Inclination::VERTICAL,
            &layout,
        )
        .unwrap(),
    )
}

/// The closed-form contact of [`arc_wheel_on_a_plane`] at roll `phi` (track frame) and
/// yaw `psi`: the profile coordinate `s`, the rolling radius `r` there and the lead.
/// The rail's normal is fixed, so the point of contact follows from the tangent plane
/// alone: the rolled outline's slope `atan(m) + phi` equals the plane's,
/// `m = -q / (cos psi w)` gives the profile slope
/// `q = -M cos psi / sqrt(1 + M^2 sin^2 psi)` (`M = tan(atan(Z') - phi)`), and the arc
/// the point `s = -q R / sqrt(1 + q^2)`, its radius, and the lead `-r q tan psi`.
fn arc_on_plane_contact(phi: f64, psi: f64) -> (f64, f64, f64) {
    let radius = ARC_RADIUS_MM;
    let m = (PLANE_SLOPE.atan() - phi).tan();
    let (sn, cs) = psi.sin_cos();
    let q = -m * cs / (1.0 + m * m * sn * sn).sqrt();
    let s = -q * radius / (1.0 + q * q).sqrt();
    let r = ARC_NOMINAL_RADIUS_MM + (radius * radius - s * s).sqrt() - radius;
    (s, r, -r * q * psi.tan())
}

/// The arc wheel on the plane rail ([`arc_wheel_on_a_plane`]): the gap's minimum lands
/// on the closed-form contact ([`arc_on_plane_contact`]) to the arc's sampling (1e-9 mm
/// in `s`), with its lead (close to `r tan(delta) psi`), at shifts, rolls and yaws up to
/// 30 mrad either way.
#[test]
fn an_arc_wheel_on_a_plane_touches_where_the_tangent_planes_agree() {
    use crate::gap::{PoseBox, Scanned, SideGap, SidePose};
    let pair = arc_wheel_on_a_plane();
    let mut checked = 0;
    for sign in [1.0, -1.0] {
        for psi in [0.01, 0.03, -0.02] {
            let mut side = SideGap::new(&pair, sign);
            let yaw = Yaw::new(sign, psi, YawModel::Exact);
            side.set_yaw(yaw);
            for y_ws in [-4.0, 0.0, 3.0] {
                for roll in [0.0, 2e-3, -1e-3] {
                    let pose = SidePose::yawed(sign, y_ws, roll, psi);
                    let mut basins = Vec::new();
                    side.basins(
                        &pose,
                        &mut PoseBox::default(),
                        &mut Scanned::default(),
                        &mut basins,
                    );
                    let p = basins
                        .iter()
                        .filter_map(|&b| side.minimum(b, None, &pose))
                        .min_by(|a, b| a.g.total_cmp(&b.g))
                        .unwrap();
                    let phi = sign * roll;
                    let (s_exact, r, lead) = arc_on_plane_contact(phi, yaw.psi());
                    let at = format!("sign {sign} psi {psi} y {y_ws} roll {roll}");
                    assert!((p.s - s_exact).abs() < 1e-9, "{at}: s {} vs {s_exact}", p.s);
                    let base = side.wheel().at(p.s);
                    assert!(
                        (yaw.lead(&base) - lead).abs() < 1e-9,
                        "{at}: lead {} vs {lead}",
                        yaw.lead(&base)
                    );
                    // The contact angle in the track frame is the plane's.
                    assert!(
                        (p.wheel.slope.atan() + phi - PLANE_SLOPE.atan()).abs() < 1e-10,
                        "{at}"
                    );
                    // Within a few per mille of the small-angle estimate r tan(delta) psi.
                    let estimate = r * (PLANE_SLOPE.atan() - phi).tan().abs() * yaw.psi();
                    assert!(
                        (lead.abs() - estimate.abs()).abs() <= 2e-3 * estimate.abs(),
                        "{at}"
                    );
                    checked += 1;
                }
            }
        }
    }
    assert_eq!(checked, 54);
}
