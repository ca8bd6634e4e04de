//! The vertical gap between one wheel and its rail for a wheelset pose, its minima, and the
//! derivative of the minimum gap with respect to the roll (envelope theorem).
//!
//! Per side the pose is seen in the side frame as a shift `delta = sign * y_ws` and a roll
//! `phi = sign * roll`. A wheel point `(Yw, Zw)` relative to the axle maps to
//! `Y = delta + cos(phi) Yw - sin(phi) Zw`, `z = h + sin(phi) Yw + cos(phi) Zw` (rotation about
//! the axle, paper Sect. 3; the lateral motion caused by roll is kept). The gap is
//! `d(s) = z(s) - Zrail(Y(s))`; without the axle height `h` it is `g(s) = d(s) - h`.

use crate::track::{HeightTable, PlacedWheel, RailPoint, SidePair, WheelPoint};

/// Step of the coarse scan of the wheel that finds the basins of the gap (mm). Refinement
/// then finds each minimum exactly; see [`COARSE_MARGIN_MM`].
pub const COARSE_STEP_MM: f64 = 0.25;
/// Coarse minima within this margin of the lowest coarse minimum are all refined. It bounds
/// the error of the coarse values (kappa h^2 / 2 = 0.006 mm for a relative curvature of
/// 1/5 mm^-1 at 0.25 mm) with a safety factor of 8.
pub const COARSE_MARGIN_MM: f64 = 0.05;
/// Coarse samples per block of the scans: a block whose lower bound of the gap (its lowest
/// wheel point against the highest rail point under it) is too high to matter is skipped.
const SCAN_BLOCK: usize = 8;
/// Block bounds kept on the stack by a scan (a wheel of 256 mm at the coarse step); a scan
/// over more computes them twice.
const MAX_SCAN_BLOCKS: usize = 128;

/// The coarse samples of block `b` inside `first..last`.
#[inline]
fn block_samples(b: usize, first: usize, last: usize) -> std::ops::Range<usize> {
    (b * SCAN_BLOCK).max(first)..((b + 1) * SCAN_BLOCK).min(last)
}
/// Two minima closer than this in the wheel coordinate are one basin (mm).
pub const SAME_BASIN_MM: f64 = 0.5;
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

/// The pose of one side: shift and roll as seen in the side frame.
///
/// Plain numbers rather than a `nalgebra::Isometry2` (used for the rail's frame in
/// `track::rail`): the gap is evaluated millions of times per sweep and only needs the
/// lateral position and height of a wheel point, `delta + cos s - sin z` and its height,
/// with the axle height solved separately; a general 2-D transform would carry what this
/// loop does not use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SidePose {
    /// `sign * y_ws` (mm).
    pub delta: f64,
    /// `cos(sign * roll)`.
    pub cos: f64,
    /// `sin(sign * roll)`.
    pub sin: f64,
}

impl SidePose {
    /// The pose of the side with `sign` (+1 left, -1 right) for a wheelset shift and roll.
    pub fn new(sign: f64, y_ws: f64, roll: f64) -> SidePose {
        let (sin, cos) = (sign * roll).sin_cos();
        SidePose {
            delta: sign * y_ws,
            cos,
            sin,
        }
    }

    /// Side-frame lateral position and height above the axle of a wheel point.
    #[inline]
    pub fn apply(&self, yw: f64, zw: f64) -> [f64; 2] {
        [
            self.delta + self.cos * yw - self.sin * zw,
            self.sin * yw + self.cos * zw,
        ]
    }
}

/// The gap at one wheel point, with everything the contact quantities need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GapPoint {
    /// Wheel profile coordinate (mm).
    pub s: f64,
    /// `g(s) = z - h - Zrail`: the gap without the axle height (mm).
    pub g: f64,
    /// `dg/ds`.
    pub dg: f64,
    /// `d2g/ds2` (1/mm).
    pub ddg: f64,
    /// Side-frame lateral position of the wheel point (mm).
    pub y: f64,
    /// Height of the wheel point above the axle (mm, negative).
    pub z_rel: f64,
    /// The wheel point (no roll).
    pub wheel: WheelPoint,
    /// The rail under it.
    pub rail: RailPoint,
}

impl GapPoint {
    /// Derivative of the gap at this point with respect to the side roll `phi`, the point
    /// held fixed: `(Y - delta) + Zrail'(Y) * z_rel`. At a unique minimiser it is the
    /// derivative of the minimum gap (envelope theorem).
    #[inline]
    pub fn dg_dphi(&self, pose: &SidePose) -> f64 {
        (self.y - pose.delta) + self.rail.slope * self.z_rel
    }
}

/// One side's geometry prepared for repeated gap evaluations: the placed pair and the coarse
/// wheel samples (the coarse scans read the rail's [`HeightTable`]). Built once per sweep.
#[derive(Debug, Clone)]
pub struct SideGap<'a> {
    /// The wheel and rail of the side.
    pub pair: &'a SidePair,
    /// +1 left, -1 right.
    pub sign: f64,
    coarse: Vec<[f64; 3]>,
    /// Per block of [`SCAN_BLOCK`] coarse samples: `[Yw_lo, Yw_hi, Zw_lo, Zw_hi]`.
    blocks: Vec<[f64; 4]>,
    tabulated: Option<Tables>,
    /// The wheel profile's domain: beyond it the profile is clamped, and a point there
    /// would be a phantom of the wheel's end displaced sideways.
    domain: (f64, f64),
    /// Section joints of the wheel profile (where its value may jump).
    joints: Vec<f64>,
    /// Side-frame lateral positions of the rail profile's breaks
    /// ([`crate::profile::Profile::breaks`]) and of the ends of its running surface, increasing.
    rail_break_ys: Vec<f64>,
    /// The wheel profile's breaks and the ends of its domain, increasing.
    wheel_breaks: Vec<f64>,
}

/// Tabulated wheel `(s, Yw, Zw)` and rail, for the paper's solver.
#[derive(Debug, Clone)]
struct Tables {
    wheel: Vec<[f64; 3]>,
    rail: HeightTable,
}

/// Keeps the coarse minimum `(g, i)` among the lowest `found.len()`.
#[inline]
fn record(found: &mut [(f64, usize); 16], count: &mut usize, g: f64, i: usize) {
    if *count < found.len() {
        found[*count] = (g, i);
        *count += 1;
    } else if let Some(worst) = found
        .iter_mut()
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .filter(|w| w.0 > g)
    {
        *worst = (g, i);
    }
}

/// A bracket `[lo, hi]` in `s` around a coarse minimum, to be refined.
pub type Basin = (f64, f64);

impl<'a> SideGap<'a> {
    /// Prepares the side with `sign` (+1 left, -1 right).
    pub fn new(pair: &'a SidePair, sign: f64) -> SideGap<'a> {
        let (lo, hi) = pair.wheel.profile().domain();
        let n = ((hi - lo) / COARSE_STEP_MM).ceil() as usize;
        let coarse: Vec<[f64; 3]> = (0..=n)
            .map(|i| {
                let s = lo + (hi - lo) * i as f64 / n as f64;
                let p = pair.wheel.at(s);
                [s, p.y, p.z]
            })
            .collect();
        let blocks = coarse
            .chunks(SCAN_BLOCK)
            .map(|c| {
                let (z_lo, z_hi) = c
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                        (a.min(p[2]), b.max(p[2]))
                    });
                [c[0][1], c[c.len() - 1][1], z_lo, z_hi]
            })
            .collect();
        SideGap {
            pair,
            sign,
            coarse,
            blocks,
            tabulated: None,
            domain: (lo, hi),
            joints: pair.wheel.profile().joints(),
            rail_break_ys: {
                // The ends of the running surface too: beyond them the gap is undefined.
                let (y_lo, y_hi) = pair.rail.y_range();
                let mut ys: Vec<f64> = pair
                    .rail
                    .profile()
                    .breaks()
                    .into_iter()
                    .map(|u| pair.rail.point_of(u)[0])
                    .chain([y_lo, y_hi])
                    .collect();
                ys.sort_by(f64::total_cmp);
                ys
            },
            wheel_breaks: {
                let mut b = pair.wheel.profile().breaks();
                b.extend([lo, hi]);
                b.sort_by(f64::total_cmp);
                b
            },
        }
    }

    /// Adds the tables the paper's solver searches: wheel and rail tabulated every
    /// `step_mm`, the rail height between its table points interpolated linearly.
    pub fn with_tables(mut self, step_mm: f64) -> SideGap<'a> {
        let (lo, hi) = self.pair.wheel.profile().domain();
        let n = ((hi - lo) / step_mm).round().max(1.0) as usize;
        let wheel = (0..=n)
            .map(|i| {
                let s = lo + (hi - lo) * i as f64 / n as f64;
                let p = self.pair.wheel.at(s);
                [s, p.y, p.z]
            })
            .collect();
        self.tabulated = Some(Tables {
            wheel,
            rail: HeightTable::new(&self.pair.rail, step_mm),
        });
        self
    }

    /// The lowest gap over the tabulated wheel points with the tabulated rail (the paper's
    /// discrete minimum): `(s, g, Y)` of the table point, or `None` without tables or
    /// without a wheel point above the rail.
    pub fn tabulated_minimum(&self, pose: &SidePose) -> Option<(f64, f64, f64)> {
        let t = self.tabulated.as_ref()?;
        let mut best: Option<(f64, f64, f64)> = None;
        for &[s, yw, zw] in &t.wheel {
            let [y, z] = pose.apply(yw, zw);
            if let Some(zr) = t.rail.height(y) {
                let g = z - zr;
                if best.is_none_or(|b| g < b.1) {
                    best = Some((s, g, y));
                }
            }
        }
        best
    }

    /// Where the wheel profile's second derivative may jump (joints, spline knots) and the
    /// ends of its domain, increasing (mm).
    pub fn wheel_breaks(&self) -> &[f64] {
        &self.wheel_breaks
    }

    /// Side-frame lateral positions `Y` of the rail profile's breaks (joints, spline knots)
    /// and of the ends of its running surface, increasing (mm).
    pub fn rail_break_ys(&self) -> &[f64] {
        &self.rail_break_ys
    }

    /// The wheel.
    pub fn wheel(&self) -> &PlacedWheel {
        &self.pair.wheel
    }

    /// The gap at `s` for `pose`, or `None` where the wheel point is not above the rail or
    /// `s` lies outside the wheel profile.
    #[inline]
    pub fn at(&self, s: f64, pose: &SidePose) -> Option<GapPoint> {
        if !(self.domain.0..=self.domain.1).contains(&s) {
            return None;
        }
        let wheel = self.pair.wheel.at(s);
        let [y, z_rel] = pose.apply(wheel.y, wheel.z);
        let rail = self.pair.rail.at(y)?;
        // dZw/ds = -F' and dYw/ds = 1; wheel.slope = -F', wheel.d2 = -F''.
        let f1 = -wheel.slope;
        let f2 = -wheel.d2;
        let dy = pose.cos + pose.sin * f1;
        let dz = pose.sin - pose.cos * f1;
        let ddy = pose.sin * f2;
        let ddz = -pose.cos * f2;
        let rail_dd = rail.d2;
        Some(GapPoint {
            s,
            g: z_rel - rail.z,
            dg: dz - rail.slope * dy,
            ddg: ddz - rail_dd * dy * dy - rail.slope * ddy,
            y,
            z_rel,
            wheel,
            rail,
        })
    }

    /// Basins of the gap found by the coarse scan: brackets around every sampled local
    /// minimum within [`COARSE_MARGIN_MM`] of the lowest, lowest first.
    pub fn basins(&self, pose: &SidePose, out: &mut Vec<Basin>) {
        out.clear();
        // Only wheel samples that can lie above the rail.
        let (first, last) = self.over_rail(pose);
        let coarse = &self.coarse[first..last];
        let n = coarse.len();
        if n == 0 {
            return;
        }
        // The lowest sample is a sampled local minimum, and the lowest of them: a block
        // whose bound lies more than the margin above some sample's gap holds no minimum
        // that is refined. The block with the lowest bound gives that sample first.
        let blocks = first / SCAN_BLOCK..(last - 1) / SCAN_BLOCK + 1;
        let mut bounds = [0.0; MAX_SCAN_BLOCKS];
        let stored = blocks.len() <= MAX_SCAN_BLOCKS;
        let bound = |b: usize, bounds: &[f64]| {
            if stored {
                bounds[b - blocks.start]
            } else {
                self.block_bound(b, pose)
            }
        };
        let mut best = (f64::INFINITY, blocks.start);
        for b in blocks.clone() {
            let v = self.block_bound(b, pose);
            if stored {
                bounds[b - blocks.start] = v;
            }
            if v < best.0 {
                best = (v, b);
            }
        }
        let b = best.1;
        let mut running = block_samples(b, first, last)
            .fold(f64::INFINITY, |m, i| m.min(self.coarse_gap(i, pose)));
        // Sampled local minima `(gap, index)`, the lowest few kept (more than 16 coarse
        // minima within one wheel would be noise; the lowest are the ones refined).
        let mut found: [(f64, usize); 16] = [(0.0, 0); 16];
        let mut count = 0;
        let mut lowest = f64::INFINITY;
        // The gap of sample i is known when sample i + 1 is computed: `here` is sample i - 1.
        // Samples of skipped blocks count as off the rail (+inf): higher than any sample
        // that could be refined, so the minima that matter are found as without skipping.
        let (mut prev, mut here) = (f64::INFINITY, f64::INFINITY);
        for b in blocks.clone() {
            let skip = bound(b, &bounds) > running + COARSE_MARGIN_MM;
            for i in block_samples(b, first, last) {
                let next = if skip {
                    f64::INFINITY
                } else {
                    self.coarse_gap(i, pose)
                };
                running = running.min(next);
                if here <= prev && here <= next && here < f64::INFINITY {
                    lowest = lowest.min(here);
                    record(&mut found, &mut count, here, i - first - 1);
                }
                prev = here;
                here = next;
            }
        }
        // The last sample has no right neighbour.
        if here <= prev && here < f64::INFINITY {
            lowest = lowest.min(here);
            record(&mut found, &mut count, here, n - 1);
        }
        let found = &mut found[..count];
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        for &(g, i) in found.iter() {
            if g <= lowest + COARSE_MARGIN_MM {
                let lo = coarse[i.saturating_sub(1)][0];
                let hi = coarse[(i + 1).min(n - 1)][0];
                out.push((lo, hi));
            }
        }
    }

    /// The coarse gap (table rail) of sample `i`, `+inf` where it is not above the rail.
    #[inline]
    fn coarse_gap(&self, i: usize, pose: &SidePose) -> f64 {
        let [_, yw, zw] = self.coarse[i];
        let [y, z] = pose.apply(yw, zw);
        self.pair
            .rail
            .heights()
            .height(y)
            .map_or(f64::INFINITY, |zr| z - zr)
    }

    /// A lower bound of the coarse gaps of block `b` at `pose` (`+inf` when none of its
    /// samples can be above the rail): the lowest its points can be, against the highest
    /// the rail table is under the lateral span they can cover.
    #[inline]
    fn block_bound(&self, b: usize, pose: &SidePose) -> f64 {
        let [yw_lo, yw_hi, zw_lo, zw_hi] = self.blocks[b];
        let (cos, sin) = (pose.cos, pose.sin);
        // Y = delta + cos Yw - sin Zw, z = sin Yw + cos Zw (cos > 0); Yw and Zw vary
        // independently within their ranges, so the extremes lie at range ends.
        let (a, c) = (-sin * zw_lo, -sin * zw_hi);
        let y_lo = pose.delta + cos * yw_lo + a.min(c);
        let y_hi = pose.delta + cos * yw_hi + a.max(c);
        let z_lo = (sin * yw_lo).min(sin * yw_hi) + cos * zw_lo;
        self.pair
            .rail
            .heights()
            .max_over(y_lo, y_hi)
            .map_or(f64::INFINITY, |rail| z_lo - rail)
    }

    /// Stretches of the wheel (`(s_lo, s_hi)`, increasing, disjoint) where the coarse gap
    /// lies below `threshold` (mm, same reference as [`GapPoint::g`]), each widened by one
    /// coarse step so that the fine gap below the threshold lies inside.
    pub fn low_regions(&self, pose: &SidePose, threshold: f64, out: &mut Vec<(f64, f64)>) {
        out.clear();
        let n = self.coarse.len();
        // Samples outside `first..last` cannot lie above the rail (see `basins`): they are
        // not low, exactly as the table would answer.
        let (first, last) = self.over_rail(pose);
        if first >= last {
            return;
        }
        let mut open: Option<usize> = None;
        let close = |first_low: usize, i: usize, out: &mut Vec<(f64, f64)>| {
            let lo = self.coarse[first_low.saturating_sub(1)][0];
            let hi = self.coarse[i.min(n - 1)][0];
            match out.last_mut() {
                Some(last) if last.1 >= lo => last.1 = hi,
                _ => out.push((lo, hi)),
            }
        };
        for b in first / SCAN_BLOCK..(last - 1) / SCAN_BLOCK + 1 {
            // A block whose bound reaches the threshold has no low sample.
            let skip = self.block_bound(b, pose) >= threshold;
            for i in block_samples(b, first, last) {
                let low = !skip && self.coarse_gap(i, pose) < threshold;
                match (low, open) {
                    (true, None) => open = Some(i),
                    (false, Some(first_low)) => {
                        close(first_low, i, out);
                        open = None;
                    }
                    _ => {}
                }
            }
        }
        if let Some(first_low) = open {
            close(first_low, last, out);
        }
    }

    /// The index range of the coarse samples that can lie above the rail at `pose`:
    /// `Y = delta + Yw +- |sin phi| |Zw|`, with one sample more on each side.
    fn over_rail(&self, pose: &SidePose) -> (usize, usize) {
        let (y_lo, y_hi) = self.pair.rail.y_range();
        // Y = delta + cos Yw - sin Zw differs from delta + Yw by at most
        // |sin| |Zw| + (1 - cos) |Yw|, with |Zw| <= r0 + 100 and |Yw| <= taping line + 100:
        // the second term is 13 mm at a roll of 0.19 rad (very unequal wheel radii).
        let wheel = &self.pair.wheel;
        let reach = pose.sin.abs() * (wheel.nominal_radius_mm() + 100.0)
            + (1.0 - pose.cos) * (wheel.taping_line_mm() + 100.0)
            + 1.0;
        let first = self
            .coarse
            .partition_point(|c| pose.delta + c[1] < y_lo - reach)
            .saturating_sub(1);
        let last = (self
            .coarse
            .partition_point(|c| pose.delta + c[1] <= y_hi + reach)
            + 1)
        .min(self.coarse.len());
        (first, last)
    }

    /// The minimum of the gap in a basin: safeguarded Newton on `dg/ds = 0` inside the
    /// bracket, which slides when the minimum lies beyond it (the basin moved with the pose).
    pub fn minimum(&self, basin: Basin, start: Option<f64>, pose: &SidePose) -> Option<GapPoint> {
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
    pub fn minimum_within(&self, basin: Basin, start: f64, pose: &SidePose) -> Option<GapPoint> {
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

    fn newton_in(&self, mut lo: f64, mut hi: f64, s0: f64, pose: &SidePose) -> Option<GapPoint> {
        // The bracket ends are evaluated only when needed: to start off the rail, to know
        // which side of the rail a step left, or as candidates when the iteration did not
        // end at a smooth interior minimum.
        let mut p_lo: Option<Option<GapPoint>> = None;
        let mut p_hi: Option<Option<GapPoint>> = None;
        let mut p = match self.at(s0, pose) {
            Some(p) => p,
            None => {
                let a = self.at(lo, pose);
                let b = self.at(hi, pose);
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
            let newton = p.s - p.dg / p.ddg;
            let is_newton = p.ddg > 0.0 && newton > lo && newton < hi;
            let next = if is_newton { newton } else { 0.5 * (lo + hi) };
            if (next - p.s).abs() < LOCAL_TOL_MM || hi - lo < LOCAL_TOL_MM {
                smooth = is_newton && (next - p.s).abs() < LOCAL_TOL_MM;
                break;
            }
            p = match self.at(next, pose) {
                Some(q) => q,
                None => {
                    // Left the rail: the minimum lies on the defined side.
                    let lo_defined = *p_lo.get_or_insert_with(|| self.at(lo, pose));
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
        let p_lo = p_lo.unwrap_or_else(|| self.at(lo, pose));
        let p_hi = p_hi.unwrap_or_else(|| self.at(hi, pose));
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
    use crate::scene::Scene;

    fn placement() -> crate::track::Placement {
        let scene = Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
        crate::pipeline::place(&scene).unwrap()
    }

    /// Poses over the paper sweep and beyond, with rolls up to 0.02 rad, and the solved
    /// poses around the paper's jumps, where two minima lie within the margin.
    fn poses() -> Vec<SidePose> {
        let mut poses: Vec<SidePose> = (0..=120)
            .flat_map(|i| {
                let y_ws = -30.0 + 0.5 * f64::from(i);
                [-0.02, -1e-3, 0.0, 7e-4, 0.02].map(|roll| SidePose::new(1.0, y_ws, roll))
            })
            .collect();
        let near_jumps: Vec<f64> = (0..=40)
            .flat_map(|i| {
                let d = 0.0025 * f64::from(i) - 0.05;
                [0.226 + d, 4.992 + d, 6.26 + d]
            })
            .collect();
        let sweep =
            crate::rigid::search(&placement(), &near_jumps, crate::rigid::Solver::default());
        poses.extend(
            sweep
                .positions
                .iter()
                .map(|p| SidePose::new(1.0, p.y_ws, p.roll)),
        );
        poses
    }

    /// The scans without skipping: every sample of the over-rail range evaluated.
    fn all_gaps(side: &SideGap, pose: &SidePose) -> Vec<(usize, f64)> {
        let (first, last) = side.over_rail(pose);
        (first..last)
            .map(|i| (i, side.coarse_gap(i, pose)))
            .collect()
    }

    #[test]
    fn skipping_blocks_finds_the_basins_and_low_regions_of_a_full_scan() {
        let placement = placement();
        let side = SideGap::new(&placement.left, 1.0);
        let (mut basins, mut regions) = (Vec::new(), Vec::new());
        let mut skipped_any = false;
        let mut several_basins = 0;
        for pose in poses() {
            let gaps = all_gaps(&side, &pose);
            let Some(lowest) = gaps.iter().map(|g| g.1).min_by(f64::total_cmp) else {
                continue;
            };
            // Basins: brackets around the sampled local minima within the margin.
            side.basins(&pose, &mut basins);
            let mut expected: Vec<(f64, Basin)> = Vec::new();
            for (k, &(i, g)) in gaps.iter().enumerate() {
                let prev = if k > 0 { gaps[k - 1].1 } else { f64::INFINITY };
                let next = gaps.get(k + 1).map_or(f64::INFINITY, |n| n.1);
                if g < f64::INFINITY && g <= prev && g <= next && g <= lowest + COARSE_MARGIN_MM {
                    let lo = side.coarse[i.saturating_sub(1).max(gaps[0].0)][0];
                    let hi = side.coarse[(i + 1).min(gaps[gaps.len() - 1].0)][0];
                    expected.push((g, (lo, hi)));
                }
            }
            expected.sort_by(|a, b| a.0.total_cmp(&b.0));
            if expected.len() > 1 {
                several_basins += 1;
            }
            let expected: Vec<Basin> = expected.into_iter().map(|e| e.1).collect();
            assert_eq!(basins, expected, "basins at {pose:?}");
            // Low regions at a threshold 0.3 mm above the lowest sample.
            let threshold = lowest + 0.3;
            side.low_regions(&pose, threshold, &mut regions);
            // Runs of low samples, each from the sample before its first to its end.
            let n = side.coarse.len();
            let mut expected: Vec<(f64, f64)> = Vec::new();
            let mut k = 0;
            while k < gaps.len() {
                if gaps[k].1 < threshold {
                    let start = gaps[k].0;
                    while k < gaps.len() && gaps[k].1 < threshold {
                        k += 1;
                    }
                    let end = gaps.get(k).map_or(gaps[gaps.len() - 1].0 + 1, |g| g.0);
                    let (lo, hi) = (
                        side.coarse[start.saturating_sub(1)][0],
                        side.coarse[end.min(n - 1)][0],
                    );
                    match expected.last_mut() {
                        Some(last) if last.1 >= lo => last.1 = hi,
                        _ => expected.push((lo, hi)),
                    }
                } else {
                    k += 1;
                }
            }
            assert_eq!(regions, expected, "low regions at {pose:?}");
            let blocks = gaps[0].0 / SCAN_BLOCK..gaps[gaps.len() - 1].0 / SCAN_BLOCK + 1;
            skipped_any |= blocks
                .into_iter()
                .any(|b| side.block_bound(b, &pose) >= threshold);
        }
        assert!(
            skipped_any,
            "the bounds never allowed a skip: the test proves nothing"
        );
        assert!(
            several_basins > 10,
            "{several_basins} poses with two basins to refine"
        );
    }

    #[test]
    fn block_bounds_are_below_every_sample_of_their_block() {
        let placement = placement();
        let side = SideGap::new(&placement.left, 1.0);
        for pose in poses() {
            for (i, g) in all_gaps(&side, &pose) {
                let bound = side.block_bound(i / SCAN_BLOCK, &pose);
                assert!(
                    bound <= g,
                    "sample {i}: bound {bound} above gap {g} at {pose:?}"
                );
            }
        }
    }
}
