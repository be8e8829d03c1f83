#!/usr/bin/python3
"""The accuracy criterion of docs/performance.md ("Accuracy"), with its statistical test.

Reads what `build/bench/accuracy --json FILE ...` wrote (for every genome an ensemble at the
production settings and one at 100x tighter tolerances) and judges each genome:

- regular: the tight ensemble's interquartile range is under 2 % of its median (of 1 when the
  median is smaller than 1); then the two medians must agree within 1 %;
- otherwise the two ensembles must not be distinguishable: a two-sample Kolmogorov-Smirnov
  test (SciPy) with p > 0.05, or the production median inside the tight interquartile range;
- and always: the majority's gait class and fall verdict agree;
- no lost walker: a genome whose tight median is >= 5 (a walker) must not have a production
  majority (more than half its members) <= 1 (a walker that went nowhere);
- no numerical walker: nor a production majority >= 5 while the tight median is <= 1.

  accuracy.py FILE.json [--markdown OUT]

Prints one line per genome and the verdict; exits 0 when every genome passes, 1 when one does
not, 2 on bad input.
"""

import argparse
import json
import statistics
import sys

import numpy
from scipy import stats

REGULAR_IQR = 0.02  # of the tight median
REGULAR_MEDIANS = 0.01  # relative
KS_ALPHA = 0.05
WALKER = 5.0  # a walker's fitness, at least (control/accuracy.h kWalkerFitness)
NON_WALKER = 1.0  # a walker that went nowhere, at most (kNonWalkerFitness)


def relative_difference(value, reference):
    return abs(value - reference) / max(1.0, abs(reference))


def quartiles(values):
    return tuple(float(q) for q in numpy.quantile(values, [0.25, 0.75]))  # linear, as control/accuracy.cc


def majority(count, size):
    return 2 * count > size


def judge(genome):
    """The verdict for one genome of the accuracy tool's JSON: a dict of what was tested."""
    production, tight = genome["production"], genome["tight"]
    a, b = production["fitness"], tight["fitness"]
    if not a or not b:
        raise ValueError(f"{genome.get('genome', '?')}: an ensemble is empty")
    tight_median = statistics.median(b)
    low, high = quartiles(b)
    regular = high - low < REGULAR_IQR * max(1.0, abs(tight_median))
    difference = relative_difference(statistics.median(a), tight_median)
    verdict = {
        "genome": genome["genome"],
        "median": statistics.median(a),
        "tight_median": tight_median,
        "tight_iqr": [low, high],
        "regular": regular,
        "median_difference": difference,
        "ks_p": None,
    }
    if regular:
        fitness_agrees = difference < REGULAR_MEDIANS
    else:
        inside = low <= statistics.median(a) <= high
        # identical ensembles (e.g. every member falls) are indistinguishable by definition
        verdict["ks_p"] = 1.0 if sorted(a) == sorted(b) else float(stats.ks_2samp(a, b).pvalue)
        fitness_agrees = inside or verdict["ks_p"] > KS_ALPHA
    gait = all(
        majority(production[k], len(a)) == majority(tight[k], len(b)) for k in ("bipeds", "tripods")
    )
    fall = majority(production["falls"], len(a)) == majority(tight["falls"], len(b))
    # a walk made or broken by the integration error
    lost = tight_median >= WALKER and majority(sum(f <= NON_WALKER for f in a), len(a))
    numerical = tight_median <= NON_WALKER and majority(sum(f >= WALKER for f in a), len(a))
    verdict.update(fitness_agrees=fitness_agrees, gait_agrees=gait, fall_agrees=fall,
                   lost_walker=lost, numerical_walker=numerical,
                   passes=fitness_agrees and gait and fall and not lost and not numerical,
                   steps_median=production.get("steps_median"), wall_ms_median=production.get("wall_ms_median"))
    return verdict


def markdown(data, verdicts):
    lines = [
        f"Settings: {data['settings']} (rtol {data['relative_tolerance']:g}, atol_q "
        f"{data['absolute_tolerance_position']:g}, atol_v {data['absolute_tolerance_velocity']:g}); "
        f"ensembles of {data['ensemble']} against 100x tighter tolerances.",
        "",
        "| genome | median | tight: median [IQR] | regular | medians differ | KS p | gait, fall | walker | passes "
        "| steps | ms |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for v in verdicts:
        ks = "—" if v["ks_p"] is None else f"{v['ks_p']:.3f}"
        lines.append(
            f"| {v['genome']} | {v['median']:.3f} | {v['tight_median']:.3f} [{v['tight_iqr'][0]:.3f}, "
            f"{v['tight_iqr'][1]:.3f}] | {'yes' if v['regular'] else 'no'} | {100 * v['median_difference']:.2f} % | "
            f"{ks} | {'agree' if v['gait_agrees'] and v['fall_agrees'] else 'DIFFER'} | "
            f"{'LOST' if v['lost_walker'] else 'NUMERICAL' if v['numerical_walker'] else 'kept'} | "
            f"{'yes' if v['passes'] else '**no**'} | {v['steps_median']:.0f} | {v['wall_ms_median']:.1f} |")
    passed = sum(v["passes"] for v in verdicts)
    lines += ["", f"{passed} of {len(verdicts)} genomes pass; median {statistics.median(v['steps_median'] for v in verdicts):.0f} "
              f"steps and {statistics.median(v['wall_ms_median'] for v in verdicts):.1f} ms per evaluation."]
    return "\n".join(lines) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("json", help="output of build/bench/accuracy --json")
    parser.add_argument("--markdown", help="also write the table as Markdown")
    args = parser.parse_args(argv)
    try:
        with open(args.json) as f:
            data = json.load(f)
        verdicts = [judge(g) for g in data["genomes"]]
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"accuracy.py: {args.json}: {e!r}", file=sys.stderr)
        return 2
    table = markdown(data, verdicts)
    print(table, end="")
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(table)
    return 0 if all(v["passes"] for v in verdicts) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
