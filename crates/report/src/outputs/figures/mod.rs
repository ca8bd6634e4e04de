//! Charts of stage results. Each function takes the stage result it draws (its dependency
//! is its signature) and returns a [`crate::Figure`](crate::Figure); rendering to
//! SVG/PNG bytes happens in [`super`].
//!
//! Jumps of a contact point are drawn as gaps (a NaN breaks the line), positions that did
//! not converge are left out, never joined across.
//!
//! One file per stage: [`profiles`], [`rigid`], [`quasi_elastic`], [`hertz`], [`conicity`],
//! [`creep`],
//! and the charts of the [`tradeoff`] studies ([`fastsim_tradeoff`] for FASTSIM's grid).

mod conicity;
mod creep;
mod hertz;
mod profiles;
mod quasi_elastic;
mod rigid;
mod tradeoff;

pub(crate) use conicity::{delta_r_linearised, equivalent_conicity};
pub(crate) use creep::{creep_curve, creep_forces};
pub(crate) use hertz::{hertz_accuracy, pressure, semi_axes};
pub(crate) use profiles::{conicity, conicity_caption, curvature, profiles};
pub(crate) use quasi_elastic::{epsilon_sensitivity, quasi_elastic_map, quasi_elastic_points};
pub(crate) use rigid::{
    contact_angle_parameter, contact_angles, contact_lead, contact_map, contact_points,
    flange_onsets, roll, rolling_radius,
};
pub(crate) use tradeoff::{fastsim_tradeoff, tradeoff};

const LEFT: usize = 0;
const RIGHT: usize = 1;
const RIGID: usize = 2;
const QE: usize = 3;

/// A polyline of `(x, y)` points.
type Line = Vec<(f64, f64)>;

const SHIFT: &str = "lateral shift of the wheelset y_ws (mm)";
