"""The cut-offs' share: the evaluations that scored load.CUT_OFF_FITNESS (-124), as a share
of each case's evaluations, by block of BLOCK generations and over the whole run, for
each experiment (experiments.py) that has a cut-off: the authors' (past 25 s of wall
clock: their summarisedOutput files, authors.py) and ours under a budget of right-hand
sides (program.evaluation.cut_off_rhs: each run's evaluations.csv, or its cut_offs.csv
where that is not kept). Ours on CVODE have none.

`run_counts` and `write_run` make a run's cut_offs.csv from its evaluations.csv, so that
results committed without the per-evaluation data keep their cut-offs
(scripts/stage_results.sh, by `walkers_stats cut-offs`).
"""
import os

import numpy as np

from . import experiments
from .load import (CUT_OFFS_COLUMNS, CUT_OFFS_FILE, MANIFEST, InputError, count, count_cut_offs,
                   field, load_generations, read_json)
from .text import fmt_percent, write_atomically

BLOCK = 500
THEIR_CUT_OFF = "past 25 s of wall clock"


def blocks(cut_offs, evaluations):
    """[{first, last, cut_offs, evaluations}] of each block of BLOCK generations and of
    the whole run ("first": 0, "last": the last generation, as the final entry), from
    counts per generation summed over a case's runs."""
    n = len(cut_offs)
    spans = [(g, min(g + BLOCK, n) - 1) for g in range(0, n, BLOCK)] + [(0, n - 1)]
    return [{"first": a, "last": b, "cut_offs": int(cut_offs[a:b + 1].sum()),
             "evaluations": int(evaluations[a:b + 1].sum())} for a, b in spans]


def summed(per_run):
    """[(cut-offs, evaluations) per generation of each run] -> their sums per
    generation, over the generations every run has."""
    n = min(len(c) for c, _ in per_run)
    return sum(c[:n] for c, _ in per_run), sum(e[:n] for _, e in per_run)


def theirs(authors, scaffolds):
    """The authors' entry: per case, their children's cut-offs by block."""
    cases = {}
    for s in scaffolds:
        per_run = authors["children"].get(s["number"])
        if per_run:
            cases[s["name"]] = {"runs": len(per_run), "unrecorded": [],
                                "blocks": blocks(*summed(per_run))}
    return {"experiment": experiments.AUTHORS.id, "label": experiments.AUTHORS.label,
            "cut_off": THEIR_CUT_OFF, "cases": cases}


def ours(rep):
    """A reproduction's entry: without a cut-off, none; with one, per case the cut-offs
    of the runs that recorded them (and the runs that did not)."""
    experiment = experiments.of_reproduction(rep)
    entry = {"experiment": experiment.id, "label": experiment.label, "cut_off": None, "cases": {}}
    if not rep["cut_off_rhs"]:
        entry["note"] = (f"none: its runs were made without one ({MANIFEST} sets no "
                         "program.evaluation.cut_off_rhs)")
        return entry
    entry["cut_off"] = f"past {rep['cut_off_rhs']:,} right-hand sides"
    for s in rep["scaffolds"]:
        runs = [r for r in rep["primary"] if r["case"] == s["name"]]
        recorded = [r for r in runs if r["cut_offs"] is not None]
        if not runs:
            continue
        case = {"runs": len(recorded), "blocks": None,
                "unrecorded": [r["dir"] for r in runs if r["cut_offs"] is None]}
        if recorded:
            # every generation evaluates the population
            case["blocks"] = blocks(*summed([(r["cut_offs"], np.full(len(r["cut_offs"]),
                                                                     rep["population"]))
                                             for r in recorded]))
        entry["cases"][s["name"]] = case
    return entry


def compare(reps, authors):
    """The block "cut_offs": the authors' entry (given their checkout) and one for each
    loaded reproduction of `reps`."""
    scaffolds = reps[0]["scaffolds"]
    return {"block": BLOCK,
            "note": None if authors is not None else
            experiments.AUTHORS_MISSING,
            "experiments": ([theirs(authors, scaffolds)] if authors is not None else []) +
                           [ours(rep) for rep in reps]}


def sentence(label):
    """A label that opens a sentence: its first letter capital."""
    return label[:1].upper() + label[1:]


def markdown(block, scaffolds):
    """The section "The cut-offs" of summary.md (or of the experiments' page)."""
    lines = ["## The cut-offs", "",
             "Evaluations cut off (fitness −124) as a share of each case's evaluations, by block "
             f"of {block['block']} generations and over the whole run: the authors' "
             f"{THEIR_CUT_OFF} (every child's fitness in their `summarisedOutput` files), ours "
             "past a budget of right-hand sides (each run's `evaluations.csv`).", ""]
    if block["note"]:
        lines += [f"*Note: {block['note']}.*", ""]
    # one table for each set of blocks (experiments of other lengths have other blocks)
    tables = {}
    for s in scaffolds:
        for e in block["experiments"]:
            c = e["cases"].get(s["name"])
            if e["cut_off"] is None or c is None or c["blocks"] is None:
                continue
            cells = [fmt_percent(b["cut_offs"] / b["evaluations"]) if b["evaluations"] else "—"
                     for b in c["blocks"]]
            spans = tuple((b["first"], b["last"]) for b in c["blocks"])
            tables.setdefault(spans, []).append(
                f"| {s['number']}, {s['label']}: {e['label']} ({c['runs']} runs) | "
                f"{e['cut_off']} | " + " | ".join(cells) + " |")
    for spans, rows in tables.items():
        lines += ["| case | cut off | " + " | ".join(f"{a}–{b}" for a, b in spans[:-1]) +
                  " | all |", "|---|---|" + "---|" * len(spans)] + rows + [""]
    for e in block["experiments"]:
        if e["cut_off"] is None:
            lines.append(f"- {sentence(e['label'])}: {e['note']}.")
        unrecorded = [d for c in e["cases"].values() for d in c["unrecorded"]]
        if unrecorded:
            lines.append(f"- {sentence(e['label'])}: no cut-offs recorded for "
                         f"{', '.join(unrecorded)} (neither evaluations.csv nor {CUT_OFFS_FILE}).")
    return "\n".join(lines).rstrip("\n") + "\n"


def run_cut_off(run_dir):
    """The right-hand sides past which a run's evaluations were cut off (its config.json's
    evaluation.cut_off_rhs), 0 for none."""
    path = os.path.join(run_dir, "config.json")
    evaluation = field(read_json(path, required=True), "evaluation", path, "", dict)
    return count(evaluation, "cut_off_rhs", path, "evaluation.", 0, 2 ** 62) \
        if "cut_off_rhs" in evaluation else 0


def run_counts(run_dir):
    """The children cut off at each generation of a run's generations.csv, counted in
    its evaluations.csv."""
    evaluations = os.path.join(run_dir, "evaluations.csv")
    if not os.path.isfile(evaluations):
        raise InputError(f"{evaluations}: file not found")
    generations = len(load_generations(os.path.join(run_dir, "generations.csv"))["generation"])
    return count_cut_offs(evaluations, generations)


def write_run(run_dir, counts):
    """RUN_DIR/cut_offs.csv of run_counts's counts; returns its path."""
    path = os.path.join(run_dir, CUT_OFFS_FILE)
    write_atomically(path, ",".join(CUT_OFFS_COLUMNS) + "\n" +
                     "".join(f"{g},{k}\n" for g, k in enumerate(counts)))
    return path
