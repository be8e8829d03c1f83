"""The experiments side by side: `walkers_stats experiments ROOT [--authors PATH]
[--readme README.md]`.

ROOT is the tree of committed results (docs/results/): each experiment of ours lies in
its folder under it (experiments.EXPERIMENTS: CVODE's in ROOT itself, RK-Merson's in
ROOT/rk-merson) and counts once its summary.json is there; until then it is "pending".
From each one present this reads its summary (the claims' verdicts, the final bests
recorded and re-scored: written by `summary`, not decided again here) and its runs (the
gaits and curves), and from the authors' checkout their runs, and writes

  ROOT/experiments.json, ROOT/experiments.md   the claims with a verdict column an
      experiment, the final bests like with like (recorded against recorded, re-scored
      against re-scored), where the tripods go (tripods.py) and the cut-offs
      (cut_offs.py), every experiment in one table;
  ROOT/figures/experiments-fig9.png/.svg, experiments-tripods.png/.svg   Fig. 9 and
      the tripods' figure with every experiment (figures.py);
  with --readme, the block of that file between README_BEGIN and README_END: the
      claims and the final bests.

Given the same files it writes the same bytes; bad input is an InputError naming the file
and the field, and then nothing is written.
"""
import json
import os

import numpy as np

from . import cut_offs, experiments, figures, load, tripods
from .text import finite_or_null, fmt_p, n_label, write_atomically

PAGE, DATA = "experiments.md", "experiments.json"
FIGURES = ("experiments-fig9", "experiments-tripods")
README_BEGIN = "<!-- walkers_stats experiments: begin (remade by the command, not by hand) -->"
README_END = "<!-- walkers_stats experiments: end -->"
PENDING = "pending"


def summary_of(folder):
    """A summary.json's claims and final bests, every field checked."""
    path = os.path.join(folder, "summary.json")
    summary = load.read_json(path, required=True)
    block = load.field(summary, "claims", path, "", dict)

    def p_of(finding, key, where):
        """A finding's test's p (null when it has no such test)."""
        test = finding.get(key)
        return None if test is None else load.number(test, "p", path, f"{where}{key}.",
                                                     allow_null=True)
    findings = []
    for i, f in enumerate(load.field(block, "findings", path, "claims.", list)):
        where = f"claims.findings[{i}]."
        findings.append({
            **{k: load.field(f, k, path, where, str)
               for k in ("id", "statement", "paper_says", "we_find", "verdict")},
            **{f"{k}_p": p_of(f, k, where) for k in ("test", "paired_test")}})
    cases = {}
    for case, c in load.field(block, "cases", path, "claims.", dict).items():
        where = f"claims.cases.{case}."
        cases[case] = {"runs": load.count(c, "runs", path, where, 1, 10 ** 6),
                       "rescored": load.number(load.field(c, "final_best", path, where, dict),
                                               "mean", path, f"{where}final_best.")}
    return {"findings": findings, "cases": cases}


def load_ours(root):
    """[(experiment, (reproduction, summary) or None)] for each experiment of ours."""
    out = []
    for experiment in experiments.EXPERIMENTS:
        if experiment == experiments.AUTHORS:
            continue
        folder = os.path.normpath(os.path.join(root, experiment.folder))
        if not os.path.isfile(os.path.join(folder, "summary.json")):
            out.append((experiment, None))
            continue
        rep = load.load_reproduction(folder)
        if experiments.of_reproduction(rep) != experiment:
            raise load.InputError(
                f"{os.path.join(folder, load.MANIFEST)}: field 'program.evaluation.integrator' is "
                f"'{rep['integrator']}', but {folder} is the folder of {experiment.label}")
        out.append((experiment, (rep, summary_of(folder))))
    present = [found[0] for _, found in out if found]
    if not present:
        raise load.InputError(f"{root}: no experiment of ours has a summary.json (in "
                              f"{', '.join(e.folder for e, _ in out)})")
    names = [[s["name"] for s in rep["scaffolds"]] for rep in present]
    if any(n != names[0] for n in names):
        raise load.InputError(f"{root}: the experiments' reproduction.json list other scaffolds")
    return out


def claims_rows(ours):
    """Per claim (in the first present summary's order): the paper's words, and per
    experiment of ours its figure, p, paired p and verdict (None: pending)."""
    present = [found[1] for _, found in ours if found]
    rows = []
    for first in present[0]["findings"]:
        row = {"id": first["id"], "statement": first["statement"], "paper_says": first["paper_says"],
               "by_experiment": {}}
        for experiment, found in ours:
            f = None if found is None else next(
                (f for f in found[1]["findings"] if f["id"] == first["id"]), None)
            row["by_experiment"][experiment.id] = None if f is None else \
                {k: f[k] for k in ("we_find", "verdict", "test_p", "paired_test_p")}
        rows.append(row)
    return rows


def finals_rows(ours, authors, scaffolds):
    """Per case: the authors' final best recorded (their mean, from their checkout), and
    per experiment of ours its recorded and re-scored means (None: pending)."""
    rows = []
    for s in scaffolds:
        theirs = None if authors is None else authors["runs"].get(s["number"])
        row = {"case": s["name"], "authors_recorded": None if not theirs else
               float(np.mean([curve[-1] for curve in theirs])), "by_experiment": {}}
        for experiment, found in ours:
            entry = None
            if found is not None and s["name"] in found[1]["cases"]:
                rep, summary = found
                runs = [r for r in rep["primary"] if r["case"] == s["name"]]
                entry = {"runs": len(runs),
                         "recorded": float(np.mean([r["data"]["best_fitness"][-1] for r in runs])),
                         "rescored": summary["cases"][s["name"]]["rescored"]}
            row["by_experiment"][experiment.id] = entry
        rows.append(row)
    return rows


def build(root, authors):
    """experiments.json's content and what the figures need."""
    ours = load_ours(root)
    reps = [found[0] for _, found in ours if found]
    scaffolds = reps[0]["scaffolds"]
    series = ([experiments.theirs(authors, scaffolds)] if authors is not None else []) + \
        [experiments.ours(rep) for rep in reps]
    content = {
        "experiments": [{"id": e.id, "label": e.label, "folder": e.folder,
                         "state": "present" if found else PENDING,
                         "runs": None if not found else
                         {case: c["runs"] for case, c in found[1]["cases"].items()}}
                        for e, found in ours],
        "checkout": None if authors is None else authors["checkout"],
        "claims": claims_rows(ours),
        "finals": finals_rows(ours, authors, scaffolds),
        "tripods": tripods.compare(series, scaffolds),
        "cut_offs": cut_offs.compare(reps, authors),
    }
    return finite_or_null(content), {"series": series, "scaffolds": scaffolds,
                                     "generations": max(rep["generations"] for rep in reps)}


def heading(entry):
    """'ours on CVODE, n = 10', or '…: pending'."""
    if entry["state"] == PENDING:
        return f"{entry['label']}: {PENDING}"
    return f"{entry['label']}, n = {n_label(*entry['runs'].values())}"


def claims_table(content):
    """The claims, one column of verdicts an experiment of ours."""
    ours = content["experiments"]
    lines = ["| the paper's claim | the paper | " + " | ".join(heading(e) for e in ours) + " |",
             "|---|---|" + "---|" * len(ours)]
    for row in content["claims"]:
        cells = []
        for e in ours:
            f = row["by_experiment"][e["id"]]
            cells.append(PENDING if f is None else
                         f"{f['we_find']}; p = {fmt_p(f['test_p'])}: **{f['verdict']}**")
        lines.append(f"| {row['statement']} | {row['paper_says']} | " + " | ".join(cells) + " |")
    return lines


def finals_table(content, scaffolds):
    """The final bests: recorded against recorded, re-scored against re-scored."""
    ours = content["experiments"]
    lines = ["| case | the authors' runs: recorded | " +
             " | ".join(f"{e['label']}: recorded | re-scored" for e in ours) + " |",
             "|---|---|" + "---|---|" * len(ours)]
    for s, row in zip(scaffolds, content["finals"]):
        cells = ["—" if row["authors_recorded"] is None else f"{row['authors_recorded']:.2f}"]
        for e in ours:
            entry = row["by_experiment"][e["id"]]
            cells += [PENDING] * 2 if entry is None else \
                [f"{entry['recorded']:.2f}", f"{entry['rescored']:.2f}"]
        lines.append(f"| {s['number']}, {s['label']} | " + " | ".join(cells) + " |")
    return lines


def readme_block(content, scaffolds):
    """What the README's block holds: the claims and the final bests."""
    return "\n".join(
        ["The claims, each tested by the rule of `docs/statistics.md` on each experiment of "
         "ours: its figure, its one-sided p and its verdict (the paired tests over replicates "
         "are in each summary).", ""] + claims_table(content) +
        ["", "The final bests, mean over a case's runs, like with like: what the runs recorded "
         "(theirs and ours), and ours re-scored by ensembles of 25 (the final-fitness claims "
         "above use these; the paper's figures are recorded ones).", ""] +
        finals_table(content, scaffolds)) + "\n"


def markdown(content, scaffolds):
    """experiments.md."""
    def where(folder):  # an experiment's folder, relative to this file's
        return " (this folder)" if folder == "." else f" (`{folder}/`)" if folder else ""
    named = "; ".join(f"{e['label']}: {e['state']}{where(e['folder'])}" for e in content["experiments"])
    parts = ["# The experiments side by side\n",
             "The authors' nine runs, ours on CVODE and ours as the authors ran it (Simbody's "
             "Runge–Kutta–Merson at their accuracy 0.05 and their cut-off), set side by side: "
             f"{named}. Made by `walkers_stats experiments` (`docs/statistics.md`).\n",
             "## The claims\n\n" + readme_block(content, scaffolds),
             tripods.markdown(content["tripods"], scaffolds) +
             "\n![where the tripods go](figures/experiments-tripods.png)\n",
             "## Best fitness per generation\n\n![Fig. 9, one panel a case, every experiment]"
             "(figures/experiments-fig9.png)\n",
             cut_offs.markdown(content["cut_offs"], scaffolds)]
    return "\n".join(parts)


def replace_block(path, block):
    """The text of file `path` with its block between README_BEGIN and README_END
    replaced by `block`."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        raise load.InputError(f"{path}: cannot be read ({e.strerror})") from None
    begin, end = text.find(README_BEGIN), text.find(README_END)
    if begin < 0 or end < begin:
        raise load.InputError(f"{path}: no block between the lines '{README_BEGIN}' and "
                              f"'{README_END}'")
    return text[:begin + len(README_BEGIN)] + "\n" + block + text[end:]


def write(root, authors, readme=None):
    """Build everything, then write the page, its data, the figures and the README's
    block; returns the exit status."""
    content, drawing = build(root, authors)
    page = markdown(content, drawing["scaffolds"])
    readme_text = None if readme is None else \
        replace_block(readme, readme_block(content, drawing["scaffolds"]))
    out_dir = os.path.join(root, "figures")
    os.makedirs(out_dir, exist_ok=True)
    with figures.plt.rc_context(figures.STYLE):
        figures.fig9(drawing["series"], drawing["scaffolds"], drawing["generations"], out_dir,
                     FIGURES[0])
        figures.tripods_figure(drawing["series"], drawing["scaffolds"], drawing["generations"],
                               out_dir, FIGURES[1])
    write_atomically(os.path.join(root, DATA), json.dumps(
        content, indent=2, sort_keys=True, ensure_ascii=False, allow_nan=False) + "\n")
    write_atomically(os.path.join(root, PAGE), page)
    if readme_text is not None:
        write_atomically(readme, readme_text)
    return 0
