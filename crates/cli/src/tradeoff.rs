//! `wheelrail tradeoff`: run time against error of numerical settings, measured or redrawn
//! from a folder's files.

use crate::write::{Group, write_folder};
use crate::{Error, out_dir};
use std::io::IsTerminal;
use std::path::Path;
use std::process::ExitCode;
use wheelrail::scene::Scene;
use wheelrail_report::outputs;

/// `wheelrail tradeoff --replot`: the charts drawn again from the folder's `tradeoff.csv`
/// and `fastsim_tradeoff.csv`, which are written back as they were (the study's files are
/// one group of the folder). A folder from before FASTSIM's study has no
/// `fastsim_tradeoff.csv`: only the first chart is drawn, with a note.
pub(crate) fn tradeoff_replot(scene_path: &Path, out: Option<&Path>) -> Result<ExitCode, Error> {
    let scene = Scene::load(scene_path)?;
    let dir = out_dir(scene_path, out);
    let (mut files, mut redrawn) = (Vec::new(), Vec::new());
    for study in outputs::Study::ALL {
        let path = dir.join(format!("{}.csv", study.name()));
        if study == outputs::Study::FastsimGrids && !path.exists() {
            eprintln!(
                "note: no {}: FASTSIM's grid chart not drawn (`wheelrail tradeoff` without --replot measures it)",
                path.display()
            );
            continue;
        }
        let csv = std::fs::read_to_string(&path).map_err(|source| Error::Io {
            path: path.clone(),
            source,
        })?;
        let points = study
            .points(&csv, &path.display().to_string())
            .map_err(|e| Error::Usage(format!("--replot: {e}")))?;
        files.extend(study.files(csv, &points, scene.formats())?);
        redrawn.push(path);
    }
    write_folder(&dir, Group::Tradeoff, &files)?;
    for path in redrawn {
        eprintln!("redrew the chart of {}", path.display());
    }
    Ok(ExitCode::SUCCESS)
}

/// `wheelrail tradeoff`: the scene's numerical settings and FASTSIM's grids measured, their
/// tables and charts written, both tables printed.
pub(crate) fn tradeoff(
    scene_path: &Path,
    out: Option<&Path>,
    repeats: usize,
) -> Result<ExitCode, Error> {
    if !(1..=1000).contains(&repeats) {
        return Err(Error::Usage(format!(
            "--repeats {repeats}: expected 1 to 1000"
        )));
    }
    let scene = Scene::load(scene_path)?;
    let settings = wheelrail_report::tradeoff::grid(&scene);
    // Progress only for a person watching: a terminal, where the line is redrawn in place.
    let progress_shown = std::io::stderr().is_terminal();
    let progress = |done: usize, total: usize, label: &str| {
        if progress_shown {
            eprint!("\r\x1b[2K[{done}/{total} runs] {label}");
        }
    };
    let measured = wheelrail_report::tradeoff::study(&scene, &settings, repeats, progress)?;
    let grids = wheelrail_report::tradeoff::fastsim::study(
        &wheelrail::creep::fastsim::STUDY_GRIDS,
        repeats,
        progress,
    );
    if progress_shown {
        eprint!("\r\x1b[2K");
    }
    let mut files = outputs::tradeoff_files(&measured, scene.formats())?;
    files.extend(outputs::fastsim_tradeoff_files(&grids, scene.formats())?);
    let dir = out_dir(scene_path, out);
    write_folder(&dir, Group::Tradeoff, &files)?;
    print_study(
        [
            "setting",
            "median_ms",
            "min-max_ms",
            "contact_mm",
            "a,b_rel",
        ],
        measured.iter().map(|m| {
            let t = m.range_s;
            let errors = [m.errors.contact_mm, m.errors.a_rel.max(m.errors.b_rel)];
            (
                m.setting.label.clone(),
                [m.median_s, t.0, t.1].map(|t| 1e3 * t),
                errors,
            )
        }),
    );
    println!();
    print_study(
        ["FASTSIM grid", "median_us", "min-max_us", "force", "moment"],
        grids.iter().map(|g| {
            let t = g.timing;
            let times = [t.median_s, t.range_s.0, t.range_s.1].map(|t| 1e6 * t);
            let label = wheelrail_report::tradeoff::fastsim::label(g.grid);
            (label, times, [g.force_error, g.moment_error])
        }),
    );
    println!(
        "(single thread; {repeats} timed rounds after a warm-up round, settings or grids in a random order in each; FASTSIM's errors relative to mu FN and mu FN c against {}x{})",
        wheelrail::creep::fastsim::STUDY_REFERENCE.strips,
        wheelrail::creep::fastsim::STUDY_REFERENCE.elements
    );
    for study in outputs::Study::ALL {
        eprintln!(
            "wrote {}",
            dir.join(format!("{}.csv", study.name())).display()
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// Prints a study's table under the five `columns`: per row its label, its median, fastest
/// and slowest times and its two errors.
fn print_study(columns: [&str; 5], rows: impl Iterator<Item = (String, [f64; 3], [f64; 2])>) {
    let [label, median, range, e0, e1] = columns;
    println!("{label:<40} {median:>9} {range:>17}  {e0:>10}  {e1:>8}");
    for (label, [median, lo, hi], [e0, e1]) in rows {
        let range = format!("{lo:.2}-{hi:.2}");
        println!("{label:<40} {median:>9.2} {range:>17}  {e0:>10.1e}  {e1:>8.1e}");
    }
}
