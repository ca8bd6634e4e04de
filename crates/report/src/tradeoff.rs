//! Run time against error: the scene's pipeline (placement, rigid, quasi-elastic, Hertz;
//! no rendering) under a grid of numerical settings, each timed and compared with a
//! converged reference computed once with the finest settings.
//!
//! Errors over the whole sweep, both wheels:
//! - `contact_mm`: rigid contact position (wheel coordinate), positions within one sweep step
//!   of a reference jump excluded (there an arbitrarily small change moves the jump);
//! - `qe_location_mm`: quasi-elastic contact location, weight-averaged over the patches (so
//!   that a change of the heaviest patch is not counted as an error of its size);
//! - `roll_rad`; `a_rel`, `b_rel`, `p0_rel`: relative errors of the Hertz results where both
//!   the setting and the reference have an ellipse.
//!
//! [`fastsim`] measures FASTSIM's discretisation the same way (its grids timed in rounds of
//! random order after a warm-up, errors against a converged grid).

pub mod fastsim;

use std::sync::Arc;
use std::time::Instant;
use wheelrail::hertz::{self, EllipseMethod};
use wheelrail::pipeline::{self, Stage};
use wheelrail::profile::read::PointProfile;
use wheelrail::profile::{Profile, ProfileKind};
use wheelrail::quasi_elastic::{self, QuasiElasticSweep};
use wheelrail::rigid::{RigidSweep, Solver, Stop};
use wheelrail::rng::SplitMix64;
use wheelrail::scene::{ProfileRef, Scene};
use wheelrail::track::{Placement, SidePair};

/// One combination of numerical settings.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// Short label, e.g. `default` or `sampled 0.5 mm, paper solver`.
    pub label: String,
    /// `None`: the scene's profiles as they are; `Some(h)`: built-in profiles sampled every
    /// `h` mm and read back through the CSV reader and an interpolating spline.
    pub profile_step_mm: Option<f64>,
    /// Rigid solver.
    pub solver: Solver,
    /// Quasi-elastic settings.
    pub quasi_elastic: quasi_elastic::QuasiElasticSettings,
    /// Hertz method.
    pub hertz: EllipseMethod,
}

/// The measured cost and errors of one setting.
#[derive(Debug, Clone)]
pub struct Measurement {
    /// The setting.
    pub setting: Setting,
    /// Median wall time of one run (s), single-threaded, over the timed rounds.
    pub median_s: f64,
    /// Fastest and slowest of the timed runs (s).
    pub range_s: (f64, f64),
    /// Errors against the reference (see the module docs).
    pub errors: Errors,
}

/// Errors of one setting against the reference.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Errors {
    /// Rigid contact position, mm.
    pub contact_mm: f64,
    /// Quasi-elastic location, mm.
    pub qe_location_mm: f64,
    /// Roll, rad.
    pub roll_rad: f64,
    /// Semi-axis a, relative.
    pub a_rel: f64,
    /// Semi-axis b, relative.
    pub b_rel: f64,
    /// Maximum pressure, relative.
    pub p0_rel: f64,
}

/// Panel length of the reference's Gauss-Legendre quadrature, in weight widths: a sixth of
/// the default's.
pub const REFERENCE_PANEL_WIDTHS: f64 = 0.5;

/// The study's quasi-elastic settings, each a constant of this module within the ranges
/// `QuasiElasticSettings::new` checks.
fn within_ranges(
    settings: Result<quasi_elastic::QuasiElasticSettings, quasi_elastic::QuasiElasticSettingsError>,
) -> quasi_elastic::QuasiElasticSettings {
    settings.expect("the study's settings are within the quasi-elastic search's ranges")
}

/// The reference: analytic profiles, default solver, Gauss-Legendre quadrature on panels of
/// half a weight width with the cut-off at exp(-60), exact Hertz.
pub fn reference_setting() -> Setting {
    Setting {
        label: "reference".into(),
        profile_step_mm: None,
        solver: Solver::default(),
        quasi_elastic: within_ranges(
            quasi_elastic::QuasiElasticSettings::default()
                .with_cutoff(60.0)
                .and_then(|q| {
                    q.with_quadrature(quasi_elastic::Quadrature::GaussLegendre {
                        panel_widths: REFERENCE_PANEL_WIDTHS,
                    })
                }),
        ),
        hertz: EllipseMethod::Exact,
    }
}

/// The project's default settings (what a scene gets without numerical keys).
pub fn default_setting(scene: &Scene) -> Setting {
    Setting {
        label: "default".into(),
        profile_step_mm: None,
        solver: Solver::default(),
        quasi_elastic: *scene.quasi_elastic(),
        hertz: EllipseMethod::Exact,
    }
}

/// The paper's numerical choices: tabulated profiles (0.1 mm), its rigid iteration, a
/// trapezoid sum on the table (0.1 mm), its series and fixed-point iteration for Hertz.
pub fn paper_setting(scene: &Scene) -> Setting {
    Setting {
        label: "paper".into(),
        profile_step_mm: Some(0.1),
        solver: Solver::Paper,
        quasi_elastic: within_ranges(
            scene
                .quasi_elastic()
                .with_quadrature(quasi_elastic::Quadrature::Trapezoid { max_step_mm: 0.1 }),
        ),
        hertz: EllipseMethod::Paper,
    }
}

/// The grid of the study: the default, the paper's, and one-at-a-time and combined
/// variations of profile sampling, solver, quadrature kind and step, cut-off and Hertz method.
pub fn grid(scene: &Scene) -> Vec<Setting> {
    let d = default_setting(scene);
    let mut out = vec![d.clone(), paper_setting(scene)];
    for step in [0.05, 0.1, 0.2, 0.5, 1.0] {
        out.push(Setting {
            label: format!("profiles sampled {step} mm"),
            profile_step_mm: Some(step),
            ..d.clone()
        });
    }
    out.push(Setting {
        label: "paper rigid solver".into(),
        solver: Solver::Paper,
        ..d.clone()
    });
    for max_step in [0.01, 0.05, 0.2] {
        out.push(Setting {
            label: format!("trapezoid {max_step} mm"),
            quasi_elastic: within_ranges(d.quasi_elastic.with_quadrature(
                quasi_elastic::Quadrature::Trapezoid {
                    max_step_mm: max_step,
                },
            )),
            ..d.clone()
        });
    }
    for panel_widths in [2.0, 4.0] {
        out.push(Setting {
            label: format!("Gauss-Legendre panels of {panel_widths} widths"),
            quasi_elastic: within_ranges(
                d.quasi_elastic
                    .with_quadrature(quasi_elastic::Quadrature::GaussLegendre { panel_widths }),
            ),
            ..d.clone()
        });
    }
    for cutoff in [10.0, 15.0, 37.0] {
        out.push(Setting {
            label: format!("cut-off exp(-{cutoff})"),
            quasi_elastic: within_ranges(d.quasi_elastic.with_cutoff(cutoff)),
            ..d.clone()
        });
    }
    out.push(Setting {
        label: "paper Hertz".into(),
        hertz: EllipseMethod::Paper,
        ..d.clone()
    });
    out
}

/// What one run of a setting produces.
struct Run {
    rigid: Arc<RigidSweep>,
    quasi_elastic: QuasiElasticSweep,
    hertz: hertz::HertzSweep,
}

/// The scene with `setting`'s numerical choices in place of its own.
fn with_setting(scene: &Scene, setting: &Setting) -> Scene {
    scene.with_numerics(setting.solver, setting.quasi_elastic, setting.hertz)
}

fn placement_for(scene: &Scene, setting: &Setting) -> Result<Placement, crate::Error> {
    let Some(step) = setting.profile_step_mm else {
        return Ok(pipeline::place(scene)?);
    };
    // The scene's profiles sampled every `step` mm (section joints included) and fitted
    // again by an interpolating spline, as a measured file would be.
    let sampled = |r: &ProfileRef, kind| -> Result<Profile, crate::Error> {
        let profile = scene.load_profile(r, kind, "tradeoff")?;
        let points = profile.sample(step).iter().map(|r| [r[0], r[1]]).collect();
        let points = PointProfile::from_points(kind, "sampled", points)?;
        Ok(Profile::from_points(points, 0.0)?)
    };
    let side = |i: usize| -> Result<SidePair, crate::Error> {
        SidePair::place(
            sampled(&scene.wheel_profiles()[i], ProfileKind::Wheel)?,
            scene.nominal_radius_mm()[i],
            sampled(&scene.rail_profiles()[i], ProfileKind::Rail)?,
            scene.rail_profile_inclination(),
            scene.layout(),
        )
        .map_err(crate::Error::from)
    };
    // One profile and radius for both wheels and one rail profile: one side placed and
    // cloned for the other, as `pipeline::place` places a scene's measured files (the
    // wheelset is then mirror-symmetric, and a symmetric sweep solves half of it).
    let left = side(0)?;
    let right = if scene.same_wheels() && scene.same_rails() {
        left.clone()
    } else {
        side(1)?
    };
    Placement::new(scene.layout().clone(), left, right).map_err(crate::Error::from)
}

/// One run of the pipeline's stages (placement included, as a report runs them) under
/// `setting`: the same code as `wheelrail report`, with the setting's overrides.
fn run_once(scene: &Scene, setting: &Setting) -> Result<Run, crate::Error> {
    let scene = with_setting(scene, setting);
    let placement = placement_for(&scene, setting)?;
    let results = pipeline::run_on(&scene, placement, &[Stage::QuasiElastic, Stage::Hertz]);
    let missing = "both stages and the rigid stage they need ran";
    Ok(Run {
        rigid: results.rigid.expect(missing),
        quasi_elastic: results.quasi_elastic.expect(missing),
        hertz: results.hertz.expect(missing),
    })
}

/// Runs the study: the reference once, then a warm-up round (each setting once, untimed:
/// its results give the errors) and `repeats` timed rounds. Every round runs all settings
/// in its own random order, so that no setting is favoured by running first or after a
/// particular other one (cold caches, frequency changes, other load on the machine); each
/// setting's median and spread (fastest, slowest) are over its timed runs. Placement, which
/// reads and fits profiles, is timed with the run. `progress(done, total, label)` is called
/// before each run and once at the end (`done == total`, label `done`).
///
/// The order comes from a fixed seed ([`ORDER_SEED`]): the same study runs the same order.
///
/// # Errors
/// [`crate::Error`] when a profile cannot be read or placed.
pub fn study(
    scene: &Scene,
    settings: &[Setting],
    repeats: usize,
    progress: impl FnMut(usize, usize, &str) + Send,
) -> Result<Vec<Measurement>, crate::Error> {
    // Timed single-threaded: the stages' own parallelism (rayon) is confined to one thread,
    // so that settings compare by their work, not by how well they parallelise.
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    pool.install(|| study_on_this_thread(scene, settings, repeats, progress))
}

/// Seed of the random order of the settings in each round of [`study`].
pub const ORDER_SEED: u64 = 0x5EED_F7AD;

fn study_on_this_thread(
    scene: &Scene,
    settings: &[Setting],
    repeats: usize,
    mut progress: impl FnMut(usize, usize, &str),
) -> Result<Vec<Measurement>, crate::Error> {
    let reference_setting = reference_setting();
    let reference = run_once(scene, &reference_setting)?;
    let mut errors_of: Vec<Option<Errors>> = vec![None; settings.len()];
    let labels: Vec<&str> = settings.iter().map(|s| s.label.as_str()).collect();
    let timings = timed_rounds(&labels, repeats, &mut progress, |i, warm_up| {
        let run = run_once(scene, &settings[i])?;
        if warm_up {
            errors_of[i] = Some(errors(&reference, &run));
        }
        Ok::<(), crate::Error>(())
    })?;
    Ok(settings
        .iter()
        .zip(timings)
        .zip(errors_of)
        .map(|((setting, timing), errors)| Measurement {
            setting: setting.clone(),
            median_s: timing.median_s,
            range_s: timing.range_s,
            errors: errors.expect("every setting ran in the warm-up round"),
        })
        .collect())
}

/// The median and the fastest and slowest of one item's timed runs, s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timing {
    /// Median of the timed runs, s.
    pub median_s: f64,
    /// Fastest and slowest of the timed runs, s.
    pub range_s: (f64, f64),
}

/// Times `run(i, warm_up)` for each item `i` of `labels`: a warm-up round (each item once,
/// untimed, `warm_up` true) and `repeats` (at least 1) timed rounds, every round over all
/// items in its own random order from [`ORDER_SEED`]. The warm-up pays for an item's first
/// use of code and data, which would otherwise make whichever item runs first look slower
/// than an equal one run later. `progress(done, total, label)` is called before each run
/// and once at the end (`done == total`, label `done`).
fn timed_rounds<E>(
    labels: &[&str],
    repeats: usize,
    progress: &mut impl FnMut(usize, usize, &str),
    mut run: impl FnMut(usize, bool) -> Result<(), E>,
) -> Result<Vec<Timing>, E> {
    let rounds = 1 + repeats.max(1);
    let total = rounds * labels.len();
    let mut rng = SplitMix64::new(ORDER_SEED);
    let mut times: Vec<Vec<f64>> = vec![Vec::with_capacity(rounds - 1); labels.len()];
    let mut done = 0;
    for round in 0..rounds {
        for i in rng.permutation(labels.len()) {
            progress(done, total, labels[i]);
            done += 1;
            let start = Instant::now();
            run(i, round == 0)?;
            let elapsed = start.elapsed().as_secs_f64();
            if round > 0 {
                times[i].push(elapsed);
            }
        }
    }
    progress(total, total, "done");
    Ok(times
        .into_iter()
        .map(|mut times| {
            times.sort_by(f64::total_cmp);
            Timing {
                median_s: median(&times),
                range_s: (times[0], times[times.len() - 1]),
            }
        })
        .collect())
}

/// Median of sorted, non-empty `times` (the mean of the middle two for an even count).
fn median(times: &[f64]) -> f64 {
    let n = times.len();
    if n % 2 == 1 {
        times[n / 2]
    } else {
        0.5 * (times[n / 2 - 1] + times[n / 2])
    }
}

fn errors(reference: &Run, run: &Run) -> Errors {
    let mut e = Errors::default();
    let step = reference
        .rigid
        .positions()
        .windows(2)
        .map(|w| w[1].y_ws - w[0].y_ws)
        .fold(0.0, f64::max);
    let near_jump = |y: f64| {
        reference
            .rigid
            .jumps()
            .iter()
            .any(|j| (y - j.y_from).abs() <= step + 1e-9)
    };
    for (a, b) in reference
        .rigid
        .positions()
        .iter()
        .zip(run.rigid.positions())
    {
        if a.stop != Stop::Converged || b.stop != Stop::Converged {
            continue;
        }
        e.roll_rad = e.roll_rad.max((a.roll - b.roll).abs());
        if near_jump(a.y_ws) {
            continue;
        }
        for k in 0..2 {
            if let (Some(ca), Some(cb)) = (a.contact[k], b.contact[k]) {
                e.contact_mm = e.contact_mm.max((ca.s - cb.s).abs());
            }
        }
    }
    let location = |side: &quasi_elastic::SideResult| -> f64 {
        side.patches.iter().map(|p| p.weight_share * p.s).sum()
    };
    for (a, b) in reference
        .quasi_elastic
        .positions()
        .iter()
        .zip(run.quasi_elastic.positions())
    {
        for k in 0..2 {
            if !a.sides[k].patches.is_empty() && !b.sides[k].patches.is_empty() {
                e.qe_location_mm = e
                    .qe_location_mm
                    .max((location(&a.sides[k]) - location(&b.sides[k])).abs());
            }
        }
    }
    for (a, b) in reference
        .hertz
        .positions()
        .iter()
        .zip(run.hertz.positions())
    {
        for k in 0..2 {
            let ea = a.sides[k].ellipse();
            let eb = b.sides[k].ellipse();
            if let (Some(x), Some(y)) = (ea, eb) {
                e.a_rel = e.a_rel.max((y.a_mm / x.a_mm - 1.0).abs());
                e.b_rel = e.b_rel.max((y.b_mm / x.b_mm - 1.0).abs());
                e.p0_rel = e.p0_rel.max((y.p0_mpa / x.p0_mpa - 1.0).abs());
            }
        }
    }
    e
}

/// The settings on the Pareto front of (time, error): no other setting is at least as fast
/// and at least as accurate and better in one of them. Indices into `m`, fastest first.
pub fn pareto_front(m: &[Measurement], error: impl Fn(&Errors) -> f64) -> Vec<usize> {
    let points: Vec<(f64, f64)> = m.iter().map(|x| (x.median_s, error(&x.errors))).collect();
    pareto_indices(&points)
}

/// The Pareto front of `(time, error)` points: indices of those no other point beats in
/// both, fastest first (errors falling).
pub fn pareto_indices(points: &[(f64, f64)]) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..points.len()).collect();
    idx.sort_by(|&a, &b| points[a].0.total_cmp(&points[b].0));
    let mut front = Vec::new();
    let mut best = f64::INFINITY;
    for i in idx {
        let e = points[i].1;
        if e < best {
            best = e;
            front.push(i);
        }
    }
    front
}

/// What a study's chart shows of one point (a setting, or a FASTSIM grid): its label,
/// median time and the two errors its panels plot. From a [`Measurement`] or a
/// [`fastsim::GridMeasurement`], or from a row of the study's table ([`chart_points`],
/// [`fastsim::chart_points`]), so that the chart can be drawn again without measuring again.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartPoint {
    /// The setting's or grid's label.
    pub label: String,
    /// Median run time: ms for a setting (a run of the scene), µs for a grid (one patch).
    pub median: f64,
    /// The errors of the two panels: for a setting the rigid contact position error (mm) and
    /// the larger relative error of the semi-axes a and b; for a grid the force and the
    /// spin-moment errors (relative to `μ FN` and `μ FN c`).
    pub errors: [f64; 2],
}

impl From<&Measurement> for ChartPoint {
    fn from(m: &Measurement) -> ChartPoint {
        ChartPoint {
            label: m.setting.label.clone(),
            median: 1e3 * m.median_s,
            errors: [m.errors.contact_mm, m.errors.a_rel.max(m.errors.b_rel)],
        }
    }
}

/// Why a text is no table of a study (`tradeoff.csv`: [`chart_points`];
/// `fastsim_tradeoff.csv`: [`fastsim::chart_points`]).
#[derive(Debug, Clone, PartialEq)]
pub enum TradeoffCsvError {
    /// The text is no CSV table (the file, why).
    Table(String, crate::TableError),
    /// A column the chart needs is missing.
    NoColumn {
        /// The file.
        origin: String,
        /// The column.
        column: &'static str,
        /// The file name of the study's table (`tradeoff.csv`).
        table: &'static str,
    },
    /// A column the chart needs holds a cell that is no number (`NaN` is one).
    NotNumbers {
        /// The file.
        origin: String,
        /// The column.
        column: &'static str,
    },
}

impl std::fmt::Display for TradeoffCsvError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TradeoffCsvError::Table(origin, e) => write!(f, "{origin}: {e}"),
            TradeoffCsvError::NoColumn {
                origin,
                column,
                table,
            } => write!(f, "{origin}: no column {column:?}: not a {table}"),
            TradeoffCsvError::NotNumbers { origin, column } => write!(
                f,
                "{origin}: column {column:?} has a cell that is no number (NaN is one)"
            ),
        }
    }
}

impl std::error::Error for TradeoffCsvError {}

/// A study's table read back for its chart: its columns by name, errors naming the file.
struct StudyCsv<'a> {
    table: crate::Table,
    origin: &'a str,
    name: &'static str,
}

impl<'a> StudyCsv<'a> {
    /// `text` read as the table `name` (e.g. `tradeoff.csv`) from the file `origin`.
    fn parse(text: &str, origin: &'a str, name: &'static str) -> Result<Self, TradeoffCsvError> {
        let table = crate::Table::parse_csv(text)
            .map_err(|e| TradeoffCsvError::Table(origin.to_string(), e))?;
        Ok(StudyCsv {
            table,
            origin,
            name,
        })
    }

    fn missing(&self, column: &'static str) -> TradeoffCsvError {
        TradeoffCsvError::NoColumn {
            origin: self.origin.to_string(),
            column,
            table: self.name,
        }
    }

    /// The numbers of `column`.
    fn numbers(&self, column: &'static str) -> Result<&[f64], TradeoffCsvError> {
        match (self.table.numeric(column), self.table.text(column)) {
            (Some(v), _) => Ok(v),
            (None, Some(_)) => Err(TradeoffCsvError::NotNumbers {
                origin: self.origin.to_string(),
                column,
            }),
            (None, None) => Err(self.missing(column)),
        }
    }

    /// A chart point per row: its label from the text column `label`, its median time
    /// from `median`, its errors from `errors(row)`.
    fn points(
        &self,
        label: &'static str,
        median: &'static str,
        errors: impl Fn(usize) -> [f64; 2],
    ) -> Result<Vec<ChartPoint>, TradeoffCsvError> {
        let labels = self.table.text(label).ok_or_else(|| self.missing(label))?;
        let median = self.numbers(median)?;
        Ok(labels
            .iter()
            .enumerate()
            .map(|(i, label)| ChartPoint {
                label: label.to_string(),
                median: median[i],
                errors: errors(i),
            })
            .collect())
    }
}

/// The chart points of a `tradeoff.csv` as `wheelrail tradeoff` writes it.
///
/// # Errors
/// [`TradeoffCsvError`] naming `origin` when the text is no such table (a column missing,
/// a row without a number where one is needed).
pub fn chart_points(text: &str, origin: &str) -> Result<Vec<ChartPoint>, TradeoffCsvError> {
    let csv = StudyCsv::parse(text, origin, "tradeoff.csv")?;
    let (contact, a, b) = (
        csv.numbers("contact_error_mm")?,
        csv.numbers("a_rel_error")?,
        csv.numbers("b_rel_error")?,
    );
    csv.points("setting", "median_ms", |i| [contact[i], a[i].max(b[i])])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounds_are_permutations_in_changing_orders() {
        let mut rng = SplitMix64::new(ORDER_SEED);
        let orders: Vec<Vec<usize>> = (0..6).map(|_| rng.permutation(17)).collect();
        for order in &orders {
            let mut sorted = order.clone();
            sorted.sort_unstable();
            assert_eq!(sorted, (0..17).collect::<Vec<_>>());
        }
        // Which setting runs first changes from round to round.
        let firsts: std::collections::HashSet<usize> = orders.iter().map(|o| o[0]).collect();
        assert!(firsts.len() >= 3, "{orders:?}");
    }

    #[test]
    fn median_of_even_and_odd_counts() {
        assert_eq!(median(&[1.0, 2.0, 9.0]).to_bits(), 2.0f64.to_bits());
        assert_eq!(median(&[1.0, 2.0, 4.0, 9.0]).to_bits(), 3.0f64.to_bits());
    }
}
