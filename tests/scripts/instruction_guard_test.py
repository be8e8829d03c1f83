#!/usr/bin/env python3
"""Tests for scripts/instruction_guard.py with a stand-in for valgrind that reports a given count.

Run:  /usr/bin/python3 tests/scripts/instruction_guard_test.py
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "instruction_guard.py")
GENOME = "data/genomes/bench/authors_case1_biped.json"

# prints cachegrind's summary line with the count in $FAKE_COUNT, and the command it ran
FAKE_VALGRIND = """#!/bin/sh
echo "$@" >> "$FAKE_LOG"
echo "==1== I   refs:      $FAKE_COUNT" >&2
exit "${FAKE_EXIT:-0}"
"""


class Guard(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)
        bin_dir = os.path.join(self.dir.name, "bin")
        os.mkdir(bin_dir)
        valgrind = os.path.join(bin_dir, "valgrind")
        with open(valgrind, "w") as f:
            f.write(FAKE_VALGRIND)
        os.chmod(valgrind, 0o755)
        self.log = os.path.join(self.dir.name, "log")
        self.env = dict(os.environ, PATH=bin_dir + os.pathsep + "/usr/bin:/bin", FAKE_LOG=self.log)
        self.budget = os.path.join(self.dir.name, "budget.json")
        self.write_budget([{"integrator": "cvode", "genome": GENOME, "arguments": [], "instructions": 1_000_000}])

    def write_budget(self, entries):
        with open(self.budget, "w") as f:
            json.dump({"evaluations": entries}, f)

    def guard(self, count, *extra, env=None):
        env = dict(env or self.env, FAKE_COUNT=f"{count:,}")
        return subprocess.run([sys.executable, SCRIPT, "--walkers", "/bin/true", "--budget", self.budget,
                               "--source", ROOT, *extra], capture_output=True, text=True, env=env)

    def test_a_count_within_three_percent_of_the_budget_passes(self):
        for count in (900_000, 1_000_000, 1_030_000):
            run = self.guard(count)
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            self.assertIn(f"cvode authors_case1_biped: {count:,} instructions, budget 1,000,000", run.stdout)
        with open(self.log) as f:
            self.assertIn(f"--tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null /bin/true evaluate "
                          f"--genome {os.path.join(ROOT, GENOME)}", f.read())

    def test_a_count_more_than_three_percent_over_fails(self):
        run = self.guard(1_030_001)
        self.assertEqual(run.returncode, 1)
        self.assertIn("1,030,001 instructions, budget 1,000,000 (+3.00 %", run.stdout)
        self.assertIn("OVER BUDGET", run.stdout)

    def test_a_count_far_below_asks_for_a_lower_budget_and_write_sets_it(self):
        run = self.guard(500_000)
        self.assertEqual(run.returncode, 0)
        self.assertIn("lower the budget", run.stdout)
        self.assertEqual(self.guard(500_000, "--write").returncode, 0)
        with open(self.budget) as f:
            self.assertEqual(json.load(f)["evaluations"][0]["instructions"], 500_000)
        self.assertEqual(self.guard(510_000).returncode, 0)
        self.assertEqual(self.guard(520_000).returncode, 1)

    def test_every_entry_runs_with_its_arguments(self):
        self.write_budget([
            {"integrator": "cvode", "genome": GENOME, "instructions": 1_000_000},
            {"integrator": "other", "genome": GENOME, "arguments": ["--integrator", "other"], "instructions": 2_000_000},
        ])
        run = self.guard(1_500_000)
        self.assertEqual(run.returncode, 1)  # 50 % over the first, 25 % under the second
        self.assertIn("cvode authors_case1_biped: 1,500,000 instructions, budget 1,000,000", run.stdout)
        self.assertIn("other authors_case1_biped: 1,500,000 instructions, budget 2,000,000", run.stdout)
        with open(self.log) as f:
            self.assertTrue(f.read().splitlines()[1].endswith("--integrator other"))

    def test_valgrind_missing_skips(self):
        env = dict(self.env, PATH=os.path.join(self.dir.name, "nothing"))
        run = self.guard(1, env=env)
        self.assertEqual(run.returncode, 77)
        self.assertIn("valgrind is not installed", run.stdout)

    def test_a_failed_evaluation_is_an_error(self):
        run = self.guard(1_000_000, env=dict(self.env, FAKE_EXIT="3"))
        self.assertEqual(run.returncode, 2)
        self.assertIn("failed (exit 3)", run.stderr)

    def test_bad_budget_files_are_refused_naming_the_field(self):
        cases = [
            ([], "\"evaluations\" must be a non-empty list"),
            ([{"genome": GENOME, "instructions": 1}], "evaluations[0]: \"integrator\" must be a non-empty string"),
            ([{"integrator": "cvode", "genome": "no/such.json", "instructions": 1}], "genome no/such.json is not a file"),
            ([{"integrator": "cvode", "genome": GENOME, "instructions": 0}], "\"instructions\" must be a whole number"),
            ([{"integrator": "cvode", "genome": GENOME, "instructions": 1.5}], "\"instructions\" must be a whole number"),
            ([{"integrator": "cvode", "genome": GENOME, "arguments": "--x", "instructions": 1}],
             "\"arguments\" must be a list of strings"),
            ([{"integrator": "cvode", "genome": GENOME, "instructions": 1}] * 2,
             "evaluations[1]: a second entry for integrator cvode"),
        ]
        for entries, message in cases:
            self.write_budget(entries)
            run = self.guard(1)
            self.assertEqual(run.returncode, 2, message)
            self.assertIn("budget.json", run.stderr)
            self.assertIn(message, run.stderr)


if __name__ == "__main__":
    unittest.main()
