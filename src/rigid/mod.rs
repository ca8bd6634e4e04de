//! Rigid contact search with the wheelset roll solved (paper Sect. 3, Eqs. 2-5).
//!
//! For every lateral shift `y_ws` of the sweep, [`search`] finds the roll `theta` and the
//! axle height `h` at which both wheels touch their rails (minimum gap zero on both sides) and
//! nothing penetrates. Zero yaw. Left and right profiles may differ.
//!
//! Why it works: the minimum gap of the left wheel `m_L(theta)` is the minimum of functions
//! that all grow with `theta` (roll lifts the left wheel), and `m_R` of functions that all
//! fall, so `F(theta) = m_L - m_R` is continuous and strictly increasing even where the
//! contact point jumps (there only its slope jumps). Its root is unique. By the envelope
//! theorem `dm/dphi = (Y - delta) + Zrail'(Y) z_rel` at the minimiser: the lever arm of the
//! contact point about the axle.
//!
//! Two solvers ([`Solver`]):
//!
//! * `Default`: Newton on `F` with that exact derivative, safeguarded by a bracket
//!   (bisection when a Newton step leaves it: `F` has kinks where the contact point jumps),
//!   continuation from the previous position, minima refined exactly inside basins found by
//!   one coarse scan per position and re-verified by a scan at the solution. Stops at
//!   `|F| <=` [`RollSettings::residual_tol_mm`] (1e-11 mm by default); its tolerances and
//!   caps are the [`RollSettings`] the variant carries.
//! * `Paper`: the paper's iteration, `theta += (d_min,r - d_min,l) / (y_min,l - y_min,r)`
//!   from `theta = 0` at every position, the minima taken over the wheel profile tabulated
//!   every `PAPER_TABLE_STEP_MM`, stopping at `|d_min,r - d_min,l| <` 1e-4 mm (its Eq. 4).
//!
//! Every [`RigidPosition`] says why its iteration stopped ([`Stop`]: `Converged`, `IterationCap`,
//! `NoContact`, `Stalled`); the outputs flag the others instead of plotting them.

mod continuation;
mod driver;
mod jumps;
mod level;
mod minima;
mod paper;
mod roll;
mod settings;
mod solve;

use minima::Scratch;
pub use settings::{RollSettings, RollSettingsError};
use solve::PositionSolver;

use crate::gap::ContactPoint;
use crate::sweep::{Mirror, Mirrored, Sweep, YawRule};
use crate::track::{Placement, Side};

/// Why the roll iteration at one position stopped (shared with [`crate::hertz`]).
pub use crate::Stop;

/// The paper's tolerance on `|d_min,r - d_min,l|` (its Eq. 4: "1e-4 is enough"), mm.
pub(crate) const PAPER_TOL_MM: f64 = 1e-4;
/// Iteration cap of the paper's solver (it states none; 1000 as for its Hertz iteration).
pub(crate) const PAPER_MAX_ITER: usize = 1000;
/// Spacing of the tabulated wheel profile the paper's solver searches (mm). The paper works
/// on "tabular data" without stating the spacing; 0.1 mm is a common table step.
pub(crate) const PAPER_TABLE_STEP_MM: f64 = 0.1;
/// A second local minimum of the gap within this distance of the first is reported as a
/// second contact point (mm). 0.01 mm is the paper's quasi-elastic regularisation: a smaller
/// separation is within the elastic approach of a loaded contact.
pub(crate) const TWO_POINT_GAP_TOL_MM: f64 = 0.01;

/// Which rigid solver to run, with its settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Solver {
    /// Newton with the exact derivative, continuation, exact minima (the project's), with
    /// its tolerances and caps.
    Default(RollSettings),
    /// The paper's semi-analytical iteration on tabulated profiles, with the paper's
    /// tolerance (`PAPER_TOL_MM`), a cap (`PAPER_MAX_ITER`) and table step
    /// (`PAPER_TABLE_STEP_MM`): reproduced as stated, not tuned.
    Paper,
    /// No roll: each wheel is shifted with the wheelset and lowered onto its own rail, the
    /// wheelset held level (scene key `[rigid] roll = "none"`). This is how the Δr
    /// functions of EN 15302 Annex E are computed (its case E3, cones of 1:40 and 1:5,
    /// has Δr slopes of exactly 2 x 0.025 and 0.025 + 0.2 per mm); a real wheelset rolls,
    /// which shifts its contact points by about `r0` times the roll.
    NoRoll,
}

impl Default for Solver {
    /// The project's solver with its default settings.
    fn default() -> Solver {
        Solver::Default(RollSettings::default())
    }
}

impl Solver {
    /// Name used in scene files and tables.
    pub fn name(self) -> &'static str {
        match self {
            Solver::Default(_) => "default",
            Solver::Paper => "paper",
            Solver::NoRoll => "no_roll",
        }
    }

    /// The solver of a [name](Solver::name) (the default one with its default settings).
    /// A scene names the level wheelset by its `roll` key, not as a solver.
    pub fn from_name(name: &str) -> Option<Solver> {
        match name {
            "default" => Some(Solver::default()),
            "paper" => Some(Solver::Paper),
            "no_roll" => Some(Solver::NoRoll),
            _ => None,
        }
    }
}

/// The rigid contact of one wheel at one position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SideContact {
    /// Wheel profile coordinate of the contact point (mm).
    pub s: f64,
    /// Track-frame lateral position of the contact point (mm).
    pub y: f64,
    /// Track-frame height of the contact point (mm).
    pub z: f64,
    /// Rolling radius `r0 + F(s)` (mm).
    pub r: f64,
    /// Contact angle in the track frame, mirrored per side, roll included (rad).
    pub gamma: f64,
    /// The rail's profile coordinate of the contact point (mm, rail side frame).
    pub rail_u: f64,
    /// Tangent of the rail's contact angle at the point (side frame, inclination included).
    pub rail_tan_gamma: f64,
    /// Lateral curvature of the wheel at the point, convex positive (1/mm).
    pub wheel_curvature: f64,
    /// Lateral curvature of the rail at the point, convex positive (1/mm).
    pub rail_curvature: f64,
    /// Longitudinal position of the contact point along the track (mm, x forward),
    /// relative to the wheelset centre: 0 without yaw.
    pub x: f64,
    /// Distance of the contact point ahead of the axle along the wheelset's own forward
    /// axis (mm): 0 without yaw (`crate::gap::Yaw::lead`).
    pub lead: f64,
    /// A second contact point: another local minimum of the gap within
    /// `TWO_POINT_GAP_TOL_MM`; `(s, gap)` in mm.
    pub second: Option<(f64, f64)>,
}

impl SideContact {
    /// The contact seen in the mirror `y -> -y` of the track: the other wheel's contact at
    /// the mirrored position. Only the track-frame `y` changes sign; the other columns are
    /// in the side frame or mirrored per side already.
    fn mirrored(&self) -> SideContact {
        SideContact {
            y: -self.y,
            ..*self
        }
    }

    /// The contact point's columns shared with the quasi-elastic patches.
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
}

/// The solution at one lateral position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidPosition {
    /// Lateral shift of the wheelset (mm).
    pub y_ws: f64,
    /// Yaw of the wheelset (rad), right-hand about +z: positive turns its forward axis to
    /// the left. Imposed by the sweep ([`crate::sweep::YawRule`]), not solved.
    pub yaw: f64,
    /// Roll (rad), right-hand about +x: positive lifts the left wheel.
    pub roll: f64,
    /// Height of the axle above the track origin (mm).
    pub axle_height: f64,
    /// Left and right contacts (`None` when that wheel has no contact).
    pub contact: [Option<SideContact>; 2],
    /// Roll iterations used.
    pub iterations: usize,
    /// Why the iteration stopped.
    pub stop: Stop,
    /// Final `|m_L - m_R|` (mm).
    pub residual: f64,
}

impl Mirrored for RigidPosition {
    /// The solution at the mirrored shift `y_ws` (`-self.y_ws`) of a mirror-symmetric
    /// wheelset: the wheels swap, the roll and the yaw change sign, the height stays.
    fn mirrored(&self, y_ws: f64) -> RigidPosition {
        RigidPosition {
            y_ws,
            // 0 - roll: a level wheelset's roll of 0 stays 0, not -0 (and the yaw).
            yaw: 0.0 - self.yaw,
            roll: 0.0 - self.roll,
            contact: [
                self.contact[1].map(|c| c.mirrored()),
                self.contact[0].map(|c| c.mirrored()),
            ],
            ..*self
        }
    }
}

impl RigidPosition {
    /// The contact of `side`.
    pub fn side(&self, side: Side) -> Option<&SideContact> {
        self.contact[side_index(side)].as_ref()
    }

    /// Rolling radius difference `r_left - r_right` (mm); NaN unless both wheels touch and
    /// the iteration converged; 0 where it is smaller than 1e-9 mm (`DELTA_R_RESOLUTION_MM`).
    pub fn delta_r(&self) -> f64 {
        match self.contact {
            [Some(l), Some(r)] if self.stop == Stop::Converged => resolved_delta_r(l.r - r.r),
            _ => f64::NAN,
        }
    }
}

/// The resolution of a rolling radius difference (mm): a Δr smaller than this is 0.
///
/// Each rolling radius is `r0 + F(s)` with `r0` of 300 to 600 mm, so two radii that are
/// equal in exact arithmetic differ by a few units of the last place of `r0` (6e-14 mm at
/// 460 mm): on a cylindrical band (EN 15302 case E4, wheel R-UIC519I) Δr is ±6e-13 mm
/// instead of 0, and the signs of that noise would make equilibria and turning points of
/// the kinematic motion out of nothing. 1e-9 mm is four orders of magnitude above that
/// rounding and cannot hide a real slope: a Δr of 1e-9 mm at a shift of 0.01 mm is a
/// conicity of 5e-8, five orders of magnitude below the 1e-3 to which `tan γe` is quoted
/// and judged (EN 15302 Annex F), and a real cone's Δr exceeds it at every sweep position
/// off the centre.
pub(crate) const DELTA_R_RESOLUTION_MM: f64 = 1e-9;

/// `delta_r` (mm), or 0 where it is smaller than [`DELTA_R_RESOLUTION_MM`] (NaN stays NaN).
pub(crate) fn resolved_delta_r(delta_r: f64) -> f64 {
    if delta_r.abs() < DELTA_R_RESOLUTION_MM {
        0.0
    } else {
        delta_r
    }
}

/// What a contact-point jump is: a jump between two contacts the profiles separate, or a
/// sampling artefact (`ARTEFACT_HOLLOW_MM`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JumpKind {
    /// The contact point jumps between two contacts separated by a hollow of the gap at
    /// least `ARTEFACT_HOLLOW_MM` deep (a tread-to-flange jump, a two-point contact):
    /// located to 1e-4 mm, a step of Δr, a break in the charts.
    Jump,
    /// A sampling artefact: the contact point hops between two minima of the gap of a
    /// sampled profile that a hollow shallower than `ARTEFACT_HOLLOW_MM` separates. Not
    /// refined (its interval is the sweep's step that holds it), continuous in Δr and in the
    /// charts, counted apart.
    Artefact,
}

impl JumpKind {
    /// The name in the `kind` column of `rigid_jumps.csv`.
    pub fn name(self) -> &'static str {
        match self {
            JumpKind::Jump => "jump",
            JumpKind::Artefact => "artefact",
        }
    }
}

/// The hollow below which a jump of a sampled profile's contact point is a sampling
/// artefact (mm): where the gap between the two contacts rises less than this above them.
///
/// A contact point jumps where two minima of the gap exchange the role of the lowest. On a
/// nearly conformal pair of sampled profiles (the EN 15302 reference wheel R-UIC519A on its
/// rail, whose tread curvature wanders by 2e-3 / mm around the rail crown's) the gap is flat
/// to a micrometre over millimetres and its minima lie in undulations of the data: the
/// contact point hops between them every few tenths of a millimetre of shift, across
/// hollows of at most 0.5 µm (measured on the 38 jumps of E1). A change of the profiles
/// within what their data resolve fills such a hollow and the contact point then moves
/// continuously; so does any loaded contact (the quasi-elastic regularisation spans 0.01
/// mm). 1.5 µm lies a factor 3 above those hops and below every tread-to-flange jump and
/// two-point contact of the committed scenes (5 µm and more) and the tread jump of S1002 on
/// UIC60 1:40 (3.9 µm, analytic; 4.3 µm in the Manchester benchmark's sampled files).
/// Built-in (analytic) profiles have no sampling: their jumps are always jumps.
pub const ARTEFACT_HOLLOW_MM: f64 = 2e-3;

/// An interval of `y_ws` across which the contact point of one wheel jumps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jump {
    /// The wheel whose contact point jumps.
    pub side: Side,
    /// Lower end of the interval (mm): of a jump, refined to 1e-4 mm; of an
    /// artefact, the sweep position before it.
    pub y_from: f64,
    /// Upper end of the interval (mm).
    pub y_to: f64,
    /// Wheel coordinate of the contact point at `y_from` (mm).
    pub s_from: f64,
    /// Wheel coordinate of the contact point at `y_to` (mm).
    pub s_to: f64,
    /// Rolling radius difference `r_left - r_right` at `y_from` (mm; NaN where a wheel has
    /// no contact): the value of the Δr function just before the jump.
    pub delta_r_from: f64,
    /// Rolling radius difference at `y_to` (mm): the value just after the jump.
    pub delta_r_to: f64,
    /// How far the gap rises between the two contacts above the higher of them, where they
    /// exchange the role of the lowest (mm; NaN where it could not be measured).
    pub hollow_mm: f64,
    /// A jump or a sampling artefact.
    pub kind: JumpKind,
}

impl Jump {
    /// The jump of the other wheel at the mirrored shifts of a mirror-symmetric wheelset:
    /// the interval's ends swap and change sign, and so does Δr.
    fn mirrored(&self) -> Jump {
        Jump {
            side: match self.side {
                Side::Left => Side::Right,
                Side::Right => Side::Left,
            },
            y_from: -self.y_to,
            y_to: -self.y_from,
            s_from: self.s_to,
            s_to: self.s_from,
            delta_r_from: -self.delta_r_to,
            delta_r_to: -self.delta_r_from,
            ..*self
        }
    }
}

/// A contact point moving more than this between neighbouring positions of the sweep is
/// examined as a possible jump (mm).
pub(crate) const JUMP_SCREEN_MM: f64 = 0.5;
/// Jump intervals are refined by bisection to this width in `y_ws` (mm).
pub const JUMP_REFINE_MM: f64 = 1e-4;
/// After refinement a jump must still move the contact point this far (mm); a contact point
/// that only moves fast shrinks its motion with the interval.
pub(crate) const JUMP_CONFIRM_MM: f64 = 0.1;

/// The rigid solution over a sweep, as [`search`] computed it (read through its accessors:
/// the stages computed from it rely on its positions being those of its sweep).
#[derive(Debug, Clone)]
pub struct RigidSweep {
    solver: Solver,
    positions: Vec<RigidPosition>,
    centre: RigidPosition,
    jumps: Vec<Jump>,
    /// Whether the positions before the middle are the mirror images of those after it.
    mirror: Option<Mirror>,
    /// The yaw of the wheelset along the sweep.
    yaw: YawRule,
}

impl RigidSweep {
    /// The yaw of the wheelset along the sweep (the positions' own in
    /// [`RigidPosition::yaw`]).
    pub fn yaw(&self) -> &YawRule {
        &self.yaw
    }

    /// The solver used.
    pub fn solver(&self) -> Solver {
        self.solver
    }

    /// One solution per lateral position, in sweep order.
    pub fn positions(&self) -> &[RigidPosition] {
        &self.positions
    }

    /// The centred solution (`y_ws = 0`), the reference of `z_ws` and `l0`.
    pub fn centre(&self) -> &RigidPosition {
        &self.centre
    }

    /// Contact-point jumps, by side and `y_ws`.
    pub fn jumps(&self) -> &[Jump] {
        &self.jumps
    }

    /// Whether the positions before the middle are the mirror images of those after it.
    pub(crate) fn mirror(&self) -> Option<Mirror> {
        self.mirror
    }

    /// Half the lateral distance between the contact points of the centred wheelset (mm):
    /// Wickens' `l0`.
    pub fn l0_mm(&self) -> f64 {
        match self.centre.contact {
            [Some(l), Some(r)] => 0.5 * (l.y - r.y),
            _ => f64::NAN,
        }
    }

    /// Vertical displacement of the wheelset relative to the centred position (mm, up).
    pub fn z_ws(&self, p: &RigidPosition) -> f64 {
        p.axle_height - self.centre.axle_height
    }

    /// The shift where the contact angle of `side` first exceeds `FLANGE_CONTACT_GAMMA_RAD`
    /// moving that wheel towards its rail (left: increasing `y_ws > 0`; right: decreasing
    /// `y_ws < 0`): linear between the two positions around the crossing, or the middle of a
    /// contact-point jump between them. NaN when the sweep does not reach it.
    pub fn flange_contact_mm(&self, side: Side) -> f64 {
        let outward: Vec<&RigidPosition> = match side {
            Side::Left => self.positions.iter().filter(|p| p.y_ws >= 0.0).collect(),
            Side::Right => self
                .positions
                .iter()
                .rev()
                .filter(|p| p.y_ws <= 0.0)
                .collect(),
        };
        let on = |g: f64| g > FLANGE_CONTACT_GAMMA_RAD;
        for w in outward.windows(2) {
            let (a, b) = (w[0], w[1]);
            let (ga, gb) = (contact_angle(a, side), contact_angle(b, side));
            if !on(gb) {
                continue;
            }
            if on(ga) {
                // Already on the flange at the first position of the half sweep.
                return a.y_ws;
            }
            let (lo, hi) = if a.y_ws < b.y_ws {
                (a.y_ws, b.y_ws)
            } else {
                (b.y_ws, a.y_ws)
            };
            if let Some(j) = self
                .jumps
                .iter()
                .find(|j| j.side == side && j.y_from >= lo && j.y_to <= hi)
            {
                return 0.5 * (j.y_from + j.y_to);
            }
            if ga.is_nan() {
                return b.y_ws;
            }
            let t = (FLANGE_CONTACT_GAMMA_RAD - ga) / (gb - ga);
            return a.y_ws + t * (b.y_ws - a.y_ws);
        }
        f64::NAN
    }

    /// Wickens' parameters of position `p` of this sweep (with its [`l0_mm`](Self::l0_mm));
    /// NaN at `y_ws = 0` (|y_ws| below `WICKENS_CENTRE_MM`), where they are undefined,
    /// and where the position did not converge.
    ///
    /// # Example
    /// ```
    /// use wheelrail::{pipeline, rigid, scene::Scene};
    /// let scene = Scene::from_toml("", "inline", std::path::Path::new(".")).unwrap();
    /// let shifts = wheelrail::sweep::Sweep::from_slice(&[2.0]).unwrap();
    /// let sweep = rigid::search(&pipeline::place(&scene).unwrap(), &shifts, rigid::Solver::default());
    /// let w = sweep.wickens(&sweep.positions()[0]);
    /// // S1002 on UIC60 1:40 at 2 mm: a conicity of about 0.2.
    /// assert!(w.lambda > 0.1 && w.lambda < 0.3);
    /// ```
    pub fn wickens(&self, p: &RigidPosition) -> Wickens {
        if p.stop != Stop::Converged || p.y_ws.abs() < WICKENS_CENTRE_MM {
            return Wickens {
                lambda: f64::NAN,
                epsilon: f64::NAN,
                sigma: f64::NAN,
            };
        }
        let l0 = self.l0_mm();
        let tan = |k: usize| p.contact[k].map_or(f64::NAN, |c| c.gamma.tan());
        Wickens {
            lambda: p.delta_r() / (2.0 * p.y_ws),
            epsilon: l0 * (tan(0) - tan(1)) / (2.0 * p.y_ws),
            sigma: l0 * p.roll / p.y_ws,
        }
    }
}

/// Contact angle above which a wheel is in flange contact (rad): 63°, below the flank angle
/// of S1002 (70°, 1.22 rad) and of the usual worn flanges (65-70°), above every tread and
/// flange-root contact (S1002 on UIC60 1:40 reaches 0.9 rad at the root).
pub(crate) const FLANGE_CONTACT_GAMMA_RAD: f64 = 1.1;

/// The contact angle of `side` at `p` (rad), NaN unless it converged with that contact.
pub(crate) fn contact_angle(p: &RigidPosition, side: Side) -> f64 {
    match p.side(side) {
        Some(c) if p.stop == Stop::Converged => c.gamma,
        _ => f64::NAN,
    }
}

/// Shifts closer to 0 than this are the centred wheelset, where Wickens' parameters, ratios
/// to `y_ws`, are undefined (mm; the sweep rounds its positions to 1e-9 mm).
pub const WICKENS_CENTRE_MM: f64 = 1e-12;

/// Wickens' linearisation parameters of one position (A. H. Wickens, Fundamentals of Rail
/// Vehicle Dynamics, 2003), with `l0` half the lateral distance between the contact points
/// of the centred wheelset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wickens {
    /// Equivalent conicity `λ = Δr / (2 y_ws)` (dimensionless).
    pub lambda: f64,
    /// Contact angle parameter `ε = l0 (tan γ_l - tan γ_r) / (2 y_ws)` (dimensionless).
    pub epsilon: f64,
    /// Roll angle parameter `σ = l0 θ / y_ws` (dimensionless).
    pub sigma: f64,
}

fn side_index(side: Side) -> usize {
    match side {
        Side::Left => 0,
        Side::Right => 1,
    }
}

/// Solves the rigid contact at every lateral shift of `sweep_mm` (increasing).
///
/// A [mirror-symmetric](Placement::is_mirror_symmetric) wheelset on a sweep symmetric about
/// the centre (shifts opposite within 1e-12 mm, as scenes and evenly spaced sweeps give
/// them) is solved from the middle position on, and the positions before it and their jumps are the mirror images:
/// the wheels swapped, the roll and the track-frame `y` of the contacts negated. They equal
/// what solving them gives to the solver's accuracy (bit for bit for the level wheelset),
/// and the Δr function is exactly odd.
///
/// # Example
/// ```
/// use wheelrail::{scene::Scene, pipeline, rigid};
/// let scene = Scene::from_toml("", "inline", std::path::Path::new(".")).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// let sweep = rigid::search(&placement, &wheelrail::sweep::Sweep::from_slice(&[0.0, 3.0]).unwrap(), rigid::Solver::default());
/// // A symmetric wheelset at y_ws = 0 does not roll.
/// assert!(sweep.positions()[0].roll.abs() < 1e-12);
/// // Shifted to the left it rolls to lift the left wheel (positive roll, crate docs).
/// assert!(sweep.positions()[1].roll > 0.0);
/// ```
pub fn search(placement: &Placement, sweep: &Sweep, solver: Solver) -> RigidSweep {
    let solve = PositionSolver::new(placement, solver, *sweep.yaw());
    // The centre's buffers serve the jumps' refinements after it.
    let mut scratch = Scratch::default();
    let centre = solve.solve(0.0, 0.0, &mut scratch, None);
    let mirror = Mirror::of(placement, sweep);
    let positions = driver::positions(&solve, sweep, mirror, centre.roll);
    let jumps = driver::jumps(&solve, &positions, mirror, &mut scratch);
    RigidSweep {
        solver,
        positions,
        centre,
        jumps,
        mirror,
        yaw: *sweep.yaw(),
    }
}

/// `sweep` (solved by [`search`] on `placement`) continued beyond its ends to reach
/// `from` and `to` (mm): new positions spaced as the sweep's end steps (for a sweep of one
/// position, 0.1 mm: `EXTENSION_STEP_MM`) and rounded to 1e-9 mm, each end continued
/// outwards from the positions nearest it, and the jumps of the new windows. The positions
/// and jumps it had are kept as they are, so the result holds the sweep's values to the bit
/// where they overlap. A bound already
/// inside the sweep adds nothing on that side. The result is not mirrored: the quasi-
/// elastic pass and the Hertz sweep are computed on the scene's own sweep, not on this
/// one (the equivalent conicity asks for it, [`crate::conicity::assess_on`]).
pub(crate) fn extend(placement: &Placement, sweep: &RigidSweep, from: f64, to: f64) -> RigidSweep {
    let p = &sweep.positions;
    let n = p.len();
    let step = |a: usize, b: usize| {
        if n > 1 {
            (p[b].y_ws - p[a].y_ws).abs()
        } else {
            EXTENSION_STEP_MM
        }
    };
    let outwards = |start: f64, step: f64, bound: f64| -> Vec<f64> {
        let count = ((bound - start).abs() / step - 1e-9).ceil().max(0.0) as usize;
        // Rounded to 1e-9 mm as `Sweep::range` rounds its shifts: clean printed values.
        (1..=count)
            .map(|i| ((start + (bound - start).signum() * step * i as f64) * 1e9).round() / 1e9)
            .collect()
    };
    let left = outwards(p[0].y_ws, step(0, 1.min(n - 1)), from.min(p[0].y_ws));
    let right = outwards(
        p[n - 1].y_ws,
        step(n.saturating_sub(2), n - 1),
        to.max(p[n - 1].y_ws),
    );
    if left.is_empty() && right.is_empty() {
        return sweep.clone();
    }
    let solve = PositionSolver::new(placement, sweep.solver, sweep.yaw);
    let ends = |positions: &[RigidPosition]| -> Vec<RigidPosition> {
        positions
            .iter()
            .filter(|q| q.stop == Stop::Converged)
            .copied()
            .collect()
    };
    let roll_of = |q: &RigidPosition| q.roll;
    // Each end from its last three positions, in the order a continuation outwards would
    // have solved them.
    let before_left: Vec<RigidPosition> = ends(&p[..3.min(n)]).into_iter().rev().collect();
    let before_right = ends(&p[n.saturating_sub(3)..]);
    let mut new_left = driver::continued(
        &solve,
        &before_left,
        left.iter().copied(),
        p.first().map_or(0.0, roll_of),
    );
    new_left.reverse();
    let new_right = driver::continued(
        &solve,
        &before_right,
        right.iter().copied(),
        p.last().map_or(0.0, roll_of),
    );
    let mut scratch = Scratch::default();
    let mut positions = new_left;
    let mut jumps = Vec::new();
    if !positions.is_empty() {
        positions.push(p[0]);
        jumps = driver::jumps_in(&solve, &positions, &mut scratch);
        positions.pop();
    }
    jumps.extend(sweep.jumps.iter().copied());
    positions.extend(p.iter().copied());
    if !new_right.is_empty() {
        let mut window = vec![p[n - 1]];
        window.extend(new_right.iter().copied());
        jumps.extend(driver::jumps_in(&solve, &window, &mut scratch));
        positions.extend(new_right);
    }
    RigidSweep {
        solver: sweep.solver,
        positions,
        centre: sweep.centre,
        jumps,
        mirror: None,
        yaw: sweep.yaw,
    }
}

/// The step of [`extend`] beyond a sweep of one position (mm): the EN 15302 Annex E grid.
pub(crate) const EXTENSION_STEP_MM: f64 = 0.1;

#[cfg(test)]
mod tests {
    use super::*;

    /// Every solver's name reads back as that solver (the default one with its default
    /// settings), and no other name does.
    #[test]
    fn solver_names_round_trip() {
        for solver in [Solver::default(), Solver::Paper, Solver::NoRoll] {
            assert_eq!(Solver::from_name(solver.name()), Some(solver));
        }
        assert_eq!(Solver::from_name("fast"), None);
    }

    /// A sweep from -2 to 2 mm by 0.5 mm extended to ±3 mm gains two positions at each end
    /// at the same step and keeps its own positions to the bit.
    #[test]
    fn an_extended_sweep_keeps_its_positions() {
        let scene = crate::scene::Scene::from_toml("", "inline", std::path::Path::new("."))
            .expect("the default scene");
        let placement = crate::pipeline::place(&scene).expect("the default placement");
        let sweep = search(
            &placement,
            &Sweep::range(-2.0, 2.0, 0.5).expect("a valid range"),
            Solver::default(),
        );
        let wider = extend(&placement, &sweep, -3.0, 3.0);
        assert_eq!(wider.positions().len(), 13);
        assert_eq!(wider.positions()[2], sweep.positions()[0]);
    }
}
