"""Where the tripods go: for each experiment (experiments.py) and case, the share of runs
whose best is a tripod at the generations REPORTED and at the last, the generation from
which each run's best is a biped for good, and Fisher's exact test (two-sided) of each
case's final share against the authors'. The gaits are the runs' recorded ones: ours from
generations.csv's best_gait, theirs from their labels (authors.py).
"""
from . import claims, experiments
from .experiments import AUTHORS
from .statistics import fisher_p
from .text import fmt_generation, fmt_p

REPORTED = (0, 250, 500, 750, 1000, 2000)   # and each run's last, 3999 in a paper's run


def is_tripod(course, g):
    """Whether a run's best at generation g is a tripod (a best that fell is not)."""
    return course["best_gait"][g] == "tripod"


def shares(courses):
    """[{generation, tripods, runs}] at each of REPORTED that every run reaches, and at
    the runs' last (each its own: "generation" is then "last")."""
    last = min(len(c["generation"]) for c in courses) - 1
    out = [{"generation": g, "tripods": sum(is_tripod(c, g) for c in courses), "runs": len(courses)}
           for g in REPORTED if g < last]
    out.append({"generation": "last", "tripods": sum(is_tripod(c, -1) for c in courses),
                "runs": len(courses)})
    return out


def case_entry(courses, theirs):
    """An experiment's case: its shares, each run's generation of a biped for good (the
    claims' time_entry), and with `theirs` (the authors' courses of the case, or None
    for theirs or none) Fisher's test of the final shares."""
    never = claims.never_generation(courses)
    entry = {"runs": len(courses), "last_generation": min(len(c["generation"]) for c in courses) - 1,
             "tripod_shares": shares(courses),
             "biped_for_good": claims.time_entry(
                 [claims.time_to_biped(c, True, never) for c in courses], never)}
    if theirs:
        k, n = claims.tripod_finals(courses), len(courses)
        k_theirs, n_theirs = claims.tripod_finals(theirs), len(theirs)
        entry["final_against_authors"] = {
            "test": "Fisher's exact, two-sided", "tripods": k, "runs": n,
            "authors_tripods": k_theirs, "authors_runs": n_theirs,
            "p": fisher_p(k, n, k_theirs, n_theirs, "two-sided")}
    return entry


def compare(series, scaffolds):
    """The block "tripods" of a summary: series is [(experiment, {case: [course]})]
    (experiments.series), the authors' first when present."""
    authors = {e.id: courses for e, courses in series}.get(AUTHORS.id)
    out = {"generations": list(REPORTED) + ["last"],
           "note": None if authors is not None else
           experiments.AUTHORS_MISSING,
           "experiments": []}
    for experiment, by_case in series:
        cases = {}
        for s in scaffolds:
            courses = by_case.get(s["name"])
            if courses:
                theirs = None if experiment == AUTHORS or authors is None else authors.get(s["name"])
                cases[s["name"]] = case_entry(courses, theirs)
        out["experiments"].append({"experiment": experiment.id, "label": experiment.label,
                                   "cases": cases})
    return out


def markdown(block, scaffolds):
    """The section "Where the tripods go" of summary.md (or of the experiments' page)."""
    lasts = {c["last_generation"] for e in block["experiments"] for c in e["cases"].values()}
    last = str(lasts.pop()) if len(lasts) == 1 else "last"
    lines = ["## Where the tripods go", "",
             "The runs whose best is a tripod at a generation (the recorded gaits: ours from "
             "`generations.csv`, the authors' from their labels, where a *bipedal-tripod* counts "
             "as a tripod), the generation from which a run's best is a biped to the end (the "
             "median over the runs; *never* when its last best is a tripod), and Fisher's exact "
             "test (two-sided) of the runs ending as tripods against the authors'.", ""]
    if block["note"]:
        lines += [f"*Note: {block['note']}.*", ""]
    lines += ["| case | runs | " + " | ".join(
        f"tripods at {g}" if g == REPORTED[0] else str(g) for g in REPORTED) +
        f" | {last} | biped for good from: median (never) | ending as tripods, against the "
        "authors': Fisher's p |",
        "|---|---|" + "---|" * (len(REPORTED) + 3)]
    for s in scaffolds:
        for entry in block["experiments"]:
            c = entry["cases"].get(s["name"])
            if c is None:
                continue
            at = {row["generation"]: f"{row['tripods']} of {row['runs']}" for row in c["tripod_shares"]}
            good = c["biped_for_good"]
            fisher = c.get("final_against_authors")
            lines.append(
                f"| {s['number']}, {s['label']}: {entry['label']} | {c['runs']} | " +
                " | ".join(at.get(g, "—") for g in REPORTED) + f" | {at['last']} | "
                f"{fmt_generation(good['median'])} (never: {good['never']}) | "
                f"{fmt_p(fisher['p']) if fisher else '—'} |")
    return "\n".join(lines) + "\n"
