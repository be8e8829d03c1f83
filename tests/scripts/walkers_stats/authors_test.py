#!/usr/bin/env python3
"""Tests for walkers_stats/authors.py: the authors' fitness-data files read (their
format, known curves, malformed files named), and their runs beside ours in the summary
and in Fig. 9, with and without a checkout. The checkout is a stand-in that the tests
write (fixtures.authors_checkout), never the authors' own data.

Run:  /usr/bin/python3 tests/scripts/walkers_stats/authors_test.py   (needs numpy, scipy)
"""
import json
import os
import tempfile
import unittest
from unittest import mock

import numpy as np

import fixtures
from claims_test import PAPER_LIKE
from fixtures import run_statistics
from walkers_stats import authors, figures, load, paper, summary

# their stand-in runs: case 1 flat at 10, 12 and 14 (mean 12); case 2 flat at 12; case 3
# at 5 until generation 2000, then 20 (it leads case 1 in half the generations)
THEIRS = {1: [[(0, 10.0)], [(0, 12.0)], [(0, 14.0)]],
          2: [[(0, 12.0)]] * 3,
          3: [[(0, 4.0), (0, 5.0), (2000, 20.0)]] * 3}


class OneFileTest(unittest.TestCase):
    """A test of one of their files, FILE in a folder of its own."""
    FILE = "case1-1.txt"

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.path = os.path.join(self.tmp.name, self.FILE)

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, text):
        """The file's text."""
        with open(self.path, "w", encoding="utf-8") as f:
            f.write(text)


class ReadRunTest(OneFileTest):
    """One run's file: the best fitness of every generation, or an error naming the line."""

    def test_each_improvement_holds_from_its_generation_on(self):
        fixtures.write_authors_run(self.path, [(0, 1.0), (0, 2.0), (5, 3.0), (100, 4.5)])
        curve = authors.read_run(self.path)
        self.assertEqual(len(curve), paper.GENERATIONS)
        self.assertEqual([curve[g] for g in (0, 4, 5, 99, 100, paper.GENERATIONS - 1)],
                         [2.0, 2.0, 3.0, 3.0, 4.5, 4.5])

    def test_their_format_as_their_files_have_it(self):
        self.write("0,\n0,\n9\ncount: 3\n4.8763,\n5.71967,\n6.87906\ncount: 3\n")
        curve = authors.read_run(self.path)
        self.assertEqual((curve[8], curve[9]), (5.71967, 6.87906))

    def test_malformed_files_are_named(self):
        cases = [
            ("0,\n5\ncount: 3\n1.0,\n2.0\ncount: 2\n", "line 3 says 3 values, the lines above hold 2"),
            ("0,\nfive\ncount: 2\n1.0,\n2.0\ncount: 2\n", "line 2: 'five' is not a generation"),
            ("0,\n7,\n5\ncount: 3\n1.0,\n2.0,\n3.0\ncount: 3\n",
             f"the generations must rise from 0 and stay below {paper.GENERATIONS}"),
            (f"0,\n{paper.GENERATIONS}\ncount: 2\n1.0,\n2.0\ncount: 2\n",
             f"the generations must rise from 0 and stay below {paper.GENERATIONS}"),
            ("0,\n5\ncount: 2\n1.0,\n2.0\n", "expected two 'count: K' lines, found 1"),
            ("0,\n5\ncount: 2\n1.0,\nnan\ncount: 2\n", "a fitness is not a finite number"),
            ("0,\n5\ncount: 2\n1.0\ncount: 1\n", "2 generations but 1 fitnesses"),
        ]
        for text, message in cases:
            self.write(text)
            with self.assertRaises(load.InputError, msg=message) as raised:
                authors.read_run(self.path)
            self.assertEqual(str(raised.exception), f"{self.path}: {message}")


class LabelsTest(OneFileTest):
    """Their gait labels (bump-data) in each of their three layouts, matched to the runs
    by their improvements; every child's fitness (summarisedOutput) and its cut-offs."""
    FILE = "c1_1.txt"

    # the same three improvements in each layout (stand-in numbers, not theirs)
    LAYOUTS = {
        "bump, then generation_child and fitness on lines of their own":
            "$ their script run_x\nbump 1 >>> tripod\ncurrentGen:\n0_0\nmaxFitness:\n4.5\n\n"
            "bump 2 >>> bipedal-tripod\ncurrentGen: \n7_3\nmaxFitness:\n5.25\nwalkerVis.o 0.1 0.2\n\n"
            "bump 3 >>> biped\ncurrentGen: 31_12\nmaxFitness:\n6.0\n\ncount: 3\n\n2400\n>>>\n",
        "generation and child, then bump and fitness":
            "$ their script run_x\ncurrentGen: 0\ncurrentNum: 0\nbump 1 >>> tripod\n4.5 \n\n"
            "currentGen: 7\ncurrentNum: 3\nbump 2 >>>bipedal-tripod\n5.25 \nwalkerVis.o 0.1\n\n"
            "currentGen: 31\ncurrentNum: 12\nbump 3 >>> biped\n6.0 \n\ncount: 3\n",
        "generation and child, then >kG fitness":
            "$ their script run_x\ncurrentGen: 0\ncurrentNum: 0\n>1T 4.5\n\ncurrentGen: 7\n"
            "currentNum: 3\n>2TB 5.25\nwalkerVis.o 0.1\n\ncurrentGen: 31\ncurrentNum: 12\n>3B 6.0\n"
            "count: 3\nadd data\ncurrentGen: 40\n>4B 9.0\n",
    }

    def test_each_layout_gives_the_same_bumps(self):
        for layout, text in self.LAYOUTS.items():
            self.write(text)
            # a bipedal-tripod counts as a tripod
            self.assertEqual(authors.read_labels(self.path),
                             [(0, 4.5, "tripod"), (7, 5.25, "tripod"), (31, 6.0, "biped")], layout)

    def test_malformed_labels_are_named(self):
        good = self.LAYOUTS["bump, then generation_child and fitness on lines of their own"]
        cases = [
            (good.replace("bump 2 >>> bipedal-tripod", "bump 2 >>> quadruped"),
             "line 8: 'bump 2 >>> quadruped' is not bump 2 with a gait of biped, B, tripod, T, "
             "bipedal-tripod, TB"),
            (good.replace("bump 3 >>> biped", "bump 4 >>> biped"),
             "line 15: 'bump 4 >>> biped' is not bump 3 with a gait of"),
            (good.replace("count: 3", "count: 4"), "line 20 says 4 bumps, the lines above hold 3 whole ones"),
            (good.replace("\n7_3\n", "\nseven\n"), "line 10: 'seven' is not a generation G_C"),
            (good.replace("5.25", "fast"), "line 12: 'fast' is not a fitness"),
            (good.replace("count: 3", "three"), "no 'count: K' line"),
        ]
        for text, message in cases:
            self.write(text)
            with self.assertRaises(load.InputError) as raised:
                authors.read_labels(self.path)
            self.assertTrue(str(raised.exception).startswith(f"{self.path}: {message}"),
                            str(raised.exception))

    def test_a_runs_labels_are_the_file_with_its_improvements(self):
        fitness = os.path.join(self.tmp.name, "case1-1.txt")
        fixtures.write_authors_run(fitness, [(0, 4.5), (7, 5.25), (31, 6.0)])
        other = [(0, 4.5), (9, 7.0)]
        labels = {"c1_1.txt": [(g, f, "biped") for g, f in other],
                  "c1_2.txt": [(0, 4.5, "tripod"), (7, 5.25, "tripod"), (31, 6.0, "biped")]}
        gaits = authors.run_gaits(fitness, labels)
        self.assertEqual(len(gaits), paper.GENERATIONS)
        self.assertEqual([gaits[g] for g in (0, 6, 7, 30, 31, paper.GENERATIONS - 1)],
                         ["tripod"] * 4 + ["biped"] * 2)
        with self.assertRaises(load.InputError) as raised:
            authors.run_gaits(fitness, {"c1_1.txt": labels["c1_1.txt"]})
        self.assertEqual(str(raised.exception), f"{fitness}: 0 differently labelled files of "
                         "c1_1.txt have its improvements as their bumps (generation, fitness), not one")

    def test_children_cut_off_per_generation(self):
        path = os.path.join(self.tmp.name, "summarisedOutput-01")
        fixtures.write_authors_children(path, {0: 2, 3999: 16, 17: 1})
        cut_offs, evaluations = authors.read_children(path)
        self.assertEqual(len(cut_offs), paper.GENERATIONS)
        self.assertEqual((cut_offs[0], cut_offs[17], cut_offs[3999], cut_offs.sum()), (2, 1, 16, 19))
        self.assertTrue(np.all(evaluations == fixtures.POPULATION))
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for bad, message in ((text.replace("Generation: 5\n", "Generation: 6\n", 1),
                              "line 36: 'Generation: 6' is not generation 5 followed by "
                              "'Current Fitness:'"),
                             (text.replace("[1.5, 1.5", "[1.5, far", 1),
                              "line 10: '[1.5, far, 1.5"),
                             (text[:text.index("Generation: 3999")], "3999 generations, not 4000")):
            with open(path, "w", encoding="utf-8") as f:
                f.write(bad)
            with self.assertRaises(load.InputError) as raised:
                authors.read_children(path)
            self.assertTrue(str(raised.exception).startswith(f"{path}: {message}"),
                            str(raised.exception))


class LoadAuthorsTest(unittest.TestCase):
    """A checkout: its runs by case and run number, or an error naming it."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def test_runs_by_case_and_run_number(self):
        checkout = fixtures.authors_checkout(self.tmp.name, {2: [[(0, float(m))] for m in range(1, 11)]})
        runs = authors.load_authors(checkout)["runs"]
        self.assertEqual(list(runs), [2])
        self.assertEqual([curve[0] for curve in runs[2]], [float(m) for m in range(1, 11)])

    def test_describe(self):
        checkout = fixtures.authors_checkout(self.tmp.name, THEIRS)
        self.assertEqual(authors.describe(authors.load_authors(checkout)),
                         "9 runs of the authors: case 1: 3, case 2: 3, case 3: 3")
        status, out, err = run_statistics("authors", checkout)
        self.assertEqual((status, out.strip()), (0, "9 runs of the authors: case 1: 3, case 2: 3, case 3: 3"), err)

    def test_the_labels_and_the_children_come_with_the_runs(self):
        gaits = {2: [["tripod", "biped"], ["tripod", "tripod"], ["biped", "tripod"]]}
        checkout = fixtures.authors_checkout(
            self.tmp.name, {2: [[(0, 1.0), (10, 2.0)], [(0, 1.0), (20, 3.0)], [(0, 1.0), (30, 4.0)]]},
            gaits=gaits, cut_offs={2: [{}, {5: 3}, {}]})
        found = authors.load_authors(checkout)
        # the labels' files are numbered the other way round: matched by their bumps
        self.assertEqual([[run[g] for g in (0, 9, 10, 25, 30)] for run in found["gaits"][2]],
                         [["tripod", "tripod", "biped", "biped", "biped"],
                          ["tripod"] * 5, ["biped", "biped", "biped", "biped", "tripod"]])
        self.assertEqual([int(c.sum()) for c, _ in found["children"][2]], [0, 3, 0])
        # a run without its labels, or a case without every run's children, is named
        os.remove(os.path.join(checkout, authors.BUMP_DATA, "c2_2.txt"))
        with self.assertRaises(load.InputError) as raised:
            authors.load_authors(checkout)
        self.assertIn("case2-2.txt: 0 differently labelled files of", str(raised.exception))
        fixtures.write_authors_labels(os.path.join(checkout, authors.BUMP_DATA, "c2_2.txt"),
                                      [(0, 1.0), (20, 3.0)], ["tripod", "tripod"])
        os.remove(os.path.join(checkout, "CaseData", "case2", "summarisedOutput-03"))
        with self.assertRaises(load.InputError) as raised:
            authors.load_authors(checkout)
        self.assertIn("summarisedOutput-*: 2 files, not one for each of case 2's 3 runs",
                      str(raised.exception))

    def test_a_folder_without_their_runs_is_named(self):
        with self.assertRaises(load.InputError) as raised:
            authors.load_authors(self.tmp.name)
        self.assertEqual(str(raised.exception), f"{self.tmp.name}: no {authors.FITNESS_DATA}/ (a checkout "
                                                "of github.com/jhuizhu/bipedalism-scaffolded-learning has it)")
        os.makedirs(os.path.join(self.tmp.name, authors.FITNESS_DATA))
        with self.assertRaises(load.InputError) as raised:
            authors.load_authors(self.tmp.name)
        self.assertIn("no run files caseN-M.txt", str(raised.exception))
        status, _, err = run_statistics("authors", self.tmp.name)
        self.assertEqual(status, 1)
        self.assertIn("no run files caseN-M.txt", err)


class BesideOursTest(unittest.TestCase):
    """Their runs beside ours (PAPER_LIKE: four runs a case of 20 generations)."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.rep = fixtures.claims_reproduction(self.tmp.name, PAPER_LIKE)
        self.checkout = fixtures.authors_checkout(self.tmp.name, THEIRS)

    def tearDown(self):
        self.tmp.cleanup()

    def test_the_table_and_the_findings(self):
        rep = load.load_reproduction(self.rep)
        beside = summary.summarize(rep, authors.load_authors(self.checkout))["beside_authors"]
        self.assertEqual(beside["checkout"], self.checkout)
        self.assertIsNone(beside["note"])
        rows = {(r["case"], r["generation"]): r for r in beside["at_generations"]}
        # every case at our last generation (19) and at the paper's
        self.assertEqual(sorted({g for _, g in rows}), [19, 500, 1000, 2000, 3999])
        free = rows[("free", 19)]
        self.assertAlmostEqual(free["ours"]["mean"], 18.625, places=12)
        self.assertEqual(free["ours"]["runs"], 4)
        low, high = free["ours"]["interval"]
        self.assertTrue(17.5 <= low < 18.625 < high <= 20.0)
        self.assertEqual(free["authors"], {"mean": 12.0, "runs": 3})
        self.assertFalse(free["inside"])
        self.assertTrue(rows[("time", 19)]["inside"])        # ours 12.125, theirs 12
        self.assertEqual(rows[("performance", 1000)]["authors"]["mean"], 5.0)
        self.assertEqual(rows[("performance", 2000)]["authors"]["mean"], 20.0)
        self.assertIsNone(rows[("performance", 2000)]["ours"])   # not reached
        self.assertIsNone(rows[("performance", 2000)]["inside"])
        self.assertEqual(beside["case3_leads_share"]["authors"], 0.5)
        self.assertEqual(beside["case2_over_case1_final"]["authors"], 1.0)
        self.assertEqual(beside["case3_leads_share"]["paper"], paper.CASE3_LEADS_SHARE)

    def test_the_summary_command_sets_them_beside_ours(self):
        status, _, err = run_statistics("summary", self.rep, "--authors", self.checkout)
        self.assertEqual(status, 0, err)
        with open(os.path.join(self.rep, "summary.md"), encoding="utf-8") as f:
            md = f.read()
        self.assertNotIn("Note:", md)
        self.assertRegex(md, r"\| 1, free \| 19 \| 18\.62 \[[0-9.]+, [0-9.]+\] \(4\) \| 12\.00 \(3\) \| \*\*no\*\* \|")
        self.assertRegex(md, r"\| 2, time-constrained \| 19 \| 12\.12 \[[0-9.]+, [0-9.]+\] \(4\) \| 12\.00 \(3\) \| yes \|")
        self.assertIn("| 3, performance-based | 3999 | not reached | 20.00 (3) | — |", md)
        self.assertIn("| generations in which case 3's mean best exceeds case 1's | 95.0 % | 50.0 % | 83.0 % |", md)
        self.assertIn("| case 2's final mean best as a share of case 1's (recorded) | 65.1 % | 100.0 % | 66.0 % |", md)
        with open(os.path.join(self.rep, "summary.json"), encoding="utf-8") as f:
            self.assertEqual(json.load(f)["beside_authors"]["checkout"], self.checkout)

    def test_without_a_checkout_the_summary_says_why(self):
        status, _, err = run_statistics("summary", self.rep)
        self.assertEqual(status, 0, err)
        with open(os.path.join(self.rep, "summary.md"), encoding="utf-8") as f:
            md = f.read()
        self.assertIn("*Note: the authors' runs are missing: no checkout of their repository was "
                      "named (walkers reproduce --authors-checkout PATH).*", md)
        self.assertIn("| 1, free | 19 | 18.62", md)

    def test_a_bad_checkout_is_an_error_and_nothing_is_written(self):
        for command in ("summary", "figures"):
            status, _, err = run_statistics(command, self.rep, "--authors", self.tmp.name)
            self.assertEqual(status, 1, err)
            self.assertIn(f"{self.tmp.name}: no {authors.FITNESS_DATA}/", err)
        self.assertFalse(os.path.exists(os.path.join(self.rep, "summary.json")))
        self.assertFalse(os.path.exists(os.path.join(self.rep, "figures")))

    def test_fig9_draws_their_runs_as_thin_dashed_lines(self):
        def fig9(theirs):
            """Fig. 9 as drawn, with the authors' runs `theirs` (or None): its panels, one
            a case, and its legend row."""
            drawn = {}
            inputs = figures.load_inputs(self.rep, theirs)
            with mock.patch.object(figures, "save", lambda fig, out, name: drawn.__setitem__(name, fig)), \
                    figures.plt.rc_context(figures.STYLE):
                figures.fig9(inputs["series"], inputs["scaffolds"], inputs["generations"], None)
            return drawn["fig9"].axes[:3], drawn["fig9"].axes[3]

        panels, key = fig9(authors.load_authors(self.checkout))
        for panel, scaffold in zip(panels, fixtures.SCAFFOLDS):
            dashed = [l for l in panel.get_lines() if l.get_linestyle() == "--"]
            self.assertEqual(len(dashed), 3, scaffold["name"])     # their three runs of the case
            for line in dashed:
                self.assertLess(line.get_linewidth(), 1.0)
                self.assertEqual(len(line.get_xdata()), 20)      # cut to our generations
            self.assertIn(scaffold["label"], panel.get_title())
        self.assertEqual([list(l.get_ydata()[:1]) for l in panels[2].get_lines()
                          if l.get_linestyle() == "--"], [[5.0]] * 3)
        labels = [t.get_text() for t in key.get_legend().get_texts()]
        self.assertIn("the authors' runs (3 runs a case)", labels)
        self.assertIn("ours on CVODE (4 runs a case)", labels)
        # without a checkout: no lines of theirs, and the legend says why
        panels, key = fig9(None)
        self.assertEqual([l for p in panels for l in p.get_lines() if l.get_linestyle() == "--"], [])
        self.assertIn("no checkout", " ".join(t.get_text() for t in key.get_legend().get_texts()))
        figures.plt.close("all")


if __name__ == "__main__":
    unittest.main(verbosity=2)
