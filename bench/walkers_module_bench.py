#!/usr/bin/env python3
"""Evaluations per second from Python (the module walkers, python/) against the
command line, on 16 genomes: the 9 of data/genomes/bench/ and the first 7 of
data/genomes/authors/ (docs/python.md, "Speed").

  PYTHONPATH=build/python /usr/bin/python3 bench/walkers_module_bench.py [--rounds 3]

Each way evaluates the 16 once a round; the table gives the median round. The
evaluations' own time is the sum of the wall_ms that walkers.evaluate reports
(the time inside the C++ evaluation); over N threads, that sum divided by N is
the least any batch of them can take, the bound a batch is compared with. The
same batch in C++ (evaluation_bench's Batch/16_genomes_2_threads, one iteration
a round, its own timing) is timed in the same rounds, and the script ends with
evaluate_batch's time over the C++ batch's, round by round.
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import time

import numpy as np

import walkers

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[1]


def genome_files():
    bench = sorted((SOURCE_DIR / "data/genomes/bench").glob("*.json"))
    authors = sorted((SOURCE_DIR / "data/genomes/authors").glob("*.json"))[:7]
    return bench + authors


def cpp_batch(program):
    """One run of evaluation_bench's Batch/16_genomes_2_threads: its wall time [s]."""
    out = subprocess.run([program, "--benchmark_filter=^Batch/", "--benchmark_format=json"], check=True,
                         capture_output=True, text=True).stdout
    (run,) = json.loads(out)["benchmarks"]
    assert run["time_unit"] == "ms", run["time_unit"]
    return run["real_time"] / 1000


def timed(work):
    start = time.perf_counter()
    out = work()
    return time.perf_counter() - start, out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--program", default=str(SOURCE_DIR / "build/app/walkers"), help="the walkers program")
    parser.add_argument("--evaluation-bench", default=str(SOURCE_DIR / "build/bench/evaluation_bench"),
                        help="the C++ benchmark whose Batch/16_genomes_2_threads is the same batch without Python")
    args = parser.parse_args()
    files = genome_files()
    rows = np.stack([walkers.genome_array(str(f)) for f in files])
    n = len(files)

    ways = {
        "walkers evaluate --json, a process per genome": lambda: [
            json.loads(subprocess.run([args.program, "evaluate", "--genome", str(f), "--json"], check=True,
                                      capture_output=True, text=True).stdout) for f in files],
        "walkers.evaluate, one by one": lambda: [walkers.evaluate(str(f)) for f in files],
        "walkers.evaluate_batch, 1 thread": lambda: walkers.evaluate_batch(rows, threads=1),
        "walkers.evaluate_batch, 2 threads": lambda: walkers.evaluate_batch(rows, threads=2),
        "C++, the same batch on 2 threads (evaluation_bench)": lambda: cpp_batch(args.evaluation_bench),
    }
    seconds = {way: [] for way in ways}
    inside = []  # the evaluations' own time a round [s]
    for _ in range(args.rounds):
        for way, work in ways.items():
            t, out = timed(work)
            if way.startswith("C++"):
                t = out  # the benchmark's own timing, without the process's start
            seconds[way].append(t)
            if way == "walkers.evaluate, one by one":
                inside.append(sum(r["wall_ms"] for r in out) / 1000)
    own = statistics.median(inside)
    print(f"{n} genomes, median of {args.rounds} rounds; the evaluations' own time {own:.2f} s")
    print("| way | wall time [s] | evaluations/s | over the least it can take |")
    print("|---|---|---|---|")
    for way, ts in seconds.items():
        t = statistics.median(ts)
        threads = 2 if "2 threads" in way else 1
        print(f"| {way} | {t:.2f} | {n / t:.1f} | {t / (own / threads):.3f} |")
    # the batch from Python against the same batch in C++, round by round (the same moment's machine)
    ratios = [p / c for p, c in zip(seconds["walkers.evaluate_batch, 2 threads"],
                                    seconds["C++, the same batch on 2 threads (evaluation_bench)"])]
    print(f"evaluate_batch on 2 threads over the C++ batch: median {statistics.median(ratios):.3f} "
          f"(rounds: {', '.join(f'{r:.3f}' for r in ratios)})")


if __name__ == "__main__":
    main()
