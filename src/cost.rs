//! The work a scene asks for, estimated from its keys and profiles before anything runs,
//! and the budget above which a run needs `--allow-long`.
//!
//! The unit of work is one evaluation of the gap between a wheel point and its rail (about
//! 80 ns on the development machine, one core: the quasi-elastic pass runs 12 million nodes
//! per second). The estimate is deliberately coarse and errs high: it assumes the weight's
//! low region is as wide as a nearly flat gap (curvature [`FLAT_GAP_CURVATURE_PER_MM`])
//! makes it, clipped to the profile, and counts every spline knot in it.

use crate::pipeline::{self, Stage};
use crate::quasi_elastic::Quadrature;
use crate::scene::Scene;
use crate::track::Placement;

/// The largest estimated work a run may take without `--allow-long` (gap evaluations):
/// 3e8, about 25 s on one core of the development machine, at most a minute on a slow one.
pub const WORK_BUDGET: f64 = 3e8;

/// Gap evaluations per position and wheel of the default rigid solver: 8 µs per position
/// (README, Speed) is about 100 evaluations, with margin for the jump refinement.
const RIGID_DEFAULT_PER_WHEEL: f64 = 100.0;
/// The paper's rigid iteration takes 27 times the default (README, Speed).
const RIGID_PAPER_FACTOR: f64 = 27.0;
/// Gap curvature of a nearly flat contact (1/mm) that sizes the low region of the weight:
/// the tread of a 460 mm wheel on a 300 mm rail crown gives 1.2e-3; worn, conformal
/// contacts lower, which the clip to the profile's width covers.
pub const FLAT_GAP_CURVATURE_PER_MM: f64 = 1e-3;
/// Nodes of a Gauss-Legendre panel (8 points, both halves of a piece).
const GAUSS_NODES_PER_PANEL: f64 = 16.0;
/// One conicity amplitude walks every piece of the Δr function at about 3 ns: this many
/// pieces cost one gap evaluation.
const CONICITY_PIECES_PER_EVALUATION: f64 = 25.0;

/// The estimated work of a scene and what drives it.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// Estimated gap evaluations.
    pub evaluations: f64,
    /// The scene keys that drive the estimate, with their values as text, largest factor
    /// first.
    pub drivers: Vec<(&'static str, String)>,
}

impl Estimate {
    /// Whether the estimate is within [`WORK_BUDGET`].
    pub fn within_budget(&self) -> bool {
        self.evaluations <= WORK_BUDGET
    }

    /// One line for messages: the estimate, the budget and the keys that drive it.
    pub fn describe(&self) -> String {
        let drivers: Vec<String> = self
            .drivers
            .iter()
            .map(|(k, v)| format!("{k} = {v}"))
            .collect();
        format!(
            "estimated {:.2e} gap evaluations (budget {WORK_BUDGET:.0e}, about 25 s on one core), driven by {}",
            self.evaluations,
            drivers.join(", ")
        )
    }
}

/// Estimates the work of `scene`: positions × wheels × (rigid iterations + quadrature
/// nodes of every quasi-elastic pass) + the conicity's amplitudes × pieces. The profiles
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
    let rigid = match scene.rigid_solver {
        crate::rigid::Solver::Paper => RIGID_PAPER_FACTOR * RIGID_DEFAULT_PER_WHEEL,
        _ => RIGID_DEFAULT_PER_WHEEL,
    };
    // The contact table: one rigid sweep of both wheels per yaw of its grid.
    let table = match (&scene.contact_table, stages.contains(&Stage::ContactTable)) {
        (Some(grid), true) => {
            let nodes = grid.shifts().len() * grid.yaws_rad().len();
            drivers.push((
                "table.step_mm, table.yaw_step_mrad",
                format!("{nodes} shift x yaw nodes"),
            ));
            2.0 * nodes as f64 * rigid
        }
        _ => 0.0,
    };
    if !stages.contains(&Stage::Rigid) {
        return Estimate {
            evaluations: table,
            drivers,
        };
    }
    drivers.push(("sweep.step_mm", format!("{} positions", scene.sweep.len())));
    if matches!(scene.rigid_solver, crate::rigid::Solver::Paper) {
        drivers.push(("rigid.solver", "\"paper\"".into()));
    }
    let mut per_wheel = rigid;

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
    if !passes.is_empty() {
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
    }
    let mut evaluations = 2.0 * positions * per_wheel + table;
    if stages.contains(&Stage::EquivalentConicity) {
        let amplitudes = scene.conicity.amplitudes_mm.as_ref().map_or(96, Vec::len) as f64;
        evaluations += amplitudes * positions / CONICITY_PIECES_PER_EVALUATION;
        if scene.conicity.amplitudes_mm.is_some() {
            drivers.push(("conicity.amplitudes_mm", format!("{amplitudes} amplitudes")));
        }
    }
    Estimate {
        evaluations,
        drivers,
    }
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
