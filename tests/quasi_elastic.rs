//! Quasi-elastic search: analytic averages, convergence to the rigid solution as eps -> 0,
//! smoothing of the rigid jumps, and mirror symmetry.

use proptest::prelude::*;
use std::path::Path;
use std::sync::OnceLock;
use wheelrail::quasi_elastic::{self, QuasiElasticSettings, average};
use wheelrail::rigid::{self, Solver};
use wheelrail::scene::Scene;
use wheelrail::sweep::Sweep;
use wheelrail::track::{Placement, Side};

fn placement() -> &'static Placement {
    static P: OnceLock<Placement> = OnceLock::new();
    P.get_or_init(|| {
        let scene = Scene::from_toml("", "paper defaults", Path::new(".")).unwrap();
        wheelrail::pipeline::place(&scene).unwrap()
    })
}

fn eps(e: f64) -> QuasiElasticSettings {
    QuasiElasticSettings::default().with_epsilon(e).unwrap()
}

#[test]
fn parabolic_gap_on_even_and_uneven_grids() {
    // d(s) = kappa s^2 / 2: the weight is a Gaussian centred at 0, so the averaged location
    // is 0 (to rounding, by symmetry on the even grid: measured 9.3e-18 mm; to the
    // trapezoid error on the uneven one: measured 2.1e-6 mm) and a constant field averages
    // to itself. Each bound is about twice what was measured.
    let kappa = 0.004;
    let e = 0.01;
    let even: Vec<f64> = (-2000..=2000).map(|i| f64::from(i) * 0.01).collect();
    // Uneven: spacing alternating 0.004 / 0.016 mm, then stretched near one end.
    let mut uneven = vec![-20.0];
    let mut k = 0;
    while *uneven.last().unwrap() < 20.0 {
        let h = if k % 2 == 0 { 0.004 } else { 0.016 }
            * if uneven.last().unwrap() > &5.0 {
                3.0
            } else {
                1.0
            };
        uneven.push(uneven.last().unwrap() + h);
        k += 1;
    }
    for (nodes, tol, weight_tol) in [(&even, 2e-17, 2e-15), (&uneven, 5e-6, 1e-6)] {
        let gaps: Vec<f64> = nodes.iter().map(|s| 0.5 * kappa * s * s).collect();
        let fields: Vec<[f64; 2]> = nodes.iter().map(|&s| [s, kappa]).collect();
        let a = average(nodes, &gaps, &fields, e, 37.0);
        assert_eq!(a.len(), 1);
        assert!(a[0].mean[0].abs() < tol, "location {}", a[0].mean[0]);
        // A constant averages to itself up to the rounding of 4000 weighted additions
        // (measured 3.7e-15 relative).
        assert!(
            (a[0].mean[1] - kappa).abs() < 1e-14 * kappa,
            "curvature {}",
            a[0].mean[1]
        );
        // Integral of the weight: sqrt(2 pi eps / kappa) (Gaussian). The trapezoid rule is
        // exact to rounding on the even grid (measured 5.6e-16 relative: the Gaussian's
        // tails decay faster than any power) and errs by 4.7e-7 on the uneven one.
        let exact = (2.0 * std::f64::consts::PI * e / kappa).sqrt();
        assert!(
            (a[0].weight - exact).abs() < weight_tol * exact,
            "{} vs {exact}",
            a[0].weight
        );
    }
}

#[test]
fn two_equal_minima_give_two_patches() {
    // d(s) = kappa/2 min((s - 3)^2, (s + 3)^2): two equal wells, barrier 0.018 mm >> eps.
    let nodes: Vec<f64> = (-800..=800).map(|i| f64::from(i) * 0.01).collect();
    let gaps: Vec<f64> = nodes
        .iter()
        .map(|s| 0.002 * ((s - 3.0) * (s - 3.0)).min((s + 3.0) * (s + 3.0)))
        .collect();
    let fields: Vec<[f64; 1]> = nodes.iter().map(|&s| [s]).collect();
    let a = average(&nodes, &gaps, &fields, 0.001, 37.0);
    assert_eq!(a.len(), 2);
    // Each patch is cut at the barrier s = 0, where its weight is exp(-0.018 / 0.001) =
    // 1.5e-8: the one-sided truncation biases each location by about 3e-9 mm (measured
    // 3.04e-9 mm); the weights are equal to rounding (measured 7.1e-16 relative).
    assert!(
        (a[0].mean[0] + 3.0).abs() < 6e-9 && (a[1].mean[0] - 3.0).abs() < 6e-9,
        "{a:?}"
    );
    assert!((a[0].weight - a[1].weight).abs() < 2e-15 * a[0].weight);
}

#[test]
fn cutoff_changes_nothing_at_output_precision() {
    // Cutting at exp(-25) (the default) against cutting at exp(-60): same averages
    // to 1e-9 mm (10 significant digits of the outputs) at every position of a coarse paper
    // sweep. The cut-off moves the ends of the integration regions and so the quadrature
    // panels: the results differ by the quadrature's own error, measured 7e-13 to
    // 4.5e-10 mm; the bound, the outputs' precision, is about twice the largest.
    let sweep: Vec<f64> = (0..=30).map(|i| -15.0 + f64::from(i)).collect();
    let r = rigid::search(
        placement(),
        &Sweep::from_slice(&sweep).unwrap(),
        Solver::default(),
    );
    let a = quasi_elastic::search(placement(), r.clone(), &QuasiElasticSettings::default());
    let b = quasi_elastic::search(
        placement(),
        r.clone(),
        &QuasiElasticSettings::default().with_cutoff(60.0).unwrap(),
    );
    for (p, q) in a.positions().iter().zip(b.positions()) {
        for side in [Side::Left, Side::Right] {
            let (x, y) = (p.side(side).main().unwrap(), q.side(side).main().unwrap());
            assert!(
                (x.s - y.s).abs() < 1e-9,
                "y_ws {}: {} vs {}",
                p.y_ws,
                x.s,
                y.s
            );
        }
    }
}

#[test]
fn converges_to_rigid_as_eps_decreases() {
    // Away from the jumps (0.226, 4.99, 6.26 mm) the quasi-elastic contact location tends to
    // the rigid one: the error shrinks with eps (measured: linearly, 0.37, 0.034 and
    // 0.0034 mm, a factor 0.094 and 0.099 per decade; the weight is a Gaussian of width
    // sqrt(eps / d'') whose skew from the third derivative of the gap shifts its mean in
    // proportion to eps). Bounds about twice the measured factors and error.
    let sweep = [-12.0, -8.0, -3.0, 2.0, 3.5, 9.0, 13.0];
    let r = rigid::search(
        placement(),
        &Sweep::from_slice(&sweep).unwrap(),
        Solver::default(),
    );
    let errs: Vec<f64> = [0.01, 0.001, 0.0001]
        .iter()
        .map(|&e| {
            let q = quasi_elastic::search(placement(), r.clone(), &eps(e));
            r.positions()
                .iter()
                .zip(q.positions())
                .flat_map(|(rp, qp)| {
                    [Side::Left, Side::Right].map(|side| {
                        (rp.side(side).unwrap().s - qp.side(side).main().unwrap().s).abs()
                    })
                })
                .fold(0.0, f64::max)
        })
        .collect();
    println!("max |s_qe - s_rigid| for eps 0.01, 0.001, 0.0001 mm: {errs:?}");
    assert!(
        errs[1] < 0.2 * errs[0] && errs[2] < 0.2 * errs[1],
        "{errs:?}"
    );
    assert!(errs[2] < 0.007, "{errs:?}");
}

#[test]
fn smooths_the_rigid_jumps() {
    // At the paper's eps no patch that carries weight jumps: between neighbouring positions
    // of the 0.1 mm sweep every patch with more than 5 % of the weight has a patch within
    // 1.5 mm at the other position (measured: 0.96 mm, where the tread contact moves fast
    // but continuously, about 9 mm per mm of shift near the centre), where the rigid contact point jumps by 9.8 mm (near
    // centre) and 10.9 mm (to the flange root). Near 5 mm the weight passes continuously
    // from the tread patch to the flange-root patch instead. The flange onset (6.26 mm) is
    // excluded: there the flange is a new body in contact.
    let sweep: Vec<f64> = (0..=60).map(|i| 0.1 * f64::from(i)).collect();
    let r = rigid::search(
        placement(),
        &Sweep::from_slice(&sweep).unwrap(),
        Solver::default(),
    );
    let q = quasi_elastic::search(placement(), r.clone(), &QuasiElasticSettings::default());
    let mut rigid_max: f64 = 0.0;
    for (a, b) in r.positions().iter().zip(&r.positions()[1..]) {
        rigid_max =
            rigid_max.max((a.side(Side::Left).unwrap().s - b.side(Side::Left).unwrap().s).abs());
    }
    let mut qe_max: f64 = 0.0;
    for (a, b) in q.positions().iter().zip(&q.positions()[1..]) {
        for (x, z) in [(a, b), (b, a)] {
            for p in x
                .side(Side::Left)
                .patches
                .iter()
                .filter(|p| p.weight_share > 0.05)
            {
                let nearest = z
                    .side(Side::Left)
                    .patches
                    .iter()
                    .map(|o| (o.s - p.s).abs())
                    .fold(f64::INFINITY, f64::min);
                qe_max = qe_max.max(nearest);
            }
        }
    }
    println!(
        "largest step of the left contact, 0..6 mm: rigid {rigid_max:.3} mm, quasi-elastic patches {qe_max:.3} mm"
    );
    assert!(rigid_max > 9.0, "{rigid_max}");
    assert!(qe_max < 1.5, "{qe_max}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]
    #[test]
    fn mirror_symmetry(y in 0.0f64..15.0) {
        // Both shifts solved and averaged: a mirror-symmetric placement would mirror them.
        // The two solves start from different points and agree to the roll solver's
        // tolerance, magnified where the gap is flat; over 4000 draws (two seeds) at most
        // 8.5e-10 mm in s and y, 1.0e-10 rad in gamma, 4.7e-12 1/mm in curvature and 9.9e-11
        // in weight share. Bounds about twice these.
        let unmirrored = placement().clone().without_mirroring();
        let r = rigid::search(&unmirrored, &Sweep::from_slice(&[-y, y]).unwrap(), Solver::default());
        let q = quasi_elastic::search(&unmirrored, r.clone(), &QuasiElasticSettings::default());
        let (m, p) = (&q.positions()[0], &q.positions()[1]);
        let pairs = [(m.side(Side::Left), p.side(Side::Right)), (m.side(Side::Right), p.side(Side::Left))];
        for (a, b) in pairs {
            prop_assert_eq!(a.patches.len(), b.patches.len());
            for (x, z) in a.patches.iter().zip(&b.patches) {
                prop_assert!((x.s - z.s).abs() < 2e-9, "{} {}", x.s, z.s);
                prop_assert!((x.y + z.y).abs() < 2e-9);
                prop_assert!((x.gamma - z.gamma).abs() < 2e-10);
                prop_assert!((x.wheel_curvature - z.wheel_curvature).abs() < 1e-11);
                prop_assert!((x.weight_share - z.weight_share).abs() < 2e-10);
            }
        }
    }
}

#[test]
fn weight_shares_match_an_independent_integration() {
    // Regression (weights were normalised per low region, so shares of patches in separate
    // regions were wrong): at positions with two patches, each patch's share equals the
    // integral of exp(-(d - d_min)/eps) on its side of the barrier over the whole wheel,
    // summed independently by a trapezoid rule every 0.0005 mm (first-order error where a
    // curvature jumps: measured at most 1.5e-6 of the share; bound twice that).
    use wheelrail::gap::{SideGap, SidePose};
    let sweep: Vec<f64> = (0..=30).map(|i| 3.5 + 0.1 * f64::from(i)).collect();
    let r = rigid::search(
        placement(),
        &Sweep::from_slice(&sweep).unwrap(),
        Solver::default(),
    );
    let q = quasi_elastic::search(placement(), r.clone(), &QuasiElasticSettings::default());
    let side = SideGap::new(placement().left(), 1.0);
    let mut checked = 0;
    for (rp, qp) in r.positions().iter().zip(q.positions()) {
        let patches = &qp.side(Side::Left).patches;
        if patches.len() != 2 {
            continue;
        }
        let pose = SidePose::new(1.0, rp.y_ws, rp.roll);
        let d_min = rp.axle_height + side.at(rp.side(Side::Left).unwrap().s, &pose).unwrap().g;
        let (s1, s2) = (
            patches[0].s.min(patches[1].s),
            patches[0].s.max(patches[1].s),
        );
        // The barrier: the highest gap between the two patch locations.
        let mut barrier = (f64::NEG_INFINITY, s1);
        let mut s = s1;
        while s < s2 {
            let g = side.at(s, &pose).unwrap().g;
            if g > barrier.0 {
                barrier = (g, s);
            }
            s += 0.001;
        }
        let (mut below, mut above) = (0.0, 0.0);
        let h = 0.0005;
        for i in 0..=260_000 {
            let s = -70.0 + h * f64::from(i);
            if let Some(p) = side.at(s, &pose) {
                let w = h * (-(p.g + rp.axle_height - d_min) / 0.01).exp();
                if s < barrier.1 {
                    below += w
                } else {
                    above += w
                }
            }
        }
        let share_below = below / (below + above);
        let patch_below = if patches[0].s < barrier.1 {
            patches[0]
        } else {
            patches[1]
        };
        assert!(
            (patch_below.weight_share - share_below).abs() < 3e-6,
            "y_ws {}: share {} vs independent {share_below}",
            rp.y_ws,
            patch_below.weight_share
        );
        checked += 1;
    }
    // Measured: 9 two-patch positions.
    assert!(checked >= 6, "only {checked} two-patch positions");
}
