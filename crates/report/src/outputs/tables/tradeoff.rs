//! The tables of `wheelrail tradeoff`: run time against error of the scene's settings
//! (`tradeoff.csv`) and of FASTSIM's grids (`fastsim_tradeoff.csv`).

use crate::{Table, TableError};

/// The run time against error study (`tradeoff.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn tradeoff(m: &[crate::tradeoff::Measurement]) -> Result<Table, TableError> {
    let col =
        |f: &dyn Fn(&crate::tradeoff::Measurement) -> f64| m.iter().map(f).collect::<Vec<_>>();
    Table::builder()
        .comment("run time against error: the scene's pipeline (placement, rigid, quasi-elastic, Hertz; no rendering) per setting, single-threaded")
        .comment("errors against the reference (analytic profiles, default solver, Gauss-Legendre panels of half a weight width, cut-off exp(-60), exact Hertz), max over the sweep and both wheels; contact_mm excludes positions within one step of a reference jump; qe_location_mm is weight-averaged over the patches")
        .comment("median_ms, min_ms, max_ms over the timed rounds: after an untimed warm-up round, each round runs every setting once in its own random order")
        .comment("times are machine-dependent: compare settings as ratios within one run")
        .text("setting", m.iter().map(|x| x.setting.label.clone()))
        .numeric("profile_step_mm", col(&|x| x.setting.profile_step_mm.unwrap_or(f64::NAN)))
        .text("rigid_solver", m.iter().map(|x| x.setting.solver.name()))
        .text("qe_quadrature", m.iter().map(|x| x.setting.quasi_elastic.quadrature().name()))
        .numeric("qe_cutoff", col(&|x| x.setting.quasi_elastic.cutoff()))
        .text("hertz_method", m.iter().map(|x| x.setting.hertz.to_string()))
        .numeric("median_ms", col(&|x| 1e3 * x.median_s))
        .numeric("min_ms", col(&|x| 1e3 * x.range_s.0))
        .numeric("max_ms", col(&|x| 1e3 * x.range_s.1))
        .numeric("contact_error_mm", col(&|x| x.errors.contact_mm))
        .numeric("qe_location_error_mm", col(&|x| x.errors.qe_location_mm))
        .numeric("roll_error_rad", col(&|x| x.errors.roll_rad))
        .numeric("a_rel_error", col(&|x| x.errors.a_rel))
        .numeric("b_rel_error", col(&|x| x.errors.b_rel))
        .numeric("p0_rel_error", col(&|x| x.errors.p0_rel))
        .text(
            "status",
            m.iter().map(|x| match x.setting.profile_step_mm {
                Some(_) => "ok",
                None => "analytic profiles: no profile_step_mm (NaN)",
            }),
        )
        .build()
}

/// FASTSIM's discretisation study (`fastsim_tradeoff.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn fastsim_tradeoff(
    m: &[crate::tradeoff::fastsim::GridMeasurement],
) -> Result<Table, TableError> {
    use crate::tradeoff::fastsim::{PASSES, label};
    use wheelrail::creep::fastsim::{STUDY_REFERENCE, study_cases};
    let col = |f: &dyn Fn(&crate::tradeoff::fastsim::GridMeasurement) -> f64| {
        m.iter().map(f).collect::<Vec<_>>()
    };
    let cases = study_cases();
    let mut patches: Vec<String> = Vec::new();
    for (p, _) in &cases {
        let text = format!(
            "a = {}, b = {} mm at FN = {} kN",
            p.a_mm(),
            p.b_mm(),
            1e-3 * p.normal_force_n()
        );
        if !patches.contains(&text) {
            patches.push(text);
        }
    }
    let defaults = wheelrail::creep::Settings::default();
    let cases = cases.len();
    Table::builder()
        .comment("run time against error of FASTSIM's discretisation: grid = strips across the patch (lateral) x elements along each strip (rolling direction); the default grid is marked (default)")
        .comment(format!(
            "errors against the reference grid {}x{} with the same settings otherwise (the default: parabolic bound, blended flexibilities, midpoint scheme, mu = {}, G = {} GPa, nu = {}), the largest over the {cases} cases of creep::fastsim::study_cases: patches {}; creepages of 0.3, 1 and 3 times the creepage that saturates linear theory in xi, eta, phi alone and all three at once",
            STUDY_REFERENCE.strips,
            STUDY_REFERENCE.elements,
            defaults.friction(),
            1e-3 * defaults.shear_modulus_mpa(),
            defaults.poisson(),
            patches.join(" and ")
        ))
        .comment("force_error = max(|dFx|, |dFy|) / (mu FN); moment_error = |dMz| / (mu FN c), c = sqrt(a b): both dimensionless")
        .comment(format!(
            "median_us, min_us, max_us: one patch's FASTSIM solve (microseconds), single-threaded; each timed run solves the {cases} cases {PASSES} times; after an untimed warm-up round, each round runs every grid once in its own random order"
        ))
        .comment("times are machine-dependent: compare grids as ratios within one run")
        .text("grid", m.iter().map(|x| label(x.grid)))
        .numeric("strips", col(&|x| f64::from(x.grid.strips)))
        .numeric("elements", col(&|x| f64::from(x.grid.elements)))
        .numeric("median_us", col(&|x| 1e6 * x.timing.median_s))
        .numeric("min_us", col(&|x| 1e6 * x.timing.range_s.0))
        .numeric("max_us", col(&|x| 1e6 * x.timing.range_s.1))
        .numeric("force_error", col(&|x| x.force_error))
        .numeric("moment_error", col(&|x| x.moment_error))
        .text(
            "status",
            m.iter().map(|x| {
                if x.force_error.is_finite() && x.moment_error.is_finite() {
                    "ok"
                } else {
                    "grid out of range: not solved (NaN)"
                }
            }),
        )
        .build()
}
