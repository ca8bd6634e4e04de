//! The certificate against a full fine scan (brute force) on noisy measured-like profiles,
//! and on the paper's profiles.

use super::super::{GapPoint, SideGap, SidePose, Yaw, YawModel};
use super::CERTIFY_TOL_MM;
use crate::profile::read::{ProfileFormat, parse_str};
use crate::profile::{Profile, ProfileKind};
use crate::track::{Inclination, PlacedRail, PlacedWheel, SidePair, TrackLayout};

/// `profile` sampled every `step_mm` with Gaussian noise of `std_um` on its height, read back
/// as a smoothed spline (4 mm): the noisy profiles of `tests/stress.rs`, number for number.
fn noisy(profile: &Profile, step_mm: f64, std_um: f64, seed: u64) -> Profile {
    let mut rng = crate::rng::SplitMix64::new(seed);
    // Box-Muller on uniforms in (0, 1], as the stress tests draw them.
    let mut uniform = || ((rng.next_u64() >> 11) as f64 + 1.0) / (1u64 << 53) as f64;
    let mut gaussian = || {
        let (u, v) = (uniform(), uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    };
    let header = match profile.kind() {
        ProfileKind::Wheel => "s_mm,F_mm\n",
        ProfileKind::Rail => "y_mm,z_mm\n",
    };
    let mut text = String::from(header);
    for [u, v, _, _] in profile.sample(step_mm) {
        let v = v + 1e-3 * std_um * gaussian();
        text.push_str(&format!("{u:?},{v:?}\n"));
    }
    let points = parse_str(&text, ProfileFormat::Csv, profile.kind(), "noisy.csv").unwrap();
    Profile::from_points(points, 4.0).unwrap()
}

fn pair(wheel: Profile, rail: Profile, inclination: &str) -> SidePair {
    let layout = TrackLayout::standard(Inclination::parse(inclination).unwrap());
    SidePair::new(
        PlacedWheel::place(wheel, 460.0, &layout).unwrap(),
        PlacedRail::place(rail, Inclination::VERTICAL, &layout).unwrap(),
    )
}

/// The minimum the search without the certificate finds: Newton in every basin of the scan.
fn basin_minimum(side: &SideGap, pose: &SidePose) -> Option<(GapPoint, Vec<GapPoint>)> {
    let mut basins = Vec::new();
    let mut scanned = super::super::Scanned::default();
    side.basins(
        pose,
        &mut super::super::PoseBox::default(),
        &mut scanned,
        &mut basins,
    );
    let minima: Vec<GapPoint> = basins
        .iter()
        .filter_map(|&b| side.minimum(b, None, pose))
        .collect();
    let best = *minima.iter().min_by(|a, b| a.g.total_cmp(&b.g))?;
    Some((best, minima))
}

/// The lowest gap of a scan every `step` mm over the whole wheel.
fn fine_scan(side: &SideGap, pose: &SidePose, step: f64) -> Option<(f64, f64)> {
    let (lo, hi) = side.wheel().profile().domain();
    let n = ((hi - lo) / step).ceil() as usize;
    (0..=n)
        .filter_map(|i| {
            let s = (lo + step * i as f64).min(hi);
            side.at(s, pose).map(|p| (s, p.g))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
}

/// Over noisy profiles and poses: the certified minimum is never above the fine scan's lowest
/// point by more than the tolerance, every certificate completes, and the certificate does
/// find lower minima that the basins missed (so that the comparison has teeth).
#[test]
fn the_certified_minimum_is_the_lowest_of_a_fine_scan_on_noisy_profiles() {
    let mut corrected = 0;
    let mut poses = 0;
    // (seed, wheel and rail noise in um, step in mm, inclination): the first is the case of
    // `tests/stress.rs::a_lower_minimum_in_the_same_bracket_is_found`.
    let mut cases = vec![(
        6_453_237_190_401_519_453,
        19.782957939549426,
        4.794684472837532,
        0.5466012101744516,
        "vertical",
    )];
    for (k, incl) in ["vertical", "1:40", "1:20"].into_iter().enumerate() {
        for seed in 0..3u64 {
            cases.push((seed + 10 * k as u64, 20.0, 5.0, 0.55, incl));
        }
    }
    for (n, (seed, wheel_um, rail_um, step, incl)) in cases.into_iter().enumerate() {
        let wheel = noisy(&Profile::s1002(), step, wheel_um, seed);
        let rail = noisy(&Profile::uic60e1(), step, rail_um, seed ^ 1);
        let pair = pair(wheel, rail, incl);
        // A sweep of shifts and rolls, and for the first case the rolls about its solution
        // at y_ws = -10 (-0.0121 rad), where two minima in one bracket cross.
        let mut poses_of_case: Vec<(f64, f64)> = (0..=48)
            .flat_map(|i| [-2e-3, 0.0, 1e-3].map(|roll| (-12.0 + 0.5 * f64::from(i), roll)))
            .collect();
        if n == 0 {
            poses_of_case.extend((0..150).map(|i| (-10.0, -0.0123 + 2e-6 * f64::from(i))));
        }
        for sign in [1.0, -1.0] {
            let side = SideGap::new(&pair, sign);
            for &(y_ws, roll) in &poses_of_case {
                let pose = SidePose::new(sign, y_ws, roll);
                let Some((best, minima)) = basin_minimum(&side, &pose) else {
                    continue;
                };
                let cert = side.certify(&pose, best, &minima);
                assert!(cert.complete, "{incl} seed {seed} y {y_ws}: {cert:?}");
                let certified = cert.lower.unwrap_or(best);
                if cert.lower.is_some() {
                    corrected += 1;
                }
                let (s, brute) = fine_scan(&side, &pose, 0.002).unwrap();
                assert!(
                    certified.g <= brute + CERTIFY_TOL_MM,
                    "{incl} seed {seed} y {y_ws}: {} at {} above the scan's {brute} at {s}",
                    certified.g,
                    certified.s
                );
                poses += 1;
            }
        }
    }
    assert!(poses > 2000, "{poses}");
    assert!(
        corrected > 0,
        "the basins missed no minimum in {poses} poses"
    );
}

/// The certificate of a yawed wheel (its outline in place of the profile) against the fine
/// scan of the same outline: on the paper's profiles and on noisy ones, both sides, yaws up
/// to 30 mrad either way and shifts onto the flange; every certificate completes and
/// nothing the fine scan finds lies lower than the certified minimum by more than the
/// tolerance (plus S1002's value jump at its joints, which the scan may straddle).
#[test]
fn the_certified_minimum_of_a_yawed_wheel_is_the_lowest_of_a_fine_scan() {
    let mut cases = vec![(
        "analytic 1:40".to_string(),
        pair(Profile::s1002(), Profile::uic60e1(), "1:40"),
    )];
    for (seed, incl) in [(21u64, "1:40"), (22, "vertical")] {
        let wheel = noisy(&Profile::s1002(), 0.55, 20.0, seed);
        let rail = noisy(&Profile::uic60e1(), 0.55, 5.0, seed ^ 1);
        cases.push((format!("noisy seed {seed} {incl}"), pair(wheel, rail, incl)));
    }
    let mut poses = 0;
    for (name, pair) in &cases {
        for sign in [1.0, -1.0] {
            for yaw_rad in [0.03, -0.024, 0.01] {
                let mut side = SideGap::new(pair, sign);
                side.set_yaw(Yaw::new(sign, yaw_rad, YawModel::Exact));
                for i in 0..=24 {
                    for roll in [-2e-3, 1e-3] {
                        let y_ws = -12.0 + f64::from(i);
                        let pose = SidePose::yawed(sign, y_ws, roll, yaw_rad);
                        let Some((best, minima)) = basin_minimum(&side, &pose) else {
                            continue;
                        };
                        let cert = side.certify(&pose, best, &minima);
                        assert!(cert.complete, "{name} yaw {yaw_rad} y {y_ws}: {cert:?}");
                        let certified = cert.lower.unwrap_or(best);
                        let (s, brute) = fine_scan(&side, &pose, 0.002).unwrap();
                        assert!(
                            certified.g <= brute + CERTIFY_TOL_MM + 1.2e-4,
                            "{name} yaw {yaw_rad} y {y_ws}: {} at {} above the scan's {brute} at {s}",
                            certified.g,
                            certified.s
                        );
                        poses += 1;
                    }
                }
            }
        }
    }
    assert!(poses > 800, "{poses}");
}

/// On the paper's S1002 and UIC60 at 1:40 the basins' minimum is already global: the
/// certificate finds nothing lower, and is cheap (few cells where the contact lies).
#[test]
fn on_the_paper_profiles_the_basins_minimum_is_certified() {
    let pair = pair(Profile::s1002(), Profile::uic60e1(), "1:40");
    let side = SideGap::new(&pair, 1.0);
    for i in 0..=60 {
        let y_ws = -15.0 + 0.5 * f64::from(i);
        let pose = SidePose::new(1.0, y_ws, 1e-3);
        let (best, minima) = basin_minimum(&side, &pose).unwrap();
        let cert = side.certify(&pose, best, &minima);
        assert!(cert.complete && cert.lower.is_none(), "y {y_ws}: {cert:?}");
        let (_, brute) = fine_scan(&side, &pose, 0.002).unwrap();
        // The S1002's value jumps (1.2e-4 mm at s = -35) can put the scan's lowest point
        // on the other side of a joint; elsewhere the minimum is the scan's within rounding.
        assert!(best.g <= brute + 1.2e-4, "y {y_ws}: {} vs {brute}", best.g);
    }
}

/// The sharp bound from both ends of a cell against the parabola it bounds: exact for a
/// quadratic with `g'' = m`, below it for `g'' > m`.
#[test]
fn the_bound_from_both_ends_is_exact_for_a_parabola() {
    let g = |s: f64, k: f64| 0.3 + k * (s - 0.1) * (s - 0.1) / 2.0;
    let dg = |s: f64, k: f64| k * (s - 0.1);
    let (a, b) = (0.0, 0.25);
    for (k, exact) in [(0.5, true), (2.0, false)] {
        let lb = super::from_both_ends(a, b, (g(a, k), dg(a, k)), (g(b, k), dg(b, k)), 0.5);
        if exact {
            assert!((lb - 0.3).abs() < 1e-15, "{lb}");
        } else {
            // Each Taylor parabola lies below g by (k - m) t^2 / 2 at a distance t from its
            // end: at most that at the full width.
            let (h, m) = (b - a, 0.5);
            assert!(lb <= 0.3 && lb >= 0.3 - (k - m) * h * h / 2.0, "{lb}");
        }
    }
}

/// The cases of the dense tests of the bounds: the paper's profiles at 1:40 and vertical,
/// and noisy measured-like ones (the noise of `tests/stress.rs`).
fn bound_cases() -> Vec<(String, SidePair)> {
    let mut cases = vec![
        (
            "analytic 1:40".to_string(),
            pair(Profile::s1002(), Profile::uic60e1(), "1:40"),
        ),
        (
            "analytic vertical".to_string(),
            pair(Profile::s1002(), Profile::uic60e1(), "vertical"),
        ),
    ];
    for (seed, incl) in [(3u64, "1:40"), (4, "vertical"), (5, "1:20")] {
        let wheel = noisy(&Profile::s1002(), 0.55, 20.0, seed);
        let rail = noisy(&Profile::uic60e1(), 0.55, 5.0, seed ^ 1);
        cases.push((format!("noisy seed {seed} {incl}"), pair(wheel, rail, incl)));
    }
    cases
}

/// The gap every `h / 400` over the coarse cells `i..j` (`None` off the rail).
fn dense(side: &SideGap, pose: &SidePose, i: usize, j: usize) -> Vec<(f64, Option<f64>)> {
    let (a, b) = (side.coarse[i][0], side.coarse[j][0]);
    let n = 400 * (j - i);
    (0..=n)
        .map(|k| {
            let s = a + (b - a) * k as f64 / n as f64;
            (s, side.at(s, pose).map(|p| p.g))
        })
        .collect()
}

/// On random blocks and poses of analytic and noisy profiles, a dense sample of the exact gap
/// (every 0.000625 mm) never lies below the bounds the certificate skips cells with: the
/// interpolation bound on the coarse samples with the block's cushion at the pose and over a
/// box of poses about another pose, the block's rigorous bound, and the convexity bound about
/// the minimum; and the gap's second differences lie within `curvature_range` on cells
/// without joints. The bounds are close enough to be tested: some cushion is below 1e-3 mm
/// and some convexity bound within 1e-3 mm of the sampled gap.
#[test]
fn the_cushion_and_convexity_bounds_lie_below_a_dense_sample() {
    use super::super::PoseBox;
    use super::super::scan::SCAN_BLOCK;
    use super::{curvature_range, pose_trig, span};
    let mut rng = crate::rng::SplitMix64::new(20_261_123);
    let mut uniform =
        |lo: f64, hi: f64| lo + (hi - lo) * (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    let (mut blocks, mut tight_cushion, mut convex, mut tight_convex, mut curved) = (0, 0, 0, 0, 0);
    for (name, pair) in bound_cases() {
        for (sign, yaw_rad) in [(1.0, 0.0), (-1.0, 0.0), (1.0, 0.03), (-1.0, -0.025)] {
            let mut side = SideGap::new(&pair, sign);
            side.set_yaw(Yaw::new(sign, yaw_rad, YawModel::Exact));
            let n = side.coarse.len() - 1;
            let cells = side.pair.wheel.cells(n);
            let h = side.coarse[1][0] - side.coarse[0][0];
            for _ in 0..12 {
                let (y_ws, roll) = (uniform(-11.0, 11.0), uniform(-3e-3, 3e-3));
                let pose = SidePose::yawed(sign, y_ws, roll, yaw_rad);
                let Some((best, _)) = basin_minimum(&side, &pose) else {
                    continue;
                };
                // A box about a pose nearby that holds `pose`.
                let mut pose_box = PoseBox::default();
                let near = SidePose::yawed(
                    sign,
                    y_ws + uniform(-0.9, 0.9),
                    roll + uniform(-8e-4, 8e-4),
                    yaw_rad,
                );
                side.fill_pose_box(&near, &mut pose_box);
                assert!(pose_box.holds(&pose));
                // The block of the contact, its neighbours and a random one.
                let at = (((best.s - side.coarse[0][0]) / h) as usize).min(n - 1);
                let random = (uniform(0.0, 1.0) * n as f64) as usize;
                for i0 in [at, at.saturating_sub(SCAN_BLOCK), at + SCAN_BLOCK, random] {
                    let b = i0.min(n - 1) / SCAN_BLOCK;
                    let (i, j) = side.block_cells(b);
                    let samples = dense(&side, &pose, i, j);
                    let lowest = samples
                        .iter()
                        .filter_map(|x| x.1)
                        .fold(f64::INFINITY, f64::min);
                    let bound = side.certified_block_bound(b, &pose);
                    assert!(
                        bound <= lowest,
                        "{name} y {y_ws} b {b}: {bound} above {lowest}"
                    );
                    let cushion = side.block_cushion(b, &cells, &pose);
                    let boxed = side.box_cushion(b, &cells, &pose_box);
                    for c in i..j {
                        let (ga, gb) = (side.coarse_gap(c, &pose), side.coarse_gap(c + 1, &pose));
                        if ga.max(gb) == f64::INFINITY || !cushion.is_finite() {
                            continue;
                        }
                        for (s, g) in &samples[400 * (c - i)..=400 * (c + 1 - i)] {
                            let g = g.expect("a cell with both samples over the rail");
                            for (what, cu) in [("pose", cushion), ("box", boxed)] {
                                assert!(
                                    g >= ga.min(gb) - cu,
                                    "{name} y {y_ws} s {s} ({what}): {g} below {} - {cu}",
                                    ga.min(gb)
                                );
                            }
                        }
                        tight_cushion += usize::from(cushion < 1e-3);
                    }
                    blocks += 1;
                    // The second differences every 0.01 mm on each joint-free cell.
                    for c in i..j {
                        let w = side.cells_over(&cells, c, c + 1);
                        let [y_lo, y_hi, _] =
                            span(&pose, (side.coarse[c][1], side.coarse[c + 1][1]), w.z);
                        let Some(r) = side.pair.rail.binned_bounds(y_lo, y_hi) else {
                            continue;
                        };
                        if w.jump > 0.0 || r.jump > 0.0 {
                            continue;
                        }
                        let (m, big_m) = curvature_range(pose_trig(&pose), &w.d, &r);
                        let d = 0.01;
                        for k in 1..25 {
                            let s = side.coarse[c][0] + d * f64::from(k);
                            // The gap against Yw, which its derivatives are taken along.
                            let g = |s: f64| side.at(s, &pose).map(|p| (p.wheel.y, p.g));
                            let (Some((y0, g0)), Some((y1, g1)), Some((y2, g2))) =
                                (g(s - d), g(s), g(s + d))
                            else {
                                continue;
                            };
                            // The second difference is g'' at a point within d of s (inside
                            // the cell), up to the errors of the three gaps, each within
                            // `EXACT_PAD_MM` of the exact gap (the rail's surface table, 8.5e-13
                            // mm, and rounding near 460 mm): 4 x 1e-11 / d^2 = 4e-7 per mm.
                            // Seen: 4.7e-8 on the analytic cone (g'' = 0 exactly) in cells
                            // the blocks of 16 samples bring into the test.
                            let second = if side.yawed() {
                                2.0 * ((g2 - g1) / (y2 - y1) - (g1 - g0) / (y1 - y0)) / (y2 - y0)
                            } else {
                                (g0 - 2.0 * g1 + g2) / (d * d)
                            };
                            let slack = 4.0 * super::super::certify::EXACT_PAD_MM / (d * d);
                            assert!(
                                second >= m - slack && second <= big_m + slack,
                                "{name} y {y_ws} s {s}: g'' {second} outside [{m}, {big_m}]"
                            );
                            curved += 1;
                        }
                    }
                }
                // Convexity about the minimum, out to 6 coarse cells either side.
                for off in [-6i64, -3, -1, 0, 1, 3, 6] {
                    let c = (at as i64 + off).clamp(0, n as i64 - 1) as usize;
                    let Some((low, lo, hi)) = side.convex_bound(c, &best, &pose, &cells) else {
                        continue;
                    };
                    let samples = dense(&side, &pose, lo, hi);
                    let lowest = samples
                        .iter()
                        .filter_map(|x| x.1)
                        .fold(f64::INFINITY, f64::min);
                    assert!(
                        low <= lowest,
                        "{name} y {y_ws} cells {lo}..{hi}: {low} above {lowest}"
                    );
                    convex += 1;
                    tight_convex += usize::from(lowest - low < 1e-3);
                }
            }
        }
    }
    eprintln!(
        "{blocks} blocks, {curved} second differences, {convex} convex zones ({tight_convex} tight), {tight_cushion} cushions below 1e-3 mm"
    );
    assert!(
        blocks > 200 && curved > 1000 && convex > 100,
        "{blocks} {curved} {convex}"
    );
    assert!(
        tight_cushion > 100 && tight_convex > 20,
        "{tight_cushion} {tight_convex}"
    );
}
