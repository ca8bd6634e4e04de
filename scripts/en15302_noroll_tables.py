#!/usr/bin/env python3
"""Writes tests/data/en15302/noroll/E{1..9}_delta_r.csv: the rolling radius difference of the
nine EN 15302 reference cases by the independent no-roll model of scripts/en15302_noroll.py,
as crates/cli/tests/en15302.rs compares wheelrail's with it.

Usage (from the project's root; Python 3 standard library; a few minutes):
    python3 scripts/en15302_noroll_tables.py

Each case as tests/data/en15302/cases_e1_e9.csv sets it (wheels per side, radii, rail), at
the committed scenes' gauge of 1435 mm at the rail file's gauge point (the files' own frame:
--rail-offset-mm 0), shifts from -11 to 11 mm (the motions up to 7.5 mm
of the off-centre cases reach beyond -10 mm) in steps of 0.1 mm, of 0.01 mm for the
cylindrical band of R-UIC519I (E4, E8), whose edge is a jump the Klingel integral of a
table locates only to its step.
"""
import csv
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "tests", "data", "en15302")
OUT = os.path.join(DATA, "noroll")


def main():
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(DATA, "cases_e1_e9.csv"), newline="") as f:
        rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
    jobs = []
    with tempfile.TemporaryDirectory() as tmp:
        for r in rows:
            case = r["case"]
            radii = [float(r["left_wheel_diameter_mm"]) / 2, float(r["right_wheel_diameter_mm"]) / 2]
            step = "0.01" if r["left_wheel"] == "R-UIC519I" else "0.1"
            args = [
                sys.executable, os.path.join(ROOT, "scripts", "en15302_noroll.py"),
                os.path.join(DATA, r["left_wheel"] + ".csv"),
                os.path.join(DATA, r["right_wheel"] + ".csv"),
                os.path.join(DATA, r["rail"] + ".csv"),
                os.path.join(tmp, case),
                "--rail-offset-mm", "0", "--from-mm", "-11", "--to-mm", "11",
                "--step-mm", step, "--radii-mm", str(radii[0]), str(radii[1]),
            ]
            jobs.append((case, r, step, subprocess.Popen(args)))
        for case, r, step, p in jobs:
            if p.wait() != 0:
                sys.exit(f"{case}: the no-roll model failed")
            with open(os.path.join(tmp, case, "rigid.csv")) as f:
                lines = [l for l in f if not l.startswith("#")]
            head = lines[0].strip().split(",")
            iy, idr = head.index("y_ws_mm"), head.index("delta_r_mm")
            with open(os.path.join(OUT, f"{case}_delta_r.csv"), "w") as f:
                f.write(f"# EN 15302 case {case}: left {r['left_wheel']} ({r['left_wheel_diameter_mm']} mm), "
                        f"right {r['right_wheel']} ({r['right_wheel_diameter_mm']} mm), rail {r['rail']}, gauge 1435 mm\n")
                f.write("# independent no-roll model (scripts/en15302_noroll.py, written by "
                        "scripts/en15302_noroll_tables.py), not wheelrail's rigid search\n")
                f.write(f"# y lateral shift of the wheelset, positive to the left; delta_r = r_left - r_right; step {step} mm\n")
                f.write("y_mm,delta_r_mm\n")
                for l in lines[1:]:
                    c = l.strip().split(",")
                    f.write(f"{c[iy]},{c[idr]}\n")


if __name__ == "__main__":
    main()
