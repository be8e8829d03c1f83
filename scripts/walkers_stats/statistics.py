"""The statistics of a reproduction, each computed here and only here: exact tests,
effect sizes and seeded bootstrap intervals (docs/statistics.md). SciPy does the work;
nothing random is left unseeded, so the same runs give the same bits.

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
  * The share of generations in which one case's mean best leads another's: its
    bootstrap interval (whole curves resampled), and as its test the permutation test
    (as for U) of the difference of the cases' mean best fitness averaged over the
    generations (the area under the mean curves). The share itself is a poor test
    statistic: when the replicates' curves keep their order, shuffled labels give
    shares near 0 or 1.
  * Paired bootstrap (a run's best biped with its best tripod); the sign test
    (scipy.stats.binomtest).
  * Pairs of replicates (replicate r of two cases): Wilcoxon's signed-rank test, its
    p over the ways of signing the ranks of the differences (every one up to
    EXACT_SPLITS: 17 pairs), ties given midranks and zero differences left out; or
    the sign test.
  * Time to a biped: the generation of a run's first biped best, and that from which
    its best is a biped to the end ("for good").
"""
import math
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


def rng():
    """A fresh generator from SEED: each statistic draws the same numbers whatever
    was computed before it."""
    return np.random.default_rng(SEED)


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


def fisher_p(k1, n1, k2, n2, alternative):
    """Fisher's exact test of k1/n1 against k2/n2: its p-value ('greater': that k1/n1
    exceeds k2/n2; 'two-sided': that they differ)."""
    return float(stats.fisher_exact([[k1, n1 - k1], [k2, n2 - k2]],
                                    alternative=alternative).pvalue)


def sign_test_greater(x, y):
    """Sign test that x_i > y_i more often than not, over the pairs that differ:
    (pairs with x_i > y_i, pairs that differ, one-sided p or None without any)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    wins, n = int(np.sum(x > y)), int(np.sum(x != y))
    if n == 0:
        return wins, n, None
    return wins, n, float(stats.binomtest(wins, n, 0.5, alternative="greater").pvalue)


def signed_rank_test(x, y, alternative):
    """Wilcoxon's signed-rank test of the pairs (x_i, y_i) ('greater': x_i - y_i tends to
    be positive): the pairs that differ, their |x_i - y_i| ranked (midranks for ties),
    W+ the sum of the ranks of the positive differences, and its one-sided p over the
    2^n ways of signing the ranks: every one of them up to EXACT_SPLITS (17 pairs),
    else MONTE_CARLO_PERMUTATIONS seeded ones. Returns (W+, pairs that differ, p,
    exact); p is None without any."""
    d = np.asarray(x, float) - np.asarray(y, float)
    d = d[d != 0]
    if len(d) == 0:
        return 0.0, 0, None, True
    ranks = stats.rankdata(np.abs(d))
    observed = float(ranks[d > 0].sum())
    exact = 2 ** len(d) <= EXACT_SPLITS
    if exact:
        # row k signs rank i positive when bit i of k is set
        positive = (np.arange(2 ** len(d))[:, None] >> np.arange(len(d))) & 1
    else:
        positive = rng().random((MONTE_CARLO_PERMUTATIONS, len(d))) < 0.5
    null = positive @ ranks
    slack = 1e-9 * max(1.0, observed)          # equal up to rounding counts as equal
    hits = np.sum(null >= observed - slack if alternative == "greater" else null <= observed + slack)
    p = hits / len(null) if exact else (hits + 1) / (len(null) + 1)
    return observed, len(d), float(p), exact


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


def median_time(values, axis=-1):
    """The generation by which half the runs had become bipeds: the smallest value
    with at least half the runs at or below it (vectorised)."""
    return np.quantile(values, 0.5, axis=axis, method="inverted_cdf")


def mean_and_sd(values):
    """(mean, sample standard deviation) of the values; the sd is 0 for one value."""
    values = np.asarray(values, float)
    return float(values.mean()), float(values.std(ddof=1)) if len(values) > 1 else 0.0


def reported_generations(last):
    """The generations (numbered from 0) at which best fitness is reported: the
    paper's 500, 1000 and 2000 that come before `last`, and `last`."""
    return [g for g in (500, 1000, 2000) if g < last] + [last]
