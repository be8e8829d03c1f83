"""The authors' own runs beside ours.

Their repository (github.com/jhuizhu/bipedalism-scaffolded-learning) is not part of this
project: the user names a checkout of it (`walkers reproduce --authors-checkout PATH`, or
`--authors PATH` of this package's summary and figures), and only the numbers compared
enter our files.

CHECKOUT/CaseData/image/fitness-data/caseN-M.txt holds run M of the paper's case N: the
generations at which the run's best fitness improved, one a line (each but the last
ending in a comma), a line "count: K", then the K best fitnesses likewise and "count: K"
again. A generation's best fitness is that of the last improvement at or before it; a
run has paper.GENERATIONS generations, numbered from 0.
"""
import glob
import math
import os
import re

import numpy as np

from . import paper
from .load import InputError, of_case, paper_cases
from .statistics import bootstrap_interval, mean_and_sd, ratio_of_means, reported_generations, \
    share_leading

FITNESS_DATA = os.path.join("CaseData", "image", "fitness-data")
RUN_FILE = re.compile(r"case(\d+)-(\d+)\.txt")


def read_run(path):
    """One run's file -> its best fitness per generation (paper.GENERATIONS values)."""
    with open(path, encoding="utf-8") as f:
        lines = [line.strip() for line in f]
    counts = [i for i, line in enumerate(lines) if line.startswith("count:")]
    if len(counts) != 2:
        raise InputError(f"{path}: expected two 'count: K' lines, found {len(counts)}")

    def column(first, end, kind, what):
        """The values of lines [first, end), each as `kind`, and the count line's K."""
        values = []
        for i in range(first, end):
            text = lines[i].rstrip(",").strip()
            if not text:
                continue
            try:
                values.append(kind(text))
            except ValueError:
                raise InputError(f"{path}: line {i + 1}: '{lines[i]}' is not {what}") from None
        try:
            k = int(lines[end].split(":", 1)[1])
        except ValueError:
            raise InputError(f"{path}: line {end + 1}: '{lines[end]}' is not 'count: K'") from None
        if k != len(values):
            raise InputError(f"{path}: line {end + 1} says {k} values, the lines above hold "
                             f"{len(values)}")
        return values

    generations = column(0, counts[0], int, "a generation")
    fitness = column(counts[0] + 1, counts[1], float, "a fitness")
    if len(generations) != len(fitness) or not generations:
        raise InputError(f"{path}: {len(generations)} generations but {len(fitness)} fitnesses")
    if generations[0] != 0 or any(b < a for a, b in zip(generations, generations[1:])) or \
            generations[-1] >= paper.GENERATIONS:
        raise InputError(f"{path}: the generations must rise from 0 and stay below "
                         f"{paper.GENERATIONS}")
    if not all(math.isfinite(f) for f in fitness):
        raise InputError(f"{path}: a fitness is not a finite number")
    # each improvement holds from its generation on; of two at one generation the later
    curve = np.empty(paper.GENERATIONS)
    for g, f in zip(generations, fitness):
        curve[g:] = f
    return curve


def load_authors(checkout):
    """{"checkout": path, "runs": {case number: [best fitness per generation of each
    run, by run number]}}; InputError naming the path when there is nothing to read."""
    folder = os.path.join(checkout, FITNESS_DATA)
    if not os.path.isdir(folder):
        raise InputError(f"{checkout}: no {FITNESS_DATA}/ (a checkout of "
                         "github.com/jhuizhu/bipedalism-scaffolded-learning has it)")
    found = {}
    for path in glob.glob(os.path.join(folder, "case*-*.txt")):
        match = RUN_FILE.fullmatch(os.path.basename(path))
        if match:
            found.setdefault(int(match[1]), []).append((int(match[2]), path))
    if not found:
        raise InputError(f"{folder}: no run files caseN-M.txt")
    return {"checkout": checkout,
            "runs": {case: [read_run(path) for _, path in sorted(files)]
                     for case, files in sorted(found.items())}}


def describe(authors):
    """'9 runs of the authors: case 1: 3, case 2: 3, case 3: 3' """
    runs = authors["runs"]
    return (f"{sum(len(r) for r in runs.values())} runs of the authors: " +
            ", ".join(f"case {case}: {len(r)}" for case, r in runs.items()))


def at_generation(curves, g):
    """The values of the curves (replicates x generations) at generation g; None when
    they end before it."""
    return None if curves.shape[1] <= g else curves[:, g]


def compare(rep, authors, ours_share):
    """The block "beside_authors" of summary.json: per case and reported generation our
    mean best fitness with its 95 % interval beside the authors' mean and whether theirs
    lies inside; the share of generations in which case 3 leads case 1 (ours:
    `ours_share`, the claim's) and case 2's final as a share of case 1's (the fitness
    the runs recorded, as theirs are), theirs and ours. `authors` is load_authors's,
    or None (then the note says why theirs are missing)."""
    theirs_by_case = {}
    if authors is not None:
        for s in rep["scaffolds"]:
            if s["number"] in authors["runs"]:
                theirs_by_case[s["name"]] = np.array(authors["runs"][s["number"]])
    ours_by_case = {s["name"]: of_case(rep["primary"], s["name"]) for s in rep["scaffolds"]}
    ours_curves = {}
    for case, runs in ours_by_case.items():
        if runs:
            n = min(len(r["data"]["best_fitness"]) for r in runs)
            ours_curves[case] = np.array([r["data"]["best_fitness"][:n] for r in runs])
    # the generations: the paper's and our last, each numbered from 0
    generations = sorted(set(reported_generations(paper.GENERATIONS - 1)) |
                         {c.shape[1] - 1 for c in ours_curves.values()})
    rows = []
    for s in rep["scaffolds"]:
        case = s["name"]
        for g in generations:
            row = {"case": case, "generation": g, "ours": None, "authors": None, "inside": None}
            values = at_generation(ours_curves[case], g) if case in ours_curves else None
            if values is not None:
                mean, sd = mean_and_sd(values)
                interval = bootstrap_interval((values,), np.mean)
                row["ours"] = {"mean": mean, "sd": sd, "runs": len(values),
                               "interval": None if interval is None else list(interval)}
            theirs = at_generation(theirs_by_case[case], g) if case in theirs_by_case else None
            if theirs is not None:
                row["authors"] = {"mean": float(np.mean(theirs)), "runs": len(theirs)}
            if row["ours"] and row["authors"] and row["ours"]["interval"]:
                low, high = row["ours"]["interval"]
                row["inside"] = bool(low <= row["authors"]["mean"] <= high)
            if row["ours"] or row["authors"]:
                rows.append(row)

    c1, c2, c3 = paper_cases(rep["scaffolds"])

    def recorded_ratio(curves_by_case):
        """case 2's final mean best over case 1's, from curves; None without both."""
        if c1 not in curves_by_case or c2 not in curves_by_case:
            return None
        return float(ratio_of_means(curves_by_case[c2][:, -1], curves_by_case[c1][:, -1]))

    def curves_share(curves_by_case):
        """the share of generations in which case 3's mean leads case 1's; None without both."""
        if c1 not in curves_by_case or c3 not in curves_by_case:
            return None
        return share_leading(curves_by_case[c3], curves_by_case[c1])

    return {"checkout": None if authors is None else authors["checkout"],
            "note": None if authors is not None else
            "the authors' runs are missing: no checkout of their repository was named "
            "(walkers reproduce --authors-checkout PATH)",
            "at_generations": rows,
            "case3_leads_share": {"ours": ours_share, "authors": curves_share(theirs_by_case),
                                  "paper": paper.CASE3_LEADS_SHARE},
            "case2_over_case1_final": {"ours": recorded_ratio(ours_curves),
                                       "authors": recorded_ratio(theirs_by_case),
                                       "paper": paper.CASE2_OVER_CASE1}}
