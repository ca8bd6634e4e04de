//! Kalker's creep coefficients `C11`, `C22`, `C23` of the linear theory of rolling contact
//! (Kalker 1990, Table E.3; Johnson 1985, Table 8.1) as functions of the semi-axis ratio
//! `a/b` and Poisson's ratio `ν`.
//!
//! # Data
//!
//! The table is committed as data, `src/creep/kalker_table_e3.csv`, with its source in its
//! header: rows `g = 0.1, 0.2, …, 1` for `a < b` (`g = a/b`) and `a > b` (`g = b/a`), columns
//! `ν = 0, 0.25, 0.5`, three significant digits.
//!
//! # Interpolation (stated, and measured)
//!
//! * In `ν`: the parabola through the three columns, of `1/C` (as CONTACT's `linrol`
//!   interpolates). It is exact where `C ∝ 1/(1 - ν)`, which `C11` approaches for `a ≪ b`.
//!   Inside `[0, 0.5]` only: the table says nothing beyond.
//! * In `g`, between rows: `ln C` linear in `ln g`, so a power law `C ∝ g^k` is reproduced
//!   exactly. The coefficients follow power laws at both ends of the table (`C23 ∝ √g` for
//!   `a ≪ b`; `C ∝ 1/(g ln(16/g²))` for `a ≫ b`), where linear interpolation in `g` (CONTACT's
//!   choice) overshoots: at `b/a = 0.15` it gives `C11 = 8.83` for `ν = 0` against 8.32 here;
//!   Kalker's asymptote gives 7.95 there and lies 3-4 % below the table at the rows 0.1 and
//!   0.2, so the coefficient is near 8.2. Between `g = 0.4` and 1
//!   the two interpolations differ by up to 1.2 % (`C23` for `a > b`, the coefficient that
//!   changes fastest; 0.6 % for the others; test `interpolations_agree_where_the_table_is_dense`):
//!   that is the interpolation's uncertainty there, next to the table's three digits.
//!   The `ν`-parabola is taken on the two rows first, then the rows are joined in `g`.
//! * Below `g = 0.1`, Kalker's asymptotes for `g → 0` (`asymptote`), multiplied by a factor
//!   that is the table's ratio to the asymptote at `g = 0.1` and goes linearly in `g` to 1 at
//!   `g = 0`: continuous at the table's edge (the bare asymptotes jump by 1-6 % there), and
//!   the asymptote itself as `g → 0`.
//!
//! # References
//!
//! * J.J. Kalker (1990), Three-dimensional elastic bodies in rolling contact, Kluwer:
//!   Table E.3 and its asymptotes for `g → 0` (as transcribed in CONTACT's `linrol`,
//!   `src/m_hertz.f90` of github.com/eve70a/CONTACT).
//! * K.L. Johnson (1985), Contact Mechanics, Cambridge University Press, Table 8.1.

use std::f64::consts::PI;
use std::sync::OnceLock;

/// Kalker's creep coefficients of one contact ellipse (dimensionless): with `c = √(ab)` and
/// `G` the shear modulus, the linear theory's forces on the rail are `Fx = -G c² C11 ξ`,
/// `Fy = -G c² C22 η - G c³ C23 φ` (Kalker 1990, Appendix E; Johnson 1985, §8.4; see
/// [`crate::creep::linear`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    /// Longitudinal creepage to longitudinal force.
    pub c11: f64,
    /// Lateral creepage to lateral force.
    pub c22: f64,
    /// Spin to lateral force (and lateral creepage to spin moment).
    pub c23: f64,
}

/// The smallest `g = min(a/b, b/a)` of the table; below it the asymptotes apply.
pub(crate) const TABLE_G_MIN: f64 = 0.1;

/// Poisson's ratios the table's columns hold; [`kalker`] interpolates between them only.
pub(crate) const POISSON_RANGE: (f64, f64) = (0.0, 0.5);

/// The committed table (see the module docs).
const TABLE_CSV: &str = include_str!("kalker_table_e3.csv");

/// Rows per branch: `g = 0.1, …, 1`.
const ROWS: usize = 10;

/// One row: `g` and the coefficients `[C11, C22, C23]`, each at `ν = [0, 0.25, 0.5]`.
#[derive(Debug, Clone, Copy)]
struct Row {
    g: f64,
    c: [[f64; 3]; 3],
}

/// The two branches of the table (`a < b`, `a > b`), rows in increasing `g`.
#[derive(Debug)]
struct Table {
    branches: [[Row; ROWS]; 2],
}

/// The table, parsed once.
fn table() -> &'static Table {
    static TABLE: OnceLock<Table> = OnceLock::new();
    TABLE.get_or_init(|| {
        // The file is part of the source tree and checked by the tests below, not input.
        parse(TABLE_CSV).expect("src/creep/kalker_table_e3.csv is well formed")
    })
}

/// Parses the committed table; `Err` names the first line that does not fit.
fn parse(text: &str) -> Result<Table, String> {
    let mut rows: [Vec<Row>; 2] = [Vec::new(), Vec::new()];
    let data = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.starts_with('#') && !l.trim().is_empty())
        .skip(1);
    for (i, line) in data {
        let fields: Vec<&str> = line.split(',').collect();
        let bad = || format!("line {}: {line:?}", i + 1);
        let branch = match fields.first() {
            Some(&"a<b") => 0,
            Some(&"a>b") => 1,
            _ => return Err(bad()),
        };
        let numbers: Vec<f64> = fields[1..]
            .iter()
            .map(|f| f.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| bad())?;
        let [
            g,
            c11_0,
            c11_1,
            c11_2,
            c22_0,
            c22_1,
            c22_2,
            c23_0,
            c23_1,
            c23_2,
        ] = numbers[..]
        else {
            return Err(bad());
        };
        rows[branch].push(Row {
            g,
            c: [
                [c11_0, c11_1, c11_2],
                [c22_0, c22_1, c22_2],
                [c23_0, c23_1, c23_2],
            ],
        });
    }
    let mut branches = [[Row {
        g: 0.0,
        c: [[0.0; 3]; 3],
    }; ROWS]; 2];
    for (b, rows) in rows.iter_mut().enumerate() {
        rows.sort_by(|x, y| x.g.total_cmp(&y.g));
        if rows.len() != ROWS {
            return Err(format!("branch {b}: {} rows, expected {ROWS}", rows.len()));
        }
        branches[b].copy_from_slice(rows);
    }
    Ok(Table { branches })
}

/// Kalker's `C11`, `C22`, `C23` for the semi-axis ratio `a_over_b` (`a` along the rolling
/// direction) and Poisson's ratio `poisson`, interpolated as the module docs state.
///
/// # Units
///
/// Dimensionless in and out.
///
/// # Panics
///
/// Never for the documented domain: `a_over_b` positive and finite, `poisson` within
/// 0 to 0.5, the table's columns (the callers, [`super::Settings`] and the patch's semi-axes,
/// check both).
///
/// # Example
///
/// ```
/// use wheelrail::creep::coefficients::kalker;
/// // Table E.3, a/b = 1 (circle), ν = 0.25.
/// let c = kalker(1.0, 0.25);
/// assert!((c.c11 - 4.12).abs() < 1e-12 && (c.c22 - 3.67).abs() < 1e-12);
/// assert!((c.c23 - 1.47).abs() < 1e-12);
/// ```
pub fn kalker(a_over_b: f64, poisson: f64) -> Coefficients {
    debug_assert!(a_over_b > 0.0 && a_over_b.is_finite(), "a/b = {a_over_b}");
    let (branch, g) = if a_over_b <= 1.0 {
        (0, a_over_b)
    } else {
        (1, 1.0 / a_over_b)
    };
    if g >= TABLE_G_MIN {
        return to_coefficients(table_at(branch, g, poisson));
    }
    // Asymptote, corrected towards the table's row at g = 0.1 (module docs).
    let at_edge = table_at(branch, TABLE_G_MIN, poisson);
    let asym_edge = asymptote_array(branch, TABLE_G_MIN, poisson);
    let asym = asymptote_array(branch, g, poisson);
    let blend = g / TABLE_G_MIN;
    to_coefficients(std::array::from_fn(|k| {
        asym[k] * (1.0 + blend * (at_edge[k] / asym_edge[k] - 1.0))
    }))
}

/// Kalker's asymptotic creep coefficients for `g = min(a/b, b/a) → 0` (Kalker 1990,
/// Appendix E, as in CONTACT's `linrol`), with `Λ = ln(16/g²)`:
///
/// * `a ≪ b` (`g = a/b`): `C11 = π²/(4(1-ν))`, `C22 = π²/4`,
///   `C23 = π√g/(3(1-ν)) · (1 + ν(ln(16/g) - 5))`;
/// * `a ≫ b` (`g = b/a`): `C11 = 2π/((Λ - 2ν) g) · (1 + (3 - ln 4)/(Λ - 2ν))`,
///   `C22 = 2π/g · (1 + (1-ν)(3 - ln 4)/((1-ν)Λ + 2ν)) / ((1-ν)Λ + 2ν)`,
///   `C23 = 2π/(3 g^{3/2} ((1-ν)Λ - 2 + 4ν))`.
///
/// [`kalker`] uses them below `g = 0.1`; here for the tests (which check the closed forms of
/// the limits `a ≪ b`).
#[cfg(test)]
fn asymptote(a_over_b: f64, poisson: f64) -> Coefficients {
    let (branch, g) = if a_over_b <= 1.0 {
        (0, a_over_b)
    } else {
        (1, 1.0 / a_over_b)
    };
    to_coefficients(asymptote_array(branch, g, poisson))
}

fn to_coefficients([c11, c22, c23]: [f64; 3]) -> Coefficients {
    Coefficients { c11, c22, c23 }
}

/// [`asymptote`] as `[C11, C22, C23]` for a branch (0: `a < b`, 1: `a > b`).
fn asymptote_array(branch: usize, g: f64, nu: f64) -> [f64; 3] {
    if branch == 0 {
        let c11 = PI * PI / (4.0 * (1.0 - nu));
        let c22 = PI * PI / 4.0;
        let c23 = PI * g.sqrt() / (3.0 * (1.0 - nu)) * (1.0 + nu * ((16.0 / g).ln() - 5.0));
        [c11, c22, c23]
    } else {
        let lambda = (16.0 / (g * g)).ln();
        let k = 3.0 - 4.0_f64.ln();
        let c11 = 2.0 * PI / ((lambda - 2.0 * nu) * g) * (1.0 + k / (lambda - 2.0 * nu));
        let d = (1.0 - nu) * lambda + 2.0 * nu;
        let c22 = 2.0 * PI / g * (1.0 + (1.0 - nu) * k / d) / d;
        let c23 = 2.0 * PI / (3.0 * g.powf(1.5) * ((1.0 - nu) * lambda - 2.0 + 4.0 * nu));
        [c11, c22, c23]
    }
}

/// The parabola through `1/C` at `ν = 0, 0.25, 0.5`, evaluated at `nu`.
fn across_poisson(c: [f64; 3], nu: f64) -> f64 {
    // Lagrange weights of the nodes 0, 0.25, 0.5.
    let w0 = 8.0 * (nu - 0.25) * (nu - 0.5);
    let w1 = -16.0 * nu * (nu - 0.5);
    let w2 = 8.0 * nu * (nu - 0.25);
    1.0 / (w0 / c[0] + w1 / c[1] + w2 / c[2])
}

/// The table's `[C11, C22, C23]` at `g` in `[0.1, 1]` on a branch, interpolated in `ν` on the
/// two rows around `g`, then with `ln C` linear in `ln g`.
fn table_at(branch: usize, g: f64, nu: f64) -> [f64; 3] {
    let rows = &table().branches[branch];
    let i = rows[1..ROWS - 1].iter().take_while(|r| r.g <= g).count();
    let (lo, hi) = (&rows[i], &rows[i + 1]);
    let t = (g / lo.g).ln() / (hi.g / lo.g).ln();
    std::array::from_fn(|k| {
        let (c_lo, c_hi) = (across_poisson(lo.c[k], nu), across_poisson(hi.c[k], nu));
        c_lo * (c_hi / c_lo).powf(t)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// CONTACT's interpolation in `g` (linear in `g`, after `ν`), for the comparison.
    fn linear_in_g(branch: usize, g: f64, nu: f64) -> [f64; 3] {
        let rows = &table().branches[branch];
        let i = rows[1..ROWS - 1].iter().take_while(|r| r.g <= g).count();
        let (lo, hi) = (&rows[i], &rows[i + 1]);
        let t = (g - lo.g) / (hi.g - lo.g);
        std::array::from_fn(|k| {
            let (c_lo, c_hi) = (across_poisson(lo.c[k], nu), across_poisson(hi.c[k], nu));
            c_lo + t * (c_hi - c_lo)
        })
    }

    fn ratio_of(branch: usize, g: f64) -> f64 {
        if branch == 0 { g } else { 1.0 / g }
    }

    #[test]
    fn the_table_parses_with_both_branches_meeting_at_the_circle() {
        let t = table();
        for b in 0..2 {
            let gs: Vec<f64> = t.branches[b].iter().map(|r| r.g).collect();
            let expected: Vec<f64> = (1..=10).map(|i| f64::from(i) / 10.0).collect();
            assert_eq!(gs, expected);
        }
        // g = 1 is one ellipse (a circle): the two branches' rows agree exactly.
        assert_eq!(t.branches[0][9].c, t.branches[1][9].c);
    }

    #[test]
    fn table_values_are_returned_at_the_nodes() {
        // Every node of the table, every column: the interpolation passes through it (the
        // parabola in ν reproduces its nodes up to rounding: measured one ulp, bound two).
        let t = table();
        for branch in 0..2 {
            for row in &t.branches[branch] {
                for (m, nu) in [0.0, 0.25, 0.5].into_iter().enumerate() {
                    let c = kalker(ratio_of(branch, row.g), nu);
                    for (k, got) in [c.c11, c.c22, c.c23].into_iter().enumerate() {
                        let want = row.c[k][m];
                        assert!(
                            (got / want - 1.0).abs() < 4.5e-16,
                            "branch {branch} g {} nu {nu}: {got} vs {want}",
                            row.g
                        );
                    }
                }
            }
        }
        // Two values quoted from Table E.3 directly: a/b = 0.5 (a < b), ν = 0.5: C23 = 1.07;
        // b/a = 0.2, ν = 0.25: C22 = 8.14 (measured exact; two ulps of 8.14 allowed).
        assert!((kalker(0.5, 0.5).c23 - 1.07).abs() < 4e-15);
        assert!((kalker(5.0, 0.25).c22 - 8.14).abs() < 4e-15);
    }

    #[test]
    fn poisson_zero_makes_c11_equal_c22() {
        // A property of Kalker's theory that the table shows in every row: for ν = 0 the
        // longitudinal and lateral problems are the same. It holds between the rows too
        // (measured within two ulps).
        for i in 0..200 {
            let a_over_b = 10f64.powf(-2.0 + 4.0 * f64::from(i) / 199.0);
            let c = kalker(a_over_b, 0.0);
            assert!((c.c11 / c.c22 - 1.0).abs() < 1e-15, "a/b {a_over_b}");
        }
    }

    #[test]
    fn coefficients_grow_with_poisson_ratio_and_are_continuous() {
        // Table E.3 grows with ν in every row (C22 for a ≪ b only by 0.01 per 0.25); the
        // interpolation keeps that, and has no jump at the rows nor at the table's edge.
        let mut previous: Option<[f64; 3]> = None;
        for i in 0..=4000 {
            let a_over_b = 10f64.powf(-2.0 + 4.0 * f64::from(i) / 4000.0);
            let lo = kalker(a_over_b, 0.1);
            let hi = kalker(a_over_b, 0.4);
            assert!(
                lo.c11 < hi.c11 && lo.c22 <= hi.c22 && lo.c23 < hi.c23,
                "{a_over_b}"
            );
            let now = [hi.c11, hi.c22, hi.c23];
            if let Some(p) = previous {
                // Steps of 0.23 % in a/b: a coefficient moves by less than 0.4 % (C23 scales
                // like (b/a)^-1.5 for a ≫ b, the steepest of them), so nothing jumps.
                for k in 0..3 {
                    assert!((now[k] / p[k] - 1.0).abs() < 4e-3, "{a_over_b} k {k}");
                }
            }
            previous = Some(now);
        }
    }

    #[test]
    fn asymptotes_are_reached_as_the_ellipse_narrows() {
        // Correction factor 1 + (g/0.1)(table/asymptote - 1): at g = 1e-4 the result is
        // within 0.01 % of Kalker's asymptote (the factor's deviation is at most 6 % at
        // g = 0.1, times g/0.1 = 1e-3).
        for nu in [0.0, 0.28, 0.5] {
            for a_over_b in [1e-4, 1e4] {
                let c = kalker(a_over_b, nu);
                let a = asymptote(a_over_b, nu);
                for (x, y) in [(c.c11, a.c11), (c.c22, a.c22), (c.c23, a.c23)] {
                    assert!(
                        (x / y - 1.0).abs() < 1e-4,
                        "a/b {a_over_b} nu {nu}: {x} {y}"
                    );
                }
            }
        }
        // Closed forms of the limits: a ≪ b, C11 = π²/(4(1-ν)), C22 = π²/4 (Kalker 1990;
        // measured exact, two ulps allowed).
        let a = asymptote(1e-9, 0.25);
        assert!((a.c11 - PI * PI / 3.0).abs() < 1e-15);
        assert!((a.c22 - PI * PI / 4.0).abs() < 1e-15);
        // The bare asymptotes lie within 7 % of the table's last rows (how far the
        // correction has to reach).
        for branch in 0..2 {
            for nu in [0.0, 0.25, 0.5] {
                let t = table_at(branch, TABLE_G_MIN, nu);
                let a = asymptote_array(branch, TABLE_G_MIN, nu);
                for k in 0..3 {
                    assert!((t[k] / a[k] - 1.0).abs() < 0.07, "{branch} {nu} {k}");
                }
            }
        }
    }

    #[test]
    fn interpolations_agree_where_the_table_is_dense() {
        // ln-ln against CONTACT's linear interpolation in g, at every tenth of a row from
        // g = 0.4 to 1 on both branches: up to 1.2 % for C23 (a > b), 0.6 % for C11 and C22
        // (module docs). Near g = 0.1 on the a > b side they differ by up to 7 %.
        let mut worst = [0.0f64; 3];
        for branch in 0..2 {
            for i in 0..=60 {
                let g = 0.4 + 0.01 * f64::from(i);
                for nu in [0.0, 0.28, 0.5] {
                    let x = table_at(branch, g, nu);
                    let y = linear_in_g(branch, g, nu);
                    for k in 0..3 {
                        worst[k] = worst[k].max((x[k] / y[k] - 1.0).abs());
                    }
                }
            }
        }
        assert!(
            worst[0] < 6e-3 && worst[1] < 6e-3 && worst[2] < 1.3e-2,
            "{worst:?}"
        );
        let at = |g| table_at(1, g, 0.0)[0] / linear_in_g(1, g, 0.0)[0] - 1.0;
        // Measured -5.775 %, quoted to a tenth of a per cent.
        assert!((at(0.15) + 0.058).abs() < 1e-3, "{}", at(0.15));
    }
}
