#!/usr/bin/env python3
"""Tests for walkers_stats/summary.py and the summary command as `walkers reproduce` runs
it (`scripts/walkers_stats summary DIR`): the files it owns, their numbers on synthetic
reproductions (fixtures.py), the same bytes when run again, and bad input named.

Run:  /usr/bin/python3 tests/scripts/walkers_stats/summary_test.py   (needs numpy, scipy)
"""
import json
import os
import shutil
import tempfile
import unittest

import fixtures
from claims_test import ALIKE, PAPER_LIKE
from fixtures import edit_json, run_statistics
from walkers_stats import claims, load, summary


class SummaryTest(unittest.TestCase):
    """The summary command on a reproduction of four replicates a case that follows the
    paper."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.rep = fixtures.claims_reproduction(self.tmp.name, PAPER_LIKE, ensemble=3)

    def tearDown(self):
        self.tmp.cleanup()

    def read(self, name):
        """A file of the reproduction, as text."""
        with open(os.path.join(self.rep, name), encoding="utf-8") as f:
            return f.read()

    def test_writes_both_files_and_again_the_same(self):
        status, out, err = run_statistics("summary", self.rep)
        self.assertEqual(status, 0, err)
        self.assertEqual(err, "")
        s = json.loads(self.read("summary.json"))
        md = self.read("summary.md")
        self.assertEqual(len(s["claims"]["findings"]), len(claims.CLAIMS))
        for f in s["claims"]["findings"]:
            self.assertIn(f"- {f['line']}\n", md)
            self.assertIn(f["line"].replace("**", ""), out)
        sections = ["## Best fitness, beside the authors' runs", "## Claims",
                    "## The best biped and the best tripod", "## Figures"]
        self.assertEqual(sorted(sections, key=md.index), sections)
        self.assertIn("| time | 4 |", md)
        # what made the runs: the program's commit and settings, carried over
        self.assertEqual(s["program"]["commit"], "0123456789ab")
        self.assertEqual(s["program"]["evaluation"]["relative_tolerance"], 1e-7)
        self.assertIn("commit `0123456789ab`", md)
        # again: the same bytes
        first = (self.read("summary.json"), md)
        status, _, err = run_statistics("summary", self.rep)
        self.assertEqual(status, 0, err)
        self.assertEqual((self.read("summary.json"), self.read("summary.md")), first)

    def test_counts_rates_and_bests(self):
        rep = load.load_reproduction(self.rep)
        s = summary.summarize(rep, None)
        # 12 runs of 20 generations of 16 children, 3 falls a generation, 40 per second
        self.assertEqual(len(s["runs"]), 12)
        self.assertEqual(s["evaluations"], 12 * 20 * fixtures.POPULATION)
        self.assertEqual(s["runs"][0]["falls"], 20 * 3)
        self.assertAlmostEqual(s["fell_share"], 3 / fixtures.POPULATION, places=12)
        self.assertAlmostEqual(s["evaluation_seconds"], 12 * 20 * fixtures.POPULATION / 40.0, places=9)
        self.assertAlmostEqual(s["evals_per_s"], 40.0, places=9)
        # the best biped and tripod: performance-4's 24.0, time-1's 12.0 (re-scored as recorded)
        self.assertEqual((s["best_biped"]["run"], s["best_biped"]["fitness"]), ("performance-4", 24.0))
        self.assertEqual((s["best_tripod"]["run"], s["best_tripod"]["fitness"]), ("time-4", 12.5))
        self.assertEqual(s["rescores"], {"ensemble": 3, "not_reproduced": []})
        md = summary.markdown(s, rep)
        self.assertIn("| best biped | 24.00, re-scored 24.00 (performance-4, 19/1) | from case 3 |", md)
        self.assertIn("| evaluations that fell | 18.8 % | 37–49 % (the authors' runs) |", md)
        self.assertIn("for 36 of the 36 finalists.", md)

    def test_a_recorded_fitness_not_scored_again_is_named(self):
        edit_json(os.path.join(self.rep, "reproduction.json"),
                  lambda m: m["runs"][2]["final_best"]["rescore"].update(recorded_reproduced=False))
        rep = load.load_reproduction(self.rep)
        s = summary.summarize(rep, None)
        self.assertEqual(s["rescores"]["not_reproduced"], ["free-3 19/0 (final_best)"])
        self.assertIn("for 35 of the 36 finalists (not: free-3 19/0 (final_best): those runs were "
                      "made by other numerics).", summary.markdown(s, rep))

    def test_without_the_authors_runs_a_note_says_why(self):
        s = summary.summarize(load.load_reproduction(self.rep), None)
        beside = s["beside_authors"]
        self.assertIsNone(beside["checkout"])
        self.assertIn("no checkout of their repository was named", beside["note"])
        self.assertTrue(all(row["authors"] is None for row in beside["at_generations"]))
        # ours still: at our last generation, 19 (the paper's are not reached)
        self.assertEqual([(r["case"], r["generation"]) for r in beside["at_generations"]],
                         [(c, 19) for c in fixtures.CASES])
        self.assertAlmostEqual(beside["at_generations"][0]["ours"]["mean"], 18.625, places=12)
        self.assertEqual(beside["case3_leads_share"]["ours"],
                         next(f for f in s["claims"]["findings"]
                              if f["id"] == "case3_leads_generations")["effect"]["value"])
        self.assertAlmostEqual(beside["case2_over_case1_final"]["ours"], 48.5 / 74.5, places=12)
        self.assertIsNone(beside["case2_over_case1_final"]["authors"])

    def test_learners_get_their_table(self):
        runs = fixtures.claims_runs(PAPER_LIKE) + fixtures.claims_runs(ALIKE, learner="pso")
        rep_dir = fixtures.write_reproduction(os.path.join(self.tmp.name, "two"), runs,
                                              learners=("ga", "pso"))
        status, _, err = run_statistics("summary", rep_dir)
        self.assertEqual(status, 0, err)
        with open(os.path.join(rep_dir, "summary.md"), encoding="utf-8") as f:
            md = f.read()
        self.assertIn("## Learners under the scaffolds", md)
        self.assertIn("| genetic algorithm (ga) | 18.62, 0 of 4 tripods | 12.12, 3 of 4 tripods | "
                      "22.50, 0 of 4 tripods | 95.0 % | 65.1 % |", md)
        self.assertIn("| particle swarm (pso) | 19.75, 0 of 4 tripods |", md)
        with open(os.path.join(rep_dir, "summary.json"), encoding="utf-8") as f:
            s = json.load(f)
        self.assertEqual(s["learners"], ["ga", "pso"])
        self.assertEqual(len(s["runs"]), 12, "the paper's statistics are the first learner's")
        self.assertEqual([e["learner"] for e in s["claims"]["learners"]], ["ga", "pso"])

    def test_a_ratio_over_zero_is_null_in_json(self):
        runs = {c: list(v) for c, v in PAPER_LIKE.items()}
        runs["free"] = [(0.0, None, None, 0.0) for _ in range(4)]     # case 1 never moved
        rep = fixtures.claims_reproduction(os.path.join(self.tmp.name, "zero"), runs)
        status, _, err = run_statistics("summary", rep)
        self.assertEqual(status, 0, err)
        self.assertEqual(err, "")                  # no warning either
        with open(os.path.join(rep, "summary.json")) as f:
            block = json.load(f)["claims"]
        below = next(f for f in block["findings"] if f["id"] == "case2_below_case1")
        self.assertIsNone(below["effect"]["value"])
        self.assertTrue(below["verdict"].startswith("inconclusive"), below["verdict"])


class BadInputTest(unittest.TestCase):
    """Bad input names the file and the field; nothing is written; the status is 1."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.rep = fixtures.claims_reproduction(self.tmp.name, PAPER_LIKE, ensemble=3)
        self.manifest = os.path.join(self.rep, "reproduction.json")

    def tearDown(self):
        self.tmp.cleanup()

    def refused(self, message):
        """Run the summary; it must fail naming `message` and write nothing."""
        status, _, err = run_statistics("summary", self.rep)
        self.assertEqual(status, 1, err)
        self.assertIn(message, err)
        self.assertNotIn("Traceback", err)
        self.assertFalse(os.path.exists(os.path.join(self.rep, "summary.json")))
        self.assertFalse(os.path.exists(os.path.join(self.rep, "summary.md")))

    def test_missing_generations_names_the_file(self):
        path = os.path.join(self.rep, "time-2", "generations.csv")
        os.remove(path)
        self.refused(f"{path}: file not found")

    def test_bad_fields_are_named(self):
        with open(self.manifest) as f:
            original = f.read()
        cases = [
            (lambda m: m["runs"][2].pop("best_tripod"), "missing field 'runs[2].best_tripod'"),
            (lambda m: m["runs"][1]["best_biped"].__setitem__("fitness", "far"),
             "field 'runs[1].best_biped.fitness' must be a finite number"),
            (lambda m: m["runs"][0]["final_best"]["rescore"]["fitness"].pop(),
             "field 'runs[0].final_best.rescore.fitness' has 2 members, not the ensemble's 3"),
            (lambda m: m["runs"][0]["final_best"]["rescore"].__setitem__("bipeds", 4),
             "field 'runs[0].final_best.rescore.bipeds' is 4, outside [0, 3]"),
            (lambda m: m["scaffolds"][1].__setitem__("paper_tripod_finals", 4),
             "field 'scaffolds[1].paper_tripod_finals' is 4, outside [0, 3]"),
            (lambda m: m["runs"][0].__setitem__("case", "lazy"),
             "field 'runs[0].case' is 'lazy', expected one of free, time, performance"),
            (lambda m: m.__setitem__("best_biped", {"run": "free-1", "id": "3/1"}),
             "field 'best_biped' names free-1 3/1, which is not that run's best_biped"),
            (lambda m: m.pop("ensemble"), "missing field 'ensemble'"),
        ]
        for change, message in cases:
            obj = json.loads(original)
            change(obj)
            fixtures.write_json(self.manifest, obj)
            self.refused(f"{self.manifest}: {message}")

    def test_a_run_changed_since_is_named(self):
        # a run continued after reproduction.json was written: its last best differs
        path = os.path.join(self.rep, "free-1", "generations.csv")
        with open(path) as f:
            lines = f.readlines()
        lines.append(lines[-1].replace("19,", "20,", 1).replace(",19.0,", ",19.5,", 1))
        with open(path, "w") as f:
            f.writelines(lines)
        self.refused(f"{path}: the last best fitness 19.5 is not {self.manifest}'s "
                     "runs[0].final_best.fitness 19.0: the run changed since; "
                     "`walkers reproduce --resume` writes both again")

    def test_bad_generations_row_is_named(self):
        path = os.path.join(self.rep, "free-1", "generations.csv")
        with open(path) as f:
            lines = f.readlines()
        lines[3] = lines[3].replace("tripod", "quadruped").replace("biped", "quadruped")
        with open(path, "w") as f:
            f.writelines(lines)
        self.refused(f"{path}: line 4, column best_gait: 'quadruped'")

    def test_not_a_directory(self):
        status, _, err = run_statistics("summary", os.path.join(self.tmp.name, "nowhere"))
        self.assertEqual(status, 1)
        self.assertIn("nowhere: not a directory", err)

    def test_an_earlier_summary_is_kept_when_the_input_is_bad(self):
        self.assertEqual(run_statistics("summary", self.rep)[0], 0)
        with open(os.path.join(self.rep, "summary.md"), encoding="utf-8") as f:
            earlier = f.read()
        shutil.rmtree(os.path.join(self.rep, "time-3"))
        status, _, err = run_statistics("summary", self.rep)
        self.assertEqual(status, 1, err)
        with open(os.path.join(self.rep, "summary.md"), encoding="utf-8") as f:
            self.assertEqual(f.read(), earlier)


if __name__ == "__main__":
    unittest.main(verbosity=2)
