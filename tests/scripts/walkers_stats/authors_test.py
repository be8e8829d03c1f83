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


class ReadRunTest(unittest.TestCase):
    """One run's file: the best fitness of every generation, or an error naming the line."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.path = os.path.join(self.tmp.name, "case1-1.txt")

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, text):
        """The run file's text."""
        with open(self.path, "w", encoding="utf-8") as f:
            f.write(text)

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
            """Fig. 9 as drawn, with the authors' runs `theirs` (or None)."""
            drawn = {}
            inputs = figures.load_inputs(self.rep, theirs)
            with mock.patch.object(figures, "save", lambda fig, out, name: drawn.__setitem__(name, fig)), \
                    figures.plt.rc_context(figures.STYLE):
                figures.fig9(inputs["runs"], inputs["scaffolds"], inputs["generations"],
                             inputs["authors"], None)
            return drawn["fig9"].axes[0]

        ax = fig9(authors.load_authors(self.checkout))
        dashed = [l for l in ax.get_lines() if l.get_linestyle() == "--"]
        self.assertEqual(len(dashed), 9)
        for line in dashed:
            self.assertLess(line.get_linewidth(), 1.0)
            self.assertEqual(len(line.get_xdata()), 20)      # cut to our generations
        case3 = [l for l in dashed if l.get_color() == fixtures.SCAFFOLDS[2]["colour"]]
        self.assertEqual([list(l.get_ydata()[:1]) for l in case3], [[5.0]] * 3)
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        self.assertIn("the authors' runs", labels)
        self.assertEqual(len(ax.texts), 0)
        # without a checkout: no lines of theirs, and a note says why
        ax = fig9(None)
        self.assertEqual([l for l in ax.get_lines() if l.get_linestyle() == "--"], [])
        self.assertIn("no checkout", " ".join(t.get_text() for t in ax.texts))
        figures.plt.close("all")


if __name__ == "__main__":
    unittest.main(verbosity=2)
