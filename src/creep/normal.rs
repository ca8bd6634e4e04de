//! The normal force of a patch from the vertical load it carries, with the tangential
//! force's vertical part, as CONTACT does.
//!
//! # The equation
//!
//! On a patch of contact angle δ the wheel presses the rail with `FN` along the normal and
//! `Fy` along `t_y = (0, cos δ, sin δ)` (forces on the rail, [`super`] module docs), so the
//! vertical load it passes down is
//!
//! ```text
//! FZ = FN cos δ - Fy(FN) sin δ
//! ```
//!
//! (CONTACT: `FZ = FN cos δ + FS sin δ` in its frame, where `FS = -Fy`). `Fy` depends on
//! `FN` through the ellipse (`a, b ∝ FN^(1/3)`) and the traction bound (`μ FN`). On a flange
//! the difference is large: in Manchester case A-2.2 at 7 mm the right wheel carries
//! 10 kN with `FN` = 14.0 kN, not the 20.6 kN of `FZ / cos δ` (`manchester_a22_given.csv`).
//!
//! # The solve
//!
//! The residual `r(FN) = FN cos δ - Fy(FN) sin δ - FZ` is solved for `FN` by the Illinois
//! variant of regula falsi on a bracket: starting from `FN0 = FZ / cos δ` and the fixed-point
//! step `FN1 = (FZ + Fy(FN0) sin δ) / cos δ`, a bracket is sought by secant steps (each at
//! most a factor 4 from the last point), then narrowed until `|r| ≤ tol · FZ`. When
//! `|Fy| ≤ μ FN` (FASTSIM, Polach without spin) and `μ tan|δ| < 1`, a root lies in
//! `[FZ/(cos δ + μ |sin δ|), FZ/(cos δ - μ |sin δ|)]` and `r` is continuous (FASTSIM's
//! discrete sums are continuous in `FN`: the cells do not move, they scale), so the solve
//! converges. Measured (test `normal_force_solve_converges_fast`, tread and flange patches
//! from free rolling to full slip, default tolerance 1e-10): 3 to 6 evaluations of FASTSIM
//! or Polach; up to 11 of linear theory, whose force grows without bound.
//!
//! No root exists when the friction pulls the wheel down harder than the normal force can
//! hold it up (`μ tan|δ| ≥ 1` with the tangential force saturated against the load: Nadal's
//! limit of flange climbing): `Outcome::NoEquilibrium`.

use super::CreepError;
use crate::hertz::NotHertzianReason;
use std::ops::ControlFlow;

/// How [`solve`] ended: the normal force that balances the vertical load (N), or why none
/// was found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Outcome {
    /// `|r| ≤ tol · FZ`.
    Converged {
        /// The normal force, N.
        normal_force_n: f64,
        /// Evaluations of the tangential model.
        iterations: u32,
    },
    /// The cap was reached first; the best point so far.
    IterationCap {
        /// The normal force of the smallest residual, N.
        normal_force_n: f64,
    },
    /// No bracket was found: no normal force balances the load.
    NoEquilibrium,
    /// The patch is not Hertzian at some normal force the solve tried.
    NotHertzian(NotHertzianReason),
}

/// Solves `FN cos δ - Fy(FN) sin δ = FZ` for `FN` (module docs); `lateral_force(FN)` is `Fy`
/// at `FN`, or why the patch has no ellipse there.
///
/// # Units
///
/// N, rad.
///
/// # Errors
///
/// Whatever `lateral_force` returns as an error.
///
/// # Example
///
/// ```
/// use wheelrail::creep::normal::{Outcome, solve};
/// // A lateral force that is a fixed 10 % of FN, on the rail along -t_y: FN (cos δ + 0.1 sin δ) = FZ.
/// let delta: f64 = 1.0;
/// let out = solve(10_000.0, delta, 1e-12, 50, |fn_n| Ok(Ok(-0.1 * fn_n)))?;
/// let Outcome::Converged { normal_force_n, .. } = out else { panic!("{out:?}") };
/// assert!((normal_force_n - 10_000.0 / (delta.cos() + 0.1 * delta.sin())).abs() < 1e-6);
/// # Ok::<(), wheelrail::creep::CreepError>(())
/// ```
pub fn solve(
    vertical_load_n: f64,
    contact_angle_rad: f64,
    tolerance: f64,
    max_iterations: u32,
    lateral_force: impl FnMut(f64) -> Result<Result<f64, NotHertzianReason>, CreepError>,
) -> Result<Outcome, CreepError> {
    let (sin_d, cos_d) = contact_angle_rad.sin_cos();
    let mut f = Residual {
        lateral_force,
        fz: vertical_load_n,
        sin_d,
        cos_d,
        tolerance,
        max_iterations,
        iterations: 0,
        best: (f64::NAN, f64::INFINITY),
    };
    let x0 = vertical_load_n / cos_d;
    let r0 = match f.at(x0)? {
        Ok(r) => r,
        Err(reason) => return Ok(Outcome::NotHertzian(reason)),
    };
    if f.converged(r0) {
        return Ok(f.converged_at(x0));
    }
    match bracket(&mut f, x0, r0)? {
        ControlFlow::Continue(ends) => illinois(&mut f, ends),
        ControlFlow::Break(outcome) => Ok(outcome),
    }
}

/// The residual `r(FN) = FN cos δ - Fy(FN) sin δ - FZ` of one solve, with its count of
/// evaluations and the point of the smallest `|r|` so far.
struct Residual<F> {
    /// `Fy(FN)`, or why the patch has no ellipse at `FN`.
    lateral_force: F,
    /// The vertical load `FZ`, N.
    fz: f64,
    /// `sin δ` of the contact angle.
    sin_d: f64,
    /// `cos δ`.
    cos_d: f64,
    /// `|r| ≤ tolerance · FZ` converges.
    tolerance: f64,
    /// The cap on `iterations`.
    max_iterations: u32,
    /// Evaluations of the tangential model so far.
    iterations: u32,
    /// `(FN, r)` of the smallest `|r|` so far.
    best: (f64, f64),
}

impl<F> Residual<F>
where
    F: FnMut(f64) -> Result<Result<f64, NotHertzianReason>, CreepError>,
{
    /// `r(fn_n)`, counted and kept if it is the best so far.
    fn at(&mut self, fn_n: f64) -> Result<Result<f64, NotHertzianReason>, CreepError> {
        self.iterations += 1;
        let r = (self.lateral_force)(fn_n)?.map(|fy| fn_n * self.cos_d - fy * self.sin_d - self.fz);
        if let Ok(r) = r
            && r.abs() < self.best.1.abs()
        {
            self.best = (fn_n, r);
        }
        Ok(r)
    }

    fn converged(&self, r: f64) -> bool {
        r.abs() <= self.tolerance * self.fz
    }

    fn converged_at(&self, fn_n: f64) -> Outcome {
        Outcome::Converged {
            normal_force_n: fn_n,
            iterations: self.iterations,
        }
    }

    fn capped(&self) -> bool {
        self.iterations >= self.max_iterations
    }
}

/// Two normal forces `(x, r(x))` whose residuals differ in sign.
type Bracket = ((f64, f64), (f64, f64));

/// From `(x0, r0)`, the fixed-point step, then secant steps (each at most a factor 4 from
/// the last point) until the residual changes sign: the bracket, or how the solve ended
/// without one (converged on the way, not Hertzian, the cap, no equilibrium).
fn bracket<F>(
    f: &mut Residual<F>,
    x0: f64,
    r0: f64,
) -> Result<ControlFlow<Outcome, Bracket>, CreepError>
where
    F: FnMut(f64) -> Result<Result<f64, NotHertzianReason>, CreepError>,
{
    let (mut x_a, mut r_a) = (x0, r0);
    let mut x_b = (x0 - r0 / f.cos_d).clamp(0.25 * x0, 4.0 * x0);
    loop {
        if f.capped() {
            return Ok(ControlFlow::Break(
                if f.best.0.is_finite() && x_b.is_finite() {
                    Outcome::IterationCap {
                        normal_force_n: f.best.0,
                    }
                } else {
                    Outcome::NoEquilibrium
                },
            ));
        }
        let r_b = match f.at(x_b)? {
            Ok(r) => r,
            Err(reason) => return Ok(ControlFlow::Break(Outcome::NotHertzian(reason))),
        };
        if f.converged(r_b) {
            return Ok(ControlFlow::Break(f.converged_at(x_b)));
        }
        if (r_a < 0.0) != (r_b < 0.0) {
            return Ok(ControlFlow::Continue(((x_a, r_a), (x_b, r_b))));
        }
        // Same sign: step on along the secant, at most a factor 4 from the last point, and
        // give up where no finite normal force is left to try.
        let secant = x_b - r_b * (x_b - x_a) / (r_b - r_a);
        let next = if secant.is_finite() && secant > 0.0 {
            secant.clamp(0.25 * x_b, 4.0 * x_b)
        } else if r_b < 0.0 {
            4.0 * x_b
        } else {
            0.25 * x_b
        };
        if !(next.is_finite() && next > f64::MIN_POSITIVE && next < 1e300) {
            return Ok(ControlFlow::Break(Outcome::NoEquilibrium));
        }
        (x_a, r_a) = (x_b, r_b);
        x_b = next;
        if x_b > 1e6 * x0 || x_b < 1e-6 * x0 {
            // Six orders of magnitude without a sign change: the residual keeps its sign
            // (no equilibrium); a real root is within a factor 1/(1 - μ tan|δ|) of x0.
            return Ok(ControlFlow::Break(Outcome::NoEquilibrium));
        }
    }
}

/// The Illinois variant of regula falsi on `bracket`: halving the weight of an end kept
/// twice in a row, until the residual converges or the bracket is a few ulps wide.
fn illinois<F>(f: &mut Residual<F>, bracket: Bracket) -> Result<Outcome, CreepError>
where
    F: FnMut(f64) -> Result<Result<f64, NotHertzianReason>, CreepError>,
{
    let ((mut lo, mut r_lo), (mut hi, mut r_hi)) = bracket;
    let mut kept: i8 = 0;
    while !f.capped() {
        let x = (lo * r_hi - hi * r_lo) / (r_hi - r_lo);
        let r = match f.at(x)? {
            Ok(r) => r,
            Err(reason) => return Ok(Outcome::NotHertzian(reason)),
        };
        if f.converged(r) || (hi - lo).abs() <= 4.0 * f64::EPSILON * x.abs() {
            return Ok(f.converged_at(x));
        }
        if (r < 0.0) == (r_lo < 0.0) {
            (lo, r_lo) = (x, r);
            if kept == 1 {
                r_hi *= 0.5;
            }
            kept = 1;
        } else {
            (hi, r_hi) = (x, r);
            if kept == -1 {
                r_lo *= 0.5;
            }
            kept = -1;
        }
    }
    Ok(Outcome::IterationCap {
        normal_force_n: f.best.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_patch_needs_one_evaluation() {
        // δ = 0: FN = FZ whatever Fy is.
        let out = solve(5000.0, 0.0, 1e-10, 10, |_| Ok(Ok(1234.0))).unwrap();
        assert_eq!(
            out,
            Outcome::Converged {
                normal_force_n: 5000.0,
                iterations: 1
            }
        );
    }

    #[test]
    fn saturated_friction_has_its_closed_form() {
        // Fy = ±μ FN (saturated): FN (cos δ ∓ μ sin δ) = FZ.
        let (fz, delta, mu) = (10_000.0, 1.2_f64, 0.3);
        for sign in [1.0, -1.0] {
            let out = solve(fz, delta, 1e-12, 60, |fn_n| Ok(Ok(sign * mu * fn_n))).unwrap();
            let Outcome::Converged { normal_force_n, .. } = out else {
                panic!("{out:?}")
            };
            let exact = fz / (delta.cos() - sign * mu * delta.sin());
            // Measured 1.6e-15 (the solve stops at 1e-12 of FZ, here well inside it).
            assert!((normal_force_n / exact - 1.0).abs() < 4e-15, "{sign}");
        }
    }

    #[test]
    fn beyond_nadals_limit_there_is_no_equilibrium() {
        // μ tan δ = 0.5 tan 1.3 = 1.8 > 1 with the friction against the load.
        let out = solve(10_000.0, 1.3, 1e-10, 60, |fn_n| Ok(Ok(0.5 * fn_n))).unwrap();
        assert_eq!(out, Outcome::NoEquilibrium);
    }

    #[test]
    fn a_nonlinear_force_converges_in_few_steps() {
        // A saturating curve like FASTSIM's (Fy ∝ FN^(2/3) at small FN, μ FN at large).
        let (fz, delta) = (10_000.0, -1.06_f64);
        let fy = |fn_n: f64| -0.3 * fn_n * (1.0 - (-(2000.0 / fn_n).powf(1.0 / 3.0) * 1.5).exp());
        let out = solve(fz, delta, 1e-10, 60, |fn_n| Ok(Ok(fy(fn_n)))).unwrap();
        let Outcome::Converged {
            normal_force_n,
            iterations,
        } = out
        else {
            panic!("{out:?}")
        };
        let r = normal_force_n * delta.cos() - fy(normal_force_n) * delta.sin() - fz;
        assert!(r.abs() <= 1e-10 * fz, "{r}");
        assert!(iterations <= 10, "{iterations}");
    }
}
