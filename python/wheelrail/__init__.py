"""Railway wheel/rail contact geometry and Hertzian contact, with NumPy arrays in and out.

The Rust library wheelrail as a Python package: profiles, placement on the track, rigid
and quasi-elastic contact search, Hertz ellipses, creep forces, the equivalent conicity of EN
15302 and fleets of measured profiles, each one call away. Tables are ``dict[str, numpy.ndarray]``
in column order, with the same column names (units in the names) and values as the CSV
files of ``wheelrail report``; ``pandas.DataFrame(table)`` takes one as it is.

Units: millimetres, newtons, megapascals and radians. Frames and signs: the track frame
has x forward, y lateral positive to the left, z up; each wheel and rail is described in
its own side frame whose lateral coordinate grows towards the field side (see the crate
documentation of wheelrail, "Frames and signs").

Long calls release the interpreter lock, so a thread pool of your own runs them side by
side. Bad input raises :class:`InputError` (a ``ValueError``) with the command line's
message, which names the file and the key or line.
"""

from ._wheelrail import (
    InputError,
    Run,
    __version__,
    creep_forces,
    equivalent_conicity,
    fleet,
    hertz_ellipse,
    read_profile,
    rigid_sweep,
    run,
)

__all__ = [
    "InputError",
    "Run",
    "__version__",
    "creep_forces",
    "equivalent_conicity",
    "fleet",
    "hertz_ellipse",
    "read_profile",
    "rigid_sweep",
    "run",
]
