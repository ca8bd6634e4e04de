//! Fleet assessment: many measured profiles through one template scene, one summary row each.
//!
//! The template [`Scene`] fixes everything but the profiles that vary: track, load, sweep,
//! settings, and the profiles the fleet's inputs do not replace. Each [`Item`] names the
//! files of one wheelset (a wheel profile put on both wheels, the right one mirrored by its
//! side frame; or two wheels measured separately; or a rail profile for a grinding
//! assessment). [`Fleet::new`] places the template's fixed profiles once and shares them;
//! [`Fleet::assess`] reads, fits and places an item's files with the same functions as a
//! report run (`pipeline::place_wheels`, `pipeline::place_rails`, `pipeline::assemble`)
//! and runs the stages the summary needs with [`pipeline::run_on`], so its numbers agree to
//! the last digit with `wheelrail report` on the template with those files.
//!
//! [`Fleet::assess_in_order`] runs items in parallel (rayon) and hands their rows to the
//! caller in input order as they complete, whatever the number of threads. [`synthetic`]
//! generates worn S1002 profiles for tests, benchmarks and the example fleet.
//!
//! Nothing here touches the file system except the profile readers; a failure of one item
//! (unreadable file, bad profile, no overlap with its rail) is that item's row, never an
//! error of the fleet.

mod inputs;
pub mod synthetic;

pub(crate) use inputs::parse_pairs;
pub use inputs::{FleetError, Inputs, Item, PairsProblem, Shard, items_of_files};

use crate::cache::PlacementCache;
use crate::conicity::Parameters;
use crate::pipeline::{self, Results, Stage};
use crate::profile::Source;
use crate::scene::{ProfileRef, Scene, SceneError};
use crate::track::{PlacedRail, PlacedWheel, Side};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The largest Hertz pressure of one pair over its sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaxPressure {
    /// The largest maximum pressure p0 over the sweep and both wheels (MPa).
    pub p0_mpa: f64,
    /// The wheelset shift where it occurs (mm, track frame, first such position).
    pub y_ws_mm: f64,
    /// The wheel that carries it.
    pub side: Side,
}

/// What a fleet keeps of one pair's run: the pair's parameters, its equivalent conicity
/// function by the scene's method, and the largest Hertz pressure when Hertz ran.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// The pair's parameters ([`Parameters::rows`] gives their names and units).
    pub parameters: Parameters,
    /// `(amplitude mm, tan γe)` by the scene's method (NaN where not computable).
    pub conicity: Vec<(f64, f64)>,
    /// The largest p0 over the sweep; `None` when Hertz did not run or no ellipse exists.
    pub max_p0: Option<MaxPressure>,
    /// The wheels' flange dimensions against their limits, the rails' wear against the
    /// template's rails (a fleet of rails).
    pub maintenance: crate::maintenance::Assessment,
}

/// The summary of a run: the equivalent conicity by `settings`' method and the pair's
/// parameters (from the run's conicity stage when it ran, else computed here from its rigid
/// sweep by [`crate::conicity::assess_by_method_on`], the same values without the other
/// method's function), and the largest Hertz pressure if Hertz ran.
///
/// # Panics
/// If the run computed neither the equivalent conicity nor the rigid sweep (a caller's bug:
/// [`Fleet`] always runs the rigid search).
pub(crate) fn summarise(
    results: &Results,
    settings: &crate::conicity::ConicitySettings,
) -> Summary {
    let points = |c: &crate::conicity::EquivalentConicity| -> Vec<(f64, f64)> {
        c.points
            .iter()
            .map(|p| (p.amplitude_mm, p.tan_gamma_e))
            .collect()
    };
    let (conicity, parameters) = match &results.conicity {
        Some(c) => (points(c.by(settings.method)), c.parameters),
        None => {
            let rigid = results
                .rigid
                .as_ref()
                .expect("a fleet run computes the rigid sweep");
            let (function, parameters) =
                crate::conicity::assess_by_method_on(&results.placement, rigid, settings);
            (points(&function), parameters)
        }
    };
    let mut max_p0: Option<MaxPressure> = None;
    for p in results.hertz.iter().flat_map(|h| h.positions()) {
        for (k, side) in [Side::Left, Side::Right].into_iter().enumerate() {
            if let Some(e) = p.sides[k].ellipse()
                && e.p0_mpa.is_finite()
                && max_p0.is_none_or(|m| e.p0_mpa > m.p0_mpa)
            {
                max_p0 = Some(MaxPressure {
                    p0_mpa: e.p0_mpa,
                    y_ws_mm: p.y_ws,
                    side,
                });
            }
        }
    }
    Summary {
        parameters,
        conicity,
        max_p0,
        maintenance: results.maintenance.clone(),
    }
}

/// One input file of a row: its role, path and the SHA-256 of its bytes (`None` when it
/// could not be read).
#[derive(Debug, Clone, PartialEq)]
pub struct InputFile {
    /// `wheel`, `rail`, `left_wheel`, ... (see [`Inputs::roles`]).
    pub role: &'static str,
    /// The path as given (resolved against the pairs file's folder for pairs).
    pub path: Option<PathBuf>,
    /// SHA-256 of the file's bytes, lower-case hex.
    pub sha256: Option<String>,
}

/// The result of one item: its id, its files and the summary or why it failed.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The item's id.
    pub id: String,
    /// The item's files, in the order of [`Inputs::roles`].
    pub files: Vec<InputFile>,
    /// The summary, or why the item failed.
    pub outcome: Result<Summary, RowError>,
}

/// Why an item's row failed: the message of its first file that could not be read or
/// placed (the reader's own, naming the file and line, without the template scene's key),
/// or of a failure while assessing it (a report that could not be written).
#[derive(Debug, Clone, PartialEq)]
pub struct RowError(String);

impl RowError {
    /// A failure described by `message` (the row's `status`).
    pub fn new(message: String) -> RowError {
        RowError(message)
    }
}

impl From<SceneError> for RowError {
    fn from(e: SceneError) -> RowError {
        match e {
            SceneError::Profile { message, .. } => RowError(message),
            e => RowError(e.to_string()),
        }
    }
}

impl std::fmt::Display for RowError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for RowError {}

/// A template scene with its fixed profiles placed once, ready to assess items.
#[derive(Debug)]
pub struct Fleet {
    template: Scene,
    inputs: Inputs,
    stages: Vec<Stage>,
    wheels: Option<[PlacedWheel; 2]>,
    rails: Option<[Arc<PlacedRail>; 2]>,
    /// The items' placed rails when a pairs file lists rails (pairs often share a rail
    /// file; see [`PlacementCache`]).
    rail_cache: Option<PlacementCache>,
}

impl Fleet {
    /// Prepares `template` for `items` of kind `inputs`: the template's wheels (rails) are
    /// read and placed once if some item keeps them. The stages run per item are the rigid
    /// search (the summary computes the conicity of the scene's method from it) and, when
    /// the template's figures need it, Hertz; with `full`, every stage the template's
    /// figures need and the equivalent conicity (for a full report per pair).
    ///
    /// # Errors
    /// The template's own profiles cannot be read or placed.
    pub fn new(
        template: Scene,
        inputs: Inputs,
        items: &[Item],
        full: bool,
    ) -> Result<Fleet, SceneError> {
        let wheels = if items.iter().any(|i| i.wheels.is_none()) {
            Some(pipeline::place_wheels(&template)?)
        } else {
            None
        };
        let rails = if items.iter().any(|i| i.rails.is_none()) {
            Some(pipeline::place_rails(&template)?)
        } else {
            None
        };
        // The conicity function of one method and the parameters are computed from the
        // rigid sweep by the summary; a full report needs the whole stage.
        let mut stages = vec![Stage::Rigid];
        if full {
            stages.extend(pipeline::needed_stages(&template));
            stages.push(Stage::EquivalentConicity);
        } else if pipeline::needed_stages(&template).contains(&Stage::Hertz) {
            stages.push(Stage::Hertz);
        }
        let stages = pipeline::closed_stages(&template, &stages);
        let rail_cache = matches!(inputs, Inputs::Pairs { rails: true }).then(PlacementCache::new);
        let mut template = template;
        if inputs.has_rails() && template.nominal_rails.is_none() {
            // A rail's wear is measured against the template's rail on its side; read once
            // here, so that a template rail that cannot be read stops the fleet.
            template.nominal_rails = Some(template.rail_profiles.clone());
        }
        pipeline::nominal_rails(&template)?;
        Ok(Fleet {
            template,
            inputs,
            stages,
            wheels,
            rails,
            rail_cache,
        })
    }

    /// The template scene.
    pub fn template(&self) -> &Scene {
        &self.template
    }

    /// What the items replace.
    pub fn inputs(&self) -> Inputs {
        self.inputs
    }

    /// The pipeline stages run for each item, in run order (the summary adds the
    /// equivalent conicity of the scene's method when the stage itself does not run).
    pub fn stages(&self) -> &[Stage] {
        &self.stages
    }

    /// What each item computes, in words: the stages, and the equivalent conicity.
    pub fn describe_stages(&self) -> String {
        let mut names: Vec<String> = self.stages.iter().map(|s| s.name().to_string()).collect();
        if !self.stages.contains(&Stage::EquivalentConicity) {
            names.push(format!(
                "equivalent_conicity ({} method and parameters only)",
                self.template.conicity.method.name()
            ));
        }
        names.join(", ")
    }

    /// Whether the rows carry the Hertz pressure (the template's figures need Hertz).
    pub fn has_hertz(&self) -> bool {
        self.stages.contains(&Stage::Hertz)
    }

    /// The template with `item`'s files in place of its profiles: the scene a single
    /// `wheelrail report` of this pair would run.
    pub fn scene_for(&self, item: &Item) -> Scene {
        // The one place that writes a scene's profile fields.
        let mut scene = self.template.clone();
        if let Some([l, r]) = &item.wheels {
            scene.wheel_profiles = [ProfileRef::File(l.clone()), ProfileRef::File(r.clone())];
        }
        if let Some([l, r]) = &item.rails {
            scene.rail_profiles = [ProfileRef::File(l.clone()), ProfileRef::File(r.clone())];
        }
        scene
    }

    /// Places `item`'s profiles (its files read, fitted and placed as a report does; the
    /// template's wheels cloned, its rails shared; a rail file of a pairs file placed once
    /// for all the pairs that list it) and runs the fleet's stages on them.
    ///
    /// # Errors
    /// [`RowError`]: the first file that cannot be read or placed (naming the file and
    /// line), or a wheel that does not overlap its rail.
    pub fn run(&self, item: &Item) -> Result<(Scene, Results), RowError> {
        let scene = self.scene_for(item);
        let wheels = match (&item.wheels, &self.wheels) {
            (Some(_), _) | (None, None) => pipeline::place_wheels(&scene)?,
            (None, Some(shared)) => shared.clone(),
        };
        let rails = match (&item.rails, &self.rails, &self.rail_cache) {
            (Some(_), _, Some(cache)) => pipeline::place_rails_cached(&scene, cache)?,
            (Some(_), _, None) | (None, None, _) => pipeline::place_rails(&scene)?,
            (None, Some(shared), _) => shared.clone(),
        };
        let placement = pipeline::assemble(&scene, wheels, rails)?;
        let results = pipeline::run_on(&scene, placement, &self.stages);
        Ok((scene, results))
    }

    /// The row of `item`, from [`Fleet::run`] (or from `run`'s results when the caller ran
    /// it, e.g. to write a full report too).
    pub fn row(&self, item: &Item, run: Result<&Results, &RowError>) -> Row {
        let outcome = run
            .map(|r| summarise(r, &self.template.conicity))
            .map_err(RowError::clone);
        let files = self
            .inputs
            .roles()
            .iter()
            .zip(self.inputs.files(item))
            .map(|(&role, path)| {
                let placed = run.ok().and_then(|r| placed_sha256(r, role));
                let sha256 = placed.or_else(|| {
                    path.as_ref()
                        .and_then(|p| std::fs::read(p).ok())
                        .map(|b| crate::profile::read::sha256_hex(&b))
                });
                InputFile { role, path, sha256 }
            })
            .collect();
        Row {
            id: item.id.clone(),
            files,
            outcome,
        }
    }

    /// Runs and summarises `item`.
    pub fn assess(&self, item: &Item) -> Row {
        let run = self.run(item);
        self.row(item, run.as_ref().map(|(_, r)| r))
    }

    /// The row of `item` when its assessment gave no row (a bug that panicked, caught by
    /// [`Fleet::assess_in_order`]): its files by path, without hashes, and `message` as its
    /// outcome.
    pub fn failed_row(&self, item: &Item, error: RowError) -> Row {
        Row {
            id: item.id.clone(),
            files: self
                .inputs
                .roles()
                .iter()
                .zip(self.inputs.files(item))
                .map(|(&role, path)| InputFile {
                    role,
                    path,
                    sha256: None,
                })
                .collect(),
            outcome: Err(error),
        }
    }

    /// Assesses `items` in parallel (on the current rayon pool, each thread taking the next
    /// item; `assess` is [`Fleet::assess`] or a caller's variant of it) and hands each row to
    /// `sink` in input order, as soon as it and all before it are done, whatever the number
    /// of threads; an item whose assessment panics (a bug) gets [`Fleet::failed_row`] saying
    /// so, and the others run.
    pub fn assess_in_order(
        &self,
        items: &[Item],
        assess: impl Fn(&Item) -> Row + Sync,
        mut sink: impl FnMut(usize, Row) + Send,
    ) {
        in_order(
            items,
            |item| Ok(assess(item)),
            |panic| {
                Err(RowError::new(format!(
                    "internal error (please report): {panic}"
                )))
            },
            |i, row: Result<Row, RowError>| {
                sink(
                    i,
                    row.unwrap_or_else(|error| self.failed_row(&items[i], error)),
                );
            },
        );
    }
}

/// The items of a pairs file (see `parse_pairs`: paths in it are relative to its folder)
/// and what they replace.
///
/// # Errors
/// [`FleetError::Unreadable`] when the file cannot be read, [`FleetError::Pairs`] (naming
/// the file and line) when it is malformed.
pub fn read_pairs(path: &Path) -> Result<(Vec<Item>, Inputs), FleetError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| FleetError::Unreadable(path.to_path_buf(), e.to_string()))?;
    let dir = path.parent().unwrap_or(Path::new(""));
    parse_pairs(&text, &path.display().to_string(), dir)
}

/// The SHA-256 the reader took of the file of `role`, from the placed profile.
fn placed_sha256(results: &Results, role: &str) -> Option<String> {
    let p = &results.placement;
    let profile = match role {
        "wheel" | "left_wheel" => p.left.wheel.profile(),
        "right_wheel" => p.right.wheel.profile(),
        "rail" | "left_rail" => p.left.rail.profile(),
        "right_rail" => p.right.rail.profile(),
        _ => return None,
    };
    match profile.source() {
        Source::File { sha256, .. } => Some(sha256.clone()),
        Source::Definition(_) => None,
    }
}

/// Runs `f` on every item in parallel (the current rayon pool; each thread takes the next
/// item in input order) and calls `sink` with each result in input order as soon as it and
/// all before it are done. `sink` runs on a thread of its own, so a slow sink (a file, a
/// progress bar) never holds up the workers; results wait in memory only while an earlier
/// item is still running. A panic in `f` becomes `on_panic(message)` for that item.
pub(crate) fn in_order<T, R>(
    items: &[T],
    f: impl Fn(&T) -> R + Sync,
    on_panic: impl Fn(String) -> R + Sync,
    sink: impl FnMut(usize, R) + Send,
) where
    T: Sync,
    R: Send,
{
    let next = AtomicUsize::new(0);
    let (tx, rx) = std::sync::mpsc::channel::<(usize, R)>();
    std::thread::scope(|scope| {
        let mut sink = sink;
        scope.spawn(move || {
            let mut waiting = BTreeMap::new();
            let mut due = 0;
            for (i, r) in rx {
                waiting.insert(i, r);
                while let Some(r) = waiting.remove(&due) {
                    sink(due, r);
                    due += 1;
                }
            }
        });
        // One job per thread of the current pool, each taking the next item until none is
        // left (rayon::scope: from inside a pool, its idle threads steal the jobs).
        let work = |tx: std::sync::mpsc::Sender<(usize, R)>| loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(item) = items.get(i) else { break };
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| f(item)))
                .unwrap_or_else(|p| {
                    let text = p
                        .downcast_ref::<&str>()
                        .map(|s| (*s).to_string())
                        .or_else(|| p.downcast_ref::<String>().cloned())
                        .unwrap_or_default();
                    on_panic(text)
                });
            if tx.send((i, r)).is_err() {
                break;
            }
        };
        rayon::scope(|s| {
            for _ in 0..rayon::current_num_threads() {
                let tx = tx.clone();
                let work = &work;
                s.spawn(move |_| work(tx));
            }
        });
        drop(tx);
    });
}
