"""Shared fixtures: the repository's root, the command-line binary the package is compared
with, and the comparison of a table with a CSV file to the last printed digit."""

import csv
import io
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def cli():
    """Runs the `wheelrail` binary (WHEELRAIL_BIN, else target/release/wheelrail, built by
    `cargo build --release` or `cargo test --release`) from the repository root; returns
    the completed process."""
    binary = Path(os.environ.get("WHEELRAIL_BIN", ROOT / "target" / "release" / "wheelrail"))
    if not binary.is_file():
        pytest.fail(
            f"{binary}: no wheelrail binary to compare with; build it with "
            "`cargo build --release` (or set WHEELRAIL_BIN)"
        )

    def run(*args, check=True):
        done = subprocess.run(
            [str(binary), *map(str, args)], cwd=ROOT, capture_output=True, text=True
        )
        if check and done.returncode != 0:
            raise AssertionError(f"wheelrail {' '.join(map(str, args))}: {done.stderr}")
        return done

    return run


def read_csv(text):
    """The header and rows of a CSV text whose `#` lines are comments."""
    lines = [line for line in io.StringIO(text) if not line.startswith("#")]
    rows = list(csv.reader(lines))
    return rows[0], rows[1:]


def printed(value):
    """`value` rounded to the 10 significant digits every CSV prints, as a float."""
    return float(f"{value:.9e}")


def assert_table_is_csv(table, text, where=""):
    """Asserts that `table` (dict of arrays) holds the CSV `text`: the same columns in the
    same order, text cells equal, and each number equal to the CSV's to its last printed
    digit (the value rounded to 10 significant digits reads as the printed one; NaN where
    the CSV says NaN)."""
    header, rows = read_csv(text)
    assert list(table) == header, where
    for j, name in enumerate(header):
        column = table[name]
        assert len(column) == len(rows), f"{where} {name}"
        for i, row in enumerate(rows):
            cell = row[j]
            if column.dtype.kind == "f":
                value = float(column[i])
                if cell == "NaN":
                    assert math.isnan(value), f"{where} {name} row {i}: {value} for NaN"
                else:
                    assert printed(value) == float(cell), f"{where} {name} row {i}: {value} for {cell}"
            else:
                assert column.dtype.kind == "U", f"{where} {name}: dtype {column.dtype}"
                assert str(column[i]) == cell, f"{where} {name} row {i}"


def csv_column(path, name):
    """The numeric column `name` of a CSV file as a float64 array."""
    header, rows = read_csv(Path(path).read_text())
    j = header.index(name)
    return np.array([float(r[j]) for r in rows])
