#!/usr/bin/python3
"""The instruction guard: one evaluation's instructions against the budget kept in the tree.

For each entry of the budget file (bench/instruction_budget.json) runs

  valgrind --tool=cachegrind --cache-sim=no WALKERS evaluate --genome GENOME ARGUMENTS...

and reads the instructions it executed (cachegrind's "I refs"). An entry fails when its count
exceeds its budget by more than 3 %. Instruction counts do not move with the machine's load, so
the guard does not flake; a change that makes an evaluation cheaper lowers the budget in the same
commit (--write). The budgets are those of a Release build by Debian 12's compiler.

  instruction_guard.py --walkers build/app/walkers [--budget FILE] [--source DIR] [--write]

The budget file: {"evaluations": [{"integrator": NAME, "genome": PATH (from the source folder),
"arguments": [extra arguments of walkers evaluate], "instructions": N}, ...]}, one entry per
integrator and genome.

Exits 0 when every count is within its budget, 1 when one is not, 2 on bad input or a failed
evaluation, and 77 (ctest's skip) when valgrind is not installed.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys

ALLOWED_EXCESS_PERCENT = 3  # over the budget
SKIP = 77
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class BadInput(Exception):
    pass


def load_budget(path, source):
    """The budget file's entries, each checked; BadInput names the file, the entry and the field."""
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        raise BadInput(f"{path}: {e}") from e
    entries = data.get("evaluations") if isinstance(data, dict) else None
    if not isinstance(entries, list) or not entries:
        raise BadInput(f"{path}: \"evaluations\" must be a non-empty list of entries")
    seen = set()
    for i, entry in enumerate(entries):
        where = f"{path}: evaluations[{i}]"
        if not isinstance(entry, dict):
            raise BadInput(f"{where} must be an object")
        for key in ("integrator", "genome"):
            if not isinstance(entry.get(key), str) or not entry[key]:
                raise BadInput(f"{where}: \"{key}\" must be a non-empty string")
        if not os.path.isfile(os.path.join(source, entry["genome"])):
            raise BadInput(f"{where}: genome {entry['genome']} is not a file under {source}")
        arguments = entry.get("arguments", [])
        if not isinstance(arguments, list) or not all(isinstance(a, str) for a in arguments):
            raise BadInput(f"{where}: \"arguments\" must be a list of strings")
        count = entry.get("instructions")
        if not isinstance(count, int) or isinstance(count, bool) or not 0 < count < 10**15:
            raise BadInput(f"{where}: \"instructions\" must be a whole number in 1..1e15, got {count!r}")
        key = (entry["integrator"], entry["genome"])
        if key in seen:
            raise BadInput(f"{where}: a second entry for integrator {key[0]} and genome {key[1]}")
        seen.add(key)
    return data, entries


def count_instructions(valgrind, walkers, genome, arguments):
    """The instructions one `walkers evaluate` executes under cachegrind."""
    command = [valgrind, "--tool=cachegrind", "--cache-sim=no", "--cachegrind-out-file=/dev/null",
               walkers, "evaluate", "--genome", genome, *arguments]
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        raise BadInput(f"{' '.join(command)} failed (exit {run.returncode}):\n{run.stderr[-2000:]}")
    found = re.search(r"I\s+refs:\s+([\d,]+)", run.stderr)
    if not found:
        raise BadInput(f"{' '.join(command)}: no \"I refs\" in cachegrind's output:\n{run.stderr[-2000:]}")
    return int(found.group(1).replace(",", ""))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--walkers", required=True, help="the walkers program (a Release build)")
    parser.add_argument("--budget", default=os.path.join(ROOT, "bench", "instruction_budget.json"))
    parser.add_argument("--source", default=ROOT, help="the folder the genomes' paths start from")
    parser.add_argument("--write", action="store_true",
                        help="set every budget to the count measured now (after a speed change)")
    args = parser.parse_args(argv)
    valgrind = shutil.which("valgrind")
    if valgrind is None:
        print("instruction_guard.py: valgrind is not installed (Debian: valgrind, which scripts/setup.sh --test "
              "installs): skipped")
        return SKIP
    try:
        if not os.access(args.walkers, os.X_OK):
            raise BadInput(f"--walkers {args.walkers}: not an executable program")
        data, entries = load_budget(args.budget, args.source)
        failed = 0
        for entry in entries:
            count = count_instructions(valgrind, args.walkers, os.path.join(args.source, entry["genome"]),
                                       entry.get("arguments", []))
            budget = entry["instructions"]
            excess = count / budget - 1
            ok = 100 * count <= (100 + ALLOWED_EXCESS_PERCENT) * budget  # exact, in integers
            failed += 0 if ok else 1
            name = os.path.splitext(os.path.basename(entry["genome"]))[0]
            if args.write:
                print(f"{entry['integrator']} {name}: {count:,} instructions, the budget was {budget:,}")
                entry["instructions"] = count
                continue
            print(f"{entry['integrator']} {name}: {count:,} instructions, budget {budget:,} ({100 * excess:+.2f} %; "
                  f"allowed up to +{ALLOWED_EXCESS_PERCENT} %): {'ok' if ok else 'OVER BUDGET'}")
            if 100 * count < (100 - ALLOWED_EXCESS_PERCENT) * budget:
                print(f"  {-100 * excess:.1f} % below its budget: lower the budget in the same commit "
                      f"(instruction_guard.py --write)")
    except BadInput as e:
        print(f"instruction_guard.py: {e}", file=sys.stderr)
        return 2
    if args.write:
        with open(args.budget, "w") as f:
            json.dump(data, f, indent=2)
            f.write("\n")
        print(f"wrote the counts to {args.budget}")
        return 0
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
