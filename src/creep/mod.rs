//! Creep forces: what a contact patch transmits tangentially, from the wheelset's motion.
//!
//! Stage entry: [`forces`], one patch at a time: the creepages from the motion
//! ([`creepage`]), the normal force from the patch's share of the wheel's vertical load
//! ([`normal`]), the Hertz ellipse for that normal force ([`crate::hertz::ellipse`]), and the
//! tangential forces by one of three models behind one interface (`tangential::solve`):
//!
//! * [`Method::Linear`]: Kalker's linear theory (Kalker 1990, Appendix E; Johnson 1985,
//!   §8.4), the limit of small creepage, with Kalker's coefficients ([`coefficients`]);
//! * [`Method::Fastsim`] (default): Kalker's simplified theory, FASTSIM (Kalker 1982), with
//!   the parabolic or elliptic traction bound and three flexibilities blended as CONTACT
//!   blends them ([`fastsim`]);
//! * [`Method::Polach`]: Polach's closed form (Polach 1999), with his spin extension
//!   ([`polach`]).
//!
//! # Units
//!
//! Millimetres, newtons, MPa (N/mm²), radians, seconds. Creepages ξ, η dimensionless, the
//! spin φ in 1/mm; forces in N, the spin moment in N mm.
//!
//! # Frames and signs
//!
//! **Forces are those of the wheel on the rail**, in the patch's contact frame, and the
//! creepages are the velocity of the rail relative to the wheel over the rolling speed
//! (Kalker's and CONTACT's convention): a positive creepage gives a negative force, the
//! linear theory reads `Fx = -G c² C11 ξ`. The contact frame is the track frame (x forward,
//! y left, z up) turned about x by the patch's contact angle δ: `t_x` along the rail, `t_y`
//! in the tangent plane, `n` the normal out of the rail into the wheel (see [`creepage`]).
//! `Fy` is along `t_y`, `Mz` about `n`. The normal force `FN` presses the rail along `-n`;
//! the vertical load the patch carries is `FZ = FN cos δ - Fy sin δ` ([`normal`]). CONTACT's
//! frame is this one turned by π about x: its `FX`, `FN` equal ours, its `FS`, `MN`, `CETA`,
//! `CPHI` are the negatives of our `Fy`, `Mz`, `η`, `φ`.
//!
//! # References
//!
//! * J.J. Kalker (1990), Three-dimensional elastic bodies in rolling contact, Kluwer:
//!   §1.2 (creepages), Appendix E (linear theory, Table E.3), Ch. 3 (simplified theory);
//!   cited by section: equation numbers were not checked against the book.
//! * J.J. Kalker (1982), A fast algorithm for the simplified theory of rolling contact,
//!   Vehicle System Dynamics 11, 1-13 (FASTSIM).
//! * O. Polach (1999), A fast wheel-rail forces calculation computer code, Vehicle System
//!   Dynamics 33 (Suppl.), 728-739; O. Polach (2005), Creep forces in simulations of
//!   traction vehicles running on adhesion limit, Wear 258, 992-1000 (§2 restates the
//!   method with spin as used here; that paper's reduction factors for large creepage are
//!   not used).
//! * E.A.H. Vollebregt, CONTACT (github.com/eve70a/CONTACT): its FASTSIM with three
//!   flexibilities and their blending (`simpflex` in `src/m_hertz.f90`).
//! * K.L. Johnson (1985), Contact Mechanics, Cambridge University Press, Ch. 8.

pub mod coefficients;
pub mod command;
pub mod creepage;
pub mod fastsim;
pub mod linear;
pub mod normal;
pub mod polach;
pub mod sweep;
pub mod tangential;

mod error;
mod patch;
mod settings;

pub use error::CreepError;
pub use patch::{Patch, PatchForces, Shape, Status, forces};
pub(crate) use settings::DEFAULT_FRICTION;
pub use settings::{Bound, DEFAULT_GRID, Flexibility, Grid, Method, Scheme, Settings};
