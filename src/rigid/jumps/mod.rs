//! Contact-point jumps of a sweep, located to [`JUMP_REFINE_MM`](super::JUMP_REFINE_MM): the
//! interval of a jump is shrunk by the secant root of the difference of the two competing
//! minima, with bisection as the fallback.
//!
//! The parts: `refine.rs` narrows one candidate's window (secant or bisection), `steps.rs`
//! keeps a refinement's provisional solves and certifies its ends on what they saw, and
//! `artefact.rs` tells a sampling artefact from a jump (before refining where it can, by
//! the hollow at the ends of a refined jump otherwise). The two competing minima both
//! follow are here.

mod artefact;
mod refine;
mod steps;
#[cfg(test)]
mod tests;

use super::level::join_sides;
use super::minima::Scratch;
use super::{
    ARTEFACT_HOLLOW_MM, JUMP_CONFIRM_MM, JUMP_SCREEN_MM, Jump, JumpKind, RigidPosition, side_index,
};
use crate::gap::{self, GapPoint, SideGap};
use crate::track::Side;
#[cfg(test)]
pub(super) use artefact::EXCHANGE_HEIGHT_MM;
use artefact::{refined_hollow, unrefined_artefact};
use refine::{Task, WindowStart};
use steps::Steps;

/// What [`find_jumps`] refines with: a solve of one position, and the two sides' gaps as
/// they are at a shift (prepared for the yaw there, which may change along a sweep).
pub(super) trait Refine<'a> {
    /// The position at `y_ws` from the start roll `theta0`, as `ask` and `scratch` say.
    fn solve(&mut self, y_ws: f64, theta0: f64, ask: Ask, scratch: &mut Scratch) -> RigidPosition;
    /// The two sides' gaps at the shift `y_ws`.
    fn sides_at(&mut self, y_ws: f64) -> &[SideGap<'a>; 2];
}

/// Fixed sides (one yaw for the whole sweep) and a solve closure: what the unit tests
/// refine with.
#[cfg(test)]
pub(super) struct Fixed<'s, 'a, F> {
    /// The sides, prepared for the sweep's yaw.
    pub(super) sides: &'s [SideGap<'a>; 2],
    /// `solve(y_ws, theta0, ask, scratch)`.
    pub(super) solve: F,
}

#[cfg(test)]
impl<'s, 'a, F: FnMut(f64, f64, Ask, &mut Scratch) -> RigidPosition> Fixed<'s, 'a, F> {
    /// `solve` on `sides`.
    pub(super) fn new(sides: &'s [SideGap<'a>; 2], solve: F) -> Fixed<'s, 'a, F> {
        Fixed { sides, solve }
    }
}

#[cfg(test)]
impl<'a, F: FnMut(f64, f64, Ask, &mut Scratch) -> RigidPosition> Refine<'a> for Fixed<'_, 'a, F> {
    fn solve(&mut self, y_ws: f64, theta0: f64, ask: Ask, scratch: &mut Scratch) -> RigidPosition {
        (self.solve)(y_ws, theta0, ask, scratch)
    }

    fn sides_at(&mut self, _y_ws: f64) -> &[SideGap<'a>; 2] {
        self.sides
    }
}

/// What the refinement of a jump may ask of the solver.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Refinement {
    /// Whether the wheels do not interact (the level wheelset): a position can be solved
    /// for one wheel alone.
    pub(super) separable: bool,
    /// Whether the solver certifies its global minima (all but the paper's iteration): the
    /// positions a refinement steers by may then skip the certificate, which only the two
    /// ends a refinement stops at need.
    pub(super) certifying: bool,
    /// Whether a candidate is first examined as a sampling artefact, which is then not
    /// refined (every sweep); `false`: every candidate is refined and classified by the
    /// hollow at its refined ends (the tests' reference for the first).
    pub(super) artefacts_unrefined: bool,
}

/// Finds the intervals of `y_ws` across which a contact point jumps, refined to
/// [`JUMP_REFINE_MM`]. `solve(y_ws, theta0, ask, scratch)` solves one position as `ask`
/// says ([`Ask`]: one wheel only), cold (from no warm basins) at the first solve of a
/// refinement and certified or provisionally as `scratch` is set for it here
/// ([`Scratch::warm`], [`Scratch::provisional`]); a
/// [`separable`](Refinement::separable) solver (the level wheelset, whose wheels do not
/// interact) answers `only = Some(k)` with that wheel's half of the position (see
/// `level.rs`): the refinement
/// of a wheel's jump solves that wheel only, and the other wheel only at the two ends of a
/// confirmed jump.
///
/// A jump is where two local minima of the gap of one wheel, `A` (the contact before) and
/// `B` (after), exchange the role of the lowest: `h = g_A - g_B`, both followed at the
/// solved pose, changes sign there. While both can be followed at the ends of the interval,
/// the next position is the secant root of `h` (once the interval is narrow, two positions
/// straddling the root by less than half the refinement width: most jumps are located with
/// three solves instead of ten). Otherwise, or when that stops making progress, the interval
/// is bisected (an interval too wide to follow the minima across is bisected once and the
/// secant tried again: see [`SECANT_RETRY_WIDTH_MM`](refine::SECANT_RETRY_WIDTH_MM)).
///
/// The positions a refinement steers by are provisional (solved without the certificate of
/// the global minimum): only the two it ends on are reported, and those are certified on
/// what the solves' own scans saw ([`Steps::certified`]) before a jump is confirmed or a
/// candidate dropped. Where a certificate finds a lower point at an end, the refinement is
/// made again with every position certified, as each was before: a separable solver's
/// position depends on its shift alone, so the provisional steps before the first one a
/// certificate rejects are kept; otherwise it starts again from the window. So every
/// position the result rests on is certified, and the certificates of the discarded steps
/// (two thirds of them on the EN 15302 pair) are not made. A confirmed interval holds a
/// jump of the certified contact either way; a provisional step that was no global minimum
/// but left both ends certified may have steered to another jump of the same window than a
/// refinement certified throughout would find (on the paper scene and the EN 15302 pair
/// the jumps are those of such a refinement, bit for bit: the tests below and in
/// `level.rs`). A solver that certifies nothing (not [`certifying`](Refinement::certifying):
/// the paper's iteration) steers by the positions it reports.
pub(super) fn find_jumps<'a>(
    solver: &mut impl Refine<'a>,
    positions: &[RigidPosition],
    Refinement {
        separable,
        certifying,
        artefacts_unrefined,
    }: Refinement,
    scratch: &mut Scratch,
) -> Vec<Jump> {
    let mut jumps = Vec::new();
    let mut steps = Steps::default();
    for w in positions.windows(2) {
        let candidate = |side| {
            let (Some(a), Some(b)) = (w[0].side(side), w[1].side(side)) else {
                return false;
            };
            (a.s - b.s).abs() > JUMP_SCREEN_MM
        };
        let mut start = WindowStart {
            solved: None,
            keep: false,
        };
        for side in [Side::Left, Side::Right] {
            if !candidate(side) {
                continue;
            }
            start.keep = side == Side::Left && candidate(Side::Right);
            let k = side_index(side);
            if let Some(artefact) = artefacts_unrefined
                .then(|| unrefined_artefact(solver, side, w))
                .flatten()
            {
                jumps.push(artefact);
                continue;
            }
            let task = Task { side, separable };
            steps.clear();
            let record = certifying.then_some(&mut steps);
            let mut ends = task.refine(w, record, &[], scratch, &mut start, solver);
            let mut provisional = [ends[0].1, ends[1].1].into_iter().flatten();
            if !provisional.all(|i| steps.certified(solver, i, task.wheels())) {
                // The certified steps stand where the solver's positions depend on the shift
                // alone; the first step a certificate rejects is solved again, certified.
                let good = if separable {
                    (0..steps.len())
                        .find(|&i| !steps.certified(solver, i, task.wheels()))
                        .unwrap_or(steps.len())
                } else {
                    0
                };
                let known = steps.positions(good);
                ends = task.refine(w, None, &known, scratch, &mut start, solver);
            }
            let [(pa, _), (pb, _)] = ends;
            let (Some(ca), Some(cb)) = (pa.0.side(side), pb.0.side(side)) else {
                continue;
            };
            if (ca.s - cb.s).abs() <= JUMP_CONFIRM_MM {
                continue;
            }
            // The other wheel at the ends of a confirmed jump, for its Δr.
            let mut whole = |(p, half): (RigidPosition, bool)| {
                if !half {
                    return p;
                }
                let ask = Ask {
                    cold: false,
                    only: Some(1 - k),
                    certified: true,
                };
                join_sides(&p, &ask.solve(solver, p.y_ws, p.roll, scratch), k)
            };
            let (pa, pb) = (whole(pa), whole(pb));
            let hollow = refined_hollow(solver, k, &pa, &pb, ca.s, cb.s);
            let sampled = solver.sides_at(pa.y_ws)[k].is_sampled();
            let kind = if sampled && hollow < ARTEFACT_HOLLOW_MM {
                JumpKind::Artefact
            } else {
                JumpKind::Jump
            };
            jumps.push(jump_between(side, (&pa, &pb), hollow, kind));
        }
    }
    jumps
}

/// What [`find_jumps`] asks of a solve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Ask {
    /// The first solve of a refinement: from no warm basins.
    pub(super) cold: bool,
    /// `Some(k)`: wheel `k` alone (separable solvers).
    pub(super) only: Option<usize>,
    /// Whether the global minimum is certified (false: provisional, see
    /// [`Scratch::provisional`]).
    pub(super) certified: bool,
}

impl Ask {
    /// `solve(y_ws, theta0, self)`: from no warm basins when cold, provisional
    /// ([`Scratch::provisional`]) unless certified.
    fn solve<'a>(
        self,
        solver: &mut impl Refine<'a>,
        y_ws: f64,
        theta0: f64,
        scratch: &mut Scratch,
    ) -> RigidPosition {
        scratch.warm &= !self.cold;
        scratch.provisional = !self.certified;
        solver.solve(y_ws, theta0, self, scratch)
    }
}

/// The jump of `side`'s contact point from `pa` to `pb` (each with a contact on that side),
/// with the hollow between the two contacts and its kind.
fn jump_between(
    side: Side,
    (pa, pb): (&RigidPosition, &RigidPosition),
    hollow_mm: f64,
    kind: JumpKind,
) -> Jump {
    let s = |p: &RigidPosition| p.side(side).map_or(f64::NAN, |c| c.s);
    Jump {
        side,
        y_from: pa.y_ws,
        y_to: pb.y_ws,
        s_from: s(pa),
        s_to: s(pb),
        delta_r_from: pa.delta_r(),
        delta_r_to: pb.delta_r(),
        hollow_mm,
        kind,
    }
}

/// The minima of the gap at `pose` followed from `s_a` and from `s_b` as `follow` says,
/// when both exist and are two.
fn competing_minima(
    gap: &SideGap,
    pose: &gap::SidePose,
    s_a: f64,
    s_b: f64,
    Follow { reach, apart }: Follow,
) -> Option<(GapPoint, GapPoint)> {
    let a = gap.minimum_within((s_a - reach, s_a + reach), s_a, pose)?;
    let b = gap.minimum_within((s_b - reach, s_b + reach), s_b, pose)?;
    ((a.s - b.s).abs() > apart).then_some((a, b))
}

/// How far a competing minimum is followed from where it was (mm): across a jump interval
/// of 0.1 mm the contact points move by a few tenths of a millimetre.
const FOLLOW_REACH_MM: f64 = 1.0;

/// How two competing minima are followed: how far from where they were (mm), and how far
/// apart they must stay to count as two (mm).
#[derive(Clone, Copy)]
struct Follow {
    reach: f64,
    apart: f64,
}

impl Follow {
    /// The refinement's: [`FOLLOW_REACH_MM`], and minima in two basins
    /// ([`gap::SAME_BASIN_MM`]).
    const ACROSS_BASINS: Follow = Follow {
        reach: FOLLOW_REACH_MM,
        apart: gap::SAME_BASIN_MM,
    };

    /// Two minima `s_a` and `s_b` apart, each followed within half that distance (at most
    /// [`FOLLOW_REACH_MM`]), so that neither is followed into the other; any two distinct
    /// points count (the hops of a contact point between neighbouring undulations of a
    /// sampled profile, a few tenths of a millimetre).
    fn within_half(s_a: f64, s_b: f64) -> Follow {
        Follow {
            reach: (0.5 * (s_a - s_b).abs()).min(FOLLOW_REACH_MM),
            apart: 0.0,
        }
    }
}
