//! The level wheelset (no roll) of EN 15302 Annex E: each wheel lowered onto its own rail.

use super::minima::{Scratch, certify_minimum, side_minimum};
use super::{Position, RollSettings, finish, no_contact};
use crate::gap::{SideGap, SidePose};

/// Each wheel at roll 0 on its own rail: the global minimum of each side's gap over a fresh
/// scan of its basins, certified global (`gap::certify`). The axle height is the mean of the two wheels' own heights.
pub(super) fn solve_no_roll(sides: &[SideGap; 2], y_ws: f64, scratch: &mut Scratch) -> Position {
    // No roll iteration to tune: basins are told apart as by the default solver.
    let same = RollSettings::default().same_minimum_mm;
    let p = [
        SidePose::new(1.0, y_ws, 0.0),
        SidePose::new(-1.0, y_ws, 0.0),
    ];
    for k in 0..2 {
        sides[k].basins(
            &p[k],
            &mut scratch.boxes[k],
            &mut scratch.scanned[k],
            &mut scratch.basins[k],
        );
        scratch.minima[k].clear();
    }
    let [b0, b1] = &mut scratch.basins;
    let [m0, m1] = &mut scratch.minima;
    let mut mins = [
        side_minimum(&sides[0], &p[0], b0, m0, same),
        side_minimum(&sides[1], &p[1], b1, m1, same),
    ];
    for (k, found) in mins.iter_mut().enumerate() {
        if let Some(found) = found {
            let (pose_box, scanned) = (&mut scratch.boxes[k], &mut scratch.scanned[k]);
            let (basins, minima) = (&mut scratch.basins[k], &mut scratch.minima[k]);
            certify_minimum(&sides[k], &p[k], pose_box, scanned, basins, minima, found);
        }
    }
    match mins {
        [Some(left), Some(right)] => finish(sides, y_ws, 0.0, [left, right], 1, 0.0),
        _ => no_contact(y_ws, 0.0, 1),
    }
}
