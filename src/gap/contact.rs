//! The contact point both searches report, in the track frame.

/// A contact point of one wheel on its rail, in the track frame: the rigid contact
/// ([`crate::rigid::SideContact::point`]) or a quasi-elastic patch's weighted average
/// ([`crate::quasi_elastic::Patch::point`]). The contact columns of `rigid.csv` and
/// `quasi_elastic.csv` are written from it.
///
/// # Units and frames
///
/// Millimetres and radians; `y`, `z` and `gamma` in the track frame (y positive to the left,
/// z up, `gamma` mirrored per side and roll included, positive on tread and flange);
/// `s` the wheel profile coordinate; curvatures convex positive (1/mm).
///
/// # Example
/// ```
/// use wheelrail::{pipeline, quasi_elastic, rigid, scene::Scene};
/// let scene = Scene::from_toml("", "inline", std::path::Path::new(".")).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// let rigid = rigid::search(&placement, &wheelrail::sweep::Sweep::from_slice(&[2.0]).unwrap(), rigid::Solver::default());
/// let qe = quasi_elastic::search(&placement, rigid.clone(), &quasi_elastic::QuasiElasticSettings::default());
/// let a = rigid.positions()[0].contact[0].unwrap().point();
/// let b = qe.positions()[0].sides[0].main().unwrap().point();
/// // The averaged contact lies on the tread near the rigid one (left wheel, y > 0).
/// assert!(a.y > 700.0 && (a.s - b.s).abs() < 3.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPoint {
    /// Wheel profile coordinate of the contact point (mm).
    pub s: f64,
    /// Track-frame lateral position of the contact point (mm).
    pub y: f64,
    /// Track-frame height of the contact point (mm).
    pub z: f64,
    /// Rolling radius (mm).
    pub r: f64,
    /// Contact angle in the track frame, mirrored per side, roll included (rad).
    pub gamma: f64,
    /// Tangent of the rail's contact angle at the point (side frame, inclination included).
    pub rail_tan_gamma: f64,
    /// Lateral curvature of the wheel at the point, convex positive (1/mm).
    pub wheel_curvature: f64,
    /// Lateral curvature of the rail at the point, convex positive (1/mm).
    pub rail_curvature: f64,
    /// Longitudinal position along the track (mm, x forward) relative to the wheelset
    /// centre: 0 without yaw.
    pub x: f64,
    /// Distance ahead of the axle along the wheelset's own forward axis (mm): 0 without
    /// yaw.
    pub lead: f64,
}

impl ContactPoint {
    /// Every field as NaN: the row of a missing contact.
    pub const NAN: ContactPoint = ContactPoint {
        s: f64::NAN,
        y: f64::NAN,
        z: f64::NAN,
        r: f64::NAN,
        gamma: f64::NAN,
        rail_tan_gamma: f64::NAN,
        wheel_curvature: f64::NAN,
        rail_curvature: f64::NAN,
        x: f64::NAN,
        lead: f64::NAN,
    };
}
