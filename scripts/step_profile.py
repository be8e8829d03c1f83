#!/usr/bin/python3
"""Tables of step profiles: what `walkers evaluate --profile-summary FILE` wrote, one file a genome.

For each genome and walking state (DS, LS, RS) with ticks: the ticks, CVODE steps per tick (mean
and median), rejected attempts per tick (error test, Newton), the mean step, the three components
that limit the most steps with their shares, and the contact pairs, contact springs and joint
stops switched per tick (docs/step_profile.md).

  step_profile.py SUMMARY.json... [--markdown OUT]

The genome's name is the file's name without .json. Exits 2 on bad input, naming the file.
"""

import argparse
import json
import os
import sys

STATES = ["DS", "LS", "RS"]


def rows(name, summary):
    """The table's rows for one genome's summary."""
    out = []
    for state in STATES:
        s = summary[state]
        ticks = s["ticks"]
        if ticks == 0:
            continue
        limiting = s["limiting"]
        steps = sum(limiting.values()) or 1
        top = sorted(limiting.items(), key=lambda kv: -kv[1])[:3]
        out.append([name, state, str(ticks), f"{s['steps_per_tick']['mean']:.0f}",
                    f"{s['steps_per_tick']['median']:.0f}", f"{s['error_test_failures'] / ticks:.1f}",
                    f"{s['nonlinear_failures'] / ticks:.1f}", f"{1e3 * s['step']['mean']:.3f}",
                    ", ".join(f"{k} {100 * v / steps:.0f} %" for k, v in top),
                    f"{s['pair_switches']['per_tick']:.2f}", f"{s['spring_switches']['per_tick']:.1f}",
                    f"{s['stop_switches']['per_tick']:.2f}"])
    return out


HEADER = ["genome", "state", "ticks", "steps/tick", "median", "error-test fails/tick", "Newton fails/tick",
          "mean step [ms]", "limiting components (share of steps)", "pair switches/tick", "spring switches/tick",
          "stop switches/tick"]


def table(files):
    lines = ["| " + " | ".join(HEADER) + " |", "|" + "---|" * len(HEADER)]
    for path in files:
        with open(path) as f:
            summary = json.load(f)
        name = os.path.splitext(os.path.basename(path))[0]
        try:
            lines += ["| " + " | ".join(r) + " |" for r in rows(name, summary)]
        except (KeyError, TypeError, ZeroDivisionError) as e:
            raise ValueError(f"{path}: not a step profile summary (missing {e})")
    return "\n".join(lines) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("summaries", nargs="+", help="files of walkers evaluate --profile-summary")
    parser.add_argument("--markdown", help="also write the table to this file")
    args = parser.parse_args(argv)
    try:
        text = table(args.summaries)
    except (OSError, ValueError) as e:
        print(f"step_profile.py: {e}", file=sys.stderr)
        return 2
    print(text, end="")
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
