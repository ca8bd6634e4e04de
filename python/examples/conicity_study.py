"""Equivalent conicity against track gauge: the EN 15302 reference pair R-UIC519A on
S-UIC519A (rails inclined 1:20), gauge 1432 to 1440 mm and the standard's reference gauge.

A study no single command does: tan γe(3 mm) as the gauge widens or closes, for the
wheelset held level (the rolling radius difference of EN 15302 Annex E) and with its roll
solved (both wheels touching, as a real wheelset runs). Everything else is the committed
scene reports/en15302_e1/scene.toml: sweep -7.5 to 7.5 mm by 0.1 mm, flange back 1360 mm,
the rail file's gauge point 14.4918 mm below its top (see that scene's comments).

Run from the repository root (after `pip install ./python`):

    python python/examples/conicity_study.py [--out FOLDER]

It prints the table and, when matplotlib is installed, saves FOLDER/conicity_vs_gauge.png
(default: the current folder).
"""

import argparse
from pathlib import Path

import numpy as np

import wheelrail

DATA = Path(__file__).resolve().parents[2] / "tests" / "data" / "en15302"
# Every half millimetre; the standard's gauge, 1435 mm (the committed scene's), is one of them.
GAUGES_MM = np.arange(1432.0, 1440.0 + 0.25, 0.5)
SHIFTS_MM = np.round(np.arange(-75, 76) * 0.1, 9)  # -7.5 .. 7.5 mm, as the scene's sweep


def tan_gamma_e_3mm(wheel, rail, gauge_mm, solver):
    """tan γe at 3 mm amplitude (EN 15302 Annex B, Klingel) of the pair on this gauge."""
    tables = wheelrail.rigid_sweep(
        wheel,
        rail,
        SHIFTS_MM,
        gauge_mm=gauge_mm,
        gauge_point_depth_mm=14.4918,
        inclination="1:20",
        rail_profile_inclination="1:20",
        solver=solver,
    )
    parameters = tables["parameters"]
    row = list(parameters["parameter"]).index("tan_gamma_e_3mm")
    return float(parameters["value"][row])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("."), help="folder of the figure")
    out = parser.parse_args().out

    wheel = wheelrail.read_profile(DATA / "R-UIC519A.csv", "wheel")
    rail = wheelrail.read_profile(DATA / "S-UIC519A.csv", "rail")
    level = [tan_gamma_e_3mm(wheel, rail, g, "no_roll") for g in GAUGES_MM]
    rolled = [tan_gamma_e_3mm(wheel, rail, g, "default") for g in GAUGES_MM]

    print("gauge_mm,tan_gamma_e_3mm_level,tan_gamma_e_3mm_roll_solved")
    for g, a, b in zip(GAUGES_MM, level, rolled):
        print(f"{g:.2f},{a:.4f},{b:.4f}")

    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib is not installed: no figure)")
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(GAUGES_MM, level, "o-", label="wheelset held level (EN 15302 Annex E Δr)")
    ax.plot(GAUGES_MM, rolled, "s--", label="roll solved (both wheels touching)")
    ax.axvline(1435.0, color="0.6", linewidth=0.8)
    ax.text(1435.08, 0.97, "standard gauge", transform=ax.get_xaxis_transform(), va="top", fontsize=8)
    ax.set_xlabel("track gauge (mm)")
    ax.set_ylabel("equivalent conicity tan γe(3 mm) (dimensionless)")
    ax.set_title("R-UIC519A on S-UIC519A 1:20: equivalent conicity against gauge", fontsize=10)
    ax.grid(True, linewidth=0.4)
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(out / "conicity_vs_gauge.png", dpi=120)
    print(f"wrote {out / 'conicity_vs_gauge.png'}")


if __name__ == "__main__":
    main()
