//! One test per fixed bug, named after what went wrong, with the input that showed it.
//! Found by the stress suite (`tests/stress.rs`) and the fuzz tests (`tests/fuzz.rs`).

use std::path::Path;
use wheelrail::profile::Profile;
use wheelrail::quasi_elastic::{self, QuasiElasticSettings};
use wheelrail::rigid::{self, Solver, Stop};
use wheelrail::scene::Scene;
use wheelrail::sweep::Sweep;
use wheelrail::track::Side;

fn place(toml: &str) -> wheelrail::track::Placement {
    let scene = Scene::from_toml(toml, "regression.toml", Path::new(".")).unwrap();
    wheelrail::pipeline::place(&scene).unwrap()
}

/// Quasi-elastic patches of separate low regions were weighted each relative to their own
/// lowest gap instead of a common reference: a tread region whose gap lies wholly above the
/// cut-off (it is scanned because the coarse threshold has a margin of 0.05 mm) became a
/// patch with a weight share comparable to the real contact's, e.g. S1002 on UIC60 1:40 at
/// eps = 0.001 mm near the jump to the flange root (22 % of the weight at 0.083 mm above
/// the minimum). Every patch must contain a node whose gap is within the cut-off of the
/// lowest patch (which lies at the rigid minimum), and a patch whose lowest gap lies `g`
/// above it weighs at most exp(-g / eps) relative to the main one's weight times the ratio
/// of their widths (the region scanned, at most 130 mm, against the main patch's
/// sqrt(2 pi eps / d'') > 0.01 mm: a factor 1.3e4).
#[test]
fn quasi_elastic_regions_share_the_rigid_minimum() {
    let placement = place("");
    let ys: Vec<f64> = (0..=200).map(|i| 3.0 + 0.02 * f64::from(i)).collect();
    let rigid = rigid::search(
        &placement,
        &Sweep::from_slice(&ys).unwrap(),
        Solver::default(),
    );
    for eps in [1e-3, 3e-3] {
        let settings = QuasiElasticSettings::default().with_epsilon(eps).unwrap();
        let qe = quasi_elastic::search(&placement, rigid.clone(), &settings);
        for (p, q) in rigid.positions().iter().zip(qe.positions()) {
            assert_eq!(p.stop, Stop::Converged);
            for side in [Side::Left, Side::Right] {
                let patches = &q.side(side).patches;
                let main = patches[0].weight_share;
                let lowest = patches
                    .iter()
                    .map(|p| p.gap_above_min)
                    .fold(f64::INFINITY, f64::min);
                // The quadrature resolves the weight here: a node lies close to the rigid
                // minimum (measured within 0.034 eps).
                assert!(
                    lowest <= 0.07 * eps,
                    "y_ws {}: {side:?} {patches:?}",
                    p.y_ws
                );
                for patch in patches {
                    assert!(
                        patch.gap_above_min - lowest <= settings.cutoff() * eps,
                        "eps {eps}, y_ws {}: {side:?} patch {patch:?} lies above the cut-off",
                        p.y_ws
                    );
                    let bound = 1.3e4 * main * (-patch.gap_above_min / eps).exp();
                    assert!(
                        patch.weight_share <= bound,
                        "eps {eps}, y_ws {}: {side:?} patch {patch:?} weighs more than {bound}",
                        p.y_ws
                    );
                }
            }
        }
    }
}

/// S1002's flange-back arc (R20.5) has a vertical tangent at the end of the definition,
/// s = -70 mm: its slope was infinite and its curvature inf/inf = NaN there, and a
/// quasi-elastic average with a large eps (1 mm: the cut-off reaches 37 mm above the
/// minimum) over the flange back reported NaN curvature for a wheelset shifted 45 mm.
#[test]
fn s1002_end_of_definition_has_finite_derivatives() {
    let wheel = Profile::s1002();
    let [f, d1, d2] = wheel.eval(-70.0);
    assert!(
        f.is_finite() && d1.is_finite() && d2.is_finite(),
        "{d1} {d2}"
    );
    // The arc's curvature at its vertical tangent is 1/20.5 (convex towards the rail;
    // measured 7.3e-14 1/mm off: the rounding of the arc's closed form).
    let k = wheel.convex_curvature(-70.0);
    assert!((k - 1.0 / 20.5).abs() < 2e-13, "{k}");
    // The run that showed it (from the stress suite's shrunk case).
    let placement = place(
        "[wheel]\nnominal_radius_mm = 300.0\n[rail]\ninclination = \"vertical\"\n\
         [track]\ngauge_mm = 1430.0\ngauge_point_depth_mm = 10.0\n\
         [wheelset]\nflange_back_mm = 1355.0\n",
    );
    let rigid = rigid::search(
        &placement,
        &Sweep::from_slice(&[-45.0, 45.0]).unwrap(),
        Solver::default(),
    );
    let settings = QuasiElasticSettings::default().with_epsilon(1.0).unwrap();
    let qe = quasi_elastic::search(&placement, rigid.clone(), &settings);
    for q in qe.positions() {
        for side in [Side::Left, Side::Right] {
            for p in &q.side(side).patches {
                assert!(
                    p.wheel_curvature.is_finite() && p.gamma.is_finite(),
                    "y_ws {}: {side:?} {p:?}",
                    q.y_ws
                );
            }
        }
    }
}

/// The first fix of the bug above took the rigid minimum as the common reference and dropped
/// regions without a node within the cut-off of it; where the weight is narrower than the
/// quadrature step (eps = 1e-5 mm at a kink of the gap) that left a converged contact
/// without any patch. Found by the stress suite: unequal radii 300/588 mm, y_ws = -6 mm.
#[test]
fn quasi_elastic_always_has_a_patch_at_a_converged_contact() {
    let placement = place(
        "[wheel]\nleft_nominal_radius_mm = 300.0\nright_nominal_radius_mm = 588.1725327496852\n\
         [rail]\ninclination = \"vertical\"\n\
         [track]\ngauge_mm = 1430.0\ngauge_point_depth_mm = 10.0\n\
         [wheelset]\nflange_back_mm = 1355.0\n",
    );
    let ys: Vec<f64> = (0..=24).map(|i| -6.0 + 0.5 * f64::from(i)).collect();
    let rigid = rigid::search(
        &placement,
        &Sweep::from_slice(&ys).unwrap(),
        Solver::default(),
    );
    for eps in [1e-5, 1e-4] {
        let settings = QuasiElasticSettings::default().with_epsilon(eps).unwrap();
        let qe = quasi_elastic::search(&placement, rigid.clone(), &settings);
        // The invariant guarded here: a converged rigid contact has a quasi-elastic patch.
        // (With these absurd radii, roll 0.19 rad, the rigid search may also flag a position
        // as NoContact; flagged positions are checked elsewhere.)
        let mut converged = 0;
        for (p, q) in rigid.positions().iter().zip(qe.positions()) {
            if p.stop != Stop::Converged {
                continue;
            }
            converged += 1;
            for side in [Side::Left, Side::Right] {
                let patches = &q.side(side).patches;
                assert!(!patches.is_empty(), "eps {eps}, y_ws {}: {side:?}", p.y_ws);
                // The nodes stay on the wheel (-70 to 60 mm) and none is below the rigid
                // minimum (nodes beyond the domain were phantom points of a clamped profile).
                for patch in patches {
                    assert!((-70.0..=60.0).contains(&patch.s), "{patch:?}");
                    assert!(patch.gap_above_min >= -1e-9, "{patch:?}");
                }
                // Normalised shares: measured exact, 4.5e-16 (two ulps of 1) allows rounding.
                let total: f64 = patches.iter().map(|p| p.weight_share).sum();
                assert!((total - 1.0).abs() < 4.5e-16, "{total}");
            }
        }
        // Measured: 25 of 25 at both eps.
        assert!(
            converged >= 20,
            "only {converged} of {} positions converged",
            ys.len()
        );
    }
}

/// Found by `tests/fuzz.rs` (mutated scenes): `wheel_load_kN = 1e306` passes the scene's
/// check (positive and finite in kN) and becomes inf N when converted; `young_GPa` overflows
/// the same way but `Material::new` catches it. Hertz then flags every position ("load must
/// be finite"), but a checked `Scene` should not hold inf. The fix belongs in `src/scene.rs`
/// (check after converting).
#[test]
fn scene_rejects_values_that_overflow_on_conversion() {
    let scene = Scene::from_toml("[load]\nwheel_load_kN = 1e306\n", "t", Path::new("."));
    assert!(scene.is_err(), "{:?}", scene.map(|s| s.wheel_load_n()));
}

/// Found while fuzzing scenes: any positive `quasi_elastic.max_step_mm` is accepted, but the
/// quadrature places its nodes at that step over the low regions (the search's own floor,
/// 1e-4 mm, applies only to the step it derives from eps), so 1e-6 mm takes 28 s per
/// position (measured; 2.4 h for the default sweep) and 1e-9 mm runs out of memory. The fix
/// belongs in `src/scene.rs` (a lower bound, e.g. 1e-4 mm).
#[test]
fn scene_rejects_a_quadrature_step_that_cannot_finish() {
    let scene = Scene::from_toml(
        "[quasi_elastic]\nquadrature = \"trapezoid\"\nmax_step_mm = 1e-9\n",
        "t",
        Path::new("."),
    );
    let e = scene.unwrap_err().to_string();
    assert!(e.contains("quasi_elastic.max_step_mm"), "{e}");
}

/// Found by the stress suite in CI (radii 583.5 / 338.9 mm, vertical rails, eps = 1e-5 mm,
/// y_ws = 21 mm): the minimum of the gap sits at the vertical flange-back end of the wheel
/// profile, where the weight is narrower than any quadrature node spacing, and the Gauss-
/// Legendre pass returned no patch for a converged contact. The average now tends to its
/// limit, the value at the rigid contact point.
#[test]
fn quasi_elastic_patch_where_the_weight_is_narrower_than_any_node() {
    let placement = place(
        "[wheel]\nleft_nominal_radius_mm = 583.54963191168\nright_nominal_radius_mm = 338.9177371966275\n\
         [rail]\ninclination = \"vertical\"\n\
         [track]\ngauge_mm = 1430.0\ngauge_point_depth_mm = 10.0\n\
         [wheelset]\nflange_back_mm = 1355.0\n",
    );
    // The stress suite's sweep: -45..45 mm every 3 mm (continuation reaches 21 mm from it).
    let ys: Vec<f64> = (0..31).map(|i| -45.0 + 3.0 * f64::from(i)).collect();
    let rigid = rigid::search(
        &placement,
        &Sweep::from_slice(&ys).unwrap(),
        Solver::default(),
    );
    let settings = QuasiElasticSettings::default().with_epsilon(1e-5).unwrap();
    let qe = quasi_elastic::search(&placement, rigid.clone(), &settings);
    let mut checked = 0;
    for (p, q) in rigid.positions().iter().zip(qe.positions()) {
        if p.stop != Stop::Converged {
            continue;
        }
        for (k, side) in [Side::Left, Side::Right].into_iter().enumerate() {
            let patches = &q.side(side).patches;
            assert!(
                !patches.is_empty(),
                "y_ws {}: {side:?} has no patch",
                p.y_ws
            );
            // Where the fallback applies, the patch is the rigid point itself; elsewhere the
            // average lies within 1.8e-3 mm of it (measured).
            let rigid_s = p.contact[k].unwrap().s;
            assert!(
                patches.iter().any(|x| (x.s - rigid_s).abs() < 4e-3),
                "y_ws {}: {patches:?}",
                p.y_ws
            );
            checked += 1;
        }
    }
    // Measured: 44 converged wheel contacts.
    assert!(checked >= 40, "{checked} contacts checked");
}

/// A contact held at the end of the rail's running surface (where it turns steeper than the
/// placed-slope limit) hit the iteration cap: the envelope-theorem slope of Newton's method
/// on the roll is exact only at smooth minima, and the residual fell by a factor 0.66 per
/// step (1.35e-11 mm after 60 iterations). Measured right rail of `measured_average` at
/// y_ws = -8.4 mm, reached from a sweep every 0.3 mm; found while checking the quasi-elastic
/// pass on measured profiles. Every position of that sweep converges now.
#[test]
fn rigid_converges_at_a_contact_on_the_end_of_the_rail_surface() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports/measured_average/scene.toml");
    let scene = Scene::load(&path).unwrap();
    let placement = wheelrail::pipeline::place(&scene).unwrap();
    let sweep: Vec<f64> = (-40..=40).map(|i| f64::from(3 * i) / 10.0).collect();
    let r = rigid::search(
        &placement,
        &Sweep::from_slice(&sweep).unwrap(),
        Solver::default(),
    );
    let at = r
        .positions()
        .iter()
        .find(|p| (p.y_ws + 8.4).abs() < 1e-12)
        .unwrap();
    assert_eq!(at.stop, Stop::Converged, "{at:?}");
    assert!(at.residual <= rigid::RollSettings::default().residual_tol_mm());
    for p in r.positions() {
        assert_eq!(p.stop, Stop::Converged, "y_ws {}: {:?}", p.y_ws, p.stop);
    }
}
