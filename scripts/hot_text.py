#!/usr/bin/env python3
"""The functions a report runs, as the linker-script fragment `link/hot-text.ld`.

    cargo build --release
    python3 scripts/hot_text.py [SCENE ...] > link/hot-text.ld

Runs `target/release/wheelrail report` under callgrind (valgrind, one thread) twice for each
scene (default: `reports/en15302_e1/scene.toml`): first its core, the scene with one figure
in SVG (what every report runs: the profiles placed, the sweep solved, the tables, one chart
and the page), then the scene as it is. It keeps the functions that ran and that the program
defines (`nm`), and writes a fragment of linker script that gathers their sections into an
output section `.text.hot` placed before `.text` (`INSERT BEFORE`: the rest of the layout
stays the linker's default; GNU ld and LLD both read it). The core's functions come first,
so that a short report (`../shared/peer/awrcc/compare.sh` runs one) maps the fewest pages of
code; those only the whole scene runs (the other figures, PNG) follow.

rustc puts every function in a section of its own, `.text.<symbol>`, so the fragment names
sections by symbol. The hashes in the symbols (`17h<16 hex digits>E` of the legacy scheme,
the crate disambiguators `Cs<base-62>_` of v0) change with the build, the toolchain and the
dependencies' versions, so they are written as wildcards: a pattern that matches nothing
is allowed, and a function renamed or new since the fragment was made is only left in
`.text` with the rest. The C library's functions (the program links it statically where it
can: build.rs) come from the members of its archives, named as `archive:member`; where the
program links it dynamically those patterns match nothing. valgrind's CPU has no AVX-512, so
the string functions the C library picks for it may not be those it picks on the machine.

The order within each part is the functions' own instruction counts, largest first, then
the others that ran. Standard library only (with valgrind's `callgrind_annotate`, binutils'
`nm` and the C compiler, asked where its archives are). Why the program is linked so:
`build.rs`.
"""

import os
import re
import subprocess
import sys
import tempfile
import tomllib

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
            if len(p) == 3 and p[1] in "tTwWi"}


def pattern(symbol):
    """The section pattern of `symbol` with its hashes as wildcards (LLVM puts a cold
    function, `#[cold]` or only called on a cold path, in `.text.unlikely.<symbol>`)."""
    symbol = re.sub(r"17h[0-9a-f]{16}E$", "17h*", symbol)
    symbol = re.sub(r"Cs[0-9A-Za-z]+_", "Cs*_", symbol)
    return f"*(.text.{symbol} .text.unlikely.{symbol})"


ARCHIVES = ["libc.a", "libm.a", "libgcc.a", "libgcc_eh.a"]


def archive_members():
    """The function symbols the C compiler's static archives define, each with the pattern of
    the member that holds it (`*libc.a:malloc.o(.text .text.*)`); none where it has none."""
    members = {}
    for name in ARCHIVES:
        path = subprocess.run(["cc", f"-print-file-name={name}"], capture_output=True,
                              text=True).stdout.strip()
        if not os.path.isabs(path):
            continue
        for archive in archives(path):
            listing = subprocess.run(["nm", "-A", "--defined-only", archive],
                                     capture_output=True, text=True).stdout
            # `archive:member:address type symbol` per line.
            every, defined_in = set(), {}
            for line in listing.splitlines():
                where, _, rest = line.rpartition(":")
                member = where.rpartition(":")[2]
                every.add(member)
                parts = rest.split()
                if len(parts) == 3 and parts[1] in "tTwWi":
                    defined_in.setdefault(parts[2], member)
            base = os.path.basename(archive)
            for symbol, member in defined_in.items():
                members.setdefault(symbol, [f"*{base}:{m}(.text .text.*)"
                                            for m in variants(member, every)])
    return members


def variants(member, every):
    """`member` and, for a string function's version for one instruction set (glibc's
    `memmove-avx-unaligned-erms.o`), its AVX-512 and EVEX versions among `every` member: the
    ones a CPU with AVX-512 runs, which valgrind's CPU has not."""
    m = re.match(r"([a-z0-9_]+)-(sse2|ssse3|sse4_1|sse4_2|avx|avx2)(-.*)?\.o$", member)
    if not m:
        return [member]
    stem = m.group(1) + "-"
    return [member] + sorted(o for o in every
                             if o.startswith((stem + "evex", stem + "avx512")))


def archives(path):
    """The archive at `path`, or those a linker script there names (glibc's `libm.a` is
    `GROUP ( libm-2.36.a libmvec.a )`)."""
    with open(path, "rb") as f:
        if f.read(8) == b"!<arch>\n":
            return [path]
    text = open(path, encoding="utf-8", errors="replace").read()
    names = re.findall(r"[^\s()]+\.a\b", re.sub(r"/\*.*?\*/", "", text, flags=re.S))
    return [n if os.path.isabs(n) else os.path.join(os.path.dirname(path), n) for n in names]


def core_scene(scene):
    """`scene` with its first figure alone, in SVG, written beside it (relative paths in it
    stay right); the path of the copy."""
    text = open(scene, encoding="utf-8").read()
    figures = tomllib.loads(text).get("outputs", {}).get("figures", [])
    figure = f'figures = ["{figures[0]}"]' if figures else "figures = []"
    text = re.sub(r"^figures\s*=.*$", figure, text, flags=re.M)
    text = re.sub(r"^formats\s*=.*$", 'formats = ["svg"]', text, flags=re.M)
    path = os.path.join(os.path.dirname(scene), ".hot-text-core.toml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def main():
    scenes = sys.argv[1:] or ["reports/en15302_e1/scene.toml"]
    defined = defined_functions()
    members = archive_members()
    patterns = []
    seen = set()
    with tempfile.TemporaryDirectory() as tmp:
        runs = []

        def run(scene, tag):
            runs.append(ran(scene, os.path.join(tmp, f"{tag}{len(runs)}"),
                            os.path.join(tmp, f"cg{len(runs)}")))

        for scene in scenes:
            core = core_scene(scene)
            try:
                run(core, "core")
            finally:
                os.remove(core)
        for scene in scenes:
            run(scene, "out")
        for names in runs:
            for name in names:
                if name not in defined:
                    continue
                # rustc's functions (its C `main` and the compiler's built-ins among
                # them), and those of the C library's archives.
                for p in [pattern(name)] + members.get(name, []):
                    if p not in seen:
                        seen.add(p)
                        patterns.append(p)
    print("/* The functions a report runs, gathered before the rest of the program's code:")
    print(f"   written by scripts/hot_text.py from {', '.join(scenes)}; see build.rs. */")
    print("SECTIONS\n{\n  .text.hot : {")
    for p in patterns:
        print(f"    {p}")
    print("  }\n}\nINSERT BEFORE .text;")


if __name__ == "__main__":
    main()
