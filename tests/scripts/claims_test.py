#!/usr/bin/env python3
"""Tests for scripts/claims.py: each statistic on hand-made data with known answers
(ties and single replicates included), the verdict rule, the verdict lines, and the
script on synthetic reproduction directories.

Run:  /usr/bin/python3 tests/scripts/claims_test.py   (needs numpy and scipy)

Known answers come from closed forms (Wilson's formula, hypergeometric and binomial
probabilities), from enumerating every split by hand in the test (itertools), or from
published tables (Newcombe 1998, Table II).
"""
import csv
import importlib.util
import itertools
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
import warnings

import numpy as np
from scipy import stats

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "claims.py")
Z = stats.norm.ppf(0.975)


def load_claims():
    """scripts/claims.py as a module."""
    spec = importlib.util.spec_from_file_location("claims", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


claims = load_claims()


def enumerated_rank_sum_p(x, y, alternative):
    """The exact one-sided p of the rank-sum test by listing every split of the pooled
    midranks: the share of splits whose rank sum is at least (or at most) x's."""
    ranks = stats.rankdata(list(x) + list(y))
    observed = ranks[:len(x)].sum()
    sums = [sum(ranks[i] for i in chosen)
            for chosen in itertools.combinations(range(len(ranks)), len(x))]
    if alternative == "greater":
        hits = sum(s >= observed - 1e-9 for s in sums)
    else:
        hits = sum(s <= observed + 1e-9 for s in sums)
    return hits / len(sums)


def wilson(k, n):
    """Wilson's score interval written out (the test's own oracle)."""
    p = k / n
    centre = (p + Z * Z / (2 * n)) / (1 + Z * Z / n)
    half = Z / (1 + Z * Z / n) * math.sqrt(p * (1 - p) / n + Z * Z / (4 * n * n))
    return centre - half, centre + half


class RankSumTest(unittest.TestCase):
    """Mann-Whitney U and its exact permutation p-value."""

    def test_separated_samples(self):
        # x above y entirely: U = 3 * 3, and 1 of the C(6, 3) = 20 splits is as extreme
        u, p, exact = claims.rank_sum_test([3, 4, 5], [0, 1, 2], "greater")
        self.assertEqual(u, 9.0)
        self.assertAlmostEqual(p, 1 / 20, places=12)
        self.assertTrue(exact)
        u, p, _ = claims.rank_sum_test([3, 4, 5], [0, 1, 2], "less")
        self.assertAlmostEqual(p, 1.0, places=12)

    def test_agrees_with_scipys_exact_mann_whitney_without_ties(self):
        gen = np.random.default_rng(5)
        for n1, n2 in ((4, 5), (6, 6), (3, 8)):
            x, y = gen.normal(0.5, 1, n1), gen.normal(0, 1, n2)
            for alternative in ("greater", "less"):
                u, p, exact = claims.rank_sum_test(x, y, alternative)
                ref = stats.mannwhitneyu(x, y, alternative=alternative, method="exact")
                self.assertTrue(exact)
                self.assertEqual(u, ref.statistic)
                self.assertAlmostEqual(p, ref.pvalue, places=12, msg=(n1, n2, alternative))

    def test_ties_are_exact(self):
        x, y = [1, 2, 2, 3], [2, 2, 0, 1, 1]
        for alternative in ("greater", "less"):
            u, p, _ = claims.rank_sum_test(x, y, alternative)
            self.assertAlmostEqual(p, enumerated_rank_sum_p(x, y, alternative), places=12)
        # U counts a tie as half a win: 1 > 0 (1), 1 = 1 twice (1), 2 > 0, 1, 1 (3) and
        # 2 = 2 twice (1), twice over, 3 > all five (5)
        self.assertEqual(u, 1 + 1 + 2 * (3 + 1) + 5)

    def test_all_tied(self):
        u, p, _ = claims.rank_sum_test([4, 4], [4, 4, 4], "greater")
        self.assertEqual(u, 3.0)
        self.assertAlmostEqual(p, 1.0, places=12)

    def test_one_replicate_each(self):
        # two splits: x above y is one of them
        u, p, exact = claims.rank_sum_test([2.0], [1.0], "greater")
        self.assertEqual((u, exact), (1.0, True))
        self.assertAlmostEqual(p, 0.5, places=12)
        with self.assertRaises(ValueError):
            claims.rank_sum_test([], [1.0], "greater")

    def test_one_replicate_against_several(self):
        # midranks 1.5 | 1.5, 3, 4: x's rank sum is the least of the four splits'
        self.assertAlmostEqual(claims.rank_sum_test([1], [1, 2, 3], "greater")[1], 1.0, places=12)
        self.assertAlmostEqual(claims.rank_sum_test([1], [1, 2, 3], "less")[1], 0.5, places=12)
        for x, y in (([3, 3, 1], [2]), ([5], [1, 5, 2, 2]), ([0.5], [1, 2])):
            for alternative in ("greater", "less"):
                self.assertAlmostEqual(claims.rank_sum_test(x, y, alternative)[1],
                                       enumerated_rank_sum_p(x, y, alternative), places=12,
                                       msg=(x, y, alternative))

    def test_large_samples_use_seeded_random_permutations(self):
        gen = np.random.default_rng(9)
        x, y = gen.normal(0.3, 1, 12), gen.normal(0, 1, 12)   # C(24, 12) > EXACT_SPLITS
        u, p, exact = claims.rank_sum_test(x, y, "greater")
        self.assertFalse(exact)
        ref = stats.mannwhitneyu(x, y, alternative="greater", method="exact").pvalue
        self.assertLess(abs(p - ref), 4 * math.sqrt(ref * (1 - ref) / claims.MONTE_CARLO_PERMUTATIONS))
        self.assertEqual(p, claims.rank_sum_test(x, y, "greater")[1])   # same seed, same bits


class EffectSizeTest(unittest.TestCase):
    """Cliff's delta, the Hodges-Lehmann shift and the ratio of means."""

    def test_cliffs_delta(self):
        self.assertEqual(claims.cliffs_delta([5, 6], [1, 2, 3]), 1.0)
        self.assertEqual(claims.cliffs_delta([1, 2, 3], [5, 6]), -1.0)
        # pairs: 1<2, 1<3, 2=2, 2<3
        self.assertEqual(claims.cliffs_delta([1, 2], [2, 3]), -0.75)
        self.assertEqual(claims.cliffs_delta([7], [7]), 0.0)

    def test_cliffs_delta_is_2u_over_pairs_minus_1(self):
        x, y = [1, 2, 2, 3, 5], [2, 2, 0, 1, 1, 4]
        u, _, _ = claims.rank_sum_test(x, y, "greater")
        self.assertAlmostEqual(claims.cliffs_delta(x, y), 2 * u / (len(x) * len(y)) - 1, places=12)

    def test_cliffs_delta_vectorised(self):
        x = np.array([[1, 2], [5, 6]])
        y = np.array([[2, 3], [1, 1]])
        np.testing.assert_array_equal(claims.cliffs_delta(x, y), [-0.75, 1.0])

    def test_hodges_lehmann(self):
        self.assertEqual(claims.hodges_lehmann([1, 2, 3], [0]), 2.0)
        self.assertEqual(claims.hodges_lehmann([1, 2], [0, 0]), 1.5)        # 1, 1, 2, 2
        self.assertEqual(claims.hodges_lehmann([4], [1]), 3.0)
        np.testing.assert_array_equal(claims.hodges_lehmann([[1, 2], [3, 3]], [[0, 0], [1, 1]]),
                                      [1.5, 2.0])

    def test_ratio_of_means(self):
        self.assertEqual(claims.ratio_of_means([1, 3], [4, 4]), 0.5)


class BootstrapTest(unittest.TestCase):
    """Percentile bootstrap intervals, seeded."""

    def test_two_points(self):
        # the mean of a resample of [0, 1] is 0, 0.5 or 1 (1/4, 1/2, 1/4): the 2.5th
        # and 97.5th percentiles are 0 and 1
        self.assertEqual(claims.bootstrap_interval(([0.0, 1.0],), np.mean), (0.0, 1.0))

    def test_constant_sample_and_single_value(self):
        self.assertEqual(claims.bootstrap_interval(([3.0, 3.0, 3.0],), np.mean), (3.0, 3.0))
        self.assertIsNone(claims.bootstrap_interval(([3.0],), np.mean))
        self.assertIsNone(claims.bootstrap_interval(([1.0, 2.0], [3.0]), claims.cliffs_delta))

    def test_separated_samples_give_delta_one(self):
        self.assertEqual(claims.bootstrap_interval(([5, 6, 7], [1, 2]), claims.cliffs_delta),
                         (1.0, 1.0))

    def test_deterministic_and_sensible(self):
        gen = np.random.default_rng(3)
        x = gen.normal(10, 2, 8)
        a = claims.bootstrap_interval((x,), np.mean)
        self.assertEqual(a, claims.bootstrap_interval((x,), np.mean))     # same bits
        self.assertLess(a[0], np.mean(x))
        self.assertGreater(a[1], np.mean(x))
        self.assertGreaterEqual(a[0], x.min())
        self.assertLessEqual(a[1], x.max())

    def test_mean_band(self):
        self.assertIsNone(claims.mean_band([[1.0, 2.0, 3.0]]))
        low, high = claims.mean_band([[0.0, 5.0, 1.0], [1.0, 5.0, 3.0]])
        # two replicates: the resampled mean is either value or their average
        np.testing.assert_array_equal(low, [0.0, 5.0, 1.0])
        np.testing.assert_array_equal(high, [1.0, 5.0, 3.0])
        gen = np.random.default_rng(4)
        curves = gen.normal(5, 1, (6, 50))
        low, high = claims.mean_band(curves)
        self.assertTrue(np.all(low <= curves.mean(axis=0)) and np.all(curves.mean(axis=0) <= high))
        self.assertTrue(np.all(low < high))
        np.testing.assert_array_equal(low, claims.mean_band(curves)[0])   # same bits

    def test_paired_bootstrap_drops_resamples_without_a_value(self):
        def ratio_of_maxima(b, t, axis=-1):
            """max b / max t, NaN when t is all NaN"""
            return np.nanmax(b, axis=axis) / np.nanmax(t, axis=axis)
        b, t = np.array([2.0, 2.0, 2.0]), np.array([1.0, np.nan, 1.0])
        interval, undefined = claims.bootstrap_paired(b, t, ratio_of_maxima)
        self.assertEqual(interval, (2.0, 2.0))
        # a resample holds only the second run with probability 1/27
        expected = claims.BOOTSTRAP_RESAMPLES / 27
        self.assertLess(abs(undefined - expected), 5 * math.sqrt(expected))
        self.assertEqual(claims.bootstrap_paired(b[:1], t[:1], ratio_of_maxima), (None, 0))


class ShareOfGenerationsTest(unittest.TestCase):
    """The share of generations in which one case's mean leads, its test and interval."""

    def test_share(self):
        a = [[1, 5, 5, 5], [3, 5, 5, 9]]     # mean 2, 5, 5, 7
        b = [[2, 4, 6, 1]]                   # 2, 4, 6, 1: a leads in generations 1 and 3
        self.assertEqual(claims.share_leading(a, b), 0.5)
        self.assertEqual(claims.share_leading([[1, 2, 3, 4]], [[0, 0]]), 1.0)  # common length

    def test_curve_test_by_enumeration(self):
        a = [[10.0, 10.0, 3.0], [11.0, 11.0, 0.0], [4.0, 9.0, 9.0]]
        b = [[0.0, 0.0, 5.0], [1.0, 8.0, 1.0], [6.0, 2.0, 2.0]]
        areas = np.array(a + b).mean(axis=1)             # 23/3, 22/3, 22/3, 5/3, 10/3, 10/3
        observed = areas[:3].mean() - areas[3:].mean()
        values = []
        for chosen in itertools.combinations(range(6), 3):
            rest = [i for i in range(6) if i not in chosen]
            values.append(areas[list(chosen)].mean() - areas[rest].mean())
        expected = np.mean(np.array(values) >= observed - 1e-12)
        difference, p, exact = claims.curve_test(a, b)
        self.assertTrue(exact)
        self.assertAlmostEqual(difference, observed, places=12)
        self.assertAlmostEqual(p, expected, places=12)
        self.assertAlmostEqual(p, 1 / 20, places=12)     # a's three are the largest

    def test_one_replicate_each(self):
        difference, p, exact = claims.curve_test([[2.0, 2.0]], [[1.0, 1.0]])
        self.assertEqual((difference, p, exact), (1.0, 0.5, True))
        self.assertIsNone(claims.share_interval([[2.0, 2.0]], [[1.0, 1.0]]))

    def test_interval(self):
        a = [[5.0, 5.0, 5.0, 5.0], [6.0, 6.0, 6.0, 6.0]]
        b = [[1.0, 1.0, 1.0, 1.0], [2.0, 2.0, 2.0, 2.0]]
        self.assertEqual(claims.share_interval(a, b), (1.0, 1.0))


class ProportionsTest(unittest.TestCase):
    """Wilson and Newcombe intervals, Fisher's exact test and the sign test."""

    def test_wilson_closed_form(self):
        for k, n in ((0, 3), (2, 3), (3, 3), (1, 1), (7, 10)):
            low, high = claims.wilson_interval(k, n)
            ref = wilson(k, n)
            self.assertAlmostEqual(low, max(0.0, ref[0]), places=12, msg=(k, n))
            self.assertAlmostEqual(high, min(1.0, ref[1]), places=12, msg=(k, n))
        # none of three: the upper limit is z^2 / (n + z^2)
        self.assertAlmostEqual(claims.wilson_interval(0, 3)[1], Z * Z / (3 + Z * Z), places=12)
        self.assertIsNone(claims.wilson_interval(0, 0))

    def test_newcombe_published_values(self):
        # Newcombe (1998), Table II, method 10, to the four decimals printed there
        table = {(56, 70, 48, 80): (0.0524, 0.3339), (9, 10, 3, 10): (0.1705, 0.8090),
                 (6, 7, 2, 7): (0.0582, 0.8062), (5, 56, 0, 29): (-0.0381, 0.1926),
                 (0, 10, 0, 20): (-0.1611, 0.2775), (0, 10, 0, 10): (-0.2775, 0.2775),
                 (10, 10, 0, 20): (0.6791, 1.0000), (10, 10, 0, 10): (0.6075, 1.0000)}
        for counts, (low, high) in table.items():
            got = claims.newcombe_interval(*counts)
            self.assertAlmostEqual(got[0], low, places=4, msg=counts)
            self.assertAlmostEqual(got[1], high, places=4, msg=counts)
        self.assertIsNone(claims.newcombe_interval(0, 0, 1, 2))

    def test_fisher_hypergeometric(self):
        # the paper's 2 of 3 against 0 of 6: P(both tripods among case 2's three) = 7/84
        self.assertAlmostEqual(claims.fisher_greater(2, 3, 0, 6), 1 / 12, places=12)
        self.assertAlmostEqual(claims.fisher_greater(3, 3, 0, 3), 1 / 20, places=12)
        self.assertAlmostEqual(claims.fisher_greater(0, 3, 0, 6), 1.0, places=12)
        self.assertAlmostEqual(claims.fisher_greater(0, 1, 1, 2), 1.0, places=12)

    def test_sign_test(self):
        self.assertEqual(claims.sign_test_greater([2] * 9, [1] * 9), (9, 9, 0.5 ** 9))
        wins, n, p = claims.sign_test_greater([1, 2, 3], [1, 1, 1])     # the tie is dropped
        self.assertEqual((wins, n), (2, 2))
        self.assertAlmostEqual(p, 0.25, places=12)
        wins, n, p = claims.sign_test_greater([1, 2, 3, 0], [0, 0, 0, 5])   # P(X >= 3 of 4)
        self.assertAlmostEqual(p, 5 / 16, places=12)
        self.assertEqual(claims.sign_test_greater([1.0], [1.0]), (0, 0, None))


class TimeToBipedTest(unittest.TestCase):
    """The first biped, the biped for good, and their median."""

    def test_first_and_for_good(self):
        gens = [0, 1, 2, 3, 4]
        self.assertEqual(claims.first_biped(gens, ["tripod", "biped", "tripod", "biped", "biped"]), 1)
        self.assertEqual(claims.biped_for_good(gens, ["tripod", "biped", "tripod", "biped", "biped"]), 3)
        self.assertEqual(claims.biped_for_good(gens, ["biped", "biped", "none", "biped", "biped"]), 3)
        self.assertIsNone(claims.biped_for_good(gens, ["biped", "biped", "biped", "biped", "tripod"]))
        self.assertIsNone(claims.first_biped(gens, ["tripod"] * 5))
        self.assertEqual(claims.first_biped([7], ["biped"]), 7)
        self.assertEqual(claims.biped_for_good([7], ["biped"]), 7)

    def test_median_time(self):
        self.assertEqual(claims.median_time([5, 7, 9]), 7)
        self.assertEqual(claims.median_time([100, 4001]), 100)      # half by generation 100
        self.assertEqual(claims.median_time([4001, 4001, 3]), 4001)
        self.assertEqual(claims.median_time([8]), 8)

    def test_time_entry_says_never(self):
        entry = claims.time_entry([3.0, 10.0, 10.0], never=10)
        self.assertEqual(entry["median"], None)
        self.assertEqual(entry["never"], 2)
        self.assertEqual(entry["runs"], [3, None, None])
        self.assertEqual(entry["interval"], [3, None])


class VerdictTest(unittest.TestCase):
    """The rule: p < 0.05 reproduces; an interval wholly on the no-effect side of the
    paper's value does not; anything else is inconclusive at n = N."""

    def test_rule(self):
        v = claims.verdict
        self.assertEqual(v(0.01, (-1, 1), +1, 0, None, "3"), "reproduced")
        self.assertEqual(v(0.049, None, -1, 1, 0.66, "3"), "reproduced")
        self.assertEqual(v(0.05, (0.1, 0.9), +1, 0, None, "3"), "inconclusive at n = 3")
        # direction only: an interval at or below no effect
        self.assertEqual(v(0.5, (-0.5, 0.0), +1, 0, None, "3"), "not reproduced")
        self.assertEqual(v(0.5, (-0.5, 0.01), +1, 0, None, "3"), "inconclusive at n = 3")
        # a number: the interval must exclude it on the no-effect side
        self.assertEqual(v(0.3, (0.85, 1.25), -1, 1, 0.66, "10"), "not reproduced")
        self.assertEqual(v(0.3, (0.60, 1.25), -1, 1, 0.66, "10"), "inconclusive at n = 10")
        self.assertEqual(v(0.3, (0.40, 0.60), -1, 1, 0.66, "10"), "inconclusive at n = 10")
        self.assertEqual(v(0.3, (0.10, 0.30), +1, 0, 0.375, "3/2"), "not reproduced")
        self.assertEqual(v(0.3, (0.10, 0.50), +1, 0, 0.375, "3/2"), "inconclusive at n = 3/2")
        self.assertEqual(v(None, None, +1, 0, 0.375, "1"), "inconclusive at n = 1")

    def test_formats(self):
        self.assertEqual(claims.fmt_p(0.0123), "0.012")
        self.assertEqual(claims.fmt_p(0.0005250), "5.2e-04")
        self.assertEqual(claims.fmt_p(None), "—")
        self.assertEqual(claims.fmt_interval((0.1, 0.25), "{:.1f}", 100, " %"), "[10.0, 25.0] %")
        self.assertEqual(claims.fmt_interval(None), "(no interval)")
        self.assertEqual(claims.n_label(3, 3, 3), "3")
        self.assertEqual(claims.n_label(3, 2), "3/2")
        self.assertEqual(claims.fmt_generation(4001, never=4001), "never")
        self.assertEqual(claims.fmt_generation(12.0, never=4001), "12")


# ----------------------------------------------------------------------------- synthetic runs

CASES = ("free", "time", "performance")
HEADER = ["generation", "best_fitness", "ave_best3", "archive_mean", "ceiling_half_body_x",
          "best_half_body_x", "best_femur", "best_tibia", "best_gait", "falls", "evals_per_s"]


def write_generations(path, fitness, gaits):
    """A generations.csv with the given best fitness and gait per generation."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(HEADER)
        for g, (fit, gait) in enumerate(zip(fitness, gaits)):
            w.writerow([g, fit, fit, fit, 0.9, 0.5, 0.5, 0.6, gait, 0, 40.0])


def make_reproduction(root, runs, generations=20):
    """A reproduction directory from {case: [(final fitness, biped from generation or
    None, best biped, best tripod)]}; its summary.json and summary.md look like the
    program's."""
    rep = os.path.join(root, "rep")
    os.makedirs(rep)
    listed = []
    for case in CASES:
        for r, (final, biped_from, best_biped, best_tripod) in enumerate(runs.get(case, []), 1):
            name = f"{case}-{r}"
            os.makedirs(os.path.join(rep, name))
            fitness = np.linspace(1.0, final, generations)
            gaits = ["tripod" if biped_from is None or g < biped_from else "biped"
                     for g in range(generations)]
            write_generations(os.path.join(rep, name, "generations.csv"), fitness, gaits)
            listed.append({"case": case, "replicate": r, "dir": name, "seed": r,
                           "final_best_fitness": final,
                           "final_best_gait": gaits[-1],
                           "best_biped_fitness": best_biped, "best_tripod_fitness": best_tripod})
    summary = {"cases": {c: {"paper_tripod_finals_of_3": 2 if c == "time" else 0, "runs": 0}
                         for c in CASES if c in runs},
               "case3_over_case1_share": {"paper": 0.83, "value": None},
               "case2_over_case1_final": {"paper": 0.66, "value": None},
               "biped_over_tripod": {"paper": 1.375, "value": None},
               "generations": generations, "replicates": max(len(v) for v in runs.values()),
               "runs": listed}
    with open(os.path.join(rep, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    with open(os.path.join(rep, "summary.md"), "w") as f:
        f.write("# Reproduction\n\n## Findings beside the paper's\n\n| a | b |\n\n"
                "## Figures\n\n![fig9](figures/fig9.png)\n")
    return rep


def run_script(rep):
    """Run claims.py on rep: (exit status, stdout, stderr)."""
    proc = subprocess.run([sys.executable, SCRIPT, rep], capture_output=True, text=True,
                          timeout=600)
    return proc.returncode, proc.stdout, proc.stderr


# the paper's picture, four replicates a case: case 3 ends above case 1 in every
# replicate, case 2 far below it and mostly a tripod
PAPER_LIKE = {
    "free": [(19.0, 5, 19.0, 8.0), (18.0, 8, 18.0, 7.0), (20.0, 4, 20.0, 9.0), (17.5, 6, 17.5, 6.0)],
    "time": [(12.0, None, 9.0, 12.0), (11.0, None, 8.0, 11.0), (13.0, 15, 13.0, 10.0),
             (12.5, None, 7.0, 12.5)],
    "performance": [(22.0, 3, 22.0, 8.5), (23.0, 2, 23.0, 9.0), (21.0, 4, 21.0, 7.5),
                    (24.0, 3, 24.0, 8.0)],
}
# ours: the three cases alike, no tripods
ALIKE = {c: [(19.0 + 0.5 * k, 3 + k, 19.0 + 0.5 * k, 9.0) for k in (0, 3, 1, 2)] for c in CASES}


class ClaimsOnRunsTest(unittest.TestCase):
    """The findings and their lines on synthetic reproductions."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def findings(self, runs):
        """{claim id: finding} of the reproduction `runs`."""
        rep = claims.load_reproduction(make_reproduction(self.tmp.name, runs))
        block = claims.evaluate(rep)
        return {f["id"]: f for f in block["findings"]}, block

    def test_paper_like_runs_reproduce_the_paper(self):
        found, block = self.findings(PAPER_LIKE)
        self.assertEqual([f["id"] for f in block["findings"]],
                         [c.__name__.replace("claim_", "") for c in claims.CLAIMS])
        case3 = found["case3_above_case1"]
        self.assertEqual(case3["verdict"], "reproduced")
        self.assertAlmostEqual(case3["test"]["p"], 1 / 70, places=12)   # 1 of C(8, 4) splits
        self.assertEqual(case3["effect"]["value"], 1.0)
        self.assertIn("Case 3 (performance) ends above case 1 (free) — paper: case 3 ends "
                      "highest: **reproduced**: final best 22.50 against 18.62 (means)",
                      case3["line"])
        self.assertIn("p = 0.014", case3["line"])
        share = found["case3_leads_generations"]
        self.assertEqual(share["verdict"], "reproduced")
        self.assertAlmostEqual(share["effect"]["value"], 19 / 20)   # all but generation 0
        below = found["case2_below_case1"]
        self.assertEqual(below["verdict"], "reproduced")
        self.assertAlmostEqual(below["effect"]["value"], 48.5 / 74.5, places=12)
        self.assertIn("65.1 % of case 1's", below["line"])
        low, high = below["effect"]["interval"]
        self.assertEqual(below["line"].endswith("lies within our interval."), low <= 0.66 <= high)
        tripods = found["case2_more_tripods"]
        # 3 of 4 against 0 of 8: C(3,3) C(9,1) / C(12,4) = 9/495 = 1/55
        self.assertAlmostEqual(tripods["test"]["p"], 1 / 55, places=12)
        self.assertEqual(tripods["verdict"], "reproduced")
        self.assertIn("3 of 4", tripods["line"])
        self.assertIn("0 of 8", tripods["line"])
        biped = found["biped_above_tripod"]
        self.assertAlmostEqual(biped["effect"]["value"], 24.0 / 12.5 - 1, places=12)
        # a run's best biped beats its best tripod in 9 of 12 runs: P(X >= 9 | 12, 1/2)
        self.assertEqual((biped["test"]["statistic"], biped["test"]["pairs"]), (9, 12))
        self.assertAlmostEqual(biped["test"]["p"], 299 / 4096, places=12)
        self.assertEqual(biped["verdict"], "inconclusive at n = 4")
        later = found["case2_later_biped"]
        self.assertEqual(later["verdict"], "reproduced")
        self.assertIn("median generation never against 5", later["line"])
        self.assertEqual(block["cases"]["time"]["biped_for_good_generation"]["never"], 3)
        self.assertEqual(block["cases"]["time"]["tripod_finals"]["tripods"], 3)

    def test_each_learner_gets_the_scaffolds_claims(self):
        # the GA's runs follow the paper, another learner's are alike in every case
        rep_dir = make_reproduction(os.path.join(self.tmp.name, "a"), PAPER_LIKE)
        alike_dir = make_reproduction(os.path.join(self.tmp.name, "b"), ALIKE)
        path = os.path.join(rep_dir, "summary.json")
        with open(path) as f:
            summary = json.load(f)
        with open(os.path.join(alike_dir, "summary.json")) as f:
            alike = json.load(f)["runs"]
        learner_runs = [{**run, "learner": "ga"} for run in summary["runs"]]
        for run in alike:
            name = "pso-" + run["dir"]
            shutil.copytree(os.path.join(alike_dir, run["dir"]), os.path.join(rep_dir, name))
            learner_runs.append({**run, "dir": name, "learner": "pso"})
        summary["learners"] = [{"name": "ga"}, {"name": "pso"}]
        summary["learner_runs"] = learner_runs
        with open(path, "w") as f:
            json.dump(summary, f)
        block = claims.evaluate(claims.load_reproduction(rep_dir))
        by_learner = {e["learner"]: {f["id"]: f["verdict"] for f in e["findings"]}
                      for e in block["learners"]}
        ids = [c.__name__.replace("claim_", "") for c in claims.LEARNER_CLAIMS]
        self.assertEqual(sorted(by_learner), ["ga", "pso"])
        self.assertEqual(list(by_learner["ga"]), ids)
        self.assertEqual(by_learner["ga"]["case3_above_case1"], "reproduced")
        self.assertEqual(by_learner["ga"]["case2_below_case1"], "reproduced")
        self.assertNotEqual(by_learner["pso"]["case2_below_case1"], "reproduced")
        self.assertNotEqual(by_learner["pso"]["case2_more_tripods"], "reproduced")  # no tripods
        md = claims.markdown(block)
        self.assertIn("- pso: Case 3 (performance) ends above case 1 (free)", md)
        # one learner: no per-learner block
        summary["learners"] = [{"name": "ga"}]
        with open(path, "w") as f:
            json.dump(summary, f)
        self.assertNotIn("learners", claims.evaluate(claims.load_reproduction(rep_dir)))

    def test_alike_cases_do_not_reproduce_the_paper(self):
        found, _ = self.findings(ALIKE)
        # δ = 0, but four replicates cannot rule out that case 3 is the better
        case3 = found["case3_above_case1"]
        self.assertEqual(case3["effect"]["value"], 0.0)
        self.assertGreater(case3["effect"]["interval"][1], 0.0)
        self.assertEqual(case3["verdict"], "inconclusive at n = 4")
        # the paper's 66 % lies below the interval
        below = found["case2_below_case1"]
        self.assertEqual(below["effect"]["value"], 1.0)
        self.assertGreater(below["effect"]["interval"][0], 0.66)
        self.assertEqual(below["verdict"], "not reproduced")
        self.assertIn("100.0 % of case 1's", below["line"])
        self.assertTrue(below["line"].endswith("; the paper's value lies below our interval."),
                        below["line"])
        tripods = found["case2_more_tripods"]
        self.assertEqual(tripods["test"]["p"], 1.0)
        # 0 of 4 against 0 of 8: Newcombe's upper limit is case 2's Wilson upper, 49 %
        self.assertAlmostEqual(tripods["effect"]["interval"][1], Z * Z / (4 + Z * Z), places=12)
        self.assertEqual(tripods["verdict"], "not reproduced")
        self.assertEqual(found["case2_later_biped"]["verdict"], "inconclusive at n = 4")
        # the mean curves coincide: case 3 never leads, but resampled it may
        share = found["case3_leads_generations"]
        self.assertEqual(share["effect"]["value"], 0.0)
        self.assertGreater(share["effect"]["interval"][1], 0.83)
        self.assertEqual(share["verdict"], "inconclusive at n = 4")

    def test_a_case_identically_ahead_is_ruled_out_in_the_other_direction(self):
        runs = {c: list(v) for c, v in ALIKE.items()}
        runs["free"] = [(f + 5, b, bb + 5, bt) for f, b, bb, bt in ALIKE["free"]]
        found, _ = self.findings(runs)
        case3 = found["case3_above_case1"]
        self.assertEqual(case3["effect"]["interval"], [-1.0, -1.0])
        self.assertEqual(case3["verdict"], "not reproduced")
        share = found["case3_leads_generations"]
        self.assertEqual(share["effect"]["interval"], [0.0, 0.0])
        self.assertEqual(share["verdict"], "not reproduced")
        self.assertIn("0.0 % of 20 generations [0.0, 0.0] %", share["line"])

    def test_one_replicate_is_inconclusive(self):
        runs = {c: v[:1] for c, v in PAPER_LIKE.items()}
        found, block = self.findings(runs)
        for claim in ("case3_above_case1", "case3_leads_generations", "case2_below_case1",
                      "case2_later_biped"):
            self.assertEqual(found[claim]["verdict"], "inconclusive at n = 1", claim)
            self.assertIn("**inconclusive at n = 1**", found[claim]["line"])
            self.assertIsNone(found[claim]["effect"]["interval"], claim)
            self.assertIn("(no interval)", found[claim]["line"])
        self.assertAlmostEqual(found["case3_above_case1"]["test"]["p"], 0.5, places=12)
        # 1 of 1 against 0 of 2: Newcombe's upper limit (1.0) holds the paper's +67 points
        self.assertEqual(found["case2_more_tripods"]["verdict"], "inconclusive at n = 1")
        self.assertIsNone(block["cases"]["free"]["final_best"]["mean_interval"])

    def test_a_missing_case_is_inconclusive_at_n_0(self):
        found, _ = self.findings({"free": PAPER_LIKE["free"], "performance": PAPER_LIKE["performance"]})
        self.assertEqual(found["case2_below_case1"]["verdict"], "inconclusive at n = 0")
        self.assertIn("no runs of case time", found["case2_below_case1"]["line"])
        self.assertEqual(found["case3_above_case1"]["verdict"], "reproduced")

    def test_no_tripod_anywhere_is_inconclusive_at_n_0(self):
        runs = {c: [(f, b, bb, None) for f, b, bb, _ in v] for c, v in ALIKE.items()}
        found, _ = self.findings(runs)
        self.assertEqual(found["biped_above_tripod"]["verdict"], "inconclusive at n = 0")
        self.assertIn("no run evaluated a tripod", found["biped_above_tripod"]["line"])


class ScriptTest(unittest.TestCase):
    """claims.py as walkers reproduce runs it."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.rep = make_reproduction(self.tmp.name, PAPER_LIKE)

    def tearDown(self):
        self.tmp.cleanup()

    def read(self, name):
        """A file of the reproduction, as text."""
        with open(os.path.join(self.rep, name), encoding="utf-8") as f:
            return f.read()

    def test_writes_the_block_and_the_section_and_again_the_same(self):
        status, out, err = run_script(self.rep)
        self.assertEqual(status, 0, err)
        self.assertEqual(err, "")
        summary = json.loads(self.read("summary.json"))
        block = summary["claims"]
        self.assertEqual(len(block["findings"]), len(claims.CLAIMS))
        self.assertEqual(summary["runs"][0]["dir"], "free-1")     # the rest kept
        md = self.read("summary.md")
        self.assertLess(md.index("## Findings"), md.index("## Claims"))
        self.assertLess(md.index("## Claims"), md.index("## Figures"))
        for f in block["findings"]:
            self.assertIn(f"- {f['line']}\n", md)
            self.assertIn(f["line"].replace("**", ""), out)
        self.assertIn("| time | 4 |", md)
        # again: the same bytes, one section
        first = (self.read("summary.json"), md)
        status, _, err = run_script(self.rep)
        self.assertEqual(status, 0, err)
        self.assertEqual((self.read("summary.json"), self.read("summary.md")), first)
        self.assertEqual(self.read("summary.md").count("## Claims"), 1)

    def test_missing_generations_names_the_file(self):
        path = os.path.join(self.rep, "time-2", "generations.csv")
        os.remove(path)
        before = self.read("summary.json")
        status, _, err = run_script(self.rep)
        self.assertEqual(status, 1)
        self.assertIn(f"{path}: file not found", err)
        self.assertEqual(self.read("summary.json"), before)

    def test_bad_fields_are_named(self):
        cases = [
            (lambda s: s["runs"][2].pop("best_tripod_fitness"),
             "missing field 'runs[2].best_tripod_fitness'"),
            (lambda s: s["runs"][1].__setitem__("best_biped_fitness", "far"),
             "field 'runs[1].best_biped_fitness' must be a finite number or null"),
            (lambda s: s["biped_over_tripod"].pop("paper"), "missing field 'biped_over_tripod.paper'"),
            (lambda s: s["cases"]["time"].__setitem__("paper_tripod_finals_of_3", 4),
             "field 'cases.time.paper_tripod_finals_of_3' is 4, outside [0, 3]"),
            (lambda s: s["runs"][0].__setitem__("case", "lazy"),
             "field 'runs[0].case' is 'lazy', not one of the cases it lists"),
        ]
        path = os.path.join(self.rep, "summary.json")
        with open(path) as f:
            original = f.read()
        for change, message in cases:
            summary = json.loads(original)
            change(summary)
            with open(path, "w") as f:
                json.dump(summary, f)
            status, _, err = run_script(self.rep)
            self.assertEqual(status, 1, message)
            self.assertIn(f"{path}: {message}", err)

    def test_bad_generations_row_is_named(self):
        path = os.path.join(self.rep, "free-1", "generations.csv")
        with open(path) as f:
            lines = f.readlines()
        lines[3] = lines[3].replace("tripod", "quadruped").replace("biped", "quadruped")
        with open(path, "w") as f:
            f.writelines(lines)
        status, _, err = run_script(self.rep)
        self.assertEqual(status, 1)
        self.assertIn(f"{path}: line 4, column best_gait: 'quadruped'", err)

    def test_a_ratio_over_zero_is_null_in_json(self):
        runs = {c: list(v) for c, v in PAPER_LIKE.items()}
        runs["free"] = [(0.0, None, None, 0.0) for _ in range(4)]     # case 1 never moved
        rep = make_reproduction(os.path.join(self.tmp.name, "zero"), runs)
        status, _, err = run_script(rep)
        self.assertEqual(status, 0, err)
        self.assertEqual(err, "")                  # no warning either
        with open(os.path.join(rep, "summary.json")) as f:
            block = json.load(f)["claims"]
        below = next(f for f in block["findings"] if f["id"] == "case2_below_case1")
        self.assertIsNone(below["effect"]["value"])
        self.assertTrue(below["verdict"].startswith("inconclusive"), below["verdict"])

    def test_not_a_directory(self):
        status, _, err = run_script(os.path.join(self.tmp.name, "nowhere"))
        self.assertEqual(status, 1)
        self.assertIn("nowhere: not a directory", err)


if __name__ == "__main__":
    warnings.simplefilter("error")       # the statistics must run warning-free
    unittest.main(verbosity=2)
