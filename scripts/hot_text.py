#!/usr/bin/env python3
"""The functions a report runs, as the linker-script fragment `link/hot-text.ld`.

    cargo build --release
    python3 scripts/hot_text.py [SCENE ...] > link/hot-text.ld

Runs `target/release/wheelrail report SCENE --out TMP` under callgrind (valgrind, one
thread) for each scene (default: `reports/en15302_e1/scene.toml`), keeps the functions that
ran and that the program itself defines (`nm`), and writes a fragment of linker script that
gathers their sections into an output section `.text.hot` placed before `.text` (`INSERT
BEFORE`: the rest of the layout stays the linker's default; GNU ld and LLD both read it).
rustc puts every function in a section of its own, `.text.<symbol>`, so the fragment names
sections by symbol. The hashes in the symbols (`17h<16 hex digits>E` of the legacy scheme,
the crate disambiguators `Cs<base-62>_` of v0) change with the build, the toolchain and the
dependencies' versions, so they are written as wildcards: a pattern that matches nothing
is allowed, and a function renamed or new since the fragment was made is only left in
`.text` with the rest. Why the program is linked so: `build.rs`.

The order is the functions' own instruction counts, largest first, then the others that
ran. Standard library only (with valgrind's `callgrind_annotate` and binutils' `nm`).
"""

import os
import re
import subprocess
import sys
import tempfile

BIN = "target/release/wheelrail"


def ran(scene, out_dir, profile):
    """The mangled names of the functions that ran in a report of `scene`, by their own
    instruction counts, largest first (the ones below the annotation's threshold after)."""
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    subprocess.run(
        ["valgrind", "--tool=callgrind", "--demangle=no", f"--callgrind-out-file={profile}",
         BIN, "report", scene, "--out", out_dir],
        check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    annotated = subprocess.run(
        ["callgrind_annotate", "--inclusive=no", "--threshold=100", profile],
        check=True, capture_output=True, text=True).stdout
    ordered = []
    for line in annotated.splitlines():
        m = re.match(r"\s*[\d,]+\s+\([\s\d.]+%\)\s+(?:[^:\s]*:)?(\S+)\s+\[", line)
        if m:
            ordered.append(m.group(1))
    text = open(profile, encoding="utf-8", errors="replace").read()
    every = re.findall(r"^c?fn=\(\d+\) (\S+)", text, re.M)
    return ordered + every


def defined_functions():
    """The program's own function symbols (`nm`: text symbols)."""
    listing = subprocess.run(["nm", "--defined-only", BIN], check=True,
                             capture_output=True, text=True).stdout
    return {p[2] for p in (l.split() for l in listing.splitlines())
            if len(p) == 3 and p[1] in "tTwW"}


def pattern(symbol):
    """The section pattern of `symbol` with its hashes as wildcards."""
    symbol = re.sub(r"17h[0-9a-f]{16}E$", "17h*", symbol)
    symbol = re.sub(r"Cs[0-9A-Za-z]+_", "Cs*_", symbol)
    return ".text." + symbol


def main():
    scenes = sys.argv[1:] or ["reports/en15302_e1/scene.toml"]
    defined = defined_functions()
    patterns = []
    seen = set()
    with tempfile.TemporaryDirectory() as tmp:
        for i, scene in enumerate(scenes):
            names = ran(scene, os.path.join(tmp, f"out{i}"), os.path.join(tmp, f"cg{i}"))
            for name in names:
                if name in defined and name.startswith(("_ZN", "_R")):
                    p = pattern(name)
                    if p not in seen:
                        seen.add(p)
                        patterns.append(p)
    print("/* The functions a report runs, gathered before the rest of the program's code:")
    print(f"   written by scripts/hot_text.py from {', '.join(scenes)}; see build.rs. */")
    print("SECTIONS\n{\n  .text.hot : {")
    for p in patterns:
        print(f"    *({p})")
    print("  }\n}\nINSERT BEFORE .text;")


if __name__ == "__main__":
    main()
