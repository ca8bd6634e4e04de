//! The pipeline's stages on the paper scene (defaults of an empty scene file: S1002 on
//! UIC60 1:40, 301 positions from -15 to 15 mm every 0.1 mm): profile placement, the rigid
//! sweep with both solvers, the quasi-elastic pass and the Hertz ellipses over the sweep.
//! Run with `cargo bench --bench pipeline`; compare the solvers as ratios of medians taken
//! in the same run (the machine is shared).

use divan::black_box;
use std::path::Path;
use std::sync::{Arc, OnceLock};
use wheelrail::cache::PlacementCache;
use wheelrail::profile::read::PointProfile;
use wheelrail::profile::{Profile, ProfileKind};
use wheelrail::quasi_elastic::{self, QuasiElasticSweep};
use wheelrail::rigid::{self, RigidSweep, Solver};
use wheelrail::scene::Scene;
use wheelrail::sweep::{Sweep, YawModel, YawRule};
use wheelrail::track::{PlacedRail, PlacedWheel, Placement, SidePair};
use wheelrail::{hertz, pipeline};

fn main() {
    divan::main();
}

fn scene() -> &'static Scene {
    static S: OnceLock<Scene> = OnceLock::new();
    S.get_or_init(|| Scene::from_toml("", "paper defaults", Path::new(".")).unwrap())
}

fn placement() -> &'static Placement {
    static P: OnceLock<Placement> = OnceLock::new();
    P.get_or_init(|| pipeline::place(scene()).unwrap())
}

/// The rigid sweep the quasi-elastic benchmarks average around, shared (as a pipeline
/// shares it with its quasi-elastic results: no copy per run).
fn rigid_sweep() -> &'static Arc<RigidSweep> {
    static R: OnceLock<Arc<RigidSweep>> = OnceLock::new();
    R.get_or_init(|| {
        Arc::new(rigid::search(
            placement(),
            scene().sweep(),
            Solver::default(),
        ))
    })
}

/// The paper placement with the mirror switched off: every position of a sweep is solved
/// and averaged (the work of a wheelset whose two wheels differ, such as a measured pair).
fn placement_unmirrored() -> &'static Placement {
    static P: OnceLock<Placement> = OnceLock::new();
    P.get_or_init(|| placement().clone().without_mirroring())
}

fn quasi_elastic_sweep() -> &'static QuasiElasticSweep {
    static Q: OnceLock<QuasiElasticSweep> = OnceLock::new();
    Q.get_or_init(|| {
        quasi_elastic::search(
            placement(),
            Arc::clone(rigid_sweep()),
            scene().quasi_elastic(),
        )
    })
}

/// Step at which the sampled benchmarks sample the built-in profiles (mm), as the tradeoff
/// study's sampled setting.
const SAMPLE_STEP_MM: f64 = 0.25;

/// The points of a sampled profile `(u, v)` (mm).
type Points = Vec<[f64; 2]>;

/// S1002 and UIC60 sampled every [`SAMPLE_STEP_MM`] (section joints included): the points a
/// measured pair would give, `(wheel, rail)`.
fn sampled_points() -> &'static (Points, Points) {
    static P: OnceLock<(Points, Points)> = OnceLock::new();
    P.get_or_init(|| {
        let points = |p: Profile| {
            p.sample(SAMPLE_STEP_MM)
                .iter()
                .map(|r| [r[0], r[1]])
                .collect()
        };
        (points(Profile::s1002()), points(Profile::uic60e1()))
    })
}

/// The sampled wheel and rail checked, fitted (interpolating splines) and placed as the
/// paper scene places the analytic ones (`pipeline::place`): each profile fitted and placed
/// once, the wheel cloned for the right side and the rail shared by both sides (a
/// mirror-symmetric wheelset, as a scene naming one measured profile for both wheels
/// gives).
fn place_sampled_pair(wheel: &[[f64; 2]], rail: &[[f64; 2]]) -> Placement {
    let analytic = placement();
    let layout = analytic.layout();
    let fit = |kind, points: &[[f64; 2]]| {
        let points = PointProfile::from_points(kind, "sampled", points.to_vec()).unwrap();
        Profile::from_points(points, 0.0).unwrap()
    };
    let wheel = fit(ProfileKind::Wheel, wheel);
    let rail = Arc::new(
        PlacedRail::place(
            fit(ProfileKind::Rail, rail),
            scene().rail_profile_inclination(),
            layout,
        )
        .unwrap(),
    );
    let wheel =
        PlacedWheel::place(wheel, analytic.left().wheel().nominal_radius_mm(), layout).unwrap();
    let left = SidePair::new(wheel.clone(), rail.clone());
    let right = SidePair::new(wheel, rail);
    Placement::new(layout.clone(), left, right).unwrap()
}

fn sampled_placement() -> &'static Placement {
    static P: OnceLock<Placement> = OnceLock::new();
    P.get_or_init(|| {
        let (wheel, rail) = sampled_points();
        place_sampled_pair(wheel, rail)
    })
}

/// Checking, fitting and placing S1002 and UIC60 sampled every 0.25 mm (both sides, one
/// fit and one rail placement each, as the paper scene's placement).
#[divan::bench]
fn place_sampled() -> Placement {
    let (wheel, rail) = sampled_points();
    place_sampled_pair(black_box(wheel), black_box(rail))
}

/// The rigid sweep of the paper scene on the sampled profiles, default solver.
#[divan::bench]
fn rigid_sampled() -> RigidSweep {
    rigid::search(
        black_box(sampled_placement()),
        scene().sweep(),
        black_box(Solver::default()),
    )
}

/// Loading and placing the four profiles (cold: the rail's tables built).
#[divan::bench]
fn place() -> Placement {
    pipeline::place(black_box(scene())).unwrap()
}

/// The same placement from a cache that holds it (another scene of the run placed the
/// same profiles on the same track): the profiles' keys, the rail shared, the wheels
/// placed and the sides checked.
#[divan::bench]
fn place_cached() -> Placement {
    static CACHE: OnceLock<PlacementCache> = OnceLock::new();
    let cache = CACHE.get_or_init(|| {
        let cache = PlacementCache::new();
        pipeline::place_cached(scene(), &cache).unwrap();
        cache
    });
    pipeline::place_cached(black_box(scene()), cache).unwrap()
}

/// The rigid sweep with the project's solver.
#[divan::bench]
fn rigid_default() -> RigidSweep {
    rigid::search(
        black_box(placement()),
        scene().sweep(),
        black_box(Solver::default()),
    )
}

/// The same sweep solved at every position: the mirror switched off, so that the
/// positions left of the centre are not mirrored (a wheelset of two different wheels).
#[divan::bench]
fn rigid_default_unmirrored() -> RigidSweep {
    rigid::search(
        black_box(placement_unmirrored()),
        scene().sweep(),
        black_box(Solver::default()),
    )
}

/// The paper sweep with the wheelset at a fixed yaw of 10 mrad (a wheelset in a curve; a row
/// of a contact table), solved at every position: the wheel's outline prepared once.
/// Compare with `rigid_default_unmirrored` (the same positions without yaw).
#[divan::bench]
fn rigid_yawed() -> RigidSweep {
    static S: OnceLock<Sweep> = OnceLock::new();
    let sweep = S.get_or_init(|| yawed(YawRule::new(0.01, 0.0, YawModel::Exact)));
    rigid::search(
        black_box(placement_unmirrored()),
        sweep,
        black_box(Solver::default()),
    )
}

/// The same sweep with the yaw growing with the shift as the Manchester benchmark's does
/// (2.4 mrad per mm, 36 mrad at 15 mm): the outline prepared again for every position and
/// every step of a jump's refinement.
#[divan::bench]
fn rigid_yawed_growing() -> RigidSweep {
    static S: OnceLock<Sweep> = OnceLock::new();
    let sweep = S.get_or_init(|| yawed(YawRule::new(0.0, 2.4e-3, YawModel::Exact)));
    rigid::search(
        black_box(placement_unmirrored()),
        sweep,
        black_box(Solver::default()),
    )
}

/// The paper sweep with the wheelset yawed by `yaw`.
fn yawed(yaw: YawRule) -> Sweep {
    scene().sweep().clone().with_yaw(yaw).unwrap()
}

/// The rigid sweep with the paper's solver.
#[divan::bench(sample_count = 30)]
fn rigid_paper() -> RigidSweep {
    rigid::search(
        black_box(placement()),
        scene().sweep(),
        black_box(Solver::Paper),
    )
}

/// The quasi-elastic pass over the default rigid sweep.
#[divan::bench]
fn quasi_elastic() -> QuasiElasticSweep {
    quasi_elastic::search(
        black_box(placement()),
        Arc::clone(rigid_sweep()),
        scene().quasi_elastic(),
    )
}

/// The same pass averaging every position (the mirror switched off, as
/// `rigid_default_unmirrored`).
#[divan::bench]
fn quasi_elastic_unmirrored() -> QuasiElasticSweep {
    quasi_elastic::search(
        black_box(placement_unmirrored()),
        Arc::clone(rigid_sweep()),
        scene().quasi_elastic(),
    )
}

/// Hertz ellipses over the sweep, from the quasi-elastic contacts (the scene's default).
#[divan::bench]
fn hertz_sweep() -> hertz::HertzSweep {
    let s = scene();
    let e_star = hertz::effective_modulus(s.wheel_material(), s.rail_material());
    let contacts = hertz::Contacts::QuasiElastic(black_box(quasi_elastic_sweep()));
    hertz::sweep(contacts, s.wheel_load_n(), e_star, s.hertz())
}

/// Positions from -15 to 15 mm, `n` of them: the sweep-length scaling of the rigid sweep
/// and the quasi-elastic pass (time per position = median / n).
fn sweep_of(n: usize) -> Sweep {
    let shifts: Vec<f64> = (0..n)
        .map(|i| -15.0 + 30.0 * i as f64 / (n - 1) as f64)
        .collect();
    Sweep::from_slice(&shifts).unwrap()
}

/// The rigid sweep (default solver) over 31, 301 and 3001 positions.
#[divan::bench(args = [31, 301, 3001])]
fn rigid_positions(bencher: divan::Bencher, n: usize) {
    let sweep = sweep_of(n);
    bencher.bench(|| rigid::search(black_box(placement()), &sweep, Solver::default()));
}

/// The quasi-elastic pass over rigid sweeps of 31, 301 and 3001 positions.
#[divan::bench(args = [31, 301, 3001])]
fn quasi_elastic_positions(bencher: divan::Bencher, n: usize) {
    let rigid = Arc::new(rigid::search(placement(), &sweep_of(n), Solver::default()));
    bencher.bench(|| {
        let rigid = Arc::clone(&rigid);
        quasi_elastic::search(black_box(placement()), rigid, scene().quasi_elastic())
    });
}

/// The machine's clock during the run, to turn the other medians into cycles: a chain of
/// 1,000,000 dependent 64-bit multiplications (each squares the last result, which no
/// compiler can shorten: a product by a constant factor it can regroup), 3 cycles each on
/// current x86_64 cores (Intel since Nehalem, AMD since Zen), so 3,000,000 cycles. The clock
/// in GHz is 3 / the median in ms; with callgrind's instructions per call it gives the
/// instructions per cycle of a benchmark. Measured in the same run as the benchmarks it
/// converts: a virtual machine's clock moves with its host's load.
#[divan::bench]
fn clock_reference() -> u64 {
    let mut x = black_box(3_u64);
    for _ in 0..1_000_000 {
        x = x.wrapping_mul(x);
    }
    x
}

/// The EN 15302 reference pair (R-UIC519A on S-UIC519A 1:20, 141 positions:
/// `benches/data/en15302_e1_delta_r.toml`) as the numerics compute it: the scene and its two
/// 1000-point files read, fitted and placed, the rigid sweep and the equivalent conicity
/// (no tables, figures or files: `cargo bench --bench scene` renders them too).
#[divan::bench(sample_count = 30)]
fn en15302_e1_profiles_and_sweep(bencher: divan::Bencher) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/data/en15302_e1_delta_r.toml");
    bencher.bench(|| {
        let scene = Scene::load(black_box(&path)).unwrap();
        pipeline::run(&scene).unwrap()
    });
}

/// The EN 15302 pair's profiles alone: the two files read, fitted and placed.
#[divan::bench(sample_count = 30)]
fn en15302_e1_profiles(bencher: divan::Bencher) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/data/en15302_e1_delta_r.toml");
    let scene = Scene::load(&path).unwrap();
    bencher.bench(|| pipeline::place(black_box(&scene)).unwrap());
}
