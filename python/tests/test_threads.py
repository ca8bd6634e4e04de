"""Long calls release the interpreter: a thread pool of the user's runs them side by side.

The tests are decided by order, not by time: a call that reads a named pipe (FIFO) waits
until another Python thread writes into it, which it can do only while the call has the
interpreter released. A call that kept it would wait forever, so a watchdog (faulthandler,
which needs no interpreter) ends the process after a minute instead of hanging CI."""

import faulthandler
import os
import sys
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import wheelrail

pytestmark = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")


def call_reading_a_pipe(call, pipe, text):
    """Runs `call` (which opens `pipe` for reading) in a thread and writes `text` into the
    pipe from this one; returns what `call` returned."""
    out = {}
    reader = threading.Thread(target=lambda: out.setdefault("value", call()))
    faulthandler.dump_traceback_later(60, exit=True)
    try:
        reader.start()
        with open(pipe, "w") as f:  # blocks until the call opens the pipe, then writes
            f.write(text)
        reader.join()
    finally:
        faulthandler.cancel_dump_traceback_later()
    return out["value"]


def test_run_releases_the_interpreter_while_it_reads_and_computes(root, tmp_path):
    pipe = tmp_path / "scene.toml"
    os.mkfifo(pipe)
    text = (root / "reports/paper/scene.toml").read_text()
    r = call_reading_a_pipe(lambda: wheelrail.run(pipe, stages=["rigid"]), pipe, text)
    assert len(r.tables["rigid"]["y_ws_mm"]) == 301


def test_read_profile_releases_the_interpreter(root, tmp_path):
    pipe = tmp_path / "wheel.csv"
    os.mkfifo(pipe)
    text = (root / "profiles/s1002.csv").read_text()
    p = call_reading_a_pipe(lambda: wheelrail.read_profile(pipe), pipe, text)
    assert np.array_equal(p["s_mm"], wheelrail.read_profile(root / "profiles/s1002.csv")["s_mm"])


def test_a_thread_pool_gives_the_results_of_one_thread(root):
    scenes = [root / "reports/paper/scene.toml", root / "reports/en15302_e1/scene.toml"] * 2
    alone = [wheelrail.run(s).tables["equivalent_conicity"] for s in scenes]
    with ThreadPoolExecutor(max_workers=4) as pool:
        pooled = list(pool.map(lambda s: wheelrail.run(s).tables["equivalent_conicity"], scenes))
    for a, b in zip(alone, pooled):
        for name in a:
            np.testing.assert_array_equal(a[name], b[name])
