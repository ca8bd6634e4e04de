//! The stages of a run and the figures that draw their results: the vocabulary shared by
//! the scene file (`[outputs] figures`) and the pipeline, which owns neither.

/// A stage of the pipeline.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Stage {
    /// Profiles loaded, slopes and curvatures, wheels and rails placed.
    Profiles,
    /// Rigid contact search over the sweep.
    Rigid,
    /// Quasi-elastic contact search over the sweep.
    QuasiElastic,
    /// Quasi-elastic search repeated for the scene's sensitivity values of eps.
    EpsilonSensitivity,
    /// Hertz ellipses over the sweep.
    Hertz,
    /// Equivalent conicity (EN 15302) and the pair's parameters, from the rigid Δr.
    EquivalentConicity,
    /// Accuracy of the paper's Hertz numerics against the exact method (scene-independent).
    HertzAccuracy,
    /// Creep forces of every patch over the sweep (`[creep]`).
    Creep,
    /// The contact table on a grid of shift × yaw (`[table]`): a rigid and a Hertz sweep
    /// per yaw, computed on the placement.
    ContactTable,
}

impl Stage {
    /// Every stage, in an order that respects the dependencies.
    pub const ALL: [Stage; 9] = [
        Stage::Profiles,
        Stage::Rigid,
        Stage::QuasiElastic,
        Stage::EpsilonSensitivity,
        Stage::Hertz,
        Stage::EquivalentConicity,
        Stage::HertzAccuracy,
        Stage::Creep,
        Stage::ContactTable,
    ];

    /// The stage's name as printed in run records.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Profiles => "profiles",
            Stage::Rigid => "rigid",
            Stage::QuasiElastic => "quasi_elastic",
            Stage::EpsilonSensitivity => "epsilon_sensitivity",
            Stage::Hertz => "hertz",
            Stage::EquivalentConicity => "equivalent_conicity",
            Stage::HertzAccuracy => "hertz_accuracy",
            Stage::Creep => "creep",
            Stage::ContactTable => "contact_table",
        }
    }

    /// The stage of a [`name`](Stage::name).
    ///
    /// ```
    /// use wheelrail::pipeline::Stage;
    /// assert!(Stage::ALL.iter().all(|&s| Stage::from_name(s.name()) == Some(s)));
    /// assert_eq!(Stage::from_name("rigid_search"), None);
    /// ```
    pub fn from_name(name: &str) -> Option<Stage> {
        Stage::ALL.into_iter().find(|s| s.name() == name)
    }

    /// The stages whose results this stage uses directly.
    pub fn requires(self) -> &'static [Stage] {
        match self {
            Stage::Profiles | Stage::HertzAccuracy => &[],
            Stage::Rigid | Stage::ContactTable => &[Stage::Profiles],
            Stage::QuasiElastic | Stage::EpsilonSensitivity | Stage::EquivalentConicity => {
                &[Stage::Rigid]
            }
            // Hertz may use the rigid contact only; the closure below adds QuasiElastic when
            // the scene says so (see `needed_stages`).
            Stage::Hertz => &[Stage::Rigid],
            // Creep too, with QuasiElastic added for `[creep] contact = "quasi_elastic"`.
            Stage::Creep => &[Stage::Rigid],
        }
    }
}

/// A figure a scene can ask for in `[outputs] figures`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Figure {
    /// Wheel and rail profiles in their placed positions (paper Fig. 1).
    Profiles,
    /// tan(gamma) of wheel and rail against the lateral coordinate (paper Fig. 1).
    Conicity,
    /// Lateral curvature of wheel and rail against the lateral coordinate.
    Curvature,
    /// Rigid contact points on wheel and rail against the shift (paper Fig. 2).
    ContactPoints,
    /// Rolling radius difference against the shift (paper Fig. 2).
    RollingRadius,
    /// Contact angles against the shift (paper Fig. 2).
    ContactAngles,
    /// Lead of each wheel's contact ahead of the axle against the shift (yaw).
    ContactLead,
    /// Roll angle against the shift (paper Fig. 2).
    Roll,
    /// Wickens' contact angle parameter against the shift (paper Fig. 2).
    ContactAngleParameter,
    /// Profiles with the rigid contact points of the whole sweep.
    ContactMap,
    /// Rigid against quasi-elastic contact points (paper Fig. 4).
    QuasiElasticPoints,
    /// Contact map with rigid and quasi-elastic points (paper Fig. 5).
    QuasiElasticMap,
    /// Quasi-elastic contact position for several eps.
    EpsilonSensitivity,
    /// Semi-axes of the contact ellipses (paper Fig. 6).
    SemiAxes,
    /// Maximum contact pressure.
    Pressure,
    /// Accuracy of the paper's Hertz numerics.
    HertzAccuracy,
    /// Equivalent conicity against the amplitude, both methods (EN 15302).
    EquivalentConicity,
    /// Δr with the linear function of the equivalent cone at 3 mm.
    DeltaRLinearised,
    /// Longitudinal and lateral creep forces of each wheel against the shift.
    CreepForces,
    /// Force against creepage on one patch: the three tangential models.
    CreepCurve,
}

impl Figure {
    /// Every figure, in report order.
    pub const ALL: [Figure; 20] = [
        Figure::Profiles,
        Figure::Conicity,
        Figure::Curvature,
        Figure::ContactPoints,
        Figure::RollingRadius,
        Figure::EquivalentConicity,
        Figure::DeltaRLinearised,
        Figure::ContactAngles,
        Figure::ContactLead,
        Figure::Roll,
        Figure::ContactAngleParameter,
        Figure::ContactMap,
        Figure::QuasiElasticPoints,
        Figure::QuasiElasticMap,
        Figure::EpsilonSensitivity,
        Figure::SemiAxes,
        Figure::Pressure,
        Figure::HertzAccuracy,
        Figure::CreepForces,
        Figure::CreepCurve,
    ];

    /// The name used in scene files and as the file stem.
    pub fn name(self) -> &'static str {
        match self {
            Figure::Profiles => "profiles",
            Figure::Conicity => "conicity",
            Figure::Curvature => "curvature",
            Figure::ContactPoints => "contact_points",
            Figure::RollingRadius => "rolling_radius",
            Figure::ContactAngles => "contact_angles",
            Figure::ContactLead => "contact_lead",
            Figure::Roll => "roll",
            Figure::ContactAngleParameter => "contact_angle_parameter",
            Figure::ContactMap => "contact_map",
            Figure::QuasiElasticPoints => "qe_contact_points",
            Figure::QuasiElasticMap => "qe_contact_map",
            Figure::EpsilonSensitivity => "qe_epsilon",
            Figure::SemiAxes => "semi_axes",
            Figure::Pressure => "pressure",
            Figure::HertzAccuracy => "hertz_accuracy",
            Figure::EquivalentConicity => "equivalent_conicity",
            Figure::DeltaRLinearised => "delta_r_linearised",
            Figure::CreepForces => "creep_forces",
            Figure::CreepCurve => "creep_curve",
        }
    }

    /// The figure of a scene-file name.
    pub fn from_name(name: &str) -> Option<Figure> {
        Figure::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The stage whose result the figure draws.
    pub fn stage(self) -> Stage {
        match self {
            Figure::Profiles | Figure::Conicity | Figure::Curvature => Stage::Profiles,
            Figure::ContactPoints
            | Figure::RollingRadius
            | Figure::ContactAngles
            | Figure::ContactLead
            | Figure::Roll
            | Figure::ContactAngleParameter
            | Figure::ContactMap => Stage::Rigid,
            Figure::QuasiElasticPoints | Figure::QuasiElasticMap => Stage::QuasiElastic,
            Figure::EpsilonSensitivity => Stage::EpsilonSensitivity,
            Figure::SemiAxes | Figure::Pressure => Stage::Hertz,
            Figure::HertzAccuracy => Stage::HertzAccuracy,
            Figure::EquivalentConicity | Figure::DeltaRLinearised => Stage::EquivalentConicity,
            Figure::CreepForces | Figure::CreepCurve => Stage::Creep,
        }
    }
}
