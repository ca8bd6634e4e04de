//! The six measured or converted MiniProf profiles of `tests/data/profiles/` through the whole
//! contact search: read (dropping the points that step back, [`StepBack::Drop`], where the
//! strict reader refuses the file), fitted with the default smoothing, placed and searched
//! with [`rigid::search`] and [`quasi_elastic::search`]. Measured wheels run on the nominal
//! UIC60 rail, measured rails under the nominal S1002 wheel. Every position must be finite
//! and plausible or flagged, and nothing may panic.

use std::path::{Path, PathBuf};
use wheelrail::gap::{SideGap, SidePose};
use wheelrail::profile::read::{ReadError, ReadOptions, StepBack, read_profile, read_profile_with};
use wheelrail::profile::{Profile, ProfileKind};
use wheelrail::quasi_elastic::{self, QuasiElasticSettings};
use wheelrail::rigid::{self, Solver, Stop};
use wheelrail::sweep::Sweep;

/// The filter wavelength measured profiles want (mm): the README's 4 mm.
const FILTER_WAVELENGTH_MM: f64 = 4.0;
use wheelrail::track::{
    Inclination, PlacedRail, PlacedWheel, Placement, Side, SidePair, TrackLayout,
};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/profiles")
        .join(name)
}

const DROP: ReadOptions = ReadOptions::new(StepBack::Drop);

/// The MiniProf files, their kind, and the lines the strict reader names (None: it accepts
/// the file).
const MINIPROF: [(&str, ProfileKind, Option<usize>); 6] = [
    ("Car7216_0001r.whl", ProfileKind::Wheel, Some(223)),
    ("Car7358_0001r.whl", ProfileKind::Wheel, Some(216)),
    ("avg_wheel.whl", ProfileKind::Wheel, None),
    ("avg_HR.BAN", ProfileKind::Rail, Some(135)),
    ("avg_low2.ban", ProfileKind::Rail, None),
    ("MBench_UIC60_v3.ban", ProfileKind::Rail, None),
];

#[test]
fn strict_by_default_and_dropping_on_request() {
    for (name, kind, zig_zag_line) in MINIPROF {
        let strict = read_profile(&data(name), kind);
        let lenient = read_profile_with(&data(name), kind, &DROP)
            .unwrap_or_else(|e| panic!("{name} with StepBack::Drop: {e}"));
        assert!(
            lenient.points.windows(2).all(|w| w[1][0] > w[0][0]),
            "{name}: not increasing"
        );
        match (zig_zag_line, strict) {
            (None, Ok(strict)) => {
                // Files the strict reader accepts read to the same points, nothing dropped.
                assert_eq!(strict.points, lenient.points, "{name}");
                assert!(lenient.dropped_step_backs.is_empty(), "{name}");
                assert!(strict.dropped_step_backs.is_empty(), "{name}");
            }
            (Some(line), Err(err)) => {
                assert!(
                    matches!(err, ReadError::NonMonotonic { .. }),
                    "{name}: {err}"
                );
                // The strict error's line (or its partner in the zig-zag) is among the
                // dropped ones; a zig-zag costs a few points, not a part of the profile.
                let dropped = &lenient.dropped_step_backs;
                assert!(
                    dropped.iter().any(|&l| l.abs_diff(line) <= 1),
                    "{name}: dropped {dropped:?}, strict error at line {line}"
                );
                assert!(dropped.len() <= 10, "{name}: dropped {dropped:?}");
                println!(
                    "{name}: {} points kept, lines {dropped:?} dropped",
                    lenient.points.len()
                );
            }
            (expected, got) => panic!("{name}: expected {expected:?}, strict reader gave {got:?}"),
        }
    }
}

fn layout() -> TrackLayout {
    TrackLayout::standard(Inclination::parse("1:40").unwrap())
}

fn measured(name: &str, kind: ProfileKind) -> Profile {
    let points = read_profile_with(&data(name), kind, &DROP).unwrap();
    Profile::from_points(points, FILTER_WAVELENGTH_MM).unwrap()
}

fn placement(wheel: Profile, rail: Profile, rail_inclination: Inclination) -> Placement {
    let layout = layout();
    let pair = || {
        SidePair::new(
            PlacedWheel::place(wheel.clone(), 460.0, &layout).unwrap(),
            PlacedRail::place(rail.clone(), rail_inclination, &layout).unwrap(),
        )
    };
    Placement::new(layout.clone(), pair(), pair()).unwrap()
}

/// Finite-or-flagged checks of a sweep (the plausibility bounds of `tests/stress.rs`); returns
/// how many positions converged.
fn check(placement: &Placement, name: &str) -> usize {
    let ys: Vec<f64> = (0..=100).map(|i| -25.0 + 0.5 * f64::from(i)).collect();
    let sweep = rigid::search(
        placement,
        &Sweep::from_slice(&ys).unwrap(),
        Solver::default(),
    );
    let qe = quasi_elastic::search(placement, sweep.clone(), &QuasiElasticSettings::default());
    let mut converged = 0;
    for (pos, q) in sweep.positions().iter().zip(qe.positions()) {
        if pos.stop != Stop::Converged {
            continue;
        }
        converged += 1;
        let at = format!("{name}, y_ws = {}", pos.y_ws);
        assert!(
            pos.roll.is_finite() && pos.roll.abs() < 0.1,
            "{at}: {pos:?}"
        );
        assert!(
            pos.axle_height.is_finite() && pos.residual <= 1e-9,
            "{at}: {pos:?}"
        );
        for side in [Side::Left, Side::Right] {
            let c = pos.side(side).expect("converged with contact");
            let values = [
                c.s,
                c.y,
                c.z,
                c.r,
                c.gamma,
                c.wheel_curvature,
                c.rail_curvature,
            ];
            assert!(values.iter().all(|v| v.is_finite()), "{at}: {c:?}");
            // No wheel point below the rail (sampled every 0.05 mm) by more than the residual
            // the issue allows (measured: every point at least 3.6e-12 mm above it).
            let sign = side.sign();
            let gap = SideGap::new(placement.side(side), sign);
            let pose = SidePose::new(sign, pos.y_ws, pos.roll);
            let (lo, hi) = placement.side(side).wheel().profile().domain();
            let n = ((hi - lo) / 0.05).ceil() as usize;
            for i in 0..=n {
                let s = (lo + 0.05 * i as f64).min(hi);
                if let Some(p) = gap.at(s, &pose) {
                    let d = p.g + pos.axle_height;
                    assert!(d >= -1e-9, "{at}: {side:?} penetrates by {d} at s = {s}");
                }
            }
            let patches = &q.side(side).patches;
            assert!(!patches.is_empty(), "{at}: {side:?} without patch");
            // Normalised shares: measured within 1.1e-16 of 1, bound two ulps of 1.
            let total: f64 = patches.iter().map(|p| p.weight_share).sum();
            assert!((total - 1.0).abs() < 4.5e-16, "{at}: shares {total}");
            for p in patches {
                assert!(
                    [p.s, p.r, p.gamma, p.wheel_curvature, p.rail_curvature]
                        .iter()
                        .all(|v| v.is_finite()),
                    "{at}: {p:?}"
                );
            }
        }
    }
    converged
}

#[test]
fn measured_wheels_run_on_uic60() {
    for name in ["Car7216_0001r.whl", "Car7358_0001r.whl", "avg_wheel.whl"] {
        let placement = placement(
            measured(name, ProfileKind::Wheel),
            Profile::uic60e1(),
            Inclination::VERTICAL,
        );
        let converged = check(&placement, name);
        println!("{name} on UIC60 1:40: {converged} of 101 positions converged");
        // Tread and flange contact of a worn wheel: measured 101 of 101 for each wheel (the
        // flangeway clearance alone, +-5 mm, is 21 positions).
        assert!(converged >= 90, "{name}: {converged}");
    }
}

#[test]
fn measured_rails_run_under_s1002() {
    for (name, inclination) in [
        ("avg_HR.BAN", "vertical"),
        ("avg_low2.ban", "vertical"),
        // Converted from the SIMPACK file, which is already inclined 1:40.
        ("MBench_UIC60_v3.ban", "1:40"),
    ] {
        let placement = placement(
            Profile::s1002(),
            measured(name, ProfileKind::Rail),
            Inclination::parse(inclination).unwrap(),
        );
        let converged = check(&placement, name);
        println!("S1002 on {name}: {converged} of 101 positions converged");
        // Measured: 101 of 101 for each rail.
        assert!(converged >= 90, "{name}: {converged}");
    }
}
