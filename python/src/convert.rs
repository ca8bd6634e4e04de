//! Conversions between Python and the library: errors, the interpreter released around a
//! call, tables and the scene as dicts, arrays and profiles in.

use numpy::{AllowTypeChange, PyArray1, PyArrayLike1, PyArrayLike2};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::fmt::Display;
use wheelrail::plausible::Range;
use wheelrail::profile::read::PointProfile;
use wheelrail::profile::{Profile, ProfileKind};
use wheelrail::scene::{ImageFormat, ProfileRef, Scene};
use wheelrail_report::{Column, ColumnData, Table};

pyo3::create_exception!(
    wheelrail,
    InputError,
    PyValueError,
    "Input that wheelrail cannot use: a bad scene, profile file, argument or name. The message is the command line's: it names the file and the key or line, or the argument."
);

/// An `InputError` with `message`.
pub fn input(message: impl Display) -> PyErr {
    InputError::new_err(message.to_string())
}

/// An `InputError` for a `name` that is none of `expected`, naming the argument `what`.
pub fn one_of<'a>(what: &str, name: &str, expected: impl IntoIterator<Item = &'a str>) -> PyErr {
    let expected: Vec<String> = expected.into_iter().map(|e| format!("{e:?}")).collect();
    input(format!(
        "{what}: unknown {name:?}; expected {}",
        expected.join(", ")
    ))
}

/// `values` of the argument `name` checked against `range` (the library's ranges of
/// physical inputs, which the command line checks its flags against): the first outside it
/// is an `InputError` with the range's message after the name, and `case i:` before it
/// when the argument is one value per case (`scalar` false).
pub fn plausible(name: &str, range: &'static Range, values: &[f64], scalar: bool) -> PyResult<()> {
    for (i, &v) in values.iter().enumerate() {
        if let Err(problem) = range.check(v) {
            return Err(input(if scalar {
                format!("{name}: {problem}")
            } else {
                format!("case {i}: {name}: {problem}")
            }));
        }
    }
    Ok(())
}

/// A number in a message as the library's messages write it (`70`, `0.5`, `NaN`).
pub fn number(x: f64) -> String {
    format!("{x}")
}

/// Runs `f` with the interpreter released, so that other Python threads run meanwhile; a
/// panic in the library (a bug) comes back as a `RuntimeError` saying so.
pub fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> T + Send) -> PyResult<T> {
    py.detach(|| std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)))
        .map_err(|panic| {
            let text = panic
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            PyRuntimeError::new_err(format!(
                "internal error in wheelrail (please report it): {text}"
            ))
        })
}

/// A table as `dict[str, numpy.ndarray]` in column order: numbers as `float64` arrays that
/// take over the table's vectors (no copy), text as `str` arrays.
pub fn table_dict<'py>(py: Python<'py>, table: Table) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for Column { name, data } in table.into_columns() {
        match data {
            ColumnData::Numeric(values) => d.set_item(name, PyArray1::from_vec(py, values))?,
            ColumnData::Text(values) => d.set_item(name, text_array(py, &values)?)?,
        }
    }
    Ok(d)
}

/// Strings as a NumPy `str` array (dtype `U<width>`, the longest string's length): their
/// UCS-4 code points written into one vector handed to NumPy and viewed as strings, so no
/// Python string is made per cell (`numpy.array(list, dtype=str)` would make one for each
/// text cell of every table, the largest part of a call's conversion).
pub fn text_array<'py, S: AsRef<str>>(
    py: Python<'py>,
    values: &[S],
) -> PyResult<Bound<'py, PyAny>> {
    let width = values
        .iter()
        .map(|s| s.as_ref().chars().count())
        .max()
        .unwrap_or(0)
        .max(1);
    let mut code_points = vec![0u32; values.len() * width];
    for (cells, s) in code_points.chunks_mut(width).zip(values) {
        for (cell, c) in cells.iter_mut().zip(s.as_ref().chars()) {
            *cell = u32::from(c);
        }
    }
    // Native byte order, as the u32 vector has it; NumPy drops the zeros that pad a string.
    let dtype = py
        .import("numpy")?
        .getattr("dtype")?
        .call1((format!("U{width}"),))?;
    PyArray1::from_vec(py, code_points).call_method1("view", (dtype,))
}

/// The values of a 1-D array-like argument, copied into a vector the library owns (it
/// computes with the interpreter released, when Python threads could write the array).
pub fn to_vec(a: &PyArrayLike1<'_, f64, AllowTypeChange>) -> Vec<f64> {
    a.as_array().iter().copied().collect()
}

/// The names of a profile's point columns, as the library's CSV profile files have them.
pub fn point_columns(kind: ProfileKind) -> [&'static str; 2] {
    match kind {
        ProfileKind::Wheel => ["s_mm", "F_mm"],
        ProfileKind::Rail => ["y_mm", "z_mm"],
    }
}

/// The checked scene as a dict, every key after defaults and unit conversions.
pub fn scene_dict<'py>(py: Python<'py>, scene: &Scene) -> PyResult<Bound<'py, PyDict>> {
    let profile = |r: &ProfileRef| match r {
        ProfileRef::BuiltIn(name) => name.clone(),
        ProfileRef::File(path) => path.display().to_string(),
    };
    let material = |m: &wheelrail::hertz::Material| -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("young_MPa", m.young_mpa())?;
        d.set_item("poisson", m.poisson())?;
        Ok(d)
    };
    let layout = scene.layout();
    let d = PyDict::new(py);
    d.set_item("path", scene.path())?;
    d.set_item("name", scene.name())?;
    d.set_item("title", scene.title())?;
    d.set_item(
        "wheel_profiles",
        scene.wheel_profiles().each_ref().map(profile),
    )?;
    d.set_item("nominal_radius_mm", scene.nominal_radius_mm())?;
    d.set_item(
        "rail_profiles",
        scene.rail_profiles().each_ref().map(profile),
    )?;
    d.set_item(
        "rail_profile_inclination_rad",
        scene.rail_profile_inclination().radians(),
    )?;
    d.set_item("smoothing_wavelength_mm", scene.smoothing_wavelength_mm())?;
    d.set_item("gauge_mm", layout.gauge_mm())?;
    d.set_item("gauge_point_depth_mm", layout.gauge_point_depth_mm())?;
    d.set_item("inclination_rad", layout.inclination().radians())?;
    d.set_item("flange_back_mm", layout.flange_back_mm())?;
    d.set_item("taping_line_mm", layout.taping_line_mm())?;
    d.set_item("wheel_load_N", scene.wheel_load_n())?;
    d.set_item("wheel_material", material(scene.wheel_material())?)?;
    d.set_item("rail_material", material(scene.rail_material())?)?;
    d.set_item(
        "sweep_mm",
        PyArray1::from_slice(py, scene.sweep().shifts_mm()),
    )?;
    d.set_item("rigid_solver", scene.rigid_solver().name())?;
    let qe = scene.quasi_elastic();
    let quasi_elastic = PyDict::new(py);
    quasi_elastic.set_item("epsilon_mm", qe.epsilon_mm())?;
    quasi_elastic.set_item("cutoff", qe.cutoff())?;
    quasi_elastic.set_item("quadrature", qe.quadrature().name())?;
    d.set_item("quasi_elastic", quasi_elastic)?;
    d.set_item("epsilon_sensitivity_mm", scene.epsilon_sensitivity_mm())?;
    let h = scene.hertz();
    let hertz = PyDict::new(py);
    hertz.set_item("method", h.method().to_string())?;
    hertz.set_item("contact", scene.hertz_contact().name())?;
    hertz.set_item("normal_load", h.normal_load().name())?;
    d.set_item("hertz", hertz)?;
    let c = scene.conicity();
    let conicity = PyDict::new(py);
    conicity.set_item("method", c.method().name())?;
    conicity.set_item("amplitudes_mm", c.amplitudes_mm())?;
    d.set_item("conicity", conicity)?;
    d.set_item("conicity_limit", scene.fleet().conicity_limit())?;
    let figures: Vec<&str> = scene.figures().iter().map(|f| f.name()).collect();
    d.set_item("figures", figures)?;
    let formats: Vec<&str> = scene
        .formats()
        .iter()
        .map(|f| match f {
            ImageFormat::Svg => "svg",
            ImageFormat::Png => "png",
        })
        .collect();
    d.set_item("formats", formats)?;
    Ok(d)
}

/// A profile argument: a built-in name, a dict from `read_profile`, or an (N, 2) array of
/// points in the side frame.
pub enum ProfileArg<'py> {
    /// A built-in profile's name.
    Name(String),
    /// A dict from `read_profile`.
    Read(Bound<'py, PyDict>),
    /// Points `[lateral, vertical]` (mm).
    Points(PyArrayLike2<'py, f64, AllowTypeChange>),
}

impl<'a, 'py> FromPyObject<'a, 'py> for ProfileArg<'py> {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if let Ok(name) = obj.extract::<String>() {
            return Ok(ProfileArg::Name(name));
        }
        if let Ok(d) = obj.cast::<PyDict>() {
            return Ok(ProfileArg::Read(d.to_owned()));
        }
        obj.extract().map(ProfileArg::Points).map_err(|_| {
            input("expected a built-in profile name, a dict from read_profile, or an (N, 2) array of points in mm")
        })
    }
}

/// A profile argument's data, taken from Python: to be made a profile with the interpreter
/// released.
pub enum ProfileData {
    /// A built-in profile.
    BuiltIn(Profile),
    /// Points to check and fit.
    Points {
        /// Wheel or rail.
        kind: ProfileKind,
        /// What messages call them (the file of a dict, else the argument).
        name: String,
        /// `[lateral, vertical]` (mm), side frame.
        points: Vec<[f64; 2]>,
    },
}

impl ProfileArg<'_> {
    /// The data of the argument `arg`, which must be a profile of `kind`.
    pub fn points(&self, kind: ProfileKind, arg: &str) -> PyResult<ProfileData> {
        match self {
            ProfileArg::Name(name) => match Profile::built_in(name) {
                Some(p) if p.kind() == kind => Ok(ProfileData::BuiltIn(p)),
                Some(p) => Err(input(format!("{arg}: {name} is a {} profile", p.kind()))),
                None => Err(one_of(arg, name, Profile::BUILT_IN)),
            },
            ProfileArg::Read(d) => {
                if let Some(k) = d.get_item("kind")? {
                    let k: String = k.extract()?;
                    if k != kind.to_string() {
                        return Err(input(format!("{arg}: the dict holds a {k} profile")));
                    }
                }
                let [u, v] = point_columns(kind);
                let column = |c: &str| -> PyResult<Vec<f64>> {
                    let values = d
                        .get_item(c)?
                        .ok_or_else(|| input(format!("{arg}: the dict has no key {c:?}")))?;
                    let values: PyArrayLike1<'_, f64, AllowTypeChange> = values.extract()?;
                    Ok(to_vec(&values))
                };
                let (u, v) = (column(u)?, column(v)?);
                if u.len() != v.len() {
                    return Err(input(format!("{arg}: its two columns differ in length")));
                }
                let name = match d.get_item("path")? {
                    Some(p) => p.extract::<String>()?,
                    None => arg.to_string(),
                };
                Ok(ProfileData::Points {
                    kind,
                    name,
                    points: u.into_iter().zip(v).map(|(u, v)| [u, v]).collect(),
                })
            }
            ProfileArg::Points(a) => {
                let a = a.as_array();
                if a.ncols() != 2 {
                    return Err(input(format!(
                        "{arg}: an array of {} columns; expected two, [lateral, vertical] in mm",
                        a.ncols()
                    )));
                }
                Ok(ProfileData::Points {
                    kind,
                    name: arg.to_string(),
                    points: a.rows().into_iter().map(|r| [r[0], r[1]]).collect(),
                })
            }
        }
    }
}

impl ProfileData {
    /// The profile: points checked as a file's are, and fitted by the spline of filter
    /// wavelength `smoothing_wavelength_mm` (0 interpolates them).
    ///
    /// # Errors
    /// The reader's message (naming the point) or the spline's.
    pub fn profile(self, smoothing_wavelength_mm: f64) -> Result<Profile, String> {
        match self {
            ProfileData::BuiltIn(p) => Ok(p),
            ProfileData::Points { kind, name, points } => {
                let points =
                    PointProfile::from_points(kind, &name, points).map_err(|e| e.to_string())?;
                Profile::from_points(points, smoothing_wavelength_mm)
                    .map_err(|e| format!("{name}: {e}"))
            }
        }
    }
}

/// A float or a 1-D array of floats (an argument of `hertz_ellipse`).
pub enum Values<'py> {
    /// One value for every case.
    One(f64),
    /// One value per case.
    Many(PyArrayLike1<'py, f64, AllowTypeChange>),
}

impl<'a, 'py> FromPyObject<'a, 'py> for Values<'py> {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if let Ok(many) = obj.extract() {
            return Ok(Values::Many(many));
        }
        obj.extract()
            .map(Values::One)
            .map_err(|_| input("expected a float or a 1-D array of floats"))
    }
}

impl Values<'_> {
    /// The single case of a float argument (NaN for an array: only called when all are
    /// floats).
    pub fn one(&self) -> Vec<f64> {
        match self {
            Values::One(v) => vec![*v],
            Values::Many(_) => vec![f64::NAN],
        }
    }

    /// The values of `N` named arguments case by case, floats repeated, when one of them is
    /// an array; `None` when all are floats.
    ///
    /// # Errors
    /// Arrays of different lengths.
    pub fn broadcast<const N: usize>(
        args: [(&str, &Values<'_>); N],
    ) -> PyResult<Option<[Vec<f64>; N]>> {
        let lengths: Vec<(&str, usize)> = args
            .iter()
            .filter_map(|(name, v)| match v {
                Values::Many(a) => Some((*name, a.as_array().len())),
                Values::One(_) => None,
            })
            .collect();
        let Some(&(first, n)) = lengths.first() else {
            return Ok(None);
        };
        if let Some((name, m)) = lengths.iter().find(|(_, m)| *m != n) {
            return Err(input(format!(
                "{name}: {m} values where {first} has {n}; arrays must have one length"
            )));
        }
        Ok(Some(args.map(|(_, v)| match v {
            Values::One(x) => vec![*x; n],
            Values::Many(a) => to_vec(a),
        })))
    }
}
