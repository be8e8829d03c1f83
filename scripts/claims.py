#!/usr/bin/env python3
"""The paper's claims tested on a reproduction directory, each with a verdict.

Usage:  /usr/bin/python3 scripts/claims.py RUN_DIR

(Debian's /usr/bin/python3 with python3-scipy and python3-matplotlib.) `walkers
reproduce` runs it after writing its statistics and before drawing the figures; run
it by hand only on a reproduction no `walkers` process is writing. It reads

  RUN_DIR/summary.json               the runs (case, replicate, dir, and the best biped's
                                     and best tripod's fitness of each: best_biped_fitness,
                                     best_tripod_fitness, null for none), and the paper's
                                     values beside ours (case3_over_case1_share.paper,
                                     case2_over_case1_final.paper, biped_over_tripod.paper,
                                     cases.<case>.paper_tripod_finals_of_3)
  RUN_DIR/<run dir>/generations.csv  every run's best fitness and gait per generation
                                     (read by scripts/figures.py's checked loader)

and adds to them (replacing what an earlier run of it added)

  summary.json  a "claims" block: the rule, per case the final best, tripods and
                time to a biped with intervals, and per claim its test, effect,
                interval, verdict and the line below
  summary.md    a "## Claims" section: one line per claim, a table per case

A missing or malformed input is an error naming the file and the field (or line and
column); nothing is written and the exit status is 1.

Verdict rule, per claim (ALPHA = 0.05, intervals at 95 %):
  reproduced       the one-sided test in the paper's direction gives p < 0.05;
  not reproduced   otherwise, when our 95 % interval of the effect lies wholly on the
                   no-effect side of the paper's value: beyond it, for a claim the
                   paper gives a number for (83 %, 66 %, 2 of 3, +37.5 %), or at or
                   beyond no effect, for a claim of direction only;
  inconclusive at n = N   otherwise (N: runs per case).

Statistics (SciPy does the work; nothing random is left unseeded):
  * Mann-Whitney U: U from the pooled midranks; its one-sided p by a permutation test
    of those ranks (scipy.stats.permutation_test): exact, ties included, when the
    two samples have at most EXACT_SPLITS splits, else MONTE_CARLO_PERMUTATIONS
    seeded random ones; with one value on a side, every split is listed here.
  * Cliff's delta: mean over all pairs of sign(x_i - y_j) (= 2U / (n_x n_y) - 1);
    Hodges-Lehmann shift: median of all differences x_i - y_j.
  * Intervals of effects: scipy.stats.bootstrap, percentile method,
    BOOTSTRAP_RESAMPLES resamples of the replicates within each case, seeded with
    SEED; none with fewer than two replicates. With a handful of replicates such
    intervals are too narrow; the tests' p-values are exact.
  * Proportions: Wilson intervals (scipy.stats.binomtest(...).proportion_ci); their
    difference: Newcombe's hybrid score interval (his method 10) from the Wilson
    limits; Fisher's exact test (scipy.stats.fisher_exact).
  * The share of generations in which case 3's mean best leads case 1's: its bootstrap
    interval (whole curves resampled), and as its test the permutation test (as for
    U) of the difference of the cases' mean best fitness averaged over the generations
    (the area under the mean curves). The share itself is a poor test statistic: when
    the replicates' curves keep their order, shuffled labels give shares near 0 or 1.
  * The best biped against the best tripod: their ratio over all runs, with a
    bootstrap of the runs as pairs (resamples without a tripod left out); the sign test (scipy.stats.binomtest) of "a run's best
    biped walks further than its best tripod" over the runs that have both.
  * Time to a biped: the generation of a run's first biped best, and that from which
    its best is a biped to the end ("for good"); a run that ends otherwise never
    became one, and ranks after every run that did.
"""
import argparse
import importlib.util
import json
import math
import os
import sys
import warnings

import numpy as np
from scipy import stats

ALPHA = 0.05
CONFIDENCE = 0.95
SEED = 21                        # every bootstrap and random permutation starts here
BOOTSTRAP_RESAMPLES = 10_001      # its 2.5 % and 97.5 % points fall on resampled values
EXACT_SPLITS = 200_000           # C(20, 10) = 184,756: ten replicates a case, exact
MONTE_CARLO_PERMUTATIONS = 99_999
BATCH_ELEMENTS = 4_000_000       # numbers per vectorised batch, to bound memory

REPRODUCED, NOT_REPRODUCED = "reproduced", "not reproduced"
RULE = ("reproduced: the one-sided test in the paper's direction gives p < 0.05; "
        "not reproduced: otherwise, when our 95 % interval of the effect lies wholly on "
        "the no-effect side of the paper's value (of no effect itself, for a claim of "
        "direction only); inconclusive at n = N (runs per case) otherwise")


class InputError(Exception):
    """A missing or malformed input; the message names the file and field."""


def rng():
    """A fresh generator from SEED: each statistic draws the same numbers whatever
    was computed before it."""
    return np.random.default_rng(SEED)


# ----------------------------------------------------------------------------- statistics

def permutation_p(x, y, statistic, alternative):
    """One-sided p-value of statistic(x, y, axis) against its values over the splits of
    the pooled values into groups of len(x) and len(y) ('greater': x's value is large).
    Returns (p, exact): exact over every split when there are at most EXACT_SPLITS,
    else over MONTE_CARLO_PERMUTATIONS seeded random ones."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    if len(x) < 1 or len(y) < 1:
        raise ValueError("a permutation test needs at least one value on each side")
    splits = math.comb(len(x) + len(y), len(x))
    if min(len(x), len(y)) < 2:
        # scipy's permutation_test wants two values a side; with one there are only
        # len(x) + len(y) splits, listed here
        pooled = np.concatenate([x, y])
        observed = statistic(x, y, axis=-1)
        values = []
        for i in range(len(pooled)):
            rest = np.delete(pooled, i)
            one, other = (pooled[i:i + 1], rest) if len(x) == 1 else (rest, pooled[i:i + 1])
            values.append(statistic(one, other, axis=-1))
        values = np.array(values)
        slack = 1e-12 * max(1.0, abs(observed))        # equal up to rounding counts as equal
        hits = values >= observed - slack if alternative == "greater" else values <= observed + slack
        return float(np.mean(hits)), True
    exact = splits <= EXACT_SPLITS
    res = stats.permutation_test((x, y), statistic, permutation_type="independent",
                                 vectorized=True, alternative=alternative,
                                 n_resamples=np.inf if exact else MONTE_CARLO_PERMUTATIONS,
                                 batch=max(1, BATCH_ELEMENTS // (len(x) + len(y))),
                                 random_state=rng())
    return float(res.pvalue), exact


def rank_sum_test(x, y, alternative):
    """Mann-Whitney U of x against y and its one-sided p-value ('greater': x tends to
    be larger), by permutation of the pooled midranks. Returns (U, p, exact)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    if len(x) < 1 or len(y) < 1:
        raise ValueError("the Mann-Whitney test needs at least one value on each side")
    ranks = stats.rankdata(np.concatenate([x, y]))      # midranks for ties
    u = float(ranks[:len(x)].sum() - len(x) * (len(x) + 1) / 2)
    p, exact = permutation_p(ranks[:len(x)], ranks[len(x):],
                             lambda a, b, axis: np.sum(a, axis=axis), alternative)
    return u, p, exact


def mean_difference(x, y, axis=-1):
    """mean(x) - mean(y), along `axis` (vectorised)."""
    return np.mean(x, axis=axis) - np.mean(y, axis=axis)


def cliffs_delta(x, y, axis=-1):
    """Mean over all pairs of sign(x_i - y_j), along `axis` (vectorised for the
    bootstrap)."""
    x, y = np.moveaxis(np.asarray(x, float), axis, -1), np.moveaxis(np.asarray(y, float), axis, -1)
    xi, yj = x[..., :, None], y[..., None, :]
    return ((xi > yj).astype(float) - (xi < yj)).mean(axis=(-2, -1))


def hodges_lehmann(x, y, axis=-1):
    """Median of all differences x_i - y_j, along `axis` (vectorised)."""
    x, y = np.moveaxis(np.asarray(x, float), axis, -1), np.moveaxis(np.asarray(y, float), axis, -1)
    d = x[..., :, None] - y[..., None, :]
    return np.median(d.reshape(d.shape[:-2] + (-1,)), axis=-1)


def ratio_of_means(x, y, axis=-1):
    """mean(x) / mean(y), along `axis` (vectorised); inf or NaN over a zero mean."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.mean(x, axis=axis) / np.mean(y, axis=axis)


def bootstrap_interval(samples, statistic):
    """95 % percentile bootstrap interval (low, high) of statistic(*samples, axis),
    each sample resampled on its own; None when a sample has fewer than two values or
    the interval is not finite."""
    samples = [np.asarray(s, float) for s in samples]
    if any(len(s) < 2 for s in samples):
        return None
    per_resample = sum(len(s) for s in samples) * max(len(s) for s in samples)
    with np.errstate(invalid="ignore", divide="ignore"):
        res = stats.bootstrap(samples, statistic, n_resamples=BOOTSTRAP_RESAMPLES,
                              vectorized=True, axis=-1, confidence_level=CONFIDENCE,
                              method="percentile", random_state=rng(),
                              batch=max(1, BATCH_ELEMENTS // per_resample))
    low, high = float(res.confidence_interval.low), float(res.confidence_interval.high)
    return (low, high) if math.isfinite(low) and math.isfinite(high) else None


def mean_band(curves):
    """Per column of curves (replicates x generations), the 95 % percentile bootstrap
    interval of the mean over the replicates, the same resamples of whole curves for
    every column: (low, high) arrays, or None with fewer than two replicates."""
    curves = np.asarray(curves, float)
    if curves.shape[0] < 2:
        return None
    res = stats.bootstrap((curves,), np.mean, n_resamples=BOOTSTRAP_RESAMPLES,
                          vectorized=True, axis=0, confidence_level=CONFIDENCE,
                          method="percentile", random_state=rng(),
                          batch=max(1, BATCH_ELEMENTS // curves.size))
    return np.asarray(res.confidence_interval.low), np.asarray(res.confidence_interval.high)


def common_curves(curves_a, curves_b):
    """The two cases' curves (replicates x generations) cut to the generations all have."""
    n = min(min(len(c) for c in curves_a), min(len(c) for c in curves_b))
    return (np.array([c[:n] for c in curves_a], float),
            np.array([c[:n] for c in curves_b], float))


def share_leading(curves_a, curves_b):
    """The share of generations in which the mean over a's replicates exceeds b's."""
    a, b = common_curves(curves_a, curves_b)
    return float(np.mean(a.mean(axis=0) > b.mean(axis=0)))


def _share_by_index(curves):
    """statistic(i, j, axis) = share of generations where the mean of curves[i]
    exceeds that of curves[j]: index samples make whole curves resample together."""
    def statistic(i, j, axis):
        i, j = np.moveaxis(i, axis, -1).astype(int), np.moveaxis(j, axis, -1).astype(int)
        return np.mean(curves[i].mean(axis=-2) > curves[j].mean(axis=-2), axis=-1)
    return statistic


def curve_test(curves_a, curves_b):
    """One-sided permutation test that a's mean curve lies above b's over the
    generations: the difference of the mean over a's and b's replicates of each
    replicate's best fitness averaged over the generations (the area under its curve).
    Returns (difference, p, exact)."""
    a, b = common_curves(curves_a, curves_b)
    x, y = a.mean(axis=1), b.mean(axis=1)
    p, exact = permutation_p(x, y, mean_difference, "greater")
    return float(mean_difference(x, y)), p, exact


def share_interval(curves_a, curves_b):
    """95 % bootstrap interval of share_leading, resampling each case's curves."""
    a, b = common_curves(curves_a, curves_b)
    if len(a) < 2 or len(b) < 2:
        return None
    curves = np.concatenate([a, b])
    res = stats.bootstrap((np.arange(len(a)), np.arange(len(a), len(curves))),
                          _share_by_index(curves), n_resamples=BOOTSTRAP_RESAMPLES,
                          vectorized=True, axis=-1, confidence_level=CONFIDENCE,
                          method="percentile", random_state=rng(),
                          batch=max(1, BATCH_ELEMENTS // curves.size))
    return float(res.confidence_interval.low), float(res.confidence_interval.high)


def wilson_interval(k, n):
    """95 % Wilson score interval of k successes in n trials; None for n = 0."""
    if n == 0:
        return None
    ci = stats.binomtest(k, n).proportion_ci(confidence_level=CONFIDENCE, method="wilson")
    return float(ci.low), float(ci.high)


def newcombe_interval(k1, n1, k2, n2):
    """95 % interval of k1/n1 - k2/n2: Newcombe's hybrid score interval (Statistics in
    Medicine 17:873, 1998, method 10), built from the two Wilson intervals."""
    if n1 == 0 or n2 == 0:
        return None
    p1, p2 = k1 / n1, k2 / n2
    (l1, u1), (l2, u2) = wilson_interval(k1, n1), wilson_interval(k2, n2)
    d = p1 - p2
    return d - math.hypot(p1 - l1, u2 - p2), d + math.hypot(u1 - p1, p2 - l2)


def fisher_greater(k1, n1, k2, n2):
    """One-sided Fisher's exact test that k1/n1 exceeds k2/n2: its p-value."""
    return float(stats.fisher_exact([[k1, n1 - k1], [k2, n2 - k2]],
                                    alternative="greater").pvalue)


def sign_test_greater(x, y):
    """Sign test that x_i > y_i more often than not, over the pairs that differ:
    (pairs with x_i > y_i, pairs that differ, one-sided p or None without any)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    wins, n = int(np.sum(x > y)), int(np.sum(x != y))
    if n == 0:
        return wins, n, None
    return wins, n, float(stats.binomtest(wins, n, 0.5, alternative="greater").pvalue)


def first_biped(generations, gaits):
    """The generation of the first biped best; None if the best never was one."""
    for g, gait in zip(generations, gaits):
        if gait == "biped":
            return int(g)
    return None


def biped_for_good(generations, gaits):
    """The generation from which the best is a biped to the end; None if the last
    best is not a biped."""
    start = None
    for g, gait in zip(generations, gaits):
        start = (int(g) if start is None else start) if gait == "biped" else None
    return start


def verdict(p, interval, direction, null, paper, n_label):
    """The claim's verdict by the rule above. direction +1: the paper says the effect
    exceeds `null`; -1: it is below. paper: the paper's value of the effect, or None
    for a claim of direction only."""
    if p is not None and p < ALPHA:
        return REPRODUCED
    if interval is not None:
        low, high = interval
        if direction > 0 and (high < paper if paper is not None else high <= null):
            return NOT_REPRODUCED
        if direction < 0 and (low > paper if paper is not None else low >= null):
            return NOT_REPRODUCED
    return f"inconclusive at n = {n_label}"


# ----------------------------------------------------------------------------- formatting

def fmt_p(p):
    """A p-value to read: three decimals, or two significant digits below 0.001."""
    if p is None:
        return "—"
    return f"{p:.3f}" if p >= 0.001 else f"{p:.1e}"


def fmt_interval(interval, fmt="{:.2f}", scale=1.0, unit=""):
    """'[low, high] unit' (scaled), or '(no interval)'."""
    if interval is None:
        return "(no interval)"
    return "[" + ", ".join(fmt.format(scale * v) for v in interval) + "]" + unit


def fmt_generation(g, never=None):
    """A generation number, or 'never' (None, or at least `never`)."""
    return "never" if g is None or never is not None and g >= never - 0.5 else f"{float(g):.0f}"


def n_label(*counts):
    """'10' when every case has 10 runs, else '10/9'."""
    return str(counts[0]) if len(set(counts)) == 1 else "/".join(str(c) for c in counts)


def finite_or_null(obj):
    """obj with every non-finite number (a ratio over a zero, say) made null, for JSON."""
    if isinstance(obj, dict):
        return {k: finite_or_null(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [finite_or_null(v) for v in obj]
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def json_interval(interval):
    """An interval as a JSON list, or null."""
    return None if interval is None else [float(v) for v in interval]


# ----------------------------------------------------------------------------- inputs

def _figures():
    """scripts/figures.py as a module, for its checked loaders (imported here, not at
    the top, because figures.py imports this file for its statistics)."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "figures.py")
    spec = importlib.util.spec_from_file_location("walkers_figures", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def number(obj, key, path, where, allow_null=False):
    """obj[key], a finite number (or null when allowed); errors name file and field."""
    if not isinstance(obj, dict) or key not in obj:
        raise InputError(f"{path}: missing field '{where}{key}'")
    value = obj[key]
    if value is None and allow_null:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InputError(f"{path}: field '{where}{key}' must be a finite number"
                         + (" or null" if allow_null else ""))
    return float(value)


def load_reproduction(run_dir):
    """summary.json's runs with their generations.csv, and the paper's values;
    raises InputError naming the bad file and field."""
    figures = _figures()
    path = os.path.join(run_dir, "summary.json")
    try:
        summary = figures.read_json(path, required=True)
        if not isinstance(summary, dict):
            raise InputError(f"{path}: expected a JSON object")
        cases = figures.field(summary, "cases", path, "", dict)
        paper = {"share": number(figures.field(summary, "case3_over_case1_share", path, "", dict),
                                 "paper", path, "case3_over_case1_share."),
                 "ratio": number(figures.field(summary, "case2_over_case1_final", path, "", dict),
                                 "paper", path, "case2_over_case1_final."),
                 "biped_over_tripod": number(figures.field(summary, "biped_over_tripod", path, "", dict),
                                             "paper", path, "biped_over_tripod."),
                 "tripods_of_3": {}}
        for name, case in cases.items():
            k = figures.field(case, "paper_tripod_finals_of_3", path, f"cases.{name}.", int)
            if not 0 <= k <= 3:
                raise InputError(f"{path}: field 'cases.{name}.paper_tripod_finals_of_3' is {k}, "
                                 "outside [0, 3]")
            paper["tripods_of_3"][name] = k
        runs = [load_run(figures, run_dir, run, path, f"runs[{i}].", cases)
                for i, run in enumerate(figures.field(summary, "runs", path, "", list))]
        # with two learners or more, every learner's runs (summary.json's learner_runs)
        learners = {}
        if len(summary.get("learners", [])) > 1:
            for i, run in enumerate(figures.field(summary, "learner_runs", path, "", list)):
                where = f"learner_runs[{i}]."
                learner = figures.field(run, "learner", path, where, str)
                learners.setdefault(learner, []).append(load_run(figures, run_dir, run, path, where, cases))
    except figures.InputError as e:
        raise InputError(str(e)) from None
    return {"summary": summary, "runs": runs, "paper": paper, "learners": learners}


def load_run(figures, run_dir, run, path, where, cases):
    """One run of summary.json with its generations.csv."""
    entry = {key: figures.field(run, key, path, where, str) for key in ("case", "dir")}
    entry["replicate"] = figures.field(run, "replicate", path, where, int)
    if entry["case"] not in cases:
        raise InputError(f"{path}: field '{where}case' is '{entry['case']}', not one of "
                         f"the cases it lists ({', '.join(sorted(cases))})")
    for gait in ("biped", "tripod"):
        entry[f"best_{gait}"] = number(run, f"best_{gait}_fitness", path, where, allow_null=True)
    data = figures.load_generations(os.path.join(run_dir, entry["dir"], "generations.csv"))
    entry["generation"] = [int(g) for g in data["generation"]]
    entry["best_fitness"] = [float(f) for f in data["best_fitness"]]
    entry["best_gait"] = list(data["best_gait"])
    return entry


# ----------------------------------------------------------------------------- the claims

FREE, TIME, PERFORMANCE = "free", "time", "performance"   # the paper's cases 1, 2, 3


def of_case(runs, case):
    """The runs of one case, by replicate."""
    return sorted((r for r in runs if r["case"] == case), key=lambda r: r["replicate"])


def finals(runs):
    """Each run's final best fitness."""
    return [r["best_fitness"][-1] for r in runs]


def tripod_finals(runs):
    """How many of the runs end with a tripod as their best."""
    return sum(r["best_gait"][-1] == "tripod" for r in runs)


def never_generation(runs):
    """The generation that stands for "never a biped": one after the last of any run,
    so that such a run ranks after every run that became one."""
    return max(r["generation"][-1] for r in runs) + 1


def time_to_biped(run, for_good, never):
    """first_biped or biped_for_good of a run; `never` when it has none."""
    g = (biped_for_good if for_good else first_biped)(run["generation"], run["best_gait"])
    return float(never if g is None else g)


def median_time(values, axis=-1):
    """The generation by which half the runs had become bipeds: the smallest value
    with at least half the runs at or below it (vectorised)."""
    return np.quantile(values, 0.5, axis=axis, method="inverted_cdf")


def missing(claim, text, needed, runs):
    """The finding of a claim that lacks runs of a case it compares."""
    absent = [c for c in needed if not of_case(runs, c)]
    if not absent:
        return None
    line = f"{text}: **inconclusive at n = 0**: no runs of case {', '.join(absent)}."
    return {"id": claim, "claim": text, "verdict": "inconclusive at n = 0", "line": line}


def finding(claim, text, p, effect, direction, null, paper, n, line_numbers, extra=None):
    """A claim's JSON entry, with its verdict and its line."""
    v = verdict(p, effect["interval"], direction, null, paper, n)
    effect = {**effect, "interval": json_interval(effect["interval"]), "null": null,
              "paper": paper, "paper_direction": "above" if direction > 0 else "below"}
    if paper is not None and effect["interval"] is not None:
        low, high = effect["interval"]
        where = "below" if paper < low else "above" if paper > high else "within"
        line_numbers += f"; the paper's value lies {where} our interval"
    out = {"id": claim, "claim": text, "verdict": v, "effect": effect,
           "line": f"{text}: **{v}**: {line_numbers}."}
    out.update(extra or {})
    return out


def claim_case3_above_case1(rep):
    """Case 3 ends above case 1 (final best fitness)."""
    text = "Case 3 (performance) ends above case 1 (free) — paper: case 3 ends highest"
    runs = rep["runs"]
    gap = missing("case3_above_case1", text, (FREE, PERFORMANCE), runs)
    if gap:
        return gap
    x, y = finals(of_case(runs, PERFORMANCE)), finals(of_case(runs, FREE))
    u, p, exact = rank_sum_test(x, y, "greater")
    delta = {"name": "Cliff's delta", "value": float(cliffs_delta(x, y)),
             "interval": bootstrap_interval((x, y), cliffs_delta)}
    shift_ci = bootstrap_interval((x, y), hodges_lehmann)
    shift = float(hodges_lehmann(x, y))
    numbers = (f"final best {np.mean(x):.2f} against {np.mean(y):.2f} (means), Cliff's δ = "
               f"{delta['value']:+.2f} {fmt_interval(delta['interval'], '{:+.2f}')}, "
               f"Hodges–Lehmann shift {shift:+.2f} {fmt_interval(shift_ci, '{:+.2f}')}; "
               f"one-sided Mann–Whitney U = {u:g}, p = {fmt_p(p)}")
    test = {"name": "Mann-Whitney U, one-sided (case 3 > case 1)", "statistic": u, "p": p,
            "exact": exact}
    return finding("case3_above_case1", text, p, delta, +1, 0.0, None, n_label(len(x), len(y)),
                   numbers, {"test": test, "n": [len(x), len(y)],
                             "hodges_lehmann": {"value": shift,
                                                "interval": json_interval(shift_ci)}})


def claim_case3_leads_generations(rep):
    """Case 3's mean best leads case 1's in most generations (the paper: 83 %)."""
    text = "Case 3's mean best leads case 1's in most generations — paper: in {:.0f} %".format(
        100 * rep["paper"]["share"])
    runs = rep["runs"]
    gap = missing("case3_leads_generations", text, (FREE, PERFORMANCE), runs)
    if gap:
        return gap
    a = [r["best_fitness"] for r in of_case(runs, PERFORMANCE)]
    b = [r["best_fitness"] for r in of_case(runs, FREE)]
    share = share_leading(a, b)
    area, p, exact = curve_test(a, b)
    interval = share_interval(a, b)
    generations = common_curves(a, b)[0].shape[1]
    numbers = (f"{100 * share:.1f} % of {generations} generations "
               f"{fmt_interval(interval, '{:.1f}', 100, ' %')}; best fitness averaged over the "
               f"generations, case 3 − case 1: {area:+.2f}, one-sided permutation "
               f"p = {fmt_p(p)}")
    test = {"name": "permutation test of the replicates' best fitness averaged over the "
                    "generations, case 3 - case 1, one-sided", "statistic": area, "p": p,
            "exact": exact}
    effect = {"name": "share of generations", "value": share, "interval": interval}
    return finding("case3_leads_generations", text, p, effect, +1, 0.5, rep["paper"]["share"],
                   n_label(len(a), len(b)), numbers,
                   {"test": test, "n": [len(a), len(b)], "generations": generations})


def claim_case2_below_case1(rep):
    """Case 2 ends below case 1 (the paper: at 66 % of it)."""
    paper = rep["paper"]["ratio"]
    text = f"Case 2 (time) ends below case 1 (free) — paper: at {100 * paper:.0f} % of case 1"
    runs = rep["runs"]
    gap = missing("case2_below_case1", text, (FREE, TIME), runs)
    if gap:
        return gap
    x, y = finals(of_case(runs, TIME)), finals(of_case(runs, FREE))
    u, p, exact = rank_sum_test(x, y, "less")
    ratio = {"name": "ratio of the final mean best fitness, case 2 / case 1",
             "value": float(ratio_of_means(x, y)),
             "interval": bootstrap_interval((x, y), ratio_of_means)}
    numbers = (f"case 2's final mean best is {100 * ratio['value']:.1f} % of case 1's "
               f"{fmt_interval(ratio['interval'], '{:.1f}', 100, ' %')}, Cliff's δ = "
               f"{float(cliffs_delta(x, y)):+.2f}; one-sided Mann–Whitney U = {u:g}, "
               f"p = {fmt_p(p)}")
    test = {"name": "Mann-Whitney U, one-sided (case 2 < case 1)", "statistic": u, "p": p,
            "exact": exact}
    return finding("case2_below_case1", text, p, ratio, -1, 1.0, paper, n_label(len(x), len(y)),
                   numbers, {"test": test, "n": [len(x), len(y)],
                             "cliffs_delta": float(cliffs_delta(x, y))})


def claim_case2_more_tripods(rep):
    """Case 2 ends as a tripod more often than cases 1 and 3 (the paper: 2 of 3, 0 of 6)."""
    paper = rep["paper"]["tripods_of_3"]
    others = (FREE, PERFORMANCE)
    text = "Case 2 ends as a tripod more often than cases 1 and 3"
    runs = rep["runs"]
    gap = missing("case2_more_tripods", text, (FREE, TIME, PERFORMANCE), runs)
    if gap:
        return gap
    k2p, kop = paper[TIME], sum(paper[c] for c in others)
    text += f" — paper: {k2p} of 3 against {kop} of 6"
    time_runs = of_case(runs, TIME)
    other_runs = [r for c in others for r in of_case(runs, c)]
    k2, n2 = tripod_finals(time_runs), len(time_runs)
    ko, no = tripod_finals(other_runs), len(other_runs)
    p = fisher_greater(k2, n2, ko, no)
    w2, wo = wilson_interval(k2, n2), wilson_interval(ko, no)
    effect = {"name": "difference of the shares ending as tripods, case 2 - cases 1 and 3",
              "value": k2 / n2 - ko / no, "interval": newcombe_interval(k2, n2, ko, no)}
    numbers = (f"{k2} of {n2} {fmt_interval(w2, '{:.0f}', 100, ' %')} against {ko} of {no} "
               f"{fmt_interval(wo, '{:.0f}', 100, ' %')} (Wilson), difference "
               f"{100 * effect['value']:+.0f} points "
               f"{fmt_interval(effect['interval'], '{:+.0f}', 100)} (Newcombe); one-sided "
               f"Fisher's exact p = {fmt_p(p)}")
    test = {"name": "Fisher's exact, one-sided (case 2 > cases 1 and 3)", "p": p}
    shares = {"case2": {"tripods": k2, "runs": n2, "wilson": json_interval(w2)},
              "cases1and3": {"tripods": ko, "runs": no, "wilson": json_interval(wo)}}
    return finding("case2_more_tripods", text, p, effect, +1, 0.0, k2p / 3 - kop / 6,
                   n_label(*(len(of_case(runs, c)) for c in (FREE, TIME, PERFORMANCE))), numbers,
                   {"test": test, "shares": shares})


def claim_biped_above_tripod(rep):
    """The best biped walks further than the best tripod (the paper: +37.5 %)."""
    paper = rep["paper"]["biped_over_tripod"] - 1.0
    text = f"The best biped walks further than the best tripod — paper: {100 * paper:+.1f} %"
    runs = rep["runs"]
    bipeds = np.array([np.nan if r["best_biped"] is None else r["best_biped"] for r in runs])
    tripods = np.array([np.nan if r["best_tripod"] is None else r["best_tripod"] for r in runs])
    if np.all(np.isnan(bipeds)) or np.all(np.isnan(tripods)):
        line = f"{text}: **inconclusive at n = 0**: no run evaluated a " + \
            ("biped" if np.all(np.isnan(bipeds)) else "tripod") + " that did not fall."
        return {"id": "biped_above_tripod", "claim": text, "verdict": "inconclusive at n = 0",
                "line": line}

    def excess(b, t, axis=-1):
        """best biped / best tripod - 1 over the (resampled) runs."""
        with np.errstate(invalid="ignore"):
            return np.nanmax(b, axis=axis) / np.nanmax(t, axis=axis) - 1.0

    value = float(excess(bipeds, tripods))
    # the runs resampled as pairs (a run's best biped with its best tripod); a
    # resample without any tripod (or biped) has no ratio and is left out
    interval, undefined = bootstrap_paired(bipeds, tripods, excess)
    both = ~np.isnan(bipeds) & ~np.isnan(tripods)
    wins, pairs, p = sign_test_greater(bipeds[both], tripods[both])
    effect = {"name": "best biped / best tripod - 1, over all runs", "value": value,
              "interval": interval, "resamples_without_a_ratio": undefined}
    numbers = (f"{100 * value:+.1f} % ({np.nanmax(bipeds):.2f} against {np.nanmax(tripods):.2f}) "
               f"{fmt_interval(interval, '{:+.1f}', 100, ' %')} over resampled runs; a run's best "
               f"biped beats its best tripod in {wins} of {pairs} runs, one-sided sign test "
               f"p = {fmt_p(p)}")
    test = {"name": "sign test over runs, one-sided (a run's best biped > its best tripod)",
            "statistic": wins, "pairs": pairs, "p": p}
    return finding("biped_above_tripod", text, p, effect, +1, 0.0, paper,
                   n_label(*(len(of_case(runs, c)) for c in sorted({r["case"] for r in runs}))),
                   numbers, {"test": test})


def bootstrap_paired(x, y, statistic):
    """95 % percentile bootstrap interval of statistic(x, y, axis), resampling the pairs
    (x_i, y_i) together, and how many resamples had no value (NaN: dropped from the
    percentiles); (None, 0) with fewer than two pairs."""
    if len(x) < 2:
        return None, 0
    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.filterwarnings("ignore", "All-NaN slice", RuntimeWarning)
        res = stats.bootstrap((x, y), statistic, n_resamples=BOOTSTRAP_RESAMPLES, paired=True,
                              vectorized=True, axis=-1, confidence_level=CONFIDENCE,
                              method="percentile", random_state=rng())
    values = res.bootstrap_distribution
    defined = values[np.isfinite(values)]
    if len(defined) < len(values) / 2:
        return None, len(values) - len(defined)
    tail = 50 * (1 - CONFIDENCE)
    low, high = np.percentile(defined, [tail, 100 - tail])
    return (float(low), float(high)), len(values) - len(defined)


def claim_case2_later_biped(rep):
    """Case 2's best becomes a biped for good later than case 1's (the paper: the
    time-constrained scaffold hinders bipedal evolution)."""
    text = ("Case 2's best becomes a biped for good later than case 1's — paper: the "
            "time-constrained scaffold hinders bipedal evolution")
    runs = rep["runs"]
    gap = missing("case2_later_biped", text, (FREE, TIME), runs)
    if gap:
        return gap
    never = never_generation(runs)
    x = [time_to_biped(r, True, never) for r in of_case(runs, TIME)]
    y = [time_to_biped(r, True, never) for r in of_case(runs, FREE)]
    u, p, exact = rank_sum_test(x, y, "greater")
    delta = {"name": "Cliff's delta of the generation of a biped for good, case 2 vs case 1",
             "value": float(cliffs_delta(x, y)),
             "interval": bootstrap_interval((x, y), cliffs_delta)}
    numbers = (f"median generation {fmt_generation(median_time(x), never)} against "
               f"{fmt_generation(median_time(y), never)} (never: {x.count(never)} and "
               f"{y.count(never)}), Cliff's δ = {delta['value']:+.2f} "
               f"{fmt_interval(delta['interval'], '{:+.2f}')}; one-sided Mann–Whitney "
               f"U = {u:g}, p = {fmt_p(p)}")
    test = {"name": "Mann-Whitney U, one-sided (case 2 later than case 1)", "statistic": u,
            "p": p, "exact": exact}
    return finding("case2_later_biped", text, p, delta, +1, 0.0, None, n_label(len(x), len(y)),
                   numbers, {"test": test, "n": [len(x), len(y)]})


# the paper's claims, in the order of its §3
CLAIMS = (claim_case3_above_case1, claim_case3_leads_generations, claim_case2_below_case1,
          claim_case2_more_tripods, claim_biped_above_tripod, claim_case2_later_biped)
# the scaffolds' effects, tested for each learner of a reproduction with two or more
LEARNER_CLAIMS = (claim_case3_above_case1, claim_case2_below_case1, claim_case2_more_tripods)


def time_entry(values, never):
    """Per case: the median time to a biped with its bootstrap interval, the runs that
    never became one, and each run's generation; 'never' is null."""
    def generation(v):
        """A JSON generation: an integer, or null for never."""
        return None if v >= never - 0.5 else int(round(v))
    interval = bootstrap_interval((values,), median_time)
    return {"median": generation(float(median_time(values))),
            "interval": None if interval is None else [generation(v) for v in interval],
            "never": values.count(never), "runs": [generation(v) for v in values]}


def case_table(rep):
    """Per case (in the order summary.json's runs list them): final best, tripods and
    time to a biped, with intervals."""
    out = {}
    names = []
    never = never_generation(rep["runs"]) if rep["runs"] else 0
    for r in rep["runs"]:
        if r["case"] not in names:
            names.append(r["case"])
    for case in names:
        runs = of_case(rep["runs"], case)
        x = finals(runs)
        k = tripod_finals(runs)
        first = [time_to_biped(r, False, never) for r in runs]
        good = [time_to_biped(r, True, never) for r in runs]
        out[case] = {
            "runs": len(runs),
            "final_best": {"mean": float(np.mean(x)), "median": float(np.median(x)),
                           "mean_interval": json_interval(bootstrap_interval((x,), np.mean))},
            "tripod_finals": {"tripods": k, "share": k / len(runs),
                              "wilson": json_interval(wilson_interval(k, len(runs)))},
            "first_biped_generation": time_entry(first, never),
            "biped_for_good_generation": time_entry(good, never),
        }
    return out


def evaluate(rep):
    """The claims block of summary.json."""
    return {"rule": RULE, "alpha": ALPHA, "confidence": CONFIDENCE,
            "bootstrap": {"method": "percentile", "resamples": BOOTSTRAP_RESAMPLES, "seed": SEED},
            "permutations": {"exact_up_to_splits": EXACT_SPLITS,
                             "monte_carlo": MONTE_CARLO_PERMUTATIONS, "seed": SEED},
            "cases": case_table(rep),
            "findings": [claim(rep) for claim in CLAIMS],
            **({"learners": [{"learner": name,
                              "findings": [claim({**rep, "runs": runs}) for claim in LEARNER_CLAIMS]}
                             for name, runs in rep["learners"].items()]}
               if rep.get("learners") else {})}


# ----------------------------------------------------------------------------- output

def markdown(block):
    """The '## Claims' section of summary.md."""
    lines = ["## Claims", "",
             "Each claim of the paper, tested on these runs. Verdict rule: " + block["rule"] +
             ". Intervals are 95 % (bootstrap: percentile, "
             f"{block['bootstrap']['resamples']} resamples, seed {block['bootstrap']['seed']}; "
             "Wilson and Newcombe for proportions).", ""]
    lines += [f"- {f['line']}" for f in block["findings"]]
    lines += ["", "| case | runs | final best: mean [95 %] | final best is a tripod [Wilson 95 %] "
              "| first biped best: median generation [95 %] | biped for good from: median [95 %] |",
              "|---|---|---|---|---|---|"]

    def gen_cell(entry):
        """'median [low, high] (never: k)'"""
        ci = entry["interval"]
        text = fmt_generation(entry["median"])
        text += (" [" + ", ".join(fmt_generation(v) for v in ci) + "]") if ci else ""
        return text + (f" (never: {entry['never']})" if entry["never"] else "")

    for case, c in block["cases"].items():
        t = c["tripod_finals"]
        lines.append(
            f"| {case} | {c['runs']} | {c['final_best']['mean']:.2f} "
            f"{fmt_interval(c['final_best']['mean_interval'])} | {t['tripods']} of {c['runs']} "
            f"{fmt_interval(t['wilson'], '{:.0f}', 100, ' %')} | "
            f"{gen_cell(c['first_biped_generation'])} | {gen_cell(c['biped_for_good_generation'])} |")
    if block.get("learners"):
        lines += ["", "The scaffolds' effects for each learner, by the same tests and rule:", ""]
        lines += [f"- {entry['learner']}: {f['line']}" for entry in block["learners"]
                  for f in entry["findings"]]
    return "\n".join(lines) + "\n"


def replace_section(md, section):
    """md with its '## Claims' section replaced by `section`, or `section` put before
    '## Figures' (or at the end) when it has none."""
    lines = md.splitlines(keepends=True)
    start = next((i for i, l in enumerate(lines) if l.rstrip("\n") == "## Claims"), None)
    if start is not None:
        end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")),
                   len(lines))
        del lines[start:end]
    else:
        start = next((i for i, l in enumerate(lines) if l.rstrip("\n") == "## Figures"),
                     len(lines))
        if start > 0 and lines[start - 1].strip():
            section = "\n" + section
    return "".join(lines[:start]) + section + "\n" + "".join(lines[start:])


def write_atomically(path, text):
    """Write text to path through a temporary file renamed into place."""
    temporary = f"{path}.tmp.{os.getpid()}"
    try:
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def write_claims(run_dir, block):
    """Add the block to summary.json and its section to summary.md."""
    summary_path = os.path.join(run_dir, "summary.json")
    with open(summary_path, encoding="utf-8") as f:
        summary = json.load(f)
    summary["claims"] = finite_or_null(block)
    md_path = os.path.join(run_dir, "summary.md")
    md = ""
    if os.path.isfile(md_path):
        with open(md_path, encoding="utf-8") as f:
            md = f.read()
    # both texts first: a failure leaves both files as they were
    json_text = json.dumps(summary, indent=2, sort_keys=True, ensure_ascii=False,
                           allow_nan=False) + "\n"
    md_text = replace_section(md, markdown(block))
    write_atomically(summary_path, json_text)
    write_atomically(md_path, md_text)


def main(argv=None):
    """Parse arguments, test the claims, write them; returns the exit status."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="reproduction directory (with summary.json)")
    args = parser.parse_args(argv)
    try:
        if not os.path.isdir(args.run_dir):
            raise InputError(f"{args.run_dir}: not a directory")
        block = evaluate(load_reproduction(args.run_dir))
        write_claims(args.run_dir, block)
    except InputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    except OSError as e:
        print(f"error: writing the claims failed: {e}", file=sys.stderr)
        return 1
    for f in block["findings"]:
        print(f["line"].replace("**", ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
