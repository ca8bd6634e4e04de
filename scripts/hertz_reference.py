#!/usr/bin/env python3
"""Reference Hertz ellipses at 50 significant digits, for tests/hertz.rs.

Regenerate with:

    python3 scripts/hertz_reference.py > tests/data/hertz_reference.csv

With `--fit` it prints instead the Chebyshev fits of the Newton starting value used in
src/hertz/exact.rs (START_PIECES): ln(b/a) - (2/3) ln(A/B) on pieces of x = ln(A/B), as
polynomials in t = (2x - lo - hi)/(hi - lo), highest degree first, with the fit's error bound.

Requires mpmath (tested with 1.3). Independent of the Rust code: the shape equation is solved
in its textbook form (Johnson 1985, §4.2; paper Eq. 14) with mpmath's ellipk/ellipe and
findroot, at a working precision of 50 digits (the cancellation near the circle costs at most
~25 of them for the cases below).

For A' = min(A, B), B' = max(A, B), g = b/a <= 1, m = 1 - g^2:

    A'/B' = g^2 (K(m) - E(m)) / (E(m) - g^2 K(m))            (paper Eq. 14)
    a_major^3 = 3 P (K - E) / (2 pi E* m A')                   (paper Eq. 20)
    b_minor = g a_major,  p0 = 3 P / (2 pi a b)                (paper Eq. 11)
    approach = 3 P K / (2 pi a_major E*)                       (Johnson 1985, §4.2)

and a_mm is reported along A, b_mm along B. Inputs are written as the exact decimal expansion
of the f64 the test will read (repr), and the computation uses exactly that binary value.
"""

import sys

import mpmath as mp

mp.mp.dps = 50


def shape(ratio):
    """g = b/a in (0, 1] for the curvature ratio A'/B' in (0, 1]."""
    if ratio == 1:
        return mp.mpf(1)

    def residual(u):
        g = mp.exp(u)
        m = 1 - g * g
        k, e = mp.ellipk(m), mp.ellipe(m)
        return mp.log(g * g * (k - e) / (e - g * g * k)) - mp.log(ratio)

    # Start: Greenwood's (A/B)^(2/3), then the secant method in ln g.
    u0 = mp.log(ratio) * 2 / 3
    u = mp.findroot(residual, (u0, u0 * mp.mpf("1.01")), solver="secant", tol=mp.mpf(10) ** -45)
    return mp.exp(u)


def ellipse(a_curv, b_curv, load, e_star):
    small, large = min(a_curv, b_curv), max(a_curv, b_curv)
    g = shape(small / large)
    if g == 1:
        k, d = mp.pi / 2, mp.pi / 4
    else:
        m = 1 - g * g
        k, e = mp.ellipk(m), mp.ellipe(m)
        d = (k - e) / m
    major = mp.cbrt(3 * load * d / (2 * mp.pi * e_star * small))
    minor = g * major
    p0 = 3 * load / (2 * mp.pi * major * minor)
    approach = 3 * load * k / (2 * mp.pi * major * e_star)
    if a_curv <= b_curv:
        return major, minor, p0, approach
    return minor, major, p0, approach


def cases():
    """(A, B, P, E*) as Python floats (f64)."""
    e_steel = 210000.0 / (2.0 * (1.0 - 0.3 * 0.3))
    b = 1.0 / 600.0
    # 41 ratios log-spaced over [1e-6, 1], the UIC wheel load and steel.
    for i in range(41):
        ratio = 10.0 ** (-6.0 + 6.0 * i / 40.0)
        yield ratio * b, b, 70000.0, e_steel
    # Extreme ratios, near-circles, A > B (a is then the minor, rolling axis), other loads and
    # moduli.
    for ratio in (1e-9, 1e-8, 1e-7, 1.0 - 1e-3, 1.0 - 1e-6, 1.0 - 1e-9, 1.0 - 2.0**-52):
        yield ratio * b, b, 70000.0, e_steel
    yield 0.02, 1.0 / 600.0, 70000.0, e_steel
    yield 1.0 / 13.0, 1.0 / 920.0, 20000.0, e_steel
    yield 0.05, 0.05, 100.0, e_steel
    yield 1.0 / 920.0, 1.0 / 300.0, 1000.0, 1.0e5
    yield 1.0 / 920.0, 1.0 / 300.0, 1.5e5, 7.0e4
    yield 3.7e-4, 0.8, 12.5, 2.0e3


# Pieces of ln(A/B) for the starting-value fits and the number of coefficients of each;
# chosen so that every piece is fitted to better than 1e-9 in ln(b/a).
FIT_PIECES = ((-3.0, 0.0, 13), (-10.0, -3.0, 13), (-28.0, -10.0, 13))


def fit():
    mp.mp.dps = 30
    for lo, hi, n in FIT_PIECES:

        def deviation(t):
            x = lo + (t + 1) / 2 * (hi - lo)
            return mp.log(shape(mp.exp(x))) - x * 2 / 3

        poly, err = mp.chebyfit(deviation, [-1, 1], n, error=True)
        coeffs = ", ".join(repr(float(c)) for c in poly)
        print(f"// lo = {lo}, hi = {hi}, max error {mp.nstr(err, 3)}")
        print(f"[{coeffs}]")


def main():
    if sys.argv[1:] == ["--fit"]:
        fit()
        return
    out = sys.stdout
    out.write("# Hertz ellipse references from scripts/hertz_reference.py (mpmath, 50 digits).\n")
    out.write("# Regenerate: python3 scripts/hertz_reference.py > tests/data/hertz_reference.csv\n")
    out.write("A_per_mm,B_per_mm,load_N,e_star_MPa,a_mm,b_mm,p0_MPa,approach_mm\n")
    for a_curv, b_curv, load, e_star in cases():
        inputs = [a_curv, b_curv, load, e_star]
        a, b, p0, approach = ellipse(*(mp.mpf(x) for x in inputs))
        fields = [repr(x) for x in inputs] + [mp.nstr(v, 20, min_fixed=1, max_fixed=0) for v in (a, b, p0, approach)]
        out.write(",".join(fields) + "\n")


if __name__ == "__main__":
    main()
