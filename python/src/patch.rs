//! One contact patch from plain numbers: the Hertz ellipse (`hertz_ellipse`) and the creep
//! forces (`creep_forces`), each for floats or for arrays of cases.

use super::*;

/// The Hertz contact ellipse of two bodies of one material, as ``wheelrail hertz`` gives
/// it (the exact method to machine precision, or the paper's numerics).
///
/// Each of ``A_per_mm``, ``B_per_mm``, ``load_N`` is a float or a 1-D array; arrays have
/// one length and floats apply to every case. The inputs must lie in the command line's
/// ranges (curvatures at most 1/mm in magnitude), checked in its order: load, modulus,
/// Poisson's ratio, curvatures.
///
/// Parameters
/// ----------
/// A_per_mm, B_per_mm : float or array_like
///     Relative curvatures in the rolling and the lateral direction (1/mm).
/// load_N : float or array_like
///     Normal load (N, 1 N to 1 MN).
/// young_GPa : float
///     Young's modulus of both bodies (GPa, 1 to 1000).
/// poisson : float
///     Poisson's ratio of both bodies, in [0, 0.5).
/// method : {"exact", "paper"}
///     The numerics.
///
/// Returns
/// -------
/// dict
///     ``a_mm`` (semi-axis along the rolling direction), ``b_mm`` (lateral), ``p0_MPa``
///     (maximum pressure), ``approach_mm``, ``e`` (eccentricity), ``method``,
///     ``iterations`` and ``stop`` (``converged``, ``iteration_cap``, ``left_domain``, or
///     ``not_hertzian`` where A or B or A + B is not positive: NaN numbers there, not an
///     error). Floats for floats in, ``float64``/``str`` arrays for arrays in.
///
/// Raises
/// ------
/// InputError
///     A load, material or curvature outside what a wheel and rail can be (the message of
///     ``wheelrail hertz`` after the argument's name, ``case i:`` before it for arrays),
///     arrays of different lengths.
#[pyfunction]
#[pyo3(signature = (A_per_mm, B_per_mm, load_N, young_GPa = 210.0, poisson = 0.3, method = "exact"))]
#[allow(non_snake_case)] // the units of the names, as in the CLI's columns
pub(crate) fn hertz_ellipse<'py>(
    py: Python<'py>,
    A_per_mm: Values<'py>,
    B_per_mm: Values<'py>,
    load_N: Values<'py>,
    young_GPa: f64,
    poisson: f64,
    method: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let method = [EllipseMethod::Exact, EllipseMethod::Paper]
        .into_iter()
        .find(|m| m.to_string() == method)
        .ok_or_else(|| one_of("method", method, ["exact", "paper"]))?;
    let cases = Values::broadcast([
        ("A_per_mm", &A_per_mm),
        ("B_per_mm", &B_per_mm),
        ("load_N", &load_N),
    ])?;
    let scalar = cases.is_none();
    let [a, b, load] = cases.unwrap_or_else(|| [A_per_mm.one(), B_per_mm.one(), load_N.one()]);
    plausible("load_N", &plausible::NORMAL_LOAD_N, &load, scalar)?;
    plausible("young_GPa", &plausible::YOUNG_GPA, &[young_GPa], true)?;
    plausible("poisson", &plausible::POISSON, &[poisson], true)?;
    plausible("A_per_mm", &plausible::CURVATURE_PER_MM, &a, scalar)?;
    plausible("B_per_mm", &plausible::CURVATURE_PER_MM, &b, scalar)?;
    // GPa to MPa, as `wheelrail hertz` converts --young-gpa.
    let material = Material::new(young_GPa * 1e3, poisson).map_err(input)?;
    let e_star = hertz::effective_modulus(&material, &material);
    let contacts = detached(py, move || {
        (0..a.len())
            .map(|i| {
                hertz::ellipse(a[i], b[i], load[i], e_star, method).map_err(|e| {
                    if scalar {
                        e.to_string()
                    } else {
                        format!("case {i}: {e}")
                    }
                })
            })
            .collect::<Result<Vec<Contact>, String>>()
    })?
    .map_err(input)?;
    // A case without an ellipse: NaN numbers and 0 iterations, as the command line's row.
    let column = |f: fn(&hertz::Ellipse) -> f64, none: f64| -> Vec<f64> {
        contacts
            .iter()
            .map(|c| c.ellipse().map_or(none, f))
            .collect()
    };
    let numbers = [
        ("a_mm", column(|e| e.a_mm, f64::NAN)),
        ("b_mm", column(|e| e.b_mm, f64::NAN)),
        ("p0_MPa", column(|e| e.p0_mpa, f64::NAN)),
        ("approach_mm", column(|e| e.approach_mm, f64::NAN)),
        ("e", column(|e| e.eccentricity, f64::NAN)),
        ("iterations", column(|e| f64::from(e.iterations), 0.0)),
    ];
    let stop: Vec<String> = contacts
        .iter()
        .map(|c| {
            c.ellipse()
                .map_or("not_hertzian".into(), |e| e.stop.to_string())
        })
        .collect();
    let d = PyDict::new(py);
    for (name, values) in numbers {
        if scalar {
            d.set_item(name, values[0])?;
        } else {
            d.set_item(name, PyArray1::from_vec(py, values))?;
        }
        if name == "e" {
            // The command line's column order: method after e.
            d.set_item("method", method.to_string())?;
        }
    }
    if scalar {
        d.set_item("stop", &stop[0])?;
    } else {
        d.set_item("stop", text_array(py, &stop)?)?;
    }
    Ok(d)
}

/// The tangential problem of one elliptic contact patch, as ``wheelrail creep`` solves it.
///
/// Parameters
/// ----------
/// a_mm, b_mm : float
///     Semi-axes of the contact ellipse in the rolling and the lateral direction (mm, 0.01
///     to 50).
/// normal_force_N : float
///     Normal force (N, 1 to 1e6).
/// xi, eta : float
///     Longitudinal and lateral creepage: the rail's velocity relative to the wheel over the
///     rolling speed (-1 to 1).
/// phi_per_mm : float
///     Spin creepage (1/mm, -0.1 to 0.1).
/// mu : float
///     Coefficient of friction (0.01 to 1).
/// shear_modulus_GPa : float
///     Shear modulus of both bodies (GPa, 1 to 1000).
/// poisson : float
///     Poisson's ratio of both bodies (0 to 0.5).
/// method : {"fastsim", "linear", "polach"}
///     The tangential model: Kalker's FASTSIM (32 × 32 strips), his linear theory, or
///     Polach's method.
/// bound : {"parabolic", "elliptic"}
///     FASTSIM's traction bound.
///
/// Returns
/// -------
/// dict
///     The row of ``wheelrail creep``: ``method``, Kalker's ``c11``, ``c22``, ``c23``,
///     ``fx_N``, ``fy_N`` (the wheel's force on the rail in the patch's contact frame: x
///     rolling, y lateral; a positive creepage gives a negative force), ``mz_Nmm`` (NaN for
///     the models without a spin moment), ``adhesion_fraction``.
///
/// Raises
/// ------
/// InputError
///     A value outside its range (the message of ``wheelrail creep`` after the argument's
///     name), an unknown method or bound.
#[pyfunction]
#[pyo3(signature = (a_mm, b_mm, normal_force_N, xi, eta, phi_per_mm, mu = 0.3, shear_modulus_GPa = 82.0, poisson = 0.28, method = "fastsim", bound = "parabolic"))]
#[allow(non_snake_case, clippy::too_many_arguments)] // the command's options, with their units
pub(crate) fn creep_forces<'py>(
    py: Python<'py>,
    a_mm: f64,
    b_mm: f64,
    normal_force_N: f64,
    xi: f64,
    eta: f64,
    phi_per_mm: f64,
    mu: f64,
    shear_modulus_GPa: f64,
    poisson: f64,
    method: &str,
    bound: &str,
) -> PyResult<Bound<'py, PyDict>> {
    use wheelrail::creep::command::{CommandError, PatchInputs, RANGES, solve};
    use wheelrail::creep::{Bound as TractionBound, Method};
    let methods = [Method::Fastsim, Method::Linear, Method::Polach];
    let method = methods
        .into_iter()
        .find(|m| m.to_string() == method)
        .ok_or_else(|| one_of("method", method, ["fastsim", "linear", "polach"]))?;
    let bounds = [TractionBound::Parabolic, TractionBound::Elliptic];
    let bound = bounds
        .into_iter()
        .find(|b| b.to_string() == bound)
        .ok_or_else(|| one_of("bound", bound, ["parabolic", "elliptic"]))?;
    let inputs = PatchInputs {
        a_mm,
        b_mm,
        normal_force_n: normal_force_N,
        xi,
        eta,
        phi_per_mm,
        mu,
        shear_modulus_gpa: shear_modulus_GPa,
        poisson,
        method,
        bound,
    };
    // The arguments' names, in the order of the command's options (`RANGES`).
    const NAMES: [&str; 9] = [
        "a_mm",
        "b_mm",
        "normal_force_N",
        "xi",
        "eta",
        "phi_per_mm",
        "mu",
        "shear_modulus_GPa",
        "poisson",
    ];
    let t = detached(py, move || solve(&inputs))?.map_err(|e| match e {
        CommandError::Implausible { range, value } => {
            let name = RANGES
                .iter()
                .position(|r| r.key == range.key)
                .map_or(range.key, |i| NAMES[i]);
            input(range.refusal(name, value))
        }
        CommandError::Creep(e) => input(e),
        e => input(e),
    })?;
    let d = PyDict::new(py);
    d.set_item("method", method.to_string())?;
    // `+ 0.0` turns a negative zero into 0, as the command line prints it.
    let numbers = [
        ("c11", t.coefficients.c11),
        ("c22", t.coefficients.c22),
        ("c23", t.coefficients.c23),
        ("fx_N", t.fx_n + 0.0),
        ("fy_N", t.fy_n + 0.0),
        ("mz_Nmm", t.mz_nmm + 0.0),
        ("adhesion_fraction", t.adhesion_fraction),
    ];
    for (name, value) in numbers {
        d.set_item(name, value)?;
    }
    Ok(d)
}
