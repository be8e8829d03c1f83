#!/usr/bin/python3
"""The accuracy criterion of docs/performance.md ("Accuracy"), judged over a set of genomes.

Reads what `build/bench/accuracy --json FILE ...` wrote: for every genome an ensemble at the
production settings and one at the reference, 100x tighter tolerances, both perturbed alike
(control/accuracy.h). Several files are judged as one set; they must agree on the settings, the
ensemble size and the perturbation.

Each genome:
- regular: the reference's interquartile range is under 2 % of its median (of 1 when the median is
  smaller than 1); its fitness agrees when the two medians are within 1 % or production's median
  lies inside the reference's interquartile range;
- irregular (the others): a two-sample Kolmogorov-Smirnov test (SciPy) of the two ensembles, its
  p-value Holm-corrected over every irregular genome of the set; its fitness agrees when the
  corrected p-value exceeds 0.05 (a family-wise 0.05);
- the majority's gait class and fall verdict agree;
- no lost walker: a genome whose reference median is >= 5 (a walker) must not have a production
  majority (more than half its members) <= 1 (a walker that went nowhere);
- no numerical walker: nor a production majority >= 5 while the reference median is <= 1.

The set, beside every genome passing:
- no drift: the median over the genomes of the signed relative difference of the medians,
  (production - reference) / max(1, |reference|), lies within +-1 %;
- and Spearman's rank correlation of the production medians against the reference medians is
  >= 0.95 (applied to sets of at least 3 genomes whose reference medians are not all equal).

  accuracy.py FILE.json [FILE.json ...] [--markdown OUT]

Prints one line per genome and the verdict; exits 0 when the set passes, 1 when it does not, 2 on
bad input.
"""

import argparse
import json
import math
import statistics
import sys

import numpy
from scipy import stats

REGULAR_IQR = 0.02  # of the reference median (control/accuracy.h kRegularIqr)
REGULAR_MEDIANS = 0.01  # relative (kRegularMedians)
FAMILY_ALPHA = 0.05  # family-wise, over the irregular genomes' KS tests
DRIFT = 0.01  # the median signed relative difference, at most this far from 0
SPEARMAN = 0.95  # production medians against reference medians, at least
SPEARMAN_MIN_GENOMES = 3
WALKER = 5.0  # a walker's fitness, at least (kWalkerFitness)
NON_WALKER = 1.0  # a walker that went nowhere, at most (kNonWalkerFitness)
# what the files of one set must share
SHARED = ("settings", "relative_tolerance", "absolute_tolerance_position", "absolute_tolerance_velocity",
          "ensemble", "perturbation")


def signed_difference(value, reference):
    return (value - reference) / max(1.0, abs(reference))


def quartiles(values):
    return tuple(float(q) for q in numpy.quantile(values, [0.25, 0.75]))  # linear, as control/accuracy.cc


def majority(count, size):
    return 2 * count > size


def judge(genome):
    """One genome's own rules (a dict); an irregular genome's KS p-value is not yet corrected."""
    production, reference = genome["production"], genome["tight"]
    a, b = production["fitness"], reference["fitness"]
    median, reference_median = statistics.median(a), statistics.median(b)
    low, high = quartiles(b)
    production_low, production_high = quartiles(a)
    regular = high - low < REGULAR_IQR * max(1.0, abs(reference_median))
    difference = signed_difference(median, reference_median)
    verdict = {
        "genome": genome["genome"],
        "median": median,
        "tight_median": reference_median,
        "tight_iqr": [low, high],
        "iqr": [production_low, production_high],
        "regular": regular,
        # production's ensemble spreads as a chaotic walker's does (the reference's test, on production)
        "production_spreads": production_high - production_low >= REGULAR_IQR * max(1.0, abs(median)),
        "signed_difference": difference,
        "median_difference": abs(difference),
        "ks_p": None,
        "ks_p_holm": None,
        "fitness_agrees": regular and (abs(difference) < REGULAR_MEDIANS or low <= median <= high),
    }
    if not regular:
        # identical ensembles (e.g. every member falls) are indistinguishable by definition
        verdict["ks_p"] = 1.0 if sorted(a) == sorted(b) else float(stats.ks_2samp(a, b).pvalue)
    gait = all(
        majority(production[k], len(a)) == majority(reference[k], len(b)) for k in ("bipeds", "tripods")
    )
    fall = majority(production["falls"], len(a)) == majority(reference["falls"], len(b))
    # a walk made or broken by the integration error
    lost = reference_median >= WALKER and majority(sum(f <= NON_WALKER for f in a), len(a))
    numerical = reference_median <= NON_WALKER and majority(sum(f >= WALKER for f in a), len(a))
    verdict.update(gait_agrees=gait, fall_agrees=fall, lost_walker=lost, numerical_walker=numerical,
                   steps_median=production.get("steps_median"), wall_ms_median=production.get("wall_ms_median"))
    verdict["passes"] = verdict["fitness_agrees"] and gait and fall and not lost and not numerical
    return verdict


def holm(pvalues):
    """Holm's step-down adjusted p-values, in the given order: the k-th smallest of m is multiplied
    by m - k + 1, capped at 1, and made non-decreasing in that order."""
    order = sorted(range(len(pvalues)), key=lambda i: pvalues[i])
    adjusted = [0.0] * len(pvalues)
    running = 0.0
    for rank, i in enumerate(order):
        running = max(running, min(1.0, (len(pvalues) - rank) * pvalues[i]))
        adjusted[i] = running
    return adjusted


def judge_set(genomes):
    """Every genome's verdict (list of dicts) and the set's (a dict)."""
    verdicts = [judge(g) for g in genomes]
    irregular = [v for v in verdicts if not v["regular"]]
    for v, p in zip(irregular, holm([v["ks_p"] for v in irregular])):
        v["ks_p_holm"] = p
        v["fitness_agrees"] = p > FAMILY_ALPHA
        v["passes"] = (v["fitness_agrees"] and v["gait_agrees"] and v["fall_agrees"] and not v["lost_walker"]
                       and not v["numerical_walker"])
    drift = statistics.median(v["signed_difference"] for v in verdicts)
    medians = [v["median"] for v in verdicts]
    reference = [v["tight_median"] for v in verdicts]
    spearman = None  # not applied
    if len(verdicts) >= SPEARMAN_MIN_GENOMES and len(set(reference)) > 1:
        # production medians all equal have no ranks: nan, which fails
        spearman = float(stats.spearmanr(medians, reference).correlation) if len(set(medians)) > 1 else math.nan
    spearman_passes = spearman is None or spearman >= SPEARMAN  # nan fails
    genomes_pass = sum(v["passes"] for v in verdicts)
    # how much the reference spreads the walkers that production spreads: its IQR over production's
    ratios = [(v["tight_iqr"][1] - v["tight_iqr"][0]) / (v["iqr"][1] - v["iqr"][0])
              for v in verdicts if v["production_spreads"]]
    return verdicts, {
        "spread_ratio": statistics.median(ratios) if ratios else None,
        "spreading": len(ratios),
        "genomes": len(verdicts),
        "genomes_pass": genomes_pass,
        "irregular": len(irregular),
        "drift": drift,
        "drift_passes": abs(drift) <= DRIFT,
        "spearman": spearman,
        "spearman_passes": spearman_passes,
        "passes": genomes_pass == len(verdicts) and abs(drift) <= DRIFT and spearman_passes,
    }


def check_genome(genome):
    """Raises ValueError naming the genome and the field when an entry is not what the tool writes."""
    name = genome.get("genome", "?") if isinstance(genome, dict) else "?"
    if not isinstance(genome, dict) or not isinstance(genome.get("genome"), str):
        raise ValueError(f"genome {name}: no name (\"genome\")")
    for side in ("production", "tight"):
        ensemble = genome.get(side)
        if not isinstance(ensemble, dict):
            raise ValueError(f"genome {name}: no {side} ensemble")
        fitness = ensemble.get("fitness")
        if not isinstance(fitness, list) or not fitness or not all(isinstance(f, (int, float)) for f in fitness):
            raise ValueError(f"genome {name}: {side}.fitness must be a non-empty list of numbers")
        for key in ("bipeds", "tripods", "falls"):
            if not isinstance(ensemble.get(key), int) or not 0 <= ensemble[key] <= len(fitness):
                raise ValueError(f"genome {name}: {side}.{key} must be a count in 0..{len(fitness)}")


def load(paths):
    """The shared header and the genomes of one or more files of the accuracy tool."""
    header, genomes, names = None, [], {}
    for path in paths:
        try:
            with open(path) as f:
                data = json.load(f)
            shared = {key: data.get(key) for key in SHARED}
            if header is None:
                header = shared
            for key in SHARED:
                if shared[key] != header[key]:
                    raise ValueError(f"{key} is {shared[key]!r}, but {paths[0]} has {header[key]!r}: "
                                     "one set needs the same settings, ensemble and perturbation")
            for g in data["genomes"]:
                check_genome(g)
                if g["genome"] in names:
                    raise ValueError(f"genome {g['genome']} is also in {names[g['genome']]}")
                names[g["genome"]] = path
                genomes.append(g)
        except (OSError, ValueError, KeyError, TypeError) as e:
            raise ValueError(f"{path}: {e}") from e
    if not genomes:
        raise ValueError(f"{', '.join(paths)}: no genomes")
    return header, genomes


def markdown(header, verdicts, verdict):
    perturbation = header.get("perturbation") or {"kind": "tolerance", "step": 1e-4}
    lines = [
        f"Settings: {header['settings']} (rtol {header['relative_tolerance']:g}, atol_q "
        f"{header['absolute_tolerance_position']:g}, atol_v {header['absolute_tolerance_velocity']:g}); "
        f"ensembles of {header['ensemble']} against 100x tighter tolerances, perturbed by "
        f"{perturbation['kind']} in steps of {perturbation['step']:g}.",
        "",
        "| genome | median [IQR] | reference: median [IQR] | regular | medians differ | KS p (Holm) | gait, fall "
        "| walker | passes | steps | ms |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for v in verdicts:
        ks = "—" if v["ks_p"] is None else f"{v['ks_p']:.3f} ({v['ks_p_holm']:.3f})"
        lines.append(
            f"| {v['genome']} | {v['median']:.3f} [{v['iqr'][0]:.3f}, {v['iqr'][1]:.3f}] | "
            f"{v['tight_median']:.3f} [{v['tight_iqr'][0]:.3f}, "
            f"{v['tight_iqr'][1]:.3f}] | {'yes' if v['regular'] else 'no'} | {100 * v['signed_difference']:+.2f} % | "
            f"{ks} | {'agree' if v['gait_agrees'] and v['fall_agrees'] else 'DIFFER'} | "
            f"{'LOST' if v['lost_walker'] else 'NUMERICAL' if v['numerical_walker'] else 'kept'} | "
            f"{'yes' if v['passes'] else '**no**'} | {v['steps_median']:.0f} | {v['wall_ms_median']:.1f} |")
    spearman = "not applied" if verdict["spearman"] is None else f"{verdict['spearman']:.3f}"
    lines += [
        "",
        f"{verdict['genomes_pass']} of {verdict['genomes']} genomes pass ({verdict['irregular']} irregular, KS "
        f"Holm-corrected over them); drift: median relative difference {100 * verdict['drift']:+.2f} % "
        f"({'within' if verdict['drift_passes'] else 'OUTSIDE'} ±{100 * DRIFT:g} %), Spearman {spearman} "
        f"({'passes' if verdict['spearman_passes'] else 'FAILS'} ≥ {SPEARMAN}); "
        f"the set {'passes' if verdict['passes'] else '**fails**'}. Median "
        f"{statistics.median(v['steps_median'] for v in verdicts):.0f} steps and "
        f"{statistics.median(v['wall_ms_median'] for v in verdicts):.1f} ms per evaluation.",
        "",
        f"Spread: production's ensemble spreads {verdict['spreading']} of the {verdict['genomes']} genomes "
        f"(IQR >= {100 * REGULAR_IQR:g} % of the median)"
        + ("." if verdict["spread_ratio"] is None else
           f"; on them the reference's IQR is a median {verdict['spread_ratio']:.2f} of production's."),
    ]
    return "\n".join(lines) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("json", nargs="+", help="output of build/bench/accuracy --json; several make one set")
    parser.add_argument("--markdown", help="also write the table as Markdown")
    args = parser.parse_args(argv)
    try:
        header, genomes = load(args.json)
        verdicts, verdict = judge_set(genomes)
    except (ValueError, KeyError, TypeError) as e:
        print(f"accuracy.py: {e}", file=sys.stderr)
        return 2
    table = markdown(header, verdicts, verdict)
    print(table, end="")
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(table)
    return 0 if verdict["passes"] else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
