//! The default roll solver: safeguarded Newton on `F = m_L - m_R` with the exact slope,
//! minima followed in their basins and verified by a scan at the solution.
//!
//! Laid out as an argmin-style solver: [`Iteration::evaluate`] computes `F` at the current
//! roll, [`Iteration::check`] (the termination check) says whether and why to stop,
//! [`Iteration::step`] moves the roll; the [`Bracket`] is their shared safeguard.

use super::minima::{Scratch, certify_minimum, keep_lowest_known, side_minimum};
use super::solve::{finish, no_contact};
use super::{RigidPosition, RollSettings, Stop};
use crate::gap::{GapPoint, SideGap, SidePose};

/// The envelope-theorem slope gives way to the secant of the last two iterates where the
/// residual fell by less than this factor in one step (slow, linear convergence: a minimum
/// held at the end of the rail's running surface, measured 0.66 per step).
const SLOW_RATIO: f64 = 0.5;
/// The secant step is held to this many times the last step.
const SECANT_STEP_LIMIT: f64 = 4.0;
/// Slope `dF/dtheta` assumed without a bracket and without a useful slope (mm/rad): the
/// tread's lever arm, 2 x 750 mm.
const FALLBACK_SLOPE_MM: f64 = 1500.0;

/// The bracket on the roll: `F < 0` at `lo`, `F > 0` at `hi` (infinite while unknown).
#[derive(Debug, Clone, Copy)]
struct Bracket {
    lo: f64,
    hi: f64,
}

impl Bracket {
    const OPEN: Bracket = Bracket {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// Narrows the bracket with the sign of `F(theta) = f`.
    #[inline]
    fn narrow(&mut self, theta: f64, f: f64) {
        if f > 0.0 {
            self.hi = self.hi.min(theta);
        } else {
            self.lo = self.lo.max(theta);
        }
    }

    /// Whether the bracket has shrunk to the last bits of a roll near `theta`.
    #[inline]
    fn collapsed(&self, theta: f64, settings: &RollSettings) -> bool {
        self.hi - self.lo <= settings.bracket_collapse_rad * theta.abs().max(1.0)
    }
}

/// What the termination check decided.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Verdict {
    /// Stop, for this reason.
    Stop(Stop),
    /// A root on basins not scanned at this pose: scan there and evaluate again, keeping the
    /// bracket only when it collapsed (it pins this roll).
    Verify { keep_bracket: bool },
    /// Take a step.
    Step,
}

/// `F` and the minima it comes from at one roll.
struct Evaluation {
    poses: [SidePose; 2],
    mins: [(GapPoint, Option<GapPoint>); 2],
    /// `F = m_L - m_R` (mm).
    f: f64,
}

/// The state of the roll iteration at one lateral position.
struct Iteration {
    y_ws: f64,
    theta: f64,
    iterations: usize,
    bracket: Bracket,
    /// Whether the next evaluation scans for basins.
    scan: bool,
    /// Whether the last evaluation scanned (its basins hold the lowest gap at its pose).
    fresh: bool,
    /// Whether the next evaluation re-examines the previous pose after a verification scan
    /// (the minima found there are reused).
    verify: bool,
    /// Whether the wheelset was already tried unrolled after losing contact.
    retried_level: bool,
    /// The roll at which the basins were last scanned (warm basins: about the start roll).
    scanned_theta: f64,
    /// The previous iterate `(theta, F)` on the same basins, for the secant slope.
    previous: Option<(f64, f64)>,
}

/// Newton on the roll with the exact derivative of `F = m_L - m_R`, safeguarded by a
/// bracket. The minima are followed in the basins of the previous solution (or of a scan
/// at `theta0` when there are none; the search moves each contact's basin to where the
/// continuation predicts its contact point); a root is accepted only when a scan at that very pose
/// found the basins it was computed from (the global check), otherwise the scan is made
/// there and the iteration goes on with its basins.
pub(super) fn solve_default(
    sides: &[SideGap; 2],
    settings: &RollSettings,
    y_ws: f64,
    theta0: f64,
    scratch: &mut Scratch,
) -> RigidPosition {
    let mut it = Iteration {
        y_ws,
        theta: theta0,
        iterations: 0,
        bracket: Bracket::OPEN,
        scan: !scratch.warm,
        fresh: false,
        verify: false,
        retried_level: false,
        scanned_theta: theta0,
        previous: None,
    };
    loop {
        it.iterations += 1;
        let Some(mut e) = it.evaluate(sides, settings, scratch) else {
            if it.recover_contact() {
                continue;
            }
            scratch.warm = false;
            return no_contact(y_ws, super::solve::yaw_of(sides), it.theta, it.iterations);
        };
        it.observe(&e, settings);
        let mut verdict = it.check(&e, settings);
        // The minima a root is accepted on are certified global (`gap::certify`); a lower
        // point found changes `F` and the verdict. Only fresh evaluations stop: on followed
        // basins a root is verified by a scan first, and the scan is what the certificate
        // reads. A provisional solve (a jump refinement's step) is certified by its caller
        // where it is kept.
        if matches!(verdict, Verdict::Stop(_))
            && it.fresh
            && !scratch.provisional
            && certify(sides, &mut e, scratch)
        {
            it.observe(&e, settings);
            verdict = it.check(&e, settings);
        }
        match verdict {
            Verdict::Stop(stop) => {
                scratch.warm = stop == Stop::Converged;
                let mut pos = finish(sides, y_ws, it.theta, e.mins, it.iterations, e.f);
                pos.stop = stop;
                return pos;
            }
            Verdict::Verify { keep_bracket } => {
                it.scan = true;
                it.verify = true;
                if !keep_bracket {
                    it.bracket = Bracket::OPEN;
                }
            }
            Verdict::Step => it.step(&e),
        }
    }
}

/// Certifies the minima of both wheels in `e` ([`certify_minimum`]); whether a lower point
/// was found (`e` then holds it and its `F`).
fn certify(sides: &[SideGap; 2], e: &mut Evaluation, scratch: &mut Scratch) -> bool {
    let mut lower = false;
    for (k, side) in sides.iter().enumerate() {
        let (basins, minima) = (&mut scratch.basins[k], &mut scratch.minima[k]);
        let (pose_box, scanned) = (&mut scratch.boxes[k], &mut scratch.scanned[k]);
        let found = &mut e.mins[k];
        lower |= certify_minimum(side, &e.poses[k], pose_box, scanned, basins, minima, found);
    }
    if lower {
        e.f = e.mins[0].0.g - e.mins[1].0.g;
    }
    lower
}

impl Iteration {
    /// `F` at the current roll from the minima of both wheels, scanning for basins first
    /// when asked to or when the roll moved past [`RollSettings::rescan_roll_rad`]; `None`
    /// when a wheel has no minimum above its rail.
    fn evaluate(
        &mut self,
        sides: &[SideGap; 2],
        settings: &RollSettings,
        scratch: &mut Scratch,
    ) -> Option<Evaluation> {
        let poses = SideGap::poses(sides, self.y_ws, self.theta);
        if (self.theta - self.scanned_theta).abs() > settings.rescan_roll_rad {
            // The wheel has turned so far that its points moved by more than the basins can
            // follow (r0 * rescan_roll_rad = 0.25 mm): scan again, and drop the bracket,
            // which may rest on minima of basins that no longer hold the lowest gap.
            self.scan = true;
            self.bracket = Bracket::OPEN;
        }
        self.fresh = self.scan;
        if self.scan {
            for k in 0..2 {
                let (boxes, scanned) = (&mut scratch.boxes[k], &mut scratch.scanned[k]);
                sides[k].basins(&poses[k], boxes, scanned, &mut scratch.basins[k]);
                if self.verify {
                    // A lower minimum the certificate found at this pose stays.
                    keep_lowest_known(&mut scratch.basins[k], &scratch.minima[k]);
                }
            }
            self.scan = false;
            self.scanned_theta = self.theta;
        }
        let [b0, b1] = &mut scratch.basins;
        let [m0, m1] = &mut scratch.minima;
        if !self.verify {
            // The pose changed: nothing is known at it.
            m0.clear();
            m1.clear();
        }
        let same = settings.same_minimum_mm;
        let left = side_minimum(&sides[0], &poses[0], b0, m0, same);
        let right = side_minimum(&sides[1], &poses[1], b1, m1, same);
        self.verify = false;
        let (left, right) = (left?, right?);
        Some(Evaluation {
            poses,
            mins: [left, right],
            f: left.0.g - right.0.g,
        })
    }

    /// After an evaluation without contact: whether to try again (rescanned, or unrolled).
    fn recover_contact(&mut self) -> bool {
        if !self.fresh {
            // The warm basins may have slid off the rail: scan before giving up.
            self.scan = true;
            return true;
        }
        if !self.retried_level {
            // A start roll extrapolated across a jump of the roll can turn the wheels off
            // their rails; no contact is declared only for the wheelset unrolled.
            self.retried_level = true;
            self.theta = 0.0;
            self.scan = true;
            self.bracket = Bracket::OPEN;
            return true;
        }
        false
    }

    /// Narrows the bracket with the evaluation, unless it is already a root.
    fn observe(&mut self, e: &Evaluation, settings: &RollSettings) {
        let within = e.f.abs() <= settings.residual_tol_mm;
        if !within {
            self.bracket.narrow(self.theta, e.f);
        }
    }

    /// The termination check: converged (on freshly scanned basins), verify a root found on
    /// followed basins, the iteration cap, a stalled bracket, or go on.
    fn check(&self, e: &Evaluation, settings: &RollSettings) -> Verdict {
        let within = e.f.abs() <= settings.residual_tol_mm;
        // A bracket collapsed to the last bit of the roll: where rounding of the gaps (about
        // 1e-13 mm each at |g| ~ 450 mm) keeps |F| just above the tolerance, the root is found
        // as well as doubles allow, and accepted within `collapsed_residual_mm`.
        let collapsed = !within && self.bracket.collapsed(self.theta, settings);
        if within || (collapsed && e.f.abs() <= settings.collapsed_residual_mm) {
            if self.fresh {
                return Verdict::Stop(Stop::Converged);
            }
            // Verify against a scan at the solution: a basin that was not a coarse minimum
            // where the basins were found may hold the lowest gap now. A bracket built on the
            // old basins is dropped (a collapsed one is kept: it pins this roll).
            return Verdict::Verify {
                keep_bracket: !within,
            };
        }
        if self.iterations >= settings.max_iter {
            return Verdict::Stop(Stop::IterationCap);
        }
        if collapsed {
            if !self.fresh {
                // No root between two rolls a bit apart: F jumps there. On followed basins
                // that is where one wheel's minimum was taken from a basin that no longer
                // holds its lowest gap (the lowest gap itself, and so F, is continuous in the
                // roll): scan at this pose, and drop the bracket built on those minima.
                return Verdict::Verify {
                    keep_bracket: false,
                };
            }
            return Verdict::Stop(Stop::Stalled);
        }
        Verdict::Step
    }

    /// The next roll: Newton with the envelope-theorem slope (or the secant where that
    /// converges slowly) inside the bracket, bisection when the step leaves it.
    fn step(&mut self, e: &Evaluation) {
        let (theta, f) = (self.theta, e.f);
        // dF/dtheta = dm_L/dphi_L + dm_R/dphi_R (phi_R = -theta): envelope theorem.
        let [(left, _), (right, _)] = e.mins;
        let mut slope = left.dg_dphi(&e.poses[0]) + right.dg_dphi(&e.poses[1]);
        // The envelope theorem holds at a smooth minimum; a minimum held at the end of the
        // rail's running surface moves with the roll in another way, and Newton with that
        // slope only gains a constant factor per step (0.66 measured: 60 iterations were not
        // enough). Where the residual fell by less than SLOW_RATIO, the secant slope of the
        // last two iterates (positive: F increases) takes over.
        // Only iterates on the same basins compare (a scan may have changed them), and the
        // secant step is held to SECANT_STEP_LIMIT times the last one.
        if self.fresh {
            self.previous = None;
        }
        if let Some((t0, f0)) = self.previous
            && f.abs() > SLOW_RATIO * f0.abs()
            && f.signum() == f0.signum()
            && (theta - t0).abs() > 0.0
        {
            let secant = (f - f0) / (theta - t0);
            if secant > 0.0 && (f / secant).abs() <= SECANT_STEP_LIMIT * (theta - t0).abs() {
                slope = secant;
            }
        }
        self.previous = Some((theta, f));
        let newton = theta - f / slope;
        let Bracket { lo, hi } = self.bracket;
        self.theta = if slope > 0.0 && newton > lo && newton < hi {
            newton
        } else if lo.is_finite() && hi.is_finite() {
            0.5 * (lo + hi)
        } else {
            // No bracket yet and a useless slope: step by the tread's lever arm.
            theta - f / FALLBACK_SLOPE_MM
        };
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Solver, search};
    use super::*;

    /// The settings the solver carries decide where it stops, and the position says why.
    #[test]
    fn the_settings_decide_where_the_iteration_stops() {
        let placement = crate::gap::tests::placement();
        let default = search(
            &placement,
            &crate::sweep::Sweep::from_slice(&[5.0]).unwrap(),
            Solver::default(),
        )
        .positions[0];
        assert_eq!(default.stop, Stop::Converged);
        assert!(default.residual <= RollSettings::default().residual_tol_mm);
        // At 5 mm the start roll (the centre's, 0) is off: the first evaluation is no root.
        assert!(default.iterations > 1, "{default:?}");
        let capped = RollSettings::default().with_max_iter(1).unwrap();
        let p = search(
            &placement,
            &crate::sweep::Sweep::from_slice(&[5.0]).unwrap(),
            Solver::Default(capped),
        )
        .positions[0];
        assert_eq!((p.stop, p.iterations), (Stop::IterationCap, 1));
        assert_eq!(p.stop.status_text(), "iteration cap");
    }
}
