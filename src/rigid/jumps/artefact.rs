//! Sampling artefacts told apart from jumps: a hop of a sampled profile's contact point
//! between two minima of the gap that a hollow shallower than [`ARTEFACT_HOLLOW_MM`]
//! separates. Classified before refining where the two minima can be followed to their
//! exchange ([`unrefined_artefact`]), by the hollow at the ends of a refined jump otherwise
//! ([`refined_hollow`]).

use super::{Follow, Refine, competing_minima, jump_between};
use crate::gap::GapPoint;
use crate::rigid::{
    ARTEFACT_HOLLOW_MM, JUMP_CONFIRM_MM, Jump, JumpKind, RigidPosition, side_index,
};
use crate::track::Side;

/// The artefact in the window `w` of a sweep where the contact point of `side` moves far,
/// without refining it, where the side's profiles are sampled: the two minima of the gap
/// that hold the contact at the window's ends, `A` (at the first) and `B` (at the second),
/// are followed (each within half their distance) at poses between the ends, the roll
/// there linear between the ends', to where they exchange the role of the lowest (see
/// [`exchange`]); there the hollow between them is measured. Two minima at least
/// [`JUMP_CONFIRM_MM`] apart (what a refined jump must move the contact point) with a
/// hollow shallower than
/// [`ARTEFACT_HOLLOW_MM`] (after adding the difference of their heights, by which the pose
/// may miss the exchange) is an artefact, reported over the window; anything else (`None`:
/// a deeper hollow, minima that cannot be followed, a contact point that moves continuously)
/// is refined as a jump (and dropped if its contact point only moves fast).
#[inline(never)]
pub(super) fn unrefined_artefact<'a>(
    solver: &mut impl Refine<'a>,
    side: Side,
    w: &[RigidPosition],
) -> Option<Jump> {
    let k = side_index(side);
    let (pa, pb) = (&w[0], &w[1]);
    let (ca, cb) = (pa.side(side)?, pb.side(side)?);
    if !solver.sides_at(pa.y_ws)[k].is_sampled() {
        return None;
    }
    let (pose_y, a, b) = exchange(solver, k, (pa, pb), (ca.s, cb.s))?;
    let gap = &solver.sides_at(pose_y.0)[k];
    let pose = gap.pose(pose_y.0, pose_y.1);
    let hollow = gap.hollow(&pose, (a.s, a.g), (b.s, b.g))?;
    // Two minima, as far apart as a confirmed jump moves the contact point.
    let two = hollow > RIDGE_MM && (a.s - b.s).abs() > JUMP_CONFIRM_MM;
    (two && hollow + (a.g - b.g).abs() < ARTEFACT_HOLLOW_MM)
        .then(|| jump_between(side, (pa, pb), hollow, JumpKind::Artefact))
}

/// The least rise of the gap between two points found as minima for them to be two minima
/// (mm): two minima of a smooth function have a ridge between them; a rise below this,
/// a thousand times the rounding of gaps near `-r0` (1e-13 mm), is one basin (a contact
/// point that moves continuously, found twice), and the window is refined as before.
const RIDGE_MM: f64 = 1e-10;

/// Two minima whose heights differ by less than this are at their exchange for
/// [`exchange`] (mm): a tenth of [`ARTEFACT_HOLLOW_MM`], which their difference is added to.
pub(in crate::rigid) const EXCHANGE_HEIGHT_MM: f64 = 0.1 * ARTEFACT_HOLLOW_MM;

/// Halvings of a window by which [`exchange`] narrows the shift where two minima exchange
/// the role of the lowest, at most: a window of 0.1 mm to 0.8 µm of shift, where their
/// heights differ by at most 1e-6 mm (their slopes in the shift differ by less than 1), far
/// below [`EXCHANGE_HEIGHT_MM`], which ends it sooner. The minima of the small hops of a
/// sampled profile coexist over a few micrometres of shift only (two of E1's are found at
/// the seventh halving, not the fifth). A window where the two are never found at one pose
/// by then (most often a contact point that moves continuously) is refined.
const EXCHANGE_HALVINGS: usize = 7;

/// Where the minimum `A` of the gap of wheel `k` (the contact at `pa`, at `s_a`) and the
/// minimum `B` (the contact at `pb`, at `s_b`) exchange the role of the lowest: the pose
/// `(y_ws, roll)` that bisection on `g_A - g_B` ends on, with both minima there. Each is
/// followed from where it was last found, in a bracket of its own (split halfway between
/// the two, reaching out by half their first distance); where only `A` is
/// found, `B` has not appeared yet (the exchange lies beyond), where only `B`, `A` has gone
/// (it lies before). Minima only, no positions solved: a pose costs two local
/// minimisations. `None` when the two are never found at one pose (a contact point that
/// moves continuously, or minima that cannot be followed).
fn exchange<'a>(
    solver: &mut impl Refine<'a>,
    k: usize,
    (pa, pb): (&RigidPosition, &RigidPosition),
    (s_a, s_b): (f64, f64),
) -> Option<((f64, f64), GapPoint, GapPoint)> {
    let follow = Follow::within_half(s_a, s_b);
    let (mut lo, mut hi) = (0.0, 1.0);
    let (mut last_a, mut last_b) = (s_a, s_b);
    let mut best = None;
    for _ in 0..EXCHANGE_HALVINGS {
        let t = 0.5 * (lo + hi);
        let y = pa.y_ws + t * (pb.y_ws - pa.y_ws);
        let roll = pa.roll + t * (pb.roll - pa.roll);
        let gap = &solver.sides_at(y)[k];
        let pose = gap.pose(y, roll);
        // Each in its own bracket, split halfway between where they were last found, so
        // that the two are never one minimum found twice.
        let (split, reach) = (0.5 * (last_a + last_b), follow.reach);
        let outwards = if last_a < last_b { -1.0 } else { 1.0 };
        let bracket = |from: f64, to: f64| (from.min(to), from.max(to));
        let a = gap.minimum_within(bracket(last_a + outwards * reach, split), last_a, &pose);
        let b = gap.minimum_within(bracket(split, last_b - outwards * reach), last_b, &pose);
        match (a, b) {
            (Some(a), Some(b)) if (a.s - b.s).abs() > follow.apart => {
                (last_a, last_b) = (a.s, b.s);
                if a.g < b.g {
                    lo = t;
                } else {
                    hi = t;
                }
                best = Some(((y, roll), a, b));
                if (a.g - b.g).abs() <= EXCHANGE_HEIGHT_MM {
                    // Close enough to the exchange: the hollow here is the hollow there
                    // to within this.
                    return best;
                }
            }
            (Some(a), None) => {
                last_a = a.s;
                lo = t;
            }
            (None, Some(b)) => {
                last_b = b.s;
                hi = t;
            }
            _ => return best,
        }
    }
    best
}

/// The hollow of a refined jump between `pa` (contact at `s_a`) and `pb` (at `s_b`): at
/// `pa`'s pose, between its contact and the minimum followed from `s_b`, or at `pb`'s the
/// other way round (mm); NaN where neither can be followed.
#[inline(never)]
pub(super) fn refined_hollow<'a>(
    solver: &mut impl Refine<'a>,
    k: usize,
    pa: &RigidPosition,
    pb: &RigidPosition,
    s_a: f64,
    s_b: f64,
) -> f64 {
    [pa, pb]
        .into_iter()
        .find_map(|p| {
            let gap = &solver.sides_at(p.y_ws)[k];
            let pose = gap.pose(p.y_ws, p.roll);
            let follow = Follow::within_half(s_a, s_b);
            let (a, b) = competing_minima(gap, &pose, s_a, s_b, follow)?;
            gap.hollow(&pose, (a.s, a.g), (b.s, b.g))
        })
        .unwrap_or(f64::NAN)
}
