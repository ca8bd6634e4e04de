//! The contact table a vehicle model reads: the rigid contact of each wheel, its Hertz
//! ellipse and Kalker's creep coefficients on a grid of lateral shift × yaw.
//!
//! Stage entry: [`compute`]. Each yaw of the grid is one rigid sweep over the shifts with
//! that fixed yaw ([`crate::rigid::search`], the yawed outline of `crate::gap`), followed
//! by the Hertz sweep of its rigid contacts ([`crate::hertz::sweep`], the scene's method and
//! normal-load rule) and Kalker's coefficients of each ellipse
//! (`crate::creep::coefficients::kalker`): the pipeline's own stages, so that the row of
//! yaw 0 is the ordinary rigid and Hertz sweep's, to the bit.
//!
//! # Frames, units, interpolation
//!
//! As [`crate::rigid`] and [`crate::hertz`] state them (track frame x forward, y left, z
//! up; mm, N, MPa, rad). The values are those at the grid's nodes. Between two nodes a
//! linear interpolation is as good as the grid is fine, except across a jump of a contact
//! point (the onset of flange contact): there the quantities of the wheel change
//! discontinuously between the two nodes and no interpolation holds.

use crate::creep::coefficients::{Coefficients, kalker};
use crate::gap::YawModel;
use crate::hertz::{Contacts, HertzSettings, HertzSweep, SideHertz};
use crate::rigid::{self, RigidSweep, Solver};
use crate::sweep::{MAX_YAW_RAD, Sweep, SweepError, YawRule};
use crate::track::Placement;
use std::fmt;

/// The most yaws a grid may have: each is one rigid sweep.
pub(crate) const MAX_YAWS: usize = 401;

/// A grid of lateral shift × yaw, checked by [`Grid::new`].
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    shifts: Sweep,
    yaws_rad: Vec<f64>,
    model: YawModel,
}

/// A grid that cannot be computed.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum GridError {
    /// No yaw, more than 401 (`MAX_YAWS`), or yaws that do not increase.
    Yaws {
        /// How many were given.
        count: usize,
    },
    /// A yaw beyond ±0.05 rad (`MAX_YAW_RAD`) or not finite.
    Yaw(SweepError),
}

impl fmt::Display for GridError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GridError::Yaws { count } => write!(
                f,
                "{count} yaws: expected 1 to {MAX_YAWS}, strictly increasing"
            ),
            GridError::Yaw(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for GridError {}

impl Grid {
    /// The grid of `shifts` (mm) and `yaws_rad` (rad, strictly increasing, each within
    /// ±0.05 rad, `MAX_YAW_RAD`), the yawed outline by `model`.
    ///
    /// # Errors
    ///
    /// [`GridError::Yaws`] for an empty, too long or not increasing list,
    /// [`GridError::Yaw`] for a yaw out of range.
    pub fn new(shifts: Sweep, yaws_rad: Vec<f64>, model: YawModel) -> Result<Grid, GridError> {
        let count = yaws_rad.len();
        if count == 0 || count > MAX_YAWS || yaws_rad.windows(2).any(|w| w[1] <= w[0]) {
            return Err(GridError::Yaws { count });
        }
        for &yaw in &yaws_rad {
            shifts
                .clone()
                .with_yaw(YawRule::new(yaw, 0.0, model))
                .map_err(GridError::Yaw)?;
        }
        debug_assert!(yaws_rad.iter().all(|y| y.abs() <= MAX_YAW_RAD));
        Ok(Grid {
            shifts,
            yaws_rad,
            model,
        })
    }

    /// The lateral shifts, mm.
    pub fn shifts(&self) -> &Sweep {
        &self.shifts
    }

    /// The yaws, rad, increasing.
    pub fn yaws_rad(&self) -> &[f64] {
        &self.yaws_rad
    }

    /// The yawed outline's model.
    pub fn model(&self) -> YawModel {
        self.model
    }
}

/// One yaw of the table: its rigid sweep, its Hertz sweep and the coefficients of each
/// ellipse.
#[derive(Debug, Clone)]
pub struct YawRow {
    /// The yaw, rad.
    pub yaw_rad: f64,
    /// The rigid sweep at this yaw.
    pub rigid: RigidSweep,
    /// The Hertz ellipses of its contacts.
    pub hertz: HertzSweep,
    /// Kalker's coefficients per position and wheel (`None` without an ellipse).
    pub coefficients: Vec<[Option<Coefficients>; 2]>,
}

/// The contact table: one [`YawRow`] per yaw of the grid, in its order.
#[derive(Debug, Clone)]
pub struct ContactTable {
    /// The grid.
    pub grid: Grid,
    /// The Hertz settings used.
    pub hertz: HertzSettings,
    /// Poisson's ratio of the coefficients.
    pub poisson: f64,
    /// Vertical load per wheel, N.
    pub wheel_load_n: f64,
    /// One row per yaw.
    pub rows: Vec<YawRow>,
}

/// The contact table on `grid` (module docs): the rigid search by `solver`, ellipses for
/// `wheel_load_n` (N) with the effective modulus `e_star_mpa` (MPa), coefficients for
/// Poisson's ratio `poisson`.
///
/// # Example
///
/// ```
/// use wheelrail::contact_table::{Grid, compute};
/// use wheelrail::{pipeline, scene::Scene, sweep::{Sweep, YawModel}};
/// let scene = Scene::from_toml("", "doc", ".".as_ref()).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// let grid = Grid::new(Sweep::range(-2.0, 2.0, 2.0).unwrap(), vec![-0.005, 0.0, 0.005], YawModel::Exact).unwrap();
/// let table = compute(&placement, &grid, Default::default(), 70e3, 115_385.0, &Default::default(), 0.3);
/// assert_eq!(table.rows.len(), 3);
/// assert!(table.rows[2].rigid.positions()[1].contact[0].unwrap().lead.abs() > 0.0);
/// ```
pub fn compute(
    placement: &Placement,
    grid: &Grid,
    solver: Solver,
    wheel_load_n: f64,
    e_star_mpa: f64,
    hertz: &HertzSettings,
    poisson: f64,
) -> ContactTable {
    let rows = grid
        .yaws_rad
        .iter()
        .map(|&yaw_rad| {
            let sweep = grid
                .shifts
                .clone()
                .with_yaw(YawRule::new(yaw_rad, 0.0, grid.model))
                .expect("Grid::new checked every yaw");
            let rigid = rigid::search(placement, &sweep, solver);
            let h = crate::hertz::sweep(Contacts::Rigid(&rigid), wheel_load_n, e_star_mpa, hertz);
            let coefficients = h
                .positions()
                .iter()
                .map(|p| p.sides.each_ref().map(|s| coefficients_of(s, poisson)))
                .collect();
            YawRow {
                yaw_rad,
                rigid,
                hertz: h,
                coefficients,
            }
        })
        .collect();
    ContactTable {
        grid: grid.clone(),
        hertz: *hertz,
        poisson,
        wheel_load_n,
        rows,
    }
}

/// Kalker's coefficients of a wheel's ellipse, if it has one.
fn coefficients_of(side: &SideHertz, poisson: f64) -> Option<Coefficients> {
    side.ellipse().map(|e| kalker(e.a_mm / e.b_mm, poisson))
}
