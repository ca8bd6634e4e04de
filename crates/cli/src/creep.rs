//! `wheelrail creep`: the tangential problem of one elliptic patch from the command line,
//! printed as CSV.
//!
//! # Output
//!
//! A header and one row:
//!
//! ```text
//! method,c11,c22,c23,fx_N,fy_N,mz_Nmm,adhesion_fraction
//! ```
//!
//! numbers in shortest round-trip form; forces of the wheel on the rail in the patch's
//! contact frame (x rolling, y lateral, z the normal out of the rail; a positive creepage
//! gives a negative force), Kalker's coefficients of the ellipse. `mz_Nmm` is NaN for the
//! models that give no spin moment (linear theory without `C33`, Polach), with the reason
//! on standard error.
//!
//! # Plausible values
//!
//! Every number is checked against `creep::command::RANGES` (one table, the key, its range
//! and why, shared with the Python binding through `creep::command`); a value outside is an
//! error naming the key and the range (exit code 2).

#[cfg(test)]
use wheelrail::creep::command::RANGES;
use wheelrail::creep::command::{CommandError, PatchInputs, missing_spin_moment, solve};
use wheelrail::creep::{Bound, Method};

/// Arguments of `wheelrail creep`.
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct CreepArgs {
    /// Semi-axis of the contact ellipse in the rolling direction, mm.
    #[arg(long, value_name = "mm", allow_hyphen_values = true)]
    pub a_mm: f64,
    /// Lateral semi-axis, mm.
    #[arg(long, value_name = "mm", allow_hyphen_values = true)]
    pub b_mm: f64,
    /// Normal force, N.
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub normal_force_n: f64,
    /// Longitudinal creepage ξ (velocity of the rail relative to the wheel / rolling speed).
    #[arg(long, allow_hyphen_values = true)]
    pub xi: f64,
    /// Lateral creepage η.
    #[arg(long, allow_hyphen_values = true)]
    pub eta: f64,
    /// Spin creepage φ, 1/mm.
    #[arg(long, value_name = "1/mm", allow_hyphen_values = true)]
    pub phi_per_mm: f64,
    /// Coefficient of friction.
    #[arg(long, default_value_t = 0.3, allow_hyphen_values = true)]
    pub mu: f64,
    /// Shear modulus of both bodies, GPa.
    #[arg(
        long,
        value_name = "GPa",
        default_value_t = 82.0,
        allow_hyphen_values = true
    )]
    pub shear_modulus_gpa: f64,
    /// Poisson's ratio of both bodies.
    #[arg(long, default_value_t = 0.28, allow_hyphen_values = true)]
    pub poisson: f64,
    /// Tangential model.
    #[arg(long, default_value_t = Method::Fastsim,
        value_parser = crate::named(&[Method::Fastsim, Method::Linear, Method::Polach]))]
    pub method: Method,
    /// FASTSIM's traction bound (FASTSIM only).
    #[arg(long, default_value_t = Bound::Parabolic,
        value_parser = crate::named(&[Bound::Parabolic, Bound::Elliptic]))]
    pub bound: Bound,
}

/// The CSV header printed by [`run`].
pub const HEADER: &str = "method,c11,c22,c23,fx_N,fy_N,mz_Nmm,adhesion_fraction";

/// What [`run`] returns: the text to print and, when the spin moment is NaN, why.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    /// Header and one row, newline-terminated (standard output).
    pub csv: String,
    /// Why `mz_Nmm` is NaN, in words (standard error).
    pub note: Option<String>,
}

/// Solves the patch described by `args` and returns the text to print.
///
/// # Units
///
/// Inputs as documented on [`CreepArgs`]; output columns carry their unit.
///
/// # Errors
///
/// `CommandError::Implausible` for a value outside its range in `creep::command::RANGES`
/// (NaN and infinities included), naming the key.
///
/// # Example
///
/// ```
/// use clap::Parser;
/// use wheelrail_cli::creep::{CreepArgs, run};
/// #[derive(Parser)]
/// struct Cli {
///     #[command(flatten)]
///     creep: CreepArgs,
/// }
/// let cli = Cli::parse_from([
///     "creep", "--a-mm", "6", "--b-mm", "4", "--normal-force-n", "50000",
///     "--xi", "1e-4", "--eta", "0", "--phi-per-mm", "0", "--method", "linear",
/// ]);
/// let out = run(&cli.creep)?.csv;
/// assert!(out.starts_with("method,c11,c22,c23,fx_N,fy_N,mz_Nmm,adhesion_fraction\nlinear,"));
/// # Ok::<(), wheelrail::creep::command::CommandError>(())
/// ```
pub fn run(args: &CreepArgs) -> Result<Solved, CommandError> {
    let t = solve(&PatchInputs::from(args))?;
    // `+ 0.0` turns a negative zero (a force of -F · 0) into 0.
    let row = format!(
        "{},{:e},{:e},{:e},{:e},{:e},{:e},{:e}",
        args.method,
        t.coefficients.c11,
        t.coefficients.c22,
        t.coefficients.c23,
        t.fx_n + 0.0,
        t.fy_n + 0.0,
        t.mz_nmm + 0.0,
        t.adhesion_fraction
    );
    let note = missing_spin_moment(args.method).map(|n| n.replace("the method ", "--method "));
    Ok(Solved {
        csv: format!("{HEADER}\n{row}\n"),
        note,
    })
}

impl From<&CreepArgs> for PatchInputs {
    fn from(a: &CreepArgs) -> PatchInputs {
        PatchInputs {
            a_mm: a.a_mm,
            b_mm: a.b_mm,
            normal_force_n: a.normal_force_n,
            xi: a.xi,
            eta: a.eta,
            phi_per_mm: a.phi_per_mm,
            mu: a.mu,
            shear_modulus_gpa: a.shear_modulus_gpa,
            poisson: a.poisson,
            method: a.method,
            bound: a.bound,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Debug, Parser)]
    struct Cli {
        #[command(flatten)]
        creep: CreepArgs,
    }

    /// A patch of 6 × 4 mm at 50 kN with all three creepages (`--xi`, `--eta`,
    /// `--phi-per-mm` are the last three values).
    const BASE: [&str; 13] = [
        "creep",
        "--a-mm",
        "6",
        "--b-mm",
        "4",
        "--normal-force-n",
        "50000",
        "--xi",
        "-1e-3",
        "--eta",
        "2e-3",
        "--phi-per-mm",
        "-1e-4",
    ];

    fn parse(extra: &[&str]) -> Result<CreepArgs, clap::Error> {
        let mut argv = BASE.to_vec();
        argv.extend_from_slice(extra);
        Cli::try_parse_from(argv).map(|c| c.creep)
    }

    #[test]
    fn the_ranges_name_the_options_in_order() {
        // The table and the values checked against it line up by position: the keys are the
        // options clap derives from the fields, in the order `run` lists them.
        let keys: Vec<&str> = RANGES.iter().map(|r| r.key).collect();
        assert_eq!(
            keys,
            [
                "--a-mm",
                "--b-mm",
                "--normal-force-n",
                "--xi",
                "--eta",
                "--phi-per-mm",
                "--mu",
                "--shear-modulus-gpa",
                "--poisson"
            ]
        );
        for (i, r) in RANGES.iter().enumerate() {
            assert!(r.min < r.max, "{}", r.key);
            // Each key is an option the parser knows: replacing it with a value out of its
            // range is refused by `run` with that key in the message.
            let bad = format!("{}", r.max * 2.0 + 1.0);
            let mut argv: Vec<String> = BASE.iter().map(|s| s.to_string()).collect();
            match argv.iter().position(|a| a == r.key) {
                Some(k) => argv[k + 1] = bad.clone(),
                None => argv.extend([r.key.to_string(), bad.clone()]),
            }
            let args = Cli::try_parse_from(&argv)
                .unwrap_or_else(|e| panic!("{i}: {e}"))
                .creep;
            let err = run(&args).unwrap_err().to_string();
            assert!(
                err.starts_with(&format!("{} {bad}: expected", r.key)),
                "{err}"
            );
        }
    }

    #[test]
    fn nan_and_infinity_are_refused() {
        for v in ["nan", "inf", "-inf"] {
            let args = parse(&["--mu", v]).unwrap();
            assert!(
                matches!(run(&args), Err(CommandError::Implausible { .. })),
                "{v}"
            );
        }
    }

    #[test]
    fn methods_print_their_row_and_notes() {
        for (method, note) in [("fastsim", false), ("linear", true), ("polach", true)] {
            let solved = run(&parse(&["--method", method]).unwrap()).unwrap();
            let mut lines = solved.csv.lines();
            assert_eq!(lines.next(), Some(HEADER));
            let row: Vec<&str> = lines.next().unwrap().split(',').collect();
            assert_eq!(row.len(), 8);
            assert_eq!(row[0], method);
            assert_eq!(row[6] == "NaN", note, "{method}: {}", row[6]);
            assert_eq!(solved.note.is_some(), note);
            // ξ < 0 pulls the rail forwards: Fx > 0 for every model.
            assert!(row[4].parse::<f64>().unwrap() > 0.0, "{method}");
        }
    }
}
