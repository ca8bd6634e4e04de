//! The work a scene asks for and the bytes it will write, estimated from its keys and
//! profiles before anything runs, and the budgets above which a run needs `--allow-long`.
//!
//! The unit of work is one evaluation of the gap between a wheel point and its rail (tens of
//! nanoseconds on a current core; `examples/evaluation_counts.rs` counts them per stage).
//! The estimate is deliberately coarse and errs high: it assumes the weight's
//! low region is as wide as a nearly flat gap (a gap curvature of 1e-3 1/mm)
//! makes it, clipped to the profile, and counts every spline knot in it.

use crate::pipeline::{self, Stage};
use crate::quasi_elastic::Quadrature;
use crate::scene::Scene;
use crate::track::Placement;

/// The largest estimated work a run may take without `--allow-long` (gap evaluations):
/// 3e8, about 25 s on one core of the development machine, at most a minute on a slow one.
pub const WORK_BUDGET: f64 = 3e8;

/// The most bytes a run may write without `--allow-long`: 1e8 (100 MB). The tables grow
/// with the sweep (a 100,001-position sweep with every figure writes 115 MB of CSV); the
/// charts do not (they are drawn at their resolution).
pub const WRITE_BUDGET_BYTES: f64 = 1e8;

/// Bytes of one value in a CSV row: 10 significant digits in scientific form with sign,
/// exponent and separator are 13 to 17 (`-1.234567890e-10,`); a status column counts alike.
const CSV_BYTES_PER_VALUE: f64 = 15.0;
/// Values per row of the tables that have one row per position (`outputs::tables`: the
/// column counts of `rigid.csv`, `quasi_elastic.csv`, `hertz.csv`; `qe_epsilon.csv` has
/// 4 plus 2 per value of eps). The counts are upper ones, so the estimate errs high
/// (`crates/cli/tests/robustness.rs` holds it above what a long sweep writes, by less than a third).
const RIGID_VALUES: f64 = 30.0;
const QUASI_ELASTIC_VALUES: f64 = 25.0;
const HERTZ_VALUES: f64 = 17.0;
/// Bytes of the files that do not grow with the sweep: up to four profile tables (90 kB
/// each at most), the conicity and accuracy tables, the page.
const FIXED_BYTES: f64 = 5e5;
/// Bytes of one figure in one format: a PNG of the default size is about 90 kB, an SVG
/// drawn at its resolution mostly less (the contact map of quasi-elastic patches over
/// 100,001 positions, the largest, 680 kB).
const IMAGE_BYTES: f64 = 2e5;

/// Gap evaluations per position and wheel of the default rigid solver, an estimate that
/// errs high: a position takes a coarse scan of cheap samples and a few exact gaps, and the
/// jump refinement solves a few positions more per jump (`examples/evaluation_counts.rs`
/// counts them for a scene).
const RIGID_DEFAULT_PER_WHEEL: f64 = 100.0;
/// The paper's rigid iteration per position, in units of the default solver's work: it
/// restarts from roll 0 at every position, converges linearly and searches the whole
/// tabulated wheel at every step (the benchmarks `rigid_paper` and
/// `rigid_default_unmirrored` compare the two).
const RIGID_PAPER_FACTOR: f64 = 27.0;
/// Gap curvature of a nearly flat contact (1/mm) that sizes the low region of the weight:
/// the tread of a 460 mm wheel on a 300 mm rail crown gives 1.2e-3; worn, conformal
/// contacts lower, which the clip to the profile's width covers.
pub(crate) const FLAT_GAP_CURVATURE_PER_MM: f64 = 1e-3;
/// Nodes of a Gauss-Legendre panel (8 points, both halves of a piece).
const GAUSS_NODES_PER_PANEL: f64 = 16.0;
/// One conicity amplitude walks every piece of the Δr function, a few operations each: this
/// many pieces cost about one gap evaluation.
const CONICITY_PIECES_PER_EVALUATION: f64 = 25.0;

/// The estimated work of a scene, the bytes it will write and what drives them.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// Estimated gap evaluations.
    pub evaluations: f64,
    /// Estimated bytes of the files a report of the scene writes (tables, figures, page).
    pub bytes: f64,
    /// The scene keys that drive the estimate, with their values as text, largest factor
    /// first.
    pub drivers: Vec<(&'static str, String)>,
}

impl Estimate {
    /// Whether the estimate is within [`WORK_BUDGET`] and [`WRITE_BUDGET_BYTES`].
    pub fn within_budget(&self) -> bool {
        self.within_work_budget() && self.bytes <= WRITE_BUDGET_BYTES
    }

    /// Whether the estimated work is within [`WORK_BUDGET`] (a run that writes no report of
    /// the scene, such as a fleet's row, counts no bytes).
    pub fn within_work_budget(&self) -> bool {
        self.evaluations <= WORK_BUDGET
    }

    /// One line for messages: the estimates, the budgets and the keys that drive them.
    pub fn describe(&self) -> String {
        let drivers: Vec<String> = self
            .drivers
            .iter()
            .map(|(k, v)| format!("{k} = {v}"))
            .collect();
        format!(
            "estimated {:.2e} gap evaluations (budget {WORK_BUDGET:.0e}, about 25 s on one core) and {:.0} MB of files (budget {:.0} MB), driven by {}",
            self.evaluations,
            (self.bytes / 1e6).ceil(),
            WRITE_BUDGET_BYTES / 1e6,
            drivers.join(", ")
        )
    }
}

/// Estimates the work of `scene`: positions × wheels × (rigid iterations + quadrature
/// nodes of every quasi-elastic pass) + the conicity's amplitudes × pieces; and the bytes
/// of its report: positions × the values of its per-position tables, the fixed tables,
/// and each figure in each format. The profiles
/// come from the run's own `placement` (the profile stage, which every run does first), so
/// that the knots of splines are counted without reading the files again.
///
/// # Example
/// ```
/// use wheelrail::{cost, pipeline, scene::Scene};
/// let scene = Scene::from_toml("", "doc", ".".as_ref()).unwrap(); // the paper's case
/// let estimate = cost::estimate(&scene, &pipeline::place(&scene).unwrap());
/// assert!(estimate.within_budget(), "{}", estimate.describe());
/// ```
pub fn estimate(scene: &Scene, placement: &Placement) -> Estimate {
    let stages = pipeline::needed_stages(scene);
    let positions = scene.sweep.len() as f64;
    let mut drivers: Vec<(&'static str, String)> = Vec::new();
    let images = (scene.figures.len() * scene.formats.len()) as f64;
    let bytes = written_bytes(scene, &stages) + images * IMAGE_BYTES;
    let rigid = match scene.rigid_solver {
        crate::rigid::Solver::Paper => RIGID_PAPER_FACTOR * RIGID_DEFAULT_PER_WHEEL,
        _ => RIGID_DEFAULT_PER_WHEEL,
    };
    let table = contact_table_work(scene, &stages, rigid, &mut drivers);
    if !stages.contains(&Stage::Rigid) {
        return Estimate {
            evaluations: table,
            bytes,
            drivers,
        };
    }
    drivers.push(("sweep.step_mm", format!("{} positions", scene.sweep.len())));
    if matches!(scene.rigid_solver, crate::rigid::Solver::Paper) {
        drivers.push(("rigid.solver", "\"paper\"".into()));
    }
    let per_wheel = with_quasi_elastic_work(rigid, scene, &stages, placement, &mut drivers);
    let mut evaluations = 2.0 * positions * per_wheel + table;
    if stages.contains(&Stage::EquivalentConicity) {
        let amplitudes = scene.conicity.amplitudes_mm.as_ref().map_or(96, Vec::len) as f64;
        evaluations += amplitudes * positions / CONICITY_PIECES_PER_EVALUATION;
        if scene.conicity.amplitudes_mm.is_some() {
            drivers.push(("conicity.amplitudes_mm", format!("{amplitudes} amplitudes")));
        }
    }
    if images * IMAGE_BYTES > 0.1 * bytes {
        drivers.push((
            "outputs.figures",
            format!(
                "{} figures in {} formats",
                scene.figures.len(),
                scene.formats.len()
            ),
        ));
    }
    Estimate {
        evaluations,
        bytes,
        drivers,
    }
}

/// The work of the contact table when `stages` compute it: one rigid sweep of both wheels
/// per yaw of its grid, `rigid` evaluations per position and wheel.
fn contact_table_work(
    scene: &Scene,
    stages: &[Stage],
    rigid: f64,
    drivers: &mut Vec<(&'static str, String)>,
) -> f64 {
    match (&scene.contact_table, stages.contains(&Stage::ContactTable)) {
        (Some(grid), true) => {
            let nodes = grid.shifts().len() * grid.yaws_rad().len();
            drivers.push((
                "table.step_mm, table.yaw_step_mrad",
                format!("{nodes} shift x yaw nodes"),
            ));
            2.0 * nodes as f64 * rigid
        }
        _ => 0.0,
    }
}

/// `per_wheel` (the rigid work of a position and wheel) with the quadrature nodes of every
/// quasi-elastic pass that `stages` run added: the quasi-elastic stage's eps, then each of
/// the sensitivity's.
fn with_quasi_elastic_work(
    mut per_wheel: f64,
    scene: &Scene,
    stages: &[Stage],
    placement: &Placement,
    drivers: &mut Vec<(&'static str, String)>,
) -> f64 {
    let mut passes: Vec<f64> = Vec::new();
    if stages.contains(&Stage::QuasiElastic) {
        passes.push(scene.quasi_elastic.epsilon_mm);
    }
    if stages.contains(&Stage::EpsilonSensitivity) {
        passes.extend(&scene.epsilon_sensitivity_mm);
        drivers.push((
            "quasi_elastic.sensitivity_epsilon_mm",
            format!("{} values", scene.epsilon_sensitivity_mm.len()),
        ));
    }
    if passes.is_empty() {
        return per_wheel;
    }
    let (width_mm, breaks_per_mm) = break_density(placement);
    let qe = &scene.quasi_elastic;
    for eps in passes {
        per_wheel += quadrature_nodes(qe.quadrature, qe.cutoff, eps, width_mm, breaks_per_mm);
    }
    drivers.push(("quasi_elastic.cutoff", format!("{}", qe.cutoff)));
    match qe.quadrature {
        Quadrature::GaussLegendre { panel_widths } => {
            drivers.push(("quasi_elastic.panel_widths", format!("{panel_widths}")));
        }
        Quadrature::Trapezoid { max_step_mm } => {
            drivers.push(("quasi_elastic.max_step_mm", format!("{max_step_mm}")));
        }
    }
    if breaks_per_mm > 1.0 {
        drivers.push((
            "wheel.profile, rail.profile",
            format!("{breaks_per_mm:.1} spline knots per mm"),
        ));
    }
    per_wheel
}

/// Bytes of the tables of a run of `stages`, and its page.
fn written_bytes(scene: &Scene, stages: &[Stage]) -> f64 {
    let mut values = 0.0;
    if stages.contains(&Stage::Rigid) {
        values += RIGID_VALUES;
    }
    if stages.contains(&Stage::QuasiElastic) {
        values += QUASI_ELASTIC_VALUES;
    }
    if stages.contains(&Stage::Hertz) {
        values += HERTZ_VALUES;
    }
    if stages.contains(&Stage::EpsilonSensitivity) {
        values += 4.0 + 2.0 * scene.epsilon_sensitivity_mm.len() as f64;
    }
    FIXED_BYTES + scene.sweep().len() as f64 * values * CSV_BYTES_PER_VALUE
}

/// Quadrature nodes of one quasi-elastic pass, one wheel, one position.
fn quadrature_nodes(
    quadrature: Quadrature,
    cutoff: f64,
    eps: f64,
    profile_width_mm: f64,
    breaks_per_mm: f64,
) -> f64 {
    let k = FLAT_GAP_CURVATURE_PER_MM;
    // The gap rises by cutoff * eps over sqrt(2 cutoff eps / k) either side of its minimum.
    let region = (2.0 * (2.0 * cutoff * eps / k).sqrt()).min(profile_width_mm);
    let width = (eps / k).sqrt();
    match quadrature {
        Quadrature::GaussLegendre { panel_widths } => {
            // Panels of panel_widths widths, and a 4-point piece between neighbouring breaks.
            GAUSS_NODES_PER_PANEL * (region / (panel_widths * width)).ceil()
                + 8.0 * breaks_per_mm * region
        }
        Quadrature::Trapezoid { max_step_mm } => {
            // The trapezoid variant's own step rule (`quasi_elastic::average`).
            let wanted = (width / crate::quasi_elastic::TRAPEZOID_STEPS_PER_WIDTH)
                .max(crate::quasi_elastic::MIN_STEP_MM);
            let step = max_step_mm
                .min(wanted)
                .max(crate::quasi_elastic::MIN_STEP_MM / 2.0);
            region / step
        }
    }
}

/// The widest profile domain of the placement (mm) and the largest density of breaks
/// (section joints or spline knots) per mm of its wheel and rail profiles together.
fn break_density(placement: &Placement) -> (f64, f64) {
    let mut width: f64 = 0.0;
    let mut density = [0.0_f64; 2];
    for pair in [&placement.left, &placement.right] {
        for (k, p) in [pair.wheel.profile(), pair.rail.profile()]
            .into_iter()
            .enumerate()
        {
            let (lo, hi) = p.domain();
            let w = (hi - lo).max(1.0);
            width = width.max(w);
            density[k] = density[k].max(p.breaks().len() as f64 / w);
        }
    }
    (width, density[0] + density[1])
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    fn scene(text: &str) -> Scene {
        Scene::from_toml(text, "test.toml", Path::new(".")).unwrap()
    }

    /// The estimate of a scene given as TOML text, with its own placement.
    fn estimate_of(text: &str) -> Estimate {
        let s = scene(text);
        estimate(&s, &pipeline::place(&s).unwrap())
    }

    #[test]
    fn the_paper_scene_is_far_within_the_budget() {
        let e = estimate_of("");
        // 301 positions, 1 + 5 passes of about 40 nodes: about 2e5 evaluations.
        assert!(e.evaluations < 1e-2 * WORK_BUDGET, "{}", e.describe());
    }

    #[test]
    fn a_fine_trapezoid_with_a_large_cutoff_is_refused_naming_its_keys() {
        let e = estimate_of(
            "[quasi_elastic]\nquadrature = \"trapezoid\"\nmax_step_mm = 0.0001\ncutoff = 700.0\n\
             [outputs]\nfigures = [\"qe_contact_points\"]",
        );
        assert!(!e.within_budget(), "{}", e.describe());
        let text = e.describe();
        assert!(
            text.contains("quasi_elastic.max_step_mm") && text.contains("quasi_elastic.cutoff"),
            "{text}"
        );
    }

    /// A contact table of 401 yaws by 20001 shifts is eight million rigid positions: refused,
    /// naming its keys, even where no figure asks for a contact search.
    #[test]
    fn a_huge_contact_table_is_refused_naming_its_keys() {
        let e = estimate_of(
            "[table]\nfrom_mm = -10.0\nto_mm = 10.0\nstep_mm = 0.001\n\
             yaw_from_mrad = -20.0\nyaw_to_mrad = 20.0\nyaw_step_mrad = 0.1\n\
             [outputs]\nfigures = [\"profiles\"]",
        );
        assert!(!e.within_budget(), "{}", e.describe());
        assert!(
            e.describe().contains("table.yaw_step_mrad"),
            "{}",
            e.describe()
        );
    }

    #[test]
    fn profiles_only_cost_nothing() {
        let e = estimate_of("[outputs]\nfigures = [\"profiles\"]");
        assert!(e.evaluations.abs() < 1e-300 && e.within_budget());
    }
}
