#!/usr/bin/env python3
"""Tests for the experiments set side by side: where the tripods go (tripods.py), the
cut-offs' share (cut_offs.py, and the `cut-offs` command that keeps them), and the
`experiments` command (side_by_side.py) over a tree of results with and without the
experiment as the authors ran it, on hand-made runs with known shares, Fisher's p and
counts, and a stand-in checkout of the authors' (fixtures.authors_checkout).

Run:  /usr/bin/python3 tests/scripts/walkers_stats/experiments_test.py   (needs numpy, scipy)
"""
import json
import os
import shutil
import tempfile
import unittest

import numpy as np

import fixtures
from claims_test import PAPER_LIKE
from fixtures import edit_json, run_statistics
from walkers_stats import authors, cut_offs, experiments, load, side_by_side, tripods

GENERATIONS = 4000


def tripod_until(case, replicate, until, final=10.0, cut_offs=None):
    """A run whose best is a tripod before generation `until` (None: to the end) and a
    biped from it, its fitness rising linearly to `final`."""
    gaits = ["tripod" if until is None or g < until else "biped" for g in range(GENERATIONS)]
    return fixtures.run(case, replicate, np.linspace(1.0, final, GENERATIONS), gaits,
                        best_biped=final if until is not None else None,
                        best_tripod=final if until is None else 1.0, cut_offs=cut_offs)


# ours: free a tripod until 100, 300 and 800 and to the end; time a tripod to the end in
# every run; performance a biped from generation 0
OURS = ([tripod_until("free", r, u) for r, u in enumerate((100, 300, 800, None), 1)] +
        [tripod_until("time", r, None, 8.0 + r) for r in range(1, 5)] +
        [tripod_until("performance", r, 0, 12.0 + r) for r in range(1, 5)])
# theirs: three runs a case, each a tripod until 600 (a bipedal-tripod from 100), a biped
# from then on
THEIR_RUNS = {case: [[(0, 4.0), (100, 5.0), (600, 8.0 + m)] for m in range(3)] for case in (1, 2, 3)}
THEIR_GAITS = {case: [["tripod", "bipedal-tripod", "biped"]] * 3 for case in (1, 2, 3)}
# theirs cut off: case 2's first run 4 children at generation 10, 2 at 600 and 8 at 3999
THEIR_CUT_OFFS = {2: [{10: 4, 600: 2, 3999: 8}, {}, {}]}


class TripodsTest(unittest.TestCase):
    """The share of tripod bests at the reported generations, the biped for good, and
    Fisher's test against the authors'."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        rep = load.load_reproduction(fixtures.write_reproduction(cls.tmp.name, OURS, GENERATIONS))
        theirs = authors.load_authors(fixtures.authors_checkout(
            cls.tmp.name, THEIR_RUNS, gaits=THEIR_GAITS, cut_offs=THEIR_CUT_OFFS))
        cls.rep, cls.theirs = rep, theirs
        cls.block = tripods.compare(experiments.series(rep, theirs), rep["scaffolds"])

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def entry(self, experiment, case):
        """An experiment's entry of a case."""
        return next(e for e in self.block["experiments"] if e["experiment"] == experiment)["cases"][case]

    def test_the_shares_at_the_reported_generations(self):
        self.assertEqual([e["experiment"] for e in self.block["experiments"]], ["authors", "cvode"])
        free = self.entry("cvode", "free")
        self.assertEqual([(row["generation"], row["tripods"]) for row in free["tripod_shares"]],
                         [(0, 4), (250, 3), (500, 2), (750, 2), (1000, 1), (2000, 1), ("last", 1)])
        self.assertTrue(all(row["runs"] == 4 for row in free["tripod_shares"]))
        self.assertEqual([row["tripods"] for row in self.entry("cvode", "performance")["tripod_shares"]],
                         [0] * 7)
        # theirs: tripods until 600 (a bipedal-tripod counts as one)
        self.assertEqual([row["tripods"] for row in self.entry("authors", "free")["tripod_shares"]],
                         [3, 3, 3, 0, 0, 0, 0])
        self.assertIsNone(self.block["note"])

    def test_the_biped_for_good(self):
        free = self.entry("cvode", "free")["biped_for_good"]
        # 100, 300, 800 and never: half the runs are bipeds for good by 300
        self.assertEqual((free["median"], free["never"], free["runs"]), (300, 1, [100, 300, 800, None]))
        self.assertEqual(self.entry("cvode", "time")["biped_for_good"]["never"], 4)
        self.assertEqual(self.entry("authors", "time")["biped_for_good"]["runs"], [600] * 3)

    def test_fisher_against_the_authors(self):
        # time: 4 of 4 ending as tripods against their 0 of 3. With 4 tripods among 7 runs,
        # C(4, k) C(3, 4 - k) / C(7, 4) for k = 1..4 is 4, 18, 12, 1 / 35: only k = 4 is as
        # unlikely as the observed
        fisher = self.entry("cvode", "time")["final_against_authors"]
        self.assertEqual((fisher["tripods"], fisher["runs"], fisher["authors_tripods"],
                          fisher["authors_runs"]), (4, 4, 0, 3))
        self.assertAlmostEqual(fisher["p"], 1 / 35, places=12)
        self.assertEqual(self.entry("cvode", "performance")["final_against_authors"]["p"], 1.0)
        self.assertNotIn("final_against_authors", self.entry("authors", "time"))

    def test_the_table(self):
        md = tripods.markdown(self.block, self.rep["scaffolds"])
        self.assertIn("| case | runs | tripods at 0 | 250 | 500 | 750 | 1000 | 2000 | 3999 |", md)
        self.assertIn("| 1, free: ours on CVODE | 4 | 4 of 4 | 3 of 4 | 2 of 4 | 2 of 4 | 1 of 4 | "
                      "1 of 4 | 1 of 4 | 300 (never: 1) | 1.000 |", md)
        self.assertIn("| 2, time-constrained: ours on CVODE | 4 | 4 of 4 | 4 of 4 | 4 of 4 | 4 of 4 | "
                      "4 of 4 | 4 of 4 | 4 of 4 | never (never: 4) | 0.029 |", md)
        self.assertIn("| 2, time-constrained: the authors' runs | 3 | 3 of 3 | 3 of 3 | 3 of 3 | "
                      "0 of 3 | 0 of 3 | 0 of 3 | 0 of 3 | 600 (never: 0) | — |", md)
        self.assertLess(md.index("1, free: the authors' runs"), md.index("1, free: ours on CVODE"))

    def test_without_the_authors_a_note(self):
        block = tripods.compare(experiments.series(self.rep, None), self.rep["scaffolds"])
        self.assertEqual([e["experiment"] for e in block["experiments"]], ["cvode"])
        self.assertNotIn("final_against_authors", block["experiments"][0]["cases"]["free"])
        self.assertIn("*Note: the authors' runs are missing", tripods.markdown(block, self.rep["scaffolds"]))


def rk_merson_runs(generations=20):
    """PAPER_LIKE's runs with cut-offs: free-1 3 children at generation 2 and 1 at 12;
    time-2 16 at generation 19 (of 20, in blocks of 10 generations)."""
    runs = fixtures.claims_runs(PAPER_LIKE, generations)
    for r in runs:
        r["cut_offs"] = {("free", 1): {2: 3, 12: 1}, ("time", 2): {19: 16}}.get(
            (r["case"], r["replicate"]), {})
    return runs


class CutOffsTest(unittest.TestCase):
    """The cut-offs by case and block: ours counted in evaluations.csv (or kept in
    cut_offs.csv), theirs in their summarisedOutput files, none under CVODE."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.rep_dir = fixtures.write_reproduction(self.tmp.name, rk_merson_runs(), 20,
                                                   evaluation=fixtures.RK_MERSON)
        self.checkout = fixtures.authors_checkout(self.tmp.name, THEIR_RUNS, gaits=THEIR_GAITS,
                                                  cut_offs=THEIR_CUT_OFFS)

    def tearDown(self):
        self.tmp.cleanup()

    def test_ours_by_block(self):
        with mock_block(10):
            rep = load.load_reproduction(self.rep_dir)
            block = cut_offs.compare([rep], None)
        (ours,) = block["experiments"]
        self.assertEqual((ours["experiment"], ours["cut_off"]),
                         ("rk-merson", "past 128,000 right-hand sides"))
        free = ours["cases"]["free"]
        # four runs of 16 children a generation; blocks 0-9, 10-19 and the whole run
        self.assertEqual([(b["first"], b["last"], b["cut_offs"], b["evaluations"]) for b in free["blocks"]],
                         [(0, 9, 3, 640), (10, 19, 1, 640), (0, 19, 4, 1280)])
        self.assertEqual([b["cut_offs"] for b in ours["cases"]["time"]["blocks"]], [0, 16, 16])
        self.assertEqual([b["cut_offs"] for b in ours["cases"]["performance"]["blocks"]], [0, 0, 0])
        md = cut_offs.markdown(block, rep["scaffolds"])
        self.assertIn("| case | cut off | 0–9 | 10–19 | all |", md)
        self.assertIn("| 1, free: ours as the authors ran it (RK-Merson) (4 runs) | past 128,000 "
                      "right-hand sides | 0.5 % | 0.2 % | 0.3 % |", md)
        self.assertIn("*Note: the authors' runs are missing", md)

    def test_theirs_by_block(self):
        rep = load.load_reproduction(self.rep_dir)
        block = cut_offs.compare([rep], authors.load_authors(self.checkout))
        theirs = block["experiments"][0]
        self.assertEqual((theirs["experiment"], theirs["cut_off"]), ("authors", "past 25 s of wall clock"))
        time = theirs["cases"]["time"]["blocks"]
        self.assertEqual(len(time), 9)
        self.assertEqual([(b["first"], b["last"]) for b in time[:2]] + [(time[-1]["first"], time[-1]["last"])],
                         [(0, 499), (500, 999), (0, 3999)])
        self.assertEqual([b["cut_offs"] for b in time], [4, 2, 0, 0, 0, 0, 0, 8, 14])
        self.assertEqual(time[0]["evaluations"], 3 * 500 * fixtures.POPULATION)
        self.assertIn("| 2, time-constrained: the authors' runs (3 runs) | past 25 s of wall clock | "
                      "0.0 % | 0.0 % |", cut_offs.markdown(block, rep["scaffolds"]))

    def test_cvode_has_none(self):
        rep = load.load_reproduction(fixtures.claims_reproduction(os.path.join(self.tmp.name, "c"),
                                                                  PAPER_LIKE))
        self.assertTrue(all(r["cut_offs"] is None for r in rep["runs"]))
        block = cut_offs.compare([rep], None)
        self.assertEqual(block["experiments"][0]["cut_off"], None)
        self.assertIn("- Ours on CVODE: none: its runs were made without one (reproduction.json "
                      "sets no program.evaluation.cut_off_rhs).", cut_offs.markdown(block, rep["scaffolds"]))

    def test_kept_in_cut_offs_csv_when_evaluations_csv_is_not(self):
        status, _, err = run_statistics("summary", self.rep_dir)
        self.assertEqual(status, 0, err)
        with open(os.path.join(self.rep_dir, "summary.json"), encoding="utf-8") as f:
            first = f.read()
        runs = [os.path.join(self.rep_dir, d) for d in sorted(os.listdir(self.rep_dir))
                if os.path.isdir(os.path.join(self.rep_dir, d))]
        status, out, err = run_statistics("cut-offs", *runs)
        self.assertEqual(status, 0, err)
        self.assertEqual(out.count("wrote "), 12)
        with open(os.path.join(self.rep_dir, "free-1", "cut_offs.csv"), encoding="utf-8") as f:
            lines = f.read().splitlines()
        self.assertEqual(lines[:4], ["generation,cut_offs", "0,0", "1,0", "2,3"])
        self.assertEqual(len(lines), 21)
        for run in runs:
            os.remove(os.path.join(run, "evaluations.csv"))
        status, _, err = run_statistics("summary", self.rep_dir)
        self.assertEqual(status, 0, err)
        with open(os.path.join(self.rep_dir, "summary.json"), encoding="utf-8") as f:
            self.assertEqual(f.read(), first, "the summary changed without evaluations.csv")
        # a run with neither is named, and counted out
        os.remove(os.path.join(self.rep_dir, "time-2", "cut_offs.csv"))
        rep = load.load_reproduction(self.rep_dir)
        block = cut_offs.compare([rep], None)
        time = block["experiments"][0]["cases"]["time"]
        self.assertEqual((time["runs"], time["unrecorded"]), (3, ["time-2"]))
        self.assertIn("no cut-offs recorded for time-2 (neither evaluations.csv nor cut_offs.csv)",
                      cut_offs.markdown(block, rep["scaffolds"]))
        # the command needs evaluations.csv; nothing is written when a run lacks it
        os.remove(os.path.join(runs[0], "cut_offs.csv"))
        status, _, err = run_statistics("cut-offs", runs[0], os.path.join(self.rep_dir, "time-3"))
        self.assertEqual(status, 1)
        self.assertIn(f"{os.path.join(runs[0], 'evaluations.csv')}: file not found", err)
        # a run made without a cut-off has none to keep
        cvode = fixtures.claims_reproduction(os.path.join(self.tmp.name, "c"), PAPER_LIKE)
        status, out, err = run_statistics("cut-offs", os.path.join(cvode, "free-1"))
        self.assertEqual((status, out.strip()),
                         (0, f"{os.path.join(cvode, 'free-1')}: no cut-off, nothing to keep"), err)
        self.assertFalse(os.path.exists(os.path.join(cvode, "free-1", "cut_offs.csv")))

    def test_bad_records_are_named(self):
        path = os.path.join(self.rep_dir, "free-1", "evaluations.csv")
        with open(path) as f:
            lines = f.readlines()
        lines[5] = "0,4,,0.5\n"            # no fitness
        with open(path, "w") as f:
            f.writelines(lines)
        status, _, err = run_statistics("summary", self.rep_dir)
        self.assertEqual(status, 1)
        self.assertIn(f"{path}: line 6: no generation and fitness", err)
        os.remove(path)
        with open(os.path.join(self.rep_dir, "free-1", "cut_offs.csv"), "w") as f:
            f.write("generation,cut_offs\n0,0\n2,1\n")
        status, _, err = run_statistics("summary", self.rep_dir)
        self.assertEqual(status, 1)
        self.assertIn("cut_offs.csv: line 3: '2,1' is not generation 1 and a count", err)
        edit_json(os.path.join(self.rep_dir, "reproduction.json"),
                  lambda m: m["program"]["evaluation"].update(integrator="euler"))
        status, _, err = run_statistics("summary", self.rep_dir)
        self.assertIn("field 'program.evaluation.integrator' is 'euler', expected one of cvode, "
                      "rk-merson", err)


class mock_block:
    """cut_offs.BLOCK set to `size` generations for a while (the tests' runs are short)."""

    def __init__(self, size):
        self.size = size

    def __enter__(self):
        self.saved, cut_offs.BLOCK = cut_offs.BLOCK, self.size

    def __exit__(self, *exc):
        cut_offs.BLOCK = self.saved


class SideBySideTest(unittest.TestCase):
    """`walkers_stats experiments ROOT`: CVODE's results in ROOT, RK-Merson's in
    ROOT/rk-merson once its summary exists."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = fixtures.claims_reproduction(self.tmp.name, PAPER_LIKE, folder="results")
        self.checkout = fixtures.authors_checkout(self.tmp.name, THEIR_RUNS, gaits=THEIR_GAITS,
                                                  cut_offs=THEIR_CUT_OFFS)
        self.assertEqual(run_statistics("summary", self.root, "--authors", self.checkout)[0], 0)
        self.readme = os.path.join(self.tmp.name, "README.md")
        with open(self.readme, "w", encoding="utf-8") as f:
            f.write(f"# Title\n\nBefore.\n\n{side_by_side.README_BEGIN}\nold table\n"
                    f"{side_by_side.README_END}\n\nAfter.\n")

    def tearDown(self):
        self.tmp.cleanup()

    def experiments(self, *extra):
        """Run the command; returns (experiments.json, experiments.md, README.md)."""
        status, _, err = run_statistics("experiments", self.root, "--authors", self.checkout,
                                        "--readme", self.readme, *extra)
        self.assertEqual(status, 0, err)
        texts = []
        for path in (os.path.join(self.root, side_by_side.DATA),
                     os.path.join(self.root, side_by_side.PAGE), self.readme):
            with open(path, encoding="utf-8") as f:
                texts.append(f.read())
        return json.loads(texts[0]), texts[1], texts[2]

    def test_cvode_and_the_authors_until_rk_merson_arrives(self):
        data, md, readme = self.experiments()
        self.assertEqual([(e["id"], e["state"]) for e in data["experiments"]],
                         [("cvode", "present"), ("rk-merson", "pending")])
        self.assertIn("| the paper's claim | the paper | ours on CVODE, n = 4 | ours as the authors "
                      "ran it (RK-Merson): pending |", md)
        self.assertIn("| Case 2 ends as a tripod more often than cases 1 and 3 | 2 of 3 against 0 of 6 "
                      "| 3 of 4 against 0 of 8; p = 0.018: **reproduced** | pending |", md)
        # like with like: their recorded 9, 10, 11 (mean 10) beside ours recorded and re-scored
        self.assertIn("| 1, free | 9.00 | 18.62 | 18.62 | pending | pending |", md)
        for name in side_by_side.FIGURES:
            for ext in ("png", "svg"):
                self.assertTrue(os.path.isfile(os.path.join(self.root, "figures", f"{name}.{ext}")))
        # the README's block holds the claims and the finals, the rest of it stays
        self.assertTrue(readme.startswith(f"# Title\n\nBefore.\n\n{side_by_side.README_BEGIN}\n"))
        self.assertTrue(readme.endswith(f"{side_by_side.README_END}\n\nAfter.\n"))
        self.assertNotIn("old table", readme)
        self.assertIn("| 3 of 4 against 0 of 8; p = 0.018: **reproduced** | pending |", readme)
        # again: the same bytes
        self.assertEqual(self.experiments(), (data, md, readme))

    def test_with_rk_merson_every_experiment(self):
        rk = fixtures.write_reproduction(self.root, rk_merson_runs(), 20,
                                         evaluation=fixtures.RK_MERSON, folder="rk-merson")
        self.experiments()        # without its summary it is pending still
        self.assertEqual(run_statistics("summary", rk, "--authors", self.checkout)[0], 0)
        data, md, readme = self.experiments()
        self.assertEqual([(e["id"], e["state"]) for e in data["experiments"]],
                         [("cvode", "present"), ("rk-merson", "present")])
        self.assertIn("| ours on CVODE, n = 4 | ours as the authors ran it (RK-Merson), n = 4 |", md)
        self.assertNotIn("pending", readme)
        self.assertEqual([e["experiment"] for e in data["tripods"]["experiments"]],
                         ["authors", "cvode", "rk-merson"])
        self.assertEqual([e["experiment"] for e in data["cut_offs"]["experiments"]],
                         ["authors", "cvode", "rk-merson"])
        self.assertIn("| 1, free: ours as the authors ran it (RK-Merson) (4 runs) | past 128,000 "
                      "right-hand sides | 0.3 % | 0.3 % |", md)
        self.assertIn("| case | cut off | 0–499 | 500–999 |", md)     # theirs: other blocks

    def test_bad_input_is_named_and_nothing_written(self):
        # a CVODE reproduction in RK-Merson's folder
        shutil.copytree(self.root, os.path.join(self.root, "rk-merson"),
                        ignore=shutil.ignore_patterns("rk-merson"))
        status, _, err = run_statistics("experiments", self.root, "--readme", self.readme)
        self.assertEqual(status, 1)
        self.assertIn("rk-merson/reproduction.json: field 'program.evaluation.integrator' is 'cvode', "
                      "but", err)
        shutil.rmtree(os.path.join(self.root, "rk-merson"))
        with open(self.readme, "w", encoding="utf-8") as f:
            f.write("# No block\n")
        status, _, err = run_statistics("experiments", self.root, "--readme", self.readme)
        self.assertEqual(status, 1)
        self.assertIn(f"{self.readme}: no block between the lines", err)
        edit_json(os.path.join(self.root, "summary.json"), lambda s: s["claims"].pop("findings"))
        status, _, err = run_statistics("experiments", self.root)
        self.assertIn("summary.json: missing field 'claims.findings'", err)
        self.assertFalse(os.path.exists(os.path.join(self.root, side_by_side.PAGE)))
        os.remove(os.path.join(self.root, "summary.json"))
        status, _, err = run_statistics("experiments", self.root)
        self.assertEqual(status, 1)
        self.assertIn("no experiment of ours has a summary.json", err)


if __name__ == "__main__":
    unittest.main(verbosity=2)
