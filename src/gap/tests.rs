//! The scans with block skipping against full scans, and the block bounds.

use super::pose_box::{POSE_BOX_DELTA_MM, POSE_BOX_SIN};
use super::scan::SCAN_BLOCK;
use super::*;
use crate::scene::Scene;

/// The paper scene's placement (defaults of an empty scene file), for the tests of the
/// searches that stand on the gap.
pub(crate) fn placement() -> crate::track::Placement {
    let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
    crate::pipeline::place(&scene).unwrap()
}

/// The yaws the scans are checked at (rad): none, and the outline of a yaw either way.
const YAWS: [f64; 3] = [0.0, 0.03, -0.02];

/// The left side of `placement` seen through the outline of `yaw`, its boxes of poses
/// spanning nearby yaws.
fn left_at_yaw(placement: &crate::track::Placement, yaw: f64) -> SideGap<'_> {
    let mut side = SideGap::new(&placement.left, 1.0);
    side.set_yaw_varies(true);
    side.set_yaw(Yaw::new(1.0, yaw, YawModel::Exact));
    side
}

/// [`poses`] of the left side at `yaw`.
fn poses_at_yaw(yaw: f64) -> Vec<SidePose> {
    poses()
        .into_iter()
        .map(|p| SidePose {
            yaw: Yaw::side_psi(1.0, yaw),
            ..p
        })
        .collect()
}

/// Poses over the paper sweep and beyond, with rolls up to 0.02 rad, and the solved
/// poses around the paper's jumps, where two minima lie within the margin.
fn poses() -> Vec<SidePose> {
    let mut poses: Vec<SidePose> = (0..=120)
        .flat_map(|i| {
            let y_ws = -30.0 + 0.5 * f64::from(i);
            [-0.02, -1e-3, 0.0, 7e-4, 0.02].map(|roll| SidePose::new(1.0, y_ws, roll))
        })
        .collect();
    let mut near_jumps: Vec<f64> = (0..=40)
        .flat_map(|i| {
            let d = 0.0025 * f64::from(i) - 0.05;
            [0.226 + d, 4.992 + d, 6.26 + d]
        })
        .collect();
    near_jumps.sort_by(f64::total_cmp);
    let sweep = crate::rigid::search(
        &placement(),
        &crate::sweep::Sweep::from_slice(&near_jumps).unwrap(),
        crate::rigid::Solver::default(),
    );
    poses.extend(
        sweep
            .positions()
            .iter()
            .map(|p| SidePose::new(1.0, p.y_ws, p.roll)),
    );
    poses
}

/// The scans without skipping: every sample of the over-rail range evaluated.
fn all_gaps(side: &SideGap, pose: &SidePose) -> Vec<(usize, f64)> {
    let (first, last) = side.over_rail(pose);
    (first..last)
        .map(|i| (i, side.coarse_gap(i, pose)))
        .collect()
}

/// What the scan for basins recorded for the certificate is what a sample by sample
/// evaluation gives: every sample of every block it marks evaluated bit for bit
/// ([`SideGap::coarse_gap`]), the block's lowest and whether all are over the rail; at
/// least one block is evaluated where a sample lies above the rail. Every sample of a
/// block it skipped lies above the lowest sample plus [`COARSE_MARGIN_MM`] (what the
/// certificate relies on, and what makes the skip change no basin).
fn assert_scanned_gaps_exact(side: &SideGap, pose: &SidePose, scanned: &Scanned) {
    let (first, last) = scanned.range;
    let level = (first..last)
        .map(|i| side.coarse_gap(i, pose))
        .fold(f64::INFINITY, f64::min)
        + COARSE_MARGIN_MM;
    let mut evaluated = 0;
    for b in first / SCAN_BLOCK..last.div_ceil(SCAN_BLOCK) {
        let samples = super::scan::block_samples(b, first, last);
        if !scanned.evaluated(b) {
            for i in samples {
                let g = side.coarse_gap(i, pose);
                assert!(g > level, "skipped sample {i}: {g} at {pose:?}");
            }
            continue;
        }
        evaluated += 1;
        let (mut lowest, mut on_rail) = (f64::INFINITY, true);
        for i in samples {
            let g = side.coarse_gap(i, pose);
            let at = format!("sample {i} at {pose:?}");
            assert_eq!(scanned.gaps[i].to_bits(), g.to_bits(), "{at}");
            lowest = lowest.min(g);
            on_rail &= g < f64::INFINITY;
        }
        let at = format!("block {b} at {pose:?}");
        assert_eq!(scanned.block_min[b].to_bits(), lowest.to_bits(), "{at}");
        assert_eq!(scanned.on_rail(b), on_rail, "{at}");
    }
    let on_rail = (first..last).any(|i| side.coarse_gap(i, pose) < f64::INFINITY);
    assert!(evaluated > 0 || !on_rail, "no block evaluated at {pose:?}");
}

/// The coarse samples of a block four at a time in SIMD lanes ([`SideGap::block_gaps`])
/// are [`SideGap::coarse_gap`] sample by sample to the bit, with their lowest (bits too)
/// and whether all lie over the rail: every block of the whole wheel (not only the
/// over-rail range, so that blocks hold samples off the rail, partly or wholly) at every
/// pose of the scan tests, the blocks also cut short at either end (1 to 3 samples left
/// over the lanes, and a start off the lanes' alignment).
#[test]
fn block_gaps_are_the_coarse_gaps_to_the_bit() {
    let placement = placement();
    for yaw in YAWS {
        let side = left_at_yaw(&placement, yaw);
        let n = side.coarse.len();
        let mut scanned = Scanned::default();
        scanned.gaps = vec![f64::NAN; n];
        let (mut mixed, mut lanes_and_tail) = (0, 0);
        for pose in poses_at_yaw(yaw) {
            for start in (0..n).step_by(SCAN_BLOCK) {
                for (cut_start, cut_end) in [(0, 0), (1, 0), (0, 1), (3, 2), (5, 7)] {
                    let range = (start + cut_start).min(n)..(start + SCAN_BLOCK - cut_end).min(n);
                    if range.is_empty() {
                        continue;
                    }
                    lanes_and_tail += usize::from(range.len() >= 4 && range.len() % 4 != 0);
                    let (lowest, on_rail) = side.block_gaps(range.clone(), &pose, &mut scanned);
                    let (mut expected_low, mut expected_on) = (f64::INFINITY, true);
                    for i in range.clone() {
                        let g = side.coarse_gap(i, &pose);
                        assert_eq!(scanned.gaps[i].to_bits(), g.to_bits(), "{i} at {pose:?}");
                        if g < expected_low {
                            expected_low = g;
                        }
                        expected_on &= g < f64::INFINITY;
                    }
                    let at = format!("{range:?} at {pose:?}");
                    assert_eq!(lowest.to_bits(), expected_low.to_bits(), "{at}");
                    assert_eq!(on_rail, expected_on, "{at}");
                    mixed += usize::from(!on_rail && lowest < f64::INFINITY);
                }
            }
        }
        assert!(mixed > 100, "blocks partly off the rail: {mixed}");
        assert!(
            lanes_and_tail > 100,
            "blocks with samples left over the lanes"
        );
    }
}

#[test]
fn skipping_blocks_finds_the_basins_and_low_regions_of_a_full_scan() {
    let placement = placement();
    for yaw in YAWS {
        let side = left_at_yaw(&placement, yaw);
        let (mut basins, mut regions) = (Vec::new(), Vec::new());
        // One box carried from pose to pose (the poses near the jumps lie in each other's
        // boxes), and one made afresh at every pose: both scans find the same basins.
        let (mut carried, mut carried_held) = (PoseBox::default(), 0);
        let mut fresh_basins = Vec::new();
        let mut skipped_any = false;
        let mut several_basins = 0;
        for pose in poses_at_yaw(yaw) {
            let gaps = all_gaps(&side, &pose);
            let Some(lowest) = gaps.iter().map(|g| g.1).min_by(f64::total_cmp) else {
                continue;
            };
            // Basins: brackets around the sampled local minima within the margin.
            carried_held += usize::from(carried.holds(&pose));
            let mut scanned = Scanned::default();
            side.basins(&pose, &mut carried, &mut scanned, &mut basins);
            assert_scanned_gaps_exact(&side, &pose, &scanned);
            side.basins(
                &pose,
                &mut PoseBox::default(),
                &mut Scanned::default(),
                &mut fresh_basins,
            );
            assert_eq!(basins, fresh_basins, "carried and fresh box at {pose:?}");
            let mut expected: Vec<(f64, Basin)> = Vec::new();
            for (k, &(i, g)) in gaps.iter().enumerate() {
                let prev = if k > 0 { gaps[k - 1].1 } else { f64::INFINITY };
                let next = gaps.get(k + 1).map_or(f64::INFINITY, |n| n.1);
                if g < f64::INFINITY && g <= prev && g <= next && g <= lowest + COARSE_MARGIN_MM {
                    let lo = side.coarse[i.saturating_sub(1).max(gaps[0].0)][0];
                    let hi = side.coarse[(i + 1).min(gaps[gaps.len() - 1].0)][0];
                    expected.push((g, (lo, hi)));
                }
            }
            expected.sort_by(|a, b| a.0.total_cmp(&b.0));
            if expected.len() > 1 {
                several_basins += 1;
            }
            let expected: Vec<Basin> = expected.into_iter().map(|e| e.1).collect();
            assert_eq!(basins, expected, "basins at {pose:?}");
            // Low regions at a threshold 0.3 mm above the lowest sample.
            let threshold = lowest + 0.3;
            side.low_regions(&pose, threshold, &mut regions);
            // Runs of low samples, each from the sample before its first to its end.
            let n = side.coarse.len();
            let mut expected: Vec<(f64, f64)> = Vec::new();
            let mut k = 0;
            while k < gaps.len() {
                if gaps[k].1 < threshold {
                    let start = gaps[k].0;
                    while k < gaps.len() && gaps[k].1 < threshold {
                        k += 1;
                    }
                    let end = gaps.get(k).map_or(gaps[gaps.len() - 1].0 + 1, |g| g.0);
                    let (lo, hi) = (
                        side.coarse[start.saturating_sub(1)][0],
                        side.coarse[end.min(n - 1)][0],
                    );
                    match expected.last_mut() {
                        Some(last) if last.1 >= lo => last.1 = hi,
                        _ => expected.push((lo, hi)),
                    }
                } else {
                    k += 1;
                }
            }
            assert_eq!(regions, expected, "low regions at {pose:?}");
            let blocks = gaps[0].0 / SCAN_BLOCK..gaps[gaps.len() - 1].0 / SCAN_BLOCK + 1;
            skipped_any |= blocks
                .into_iter()
                .any(|b| side.block_bound(b, &pose) >= threshold);
        }
        assert!(
            skipped_any,
            "the bounds never allowed a skip: the test proves nothing"
        );
        assert!(
            several_basins > 10,
            "{several_basins} poses with two basins to refine"
        );
        assert!(
            carried_held > 50,
            "the carried box held {carried_held} times"
        );
    }
}

#[test]
fn block_bounds_are_below_every_sample_of_their_block() {
    let placement = placement();
    for yaw in YAWS {
        let side = left_at_yaw(&placement, yaw);
        for pose in poses_at_yaw(yaw) {
            for (i, g) in all_gaps(&side, &pose) {
                let bound = side.block_bound(i / SCAN_BLOCK, &pose);
                assert!(
                    bound <= g,
                    "sample {i}: bound {bound} above gap {g} at {pose:?}"
                );
            }
        }
    }
}

/// A pose from its side-frame shift and `sin(phi)` (`cos(phi) > 0`).
fn pose_of(delta: f64, sin: f64) -> SidePose {
    SidePose {
        delta,
        cos: (1.0 - sin * sin).sqrt(),
        sin,
        yaw: 0.0,
    }
}

#[test]
fn pose_box_bounds_are_below_every_sample_of_their_block_in_the_box() {
    use super::pose_box::POSE_BOX_YAW_RAD;
    let placement = placement();
    for yaw in YAWS {
        let side = left_at_yaw(&placement, yaw);
        let mut pose_box = PoseBox::default();
        // Blocks within the margin of the lowest sample by the box bound but not by the bound
        // at the pose: where the box loosens the bound (it must, a little).
        let (mut looser, mut skipped) = (0, 0);
        let (mut spanning, mut boxes) = (0, 0);
        // With yaw, the box spans yaws about its own: the side at either end of them too.
        let yaw_ends: &[f64] = if yaw == 0.0 {
            &[0.0]
        } else {
            &[-1.0, 0.0, 1.0]
        };
        for centre in poses_at_yaw(yaw).iter().step_by(7) {
            side.fill_pose_box(centre, &mut pose_box);
            let [yc, zc] = pose_box.reference;
            spanning += usize::from(pose_box.yaw_half > 0.0);
            boxes += 1;
            for &fy in yaw_ends {
                if fy != 0.0 && pose_box.yaw_half == 0.0 {
                    continue;
                }
                let psi = yaw + fy * POSE_BOX_YAW_RAD * (1.0 - 1e-12);
                let side = left_at_yaw(&placement, psi);
                // The corners of the box (a hair inside it), the centre and the middles of
                // its edges.
                let (dd, ds) = (
                    POSE_BOX_DELTA_MM * (1.0 - 1e-12),
                    POSE_BOX_SIN * (1.0 - 1e-12),
                );
                for (fd, fs) in [-1.0, 0.0, 1.0]
                    .iter()
                    .flat_map(|&a| [-1.0, 0.0, 1.0].map(|b| (a, b)))
                {
                    let pose = SidePose {
                        yaw: Yaw::side_psi(1.0, psi),
                        ..pose_of(centre.delta + fd * dd, centre.sin + fs * ds)
                    };
                    assert!(
                        pose_box.holds(&pose),
                        "{pose:?} not in the box at {centre:?}"
                    );
                    let common = pose.sin * yc + pose.cos * zc;
                    let gaps = all_gaps(&side, &pose);
                    let lowest = gaps.iter().map(|g| g.1).fold(f64::INFINITY, f64::min);
                    for &(i, g) in &gaps {
                        let bound = pose_box.bounds[i / SCAN_BLOCK] + common;
                        assert!(
                            bound <= g,
                            "sample {i}: box bound {bound} above gap {g} at {pose:?} (box at {centre:?})"
                        );
                    }
                    for b in gaps[0].0 / SCAN_BLOCK..gaps[gaps.len() - 1].0 / SCAN_BLOCK + 1 {
                        let (boxed, here) =
                            (pose_box.bounds[b] + common, side.block_bound(b, &pose));
                        let cut = lowest + COARSE_MARGIN_MM;
                        looser += usize::from(boxed <= cut && here > cut);
                        skipped += usize::from(boxed > cut);
                    }
                }
            }
        }
        assert!(
            looser > 0,
            "the box bounds never looser than the bounds at the pose"
        );
        assert!(skipped > 1000, "the box bounds skipped {skipped} blocks");
        // Every box of a yawed side spans yaws (on S1002 the part of the wheel that takes
        // part is the same within a milliradian of these yaws).
        assert_eq!(spanning, if yaw == 0.0 { 0 } else { boxes }, "yaw {yaw}");
    }
}

/// [`SideGap::each_x4`] on the wheel points of [`PlacedWheel::at_x4`] is [`SideGap::at`] to
/// the bit, `None` lanes included: groups of four over the whole wheel domain and beyond
/// (off the profile, off the rail), at every pose of [`poses`].
#[test]
fn four_gaps_at_once_are_at_to_the_bit() {
    let placement = placement();
    for yaw in YAWS {
        let side = left_at_yaw(&placement, yaw);
        let (lo, hi) = side.domain;
        let bits =
            |p: Option<GapPoint>| p.map(|p| [p.g, p.dg, p.ddg, p.y, p.z_rel].map(f64::to_bits));
        let (mut nones, mut somes) = (0, 0);
        for pose in poses_at_yaw(yaw) {
            for i in 0..=400 {
                let s0 = lo - 2.0 + (hi - lo + 4.0) * f64::from(i) / 400.0;
                for spread in [0.01, 0.3] {
                    let s = [0.0, 1.0, 2.0, 3.0].map(|k| s0 + spread * k);
                    let mut four = [None; 4];
                    side.each_x4(s, side.wheel().at_x4(s), &pose, |i, p| four[i] = Some(p));
                    for (lane, &si) in four.into_iter().zip(&s) {
                        let one = side.at(si, &pose);
                        (nones, somes) = (
                            nones + usize::from(one.is_none()),
                            somes + usize::from(one.is_some()),
                        );
                        assert_eq!(lane, one, "s = {si}");
                        assert_eq!(bits(lane), bits(one), "s = {si}");
                    }
                }
            }
        }
        assert!(nones > 0 && somes > 0);
    }
}

/// The breaks sorted by a check and two insertions are those `sort_by(f64::total_cmp)`
/// gives, bit for bit: increasing, decreasing and unordered inputs, ends inside, outside
/// and equal to a break, signed zeros.
#[test]
fn breaks_sorted_with_their_ends_are_those_of_a_sort() {
    let inputs: [&[f64]; 6] = [
        &[],
        &[1.0, 2.0, 2.0, 5.0],
        &[5.0, 2.0, 2.0, 1.0],
        &[3.0, 1.0, 2.0],
        &[-0.0, 0.0, 1.0],
        &[0.0, -0.0],
    ];
    let ends = [
        [0.5, 6.0],
        [2.0, 2.0],
        [-1.0, -0.0],
        [7.0, 0.0],
        [0.0, -0.0],
    ];
    for values in inputs {
        for extra in ends {
            let mut sorted = values.to_vec();
            sorted.extend(extra);
            sorted.sort_by(f64::total_cmp);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            let got = super::sorted_with(values.to_vec(), extra);
            assert_eq!(bits(&got), bits(&sorted), "{values:?} with {extra:?}");
        }
    }
}

/// The partition point found by walking from a guess is the bisection's, on the coarse
/// samples of S1002 (evenly spaced in `Yw`) and of the outline of a yaw (not evenly
/// spaced), for thresholds before, among and beyond the samples, and guesses that are far
/// off or NaN.
#[test]
fn partition_near_is_the_partition_point() {
    let placement = placement();
    for yaw in YAWS {
        let side = left_at_yaw(&placement, yaw);
        let coarse = &side.coarse;
        let (y0, y1) = (coarse[0][1], coarse[coarse.len() - 1][1]);
        let mut rng = crate::rng::SplitMix64::new(5);
        for _ in 0..2000 {
            let y = y0 - 5.0 + (y1 - y0 + 10.0) * rng.uniform();
            let below = |c: &[f64; 3]| c[1] < y;
            let expected = coarse.partition_point(below);
            for guess in [y, y + 30.0 * (rng.uniform() - 0.5), f64::NAN, -1e9, 1e9] {
                assert_eq!(
                    super::scan::partition_near(coarse, guess, below),
                    expected,
                    "yaw {yaw}, y {y}, guess {guess}"
                );
            }
        }
    }
}
