#!/usr/bin/env python3
"""Tests for walkers_stats/claims.py: the verdict rule, the verdict lines, and the claims
on synthetic reproductions (written by fixtures.py as the program writes them) that do
and do not follow the paper; the claims about final fitness use the re-scored medians.

Run:  /usr/bin/python3 tests/scripts/walkers_stats/claims_test.py   (needs numpy, scipy)
"""
import os
import tempfile
import unittest
import warnings

from scipy import stats

import fixtures
from walkers_stats import claims, load, text

Z = stats.norm.ppf(0.975)

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
        self.assertEqual(text.fmt_p(0.0123), "0.012")
        self.assertEqual(text.fmt_p(0.0005250), "5.2e-04")
        self.assertEqual(text.fmt_p(None), "—")
        self.assertEqual(text.fmt_interval((0.1, 0.25), "{:.1f}", 100, " %"), "[10.0, 25.0] %")
        self.assertEqual(text.fmt_interval(None), "(no interval)")
        self.assertEqual(text.n_label(3, 3, 3), "3")
        self.assertEqual(text.n_label(3, 2), "3/2")
        self.assertEqual(text.fmt_generation(4001, never=4001), "never")
        self.assertEqual(text.fmt_generation(12.0, never=4001), "12")
        self.assertEqual(text.fmt_percent(0.8263), "82.6 %")
        self.assertEqual(text.fmt_percent(None), "—")


class TimeEntryTest(unittest.TestCase):
    """The per-case entry of the time to a biped."""

    def test_time_entry_says_never(self):
        entry = claims.time_entry([3.0, 10.0, 10.0], never=10)
        self.assertEqual(entry["median"], None)
        self.assertEqual(entry["never"], 2)
        self.assertEqual(entry["runs"], [3, None, None])
        self.assertEqual(entry["interval"], [3, None])



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
ALIKE = {c: [(19.0 + 0.5 * k, 3 + k, 19.0 + 0.5 * k, 9.0) for k in (0, 3, 1, 2)] for c in fixtures.CASES}


class ClaimsOnRunsTest(unittest.TestCase):
    """The findings and their lines on synthetic reproductions."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def findings(self, runs):
        """{claim id: finding} of the reproduction `runs`."""
        rep = load.load_reproduction(fixtures.claims_reproduction(tempfile.mkdtemp(dir=self.tmp.name), runs))
        block = claims.evaluate(claims.claims_input(rep))
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
                      "highest: **reproduced**: final best 22.50 against 18.62 (means of the re-scored medians)",
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

    def test_the_verdict_table_sets_ours_beside_the_papers(self):
        found, block = self.findings(PAPER_LIKE)
        table = claims.verdict_table(block["findings"])
        self.assertEqual(len(table), 2 + len(claims.CLAIMS))
        self.assertIn("| Case 2 (time) ends below case 1 (free) | at 66 % of case 1 | "
                      "at 65.1 % of case 1 |", "\n".join(table))
        self.assertIn("| Case 2 ends as a tripod more often than cases 1 and 3 | 2 of 3 against "
                      "0 of 6 | 3 of 4 against 0 of 8 | 0.018 | 0.125 | **reproduced** |", table)
        self.assertIn("| +37.5 % | +92.0 % | 0.073 | — | **inconclusive at n = 4** |",
                      table[2 + claims.CLAIMS.index(claims.claim_biped_above_tripod)])
        self.assertIn("| the time-constrained scaffold hinders bipedal evolution | median "
                      "generation never against 5 |",
                      table[2 + claims.CLAIMS.index(claims.claim_case2_later_biped)])
        # a claim these runs cannot test has no figure of ours and no p
        found, block = self.findings({"free": PAPER_LIKE["free"],
                                      "performance": PAPER_LIKE["performance"]})
        row = claims.verdict_table(block["findings"])[
            2 + claims.CLAIMS.index(claims.claim_case2_below_case1)]
        self.assertTrue(row.endswith("| at 66 % of case 1 | — | — | — | **inconclusive at n = 0** |"), row)
        self.assertIn(row, claims.markdown(block))

    def test_paired_tests_over_replicates_stand_beside_and_decide_nothing(self):
        found, _ = self.findings(PAPER_LIKE)
        # case 3 above case 1 in each of the 4 replicates: W+ = 1 + 2 + 3 + 4, p = 1/2^4
        for claim in ("case3_above_case1", "case3_leads_generations"):
            paired = found[claim]["paired_test"]
            self.assertEqual((paired["statistic"], paired["pairs"], paired["exact"]), (10.0, 4, True))
            self.assertEqual(paired["p"], 1 / 16, claim)
            self.assertIn("Wilcoxon signed-rank", paired["name"])
            self.assertIn("paired over replicates: Wilcoxon signed-rank W+ = 10 of 4 pairs that "
                          "differ, p = 0.062", found[claim]["line"])
        # case 2 below case 1 in every replicate: W+ = 0, p = 1/16 the other way
        below = found["case2_below_case1"]["paired_test"]
        self.assertEqual((below["statistic"], below["p"]), (0.0, 1 / 16))
        # case 2 a tripod in replicates 1, 2 and 4, cases 1 and 3 in none: 3 of 3, p = 1/8
        tripods = found["case2_more_tripods"]["paired_test"]
        self.assertEqual((tripods["statistic"], tripods["pairs"], tripods["p"]), (3, 3, 1 / 8))
        self.assertIn("sign test", tripods["name"])
        later = found["case2_later_biped"]["paired_test"]
        self.assertEqual((later["statistic"], later["pairs"], later["p"]), (4, 4, 1 / 16))
        # the verdicts are the independent tests': p = 1/16 would not have reproduced them
        for claim in ("case3_above_case1", "case2_below_case1", "case2_later_biped"):
            self.assertEqual(found[claim]["verdict"], "reproduced", claim)
        self.assertNotIn("paired_test", found["biped_above_tripod"])

    def test_only_replicates_that_both_cases_have_are_paired(self):
        runs = {c: list(v) for c, v in PAPER_LIKE.items()}
        runs["free"] = runs["free"][:3]          # free-4 missing: three pairs
        runs["performance"][0] = (15.0,) + runs["performance"][0][1:]   # replicate 1 reversed
        found, _ = self.findings(runs)
        paired = found["case3_above_case1"]["paired_test"]
        # differences 15 - 19 = -4, 23 - 18 = 5, 21 - 20 = 1, ranked 2, 3, 1: W+ = 3 + 1;
        # the signings with W+ >= 4 are {1, 3}, {2, 3} and {1, 2, 3}: 3 of 8
        self.assertEqual((paired["statistic"], paired["pairs"], paired["p"]), (4.0, 3, 3 / 8))
        self.assertEqual(claims.replicate_pairs(
            [{"case": c, "replicate": r, "final": 10 * k + r} for k, c in enumerate("ab")
             for r in ((1, 2, 5) if c == "a" else (2, 5, 7))], ("a", "b"), lambda r: r["final"]),
            [[2, 5], [12, 15]])

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

    def test_final_fitness_is_the_re_scored_median(self):
        # recorded, case 3 ends far above case 1; re-scored, every final is alike: the
        # claims about final fitness follow the medians, those about the curves do not
        runs = {c: list(v) for c, v in PAPER_LIKE.items()}
        for case in ("free", "performance"):
            runs[case] = [(f, b, bb, bt, {"final_best": 20.0}) for f, b, bb, bt in runs[case]]
        found, block = self.findings(runs)
        case3 = found["case3_above_case1"]
        self.assertEqual(case3["effect"]["value"], 0.0)
        self.assertNotEqual(case3["verdict"], "reproduced")
        self.assertIn("final best 20.00 against 20.00 (means of the re-scored medians)", case3["line"])
        self.assertEqual(block["cases"]["free"]["final_best"]["mean"], 20.0)
        self.assertEqual(found["case3_leads_generations"]["verdict"], "reproduced")
        # the best biped against the best tripod: their medians too
        runs = {c: [(f, b, bb, bt, {"best_biped": 2 * bt}) for f, b, bb, bt in v]
                for c, v in PAPER_LIKE.items()}
        found, _ = self.findings(runs)
        self.assertAlmostEqual(found["biped_above_tripod"]["effect"]["value"], 1.0, places=12)
        self.assertEqual(found["biped_above_tripod"]["test"]["statistic"], 12)   # every run

    def test_the_cases_are_the_scaffolds_places(self):
        # the scaffolds' names come from reproduction.json: renamed, the claims follow
        renamed = [dict(s, name=s["name"].upper()) for s in fixtures.SCAFFOLDS]
        spec = {c.upper(): v for c, v in PAPER_LIKE.items()}
        runs = fixtures.claims_runs(spec)
        rep = load.load_reproduction(fixtures.write_reproduction(self.tmp.name, runs, scaffolds=renamed))
        found = {f["id"]: f for f in claims.evaluate(claims.claims_input(rep))["findings"]}
        self.assertTrue(found["case3_above_case1"]["claim"].startswith(
            "Case 3 (PERFORMANCE) ends above case 1 (FREE)"))
        self.assertEqual(found["case2_more_tripods"]["verdict"], "reproduced")

    def test_each_learner_gets_the_scaffolds_claims(self):
        # the GA's runs follow the paper, another learner's are alike in every case
        runs = fixtures.claims_runs(PAPER_LIKE) + fixtures.claims_runs(ALIKE, learner="pso")
        rep = load.load_reproduction(fixtures.write_reproduction(self.tmp.name, runs,
                                                                 learners=("ga", "pso")))
        self.assertEqual(len(rep["primary"]), 12)
        block = claims.evaluate(claims.claims_input(rep))
        by_learner = {e["learner"]: {f["id"]: f["verdict"] for f in e["findings"]}
                      for e in block["learners"]}
        ids = [c.__name__.replace("claim_", "") for c in claims.LEARNER_CLAIMS]
        self.assertEqual(sorted(by_learner), ["ga", "pso"])
        self.assertEqual(list(by_learner["ga"]), ids)
        self.assertEqual(by_learner["ga"]["case3_above_case1"], "reproduced")
        self.assertEqual(by_learner["ga"]["case2_below_case1"], "reproduced")
        self.assertNotEqual(by_learner["pso"]["case2_below_case1"], "reproduced")
        self.assertNotEqual(by_learner["pso"]["case2_more_tripods"], "reproduced")  # no tripods
        # each learner's own table of cases
        pso = next(e for e in block["learners"] if e["learner"] == "pso")
        self.assertEqual(pso["cases"]["time"]["tripod_finals"]["tripods"], 0)
        self.assertAlmostEqual(pso["cases"]["free"]["final_best"]["mean"], 19.75, places=12)
        md = claims.markdown(block)
        self.assertIn("- pso: Case 3 (performance) ends above case 1 (free)", md)
        # the first learner's findings are the paper's claims
        self.assertEqual({f["id"]: f["verdict"] for f in block["findings"]}["case3_above_case1"],
                         "reproduced")


if __name__ == "__main__":
    warnings.simplefilter("error")       # the statistics must run warning-free
    unittest.main(verbosity=2)
