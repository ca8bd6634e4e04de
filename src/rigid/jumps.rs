//! Contact-point jumps of a sweep, located to [`JUMP_REFINE_MM`](super::JUMP_REFINE_MM): the
//! interval of a jump is shrunk by the secant root of the difference of the two competing
//! minima, with bisection as the fallback.

use super::level::join_sides;
use super::minima::Scratch;
use super::{
    ARTEFACT_HOLLOW_MM, JUMP_CONFIRM_MM, JUMP_REFINE_MM, JUMP_SCREEN_MM, Jump, JumpKind,
    RigidPosition, side_index,
};
use crate::gap::{self, GapPoint, PoseBox, Scanned, SideGap};
use crate::track::Side;

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
    /// positions a refinement steers by may then skip the certificate. Measured against
    /// refinements certified throughout (one thread, 10 alternated runs of `cargo bench
    /// --bench pipeline -- rigid_default`): the paper sweep 1.02 ms against 1.12 ms (8.57
    /// against 9.09 M instructions); a sweep of 31 positions in 1 mm steps 8.93 against
    /// 9.80 M instructions.
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
/// secant tried again: see [`SECANT_RETRY_WIDTH_MM`]).
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

/// The first solve of a window's refinements where no secant root is found: its midpoint,
/// cold, from the window's lower roll, the same for both wheels. The second wheel's
/// refinement takes the first's position and the state it left (a cold solve depends on
/// its shift and start roll alone: the test
/// `a_cold_solve_does_not_depend_on_what_was_solved_before`), instead of solving it again.
/// Measured (`cargo bench --bench pipeline`, one thread): a sweep of 31 positions in 1 mm
/// steps, where most windows are refined for both wheels, 1.099 ms without it against
/// 1.038 ms (16 paired runs; 8.93 against 8.40 M instructions); `rigid_default` 8.57
/// against 8.53 M.
///
/// The state is kept only where the right wheel's refinement may follow (its contact point
/// moves far in the window too): on the EN 15302 E1 pair no window has candidates on both
/// wheels, and the 16 copies made in vain cost 75 k instructions (callgrind) and their
/// allocations.
struct WindowStart {
    solved: Option<(Ask, RigidPosition, Scratch)>,
    /// Whether a second refinement of the window may read what the first solved.
    keep: bool,
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
struct Task {
    side: Side,
    separable: bool,
}

/// An end of a candidate interval: the position, whether it is a refinement's half
/// position (separable solvers), and the provisional step it was solved at (`None`:
/// certified, the sweep's or a certified refinement's).
type End = ((RigidPosition, bool), Option<usize>);

/// What a provisional solve's scans saw at its pose, per wheel: the scan, the pose box it
/// read (an index into [`Steps::boxes`]) and the minima found, as the solve's own
/// certificate would have read them.
#[derive(Debug, Default)]
struct Seen {
    scanned: [Scanned; 2],
    boxes: [usize; 2],
    minima: [Vec<GapPoint>; 2],
}

/// The provisional solves of one refinement in order, each with what it saw; buffers
/// reused across refinements.
#[derive(Debug, Default)]
struct Steps {
    done: Vec<(RigidPosition, Seen)>,
    pool: Vec<Seen>,
    /// The pose boxes the steps' scans read, per wheel, each box once: the solves of a
    /// refinement, 0.1 mm of shift apart at most, mostly read one box (it holds ±1 mm), and
    /// so do the refinements of neighbouring windows. Kept across refinements (the last box
    /// of each wheel), so that the certificates' cushions made in a box serve every
    /// certificate read against it, instead of each step's copy of the box making them
    /// again. Measured on the EN 15302 E1 pair (141 positions, mirrored, callgrind): the
    /// certificates of the jump search 0.81 -> 0.68 M instructions (the cushions made 271
    /// -> 28 times), a box copied once instead of at each of the 73 steps.
    boxes: Vec<(usize, PoseBox)>,
    box_pool: Vec<PoseBox>,
}

impl Steps {
    fn clear(&mut self) {
        self.pool.extend(self.done.drain(..).map(|(_, seen)| seen));
        // The last box of each wheel stays: the next refinement's first solves most often
        // read it again.
        let mut kept = 0;
        for i in 0..self.boxes.len() {
            let w = self.boxes[i].0;
            if self.boxes[i + 1..].iter().all(|(v, _)| *v != w) {
                self.boxes.swap(kept, i);
                kept += 1;
            }
        }
        self.box_pool
            .extend(self.boxes.drain(kept..).map(|(_, pose_box)| pose_box));
    }

    fn len(&self) -> usize {
        self.done.len()
    }

    /// The positions of the first `n` steps.
    fn positions(&self, n: usize) -> Vec<RigidPosition> {
        self.done[..n].iter().map(|(p, _)| *p).collect()
    }

    /// Records a provisional solve `p` with what its scans saw for `wheels`, taken from
    /// `scratch` (the scans are swapped: each keeps its own count of scans, so a buffer
    /// handed back to the solver stays consistent; the pose box is copied where it is not
    /// kept already); the step's index.
    fn push(&mut self, p: RigidPosition, scratch: &mut Scratch, wheels: &[usize]) -> usize {
        let mut seen = self.pool.pop().unwrap_or_default();
        for &w in wheels {
            std::mem::swap(&mut seen.scanned[w], &mut scratch.scanned[w]);
            seen.boxes[w] = self.box_index(w, &scratch.boxes[w]);
            seen.minima[w].clone_from(&scratch.minima[w]);
        }
        self.done.push((p, seen));
        self.done.len() - 1
    }

    /// The index in [`Steps::boxes`] of wheel `w`'s box `current`, copied there if it is
    /// not yet.
    fn box_index(&mut self, w: usize, current: &PoseBox) -> usize {
        let same = |(v, b): &(usize, PoseBox)| *v == w && b.made_at_same_pose(current);
        if let Some(i) = self.boxes.iter().rposition(same) {
            return i;
        }
        let mut pose_box = self.box_pool.pop().unwrap_or_default();
        pose_box.clone_from(current);
        self.boxes.push((w, pose_box));
        self.boxes.len() - 1
    }

    /// Whether step `i` holds the global minima of `wheels`: the certificate
    /// (`gap::certify`) finds no point lower than the contact by more than its tolerance,
    /// so that a certified solve gives the same position. It reads what the solve's scan
    /// saw at the step's pose, with the minima the solve found, as the solve's own
    /// certificate would have; a solve that stopped on a pose it did not scan (an
    /// iteration cap) is scanned again.
    fn certified<'a>(&mut self, solver: &mut impl Refine<'a>, i: usize, wheels: &[usize]) -> bool {
        let (p, seen) = &mut self.done[i];
        let boxes = &mut self.boxes;
        let sides = solver.sides_at(p.y_ws);
        wheels.iter().all(|&w| {
            let (side, Some(c)) = (&sides[w], p.contact[w]) else {
                return true;
            };
            let pose = side.pose(p.y_ws, p.roll);
            let minima = &seen.minima[w];
            let found = minima.iter().find(|m| m.s.to_bits() == c.s.to_bits());
            let Some(best) = found.copied().or_else(|| side.at(c.s, &pose)) else {
                return false;
            };
            let certificate = if seen.scanned[w].pose() == Some(pose) {
                let (pose_box, scanned) = (&mut boxes[seen.boxes[w]].1, &mut seen.scanned[w]);
                side.certify_scanned(&pose, best, minima, pose_box, scanned)
            } else {
                side.certify(&pose, best, &[best])
            };
            certificate.lower.is_none()
        })
    }
}

impl Task {
    /// The wheels whose minima a position's certificate covers: wheel `k` alone for a
    /// separable solver (its ends are halves), both otherwise (their minima balance the roll).
    fn wheels(&self) -> &'static [usize] {
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
    fn refine<'a>(
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
fn unrefined_artefact<'a>(
    solver: &mut impl Refine<'a>,
    side: super::Side,
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

/// The jump of `side`'s contact point from `pa` to `pb` (each with a contact on that side),
/// with the hollow between the two contacts and its kind.
fn jump_between(
    side: super::Side,
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

/// The least rise of the gap between two points found as minima for them to be two minima
/// (mm): two minima of a smooth function have a ridge between them; a rise below this,
/// a thousand times the rounding of gaps near `-r0` (1e-13 mm), is one basin (a contact
/// point that moves continuously, found twice), and the window is refined as before.
const RIDGE_MM: f64 = 1e-10;

/// Two minima whose heights differ by less than this are at their exchange for
/// [`exchange`] (mm): a tenth of [`ARTEFACT_HOLLOW_MM`], which their difference is added to.
pub(super) const EXCHANGE_HEIGHT_MM: f64 = 0.1 * ARTEFACT_HOLLOW_MM;

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
fn refined_hollow<'a>(
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

#[cfg(test)]
mod tests {
    use super::super::minima::Scratch;
    use super::super::roll::solve_default;
    use super::super::{RollSettings, Solver, search};
    use super::*;
    use crate::scene::Scene;
    use crate::sweep::Mirrored;

    /// With roll (the paper scene), the mirror images of the positions after the middle
    /// of a symmetric sweep are the positions solved before it, to the solver's accuracy:
    /// the roll solve of a mirrored position starts from the mirrored prediction, and its
    /// root is found to 1e-11 mm of residual, not bit for bit. The half after the middle
    /// is the same solves in the same order, bit for bit. The sweep is spaced evenly as
    /// `-15 + 30 i / 300`, whose opposite shifts differ in their last bits: mirrored all
    /// the same (`MIRRORED_SHIFT_MM`), each image reported at the sweep's own shift.
    #[test]
    fn a_symmetric_sweep_with_roll_mirrors_its_half() {
        let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
        let placement = crate::pipeline::place(&scene).unwrap();
        assert!(placement.is_mirror_symmetric());
        let sweep: Vec<f64> = (0..301)
            .map(|i| -15.0 + 30.0 * f64::from(i) / 300.0)
            .collect();
        let n = sweep.len();
        assert!((0..n / 2).any(|i| sweep[i].to_bits() != (-sweep[n - 1 - i]).to_bits()));
        let shifts = crate::sweep::Sweep::from_slice(&sweep).unwrap();
        assert!(shifts.is_symmetric());
        let mirrored = search(&placement, &shifts, Solver::default());
        for (i, p) in mirrored.positions.iter().enumerate() {
            let image = mirrored.positions[n - 1 - i].mirrored(sweep[i]);
            assert_eq!(format!("{p:?}"), format!("{image:?}"));
        }
        let solved = search(
            &placement.clone().without_mirroring(),
            &shifts,
            Solver::default(),
        );
        let (mut roll, mut s, mut r, mut height) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for (i, (m, p)) in mirrored.positions.iter().zip(&solved.positions).enumerate() {
            if i >= n / 2 {
                assert_eq!(format!("{m:?}"), format!("{p:?}"), "y = {}", p.y_ws);
                continue;
            }
            roll = roll.max((m.roll - p.roll).abs());
            height = height.max((m.axle_height - p.axle_height).abs());
            for k in 0..2 {
                let (a, b) = (m.contact[k].unwrap(), p.contact[k].unwrap());
                s = s.max((a.s - b.s).abs());
                r = r.max((a.r - b.r).abs());
            }
        }
        // Measured: roll 1.2e-14 rad, height 1.0e-11 mm, s 1.4e-10 mm, r 6.7e-11 mm: far
        // inside the accuracy the solver is held to against brute force (1e-6 mm, 1e-9 rad).
        assert!(
            roll < 1e-12 && height < 1e-9,
            "roll {roll:e} height {height:e}"
        );
        assert!(s < 1e-8 && r < 1e-9, "s {s:e} r {r:e}");
        assert_eq!(mirrored.jumps.len(), solved.jumps.len());
        assert!(mirrored.jumps.len() >= 6);
        for (m, p) in mirrored.jumps.iter().zip(&solved.jumps) {
            // The same jump, located to the same interval within 1e-9 mm (measured: 6e-11);
            // its ends' contacts within 1e-7 mm and Δr within 1e-7 mm (measured: 9e-9 and
            // 8e-9, at a near-conformal flange contact that moves 2.5e4 mm per radian of
            // roll, see tests/rigid.rs).
            assert_eq!(m.side, p.side);
            assert!((m.y_from - p.y_from).abs() < 1e-9 && (m.y_to - p.y_to).abs() < 1e-9);
            assert!((m.s_from - p.s_from).abs() < 1e-7 && (m.s_to - p.s_to).abs() < 1e-7);
            let dr = (m.delta_r_from - p.delta_r_from).abs() + (m.delta_r_to - p.delta_r_to).abs();
            assert!(dr < 1e-7, "{m:?} vs {p:?}");
        }
    }

    /// A sweep of 1 mm steps locates the jumps the paper sweep (0.1 mm steps) locates, and
    /// the secant, tried again on the halves of an interval too wide to follow the
    /// competing minima across, locates each of them with fewer solves than bisection (14
    /// from 1 mm to 1e-4 mm).
    #[test]
    fn jumps_across_wide_steps_are_located_by_the_secant() {
        let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
        let placement = crate::pipeline::place(&scene).unwrap();
        let coarse: Vec<f64> = (-15..=15).map(f64::from).collect();
        let wide = search(
            &placement,
            &crate::sweep::Sweep::from_slice(&coarse).unwrap(),
            Solver::default(),
        );
        let fine = search(&placement, scene.sweep(), Solver::default());
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
        let jumps = find_jumps(
            &mut Fixed::new(&sides, |y, theta0, _, scratch| {
                solves += 1;
                solve_default(&sides, &settings, y, theta0, scratch)
            }),
            window,
            Refinement {
                separable: false,
                certifying: true,
                artefacts_unrefined: true,
            },
            &mut scratch,
        );
        assert_eq!(jumps.len(), 1, "{jumps:?}");
        // Measured: 9 solves (5 for the jump, 4 for the left wheel's candidate in the
        // window, which is no jump), 18 where a failed secant falls back to bisection.
        eprintln!("{solves} solves");
        assert!(solves <= 12, "{solves} solves");
    }

    /// On the paper scene (the roll solver) refinements steered by provisional positions
    /// find the jumps of refinements certified throughout, bit for bit, and certify fewer
    /// positions.
    #[test]
    fn provisional_refinements_with_roll_give_the_jumps_of_certified_ones() {
        let placement = crate::gap::tests::placement();
        let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
        let sweep = search(&placement, scene.sweep(), Solver::default());
        let sides = SideGap::both(&placement);
        let settings = RollSettings::default();
        let [(certified, all), (steered, some)] = [false, true].map(|provisional| {
            let (mut scratch, mut certified) = (Scratch::default(), 0);
            let jumps = find_jumps(
                &mut Fixed::new(&sides, |y, theta0, ask, s| {
                    s.provisional = provisional && !ask.certified;
                    certified += usize::from(!s.provisional);
                    solve_default(&sides, &settings, y, theta0, s)
                }),
                &sweep.positions,
                Refinement {
                    separable: false,
                    certifying: true,
                    artefacts_unrefined: true,
                },
                &mut scratch,
            );
            (format!("{jumps:?}"), certified)
        });
        assert_eq!(steered, certified);
        eprintln!("{some} of {all} solves certified");
        assert!(some < all / 2, "{some} of {all} solves certified");
    }

    /// A cold solve is a function of its shift and start roll alone, whatever was solved
    /// before with the same scratch (what the sweep driver relies on to refine the windows
    /// of a sweep's two halves at once, each half with its own state): compared bit for
    /// bit through `Debug` at the
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
