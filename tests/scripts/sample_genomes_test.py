#!/usr/bin/env python3
"""Tests for scripts/sample_genomes.py on synthetic run folders.

Run:  /usr/bin/python3 tests/scripts/sample_genomes_test.py
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "sample_genomes.py")

GENES = ["halfBodyX", "kx"]
RESULTS = "fitness,distance,fell,gait,footsteps,trunk_contact_fraction,cvode_steps,failure,wall_ms"


def make_run(folder, case, generations, children):
    """A run whose child c of generation g has halfBodyX = g + c / 100 and fitness = g."""
    os.makedirs(folder)
    with open(os.path.join(folder, "config.json"), "w") as f:
        json.dump({"case": case}, f)
    evaluations = os.path.join(folder, "evaluations.csv")
    with open(evaluations, "w") as f:
        f.write("generation,child,parents," + ",".join(GENES) + "," + RESULTS + "\n")
        for g in range(generations):
            for c in range(children):
                gait = "none" if c == 0 else "biped"
                f.write(f"{g},{c},,{g + c / 100!r},1500,{g}.0,1.0,{int(c == 0)},{gait},3,0,100,,5.0\n")
    checkpoint = {"evaluations_bytes": os.path.getsize(evaluations),
                  "archive": [{"genome": {"halfBodyX": 1.0, "kx": 2.0, "kneeMass": 0.7}}]}
    with open(os.path.join(folder, "checkpoint.json"), "w") as f:
        json.dump(checkpoint, f)
    # a generation begun after the checkpoint, which the run did not finish
    with open(evaluations, "a") as f:
        f.write(f"{generations},0,,{generations!r},1500,{generations}.0,1.0,0,biped,3,0,100,,5.0\n")


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)


class SampleGenomes(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.free = os.path.join(self.dir.name, "sample_free")
        self.time = os.path.join(self.dir.name, "sample_time")
        make_run(self.free, "free", 100, 4)
        make_run(self.time, "time", 30, 3)

    def tearDown(self):
        self.dir.cleanup()

    def sample(self, out, seed=7, per_run=10):
        result = run("--per-run", str(per_run), "--seed", str(seed), "--out", out, self.free, self.time)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(out, "index.csv")) as f:
            return list(csv.DictReader(f))

    def test_one_draw_per_stratum_of_generations_with_the_runs_genome(self):
        out = os.path.join(self.dir.name, "out")
        index = self.sample(out)
        self.assertEqual(len(index), 20)
        free = [r for r in index if r["run"] == "sample_free"]
        time = [r for r in index if r["run"] == "sample_time"]
        self.assertEqual({r["case"] for r in free}, {"free"})
        self.assertEqual({r["case"] for r in time}, {"time"})
        # strata of 10 and of 3 generations, in order
        for k, r in enumerate(free):
            self.assertTrue(10 * k <= int(r["generation"]) < 10 * (k + 1), r)
        for k, r in enumerate(time):
            self.assertTrue(3 * k <= int(r["generation"]) < 3 * (k + 1), r)
        self.assertLess(max(int(r["generation"]) for r in index), 100)  # not the unfinished generation
        for r in index:
            with open(os.path.join(out, r["file"])) as f:
                genome = json.load(f)
            g, c = int(r["generation"]), int(r["child"])
            self.assertEqual(r["file"], f"{r['run']}_g{g}_c{c}.json")
            self.assertEqual(genome, {"halfBodyX": g + c / 100, "kx": 1500.0, "kneeMass": 0.7})
            self.assertEqual(float(r["recorded_fitness"]), g)
            self.assertEqual(r["recorded_gait"], "none" if c == 0 else "biped")

    def test_the_same_seed_draws_the_same_and_another_seed_does_not(self):
        a = self.sample(os.path.join(self.dir.name, "a"), seed=7)
        b = self.sample(os.path.join(self.dir.name, "b"), seed=7)
        c = self.sample(os.path.join(self.dir.name, "c"), seed=8)
        self.assertEqual(a, b)
        self.assertNotEqual(a, c)

    def test_bad_input_names_the_file_row_and_column(self):
        path = os.path.join(self.free, "evaluations.csv")
        with open(path) as f:
            lines = f.readlines()
        lines[3] = lines[3].replace(",1500,", ",abc,", 1)
        with open(path, "w") as f:
            f.writelines(lines)
        result = run("--per-run", "100", "--seed", "1", "--out", os.path.join(self.dir.name, "x"), self.free)
        self.assertEqual(result.returncode, 2)
        self.assertIn("evaluations.csv: row 4, column 'kx'", result.stderr)
        too_many = run("--per-run", "31", "--seed", "1", "--out", os.path.join(self.dir.name, "y"), self.time)
        self.assertEqual(too_many.returncode, 2)
        self.assertIn("31 draws asked of 30 generations", too_many.stderr)
        missing = run("--per-run", "1", "--seed", "1", "--out", os.path.join(self.dir.name, "z"),
                      os.path.join(self.dir.name, "nowhere"))
        self.assertEqual(missing.returncode, 2)
        self.assertIn("nowhere", missing.stderr)


if __name__ == "__main__":
    unittest.main()
