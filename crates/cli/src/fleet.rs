//! `wheelrail fleet`: many profiles through one template scene, `fleet.csv` streamed row by
//! row in input order, then the charts and `index.html` (see [`wheelrail::fleet`]).
//!
//! Exit codes: 0 every row ok, 3 some rows failed (their status says why), 2 nothing could
//! run (bad scene, bad pairs file, no profiles, unwritable output).

use super::write::{Group, write_folder};
use crate::Error;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};
use wheelrail::fleet::{self, Fleet, Inputs, Item, Row, RowError, Shard};
use wheelrail::scene::Scene;
use wheelrail_report::outputs::{self, OutputFile};

/// The arguments of `wheelrail fleet`.
#[derive(Debug, clap::Args)]
pub struct FleetArgs {
    /// The template scene (track, rail, load, sweep, stages, settings; `[fleet]`).
    pub scene: PathBuf,
    /// Wheel profile files (any format the readers accept), each put on both wheels; rail
    /// profiles with --rail.
    #[arg(required_unless_present = "pairs")]
    pub profiles: Vec<PathBuf>,
    /// Output folder: fleet.csv, the charts and index.html.
    #[arg(long)]
    pub out: PathBuf,
    /// The profiles are rails: each is put on both rails under the template's wheels.
    #[arg(long, conflicts_with = "pairs")]
    pub rail: bool,
    /// A CSV of wheelsets measured wheel by wheel: columns id,left_wheel,right_wheel and
    /// optionally left_rail,right_rail (paths relative to the CSV).
    #[arg(long, conflicts_with = "profiles")]
    pub pairs: Option<PathBuf>,
    /// Process only part K of N (consecutive parts of the input list, sizes within one):
    /// the parts' fleet.csv files, concatenated in order without their header lines, are
    /// the whole fleet's.
    #[arg(long, value_name = "K/N")]
    pub shard: Option<String>,
    /// Run a template whose estimated work per pair exceeds the budget of a report
    /// (`cost::WORK_BUDGET`; with --reports also the bytes of each report,
    /// `cost::WRITE_BUDGET_BYTES`).
    #[arg(long)]
    pub allow_long: bool,
    /// Also write each pair's full report (the template's figures) into DIR/ID/ (ID the row's id).
    #[arg(long)]
    pub reports: bool,
}

/// The streamed CSV's name while the run is going on; renamed when the run is complete.
pub const PARTIAL_CSV: &str = "fleet.csv.partial";

/// The items the command line names (profile files, or a pairs file), the shard's part of
/// them.
///
/// # Errors
/// An unreadable or malformed pairs file, no profiles, a bad shard, an id that `--reports`
/// cannot use as a folder name.
fn items(args: &FleetArgs) -> Result<(Vec<Item>, Inputs), Error> {
    let (items, inputs) = match &args.pairs {
        Some(path) => fleet::read_pairs(path)?,
        None => {
            let inputs = if args.rail {
                Inputs::Rails
            } else {
                Inputs::Wheels
            };
            (fleet::items_of_files(&args.profiles, args.rail), inputs)
        }
    };
    if items.is_empty() {
        return Err(fleet::FleetError::NoItems.into());
    }
    let items: Vec<Item> = match &args.shard {
        Some(text) => {
            let shard = Shard::parse(text)?;
            items[shard.range(items.len())].to_vec()
        }
        None => items,
    };
    if args.reports
        && let Some(item) = items.iter().find(|i| is_fleet_output(&i.id))
    {
        return Err(Error::Usage(format!(
            "id {:?}: --reports would write its report folder where the fleet writes a file of that name; rename the profile file or the pair",
            item.id
        )));
    }
    Ok((items, inputs))
}

/// Each pair computes at most what a report of the template would: refused as a report
/// would be (estimated on the template's own profiles, when they can be placed), its bytes
/// counted only when each pair writes its `reports`.
fn within_budget(
    fleet: &Fleet,
    template_path: &str,
    allow_long: bool,
    reports: bool,
) -> Result<(), Error> {
    if let Ok(placement) = wheelrail::pipeline::place(fleet.template()) {
        let estimate = wheelrail::cost::estimate(fleet.template(), &placement);
        let within = if reports {
            estimate.within_budget()
        } else {
            estimate.within_work_budget()
        };
        if !within && !allow_long {
            return Err(Error::WorkBudget {
                scene: format!("{template_path}: each pair"),
                estimate: estimate.describe(),
            });
        }
    }
    Ok(())
}

/// Creates the output folder `dir` (a file in its place is an error).
fn output_folder(dir: &Path) -> Result<(), Error> {
    if dir.exists() && !dir.is_dir() {
        return Err(Error::Output {
            path: dir.to_path_buf(),
            problem: "is a file, not a folder (choose another --out)".into(),
        });
    }
    std::fs::create_dir_all(dir).map_err(|source| Error::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    Ok(())
}

/// Runs `wheelrail fleet`.
///
/// # Errors
/// Everything that stops the whole fleet (exit code 2): the scene, the pairs file, the
/// shard, an empty list, the output folder.
pub fn run(args: &FleetArgs) -> Result<ExitCode, Error> {
    let template = Scene::load(&args.scene)?;
    let (items, inputs) = items(args)?;
    let template_path = args.scene.display().to_string();
    let fleet = Fleet::new(template, inputs, &items, args.reports)?;
    within_budget(&fleet, &template_path, args.allow_long, args.reports)?;
    let dir = &args.out;
    output_folder(dir)?;
    let partial = dir.join(PARTIAL_CSV);
    let io = |source| Error::Io {
        path: partial.clone(),
        source,
    };
    let mut csv = std::io::BufWriter::new(std::fs::File::create(&partial).map_err(io)?);
    csv.write_all(outputs::fleet::csv_header(&fleet, &template_path).as_bytes())
        .map_err(io)?;
    csv.flush().map_err(io)?;

    let mut progress = Progress::new(items.len());
    let mut rows: Vec<Row> = Vec::with_capacity(items.len());
    let mut write_error = None;
    fleet.assess_in_order(
        &items,
        |item| assess(&fleet, item, args.reports.then_some(dir.as_path())),
        |_, row| {
            if write_error.is_none() {
                let line = outputs::fleet::csv_line(&fleet, &row);
                // Flushed per row: an interrupted run keeps every row it finished.
                if let Err(e) = csv.write_all(line.as_bytes()).and_then(|()| csv.flush()) {
                    write_error = Some(e);
                }
            }
            progress.step(row.outcome.is_ok());
            rows.push(row);
        },
    );
    progress.finish();
    if let Some(e) = write_error {
        return Err(io(e));
    }
    drop(csv);
    let csv_bytes = std::fs::read(&partial).map_err(io)?;
    let mut files = outputs::fleet::render(&fleet, &rows, &template_path, args.reports)?;
    files.push(OutputFile {
        name: "fleet.csv".into(),
        bytes: csv_bytes,
    });
    // The whole folder (fleet.csv with the charts and page) is swapped in at once.
    write_folder(dir, Group::Fleet, &files)?;
    let _ = std::fs::remove_file(&partial);
    let failed = rows.iter().filter(|r| r.outcome.is_err()).count();
    eprintln!(
        "{} rows ({} ok, {failed} failed) in {}: open {}",
        rows.len(),
        rows.len() - failed,
        dir.join("fleet.csv").display(),
        dir.join("index.html").display()
    );
    Ok(if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(3)
    })
}

/// Whether `name` is one of the files `wheelrail fleet` writes into its folder.
fn is_fleet_output(name: &str) -> bool {
    [
        "fleet.csv",
        PARTIAL_CSV,
        "index.html",
        super::write::MANIFEST,
    ]
    .contains(&name)
        || name.starts_with("fleet_conicity_")
}

/// One item's row; with `reports`, its full report written into `reports/<id>/` too.
fn assess(fleet: &Fleet, item: &Item, reports: Option<&Path>) -> Row {
    let Some(dir) = reports else {
        return fleet.assess(item);
    };
    let run = fleet.run(item);
    let mut row = fleet.row(item, run.as_ref().map(|(_, r)| r));
    if let Ok((scene, results)) = &run {
        let written = outputs::render(scene, results, &[])
            .map_err(Error::from)
            .and_then(|files| write_folder(&dir.join(&item.id), Group::Report, &files));
        if let Err(e) = written {
            row.outcome = Err(RowError::new(format!("report not written: {e}")));
        }
    }
    row
}

/// Progress on standard error: a bar with count, rate and time left on a terminal, a plain
/// line every [`Progress::PLAIN_EVERY`] otherwise (and a last one at the end).
struct Progress {
    bar: Option<indicatif::ProgressBar>,
    total: usize,
    done: usize,
    failed: usize,
    start: Instant,
    last_line: Instant,
}

impl Progress {
    const PLAIN_EVERY: Duration = Duration::from_secs(10);

    fn new(total: usize) -> Progress {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = indicatif::ProgressBar::new(total as u64);
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} profiles, {rate}, {eta} left {msg}",
            ) {
                bar.set_style(style.with_key(
                    "rate",
                    |s: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
                        let _ = write!(w, "{:.0}/s", s.per_sec());
                    },
                ));
            }
            bar
        });
        let now = Instant::now();
        Progress {
            bar,
            total,
            done: 0,
            failed: 0,
            start: now,
            last_line: now,
        }
    }

    fn step(&mut self, ok: bool) {
        self.done += 1;
        if !ok {
            self.failed += 1;
        }
        if let Some(bar) = &self.bar {
            if !ok {
                bar.set_message(format!("({} failed)", self.failed));
            }
            bar.inc(1);
        } else if self.last_line.elapsed() >= Self::PLAIN_EVERY {
            self.last_line = Instant::now();
            self.line();
        }
    }

    fn line(&self) {
        let seconds = self.start.elapsed().as_secs_f64();
        let rate = self.done as f64 / seconds.max(1e-9);
        eprintln!(
            "fleet: {}/{} profiles ({} failed) in {seconds:.1} s, {rate:.0}/s, about {:.0} s left",
            self.done,
            self.total,
            self.failed,
            (self.total - self.done) as f64 / rate.max(1e-9)
        );
    }

    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
        self.line();
    }
}
