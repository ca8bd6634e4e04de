#!/usr/bin/env python3
"""Flange dimensions Sh, Sd, qR of MiniProf wheel files, computed on the raw measured points.

Usage: python3 scripts/flange_dimensions.py FILE.whl... > tests/data/flange_dimensions.csv

An independent check of wheelrail's `maintenance::flange_dimensions`: it shares no code with
the Rust (no spline, no reader, no validation). The points are taken as the file lists them,
joined by straight lines, and walked along the curve, so points that step back at the flange
tip are neither dropped nor reordered.

Definitions (EN 15313; the wheel figures of the TSI, Regulation (EU) No 321/2013 4.2.3.6.2,
Figure 1 and Table 3):

* MiniProf measures a wheel from its inner face: X = 0 on the inner face, growing towards
  the field side; Y the radius increase. The taping line (measuring circle) is 70 mm from
  the inner face, at X = 70.
* F0: the height Y of the profile at X = 70 (linear interpolation along the tread).
* Sh, flange height: the highest Y of the flange (the flange tip) minus F0.
* Sd, flange thickness: X of the point of the flange's field-side flank at height F0 + 10
  mm (the first crossing of that height walking from the tip towards the field side),
  measured from the inner face (X = 0).
* qR: X of the Sd point minus X of the point of the same flank 2 mm below the tip (height
  tip - 2 mm, the first crossing walking from the tip towards the field side).

Python 3 standard library only.
"""
import sys

TAPING_LINE_X_MM = 70.0
SD_HEIGHT_MM = 10.0
QR_BELOW_TIP_MM = 2.0
COMMENT_STARTS = ('"', "!", "%", "#")


def is_number(token):
    try:
        float(token)
        return True
    except ValueError:
        return False


def read_points(path):
    """(X, Y) of the data rows: after the header (ended by a blank line after content, or
    by the first line of numbers only), comment lines skipped."""
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
            if line.startswith(COMMENT_STARTS):
                continue
            saw_content = True
            tokens = line.replace(",", " ").split()
            numbers = len(tokens) >= 2 and all(is_number(t) for t in tokens)
            if in_header and not numbers:
                continue
            in_header = False
            points.append((float(tokens[0]), float(tokens[1])))
    return points


def crossing(points, start, level):
    """X where the polyline, walked from index `start` towards higher indices, first comes
    down through height `level`."""
    for i in range(start, len(points) - 1):
        (x0, y0), (x1, y1) = points[i], points[i + 1]
        if y0 >= level > y1:
            return x0 + (x1 - x0) * (y0 - level) / (y0 - y1)
    raise ValueError(f"the profile never comes down through {level} mm")


def height_at(points, x):
    """Y at `x` on the first segment (from the field side back) that spans it."""
    for i in range(len(points) - 1, 0, -1):
        (x0, y0), (x1, y1) = points[i - 1], points[i]
        if min(x0, x1) <= x <= max(x0, x1) and x0 != x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    raise ValueError(f"no point pair spans X = {x}")


def dimensions(points):
    f0 = height_at(points, TAPING_LINE_X_MM)
    flange = [i for i, p in enumerate(points) if p[0] < TAPING_LINE_X_MM]
    tip = max(flange, key=lambda i: points[i][1])
    x_tip, y_tip = points[tip]
    x_sd = crossing(points, tip, f0 + SD_HEIGHT_MM)
    x_qr = crossing(points, tip, y_tip - QR_BELOW_TIP_MM)
    return {
        "taping_line_F_mm": f0,
        "tip_s_mm": x_tip - TAPING_LINE_X_MM,
        "sh_mm": y_tip - f0,
        "sd_mm": x_sd,
        "qr_mm": x_sd - x_qr,
    }


def main(paths):
    columns = ["sh_mm", "sd_mm", "qr_mm", "taping_line_F_mm", "tip_s_mm"]
    print("# flange dimensions of MiniProf wheel files from their raw points joined by straight lines")
    print("# written by scripts/flange_dimensions.py (Python standard library; shares no code with wheelrail)")
    print("# sh_mm flange height above the taping line (70 mm from the inner face); sd_mm flange thickness from the inner face at 10 mm above the taping line; qr_mm from the Sd point to the flank 2 mm below the tip")
    print("# taping_line_F_mm the height of the profile at the taping line; tip_s_mm the tip's lateral position from the taping line (positive towards the field side)")
    print("file," + ",".join(columns))
    for path in paths:
        d = dimensions(read_points(path))
        name = path.replace("\\", "/").split("/")[-1]
        print(name + "," + ",".join(f"{d[c]:.6f}" for c in columns))


if __name__ == "__main__":
    main(sys.argv[1:])
