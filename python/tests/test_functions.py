"""The package's functions against the command line on the same input (`wheelrail hertz`,
`wheelrail conicity`, the committed reports of `wheelrail report`), to the last printed
digit, and their errors."""

import numpy as np
import pytest

import wheelrail
from conftest import assert_table_is_csv, csv_column, read_csv

# --- hertz_ellipse ---------------------------------------------------------------------

HERTZ_CASES = [
    # A, B (1/mm), load (N), young (GPa), poisson, method
    (0.001, 0.002, 1e5, 210.0, 0.3, "exact"),
    (1 / 920, 1 / 600, 70000.0, 210.0, 0.3, "exact"),
    (0.05, 0.05, 100.0, 210.0, 0.3, "exact"),
    (0.001, 0.002, 1e5, 200.0, 0.25, "paper"),
    (0.004, 0.0002, 5e4, 210.0, 0.3, "paper"),
    (0.001, -0.003, 5e4, 210.0, 0.3, "exact"),  # A + B < 0: not Hertzian, a NaN row
]


@pytest.mark.parametrize("case", HERTZ_CASES)
def test_hertz_ellipse_is_the_command_lines_row(case, cli):
    a, b, load, young, poisson, method = case
    done = cli(
        "hertz", "--A", repr(a), "--B", repr(b), "--load", repr(load),
        "--young-gpa", repr(young), "--poisson", repr(poisson), "--method", method,
    )
    header, [row] = read_csv(done.stdout)
    got = wheelrail.hertz_ellipse(a, b, load, young_GPa=young, poisson=poisson, method=method)
    assert list(got) == header
    for name, cell in zip(header, row):
        if name in ("method", "stop"):
            assert got[name] == cell
        elif cell == "NaN":
            assert np.isnan(got[name])
        else:
            # The command line prints the shortest text that reads back as the same f64.
            assert got[name] == float(cell), name


def test_hertz_ellipse_takes_arrays_case_by_case():
    a = np.array([0.001, 1 / 920, 0.001])
    load = [1e5, 7e4, 5e4]
    got = wheelrail.hertz_ellipse(a, 0.002, load, method="paper")
    assert got["stop"].dtype.kind == "U" and got["a_mm"].dtype == np.float64
    for i in range(3):
        one = wheelrail.hertz_ellipse(a[i], 0.002, load[i], method="paper")
        for name, value in one.items():
            assert got[name] if name == "method" else got[name][i] == value


@pytest.mark.parametrize(
    "flag, argument, value",
    [
        ("--load", "load_N", "-1"),
        ("--load", "load_N", "0.07"),  # kN for N: the likely unit mistake is named
        ("--young-gpa", "young_GPa", "210000"),
        ("--poisson", "poisson", "0.5"),
        ("--A", "A_per_mm", "1.5"),
        ("--B", "B_per_mm", "nan"),
    ],
)
def test_hertz_ellipse_errors_are_the_command_lines(flag, argument, value, cli):
    # The same verdict in the same words, each after its own name of the argument.
    args = {"--A": "0.001", "--B": "0.002", "--load": "1e5", "--young-gpa": "210", "--poisson": "0.3"}
    args[flag] = value
    done = cli("hertz", *[x for pair in args.items() for x in pair], check=False)
    assert done.returncode == 2
    kwargs = {"A_per_mm": 0.001, "B_per_mm": 0.002, "load_N": 1e5, "young_GPa": 210.0, "poisson": 0.3}
    kwargs[argument] = float(value)
    with pytest.raises(wheelrail.InputError) as raised:
        wheelrail.hertz_ellipse(**kwargs)
    message = str(raised.value)
    assert message.startswith(f"{argument}: ")
    assert done.stderr == f"error: {flag}: {message.removeprefix(argument + ': ')}\n"


def test_hertz_ellipse_errors_name_the_case_and_argument():
    with pytest.raises(wheelrail.InputError, match="case 1: load_N: -1 N is not a wheel load"):
        wheelrail.hertz_ellipse(1.0, 1.0, [1.0, -1.0])
    with pytest.raises(wheelrail.InputError, match="B_per_mm: 3 values where A_per_mm has 2"):
        wheelrail.hertz_ellipse([1.0, 1.0], [1.0, 1.0, 1.0], 1.0)
    with pytest.raises(wheelrail.InputError, match='method: unknown "agm"'):
        wheelrail.hertz_ellipse(1.0, 1.0, 1.0, method="agm")


# --- creep_forces ------------------------------------------------------------------------

CREEP_CASES = [
    # CONTACT's FASTSIM example (a = 8, b = 4 mm, 82 kN), each model and bound.
    dict(a_mm=8.0, b_mm=4.0, normal_force_N=82000.0, xi=0.0, eta=-6.25e-4, phi_per_mm=6.25e-4),
    dict(a_mm=8.0, b_mm=4.0, normal_force_N=82000.0, xi=0.0, eta=-6.25e-4, phi_per_mm=6.25e-4,
         bound="elliptic"),
    dict(a_mm=8.0, b_mm=4.0, normal_force_N=82000.0, xi=0.0, eta=-6.25e-4, phi_per_mm=6.25e-4,
         method="polach"),
    dict(a_mm=6.0, b_mm=4.0, normal_force_N=5e4, xi=-1e-3, eta=2e-3, phi_per_mm=-1e-4,
         mu=0.4, shear_modulus_GPa=80.0, poisson=0.3, method="linear"),
]

FLAGS = {
    "a_mm": "--a-mm", "b_mm": "--b-mm", "normal_force_N": "--normal-force-n", "xi": "--xi",
    "eta": "--eta", "phi_per_mm": "--phi-per-mm", "mu": "--mu",
    "shear_modulus_GPa": "--shear-modulus-gpa", "poisson": "--poisson", "method": "--method",
    "bound": "--bound",
}


def creep_command(kwargs):
    return ["creep", *[x for k, v in kwargs.items() for x in (FLAGS[k], repr(v) if isinstance(v, float) else v)]]


@pytest.mark.parametrize("case", CREEP_CASES)
def test_creep_forces_is_the_command_lines_row(case, cli):
    header, [row] = read_csv(cli(*creep_command(case)).stdout)
    got = wheelrail.creep_forces(**case)
    assert list(got) == header
    for name, cell in zip(header, row):
        if name == "method":
            assert got[name] == cell
        elif cell == "NaN":
            assert np.isnan(got[name]), name
        else:
            assert got[name] == float(cell), name


@pytest.mark.parametrize(
    "argument, value",
    [("a_mm", 0.008), ("normal_force_N", 82.0e6), ("xi", 2.0), ("mu", float("nan")), ("poisson", 0.6)],
)
def test_creep_forces_errors_are_the_command_lines(argument, value, cli):
    case = dict(CREEP_CASES[0])
    case[argument] = value
    done = cli(*creep_command(case), check=False)
    assert done.returncode == 2
    with pytest.raises(wheelrail.InputError) as raised:
        wheelrail.creep_forces(**case)
    message = str(raised.value)
    assert message.startswith(f"{argument} ")
    assert done.stderr == f"error: {FLAGS[argument]} {message.removeprefix(argument + ' ')}\n"


def test_creep_forces_names_an_unknown_model():
    with pytest.raises(wheelrail.InputError, match='method: unknown "contact"'):
        wheelrail.creep_forces(8.0, 4.0, 82000.0, 0.0, 0.0, 0.0, method="contact")
    with pytest.raises(wheelrail.InputError, match='bound: unknown "square"'):
        wheelrail.creep_forces(8.0, 4.0, 82000.0, 0.0, 0.0, 0.0, bound="square")


# --- equivalent_conicity -----------------------------------------------------------------

@pytest.mark.parametrize(
    "args",
    [
        [],
        ["--method", "regression"],
        ["--amplitudes-mm", "0.5:20:0.25"],  # beyond 15 mm: NaN rows with their status
        ["--method", "regression", "--amplitudes-mm", "1:6:1"],
    ],
)
def test_equivalent_conicity_is_the_command_lines_table(args, cli, root):
    source = root / "reports/paper/rigid.csv"
    expected = cli("conicity", source, *args).stdout
    method = args[args.index("--method") + 1] if "--method" in args else "klingel"
    amplitudes = None
    if "--amplitudes-mm" in args:
        # The amplitudes the command line made of FROM:TO:STEP, as it printed them.
        header, rows = read_csv(expected)
        amplitudes = [float(r[0]) for r in rows]
    got = wheelrail.equivalent_conicity(
        csv_column(source, "y_ws_mm"),
        csv_column(source, "delta_r_mm"),
        amplitudes_mm=amplitudes,
        method=method,
    )
    assert_table_is_csv(got, expected)


def test_equivalent_conicity_refuses_what_the_library_refuses():
    with pytest.raises(wheelrail.InputError, match="y_mm, delta_r_mm: y does not increase at point 2"):
        wheelrail.equivalent_conicity([-1.0, 0.0, 0.0, 1.0], [-0.1, 0.0, 0.0, 0.1])
    with pytest.raises(wheelrail.InputError, match="2 points; at least 3"):
        wheelrail.equivalent_conicity([-1.0, 1.0], [-0.1, 0.1])
    with pytest.raises(wheelrail.InputError, match="never changes sign"):
        wheelrail.equivalent_conicity([-1.0, 0.0, 1.0], [0.1, 0.2, 0.3])
    with pytest.raises(wheelrail.InputError, match="amplitudes_mm: -1 at index 1"):
        wheelrail.equivalent_conicity([-1.0, 0.0, 1.0], [-0.1, 0.0, 0.1], amplitudes_mm=[1, -1])


# --- read_profile ------------------------------------------------------------------------

def test_read_profile_gives_the_files_points(root):
    # The project's S1002 CSV: its first two columns are the points, in the side frame.
    path = root / "profiles/s1002.csv"
    p = wheelrail.read_profile(path, "wheel")
    assert p["kind"] == "wheel" and p["format"] == "csv" and p["path"] == str(path)
    assert len(p["sha256"]) == 64 and p["dropped_step_backs"] == []
    assert np.array_equal(p["s_mm"], csv_column(path, "s_mm"))
    assert np.array_equal(p["F_mm"], csv_column(path, "F_mm"))


def test_read_profile_maps_simpack_to_the_side_frame(root):
    # EN 13715 S1002: the flange tip 28 mm above the taping line, at s = -55 mm.
    p = wheelrail.read_profile(root / "tests/data/profiles/MBench_S1002_v3.prw", "wheel")
    tip = int(np.argmax(p["F_mm"]))
    assert abs(p["F_mm"][tip] - 28.0) < 1e-3 and abs(p["s_mm"][tip] + 55.0) < 0.2
    rail = wheelrail.read_profile(root / "tests/data/profiles/MBench_UIC60_v3.prr", kind="rail")
    assert set(rail) >= {"y_mm", "z_mm"} and np.all(np.diff(rail["y_mm"]) > 0)


def test_read_profile_drops_step_backs_when_asked(root):
    path = root / "tests/data/profiles/Car7216_0001r.whl"
    with pytest.raises(wheelrail.InputError, match=":223"):
        wheelrail.read_profile(path)
    assert 223 in wheelrail.read_profile(path, drop_step_backs=True)["dropped_step_backs"]


def test_a_bad_profile_raises_the_readers_message(root, tmp_path, cli):
    bad = root / "tests/data/profiles/bad/metres_header.csv"
    with pytest.raises(wheelrail.InputError) as raised:
        wheelrail.read_profile(bad, "rail")
    assert str(bad) in str(raised.value)
    # The command line says the same behind the scene key that names the file.
    scene = tmp_path / "scene.toml"
    scene.write_text(f'[rail]\nprofile = "{bad}"\n')
    done = cli("report", scene, "--out", tmp_path / "out", check=False)
    assert done.stderr.endswith(f": {raised.value}\n"), done.stderr
    with pytest.raises(wheelrail.InputError, match='kind: unknown "axle"'):
        wheelrail.read_profile(bad, "axle")


# --- rigid_sweep -------------------------------------------------------------------------

RIGID_TABLES = ["rigid", "rigid_jumps", "equivalent_conicity", "parameters"]


def test_rigid_sweep_of_built_in_profiles_is_the_papers_report(root):
    folder = root / "reports/paper"
    shifts = csv_column(folder / "rigid.csv", "y_ws_mm")
    got = wheelrail.rigid_sweep("S1002", "UIC60E1", shifts)
    assert list(got) == RIGID_TABLES
    for name in RIGID_TABLES:
        assert_table_is_csv(got[name], (folder / f"{name}.csv").read_text(), name)


def test_rigid_sweep_of_read_profiles_is_the_en15302_report(root):
    # reports/en15302_e1/scene.toml: R-UIC519A on S-UIC519A, both inclined 1:20 in the
    # files, gauge 1435 mm, the gauge point 14.4918 mm down, no roll (EN 15302 Annex E).
    folder = root / "reports/en15302_e1"
    data = root / "tests/data/en15302"
    got = wheelrail.rigid_sweep(
        wheelrail.read_profile(data / "R-UIC519A.csv", "wheel"),
        wheelrail.read_profile(data / "S-UIC519A.csv", "rail"),
        csv_column(folder / "rigid.csv", "y_ws_mm"),
        inclination="1:20",
        rail_profile_inclination="1:20",
        gauge_mm=1435.0,
        gauge_point_depth_mm=14.4918,
        solver="no_roll",
    )
    for name in RIGID_TABLES:
        assert_table_is_csv(got[name], (folder / f"{name}.csv").read_text(), name)


def test_rigid_sweep_takes_points_as_an_array(root):
    wheel = wheelrail.read_profile(root / "profiles/s1002.csv", "wheel")
    points = np.column_stack([wheel["s_mm"], wheel["F_mm"]])
    shifts = np.linspace(-3, 3, 13)
    by_dict = wheelrail.rigid_sweep(wheel, "UIC60E1", shifts)
    by_array = wheelrail.rigid_sweep(points, "UIC60E1", shifts)
    for name in by_dict["rigid"]:
        np.testing.assert_array_equal(by_dict["rigid"][name], by_array["rigid"][name])


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(shifts_mm=[0.0, 0.0]), "shifts_mm: 0 at index 1 does not increase"),
        (dict(shifts_mm=[0.0, float("nan")]), "shifts_mm: NaN at index 1 is not finite"),
        (dict(shifts_mm=[]), "shifts_mm: no shifts"),
        (dict(gauge_mm=14350.0), "gauge_mm: 14350 mm is not a railway gauge"),
        (dict(flange_back_mm=1500.0), "flange_back_mm: 1500 mm does not fit"),
        (dict(inclination="1:4"), "inclination: inclination 0.2449"),
        (dict(wheel="UIC60E1"), "wheel: UIC60E1 is a rail profile"),
        (dict(rail="S1003"), 'rail: unknown "S1003"'),
        (dict(wheel=np.zeros((10, 3))), "wheel: an array of 3 columns"),
        (dict(wheel=[[0.0, 0.0], [1.0, 0.0]]), "wheel"),
        (dict(solver="newton"), 'solver: unknown "newton"'),
        (dict(amplitudes_mm=[0.0]), "amplitudes_mm: 0 at index 0"),
    ],
)
def test_rigid_sweep_names_the_bad_argument(kwargs, message):
    args = dict(wheel="S1002", rail="UIC60E1", shifts_mm=[0.0, 1.0])
    args.update(kwargs)
    with pytest.raises(wheelrail.InputError, match=message.replace("(", r"\(")):
        wheelrail.rigid_sweep(**args)
