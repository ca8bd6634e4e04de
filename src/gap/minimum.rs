//! The exact local minima of the gap: safeguarded Newton on `dg/ds = 0` inside a basin,
//! the basin sliding after a minimum that moved with the pose, and the one-sided limits at
//! the wheel profile's section joints.

use super::{Basin, COARSE_STEP_MM, GapPoint, SideGap, SidePose};

/// Convergence of the local minimisation in the wheel coordinate (mm).
const LOCAL_TOL_MM: f64 = 1e-11;
/// A local minimum this close to an end of its bracket, with the gap still falling
/// outwards, lies beyond the bracket (mm); the bisection stops within a few LOCAL_TOL_MM.
const AT_END_MM: f64 = 1e-8;
/// Distance below a section joint at which the other section's limit is evaluated (mm).
const JOINT_SIDE_MM: f64 = 1e-12;
/// A bracket end replaces the Newton point only when its gap is lower by this much (mm).
const END_PREFERENCE_MM: f64 = 1e-12;
/// How many bracket widths a basin may slide while its minimum is followed (about 10 mm).
const MAX_SLIDES: usize = 40;
/// Iterations of the safeguarded Newton search for one local minimum; 5-8 are used.
const LOCAL_MAX_ITER: usize = 100;

impl SideGap<'_> {
    /// The minimum of the gap in a basin: safeguarded Newton on `dg/ds = 0` inside the
    /// bracket, which slides when the minimum lies beyond it (the basin moved with the pose).
    pub(crate) fn minimum(
        &self,
        basin: Basin,
        start: Option<f64>,
        pose: &SidePose,
    ) -> Option<GapPoint> {
        let (dom_lo, dom_hi) = self.pair.wheel.profile().domain();
        let (mut lo, mut hi) = basin;
        let width = (hi - lo).max(COARSE_STEP_MM);
        for _slide in 0..MAX_SLIDES {
            let s0 = start
                .filter(|s| (lo..=hi).contains(s))
                .unwrap_or(0.5 * (lo + hi));
            let p = self.newton_in(lo, hi, s0, pose)?;
            let at_lo = p.s <= lo + AT_END_MM && p.dg > 0.0 && lo > dom_lo;
            let at_hi = p.s >= hi - AT_END_MM && p.dg < 0.0 && hi < dom_hi;
            if at_lo {
                hi = lo;
                lo = (lo - width).max(dom_lo);
            } else if at_hi {
                lo = hi;
                hi = (hi + width).min(dom_hi);
            } else {
                return Some(self.lowest_at_joints(p, lo, hi, pose));
            }
        }
        None
    }

    /// The minimum of the gap inside `basin` only: `None` when it lies at an end of the
    /// basin with the gap still falling outwards (the minimum has left it).
    pub(crate) fn minimum_within(
        &self,
        basin: Basin,
        start: f64,
        pose: &SidePose,
    ) -> Option<GapPoint> {
        let (lo, hi) = basin;
        let p = self.newton_in(lo, hi, start.clamp(lo, hi), pose)?;
        let beyond = (p.s <= lo + AT_END_MM && p.dg > 0.0) || (p.s >= hi - AT_END_MM && p.dg < 0.0);
        (!beyond).then(|| self.lowest_at_joints(p, lo, hi, pose))
    }

    /// `p`, or the one-sided limit of the gap at a section joint of the wheel profile inside
    /// `[lo, hi]` where that is clearly lower. A profile whose value jumps at a joint (S1002:
    /// 3.6e-5 mm at s = -26, 1.2e-4 mm at s = -35) can have its minimum there, which no
    /// derivative sees; missing it makes the minimum gap jump as the roll changes, and the
    /// roll iteration stall where the contact is nearly conformal.
    fn lowest_at_joints(&self, p: GapPoint, lo: f64, hi: f64, pose: &SidePose) -> GapPoint {
        let mut best = p;
        for &j in &self.joints {
            if j <= lo || j >= hi {
                continue;
            }
            // At the joint the field-side section is evaluated; just below it, the other.
            for s in [j, j - JOINT_SIDE_MM] {
                if let Some(q) = self.at(s, pose)
                    && q.g < best.g - END_PREFERENCE_MM
                {
                    best = q;
                }
            }
        }
        best
    }

    /// Before bisecting towards an end of the bracket not evaluated yet: that end, when the
    /// gap still falls outwards there (`dg` of the sign that points out of the bracket, as
    /// at `p`). The minimum then lies at or beyond that end, which the bisection would only
    /// confirm after about 36 halvings of a coarse bracket down to [`LOCAL_TOL_MM`]; the
    /// callers slide the basin on, as they did on the point the bisection left next to
    /// the end. The end evaluated is kept in `p_lo` / `p_hi` either way.
    fn falling_out_at_end(
        &self,
        p: &GapPoint,
        lo: f64,
        hi: f64,
        p_lo: &mut Option<Option<GapPoint>>,
        p_hi: &mut Option<Option<GapPoint>>,
        pose: &SidePose,
    ) -> Option<GapPoint> {
        let (end, cached, outwards) = if p.dg > 0.0 {
            (lo, p_lo, 1.0)
        } else {
            (hi, p_hi, -1.0)
        };
        if cached.is_some() {
            return None;
        }
        let q = self.at(end, pose);
        *cached = Some(q);
        q.filter(|q| q.dg * outwards > 0.0)
    }

    /// The minimum of the gap in `[lo, hi]` from `s0`: safeguarded Newton steps, bisection
    /// where a step leaves the bracket, the bracket ends where they are clearly lower.
    pub(super) fn newton_in(&self, lo: f64, hi: f64, s0: f64, pose: &SidePose) -> Option<GapPoint> {
        // Whether the wheel is yawed, decided once for the whole iteration: the unyawed
        // evaluations are the profile's alone, with no test and no outline between.
        if self.yawed() {
            self.newton_as::<true>(lo, hi, s0, pose)
        } else {
            self.newton_as::<false>(lo, hi, s0, pose)
        }
    }

    /// [`SideGap::newton_in`] on a side that is [`yawed`](SideGap::yawed) or not (`YAWED`).
    fn newton_as<const YAWED: bool>(
        &self,
        mut lo: f64,
        mut hi: f64,
        s0: f64,
        pose: &SidePose,
    ) -> Option<GapPoint> {
        // The bracket ends are evaluated only when needed: to start off the rail, to know
        // which side of the rail a step left, or as candidates when the iteration did not
        // end at a smooth interior minimum.
        let mut p_lo: Option<Option<GapPoint>> = None;
        let mut p_hi: Option<Option<GapPoint>> = None;
        let mut p = match self.at_as::<YAWED>(s0, pose) {
            Some(p) => p,
            None => {
                let a = self.at_as::<YAWED>(lo, pose);
                let b = self.at_as::<YAWED>(hi, pose);
                (p_lo, p_hi) = (Some(a), Some(b));
                a.or(b)?
            }
        };
        let mut smooth = false;
        for _ in 0..LOCAL_MAX_ITER {
            // Shrink the bracket with the sign of the derivative (minimum side).
            if p.dg > 0.0 {
                hi = p.s;
                p_hi = Some(Some(p));
            } else {
                lo = p.s;
                p_lo = Some(Some(p));
            }
            // A Newton step along Yw, which the derivatives are taken along, in `s` (`dy_ds`
            // is 1 without yaw: no division by it).
            let step = p.dg / p.ddg;
            let newton = p.s - if YAWED { step / p.wheel.dy_ds } else { step };
            let is_newton = p.ddg > 0.0 && newton > lo && newton < hi;
            if !is_newton
                && let Some(end) = self.falling_out_at_end(&p, lo, hi, &mut p_lo, &mut p_hi, pose)
            {
                return Some(end);
            }
            let next = if is_newton { newton } else { 0.5 * (lo + hi) };
            if (next - p.s).abs() < LOCAL_TOL_MM || hi - lo < LOCAL_TOL_MM {
                smooth = is_newton && (next - p.s).abs() < LOCAL_TOL_MM;
                break;
            }
            p = match self.at_as::<YAWED>(next, pose) {
                Some(q) => q,
                None => {
                    // Left the rail: the minimum lies on the defined side.
                    let lo_defined = *p_lo.get_or_insert_with(|| self.at_as::<YAWED>(lo, pose));
                    if lo_defined.is_none() {
                        lo = next;
                    } else {
                        hi = next;
                    }
                    continue;
                }
            };
        }
        if smooth {
            // A Newton step converged to an interior minimum of the smooth gap: the bracket
            // ends lie higher (they bound a basin of the coarse scan around it).
            return Some(p);
        }
        // The bracket ends are candidates too (a minimum at a value jump of the profile, or
        // at the end of the rail), but only when clearly lower: gaps near -r0 = -460 mm
        // resolve to about 1e-13 mm, and an end point "lower" by rounding would replace the
        // Newton solution by a point 1e-9 mm away from it.
        let p_lo = p_lo.unwrap_or_else(|| self.at_as::<YAWED>(lo, pose));
        let p_hi = p_hi.unwrap_or_else(|| self.at_as::<YAWED>(hi, pose));
        let mut best = p;
        for q in [p_lo, p_hi].into_iter().flatten() {
            if q.g < best.g - END_PREFERENCE_MM {
                best = q;
            }
        }
        Some(best)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A basin placed up to 4 mm beside the tread minimum, where the gap falls all the way
    /// to it, slides onto that minimum: the shortcut at the bracket ends ends each slide
    /// where the bisection ended it. Against a 0.0005 mm brute-force scan.
    #[test]
    fn a_basin_beside_the_minimum_slides_onto_it() {
        let placement = super::super::tests::placement();
        let side = SideGap::new(&placement.left, 1.0);
        let mut slid = 0;
        for i in 0..=14 {
            for roll in [0.0, 5e-3, -5e-3] {
                let pose = SidePose::new(1.0, -14.0 + 2.0 * f64::from(i), roll);
                let gap = |s: f64| side.at(s, &pose).map_or(f64::INFINITY, |p| p.g);
                // The lowest point of the tread (s > -20 mm, away from the flange), where it
                // is an interior minimum.
                let end = side.wheel().profile().domain().1;
                let n = ((end + 20.0) / 0.0005) as u32;
                let grid: Vec<f64> = (0..=n).map(|k| -20.0 + 0.0005 * f64::from(k)).collect();
                let (s_min, g_min) = grid
                    .iter()
                    .map(|&s| (s, gap(s)))
                    .min_by(|a, b| a.1.total_cmp(&b.1))
                    .unwrap();
                if s_min - grid[0] < 5.0 || grid[grid.len() - 1] - s_min < 5.0 {
                    continue;
                }
                for offset in [-4.0, -2.5, -1.0, 1.0, 2.5, 4.0] {
                    let centre = s_min + offset;
                    // Only where the gap falls monotonically from the basin to the minimum.
                    let path: Vec<f64> = grid
                        .iter()
                        .filter(|&&s| {
                            (s - s_min) * offset >= 0.0 && (s - s_min).abs() <= offset.abs() + 0.25
                        })
                        .map(|&s| gap(s))
                        .collect();
                    let falls = if offset > 0.0 {
                        path.windows(2).all(|w| w[1] >= w[0])
                    } else {
                        path.windows(2).all(|w| w[1] <= w[0])
                    };
                    if !falls {
                        continue;
                    }
                    let p = side
                        .minimum((centre - 0.25, centre + 0.25), None, &pose)
                        .unwrap();
                    assert!(
                        (p.s - s_min).abs() < 1e-3 && p.g <= g_min + 1e-12,
                        "pose {pose:?} offset {offset}: {} {} against {s_min} {g_min}",
                        p.s,
                        p.g
                    );
                    slid += 1;
                }
            }
        }
        assert!(slid > 100, "{slid} slides checked");
    }

    /// Whatever its start, the search in a bracket ends on a local minimum of the gap
    /// restricted to the bracket: no point within 1e-3 mm of it on the bracket is lower,
    /// beyond the rounding of the gap itself (up to about 1e-11 mm: near -460 mm, with the
    /// S1002 polynomials' cancellations; 1e-10 is allowed). Random brackets of 0.1 to 3 mm
    /// over the whole wheel, random starts and poses; an end returned with the gap falling
    /// into the bracket would fail.
    #[test]
    fn the_search_in_a_bracket_ends_on_a_local_minimum_of_the_bracket() {
        let placement = super::super::tests::placement();
        let side = SideGap::new(&placement.left, 1.0);
        let (dom_lo, dom_hi) = side.wheel().profile().domain();
        let mut rng = crate::rng::SplitMix64::new(11);
        let mut at_ends = 0;
        for _ in 0..4000 {
            let pose = SidePose::new(
                1.0,
                -15.0 + 30.0 * rng.uniform(),
                0.02 * (rng.uniform() - 0.5),
            );
            let lo = dom_lo + (dom_hi - dom_lo - 3.0) * rng.uniform();
            let hi = lo + 0.1 + 2.9 * rng.uniform();
            let s0 = lo + (hi - lo) * rng.uniform();
            let Some(p) = side.newton_in(lo, hi, s0, &pose) else {
                continue;
            };
            for d in [1e-9, 1e-6, 1e-4, 1e-3] {
                for s in [p.s - d, p.s + d] {
                    if let Some(q) = side.at(s, &pose).filter(|_| (lo..=hi).contains(&s)) {
                        assert!(
                            q.g >= p.g - 1e-10,
                            "{pose:?} [{lo}, {hi}] from {s0}: {} at {} but {} at {s}",
                            p.g,
                            p.s,
                            q.g
                        );
                    }
                }
            }
            // At an end, the gap does not fall into the bracket.
            let (at_lo, at_hi) = (p.s <= lo + AT_END_MM, p.s >= hi - AT_END_MM);
            assert!(
                !((at_lo && p.dg < 0.0) || (at_hi && p.dg > 0.0)),
                "{pose:?} [{lo}, {hi}] from {s0}: end {} with dg {}",
                p.s,
                p.dg
            );
            at_ends += usize::from(at_lo || at_hi);
        }
        assert!(at_ends > 100, "{at_ends} minima at a bracket end");
    }

    /// A start on the concave flank below a local maximum, with the bracket reaching past
    /// the local minimum beside it: the bisection towards that end must stop at the minimum,
    /// not at the end, where the gap falls into the bracket (a shortcut that took any end
    /// evaluated on the way would return it).
    #[test]
    fn a_bisection_towards_an_end_stops_at_the_minimum_before_it() {
        let placement = super::super::tests::placement();
        let side = SideGap::new(&placement.left, 1.0);
        let (dom_lo, dom_hi) = side.wheel().profile().domain();
        let mut cases = 0;
        for i in 0..=30 {
            let pose = SidePose::new(1.0, -15.0 + f64::from(i), 0.0);
            let n = ((dom_hi - dom_lo) / 0.01) as usize;
            let s: Vec<f64> = (0..=n).map(|k| dom_lo + 0.01 * k as f64).collect();
            let g: Vec<Option<GapPoint>> = s.iter().map(|&s| side.at(s, &pose)).collect();
            for k in 2..n - 2 {
                // A local maximum at k with a local minimum m within 3 mm below it in s.
                let (Some(a), Some(b), Some(c)) = (g[k - 1], g[k], g[k + 1]) else {
                    continue;
                };
                if !(b.g > a.g && b.g > c.g) {
                    continue;
                }
                let Some(m) = (k.saturating_sub(300)..k).rev().find(|&m| {
                    matches!((g[m - 1], g[m], g[m + 1]), (Some(x), Some(y), Some(z)) if y.g < x.g && y.g < z.g)
                }) else {
                    continue;
                };
                // Start where the gap rises and is concave, between the two.
                let Some(start) = (m + 1..k)
                    .rev()
                    .find(|&j| g[j].is_some_and(|p| p.dg > 0.0 && p.ddg < 0.0))
                else {
                    continue;
                };
                let lo = (s[m] - 0.5).max(dom_lo);
                if side.at(lo, &pose).is_none_or(|p| p.dg >= 0.0) {
                    continue;
                }
                let p = side.newton_in(lo, s[k], s[start], &pose).unwrap();
                assert!(
                    (p.s - s[m]).abs() < 0.02,
                    "{pose:?} [{lo}, {}] from {}: {} instead of the minimum near {}",
                    s[k],
                    s[start],
                    p.s,
                    s[m]
                );
                cases += 1;
            }
        }
        assert!(cases > 0, "no concave start below a maximum found");
    }
}
