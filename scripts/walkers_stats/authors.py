"""The authors' own runs beside ours.

Their repository (github.com/jhuizhu/bipedalism-scaffolded-learning) is not part of this
project: the user names a checkout of it (`walkers reproduce --authors-checkout PATH`, or
`--authors PATH` of this package's summary and figures), and only the numbers compared
enter our files.

A checkout holds, for run M of the paper's case N:

  CaseData/image/fitness-data/caseN-M.txt  the generations at which the run's best fitness
      improved, one a line (each but the last ending in a comma), a line "count: K", then
      the K best fitnesses likewise and "count: K" again;
  CaseData/image/bump-data/cN_K.txt  the same improvements ("bumps"), each with the gait
      the authors gave the new best, in one of three layouts (read_labels); then
      "count: K". Their numbers K are not always the runs' M (case 3's 1 and 3 are
      swapped): a run's labels are the file whose bumps are its improvements;
  CaseData/caseN/summarisedOutput-<start time>  every child's fitness, generation by
      generation ("Generation: G", "Current Fitness:", then a list of the population's
      fitnesses; -124 for an evaluation cut off past 25 s of wall clock).

A generation's best fitness and gait are those of the last improvement at or before it; a
run has paper.GENERATIONS generations, numbered from 0. Their gaits are "biped", "tripod"
and "bipedal-tripod" (B, T, TB in one file), a walker that leans on its trunk part of the
time: it counts as a tripod, as our gait class would call it (a trunk that bears weight at
10 % of the ticks or more: docs/model.md, "Evaluation").
"""
import glob
import math
import os
import re

import numpy as np

from . import paper
from .load import CUT_OFF_FITNESS, InputError, of_case, paper_cases
from .statistics import bootstrap_interval, mean_and_sd, ratio_of_means, reported_generations, \
    share_leading

FITNESS_DATA = os.path.join("CaseData", "image", "fitness-data")
RUN_FILE = re.compile(r"case(\d+)-(\d+)\.txt")
BUMP_DATA = os.path.join("CaseData", "image", "bump-data")
CHILDREN = os.path.join("CaseData", "case{}", "summarisedOutput-*")
# their gait labels, as our two classes
GAITS = {"biped": "biped", "B": "biped", "tripod": "tripod", "T": "tripod",
         "bipedal-tripod": "tripod", "TB": "tripod"}


def read_run(path):
    """One run's file -> its best fitness per generation (paper.GENERATIONS values)."""
    # each improvement holds from its generation on; of two at one generation the later
    curve = np.empty(paper.GENERATIONS)
    for g, f in read_improvements(path):
        curve[g:] = f
    return curve


def read_improvements(path):
    """One run's fitness-data file -> [(generation, best fitness)] of its improvements."""
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
    return list(zip(generations, fitness))


# the lines of a bump-data file: a generation ("currentGen: G", "currentGen: G_C", or
# "currentGen:" with "G_C" on the next line), a label ("bump k >>> gait", or ">kT fitness"
# with the fitness), a fitness (after "maxFitness:", or alone after a label)
GENERATION = re.compile(r"currentGen:\s*(\d+)(?:_\d+)?")
GENERATION_NEXT = re.compile(r"(\d+)_\d+")
LABEL = re.compile(r"bump\s+(\d+)\s*>>>\s*(\S+)")
SHORT_LABEL = re.compile(r">(\d+)([A-Z]+)\s+(\S+)")
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


def read_labels(path):
    """A bump-data file -> [(generation, fitness, gait)] of its improvements in order,
    gait "biped" or "tripod" (GAITS); InputError naming the line."""
    with open(path, encoding="utf-8") as f:
        lines = [line.strip() for line in f]
    bumps, bump, expect = [], {}, None

    def parse_fitness(text, i):
        """A fitness, or an error naming line i."""
        if not NUMBER.fullmatch(text):
            raise InputError(f"{path}: line {i + 1}: '{text}' is not a fitness")
        return float(text)

    for i, line in enumerate(lines):
        if line.startswith("count:"):
            try:
                k = int(line.split(":", 1)[1])
            except ValueError:
                raise InputError(f"{path}: line {i + 1}: '{line}' is not 'count: K'") from None
            if bump or k != len(bumps):
                raise InputError(f"{path}: line {i + 1} says {k} bumps, the lines above hold "
                                 f"{len(bumps)} whole ones")
            return bumps
        if expect == "generation":
            match = GENERATION_NEXT.fullmatch(line)
            if not match:
                raise InputError(f"{path}: line {i + 1}: '{line}' is not a generation G_C")
            bump["generation"], expect = int(match[1]), None
        elif expect == "fitness":
            bump["fitness"], expect = parse_fitness(line, i), None
        elif line == "currentGen:":
            expect = "generation"
        elif line == "maxFitness:":
            expect = "fitness"
        elif GENERATION.fullmatch(line):
            bump["generation"] = int(GENERATION.fullmatch(line)[1])
        elif LABEL.fullmatch(line) or SHORT_LABEL.fullmatch(line):
            match = LABEL.fullmatch(line) or SHORT_LABEL.fullmatch(line)
            if int(match[1]) != len(bumps) + 1 or match[2] not in GAITS:
                raise InputError(f"{path}: line {i + 1}: '{line}' is not bump {len(bumps) + 1} "
                                 f"with a gait of {', '.join(GAITS)}")
            bump["gait"] = GAITS[match[2]]
            if match.re is SHORT_LABEL:
                bump["fitness"] = parse_fitness(match[3], i)
        elif NUMBER.fullmatch(line) and "gait" in bump and "fitness" not in bump:
            bump["fitness"] = parse_fitness(line, i)
        if len(bump) == 3:
            bumps.append((bump["generation"], bump["fitness"], bump["gait"]))
            bump = {}
    raise InputError(f"{path}: no 'count: K' line")


def run_gaits(fitness_path, labels):
    """The gait of a run's best at every generation (paper.GENERATIONS of them), from
    the file of `labels` ({path: read_labels}) whose bumps are the improvements of the
    run's fitness-data file (several alike are one)."""
    improvements = read_improvements(fitness_path)
    matches = {tuple(bumps) for bumps in labels.values()
               if [(g, f) for g, f, _ in bumps] == improvements}
    if len(matches) != 1:
        raise InputError(f"{fitness_path}: {len(matches)} differently labelled files of "
                         f"{', '.join(sorted(labels)) or '(none)'} have its improvements as their "
                         "bumps (generation, fitness), not one")
    gaits = [None] * paper.GENERATIONS
    bumps = matches.pop()
    for g, _, gait in bumps:
        gaits[g:] = [gait] * (paper.GENERATIONS - g)
    return gaits


def read_children(path):
    """A summarisedOutput file -> (cut-offs, evaluations) per generation: how many of
    the generation's children scored CUT_OFF_FITNESS, of how many."""
    cut_offs, evaluations = [], []
    with open(path, encoding="utf-8") as f:
        lines = [line.strip() for line in f]
    for i, line in enumerate(lines):
        if not line.startswith("Generation:"):
            continue
        if line != f"Generation: {len(cut_offs)}" or i + 2 >= len(lines) or \
                lines[i + 1] != "Current Fitness:":
            raise InputError(f"{path}: line {i + 1}: '{line}' is not generation {len(cut_offs)} "
                             "followed by 'Current Fitness:'")
        children = lines[i + 2]
        try:
            fitness = [float(v) for v in children.strip("[]").split(",")]
        except ValueError:
            raise InputError(f"{path}: line {i + 3}: '{children[:60]}' is not a list of "
                             "fitnesses") from None
        cut_offs.append(sum(v == CUT_OFF_FITNESS for v in fitness))
        evaluations.append(len(fitness))
    if len(cut_offs) != paper.GENERATIONS:
        raise InputError(f"{path}: {len(cut_offs)} generations, not {paper.GENERATIONS}")
    return np.array(cut_offs), np.array(evaluations)


def load_authors(checkout):
    """{"checkout": path, "runs": {case number: [best fitness per generation of each
    run, by run number]}, "gaits": {case number: [the best's gait per generation of
    each run, likewise]}, "children": {case number: [(cut-offs, evaluations) per
    generation of each of its runs]}}; InputError naming the path when a file is
    missing or malformed."""
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
    out = {"checkout": checkout, "runs": {}, "gaits": {}, "children": {}}
    for case, files in sorted(found.items()):
        files.sort()
        out["runs"][case] = [read_run(path) for _, path in files]
        labels = {path: read_labels(path) for path in
                  glob.glob(os.path.join(checkout, BUMP_DATA, f"c{case}_*.txt"))}
        out["gaits"][case] = [run_gaits(path, labels) for _, path in files]
        children = sorted(glob.glob(os.path.join(checkout, CHILDREN.format(case))))
        if len(children) != len(files):
            raise InputError(f"{os.path.join(checkout, CHILDREN.format(case))}: "
                             f"{len(children)} files, not one for each of case {case}'s "
                             f"{len(files)} runs")
        out["children"][case] = [read_children(path) for path in children]
    return out


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
