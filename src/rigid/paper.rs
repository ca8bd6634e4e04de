//! The paper's roll iteration (its Eqs. 2-5) on the tabulated wheel profile.

use super::solve::{finish, no_contact, yaw_of};
use super::{PAPER_MAX_ITER, PAPER_TOL_MM, RigidPosition, Stop};
use crate::gap::SideGap;

pub(super) fn solve_paper(sides: &[SideGap; 2], y_ws: f64) -> RigidPosition {
    let mut theta = 0.0;
    let mut iterations = 0;
    loop {
        iterations += 1;
        let p = sides.each_ref().map(|side| side.pose(y_ws, theta));
        let (Some(left), Some(right)) = (
            sides[0].tabulated_minimum(&p[0]),
            sides[1].tabulated_minimum(&p[1]),
        ) else {
            return no_contact(y_ws, yaw_of(sides), theta, iterations);
        };
        let f = left.1 - right.1;
        let converged = f.abs() < PAPER_TOL_MM;
        if converged || iterations >= PAPER_MAX_ITER {
            // Contact quantities at the table points where the minima were found.
            let at = |k: usize, s: f64| sides[k].at(s, &p[k]);
            let (Some(l), Some(r)) = (at(0, left.0), at(1, right.0)) else {
                return no_contact(y_ws, yaw_of(sides), theta, iterations);
            };
            let mut pos = finish(sides, y_ws, theta, [(l, None), (r, None)], iterations, f);
            // The paper's height closes the tabulated gaps.
            pos.axle_height = -0.5 * (left.1 + right.1);
            if !converged {
                pos.stop = Stop::IterationCap;
            }
            return pos;
        }
        // Paper Eq. 3 with track-frame positions y_min,l = Y_l and y_min,r = -Y_r.
        theta += (right.1 - left.1) / (left.2 + right.2);
    }
}
