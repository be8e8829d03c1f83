#!/usr/bin/python3
"""scripts/compare_authors.py on synthetic data: genome files from a made-up run record of the
authors' evolver, and the side-by-side comparison with stand-ins for both programs (the real
ones need Simbody and a build; their arithmetic is not what is tested here)."""

import json
import os
import pathlib
import stat
import subprocess
import sys
import tempfile
import unittest

HERE = pathlib.Path(__file__).resolve().parent
TOOL = HERE.parent.parent / "scripts" / "compare_authors.py"
sys.path.insert(0, str(TOOL.parent))
import compare_authors  # noqa: E402

GENES = {
    "halfBodyX": 0.5, "halfBodyY": 0.1, "halfBodyZ": 0.3, "halfFootBodyX": 0.2, "halfFootBodyY": 0.05,
    "halfFootBodyZ": 0.07, "k1": 1500.0, "k2": 7000.0, "lambda1": 700.0, "lambda2": 1900.0,
    "bodyStraightK": 300.0, "bodyStraightL": 100.0, "kneeMass": 0.7, "ankleMass": 0.1, "hipMass": 0.1,
    "stepK": 200.0, "stableTolerance": 0.2, "tibiaLength": 0.6, "femurLength": 0.5, "standOffset": 0.01,
    "stepOffset": -0.002,
}

# Their program: prints a fitness that is kx / 100 (so the tests know it), or exits 254 (a
# fall, return -2) when kx is 1234, or takes 30 s when kx is 999.
FAKE_AUTHORS = """#!/bin/sh
kx=$7
if [ "$kx" = "1234" ]; then exit 254; fi
if [ "$kx" = "999" ]; then exec sleep 30; fi
awk -v kx="$kx" 'BEGIN { printf "%.4f", kx / 100 }'
"""

# walkers evaluate --ensemble N --json: a median 0.9 x kx / 100 (0.5 x under rk-merson), one tripod
# when ky > 8000.
FAKE_WALKERS = """#!/usr/bin/python3
import json, sys
args = sys.argv[1:]
g = json.load(open(args[args.index("--genome") + 1]))
n = int(args[args.index("--ensemble") + 1])
assert args[args.index("--cut-off") + 1] == "none"
f = (0.5 if args[args.index("--integrator") + 1] == "rk-merson" else 0.9) * g["kx"] / 100
print(json.dumps({"fitness": f, "wall_ms": 1.0, "ensemble": {
    "fitness_median": f, "fitness_min": f - 1, "fitness_max": f + 1, "size": n,
    "bipeds": n if g["ky"] <= 8000 else n - 1, "tripods": 0 if g["ky"] <= 8000 else 1, "falls": 0}}))
"""


def archive_record(fitnesses_and_kx):
    """A summarisedOutput file: a generation's lines, then the final archive."""
    archive = []
    for fitness, kx in fitnesses_and_kx:
        genes = dict(GENES, k1=kx)
        archive.append([genes, fitness])
    return ("Generation: 0\nCurrent Fitness:\n[1.0, 2.0]\n\nAll time fittest:\n[2.0, 1.0]\n\n"
            + str(archive) + "Done at 05_30_21_08_14\n")


def executable(path, text):
    path.write_text(text)
    path.chmod(path.stat().st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
    return path


class CompareAuthorsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = pathlib.Path(self.tmp.name)
        repo = self.root / "repo" / "CaseData" / "case2"
        repo.mkdir(parents=True)
        (repo / "summarisedOutput-05_28_16_31_22").write_text(
            archive_record([(15.2, 1500.0), (14.9, 1400.0), (14.2, 1234.0)]))

    def tearDown(self):
        self.tmp.cleanup()

    def run_tool(self, *args):
        return subprocess.run([sys.executable, str(TOOL), *args], capture_output=True, text=True)

    def run_both(self, genomes, *args):
        """`run` on a folder of genome files, with the fake programs and ensembles of 3."""
        authors = executable(self.root / "walker", FAKE_AUTHORS)
        walkers = executable(self.root / "walkers", FAKE_WALKERS)
        return self.run_tool("run", "--authors-binary", str(authors), "--walkers", str(walkers),
                             "--genomes", str(genomes), "--ensemble", "3", *args)

    def test_extract_writes_the_top_of_the_final_archive_as_genome_files(self):
        out = self.root / "genomes"
        p = self.run_tool("extract", "--authors", str(self.root / "repo"), "--out", str(out), "--top", "2")
        self.assertEqual(p.returncode, 0, p.stderr)
        files = sorted(x.name for x in out.glob("*.json"))
        self.assertEqual(files, ["archive_case2_05_28_16_31_22_0.json", "archive_case2_05_28_16_31_22_1.json"])
        g = json.loads((out / files[1]).read_text())
        self.assertEqual(g["kx"], 1400.0)              # their k1
        self.assertEqual(g["halfFootX"], 0.2)          # their halfFootBodyX
        self.assertEqual(g["lambdaTheta"], 100.0)      # their bodyStraightL
        self.assertEqual(len(g), 21)
        origin = (out / "origin.csv").read_text().splitlines()
        self.assertEqual(origin[0], "file,case,run,rank,authors_recorded_fitness")
        self.assertEqual(origin[2], "archive_case2_05_28_16_31_22_1.json,time,05_28_16_31_22,1,14.9")
        # nothing is replaced without --force
        again = self.run_tool("extract", "--authors", str(self.root / "repo"), "--out", str(out))
        self.assertEqual(again.returncode, 2)
        self.assertIn("exists", again.stderr)

    def test_run_compares_both_programs_genome_by_genome(self):
        out = self.root / "genomes"
        self.assertEqual(self.run_tool("extract", "--authors", str(self.root / "repo"), "--out", str(out)).returncode, 0)
        report, table = self.root / "report.json", self.root / "table.md"
        p = self.run_both(out, "--jobs", "2", "--json", str(report), "--markdown", str(table))
        self.assertEqual(p.returncode, 0, p.stderr)
        r = json.loads(report.read_text())
        rows = {row["genome"]: row for row in r["rows"]}
        self.assertAlmostEqual(rows["archive_case2_05_28_16_31_22_0"]["authors"], 15.0)
        self.assertAlmostEqual(rows["archive_case2_05_28_16_31_22_0"]["ours_median"], 13.5)
        self.assertEqual(rows["archive_case2_05_28_16_31_22_2"]["authors"], -1.0)  # their program's fall
        self.assertEqual(rows["archive_case2_05_28_16_31_22_2"]["authors_note"], "fell")
        s = r["summary"]
        self.assertEqual(s["compared"], 3)
        self.assertAlmostEqual(s["spearman"], 1.0)       # the same order in both
        self.assertAlmostEqual(s["median_ratio"], 0.9)   # over the two that walk in theirs
        self.assertIn("Spearman 1.000", p.stdout)
        # the table beside the fitness their evolver recorded
        lines = table.read_text().splitlines()
        self.assertIn("| `archive_case2_05_28_16_31_22_1` | 14.90 | 14.00 | 12.60 [11.60, 13.60] | 0.90 | biped |", lines)
        self.assertIn("| `archive_case2_05_28_16_31_22_2` | 14.20 | -1.00 |", lines[4])

    def test_both_of_our_integrators_side_by_side(self):
        out = self.root / "genomes"
        self.assertEqual(self.run_tool("extract", "--authors", str(self.root / "repo"), "--out", str(out)).returncode, 0)
        report = self.root / "report.json"
        p = self.run_both(out, "--integrator", "cvode", "--integrator", "rk-merson", "--json", str(report))
        self.assertEqual(p.returncode, 0, p.stderr)
        r = json.loads(report.read_text())
        self.assertEqual(r["integrators"], ["cvode", "rk-merson"])
        self.assertAlmostEqual(r["summaries"]["cvode"]["median_ratio"], 0.9)
        self.assertAlmostEqual(r["summaries"]["rk-merson"]["median_ratio"], 0.5)
        # 0.5 of theirs is beyond a factor 1.5 for both that walk in theirs; the fall in theirs walks in ours
        self.assertEqual(r["summaries"]["rk-merson"]["beyond_factor"], 3)
        self.assertEqual(r["summaries"]["cvode"]["beyond_factor"], 1)
        self.assertIn("rk-merson: 3 of 3 compared", p.stdout)
        bad = self.run_both(out, "--accuracy", "0")
        self.assertEqual(bad.returncode, 2)
        self.assertIn("--accuracy", bad.stderr)

    def test_their_program_is_waited_for_as_long_as_timeout_says(self):
        genomes = self.root / "genomes"
        genomes.mkdir()
        for kx in (1500.0, 999.0):
            genome = dict(compare_authors.genome_from_authors(GENES, "test"), kx=kx)
            (genomes / f"kx{kx:.0f}.json").write_text(json.dumps(genome))
        report, table = self.root / "report.json", self.root / "table.md"
        p = self.run_both(genomes, "--timeout", "0.5", "--json", str(report), "--markdown", str(table))
        self.assertEqual(p.returncode, 0, p.stderr)
        rows = {row["genome"]: row for row in json.loads(report.read_text())["rows"]}
        self.assertIsNone(rows["kx999"]["authors"])
        self.assertEqual(rows["kx999"]["authors_note"], "timeout")
        self.assertLess(rows["kx999"]["authors_ms"], 10000.0)
        self.assertAlmostEqual(rows["kx1500"]["authors"], 15.0)
        self.assertIn("| `kx999` | — | > 0.5 s |", table.read_text())
        # a timeout that is not a positive number of seconds is refused before anything runs
        bad = self.run_both(genomes, "--timeout", "0")
        self.assertEqual(bad.returncode, 2)
        self.assertIn("--timeout 0", bad.stderr)

    def write_run(self, name, case, biped, tripod, best):
        """A finished run's folder as `walkers reproduce` leaves it: its finals (a best biped and
        a best tripod, each a (fitness, kx) or None) and its final best, one of them."""
        run = self.root / "results" / name
        run.mkdir(parents=True)
        finals = {"generations": 4000}
        genomes = {}
        for gait, final in (("biped", biped), ("tripod", tripod)):
            if final is not None:
                genomes[gait] = dict(compare_authors.genome_from_authors(GENES, "test"), kx=final[1])
                finals[f"best_{gait}"] = {"fitness": final[0], "gait": gait, "genome": genomes[gait]}
        (run / "finals.json").write_text(json.dumps(finals))
        (run / "config.json").write_text(json.dumps({"case": case, "seed": 1}))
        (run / "best.json").write_text(json.dumps(genomes[best]))

    def test_finals_writes_each_runs_best_biped_and_best_tripod_as_genome_files(self):
        self.write_run("free-1", "free", (12.5, 1300.0), (15.25, 1600.0), "tripod")
        self.write_run("performance-1", "performance", (20.5, 2100.0), None, "biped")
        out = self.root / "finals"
        p = self.run_tool("finals", "--results", str(self.root / "results"), "--out", str(out))
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(sorted(x.name for x in out.glob("*.json")),
                         ["free-1-biped.json", "free-1-tripod.json", "performance-1-biped.json"])
        self.assertEqual(json.loads((out / "free-1-tripod.json").read_text())["kx"], 1600.0)
        self.assertEqual((out / "origin.csv").read_text().splitlines(), [
            "file,case,run,gait,final_best,recorded_fitness",
            "free-1-biped.json,free,free-1,biped,no,12.5",
            "free-1-tripod.json,free,free-1,tripod,yes,15.25",
            "performance-1-biped.json,performance,performance-1,biped,yes,20.5"])
        # both programs on them, beside what our runs recorded
        table = self.root / "table.md"
        p = self.run_both(out, "--jobs", "1", "--markdown", str(table))
        self.assertEqual(p.returncode, 0, p.stderr)
        lines = table.read_text().splitlines()
        self.assertTrue(lines[0].startswith("| genome | recorded by our runs | theirs |"), lines[0])
        self.assertIn("| `free-1-tripod` | 15.25 | 16.00 | 14.40 [13.40, 15.40] | 0.90 | biped |", lines)
        # nothing is replaced without --force, and a folder without runs is refused
        again = self.run_tool("finals", "--results", str(self.root / "results"), "--out", str(out))
        self.assertEqual(again.returncode, 2)
        self.assertIn("exists", again.stderr)
        empty = self.run_tool("finals", "--results", str(self.root / "repo"), "--out", str(self.root / "none"))
        self.assertEqual(empty.returncode, 2)
        self.assertIn("no */finals.json", empty.stderr)

    def test_the_runs_final_bests_are_summarised_by_case_in_the_runs_order(self):
        self.write_run("time-1", "time", (9.0, 900.0), (8.0, 800.0), "biped")
        self.write_run("free-10", "free", (12.5, 1300.0), (15.25, 1600.0), "tripod")
        self.write_run("free-2", "free", (11.0, 1100.0), None, "biped")
        out = self.root / "finals"
        self.assertEqual(self.run_tool("finals", "--results", str(self.root / "results"), "--out", str(out)).returncode, 0)
        order = [line.split(",")[0] for line in (out / "origin.csv").read_text().splitlines()[1:]]
        self.assertEqual(order, ["free-2-biped.json", "free-10-biped.json", "free-10-tripod.json",
                                 "time-1-biped.json", "time-1-tripod.json"])
        report = self.root / "report.json"
        p = self.run_both(out, "--jobs", "2", "--json", str(report))
        self.assertEqual(p.returncode, 0, p.stderr)
        r = json.loads(report.read_text())
        self.assertEqual([row["genome"] for row in r["rows"]], [name[:-5] for name in order])
        # the final bests: free-2's biped, free-10's tripod and time-1's biped
        final = r["final_bests"]
        self.assertEqual((final["genomes"], final["compared"]), (3, 3))
        self.assertAlmostEqual(final["median_ratio"], 0.9)
        self.assertEqual(list(final["by_case"]), ["free", "time"])
        self.assertAlmostEqual(final["by_case"]["free"]["theirs_mean"], (11.0 + 16.0) / 2)
        self.assertAlmostEqual(final["by_case"]["free"]["ours_mean"], 0.9 * (11.0 + 16.0) / 2)
        self.assertEqual(final["by_case"]["time"]["compared"], 1)
        self.assertIn("the runs' final bests: 3 of 3 compared", p.stdout)
        self.assertIn("free 13.500 against 12.150 (2)", p.stdout)

    def test_their_genes_go_to_their_program_as_their_evolver_gave_them(self):
        genome = {ours: float(GENES[theirs]) for ours, theirs in compare_authors.AUTHORS_ARGUMENTS}
        genome["kx"] = 1572.4184169068672
        args = compare_authors.authors_arguments(genome)
        self.assertEqual(len(args), 21)
        self.assertEqual(args[6], "1572.41841691")  # Python 2's str(): 12 significant digits
        self.assertEqual(args[12:15], ["0.7", "0.1", "0.1"])  # the masses between the VMC and stepK genes

    def test_their_program_is_never_built_inside_this_repository(self):
        source = self.root / "repo" / "simbody" / "twoLegVar" / "walker.cpp"
        source.parent.mkdir(parents=True)
        source.write_text("int main() {}\n")
        with self.assertRaisesRegex(compare_authors.ToolError, "inside this repository"):
            compare_authors.build_authors(str(self.root / "repo"), str(compare_authors.ROOT / "build" / "authors"))


if __name__ == "__main__":
    unittest.main()
