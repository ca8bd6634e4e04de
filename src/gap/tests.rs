//! The scans with block skipping against full scans, and the block bounds.

use super::scan::SCAN_BLOCK;
use super::*;
use crate::scene::Scene;

fn placement() -> crate::track::Placement {
    let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
    crate::pipeline::place(&scene).unwrap()
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
    let near_jumps: Vec<f64> = (0..=40)
        .flat_map(|i| {
            let d = 0.0025 * f64::from(i) - 0.05;
            [0.226 + d, 4.992 + d, 6.26 + d]
        })
        .collect();
    let sweep = crate::rigid::search(&placement(), &near_jumps, crate::rigid::Solver::default());
    poses.extend(
        sweep
            .positions
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

#[test]
fn skipping_blocks_finds_the_basins_and_low_regions_of_a_full_scan() {
    let placement = placement();
    let side = SideGap::new(&placement.left, 1.0);
    let (mut basins, mut regions) = (Vec::new(), Vec::new());
    let mut skipped_any = false;
    let mut several_basins = 0;
    for pose in poses() {
        let gaps = all_gaps(&side, &pose);
        let Some(lowest) = gaps.iter().map(|g| g.1).min_by(f64::total_cmp) else {
            continue;
        };
        // Basins: brackets around the sampled local minima within the margin.
        side.basins(&pose, &mut basins);
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
}

#[test]
fn block_bounds_are_below_every_sample_of_their_block() {
    let placement = placement();
    let side = SideGap::new(&placement.left, 1.0);
    for pose in poses() {
        for (i, g) in all_gaps(&side, &pose) {
            let bound = side.block_bound(i / SCAN_BLOCK, &pose);
            assert!(
                bound <= g,
                "sample {i}: bound {bound} above gap {g} at {pose:?}"
            );
        }
    }
}
