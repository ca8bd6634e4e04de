//! Contact-point jumps of a sweep, located to [`JUMP_REFINE_MM`](super::JUMP_REFINE_MM): the
//! interval of a jump is shrunk by the secant root of the difference of the two competing
//! minima, with bisection as the fallback.

use super::level::join_sides;
use super::{JUMP_CONFIRM_MM, JUMP_REFINE_MM, JUMP_SCREEN_MM, Jump, Position, side_index};
use crate::gap::{self, SideGap, SidePose};
use crate::track::Side;

/// Finds the intervals of `y_ws` across which a contact point jumps, refined to
/// [`JUMP_REFINE_MM`]. `solve(y_ws, theta0, cold, only)` solves one position, `cold` at the
/// first of a refinement; `only = Some(k)` asks for wheel `k` alone, which a `separable`
/// solver (the level wheelset, whose wheels do not interact) answers with that wheel's
/// half of the position (see `level.rs`): the refinement of a wheel's jump solves that
/// wheel only, and the other wheel only at the two ends of a confirmed jump.
///
/// A jump is where two local minima of the gap of one wheel, `A` (the contact before) and
/// `B` (after), exchange the role of the lowest: `h = g_A - g_B`, both followed at the
/// solved pose, changes sign there. While both can be followed at the ends of the interval,
/// the next position is the secant root of `h` (once the interval is narrow, two positions
/// straddling the root by less than half the refinement width: most jumps are located with
/// three solves instead of ten). Otherwise, or when that stops making progress, the interval
/// is bisected (an interval too wide to follow the minima across is bisected once and the
/// secant tried again: see [`SECANT_RETRY_WIDTH_MM`]).
pub(super) fn find_jumps(
    sides: &[SideGap; 2],
    positions: &[Position],
    separable: bool,
    mut solve: impl FnMut(f64, f64, bool, Option<usize>) -> Position,
) -> Vec<Jump> {
    let mut jumps = Vec::new();
    for w in positions.windows(2) {
        for side in [Side::Left, Side::Right] {
            let (Some(a), Some(b)) = (w[0].side(side), w[1].side(side)) else {
                continue;
            };
            if (a.s - b.s).abs() <= JUMP_SCREEN_MM {
                continue;
            }
            let k = side_index(side);
            let (mut pa, mut pb) = (w[0], w[1]);
            // Whether an end is a refinement's half position (separable solvers).
            let (mut a_half, mut b_half) = (false, false);
            let only = separable.then_some(k);
            let mut cold = true;
            let contact_s = |p: &Position| p.side(side).map_or(f64::NAN, |c| c.s);
            let motion = |pa: &Position, pb: &Position| (contact_s(pa) - contact_s(pb)).abs();
            let mut secant_steps = 0;
            // A jump keeps its size in the part of the interval that holds it; a contact
            // point that only moves fast moves less across each part, and once it moves less
            // than JUMP_CONFIRM_MM across the interval the candidate is dropped (most
            // candidates near the flange are such, after about 3 halvings instead of 10).
            while pb.y_ws - pa.y_ws > JUMP_REFINE_MM && motion(&pa, &pb) > JUMP_CONFIRM_MM {
                let width = pb.y_ws - pa.y_ws;
                let root = (secant_steps < MAX_SECANT_STEPS)
                    .then(|| competing_root(&sides[k], &pa, &pb, contact_s(&pa), contact_s(&pb)))
                    .flatten();
                // Without two competing minima now, bisection to the end; across an
                // interval wider than SECANT_RETRY_WIDTH_MM the minima may only have moved
                // out of reach, and the secant is tried again on the half bisection keeps.
                secant_steps = if root.is_some() || width > SECANT_RETRY_WIDTH_MM {
                    secant_steps + 1
                } else {
                    MAX_SECANT_STEPS
                };
                let ys: &[f64] = match root {
                    Some(r) if width <= STRADDLE_WIDTHS * JUMP_REFINE_MM => {
                        let half = 0.49 * JUMP_REFINE_MM;
                        &[
                            (r - half).max(pa.y_ws + 0.01 * width),
                            (r + half).min(pb.y_ws - 0.01 * width),
                        ]
                    }
                    // Kept off the ends, so that the interval shrinks.
                    Some(r) => &[r.clamp(pa.y_ws + 0.01 * width, pb.y_ws - 0.01 * width)],
                    None => &[0.5 * (pa.y_ws + pb.y_ws)],
                };
                let mut lost = false;
                for &y in ys {
                    // A second straddling position that the first already moved an end past
                    // is not solved: the interval only shrinks.
                    if !(y > pa.y_ws && y < pb.y_ws) {
                        continue;
                    }
                    // From the roll of the lower end: the refinement follows the branch the
                    // sweep came on (where two rolls balance the wheelset, as near a fold of
                    // a measured flange, a start between the ends can land on the other).
                    let mid = solve(y, pa.roll, cold, only);
                    cold = false;
                    let Some(m) = mid.side(side) else {
                        lost = true;
                        break;
                    };
                    if (m.s - contact_s(&pa)).abs() >= (m.s - contact_s(&pb)).abs() {
                        (pb, b_half) = (mid, separable);
                    } else {
                        (pa, a_half) = (mid, separable);
                    }
                }
                if lost {
                    break;
                }
            }
            if let (Some(ca), Some(cb)) = (pa.side(side), pb.side(side))
                && (ca.s - cb.s).abs() > JUMP_CONFIRM_MM
            {
                // The other wheel at the ends of a confirmed jump, for its Δr.
                let mut whole = |p: Position, half: bool| match half {
                    true => join_sides(&p, &solve(p.y_ws, p.roll, false, Some(1 - k)), k),
                    false => p,
                };
                let (pa, pb) = (whole(pa, a_half), whole(pb, b_half));
                jumps.push(Jump {
                    side,
                    y_from: pa.y_ws,
                    y_to: pb.y_ws,
                    s_from: ca.s,
                    s_to: cb.s,
                    delta_r_from: pa.delta_r(),
                    delta_r_to: pb.delta_r(),
                });
            }
        }
    }
    jumps
}

/// How far a competing minimum is followed from where it was (mm): across a jump interval
/// of 0.1 mm the contact points move by a few tenths of a millimetre.
const FOLLOW_REACH_MM: f64 = 1.0;
/// A secant that fails across an interval wider than this (mm) is tried again on the half
/// bisection keeps: there the competing minima may have moved further than
/// [`FOLLOW_REACH_MM`] from where they were at the ends (sweeps of 1 mm steps), while across
/// the paper sweep's 0.1 mm steps a failure means that they do not compete.
const SECANT_RETRY_WIDTH_MM: f64 = 0.2;
/// Secant steps of one jump refinement before it falls back to bisection.
const MAX_SECANT_STEPS: usize = 6;
/// An interval narrower than this many refinement widths is finished by straddling the
/// secant root.
const STRADDLE_WIDTHS: f64 = 100.0;

/// The secant root in `y_ws` of `h = g_A - g_B` between `pa` and `pb`, where `A` is the
/// minimum of the gap at `s_a` (the contact at `pa`) and `B` the one at `s_b`, each followed
/// at both poses; `None` when a minimum cannot be followed, `A` and `B` merge, or `h` does
/// not change sign.
fn competing_root(side: &SideGap, pa: &Position, pb: &Position, s_a: f64, s_b: f64) -> Option<f64> {
    let h = |p: &Position| -> Option<f64> {
        let pose = SidePose::new(side.sign, p.y_ws, p.roll);
        let reach = FOLLOW_REACH_MM;
        let a = side.minimum_within((s_a - reach, s_a + reach), s_a, &pose)?;
        let b = side.minimum_within((s_b - reach, s_b + reach), s_b, &pose)?;
        ((a.s - b.s).abs() > gap::SAME_BASIN_MM).then_some(a.g - b.g)
    };
    let (ha, hb) = (h(pa)?, h(pb)?);
    (ha < 0.0 && hb > 0.0).then(|| pa.y_ws - ha * (pb.y_ws - pa.y_ws) / (hb - ha))
}

#[cfg(test)]
mod tests {
    use super::super::minima::Scratch;
    use super::super::roll::solve_default;
    use super::super::{RollSettings, Solver, search};
    use super::*;
    use crate::scene::Scene;

    /// A sweep of 1 mm steps locates the jumps the paper sweep (0.1 mm steps) locates, and
    /// the secant, tried again on the halves of an interval too wide to follow the
    /// competing minima across, locates each of them with fewer solves than bisection (14
    /// from 1 mm to 1e-4 mm).
    #[test]
    fn jumps_across_wide_steps_are_located_by_the_secant() {
        let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
        let placement = crate::pipeline::place(&scene).unwrap();
        let coarse: Vec<f64> = (-15..=15).map(f64::from).collect();
        let wide = search(&placement, &coarse, Solver::default());
        let fine = search(&placement, scene.sweep_mm(), Solver::default());
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
        let jumps = find_jumps(&sides, window, false, |y, theta0, cold, _| {
            solves += 1;
            scratch.warm &= !cold;
            solve_default(&sides, &settings, y, theta0, &mut scratch)
        });
        assert_eq!(jumps.len(), 1, "{jumps:?}");
        // Measured: 9 solves (5 for the jump, 4 for the left wheel's candidate in the
        // window, which is no jump), 18 where a failed secant falls back to bisection.
        eprintln!("{solves} solves");
        assert!(solves <= 12, "{solves} solves");
    }

    /// A cold solve is a function of its shift and start roll alone, whatever was solved
    /// before with the same scratch (what `search` relies on to solve the first midpoint
    /// of a window once for both wheels): compared bit for bit through `Debug` at the
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
}
