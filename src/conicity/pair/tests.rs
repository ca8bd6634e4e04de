use super::*;
use crate::rigid::{Solver, search};
use crate::scene::Scene;

/// A fleet's summary (one method) and the stage agree to the last digit.
#[test]
fn one_method_gives_the_stages_values() {
    let scene = Scene::from_toml(
        "[sweep]\nfrom_mm = -8.0\nto_mm = 8.0\nstep_mm = 0.2",
        "t",
        ".".as_ref(),
    )
    .unwrap();
    let placement = crate::pipeline::place(&scene).unwrap();
    let sweep = search(&placement, &scene.sweep, Solver::default());
    for method in [ConicityMethod::Klingel, ConicityMethod::Regression] {
        let settings = ConicitySettings {
            method,
            amplitudes_mm: None,
        };
        let whole = assess_on(&placement, &sweep, &settings);
        let (function, parameters) = assess_by_method_on(&placement, &sweep, &settings);
        assert_eq!(parameters, whole.parameters);
        assert_eq!(function.points.len(), whole.by(method).points.len());
        for (a, b) in function.points.iter().zip(&whole.by(method).points) {
            assert_eq!(a.tan_gamma_e.to_bits(), b.tan_gamma_e.to_bits());
        }
    }
}

/// An off-centre pair (radii 460 and 459.5 mm: equilibrium at -0.53 mm) swept only
/// from -3 to 3 mm: `assess_on` asks the rigid search for the shifts its motions need
/// and gives every amplitude up to 7.5 mm by both methods, as a sweep from -15 to 15 mm
/// gives them (within 2e-11, twice the 9.9e-12 measured: the positions beyond 3 mm are
/// continued from the sweep's ends instead of from the centre, and solved to the roll
/// solver's residual of 1e-11 mm), and `assess` on the narrow sweep leaves them out.
#[test]
fn an_off_centre_pair_gets_every_amplitude_from_a_narrow_sweep() {
    let scene = |from: f64| {
        Scene::from_toml(
            &format!(
                "[wheel]\nleft_nominal_radius_mm = 460.0\nright_nominal_radius_mm = 459.5\n[sweep]\nfrom_mm = {from}\nto_mm = {}\nstep_mm = 0.1",
                -from
            ),
            "t",
            ".".as_ref(),
        )
        .unwrap()
    };
    let (narrow, wide) = (scene(-3.0), scene(-15.0));
    let placement = crate::pipeline::place(&narrow).unwrap();
    let settings = ConicitySettings::default();
    let short = search(&placement, &narrow.sweep, Solver::default());
    let long = search(&placement, &wide.sweep, Solver::default());
    let reached = assess_on(&placement, &short, &settings);
    let reference = assess(&long, &settings);
    assert!(assess(&short, &settings).klingel.at(7.5).is_none());
    assert!(
        reached.parameters.equilibrium_mm < -0.3,
        "{:?}",
        reached.parameters
    );
    for method in ConicityMethod::ALL {
        for p in &reference.by(method).points {
            if p.amplitude_mm > STANDARD_MAX_AMPLITUDE_MM + 1e-9 {
                continue;
            }
            let got = reached.by(method).at(p.amplitude_mm).unwrap();
            assert!(
                (got - p.tan_gamma_e).abs() < 2e-11,
                "{method:?} at {}: {got} vs {}",
                p.amplitude_mm,
                p.tan_gamma_e
            );
        }
    }
    // The parameters that describe the sweep are the narrow sweep's own.
    assert_eq!(
        reached.parameters.contact_point_jumps + reached.parameters.sampling_artefacts,
        short.jumps().len()
    );
}
