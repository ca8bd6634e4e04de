#!/usr/bin/env python3
"""Links of the crate's rustdoc pages that lead nowhere.

    python3 scripts/doc_links.py target/doc

rustdoc warns about links to private items, but not about links to `#[doc(hidden)]`
items: it prints ``[`x`]`` as it stands (`[x]` in code type, no link) and writes
`[text](path::x)` with the path as its target. This finds both, and any other relative
link of `target/doc/wheelrail/` whose file does not exist. Prints each missing target with
the pages that link to it; exits 1 if there is one. Standard library only.
"""

import os
import re
import sys


def missing_targets(doc):
    crate = os.path.join(doc, "wheelrail")
    missing = {}
    for folder, _, files in os.walk(crate):
        for name in files:
            if not name.endswith(".html"):
                continue
            page = os.path.join(folder, name)
            with open(page, encoding="utf-8") as f:
                text = f.read()
            if "Redirecting to" in text[:600]:
                continue
            for name in re.findall(r"\[<code>([^<]{1,100})</code>\]", text):
                missing.setdefault(f"[`{name}`] (no link)", set()).add(os.path.relpath(page, doc))
            for href in re.findall(r'href="([^"#?]+)', text):
                if href.startswith(("http:", "https:", "mailto:", "javascript:")):
                    continue
                target = os.path.normpath(os.path.join(folder, href))
                inside = os.path.commonpath([target, os.path.abspath(crate)]) == os.path.abspath(crate)
                if inside and not os.path.exists(target):
                    missing.setdefault(os.path.relpath(target, doc), set()).add(
                        os.path.relpath(page, doc)
                    )
    return missing


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    missing = missing_targets(os.path.abspath(sys.argv[1]))
    for target in sorted(missing):
        print(f"{target} <- {', '.join(sorted(missing[target]))}")
    if missing:
        print(f"{len(missing)} link targets missing", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
