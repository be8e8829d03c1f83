"""summary.json and summary.md of a reproduction: written here, and only here, from the
files load.py reads (and, when named, the authors' runs: authors.py).

  summary.json  the configuration; the first learner's runs with their finals, re-scores,
                evaluations, falls and evaluation time; the best biped and best tripod;
                the rates; "beside_authors" (authors.compare); "claims" (claims.evaluate,
                with a block per learner when there are two or more); "tripods"
                (tripods.compare) and "cut_offs" (cut_offs.compare), the authors' beside
                ours
  summary.md    the same as tables and lines a person reads

Both are written through temporary files renamed into place, and only once both texts
are made: a failure leaves the earlier files as they were. The same inputs give the same
bytes.
"""
import json
import os

import numpy as np

from . import authors as the_authors
from . import claims, cut_offs, experiments, paper, tripods
from .text import finite_or_null, fmt_interval, fmt_percent, write_atomically

FIGURES = ("fig4a", "fig4b", "fig5", "fig6", "fig7", "fig8", "fig9", "tripods", "finals")
FINALISTS = ("final_best", "best_biped", "best_tripod")


def run_entry(run, population):
    """A run of summary.json: its finals, and what its generations.csv says of its
    evaluations (population x generations), falls and evaluation time (the sum over
    generations of population / evals_per_s)."""
    data = run["data"]
    rates = data["evals_per_s"][data["evals_per_s"] > 0]
    return {**{k: run[k] for k in ("case", "replicate", "dir", "seed") + FINALISTS},
            "generations": len(data["generation"]),
            "evaluations": population * len(data["generation"]),
            "falls": int(np.sum(data["falls"])),
            "evaluation_seconds": float(np.sum(population / rates))}


def not_reproduced(runs):
    """The finalists whose unperturbed ensemble member did not score what the run
    recorded: "free-1 29/3 (final_best)"."""
    return [f"{r['dir']} {r[k]['id']} ({k})" for r in runs for k in FINALISTS
            if r[k] is not None and r[k]["rescore"]["recorded_reproduced"] is False]


def summarize(rep, authors):
    """summary.json's content from a loaded reproduction and the authors' runs (or None)."""
    block = claims.evaluate(claims.claims_input(rep))
    share = next(f for f in block["findings"] if f["id"] == "case3_leads_generations")
    runs = [run_entry(r, rep["population"]) for r in rep["primary"]]
    evaluations = sum(r["evaluations"] for r in runs)
    seconds = sum(r["evaluation_seconds"] for r in runs)
    summary = {
        **{k: rep[k] for k in ("preset", "generations", "replicates", "seed", "population",
                               "ensemble", "program", "best_biped", "best_tripod")},
        "learners": [l["name"] for l in rep["learners"]],
        "runs": runs,
        "evaluations": evaluations,
        "fell_share": sum(r["falls"] for r in runs) / evaluations if evaluations else None,
        "evaluation_seconds": seconds,
        "evals_per_s": evaluations / seconds if seconds > 0 else None,
        "rescores": {"ensemble": rep["ensemble"], "not_reproduced": not_reproduced(rep["runs"])},
        "beside_authors": the_authors.compare(rep, authors, share.get("effect", {}).get("value")),
        "claims": block,
        "tripods": tripods.compare(experiments.series(rep, authors), rep["scaffolds"]),
        "cut_offs": cut_offs.compare([rep], authors),
    }
    return finite_or_null(summary)


def case_label(scaffold):
    """'2, time-constrained'"""
    return f"{scaffold['number']}, {scaffold['label']}"


def beside_authors_markdown(beside, scaffolds):
    """The section of best fitness per generation, ours beside the authors'."""
    by_name = {s["name"]: s for s in scaffolds}
    lines = ["## Best fitness, beside the authors' runs", "",
             "Best fitness at the generations (numbered from 0) the paper reports and at our last: "
             "our mean over the runs with its 95 % bootstrap interval, the authors' mean over "
             "their runs (their `fitness-data`), and whether theirs lies inside our interval. "
             "These are the fitnesses the runs recorded, theirs as ours.", ""]
    if beside["note"]:
        lines += [f"*Note: {beside['note']}.*", ""]
    lines += ["| case | generation | ours: mean [95 %] (runs) | the authors': mean (runs) | "
              "theirs inside ours |", "|---|---|---|---|---|"]
    for row in beside["at_generations"]:
        ours, theirs = row["ours"], row["authors"]
        ours_cell = "not reached" if ours is None else \
            f"{ours['mean']:.2f} {fmt_interval(ours['interval'])} ({ours['runs']})"
        theirs_cell = "—" if theirs is None else f"{theirs['mean']:.2f} ({theirs['runs']})"
        inside = {True: "yes", False: "**no**", None: "—"}[row["inside"]]
        lines.append(f"| {case_label(by_name[row['case']])} | {row['generation']} | {ours_cell} | "
                     f"{theirs_cell} | {inside} |")
    share, ratio = beside["case3_leads_share"], beside["case2_over_case1_final"]
    lines += ["", "| finding | ours | the authors' runs | paper |", "|---|---|---|---|",
              f"| generations in which case 3's mean best exceeds case 1's | "
              f"{fmt_percent(share['ours'])} | {fmt_percent(share['authors'])} | "
              f"{fmt_percent(share['paper'])} |",
              f"| case 2's final mean best as a share of case 1's (recorded) | "
              f"{fmt_percent(ratio['ours'])} | {fmt_percent(ratio['authors'])} | "
              f"{fmt_percent(ratio['paper'])} |"]
    return "\n".join(lines) + "\n"


def bests_markdown(summary):
    """The section of the best biped and tripod, the falls and the evaluations."""
    def who(pick):
        """'12.34, re-scored 12.30 (performance-2, 2964/8)' or 'none'"""
        if pick is None:
            return "none"
        return (f"{pick['fitness']:.2f}, re-scored {pick['rescore']['median']:.2f} "
                f"({pick['run']}, {pick['id']})")
    lines = ["## The best biped and the best tripod", "",
             "| | ours: recorded, re-scored median (run, generation/child) | paper |",
             "|---|---|---|",
             f"| best biped | {who(summary['best_biped'])} | from case {paper.BEST_BIPED_FROM} |",
             f"| best tripod | {who(summary['best_tripod'])} | from case {paper.BEST_TRIPOD_FROM} |",
             f"| evaluations that fell | {fmt_percent(summary['fell_share'])} | {paper.FELL} |", "",
             f"{summary['evaluations']} evaluations in {summary['evaluation_seconds']:.0f} s of "
             f"evaluation time ({summary['evals_per_s'] or 0:.1f} per second)."]
    return "\n".join(lines) + "\n"


def learners_markdown(block, learners, scaffolds):
    """The section comparing the learners under each scaffold (two learners or more)."""
    labels = {l["name"]: f"{l['label']} ({l['name']})" for l in learners}
    lines = ["## Learners under the scaffolds", "",
             "Each learner's final best (re-scored: mean over its runs), its runs ending as "
             "tripods, and the scaffolds' effects by the claims' tests (lines above).", "",
             "| learner | " + " | ".join(f"case {case_label(s)}" for s in scaffolds) +
             " | generations in which case 3's mean best exceeds case 1's | case 2's final "
             "mean best over case 1's |",
             "|---|" + "---|" * (len(scaffolds) + 2)]
    for entry in block["learners"]:
        cells = []
        for s in scaffolds:
            c = entry["cases"].get(s["name"])
            cells.append("—" if c is None else
                         f"{c['final_best']['mean']:.2f}, {c['tripod_finals']['tripods']} of "
                         f"{c['runs']} tripods")
        effects = {f["id"]: f.get("effect", {}).get("value") for f in entry["findings"]}
        lines.append(f"| {labels[entry['learner']]} | " + " | ".join(cells) +
                     f" | {fmt_percent(effects['case3_leads_generations'])} | "
                     f"{fmt_percent(effects['case2_below_case1'])} |")
    lines += ["", "![learners](figures/learners.png)"]
    return "\n".join(lines) + "\n"


def markdown(summary, rep):
    """summary.md."""
    title = (f"# Reproduction: {rep['replicates']} replicate(s) x {rep['generations']} "
             f"generations, preset {rep['preset']}")
    if len(rep["learners"]) > 1:
        title += ", learners " + ", ".join(summary["learners"])
    finalists = sum(r[k] is not None for r in rep["runs"] for k in FINALISTS)
    odd = rep["ensemble"] % 2 == 1
    missed = summary["rescores"]["not_reproduced"]
    intro = (f"Each run's final best, best biped and best tripod was evaluated again by an "
             f"ensemble of {rep['ensemble']} (the relative tolerance scaled by 1 + k·10⁻⁴); the "
             "claims about final fitness use their medians, the curves are the fitness the runs "
             "recorded.")
    if odd:
        intro += (f" The ensembles' unperturbed members scored what the runs recorded for "
                  f"{finalists - len(missed)} of the {finalists} finalists"
                  + ("." if not missed else f" (not: {', '.join(missed)}: those runs were made "
                     "by other numerics)."))
    intro += (f" The program that wrote `reproduction.json` was built from commit "
              f"`{rep['program']['commit']}`; the runs' evaluation settings are in `summary.json` "
              "(`program.evaluation`) and in each run's `config.json`.")
    parts = [title + "\n", intro + "\n", beside_authors_markdown(summary["beside_authors"],
                                                                 rep["scaffolds"]),
             claims.markdown(summary["claims"]),
             tripods.markdown(summary["tripods"], rep["scaffolds"]),
             cut_offs.markdown(summary["cut_offs"], rep["scaffolds"]), bests_markdown(summary)]
    if len(rep["learners"]) > 1:
        parts.append(learners_markdown(summary["claims"], rep["learners"], rep["scaffolds"]))
    parts.append("## Figures\n\n" + "".join(f"![{fig}](figures/{fig}.png)\n" for fig in FIGURES))
    return "\n".join(parts)


def write(run_dir, summary, rep):
    """Write summary.json and summary.md (both texts first)."""
    json_text = json.dumps(summary, indent=2, sort_keys=True, ensure_ascii=False,
                           allow_nan=False) + "\n"
    md_text = markdown(summary, rep)
    write_atomically(os.path.join(run_dir, "summary.json"), json_text)
    write_atomically(os.path.join(run_dir, "summary.md"), md_text)


def report(summary):
    """The lines `walkers reproduce` prints: evaluations, the bests, the verdicts."""
    lines = [f"{summary['evaluations']} evaluations ({summary['evals_per_s'] or 0:.1f} per second "
             "of evaluation time)"]
    for gait in ("biped", "tripod"):
        pick = summary[f"best_{gait}"]
        if pick is not None:
            lines.append(f"best {gait} {pick['fitness']:.3f}, re-scored {pick['rescore']['median']:.3f} "
                         f"({pick['run']} {pick['id']})")
    lines += [f["line"].replace("**", "") for f in summary["claims"]["findings"]]
    return "\n".join(lines)
