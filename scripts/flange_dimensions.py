#!/usr/bin/env python3
"""Flange dimensions Sh, Sd, qR of wheel profile files, computed on the raw measured points.

Usage: python3 scripts/flange_dimensions.py FILE... > tests/data/flange_dimensions.csv

FILE is a MiniProf wheel (.whl), a SIMPACK wheel (.prw) or a wheel CSV (.csv, `s_mm,F_mm`).

An independent check of wheelrail's `maintenance::flange_dimensions`: it shares no code with
the Rust (no spline, no reader, no validation). The points are taken as the file lists them
(turned round if the file starts on the field side), joined by straight lines, and walked
along the curve, so points that step back at the flange tip are neither dropped nor
reordered, and no smoothing of any kind is applied.

Definitions (EN 15313; the wheel figures of the TSI, Regulation (EU) No 321/2013 4.2.3.6.2,
Figure 1 and Table 3), in the wheel side frame: s (mm) from the taping line, positive
towards the field side, the inner face at s = -70 (the taping line is 70 mm from it); F (mm)
the radius increase, positive towards the flange tip.

* F0: the height of the profile at s = 0 (linear interpolation along the tread).
* Sh, flange height: the highest F of the flange side (s < 0; the flange tip) minus F0.
* Sd, flange thickness: s + 70 of the point of the flange's field-side flank at height
  F0 + 10 mm (the first crossing of that height walking from the tip towards the field
  side), i.e. measured from the inner face.
* qR: s of the Sd point minus s of the point of the same flank 2 mm below the tip (the
  first crossing of that height walking from the tip towards the field side).

A flange lower than 10 mm above F0 has no Sd point: its row says so, its values NaN.

How the formats give (s, F):

* MiniProf: X from the inner face (X = 0), growing towards the field side, and Y the radius
  increase: s = X - 70, F = Y. A header ends at a blank line after content or at the first
  line of numbers only; lines starting with " ! % # are comments.
* SIMPACK: the rows `y z` between point.begin and point.end (`!` and `%` start comments),
  with the processing entries these files use: shift.y/z added, mirror.y/z negating, the
  unit factor units.len.f (length unit per metre; 1000 = mm, SIMPACK's default 1 = m). A
  rotation, active bounds or a minimum point distance are refused (not needed here, and
  their conventions are not checked by this script). A wheel's (s, F) is (y, z).
* CSV: the first two columns of the rows after the header row, s and F in mm; lines
  starting with # are comments.

Python 3 standard library only.
"""
import csv
import hashlib
import math
import sys

TAPING_LINE_FROM_INNER_FACE_MM = 70.0
SD_HEIGHT_MM = 10.0
QR_BELOW_TIP_MM = 2.0
MINIPROF_COMMENTS = ('"', "!", "%", "#")


def is_number(token):
    try:
        float(token)
        return True
    except ValueError:
        return False


def read_miniprof(path):
    """(s, F) of the data rows, in file order."""
    points = []
    in_header = True
    saw_content = False
    with open(path, encoding="latin-1") as f:
        for raw in f:
            line = raw.strip()
            if not line:
                if saw_content:
                    in_header = False
                continue
            if line.startswith(MINIPROF_COMMENTS):
                continue
            saw_content = True
            tokens = line.replace(",", " ").split()
            numbers = len(tokens) >= 2 and all(is_number(t) for t in tokens)
            if in_header and not numbers:
                continue
            in_header = False
            x, y = float(tokens[0]), float(tokens[1])
            points.append((x - TAPING_LINE_FROM_INNER_FACE_MM, y))
    return points


def simpack_number(token):
    return float(token.replace("D", "E").replace("d", "e"))


def read_simpack(path):
    """(s, F) of the point rows of a SIMPACK wheel, in file order after its processing."""
    settings = {}
    rows = []
    in_points = False
    with open(path, encoding="latin-1") as f:
        for raw in f:
            line = raw.split("!")[0].split("%")[0].strip()
            if not line:
                continue
            if line == "point.begin":
                in_points = True
            elif line == "point.end":
                in_points = False
            elif in_points:
                tokens = line.split()
                rows.append((simpack_number(tokens[0]), simpack_number(tokens[1])))
            elif "=" in line:
                key, value = (part.strip() for part in line.split("=", 1))
                settings[key] = value

    def setting(key, default):
        return simpack_number(settings[key]) if key in settings else default

    if setting("rotate", 0.0) != 0.0:
        raise ValueError(f"{path}: rotate is not supported by this check")
    if setting("point.dist.min", 0.0) > 0.0:
        raise ValueError(f"{path}: point.dist.min is not supported by this check")
    for axis in "yz":
        if setting(f"bound.{axis}.min", 1.0) < setting(f"bound.{axis}.max", 0.0):
            raise ValueError(f"{path}: bound.{axis} is not supported by this check")
    shift = (setting("shift.y", 0.0), setting("shift.z", 0.0))
    mirror = (setting("mirror.y", 0.0) == 1.0, setting("mirror.z", 0.0) == 1.0)
    to_mm = 1000.0 / setting("units.len.f", 1.0)
    points = []
    for y, z in rows:
        y, z = y + shift[0], z + shift[1]
        y, z = (-y if mirror[0] else y), (-z if mirror[1] else z)
        points.append((y * to_mm, z * to_mm))
    return points


def read_csv(path):
    """(s, F) of the first two columns of the rows after the header row."""
    with open(path, encoding="utf-8", newline="") as f:
        lines = [l for l in f if l.strip() and not l.startswith("#")]
    rows = list(csv.reader(lines))
    return [(float(r[0]), float(r[1])) for r in rows[1:]]


def read_points(path):
    extension = path.lower().rsplit(".", 1)[-1]
    reader = {"whl": read_miniprof, "prw": read_simpack, "csv": read_csv}[extension]
    points = reader(path)
    # The walk goes from the flange towards the field side.
    if points[0][0] > points[-1][0]:
        points.reverse()
    return points


def crossing(points, start, level):
    """s where the polyline, walked from index `start` towards higher indices, first comes
    down through height `level`."""
    for i in range(start, len(points) - 1):
        (s0, f0), (s1, f1) = points[i], points[i + 1]
        if f0 >= level > f1:
            return s0 + (s1 - s0) * (f0 - level) / (f0 - f1)
    raise ValueError(f"the profile never comes down through {level} mm")


def height_at(points, s):
    """F at `s` on the first segment (from the field side back) that spans it."""
    for i in range(len(points) - 1, 0, -1):
        (s0, f0), (s1, f1) = points[i - 1], points[i]
        if min(s0, s1) <= s <= max(s0, s1) and s0 != s1:
            return f0 + (f1 - f0) * (s - s0) / (s1 - s0)
    raise ValueError(f"no point pair spans s = {s}")


def dimensions(points):
    f0 = height_at(points, 0.0)
    flange = [i for i, p in enumerate(points) if p[0] < 0.0]
    tip = max(flange, key=lambda i: points[i][1])
    s_tip, f_tip = points[tip]
    d = {
        "status": "ok",
        "taping_line_F_mm": f0,
        "tip_s_mm": s_tip,
        "sh_mm": f_tip - f0,
        "sd_mm": math.nan,
        "qr_mm": math.nan,
    }
    if f_tip - f0 < SD_HEIGHT_MM:
        d["status"] = "flange lower than the 10 mm where Sd is measured"
        return d
    s_sd = crossing(points, tip, f0 + SD_HEIGHT_MM)
    s_qr = crossing(points, tip, f_tip - QR_BELOW_TIP_MM)
    d["sd_mm"] = s_sd + TAPING_LINE_FROM_INNER_FACE_MM
    d["qr_mm"] = s_sd - s_qr
    return d


def number(value):
    return "NaN" if math.isnan(value) else f"{value:.6f}"


def main(paths):
    columns = ["sh_mm", "sd_mm", "qr_mm", "taping_line_F_mm", "tip_s_mm"]
    print("# flange dimensions of wheel profile files from their raw points joined by straight lines (no points dropped, no smoothing)")
    print("# written by scripts/flange_dimensions.py (Python standard library; shares no code with wheelrail)")
    print("# sh_mm flange height above the taping line (70 mm from the inner face); sd_mm flange thickness from the inner face at 10 mm above the taping line; qr_mm from the Sd point to the flank 2 mm below the tip")
    print("# taping_line_F_mm the height of the profile at the taping line; tip_s_mm the tip's lateral position from the taping line (positive towards the field side); status ok or why Sd and qR are undefined (NaN)")
    print("# sha256 of the file's bytes, to tell which file was measured")
    print("file,sha256," + ",".join(columns) + ",status")
    for path in paths:
        d = dimensions(read_points(path))
        name = path.replace("\\", "/").split("/")[-1]
        with open(path, "rb") as f:
            sha256 = hashlib.sha256(f.read()).hexdigest()
        print(f"{name},{sha256}," + ",".join(number(d[c]) for c in columns) + "," + d["status"])


if __name__ == "__main__":
    main(sys.argv[1:])
