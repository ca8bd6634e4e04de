//! The minima of each wheel's gap over its basins, followed from one pose to the next: the
//! step both the default roll solver and the level wheelset take per evaluation.

use super::TWO_POINT_GAP_TOL_MM;
use crate::gap::{self, Basin, GapPoint, PoseBox, Scanned, SideGap, SidePose};

/// Buffers reused across positions (no allocation per position). The basins of the last
/// solution start the next position (continuation): its scan at the solution verifies them.
#[derive(Debug, Default, Clone)]
pub(super) struct Scratch {
    pub(super) basins: [Vec<Basin>; 2],
    /// Per side, the block bounds of the scans over a box of poses about the last ones.
    pub(super) boxes: [PoseBox; 2],
    /// Per side, what the last scan for basins saw at its pose, for the certificate there.
    pub(super) scanned: [Scanned; 2],
    /// The minima found in `basins` at the current pose, reused after a verification scan
    /// at that same pose for the basins that contain them.
    pub(super) minima: [Vec<GapPoint>; 2],
    /// Whether `basins` holds the basins of a previous solution.
    pub(super) warm: bool,
    /// Whether the solves skip the certificate of the global minimum: the provisional
    /// positions a jump refinement steers by, whose kept ends it certifies itself
    /// (`jumps.rs`). False (certified) by default.
    pub(super) provisional: bool,
}

/// The lowest minimum of one side over its basins, and a second one within the two-point
/// tolerance in another basin. Each basin is re-centred on its minimum, so that the next
/// call (a nearby pose) starts there; a basin whose minimum another basin already found is
/// dropped ([`RollSettings::same_minimum_mm`](super::RollSettings::same_minimum_mm)).
///
/// `minima` holds on entry the minima already known at this very pose (or nothing); a basin
/// that contains one of them takes it instead of searching again. On return it holds the
/// minima of the basins.
pub(super) fn side_minimum(
    side: &SideGap,
    pose: &SidePose,
    basins: &mut Vec<Basin>,
    minima: &mut Vec<GapPoint>,
    same_minimum_mm: f64,
) -> Option<(GapPoint, Option<GapPoint>)> {
    let mut best: Option<GapPoint> = None;
    let mut second: Option<GapPoint> = None;
    let mut kept = 0;
    let known = minima.len();
    for i in 0..basins.len() {
        let b = basins[i];
        // The lowest of them: a basin of a scan can hold two minima (the certificate's
        // lower one and the one Newton found in it), and the higher is no minimum of it.
        let reuse = minima[..known]
            .iter()
            .filter(|q| (b.0..=b.1).contains(&q.s))
            .min_by(|p, q| p.g.total_cmp(&q.g))
            .copied();
        let Some(p) = reuse.or_else(|| side.minimum(b, None, pose)) else {
            continue;
        };
        minima.push(p);
        let duplicate = basins[..kept]
            .iter()
            .any(|k| (0.5 * (k.0 + k.1) - p.s).abs() <= same_minimum_mm);
        if !duplicate {
            let half = 0.5 * (b.1 - b.0);
            basins[kept] = (p.s - half, p.s + half);
            kept += 1;
        }
        match best {
            Some(q) if p.g >= q.g => {
                if (p.s - q.s).abs() > gap::SAME_BASIN_MM && second.is_none_or(|r| p.g < r.g) {
                    second = Some(p);
                }
            }
            _ => {
                if let Some(q) = best.filter(|q| (p.s - q.s).abs() > gap::SAME_BASIN_MM) {
                    second = Some(q);
                }
                best = Some(p);
            }
        }
    }
    basins.truncate(kept);
    minima.drain(..known);
    best.map(|b| (b, second.filter(|s| s.g - b.g <= TWO_POINT_GAP_TOL_MM)))
}

/// Certifies that `found` (the lowest minimum of one side at `pose` and a second one, from
/// [`side_minimum`], whose `minima` and `basins` these are) is the global minimum of the gap
/// ([`SideGap::certify_scanned`], with what the scan at `pose` saw); a lower point replaces
/// it and starts a basin of its own (the old minimum becomes the second where in another
/// basin and within the two-point tolerance). Whether a lower point was found.
pub(super) fn certify_minimum(
    side: &SideGap,
    pose: &SidePose,
    pose_box: &mut PoseBox,
    scanned: &mut Scanned,
    basins: &mut Vec<Basin>,
    minima: &mut Vec<GapPoint>,
    found: &mut (GapPoint, Option<GapPoint>),
) -> bool {
    let b = found.0;
    let Some(p) = side
        .certify_scanned(pose, b, minima, pose_box, scanned)
        .lower
    else {
        return false;
    };
    minima.push(p);
    basins.push((p.s - gap::COARSE_STEP_MM, p.s + gap::COARSE_STEP_MM));
    let second = if (p.s - b.s).abs() > gap::SAME_BASIN_MM {
        Some(b)
    } else {
        found.1
    };
    *found = (p, second.filter(|s| s.g - p.g <= TWO_POINT_GAP_TOL_MM));
    true
}

/// After a scan at the pose where `minima` were found (in basins followed from elsewhere):
/// keeps a basin about the lowest of them where the scan's `basins` miss it (a lower point
/// the certificate found inside one bracket of a scan), so that the evaluation after the
/// scan sees the same lowest gap.
pub(super) fn keep_lowest_known(basins: &mut Vec<Basin>, minima: &[GapPoint]) {
    let Some(low) = minima.iter().min_by(|p, q| p.g.total_cmp(&q.g)) else {
        return;
    };
    if !basins.iter().any(|b| (b.0..=b.1).contains(&low.s)) {
        basins.push((low.s - gap::COARSE_STEP_MM, low.s + gap::COARSE_STEP_MM));
    }
}

impl Scratch {
    /// Moves the warm basin centred on each side's previous contact point `s` to the
    /// predicted contact point `s_next`, `moved = [(s, s_next)]` per side (continuation); the
    /// others stay.
    pub(super) fn move_contact_basins(
        &mut self,
        moved: [Option<(f64, f64)>; 2],
        same_minimum_mm: f64,
    ) {
        for (basins, moved) in self.basins.iter_mut().zip(moved) {
            let Some((from, to)) = moved else {
                continue;
            };
            if let Some(b) = basins
                .iter_mut()
                .find(|b| (0.5 * (b.0 + b.1) - from).abs() <= same_minimum_mm)
            {
                let half = 0.5 * (b.1 - b.0);
                *b = (to - half, to + half);
            }
        }
    }
}
