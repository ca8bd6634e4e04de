//! Creep forces against the theory they must reduce to: odd symmetry in the creepages,
//! Kalker's linear theory at small creepage, saturation at μ FN at large creepage, and
//! Polach's method at its limits.

use wheelrail::creep::coefficients::kalker;
use wheelrail::creep::creepage::Creepages;
use wheelrail::creep::tangential::{EllipticPatch, solve};
use wheelrail::creep::{Bound, Method, Settings};

/// Steel as in CONTACT's examples: G = 82 GPa, ν = 0.28, μ = 0.3.
fn steel(method: Method) -> Settings {
    Settings::new(method, 0.3, 82_000.0, 0.28).unwrap()
}

#[test]
fn forces_are_odd_in_the_creepages() {
    // Reversing every creepage reverses every force and moment, to the bit (the models use
    // the creepages through odd operations and squares); mirroring the patch across its
    // x axis (η, φ reversed, ξ kept) reverses Fy and Mz and keeps Fx, to rounding (the strips
    // are summed in another order; measured at most 3.7e-17 μ FN in force and
    // 2.4e-16 μ FN mm in moment).
    let patch = EllipticPatch::new(6.0, 4.0, 50_000.0).unwrap();
    let cases = [
        Creepages {
            xi: 3e-4,
            eta: -5e-4,
            phi_per_mm: 2e-4,
        },
        Creepages {
            xi: -2e-3,
            eta: 1e-3,
            phi_per_mm: -1e-3,
        },
        Creepages {
            xi: 0.0,
            eta: 0.0,
            phi_per_mm: 3e-3,
        },
    ];
    for method in [Method::Fastsim, Method::Linear, Method::Polach] {
        for bound in [Bound::Parabolic, Bound::Elliptic] {
            let s = steel(method).with_bound(bound);
            for c in cases {
                let t = solve(&patch, &c, &s);
                let neg = solve(
                    &patch,
                    &Creepages {
                        xi: -c.xi,
                        eta: -c.eta,
                        phi_per_mm: -c.phi_per_mm,
                    },
                    &s,
                );
                for (x, y) in [
                    (t.fx_n, neg.fx_n),
                    (t.fy_n, neg.fy_n),
                    (t.mz_nmm, neg.mz_nmm),
                ] {
                    assert!(
                        x.to_bits() == (-y).to_bits() || (x.is_nan() && y.is_nan()),
                        "{method} {c:?}"
                    );
                }
                assert_eq!(
                    t.adhesion_fraction.to_bits(),
                    neg.adhesion_fraction.to_bits()
                );
                let mirrored = solve(
                    &patch,
                    &Creepages {
                        xi: c.xi,
                        eta: -c.eta,
                        phi_per_mm: -c.phi_per_mm,
                    },
                    &s,
                );
                let scale = 0.3 * 50_000.0;
                assert!(
                    (t.fx_n - mirrored.fx_n).abs() < 1e-16 * scale,
                    "{method} {c:?}"
                );
                assert!(
                    (t.fy_n + mirrored.fy_n).abs() < 1e-16 * scale,
                    "{method} {c:?}"
                );
                if method == Method::Fastsim {
                    assert!((t.mz_nmm + mirrored.mz_nmm).abs() < 1e-16 * scale * 5.0);
                }
            }
        }
    }
}

/// Kalker's linear theory on `patch` (forces on the rail), from its definition.
fn kalker_linear(patch: &EllipticPatch, c: &Creepages) -> (f64, f64) {
    let k = kalker(patch.a_mm() / patch.b_mm(), 0.28);
    let g = 82_000.0;
    let cc = patch.c_mm();
    (
        -g * cc * cc * k.c11 * c.xi,
        -g * cc * cc * (k.c22 * c.eta + cc * k.c23 * c.phi_per_mm),
    )
}

#[test]
fn small_creepage_tends_to_linear_theory() {
    // Pure ξ, η or φ at 1e-4 of the creepage that saturates linear theory: linear theory
    // is its own formula (measured exact; two ulps allowed), FASTSIM within 1e-3 (its
    // strips' midpoint rule across the patch: 1/(2 n²) = 5e-4 for 32 strips; measured
    // 5.7e-4), Polach within 4e-8 (his ε is 1e-4 there; the limits are exact, see
    // `creep::polach`; measured 1.6e-8), both fully adhering (adhesion fraction measured
    // 1 for FASTSIM, within 4.7e-8 of it for Polach).
    for (a, b) in [(6.0, 4.0), (3.0, 8.0), (10.0, 1.0)] {
        let patch = EllipticPatch::new(a, b, 50_000.0).unwrap();
        let k = kalker(a / b, 0.28);
        let cc = patch.c_mm();
        let t = 0.3 * 50_000.0 / 82_000.0 * 1e-4;
        for c in [
            Creepages {
                xi: t / (cc * cc * k.c11),
                eta: 0.0,
                phi_per_mm: 0.0,
            },
            Creepages {
                xi: 0.0,
                eta: t / (cc * cc * k.c22),
                phi_per_mm: 0.0,
            },
            Creepages {
                xi: 0.0,
                eta: 0.0,
                phi_per_mm: t / (cc * cc * cc * k.c23),
            },
        ] {
            let (fx, fy) = kalker_linear(&patch, &c);
            let linear = solve(&patch, &c, &steel(Method::Linear));
            assert!(
                (linear.fx_n - fx).abs() <= 4.5e-16 * fx.abs()
                    && (linear.fy_n - fy).abs() <= 4.5e-16 * fy.abs()
            );
            for (method, tol) in [(Method::Fastsim, 1e-3), (Method::Polach, 4e-8)] {
                let got = solve(&patch, &c, &steel(method));
                let (want, g) = if c.xi != 0.0 {
                    (fx, got.fx_n)
                } else {
                    (fy, got.fy_n)
                };
                assert!(
                    (g / want - 1.0).abs() < tol,
                    "{method} {a}x{b} {c:?}: {g} vs {want}"
                );
                assert!(
                    (got.adhesion_fraction - 1.0).abs() < 1e-7,
                    "{method} {c:?}: {}",
                    got.adhesion_fraction
                );
            }
        }
    }
}

#[test]
fn large_creepage_saturates_at_mu_fn() {
    // Pure ξ or η a hundred times beyond saturation: the force is μ FN (FASTSIM: to rounding,
    // its cells carry FN exactly and all slip, measured 1.1e-16; Polach: ε > 200, short by
    // 4/(3π ε³) < 1e-7, measured 3.8e-8).
    // With spin as well, FASTSIM's force stays within μ FN.
    let patch = EllipticPatch::new(6.0, 4.0, 50_000.0).unwrap();
    let mu_fn = 0.3 * 50_000.0;
    for c in [
        Creepages {
            xi: 0.5,
            eta: 0.0,
            phi_per_mm: 0.0,
        },
        Creepages {
            xi: 0.0,
            eta: -0.5,
            phi_per_mm: 0.0,
        },
        Creepages {
            xi: 0.3,
            eta: 0.4,
            phi_per_mm: 0.0,
        },
    ] {
        for (method, bound, tol) in [
            (Method::Fastsim, Bound::Parabolic, 4.5e-16),
            (Method::Fastsim, Bound::Elliptic, 4.5e-16),
            (Method::Polach, Bound::Parabolic, 1e-7),
        ] {
            let t = solve(&patch, &c, &steel(method).with_bound(bound));
            let f = t.fx_n.hypot(t.fy_n);
            assert!((f / mu_fn - 1.0).abs() < tol, "{method} {bound} {c:?}: {f}");
            // Opposite to the creepage (forces on the rail).
            assert!(t.fx_n * c.xi <= 0.0 && t.fy_n * c.eta <= 0.0);
            if method == Method::Fastsim {
                assert_eq!(t.adhesion_fraction.to_bits(), 0.0f64.to_bits());
            }
        }
    }
    let spin = Creepages {
        xi: 0.01,
        eta: 0.02,
        phi_per_mm: 0.05,
    };
    let t = solve(&patch, &spin, &steel(Method::Fastsim));
    assert!(t.fx_n.hypot(t.fy_n) <= mu_fn * (1.0 + 1e-12));
}

#[test]
fn polach_at_its_limits() {
    // Small creepage: Kalker's linear theory exactly, including the spin term (-G c³ C23 φ)
    // and combined η and φ (measured 1.3e-11 relative, bound 3e-11); large creepage: μ FN
    // (measured 8.4e-9 short at ξ = 1, bound 2e-8); the adhesion fraction 1/(1 + ε²) from 1
    // to 0 (measured 7.3e-6 at ξ = 1).
    let patch = EllipticPatch::new(5.0, 7.0, 80_000.0).unwrap();
    let s = steel(Method::Polach);
    let small = Creepages {
        xi: 0.0,
        eta: 1e-8,
        phi_per_mm: 1e-9,
    };
    let (_, fy) = kalker_linear(&patch, &small);
    let t = solve(&patch, &small, &s);
    assert!((t.fy_n / fy - 1.0).abs() < 3e-11, "{} vs {fy}", t.fy_n);
    assert!(t.mz_nmm.is_nan());
    let mut previous = 1.0;
    for k in 1..=8 {
        let c = Creepages {
            xi: 10f64.powi(k - 8),
            eta: 0.0,
            phi_per_mm: 0.0,
        };
        let t = solve(&patch, &c, &s);
        assert!(t.adhesion_fraction < previous);
        previous = t.adhesion_fraction;
    }
    assert!(
        previous < 1e-5
            && (-solve(
                &patch,
                &Creepages {
                    xi: 1.0,
                    eta: 0.0,
                    phi_per_mm: 0.0
                },
                &s
            )
            .fx_n
                / (0.3 * 80_000.0)
                - 1.0)
                .abs()
                < 2e-8
    );
}
