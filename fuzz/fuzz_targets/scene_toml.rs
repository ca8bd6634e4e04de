//! The scene parser on arbitrary text: `Scene::from_toml` returns, and a scene it accepts
//! has a non-empty increasing finite sweep and values within the documented ranges.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wheelrail::quasi_elastic::{Quadrature, QuasiElasticSettings as Qe};
use wheelrail::scene::Scene;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let Ok(scene) = Scene::from_toml(&text, "fuzz.toml", std::path::Path::new(".")) else {
        return;
    };
    let sweep = scene.sweep().shifts_mm();
    assert!(!sweep.is_empty());
    assert!(sweep.iter().all(|y| y.is_finite() && y.abs() <= 100.0));
    assert!(sweep.windows(2).all(|w| w[1] > w[0]));
    assert!(
        scene
            .nominal_radius_mm()
            .iter()
            .all(|r| (100.0..=1000.0).contains(r))
    );
    assert!(scene.wheel_load_n().is_finite() && scene.wheel_load_n() > 0.0);
    // The sensitivity values are distinct (each is a column of qe_epsilon.csv).
    let eps = scene.epsilon_sensitivity_mm();
    assert!(
        eps.iter()
            .enumerate()
            .all(|(i, e)| eps[..i].iter().all(|f| f.to_bits() != e.to_bits()))
    );
    let qe = scene.quasi_elastic();
    assert!((Qe::EPSILON_RANGE_MM.0..=Qe::EPSILON_RANGE_MM.1).contains(&qe.epsilon_mm()));
    assert!((Qe::CUTOFF_RANGE.0..=Qe::CUTOFF_RANGE.1).contains(&qe.cutoff()));
    match qe.quadrature() {
        Quadrature::GaussLegendre { panel_widths } => {
            assert!((Qe::PANEL_WIDTHS_RANGE.0..=Qe::PANEL_WIDTHS_RANGE.1).contains(&panel_widths));
        }
        Quadrature::Trapezoid { max_step_mm } => {
            assert!(
                (Qe::TRAPEZOID_STEP_RANGE_MM.0..=Qe::TRAPEZOID_STEP_RANGE_MM.1).contains(&max_step_mm)
            );
        }
    }
    let layout = scene.layout();
    assert!(layout.gauge_mm().is_finite() && layout.flange_back_mm() < layout.gauge_mm());
    assert!((0.0..=0.2).contains(&layout.inclination().radians()));
    // [fleet]: a limit, if any, within its documented range.
    assert!(
        scene
            .fleet()
            .conicity_limit()
            .is_none_or(|l| l > 0.0 && l <= 2.0)
    );
});
