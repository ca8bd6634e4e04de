#!/usr/bin/env python3
"""Rolling radius difference WITHOUT wheelset roll, for checking the EN 15302 Annex E tables.

Usage:
    python3 scripts/en15302_noroll.py LEFT_WHEEL.csv RIGHT_WHEEL.csv RAIL.csv OUT_DIR
        [--rail-offset-mm 0] [--from-mm -7.5] [--to-mm 7.5] [--step-mm 0.1] [--grid-mm 0.005]
        [--radii-mm LEFT RIGHT]

This is NOT wheelrail's rigid search: it is an independent, deliberately simple model used as
evidence (see reports/en15302_e*/scene.toml). Each wheel is translated laterally by the
wheelset shift y only (no roll, each wheel lowered onto its rail on its own), the contact is
the smallest vertical gap, and delta_r = F_left(s_left) - F_right(s_right), plus the
difference of the wheels' nominal radii given by --radii-mm (EN 15302 cases E5-E8: 460 459).

Frames: the wheel CSVs are wheelrail wheel files (`s_mm,F_mm`, s from the taping line), the
rail CSV a wheelrail rail file (`y_mm,z_mm`). As in the EN 15302 reference files
(tests/data/en15302/NOTICE.md), wheel and rail share one frame per side for the centred
wheelset: the taping line is at rail y = 0. --rail-offset-mm d moves the rails d towards
the field side (a gauge wider by 2 d). Per side: wheel point s lies over rail point
y = s - d + y_ws on the left (y_ws > 0 moves the wheelset left, its left flange towards
the left rail) and y = s - d - y_ws on the right.

Both profiles are natural cubic splines through their points, evaluated on a grid of
--grid-mm along the rail; the minimum is taken over the grid points (no refinement).

Writes OUT_DIR/rigid.csv (y_ws_mm, left_s_mm, right_s_mm, left_F_mm, right_F_mm,
delta_r_mm) and OUT_DIR/rigid_jumps.csv (side, y_from_mm, y_to_mm, s_from_mm, s_to_mm:
positions between which a contact point moves by more than 1 mm), which
scripts/en15302_compare.py reads like a wheelrail run. Python 3 standard library only.
"""
import argparse
import bisect
import csv
import os
import sys


def read_profile(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(l for l in f if l.strip() and not l.startswith("#"))]
    return [float(r[0]) for r in rows[1:]], [float(r[1]) for r in rows[1:]], rows[0][0]


class Spline:
    """Natural cubic spline through (x, y), x strictly increasing."""

    def __init__(self, x, y):
        n = len(x)
        h = [x[i + 1] - x[i] for i in range(n - 1)]
        # Tridiagonal system for the second derivatives m (m_0 = m_{n-1} = 0).
        a = [0.0] * n
        b = [1.0] * n
        c = [0.0] * n
        d = [0.0] * n
        for i in range(1, n - 1):
            a[i] = h[i - 1]
            b[i] = 2.0 * (h[i - 1] + h[i])
            c[i] = h[i]
            d[i] = 6.0 * ((y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1])
        for i in range(1, n):
            w = a[i] / b[i - 1]
            b[i] -= w * c[i - 1]
            d[i] -= w * d[i - 1]
        m = [0.0] * n
        m[n - 1] = d[n - 1] / b[n - 1]
        for i in range(n - 2, -1, -1):
            m[i] = (d[i] - c[i] * m[i + 1]) / b[i]
        self.x, self.y, self.m, self.h = x, y, m, h

    def __call__(self, t):
        x = self.x
        if t < x[0] or t > x[-1]:
            return None
        i = min(max(bisect.bisect_right(x, t) - 1, 0), len(x) - 2)
        h = self.h[i]
        u = (x[i + 1] - t) / h
        v = (t - x[i]) / h
        return (u * self.y[i] + v * self.y[i + 1]
                + ((u ** 3 - u) * self.m[i] + (v ** 3 - v) * self.m[i + 1]) * h * h / 6.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("left_wheel")
    ap.add_argument("right_wheel")
    ap.add_argument("rail")
    ap.add_argument("out_dir")
    ap.add_argument("--rail-offset-mm", type=float, default=0.0)
    ap.add_argument("--from-mm", type=float, default=-7.5)
    ap.add_argument("--to-mm", type=float, default=7.5)
    ap.add_argument("--step-mm", type=float, default=0.1)
    ap.add_argument("--grid-mm", type=float, default=0.005)
    ap.add_argument("--radii-mm", type=float, nargs=2, default=(0.0, 0.0))
    a = ap.parse_args()

    wheels = []
    for path in (a.left_wheel, a.right_wheel):
        s, f, head = read_profile(path)
        if head != "s_mm":
            sys.exit(f"{path}: not a wheel file (first column {head!r}, expected s_mm)")
        wheels.append(Spline(s, f))
    ry, rz, head = read_profile(a.rail)
    if head != "y_mm":
        sys.exit(f"{a.rail}: not a rail file (first column {head!r}, expected y_mm)")
    rail = Spline(ry, rz)
    g = a.grid_mm
    n = int((ry[-1] - ry[0]) / g)
    grid = [ry[0] + k * g for k in range(n + 1)]
    rail_z = [rail(y) for y in grid]
    d = a.rail_offset_mm

    count = int(round((a.to_mm - a.from_mm) / a.step_mm))
    rows = []
    for j in range(count + 1):
        y_ws = a.from_mm + j * a.step_mm
        out = []
        for side, wheel in (("left", wheels[0]), ("right", wheels[1])):
            shift = d - y_ws if side == "left" else d + y_ws  # s = y_rail + shift
            best = None
            for y, zr in zip(grid, rail_z):
                f = wheel(y + shift)
                if f is None:
                    continue
                gap = -f - zr  # wheel surface at -F above the taping-line level
                if best is None or gap < best[0]:
                    best = (gap, y + shift, f)
            if best is None:
                sys.exit(f"no overlap of wheel and rail at y_ws = {y_ws}")
            out.append(best)
        (_, sl, fl), (_, sr, fr) = out
        rows.append((y_ws, sl, sr, fl, fr, a.radii_mm[0] - a.radii_mm[1] + fl - fr))

    os.makedirs(a.out_dir, exist_ok=True)
    with open(os.path.join(a.out_dir, "rigid.csv"), "w") as f:
        f.write("# NO-ROLL model of scripts/en15302_noroll.py (not wheelrail's rigid search)\n")
        f.write(f"# left {a.left_wheel}, right {a.right_wheel}, rail {a.rail}, rail offset {d} mm, radii {a.radii_mm[0]} {a.radii_mm[1]} mm\n")
        f.write("y_ws_mm,left_s_mm,right_s_mm,left_F_mm,right_F_mm,delta_r_mm\n")
        for r in rows:
            f.write(",".join(f"{v:.6f}" for v in r) + "\n")
    with open(os.path.join(a.out_dir, "rigid_jumps.csv"), "w") as f:
        f.write("# contact point moving by more than 1 mm between neighbouring positions\n")
        f.write("side,y_from_mm,y_to_mm,s_from_mm,s_to_mm\n")
        for r0, r1 in zip(rows, rows[1:]):
            for side, k in (("left", 1), ("right", 2)):
                if abs(r1[k] - r0[k]) > 1.0:
                    f.write(f"{side},{r0[0]:.6f},{r1[0]:.6f},{r0[k]:.6f},{r1[k]:.6f}\n")


if __name__ == "__main__":
    main()
