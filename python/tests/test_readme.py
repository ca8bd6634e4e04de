"""The README's section "Use from Python": its example prints what the README says."""

import re
import subprocess
import sys


def test_the_readmes_example_prints_what_it_says(root):
    readme = (root / "README.md").read_text()
    section = readme.split("## Use from Python\n", 1)[1].split("\n## ", 1)[0]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    stated = re.search(r"```text\n(.*?)```", section, re.S).group(1)
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=root, capture_output=True, text=True, check=True
    )
    assert done.stdout == stated
    assert len(section.splitlines()) <= 40
