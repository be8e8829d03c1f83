#!/usr/bin/env python3
"""Tests for walkers_stats/statistics.py: each statistic on hand-made data with known
answers (ties and single replicates included).

Run:  /usr/bin/python3 tests/scripts/walkers_stats/statistics_test.py   (needs numpy, scipy)

Known answers come from closed forms (Wilson's formula, hypergeometric and binomial
probabilities), from enumerating every split by hand in the test (itertools), or from
published tables (Newcombe 1998, Table II).
"""
import itertools
import math
import unittest
import warnings

import numpy as np
from scipy import stats

import fixtures  # noqa: F401  - puts the package on the path
from walkers_stats import statistics

Z = stats.norm.ppf(0.975)


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
        u, p, exact = statistics.rank_sum_test([3, 4, 5], [0, 1, 2], "greater")
        self.assertEqual(u, 9.0)
        self.assertAlmostEqual(p, 1 / 20, places=12)
        self.assertTrue(exact)
        u, p, _ = statistics.rank_sum_test([3, 4, 5], [0, 1, 2], "less")
        self.assertAlmostEqual(p, 1.0, places=12)

    def test_agrees_with_scipys_exact_mann_whitney_without_ties(self):
        gen = np.random.default_rng(5)
        for n1, n2 in ((4, 5), (6, 6), (3, 8)):
            x, y = gen.normal(0.5, 1, n1), gen.normal(0, 1, n2)
            for alternative in ("greater", "less"):
                u, p, exact = statistics.rank_sum_test(x, y, alternative)
                ref = stats.mannwhitneyu(x, y, alternative=alternative, method="exact")
                self.assertTrue(exact)
                self.assertEqual(u, ref.statistic)
                self.assertAlmostEqual(p, ref.pvalue, places=12, msg=(n1, n2, alternative))

    def test_ties_are_exact(self):
        x, y = [1, 2, 2, 3], [2, 2, 0, 1, 1]
        for alternative in ("greater", "less"):
            u, p, _ = statistics.rank_sum_test(x, y, alternative)
            self.assertAlmostEqual(p, enumerated_rank_sum_p(x, y, alternative), places=12)
        # U counts a tie as half a win: 1 > 0 (1), 1 = 1 twice (1), 2 > 0, 1, 1 (3) and
        # 2 = 2 twice (1), twice over, 3 > all five (5)
        self.assertEqual(u, 1 + 1 + 2 * (3 + 1) + 5)

    def test_all_tied(self):
        u, p, _ = statistics.rank_sum_test([4, 4], [4, 4, 4], "greater")
        self.assertEqual(u, 3.0)
        self.assertAlmostEqual(p, 1.0, places=12)

    def test_one_replicate_each(self):
        # two splits: x above y is one of them
        u, p, exact = statistics.rank_sum_test([2.0], [1.0], "greater")
        self.assertEqual((u, exact), (1.0, True))
        self.assertAlmostEqual(p, 0.5, places=12)
        with self.assertRaises(ValueError):
            statistics.rank_sum_test([], [1.0], "greater")

    def test_one_replicate_against_several(self):
        # midranks 1.5 | 1.5, 3, 4: x's rank sum is the least of the four splits'
        self.assertAlmostEqual(statistics.rank_sum_test([1], [1, 2, 3], "greater")[1], 1.0, places=12)
        self.assertAlmostEqual(statistics.rank_sum_test([1], [1, 2, 3], "less")[1], 0.5, places=12)
        for x, y in (([3, 3, 1], [2]), ([5], [1, 5, 2, 2]), ([0.5], [1, 2])):
            for alternative in ("greater", "less"):
                self.assertAlmostEqual(statistics.rank_sum_test(x, y, alternative)[1],
                                       enumerated_rank_sum_p(x, y, alternative), places=12,
                                       msg=(x, y, alternative))

    def test_large_samples_use_seeded_random_permutations(self):
        gen = np.random.default_rng(9)
        x, y = gen.normal(0.3, 1, 12), gen.normal(0, 1, 12)   # C(24, 12) > EXACT_SPLITS
        u, p, exact = statistics.rank_sum_test(x, y, "greater")
        self.assertFalse(exact)
        ref = stats.mannwhitneyu(x, y, alternative="greater", method="exact").pvalue
        self.assertLess(abs(p - ref), 4 * math.sqrt(ref * (1 - ref) / statistics.MONTE_CARLO_PERMUTATIONS))
        self.assertEqual(p, statistics.rank_sum_test(x, y, "greater")[1])   # same seed, same bits


class EffectSizeTest(unittest.TestCase):
    """Cliff's delta, the Hodges-Lehmann shift and the ratio of means."""

    def test_cliffs_delta(self):
        self.assertEqual(statistics.cliffs_delta([5, 6], [1, 2, 3]), 1.0)
        self.assertEqual(statistics.cliffs_delta([1, 2, 3], [5, 6]), -1.0)
        # pairs: 1<2, 1<3, 2=2, 2<3
        self.assertEqual(statistics.cliffs_delta([1, 2], [2, 3]), -0.75)
        self.assertEqual(statistics.cliffs_delta([7], [7]), 0.0)

    def test_cliffs_delta_is_2u_over_pairs_minus_1(self):
        x, y = [1, 2, 2, 3, 5], [2, 2, 0, 1, 1, 4]
        u, _, _ = statistics.rank_sum_test(x, y, "greater")
        self.assertAlmostEqual(statistics.cliffs_delta(x, y), 2 * u / (len(x) * len(y)) - 1, places=12)

    def test_cliffs_delta_vectorised(self):
        x = np.array([[1, 2], [5, 6]])
        y = np.array([[2, 3], [1, 1]])
        np.testing.assert_array_equal(statistics.cliffs_delta(x, y), [-0.75, 1.0])

    def test_hodges_lehmann(self):
        self.assertEqual(statistics.hodges_lehmann([1, 2, 3], [0]), 2.0)
        self.assertEqual(statistics.hodges_lehmann([1, 2], [0, 0]), 1.5)        # 1, 1, 2, 2
        self.assertEqual(statistics.hodges_lehmann([4], [1]), 3.0)
        np.testing.assert_array_equal(statistics.hodges_lehmann([[1, 2], [3, 3]], [[0, 0], [1, 1]]),
                                      [1.5, 2.0])

    def test_ratio_of_means(self):
        self.assertEqual(statistics.ratio_of_means([1, 3], [4, 4]), 0.5)


class BootstrapTest(unittest.TestCase):
    """Percentile bootstrap intervals, seeded."""

    def test_two_points(self):
        # the mean of a resample of [0, 1] is 0, 0.5 or 1 (1/4, 1/2, 1/4): the 2.5th
        # and 97.5th percentiles are 0 and 1
        self.assertEqual(statistics.bootstrap_interval(([0.0, 1.0],), np.mean), (0.0, 1.0))

    def test_constant_sample_and_single_value(self):
        self.assertEqual(statistics.bootstrap_interval(([3.0, 3.0, 3.0],), np.mean), (3.0, 3.0))
        self.assertIsNone(statistics.bootstrap_interval(([3.0],), np.mean))
        self.assertIsNone(statistics.bootstrap_interval(([1.0, 2.0], [3.0]), statistics.cliffs_delta))

    def test_separated_samples_give_delta_one(self):
        self.assertEqual(statistics.bootstrap_interval(([5, 6, 7], [1, 2]), statistics.cliffs_delta),
                         (1.0, 1.0))

    def test_deterministic_and_sensible(self):
        gen = np.random.default_rng(3)
        x = gen.normal(10, 2, 8)
        a = statistics.bootstrap_interval((x,), np.mean)
        self.assertEqual(a, statistics.bootstrap_interval((x,), np.mean))     # same bits
        self.assertLess(a[0], np.mean(x))
        self.assertGreater(a[1], np.mean(x))
        self.assertGreaterEqual(a[0], x.min())
        self.assertLessEqual(a[1], x.max())

    def test_mean_band(self):
        self.assertIsNone(statistics.mean_band([[1.0, 2.0, 3.0]]))
        low, high = statistics.mean_band([[0.0, 5.0, 1.0], [1.0, 5.0, 3.0]])
        # two replicates: the resampled mean is either value or their average
        np.testing.assert_array_equal(low, [0.0, 5.0, 1.0])
        np.testing.assert_array_equal(high, [1.0, 5.0, 3.0])
        gen = np.random.default_rng(4)
        curves = gen.normal(5, 1, (6, 50))
        low, high = statistics.mean_band(curves)
        self.assertTrue(np.all(low <= curves.mean(axis=0)) and np.all(curves.mean(axis=0) <= high))
        self.assertTrue(np.all(low < high))
        np.testing.assert_array_equal(low, statistics.mean_band(curves)[0])   # same bits

    def test_paired_bootstrap_drops_resamples_without_a_value(self):
        def ratio_of_maxima(b, t, axis=-1):
            """max b / max t, NaN when t is all NaN"""
            return np.nanmax(b, axis=axis) / np.nanmax(t, axis=axis)
        b, t = np.array([2.0, 2.0, 2.0]), np.array([1.0, np.nan, 1.0])
        interval, undefined = statistics.bootstrap_paired(b, t, ratio_of_maxima)
        self.assertEqual(interval, (2.0, 2.0))
        # a resample holds only the second run with probability 1/27
        expected = statistics.BOOTSTRAP_RESAMPLES / 27
        self.assertLess(abs(undefined - expected), 5 * math.sqrt(expected))
        self.assertEqual(statistics.bootstrap_paired(b[:1], t[:1], ratio_of_maxima), (None, 0))


class ShareOfGenerationsTest(unittest.TestCase):
    """The share of generations in which one case's mean leads, its test and interval."""

    def test_share(self):
        a = [[1, 5, 5, 5], [3, 5, 5, 9]]     # mean 2, 5, 5, 7
        b = [[2, 4, 6, 1]]                   # 2, 4, 6, 1: a leads in generations 1 and 3
        self.assertEqual(statistics.share_leading(a, b), 0.5)
        self.assertEqual(statistics.share_leading([[1, 2, 3, 4]], [[0, 0]]), 1.0)  # common length

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
        difference, p, exact = statistics.curve_test(a, b)
        self.assertTrue(exact)
        self.assertAlmostEqual(difference, observed, places=12)
        self.assertAlmostEqual(p, expected, places=12)
        self.assertAlmostEqual(p, 1 / 20, places=12)     # a's three are the largest

    def test_one_replicate_each(self):
        difference, p, exact = statistics.curve_test([[2.0, 2.0]], [[1.0, 1.0]])
        self.assertEqual((difference, p, exact), (1.0, 0.5, True))
        self.assertIsNone(statistics.share_interval([[2.0, 2.0]], [[1.0, 1.0]]))

    def test_interval(self):
        a = [[5.0, 5.0, 5.0, 5.0], [6.0, 6.0, 6.0, 6.0]]
        b = [[1.0, 1.0, 1.0, 1.0], [2.0, 2.0, 2.0, 2.0]]
        self.assertEqual(statistics.share_interval(a, b), (1.0, 1.0))


class ProportionsTest(unittest.TestCase):
    """Wilson and Newcombe intervals, Fisher's exact test and the sign test."""

    def test_wilson_closed_form(self):
        for k, n in ((0, 3), (2, 3), (3, 3), (1, 1), (7, 10)):
            low, high = statistics.wilson_interval(k, n)
            ref = wilson(k, n)
            self.assertAlmostEqual(low, max(0.0, ref[0]), places=12, msg=(k, n))
            self.assertAlmostEqual(high, min(1.0, ref[1]), places=12, msg=(k, n))
        # none of three: the upper limit is z^2 / (n + z^2)
        self.assertAlmostEqual(statistics.wilson_interval(0, 3)[1], Z * Z / (3 + Z * Z), places=12)
        self.assertIsNone(statistics.wilson_interval(0, 0))

    def test_newcombe_published_values(self):
        # Newcombe (1998), Table II, method 10, to the four decimals printed there
        table = {(56, 70, 48, 80): (0.0524, 0.3339), (9, 10, 3, 10): (0.1705, 0.8090),
                 (6, 7, 2, 7): (0.0582, 0.8062), (5, 56, 0, 29): (-0.0381, 0.1926),
                 (0, 10, 0, 20): (-0.1611, 0.2775), (0, 10, 0, 10): (-0.2775, 0.2775),
                 (10, 10, 0, 20): (0.6791, 1.0000), (10, 10, 0, 10): (0.6075, 1.0000)}
        for counts, (low, high) in table.items():
            got = statistics.newcombe_interval(*counts)
            self.assertAlmostEqual(got[0], low, places=4, msg=counts)
            self.assertAlmostEqual(got[1], high, places=4, msg=counts)
        self.assertIsNone(statistics.newcombe_interval(0, 0, 1, 2))

    def test_fisher_hypergeometric(self):
        # the paper's 2 of 3 against 0 of 6: P(both tripods among case 2's three) = 7/84
        self.assertAlmostEqual(statistics.fisher_p(2, 3, 0, 6, "greater"), 1 / 12, places=12)
        self.assertAlmostEqual(statistics.fisher_p(3, 3, 0, 3, "greater"), 1 / 20, places=12)
        self.assertAlmostEqual(statistics.fisher_p(0, 3, 0, 6, "greater"), 1.0, places=12)
        self.assertAlmostEqual(statistics.fisher_p(0, 1, 1, 2, "greater"), 1.0, places=12)
        # two-sided, 8 of 10 against 0 of 3: of the tables with 8 tripods among 13 runs,
        # C(8, k) C(5, 10 - k) / C(13, 10) for k = 5..8 is 56, 140, 80, 10 / 286; only the
        # observed k = 8 is as unlikely
        self.assertAlmostEqual(statistics.fisher_p(8, 10, 0, 3, "two-sided"), 10 / 286, places=12)
        self.assertAlmostEqual(statistics.fisher_p(0, 3, 8, 10, "two-sided"), 10 / 286, places=12)
        self.assertAlmostEqual(statistics.fisher_p(2, 3, 1, 3, "two-sided"), 1.0, places=12)

    def test_sign_test(self):
        self.assertEqual(statistics.sign_test_greater([2] * 9, [1] * 9), (9, 9, 0.5 ** 9))
        wins, n, p = statistics.sign_test_greater([1, 2, 3], [1, 1, 1])     # the tie is dropped
        self.assertEqual((wins, n), (2, 2))
        self.assertAlmostEqual(p, 0.25, places=12)
        wins, n, p = statistics.sign_test_greater([1, 2, 3, 0], [0, 0, 0, 5])   # P(X >= 3 of 4)
        self.assertAlmostEqual(p, 5 / 16, places=12)
        self.assertEqual(statistics.sign_test_greater([1.0], [1.0]), (0, 0, None))


def enumerated_signed_rank_p(x, y, alternative):
    """The exact one-sided p of the signed-rank test by listing every way of signing the
    ranks of the non-zero differences (midranks for ties)."""
    d = [a - b for a, b in zip(x, y) if a != b]
    ranks = stats.rankdata([abs(v) for v in d])
    observed = sum(r for r, v in zip(ranks, d) if v > 0)
    sums = [sum(r for r, s in zip(ranks, signs) if s) for signs in
            itertools.product((False, True), repeat=len(d))]
    if alternative == "greater":
        return sum(s >= observed - 1e-9 for s in sums) / len(sums)
    return sum(s <= observed + 1e-9 for s in sums) / len(sums)


class SignedRankTest(unittest.TestCase):
    """Wilcoxon's signed-rank test of replicate pairs, exact over every signing."""

    def test_every_pair_one_way(self):
        # 5 pairs all above: W+ = 15 and 1 of the 2^5 signings is as extreme
        self.assertEqual(statistics.signed_rank_test([2, 3, 4, 5, 6], [1, 1, 1, 1, 1], "greater"),
                         (15.0, 5, 1 / 32, True))
        self.assertEqual(statistics.signed_rank_test([2, 3, 4, 5, 6], [1, 1, 1, 1, 1], "less"),
                         (15.0, 5, 1.0, True))

    def test_ties_and_zero_differences_against_the_listed_signings(self):
        # differences 1, -1, 2, 2, 0, -3, 4, 0.5: the zeros leave, ties share midranks
        x = [2.0, 1.0, 5.0, 6.0, 3.0, 1.0, 9.0, 3.5]
        y = [1.0, 2.0, 3.0, 4.0, 3.0, 4.0, 5.0, 3.0]
        for alternative in ("greater", "less"):
            w, pairs, p, exact = statistics.signed_rank_test(x, y, alternative)
            self.assertEqual((pairs, exact), (7, True))
            self.assertEqual(w, 2.5 + 4.5 + 4.5 + 7 + 1)
            self.assertAlmostEqual(p, enumerated_signed_rank_p(x, y, alternative), places=12)

    def test_agrees_with_scipys_exact_wilcoxon_without_ties(self):
        gen = np.random.default_rng(11)
        for n in (3, 8, 12):
            x, y = gen.normal(0.3, 1, n), gen.normal(0, 1, n)
            for alternative in ("greater", "less"):
                _, _, p, _ = statistics.signed_rank_test(x, y, alternative)
                expected = stats.wilcoxon(x, y, alternative=alternative, method="exact").pvalue
                self.assertAlmostEqual(p, expected, places=12)

    def test_beyond_exact_a_seeded_monte_carlo(self):
        gen = np.random.default_rng(3)
        x, y = gen.normal(0.4, 1, 20), gen.normal(0, 1, 20)
        first = statistics.signed_rank_test(x, y, "greater")
        self.assertFalse(first[3])
        self.assertEqual(statistics.signed_rank_test(x, y, "greater"), first)    # seeded
        expected = stats.wilcoxon(x, y, alternative="greater", method="exact").pvalue
        self.assertAlmostEqual(first[2], expected, delta=0.005)

    def test_one_pair_and_none(self):
        self.assertEqual(statistics.signed_rank_test([1.0], [0.0], "greater"), (1.0, 1, 0.5, True))
        self.assertEqual(statistics.signed_rank_test([1.0, 2.0], [1.0, 2.0], "greater"),
                         (0.0, 0, None, True))


class TimeToBipedTest(unittest.TestCase):
    """The first biped, the biped for good, and their median."""

    def test_first_and_for_good(self):
        gens = [0, 1, 2, 3, 4]
        self.assertEqual(statistics.first_biped(gens, ["tripod", "biped", "tripod", "biped", "biped"]), 1)
        self.assertEqual(statistics.biped_for_good(gens, ["tripod", "biped", "tripod", "biped", "biped"]), 3)
        self.assertEqual(statistics.biped_for_good(gens, ["biped", "biped", "none", "biped", "biped"]), 3)
        self.assertIsNone(statistics.biped_for_good(gens, ["biped", "biped", "biped", "biped", "tripod"]))
        self.assertIsNone(statistics.first_biped(gens, ["tripod"] * 5))
        self.assertEqual(statistics.first_biped([7], ["biped"]), 7)
        self.assertEqual(statistics.biped_for_good([7], ["biped"]), 7)

    def test_median_time(self):
        self.assertEqual(statistics.median_time([5, 7, 9]), 7)
        self.assertEqual(statistics.median_time([100, 4001]), 100)      # half by generation 100
        self.assertEqual(statistics.median_time([4001, 4001, 3]), 4001)
        self.assertEqual(statistics.median_time([8]), 8)



class SummariesTest(unittest.TestCase):
    """Mean and standard deviation; the generations reported."""

    def test_mean_and_sample_sd(self):
        mean, sd = statistics.mean_and_sd([2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0])
        self.assertEqual(mean, 5.0)
        self.assertAlmostEqual(sd, math.sqrt(32.0 / 7.0), places=12)
        self.assertEqual(statistics.mean_and_sd([3.0]), (3.0, 0.0))

    def test_reported_generations(self):
        self.assertEqual(statistics.reported_generations(3999), [500, 1000, 2000, 3999])
        self.assertEqual(statistics.reported_generations(1499), [500, 1000, 1499])
        self.assertEqual(statistics.reported_generations(29), [29])
        self.assertEqual(statistics.reported_generations(500), [500])


if __name__ == "__main__":
    warnings.simplefilter("error")       # the statistics must run warning-free
    unittest.main(verbosity=2)
