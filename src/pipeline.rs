//! The stage graph: which stage results each output needs, and a run that computes exactly
//! those.
//!
//! ```text
//! Profiles ──> Rigid ──> QuasiElastic ──> Hertz
//!                    ├─> EpsilonSensitivity
//!                    └─> EquivalentConicity
//!                    └─> Creep (QuasiElastic first when `[creep] contact` is quasi-elastic)
//! HertzAccuracy (no inputs: the paper's Hertz numerics against the exact ones)
//! Profiles ──> ContactTable (a rigid and a Hertz sweep per yaw of `[table]`)
//! ```
//!
//! Every figure declares the one stage whose result it draws (`Figure::stage`); the run
//! computes that stage and the stages it depends on ([`Stage::requires`]), nothing else, and
//! records what it ran in a `RunRecord` (printed by `wheelrail report --timings`).

use crate::cache::{PlacementCache, ProfileKey, RailKey};
use crate::conicity;
use crate::hertz;
use crate::maintenance::{self, NominalRails, WearError};
use crate::profile::{Profile, ProfileKind};
use crate::quasi_elastic::{self, QuasiElasticSweep};
use crate::rigid::{self, RigidSweep};
use crate::scene::{ProfileRef, Scene, SceneError};
use crate::track::{PlacedRail, PlacedWheel, Placement, PlacementError, Side, SidePair};
use std::sync::Arc;
use std::time::Instant;

pub use crate::stage::Figure;
pub use crate::stage::Stage;

/// What a run computed, with wall-clock times, for `--timings` and for tests that check that
/// no unneeded stage ran.
#[derive(Debug, Clone, Default)]
pub struct RunRecord {
    /// The stages run, in order, with their duration in seconds.
    pub stages: Vec<(Stage, f64)>,
}

/// A stage starting (`None`) or done after so many seconds, as a run reports it to its
/// caller's progress callback.
pub type Progress<'a> = &'a mut dyn FnMut(Stage, Option<f64>);

impl RunRecord {
    /// Whether `stage` ran.
    pub fn ran(&self, stage: Stage) -> bool {
        self.stages.iter().any(|(s, _)| *s == stage)
    }

    /// Runs `f` as `stage`, timed, telling `progress` when it starts and ends.
    fn time<T>(&mut self, stage: Stage, progress: Progress, f: impl FnOnce() -> T) -> T {
        progress(stage, None);
        let start = Instant::now();
        let out = f();
        let seconds = start.elapsed().as_secs_f64();
        progress(stage, Some(seconds));
        self.stages.push((stage, seconds));
        out
    }
}

/// The quasi-elastic solution for each sensitivity value of eps.
#[derive(Debug, Clone)]
pub struct EpsilonSweeps {
    /// `(eps in mm, solution)`, in the scene's order.
    pub runs: Vec<(f64, QuasiElasticSweep)>,
}

/// The results of the stages a scene needed; a stage that was not needed is `None`.
#[derive(Debug, Clone)]
pub struct Results {
    /// Profiles placed on the track (always computed).
    pub placement: Placement,
    /// The wheels' flange dimensions against their limits, and the rails' wear when the
    /// scene names nominal rails (always computed, with the profiles).
    pub maintenance: maintenance::Assessment,
    /// Rigid contact over the sweep (shared with the quasi-elastic results computed on it).
    pub rigid: Option<Arc<RigidSweep>>,
    /// Quasi-elastic contact over the sweep.
    pub quasi_elastic: Option<QuasiElasticSweep>,
    /// Quasi-elastic contact for the sensitivity values of eps.
    pub epsilon: Option<EpsilonSweeps>,
    /// Hertz ellipses over the sweep.
    pub hertz: Option<hertz::HertzSweep>,
    /// Equivalent conicity and the pair's parameters.
    pub conicity: Option<conicity::PairConicity>,
    /// Accuracy of the paper's Hertz numerics.
    pub hertz_accuracy: Option<hertz::accuracy::HertzAccuracy>,
    /// Creep forces over the sweep (or why the stage could not run).
    pub creep: Option<Result<crate::creep::sweep::CreepSweep, crate::creep::CreepError>>,
    /// The contact table.
    pub contact_table: Option<crate::contact_table::ContactTable>,
    /// What ran, and how long it took.
    pub record: RunRecord,
}

/// The stages `scene`'s outputs need, closed under dependencies, in run order: those of
/// its figures, the creep stage for a scene with `[creep]` (`creep.csv`), the contact table
/// for one with `[table]`. The profile stage always runs (placement is validated for every
/// scene).
pub fn needed_stages(scene: &Scene) -> Vec<Stage> {
    let mut wanted: Vec<Stage> = scene.figures.iter().map(|f| f.stage()).collect();
    if scene.asks_for_creep {
        wanted.push(Stage::Creep);
    }
    if scene.contact_table.is_some() {
        wanted.push(Stage::ContactTable);
    }
    closed_stages(scene, &wanted)
}

/// `wanted` and the stages they depend on ([`Stage::requires`]; Hertz also needs the
/// quasi-elastic stage when the scene's Hertz contact is quasi-elastic), with
/// [`Stage::Profiles`], in run order.
pub(crate) fn closed_stages(scene: &Scene, wanted: &[Stage]) -> Vec<Stage> {
    let mut wanted: Vec<Stage> = wanted.to_vec();
    wanted.push(Stage::Profiles);
    let mut closed = std::collections::BTreeSet::new();
    while let Some(s) = wanted.pop() {
        if closed.insert(s) {
            wanted.extend_from_slice(s.requires());
            let quasi_elastic = match s {
                Stage::Hertz => scene.hertz_contact,
                Stage::Creep => scene.creep().contact,
                _ => hertz::ContactSource::Rigid,
            };
            if quasi_elastic == hertz::ContactSource::QuasiElastic {
                wanted.push(Stage::QuasiElastic);
            }
        }
    }
    Stage::ALL
        .into_iter()
        .filter(|s| closed.contains(s))
        .collect()
}

/// Places the scene's profiles and runs the stages its outputs need (and only those: see
/// `needed_stages`).
///
/// # Errors
/// [`SceneError`] when a profile cannot be read or placed (naming its key).
///
/// # Example
/// ```
/// use wheelrail::{pipeline, scene::Scene};
/// let scene = Scene::from_toml(
///     "[sweep]\nfrom_mm = 0.0\nto_mm = 1.0\nstep_mm = 0.5\n[outputs]\nfigures = [\"semi_axes\"]",
///     "doc",
///     ".".as_ref(),
/// )
/// .unwrap();
/// let results = pipeline::run(&scene).unwrap();
/// let hertz = results.hertz.unwrap(); // semi_axes draws the Hertz stage
/// assert_eq!(hertz.positions().len(), 3);
/// assert!(results.conicity.is_none()); // not needed by the figures
/// ```
pub fn run(scene: &Scene) -> Result<Results, SceneError> {
    run_gated(scene, None, |_| Ok::<_, SceneError>(false), &mut |_, _| {})
}

/// [`run`], placing the profiles through `cache` when given (the scenes of one run that
/// share profiles), with `gate` called on the placement (the first stage, which every run
/// does) before any other stage: it may refuse the run (a work budget that needs the
/// profiles), or return whether to tell `progress` of each stage's start and end (a long
/// run's progress).
pub fn run_gated<E: From<SceneError>>(
    scene: &Scene,
    cache: Option<&PlacementCache>,
    gate: impl FnOnce(&Placement) -> Result<bool, E>,
    progress: Progress,
) -> Result<Results, E> {
    let mut record = RunRecord::default();
    let (placement, nominal) = record.time(Stage::Profiles, &mut |_, _| {}, || {
        let placement = match cache {
            Some(cache) => place_cached(scene, cache),
            None => place(scene),
        }?;
        Ok::<_, SceneError>((placement, nominal_rails(scene)?))
    })?;
    let mut quiet = |_, _| {};
    let progress: Progress = if gate(&placement)? {
        progress
    } else {
        &mut quiet
    };
    Ok(run_recorded(
        scene,
        placement,
        Ok(nominal),
        &needed_stages(scene),
        record,
        progress,
    ))
}

/// The scene's nominal rails (`rail.nominal_profile`, or a fleet's template rails) read,
/// with the inclination in their data; `None` when the scene names none.
///
/// # Errors
/// [`SceneError`] naming `rail.nominal_profile` when a nominal rail cannot be read.
pub(crate) fn nominal_rails(scene: &Scene) -> Result<Option<NominalRails>, SceneError> {
    let Some(refs) = &scene.nominal_rails else {
        return Ok(None);
    };
    let load = |r: &ProfileRef| scene.load_profile(r, ProfileKind::Rail, "rail.nominal_profile");
    let left = load(&refs[0])?;
    let right = if refs[1] == refs[0] {
        left.clone()
    } else {
        load(&refs[1])?
    };
    Ok(Some(NominalRails {
        profiles: [left, right],
        profile_inclination: scene.rail_profile_inclination,
    }))
}

/// Runs `stages` (and the stages they depend on, see `closed_stages`) of `scene` on a
/// placement made by the caller: a study that samples the scene's profiles, or a fleet that
/// places its shared rail once. Every other input (sweep, solver, quasi-elastic and Hertz
/// settings, load, materials) is the scene's, so a caller overrides a setting by changing
/// it in a copy of the scene. The same code computes [`run`]'s stages: results agree to the
/// last digit with a report of the same scene and placement.
///
/// ```
/// use wheelrail::pipeline::{self, Stage};
/// use wheelrail::scene::Scene;
/// let scene = Scene::from_toml("[sweep]\nfrom_mm = 0.0\nto_mm = 2.0\nstep_mm = 1.0", "doc", ".".as_ref()).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// let results = pipeline::run_on(&scene, placement, &[Stage::Rigid]);
/// assert_eq!(results.rigid.unwrap().positions().len(), 3);
/// assert!(results.quasi_elastic.is_none());
/// ```
pub fn run_on(scene: &Scene, placement: Placement, stages: &[Stage]) -> Results {
    let stages = closed_stages(scene, stages);
    run_recorded(
        scene,
        placement,
        nominal_rails(scene).map_err(|e| e.to_string()),
        &stages,
        RunRecord::default(),
        &mut |_, _| {},
    )
}

/// The flange dimensions of `placement`'s wheels against the scene's limits, and its rails'
/// wear against the `nominal` rails (or why those could not be read).
fn maintenance_of(
    scene: &Scene,
    placement: &Placement,
    nominal: Result<Option<NominalRails>, String>,
) -> maintenance::Assessment {
    match nominal {
        Ok(nominal) => maintenance::assess(placement, &scene.limits, nominal.as_ref()),
        Err(message) => {
            let unreadable = || {
                Err(WearError::NominalUnreadable {
                    message: message.clone(),
                })
            };
            maintenance::Assessment {
                rails: Some([unreadable(), unreadable()]),
                ..maintenance::assess(placement, &scene.limits, None)
            }
        }
    }
}

/// Runs `stages` (closed under dependencies, in run order) on `placement`, with the
/// scene's nominal rails read (or the message of why they could not be).
fn run_recorded(
    scene: &Scene,
    placement: Placement,
    nominal: Result<Option<NominalRails>, String>,
    stages: &[Stage],
    record: RunRecord,
    progress: Progress,
) -> Results {
    let maintenance = maintenance_of(scene, &placement, nominal);
    let mut results = Results {
        placement,
        maintenance,
        rigid: None,
        quasi_elastic: None,
        epsilon: None,
        hertz: None,
        conicity: None,
        hertz_accuracy: None,
        creep: None,
        contact_table: None,
        record,
    };
    for &stage in stages {
        run_stage(scene, stage, &mut results, progress);
    }
    results
}

/// Runs `stage` of `scene` into `results`, which hold the stages it requires, timed in
/// their record.
fn run_stage(scene: &Scene, stage: Stage, results: &mut Results, progress: Progress) {
    let record = &mut results.record;
    match stage {
        Stage::Profiles => {}
        Stage::Rigid => {
            let r = record.time(stage, progress, || {
                rigid::search(&results.placement, &scene.sweep, scene.rigid_solver)
            });
            results.rigid = Some(Arc::new(r));
        }
        Stage::QuasiElastic => {
            let rigid = results
                .rigid
                .as_ref()
                .expect("rigid runs before quasi-elastic");
            let q = record.time(stage, progress, || {
                let rigid = Arc::clone(rigid);
                quasi_elastic::search(&results.placement, rigid, &scene.quasi_elastic)
            });
            results.quasi_elastic = Some(q);
        }
        Stage::EpsilonSensitivity => {
            let rigid = results
                .rigid
                .as_ref()
                .expect("rigid runs before the sensitivity");
            let placement = &results.placement;
            let e = record.time(stage, progress, || epsilon_sweeps(scene, placement, rigid));
            results.epsilon = Some(e);
        }
        Stage::Hertz => {
            let (rigid, qe) = (results.rigid.as_ref(), results.quasi_elastic.as_ref());
            let h = record.time(stage, progress, || hertz_sweep(scene, rigid, qe));
            results.hertz = Some(h);
        }
        Stage::EquivalentConicity => {
            let rigid = results
                .rigid
                .as_ref()
                .expect("rigid runs before the equivalent conicity");
            let c = record.time(stage, progress, || {
                conicity::assess_on(&results.placement, rigid, &scene.conicity)
            });
            results.conicity = Some(c);
        }
        Stage::HertzAccuracy => {
            let a = record.time(stage, progress, hertz::accuracy::study);
            results.hertz_accuracy = Some(a);
        }
        Stage::Creep => {
            let (rigid, qe) = (results.rigid.as_deref(), results.quasi_elastic.as_ref());
            let placement = &results.placement;
            let c = record.time(stage, progress, || creep_sweep(scene, placement, rigid, qe));
            results.creep = Some(c);
        }
        Stage::ContactTable => {
            if let Some(grid) = &scene.contact_table {
                let placement = &results.placement;
                let t = record.time(stage, progress, || contact_table(scene, placement, grid));
                results.contact_table = Some(t);
            }
        }
    }
}

/// The Hertz ellipses of the scene's contacts (`[hertz] contact`: the rigid ones or the
/// quasi-elastic ones, which run before).
fn hertz_sweep(
    scene: &Scene,
    rigid: Option<&Arc<RigidSweep>>,
    quasi_elastic: Option<&QuasiElasticSweep>,
) -> hertz::HertzSweep {
    let contacts = contacts(rigid.map(|r| &**r), quasi_elastic, scene.hertz_contact);
    let e_star = hertz::effective_modulus(&scene.wheel_material, &scene.rail_material);
    hertz::sweep(contacts, scene.wheel_load_n, e_star, &scene.hertz)
}

/// The creep forces of the scene's contacts (`[creep] contact`: the rigid ones or the
/// quasi-elastic ones, which run before).
fn creep_sweep(
    scene: &Scene,
    placement: &Placement,
    rigid: Option<&RigidSweep>,
    quasi_elastic: Option<&QuasiElasticSweep>,
) -> Result<crate::creep::sweep::CreepSweep, crate::creep::CreepError> {
    let creep = &scene.creep;
    crate::creep::sweep::sweep(
        placement,
        contacts(rigid, quasi_elastic, creep.contact),
        scene.wheel_load_n,
        &creep.kinematics,
        &creep.settings,
    )
}

/// The contact table of `grid` on `placement`, with the scene's rigid solver, load,
/// materials and Hertz settings.
fn contact_table(
    scene: &Scene,
    placement: &Placement,
    grid: &crate::contact_table::Grid,
) -> crate::contact_table::ContactTable {
    let e_star = hertz::effective_modulus(&scene.wheel_material, &scene.rail_material);
    crate::contact_table::compute(
        placement,
        grid,
        scene.rigid_solver,
        scene.wheel_load_n,
        e_star,
        &scene.hertz,
        scene.creep.settings.poisson(),
    )
}

/// The contacts of `source`: the rigid sweep or the quasi-elastic one (the stage graph ran
/// their stage first).
fn contacts<'a>(
    rigid: Option<&'a RigidSweep>,
    quasi_elastic: Option<&'a QuasiElasticSweep>,
    source: hertz::ContactSource,
) -> hertz::Contacts<'a> {
    match source {
        hertz::ContactSource::Rigid => hertz::Contacts::Rigid(rigid.expect("rigid runs first")),
        hertz::ContactSource::QuasiElastic => {
            hertz::Contacts::QuasiElastic(quasi_elastic.expect("its contacts run first"))
        }
    }
}

/// The quasi-elastic search on `rigid` at each of the scene's sensitivity values of eps.
fn epsilon_sweeps(scene: &Scene, placement: &Placement, rigid: &Arc<RigidSweep>) -> EpsilonSweeps {
    let runs = scene
        .epsilon_sensitivity_mm
        .iter()
        .map(|&eps| {
            let settings = quasi_elastic::QuasiElasticSettings {
                epsilon_mm: eps,
                ..scene.quasi_elastic
            };
            let q = quasi_elastic::search(placement, Arc::clone(rigid), &settings);
            (eps, q)
        })
        .collect();
    EpsilonSweeps { runs }
}

/// Loads the scene's four profiles and places them: `place_wheels`, `place_rails` and
/// `assemble`.
///
/// # Errors
/// [`SceneError`] naming the profile key.
pub fn place(scene: &Scene) -> Result<Placement, SceneError> {
    let (wheels, rails) = join_in_pool(|| place_wheels(scene), || place_rails(scene));
    assemble(scene, wheels?, rails?)
}

/// [`place`], taking the fitted profiles and placed rails from `cache` where a scene run
/// before had the same ones (see [`PlacementCache`]) and leaving this scene's there: the
/// same placement to the last digit.
///
/// # Errors
/// As [`place`].
pub fn place_cached(scene: &Scene, cache: &PlacementCache) -> Result<Placement, SceneError> {
    let (wheels, rails) = join_in_pool(
        || place_wheels_in(scene, Some(cache)),
        || place_rails_in(scene, Some(cache)),
    );
    assemble(scene, wheels?, rails?)
}

/// Runs `a` and `b` in parallel on a thread of a rayon pool (joining there costs
/// microseconds), one after the other on any other thread (where starting the pool would
/// cost more than the work saves). Both run either way, and each returns what it would
/// alone: the results do not depend on the number of threads. A scene's wheels and rails
/// are the two halves (the rails, with their tables, the larger).
pub(crate) fn join_in_pool<A, B, RA, RB>(a: A, b: B) -> (RA, RB)
where
    A: FnOnce() -> RA + Send,
    B: FnOnce() -> RB + Send,
    RA: Send,
    RB: Send,
{
    if rayon::current_thread_index().is_some() {
        rayon::join(a, b)
    } else {
        (a(), b())
    }
}

/// The error of placing the profile of `key`.
fn placement_error(scene: &Scene, key: &'static str, e: PlacementError) -> SceneError {
    SceneError::Profile {
        path: scene.path.clone(),
        key,
        message: e.to_string(),
    }
}

/// Loads `scene`'s profile `r` of `kind` (the scene key `key`), through `cache` if given.
fn load_profile(
    scene: &Scene,
    cache: Option<&PlacementCache>,
    r: &ProfileRef,
    kind: ProfileKind,
    key: &'static str,
) -> Result<Profile, SceneError> {
    let load = || scene.load_profile(r, kind, key);
    match cache {
        Some(cache) => cache.profile(ProfileKey::of(scene, r, kind), load),
        None => load(),
    }
}

/// Loads the scene's left and right wheel profiles and places them. The right wheel takes
/// the left's profile when the scene names the same one (the usual case): read, fitted and
/// placed once.
///
/// # Errors
/// [`SceneError`] naming the profile key.
pub fn place_wheels(scene: &Scene) -> Result<[PlacedWheel; 2], SceneError> {
    place_wheels_in(scene, None)
}

/// `place_wheels`, with the profiles from `cache` when given.
fn place_wheels_in(
    scene: &Scene,
    cache: Option<&PlacementCache>,
) -> Result<[PlacedWheel; 2], SceneError> {
    let keys = scene.wheel_profile_keys;
    let place = |i: usize, profile| {
        PlacedWheel::place(profile, scene.nominal_radius_mm[i], &scene.layout)
            .map_err(|e| placement_error(scene, keys[i], e))
    };
    let load = |i: usize| {
        load_profile(
            scene,
            cache,
            &scene.wheel_profiles[i],
            ProfileKind::Wheel,
            keys[i],
        )
    };
    let left = place(0, load(0)?)?;
    let same_profile = scene.wheel_profiles[1] == scene.wheel_profiles[0];
    let right = if scene.same_wheels() {
        // The same wheel: its clone shares the cell bounds the searches build on first use
        // (a function of the wheel alone, so built once for both).
        left.clone()
    } else if same_profile {
        place(1, left.profile().clone())?
    } else {
        place(1, load(1)?)?
    };
    Ok([left, right])
}

/// Loads the scene's left and right rail profiles and places them; the right rail is the
/// left one, shared, when the scene names the same profile.
///
/// # Errors
/// [`SceneError`] naming the profile key.
pub fn place_rails(scene: &Scene) -> Result<[Arc<PlacedRail>; 2], SceneError> {
    place_rails_in(scene, None)
}

/// `place_rails`, through `cache` when given (see [`place_cached`]).
///
/// # Errors
/// As `place_rails`.
pub(crate) fn place_rails_cached(
    scene: &Scene,
    cache: &PlacementCache,
) -> Result<[Arc<PlacedRail>; 2], SceneError> {
    place_rails_in(scene, Some(cache))
}

/// `place_rails`, with the profiles and rails from `cache` when given.
fn place_rails_in(
    scene: &Scene,
    cache: Option<&PlacementCache>,
) -> Result<[Arc<PlacedRail>; 2], SceneError> {
    let keys = scene.rail_profile_keys;
    let place = |i: usize| -> Result<Arc<PlacedRail>, SceneError> {
        let r = &scene.rail_profiles[i];
        let profile_key = cache.and_then(|_| ProfileKey::of(scene, r, ProfileKind::Rail));
        let place = || {
            // On a miss the profile may still be cached (a rail of another layout).
            let load = || scene.load_profile(r, ProfileKind::Rail, keys[i]);
            let rail = match cache {
                Some(cache) => cache.profile(profile_key.clone(), load)?,
                None => load()?,
            };
            PlacedRail::place(rail, scene.rail_profile_inclination, &scene.layout)
                .map_err(|e| placement_error(scene, keys[i], e))
        };
        match cache {
            Some(cache) => {
                let key = profile_key
                    .clone()
                    .map(|k| RailKey::of(k, scene.rail_profile_inclination, &scene.layout));
                cache.rail(key, place)
            }
            None => place().map(Arc::new),
        }
    };
    let left = place(0)?;
    let right = if scene.same_rails() {
        Arc::clone(&left)
    } else {
        place(1)?
    };
    Ok([left, right])
}

/// The placement of placed wheels and rails `[left, right]` on `scene`'s track, checked by
/// [`Placement::new`] (a wheel that lies nowhere above its rail with the wheelset centred
/// is an error naming its key). A fleet places its shared rails (or wheels) once and
/// assembles each pair from them.
///
/// # Errors
/// [`SceneError`] naming the wheel's profile key.
pub(crate) fn assemble(
    scene: &Scene,
    wheels: [PlacedWheel; 2],
    rails: [Arc<PlacedRail>; 2],
) -> Result<Placement, SceneError> {
    let wheel_keys = scene.wheel_profile_keys;
    let [left_wheel, right_wheel] = wheels;
    let [left_rail, right_rail] = rails;
    let left = SidePair::new(left_wheel, left_rail);
    let right = SidePair::new(right_wheel, right_rail);
    Placement::new(scene.layout.clone(), left, right).map_err(|e| {
        let key = match e {
            PlacementError::NoOverlap {
                side: Side::Right, ..
            } => wheel_keys[1],
            _ => wheel_keys[0],
        };
        placement_error(scene, key, e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A wheelset's two equal wheels are one wheel cloned, whose cell bounds (built by the
    /// first search) serve both; wheels of another radius are placed on their own.
    #[test]
    fn equal_wheels_share_their_cell_bounds() {
        let equal = Scene::from_toml("", "equal", std::path::Path::new(".")).unwrap();
        let [left, right] = place_wheels(&equal).unwrap();
        assert!(left.shares_cells_with(&right));
        let text = "[wheel]\nnominal_radius_mm = 460.0\nright_nominal_radius_mm = 455.0\n";
        let unequal = Scene::from_toml(text, "unequal", std::path::Path::new(".")).unwrap();
        let [left, right] = place_wheels(&unequal).unwrap();
        assert!(!left.shares_cells_with(&right));
        assert!((right.nominal_radius_mm() - 455.0).abs() < 1e-12);
    }
}
