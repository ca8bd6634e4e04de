"""The example study python/examples/conicity_study.py runs, and its row at the reference
gauge is the committed EN 15302 E1 report's tan γe(3 mm) (the same scene at the standard's 1435 mm)."""

import subprocess
import sys

from conftest import read_csv


def test_the_conicity_study_runs_and_agrees_with_the_report(root, tmp_path):
    done = subprocess.run(
        [sys.executable, str(root / "python/examples/conicity_study.py"), "--out", str(tmp_path)],
        capture_output=True, text=True, check=True,
    )
    header, rows = read_csv("\n".join(line for line in done.stdout.splitlines() if "," in line))
    assert header == ["gauge_mm", "tan_gamma_e_3mm_level", "tan_gamma_e_3mm_roll_solved"]
    gauges = [1432 + 0.5 * i for i in range(17)]
    assert [r[0] for r in rows] == [f"{g:.2f}" for g in gauges]
    standard = dict((r[0], r) for r in rows)["1435.00"]
    report = root / "reports/en15302_e1/parameters.csv"
    _, parameters = read_csv(report.read_text())
    expected = float(dict((p[0], p[1]) for p in parameters)["tan_gamma_e_3mm"])
    assert standard[1] == f"{expected:.4f}"
    # On this pair a wider gauge puts the contact on flatter tread: the conicity falls.
    level = [float(r[1]) for r in rows]
    assert all(a > b for a, b in zip(level, level[1:]))
