#!/usr/bin/python3
"""Two builds' evaluation speed side by side, in one run on one machine.

Runs the `evaluation_bench` programs of two builds alternately, round after round, so that
both see the same load (one evaluation per benchmark per round), and prints per genome the
median CPU time of each over the rounds and their ratio,
then the median over the genomes (docs/performance.md, "Against an earlier commit").

  speed_compare.py --baseline OLD/build/bench/evaluation_bench \
                   --candidate build/bench/evaluation_bench [--filter 'Genome/'] [--rounds 5] [--json OUT]

Both programs must register the same benchmark names (an older commit is built with this
commit's bench/evaluation_bench.cc and bench/genome_set.h copied in).
"""

import argparse
import json
import statistics
import subprocess
import sys


def run(binary, name_filter):
    """{benchmark name: (cpu ms, CVODE steps)} of one run of the program: one evaluation per
    benchmark, as the rounds give the repetitions."""
    out = subprocess.run([binary, f"--benchmark_filter={name_filter}", "--benchmark_format=json",
                          "--benchmark_min_time=0.001"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"speed_compare: {binary} failed ({out.returncode}): {out.stderr.strip()[:500]}")
    times = {}
    for b in json.loads(out.stdout)["benchmarks"]:
        scale = {"ms": 1.0, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b["time_unit"]]
        # an older build's evaluation_bench names the steps "cvode_steps"
        times[b["name"]] = (b["cpu_time"] * scale, b.get("steps", b.get("cvode_steps")))
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline", required=True, help="the earlier build's evaluation_bench")
    parser.add_argument("--candidate", required=True, help="this build's evaluation_bench")
    parser.add_argument("--filter", default="Genome/", help="Google Benchmark filter (default: every genome)")
    parser.add_argument("--rounds", type=int, default=5, help="alternating runs of each (default 5)")
    parser.add_argument("--json", help="write every figure to this file")
    args = parser.parse_args()
    if args.rounds < 1:
        sys.exit("speed_compare: --rounds must be at least 1")

    samples = {"baseline": {}, "candidate": {}}
    steps = {"baseline": {}, "candidate": {}}
    for r in range(args.rounds):
        for which in ("baseline", "candidate") if r % 2 == 0 else ("candidate", "baseline"):
            for name, (ms, s) in run(getattr(args, which), args.filter).items():
                samples[which].setdefault(name, []).append(ms)
                steps[which][name] = s
        print(f"round {r + 1} of {args.rounds} done", file=sys.stderr)

    names = sorted(set(samples["baseline"]) & set(samples["candidate"]))
    if not names:
        sys.exit(f"speed_compare: no benchmark matched {args.filter!r} in both programs")
    rows = []
    print(f"{'benchmark':48} {'baseline ms':>12} {'candidate ms':>12} {'speed-up':>9} {'steps':>15}")
    for name in names:
        old, new = statistics.median(samples["baseline"][name]), statistics.median(samples["candidate"][name])
        rows.append({"name": name, "baseline_ms": old, "candidate_ms": new, "speedup": old / new,
                     "baseline_steps": steps["baseline"][name], "candidate_steps": steps["candidate"][name]})
        step_text = f"{steps['baseline'][name] or 0:.0f}/{steps['candidate'][name] or 0:.0f}"
        print(f"{name:48} {old:12.1f} {new:12.1f} {old / new:8.2f}x {step_text:>15}")
    old_median = statistics.median(r["baseline_ms"] for r in rows)
    new_median = statistics.median(r["candidate_ms"] for r in rows)
    print(f"{'median over the ' + str(len(rows)) + ' benchmarks':48} {old_median:12.1f} {new_median:12.1f} "
          f"{old_median / new_median:8.2f}x")
    print(f"median of the per-benchmark speed-ups: {statistics.median(r['speedup'] for r in rows):.2f}x")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"rounds": args.rounds, "filter": args.filter, "benchmarks": rows,
                       "baseline_median_ms": old_median, "candidate_median_ms": new_median}, f, indent=1)


if __name__ == "__main__":
    main()
