//! The yawed wheelset: the Manchester benchmark's case against CONTACT's given results,
//! every wheel-case of it against a brute force over the wheel's surface, and the mirror
//! image of a yaw that grows with the shift.

mod common;

use wheelrail::pipeline;
use wheelrail::rigid::{self, RigidPosition as Position, RigidSweep, SideContact};
use wheelrail::scene::Scene;
use wheelrail::sweep::{Sweep, YawRule};
use wheelrail::track::{Placement, Side};

const SCENE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/reports/manchester_a22/scene.toml"
);

/// The Manchester scene, its placement and its rigid sweep.
fn manchester() -> (Scene, Placement, RigidSweep) {
    let text = std::fs::read_to_string(SCENE).unwrap();
    let dir = std::path::Path::new(SCENE).parent().unwrap();
    let scene = Scene::from_toml(&text, SCENE, dir).unwrap();
    let placement = pipeline::place(&scene).unwrap();
    let sweep = rigid::search(&placement, scene.sweep(), rigid::Solver::default());
    (scene, placement, sweep)
}

/// One of CONTACT's given wheel-cases (`tests/data/contact/manchester_a22_given.csv`).
#[derive(Debug)]
struct Given {
    side: Side,
    /// CONTACT's shift (y to the right): minus wheelrail's.
    y_contact_mm: f64,
    /// Contact reference point along the track (mm).
    x_track_mm: f64,
    /// The lead (mm).
    lead_mm: f64,
    /// Lateral position on the rail profile (mm; left rail + towards the track centre,
    /// right rail + towards the field side, from the top of the inclined rail).
    y_rail_mm: f64,
    /// Contact angle (rad; + left, - right).
    delta_rad: f64,
}

fn given() -> Vec<Given> {
    common::manchester_given()
        .into_iter()
        .map(|g| Given {
            side: g.side,
            y_contact_mm: g.num("y_ws_mm"),
            x_track_mm: g.num("XCP_tr"),
            lead_mm: g.num("XCP_w"),
            y_rail_mm: g.num("YCP_r"),
            delta_rad: g.num("DELTCP_tr"),
        })
        .collect()
}

/// The contact's lateral position on its rail as CONTACT reports it: from the top of the
/// inclined rail, + towards the field side on the right rail and towards the track centre
/// on the left (wheelrail's side frame grows towards the field side on both).
fn rail_position(placement: &Placement, side: Side, c: &SideContact) -> f64 {
    let from_top = c.y.abs() - placement.side(side).rail().top()[0];
    match side {
        Side::Left => -from_top,
        Side::Right => from_top,
    }
}

/// Flange contact, for comparing with CONTACT: a contact angle above 0.7 rad (its tread
/// and flange-root contacts stay below 0.42 rad in, its flange contacts above 0.8).
const FLANGE_RAD: f64 = 0.7;

/// The six wheel-cases CONTACT's results are given for. CONTACT reports the centre of its
/// elastic patch, the rigid point differs from it by (measured): lead 0.0015 mm on the
/// tread and 0.68 % (0.097 mm) at the flange, contact angle 0.0047 rad, position along the
/// track 0.0026 mm on the tread and 0.097 mm at the flange (the lead's difference), on the
/// rail 1.38 mm at the centred wheelset's wide patch and 0.133 mm elsewhere. Bounds: about
/// twice these (lead max(0.003 mm, 1.4 %), angle 0.01 rad, x 0.006 mm on the tread and
/// 0.2 mm at the flange), the rail's 1.5 and 0.15 mm as they were (1.1 times). Flange
/// contact on the same cases. Prints the differences.
#[test]
fn the_given_wheel_cases_agree_with_contact() {
    let (_, placement, sweep) = manchester();
    for g in given() {
        let y_ws = -g.y_contact_mm;
        let p = sweep
            .positions()
            .iter()
            .find(|p| (p.y_ws - y_ws).abs() < 1e-9)
            .unwrap();
        let c = p.side(g.side).unwrap();
        let rail = rail_position(&placement, g.side, c);
        let (d_lead, d_x, d_rail, d_gamma) = (
            c.lead - g.lead_mm,
            c.x - g.x_track_mm,
            rail - g.y_rail_mm,
            c.gamma - g.delta_rad.abs(),
        );
        eprintln!(
            "{:5} y_ws {y_ws:5.1}: lead {:8.4} vs {:8.4} ({d_lead:+.4}), x {:8.4} vs {:8.4} ({d_x:+.4}), on the rail {:8.3} vs {:8.3} ({d_rail:+.3}), angle {:.4} vs {:.4} ({d_gamma:+.4})",
            g.side.name(),
            c.lead,
            g.lead_mm,
            c.x,
            g.x_track_mm,
            rail,
            g.y_rail_mm,
            c.gamma,
            g.delta_rad.abs()
        );
        let at = format!("{} at y_ws = {y_ws}", g.side.name());
        assert!(
            d_lead.abs() <= 0.003f64.max(0.014 * g.lead_mm.abs()),
            "{at}: lead"
        );
        assert!(d_gamma.abs() <= 0.01, "{at}: contact angle");
        assert_eq!(
            c.gamma > FLANGE_RAD,
            g.delta_rad.abs() > FLANGE_RAD,
            "{at}: flange contact"
        );
        let x_tol = if c.gamma > FLANGE_RAD { 0.2 } else { 0.006 };
        assert!(d_x.abs() <= x_tol, "{at}: x");
        let rail_tol = if y_ws == 0.0 { 1.5 } else { 0.15 };
        assert!(d_rail.abs() <= rail_tol, "{at}: position on the rail");
    }
}

/// The lowest gap between the yawed, rolled and lifted surface of revolution and the rail
/// below it over a patch of the wheel's surface, by brute force without the outline's
/// closed forms: for each profile coordinate `s` (a grid), the angle `beta` about the
/// bottom of its circle (grid, then golden section); `(gap, s, beta)`.
fn brute_lowest(
    placement: &Placement,
    side: Side,
    p: &Position,
    (s_lo, s_hi, ds): (f64, f64, f64),
) -> (f64, f64, f64) {
    let pair = placement.side(side);
    let sign = side_sign(side);
    let (delta, phi, psi) = (sign * p.y_ws, sign * p.roll, sign * p.yaw);
    let (sp, cp) = psi.sin_cos();
    let (sr, cr) = phi.sin_cos();
    let gap = |s: f64, beta: f64| -> f64 {
        let w = pair.wheel().at(s);
        let (yw, r) = (w.y, -w.z);
        // P = Yw a + r (-sin beta e1 + cos beta e2), a = (-sin psi, cos psi, 0),
        // e1 = (cos psi, sin psi, 0), e2 = (0, 0, -1); then rolled about x and shifted.
        let py = yw * cp - r * beta.sin() * sp;
        let pz = -r * beta.cos();
        let y = delta + cr * py - sr * pz;
        let z = p.axle_height + sr * py + cr * pz;
        pair.rail().at(y).map_or(f64::INFINITY, |rail| z - rail.z)
    };
    let lowest_at = |s: f64| -> (f64, f64) {
        let grid = (-300..=300).map(|k| 1e-3 * f64::from(k));
        let b0 = grid
            .min_by(|a, b| gap(s, *a).total_cmp(&gap(s, *b)))
            .unwrap();
        let (mut a, mut b) = (b0 - 1e-3, b0 + 1e-3);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..60 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if gap(s, c) < gap(s, d) {
                b = d;
            } else {
                a = c;
            }
        }
        let beta = 0.5 * (a + b);
        (gap(s, beta), beta)
    };
    let n = ((s_hi - s_lo) / ds).round() as usize;
    (0..=n)
        .map(|i| {
            let s = s_lo + (s_hi - s_lo) * i as f64 / n.max(1) as f64;
            let (g, beta) = lowest_at(s);
            (g, s, beta)
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap()
}

fn side_sign(side: Side) -> f64 {
    match side {
        Side::Left => 1.0,
        Side::Right => -1.0,
    }
}

/// All 42 wheel-cases of A-2.2 (CONTACT's results are given for 6 of them): by brute force
/// over the yawed, rolled wheel's surface (no closed form of the outline), no point of
/// either wheel lies below its rail by more than 2e-12 mm (measured 7.4e-13 mm: the golden
/// section's resolution), and the surface point the search reports (its profile coordinate
/// and lead, `lead = -r sin(beta)` on its circle) touches the rail to 2e-12 mm (measured
/// 7.4e-13 mm) at the reported x; the brute force's lowest point lies within half its
/// 0.01 mm grid of it in `s` (measured: on the grid point at the reported `s`), and within
/// 3e-5 mm in lead (measured 1.2e-5 mm: the minimum is flat along the circle).
#[test]
fn every_wheel_case_touches_where_a_brute_force_over_the_surface_finds_it() {
    let (_, placement, sweep) = manchester();
    let mut cases = 0;
    for p in sweep.positions() {
        assert_eq!(p.stop, rigid::Stop::Converged, "y_ws {}", p.y_ws);
        for side in [Side::Left, Side::Right] {
            let c = p.side(side).unwrap();
            let at = format!("{} at y_ws = {}", side.name(), p.y_ws);
            let (lo, hi) = placement.side(side).wheel().profile().domain();
            let global = brute_lowest(&placement, side, p, (lo.max(-40.0), hi.min(40.0), 0.25));
            let near = brute_lowest(&placement, side, p, (c.s - 1.0, c.s + 1.0, 0.01));
            let lowest = global.0.min(near.0);
            assert!(lowest >= -2e-12, "{at}: a point {lowest} mm below the rail");
            // The reported point on the surface.
            let pair = placement.side(side);
            let w = pair.wheel().at(c.s);
            let r = -w.z;
            let beta = (-c.lead / r).asin();
            let sign = side_sign(side);
            let psi = sign * p.yaw;
            let x = -w.y * psi.sin() - r * beta.sin() * psi.cos();
            // The same formula as the search's: measured equal; 1e-12 mm allows a rounding.
            assert!((x - c.x).abs() < 1e-12, "{at}: x {x} vs {}", c.x);
            let (_, s_near, beta_near) = near;
            let one = brute_lowest(&placement, side, p, (c.s, c.s, 1.0));
            assert!(
                one.0.abs() < 2e-12,
                "{at}: the reported point is {} mm off the rail",
                one.0
            );
            assert!((one.2 - beta).abs() * r < 3e-5, "{at}: lead");
            assert!((s_near - c.s).abs() < 0.005, "{at}: s {s_near} vs {}", c.s);
            assert!(
                (-r * beta_near.sin() - c.lead).abs() < 3e-5,
                "{at}: lead {} vs {}",
                -r * beta_near.sin(),
                c.lead
            );
            cases += 1;
        }
    }
    assert_eq!(cases, 42);
}

/// A yaw that grows with the shift (odd in it) keeps a symmetric wheelset's sweep
/// symmetric: the positions before the middle are the images of those after it (wheels
/// swapped, roll, yaw and lateral positions negated, lead and x kept), to the solver's
/// accuracy against the same sweep solved at every position. Measured: s 3.4e-11 mm, roll
/// 1.4e-14 rad, lead and x 2.7e-11 mm; bounds about twice these.
#[test]
fn an_odd_yaw_mirrors_the_half_sweep() {
    let scene = Scene::from_toml("", "test", ".".as_ref()).unwrap();
    let placement = pipeline::place(&scene).unwrap();
    let sweep = Sweep::range(-8.0, 8.0, 0.25)
        .unwrap()
        .with_yaw(YawRule::new(0.0, 2.4e-3, Default::default()))
        .unwrap();
    let mirrored = rigid::search(&placement, &sweep, rigid::Solver::default());
    let solved = rigid::search(
        &placement.clone().without_mirroring(),
        &sweep,
        rigid::Solver::default(),
    );
    let (mut lead, mut roll) = (0.0f64, 0.0f64);
    for (m, p) in mirrored.positions().iter().zip(solved.positions()) {
        assert_eq!(m.yaw.to_bits(), p.yaw.to_bits());
        roll = roll.max((m.roll - p.roll).abs());
        for k in 0..2 {
            let (a, b) = (m.contact[k].unwrap(), p.contact[k].unwrap());
            lead = lead.max((a.lead - b.lead).abs()).max((a.x - b.x).abs());
            assert!(
                (a.s - b.s).abs() < 7e-11,
                "y {}: s {} vs {}",
                p.y_ws,
                a.s,
                b.s
            );
        }
    }
    eprintln!("largest differences: roll {roll:e} rad, lead and x {lead:e} mm");
    assert!(roll < 3e-14 && lead < 6e-11, "roll {roll:e} lead {lead:e}");
    assert_eq!(mirrored.jumps().len(), solved.jumps().len());
}
