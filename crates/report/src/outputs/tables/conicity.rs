//! The equivalent conicity tables (EN 15302): `equivalent_conicity.csv`, `parameters.csv`
//! and the table `wheelrail conicity` prints.

use crate::{Table, TableError};
use wheelrail::conicity::ParameterRow;

/// Definition lines shared by the conicity tables.
const CONICITY_FRAME: &str = "y lateral displacement of the wheelset, positive to the left (track frame); delta_r = r_left - r_right; amplitude = half the peak-to-peak motion; centre_mm = middle of the motion (the equilibrium for a symmetric pair)";

/// The equivalent conicity of one method over its amplitudes, as printed by `wheelrail
/// conicity` (`source` names the Δr table).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn conicity_points(
    c: &wheelrail::conicity::EquivalentConicity,
    source: &str,
) -> Result<Table, TableError> {
    let p = &c.points;
    Table::builder()
        .comment(format!(
            "equivalent conicity tan_gamma_e (EN 15302), method {}, from {source}",
            conicity_method_text(c.method)
        ))
        .comment(CONICITY_FRAME)
        .comment(format!(
            "equilibrium (delta_r = 0) at y = {:.6} mm; largest amplitude the delta_r function supports: {:.6} mm",
            c.equilibrium_mm, c.max_amplitude_mm
        ))
        .numeric("amplitude_mm", p.iter().map(|p| p.amplitude_mm).collect::<Vec<_>>())
        .numeric("tan_gamma_e", p.iter().map(|p| p.tan_gamma_e).collect::<Vec<_>>())
        .numeric("centre_mm", p.iter().map(|p| p.centre_mm).collect::<Vec<_>>())
        .text("status", p.iter().map(|p| p.status.name()))
        .build()
}

/// What each method is, for table headers.
pub fn conicity_method_text(m: wheelrail::conicity::ConicityMethod) -> &'static str {
    match m {
        wheelrail::conicity::ConicityMethod::Klingel => {
            "klingel (EN 15302 Annex B: wavelength of the nonlinear kinematic motion, closed-form integral)"
        }
        wheelrail::conicity::ConicityMethod::Regression => {
            "regression (EN 15302 Annex C: least-squares line through delta_r over the motion, weighted as a harmonic motion)"
        }
    }
}

/// The equivalent conicity function of a pair by both methods (`equivalent_conicity.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn equivalent_conicity(c: &wheelrail::conicity::PairConicity) -> Result<Table, TableError> {
    use wheelrail::conicity::ConicityMethod;
    let k = &c.klingel.points;
    let r = &c.regression.points;
    Table::builder()
        .comment("equivalent conicity tan_gamma_e (EN 15302) of the rigid delta_r function, by both methods; NaN with a status where not computable")
        .comment(format!("tan_gamma_e_klingel: {}", conicity_method_text(ConicityMethod::Klingel)))
        .comment(format!("tan_gamma_e_regression: {}", conicity_method_text(ConicityMethod::Regression)))
        .comment(CONICITY_FRAME)
        .comment(format!(
            "equilibrium (delta_r = 0) at y = {:.6} mm; largest amplitude supported: {:.6} mm (klingel), {:.6} mm (regression)",
            c.klingel.equilibrium_mm, c.klingel.max_amplitude_mm, c.regression.max_amplitude_mm
        ))
        .numeric("amplitude_mm", k.iter().map(|p| p.amplitude_mm).collect::<Vec<_>>())
        .numeric("tan_gamma_e_klingel", k.iter().map(|p| p.tan_gamma_e).collect::<Vec<_>>())
        .numeric("tan_gamma_e_regression", r.iter().map(|p| p.tan_gamma_e).collect::<Vec<_>>())
        .numeric("centre_mm", k.iter().map(|p| p.centre_mm).collect::<Vec<_>>())
        .text("status_klingel", k.iter().map(|p| p.status.name()))
        .text("status_regression", r.iter().map(|p| p.status.name()))
        .build()
}

/// The parameters of the pair (`parameters.csv`): one row each, with unit and definition.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn parameters(p: &wheelrail::conicity::Parameters) -> Result<Table, TableError> {
    let rows = p.rows();
    Table::builder()
        .comment("parameters of the wheel/rail pair from its rigid sweep; NaN where undefined (e.g. flange contact beyond the sweep), with the reason in status")
        .comment(CONICITY_FRAME)
        .text("parameter", rows.iter().map(|r| r.name))
        .numeric("value", rows.iter().map(|r| r.value).collect::<Vec<_>>())
        .text("unit", rows.iter().map(|r| r.unit))
        .text("definition", rows.iter().map(|r| r.definition.clone()))
        .text("status", rows.iter().map(ParameterRow::status))
        .build()
}
