"""The paper's claims tested on a reproduction, each with a verdict (docs/statistics.md).

The claims about final fitness (case 3 above case 1, case 2 below case 1, the best biped
against the best tripod) use each finalist's re-scored median (reproduction.json's
ensembles): one recorded fitness of a chaotic walker is one draw. The claims about the
course of evolution (case 3 leading in most generations, case 2's tripods, the time to a
biped) use the runs' recorded curves and gaits. The paper's cases are named by their
numbers 1, 2, 3: the places of the scaffolds in reproduction.json.

Beside each test between cases stands its paired counterpart over replicates
(replicate r of every case starts from seed r: docs/statistics.md, "The paired design"):
Wilcoxon's signed-rank test for fitness, the sign test for gaits and generations. It
decides nothing: the verdicts are the rule's, below.

Verdict rule, per claim (ALPHA = 0.05, intervals at 95 %):
  reproduced       the one-sided test in the paper's direction gives p < 0.05;
  not reproduced   otherwise, when our 95 % interval of the effect lies wholly on the
                   no-effect side of the paper's value: beyond it, for a claim the
                   paper gives a number for (83 %, 66 %, 2 of 3, +37.5 %), or at or
                   beyond no effect, for a claim of direction only;
  inconclusive at n = N   otherwise (N: runs per case).
"""
from collections import namedtuple

import numpy as np

from . import paper as the_paper
from .load import of_case, paper_cases
from .statistics import (ALPHA, BOOTSTRAP_RESAMPLES, CONFIDENCE, EXACT_SPLITS,
                         MONTE_CARLO_PERMUTATIONS, SEED, biped_for_good, bootstrap_interval,
                         bootstrap_paired, cliffs_delta, common_curves, curve_test, first_biped,
                         fisher_p, hodges_lehmann, median_time, newcombe_interval,
                         rank_sum_test, ratio_of_means, share_interval, share_leading,
                         sign_test_greater, signed_rank_test, wilson_interval)
from .text import fmt_generation, fmt_interval, fmt_p, json_interval, n_label

REPRODUCED, NOT_REPRODUCED = "reproduced", "not reproduced"
RULE = ("reproduced: the one-sided test in the paper's direction gives p < 0.05; "
        "not reproduced: otherwise, when our 95 % interval of the effect lies wholly on "
        "the no-effect side of the paper's value (of no effect itself, for a claim of "
        "direction only); inconclusive at n = N (runs per case) otherwise. The tests "
        "compare the cases' runs as independent samples; the paired tests over "
        "replicates stand beside them and decide nothing")


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




# ----------------------------------------------------------------------------- inputs

def claim_run(run):
    """What the claims use of a run (load.load_run's): its recorded curve and gaits, and
    its finals' re-scored medians (None for a finalist it lacks)."""
    def median(key):
        """The re-scored median of a finalist, or None."""
        return None if run[key] is None else run[key]["rescore"]["median"]
    return {"case": run["case"], "replicate": run["replicate"], "dir": run["dir"],
            "generation": [int(g) for g in run["data"]["generation"]],
            "best_fitness": [float(f) for f in run["data"]["best_fitness"]],
            "best_gait": list(run["data"]["best_gait"]),
            "final": median("final_best"), "best_biped": median("best_biped"),
            "best_tripod": median("best_tripod")}


def claims_input(rep):
    """What the claims read of a loaded reproduction (load.load_reproduction): the first
    learner's runs, the names of the paper's cases 1, 2, 3 and of every case, the paper's
    values, and with two learners or more every learner's runs."""
    learners = {}
    if len(rep["learners"]) > 1:
        for learner in rep["learners"]:
            learners[learner["name"]] = [claim_run(r) for r in rep["runs"]
                                         if r["learner"] == learner["name"]]
    return {"runs": [claim_run(r) for r in rep["primary"]],
            "cases": paper_cases(rep["scaffolds"]),
            "every_case": [s["name"] for s in rep["scaffolds"]],
            "paper": {"share": the_paper.CASE3_LEADS_SHARE, "ratio": the_paper.CASE2_OVER_CASE1,
                      "biped_over_tripod": the_paper.BIPED_OVER_TRIPOD,
                      "tripods": {s["name"]: s["paper_tripod_finals"] for s in rep["scaffolds"]}},
            "learners": learners}


# ----------------------------------------------------------------------------- the claims

def finals(runs):
    """Each run's final best fitness: its re-scored median."""
    return [r["final"] for r in runs]


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


# A claim of the paper: its id in summary.json, what it says and the paper's own figure
# or words for it ("in 83 %").
Claim = namedtuple("Claim", "id statement paper_says")


def claim_text(claim):
    """'statement — paper: what the paper says', a finding's `claim`."""
    return f"{claim.statement} — paper: {claim.paper_says}"


def undecided(claim, why):
    """The finding of a claim that these runs cannot test at all."""
    v = "inconclusive at n = 0"
    return {"id": claim.id, "claim": claim_text(claim), "statement": claim.statement,
            "paper_says": claim.paper_says, "we_find": "—", "verdict": v,
            "line": f"{claim_text(claim)}: **{v}**: {why}."}


def missing(claim, needed, runs):
    """The finding of a claim that lacks runs of a case it compares."""
    absent = [c for c in needed if not of_case(runs, c)]
    if not absent:
        return None
    return undecided(claim, f"no runs of case {', '.join(absent)}")


def compared_finals(claim, runs, case_x, case_y):
    """(None, x, y): the re-scored finals of case_x's and case_y's runs; or (the finding
    of a claim that lacks runs of one of them, None, None)."""
    gap = missing(claim, (case_y, case_x), runs)
    if gap:
        return gap, None, None
    return None, finals(of_case(runs, case_x)), finals(of_case(runs, case_y))


def replicate_pairs(runs, cases, value):
    """value(run) of each case's runs, for the replicates every one of `cases` has, in
    replicate order: one list per case, the k-th entries of one replicate."""
    by_case = [{r["replicate"]: value(r) for r in of_case(runs, c)} for c in cases]
    common = sorted(set.intersection(*(set(values) for values in by_case)))
    return [[values[r] for r in common] for values in by_case]


def paired_signed_rank(x, y, alternative, direction):
    """The one-sided signed-rank test of replicate pairs (x_r, y_r): its record for
    summary.json and its words for the line."""
    w, pairs, p, exact = signed_rank_test(x, y, alternative)
    return ({"name": f"Wilcoxon signed-rank over replicates, one-sided ({direction})",
             "statistic": w, "pairs": pairs, "p": p, "exact": exact},
            f"paired over replicates: Wilcoxon signed-rank W+ = {w:g} of {pairs} pairs that "
            f"differ, p = {fmt_p(p)}")


def paired_sign(x, y, direction):
    """The one-sided sign test that x_r > y_r in most replicates: its record and words."""
    wins, pairs, p = sign_test_greater(x, y)
    return ({"name": f"sign test over replicates, one-sided ({direction})", "statistic": wins,
             "pairs": pairs, "p": p},
            f"paired over replicates: sign test, {wins} of {pairs} pairs that differ, "
            f"p = {fmt_p(p)}")


def mann_whitney(x, y, alternative, direction):
    """The one-sided Mann-Whitney test of x against y ('greater' or 'less'): U, p and the
    test's record for summary.json, named with its direction (e.g. "case 3 > case 1")."""
    u, p, exact = rank_sum_test(x, y, alternative)
    return u, p, {"name": f"Mann-Whitney U, one-sided ({direction})", "statistic": u, "p": p,
                  "exact": exact}


def two_sample_effect(name, statistic, x, y):
    """An effect of x against y: statistic(x, y) with its bootstrap interval."""
    return {"name": name, "value": float(statistic(x, y)),
            "interval": bootstrap_interval((x, y), statistic)}


def finding(claim, we_find, p, effect, direction, null, paper, n, line_numbers, extra=None):
    """A claim's JSON entry, with its verdict and its line. we_find: our counterpart of
    the paper's figure, in as few words (the verdict table's cell)."""
    v = verdict(p, effect["interval"], direction, null, paper, n)
    effect = {**effect, "interval": json_interval(effect["interval"]), "null": null,
              "paper": paper, "paper_direction": "above" if direction > 0 else "below"}
    if paper is not None and effect["interval"] is not None:
        low, high = effect["interval"]
        where = "below" if paper < low else "above" if paper > high else "within"
        line_numbers += f"; the paper's value lies {where} our interval"
    out = {"id": claim.id, "claim": claim_text(claim), "statement": claim.statement,
           "paper_says": claim.paper_says, "we_find": we_find, "verdict": v, "effect": effect,
           "line": f"{claim_text(claim)}: **{v}**: {line_numbers}."}
    out.update(extra or {})
    return out


def claim_case3_above_case1(rep):
    """Case 3 ends above case 1 (final best fitness)."""
    c1, _, c3 = rep["cases"]
    claim = Claim("case3_above_case1", f"Case 3 ({c3}) ends above case 1 ({c1})",
                  "case 3 ends highest")
    gap, x, y = compared_finals(claim, rep["runs"], c3, c1)
    if gap:
        return gap
    u, p, test = mann_whitney(x, y, "greater", "case 3 > case 1")
    paired, paired_words = paired_signed_rank(
        *replicate_pairs(rep["runs"], (c3, c1), lambda r: r["final"]), "greater", "case 3 > case 1")
    delta = two_sample_effect("Cliff's delta", cliffs_delta, x, y)
    shift = two_sample_effect("Hodges-Lehmann shift", hodges_lehmann, x, y)
    numbers = (f"final best {np.mean(x):.2f} against {np.mean(y):.2f} (means of the re-scored "
               f"medians), Cliff's δ = "
               f"{delta['value']:+.2f} {fmt_interval(delta['interval'], '{:+.2f}')}, "
               f"Hodges–Lehmann shift {shift['value']:+.2f} "
               f"{fmt_interval(shift['interval'], '{:+.2f}')}; "
               f"one-sided Mann–Whitney U = {u:g}, p = {fmt_p(p)}; {paired_words}")
    return finding(claim, f"{np.mean(x):.2f} against {np.mean(y):.2f}", p, delta, +1, 0.0, None,
                   n_label(len(x), len(y)),
                   numbers, {"test": test, "paired_test": paired, "n": [len(x), len(y)],
                             "hodges_lehmann": {"value": shift["value"],
                                                "interval": json_interval(shift["interval"])}})


def claim_case3_leads_generations(rep):
    """Case 3's mean best leads case 1's in most generations (the paper: 83 %)."""
    claim = Claim("case3_leads_generations", "Case 3's mean best leads case 1's in most generations",
                  f"in {100 * rep['paper']['share']:.0f} %")
    c1, _, c3 = rep["cases"]
    runs = rep["runs"]
    gap = missing(claim, (c1, c3), runs)
    if gap:
        return gap
    a = [r["best_fitness"] for r in of_case(runs, c3)]
    b = [r["best_fitness"] for r in of_case(runs, c1)]
    share = share_leading(a, b)
    area, p, exact = curve_test(a, b)
    interval = share_interval(a, b)
    generations = common_curves(a, b)[0].shape[1]
    paired, paired_words = paired_signed_rank(
        *replicate_pairs(runs, (c3, c1), lambda r: float(np.mean(r["best_fitness"][:generations]))),
        "greater", "case 3 > case 1")
    numbers = (f"{100 * share:.1f} % of {generations} generations "
               f"{fmt_interval(interval, '{:.1f}', 100, ' %')}; best fitness averaged over the "
               f"generations, case 3 − case 1: {area:+.2f}, one-sided permutation "
               f"p = {fmt_p(p)}; {paired_words}")
    test = {"name": "permutation test of the replicates' best fitness averaged over the "
                    "generations, case 3 - case 1, one-sided", "statistic": area, "p": p,
            "exact": exact}
    effect = {"name": "share of generations", "value": share, "interval": interval}
    return finding(claim, f"in {100 * share:.1f} %", p, effect, +1, 0.5, rep["paper"]["share"],
                   n_label(len(a), len(b)), numbers,
                   {"test": test, "paired_test": paired, "n": [len(a), len(b)],
                    "generations": generations})


def claim_case2_below_case1(rep):
    """Case 2 ends below case 1 (the paper: at 66 % of it)."""
    paper = rep["paper"]["ratio"]
    c1, c2, _ = rep["cases"]
    claim = Claim("case2_below_case1", f"Case 2 ({c2}) ends below case 1 ({c1})",
                  f"at {100 * paper:.0f} % of case 1")
    gap, x, y = compared_finals(claim, rep["runs"], c2, c1)
    if gap:
        return gap
    u, p, test = mann_whitney(x, y, "less", "case 2 < case 1")
    paired, paired_words = paired_signed_rank(
        *replicate_pairs(rep["runs"], (c2, c1), lambda r: r["final"]), "less", "case 2 < case 1")
    ratio = two_sample_effect("ratio of the final mean best fitness (re-scored medians), "
                              "case 2 / case 1", ratio_of_means, x, y)
    numbers = (f"case 2's final mean best is {100 * ratio['value']:.1f} % of case 1's "
               f"{fmt_interval(ratio['interval'], '{:.1f}', 100, ' %')}, Cliff's δ = "
               f"{float(cliffs_delta(x, y)):+.2f}; one-sided Mann–Whitney U = {u:g}, "
               f"p = {fmt_p(p)}; {paired_words}")
    return finding(claim, f"at {100 * ratio['value']:.1f} % of case 1", p, ratio, -1, 1.0, paper,
                   n_label(len(x), len(y)), numbers, {"test": test, "paired_test": paired,
                                                      "n": [len(x), len(y)],
                             "cliffs_delta": float(cliffs_delta(x, y))})


def claim_case2_more_tripods(rep):
    """Case 2 ends as a tripod more often than cases 1 and 3 (the paper: 2 of 3, 0 of 6)."""
    paper = rep["paper"]["tripods"]
    c1, c2, c3 = rep["cases"]
    others = (c1, c3)
    k2p, kop = paper[c2], sum(paper[c] for c in others)
    n2p, nop = the_paper.RUNS_PER_CASE, the_paper.RUNS_PER_CASE * len(others)
    claim = Claim("case2_more_tripods", "Case 2 ends as a tripod more often than cases 1 and 3",
                  f"{k2p} of {n2p} against {kop} of {nop}")
    runs = rep["runs"]
    gap = missing(claim, (c1, c2, c3), runs)
    if gap:
        return gap
    time_runs = of_case(runs, c2)
    other_runs = [r for c in others for r in of_case(runs, c)]
    k2, n2 = tripod_finals(time_runs), len(time_runs)
    ko, no = tripod_finals(other_runs), len(other_runs)
    p = fisher_p(k2, n2, ko, no, "greater")
    # paired: per replicate, case 2's tripod (1 or 0) against the mean of cases 1 and 3
    t1, t2, t3 = replicate_pairs(runs, (c1, c2, c3),
                                 lambda r: float(r["best_gait"][-1] == "tripod"))
    paired, paired_words = paired_sign(t2, [(a + b) / 2 for a, b in zip(t1, t3)],
                                       "case 2 > cases 1 and 3")
    w2, wo = wilson_interval(k2, n2), wilson_interval(ko, no)
    effect = {"name": "difference of the shares ending as tripods, case 2 - cases 1 and 3",
              "value": k2 / n2 - ko / no, "interval": newcombe_interval(k2, n2, ko, no)}
    numbers = (f"{k2} of {n2} {fmt_interval(w2, '{:.0f}', 100, ' %')} against {ko} of {no} "
               f"{fmt_interval(wo, '{:.0f}', 100, ' %')} (Wilson), difference "
               f"{100 * effect['value']:+.0f} points "
               f"{fmt_interval(effect['interval'], '{:+.0f}', 100)} (Newcombe); one-sided "
               f"Fisher's exact p = {fmt_p(p)}; {paired_words}")
    test = {"name": "Fisher's exact, one-sided (case 2 > cases 1 and 3)", "p": p}
    shares = {"case2": {"tripods": k2, "runs": n2, "wilson": json_interval(w2)},
              "cases1and3": {"tripods": ko, "runs": no, "wilson": json_interval(wo)}}
    return finding(claim, f"{k2} of {n2} against {ko} of {no}", p, effect, +1, 0.0,
                   k2p / n2p - kop / nop,
                   n_label(*(len(of_case(runs, c)) for c in (c1, c2, c3))), numbers,
                   {"test": test, "paired_test": paired, "shares": shares})


def claim_biped_above_tripod(rep):
    """The best biped walks further than the best tripod (the paper: +37.5 %)."""
    paper = rep["paper"]["biped_over_tripod"] - 1.0
    claim = Claim("biped_above_tripod", "The best biped walks further than the best tripod",
                  f"{100 * paper:+.1f} %")
    runs = rep["runs"]
    bipeds = np.array([np.nan if r["best_biped"] is None else r["best_biped"] for r in runs])
    tripods = np.array([np.nan if r["best_tripod"] is None else r["best_tripod"] for r in runs])
    if np.all(np.isnan(bipeds)) or np.all(np.isnan(tripods)):
        gait = "biped" if np.all(np.isnan(bipeds)) else "tripod"
        return undecided(claim, f"no run evaluated a {gait} that did not fall")

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
    effect = {"name": "best biped / best tripod - 1 (re-scored medians), over all runs",
              "value": value,
              "interval": interval, "resamples_without_a_ratio": undefined}
    numbers = (f"{100 * value:+.1f} % ({np.nanmax(bipeds):.2f} against {np.nanmax(tripods):.2f}) "
               f"{fmt_interval(interval, '{:+.1f}', 100, ' %')} over resampled runs; a run's best "
               f"biped beats its best tripod in {wins} of {pairs} runs, one-sided sign test "
               f"p = {fmt_p(p)}")
    test = {"name": "sign test over runs, one-sided (a run's best biped > its best tripod)",
            "statistic": wins, "pairs": pairs, "p": p}
    return finding(claim, f"{100 * value:+.1f} %", p, effect, +1, 0.0, paper,
                   n_label(*(len(of_case(runs, c)) for c in sorted({r["case"] for r in runs}))),
                   numbers, {"test": test})


def claim_case2_later_biped(rep):
    """Case 2's best becomes a biped for good later than case 1's (the paper: the
    time-constrained scaffold hinders bipedal evolution)."""
    claim = Claim("case2_later_biped", "Case 2's best becomes a biped for good later than case 1's",
                  "the time-constrained scaffold hinders bipedal evolution")
    c1, c2, _ = rep["cases"]
    runs = rep["runs"]
    gap = missing(claim, (c1, c2), runs)
    if gap:
        return gap
    never = never_generation(runs)
    x = [time_to_biped(r, True, never) for r in of_case(runs, c2)]
    y = [time_to_biped(r, True, never) for r in of_case(runs, c1)]
    u, p, test = mann_whitney(x, y, "greater", "case 2 later than case 1")
    paired, paired_words = paired_sign(
        *replicate_pairs(runs, (c2, c1), lambda r: time_to_biped(r, True, never)),
        "case 2 later than case 1")
    delta = two_sample_effect("Cliff's delta of the generation of a biped for good, case 2 vs "
                              "case 1", cliffs_delta, x, y)
    medians = (f"median generation {fmt_generation(median_time(x), never)} against "
               f"{fmt_generation(median_time(y), never)}")
    numbers = (f"{medians} (never: {x.count(never)} and {y.count(never)}), Cliff's δ = "
               f"{delta['value']:+.2f} {fmt_interval(delta['interval'], '{:+.2f}')}; one-sided "
               f"Mann–Whitney U = {u:g}, p = {fmt_p(p)}; {paired_words}")
    return finding(claim, medians, p, delta, +1, 0.0, None, n_label(len(x), len(y)),
                   numbers, {"test": test, "paired_test": paired, "n": [len(x), len(y)]})


# the paper's claims, in the order of its §3
CLAIMS = (claim_case3_above_case1, claim_case3_leads_generations, claim_case2_below_case1,
          claim_case2_more_tripods, claim_biped_above_tripod, claim_case2_later_biped)
# the scaffolds' effects, tested for each learner of a reproduction with two or more
LEARNER_CLAIMS = (claim_case3_above_case1, claim_case3_leads_generations, claim_case2_below_case1,
                  claim_case2_more_tripods)


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
    """Per case that has runs (in the paper's order): final best (re-scored), tripods
    (with the paper's) and time to a biped, with intervals."""
    out = {}
    never = never_generation(rep["runs"]) if rep["runs"] else 0
    for case in rep["every_case"]:
        runs = of_case(rep["runs"], case)
        if not runs:
            continue
        x = finals(runs)
        k = tripod_finals(runs)
        first = [time_to_biped(r, False, never) for r in runs]
        good = [time_to_biped(r, True, never) for r in runs]
        out[case] = {
            "runs": len(runs),
            "final_best": {"mean": float(np.mean(x)), "median": float(np.median(x)),
                           "mean_interval": json_interval(bootstrap_interval((x,), np.mean))},
            "tripod_finals": {"tripods": k, "share": k / len(runs),
                              "wilson": json_interval(wilson_interval(k, len(runs))),
                              "paper": rep["paper"]["tripods"][case]},
            "first_biped_generation": time_entry(first, never),
            "biped_for_good_generation": time_entry(good, never),
        }
    return out


def evaluate(rep):
    """The claims block of summary.json, from claims_input's dict."""
    return {"rule": RULE, "alpha": ALPHA, "confidence": CONFIDENCE,
            "bootstrap": {"method": "percentile", "resamples": BOOTSTRAP_RESAMPLES, "seed": SEED},
            "permutations": {"exact_up_to_splits": EXACT_SPLITS,
                             "monte_carlo": MONTE_CARLO_PERMUTATIONS, "seed": SEED},
            "cases": case_table(rep),
            "findings": [claim(rep) for claim in CLAIMS],
            **({"learners": [{"learner": name, "cases": case_table({**rep, "runs": runs}),
                              "findings": [claim({**rep, "runs": runs}) for claim in LEARNER_CLAIMS]}
                             for name, runs in rep["learners"].items()]}
               if rep.get("learners") else {})}


# ----------------------------------------------------------------------------- output

def verdict_table(findings):
    """The claims at a glance: what the paper says, what we find, p (and the paired
    test's, which decides nothing) and the verdict."""
    lines = ["| the paper's claim | the paper | ours | one-sided p | paired over replicates: p "
             "| verdict |",
             "|---|---|---|---|---|---|"]
    for f in findings:
        p = f.get("test", {}).get("p")
        paired = f.get("paired_test", {}).get("p")
        lines.append(f"| {f['statement']} | {f['paper_says']} | {f['we_find']} | {fmt_p(p)} | "
                     f"{fmt_p(paired)} | **{f['verdict']}** |")
    return lines


def markdown(block):
    """The '## Claims' section of summary.md."""
    lines = ["## Claims", "",
             "Each claim of the paper, tested on these runs. Verdict rule: " + block["rule"] +
             ". Intervals are 95 % (bootstrap: percentile, "
             f"{block['bootstrap']['resamples']} resamples, seed {block['bootstrap']['seed']}; "
             "Wilson and Newcombe for proportions).", ""]
    lines += verdict_table(block["findings"]) + [""]
    lines += [f"- {f['line']}" for f in block["findings"]]
    lines += ["", "| case | runs | final best, re-scored: mean [95 %] | final best is a tripod "
              "[Wilson 95 %] | paper | first biped best: median generation [95 %] "
              "| biped for good from: median [95 %] |",
              "|---|---|---|---|---|---|---|"]

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
            f"{fmt_interval(t['wilson'], '{:.0f}', 100, ' %')} | {t['paper']} of {the_paper.RUNS_PER_CASE} | "
            f"{gen_cell(c['first_biped_generation'])} | {gen_cell(c['biped_for_good_generation'])} |")
    if block.get("learners"):
        lines += ["", "The scaffolds' effects for each learner, by the same tests and rule:", ""]
        lines += [f"- {entry['learner']}: {f['line']}" for entry in block["learners"]
                  for f in entry["findings"]]
    return "\n".join(lines) + "\n"

