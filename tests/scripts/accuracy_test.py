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


def judged(genomes):
    """Every genome's verdict and the set's, as scripts/accuracy.py judges one set."""
    return accuracy.judge_set(genomes)


def wide(median, spread=0.3, size=25, scale=1.0):
    """An irregular ensemble: `size` members spread evenly over median * (1 +- spread), times `scale`."""
    return ensemble([scale * median * (1 - spread + 2 * spread * j / (size - 1)) for j in range(size)])


class Genome(unittest.TestCase):
    def test_regular_genome_needs_medians_within_one_percent(self):
        tight = ensemble([10.00, 10.01, 10.02, 10.03, 10.04])  # IQR 0.02 < 2 % of 10.02
        close = accuracy.judge(genome(ensemble([10.05, 10.06, 10.07, 10.08, 10.09]), tight))
        self.assertTrue(close["regular"])
        self.assertAlmostEqual(close["median_difference"], 0.05 / 10.02)
        self.assertTrue(close["passes"])
        far = accuracy.judge(genome(ensemble([10.2, 10.2, 10.2, 10.2, 10.2]), tight))
        self.assertFalse(far["passes"])  # 1.8 % apart, outside the IQR
        self.assertIsNone(far["ks_p"])  # regular genomes get no KS test

    def test_regular_genome_passes_with_its_median_inside_the_reference_iqr(self):
        tight = ensemble([9.5, 9.98, 10.0, 10.17, 10.5])  # IQR [9.98, 10.17]: 1.9 % of 10
        v = accuracy.judge(genome(ensemble([10.16] * 5), tight))
        self.assertTrue(v["regular"])
        self.assertGreater(v["median_difference"], 0.01)
        self.assertTrue(v["passes"])
        self.assertFalse(accuracy.judge(genome(ensemble([10.18] * 5), tight))["passes"])  # just outside

    def test_a_planted_three_percent_bias_fails_a_regular_genome(self):
        tight = ensemble([10.00, 10.01, 10.02, 10.03, 10.04])
        biased = accuracy.judge(genome(ensemble([1.03 * f for f in tight["fitness"]]), tight))
        self.assertTrue(biased["regular"])
        self.assertAlmostEqual(biased["signed_difference"], 0.03)
        self.assertFalse(biased["passes"])

    def test_identical_ensembles_are_indistinguishable(self):
        falls = ensemble([-1.0] * 5, bipeds=0, falls=5)
        verdicts, verdict = judged([genome(falls, falls)])
        self.assertTrue(verdicts[0]["passes"])
        self.assertTrue(verdict["passes"])

    def test_gait_and_fall_majorities_must_agree(self):
        walk = [5.0, 5.0, 5.0]
        self.assertFalse(accuracy.judge(genome(ensemble(walk, bipeds=0, tripods=3), ensemble(walk)))["passes"])
        self.assertFalse(accuracy.judge(genome(ensemble(walk, falls=2), ensemble(walk)))["passes"])
        self.assertTrue(accuracy.judge(genome(ensemble(walk, falls=1), ensemble(walk)))["passes"])

    def test_no_lost_walkers(self):
        # the reference walks (median 6); production stalls in 3 of 5, its median 0.9 (a regular genome
        # would need it inside the reference IQR [0.8, 7], an irregular one a KS test)
        tight = ensemble([0.5, 0.8, 6.0, 7.0, 8.0])
        lost = judged([genome(ensemble([0.5, 0.6, 0.9, 7.0, 8.0]), tight)])[0][0]
        self.assertTrue(lost["lost_walker"])
        self.assertFalse(lost["passes"])
        kept = judged([genome(ensemble([0.5, 0.6, 6.0, 7.0, 8.0]), tight)])[0][0]  # 2 of 5: no majority
        self.assertFalse(kept["lost_walker"])
        self.assertTrue(kept["passes"])
        self.assertFalse(accuracy.judge(genome(ensemble([0.5, 1.0, 7.0, 8.0]), tight))["lost_walker"])  # half
        self.assertTrue(accuracy.judge(genome(ensemble([0.5, 1.0, 1.0, 8.0]), tight))["lost_walker"])

    def test_no_numerical_walkers(self):
        # the reference stalls (median 0.7); production walks in 4 of 5
        tight = ensemble([0.5, 0.6, 0.7, 6.0, 7.0])
        made = judged([genome(ensemble([0.5, 5.5, 6.0, 6.5, 7.0]), tight)])[0][0]
        self.assertTrue(made["numerical_walker"])
        self.assertFalse(made["lost_walker"])
        self.assertFalse(made["passes"])
        kept = judged([genome(ensemble([0.5, 0.6, 4.9, 6.5, 7.0]), tight)])[0][0]  # 4.9 is no walker
        self.assertFalse(kept["numerical_walker"])
        self.assertTrue(kept["passes"])
        between = accuracy.judge(genome(ensemble([0.0, 0.0, 0.0, 9.0, 9.0]), ensemble([2.0, 3.0, 3.0, 3.0, 4.0])))
        self.assertFalse(between["lost_walker"] or between["numerical_walker"])


class Set(unittest.TestCase):
    def test_holm_multiplies_the_kth_smallest_by_m_minus_k_plus_one(self):
        adjusted = accuracy.holm([0.01, 0.04, 0.03])  # 3 x 0.01, 2 x 0.03, then max(0.06, 1 x 0.04)
        for got, want in zip(adjusted, [0.03, 0.06, 0.06]):
            self.assertAlmostEqual(got, want)
        self.assertEqual(accuracy.holm([0.6, 0.9]), [1.0, 1.0])  # 2 x 0.6 capped; 0.9 raised to it
        self.assertEqual(accuracy.holm([]), [])

    def test_irregular_genomes_are_judged_by_ks_holm_corrected_over_the_set(self):
        tight = ensemble([float(i) for i in range(1, 26)])  # IQR [7, 19]: irregular
        shifted = genome(ensemble([i + 10.0 for i in range(1, 26)]), tight, "shifted")
        alone = judged([shifted])[0][0]
        self.assertFalse(alone["regular"])
        self.assertGreater(alone["ks_p"], 0.025)
        self.assertLess(alone["ks_p"], 0.05)
        self.assertEqual(alone["ks_p_holm"], alone["ks_p"])  # one test: no correction
        self.assertFalse(alone["passes"])
        # beside a second irregular genome its p-value is doubled, above the family-wise 0.05
        same = genome(tight, tight, "same")
        pair = judged([shifted, same])[0]
        self.assertAlmostEqual(pair[0]["ks_p_holm"], 2 * alone["ks_p"])
        self.assertTrue(pair[0]["passes"])
        self.assertTrue(pair[1]["passes"])
        # a regular genome takes no part in the correction
        regular = genome(ensemble([3.0] * 25), ensemble([3.0] * 25), "regular")
        self.assertFalse(judged([shifted, regular])[0][0]["passes"])
        # a clearly different ensemble fails even after the correction
        apart = genome(ensemble([i + 11.0 for i in range(1, 26)]), tight, "apart")
        self.assertFalse(judged([apart, same])[0][0]["passes"])

    def test_a_set_without_drift_passes(self):
        genomes = [genome(wide(10.0 + i, scale=1.002), wide(10.0 + i), f"g{i}") for i in range(12)]
        verdicts, verdict = judged(genomes)
        self.assertTrue(all(not v["regular"] and v["passes"] for v in verdicts))
        self.assertAlmostEqual(verdict["drift"], 0.002)
        self.assertAlmostEqual(verdict["spearman"], 1.0)
        self.assertTrue(verdict["passes"])

    def test_a_planted_three_percent_bias_fails_the_set(self):
        # each genome alone passes: its ensembles spread +-30 %, so KS cannot tell a 3 % bias
        genomes = [genome(wide(10.0 + i, scale=1.03), wide(10.0 + i), f"g{i}") for i in range(12)]
        verdicts, verdict = judged(genomes)
        self.assertTrue(all(not v["regular"] and v["passes"] for v in verdicts))
        self.assertAlmostEqual(verdict["drift"], 0.03)
        self.assertFalse(verdict["drift_passes"])
        self.assertFalse(verdict["passes"])
        # the same bias downwards
        genomes = [genome(wide(10.0 + i, scale=0.97), wide(10.0 + i), f"g{i}") for i in range(12)]
        self.assertFalse(judged(genomes)[1]["passes"])

    def test_the_ranks_of_the_medians_must_agree(self):
        # production's medians in the reverse order: each within its reference's spread, no drift
        genomes = [genome(wide(10.0 + 0.1 * (11 - i)), wide(10.0 + 0.1 * i), f"g{i}") for i in range(12)]
        verdicts, verdict = judged(genomes)
        self.assertTrue(all(v["passes"] for v in verdicts))
        self.assertLess(abs(verdict["drift"]), 1e-3)
        self.assertAlmostEqual(verdict["spearman"], -1.0)
        self.assertFalse(verdict["passes"])
        # production's medians all equal have no ranks
        genomes = [genome(wide(10.5), wide(10.0 + 0.1 * i), f"g{i}") for i in range(12)]
        self.assertFalse(judged(genomes)[1]["spearman_passes"])

    def test_spearman_needs_three_genomes_and_reference_medians_that_differ(self):
        two = [genome(wide(10.0 + i), wide(10.0 + i), f"g{i}") for i in range(2)]
        self.assertIsNone(judged(two)[1]["spearman"])
        self.assertTrue(judged(two)[1]["passes"])
        level = [genome(wide(10.0), wide(10.0), f"g{i}") for i in range(4)]
        self.assertIsNone(judged(level)[1]["spearman"])


class Spread(unittest.TestCase):
    def test_the_reference_iqr_over_production_on_the_walkers_production_spreads(self):
        genomes = [genome(wide(10.0 + i), wide(10.0 + i, spread=0.15), f"g{i}") for i in range(3)]
        genomes.append(genome(ensemble([5.0] * 5), ensemble([5.0] * 5), "still"))  # spreads in neither
        verdicts, verdict = judged(genomes)
        self.assertEqual([v["production_spreads"] for v in verdicts], [True, True, True, False])
        self.assertEqual(verdict["spreading"], 3)
        self.assertAlmostEqual(verdict["spread_ratio"], 0.5)
        self.assertIsNone(judged(genomes[3:])[1]["spread_ratio"])


class CommandLine(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def write(self, name, genomes, **header):
        path = os.path.join(self.dir.name, name)
        data = {"settings": "x", "relative_tolerance": 1e-6, "absolute_tolerance_position": 1e-6,
                "absolute_tolerance_velocity": 1e-4, "ensemble": 2,
                "perturbation": {"kind": "start", "step": 1e-7}, "genomes": genomes}
        data.update(header)
        with open(path, "w") as f:
            json.dump(data, f)
        return path

    def run_script(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)

    def test_exit_status(self):
        good = genome(ensemble([1.0, 1.0]), ensemble([1.0, 1.0]), "good")
        bad = genome(ensemble([3.0, 3.0]), ensemble([1.0, 1.0]), "bad")
        self.assertEqual(self.run_script(self.write("a.json", [good])).returncode, 0)
        failing = self.run_script(self.write("a.json", [good, bad]))
        self.assertEqual(failing.returncode, 1)
        self.assertIn("1 of 2 genomes pass", failing.stdout)

    def test_several_files_are_one_set(self):
        tight = ensemble([float(i) for i in range(1, 26)])
        shifted = genome(ensemble([i + 10.0 for i in range(1, 26)]), tight, "shifted")
        first = self.write("first.json", [shifted])
        self.assertEqual(self.run_script(first).returncode, 1)  # alone its KS p is below 0.05
        second = self.write("second.json", [genome(tight, tight, "same"), genome(tight, tight, "same_again")])
        both = self.run_script(first, second, "--markdown", os.path.join(self.dir.name, "set.md"))
        self.assertEqual(both.returncode, 0, both.stdout)  # three tests: Holm triples it; the median drift is 0
        self.assertIn("3 of 3 genomes pass", both.stdout)
        with open(os.path.join(self.dir.name, "set.md")) as f:
            self.assertEqual(f.read(), both.stdout)

    def test_bad_input_is_refused_naming_the_file_and_the_field(self):
        good = genome(ensemble([1.0, 1.0]), ensemble([1.0, 1.0]), "good")
        broken = self.run_script(self.write("a.json", [{"genome": "x"}]))
        self.assertEqual(broken.returncode, 2)
        self.assertIn("a.json", broken.stderr)
        self.assertIn("genome x: no production ensemble", broken.stderr)
        empty = self.run_script(self.write("e.json", [genome(ensemble([]), ensemble([1.0]), "e")]))
        self.assertEqual(empty.returncode, 2)
        self.assertIn("production.fitness", empty.stderr)
        counts = self.run_script(self.write("c.json", [genome(ensemble([1.0], bipeds=2), ensemble([1.0]), "c")]))
        self.assertEqual(counts.returncode, 2)
        self.assertIn("production.bipeds must be a count in 0..1", counts.stderr)
        first = self.write("first.json", [good])
        other = self.write("other.json", [genome(ensemble([1.0, 1.0]), ensemble([1.0, 1.0]), "g2")], ensemble=3)
        mixed = self.run_script(first, other)
        self.assertEqual(mixed.returncode, 2)
        self.assertIn("other.json: ensemble is 3", mixed.stderr)
        again = self.run_script(first, self.write("again.json", [good]))
        self.assertEqual(again.returncode, 2)
        self.assertIn("genome good is also in", again.stderr)
        self.assertEqual(self.run_script(os.path.join(self.dir.name, "missing.json")).returncode, 2)


if __name__ == "__main__":
    unittest.main()
