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
//! * The integrals are taken in the wheel coordinate `s` by 8-point Gauss-Legendre panels
//!   ([`Quadrature::GaussLegendre`], `DEFAULT_PANEL_WIDTHS` weight widths
//!   `sqrt(eps / d'')` long) on the pieces where the integrand is smooth: they end at the
//!   section joints of wheel and rail, where curvatures jump. The trapezoid rule on a fixed
//!   grid is kept as a variant ([`Quadrature::Trapezoid`], `average`); it is only first
//!   order across a joint.
//! * The integrals are cut where `d - d_min > cutoff * eps` (`DEFAULT_CUTOFF` = 25: the
//!   weight left out is below 2e-12 of the total for a quadratic gap).
//! * Separate low regions of the gap (tread and flange) are averaged separately: one
//!   [`Patch`] per local minimum, split where a barrier higher than `eps` separates minima.

use crate::gap::{ContactPoint, SideGap, SidePose, Yaw};
use crate::rigid::{RigidSweep, Stop};
use crate::sweep::{Mirror, Mirrored};
use crate::track::{Placement, Side};
use std::sync::Arc;

mod gauss;
mod settings;
mod trapezoid;

use gauss::gauss_region;
pub use trapezoid::average;
use trapezoid::trapezoid_region;
pub(crate) use trapezoid::{MIN_STEP_MM, TRAPEZOID_STEPS_PER_WIDTH};

pub(crate) use settings::{
    DEFAULT_CUTOFF, DEFAULT_EPSILON_MM, DEFAULT_MAX_STEP_MM, DEFAULT_PANEL_WIDTHS, EPSILON_RANGE_MM,
};
pub use settings::{Quadrature, QuasiElasticSettings, QuasiElasticSettingsError};

/// Local minima of the gap separated by a barrier lower than `BARRIER_EPS * eps` above the
/// higher of the two belong to one patch: the weight barely dips between them.
const BARRIER_EPS: f64 = 1.0;

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
    /// Averaged longitudinal position along the track (mm, x forward) relative to the
    /// wheelset centre: 0 without yaw.
    pub x: f64,
    /// Averaged distance ahead of the axle along the wheelset's own forward axis (mm): 0
    /// without yaw.
    pub lead: f64,
    /// Share of the total weight of the wheel that falls in this patch (0-1).
    pub weight_share: f64,
    /// Smallest gap in the patch above the rigid minimum (mm).
    pub gap_above_min: f64,
}

impl Patch {
    /// The patch seen in the mirror `y -> -y` of the track: the other wheel's at the
    /// mirrored position (only the track-frame `y` changes sign, as for
    /// [`crate::rigid::SideContact`]).
    fn mirror_image(&self) -> Patch {
        Patch {
            y: -self.y,
            ..*self
        }
    }

    /// The averaged contact point: the columns shared with the rigid contact.
    pub fn point(&self) -> ContactPoint {
        ContactPoint {
            s: self.s,
            y: self.y,
            z: self.z,
            r: self.r,
            gamma: self.gamma,
            rail_tan_gamma: self.rail_tan_gamma,
            wheel_curvature: self.wheel_curvature,
            rail_curvature: self.rail_curvature,
            x: self.x,
            lead: self.lead,
        }
    }

    /// Whether every number of the patch is finite.
    pub fn is_finite(&self) -> bool {
        [
            self.s,
            self.y,
            self.z,
            self.r,
            self.gamma,
            self.rail_tan_gamma,
            self.wheel_curvature,
            self.rail_curvature,
            self.x,
            self.lead,
            self.weight_share,
        ]
        .iter()
        .all(|v| v.is_finite())
    }
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
pub struct QuasiElasticPosition {
    /// Lateral shift of the wheelset (mm).
    pub y_ws: f64,
    /// Left and right results (empty when the rigid solution is missing).
    pub sides: [SideResult; 2],
    /// The rigid solution's stop reason (the quasi-elastic pass adds none of its own).
    pub rigid_stop: Stop,
}

impl Mirrored for QuasiElasticPosition {
    fn mirrored(&self, y_ws: f64) -> QuasiElasticPosition {
        let side = |k: usize| SideResult {
            patches: self.sides[k]
                .patches
                .iter()
                .map(Patch::mirror_image)
                .collect(),
        };
        QuasiElasticPosition {
            y_ws,
            sides: [side(1), side(0)],
            rigid_stop: self.rigid_stop,
        }
    }
}

impl QuasiElasticPosition {
    /// The result of `side`.
    pub fn side(&self, side: Side) -> &SideResult {
        match side {
            Side::Left => &self.sides[0],
            Side::Right => &self.sides[1],
        }
    }
}

/// The quasi-elastic solution over a sweep, with the rigid sweep it was computed on: one
/// result per rigid position, so that a stage computed from both (Hertz) reads them
/// together.
#[derive(Debug, Clone)]
pub struct QuasiElasticSweep {
    settings: QuasiElasticSettings,
    rigid: Arc<RigidSweep>,
    positions: Vec<QuasiElasticPosition>,
    /// Whether the positions before the middle are the mirror images of those after it.
    mirror: Option<Mirror>,
}

impl QuasiElasticSweep {
    /// The settings used.
    pub fn settings(&self) -> &QuasiElasticSettings {
        &self.settings
    }

    /// The rigid sweep the averages were taken around.
    pub fn rigid(&self) -> &RigidSweep {
        &self.rigid
    }

    /// One result per position of [the rigid sweep](Self::rigid), in its order.
    pub fn positions(&self) -> &[QuasiElasticPosition] {
        &self.positions
    }

    /// Whether the positions before the middle are the mirror images of those after it.
    pub(crate) fn mirror(&self) -> Option<Mirror> {
        self.mirror
    }
}

/// Averages the contact of every position of a rigid sweep, which the result keeps
/// (`rigid` moved in, or shared as an `Arc`: [`QuasiElasticSweep::rigid`]).
///
/// On a [mirror-symmetric](crate::track::Placement::is_mirror_symmetric) wheelset whose
/// rigid positions are mirror images about the middle one (as [`crate::rigid::search`] gives
/// them on a symmetric sweep), the positions from the middle on are averaged and those
/// before it are their mirror images, bit for bit what averaging them would give.
///
/// # Example
/// ```
/// use wheelrail::{pipeline, quasi_elastic, rigid, scene::Scene};
/// let scene = Scene::from_toml("", "inline", std::path::Path::new(".")).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// let rigid = rigid::search(&placement, &wheelrail::sweep::Sweep::from_slice(&[2.0]).unwrap(), rigid::Solver::default());
/// let qe = quasi_elastic::search(&placement, rigid, &quasi_elastic::QuasiElasticSettings::default());
/// let patch = qe.positions()[0].sides[0].main().unwrap();
/// // Averaging moves the contact point, but stays on the tread near the rigid point.
/// assert!((patch.s - qe.rigid().positions()[0].contact[0].unwrap().s).abs() < 3.0);
/// ```
pub fn search(
    placement: &Placement,
    rigid: impl Into<Arc<RigidSweep>>,
    settings: &QuasiElasticSettings,
) -> QuasiElasticSweep {
    let rigid: Arc<RigidSweep> = rigid.into();
    let yaw = *rigid.yaw();
    // Prepared for the yaw of a position (once where it is fixed along the sweep).
    let prepare = |sides: &mut [SideGap; 2], y_ws: f64| {
        for side in sides {
            side.set_yaw(Yaw::new(side.sign, yaw.at(y_ws), yaw.model()));
        }
    };
    let mut sides = SideGap::both(placement);
    prepare(&mut sides, 0.0);
    // Where the rigid positions before the middle are the mirror images of those after it,
    // a wheel at a position is averaged exactly as the other wheel at the mirrored
    // position, operation for operation (both in their side frames): the images are what
    // averaging gives.
    let mirror = rigid.mirror().filter(|_| placement.mirrors());
    let all = rigid.positions();
    let first = mirror.map_or(0, Mirror::middle);
    // Positions are independent: averaged in parallel (rayon), buffers per thread.
    use rayon::prelude::*;
    let solved: Vec<QuasiElasticPosition> = all[first..]
        .par_iter()
        .map_init(
            || (Work::default(), yaw.varies().then(|| sides.clone())),
            |(work, own), p| {
                let mut result = [SideResult::default(), SideResult::default()];
                let sides = match own {
                    Some(own) => {
                        prepare(own, p.y_ws);
                        &*own
                    }
                    None => &sides,
                };
                if p.stop == Stop::Converged {
                    for k in 0..2 {
                        if let Some(c) = p.contact[k] {
                            let (y_ws, roll, height) = (p.y_ws, p.roll, p.axle_height);
                            let side = &sides[k];
                            result[k] = side_average(side, y_ws, roll, height, c.s, settings, work);
                        }
                    }
                }
                QuasiElasticPosition {
                    y_ws: p.y_ws,
                    sides: result,
                    rigid_stop: p.stop,
                }
            },
        )
        .collect();
    let positions = match mirror {
        Some(mirror) => mirror.complete(solved, |i| all[i].y_ws),
        None => solved,
    };
    QuasiElasticSweep {
        settings: *settings,
        rigid,
        positions,
        mirror,
    }
}

/// Number of averaged fields per node (see [`side_average`]).
const FIELDS: usize = 9;

/// Buffers reused across positions.
#[derive(Debug, Default)]
struct Work {
    regions: Vec<(f64, f64)>,
    nodes: Vec<f64>,
    gaps: Vec<f64>,
    fields: Vec<[f64; FIELDS]>,
    breaks: Vec<(f64, bool)>,
}

/// The fields averaged at one node: `s`, track-frame `y`, the rail's height, `F` (the
/// rolling radius less `r0`), the wheel's slope as the rail sees it (the outline's with
/// yaw), the rail's slope, the profile's and the rail's curvatures, the lead.
fn fields_of(side: &SideGap, p: &crate::gap::GapPoint) -> [f64; FIELDS] {
    let (f, wheel_curvature, lead) = if side.has_yaw() {
        let profile = side.yaw().profile_point(&p.wheel);
        (
            -profile.z - side.wheel().nominal_radius_mm(),
            profile.curvature(),
            side.yaw().lead(&profile),
        )
    } else {
        (
            -p.wheel.z - side.wheel().nominal_radius_mm(),
            p.wheel.curvature(),
            0.0,
        )
    };
    [
        p.s,
        side.sign * p.y,
        p.rail.z,
        f,
        p.wheel.slope,
        p.rail.slope,
        wheel_curvature,
        p.rail.curvature(),
        lead,
    ]
}

/// One wheel's averaging pass at one position: its gap and pose, the reference the gaps
/// are measured from, and the weight's width there.
#[derive(Clone, Copy)]
struct Pass<'a> {
    side: &'a SideGap<'a>,
    pose: SidePose,
    /// Axle height of the rigid solution (mm): `d = g + axle_height`.
    axle_height: f64,
    /// The gap the weights are measured from (mm): the rigid minimum of this wheel.
    d_min: f64,
    /// The distance over which the gap rises by eps at the rigid point (mm).
    width: f64,
    settings: &'a QuasiElasticSettings,
}

/// The patches of one wheel at one position, heaviest first: the weighted averages over
/// the low regions of the gap around the rigid contact point `s_rigid`.
fn side_average(
    side: &SideGap,
    y_ws: f64,
    roll: f64,
    axle_height: f64,
    s_rigid: f64,
    settings: &QuasiElasticSettings,
    work: &mut Work,
) -> SideResult {
    let eps = settings.epsilon_mm;
    let pose = side.pose(y_ws, roll);
    let Some(at_rigid) = side.at(s_rigid, &pose) else {
        return SideResult::default();
    };
    // The distance over which the gap rises by eps: sqrt(eps / d'') at a smooth minimum,
    // eps / |d'| at a minimum on an end of the surfaces (the rail's running surface ends
    // where it turns steep), where the gap rises linearly and the weight decays within
    // eps / |d'|: panels sized by the curvature alone would step over it.
    let width = (eps / at_rigid.ddg.max(1e-12))
        .sqrt()
        .min(eps / at_rigid.dg.abs().max(f64::MIN_POSITIVE));
    let limit = settings.cutoff * eps;
    // Regions where the gap may be below the cut-off; the coarse gap errs by less than
    // the margin (see gap::COARSE_MARGIN_MM).
    side.low_regions_from(
        &pose,
        at_rigid.g + limit + crate::gap::COARSE_MARGIN_MM,
        Some(s_rigid),
        &mut work.regions,
    );
    include_rigid_point(&mut work.regions, s_rigid, side.wheel().profile().domain());
    // Gaps are measured from the rigid minimum of this wheel: one reference for every
    // region and patch, so that their weights compare.
    let pass = Pass {
        side,
        pose,
        axle_height,
        d_min: at_rigid.g + axle_height,
        width,
        settings,
    };
    let mut patches = average_regions(pass, work);
    if patches.iter().all(|a| a.weight <= 0.0) {
        // The weight is narrower than any node spacing (a minimum at a vertical end of the
        // profile, or eps far below the gap's curvature): the average tends to the value at
        // the minimum itself, the rigid contact point.
        patches = vec![Average {
            mean: fields_of(side, &at_rigid),
            weight: 1.0,
            min_gap: 0.0,
        }];
    }
    patches_of(side, roll, &patches)
}

/// The averages over every low region in `work.regions`, split into patches.
///
/// A rigid point that is not the minimum (the paper's solver stops at residuals of
/// microns) leaves nodes below the reference; with a small eps their weights
/// exp(-gap/eps) overflow. Then the pass is repeated from the lowest node (the regions,
/// found from the rigid reference, hold every node below the cut-off of the lower one).
fn average_regions(mut pass: Pass, work: &mut Work) -> Vec<Average<FIELDS>> {
    let mut patches: Vec<Average<FIELDS>> = Vec::new();
    let regions = std::mem::take(&mut work.regions);
    for _reference in 0..2 {
        patches.clear();
        for &region in &regions {
            match pass.settings.quadrature {
                Quadrature::GaussLegendre { panel_widths } => {
                    gauss_region(&pass, panel_widths, region, work, &mut patches);
                }
                Quadrature::Trapezoid { max_step_mm } => {
                    trapezoid_region(&pass, max_step_mm, region, work, &mut patches);
                }
            }
        }
        let lowest = patches
            .iter()
            .map(|a| a.min_gap)
            .fold(f64::INFINITY, f64::min);
        if patches.iter().all(Average::is_finite) || lowest >= 0.0 {
            break;
        }
        pass.d_min += lowest;
    }
    work.regions = regions;
    patches
}

/// The patches of the averages `a` (those with weight), heaviest first.
fn patches_of(side: &SideGap, roll: f64, averages: &[Average<FIELDS>]) -> SideResult {
    let total_weight: f64 = averages.iter().map(|a| a.weight).sum();
    let r0 = side.wheel().nominal_radius_mm();
    let phi = side.sign * roll;
    let mut out: Vec<Patch> = averages
        .iter()
        .filter(|a| a.weight > 0.0)
        .map(|a| {
            let [s, y, z, f, wheel_slope, rail_slope, kw, kr, lead] = a.mean;
            let (x, lead) = if side.has_yaw() {
                let yw = side.wheel().taping_line_mm() + s;
                (side.yaw().x_of(yw, lead), lead)
            } else {
                (0.0, 0.0)
            };
            Patch {
                s,
                y,
                z,
                r: r0 + f,
                gamma: wheel_slope.atan() + phi,
                rail_tan_gamma: rail_slope,
                wheel_curvature: kw,
                rail_curvature: kr,
                x,
                lead,
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
/// 1/5 mm^-1 (see [`crate::gap::COARSE_MARGIN_MM`]); a sharper minimum, such as the
/// S1002 flange-back arc near its vertical tangent (d'' = 370 1/mm), can lie between coarse
/// samples that are all above the threshold. The rigid point is the minimum by definition.
/// The added region stays inside the wheel's `domain`.
fn include_rigid_point(regions: &mut Vec<(f64, f64)>, s_rigid: f64, domain: (f64, f64)) {
    if regions.iter().any(|r| (r.0..=r.1).contains(&s_rigid)) {
        return;
    }
    let step = crate::gap::COARSE_STEP_MM;
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

/// Indices of the local maxima of `gaps` that rise more than `barrier` above the lowest
/// gap on each side up to the neighbouring maxima (interior indices only).
fn barrier_maxima(gaps: &[f64], barrier: f64) -> Vec<usize> {
    // Most regions have no interior local maximum at all.
    if falls_then_rises(gaps) {
        return Vec::new();
    }
    barrier_scan(gaps, barrier)
}

/// Whether `gaps` falls strictly, then never falls again: no interior local maximum (one
/// at `i` would need `gaps[i - 1] <= gaps[i] > gaps[i + 1]`).
fn falls_then_rises(gaps: &[f64]) -> bool {
    gaps.windows(2)
        .skip_while(|w| w[1] < w[0])
        .all(|w| w[1] >= w[0])
}

/// [`barrier_maxima`] by a scan of every local maximum.
fn barrier_scan(gaps: &[f64], barrier: f64) -> Vec<usize> {
    let n = gaps.len();
    let mut out = Vec::new();
    let mut run_min = gaps.first().copied().unwrap_or(f64::INFINITY);
    let mut i = 1;
    while i + 1 < n {
        run_min = run_min.min(gaps[i]);
        if gaps[i] >= gaps[i - 1] && gaps[i] > gaps[i + 1] {
            let mut j = i + 1;
            let mut next_min = gaps[i + 1];
            while j + 1 < n && gaps[j + 1] <= gaps[j] {
                j += 1;
                next_min = next_min.min(gaps[j]);
            }
            if gaps[i] - run_min.max(next_min) > barrier {
                out.push(i);
                run_min = gaps[i];
            }
        }
        i += 1;
    }
    out
}

/// One patch of `average`: the weight-averaged fields, the integral of the weight, and
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

impl<const N: usize> Average<N> {
    /// Whether the weight and every mean are finite (weights overflow when gaps lie far
    /// below the reference they are measured from).
    pub fn is_finite(&self) -> bool {
        self.weight.is_finite() && self.mean.iter().all(|v| v.is_finite())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a mirror-symmetric wheelset whose rigid positions mirror about the middle, the
    /// positions before the middle are mirror images of those after it, and they are bit
    /// for bit what averaging them gives (each wheel is averaged in its side frame), with
    /// either quadrature.
    #[test]
    fn a_symmetric_sweep_mirrors_its_half() {
        let scene = crate::scene::Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
        let placement = crate::pipeline::place(&scene).unwrap();
        let rigid = crate::rigid::search(&placement, scene.sweep(), Default::default());
        // The mirror is taken: the rigid positions are mirror images.
        let p = rigid.positions();
        let n = p.len();
        assert!(placement.is_mirror_symmetric() && n == 301);
        assert!((0..n).all(|i| p[i] == p[n - 1 - i].mirrored(p[i].y_ws)));
        let unmirrored = placement.clone().without_mirroring();
        for quadrature in [
            Quadrature::default(),
            Quadrature::Trapezoid { max_step_mm: 0.05 },
        ] {
            let settings = QuasiElasticSettings::default()
                .with_quadrature(quadrature)
                .unwrap();
            let mirrored = search(&placement, rigid.clone(), &settings);
            let averaged = search(&unmirrored, rigid.clone(), &settings);
            assert_eq!(
                format!("{:?}", mirrored.positions),
                format!("{:?}", averaged.positions)
            );
        }
    }

    /// The shortcut for a gap that falls then rises gives what the scan gives, on random
    /// sequences of few distinct values (ties, plateaus, bumps), half of them unimodal.
    #[test]
    fn barrier_shortcut_agrees_with_the_scan() {
        let mut rng = crate::rng::SplitMix64::new(7);
        let (mut shortcut, mut with_barriers) = (0, 0);
        for case in 0..20_000 {
            let n = (rng.next_u64() % 12) as usize;
            let mut gaps: Vec<f64> = (0..n).map(|_| (rng.next_u64() % 5) as f64).collect();
            if case % 2 == 0 {
                // Falling then rising, ties allowed.
                let k = if n > 0 {
                    (rng.next_u64() as usize) % n
                } else {
                    0
                };
                gaps[..k].sort_by(|a, b| b.total_cmp(a));
                gaps[k..].sort_by(f64::total_cmp);
            }
            let scan = barrier_scan(&gaps, 0.5);
            assert_eq!(barrier_maxima(&gaps, 0.5), scan, "gaps {gaps:?}");
            shortcut += usize::from(falls_then_rises(&gaps));
            with_barriers += usize::from(!scan.is_empty());
        }
        assert!(
            shortcut > 5_000 && with_barriers > 2_000,
            "{shortcut} {with_barriers}"
        );
    }
}
