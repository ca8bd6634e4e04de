//! The outputs of a scene: its tables (CSV), figures (SVG, PNG) and the `index.html` report,
//! as bytes. Nothing here touches the file system; the command line (`app`) writes the files.
//!
//! The tables ([`tables()`], [`mod@tables`], the fleet's rows in [`fleet`]) need no feature:
//! a library user (the Python package among them) gets the same columns and numbers as the
//! CSV files. The figures and the report pages need the feature `cli` (plotters, png).
//!
//! To add a figure: a variant in [`wheelrail::pipeline::Figure`] (name, stage), a function in
//! `outputs/figures/` (one file per stage) taking that stage's result, a caption in `caption`,
//! an arm in `figure`.

pub mod creep;
mod figures;
pub mod fleet;
mod page;
pub mod tables;

use crate::Error;
use crate::FigureEntry;
use crate::Table;
use wheelrail::pipeline::Figure;
use wheelrail::pipeline::Results;
use wheelrail::scene::ImageFormat;
use wheelrail::scene::Scene;
use wheelrail::track::Side;

/// One output file: its name in the output folder and its bytes.
#[derive(Debug, Clone)]
pub struct OutputFile {
    /// File name (no folders).
    pub name: String,
    /// Contents.
    pub bytes: Vec<u8>,
}

/// A table with its file name and a one-line description.
#[derive(Debug, Clone)]
pub struct NamedTable {
    /// File name, e.g. `rigid.csv`.
    pub file: String,
    /// What it holds.
    pub description: String,
    /// The table.
    pub table: Table,
}

/// How numbers are written in every CSV: 10 significant digits, enough for 1e-7 mm on a
/// track-frame position and stable in golden diffs.
pub const CSV_FORMAT: crate::NumberFormat = crate::NumberFormat::Significant(10);

fn table_error(e: crate::TableError) -> Error {
    Error::Table(e)
}

/// The tables of every stage that ran.
///
/// # Errors
/// Only internal inconsistencies (a bug), as [`Error::Table`].
pub fn tables(scene: &Scene, results: &Results) -> Result<Vec<NamedTable>, Error> {
    let mut out = Vec::new();
    profile_tables(scene, results, &mut out)?;
    contact_tables(scene, results, &mut out)?;
    assessment_tables(results, &mut out)?;
    Ok(out)
}

/// Appends `table` to `out` as the file `file`.
fn push_table(out: &mut Vec<NamedTable>, file: &str, description: &str, table: Table) {
    out.push(NamedTable {
        file: file.to_string(),
        description: description.to_string(),
        table,
    });
}

/// The profiles' tables: the wheels, the rails as placed, their dimensions and wear.
fn profile_tables(
    scene: &Scene,
    results: &Results,
    out: &mut Vec<NamedTable>,
) -> Result<(), Error> {
    let mut push =
        |file: &str, description: &str, table: Table| push_table(out, file, description, table);
    let p = &results.placement;
    push(
        "wheel_profile.csv",
        "left wheel profile: height, slope, curvature",
        tables::wheel_profile(p.left().wheel()).map_err(table_error)?,
    );
    if scene.wheel_profiles()[0] != scene.wheel_profiles()[1] {
        push(
            "right_wheel_profile.csv",
            "right wheel profile",
            tables::wheel_profile(p.right().wheel()).map_err(table_error)?,
        );
    }
    push(
        "rail_profile.csv",
        "left rail as placed: height, slope, curvature",
        tables::rail_profile(p.left().rail(), Side::Left).map_err(table_error)?,
    );
    if scene.rail_profiles()[0] != scene.rail_profiles()[1] {
        push(
            "right_rail_profile.csv",
            "right rail as placed",
            tables::rail_profile(p.right().rail(), Side::Right).map_err(table_error)?,
        );
    }
    push(
        "profile_dimensions.csv",
        "flange dimensions Sh, Sd, qR of the wheels against their limits; rail wear against the nominal rail",
        tables::profile_dimensions(p, &results.maintenance).map_err(table_error)?,
    );
    Ok(())
}

/// The contact searches' tables: rigid, quasi-elastic, eps sensitivity, Hertz.
fn contact_tables(
    scene: &Scene,
    results: &Results,
    out: &mut Vec<NamedTable>,
) -> Result<(), Error> {
    let mut push =
        |file: &str, description: &str, table: Table| push_table(out, file, description, table);
    if let Some(r) = &results.rigid {
        push(
            "rigid.csv",
            "rigid contact over the sweep",
            tables::rigid(r).map_err(table_error)?,
        );
        push(
            "rigid_jumps.csv",
            "intervals where a rigid contact point jumps",
            tables::rigid_jumps(r).map_err(table_error)?,
        );
    }
    if let Some(q) = &results.quasi_elastic {
        push(
            "quasi_elastic.csv",
            "quasi-elastic contact over the sweep",
            tables::quasi_elastic(q).map_err(table_error)?,
        );
    }
    if let (Some(r), Some(e)) = (&results.rigid, &results.epsilon) {
        push(
            "qe_epsilon.csv",
            "quasi-elastic contact location for several eps",
            tables::epsilon_sensitivity(r, e).map_err(table_error)?,
        );
    }
    if let Some(h) = &results.hertz {
        push(
            "hertz.csv",
            "Hertz contact ellipses over the sweep",
            tables::hertz(h, scene.hertz()).map_err(table_error)?,
        );
    }
    Ok(())
}

/// The tables that assess the contact, in this order: equivalent conicity and the pair's
/// parameters, creep forces, the contact table, the accuracy of the paper's Hertz numerics.
fn assessment_tables(results: &Results, out: &mut Vec<NamedTable>) -> Result<(), Error> {
    let mut push =
        |file: &str, description: &str, table: Table| push_table(out, file, description, table);
    if let Some(c) = &results.conicity {
        push(
            "equivalent_conicity.csv",
            "equivalent conicity against the amplitude, both methods (EN 15302)",
            tables::equivalent_conicity(c).map_err(table_error)?,
        );
        push(
            "parameters.csv",
            "parameters of the pair: tan gamma_e at 2, 3, 4 mm, nonlinearity, flange contact, jumps",
            tables::parameters(&c.parameters).map_err(table_error)?,
        );
    }
    if let Some(Ok(c)) = &results.creep {
        push(
            "creep.csv",
            "creep forces of every patch over the sweep",
            creep::creep(c).map_err(table_error)?,
        );
    }
    if let Some(t) = &results.contact_table {
        push(
            "contact_table.csv",
            "contact table: rigid contact, Hertz ellipse and Kalker's coefficients on a grid of shift x yaw",
            creep::contact_table(t).map_err(table_error)?,
        );
    }
    if let Some(a) = &results.hertz_accuracy {
        let (series, ratio) = tables::hertz_accuracy(a).map_err(table_error)?;
        push(
            "hertz_accuracy_series.csv",
            "error of the paper's K and E series",
            series,
        );
        push(
            "hertz_accuracy_ratio.csv",
            "error of the paper's b/a iteration",
            ratio,
        );
    }
    Ok(())
}

/// The chart of `fig`, from the stage result it draws (which the run computed).
///
/// # Errors
/// [`Error::MissingStage`] if the stage result is missing (the pipeline was run for another
/// scene).
pub fn figure(fig: Figure, results: &Results) -> Result<crate::Figure, Error> {
    let missing = || Error::MissingStage {
        figure: fig.name(),
        stage: fig.stage().name(),
    };
    let p = &results.placement;
    let rigid = || results.rigid.as_ref().ok_or_else(missing);
    Ok(match fig {
        Figure::Profiles => figures::profiles(p),
        Figure::Conicity => figures::conicity(p),
        Figure::Curvature => figures::curvature(p),
        Figure::ContactPoints => figures::contact_points(p, rigid()?),
        Figure::RollingRadius => figures::rolling_radius(rigid()?),
        Figure::ContactAngles => figures::contact_angles(rigid()?),
        Figure::ContactLead => figures::contact_lead(rigid()?),
        Figure::Roll => figures::roll(rigid()?),
        Figure::ContactAngleParameter => figures::contact_angle_parameter(rigid()?),
        Figure::ContactMap => figures::contact_map(p, rigid()?),
        Figure::QuasiElasticPoints => figures::quasi_elastic_points(
            rigid()?,
            results.quasi_elastic.as_ref().ok_or_else(missing)?,
        ),
        Figure::QuasiElasticMap => figures::quasi_elastic_map(
            p,
            rigid()?,
            results.quasi_elastic.as_ref().ok_or_else(missing)?,
        ),
        Figure::EpsilonSensitivity => {
            figures::epsilon_sensitivity(rigid()?, results.epsilon.as_ref().ok_or_else(missing)?)
        }
        Figure::SemiAxes => {
            figures::semi_axes(results.hertz.as_ref().ok_or_else(missing)?.positions())
        }
        Figure::Pressure => {
            figures::pressure(results.hertz.as_ref().ok_or_else(missing)?.positions())
        }
        Figure::HertzAccuracy => {
            figures::hertz_accuracy(results.hertz_accuracy.as_ref().ok_or_else(missing)?)
        }
        Figure::EquivalentConicity => {
            figures::equivalent_conicity(results.conicity.as_ref().ok_or_else(missing)?)
        }
        Figure::DeltaRLinearised => {
            figures::delta_r_linearised(results.conicity.as_ref().ok_or_else(missing)?)
        }
        Figure::CreepForces => figures::creep_forces(creep_result(results, missing)?),
        Figure::CreepCurve => figures::creep_curve(
            wheelrail::creep::sweep::curve(creep_result(results, missing)?).as_ref(),
        ),
    })
}

/// The creep stage's result, its error, or `missing()` where it did not run.
fn creep_result(
    results: &Results,
    missing: impl Fn() -> Error,
) -> Result<&wheelrail::creep::sweep::CreepSweep, Error> {
    match &results.creep {
        Some(Ok(c)) => Ok(c),
        Some(Err(e)) => Err(Error::Numerics(e.clone().into())),
        None => Err(missing()),
    }
}

/// The figure of the paper (Onat, Voltr & Lata 2014) that `fig` redraws, if any.
fn paper_figure(fig: Figure) -> Option<&'static str> {
    Some(match fig {
        Figure::Profiles | Figure::Conicity => "Fig. 1",
        Figure::ContactPoints
        | Figure::RollingRadius
        | Figure::ContactAngles
        | Figure::Roll
        | Figure::ContactAngleParameter => "Fig. 2",
        Figure::QuasiElasticPoints => "Fig. 4",
        Figure::QuasiElasticMap => "Fig. 5",
        Figure::SemiAxes => "Fig. 6",
        _ => return None,
    })
}

/// The caption of a figure in the report: "Paper Fig. N: " before it only where the scene
/// is the paper's case ([`Scene::is_paper_case`]), remarks only where the figure shows what
/// they describe.
pub(crate) fn caption(fig: Figure, scene: &Scene, results: &Results) -> String {
    let text = match fig {
        Figure::Profiles => "wheel and rail of the left side in their placed positions (centred wheelset resting on the rail, no roll), track frame.".into(),
        Figure::Conicity => figures::conicity_caption(&results.placement),
        Figure::Curvature => {
            let joints = if results.placement.left().wheel().profile().joints().is_empty() {
                ""
            } else {
                " The wheel's curvature jumps at every section joint of its definition."
            };
            format!("lateral curvature of the profiles, convex positive.{joints}")
        }
        Figure::ContactPoints => "rigid contact points on the wheel (profile coordinate) and on the rail (from the top of rail) against the lateral shift. Jumps of a contact point are gaps, not lines.".into(),
        Figure::RollingRadius => "rolling radius difference r_left - r_right of the rigid contact.".into(),
        Figure::ContactAngles => "contact angles of the rigid contact in the track frame, roll included, mirrored per side.".into(),
        Figure::ContactLead => {
            let yaw = scene.sweep().yaw();
            format!(
                "lead of each wheel's rigid contact point ahead of the axle, along the wheelset's own forward axis, for the wheelset yawed by {} mrad + {} mrad/mm × y_ws ({} outline: the points of the wheel the rail sees); on the tread a fraction of a millimetre, on the flange about r tan γ ψ. Without yaw the lead is 0.",
                wheelrail::message::Number(yaw.yaw_rad() * 1e3),
                wheelrail::message::Number(yaw.yaw_rad_per_mm() * 1e3),
                yaw.model().name()
            )
        }
        Figure::Roll => "roll angle of the wheelset solved with the contact (paper Eqs. 2-5).".into(),
        Figure::ContactAngleParameter => "Wickens' contact angle parameter; undefined at y_ws = 0.".into(),
        Figure::ContactMap => "contact map: each rigid contact point of the sweep on the wheel (drawn 8 mm above its resting place) linked to its point on the rail; where contact lives and where it jumps.".into(),
        Figure::QuasiElasticPoints => format!("rigid and quasi-elastic contact points (eps = {} mm); the quasi-elastic heaviest patch as a line, a second patch as markers.", scene.quasi_elastic().epsilon_mm()),
        Figure::QuasiElasticMap => "contact map with rigid and quasi-elastic contact points.".into(),
        Figure::EpsilonSensitivity => "sensitivity of the quasi-elastic contact location to the regularisation parameter eps; as eps decreases it tends to the rigid solution.".into(),
        Figure::SemiAxes => format!(
            "semi-axes of the Hertz contact ellipses ({} method, {} contact, normal load {}, vertical wheel load {} kN).",
            scene.hertz().method(), scene.hertz_contact().name(), scene.hertz().normal_load().name(), scene.wheel_load_n() / 1000.0
        ),
        Figure::Pressure => "maximum Hertz pressure p0 = 3P / (2 pi a b) (paper Eq. 11).".into(),
        Figure::EquivalentConicity => format!("equivalent conicity tan γe against the amplitude ŷ of the kinematic motion (EN 15302): Klingel wavelength of the nonlinear motion (Annex B, exact closed-form integral) and harmonically weighted regression of Δr (Annex C); tan γe(3 mm) by the scene's method ({}) marked. Gauge and rolling radius cancel.", scene.conicity().method().name()),
        Figure::DeltaRLinearised => "rolling radius difference of the rigid sweep (jumps as steps) and the linear function 2 tan γe(3 mm) (y - y_eq) of the equivalent cone over the motion y_eq ± 3 mm.".into(),
        Figure::CreepForces => {
            let c = scene.creep();
            format!(
                "creep forces of the wheel on the rail in each patch's contact frame (Fx along the rail, Fy in the contact plane; a positive creepage gives a negative force), {} with mu = {}, from the {} contacts; the heaviest patch as a line, a second patch as markers; patches that did not converge left out. The wheelset {}, at the speed {} m/s, each patch carrying its weight share of the {} kN wheel load with the normal force solved for it (FN cos δ - Fy sin δ = load).",
                c.settings.method(),
                c.settings.friction(),
                c.contact.name(),
                match c.kinematics.pitch_rate {
                    wheelrail::creep::sweep::PitchRate::FreeRolling => "rolls freely (pitch rate from the mean rolling radius of the two wheels' contacts)",
                    wheelrail::creep::sweep::PitchRate::Given(_) => "rolls at the pitch rates the scene gives",
                },
                c.kinematics.speed_mm_s / 1000.0,
                scene.wheel_load_n() / 1000.0
            )
        }
        Figure::CreepCurve => "force against creepage on one patch, the one of the sweep that uses the largest part of its friction (named in the title): its creepages xi, eta, phi scaled together from free rolling (0) through the patch as the sweep found it (the mark) towards full sliding, on its ellipse at its normal force. Kalker's linear theory is the slope at the origin; FASTSIM (the scene's bound and grid) saturates at mu FN (the dashed line at 1). Polach's method with spin levels off lower where the spin is large: it divides the force along (xi, eta) by the creepage with spin, sqrt(xi^2 + (eta + a phi)^2), and adds a bounded lateral force of the spin.".into(),
        Figure::HertzAccuracy => "accuracy of the paper's Hertz numerics: its truncated series for K and E (Eqs. 15-18) against the arithmetic-geometric mean, and its fixed-point iteration for b/a against the exact inversion; the exact method's b/a against 50-digit mpmath references.".into(),
    };
    match paper_figure(fig) {
        Some(n) if scene.is_paper_case() => format!("Paper {n}: {text}"),
        _ => capitalised(&text),
    }
}

/// `text` with its first letter in upper case.
pub(crate) fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}
/// Every output file of a scene: its tables, then its figures in the scene's formats (made
/// in parallel on rayon's pool, one figure a task), then `index.html`. `extra` figures
/// (already written by another command, such as `wheelrail tradeoff`) are listed in the page
/// after the scene's own.
///
/// # Errors
/// [`Error::Chart`] when a figure cannot be rendered.
pub fn render(
    scene: &Scene,
    results: &Results,
    extra: &[FigureEntry],
) -> Result<Vec<OutputFile>, Error> {
    use rayon::prelude::*;
    let tables = tables(scene, results)?;
    let figures: Vec<Vec<OutputFile>> = scene
        .figures()
        .par_iter()
        .map(|&fig| chart_files(fig.name(), &figure(fig, results)?, scene.formats()))
        .collect::<Result<_, _>>()?;
    let entries: Vec<FigureEntry> = scene
        .figures()
        .iter()
        .map(|&fig| figure_entry(fig.name(), caption(fig, scene, results), scene.formats()))
        .chain(extra.iter().cloned())
        .collect();
    let listed: Vec<(String, String)> = tables
        .iter()
        .map(|t| (t.file.clone(), t.description.clone()))
        .collect();
    let page = page::report_page(scene, results, &listed, entries);
    let mut files: Vec<OutputFile> = tables
        .into_iter()
        .map(|t| OutputFile {
            bytes: t.table.to_csv_bytes(CSV_FORMAT),
            name: t.file,
        })
        .collect();
    files.extend(figures.into_iter().flatten());
    files.push(OutputFile {
        name: "index.html".into(),
        bytes: crate::render_html(&page).into_bytes(),
    });
    Ok(files)
}
/// The files of the chart `name` in each of `formats` (`NAME.svg`, `NAME.png`).
///
/// # Errors
/// [`Error::Chart`] naming the chart when it cannot be rendered.
pub(crate) fn chart_files(
    name: &str,
    chart: &crate::Figure,
    formats: &[ImageFormat],
) -> Result<Vec<OutputFile>, Error> {
    let fail = |e| Error::Chart(name.into(), e);
    formats
        .iter()
        .map(|format| {
            Ok(match format {
                ImageFormat::Svg => OutputFile {
                    name: format!("{name}.svg"),
                    bytes: crate::render_svg(chart).map_err(fail)?.into_bytes(),
                },
                ImageFormat::Png => OutputFile {
                    name: format!("{name}.png"),
                    bytes: crate::render_png(chart).map_err(fail)?,
                },
            })
        })
        .collect()
}
/// The report page's entry of the chart `name`, with the files [`chart_files`] makes of it
/// in `formats` (an empty name for a format not made).
pub(crate) fn figure_entry(name: &str, caption: String, formats: &[ImageFormat]) -> FigureEntry {
    let file = |format: ImageFormat, extension: &str| {
        if formats.contains(&format) {
            format!("{name}.{extension}")
        } else {
            String::new()
        }
    };
    FigureEntry {
        name: name.to_string(),
        caption,
        svg: file(ImageFormat::Svg, "svg"),
        png: file(ImageFormat::Png, "png"),
    }
}

/// A study of `wheelrail tradeoff`: run time against error of the scene's numerical settings
/// (`tradeoff.csv` and chart `tradeoff`) or of FASTSIM's grid (`fastsim_tradeoff`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Study {
    /// The scene's numerical settings ([`crate::tradeoff::study`]).
    Settings,
    /// FASTSIM's grids ([`crate::tradeoff::fastsim::study`]).
    FastsimGrids,
}

impl Study {
    /// Both studies, in the order of the report page.
    pub const ALL: [Study; 2] = [Study::Settings, Study::FastsimGrids];

    /// The stem of the study's files (`tradeoff`: `tradeoff.csv`, `tradeoff.svg`, ...).
    pub fn name(self) -> &'static str {
        match self {
            Study::Settings => "tradeoff",
            Study::FastsimGrids => "fastsim_tradeoff",
        }
    }

    /// The chart points of the study's table `text` read from `origin`.
    ///
    /// # Errors
    /// [`crate::tradeoff::TradeoffCsvError`] when the text is no such table.
    pub fn points(
        self,
        text: &str,
        origin: &str,
    ) -> Result<Vec<crate::tradeoff::ChartPoint>, crate::tradeoff::TradeoffCsvError> {
        match self {
            Study::Settings => crate::tradeoff::chart_points(text, origin),
            Study::FastsimGrids => crate::tradeoff::fastsim::chart_points(text, origin),
        }
    }

    /// The chart of the study's `points`.
    pub fn chart(self, points: &[crate::tradeoff::ChartPoint]) -> crate::Figure {
        match self {
            Study::Settings => figures::tradeoff(points),
            Study::FastsimGrids => figures::fastsim_tradeoff(points),
        }
    }

    /// The study's table as `csv` and the chart of its `points` in `formats` (also to draw
    /// the chart again from a committed table, `wheelrail tradeoff --replot`).
    ///
    /// # Errors
    /// [`Error::Chart`] when the chart cannot be rendered.
    pub fn files(
        self,
        csv: String,
        points: &[crate::tradeoff::ChartPoint],
        formats: &[ImageFormat],
    ) -> Result<Vec<OutputFile>, Error> {
        let name = self.name();
        let mut files = vec![OutputFile {
            name: format!("{name}.csv"),
            bytes: csv.into_bytes(),
        }];
        files.extend(chart_files(name, &self.chart(points), formats)?);
        Ok(files)
    }

    /// The report page's entry of the study's chart.
    pub fn entry(self) -> FigureEntry {
        let caption = match self {
            Study::Settings => String::from(
                "Run time against error of numerical settings (measured by `wheelrail tradeoff`, not by the report run: times are those of the machine that ran it). Each point is a setting, numbered as in the key below the chart (tradeoff.csv has every measurement); the Pareto front, the settings no other beats in both time and error, is the staircase that bounds what they dominate. Errors of exactly 0, settings that reproduce the reference to the last bit, are drawn in the shaded band 'exact (0)' at the foot of a panel, below the decades of the others.",
            ),
            Study::FastsimGrids => {
                use wheelrail::creep::{DEFAULT_GRID, fastsim::STUDY_REFERENCE};
                format!(
                    "Run time against error of FASTSIM's discretisation (measured by `wheelrail tradeoff`: times are those of the machine that ran it), strips across the patch times elements along each strip. Errors are the largest over {} cases (patches of a/b = 1.5 and 0.375 at 50 kN; creepages of 0.3, 1 and 3 times the creepage that saturates linear theory, in ξ, η, φ alone and together) against FASTSIM on {} x {} cells, forces relative to μ FN and spin moments to μ FN c; the time is one patch's solve, single-threaded. The default grid, {} x {}, is chosen from this study (fastsim_tradeoff.csv has every measurement); the Pareto front is the staircase that bounds what the grids on it dominate.",
                    wheelrail::creep::fastsim::study_cases().len(),
                    STUDY_REFERENCE.strips,
                    STUDY_REFERENCE.elements,
                    DEFAULT_GRID.strips,
                    DEFAULT_GRID.elements
                )
            }
        };
        let name = self.name();
        FigureEntry {
            name: name.into(),
            caption,
            svg: format!("{name}.svg"),
            png: format!("{name}.png"),
        }
    }
}

/// The files of the scene settings' study: `tradeoff.csv` and its chart in `formats`.
///
/// # Errors
/// [`Error::Chart`] when the chart cannot be rendered.
pub fn tradeoff_files(
    m: &[crate::tradeoff::Measurement],
    formats: &[ImageFormat],
) -> Result<Vec<OutputFile>, Error> {
    let csv = tables::tradeoff(m).map_err(table_error)?;
    let points: Vec<crate::tradeoff::ChartPoint> = m.iter().map(Into::into).collect();
    Study::Settings.files(csv.to_csv_with(CSV_FORMAT), &points, formats)
}

/// The files of FASTSIM's grid study: `fastsim_tradeoff.csv` and its chart in `formats`.
///
/// # Errors
/// [`Error::Chart`] when the chart cannot be rendered.
pub fn fastsim_tradeoff_files(
    m: &[crate::tradeoff::fastsim::GridMeasurement],
    formats: &[ImageFormat],
) -> Result<Vec<OutputFile>, Error> {
    let points: Vec<_> = m.iter().map(Into::into).collect();
    let csv = tables::fastsim_tradeoff(m).map_err(table_error)?;
    Study::FastsimGrids.files(csv.to_csv_with(CSV_FORMAT), &points, formats)
}
