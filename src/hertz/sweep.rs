//! Hertz contact over a lateral sweep: the contact ellipse of each wheel at each position,
//! from the quasi-elastic (default) or the rigid contact.
//!
//! Curvatures at the contact point (psi = 0 on straight track):
//! wheel rolling `cos(gamma) / r` (the normal meets the axle at `r / cos(gamma)`), wheel
//! lateral and rail lateral from the contact search (convex positive), rail rolling 0; so
//! `A = cos(gamma) / (2 r)` and `B = (k_wheel + k_rail) / 2`.
//!
//! Normal load from the vertical wheel load `Q`: `P = Q / cos(gamma)` (projected, default:
//! the normal force whose vertical component carries `Q`, lateral force ignored) or `P = Q`
//! (vertical). Where the quasi-elastic search found two patches, the load is split between
//! them in proportion to their weight shares (an approximation: the weights follow the gap,
//! not the elastic load sharing), the heaviest patch is reported, and the status says so.

use super::{Contact, EllipseMethod, PrincipalCurvatures, ellipse, relative_curvatures};
use crate::quasi_elastic::QuasiElasticSweep;
use crate::rigid::{RigidSweep, Stop};
use crate::sweep::{Mirror, Mirrored};
use crate::track::Side;

/// Which contact the ellipses are computed for (the scene's `[hertz] contact`): the stage
/// graph runs the quasi-elastic search for Hertz only where it is asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ContactSource {
    /// The heaviest quasi-elastic patch (paper Fig. 6).
    #[default]
    QuasiElastic,
    /// The rigid contact point.
    Rigid,
}

impl ContactSource {
    /// The scene's name for it (`[hertz] contact`).
    pub fn name(self) -> &'static str {
        match self {
            ContactSource::QuasiElastic => "quasi_elastic",
            ContactSource::Rigid => "rigid",
        }
    }
}

/// How the normal load follows from the vertical wheel load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NormalLoad {
    /// `P = Q / cos(gamma)`.
    #[default]
    Projected,
    /// `P = Q`.
    Vertical,
}

impl NormalLoad {
    /// The scene's name for it (`[hertz] normal_load`).
    pub fn name(self) -> &'static str {
        match self {
            NormalLoad::Projected => "projected",
            NormalLoad::Vertical => "vertical",
        }
    }
}

/// The contacts a Hertz sweep is computed for: each rigid contact, or the heaviest patch of
/// each quasi-elastic position (which carries the rigid sweep it was averaged around, so
/// that the two always belong together).
#[derive(Debug, Clone, Copy)]
pub enum Contacts<'a> {
    /// The rigid contact points.
    Rigid(&'a RigidSweep),
    /// The heaviest quasi-elastic patches (paper Fig. 6).
    QuasiElastic(&'a QuasiElasticSweep),
}

impl<'a> Contacts<'a> {
    /// The rigid sweep of the contacts.
    fn rigid(self) -> &'a RigidSweep {
        match self {
            Contacts::Rigid(rigid) => rigid,
            Contacts::QuasiElastic(qe) => qe.rigid(),
        }
    }

    /// Which contacts these are.
    pub fn source(self) -> ContactSource {
        match self {
            Contacts::Rigid(_) => ContactSource::Rigid,
            Contacts::QuasiElastic(_) => ContactSource::QuasiElastic,
        }
    }
}

/// HertzSettings of the sweep.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HertzSettings {
    /// Ellipse method.
    pub(crate) method: EllipseMethod,
    /// Normal-load rule.
    pub(crate) normal_load: NormalLoad,
}

impl HertzSettings {
    /// The ellipse `method` and the `normal_load` rule (any combination is valid).
    pub fn new(method: EllipseMethod, normal_load: NormalLoad) -> HertzSettings {
        HertzSettings {
            method,
            normal_load,
        }
    }

    /// The ellipse method.
    pub fn method(&self) -> EllipseMethod {
        self.method
    }

    /// The normal-load rule.
    pub fn normal_load(&self) -> NormalLoad {
        self.normal_load
    }
}

/// The Hertz results over a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct HertzSweep {
    source: ContactSource,
    positions: Vec<HertzPosition>,
}

impl HertzSweep {
    /// The contacts the ellipses were computed for.
    pub fn source(&self) -> ContactSource {
        self.source
    }

    /// One result per position of the sweep, in its order.
    pub fn positions(&self) -> &[HertzPosition] {
        &self.positions
    }
}

/// The Hertz result of one wheel at one position.
#[derive(Debug, Clone, PartialEq)]
pub struct SideHertz {
    /// Relative curvature in the rolling direction, 1/mm (NaN without contact).
    pub a_curvature: f64,
    /// Relative curvature in the lateral direction, 1/mm (NaN without contact).
    pub b_curvature: f64,
    /// Normal load on the reported patch, N (NaN without contact).
    pub normal_load_n: f64,
    /// The ellipse, or why there is none (`None`: no contact to compute).
    pub contact: Option<Contact>,
    /// `ok`, or why the row is incomplete or approximate.
    pub status: String,
}

impl SideHertz {
    /// The ellipse, where the contact is Hertzian.
    pub fn ellipse(&self) -> Option<&super::Ellipse> {
        self.contact.as_ref().and_then(|c| c.ellipse())
    }
}

/// The Hertz results at one position.
#[derive(Debug, Clone, PartialEq)]
pub struct HertzPosition {
    /// Lateral shift of the wheelset (mm).
    pub y_ws: f64,
    /// Left and right wheels.
    pub sides: [SideHertz; 2],
}

impl HertzPosition {
    /// The result of the wheel of `side`.
    pub fn side(&self, side: Side) -> &SideHertz {
        match side {
            Side::Left => &self.sides[0],
            Side::Right => &self.sides[1],
        }
    }
}

impl Mirrored for HertzPosition {
    /// The other wheel's result at the mirrored position: every Hertz quantity is the same
    /// in either side's frame.
    fn mirrored(&self, y_ws: f64) -> HertzPosition {
        let [left, right] = &self.sides;
        HertzPosition {
            y_ws,
            sides: [right.clone(), left.clone()],
        }
    }
}

/// Computes the ellipses of both wheels over a sweep, for `contacts`.
///
/// Where the contacts before the middle of the sweep are the mirror images of those after it
/// (a mirror-symmetric wheelset on a symmetric sweep), the ellipses from the middle on are
/// computed and the others are their mirror images: each ellipse is a function of its
/// wheel's contact alone.
///
/// # Units
/// `wheel_load_n` in N, `e_star_mpa` in MPa.
pub fn sweep(
    contacts: Contacts,
    wheel_load_n: f64,
    e_star_mpa: f64,
    settings: &HertzSettings,
) -> HertzSweep {
    let mirror = match contacts {
        Contacts::Rigid(rigid) => rigid.mirror(),
        Contacts::QuasiElastic(qe) => qe.mirror(),
    };
    let rigid = contacts.rigid().positions();
    let first = mirror.map_or(0, Mirror::middle);
    let solved: Vec<HertzPosition> = (first..rigid.len())
        .map(|i| {
            let side = |k: usize| {
                let input = contact_input(contacts, i, k);
                side_hertz(input, wheel_load_n, e_star_mpa, settings)
            };
            HertzPosition {
                y_ws: rigid[i].y_ws,
                sides: [side(0), side(1)],
            }
        })
        .collect();
    let positions = match mirror {
        Some(mirror) => mirror.complete(solved, |i| rigid[i].y_ws),
        None => solved,
    };
    HertzSweep {
        source: contacts.source(),
        positions,
    }
}

/// What one wheel's ellipse depends on: rolling radius, contact angle, lateral curvatures of
/// wheel and rail, the patch's weight share and the number of patches.
struct Input {
    r: f64,
    gamma: f64,
    wheel_curvature: f64,
    rail_curvature: f64,
    share: f64,
    patches: usize,
}

/// The input of wheel `k` at position `i`, or why there is no contact to compute.
fn contact_input(contacts: Contacts, i: usize, k: usize) -> Result<Input, String> {
    let p = &contacts.rigid().positions()[i];
    if p.stop != Stop::Converged {
        return Err(format!("rigid search: {}", p.stop.status_text()));
    }
    let contact = match contacts {
        Contacts::Rigid(_) => p.contact[k].map(|c| Input {
            r: c.r,
            gamma: c.gamma,
            wheel_curvature: c.wheel_curvature,
            rail_curvature: c.rail_curvature,
            share: 1.0,
            patches: 1,
        }),
        Contacts::QuasiElastic(qe) => {
            let side = &qe.positions()[i].sides[k];
            side.main().map(|m| Input {
                r: m.r,
                gamma: m.gamma,
                wheel_curvature: m.wheel_curvature,
                rail_curvature: m.rail_curvature,
                share: m.weight_share,
                patches: side.patches.len(),
            })
        }
    };
    contact.ok_or_else(|| "no contact".into())
}

/// The Hertz result of one wheel from its contact `input`.
fn side_hertz(
    input: Result<Input, String>,
    wheel_load_n: f64,
    e_star_mpa: f64,
    settings: &HertzSettings,
) -> SideHertz {
    let c = match input {
        Ok(c) => c,
        Err(status) => return missing(status),
    };
    let (a, b) = relative_curvatures(
        &PrincipalCurvatures {
            wheel_rolling: c.gamma.cos() / c.r,
            wheel_lateral: c.wheel_curvature,
            rail_rolling: 0.0,
            rail_lateral: c.rail_curvature,
        },
        0.0,
    );
    let vertical = wheel_load_n * c.share;
    let load = match settings.normal_load {
        NormalLoad::Projected => vertical / c.gamma.cos(),
        NormalLoad::Vertical => vertical,
    };
    let (contact, mut status) = match ellipse(a, b, load, e_star_mpa, settings.method) {
        Ok(e @ Contact::Hertzian(ellipse)) => {
            let status = match ellipse.stop {
                super::Stop::Converged => "ok".to_string(),
                other => format!("ellipse: {other}"),
            };
            (Some(e), status)
        }
        Ok(e @ Contact::NotHertzian(reason)) => (Some(e), reason.to_string()),
        Err(e) => (None, format!("error: {e}")),
    };
    if c.patches > 1 {
        status.push_str(&format!(
            "; {} patches, load split by weight (reported patch {:.0} %)",
            c.patches,
            100.0 * c.share
        ));
    }
    SideHertz {
        a_curvature: a,
        b_curvature: b,
        normal_load_n: load,
        contact,
        status,
    }
}

fn missing(status: String) -> SideHertz {
    SideHertz {
        a_curvature: f64::NAN,
        b_curvature: f64::NAN,
        normal_load_n: f64::NAN,
        contact: None,
        status,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On the paper scene (a mirror-symmetric wheelset, its sweep mirrored about the
    /// middle) the ellipses before the middle are taken from their mirror images, and each
    /// is what computing it from its own contact gives, for both contact sources.
    #[test]
    fn mirrored_wheels_take_their_images_ellipses() {
        let scene = crate::scene::Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
        let e_star = super::super::effective_modulus(scene.wheel_material(), scene.rail_material());
        let placement = crate::pipeline::place(&scene).unwrap();
        let rigid = crate::rigid::search(&placement, scene.sweep(), Default::default());
        let qe = crate::quasi_elastic::search(&placement, rigid.clone(), scene.quasi_elastic());
        assert!(rigid.mirror().is_some() && qe.mirror().is_some());
        let settings = HertzSettings::default();
        for contacts in [Contacts::QuasiElastic(&qe), Contacts::Rigid(&rigid)] {
            let swept = sweep(contacts, 70e3, e_star, &settings);
            for (i, p) in swept.positions().iter().enumerate() {
                for (k, side) in p.sides.iter().enumerate() {
                    let input = contact_input(contacts, i, k);
                    let computed = side_hertz(input, 70e3, e_star, &settings);
                    let source = contacts.source();
                    assert_eq!(
                        format!("{side:?}"),
                        format!("{computed:?}"),
                        "{source:?} {i}"
                    );
                }
            }
        }
    }
}
