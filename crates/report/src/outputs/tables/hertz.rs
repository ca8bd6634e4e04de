//! The Hertz tables: the ellipses over the sweep (`hertz.csv`) and the errors of the
//! paper's numerics (`hertz_accuracy_series.csv`, `hertz_accuracy_ratio.csv`).

use crate::{Table, TableError};
use wheelrail::hertz::accuracy::HertzAccuracy;
use wheelrail::track::Side;

/// Hertz ellipses over the sweep (`hertz.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn hertz(
    sweep: &wheelrail::hertz::HertzSweep,
    settings: &wheelrail::hertz::HertzSettings,
) -> Result<Table, TableError> {
    let h = sweep.positions();
    let mut t = Table::builder()
        .comment(format!(
            "Hertz contact ellipses, method {}, contact {}, normal load {}",
            settings.method(), sweep.source().name(), settings.normal_load().name()
        ))
        .comment("a_mm semi-axis along the rolling direction, b_mm lateral; p0_MPa maximum pressure; A, B relative curvatures (1/mm) in the rolling and lateral directions")
        .numeric("y_ws_mm", h.iter().map(|p| p.y_ws).collect::<Vec<_>>());
    for (k, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let name = side.name();
        let ell = |f: &dyn Fn(&wheelrail::hertz::Ellipse) -> f64| -> Vec<f64> {
            h.iter()
                .map(|p| p.sides[k].ellipse().map_or(f64::NAN, f))
                .collect()
        };
        t = t
            .numeric(format!("{name}_a_mm"), ell(&|e| e.a_mm))
            .numeric(format!("{name}_b_mm"), ell(&|e| e.b_mm))
            .numeric(format!("{name}_p0_MPa"), ell(&|e| e.p0_mpa))
            .numeric(format!("{name}_approach_mm"), ell(&|e| e.approach_mm))
            .numeric(
                format!("{name}_normal_load_N"),
                h.iter()
                    .map(|p| p.sides[k].normal_load_n)
                    .collect::<Vec<_>>(),
            )
            .numeric(
                format!("{name}_A_per_mm"),
                h.iter().map(|p| p.sides[k].a_curvature).collect::<Vec<_>>(),
            )
            .numeric(
                format!("{name}_B_per_mm"),
                h.iter().map(|p| p.sides[k].b_curvature).collect::<Vec<_>>(),
            )
            .text(
                format!("{name}_status"),
                h.iter().map(|p| p.sides[k].status.clone()),
            );
    }
    t.build()
}

/// Errors of the paper's Hertz numerics (`hertz_accuracy_series.csv`,
/// `hertz_accuracy_ratio.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn hertz_accuracy(a: &HertzAccuracy) -> Result<(Table, Table), TableError> {
    let series = Table::builder()
        .comment("relative error of the paper's truncated series (its Eqs. 15-18, terms summed until below 1e-3) against K and E by the AGM")
        .numeric("e", a.series.iter().map(|r| r.0).collect::<Vec<_>>())
        .numeric("K_rel_error", a.series.iter().map(|r| r.1).collect::<Vec<_>>())
        .numeric("E_rel_error", a.series.iter().map(|r| r.2).collect::<Vec<_>>())
        .build()?;
    let ratio = Table::builder()
        .comment("relative error of b/a from the paper's fixed-point iteration (from e = 0.5, |de| <= 1e-3) against the exact inversion")
        .numeric("A_over_B", a.ratio.iter().map(|r| r.0).collect::<Vec<_>>())
        .numeric("b_over_a_rel_error", a.ratio.iter().map(|r| r.1).collect::<Vec<_>>())
        .numeric("iterations", a.ratio.iter().map(|r| f64::from(r.2)).collect::<Vec<_>>())
        .build()?;
    Ok((series, ratio))
}
