//! Tests of the jump search on the paper scene: mirrored halves, wide steps, provisional
//! refinements and cold solves.

use super::super::minima::Scratch;
use super::super::roll::solve_default;
use super::super::{RollSettings, Solver, search};
use super::*;
use crate::scene::Scene;
use crate::sweep::Mirrored;

/// With roll (the paper scene), the mirror images of the positions after the middle
/// of a symmetric sweep are the positions solved before it, to the solver's accuracy:
/// the roll solve of a mirrored position starts from the mirrored prediction, and its
/// root is found to 1e-11 mm of residual, not bit for bit. The half after the middle
/// is the same solves in the same order, bit for bit. The sweep is spaced evenly as
/// `-15 + 30 i / 300`, whose opposite shifts differ in their last bits: mirrored all
/// the same (`MIRRORED_SHIFT_MM`), each image reported at the sweep's own shift.
#[test]
fn a_symmetric_sweep_with_roll_mirrors_its_half() {
    let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
    let placement = crate::pipeline::place(&scene).unwrap();
    assert!(placement.is_mirror_symmetric());
    let sweep: Vec<f64> = (0..301)
        .map(|i| -15.0 + 30.0 * f64::from(i) / 300.0)
        .collect();
    let n = sweep.len();
    assert!((0..n / 2).any(|i| sweep[i].to_bits() != (-sweep[n - 1 - i]).to_bits()));
    let shifts = crate::sweep::Sweep::from_slice(&sweep).unwrap();
    assert!(shifts.is_symmetric());
    let mirrored = search(&placement, &shifts, Solver::default());
    for (i, p) in mirrored.positions.iter().enumerate() {
        let image = mirrored.positions[n - 1 - i].mirrored(sweep[i]);
        assert_eq!(format!("{p:?}"), format!("{image:?}"));
    }
    let solved = search(
        &placement.clone().without_mirroring(),
        &shifts,
        Solver::default(),
    );
    let (mut roll, mut s, mut r, mut height) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (i, (m, p)) in mirrored.positions.iter().zip(&solved.positions).enumerate() {
        if i >= n / 2 {
            assert_eq!(format!("{m:?}"), format!("{p:?}"), "y = {}", p.y_ws);
            continue;
        }
        roll = roll.max((m.roll - p.roll).abs());
        height = height.max((m.axle_height - p.axle_height).abs());
        for k in 0..2 {
            let (a, b) = (m.contact[k].unwrap(), p.contact[k].unwrap());
            s = s.max((a.s - b.s).abs());
            r = r.max((a.r - b.r).abs());
        }
    }
    // Measured: roll 1.2e-14 rad, height 1.0e-11 mm, s 1.4e-10 mm, r 6.7e-11 mm: far
    // inside the accuracy the solver is held to against brute force (1e-6 mm, 1e-9 rad).
    assert!(
        roll < 1e-12 && height < 1e-9,
        "roll {roll:e} height {height:e}"
    );
    assert!(s < 1e-8 && r < 1e-9, "s {s:e} r {r:e}");
    assert_eq!(mirrored.jumps.len(), solved.jumps.len());
    assert!(mirrored.jumps.len() >= 6);
    for (m, p) in mirrored.jumps.iter().zip(&solved.jumps) {
        // The same jump, located to the same interval within 1e-9 mm (measured: 6e-11);
        // its ends' contacts within 1e-7 mm and Δr within 1e-7 mm (measured: 9e-9 and
        // 8e-9, at a near-conformal flange contact that moves 2.5e4 mm per radian of
        // roll, see tests/rigid.rs).
        assert_eq!(m.side, p.side);
        assert!((m.y_from - p.y_from).abs() < 1e-9 && (m.y_to - p.y_to).abs() < 1e-9);
        assert!((m.s_from - p.s_from).abs() < 1e-7 && (m.s_to - p.s_to).abs() < 1e-7);
        let dr = (m.delta_r_from - p.delta_r_from).abs() + (m.delta_r_to - p.delta_r_to).abs();
        assert!(dr < 1e-7, "{m:?} vs {p:?}");
    }
}

/// A sweep of 1 mm steps locates the jumps the paper sweep (0.1 mm steps) locates, and
/// the secant, tried again on the halves of an interval too wide to follow the
/// competing minima across, locates each of them with fewer solves than bisection (14
/// from 1 mm to 1e-4 mm).
#[test]
fn jumps_across_wide_steps_are_located_by_the_secant() {
    let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
    let placement = crate::pipeline::place(&scene).unwrap();
    let coarse: Vec<f64> = (-15..=15).map(f64::from).collect();
    let wide = search(
        &placement,
        &crate::sweep::Sweep::from_slice(&coarse).unwrap(),
        Solver::default(),
    );
    let fine = search(&placement, scene.sweep(), Solver::default());
    assert_eq!(wide.jumps.len(), fine.jumps.len());
    for (w, f) in wide.jumps.iter().zip(&fine.jumps) {
        // Both intervals, each at most JUMP_REFINE_MM wide, hold the same jump.
        assert_eq!(w.side, f.side);
        assert!(w.y_from <= f.y_to && f.y_from <= w.y_to, "{w:?} vs {f:?}");
        assert!((w.s_from - f.s_from).abs() < 0.05, "{w:?} vs {f:?}");
        assert!((w.s_to - f.s_to).abs() < 0.05, "{w:?} vs {f:?}");
    }
    // The jump of the right wheel between -5 and -4 mm, alone.
    let sides = SideGap::both(&placement);
    let settings = RollSettings::default();
    let mut scratch = Scratch::default();
    let mut solves = 0;
    let window = &wide.positions[10..12];
    assert_eq!((window[0].y_ws, window[1].y_ws), (-5.0, -4.0));
    let jumps = find_jumps(
        &mut Fixed::new(&sides, |y, theta0, _, scratch| {
            solves += 1;
            solve_default(&sides, &settings, y, theta0, scratch)
        }),
        window,
        Refinement {
            separable: false,
            certifying: true,
            artefacts_unrefined: true,
        },
        &mut scratch,
    );
    assert_eq!(jumps.len(), 1, "{jumps:?}");
    // Measured: 9 solves (5 for the jump, 4 for the left wheel's candidate in the
    // window, which is no jump), 18 where a failed secant falls back to bisection.
    eprintln!("{solves} solves");
    assert!(solves <= 12, "{solves} solves");
}

/// On the paper scene (the roll solver) refinements steered by provisional positions
/// find the jumps of refinements certified throughout, bit for bit, and certify fewer
/// positions.
#[test]
fn provisional_refinements_with_roll_give_the_jumps_of_certified_ones() {
    let placement = crate::gap::tests::placement();
    let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
    let sweep = search(&placement, scene.sweep(), Solver::default());
    let sides = SideGap::both(&placement);
    let settings = RollSettings::default();
    let [(certified, all), (steered, some)] = [false, true].map(|provisional| {
        let (mut scratch, mut certified) = (Scratch::default(), 0);
        let jumps = find_jumps(
            &mut Fixed::new(&sides, |y, theta0, ask, s| {
                s.provisional = provisional && !ask.certified;
                certified += usize::from(!s.provisional);
                solve_default(&sides, &settings, y, theta0, s)
            }),
            &sweep.positions,
            Refinement {
                separable: false,
                certifying: true,
                artefacts_unrefined: true,
            },
            &mut scratch,
        );
        (format!("{jumps:?}"), certified)
    });
    assert_eq!(steered, certified);
    eprintln!("{some} of {all} solves certified");
    assert!(some < all / 2, "{some} of {all} solves certified");
}

/// A cold solve is a function of its shift and start roll alone, whatever was solved
/// before with the same scratch (what the sweep driver relies on to refine the windows
/// of a sweep's two halves at once, each half with its own state): compared bit for
/// bit through `Debug` at the
/// midpoints of a sweep of 1 mm steps, each solved after a nearby shift (whose pose
/// boxes hold it) and after a far one.
#[test]
fn a_cold_solve_does_not_depend_on_what_was_solved_before() {
    let placement = crate::gap::tests::placement();
    let sides = SideGap::both(&placement);
    let settings = RollSettings::default();
    let mut scratch = Scratch::default();
    let cold = |y: f64, theta0: f64, scratch: &mut Scratch| {
        scratch.warm = false;
        solve_default(&sides, &settings, y, theta0, scratch)
    };
    for i in -15..15 {
        let (y, theta0) = (f64::from(i) + 0.5, 1e-4 * f64::from(i));
        let solved: Vec<String> = [y - 0.3, -14.0 * y.signum()]
            .map(|before| {
                let p = cold(before, 0.0, &mut scratch);
                scratch.warm = p.stop == crate::rigid::Stop::Converged;
                format!("{:?}", cold(y, theta0, &mut scratch))
            })
            .into();
        assert_eq!(solved[0], solved[1], "y = {y}");
    }
}
