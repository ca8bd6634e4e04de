//! Figures of the equivalent conicity stage (EN 15302).

use super::{Line, RIGID, SHIFT};
use crate::{Chart, Figure, LegendPosition, Series};

/// The equivalent conicity function by both methods, `tan γe(3 mm)` marked (EN 15302).
pub(crate) fn equivalent_conicity(c: &wheelrail::conicity::PairConicity) -> Figure {
    use wheelrail::conicity::ConicityMethod;
    const REFERENCE_AMPLITUDE_MM: f64 = wheelrail::conicity::Parameters::REFERENCE_AMPLITUDE_MM;
    let series = |m: ConicityMethod| -> Line {
        c.by(m)
            .points
            .iter()
            .map(|p| (p.amplitude_mm, p.tan_gamma_e))
            .collect()
    };
    let method = c.parameters.method;
    let at3 = c.parameters.tan_gamma_e_3mm;
    let mut chart = Chart::new(
        "Equivalent conicity (EN 15302)",
        "amplitude of the kinematic motion ŷ (mm)",
        "equivalent conicity tan γe",
    )
    .series(
        Series::line(
            "Klingel wavelength (Annex B)",
            series(ConicityMethod::Klingel),
        )
        .color(0),
    )
    .series(
        Series::line(
            "regression of Δr (Annex C)",
            series(ConicityMethod::Regression),
        )
        .color(1)
        .dashed(),
    );
    if at3.is_finite() {
        chart = chart
            .series(
                Series::markers(
                    format!("tan γe(3 mm) = {at3:.3} ({})", method.name()),
                    vec![(REFERENCE_AMPLITUDE_MM, at3)],
                )
                .color(2),
            )
            .vline(REFERENCE_AMPLITUDE_MM, "ŷ = 3 mm");
    }
    Figure::single(chart.legend(LegendPosition::Auto))
}

/// Δr of the rigid sweep with the linear function of the equivalent cone at ŷ = 3 mm,
/// `2 tan γe(3 mm) (y - y_eq)`, over the motion `y_eq ± 3 mm`.
pub(crate) fn delta_r_linearised(c: &wheelrail::conicity::PairConicity) -> Figure {
    const REFERENCE_AMPLITUDE_MM: f64 = wheelrail::conicity::Parameters::REFERENCE_AMPLITUDE_MM;
    let p = &c.parameters;
    let eq = if p.equilibrium_mm.is_finite() {
        p.equilibrium_mm
    } else {
        0.0
    };
    let a = REFERENCE_AMPLITUDE_MM;
    // The window: twice the motion, scaled to Δr within it (flange contact beyond would
    // flatten the part that matters).
    let (x_lo, x_hi) = (eq - 2.2 * a, eq + 2.2 * a);
    let within: Line = c
        .delta_r
        .points()
        .filter(|(y, _)| *y >= x_lo && *y <= x_hi)
        .collect();
    let span = within
        .iter()
        .filter(|(y, _)| (y - eq).abs() <= 1.6 * a)
        .map(|(_, d)| d.abs())
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max)
        .max(1e-3);
    let tan = p.tan_gamma_e_3mm;
    let mut chart = Chart::new(
        "Rolling radius difference and its equivalent cone at ŷ = 3 mm",
        SHIFT,
        "Δr = r_left - r_right (mm)",
    )
    .x_range(x_lo, x_hi)
    .y_range(-1.25 * span, 1.25 * span)
    .series(Series::line("Δr (rigid)", within).color(RIGID));
    if tan.is_finite() {
        chart = chart.series(
            Series::line(
                format!("2 tan γe(3 mm) (y - y_eq), tan γe = {tan:.3}"),
                vec![(eq - a, -2.0 * tan * a), (eq + a, 2.0 * tan * a)],
            )
            .color(1)
            .dashed(),
        );
    }
    Figure::single(
        chart
            .vline(eq - a, "y_eq - 3 mm")
            .vline(eq + a, "y_eq + 3 mm")
            .legend(LegendPosition::LowerRight),
    )
}
