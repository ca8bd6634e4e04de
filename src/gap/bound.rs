//! The bounds the certificate of the global minimum (`certify.rs`) stands on, and its deep
//! search of one coarse cell of the wheel where the cheap bounds do not reach the threshold.
//!
//! # The bounds
//!
//! On a cell `[a, b]` of the wheel coordinate, `h = b - a`, let `m <= g'' <= M` (the gap's
//! second derivative, where the cell holds no section joint of either profile):
//!
//! * interpolation: `g >= min(g(a), g(b)) - max(M, 0) h^2 / 8` (`g` less its linear
//!   interpolant is at least `-M (s - a)(b - s) / 2`, whose lowest is `-M h^2 / 8`);
//! * Taylor: `g(s) >= max(g(a) + g'(a) (s - a) + m (s - a)^2 / 2,
//!   g(b) + g'(b) (s - b) + m (s - b)^2 / 2)`, minimised over the cell ([`from_both_ends`]);
//! * convexity: where `m >= 0` on an interval holding a point `s_k`,
//!   `g(s) >= g(s_k) + g'(s_k) (s - s_k)` on it (the tangent lies below a convex function);
//! * zeroth order: `g >= z_min - Z_max`, the lowest the wheel can be over the cell against
//!   the highest the rail is under the lateral span it covers.
//!
//! `m` and `M` follow by interval arithmetic ([`curvature_range`]) from
//! `g'' = -cos F'' - Z'' dy^2 - Z' sin F''`, `dy = cos + sin F'` ([`SideGap::at`]), the
//! wheel's `F'`, `F''` over the cell ([`crate::profile::Profile::derivative_bounds`]: spline
//! pieces, arcs, polynomials, padded for rounding) and the rail's `Z'`, `Z''`, `Z` over its
//! lateral span (the rail profile's bounds rotated into the side frame, per 0.25 mm bin of
//! `Y` for coarse cells, exact for smaller ones). Across a joint the gap may step by the
//! profiles' value jumps and bend by their slope jumps: the bounds subtract `|jump of F| +
//! |jump of F'| h` per wheel joint and the rail's like terms (`WheelCell::jump`,
//! `SurfaceBounds::jump`).
//!
//! # The deep search of a cell
//!
//! A coarse cell whose cheap bounds stay below the threshold has its ends evaluated exactly
//! and is bounded by all of the above; where `m >= 0` the gap is convex on it and its minimum
//! is an end, a known minimum inside (flat tangent) or the one stationary point, which
//! Newton finds; otherwise it is split at the wheel's section joints (where its value may
//! jump) and at the known minima, and halved (to [`MAX_DEPTH`] halvings).

use super::{GapPoint, SideGap, SidePose};
use crate::profile::bounds::DerivativeBounds;
use crate::track::{SurfaceBounds, WheelCell, WheelCells};

/// How far below the lowest gap found a cell's bound must stay for the cell to be searched
/// (mm): far below the 1e-6 mm of the no-penetration check and of the brute-force
/// agreement, far above the rounding of gaps near `-r0` (1e-13 mm).
pub const CERTIFY_TOL_MM: f64 = 1e-9;
/// Halvings of a coarse cell after which a cell is given up uncertified
/// ([`Certificate::complete`](super::Certificate) false; 0.25 mm / 2^40 is 2e-13 mm, below
/// the rounding of the wheel coordinate).
const MAX_DEPTH: u32 = 40;
/// Cells this deep or less (a coarse cell is 0) bound the rail per bin of
/// [`PlacedRail::binned_bounds`](crate::track::PlacedRail); deeper ones bound it exactly over
/// their lateral span (two inversions of the rail profile).
const BINNED_DEPTH: u32 = 2;
/// Cells examined per certificate after which the search stops uncertified (a profile too
/// rough for the bound; never reached in the tests).
const MAX_CELLS: usize = 20_000;

/// A cell end: the wheel coordinate and the gap there (`None` off the rail).
#[derive(Debug, Clone, Copy)]
pub(super) struct End {
    s: f64,
    p: Option<GapPoint>,
}

/// A cell still to be bounded.
#[derive(Debug, Clone, Copy)]
pub(super) struct Cell {
    a: End,
    b: End,
    depth: u32,
    /// The coarse cells `i..j` it spans (a block, or one coarse cell), whose precomputed
    /// wheel bounds apply; `None` for a part of a coarse cell.
    coarse: Option<(usize, usize)>,
    /// How much lower than the lowest gap found a point of the cell must be to count (mm):
    /// the profiles' largest value jumps at joints, or the step of the gap at a wheel joint
    /// at an end of the cell where larger.
    slack: f64,
}

/// The search's state: the lowest point so far and the work done.
pub(super) struct Search {
    /// The lowest point found (at first the lowest known minimum).
    pub(super) best: GapPoint,
    /// `best.g -` [`CERTIFY_TOL_MM`]: a cell whose bound reaches it less the slack holds
    /// no point that counts.
    pub(super) threshold: f64,
    /// Whether every cell was bounded so far.
    pub(super) complete: bool,
    /// Cells examined.
    pub(super) cells: usize,
    stack: Vec<Cell>,
}

impl Search {
    /// A search from the lowest known minimum `best`.
    pub(super) fn new(best: GapPoint) -> Search {
        Search {
            best,
            threshold: best.g - CERTIFY_TOL_MM,
            complete: true,
            cells: 0,
            stack: Vec::new(),
        }
    }

    /// Takes `p` as the lowest point where it lies lower than the lowest so far by more
    /// than `slack`.
    pub(super) fn consider(&mut self, p: Option<GapPoint>, slack: f64) {
        if let Some(p) = p
            && p.g < self.best.g - slack
        {
            self.best = p;
            self.threshold = p.g - CERTIFY_TOL_MM;
        }
    }
}

impl SideGap<'_> {
    /// The deep search of the coarse cell `i` (between the coarse samples `i` and `i + 1`):
    /// its ends evaluated exactly, its parts bounded and searched until every one reaches
    /// the threshold less `slack` (the profiles' value jumps) or is searched to its minimum.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn search_cell(
        &self,
        i: usize,
        cells: &WheelCells,
        known: &[GapPoint],
        pose: &SidePose,
        slack: f64,
        search: &mut Search,
    ) {
        let cell = Cell {
            a: self.end(self.coarse[i][0], pose),
            b: self.end(self.coarse[i + 1][0], pose),
            depth: 0,
            coarse: Some((i, i + 1)),
            slack,
        };
        search.consider(cell.a.p, slack);
        search.consider(cell.b.p, slack);
        let mut stack = std::mem::take(&mut search.stack);
        stack.push(cell);
        while let Some(cell) = stack.pop() {
            search.cells += 1;
            if search.cells > MAX_CELLS {
                search.complete = false;
                stack.clear();
                break;
            }
            self.bound_cell(cell, cells, known, pose, search, &mut stack);
        }
        search.stack = stack;
    }

    fn end(&self, s: f64, pose: &SidePose) -> End {
        End {
            s,
            p: self.at(s, pose),
        }
    }

    /// Pushes the parts of `cell` (a coarse cell) between the wheel's section joints and the
    /// `known` minima inside; `false` (nothing pushed) where there are none.
    fn split(
        &self,
        cell: Cell,
        known: &[GapPoint],
        pose: &SidePose,
        stack: &mut Vec<Cell>,
    ) -> bool {
        let (a, b) = (cell.a.s, cell.b.s);
        let inside = |s: f64| a < s && s < b;
        // A joint at `b` too: `b` is evaluated on the joint's field side, the cell below it.
        let at_joint = |j: f64| a < j && j <= b;
        if !self.joints.iter().any(|&j| at_joint(j)) && !known.iter().any(|k| inside(k.s)) {
            return false;
        }
        let mut cuts: Vec<(End, End, f64)> = Vec::new();
        for &j in &self.joints {
            if at_joint(j) {
                // The section below the joint up to just below it, the one above from it.
                let (below, above) = (self.end(j - 1e-12, pose), self.end(j, pose));
                let step = match (below.p, above.p) {
                    (Some(p), Some(q)) => (p.g - q.g).abs(),
                    _ => 0.0,
                };
                cuts.push((below, above, step));
            }
        }
        for k in known {
            if inside(k.s) && self.joints.iter().all(|&j| (j - k.s).abs() > 1e-9) {
                let e = End {
                    s: k.s,
                    p: Some(*k),
                };
                cuts.push((e, e, 0.0));
            }
        }
        if cuts.is_empty() {
            return false;
        }
        cuts.sort_by(|x, y| x.0.s.total_cmp(&y.0.s));
        let (mut from, mut step_before) = (cell.a, cell.slack);
        for (below, above, step) in cuts {
            stack.push(Cell {
                a: from,
                b: below,
                depth: 1,
                coarse: None,
                slack: step_before.max(step),
            });
            (from, step_before) = (above, step);
        }
        stack.push(Cell {
            a: from,
            b: cell.b,
            depth: 1,
            coarse: None,
            slack: step_before.max(cell.slack),
        });
        true
    }

    /// Bounds `cell`: done when its bound reaches the threshold or its minimum is found
    /// (convex), otherwise its coarse cells (a block) or its halves are pushed.
    fn bound_cell(
        &self,
        cell: Cell,
        cells: &WheelCells,
        known: &[GapPoint],
        pose: &SidePose,
        search: &mut Search,
        stack: &mut Vec<Cell>,
    ) {
        count!(DeepCell, 1);
        let (a, b) = (cell.a.s, cell.b.s);
        if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
            return;
        }
        let wheel = match cell.coarse {
            Some((i, j)) => self.cells_over(cells, i, j),
            None => self.sub_cell(a, b),
        };
        let Some((lb, m)) = self.lower_bound(&cell, &wheel, pose) else {
            return;
        };
        if lb >= search.threshold - cell.slack {
            return;
        }
        if let (Some(pa), Some(pb), true) = (cell.a.p, cell.b.p, m >= 0.0 && wheel.jump == 0.0) {
            // Convex: the minimum is an end or the one stationary point between, and the
            // gap lies above the tangent at any point: at a known minimum inside, flat.
            // The cell's length along Yw, which `dg` is taken along.
            let length = if self.yawed() {
                pb.wheel.y - pa.wheel.y
            } else {
                b - a
            };
            let flat = known
                .iter()
                .find(|k| a < k.s && k.s < b && k.dg.abs() * length <= 0.5 * CERTIFY_TOL_MM);
            if let Some(k) = flat {
                search.consider(Some(*k), cell.slack);
            } else if pa.dg >= 0.0 || pb.dg <= 0.0 {
                search.consider(Some(if pa.g <= pb.g { pa } else { pb }), cell.slack);
            } else {
                search.consider(self.newton_in(a, b, 0.5 * (a + b), pose), cell.slack);
            }
            return;
        }
        if cell.coarse.is_some() && self.split(cell, known, pose, stack) {
            return;
        }
        if cell.depth >= MAX_DEPTH {
            search.complete = false;
            return;
        }
        let mid = self.end(0.5 * (a + b), pose);
        search.consider(mid.p, cell.slack);
        let depth = cell.depth + 1;
        stack.push(Cell {
            a: cell.a,
            b: mid,
            depth,
            coarse: None,
            slack: cell.slack,
        });
        stack.push(Cell {
            a: mid,
            b: cell.b,
            depth,
            coarse: None,
            slack: cell.slack,
        });
    }

    /// A lower bound of the gap on `cell` and the lower bound `m` of its second derivative
    /// (`-inf` where an end is off the rail); `None` where no point of the cell is over the
    /// rail.
    fn lower_bound(&self, cell: &Cell, wheel: &WheelCell, pose: &SidePose) -> Option<(f64, f64)> {
        let (a, b) = (cell.a.s, cell.b.s);
        let [y_lo, y_hi, z_lo] = span(pose, self.yw_range(a, b)?, wheel.z);
        let rail = &self.pair.rail;
        let r = if cell.depth <= BINNED_DEPTH {
            rail.binned_bounds(y_lo, y_hi)?
        } else {
            rail.surface_bounds(y_lo, y_hi)?
        };
        let zeroth = z_lo - r.z_max;
        let (Some(pa), Some(pb)) = (cell.a.p, cell.b.p) else {
            return Some((zeroth, f64::NEG_INFINITY));
        };
        let (m, big_m) = curvature_range(pose_trig(pose), &wheel.d, &r);
        // Along Yw, which the derivatives are taken along: `s` itself without yaw.
        let (ya, yb) = if self.yawed() {
            (pa.wheel.y, pb.wheel.y)
        } else {
            (a, b)
        };
        let h = yb - ya;
        let jump = joint_terms(wheel.jump, &r, pose.sin.abs());
        let interpolated = pa.g.min(pb.g) - big_m.max(0.0) * h * h / 8.0 - jump;
        let taylor = from_both_ends(ya, yb, (pa.g, pa.dg), (pb.g, pb.dg), m) - jump;
        // NaN (unbounded products) falls back to the zeroth order.
        let lb = [interpolated, taylor]
            .into_iter()
            .filter(|v| !v.is_nan())
            .fold(zeroth, f64::max);
        Some((lb, m))
    }
}

/// `[Y_lo, Y_hi, z_lo]`: the lateral span and the lowest height above the axle of wheel
/// points with `Yw` in `yw` and `Zw` in `zw` at `pose` (`Y = delta + cos Yw - sin Zw`,
/// `z = sin Yw + cos Zw`, extremes at the range ends).
#[inline]
pub(super) fn span(pose: &SidePose, yw: (f64, f64), zw: (f64, f64)) -> [f64; 3] {
    let (cos, sin) = (pose.cos, pose.sin);
    let (p, q) = (-sin * zw.0, -sin * zw.1);
    [
        pose.delta + cos * yw.0 + p.min(q),
        pose.delta + cos * yw.1 + p.max(q),
        (sin * yw.0).min(sin * yw.1) + cos * zw.0,
    ]
}

/// The range `(m, M)` of the gap's second derivative
/// `g'' = -cos F'' - Z'' dy^2 - Z' sin F''`, `dy = cos + sin F'`, for the wheel's `F'`, `F''`
/// in `wheel`, the rail's `Z'`, `Z''` in `rail` and `cos phi`, `sin phi` in `trig` (a pose:
/// [`pose_trig`], or a box of poses), by interval arithmetic; `(-inf, inf)` where a bound is
/// unbounded.
#[inline]
pub(super) fn curvature_range(
    [cos, sin]: [(f64, f64); 2],
    wheel: &DerivativeBounds,
    rail: &SurfaceBounds,
) -> (f64, f64) {
    let f2 = wheel.d2;
    let dy = product(sin, wheel.d1);
    let dy2 = square((cos.0 + dy.0, cos.1 + dy.1));
    let t1 = product(cos, f2);
    let t2 = product(rail.d2, dy2);
    let t3 = product(rail.slope, product(sin, f2));
    let (m, big_m) = (-t1.1 - t2.1 - t3.1, -t1.0 - t2.0 - t3.0);
    if m.is_nan() || big_m.is_nan() {
        (f64::NEG_INFINITY, f64::INFINITY)
    } else {
        (m, big_m)
    }
}

/// `cos phi` and `sin phi` of `pose` as the ranges [`curvature_range`] takes.
#[inline]
pub(super) fn pose_trig(pose: &SidePose) -> [(f64, f64); 2] {
    [(pose.cos, pose.cos), (pose.sin, pose.sin)]
}

/// What the section joints add to a bound from the derivatives (mm): the wheel's `jump`
/// (`|jump of F| + |jump of F'| L` per joint over a length `L`) times the largest factor by
/// which they reach the gap at `|sin phi| <= sin_abs` (`cos <= 1` for the value, `|cos + Z' sin| <= 1 + |Z'| |sin|`
/// for the slope), plus the rail's (`SurfaceBounds::jump`).
#[inline]
pub(super) fn joint_terms(wheel_jump: f64, rail: &SurfaceBounds, sin_abs: f64) -> f64 {
    if wheel_jump <= 0.0 {
        return rail.jump;
    }
    let slope = rail.slope.0.abs().max(rail.slope.1.abs());
    // `max` drops the NaN of an unbounded slope at no roll, where the term vanishes.
    wheel_jump * (1.0 + (slope * sin_abs).max(0.0)) + rail.jump
}

/// The product of two intervals; unbounded where a corner is NaN (`0 x inf`: `f64::min`
/// would pass over it).
#[inline]
fn product(x: (f64, f64), y: (f64, f64)) -> (f64, f64) {
    let c = [x.0 * y.0, x.0 * y.1, x.1 * y.0, x.1 * y.1];
    if c.iter().any(|v| v.is_nan()) {
        return (f64::NEG_INFINITY, f64::INFINITY);
    }
    (
        c.iter().copied().fold(f64::INFINITY, f64::min),
        c.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    )
}

/// The square of an interval.
#[inline]
fn square(x: (f64, f64)) -> (f64, f64) {
    let (p, q) = (x.0 * x.0, x.1 * x.1);
    if x.0 <= 0.0 && 0.0 <= x.1 {
        (0.0, p.max(q))
    } else {
        (p.min(q), p.max(q))
    }
}

/// The minimum over `[a, b]` of the larger of the two Taylor lower bounds
/// `g_a + g_a' (s - a) + m (s - a)^2 / 2` and `g_b + g_b' (s - b) + m (s - b)^2 / 2`. Their
/// difference is linear in `s`, so each dominates on one side of where they cross.
pub(super) fn from_both_ends(
    a: f64,
    b: f64,
    (ga, da): (f64, f64),
    (gb, db): (f64, f64),
    m: f64,
) -> f64 {
    let qa = |s: f64| ga + da * (s - a) + 0.5 * m * (s - a) * (s - a);
    let qb = |s: f64| gb + db * (s - b) + 0.5 * m * (s - b) * (s - b);
    // Minimum of one parabola over [lo, hi].
    let lowest = |q: &dyn Fn(f64) -> f64, x0: f64, g0: f64, d0: f64, lo: f64, hi: f64| {
        let mut v = q(lo).min(q(hi));
        if m > 0.0 {
            let vertex = x0 - d0 / m;
            if lo < vertex && vertex < hi {
                v = v.min(g0 - 0.5 * d0 * d0 / m);
            }
        }
        v
    };
    let (at_a, at_b) = (qa(a) - qb(a), qa(b) - qb(b));
    let on_a = |lo, hi| lowest(&qa, a, ga, da, lo, hi);
    let on_b = |lo, hi| lowest(&qb, b, gb, db, lo, hi);
    if (at_a >= 0.0) == (at_b >= 0.0) {
        if at_a + at_b >= 0.0 {
            on_a(a, b)
        } else {
            on_b(a, b)
        }
    } else {
        let cross = (a + (b - a) * at_a / (at_a - at_b)).clamp(a, b);
        if at_a >= 0.0 {
            on_a(a, cross).min(on_b(cross, b))
        } else {
            on_b(a, cross).min(on_a(cross, b))
        }
    }
}

#[cfg(test)]
#[path = "bound_tests.rs"]
mod tests;
