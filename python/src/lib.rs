//! The Python package `wheelrail`: the library's public API as Python functions, with NumPy
//! arrays in and out.
//!
//! A thin skin: every function converts its arguments, calls the library with the
//! interpreter released (`convert::detached`), and converts the result; no numerics live
//! here, so the library's tests cover what it computes. Tables are the library's own
//! (`wheelrail_report::outputs::tables`), handed to NumPy column by column without a copy: the
//! same names and values as the CSV files of `wheelrail report`. Errors of input map to
//! `wheelrail.InputError` (a `ValueError`) with the library's message, the one the command
//! line prints (`convert::input`); a panic (a bug) becomes a `RuntimeError`, never an
//! abort.

mod convert;
mod patch;

use convert::{
    InputError, ProfileArg, Values, detached, input, number, one_of, plausible, scene_dict,
    table_dict, text_array, to_vec,
};
use numpy::{AllowTypeChange, PyArray1, PyArrayLike1};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::{Path, PathBuf};
use wheelrail::conicity::DeltaR;
use wheelrail::fleet::{Fleet, FleetError, Inputs, items_of_files, read_pairs};
use wheelrail::hertz::Contact;
use wheelrail::pipeline::Stage;
use wheelrail::plausible;
use wheelrail::prelude::{
    ConicityMethod, ConicitySettings, EllipseMethod, Inclination, Material, Placement, ProfileKind,
    ReadOptions, Scene, Solver, StepBack, Sweep, TrackLayout, conicity, hertz, pipeline,
    read_profile_with, rigid,
};
use wheelrail::sweep::SweepError;
use wheelrail::track::LayoutError;
use wheelrail_report::outputs;

/// The result of :func:`run`: the tables of every stage that ran and the checked scene.
///
/// Attributes
/// ----------
/// tables : dict[str, dict[str, numpy.ndarray]]
///     Each table of the report by the name of its CSV file without ``.csv``
///     (``"wheel_profile"``, ``"rail_profile"``, ``"profile_dimensions"``, ``"rigid"``,
///     ``"rigid_jumps"``, ``"quasi_elastic"``, ``"qe_epsilon"``, ``"hertz"``,
///     ``"equivalent_conicity"``, ``"parameters"``, ``"creep"``, ``"contact_table"``,
///     ...), in the order the report writes them. A table maps its
///     column names (units in the names) to arrays in column order: ``float64`` for
///     numbers (NaN where a value is undefined, the reason in a status column), ``str``
///     for text. ``pandas.DataFrame(run.tables["rigid"])`` takes it as it is.
/// scene : dict
///     The checked scene: every key with its value after the defaults and unit
///     conversions (mm, N, MPa, rad; the unit in each key's name).
/// timings : dict[str, float]
///     The stages that ran, in order, with their wall-clock time in seconds (the
///     placement, ``"profiles"``, only when the scene's own stages ran).
#[pyclass(frozen, module = "wheelrail")]
struct Run {
    #[pyo3(get)]
    tables: Py<PyDict>,
    #[pyo3(get)]
    scene: Py<PyDict>,
    #[pyo3(get)]
    timings: Py<PyDict>,
    /// The scene file as given, for the repr.
    path: String,
}

#[pymethods]
impl Run {
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let names: Vec<String> = self.tables.bind(py).keys().extract()?;
        Ok(format!("Run(scene={:?}, tables={names:?})", self.path))
    }
}

/// Runs a scene file as ``wheelrail report`` does and returns its tables.
///
/// Parameters
/// ----------
/// scene_path : str or os.PathLike
///     The scene file (TOML); profile paths in it are relative to its folder.
/// stages : sequence of str, optional
///     The stages to run (``"rigid"``, ``"quasi_elastic"``, ``"epsilon_sensitivity"``,
///     ``"hertz"``, ``"equivalent_conicity"``, ``"hertz_accuracy"``, ``"creep"``,
///     ``"contact_table"``) with the stages they need. Default: those the scene's figures,
///     ``[creep]`` and ``[table]`` need, as the report runs them.
///
/// Returns
/// -------
/// Run
///     ``.tables`` (the CSV files' columns and values), ``.scene``, ``.timings``.
///
/// Raises
/// ------
/// InputError
///     The scene or a profile it names cannot be read, is invalid or cannot be placed (the
///     message names the file and the key or line, as the command line's does), or a
///     stage name is unknown.
#[pyfunction]
#[pyo3(signature = (scene_path, stages = None))]
fn run(py: Python<'_>, scene_path: PathBuf, stages: Option<Vec<String>>) -> PyResult<Run> {
    let stages = stages
        .map(|names| {
            names
                .iter()
                .map(|n| {
                    Stage::from_name(n)
                        .ok_or_else(|| one_of("stages", n, Stage::ALL.iter().map(|s| s.name())))
                })
                .collect::<PyResult<Vec<Stage>>>()
        })
        .transpose()?;
    let (scene, results, tables) = detached(py, move || {
        let scene = Scene::load(&scene_path)?;
        let results = match &stages {
            None => pipeline::run(&scene)?,
            Some(stages) => pipeline::run_on(&scene, pipeline::place(&scene)?, stages),
        };
        let tables = outputs::tables(&scene, &results)?;
        Ok::<_, wheelrail_report::Error>((scene, results, tables))
    })?
    .map_err(input)?;
    let all = PyDict::new(py);
    for t in tables {
        let name = t.file.strip_suffix(".csv").unwrap_or(&t.file);
        all.set_item(name, table_dict(py, t.table)?)?;
    }
    let timings = PyDict::new(py);
    for (stage, seconds) in &results.record.stages {
        timings.set_item(stage.name(), seconds)?;
    }
    Ok(Run {
        tables: all.unbind(),
        scene: scene_dict(py, &scene)?.unbind(),
        timings: timings.unbind(),
        path: scene.path().to_string(),
    })
}

/// Reads a wheel or rail profile file into arrays, in the profile's side frame.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     ``.csv`` (wheelrail's CSV), ``.prw``/``.prr`` (SIMPACK), ``.whl``/``.ban``
///     (MiniProf), any case.
/// kind : {"wheel", "rail"}
///     What the file holds.
/// drop_step_backs : bool
///     Drop measured points that step back laterally (listed in ``dropped_step_backs``)
///     instead of refusing the file, as the scene key ``drop_step_backs`` does.
///
/// Returns
/// -------
/// dict
///     A wheel: ``s_mm`` (from the taping line, positive towards the field side, the
///     flange at s < 0) and ``F_mm`` (radius increase over the nominal radius); a rail:
///     ``y_mm`` (lateral, positive towards the field side) and ``z_mm`` (up), as
///     ``float64`` arrays in increasing lateral order; and ``kind``, ``path``, ``sha256``
///     (of the file's bytes), ``format``, ``dropped_step_backs`` (1-based lines).
///
/// Raises
/// ------
/// InputError
///     The file cannot be read or is not a valid profile (the message names the file and
///     line).
#[pyfunction]
#[pyo3(signature = (path, kind = "wheel", drop_step_backs = false))]
fn read_profile<'py>(
    py: Python<'py>,
    path: PathBuf,
    kind: &str,
    drop_step_backs: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let kind = profile_kind(kind)?;
    let options = ReadOptions::new(if drop_step_backs {
        StepBack::Drop
    } else {
        StepBack::Refuse
    });
    let profile = detached(py, move || read_profile_with(&path, kind, &options))?.map_err(input)?;
    let (lateral, vertical) = profile.columns();
    let [lateral_name, vertical_name] = convert::point_columns(kind);
    let d = PyDict::new(py);
    d.set_item(lateral_name, PyArray1::from_vec(py, lateral))?;
    d.set_item(vertical_name, PyArray1::from_vec(py, vertical))?;
    d.set_item("kind", kind.to_string())?;
    d.set_item("path", &profile.source.path)?;
    d.set_item("sha256", &profile.source.sha256)?;
    d.set_item("format", profile.source.format.name())?;
    d.set_item("dropped_step_backs", &profile.dropped_step_backs)?;
    Ok(d)
}

/// Rigid contact of a symmetric wheelset over lateral shifts, with the equivalent
/// conicity of its Δr: the library's ``Placement`` and ``rigid.search`` underneath.
///
/// Both wheels get ``wheel`` (the right one mirrored by its side frame), both rails
/// ``rail``.
///
/// Parameters
/// ----------
/// wheel, rail : str, dict or array_like
///     A built-in profile name (``"S1002"``, ``"UIC60E1"``), a dict from
///     :func:`read_profile`, or points as an (N, 2) array in the side frame (mm; a wheel
///     ``[s, F]``, a rail ``[y, z]``).
/// shifts_mm : array_like
///     Lateral shifts of the wheelset (mm, track frame, positive to the left), finite and
///     strictly increasing.
/// inclination : str
///     Rail inclination of the track: ``"1:40"``, ``"1:20"``, ``"1:30"``, ``"vertical"``
///     or an angle in radians.
/// gauge_mm, gauge_point_depth_mm, flange_back_mm, nominal_radius_mm : float
///     Track gauge, depth of the gauge point below the top of rail, distance between the
///     wheels' inner faces, nominal rolling radius (mm).
/// rail_profile_inclination : str
///     The inclination the rail points already have (default upright).
/// smoothing_wavelength_mm : float
///     Filter wavelength of the spline through points (0 interpolates them).
/// solver : {"default", "paper", "no_roll"}
///     The rigid solver: the project's, the paper's iteration, or no roll (the wheelset
///     held level, EN 15302 Annex E).
/// conicity_method : {"klingel", "regression"}
///     The method of the pair's parameters (both are tabulated).
/// amplitudes_mm : array_like, optional
///     Amplitudes of the equivalent conicity (mm, > 0); default 0.5 to 10 mm by 0.1 mm,
///     clipped to what the sweep supports.
///
/// Returns
/// -------
/// dict[str, dict[str, numpy.ndarray]]
///     The tables ``"rigid"``, ``"rigid_jumps"``, ``"equivalent_conicity"`` and
///     ``"parameters"``, as :attr:`Run.tables` holds them.
///
/// Raises
/// ------
/// InputError
///     A bad profile, layout, shift or name (the message names the argument).
#[pyfunction]
#[pyo3(signature = (
    wheel, rail, shifts_mm, *, inclination = "1:40", gauge_mm = 1435.0,
    gauge_point_depth_mm = 14.0, flange_back_mm = 1360.0, nominal_radius_mm = 460.0,
    rail_profile_inclination = "vertical", smoothing_wavelength_mm = 0.0, solver = "default",
    conicity_method = "klingel", amplitudes_mm = None
))]
#[allow(clippy::too_many_arguments)] // Python's keyword arguments, one per scene key
fn rigid_sweep<'py>(
    py: Python<'py>,
    wheel: ProfileArg<'py>,
    rail: ProfileArg<'py>,
    shifts_mm: PyArrayLike1<'py, f64, AllowTypeChange>,
    inclination: &str,
    gauge_mm: f64,
    gauge_point_depth_mm: f64,
    flange_back_mm: f64,
    nominal_radius_mm: f64,
    rail_profile_inclination: &str,
    smoothing_wavelength_mm: f64,
    solver: &str,
    conicity_method: &str,
    amplitudes_mm: Option<PyArrayLike1<'py, f64, AllowTypeChange>>,
) -> PyResult<Bound<'py, PyDict>> {
    let parse =
        |key: &str, text: &str| Inclination::parse(text).map_err(|e| input(format!("{key}: {e}")));
    let layout = TrackLayout::new(
        gauge_mm,
        gauge_point_depth_mm,
        flange_back_mm,
        parse("inclination", inclination)?,
    )
    .map_err(|e| {
        let key = match e {
            LayoutError::Gauge { .. } => "gauge_mm",
            LayoutError::GaugePointDepth { .. } => "gauge_point_depth_mm",
            LayoutError::FlangeBack { .. } => "flange_back_mm",
            _ => "inclination",
        };
        input(format!("{key}: {e}"))
    })?;
    let rail_profile_inclination = parse("rail_profile_inclination", rail_profile_inclination)?;
    let solver = Solver::from_name(solver)
        .ok_or_else(|| one_of("solver", solver, ["default", "paper", "no_roll"]))?;
    let settings = ConicitySettings::new(conicity_method_named(conicity_method)?);
    let settings = match amplitudes_mm {
        Some(a) => settings
            .with_amplitudes_mm(amplitudes(&a)?)
            .map_err(|e| input(format!("amplitudes_mm: {e}")))?,
        None => settings,
    };
    let shifts = sweep(&shifts_mm)?;
    let wheel = wheel.points(ProfileKind::Wheel, "wheel")?;
    let rail = rail.points(ProfileKind::Rail, "rail")?;
    let tables = detached(py, move || {
        let wheel = wheel.profile(smoothing_wavelength_mm)?;
        let rail = rail.profile(smoothing_wavelength_mm)?;
        let placement = Placement::symmetric(
            wheel,
            nominal_radius_mm,
            rail,
            rail_profile_inclination,
            layout,
        )
        .map_err(|e| e.to_string())?;
        let sweep = rigid::search(&placement, &shifts, solver);
        let pair = conicity::assess(&sweep, &settings);
        let table = |name: &'static str, t: Result<wheelrail_report::Table, _>| {
            t.map(|t| (name, t))
                .map_err(|e| format!("internal error building {name}: {e}"))
        };
        Ok::<_, String>([
            table("rigid", outputs::tables::rigid(&sweep))?,
            table("rigid_jumps", outputs::tables::rigid_jumps(&sweep))?,
            table(
                "equivalent_conicity",
                outputs::tables::equivalent_conicity(&pair),
            )?,
            table("parameters", outputs::tables::parameters(&pair.parameters))?,
        ])
    })?
    .map_err(input)?;
    let d = PyDict::new(py);
    for (name, t) in tables {
        d.set_item(name, table_dict(py, t)?)?;
    }
    Ok(d)
}

/// The equivalent conicity of EN 15302 from a rolling radius difference function, as
/// ``wheelrail conicity`` prints it.
///
/// Parameters
/// ----------
/// y_mm : array_like
///     Lateral displacements (mm, positive to the left), strictly increasing, at least 3.
/// delta_r_mm : array_like
///     Δr = r_left - r_right at each (mm), finite, changing sign from negative to positive.
/// amplitudes_mm : array_like, optional
///     Amplitudes (mm, > 0), all reported (NaN with a status beyond what Δr supports).
///     Default 0.5 to 10 mm by 0.1 mm, clipped to what Δr supports.
/// method : {"klingel", "regression"}
///     EN 15302 Annex B (Klingel wavelength) or Annex C (regression).
///
/// Returns
/// -------
/// dict[str, numpy.ndarray]
///     ``amplitude_mm``, ``tan_gamma_e``, ``centre_mm`` (float64) and ``status`` (str).
///
/// Raises
/// ------
/// InputError
///     Too few points, a point not finite or not increasing, no sign change, a bad
///     amplitude or method.
#[pyfunction]
#[pyo3(signature = (y_mm, delta_r_mm, amplitudes_mm = None, method = "klingel"))]
fn equivalent_conicity<'py>(
    py: Python<'py>,
    y_mm: PyArrayLike1<'py, f64, AllowTypeChange>,
    delta_r_mm: PyArrayLike1<'py, f64, AllowTypeChange>,
    amplitudes_mm: Option<PyArrayLike1<'py, f64, AllowTypeChange>>,
    method: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let method = conicity_method_named(method)?;
    let amplitudes = amplitudes_mm.map(|a| amplitudes(&a)).transpose()?;
    let delta_r = DeltaR::new(to_vec(&y_mm), to_vec(&delta_r_mm))
        .map_err(|e| input(format!("y_mm, delta_r_mm: {e}")))?;
    let table = detached(py, move || {
        let result = match amplitudes {
            Some(a) => conicity::equivalent_conicity(&delta_r, &a, method),
            None => conicity::equivalent_conicity_clipped(&delta_r, method),
        };
        outputs::tables::conicity_points(&result, "arrays")
    })?
    .map_err(|e| input(format!("internal error building the table: {e}")))?;
    table_dict(py, table)
}

/// Assesses many profiles through one template scene, as ``wheelrail fleet`` does, and
/// returns the rows of its ``fleet.csv``.
///
/// Parameters
/// ----------
/// scene_path : str or os.PathLike
///     The template scene (track, rail, load, sweep, settings).
/// profiles : sequence of str or os.PathLike
///     Profile files, each put on both wheels (both rails with ``rails=True``); the ids
///     come from the file names.
/// pairs : str or os.PathLike, optional
///     Instead of ``profiles``: a CSV of wheelsets measured wheel by wheel (columns
///     ``id,left_wheel,right_wheel`` and optionally ``left_rail,right_rail``, paths
///     relative to it).
/// rails : bool
///     The profiles are rails.
///
/// Returns
/// -------
/// dict[str, numpy.ndarray]
///     ``fleet.csv``'s columns in input order: ``id``, the files and their SHA-256,
///     ``status`` (``ok``, or why a row's files could not be assessed), the pair's
///     parameters, ``max_p0_MPa`` and where when the template runs Hertz, and
///     ``undefined_status``. A bad file is its row's status, not an exception.
///
/// Raises
/// ------
/// InputError
///     The scene or the pairs file cannot be read or is invalid, no profiles are given,
///     or both ``profiles`` and ``pairs``.
#[pyfunction]
#[pyo3(signature = (scene_path, profiles = None, pairs = None, rails = false))]
fn fleet<'py>(
    py: Python<'py>,
    scene_path: PathBuf,
    profiles: Option<Vec<PathBuf>>,
    pairs: Option<PathBuf>,
    rails: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let profiles = profiles.unwrap_or_default();
    if pairs.is_some() && (rails || !profiles.is_empty()) {
        return Err(input(
            "pairs: a pairs file names its own wheels and rails; give either profiles or pairs",
        ));
    }
    let table = detached(py, move || {
        let template = Scene::load(&scene_path)?;
        let (items, inputs) = match &pairs {
            Some(path) => read_pairs(Path::new(path))?,
            None if rails => (items_of_files(&profiles, true), Inputs::Rails),
            None => (items_of_files(&profiles, false), Inputs::Wheels),
        };
        if items.is_empty() {
            return Err(FleetError::NoItems.into());
        }
        let fleet = Fleet::new(template, inputs, &items, false)?;
        let mut rows = Vec::with_capacity(items.len());
        fleet.assess_in_order(&items, |item| fleet.assess(item), |_, row| rows.push(row));
        outputs::fleet::table(&fleet, &rows).map_err(wheelrail_report::Error::from)
    })?
    .map_err(input)?;
    table_dict(py, table)
}

/// `kind` as the library's profile kind.
fn profile_kind(kind: &str) -> PyResult<ProfileKind> {
    [ProfileKind::Wheel, ProfileKind::Rail]
        .into_iter()
        .find(|k| k.to_string() == kind)
        .ok_or_else(|| one_of("kind", kind, ["wheel", "rail"]))
}

/// The conicity method of a name.
fn conicity_method_named(name: &str) -> PyResult<ConicityMethod> {
    ConicityMethod::from_name(name).ok_or_else(|| {
        one_of(
            "method",
            name,
            ConicityMethod::ALL.map(ConicityMethod::name),
        )
    })
}

/// Amplitudes of the equivalent conicity, checked as the command line's `--amplitudes-mm`
/// are: finite and positive (the library computes any such amplitude, NaN where Δr does
/// not support it).
fn amplitudes(a: &PyArrayLike1<'_, f64, AllowTypeChange>) -> PyResult<Vec<f64>> {
    let a = to_vec(a);
    match a.iter().position(|v| !(v.is_finite() && *v > 0.0)) {
        Some(i) => Err(input(format!(
            "amplitudes_mm: {} at index {i}: expected finite amplitudes > 0 mm",
            number(a[i])
        ))),
        None => Ok(a),
    }
}

/// The library's checked sweep of `shifts` (at least one, finite, strictly increasing),
/// its error told by the index in the argument.
fn sweep(shifts: &PyArrayLike1<'_, f64, AllowTypeChange>) -> PyResult<Sweep> {
    let shifts = to_vec(shifts);
    Sweep::from_slice(&shifts).map_err(|e| match e {
        SweepError::Empty => input("shifts_mm: no shifts; expected at least one (mm)"),
        SweepError::NotIncreasing {
            index,
            shift_mm,
            previous_mm,
        } => input(format!(
            "shifts_mm: {} at index {index} does not increase (index {}: {})",
            number(shift_mm),
            index - 1,
            number(previous_mm)
        )),
        // The first shift that is not finite (`Sweep::from_slice` checks them in order).
        SweepError::NonFinite { value } => {
            let i = shifts.iter().position(|v| !v.is_finite()).unwrap_or(0);
            input(format!(
                "shifts_mm: {} at index {i} is not finite",
                number(value)
            ))
        }
        other => input(format!("shifts_mm: {other}")),
    })
}

/// Railway wheel/rail contact geometry and Hertzian contact (the Rust library wheelrail),
/// with NumPy arrays in and out.
#[pymodule]
fn _wheelrail(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("InputError", m.py().get_type::<InputError>())?;
    m.add_class::<Run>()?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(read_profile, m)?)?;
    m.add_function(wrap_pyfunction!(rigid_sweep, m)?)?;
    m.add_function(wrap_pyfunction!(equivalent_conicity, m)?)?;
    m.add_function(wrap_pyfunction!(patch::hertz_ellipse, m)?)?;
    m.add_function(wrap_pyfunction!(patch::creep_forces, m)?)?;
    m.add_function(wrap_pyfunction!(fleet, m)?)?;
    Ok(())
}
