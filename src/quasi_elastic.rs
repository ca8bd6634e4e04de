//! Quasi-elastic contact search (paper Sect. 4, Eqs. 6-8; Arnold & Netter 1997, Netter et
//! al. 1998).
//!
//! Around the rigid solution (same roll and height) every contact quantity is averaged over
//! the wheel with the weight `w(s) = exp(-(d(s) - d_min) / eps)`, `d` the vertical gap and
//! `eps` the regularisation parameter (paper: 1e-5 m = 0.01 mm): the contact location
//! (Eq. 7), the rolling radius, the contact angle through the averaged slope, and the lateral
//! curvatures of wheel and rail (Eq. 8: curvatures, never radii, which are infinite on
//! straight parts).
//!
//! Numerics:
//!
//! * `d_min` is subtracted in the exponent: the same weights after normalisation, and no
//!   underflow.
//! * The integrals are taken in the wheel coordinate `s` with trapezoid weights, valid on
//!   uneven nodes ([`average`]); the search places its nodes evenly with a step that
//!   resolves the weight's width `sqrt(eps / d'')` (trapezoid sums of such bell-shaped
//!   integrands converge exponentially).
//! * The integrals are cut where `d - d_min > cutoff * eps` ([`DEFAULT_CUTOFF`] = 37:
//!   w < 1e-16, nothing is lost at double precision).
//! * Separate low regions of the gap (tread and flange) are averaged separately: one
//!   [`Patch`] per local minimum, split where a barrier higher than `eps` separates minima.

use crate::rigid::gap::{SideGap, SidePose};
use crate::rigid::{RigidSweep, Stop};
use crate::track::{Placement, Side};

/// Default regularisation parameter (mm): the paper's 1e-5 m.
pub const DEFAULT_EPSILON_MM: f64 = 0.01;
/// Integrals stop where `(d - d_min) / eps` exceeds this: `exp(-37) = 8.5e-17`.
pub const DEFAULT_CUTOFF: f64 = 37.0;
/// Largest quadrature step in the wheel coordinate (mm).
pub const DEFAULT_MAX_STEP_MM: f64 = 0.05;
/// Steps per weight width `sqrt(eps / d'')` at the rigid contact point.
const STEPS_PER_WIDTH: f64 = 8.0;
/// Smallest quadrature step wanted (mm): bounds the cost where `eps / d''` is tiny.
const MIN_STEP_MM: f64 = 1e-4;
/// Local minima of the gap separated by a barrier lower than `BARRIER_EPS * eps` above the
/// higher of the two belong to one patch: the weight barely dips between them.
const BARRIER_EPS: f64 = 1.0;

/// Settings of the quasi-elastic search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Regularisation parameter `eps` (mm).
    pub epsilon_mm: f64,
    /// Cut-off of the weight, in units of `eps`.
    pub cutoff: f64,
    /// Largest quadrature step (mm).
    pub max_step_mm: f64,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            epsilon_mm: DEFAULT_EPSILON_MM,
            cutoff: DEFAULT_CUTOFF,
            max_step_mm: DEFAULT_MAX_STEP_MM,
        }
    }
}

/// The weighted average of one patch (one local minimum of the gap).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Patch {
    /// Averaged wheel coordinate (mm).
    pub s: f64,
    /// Averaged track-frame lateral position of the contact (mm).
    pub y: f64,
    /// Averaged track-frame height of the rail surface at the contact (mm).
    pub z: f64,
    /// Averaged rolling radius (mm).
    pub r: f64,
    /// Contact angle from the averaged wheel slope, roll included, mirrored per side (rad).
    pub gamma: f64,
    /// Averaged tangent of the rail's contact angle (side frame).
    pub rail_tan_gamma: f64,
    /// Averaged lateral wheel curvature, convex positive (1/mm).
    pub wheel_curvature: f64,
    /// Averaged lateral rail curvature, convex positive (1/mm).
    pub rail_curvature: f64,
    /// Share of the total weight of the wheel that falls in this patch (0-1).
    pub weight_share: f64,
    /// Smallest gap in the patch above the rigid minimum (mm).
    pub gap_above_min: f64,
}

/// Quasi-elastic contact of one wheel at one position: its patches, heaviest first.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SideResult {
    /// Patches, by decreasing weight share.
    pub patches: Vec<Patch>,
}

impl SideResult {
    /// The heaviest patch.
    pub fn main(&self) -> Option<&Patch> {
        self.patches.first()
    }

    /// The second heaviest patch, if any.
    pub fn second(&self) -> Option<&Patch> {
        self.patches.get(1)
    }
}

/// The quasi-elastic result at one lateral position.
#[derive(Debug, Clone, PartialEq)]
pub struct Position {
    /// Lateral shift of the wheelset (mm).
    pub y_ws: f64,
    /// Left and right results (empty when the rigid solution is missing).
    pub sides: [SideResult; 2],
    /// The rigid solution's stop reason (the quasi-elastic pass adds none of its own).
    pub rigid_stop: Stop,
}

impl Position {
    /// The result of `side`.
    pub fn side(&self, side: Side) -> &SideResult {
        match side {
            Side::Left => &self.sides[0],
            Side::Right => &self.sides[1],
        }
    }
}

/// The quasi-elastic solution over a sweep.
#[derive(Debug, Clone)]
pub struct QuasiElasticSweep {
    /// The settings used.
    pub settings: Settings,
    /// One result per position of the rigid sweep.
    pub positions: Vec<Position>,
}

/// Averages the contact of every position of a rigid sweep.
///
/// # Example
/// ```
/// use wheelrail::{pipeline, quasi_elastic, rigid, scene::Scene};
/// let scene = Scene::from_toml("", "inline", std::path::Path::new(".")).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// let rigid = rigid::search(&placement, &[2.0], rigid::Solver::Default);
/// let qe = quasi_elastic::search(&placement, &rigid, &quasi_elastic::Settings::default());
/// let patch = qe.positions[0].sides[0].main().unwrap();
/// // Averaging moves the contact point, but stays on the tread near the rigid point.
/// assert!((patch.s - rigid.positions[0].contact[0].unwrap().s).abs() < 3.0);
/// ```
pub fn search(placement: &Placement, rigid: &RigidSweep, settings: &Settings) -> QuasiElasticSweep {
    let sides = [
        SideGap::new(&placement.left, 1.0),
        SideGap::new(&placement.right, -1.0),
    ];
    let mut work = Work::default();
    let positions = rigid
        .positions
        .iter()
        .map(|p| {
            let mut result = [SideResult::default(), SideResult::default()];
            if p.stop == Stop::Converged {
                for k in 0..2 {
                    if let Some(c) = p.contact[k] {
                        result[k] = side_average(
                            &sides[k],
                            p.y_ws,
                            p.roll,
                            p.axle_height,
                            c.s,
                            settings,
                            &mut work,
                        );
                    }
                }
            }
            Position {
                y_ws: p.y_ws,
                sides: result,
                rigid_stop: p.stop,
            }
        })
        .collect();
    QuasiElasticSweep {
        settings: *settings,
        positions,
    }
}

/// Number of averaged fields per node (see [`side_average`]).
const FIELDS: usize = 8;

/// Buffers reused across positions.
#[derive(Debug, Default)]
struct Work {
    regions: Vec<(f64, f64)>,
    nodes: Vec<f64>,
    gaps: Vec<f64>,
    fields: Vec<[f64; FIELDS]>,
}

fn side_average(
    side: &SideGap,
    y_ws: f64,
    roll: f64,
    axle_height: f64,
    s_rigid: f64,
    settings: &Settings,
    work: &mut Work,
) -> SideResult {
    let eps = settings.epsilon_mm;
    let pose = SidePose::new(side.sign, y_ws, roll);
    let Some(at_rigid) = side.at(s_rigid, &pose) else {
        return SideResult::default();
    };
    // The rigid minimum, and the quadrature step from the weight's width there.
    let d_min = at_rigid.g + axle_height;
    let width = (eps / at_rigid.ddg.max(1e-12)).sqrt();
    // The step is the largest step halved until it resolves the width, and the nodes are
    // its multiples: a fixed grid, the same on both sides of a symmetric wheelset (a grid
    // anchored at the rigid point would move with its last-digit differences).
    let wanted = (width / STEPS_PER_WIDTH).max(MIN_STEP_MM);
    let halvings = (settings.max_step_mm / wanted).log2().ceil().max(0.0);
    let step = settings.max_step_mm / halvings.exp2();
    let limit = settings.cutoff * eps;
    // Regions where the gap may be below the cut-off; the coarse gap errs by less than
    // the margin (see rigid::gap::COARSE_MARGIN_MM).
    side.low_regions(
        &pose,
        at_rigid.g + limit + crate::rigid::gap::COARSE_MARGIN_MM,
        &mut work.regions,
    );
    let domain = side.wheel().profile().domain();
    include_rigid_point(&mut work.regions, s_rigid, domain);
    let mut patches = Vec::new();
    let mut total_weight = 0.0;
    let regions = std::mem::take(&mut work.regions);
    for &(lo, hi) in &regions {
        work.nodes.clear();
        work.gaps.clear();
        work.fields.clear();
        let k_lo = (lo / step).floor() as i64;
        let k_hi = (hi / step).ceil() as i64;
        for k in k_lo..=k_hi {
            let s = k as f64 * step;
            // The grid is rounded outwards; beyond its domain the profile is clamped and a
            // node there would be a phantom point of the wheel.
            if !(domain.0..=domain.1).contains(&s) {
                continue;
            }
            let Some(p) = side.at(s, &pose) else { continue };
            let d = p.g + axle_height - d_min;
            work.nodes.push(s);
            work.gaps.push(d);
            work.fields.push([
                s,
                side.sign * p.y,
                p.rail.z,
                -p.wheel.z - side.wheel().nominal_radius_mm(),
                p.wheel.slope,
                p.rail.slope,
                p.wheel.curvature(),
                p.rail.curvature(),
            ]);
        }
        let region_min = work.gaps.iter().copied().fold(f64::INFINITY, f64::min);
        for a in average(&work.nodes, &work.gaps, &work.fields, eps, settings.cutoff) {
            patches.push((region_min, a));
        }
    }
    work.regions = regions;
    // `average` weighs each region relative to the region's own lowest node; all regions
    // must share one reference, the lowest node of all, so scale each by
    // exp(-(region_min - lowest) / eps), and drop a region that lies wholly above the
    // cut-off (the coarse threshold includes a margin, so such regions occur). The lowest
    // node rather than the rigid minimum: where the weight is narrower than the quadrature
    // step, no node may lie within the cut-off of the rigid minimum.
    let lowest = patches
        .iter()
        .map(|(m, _)| *m)
        .fold(f64::INFINITY, f64::min);
    let patches: Vec<Average<FIELDS>> = patches
        .into_iter()
        .filter(|(m, _)| (m - lowest) / eps <= settings.cutoff)
        .map(|(m, mut a)| {
            a.weight *= (-(m - lowest) / eps).exp();
            total_weight += a.weight;
            a
        })
        .collect();
    let r0 = side.wheel().nominal_radius_mm();
    let phi = side.sign * roll;
    let mut out: Vec<Patch> = patches
        .iter()
        .filter(|a| a.weight > 0.0)
        .map(|a| {
            let [s, y, z, f, wheel_slope, rail_slope, kw, kr] = a.mean;
            Patch {
                s,
                y,
                z,
                r: r0 + f,
                gamma: wheel_slope.atan() + phi,
                rail_tan_gamma: rail_slope,
                wheel_curvature: kw,
                rail_curvature: kr,
                weight_share: a.weight / total_weight,
                gap_above_min: a.min_gap,
            }
        })
        .collect();
    out.sort_by(|a, b| b.weight_share.total_cmp(&a.weight_share));
    SideResult { patches: out }
}

/// Adds the neighbourhood of the rigid contact point to the low regions (sorted, disjoint)
/// when no region contains it. The coarse scan's margin assumes gap curvatures up to
/// 1/5 mm^-1 (see [`crate::rigid::gap::COARSE_MARGIN_MM`]); a sharper minimum, such as the
/// S1002 flange-back arc near its vertical tangent (d'' = 370 1/mm), can lie between coarse
/// samples that are all above the threshold. The rigid point is the minimum by definition.
/// The added region stays inside the wheel's `domain`.
fn include_rigid_point(regions: &mut Vec<(f64, f64)>, s_rigid: f64, domain: (f64, f64)) {
    if regions.iter().any(|r| (r.0..=r.1).contains(&s_rigid)) {
        return;
    }
    let step = crate::rigid::gap::COARSE_STEP_MM;
    regions.push((
        (s_rigid - step).max(domain.0),
        (s_rigid + step).min(domain.1),
    ));
    regions.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut merged: Vec<(f64, f64)> = Vec::with_capacity(regions.len());
    for &r in regions.iter() {
        match merged.last_mut() {
            Some(last) if r.0 <= last.1 => last.1 = last.1.max(r.1),
            _ => merged.push(r),
        }
    }
    *regions = merged;
}

/// One patch of [`average`]: the weight-averaged fields, the integral of the weight, and
/// the smallest gap in the patch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Average<const N: usize> {
    /// Weighted means of the fields.
    pub mean: [f64; N],
    /// Integral of the weight over the patch (mm).
    pub weight: f64,
    /// Smallest gap of the patch (same reference as the gaps given).
    pub min_gap: f64,
}

/// Weighted averages of `fields` over `nodes` (increasing, possibly uneven) with weights
/// `exp(-(gap - min gap) / eps)` and trapezoid quadrature, one [`Average`] per patch: the
/// nodes are split into patches at every local maximum of the gap that rises more than
/// `eps` above both neighbouring minima. Nodes where `(gap - min) / eps > cutoff` weigh 0.
///
/// # Example
/// ```
/// use wheelrail::quasi_elastic::average;
/// // Gap kappa s^2 / 2 on an even grid: the averaged location is 0.
/// let s: Vec<f64> = (-200..=200).map(|i| f64::from(i) * 0.01).collect();
/// let gap: Vec<f64> = s.iter().map(|s| 0.05 * s * s).collect();
/// let fields: Vec<[f64; 1]> = s.iter().map(|&s| [s]).collect();
/// let a = average(&s, &gap, &fields, 0.01, 37.0);
/// assert_eq!(a.len(), 1);
/// assert!(a[0].mean[0].abs() < 1e-15);
/// ```
pub fn average<const N: usize>(
    nodes: &[f64],
    gaps: &[f64],
    fields: &[[f64; N]],
    eps: f64,
    cutoff: f64,
) -> Vec<Average<N>> {
    let n = nodes.len();
    if n == 0 {
        return Vec::new();
    }
    let global_min = gaps.iter().copied().fold(f64::INFINITY, f64::min);
    // Split points: local maxima with a barrier above both neighbouring minima.
    let mut bounds = vec![0];
    let mut run_min = gaps[0];
    let mut i = 1;
    while i + 1 < n {
        run_min = run_min.min(gaps[i]);
        if gaps[i] >= gaps[i - 1] && gaps[i] > gaps[i + 1] {
            // Lowest gap on the far side up to the next local maximum.
            let mut j = i + 1;
            let mut next_min = gaps[i + 1];
            while j + 1 < n && gaps[j + 1] <= gaps[j] {
                j += 1;
                next_min = next_min.min(gaps[j]);
            }
            if gaps[i] - run_min.max(next_min) > BARRIER_EPS * eps {
                bounds.push(i);
                run_min = gaps[i];
            }
        }
        i += 1;
    }
    bounds.push(n - 1);
    bounds
        .windows(2)
        .filter_map(|b| {
            let (first, last) = (b[0], b[1]);
            let mut sum_w = 0.0;
            let mut sum = [0.0; N];
            let mut min_gap = f64::INFINITY;
            for k in first..=last {
                min_gap = min_gap.min(gaps[k]);
                let x = (gaps[k] - global_min) / eps;
                if x > cutoff {
                    continue;
                }
                // Trapezoid weight of node k within [first, last]; a split node is shared.
                let left = if k > first {
                    nodes[k] - nodes[k - 1]
                } else {
                    0.0
                };
                let right = if k < last {
                    nodes[k + 1] - nodes[k]
                } else {
                    0.0
                };
                let w = 0.5 * (left + right) * (-x).exp();
                sum_w += w;
                for (acc, f) in sum.iter_mut().zip(fields[k]) {
                    *acc += w * f;
                }
            }
            (sum_w > 0.0).then(|| Average {
                mean: sum.map(|v| v / sum_w),
                weight: sum_w,
                min_gap,
            })
        })
        .collect()
}
