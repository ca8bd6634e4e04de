//! The refinement of one candidate jump: its window narrowed to
//! [`JUMP_REFINE_MM`] by the secant root of the difference of the two competing minima where
//! both can be followed, by bisection otherwise (see [`super::find_jumps`]).

use super::steps::Steps;
use super::{Ask, Follow, Refine, competing_minima};
use crate::rigid::minima::Scratch;
use crate::rigid::{JUMP_CONFIRM_MM, JUMP_REFINE_MM, RigidPosition, side_index};
use crate::track::Side;

/// The first solve of a window's refinements where no secant root is found: its midpoint,
/// cold, from the window's lower roll, the same for both wheels. The second wheel's
/// refinement takes the first's position and the state it left (a cold solve depends on
/// its shift and start roll alone: the test
/// `a_cold_solve_does_not_depend_on_what_was_solved_before`), instead of solving it again:
/// a sweep of wide steps refines most windows for both wheels.
///
/// The state is kept only where the right wheel's refinement may follow (its contact point
/// moves far in the window too): a sampled pair such as EN 15302 E1's has windows with a
/// candidate on one wheel only, where a copy of the state would be made in vain.
pub(super) struct WindowStart {
    pub(super) solved: Option<(Ask, RigidPosition, Scratch)>,
    /// Whether a second refinement of the window may read what the first solved.
    pub(super) keep: bool,
}

impl WindowStart {
    /// `ask.solve` at the window's midpoint `y_ws` from `theta0`, or what the other wheel's
    /// refinement got there with the same `ask`.
    fn solve<'a>(
        &mut self,
        ask: Ask,
        y_ws: f64,
        theta0: f64,
        scratch: &mut Scratch,
        solver: &mut impl Refine<'a>,
    ) -> RigidPosition {
        if let Some((asked, p, after)) = &self.solved
            && *asked == ask
        {
            scratch.clone_from(after);
            return *p;
        }
        let p = ask.solve(solver, y_ws, theta0, scratch);
        if self.keep {
            self.solved = Some((ask, p, scratch.clone()));
        }
        p
    }
}

/// One wheel's candidate jumps in a sweep.
#[derive(Clone, Copy)]
pub(super) struct Task {
    pub(super) side: Side,
    pub(super) separable: bool,
}

/// An end of a candidate interval: the position, whether it is a refinement's half
/// position (separable solvers), and the provisional step it was solved at (`None`:
/// certified, the sweep's or a certified refinement's).
pub(super) type End = ((RigidPosition, bool), Option<usize>);

impl Task {
    /// The wheels whose minima a position's certificate covers: wheel `k` alone for a
    /// separable solver (its ends are halves), both otherwise (their minima balance the roll).
    pub(super) fn wheels(&self) -> &'static [usize] {
        match (self.separable, side_index(self.side)) {
            (false, _) => &[0, 1],
            (true, 0) => &[0],
            (true, _) => &[1],
        }
    }

    /// Narrows the window `w` on this wheel (see [`find_jumps`]): provisionally, recording
    /// each solve in `steps`, or (`None`) certified, the first solves being `known` (the
    /// certified positions of those steps).
    #[inline(never)]
    pub(super) fn refine<'a>(
        &self,
        w: &[RigidPosition],
        mut steps: Option<&mut Steps>,
        known: &[RigidPosition],
        scratch: &mut Scratch,
        start: &mut WindowStart,
        solver: &mut impl Refine<'a>,
    ) -> [End; 2] {
        let (side, k) = (self.side, side_index(self.side));
        let mut ends: [End; 2] = [((w[0], false), None), ((w[1], false), None)];
        let only = self.separable.then_some(k);
        let mut cold = true;
        let mut solved = 0;
        let contact_s = |p: &RigidPosition| p.side(side).map_or(f64::NAN, |c| c.s);
        let motion = |e: &[End; 2]| (contact_s(&e[0].0.0) - contact_s(&e[1].0.0)).abs();
        let mut secant_steps = 0;
        // A jump keeps its size in the part of the interval that holds it; a contact
        // point that only moves fast moves less across each part, and once it moves less
        // than JUMP_CONFIRM_MM across the interval the candidate is dropped (most
        // candidates near the flange are such, after about 3 halvings instead of 10).
        while ends[1].0.0.y_ws - ends[0].0.0.y_ws > JUMP_REFINE_MM
            && motion(&ends) > JUMP_CONFIRM_MM
        {
            let (pa, pb) = (ends[0].0.0, ends[1].0.0);
            let width = pb.y_ws - pa.y_ws;
            let root = (secant_steps < MAX_SECANT_STEPS)
                .then(|| competing_root(solver, k, &pa, &pb, contact_s(&pa), contact_s(&pb)))
                .flatten();
            // Without two competing minima now, bisection to the end; across an
            // interval wider than SECANT_RETRY_WIDTH_MM the minima may only have moved
            // out of reach, and the secant is tried again on the half bisection keeps.
            secant_steps = if root.is_some() || width > SECANT_RETRY_WIDTH_MM {
                secant_steps + 1
            } else {
                MAX_SECANT_STEPS
            };
            let (ys, n) = next_shifts(root, pa.y_ws, pb.y_ws);
            for &y in &ys[..n] {
                let (a, b) = (ends[0].0.0, ends[1].0.0);
                // A second straddling position that the first already moved an end past
                // is not solved: the interval only shrinks.
                if !(y > a.y_ws && y < b.y_ws) {
                    continue;
                }
                // From the roll of the lower end: the refinement follows the branch the
                // sweep came on (where two rolls balance the wheelset, as near a fold of
                // a measured flange, a start between the ends can land on the other).
                let ask = Ask {
                    cold,
                    only,
                    certified: steps.is_none(),
                };
                let mid = match known.get(solved) {
                    Some(p) => *p,
                    // The window's midpoint from its lower roll, cold: the same solve for
                    // both wheels' refinements.
                    None if cold && root.is_none() => start.solve(ask, y, a.roll, scratch, solver),
                    None => ask.solve(solver, y, a.roll, scratch),
                };
                (cold, solved) = (false, solved + 1);
                let Some(m) = mid.side(side) else {
                    return ends;
                };
                let step = steps
                    .as_deref_mut()
                    .map(|s| s.push(mid, scratch, self.wheels()));
                let kept = usize::from((m.s - contact_s(&a)).abs() >= (m.s - contact_s(&b)).abs());
                ends[kept] = ((mid, self.separable), step);
            }
        }
        ends
    }
}

/// The shifts to solve next in the interval `(lo, hi)`: around the secant `root` where the
/// interval is narrow (two positions straddling it by less than half the refinement
/// width), the root itself kept off the ends (so that the interval shrinks), or the
/// midpoint without a root; the first `n` of the array.
fn next_shifts(root: Option<f64>, lo: f64, hi: f64) -> ([f64; 2], usize) {
    let width = hi - lo;
    let (first, last) = (lo + 0.01 * width, hi - 0.01 * width);
    match root {
        Some(r) if width <= STRADDLE_WIDTHS * JUMP_REFINE_MM => {
            let half = 0.49 * JUMP_REFINE_MM;
            ([(r - half).max(first), (r + half).min(last)], 2)
        }
        Some(r) => ([r.clamp(first, last), f64::NAN], 1),
        None => ([0.5 * (lo + hi), f64::NAN], 1),
    }
}

/// A secant that fails across an interval wider than this (mm) is tried again on the half
/// bisection keeps: there the competing minima may have moved further than
/// [`FOLLOW_REACH_MM`](super::FOLLOW_REACH_MM) from where they were at the ends (sweeps of 1 mm steps), while across
/// the paper sweep's 0.1 mm steps a failure means that they do not compete.
pub(super) const SECANT_RETRY_WIDTH_MM: f64 = 0.2;
/// Secant steps of one jump refinement before it falls back to bisection.
const MAX_SECANT_STEPS: usize = 6;
/// An interval narrower than this many refinement widths is finished by straddling the
/// secant root.
const STRADDLE_WIDTHS: f64 = 100.0;

/// The secant root in `y_ws` of `h = g_A - g_B` between `pa` and `pb`, where `A` is the
/// minimum of the gap at `s_a` (the contact at `pa`) and `B` the one at `s_b`, each followed
/// at both poses; `None` when a minimum cannot be followed, `A` and `B` merge, or `h` does
/// not change sign.
fn competing_root<'a>(
    solver: &mut impl Refine<'a>,
    k: usize,
    pa: &RigidPosition,
    pb: &RigidPosition,
    s_a: f64,
    s_b: f64,
) -> Option<f64> {
    crossing(solver, k, (pa, pb), (s_a, s_b), Follow::ACROSS_BASINS)
}

/// [`competing_root`] with the minima followed as `follow` says.
fn crossing<'a>(
    solver: &mut impl Refine<'a>,
    k: usize,
    (pa, pb): (&RigidPosition, &RigidPosition),
    (s_a, s_b): (f64, f64),
    follow: Follow,
) -> Option<f64> {
    let mut h = |p: &RigidPosition| -> Option<f64> {
        let side = &solver.sides_at(p.y_ws)[k];
        let pose = side.pose(p.y_ws, p.roll);
        let (a, b) = competing_minima(side, &pose, s_a, s_b, follow)?;
        Some(a.g - b.g)
    };
    let (ha, hb) = (h(pa)?, h(pb)?);
    (ha < 0.0 && hb > 0.0).then(|| pa.y_ws - ha * (pb.y_ws - pa.y_ws) / (hb - ha))
}
