//! The sweep driver of the rigid search: which positions are solved, in which order and from
//! which start (continuation outwards from the centre, the two directions in parallel), which
//! are mirrored, and the contact-point jumps between them. Each position is solved by the
//! [`PositionSolver`].

use super::continuation::Continuation;
use super::jumps::{Ask, Refine, Refinement, find_jumps};
use super::minima::Scratch;
use super::solve::PositionSolver;
use super::{Jump, RigidPosition, Solver};
use crate::gap::SideGap;
use crate::sweep::{Mirror, Sweep};

/// The solver a continuation or a refinement solves with: the sweep's own where the yaw is
/// fixed; where it changes along the sweep, copies prepared for the yaws of the last few
/// shifts asked for (a refinement goes back and forth between the two ends of its window
/// and the point between them), the least recently used prepared again.
struct Local<'s, 'a> {
    shared: &'s PositionSolver<'a>,
    /// Copies, most recently used last.
    own: Vec<PositionSolver<'a>>,
}

/// Copies a [`Local`] keeps: the two ends of a refinement's window and its next point.
const PREPARED_YAWS: usize = 3;

impl<'s, 'a> Local<'s, 'a> {
    fn new(shared: &'s PositionSolver<'a>) -> Local<'s, 'a> {
        Local {
            shared,
            own: Vec::new(),
        }
    }

    /// The solver prepared for the shift `y_ws`.
    fn at(&mut self, y_ws: f64) -> &PositionSolver<'a> {
        if !self.shared.yaw_varies() {
            return self.shared;
        }
        // As the sides store it: no yaw as +0.
        let key = (self.shared.yaw_at(y_ws) + 0.0).to_bits();
        let k = match self
            .own
            .iter()
            .position(|s| s.prepared_yaw().to_bits() == key)
        {
            Some(k) => k,
            None if self.own.len() < PREPARED_YAWS => {
                self.own.push(self.shared.clone());
                self.own.len() - 1
            }
            None => 0,
        };
        let mut solver = self.own.remove(k);
        solver.prepare(y_ws);
        self.own.push(solver);
        self.own.last().expect("pushed")
    }
}

impl<'a> Refine<'a> for Local<'_, 'a> {
    fn solve(&mut self, y_ws: f64, theta0: f64, ask: Ask, scratch: &mut Scratch) -> RigidPosition {
        self.at(y_ws).solve(y_ws, theta0, scratch, ask.only)
    }

    fn sides_at(&mut self, y_ws: f64) -> &[SideGap<'a>; 2] {
        self.at(y_ws).sides()
    }
}

/// Halves of a sweep shorter than this (positions) run one after the other on a calling
/// thread outside a rayon pool: starting the pool (its threads spawned, the job handed over
/// and the caller woken) costs as much as solving a few dozen positions, so that only a
/// half of about a hundred positions saves clearly more than it costs. Inside a pool (a
/// fleet, several scenes, the quasi-elastic pass already run) joining costs little and the
/// halves always run in parallel.
const PARALLEL_MIN_HALF: usize = 100;

/// The positions of `sweep`, continued outwards from the position nearest the centre,
/// each direction from the centre's roll `centre_roll`. With `mirror`, only the positions
/// from the middle on are solved (one direction) and those before it are their mirror
/// images. The two directions are independent continuations: they run in parallel
/// (rayon) and give the same results on any number of threads, or one after the other on
/// the calling thread where starting the pool would cost more ([`PARALLEL_MIN_HALF`]).
pub(super) fn positions(
    solve: &PositionSolver,
    sweep: &Sweep,
    mirror: Option<Mirror>,
    centre_roll: f64,
) -> Vec<RigidPosition> {
    let shifts = sweep.shifts_mm();
    let n = shifts.len();
    let start = match mirror {
        Some(mirror) => mirror.middle(),
        None => shifts
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
            .map_or(0, |(i, _)| i),
    };
    let forward = || continuation(solve, shifts, start..n, centre_roll);
    let backward = || continuation(solve, shifts, (0..start).rev(), centre_roll);
    if let Some(mirror) = mirror {
        return mirror.complete(forward(), |i| shifts[i]);
    }
    let in_pool = rayon::current_thread_index().is_some();
    let (forward, mut backward) = if in_pool || start.min(n - start) >= PARALLEL_MIN_HALF {
        rayon::join(forward, backward)
    } else {
        (forward(), backward())
    };
    backward.reverse();
    backward.extend(forward);
    backward
}

/// The positions at `indices` of `shifts`, in that order, each started from the roll the
/// positions before it predict (and, for the default solver, its contacts' basins where
/// the continuation predicts the contact points).
fn continuation(
    solve: &PositionSolver,
    shifts: &[f64],
    indices: impl Iterator<Item = usize>,
    centre_roll: f64,
) -> Vec<RigidPosition> {
    continued(solve, &[], indices.map(|i| shifts[i]), centre_roll)
}

/// The positions at the shifts `ys`, in that order, continued from the converged positions
/// `before` (in the order they were solved, the last nearest the first shift; none: from
/// the roll `roll`), each started from the roll the positions before it predict (and, for
/// the default solver, its contacts' basins where the continuation predicts the contact
/// points).
pub(super) fn continued(
    solve: &PositionSolver,
    before: &[RigidPosition],
    ys: impl Iterator<Item = f64>,
    roll: f64,
) -> Vec<RigidPosition> {
    let mut scratch = Scratch::default();
    let mut path = Continuation::new(roll);
    for p in before {
        path.push(p);
    }
    let mut local = Local::new(solve);
    ys.map(|y| {
        if let Solver::Default(settings) = solve.solver()
            && scratch.warm
        {
            scratch.move_contact_basins(path.moved_contacts(y), settings.same_minimum_mm);
        }
        let p = local.at(y).solve(y, path.predict(y), &mut scratch, None);
        path.push(&p);
        p
    })
    .collect()
}

/// The contact-point jumps between neighbouring `positions`, in the windows' order (the
/// left wheel's first within a window). With `mirror`, the windows from the middle
/// position on are refined and those before it are their mirror images, in order; the
/// middle window of an even sweep, its own mirror image, is refined as it is.
pub(super) fn jumps(
    solve: &PositionSolver,
    positions: &[RigidPosition],
    mirror: Option<Mirror>,
    scratch: &mut Scratch,
) -> Vec<Jump> {
    let Some(mirror) = mirror else {
        return jumps_of(solve, positions, scratch);
    };
    let (middle, n) = (mirror.middle(), positions.len());
    let after = jumps_of(solve, &positions[middle..], scratch);
    let mut jumps: Vec<Jump> = after.iter().rev().map(Jump::mirrored).collect();
    if n.is_multiple_of(2) {
        jumps.extend(jumps_in(solve, &positions[middle - 1..=middle], scratch));
    }
    jumps.extend(after);
    jumps
}

/// The jumps of the windows of `part`, refined with `scratch`. Each window's refinements
/// start cold (their results do not depend on what was solved before, only their work does:
/// the test `a_cold_solve_does_not_depend_on_what_was_solved_before`), so in a pool the two
/// halves of `part` are refined at once, the second with a state of its own, and their
/// jumps joined in the windows' order: the jumps of one pass.
fn jumps_of(solve: &PositionSolver, part: &[RigidPosition], scratch: &mut Scratch) -> Vec<Jump> {
    let in_pool = rayon::current_thread_index().is_some();
    if !(in_pool && part.len() > 2) {
        return jumps_in(solve, part, scratch);
    }
    let middle = part.len() / 2;
    let (mut low, high) = rayon::join(
        || jumps_in(solve, &part[..=middle], scratch),
        || jumps_in(solve, &part[middle..], &mut Scratch::default()),
    );
    low.extend(high);
    low
}

/// The jumps of the windows of `part`, refined one after the other with `scratch`.
pub(super) fn jumps_in(
    solve: &PositionSolver,
    part: &[RigidPosition],
    scratch: &mut Scratch,
) -> Vec<Jump> {
    let refinement = Refinement {
        // The level wheelset's wheels are solved one at a time.
        separable: *solve.solver() == Solver::NoRoll,
        // The paper's iteration certifies nothing: its refinements have no certificates
        // to skip.
        certifying: *solve.solver() != Solver::Paper,
        artefacts_unrefined: true,
    };
    find_jumps(&mut Local::new(solve), part, refinement, scratch)
}
