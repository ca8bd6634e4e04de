//! Hertz contact ellipse against independent references: 50-digit mpmath solutions, the
//! classical Hertz coefficients, closed forms, and invariants of the physics.

use proptest::prelude::*;
use std::f64::consts::PI;
use wheelrail::hertz::{
    Contact, Ellipse, EllipseMethod, HertzError, Material, NotHertzianReason, PrincipalCurvatures,
    Stop, accuracy, ellipse, relative_curvatures,
};

/// Steel on steel, E = 210 GPa, ν = 0.3: E* = E / (2 (1 - ν²)).
const E_STEEL: f64 = 210_000.0 / (2.0 * (1.0 - 0.09));

fn solve(a: f64, b: f64, load: f64, e_star: f64, method: EllipseMethod) -> Ellipse {
    match ellipse(a, b, load, e_star, method) {
        Ok(Contact::Hertzian(e)) => e,
        other => panic!("A = {a}, B = {b}: expected a Hertzian contact, got {other:?}"),
    }
}

fn rel(x: f64, reference: f64) -> f64 {
    (x - reference).abs() / reference.abs()
}

/// Exact method against `tests/data/hertz_reference.csv` (scripts/hertz_reference.py, mpmath
/// at 50 digits, textbook equations solved independently of the Rust code).
#[test]
fn exact_matches_mpmath_references() {
    // Measured at most 8.9e-16 (b) over the 54 cases: the rounding of the AGM, the Newton
    // solve and the closing products; twice that. (The brief asked for 1e-12.)
    const TOL: f64 = 2e-15;
    let data = include_str!("data/hertz_reference.csv");
    let mut rows = 0;
    let mut worst = [0.0f64; 4];
    for line in data.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let v: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let c = solve(v[0], v[1], v[2], v[3], EllipseMethod::Exact);
        assert_eq!(c.stop, Stop::Converged);
        let got = [c.a_mm, c.b_mm, c.p0_mpa, c.approach_mm];
        for (col, name) in ["a", "b", "p0", "approach"].iter().enumerate() {
            let err = rel(got[col], v[4 + col]);
            worst[col] = worst[col].max(err);
            assert!(
                err <= TOL,
                "A = {}, B = {}: {name} = {:e}, reference {:e}, rel. error {err:e}",
                v[0],
                v[1],
                got[col],
                v[4 + col]
            );
        }
        rows += 1;
    }
    assert!(rows >= 40, "only {rows} reference rows");
    println!(
        "max rel. error over {rows} cases: a {:e}, b {:e}, p0 {:e}, approach {:e}",
        worst[0], worst[1], worst[2], worst[3]
    );
}

/// Classical Hertz coefficients m, n (a = m [3P/(4E*(A+B))]^(1/3), cos θ = (B-A)/(A+B)),
/// the classical table's values (as restated in the project's reference notes, outside this
/// repository), to 4 decimals (±5e-5: the table's
/// rounding).
#[test]
fn classical_coefficients_m_n() {
    let table = [
        (30.0, 2.7306, 0.4931),
        (40.0, 2.1357, 0.5673),
        (50.0, 1.7541, 0.6407),
        (60.0, 1.4858, 0.7171),
        (70.0, 1.2851, 0.7999),
        (80.0, 1.1278, 0.8927),
        (90.0, 1.0, 1.0),
    ];
    let (load, b) = (1000.0, 0.01);
    let mut worst: f64 = 0.0;
    for (theta_deg, m, n) in table {
        let cos: f64 = f64::to_radians(theta_deg).cos();
        let a = b * (1.0 - cos) / (1.0 + cos);
        let c = solve(a, b, load, E_STEEL, EllipseMethod::Exact);
        let scale = (3.0 * load / (4.0 * E_STEEL * (a + b))).cbrt();
        worst = worst
            .max((c.a_mm / scale - m).abs())
            .max((c.b_mm / scale - n).abs());
        assert!(
            (c.a_mm / scale - m).abs() <= 5e-5,
            "θ = {theta_deg}: m = {}",
            c.a_mm / scale
        );
        assert!(
            (c.b_mm / scale - n).abs() <= 5e-5,
            "θ = {theta_deg}: n = {}",
            c.b_mm / scale
        );
    }
    println!("m, n against the classical table: max deviation {worst:e}");
}

/// Sphere on plane, A = B = 1/(2R): a = (3PR/(4E*))^(1/3), δ = a²/R, p0 = 3P/(2πa²)
/// (Johnson 1985, §4.2). Measured at most 5.4e-16 (the mean pressure): a few roundings in
/// cbrt and the products; 1.5e-15 allows them and another libm's cbrt.
#[test]
fn sphere_on_plane_closed_form() {
    for (r, load, e_star) in [
        (10.0, 100.0, E_STEEL),
        (460.0, 7e4, E_STEEL),
        (1.0, 1e-3, 1e3),
    ] {
        let c = solve(0.5 / r, 0.5 / r, load, e_star, EllipseMethod::Exact);
        let a = (3.0 * load * r / (4.0 * e_star)).cbrt();
        const TOL: f64 = 1.5e-15;
        assert!(rel(c.a_mm, a) <= TOL && rel(c.b_mm, a) <= TOL);
        assert!(rel(c.approach_mm, a * a / r) <= TOL);
        assert!(rel(c.p0_mpa, 3.0 * load / (2.0 * PI * a * a)) <= TOL);
        assert!(rel(c.mean_pressure_mpa, load / (PI * a * a)) <= TOL);
        assert!(c.eccentricity.abs() <= 1e-15);
        assert_eq!((c.iterations, c.stop), (0, Stop::Converged));
    }
}

/// Near the circle the exact method stays exact: the approach to the circle is smooth
/// (checked against the circle itself: at A/B = 1 - 1e-12 the semi-axes differ from the
/// circle's by a fraction of 1e-12). Measured: a 5.0e-13, b 1.7e-13, the approach 1.7e-13;
/// the bounds are about twice these.
#[test]
fn near_circle_is_continuous() {
    let b = 0.01;
    let circle = solve(b, b, 1e3, E_STEEL, EllipseMethod::Exact);
    let near = solve(b * (1.0 - 1e-12), b, 1e3, E_STEEL, EllipseMethod::Exact);
    assert!(rel(near.a_mm, circle.a_mm) <= 1e-12 && near.a_mm > circle.a_mm);
    assert!(rel(near.b_mm, circle.b_mm) <= 4e-13);
    assert!(rel(near.approach_mm, circle.approach_mm) <= 4e-13);
}

/// Down to A/B = 1e-300 the exact method returns finite, converged ellipses with b/a
/// decreasing monotonically (no reference needed: the monotonicity is the physics).
#[test]
fn extreme_ratios_stay_finite_and_monotonic() {
    let mut last_ratio = f64::INFINITY;
    for k in 0..=300 {
        let c = solve(10f64.powi(-k), 1.0, 1.0, 1.0, EllipseMethod::Exact);
        assert_eq!(c.stop, Stop::Converged);
        let g = c.b_mm / c.a_mm;
        assert!(
            g > 0.0 && g < last_ratio || k == 0,
            "A/B = 1e-{k}: b/a = {g}"
        );
        assert!(c.p0_mpa.is_finite() && c.approach_mm.is_finite());
        last_ratio = g;
    }
}

#[test]
fn not_hertzian_cases_are_results() {
    let cases = [
        (-0.01, 0.005, NotHertzianReason::Conformal),
        (0.0, 0.0, NotHertzianReason::Conformal),
        (0.0, 0.01, NotHertzianReason::NonPositiveRolling),
        (-0.001, 0.01, NotHertzianReason::NonPositiveRolling),
        (0.01, -0.001, NotHertzianReason::NonPositiveLateral),
    ];
    for (a, b, reason) in cases {
        for method in [EllipseMethod::Exact, EllipseMethod::Paper] {
            assert_eq!(
                ellipse(a, b, 1e4, E_STEEL, method),
                Ok(Contact::NotHertzian(reason)),
                "A = {a}, B = {b}"
            );
        }
    }
}

#[test]
fn invalid_inputs_are_errors_named_after_the_condition() {
    let m = EllipseMethod::Exact;
    assert_eq!(
        ellipse(0.01, 0.01, 0.0, E_STEEL, m),
        Err(HertzError::NonPositiveLoad { load_n: 0.0 })
    );
    assert_eq!(
        ellipse(0.01, 0.01, 1.0, -1.0, m),
        Err(HertzError::NonPositiveModulus { value_mpa: -1.0 })
    );
    assert!(matches!(
        ellipse(f64::NAN, 0.01, 1.0, E_STEEL, m),
        Err(HertzError::NonFinite { quantity: "A", .. })
    ));
    assert!(matches!(
        ellipse(0.01, f64::INFINITY, 1.0, E_STEEL, m),
        Err(HertzError::NonFinite { quantity: "B", .. })
    ));
    assert!(matches!(
        ellipse(0.01, 0.01, f64::INFINITY, E_STEEL, m),
        Err(HertzError::NonFinite {
            quantity: "load",
            ..
        })
    ));
    assert_eq!(
        Material::new(0.0, 0.3),
        Err(HertzError::NonPositiveModulus { value_mpa: 0.0 })
    );
    assert_eq!(
        Material::new(2e5, -1.0),
        Err(HertzError::PoissonOutOfRange { poisson: -1.0 })
    );
    assert!(matches!(
        Material::new(f64::NAN, 0.3),
        Err(HertzError::NonFinite { .. })
    ));
    // Overflowing inputs are reported, not returned as inf.
    assert_eq!(
        ellipse(1e-300, 1.0, 1e300, 1e-300, m),
        Err(HertzError::NonFiniteResult)
    );
    // Display is a sentence naming the value.
    let msg = HertzError::NonPositiveLoad { load_n: -5.0 }.to_string();
    assert!(msg.contains("-5"), "{msg}");
}

#[test]
fn relative_curvatures_at_psi_zero_are_the_sums() {
    let k = PrincipalCurvatures {
        wheel_rolling: 1.0 / 460.0,
        wheel_lateral: -1.0 / 100.0,
        rail_rolling: 0.0,
        rail_lateral: 1.0 / 13.0,
    };
    let (a, b) = relative_curvatures(&k, 0.0);
    // Bitwise: at ψ = 0 the sums are formed directly (documented).
    assert_eq!(a.to_bits(), (0.5 * (1.0_f64 / 460.0)).to_bits());
    assert_eq!(
        b.to_bits(),
        (0.5 * (-1.0_f64 / 100.0 + 1.0 / 13.0)).to_bits()
    );
    // ψ = π/2 swaps the rail's axes (measured: exact; 1e-15 allows a rounding or two).
    let (a, b) = relative_curvatures(&k, PI / 2.0);
    assert!(rel(a, 0.5 * (1.0 / 460.0 + 1.0 / 13.0)) <= 1e-15);
    assert!(rel(b, 0.5 * (-1.0 / 100.0)) <= 1e-15);
}

fn curvature() -> impl Strategy<Value = f64> {
    prop_oneof![-0.1..0.1f64, Just(0.0)]
}

proptest! {
    // Failing cases are printed with their seed; no regression files in the tree.
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::default() })]

    /// Paper Eqs. 12-13: A + B is half the sum of the four curvatures; |B - A| the Eq. 13
    /// root. Absolute on curvatures up to 0.1/mm: measured at most 2.8e-17 and 4.9e-17 over
    /// 3000 draws (a few roundings); 1e-16.
    #[test]
    fn relative_curvatures_satisfy_eqs_12_13(
        k1x in curvature(), k1y in curvature(), k2x in curvature(), k2y in curvature(),
        psi in -3.2..3.2f64,
    ) {
        let k = PrincipalCurvatures {
            wheel_rolling: k1x, wheel_lateral: k1y, rail_rolling: k2x, rail_lateral: k2y,
        };
        let (a, b) = relative_curvatures(&k, psi);
        prop_assert!((a + b - 0.5 * (k1x + k1y + k2x + k2y)).abs() <= 1e-16);
        let (d1, d2) = (k1x - k1y, k2x - k2y);
        let diff = 0.5 * (d1 * d1 + d2 * d2 + 2.0 * d1 * d2 * (2.0 * psi).cos()).max(0.0).sqrt();
        prop_assert!(((b - a).abs() - diff).abs() <= 1e-16);
    }

    /// A stays with the rolling direction: a small ψ moves A by O(ψ²) from its ψ = 0 value
    /// (the eigenvalues are even in ψ), it does not jump to B. Bound from second-order
    /// perturbation of the 2×2 tensor: |2ΔA| ≤ |k₂ᵧ| ψ² + (k₂ᵧ ψ)²/gap with gap the distance
    /// between the diagonal terms (margin 10 % for the higher orders, 1e-16 for rounding).
    #[test]
    fn rolling_association_is_continuous_in_psi(
        k1x in 0.001..0.1f64, k1y in -0.1..0.1f64, k2y in -0.1..0.1f64, psi in -1e-3..1e-3f64,
    ) {
        let gap = (k1x - k1y - k2y).abs();
        prop_assume!(gap > 1e-3);
        let k = PrincipalCurvatures {
            wheel_rolling: k1x, wheel_lateral: k1y, rail_rolling: 0.0, rail_lateral: k2y,
        };
        let (a0, b0) = relative_curvatures(&k, 0.0);
        let (a, b) = relative_curvatures(&k, psi);
        let bound = 0.5 * 1.1 * (k2y.abs() * psi * psi + (k2y * psi).powi(2) / gap) + 1e-16;
        prop_assert!((a - a0).abs() <= bound && (b - b0).abs() <= bound);
        prop_assert!((a - a0).abs() < (a - b0).abs());
    }

    /// Swapping A and B swaps a and b (the physics is symmetric; the implementation orders the
    /// curvatures first, so both run the same operations: equal to the bit, as measured over
    /// 3000 draws).
    #[test]
    fn swapping_a_and_b_swaps_the_axes(
        a in 1e-6..1.0f64, b in 1e-6..1.0f64, load in 1.0..1e6f64,
        method in prop_oneof![Just(EllipseMethod::Exact), Just(EllipseMethod::Paper)],
    ) {
        let x = solve(a, b, load, E_STEEL, method);
        let y = solve(b, a, load, E_STEEL, method);
        prop_assert_eq!(x.a_mm.to_bits(), y.b_mm.to_bits());
        prop_assert_eq!(x.b_mm.to_bits(), y.a_mm.to_bits());
        prop_assert_eq!(x.p0_mpa.to_bits(), y.p0_mpa.to_bits());
        prop_assert_eq!(x.approach_mm.to_bits(), y.approach_mm.to_bits());
    }

    /// Hertz scaling: a, b ∝ P^(1/3), p0 ∝ P^(1/3), δ ∝ P^(2/3), so 8 P doubles a, b and p0
    /// and quadruples δ (Johnson 1985, §4.2). Measured exact over 3000 draws (8 is a power of
    /// two and cbrt(8x) = 2 cbrt(x) to the bit here); 4.5e-16, two ulps, allows another
    /// libm's cbrt.
    #[test]
    fn eight_times_the_load_doubles_a_b_p0(
        a in 1e-6..1.0f64, b in 1e-6..1.0f64, load in 1.0..1e6f64,
        method in prop_oneof![Just(EllipseMethod::Exact), Just(EllipseMethod::Paper)],
    ) {
        let x = solve(a, b, load, E_STEEL, method);
        let y = solve(a, b, 8.0 * load, E_STEEL, method);
        const TOL: f64 = 4.5e-16;
        prop_assert!(rel(y.a_mm, 2.0 * x.a_mm) <= TOL);
        prop_assert!(rel(y.b_mm, 2.0 * x.b_mm) <= TOL);
        prop_assert!(rel(y.p0_mpa, 2.0 * x.p0_mpa) <= TOL);
        prop_assert!(rel(y.approach_mm, 4.0 * x.approach_mm) <= TOL);
    }

    /// The paper's method never panics or returns NaN for valid input: every result is finite
    /// and carries a stop reason.
    #[test]
    fn paper_method_is_finite(a in 1e-300..1.0f64, b in 1e-300..1.0f64) {
        let c = solve(a, b, 1e4, E_STEEL, EllipseMethod::Paper);
        prop_assert!(c.a_mm.is_finite() && c.b_mm.is_finite() && c.a_mm > 0.0 && c.b_mm > 0.0);
        prop_assert!(c.p0_mpa.is_finite() && c.approach_mm.is_finite());
        prop_assert!(c.eccentricity > 0.0 && c.eccentricity < 1.0);
    }
}

/// The paper's series (Eqs. 15-18, terms down to 1e-3) against the exact K and E. Expected
/// behaviour from the paper's own statement and the project's reference notes: accurate to
/// the 1e-3 level for small e, per-cent errors in K as e -> 1 (the series cannot follow K's
/// logarithmic singularity), E much better.
#[test]
fn paper_series_error() {
    let (k0, e0) = accuracy::series_error(0.3);
    // e = 0.3: the terms fall below 1e-3 after three terms; the tail is what is left,
    // measured -5.2e-6 (K) and 1.5e-5 (E) relative; bound about twice the larger.
    assert!(k0.abs() < 3e-5 && e0.abs() < 3e-5, "{k0} {e0}");
    let (k1, e1) = accuracy::series_error(0.99);
    // Measured: K -1.0 %, E +0.8 % (the K series is too small, E too large; hertz.md's 31 %
    // and 6 % are for four fixed terms, the 1e-3 threshold sums ~100 terms here).
    assert!(k1 < -0.005 && k1 > -0.02, "K error at e = 0.99: {k1}");
    assert!(e1 > 0.005 && e1 < 0.012, "E error at e = 0.99: {e1}");
    // Measured -17 %: K's logarithmic singularity.
    let (k2, _) = accuracy::series_error(0.9999);
    assert!(k2 < -0.1, "K error at e = 0.9999: {k2}");
}

/// Prints the accuracy table of the paper's method (copied into the module docs of
/// src/hertz/mod.rs) and asserts its known behaviour:
/// `cargo test --test hertz -- --nocapture paper_error_table`.
#[test]
fn paper_error_table() {
    println!(
        "{:>8} {:>11} {:>11} {:>11} {:>11} {:>5} {:>12}",
        "A/B", "b/a exact", "err b/a", "err a", "err p0", "iter", "stop"
    );
    let b = 1.0 / 600.0;
    let mut rows = Vec::new();
    for ratio in [
        1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.2, 0.5, 0.8, 0.9, 0.99, 0.999, 1.0,
    ] {
        let x = solve(ratio * b, b, 7e4, E_STEEL, EllipseMethod::Exact);
        let p = solve(ratio * b, b, 7e4, E_STEEL, EllipseMethod::Paper);
        let g_exact = x.b_mm / x.a_mm;
        let err_g = (p.b_mm / p.a_mm) / g_exact - 1.0;
        let err_a = p.a_mm / x.a_mm - 1.0;
        let err_p0 = p.p0_mpa / x.p0_mpa - 1.0;
        let ratio_text = if ratio < 0.01 {
            format!("{ratio:.0e}")
        } else {
            format!("{ratio}")
        };
        println!(
            "{ratio_text:>8} {g_exact:>11.6} {err_g:>+11.2e} {err_a:>+11.2e} {err_p0:>+11.2e} {:>5} {:>12}",
            p.iterations, p.stop
        );
        // accuracy::paper_ratio_error is the same number (it is what a chart would use).
        let (err_helper, iterations) = accuracy::paper_ratio_error(ratio);
        // Measured at most 1.1e-14 apart: the helper takes b/a from the shapes, the table
        // from the semi-axes, each with its roundings.
        assert!((err_helper - err_g).abs() <= 3e-14 && iterations == p.iterations);
        rows.push((ratio, err_g, err_p0, p.stop));
    }
    let at = |r: f64| {
        rows.iter()
            .find(|row| (row.0 / r - 1.0).abs() < 1e-9)
            .unwrap()
    };
    // Elongated contacts: the K series and the loose |Δe| stop give ~10 % errors in b/a at
    // A/B = 1e-3 (hertz.md: 11 %; measured 16 %) and worse below.
    assert!(
        at(1e-3).1.abs() > 0.05 && at(1e-3).1.abs() < 0.25,
        "{:?}",
        at(1e-3)
    );
    assert!(at(1e-6).1.abs() > at(1e-3).1.abs());
    // Moderate ratios: per-cent level (measured 1.3 % at A/B = 0.1).
    assert!(
        at(0.1).1.abs() > 1e-3 && at(0.1).1.abs() < 0.03,
        "{:?}",
        at(0.1)
    );
    // Near the circle the truncated series make the update leave the domain (e² < 0): the
    // result is flagged, and b/a, being close to 1 anyway, is off by < 1e-3.
    assert_eq!(at(1.0).3, Stop::LeftDomain);
    assert!(at(1.0).1.abs() < 1e-3);
}
