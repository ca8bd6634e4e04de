//! `wheelrail hertz`: one Hertz solve from the command line, printed as CSV.
//!
//! Input either as relative curvatures (`--A`, `--B`, 1/mm) or as the four signed principal
//! radii of wheel (1) and rail (2) (`--r1x --r1y --r2x --r2y`, mm, convex positive, `inf` for
//! a straight direction, principal directions aligned: ψ = 0). Both bodies have the same
//! material.
//!
//! # Output
//!
//! A header and one row:
//!
//! ```text
//! a_mm,b_mm,p0_MPa,approach_mm,e,method,iterations,stop
//! ```
//!
//! numbers in shortest round-trip form, `e` the eccentricity, `stop` the solver's
//! [`Stop`](wheelrail::Stop) (`converged`, `iteration_cap`, `left_domain`), so that a
//! non-converged paper solve is visible.
//!
//! A non-Hertzian case (`A + B <= 0`, `A <= 0` or `B <= 0`) is a result, not an error: the row
//! carries `NaN` in the numeric columns, the method, `0` iterations and `not_hertzian` in the
//! `stop` column, [`run`] returns `Ok` with the reason in words as [`Solved::note`] (printed
//! to standard error), and the exit code is 0. This follows
//! the crate's CSV convention (a row that could not be computed carries NaN and a status; it
//! is never dropped) and lets a script loop over cases without treating geometry as failure.
//! Input outside what a wheel and a rail can be is an error naming the flag, the range and
//! the likely unit mistake: the ranges are those of the scene's keys
//! (`wheelrail::plausible`: loads 1 N to 1 MN, `E` 1 to 1000 GPa, `0 <= poisson < 0.5`), and
//! radii of at least 1 mm and curvatures of at most 1/mm in magnitude (a smaller radius or a
//! larger curvature reads as metres).

use std::fmt;
use wheelrail::hertz::{
    Contact, EllipseMethod, HertzError, Material, PrincipalCurvatures, effective_modulus, ellipse,
    relative_curvatures,
};
use wheelrail::plausible::{self, Implausible, Range};

/// Arguments of `wheelrail hertz`.
#[derive(Debug, Clone, PartialEq, clap::Args)]
#[command(group(
    clap::ArgGroup::new("curvatures")
        .args(["a", "b"])
        .multiple(true)
        .conflicts_with("radii")
))]
#[command(group(
    clap::ArgGroup::new("radii")
        .args(["r1x", "r1y", "r2x", "r2y"])
        .multiple(true)
))]
pub struct HertzArgs {
    /// Relative curvature A in the rolling direction, 1/mm.
    #[arg(long = "A", value_name = "1/mm", allow_hyphen_values = true)]
    #[arg(required_unless_present = "radii")]
    pub a: Option<f64>,
    /// Relative curvature B in the lateral direction, 1/mm.
    #[arg(long = "B", value_name = "1/mm", allow_hyphen_values = true)]
    #[arg(required_unless_present = "radii")]
    pub b: Option<f64>,
    /// Wheel principal radius, rolling direction, mm (convex positive, `inf` for flat).
    #[arg(long, value_name = "mm", allow_hyphen_values = true)]
    #[arg(required_unless_present = "curvatures")]
    pub r1x: Option<f64>,
    /// Wheel principal radius, lateral direction, mm (convex positive, `inf` for flat).
    #[arg(long, value_name = "mm", allow_hyphen_values = true)]
    #[arg(required_unless_present = "curvatures")]
    pub r1y: Option<f64>,
    /// Rail principal radius, rolling direction, mm (convex positive, `inf` for flat).
    #[arg(long, value_name = "mm", allow_hyphen_values = true)]
    #[arg(required_unless_present = "curvatures")]
    pub r2x: Option<f64>,
    /// Rail principal radius, lateral direction, mm (convex positive, `inf` for flat).
    #[arg(long, value_name = "mm", allow_hyphen_values = true)]
    #[arg(required_unless_present = "curvatures")]
    pub r2y: Option<f64>,
    /// Normal load, N.
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub load: f64,
    /// Young's modulus of both bodies, GPa.
    #[arg(long, value_name = "GPa", default_value_t = 210.0)]
    pub young_gpa: f64,
    /// Poisson's ratio of both bodies.
    #[arg(long, default_value_t = 0.3, allow_hyphen_values = true)]
    pub poisson: f64,
    /// Numerical method.
    #[arg(long, default_value_t = EllipseMethod::Exact,
        value_parser = crate::named(&[EllipseMethod::Exact, EllipseMethod::Paper]))]
    pub method: EllipseMethod,
}

/// The CSV header printed by [`run`].
pub const HEADER: &str = "a_mm,b_mm,p0_MPa,approach_mm,e,method,iterations,stop";

/// What [`run`] returns: the text to print and, for a non-Hertzian case, why.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    /// Header and one row, newline-terminated (standard output).
    pub csv: String,
    /// Why the row is NaN, in words (standard error), for a non-Hertzian case.
    pub note: Option<String>,
}

/// MPa per GPa: the one unit conversion of this command.
const MPA_PER_GPA: f64 = 1e3;

/// Why [`run`] refused its arguments.
#[derive(Debug, Clone, PartialEq)]
pub enum RunError {
    /// An argument is outside what a wheel and a rail can be.
    Implausible {
        /// The flag, as typed (`--young-gpa`).
        flag: &'static str,
        /// The value and its range.
        problem: Implausible,
    },
    /// The Hertz solution itself failed ([`HertzError::NonFiniteResult`]).
    Hertz(HertzError),
}

impl fmt::Display for RunError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RunError::Implausible { flag, problem } => write!(f, "{flag}: {problem}"),
            RunError::Hertz(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for RunError {}

impl From<HertzError> for RunError {
    fn from(e: HertzError) -> Self {
        RunError::Hertz(e)
    }
}

/// `value` of `flag` checked against `range`.
fn checked(flag: &'static str, range: &'static Range, value: f64) -> Result<f64, RunError> {
    range
        .check(value)
        .map_err(|problem| RunError::Implausible { flag, problem })
}

/// Solves the case described by `args` and returns the text to print (header and one row,
/// newline-terminated) and, for a non-Hertzian case, the reason.
///
/// # Units
///
/// Inputs as documented on [`HertzArgs`]; output columns carry their unit.
///
/// # Errors
///
/// [`RunError::Implausible`] for an argument outside its range in `wheelrail::plausible`
/// (a radius left out by a library caller is NaN, and refused so), [`RunError::Hertz`] when
/// the solution overflows. A non-Hertzian geometry is **not** an error (see the module
/// docs).
///
/// # Example
///
/// ```
/// use clap::Parser;
/// use wheelrail_cli::hertz::{HertzArgs, run};
/// #[derive(Parser)]
/// struct Cli {
///     #[command(flatten)]
///     hertz: HertzArgs,
/// }
/// let cli = Cli::parse_from(["hertz", "--A", "0.05", "--B", "0.05", "--load", "100"]);
/// let out = run(&cli.hertz)?.csv;
/// assert!(out.starts_with("a_mm,b_mm,p0_MPa,approach_mm,e,method,iterations,stop\n"));
/// assert!(out.lines().nth(1).unwrap().ends_with(",exact,0,converged"));
/// // Radii in metres are refused, naming the flag and the likely mistake.
/// let metres = Cli::parse_from(["hertz", "--r1x", "0.46", "--r1y", "inf", "--r2x", "inf", "--r2y", "0.3", "--load", "7e4"]);
/// let e = run(&metres.hertz).unwrap_err().to_string();
/// assert!(e.starts_with("--r1x: 0.46 mm is not") && e.ends_with("0.46 m = 460 mm"), "{e}");
/// # Ok::<(), wheelrail_cli::hertz::RunError>(())
/// ```
pub fn run(args: &HertzArgs) -> Result<Solved, RunError> {
    let load = checked("--load", &plausible::NORMAL_LOAD_N, args.load)?;
    let young_gpa = checked("--young-gpa", &plausible::YOUNG_GPA, args.young_gpa)?;
    let poisson = checked("--poisson", &plausible::POISSON, args.poisson)?;
    let material = Material::new(young_gpa * MPA_PER_GPA, poisson)?;
    let e_star = effective_modulus(&material, &material);
    let (a, b) = match (args.a, args.b) {
        (Some(a), Some(b)) => (
            checked("--A", &plausible::CURVATURE_PER_MM, a)?,
            checked("--B", &plausible::CURVATURE_PER_MM, b)?,
        ),
        _ => {
            // clap guarantees all four radii when A and B are absent; a library caller that
            // builds HertzArgs by hand and leaves one out gets NaN, which is refused.
            let curvature = |flag: &'static str, r: Option<f64>| -> Result<f64, RunError> {
                Ok(1.0 / checked(flag, &plausible::RADIUS_MM, r.unwrap_or(f64::NAN))?)
            };
            let k = PrincipalCurvatures {
                wheel_rolling: curvature("--r1x", args.r1x)?,
                wheel_lateral: curvature("--r1y", args.r1y)?,
                rail_rolling: curvature("--r2x", args.r2x)?,
                rail_lateral: curvature("--r2y", args.r2y)?,
            };
            relative_curvatures(&k, 0.0)
        }
    };
    let (row, note) = match ellipse(a, b, load, e_star, args.method)? {
        Contact::Hertzian(c) => (
            format!(
                "{:e},{:e},{:e},{:e},{:e},{},{},{}",
                c.a_mm,
                c.b_mm,
                c.p0_mpa,
                c.approach_mm,
                c.eccentricity,
                c.method,
                c.iterations,
                c.stop
            ),
            None,
        ),
        Contact::NotHertzian(reason) => (
            format!("NaN,NaN,NaN,NaN,NaN,{},0,not_hertzian", args.method),
            Some(format!(
                "no Hertz ellipse for A = {} 1/mm, B = {} 1/mm ({reason}): the row is NaN",
                wheelrail::message::Number(a),
                wheelrail::message::Number(b)
            )),
        ),
    };
    Ok(Solved {
        csv: format!("{HEADER}\n{row}\n"),
        note,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Debug, Parser)]
    struct Cli {
        #[command(flatten)]
        hertz: HertzArgs,
    }

    fn parse(args: &[&str]) -> Result<HertzArgs, clap::Error> {
        let mut argv = vec!["hertz"];
        argv.extend_from_slice(args);
        Cli::try_parse_from(argv).map(|c| c.hertz)
    }

    fn row(out: &str) -> Vec<String> {
        let mut lines = out.lines();
        assert_eq!(lines.next(), Some(HEADER));
        let fields = lines
            .next()
            .expect("one row")
            .split(',')
            .map(String::from)
            .collect();
        assert_eq!(lines.next(), None);
        fields
    }

    fn num(s: &str) -> f64 {
        s.parse().expect("a number")
    }

    #[test]
    fn curvatures_and_radii_give_the_same_row() {
        // Wheel r = 460 mm, flat tread; rail crown 300 mm, straight: A = 1/920, B = 1/600.
        let by_curv = parse(&[
            "--A",
            "0.0010869565217391304",
            "--B",
            "0.0016666666666666668",
            "--load",
            "70000",
        ])
        .unwrap();
        let by_radii = parse(&[
            "--r1x", "460", "--r1y", "inf", "--r2x", "inf", "--r2y", "300", "--load", "70000",
        ])
        .unwrap();
        let (x, y) = (
            row(&run(&by_curv).unwrap().csv),
            row(&run(&by_radii).unwrap().csv),
        );
        for col in 0..5 {
            // 1e-15: the two inputs differ only in the rounding of 1/(2 R).
            assert!(
                (num(&x[col]) / num(&y[col]) - 1.0).abs() <= 1e-15,
                "column {col}"
            );
        }
        assert_eq!(&x[5..], ["exact", &x[6], "converged"]);
        // a along rolling (A = 1/920 < B = 1/600, so a is the major axis).
        assert!(num(&x[0]) > num(&x[1]));
    }

    #[test]
    fn paper_method_and_material_are_passed_through() {
        let args = parse(&[
            "--A",
            "0.001",
            "--B",
            "0.002",
            "--load",
            "1e5",
            "--method",
            "paper",
            "--young-gpa",
            "200",
            "--poisson",
            "0.25",
        ])
        .unwrap();
        assert_eq!(args.method, EllipseMethod::Paper);
        let r = row(&run(&args).unwrap().csv);
        assert_eq!(r[5], "paper");
        // Exact p0 for these inputs from the library; the paper method is within 5 % at
        // A/B = 0.5 (see the accuracy table in the module docs).
        let e_star = 200e3 / (2.0 * (1.0 - 0.0625));
        let exact = ellipse(0.001, 0.002, 1e5, e_star, EllipseMethod::Exact).unwrap();
        let p0 = exact.ellipse().unwrap().p0_mpa;
        assert!((num(&r[2]) / p0 - 1.0).abs() < 0.05);
    }

    #[test]
    fn non_hertzian_prints_nan_and_the_reason() {
        // Concave wheel flange root (r1y = -12 mm) against a 13 mm gauge corner: B < 0.
        let args = parse(&[
            "--r1x", "460", "--r1y", "-12", "--r2x", "inf", "--r2y", "13", "--load", "5e4",
        ])
        .unwrap();
        let r = row(&run(&args).unwrap().csv);
        assert!(r[..5].iter().all(|v| v == "NaN"));
        assert_eq!(r[7], "not_hertzian");
        let note = run(&args).unwrap().note.unwrap();
        assert!(
            note.contains("A + B <= 0") && note.contains("B = -0.0032"),
            "{note}"
        );
    }

    /// The flag and the message of `args`' refusal.
    fn refusal(args: &[&str]) -> (&'static str, String) {
        match run(&parse(args).unwrap()) {
            Err(RunError::Implausible { flag, problem }) => (flag, problem.to_string()),
            other => panic!("{args:?} gave {other:?}"),
        }
    }

    #[test]
    fn implausible_inputs_name_their_flag_and_range() {
        let radii = |r1x: &'static str| {
            [
                "--r1x", r1x, "--r1y", "inf", "--r2x", "inf", "--r2y", "300", "--load", "1",
            ]
        };
        let (flag, m) = refusal(&radii("0"));
        assert_eq!(flag, "--r1x");
        assert!(m.starts_with("0 mm is not a principal radius"), "{m}");
        let (flag, m) = refusal(&["--A", "1", "--B", "1", "--load", "-1"]);
        assert_eq!(flag, "--load");
        assert!(m.contains("expected 1 to 1000000 N"), "{m}");
        let (flag, m) = refusal(&["--A", "0.001", "--B", "2.5", "--load", "1"]);
        assert_eq!(flag, "--B");
        assert!(m.ends_with("2.5 1/m = 0.0025 1/mm"), "{m}");
    }

    /// `--poisson`, `--young-gpa` and `--load` get the verdict and the words of the scene's
    /// keys (one table, `wheelrail::plausible`).
    #[test]
    fn the_scene_and_the_command_refuse_alike() {
        use wheelrail::scene::{Scene, SceneError};
        let scene_message = |toml: &str| match Scene::from_toml(toml, "t.toml", ".".as_ref()) {
            Err(SceneError::Invalid { message, .. }) => message,
            other => panic!("{toml}: {other:?}"),
        };
        let base = ["--A", "0.001", "--B", "0.002", "--load", "7e4"];
        for (flag, value, toml) in [
            ("--poisson", "0.5", "[material]\npoisson = 0.5"),
            ("--poisson", "-0.5", "[material]\npoisson = -0.5"),
            ("--young-gpa", "210000", "[material]\nyoung_GPa = 210000.0"),
            ("--young-gpa", "0.5", "[material]\nyoung_GPa = 0.5"),
        ] {
            let mut args = base.to_vec();
            args.extend([flag, value]);
            let (f, m) = refusal(&args);
            assert_eq!(f, flag);
            assert_eq!(m, scene_message(toml));
        }
        // The load in N against the scene's kN: the same range, each in its unit.
        let (_, m) = refusal(&["--A", "0.001", "--B", "0.002", "--load", "2e6"]);
        assert_eq!(m, "2000000 N is not a wheel load; expected 1 to 1000000 N");
        assert_eq!(
            scene_message("[load]\nwheel_load_kN = 2000.0"),
            "2000 kN is not a wheel load; expected 0.001 to 1000 kN; likely a unit mistake: 2000 N = 2 kN"
        );
    }

    #[test]
    fn clap_enforces_one_complete_input_style() {
        // Mixed styles, a lone --A, three radii, nothing: all rejected by the parser.
        assert!(parse(&["--A", "1", "--B", "1", "--r1x", "1", "--load", "1"]).is_err());
        assert!(parse(&["--A", "1", "--load", "1"]).is_err());
        assert!(parse(&["--r1x", "1", "--r1y", "1", "--r2x", "1", "--load", "1"]).is_err());
        assert!(parse(&["--load", "1"]).is_err());
        assert!(parse(&["--A", "1", "--B", "1"]).is_err());
        assert!(parse(&["--A", "1", "--B", "1", "--load", "1"]).is_ok());
    }
}
