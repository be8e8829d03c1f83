"""The experiments set side by side, declared once: the authors' nine runs, ours on CVODE,
and ours as the authors ran it (Simbody's Runge-Kutta-Merson at their accuracy, their
cut-off). Every table and figure that compares experiments takes them in this order and
by these names; a reproduction of ours is one of them by its integrator
(reproduction.json's program.evaluation.integrator, load.INTEGRATORS).

An experiment's runs, for the comparisons, are "courses": per case, one dict a run with
its "replicate" (their run number M for the authors'), "generation", "best_fitness" and
"best_gait" per generation (claims.claim_run's keys), so that the claims' helpers of
time and gait apply to theirs as to ours.
"""
from collections import namedtuple

from . import claims
from .load import InputError, MANIFEST

# folder: where its results lie in the tree of committed results (docs/results/), or None
# for the authors' (a checkout the user names)
Experiment = namedtuple("Experiment", "id label folder colour")
AUTHORS = Experiment("authors", "the authors' runs", None, "0.15")
EXPERIMENTS = (AUTHORS,
               Experiment("cvode", "ours on CVODE", ".", "tab:blue"),
               Experiment("rk-merson", "ours as the authors ran it (RK-Merson)", "rk-merson",
                          "tab:red"))

AUTHORS_MISSING = "the authors' runs are missing: no checkout of their repository was named"


def of_reproduction(rep):
    """The experiment a loaded reproduction (load.load_reproduction) belongs to."""
    for experiment in EXPERIMENTS:
        if experiment.id == rep["integrator"]:
            return experiment
    raise InputError(f"{MANIFEST}: field 'program.evaluation.integrator' is "
                     f"'{rep['integrator']}', which no experiment declares")


def ours(rep):
    """(experiment, {case name: [course of each of the first learner's runs]})."""
    return of_reproduction(rep), {s["name"]: [claims.claim_run(r) for r in rep["primary"]
                                              if r["case"] == s["name"]]
                                  for s in rep["scaffolds"]}


def theirs(authors, scaffolds):
    """(AUTHORS, {case name: [course of each of their runs]}): their case N is the
    scaffold in place N; a case they have no runs of is left out."""
    courses = {}
    for s in scaffolds:
        curves = authors["runs"].get(s["number"], [])
        gaits = authors["gaits"].get(s["number"], [])
        if curves:
            courses[s["name"]] = [{"replicate": m, "generation": list(range(len(curve))),
                                   "best_fitness": [float(f) for f in curve], "best_gait": gait}
                                  for m, (curve, gait) in enumerate(zip(curves, gaits), 1)]
    return AUTHORS, courses


def series(rep, authors):
    """The experiments a reproduction's summary and figures set side by side: the
    authors' (when their checkout was named) and this reproduction's."""
    return ([theirs(authors, rep["scaffolds"])] if authors is not None else []) + [ours(rep)]
