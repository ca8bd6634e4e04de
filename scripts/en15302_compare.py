#!/usr/bin/env python3
"""Compare the rolling radius difference of a wheelrail run with an EN 15302 Annex E table.

Usage:
    python3 scripts/en15302_compare.py RUN_DIR_OR_RIGID_CSV ANNEX_E_CSV [--inner-mm 5]
        [--exclude-mm 0.3] [--jump-ratio 20] [--list]

RUN_DIR_OR_RIGID_CSV: the folder written by `wheelrail report SCENE --out DIR` (rigid.csv and
rigid_jumps.csv are read from it) or the rigid.csv itself (rigid_jumps.csv beside it).
ANNEX_E_CSV: `y_mm,delta_r_mm` (tests/data/en15302/annexE/E*_delta_r.csv).

Both are in wheelrail's convention: delta_r = r_left - r_right, y_ws > 0 moves the wheelset
to the left. At each Annex E position y the run's delta_r_mm is taken at the same y_ws (a
row within 1e-6 mm; otherwise linear interpolation between the neighbouring rows, refused
across a contact-point jump). Prints the largest |delta_r_run - delta_r_annexE|:

* inner: over |y| <= inner-mm (5), leaving out positions within exclude-mm (0.3) of a jump
  of the Annex E table itself: a step between neighbouring points more than jump-ratio (20)
  times the larger adjacent step, placed at the middle of its interval (the rule of
  crates/cli/tests/en15302.rs);
* inner, all points: the same without leaving anything out;
* whole: over the whole table (-6.8..6.8 mm), nothing left out;
* whole, jumps excluded.

--list prints every position (y, run, Annex E, difference, excluded). Exit code 0; 2 on bad
input. Python 3 standard library only.
"""
import argparse
import csv
import math
import os
import sys


def read_table(path):
    """Rows of a CSV with `#` comment lines, as dicts of strings."""
    with open(path, newline="") as f:
        lines = [l for l in f if l.strip() and not l.startswith("#")]
    return list(csv.DictReader(lines))


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(2)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("run")
    ap.add_argument("annex")
    ap.add_argument("--inner-mm", type=float, default=5.0)
    ap.add_argument("--exclude-mm", type=float, default=0.3)
    ap.add_argument("--jump-ratio", type=float, default=20.0)
    ap.add_argument("--list", action="store_true")
    a = ap.parse_args()

    rigid = os.path.join(a.run, "rigid.csv") if os.path.isdir(a.run) else a.run
    jumps_path = os.path.join(os.path.dirname(rigid), "rigid_jumps.csv")
    try:
        rows = read_table(rigid)
        run = sorted((float(r["y_ws_mm"]), float(r["delta_r_mm"])) for r in rows)
        jumps = [(float(r["y_from_mm"]), float(r["y_to_mm"]), r["side"])
                 for r in read_table(jumps_path)] if os.path.exists(jumps_path) else []
        ref = [(float(r["y_mm"]), float(r["delta_r_mm"])) for r in read_table(a.annex)]
    except (OSError, KeyError, ValueError) as e:
        fail(f"{e}")
    if not os.path.exists(jumps_path):
        print(f"note: no {jumps_path}: no jumps excluded", file=sys.stderr)

    def jump_between(y0, y1):
        return any(y0 < hi and lo < y1 for lo, hi, _ in jumps)

    def run_at(y):
        for i, (yr, dr) in enumerate(run):
            if abs(yr - y) <= 1e-6:
                return dr
            if yr > y:
                if i == 0:
                    return math.nan
                (y0, d0), (y1, d1) = run[i - 1], run[i]
                if jump_between(y0, y1):
                    return math.nan
                return d0 + (d1 - d0) * (y - y0) / (y1 - y0)
        return math.nan

    steps = [abs(ref[i + 1][1] - ref[i][1]) for i in range(len(ref) - 1)]
    annex_jumps = [
        0.5 * (ref[i][0] + ref[i + 1][0])
        for i in range(len(steps))
        if steps[i] > a.jump_ratio * max(steps[j] for j in (i - 1, i + 1) if 0 <= j < len(steps))
    ]

    def near_jump(y):
        return any(abs(y - j) <= a.exclude_mm + 1e-9 for j in annex_jumps)

    stats = {k: (0.0, math.nan, 0) for k in ("inner", "inner_all", "whole", "whole_excl")}
    missing = []
    excluded_inner = 0

    def update(key, y, d):
        best, y_best, n = stats[key]
        stats[key] = (d, y, n + 1) if d > best or n == 0 else (best, y_best, n + 1)

    if a.list:
        print("y_mm,run_delta_r_mm,annexE_delta_r_mm,diff_mm,near_jump")
    for y, dr_ref in ref:
        dr = run_at(y)
        excl = near_jump(y)
        if a.list:
            print(f"{y:.1f},{dr:.4f},{dr_ref:.4f},{dr - dr_ref:+.4f},{int(excl)}")
        if math.isnan(dr):
            missing.append(y)
            continue
        d = abs(dr - dr_ref)
        inner = abs(y) <= a.inner_mm + 1e-9
        update("whole", y, d)
        if not excl:
            update("whole_excl", y, d)
        if inner:
            update("inner_all", y, d)
            if excl:
                excluded_inner += 1
            else:
                update("inner", y, d)

    print(f"run: {rigid}")
    print(f"annex E: {a.annex}")
    labels = {
        "inner": f"|y| <= {a.inner_mm:g} mm, {a.exclude_mm:g} mm around jumps left out",
        "inner_all": f"|y| <= {a.inner_mm:g} mm, all points",
        "whole": f"{ref[0][0]:g}..{ref[-1][0]:g} mm, all points",
        "whole_excl": f"{ref[0][0]:g}..{ref[-1][0]:g} mm, {a.exclude_mm:g} mm around jumps left out",
    }
    for key in ("inner", "inner_all", "whole", "whole_excl"):
        best, y_best, n = stats[key]
        at = f" at y = {y_best:+.1f} mm" if n else ""
        print(f"max |d delta_r| {labels[key]}: {best:.4f} mm{at} ({n} points)")
    print(f"points within {a.exclude_mm:g} mm of a jump of Annex E (|y| <= {a.inner_mm:g}): {excluded_inner}; "
          f"Annex E's jumps at y = " + (", ".join(f"{j:+.2f}" for j in annex_jumps) or "none") + " mm")
    if missing:
        print(f"no run value (outside the sweep, NaN, or across a jump) at y = "
              + ", ".join(f"{y:g}" for y in missing))


if __name__ == "__main__":
    main()
