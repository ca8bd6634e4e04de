//! Rigid contact search: invariants, an independent brute-force reference, and the known
//! features of S1002 on UIC60 1:40 (from the project's reference notes on the contact search,
//! outside this repository; each value is restated where it is checked).

use proptest::prelude::*;
use std::path::Path;
use std::sync::OnceLock;
use wheelrail::gap::{SideGap, SidePose};
use wheelrail::rigid::{self, Solver, Stop};
use wheelrail::scene::Scene;
use wheelrail::sweep::Sweep;
use wheelrail::track::{Placement, Side};

fn paper_placement() -> &'static Placement {
    static P: OnceLock<Placement> = OnceLock::new();
    P.get_or_init(|| {
        let scene = Scene::from_toml("", "paper defaults", Path::new(".")).unwrap();
        wheelrail::pipeline::place(&scene).unwrap()
    })
}

/// The paper placement with the mirror switched off: `-y` solved, not mirrored from `y`.
fn paper_placement_unmirrored() -> &'static Placement {
    static P: OnceLock<Placement> = OnceLock::new();
    P.get_or_init(|| paper_placement().clone().without_mirroring())
}

fn paper_sweep(solver: Solver) -> &'static rigid::RigidSweep {
    static D: OnceLock<rigid::RigidSweep> = OnceLock::new();
    static P: OnceLock<rigid::RigidSweep> = OnceLock::new();
    let sweep: Vec<f64> = (0..=300).map(|i| -15.0 + 0.1 * f64::from(i)).collect();
    let cell = if matches!(solver, Solver::Default(_)) {
        &D
    } else {
        &P
    };
    cell.get_or_init(|| {
        rigid::search(
            paper_placement(),
            &Sweep::from_slice(&sweep).unwrap(),
            solver,
        )
    })
}

/// The smallest gap of one side over wheel points every `step` mm, at a solved position.
fn min_gap(side: Side, pos: &rigid::RigidPosition, step: f64) -> f64 {
    let placement = paper_placement();
    let sign = side.sign();
    let gap = SideGap::new(placement.side(side), sign);
    let pose = SidePose::new(sign, pos.y_ws, pos.roll);
    let n = (130.0 / step).round() as usize;
    (0..=n)
        .filter_map(|i| gap.at(-70.0 + 130.0 * i as f64 / n as f64, &pose))
        .map(|p| p.g + pos.axle_height)
        .fold(f64::INFINITY, f64::min)
}

/// How far the contact point of `side` moves per radian of roll at a solved position
/// (mm/rad), `|d g'/d phi| / g''` at the contact (implicit function theorem on `g'(s) = 0`,
/// the roll derivative by central differences of `g'` over 1e-6 rad), and `g''` there.
fn contact_roll_sensitivity(pos: &rigid::RigidPosition, side: Side) -> (f64, f64) {
    let sign = side.sign();
    let gap = SideGap::new(paper_placement().side(side), sign);
    let s = pos.side(side).unwrap().s;
    let at = |roll: f64| gap.at(s, &SidePose::new(sign, pos.y_ws, roll)).unwrap();
    let h = 1e-6;
    let d_dg = (at(pos.roll + h).dg - at(pos.roll - h).dg) / (2.0 * h);
    let ddg = at(pos.roll).ddg;
    ((d_dg / ddg).abs(), ddg)
}

#[test]
fn every_position_converges_touches_and_does_not_penetrate() {
    // Default solver: residual <= 1e-9 mm and gaps >= -1e-9 mm over wheel points every
    // 0.01 mm (the requirements; measured: residual at most 9.3e-12 mm, no gap
    // below +4e-12 mm), and the smallest gap is 0 to within the 0.01 mm sampling: a point
    // of the sampled wheel lies within 0.005 mm of the contact point, where the gap grows
    // quadratically (1/2 * 0.2 1/mm * 0.005^2 = 2.5e-6 mm on the tread) or, at a flank
    // contact with a slope mismatch, faster. Measured at most 2.1e-5 mm; bound 5e-5 mm.
    for pos in paper_sweep(Solver::default()).positions() {
        assert_eq!(pos.stop, Stop::Converged, "y_ws = {}", pos.y_ws);
        assert!(
            pos.residual <= 1e-9,
            "y_ws = {}: residual {}",
            pos.y_ws,
            pos.residual
        );
        for side in [Side::Left, Side::Right] {
            let g = min_gap(side, pos, 0.01);
            assert!(
                g >= -1e-9,
                "{side:?} penetrates by {g} at y_ws = {}",
                pos.y_ws
            );
            assert!(
                g <= 5e-5,
                "{side:?} lifts off by {g} at y_ws = {}",
                pos.y_ws
            );
        }
    }
}

#[test]
fn paper_solver_touches_within_its_tolerance() {
    // The paper stops at |d_l - d_r| < 1e-4 mm on its tables (wheel and rail every 0.1 mm,
    // rail interpolated linearly). The interpolation errs vertically by Z'' h^2 / 8 with
    // Z'' = kappa (1 + tan^2 gamma)^1.5: 1e-4 mm on the crown, but 1/13 * 25 * 0.01 / 8 =
    // 2.4e-3 mm on the 70 degree flank. Over its own table points, evaluated exactly, the
    // gaps therefore lie within 3e-3 mm of zero: a measured property of the method
    // (measured at most 1.8e-3 mm).
    for pos in paper_sweep(Solver::Paper).positions() {
        assert_eq!(pos.stop, Stop::Converged, "y_ws = {}", pos.y_ws);
        for side in [Side::Left, Side::Right] {
            let g = min_gap(side, pos, 0.1);
            assert!(g.abs() <= 3e-3, "{side:?} gap {g} at y_ws = {}", pos.y_ws);
        }
    }
}

/// Independent reference: dense scan of the gap every 0.002 mm refined by bisection on the
/// sign of its derivative, and bisection on the roll over [-0.05, 0.05] rad to 1e-15 rad.
fn brute_force(y_ws: f64) -> (f64, [f64; 2]) {
    let placement = paper_placement();
    let sides = [
        SideGap::new(placement.left(), 1.0),
        SideGap::new(placement.right(), -1.0),
    ];
    let min = |k: usize, roll: f64| -> (f64, f64) {
        let sign = sides[k].sign;
        let pose = SidePose::new(sign, y_ws, roll);
        let g = |s: f64| sides[k].at(s, &pose).map_or(f64::INFINITY, |p| p.g);
        let step = 0.002;
        let mut best = (f64::INFINITY, 0.0);
        for i in 0..=65_000 {
            let s = -70.0 + step * f64::from(i);
            let v = g(s);
            if v < best.0 {
                best = (v, s);
            }
        }
        // Refine on the sign of dg/ds (comparing gap values would resolve s only to
        // sqrt(2 * 1e-13 / g'') ~ 1e-5 mm on the flat tread: |g| is about 460 mm).
        let dg = |s: f64| sides[k].at(s, &pose).map_or(0.0, |p| p.dg);
        let (mut a, mut b) = (best.1 - step, best.1 + step);
        if dg(a) < 0.0 && dg(b) > 0.0 {
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if dg(m) > 0.0 {
                    b = m;
                } else {
                    a = m;
                }
            }
        } else {
            (a, b) = (best.1, best.1);
        }
        let s = 0.5 * (a + b);
        (g(s).min(best.0), s)
    };
    let f = |roll: f64| min(0, roll).0 - min(1, roll).0;
    let (mut lo, mut hi) = (-0.05, 0.05);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let roll = 0.5 * (lo + hi);
    (roll, [min(0, roll).1, min(1, roll).1])
}

#[test]
fn default_solver_agrees_with_brute_force() {
    // Positions away from the contact jumps (0.226, 4.992, 6.26 mm) where the contact point
    // is well defined. The requirements: 1e-6 mm in contact position, 1e-9 rad in
    // roll (measured at most 8.3e-12 mm and 2.2e-15 rad: the rounding of g' over g'' on
    // the flat tread).
    let shifts = [
        -12.3, -7.7, -3.3, -1.05, 0.0, 0.55, 2.7, 4.4, 5.6, 8.9, 14.2,
    ];
    let solved = rigid::search(
        paper_placement(),
        &Sweep::from_slice(&shifts).unwrap(),
        Solver::default(),
    );
    for pos in solved.positions() {
        let (roll, s) = brute_force(pos.y_ws);
        assert!(
            (pos.roll - roll).abs() < 1e-9,
            "y_ws {}: roll {} vs {roll}",
            pos.y_ws,
            pos.roll
        );
        for (k, side) in [Side::Left, Side::Right].into_iter().enumerate() {
            let c = pos.side(side).unwrap();
            assert!(
                (c.s - s[k]).abs() < 1e-6,
                "y_ws {} {side:?}: s {} vs {}",
                pos.y_ws,
                c.s,
                s[k]
            );
        }
    }
}

#[test]
fn known_features_of_s1002_on_uic60_at_1_in_40() {
    let sweep = paper_sweep(Solver::default());
    let left_jumps: Vec<_> = sweep
        .jumps()
        .iter()
        .filter(|j| j.side == Side::Left)
        .collect();
    // Near-centre jump of the left contact point within the first half millimetre.
    assert!(
        left_jumps.iter().any(|j| j.y_from > 0.0 && j.y_to < 0.5),
        "{left_jumps:?}"
    );
    // A jump to the flange root (s < -25 mm) near y_ws = 5 mm (4.5 to 5.5).
    assert!(
        left_jumps
            .iter()
            .any(|j| (4.5..5.5).contains(&j.y_from) && j.s_to < -25.0),
        "{left_jumps:?}"
    );
    // Jumps are refined to 1e-4 mm.
    for j in sweep.jumps() {
        assert!(j.y_to - j.y_from <= 1.0001e-4, "{j:?}");
    }
    // Flange contact (left contact angle above 1.1 rad) starts between 6 and 7 mm ...
    let onset = sweep
        .positions()
        .iter()
        .find(|p| p.side(Side::Left).unwrap().gamma > 1.1)
        .expect("flange contact within the sweep");
    assert!((6.0..7.0).contains(&onset.y_ws), "onset at {}", onset.y_ws);
    // ... and the rolling radius difference exceeds 10 mm within half a millimetre of it.
    let dr =
        |p: &rigid::RigidPosition| p.side(Side::Left).unwrap().r - p.side(Side::Right).unwrap().r;
    assert!(
        sweep
            .positions()
            .iter()
            .any(|p| p.y_ws <= onset.y_ws + 0.5 && dr(p) > 10.0),
        "delta_r stays below 10 mm after onset"
    );
    // Below the onset the roll is at most 1e-3 rad; beyond it, an order of magnitude more.
    let roll_at = |y: f64| {
        sweep
            .positions()
            .iter()
            .find(|p| (p.y_ws - y).abs() < 1e-9)
            .unwrap()
            .roll
    };
    assert!(roll_at(6.0) < 1e-3 && roll_at(8.0) > 5e-3);
}

#[test]
fn paper_solver_error_against_default_is_bounded() {
    // Measured, not assumed: the paper's tabulated minimum puts the contact point on its
    // 0.1 mm table, so away from the jumps its error is at most half a table step (0.05 mm)
    // plus the motion its 1e-4 mm residual allows: measured 0.0498 mm, and 7.2e-6 rad in
    // roll. Bounds about twice and 1.4 times these (the roll's bound was set first).
    let d = paper_sweep(Solver::default());
    let p = paper_sweep(Solver::Paper);
    let near_jump = |y: f64| d.jumps().iter().any(|j| (y - j.y_from).abs() < 0.15);
    let mut worst_s: f64 = 0.0;
    let mut worst_roll: f64 = 0.0;
    let mut compared = 0;
    for (a, b) in d.positions().iter().zip(p.positions()) {
        if near_jump(a.y_ws) {
            continue;
        }
        compared += 1;
        worst_roll = worst_roll.max((a.roll - b.roll).abs());
        for side in [Side::Left, Side::Right] {
            worst_s = worst_s.max((a.side(side).unwrap().s - b.side(side).unwrap().s).abs());
        }
    }
    println!(
        "paper vs default: max |ds| = {worst_s:.3e} mm, max |droll| = {worst_roll:.3e} rad over {compared} positions"
    );
    // Measured: 283 of the 301 positions lie away from the jumps.
    assert!(compared >= 250, "{compared} positions compared");
    assert!(worst_s < 0.1, "{worst_s}");
    assert!(worst_roll < 1e-5, "{worst_roll}");
    assert!(
        worst_s > 1e-3,
        "the paper solver cannot be exact on a 0.1 mm table"
    );
}

/// Checks that the solutions at `-y` and `+y` of the symmetric paper scene mirror each
/// other, both solved (the mirror switched off: a mirror-symmetric placement would mirror
/// the solution at `y` onto `-y`).
fn assert_mirrored(y: f64) -> Result<(), TestCaseError> {
    // A symmetric scene: results at -y equal those at +y with sides swapped and roll
    // flipped (both solves converge to 1e-11 mm residual). Over 1200 draws (three seeds):
    // rolls at most 3.5e-14 rad apart, axle heights 2.4e-11 mm, contact angles 3.2e-14 rad,
    // contact positions 1.7e-11 mm; bounds about twice these (positions 4e-11 mm), except
    // where a near-conformal contact makes its position ill-conditioned. The contact point
    // is the root of `g'`, and two things move it:
    // - the roll: the two rolls are one root found from different starts and differ by the
    //   solver's tolerance (about 1e-14 rad); the point moves by `contact_roll_sensitivity`
    //   per radian;
    // - the rounding of `g'` itself, about 2e-12 (measured at the case below: `g'` changes
    //   by 2.4e-12 between points 1.44e-9 mm apart where `g''` predicts 4.1e-12), which
    //   moves the root by 2e-12 / g''.
    // At y = 6.2546749581041965 mm the flange contact (relative curvature 1.5e-3 1/mm,
    // g'' = 2.8e-3 1/mm) moves 2.5e4 mm per radian, and the two solves' contacts differ by
    // 1.44e-9 mm for rolls 1.6e-14 rad apart: 4.1e-10 mm from the roll, 7e-10 mm per
    // side from the rounding. Positions are compared within 4e-11 mm plus twice both (over
    // the draws, no position differed by more than 1.1e-11 mm beyond twice both).
    let s = rigid::search(
        paper_placement_unmirrored(),
        &Sweep::from_slice(&[-y, y]).unwrap(),
        Solver::default(),
    );
    let (m, p) = (&s.positions()[0], &s.positions()[1]);
    let d_roll = (m.roll + p.roll).abs();
    prop_assert!(d_roll < 1e-13);
    prop_assert!((m.axle_height - p.axle_height).abs() < 5e-11);
    let (ml, mr) = (m.side(Side::Left).unwrap(), m.side(Side::Right).unwrap());
    let (pl, pr) = (p.side(Side::Left).unwrap(), p.side(Side::Right).unwrap());
    let tol = |a: Side, b: Side| {
        let ((k_a, dd_a), (k_b, dd_b)) = (
            contact_roll_sensitivity(m, a),
            contact_roll_sensitivity(p, b),
        );
        4e-11 + 2.0 * k_a.max(k_b) * d_roll + 2.0 * 2e-12 / dd_a.min(dd_b)
    };
    let (tol_lr, tol_rl) = (tol(Side::Left, Side::Right), tol(Side::Right, Side::Left));
    prop_assert!(
        (ml.s - pr.s).abs() < tol_lr,
        "{} {} (tolerance {tol_lr:e})",
        ml.s,
        pr.s
    );
    prop_assert!(
        (mr.s - pl.s).abs() < tol_rl,
        "{} {} (tolerance {tol_rl:e})",
        mr.s,
        pl.s
    );
    // dY/ds = cos(phi) + sin(phi) F' is within 1e-3 of 1 here.
    prop_assert!((ml.y + pr.y).abs() < tol_lr);
    prop_assert!((ml.gamma - pr.gamma).abs() < 1e-13);
    // dr/ds is the wheel's slope, at most 1 where contact is possible (45 degrees):
    // each difference is within its side's tolerance.
    prop_assert!(((ml.r - mr.r) + (pl.r - pr.r)).abs() < tol_lr + tol_rl);
    Ok(())
}

#[test]
fn mirror_symmetry_holds_at_a_near_conformal_flange_contact() {
    // The draw that failed a fixed 1e-9 mm tolerance (see `assert_mirrored`).
    assert_mirrored(6.2546749581041965).unwrap();
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn mirror_symmetry(y in 0.0f64..15.0) {
        assert_mirrored(y)?;
    }
}

/// The paper placement rebuilt from the analytic profiles sampled every `step` mm, written as
/// a CSV profile (every digit of each point), read back through the CSV reader and fitted
/// with an interpolating spline.
fn resampled_placement(step: f64) -> Placement {
    use wheelrail::profile::read::{ProfileFormat, parse_str};
    use wheelrail::profile::{Profile, ProfileKind};
    use wheelrail::track::{Inclination, PlacedRail, PlacedWheel, SidePair};
    let sampled = |p: Profile| {
        let header = match p.kind() {
            ProfileKind::Wheel => "s_mm,F_mm",
            ProfileKind::Rail => "y_mm,z_mm",
        };
        let text: String = std::iter::once(header.to_string())
            .chain(
                p.sample(step)
                    .iter()
                    .map(|r| format!("{:?},{:?}", r[0], r[1])),
            )
            .map(|line| line + "\n")
            .collect();
        let points = parse_str(&text, ProfileFormat::Csv, p.kind(), "resampled").unwrap();
        Profile::from_points(points, 0.0).unwrap()
    };
    let layout = paper_placement().layout().clone();
    let pair = || {
        SidePair::new(
            PlacedWheel::place(sampled(Profile::s1002()), 460.0, &layout).unwrap(),
            PlacedRail::place(sampled(Profile::uic60e1()), Inclination::VERTICAL, &layout).unwrap(),
        )
    };
    Placement::new(layout.clone(), pair(), pair()).unwrap()
}

#[test]
fn contact_positions_converge_with_profile_resolution() {
    // Analytic profiles against the same profiles sampled every 0.1 mm (interpolating
    // spline), over the paper sweep, away from the jumps (0.3 mm either side) where a
    // 1e-7 mm change of the gap moves the jump itself. The contact position error is the
    // slope error of the spline (5e-6 at 0.1 mm) over the relative curvature of the gap:
    // about 1e-3 mm on the tread, more where the gap is flat (conformal flange root).
    // Measured: 2.5e-3 mm in position; 3.6e-6 rad in roll, growing towards the flange onset
    // where the roll changes by 7e-3 rad per mm of shift (ill-conditioned there). Bounds
    // twice and 1.4 times these.
    let sweep: Vec<f64> = (0..=300).map(|i| -15.0 + 0.1 * f64::from(i)).collect();
    let exact = paper_sweep(Solver::default());
    let resampled = rigid::search(
        &resampled_placement(0.1),
        &Sweep::from_slice(&sweep).unwrap(),
        Solver::default(),
    );
    let near_jump = |y: f64| exact.jumps().iter().any(|j| (y - j.y_from).abs() < 0.3);
    let mut worst_s: f64 = 0.0;
    let mut worst_roll: f64 = 0.0;
    let mut compared = 0;
    for (a, b) in exact.positions().iter().zip(resampled.positions()) {
        assert_eq!(b.stop, Stop::Converged, "y_ws = {}", b.y_ws);
        if near_jump(a.y_ws) {
            continue;
        }
        compared += 1;
        worst_roll = worst_roll.max((a.roll - b.roll).abs());
        for side in [Side::Left, Side::Right] {
            worst_s = worst_s.max((a.side(side).unwrap().s - b.side(side).unwrap().s).abs());
        }
    }
    println!(
        "analytic vs 0.1 mm resampled: max |ds| = {worst_s:.2e} mm, max |droll| = {worst_roll:.2e} rad over {compared} positions"
    );
    // Measured: 266 of the 301 positions lie 0.3 mm or more from the jumps.
    assert!(compared >= 240, "{compared} positions compared");
    assert!(worst_s < 5e-3, "{worst_s}");
    assert!(worst_roll < 5e-6, "{worst_roll}");
}

/// Mirror symmetry is decided by content: the paper's wheelset placed as a scene places it
/// (one side cloned), with `Placement::symmetric`, with its two sides placed separately,
/// and from separately fitted splines through the same points, is mirror-symmetric every
/// way and gives the same sweep to the bit (compared through `Debug`); another radius or a
/// fitted wheel on one side is not mirror-symmetric.
#[test]
fn equal_placements_built_any_way_give_the_same_results() {
    use wheelrail::profile::{Profile, read::PointProfile};
    use wheelrail::track::{Inclination, SidePair};
    let layout = paper_placement().layout().clone();
    let upright = Inclination::VERTICAL;
    let side = |wheel: Profile, radius: f64, rail: Profile| {
        SidePair::place(wheel, radius, rail, upright, &layout).unwrap()
    };
    let apart = |wheel: &dyn Fn() -> Profile, rail: &dyn Fn() -> Profile, right_radius| {
        let left = side(wheel(), 460.0, rail());
        let right = side(wheel(), right_radius, rail());
        Placement::new(layout.clone(), left, right).unwrap()
    };
    let sampled = |p: Profile| {
        let kind = p.kind();
        let points = p.sample(0.5).iter().map(|r| [r[0], r[1]]).collect();
        let points = PointProfile::from_points(kind, "sampled", points).unwrap();
        Profile::from_points(points, 0.0).unwrap()
    };
    let symmetric = Placement::symmetric(
        Profile::s1002(),
        460.0,
        Profile::uic60e1(),
        upright,
        layout.clone(),
    )
    .unwrap();
    let analytic = [
        paper_placement().clone(),
        symmetric,
        apart(&Profile::s1002, &Profile::uic60e1, 460.0),
    ];
    let wheel = || sampled(Profile::s1002());
    let rail = || sampled(Profile::uic60e1());
    let fitted = [apart(&wheel, &rail, 460.0), {
        let (wheel, rail) = (wheel(), rail());
        Placement::symmetric(wheel, 460.0, rail, upright, layout.clone()).unwrap()
    }];
    let sweep = Sweep::range(-15.0, 15.0, 0.25).unwrap();
    for same in [&analytic[..], &fitted[..]] {
        let runs: Vec<String> = same
            .iter()
            .map(|p| {
                assert!(p.is_mirror_symmetric() && p.mirrors());
                format!("{:?}", rigid::search(p, &sweep, Solver::default()))
            })
            .collect();
        assert!(runs.iter().all(|r| *r == runs[0]));
    }
    assert!(!apart(&Profile::s1002, &Profile::uic60e1, 455.0).is_mirror_symmetric());
    let left = side(Profile::s1002(), 460.0, Profile::uic60e1());
    let right = side(wheel(), 460.0, Profile::uic60e1());
    assert!(
        !Placement::new(layout.clone(), left, right)
            .unwrap()
            .is_mirror_symmetric()
    );
}

/// The tread-to-flange jumps of every committed report stay jumps, whatever the sampling of
/// its profiles: in each `rigid_jumps.csv`, a jump whose contact point moves between the
/// tread (s > -25 mm: the flange root of the S1002 family begins at about -26 mm) and the
/// flange (s < -30 mm) has the kind `jump`, and the sampled profiles' hops are counted
/// (the EN 15302 reference wheel R-UIC519A has 34 in ±7.5 mm, each across a hollow below
/// 2 µm). Measured over the committed reports: 10 tread-to-flange jumps, 106 artefacts.
#[test]
fn tread_to_flange_jumps_of_the_committed_reports_stay_jumps() {
    let reports = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    let (mut tread_to_flange, mut artefacts) = (0, 0);
    for entry in std::fs::read_dir(&reports).unwrap() {
        let path = entry.unwrap().path().join("rigid_jumps.csv");
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let mut lines = text.lines().filter(|l| !l.starts_with('#'));
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
        let (from, to, kind, hollow) = (
            column("s_from_mm"),
            column("s_to_mm"),
            column("kind"),
            column("hollow_mm"),
        );
        for row in lines {
            let c: Vec<&str> = row.split(',').collect();
            let (a, b): (f64, f64) = (c[from].parse().unwrap(), c[to].parse().unwrap());
            if a.max(b) > -25.0 && a.min(b) < -30.0 {
                assert_eq!(c[kind], "jump", "{}: {row}", path.display());
                tread_to_flange += 1;
            }
            if c[kind] == "artefact" {
                let h: f64 = c[hollow].parse().unwrap();
                assert!(h < rigid::ARTEFACT_HOLLOW_MM, "{}: {row}", path.display());
                artefacts += 1;
            }
        }
    }
    assert!(
        tread_to_flange >= 8,
        "{tread_to_flange} tread-to-flange jumps"
    );
    assert!(artefacts >= 34, "{artefacts} artefacts");
}
