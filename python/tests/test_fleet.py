"""`wheelrail.fleet` against `wheelrail fleet` on the same profiles: the rows of its
fleet.csv, column by column to the last printed digit; a bad file is a row, not an error."""

import pytest

import wheelrail
from conftest import assert_table_is_csv

SCENE = "reports/fleet/scene.toml"
PROFILES = [
    "tests/data/profiles/Car7216_0001r.whl",  # folds back at its flange tip: dropped
    "tests/data/profiles/no_such_wheel.whl",  # a row that says why
    "tests/data/profiles/avg_wheel.whl",
    "tests/data/profiles/MBench_S1002_v3.prw",
]


def test_a_small_fleet_is_the_command_lines_fleet_csv(cli, root, tmp_path, monkeypatch):
    # Paths as given on both sides (relative to the repository), so the file columns agree.
    monkeypatch.chdir(root)
    got = wheelrail.fleet(SCENE, PROFILES)
    done = cli("fleet", SCENE, *PROFILES, "--out", tmp_path / "fleet", check=False)
    assert done.returncode == 3  # one row failed
    assert_table_is_csv(got, (tmp_path / "fleet" / "fleet.csv").read_text())
    assert list(got["status"][[0, 2, 3]]) == ["ok"] * 3
    assert "no_such_wheel.whl" in got["status"][1]
    assert got["id"].tolist() == ["Car7216_0001r", "no_such_wheel", "avg_wheel", "MBench_S1002_v3"]


def test_a_pairs_file_is_the_command_lines_too(cli, root, tmp_path):
    pairs = tmp_path / "pairs.csv"
    data = root / "tests/data/profiles"
    pairs.write_text(
        "id,left_wheel,right_wheel\n"
        f"measured,{data / 'Car7216_0001r.whl'},{data / 'Car7358_0001r.whl'}\n"
        f"benchmark,{data / 'MBench_S1002_v3.prw'},{data / 'avg_wheel.whl'}\n"
    )
    got = wheelrail.fleet(root / SCENE, pairs=pairs)
    cli("fleet", root / SCENE, "--pairs", pairs, "--out", tmp_path / "fleet")
    assert_table_is_csv(got, (tmp_path / "fleet" / "fleet.csv").read_text())
    assert list(got)[:5] == ["id", "left_wheel_file", "left_wheel_sha256", "right_wheel_file", "right_wheel_sha256"]


def test_a_fleet_that_cannot_run_raises_the_command_lines_message(cli, root, tmp_path):
    with pytest.raises(wheelrail.InputError) as raised:
        wheelrail.fleet(root / SCENE, [])
    done = cli("fleet", root / SCENE, "--pairs", tmp_path / "none.csv", "--out", tmp_path / "o", check=False)
    assert str(raised.value) == "no profiles to assess"
    with pytest.raises(wheelrail.InputError) as raised:
        wheelrail.fleet(root / SCENE, pairs=tmp_path / "none.csv")
    assert done.stderr == f"error: {raised.value}\n"
    with pytest.raises(wheelrail.InputError, match="either profiles or pairs"):
        wheelrail.fleet(root / SCENE, ["a.whl"], pairs=tmp_path / "none.csv")
