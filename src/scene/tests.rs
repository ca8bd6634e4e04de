use super::*;

fn scene(text: &str) -> Result<Scene, SceneError> {
    Scene::from_toml(text, "test.toml", Path::new("."))
}

#[test]
fn defaults_are_the_paper_case() {
    let s = scene("").unwrap();
    let sweep = s.sweep.shifts_mm();
    assert_eq!(sweep.len(), 301);
    assert!(sweep[150].abs() < 1e-15 && (sweep[300] - 15.0).abs() < 1e-12);
    assert!((s.wheel_load_n - 70_000.0).abs() < 1e-9);
    assert!((s.wheel_material.young_mpa - 210_000.0).abs() < 1e-9);
    assert!(s.is_paper_case());
}

/// The paper's case: its physical keys at their defaults, written or not; the sweep and
/// the solvers free.
#[test]
fn the_paper_case_is_the_paper_geometry_load_and_material() {
    for same in [
        "[wheel]\nprofile = \"s1002\"\n[rail]\nprofile = \"60E1\"\ninclination = \"1:40\"",
        "[sweep]\nfrom_mm = -5.0\nto_mm = 5.0\n[rigid]\nsolver = \"paper\"",
        "[load]\nwheel_load_kN = 70.0\n[material]\npoisson = 0.3",
    ] {
        assert!(scene(same).unwrap().is_paper_case(), "{same}");
    }
    for other in [
        "[rail]\ninclination = \"1:20\"",
        "[wheel]\nright_nominal_radius_mm = 450.0",
        "[load]\nwheel_load_kN = 100.0",
        "[material]\nrail_poisson = 0.28",
        "[track]\ngauge_mm = 1000.0\n[wheelset]\nflange_back_mm = 920.0",
        "[wheel]\nprofile = \"tests/data/en15302/R-UIC519A.csv\"",
    ] {
        assert!(!scene(other).unwrap().is_paper_case(), "{other}");
    }
}

#[test]
fn errors_name_the_key() {
    let cases = [
        ("[track]\ngauge_mm = -1435.0", "track.gauge_mm"),
        ("[material]\npoisson = 0.5", "material.poisson"),
        ("[sweep]\nstep_mm = 0.0", "sweep.step_mm"),
        ("[sweep]\nfrom_mm = 5.0\nto_mm = 1.0", "sweep.to_mm"),
        (
            "[sweep]\nfrom_mm = -15.0\nto_mm = 15.0\nstep_mm = 1e-5",
            "sweep.step_mm",
        ),
        ("[load]\nwheel_load_kN = -70.0", "load.wheel_load_kN"),
        ("[rail]\ninclination = \"1:x\"", "rail.inclination"),
        ("[outputs]\nfigures = [\"nope\"]", "outputs.figures"),
        (
            "[quasi_elastic]\npanel_widths = 20.0",
            "quasi_elastic.panel_widths",
        ),
        (
            "[quasi_elastic]\npanel_widths = 0.01",
            "quasi_elastic.panel_widths",
        ),
        (
            "[quasi_elastic]\nquadrature = \"trapezoid\"\npanel_widths = 2.0",
            "quasi_elastic.panel_widths",
        ),
        (
            "[quasi_elastic]\nmax_step_mm = 0.05",
            "quasi_elastic.max_step_mm",
        ),
        // The bounds of the robustness checks, each naming the key as written.
        ("[material]\npoisson = -0.967", "material.poisson"),
        ("[material]\nrail_poisson = -0.1", "material.rail_poisson"),
        ("[material]\nyoung_GPa = 1e300", "material.young_GPa"),
        (
            "[material]\nwheel_young_GPa = 1e-300",
            "material.wheel_young_GPa",
        ),
        (
            "[wheel]\nnominal_radius_mm = 1e300",
            "wheel.nominal_radius_mm",
        ),
        (
            "[wheel]\nright_nominal_radius_mm = 50.0",
            "wheel.right_nominal_radius_mm",
        ),
        ("[track]\ngauge_mm = 1e300", "track.gauge_mm"),
        ("[load]\nwheel_load_kN = 5e-324", "load.wheel_load_kN"),
        (
            "[wheel]\nsmoothing_wavelength_mm = 1e300",
            "wheel.smoothing_wavelength_mm",
        ),
        ("[quasi_elastic]\ncutoff = 1.2e57", "quasi_elastic.cutoff"),
        ("[quasi_elastic]\ncutoff = 0.5", "quasi_elastic.cutoff"),
        (
            "[quasi_elastic]\nquadrature = \"trapezoid\"\nmax_step_mm = 1.7976931348623157e308",
            "quasi_elastic.max_step_mm",
        ),
        (
            "[quasi_elastic]\nsensitivity_epsilon_mm = [0.01, 0.01]",
            "quasi_elastic.sensitivity_epsilon_mm",
        ),
        (
            "[sweep]\nfrom_mm = 0.0\nto_mm = 1e-9\nstep_mm = 1e-10",
            "sweep.step_mm",
        ),
        ("[fleet]\nconicity_limit = 0.0", "fleet.conicity_limit"),
        ("[fleet]\nconicity_limit = -0.3", "fleet.conicity_limit"),
        ("[fleet]\nconicity_limit = nan", "fleet.conicity_limit"),
        ("[fleet]\nconicity_limit = 3.0", "fleet.conicity_limit"),
    ];
    for (text, key) in cases {
        let e = scene(text).unwrap_err().to_string();
        assert!(e.contains(key), "{text:?} gave {e}");
    }
}

#[test]
fn limit_errors_name_the_key() {
    let cases = [
        ("[limits]\nqr_min_mm = -1.0", "limits.qr_min_mm"),
        ("[limits]\nsh_max_mm = 1000.0", "limits.sh_max_mm"),
        ("[limits]\nsd_min_mm = nan", "limits.sd_min_mm"),
        // Above the standard's maximum of 33 mm.
        ("[limits]\nsd_min_mm = 34.0", "limits.sd_min_mm"),
        // Below the standard's minimum of 27.5 mm for a 920 mm wheel.
        ("[limits]\nsh_max_mm = 27.0", "limits.sh_max_mm"),
        (
            "[limits]\nsd_min_mm = 30.0\nsd_max_mm = 29.0",
            "limits.sd_min_mm",
        ),
    ];
    for (text, key) in cases {
        let e = scene(text).unwrap_err().to_string();
        assert!(e.contains(key), "{text:?} gave {e}");
    }
}

#[test]
fn the_fleet_limit_is_read() {
    let s = scene("[fleet]\nconicity_limit = 0.4").unwrap();
    assert_eq!(s.fleet.conicity_limit, Some(0.4));
    assert_eq!(scene("").unwrap().fleet.conicity_limit, None);
    let e = scene("[fleet]\nlimit = 0.4").unwrap_err().to_string();
    assert!(e.contains("limit") && e.contains("unknown field"), "{e}");
}

/// `[limits]` overrides the standard's limits one by one, each saying it came from the
/// scene; `rail.nominal_profile` names the nominal rail of both sides.
#[test]
fn limits_and_the_nominal_rail_are_read() {
    let s = scene("[limits]\nsd_min_mm = 24.5\n[rail]\nnominal_profile = \"UIC60E1\"").unwrap();
    let l = crate::maintenance::Limits::with_overrides(920.0, s.limits());
    assert_eq!(l.sd_min.value_mm.to_bits(), 24.5f64.to_bits());
    assert!(l.sd_min.source.contains("limits.sd_min_mm"), "{l:?}");
    assert!(l.sd_max.source.contains("321/2013"), "{l:?}");
    assert_eq!(
        s.nominal_rails(),
        Some(&[
            ProfileRef::BuiltIn("UIC60E1".into()),
            ProfileRef::BuiltIn("UIC60E1".into())
        ])
    );
    assert!(scene("").unwrap().nominal_rails().is_none());
    let e = scene("[limits]\nsd_minimum = 24.0")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("sd_minimum") && e.contains("unknown field"),
        "{e}"
    );
}

#[test]
fn unknown_keys_are_rejected_with_their_name() {
    let e = scene("[track]\ngauge = 1435.0").unwrap_err().to_string();
    assert!(e.contains("gauge") && e.contains("unknown field"), "{e}");
    let e = scene("colour = \"red\"").unwrap_err().to_string();
    assert!(e.contains("colour"), "{e}");
}
