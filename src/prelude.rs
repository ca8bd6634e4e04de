//! The types and functions a typical use needs, in one import:
//! `use wheelrail::prelude::*;` (`examples/` are written on it).
//!
//! The stages' entry functions keep their module's name (`rigid::search`,
//! `quasi_elastic::search`, `hertz::sweep`, `conicity::assess`, `pipeline::run`, `fleet`'s
//! assessment): the modules themselves are re-exported here.

pub use crate::conicity::{self, ConicityMethod, ConicitySettings, PairConicity};
pub use crate::fleet;
pub use crate::hertz::{self, Contacts, EllipseMethod, HertzSettings, HertzSweep, Material};
pub use crate::pipeline;
pub use crate::profile::read::{PointProfile, ReadOptions, StepBack, read_profile_with};
pub use crate::profile::{Profile, ProfileKind};
pub use crate::quasi_elastic::{self, QuasiElasticSettings, QuasiElasticSweep};
pub use crate::rigid::{self, RigidSweep, Solver};
pub use crate::scene::Scene;
pub use crate::sweep::Sweep;
pub use crate::track::{Inclination, Placement, Side, TrackLayout};
pub use crate::{Error, Stop};
