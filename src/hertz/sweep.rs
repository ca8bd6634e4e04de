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

use super::{Contact, Method, PrincipalCurvatures, ellipse, relative_curvatures};
use crate::quasi_elastic::QuasiElasticSweep;
use crate::rigid::{RigidSweep, Stop};

/// Which contact the ellipses are computed for.
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

/// Settings of the sweep.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Settings {
    /// Ellipse method.
    pub method: Method,
    /// Contact the ellipses are computed for.
    pub source: ContactSource,
    /// Normal-load rule.
    pub normal_load: NormalLoad,
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
pub struct Position {
    /// Lateral shift of the wheelset (mm).
    pub y_ws: f64,
    /// Left and right wheels.
    pub sides: [SideHertz; 2],
}

/// Computes the ellipses of both wheels over a sweep. `quasi_elastic` must be given when
/// `settings.source` is [`ContactSource::QuasiElastic`].
///
/// # Units
/// `wheel_load_n` in N, `e_star_mpa` in MPa.
pub fn sweep(
    rigid: &RigidSweep,
    quasi_elastic: Option<&QuasiElasticSweep>,
    wheel_load_n: f64,
    e_star_mpa: f64,
    settings: &Settings,
) -> Vec<Position> {
    sweep_reusing(
        rigid,
        quasi_elastic,
        wheel_load_n,
        e_star_mpa,
        settings,
        true,
    )
    .0
}

/// What one wheel's ellipse depends on, as bits: rolling radius, contact angle, lateral
/// curvatures of wheel and rail, the patch's weight share and the number of patches; or
/// why there is no contact.
type Input = Result<([u64; 5], usize), String>;

/// [`sweep`], where a wheel whose input is bit for bit the other wheel's at the mirrored
/// position (the positions before and after the middle of a mirror-symmetric wheelset's
/// sweep) takes that wheel's result when `reuse`: the ellipse is a function of its input.
/// Also returns how many results were taken.
fn sweep_reusing(
    rigid: &RigidSweep,
    quasi_elastic: Option<&QuasiElasticSweep>,
    wheel_load_n: f64,
    e_star_mpa: f64,
    settings: &Settings,
    reuse: bool,
) -> (Vec<Position>, usize) {
    let input = |i: usize, k: usize| -> Input {
        let p = &rigid.positions[i];
        if p.stop != Stop::Converged {
            return Err(format!("rigid search: {}", p.stop.status_text()));
        }
        let contact = match settings.source {
            ContactSource::Rigid => {
                p.contact[k].map(|c| ([c.r, c.gamma, c.wheel_curvature, c.rail_curvature, 1.0], 1))
            }
            ContactSource::QuasiElastic => quasi_elastic.and_then(|q| {
                let side = &q.positions[i].sides[k];
                side.main().map(|m| {
                    let values = [
                        m.r,
                        m.gamma,
                        m.wheel_curvature,
                        m.rail_curvature,
                        m.weight_share,
                    ];
                    (values, side.patches.len())
                })
            }),
        };
        contact
            .map(|(v, patches)| (v.map(f64::to_bits), patches))
            .ok_or_else(|| "no contact".into())
    };
    let solve = |input: &Input| -> SideHertz {
        let (bits, patches) = match input {
            Ok(v) => *v,
            Err(status) => return missing(status.clone()),
        };
        let [r, gamma, kw, kr, share] = bits.map(f64::from_bits);
        let (a, b) = relative_curvatures(
            &PrincipalCurvatures {
                wheel_rolling: gamma.cos() / r,
                wheel_lateral: kw,
                rail_rolling: 0.0,
                rail_lateral: kr,
            },
            0.0,
        );
        let vertical = wheel_load_n * share;
        let load = match settings.normal_load {
            NormalLoad::Projected => vertical / gamma.cos(),
            NormalLoad::Vertical => vertical,
        };
        let (contact, mut status) = match ellipse(a, b, load, e_star_mpa, settings.method) {
            Ok(c @ Contact::Hertzian(e)) => {
                let status = match e.stop {
                    super::Stop::Converged => "ok".to_string(),
                    other => format!("ellipse: {other}"),
                };
                (Some(c), status)
            }
            Ok(c @ Contact::NotHertzian(reason)) => (Some(c), reason.to_string()),
            Err(e) => (None, format!("error: {e}")),
        };
        if patches > 1 {
            status.push_str(&format!(
                "; {patches} patches, load split by weight (reported patch {:.0} %)",
                100.0 * share
            ));
        }
        SideHertz {
            a_curvature: a,
            b_curvature: b,
            normal_load_n: load,
            contact,
            status,
        }
    };
    let n = rigid.positions.len();
    let inputs: Vec<[Input; 2]> = (0..n).map(|i| [0, 1].map(|k| input(i, k))).collect();
    // From the middle on first, so that the positions before it can take their mirror
    // images' results.
    let mut sides: Vec<Option<[SideHertz; 2]>> = vec![None; n];
    let mut taken = 0;
    for i in (n / 2..n).chain(0..n / 2) {
        let j = n - 1 - i;
        sides[i] = Some([0, 1].map(|k| {
            if reuse
                && i < n / 2
                && inputs[i][k] == inputs[j][1 - k]
                && let Some(mirror) = &sides[j]
            {
                taken += 1;
                return mirror[1 - k].clone();
            }
            solve(&inputs[i][k])
        }));
    }
    let positions = rigid
        .positions
        .iter()
        .zip(sides)
        .map(|(p, sides)| Position {
            y_ws: p.y_ws,
            sides: sides.expect("every position solved"),
        })
        .collect();
    (positions, taken)
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
    /// middle), every wheel before the middle takes its mirror image's ellipse, and the
    /// sweep is what computing every ellipse gives, for both contact sources.
    #[test]
    fn mirrored_wheels_take_their_images_ellipses() {
        let scene = crate::scene::Scene::from_toml("", "test", std::path::Path::new(".")).unwrap();
        let placement = crate::pipeline::place(&scene).unwrap();
        let rigid = crate::rigid::search(&placement, scene.sweep(), Default::default());
        let qe = crate::quasi_elastic::search(&placement, &rigid, scene.quasi_elastic());
        let e_star = super::super::effective_modulus(scene.wheel_material(), scene.rail_material());
        for source in [ContactSource::QuasiElastic, ContactSource::Rigid] {
            let settings = Settings {
                source,
                ..Settings::default()
            };
            let run = |reuse| sweep_reusing(&rigid, Some(&qe), 70e3, e_star, &settings, reuse);
            let ((reusing, taken), (computing, none)) = (run(true), run(false));
            // Both wheels of the 150 positions before the middle.
            assert_eq!((taken, none), (300, 0), "{source:?}");
            assert_eq!(format!("{reusing:?}"), format!("{computing:?}"));
        }
    }
}
