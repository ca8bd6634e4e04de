//! # wheelrail
//!
//! Railway wheel/rail contact geometry and Hertzian contact, after Onat, Voltr & Lata (2014),
//! "Nonlinear wheel/rail contact geometry characteristics & determination of Hertzian contact".
//!
//! The pipeline is the module list:
//!
//! 1. [`profile`]: wheel and rail profiles (analytic S1002 and UIC60, or read from files),
//!    their slopes and curvatures;
//! 2. [`track`]: placing the wheels and rails of a wheelset on the track
//!    ([`track::Placement`], mirror-symmetric or not), over a [`sweep::Sweep`] of shifts;
//! 3. [`rigid`]: rigid contact search with the wheelset roll solved (paper Eqs. 2-5);
//! 4. [`quasi_elastic`]: quasi-elastic contact search (paper Eqs. 6-8);
//! 5. [`hertz`]: the Hertz contact ellipse (paper Eqs. 9-20), one or over a sweep;
//! 6. [`conicity`]: the equivalent conicity of EN 15302 from the rigid Δr function, and the
//!    parameters of a wheel/rail pair;
//! 7. [`creep`]: creepages from the wheelset's motion and the creep forces of a patch
//!    (Kalker's linear theory, FASTSIM, Polach), and over a sweep (the stage a scene's
//!    `[creep]` runs);
//! 8. [`contact_table`]: the contact table a vehicle model reads (shift × yaw);
//!
//! and beside the contact pipeline, [`maintenance`]: a wheel's flange dimensions Sh, Sd, qR
//! (EN 15313) against their limits, a rail's wear against its nominal profile.
//!
//! and [`scene`] describes a run, [`pipeline`] computes exactly the stages a scene's outputs
//! need, [`fleet`] assesses many profiles against one scene; beside them [`gap`] gives the
//! gap of a wheel over its rail at one point (what both searches stand on), [`cache`]
//! shares placed profiles between the scenes of a run, [`cost`] estimates a scene's work
//! and [`plausible`] holds the accepted ranges of physical inputs. [`prelude`] holds what a
//! typical use needs; [`Error`] converts from every error type of the crate. The crate has
//! no features and knows no file format it writes: the crate `wheelrail-report` turns
//! results into tables, CSV, charts and pages, and `wheelrail-cli` is the command line.
//!
//! # Quick start
//!
//! Profiles from your own points (here S1002 and 60E1 sampled every 0.5 mm, in their side
//! frames), a standard-gauge track with rails inclined 1:40, a rigid sweep, and the
//! equivalent conicity of EN 15302 (`examples/own_profiles.rs` prints more):
//!
//! ```
//! use wheelrail::prelude::*;
//!
//! # fn main() -> Result<(), Error> {
//! let points = |p: Profile| p.sample(0.5).iter().map(|r| [r[0], r[1]]).collect();
//! let wheel = PointProfile::from_points(ProfileKind::Wheel, "my wheel", points(Profile::s1002()))?;
//! let rail = PointProfile::from_points(ProfileKind::Rail, "my rail", points(Profile::uic60e1()))?;
//! let (wheel, rail) = (Profile::from_points(wheel, 0.0)?, Profile::from_points(rail, 0.0)?);
//!
//! let layout = TrackLayout::standard(Inclination::parse("1:40")?);
//! let placement = Placement::symmetric(wheel, 460.0, rail, Inclination::VERTICAL, layout)?;
//! let sweep = rigid::search(&placement, &Sweep::range(-10.0, 10.0, 0.1)?, Solver::default());
//! let pair = conicity::assess(&sweep, &ConicitySettings::default());
//! assert!((0.1..0.3).contains(&pair.parameters.tan_gamma_e_3mm));
//! # Ok(())
//! # }
//! ```
//!
//! # Units
//!
//! Millimetres, newtons, megapascals (N/mm²) and radians everywhere inside and in every output.
//! Scene keys and CSV columns carry their unit in the name (`gauge_mm`, `p0_MPa`, `roll_rad`);
//! other units (`wheel_load_kN`, `young_GPa`) are converted once when a scene is loaded.
//!
//! # Frames and signs
//!
//! Track frame: x forward, **y lateral positive to the left**, **z up**; origin on the track
//! centre line at the height of the top of the (inclined) rails. The left rail and wheel are at
//! y > 0. A wheelset shift `y_ws > 0` moves the wheelset to the left (the left flange approaches
//! the left rail). Roll is a right-hand rotation about +x: positive roll lifts the left wheel.
//!
//! Each wheel and rail is described in its own *mirrored* side frame whose lateral coordinate
//! grows towards the field side (away from the track centre), so a symmetric wheelset gives the
//! same numbers on both sides at `y_ws = 0`:
//!
//! * wheel: `s` (mm) from the taping line, positive towards the field side (the flange is at
//!   s < 0); `F(s)` (mm) the radius increase over the nominal radius, positive towards the
//!   flange tip. The rolling radius is `r = r0 + F(s)`.
//! * rail: lateral coordinate positive towards the field side, height positive up.
//! * contact angle `gamma`: angle of the tangent plane to the track plane in the side frame,
//!   positive on the conical tread and on the flange (about +0.03 rad on the tread, +1.22 rad
//!   on the S1002 flank); `tan(gamma) = -dF/ds` for the wheel, `dz/dy` for the rail.
//!
//! This is the full statement: the types that carry a frame restate it, and every CSV header
//! repeats it.

/// Counts `n` events of a [`counters`] kind with the feature `count-evaluations`; nothing
/// without it.
macro_rules! count {
    ($event:ident, $n:expr) => {
        #[cfg(feature = "count-evaluations")]
        $crate::counters::add($crate::counters::Event::$event, $n as u64);
    };
}

pub mod cache;
pub mod conicity;
pub mod contact_table;
pub mod cost;
#[cfg(feature = "count-evaluations")]
pub mod counters;
pub mod creep;
mod delimited;
mod error;
pub mod fleet;
pub mod gap;
pub mod hertz;
pub mod maintenance;
pub mod message;
pub mod pipeline;
pub mod plausible;
pub mod prelude;
pub mod profile;
pub mod quasi_elastic;
pub mod rigid;
pub mod rng;
pub mod scene;
mod stage;
mod stop;
pub mod sweep;
pub mod track;

pub use error::Error;
pub use stop::Stop;
