//! The default roll solver: safeguarded Newton on `F = m_L - m_R` with the exact slope,
//! minima followed in their basins and verified by a scan at the solution; and the level
//! wheelset (no roll) of EN 15302 Annex E.

use super::{
    COLLAPSED_RESIDUAL_MM, DEFAULT_MAX_ITER, Position, ROLL_RESIDUAL_TOL_MM, Stop,
    TWO_POINT_GAP_TOL_MM, finish, no_contact,
};
use crate::gap::{self, Basin, GapPoint, SideGap, SidePose};

/// Buffers reused across positions (no allocation per position). The basins of the last
/// solution start the next position (continuation): its scan at the solution verifies them.
#[derive(Debug, Default)]
pub(super) struct Scratch {
    pub(super) basins: [Vec<Basin>; 2],
    /// The minima found in `basins` at the current pose, reused after a verification scan
    /// at that same pose for the basins that contain them.
    minima: [Vec<GapPoint>; 2],
    /// Whether `basins` holds the basins of a previous solution.
    pub(super) warm: bool,
}

/// The lowest minimum of one side over its basins, and a second one within the two-point
/// tolerance in another basin. Each basin is re-centred on its minimum, so that the next
/// call (a nearby pose) starts there; a basin whose minimum another basin already found is
/// dropped.
///
/// `minima` holds on entry the minima already known at this very pose (or nothing); a basin
/// that contains one of them takes it instead of searching again. On return it holds the
/// minima of the basins.
fn side_minimum(
    side: &SideGap,
    pose: &SidePose,
    basins: &mut Vec<Basin>,
    minima: &mut Vec<GapPoint>,
) -> Option<(GapPoint, Option<GapPoint>)> {
    let mut best: Option<GapPoint> = None;
    let mut second: Option<GapPoint> = None;
    let mut kept = 0;
    let known = minima.len();
    for i in 0..basins.len() {
        let b = basins[i];
        let reuse = minima[..known]
            .iter()
            .find(|q| (b.0..=b.1).contains(&q.s))
            .copied();
        let Some(p) = reuse.or_else(|| side.minimum(b, None, pose)) else {
            continue;
        };
        minima.push(p);
        let duplicate = basins[..kept]
            .iter()
            .any(|k| (0.5 * (k.0 + k.1) - p.s).abs() <= SAME_MINIMUM_MM);
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

/// Two basins whose minima lie this close have slid onto the same minimum; one is dropped
/// (mm). Far above the local tolerance (1e-11 mm), far below any distance between two
/// distinct minima of a profile (joints are millimetres apart).
const SAME_MINIMUM_MM: f64 = 1e-6;
/// A bracket on the roll narrower than this has collapsed (rad).
const BRACKET_COLLAPSE_RAD: f64 = 1e-15;

/// Newton on the roll with the exact derivative of `F = m_L - m_R`, safeguarded by a
/// bracket. The minima are followed in the basins of the previous solution (or of a scan
/// at `theta0` when there are none); a root is accepted only when a scan at that very pose
/// found the basins it was computed from (the global check), otherwise the scan is made
/// there and the iteration goes on with its basins.
/// Roll change after which the default solver scans for basins again (rad): wheel points
/// move by about r0 * 5e-4 = 0.25 mm, one coarse step; smaller moves are followed by the
/// basins themselves. Large-roll wheelsets (very unequal radii) need it.
const RESCAN_ROLL_RAD: f64 = 5e-4;

pub(super) fn solve_default(
    sides: &[SideGap; 2],
    y_ws: f64,
    theta0: f64,
    scratch: &mut Scratch,
) -> Position {
    let poses = |theta: f64| {
        [
            SidePose::new(1.0, y_ws, theta),
            SidePose::new(-1.0, y_ws, theta),
        ]
    };
    let mut theta = theta0;
    let mut scan = !scratch.warm;
    let mut retried_level = false;
    // The roll at which the basins were last scanned (warm basins: about the start roll).
    let mut scanned_theta = theta0;
    // Whether this iteration re-examines the previous pose after a verification scan.
    let mut verify = false;
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    let mut iterations = 0;
    // The previous iterate `(theta, F)`, for the secant slope.
    let mut previous: Option<(f64, f64)> = None;
    loop {
        iterations += 1;
        let p = poses(theta);
        if (theta - scanned_theta).abs() > RESCAN_ROLL_RAD {
            // The wheel has turned so far that its points moved by more than the basins can
            // follow (r0 * RESCAN_ROLL_RAD = 0.25 mm): scan again, and drop the bracket,
            // which may rest on minima of basins that no longer hold the lowest gap.
            scan = true;
            (lo, hi) = (f64::NEG_INFINITY, f64::INFINITY);
        }
        let fresh = scan;
        if scan {
            for k in 0..2 {
                sides[k].basins(&p[k], &mut scratch.basins[k]);
            }
            scan = false;
            scanned_theta = theta;
        }
        let [b0, b1] = &mut scratch.basins;
        let [m0, m1] = &mut scratch.minima;
        if !verify {
            // The pose changed: nothing is known at it.
            m0.clear();
            m1.clear();
        }
        let mins = [
            side_minimum(&sides[0], &p[0], b0, m0),
            side_minimum(&sides[1], &p[1], b1, m1),
        ];
        verify = false;
        let (Some(left), Some(right)) = (mins[0], mins[1]) else {
            if !fresh {
                // The warm basins may have slid off the rail: scan before giving up.
                scan = true;
                continue;
            }
            if !retried_level {
                // A start roll extrapolated across a jump of the roll can turn the wheels
                // off their rails; no contact is declared only for the wheelset unrolled.
                retried_level = true;
                theta = 0.0;
                scan = true;
                (lo, hi) = (f64::NEG_INFINITY, f64::INFINITY);
                continue;
            }
            scratch.warm = false;
            return no_contact(y_ws, theta, iterations);
        };
        let f = left.0.g - right.0.g;
        let done = |stop: Stop| {
            let mut pos = finish(sides, y_ws, theta, [left, right], iterations, f);
            pos.stop = stop;
            pos
        };
        let within = f.abs() <= ROLL_RESIDUAL_TOL_MM;
        if !within {
            if f > 0.0 {
                hi = hi.min(theta);
            } else {
                lo = lo.max(theta);
            }
        }
        // A bracket collapsed to the last bit of the roll: where rounding of the gaps (about
        // 1e-13 mm each at |g| ~ 450 mm) keeps |F| just above the tolerance, the root is found
        // as well as doubles allow, and accepted within the promised COLLAPSED_RESIDUAL_MM.
        let collapsed = !within && hi - lo <= BRACKET_COLLAPSE_RAD * theta.abs().max(1.0);
        if within || (collapsed && f.abs() <= COLLAPSED_RESIDUAL_MM) {
            if fresh {
                scratch.warm = true;
                return done(Stop::Converged);
            }
            // Verify against a scan at the solution: a basin that was not a coarse minimum
            // where the basins were found may hold the lowest gap now. A bracket built on the
            // old basins is dropped (a collapsed one is kept: it pins this roll).
            scan = true;
            verify = true;
            if within {
                (lo, hi) = (f64::NEG_INFINITY, f64::INFINITY);
            }
            continue;
        }
        if iterations >= DEFAULT_MAX_ITER {
            scratch.warm = false;
            return done(Stop::IterationCap);
        }
        if collapsed {
            scratch.warm = false;
            return done(Stop::Stalled);
        }
        // dF/dtheta = dm_L/dphi_L + dm_R/dphi_R (phi_R = -theta): envelope theorem.
        let mut slope = left.0.dg_dphi(&p[0]) + right.0.dg_dphi(&p[1]);
        // The envelope theorem holds at a smooth minimum; a minimum held at the end of the
        // rail's running surface moves with the roll in another way, and Newton with that
        // slope only gains a constant factor per step (0.66 measured: 60 iterations were not
        // enough). Where the residual fell by less than half, the secant slope of the last
        // two iterates (positive: F increases) takes over.
        // Only iterates on the same basins compare (a scan may have changed them), and the
        // secant step is held to four times the last one.
        if fresh {
            previous = None;
        }
        if let Some((t0, f0)) = previous
            && f.abs() > 0.5 * f0.abs()
            && f.signum() == f0.signum()
            && (theta - t0).abs() > 0.0
        {
            let secant = (f - f0) / (theta - t0);
            if secant > 0.0 && (f / secant).abs() <= 4.0 * (theta - t0).abs() {
                slope = secant;
            }
        }
        previous = Some((theta, f));
        let newton = theta - f / slope;
        theta = if slope > 0.0 && newton > lo && newton < hi {
            newton
        } else if lo.is_finite() && hi.is_finite() {
            0.5 * (lo + hi)
        } else {
            // No bracket yet and a useless slope: step by the tread's lever arm, 2 x 750 mm.
            theta - f / 1500.0
        };
    }
}

/// Each wheel at roll 0 on its own rail: the global minimum of each side's gap over a fresh
/// scan of its basins. The axle height is the mean of the two wheels' own heights.
pub(super) fn solve_no_roll(sides: &[SideGap; 2], y_ws: f64, scratch: &mut Scratch) -> Position {
    let p = [
        SidePose::new(1.0, y_ws, 0.0),
        SidePose::new(-1.0, y_ws, 0.0),
    ];
    for k in 0..2 {
        sides[k].basins(&p[k], &mut scratch.basins[k]);
        scratch.minima[k].clear();
    }
    let [b0, b1] = &mut scratch.basins;
    let [m0, m1] = &mut scratch.minima;
    let mins = [
        side_minimum(&sides[0], &p[0], b0, m0),
        side_minimum(&sides[1], &p[1], b1, m1),
    ];
    match mins {
        [Some(left), Some(right)] => finish(sides, y_ws, 0.0, [left, right], 1, 0.0),
        _ => no_contact(y_ws, 0.0, 1),
    }
}
