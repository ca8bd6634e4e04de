# Type stubs of the extension module wheelrail._wheelrail (python/src/lib.rs). The full
# documentation of each function is its docstring (help(wheelrail.run)); tests/test_stubs.py
# checks that these signatures are the module's.

import os
from typing import Any, Dict, Literal, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

Table = Dict[str, np.ndarray]
"""A table: column name (unit in the name) -> float64 or str array, in column order."""

Path = Union[str, "os.PathLike[str]"]
Floats = npt.ArrayLike
ProfileInput = Union[str, Dict[str, Any], npt.ArrayLike]

class InputError(ValueError):
    """Input wheelrail cannot use; the message names the file and the key or line."""

class Run:
    """The result of run(): the tables of every stage that ran and the checked scene."""

    @property
    def tables(self) -> Dict[str, Table]:
        """Each table by its CSV file's name without .csv ("rigid", "hertz", ...)."""
    @property
    def scene(self) -> Dict[str, Any]:
        """The checked scene: every key after defaults and unit conversions."""
    @property
    def timings(self) -> Dict[str, float]:
        """The stages that ran, in order, with their wall-clock time (s)."""

def run(scene_path: Path, stages: Optional[Sequence[str]] = None) -> Run:
    """Runs a scene file as `wheelrail report` does and returns its tables."""

def read_profile(
    path: Path, kind: Literal["wheel", "rail"] = "wheel", drop_step_backs: bool = False
) -> Dict[str, Any]:
    """Reads a wheel (s_mm, F_mm) or rail (y_mm, z_mm) profile file into arrays."""

def rigid_sweep(
    wheel: ProfileInput,
    rail: ProfileInput,
    shifts_mm: Floats,
    *,
    inclination: str = "1:40",
    gauge_mm: float = 1435.0,
    gauge_point_depth_mm: float = 14.0,
    flange_back_mm: float = 1360.0,
    nominal_radius_mm: float = 460.0,
    rail_profile_inclination: str = "vertical",
    smoothing_wavelength_mm: float = 0.0,
    solver: Literal["default", "paper", "no_roll"] = "default",
    conicity_method: Literal["klingel", "regression"] = "klingel",
    amplitudes_mm: Optional[Floats] = None,
) -> Dict[str, Table]:
    """Rigid contact of a symmetric wheelset over lateral shifts, with the equivalent
    conicity: the tables "rigid", "rigid_jumps", "equivalent_conicity", "parameters"."""

def equivalent_conicity(
    y_mm: Floats,
    delta_r_mm: Floats,
    amplitudes_mm: Optional[Floats] = None,
    method: Literal["klingel", "regression"] = "klingel",
) -> Table:
    """EN 15302 equivalent conicity of a Δr function: amplitude_mm, tan_gamma_e,
    centre_mm, status (as `wheelrail conicity` prints them)."""

@overload
def hertz_ellipse(
    A_per_mm: float,
    B_per_mm: float,
    load_N: float,
    young_GPa: float = 210.0,
    poisson: float = 0.3,
    method: Literal["exact", "paper"] = "exact",
) -> Dict[str, Union[float, str]]: ...
@overload
def hertz_ellipse(
    A_per_mm: Floats,
    B_per_mm: Floats,
    load_N: Floats,
    young_GPa: float = 210.0,
    poisson: float = 0.3,
    method: Literal["exact", "paper"] = "exact",
) -> Dict[str, Union[np.ndarray, str]]: ...
def creep_forces(
    a_mm: float,
    b_mm: float,
    normal_force_N: float,
    xi: float,
    eta: float,
    phi_per_mm: float,
    mu: float = 0.3,
    shear_modulus_GPa: float = 82.0,
    poisson: float = 0.28,
    method: Literal["fastsim", "linear", "polach"] = "fastsim",
    bound: Literal["parabolic", "elliptic"] = "parabolic",
) -> Dict[str, Union[float, str]]:
    """The tangential problem of one elliptic patch, as `wheelrail creep` solves it: method,
    c11, c22, c23, fx_N, fy_N, mz_Nmm, adhesion_fraction."""

def fleet(
    scene_path: Path,
    profiles: Optional[Sequence[Path]] = None,
    pairs: Optional[Path] = None,
    rails: bool = False,
) -> Table:
    """Assesses profiles through a template scene: the rows of `wheelrail fleet`'s fleet.csv."""
