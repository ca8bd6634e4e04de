//! `wheelrail check`: a scene's tables against golden files, with the tolerances of
//! [`golden_policy`].

use crate::write::{Group, write_folder};
use crate::{Error, print_progress, within_budget};
use std::path::Path;
use std::process::ExitCode;
use wheelrail::pipeline;
use wheelrail::scene::Scene;
use wheelrail_report::outputs::{self, CSV_FORMAT, OutputFile};
use wheelrail_report::{Tolerance, TolerancePolicy, compare_files};

/// The tolerances of golden comparisons: what the results may differ by on another platform
/// (another C library's `sin`, `cos`, `exp` and `sqrt` differ by an ulp; the code is the
/// same). A rounding-level perturbation of that kind, the paper scene's mirrored half solved
/// position by position instead of mirrored (`crates/cli/tests/golden_tolerances.rs`, which checks that
/// this policy accepts it), moves lengths by at most 1.4e-11 mm, angles 5e-14 rad,
/// curvatures 6e-16 1/mm, pressures and loads 1e-12 relative and iteration counts by one,
/// outside the conformal region below. The tolerances are about a hundred times that, and
/// never below one unit in the tenth significant digit the CSV files keep (relative 2e-9):
///
/// - lengths 1e-9 mm, angles and slopes 1e-12, curvatures 1e-13 1/mm, Wickens' ratios and
///   equivalent conicities 1e-9, iteration counts 2;
/// - the jumps' ends (`rigid_jumps.csv`): bisection stops at `rigid::JUMP_REFINE_MM`
///   (1e-4 mm), and a comparison of two nearly equal minima decided the other way on another
///   platform moves an end by up to that width in the shift and, on the flange root where
///   the contact runs 5-16 mm per mm of shift, 2e-3 mm on the wheel; a hollow's depth
///   between two such minima 2e-5 mm (6.4e-6 mm under the perturbation above).
///
/// The conformal region of the paper scene, 5 mm <= |y_ws| <= 6.5 mm (the S1002 flange root
/// on UIC60's gauge corner, the gap's curvature down to 1e-5 1/mm), amplifies the same
/// perturbation a hundredfold (1.4e-10 mm in the rigid contact point, 1e-9 mm in the
/// quasi-elastic one, 1e-10 relative in pressures): there the tolerances are a hundred times
/// wider.
pub fn golden_policy() -> TolerancePolicy {
    let tolerance = |abs: f64, rel: f64| Tolerance { abs, rel };
    // One unit in the tenth significant digit of the CSV files.
    let digits = 2e-9;
    // Lengths, angles and slopes, curvatures, Wickens' ratios and weight shares.
    let rules = |mm: f64, rad: f64, per_mm: f64, ratio: f64| {
        TolerancePolicy::new(tolerance(1e-12, digits))
            .suffix("_mm", tolerance(mm, digits))
            .suffix("_rad", tolerance(rad, digits))
            .suffix("tan_gamma", tolerance(rad, digits))
            .suffix("_per_mm", tolerance(per_mm, digits))
            .suffix("_MPa", tolerance(0.0, digits))
            .suffix("_N", tolerance(0.0, digits))
            .suffix("weight_share", tolerance(ratio, digits))
            .column("lambda", tolerance(ratio, digits))
            .column("epsilon", tolerance(ratio, digits))
            .column("sigma", tolerance(ratio, digits))
            .column("iterations", tolerance(2.0, 0.0))
            .column("tan_gamma_e_klingel", tolerance(1e-9, digits))
            .column("tan_gamma_e_regression", tolerance(1e-9, digits))
            .column("value", tolerance(1e-9, digits))
            .column(
                "y_from_mm",
                tolerance(wheelrail::rigid::JUMP_REFINE_MM, 0.0),
            )
            .column("y_to_mm", tolerance(wheelrail::rigid::JUMP_REFINE_MM, 0.0))
            .column("s_from_mm", tolerance(2e-3, 0.0))
            .column("s_to_mm", tolerance(2e-3, 0.0))
            .column("hollow_mm", tolerance(2e-5, 0.0))
            .key_column("y_ws_mm")
    };
    let conformal = || rules(1e-7, 1e-10, 1e-11, 1e-7);
    let why = "the conformal flange root";
    rules(1e-9, 1e-12, 1e-13, 1e-9)
        .region(-6.5, -5.0, why, conformal())
        .region(5.0, 6.5, why, conformal())
}

pub(crate) fn check(scene_path: &Path, golden: &Path, bless: bool) -> Result<ExitCode, Error> {
    let scene = Scene::load(scene_path)?;
    let gate = |placement: &_| within_budget(&scene, placement, false);
    let results = pipeline::run_gated(&scene, None, gate, &mut print_progress)?;
    let produced: Vec<(String, String)> = outputs::tables(&scene, &results)?
        .into_iter()
        .map(|t| (t.file, t.table.to_csv_with(CSV_FORMAT)))
        .collect();
    if bless {
        let files: Vec<OutputFile> = produced
            .iter()
            .map(|(name, text)| OutputFile {
                name: name.clone(),
                bytes: text.clone().into_bytes(),
            })
            .collect();
        write_folder(golden, Group::Golden, &files)?;
        eprintln!(
            "blessed {} golden files in {}",
            files.len(),
            golden.display()
        );
        return Ok(ExitCode::SUCCESS);
    }
    let mut expected: Vec<(String, Option<String>)> = produced
        .iter()
        .map(|(name, _)| {
            (
                name.clone(),
                std::fs::read_to_string(golden.join(name)).ok(),
            )
        })
        .collect();
    // Golden files the run no longer produces are differences too.
    let entries = std::fs::read_dir(golden).map_err(|source| Error::Io {
        path: golden.to_path_buf(),
        source,
    });
    if let Ok(entries) = entries {
        for e in entries.flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if name.ends_with(".csv") && !produced.iter().any(|(p, _)| *p == name) {
                expected.push((name, Some(String::new())));
            }
        }
    } else {
        entries?;
    }
    let rows: Vec<(&str, Option<&str>, Option<&str>)> = expected
        .iter()
        .map(|(name, text)| {
            let actual = produced
                .iter()
                .find(|(p, _)| p == name)
                .map(|(_, t)| t.as_str());
            (name.as_str(), text.as_deref(), actual)
        })
        .collect();
    let result = compare_files(&rows, &golden_policy());
    if result.is_match() {
        eprintln!("{} tables match {}", rows.len(), golden.display());
        Ok(ExitCode::SUCCESS)
    } else {
        println!("{result}");
        println!(
            "(to accept the new results: wheelrail check {} --golden {} --bless, then review the diff)",
            scene_path.display(),
            golden.display()
        );
        Ok(ExitCode::from(1))
    }
}
