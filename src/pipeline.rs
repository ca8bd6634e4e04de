//! The stage graph: which stage results each output needs, and a run that computes exactly
//! those.
//!
//! ```text
//! Profiles ──> Rigid ──> QuasiElastic ──> Hertz
//! ```
//!
//! Every figure declares the one stage whose result it draws ([`Figure::stage`]); the run
//! computes that stage and its predecessors, nothing else, and records what it ran in a
//! [`RunRecord`] (printed by `wheelrail report --timings`).

use crate::profile::ProfileKind;
use crate::scene::Scene;
use crate::track::{PlacedRail, PlacedWheel, Placement, SidePair};
use std::time::Instant;

/// A stage of the pipeline, in the order they depend on each other.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Stage {
    /// Profiles loaded, slopes and curvatures, wheels and rails placed.
    Profiles,
}

impl Stage {
    /// The stage's name as printed in run records.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Profiles => "profiles",
        }
    }
}

/// A figure a scene can ask for in `[outputs] figures`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Figure {
    /// Wheel and rail profiles in their placed positions (paper Fig. 1, left).
    Profiles,
    /// tan(gamma) of wheel and rail against the lateral coordinate (paper Fig. 1, right).
    Conicity,
    /// Lateral curvature of wheel and rail against the lateral coordinate.
    Curvature,
}

impl Figure {
    /// Every figure, in report order.
    pub const ALL: [Figure; 3] = [Figure::Profiles, Figure::Conicity, Figure::Curvature];

    /// The name used in scene files and as the file stem.
    pub fn name(self) -> &'static str {
        match self {
            Figure::Profiles => "profiles",
            Figure::Conicity => "conicity",
            Figure::Curvature => "curvature",
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
        }
    }
}

/// What a run computed, with wall-clock times, for `--timings` and for tests that check that
/// no unneeded stage ran.
#[derive(Debug, Clone, Default)]
pub struct RunRecord {
    /// The stages run, in order, with their duration in seconds.
    pub stages: Vec<(Stage, f64)>,
}

impl RunRecord {
    /// Whether `stage` ran.
    pub fn ran(&self, stage: Stage) -> bool {
        self.stages.iter().any(|(s, _)| *s == stage)
    }

    fn time<T>(&mut self, stage: Stage, f: impl FnOnce() -> T) -> T {
        let start = Instant::now();
        let out = f();
        self.stages.push((stage, start.elapsed().as_secs_f64()));
        out
    }
}

/// The results of the stages a scene needed.
#[derive(Debug, Clone)]
pub struct Results {
    /// Profiles placed on the track (always computed).
    pub placement: Placement,
    /// What ran, and how long it took.
    pub record: RunRecord,
}

/// The last stage any of the scene's outputs needs.
pub fn last_stage(scene: &Scene) -> Stage {
    scene
        .figures
        .iter()
        .map(|f| f.stage())
        .max()
        .unwrap_or(Stage::Profiles)
}

/// Runs the stages `scene`'s outputs need.
///
/// # Errors
/// [`crate::Error`] when a profile cannot be read or placed.
pub fn run(scene: &Scene) -> Result<Results, crate::Error> {
    let mut record = RunRecord::default();
    let placement = record.time(Stage::Profiles, || place(scene))?;
    Ok(Results { placement, record })
}

/// Loads the scene's four profiles and places them.
///
/// # Errors
/// [`crate::Error::Scene`] naming the profile key.
pub fn place(scene: &Scene) -> Result<Placement, crate::Error> {
    const WHEEL_KEYS: [&str; 2] = ["wheel.left_profile", "wheel.right_profile"];
    const RAIL_KEYS: [&str; 2] = ["rail.left_profile", "rail.right_profile"];
    let mut pairs = Vec::with_capacity(2);
    for i in 0..2 {
        let wheel =
            scene.load_profile(&scene.wheel_profiles[i], ProfileKind::Wheel, WHEEL_KEYS[i])?;
        let rail = scene.load_profile(&scene.rail_profiles[i], ProfileKind::Rail, RAIL_KEYS[i])?;
        let placement_error = |key: &'static str, e: crate::track::PlacementError| {
            crate::scene::SceneError::Profile {
                path: scene.path.clone(),
                key,
                message: e.to_string(),
            }
        };
        let wheel = PlacedWheel::place(wheel, scene.nominal_radius_mm[i], &scene.layout)
            .map_err(|e| placement_error(WHEEL_KEYS[i], e))?;
        let rail = PlacedRail::place(rail, scene.rail_profile_inclination, &scene.layout)
            .map_err(|e| placement_error(RAIL_KEYS[i], e))?;
        pairs.push(SidePair { wheel, rail });
    }
    let right = pairs.pop().expect("two sides were pushed");
    let left = pairs.pop().expect("two sides were pushed");
    Ok(Placement {
        layout: scene.layout.clone(),
        left,
        right,
    })
}
