//! The rigid contact at one position: [`PositionSolver`] runs the chosen [`Solver`] on the
//! two sides' gaps, from a start roll and the state a previous position left (warm basins,
//! scans, certificates' pose boxes), and returns the position with why it stopped.

use super::level::solve_no_roll;
use super::minima::Scratch;
use super::paper::solve_paper;
use super::roll::solve_default;
use super::{PAPER_TABLE_STEP_MM, RigidPosition, SideContact, Solver, Stop};
use crate::gap::{GapPoint, SideGap, Yaw};
use crate::sweep::YawRule;
use crate::track::Placement;

/// The per-position solver of a sweep: state in ([`Scratch`]), position out, with its
/// [`Stop`]. The sweep driver (`driver.rs`) decides the order, the start rolls and what
/// is mirrored.
///
/// Its sides are prepared for one yaw at a time ([`SideGap::set_yaw`]): once for a sweep of
/// a fixed yaw; where the yaw changes along the sweep, each continuation owns a copy and
/// prepares it for each position ([`PositionSolver::prepare`]).
#[derive(Clone)]
pub(super) struct PositionSolver<'a> {
    sides: [SideGap<'a>; 2],
    solver: Solver,
    yaw: YawRule,
}

impl<'a> PositionSolver<'a> {
    /// `solver` on the two sides of `placement` (the paper's on its tabulated wheels), with
    /// the wheelset yawed by `yaw` (prepared for the centre's).
    pub(super) fn new(
        placement: &'a Placement,
        solver: Solver,
        yaw: YawRule,
    ) -> PositionSolver<'a> {
        let mut sides = SideGap::both(placement);
        if solver == Solver::Paper {
            sides = sides.map(|s| s.with_tables(PAPER_TABLE_STEP_MM));
        }
        for side in &mut sides {
            side.set_yaw_varies(yaw.varies());
        }
        let mut solver = PositionSolver { sides, solver, yaw };
        solver.prepare(0.0);
        solver
    }

    /// Whether the sides must be prepared for each position (a yaw that changes along the
    /// sweep).
    pub(super) fn yaw_varies(&self) -> bool {
        self.yaw.varies()
    }

    /// The wheelset's yaw at the shift `y_ws` (rad).
    pub(super) fn yaw_at(&self, y_ws: f64) -> f64 {
        self.yaw.at(y_ws)
    }

    /// The wheelset's yaw the sides are prepared for (rad).
    pub(super) fn prepared_yaw(&self) -> f64 {
        yaw_of(&self.sides)
    }

    /// Prepares the sides for the yaw at the shift `y_ws` (nothing to do where it is the
    /// yaw they have).
    pub(super) fn prepare(&mut self, y_ws: f64) {
        let yaw = self.yaw.at(y_ws);
        for side in &mut self.sides {
            side.set_yaw(Yaw::new(side.sign, yaw, self.yaw.model()));
        }
    }

    /// The two sides' gaps, left then right, as last prepared.
    pub(super) fn sides(&self) -> &[SideGap<'a>; 2] {
        &self.sides
    }

    /// The solver.
    pub(super) fn solver(&self) -> &Solver {
        &self.solver
    }

    /// The position at the shift `y_ws` from the start roll `theta0` (the roll solvers),
    /// reading and leaving the state in `scratch`; `only = Some(k)`: wheel `k` alone, where
    /// the wheels do not interact (the level wheelset, see `level.rs`). The sides must be
    /// prepared for `y_ws` (the gap's scans check the yaw of each pose).
    pub(super) fn solve(
        &self,
        y_ws: f64,
        theta0: f64,
        scratch: &mut Scratch,
        only: Option<usize>,
    ) -> RigidPosition {
        match &self.solver {
            Solver::Default(settings) => {
                solve_default(&self.sides, settings, y_ws, theta0, scratch)
            }
            Solver::Paper => solve_paper(&self.sides, y_ws),
            Solver::NoRoll => solve_no_roll(&self.sides, y_ws, scratch, only),
        }
    }
}

/// The wheelset's yaw the sides are prepared for (rad): the left side's own.
pub(super) fn yaw_of(sides: &[SideGap; 2]) -> f64 {
    sides[0].yaw().psi()
}

pub(super) fn no_contact(y_ws: f64, yaw: f64, theta: f64, iterations: usize) -> RigidPosition {
    RigidPosition {
        y_ws,
        yaw,
        roll: theta,
        axle_height: f64::NAN,
        contact: [None, None],
        iterations,
        stop: Stop::NoContact,
        residual: f64::NAN,
    }
}

pub(super) fn finish(
    sides: &[SideGap; 2],
    y_ws: f64,
    theta: f64,
    mins: [(GapPoint, Option<GapPoint>); 2],
    iterations: usize,
    residual: f64,
) -> RigidPosition {
    // Both minimum gaps are (nearly) equal; the axle height closes the mean of them.
    let axle_height = -0.5 * (mins[0].0.g + mins[1].0.g);
    RigidPosition {
        y_ws,
        yaw: yaw_of(sides),
        roll: theta,
        axle_height,
        contact: [0, 1].map(|k| Some(side_contact(&sides[k], theta, mins[k]))),
        iterations,
        stop: Stop::Converged,
        residual: residual.abs(),
    }
}

/// The contact of one wheel at its minimum gap `m` (with a second minimum) at roll `theta`.
pub(super) fn side_contact(
    side: &SideGap,
    theta: f64,
    (m, second): (GapPoint, Option<GapPoint>),
) -> SideContact {
    let phi = side.sign * theta;
    // The profile's own point: its curvature (the outline's differs by O(psi^2)), and
    // where on the circle the outline point lies.
    let (wheel_curvature, x, lead) = if side.has_yaw() {
        let profile = side.wheel().at(m.s);
        (
            profile.curvature(),
            side.yaw().x(&profile),
            side.yaw().lead(&profile),
        )
    } else {
        (m.wheel.curvature(), 0.0, 0.0)
    };
    SideContact {
        s: m.s,
        y: side.sign * m.y,
        z: m.rail.z,
        r: side.wheel().nominal_radius_mm() + side.wheel().profile().eval(m.s)[0],
        gamma: m.wheel.slope.atan() + phi,
        rail_u: side.pair.rail.profile_coordinate(m.y).unwrap_or(f64::NAN),
        rail_tan_gamma: m.rail.slope,
        wheel_curvature,
        rail_curvature: m.rail.curvature(),
        x,
        lead,
        second: second.map(|q| (q.s, q.g - m.g)),
    }
}
