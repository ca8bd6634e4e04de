"""Times `wheelrail.run` on the paper's scene, to compare with the Rust benchmark
`cargo bench --bench scene -- paper_scene_tables` (the same work without the conversion to
NumPy). Run from the repository root after `pip install ./python`:

    python python/benchmarks/run_overhead.py [RUNS]

Prints the median and the quartiles of RUNS calls (default 200) after 10 untimed ones.
"""

import statistics
import sys
import timeit

import wheelrail

SCENE = "reports/paper/scene.toml"


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    for _ in range(10):
        wheelrail.run(SCENE)
    times = timeit.repeat(lambda: wheelrail.run(SCENE), number=1, repeat=runs)
    q1, median, q3 = statistics.quantiles(times, n=4)
    print(
        f"wheelrail.run({SCENE!r}): median {1e3 * median:.3f} ms "
        f"(quartiles {1e3 * q1:.3f} to {1e3 * q3:.3f} ms, {runs} runs)"
    )


if __name__ == "__main__":
    main()
