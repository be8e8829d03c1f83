#!/usr/bin/python3
"""Samples genomes from evolution runs, uniformly over their generations, reproducibly.

For each run folder (written by `walkers evolve`, finished or stopped), the generations 0..G
that its last checkpoint covers (evaluations.csv up to checkpoint.json's evaluations_bytes) are
cut into N strata of equal width; one generation is drawn in each stratum and one child of it
(every evaluation of it: walkers, fallers, tripods alike), with Python's random.Random(seed) in
the order the runs are given. Each draw is written as a genome file
RUN_NAME_gGENERATION_cCHILD.json; the genes come from evaluations.csv, the keys it does not hold
(the fixed masses) from the checkpoint's archive. index.csv lists every file with its run,
generation, child and what the run recorded for it.

  sample_genomes.py --per-run N --seed S --out DIR RUN...

Exits 0 on success, 2 on bad input (the message names the file, the row and the column).
"""

import argparse
import csv
import io
import json
import math
import os
import random
import sys

# the columns of evaluations.csv that are not genes (evolve/run.cc EvaluationsHeader)
ID_COLUMNS = ["generation", "child", "parents"]
RESULT_COLUMNS = ["fitness", "distance", "fell", "gait", "footsteps", "trunk_contact_fraction", "cvode_steps",
                  "failure", "wall_ms"]
INDEX_COLUMNS = ["file", "case", "run", "generation", "child", "recorded_fitness", "recorded_gait", "fell"]


class InputError(Exception):
    pass


def read_run(run):
    """(case, genes, rows): the run's case, gene names and evaluation rows as dicts."""
    config_path = os.path.join(run, "config.json")
    evaluations_path = os.path.join(run, "evaluations.csv")
    checkpoint_path = os.path.join(run, "checkpoint.json")
    try:
        with open(config_path) as f:
            case = json.load(f)["case"]
        with open(checkpoint_path) as f:
            checkpoint = json.load(f)
        size = checkpoint["evaluations_bytes"]
        best = checkpoint["archive"][0]["genome"]
        # rows past the checkpoint belong to a generation the run did not finish
        with open(evaluations_path, "rb") as f:
            text = f.read(size).decode()
    except (OSError, ValueError, KeyError, IndexError, TypeError) as e:
        raise InputError(f"{run}: {e!r}")
    reader = csv.DictReader(io.StringIO(text, newline=""))
    header = reader.fieldnames or []
    rows = list(reader)
    missing = [c for c in ID_COLUMNS + RESULT_COLUMNS if c not in header]
    if missing:
        raise InputError(f"{evaluations_path}: no column {missing[0]!r}")
    genes = [c for c in header if c not in ID_COLUMNS + RESULT_COLUMNS]
    unknown = [g for g in genes if g not in best]
    if unknown:
        raise InputError(f"{checkpoint_path}: the archive's genome has no gene {unknown[0]!r} (evaluations.csv has it)")
    if not rows:
        raise InputError(f"{evaluations_path}: no evaluations")
    fixed = {k: v for k, v in best.items() if k not in genes}
    return case, genes, fixed, rows


def number(row, column, path, line):
    try:
        x = float(row[column])
    except (TypeError, ValueError):
        raise InputError(f"{path}: row {line}, column {column!r}: {row[column]!r} is not a number")
    if not math.isfinite(x):
        raise InputError(f"{path}: row {line}, column {column!r}: {row[column]!r} is not finite")
    return x


def integer(row, column, path, line):
    x = number(row, column, path, line)
    if x != int(x) or x < 0:
        raise InputError(f"{path}: row {line}, column {column!r}: {row[column]!r} is not a whole number")
    return int(x)


def sample_run(run, per_run, rng):
    """The draws of one run: a list of (generation, child, row)."""
    case, genes, fixed, rows = read_run(run)
    path = os.path.join(run, "evaluations.csv")
    by_generation = {}
    for line, row in enumerate(rows, start=2):
        g, c = integer(row, "generation", path, line), integer(row, "child", path, line)
        for name in genes + ["fitness"]:
            number(row, name, path, line)  # every row checked, drawn or not
        by_generation.setdefault(g, []).append((c, line, row))
    last = max(by_generation)
    generations = last + 1
    if per_run > generations:
        raise InputError(f"{path}: {per_run} draws asked of {generations} generations")
    draws = []
    for k in range(per_run):
        # stratum k holds generations [k G / N, (k + 1) G / N)
        low, high = k * generations // per_run, (k + 1) * generations // per_run
        candidates = [g for g in range(low, high) if g in by_generation]
        if not candidates:
            raise InputError(f"{path}: no evaluations in generations {low}..{high - 1}")
        g = rng.choice(candidates)
        c, line, row = rng.choice(sorted(by_generation[g], key=lambda e: e[0]))
        genome = {name: number(row, name, path, line) for name in genes}
        genome.update(fixed)
        draws.append({"case": case, "generation": g, "child": c, "genome": genome,
                      "recorded_fitness": number(row, "fitness", path, line), "recorded_gait": row["gait"],
                      "fell": row["fell"]})
    return draws, last


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--per-run", type=int, required=True, help="genomes drawn from each run")
    parser.add_argument("--seed", type=int, required=True, help="seed of the draws")
    parser.add_argument("--out", required=True, help="folder for the genome files and index.csv")
    parser.add_argument("runs", nargs="+", help="run folders of walkers evolve")
    args = parser.parse_args(argv)
    if args.per_run < 1:
        parser.error("--per-run must be at least 1")
    rng = random.Random(args.seed)
    try:
        index = []
        os.makedirs(args.out, exist_ok=True)
        for run in args.runs:
            name = os.path.basename(os.path.normpath(run))
            draws, last = sample_run(run, args.per_run, rng)
            print(f"{run}: generations 0..{last}, {len(draws)} drawn")
            for d in draws:
                file = f"{name}_g{d['generation']}_c{d['child']}.json"
                with open(os.path.join(args.out, file), "w") as f:
                    json.dump(d["genome"], f, indent=2)
                    f.write("\n")
                index.append({"file": file, "case": d["case"], "run": name, "generation": d["generation"],
                              "child": d["child"], "recorded_fitness": repr(d["recorded_fitness"]),
                              "recorded_gait": d["recorded_gait"], "fell": d["fell"]})
        with open(os.path.join(args.out, "index.csv"), "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=INDEX_COLUMNS, lineterminator="\n")
            writer.writeheader()
            writer.writerows(index)
    except InputError as e:
        print(f"sample_genomes.py: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
