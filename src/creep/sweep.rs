//! The creep stage: [`forces`](super::forces) on every patch of a sweep, per position and
//! wheel, from the contacts of the contact search and the wheelset's motion.
//!
//! # What each patch is given
//!
//! * **Shape**: the relative curvatures of the Hertz sweep (`A = cos γ / (2 r)`,
//!   `B = (k_wheel + k_rail) / 2`, [`crate::hertz::sweep`]); the ellipse follows the normal
//!   force that [`super::normal`] solves.
//! * **Point**: the patch's lead, its lateral position along the axle (`±(taping line + s)`,
//!   positive on the left wheel), its rolling radius and its contact angle, signed in the
//!   track frame (γ on the left wheel, -γ on the right one; γ includes the roll).
//! * **Load**: the wheel's vertical load times the patch's weight share, as the Hertz sweep
//!   shares it (one patch of a rigid contact or a lone quasi-elastic patch carries it all;
//!   where the quasi-elastic search found two patches each carries its share, and a third
//!   patch, if any, is left out and said so in the status).
//! * **Motion**: the scene's speed, lateral velocity and yaw rate, the position's roll and
//!   yaw, and a pitch rate: free rolling by default, `ω = V / r_mean` with `r_mean` the
//!   mean of the rolling radii of the two wheels' contacts at that position (the rigid
//!   contacts, or the heaviest quasi-elastic patches: the radii the creepages are computed
//!   with, so that a centred symmetric wheelset has `ξ = 0`), or the rates the scene gives,
//!   one per position ([`PitchRate`]).
//!
//! Each patch is solved on its own: the patches of one wheel do not share their normal
//! force through elasticity, and the two wheels' forces are not put into equilibrium (a
//! quasi-static sweep prescribes the motion; a vehicle model balances the forces).

use super::creepage::{ContactPoint, Motion};
use super::{CreepError, Patch, PatchForces, Settings, Shape};
use crate::hertz::Contacts;
use crate::hertz::{PrincipalCurvatures, relative_curvatures};
use crate::rigid::Stop;
use crate::track::{Placement, Side};

/// How the wheelset's pitch rate is chosen at each position.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum PitchRate {
    /// `ω = V / r_mean`, `r_mean` the mean rolling radius of the two wheels' contacts (the
    /// rigid contacts or the heaviest patches) at the position.
    #[default]
    FreeRolling,
    /// Given rates, rad/s, one per position of the sweep in its order (positive rolls
    /// forwards).
    Given(Vec<f64>),
}

/// The wheelset's motion along a sweep, beyond what each position fixes (roll, yaw).
///
/// # Units
///
/// mm/s, rad/s.
#[derive(Debug, Clone, PartialEq)]
pub struct Kinematics {
    /// Forward speed `V`, mm/s, positive.
    pub speed_mm_s: f64,
    /// The pitch-rate rule.
    pub pitch_rate: PitchRate,
    /// Lateral velocity of the wheelset's centre, mm/s, positive to the left.
    pub lateral_velocity_mm_s: f64,
    /// Yaw rate about the wheelset's vertical axis, rad/s.
    pub yaw_rate_rad_s: f64,
}

/// The default forward speed, mm/s: 2 m/s, CONTACT's speed in the Manchester case. Without
/// lateral and yaw velocity the creepages do not depend on it.
pub(crate) const DEFAULT_SPEED_MM_S: f64 = 2000.0;

impl Default for Kinematics {
    fn default() -> Self {
        Kinematics {
            speed_mm_s: DEFAULT_SPEED_MM_S,
            pitch_rate: PitchRate::FreeRolling,
            lateral_velocity_mm_s: 0.0,
            yaw_rate_rad_s: 0.0,
        }
    }
}

/// What a scene's `[creep]` asks for: the model, the motion and the contacts.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StageSettings {
    /// The tangential model, friction and material.
    pub settings: Settings,
    /// The motion.
    pub kinematics: Kinematics,
    /// The contacts the patches come from (default: the quasi-elastic patches).
    pub contact: crate::hertz::ContactSource,
}

/// One patch of one wheel at one position: what it was given and what it transmits.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchRow {
    /// 0 for the heaviest patch (or the rigid contact), 1 for the second.
    pub patch: usize,
    /// The contact point handed to [`super::forces`].
    pub point: ContactPoint,
    /// The vertical load the patch carries, N.
    pub vertical_load_n: f64,
    /// The forces, or why there are none (an input error's message).
    pub forces: Result<PatchForces, String>,
    /// A note on the row (patches left out), empty when there is none.
    pub note: String,
}

impl PatchRow {
    /// `converged`, `iteration_cap`, `no_equilibrium`, `not_hertzian` (see
    /// [`super::Status`]) or `error: ...`, with the row's note.
    pub fn status(&self) -> String {
        let mut s = match &self.forces {
            Ok(f) => f.status.as_str().to_string(),
            Err(e) => format!("error: {e}"),
        };
        if !self.note.is_empty() {
            s.push_str("; ");
            s.push_str(&self.note);
        }
        s
    }
}

/// The creep results of one wheel at one position.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SideCreep {
    /// Its patches, heaviest first; empty without contact.
    pub patches: Vec<PatchRow>,
    /// Why there are no patches (no contact, a rigid position that did not converge), or
    /// empty.
    pub missing: String,
}

/// The creep results at one position.
#[derive(Debug, Clone, PartialEq)]
pub struct Position {
    /// Lateral shift of the wheelset, mm.
    pub y_ws: f64,
    /// Yaw of the wheelset, rad.
    pub yaw: f64,
    /// Roll of the wheelset, rad.
    pub roll: f64,
    /// The pitch rate used, rad/s (NaN where free rolling had no mean radius).
    pub pitch_rate_rad_s: f64,
    /// Left and right wheels.
    pub sides: [SideCreep; 2],
}

impl Position {
    /// The wheel of `side`.
    pub fn side(&self, side: Side) -> &SideCreep {
        &self.sides[usize::from(side == Side::Right)]
    }
}

/// The creep forces over a sweep, with the settings that made them.
#[derive(Debug, Clone, PartialEq)]
pub struct CreepSweep {
    settings: Settings,
    kinematics: Kinematics,
    source: crate::hertz::ContactSource,
    positions: Vec<Position>,
}

impl CreepSweep {
    /// The tangential model's settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }
    /// The motion.
    pub fn kinematics(&self) -> &Kinematics {
        &self.kinematics
    }
    /// The contacts the patches came from.
    pub fn source(&self) -> crate::hertz::ContactSource {
        self.source
    }
    /// One result per position of the sweep, in its order.
    pub fn positions(&self) -> &[Position] {
        &self.positions
    }
}

/// The patches' inputs of one wheel: `(point, shape, weight share)` per patch, heaviest
/// first, and how many patches the search found.
type SideInputs = (Vec<(ContactPoint, Shape, f64)>, usize);

/// Creep forces of every patch over a sweep (module docs).
///
/// # Units
///
/// `wheel_load_n` in N; the rest as on [`Kinematics`] and [`Settings`].
///
/// # Errors
///
/// [`CreepError::PitchRates`] when a [`PitchRate::Given`] list does not have one rate per
/// position. A patch whose inputs [`super::forces`] refuses is a row
/// with that error, not an error of the sweep.
pub fn sweep(
    placement: &Placement,
    contacts: Contacts,
    wheel_load_n: f64,
    kinematics: &Kinematics,
    settings: &Settings,
) -> Result<CreepSweep, CreepError> {
    let rigid = match contacts {
        Contacts::Rigid(r) => r,
        Contacts::QuasiElastic(q) => q.rigid(),
    };
    if let PitchRate::Given(rates) = &kinematics.pitch_rate
        && rates.len() != rigid.positions().len()
    {
        return Err(CreepError::PitchRates {
            given: rates.len(),
            positions: rigid.positions().len(),
        });
    }
    let positions = rigid
        .positions()
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let converged = p.stop == Stop::Converged;
            let inputs = [Side::Left, Side::Right].map(|side| {
                if converged {
                    side_inputs(placement, contacts, i, side)
                } else {
                    (Vec::new(), 0)
                }
            });
            let pitch_rate_rad_s = match &kinematics.pitch_rate {
                PitchRate::Given(rates) => rates[i],
                PitchRate::FreeRolling => match (inputs[0].0.first(), inputs[1].0.first()) {
                    (Some(l), Some(r)) => {
                        let mean = 0.5 * (l.0.rolling_radius_mm + r.0.rolling_radius_mm);
                        kinematics.speed_mm_s / mean
                    }
                    _ => f64::NAN,
                },
            };
            let motion = Motion {
                speed_mm_s: kinematics.speed_mm_s,
                pitch_rate_rad_s,
                lateral_velocity_mm_s: kinematics.lateral_velocity_mm_s,
                roll_rad: p.roll,
                yaw_rad: p.yaw,
                yaw_rate_rad_s: kinematics.yaw_rate_rad_s,
            };
            let [left, right] = inputs.map(|(inputs, found)| {
                if !converged {
                    return SideCreep {
                        patches: Vec::new(),
                        missing: format!("rigid search: {}", p.stop.status_text()),
                    };
                }
                side_creep(inputs, found, wheel_load_n, &motion, settings)
            });
            Position {
                y_ws: p.y_ws,
                yaw: p.yaw,
                roll: p.roll,
                pitch_rate_rad_s,
                sides: [left, right],
            }
        })
        .collect();
    Ok(CreepSweep {
        settings: *settings,
        kinematics: kinematics.clone(),
        source: contacts.source(),
        positions,
    })
}

/// The forces of one wheel's patches from their `inputs` (`found` patches in all).
fn side_creep(
    inputs: Vec<(ContactPoint, Shape, f64)>,
    found: usize,
    wheel_load_n: f64,
    motion: &Motion,
    settings: &Settings,
) -> SideCreep {
    if inputs.is_empty() {
        return SideCreep {
            patches: Vec::new(),
            missing: "no contact".into(),
        };
    }
    let note = if found > inputs.len() {
        format!(
            "{found} patches: the {} lightest left out",
            found - inputs.len()
        )
    } else {
        String::new()
    };
    let patches = inputs
        .into_iter()
        .enumerate()
        .map(|(k, (point, shape, share))| {
            let patch = Patch {
                shape,
                point,
                vertical_load_n: wheel_load_n * share,
            };
            PatchRow {
                patch: k,
                point,
                vertical_load_n: patch.vertical_load_n,
                forces: super::forces(&patch, motion, settings).map_err(|e| e.to_string()),
                note: note.clone(),
            }
        })
        .collect();
    SideCreep {
        patches,
        missing: String::new(),
    }
}

/// The most patches a wheel's row lists: the heaviest and the second.
pub(crate) const MAX_PATCHES: usize = 2;

/// The inputs of the patches of wheel `side` at position `i` (see [`SideInputs`]).
fn side_inputs(placement: &Placement, contacts: Contacts, i: usize, side: Side) -> SideInputs {
    let k = usize::from(side == Side::Right);
    let taping = placement.side(side).wheel().taping_line_mm();
    let input = |s: f64, r: f64, gamma: f64, lead: f64, k_wheel: f64, k_rail: f64| {
        let (a_per_mm, b_per_mm) = relative_curvatures(
            &PrincipalCurvatures {
                wheel_rolling: gamma.cos() / r,
                wheel_lateral: k_wheel,
                rail_rolling: 0.0,
                rail_lateral: k_rail,
            },
            0.0,
        );
        let point = ContactPoint {
            lead_mm: lead,
            lateral_mm: side.sign() * (taping + s),
            rolling_radius_mm: r,
            contact_angle_rad: side.sign() * gamma,
        };
        (point, Shape::Curvatures { a_per_mm, b_per_mm })
    };
    match contacts {
        Contacts::Rigid(rigid) => match rigid.positions()[i].contact[k] {
            Some(c) => {
                let (point, shape) = input(
                    c.s,
                    c.r,
                    c.gamma,
                    c.lead,
                    c.wheel_curvature,
                    c.rail_curvature,
                );
                (vec![(point, shape, 1.0)], 1)
            }
            None => (Vec::new(), 0),
        },
        Contacts::QuasiElastic(qe) => {
            let patches = &qe.positions()[i].sides[k].patches;
            let inputs = patches
                .iter()
                .take(MAX_PATCHES)
                .map(|m| {
                    let (point, shape) = input(
                        m.s,
                        m.r,
                        m.gamma,
                        m.lead,
                        m.wheel_curvature,
                        m.rail_curvature,
                    );
                    (point, shape, m.weight_share)
                })
                .collect();
            (inputs, patches.len())
        }
    }
}

/// Force against creepage on one patch of a sweep, for the three models: the patch's own
/// creepages `(ξ, η, φ)` scaled by `k` from 0 (free rolling) through 1 (the patch as the
/// sweep found it) towards full sliding, on its ellipse at its normal force (held fixed).
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Position of the patch: the wheelset's shift, mm.
    pub y_ws: f64,
    /// Its wheel.
    pub side: Side,
    /// Its index on the wheel (0 heaviest).
    pub patch: usize,
    /// The patch's creepages and forces as the sweep found them.
    pub at: PatchForces,
    /// The creepage magnitude `k √(ξ² + η²)` of each point (dimensionless).
    pub creepage: Vec<f64>,
    /// For each model, `√(Fx² + Fy²) / (μ FN)` at each point.
    pub force: Vec<(super::Method, Vec<f64>)>,
}

/// Points of a [`Curve`].
const CURVE_POINTS: usize = 61;
/// The curve runs until linear theory would carry this many times `μ FN` (and at least to
/// 1.5 times the patch's own creepage).
const CURVE_LINEAR_REACH: f64 = 3.0;

/// A patch considered for [`curve`]: its rank (in partial slip, friction use), where it is,
/// and its forces.
type Candidate<'a> = ((bool, f64), &'a Position, Side, &'a PatchRow, PatchForces);

/// Friction use `√(Fx² + Fy²) / (μ FN)` below which a patch is taken to be in partial slip
/// for [`curve`]: its mark then falls within the curve's rise.
const PARTIAL_SLIP_USE: f64 = 0.95;

/// The force-creepage curve of one patch of `sweep`: among the converged patches with a
/// longitudinal or lateral creepage, the one that uses the largest part of its friction
/// (`√(Fx² + Fy²) / (μ FN)`, the sweep's own model) while in partial slip (below 0.95), or
/// the one that uses the most where every patch slides; `None` when there is none.
pub fn curve(sweep: &CreepSweep) -> Option<Curve> {
    let settings = sweep.settings();
    let mu = settings.friction();
    let used =
        |f: &PatchForces| f.tangential.fx_n.hypot(f.tangential.fy_n) / (mu * f.normal_force_n);
    // Ranked by (in partial slip, friction use).
    let mut best: Option<Candidate> = None;
    for p in sweep.positions() {
        for side in [Side::Left, Side::Right] {
            for row in &p.side(side).patches {
                let Ok(f) = &row.forces else { continue };
                let slip = f.creepages.xi.hypot(f.creepages.eta);
                if !matches!(f.status, super::Status::Converged { .. })
                    || slip.is_nan()
                    || slip == 0.0
                {
                    continue;
                }
                let u = used(f);
                let rank = (u < PARTIAL_SLIP_USE, u);
                if best.as_ref().is_none_or(|b| rank > b.0) {
                    best = Some((rank, p, side, row, *f));
                }
            }
        }
    }
    let (_, position, side, row, at) = best?;
    let patch = super::tangential::EllipticPatch::new(at.a_mm, at.b_mm, at.normal_force_n).ok()?;
    let mu_fn = mu * at.normal_force_n;
    let of = |method: super::Method, k: f64| {
        let c = super::creepage::Creepages {
            xi: k * at.creepages.xi,
            eta: k * at.creepages.eta,
            phi_per_mm: k * at.creepages.phi_per_mm,
        };
        let t = super::tangential::solve(&patch, &c, &settings.with_method(method));
        t.fx_n.hypot(t.fy_n) / mu_fn
    };
    let linear_at_1 = of(super::Method::Linear, 1.0);
    let k_max = (CURVE_LINEAR_REACH / linear_at_1).max(1.5);
    let ks: Vec<f64> = (0..CURVE_POINTS)
        .map(|i| k_max * i as f64 / (CURVE_POINTS - 1) as f64)
        .collect();
    let slip = at.creepages.xi.hypot(at.creepages.eta);
    let force = [
        super::Method::Linear,
        super::Method::Fastsim,
        super::Method::Polach,
    ]
    .into_iter()
    .map(|m| (m, ks.iter().map(|&k| of(m, k)).collect()))
    .collect();
    Some(Curve {
        y_ws: position.y_ws,
        side,
        patch: row.patch,
        at,
        creepage: ks.iter().map(|k| k * slip).collect(),
        force,
    })
}
