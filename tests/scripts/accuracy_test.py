#!/usr/bin/env python3
"""Tests for scripts/accuracy.py, the accuracy criterion, on hand-made ensembles.

Run:  /usr/bin/python3 tests/scripts/accuracy_test.py   (needs SciPy)
"""
import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "accuracy.py")
spec = importlib.util.spec_from_file_location("accuracy", SCRIPT)
accuracy = importlib.util.module_from_spec(spec)
spec.loader.exec_module(accuracy)


def ensemble(fitness, bipeds=None, tripods=0, falls=0):
    return {"fitness": fitness, "bipeds": len(fitness) if bipeds is None else bipeds, "tripods": tripods,
            "falls": falls, "steps_median": 1000.0, "wall_ms_median": 10.0}


def genome(production, tight, name="g"):
    return {"genome": name, "production": production, "tight": tight}


class Criterion(unittest.TestCase):
    def test_regular_genome_needs_medians_within_one_percent(self):
        tight = ensemble([10.00, 10.01, 10.02, 10.03, 10.04])  # IQR 0.02 < 2 % of 10.02
        close = accuracy.judge(genome(ensemble([10.05, 10.06, 10.07, 10.08, 10.09]), tight))
        self.assertTrue(close["regular"])
        self.assertAlmostEqual(close["median_difference"], 0.05 / 10.02)
        self.assertTrue(close["passes"])
        far = accuracy.judge(genome(ensemble([10.2, 10.2, 10.2, 10.2, 10.2]), tight))
        self.assertFalse(far["passes"])  # 1.8 % apart
        self.assertIsNone(far["ks_p"])  # regular genomes get no KS test

    def test_irregular_genome_passes_inside_the_iqr_or_by_ks(self):
        tight = ensemble([2.0, 5.0, 8.0, 11.0, 14.0, 17.0, 20.0])  # IQR [6.5, 15.5]
        inside = accuracy.judge(genome(ensemble([0.0, 1.0, 9.0, 30.0, 40.0, 41.0, 42.0]), tight))
        self.assertFalse(inside["regular"])
        self.assertTrue(inside["fitness_agrees"])  # median 30 is outside, but ...
        # ... the same values shifted out of the IQR and clearly from another distribution fail
        apart = accuracy.judge(genome(ensemble([50.0, 51.0, 52.0, 53.0, 54.0, 55.0, 56.0]), tight))
        self.assertLess(apart["ks_p"], 0.05)
        self.assertFalse(apart["passes"])

    def test_ks_decides_when_the_median_is_outside(self):
        tight = ensemble([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0])  # IQR [3.25, 7.75]
        v = accuracy.judge(genome(ensemble([1.0, 2.0, 8.0, 8.5, 9.0, 9.2, 9.5, 9.7, 10.0, 10.5]), tight))
        self.assertFalse(v["tight_iqr"][0] <= v["median"] <= v["tight_iqr"][1])
        self.assertGreater(v["ks_p"], 0.05)
        self.assertTrue(v["passes"])

    def test_identical_ensembles_are_indistinguishable(self):
        falls = ensemble([-1.0] * 5, bipeds=0, falls=5)
        v = accuracy.judge(genome(falls, falls))
        self.assertTrue(v["passes"])

    def test_gait_and_fall_majorities_must_agree(self):
        walk = [5.0, 5.0, 5.0]
        self.assertFalse(accuracy.judge(genome(ensemble(walk, bipeds=0, tripods=3), ensemble(walk)))["passes"])
        self.assertFalse(accuracy.judge(genome(ensemble(walk, falls=2), ensemble(walk)))["passes"])
        self.assertTrue(accuracy.judge(genome(ensemble(walk, falls=1), ensemble(walk)))["passes"])

    def test_no_lost_walkers(self):
        # the tight ensemble walks (median 6); production stalls in 3 of 5, though its median
        # 0.9 lies inside the tight interquartile range [0.8, 7]
        tight = ensemble([0.5, 0.8, 6.0, 7.0, 8.0])
        lost = accuracy.judge(genome(ensemble([0.5, 0.6, 0.9, 7.0, 8.0]), tight))
        self.assertTrue(lost["fitness_agrees"])
        self.assertTrue(lost["lost_walker"])
        self.assertFalse(lost["passes"])
        kept = accuracy.judge(genome(ensemble([0.5, 0.6, 6.0, 7.0, 8.0]), tight))  # 2 of 5: no majority
        self.assertFalse(kept["lost_walker"])
        self.assertTrue(kept["passes"])
        self.assertFalse(accuracy.judge(genome(ensemble([0.5, 1.0, 7.0, 8.0]), tight))["lost_walker"])  # half
        self.assertTrue(accuracy.judge(genome(ensemble([0.5, 1.0, 1.0, 8.0]), tight))["lost_walker"])

    def test_no_numerical_walkers(self):
        # the tight ensemble stalls (median 0.7); production walks in 4 of 5, its median 6 inside
        # the tight interquartile range [0.6, 6]
        tight = ensemble([0.5, 0.6, 0.7, 6.0, 7.0])
        made = accuracy.judge(genome(ensemble([0.5, 5.5, 6.0, 6.5, 7.0]), tight))
        self.assertTrue(made["fitness_agrees"])
        self.assertTrue(made["numerical_walker"])
        self.assertFalse(made["lost_walker"])
        self.assertFalse(made["passes"])
        kept = accuracy.judge(genome(ensemble([0.5, 0.6, 4.9, 6.5, 7.0]), tight))  # 4.9 is no walker
        self.assertFalse(kept["numerical_walker"])
        self.assertTrue(kept["passes"])
        between = accuracy.judge(genome(ensemble([0.0, 0.0, 0.0, 9.0, 9.0]), ensemble([2.0, 3.0, 3.0, 3.0, 4.0])))
        self.assertFalse(between["lost_walker"] or between["numerical_walker"])

    def test_command_line_exit_status_and_bad_input(self):
        good = genome(ensemble([1.0, 1.0]), ensemble([1.0, 1.0]), "good")
        bad = genome(ensemble([3.0, 3.0]), ensemble([1.0, 1.0]), "bad")
        with tempfile.TemporaryDirectory() as d:
            def run(genomes):
                path = os.path.join(d, "a.json")
                with open(path, "w") as f:
                    json.dump({"settings": "x", "relative_tolerance": 1e-6, "absolute_tolerance_position": 1e-6,
                               "absolute_tolerance_velocity": 1e-4, "ensemble": 2, "genomes": genomes}, f)
                return subprocess.run([sys.executable, SCRIPT, path], capture_output=True, text=True)
            self.assertEqual(run([good]).returncode, 0)
            failing = run([good, bad])
            self.assertEqual(failing.returncode, 1)
            self.assertIn("1 of 2 genomes pass", failing.stdout)
            broken = run([{"genome": "x"}])
            self.assertEqual(broken.returncode, 2)
            self.assertIn("a.json", broken.stderr)


if __name__ == "__main__":
    unittest.main()
