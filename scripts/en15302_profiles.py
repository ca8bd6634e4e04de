#!/usr/bin/env python3
"""Convert the EN 15302 reference profiles (Criogenox .dat tables as CSV) to wheelrail's CSV.

Usage: python3 scripts/en15302_profiles.py SOURCE_DIR OUT_DIR

SOURCE_DIR holds RUIC519A.csv, RUIC519B.csv, RUIC519H.csv, RUIC519I.csv and SUIC519A.csv with
the header `y_mm,z_mm` (see tests/data/en15302/NOTICE.md). Writes R-UIC519A.csv ... and
S-UIC519A.csv into OUT_DIR.

* Wheels: the source's y is already measured from the taping line, positive towards the field
  side, with the flange back at y = -70 (wheelrail's wheel side frame `s`); its z is minus the
  radius increase (flange tip at z = -28). So s_mm = y_mm and F_mm = -z_mm, written with the
  source's digits (only the sign character changes).
* Rail: the source's (y, z) already is wheelrail's rail side frame (y towards the field side,
  z up; placement finds the top and the gauge point), so the points are copied unchanged.
  They are inclined about 1:20 in the file: scenes say profile_inclination = "1:20".

Python 3 standard library only.
"""
import csv
import os
import sys

WHEELS = "ABHI"


def negate(text):
    """Minus the decimal number `text`, keeping its digits."""
    t = text.strip()
    if t.startswith("-"):
        return t[1:]
    if t.startswith("+"):
        t = t[1:]
    return "-" + t


def read_rows(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    if [c.strip() for c in rows[0][:2]] != ["y_mm", "z_mm"]:
        sys.exit(f"{path}: expected the header y_mm,z_mm, found {rows[0]}")
    for i, r in enumerate(rows[1:], start=2):
        if len(r) != 2:
            sys.exit(f"{path}:{i}: expected two columns")
        float(r[0]), float(r[1])  # numbers, or a ValueError naming them
    return rows[1:]


def write(path, header_lines, columns, rows):
    with open(path, "w", newline="") as f:
        for line in header_lines:
            f.write("# " + line + "\n")
        f.write(",".join(columns) + "\n")
        for a, b in rows:
            f.write(f"{a.strip()},{b.strip()}\n")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    src, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    for w in WHEELS:
        name = f"RUIC519{w}.csv"
        rows = read_rows(os.path.join(src, name))
        write(
            os.path.join(out, f"R-UIC519{w}.csv"),
            [
                f"EN 15302 reference wheel R-UIC519{w} (converted from {name} by scripts/en15302_profiles.py;",
                "sources and licence: NOTICE.md beside this file).",
                "s_mm: from the taping line, positive towards the field side (flange back at -70).",
                "F_mm: radius increase over the nominal radius = -z_mm of the source.",
            ],
            ["s_mm", "F_mm"],
            [(y, negate(z)) for y, z in rows],
        )
    rows = read_rows(os.path.join(src, "SUIC519A.csv"))
    write(
        os.path.join(out, "S-UIC519A.csv"),
        [
            "EN 15302 reference rail S-UIC519A (points of SUIC519A.csv unchanged, written by",
            "scripts/en15302_profiles.py; sources and licence: NOTICE.md beside this file).",
            "y_mm: lateral, positive towards the field side; z_mm: height, up.",
            "The points are already inclined about 1:20 (profile_inclination = \"1:20\").",
        ],
        ["y_mm", "z_mm"],
        rows,
    )


if __name__ == "__main__":
    main()
